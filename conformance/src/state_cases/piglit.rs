//! Scripts from piglit's GL 1.x tests that tilegl failed (docs/piglit.md): the same calls on
//! Mesa and on tilegl (Rust API and C ABI), every answer (queries, read-backs, GL errors)
//! equal to Mesa's. Depth read-backs may differ by one unit of the 16-bit type (both
//! implementations round a converted depth).

super::state_case_list!(source = include_str!("piglit.rs"), agree = |a: &Answer, b: &Answer| {
    a.values.len() == b.values.len()
        && a.values
            .iter()
            .zip(&b.values)
            .all(|(x, y)| (x - y).abs() <= a.tolerance)
};
    piglit_sized_format_channels: "piglit's sized-texture-format-channels: the component sizes glGetTexLevelParameter reports for sized formats, GL_TEXTURE_STENCIL_SIZE among them (8 for the depth-stencil formats, 0 for the others). Every answer equals Mesa's (depth read-backs within one unit of the 16-bit type).",
    piglit_get_tex_image_luminance: "piglit's getteximage-luminance: an RGBA image read back as GL_LUMINANCE and GL_LUMINANCE_ALPHA, and a luminance image read back as RGBA. Every answer equals Mesa's (depth read-backs within one unit of the 16-bit type).",
    piglit_copy_pixels_depth_stencil: "piglit's depthstencil-default_fb-copypixels: glCopyPixels(GL_DEPTH_STENCIL) copies the depth and the stencil of a rectangle. Every answer equals Mesa's (depth read-backs within one unit of the 16-bit type).",
    piglit_depth_stencil_pixels: "piglit's depthstencil-default_fb-readpixels-24_8 and -drawpixels-24_8: glReadPixels and glDrawPixels with GL_DEPTH_STENCIL / GL_UNSIGNED_INT_24_8 (EXT_packed_depth_stencil), with depth scale and bias and (on read-back) index offset, the depth and stencil write masks, the depth test off, and the errors of other types and formats. Every answer equals Mesa's (24-bit depths within one unit).",
    piglit_get_tex_image_depth_stencil: "piglit's getteximage-depth with EXT_packed_depth_stencil listed: depth-stencil images uploaded and read back with glGetTexImage(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8), the depth of each word compared (tilegl's depth textures keep no stencil), and the error of reading a colour image so. Every answer equals Mesa's (24-bit depths within one unit).",
    piglit_errors: "Error codes piglit's copyteximage, max-texture-size-level and draw-pixels expect, and glEnable of an array's name (several piglit GL 1.x tests enable their arrays so). Every answer equals Mesa's (depth read-backs within one unit of the 16-bit type).",
    piglit_depth_rectangle: "piglit's getteximage-depth on GL_TEXTURE_RECTANGLE: depth images on rectangles. Every answer equals Mesa's (depth read-backs within one unit of the 16-bit type).",
    piglit_beginend_coverage: "piglit's gl-1.0-beginend-coverage: glIndex*, glClearIndex and glIndexMask set colour-index state in an RGBA context without error (glIndex* also between glBegin and glEnd); glTexGenf/glTexGeni with a plane set (param, 0, 0, 0) (section 2.11.4 names no error for the scalar forms); glTexParameterf(GL_TEXTURE_BORDER_COLOR) is GL_INVALID_ENUM; glDrawArrays and glDrawElements from a display list executed between glBegin and glEnd are GL_INVALID_OPERATION. Every answer equals Mesa's (depth read-backs within one unit of the 16-bit type).",
    piglit_proxy_memory_limit: "piglit's tex3d-maxsize and max-texture-size: proxy images (GL_PROXY_TEXTURE_2D/3D) of GL_INTENSITY8, GL_RGBA8 and GL_RGBA32F halved one side at a time from the largest side, as the test probes them; an image whose storage exceeds the implementation's per-image limit (llvmpipe's 2 GiB) reads back as width, height and depth 0 without an error. Every answer equals Mesa's.",
    piglit_depth_stencil_uploads: "piglit's texsubimage-depth-formats and teximage-errors: depth uploaded as GL_DEPTH_STENCIL / GL_UNSIGNED_INT_24_8 (EXT_packed_depth_stencil) into depth textures, depth-stencil textures keeping the stencil indices too (read back as GL_DEPTH_STENCIL, which a depth-only texture refuses), and the errors of formats that do not match the internal format's kind. Every answer equals Mesa's (depth read-backs within one unit of the 16-bit type).",
);

use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::Gl;

/// One answer: a label, the values, and how far they may differ from Mesa's.
#[derive(Debug)]
pub struct Answer {
    label: String,
    values: Vec<f64>,
    tolerance: f64,
}

type Answers = Vec<Answer>;

impl super::Recorded for Answer {
    fn label(&self) -> String {
        self.label.clone()
    }
    fn value(&self) -> String {
        format!("{:?}", self.values)
    }
}

fn exact(out: &mut Answers, label: String, values: Vec<f64>) {
    out.push(Answer {
        label,
        values,
        tolerance: 0.0,
    });
}

fn err(gl: &mut dyn Gl, out: &mut Answers, label: &str) {
    let e = gl.get_error();
    exact(out, format!("glGetError after {label}"), vec![e as f64]);
}

/// piglit's sized-texture-format-channels: the component sizes glGetTexLevelParameter
/// reports for sized formats, GL_TEXTURE_STENCIL_SIZE among them (8 for the depth-stencil
/// formats, 0 for the others).
fn piglit_sized_format_channels(gl: &mut dyn Gl, out: &mut Answers) {
    const SIZES: [GLenum; 8] = [
        GL_TEXTURE_RED_SIZE,
        GL_TEXTURE_GREEN_SIZE,
        GL_TEXTURE_BLUE_SIZE,
        GL_TEXTURE_ALPHA_SIZE,
        GL_TEXTURE_LUMINANCE_SIZE,
        GL_TEXTURE_INTENSITY_SIZE,
        GL_TEXTURE_DEPTH_SIZE,
        GL_TEXTURE_STENCIL_SIZE_EXT,
    ];
    for (format, data_format) in [
        (GL_ALPHA8, GL_RGBA),
        (GL_LUMINANCE8, GL_RGBA),
        (GL_LUMINANCE8_ALPHA8, GL_RGBA),
        (GL_INTENSITY8, GL_RGBA),
        (GL_RGB8, GL_RGBA),
        (GL_RGBA8, GL_RGBA),
        (GL_R8, GL_RGBA),
        (GL_RG8, GL_RGBA),
        (GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT),
        (GL_DEPTH24_STENCIL8_EXT, GL_DEPTH_COMPONENT),
        (GL_DEPTH32F_STENCIL8, GL_DEPTH_COMPONENT),
        (GL_DEPTH_STENCIL_EXT, GL_DEPTH_COMPONENT),
    ] {
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            format as i32,
            1,
            1,
            0,
            data_format,
            GL_FLOAT,
            None,
        );
        let values = SIZES
            .iter()
            .map(|&p| {
                let mut v = [-1];
                gl.get_tex_level_parameteriv(GL_TEXTURE_2D, 0, p, &mut v);
                v[0] as f64
            })
            .collect();
        exact(out, format!("sizes of 0x{format:04x}"), values);
        err(gl, out, &format!("0x{format:04x}"));
    }
}

/// piglit's getteximage-luminance: an RGBA image read back as GL_LUMINANCE and
/// GL_LUMINANCE_ALPHA, and a luminance image read back as RGBA.
fn piglit_get_tex_image_luminance(gl: &mut dyn Gl, out: &mut Answers) {
    let rgba = [128u8, 64, 32, 200];
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&rgba),
    );
    for format in [GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_RED, GL_RGBA] {
        let mut px = [0u8; 4];
        gl.get_tex_image(GL_TEXTURE_2D, 0, format, GL_UNSIGNED_BYTE, &mut px);
        exact(
            out,
            format!("RGBA image as 0x{format:04x}"),
            px.iter().map(|&v| v as f64).collect(),
        );
    }
    let lum = [96u8];
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE8 as i32,
        1,
        1,
        0,
        GL_LUMINANCE,
        GL_UNSIGNED_BYTE,
        Some(&lum),
    );
    for format in [GL_LUMINANCE, GL_RGBA] {
        let mut px = [0u8; 4];
        gl.get_tex_image(GL_TEXTURE_2D, 0, format, GL_UNSIGNED_BYTE, &mut px);
        exact(
            out,
            format!("luminance image as 0x{format:04x}"),
            px.iter().map(|&v| v as f64).collect(),
        );
    }
    err(gl, out, "get_tex_image");
}

/// piglit's depthstencil-default_fb-copypixels: glCopyPixels(GL_DEPTH_STENCIL) copies the
/// depth and the stencil of a rectangle.
fn piglit_copy_pixels_depth_stencil(gl: &mut dyn Gl, out: &mut Answers) {
    gl.clear_depth(0.0);
    gl.clear_stencil(0xfe);
    gl.clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_ALWAYS);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
    gl.stencil_func(GL_ALWAYS, 0x33, !0);
    // The upper-right quarter at depth 0.25, stencil 0x33.
    gl.begin(GL_QUADS);
    for (x, y) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        gl.vertex_3f(x, y, -0.5);
    }
    gl.end();
    gl.disable(GL_STENCIL_TEST);
    gl.raster_pos_2f(-1.0, -1.0);
    gl.copy_pixels(33, 33, 31, 31, GL_DEPTH_STENCIL_EXT);
    err(gl, out, "copy_pixels(GL_DEPTH_STENCIL)");
    gl.disable(GL_DEPTH_TEST);
    for (x, y) in [(0, 0), (30, 30), (10, 20), (31, 31), (40, 40), (5, 50)] {
        let mut d = [0u8; 2];
        gl.read_pixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, &mut d);
        out.push(Answer {
            label: format!("depth at ({x}, {y})"),
            values: vec![u16::from_ne_bytes(d) as f64],
            tolerance: 1.0,
        });
        let mut s = [0u8; 1];
        gl.read_pixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &mut s);
        exact(out, format!("stencil at ({x}, {y})"), vec![s[0] as f64]);
    }
    err(gl, out, "read-backs");
}

/// piglit's getteximage-depth on GL_TEXTURE_RECTANGLE: depth images on rectangles.
fn piglit_depth_rectangle(gl: &mut dyn Gl, out: &mut Answers) {
    let depths: Vec<u8> = (0..8)
        .flat_map(|i| (i as f32 / 7.0).to_ne_bytes())
        .collect();
    for format in [
        GL_DEPTH_COMPONENT,
        GL_DEPTH_COMPONENT16,
        GL_DEPTH_COMPONENT24,
    ] {
        gl.tex_image_2d(
            GL_TEXTURE_RECTANGLE_ARB,
            0,
            format as i32,
            4,
            2,
            0,
            GL_DEPTH_COMPONENT,
            GL_FLOAT,
            Some(&depths),
        );
        err(gl, out, &format!("rectangle 0x{format:04x}"));
        let mut back = [0u8; 16];
        gl.get_tex_image(
            GL_TEXTURE_RECTANGLE_ARB,
            0,
            GL_DEPTH_COMPONENT,
            GL_UNSIGNED_SHORT,
            &mut back,
        );
        out.push(Answer {
            label: format!("rectangle 0x{format:04x} read back"),
            values: back
                .chunks(2)
                .map(|c| u16::from_ne_bytes([c[0], c[1]]) as f64)
                .collect(),
            tolerance: 1.0,
        });
        err(gl, out, "get_tex_image");
    }
}

/// piglit's texsubimage-depth-formats and teximage-errors: depth uploaded as
/// GL_DEPTH_STENCIL / GL_UNSIGNED_INT_24_8 (EXT_packed_depth_stencil) into depth textures,
/// and the errors of formats that do not match the internal format's kind.
fn piglit_depth_stencil_uploads(gl: &mut dyn Gl, out: &mut Answers) {
    let words: Vec<u8> = [0x4000_00bbu32, 0x7f00_00bb, 0xc000_00bb, 0xff00_00bb]
        .iter()
        .flat_map(|w| w.to_ne_bytes())
        .collect();
    for internal in [
        GL_DEPTH24_STENCIL8_EXT,
        GL_DEPTH_COMPONENT24,
        GL_DEPTH_COMPONENT16,
    ] {
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            internal as i32,
            2,
            2,
            0,
            GL_DEPTH_STENCIL_EXT,
            GL_UNSIGNED_INT_24_8_EXT,
            Some(&words),
        );
        err(gl, out, &format!("tex_image_2d 0x{internal:04x} from 24_8"));
        // The lower row again through glTexSubImage2D, swapped.
        let row: Vec<u8> = words[4..8].iter().chain(&words[0..4]).copied().collect();
        gl.tex_sub_image_2d(
            GL_TEXTURE_2D,
            0,
            0,
            0,
            2,
            1,
            GL_DEPTH_STENCIL_EXT,
            GL_UNSIGNED_INT_24_8_EXT,
            Some(&row),
        );
        err(gl, out, "tex_sub_image_2d from 24_8");
        let mut back = [0u8; 8];
        gl.get_tex_image(
            GL_TEXTURE_2D,
            0,
            GL_DEPTH_COMPONENT,
            GL_UNSIGNED_SHORT,
            &mut back,
        );
        out.push(Answer {
            label: format!("0x{internal:04x} read back"),
            values: back
                .chunks(2)
                .map(|c| u16::from_ne_bytes([c[0], c[1]]) as f64)
                .collect(),
            tolerance: 1.0,
        });
        // Depth and stencil packed back, with the stencil indices distinct per texel.
        let words2: Vec<u8> = [0x1234_5601u32, 0x89ab_cd7f, 0x0000_0080, 0xffff_ffff]
            .iter()
            .flat_map(|w| w.to_ne_bytes())
            .collect();
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            internal as i32,
            2,
            2,
            0,
            GL_DEPTH_STENCIL_EXT,
            GL_UNSIGNED_INT_24_8_EXT,
            Some(&words2),
        );
        let mut packed = [0u8; 16];
        gl.get_tex_image(
            GL_TEXTURE_2D,
            0,
            GL_DEPTH_STENCIL_EXT,
            GL_UNSIGNED_INT_24_8_EXT,
            &mut packed,
        );
        err(
            gl,
            out,
            &format!("get_tex_image 0x{internal:04x} as DEPTH_STENCIL"),
        );
        if internal == GL_DEPTH24_STENCIL8_EXT {
            let words: Vec<u32> = packed
                .chunks(4)
                .map(|c| u32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
                .collect();
            exact(
                out,
                "stencil read back".into(),
                words.iter().map(|w| (w & 0xff) as f64).collect(),
            );
            out.push(Answer {
                label: "depth read back (24 bits)".into(),
                values: words.iter().map(|w| (w >> 8) as f64).collect(),
                tolerance: 1.0,
            });
        }
    }
    let data = [0u8; 64];
    for (internal, format, ty) in [
        (GL_DEPTH_COMPONENT16, GL_STENCIL_INDEX, GL_INT),
        (GL_DEPTH24_STENCIL8_EXT, GL_STENCIL_INDEX, GL_INT),
        (GL_RGBA8, GL_DEPTH_COMPONENT, GL_FLOAT),
        (GL_RGBA8, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT),
        (
            GL_DEPTH_COMPONENT24,
            GL_DEPTH_COMPONENT,
            GL_UNSIGNED_INT_24_8_EXT,
        ),
        (GL_RGBA8, GL_RGBA, GL_UNSIGNED_INT_24_8_EXT),
    ] {
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            internal as i32,
            2,
            2,
            0,
            format,
            ty,
            Some(&data),
        );
        err(
            gl,
            out,
            &format!("tex_image_2d 0x{internal:04x} 0x{format:04x} 0x{ty:04x}"),
        );
    }
}

/// piglit's gl-1.0-beginend-coverage, the parts where tilegl and Mesa agree (the lighting
/// commands' scalar forms with vector parameters are GL_INVALID_ENUM by section 2.14.2; Mesa
/// accepts them, so `tests/state_errors.rs` checks those against the specification).
fn piglit_beginend_coverage(gl: &mut dyn Gl, out: &mut Answers) {
    let get_f = |gl: &mut dyn Gl, out: &mut Answers, pname: GLenum, label: &str| {
        let mut v = [-9.0f32];
        gl.get_floatv(pname, &mut v);
        exact(out, label.into(), vec![v[0] as f64]);
    };
    gl.indexf(7.5);
    err(gl, out, "indexf");
    get_f(gl, out, GL_CURRENT_INDEX, "current index after indexf(7.5)");
    gl.indexub(200);
    get_f(
        gl,
        out,
        GL_CURRENT_INDEX,
        "current index after indexub(200)",
    );
    gl.begin(GL_POINTS);
    gl.indexi(9);
    gl.indexsv(&[11]);
    gl.end();
    err(gl, out, "indexi, indexsv between begin and end");
    get_f(gl, out, GL_CURRENT_INDEX, "current index after indexsv(11)");
    gl.clear_index(3.0);
    gl.index_mask(5);
    err(gl, out, "clear_index, index_mask");
    get_f(gl, out, GL_INDEX_CLEAR_VALUE, "index clear value");
    let mut m = [0];
    gl.get_integerv(GL_INDEX_WRITEMASK, &mut m);
    exact(out, "index write mask".into(), vec![m[0] as f64]);
    gl.begin(GL_POINTS);
    gl.clear_index(4.0);
    gl.end();
    err(gl, out, "clear_index between begin and end");
    gl.begin(GL_POINTS);
    gl.index_mask(4);
    gl.end();
    err(gl, out, "index_mask between begin and end");
    for (pname, f) in [(GL_OBJECT_PLANE, 0.5), (GL_EYE_PLANE, 2.0)] {
        gl.tex_genf(GL_S, pname, f);
        err(gl, out, &format!("tex_genf 0x{pname:04x}"));
        let mut v = [-9.0f32; 4];
        gl.get_tex_genfv(GL_S, pname, &mut v);
        exact(
            out,
            format!("plane 0x{pname:04x}"),
            v.map(|x| x as f64).to_vec(),
        );
    }
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.5);
    err(gl, out, "tex_parameterf(GL_TEXTURE_BORDER_COLOR)");
    // Array draws from a list, executed inside glBegin/glEnd.
    let verts = [0.0f32; 8];
    gl.vertex_pointer(2, GL_FLOAT, 0, tilegl::ClientPtr(verts.as_ptr() as usize));
    for enabled in [false, true] {
        if enabled {
            gl.enable_client_state(GL_VERTEX_ARRAY);
        }
        gl.new_list(5, GL_COMPILE);
        gl.draw_arrays(GL_POINTS, 0, 1);
        gl.end_list();
        gl.new_list(6, GL_COMPILE);
        gl.draw_elements(
            GL_POINTS,
            1,
            GL_UNSIGNED_INT,
            tilegl::ClientPtr([0u32].as_ptr() as usize),
        );
        gl.end_list();
        err(gl, out, "compiling array draws");
        for list in [5, 6] {
            gl.begin(GL_POINTS);
            gl.call_list(list);
            gl.end();
            err(
                gl,
                out,
                &format!("list {list} between begin and end, arrays {enabled}"),
            );
            gl.new_list(7, GL_COMPILE);
            gl.begin(GL_POINTS);
            gl.call_list(list);
            gl.end();
            gl.end_list();
            gl.call_list(7);
            err(
                gl,
                out,
                &format!("list of begin, list {list}, end, arrays {enabled}"),
            );
        }
        gl.new_list(8, GL_COMPILE);
        gl.begin(GL_POINTS);
        gl.draw_arrays(GL_POINTS, 0, 1);
        gl.end();
        gl.end_list();
        err(gl, out, "compiling begin, draw_arrays, end");
        gl.call_list(8);
        err(
            gl,
            out,
            &format!("list of begin, draw_arrays, end, arrays {enabled}"),
        );
        gl.new_list(8, GL_COMPILE_AND_EXECUTE);
        gl.begin(GL_POINTS);
        gl.draw_arrays(GL_POINTS, 0, 1);
        gl.end();
        gl.end_list();
        err(gl, out, "compile-and-execute begin, draw_arrays, end");
        gl.call_list(8);
        err(gl, out, "that list called");
    }
    gl.disable_client_state(GL_VERTEX_ARRAY);
    gl.delete_lists(5, 4);
}

/// Error codes piglit's copyteximage, max-texture-size-level and draw-pixels expect, and
/// glEnable of an array's name (several piglit GL 1.x tests enable their arrays so).
fn piglit_errors(gl: &mut dyn Gl, out: &mut Answers) {
    for f in 1..=4 {
        gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, f, 0, 0, 4, 4, 0);
        err(gl, out, &format!("copy_tex_image_2d internalformat {f}"));
    }
    let mut max = [0];
    gl.get_integerv(GL_MAX_TEXTURE_SIZE, &mut max);
    for level in 1..3 {
        let size = max[0] >> (level - 1);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            level,
            GL_RGBA as i32,
            size,
            1,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            None,
        );
        err(
            gl,
            out,
            &format!("tex_image_2d level {level} width max/2^{}", level - 1),
        );
    }
    let data = [0u8; 64];
    for format in [
        GL_STENCIL_INDEX,
        GL_DEPTH_COMPONENT,
        GL_LUMINANCE,
        GL_RGBA,
        GL_RGB,
    ] {
        for ty in [GL_UNSIGNED_BYTE_3_3_2, GL_UNSIGNED_SHORT_4_4_4_4] {
            gl.draw_pixels(2, 2, format, ty, Some(&data));
            err(gl, out, &format!("draw_pixels 0x{format:04x} 0x{ty:04x}"));
        }
    }
    for array in [GL_VERTEX_ARRAY, GL_COLOR_ARRAY, GL_NORMAL_ARRAY] {
        gl.enable(array);
        let on = gl.is_enabled(array);
        err(gl, out, &format!("enable(0x{array:04x})"));
        gl.disable(array);
        let off = gl.is_enabled(array);
        exact(
            out,
            format!("is_enabled(0x{array:04x}) after enable, disable"),
            vec![on as f64, off as f64],
        );
    }
}

/// Reads a `w` x `h` rectangle as GL_DEPTH_STENCIL / GL_UNSIGNED_INT_24_8 and records each
/// word's depth (within one unit of 24 bits) and stencil index (exact).
fn read_depth_stencil(gl: &mut dyn Gl, out: &mut Answers, label: &str, w: i32, h: i32) {
    let mut words = vec![0u8; (w * h * 4) as usize];
    gl.read_pixels(
        0,
        0,
        w,
        h,
        GL_DEPTH_STENCIL_EXT,
        GL_UNSIGNED_INT_24_8_EXT,
        &mut words,
    );
    let words: Vec<u32> = words
        .chunks(4)
        .map(|c| u32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    out.push(Answer {
        label: format!("{label}: depths (24 bits)"),
        values: words.iter().map(|w| (w >> 8) as f64).collect(),
        tolerance: 1.0,
    });
    exact(
        out,
        format!("{label}: stencil indices"),
        words.iter().map(|w| (w & 0xff) as f64).collect(),
    );
    err(gl, out, label);
}

/// piglit's depthstencil-default_fb-readpixels-24_8 and -drawpixels-24_8: glReadPixels and
/// glDrawPixels with GL_DEPTH_STENCIL / GL_UNSIGNED_INT_24_8 (EXT_packed_depth_stencil), with
/// depth scale and bias and (on read-back) index offset, the depth and stencil write masks, the depth test off, and
/// the errors of other types and formats.
fn piglit_depth_stencil_pixels(gl: &mut dyn Gl, out: &mut Answers) {
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear_depth(0.75);
    gl.clear_stencil(0x12);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    // The right half of a 4 x 2 rectangle at another depth and stencil.
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(2, 0, 2, 2);
    gl.clear_depth(0.375);
    gl.clear_stencil(0xc3);
    gl.clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.disable(GL_SCISSOR_TEST);
    gl.pixel_storei(GL_PACK_ALIGNMENT, 1);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    read_depth_stencil(gl, out, "read cleared", 4, 2);
    gl.pixel_transferf(GL_DEPTH_SCALE, 0.5);
    gl.pixel_transferf(GL_DEPTH_BIAS, 0.125);
    gl.pixel_transferi(GL_INDEX_OFFSET, 3);
    read_depth_stencil(
        gl,
        out,
        "read with depth scale 0.5, bias 0.125, index offset 3",
        4,
        2,
    );

    // Drawn with the same depth transfer (d / 2 + 1/8). The index offset is left out: llvmpipe
    // applies it to glReadPixels' stencil but not to glDrawPixels' (tilegl does, as for
    // GL_STENCIL_INDEX; tests/pixel_rect.rs checks that).
    gl.pixel_transferi(GL_INDEX_OFFSET, 0);
    let words: Vec<u8> = [
        (0x00_0000u32, 0x00u32),
        (0xff_ffff, 0xff),
        (0x80_0000, 0x40),
        (0x40_0000, 0x0f),
        (0x12_3456, 0x81),
        (0xc0_0000, 0xfc),
    ]
    .iter()
    .flat_map(|&(d, s)| ((d << 8) | s).to_ne_bytes())
    .collect();
    gl.window_pos_2i(0, 0);
    gl.draw_pixels(
        3,
        2,
        GL_DEPTH_STENCIL_EXT,
        GL_UNSIGNED_INT_24_8_EXT,
        Some(&words),
    );
    err(
        gl,
        out,
        "draw_pixels(GL_DEPTH_STENCIL) with transfer, depth test off",
    );
    gl.pixel_transferf(GL_DEPTH_SCALE, 1.0);
    gl.pixel_transferf(GL_DEPTH_BIAS, 0.0);
    read_depth_stencil(gl, out, "read after draw", 4, 2);
    let mut color = [0u8; 4 * 4 * 2];
    gl.read_pixels(0, 0, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, &mut color);
    exact(
        out,
        "colour after draw".into(),
        color.iter().map(|&c| c as f64).collect(),
    );

    // Depth mask off and stencil write mask 0x0f: the stencil's low bits only.
    gl.depth_mask(0);
    gl.stencil_mask(0x0f);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_NEVER);
    gl.window_pos_2i(1, 1);
    gl.draw_pixels(
        3,
        1,
        GL_DEPTH_STENCIL_EXT,
        GL_UNSIGNED_INT_24_8_EXT,
        Some(&words[..12]),
    );
    err(gl, out, "draw_pixels with masks, depth func never");
    gl.depth_mask(1);
    gl.stencil_mask(0xff);
    gl.disable(GL_DEPTH_TEST);
    read_depth_stencil(gl, out, "read after masked draw", 4, 2);

    // Other types with GL_DEPTH_STENCIL, and GL_UNSIGNED_INT_24_8 with other formats.
    let mut buf = [0u8; 64];
    for ty in [GL_UNSIGNED_INT, GL_FLOAT, GL_UNSIGNED_BYTE] {
        gl.read_pixels(0, 0, 1, 1, GL_DEPTH_STENCIL_EXT, ty, &mut buf);
        err(
            gl,
            out,
            &format!("read_pixels(GL_DEPTH_STENCIL, 0x{ty:04x})"),
        );
        gl.draw_pixels(1, 1, GL_DEPTH_STENCIL_EXT, ty, Some(&buf));
        err(
            gl,
            out,
            &format!("draw_pixels(GL_DEPTH_STENCIL, 0x{ty:04x})"),
        );
    }
    for format in [GL_DEPTH_COMPONENT, GL_STENCIL_INDEX, GL_RGBA] {
        gl.read_pixels(0, 0, 1, 1, format, GL_UNSIGNED_INT_24_8_EXT, &mut buf);
        err(gl, out, &format!("read_pixels(0x{format:04x}, 24_8)"));
        gl.draw_pixels(1, 1, format, GL_UNSIGNED_INT_24_8_EXT, Some(&buf));
        err(gl, out, &format!("draw_pixels(0x{format:04x}, 24_8)"));
    }
}

/// piglit's getteximage-depth with EXT_packed_depth_stencil listed: depth-stencil images
/// uploaded and read back with glGetTexImage(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8), the
/// depth of each word compared (tilegl's depth textures keep no stencil), and the error of
/// reading a colour image so.
fn piglit_get_tex_image_depth_stencil(gl: &mut dyn Gl, out: &mut Answers) {
    let words: Vec<u8> = (0..8u32)
        .flat_map(|x| ((0xffff_ff00u32 as f32 * (x as f32 / 7.0)) as u32 | 0x5a).to_ne_bytes())
        .collect();
    for (target, internal) in [
        (GL_TEXTURE_2D, GL_DEPTH24_STENCIL8_EXT),
        (GL_TEXTURE_2D, GL_DEPTH_STENCIL_EXT),
        (GL_TEXTURE_RECTANGLE_ARB, GL_DEPTH24_STENCIL8_EXT),
    ] {
        gl.tex_image_2d(
            target,
            0,
            internal as i32,
            4,
            2,
            0,
            GL_DEPTH_STENCIL_EXT,
            GL_UNSIGNED_INT_24_8_EXT,
            Some(&words),
        );
        err(gl, out, &format!("upload 0x{target:04x} 0x{internal:04x}"));
        let mut back = [0u8; 32];
        gl.get_tex_image(
            target,
            0,
            GL_DEPTH_STENCIL_EXT,
            GL_UNSIGNED_INT_24_8_EXT,
            &mut back,
        );
        err(gl, out, "get_tex_image(GL_DEPTH_STENCIL)");
        out.push(Answer {
            label: format!("0x{target:04x} 0x{internal:04x} depths read back (24 bits)"),
            values: back
                .chunks(4)
                .map(|c| (u32::from_ne_bytes([c[0], c[1], c[2], c[3]]) >> 8) as f64)
                .collect(),
            tolerance: 1.0,
        });
    }
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[1, 2, 3, 4]),
    );
    let mut back = [0u8; 4];
    gl.get_tex_image(
        GL_TEXTURE_2D,
        0,
        GL_DEPTH_STENCIL_EXT,
        GL_UNSIGNED_INT_24_8_EXT,
        &mut back,
    );
    err(gl, out, "get_tex_image(GL_DEPTH_STENCIL) of an RGBA image");
}

/// piglit's tex3d-maxsize probe (and max-texture-size's 2D one): proxy images halved one side
/// at a time, as the test does, until one is accepted; every step's answers are recorded, so
/// the first size accepted is Mesa's.
fn piglit_proxy_memory_limit(gl: &mut dyn Gl, out: &mut Answers) {
    let probe = |gl: &mut dyn Gl, out: &mut Answers, target: GLenum, ifmt: GLenum, start: i32| {
        let dims = if target == GL_PROXY_TEXTURE_3D { 3 } else { 2 };
        let mut size = [start, start, if dims == 3 { start } else { 1 }];
        let mut dim = 0;
        while size.iter().all(|&s| s >= 1) {
            if dims == 3 {
                gl.tex_image_3d(
                    target,
                    0,
                    ifmt as i32,
                    size[0],
                    size[1],
                    size[2],
                    0,
                    GL_RGBA,
                    GL_UNSIGNED_BYTE,
                    None,
                );
            } else {
                gl.tex_image_2d(
                    target,
                    0,
                    ifmt as i32,
                    size[0],
                    size[1],
                    0,
                    GL_RGBA,
                    GL_UNSIGNED_BYTE,
                    None,
                );
            }
            let mut got = Vec::new();
            for p in [GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_DEPTH] {
                let mut v = [-1];
                gl.get_tex_level_parameteriv(target, 0, p, &mut v);
                got.push(v[0] as f64);
            }
            let label = format!("proxy 0x{target:04x} 0x{ifmt:04x} {size:?}");
            exact(out, label.clone(), got.clone());
            err(gl, out, &label);
            if got[0] as i32 == size[0] {
                return;
            }
            size[dim] /= 2;
            dim = (dim + 1) % dims;
        }
    };
    let mut max = [0];
    gl.get_integerv(GL_MAX_3D_TEXTURE_SIZE, &mut max);
    for ifmt in [GL_INTENSITY8, GL_RGBA8, GL_RGBA32F_ARB] {
        probe(gl, out, GL_PROXY_TEXTURE_3D, ifmt, max[0]);
    }
    gl.get_integerv(GL_MAX_TEXTURE_SIZE, &mut max);
    for ifmt in [GL_RGBA8, GL_RGBA32F_ARB] {
        probe(gl, out, GL_PROXY_TEXTURE_2D, ifmt, max[0]);
    }
}

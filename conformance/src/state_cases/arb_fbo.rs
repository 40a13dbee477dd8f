//! ARB_framebuffer_object: the same calls on Mesa and on tilegl (Rust API and C ABI), every
//! answer (statuses, queries, GL errors, read-backs) equal to Mesa's. The commands are called
//! by their unsuffixed names (`glBindFramebuffer`, `glRenderbufferStorageMultisample`,
//! `glFramebufferTextureLayer` are their own entry points; the others are aliases of the EXT
//! ones). Where the extension's text and Mesa 22's compatibility profile differ (binding a
//! name `glGen*` did not return, `GL_MAX_SAMPLES`, a depth-only object whose draw buffer is
//! not `GL_NONE`) tilegl keeps the text, checked by `tests/arb_fbo.rs`; no case here goes
//! there.

super::state_case_list!(source = include_str!("arb_fbo.rs"), agree = |a: &Answer, b: &Answer| {
    a.values.len() == b.values.len()
        && a.values
            .iter()
            .zip(&b.values)
            .all(|(x, y)| (x - y).abs() <= a.tolerance)
};
    arb_fbo_bindings_and_storage: "Generated names bound through glBindFramebuffer to GL_DRAW_FRAMEBUFFER, GL_READ_FRAMEBUFFER and GL_FRAMEBUFFER, the three binding queries, glIsFramebuffer/glIsRenderbuffer before and after binding, deletion unbinding both targets, glRenderbufferStorageMultisample with 0 samples (sizes, internal format, GL_RENDERBUFFER_SAMPLES) and its errors (a negative sample count, a bad target or format, a negative width, no bound renderbuffer; Mesa accepts counts above GL_MAX_SAMPLES, which the extension makes GL_INVALID_VALUE: tests/arb_fbo.rs). Every answer equals Mesa's.",
    arb_fbo_depth_stencil_attachment: "GL_DEPTH_STENCIL_ATTACHMENT: a packed depth-stencil renderbuffer attached to both points at once, the type and name queries of the depth, stencil and combined points, depth- and stencil-tested drawing read back, different images at the two points (the combined query fails with GL_INVALID_OPERATION) and detaching both with 0. Every answer equals Mesa's (depths within two units of 24 bits).",
    arb_fbo_attachment_formats: "The format queries of section 6.1.3 (GL_FRAMEBUFFER_ATTACHMENT_RED/GREEN/BLUE/ALPHA/DEPTH/STENCIL_SIZE, COMPONENT_TYPE, COLOR_ENCODING) of RGBA8 and RGB8 renderbuffers and textures, a 24-bit depth renderbuffer and texture and a packed depth-stencil renderbuffer at each point; an empty point (its name 0, anything else GL_INVALID_OPERATION) and texture-only queries of a renderbuffer (GL_INVALID_ENUM). Every answer equals Mesa's.",
    arb_fbo_mixed_sizes: "Attachments of different sizes (a 16x12 colour texture with an 8x16 depth renderbuffer) are complete; clears and depth-tested quads inside the common 8x12 rectangle, read back while bound and through glGetTexImage (the common rectangle only). Every answer equals Mesa's.",
    arb_fbo_color_renderable_formats: "ALPHA8, LUMINANCE8, LUMINANCE8_ALPHA8 and RGB8 textures as colour attachments: complete, cleared, drawn into with blending (GL_SRC_ALPHA and GL_DST_ALPHA factors), read back while bound (the components the image lacks read 0, alpha 1) and through glGetTexImage. Every answer equals Mesa's, except LUMINANCE8's blended luminance, within one unit (llvmpipe rounds it down).",
    arb_fbo_texture_layer: "glFramebufferTextureLayer: each layer of a 3D texture attached in turn and cleared to its own colour, the layer and level queries, status, glGetTexImage of the whole texture, and the errors (a 2D texture: GL_INVALID_OPERATION; a negative layer or level, a level beyond the largest: GL_INVALID_VALUE; an unknown attachment point or target: GL_INVALID_ENUM). Every answer equals Mesa's.",
    arb_fbo_blit_and_mipmap: "glBlitFramebuffer between two framebuffer objects bound separately to GL_READ_FRAMEBUFFER and GL_DRAW_FRAMEBUFFER (1:1 and mirrored, GL_NEAREST), glCheckFramebufferStatus of each target, then glGenerateMipmap of the texture drawn into and its level 1 read back. Every answer equals Mesa's.",
);

use super::fbo::{err, exact, int, pixel_space, quad, read_rgba, Answer, Answers};
use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::Gl;

fn status_of(gl: &mut dyn Gl, out: &mut Answers, target: GLenum, label: &str) {
    let s = gl.check_framebuffer_status_ext(target);
    exact(out, format!("status {label}"), vec![s as f64]);
}

fn gen_framebuffer(gl: &mut dyn Gl) -> u32 {
    let mut f = [0];
    gl.gen_framebuffers_ext(1, &mut f);
    f[0]
}

fn renderbuffer(gl: &mut dyn Gl, format: GLenum, w: i32, h: i32) -> u32 {
    let mut rb = [0];
    gl.gen_renderbuffers_ext(1, &mut rb);
    gl.bind_renderbuffer(GL_RENDERBUFFER, rb[0]);
    gl.renderbuffer_storage_multisample(GL_RENDERBUFFER, 0, format, w, h);
    rb[0]
}

fn texture_2d(gl: &mut dyn Gl, format: GLenum, w: i32, h: i32) -> u32 {
    let mut t = [0];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    let data_format = if format == GL_DEPTH_COMPONENT24 {
        GL_DEPTH_COMPONENT
    } else {
        GL_RGBA
    };
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        format as i32,
        w,
        h,
        0,
        data_format,
        GL_UNSIGNED_BYTE,
        None,
    );
    t[0]
}

fn attachment(gl: &mut dyn Gl, out: &mut Answers, point: GLenum, pname: GLenum, label: &str) {
    let mut v = [-1];
    gl.get_framebuffer_attachment_parameteriv_ext(GL_FRAMEBUFFER, point, pname, &mut v);
    exact(
        out,
        format!("attachment 0x{point:04x} 0x{pname:04x} {label}"),
        vec![v[0] as f64],
    );
    err(gl, out, &format!("attachment query 0x{pname:04x} {label}"));
}

fn renderbuffer_param(gl: &mut dyn Gl, out: &mut Answers, pname: GLenum) {
    let mut v = [-1];
    gl.get_renderbuffer_parameteriv_ext(GL_RENDERBUFFER, pname, &mut v);
    exact(
        out,
        format!("glGetRenderbufferParameteriv(0x{pname:04x})"),
        vec![v[0] as f64],
    );
    err(gl, out, "glGetRenderbufferParameteriv");
}

fn get_tex_image(gl: &mut dyn Gl, out: &mut Answers, target: GLenum, level: i32, n: usize) {
    let mut texels = vec![0u8; n * 4];
    gl.get_tex_image(target, level, GL_RGBA, GL_UNSIGNED_BYTE, &mut texels);
    exact(
        out,
        format!("glGetTexImage 0x{target:04x} level {level}"),
        texels.iter().map(|&v| v as f64).collect(),
    );
    err(gl, out, "glGetTexImage");
}

fn is_objects(gl: &mut dyn Gl, out: &mut Answers, fb: u32, rb: u32, label: &str) {
    let f = gl.is_framebuffer_ext(fb);
    let r = gl.is_renderbuffer_ext(rb);
    exact(
        out,
        format!("glIsFramebuffer/glIsRenderbuffer {label}"),
        vec![f as f64, r as f64],
    );
}

/// Bindings of generated names and renderbuffer storage with 0 samples.
fn arb_fbo_bindings_and_storage(gl: &mut dyn Gl, out: &mut Answers) {
    let (a, b) = (gen_framebuffer(gl), gen_framebuffer(gl));
    let mut rb = [0];
    gl.gen_renderbuffers_ext(1, &mut rb);
    is_objects(gl, out, a, rb[0], "generated, unbound");
    gl.bind_framebuffer(GL_DRAW_FRAMEBUFFER, a);
    gl.bind_framebuffer(GL_READ_FRAMEBUFFER, b);
    err(gl, out, "glBindFramebuffer of generated names");
    is_objects(gl, out, a, rb[0], "after binding the framebuffer");
    for q in [
        GL_FRAMEBUFFER_BINDING,
        GL_DRAW_FRAMEBUFFER_BINDING,
        GL_READ_FRAMEBUFFER_BINDING,
    ] {
        int(gl, out, q);
    }
    gl.bind_framebuffer(GL_FRAMEBUFFER, b);
    int(gl, out, GL_DRAW_FRAMEBUFFER_BINDING);
    int(gl, out, GL_READ_FRAMEBUFFER_BINDING);
    gl.bind_framebuffer(0x1234, a);
    err(gl, out, "glBindFramebuffer with a bad target");
    // Storage: no renderbuffer bound yet.
    gl.renderbuffer_storage_multisample(GL_RENDERBUFFER, 0, GL_RGBA8, 4, 4);
    err(gl, out, "storage without a bound renderbuffer");
    gl.bind_renderbuffer(GL_RENDERBUFFER, rb[0]);
    err(gl, out, "glBindRenderbuffer of a generated name");
    is_objects(gl, out, a, rb[0], "after binding the renderbuffer");
    int(gl, out, GL_RENDERBUFFER_BINDING);
    for p in [
        GL_RENDERBUFFER_WIDTH,
        GL_RENDERBUFFER_INTERNAL_FORMAT,
        GL_RENDERBUFFER_SAMPLES,
    ] {
        renderbuffer_param(gl, out, p);
    }
    gl.renderbuffer_storage_multisample(GL_RENDERBUFFER, 0, GL_RGBA8, 12, 6);
    err(gl, out, "glRenderbufferStorageMultisample 0 samples");
    for p in [
        GL_RENDERBUFFER_WIDTH,
        GL_RENDERBUFFER_HEIGHT,
        GL_RENDERBUFFER_INTERNAL_FORMAT,
        GL_RENDERBUFFER_SAMPLES,
        GL_RENDERBUFFER_RED_SIZE,
        GL_RENDERBUFFER_ALPHA_SIZE,
        GL_RENDERBUFFER_DEPTH_SIZE,
    ] {
        renderbuffer_param(gl, out, p);
    }
    gl.renderbuffer_storage_multisample(GL_RENDERBUFFER, -1, GL_RGBA8, 4, 4);
    err(gl, out, "negative samples");
    gl.renderbuffer_storage_multisample(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4);
    err(gl, out, "storage with a bad target");
    gl.renderbuffer_storage_multisample(GL_RENDERBUFFER, 0, 0x1234, 4, 4);
    err(gl, out, "storage with a bad format");
    gl.renderbuffer_storage_multisample(GL_RENDERBUFFER, 0, GL_RGBA8, -1, 4);
    err(gl, out, "storage with a negative width");
    renderbuffer_param(gl, out, GL_RENDERBUFFER_WIDTH);
    gl.delete_framebuffers_ext(1, &[b]);
    int(gl, out, GL_DRAW_FRAMEBUFFER_BINDING);
    int(gl, out, GL_READ_FRAMEBUFFER_BINDING);
    gl.delete_renderbuffers_ext(1, &rb);
    int(gl, out, GL_RENDERBUFFER_BINDING);
    is_objects(gl, out, b, rb[0], "deleted");
    is_objects(gl, out, a, 0, "the other framebuffer; renderbuffer 0");
    gl.bind_framebuffer(GL_FRAMEBUFFER, 0);
    err(gl, out, "binding 0");
}

/// GL_DEPTH_STENCIL_ATTACHMENT with a packed depth-stencil renderbuffer.
fn arb_fbo_depth_stencil_attachment(gl: &mut dyn Gl, out: &mut Answers) {
    let fb = gen_framebuffer(gl);
    gl.bind_framebuffer(GL_FRAMEBUFFER, fb);
    let color = renderbuffer(gl, GL_RGBA8, 16, 16);
    let ds = renderbuffer(gl, GL_DEPTH24_STENCIL8, 16, 16);
    gl.framebuffer_renderbuffer_ext(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER,
        GL_DEPTH_STENCIL_ATTACHMENT,
        GL_RENDERBUFFER,
        ds,
    );
    err(gl, out, "attach at GL_DEPTH_STENCIL_ATTACHMENT");
    status_of(gl, out, GL_FRAMEBUFFER, "colour + depth-stencil");
    for point in [
        GL_DEPTH_ATTACHMENT,
        GL_STENCIL_ATTACHMENT,
        GL_DEPTH_STENCIL_ATTACHMENT,
    ] {
        attachment(
            gl,
            out,
            point,
            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
            "depth-stencil",
        );
        attachment(
            gl,
            out,
            point,
            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
            "depth-stencil",
        );
    }
    int(gl, out, GL_DEPTH_BITS);
    int(gl, out, GL_STENCIL_BITS);
    pixel_space(gl, 16, 16);
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear_depth(1.0);
    gl.clear_stencil(0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_ALWAYS, 1, 0xff);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
    gl.color_4f(1.0, 0.0, 0.0, 1.0);
    quad(gl, 0.0, 0.0, 10.0, 10.0, 0.5);
    gl.stencil_func(GL_EQUAL, 1, 0xff);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_INCR);
    gl.color_4f(0.0, 1.0, 0.0, 1.0);
    quad(gl, 4.0, 4.0, 16.0, 16.0, -0.5);
    gl.disable(GL_STENCIL_TEST);
    gl.disable(GL_DEPTH_TEST);
    err(gl, out, "depth- and stencil-tested drawing");
    read_rgba(gl, out, "depth-stencil object", 0, 0, 16, 16);
    let mut bytes = vec![0u8; 16 * 16 * 4];
    gl.read_pixels(0, 0, 16, 16, GL_DEPTH_COMPONENT, GL_FLOAT, &mut bytes);
    out.push(Answer {
        label: "depth of the depth-stencil object".into(),
        values: super::fbo::floats(&bytes)
            .iter()
            .map(|&d| d as f64)
            .collect(),
        tolerance: 2.0 / 16777215.0,
    });
    let mut stencil = vec![0u8; 16 * 16];
    gl.read_pixels(
        0,
        0,
        16,
        16,
        GL_STENCIL_INDEX,
        GL_UNSIGNED_BYTE,
        &mut stencil,
    );
    exact(
        out,
        "stencil of the depth-stencil object".into(),
        stencil.iter().map(|&s| s as f64).collect(),
    );
    err(gl, out, "reading depth and stencil");
    // Different images at the two points: the combined query fails.
    let depth_only = renderbuffer(gl, GL_DEPTH_COMPONENT24, 16, 16);
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER,
        GL_DEPTH_ATTACHMENT,
        GL_RENDERBUFFER,
        depth_only,
    );
    // (The status is implementation-dependent here: Mesa answers GL_FRAMEBUFFER_UNSUPPORTED
    // for separate depth and stencil images, tilegl, which keeps them apart anyway, complete.)
    attachment(
        gl,
        out,
        GL_DEPTH_STENCIL_ATTACHMENT,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
        "different images",
    );
    attachment(
        gl,
        out,
        GL_STENCIL_ATTACHMENT,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
        "different images",
    );
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER,
        GL_DEPTH_STENCIL_ATTACHMENT,
        GL_RENDERBUFFER,
        0,
    );
    err(gl, out, "detach both");
    for point in [GL_DEPTH_ATTACHMENT, GL_STENCIL_ATTACHMENT] {
        attachment(
            gl,
            out,
            point,
            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
            "detached",
        );
    }
    int(gl, out, GL_DEPTH_BITS);
    gl.bind_framebuffer(GL_FRAMEBUFFER, 0);
}

/// The format queries of attached images.
fn arb_fbo_attachment_formats(gl: &mut dyn Gl, out: &mut Answers) {
    const SIZES: [GLenum; 8] = [
        GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE,
        GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE,
        GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE,
        GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE,
        GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE,
        GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE,
        GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE,
        GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING,
    ];
    let fb = gen_framebuffer(gl);
    gl.bind_framebuffer(GL_FRAMEBUFFER, fb);
    // An empty point: its type and name, nothing else.
    attachment(
        gl,
        out,
        GL_COLOR_ATTACHMENT0,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
        "empty",
    );
    attachment(
        gl,
        out,
        GL_COLOR_ATTACHMENT0,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
        "empty",
    );
    attachment(
        gl,
        out,
        GL_COLOR_ATTACHMENT0,
        GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE,
        "empty",
    );
    attachment(
        gl,
        out,
        GL_COLOR_ATTACHMENT0,
        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL,
        "empty",
    );
    for (format, label) in [(GL_RGBA8, "RGBA8"), (GL_RGB8, "RGB8")] {
        let rb = renderbuffer(gl, format, 8, 8);
        gl.framebuffer_renderbuffer_ext(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
        let label = format!("{label} renderbuffer");
        for p in SIZES {
            attachment(gl, out, GL_COLOR_ATTACHMENT0, p, &label);
        }
        attachment(
            gl,
            out,
            GL_COLOR_ATTACHMENT0,
            GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL,
            &label,
        );
        let tex = texture_2d(gl, format, 8, 8);
        gl.framebuffer_texture_2dext(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
        let label = label.replace("renderbuffer", "texture");
        for p in SIZES {
            attachment(gl, out, GL_COLOR_ATTACHMENT0, p, &label);
        }
        attachment(
            gl,
            out,
            GL_COLOR_ATTACHMENT0,
            GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE,
            &label,
        );
    }
    let depth = renderbuffer(gl, GL_DEPTH_COMPONENT24, 8, 8);
    gl.framebuffer_renderbuffer_ext(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    for p in SIZES {
        attachment(gl, out, GL_DEPTH_ATTACHMENT, p, "depth renderbuffer");
    }
    let dtex = texture_2d(gl, GL_DEPTH_COMPONENT24, 8, 8);
    gl.framebuffer_texture_2dext(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, dtex, 0);
    for p in SIZES {
        attachment(gl, out, GL_DEPTH_ATTACHMENT, p, "depth texture");
    }
    let ds = renderbuffer(gl, GL_DEPTH24_STENCIL8, 8, 8);
    gl.framebuffer_renderbuffer_ext(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ds);
    gl.framebuffer_renderbuffer_ext(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds);
    for point in [GL_DEPTH_ATTACHMENT, GL_STENCIL_ATTACHMENT] {
        for p in SIZES {
            if p == GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE {
                continue;
            }
            attachment(gl, out, point, p, "depth-stencil renderbuffer");
        }
    }
    attachment(
        gl,
        out,
        GL_DEPTH_ATTACHMENT,
        GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE,
        "depth-stencil renderbuffer",
    );
    status_of(
        gl,
        out,
        GL_FRAMEBUFFER,
        "RGB8 texture, depth-stencil renderbuffer",
    );
    gl.bind_framebuffer(GL_FRAMEBUFFER, 0);
}

/// Attachments of different sizes draw into their common rectangle.
fn arb_fbo_mixed_sizes(gl: &mut dyn Gl, out: &mut Answers) {
    let tex = texture_2d(gl, GL_RGBA8, 16, 12);
    let mut zero = vec![0u8; 16 * 12 * 4];
    zero.iter_mut()
        .enumerate()
        .for_each(|(i, v)| *v = (i % 7) as u8);
    gl.tex_sub_image_2d(
        GL_TEXTURE_2D,
        0,
        0,
        0,
        16,
        12,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&zero),
    );
    let fb = gen_framebuffer(gl);
    gl.bind_framebuffer(GL_FRAMEBUFFER, fb);
    gl.framebuffer_texture_2dext(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    let depth = renderbuffer(gl, GL_DEPTH_COMPONENT24, 8, 16);
    gl.framebuffer_renderbuffer_ext(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    status_of(gl, out, GL_FRAMEBUFFER, "16x12 colour, 8x16 depth");
    pixel_space(gl, 8, 12);
    gl.clear_color(0.0, 0.25, 0.5, 1.0);
    gl.clear_depth(0.5);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    err(gl, out, "clear");
    gl.enable(GL_DEPTH_TEST);
    gl.color_4f(1.0, 0.0, 0.0, 1.0);
    quad(gl, 0.0, 0.0, 6.0, 6.0, 0.5); // behind: depth 0.75
    gl.color_4f(0.0, 1.0, 0.0, 1.0);
    quad(gl, 2.0, 2.0, 8.0, 12.0, -0.5); // in front: depth 0.25
    gl.disable(GL_DEPTH_TEST);
    err(gl, out, "drawing");
    read_rgba(gl, out, "the common rectangle", 0, 0, 8, 12);
    gl.bind_framebuffer(GL_FRAMEBUFFER, 0);
    // Inside the common rectangle the texture holds the drawing; outside, undefined.
    let mut texels = vec![0u8; 16 * 12 * 4];
    gl.bind_texture(GL_TEXTURE_2D, tex);
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut texels);
    let common: Vec<f64> = texels
        .chunks(16 * 4)
        .flat_map(|row| row[..8 * 4].iter().map(|&v| v as f64))
        .collect();
    exact(out, "glGetTexImage of the common rectangle".into(), common);
    pixel_space(gl, 64, 64);
}

/// ALPHA, LUMINANCE, LUMINANCE_ALPHA and RGB textures drawn into.
fn arb_fbo_color_renderable_formats(gl: &mut dyn Gl, out: &mut Answers) {
    for (format, label) in [
        (GL_ALPHA8, "ALPHA8"),
        (GL_LUMINANCE8, "LUMINANCE8"),
        (GL_LUMINANCE8_ALPHA8, "LUMINANCE8_ALPHA8"),
        (GL_RGB8, "RGB8"),
    ] {
        let tex = texture_2d(gl, format, 8, 4);
        let fb = gen_framebuffer(gl);
        gl.bind_framebuffer(GL_FRAMEBUFFER, fb);
        gl.framebuffer_texture_2dext(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
        status_of(gl, out, GL_FRAMEBUFFER, label);
        pixel_space(gl, 8, 4);
        gl.clear_color(0.2, 0.4, 0.6, 0.8);
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        gl.color_4f(1.0, 0.6, 0.2, 0.4);
        quad(gl, 2.0, 0.0, 4.0, 4.0, 0.0);
        gl.blend_func(GL_DST_ALPHA, GL_ZERO);
        gl.color_4f(0.6, 0.8, 1.0, 0.5);
        quad(gl, 4.0, 0.0, 6.0, 4.0, 0.0);
        gl.disable(GL_BLEND);
        err(gl, out, &format!("drawing into {label}"));
        // llvmpipe rounds the blended luminance down where tilegl rounds to nearest
        // (1 * 0.4 + 0.2 * 0.6 = 0.52: 132.6, Mesa 132, tilegl 133; its RGB8 and
        // LUMINANCE8_ALPHA8 images give 133): one unit allowed for LUMINANCE8.
        let tolerance = if format == GL_LUMINANCE8 { 1.0 } else { 0.0 };
        let mut px = vec![0u8; 8 * 4 * 4];
        gl.read_pixels(0, 0, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
        out.push(Answer {
            label: format!("glReadPixels {label}"),
            values: px.iter().map(|&v| v as f64).collect(),
            tolerance,
        });
        gl.bind_framebuffer(GL_FRAMEBUFFER, 0);
        gl.bind_texture(GL_TEXTURE_2D, tex);
        let mut texels = vec![0u8; 8 * 4 * 4];
        gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut texels);
        out.push(Answer {
            label: format!("glGetTexImage {label}"),
            values: texels.iter().map(|&v| v as f64).collect(),
            tolerance,
        });
        err(gl, out, "glGetTexImage");
        gl.delete_framebuffers_ext(1, &[fb]);
    }
    pixel_space(gl, 64, 64);
}

/// glFramebufferTextureLayer on a 3D texture.
fn arb_fbo_texture_layer(gl: &mut dyn Gl, out: &mut Answers) {
    let mut t = [0; 2];
    gl.gen_textures(2, &mut t);
    gl.bind_texture(GL_TEXTURE_3D, t[0]);
    gl.tex_image_3d(
        GL_TEXTURE_3D,
        0,
        GL_RGBA8 as i32,
        4,
        4,
        3,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    let _ = texture_2d(gl, GL_RGBA8, 4, 4);
    let flat = t[1];
    gl.bind_texture(GL_TEXTURE_2D, flat);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        4,
        4,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    let fb = gen_framebuffer(gl);
    gl.bind_framebuffer(GL_FRAMEBUFFER, fb);
    gl.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, flat, 0, 0);
    err(gl, out, "a 2D texture");
    gl.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t[0], 0, -1);
    err(gl, out, "a negative layer");
    gl.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t[0], -1, 0);
    err(gl, out, "a negative level");
    gl.framebuffer_texture_layer(GL_FRAMEBUFFER, 0x1234, t[0], 0, 0);
    err(gl, out, "a bad attachment point");
    gl.framebuffer_texture_layer(0x1234, GL_COLOR_ATTACHMENT0, t[0], 0, 0);
    err(gl, out, "a bad target");
    attachment(
        gl,
        out,
        GL_COLOR_ATTACHMENT0,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
        "after the errors",
    );
    let colors = [
        [1.0, 0.0, 0.0, 1.0],
        [0.0, 1.0, 0.0, 0.5],
        [0.0, 0.0, 1.0, 0.25],
    ];
    for (layer, c) in colors.iter().enumerate() {
        gl.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t[0], 0, layer as i32);
        err(gl, out, &format!("layer {layer}"));
        attachment(
            gl,
            out,
            GL_COLOR_ATTACHMENT0,
            GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER,
            &format!("layer {layer}"),
        );
        attachment(
            gl,
            out,
            GL_COLOR_ATTACHMENT0,
            GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL,
            &format!("layer {layer}"),
        );
        status_of(gl, out, GL_FRAMEBUFFER, &format!("layer {layer}"));
        gl.clear_color(c[0], c[1], c[2], c[3]);
        gl.clear(GL_COLOR_BUFFER_BIT);
        read_rgba(gl, out, &format!("layer {layer}"), 0, 0, 4, 4);
    }
    gl.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t[0], 20, 0);
    err(gl, out, "a level beyond the texture's");
    gl.bind_framebuffer(GL_FRAMEBUFFER, 0);
    gl.bind_texture(GL_TEXTURE_3D, t[0]);
    get_tex_image(gl, out, GL_TEXTURE_3D, 0, 4 * 4 * 3);
}

/// glBlitFramebuffer between objects, then glGenerateMipmap of the drawn texture.
fn arb_fbo_blit_and_mipmap(gl: &mut dyn Gl, out: &mut Answers) {
    let src_tex = texture_2d(gl, GL_RGBA8, 8, 8);
    let src = gen_framebuffer(gl);
    gl.bind_framebuffer(GL_FRAMEBUFFER, src);
    gl.framebuffer_texture_2dext(
        GL_FRAMEBUFFER,
        GL_COLOR_ATTACHMENT0,
        GL_TEXTURE_2D,
        src_tex,
        0,
    );
    pixel_space(gl, 8, 8);
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let mut k = 0.0;
    for y in 0..4 {
        for x in 0..4 {
            k += 1.0 / 16.0;
            gl.color_4f(k, 1.0 - k, (x as f32) / 4.0, (y as f32) / 4.0 + 0.25);
            let (x0, y0) = (x as f32 * 2.0, y as f32 * 2.0);
            quad(gl, x0, y0, x0 + 2.0, y0 + 2.0, 0.0);
        }
    }
    err(gl, out, "drawing the source");
    let dst_tex = texture_2d(gl, GL_RGBA8, 8, 8);
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_NEAREST_MIPMAP_NEAREST as i32,
    );
    let dst = gen_framebuffer(gl);
    gl.bind_framebuffer(GL_DRAW_FRAMEBUFFER, dst);
    gl.framebuffer_texture_2dext(
        GL_DRAW_FRAMEBUFFER,
        GL_COLOR_ATTACHMENT0,
        GL_TEXTURE_2D,
        dst_tex,
        0,
    );
    status_of(gl, out, GL_DRAW_FRAMEBUFFER, "draw");
    status_of(gl, out, GL_READ_FRAMEBUFFER, "read");
    int(gl, out, GL_DRAW_FRAMEBUFFER_BINDING);
    int(gl, out, GL_READ_FRAMEBUFFER_BINDING);
    gl.clear_color(0.5, 0.5, 0.5, 0.5);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.blit_framebuffer_ext(0, 0, 4, 8, 0, 0, 4, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    gl.blit_framebuffer_ext(4, 0, 8, 8, 8, 8, 4, 0, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    err(gl, out, "glBlitFramebuffer");
    gl.bind_framebuffer(GL_READ_FRAMEBUFFER, dst);
    read_rgba(gl, out, "the blit's destination", 0, 0, 8, 8);
    gl.bind_framebuffer(GL_FRAMEBUFFER, 0);
    gl.bind_texture(GL_TEXTURE_2D, dst_tex);
    gl.generate_mipmap_ext(GL_TEXTURE_2D);
    err(gl, out, "glGenerateMipmap");
    get_tex_image(gl, out, GL_TEXTURE_2D, 1, 4 * 4);
    get_tex_image(gl, out, GL_TEXTURE_2D, 3, 1);
    pixel_space(gl, 64, 64);
}

//! Table-driven error semantics (OpenGL 1.5 section 2.5 and each call's error rules): every
//! erroneous call records the specified error and changes no other state.

mod common;

use common::state_fingerprint;
use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::{Context, Gl};

type Call = fn(&mut Context);

/// (description, set-up, erroneous call, expected error)
fn cases() -> Vec<(&'static str, Call, Call, GLenum)> {
    fn none(_: &mut Context) {}
    vec![
        // Section 2.14.2: "In the non-vector versions, param is a value to which to set a
        // single-valued parameter. (If param corresponds to a multi-valued parameter, the
        // error INVALID_ENUM results.)" Mesa 22 accepts these (it sets (param, 0, 0, 0));
        // piglit's gl-1.0-beginend-coverage expects that, docs/piglit.md says why tilegl
        // keeps the specification.
        (
            "materialf multi-valued",
            none,
            |g| g.materialf(GL_FRONT, GL_AMBIENT, 0.5),
            GL_INVALID_ENUM,
        ),
        (
            "materiali multi-valued",
            none,
            |g| g.materiali(GL_FRONT_AND_BACK, GL_DIFFUSE, 1),
            GL_INVALID_ENUM,
        ),
        (
            "lightf multi-valued",
            none,
            |g| g.lightf(GL_LIGHT0, GL_POSITION, 0.5),
            GL_INVALID_ENUM,
        ),
        (
            "lightModelf multi-valued",
            none,
            |g| g.light_modelf(GL_LIGHT_MODEL_AMBIENT, 0.5),
            GL_INVALID_ENUM,
        ),
        // Section 3.8.4 describes the scalar forms for single-valued parameters only; Mesa
        // (and OpenGL 4's explicit rule) make a border colour through them INVALID_ENUM.
        (
            "texParameterf border colour",
            none,
            |g| g.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.5),
            GL_INVALID_ENUM,
        ),
        (
            "enable bad cap",
            none,
            |g| g.enable(GL_TEXTURE_ENV),
            GL_INVALID_ENUM,
        ),
        (
            "disable bad cap",
            none,
            |g| g.disable(0xFFFF),
            GL_INVALID_ENUM,
        ),
        (
            "isEnabled bad cap",
            none,
            |g| {
                g.is_enabled(GL_VERSION);
            },
            GL_INVALID_ENUM,
        ),
        (
            "depthFunc bad",
            none,
            |g| g.depth_func(GL_ZERO),
            GL_INVALID_ENUM,
        ),
        (
            "cullFace bad",
            none,
            |g| g.cull_face(GL_LEFT),
            GL_INVALID_ENUM,
        ),
        (
            "frontFace bad",
            none,
            |g| g.front_face(GL_FRONT),
            GL_INVALID_ENUM,
        ),
        (
            "shadeModel bad",
            none,
            |g| g.shade_model(GL_LINE),
            GL_INVALID_ENUM,
        ),
        (
            "matrixMode bad",
            none,
            |g| g.matrix_mode(GL_COLOR),
            GL_INVALID_ENUM,
        ),
        (
            "hint bad target",
            none,
            |g| g.hint(GL_FASTEST, GL_NICEST),
            GL_INVALID_ENUM,
        ),
        (
            "hint bad mode",
            none,
            |g| g.hint(GL_FOG_HINT, GL_FOG),
            GL_INVALID_ENUM,
        ),
        (
            "getString bad",
            none,
            |g| {
                g.get_string(GL_RENDER);
            },
            GL_INVALID_ENUM,
        ),
        (
            "pixelStore bad pname",
            none,
            |g| g.pixel_storei(GL_PACK_SWAP_BYTES + 100, 1),
            GL_INVALID_ENUM,
        ),
        (
            "pixelStore alignment 3",
            none,
            |g| g.pixel_storei(GL_PACK_ALIGNMENT, 3),
            GL_INVALID_VALUE,
        ),
        (
            "pixelStore negative row length",
            none,
            |g| g.pixel_storei(GL_UNPACK_ROW_LENGTH, -1),
            GL_INVALID_VALUE,
        ),
        (
            "pixelStoref alignment 0",
            none,
            |g| g.pixel_storef(GL_UNPACK_ALIGNMENT, 0.0),
            GL_INVALID_VALUE,
        ),
        (
            "scissor negative",
            none,
            |g| g.scissor(0, 0, -1, 4),
            GL_INVALID_VALUE,
        ),
        (
            "viewport negative",
            none,
            |g| g.viewport(0, 0, 4, -1),
            GL_INVALID_VALUE,
        ),
        (
            "clear bad bits",
            none,
            |g| g.clear(GL_COLOR_BUFFER_BIT | 0x1),
            GL_INVALID_VALUE,
        ),
        (
            "frustum near 0",
            none,
            |g| g.frustum(-1.0, 1.0, -1.0, 1.0, 0.0, 10.0),
            GL_INVALID_VALUE,
        ),
        (
            "frustum far negative",
            none,
            |g| g.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, -1.0),
            GL_INVALID_VALUE,
        ),
        (
            "frustum left == right",
            none,
            |g| g.frustum(1.0, 1.0, -1.0, 1.0, 1.0, 10.0),
            GL_INVALID_VALUE,
        ),
        (
            "frustum near == far",
            none,
            |g| g.frustum(-1.0, 1.0, -1.0, 1.0, 2.0, 2.0),
            GL_INVALID_VALUE,
        ),
        (
            "ortho bottom == top",
            none,
            |g| g.ortho(-1.0, 1.0, 2.0, 2.0, -1.0, 1.0),
            GL_INVALID_VALUE,
        ),
        (
            "ortho near == far",
            none,
            |g| g.ortho(-1.0, 1.0, -1.0, 1.0, 1.0, 1.0),
            GL_INVALID_VALUE,
        ),
        (
            "clipPlane bad",
            none,
            |g| g.clip_plane(GL_CLIP_PLANE0 + 8, &[1.0; 4]),
            GL_INVALID_ENUM,
        ),
        (
            "getClipPlane bad",
            none,
            |g| g.get_clip_plane(GL_LIGHT0, &mut [0.0; 4]),
            GL_INVALID_ENUM,
        ),
        (
            "popMatrix at depth 1",
            none,
            |g| g.pop_matrix(),
            GL_STACK_UNDERFLOW,
        ),
        (
            "pushMatrix projection overflow",
            |g| {
                g.matrix_mode(GL_PROJECTION);
                let mut depth = [0i32];
                g.get_integerv(GL_MAX_PROJECTION_STACK_DEPTH, &mut depth);
                for _ in 1..depth[0] {
                    g.push_matrix();
                }
            },
            |g| g.push_matrix(),
            GL_STACK_OVERFLOW,
        ),
        (
            "pushMatrix modelview overflow",
            |g| {
                for _ in 1..32 {
                    g.push_matrix();
                }
            },
            |g| g.push_matrix(),
            GL_STACK_OVERFLOW,
        ),
        (
            "begin bad mode",
            none,
            |g| g.begin(GL_POLYGON + 1),
            GL_INVALID_ENUM,
        ),
        ("end without begin", none, |g| g.end(), GL_INVALID_OPERATION),
        (
            "readPixels bad format",
            none,
            |g| g.read_pixels(0, 0, 1, 1, GL_RGBA8, GL_UNSIGNED_BYTE, &mut [0; 16]),
            GL_INVALID_ENUM,
        ),
        (
            "readPixels bad type",
            none,
            |g| g.read_pixels(0, 0, 1, 1, GL_RGBA, GL_RGBA, &mut [0; 16]),
            GL_INVALID_ENUM,
        ),
        (
            "readPixels negative width",
            none,
            |g| g.read_pixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut [0; 16]),
            GL_INVALID_VALUE,
        ),
        (
            "readPixels short slice",
            none,
            |g| g.read_pixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, &mut [0; 15]),
            GL_INVALID_VALUE,
        ),
        (
            "getIntegerv bad",
            none,
            |g| g.get_integerv(GL_RGBA, &mut [0; 16]),
            GL_INVALID_ENUM,
        ),
        (
            "getFloatv short slice",
            none,
            |g| g.get_floatv(GL_MODELVIEW_MATRIX, &mut [0.0; 4]),
            GL_INVALID_VALUE,
        ),
        (
            "accum without an accumulation buffer",
            none,
            |g| g.accum(GL_ACCUM, 0.5),
            GL_INVALID_OPERATION,
        ),
        ("pointSize 0", none, |g| g.point_size(0.0), GL_INVALID_VALUE),
        (
            "pointSize NaN",
            none,
            |g| g.point_size(f32::NAN),
            GL_INVALID_VALUE,
        ),
        (
            "lineWidth -1",
            none,
            |g| g.line_width(-1.0),
            GL_INVALID_VALUE,
        ),
        (
            "polygonMode bad mode",
            none,
            |g| g.polygon_mode(GL_FRONT, GL_TRIANGLES),
            GL_INVALID_ENUM,
        ),
        (
            "polygonMode bad face",
            none,
            |g| g.polygon_mode(GL_LEFT, GL_LINE),
            GL_INVALID_ENUM,
        ),
        (
            "pointParameter negative min",
            none,
            |g| g.point_parameterf(GL_POINT_SIZE_MIN, -1.0),
            GL_INVALID_VALUE,
        ),
        (
            "pointParameter bad name",
            none,
            |g| g.point_parameterf(GL_POINT_SIZE, 1.0),
            GL_INVALID_ENUM,
        ),
        // Section 3.8.2: CopyTexImage's internalformat (an enum) may not be 1, 2, 3 or 4.
        (
            "copyTexImage1D internalformat 3",
            none,
            |g| g.copy_tex_image_1d(GL_TEXTURE_1D, 0, 3, 0, 0, 4, 0),
            GL_INVALID_ENUM,
        ),
        (
            "copyTexImage2D internalformat 4",
            none,
            |g| g.copy_tex_image_2d(GL_TEXTURE_2D, 0, 4, 0, 0, 4, 4, 0),
            GL_INVALID_ENUM,
        ),
        // Section 3.8.1: level l holds images up to 2^(k - l) (k = log2 MAX_TEXTURE_SIZE).
        (
            "texImage2D level 1 as wide as level 0 may be",
            none,
            |g| {
                let max = max_texture_size(g);
                g.tex_image_2d(
                    GL_TEXTURE_2D,
                    1,
                    GL_RGBA as i32,
                    max,
                    1,
                    0,
                    GL_RGBA,
                    GL_UNSIGNED_BYTE,
                    None,
                )
            },
            GL_INVALID_VALUE,
        ),
        (
            "texImage2D level 2 as tall as level 1 may be",
            none,
            |g| {
                let max = max_texture_size(g);
                g.tex_image_2d(
                    GL_TEXTURE_2D,
                    2,
                    GL_RGBA as i32,
                    1,
                    max / 2,
                    0,
                    GL_RGBA,
                    GL_UNSIGNED_BYTE,
                    None,
                )
            },
            GL_INVALID_VALUE,
        ),
        (
            "copyTexImage1D level 3 wider than 2^(k-3)",
            none,
            |g| {
                let max = max_texture_size(g);
                g.copy_tex_image_1d(GL_TEXTURE_1D, 3, GL_RGBA, 0, 0, max / 4, 0)
            },
            GL_INVALID_VALUE,
        ),
        // Section 3.6.4: packed types need format RGB or RGBA/BGRA.
        (
            "drawPixels stencil index with a packed type",
            none,
            |g| {
                g.draw_pixels(
                    1,
                    1,
                    GL_STENCIL_INDEX,
                    GL_UNSIGNED_SHORT_5_6_5,
                    Some(&[0; 2]),
                )
            },
            GL_INVALID_OPERATION,
        ),
        // GL_RG (not GL 1.5's) with a packed type has two errors; GL records either, and
        // llvmpipe and piglit's draw-pixels expect this one.
        (
            "drawPixels GL_RG with a packed type",
            none,
            |g| g.draw_pixels(1, 1, 0x8227, GL_UNSIGNED_BYTE_3_3_2, Some(&[0; 1])),
            GL_INVALID_OPERATION,
        ),
    ]
}

fn max_texture_size(g: &mut Context) -> i32 {
    let mut max = [0];
    g.get_integerv(GL_MAX_TEXTURE_SIZE, &mut max);
    max[0]
}

#[test]
fn every_error_is_recorded_and_changes_nothing() {
    for (name, setup, call, expected) in cases() {
        let mut gl = Context::new(8, 8);
        setup(&mut gl);
        assert_eq!(
            gl.get_error(),
            GL_NO_ERROR,
            "{name}: set-up raised an error"
        );
        let before = state_fingerprint(&mut gl);
        call(&mut gl);
        assert_eq!(gl.get_error(), expected, "{name}");
        assert_eq!(
            gl.get_error(),
            GL_NO_ERROR,
            "{name}: error flag not cleared by glGetError"
        );
        let after = state_fingerprint(&mut gl);
        assert_eq!(before, after, "{name}: state changed by an erroneous call");
    }
}

#[test]
fn calls_inside_begin_end_are_rejected_without_effect() {
    let inside: Vec<(&str, Call)> = vec![
        ("enable", |g| g.enable(GL_DEPTH_TEST)),
        ("depthFunc", |g| g.depth_func(GL_ALWAYS)),
        ("matrixMode", |g| g.matrix_mode(GL_PROJECTION)),
        ("loadIdentity", |g| g.translatef(1.0, 2.0, 3.0)),
        ("viewport", |g| g.viewport(1, 1, 2, 2)),
        ("clear", |g| g.clear(GL_COLOR_BUFFER_BIT)),
        ("begin", |g| g.begin(GL_POINTS)),
        ("getIntegerv", |g| g.get_integerv(GL_VIEWPORT, &mut [0; 4])),
        ("rect", |g| g.rectf(0.0, 0.0, 1.0, 1.0)),
        ("unimplemented", |g| g.blend_func(GL_ONE, GL_ONE)),
    ];
    for (name, call) in inside {
        let mut gl = Context::new(8, 8);
        let before = state_fingerprint(&mut gl);
        gl.begin(GL_TRIANGLES);
        call(&mut gl);
        // glGetError itself is an error inside glBegin/glEnd and returns 0.
        assert_eq!(gl.get_error(), 0, "{name}");
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION, "{name}");
        assert_eq!(state_fingerprint(&mut gl), before, "{name}: state changed");
    }
}

#[test]
fn vertex_calls_are_legal_inside_begin_end() {
    let mut gl = Context::new(8, 8);
    gl.begin(GL_TRIANGLES);
    gl.color_4ub(1, 2, 3, 4);
    gl.normal_3f(0.0, 1.0, 0.0);
    gl.tex_coord_2f(0.5, 0.5);
    gl.vertex_2f(0.0, 0.0);
    gl.end();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn first_error_sticks_until_read() {
    let mut gl = Context::new(8, 8);
    gl.enable(0xFFFF); // INVALID_ENUM
    gl.viewport(0, 0, -1, -1); // INVALID_VALUE, dropped
    gl.pop_matrix(); // STACK_UNDERFLOW, dropped
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn rasterization_controls_are_stored_and_queried_per_spec() {
    let mut gl = Context::new(8, 8);
    let mut f = [0f32; 4];
    let mut i = [0i32; 4];
    // Defaults (table 6.11 - 6.13).
    gl.get_floatv(GL_POINT_SIZE, &mut f);
    assert_eq!(f[0], 1.0);
    gl.get_integerv(GL_POLYGON_MODE, &mut i);
    assert_eq!(&i[..2], &[GL_FILL as i32, GL_FILL as i32]);
    gl.get_integerv(GL_LINE_STIPPLE_PATTERN, &mut i);
    assert_eq!(i[0], 0xFFFF);
    gl.get_floatv(GL_POINT_DISTANCE_ATTENUATION, &mut f);
    assert_eq!(&f[..3], &[1.0, 0.0, 0.0]);
    // Setters.
    gl.point_size(3.5);
    gl.line_width(2.0);
    gl.line_stipple(300, 0x0F0F); // factor clamped to 256
    gl.polygon_mode(GL_BACK, GL_LINE);
    gl.polygon_offset(1.5, -2.0);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.get_floatv(GL_POINT_SIZE, &mut f);
    assert_eq!(f[0], 3.5);
    gl.get_floatv(GL_LINE_WIDTH, &mut f);
    assert_eq!(f[0], 2.0);
    gl.get_integerv(GL_LINE_STIPPLE_REPEAT, &mut i);
    assert_eq!(i[0], 256);
    gl.get_integerv(GL_POLYGON_MODE, &mut i);
    assert_eq!(&i[..2], &[GL_FILL as i32, GL_LINE as i32]);
    gl.get_floatv(GL_POLYGON_OFFSET_FACTOR, &mut f);
    assert_eq!(f[0], 1.5);
    gl.get_floatv(GL_POLYGON_OFFSET_UNITS, &mut f);
    assert_eq!(f[0], -2.0);
    // The polygon stipple round-trips through the unpack and pack state.
    let pattern: Vec<u8> = (0..128u32).map(|k| (k * 37 + 11) as u8).collect();
    gl.polygon_stipple(&pattern);
    let mut back = vec![0u8; 128];
    gl.get_polygon_stipple(&mut back);
    assert_eq!(back, pattern);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

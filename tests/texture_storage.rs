//! ARB_texture_storage where its text decides (the cases compared with Mesa are in
//! `conformance/src/state_cases/tex_storage.rs`).

use tilegl::enums::*;
use tilegl::{Context, Gl};

#[test]
fn the_base_level_query_keeps_the_value_set_and_sampling_clamps_it() {
    // Section 3.8.6: "if TEXTURE_IMMUTABLE_FORMAT is TRUE, then level_base is clamped to the
    // range [0, <levels> - 1] and level_max is then clamped to the range [level_base,
    // <levels> - 1]": the clamp is of the level used, the parameter keeps its value (Mesa
    // stores the clamped value, as OpenGL 4.3 later specified).
    let mut gl = Context::new(8, 8);
    let mut t = [0];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    gl.tex_storage_2d(GL_TEXTURE_2D, 2, GL_RGBA8, 2, 2);
    let level1 = [0u8, 255, 0, 255];
    gl.tex_sub_image_2d(
        GL_TEXTURE_2D,
        1,
        0,
        0,
        1,
        1,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&level1),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 7);
    let mut v = [-1];
    gl.get_tex_parameteriv(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, &mut v);
    assert_eq!(v[0], 7);
    gl.get_tex_parameteriv(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_FORMAT, &mut v);
    assert_eq!(v[0], 1);
    // level_base = 1: complete, and every fragment samples level 1.
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.color_4f(1.0, 0.0, 0.0, 1.0);
    gl.begin(GL_QUADS);
    for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        gl.tex_coord_2f(0.5, 0.5);
        gl.vertex_2f(x, y);
    }
    gl.end();
    let mut px = [0u8; 4];
    gl.read_pixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    assert_eq!(px, level1);
    // "TexImage* ... TexStorage* ... INVALID_OPERATION ... even if it does not affect the
    // dimensions or format"; a query-only parameter cannot be set.
    gl.tex_storage_2d(GL_TEXTURE_2D, 2, GL_RGBA8, 2, 2);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_FORMAT, 0);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
}

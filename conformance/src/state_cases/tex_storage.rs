//! ARB_texture_storage: the same calls on Mesa and on tilegl (Rust API and C ABI), every
//! answer (level sizes and formats, `GL_TEXTURE_IMMUTABLE_FORMAT`, GL errors, sampled
//! pictures) equal to Mesa's.

super::state_case_list!(source = include_str!("tex_storage.rs"), agree = |a: &Answer, b: &Answer| {
    a.values.len() == b.values.len()
        && a.values
            .iter()
            .zip(&b.values)
            .all(|(x, y)| (x - y).abs() <= a.tolerance)
};
    tex_storage_levels_and_immutability: "glTexStorage2D of 3 levels of an 8x4 GL_RGBA8 texture: each level's size and internal format (level 3 undefined), GL_TEXTURE_IMMUTABLE_FORMAT before and after, glTexImage2D, glCopyTexImage2D and a second glTexStorage2D refused with GL_INVALID_OPERATION, glTexSubImage2D of each level accepted, then the texture drawn with mipmapping and GL_TEXTURE_BASE_LEVEL 5 (level_base clamped to the last level, 2). Every answer equals Mesa's.",
    tex_storage_errors_and_targets: "The errors of the extension (a bad target, an unsized or generic compressed format, zero levels or size, more levels than the size allows), glTexStorage1D and glTexStorage3D level sizes, a cube map's six faces, a depth format, and proxies (sizes recorded, GL_TEXTURE_IMMUTABLE_FORMAT stays false). Every answer equals Mesa's.",
);

use super::fbo::{err, exact, pixel_space, quad, read_rgba, Answer, Answers};
use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::Gl;

fn level_params(gl: &mut dyn Gl, out: &mut Answers, target: GLenum, level: i32, label: &str) {
    let mut values = Vec::new();
    // An undefined level's internal format is 1 by OpenGL 1.x's state table and GL_RGBA by
    // later ones (Mesa): compared for defined levels only.
    let defined = {
        let mut w = [0];
        gl.get_tex_level_parameteriv(target, level, GL_TEXTURE_WIDTH, &mut w);
        w[0] > 0
    };
    let pnames: &[GLenum] = if defined {
        &[
            GL_TEXTURE_WIDTH,
            GL_TEXTURE_HEIGHT,
            GL_TEXTURE_DEPTH,
            GL_TEXTURE_INTERNAL_FORMAT,
        ]
    } else {
        &[GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_DEPTH]
    };
    for &p in pnames {
        let mut v = [-1];
        gl.get_tex_level_parameteriv(target, level, p, &mut v);
        values.push(v[0] as f64);
    }
    exact(
        out,
        format!("level {level} of 0x{target:04x} {label}: width, height, depth(, format)"),
        values,
    );
    err(gl, out, &format!("level queries {label}"));
}

fn immutable(gl: &mut dyn Gl, out: &mut Answers, target: GLenum, label: &str) {
    let mut v = [-1];
    gl.get_tex_parameteriv(target, GL_TEXTURE_IMMUTABLE_FORMAT, &mut v);
    exact(
        out,
        format!("GL_TEXTURE_IMMUTABLE_FORMAT {label}"),
        vec![v[0] as f64],
    );
    err(gl, out, &format!("immutable query {label}"));
}

fn new_texture(gl: &mut dyn Gl, target: GLenum) -> u32 {
    let mut t = [0];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(target, t[0]);
    t[0]
}

/// Levels, immutability and the base-level clamp.
fn tex_storage_levels_and_immutability(gl: &mut dyn Gl, out: &mut Answers) {
    new_texture(gl, GL_TEXTURE_2D);
    immutable(gl, out, GL_TEXTURE_2D, "before");
    gl.tex_storage_2d(GL_TEXTURE_2D, 3, GL_RGBA8, 8, 4);
    err(gl, out, "glTexStorage2D");
    immutable(gl, out, GL_TEXTURE_2D, "after");
    for level in 0..4 {
        level_params(gl, out, GL_TEXTURE_2D, level, "RGBA8 storage");
    }
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        8,
        4,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    err(gl, out, "glTexImage2D of an immutable texture");
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        3,
        GL_RGBA8 as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    err(gl, out, "glTexImage2D of a level beyond the storage");
    gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, 8, 4, 0);
    err(gl, out, "glCopyTexImage2D of an immutable texture");
    gl.tex_storage_2d(GL_TEXTURE_2D, 1, GL_RGBA8, 8, 4);
    err(gl, out, "a second glTexStorage2D");
    // Each level its own colour.
    let colours: [[u8; 4]; 3] = [[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255]];
    let (mut w, mut h) = (8, 4);
    for (level, c) in colours.iter().enumerate() {
        let px: Vec<u8> = (0..w * h).flat_map(|_| *c).collect();
        gl.tex_sub_image_2d(
            GL_TEXTURE_2D,
            level as i32,
            0,
            0,
            w,
            h,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&px),
        );
        w = (w / 2).max(1);
        h = (h / 2).max(1);
    }
    err(gl, out, "glTexSubImage2D of each level");
    level_params(gl, out, GL_TEXTURE_2D, 0, "after the sub-images");
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_NEAREST_MIPMAP_NEAREST as i32,
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    pixel_space(gl, 64, 64);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    // 8x4 texels over 8x4 pixels: level 0; over 2x1 pixels: level 2.
    quad(gl, 0.0, 0.0, 8.0, 4.0, 0.0);
    quad(gl, 16.0, 0.0, 18.0, 1.0, 0.0);
    // (The query of GL_TEXTURE_BASE_LEVEL is not compared: Mesa stores the clamped value,
    // as OpenGL 4.3 does; the extension clamps the level_base used, tests/arb_fbo.rs.)
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 5);
    // level_base is clamped to 2: the texture is complete and samples level 2.
    quad(gl, 24.0, 0.0, 32.0, 4.0, 0.0);
    gl.disable(GL_TEXTURE_2D);
    err(gl, out, "drawing");
    read_rgba(gl, out, "level 0, level 2, clamped base level", 0, 0, 32, 4);
}

/// Errors, other targets, a depth format and proxies.
fn tex_storage_errors_and_targets(gl: &mut dyn Gl, out: &mut Answers) {
    new_texture(gl, GL_TEXTURE_2D);
    gl.tex_storage_2d(GL_TEXTURE_3D, 1, GL_RGBA8, 4, 4);
    err(gl, out, "glTexStorage2D(GL_TEXTURE_3D)");
    gl.tex_storage_2d(GL_TEXTURE_2D, 1, GL_RGBA, 4, 4);
    err(gl, out, "an unsized format");
    gl.tex_storage_2d(GL_TEXTURE_2D, 1, GL_COMPRESSED_RGBA, 4, 4);
    err(gl, out, "a generic compressed format");
    gl.tex_storage_2d(GL_TEXTURE_2D, 1, 0x1234, 4, 4);
    err(gl, out, "an unknown format");
    gl.tex_storage_2d(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4);
    err(gl, out, "zero levels");
    gl.tex_storage_2d(GL_TEXTURE_2D, 1, GL_RGBA8, 0, 4);
    err(gl, out, "zero width");
    gl.tex_storage_2d(GL_TEXTURE_2D, 4, GL_RGBA8, 4, 2);
    err(gl, out, "more levels than log2(4) + 1");
    immutable(gl, out, GL_TEXTURE_2D, "after the errors");
    gl.tex_storage_2d(GL_TEXTURE_2D, 3, GL_RGBA8, 4, 2);
    err(gl, out, "all levels of 4x2");
    for level in 0..3 {
        level_params(gl, out, GL_TEXTURE_2D, level, "4x2");
    }
    new_texture(gl, GL_TEXTURE_1D);
    gl.tex_storage_1d(GL_TEXTURE_1D, 4, GL_RGB8, 16);
    err(gl, out, "glTexStorage1D");
    for level in 0..5 {
        level_params(gl, out, GL_TEXTURE_1D, level, "1D");
    }
    immutable(gl, out, GL_TEXTURE_1D, "1D");
    gl.tex_storage_1d(GL_TEXTURE_2D, 1, GL_RGB8, 16);
    err(gl, out, "glTexStorage1D(GL_TEXTURE_2D)");
    new_texture(gl, GL_TEXTURE_3D);
    gl.tex_storage_3d(GL_TEXTURE_3D, 3, GL_RGBA8, 8, 4, 2);
    err(gl, out, "glTexStorage3D");
    for level in 0..4 {
        level_params(gl, out, GL_TEXTURE_3D, level, "3D");
    }
    gl.tex_image_3d(
        GL_TEXTURE_3D,
        0,
        GL_RGBA8 as i32,
        8,
        4,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    err(gl, out, "glTexImage3D of an immutable texture");
    new_texture(gl, GL_TEXTURE_CUBE_MAP);
    gl.tex_storage_2d(GL_TEXTURE_CUBE_MAP, 2, GL_RGBA8, 4, 4);
    err(gl, out, "cube map storage");
    for face in [
        GL_TEXTURE_CUBE_MAP_POSITIVE_X,
        GL_TEXTURE_CUBE_MAP_NEGATIVE_Z,
    ] {
        for level in 0..2 {
            level_params(gl, out, face, level, "cube face");
        }
    }
    immutable(gl, out, GL_TEXTURE_CUBE_MAP, "cube map");
    new_texture(gl, GL_TEXTURE_2D);
    gl.tex_storage_2d(GL_TEXTURE_2D, 2, GL_DEPTH_COMPONENT24, 8, 8);
    err(gl, out, "depth storage");
    level_params(gl, out, GL_TEXTURE_2D, 1, "depth");
    // Proxies: the sizes are recorded; nothing becomes immutable.
    gl.tex_storage_2d(GL_PROXY_TEXTURE_2D, 2, GL_RGBA8, 16, 8);
    err(gl, out, "proxy storage");
    for level in 0..2 {
        level_params(gl, out, GL_PROXY_TEXTURE_2D, level, "proxy");
    }
    immutable(gl, out, GL_TEXTURE_2D, "the bound texture after a proxy");
    gl.tex_storage_2d(GL_PROXY_TEXTURE_2D, 1, GL_RGBA8, 1 << 20, 8);
    err(gl, out, "a proxy too large");
    level_params(gl, out, GL_PROXY_TEXTURE_2D, 0, "proxy too large");
}

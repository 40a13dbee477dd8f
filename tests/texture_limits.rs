//! Texture size limits as Mesa reports them (16384 for 1D/2D and cube maps, 2048 for 3D) and
//! the ARB_texture_float internal formats, sampled at the far end of a 16384-wide texture and
//! checked against section 3.8.8's equations computed here.

mod common;

use common::{read_rgba, threaded_context};
use tilegl::enums::*;
use tilegl::Gl;

const TW: usize = 16384;

/// Texel i's red and green: functions of i that differ between neighbours.
fn texel(i: usize) -> [f32; 4] {
    [
        (i % 251) as f32 / 250.0,
        ((i / 7) % 239) as f32 / 238.0,
        0.5,
        1.0,
    ]
}

/// A 16384 x 2 `GL_RGBA32F` texture from `GL_FLOAT` data (both rows alike), `filter` for
/// minification and magnification.
fn upload(gl: &mut dyn Gl, internal: GLenum, filter: GLenum) {
    let mut bytes = Vec::with_capacity(TW * 2 * 16);
    for _row in 0..2 {
        for i in 0..TW {
            for c in texel(i) {
                bytes.extend_from_slice(&c.to_ne_bytes());
            }
        }
    }
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        internal as i32,
        TW as i32,
        2,
        0,
        GL_RGBA,
        GL_FLOAT,
        Some(&bytes),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE as i32);
}

/// Draws a 64 x 64 window whose pixel column x samples s = (first + x + offset) / 16384 (t at
/// the middle of the texture), `GL_REPLACE`; returns the picture.
fn draw_columns(internal: GLenum, filter: GLenum, first: f64, offset: f64) -> Vec<[u8; 4]> {
    let mut gl = threaded_context(64, 64, 1);
    upload(&mut gl, internal, filter);
    assert_eq!(gl.get_error(), GL_NO_ERROR, "{internal:#x} accepted");
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 64.0, 0.0, 64.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    // s at window x: (first + offset - 0.5 + x) / TW, so the pixel centre x + 1/2 samples
    // texel coordinate u = first + offset + x.
    let s = |x: f64| (first + offset - 0.5 + x) / TW as f64;
    gl.begin(GL_QUADS);
    for (x, y) in [(0.0, 0.0), (64.0, 0.0), (64.0, 64.0), (0.0, 64.0)] {
        gl.tex_coord_2f(s(x) as f32, 0.5);
        gl.vertex_2f(x as f32, y as f32);
    }
    gl.end();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    read_rgba(&mut gl)
}

#[test]
fn limits_are_mesas() {
    let mut gl = threaded_context(8, 8, 1);
    let mut v = [0i32];
    for (pname, want) in [
        (GL_MAX_TEXTURE_SIZE, 16384),
        (GL_MAX_3D_TEXTURE_SIZE, 2048),
        (GL_MAX_CUBE_MAP_TEXTURE_SIZE, 16384),
    ] {
        gl.get_integerv(pname, &mut v);
        assert_eq!(v[0], want, "{pname:#x}");
    }
    // One past the limit is GL_INVALID_VALUE; the limit itself is a legal size (a proxy
    // query answers without allocating).
    gl.tex_image_2d(
        GL_PROXY_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        16384,
        16384,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    let mut w = [0i32];
    gl.get_tex_level_parameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &mut w);
    assert_eq!(w[0], 16384);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        16385,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    // ARB_texture_float is advertised, as on Mesa: float formats keep values outside [0, 1]
    // (tests/texture_float.rs checks that).
    let ext = gl.get_string(GL_EXTENSIONS).unwrap_or_default();
    assert!(ext.split(' ').any(|e| e == "GL_ARB_texture_float"));
}

#[test]
fn nearest_at_the_far_end_of_a_16384_wide_float_texture_is_the_texel_under_the_centre() {
    // Pixel x samples u = 16310 + x + 0.5: texel floor(u) = 16310 + x (equation 3.19 with
    // the texel centre in the middle of the pixel's u range).
    for internal in [GL_RGBA32F_ARB, GL_RGBA16F_ARB, GL_RGBA8] {
        let img = draw_columns(internal, GL_NEAREST, 16310.0, 0.5);
        for x in 0..64usize {
            let want = texel((16310 + x).min(TW - 1)).map(|c| (c * 255.0).round() as i32);
            let got = img[32 * 64 + x];
            for c in 0..4 {
                assert!(
                    (got[c] as i32 - want[c]).abs() <= 1,
                    "{internal:#x} x {x}: {got:?} vs {want:?}"
                );
            }
        }
    }
}

#[test]
fn linear_at_the_far_end_of_a_16384_wide_float_texture_weights_the_two_texels() {
    // Pixel x samples u = 16300 + x + 0.75: i0 = floor(u - 1/2) = 16300 + x, alpha = 1/4
    // (equations 3.20-3.22), clamped to the edge past the last texel.
    let img = draw_columns(GL_RGBA32F_ARB, GL_LINEAR, 16300.0, 0.75);
    for x in 0..64usize {
        let (i0, i1) = ((16300 + x).min(TW - 1), (16301 + x).min(TW - 1));
        let (a, b) = (texel(i0), texel(i1));
        let got = img[32 * 64 + x];
        for c in 0..4 {
            let want = (0.75 * a[c] + 0.25 * b[c]) * 255.0;
            assert!(
                (got[c] as f32 - want).abs() <= 1.5,
                "x {x} channel {c}: {} vs {want}",
                got[c]
            );
        }
    }
}

#[test]
fn every_float_internal_format_is_accepted() {
    let mut gl = threaded_context(8, 8, 1);
    for internal in [
        GL_RGBA32F_ARB,
        GL_RGB32F_ARB,
        GL_ALPHA32F_ARB,
        GL_INTENSITY32F_ARB,
        GL_LUMINANCE32F_ARB,
        GL_LUMINANCE_ALPHA32F_ARB,
        GL_RGBA16F_ARB,
        GL_RGB16F_ARB,
        GL_ALPHA16F_ARB,
        GL_INTENSITY16F_ARB,
        GL_LUMINANCE16F_ARB,
        GL_LUMINANCE_ALPHA16F_ARB,
    ] {
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            internal as i32,
            4,
            4,
            0,
            GL_RGBA,
            GL_FLOAT,
            Some(&[0u8; 4 * 4 * 16]),
        );
        assert_eq!(gl.get_error(), GL_NO_ERROR, "{internal:#x}");
        let mut f = [0i32];
        gl.get_tex_level_parameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &mut f);
        assert_eq!(f[0], internal as i32);
    }
}

#[test]
fn extension_names_each_end_with_a_space() {
    // Programs that print the names one per line by turning spaces into newlines (piglit's
    // glinfo, whose verdict line must start a line) need the last name ended too.
    let mut gl = tilegl::Context::new(4, 4);
    let ext = gl.get_string(GL_EXTENSIONS).unwrap_or_default();
    assert!(ext.ends_with(' '), "{ext:?}");
    let names: Vec<&str> = ext.split(' ').collect();
    assert_eq!(names.last(), Some(&""));
    assert!(names[..names.len() - 1]
        .iter()
        .all(|n| n.starts_with("GL_") && n.len() > 3));
}

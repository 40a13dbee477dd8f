//! Differential tests of texturing, texture coordinate generation and the texture environment
//! (scenes in `tilegl_conformance::scenes_texture`), under each scene's tolerance.

use tilegl::enums::*;
use tilegl::Gl;
use tilegl_conformance::compare::{compare_scene, diff, Scene};
use tilegl_conformance::scenes_texture::TEXTURE_SCENES;
use tilegl_conformance::tolerance::DIFFERENTIAL;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn texture_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("TEXTURE_SCENES", TEXTURE_SCENES);
}

/// An 8x8 texture of unrelated bytes (`components` per texel), magnified LINEAR onto a
/// 64x64 pixel-space quad with REPLACE, texture coordinates from -0.25 to 1.25 (`REPEAT`) or
/// 0 to 1 (`CLAMP_TO_EDGE`): every pixel centre's coordinate in 1/256 texels is an integer
/// (48 x - 488, or 32 x - 112), so both renderers see the same weights and llvmpipe's 8-bit
/// fixed-point filter is the only rounding left.
fn magnified_bytes(gl: &mut dyn Gl, format: GLenum, components: usize, wrap: GLenum) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 64.0, 0.0, 64.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_2D, name[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    let texels: Vec<u8> = (0..64 * components)
        .map(|i| ((i * 7919 + (i / components) * 104_729) % 251) as u8)
        .collect();
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        format as i32,
        8,
        8,
        0,
        format,
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    let (lo, hi) = if wrap == GL_REPEAT {
        (-0.25, 1.25)
    } else {
        (0.0, 1.0)
    };
    gl.begin(GL_QUADS);
    for (s, t, x, y) in [
        (lo, lo, 0.0, 0.0),
        (hi, lo, 64.0, 0.0),
        (hi, hi, 64.0, 64.0),
        (lo, hi, 0.0, 64.0),
    ] {
        gl.tex_coord_2f(s, t);
        gl.vertex_2f(x, y);
    }
    gl.end();
}

fn magnified_rgba_repeat(gl: &mut dyn Gl) {
    magnified_bytes(gl, GL_RGBA, 4, GL_REPEAT);
}

fn magnified_luminance_edge(gl: &mut dyn Gl) {
    magnified_bytes(gl, GL_LUMINANCE, 1, GL_CLAMP_TO_EDGE);
}

fn magnified_rgb_edge(gl: &mut dyn Gl) {
    magnified_bytes(gl, GL_RGB, 3, GL_CLAMP_TO_EDGE);
}

/// Bilinear magnification of byte textures gives llvmpipe's picture exactly: tilegl filters
/// them with llvmpipe's 8-bit fixed-point rule (`tilegl::texture::fixed`), where an f32
/// filter rounds differently on a share of the pixels (by one step of 1/255).
#[test]
fn fixed_point_bilinear_magnification_equals_llvmpipe() {
    let scenes = [
        (
            "fixed_bilinear_rgba_repeat",
            magnified_rgba_repeat as fn(&mut dyn Gl),
        ),
        ("fixed_bilinear_luminance_edge", magnified_luminance_edge),
        ("fixed_bilinear_rgb_edge", magnified_rgb_edge),
    ];
    for (name, draw) in scenes {
        let scene = Scene {
            name,
            width: 64,
            height: 64,
            draw,
            tolerance: DIFFERENTIAL,
        };
        let cmp = compare_scene(&scene, DIFFERENTIAL).expect("the Mesa oracle");
        assert!(cmp.mesa_empty.is_none(), "{name}: Mesa drew nothing");
        let exact = diff(&cmp.tilegl.image, &cmp.mesa.image, 0);
        eprintln!(
            "{name}: max {} mean {:.4} differing {:.3} %",
            exact.max,
            exact.mean,
            100.0 * exact.bad_share
        );
        assert_eq!(exact.max, 0, "{name}: {}", cmp.summary());
    }
}

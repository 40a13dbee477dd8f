//! Twin tests of the block routes of draws with two texture units or more (issue 23,
//! `pair_sampled8`'s `program_block`: every unit's texels and the cascade in registers):
//! cascades that neither the `GL_COMBINE` chain nor the byte environment takes (texture
//! environment modes other than `GL_COMBINE`, fog, colours that are not bytes, a unit whose
//! texel the cascade never reads). Each state is drawn on the general path (forced) and on
//! the chosen path: the colour and depth buffers must be identical, and the draw must change
//! the picture, so that a state that drew nothing cannot pass.

mod common;

use common::{random_texture, random_triangles, read_buffers, Rng};
use tilegl::enums::*;
use tilegl::{Context, Gl};

const SIZE: i32 = 96;

type Setup = (&'static str, fn(&mut Context, &mut Rng));

/// A perspective view over random coloured, depth-tested triangles.
fn scene(gl: &mut Context, rng: &mut Rng) {
    gl.enable(GL_DEPTH_TEST);
    gl.clear_color(0.2, 0.1, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    random_triangles(gl, rng, 200);
}

/// A strip of 120 random vertices through the view volume with random colours (or `color`)
/// and random coordinates on units 0..4.
fn multi_strip(gl: &mut Context, rng: &mut Rng, color: Option<[f32; 4]>) {
    gl.begin(GL_TRIANGLE_STRIP);
    for _ in 0..120 {
        let c = color.unwrap_or_else(|| {
            [
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
            ]
        });
        gl.color_4f(c[0], c[1], c[2], c[3]);
        for unit in [GL_TEXTURE0, GL_TEXTURE1, GL_TEXTURE2, GL_TEXTURE3] {
            gl.multi_tex_coord_2f(unit, rng.range(-2.0, 2.0), rng.range(-2.0, 2.0));
        }
        gl.vertex_3f(
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-9.0, -0.5),
        );
    }
    gl.end();
}

/// A random texture of `format` and `size` on `unit`, enabled, filtered by `min`, under
/// `mode` with the constant colour (0.6, 0.5, 0.4, 0.3).
fn unit(
    gl: &mut Context,
    rng: &mut Rng,
    unit: GLenum,
    format: GLenum,
    size: i32,
    min: GLenum,
    mode: GLenum,
) {
    gl.active_texture(unit);
    random_texture(gl, rng, format, size, size);
    if min != GL_LINEAR && min != GL_NEAREST {
        gl.generate_mipmap_ext(GL_TEXTURE_2D);
    }
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, mode as i32);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.6, 0.5, 0.4, 0.3]);
    gl.active_texture(GL_TEXTURE0);
}

/// The current unit through `GL_COMBINE` with RGB and alpha function `func` of sources
/// `sources` (operands: colour, then alpha) at scale `scale`.
fn combine(gl: &mut Context, target: GLenum, func: GLenum, sources: [GLenum; 3], scale: f32) {
    gl.active_texture(target);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, func as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, func as i32);
    for (k, s) in sources.into_iter().enumerate() {
        gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + k as GLenum, s as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + k as GLenum, s as i32);
    }
    gl.tex_envi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_ALPHA as i32);
    gl.tex_envf(GL_TEXTURE_ENV, GL_RGB_SCALE, scale);
    gl.active_texture(GL_TEXTURE0);
}

/// Draws `setup`'s state over [`scene`] on the general path and on the chosen path: the
/// colour and depth buffers must be identical and the colours differ from the scene's.
fn twins(states: &[Setup]) {
    for &(name, setup) in states {
        let render = |general: bool, draw: bool| {
            let mut gl = Context::new(SIZE, SIZE);
            gl.set_force_general_path(general);
            let mut rng = Rng(0x5EED);
            scene(&mut gl, &mut rng);
            if draw {
                setup(&mut gl, &mut rng);
            }
            assert_eq!(gl.get_error(), GL_NO_ERROR, "{name}");
            read_buffers(&mut gl)
        };
        let general = render(true, true);
        let fast = render(false, true);
        let off = general
            .0
            .iter()
            .zip(&fast.0)
            .filter(|(a, b)| a != b)
            .count();
        assert_eq!(off, 0, "{name}: {off} pixels differ");
        assert_eq!(general.1, fast.1, "{name}: depth");
        let before = render(true, false);
        assert_ne!(general.0, before.0, "{name}: the draw changed nothing");
    }
}

/// Cascades of two to four units on the register block route (`program_block`): each
/// environment mode on the first units, `GL_COMBINE` after them, a unit whose texel a later
/// `REPLACE` hides, fog and blending after the cascade, colours out of [0, 1], and the byte
/// environment's cascade with colours that are not bytes (its blocks leave the byte route).
#[test]
fn multi_unit_blocks_match_the_general_path() {
    let states: [Setup; 7] = [
        ("RGBA REPLACE, LUMINANCE BLEND", |gl, rng| {
            unit(
                gl,
                rng,
                GL_TEXTURE0,
                GL_RGBA,
                32,
                GL_LINEAR_MIPMAP_LINEAR,
                GL_REPLACE,
            );
            unit(gl, rng, GL_TEXTURE1, GL_LUMINANCE, 16, GL_LINEAR, GL_BLEND);
            multi_strip(gl, rng, None);
        }),
        ("RGB MODULATE, INTENSITY ADD, EXP2 fog", |gl, rng| {
            unit(
                gl,
                rng,
                GL_TEXTURE0,
                GL_RGB,
                16,
                GL_NEAREST_MIPMAP_LINEAR,
                GL_MODULATE,
            );
            unit(gl, rng, GL_TEXTURE1, GL_INTENSITY, 8, GL_LINEAR, GL_ADD);
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_EXP2 as i32);
            gl.fogf(GL_FOG_DENSITY, 0.2);
            gl.fogfv(GL_FOG_COLOR, &[0.3, 0.6, 0.9, 0.5]);
            multi_strip(gl, rng, None);
        }),
        (
            "RGBA DECAL, MODULATE, COMBINE INTERPOLATE, alpha over",
            |gl, rng| {
                unit(
                    gl,
                    rng,
                    GL_TEXTURE0,
                    GL_RGBA,
                    16,
                    GL_LINEAR_MIPMAP_NEAREST,
                    GL_DECAL,
                );
                unit(
                    gl,
                    rng,
                    GL_TEXTURE1,
                    GL_LUMINANCE_ALPHA,
                    16,
                    GL_LINEAR,
                    GL_MODULATE,
                );
                unit(gl, rng, GL_TEXTURE2, GL_RGB, 8, GL_NEAREST, GL_MODULATE);
                combine(
                    gl,
                    GL_TEXTURE2,
                    GL_INTERPOLATE,
                    [GL_PREVIOUS, GL_TEXTURE, GL_PRIMARY_COLOR],
                    1.0,
                );
                gl.enable(GL_BLEND);
                gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                multi_strip(gl, rng, None);
            },
        ),
        ("MODULATE hidden by RGBA REPLACE", |gl, rng| {
            unit(
                gl,
                rng,
                GL_TEXTURE0,
                GL_RGB,
                16,
                GL_LINEAR_MIPMAP_LINEAR,
                GL_MODULATE,
            );
            unit(gl, rng, GL_TEXTURE1, GL_RGBA, 16, GL_LINEAR, GL_REPLACE);
            multi_strip(gl, rng, None);
        }),
        (
            "four units: ADD, COMBINE SUBTRACT x2, BLEND, colour out of [0, 1]",
            |gl, rng| {
                unit(gl, rng, GL_TEXTURE0, GL_ALPHA, 16, GL_LINEAR, GL_ADD);
                unit(
                    gl,
                    rng,
                    GL_TEXTURE1,
                    GL_RGBA,
                    32,
                    GL_LINEAR_MIPMAP_LINEAR,
                    GL_MODULATE,
                );
                combine(
                    gl,
                    GL_TEXTURE1,
                    GL_SUBTRACT,
                    [GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT],
                    2.0,
                );
                unit(
                    gl,
                    rng,
                    GL_TEXTURE2,
                    GL_LUMINANCE,
                    8,
                    GL_NEAREST,
                    GL_MODULATE,
                );
                unit(gl, rng, GL_TEXTURE3, GL_RGB, 16, GL_LINEAR, GL_BLEND);
                multi_strip(gl, rng, Some([1.5, -0.25, 0.6, 0.8]));
            },
        ),
        ("byte cascade with colours that are not bytes", |gl, rng| {
            unit(
                gl,
                rng,
                GL_TEXTURE0,
                GL_RGB,
                32,
                GL_LINEAR_MIPMAP_LINEAR,
                GL_REPLACE,
            );
            unit(
                gl,
                rng,
                GL_TEXTURE1,
                GL_LUMINANCE,
                16,
                GL_LINEAR,
                GL_MODULATE,
            );
            combine(
                gl,
                GL_TEXTURE1,
                GL_MODULATE,
                [GL_PREVIOUS, GL_TEXTURE, GL_CONSTANT],
                2.0,
            );
            multi_strip(gl, rng, None);
        }),
        (
            "MODULATE x2 with constant coordinates on unit 1",
            |gl, rng| {
                unit(
                    gl,
                    rng,
                    GL_TEXTURE0,
                    GL_RGBA,
                    32,
                    GL_LINEAR_MIPMAP_LINEAR,
                    GL_MODULATE,
                );
                unit(
                    gl,
                    rng,
                    GL_TEXTURE1,
                    GL_RGB,
                    16,
                    GL_LINEAR_MIPMAP_LINEAR,
                    GL_MODULATE,
                );
                gl.begin(GL_TRIANGLE_STRIP);
                gl.multi_tex_coord_2f(GL_TEXTURE1, 0.3, 0.7);
                for _ in 0..120 {
                    gl.color_3f(
                        rng.range(0.0, 1.0),
                        rng.range(0.0, 1.0),
                        rng.range(0.0, 1.0),
                    );
                    gl.tex_coord_2f(rng.range(-2.0, 2.0), rng.range(-2.0, 2.0));
                    gl.vertex_3f(
                        rng.range(-3.0, 3.0),
                        rng.range(-3.0, 3.0),
                        rng.range(-9.0, -0.5),
                    );
                }
                gl.end();
            },
        ),
    ];
    twins(&states);
}

//! Twin tests of the eight-lane paths that took over from the per-fragment general path:
//! the stencil test and its actions ahead of the eight-fragment tail, cube maps on the
//! eight-pixel samplers, and antialiased lines' edge pixels in the untextured tail. Each state
//! is drawn on the general path (forced) and on the chosen path, and the colour, depth and stencil buffers must be identical; each draw must also
//! change the picture (or the stencil), so that a state that drew nothing cannot pass.

mod common;

use common::{random_texture, random_triangles, read_buffers, Rng};
use tilegl::enums::*;
use tilegl::{Context, Gl};

const SIZE: i32 = 96;

/// A perspective view over random coloured triangles (depth-tested), a stencil buffer
/// holding a few different values (strips drawn with `REPLACE` and `INCR` before), and the
/// state's texture set up by `setup`.
fn scene(gl: &mut Context, rng: &mut Rng) {
    gl.enable(GL_DEPTH_TEST);
    gl.clear_color(0.2, 0.1, 0.0, 1.0);
    gl.clear_stencil(0x10);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_ALWAYS, 0x13, 0xFF);
    gl.stencil_op(GL_KEEP, GL_INCR, GL_REPLACE);
    random_triangles(gl, rng, 300);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_INCR);
    strip(gl, rng, false, false);
    gl.disable(GL_STENCIL_TEST);
}

/// A strip of 120 random vertices through the view volume with random colours (`translucent`:
/// random alphas too; `constant`: one colour for all) and random normals.
fn strip(gl: &mut Context, rng: &mut Rng, translucent: bool, constant: bool) {
    gl.color_4f(0.8, 0.6, 0.3, 0.7);
    gl.begin(GL_TRIANGLE_STRIP);
    for _ in 0..120 {
        if !constant {
            let (r, g, b) = (
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
            );
            let a = if translucent {
                rng.range(0.0, 1.0)
            } else {
                1.0
            };
            gl.color_4f(r, g, b, a);
        }
        gl.normal_3f(
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        );
        gl.tex_coord_2f(rng.range(-2.0, 2.0), rng.range(-2.0, 2.0));
        gl.vertex_3f(
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-9.0, -0.5),
        );
    }
    gl.end();
}

type Setup = (&'static str, fn(&mut Context, &mut Rng));

/// Draws `setup`'s state over [`scene`] on the general path and on the chosen path: the three
/// buffers must be identical and differ from the scene's.
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
        let count = |a: &[u8], b: &[u8]| a.iter().zip(b).filter(|(x, y)| x != y).count();
        let off = general
            .0
            .iter()
            .zip(&fast.0)
            .filter(|(a, b)| a != b)
            .count();
        assert_eq!(off, 0, "{name}: {off} pixels differ");
        assert_eq!(count(&general.1, &fast.1), 0, "{name}: depth");
        assert_eq!(count(&general.2, &fast.2), 0, "{name}: stencil");
        let before = render(true, false);
        let moved = general.0 != before.0 || general.2 != before.2;
        assert!(moved, "{name}: the draw changed nothing");
    }
}

/// The stencil test on the eight-lane paths: untextured (`span_untextured8`), one RGBA unit
/// (`pair_textured` and the row paths), two units with fog (`pair_sampled8`), a constant colour
/// (the blocks' constant form), every function and action, masks, and the alpha test (which
/// keeps such keys on the general path).
#[test]
fn stencil_on_eight_lane_paths_matches_the_general_path() {
    let states: [Setup; 8] = [
        ("untextured, EQUAL, INCR/DECR/INVERT", |gl, rng| {
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_EQUAL, 0x11, 0x3F);
            gl.stencil_op(GL_INVERT, GL_DECR, GL_INCR);
            strip(gl, rng, false, false);
        }),
        (
            "untextured, over, NOTEQUAL, no depth test (the shadow quad)",
            |gl, rng| {
                gl.enable(GL_STENCIL_TEST);
                gl.stencil_func(GL_NOTEQUAL, 0x10, 0xFF);
                gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
                gl.disable(GL_DEPTH_TEST);
                gl.enable(GL_BLEND);
                gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                strip(gl, rng, true, false);
            },
        ),
        ("untextured, write mask, colour mask, GREATER", |gl, rng| {
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_GREATER, 0x12, 0x1F);
            gl.stencil_mask(0xF5);
            gl.stencil_op(GL_ZERO, GL_INCR_WRAP, GL_DECR_WRAP);
            gl.color_mask(1, 0, 1, 1);
            strip(gl, rng, false, false);
        }),
        ("one RGBA unit, trilinear, GEQUAL, REPLACE", |gl, rng| {
            random_texture(gl, rng, GL_RGBA, 32, 32);
            gl.tex_parameteri(
                GL_TEXTURE_2D,
                GL_TEXTURE_MIN_FILTER,
                GL_LINEAR_MIPMAP_LINEAR as i32,
            );
            gl.enable(GL_TEXTURE_2D);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_GEQUAL, 0x11, 0xFF);
            gl.stencil_op(GL_REPLACE, GL_ZERO, GL_INCR);
            strip(gl, rng, true, false);
        }),
        ("one RGB unit, constant colour, LESS, blended", |gl, rng| {
            random_texture(gl, rng, GL_RGB, 16, 16);
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
            gl.enable(GL_TEXTURE_2D);
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_LESS, 0x10, 0xFF);
            gl.stencil_op(GL_INVERT, GL_INCR, GL_DECR);
            strip(gl, rng, false, true);
        }),
        ("two units, EXP fog, LEQUAL", |gl, rng| {
            random_texture(gl, rng, GL_RGBA, 16, 16);
            gl.tex_parameteri(
                GL_TEXTURE_2D,
                GL_TEXTURE_MIN_FILTER,
                GL_NEAREST_MIPMAP_LINEAR as i32,
            );
            gl.enable(GL_TEXTURE_2D);
            gl.active_texture(GL_TEXTURE1);
            random_texture(gl, rng, GL_LUMINANCE, 8, 8);
            gl.enable(GL_TEXTURE_2D);
            gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD as i32);
            gl.active_texture(GL_TEXTURE0);
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_EXP as i32);
            gl.fogf(GL_FOG_DENSITY, 0.2);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_LEQUAL, 0x11, 0xFF);
            gl.stencil_op(GL_KEEP, GL_REPLACE, GL_INCR);
            strip(gl, rng, false, false);
        }),
        ("one RGBA unit, alpha test (general path)", |gl, rng| {
            random_texture(gl, rng, GL_RGBA, 16, 16);
            gl.enable(GL_TEXTURE_2D);
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_GREATER, 0.4);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_ALWAYS, 0x30, 0xFF);
            gl.stencil_op(GL_KEEP, GL_INCR, GL_REPLACE);
            strip(gl, rng, true, false);
        }),
        ("depth-only volumes, z-fail", |gl, rng| {
            gl.color_mask(0, 0, 0, 0);
            gl.depth_mask(0);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_ALWAYS, 0, 0xFF);
            gl.stencil_op(GL_KEEP, GL_INCR_WRAP, GL_KEEP);
            strip(gl, rng, false, false);
            gl.stencil_op(GL_KEEP, GL_DECR, GL_KEEP);
            gl.depth_func(GL_GREATER);
            strip(gl, rng, false, false);
        }),
    ];
    twins(&states);
}

/// A cube map on the current unit: six random faces of `size` (a power of two) with every
/// mipmap level, in `format`, filtered by `min` / `mag`, wrapped by `wrap`.
fn cube_map(gl: &mut Context, rng: &mut Rng, format: GLenum, size: i32, filters: [GLenum; 3]) {
    let [min, mag, wrap] = filters;
    let comps = match format {
        GL_RGBA => 4,
        GL_RGB => 3,
        GL_LUMINANCE_ALPHA => 2,
        _ => 1,
    };
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_CUBE_MAP, name[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    for face in 0..6 {
        let (mut s, mut level) = (size, 0);
        while s >= 1 {
            let texels: Vec<u8> = (0..s * s * comps)
                .map(|_| (rng.next_u64() >> 56) as u8)
                .collect();
            gl.tex_image_2d(
                GL_TEXTURE_CUBE_MAP_POSITIVE_X + face,
                level,
                format as i32,
                s,
                s,
                0,
                format,
                GL_UNSIGNED_BYTE,
                Some(&texels),
            );
            s /= 2;
            level += 1;
        }
    }
    gl.tex_parameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_parameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, mag as i32);
    for p in [GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R] {
        gl.tex_parameteri(GL_TEXTURE_CUBE_MAP, p, wrap as i32);
    }
    gl.enable(GL_TEXTURE_CUBE_MAP);
}

/// Texture coordinates generated by `mode` for s, t and r.
fn texgen(gl: &mut Context, mode: GLenum) {
    for c in [GL_S, GL_T, GL_R] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, mode as i32);
    }
    for c in [GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R] {
        gl.enable(c);
    }
}

/// Cube maps on the eight-pixel samplers: fixed and per-lane level plans (bilinear without
/// mipmaps, trilinear, nearest mipmaps with the 0.5 switch-over), reflection and normal-map
/// texture generation, explicit directions with q, one-, two- and four-byte texels, wrap
/// modes, a cube map beside a 2D unit, fog, blending, and lighting as the `cubemap` workload
/// draws it.
#[test]
fn cube_maps_on_eight_lane_paths_match_the_general_path() {
    let states: [Setup; 9] = [
        (
            "RGB, bilinear, reflection map, lit (the workload)",
            |gl, rng| {
                cube_map(
                    gl,
                    rng,
                    GL_RGB,
                    32,
                    [GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE],
                );
                texgen(gl, GL_REFLECTION_MAP);
                gl.enable(GL_LIGHTING);
                gl.enable(GL_LIGHT0);
                gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.4, 1.0, 0.8, 0.0]);
                strip(gl, rng, false, false);
            },
        ),
        ("RGBA, trilinear, normal map, blended", |gl, rng| {
            cube_map(
                gl,
                rng,
                GL_RGBA,
                16,
                [GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT],
            );
            texgen(gl, GL_NORMAL_MAP);
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            strip(gl, rng, true, false);
        }),
        (
            "LUMINANCE, nearest mipmaps, linear magnification",
            |gl, rng| {
                cube_map(
                    gl,
                    rng,
                    GL_LUMINANCE,
                    64,
                    [GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR, GL_CLAMP_TO_EDGE],
                );
                texgen(gl, GL_REFLECTION_MAP);
                gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
                strip(gl, rng, false, false);
            },
        ),
        (
            "LUMINANCE_ALPHA, explicit directions with q, nearest",
            |gl, rng| {
                cube_map(
                    gl,
                    rng,
                    GL_LUMINANCE_ALPHA,
                    8,
                    [GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST, GL_REPEAT],
                );
                gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL as i32);
                gl.begin(GL_TRIANGLE_STRIP);
                for _ in 0..120 {
                    gl.color_3f(
                        rng.range(0.0, 1.0),
                        rng.range(0.0, 1.0),
                        rng.range(0.0, 1.0),
                    );
                    let q = rng.range(0.3, 2.0);
                    gl.tex_coord_4f(
                        rng.range(-1.0, 1.0),
                        rng.range(-1.0, 1.0),
                        rng.range(-1.0, 1.0),
                        q,
                    );
                    gl.vertex_3f(
                        rng.range(-3.0, 3.0),
                        rng.range(-3.0, 3.0),
                        rng.range(-9.0, -0.5),
                    );
                }
                gl.end();
            },
        ),
        ("2D unit and a cube map, LINEAR fog", |gl, rng| {
            random_texture(gl, rng, GL_RGBA, 16, 16);
            gl.tex_parameteri(
                GL_TEXTURE_2D,
                GL_TEXTURE_MIN_FILTER,
                GL_LINEAR_MIPMAP_NEAREST as i32,
            );
            gl.enable(GL_TEXTURE_2D);
            gl.active_texture(GL_TEXTURE1);
            cube_map(
                gl,
                rng,
                GL_RGB,
                16,
                [GL_LINEAR, GL_NEAREST, GL_CLAMP_TO_EDGE],
            );
            texgen(gl, GL_REFLECTION_MAP);
            gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD as i32);
            gl.active_texture(GL_TEXTURE0);
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_LINEAR as i32);
            gl.fogf(GL_FOG_START, 1.0);
            gl.fogf(GL_FOG_END, 9.0);
            strip(gl, rng, false, false);
        }),
        ("RGB cube map, stencil, constant colour", |gl, rng| {
            cube_map(
                gl,
                rng,
                GL_RGB,
                16,
                [GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE],
            );
            texgen(gl, GL_NORMAL_MAP);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_NOTEQUAL, 0x11, 0xFF);
            gl.stencil_op(GL_KEEP, GL_INCR, GL_ZERO);
            strip(gl, rng, false, true);
        }),
        ("RGBA cube map, separate specular, alpha test", |gl, rng| {
            cube_map(
                gl,
                rng,
                GL_RGBA,
                32,
                [GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE],
            );
            texgen(gl, GL_REFLECTION_MAP);
            gl.enable(GL_LIGHTING);
            gl.enable(GL_LIGHT0);
            gl.light_modeli(
                GL_LIGHT_MODEL_COLOR_CONTROL,
                GL_SEPARATE_SPECULAR_COLOR as i32,
            );
            gl.materialfv(GL_FRONT, GL_SPECULAR, &[0.8, 0.8, 0.8, 1.0]);
            gl.materialf(GL_FRONT, GL_SHININESS, 20.0);
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_GREATER, 0.3);
            strip(gl, rng, false, false);
        }),
        ("RGBA cube map, COMBINE INTERPOLATE, lit", |gl, rng| {
            cube_map(
                gl,
                rng,
                GL_RGBA,
                16,
                [GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE],
            );
            texgen(gl, GL_REFLECTION_MAP);
            gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PRIMARY_COLOR as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_CONSTANT as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_SUBTRACT as i32);
            gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.6, 0.5, 0.4, 0.3]);
            gl.enable(GL_LIGHTING);
            gl.enable(GL_LIGHT0);
            gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.4, 1.0, 0.8, 0.0]);
            strip(gl, rng, false, false);
        }),
        (
            "RGB cube map, BLEND environment, nearest, normal map",
            |gl, rng| {
                cube_map(gl, rng, GL_RGB, 16, [GL_NEAREST, GL_NEAREST, GL_REPEAT]);
                texgen(gl, GL_NORMAL_MAP);
                gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND as i32);
                gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.2, 0.9, 0.4, 0.7]);
                strip(gl, rng, true, false);
            },
        ),
    ];
    twins(&states);
}

/// Quads facing the viewer: z, 1/w, the colour and the fog coordinate are the same along
/// every row, so the one-unit textured span fills its groups from one set of inputs (fog
/// factors made once); over the scene, with fog, blending and depth tests that pass and fail.
fn facing_quads(gl: &mut Context, rng: &mut Rng) {
    random_texture(gl, rng, GL_RGBA, 16, 16);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.enable(GL_TEXTURE_2D);
    for k in 0..6 {
        let z = -1.5 - 1.3 * k as f32;
        let (x, y) = (rng.range(-2.0, 1.0), rng.range(-2.0, 1.0));
        gl.color_4f(
            rng.range(0.3, 1.0),
            rng.range(0.3, 1.0),
            rng.range(0.3, 1.0),
            0.6,
        );
        gl.begin(GL_QUADS);
        for (i, (dx, dy)) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
            .iter()
            .enumerate()
        {
            gl.tex_coord_2f(dx * 1.7, dy * 1.3 + i as f32 * 0.01);
            gl.vertex_3f(x + dx * 2.5, y + dy * 2.5, z);
        }
        gl.end();
    }
}

#[test]
fn facing_textured_quads_match_the_general_path() {
    let states: [Setup; 3] = [
        ("EXP2 fog", |gl, rng| {
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_EXP2 as i32);
            gl.fogf(GL_FOG_DENSITY, 0.25);
            gl.fogfv(GL_FOG_COLOR, &[0.1, 0.6, 0.9, 1.0]);
            facing_quads(gl, rng);
        }),
        ("LINEAR fog, over, depth writes off", |gl, rng| {
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_LINEAR as i32);
            gl.fogf(GL_FOG_START, 1.0);
            gl.fogf(GL_FOG_END, 9.0);
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            gl.depth_mask(0);
            facing_quads(gl, rng);
        }),
        ("no fog, GREATER depth", |gl, rng| {
            gl.depth_func(GL_GREATER);
            facing_quads(gl, rng);
        }),
    ];
    twins(&states);
}

/// 150 antialiased segments of width `width`, each with one colour (random alpha) and both
/// ends at one eye depth, so that every fragment of a segment has the same values and the
/// pixels next to each other in a row, edge pixels included, are shaded as one run with a
/// coverage per pixel (`span_untextured8_covered`); every fifth segment has ends at
/// different depths (the per-fragment route).
fn smooth_lines(gl: &mut Context, rng: &mut Rng, width: f32) {
    gl.enable(GL_LINE_SMOOTH);
    gl.line_width(width);
    gl.begin(GL_LINES);
    for k in 0..150 {
        gl.color_4f(
            rng.range(0.2, 1.0),
            rng.range(0.2, 1.0),
            rng.range(0.2, 1.0),
            rng.range(0.1, 1.0),
        );
        let z = rng.range(-8.0, -1.2);
        let z1 = if k % 5 == 4 { z + 0.7 } else { z };
        let (x, y) = (rng.range(-1.2, 1.2) * -z, rng.range(-1.2, 1.2) * -z);
        let (len, ang) = (rng.range(0.05, 1.0) * -z, rng.range(0.0, 6.3));
        gl.vertex_3f(x, y, z);
        gl.vertex_3f(x + len * ang.cos(), y + len * ang.sin(), z1);
    }
    gl.end();
}

/// Flat sprites under an orthographic projection (the `sprites` workload's kind): each quad
/// has one depth, one colour and a constant 1/w, so every fragment of its triangles has the
/// same inputs and the one-unit textured span takes them once per primitive
/// (`SpanRun::constant_group`). Quads of 1 to 40 pixels at fractional positions, so that
/// spans start and end at every column relative to the restart columns and tile edges;
/// trilinear RGBA texture with the alpha test and blending, depth tested with writes off
/// and on; with fog (EXP, constant along a flat quad) and with colours that vary per vertex or
/// depths that vary per quad (which keep the per-span steady or stepped routes), in one draw.
fn sprites(gl: &mut Context, rng: &mut Rng, varied: bool) {
    random_texture(gl, rng, GL_RGBA, 32, 32);
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
    gl.enable(GL_TEXTURE_2D);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, SIZE as f64, 0.0, SIZE as f64, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.begin(GL_QUADS);
    for k in 0..400 {
        let (x, y) = (rng.range(-8.0, SIZE as f32), rng.range(-8.0, SIZE as f32));
        let half = rng.range(0.5, 20.0);
        let z = rng.range(-0.9, 0.9);
        gl.color_4f(
            rng.range(0.3, 1.0),
            rng.range(0.3, 1.0),
            rng.range(0.3, 1.0),
            rng.range(0.2, 1.0),
        );
        for (i, (dx, dy)) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
            .into_iter()
            .enumerate()
        {
            if varied && k % 3 == 0 {
                gl.color_4f(rng.range(0.3, 1.0), 0.5, rng.range(0.3, 1.0), 0.8);
            }
            let dz = if varied && k % 3 == 1 {
                0.1 * i as f32
            } else {
                0.0
            };
            gl.tex_coord_2f((dx + 1.0) / 2.0, (dy + 1.0) / 2.0);
            gl.vertex_3f(x + dx * half, y + dy * half, z + dz);
        }
    }
    gl.end();
}

/// Antialiased lines whose fragments have the same values: their runs of edge pixels go
/// eight at a time through the untextured tail with the coverage multiplied into each lane's
/// alpha, against each pixel alone on the general path; with blending (over, additive, a
/// constant colour), the alpha test (where coverage decides), fog, the stencil test, depth
/// tests with and without writes, a colour mask, stippling and widths from 1 to 7.5.
#[test]
fn antialiased_lines_on_eight_lane_paths_match_the_general_path() {
    let states: [Setup; 7] = [
        ("over, LESS with depth writes, width 2.5", |gl, rng| {
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            smooth_lines(gl, rng, 2.5);
        }),
        ("no blending, alpha test GREATER 0.3, width 4", |gl, rng| {
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_GREATER, 0.3);
            smooth_lines(gl, rng, 4.0);
        }),
        (
            "additive, EXP2 fog, colour mask, depth writes off",
            |gl, rng| {
                gl.enable(GL_BLEND);
                gl.blend_func(GL_SRC_ALPHA, GL_ONE);
                gl.enable(GL_FOG);
                gl.fogi(GL_FOG_MODE, GL_EXP2 as i32);
                gl.fogf(GL_FOG_DENSITY, 0.2);
                gl.fogfv(GL_FOG_COLOR, &[0.1, 0.6, 0.9, 1.0]);
                gl.color_mask(1, 1, 0, 1);
                gl.depth_mask(0);
                smooth_lines(gl, rng, 2.5);
            },
        ),
        ("over, stencil EQUAL with INCR, width 1", |gl, rng| {
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_EQUAL, 0x11, 0xFF);
            gl.stencil_op(GL_DECR, GL_INVERT, GL_INCR);
            smooth_lines(gl, rng, 1.0);
        }),
        (
            "constant-alpha blending, no depth test, width 7.5",
            |gl, rng| {
                gl.disable(GL_DEPTH_TEST);
                gl.enable(GL_BLEND);
                gl.blend_color(0.2, 0.4, 0.6, 0.3);
                gl.blend_func(GL_SRC_ALPHA_SATURATE, GL_ONE_MINUS_CONSTANT_ALPHA);
                smooth_lines(gl, rng, 7.5);
            },
        ),
        ("over, stippled, GREATER depth", |gl, rng| {
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            gl.enable(GL_LINE_STIPPLE);
            gl.line_stipple(2, 0x39CF);
            gl.depth_func(GL_GREATER);
            smooth_lines(gl, rng, 3.0);
        }),
        (
            "linear fog, alpha test with blending, width 1.5",
            |gl, rng| {
                gl.enable(GL_FOG);
                gl.fogi(GL_FOG_MODE, GL_LINEAR as i32);
                gl.fogf(GL_FOG_START, 1.0);
                gl.fogf(GL_FOG_END, 9.0);
                gl.enable(GL_ALPHA_TEST);
                gl.alpha_func(GL_LESS, 0.6);
                gl.enable(GL_BLEND);
                gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                smooth_lines(gl, rng, 1.5);
            },
        ),
    ];
    twins(&states);
}

/// 200 aliased segments of width `width` (one colour each, ends at one depth), window
/// x-major and y-major, some through the window's edges.
fn aliased_lines(gl: &mut Context, rng: &mut Rng, width: f32) {
    gl.line_width(width);
    gl.begin(GL_LINES);
    for _ in 0..200 {
        gl.color_4f(
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
        );
        let z = rng.range(-8.0, -1.2);
        let (x, y) = (rng.range(-1.3, 1.3) * -z, rng.range(-1.3, 1.3) * -z);
        let (len, ang) = (rng.range(0.02, 1.5) * -z, rng.range(0.0, 6.3));
        gl.vertex_3f(x, y, z);
        gl.vertex_3f(x + len * ang.cos(), y + len * ang.sin(), z);
    }
    gl.end();
}

/// Antialiased lines walked row by row (their coverages eight at a time) and aliased lines
/// whose colour is stored directly, against the general path's column walk and per-fragment
/// stage: with a scissor rectangle cutting segments on both axes, tiles of every size the
/// window makes, and the states that keep the direct store (no depth test, no blending) or
/// leave it (a colour mask, depth writes).
#[test]
fn lines_by_rows_and_direct_stores_match_the_general_path() {
    let states: [Setup; 6] = [
        ("aliased width 3, no depth test", |gl, rng| {
            gl.disable(GL_DEPTH_TEST);
            aliased_lines(gl, rng, 3.0);
        }),
        ("aliased widths 1 and 4, scissor", |gl, rng| {
            gl.disable(GL_DEPTH_TEST);
            gl.enable(GL_SCISSOR_TEST);
            gl.scissor(7, 13, 61, 70);
            aliased_lines(gl, rng, 1.0);
            aliased_lines(gl, rng, 4.0);
        }),
        ("aliased width 2, colour mask, depth writes", |gl, rng| {
            gl.color_mask(1, 0, 1, 1);
            aliased_lines(gl, rng, 2.0);
        }),
        (
            "smooth over, no depth test, scissor, width 2.5",
            |gl, rng| {
                gl.disable(GL_DEPTH_TEST);
                gl.enable(GL_SCISSOR_TEST);
                gl.scissor(5, 11, 70, 63);
                gl.enable(GL_BLEND);
                gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                smooth_lines(gl, rng, 2.5);
            },
        ),
        ("smooth without blending, width 1 then 6", |gl, rng| {
            smooth_lines(gl, rng, 1.0);
            smooth_lines(gl, rng, 6.0);
        }),
        ("smooth over with LEQUAL depth, width 11", |gl, rng| {
            gl.depth_func(GL_LEQUAL);
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            smooth_lines(gl, rng, 11.0);
        }),
    ];
    twins(&states);
}

#[test]
fn flat_sprites_match_the_general_path() {
    let states: [Setup; 7] = [
        ("sprites: alpha test, over, depth writes off", |gl, rng| {
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_GREATER, 0.35);
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            gl.depth_mask(0);
            sprites(gl, rng, false);
        }),
        ("sprites: depth writes on, LEQUAL", |gl, rng| {
            gl.depth_func(GL_LEQUAL);
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_GEQUAL, 0.5);
            sprites(gl, rng, false);
        }),
        ("sprites: EXP fog, blended", |gl, rng| {
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_EXP as i32);
            gl.fogf(GL_FOG_DENSITY, 0.7);
            gl.fogfv(GL_FOG_COLOR, &[0.9, 0.2, 0.4, 1.0]);
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            sprites(gl, rng, false);
        }),
        ("sprites: varied colours and depths", |gl, rng| {
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_GREATER, 0.2);
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            sprites(gl, rng, true);
        }),
        // The flat rows' depth test (`flat.rs`) chooses its function once per row: the
        // other functions, with and without writes, and no depth test.
        // The same sprites drawn again (the generator restarted) meet their own depths:
        // the functions' equal cases decide.
        (
            "sprites: GREATER, then LESS and GREATER on equal depths",
            |gl, rng| {
                let again = Rng(rng.0);
                gl.depth_func(GL_GREATER);
                gl.enable(GL_ALPHA_TEST);
                gl.alpha_func(GL_GREATER, 0.3);
                sprites(gl, rng, false);
                gl.enable(GL_BLEND);
                gl.blend_func(GL_ONE, GL_ONE);
                for func in [GL_LESS, GL_GREATER] {
                    gl.depth_func(func);
                    sprites(gl, &mut Rng(again.0), false);
                }
            },
        ),
        (
            "sprites: NOTEQUAL, then GEQUAL, EQUAL, LEQUAL, NOTEQUAL on equal depths",
            |gl, rng| {
                let again = Rng(rng.0);
                gl.enable(GL_BLEND);
                gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                gl.depth_func(GL_NOTEQUAL);
                sprites(gl, rng, false);
                gl.depth_mask(0);
                for func in [GL_GEQUAL, GL_EQUAL, GL_LEQUAL, GL_NOTEQUAL] {
                    gl.depth_func(func);
                    sprites(gl, &mut Rng(again.0), false);
                }
            },
        ),
        ("sprites: no depth test, ALWAYS", |gl, rng| {
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            gl.disable(GL_DEPTH_TEST);
            sprites(gl, rng, false);
            gl.enable(GL_DEPTH_TEST);
            gl.depth_func(GL_ALWAYS);
            sprites(gl, rng, false);
        }),
    ];
    twins(&states);
}

/// Flat sprites whose primary colours are bytes (`glColor4ub`): their rows take the byte route
/// (`fragment::simd::flat_groups_bytes`: the environment and tail on bytes) when nothing after
/// the environment needs the f32 colour. RGB and RGBA (the formats of the flat route) under
/// REPLACE and MODULATE, nearest, bilinear and trilinear, with and without blending, depth functions with and without
/// writes, a colour mask, q not 1 (the coordinates' divisions), sprites under a perspective
/// projection, and coordinates too large for the filter (those groups go one pixel at a
/// time).
#[test]
fn flat_sprites_on_the_byte_route_match_the_general_path() {
    let states: [Setup; 8] = [
        ("byte sprites: RGBA REPLACE, LESS with writes", |gl, rng| {
            gl.depth_func(GL_LESS);
            byte_sprites(gl, rng, GL_RGBA, GL_REPLACE, GL_LINEAR, 1.0, 1.0);
        }),
        (
            "byte sprites: RGB MODULATE, over, no depth writes",
            |gl, rng| {
                gl.enable(GL_BLEND);
                gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                gl.depth_mask(0);
                byte_sprites(
                    gl,
                    rng,
                    GL_RGB,
                    GL_MODULATE,
                    GL_LINEAR_MIPMAP_LINEAR,
                    1.0,
                    1.0,
                );
            },
        ),
        ("byte sprites: RGB REPLACE, GREATER, q = 2", |gl, rng| {
            gl.depth_func(GL_GREATER);
            byte_sprites(gl, rng, GL_RGB, GL_REPLACE, GL_LINEAR, 2.0, 1.0);
        }),
        (
            "byte sprites: RGBA MODULATE, ONE ONE, colour mask",
            |gl, rng| {
                gl.enable(GL_BLEND);
                gl.blend_func(GL_ONE, GL_ONE);
                gl.color_mask(1, 0, 1, 1);
                byte_sprites(gl, rng, GL_RGBA, GL_MODULATE, GL_LINEAR, 1.0, 1.0);
                gl.color_mask(1, 1, 1, 1);
            },
        ),
        (
            "byte sprites: RGB REPLACE, no depth test, over",
            |gl, rng| {
                gl.disable(GL_DEPTH_TEST);
                gl.enable(GL_BLEND);
                gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                byte_sprites(gl, rng, GL_RGB, GL_REPLACE, GL_NEAREST, 1.0, 1.0);
            },
        ),
        (
            "byte sprites: RGBA MODULATE, LEQUAL, mipmapped",
            |gl, rng| {
                gl.depth_func(GL_LEQUAL);
                byte_sprites(
                    gl,
                    rng,
                    GL_RGBA,
                    GL_MODULATE,
                    GL_NEAREST_MIPMAP_LINEAR,
                    1.0,
                    1.0,
                );
            },
        ),
        (
            "byte sprites: RGBA MODULATE, perspective, q = 0.5",
            |gl, rng| {
                byte_sprites(gl, rng, GL_RGBA, GL_MODULATE, GL_LINEAR, 0.5, -2.0);
            },
        ),
        (
            "byte sprites: RGBA REPLACE, coordinates past the filter's range",
            |gl, rng| {
                byte_sprites(gl, rng, GL_RGBA, GL_REPLACE, GL_NEAREST, 1.0e-7, 1.0);
            },
        ),
    ];
    twins(&states);
}

/// The `overdraw` workload's layers in small: rotated quads over the whole view (each nearer
/// than the last) of a `size`-square random texture of `format`, trilinear, `wrap` on both
/// axes, coordinates spanning up to eight periods (minified) or a fraction of one (magnified),
/// with constant q `q` (the coordinates scaled by it, so the same texels up to rounding).
fn layers(gl: &mut Context, rng: &mut Rng, format: GLenum, size: i32, wrap: GLenum, q: f32) {
    random_texture(gl, rng, format, size, size);
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.depth_func(GL_LESS);
    gl.begin(GL_QUADS);
    for k in 0..8 {
        let scale = [0.3, 1.0, 2.0, 3.0, 5.0, 8.0, 1.5, 0.7][k];
        let a = rng.range(0.0, 6.3);
        let (c, s) = (a.cos() * scale, a.sin() * scale);
        let (u0, v0) = (rng.range(-3.0, 3.0), rng.range(-3.0, 3.0));
        gl.color_4f(
            rng.range(0.3, 1.0),
            rng.range(0.3, 1.0),
            rng.range(0.3, 1.0),
            1.0,
        );
        let z = 0.9 - 0.2 * k as f32;
        for (x, y) in [(-1.0f32, -1.0f32), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            let (u, v) = (u0 + c * x - s * y, v0 + s * x + c * y);
            gl.tex_coord_4f(u * q, v * q, 0.0, q);
            gl.vertex_3f(x, y, z);
        }
    }
    gl.end();
}

/// The flat rows of large affine quads (`flat.rs`, the `overdraw` workload's route): the
/// depth test and writes of whole groups, the coordinates without the divisions by 1, the
/// filter's texel pairs, against the general path.
#[test]
fn flat_layers_match_the_general_path() {
    let states: [Setup; 6] = [
        ("layers: RGBA 32, REPEAT", |gl, rng| {
            layers(gl, rng, GL_RGBA, 32, GL_REPEAT, 1.0)
        }),
        ("layers: RGBA 16, CLAMP_TO_EDGE", |gl, rng| {
            layers(gl, rng, GL_RGBA, 16, GL_CLAMP_TO_EDGE, 1.0)
        }),
        ("layers: RGBA 64, REPEAT, q = 2", |gl, rng| {
            layers(gl, rng, GL_RGBA, 64, GL_REPEAT, 2.0)
        }),
        ("layers: RGB 32, REPEAT", |gl, rng| {
            layers(gl, rng, GL_RGB, 32, GL_REPEAT, 1.0)
        }),
        ("layers: LUMINANCE_ALPHA 8, REPEAT", |gl, rng| {
            layers(gl, rng, GL_LUMINANCE_ALPHA, 8, GL_REPEAT, 1.0)
        }),
        (
            "layers: RGBA 32, REPEAT, depth writes off, blended",
            |gl, rng| {
                gl.depth_mask(0);
                gl.enable(GL_BLEND);
                gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                layers(gl, rng, GL_RGBA, 32, GL_REPEAT, 1.0)
            },
        ),
    ];
    twins(&states);
}

/// 300 sprites of byte colours with a random `format` texture under `mode` filtered by
/// `min`, texture coordinates given as (s q, t q, 0, q); at `depth` 1 in a window-sized
/// orthographic view (w = 1), otherwise facing quads at z = `depth` under a frustum.
fn byte_sprites(
    gl: &mut Context,
    rng: &mut Rng,
    format: GLenum,
    mode: GLenum,
    min: GLenum,
    q: f32,
    depth: f32,
) {
    random_texture(gl, rng, format, 32, 32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, mode as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    let ortho = depth == 1.0;
    if ortho {
        gl.ortho(0.0, SIZE as f64, 0.0, SIZE as f64, -1.0, 1.0);
    } else {
        gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    }
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    let byte = |rng: &mut Rng, lo: u8| lo + (rng.next_u64() % (256 - lo as u64)) as u8;
    gl.begin(GL_QUADS);
    for k in 0..300 {
        let (x, y, half, z) = if ortho {
            (
                rng.range(-8.0, SIZE as f32),
                rng.range(-8.0, SIZE as f32),
                rng.range(0.5, 20.0),
                rng.range(-0.9, 0.9),
            )
        } else {
            let r = -depth;
            (
                rng.range(-r, r),
                rng.range(-r, r),
                rng.range(0.01, 0.3) * r,
                depth + 0.01 * (k % 7) as f32,
            )
        };
        // The texture repeated 1 to 4 times over the sprite (magnified and minified).
        let reps = rng.range(0.25, 4.0);
        let c = [byte(rng, 40), byte(rng, 40), byte(rng, 40), byte(rng, 60)];
        gl.color_4ub(c[0], c[1], c[2], c[3]);
        for (dx, dy) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            let (s, t) = ((dx + 1.0) * reps, (dy + 1.0) * reps);
            // q below 1e-6: s / q beyond the filter's range (2^30 / 256 / 32).
            gl.tex_coord_4f(s, t, 0.0, q);
            gl.vertex_3f(x + dx * half, y + dy * half, z);
        }
    }
    gl.end();
}

/// A strip of 120 random vertices with texture coordinates on units 0-2, all of colour
/// `color` (or random colours with `None`).
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
        for unit in [GL_TEXTURE0, GL_TEXTURE1, GL_TEXTURE2] {
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
/// `mode` (for `GL_COMBINE`, the RGB and alpha functions, the first two sources of each and
/// the scales).
#[allow(clippy::too_many_arguments)]
fn unit(
    gl: &mut Context,
    rng: &mut Rng,
    unit: GLenum,
    format: GLenum,
    size: i32,
    min: GLenum,
    mode: GLenum,
    combine: Option<([GLenum; 2], [GLenum; 2], [f32; 2])>,
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
    if let Some(([rgb, alpha], [s0, s1], [rgb_scale, alpha_scale])) = combine {
        gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, rgb as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, alpha as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, s0 as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, s1 as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, s0 as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, s1 as i32);
        gl.tex_envf(GL_TEXTURE_ENV, GL_RGB_SCALE, rgb_scale);
        gl.tex_envf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, alpha_scale);
    }
    gl.active_texture(GL_TEXTURE0);
}

/// The light-map units of `byte_environment_matches_the_general_path`: an RGB trilinear base
/// replaced on unit 0, a LUMINANCE light map modulated at scale 2 on unit 1.
fn lightmap_units(gl: &mut Context, rng: &mut Rng) {
    unit(
        gl,
        rng,
        GL_TEXTURE0,
        GL_RGB,
        32,
        GL_LINEAR_MIPMAP_LINEAR,
        GL_REPLACE,
        None,
    );
    let c = (
        [GL_MODULATE, GL_MODULATE],
        [GL_PREVIOUS, GL_TEXTURE],
        [2.0, 1.0],
    );
    unit(
        gl,
        rng,
        GL_TEXTURE1,
        GL_LUMINANCE,
        16,
        GL_LINEAR,
        GL_COMBINE,
        Some(c),
    );
}

/// Cascades that the byte environment takes (`fragment::bytenv`: units before the last
/// selecting, the last computed in 8-bit integers, white or black primary colours) against the
/// general path's f32 environment, with blending and masks after them; and the same cascades
/// with random colours, whose blocks go back to the f32 route.
#[test]
fn byte_environment_matches_the_general_path() {
    let states: [Setup; 7] = [
        (
            "lightmap: RGB trilinear REPLACE, LUMINANCE COMBINE MODULATE x2",
            |gl, rng| {
                lightmap_units(gl, rng);
                multi_strip(gl, rng, Some([1.0; 4]));
            },
        ),
        ("lightmap with random colours (f32 route)", |gl, rng| {
            lightmap_units(gl, rng);
            multi_strip(gl, rng, None);
        }),
        ("RGBA REPLACE, INTENSITY ADD, alpha over", |gl, rng| {
            unit(
                gl,
                rng,
                GL_TEXTURE0,
                GL_RGBA,
                16,
                GL_NEAREST_MIPMAP_LINEAR,
                GL_REPLACE,
                None,
            );
            unit(
                gl,
                rng,
                GL_TEXTURE1,
                GL_INTENSITY,
                8,
                GL_LINEAR,
                GL_ADD,
                None,
            );
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            multi_strip(gl, rng, Some([1.0; 4]));
        }),
        (
            "LUMINANCE_ALPHA COMBINE SUBTRACT x4 / ADD_SIGNED x2, colour mask",
            |gl, rng| {
                let c = (
                    [GL_SUBTRACT, GL_ADD_SIGNED],
                    [GL_TEXTURE, GL_PRIMARY_COLOR],
                    [4.0, 2.0],
                );
                unit(
                    gl,
                    rng,
                    GL_TEXTURE0,
                    GL_LUMINANCE_ALPHA,
                    16,
                    GL_LINEAR,
                    GL_COMBINE,
                    Some(c),
                );
                gl.color_mask(1, 1, 0, 1);
                multi_strip(gl, rng, Some([0.0, 0.0, 0.0, 1.0]));
            },
        ),
        ("ALPHA REPLACE, RGBA MODULATE, ONE ONE", |gl, rng| {
            unit(
                gl,
                rng,
                GL_TEXTURE0,
                GL_ALPHA,
                16,
                GL_LINEAR_MIPMAP_NEAREST,
                GL_REPLACE,
                None,
            );
            unit(
                gl,
                rng,
                GL_TEXTURE1,
                GL_RGBA,
                16,
                GL_LINEAR,
                GL_MODULATE,
                None,
            );
            gl.enable(GL_BLEND);
            gl.blend_func(GL_ONE, GL_ONE);
            multi_strip(gl, rng, Some([1.0; 4]));
        }),
        (
            "three units: REPLACE, RGB DECAL, COMBINE ADD of the constant colour",
            |gl, rng| {
                unit(
                    gl,
                    rng,
                    GL_TEXTURE0,
                    GL_LUMINANCE,
                    16,
                    GL_LINEAR,
                    GL_REPLACE,
                    None,
                );
                unit(
                    gl,
                    rng,
                    GL_TEXTURE1,
                    GL_RGB,
                    16,
                    GL_LINEAR_MIPMAP_LINEAR,
                    GL_DECAL,
                    None,
                );
                let c = (
                    [GL_ADD, GL_MODULATE],
                    [GL_PREVIOUS, GL_CONSTANT],
                    [1.0, 4.0],
                );
                unit(
                    gl,
                    rng,
                    GL_TEXTURE2,
                    GL_RGBA,
                    8,
                    GL_LINEAR,
                    GL_COMBINE,
                    Some(c),
                );
                gl.active_texture(GL_TEXTURE2);
                gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.0, 1.0, 0.0, 1.0]);
                gl.active_texture(GL_TEXTURE0);
                multi_strip(gl, rng, Some([1.0; 4]));
            },
        ),
        (
            "COMBINE MODULATE of a non-byte constant colour (f32 draw)",
            |gl, rng| {
                unit(
                    gl,
                    rng,
                    GL_TEXTURE0,
                    GL_RGB,
                    16,
                    GL_LINEAR,
                    GL_REPLACE,
                    None,
                );
                let c = (
                    [GL_MODULATE, GL_MODULATE],
                    [GL_PREVIOUS, GL_CONSTANT],
                    [2.0, 1.0],
                );
                unit(
                    gl,
                    rng,
                    GL_TEXTURE1,
                    GL_LUMINANCE,
                    16,
                    GL_LINEAR,
                    GL_COMBINE,
                    Some(c),
                );
                gl.active_texture(GL_TEXTURE1);
                gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.3, 0.7, 0.9, 0.8]);
                gl.active_texture(GL_TEXTURE0);
                multi_strip(gl, rng, Some([1.0; 4]));
            },
        ),
    ];
    twins(&states);
}

/// Cascades of `MODULATE` units only on the sampled row pairs (`pair_sampled8`'s f32 route,
/// whose environment multiplies on registers without the compiled program): RGBA, LUMINANCE,
/// ALPHA, INTENSITY and LUMINANCE_ALPHA bases, random colours, with and without fog and
/// blending, against the general path's `texenv::apply`.
#[test]
fn modulate_units_match_the_general_path() {
    let states: [Setup; 4] = [
        ("RGBA trilinear x LUMINANCE, random colours", |gl, rng| {
            unit(
                gl,
                rng,
                GL_TEXTURE0,
                GL_RGBA,
                32,
                GL_LINEAR_MIPMAP_LINEAR,
                GL_MODULATE,
                None,
            );
            unit(
                gl,
                rng,
                GL_TEXTURE1,
                GL_LUMINANCE,
                16,
                GL_LINEAR,
                GL_MODULATE,
                None,
            );
            multi_strip(gl, rng, None);
        }),
        ("RGB x ALPHA, EXP2 fog", |gl, rng| {
            unit(
                gl,
                rng,
                GL_TEXTURE0,
                GL_RGB,
                16,
                GL_NEAREST_MIPMAP_LINEAR,
                GL_MODULATE,
                None,
            );
            unit(
                gl,
                rng,
                GL_TEXTURE1,
                GL_ALPHA,
                8,
                GL_LINEAR,
                GL_MODULATE,
                None,
            );
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_EXP2 as i32);
            gl.fogf(GL_FOG_DENSITY, 0.2);
            gl.fogfv(GL_FOG_COLOR, &[0.3, 0.6, 0.9, 0.5]);
            multi_strip(gl, rng, None);
        }),
        (
            "three units: INTENSITY, LUMINANCE_ALPHA, RGBA, alpha over",
            |gl, rng| {
                unit(
                    gl,
                    rng,
                    GL_TEXTURE0,
                    GL_INTENSITY,
                    16,
                    GL_LINEAR_MIPMAP_NEAREST,
                    GL_MODULATE,
                    None,
                );
                unit(
                    gl,
                    rng,
                    GL_TEXTURE1,
                    GL_LUMINANCE_ALPHA,
                    16,
                    GL_LINEAR,
                    GL_MODULATE,
                    None,
                );
                unit(
                    gl,
                    rng,
                    GL_TEXTURE2,
                    GL_RGBA,
                    8,
                    GL_NEAREST,
                    GL_MODULATE,
                    None,
                );
                gl.enable(GL_BLEND);
                gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                multi_strip(gl, rng, None);
            },
        ),
        ("RGBA x RGBA, one colour out of [0, 1]", |gl, rng| {
            unit(
                gl,
                rng,
                GL_TEXTURE0,
                GL_RGBA,
                16,
                GL_LINEAR_MIPMAP_LINEAR,
                GL_MODULATE,
                None,
            );
            unit(
                gl,
                rng,
                GL_TEXTURE1,
                GL_RGBA,
                16,
                GL_LINEAR,
                GL_MODULATE,
                None,
            );
            multi_strip(gl, rng, Some([1.5, -0.25, 0.6, 0.8]));
        }),
    ];
    twins(&states);
}

/// One unit through `GL_COMBINE` with RGB function `rgb`, alpha function `alpha`, the first
/// two sources and operands of each and the scales, a random `format` texture filtered by
/// `min`, and the constant colour (0.6, 0.5, 0.4, 0.3).
#[allow(clippy::too_many_arguments)]
fn combine_unit(
    gl: &mut Context,
    rng: &mut Rng,
    format: GLenum,
    min: GLenum,
    [rgb, alpha]: [GLenum; 2],
    sources: [GLenum; 2],
    operands: [GLenum; 2],
    scales: [f32; 2],
) {
    unit(
        gl,
        rng,
        GL_TEXTURE0,
        format,
        16,
        min,
        GL_COMBINE,
        Some(([rgb, alpha], sources, scales)),
    );
    gl.tex_envi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, operands[0] as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, operands[1] as i32);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.6, 0.5, 0.4, 0.3]);
}

/// One-unit draws on `pair_sampled8`'s fused blocks (the texels kept in registers): every
/// `GL_COMBINE` function through the one-unit straight-line form (`cascade::Single`), with
/// primary, constant, previous and crossbar sources (the unit itself, an absent unit), every
/// operand kind, scales and blending; a one-unit `DECAL`, `BLEND` and `ADD` (the compiled
/// cascade in registers) and `MODULATE` and `REPLACE` of textures without the fast layout
/// (the tail), each against the general path.
#[test]
fn one_unit_fused_blocks_match_the_general_path() {
    let states: [Setup; 12] = [
        ("COMBINE REPLACE of the texture", |gl, rng| {
            let f = [GL_REPLACE, GL_REPLACE];
            let (s, o) = ([GL_TEXTURE, GL_PRIMARY_COLOR], [GL_SRC_COLOR; 2]);
            combine_unit(
                gl,
                rng,
                GL_RGBA,
                GL_LINEAR_MIPMAP_LINEAR,
                f,
                s,
                o,
                [1.0, 1.0],
            );
            multi_strip(gl, rng, None);
        }),
        ("COMBINE MODULATE texture x primary, x2", |gl, rng| {
            let f = [GL_MODULATE, GL_MODULATE];
            let (s, o) = ([GL_TEXTURE, GL_PRIMARY_COLOR], [GL_SRC_COLOR; 2]);
            combine_unit(
                gl,
                rng,
                GL_RGB,
                GL_LINEAR_MIPMAP_LINEAR,
                f,
                s,
                o,
                [2.0, 1.0],
            );
            multi_strip(gl, rng, None);
        }),
        ("COMBINE ADD previous + constant, alpha over", |gl, rng| {
            let f = [GL_ADD, GL_ADD];
            let (s, o) = ([GL_PREVIOUS, GL_CONSTANT], [GL_SRC_COLOR, GL_SRC_ALPHA]);
            combine_unit(gl, rng, GL_RGBA, GL_LINEAR, f, s, o, [1.0, 1.0]);
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            multi_strip(gl, rng, None);
        }),
        (
            "COMBINE ADD_SIGNED of TEXTURE0 and 1 - primary",
            |gl, rng| {
                let f = [GL_ADD_SIGNED, GL_SUBTRACT];
                let (s, o) = (
                    [GL_TEXTURE0, GL_PRIMARY_COLOR],
                    [GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR],
                );
                combine_unit(
                    gl,
                    rng,
                    GL_LUMINANCE_ALPHA,
                    GL_NEAREST_MIPMAP_LINEAR,
                    f,
                    s,
                    o,
                    [2.0, 4.0],
                );
                multi_strip(gl, rng, None);
            },
        ),
        ("COMBINE INTERPOLATE by the constant alpha", |gl, rng| {
            let f = [GL_INTERPOLATE, GL_INTERPOLATE];
            let (s, o) = ([GL_TEXTURE, GL_PRIMARY_COLOR], [GL_SRC_COLOR; 2]);
            combine_unit(
                gl,
                rng,
                GL_RGB,
                GL_LINEAR_MIPMAP_LINEAR,
                f,
                s,
                o,
                [1.0, 1.0],
            );
            multi_strip(gl, rng, None);
        }),
        (
            "COMBINE SUBTRACT of an absent unit (previous), 1 - texture alpha",
            |gl, rng| {
                let f = [GL_SUBTRACT, GL_MODULATE];
                let (s, o) = (
                    [GL_TEXTURE3, GL_TEXTURE],
                    [GL_SRC_COLOR, GL_ONE_MINUS_SRC_ALPHA],
                );
                combine_unit(gl, rng, GL_RGBA, GL_LINEAR, f, s, o, [1.0, 2.0]);
                multi_strip(gl, rng, None);
            },
        ),
        ("COMBINE DOT3_RGB texture . primary", |gl, rng| {
            let f = [GL_DOT3_RGB, GL_ADD];
            let (s, o) = ([GL_TEXTURE, GL_PRIMARY_COLOR], [GL_SRC_COLOR; 2]);
            combine_unit(
                gl,
                rng,
                GL_RGB,
                GL_LINEAR_MIPMAP_NEAREST,
                f,
                s,
                o,
                [1.0, 1.0],
            );
            multi_strip(gl, rng, None);
        }),
        ("COMBINE DOT3_RGBA x4, colour mask", |gl, rng| {
            let f = [GL_DOT3_RGBA, GL_REPLACE];
            let (s, o) = (
                [GL_TEXTURE, GL_CONSTANT],
                [GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR],
            );
            combine_unit(gl, rng, GL_INTENSITY, GL_LINEAR, f, s, o, [4.0, 2.0]);
            gl.color_mask(1, 0, 1, 1);
            multi_strip(gl, rng, None);
        }),
        ("DECAL of RGBA (cascade in registers)", |gl, rng| {
            unit(
                gl,
                rng,
                GL_TEXTURE0,
                GL_RGBA,
                16,
                GL_LINEAR_MIPMAP_LINEAR,
                GL_DECAL,
                None,
            );
            multi_strip(gl, rng, None);
        }),
        (
            "BLEND of LUMINANCE_ALPHA (cascade in registers)",
            |gl, rng| {
                unit(
                    gl,
                    rng,
                    GL_TEXTURE0,
                    GL_LUMINANCE_ALPHA,
                    16,
                    GL_LINEAR,
                    GL_BLEND,
                    None,
                );
                gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.1, 0.9, 0.3, 0.6]);
                multi_strip(gl, rng, None);
            },
        ),
        ("MODULATE of LUMINANCE (the tail)", |gl, rng| {
            unit(
                gl,
                rng,
                GL_TEXTURE0,
                GL_LUMINANCE,
                16,
                GL_LINEAR_MIPMAP_LINEAR,
                GL_MODULATE,
                None,
            );
            multi_strip(gl, rng, None);
        }),
        ("REPLACE of ALPHA, ONE ONE (the tail)", |gl, rng| {
            unit(
                gl,
                rng,
                GL_TEXTURE0,
                GL_ALPHA,
                16,
                GL_NEAREST,
                GL_REPLACE,
                None,
            );
            gl.enable(GL_BLEND);
            gl.blend_func(GL_ONE, GL_ONE);
            multi_strip(gl, rng, None);
        }),
    ];
    twins(&states);
}

/// A strip of 120 random vertices with random colours and texture coordinates on units 0-3.
fn strip4(gl: &mut Context, rng: &mut Rng) {
    gl.begin(GL_TRIANGLE_STRIP);
    for _ in 0..120 {
        gl.color_4f(
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
        );
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

/// Unit `unit` (a random `format` texture of `size`, filtered by `min`) under `GL_COMBINE`
/// with RGB function `rgb` of sources and operands `args`, alpha function `alpha` of the
/// first two sources' alphas, the scales, and constant colour `constant`.
#[allow(clippy::too_many_arguments)]
fn chain_unit(
    gl: &mut Context,
    rng: &mut Rng,
    unit: GLenum,
    (format, size, min): (GLenum, i32, GLenum),
    [rgb, alpha]: [GLenum; 2],
    args: &[(GLenum, GLenum)],
    scales: [f32; 2],
    constant: [f32; 4],
) {
    gl.active_texture(unit);
    random_texture(gl, rng, format, size, size);
    if min != GL_LINEAR && min != GL_NEAREST {
        gl.generate_mipmap_ext(GL_TEXTURE_2D);
    }
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, rgb as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, alpha as i32);
    for (i, &(source, operand)) in args.iter().enumerate() {
        let i = i as GLenum;
        gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + i, source as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + i, operand as i32);
        if i < 2 {
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + i, source as i32);
        }
    }
    gl.tex_envf(GL_TEXTURE_ENV, GL_RGB_SCALE, scales[0]);
    gl.tex_envf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, scales[1]);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &constant);
    gl.active_texture(GL_TEXTURE0);
}

/// Cascades of two to four `GL_COMBINE` units on `pair_sampled8`'s chained blocks (every
/// unit's texels in registers, `cascade::Chain`): `combine4`'s cascade, the primary colour
/// read by later units, crossbar reads of an absent unit and of the unit itself, DOT3,
/// SUBTRACT, every operand kind, scales, blending and a colour mask; and a cascade reading
/// another present unit (no chain: the compiled cascade), each against the general path.
#[test]
fn combine_chains_match_the_general_path() {
    const SRC: GLenum = GL_SRC_COLOR;
    let states: [Setup; 5] = [
        ("combine4's cascade", |gl, rng| {
            let t = |f, s, m| (f, s, m);
            let c = [0.0, 0.0, 0.0, 0.8];
            let (m, a) = (
                [GL_MODULATE, GL_MODULATE],
                [(GL_TEXTURE, SRC), (GL_PRIMARY_COLOR, SRC)],
            );
            chain_unit(
                gl,
                rng,
                GL_TEXTURE0,
                t(GL_RGBA, 32, GL_LINEAR_MIPMAP_LINEAR),
                m,
                &a,
                [1.0, 1.0],
                c,
            );
            let a = [(GL_PREVIOUS, SRC), (GL_TEXTURE, SRC)];
            chain_unit(
                gl,
                rng,
                GL_TEXTURE1,
                t(GL_LUMINANCE, 16, GL_LINEAR),
                m,
                &a,
                [2.0, 1.0],
                c,
            );
            let f = [GL_ADD_SIGNED, GL_MODULATE];
            chain_unit(
                gl,
                rng,
                GL_TEXTURE2,
                t(GL_LUMINANCE, 16, GL_LINEAR_MIPMAP_LINEAR),
                f,
                &a,
                [1.0, 1.0],
                c,
            );
            let f = [GL_INTERPOLATE, GL_MODULATE];
            let a = [
                (GL_PREVIOUS, SRC),
                (GL_TEXTURE, SRC),
                (GL_CONSTANT, GL_SRC_ALPHA),
            ];
            chain_unit(
                gl,
                rng,
                GL_TEXTURE3,
                t(GL_RGB, 32, GL_LINEAR),
                f,
                &a,
                [1.0, 1.0],
                c,
            );
            strip4(gl, rng);
        }),
        (
            "two units: primary read by the second, alpha over",
            |gl, rng| {
                let c = [0.3, 0.6, 0.9, 0.25];
                let f = [GL_ADD, GL_SUBTRACT];
                let a = [(GL_TEXTURE, SRC), (GL_CONSTANT, GL_ONE_MINUS_SRC_COLOR)];
                chain_unit(
                    gl,
                    rng,
                    GL_TEXTURE0,
                    (GL_RGBA, 16, GL_NEAREST_MIPMAP_LINEAR),
                    f,
                    &a,
                    [1.0, 2.0],
                    c,
                );
                let f = [GL_INTERPOLATE, GL_INTERPOLATE];
                let a = [
                    (GL_PREVIOUS, SRC),
                    (GL_PRIMARY_COLOR, SRC),
                    (GL_TEXTURE, GL_ONE_MINUS_SRC_ALPHA),
                ];
                chain_unit(
                    gl,
                    rng,
                    GL_TEXTURE1,
                    (GL_LUMINANCE_ALPHA, 16, GL_LINEAR),
                    f,
                    &a,
                    [1.0, 1.0],
                    c,
                );
                gl.enable(GL_BLEND);
                gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                strip4(gl, rng);
            },
        ),
        (
            "three units: DOT3, an absent unit, the unit itself, colour mask",
            |gl, rng| {
                let c = [0.5, 0.25, 0.75, 1.0];
                let f = [GL_DOT3_RGB, GL_REPLACE];
                let a = [(GL_TEXTURE0, SRC), (GL_PRIMARY_COLOR, SRC)];
                chain_unit(
                    gl,
                    rng,
                    GL_TEXTURE0,
                    (GL_RGB, 16, GL_LINEAR_MIPMAP_NEAREST),
                    f,
                    &a,
                    [1.0, 1.0],
                    c,
                );
                let f = [GL_SUBTRACT, GL_ADD];
                let a = [(GL_TEXTURE5, SRC), (GL_TEXTURE, GL_SRC_ALPHA)];
                chain_unit(
                    gl,
                    rng,
                    GL_TEXTURE1,
                    (GL_ALPHA, 16, GL_LINEAR),
                    f,
                    &a,
                    [4.0, 1.0],
                    c,
                );
                let f = [GL_MODULATE, GL_ADD_SIGNED];
                let a = [(GL_PREVIOUS, GL_ONE_MINUS_SRC_COLOR), (GL_TEXTURE2, SRC)];
                chain_unit(
                    gl,
                    rng,
                    GL_TEXTURE2,
                    (GL_INTENSITY, 16, GL_LINEAR_MIPMAP_LINEAR),
                    f,
                    &a,
                    [2.0, 2.0],
                    c,
                );
                gl.color_mask(1, 1, 0, 1);
                strip4(gl, rng);
            },
        ),
        (
            "two units: DOT3_RGBA then REPLACE of previous, x4",
            |gl, rng| {
                let c = [0.1, 0.2, 0.3, 0.4];
                let f = [GL_DOT3_RGBA, GL_MODULATE];
                let a = [(GL_TEXTURE, SRC), (GL_PREVIOUS, SRC)];
                chain_unit(
                    gl,
                    rng,
                    GL_TEXTURE0,
                    (GL_RGBA, 32, GL_LINEAR),
                    f,
                    &a,
                    [1.0, 1.0],
                    c,
                );
                let f = [GL_REPLACE, GL_MODULATE];
                let a = [(GL_PREVIOUS, SRC), (GL_TEXTURE, GL_SRC_ALPHA)];
                chain_unit(
                    gl,
                    rng,
                    GL_TEXTURE1,
                    (GL_RGBA, 16, GL_NEAREST),
                    f,
                    &a,
                    [4.0, 1.0],
                    c,
                );
                strip4(gl, rng);
            },
        ),
        (
            "two units: the second reads the first's texel (no chain)",
            |gl, rng| {
                let c = [0.5, 0.5, 0.5, 0.5];
                let m = [GL_MODULATE, GL_MODULATE];
                let a = [(GL_TEXTURE, SRC), (GL_PRIMARY_COLOR, SRC)];
                chain_unit(
                    gl,
                    rng,
                    GL_TEXTURE0,
                    (GL_RGBA, 16, GL_LINEAR),
                    m,
                    &a,
                    [1.0, 1.0],
                    c,
                );
                let f = [GL_ADD, GL_MODULATE];
                let a = [(GL_PREVIOUS, SRC), (GL_TEXTURE0, GL_ONE_MINUS_SRC_COLOR)];
                chain_unit(
                    gl,
                    rng,
                    GL_TEXTURE1,
                    (GL_RGB, 16, GL_LINEAR),
                    f,
                    &a,
                    [1.0, 1.0],
                    c,
                );
                strip4(gl, rng);
            },
        ),
    ];
    twins(&states);
}

/// Cascades on the byte route's compiled form (`bytenv::Bytes`, white primary colours):
/// complemented operands of the texture and of the previous colour's alpha, a selecting
/// `GL_COMBINE` unit taking the texture's alpha as colour, constant colours of converted
/// bytes, scales; and the same cascades with random colours (the f32 route), each against
/// the general path.
#[test]
fn compiled_byte_cascades_match_the_general_path() {
    const SRC: GLenum = GL_SRC_COLOR;
    fn bytes(b: [u8; 4]) -> [f32; 4] {
        b.map(|v| v as f32 * (1.0 / 255.0))
    }
    fn subtract(gl: &mut Context, rng: &mut Rng) {
        unit(
            gl,
            rng,
            GL_TEXTURE0,
            GL_RGBA,
            16,
            GL_LINEAR_MIPMAP_LINEAR,
            GL_REPLACE,
            None,
        );
        let f = [GL_SUBTRACT, GL_SUBTRACT];
        let a = [(GL_CONSTANT, SRC), (GL_TEXTURE, GL_ONE_MINUS_SRC_COLOR)];
        let c = bytes([51, 153, 255, 102]);
        let l = (GL_LUMINANCE, 16, GL_LINEAR);
        chain_unit(gl, rng, GL_TEXTURE1, l, f, &a, [2.0, 1.0], c);
    }
    fn alpha_as_colour(gl: &mut Context, rng: &mut Rng) {
        let c = bytes([0, 128, 255, 64]);
        let f = [GL_REPLACE, GL_REPLACE];
        let la = (GL_LUMINANCE_ALPHA, 16, GL_LINEAR_MIPMAP_LINEAR);
        chain_unit(
            gl,
            rng,
            GL_TEXTURE0,
            la,
            f,
            &[(GL_TEXTURE, GL_SRC_ALPHA)],
            [1.0, 1.0],
            c,
        );
        let f = [GL_ADD, GL_MODULATE];
        let a = [
            (GL_PREVIOUS, GL_ONE_MINUS_SRC_ALPHA),
            (GL_PRIMARY_COLOR, SRC),
        ];
        chain_unit(
            gl,
            rng,
            GL_TEXTURE1,
            (GL_RGB, 16, GL_LINEAR),
            f,
            &a,
            [1.0, 2.0],
            c,
        );
    }
    let states: [Setup; 4] = [
        ("RGBA REPLACE, constant - (1 - texture) x2", |gl, rng| {
            subtract(gl, rng);
            multi_strip(gl, rng, Some([1.0; 4]));
        }),
        ("the same with random colours (f32 route)", |gl, rng| {
            subtract(gl, rng);
            multi_strip(gl, rng, None);
        }),
        (
            "texture alpha as colour, (1 - previous alpha) + primary",
            |gl, rng| {
                alpha_as_colour(gl, rng);
                multi_strip(gl, rng, Some([1.0; 4]));
            },
        ),
        ("the same with random colours (f32 route)", |gl, rng| {
            alpha_as_colour(gl, rng);
            multi_strip(gl, rng, None);
        }),
    ];
    twins(&states);
}

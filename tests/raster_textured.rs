//! Textured rasterization: the specialised span functions with one and two texture units
//! (every base format, filter and wrap mode, affine and perspective primitives, fog and
//! stencil) give the general path's pixels bit for bit.

mod common;

use common::{random_texture, read_rgba, window_ortho, Rng};
use tilegl::enums::*;
use tilegl::{Context, Gl};

/// `count` random triangles in one `GL_TRIANGLES` batch, centred in x, y in [-4, 4] and z in
/// `z`, each vertex within 3 (x, y) and 2 (z) of its centre; `per_vertex` issues each vertex's
/// other attributes first.
fn triangle_cloud(
    gl: &mut Context,
    rng: &mut Rng,
    count: usize,
    z: std::ops::Range<f32>,
    mut per_vertex: impl FnMut(&mut Context, &mut Rng),
) {
    gl.begin(GL_TRIANGLES);
    for _ in 0..count {
        let c = [
            rng.range(-4.0, 4.0),
            rng.range(-4.0, 4.0),
            rng.range(z.start, z.end),
        ];
        for _ in 0..3 {
            per_vertex(gl, rng);
            gl.vertex_3f(
                c[0] + rng.range(-3.0, 3.0),
                c[1] + rng.range(-3.0, 3.0),
                c[2] + rng.range(-2.0, 2.0),
            );
        }
    }
    gl.end();
}

/// One textured configuration of `textured_fast_paths_match_the_general_path`.
struct TexCase {
    size: (i32, i32),
    format: GLenum,
    min: GLenum,
    mag: GLenum,
    wrap: GLenum,
    env: GLenum,
    blend: Option<(GLenum, GLenum)>,
    alpha_test: bool,
    depth_mask: u8,
    color_mask: [u8; 4],
    lod_bias: f32,
    /// Fog of this mode (density 0.35, from 0.5 to 7 units, a colour the textures do not
    /// have), or none.
    fog: Option<GLenum>,
    /// The colour sum (`GL_COLOR_SUM`) with a random secondary colour per vertex.
    color_sum: bool,
}

/// Textured primitives of every kind the fast path must reproduce: window-aligned quads (1/w
/// constant), quads with a varying q, perspective triangles, coordinates far outside [0, 1]
/// and huge or infinite ones.
fn textured_scene(gl: &mut Context, c: &TexCase, seed: u64) {
    let mut rng = Rng(seed);
    let (w, h) = c.size;
    random_texture(gl, &mut rng, c.format, w, h);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, c.min as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, c.mag as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, c.wrap as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT as i32);
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, c.lod_bias);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, c.env as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_LESS);
    gl.clear_color(0.2, 0.3, 0.4, 0.5);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if let Some((src, dst)) = c.blend {
        gl.enable(GL_BLEND);
        gl.blend_func(src, dst);
    }
    if c.alpha_test {
        gl.enable(GL_ALPHA_TEST);
        gl.alpha_func(GL_GREATER, 0.3);
    }
    gl.depth_mask(c.depth_mask);
    let m = c.color_mask;
    gl.color_mask(m[0], m[1], m[2], m[3]);
    if let Some(mode) = c.fog {
        gl.enable(GL_FOG);
        gl.fogi(GL_FOG_MODE, mode as i32);
        gl.fogf(GL_FOG_DENSITY, 0.35);
        gl.fogf(GL_FOG_START, 0.5);
        gl.fogf(GL_FOG_END, 7.0);
        gl.fogfv(GL_FOG_COLOR, &[0.9, 0.35, 0.6, 1.0]);
    }
    if c.color_sum {
        gl.enable(GL_COLOR_SUM);
    }
    window_ortho(gl);
    let sum = c.color_sum;
    let color = |gl: &mut Context, rng: &mut Rng| {
        gl.color_4f(
            rng.range(0.0, 1.2),
            rng.range(0.0, 1.0),
            rng.range(-0.1, 1.0),
            rng.range(0.2, 1.0),
        );
        if sum {
            gl.secondary_color_3f(rng.range(0.0, 0.6), rng.range(0.0, 0.3), 0.25);
        }
    };
    // Window-aligned quads with random coordinate scales and offsets.
    gl.begin(GL_QUADS);
    for i in 0..150 {
        let (x, y) = (rng.range(-10.0, 100.0), rng.range(-10.0, 100.0));
        let half = rng.range(0.5, 30.0);
        let z = rng.range(-0.9, 0.9);
        let scale = rng.range(0.05, 6.0);
        let (s0, t0) = (rng.range(-3.0, 3.0), rng.range(-3.0, 3.0));
        let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
        for (k, (dx, dy)) in corners.into_iter().enumerate() {
            color(gl, &mut rng);
            let (s, t) = (s0 + scale * (dx + 1.0) / 2.0, t0 + scale * (dy + 1.0) / 2.0);
            match i % 10 {
                // q varies per vertex: 1/w is constant, q is not.
                7 => gl.tex_coord_4f(s, t, 0.0, 1.0 + k as f32 * 0.5),
                // Huge and non-finite coordinates.
                8 => gl.tex_coord_2f(s * 1e30, t),
                9 if k == 2 => gl.tex_coord_2f(f32::INFINITY, t),
                _ => gl.tex_coord_2f(s, t),
            }
            gl.vertex_3f(x + dx * half, y + dy * half, z);
        }
    }
    gl.end();
    // Perspective triangles.
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.begin(GL_TRIANGLES);
    for i in 0..60 {
        let (cx, cy, cz) = (
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-9.0, -1.5),
        );
        for k in 0..3 {
            color(gl, &mut rng);
            // Every tenth triangle has a coordinate beyond the eight-pixel filter's range
            // (those blocks are sampled one by one).
            let far = if i % 10 == 9 && k == 0 { 3e9 } else { 1.0 };
            gl.tex_coord_2f(far * rng.range(-2.0, 2.0), rng.range(-2.0, 2.0));
            gl.vertex_3f(
                cx + rng.range(-2.0, 2.0),
                cy + rng.range(-2.0, 2.0),
                cz + rng.range(-1.0, 1.0),
            );
        }
    }
    gl.end();
}

#[test]
fn textured_fast_paths_match_the_general_path() {
    let over = Some((GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA));
    let base = TexCase {
        size: (64, 64),
        format: GL_RGBA,
        min: GL_LINEAR_MIPMAP_LINEAR,
        mag: GL_LINEAR,
        wrap: GL_REPEAT,
        env: GL_MODULATE,
        blend: over,
        alpha_test: true,
        depth_mask: 0,
        color_mask: [1; 4],
        lod_bias: 0.0,
        fog: None,
        color_sum: false,
    };
    let cases = [
        TexCase { ..base },
        TexCase {
            depth_mask: 1,
            alpha_test: false,
            ..base
        },
        TexCase {
            env: GL_REPLACE,
            blend: Some((GL_ONE, GL_ONE)),
            ..base
        },
        TexCase {
            blend: None,
            color_mask: [1, 0, 1, 1],
            depth_mask: 1,
            ..base
        },
        TexCase {
            size: (32, 16),
            format: GL_RGB,
            min: GL_NEAREST_MIPMAP_NEAREST,
            mag: GL_NEAREST,
            wrap: GL_MIRRORED_REPEAT,
            ..base
        },
        TexCase {
            size: (48, 20),
            format: GL_RGB,
            min: GL_LINEAR_MIPMAP_NEAREST,
            wrap: GL_CLAMP_TO_EDGE,
            env: GL_REPLACE,
            color_mask: [0, 1, 1, 0],
            ..base
        },
        TexCase {
            size: (20, 48),
            min: GL_NEAREST_MIPMAP_LINEAR,
            lod_bias: 0.7,
            ..base
        },
        TexCase {
            size: (16, 64),
            min: GL_LINEAR,
            mag: GL_NEAREST,
            ..base
        },
        TexCase {
            min: GL_NEAREST,
            lod_bias: -1.5,
            blend: Some((GL_SRC_ALPHA, GL_ONE)),
            ..base
        },
        // RGB texels on the eight-pixel path: REPLACE keeps the primary alpha; additive
        // and "over" blending.
        TexCase {
            format: GL_RGB,
            env: GL_REPLACE,
            blend: Some((GL_ONE, GL_ONE)),
            ..base
        },
        TexCase {
            size: (32, 32),
            format: GL_RGB,
            wrap: GL_CLAMP_TO_EDGE,
            ..base
        },
        // Other factors through the eight-fragment path's general blend.
        TexCase {
            blend: Some((GL_DST_COLOR, GL_ONE_MINUS_SRC_COLOR)),
            ..base
        },
        TexCase {
            format: GL_RGB,
            blend: Some((GL_SRC_ALPHA_SATURATE, GL_ONE_MINUS_DST_ALPHA)),
            ..base
        },
        // Fog of each mode on the eight-lane paths (affine quads, perspective rows and 4x2
        // blocks): with "over" blending and the alpha test, without blending and with depth
        // writes, on RGB texels, REPLACE, and a general blend with a colour mask.
        TexCase {
            fog: Some(GL_LINEAR),
            ..base
        },
        TexCase {
            fog: Some(GL_EXP),
            blend: None,
            alpha_test: false,
            depth_mask: 1,
            ..base
        },
        TexCase {
            fog: Some(GL_EXP2),
            blend: None,
            alpha_test: false,
            depth_mask: 1,
            ..base
        },
        TexCase {
            fog: Some(GL_EXP2),
            format: GL_RGB,
            blend: None,
            depth_mask: 1,
            ..base
        },
        TexCase {
            fog: Some(GL_LINEAR),
            size: (32, 16),
            format: GL_RGB,
            env: GL_REPLACE,
            min: GL_NEAREST_MIPMAP_NEAREST,
            mag: GL_NEAREST,
            blend: None,
            depth_mask: 1,
            ..base
        },
        TexCase {
            fog: Some(GL_EXP),
            color_mask: [1, 0, 1, 1],
            blend: Some((GL_ONE_MINUS_DST_COLOR, GL_SRC_COLOR)),
            ..base
        },
        // The colour sum on the eight-lane paths, alone and before fog.
        TexCase {
            color_sum: true,
            ..base
        },
        TexCase {
            color_sum: true,
            format: GL_RGB,
            blend: None,
            alpha_test: false,
            depth_mask: 1,
            fog: Some(GL_EXP2),
            ..base
        },
        TexCase {
            color_sum: true,
            env: GL_REPLACE,
            fog: Some(GL_LINEAR),
            blend: Some((GL_ONE, GL_ONE_MINUS_SRC_COLOR)),
            ..base
        },
        // Not fast-path keys (a clamping wrap mode, DECAL): the general path either way.
        TexCase {
            wrap: GL_CLAMP,
            ..base
        },
        TexCase {
            env: GL_DECAL,
            ..base
        },
    ];
    for (i, c) in cases.iter().enumerate() {
        let render = |general| {
            let mut gl = Context::new(96, 96);
            gl.set_force_general_path(general);
            textured_scene(&mut gl, c, 0x7E57 + i as u64);
            assert_eq!(gl.get_error(), GL_NO_ERROR);
            read_rgba(&mut gl)
        };
        let (general, fast) = (render(true), render(false));
        let differ = general.iter().zip(&fast).filter(|(a, b)| a != b).count();
        assert_eq!(differ, 0, "case {i}: {differ} pixels differ");
        if c.fog.is_some() || c.color_sum {
            // The fog and the colour sum must show: the same scene without them differs.
            let mut gl = Context::new(96, 96);
            let plain = TexCase {
                fog: None,
                color_sum: false,
                ..*c
            };
            textured_scene(&mut gl, &plain, 0x7E57 + i as u64);
            let unfogged = read_rgba(&mut gl);
            let changed = general
                .iter()
                .zip(&unfogged)
                .filter(|(a, b)| a != b)
                .count();
            assert!(changed > 1000, "case {i}: fog changed {changed} pixels");
        }
    }
}

#[test]
fn sampled_units_match_the_general_path() {
    // (unit 0 format, filter, wrap; unit 1 format, filter, wrap; fog; stencil): two units
    // through GL_COMBINE, every one-byte base format, affine and perspective primitives; the
    // eight-pixel sampler must give the general path's pictures bit for bit.
    let cases = [
        (
            GL_RGBA,
            GL_LINEAR_MIPMAP_LINEAR,
            GL_REPEAT,
            GL_LUMINANCE,
            GL_LINEAR,
            GL_CLAMP_TO_EDGE,
            false,
            false,
        ),
        (
            GL_RGB,
            GL_NEAREST_MIPMAP_LINEAR,
            GL_CLAMP_TO_EDGE,
            GL_LUMINANCE_ALPHA,
            GL_LINEAR_MIPMAP_NEAREST,
            GL_REPEAT,
            true,
            false,
        ),
        (
            GL_RGBA,
            GL_LINEAR,
            GL_REPEAT,
            GL_INTENSITY,
            GL_NEAREST,
            GL_REPEAT,
            false,
            true,
        ),
        (
            GL_LUMINANCE,
            GL_LINEAR_MIPMAP_LINEAR,
            GL_REPEAT,
            GL_ALPHA,
            GL_LINEAR_MIPMAP_LINEAR,
            GL_CLAMP_TO_EDGE,
            true,
            true,
        ),
        // Not eligible (mirrored repeat on unit 1, NPOT repeat): one by one on both paths.
        (
            GL_RGBA,
            GL_LINEAR_MIPMAP_LINEAR,
            GL_REPEAT,
            GL_RGB,
            GL_LINEAR,
            GL_MIRRORED_REPEAT,
            false,
            false,
        ),
        // The eight-fragment tail (no fog, no stencil) with additive blending, with no
        // blending and the alpha test.
        (
            GL_RGB,
            GL_LINEAR_MIPMAP_NEAREST,
            GL_REPEAT,
            GL_LUMINANCE,
            GL_LINEAR,
            GL_CLAMP_TO_EDGE,
            false,
            false,
        ),
        (
            GL_LUMINANCE_ALPHA,
            GL_NEAREST,
            GL_CLAMP_TO_EDGE,
            GL_RGBA,
            GL_LINEAR_MIPMAP_LINEAR,
            GL_REPEAT,
            false,
            false,
        ),
        // The eight-fragment tail with the general blend.
        (
            GL_RGBA,
            GL_LINEAR_MIPMAP_LINEAR,
            GL_REPEAT,
            GL_INTENSITY,
            GL_LINEAR,
            GL_REPEAT,
            false,
            false,
        ),
    ];
    for (i, &(f0, min0, wrap0, f1, min1, wrap1, fog, stencil)) in cases.iter().enumerate() {
        let render = |general: bool| {
            let mut gl = Context::new(96, 96);
            gl.set_force_general_path(general);
            let mut rng = Rng(0x5A3D + i as u64);
            gl.active_texture(GL_TEXTURE0);
            random_texture(&mut gl, &mut rng, f0, 64, 32);
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min0 as i32);
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap0 as i32);
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap0 as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
            gl.active_texture(GL_TEXTURE1);
            let size = if i == 4 { 12 } else { 16 };
            random_texture(&mut gl, &mut rng, f1, size, 16);
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min1 as i32);
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap1 as i32);
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap1 as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_MODULATE as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_PREVIOUS as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_TEXTURE as i32);
            gl.tex_envf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0);
            let alpha_fn = if i >= 5 { GL_MODULATE } else { GL_ADD };
            gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, alpha_fn as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_PREVIOUS as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_TEXTURE as i32);
            if fog {
                gl.enable(GL_FOG);
                gl.fogi(GL_FOG_MODE, GL_EXP as i32);
                gl.fogf(GL_FOG_DENSITY, 0.2);
            }
            if stencil {
                gl.enable(GL_STENCIL_TEST);
                gl.stencil_func(GL_ALWAYS, 1, 0xFF);
                gl.stencil_op(GL_KEEP, GL_KEEP, GL_INCR);
            }
            // Blending "over", additive, none, or a general one (subtraction, the
            // constant colour, SRC_ALPHA_SATURATE, separate alpha factors); the alpha test on
            // every other case.
            match if i == 7 { 3 } else { i % 3 } {
                0 => {
                    gl.enable(GL_BLEND);
                    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                }
                1 => {
                    gl.enable(GL_BLEND);
                    gl.blend_func(GL_ONE, GL_ONE);
                }
                2 => {}
                _ => {
                    gl.enable(GL_BLEND);
                    gl.blend_equation(GL_FUNC_SUBTRACT);
                    gl.blend_color(0.2, 0.1, 0.3, 0.4);
                    gl.blend_func_separate(
                        GL_ONE_MINUS_DST_COLOR,
                        GL_CONSTANT_COLOR,
                        GL_SRC_ALPHA_SATURATE,
                        GL_ONE_MINUS_CONSTANT_ALPHA,
                    );
                }
            }
            if (i % 2 == 1 && i != 7) || i == 5 || i == 6 {
                gl.enable(GL_ALPHA_TEST);
                gl.alpha_func(GL_GEQUAL, 0.4);
            }
            gl.enable(GL_DEPTH_TEST);
            gl.clear_color(0.6, 0.7, 0.8, 0.9);
            gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
            gl.matrix_mode(GL_PROJECTION);
            gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 30.0);
            gl.matrix_mode(GL_MODELVIEW);
            triangle_cloud(&mut gl, &mut rng, 80, -25.0..-1.5, |gl, rng| {
                gl.color_4f(
                    rng.range(0.0, 1.0),
                    rng.range(0.0, 1.0),
                    1.0,
                    rng.range(0.3, 1.0),
                );
                let st = [rng.range(-3.0, 3.0), rng.range(-3.0, 3.0)];
                gl.multi_tex_coord_2f(GL_TEXTURE0, st[0], st[1]);
                gl.multi_tex_coord_4f(GL_TEXTURE1, st[1], st[0], 0.0, rng.range(0.5, 2.0));
            });
            // A huge coordinate takes the one-by-one fallback inside the sampled path.
            gl.begin(GL_TRIANGLES);
            gl.multi_tex_coord_2f(GL_TEXTURE0, 3e9, 0.0);
            gl.vertex_3f(-2.0, -2.0, -3.0);
            gl.multi_tex_coord_2f(GL_TEXTURE0, 0.0, 1.0);
            gl.vertex_3f(2.0, -2.0, -3.0);
            gl.vertex_3f(0.0, 2.0, -3.0);
            gl.end();
            assert_eq!(gl.get_error(), GL_NO_ERROR);
            read_rgba(&mut gl)
        };
        let (general, sampled) = (render(true), render(false));
        let differ = general.iter().zip(&sampled).filter(|(a, b)| a != b).count();
        assert_eq!(differ, 0, "case {i}: {differ} pixels differ");
        let distinct: std::collections::HashSet<_> = general.iter().collect();

        assert!(
            distinct.len() > 100,
            "case {i}: the scene draws too little ({} colours)",
            distinct.len()
        );
    }
}

/// One texture unit of every one-byte base format under REPLACE and MODULATE, with several
/// blends: the eight-fragment tail applies the environment itself (with the base format's
/// table of which components the texture has) and must match the general path bit for bit.
#[test]
fn single_unit_formats_match_the_general_path() {
    let formats = [
        GL_ALPHA,
        GL_LUMINANCE,
        GL_LUMINANCE_ALPHA,
        GL_INTENSITY,
        GL_RGB,
        GL_RGBA,
    ];
    for (i, &format) in formats.iter().enumerate() {
        for (k, env) in [GL_REPLACE, GL_MODULATE].into_iter().enumerate() {
            let render = |general: bool| {
                let mut gl = Context::new(64, 64);
                gl.set_force_general_path(general);
                let mut rng = Rng(0x51 + (i * 2 + k) as u64);
                random_texture(&mut gl, &mut rng, format, 32, 32);
                gl.tex_parameteri(
                    GL_TEXTURE_2D,
                    GL_TEXTURE_MIN_FILTER,
                    GL_LINEAR_MIPMAP_LINEAR as i32,
                );
                gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, env as i32);
                gl.enable(GL_BLEND);
                match (i + k) % 3 {
                    0 => gl.blend_func(GL_SRC_ALPHA, GL_ONE),
                    1 => gl.blend_func(GL_ONE_MINUS_DST_COLOR, GL_SRC_COLOR),
                    _ => gl.disable(GL_BLEND),
                }
                if k == 1 {
                    gl.enable(GL_ALPHA_TEST);
                    gl.alpha_func(GL_GREATER, 0.25);
                }
                gl.clear_color(0.5, 0.25, 0.75, 0.5);
                gl.clear(GL_COLOR_BUFFER_BIT);
                gl.matrix_mode(GL_PROJECTION);
                gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 30.0);
                gl.matrix_mode(GL_MODELVIEW);
                triangle_cloud(&mut gl, &mut rng, 40, -20.0..-2.0, |gl, rng| {
                    gl.color_4f(
                        rng.range(0.0, 1.2),
                        rng.range(0.0, 1.0),
                        0.8,
                        rng.range(0.0, 1.0),
                    );
                    gl.tex_coord_2f(rng.range(-2.0, 2.0), rng.range(-2.0, 2.0));
                });
                assert_eq!(gl.get_error(), GL_NO_ERROR);
                read_rgba(&mut gl)
            };
            let (general, fast) = (render(true), render(false));
            let differ = general.iter().zip(&fast).filter(|(a, b)| a != b).count();
            assert_eq!(
                differ, 0,
                "format {format:#x}, env {env:#x}: {differ} pixels differ"
            );
            let distinct: std::collections::HashSet<_> = general.iter().collect();
            assert!(
                distinct.len() > 50,
                "format {format:#x}: {} colours",
                distinct.len()
            );
        }
    }
}

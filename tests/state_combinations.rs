//! Random combinations of fixed-function state, each drawn twice: through the fragment
//! functions specialised on the state and through the general path (every decision read at
//! run time). The two pictures must be identical, no call may raise an error and nothing may
//! panic. Each feature is tested against the specification elsewhere; this test covers the
//! combinations, where a specialised path or the attribute layout could disagree with the
//! general path or index past what a draw carries (fog, the colour sum and no texture unit
//! once did).

mod common;

use common::{random_texture, read_rgba, Rng};
use tilegl::enums::*;
use tilegl::{Context, Gl};

const CONFIGURATIONS: u64 = 600;

/// A pick from `items` by `rng`.
fn pick<T: Copy>(rng: &mut Rng, items: &[T]) -> T {
    items[(rng.next_u64() % items.len() as u64) as usize]
}

fn chance(rng: &mut Rng, p: f32) -> bool {
    rng.range(0.0, 1.0) < p
}

/// A 16x16 texture of random bytes with mipmaps, in a random one-byte format, filter and
/// wrap mode, on the active unit.
fn random_filtered_texture(gl: &mut Context, rng: &mut Rng) {
    let format = pick(
        rng,
        &[GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA],
    );
    random_texture(gl, rng, format, 16, 16);
    let min = pick(
        rng,
        &[
            GL_NEAREST,
            GL_LINEAR,
            GL_LINEAR_MIPMAP_LINEAR,
            GL_NEAREST_MIPMAP_LINEAR,
            GL_LINEAR_MIPMAP_NEAREST,
        ],
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as i32);
    let mag = pick(rng, &[GL_NEAREST, GL_LINEAR]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag as i32);
    let wrap = pick(
        rng,
        &[GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP, GL_MIRRORED_REPEAT],
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap as i32);
    let mode = pick(
        rng,
        &[
            GL_MODULATE,
            GL_REPLACE,
            GL_DECAL,
            GL_BLEND,
            GL_ADD,
            GL_COMBINE,
        ],
    );
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, mode as i32);
    gl.tex_envfv(
        GL_TEXTURE_ENV,
        GL_TEXTURE_ENV_COLOR,
        &[rng.range(0.0, 1.0), 0.5, rng.range(0.0, 1.0), 0.7],
    );
    if mode == GL_COMBINE {
        let func = pick(
            rng,
            &[
                GL_REPLACE,
                GL_MODULATE,
                GL_ADD,
                GL_ADD_SIGNED,
                GL_INTERPOLATE,
                GL_SUBTRACT,
                GL_DOT3_RGB,
            ],
        );
        gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, func as i32);
        for (src, value) in [
            (GL_SOURCE0_RGB, GL_TEXTURE),
            (GL_SOURCE1_RGB, GL_PREVIOUS),
            (GL_SOURCE2_RGB, GL_CONSTANT),
        ] {
            gl.tex_envi(GL_TEXTURE_ENV, src, value as i32);
        }
        gl.tex_envf(GL_TEXTURE_ENV, GL_RGB_SCALE, pick(rng, &[1.0, 2.0, 4.0]));
    }
}

/// Sets a random state; the draw's vertices carry every attribute.
fn random_state(gl: &mut Context, rng: &mut Rng) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -0.8, 0.8, 1.0, 30.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.enable(GL_DEPTH_TEST);
    let depth = pick(
        rng,
        &[GL_LESS, GL_LEQUAL, GL_LESS, GL_GREATER, GL_ALWAYS, GL_EQUAL],
    );
    gl.depth_func(depth);
    // GREATER starts from the near plane so that fragments pass.
    gl.clear_depth(if depth == GL_GREATER { 0.0 } else { 1.0 });
    gl.clear_color(0.2, 0.3, 0.4, 0.5);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    if chance(rng, 0.5) {
        gl.enable(GL_LIGHTING);
        gl.enable(GL_LIGHT0);
        gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 0.5, 1.0, 0.0]);
        gl.lightfv(GL_LIGHT0, GL_SPECULAR, &[0.8, 0.8, 0.8, 1.0]);
        gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.6, 0.6, 0.6, 1.0]);
        gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0);
        if chance(rng, 0.5) {
            gl.light_modeli(
                GL_LIGHT_MODEL_COLOR_CONTROL,
                GL_SEPARATE_SPECULAR_COLOR as i32,
            );
        }
        if chance(rng, 0.3) {
            gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
        }
        if chance(rng, 0.3) {
            gl.enable(GL_COLOR_MATERIAL);
        }
    } else if chance(rng, 0.4) {
        gl.enable(GL_COLOR_SUM);
    }
    if chance(rng, 0.5) {
        gl.enable(GL_FOG);
        let mode = pick(rng, &[GL_LINEAR, GL_EXP, GL_EXP2]);
        gl.fogi(GL_FOG_MODE, mode as i32);
        gl.fogf(GL_FOG_DENSITY, 0.15);
        gl.fogf(GL_FOG_START, 2.0);
        gl.fogf(GL_FOG_END, 20.0);
        gl.fogfv(GL_FOG_COLOR, &[0.9, 0.1, 0.5, 1.0]);
        if chance(rng, 0.3) {
            gl.fogi(GL_FOG_COORD_SRC, GL_FOG_COORD as i32);
        }
    }
    if chance(rng, 0.3) {
        gl.shade_model(GL_FLAT);
    }
    let units = pick(rng, &[0, 1, 1, 2]);
    for unit in 0..units {
        gl.active_texture(GL_TEXTURE0 + unit);
        random_filtered_texture(gl, rng);
        if unit == 0 && chance(rng, 0.25) {
            let mode = pick(rng, &[GL_SPHERE_MAP, GL_OBJECT_LINEAR, GL_EYE_LINEAR]);
            gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, mode as i32);
            gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, mode as i32);
            gl.enable(GL_TEXTURE_GEN_S);
            gl.enable(GL_TEXTURE_GEN_T);
        }
    }
    gl.active_texture(GL_TEXTURE0);
    if chance(rng, 0.4) {
        gl.enable(GL_BLEND);
        let (src, dst) = pick(
            rng,
            &[
                (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA),
                (GL_ONE, GL_ONE),
                (GL_DST_COLOR, GL_ZERO),
                (GL_SRC_ALPHA_SATURATE, GL_ONE),
            ],
        );
        gl.blend_func(src, dst);
    }
    if chance(rng, 0.3) {
        gl.enable(GL_ALPHA_TEST);
        gl.alpha_func(pick(rng, &[GL_GREATER, GL_LEQUAL, GL_NOTEQUAL]), 0.4);
    }
    if chance(rng, 0.2) {
        gl.depth_mask(0);
    }
    if chance(rng, 0.15) {
        gl.color_mask(1, 0, 1, 1);
    }
    if chance(rng, 0.15) {
        gl.enable(GL_STENCIL_TEST);
        gl.stencil_func(GL_ALWAYS, 1, 0xFF);
        gl.stencil_op(GL_KEEP, GL_INCR, GL_INCR);
    }
    if chance(rng, 0.1) {
        gl.enable(GL_COLOR_LOGIC_OP);
        gl.logic_op(GL_XOR);
    }
    if chance(rng, 0.2) {
        gl.enable(GL_CULL_FACE);
        gl.cull_face(pick(rng, &[GL_BACK, GL_FRONT]));
    }
    if chance(rng, 0.1) {
        gl.polygon_mode(GL_FRONT_AND_BACK, pick(rng, &[GL_LINE, GL_POINT]));
    }
    if chance(rng, 0.1) {
        gl.enable(GL_POLYGON_STIPPLE);
        let pattern: Vec<u8> = (0..128)
            .map(|i| if i % 8 < 4 { 0xAA } else { 0x5F })
            .collect();
        gl.polygon_stipple(&pattern);
    }
    if chance(rng, 0.1) {
        gl.enable(GL_POLYGON_SMOOTH);
    }
}

/// Small and large random triangles in perspective, every attribute random per vertex.
fn random_triangles(gl: &mut Context, rng: &mut Rng) {
    gl.begin(GL_TRIANGLES);
    for i in 0..30 {
        let size = if i % 3 == 0 { 3.0 } else { 0.4 };
        let c = [
            rng.range(-4.0, 4.0),
            rng.range(-3.0, 3.0),
            rng.range(-20.0, -2.0),
        ];
        for _ in 0..3 {
            gl.color_4f(
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
            );
            gl.secondary_color_3f(rng.range(0.0, 0.5), rng.range(0.0, 0.5), 0.2);
            gl.normal_3f(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 1.0);
            gl.fog_coordf(rng.range(0.0, 25.0));
            for unit in 0..2 {
                gl.multi_tex_coord_4f(
                    GL_TEXTURE0 + unit,
                    rng.range(-2.0, 2.0),
                    rng.range(-2.0, 2.0),
                    rng.range(0.0, 1.0),
                    rng.range(0.5, 2.0),
                );
            }
            gl.vertex_3f(
                c[0] + rng.range(-size, size),
                c[1] + rng.range(-size, size),
                c[2] + rng.range(-1.0, 1.0),
            );
        }
    }
    gl.end();
}

/// Renders case `case` through the general path and the specialised paths and asserts the
/// pictures are identical; answers whether anything was drawn.
fn same_picture_both_ways(case: u64, render: impl Fn(bool) -> Vec<[u8; 4]>) -> bool {
    let (general, specialised) = (render(true), render(false));
    let differ = general
        .iter()
        .zip(&specialised)
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(differ, 0, "case {case}: {differ} pixels differ");
    general.iter().any(|p| *p != general[0])
}

#[test]
fn specialised_paths_equal_the_general_path_in_random_state_combinations() {
    let mut drawn_cases = 0;
    for case in 0..CONFIGURATIONS {
        let render = |general: bool| {
            // Two tiles wide and not a multiple of the tile size.
            let mut gl = Context::new(100, 70);
            gl.set_force_general_path(general);
            let mut rng = Rng(0x5EED_0000 + case);
            random_state(&mut gl, &mut rng);
            random_triangles(&mut gl, &mut rng);
            assert_eq!(gl.get_error(), GL_NO_ERROR, "case {case}");
            read_rgba(&mut gl)
        };
        if same_picture_both_ways(case, render) {
            drawn_cases += 1;
        }
    }
    // Some states draw nothing (GREATER or EQUAL against the cleared depth, say); most must
    // draw, or the comparisons say little.
    assert!(
        drawn_cases >= CONFIGURATIONS * 2 / 3,
        "only {drawn_cases} cases drew"
    );
}

/// A coordinate that is usually ordinary and sometimes extreme (huge, tiny, zero, NaN or
/// infinite).
fn wild(rng: &mut Rng, lo: f32, hi: f32) -> f32 {
    match rng.next_u64() % 24 {
        0 => f32::NAN,
        1 => f32::INFINITY,
        2 => -1e30,
        3 => 1e-30,
        4 => 0.0,
        _ => rng.range(lo, hi),
    }
}

#[test]
fn random_primitives_with_extreme_vertices_in_random_states() {
    let modes = [
        GL_POINTS,
        GL_LINES,
        GL_LINE_STRIP,
        GL_LINE_LOOP,
        GL_TRIANGLES,
        GL_TRIANGLE_STRIP,
        GL_TRIANGLE_FAN,
        GL_QUADS,
        GL_QUAD_STRIP,
        GL_POLYGON,
    ];
    let mut drawn_cases = 0;
    for case in 0..CONFIGURATIONS / 3 {
        let render = |general: bool| {
            let mut gl = Context::new(90, 70);
            gl.set_force_general_path(general);
            let mut rng = Rng(0xE7_0000 + case);
            random_state(&mut gl, &mut rng);
            gl.point_size(rng.range(1.0, 6.0));
            gl.line_width(rng.range(1.0, 4.0));
            if chance(&mut rng, 0.3) {
                gl.enable(GL_POINT_SMOOTH);
                gl.enable(GL_LINE_SMOOTH);
            }
            if chance(&mut rng, 0.2) {
                gl.enable(GL_LINE_STIPPLE);
                gl.line_stipple(2, 0xF0F3);
            }
            for _ in 0..4 {
                gl.begin(pick(&mut rng, &modes));
                for _ in 0..(rng.next_u64() % 9) {
                    gl.color_4f(rng.range(0.0, 1.0), 0.5, rng.range(0.0, 1.0), 0.8);
                    gl.tex_coord_4f(
                        wild(&mut rng, -2.0, 2.0),
                        rng.range(-2.0, 2.0),
                        0.0,
                        wild(&mut rng, 0.5, 2.0),
                    );
                    gl.fog_coordf(wild(&mut rng, 0.0, 25.0));
                    gl.normal_3f(wild(&mut rng, -1.0, 1.0), 0.3, 1.0);
                    gl.vertex_4f(
                        wild(&mut rng, -5.0, 5.0),
                        wild(&mut rng, -4.0, 4.0),
                        rng.range(-20.0, -1.0),
                        // w near 0 and negative now and then.
                        pick(&mut rng, &[1.0, 1.0, 1.0, 1e-7, -1.0, 0.5]),
                    );
                }
                gl.end();
            }
            assert_eq!(gl.get_error(), GL_NO_ERROR, "case {case}");
            read_rgba(&mut gl)
        };
        if same_picture_both_ways(case, render) {
            drawn_cases += 1;
        }
    }
    assert!(
        drawn_cases >= CONFIGURATIONS / 6,
        "only {drawn_cases} cases drew"
    );
}

//! Twin test of the fogged untextured eight-lane routes (`span_fogged8` for keys simple but
//! for fog, `span_untextured8` for the others, both with `simd::fog_factors8`): random fog
//! states (LINEAR, EXP, EXP2 with random density, start and end, start == end included; the
//! fog coordinate from the eye distance or from the vertices; random fog colours), random
//! depth, stencil, blending and colour-mask states over small and large smooth and flat triangles in perspective. Each
//! state is drawn on the general path (forced: `span_general`, one fragment at a time, the
//! fog factor by `FogDraw::factor`) and on the chosen path: colour, depth and stencil buffers
//! must be identical bit for bit, and each draw must change the picture (so that a state that
//! drew nothing cannot pass).

mod common;

use common::{read_buffers, Rng};
use tilegl::enums::*;
use tilegl::{Context, Gl};

const SIZE: i32 = 100;

/// One random fog state: mode, parameters, colour, coordinate source and hint.
fn fog_state(gl: &mut Context, rng: &mut Rng) -> bool {
    gl.enable(GL_FOG);
    let mode = [GL_LINEAR, GL_EXP, GL_EXP2][(rng.next_u64() % 3) as usize];
    gl.fogi(GL_FOG_MODE, mode as i32);
    gl.fogf(GL_FOG_DENSITY, rng.range(0.0, 0.8));
    let start = rng.range(-2.0, 6.0);
    let end = match rng.next_u64() % 4 {
        // start == end: the linear factor's scale of 1.
        0 => start,
        // End before start.
        1 => start - rng.range(0.5, 4.0),
        _ => start + rng.range(0.5, 12.0),
    };
    gl.fogf(GL_FOG_START, start);
    gl.fogf(GL_FOG_END, end);
    gl.fogfv(
        GL_FOG_COLOR,
        &[
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
            1.0,
        ],
    );
    let hint = [GL_DONT_CARE, GL_NICEST, GL_FASTEST][(rng.next_u64() % 3) as usize];
    gl.hint(GL_FOG_HINT, hint);
    let from_vertex = rng.next_u64().is_multiple_of(3);
    if from_vertex {
        gl.fogi(GL_FOG_COORD_SRC, GL_FOG_COORD as i32);
    }
    from_vertex
}

/// The per-fragment state around fog: half the time simple but for fog (`span_fogged8`),
/// else random depth function and writes, stencil, blending, alpha test (without stencil,
/// which the eight-lane tail does not take together) and colour mask; flat or smooth shading.
fn fragment_state(gl: &mut Context, rng: &mut Rng) {
    let r = rng.next_u64();
    if r.is_multiple_of(2) {
        // Simple but for fog (`span_fogged8`): LESS or LEQUAL with depth writes, or no
        // depth test (then with any colour mask).
        match (r >> 4) % 3 {
            0 => gl.disable(GL_DEPTH_TEST),
            1 => gl.depth_func(GL_LEQUAL),
            _ => gl.depth_func(GL_LESS),
        }
        if (r >> 8).is_multiple_of(3) {
            gl.color_mask(1, 0, 1, 1);
        }
    } else {
        match (r >> 4) % 6 {
            0 => gl.disable(GL_DEPTH_TEST),
            1 => gl.depth_func(GL_LEQUAL),
            2 => gl.depth_func(GL_GREATER),
            3 => gl.depth_func(GL_ALWAYS),
            _ => gl.depth_func(GL_LESS),
        }
        if (r >> 8).is_multiple_of(4) {
            gl.depth_mask(0);
        }
        let stencil = (r >> 12).is_multiple_of(5);
        if stencil {
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_NOTEQUAL, 0x11, 0xFF);
            gl.stencil_op(GL_KEEP, GL_DECR, GL_INCR);
        }
        match (r >> 16) % 6 {
            0 => {
                gl.enable(GL_BLEND);
                gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            }
            1 => {
                gl.enable(GL_BLEND);
                gl.blend_func(GL_ONE, GL_ONE);
            }
            2 if !stencil => {
                gl.enable(GL_ALPHA_TEST);
                gl.alpha_func(GL_GREATER, 0.5);
            }
            _ => {}
        }
        if (r >> 24).is_multiple_of(5) {
            gl.color_mask(1, 0, 1, 1);
        }
    }
    if (r >> 28).is_multiple_of(4) {
        gl.shade_model(GL_FLAT);
    }
}

/// A scene under the fog: a height field of small triangles (strips of 24 x 10 cells
/// receding into the view, as the `fog` bench workload) and 40 random triangles of every
/// size, random colours and alphas, and with `from_vertex` random fog coordinates per vertex.
fn fogged_geometry(gl: &mut Context, rng: &mut Rng, from_vertex: bool) {
    let vertex = |gl: &mut Context, rng: &mut Rng, p: [f32; 3]| {
        gl.color_4f(
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
        );
        if from_vertex {
            gl.fog_coordf(rng.range(-2.0, 14.0));
        }
        gl.vertex_3f(p[0], p[1], p[2]);
    };
    let (cells, rows) = (24, 10);
    for j in 0..rows {
        gl.begin(GL_TRIANGLE_STRIP);
        for i in 0..=cells {
            for jj in [j + 1, j] {
                let x = -4.0 + 8.0 * i as f32 / cells as f32;
                let z = -1.5 - 1.2 * jj as f32;
                let y = -1.2 + 0.3 * (x * 1.7).sin() * (z * 0.9).cos() + rng.range(0.0, 0.05);
                vertex(gl, rng, [x, y, z]);
            }
        }
        gl.end();
    }
    gl.begin(GL_TRIANGLES);
    for k in 0..40 {
        // Small, medium and large (long rows that the row function takes alone).
        let size = [0.05, 0.3, 2.5][k % 3];
        let c = [
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-11.0, -1.5),
        ];
        for _ in 0..3 {
            let p = [
                c[0] + rng.range(-size, size),
                c[1] + rng.range(-size, size),
                c[2] + rng.range(-size, size).min(0.9),
            ];
            vertex(gl, rng, p);
        }
    }
    gl.end();
}

/// A perspective view with a cleared depth buffer, a stencil buffer holding a few values
/// and an unfogged backdrop of depth-tested triangles.
fn backdrop(gl: &mut Context, rng: &mut Rng) {
    gl.enable(GL_DEPTH_TEST);
    gl.clear_color(0.3, 0.1, 0.2, 0.5);
    gl.clear_stencil(0x10);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 14.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_ALWAYS, 0x11, 0xFF);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
    gl.begin(GL_TRIANGLES);
    for _ in 0..30 {
        let c = [
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-12.0, -2.0),
        ];
        for _ in 0..3 {
            gl.color_3f(rng.range(0.0, 1.0), 0.5, rng.range(0.0, 1.0));
            gl.vertex_3f(
                c[0] + rng.range(-1.5, 1.5),
                c[1] + rng.range(-1.5, 1.5),
                c[2] + rng.range(-1.0, 1.0),
            );
        }
    }
    gl.end();
    gl.disable(GL_STENCIL_TEST);
}

/// Renders state `case` (seeded by it) on the general path or the chosen one; `draw`: the
/// fogged geometry drawn (else the backdrop alone).
fn render(case: u64, general: bool, draw: bool) -> (Vec<[u8; 4]>, Vec<u8>, Vec<u8>) {
    let mut gl = Context::new(SIZE, SIZE);
    gl.set_force_general_path(general);
    let mut rng = Rng(0xF06_5EED ^ case.wrapping_mul(0x9E37_79B9_7F4A_7C15));
    backdrop(&mut gl, &mut rng);
    if draw {
        let from_vertex = fog_state(&mut gl, &mut rng);
        fragment_state(&mut gl, &mut rng);
        fogged_geometry(&mut gl, &mut rng, from_vertex);
    }
    assert_eq!(gl.get_error(), GL_NO_ERROR, "case {case}");
    read_buffers(&mut gl)
}

#[test]
fn fogged_untextured_eight_lane_route_is_the_general_path() {
    for case in 0..160 {
        let general = render(case, true, true);
        let fast = render(case, false, true);
        let off = general
            .0
            .iter()
            .zip(&fast.0)
            .filter(|(a, b)| a != b)
            .count();
        assert_eq!(off, 0, "case {case}: {off} pixels differ");
        assert!(general.1 == fast.1, "case {case}: depth differs");
        assert!(general.2 == fast.2, "case {case}: stencil differs");
        let before = render(case, true, false);
        assert!(
            general.0 != before.0 || general.2 != before.2,
            "case {case}: the draw changed nothing"
        );
    }
}

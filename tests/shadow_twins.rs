//! Twin tests of the routes the `shadow` workload's passes take (issue 23): the untextured
//! depth-tested scene eight pixels at a time (`fragment/span/rows8.rs`), the depth-and-stencil
//! spans of colourless passes (`span_depth_stencil`), and stencilled untextured spans
//! (`span_untextured8`). Random stencil functions, actions (GL_INCR / GL_DECR saturating at
//! 0 and 255, the wrapping ones, INVERT, REPLACE, ZERO), value and write masks, references
//! and depth functions (section 4.1.5, 4.1.6): each case is drawn on the general path
//! (forced) and on the chosen route, and the colour, depth and stencil buffers must be the
//! same bytes; each case's draw must change a buffer, so a route that drew nothing fails.

mod common;

use common::{read_buffers, Rng};
use tilegl::enums::*;
use tilegl::{Context, Gl};

/// Not a multiple of the tile side or of eight (partial tiles and groups at the edges); a
/// multiple of four, so that the stencil rows read back need no padding.
const SIZE: i32 = 148;

/// The seeds of [`base`]'s batches of triangles (drawn again by the cases: equal depths).
const BASE_BATCH: u64 = 0xBA5E;

/// One of [`base`]'s batches again (the same triangles, so the same depths), with the
/// current state.
fn base_batch(gl: &mut Context, rng: &mut Rng, constant: bool) {
    let k = rng.next_u64() % 5;
    triangles(gl, &mut Rng(BASE_BATCH + k), 40, constant);
}

const FUNCS: [GLenum; 8] = [
    GL_NEVER,
    GL_LESS,
    GL_EQUAL,
    GL_LEQUAL,
    GL_GREATER,
    GL_NOTEQUAL,
    GL_GEQUAL,
    GL_ALWAYS,
];
const OPS: [GLenum; 8] = [
    GL_KEEP,
    GL_ZERO,
    GL_REPLACE,
    GL_INCR,
    GL_DECR,
    GL_INVERT,
    GL_INCR_WRAP,
    GL_DECR_WRAP,
];

fn pick<T: Copy>(rng: &mut Rng, from: &[T]) -> T {
    from[(rng.next_u64() % from.len() as u64) as usize]
}

/// A perspective view over random smooth-shaded triangles (depth-tested, written), leaving
/// stencil values that include 0, 255 and values in between (REPLACE with references 0, 255
/// and random ones, then INCR), so that saturating and wrapping actions meet their limits.
fn base(gl: &mut Context, rng: &mut Rng) {
    gl.enable(GL_DEPTH_TEST);
    gl.clear_color(0.2, 0.1, 0.0, 1.0);
    gl.clear_stencil(0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.enable(GL_STENCIL_TEST);
    for k in 0..4 {
        let reference = [0xFF, 0x01, (rng.next_u64() & 0xFF) as i32, 0x80][k];
        gl.stencil_func(GL_ALWAYS, reference, 0xFF);
        gl.stencil_op(GL_KEEP, GL_INCR, GL_REPLACE);
        let mut batch = Rng(BASE_BATCH + k as u64 + rng.next_u64() % 2);
        triangles(gl, &mut batch, 40, false);
    }
    gl.disable(GL_STENCIL_TEST);
}

/// `count` random triangles in the view volume, smooth colours (or one colour for all with
/// `constant`).
fn triangles(gl: &mut Context, rng: &mut Rng, count: usize, constant: bool) {
    gl.color_4f(0.8, 0.6, 0.3, 0.7);
    gl.begin(GL_TRIANGLES);
    for _ in 0..count {
        let c = [
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-9.0, -1.5),
        ];
        for _ in 0..3 {
            // (The colours are drawn from `rng` either way: the same seed gives the same
            // triangles.)
            let color = [
                rng.range(-0.2, 1.2),
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
            ];
            if !constant {
                gl.color_4f(color[0], color[1], color[2], color[3]);
            }
            gl.vertex_3f(
                c[0] + rng.range(-2.5, 2.5),
                c[1] + rng.range(-2.5, 2.5),
                c[2] + rng.range(-1.5, 1.5),
            );
        }
    }
    gl.end();
}

/// Random stencil state: test on, a random function, reference (sometimes past 255, which
/// is clamped), value mask, write mask and three actions.
fn random_stencil(gl: &mut Context, rng: &mut Rng) -> String {
    let func = pick(rng, &FUNCS);
    let r = rng.next_u64();
    let reference = pick(rng, &[0, 1, 0xFF, 0x80, 300, (r & 0xFF) as i32]);
    let value_mask = pick(rng, &[0xFF, 0x0F, 0xF0, (r >> 8 & 0xFF) as u32]);
    let write_mask = pick(rng, &[0xFF, 0xFF, 0x7F, (r >> 16 & 0xFF) as u32]);
    let ops = [pick(rng, &OPS), pick(rng, &OPS), pick(rng, &OPS)];
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(func, reference, value_mask);
    gl.stencil_mask(write_mask);
    gl.stencil_op(ops[0], ops[1], ops[2]);
    format!(
        "stencil {func:#x} ref {reference} mask {value_mask:#x} write {write_mask:#x} ops {ops:x?}"
    )
}

/// Draws case `case` over [`base`] on the general path and on the chosen route: the three
/// buffers must be the same bytes. Answers whether the draw changed a buffer (random states
/// such as NEVER with KEEP may not; the tests require most cases to).
fn twin(case: u64, draw: fn(&mut Context, &mut Rng) -> String) -> bool {
    let render = |general: bool, with_draw: bool| {
        let mut gl = Context::new(SIZE, SIZE);
        gl.set_force_general_path(general);
        let mut rng = Rng(0x5AD0_0000 + case);
        base(&mut gl, &mut rng);
        let name = if with_draw {
            draw(&mut gl, &mut rng)
        } else {
            String::new()
        };
        assert_eq!(gl.get_error(), GL_NO_ERROR, "case {case}: {name}");
        let buffers = read_buffers(&mut gl);
        assert_eq!(gl.get_error(), GL_NO_ERROR, "case {case}: read-back");
        (buffers, name)
    };
    let (general, name) = render(true, true);
    let (fast, _) = render(false, true);
    let differ = |a: &[u8], b: &[u8]| a.iter().zip(b).filter(|(x, y)| x != y).count();
    let off = general
        .0
        .iter()
        .zip(&fast.0)
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(off, 0, "case {case} ({name}): {off} pixels differ");
    assert_eq!(
        differ(&general.1, &fast.1),
        0,
        "case {case} ({name}): depth"
    );
    assert_eq!(
        differ(&general.2, &fast.2),
        0,
        "case {case} ({name}): stencil"
    );
    let (before, _) = render(true, false);
    general.0 != before.0 || general.1 != before.1 || general.2 != before.2
}

/// Runs `cases` cases of `draw`; at least three quarters must change a buffer.
fn twins(cases: u64, draw: fn(&mut Context, &mut Rng) -> String) {
    let moved = (0..cases).filter(|&case| twin(case, draw)).count() as u64;
    assert!(
        moved * 4 >= cases * 3,
        "only {moved} of {cases} cases drew anything"
    );
}

/// The lit scene's keys (`span_specialised`: the depth test and colour mask only) eight
/// pixels at a time: LESS and LEQUAL with depth writes, no depth test, random colour masks,
/// smooth and constant colours (some outside [0, 1]), perspective and orthographic views.
#[test]
fn untextured_depth_tested_rows_match_the_general_path() {
    twins(48, |gl, rng| {
        let depth = pick(rng, &[GL_LESS, GL_LEQUAL, GL_LESS, 0]);
        if depth == 0 {
            gl.disable(GL_DEPTH_TEST);
        } else {
            gl.depth_func(depth);
        }
        let mask = if rng.next_u64() % 3 == 0 {
            [0, 1, 2, 3].map(|_| (rng.next_u64() & 1) as u8)
        } else {
            [1; 4]
        };
        gl.color_mask(mask[0], mask[1], mask[2], mask[3]);
        let ortho = rng.next_u64() % 4 == 0;
        if ortho {
            gl.matrix_mode(GL_PROJECTION);
            gl.load_identity();
            gl.ortho(-3.0, 3.0, -3.0, 3.0, 1.0, 10.0);
            gl.matrix_mode(GL_MODELVIEW);
        }
        let constant = rng.next_u64() % 2 == 0;
        if constant {
            gl.color_4f(rng.range(-0.5, 1.5), rng.range(0.0, 1.0), 0.5, 1.0);
        }
        triangles(gl, rng, 30, constant);
        base_batch(gl, rng, constant);
        format!("depth {depth:#x} mask {mask:?} ortho {ortho} constant {constant}")
    });
}

/// Colourless passes (`span_depth_stencil`: shadow volumes, depth-only passes): random
/// stencil state, random depth functions with and without depth writes, culled front or
/// back faces.
#[test]
fn depth_and_stencil_passes_match_the_general_path() {
    twins(64, |gl, rng| {
        gl.color_mask(0, 0, 0, 0);
        let write = rng.next_u64() % 3 == 0;
        gl.depth_mask(u8::from(write));
        let depth = pick(
            rng,
            &[GL_LESS, GL_LEQUAL, GL_GREATER, GL_ALWAYS, GL_EQUAL, 0],
        );
        if depth == 0 {
            gl.disable(GL_DEPTH_TEST);
        } else {
            gl.depth_func(depth);
        }
        let mut stencil = random_stencil(gl, rng);
        if rng.next_u64() % 2 == 0 {
            // The z-pass volumes' form: ALWAYS, KEEP on both failures, every bit written
            // (counting meets the saturation limits on `base`'s 0 and 255 values).
            let op = pick(rng, &[GL_INCR, GL_DECR, GL_INCR_WRAP, GL_DECR_WRAP]);
            gl.stencil_func(GL_ALWAYS, 0, 0xFF);
            gl.stencil_mask(0xFF);
            gl.stencil_op(GL_KEEP, GL_KEEP, op);
            stencil = format!("z-pass {op:#x}");
        }
        gl.enable(GL_CULL_FACE);
        let face = pick(rng, &[GL_BACK, GL_FRONT]);
        gl.cull_face(face);
        base_batch(gl, rng, false);
        triangles(gl, rng, 30, false);
        // The shadow volumes' pair of passes: the other faces with another action.
        gl.cull_face(if face == GL_BACK { GL_FRONT } else { GL_BACK });
        gl.stencil_op(GL_KEEP, GL_KEEP, pick(rng, &OPS));
        triangles(gl, rng, 30, false);
        format!("{stencil} depth {depth:#x} write {write} face {face:#x}")
    });
}

/// Stencilled colour passes (`span_untextured8`: the darkening quad, a lit pass with the
/// stencil test): random stencil state, blending over, with and without the depth test,
/// window-covering rectangles and random triangles.
#[test]
fn stencilled_colour_passes_match_the_general_path() {
    twins(48, |gl, rng| {
        let stencil = random_stencil(gl, rng);
        let blend = rng.next_u64() % 3 != 0;
        if blend {
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        }
        let depth_test = rng.next_u64() % 2 == 0;
        if !depth_test {
            gl.disable(GL_DEPTH_TEST);
        }
        let quad = rng.next_u64() % 2 == 0;
        if quad {
            gl.matrix_mode(GL_PROJECTION);
            gl.load_identity();
            gl.matrix_mode(GL_MODELVIEW);
            gl.load_identity();
            gl.color_4f(0.0, 0.0, 0.05, rng.range(0.0, 1.0));
            gl.rectf(-1.0, -1.0, 1.0, 1.0);
        } else {
            let constant = rng.next_u64() % 2 == 0;
            triangles(gl, rng, 30, constant);
            base_batch(gl, rng, constant);
        }
        format!("{stencil} blend {blend} depth test {depth_test} quad {quad}")
    });
}

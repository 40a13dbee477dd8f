//! Long `glBegin`/`glEnd` batches of independent primitives are drawn in pieces while they
//! are recorded (`vertex/immediate.rs`, `BATCH_PIECE`). Invariant: the picture and depth are
//! exactly those of the same primitives drawn each in its own `glBegin`/`glEnd`, with
//! lighting, colour material, a `glMaterial` inside the batch, every independent mode, and a
//! batch far longer than one piece.

use tilegl::enums::*;
use tilegl::Gl;

mod common;
use common::{read_depth, read_rgba, threaded_context, Rng};

const PRIMITIVES: usize = 7001;

/// Draws `PRIMITIVES` primitives of `mode` (`per` vertices each), in one batch or each in its
/// own; returns colour and depth.
fn draw(mode: GLenum, per: usize, one_batch: bool) -> (Vec<[u8; 4]>, Vec<u8>) {
    let mut gl = threaded_context(96, 80, 2);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_COLOR_MATERIAL);
    gl.point_size(2.0);
    gl.matrix_mode(GL_PROJECTION);
    gl.ortho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    let mut rng = Rng(7);
    if one_batch {
        gl.begin(mode);
    }
    for i in 0..PRIMITIVES {
        if !one_batch {
            gl.begin(mode);
        }
        if i == PRIMITIVES / 2 {
            // Inside the batch: lights the vertices recorded before it with the old material.
            gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.9, 0.8, 0.2, 1.0]);
            gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0);
        }
        // Inside the view volume: a batch that needs clipping splits its quads along the other
        // diagonal, as Mesa does (state/draw.rs), so a clipped quad would differ between one
        // batch and separate primitives by design.
        let (cx, cy) = (rng.range(-0.9, 0.9), rng.range(-0.9, 0.9));
        for _ in 0..per {
            gl.color_3f(
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
            );
            gl.normal_3f(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 1.0);
            gl.vertex_3f(
                cx + rng.range(-0.08, 0.08),
                cy + rng.range(-0.08, 0.08),
                rng.range(-0.9, 0.9),
            );
        }
        if !one_batch {
            gl.end();
        }
    }
    if one_batch {
        gl.end();
    }
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.finish();
    (read_rgba(&mut gl), read_depth(&mut gl))
}

#[test]
fn long_batches_draw_what_separate_primitives_draw() {
    for (mode, per) in [
        (GL_POINTS, 1),
        (GL_LINES, 2),
        (GL_TRIANGLES, 3),
        (GL_QUADS, 4),
    ] {
        let whole = draw(mode, per, true);
        let separate = draw(mode, per, false);
        let drawn = whole.0.iter().filter(|p| p[..3] != [0, 0, 0]).count();
        assert!(drawn > 500, "mode 0x{mode:x}: only {drawn} pixels drawn");
        assert!(whole == separate, "mode 0x{mode:x}: pictures differ");
    }
}

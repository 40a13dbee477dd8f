//! Motion blur with the accumulation buffer.
//!
//! What it teaches (GL 1.5 section 4.2.4):
//! - The accumulation buffer holds signed, higher-precision colour per pixel (16 bits per
//!   channel here). `glAccum(GL_ACCUM, w)` adds w times the colour buffer to it,
//!   `glAccum(GL_RETURN, 1)` writes it back (clamped), `glClear(GL_ACCUM_BUFFER_BIT)` clears it to
//!   `glClearAccum`.
//! - Motion blur is a time average: draw the moving object at N instants, accumulating each
//!   frame with weight 1/N, and return the sum. The same loop over jittered projections gives
//!   anti-aliasing, over jittered eye positions depth of field.
//! - Each intermediate frame is an ordinary render (cleared colour, then the object); only the
//!   accumulation buffer sees all of them.
//!
//! Run: `cargo run --release -p tilegl-conformance --example motion_blur [OUT_DIR]`
//! (default `out/motion_blur/`). The scene `accum_motion_blur` (in
//! `conformance/src/scenes_raster.rs`; eight instants of a moving rectangle) is rendered on
//! tilegl and, where Mesa's OSMesa is installed, on Mesa, and the example prints the
//! difference and both run times. `tests/differential_raster.rs` checks the scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("motion_blur", &["accum_motion_blur"]);
}

//! Planar reflection with the stencil buffer.
//!
//! What it teaches (Kilgard, "Improving shadows and reflections via the stencil buffer";
//! McReynolds & Blythe):
//! - Pass 1 draws the mirror (the floor) into the stencil buffer only: `glStencilFunc(GL_ALWAYS,
//!   1, 0xff)`, `glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE)`, colour and depth writes off.
//! - Pass 2 draws the object mirrored in the floor plane (`glScalef(1, -1, 1)`) only where the
//!   stencil is 1 (`glStencilFunc(GL_EQUAL, 1, 0xff)`), so the reflection never leaks past the
//!   mirror's edge. The mirror flips the winding of every triangle, so with back-face culling on
//!   `glFrontFace(GL_CW)` is needed; the light position is re-specified under the mirrored
//!   modelview so the reflection is lit like a reflection.
//! - Pass 3 blends the floor over it (`glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)`, alpha
//!   0.7): a polished floor. Pass 4 draws the object itself.
//!
//! Stages: the stencil mask, the reflection, the floor blended over it.
//!
//! Run: `cargo run --release -p tilegl-conformance --example planar_reflection [OUT_DIR]`
//! (default `out/planar_reflection/`). The scene `ex_planar_reflection` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("planar_reflection", &["ex_planar_reflection"]);
}

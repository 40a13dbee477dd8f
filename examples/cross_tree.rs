//! Alpha-tested cut-outs: "cross trees" made of two textured quads.
//!
//! What it teaches (Haeberli & Segal 1993; Real-Time Rendering, "cutouts"/"billboards"):
//! - A tree is a texture with alpha 1 on the trunk and leaves and 0 elsewhere, mapped on two
//!   perpendicular quads so it looks solid from every horizontal direction.
//! - `glEnable(GL_ALPHA_TEST)`, `glAlphaFunc(GL_GREATER, 0.5)` discard the transparent fragments
//!   before the depth test (GL 1.5 section 4.1.4), so they neither colour nor occlude anything:
//!   the trees need no sorting, unlike blending.
//! - With `GL_LINEAR` filtering the alpha threshold cuts the interpolated alpha, which gives
//!   smoother cut-out edges than the texel grid.
//!
//! Stage: the tree texture.
//!
//! Run: `cargo run --release -p tilegl-conformance --example cross_tree [OUT_DIR]`
//! (default `out/cross_tree/`). The scene `ex_cross_tree` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("cross_tree", &["ex_cross_tree"]);
}

//! Contouring with texture coordinate generation: height lines on a terrain.
//!
//! What it teaches (Haeberli & Segal 1993, "contouring"):
//! - `glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR)` with the object plane (0, 5, 0, 0)
//!   sets s = 5y at every vertex: the texture coordinate measures the height.
//! - A 1D texture of 16 texels, white except one dark texel, with `GL_REPEAT`, draws a dark
//!   line wherever the height crosses a multiple of 1/5: the contour lines, which follow the
//!   terrain exactly because s is linear in object space (GL 1.5 section 2.11.4).
//! - `GL_MODULATE` multiplies the lines into the shaded terrain colours; `glEnable(GL_TEXTURE_1D)`.
//!
//! Run: `cargo run --release -p tilegl-conformance --example contour [OUT_DIR]`
//! (default `out/contour/`). The scene `ex_contour` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("contour", &["ex_contour"]);
}

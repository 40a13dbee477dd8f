//! DOT3 bump mapping: per-pixel N . L from a normal map and a light vector in the vertex colour.
//!
//! What it teaches (GL 1.3 `GL_DOT3_RGB`; Real-Time Rendering, "normal mapping"; Kilgard):
//! - A normal map stores a tangent-space normal per texel, packed into RGB as 0.5 + n/2 (built
//!   here from the derivatives of the same height field as `emboss_bump`).
//! - The light vector, transformed into tangent space per vertex on the CPU (tangent = +x,
//!   bitangent = -z, normal = +y for this floor), is packed the same way into `glColor3f`;
//!   Gouraud interpolation carries it across the triangles.
//! - Unit 0: `GL_COMBINE` with `GL_COMBINE_RGB = GL_DOT3_RGB`, sources `GL_TEXTURE` and
//!   `GL_PRIMARY_COLOR`: 4 x ((r0 - 1/2)(r1 - 1/2) + (g0 - 1/2)(g1 - 1/2) + (b0 - 1/2)(b1 - 1/2)),
//!   which is N . L, written to R, G and B (GL 1.5 table 3.20).
//! - Unit 1 modulates the base texture by it.
//!
//! Stages: the normal map and the DOT3 term alone (unit 1 disabled).
//!
//! Run: `cargo run --release -p tilegl-conformance --example dot3_bump [OUT_DIR]`
//! (default `out/dot3_bump/`). The scene `ex_dot3_bump` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("dot3_bump", &["ex_dot3_bump"]);
}

//! Fog over a terrain: linear, exponential and squared-exponential.
//!
//! What it teaches (GL 1.5 section 3.10):
//! - With `glEnable(GL_FOG)` each fragment's colour is blended towards `GL_FOG_COLOR` by a factor
//!   f of its eye distance z (here |z_eye|, the fragment depth): C = f C + (1 - f) C_fog.
//! - `GL_LINEAR`: f = (end - z) / (end - start) (start 1.5, end 9): a hard horizon.
//!   `GL_EXP`: f = e^(-density z) (density 0.3). `GL_EXP2`: f = e^(-(density z)^2) (density 0.22):
//!   clear near the viewer, thick far away. Left to right in the picture.
//! - The clear colour equals the fog colour, so the terrain fades into the sky.
//!
//! Stage: the same three panels without fog.
//!
//! Run: `cargo run --release -p tilegl-conformance --example fog [OUT_DIR]`
//! (default `out/fog/`). The scene `ex_fog_terrain` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("fog", &["ex_fog_terrain"]);
}

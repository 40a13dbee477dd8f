//! Sphere environment mapping: a mirror-like torus reflecting a sky, a sun and a checkered ground.
//!
//! What it teaches (Haeberli & Segal 1993; GL 1.5 section 2.11.4):
//! - A sphere map is the picture of a perfectly reflecting ball seen from far away: every
//!   direction of the environment appears once on the disc. The example builds it by computing,
//!   for each texel, the ball's normal and the reflected view direction.
//! - `glTexGeni(GL_S/GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP)` makes GL compute per vertex the
//!   eye-space reflection vector r = u - 2 n (n . u) and s = r_x / m + 1/2, t = r_y / m + 1/2 with
//!   m = 2 sqrt(r_x^2 + r_y^2 + (r_z + 1)^2), i.e. the texel of the ball that reflects the same
//!   direction.
//! - The map is view-dependent (it is only right for the view direction it was made for) and the
//!   texture coordinates are interpolated linearly between vertices, which is why the torus is
//!   finely tessellated. The red marker is on +x; the blue one is on -z, straight ahead of the
//!   viewer behind the ball, which the sphere map squeezes into its rim.
//!
//! Stage: the generated sphere map.
//!
//! Run: `cargo run --release -p tilegl-conformance --example sphere_map [OUT_DIR]`
//! (default `out/sphere_map/`). The scene `ex_sphere_map` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("sphere_map", &["ex_sphere_map"]);
}

//! Volume rendering with a 3D texture: blended slices, back to front.
//!
//! What it teaches (Cabral, Cam & Foran 1994; Real-Time Rendering, "volume rendering"; GL 1.2
//! 3D textures):
//! - The volume is a 32^3 RGBA texture (`glTexImage3D`): colour and opacity per voxel (a
//!   torus-shaped shell and a dense core).
//! - 48 quads parallel to the screen are drawn from back to front, each textured with
//!   `glTexCoord3f` so it cuts through the volume; `glBlendFunc(GL_SRC_ALPHA,
//!   GL_ONE_MINUS_SRC_ALPHA)` composites them with the "over" operator, which approximates the
//!   volume rendering integral.
//! - The texture matrix rotates the volume about its centre (translate, rotate, translate back):
//!   the slices stay view-aligned while the data turns. `GL_CLAMP_TO_BORDER` with a transparent
//!   border colour keeps the slice corners outside the volume empty.
//!
//! Stages: the volume's 32 slices side by side, and the picture after half the slices.
//!
//! Run: `cargo run --release -p tilegl-conformance --example volume_3d [OUT_DIR]`
//! (default `out/volume_3d/`). The scene `ex_volume_3d` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("volume_3d", &["ex_volume_3d"]);
}

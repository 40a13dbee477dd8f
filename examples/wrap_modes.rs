//! Texture wrap modes: what a texture coordinate outside [0, 1] samples.
//!
//! The same quad with coordinates -0.75..1.75 on a 4x4 texture (yellow edge texels, a red/blue
//! checker inside, `GL_TEXTURE_BORDER_COLOR` green, `GL_LINEAR` filtering), left to right:
//! - `GL_REPEAT`: the integer part is dropped, the texture tiles.
//! - `GL_CLAMP`: coordinates are clamped to [0, 1]; at the edge, the linear filter's 2x2
//!   footprint reaches half outside, into the border colour, so the edges fade to green.
//! - `GL_CLAMP_TO_EDGE` (GL 1.2): clamped to [1/2N, 1 - 1/2N], so the filter never leaves the
//!   texture: the edge texels are smeared outwards.
//! - `GL_CLAMP_TO_BORDER` (GL 1.3): clamped to [-1/2N, 1 + 1/2N]: outside is the border colour.
//! - `GL_MIRRORED_REPEAT` (GL 1.4): every other repetition is mirrored, so the pattern is
//!   continuous across tile edges.
//!
//! The modes are set per axis with `glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S/T, mode)`
//! (GL 1.5 section 3.8.7).
//!
//! Run: `cargo run --release -p tilegl-conformance --example wrap_modes [OUT_DIR]`
//! (default `out/wrap_modes/`). The scene `ex_wrap_modes` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("wrap_modes", &["ex_wrap_modes"]);
}

//! A decal with a clamped transparent border, on a second texture unit.
//!
//! What it teaches (Haeberli & Segal 1993, "decals"; GL 1.5 section 3.8.13):
//! - Unit 0 modulates a brick texture; unit 1 holds an RGBA target in `GL_DECAL` mode:
//!   C = Cprev x (1 - At) + Ct x At, so the decal's alpha blends it over the wall.
//! - The decal must appear once: `GL_CLAMP_TO_BORDER` with `GL_TEXTURE_BORDER_COLOR` (0, 0, 0, 0)
//!   makes every coordinate outside [0, 1] transparent, so the wall shows through there.
//! - Unit 1's texture matrix places the decal: translate, rotate, scale (it maps wall
//!   coordinates to decal coordinates, so scaling up shrinks the decal).
//!
//! Stage: the decal texture.
//!
//! Run: `cargo run --release -p tilegl-conformance --example decal [OUT_DIR]`
//! (default `out/decal/`). The scene `ex_decal` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("decal", &["ex_decal"]);
}

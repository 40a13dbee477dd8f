//! Anti-aliased text drawn as textured quads from an alpha font texture.
//!
//! What it teaches (Haeberli & Segal 1993, "antialiased text"):
//! - The font is a texture: each glyph's coverage is rasterised once (here procedurally, from
//!   stroke segments with 4x4 supersampling) into a `GL_ALPHA` texture of 32x32 cells.
//! - Each character is one quad with the texture coordinates of its cell. `GL_MODULATE` takes the
//!   colour from `glColor` and the alpha from the texture; `glBlendFunc(GL_SRC_ALPHA,
//!   GL_ONE_MINUS_SRC_ALPHA)` blends the soft edges over the background.
//! - Texture filtering resamples the coverage at any size, rotation and perspective;
//!   `GL_GENERATE_MIPMAP` and `GL_LINEAR_MIPMAP_LINEAR` keep small and receding text smooth
//!   instead of sparkling.
//!
//! Stage: the font texture.
//!
//! Run: `cargo run --release -p tilegl-conformance --example text [OUT_DIR]`
//! (default `out/text/`). The scene `ex_text` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("text", &["ex_text"]);
}

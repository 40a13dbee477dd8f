//! Emboss bump mapping in three passes: shifted texture coordinates and a subtractive blend.
//!
//! What it teaches (Real-Time Rendering, "emboss bump mapping"; McReynolds & Blythe):
//! - Diffuse lighting of a bumpy surface needs N . L, and for a height field h the change of
//!   N . L is about the slope of h along the light direction: h(p) - h(p + d L_t), where L_t is
//!   the light direction in the surface's tangent space and d a small step.
//! - Pass 1 draws 0.5 + h/2 (the height map through `GL_COMBINE` `GL_INTERPOLATE` between the
//!   texture and a white `GL_TEXTURE_ENV_COLOR`, weighted by the primary colour 0.5).
//! - Pass 2 draws h(p + shift)/2 with the texture matrix translating the coordinates two texels
//!   towards the light, and `glBlendEquation(GL_FUNC_REVERSE_SUBTRACT)` (dst - src): the
//!   framebuffer now holds 0.5 + (h(p) - h(p + shift))/2, an embossed grey picture.
//! - Pass 3 draws the base texture times the flat surface's diffuse factor and multiplies it in
//!   with `glBlendFunc(GL_DST_COLOR, GL_SRC_COLOR)`: 2 x src x dst = colour x (1 + slope).
//! - All passes use the same geometry with `glDepthFunc(GL_LEQUAL)`.
//!
//! Stages: the height map, pass 1, pass 2 (the emboss term).
//!
//! Run: `cargo run --release -p tilegl-conformance --example emboss_bump [OUT_DIR]`
//! (default `out/emboss_bump/`). The scene `ex_emboss_bump` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("emboss_bump", &["ex_emboss_bump"]);
}

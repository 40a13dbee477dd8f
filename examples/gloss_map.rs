//! Gloss map: a texture that says how shiny each part of a surface is.
//!
//! What it teaches (Real-Time Rendering, "gloss maps"; McReynolds & Blythe):
//! - Fixed-function lighting computes one specular term per vertex for the whole material, but
//!   a tiled floor of polished metal and rough stone should only show highlights on the metal.
//! - Pass 1 draws the diffuse (and ambient) lighting times the base texture, with the material's
//!   specular colour black.
//! - Pass 2 draws the same grid lit with *only* the specular term (material ambient and diffuse
//!   black, global ambient black, `GL_SHININESS` 30), multiplied by the gloss map (a luminance
//!   texture: 1 on metal, 0.08 on stone) with `GL_MODULATE`, and adds it:
//!   `glBlendFunc(GL_ONE, GL_ONE)`, `glDepthFunc(GL_LEQUAL)`.
//! - The light is positional and `GL_LIGHT_MODEL_LOCAL_VIEWER` is on, so the highlight moves
//!   across the tessellated plane (lighting is per vertex: the plane is a 24x24 grid).
//!
//! Stages: the gloss map and the diffuse pass.
//!
//! Run: `cargo run --release -p tilegl-conformance --example gloss_map [OUT_DIR]`
//! (default `out/gloss_map/`). The scene `ex_gloss_map` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("gloss_map", &["ex_gloss_map"]);
}

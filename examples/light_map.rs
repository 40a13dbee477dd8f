//! Light maps: precomputed lighting stored in a texture and multiplied into the surface colour.
//!
//! What it teaches (Quake's light maps; Real-Time Rendering, "light mapping"):
//! - The surface texture (bricks) repeats at high frequency; the lighting (three coloured pools
//!   of light) varies slowly and is stored once over the whole floor at low resolution. The
//!   final colour is `bricks x light`.
//! - With two texture units (`ex_lightmap_multitexture`): unit 0 the bricks, unit 1 the light map,
//!   each with `GL_MODULATE` (C = Cprev x Ct), and two sets of texture coordinates per vertex
//!   (`glMultiTexCoord2f(GL_TEXTURE0, ...)` repeating 4x, `GL_TEXTURE1` once).
//! - Without multitexture (`ex_lightmap_multipass`): draw the bricks, then draw the same geometry
//!   again with the light map and `glBlendFunc(GL_DST_COLOR, GL_ZERO)`, i.e.
//!   dst = src x dst. `glDepthFunc(GL_LEQUAL)` lets the second pass through: the same vertices
//!   give the same depths (GL's invariance rules, appendix A). Both pictures agree up to 8-bit
//!   rounding of the intermediate framebuffer value.
//!
//! Stages: the brick texture, the light map, and the first pass of the multipass version.
//!
//! Run: `cargo run --release -p tilegl-conformance --example light_map [OUT_DIR]`
//! (default `out/light_map/`). The scenes `ex_lightmap_multitexture`, `ex_lightmap_multipass` (in
//! `conformance/src/scenes_examples.rs`) are rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! each prefixed with the scene's name,
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scenes against Mesa.

fn main() {
    tilegl_conformance::example_support::run(
        "light_map",
        &["ex_lightmap_multitexture", "ex_lightmap_multipass"],
    );
}

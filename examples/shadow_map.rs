//! Shadow mapping with a depth texture: render depth from the light, compare from the camera.
//!
//! What it teaches (Williams 1978; Segal et al. 1992; GL 1.4 `ARB_depth_texture` and
//! `ARB_shadow`, GL 1.5 section 3.8.14):
//! - Pass 1 renders the scene from the light, depth only (`glColorMask` off), with
//!   `glPolygonOffset(2, 4)` pushing depths back so lit surfaces do not shadow themselves
//!   ("shadow acne"). `glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, ...)` copies the
//!   depth buffer into a depth texture: the shadow map.
//! - Pass 2 renders from the camera with eye-linear texgen and the light's bias x projection x
//!   view in the texture matrix (as in `projective_texture`), so r/q is the fragment's depth as
//!   the light sees it and (s/q, t/q) its place in the shadow map.
//! - `GL_TEXTURE_COMPARE_MODE = GL_COMPARE_R_TO_TEXTURE`, `GL_TEXTURE_COMPARE_FUNC = GL_LEQUAL`
//!   make the texture lookup return 1 where r <= the stored depth (lit) and 0 where something
//!   nearer to the light is in the way (shadow). `GL_NEAREST` filtering: one comparison per pixel.
//! - `ex_shadow_map`: `GL_DEPTH_TEXTURE_MODE = GL_LUMINANCE`, `GL_MODULATE`: shadowed pixels
//!   become black.
//! - `ex_shadow_map_alpha_test`: pass A draws the scene with ambient light only; pass B draws it
//!   fully lit with the comparison in alpha (`GL_DEPTH_TEXTURE_MODE = GL_ALPHA`) and
//!   `glAlphaFunc(GL_GREATER, 0.5)`, so only lit fragments replace the ambient picture.
//!
//! Stages: the depth buffer seen from the light, the shadow map read back with `glGetTexImage`
//! (depths stretched to black..white), and the ambient pass of the alpha-test variant.
//!
//! Run: `cargo run --release -p tilegl-conformance --example shadow_map [OUT_DIR]`
//! (default `out/shadow_map/`). The scenes `ex_shadow_map`, `ex_shadow_map_alpha_test` (in
//! `conformance/src/scenes_examples.rs`) are rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! each prefixed with the scene's name,
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scenes against Mesa.

fn main() {
    tilegl_conformance::example_support::run(
        "shadow_map",
        &["ex_shadow_map", "ex_shadow_map_alpha_test"],
    );
}

//! HSV colour interpolation through a 3D lookup texture.
//!
//! What it teaches (Haeberli & Segal 1993, "texture as a lookup table"; Foley et al., HSV;
//! GL 1.2 3D textures):
//! - Gouraud shading interpolates red, green and blue linearly: between red and blue it passes
//!   through a dark purple, between yellow and blue through grey. Interpolating hue, saturation
//!   and value instead keeps colours bright and walks around the colour wheel.
//! - The rasterizer interpolates any vertex attribute, so the vertices carry (hue, saturation,
//!   value) as 3D texture coordinates (`glTexCoord3f`) and a 24 x 8 x 8 RGB 3D texture, filled
//!   with HSV-to-RGB of each texel's centre, converts per fragment (`GL_REPLACE`).
//! - HSV to RGB is piecewise multilinear: linear in saturation and value, piecewise linear in
//!   hue with breakpoints every 1/6. Trilinear filtering (`GL_LINEAR`) is exact when the table's
//!   samples fall on those breakpoints, so a tiny table suffices; the texture matrix maps the
//!   value range onto texel centres (hue h -> h + 1/48, saturation and value
//!   x -> (7x + 1/2) / 8), since texel i of n covers [i/n, (i+1)/n] with its value at the centre.
//! - `GL_REPEAT` on the hue axis makes hue wrap: a bar from hue 1.08 to 0.8 goes the short way
//!   through red, and a hue of 1.0 is the same texel as 0.0.
//!
//! Stages: the lookup table's 8 slices (one per value) side by side, and the RGB-interpolated
//! bars and triangle before the HSV ones are drawn below them and to the right.
//!
//! Run: `cargo run --release -p tilegl-conformance --example hsv_lookup [OUT_DIR]`
//! (default `out/hsv_lookup/`). The scene `ex_hsv_lookup` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("hsv_lookup", &["ex_hsv_lookup"]);
}

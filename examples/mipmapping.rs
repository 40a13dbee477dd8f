//! Mipmapping: a receding textured plane under four minification filters, and the mipmap levels
//! made visible.
//!
//! What it teaches:
//! - A texture seen at a grazing angle is *minified*: many texels fall into one pixel. Sampling
//!   one texel (`GL_NEAREST`) or four (`GL_LINEAR`) per pixel then aliases: the far checkerboard
//!   turns into moiré and sparkle (top row of `ex_mipmap_filters`: NEAREST left, LINEAR right).
//! - A mipmap is the texture pre-filtered at half, quarter, ... resolution (Williams 1983).
//!   `glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE)` before `glTexImage2D` builds
//!   the levels (here by box filtering); a mipmapped `GL_TEXTURE_MIN_FILTER` picks the level whose
//!   texels are about pixel-sized. The spec (GL 1.5 section 3.8.8) computes the level of detail
//!   λ = log2 ρ from the derivatives of the texel coordinates u, v across the screen;
//!   `GL_NEAREST_MIPMAP_NEAREST` rounds λ to one level, `GL_LINEAR_MIPMAP_LINEAR` ("trilinear")
//!   blends two levels bilinearly sampled (bottom row).
//! - `ex_mipmap_levels` gives each level its own colour (uploaded with `glTexImage2D` per level),
//!   so the picture is a map of λ: the bands are where the level changes, and the smooth
//!   transitions are LINEAR_MIPMAP_LINEAR's blend between two levels.
//!
//! - Magnification (`ex_magnify_anisotropic`, top row): a texture smaller than its footprint on
//!   the screen is *magnified*; `GL_NEAREST` shows the texels as blocks, `GL_LINEAR` blends the
//!   four nearest texels into a smooth ramp. The magnification filter applies where λ <= 0.
//! - Anisotropic filtering (bottom row, EXT_texture_filter_anisotropic): at a grazing angle a
//!   pixel's footprint is long and thin, and trilinear filtering picks the level for the long
//!   side, so the far plane blurs (left). With `GL_TEXTURE_MAX_ANISOTROPY_EXT` 16 the level is
//!   chosen for the short side and up to 16 probes are averaged along the long one: the far
//!   checkerboard stays sharp (right). `tilegl`'s bench `--workload ladder` measures the error
//!   of each setting against a supersampled reference, and its time.
//!
//! Stages: the checkerboard's level 0 and level 2 as `glGetTexImage` returns them.
//!
//! Drivers may compute ρ differently (the spec allows an approximation): tilegl, llvmpipe and
//! softpipe all use finite differences over 2x2 pixel quads, one λ per quad; the remaining
//! differences are within the measured llvmpipe-vs-softpipe spread (`conformance/TOLERANCE.md`).
//!
//! Run: `cargo run --release -p tilegl-conformance --example mipmapping [OUT_DIR]`
//! (default `out/mipmapping/`). The scenes `ex_mipmap_filters`, `ex_mipmap_levels`,
//! `ex_magnify_anisotropic` (in
//! `conformance/src/scenes_examples.rs`) are rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! each prefixed with the scene's name,
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scenes against Mesa.

fn main() {
    tilegl_conformance::example_support::run(
        "mipmapping",
        &[
            "ex_mipmap_filters",
            "ex_mipmap_levels",
            "ex_magnify_anisotropic",
        ],
    );
}

//! Points and lines: sizes, widths, stipple and antialiasing.
//!
//! What it teaches (GL 1.5 sections 3.3, 3.4, 3.11):
//! - `glPointSize`: an aliased point is the square of side round(size) around the point; with
//!   `GL_POINT_SMOOTH` a disc whose edge pixels get the covered share of their area as alpha
//!   (blend with `GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA` to see it). GL 1.4's point parameters
//!   shrink points with distance: size * sqrt(1 / (a + b d + c d^2)).
//! - `glLineWidth`: an aliased wide line is its width-1 line (the diamond-exit rule) with each
//!   fragment replaced by a column (or row) of width fragments; with `GL_LINE_SMOOTH` a
//!   rectangle with coverage at its edges.
//! - `glLineStipple(factor, pattern)`: fragment number s along the line is drawn when bit
//!   (s / factor) mod 16 of the pattern is set; the count runs on along a strip and restarts
//!   for each independent segment.
//! - Mesa 22 draws smooth points as aliased discs (no coverage); the example's difference for
//!   that scene shows the edge pixels only.
//!
//! Run: `cargo run --release -p tilegl-conformance --example points_lines [OUT_DIR]`
//! (default `out/points_lines/`). The scenes (in `conformance/src/scenes_raster.rs`) are
//! rendered on tilegl and, where Mesa's OSMesa is installed, on Mesa; the example prints the
//! differences and both run times. `tests/differential_raster.rs` checks them against Mesa.

fn main() {
    tilegl_conformance::example_support::run(
        "points_lines",
        &[
            "wide_points",
            "smooth_points",
            "point_attenuation",
            "wide_lines",
            "smooth_lines",
            "line_stipple",
        ],
    );
}

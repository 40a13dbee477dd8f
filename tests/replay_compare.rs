//! Every shared capture (the repository's copy in `conformance/traces/shared`, described by
//! its MANIFEST.md) replayed and compared with Mesa's reference pictures (the pictures listed
//! in `NAME.frames/frames.tsv`), under the shared tolerance rule: at most 0.1 % of the
//! pixels off by more than 8 in some channel, or the llvmpipe-vs-softpipe spread of that
//! picture (`NAME.frames/softpipe/`).
//!
//! Captures that need features tilegl does not have yet are listed in `KNOWN_FAILURES.tsv` (in the captures' folder) with
//! the feature. Their test checks that they still fail, and fails when one passes, so that the
//! list stays true: remove the entry then.

use std::path::PathBuf;

mod common;

/// The repository's copy of the shared captures (the test fails when it is missing).
fn traces_dir() -> PathBuf {
    common::shared_traces()
}

fn check_capture(name: &str) {
    common::check_capture(&traces_dir(), name);
}

macro_rules! captures {
    ($($test:ident => $name:literal,)*) => {
        $(
            #[test]
            fn $test() {
                check_capture($name);
            }
        )*

        const ALL: &[&str] = &[$($name),*];
    };
}

captures! {
    glxgears => "glxgears",
    piglit_1_1_linear_texture => "piglit-1-1-linear-texture",
    piglit_arb_point_sprite_checkerboard => "piglit-arb_point_sprite-checkerboard",
    piglit_bgra_sec_color_pointer => "piglit-bgra-sec-color-pointer",
    piglit_blendminmax => "piglit-blendminmax",
    piglit_copyteximage_2d => "piglit-copyteximage-2D",
    piglit_cubemap => "piglit-cubemap",
    piglit_depthrange_clear => "piglit-depthrange-clear",
    piglit_fog_modes => "piglit-fog-modes",
    piglit_gl_1_0_rendermode_feedback => "piglit-gl-1.0-rendermode-feedback",
    piglit_gl_1_0_scissor_copypixels => "piglit-gl-1.0-scissor-copypixels",
    piglit_gl_1_0_spot_light => "piglit-gl-1.0-spot-light",
    piglit_gl_1_0_texgen => "piglit-gl-1.0-texgen",
    piglit_gl_1_2_texture_base_level => "piglit-gl-1.2-texture-base-level",
    piglit_gl_1_4_polygon_offset => "piglit-gl-1.4-polygon-offset",
    piglit_levelclamp => "piglit-levelclamp",
    piglit_line_aa_width => "piglit-line-aa-width",
    piglit_linestipple => "piglit-linestipple",
    piglit_lodclamp => "piglit-lodclamp",
    piglit_mipmap_setup => "piglit-mipmap-setup",
    piglit_nv_texture_env_combine4_combine => "piglit-nv_texture_env_combine4-combine",
    piglit_polygon_mode => "piglit-polygon-mode",
    piglit_s3tc_teximage => "piglit-s3tc-teximage",
    piglit_select => "piglit-select",
    piglit_tex_border_1 => "piglit-tex-border-1",
    piglit_texwrap_2d_gl_rgba8 => "piglit-texwrap-2D-GL_RGBA8",
    piglit_two_sided_lighting_separate_specular => "piglit-two-sided-lighting-separate-specular",
    xss_antinspect => "xss-antinspect",
    xss_atlantis => "xss-atlantis",
    xss_boing => "xss-boing",
    xss_cage => "xss-cage",
    xss_deepstars => "xss-deepstars",
    xss_endgame => "xss-endgame",
    xss_extrusion => "xss-extrusion",
    xss_flurry => "xss-flurry",
    xss_glblur => "xss-glblur",
    xss_maze3d => "xss-maze3d",
    xss_polyhedra => "xss-polyhedra",
    xss_quasicrystal => "xss-quasicrystal",
    xss_timetunnel => "xss-timetunnel",
    xss_unknownpleasures => "xss-unknownpleasures",
    xss_vigilance => "xss-vigilance",
}

#[test]
fn every_shared_capture_has_a_test_and_every_known_failure_a_capture() {
    common::assert_every_capture_listed(&traces_dir(), ALL);
}

//! The corpus of real captures recorded for tilegl (`conformance/traces/corpus/`, described in
//! its `MANIFEST.md`): xscreensaver hacks that use only fixed-function GL 1.x and piglit's
//! fixed-function tests, recorded with apitrace on Mesa llvmpipe, each with llvmpipe's and
//! softpipe's pictures. Every picture listed in `NAME.frames/frames.tsv` is compared under the
//! shared tolerance rule (0.1 % of the pixels off by more than 8, widened to the
//! llvmpipe-vs-softpipe spread of that picture, capped), exactly as `tests/replay_compare.rs`
//! does for the shared captures.
//!
//! Captures that do not match yet are listed in `KNOWN_FAILURES.tsv` (in the captures' folder) with their figures; their
//! test checks that they still fail, so the list stays true. A missing capture fails its test.

use std::path::PathBuf;

mod common;

/// The corpus folder (the test fails, naming it, when it is missing).
fn traces_dir() -> PathBuf {
    common::require(&common::traces_root().join("corpus"))
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
    piglit_arb_point_sprite_mipmap => "piglit-arb_point_sprite-mipmap",
    piglit_blendsquare => "piglit-blendsquare",
    piglit_clipflat => "piglit-clipflat",
    piglit_copyteximage_border => "piglit-copyteximage-border",
    piglit_copytexsubimage => "piglit-copytexsubimage",
    piglit_depthfunc => "piglit-depthfunc",
    piglit_dlist_clear => "piglit-dlist-clear",
    piglit_dlist_fdo3129_01 => "piglit-dlist-fdo3129-01",
    piglit_dlist_fdo3129_02 => "piglit-dlist-fdo3129-02",
    piglit_dlist_fdo31590 => "piglit-dlist-fdo31590",
    piglit_draw_arrays_colormaterial => "piglit-draw-arrays-colormaterial",
    piglit_ext_fog_coord_modes => "piglit-ext_fog_coord-modes",
    piglit_gl_1_0_blend_func => "piglit-gl-1.0-blend-func",
    piglit_gl_1_0_dlist_bitmap => "piglit-gl-1.0-dlist-bitmap",
    piglit_gl_1_0_dlist_materials => "piglit-gl-1.0-dlist-materials",
    piglit_gl_1_0_drawpixels_stencil_test => "piglit-gl-1.0-drawpixels-stencil-test",
    piglit_gl_1_0_logicop => "piglit-gl-1.0-logicop",
    piglit_gl_1_0_long_line_loop => "piglit-gl-1.0-long-line-loop",
    piglit_gl_1_0_ortho_pos => "piglit-gl-1.0-ortho-pos",
    piglit_gl_1_0_rastercolor => "piglit-gl-1.0-rastercolor",
    piglit_gl_1_0_scissor_bitmap => "piglit-gl-1.0-scissor-bitmap",
    piglit_gl_1_0_scissor_clear => "piglit-gl-1.0-scissor-clear",
    piglit_gl_1_0_scissor_depth_clear => "piglit-gl-1.0-scissor-depth-clear",
    piglit_gl_1_0_scissor_polygon => "piglit-gl-1.0-scissor-polygon",
    piglit_gl_1_0_scissor_stencil_clear => "piglit-gl-1.0-scissor-stencil-clear",
    piglit_gl_1_0_textured_triangle => "piglit-gl-1.0-textured-triangle",
    piglit_gl_1_0_user_clip_all_planes => "piglit-gl-1.0-user-clip-all-planes",
    piglit_gl_1_1_draw_arrays_start => "piglit-gl-1.1-draw-arrays-start",
    piglit_gl_1_1_xor_copypixels => "piglit-gl-1.1-xor-copypixels",
    piglit_gl_1_3_texture_env => "piglit-gl-1.3-texture-env",
    piglit_gl_1_4_tex1d_2dborder => "piglit-gl-1.4-tex1d-2dborder",
    piglit_gl_1_5_normal3b3s_invariance => "piglit-gl-1.5-normal3b3s-invariance",
    piglit_infinite_spot_light => "piglit-infinite-spot-light",
    piglit_line_flat_clip_color => "piglit-line-flat-clip-color",
    piglit_lineloop => "piglit-lineloop",
    // ARB_pixel_buffer_object: glTexImage2D from a pixel-unpack buffer filled through
    // glMapBuffer (the traced pointer is NULL: offset 0 into the buffer).
    piglit_pbo_teximage => "piglit-pbo-teximage",
    piglit_point_line_no_cull => "piglit-point-line-no-cull",
    piglit_polygon_mode_offset => "piglit-polygon-mode-offset",
    piglit_polygon_offset => "piglit-polygon-offset",
    piglit_provoking_vertex => "piglit-provoking-vertex",
    piglit_stencil_drawpixels => "piglit-stencil-drawpixels",
    piglit_stencil_wrap => "piglit-stencil-wrap",
    piglit_tex3d => "piglit-tex3d",
    piglit_texgen => "piglit-texgen",
    piglit_texredefine => "piglit-texredefine",
    piglit_texture_al => "piglit-texture-al",
    piglit_triangle_rasterization_overdraw => "piglit-triangle-rasterization-overdraw",
    piglit_user_clip => "piglit-user-clip",
    xss_antmaze => "xss-antmaze",
    xss_atunnel => "xss-atunnel",
    xss_beats => "xss-beats",
    xss_blinkbox => "xss-blinkbox",
    xss_blocktube => "xss-blocktube",
    xss_bouncingcow => "xss-bouncingcow",
    xss_boxed => "xss-boxed",
    xss_circuit => "xss-circuit",
    xss_cityflow => "xss-cityflow",
    xss_crackberg => "xss-crackberg",
    xss_cube21 => "xss-cube21",
    xss_cubenetic => "xss-cubenetic",
    xss_cubestack => "xss-cubestack",
    xss_cubestorm => "xss-cubestorm",
    xss_cubetwist => "xss-cubetwist",
    xss_cubicgrid => "xss-cubicgrid",
    xss_dangerball => "xss-dangerball",
    xss_engine => "xss-engine",
    xss_flipflop => "xss-flipflop",
    xss_gears => "xss-gears",
    xss_geodesic => "xss-geodesic",
    xss_geodesicgears => "xss-geodesicgears",
    xss_glhanoi => "xss-glhanoi",
    xss_glknots => "xss-glknots",
    xss_glschool => "xss-glschool",
    xss_glsnake => "xss-glsnake",
    xss_gravitywell => "xss-gravitywell",
    xss_handsy => "xss-handsy",
    xss_headroom => "xss-headroom",
    xss_hexstrut => "xss-hexstrut",
    xss_hextrail => "xss-hextrail",
    xss_hilbert => "xss-hilbert",
    xss_hypnowheel => "xss-hypnowheel",
    xss_juggler3d => "xss-juggler3d",
    xss_kaleidocycle => "xss-kaleidocycle",
    xss_lavalite => "xss-lavalite",
    xss_lockward => "xss-lockward",
    xss_menger => "xss-menger",
    xss_moebius => "xss-moebius",
    xss_moebiusgears => "xss-moebiusgears",
    xss_morph3d => "xss-morph3d",
    xss_nakagin => "xss-nakagin",
    xss_noof => "xss-noof",
    xss_pinion => "xss-pinion",
    xss_polytopes => "xss-polytopes",
    xss_providence => "xss-providence",
    xss_pulsar => "xss-pulsar",
    xss_raverhoop => "xss-raverhoop",
    xss_razzledazzle => "xss-razzledazzle",
    xss_rubik => "xss-rubik",
    xss_rubikblocks => "xss-rubikblocks",
    xss_sonar => "xss-sonar",
    xss_spheremonics => "xss-spheremonics",
    xss_sproingies => "xss-sproingies",
    xss_stairs => "xss-stairs",
    xss_starwars => "xss-starwars",
    xss_surfaces => "xss-surfaces",
    xss_tangram => "xss-tangram",
    xss_topblock => "xss-topblock",
    xss_tronbit => "xss-tronbit",
    xss_unicrud => "xss-unicrud",
    xss_voronoi => "xss-voronoi",
    xss_winduprobot => "xss-winduprobot",
}

#[test]
fn every_corpus_capture_has_a_test_and_every_known_failure_a_capture() {
    common::assert_every_capture_listed(&traces_dir(), ALL);
}

/// Each capture (trace and pictures) stays under 2 MB, and the corpus under 60 MB.
#[test]
fn corpus_stays_small() {
    let dir = traces_dir();
    let mut corpus = 0;
    for name in ALL {
        let mut total = std::fs::metadata(dir.join(format!("{name}.trace")))
            .unwrap()
            .len();
        for sub in ["", "softpipe"] {
            let d = dir.join(format!("{name}.frames")).join(sub);
            for e in std::fs::read_dir(&d).unwrap() {
                let m = e.unwrap().metadata().unwrap();
                if m.is_file() {
                    total += m.len();
                }
            }
        }
        assert!(total < 2_000_000, "{name}: {total} bytes");
        corpus += total;
    }
    assert!(corpus < 60_000_000, "corpus: {corpus} bytes");
}

/// Every capture has at least one picture and its softpipe twin, so no test passes vacuously.
#[test]
fn every_capture_has_pictures() {
    let dir = traces_dir();
    for name in ALL {
        let frames = dir.join(format!("{name}.frames"));
        let tsv = std::fs::read_to_string(frames.join("frames.tsv")).unwrap();
        let files: Vec<&str> = tsv
            .lines()
            .skip(1)
            .filter_map(|l| l.split('\t').next())
            .filter(|f| !f.is_empty())
            .collect();
        assert!(!files.is_empty(), "{name}: no pictures listed");
        for f in files {
            assert!(frames.join(f).is_file(), "{name}: {f} missing");
            assert!(
                frames.join("softpipe").join(f).is_file(),
                "{name}: softpipe/{f} missing"
            );
        }
    }
}

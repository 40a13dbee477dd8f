//! Every shared capture replayed and compared with Mesa's reference pictures (the pictures
//! listed in `NAME.frames/frames.tsv`), under the shared tolerance rule: at most 0.1 % of the
//! pixels off by more than 8 in some channel, or the llvmpipe-vs-softpipe spread of that
//! picture (`NAME.frames/softpipe/`).
//!
//! Captures that need features tilegl does not have yet are listed in [`KNOWN_FAILURES`] with
//! the feature. Their test checks that they still fail, and fails when one passes, so that the
//! list stays true: remove the entry then.

use std::path::{Path, PathBuf};

mod common;

/// Captures that do not match yet, and why (from the unknown calls and GL errors the replay
/// reports, and from looking at the pictures).
/// Empty: every shared capture matches.
const KNOWN_FAILURES: &[(&str, &str)] = &[];

fn traces_dir() -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/traces");
    if dir.is_dir() {
        Some(dir)
    } else {
        eprintln!("shared captures not found at {}; skipping", dir.display());
        None
    }
}

fn check_capture(name: &str) {
    let Some(dir) = traces_dir() else { return };
    common::check_capture(&dir, name, KNOWN_FAILURES);
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
    piglit_blendminmax => "piglit-blendminmax",
    piglit_copyteximage_2d => "piglit-copyteximage-2D",
    piglit_cubemap => "piglit-cubemap",
    piglit_fog_modes => "piglit-fog-modes",
    piglit_gl_1_0_spot_light => "piglit-gl-1.0-spot-light",
    piglit_gl_1_0_texgen => "piglit-gl-1.0-texgen",
    piglit_gl_1_2_texture_base_level => "piglit-gl-1.2-texture-base-level",
    piglit_gl_1_4_polygon_offset => "piglit-gl-1.4-polygon-offset",
    piglit_linestipple => "piglit-linestipple",
    piglit_lodclamp => "piglit-lodclamp",
    piglit_mipmap_setup => "piglit-mipmap-setup",
    piglit_nv_texture_env_combine4_combine => "piglit-nv_texture_env_combine4-combine",
    piglit_s3tc_teximage => "piglit-s3tc-teximage",
    piglit_tex_border_1 => "piglit-tex-border-1",
    piglit_texwrap_2d_gl_rgba8 => "piglit-texwrap-2D-GL_RGBA8",
    xss_atlantis => "xss-atlantis",
    xss_cage => "xss-cage",
    xss_endgame => "xss-endgame",
    xss_flurry => "xss-flurry",
    xss_glblur => "xss-glblur",
    xss_timetunnel => "xss-timetunnel",
}

#[test]
fn every_shared_capture_has_a_test_and_every_known_failure_a_capture() {
    let Some(dir) = traces_dir() else { return };
    let mut on_disk: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| {
            let p = e.unwrap().path();
            if p.extension()? != "trace" {
                return None;
            }
            Some(p.file_stem()?.to_string_lossy().into_owned())
        })
        .collect();
    on_disk.sort();
    let mut listed: Vec<String> = ALL.iter().map(|s| s.to_string()).collect();
    listed.sort();
    assert_eq!(
        on_disk, listed,
        "add a line to captures! for each new capture"
    );
    for (name, _) in KNOWN_FAILURES {
        assert!(ALL.contains(name), "known failure {name} is not a capture");
    }
}

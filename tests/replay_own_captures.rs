//! The project's own captures (`conformance/traces/`, described in its `MANIFEST.md`) replayed
//! and compared with Mesa's reference pictures, exactly like the shared captures in
//! `tests/replay_compare.rs`: every picture listed in `NAME.frames/frames.tsv` under the shared
//! tolerance rule (0.1 % of pixels off by more than 8, or the llvmpipe-vs-softpipe spread of
//! that picture from `NAME.frames/softpipe/`).
//!
//! Captures that need features tilegl does not have yet are listed in `KNOWN_FAILURES.tsv` (in the captures' folder) with
//! the feature; their test checks that they still fail, so the list stays true.

use std::path::PathBuf;

mod common;

fn traces_dir() -> PathBuf {
    common::own_traces()
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
    glxheads => "glxheads",
    piglit_dlist_color_material => "piglit-dlist-color-material",
    piglit_gl_1_0_edgeflag => "piglit-gl-1.0-edgeflag",
    piglit_gl_1_1_xor => "piglit-gl-1.1-xor",
    piglit_gl_1_2_rescale_normal => "piglit-gl-1.2-rescale-normal",
    piglit_polygon_mode => "piglit-polygon-mode",
    piglit_two_sided_lighting => "piglit-two-sided-lighting",
    xss_polyhedra => "xss-polyhedra",
    xss_sierpinski3d => "xss-sierpinski3d",
    xss_stonerview => "xss-stonerview",
    xss_superquadrics => "xss-superquadrics",
}

#[test]
fn every_own_capture_has_a_test_and_every_known_failure_a_capture() {
    common::assert_every_capture_listed(&traces_dir(), ALL);
}

#[test]
fn captures_stay_small() {
    for name in ALL {
        let dir = traces_dir();
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
        assert!(total < 1_000_000, "{name}: {total} bytes");
    }
}

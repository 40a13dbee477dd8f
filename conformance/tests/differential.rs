//! Differential tests: the same GL calls on tilegl and on Mesa (OSMesa, in-process driver),
//! pictures compared under `tolerance::DIFFERENTIAL` (see conformance/TOLERANCE.md), state
//! queries and error sequences compared value by value.
//!
//! Without Mesa the tests print "skipped: Mesa not found" and pass, except with `CI=true`, where
//! they fail. Cases failing because of a known tilegl bug are listed in
//! `tilegl_conformance::known_failures::KNOWN_FAILURES` (they print their figures and fail if
//! they start passing). Set `TILEGL_CONFORMANCE_DUMP=DIR` to get PPM pictures of every failing
//! case.

use tilegl::enums::*;
use tilegl::{Context, Gl};
use tilegl_conformance::compare::{self, diff};
use tilegl_conformance::mesa::{self};
use tilegl_conformance::scenes::{self, SCENES};
use tilegl_conformance::state_cases;
use tilegl_conformance::tolerance::DIFFERENTIAL;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn base_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("BASE_SCENES", scenes::BASE_SCENES);
}

/// The state and error cases of `state_cases::basic` against Mesa (`TILEGL_CASE` narrows them).
#[test]
fn basic_state_cases_agree_with_mesa() {
    state_cases::run_list("state_cases::basic", state_cases::basic::CASES);
}

/// Every case name is unique across the scene lists and the state cases, and every entry of
/// `KNOWN_FAILURES` names one of them.
#[test]
fn case_names_are_unique_and_known_failures_exist() {
    let mut names: Vec<&str> = SCENES.iter().map(|s| s.name).collect();
    names.extend(state_cases::all().map(|c| c.name));
    let n = names.len();
    names.sort_unstable();
    names.dedup();
    assert_eq!(names.len(), n, "a case name is used twice");
    for (name, _) in tilegl_conformance::known_failures::KNOWN_FAILURES {
        assert!(
            names.contains(name),
            "KNOWN_FAILURES lists unknown case {name}"
        );
    }
}

/// The other Gallium driver through a child process: softpipe must agree with the in-process
/// driver on a smooth-shaded scene within the same tolerance (this exercises the subprocess
/// helper and keeps the tolerance honest).
#[test]
fn other_driver_subprocess_agrees() {
    const NAME: &str = "other_driver_subprocess_agrees";
    if compare::serve_child_request(&SCENES) {
        return;
    }
    if !mesa::require_mesa(NAME) {
        return;
    }
    for name in ["triangle_fan", "cube_128"] {
        let scene = scenes::find(name).expect("scene");
        let (here, info) = compare::render_mesa(scene).expect("mesa");
        let other = if info.driver() == "softpipe" {
            "llvmpipe"
        } else {
            "softpipe"
        };
        let (img, renderer) =
            compare::render_scene_with_driver(other, scene, &[NAME, "--exact", "--nocapture"])
                .unwrap_or_else(|e| panic!("{e}"));
        assert!(
            renderer.starts_with(other),
            "child renderer {renderer:?}, expected {other}"
        );
        let d = diff(&here.image, &img, DIFFERENTIAL.channel);
        println!("{name}: {} vs {renderer}: {d}", info.renderer);
        assert!(DIFFERENTIAL.accepts(&d), "{name}: {d}");
    }
}

/// Section 6.1.2: an integer query of a floating-point value that is not a colour, normal or
/// depth value returns the nearest integer. Mesa 22 instead maps matrix elements to the full
/// integer range (1.0 -> 2^31 - 1), so this is checked against the spec, not the oracle.
#[test]
fn spec_integer_query_of_matrix_rounds() {
    let mut gl = Context::new(16, 16);
    gl.translatef(0.4, 0.6, -1.7);
    gl.scalef(2.7, 1.0, 1.0);
    let mut v = [0x5a5a_5a5a; 16];
    gl.get_integerv(GL_MODELVIEW_MATRIX, &mut v);
    assert_eq!(v, [3, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, -2, 1]);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

/// Two identical scenes on two tilegl contexts with different thread counts give the same
/// picture (the binned tiles replay in order, DESIGN.md "How a draw call flows" step 6).
#[test]
fn threads_do_not_change_pictures() {
    let scene = scenes::find("cube_128").expect("scene");
    let one = {
        let mut ctx = Context::with_config(tilegl::ContextConfig {
            width: scene.width,
            height: scene.height,
            threads: 1,
            ..Default::default()
        });
        compare::run_scene(&mut ctx, scene)
    };
    let two = {
        let mut ctx = Context::with_config(tilegl::ContextConfig {
            width: scene.width,
            height: scene.height,
            threads: 2,
            ..Default::default()
        });
        compare::run_scene(&mut ctx, scene)
    };
    assert_eq!(one.image, two.image);
}

/// A list test fails naming every failing case with its message, after running all of them.
#[test]
fn a_list_test_names_every_failing_case() {
    let cases = [
        ("first", true),
        ("second", false),
        ("third", true),
        ("fourth", false),
    ];
    let err = std::panic::catch_unwind(|| {
        tilegl_conformance::run_case_list(
            "planted",
            &cases,
            |c| c.0,
            |c| {
                if c.1 {
                    Ok("fine".into())
                } else {
                    Err(format!("{} is off", c.0))
                }
            },
        )
    })
    .expect_err("two cases fail");
    let text = err.downcast_ref::<String>().cloned().unwrap_or_default();
    assert!(text.contains("2 of 4 cases failed"), "{text}");
    assert!(text.contains("- second: second is off") && text.contains("- fourth: fourth is off"));
    assert!(!text.contains("first") && !text.contains("third"), "{text}");
}

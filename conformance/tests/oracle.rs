//! The oracle itself is checked: its Mesa version is printed once per test binary and must be
//! the major version the tolerances were measured on (in CI a different one fails every
//! differential case), and a scene on which Mesa draws nothing (its picture is all black or
//! all its clear colour) fails instead of passing against a tilegl that draws nothing too.

use tilegl::enums::*;
use tilegl::Gl;
use tilegl_conformance::compare::{self, mesa_drew_nothing, Scene};
use tilegl_conformance::mesa::{self, EXPECTED_MESA_MAJOR, MESA_MAJOR_ENV};
use tilegl_conformance::tolerance::DIFFERENTIAL;
use tilegl_conformance::Image;

/// Set in a child started by `an_unexpected_mesa_version_fails_in_ci`.
const PROBE_ENV: &str = "TILEGL_ORACLE_PROBE";

#[test]
fn the_oracle_is_the_expected_mesa() {
    if std::env::var_os(PROBE_ENV).is_some() || !mesa::require_mesa("oracle") {
        return;
    }
    let (info, check) = mesa::oracle_identity().as_ref().expect("oracle context");
    println!("{info}");
    assert!(info.version.contains("Mesa"), "{info}");
    if std::env::var_os(MESA_MAJOR_ENV).is_none() {
        assert_eq!(check.as_ref().ok(), Some(&EXPECTED_MESA_MAJOR), "{info}");
    }
}

/// The child's body: the check every differential case starts with.
#[test]
fn oracle_probe() {
    if std::env::var_os(PROBE_ENV).is_some() {
        mesa::require_mesa("oracle_probe");
    }
}

#[test]
fn an_unexpected_mesa_version_fails_in_ci() {
    if std::env::var_os(PROBE_ENV).is_some() || !mesa::require_mesa("oracle") {
        return;
    }
    let run = |major: u32, ci: &str| {
        std::process::Command::new(std::env::current_exe().unwrap())
            .args(["oracle_probe", "--exact", "--nocapture"])
            .env(PROBE_ENV, "1")
            .env(MESA_MAJOR_ENV, major.to_string())
            .env("CI", ci)
            .output()
            .unwrap()
    };
    let expected = run(EXPECTED_MESA_MAJOR, "true");
    let text = |o: &std::process::Output| {
        String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr)
    };
    assert!(expected.status.success(), "{}", text(&expected));
    assert!(text(&expected).contains("Mesa oracle: GL_VERSION"));
    let other = run(EXPECTED_MESA_MAJOR + 77, "true");
    assert!(!other.status.success(), "{}", text(&other));
    assert!(
        text(&other).contains("unexpected oracle in CI"),
        "{}",
        text(&other)
    );
    // Outside CI the mismatch is a warning.
    let local = run(EXPECTED_MESA_MAJOR + 77, "false");
    assert!(local.status.success(), "{}", text(&local));
    assert!(text(&local).contains("warning"), "{}", text(&local));
}

fn clear_only(gl: &mut dyn Gl) {
    gl.clear_color(0.2, 0.4, 0.6, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
}

fn masked_quad(gl: &mut dyn Gl) {
    gl.color_mask(0, 0, 0, 0);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.rectf(-0.5, -0.5, 0.5, 0.5);
}

fn full_window_quad(gl: &mut dyn Gl) {
    gl.color_3f(1.0, 0.0, 0.0);
    gl.rectf(-1.0, -1.0, 1.0, 1.0);
}

#[test]
fn a_scene_mesa_draws_nothing_for_fails() {
    if std::env::var_os(PROBE_ENV).is_some() || !mesa::require_mesa("oracle") {
        return;
    }
    let scene = |name, draw| Scene {
        name,
        width: 16,
        height: 16,
        draw,
        tolerance: DIFFERENTIAL,
    };
    // Only a clear, and a quad whose colour writes are masked: tilegl gives Mesa's picture
    // exactly, and the case fails all the same.
    for s in [
        scene("planted_clear_only", clear_only),
        scene("planted_masked_quad", masked_quad),
    ] {
        let c = compare::compare_scene(&s, s.tolerance).expect("oracle");
        assert_eq!(c.diff.bad_pixels, 0, "{}", c.summary());
        assert!(!c.passed(), "{}", c.summary());
        assert!(c.summary().contains("Mesa drew nothing"), "{}", c.summary());
    }
    // One colour that was drawn (over a black clear) is a picture: it passes.
    let s = scene("planted_full_window_quad", full_window_quad);
    let c = compare::compare_scene(&s, s.tolerance).expect("oracle");
    assert!(c.passed(), "{}", c.summary());
}

#[test]
fn empty_pictures_are_recognised_without_mesa() {
    let picture = |px: [u8; 4]| Image {
        width: 2,
        height: 2,
        pixels: px.repeat(4),
    };
    let clear = [51, 102, 153, 255];
    assert!(mesa_drew_nothing("s", &picture([0, 0, 0, 255]), clear).is_some());
    assert!(mesa_drew_nothing("s", &picture([0, 0, 0, 0]), clear).is_some());
    assert!(mesa_drew_nothing("s", &picture(clear), clear).is_some());
    assert!(mesa_drew_nothing("s", &picture([52, 101, 153, 255]), clear).is_some());
    assert!(mesa_drew_nothing("s", &picture([255, 0, 0, 255]), clear).is_none());
    let mut mixed = picture(clear);
    mixed.pixels[0] = 0;
    assert!(mesa_drew_nothing("s", &mixed, clear).is_none());
}

//! The benchmark workloads (`lightmap`, `spheremap`, the `lighting` sphere, the fog workloads
//! `tunnel` and `objects` with their unfogged twins, the state toggles) draw without GL errors
//! and cover the picture, at a small size.

use std::time::Duration;

use tilegl_conformance::bench::{
    open_tilegl, ratio_table, run_mesa, run_tilegl, toggle_within, work_data, BenchConfig,
    SummaryRow, WorkData, Workload, PICTURE_NEUTRAL_TOGGLES, TOGGLES,
};
use tilegl_conformance::compare::diff;

fn small(workload: Workload) -> BenchConfig {
    BenchConfig {
        workload,
        width: 96,
        height: 72,
        frames: 1,
        budget: Duration::from_millis(1),
        ..BenchConfig::default()
    }
}

/// Share of pixels more than 2 away from the clear colour `bg`.
fn covered(image: &tilegl_conformance::Image, bg: [u8; 3]) -> f64 {
    let mut n = 0;
    for y in 0..image.height {
        for x in 0..image.width {
            let p = image.pixel(x, y);
            if (0..3).any(|i| p[i].abs_diff(bg[i]) > 2) {
                n += 1;
            }
        }
    }
    n as f64 / (image.width * image.height) as f64
}

#[test]
fn lightmap_spheremap_and_lighting_workloads_draw() {
    const GREY: [u8; 3] = [26, 26, 31];
    for (w, bg, min_cover) in [
        (Workload::Lightmap, [0, 0, 0], 0.9),
        (Workload::Spheremap, GREY, 0.2),
        (Workload::Lighting, GREY, 0.05),
    ] {
        let cfg = small(w);
        let data = work_data(&cfg);
        let r = run_tilegl(&cfg, &data, 1);
        assert_eq!(r.error, 0, "{}", w.name());
        let c = covered(&r.image, bg);
        assert!(c >= min_cover, "{}: {c:.3} of the picture drawn", w.name());
    }
    // The unlit variant of the lighting measurement covers the same pixels.
    let cfg = small(Workload::Lighting);
    let lit = run_tilegl(&cfg, &WorkData::Sphere(8, 16, true), 1);
    let unlit = run_tilegl(&cfg, &WorkData::Sphere(8, 16, false), 1);
    let (a, b) = (covered(&lit.image, GREY), covered(&unlit.image, GREY));
    assert!(a > 0.05 && (a - b).abs() < 0.01, "lit {a:.3}, unlit {b:.3}");
    assert_eq!(Workload::parse("lightmap"), Some(Workload::Lightmap));
    assert_eq!(Workload::parse("spheremap"), Some(Workload::Spheremap));
}

/// The fog workloads (`tunnel`, `objects`) and their unfogged twins draw without GL errors and
/// cover the picture; fog changes it; tilegl's picture is Mesa's within the differential
/// scenes' bound (at most 1 % of pixels off by more than 8) for all four.
#[test]
fn fog_workloads_draw_and_match_mesa() {
    let mesa = tilegl_conformance::mesa::require_mesa("fog_workloads_draw_and_match_mesa");
    let mut images = Vec::new();
    for (w, bg) in [
        (Workload::Tunnel, [64, 56, 51]),
        (Workload::TunnelNoFog, [64, 56, 51]),
        (Workload::Objects, [128, 140, 153]),
        (Workload::ObjectsNoFog, [128, 140, 153]),
    ] {
        assert_eq!(Workload::parse(w.name()), Some(w));
        let cfg = small(w);
        let data = work_data(&cfg);
        let r = run_tilegl(&cfg, &data, 1);
        assert_eq!(r.error, 0, "{}", w.name());
        let c = covered(&r.image, bg);
        assert!(c >= 0.3, "{}: {c:.3} of the picture drawn", w.name());
        if mesa {
            let (m, _) = run_mesa(&cfg, &data).expect("mesa");
            let d = diff(&r.image, &m.image, 8);
            assert!(d.bad_share <= 0.01, "{}: {d}", w.name());
        }
        images.push(r.image);
    }
    for pair in images.chunks(2) {
        let d = diff(&pair[0], &pair[1], 8);
        assert!(d.bad_share > 0.1, "fog changed little: {d}");
    }
}

/// Every toggle of the state-toggle matrix draws without GL errors; every one but the base
/// changes the tunnel's picture, except those that write only stencil values (or compute the
/// base's own `MODULATE`), which leave it as it is.
#[test]
fn toggles_draw_and_change_the_picture() {
    let mut cfg = small(Workload::TunnelNoFog);
    let data = work_data(&cfg);
    let base = run_tilegl(&cfg, &data, 1);
    for (k, (name, _)) in TOGGLES.iter().enumerate().skip(1) {
        cfg.toggle = Some(k);
        let r = run_tilegl(&cfg, &data, 1);
        assert_eq!(r.error, 0, "{name}");
        let changed = diff(&r.image, &base.image, 2).bad_pixels;
        if PICTURE_NEUTRAL_TOGGLES.contains(name) {
            assert_eq!(changed, 0, "{name}: changed the picture");
        } else {
            assert!(changed > 0, "{name}: no change");
        }
    }
    for name in PICTURE_NEUTRAL_TOGGLES {
        assert!(
            TOGGLES.iter().any(|t| t.0 == name),
            "{name} is not a toggle"
        );
    }
}

/// The largest share of pixels off by more than 8 that each workload's tilegl picture may have
/// against llvmpipe's at 96x72 (the differential scenes' 1 %, and 3 % for the smooth lines,
/// whose coverage rules differ between implementations at every line end).
fn mesa_bound(w: Workload) -> f64 {
    match w {
        Workload::Lines => 0.03,
        _ => 0.01,
    }
}

/// Every workload of the ratio table, driven through tilegl's C exports as the benchmark drives
/// it, draws without GL errors the picture the Rust API draws (1 thread against the C route's
/// default threads), and that picture is llvmpipe's within the differential bound; at least
/// part of the picture is drawn.
#[test]
fn every_workload_draws_the_same_through_the_c_exports_and_matches_mesa() {
    let mesa = tilegl_conformance::mesa::require_mesa(
        "every_workload_draws_the_same_through_the_c_exports_and_matches_mesa",
    );
    for w in Workload::ALL {
        let cfg = small(w);
        let data = work_data(&cfg);
        let rust = run_tilegl(&cfg, &data, 1);
        let mut s = open_tilegl(&cfg, &data).expect("C ABI context");
        s.round(&data, 1, Duration::ZERO, Duration::from_secs(60));
        let c = s.finish(&cfg);
        assert_eq!((rust.error, c.error), (0, 0), "{}", w.name());
        let d = diff(&rust.image, &c.image, 0);
        assert_eq!(d.bad_pixels, 0, "{}: C route vs Rust route: {d}", w.name());
        let bg = rust.image.pixel(0, rust.image.height - 1);
        assert!(
            covered(&rust.image, [bg[0], bg[1], bg[2]]) > 0.0
                || covered(&rust.image, [0, 0, 0]) > 0.0,
            "{}: nothing drawn",
            w.name()
        );
        if mesa {
            let (m, _) = run_mesa(&cfg, &data).expect("mesa");
            let d = diff(&c.image, &m.image, 8);
            assert!(d.bad_share <= mesa_bound(w), "{}: {d}", w.name());
        }
    }
}

/// The 1.5x rule of the toggle matrix, and the ratio table's layout: one row per workload,
/// the speeds as Mesa's time over tilegl's, the errors beside the times.
#[test]
fn toggle_rule_and_ratio_table() {
    // 1.5x of Mesa's added cost, or 5 % of tilegl's base time as the noise floor.
    assert!(toggle_within(3.0, 2.0, 10.0));
    assert!(!toggle_within(3.1, 2.0, 10.0));
    assert!(toggle_within(0.5, -1.0, 10.0));
    assert!(!toggle_within(0.6, -1.0, 10.0));
    let d = tilegl::compare::diff_pixels(&[0, 0, 0, 0, 9, 0, 0, 0], &[0; 8], 4, 2, 8);
    let rows = [SummaryRow {
        workload: Workload::Tunnel,
        tilegl_name: "tilegl 2T".into(),
        tilegl_ms: 10.0,
        llvmpipe_ms: Some(15.0),
        softpipe_ms: None,
        vs_llvmpipe: Some(d),
        vs_softpipe: None,
        errors: vec![],
    }];
    let t = ratio_table(&rows);
    let lines: Vec<&str> = t.lines().collect();
    assert_eq!(lines.len(), 3, "{t}");
    assert!(lines[0].contains("tilegl 2T ms"), "{t}");
    assert_eq!(
        lines[2],
        "| `tunnel` | 10.0 | 15.0 | - | 1.50x | - | 50.000 % / 1.125 | - |"
    );
}

//! The benchmark workloads (`lightmap`, `spheremap`, the `lighting` sphere, the fog workloads
//! `tunnel` and `objects` with their unfogged twins, the state toggles) draw without GL errors
//! and cover the picture, at a small size.

use std::time::Duration;

use tilegl_conformance::bench::{
    run_mesa, run_tilegl, work_data, BenchConfig, WorkData, Workload, TOGGLES,
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

/// Every toggle of the state-toggle matrix draws without GL errors, and every one but the base
/// changes the tunnel's picture.
#[test]
fn toggles_draw_and_change_the_picture() {
    let mut cfg = small(Workload::TunnelNoFog);
    let data = work_data(&cfg);
    let base = run_tilegl(&cfg, &data, 1);
    for (k, (name, _)) in TOGGLES.iter().enumerate().skip(1) {
        cfg.toggle = Some(k);
        let r = run_tilegl(&cfg, &data, 1);
        assert_eq!(r.error, 0, "{name}");
        assert!(
            diff(&r.image, &base.image, 2).bad_pixels > 0,
            "{name}: no change"
        );
    }
}

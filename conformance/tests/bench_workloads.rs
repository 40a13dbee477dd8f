//! The texture-cascade benchmark workloads (`lightmap`, `spheremap`, the `lighting` sphere)
//! draw without GL errors and cover the picture, at a small size.

use std::time::Duration;

use tilegl_conformance::bench::{run_tilegl, work_data, BenchConfig, WorkData, Workload};

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

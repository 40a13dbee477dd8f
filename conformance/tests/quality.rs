//! The quality-knob measurements and charts: the error of each setting against the
//! supersampled reference moves the way the knob says (more accumulation passes, larger
//! textures: closer), Mesa's points are measured beside tilegl's, and the chart is a real
//! labelled PNG.

use std::path::Path;
use std::time::Duration;

use tilegl_conformance::quality::{self, knobs};

fn knob(id: &str) -> quality::Knob {
    knobs().into_iter().find(|k| k.id == id).expect("knob")
}

#[test]
fn more_passes_and_larger_textures_come_closer_to_the_reference() {
    let mesa = tilegl_conformance::mesa::require_mesa("quality");
    for id in ["accum_aa", "texture_size"] {
        let r = quality::measure(&knob(id), Duration::ZERO, mesa);
        let (first, last) = (&r.tilegl[0], r.tilegl.last().unwrap());
        assert!(
            last.mean_error < first.mean_error,
            "{id}: {} error {} not below {} error {}",
            last.setting,
            last.mean_error,
            first.setting,
            first.mean_error
        );
        if mesa {
            assert_eq!(r.llvmpipe.len(), r.tilegl.len(), "{id}: Mesa measured too");
            let (f, l) = (&r.llvmpipe[0], r.llvmpipe.last().unwrap());
            assert!(l.mean_error < f.mean_error, "{id} on Mesa: {l:?} vs {f:?}");
        }
        assert!(r.tilegl.iter().all(|p| p.ms > 0.0 && p.ms.is_finite()));
    }
}

#[test]
fn charts_and_page_are_written() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("quality");
    let _ = std::fs::remove_dir_all(&dir);
    let mesa = tilegl_conformance::mesa::require_mesa("quality");
    if !Path::new(quality::FONT).is_file() {
        assert!(
            std::env::var("CI").map_or(true, |v| v != "true"),
            "CI=true and the chart font {} is missing (fonts-dejavu-core)",
            quality::FONT
        );
        eprintln!("SKIPPED: no chart font {}", quality::FONT);
        return;
    }
    let (page, results) =
        quality::write_quality(&dir, &["fog_hint", "point_smooth"], Duration::ZERO, mesa)
            .expect("quality page");
    assert_eq!(results.len(), 2);
    let html = std::fs::read_to_string(page).unwrap();
    for r in &results {
        let png = dir.join(format!("quality-{}.png", r.id));
        let img = image::open(&png).expect("chart decodes").to_rgb8();
        assert_eq!(img.dimensions(), (900, 560));
        // Axes, labels and two coloured series: more than a handful of colours.
        let colours: std::collections::HashSet<[u8; 3]> = img.pixels().map(|p| p.0).collect();
        assert!(colours.len() > 20, "{}: {} colours", r.id, colours.len());
        assert!(html.contains(&format!("quality-{}.png", r.id)));
        for p in &r.tilegl {
            assert!(html.contains(&format!("<td>{}</td>", p.setting)));
        }
    }
}

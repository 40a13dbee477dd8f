//! The teaching gallery: its entries (every teaching scene, each with a text) and a small
//! gallery written and read back (one section per scene, every picture present and decodable,
//! Mesa's pictures and the difference where Mesa is installed, the cascade views).

use std::path::Path;

use tilegl_conformance::gallery::{self, Options};
use tilegl_conformance::{mesa, scenes_examples, scenes_techniques};

#[test]
fn every_teaching_scene_is_in_the_gallery_with_a_text() {
    let entries = gallery::entries();
    let names: Vec<&str> = entries.iter().map(|e| e.name.as_str()).collect();
    for s in scenes_examples::EXAMPLE_SCENES
        .iter()
        .chain(scenes_techniques::TECHNIQUE_SCENES)
    {
        assert!(names.contains(&s.name), "{} missing", s.name);
    }
    // The seven built-in scenes of the tilegl command.
    for b in [
        "smooth_depth",
        "primitives",
        "clipping",
        "flat_smooth",
        "culling",
        "textured_fog",
        "raster_modes",
    ] {
        assert!(names.contains(&b), "{b} missing");
    }
    let mut sorted = names.clone();
    sorted.sort_unstable();
    sorted.dedup();
    assert_eq!(sorted.len(), names.len(), "a scene listed twice");
    for e in &entries {
        let words: usize = e.teaches.iter().map(|p| p.split_whitespace().count()).sum();
        assert!(
            !e.title.is_empty() && words >= 8,
            "{}: title {:?}, {} words of text",
            e.name,
            e.title,
            words
        );
    }
    for (name, _) in gallery::CASCADES {
        assert!(names.contains(name), "cascade of unknown scene {name}");
    }
}

#[test]
fn example_doc_comments_are_parsed() {
    let src = "//! Title line.\n//!\n//! What it teaches, `code`.\n//! - a point\n//!\n//! Run: \
               `cargo run`\n\nfn main() {\n    x::run(\"ex\", &[\"s1\", \"s2\"]);\n}\n";
    let src = src.replace("x::run(", "example_support::run(");
    let (scenes, title, paragraphs) = gallery::parse_example(&src);
    assert_eq!(scenes, ["s1", "s2"]);
    assert_eq!(title, "Title line.");
    assert_eq!(paragraphs, ["What it teaches, `code`.\n- a point"]);
}

fn png_size(path: &Path) -> (u32, u32) {
    let img = image::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    (img.width(), img.height())
}

#[test]
fn a_small_gallery_is_written_and_read_back() {
    let mesa_ok = mesa::mesa_available().is_ok();
    if !mesa_ok && mesa::in_ci() {
        panic!("CI: Mesa (OSMesa) must be installed for the gallery test");
    }
    let names = ["ex_detail_texture", "ex_emboss_bump", "culling"];
    let opts = Options {
        only: names.iter().map(|s| s.to_string()).collect(),
        ..Options::default()
    };
    let outcomes = gallery::run(&opts).unwrap();
    assert_eq!(outcomes.len(), 3);
    let dir = std::env::temp_dir().join(format!("tilegl-gallery-test-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let index = gallery::write(&dir, &outcomes).unwrap();
    let html = std::fs::read_to_string(&index).unwrap();
    assert!(html.starts_with("<!DOCTYPE html>"));
    assert_eq!(html.matches("<section class=\"scene\"").count(), 3);
    for n in names {
        assert!(html.contains(&format!("id=\"{n}\"")), "{n} section");
        assert!(
            html.contains(&format!("href=\"#{n}\"")),
            "{n} in the contents"
        );
    }
    // The texts: the technique's GL state, the example's doc comment, the built-in's line.
    assert!(html.contains("GL_ADD_SIGNED"));
    assert!(html.contains("Emboss"));
    assert!(html.contains("back faces culled"));
    // Every picture the page names exists and decodes; no picture is named twice.
    let srcs: Vec<&str> = html
        .split("<img src=\"")
        .skip(1)
        .map(|s| &s[..s.find('"').unwrap()])
        .collect();
    let mut unique = srcs.clone();
    unique.sort_unstable();
    unique.dedup();
    assert_eq!(unique.len(), srcs.len());
    for s in &srcs {
        assert!(!s.contains('/') && s.ends_with(".png"), "{s}");
        let (w, h) = png_size(&dir.join(s));
        assert!(w > 0 && h > 0);
    }
    for n in names {
        assert!(srcs.contains(&format!("{n}-tilegl.png").as_str()));
        if mesa_ok {
            assert!(srcs.contains(&format!("{n}-mesa.png").as_str()), "{n}");
            assert!(srcs.contains(&format!("{n}-diff.png").as_str()), "{n}");
        }
    }
    assert_eq!(png_size(&dir.join("culling-tilegl.png")), (384, 192));
    // The emboss example's passes, and the detail texture's cascade (unit 0 alone).
    assert!(srcs.iter().any(|s| s.starts_with("ex_emboss_bump-stage")));
    assert!(html.contains("Texture cascade, unit by unit"));
    assert!(srcs.contains(&"ex_detail_texture-units1-tilegl.png"));
    // The cascade view differs from the final picture (the detail adds high frequencies).
    let detail = &outcomes[0];
    assert_eq!(detail.entry.name, "ex_detail_texture");
    let (k, base_only) = &detail.tilegl.cascade[0];
    assert_eq!(*k, 1);
    let d = tilegl_conformance::compare::diff(base_only, &detail.tilegl.image, 8);
    assert!(d.bad_share > 0.2, "{d}");
    if mesa_ok {
        assert!(html.contains("llvmpipe"));
        assert!(html.contains("within tolerance"));
        assert!(!html.contains("OUTSIDE tolerance"));
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn size_and_unknown_scene() {
    let opts = Options {
        only: vec!["smooth_depth".into()],
        size: Some((64, 48)),
        no_mesa: true,
        ..Options::default()
    };
    let o = gallery::run(&opts).unwrap();
    assert_eq!(
        (o[0].tilegl.image.width, o[0].tilegl.image.height),
        (64, 48)
    );
    assert!(o[0].mesa.is_err());
    let bad = Options {
        only: vec!["no_such_scene".into()],
        ..Options::default()
    };
    let err = gallery::run(&bad).err().unwrap();
    assert!(err.contains("no_such_scene") && err.contains("ex_texenv_modes"));
}

/// Each cascade view of a multitexture scene is a different picture from the final one (the
/// scene really leaves the later units off), and the full unit count gives the final picture.
#[test]
fn cascade_views_leave_units_off() {
    use tilegl_conformance::{compare, example_support, scenes};
    for (name, range) in gallery::CASCADES {
        let scene = scenes::find(name).unwrap();
        let full = compare::render_tilegl(scene).image;
        for k in range.clone() {
            let part = example_support::with_units(k, || compare::render_tilegl(scene)).image;
            let d = compare::diff(&part, &full, 8);
            assert!(d.bad_pixels > 100, "{name} with {k} units: {d}");
        }
        let all = example_support::with_units(8, || compare::render_tilegl(scene)).image;
        assert_eq!(all, full, "{name}");
    }
}

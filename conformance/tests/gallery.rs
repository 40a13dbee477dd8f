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

/// A picture at half the size: each pixel the rounded mean of a 2x2 block.
fn half(img: &tilegl_conformance::Image) -> tilegl_conformance::Image {
    let (w, h) = (img.width / 2, img.height / 2);
    let mut pixels = Vec::with_capacity((w * h * 4) as usize);
    for y in 0..h {
        for x in 0..w {
            for c in 0..4 {
                let s: u32 = [(0, 0), (1, 0), (0, 1), (1, 1)]
                    .iter()
                    .map(|(dx, dy)| img.pixel(2 * x + dx, 2 * y + dy)[c] as u32)
                    .sum();
                pixels.push(((s + 2) / 4) as u8);
            }
        }
    }
    tilegl_conformance::Image {
        width: w,
        height: h,
        pixels,
    }
}

/// The lower-left `w` x `h` corner of a picture (what a scene drawn at its own size in a
/// bigger window would leave there).
fn corner(img: &tilegl_conformance::Image, w: i32, h: i32) -> tilegl_conformance::Image {
    let mut pixels = Vec::with_capacity((w * h * 4) as usize);
    for y in 0..h {
        for x in 0..w {
            pixels.extend_from_slice(&img.pixel(x, y));
        }
    }
    tilegl_conformance::Image {
        width: w,
        height: h,
        pixels,
    }
}

/// Entries whose picture at twice the size, halved, legitimately differs from the picture at
/// their own size by more than the bound below, and why.
const SIZE_DEPENDENT: &[(&str, &str)] = &[
    (
        "ex_prefilter_mip_rip_sat",
        "the mipmap level follows the pixel size",
    ),
    (
        "ex_mipmap_filters",
        "the mipmap level follows the pixel size",
    ),
    ("ex_mipmap_levels", "each mipmap level has its own colour"),
    (
        "ex_magnify_anisotropic",
        "the mipmap level follows the pixel size",
    ),
    (
        "ex_detail_texture",
        "the detail texture's level follows the pixel size",
    ),
    ("ex_cross_tree", "the mipmap level follows the pixel size"),
    (
        "ex_planar_reflection",
        "the mipmap level follows the pixel size",
    ),
    (
        "ex_cube_map_dynamic",
        "the cube faces keep their size (64 texels)",
    ),
    (
        "ex_airbrush",
        "the canvas copied into a texture keeps its size",
    ),
    ("wide_points", "point sizes are in pixels"),
    ("smooth_points", "point sizes are in pixels"),
    ("point_attenuation", "point sizes are in pixels"),
    ("wide_lines", "line widths are in pixels"),
    ("smooth_lines", "line widths are in pixels"),
    ("line_stipple", "stipple patterns are in pixels"),
    (
        "raster_modes",
        "point sizes, line widths and stipples are in pixels",
    ),
];

/// `--size` renders the scene at that size (its geometry scales with the window), not its own
/// picture in a corner of a bigger window: for every gallery entry, the picture at twice the
/// size, halved, is closer to the picture at its own size than the bigger picture's corner is;
/// and, except where the picture legitimately depends on the pixel size (listed with the
/// reason), at most 5 % of its pixels differ by more than 24 in a channel.
#[test]
fn a_scene_at_twice_its_size_is_the_same_picture_scaled() {
    for e in gallery::entries() {
        let render = |size| {
            let opts = Options {
                only: vec![e.name.clone()],
                size,
                no_mesa: true,
                ..Options::default()
            };
            gallery::run(&opts).unwrap().remove(0).tilegl.image
        };
        let one = render(None);
        let two = render(Some((2 * e.width, 2 * e.height)));
        assert_eq!((two.width, two.height), (2 * e.width, 2 * e.height));
        let scaled = tilegl_conformance::compare::diff(&one, &half(&two), 24);
        let cornered =
            tilegl_conformance::compare::diff(&one, &corner(&two, e.width, e.height), 24);
        println!("{}: halved {scaled}; corner {cornered}", e.name);
        assert!(
            scaled.mean < cornered.mean,
            "{}: at twice the size the picture is not scaled (halved: {scaled}; its corner: \
             {cornered})",
            e.name
        );
        if !SIZE_DEPENDENT.iter().any(|(n, _)| *n == e.name) {
            assert!(
                scaled.bad_share <= 0.05,
                "{}: at twice the size, halved: {scaled}",
                e.name
            );
        }
    }
}

/// At another size than their own, scenes still agree with Mesa drawn at that size.
#[test]
fn a_scene_at_another_size_agrees_with_mesa() {
    if !mesa::require_mesa("gallery --size") {
        return;
    }
    for (name, size) in [
        ("ex_texenv_modes", (576, 384)),
        ("ex_fog_terrain", (768, 256)),
        ("ex_shadow_map", (256, 256)),
        ("clipping", (192, 96)),
    ] {
        let opts = Options {
            only: vec![name.to_string()],
            size: Some(size),
            ..Options::default()
        };
        let o = gallery::run(&opts).unwrap().remove(0);
        let mesa = o.mesa.as_ref().unwrap();
        assert_eq!((mesa.image.width, mesa.image.height), size);
        let d = tilegl_conformance::compare::diff(
            &o.tilegl.image,
            &mesa.image,
            o.entry.tolerance.channel,
        );
        println!("{name} at {size:?}: {d}");
        assert!(o.entry.tolerance.accepts(&d), "{name} at {size:?}: {d}");
    }
}

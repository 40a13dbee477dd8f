//! The rules of the replay comparison (`tilegl::replay::reference`, used by
//! `tilegl replay --compare` and the capture tests), each against planted references:
//! the llvmpipe-vs-softpipe spread widens the tolerance only up to a cap
//! (`tilegl::compare::SPREAD_CAP`, 5 %), alpha is compared where the reference has it, and a
//! reference that shows nothing drawn (every pixel black or the clear colour) fails, unless the
//! capture's `glRenderMode` results, replayed, equal the recorded ones.

use std::path::{Path, PathBuf};

use tilegl::replay::player::Player;
use tilegl::replay::reference::{compare_replay, CompareReport};
use tilegl::replay::script::ScriptReader;
use tilegl::replay::trace::TraceReader;

mod common;

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tilegl-tolerance-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn report_text(r: &CompareReport) -> String {
    let mut t: Vec<String> = r.pictures.iter().map(|p| p.line()).collect();
    t.push(r.summary());
    t.join("\n")
}

/// glxgears (the repository's copy of the shared capture) compared with references built from
/// its real ones by `plant` (per file: the real reference, to be changed in place), and a
/// `softpipe/` folder of pictures made by `softpipe` when given.
fn glxgears_against(
    tag: &str,
    plant: impl Fn(&mut image::RgbImage),
    softpipe: Option<&dyn Fn(&image::RgbImage) -> image::RgbImage>,
) -> CompareReport {
    let dir = common::shared_traces();
    let src = common::require(&dir.join("glxgears.frames"));
    let refs = temp_dir(tag);
    let tsv = std::fs::read_to_string(common::require(&src.join("frames.tsv"))).unwrap();
    std::fs::write(refs.join("frames.tsv"), &tsv).unwrap();
    if softpipe.is_some() {
        std::fs::create_dir_all(refs.join("softpipe")).unwrap();
    }
    for line in tsv.lines().skip(1) {
        let file = line.split('\t').next().unwrap();
        let mut img = image::open(common::require(&src.join(file)))
            .unwrap()
            .to_rgb8();
        plant(&mut img);
        img.save(refs.join(file)).unwrap();
        if let Some(sp) = softpipe {
            sp(&img).save(refs.join("softpipe").join(file)).unwrap();
        }
    }
    let trace = common::require(&dir.join("glxgears.trace"));
    let mut player = Player::new(2);
    let report = compare_replay(
        &mut TraceReader::open(&trace).unwrap(),
        &mut player,
        &refs,
        None,
        &mut |_| {},
    )
    .unwrap();
    let _ = std::fs::remove_dir_all(&refs);
    assert_eq!(report.pictures.len(), 3, "{}", report_text(&report));
    report
}

/// The top `rows` rows painted magenta (glxgears draws nothing magenta, and its top rows are
/// background), so that `rows / height` of the pixels are off.
fn magenta_band(rows: u32) -> impl Fn(&mut image::RgbImage) {
    move |img: &mut image::RgbImage| {
        for y in 0..rows {
            for x in 0..img.width() {
                img.put_pixel(x, y, image::Rgb([255, 0, 255]));
            }
        }
    }
}

/// A "softpipe" picture that differs from the reference everywhere: the drivers' spread is
/// then 100 % of the pixels, far beyond the cap.
fn inverted(img: &image::RgbImage) -> image::RgbImage {
    let mut out = img.clone();
    for p in out.pixels_mut() {
        p.0 = p.0.map(|c| 255 - c);
        if p.0.iter().all(|&c| c.abs_diff(127) < 10) {
            p.0 = [0, 0, 0];
        }
    }
    out
}

#[test]
fn a_large_driver_spread_widens_the_tolerance_only_up_to_the_cap() {
    // 10 % of the pixels off (30 of 300 rows) where the drivers differ on all pixels: the
    // spread would allow it; the cap (5 %) does not.
    let ten = glxgears_against("ten", magenta_band(30), Some(&inverted));
    for p in &ten.pictures {
        let d = p.diff.expect("rendered");
        assert!(d.bad_share >= 0.10, "{}", p.line());
        assert!(p.softpipe.unwrap().bad_share > 0.5, "{}", p.line());
        assert_eq!(p.tolerance.max_bad_share, tilegl::compare::SPREAD_CAP);
        assert!(!p.ok, "{}", p.line());
    }
    assert!(!ten.all_ok());
    // 3 % off (9 rows) is within the cap where the drivers differ that much...
    let three = glxgears_against("three", magenta_band(9), Some(&inverted));
    for p in &three.pictures {
        let d = p.diff.expect("rendered");
        assert!(d.bad_share >= 0.03 && d.bad_share < 0.05, "{}", p.line());
        assert!(p.ok, "{}", p.line());
    }
    // ... and out of tolerance where they agree (no softpipe pictures: 0.1 %).
    let alone = glxgears_against("alone", magenta_band(9), None);
    for p in &alone.pictures {
        assert_eq!(p.tolerance, tilegl::compare::PROJECT);
        assert!(!p.ok, "{}", p.line());
    }
}

#[test]
fn a_black_reference_fails_even_where_the_replay_is_close() {
    // Planted black references for a real capture: they fail, and the line says why.
    let black = glxgears_against(
        "black",
        |img| img.pixels_mut().for_each(|p| p.0 = [0, 0, 0]),
        None,
    );
    for p in &black.pictures {
        assert!(!p.ok);
        assert!(p.note.contains("nothing drawn"), "{}", p.line());
    }
}

/// Replays `script` and compares its first frame with `reference` (written as a PNG of its own
/// colour type, so an RGBA image is a reference with alpha).
fn script_against(tag: &str, script: &str, reference: image::DynamicImage) -> CompareReport {
    let dir = temp_dir(tag);
    std::fs::write(
        dir.join("frames.tsv"),
        "file\tframe_index\tcall_no\tsnapshot_of\nframe-0000.png\t0\t5\tswap\n",
    )
    .unwrap();
    reference.save(dir.join("frame-0000.png")).unwrap();
    let mut player = Player::new(1);
    player.auto_window = true;
    let report = compare_replay(
        &mut ScriptReader::new(script, Path::new(".")),
        &mut player,
        &dir,
        None,
        &mut |_| {},
    )
    .unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(report.pictures.len(), 1);
    assert!(
        report.pictures[0].diff.is_some(),
        "{}",
        report_text(&report)
    );
    report
}

/// Blue clear with alpha 0.25, a half-transparent red rectangle over the left half.
const HALF_ALPHA: &str = "window(16, 8);\n\
    glClearColor(0.0f, 0.0f, 1.0f, 0.25f);\n\
    glClear(GL_COLOR_BUFFER_BIT);\n\
    glColor4f(1.0f, 0.0f, 0.0f, 0.5f);\n\
    glRectf(-1.0f, -1.0f, 0.0f, 1.0f);\n\
    swap();\n";

/// The picture `HALF_ALPHA` must give: colours and alphas converted as GL 1.5 section 2.14.9
/// says (c * 255, rounded), alpha replaced by `alpha` (when given) everywhere.
fn half_alpha_picture(alpha: Option<u8>) -> image::RgbaImage {
    let to8 = |c: f32| (c * 255.0).round() as u8;
    image::RgbaImage::from_fn(16, 8, |x, _| {
        let px = if x < 8 {
            [255, 0, 0, to8(0.5)]
        } else {
            [0, 0, 255, to8(0.25)]
        };
        image::Rgba([px[0], px[1], px[2], alpha.unwrap_or(px[3])])
    })
}

#[test]
fn alpha_is_compared_where_the_reference_has_it() {
    let right = script_against(
        "alpha-right",
        HALF_ALPHA,
        image::DynamicImage::ImageRgba8(half_alpha_picture(None)),
    );
    let p = &right.pictures[0];
    assert!(p.alpha && p.ok, "{}", p.line());
    assert!(p.line().contains("(RGBA)"), "{}", p.line());
    // The same colours with every alpha 255: the whole picture is off.
    let opaque = script_against(
        "alpha-wrong",
        HALF_ALPHA,
        image::DynamicImage::ImageRgba8(half_alpha_picture(Some(255))),
    );
    let p = &opaque.pictures[0];
    assert!(p.alpha && !p.ok, "{}", p.line());
    assert_eq!(p.diff.unwrap().bad_share, 1.0, "{}", p.line());
    // A reference without alpha (as apitrace writes them) compares RGB only.
    let rgb = script_against(
        "alpha-rgb",
        HALF_ALPHA,
        image::DynamicImage::ImageRgb8(
            image::DynamicImage::ImageRgba8(half_alpha_picture(Some(255))).to_rgb8(),
        ),
    );
    let p = &rgb.pictures[0];
    assert!(!p.alpha && p.ok, "{}", p.line());
}

#[test]
fn a_reference_showing_nothing_drawn_fails_and_one_drawn_colour_passes() {
    let uniform = |c: [u8; 3]| {
        image::DynamicImage::ImageRgb8(image::RgbImage::from_pixel(16, 8, image::Rgb(c)))
    };
    // Nothing drawn (all colour writes masked) over a black clear: the replay gives the same
    // black picture, which used to match.
    let masked = "window(16, 8);\n\
        glClear(GL_COLOR_BUFFER_BIT);\n\
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);\n\
        glColor3f(1.0f, 1.0f, 1.0f);\n\
        glRectf(-1.0f, -1.0f, 1.0f, 1.0f);\n\
        swap();\n";
    let r = script_against("black", masked, uniform([0, 0, 0]));
    let p = &r.pictures[0];
    assert_eq!(p.diff.unwrap().bad_pixels, 0, "{}", p.line());
    assert!(!p.ok && p.note.contains("black"), "{}", p.line());
    // A grey clear and nothing drawn: every pixel is the clear colour.
    let grey = "window(16, 8);\n\
        glClearColor(0.5f, 0.5f, 0.5f, 1.0f);\n\
        glClear(GL_COLOR_BUFFER_BIT);\n\
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);\n\
        glRectf(-1.0f, -1.0f, 1.0f, 1.0f);\n\
        swap();\n";
    let r = script_against("grey", grey, uniform([128, 128, 128]));
    let p = &r.pictures[0];
    assert_eq!(p.diff.unwrap().bad_pixels, 0, "{}", p.line());
    assert!(!p.ok && p.note.contains("clear colour"), "{}", p.line());
    // A drawn rectangle covering the window in one colour (how piglit probes often look) is a
    // real check: it passes.
    let red = "window(16, 8);\n\
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);\n\
        glClear(GL_COLOR_BUFFER_BIT);\n\
        glColor3f(1.0f, 0.0f, 0.0f);\n\
        glRectf(-1.0f, -1.0f, 1.0f, 1.0f);\n\
        swap();\n";
    let r = script_against("red", red, uniform([255, 0, 0]));
    let p = &r.pictures[0];
    assert!(p.ok && p.note.is_empty(), "{}", p.line());
}

/// A program that draws only in feedback mode: a grey clear, one triangle fed back as GL_2D
/// (a polygon token, its vertex count and three x, y pairs: 8 values), and the value count
/// `glRenderMode` returned when it was recorded (`RECORDED`).
fn feedback_script(recorded: i32) -> String {
    format!(
        "window(16, 8);\n\
         glClearColor(0.5f, 0.5f, 0.5f, 1.0f);\n\
         glClear(GL_COLOR_BUFFER_BIT);\n\
         glFeedbackBuffer(16, GL_2D, {{0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f}});\n\
         glRenderMode(GL_FEEDBACK) = 0;\n\
         glBegin(GL_TRIANGLES);\n\
         glVertex2f(-0.5f, -0.5f);\n\
         glVertex2f(0.5f, -0.5f);\n\
         glVertex2f(0.0f, 0.5f);\n\
         glEnd();\n\
         glRenderMode(GL_RENDER) = {recorded};\n\
         swap();\n"
    )
}

/// The frame of `feedback_script`, a picture of the clear colour only, passes when the
/// replayed `glRenderMode` results equal the recorded ones (the check of a program that draws
/// in feedback mode), and fails, saying so, when one differs; with no result that counts
/// something it is a reference of nothing drawn, which fails.
#[test]
fn render_mode_results_check_captures_that_draw_nothing() {
    let grey = image::DynamicImage::ImageRgb8(image::RgbImage::from_pixel(
        16,
        8,
        image::Rgb([128, 128, 128]),
    ));
    let frame_at = |script: String| script_against("feedback", &script, grey.clone());
    let right = frame_at(feedback_script(8));
    assert!(right.all_ok(), "{}", report_text(&right));
    assert!(
        right.pictures[0].note.contains("checked by 1 glRenderMode"),
        "{}",
        report_text(&right)
    );
    let wrong = frame_at(feedback_script(9));
    assert!(!wrong.all_ok(), "{}", report_text(&wrong));
    assert!(
        wrong.pictures[0]
            .note
            .contains("1 of 2 glRenderMode results differ"),
        "{}",
        report_text(&wrong)
    );
    let nothing = frame_at(feedback_script(8).replace("glRenderMode(GL_RENDER) = 8;\n", ""));
    assert!(!nothing.all_ok(), "{}", report_text(&nothing));
    assert!(
        nothing.pictures[0].note.contains("nothing drawn"),
        "{}",
        report_text(&nothing)
    );
}

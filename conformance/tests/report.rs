//! The conformance report's structure: a few scenes and one capture written as a report, then
//! the page read back (summary table, one row per entry with its figures and verdict, every
//! picture it names present and decodable, failures first), and, where Chromium is installed
//! (always in CI), a screenshot of the page showing the tables and pictures.

use std::path::{Path, PathBuf};

use tilegl_conformance::compare;
use tilegl_conformance::report::{self, Progress, Verdict};
use tilegl_conformance::scenes::SCENES;

fn in_ci() -> bool {
    std::env::var("CI").is_ok_and(|v| v == "true" || v == "1")
}

/// Writes a report of the `tex_nearest_replace` and `wide_lines` scenes and the `xss-cage`
/// capture into a fresh folder; returns the folder and the entries.
fn small_report(test: &str) -> (PathBuf, Vec<report::Entry>) {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("report-{test}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let traces = Path::new(env!("CARGO_MANIFEST_DIR")).join("traces/shared");
    assert!(
        traces.join("xss-cage.trace").is_file(),
        "test input missing: {}",
        traces.join("xss-cage.trace").display()
    );
    let mut progress = Progress::new(3);
    let child = [test, "--exact", "--nocapture"];
    let mut entries = report::run_scenes(&dir, "tex_nearest_replace", &mut progress, &child);
    entries.extend(report::run_scenes(
        &dir,
        "wide_lines",
        &mut progress,
        &child,
    ));
    entries.extend(report::run_captures(
        &traces,
        &dir,
        "xss-cage",
        &mut progress,
    ));
    (dir, entries)
}

#[test]
fn report_page_lists_every_entry_with_its_pictures() {
    if compare::serve_child_request(&SCENES) || !tilegl_conformance::mesa::require_mesa("report") {
        return;
    }
    let (dir, mut entries) = small_report("report_page_lists_every_entry_with_its_pictures");
    assert!(entries.len() >= 4, "{} entries", entries.len());
    for e in &entries {
        assert_eq!(
            e.verdict,
            Verdict::Pass,
            "{}: {:?} {}",
            e.name,
            e.diff,
            e.note
        );
        assert!(e.diff.is_some(), "{} has figures", e.name);
    }
    // A failing entry is listed first.
    let mut failing = entries[0].clone();
    failing.name = "planted_failure".into();
    failing.verdict = Verdict::Fail;
    entries.push(failing);
    let page = report::write_html(&dir, &entries, "Mesa under test").unwrap();
    let html = std::fs::read_to_string(&page).unwrap();
    assert!(html.contains("<table id=\"summary\">") && html.contains("<table id=\"entries\">"));
    assert!(html.contains("<td>texturing</td>") && html.contains("<td>captures</td>"));
    let rows: Vec<&str> = html.split("<tr class=").skip(1).collect();
    assert_eq!(rows.len(), entries.len(), "one row per entry");
    assert!(rows[0].contains("planted_failure"), "failures come first");
    let mut pictures = 0;
    for src in html
        .split("src=\"")
        .skip(1)
        .map(|s| &s[..s.find('"').unwrap()])
    {
        let path = dir.join(src);
        let img = image::open(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(img.width() > 0);
        pictures += 1;
    }
    // Scenes: tilegl, llvmpipe, softpipe, difference; captures: tilegl, reference, softpipe.
    assert!(pictures >= 2 * 4 + 2 * 3, "{pictures} pictures");
}

/// The page in headless Chromium: the screenshot is not blank and shows the pictures' colours.
#[test]
fn report_renders_in_chromium() {
    if compare::serve_child_request(&SCENES) || !tilegl_conformance::mesa::require_mesa("report") {
        return;
    }
    let chromium = ["/usr/bin/chromium", "/usr/bin/chromium-browser"]
        .into_iter()
        .find(|p| Path::new(p).is_file());
    let Some(chromium) = chromium else {
        assert!(!in_ci(), "CI=true and Chromium is not installed");
        eprintln!("SKIPPED: Chromium not installed (Debian package chromium)");
        return;
    };
    let (dir, entries) = small_report("report_renders_in_chromium");
    let page = report::write_html(&dir, &entries, "Mesa").unwrap();
    let shot = dir.join("screenshot.png");
    let profile = dir.join("chromium-profile");
    let out = std::process::Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--no-first-run",
            "--hide-scrollbars",
            "--window-size=1400,900",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(format!("--screenshot={}", shot.display()))
        .arg(format!("file://{}", page.display()))
        .output()
        .expect("run chromium");
    assert!(
        shot.is_file(),
        "no screenshot: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let img = image::open(&shot).unwrap().to_rgb8();
    let mut colours = std::collections::HashSet::new();
    for p in img.pixels() {
        colours.insert(p.0);
    }
    // Text alone gives a few greys; the tables' shading and the pictures give many colours.
    assert!(
        colours.len() > 200,
        "{} colours: the page looks empty",
        colours.len()
    );
}

//! The conformance report's structure: a few scenes and one capture written as a report, then
//! the page read back (summary table, one row per entry with its figures and verdict, every
//! picture it names present and decodable, failures first), and, where Chromium is installed
//! (always in CI), a screenshot of the page showing the tables and pictures.

use std::path::{Path, PathBuf};

use tilegl_conformance::compare;
use tilegl_conformance::report::{self, Progress, Verdict};
use tilegl_conformance::scenes::SCENES;
use tilegl_conformance::state_cases;

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
    assert!(html.contains("id=\"summary\"") && html.contains("id=\"states\""));
    assert!(html.contains("<table id=\"summary\">") && html.contains("<table id=\"entries\">"));
    assert!(html.contains("<td>texturing</td>") && html.contains("<td>captures</td>"));
    let picture_rows = &html[html.find("<table id=\"entries\">").unwrap()..];
    let picture_rows = &picture_rows[..picture_rows.find("</table>").unwrap()];
    let rows: Vec<&str> = picture_rows.split("<tr class=").skip(1).collect();
    assert_eq!(rows.len(), entries.len(), "one row per entry");
    assert!(rows[0].contains("planted_failure"), "failures come first");
    let summary = &html[html.find("<table id=\"summary\">").unwrap()..];
    let first_area = summary.split("<tr class=").nth(1).unwrap();
    assert!(
        first_area.starts_with("\"FAIL\"") && first_area.contains("texturing"),
        "the area with a failure comes first in the summary: {first_area}"
    );
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

/// Every state and error case of the library is in the report with the calls of its script,
/// the specification's expected result, every answer on Mesa, tilegl and tilegl's C ABI, the
/// verdict and the times; their areas are counted in the summary.
#[test]
fn state_cases_are_in_the_report() {
    if !tilegl_conformance::mesa::require_mesa("report") {
        return;
    }
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("report-state-cases");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let all: Vec<&str> = state_cases::all().map(|c| c.name).collect();
    assert!(all.len() >= 20, "{} state cases", all.len());
    // Every case has its calls and an expected result to show.
    for c in state_cases::all() {
        let calls = c.calls();
        assert!(
            calls.starts_with(&format!("pub fn {}(", c.name))
                || calls.starts_with(&format!("fn {}(", c.name)),
            "{}: calls not found: {calls:.80}",
            c.name
        );
        assert!(
            calls.lines().count() > 3 && c.expect.len() > 40,
            "{}",
            c.name
        );
    }
    // Two cases run for the page (the whole list runs in the differential tests).
    let mut progress = Progress::new(2);
    let mut states = report::run_state_cases("errors_bad_enums", &mut progress);
    states.extend(report::run_state_cases("state_lists", &mut progress));
    assert_eq!(states.len(), 2);
    for s in &states {
        assert_eq!(s.verdict, Verdict::Pass, "{}: {}", s.case.name, s.note);
        let o = &s.outcome;
        assert!(o.c_matches_rust && o.agrees_with_mesa);
        assert!(o.answers.len() > 5 && o.answers.iter().all(|a| a.agrees));
        assert!(o.answers.iter().all(|a| a.mesa.is_some() && a.rust == a.c));
        assert!(o.times.iter().all(|t| t.is_some()));
    }
    let report = report::Report {
        entries: Vec::new(),
        states,
        piglit: tilegl_conformance::piglit::read_committed(),
        mesa: "Mesa under test".into(),
    };
    let html = std::fs::read_to_string(report::write_page(&dir, &report).unwrap()).unwrap();
    let section = &html[html.find("<table id=\"states\">").unwrap()..];
    for name in ["errors_bad_enums", "state_lists"] {
        assert!(section.contains(&format!("<td>{name}</td>")), "{name} row");
        assert!(section.contains(&format!("pub fn {name}(")), "{name} calls");
    }
    assert!(section.contains("GL_INVALID_ENUM") && section.contains("glGetError after"));
    // Both areas in the summary, one case each.
    let summary = &html[..html.find("<table id=\"entries\">").unwrap()];
    for area in [
        "state cases: queries, matrices, errors",
        "state cases: arrays, buffers, lists",
    ] {
        assert!(
            summary.contains(&format!(
                "<td>{area}</td><td class=num>1</td><td class=num>1</td>"
            )),
            "{area} counted in the summary"
        );
    }
}

/// The piglit table of the committed record: every test with both verdicts, counts that add up
/// to the record's own summary, the date of the run and how to redo it.
#[test]
fn piglit_table_comes_from_the_committed_record() {
    let run = tilegl_conformance::piglit::read_committed().unwrap();
    let md = std::fs::read_to_string(tilegl_conformance::piglit::committed_record()).unwrap();
    // The record's summary table, counted independently of the parser.
    let summary = &md[md.find("## Summary").unwrap()..];
    let mut expected: Vec<(String, String, usize)> = summary
        .lines()
        .skip_while(|l| !l.starts_with('|'))
        .take_while(|l| l.starts_with('|'))
        .skip(2)
        .map(|l| {
            let c: Vec<&str> = l.split('|').map(str::trim).collect();
            (c[1].to_string(), c[2].to_string(), c[3].parse().unwrap())
        })
        .collect();
    let mut got = tilegl_conformance::piglit::summary(&run.rows);
    expected.sort();
    got.sort();
    assert_eq!(got, expected);
    assert!(run.rows.len() > 300, "{} tests", run.rows.len());
    assert!(
        run.label.contains("Machine:") && run.label.contains("2026"),
        "{}",
        run.label
    );
    assert!(run.redo.contains("tests/piglit/run.sh"), "{}", run.redo);
    let failing = run
        .rows
        .iter()
        .find(|r| r.test.ends_with("gl-1.0-beginend-coverage"))
        .unwrap();
    assert_eq!(
        (failing.mesa.as_str(), failing.tilegl.as_str()),
        ("pass", "fail")
    );
    assert!(failing.message.contains("GL_INVALID_OPERATION"));

    // A fresh run's two TSV files join by test name.
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("report-piglit-tsv");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("mesa.tsv"), "a\tpass\nb\tfail\n").unwrap();
    std::fs::write(dir.join("tilegl.tsv"), "b\tpass\nc\tskip\n").unwrap();
    let fresh =
        tilegl_conformance::piglit::from_tsv(&dir.join("mesa.tsv"), &dir.join("tilegl.tsv"))
            .unwrap();
    let rows: Vec<(&str, &str, &str)> = fresh
        .rows
        .iter()
        .map(|r| (r.test.as_str(), r.mesa.as_str(), r.tilegl.as_str()))
        .collect();
    assert_eq!(
        rows,
        [
            ("a", "pass", "-"),
            ("b", "fail", "pass"),
            ("c", "-", "skip")
        ]
    );
    let page = report::write_page(
        &dir,
        &report::Report {
            entries: Vec::new(),
            states: Vec::new(),
            piglit: Ok(run),
            mesa: String::new(),
        },
    )
    .unwrap();
    let html = std::fs::read_to_string(page).unwrap();
    let table = &html[html.find("<table id=\"piglit-tests\">").unwrap()..];
    assert!(table.split("<tr class=").count() > 300);
    assert!(table.contains("gl-1.0-beginend-coverage</td><td>pass</td><td>fail</td>"));
}

/// Every extreme-case scene is in the report with its figures, in its own area; the case where
/// Mesa is known to be less exact carries the note and its own verdict.
#[test]
fn extreme_cases_are_in_the_report_in_their_own_area() {
    if compare::serve_child_request(&SCENES) || !tilegl_conformance::mesa::require_mesa("report") {
        return;
    }
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("report-extreme");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let list: Vec<_> = tilegl_conformance::scenes_extremes::EXTREME_SCENES.to_vec();
    let mut progress = Progress::new(list.len());
    let child = [
        "extreme_cases_are_in_the_report_in_their_own_area",
        "--exact",
        "--nocapture",
    ];
    let entries = report::run_scenes(&dir, "extreme_", &mut progress, &child);
    let names: Vec<&str> = entries.iter().map(|e| e.name.as_str()).collect();
    let expected: Vec<&str> = list.iter().map(|s| s.name).collect();
    assert_eq!(names, expected);
    for e in &entries {
        assert_eq!(e.area, "extreme cases", "{}", e.name);
        assert!(
            e.diff.is_some() && e.spread.is_some(),
            "{}: figures",
            e.name
        );
        assert!(
            e.pictures.iter().all(|p| p.is_some()),
            "{}: pictures",
            e.name
        );
        match tilegl_conformance::known_failures::mesa_less_exact(&e.name) {
            Some(why) => {
                assert_eq!(e.verdict, Verdict::MesaLessExact, "{}", e.name);
                assert!(e.note.contains(why), "{}: the note", e.name);
            }
            None => assert_eq!(e.verdict, Verdict::Pass, "{}: {}", e.name, e.note),
        }
    }
    assert!(entries.iter().any(|e| e.verdict == Verdict::MesaLessExact));
    let html =
        std::fs::read_to_string(report::write_html(&dir, &entries, "Mesa").unwrap()).unwrap();
    assert!(html.contains("<td>extreme cases</td>"));
    assert!(html.contains("Mesa less exact") && html.contains("tests/cascade_extremes.rs"));
}

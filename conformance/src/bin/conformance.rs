//! `conformance [--filter PATTERN] [--report DIR] [--traces DIR]`: runs the differential
//! scenes (and, with a report, the captures of `conformance/traces/`) on tilegl and on Mesa
//! (llvmpipe, and softpipe in a child process), prints one line per entry and a summary, and
//! with `--report` writes the HTML report `DIR/index.html` and, unless `--no-quality`, the
//! error-against-run-time charts of every quality knob (`DIR/quality.html`). `tilegl
//! conformance` runs this.
//! Exit status 1 when an entry fails.

use std::path::PathBuf;
use std::process::ExitCode;

use tilegl_conformance::compare;
use tilegl_conformance::report::{self, Verdict};
use tilegl_conformance::scenes::SCENES;

fn main() -> ExitCode {
    if compare::serve_child_request(&SCENES) {
        return ExitCode::SUCCESS;
    }
    let mut filter = String::new();
    let mut dir: Option<PathBuf> = None;
    let own = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("traces");
    let mut traces = vec![own.join("shared"), own.join("corpus"), own];
    let mut quality = true;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--filter" => filter = args.next().unwrap_or_default(),
            "--report" => dir = args.next().map(PathBuf::from),
            "--traces" => traces = args.next().map(PathBuf::from).into_iter().collect(),
            "--no-traces" => traces.clear(),
            "--no-quality" => quality = false,
            _ => {
                eprintln!("usage: conformance [--filter PATTERN] [--report DIR] [--traces DIR | --no-traces] [--no-quality]");
                return ExitCode::from(2);
            }
        }
    }
    let out = dir.clone().unwrap_or_else(|| {
        std::env::temp_dir().join(format!("tilegl-conformance-{}", std::process::id()))
    });
    let (page, entries) =
        match report::write_report(&out, &traces, &filter, quality && dir.is_some()) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("conformance: {e}");
                return ExitCode::from(2);
            }
        };
    for e in &entries {
        let d = e.diff.map_or("no picture".to_string(), |d| d.to_string());
        println!(
            "{:<14} {:<28} {:<48} {d} {}",
            format!("{:?}", e.verdict),
            e.area,
            e.name,
            e.note
        );
    }
    let fails = entries
        .iter()
        .filter(|e| e.verdict == Verdict::Fail)
        .count();
    println!(
        "{} entries, {} failed; report: {}",
        entries.len(),
        fails,
        if dir.is_some() {
            page.display().to_string()
        } else {
            "not kept (use --report DIR)".into()
        }
    );
    if dir.is_none() {
        let _ = std::fs::remove_dir_all(&out);
    }
    if fails > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

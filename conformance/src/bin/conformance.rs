//! `conformance [--filter PATTERN] [--report DIR] [--traces DIR] [--piglit MESA.tsv TILEGL.tsv]`: runs the differential
//! scenes (and, with a report, the captures of `conformance/traces/`) on tilegl and on Mesa
//! (llvmpipe, and softpipe in a child process), prints one line per entry and a summary, and
//! with `--report` writes the HTML report `DIR/index.html` and, unless `--no-quality`, the
//! error-against-run-time charts of every quality knob (`DIR/quality.html`). The state and
//! error cases run too; the report's piglit table comes from the committed record
//! `docs/piglit.md`, or from the two TSV files of a fresh run given with `--piglit` (piglit
//! itself is not run here). `tilegl conformance` runs this.
//! Exit status 1 when an entry fails.

use std::path::PathBuf;
use std::process::ExitCode;

use tilegl_conformance::compare;
use tilegl_conformance::report::{self, ReportOptions};
use tilegl_conformance::scenes::SCENES;

fn main() -> ExitCode {
    if compare::serve_child_request(&SCENES) {
        return ExitCode::SUCCESS;
    }
    let mut dir: Option<PathBuf> = None;
    let own = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("traces");
    let mut opts = ReportOptions {
        traces: vec![own.join("shared"), own.join("corpus"), own],
        quality: true,
        ..ReportOptions::default()
    };
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--filter" => opts.filter = args.next().unwrap_or_default(),
            "--report" => dir = args.next().map(PathBuf::from),
            "--traces" => opts.traces = args.next().map(PathBuf::from).into_iter().collect(),
            "--no-traces" => opts.traces.clear(),
            "--no-quality" => opts.quality = false,
            "--piglit" => match (args.next(), args.next()) {
                (Some(m), Some(t)) => opts.piglit_tsv = Some((m.into(), t.into())),
                _ => return usage(),
            },
            _ => return usage(),
        }
    }
    opts.quality &= dir.is_some();
    let out = dir.clone().unwrap_or_else(|| {
        std::env::temp_dir().join(format!("tilegl-conformance-{}", std::process::id()))
    });
    let (page, report) = match report::write_report(&out, &opts) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("conformance: {e}");
            return ExitCode::from(2);
        }
    };
    for e in &report.entries {
        let d = e.diff.map_or("no picture".to_string(), |d| d.to_string());
        println!(
            "{:<14} {:<28} {:<48} {d} {}",
            format!("{:?}", e.verdict),
            e.area,
            e.name,
            e.note
        );
    }
    for s in &report.states {
        let o = &s.outcome;
        println!(
            "{:<14} {:<28} {:<48} {} of {} answers agree with Mesa, C ABI {} {}",
            format!("{:?}", s.verdict),
            s.area,
            s.case.name,
            o.answers.iter().filter(|a| a.agrees).count(),
            o.answers.len(),
            if o.c_matches_rust {
                "= Rust API"
            } else {
                "DIFFERS from the Rust API"
            },
            s.note
        );
    }
    let fails = report.failures();
    println!(
        "{} entries, {} failed; report: {}",
        report.entries.len() + report.states.len(),
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

fn usage() -> ExitCode {
    eprintln!(
        "usage: conformance [--filter PATTERN] [--report DIR] [--traces DIR | --no-traces] \
         [--no-quality] [--piglit MESA.tsv TILEGL.tsv]"
    );
    ExitCode::from(2)
}

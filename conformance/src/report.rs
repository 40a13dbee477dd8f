//! The conformance report: every differential scene and every replayed capture of
//! `conformance/traces/` rendered on tilegl and on Mesa (llvmpipe in this process, softpipe in
//! a child), compared, timed, and written as an offline HTML page (`DIR/index.html`) with the
//! pictures, a difference image, the error figures, the limit each was held to and the
//! verdict; a summary per feature area at the top, failures first, columns sortable.

use std::fmt::Write as _;
use std::io::{IsTerminal, Write as _};
use std::path::{Path, PathBuf};
use std::time::Instant;

use tilegl::compare::{Diff, Tolerance};

use crate::compare::{self, diff, Image, Scene};
use crate::known_failures::{known_failure, mesa_less_exact};
use crate::mesa::{self, MesaContext, Oracle};
use crate::piglit;
use crate::state_cases::{self, StateCase, StateOutcome};

/// The verdict of one entry.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Verdict {
    Fail,
    KnownFailure,
    /// Differs from Mesa where Mesa is known to be less exact (the note says why and where
    /// tilegl's value is checked against the specification).
    MesaLessExact,
    Pass,
}

impl Verdict {
    fn label(self) -> &'static str {
        match self {
            Verdict::Fail => "FAIL",
            Verdict::KnownFailure => "known failure",
            Verdict::MesaLessExact => "Mesa less exact",
            Verdict::Pass => "pass",
        }
    }
}

/// One row of the report.
#[derive(Clone, Debug)]
pub struct Entry {
    /// Feature area (the scene list or "captures").
    pub area: &'static str,
    pub name: String,
    /// tilegl against the reference (Mesa llvmpipe).
    pub diff: Option<Diff>,
    /// llvmpipe against softpipe: Mesa's own spread.
    pub spread: Option<Diff>,
    pub limit: Tolerance,
    pub verdict: Verdict,
    /// Milliseconds: tilegl, llvmpipe, softpipe (including its process for scenes).
    pub times: [Option<f64>; 3],
    /// Files (relative to the report folder): tilegl, llvmpipe, softpipe, difference.
    pub pictures: [Option<String>; 4],
    /// Anything else worth saying (errors, missing pictures).
    pub note: String,
}

/// The scene lists and the area each belongs to, in report order.
pub fn scene_areas() -> Vec<(&'static str, &'static [Scene])> {
    crate::scenes::SCENE_LISTS.to_vec()
}

/// A progress line on the terminal (a bar when stderr is a terminal, a line every tenth
/// otherwise).
pub struct Progress {
    total: usize,
    done: usize,
    tty: bool,
}

impl Progress {
    pub fn new(total: usize) -> Progress {
        Progress {
            total,
            done: 0,
            tty: std::io::stderr().is_terminal(),
        }
    }

    pub fn step(&mut self, what: &str) {
        self.done += 1;
        let total = self.total.max(1);
        if self.tty {
            let filled = self.done * 30 / total;
            eprint!(
                "\r[{}{}] {}/{} {:<40.40}",
                "#".repeat(filled),
                ".".repeat(30 - filled.min(30)),
                self.done,
                self.total,
                what
            );
            if self.done == self.total {
                eprintln!();
            }
            let _ = std::io::stderr().flush();
        } else if self.done * 10 / total != (self.done - 1) * 10 / total || self.done == total {
            eprintln!("{}/{} {what}", self.done, self.total);
        }
    }
}

/// Writes an RGBA picture (rows bottom-up, as `glReadPixels` gives them) as a PNG.
pub(crate) fn save_png(image: &Image, path: &Path) -> Result<(), String> {
    let (w, h) = (image.width.max(0) as u32, image.height.max(0) as u32);
    let mut top_down = Vec::with_capacity(image.pixels.len());
    for y in (0..image.height).rev() {
        let row = (y * image.width * 4) as usize;
        top_down.extend_from_slice(&image.pixels[row..row + (image.width * 4) as usize]);
    }
    image::RgbaImage::from_raw(w, h, top_down)
        .ok_or_else(|| format!("{}: bad picture size", path.display()))?
        .save_with_format(path, image::ImageFormat::Png)
        .map_err(|e| format!("{}: {e}", path.display()))
}

/// The difference picture: each pixel's largest channel difference, black where equal, dim red
/// up to the threshold of 8, bright red to yellow beyond.
pub(crate) fn difference_image(a: &Image, b: &Image) -> Option<Image> {
    if a.width != b.width || a.height != b.height || a.pixels.len() != b.pixels.len() {
        return None;
    }
    let pixels = a
        .pixels
        .chunks_exact(4)
        .zip(b.pixels.chunks_exact(4))
        .flat_map(|(p, q)| {
            let d = (0..4).map(|i| p[i].abs_diff(q[i])).max().unwrap_or(0);
            match d {
                0 => [0, 0, 0, 255],
                1..=8 => [60 + d * 10, 0, 0, 255],
                _ => [255, d.saturating_mul(2), 0, 255],
            }
        })
        .collect();
    Some(Image {
        width: a.width,
        height: a.height,
        pixels,
    })
}

fn timed<R>(f: impl FnOnce() -> R) -> (R, f64) {
    let t = Instant::now();
    let r = f();
    (r, t.elapsed().as_secs_f64() * 1000.0)
}

/// Runs every scene whose name contains `filter` on tilegl and on Mesa (llvmpipe here,
/// softpipe in a child: this executable run again with `child_args`, which must reach a call
/// of [`compare::serve_child_request`]), writing the pictures into `dir`.
pub fn run_scenes(
    dir: &Path,
    filter: &str,
    progress: &mut Progress,
    child_args: &[&str],
) -> Vec<Entry> {
    let mesa_ok = mesa::mesa_available();
    let mut entries = Vec::new();
    for (area, scenes) in scene_areas() {
        for scene in scenes.iter().filter(|s| s.name.contains(filter)) {
            progress.step(scene.name);
            entries.push(run_scene(dir, area, scene, mesa_ok.is_ok(), child_args));
        }
    }
    entries
}

/// How many entries [`run_scenes`] will produce for `filter`.
pub fn scene_count(filter: &str) -> usize {
    scene_areas()
        .iter()
        .map(|(_, s)| s.iter().filter(|s| s.name.contains(filter)).count())
        .sum()
}

fn run_scene(
    dir: &Path,
    area: &'static str,
    scene: &Scene,
    with_mesa: bool,
    child_args: &[&str],
) -> Entry {
    let file = |tag: &str| format!("{}-{tag}.png", scene.name);
    let mut note = String::new();
    let (tilegl, t_ms) = timed(|| compare::render_tilegl(scene));
    let mut pictures: [Option<String>; 4] = Default::default();
    if save_png(&tilegl.image, &dir.join(file("tilegl"))).is_ok() {
        pictures[0] = Some(file("tilegl"));
    }
    let (mut llvmpipe, mut l_ms, mut softpipe, mut s_ms) = (None, None, None, None);
    if with_mesa {
        let (m, ms) = timed(|| {
            MesaContext::create(scene.width, scene.height).map(|mut c| {
                let r = compare::run_scene(&mut *c, scene);
                (r, c.info().clone())
            })
        });
        match m {
            Ok((r, info)) => {
                if info.driver() != "llvmpipe" {
                    note.push_str(&format!("in-process Mesa is {}; ", info.renderer));
                }
                if r.error != tilegl.error {
                    note.push_str(&format!(
                        "glGetError tilegl 0x{:04x}, Mesa 0x{:04x}; ",
                        tilegl.error, r.error
                    ));
                }
                llvmpipe = Some(r.image);
                l_ms = Some(ms);
            }
            Err(e) => note.push_str(&format!("llvmpipe: {e}; ")),
        }
        let (s, ms) = timed(|| compare::render_scene_with_driver("softpipe", scene, child_args));
        match s {
            Ok((image, _)) => {
                softpipe = Some(image);
                s_ms = Some(ms);
            }
            Err(e) => note.push_str(&format!("softpipe: {e}; ")),
        }
    } else {
        note.push_str("Mesa not available; ");
    }
    for (i, (img, tag)) in [(&llvmpipe, "llvmpipe"), (&softpipe, "softpipe")]
        .into_iter()
        .enumerate()
    {
        if let Some(img) = img {
            if save_png(img, &dir.join(file(tag))).is_ok() {
                pictures[i + 1] = Some(file(tag));
            }
        }
    }
    let d = llvmpipe
        .as_ref()
        .map(|m| diff(&tilegl.image, m, scene.tolerance.channel));
    if let Some(m) = &llvmpipe {
        if let Some(img) = difference_image(&tilegl.image, m) {
            if save_png(&img, &dir.join(file("diff"))).is_ok() {
                pictures[3] = Some(file("diff"));
            }
        }
    }
    let spread = match (&llvmpipe, &softpipe) {
        (Some(l), Some(s)) => Some(diff(l, s, scene.tolerance.channel)),
        _ => None,
    };
    let mesa_error_matches = !note.contains("glGetError");
    let passed = d.is_some_and(|d| scene.tolerance.accepts(&d)) && mesa_error_matches;
    let verdict = match (passed, known_failure(scene.name)) {
        (false, _) if mesa_less_exact(scene.name).is_some() && d.is_some() => {
            note.push_str(mesa_less_exact(scene.name).unwrap_or_default());
            Verdict::MesaLessExact
        }
        (true, _) if mesa_less_exact(scene.name).is_some() => {
            note.push_str("listed in MESA_LESS_EXACT but agrees with Mesa now: remove it");
            Verdict::Fail
        }
        (true, _) => Verdict::Pass,
        (false, Some(why)) => {
            note.push_str(why);
            Verdict::KnownFailure
        }
        (false, None) => Verdict::Fail,
    };
    // A scene held to its measured difference says which answer is exact and where that is
    // checked (scenes_extremes::NOTES).
    if let Some(why) = scene.note() {
        note.push_str(why);
    }
    Entry {
        area,
        name: scene.name.to_string(),
        diff: d,
        spread,
        limit: scene.tolerance,
        verdict,
        times: [Some(t_ms), l_ms, s_ms],
        pictures,
        note,
    }
}

/// Replays every capture of `traces` (`NAME.trace` with `NAME.frames/`) whose name contains
/// `filter` and compares its pictures with the references (Mesa llvmpipe's, and softpipe's
/// where recorded), one entry per picture.
pub fn run_captures(
    traces: &Path,
    dir: &Path,
    filter: &str,
    progress: &mut Progress,
) -> Vec<Entry> {
    let mut entries = Vec::new();
    // The folder's KNOWN_FAILURES.tsv, the list the capture tests hold it to.
    let (known, list_error) = match tilegl::replay::reference::known_failures(traces) {
        Ok(k) => (k, None),
        Err(e) => (Vec::new(), Some(e)),
    };
    for trace in capture_files(traces, filter) {
        let stem = trace
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        progress.step(&stem);
        let known_why = known.iter().find(|(n, _)| *n == stem).map(|(_, w)| w);
        // A failing picture of a listed capture is a known failure, with the list's reason.
        let verdict_of = |ok: bool, note: &mut String| match (ok, known_why) {
            (true, _) => Verdict::Pass,
            (false, Some(why)) => {
                note.push_str(&format!(" known failure: {why}"));
                Verdict::KnownFailure
            }
            (false, None) => {
                if let Some(e) = &list_error {
                    note.push_str(&format!(" ({e})"));
                }
                Verdict::Fail
            }
        };
        let frames = traces.join(format!("{stem}.frames"));
        let out = dir.join(format!("capture-{stem}"));
        let _ = std::fs::create_dir_all(&out);
        let start = Instant::now();
        let report = tilegl::replay::trace::TraceReader::open(&trace)
            .map_err(|e| e.to_string())
            .and_then(|mut r| {
                let mut player = tilegl::replay::player::Player::new(0);
                tilegl::replay::reference::compare_replay(
                    &mut r,
                    &mut player,
                    &frames,
                    Some(&out),
                    &mut |_| {},
                )
            });
        let ms = start.elapsed().as_secs_f64() * 1000.0;
        match report {
            Err(mut note) => entries.push(Entry {
                area: "captures",
                name: stem.clone(),
                diff: None,
                spread: None,
                limit: tilegl::compare::PROJECT,
                verdict: verdict_of(false, &mut note),
                times: [Some(ms), None, None],
                pictures: Default::default(),
                note,
            }),
            Ok(r) => {
                let n = r.pictures.len().max(1) as f64;
                for p in r.pictures {
                    let rel = |f: &str| format!("capture-{stem}/{f}");
                    let reference = format!("reference-{}", p.file);
                    let _ = std::fs::copy(frames.join(&p.file), out.join(&reference));
                    let sp = frames.join("softpipe").join(&p.file);
                    let softpipe = format!("softpipe-{}", p.file);
                    let has_sp = std::fs::copy(&sp, out.join(&softpipe)).is_ok();
                    let ours = out.join(&p.file).is_file().then(|| rel(&p.file));
                    let mut note = p.note;
                    let verdict = verdict_of(p.ok, &mut note);
                    entries.push(Entry {
                        area: "captures",
                        name: format!("{stem}/{}", p.file),
                        diff: p.diff,
                        spread: p.softpipe,
                        limit: p.tolerance,
                        verdict,
                        times: [Some(ms / n), None, None],
                        pictures: [
                            ours,
                            Some(rel(&reference)),
                            has_sp.then(|| rel(&softpipe)),
                            None,
                        ],
                        note,
                    });
                }
            }
        }
    }
    entries
}

/// The captures (`*.trace` with a `.frames` folder) of `traces` whose names contain `filter`.
pub fn capture_files(traces: &Path, filter: &str) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(traces)
        .map(|d| {
            d.filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|e| e == "trace"))
                .filter(|p| {
                    p.file_stem()
                        .is_some_and(|s| s.to_string_lossy().contains(filter))
                })
                .filter(|p| p.with_extension("frames").is_dir())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

pub(crate) fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn figure(v: Option<f64>, digits: usize) -> String {
    v.map_or("-".into(), |v| {
        if v.is_infinite() {
            "inf".into()
        } else {
            format!("{v:.digits$}")
        }
    })
}

/// Writes `dir/index.html` of picture entries only (no state cases, no piglit table).
pub fn write_html(dir: &Path, entries: &[Entry], mesa: &str) -> Result<PathBuf, String> {
    write_page(
        dir,
        &Report {
            entries: entries.to_vec(),
            states: Vec::new(),
            piglit: Err("not included in this report".into()),
            mesa: mesa.to_string(),
        },
    )
}

/// Writes `dir/index.html`: the summary per area, one row per picture entry (failures first),
/// the state and error cases, then the piglit table.
pub fn write_page(dir: &Path, report: &Report) -> Result<PathBuf, String> {
    let (entries, mesa) = (&report.entries, report.mesa.as_str());
    let mut rows: Vec<&Entry> = entries.iter().collect();
    rows.sort_by_key(|e| e.verdict);
    // (area, verdict) of every picture entry and state case.
    let all: Vec<(&str, Verdict)> = entries
        .iter()
        .map(|e| (e.area, e.verdict))
        .chain(report.states.iter().map(|s| (s.area, s.verdict)))
        .collect();
    let mut areas: Vec<&str> = Vec::new();
    for (a, _) in &all {
        if !areas.contains(a) {
            areas.push(a);
        }
    }
    let count = |area: Option<&str>, v: Verdict| {
        all.iter()
            .filter(|(a, verdict)| area.is_none_or(|x| *a == x) && *verdict == v)
            .count()
    };
    let mut h = String::new();
    h.push_str("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>tilegl conformance report</title>\n");
    h.push_str("<style>body{font-family:sans-serif;margin:1em}table{border-collapse:collapse}table.answers td{font-size:11px}pre{font-size:11px;background:#f4f4f4;padding:4px;max-width:900px;overflow:auto}td,th{border:1px solid #ccc;padding:2px 6px;font-size:13px}th{background:#eee;cursor:pointer}tr.FAIL{background:#fdd}tr.known{background:#ffd}tr.mesa{background:#def}td.note{max-width:360px;font-size:12px;overflow-wrap:anywhere}td.num{text-align:right}img{width:96px;image-rendering:pixelated;border:1px solid #999}</style>\n");
    h.push_str("<script>function sortBy(t,c){const b=t.tBodies[0];const r=[...b.rows];const d=t.dataset.col==c&&t.dataset.dir!='d';t.dataset.col=c;t.dataset.dir=d?'d':'a';r.sort((x,y)=>{const p=x.cells[c].dataset.v??x.cells[c].textContent,q=y.cells[c].dataset.v??y.cells[c].textContent;const a=parseFloat(p),e=parseFloat(q);const k=isNaN(a)||isNaN(e)?p.localeCompare(q):a-e;return d?-k:k});r.forEach(x=>b.appendChild(x))}</script>\n</head><body>\n");
    let _ = writeln!(
        h,
        "<h1>tilegl conformance report</h1>\n<p>{} entries (pictures and state cases): {} pass, {} fail, {} known failures, {} where Mesa is known to be less exact than tilegl (the note says why and where tilegl's value is checked against the specification). Reference: {}. A picture passes when at most the listed share of its pixels differs from Mesa llvmpipe's by more than the threshold in some channel (scenes: their own tolerance; captures: the project rule widened to llvmpipe's own difference from softpipe).</p>",
        all.len(),
        count(None, Verdict::Pass),
        count(None, Verdict::Fail),
        count(None, Verdict::KnownFailure),
        count(None, Verdict::MesaLessExact),
        esc(mesa)
    );
    if dir.join("quality.html").is_file() {
        h.push_str("<p><a href=\"quality.html\">Error against run time for every quality knob</a> (charts and tables, tilegl and Mesa llvmpipe).</p>\n");
    }
    h.push_str("<p>Sections: <a href=\"#summary\">summary</a>, <a href=\"#entries\">pictures</a>, <a href=\"#states\">state and error cases</a>, <a href=\"#piglit\">piglit</a>.</p>\n");
    h.push_str("<h2>Summary by feature area</h2>\n<table id=\"summary\"><thead><tr>");
    for (i, t) in [
        "area",
        "entries",
        "pass",
        "fail",
        "known failures",
        "Mesa less exact",
    ]
    .iter()
    .enumerate()
    {
        let _ = write!(
            h,
            "<th onclick=\"sortBy(document.getElementById('summary'),{i})\">{t}</th>"
        );
    }
    h.push_str("</tr></thead><tbody>\n");
    // Areas with failures first, then in report order.
    areas.sort_by_key(|a| {
        std::cmp::Reverse((
            count(Some(a), Verdict::Fail),
            count(Some(a), Verdict::KnownFailure),
        ))
    });
    for a in &areas {
        let n = all.iter().filter(|(x, _)| x == a).count();
        let _ = writeln!(
            h,
            "<tr class=\"{}\"><td>{}</td><td class=num>{n}</td><td class=num>{}</td><td class=num>{}</td><td class=num>{}</td><td class=num>{}</td></tr>",
            if count(Some(a), Verdict::Fail) > 0 {
                "FAIL"
            } else {
                "pass"
            },
            esc(a),
            count(Some(a), Verdict::Pass),
            count(Some(a), Verdict::Fail),
            count(Some(a), Verdict::KnownFailure),
            count(Some(a), Verdict::MesaLessExact)
        );
    }
    h.push_str("</tbody></table>\n<h2>Every scene and picture</h2>\n<p>Click a column heading to sort. Pictures: tilegl, Mesa llvmpipe, Mesa softpipe, difference (tilegl vs llvmpipe: dim red up to 8, bright beyond).</p>\n");
    h.push_str("<table id=\"entries\"><thead><tr>");
    let heads = [
        "verdict",
        "area",
        "name",
        "bad% &gt;8",
        "mean",
        "max",
        "PSNR dB",
        "limit",
        "llvmpipe vs softpipe bad%",
        "tilegl ms",
        "llvmpipe ms",
        "softpipe ms",
        "pictures",
        "note",
    ];
    for (i, t) in heads.iter().enumerate() {
        let _ = write!(
            h,
            "<th onclick=\"sortBy(document.getElementById('entries'),{i})\">{t}</th>"
        );
    }
    h.push_str("</tr></thead><tbody>\n");
    for e in rows {
        let class = match e.verdict {
            Verdict::Fail => "FAIL",
            Verdict::KnownFailure => "known",
            Verdict::MesaLessExact => "mesa",
            Verdict::Pass => "pass",
        };
        let d = e.diff.as_ref();
        let pics: String = e
            .pictures
            .iter()
            .zip(["tilegl", "llvmpipe", "softpipe", "difference"])
            .map(|(p, alt)| match p {
                Some(f) => format!(
                    "<a href=\"{0}\"><img src=\"{0}\" alt=\"{alt}\" title=\"{alt}\"></a>",
                    esc(f)
                ),
                None => String::new(),
            })
            .collect();
        let _ = writeln!(
            h,
            "<tr class=\"{class}\"><td data-v=\"{}\">{}</td><td>{}</td><td>{}</td><td class=num>{}</td><td class=num>{}</td><td class=num>{}</td><td class=num data-v=\"{}\">{}</td><td>{}</td><td class=num>{}</td><td class=num>{}</td><td class=num>{}</td><td class=num>{}</td><td>{pics}</td><td class=note>{}</td></tr>",
            e.verdict as u8,
            e.verdict.label(),
            esc(e.area),
            esc(&e.name),
            figure(d.map(|d| d.bad_share * 100.0), 3),
            figure(d.map(|d| d.mean), 3),
            d.map_or("-".into(), |d| d.max.to_string()),
            d.map_or(1e9, |d| if d.psnr.is_infinite() { 1e9 } else { d.psnr }),
            figure(d.map(|d| d.psnr), 2),
            esc(&e.limit.to_string()),
            figure(e.spread.map(|s| s.bad_share * 100.0), 3),
            figure(e.times[0], 1),
            figure(e.times[1], 1),
            figure(e.times[2], 1),
            esc(&e.note)
        );
    }
    h.push_str("</tbody></table>\n");
    write_states(&mut h, &report.states);
    write_piglit(&mut h, &report.piglit);
    h.push_str("</body></html>\n");
    let path = dir.join("index.html");
    std::fs::write(&path, h).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(path)
}

/// One state or error case in the report.
#[derive(Clone, Debug)]
pub struct StateEntry {
    pub area: &'static str,
    pub case: &'static StateCase,
    pub outcome: StateOutcome,
    pub verdict: Verdict,
    /// Why it failed, or the known-failure reason.
    pub note: String,
}

/// Runs every state and error case whose name contains `filter` on Mesa and on tilegl's Rust
/// API and C ABI.
pub fn run_state_cases(filter: &str, progress: &mut Progress) -> Vec<StateEntry> {
    let mut out = Vec::new();
    for (area, cases) in state_cases::STATE_CASE_LISTS {
        for case in cases.iter().filter(|c| c.name.contains(filter)) {
            progress.step(case.name);
            let outcome = std::panic::catch_unwind(|| (case.run)(case.name)).unwrap_or_else(|_| {
                StateOutcome {
                    mesa: Err("the case panicked".into()),
                    answers: Vec::new(),
                    c_matches_rust: false,
                    agrees_with_mesa: false,
                    times: [None; 3],
                    summary: format!("{} panicked", case.name),
                }
            });
            let (verdict, note) = match outcome.check(case.name) {
                Ok(_) if outcome.agrees_with_mesa => (Verdict::Pass, String::new()),
                Ok(_) => (
                    Verdict::KnownFailure,
                    known_failure(case.name).unwrap_or_default().to_string(),
                ),
                Err(e) => (Verdict::Fail, e),
            };
            out.push(StateEntry {
                area,
                case,
                outcome,
                verdict,
                note,
            });
        }
    }
    out
}

/// How many entries [`run_state_cases`] will produce for `filter`.
pub fn state_case_count(filter: &str) -> usize {
    state_cases::all()
        .filter(|c| c.name.contains(filter))
        .count()
}

fn write_states(h: &mut String, states: &[StateEntry]) {
    h.push_str("<h2 id=\"states\">State and error cases</h2>\n");
    if states.is_empty() {
        h.push_str("<p>None in this report.</p>\n");
        return;
    }
    h.push_str("<p>Each case is a script of GL calls that records its answers (queries, <code>glGetError</code> results, read-back values) in order; it runs on Mesa llvmpipe, on tilegl through the Rust API and on tilegl through its C ABI. The C ABI must give exactly the Rust API's answers; tilegl's must agree with Mesa's under the case's rule (exact, or the stated floating-point tolerance). Open a case for its calls and every answer.</p>\n<table id=\"states\"><thead><tr>");
    let heads = [
        "verdict",
        "area",
        "case",
        "expected (specification)",
        "answers agreeing with Mesa",
        "C ABI = Rust API",
        "tilegl ms",
        "tilegl C ABI ms",
        "llvmpipe ms",
        "calls and answers",
        "note",
    ];
    for (i, t) in heads.iter().enumerate() {
        let _ = write!(
            h,
            "<th onclick=\"sortBy(document.getElementById('states'),{i})\">{t}</th>"
        );
    }
    h.push_str("</tr></thead><tbody>\n");
    let mut rows: Vec<&StateEntry> = states.iter().collect();
    rows.sort_by_key(|s| s.verdict);
    for s in rows {
        let o = &s.outcome;
        let agreeing = o.answers.iter().filter(|a| a.agrees).count();
        let mut detail = format!(
            "<details><summary>{} calls, {} answers</summary><pre>{}</pre><table class=\"answers\"><tr><th>#</th><th>answer</th><th>Mesa</th><th>tilegl</th><th>tilegl C ABI</th></tr>",
            s.case.calls().lines().count(),
            o.answers.len(),
            esc(&s.case.calls())
        );
        for (i, a) in o.answers.iter().enumerate() {
            let cell = |v: &Option<String>| esc(v.as_deref().unwrap_or("(none)"));
            let _ = write!(
                detail,
                "<tr class=\"{}\"><td>{i}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
                if a.agrees { "pass" } else { "FAIL" },
                esc(&a.label),
                cell(&a.mesa),
                cell(&a.rust),
                cell(&a.c)
            );
        }
        detail.push_str("</table></details>");
        let _ = writeln!(
            h,
            "<tr class=\"{}\"><td data-v=\"{}\">{}</td><td>{}</td><td>{}</td><td>{}</td><td class=num data-v=\"{}\">{agreeing} / {}</td><td>{}</td><td class=num>{}</td><td class=num>{}</td><td class=num>{}</td><td>{detail}</td><td class=note>{}</td></tr>",
            match s.verdict {
                Verdict::Fail => "FAIL",
                Verdict::KnownFailure | Verdict::MesaLessExact => "known",
                Verdict::Pass => "pass",
            },
            s.verdict as u8,
            s.verdict.label(),
            esc(s.area),
            esc(s.case.name),
            esc(s.case.expect),
            agreeing as f64 / o.answers.len().max(1) as f64,
            o.answers.len(),
            if o.c_matches_rust { "yes" } else { "NO" },
            figure(o.times[0], 1),
            figure(o.times[1], 1),
            figure(o.times[2], 1),
            esc(&s.note)
        );
    }
    h.push_str("</tbody></table>\n");
}

fn write_piglit(h: &mut String, run: &Result<piglit::Run, String>) {
    h.push_str("<h2 id=\"piglit\">piglit's OpenGL 1.x tests: Mesa and tilegl</h2>\n");
    let run = match run {
        Ok(r) => r,
        Err(e) => {
            let _ = writeln!(h, "<p>No piglit table: {}.</p>", esc(e));
            return;
        }
    };
    let _ = writeln!(
        h,
        "<p>Not run for this report: the verdicts of the latest recorded run ({}), every test of piglit's <code>quick</code> profile in the groups <code>spec@!opengl 1.0</code> to <code>1.5</code>, run unmodified on the system's Mesa and on tilegl's <code>libGL.so.1</code>. {}</p>\n<p>To redo it (then pass the two TSV files with <code>--piglit MESA.tsv TILEGL.tsv</code>):</p><pre>{}</pre>",
        esc(&run.source),
        esc(&run.label),
        esc(run.redo.trim_end())
    );
    h.push_str("<table id=\"piglit-summary\"><thead><tr><th>Mesa</th><th>tilegl</th><th>tests</th></tr></thead><tbody>\n");
    for (m, t, n) in piglit::summary(&run.rows) {
        let _ = writeln!(
            h,
            "<tr><td>{}</td><td>{}</td><td class=num>{n}</td></tr>",
            esc(&m),
            esc(&t)
        );
    }
    h.push_str("</tbody></table>\n<p>Tests whose verdicts differ come first; click a heading to sort.</p>\n<table id=\"piglit-tests\"><thead><tr>");
    for (i, t) in [
        "piglit test",
        "Mesa verdict",
        "tilegl verdict",
        "tilegl's first message",
    ]
    .iter()
    .enumerate()
    {
        let _ = write!(
            h,
            "<th onclick=\"sortBy(document.getElementById('piglit-tests'),{i})\">{t}</th>"
        );
    }
    h.push_str("</tr></thead><tbody>\n");
    let mut rows: Vec<&piglit::Row> = run.rows.iter().collect();
    rows.sort_by_key(|r| r.mesa == r.tilegl);
    for r in rows {
        let class = match (r.mesa.as_str(), r.tilegl.as_str()) {
            (m, t) if m == t => "pass",
            ("pass", _) => "FAIL",
            _ => "known",
        };
        let _ = writeln!(
            h,
            "<tr class=\"{class}\"><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            esc(&r.test),
            esc(&r.mesa),
            esc(&r.tilegl),
            esc(&r.message)
        );
    }
    h.push_str("</tbody></table>\n");
}

/// Everything a report page shows.
#[derive(Clone, Debug)]
pub struct Report {
    /// Pictures: scenes and captures.
    pub entries: Vec<Entry>,
    pub states: Vec<StateEntry>,
    /// The piglit verdicts, or why there are none.
    pub piglit: Result<piglit::Run, String>,
    /// The reference Mesa's description.
    pub mesa: String,
}

impl Report {
    /// How many entries failed (pictures and state cases).
    pub fn failures(&self) -> usize {
        self.entries
            .iter()
            .map(|e| e.verdict)
            .chain(self.states.iter().map(|s| s.verdict))
            .filter(|v| *v == Verdict::Fail)
            .count()
    }
}

/// What goes into a report besides the pictures of the scenes.
#[derive(Clone, Debug, Default)]
pub struct ReportOptions {
    /// Folders of captures to replay.
    pub traces: Vec<PathBuf>,
    /// Only entries whose names contain this.
    pub filter: String,
    /// The error-against-run-time charts of every quality knob (`quality.html`).
    pub quality: bool,
    /// The two TSV files of a fresh piglit run (Mesa's, tilegl's) instead of the committed
    /// record.
    pub piglit_tsv: Option<(PathBuf, PathBuf)>,
}

/// The whole report (for a program whose `main` serves the softpipe child first): scenes, state
/// and error cases, and the captures of each folder of `opts.traces`, matching `opts.filter`,
/// into `dir`; the piglit table; with `opts.quality`, the error-against-run-time charts of
/// every quality knob too (`quality.html`, linked from the page). Returns the page and what
/// it shows.
pub fn write_report(dir: &Path, opts: &ReportOptions) -> Result<(PathBuf, Report), String> {
    let filter = opts.filter.as_str();
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let captures: usize = opts
        .traces
        .iter()
        .map(|t| capture_files(t, filter).len())
        .sum();
    let mut progress = Progress::new(scene_count(filter) + state_case_count(filter) + captures);
    let mut entries = run_scenes(dir, filter, &mut progress, &[]);
    let states = run_state_cases(filter, &mut progress);
    for t in &opts.traces {
        entries.extend(run_captures(t, dir, filter, &mut progress));
    }
    let mesa = match MesaContext::create(4, 4) {
        Ok(c) => c.info().to_string(),
        Err(e) => format!("Mesa unavailable ({e})"),
    };
    if opts.quality {
        crate::quality::write_quality(
            dir,
            &[],
            std::time::Duration::from_millis(200),
            mesa::mesa_available().is_ok(),
        )?;
    }
    let piglit = match &opts.piglit_tsv {
        Some((m, t)) => piglit::from_tsv(m, t),
        None => piglit::read_committed(),
    };
    let report = Report {
        entries,
        states,
        piglit,
        mesa,
    };
    let page = write_page(dir, &report)?;
    Ok((page, report))
}

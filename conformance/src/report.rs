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
use crate::known_failures::known_failure;
use crate::mesa::{self, MesaContext, Oracle};

/// The verdict of one entry.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Verdict {
    Fail,
    KnownFailure,
    Pass,
}

impl Verdict {
    fn label(self) -> &'static str {
        match self {
            Verdict::Fail => "FAIL",
            Verdict::KnownFailure => "known failure",
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
        (true, _) => Verdict::Pass,
        (false, Some(why)) => {
            note.push_str(why);
            Verdict::KnownFailure
        }
        (false, None) => Verdict::Fail,
    };
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
    for trace in capture_files(traces, filter) {
        let stem = trace
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        progress.step(&stem);
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
            Err(e) => entries.push(Entry {
                area: "captures",
                name: stem.clone(),
                diff: None,
                spread: None,
                limit: tilegl::compare::PROJECT,
                verdict: Verdict::Fail,
                times: [Some(ms), None, None],
                pictures: Default::default(),
                note: e,
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
                    entries.push(Entry {
                        area: "captures",
                        name: format!("{stem}/{}", p.file),
                        diff: p.diff,
                        spread: p.softpipe,
                        limit: p.tolerance,
                        verdict: if p.ok { Verdict::Pass } else { Verdict::Fail },
                        times: [Some(ms / n), None, None],
                        pictures: [
                            ours,
                            Some(rel(&reference)),
                            has_sp.then(|| rel(&softpipe)),
                            None,
                        ],
                        note: p.note,
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

/// Writes `dir/index.html`: the summary per area, then one row per entry (failures first).
pub fn write_html(dir: &Path, entries: &[Entry], mesa: &str) -> Result<PathBuf, String> {
    let mut rows: Vec<&Entry> = entries.iter().collect();
    rows.sort_by_key(|e| e.verdict);
    let mut areas: Vec<&str> = Vec::new();
    for e in entries {
        if !areas.contains(&e.area) {
            areas.push(e.area);
        }
    }
    let count = |area: Option<&str>, v: Verdict| {
        entries
            .iter()
            .filter(|e| area.is_none_or(|a| e.area == a) && e.verdict == v)
            .count()
    };
    let mut h = String::new();
    h.push_str("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>tilegl conformance report</title>\n");
    h.push_str("<style>body{font-family:sans-serif;margin:1em}table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 6px;font-size:13px}th{background:#eee;cursor:pointer}tr.FAIL{background:#fdd}tr.known{background:#ffd}td.num{text-align:right}img{width:96px;image-rendering:pixelated;border:1px solid #999}</style>\n");
    h.push_str("<script>function sortBy(t,c){const b=t.tBodies[0];const r=[...b.rows];const d=t.dataset.col==c&&t.dataset.dir!='d';t.dataset.col=c;t.dataset.dir=d?'d':'a';r.sort((x,y)=>{const p=x.cells[c].dataset.v??x.cells[c].textContent,q=y.cells[c].dataset.v??y.cells[c].textContent;const a=parseFloat(p),e=parseFloat(q);const k=isNaN(a)||isNaN(e)?p.localeCompare(q):a-e;return d?-k:k});r.forEach(x=>b.appendChild(x))}</script>\n</head><body>\n");
    let _ = writeln!(
        h,
        "<h1>tilegl conformance report</h1>\n<p>{} entries: {} pass, {} fail, {} known failures. Reference: {}. A picture passes when at most the listed share of its pixels differs from Mesa llvmpipe's by more than the threshold in some channel (scenes: their own tolerance; captures: the project rule widened to llvmpipe's own difference from softpipe).</p>",
        entries.len(),
        count(None, Verdict::Pass),
        count(None, Verdict::Fail),
        count(None, Verdict::KnownFailure),
        esc(mesa)
    );
    if dir.join("quality.html").is_file() {
        h.push_str("<p><a href=\"quality.html\">Error against run time for every quality knob</a> (charts and tables, tilegl and Mesa llvmpipe).</p>\n");
    }
    h.push_str("<h2>Summary by feature area</h2>\n<table id=\"summary\"><thead><tr><th>area</th><th>entries</th><th>pass</th><th>fail</th><th>known failures</th></tr></thead><tbody>\n");
    for a in &areas {
        let n = entries.iter().filter(|e| e.area == *a).count();
        let _ = writeln!(
            h,
            "<tr><td>{}</td><td class=num>{n}</td><td class=num>{}</td><td class=num>{}</td><td class=num>{}</td></tr>",
            esc(a),
            count(Some(a), Verdict::Pass),
            count(Some(a), Verdict::Fail),
            count(Some(a), Verdict::KnownFailure)
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
            "<tr class=\"{class}\"><td data-v=\"{}\">{}</td><td>{}</td><td>{}</td><td class=num>{}</td><td class=num>{}</td><td class=num>{}</td><td class=num data-v=\"{}\">{}</td><td>{}</td><td class=num>{}</td><td class=num>{}</td><td class=num>{}</td><td class=num>{}</td><td>{pics}</td><td>{}</td></tr>",
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
    h.push_str("</tbody></table>\n</body></html>\n");
    let path = dir.join("index.html");
    std::fs::write(&path, h).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(path)
}

/// The whole report (for a program whose `main` serves the softpipe child first): scenes, and
/// the captures of each folder of `traces`, matching `filter`, into `dir`; with `quality`, the
/// error-against-run-time charts of every quality knob too (`quality.html`, linked from the
/// page). Returns the page and the entries.
pub fn write_report(
    dir: &Path,
    traces: &[PathBuf],
    filter: &str,
    quality: bool,
) -> Result<(PathBuf, Vec<Entry>), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let captures: usize = traces.iter().map(|t| capture_files(t, filter).len()).sum();
    let mut progress = Progress::new(scene_count(filter) + captures);
    let mut entries = run_scenes(dir, filter, &mut progress, &[]);
    for t in traces {
        entries.extend(run_captures(t, dir, filter, &mut progress));
    }
    let mesa = match MesaContext::create(4, 4) {
        Ok(c) => c.info().to_string(),
        Err(e) => format!("Mesa unavailable ({e})"),
    };
    if quality {
        crate::quality::write_quality(
            dir,
            &[],
            std::time::Duration::from_millis(200),
            mesa::mesa_available().is_ok(),
        )?;
    }
    let page = write_html(dir, &entries, &mesa)?;
    Ok((page, entries))
}

//! The teaching gallery: every teaching scene (the technique scenes of
//! [`crate::scenes_techniques`], the scenes the examples in `examples/` render, and the
//! built-in scenes of the `tilegl` command) rendered on tilegl and on Mesa (llvmpipe), with the
//! difference, the intermediate stages each scene snaps, for multitexture scenes the output of
//! each texture unit of the cascade, and the text of what it teaches and which GL state does
//! it; written as an offline page `DIR/index.html` with its PNGs.
//!
//! Run by `tilegl gallery [DIR] [--scene NAME]... [--size WxH]` and by `cargo run --release`
//! (the `gallery` binary of this crate).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use tilegl::{ContextConfig, FramebufferConfig, Gl};

use crate::compare::{diff, Image, Scene};
use crate::example_support::{record, with_units, Stage};
use crate::mesa::{self, MesaContext, Oracle};
use crate::report::{difference_image, esc, save_png};
use crate::tolerance::Tolerance;

#[allow(dead_code)]
#[path = "../../src/bin/tilegl/scenes.rs"]
mod builtin;

/// How an entry draws.
#[derive(Clone, Copy)]
pub enum Draw {
    /// A differential scene (fixed size, its own tolerance).
    Scene(&'static Scene),
    /// A built-in scene of the `tilegl` command (drawn for any size).
    Builtin(fn(&mut dyn Gl, i32, i32)),
}

/// One gallery entry.
#[derive(Clone)]
pub struct Entry {
    pub name: String,
    pub title: String,
    /// Where it comes from: "technique", "example NAME" or "built-in".
    pub source: String,
    /// What it teaches (paragraphs).
    pub teaches: Vec<String>,
    /// The GL state that does it (empty when the text says it inline).
    pub state: String,
    pub width: i32,
    pub height: i32,
    pub tolerance: Tolerance,
    pub draw: Draw,
    /// Stage view of the texture cascade: pictures with units `0..k` enabled for each `k` in
    /// this range (the last, all units, is the final picture).
    pub cascade: Option<std::ops::Range<usize>>,
}

/// Multitexture scenes and the unit counts of their stage views (see
/// [`crate::example_support::unit_on`]).
pub const CASCADES: &[(&str, std::ops::Range<usize>)] = &[
    ("ex_lightmap_multitexture", 1..2),
    ("ex_decal", 1..2),
    ("ex_texture_matrix_animation", 1..2),
    ("ex_detail_texture", 1..2),
    ("ex_phong_highlight_texture", 0..2),
];

/// The examples' sources: their doc comments are the scenes' texts.
const EXAMPLES: &[(&str, &str)] = &[
    ("mipmapping", include_str!("../../examples/mipmapping.rs")),
    ("wrap_modes", include_str!("../../examples/wrap_modes.rs")),
    (
        "dxt_compression",
        include_str!("../../examples/dxt_compression.rs"),
    ),
    ("light_map", include_str!("../../examples/light_map.rs")),
    ("gloss_map", include_str!("../../examples/gloss_map.rs")),
    ("sphere_map", include_str!("../../examples/sphere_map.rs")),
    ("cube_map", include_str!("../../examples/cube_map.rs")),
    ("emboss_bump", include_str!("../../examples/emboss_bump.rs")),
    ("dot3_bump", include_str!("../../examples/dot3_bump.rs")),
    (
        "projective_texture",
        include_str!("../../examples/projective_texture.rs"),
    ),
    ("shadow_map", include_str!("../../examples/shadow_map.rs")),
    ("contour", include_str!("../../examples/contour.rs")),
    ("volume_3d", include_str!("../../examples/volume_3d.rs")),
    ("text", include_str!("../../examples/text.rs")),
    ("cross_tree", include_str!("../../examples/cross_tree.rs")),
    ("decal", include_str!("../../examples/decal.rs")),
    ("fog", include_str!("../../examples/fog.rs")),
    (
        "planar_reflection",
        include_str!("../../examples/planar_reflection.rs"),
    ),
    ("hsv_lookup", include_str!("../../examples/hsv_lookup.rs")),
    ("motion_blur", include_str!("../../examples/motion_blur.rs")),
    (
        "points_lines",
        include_str!("../../examples/points_lines.rs"),
    ),
];

/// The scenes an example renders (the string literals of its `example_support::run` call
/// after the example's own name) and its doc comment split into title and paragraphs (up to
/// the "Run:" paragraph).
pub fn parse_example(source: &str) -> (Vec<String>, String, Vec<String>) {
    let scenes = source
        .find("example_support::run(")
        .map(|i| {
            let call = &source[i..];
            let call = &call[..call.find(");").unwrap_or(call.len())];
            call.split('"')
                .skip(1)
                .step_by(2)
                .skip(1)
                .map(str::to_string)
                .collect()
        })
        .unwrap_or_default();
    let mut paragraphs = vec![String::new()];
    for line in source.lines() {
        let Some(text) = line.trim_start().strip_prefix("//!") else {
            continue;
        };
        let text = text.trim();
        if text.is_empty() {
            paragraphs.push(String::new());
            continue;
        }
        let p = paragraphs.last_mut().unwrap();
        if text.starts_with("- ") && !p.is_empty() {
            p.push('\n');
        } else if !p.is_empty() {
            p.push(' ');
        }
        p.push_str(text);
    }
    paragraphs.retain(|p| !p.is_empty());
    if let Some(i) = paragraphs.iter().position(|p| p.starts_with("Run:")) {
        paragraphs.truncate(i);
    }
    let title = if paragraphs.is_empty() {
        String::new()
    } else {
        paragraphs.remove(0)
    };
    (scenes, title, paragraphs)
}

fn cascade_of(name: &str) -> Option<std::ops::Range<usize>> {
    CASCADES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, r)| r.clone())
}

/// Every gallery entry: the technique scenes, the examples' scenes (and any example scene no
/// example names), then the built-in scenes.
pub fn entries() -> Vec<Entry> {
    let scene_entry =
        |s: &'static Scene, title: &str, source: String, teaches, state: &str| Entry {
            name: s.name.to_string(),
            title: title.to_string(),
            source,
            teaches,
            state: state.to_string(),
            width: s.width,
            height: s.height,
            tolerance: s.tolerance,
            draw: Draw::Scene(s),
            cascade: cascade_of(s.name),
        };
    let mut out = Vec::new();
    for s in crate::scenes_techniques::TECHNIQUE_SCENES {
        let (_, title, teaches, state) = crate::scenes_techniques::TECHNIQUE_TEXTS
            .iter()
            .find(|t| t.0 == s.name)
            .copied()
            .unwrap_or((s.name, s.name, "", ""));
        out.push(scene_entry(
            s,
            title,
            "technique".into(),
            vec![teaches.to_string()],
            state,
        ));
    }
    for (example, source) in EXAMPLES {
        let (scenes, title, teaches) = parse_example(source);
        for name in scenes {
            if let Some(s) = crate::scenes::find(&name) {
                out.push(scene_entry(
                    s,
                    &title,
                    format!("example {example}"),
                    teaches.clone(),
                    "",
                ));
            }
        }
    }
    for s in crate::scenes_examples::EXAMPLE_SCENES {
        if !out.iter().any(|e| e.name == s.name) {
            out.push(scene_entry(s, s.name, "example scene".into(), vec![], ""));
        }
    }
    for b in builtin::SCENES {
        out.push(Entry {
            name: b.name.to_string(),
            title: b.name.replace('_', " "),
            source: "built-in".into(),
            teaches: vec![b.about.to_string()],
            state: String::new(),
            width: b.width,
            height: b.height,
            tolerance: crate::tolerance::DIFFERENTIAL,
            draw: Draw::Builtin(b.draw),
            cascade: None,
        });
    }
    out
}

/// One implementation's pictures of an entry.
pub struct Pictures {
    pub image: Image,
    pub stages: Vec<Stage>,
    /// Pictures with the first `k` units of the cascade enabled, for each `k` of the entry's
    /// cascade range.
    pub cascade: Vec<(usize, Image)>,
    pub error: u32,
    pub ms: f64,
}

fn draw_on(gl: &mut dyn Gl, entry: &Entry, w: i32, h: i32) -> (Image, u32) {
    match entry.draw {
        // A scene drawn at another size than its own: its viewports and scissor boxes scale
        // with the window (see `example_support::with_frame_scale`).
        Draw::Scene(s) => crate::example_support::with_frame_scale(
            w as f64 / s.width as f64,
            h as f64 / s.height as f64,
            || (s.draw)(gl),
        ),
        Draw::Builtin(f) => f(gl, w, h),
    }
    let error = gl.get_error();
    gl.finish();
    (Image::read(gl, w, h), error)
}

/// What is drawn on a context.
type Job<'a> = &'a mut dyn FnMut(&mut dyn Gl);
/// Runs a job on a fresh `w` x `h` context of one implementation.
type WithContext<'a> = &'a mut dyn FnMut(i32, i32, Job) -> Result<(), String>;

/// Renders an entry on fresh contexts from `with` (`size` overrides the entry's size).
fn render(entry: &Entry, size: (i32, i32), with: WithContext) -> Result<Pictures, String> {
    let (w, h) = size;
    let start = Instant::now();
    let mut result = None;
    with(w, h, &mut |gl| {
        result = Some(record(|| draw_on(gl, entry, w, h)))
    })?;
    let ms = start.elapsed().as_secs_f64() * 1000.0;
    let ((image, error), stages) = result.ok_or("nothing rendered")?;
    let mut cascade = Vec::new();
    if let Some(range) = entry.cascade.clone() {
        for k in range {
            let mut img = None;
            with(w, h, &mut |gl| {
                img = Some(with_units(k, || draw_on(gl, entry, w, h).0))
            })?;
            cascade.push((k, img.ok_or("nothing rendered")?));
        }
    }
    Ok(Pictures {
        image,
        stages,
        cascade,
        error,
        ms,
    })
}

fn with_tilegl(threads: usize) -> impl FnMut(i32, i32, Job) -> Result<(), String> {
    move |w, h, f| {
        let mut ctx = crate::client_context(ContextConfig {
            width: w,
            height: h,
            framebuffer: FramebufferConfig {
                accum_bits: 16,
                ..FramebufferConfig::default()
            },
            threads,
        });
        f(&mut ctx);
        Ok(())
    }
}

fn with_mesa(w: i32, h: i32, f: Job) -> Result<(), String> {
    let mut m = MesaContext::create(w, h).map_err(|e| e.to_string())?;
    f(&mut *m);
    Ok(())
}

/// Options of a gallery run.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// Only these entries (all when empty).
    pub only: Vec<String>,
    /// Framebuffer size for every entry instead of its own.
    pub size: Option<(i32, i32)>,
    /// tilegl shading threads (0: one per core).
    pub threads: usize,
    /// Skip Mesa even where it is installed.
    pub no_mesa: bool,
}

/// What one entry came to.
pub struct Outcome {
    pub entry: Entry,
    pub tilegl: Pictures,
    pub mesa: Result<Pictures, String>,
}

/// Renders the chosen entries. Unknown names are an error listing the known ones.
pub fn run(opts: &Options) -> Result<Vec<Outcome>, String> {
    let all = entries();
    if let Some(unknown) = opts
        .only
        .iter()
        .find(|n| !all.iter().any(|e| &e.name == *n))
    {
        let names: Vec<&str> = all.iter().map(|e| e.name.as_str()).collect();
        return Err(format!(
            "no gallery scene `{unknown}`; there are: {}",
            names.join(", ")
        ));
    }
    let mesa_ok = if opts.no_mesa {
        Err("not asked for (--no-mesa)".to_string())
    } else {
        mesa::mesa_available().map_err(|e| e.to_string())
    };
    let chosen: Vec<Entry> = all
        .into_iter()
        .filter(|e| opts.only.is_empty() || opts.only.contains(&e.name))
        .collect();
    let mut progress = crate::report::Progress::new(chosen.len());
    let mut out = Vec::new();
    for entry in chosen {
        let size = opts.size.unwrap_or((entry.width, entry.height));
        let threads = opts.threads;
        let tilegl = render(&entry, size, &mut with_tilegl(threads))?;
        let mesa = match &mesa_ok {
            Ok(()) => render(&entry, size, &mut with_mesa),
            Err(e) => Err(format!("Mesa not available: {e}")),
        };
        progress.step(&entry.name);
        out.push(Outcome {
            entry,
            tilegl,
            mesa,
        });
    }
    Ok(out)
}

/// Paragraph text as HTML: escaped, `code` in backticks, "- " lines as a list.
fn prose(text: &str) -> String {
    let code = |s: &str| {
        let mut out = String::new();
        for (i, part) in esc(s).split('`').enumerate() {
            if i % 2 == 1 {
                let _ = write!(out, "<code>{part}</code>");
            } else {
                out.push_str(part);
            }
        }
        out
    };
    let lines: Vec<&str> = text.lines().collect();
    if lines.iter().all(|l| l.starts_with("- ")) {
        let items: String = lines
            .iter()
            .map(|l| format!("<li>{}</li>", code(&l[2..])))
            .collect();
        format!("<ul>{items}</ul>")
    } else {
        format!("<p>{}</p>", code(text))
    }
}

fn figure(out: &mut String, src: &str, caption: &str) {
    let _ = write!(
        out,
        "<figure><img src=\"{}\" alt=\"{}\"><figcaption>{}</figcaption></figure>",
        esc(src),
        esc(caption),
        esc(caption)
    );
}

/// Writes the pictures and `dir/index.html`; returns the page's path.
pub fn write(dir: &Path, outcomes: &[Outcome]) -> Result<PathBuf, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut body = String::new();
    let mut toc = String::new();
    let mut within = 0;
    let mut compared = 0;
    let mut renderer = String::new();
    for o in outcomes {
        let e = &o.entry;
        let n = &e.name;
        let png = |suffix: &str| format!("{n}-{suffix}.png");
        let save = |img: &Image, file: &str| save_png(img, &dir.join(file));
        save(&o.tilegl.image, &png("tilegl"))?;
        let mut verdict = String::from("Mesa not rendered");
        let mut class = "none";
        if let Ok(m) = &o.mesa {
            save(&m.image, &png("mesa"))?;
            if let Some(d) = difference_image(&o.tilegl.image, &m.image) {
                save(&d, &png("diff"))?;
            }
            let d = diff(&o.tilegl.image, &m.image, e.tolerance.channel);
            let ok = e.tolerance.accepts(&d) && o.tilegl.error == m.error;
            compared += 1;
            within += ok as usize;
            class = if ok { "ok" } else { "off" };
            verdict = format!(
                "{}: {:.2} % of pixels off by more than {} (limit {:.2} %), max {}, PSNR {} dB",
                if ok {
                    "within tolerance"
                } else {
                    "OUTSIDE tolerance"
                },
                d.bad_share * 100.0,
                e.tolerance.channel,
                e.tolerance.max_bad_share * 100.0,
                d.max,
                if d.psnr.is_finite() {
                    format!("{:.1}", d.psnr)
                } else {
                    "inf".into()
                }
            );
        }
        if renderer.is_empty() && o.mesa.is_ok() {
            if let Ok((info, _)) = mesa::oracle_identity() {
                renderer = info.to_string();
            }
        }
        let short: String = e.title.chars().take(48).collect();
        let _ = write!(
            toc,
            "<li><a href=\"#{0}\"><code>{0}</code></a> {1}{2} <span class=\"{class}\">&#9679;</span></li>",
            esc(n),
            esc(&short),
            if short.len() < e.title.len() { "..." } else { "" }
        );
        let _ = write!(
            body,
            "<section class=\"scene\" id=\"{0}\"><h2>{1}</h2><p class=\"meta\"><code>{0}</code> \
             &middot; {2} &middot; {3}x{4} &middot; tilegl {5:.1} ms",
            esc(n),
            esc(&e.title),
            esc(&e.source),
            o.tilegl.image.width,
            o.tilegl.image.height,
            o.tilegl.ms
        );
        if let Ok(m) = &o.mesa {
            let _ = write!(body, " &middot; Mesa {:.1} ms", m.ms);
        }
        let _ = write!(
            body,
            "</p>{}",
            e.teaches.iter().map(|p| prose(p)).collect::<String>()
        );
        if !e.state.is_empty() {
            let _ = write!(
                body,
                "<p class=\"state\"><b>GL state:</b> {}</p>",
                esc(&e.state)
            );
        }
        body.push_str("<div class=\"row\">");
        figure(&mut body, &png("tilegl"), "tilegl");
        match &o.mesa {
            Ok(_) => {
                figure(&mut body, &png("mesa"), "Mesa (llvmpipe)");
                figure(&mut body, &png("diff"), "difference");
            }
            Err(err) => {
                let _ = write!(body, "<p class=\"none\">{}</p>", esc(err));
            }
        }
        if matches!(e.draw, Draw::Builtin(_)) && o.mesa.is_ok() {
            verdict.push_str(" (a built-in scene, not one of the differential tests)");
        }
        let _ = write!(body, "</div><p class=\"{class}\">{}</p>", esc(&verdict));
        if !o.tilegl.cascade.is_empty() {
            body.push_str("<h3>Texture cascade, unit by unit</h3><div class=\"row\">");
            let mesa_cascade = o.mesa.as_ref().map(|m| &m.cascade[..]).unwrap_or(&[]);
            for (i, (k, img)) in o.tilegl.cascade.iter().enumerate() {
                let f = png(&format!("units{k}-tilegl"));
                save(img, &f)?;
                let what = if *k == 0 {
                    "no texture unit".to_string()
                } else {
                    format!("units 0..{} (output of unit {})", k - 1, k - 1)
                };
                figure(&mut body, &f, &format!("{what}, tilegl"));
                if let Some((_, m)) = mesa_cascade.get(i) {
                    let f = png(&format!("units{k}-mesa"));
                    save(m, &f)?;
                    figure(&mut body, &f, &format!("{what}, Mesa"));
                }
            }
            body.push_str("</div>");
        }
        if !o.tilegl.stages.is_empty() {
            body.push_str("<h3>Stages</h3><div class=\"row\">");
            let mesa_stages = o.mesa.as_ref().map(|m| &m.stages[..]).unwrap_or(&[]);
            for (i, s) in o.tilegl.stages.iter().enumerate() {
                let f = png(&format!("stage{:02}-{}-tilegl", i + 1, s.name));
                save(&s.image, &f)?;
                figure(&mut body, &f, &format!("{}, tilegl", s.name));
                if let Some(m) = mesa_stages.get(i) {
                    let f = png(&format!("stage{:02}-{}-mesa", i + 1, m.name));
                    save(&m.image, &f)?;
                    figure(&mut body, &f, &format!("{}, Mesa", m.name));
                }
            }
            body.push_str("</div>");
        }
        body.push_str("</section>\n");
    }
    let mut html = String::new();
    let _ = write!(
        html,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>tilegl teaching gallery</title><style>\
         body{{font-family:sans-serif;margin:1.5em;background:#fafafa;color:#222;max-width:1400px}}\
         h1{{margin-bottom:0.2em}} .scene{{background:#fff;border:1px solid #ddd;border-radius:6px;\
         padding:0.6em 1em;margin:1em 0}} .row{{display:flex;flex-wrap:wrap;gap:10px;align-items:flex-start}}\
         figure{{margin:0}} figure img{{image-rendering:pixelated;border:1px solid #ccc;max-width:400px}}\
         figcaption{{font-size:0.8em;color:#555}} .meta{{color:#666;font-size:0.85em}}\
         .state{{font-size:0.9em;background:#f3f3f8;padding:0.4em}} .ok{{color:#17802f}} .off{{color:#c0261b}}\
         .none{{color:#888}} ul.toc{{columns:2;font-size:0.85em}}</style></head><body>\
         <h1>tilegl teaching gallery</h1><p>{} scenes of fixed-function texturing and rendering \
         techniques, each drawn by the same GL calls on tilegl and on Mesa ({}); {} of {} compared \
         are within their differential tolerance. The difference picture is black where equal, \
         dark red up to 8/255, bright red to yellow beyond.</p><ul class=\"toc\">{}</ul>{}</body></html>\n",
        outcomes.len(),
        if renderer.is_empty() {
            "not rendered".to_string()
        } else {
            esc(&renderer)
        },
        within,
        compared,
        toc,
        body
    );
    let path = dir.join("index.html");
    std::fs::write(&path, html).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(path)
}

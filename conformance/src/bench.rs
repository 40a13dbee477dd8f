//! The triangle benchmark: 100k random small smooth-shaded, depth-tested triangles per frame at
//! 1024x768, on tilegl (1 and 2 threads) and Mesa (llvmpipe and softpipe, the driver that is
//! not the one of this process through a child process), with ms/frame, the ratio to tilegl and
//! the image error between the implementations.
//!
//! Shared by `cargo run --release -p tilegl-conformance --bin bench` and
//! `cargo bench -p tilegl-conformance --bench triangles`.

use std::time::{Duration, Instant};

use tilegl::enums::*;
use tilegl::{Context, ContextConfig, Gl};

use crate::compare::{diff, Image};
use crate::mesa::{self, MesaContext, Oracle, OracleInfo};
use crate::prng::XorShift;

/// Benchmark parameters.
#[derive(Clone, Debug)]
pub struct BenchConfig {
    pub width: i32,
    pub height: i32,
    pub triangles: usize,
    /// Timed frames per implementation (the median is reported); one untimed warm-up frame
    /// comes first.
    pub frames: usize,
    /// Stop adding timed frames once an implementation has used this much time (at least one
    /// timed frame always runs).
    pub budget: Duration,
    pub seed: u64,
}

impl Default for BenchConfig {
    fn default() -> Self {
        BenchConfig {
            width: 1024,
            height: 768,
            triangles: 100_000,
            frames: 5,
            budget: Duration::from_secs(15),
            seed: 0x5EED_1234_ABCD_0001,
        }
    }
}

/// One vertex: window-space position (pixels, z in [-1, 1]) and colour.
#[derive(Clone, Copy, Debug)]
pub struct BenchVertex {
    pub pos: [f32; 3],
    pub color: [f32; 3],
}

/// The fixed-seed random triangles: each within a ~16-pixel box anywhere on the screen, with
/// a random depth slope and three random vertex colours.
pub fn triangles(cfg: &BenchConfig) -> Vec<BenchVertex> {
    let mut rng = XorShift::new(cfg.seed);
    let mut out = Vec::with_capacity(cfg.triangles * 3);
    for _ in 0..cfg.triangles {
        let cx = rng.range(-8.0, cfg.width as f32 + 8.0);
        let cy = rng.range(-8.0, cfg.height as f32 + 8.0);
        let cz = rng.range(-0.95, 0.95);
        for _ in 0..3 {
            out.push(BenchVertex {
                pos: [
                    cx + rng.range(-9.0, 9.0),
                    cy + rng.range(-9.0, 9.0),
                    (cz + rng.range(-0.04, 0.04)).clamp(-1.0, 1.0),
                ],
                color: [rng.next_f32(), rng.next_f32(), rng.next_f32()],
            });
        }
    }
    out
}

/// The state set once per context.
pub fn setup(gl: &mut dyn Gl, cfg: &BenchConfig) {
    gl.viewport(0, 0, cfg.width, cfg.height);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, cfg.width as f64, 0.0, cfg.height as f64, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_LESS);
    gl.shade_model(GL_SMOOTH);
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear_depth(1.0);
}

/// One frame: clear, all triangles in immediate mode, glFinish.
pub fn frame(gl: &mut dyn Gl, verts: &[BenchVertex]) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.begin(GL_TRIANGLES);
    for v in verts {
        gl.color_3fv(&v.color);
        gl.vertex_3fv(&v.pos);
    }
    gl.end();
    gl.finish();
}

/// Timings and final picture of one implementation.
#[derive(Clone, Debug)]
pub struct BenchResult {
    pub name: String,
    /// Milliseconds of each timed frame.
    pub frame_ms: Vec<f64>,
    pub image: Image,
    pub error: GLenum,
}

impl BenchResult {
    /// Median ms/frame.
    pub fn median_ms(&self) -> f64 {
        let mut v = self.frame_ms.clone();
        v.sort_by(f64::total_cmp);
        if v.is_empty() {
            return f64::NAN;
        }
        let n = v.len();
        if n % 2 == 1 {
            v[n / 2]
        } else {
            (v[n / 2 - 1] + v[n / 2]) / 2.0
        }
    }
}

/// Runs the warm-up and timed frames on `gl`.
pub fn run_frames(
    name: &str,
    gl: &mut dyn Gl,
    cfg: &BenchConfig,
    verts: &[BenchVertex],
) -> BenchResult {
    setup(gl, cfg);
    frame(gl, verts);
    let mut frame_ms = Vec::new();
    let start = Instant::now();
    while frame_ms.len() < cfg.frames.max(1) {
        let t = Instant::now();
        frame(gl, verts);
        frame_ms.push(t.elapsed().as_secs_f64() * 1000.0);
        if start.elapsed() > cfg.budget {
            break;
        }
    }
    let error = gl.get_error();
    let image = Image::read(gl, cfg.width, cfg.height);
    BenchResult {
        name: name.to_string(),
        frame_ms,
        image,
        error,
    }
}

/// tilegl with `threads` worker threads.
pub fn run_tilegl(cfg: &BenchConfig, verts: &[BenchVertex], threads: usize) -> BenchResult {
    let mut ctx = Context::with_config(ContextConfig {
        width: cfg.width,
        height: cfg.height,
        threads,
        ..ContextConfig::default()
    });
    run_frames(&format!("tilegl {threads}T"), &mut ctx, cfg, verts)
}

/// Mesa in this process (its driver is fixed by `GALLIUM_DRIVER` at the first context).
pub fn run_mesa(
    cfg: &BenchConfig,
    verts: &[BenchVertex],
) -> Result<(BenchResult, OracleInfo), String> {
    let mut mesa = MesaContext::create(cfg.width, cfg.height).map_err(|e| e.to_string())?;
    let info = mesa.info().clone();
    let mut r = run_frames("mesa", &mut *mesa, cfg, verts);
    r.name = format!("mesa {}", info.driver());
    Ok((r, info))
}

const CHILD_ARG: &str = "--mesa-child";

fn encode_result(r: &BenchResult) -> Vec<u8> {
    let header = format!(
        "{}\n{}\n{}\n",
        r.name,
        r.error,
        r.frame_ms
            .iter()
            .map(|m| m.to_string())
            .collect::<Vec<_>>()
            .join(",")
    );
    let mut out = header.into_bytes();
    out.extend_from_slice(&r.image.to_bytes());
    out
}

fn decode_result(b: &[u8]) -> Option<BenchResult> {
    let mut lines = Vec::new();
    let mut rest = b;
    for _ in 0..3 {
        let nl = rest.iter().position(|&c| c == b'\n')?;
        lines.push(String::from_utf8_lossy(&rest[..nl]).into_owned());
        rest = &rest[nl + 1..];
    }
    Some(BenchResult {
        name: lines[0].clone(),
        error: lines[1].parse().ok()?,
        frame_ms: lines[2].split(',').filter_map(|s| s.parse().ok()).collect(),
        image: Image::from_bytes(rest)?,
    })
}

/// Mesa with another Gallium driver, in a child run of the current executable.
pub fn run_mesa_subprocess(
    driver: &str,
    cfg: &BenchConfig,
    extra_args: &[&str],
) -> Result<BenchResult, String> {
    let out =
        std::env::temp_dir().join(format!("tilegl-bench-{}-{driver}.raw", std::process::id()));
    let out_s = out.to_string_lossy().into_owned();
    let frames = cfg.frames.to_string();
    let tris = cfg.triangles.to_string();
    let budget = cfg.budget.as_secs_f64().to_string();
    let mut args: Vec<&str> = extra_args.to_vec();
    args.extend_from_slice(&[
        CHILD_ARG,
        &out_s,
        "--frames",
        &frames,
        "--triangles",
        &tris,
        "--budget",
        &budget,
    ]);
    mesa::run_self_with_driver(driver, &args, &[]).map_err(|e| e.to_string())?;
    let bytes = std::fs::read(&out).map_err(|e| e.to_string())?;
    let _ = std::fs::remove_file(&out);
    decode_result(&bytes).ok_or_else(|| "bad result from bench child".to_string())
}

fn parse_args(args: &[String], cfg: &mut BenchConfig) -> Option<String> {
    let mut child_out = None;
    let mut i = 0;
    while i < args.len() {
        let next = args.get(i + 1);
        match (args[i].as_str(), next) {
            (CHILD_ARG, Some(p)) => {
                child_out = Some(p.clone());
                i += 1;
            }
            ("--frames", Some(v)) => {
                cfg.frames = v.parse().unwrap_or(cfg.frames);
                i += 1;
            }
            ("--triangles", Some(v)) => {
                cfg.triangles = v.parse().unwrap_or(cfg.triangles);
                i += 1;
            }
            ("--budget", Some(v)) => {
                if let Ok(s) = v.parse::<f64>() {
                    cfg.budget = Duration::from_secs_f64(s.max(0.0));
                }
                i += 1;
            }
            _ => {}
        }
        i += 1;
    }
    child_out
}

/// The benchmark's command line: `[--frames N] [--triangles N] [--budget SECONDS]`. Prints the
/// table and returns the process exit code.
pub fn run_cli() -> i32 {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut cfg = BenchConfig::default();
    let child_out = parse_args(&args, &mut cfg);
    let verts = triangles(&cfg);
    if let Some(out) = child_out {
        // Child mode: Mesa with the driver the parent selected.
        return match run_mesa(&cfg, &verts) {
            Ok((r, _)) => match std::fs::write(&out, encode_result(&r)) {
                Ok(()) => 0,
                Err(e) => {
                    eprintln!("bench child: {e}");
                    3
                }
            },
            Err(e) => {
                eprintln!("bench child: {e}");
                2
            }
        };
    }

    println!(
        "tilegl triangle benchmark: {} smooth-shaded depth-tested triangles/frame at {}x{}, \
         median of up to {} frames (after 1 warm-up), each ending in glFinish",
        cfg.triangles, cfg.width, cfg.height, cfg.frames
    );
    let mut results = vec![run_tilegl(&cfg, &verts, 1), run_tilegl(&cfg, &verts, 2)];
    match run_mesa(&cfg, &verts) {
        Ok((r, info)) => {
            let other = if info.driver() == "softpipe" {
                "llvmpipe"
            } else {
                "softpipe"
            };
            println!("Mesa in this process: {info}");
            results.push(r);
            // cargo bench passes --bench; keep it so the child parses args the same way.
            let extra: Vec<&str> = args
                .iter()
                .filter(|a| a.as_str() == "--bench")
                .map(|s| s.as_str())
                .collect();
            match run_mesa_subprocess(other, &cfg, &extra) {
                Ok(r) => results.push(r),
                Err(e) => println!("mesa {other}: unavailable ({e})"),
            }
        }
        Err(e) => println!("Mesa: unavailable ({e}); tilegl figures only"),
    }

    let base = results[0].median_ms();
    println!();
    println!(
        "{:<16} {:>10} {:>10} {:>8}  frames(ms)",
        "implementation", "ms/frame", "vs tilegl1", "glError"
    );
    for r in &results {
        println!(
            "{:<16} {:>10.1} {:>9.2}x {:>#8x}  {:?}",
            r.name,
            r.median_ms(),
            r.median_ms() / base,
            r.error,
            r.frame_ms
                .iter()
                .map(|m| (m * 10.0).round() / 10.0)
                .collect::<Vec<_>>()
        );
    }
    println!();
    println!("image error (per pair; bad = pixels with a channel difference > 8):");
    for i in 0..results.len() {
        for j in i + 1..results.len() {
            let d = diff(&results[i].image, &results[j].image, 8);
            println!("  {:<14} vs {:<14} {}", results[i].name, results[j].name, d);
        }
    }
    0
}

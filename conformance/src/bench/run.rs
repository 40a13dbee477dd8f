//! Running the benchmark: timing frames on each implementation (tilegl in process or through
//! its C exports, Mesa in process or in a child), the command line, the toggle matrix, the
//! lighting scaling and the texture quality ladder, and the ratio table.

#[allow(unused_imports)]
use super::*;

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
pub fn run_frames(name: &str, gl: &mut dyn Gl, cfg: &BenchConfig, data: &WorkData) -> BenchResult {
    setup(gl, cfg);
    frame(gl, data);
    let mut frame_ms = Vec::new();
    let start = Instant::now();
    while frame_ms.len() < cfg.frames.max(1) || start.elapsed() < cfg.min_time {
        let t = Instant::now();
        frame(gl, data);
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
pub fn run_tilegl(cfg: &BenchConfig, data: &WorkData, threads: usize) -> BenchResult {
    let mut ctx = crate::client_context(ContextConfig {
        width: cfg.width,
        height: cfg.height,
        threads,
        framebuffer: FramebufferConfig {
            accum_bits: 16,
            ..FramebufferConfig::default()
        },
    });
    run_frames(&format!("tilegl {threads}T"), &mut ctx, cfg, data)
}

/// Mesa in this process (its driver is fixed by `GALLIUM_DRIVER` at the first context).
pub fn run_mesa(cfg: &BenchConfig, data: &WorkData) -> Result<(BenchResult, OracleInfo), String> {
    let mut mesa = MesaContext::create(cfg.width, cfg.height).map_err(|e| e.to_string())?;
    let info = mesa.info().clone();
    let mut r = run_frames("mesa", &mut *mesa, cfg, data);
    r.name = format!("mesa {}", info.driver());
    Ok((r, info))
}

pub(super) const CHILD_ARG: &str = "--mesa-child";

pub(super) fn encode_result(r: &BenchResult) -> Vec<u8> {
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

pub(super) fn decode_result(b: &[u8]) -> Option<BenchResult> {
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
    let min_time = cfg.min_time.as_secs_f64().to_string();
    let mut args: Vec<&str> = extra_args.to_vec();
    let quality = cfg.quality.to_string();
    let toggle = cfg.toggle.map(|t| t.to_string());
    if let Some(t) = &toggle {
        args.extend_from_slice(&["--toggle", t]);
    }
    args.extend_from_slice(&[
        "--quality",
        &quality,
        "--workload",
        cfg.workload.name(),
        CHILD_ARG,
        &out_s,
        "--frames",
        &frames,
        "--triangles",
        &tris,
        "--budget",
        &budget,
        "--min-time",
        &min_time,
    ]);
    mesa::run_self_with_driver(driver, &args, &[]).map_err(|e| e.to_string())?;
    let bytes = std::fs::read(&out).map_err(|e| e.to_string())?;
    let _ = std::fs::remove_file(&out);
    decode_result(&bytes).ok_or_else(|| "bad result from bench child".to_string())
}

/// Parses the options into `cfg`; returns the child-output path (child mode) and whether
/// every workload was asked for.
pub(super) fn parse_args(args: &[String], cfg: &mut BenchConfig) -> (Option<String>, bool) {
    let mut child_out = None;
    let mut all = true;
    let mut i = 0;
    while i < args.len() {
        let next = args.get(i + 1);
        match (args[i].as_str(), next) {
            (CHILD_ARG, Some(p)) => {
                child_out = Some(p.clone());
                i += 1;
            }
            ("--workload", Some(v)) if v == "lighting" => {
                cfg.workload = Workload::Lighting;
                all = false;
                i += 1;
            }
            ("--workload", Some(v)) if v == "toggles" => {
                cfg.toggles_only = true;
                all = false;
                i += 1;
            }
            ("--toggle", Some(v)) => {
                cfg.toggle = v.parse().ok();
                i += 1;
            }
            ("--workload", Some(v)) if v == "ladder" => {
                cfg.ladder_only = true;
                all = false;
                i += 1;
            }
            ("--workload", Some(v)) => {
                match Workload::parse(v) {
                    Some(w) => {
                        cfg.workload = w;
                        all = false;
                    }
                    None => all = v == "all",
                }
                i += 1;
            }
            ("--quality", Some(v)) => {
                cfg.quality = v.parse().unwrap_or(cfg.quality);
                i += 1;
            }
            ("--frames", Some(v)) => {
                cfg.frames = v.parse().unwrap_or(cfg.frames);
                i += 1;
            }
            ("--threads", Some(v)) => {
                if let Ok(t) = v.parse::<usize>() {
                    cfg.tilegl_threads = vec![t.max(1)];
                }
                i += 1;
            }
            ("--tiny-viewport", _) => cfg.tiny_viewport = true,
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
            ("--min-time", Some(v)) => {
                if let Ok(s) = v.parse::<f64>() {
                    cfg.min_time = Duration::from_secs_f64(s.clamp(0.0, 3600.0));
                }
                i += 1;
            }
            _ => {}
        }
        i += 1;
    }
    (child_out, all)
}

/// What `--help` prints.
pub const USAGE: &str = "bench [--workload NAME|all|toggles|ladder|lighting] [--no-ladder] \
[--frames N] [--min-time SECONDS] [--budget SECONDS] [--threads N] [--toggle K] [--quality K] \
[--no-mesa] [--no-xcore] [--scaling] [--tiny-viewport]

Times each workload at 1024x768 on tilegl (through its C exports; --threads N: through the \
Rust API with N threads) and Mesa (llvmpipe with LP_NUM_THREADS=2 in this process, softpipe in \
a child), tilegl and llvmpipe in alternating rounds, and prints a ratio table with each \
workload's picture error beside its times. Workloads: triangles sprites fog overdraw horizon \
lightmap spheremap tunnel tunnel-nofog objects objects-nofog lit-triangles combine4 cubemap \
lines shadow text uploads accum; toggles: the state-toggle matrix; ladder: texture quality \
against time; lighting: lighting cost against triangle count; --scaling: time against pixels \
and triangles; --tiny-viewport: the same frames through a 1x1 viewport (what a frame costs \
besides its pixels).";

/// The benchmark's command line ([`USAGE`]). Prints one table per workload, then the ratio
/// table, and returns the process exit code.
pub fn run_cli() -> i32 {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.iter().any(|a| a == "--help" || a == "-h") {
        println!("{USAGE}");
        return 0;
    }
    if args.iter().any(|a| a == "--scaling") {
        let with_mesa =
            !args.iter().any(|a| a == "--no-mesa") && crate::mesa::mesa_available().is_ok();
        return crate::scaling::run(std::path::Path::new("target/bench"), with_mesa);
    }
    if std::env::var_os("LP_NUM_THREADS").is_none() {
        // llvmpipe with two rendering threads (the reference), set before Mesa's
        // first context reads it.
        std::env::set_var("LP_NUM_THREADS", "2");
    }
    let mut cfg = BenchConfig::default();
    let (child_out, all) = parse_args(&args, &mut cfg);
    if let Some(out) = child_out {
        // Child mode: Mesa with the driver the parent selected.
        let data = work_data(&cfg);
        return match run_mesa(&cfg, &data) {
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
    if cfg.toggles_only {
        run_toggles(&cfg);
        return 0;
    }
    let workloads: Vec<Workload> = if all {
        Workload::ALL.to_vec()
    } else if cfg.ladder_only {
        Vec::new()
    } else {
        vec![cfg.workload]
    };
    if cfg.workload == Workload::Lighting && !all {
        run_lighting_scaling(&cfg);
        return 0;
    }
    let mut rows = Vec::new();
    for w in workloads {
        cfg.workload = w;
        rows.extend(run_workload(&cfg, &args));
    }
    if !rows.is_empty() {
        println!();
        println!(
            "== ratio table ({}x{}; vs: the Mesa driver's ms over tilegl's, above 1 tilegl is \
             faster; error: tilegl's picture against the driver's)",
            cfg.width, cfg.height
        );
        print!("{}", ratio_table(&rows));
    }
    if (all && !args.iter().any(|a| a == "--no-ladder")) || cfg.ladder_only {
        run_ladder(&cfg);
    }
    0
}

/// Lighting cost against triangle count: the `lighting` sphere at 2k ... 128k triangles, lit
/// and unlit, on tilegl (1 thread, so the vertex stage is not hidden by parallel
/// rasterization) and on Mesa in this process; the lit-minus-unlit time per frame is the
/// lighting cost, fitted by least squares to a + b N (with R^2).
pub fn run_lighting_scaling(cfg: &BenchConfig) {
    println!();
    println!(
        "== lighting: a sphere of constant screen size at {}x{}, two lights (one positional, \
         attenuated), specular; median ms/frame lit and unlit",
        cfg.width, cfg.height
    );
    println!(
        "{:>10} {:>12} {:>12} {:>12} {:>12} {:>12}",
        "triangles", "tilegl lit", "unlit", "light cost", "ns/triangle", "llvmpipe cost"
    );
    let mut c = cfg.clone();
    c.workload = Workload::Lighting;
    // Lighting at glEnd costs a few ns a vertex: the difference of two medians needs many
    // frames to stand out of the machine's noise.
    c.frames = c.frames.max(25);
    // Its own alternation (below) guards against slow spells.
    c.min_time = Duration::ZERO;
    let mut points = Vec::new();
    for k in [1usize, 2, 4, 8, 16, 32, 64] {
        let (stacks, slices) = (32, 32 * k);
        let n = 2 * stacks * slices;
        // Lit and unlit alternately, three times, keeping each one's fastest median: the
        // machine's slow spells then cannot land on one side only.
        let (mut lit, mut unlit) = (f64::INFINITY, f64::INFINITY);
        for _ in 0..3 {
            let l = run_tilegl(&c, &WorkData::Sphere(stacks, slices, true), 1).median_ms();
            let u = run_tilegl(&c, &WorkData::Sphere(stacks, slices, false), 1).median_ms();
            lit = lit.min(l);
            unlit = unlit.min(u);
        }
        let mesa = match (
            run_mesa(&c, &WorkData::Sphere(stacks, slices, true)),
            run_mesa(&c, &WorkData::Sphere(stacks, slices, false)),
        ) {
            (Ok((l, _)), Ok((u, _))) => format!("{:.2}", l.median_ms() - u.median_ms()),
            _ => "-".to_string(),
        };
        let cost = lit - unlit;
        println!(
            "{:>10} {:>12.2} {:>12.2} {:>12.2} {:>12.1} {:>12}",
            n,
            lit,
            unlit,
            cost,
            cost * 1e6 / n as f64,
            mesa
        );
        points.push((n as f64, cost));
    }
    let m = points.len() as f64;
    let (sx, sy) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x, b + y));
    let (mx, my) = (sx / m, sy / m);
    let sxx: f64 = points.iter().map(|&(x, _)| (x - mx).powi(2)).sum();
    let sxy: f64 = points.iter().map(|&(x, y)| (x - mx) * (y - my)).sum();
    let syy: f64 = points.iter().map(|&(_, y)| (y - my).powi(2)).sum();
    let b = sxy / sxx;
    let a = my - b * mx;
    let r2 = if syy > 0.0 {
        sxy * sxy / (sxx * syy)
    } else {
        1.0
    };
    println!(
        "tilegl lighting cost = {a:.3} ms + {:.1} ns x triangles (R^2 = {r2:.4})",
        b * 1e6
    );
}

/// The state-toggle matrix: the `tunnel-nofog` scene with each of [`TOGGLES`] on tilegl
/// (through the C exports, or `--threads`) and Mesa in this process, in two alternating rounds
/// per toggle; the base scene is timed first and again last (its figure is the mean of the two).
/// Prints each toggle's added cost on both, tilegl's over Mesa's, whether that is within the
/// issue's 1.5x, and tilegl's picture error against Mesa's; then the same as a Markdown table.
pub fn run_toggles(cfg: &BenchConfig) {
    let mut c = cfg.clone();
    c.workload = Workload::TunnelNoFog;
    let data = work_data(&c);
    println!();
    println!(
        "== toggles: {} at {}x{}, each feature turned on alone or in a pair (medians over two \
         alternating rounds of at least {} frames and {:.1} s each)",
        describe(&c),
        c.width,
        c.height,
        c.frames.div_ceil(2),
        c.min_time.as_secs_f64() / 2.0
    );
    let (half, budget) = (c.min_time / 2, c.budget / 2);
    let frames = c.frames.div_ceil(2);
    let time = |c: &BenchConfig| -> Option<(BenchResult, Option<BenchResult>)> {
        let mut t = open_tilegl(c, &data).ok()?;
        let mut m = open_mesa(c, &data).ok().map(|(m, _)| m);
        t.round(&data, frames, half, budget);
        if let Some(m) = &mut m {
            m.round(&data, frames, half, budget);
            m.round(&data, frames, half, budget);
        }
        t.round(&data, frames, half, budget);
        Some((t.finish(c), m.map(|m| m.finish(c))))
    };
    let mut rows: Vec<(&str, f64, f64, Option<tilegl::compare::Diff>)> = Vec::new();
    for (k, (name, _)) in TOGGLES.iter().enumerate() {
        c.toggle = Some(k);
        let Some((t, m)) = time(&c) else {
            println!("tilegl: no context");
            return;
        };
        let mesa_ms = m.as_ref().map_or(f64::NAN, BenchResult::median_ms);
        let d = m.as_ref().map(|m| diff(&t.image, &m.image, 8));
        println!(
            "{:<34} tilegl {:>7.1} ms  mesa {:>7.1} ms{}{}",
            name,
            t.median_ms(),
            mesa_ms,
            d.as_ref().map_or(String::new(), |d| format!("  {d}")),
            if t.error != 0 {
                format!("  glError {:#x}", t.error)
            } else {
                String::new()
            }
        );
        rows.push((name, t.median_ms(), mesa_ms, d));
    }
    // The base again, after the toggles: the machine's drift over the run shows in the two.
    c.toggle = Some(0);
    let again = time(&c);
    let (t0, m0) = (rows[0].1, rows[0].2);
    let (bt, bm) = match &again {
        Some((t, m)) => {
            let m1 = m.as_ref().map_or(f64::NAN, BenchResult::median_ms);
            println!(
                "{:<34} tilegl {:>7.1} ms  mesa {:>7.1} ms (the base again)",
                TOGGLES[0].0,
                t.median_ms(),
                m1
            );
            ((t0 + t.median_ms()) / 2.0, (m0 + m1) / 2.0)
        }
        None => (t0, m0),
    };
    let tilegl = open_tilegl(&c, &data).map_or("tilegl".to_string(), |s| s.name);
    println!();
    println!(
        "| toggle | {tilegl} ms | added | llvmpipe ms | added | tilegl's added / llvmpipe's | \
         within 1.5x | error vs llvmpipe (>8, mean) |"
    );
    println!("| --- | ---: | ---: | ---: | ---: | ---: | --- | ---: |");
    for (k, (name, t, m, d)) in rows.iter().enumerate() {
        let (ta, ma) = (t - bt, m - bm);
        let ratio = if k == 0 {
            "-".to_string()
        } else if ma.abs() < 0.3 {
            format!("{ta:+.1} ms vs {ma:+.1} ms")
        } else {
            format!("{:.2}", ta / ma)
        };
        let within = if k == 0 {
            "-"
        } else if toggle_within(ta, ma, bt) {
            "yes"
        } else {
            "**no**"
        };
        println!(
            "| {name} | {t:.1} | {ta:+.1} | {m:.1} | {ma:+.1} | {ratio} | {within} | {} |",
            d.as_ref().map_or("-".to_string(), |d| format!(
                "{:.3} % / {:.3}",
                d.bad_share * 100.0,
                d.mean
            ))
        );
    }
    println!(
        "base: the mean of the first and last base runs; added: the toggle's time minus the \
         base's; within 1.5x: tilegl's added time is at most 1.5 times llvmpipe's, or within \
         the noise (5 % of tilegl's base time)"
    );
}

/// Whether a toggle adding `tilegl_added` ms to tilegl and `mesa_added` ms to Mesa is within
/// the bound (at most 1.5 times Mesa's added cost); differences under 5 % of tilegl's
/// base time `tilegl_base` are within the noise of the shared machine.
pub fn toggle_within(tilegl_added: f64, mesa_added: f64, tilegl_base: f64) -> bool {
    tilegl_added <= (1.5 * mesa_added).max(0.05 * tilegl_base)
}

/// " (phases differ: ...)" when two runs' cross-core round trips (`machine`) differ by more
/// than twice, else nothing: their ratio then mixes the machine's fast and slow phases.
pub(super) fn phase_note(a: Option<f64>, b: Option<f64>) -> String {
    match (a, b) {
        (Some(a), Some(b)) if a.max(b) > 2.0 * a.min(b) => {
            format!(" (phases differ: xcore {a:.0} vs {b:.0} ns)")
        }
        _ => String::new(),
    }
}

/// Box-filters an image `f` times smaller in each direction.
pub(super) fn downsample(img: &Image, f: i32) -> Image {
    let (w, h) = (img.width / f, img.height / f);
    let mut pixels = Vec::with_capacity((w * h * 4) as usize);
    for y in 0..h {
        for x in 0..w {
            let mut sum = [0u32; 4];
            for dy in 0..f {
                for dx in 0..f {
                    let p = img.pixel(x * f + dx, y * f + dy);
                    for k in 0..4 {
                        sum[k] += p[k] as u32;
                    }
                }
            }
            let n = (f * f) as u32;
            pixels.extend(sum.map(|v| ((v + n / 2) / n) as u8));
        }
    }
    Image {
        width: w,
        height: h,
        pixels,
    }
}

/// The quality ladder (error against run time): the horizon under every setting of
/// [`LADDER`] on tilegl (2 threads) and Mesa in this process, each with its median time and
/// its error against a 16x-supersampled (4x4) tilegl rendering with 16x anisotropic
/// filtering; a table and a PNG chart (`target/bench/ladder.png`).
pub fn run_ladder(cfg: &BenchConfig) {
    let mut c = cfg.clone();
    c.workload = Workload::Horizon;
    let data = work_data(&c);
    println!();
    println!(
        "== ladder: the horizon at {}x{} under each texture quality setting; error against a \
         4x4-supersampled tilegl reference (aniso 16x)",
        c.width, c.height
    );
    let reference = {
        let mut big = c.clone();
        big.width = c.width * 4;
        big.height = c.height * 4;
        big.quality = LADDER.len() - 1;
        big.frames = 1;
        big.min_time = Duration::ZERO;
        let r = run_tilegl(&big, &data, 0);
        downsample(&r.image, 4)
    };
    let mut rows = Vec::new();
    for (q, setting) in LADDER.iter().enumerate() {
        c.quality = q;
        let t = run_tilegl(&c, &data, 2);
        let m = run_mesa(&c, &data).ok().map(|(r, _)| r);
        rows.push((setting.0, t, m));
    }
    println!(
        "{:<10} {:>12} {:>14} {:>12} {:>14}",
        "setting", "tilegl ms", "tilegl err", "llvmpipe ms", "llvmpipe err"
    );
    let mut points = Vec::new();
    for (name, t, m) in &rows {
        let dt = diff(&t.image, &reference, 8);
        let (mm, me) = match m {
            Some(m) => {
                let dm = diff(&m.image, &reference, 8);
                (
                    format!("{:.1}", m.median_ms()),
                    format!("{:.2} dB", dm.psnr),
                )
            }
            None => ("-".to_string(), "-".to_string()),
        };
        println!(
            "{:<10} {:>12.1} {:>11.2} dB {:>12} {:>14}",
            name,
            t.median_ms(),
            dt.psnr,
            mm,
            me
        );
        points.push((t.median_ms(), dt.mean));
    }
    let path = std::path::Path::new("target/bench/ladder.png");
    match ladder_chart(&points, path) {
        Ok(()) => println!("chart (mean error against ms/frame): {}", path.display()),
        Err(e) => println!("chart not written: {e}"),
    }
}

/// Draws the ladder as a chart with tilegl itself: mean absolute error (y) against ms/frame
/// (x), one coloured marker per setting in [`LADDER`] order (nearest red ... aniso 16x
/// violet), joined by a line.
pub(super) fn ladder_chart(points: &[(f64, f64)], path: &std::path::Path) -> Result<(), String> {
    let (w, h) = (640, 400);
    let mut gl = Context::new(w, h);
    gl.clear_color(1.0, 1.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let max_x = points.iter().map(|p| p.0).fold(1e-9, f64::max) * 1.1;
    let max_y = points.iter().map(|p| p.1).fold(1e-9, f64::max) * 1.1;
    gl.matrix_mode(GL_PROJECTION);
    gl.ortho(-0.08, 1.02, -0.1, 1.05, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.color_3f(0.0, 0.0, 0.0);
    gl.line_width(2.0);
    gl.begin(GL_LINE_STRIP);
    gl.vertex_2f(0.0, 1.0);
    gl.vertex_2f(0.0, 0.0);
    gl.vertex_2f(1.0, 0.0);
    gl.end();
    gl.color_3f(0.6, 0.6, 0.6);
    gl.line_width(1.0);
    gl.begin(GL_LINE_STRIP);
    for &(x, y) in points {
        gl.vertex_2f((x / max_x) as f32, (y / max_y) as f32);
    }
    gl.end();
    gl.enable(GL_POINT_SMOOTH);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.point_size(12.0);
    gl.begin(GL_POINTS);
    for (k, &(x, y)) in points.iter().enumerate() {
        let hue = k as f32 / points.len().max(1) as f32;
        gl.color_3f(1.0 - hue, 0.3 + 0.4 * (hue * 3.0).sin().abs(), hue);
        gl.vertex_2f((x / max_x) as f32, (y / max_y) as f32);
    }
    gl.end();
    gl.finish();
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(|e| e.to_string())?;
    }
    tilegl::framebuffer::image::save_png(gl.framebuffer(), path).map_err(|e| e.to_string())
}

pub(super) fn describe(cfg: &BenchConfig) -> String {
    match cfg.workload {
        Workload::Triangles => format!(
            "{} smooth-shaded depth-tested triangles/frame",
            cfg.triangles
        ),
        Workload::Sprites => format!(
            "{SPRITES} alpha-blended, alpha-tested, trilinear-textured sprites/frame, depth writes off"
        ),
        Workload::Fog => format!(
            "lit {TERRAIN_CELLS}x{TERRAIN_CELLS} height field ({} triangles) under exp2 fog",
            2 * TERRAIN_CELLS * TERRAIN_CELLS
        ),
        Workload::Overdraw => {
            "8 full-screen quads/frame (overdraw 8), trilinear, modulate".to_string()
        }
        Workload::Horizon => format!(
            "a ground plane receding to the horizon, repeat, {}",
            LADDER[cfg.quality.min(LADDER.len() - 1)].0
        ),
        Workload::Lightmap => format!(
            "a corridor of {} light-mapped wall quads, base texture {} on unit 0, light map \
             through GL_COMBINE MODULATE x2 on unit 1",
            4 * CORRIDOR_SEGMENTS,
            LADDER[cfg.quality.min(LADDER.len() - 1)].0
        ),
        Workload::Spheremap => format!(
            "a lit torus of {} triangles, then again sphere-mapped and added (2 passes)",
            2 * TORUS.0 * TORUS.1
        ),
        Workload::Lighting => "a lit sphere".to_string(),
        Workload::LitTriangles => format!(
            "{} small lit triangles/frame through glNormal3f/glVertex3f, one light, specular",
            bench_scenes::LIT_TRIANGLES
        ),
        Workload::Combine4 => format!(
            "the lightmap corridor through GL_COMBINE on 4 units (base trilinear x colour, light \
             map x2, signed detail trilinear, interpolated environment), {} quads",
            4 * CORRIDOR_SEGMENTS
        ),
        Workload::Cubemap => format!(
            "a lit torus of {} triangles reflecting a cube map (GL_REFLECTION_MAP on s, t, r)",
            2 * TORUS.0 * TORUS.1
        ),
        Workload::Lines => format!(
            "{} segments/frame: half smooth (width 2.5, blended), half wide (width 3)",
            bench_scenes::LINES
        ),
        Workload::Shadow => format!(
            "a lit floor and {} plates, their shadow volumes counted in the stencil buffer \
             (z-pass, two passes), a blended darkening quad",
            bench_scenes::PLATES.0 * bench_scenes::PLATES.1
        ),
        Workload::Text => format!(
            "4 glDrawPixels of 256x192 RGBA and {} glBitmap glyphs of 8x13/frame",
            bench_scenes::TEXT.0 * bench_scenes::TEXT.1
        ),
        Workload::Uploads => "4 glTexSubImage2D of 256x256 RGBA and 1 glTexImage2D of 512x512 \
                              RGB per frame, each drawn (bilinear)"
            .to_string(),
        Workload::Accum => format!(
            "the horizon drawn {} times with a turn, averaged with glAccum (LOAD, ACCUM, RETURN)",
            bench_scenes::ACCUM_PASSES
        ),
        Workload::Tunnel | Workload::TunnelNoFog => format!(
            "a perspective tunnel of {} quads, {} walls MODULATEd by a smooth colour, depth \
             test{}",
            TUNNEL.0 * TUNNEL.1,
            LADDER[cfg.quality.min(LADDER.len() - 1)].0,
            match cfg.toggle {
                Some(t) => format!(", {}", TOGGLES[t.min(TOGGLES.len() - 1)].0),
                None if cfg.workload == Workload::Tunnel => ", EXP2 fog".to_string(),
                None => ", no fog".to_string(),
            }
        ),
        Workload::Objects | Workload::ObjectsNoFog => format!(
            "{} lit, {} textured (MODULATE) tori of {} triangles from one display list, {}",
            OBJECTS.0 * OBJECTS.1,
            LADDER[cfg.quality.min(LADDER.len() - 1)].0,
            2 * 48 * 24,
            if cfg.workload == Workload::Objects {
                "LINEAR fog"
            } else {
                "no fog"
            }
        ),
    }
}

/// A context under test: tilegl through its C exports (`OSMesaCreateContextExt`, every call
/// through the function `OSMesaGetProcAddress` returns, as Mesa is driven), tilegl through
/// the Rust API with a thread count (`--threads N`, for profiling without the C layer), or Mesa
/// in this process.
pub enum Subject {
    CAbi(CAbiContext),
    Rust(Box<Context>),
    Mesa(MesaContext),
}

impl Subject {
    pub fn gl(&mut self) -> &mut dyn Gl {
        match self {
            Subject::CAbi(c) => &mut **c,
            Subject::Rust(c) => &mut **c,
            Subject::Mesa(m) => &mut **m,
        }
    }
}

/// A subject with its workload set up and one warm-up frame drawn, collecting frame times over
/// rounds that alternate with the other subjects' (a slow spell of the shared machine then
/// falls on both sides instead of one).
pub struct Session {
    pub name: String,
    subject: Subject,
    frame_ms: Vec<f64>,
    spent: Duration,
}

impl Session {
    pub fn open(name: String, mut subject: Subject, cfg: &BenchConfig, data: &WorkData) -> Self {
        setup(subject.gl(), cfg);
        frame(subject.gl(), data);
        Session {
            name,
            subject,
            frame_ms: Vec::new(),
            spent: Duration::ZERO,
        }
    }

    /// Times frames until this round has at least `frames` of them and `min_time`, stopping
    /// early once the session has spent `budget` (at least one frame per round).
    pub fn round(&mut self, data: &WorkData, frames: usize, min_time: Duration, budget: Duration) {
        let start = Instant::now();
        let mut n = 0;
        while n < frames.max(1) || start.elapsed() < min_time {
            let t = Instant::now();
            frame(self.subject.gl(), data);
            let dt = t.elapsed();
            self.frame_ms.push(dt.as_secs_f64() * 1000.0);
            self.spent += dt;
            n += 1;
            if self.spent > budget {
                break;
            }
        }
    }

    /// The GL error after the frames and the final picture.
    pub fn finish(mut self, cfg: &BenchConfig) -> BenchResult {
        let gl = self.subject.gl();
        let error = gl.get_error();
        let image = Image::read(gl, cfg.width, cfg.height);
        BenchResult {
            name: self.name,
            frame_ms: self.frame_ms,
            image,
            error,
        }
    }
}

/// tilegl as programs reach it (the C exports, default threads: one per core), or through the
/// Rust API with `cfg.tilegl_threads[0]` threads when `--threads` was given.
pub fn open_tilegl(cfg: &BenchConfig, data: &WorkData) -> Result<Session, String> {
    match cfg.tilegl_threads.first() {
        Some(&threads) => {
            let ctx = crate::client_context(ContextConfig {
                width: cfg.width,
                height: cfg.height,
                threads,
                framebuffer: FramebufferConfig {
                    accum_bits: 16,
                    ..FramebufferConfig::default()
                },
            });
            Ok(Session::open(
                format!("tilegl {threads}T rs"),
                Subject::Rust(Box::new(ctx)),
                cfg,
                data,
            ))
        }
        None => {
            let ctx = CAbiContext::create(cfg.width, cfg.height, 16)
                .ok_or("the C ABI refused the context")?;
            let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
            Ok(Session::open(
                format!("tilegl {threads}T"),
                Subject::CAbi(ctx),
                cfg,
                data,
            ))
        }
    }
}

/// Mesa in this process (llvmpipe unless `GALLIUM_DRIVER` says otherwise).
pub fn open_mesa(cfg: &BenchConfig, data: &WorkData) -> Result<(Session, OracleInfo), String> {
    let mesa = MesaContext::create(cfg.width, cfg.height).map_err(|e| e.to_string())?;
    let info = mesa.info().clone();
    let name = format!("mesa {}", info.driver());
    Ok((Session::open(name, Subject::Mesa(mesa), cfg, data), info))
}

/// One line of the ratio table.
#[derive(Clone, Debug)]
pub struct SummaryRow {
    pub workload: Workload,
    pub tilegl_name: String,
    pub tilegl_ms: f64,
    pub llvmpipe_ms: Option<f64>,
    pub softpipe_ms: Option<f64>,
    /// tilegl's picture against llvmpipe's and softpipe's.
    pub vs_llvmpipe: Option<tilegl::compare::Diff>,
    pub vs_softpipe: Option<tilegl::compare::Diff>,
    /// A GL error reported by any implementation after the frames.
    pub errors: Vec<String>,
}

/// Times one workload: tilegl and Mesa in this process in two alternating rounds (tilegl,
/// Mesa; then Mesa, tilegl), the other Mesa driver in a child process between them; prints
/// each implementation's figures and every pair's picture difference, and returns the row of
/// the ratio table.
pub(super) fn run_workload(cfg: &BenchConfig, args: &[String]) -> Option<SummaryRow> {
    let data = work_data(cfg);
    println!();
    println!(
        "== {}: {} at {}x{}, median of at least {} frames and {:.1} s over two alternating \
         rounds (after 1 warm-up; at most {:.0} s), each ending in glFinish",
        cfg.workload.name(),
        describe(cfg),
        cfg.width,
        cfg.height,
        cfg.frames,
        cfg.min_time.as_secs_f64(),
        cfg.budget.as_secs_f64()
    );
    // The cross-core round trip just before each implementation's first round (`machine`);
    // not with `--no-xcore` (under valgrind its two spinning threads take minutes).
    let measure = !args.iter().any(|a| a == "--no-xcore");
    let cross_core_round_trip_ns = || measure.then(cross_core_round_trip_ns).flatten();
    let frames = cfg.frames.div_ceil(2);
    let (half, budget) = (cfg.min_time / 2, cfg.budget / 2);
    let mut tile = match open_tilegl(cfg, &data) {
        Ok(t) => t,
        Err(e) => {
            println!("tilegl: {e}");
            return None;
        }
    };
    let mut mesa = if args.iter().any(|a| a == "--no-mesa") {
        Err("--no-mesa".to_string())
    } else {
        open_mesa(cfg, &data)
    };
    let trip_tile = cross_core_round_trip_ns();
    tile.round(&data, frames, half, budget);
    let trip_mesa = cross_core_round_trip_ns();
    if let Ok((m, _)) = &mut mesa {
        m.round(&data, frames, half, budget);
    }
    // The other driver in a child between the rounds (softpipe takes about a second a frame:
    // three frames).
    let child = match &mesa {
        Ok((_, info)) => {
            let other = if info.driver() == "softpipe" {
                "llvmpipe"
            } else {
                "softpipe"
            };
            // cargo bench passes --bench; keep it so the child parses args the same way.
            let extra: Vec<&str> = args
                .iter()
                .filter(|a| a.as_str() == "--bench")
                .map(|s| s.as_str())
                .collect();
            let mut c = cfg.clone();
            c.frames = 3;
            c.min_time = half;
            let before = cross_core_round_trip_ns();
            Some((other, run_mesa_subprocess(other, &c, &extra), before))
        }
        Err(_) => None,
    };
    if let Ok((m, _)) = &mut mesa {
        m.round(&data, frames, half, budget);
    }
    tile.round(&data, frames, half, budget);

    let mut results = vec![tile.finish(cfg)];
    let mut round_trip = vec![trip_tile];
    match mesa {
        Ok((m, info)) => {
            println!("Mesa in this process: {info}");
            results.push(m.finish(cfg));
            round_trip.push(trip_mesa);
        }
        Err(e) => println!("Mesa: unavailable ({e}); tilegl figures only"),
    }
    if let Some((other, r, before)) = child {
        match r {
            Ok(r) => {
                results.push(r);
                round_trip.push(before);
            }
            Err(e) => println!("mesa {other}: unavailable ({e})"),
        }
    }

    let base = results[0].median_ms();
    println!(
        "{:<16} {:>10} {:>10} {:>8} {:>7}  timed frames: count, fastest, 90th percentile, \
         slowest (ms)",
        "implementation", "ms/frame", "vs tilegl", "glError", "xcore"
    );
    for (r, trip) in results.iter().zip(&round_trip) {
        let trip = trip.map_or("-".to_string(), |ns| format!("{ns:.0} ns"));
        let mut sorted = r.frame_ms.clone();
        sorted.sort_by(f64::total_cmp);
        let at = |q: f64| {
            sorted
                .get(((sorted.len() as f64 - 1.0) * q).round() as usize)
                .copied()
                .unwrap_or(f64::NAN)
        };
        println!(
            "{:<16} {:>10.1} {:>9.2}x {:>#8x} {:>7}  {} frames: {:.1}, {:.1}, {:.1}",
            r.name,
            r.median_ms(),
            r.median_ms() / base,
            r.error,
            trip,
            sorted.len(),
            at(0.0),
            at(0.9),
            at(1.0)
        );
    }
    println!(
        "xcore: a cache line's round trip between CPU 0 and CPU 1 just before the run \
         (machine::cross_core_round_trip_ns; the development VM has phases of ~100 and ~400 ns, \
         and multi-threaded renderers are slower in the second)"
    );
    // The issues' targets are speeds relative to Mesa's drivers: tilegl's speed against each
    // Mesa run's (above 1: tilegl is faster). A ratio of two runs timed in different phases of
    // the machine is marked.
    let t = &results[0];
    let speeds: Vec<String> = results
        .iter()
        .zip(&round_trip)
        .skip(1)
        .map(|(m, trip)| {
            let note = phase_note(round_trip[0], *trip);
            format!("{:.2}x {}{note}", m.median_ms() / t.median_ms(), m.name)
        })
        .collect();
    if !speeds.is_empty() {
        println!("speed of {}: {}", t.name, speeds.join(", "));
    }
    if let Some(dir) = std::env::var_os("TILEGL_BENCH_DUMP") {
        // Pictures for a closer look: DIR/WORKLOAD-IMPLEMENTATION.ppm.
        let dir = std::path::PathBuf::from(dir);
        let _ = std::fs::create_dir_all(&dir);
        for r in &results {
            let file = format!("{}-{}.ppm", cfg.workload.name(), r.name.replace(' ', "_"));
            if let Err(e) = r.image.write_ppm(&dir.join(file)) {
                println!("cannot write picture: {e}");
            }
        }
    }
    println!("image error (per pair; bad = pixels with a channel difference > 8):");
    for i in 0..results.len() {
        for j in i + 1..results.len() {
            let d = diff(&results[i].image, &results[j].image, 8);
            println!("  {:<14} vs {:<14} {}", results[i].name, results[j].name, d);
        }
    }
    let find = |driver: &str| results.iter().find(|r| r.name == format!("mesa {driver}"));
    let (llvmpipe, softpipe) = (find("llvmpipe"), find("softpipe"));
    Some(SummaryRow {
        workload: cfg.workload,
        tilegl_name: t.name.clone(),
        tilegl_ms: t.median_ms(),
        llvmpipe_ms: llvmpipe.map(BenchResult::median_ms),
        softpipe_ms: softpipe.map(BenchResult::median_ms),
        vs_llvmpipe: llvmpipe.map(|m| diff(&t.image, &m.image, 8)),
        vs_softpipe: softpipe.map(|m| diff(&t.image, &m.image, 8)),
        errors: results
            .iter()
            .filter(|r| r.error != 0)
            .map(|r| format!("{} {:#x}", r.name, r.error))
            .collect(),
    })
}

/// The ratio table of a run as Markdown: each workload's median ms on tilegl, llvmpipe and
/// softpipe, tilegl's speed against each (above 1: faster), and beside the times tilegl's
/// picture error against each (share of pixels with a channel off by more than 8, mean
/// channel difference).
pub fn ratio_table(rows: &[SummaryRow]) -> String {
    let ms = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.1}"));
    let speed = |t: f64, m: Option<f64>| m.map_or("-".to_string(), |m| format!("{:.2}x", m / t));
    let err = |d: &Option<tilegl::compare::Diff>| {
        d.as_ref().map_or("-".to_string(), |d| {
            format!("{:.3} % / {:.3}", d.bad_share * 100.0, d.mean)
        })
    };
    let tilegl = rows.first().map_or("tilegl", |r| r.tilegl_name.as_str());
    let mut out = format!(
        "| workload | {tilegl} ms | llvmpipe ms | softpipe ms | vs llvmpipe | vs softpipe | \
         error vs llvmpipe (>8, mean) | error vs softpipe (>8, mean) |\n\
         | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n"
    );
    for r in rows {
        out += &format!(
            "| `{}` | {:.1} | {} | {} | {} | {} | {} | {} |{}\n",
            r.workload.name(),
            r.tilegl_ms,
            ms(r.llvmpipe_ms),
            ms(r.softpipe_ms),
            speed(r.tilegl_ms, r.llvmpipe_ms),
            speed(r.tilegl_ms, r.softpipe_ms),
            err(&r.vs_llvmpipe),
            err(&r.vs_softpipe),
            if r.errors.is_empty() {
                String::new()
            } else {
                format!(" GL errors: {}", r.errors.join(", "))
            }
        );
    }
    out
}

//! The `tilegl` command line.
//!
//! With no subcommand (`cargo run --release`) it writes the teaching gallery into
//! `out/index.html` (every teaching scene and the built-in scenes on tilegl and on Mesa, with
//! the difference, the stages and the text, by the conformance crate's `gallery` tool);
//! `tilegl gallery DIR` does the same into `DIR`, `--tilegl-only` renders the built-in scenes
//! alone as PNGs. `run -- PROGRAM ARGS` runs an X11 GL program on tilegl's libGL.so.1.
//! `replay` and `dump` play and convert captures; `conformance` and `bench` run the
//! tilegl-conformance crate's tools.

mod run;
mod scenes;

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use clap::{Parser, Subcommand, ValueEnum};
use tilegl::enums::*;
use tilegl::{Context, ContextConfig, Gl};

/// Exit status of a subcommand that exists in the interface but is not available yet.
const NOT_AVAILABLE: u8 = 3;

#[derive(Parser, Debug)]
#[command(
    name = "tilegl",
    version,
    about = "An OpenGL 1.5 fixed-function driver emulated by a tile-based software rasterizer",
    long_about = "An OpenGL 1.5 fixed-function driver emulated by a tile-based software \
                  rasterizer.\n\nWithout a subcommand, writes the teaching gallery into \
                  out/index.html (the same as `tilegl gallery out`)."
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Replay an apitrace capture or a call script into PNGs, or compare it with reference
    /// pictures.
    ///
    /// Writes frame-NNNN.png (the back buffer just before swap N) for every frame, or those of
    /// --frames; with --calls, call-NNNNNNNNNN.png (the draw buffer right after call N) for
    /// each listed call (and frames only when --frames is given too). A capture that never
    /// swaps, replayed without --calls, gives the picture after its last call.
    Replay {
        /// An apitrace `.trace` file or a call script.
        file: PathBuf,
        /// Frames to render, `A..B` (swap A up to, not including, swap B), `A..` or `A`.
        #[arg(long, value_name = "A..B", value_parser = parse_frames)]
        frames: Option<Frames>,
        /// Call numbers after which to save the framebuffer (`call-NNNNNNNNNN.png`).
        #[arg(long, value_name = "N,M,...", value_delimiter = ',')]
        calls: Vec<u64>,
        /// Where to write the pictures.
        #[arg(short = 'o', long = "out", value_name = "DIR")]
        out: Option<PathBuf>,
        /// Compare with the reference pictures listed in DIR/frames.tsv.
        #[arg(long, value_name = "DIR")]
        compare: Option<PathBuf>,
        /// Draw `glEvalMesh2(GL_FILL)` as the specification's quad strips instead of the
        /// triangle strips Mesa draws (differs only for flat-shaded meshes).
        #[arg(long)]
        spec_meshes: bool,
        /// Draw `GL_POINT_SMOOTH` points with the specification's coverage instead of the
        /// full-colour discs Mesa draws.
        #[arg(long)]
        spec_points: bool,
    },
    /// Write an apitrace capture as a call script DIR/NAME.gl (large data in DIR/NAME.blobs/).
    Dump {
        /// An apitrace `.trace` file or a call script.
        file: PathBuf,
        /// Where to write the dump.
        #[arg(short = 'o', long = "out", value_name = "DIR", required = true)]
        out: PathBuf,
    },
    /// Run the conformance suite (lives in the tilegl-conformance crate).
    Conformance {
        /// Only cases whose name contains PATTERN.
        #[arg(long, value_name = "PATTERN")]
        filter: Option<String>,
        /// Compare against another implementation.
        #[arg(long, value_enum, value_name = "IMPL")]
        against: Option<Oracle>,
        /// Write the report into DIR.
        #[arg(long, value_name = "DIR")]
        report: Option<PathBuf>,
        /// The report's piglit table from a fresh run (the outputs of tests/piglit/run.sh on
        /// Mesa and on tilegl) instead of the committed record docs/piglit.md.
        #[arg(long, num_args = 2, value_names = ["MESA_TSV", "TILEGL_TSV"])]
        piglit: Option<Vec<PathBuf>>,
        /// Leave the quality-knob charts out of the report.
        #[arg(long)]
        no_quality: bool,
    },
    /// Run the benchmarks (live in the tilegl-conformance crate).
    Bench {
        /// Arguments for the benchmark runner.
        #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
        args: Vec<String>,
    },
    /// Run an unmodified X11 OpenGL program (GLX or EGL) on tilegl: puts the directory of
    /// tilegl's libGL.so.1 and libEGL.so.1 (beside this executable) first on LD_LIBRARY_PATH
    /// and runs PROGRAM in place of this process.
    Run {
        /// The program and its arguments (after `--`).
        #[arg(
            trailing_var_arg = true,
            allow_hyphen_values = true,
            required = true,
            value_name = "PROGRAM ARGS"
        )]
        program: Vec<std::ffi::OsString>,
    },
    /// Render the teaching gallery into DIR/index.html (default `out`): every teaching scene
    /// and the built-in scenes on tilegl and on Mesa, the difference, the stages and the text
    /// (runs the tilegl-conformance crate's `gallery` tool).
    Gallery {
        /// Output directory.
        #[arg(default_value = "out")]
        dir: PathBuf,
        /// Render only these scenes (repeatable); see --list.
        #[arg(long = "scene", value_name = "NAME")]
        scenes: Vec<String>,
        /// Framebuffer size for every scene instead of its own.
        #[arg(long, value_name = "WxH")]
        size: Option<String>,
        /// List the scenes and exit.
        #[arg(long)]
        list: bool,
        /// Worker threads for tile shading (0: one per core). The pictures are identical
        /// for any count.
        #[arg(long, default_value_t = 0)]
        threads: usize,
        /// Render only the built-in scenes, on tilegl alone, as DIR/NAME.png (no Mesa, no
        /// conformance crate needed).
        #[arg(long)]
        tilegl_only: bool,
    },
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum Oracle {
    /// Mesa's OSMesa (libOSMesa.so), loaded at run time.
    Mesa,
}

/// A range of frames (swap numbers): `start..end`, `end` exclusive, `None` = to the end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Frames {
    start: u64,
    end: Option<u64>,
}

fn parse_frames(s: &str) -> Result<Frames, String> {
    let num = |t: &str| {
        t.trim()
            .parse::<u64>()
            .map_err(|_| format!("`{t}` is not a frame number"))
    };
    let frames = match s.split_once("..") {
        None => {
            let n = num(s)?;
            Frames {
                start: n,
                end: Some(n + 1),
            }
        }
        Some((a, b)) => Frames {
            start: if a.is_empty() { 0 } else { num(a)? },
            end: if b.is_empty() { None } else { Some(num(b)?) },
        },
    };
    match frames.end {
        Some(end) if end <= frames.start => Err(format!("`{s}` is an empty range")),
        _ => Ok(frames),
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        None => conformance_tool("gallery", &["out".to_string()]),
        Some(Command::Gallery {
            dir,
            scenes,
            size,
            list,
            threads,
            tilegl_only,
        }) => {
            if tilegl_only {
                if list {
                    for s in scenes::SCENES {
                        println!("{:<14} {}x{}  {}", s.name, s.width, s.height, s.about);
                    }
                    return ExitCode::SUCCESS;
                }
                return gallery(&dir, &scenes, threads);
            }
            let mut args = vec![dir.display().to_string()];
            for s in scenes {
                args.extend(["--scene".to_string(), s]);
            }
            if let Some(size) = size {
                args.extend(["--size".to_string(), size]);
            }
            if threads != 0 {
                args.extend(["--threads".to_string(), threads.to_string()]);
            }
            if list {
                args.push("--list".to_string());
            }
            conformance_tool("gallery", &args)
        }
        Some(Command::Replay {
            file,
            frames,
            calls,
            out,
            compare,
            spec_meshes,
            spec_points,
        }) => {
            let mesh_fill = if spec_meshes {
                tilegl::MeshFill::QuadStrips
            } else {
                tilegl::MeshFill::TriangleStrips
            };
            let smooth_points = if spec_points {
                tilegl::SmoothPoints::Coverage
            } else {
                tilegl::SmoothPoints::Discs
            };
            replay(
                &file,
                frames,
                &calls,
                out.as_deref(),
                compare.as_deref(),
                (mesh_fill, smooth_points),
            )
        }
        Some(Command::Dump { file, out }) => dump(&file, &out),
        Some(Command::Run { program }) => run::run(&program),
        Some(Command::Conformance {
            filter,
            report,
            against,
            piglit,
            no_quality,
        }) => {
            let mut args = Vec::new();
            if let Some(pattern) = filter {
                args.extend(["--filter".to_string(), pattern]);
            }
            if let Some(dir) = report {
                args.extend(["--report".to_string(), dir.display().to_string()]);
            }
            if let Some(files) = piglit {
                args.push("--piglit".to_string());
                args.extend(files.iter().map(|f| f.display().to_string()));
            }
            if no_quality {
                args.push("--no-quality".to_string());
            }
            // Mesa (OSMesa) is the only oracle; the flag is accepted for it.
            let _ = against;
            conformance_tool("conformance", &args)
        }
        Some(Command::Bench { args }) => conformance_tool("bench", &args),
    }
}

/// Runs a tool of the tilegl-conformance crate (which depends on this one, so it cannot be
/// linked in): from the source tree with `cargo run --release` when this binary was built from
/// one and cargo is on the PATH (so the tool is never stale), else the tool built next to this
/// executable.
fn conformance_tool(bin: &str, args: &[String]) -> ExitCode {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml");
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut cmd = if manifest.is_file()
        && std::process::Command::new(&cargo)
            .arg("--version")
            .output()
            .is_ok_and(|o| o.status.success())
    {
        let mut c = std::process::Command::new(&cargo);
        c.args([
            "run",
            "--quiet",
            "--release",
            "-p",
            "tilegl-conformance",
            "--bin",
            bin,
        ])
        .arg("--manifest-path")
        .arg(&manifest)
        .arg("--");
        c
    } else {
        let sibling = std::env::current_exe()
            .ok()
            .map(|e| e.with_file_name(bin))
            .filter(|p| p.is_file());
        match sibling {
            Some(p) => std::process::Command::new(p),
            None => {
                return not_available(
                    bin,
                    &format!(
                        "it lives in the tilegl-conformance crate: build it with \
                         `cargo build --release -p tilegl-conformance --bin {bin}`"
                    ),
                )
            }
        }
    };
    match cmd.args(args).status() {
        Ok(s) if s.success() => ExitCode::SUCCESS,
        Ok(s) => ExitCode::from(s.code().unwrap_or(1).clamp(1, 255) as u8),
        Err(e) => {
            eprintln!("tilegl {bin}: cannot run the tool: {e}");
            ExitCode::from(3)
        }
    }
}

/// Exit status of `replay --compare` when a picture is out of tolerance.
const OUT_OF_TOLERANCE: u8 = 1;
/// Exit status when the replay itself failed (bad input, unwritable output).
const REPLAY_FAILED: u8 = 2;

/// A progress line on stderr, only when stderr is a terminal.
fn progress_printer() -> impl FnMut(&tilegl::replay::player::ReplayStats) {
    use std::io::IsTerminal;
    let on = std::io::stderr().is_terminal();
    move |s| {
        if on {
            eprint!("\r{} calls, {} frames ", s.calls, s.frames);
        }
    }
}

fn end_progress() {
    use std::io::IsTerminal;
    if std::io::stderr().is_terminal() {
        eprint!("\r\x1b[K");
    }
}

/// An apitrace capture or a call script (told apart by the first bytes), and whether it is a
/// script.
fn open_source(file: &Path) -> Result<(Box<dyn tilegl::replay::player::CallSource>, bool), String> {
    use std::io::Read;
    let mut head = [0u8; 2];
    let n = std::fs::File::open(file)
        .and_then(|mut f| f.read(&mut head))
        .map_err(|e| e.to_string())?;
    if tilegl::replay::script::looks_like_trace(&head[..n]) {
        let r = tilegl::replay::trace::TraceReader::open(file).map_err(|e| e.to_string())?;
        Ok((Box::new(r), false))
    } else {
        Ok((
            Box::new(tilegl::replay::script::ScriptReader::open(file)?),
            true,
        ))
    }
}

/// `tilegl dump FILE -o DIR`: the capture as a call script `DIR/NAME.gl`.
fn dump(file: &Path, out: &Path) -> ExitCode {
    let (mut reader, _) = match open_source(file) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("tilegl dump: {}: {e}", file.display());
            return ExitCode::from(REPLAY_FAILED);
        }
    };
    let name = file
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "dump".into());
    let header = format!(
        "tilegl call script, dumped from {} by `tilegl dump`.\n\
         Replay it with `tilegl replay {name}.gl`; call numbers are those of the capture.",
        file.display()
    );
    match tilegl::replay::script::dump(&mut *reader, out, &name, &header) {
        Ok((path, n)) => {
            println!("{}", path.display());
            eprintln!("tilegl dump: {n} calls");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("tilegl dump: {}: {e}", file.display());
            ExitCode::from(REPLAY_FAILED)
        }
    }
}

fn replay(
    file: &Path,
    frames: Option<Frames>,
    calls: &[u64],
    out: Option<&Path>,
    compare: Option<&Path>,
    (mesh_fill, smooth_points): (tilegl::MeshFill, tilegl::SmoothPoints),
) -> ExitCode {
    use tilegl::replay::player::{FrameSelection, Player, Want};
    let (mut reader, is_script) = match open_source(file) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("tilegl replay: {}: {e}", file.display());
            return ExitCode::from(REPLAY_FAILED);
        }
    };
    let new_player = || {
        let mut p = Player::new(0);
        p.auto_window = is_script;
        p.mesh_fill = mesh_fill;
        p.smooth_points = smooth_points;
        p
    };
    if let Some(out) = out {
        if let Err(e) = std::fs::create_dir_all(out) {
            eprintln!("tilegl replay: cannot create {}: {e}", out.display());
            return ExitCode::from(REPLAY_FAILED);
        }
    }
    let mut progress = progress_printer();
    if let Some(dir) = compare {
        if frames.is_some() || !calls.is_empty() {
            eprintln!("tilegl replay: --compare renders the pictures of frames.tsv; --frames and --calls are ignored");
        }
        let report = tilegl::replay::reference::compare_replay(
            &mut *reader,
            &mut new_player(),
            dir,
            out,
            &mut progress,
        );
        end_progress();
        let report = match report {
            Ok(r) => r,
            Err(e) => {
                eprintln!("tilegl replay: {e}");
                return ExitCode::from(REPLAY_FAILED);
            }
        };
        for p in &report.pictures {
            println!("{}", p.line());
        }
        for line in report.stats.report_lines() {
            eprintln!("tilegl replay: {line}");
        }
        if let Some(e) = &report.error {
            eprintln!("tilegl replay: {}: {e}", file.display());
        }
        println!("{}", report.summary());
        return if report.all_ok() {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(OUT_OF_TOLERANCE)
        };
    }
    let out = out.unwrap_or(Path::new("."));
    let frames_sel = match frames {
        Some(f) => FrameSelection::Range {
            start: f.start,
            end: f.end,
        },
        None if calls.is_empty() => FrameSelection::All,
        None => FrameSelection::None,
    };
    let want = Want {
        frames: frames_sel,
        calls: calls.iter().copied().collect(),
        // Stop after the last picture asked for (all frames: play to the end).
        stop_early: true,
    };
    let mut written = 0u64;
    let mut sink = |p: tilegl::replay::player::Picture| -> Result<(), String> {
        let path = out.join(&p.file);
        p.image
            .save_with_format(&path, image::ImageFormat::Png)
            .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        println!("{}", path.display());
        written += 1;
        Ok(())
    };
    let mut player = new_player();
    let result = player.play(&mut *reader, &want, &mut sink, &mut progress);
    end_progress();
    let stats = match result {
        Ok(s) => s,
        Err(e) => {
            for line in player.stats().report_lines() {
                eprintln!("tilegl replay: {line}");
            }
            eprintln!("tilegl replay: {}: {e}", file.display());
            return ExitCode::from(REPLAY_FAILED);
        }
    };
    // A capture that never swaps (piglit -auto): the picture after the last call.
    if stats.frames == 0 && calls.is_empty() && frames.is_none() {
        if let Some(last) = stats.last_call {
            if let Some(ctx) = player.last_context() {
                let rgba = ctx.color_image(ctx.draw_color_buffer());
                let image = image::DynamicImage::ImageRgba8(rgba).to_rgb8();
                let path = out.join(tilegl::replay::player::call_file(last));
                match image.save_with_format(&path, image::ImageFormat::Png) {
                    Ok(()) => {
                        println!("{}", path.display());
                        written += 1;
                    }
                    Err(e) => {
                        eprintln!("tilegl replay: cannot write {}: {e}", path.display());
                        return ExitCode::from(REPLAY_FAILED);
                    }
                }
            }
        }
    }
    for line in stats.report_lines() {
        eprintln!("tilegl replay: {line}");
    }
    eprintln!(
        "tilegl replay: {} calls, {} frames, {written} pictures",
        stats.calls, stats.frames
    );
    ExitCode::SUCCESS
}

fn not_available(command: &str, why: &str) -> ExitCode {
    eprintln!("tilegl {command}: not available in this build: {why}");
    ExitCode::from(NOT_AVAILABLE)
}

/// Renders the chosen built-in scenes (all when `only` is empty) into `dir`.
fn gallery(dir: &Path, only: &[String], threads: usize) -> ExitCode {
    if let Some(unknown) = only.iter().find(|n| scenes::find(n).is_none()) {
        let names: Vec<&str> = scenes::SCENES.iter().map(|s| s.name).collect();
        eprintln!(
            "tilegl: no built-in scene `{unknown}`; there are: {}",
            names.join(", ")
        );
        return ExitCode::FAILURE;
    }
    if let Err(e) = std::fs::create_dir_all(dir) {
        eprintln!("tilegl: cannot create {}: {e}", dir.display());
        return ExitCode::FAILURE;
    }
    let mut failed = false;
    let total = Instant::now();
    for scene in scenes::SCENES {
        if !only.is_empty() && !only.iter().any(|n| n == scene.name) {
            continue;
        }
        let path = dir.join(format!("{}.png", scene.name));
        match render(scene, &path, threads) {
            Ok(t) => println!(
                "{:<28} {:>8}  render, {:>8}  PNG   {}",
                path.display(),
                ms(t.render),
                ms(t.png),
                scene.about
            ),
            Err(e) => {
                eprintln!("{}: {e}", path.display());
                failed = true;
            }
        }
    }
    println!("total {}", ms(total.elapsed()));
    if failed {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}

struct Timing {
    render: Duration,
    png: Duration,
}

fn ms(d: Duration) -> String {
    format!("{:.2} ms", d.as_secs_f64() * 1e3)
}

/// Draws one scene (all GL calls until `glFinish` returns), then writes its PNG. A GL error
/// raised by the scene is a failure: the scenes use only implemented, valid calls.
fn render(scene: &scenes::Scene, path: &Path, threads: usize) -> Result<Timing, String> {
    let mut ctx = Context::with_config(ContextConfig {
        width: scene.width,
        height: scene.height,
        threads,
        ..ContextConfig::default()
    });
    let start = Instant::now();
    (scene.draw)(&mut ctx, scene.width, scene.height);
    ctx.finish();
    let render = start.elapsed();
    let error = ctx.get_error();
    if error != GL_NO_ERROR {
        return Err(format!("the scene raised GL error 0x{error:04X}"));
    }
    let start = Instant::now();
    tilegl::framebuffer::image::save_png(ctx.framebuffer(), path).map_err(|e| e.to_string())?;
    Ok(Timing {
        render,
        png: start.elapsed(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_parse() {
        let f = |start, end| Frames { start, end };
        assert_eq!(parse_frames("3..7"), Ok(f(3, Some(7))));
        assert_eq!(parse_frames("5"), Ok(f(5, Some(6))));
        assert_eq!(parse_frames("2.."), Ok(f(2, None)));
        assert_eq!(parse_frames("..4"), Ok(f(0, Some(4))));
        assert!(parse_frames("7..3").is_err());
        assert!(parse_frames("x..3").is_err());
    }

    #[test]
    fn cli_parses_the_documented_interfaces() {
        use clap::CommandFactory;
        Cli::command().debug_assert();
        let parse = |args: &[&str]| Cli::try_parse_from(args).map(|c| c.command);
        assert!(parse(&["tilegl"]).unwrap().is_none());
        let c = parse(&[
            "tilegl",
            "replay",
            "a.trace",
            "--frames",
            "0..10",
            "--calls",
            "1,5,9",
            "-o",
            "o",
            "--compare",
            "ref",
        ])
        .unwrap();
        match c {
            Some(Command::Replay { calls, frames, .. }) => {
                assert_eq!(calls, vec![1, 5, 9]);
                assert_eq!(frames.unwrap().end, Some(10));
            }
            other => panic!("{other:?}"),
        }
        assert!(
            parse(&["tilegl", "dump", "a.trace"]).is_err(),
            "-o is required"
        );
        assert!(parse(&["tilegl", "dump", "a.trace", "-o", "d"]).is_ok());
        assert!(parse(&[
            "tilegl",
            "conformance",
            "--filter",
            "depth",
            "--against",
            "mesa",
            "--report",
            "r"
        ])
        .is_ok());
        assert!(parse(&["tilegl", "conformance", "--against", "nvidia"]).is_err());
        assert!(parse(&[
            "tilegl",
            "conformance",
            "--report",
            "r",
            "--piglit",
            "m.tsv"
        ])
        .is_err());
        assert!(parse(&[
            "tilegl",
            "conformance",
            "--report",
            "r",
            "--piglit",
            "m.tsv",
            "t.tsv",
            "--no-quality"
        ])
        .is_ok());
        assert!(parse(&["tilegl", "bench", "--quick"]).is_ok());
        assert!(parse(&["tilegl", "gallery", "pics", "--scene", "clipping"]).is_ok());
        assert!(parse(&["tilegl", "gallery", "--scene", "ex_decal", "--size", "64x48"]).is_ok());
        assert!(parse(&["tilegl", "gallery", "--tilegl-only", "--list"]).is_ok());
    }
}

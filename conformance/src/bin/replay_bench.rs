//! `cargo run --release -p tilegl-conformance --bin replay_bench [-- TRACE...]`: replay
//! throughput. For each capture (default: every one in `conformance/traces/shared`, the
//! repository's copy of the shared corpus): the trace reader's parse speed (MB/s of the
//! decompressed stream), tilegl's replay (frames and calls per second, 2 worker threads, no
//! pictures written) and, where `xvfb-run` and apitrace's `glretrace`/`eglretrace` exist,
//! glretrace on Mesa llvmpipe in the same run (`--benchmark`), with the ratio. Piglit
//! captures never swap; their rate is in calls/s.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use tilegl::replay::player::{FrameSelection, Player, Want};
use tilegl::replay::trace::TraceReader;

fn parse_speed(path: &Path) -> Option<(u64, f64)> {
    let start = Instant::now();
    let mut reader = TraceReader::open(path).ok()?;
    while let Ok(Some(_)) = reader.next_call() {}
    Some((reader.offset(), start.elapsed().as_secs_f64()))
}

fn tilegl_replay(path: &Path) -> Option<(u64, u64, f64)> {
    let mut reader = TraceReader::open(path).ok()?;
    let mut player = Player::new(2);
    let want = Want {
        frames: FrameSelection::None,
        calls: Default::default(),
        stop_early: false,
    };
    let start = Instant::now();
    let stats = player
        .play(&mut reader, &want, &mut |_| Ok(()), &mut |_| {})
        .ok()?;
    Some((stats.frames, stats.calls, start.elapsed().as_secs_f64()))
}

/// glretrace's "Rendered N frames in X secs" for the capture, on llvmpipe under Xvfb.
fn glretrace(path: &Path) -> Option<(u64, f64)> {
    let egl = std::fs::read(path)
        .ok()
        .is_some_and(|b| b.windows(13).any(|w| w == b"eglMakeCurren"));
    let tool = if egl { "eglretrace" } else { "glretrace" };
    let out = Command::new("xvfb-run")
        .args(["-a", "-s", "-screen 0 1024x768x24", tool, "--benchmark"])
        .arg(path)
        .env("LIBGL_ALWAYS_SOFTWARE", "1")
        .env("GALLIUM_DRIVER", "llvmpipe")
        .output()
        .ok()?;
    let text =
        String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    let line = text.lines().find(|l| l.starts_with("Rendered "))?;
    let words: Vec<&str> = line.split_whitespace().collect();
    let frames = words.get(1)?.parse().ok()?;
    let secs = words.get(4)?.parse().ok()?;
    Some((frames, secs))
}

fn main() {
    let args: Vec<PathBuf> = std::env::args().skip(1).map(PathBuf::from).collect();
    let traces: Vec<PathBuf> = if args.is_empty() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("traces/shared");
        let mut v: Vec<PathBuf> = std::fs::read_dir(&dir)
            .map(|d| {
                d.filter_map(|e| e.ok().map(|e| e.path()))
                    .filter(|p| p.extension().is_some_and(|x| x == "trace"))
                    .collect()
            })
            .unwrap_or_default();
        v.sort();
        v
    } else {
        args
    };
    println!(
        "{:<40} {:>9} {:>7} {:>9} {:>11} {:>10} {:>11} {:>7}",
        "capture",
        "parse MB/s",
        "frames",
        "tilegl s",
        "tilegl fps",
        "calls/s",
        "glretrace s",
        "ratio"
    );
    for t in traces {
        let name = t
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let parse = parse_speed(&t);
        let Some((frames, calls, secs)) = tilegl_replay(&t) else {
            println!("{name:<40} replay failed");
            continue;
        };
        let mbs = parse.map_or(0.0, |(b, s)| b as f64 / 1e6 / s.max(1e-9));
        let gl = glretrace(&t);
        let (gl_s, ratio) = match gl {
            Some((_, s)) => (format!("{s:.3}"), format!("{:.2}x", s / secs.max(1e-9))),
            None => ("-".into(), "-".into()),
        };
        println!(
            "{:<40} {:>9.1} {:>7} {:>9.3} {:>11.1} {:>10.0} {:>11} {:>7}",
            name,
            mbs,
            frames,
            secs,
            frames as f64 / secs.max(1e-9),
            calls as f64 / secs.max(1e-9),
            gl_s,
            ratio
        );
    }
    println!("ratio = glretrace time / tilegl time (above 1: tilegl is faster)");
}

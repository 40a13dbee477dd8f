//! `gallery [DIR] [--scene NAME]... [--size WxH] [--threads N] [--no-mesa] [--list]`: the
//! teaching gallery (`tilegl_conformance::gallery`) into `DIR/index.html` (default `out`).
//! Run by `tilegl gallery` and by `cargo run --release` in the tilegl crate.

use std::path::PathBuf;
use std::process::ExitCode;

use tilegl_conformance::gallery;

fn usage() -> ExitCode {
    eprintln!(
        "usage: gallery [DIR] [--scene NAME]... [--size WxH] [--threads N] [--no-mesa] [--list]"
    );
    ExitCode::from(2)
}

fn parse_size(s: &str) -> Option<(i32, i32)> {
    let (w, h) = s.split_once(['x', 'X'])?;
    let (w, h) = (w.trim().parse().ok()?, h.trim().parse().ok()?);
    ((1..=4096).contains(&w) && (1..=4096).contains(&h)).then_some((w, h))
}

fn main() -> ExitCode {
    let mut opts = gallery::Options::default();
    let mut dir = None;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--scene" => match args.next() {
                Some(n) => opts.only.push(n),
                None => return usage(),
            },
            "--size" => match args.next().as_deref().and_then(parse_size) {
                Some(s) => opts.size = Some(s),
                None => {
                    eprintln!("gallery: --size wants WxH (1..4096 each)");
                    return usage();
                }
            },
            "--threads" => match args.next().and_then(|n| n.parse().ok()) {
                Some(n) => opts.threads = n,
                None => return usage(),
            },
            "--no-mesa" => opts.no_mesa = true,
            "--list" => {
                for e in gallery::entries() {
                    println!("{:<30} {:>4}x{:<4} {}", e.name, e.width, e.height, e.title);
                }
                return ExitCode::SUCCESS;
            }
            "-h" | "--help" => {
                usage();
                return ExitCode::SUCCESS;
            }
            s if s.starts_with('-') => return usage(),
            _ if dir.is_none() => dir = Some(PathBuf::from(a)),
            _ => return usage(),
        }
    }
    let dir = dir.unwrap_or_else(|| PathBuf::from("out"));
    let outcomes = match gallery::run(&opts) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("gallery: {e}");
            return ExitCode::from(2);
        }
    };
    for o in &outcomes {
        let mesa = match &o.mesa {
            Ok(m) => format!("Mesa {:8.1} ms", m.ms),
            Err(e) => e.clone(),
        };
        println!(
            "{:<30} tilegl {:8.1} ms   {mesa}",
            o.entry.name, o.tilegl.ms
        );
    }
    match gallery::write(&dir, &outcomes) {
        Ok(path) => {
            println!("wrote {}", path.display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("gallery: {e}");
            ExitCode::FAILURE
        }
    }
}

//! `cargo run --release -p tilegl-conformance --bin replay_mesa -- FILE.trace FRAME|cCALL W H [OUT_DIR]`:
//! plays a capture on Mesa (OSMesa, single-buffered) and on tilegl through the same dispatch,
//! and writes both pictures of frame FRAME (the buffer just before that swap) as PPM files,
//! printing their difference. A tool for finding where a replay starts to differ from Mesa.

use std::path::Path;

use tilegl::replay::dispatch::{dispatch, DispatchState, Outcome};
use tilegl::replay::trace::TraceReader;
use tilegl::Gl;
use tilegl_conformance::compare::{diff, Image};
use tilegl_conformance::mesa::{MesaContext, Oracle};

/// Plays until the `frame`-th swap, or (with `after_call`) until just after that call.
fn play(
    gl: &mut dyn Gl,
    trace: &Path,
    frame: u64,
    after_call: Option<u64>,
    w: i32,
    h: i32,
) -> Image {
    let mut reader = TraceReader::open(trace).expect("trace");
    let mut st = DispatchState::new();
    let mut swaps = 0;
    while let Ok(Some(call)) = reader.next_call() {
        if after_call.is_some_and(|n| call.no > n) {
            return Image::read(gl, w, h);
        }
        if call.name().ends_with("SwapBuffers") {
            if swaps == frame {
                return Image::read(gl, w, h);
            }
            swaps += 1;
            continue;
        }
        if let Outcome::WindowSystem = dispatch(gl, &call, &mut st) {
            continue;
        }
    }
    Image::read(gl, w, h)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() < 4 {
        eprintln!("usage: replay_mesa FILE.trace FRAME WIDTH HEIGHT [OUT_DIR]");
        std::process::exit(2);
    }
    let trace = Path::new(&args[0]);
    // FRAME, or cN for "right after call N".
    let (frame, after_call) = match args[1].strip_prefix('c') {
        Some(n) => (u64::MAX, Some(n.parse().expect("call number"))),
        None => (args[1].parse().expect("frame"), None),
    };
    let (w, h): (i32, i32) = (args[2].parse().expect("w"), args[3].parse().expect("h"));
    let out = Path::new(
        args.get(4)
            .map(|s| s.as_str())
            .unwrap_or("target/replay_mesa"),
    );
    let _ = std::fs::create_dir_all(out);
    let mut mesa = MesaContext::create(w, h).expect("Mesa");
    let m = play(&mut *mesa, trace, frame, after_call, w, h);
    let mut ctx = tilegl_conformance::client_context(tilegl::ContextConfig {
        width: w,
        height: h,
        ..Default::default()
    });
    let t = play(&mut ctx, trace, frame, after_call, w, h);
    println!("{}: tilegl vs Mesa {}", args[1], diff(&t, &m, 8));
    let _ = m.write_ppm(&out.join(format!("{}-mesa.ppm", args[1])));
    let _ = t.write_ppm(&out.join(format!("{}-tilegl.ppm", args[1])));
}

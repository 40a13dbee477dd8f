//! Memory: 10^5 create/delete cycles of textures, display lists, buffer objects and contexts
//! keep the resident memory flat (read from `/proc/self/statm`); a texture request of
//! 16384x16384 RGBA32F size gives the GL error Mesa gives (`GL_OUT_OF_MEMORY` once the size is
//! allowed, `GL_INVALID_VALUE` while it is above `GL_MAX_TEXTURE_SIZE`) without an abort and
//! without taking the memory; a capture whose blob claims gigabytes is refused with an error
//! naming the size, before the blob is read; replays hold their memory flat.
//!
//! The tests of this file run one at a time (a lock), so that one test's allocations do not
//! show in another's resident-memory figures.

use std::io::{Cursor, Read};
use std::sync::Mutex;

use tilegl::enums::*;
use tilegl::{Context, Gl};

mod common;

static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

fn lock() -> std::sync::MutexGuard<'static, ()> {
    ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner())
}

/// Resident memory of this process in bytes (`/proc/self/statm`, second field, in pages).
fn resident() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: u64 = text.split_whitespace().nth(1)?.parse().ok()?;
    Some(pages * 4096)
}

const CYCLES: usize = 100_000;

/// Runs `cycle` `CYCLES / 10` times to settle the allocator, then `CYCLES` times, and checks
/// that the resident memory grew by less than `slack` bytes over the second run (a leak of
/// `slack / CYCLES` bytes per cycle would exceed it). Returns the growth.
fn flat(what: &str, slack: u64, mut cycle: impl FnMut(usize)) -> i64 {
    let Some(_) = resident() else {
        assert!(
            !std::env::var("CI").is_ok_and(|v| v == "true" || v == "1"),
            "/proc/self/statm is needed in CI"
        );
        eprintln!("{what}: no /proc/self/statm here; not measured");
        return 0;
    };
    for i in 0..CYCLES / 10 {
        cycle(i);
    }
    let before = resident().unwrap();
    for i in 0..CYCLES {
        cycle(i);
    }
    let after = resident().unwrap();
    let growth = after as i64 - before as i64;
    eprintln!(
        "{what}: {CYCLES} cycles, resident {:.1} MiB -> {:.1} MiB ({:+} KiB)",
        before as f64 / 1048576.0,
        after as f64 / 1048576.0,
        growth / 1024
    );
    assert!(
        growth < slack as i64,
        "{what}: resident memory grew by {growth} bytes over {CYCLES} cycles"
    );
    growth
}

fn small_context() -> Context {
    common::threaded_context(32, 32, 1)
}

#[test]
fn texture_list_and_buffer_cycles_keep_memory_flat() {
    let _one = lock();
    let mut gl = small_context();
    let texels = vec![0x5au8; 16 * 16 * 4];
    // Each texture holds 1 KiB of texels and a generated mipmap chain; a leak of it per cycle
    // would be 100 MiB.
    flat("textures", 8 << 20, |i| {
        let mut name = [0u32];
        gl.gen_textures(1, &mut name);
        gl.bind_texture(GL_TEXTURE_2D, name[0]);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, (i % 2) as i32);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            16,
            16,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&texels),
        );
        gl.delete_textures(1, &name);
    });
    // A list of a few dozen recorded calls.
    flat("display lists", 8 << 20, |i| {
        let list = gl.gen_lists(1);
        gl.new_list(list, GL_COMPILE);
        gl.begin(GL_TRIANGLES);
        for k in 0..9 {
            gl.color_3f(k as f32 / 9.0, 0.5, (i % 7) as f32 / 7.0);
            gl.vertex_2f(k as f32, (k * k) as f32);
        }
        gl.end();
        gl.end_list();
        gl.delete_lists(list, 1);
    });
    // 1 KiB buffer objects, written once.
    let data = vec![7u8; 1024];
    flat("buffer objects", 8 << 20, |_| {
        let mut name = [0u32];
        gl.gen_buffers(1, &mut name);
        gl.bind_buffer(GL_ARRAY_BUFFER, name[0]);
        gl.buffer_data(GL_ARRAY_BUFFER, 1024, Some(&data), GL_STATIC_DRAW);
        gl.delete_buffers(1, &name);
    });
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn context_cycles_keep_memory_flat() {
    let _one = lock();
    // Each context has a 32x32 colour, depth and stencil buffer (a 64x64 tile: about 36 KiB)
    // and draws one triangle; a leak of it per cycle would be gigabytes.
    flat("contexts", 16 << 20, |i| {
        let mut gl = small_context();
        gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        gl.begin(GL_TRIANGLES);
        gl.vertex_2f(-1.0, -1.0);
        gl.vertex_2f(1.0, -1.0);
        gl.vertex_2f(0.0, (i % 3) as f32 * 0.5);
        gl.end();
        gl.finish();
    });
}

#[test]
fn a_planted_leak_is_caught() {
    let _one = lock();
    if resident().is_none() {
        return;
    }
    // 256 bytes written and forgotten per cycle: 25 MiB over the run.
    let caught = std::panic::catch_unwind(|| {
        flat("planted leak (its panic is expected)", 8 << 20, |i| {
            std::hint::black_box(Box::leak(vec![i as u8 | 1; 256].into_boxed_slice()));
        })
    });
    assert!(
        caught.is_err(),
        "a leak of 256 bytes per cycle went unnoticed"
    );
}

/// The error a texture image of `bytes` bytes and side `side` must give: Mesa's behaviour
/// (llvmpipe refuses images over 1 GiB with GL_OUT_OF_MEMORY), after the size check against
/// `GL_MAX_TEXTURE_SIZE`.
fn expected_error(side: i32, max: i32, bytes: u64) -> GLenum {
    if side > max {
        GL_INVALID_VALUE
    } else if bytes > 1 << 30 {
        GL_OUT_OF_MEMORY
    } else {
        GL_NO_ERROR
    }
}

#[test]
fn huge_textures_are_errors_not_aborts() {
    let _one = lock();
    let before = resident();
    let mut gl = small_context();
    let mut max = [0i32];
    gl.get_integerv(GL_MAX_TEXTURE_SIZE, &mut max);
    let mut max3 = [0i32];
    gl.get_integerv(GL_MAX_3D_TEXTURE_SIZE, &mut max3);
    // Whether the float format is accepted at all (a small image).
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA32F_ARB as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_FLOAT,
        None,
    );
    let float_ok = gl.get_error() == GL_NO_ERROR;
    let side = 16384;
    let cases: [(GLenum, u64, bool); 2] = [
        // 16384^2 texels of four 32-bit floats: 4 GiB.
        (GL_RGBA32F_ARB, 16, float_ok),
        // Of four 16-bit components: 2 GiB.
        (GL_RGBA16, 8, true),
    ];
    for (format, texel_bytes, accepted) in cases {
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            format as i32,
            side,
            side,
            0,
            GL_RGBA,
            GL_FLOAT,
            None,
        );
        let e = gl.get_error();
        let bytes = side as u64 * side as u64 * texel_bytes;
        let want = if accepted {
            expected_error(side, max[0], bytes)
        } else {
            // An internal format GL 1.5 does not accept (section 3.8.1): GL_INVALID_VALUE.
            GL_INVALID_VALUE
        };
        assert_eq!(e, want, "format 0x{format:04x}: 0x{e:04x}");
        // Nothing was specified: level 0 keeps the 1x1 image (or nothing).
        let mut w = [-1i32];
        gl.get_tex_level_parameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &mut w);
        assert!(w[0] <= 1, "width {}", w[0]);
    }
    // A 3D RGBA8 texture of side 2048 (Mesa's GL_MAX_3D_TEXTURE_SIZE): 32 GiB.
    {
        let side = 2048;
        gl.tex_image_3d(
            GL_TEXTURE_3D,
            0,
            GL_RGBA8 as i32,
            side,
            side,
            side,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            None,
        );
        let e = gl.get_error();
        let bytes = (side as u64).pow(3) * 4;
        assert_eq!(e, expected_error(side, max3[0], bytes), "3D side {side}");
    }
    // The context still works.
    gl.clear_color(0.0, 1.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    assert_eq!(common::pixel(&mut gl, 3, 3), [0, 255, 0, 255]);
    // And the refused requests took no memory.
    if let (Some(b), Some(a)) = (before, resident()) {
        assert!(
            a < b + (256 << 20),
            "resident {} MiB -> {} MiB",
            b >> 20,
            a >> 20
        );
    }
}

/// An apitrace snappy container (`at`, then length-prefixed chunks) whose first chunk is
/// `head` and whose next `zero_chunks` chunks are 1 MiB of zeros each; counts the chunks read.
struct LazyTrace {
    head: Cursor<Vec<u8>>,
    zeros: Vec<u8>,
    zero_chunks: usize,
    current: Cursor<Vec<u8>>,
    chunks_read: std::rc::Rc<std::cell::Cell<usize>>,
}

fn framed(data: &[u8]) -> Vec<u8> {
    let c = snap::raw::Encoder::new().compress_vec(data).unwrap();
    let mut out = (c.len() as u32).to_le_bytes().to_vec();
    out.extend(c);
    out
}

impl Read for LazyTrace {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.head.read(buf)?;
        if n > 0 {
            return Ok(n);
        }
        loop {
            let n = self.current.read(buf)?;
            if n > 0 || self.zero_chunks == 0 {
                return Ok(n);
            }
            self.zero_chunks -= 1;
            self.chunks_read.set(self.chunks_read.get() + 1);
            self.current = Cursor::new(self.zeros.clone());
        }
    }
}

fn varint(mut v: u64, out: &mut Vec<u8>) {
    loop {
        let b = (v & 0x7f) as u8;
        v >>= 7;
        if v == 0 {
            out.push(b);
            return;
        }
        out.push(b | 0x80);
    }
}

fn string(s: &str, out: &mut Vec<u8>) {
    varint(s.len() as u64, out);
    out.extend_from_slice(s.as_bytes());
}

/// A version-5 call stream: one `glBufferData(target, size, data, usage)` call whose `data`
/// blob claims `claim` bytes; the zeros that follow in the container are its content.
fn blob_call(claim: u64) -> Vec<u8> {
    let mut s = Vec::new();
    varint(5, &mut s); // version
    s.push(0x00); // call enter
    varint(0, &mut s); // thread
    varint(0, &mut s); // signature id, defined here
    string("glBufferData", &mut s);
    varint(4, &mut s);
    for a in ["target", "size", "data", "usage"] {
        string(a, &mut s);
    }
    s.push(0x01); // argument
    varint(2, &mut s);
    s.push(0x08); // blob
    varint(claim, &mut s);
    s
}

fn lazy_trace(claim: u64, zero_chunks: usize) -> (LazyTrace, std::rc::Rc<std::cell::Cell<usize>>) {
    let mut head = b"at".to_vec();
    head.extend(framed(&blob_call(claim)));
    let count = std::rc::Rc::new(std::cell::Cell::new(0));
    (
        LazyTrace {
            head: Cursor::new(head),
            zeros: framed(&vec![0u8; 1 << 20]),
            zero_chunks,
            current: Cursor::new(Vec::new()),
            chunks_read: count.clone(),
        },
        count,
    )
}

#[test]
fn a_capture_claiming_gigabytes_is_refused_before_reading() {
    let _one = lock();
    use tilegl::replay::trace::{TraceReader, MAX_BLOB};
    // 4 GiB claimed, backed by up to 4096 MiB of zeros: refused at once, naming the size.
    let claim = 4u64 << 30;
    let (trace, chunks) = lazy_trace(claim, 4096);
    let mut reader = TraceReader::new(Box::new(trace)).unwrap();
    let e = reader.next_call().expect_err("refused").to_string();
    assert!(
        e.contains(&claim.to_string()) && e.contains("refused") && e.contains("offset"),
        "{e}"
    );
    assert_eq!(chunks.get(), 0, "zeros read before refusing");
    // Just over the limit: refused too; at most the limit, read (here: the zeros run out first
    // and the reader says the capture is truncated).
    let (trace, _) = lazy_trace(MAX_BLOB + 1, 1);
    let mut reader = TraceReader::new(Box::new(trace)).unwrap();
    assert!(reader
        .next_call()
        .unwrap_err()
        .to_string()
        .contains("refused"));
    let (trace, chunks) = lazy_trace(3 << 20, 2);
    let mut reader = TraceReader::new(Box::new(trace)).unwrap();
    let e = reader.next_call().unwrap_err().to_string();
    assert!(e.contains("truncated"), "{e}");
    assert_eq!(chunks.get(), 2);
    // A claimed blob that is really there is read (the last zero ends the call's details).
    let (trace, _) = lazy_trace((1 << 20) - 1, 1);
    let mut reader = TraceReader::new(Box::new(trace)).unwrap();
    let call = reader
        .next_call()
        .unwrap()
        .expect("the call (incomplete: no leave)");
    assert_eq!(call.name(), "glBufferData");
    assert_eq!(call.arg(2).map(|v| v.len()), Some((1 << 20) - 1));
    // Through the command line: exit status 2 and the message.
    let dir = std::env::temp_dir().join(format!("tilegl-memory-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("claims-4gib.trace");
    let (mut trace, _) = lazy_trace(claim, 4);
    let mut bytes = Vec::new();
    trace.read_to_end(&mut bytes).unwrap();
    std::fs::write(&path, bytes).unwrap();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_tilegl"))
        .arg("replay")
        .arg(&path)
        .arg("-o")
        .arg(&dir)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("4294967296 bytes"), "{stderr}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Replays of the shared captures with the most frames (xss-flurry: 110) and the most calls
/// (xss-atlantis: 72 000), every frame snapshotted: within a replay the resident memory stays
/// flat once the capture's textures are loaded, and three rounds of the four replays end where
/// the first did.
#[test]
fn a_long_replay_holds_memory_flat() {
    let _one = lock();
    use tilegl::replay::player::{FrameSelection, Player, Want};
    use tilegl::replay::trace::TraceReader;
    if resident().is_none() {
        return;
    }
    let dir = common::shared_traces();
    let mut after_round = Vec::new();
    for round in 0..3 {
        for name in ["xss-flurry", "xss-glblur", "xss-cage", "xss-atlantis"] {
            let trace = common::require(&dir.join(format!("{name}.trace")));
            let mut player = Player::new(2);
            let want = Want {
                frames: FrameSelection::All,
                calls: Default::default(),
                stop_early: false,
            };
            let mut samples = Vec::new();
            player
                .play(
                    &mut TraceReader::open(&trace).unwrap(),
                    &want,
                    &mut |_| {
                        samples.push(resident().unwrap());
                        Ok(())
                    },
                    &mut |_| {},
                )
                .unwrap();
            assert!(samples.len() >= 10, "{name}: {} frames", samples.len());
            // From the end of the first third on (the capture's set-up is over).
            let settled = &samples[samples.len() / 3..];
            let low = *settled.iter().min().unwrap();
            let high = *settled.iter().max().unwrap();
            if round == 0 {
                eprintln!(
                    "{name}: {} frames, resident {:.1}-{:.1} MiB after the first third",
                    samples.len(),
                    low as f64 / 1048576.0,
                    high as f64 / 1048576.0
                );
            }
            assert!(
                high - low < 4 << 20,
                "{name}: resident memory grew from {low} to {high} bytes during the replay"
            );
        }
        after_round.push(resident().unwrap());
    }
    eprintln!(
        "replay rounds: resident after each {:?} MiB",
        after_round.iter().map(|r| r >> 20).collect::<Vec<_>>()
    );
    assert!(
        after_round[2] < after_round[0] + (4 << 20),
        "three rounds of replays: resident {after_round:?} bytes"
    );
}

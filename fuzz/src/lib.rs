//! The bodies of tilegl's coverage-guided fuzz targets. Each takes the fuzzer's bytes and may
//! only return: a panic (with debug assertions and overflow checks on in the fuzz build), an
//! abort, a hang or a memory blow-up is a finding. `fuzz/run` builds them into libFuzzer
//! binaries (`fuzz/bin/`); `tests/corpus.rs` replays every committed corpus and regression
//! input through the same functions in the normal test run.
//!
//! - [`trace_reader`]: the apitrace reader (`tilegl::replay::trace`), and the script writer
//!   on every call it returns (a written call must read back).
//! - [`call_script`]: the call-script reader (`tilegl::replay::script`).
//! - [`replay`]: the player over mutated captures (`tilegl::replay::player`).
//! - [`c_calls`]: structured GL call sequences through the exported C functions.
//!
//! Inputs that are not an apitrace container (`at`, snappy; `1f 8b`, gzip) are taken as a
//! decompressed call stream and put into a snappy container first, so the fuzzer mutates the
//! calls rather than the compression.

use std::io::Cursor;
use std::path::Path;

use tilegl::replay::player::{CallSource, FrameSelection, Player, Want};
use tilegl::replay::script::{looks_like_trace, write_call, ScriptReader};
use tilegl::replay::trace::{Call, TraceReader, Value};

mod c_calls;
pub use c_calls::c_calls;

/// Calls read from one input at most (keeps one input well under a second).
const MAX_CALLS: usize = 20_000;
/// Calls played from one input at most.
const MAX_PLAYED: usize = 4_000;
/// Largest window side a replayed input may ask for (fake `glViewport`).
const MAX_REPLAY_WINDOW: i64 = 128;
/// Make-current calls played from one input at most (each may create a context).
const MAX_MAKE_CURRENT: usize = 8;

/// The capture file of a fuzz input: an apitrace container as it is; anything else is a
/// decompressed call stream, put into apitrace's snappy container in 64 KiB chunks.
pub fn capture_bytes(data: &[u8]) -> Vec<u8> {
    if looks_like_trace(data) {
        return data.to_vec();
    }
    let mut out = b"at".to_vec();
    for chunk in data.chunks(1 << 16) {
        let c = snap::raw::Encoder::new()
            .compress_vec(chunk)
            .expect("snappy compresses any 64 KiB chunk");
        out.extend((c.len() as u32).to_le_bytes());
        out.extend(c);
    }
    out
}

/// The decompressed call stream of an apitrace snappy container (the inverse of
/// [`capture_bytes`]; used to make seed inputs), `None` if `file` is not one.
pub fn decompressed_stream(file: &[u8]) -> Option<Vec<u8>> {
    let mut rest = file.strip_prefix(b"at")?;
    let mut out = Vec::new();
    while rest.len() >= 4 {
        let len = u32::from_le_bytes(rest[..4].try_into().ok()?) as usize;
        let chunk = rest.get(4..4 + len)?;
        out.extend(snap::raw::Decoder::new().decompress_vec(chunk).ok()?);
        rest = &rest[4 + len..];
    }
    Some(out)
}

fn reader(data: &[u8]) -> Option<TraceReader> {
    TraceReader::new(Box::new(Cursor::new(capture_bytes(data)))).ok()
}

/// Whether `name` is written as a script identifier (other names cannot be written back).
fn is_identifier(name: &str) -> bool {
    let mut chars = name.chars();
    chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Target `trace_reader`: reads every call; each call with an identifier name is written as
/// a script statement (blobs inline), which must read back as the same function with as many
/// arguments.
pub fn trace_reader(data: &[u8]) {
    let Some(mut r) = reader(data) else {
        return;
    };
    let mut line = String::new();
    for _ in 0..MAX_CALLS {
        let call = match r.next_call() {
            Ok(Some(c)) => c,
            Ok(None) | Err(_) => return,
        };
        if !is_identifier(call.name()) {
            continue;
        }
        line.clear();
        let mut inline = |b: &[u8]| -> Result<String, String> {
            let hex: String = b.iter().map(|x| format!("{x:02x}")).collect();
            Ok(format!("hex(\"{hex}\")"))
        };
        write_call(&mut line, &call, &mut inline).expect("inline blobs cannot fail");
        let mut back = ScriptReader::new(line.as_bytes(), Path::new("/nonexistent"));
        match back.next_call() {
            Ok(Some(c)) => {
                assert_eq!(c.name(), call.name(), "{line}");
                assert_eq!(c.args.len(), call.args.len(), "{line}");
                assert_eq!(c.no, call.no, "{line}");
            }
            other => panic!("the written call does not read back: {other:?}\n{line}"),
        }
    }
}

/// Target `call_script`: reads every statement of a script (file references resolve in a
/// folder that does not exist).
pub fn call_script(data: &[u8]) {
    let mut r = ScriptReader::new(data, Path::new("/nonexistent/tilegl-fuzz"));
    for _ in 0..MAX_CALLS {
        match r.next_call() {
            Ok(Some(c)) => {
                let _ = c.name();
            }
            Ok(None) | Err(_) => return,
        }
    }
}

/// The calls of a capture, bounded for fuzzing: at most [`MAX_PLAYED`] calls and
/// [`MAX_MAKE_CURRENT`] make-current calls, window sizes at most [`MAX_REPLAY_WINDOW`].
struct Bounded<S> {
    inner: S,
    played: usize,
    make_current: usize,
}

impl<S: CallSource> CallSource for Bounded<S> {
    fn next_call(&mut self) -> Result<Option<Call>, String> {
        if self.played >= MAX_PLAYED {
            return Ok(None);
        }
        let Some(mut call) = self.inner.next_call()? else {
            return Ok(None);
        };
        self.played += 1;
        if call.name().contains("MakeCurrent") {
            self.make_current += 1;
            if self.make_current > MAX_MAKE_CURRENT {
                return Ok(None);
            }
        }
        if call.name() == "glViewport" && call.is_fake() {
            for a in call.args.iter_mut().skip(2) {
                if let Some(v) = a.as_ref().and_then(Value::as_i64) {
                    *a = Some(Value::SInt(v.clamp(-1, MAX_REPLAY_WINDOW)));
                }
            }
        }
        Ok(Some(call))
    }
}

/// Target `replay`: plays a (mutated) capture on one shading thread, snapshotting its first
/// two frames.
pub fn replay(data: &[u8]) {
    let Some(r) = reader(data) else {
        return;
    };
    let mut source = Bounded {
        inner: r,
        played: 0,
        make_current: 0,
    };
    let mut player = Player::new(1);
    let want = Want {
        frames: FrameSelection::Range {
            start: 0,
            end: Some(2),
        },
        calls: Default::default(),
        stop_early: false,
    };
    // A reader error or a panic inside the implementation is a `ReplayError` here; the fuzz
    // binaries and the corpus test catch panics with a panic hook.
    let _ = player.play(&mut source, &want, &mut |_| Ok(()), &mut |_| {});
}

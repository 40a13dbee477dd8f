//! Every committed corpus and regression input of each fuzz target (`fuzz/corpus/TARGET/`,
//! `fuzz/regressions/TARGET/`) through the target's function, without instrumentation: the
//! inputs the fuzzers found or were seeded with keep working, and a crash once found stays
//! fixed. A panic anywhere fails, also one the player catches and reports as a replay error.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, Once};

static PANICS: AtomicUsize = AtomicUsize::new(0);
/// The inputs being run, named by the panic hook: a panic inside an exported C function
/// aborts the process (it cannot unwind through `extern "C"`), so the hook is the only place
/// left to say which input it was.
static RUNNING: Mutex<Vec<String>> = Mutex::new(Vec::new());

/// Counts every panic (the player turns panics inside the implementation into errors, so a
/// returning call is no proof that none happened), after printing it as usual.
fn count_panics() {
    static HOOK: Once = Once::new();
    HOOK.call_once(|| {
        let default = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            PANICS.fetch_add(1, Ordering::SeqCst);
            default(info);
            if let Ok(running) = RUNNING.lock() {
                eprintln!("while running fuzz input(s): {}", running.join(", "));
            }
        }));
    });
}

fn inputs(target: &str) -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in ["corpus", "regressions"] {
        let Ok(entries) = std::fs::read_dir(root.join(dir).join(target)) else {
            continue;
        };
        files.extend(entries.map(|e| e.unwrap().path()).filter(|p| p.is_file()));
    }
    files.sort();
    files
}

fn replay_all(target: &str, run: fn(&[u8])) {
    count_panics();
    let files = inputs(target);
    for f in &files {
        let data = std::fs::read(f).unwrap();
        let name = f.display().to_string();
        RUNNING.lock().unwrap().push(name.clone());
        let before = PANICS.load(Ordering::SeqCst);
        let result = std::panic::catch_unwind(|| run(&data));
        RUNNING.lock().unwrap().retain(|n| *n != name);
        assert!(
            result.is_ok() && PANICS.load(Ordering::SeqCst) == before,
            "{target}: {} panicked (see above)",
            f.display()
        );
    }
    // The corpus is committed: a nearly empty one means it went missing.
    assert!(
        files.len() >= 10,
        "fuzz/corpus/{target}/ has {} inputs; expected the committed corpus",
        files.len()
    );
    println!("{target}: {} inputs", files.len());
}

#[test]
fn trace_reader_corpus() {
    replay_all("trace_reader", tilegl_fuzz::trace_reader);
}

#[test]
fn call_script_corpus() {
    replay_all("call_script", tilegl_fuzz::call_script);
}

#[test]
fn replay_corpus() {
    replay_all("replay", tilegl_fuzz::replay);
}

#[test]
fn c_calls_corpus() {
    replay_all("c_calls", tilegl_fuzz::c_calls);
}

//! The apitrace reader against the shared captures (the repository's copy): every call is read, call numbers match
//! what apitrace itself recorded in each `frames.tsv` (call number and function name), and
//! damaged input gives an error naming an offset instead of a panic.

use std::collections::HashMap;
use std::io::Cursor;
use std::path::{Path, PathBuf};

use tilegl::replay::trace::TraceReader;

mod common;

/// The repository's copy of the shared captures (the test fails when it is missing).
fn traces_dir() -> PathBuf {
    common::shared_traces()
}

fn traces(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "trace"))
        .collect();
    v.sort();
    v
}

#[test]
fn every_shared_capture_reads_to_the_end_with_apitrace_call_numbers() {
    let dir = traces_dir();
    let list = traces(&dir);
    assert!(
        list.len() >= 20,
        "expected the shared corpus, found {}",
        list.len()
    );
    for path in list {
        let mut reader = TraceReader::open(&path).unwrap();
        let mut names: HashMap<u64, String> = HashMap::new();
        while let Some(call) = reader.next_call().unwrap() {
            assert!(
                !call.incomplete,
                "{}: call {} incomplete",
                path.display(),
                call.no
            );
            let previous = names.insert(call.no, call.name().to_string());
            assert!(
                previous.is_none(),
                "{}: call {} twice",
                path.display(),
                call.no
            );
        }
        let last = *names.keys().max().unwrap();
        assert_eq!(
            names.len() as u64,
            last + 1,
            "{}: gaps in call numbers",
            path.display()
        );
        // frames.tsv was written by apitrace: its call numbers name the snapshot calls.
        let tsv = path.with_extension("frames").join("frames.tsv");
        let text = std::fs::read_to_string(common::require(&tsv)).unwrap();
        for line in text.lines().skip(1) {
            let cols: Vec<&str> = line.split('\t').collect();
            let no: u64 = cols[2].parse().unwrap();
            let name = &names[&no];
            assert_eq!(name, cols[3], "{}: call {no}", path.display());
        }
    }
}

#[test]
fn truncated_and_corrupted_captures_give_errors_not_panics() {
    let bytes = std::fs::read(common::require(&traces_dir().join("glxgears.trace"))).unwrap();
    let read_all = |data: Vec<u8>| -> Result<u64, String> {
        let mut reader =
            TraceReader::new(Box::new(Cursor::new(data))).map_err(|e| e.to_string())?;
        let mut n = 0;
        loop {
            match reader.next_call() {
                Ok(Some(_)) => n += 1,
                Ok(None) => return Ok(n),
                Err(e) => {
                    assert!(e.to_string().contains("offset"), "{e}");
                    return Err(e.to_string());
                }
            }
        }
    };
    let full = read_all(bytes.clone()).unwrap();
    // Truncation: never more calls than the whole file, and a cut inside the data is noticed.
    for cut in (0..bytes.len()).step_by(997) {
        if let Ok(n) = read_all(bytes[..cut].to_vec()) {
            assert!(n <= full)
        }
    }
    assert!(read_all(bytes[..bytes.len() / 2].to_vec()).is_err());
    // Corruption: flipped bytes anywhere never panic.
    let mut state = 0x2545_f491_u32;
    for _ in 0..200 {
        let mut damaged = bytes.clone();
        for _ in 0..4 {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            let at = state as usize % damaged.len();
            damaged[at] ^= (state >> 8) as u8 | 1;
        }
        let _ = read_all(damaged);
    }
}

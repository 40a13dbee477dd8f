//! The C ABI from C: compiles `tests/capi/*.c` (plain OSMesa programs using only
//! `<GL/gl.h>` and `<GL/osmesa.h>`) against `libtilegl.so`, runs them and expects exit status 0.
//! The programs check their pixels themselves, with expectations derived from the geometry.
//!
//! `cargo test` builds the cdylib `libtilegl.so` with the library, next to the test
//! executable's `deps/` directory. When `cc` or the GL/OSMesa headers are missing the test is
//! skipped with a message, except in CI (`CI=true`), where it fails.
//!
//! Where Mesa's own `libOSMesa.so` is installed for linking, each program is also built and
//! run against it, as a check that the program's expectations are right.

use std::path::{Path, PathBuf};
use std::process::Command;

fn in_ci() -> bool {
    std::env::var("CI").is_ok_and(|v| v == "true" || v == "1")
}

/// Skips (prints why) outside CI; fails in CI.
fn skip_or_fail(why: &str) {
    if in_ci() {
        panic!("CI=true and {why}");
    }
    eprintln!(
        "SKIPPED tests/capi.rs: {why} (install a C compiler, mesa-common-dev and libosmesa6-dev)"
    );
}

/// `target/<profile>`: the test executable lives in `target/<profile>/deps/`.
fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("current_exe");
    let deps = exe.parent().expect("test executable has a directory");
    if deps.ends_with("deps") {
        deps.parent().unwrap().to_path_buf()
    } else {
        deps.to_path_buf()
    }
}

/// The directory holding the freshest `libtilegl.so` (`target/<profile>` or its `deps/`).
fn library_dir() -> Option<PathBuf> {
    let profile = profile_dir();
    [profile.clone(), profile.join("deps")]
        .into_iter()
        .filter_map(|d| {
            let t = std::fs::metadata(d.join("libtilegl.so"))
                .and_then(|m| m.modified())
                .ok()?;
            Some((t, d))
        })
        .max_by_key(|(t, _)| *t)
        .map(|(_, d)| d)
}

/// Whether `cc` can compile a file including the two headers.
fn toolchain_problem(scratch: &Path) -> Option<String> {
    let probe = scratch.join("probe.c");
    std::fs::write(
        &probe,
        "#include <GL/gl.h>\n#include <GL/osmesa.h>\nint main(void) { return 0; }\n",
    )
    .expect("write probe");
    match Command::new("cc").arg("-fsyntax-only").arg(&probe).output() {
        Err(e) => Some(format!("no C compiler `cc` ({e})")),
        Ok(o) if !o.status.success() => Some(format!(
            "`cc` cannot compile with <GL/gl.h> and <GL/osmesa.h>: {}",
            String::from_utf8_lossy(&o.stderr).trim()
        )),
        Ok(_) => None,
    }
}

/// Compiles `source` linked with `-l<lib>` from `lib_dir` (or the system's) into `exe`.
fn compile(source: &Path, exe: &Path, lib_dir: Option<&Path>, lib: &str) -> Result<(), String> {
    let mut cmd = Command::new("cc");
    cmd.arg("-std=c99").arg("-Wall").arg(source);
    if let Some(dir) = lib_dir {
        cmd.arg(format!("-L{}", dir.display()))
            .arg(format!("-Wl,-rpath,{}", dir.display()));
    }
    cmd.arg(format!("-l{lib}")).arg("-o").arg(exe);
    let out = cmd.output().map_err(|e| format!("running cc: {e}"))?;
    if out.status.success() {
        Ok(())
    } else {
        Err(format!(
            "{cmd:?} failed:\n{}",
            String::from_utf8_lossy(&out.stderr)
        ))
    }
}

/// Runs `exe` (with `LD_LIBRARY_PATH=lib_dir`); returns whether it succeeded and its output.
fn run(exe: &Path, lib_dir: Option<&Path>) -> (bool, String) {
    let mut cmd = Command::new(exe);
    if let Some(dir) = lib_dir {
        let mut path = std::ffi::OsString::from(dir);
        if let Some(old) = std::env::var_os("LD_LIBRARY_PATH") {
            path.push(":");
            path.push(old);
        }
        cmd.env("LD_LIBRARY_PATH", path);
    }
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("running {}: {e}", exe.display()));
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    (out.status.success(), text)
}

fn c_programs() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/capi");
    let mut v: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "c"))
        .collect();
    v.sort();
    assert!(!v.is_empty(), "no C programs in {}", dir.display());
    v
}

#[test]
fn c_programs_run_against_libtilegl() {
    let scratch = Path::new(env!("CARGO_TARGET_TMPDIR")).join("capi");
    std::fs::create_dir_all(&scratch).expect("create scratch dir");
    if let Some(problem) = toolchain_problem(&scratch) {
        skip_or_fail(&problem);
        return;
    }
    let lib_dir = library_dir().unwrap_or_else(|| {
        panic!(
            "libtilegl.so not found in {} or its deps/ (cargo test builds it with the library)",
            profile_dir().display()
        )
    });
    println!("linking against {}", lib_dir.join("libtilegl.so").display());

    let mut failed = Vec::new();
    for source in c_programs() {
        let stem = source.file_stem().unwrap().to_string_lossy().into_owned();
        let exe = scratch.join(&stem);
        compile(&source, &exe, Some(&lib_dir), "tilegl").unwrap_or_else(|e| panic!("{e}"));
        let (ok, output) = run(&exe, Some(&lib_dir));
        println!("--- {stem} on tilegl ---\n{output}");
        if !ok {
            failed.push(stem);
        }
    }
    assert!(failed.is_empty(), "failed on tilegl: {failed:?}");
}

/// The same programs on Mesa's OSMesa, when it is installed for linking: if this fails, the
/// program's expectations are wrong, not tilegl.
#[test]
fn c_programs_expectations_hold_on_mesa() {
    let scratch = Path::new(env!("CARGO_TARGET_TMPDIR")).join("capi-mesa");
    std::fs::create_dir_all(&scratch).expect("create scratch dir");
    if let Some(problem) = toolchain_problem(&scratch) {
        skip_or_fail(&problem);
        return;
    }
    let mut failed = Vec::new();
    for source in c_programs() {
        let stem = source.file_stem().unwrap().to_string_lossy().into_owned();
        let exe = scratch.join(&stem);
        if let Err(e) = compile(&source, &exe, None, "OSMesa") {
            eprintln!("SKIPPED the Mesa cross-check: cannot link -lOSMesa ({e})");
            return;
        }
        let (ok, output) = run(&exe, None);
        println!("--- {stem} on Mesa ---\n{output}");
        if !ok {
            failed.push(stem);
        }
    }
    assert!(failed.is_empty(), "failed on Mesa: {failed:?}");
}

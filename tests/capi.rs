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
    cmd.arg("-std=c99").arg("-Wall").arg("-Werror").arg(source);
    if lib == "tilegl" {
        // tilegl's own headers (generated from the registry), not the system's.
        cmd.arg(format!("-I{}/include", env!("CARGO_MANIFEST_DIR")));
    }
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
            skip_or_fail(&format!(
                "cannot link -lOSMesa for the Mesa cross-check ({e})"
            ));
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

/// A section of a comparison program's output: a name and its bytes.
fn sections(output: &str) -> Vec<(String, Vec<u8>)> {
    let mut out: Vec<(String, Vec<u8>)> = Vec::new();
    for line in output.lines() {
        if let Some((name, _count)) = line.split_once(' ') {
            out.push((name.to_string(), Vec::new()));
        } else if let Some((_, bytes)) = out.last_mut() {
            for i in (0..line.len()).step_by(2) {
                let byte = line
                    .get(i..i + 2)
                    .and_then(|h| u8::from_str_radix(h, 16).ok())
                    .unwrap_or_else(|| panic!("bad hex line {line:?}"));
                bytes.push(byte);
            }
        }
    }
    out
}

/// How far tilegl's bytes of a section may be from Mesa's. GL leaves float-to-fixed rounding
/// to the implementation (one step of 1/255); `GL_RGB5` is stored with 5 bits per channel by
/// tilegl and as RGB565 by Mesa (the specification lets the implementation choose), so that
/// section may differ by one 5-bit step.
fn section_tolerance(name: &str) -> u8 {
    if name.starts_with("rgb565") {
        9
    } else {
        1
    }
}

/// C programs that print named sections of bytes (`tests/capi/compare/*.c`: pixel uploads,
/// read-backs, pixel maps, compressed images, pictures), run on tilegl and on Mesa's OSMesa:
/// every section must agree within its tolerance, and the programs must have printed
/// something. Needs Mesa's `libOSMesa.so` for linking (libosmesa6-dev); fails in CI without it.
#[test]
fn c_pixel_programs_match_mesa() {
    let scratch = Path::new(env!("CARGO_TARGET_TMPDIR")).join("capi-compare");
    std::fs::create_dir_all(&scratch).expect("create scratch dir");
    if let Some(problem) = toolchain_problem(&scratch) {
        skip_or_fail(&problem);
        return;
    }
    let lib_dir = library_dir().expect("libtilegl.so built with the library");
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/capi/compare");
    let mut programs: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "c"))
        .collect();
    programs.sort();
    assert!(!programs.is_empty(), "no programs in {}", dir.display());
    let mut failures = Vec::new();
    for source in programs {
        let stem = source.file_stem().unwrap().to_string_lossy().into_owned();
        let on_tilegl = scratch.join(format!("{stem}-tilegl"));
        let on_mesa = scratch.join(format!("{stem}-mesa"));
        compile(&source, &on_tilegl, Some(&lib_dir), "tilegl").unwrap_or_else(|e| panic!("{e}"));
        if let Err(e) = compile(&source, &on_mesa, None, "OSMesa") {
            skip_or_fail(&format!("cannot link -lOSMesa ({e})"));
            return;
        }
        let (ok_t, out_t) = run(&on_tilegl, Some(&lib_dir));
        let (ok_m, out_m) = run(&on_mesa, None);
        assert!(ok_t && ok_m, "{stem}: tilegl ok {ok_t}, Mesa ok {ok_m}");
        let (t, m) = (sections(&out_t), sections(&out_m));
        assert!(t.len() > 10, "{stem}: only {} sections on tilegl", t.len());
        assert_eq!(
            t.iter().map(|s| &s.0).collect::<Vec<_>>(),
            m.iter().map(|s| &s.0).collect::<Vec<_>>(),
            "{stem}: sections differ"
        );
        for ((name, a), (_, b)) in t.iter().zip(&m) {
            if name == "pixelmap-i-uiv" {
                // Judged by the specification (section 6.1.3: index maps return the indices
                // set), not by Mesa 22, which answers 0xfffffffd, 0xfffffffe, 0xffffffff, 0.
                let expect: Vec<u8> = [3u32, 2, 1, 0]
                    .iter()
                    .flat_map(|v| v.to_ne_bytes())
                    .collect();
                if a != &expect {
                    failures.push(format!("{stem}/{name}: {a:?}, the spec says {expect:?}"));
                }
                continue;
            }
            let tol = section_tolerance(name);
            let off: Vec<usize> = (0..a.len().min(b.len()))
                .filter(|&i| a[i].abs_diff(b[i]) > tol)
                .collect();
            if a.len() != b.len() || !off.is_empty() {
                failures.push(format!(
                    "{stem}/{name}: {} of {} bytes off by more than {tol} (first at {:?}: tilegl {:?} mesa {:?})",
                    off.len(),
                    a.len(),
                    off.first(),
                    off.first().map(|&i| a[i]),
                    off.first().map(|&i| b[i]),
                ));
            }
        }
        println!("{stem}: {} sections compared with Mesa", t.len());
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// `include/GL/gl.h` and `include/GL/glext.h` are what `build.rs` generates from the registry
/// (the C programs above compile against them). After a change to the generator, refresh them
/// with `TILEGL_BLESS_HEADERS=1 cargo test -p tilegl --test capi`.
#[test]
fn c_headers_are_the_generated_ones() {
    let include = Path::new(env!("CARGO_MANIFEST_DIR")).join("include/GL");
    for name in ["gl.h", "glext.h"] {
        let generated = std::fs::read_to_string(Path::new(env!("OUT_DIR")).join(name))
            .unwrap_or_else(|e| panic!("generated {name}: {e}"));
        let path = include.join(name);
        if std::env::var_os("TILEGL_BLESS_HEADERS").is_some() {
            std::fs::write(&path, &generated).expect("write header");
        }
        let committed =
            std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(
            committed == generated,
            "{} is not what build.rs generates: run TILEGL_BLESS_HEADERS=1 cargo test -p tilegl --test capi",
            path.display()
        );
    }
}

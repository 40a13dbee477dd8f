//! `tilegl run -- PROGRAM ARGS...`: runs an unmodified X11 OpenGL program on tilegl by putting
//! the directory of tilegl's `libGL.so.1` and `libEGL.so.1` first on `LD_LIBRARY_PATH` and
//! replacing this process with the program.

use std::ffi::{OsStr, OsString};
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

/// The directory holding tilegl's `libGL.so.1`: the one of this executable (`cargo build`
/// puts both in `target/<profile>/`), or `$TILEGL_LIB_DIR` when set.
fn library_dir() -> Result<PathBuf, String> {
    let dir = match std::env::var_os("TILEGL_LIB_DIR") {
        Some(d) => PathBuf::from(d),
        None => std::env::current_exe()
            .map_err(|e| format!("cannot find this executable: {e}"))?
            .parent()
            .map(Path::to_path_buf)
            .ok_or("this executable has no directory")?,
    };
    for lib in ["libGL.so.1", "libEGL.so.1"] {
        // `exists` follows the link: it fails for a link to a library not built yet.
        if !dir.join(lib).exists() {
            return Err(format!(
                "{} not found (build it with `cargo build --release`, or set TILEGL_LIB_DIR)",
                dir.join(lib).display()
            ));
        }
    }
    Ok(dir)
}

/// `LD_LIBRARY_PATH` with `dir` first.
fn library_path(dir: &Path, old: Option<&OsStr>) -> OsString {
    let mut path = OsString::from(dir);
    if let Some(old) = old.filter(|o| !o.is_empty()) {
        path.push(":");
        path.push(old);
    }
    path
}

pub fn run(program: &[OsString]) -> ExitCode {
    let Some((exe, args)) = program.split_first() else {
        eprintln!("tilegl run: no program given (tilegl run -- PROGRAM ARGS...)");
        return ExitCode::from(2);
    };
    let dir = match library_dir() {
        Ok(d) => d,
        Err(e) => {
            eprintln!("tilegl run: {e}");
            return ExitCode::from(1);
        }
    };
    let path = library_path(&dir, std::env::var_os("LD_LIBRARY_PATH").as_deref());
    // `exec` returns only on failure.
    let err = Command::new(exe)
        .args(args)
        .env("LD_LIBRARY_PATH", path)
        .exec();
    eprintln!("tilegl run: cannot run {}: {err}", exe.to_string_lossy());
    ExitCode::from(if err.kind() == std::io::ErrorKind::NotFound {
        127
    } else {
        126
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn library_path_puts_tilegl_first() {
        let d = Path::new("/x/target/release");
        assert_eq!(library_path(d, None), OsString::from("/x/target/release"));
        assert_eq!(
            library_path(d, Some(OsStr::new(""))),
            OsString::from("/x/target/release")
        );
        assert_eq!(
            library_path(d, Some(OsStr::new("/usr/local/lib"))),
            OsString::from("/x/target/release:/usr/local/lib")
        );
    }
}

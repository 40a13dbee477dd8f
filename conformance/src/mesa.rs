//! The Mesa oracle: an OSMesa context loaded at run time with `libloading`, driven through
//! tilegl's own `Gl` trait (via [`tilegl::capi::ForeignGl`]), so every scene and test can run
//! unchanged on tilegl and on Mesa.
//!
//! The loader sits behind the [`Oracle`] trait (`create(width, height)`, `gl()`, `info()`), so an
//! EGL/surfaceless llvmpipe context could replace OSMesa later without touching the tests.
//!
//! This is the only module of the crate with `unsafe` code.
//!
//! Mesa picks its Gallium driver (`GALLIUM_DRIVER=llvmpipe|softpipe`) once, when the first
//! context of the process is created, so one process sees one driver. To get a picture from the
//! other driver, [`run_self_with_driver`] re-runs the current executable as a child process with
//! `GALLIUM_DRIVER` set (see `compare::render_scene_with_driver`).

use std::ffi::{c_char, c_void, CStr};
use std::fmt;
use std::ops::{Deref, DerefMut};
use std::sync::OnceLock;

use tilegl::capi::ForeignGl;
use tilegl::enums::*;
use tilegl::Gl;

/// Library names tried in order.
pub const LIBRARY_NAMES: [&str; 3] = ["libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"];

/// Why the oracle cannot give an answer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum OracleError {
    /// No OSMesa library could be loaded (the message lists what was tried).
    NotFound(String),
    /// The library lacks a required OSMesa entry point.
    MissingSymbol(String),
    /// `OSMesaCreateContextExt` returned NULL.
    CreateContext,
    /// `OSMesaMakeCurrent` failed.
    MakeCurrent,
    /// Width or height out of range.
    BadSize(i32, i32),
    /// A child process run with another `GALLIUM_DRIVER` failed.
    Subprocess(String),
}

impl fmt::Display for OracleError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OracleError::NotFound(s) => write!(f, "Mesa not found: {s}"),
            OracleError::MissingSymbol(s) => write!(f, "OSMesa symbol missing: {s}"),
            OracleError::CreateContext => write!(f, "OSMesaCreateContextExt failed"),
            OracleError::MakeCurrent => write!(f, "OSMesaMakeCurrent failed"),
            OracleError::BadSize(w, h) => write!(f, "bad oracle framebuffer size {w}x{h}"),
            OracleError::Subprocess(s) => write!(f, "oracle subprocess failed: {s}"),
        }
    }
}

impl std::error::Error for OracleError {}

/// What the oracle reports about itself (`glGetString`).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct OracleInfo {
    /// `GL_VERSION`, e.g. `2.1 Mesa 22.3.6`.
    pub version: String,
    /// `GL_RENDERER`, e.g. `llvmpipe (LLVM 15.0.6, 256 bits)` or `softpipe`.
    pub renderer: String,
}

impl OracleInfo {
    /// The Gallium driver name: the first word of `GL_RENDERER` (`llvmpipe`, `softpipe`).
    pub fn driver(&self) -> &str {
        self.renderer.split_whitespace().next().unwrap_or("")
    }
}

impl fmt::Display for OracleInfo {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} / {}", self.renderer, self.version)
    }
}

/// A reference GL implementation with its own framebuffer. Implemented by [`MesaContext`]; an
/// EGL-based context would implement the same trait.
pub trait Oracle: Sized {
    /// A context with a `width` x `height` RGBA8 colour buffer, 24-bit depth and 8-bit stencil,
    /// current on the calling thread.
    fn create(width: i32, height: i32) -> Result<Self, OracleError>;
    /// The GL entry points of this context.
    fn gl(&mut self) -> &mut dyn Gl;
    /// Version and renderer strings.
    fn info(&self) -> &OracleInfo;
}

type CreateContextExtFn = unsafe extern "C" fn(u32, i32, i32, i32, *mut c_void) -> *mut c_void;
type MakeCurrentFn = unsafe extern "C" fn(*mut c_void, *mut c_void, u32, i32, i32) -> u8;
type DestroyContextFn = unsafe extern "C" fn(*mut c_void);
type GetProcAddressFn = unsafe extern "C" fn(*const c_char) -> *const c_void;

/// The loaded library and its OSMesa entry points. Loaded once per process and never unloaded
/// (Mesa's worker threads and atexit handlers do not survive `dlclose`).
struct OsMesaLib {
    _lib: libloading::Library,
    create_context_ext: CreateContextExtFn,
    make_current: MakeCurrentFn,
    destroy_context: DestroyContextFn,
    get_proc_address: GetProcAddressFn,
}

fn load_library() -> Result<OsMesaLib, OracleError> {
    let mut tried = Vec::new();
    let names: Vec<String> = match std::env::var("TILEGL_OSMESA") {
        Ok(p) if !p.is_empty() => vec![p],
        _ => LIBRARY_NAMES.iter().map(|s| s.to_string()).collect(),
    };
    for name in &names {
        // SAFETY: loading libOSMesa runs its initialisers, which have no preconditions; the
        // library is kept for the whole process (stored in a static), so symbols stay valid.
        let lib = match unsafe { libloading::Library::new(name.as_str()) } {
            Ok(lib) => lib,
            Err(e) => {
                tried.push(format!("{name}: {e}"));
                continue;
            }
        };
        // SAFETY: the function types match the prototypes of `GL/osmesa.h` (Mesa 6.3+):
        // OSMesaCreateContextExt(GLenum, GLint, GLint, GLint, OSMesaContext) -> OSMesaContext,
        // OSMesaMakeCurrent(OSMesaContext, void*, GLenum, GLsizei, GLsizei) -> GLboolean,
        // OSMesaDestroyContext(OSMesaContext), OSMesaGetProcAddress(const char*) -> OSMESAproc.
        // The copied function pointers live as long as `lib`, which is stored alongside them.
        let syms = unsafe {
            (|| -> Result<_, libloading::Error> {
                Ok((
                    *lib.get::<CreateContextExtFn>("OSMesaCreateContextExt")?,
                    *lib.get::<MakeCurrentFn>("OSMesaMakeCurrent")?,
                    *lib.get::<DestroyContextFn>("OSMesaDestroyContext")?,
                    *lib.get::<GetProcAddressFn>("OSMesaGetProcAddress")?,
                ))
            })()
        };
        let (create_context_ext, make_current, destroy_context, get_proc_address) =
            syms.map_err(|e| OracleError::MissingSymbol(format!("{name}: {e}")))?;
        return Ok(OsMesaLib {
            _lib: lib,
            create_context_ext,
            make_current,
            destroy_context,
            get_proc_address,
        });
    }
    Err(OracleError::NotFound(tried.join("; ")))
}

fn library() -> Result<&'static OsMesaLib, OracleError> {
    static LIB: OnceLock<Result<OsMesaLib, OracleError>> = OnceLock::new();
    LIB.get_or_init(load_library).as_ref().map_err(Clone::clone)
}

/// Whether an OSMesa library can be loaded in this process.
pub fn mesa_available() -> Result<(), OracleError> {
    library().map(|_| ())
}

/// An OSMesa context rendering into a buffer it owns. Derefs to [`ForeignGl`], so
/// `&mut *mesa` is a `&mut dyn Gl`.
///
/// OSMesa binds the context to the calling thread: use a `MesaContext` on the thread that
/// created it (it is `!Send`), and call [`MesaContext::make_current`] again if another OSMesa
/// context was made current on the same thread in between.
pub struct MesaContext {
    gl: ForeignGl,
    ctx: *mut c_void,
    buffer: Vec<u8>,
    width: i32,
    height: i32,
    info: OracleInfo,
}

impl MesaContext {
    /// Binds this context and its buffer to the calling thread.
    pub fn make_current(&mut self) -> Result<(), OracleError> {
        let lib = library()?;
        // SAFETY: `self.ctx` is a live context created by this library; `self.buffer` holds
        // exactly width*height*4 bytes (RGBA, GL_UNSIGNED_BYTE) and lives as long as the
        // context (it is only freed after OSMesaDestroyContext in Drop) and is never resized.
        let ok = unsafe {
            (lib.make_current)(
                self.ctx,
                self.buffer.as_mut_ptr() as *mut c_void,
                GL_UNSIGNED_BYTE,
                self.width,
                self.height,
            )
        };
        if ok == 0 {
            Err(OracleError::MakeCurrent)
        } else {
            Ok(())
        }
    }

    /// Framebuffer size.
    pub fn size(&self) -> (i32, i32) {
        (self.width, self.height)
    }

    /// Entry points the scene called that Mesa does not provide.
    pub fn missing(&self) -> &[&'static str] {
        &self.gl.missing
    }
}

impl Oracle for MesaContext {
    fn create(width: i32, height: i32) -> Result<Self, OracleError> {
        if !(1..=8192).contains(&width) || !(1..=8192).contains(&height) {
            return Err(OracleError::BadSize(width, height));
        }
        let lib = library()?;
        // SAFETY: plain constructor call with the documented argument types; a NULL sharelist
        // is allowed. GL_RGBA is OSMESA_RGBA. 16 accumulation bits, as tilegl's side has.
        let ctx = unsafe { (lib.create_context_ext)(GL_RGBA, 24, 8, 16, std::ptr::null_mut()) };
        if ctx.is_null() {
            return Err(OracleError::CreateContext);
        }
        let get_proc = lib.get_proc_address;
        let lookup = |name: &CStr| {
            // SAFETY: `name` is NUL-terminated; OSMesaGetProcAddress has no other precondition.
            unsafe { get_proc(name.as_ptr()) }
        };
        // SAFETY: OSMesaGetProcAddress returns, for a GL function name, a pointer to that
        // function with the C signature of GL/gl.h (or NULL). The library is never unloaded,
        // and the functions act on the context current on the calling thread, which we make
        // current right below and keep on this thread (`MesaContext` is !Send). Slice lengths
        // are the trait callers' responsibility, as documented on `ForeignGl::new`.
        let gl = unsafe { ForeignGl::new(lookup) };
        let mut mesa = MesaContext {
            gl,
            ctx,
            buffer: vec![0u8; width as usize * height as usize * 4],
            width,
            height,
            info: OracleInfo::default(),
        };
        mesa.make_current()?;
        mesa.info = OracleInfo {
            version: mesa.gl.get_string(GL_VERSION).unwrap_or_default(),
            renderer: mesa.gl.get_string(GL_RENDERER).unwrap_or_default(),
        };
        Ok(mesa)
    }

    fn gl(&mut self) -> &mut dyn Gl {
        &mut self.gl
    }

    fn info(&self) -> &OracleInfo {
        &self.info
    }
}

impl Deref for MesaContext {
    type Target = ForeignGl;
    fn deref(&self) -> &ForeignGl {
        &self.gl
    }
}

impl DerefMut for MesaContext {
    fn deref_mut(&mut self) -> &mut ForeignGl {
        &mut self.gl
    }
}

impl Drop for MesaContext {
    fn drop(&mut self) {
        if let Ok(lib) = library() {
            // Finish pending work and unbind first: Mesa 22 can crash destroying a context
            // that is still current.
            let _ = self.make_current();
            self.gl.finish();
            // SAFETY: NULL context and buffer is OSMesa's documented way to release the
            // current context of this thread.
            unsafe { (lib.make_current)(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0) };
            // SAFETY: `self.ctx` was created by this library and is destroyed exactly once;
            // the buffer is freed only after this call returns (fields drop after `drop`).
            unsafe { (lib.destroy_context)(self.ctx) };
        }
    }
}

/// The environment variable that marks a child process started by [`run_self_with_driver`].
pub const CHILD_ENV: &str = "TILEGL_ORACLE_CHILD";

/// Whether this process is a child started by [`run_self_with_driver`].
pub fn is_oracle_child() -> bool {
    std::env::var_os(CHILD_ENV).is_some()
}

/// Re-runs the current executable with `GALLIUM_DRIVER=driver` (and `LIBGL_ALWAYS_SOFTWARE=1`),
/// the given arguments and extra environment, and returns its output. Fails if the child exits
/// unsuccessfully. The child sees [`CHILD_ENV`] set, so it can answer the request instead of
/// doing its normal work.
pub fn run_self_with_driver(
    driver: &str,
    args: &[&str],
    env: &[(&str, &str)],
) -> Result<std::process::Output, OracleError> {
    let exe = std::env::current_exe().map_err(|e| OracleError::Subprocess(e.to_string()))?;
    let mut cmd = std::process::Command::new(exe);
    cmd.args(args)
        .env("GALLIUM_DRIVER", driver)
        .env("LIBGL_ALWAYS_SOFTWARE", "1")
        .env(CHILD_ENV, driver);
    for (k, v) in env {
        cmd.env(k, v);
    }
    let out = cmd
        .output()
        .map_err(|e| OracleError::Subprocess(e.to_string()))?;
    if !out.status.success() {
        return Err(OracleError::Subprocess(format!(
            "{driver} child exited with {}: {}{}",
            out.status,
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        )));
    }
    Ok(out)
}

/// Whether this run is CI (`CI=true` or `CI=1`), where a missing oracle or an unexpected one
/// fails instead of being reported.
pub fn in_ci() -> bool {
    std::env::var("CI")
        .map(|v| v == "true" || v == "1")
        .unwrap_or(false)
}

/// The Mesa major version the oracle's figures were measured with (Debian 12's Mesa 22.3.6:
/// conformance/TOLERANCE.md and the shared captures' TOLERANCE.md). Another major version may
/// rasterize differently; [`MESA_MAJOR_ENV`] names another expected major version.
pub const EXPECTED_MESA_MAJOR: u32 = 22;

/// The environment variable overriding [`EXPECTED_MESA_MAJOR`].
pub const MESA_MAJOR_ENV: &str = "TILEGL_MESA_MAJOR";

/// The Mesa version in a `GL_VERSION` string (`2.1 Mesa 22.3.6` -> 22), if it names one.
pub fn mesa_major(version: &str) -> Option<u32> {
    let rest = &version[version.find("Mesa ")? + 5..];
    let digits: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
    digits.parse().ok()
}

/// Checks that the oracle is the expected Mesa ([`EXPECTED_MESA_MAJOR`]): `Err` with the
/// reason when `version` is not.
pub fn check_oracle_version(version: &str) -> Result<u32, String> {
    let expected = std::env::var(MESA_MAJOR_ENV)
        .ok()
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(EXPECTED_MESA_MAJOR);
    match mesa_major(version) {
        Some(m) if m == expected => Ok(m),
        Some(m) => Err(format!(
            "the oracle is Mesa {m} (GL_VERSION {version:?}), the tolerances were measured on \
             Mesa {expected} (set {MESA_MAJOR_ENV}={m} after recalibrating)"
        )),
        None => Err(format!(
            "the oracle's GL_VERSION {version:?} names no Mesa version (expected Mesa {expected})"
        )),
    }
}

/// The oracle's identity and the outcome of [`check_oracle_version`] (its Mesa major version,
/// or why it is not the expected one), or why no context could be made.
pub type OracleIdentity = Result<(OracleInfo, Result<u32, String>), OracleError>;

/// The oracle's `GL_VERSION` and `GL_RENDERER`, read once per process from a 1x1 context and
/// printed once (to the process's standard error, past the test harness's capture), with the
/// outcome of [`check_oracle_version`].
pub fn oracle_identity() -> &'static OracleIdentity {
    static INFO: OnceLock<OracleIdentity> = OnceLock::new();
    INFO.get_or_init(|| {
        let info = MesaContext::create(1, 1)?.info().clone();
        let check = check_oracle_version(&info.version);
        use std::io::Write;
        let _ = writeln!(
            std::io::stderr(),
            "Mesa oracle: GL_VERSION {:?}, GL_RENDERER {:?}{}",
            info.version,
            info.renderer,
            match &check {
                Ok(_) => String::new(),
                Err(e) => format!(" -- UNEXPECTED: {e}"),
            }
        );
        Ok((info, check))
    })
}

/// What a test should do when the oracle is unavailable: in CI (`CI=true`) it fails, otherwise
/// it prints "skipped: Mesa not found" and passes. Returns `true` if the test should go on.
/// The first call of a process also prints the oracle's version and renderer
/// ([`oracle_identity`]); in CI a Mesa of another major version than [`EXPECTED_MESA_MAJOR`]
/// fails the test (elsewhere it is printed as a warning).
pub fn require_mesa(test: &str) -> bool {
    let ci = in_ci();
    match mesa_available() {
        Ok(()) => {}
        Err(e) => {
            assert!(!ci, "{test}: Mesa is required in CI but unavailable: {e}");
            println!("{test}: skipped: Mesa not found ({e})");
            return false;
        }
    }
    match oracle_identity() {
        Ok((_, Ok(_))) => {}
        Ok((_, Err(e))) => {
            assert!(!ci, "{test}: unexpected oracle in CI: {e}");
            println!("{test}: warning: {e}");
        }
        Err(e) => panic!("{test}: the Mesa oracle cannot create a context: {e}"),
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mesa_versions_are_read_from_gl_version() {
        assert_eq!(mesa_major("2.1 Mesa 22.3.6"), Some(22));
        assert_eq!(
            mesa_major("4.5 (Compatibility Profile) Mesa 24.2.8-1"),
            Some(24)
        );
        assert_eq!(mesa_major("4.6.0 NVIDIA 535.1"), None);
        assert_eq!(mesa_major(""), None);
        assert!(
            check_oracle_version("2.1 Mesa 22.3.6").is_ok()
                || std::env::var_os(MESA_MAJOR_ENV).is_some()
        );
        assert!(check_oracle_version("2.1 Mesa 9.2.1").is_err());
        assert!(check_oracle_version("1.5 tilegl").is_err());
    }
}

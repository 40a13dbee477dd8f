//! The replay driver: plays a stream of calls (an apitrace capture, or a call script) on
//! tilegl contexts and hands out snapshots of the framebuffer.
//!
//! - **Window-system calls** (`glX*`, `egl*`, `wgl*`, `CGL*`) are interpreted here, not by the
//!   dispatch: a make-current selects (and, the first time, creates) the tilegl context that
//!   stands for the traced context handle; a release (null context) leaves no context current;
//!   `glXSwapBuffers`/`eglSwapBuffers` end a frame (frames are counted over all contexts and
//!   threads); `*DestroyContext` drops the context. Each trace thread has its own current
//!   context. The
//!   others (visual and config choice, extension strings, ...) are skipped and counted.
//! - **Window size**: apitrace writes a fake `glViewport` with the drawable's size right after
//!   the first make-current. A context is created at that size (it is double-buffered, as the
//!   window of every shared capture is); a later fake `glViewport` with another size (a new
//!   drawable) resizes it. Without one, the context gets [`DEFAULT_SIZE`]; sides are clamped
//!   to [`MAX_WINDOW`].
//! - **Evaluator meshes**: contexts draw `glEvalMesh2(GL_FILL)` as Mesa does, with triangle
//!   strips ([`Player::mesh_fill`]), so flat-shaded meshes in Mesa captures replay to Mesa's
//!   pictures; the specification's quad strips are one setting away.
//! - **Snapshots**: `frame-NNNN.png` is the back buffer just before swap number N (from 0);
//!   `call-NNNNNNNNNN.png` is the current draw buffer right after call N.
//! - GL calls go through [`super::dispatch`]; calls it does not know, GL errors (by function
//!   and error, with the first call number) and skipped window-system calls are counted in
//!   [`ReplayStats`] and reported once each by the caller. Nothing in the input makes the
//!   player panic: reader errors and a panic inside the implementation become a
//!   [`ReplayError`] naming the call number.

use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::fmt;
use std::panic::{catch_unwind, AssertUnwindSafe};

use crate::api::enums::*;
use crate::framebuffer::{ColorBuffer, FramebufferConfig};
use crate::raster::controls::SmoothPoints;
use crate::state::evaluators::MeshFill;
use crate::state::{Context, ContextConfig};

use super::dispatch::{dispatch, DispatchState, Outcome, Returned};
use super::trace::{Call, TraceReader, Value};

/// Framebuffer size of a context made current without a fake `glViewport` after it.
pub const DEFAULT_SIZE: (i32, i32) = (256, 256);

/// Largest window side accepted from a fake `glViewport` (larger values are clamped): keeps a
/// damaged capture from allocating gigabytes of framebuffer.
pub const MAX_WINDOW: i32 = 4096;

/// Anything that yields calls in order.
pub trait CallSource {
    /// The next call, `Ok(None)` at the end; an error says where the input is bad.
    fn next_call(&mut self) -> Result<Option<Call>, String>;
}

impl CallSource for TraceReader {
    fn next_call(&mut self) -> Result<Option<Call>, String> {
        TraceReader::next_call(self).map_err(|e| e.to_string())
    }
}

/// Which frames (swap numbers) to snapshot.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FrameSelection {
    /// No frames.
    None,
    /// Every frame.
    All,
    /// Frames `start..end` (`end` exclusive, `None` = to the end).
    Range { start: u64, end: Option<u64> },
    /// These frames.
    List(BTreeSet<u64>),
}

impl FrameSelection {
    fn contains(&self, n: u64) -> bool {
        match self {
            FrameSelection::None => false,
            FrameSelection::All => true,
            FrameSelection::Range { start, end } => n >= *start && end.is_none_or(|e| n < e),
            FrameSelection::List(l) => l.contains(&n),
        }
    }

    /// The first frame number after which nothing more is wanted (`None`: never).
    fn end(&self) -> Option<u64> {
        match self {
            FrameSelection::None => Some(0),
            FrameSelection::All => None,
            FrameSelection::Range { end, .. } => *end,
            FrameSelection::List(l) => Some(l.last().map_or(0, |n| n + 1)),
        }
    }
}

/// What to snapshot.
#[derive(Clone, Debug)]
pub struct Want {
    pub frames: FrameSelection,
    /// Call numbers after which to snapshot the draw buffer.
    pub calls: BTreeSet<u64>,
    /// Stop reading once every wanted picture is taken (otherwise the whole input is played,
    /// e.g. to count unknown calls).
    pub stop_early: bool,
}

/// One snapshot.
#[derive(Clone, Debug)]
pub struct Picture {
    /// File name: `frame-NNNN.png` or `call-NNNNNNNNNN.png`.
    pub file: String,
    /// The swap number for a frame snapshot.
    pub frame: Option<u64>,
    /// The call the snapshot belongs to (the swap call for frames).
    pub call_no: u64,
    /// The colour buffer, RGB, top row first (as PNG files are).
    pub image: image::RgbImage,
    /// The colour buffer's alpha, in the same order (compared where a reference has alpha).
    pub alpha: image::GrayImage,
    /// The clear colour (`GL_COLOR_CLEAR_VALUE`) current at the snapshot, as 8-bit RGBA: a
    /// reference of only this colour shows nothing drawn.
    pub clear_color: [u8; 4],
}

/// File name of the snapshot before swap `n`.
pub fn frame_file(n: u64) -> String {
    format!("frame-{n:04}.png")
}

/// File name of the snapshot after call `n`.
pub fn call_file(n: u64) -> String {
    format!("call-{n:010}.png")
}

/// Where a GL error was raised.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ErrorCount {
    pub count: u64,
    pub first_call: u64,
}

/// What the replay met on the way.
#[derive(Clone, Debug, Default)]
pub struct ReplayStats {
    /// Calls read.
    pub calls: u64,
    /// Swaps seen.
    pub frames: u64,
    /// Number of the last call read.
    pub last_call: Option<u64>,
    /// GL functions the dispatch does not know, with counts.
    pub unknown: BTreeMap<String, u64>,
    /// Argument conversion problems, with counts.
    pub warnings: BTreeMap<String, u64>,
    /// GL errors by (function, error), with count and first call.
    pub gl_errors: BTreeMap<(String, GLenum), ErrorCount>,
    /// Window-system calls that have no effect on the replay, with counts.
    pub skipped: BTreeMap<String, u64>,
    /// GL calls made while no context was current (ignored, as GL does).
    pub without_context: u64,
    /// Size of the last window (framebuffer) used.
    pub size: Option<(i32, i32)>,
    /// Results of the calls in [`CHECKED_RESULTS`], each beside the one the capture recorded.
    pub results: Vec<ResultCheck>,
}

/// Calls whose result the capture records and tilegl must reproduce: `glRenderMode` returns
/// the number of selection hits or feedback values, the only output of programs that draw in
/// `GL_SELECT` or `GL_FEEDBACK` mode (their pictures show nothing drawn).
pub const CHECKED_RESULTS: &[&str] = &["glRenderMode"];

/// A call's result compared with the capture's.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ResultCheck {
    pub call_no: u64,
    pub name: String,
    /// What the capture recorded (the program's GL returned it).
    pub traced: i64,
    /// What tilegl returned.
    pub ours: i64,
}

impl ResultCheck {
    pub fn matches(&self) -> bool {
        self.traced == self.ours
    }
}

impl ReplayStats {
    /// One line per unknown function, GL error and warning (for the end of a replay).
    pub fn report_lines(&self) -> Vec<String> {
        let mut out = Vec::new();
        for (name, n) in &self.unknown {
            out.push(format!("unknown call {name} ({n}x): not replayed"));
        }
        for ((name, e), c) in &self.gl_errors {
            out.push(format!(
                "{name} raised {} ({}x, first at call {})",
                error_name(*e),
                c.count,
                c.first_call
            ));
        }
        for (w, n) in &self.warnings {
            out.push(format!("warning: {w} ({n}x)"));
        }
        for r in self.results.iter().filter(|r| !r.matches()) {
            out.push(format!(
                "{} at call {} returned {}, the capture {}",
                r.name, r.call_no, r.ours, r.traced
            ));
        }
        if self.without_context > 0 {
            out.push(format!(
                "{} GL calls without a current context were ignored",
                self.without_context
            ));
        }
        out
    }
}

/// The name of a GL error code.
pub fn error_name(e: GLenum) -> String {
    match e {
        GL_INVALID_ENUM => "GL_INVALID_ENUM".into(),
        GL_INVALID_VALUE => "GL_INVALID_VALUE".into(),
        GL_INVALID_OPERATION => "GL_INVALID_OPERATION".into(),
        GL_STACK_OVERFLOW => "GL_STACK_OVERFLOW".into(),
        GL_STACK_UNDERFLOW => "GL_STACK_UNDERFLOW".into(),
        GL_OUT_OF_MEMORY => "GL_OUT_OF_MEMORY".into(),
        e => format!("0x{e:04X}"),
    }
}

/// A replay that could not go on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReplayError {
    /// The call being processed, or the last call read before a reader error.
    pub call: Option<u64>,
    pub message: String,
}

impl fmt::Display for ReplayError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.call {
            Some(n) => write!(f, "call {n}: {}", self.message),
            None => write!(f, "before the first call: {}", self.message),
        }
    }
}

impl std::error::Error for ReplayError {}

/// Plays calls on tilegl contexts.
pub struct Player {
    contexts: HashMap<u64, Context>,
    /// The context current in the thread of the last call (`current`, `pending`); other
    /// threads' bindings wait in `other_threads` (GL has one current context per thread).
    current: Option<u64>,
    /// The context most recently made current (kept when released or destroyed).
    last: Option<u64>,
    /// A context made current but not created yet (waiting for the fake `glViewport`).
    pending: Option<u64>,
    thread: u64,
    other_threads: HashMap<u64, (Option<u64>, Option<u64>)>,
    dispatch: DispatchState,
    stats: ReplayStats,
    threads: usize,
    /// Create a window of [`DEFAULT_SIZE`] (or the size of a following fake `glViewport`)
    /// at the first GL call when no context was ever made current (call scripts).
    pub auto_window: bool,
    /// How the contexts connect `glEvalMesh2(GL_FILL)` grids: triangle strips unless changed,
    /// as the Mesa the captures were recorded with draws them (the specification's quad
    /// strips colour a flat-shaded quad once, Mesa's triangles twice).
    pub mesh_fill: MeshFill,
    /// How the contexts draw `GL_POINT_SMOOTH` points: full-colour discs unless changed, as
    /// the Mesa the captures were recorded with draws them (the specification's coverage
    /// shades the discs' rims).
    pub smooth_points: SmoothPoints,
}

/// The handle of the context made by [`Player::auto_window`].
const AUTO_HANDLE: u64 = u64::MAX;

impl Default for Player {
    fn default() -> Self {
        Player::new(0)
    }
}

/// The argument that holds the context handle in a make-current call.
fn make_current_ctx_arg(name: &str) -> Option<usize> {
    match name {
        "glXMakeCurrent" => Some(2),
        "glXMakeContextCurrent" | "eglMakeCurrent" => Some(3),
        "wglMakeCurrent" => Some(1),
        "CGLSetCurrentContext" => Some(0),
        _ => None,
    }
}

fn is_swap(name: &str) -> bool {
    matches!(
        name,
        "glXSwapBuffers" | "eglSwapBuffers" | "wglSwapBuffers" | "CGLFlushDrawable"
    ) || name.starts_with("eglSwapBuffersWithDamage")
}

fn handle(v: Option<&Value>) -> u64 {
    match v {
        Some(Value::Opaque(h)) => *h,
        Some(v) => v.as_i64().unwrap_or(0) as u64,
        None => 0,
    }
}

impl Player {
    /// A player whose contexts shade with `threads` workers (0: one per core).
    pub fn new(threads: usize) -> Player {
        Player {
            contexts: HashMap::new(),
            current: None,
            last: None,
            pending: None,
            thread: 0,
            other_threads: HashMap::new(),
            dispatch: DispatchState::new(),
            stats: ReplayStats::default(),
            threads,
            auto_window: false,
            mesh_fill: MeshFill::TriangleStrips,
            smooth_points: SmoothPoints::Discs,
        }
    }

    /// What the replay met so far.
    pub fn stats(&self) -> ReplayStats {
        let mut s = self.stats.clone();
        s.unknown = self.dispatch.unknown.clone();
        s.warnings = self.dispatch.warnings.clone();
        s
    }

    /// The current context, if any.
    pub fn current_context(&mut self) -> Option<&mut Context> {
        let h = self.current?;
        self.contexts.get_mut(&h)
    }

    /// The current context, or else the one most recently current (the picture a capture
    /// left on screen after releasing its context).
    pub fn last_context(&mut self) -> Option<&mut Context> {
        let h = self.current.or(self.last)?;
        self.contexts.get_mut(&h)
    }

    fn create(&mut self, handle: u64, (width, height): (i32, i32)) {
        let mut ctx = Context::with_config(ContextConfig {
            width,
            height,
            framebuffer: FramebufferConfig {
                double_buffer: true,
                ..FramebufferConfig::default()
            },
            threads: self.threads,
        });
        ctx.set_mesh_fill(self.mesh_fill);
        ctx.set_smooth_points(self.smooth_points);
        // SAFETY: the replayer hands the context the addresses of bytes it keeps alive for
        // as long as GL may use them (`dispatch::DispatchState`'s retained arrays and buffers).
        unsafe { crate::capi::client_memory::attach(&mut ctx) };
        self.contexts.insert(handle, ctx);
        self.current = Some(handle);
        self.last = Some(handle);
        self.pending = None;
        self.stats.size = Some((width, height));
    }

    /// Creates the pending context (if any) at `size` or the default size.
    fn settle_pending(&mut self, size: Option<(i32, i32)>) {
        if let Some(h) = self.pending {
            let size = size.or(self.stats.size).unwrap_or(DEFAULT_SIZE);
            self.create(h, size);
        }
    }

    fn snapshot(&mut self, file: String, frame: Option<u64>, call_no: u64) -> Option<Picture> {
        let ctx = self.current_context()?;
        let buffer = if frame.is_some() {
            ColorBuffer::Back
        } else {
            ctx.draw_color_buffer()
        };
        // Read from the state, not with glGetFloatv: that query is refused between glBegin
        // and glEnd, and the error it records would be seen by the program's glGetError.
        let clear_color = ctx
            .clear_values
            .color
            .map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
        let rgba = ctx.color_image(buffer);
        let (w, h) = rgba.dimensions();
        let raw = rgba.into_raw();
        let rgb: Vec<u8> = raw
            .chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect();
        let alpha: Vec<u8> = raw.chunks_exact(4).map(|p| p[3]).collect();
        let image = image::RgbImage::from_raw(w, h, rgb)?;
        let alpha = image::GrayImage::from_raw(w, h, alpha)?;
        Some(Picture {
            file,
            frame,
            call_no,
            image,
            alpha,
            clear_color,
        })
    }

    /// Plays one call; returns the pictures it produced (a frame before a swap, and the call
    /// snapshot if `call.no` is wanted).
    pub fn play_call(&mut self, call: &Call, want: &Want) -> Result<Vec<Picture>, ReplayError> {
        let mut pictures = Vec::new();
        if call.thread != self.thread {
            self.other_threads
                .insert(self.thread, (self.current, self.pending));
            (self.current, self.pending) = self
                .other_threads
                .remove(&call.thread)
                .unwrap_or((None, None));
            self.thread = call.thread;
        }
        self.stats.calls += 1;
        self.stats.last_call = Some(call.no);
        let name = call.name();
        let window_system = ["glX", "egl", "wgl", "CGL"]
            .iter()
            .any(|p| name.starts_with(p));
        if window_system {
            if let Some(i) = make_current_ctx_arg(name) {
                let h = handle(call.arg(i));
                if h == 0 {
                    self.current = None;
                    self.pending = None;
                } else if self.contexts.contains_key(&h) {
                    self.current = Some(h);
                    self.last = Some(h);
                    self.pending = None;
                } else {
                    self.current = None;
                    self.pending = Some(h);
                }
            } else if is_swap(name) {
                self.settle_pending(None);
                let n = self.stats.frames;
                if want.frames.contains(n) {
                    pictures.extend(self.snapshot(frame_file(n), Some(n), call.no));
                }
                if let Some(ctx) = self.current_context() {
                    ctx.swap_buffers();
                }
                self.stats.frames += 1;
            } else if name.ends_with("DestroyContext") {
                let h = handle(call.arg(1).or(call.arg(0)));
                if Some(h) != self.current && Some(h) != self.last {
                    self.contexts.remove(&h);
                }
            } else {
                *self.stats.skipped.entry(name.to_string()).or_insert(0) += 1;
            }
        } else {
            let fake_viewport = (name == "glViewport" && call.is_fake()).then(|| {
                let arg = |i| call.arg(i).and_then(Value::as_i64).unwrap_or(0);
                (
                    arg(2).clamp(0, 1 << 14) as i32,
                    arg(3).clamp(0, 1 << 14) as i32,
                )
            });
            if self.auto_window
                && self.current.is_none()
                && self.pending.is_none()
                && self.contexts.is_empty()
            {
                self.pending = Some(AUTO_HANDLE);
            }
            if self.pending.is_some() {
                self.settle_pending(fake_viewport);
            } else if let (Some(size), Some(ctx)) = (fake_viewport, self.current_context()) {
                if ctx.size() != size {
                    ctx.resize(size.0, size.1);
                }
                self.stats.size = Some(size);
            }
            let Some(h) = self.current else {
                self.stats.without_context += 1;
                return Ok(pictures);
            };
            let Some(ctx) = self.contexts.get_mut(&h) else {
                self.stats.without_context += 1;
                return Ok(pictures);
            };
            let st = &mut self.dispatch;
            let checked = CHECKED_RESULTS.contains(&name);
            let mut returned = None;
            let result = catch_unwind(AssertUnwindSafe(|| {
                if let Outcome::Called(Returned::Int(v)) = dispatch(ctx, call, st) {
                    returned = Some(v);
                }
                // Errors are collected after each call (outside glBegin/glEnd, where
                // glGetError itself would be an error); the trace's own glGetError calls
                // therefore see no error, which replay does not rely on.
                if ctx.immediate.is_none() {
                    ctx.get_error()
                } else {
                    GL_NO_ERROR
                }
            }));
            if let (true, Some(ours), Some(traced)) =
                (checked, returned, call.ret.as_ref().and_then(Value::as_i64))
            {
                self.stats.results.push(ResultCheck {
                    call_no: call.no,
                    name: name.to_string(),
                    traced,
                    ours,
                });
            }
            match result {
                Ok(GL_NO_ERROR) => {}
                Ok(e) => {
                    let c =
                        self.stats
                            .gl_errors
                            .entry((name.to_string(), e))
                            .or_insert(ErrorCount {
                                count: 0,
                                first_call: call.no,
                            });
                    c.count += 1;
                }
                Err(panic) => {
                    let what = panic
                        .downcast_ref::<&str>()
                        .map(|s| s.to_string())
                        .or_else(|| panic.downcast_ref::<String>().cloned())
                        .unwrap_or_else(|| "unknown panic".into());
                    // The context may be inconsistent now: stop here.
                    return Err(ReplayError {
                        call: Some(call.no),
                        message: format!("{name} failed inside tilegl: {what}"),
                    });
                }
            }
        }
        if want.calls.contains(&call.no) {
            pictures.extend(self.snapshot(call_file(call.no), None, call.no));
        }
        Ok(pictures)
    }

    /// Whether every picture `want` asks for has been taken, once `last_call` was played.
    fn done(&self, want: &Want, last_call: u64) -> bool {
        want.stop_early
            && want.frames.end().is_some_and(|e| self.stats.frames >= e)
            && want.calls.last().is_none_or(|&c| last_call >= c)
    }

    /// Plays `source` to its end (or until `want` is satisfied), handing each picture to
    /// `sink`, and calling `progress` every few thousand calls. A sink error stops the replay.
    pub fn play(
        &mut self,
        source: &mut dyn CallSource,
        want: &Want,
        sink: &mut dyn FnMut(Picture) -> Result<(), String>,
        progress: &mut dyn FnMut(&ReplayStats),
    ) -> Result<ReplayStats, ReplayError> {
        loop {
            let call = match source.next_call() {
                Ok(Some(c)) => c,
                Ok(None) => break,
                Err(message) => {
                    // The call being read: the one after the last call read.
                    return Err(ReplayError {
                        call: Some(self.stats.last_call.map_or(0, |n| n + 1)),
                        message: format!("cannot be read: {message}"),
                    });
                }
            };
            for p in self.play_call(&call, want)? {
                let file = p.file.clone();
                sink(p).map_err(|e| ReplayError {
                    call: Some(call.no),
                    message: format!("{file}: {e}"),
                })?;
            }
            if self.stats.calls.is_multiple_of(4096) {
                progress(&self.stats);
            }
            if self.done(want, call.no) {
                break;
            }
        }
        Ok(self.stats())
    }
}

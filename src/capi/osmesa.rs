//! The OSMesa context API with OSMesa's semantics: the caller's buffer is the colour buffer
//! (tilegl renders into its tiles and copies into the buffer at each flush point: `glFlush`,
//! `glFinish` and `OSMesaGetColorBuffer`), rows bottom-up unless `OSMESA_Y_UP` is 0.

#![allow(non_snake_case)]

use std::cell::Cell;
use std::collections::HashMap;
use std::ffi::{c_char, c_void, CStr};
use std::sync::atomic::{AtomicU8, Ordering};
use std::sync::{Mutex, OnceLock};

use crate::api::enums::*;
use crate::framebuffer::FramebufferConfig;
use crate::state::share::ShareGroup;
use crate::state::{Context, ContextConfig};

pub const OSMESA_COLOR_INDEX: GLenum = GL_COLOR_INDEX;
pub const OSMESA_RGBA: GLenum = GL_RGBA;
pub const OSMESA_BGRA: GLenum = 0x1;
pub const OSMESA_ARGB: GLenum = 0x2;
pub const OSMESA_RGB: GLenum = GL_RGB;
pub const OSMESA_BGR: GLenum = 0x4;
pub const OSMESA_RGB_565: GLenum = 0x5;
pub const OSMESA_ROW_LENGTH: GLint = 0x10;
pub const OSMESA_Y_UP: GLint = 0x11;
pub const OSMESA_WIDTH: GLint = 0x20;
pub const OSMESA_HEIGHT: GLint = 0x21;
pub const OSMESA_FORMAT: GLint = 0x22;
pub const OSMESA_TYPE: GLint = 0x23;
pub const OSMESA_MAX_WIDTH: GLint = 0x24;
pub const OSMESA_MAX_HEIGHT: GLint = 0x25;

/// An OSMesa context: a tilegl context plus the caller's colour buffer.
pub struct OsMesaContext {
    pub gl: Context,
    format: GLenum,
    buffer: *mut u8,
    width: i32,
    height: i32,
    row_length: i32,
    y_up: bool,
    /// Depth values handed out by `OSMesaGetDepthBuffer` (a copy, refreshed on each call).
    depth_copy: Vec<u32>,
    /// A window-system context (GLX, EGL): what a flush point does instead of copying into a
    /// caller buffer.
    window_present: Option<fn(&mut Context)>,
    /// A window-system context: resizes the buffers to the drawable (after `glViewport`).
    window_resize: Option<fn(&mut Context)>,
    /// Which threads an OSMesa context is current on ([`UNBOUND`], [`BOUND`],
    /// [`BOUND_DESTROY`], [`DEAD`]): a context is current on one thread at a time, and one
    /// destroyed while current on another thread is freed when that thread lets it go.
    binding: AtomicU8,
}

/// Current on no thread.
const UNBOUND: u8 = 0;
/// Current on one thread.
const BOUND: u8 = 1;
/// Current on one thread and destroyed from another: freed when released.
const BOUND_DESTROY: u8 = 2;
/// Being freed.
const DEAD: u8 = 3;

/// Lets this thread's current context go: the thread has none afterwards, and a context that
/// another thread destroyed meanwhile is freed now.
fn release_current() {
    let old = CURRENT.with(|c| c.replace(std::ptr::null_mut()));
    if old.is_null() {
        return;
    }
    // SAFETY: a current context is alive: it is freed only by its own thread (here, or in
    // OSMesaDestroyContext on this thread) or, when unbound, by any thread.
    let binding = unsafe { &(*old).binding };
    if binding
        .compare_exchange(BOUND, UNBOUND, Ordering::AcqRel, Ordering::Acquire)
        .is_err()
        && binding
            .compare_exchange(BOUND_DESTROY, DEAD, Ordering::AcqRel, Ordering::Acquire)
            .is_ok()
    {
        // SAFETY: destroyed by another thread while current here; this thread was the last
        // user and is no longer, so the context is freed exactly once, here.
        drop(unsafe { Box::from_raw(old) });
    }
}

/// The share group of every live context (OSMesa's, and the GLX and EGL contexts' inner ones),
/// by address: a context created sharing with another finds the group here, without touching
/// the other context, which may be current and in use on another thread.
fn share_groups() -> &'static Mutex<HashMap<usize, ShareGroup>> {
    static G: OnceLock<Mutex<HashMap<usize, ShareGroup>>> = OnceLock::new();
    G.get_or_init(|| Mutex::new(HashMap::new()))
}

/// Registers `ctx` (boxed: its address is its key until it is dropped) in the share group
/// of `share`, or in its own group for null. False (nothing registered) when `share` is not
/// a live context.
pub(crate) fn join_share_group(ctx: &mut OsMesaContext, share: *const OsMesaContext) -> bool {
    let mut groups = share_groups().lock().unwrap_or_else(|e| e.into_inner());
    if !share.is_null() {
        let Some(group) = groups.get(&(share as usize)) else {
            return false;
        };
        ctx.gl.join_share_group(group);
    }
    groups.insert(ctx as *const OsMesaContext as usize, ctx.gl.share_group());
    true
}

impl Drop for OsMesaContext {
    fn drop(&mut self) {
        let mut groups = share_groups().lock().unwrap_or_else(|e| e.into_inner());
        groups.remove(&(self as *const OsMesaContext as usize));
    }
}

thread_local! {
    static CURRENT: Cell<*mut OsMesaContext> = const { Cell::new(std::ptr::null_mut()) };
}

/// Runs `f` on the current context of this thread, if any.
pub(crate) fn with_current_context<R>(f: impl FnOnce(&mut OsMesaContext) -> R) -> Option<R> {
    let p = CURRENT.with(|c| c.get());
    // SAFETY: CURRENT holds either null or a pointer from OSMesaCreateContextExt that has not
    // been destroyed (OSMesaDestroyContext clears it), used only on this thread.
    unsafe { p.as_mut() }.map(f)
}

/// Makes `p` (null, or a live context that stays alive while current) this thread's current
/// context: the window-system layers (GLX, EGL) run their contexts through this plumbing.
pub(crate) fn set_current_context(p: *mut OsMesaContext) {
    CURRENT.with(|c| c.set(p));
}

fn bytes_per_pixel(format: GLenum) -> Option<usize> {
    match format {
        OSMESA_RGBA | OSMESA_BGRA | OSMESA_ARGB => Some(4),
        OSMESA_RGB | OSMESA_BGR => Some(3),
        _ => None,
    }
}

fn to_format(format: GLenum, c: [u8; 4], out: &mut [u8]) {
    let [r, g, b, a] = c;
    match format {
        OSMESA_RGBA => out.copy_from_slice(&[r, g, b, a]),
        OSMESA_BGRA => out.copy_from_slice(&[b, g, r, a]),
        OSMESA_ARGB => out.copy_from_slice(&[a, r, g, b]),
        OSMESA_RGB => out.copy_from_slice(&[r, g, b]),
        OSMESA_BGR => out.copy_from_slice(&[b, g, r]),
        _ => {}
    }
}

fn from_format(format: GLenum, p: &[u8]) -> [u8; 4] {
    match format {
        OSMESA_RGBA => [p[0], p[1], p[2], p[3]],
        OSMESA_BGRA => [p[2], p[1], p[0], p[3]],
        OSMESA_ARGB => [p[1], p[2], p[3], p[0]],
        OSMESA_RGB => [p[0], p[1], p[2], 255],
        OSMESA_BGR => [p[2], p[1], p[0], 255],
        _ => [0; 4],
    }
}

/// A context that reads and writes the calling process's memory through its `ClientPtr`s.
fn process_context(config: ContextConfig) -> Context {
    let mut gl = Context::with_config(config);
    // SAFETY: a C caller makes the GL client-memory promise (`client_memory`'s contract) for
    // every pointer it passes the C entry points, which are the only way into this context.
    unsafe { super::client_memory::attach(&mut gl) };
    gl
}

impl OsMesaContext {
    /// A context of a window-system layer: no caller buffer; `present` runs at each flush
    /// point (`glFlush`, `glFinish`).
    pub(crate) fn for_window(
        config: ContextConfig,
        present: fn(&mut Context),
        resize: fn(&mut Context),
    ) -> OsMesaContext {
        OsMesaContext {
            gl: process_context(config),
            format: OSMESA_RGBA,
            buffer: std::ptr::null_mut(),
            width: 0,
            height: 0,
            row_length: 0,
            y_up: true,
            depth_copy: Vec::new(),
            window_present: Some(present),
            window_resize: Some(resize),
            binding: AtomicU8::new(UNBOUND),
        }
    }

    fn row_offset(&self, y: i32) -> usize {
        let row = if self.y_up { y } else { self.height - 1 - y };
        let bpp = bytes_per_pixel(self.format).unwrap_or(4);
        row as usize * self.row_length.max(self.width) as usize * bpp
    }

    fn buffer_len(&self) -> usize {
        let bpp = bytes_per_pixel(self.format).unwrap_or(4);
        self.row_length.max(self.width) as usize * self.height.max(0) as usize * bpp
    }

    /// Copies the finished colour buffer into the caller's buffer: each tile's rows straight
    /// to their place (one copy per row of a tile for `OSMESA_RGBA`, which is how the tiles
    /// store pixels), the tiles split over the shading threads.
    pub(crate) fn present(&mut self) {
        if let Some(f) = self.window_present {
            f(&mut self.gl);
            return;
        }
        if self.buffer.is_null() {
            return;
        }
        let bpp = bytes_per_pixel(self.format).unwrap_or(4);
        let out = CallerBuffer {
            ptr: self.buffer,
            len: self.buffer_len(),
        };
        let (w, h) = (self.width.max(0) as usize, self.height.max(0) as usize);
        let stride = self.row_length.max(self.width).max(0) as usize * bpp;
        let (format, y_up) = (self.format, self.y_up);
        self.gl.for_each_tile(&|tile| {
            let (x0, y0) = (tile.x0.max(0) as usize, tile.y0.max(0) as usize);
            if x0 >= w || y0 >= h {
                return;
            }
            let side = tile.side() as usize;
            let n = side.min(w - x0);
            for r in 0..side.min(h - y0) {
                let y = y0 + r;
                let row = if y_up { y } else { h - 1 - y };
                let at = row * stride + x0 * bpp;
                let Some(src) = tile.color.get(r * side..r * side + n) else {
                    return;
                };
                // SAFETY: `row < h` and `x0 + n <= w <= row length`, so the range lies inside
                // the buffer (checked again by `row_mut`); tiles cover disjoint pixels, so no
                // two threads write the same bytes, and no one else touches the buffer while
                // the context renders into it.
                let Some(dst) = (unsafe { out.row_mut(at, n * bpp) }) else {
                    return;
                };
                if format == OSMESA_RGBA {
                    dst.copy_from_slice(bytemuck::cast_slice(src));
                } else {
                    for (&c, px) in src.iter().zip(dst.chunks_exact_mut(bpp)) {
                        to_format(format, c, px);
                    }
                }
            }
        });
    }

    /// Resizes a window-system context's buffers to its drawable, if that changed size.
    pub(crate) fn check_drawable_size(&mut self) {
        if let Some(f) = self.window_resize {
            f(&mut self.gl);
        }
    }

    /// Loads the caller's buffer into the colour buffer (OSMesa renders on top of it).
    fn adopt(&mut self) {
        let bpp = bytes_per_pixel(self.format).unwrap_or(4);
        let len = self.buffer_len();
        // SAFETY: as in `present`.
        let src = unsafe { std::slice::from_raw_parts(self.buffer, len) };
        let offsets: Vec<usize> = (0..self.height).map(|y| self.row_offset(y)).collect();
        let (w, h, format) = (self.width, self.height, self.format);
        let fb = self.gl.framebuffer_mut();
        for y in 0..h {
            for x in 0..w {
                let o = offsets[y as usize] + x as usize * bpp;
                fb.set_color(x, y, from_format(format, &src[o..o + bpp]));
            }
        }
    }
}

/// The caller's colour buffer while tiles are copied into it from several threads.
struct CallerBuffer {
    ptr: *mut u8,
    len: usize,
}

// SAFETY: the buffer is only written through `row_mut`, whose callers write disjoint ranges
// (one tile's rows each); OSMesaMakeCurrent's caller keeps it alive while the context uses it.
unsafe impl Sync for CallerBuffer {}

impl CallerBuffer {
    /// Bytes `at..at + n` of the buffer, or `None` past its end.
    ///
    /// # Safety
    /// No other live reference may overlap the range (each tile's rows are written by the
    /// one thread that visits the tile).
    #[allow(clippy::mut_from_ref)]
    unsafe fn row_mut(&self, at: usize, n: usize) -> Option<&mut [u8]> {
        if at.checked_add(n)? > self.len {
            return None;
        }
        // SAFETY: in bounds (checked above) of a buffer of `len` bytes that OSMesaMakeCurrent's
        // caller promised; exclusive by this function's contract.
        Some(unsafe { std::slice::from_raw_parts_mut(self.ptr.add(at), n) })
    }
}

/// `OSMesaCreateContext`: 24-bit depth, 8-bit stencil, no accumulation buffer.
#[no_mangle]
pub extern "C" fn OSMesaCreateContext(
    format: GLenum,
    sharelist: *mut OsMesaContext,
) -> *mut OsMesaContext {
    OSMesaCreateContextExt(format, 24, 8, 0, sharelist)
}

/// `OSMesaCreateContextExt`. With a `sharelist` context, the new context shares its texture
/// objects, display lists and buffer objects (null when `sharelist` is not a live context).
#[no_mangle]
pub extern "C" fn OSMesaCreateContextExt(
    format: GLenum,
    depth_bits: GLint,
    stencil_bits: GLint,
    accum_bits: GLint,
    sharelist: *mut OsMesaContext,
) -> *mut OsMesaContext {
    if bytes_per_pixel(format).is_none() {
        return std::ptr::null_mut();
    }
    let depth_bits = match depth_bits {
        d if d <= 0 => 0,
        d if d <= 16 => 16,
        d if d <= 24 => 24,
        _ => 32,
    };
    let config = ContextConfig {
        width: 0,
        height: 0,
        framebuffer: FramebufferConfig {
            depth_bits,
            stencil_bits: if stencil_bits > 0 { 8 } else { 0 },
            accum_bits: if accum_bits > 0 { 16 } else { 0 },
            double_buffer: false,
            samples: 0,
        },
        threads: 0,
    };
    let mut ctx = Box::new(OsMesaContext {
        gl: process_context(config),
        format,
        buffer: std::ptr::null_mut(),
        width: 0,
        height: 0,
        row_length: 0,
        y_up: true,
        depth_copy: Vec::new(),
        window_present: None,
        window_resize: None,
        binding: AtomicU8::new(UNBOUND),
    });
    if !join_share_group(&mut ctx, sharelist) {
        return std::ptr::null_mut();
    }
    Box::into_raw(ctx)
}

/// `OSMesaMakeCurrent`: binds `buffer` (`width` x `height` pixels of the context's format,
/// `GL_UNSIGNED_BYTE`) as the colour buffer. The viewport is set to the buffer on first use.
///
/// # Safety
/// `ctx` must come from `OSMesaCreateContext*` and not be destroyed; `buffer` must hold
/// `width * height` pixels and stay valid while the context is current.
#[no_mangle]
pub unsafe extern "C" fn OSMesaMakeCurrent(
    ctx: *mut OsMesaContext,
    buffer: *mut c_void,
    type_: GLenum,
    width: GLsizei,
    height: GLsizei,
) -> GLboolean {
    if ctx.is_null() {
        release_current();
        return GL_TRUE as GLboolean;
    }
    if buffer.is_null()
        || type_ != GL_UNSIGNED_BYTE
        || width < 1
        || height < 1
        || width > 8192
        || height > 8192
    {
        return GL_FALSE as GLboolean;
    }
    if CURRENT.with(|c| c.get()) != ctx {
        // SAFETY: the caller passes a live context from OSMesaCreateContext*.
        let binding = unsafe { &(*ctx).binding };
        if binding
            .compare_exchange(UNBOUND, BOUND, Ordering::AcqRel, Ordering::Acquire)
            .is_err()
        {
            // Current on another thread (or destroyed): a context is current on one thread
            // at a time (GLX's rule; OSMesa has none, and sharing would race).
            return GL_FALSE as GLboolean;
        }
        release_current();
    }
    // SAFETY: live, and claimed by this thread above (or already current on it), so no other
    // thread uses it.
    let c = unsafe { &mut *ctx };
    let first = c.width == 0;
    c.buffer = buffer as *mut u8;
    c.width = width;
    c.height = height;
    if c.row_length < width {
        c.row_length = width;
    }
    c.gl.resize(width, height);
    c.gl.refresh_shared_objects();
    if first {
        c.gl.viewport(0, 0, width, height);
        c.gl.scissor(0, 0, width, height);
    }
    c.adopt();
    CURRENT.with(|cur| cur.set(ctx));
    GL_TRUE as GLboolean
}

/// `OSMesaGetCurrentContext`.
#[no_mangle]
pub extern "C" fn OSMesaGetCurrentContext() -> *mut OsMesaContext {
    CURRENT.with(|c| c.get())
}

/// `OSMesaDestroyContext`.
///
/// # Safety
/// `ctx` must come from `OSMesaCreateContext*` and not be used afterwards.
#[no_mangle]
pub unsafe extern "C" fn OSMesaDestroyContext(ctx: *mut OsMesaContext) {
    if ctx.is_null() {
        return;
    }
    if CURRENT.with(|c| c.get()) == ctx {
        CURRENT.with(|c| c.set(std::ptr::null_mut()));
    } else {
        // SAFETY: the caller passes a live context from OSMesaCreateContext*.
        let binding = unsafe { &(*ctx).binding };
        if binding
            .compare_exchange(BOUND, BOUND_DESTROY, Ordering::AcqRel, Ordering::Acquire)
            .is_ok()
        {
            // Current on another thread: that thread frees it when it lets it go.
            return;
        }
        if binding
            .compare_exchange(UNBOUND, DEAD, Ordering::AcqRel, Ordering::Acquire)
            .is_err()
        {
            return; // destroyed already
        }
    }
    // SAFETY: ctx came from Box::into_raw in OSMesaCreateContextExt, is current on no other
    // thread, and is freed once (the state above admits one freeing path).
    drop(unsafe { Box::from_raw(ctx) });
}

/// `OSMesaPixelStore`: `OSMESA_ROW_LENGTH` and `OSMESA_Y_UP` of the current context.
#[no_mangle]
pub extern "C" fn OSMesaPixelStore(pname: GLint, value: GLint) {
    with_current_context(|c| match pname {
        OSMESA_ROW_LENGTH if value >= 0 => c.row_length = value.max(c.width),
        OSMESA_Y_UP => c.y_up = value != 0,
        _ => {}
    });
}

/// `OSMesaGetIntegerv`.
///
/// # Safety
/// `value` must point to a writable `GLint`.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetIntegerv(pname: GLint, value: *mut GLint) {
    if value.is_null() {
        return;
    }
    let v = match pname {
        OSMESA_MAX_WIDTH | OSMESA_MAX_HEIGHT => Some(8192),
        _ => with_current_context(|c| match pname {
            OSMESA_WIDTH => Some(c.width),
            OSMESA_HEIGHT => Some(c.height),
            OSMESA_FORMAT => Some(c.format as GLint),
            OSMESA_TYPE => Some(GL_UNSIGNED_BYTE as GLint),
            OSMESA_ROW_LENGTH => Some(c.row_length),
            OSMESA_Y_UP => Some(c.y_up as GLint),
            _ => None,
        })
        .flatten(),
    };
    if let Some(v) = v {
        // SAFETY: checked non-null; the caller provides a GLint.
        unsafe { *value = v };
    }
}

/// `OSMesaGetColorBuffer`: finishes rendering into the caller's buffer and describes it.
///
/// # Safety
/// Output pointers must be writable (null ones are skipped).
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetColorBuffer(
    ctx: *mut OsMesaContext,
    width: *mut GLint,
    height: *mut GLint,
    format: *mut GLint,
    buffer: *mut *mut c_void,
) -> GLboolean {
    // SAFETY: a live context from OSMesaCreateContext*, or null.
    let Some(c) = (unsafe { ctx.as_mut() }) else {
        return GL_FALSE as GLboolean;
    };
    if c.buffer.is_null() {
        return GL_FALSE as GLboolean;
    }
    c.present();
    // SAFETY: each pointer is checked for null and points to caller-owned storage.
    unsafe {
        if let Some(w) = width.as_mut() {
            *w = c.width;
        }
        if let Some(h) = height.as_mut() {
            *h = c.height;
        }
        if let Some(f) = format.as_mut() {
            *f = c.format as GLint;
        }
        if let Some(b) = buffer.as_mut() {
            *b = c.buffer as *mut c_void;
        }
    }
    GL_TRUE as GLboolean
}

/// `OSMesaGetDepthBuffer`: a copy of the depth buffer as 32-bit values (bottom row first),
/// valid until the next call.
///
/// # Safety
/// Output pointers must be writable (null ones are skipped).
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetDepthBuffer(
    ctx: *mut OsMesaContext,
    width: *mut GLint,
    height: *mut GLint,
    bytes_per_value: *mut GLint,
    buffer: *mut *mut c_void,
) -> GLboolean {
    // SAFETY: a live context from OSMesaCreateContext*, or null.
    let Some(c) = (unsafe { ctx.as_mut() }) else {
        return GL_FALSE as GLboolean;
    };
    let (w, h) = (c.width, c.height);
    if c.gl.framebuffer().config.depth_bits == 0 || w == 0 {
        return GL_FALSE as GLboolean;
    }
    let fb = c.gl.framebuffer();
    let copy: Vec<u32> = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| fb.depth_at(x, y).unwrap_or(0))
        .collect();
    c.depth_copy = copy;
    // SAFETY: each pointer is checked for null and points to caller-owned storage.
    unsafe {
        if let Some(p) = width.as_mut() {
            *p = w;
        }
        if let Some(p) = height.as_mut() {
            *p = h;
        }
        if let Some(p) = bytes_per_value.as_mut() {
            *p = 4;
        }
        if let Some(p) = buffer.as_mut() {
            *p = c.depth_copy.as_mut_ptr() as *mut c_void;
        }
    }
    GL_TRUE as GLboolean
}

/// `OSMesaGetProcAddress`: any exported GL or OSMesa function by name.
///
/// # Safety
/// `name` must be a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetProcAddress(name: *const c_char) -> *const c_void {
    if name.is_null() {
        return std::ptr::null();
    }
    // SAFETY: the caller passes a NUL-terminated string.
    let name = unsafe { CStr::from_ptr(name) }.to_string_lossy();
    match name.as_ref() {
        "OSMesaCreateContext" => OSMesaCreateContext as *const c_void,
        "OSMesaCreateContextExt" => OSMesaCreateContextExt as *const c_void,
        "OSMesaMakeCurrent" => OSMesaMakeCurrent as *const c_void,
        "OSMesaGetCurrentContext" => OSMesaGetCurrentContext as *const c_void,
        "OSMesaDestroyContext" => OSMesaDestroyContext as *const c_void,
        "OSMesaPixelStore" => OSMesaPixelStore as *const c_void,
        "OSMesaGetIntegerv" => OSMesaGetIntegerv as *const c_void,
        "OSMesaGetColorBuffer" => OSMesaGetColorBuffer as *const c_void,
        "OSMesaGetDepthBuffer" => OSMesaGetDepthBuffer as *const c_void,
        "OSMesaGetProcAddress" => OSMesaGetProcAddress as *const c_void,
        other => super::exports::gl_proc_address(other),
    }
}

//! What GLX and EGL share: Xlib (loaded at run time from the `libX11.so.6` the program already
//! uses, through `x11-dl`), the framebuffer configurations offered for an X screen's visuals,
//! window-system contexts, and presenting a colour buffer in a drawable (MIT-SHM's
//! `XShmPutImage` when the server is local and has it, else `XPutImage`).
//!
//! Like Mesa's xlib "fake GLX", nothing here needs the server's GLX extension: the
//! configurations are made from the server's TrueColor visuals (`XGetVisualInfo`), tilegl
//! renders into its own tiles, and a buffer swap (or a flush of a front buffer) copies the
//! finished picture into the window.

use std::collections::HashMap;
use std::ffi::{c_char, c_int, c_uint, c_ulong};
use std::sync::{Mutex, OnceLock};

use x11_dl::xlib::{self, Display, Xlib};

use super::osmesa::OsMesaContext;
use crate::framebuffer::{ColorBuffer, DrawTarget, FramebufferConfig};
use crate::state::{Context, ContextConfig};

/// Xlib's functions, or `None` when `libX11.so.6` cannot be loaded.
pub(crate) fn xlib() -> Option<&'static Xlib> {
    static X: OnceLock<Option<Xlib>> = OnceLock::new();
    X.get_or_init(|| Xlib::open().ok()).as_ref()
}

/// A framebuffer configuration: one of an X visual's combinations of back buffer, depth and
/// stencil buffer and accumulation buffer. Configurations live for the whole process (GLX and
/// EGL hand out pointers to them).
#[derive(Debug)]
pub struct FbConfig {
    /// `GLX_FBCONFIG_ID` / `EGL_CONFIG_ID`, from 1 per display.
    pub id: i32,
    pub screen: i32,
    pub visualid: c_ulong,
    /// The X visual (a pointer into Xlib's display structure, kept as an address).
    pub visual: usize,
    pub depth: i32,
    pub red: i32,
    pub green: i32,
    pub blue: i32,
    /// tilegl's colour buffers always hold 8 alpha bits (destination alpha works on every
    /// configuration), whatever the X visual shows.
    pub alpha: i32,
    pub double: bool,
    pub depth_bits: i32,
    pub stencil_bits: i32,
    /// Bits per accumulation channel.
    pub accum: i32,
    /// Samples per pixel of the multisample buffer (0: none).
    pub samples: i32,
}

impl FbConfig {
    /// Colour bits without alpha, as `GLX_BUFFER_SIZE` counts them for the visual's depth.
    pub fn buffer_size(&self) -> i32 {
        self.red + self.green + self.blue + self.alpha
    }

    pub fn context_config(&self) -> ContextConfig {
        ContextConfig {
            width: 0,
            height: 0,
            framebuffer: FramebufferConfig {
                depth_bits: self.depth_bits as u32,
                stencil_bits: self.stencil_bits as u32,
                accum_bits: self.accum as u32,
                double_buffer: self.double,
                samples: self.samples as u32,
            },
            threads: 0,
        }
    }
}

/// The configurations of each (display address, screen), made once.
type ConfigTable = HashMap<(usize, i32), Vec<&'static FbConfig>>;

fn config_table() -> &'static Mutex<ConfigTable> {
    static T: OnceLock<Mutex<ConfigTable>> = OnceLock::new();
    T.get_or_init(|| Mutex::new(HashMap::new()))
}

/// The bits of a channel mask.
fn mask_bits(m: c_ulong) -> i32 {
    m.count_ones() as i32
}

/// The configurations of `screen` (TrueColor visuals of depth 15 or more), or none without
/// Xlib or for a bad screen.
pub(crate) fn configs(dpy: *mut Display, screen: i32) -> Vec<&'static FbConfig> {
    let Some(x) = xlib() else { return Vec::new() };
    if dpy.is_null() {
        return Vec::new();
    }
    let key = (dpy as usize, screen);
    let mut table = config_table().lock().unwrap_or_else(|e| e.into_inner());
    if let Some(v) = table.get(&key) {
        return v.clone();
    }
    // SAFETY: `dpy` is the program's open display (the GLX/EGL contract); XScreenCount only
    // reads it.
    let screens = unsafe { (x.XScreenCount)(dpy) };
    if screen < 0 || screen >= screens {
        return Vec::new();
    }
    // SAFETY: a zeroed XVisualInfo is a valid template (plain integers and a null pointer).
    let mut template: xlib::XVisualInfo = unsafe { std::mem::zeroed() };
    template.screen = screen;
    template.class = xlib::TrueColor;
    let mut n: c_int = 0;
    // SAFETY: valid display, template and count pointers; the result is freed with XFree below.
    let list = unsafe {
        (x.XGetVisualInfo)(
            dpy,
            xlib::VisualScreenMask | xlib::VisualClassMask,
            &mut template,
            &mut n,
        )
    };
    let mut out = Vec::new();
    if !list.is_null() {
        // SAFETY: Xlib returned `n` visual infos at `list`.
        let infos = unsafe { std::slice::from_raw_parts(list, n.max(0) as usize) };
        let base_id = table.values().map(|v| v.len()).sum::<usize>() as i32;
        let mut id = 0;
        for vi in infos.iter().filter(|vi| vi.depth >= 15) {
            for double in [true, false] {
                // Multisample buffers (ARB_multisample) come with depth and stencil.
                let kinds = [(24, 8, 0), (0, 0, 0), (24, 8, 2), (24, 8, 4)];
                for (depth_bits, stencil_bits, samples) in kinds {
                    for accum in [0, 16] {
                        id += 1;
                        out.push(&*Box::leak(Box::new(FbConfig {
                            id: base_id + id,
                            screen,
                            visualid: vi.visualid,
                            visual: vi.visual as usize,
                            depth: vi.depth,
                            red: mask_bits(vi.red_mask),
                            green: mask_bits(vi.green_mask),
                            blue: mask_bits(vi.blue_mask),
                            alpha: 8,
                            double,
                            depth_bits,
                            stencil_bits,
                            accum,
                            samples,
                        })));
                    }
                }
            }
        }
        // SAFETY: `list` came from XGetVisualInfo.
        unsafe { (x.XFree)(list as *mut _) };
    }
    table.insert(key, out.clone());
    out
}

/// Whether `p` is one of the configurations handed out (a GLXFBConfig/EGLConfig check).
pub(crate) fn valid_config(p: *const FbConfig) -> Option<&'static FbConfig> {
    let table = config_table().lock().unwrap_or_else(|e| e.into_inner());
    table
        .values()
        .flat_map(|v| v.iter())
        .find(|c| std::ptr::eq(**c, p))
        .copied()
}

/// An `XVisualInfo` (allocated by Xlib, freed by the caller with `XFree`) for the visual of
/// `config`.
pub(crate) fn visual_info(dpy: *mut Display, config: &FbConfig) -> *mut xlib::XVisualInfo {
    let Some(x) = xlib() else {
        return std::ptr::null_mut();
    };
    // SAFETY: a zeroed XVisualInfo is a valid template.
    let mut template: xlib::XVisualInfo = unsafe { std::mem::zeroed() };
    template.visualid = config.visualid;
    template.screen = config.screen;
    let mut n = 0;
    // SAFETY: valid display (the caller's contract), template and count pointers.
    unsafe {
        (x.XGetVisualInfo)(
            dpy,
            xlib::VisualIDMask | xlib::VisualScreenMask,
            &mut template,
            &mut n,
        )
    }
}

/// The size of a window or pixmap, or `None` when Xlib fails.
pub(crate) fn drawable_size(dpy: *mut Display, drawable: c_ulong) -> Option<(i32, i32)> {
    let x = xlib()?;
    if dpy.is_null() || drawable == 0 {
        return None;
    }
    let (mut root, mut px, mut py, mut w, mut h, mut border, mut depth) = (
        0 as c_ulong,
        0,
        0,
        0 as c_uint,
        0 as c_uint,
        0 as c_uint,
        0 as c_uint,
    );
    // SAFETY: valid display and output pointers; a bad drawable is reported through the
    // program's X error handler, as with any Xlib call.
    let ok = unsafe {
        (x.XGetGeometry)(
            dpy,
            drawable,
            &mut root,
            &mut px,
            &mut py,
            &mut w,
            &mut h,
            &mut border,
            &mut depth,
        )
    };
    (ok != 0).then_some((w as i32, h as i32))
}

/// A context of the window-system layers: tilegl's context plus where its pictures go. The
/// OSMesa plumbing (current context per thread, the GL exports) runs it; its presentation hook
/// reads the thread's current drawable from here.
pub struct WindowContext {
    /// Boxed so its address stays put while it is current.
    pub inner: Box<OsMesaContext>,
    /// The address of `inner`: its key in the share-group registry.
    share_key: *const OsMesaContext,
    pub config: &'static FbConfig,
    /// The thread it is current on (GLX: one thread at a time).
    pub current_on: Option<std::thread::ThreadId>,
    /// Destroyed while current: freed when released.
    pub destroy_pending: bool,
    /// Made current at least once (the viewport is set then).
    pub was_current: bool,
    /// Swap interval asked for (recorded; swaps never wait).
    pub swap_interval: i32,
}

impl WindowContext {
    /// A context of `config`, sharing texture objects, display lists and buffer objects with
    /// `share` when given; `None` when `share` is not a live context.
    pub fn new(config: &'static FbConfig, share: Option<*const WindowContext>) -> Option<Self> {
        let mut inner = Box::new(OsMesaContext::for_window(
            config.context_config(),
            present_front_hook,
            resize_to_drawable,
        ));
        let share_inner = match share {
            // SAFETY: the caller checked `s` is a live context of its registry; only its
            // `share_key`, written once at creation, is read (through the field's address, so
            // no reference to a context another thread may be using is made).
            Some(s) => unsafe { std::ptr::addr_of!((*s).share_key).read() },
            None => std::ptr::null(),
        };
        if !super::osmesa::join_share_group(&mut inner, share_inner) {
            return None;
        }
        let share_key = &*inner as *const OsMesaContext;
        Some(WindowContext {
            inner,
            share_key,
            config,
            current_on: None,
            destroy_pending: false,
            was_current: false,
            swap_interval: 0,
        })
    }
}

/// Where the current thread's pictures go.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Target {
    pub dpy: usize,
    pub drawable: c_ulong,
    pub read: c_ulong,
    pub visual: usize,
    pub depth: i32,
}

thread_local! {
    static TARGET: std::cell::Cell<Option<Target>> = const { std::cell::Cell::new(None) };
}

pub(crate) fn current_target() -> Option<Target> {
    TARGET.with(|t| t.get())
}

pub(crate) fn set_current_target(t: Option<Target>) {
    TARGET.with(|c| c.set(t));
}

/// Makes `wc` current on this thread drawing into `target` (resizing its buffers to the
/// drawable), or releases the current context for `None`.
pub(crate) fn bind(wc: Option<(&mut WindowContext, Target)>) {
    match wc {
        None => {
            super::osmesa::set_current_context(std::ptr::null_mut());
            set_current_target(None);
        }
        Some((wc, target)) => {
            let size = drawable_size(target.dpy as *mut Display, target.drawable);
            let (w, h) = size.unwrap_or((0, 0));
            wc.inner.gl.resize(w, h);
            if !wc.was_current {
                wc.was_current = true;
                wc.inner.gl.viewport(0, 0, w, h);
                wc.inner.gl.scissor(0, 0, w, h);
                wc.inner.gl.take_drawable_check_request();
            }
            wc.inner.gl.refresh_shared_objects();
            set_current_target(Some(target));
            super::osmesa::set_current_context(&mut *wc.inner);
        }
    }
}

/// After `glViewport`: buffers of the drawable's size when the window was resized (the
/// contents then start cleared).
fn resize_to_drawable(gl: &mut Context) {
    let Some(t) = current_target() else { return };
    match drawable_size(t.dpy as *mut Display, t.drawable) {
        // Unchanged: no flush (programs set several viewports in a frame).
        Some(size) if size != gl.size() => gl.resize(size.0, size.1),
        _ => {}
    }
}

/// After `glFlush`/`glFinish`: shows the front buffer when the program draws into it
/// (single-buffered configurations, `glDrawBuffer(GL_FRONT)`); a back buffer waits for the swap.
fn present_front_hook(gl: &mut Context) {
    let Some(t) = current_target() else { return };
    let draws_front = {
        let fb = gl.framebuffer();
        !fb.is_double_buffered()
            || matches!(
                fb.draw,
                DrawTarget::One(ColorBuffer::Front) | DrawTarget::Both
            )
    };
    if draws_front {
        present(gl, &t, true);
    }
}

/// The buffer swap of the current context: back to front, then the picture to the drawable;
/// a changed drawable size reallocates the buffers for the next frame.
pub(crate) fn swap_current(gl: &mut Context) {
    let Some(t) = current_target() else { return };
    gl.swap_buffers();
    present(gl, &t, true);
    if let Some((w, h)) = drawable_size(t.dpy as *mut Display, t.drawable) {
        gl.resize(w, h);
    }
}

/// The front colour buffer, bottom row first, RGBA8.
fn front_rows(gl: &mut Context) -> (i32, i32, Vec<u8>) {
    let fb = gl.framebuffer_mut();
    let (w, h) = (fb.width, fb.height);
    if fb.is_double_buffered() && fb.resident == ColorBuffer::Back {
        fb.make_resident(ColorBuffer::Front);
        let rows = fb.color_rows_bottom_up();
        fb.make_resident(ColorBuffer::Back);
        (w, h, rows)
    } else {
        (w, h, fb.color_rows_bottom_up())
    }
}

fn shift_and_bits(mask: c_ulong) -> (u32, u32) {
    if mask == 0 {
        return (0, 0);
    }
    (mask.trailing_zeros(), mask.count_ones())
}

/// An 8-bit channel value scaled to `bits` bits at `shift`.
fn channel(v: u8, shift: u32, bits: u32) -> c_ulong {
    let scaled = if bits >= 8 {
        (v as c_ulong) << (bits - 8)
    } else {
        (v as c_ulong) >> (8 - bits)
    };
    scaled << shift
}

/// Writes `rows` (RGBA8, bottom row first, `w` x `h`) into `img`'s pixel data `data` in the
/// image's layout (X's first row is the top one).
///
/// # Safety
/// `img` is a live `w` x `h` XImage whose `data` is `data` (at least `bytes_per_line * h`
/// bytes).
unsafe fn fill_image(img: *mut xlib::XImage, data: &mut [u8], rows: &[u8], w: usize, h: usize) {
    // SAFETY: the caller's contract.
    let i = unsafe { &*img };
    let (bpl, bpp, order) = (i.bytes_per_line as usize, i.bits_per_pixel, i.byte_order);
    let (rs, rb) = shift_and_bits(i.red_mask);
    let (gs, gb) = shift_and_bits(i.green_mask);
    let (bs, bb) = shift_and_bits(i.blue_mask);
    let px = |c: &[u8]| channel(c[0], rs, rb) | channel(c[1], gs, gb) | channel(c[2], bs, bb);
    let bgrx = bpp == 32
        && order == xlib::LSBFirst
        && (i.red_mask, i.green_mask, i.blue_mask) == (0xff0000, 0xff00, 0xff);
    if bgrx {
        // The usual 24-bit TrueColor layout: bytes B, G, R, unused (a plain byte shuffle).
        for y in 0..h {
            let src = &rows[(h - 1 - y) * w * 4..][..w * 4];
            let dst = &mut data[y * bpl..][..w * 4];
            for (s, d) in src.chunks_exact(4).zip(dst.chunks_exact_mut(4)) {
                d.copy_from_slice(&[s[2], s[1], s[0], 0]);
            }
        }
    } else if bpp == 32 {
        for y in 0..h {
            let src = &rows[(h - 1 - y) * w * 4..][..w * 4];
            let dst = &mut data[y * bpl..][..w * 4];
            for (s, d) in src.chunks_exact(4).zip(dst.chunks_exact_mut(4)) {
                let v = px(s) as u32;
                d.copy_from_slice(&if order == xlib::LSBFirst {
                    v.to_le_bytes()
                } else {
                    v.to_be_bytes()
                });
            }
        }
    } else if let Some(put) = i.funcs.put_pixel {
        for y in 0..h {
            let src = &rows[(h - 1 - y) * w * 4..][..w * 4];
            for (xx, s) in src.chunks_exact(4).enumerate() {
                // SAFETY: (xx, y) is inside the w x h image whose data is `data`.
                unsafe { put(img, xx as c_int, y as c_int, px(s)) };
            }
        }
    }
}

/// MIT-SHM's functions, or `None` when `libXext.so.6` cannot be loaded.
fn xext() -> Option<&'static x11_dl::xshm::Xext> {
    static X: OnceLock<Option<x11_dl::xshm::Xext>> = OnceLock::new();
    X.get_or_init(|| x11_dl::xshm::Xext::open().ok()).as_ref()
}

extern "C" {
    fn shmget(key: c_int, size: usize, flags: c_int) -> c_int;
    fn shmat(id: c_int, addr: *const std::ffi::c_void, flags: c_int) -> *mut std::ffi::c_void;
    fn shmdt(addr: *const std::ffi::c_void) -> c_int;
    fn shmctl(id: c_int, cmd: c_int, buf: *mut std::ffi::c_void) -> c_int;
}
const IPC_PRIVATE: c_int = 0;
const IPC_CREAT: c_int = 0o1000;
const IPC_RMID: c_int = 0;

/// A shared-memory image the X server reads a drawable's frames from.
struct ShmImage {
    image: *mut xlib::XImage,
    info: Box<x11_dl::xshm::XShmSegmentInfo>,
    width: i32,
    height: i32,
}

// SAFETY: the image and segment are only used under the table's lock, on the display they
// were made for (Xlib calls on one display from several threads need XInitThreads, which is
// the program's contract as for any Xlib use).
unsafe impl Send for ShmImage {}

/// The shared-memory images by (display, drawable): one segment per drawable, replaced when
/// the drawable's size changes. At most [`SHM_IMAGES`] are kept (the oldest is freed).
type ShmTable = Vec<((usize, c_ulong), ShmImage)>;
const SHM_IMAGES: usize = 8;

fn shm_table() -> &'static Mutex<ShmTable> {
    static T: OnceLock<Mutex<ShmTable>> = OnceLock::new();
    T.get_or_init(|| Mutex::new(Vec::new()))
}

/// Whether presenting goes through MIT-SHM on `dpy`: the server has the extension with
/// shared pixmaps' image support, the display is local (a `:N` or `unix:N` name: a remote
/// server cannot map this process's memory) and `TILEGL_NO_SHM` is not set to 1.
fn shm_usable(dpy: *mut Display) -> bool {
    let mut known = shm_displays().lock().unwrap_or_else(|e| e.into_inner());
    *known.entry(dpy as usize).or_insert_with(|| {
        let (Some(x), Some(ext)) = (xlib(), xext()) else {
            return false;
        };
        // SAFETY: an open display; the hook runs inside XCloseDisplay and only drops what is
        // kept here for this display (its address may be reused by a later XOpenDisplay).
        unsafe {
            let codes = (x.XAddExtension)(dpy);
            if !codes.is_null() {
                (x.XESetCloseDisplay)(dpy, (*codes).extension, Some(forget_display));
            }
        }
        // SAFETY: an open display; XDisplayString returns its name (owned by Xlib).
        let name = unsafe {
            let p = (x.XDisplayString)(dpy);
            if p.is_null() {
                return false;
            }
            std::ffi::CStr::from_ptr(p).to_string_lossy().into_owned()
        };
        let local = name.starts_with(':') || name.starts_with("unix:");
        // SAFETY: an open display.
        let has = unsafe { (ext.XShmQueryExtension)(dpy) } != 0;
        let disabled = std::env::var("TILEGL_NO_SHM").is_ok_and(|v| v == "1");
        let usable = local && has && !disabled;
        if std::env::var("TILEGL_DEBUG_PRESENT").is_ok_and(|v| v == "1") {
            eprintln!(
                "tilegl: presenting on {name} with {}",
                if usable { "MIT-SHM" } else { "XPutImage" }
            );
        }
        usable
    })
}

/// What presenting knows per display (address): whether it uses MIT-SHM there.
fn shm_displays() -> &'static Mutex<HashMap<usize, bool>> {
    static D: OnceLock<Mutex<HashMap<usize, bool>>> = OnceLock::new();
    D.get_or_init(|| Mutex::new(HashMap::new()))
}

/// Xlib's close-display hook: forgets the display and its shared-memory images (the server
/// drops its side of the segments with the connection; this process unmaps its own).
unsafe extern "C" fn forget_display(dpy: *mut Display, _codes: *mut xlib::XExtCodes) -> c_int {
    shm_displays()
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .remove(&(dpy as usize));
    let mut table = shm_table().lock().unwrap_or_else(|e| e.into_inner());
    let Some(x) = xlib() else { return 0 };
    table.retain(|((d, _), s)| {
        if *d != dpy as usize {
            return true;
        }
        // SAFETY: made by new_shm_image; only client-side memory is released (the image
        // structure, detached from the segment first, and this process's mapping).
        unsafe {
            (*s.image).data = std::ptr::null_mut();
            (x.XDestroyImage)(s.image);
            shmdt(s.info.shmaddr as *const std::ffi::c_void);
        }
        false
    });
    0
}

/// Frees a shared-memory image (detached from the server, then from this process).
///
/// # Safety
/// `s` was made by [`new_shm_image`] on `dpy`, which is still open.
unsafe fn free_shm_image(x: &Xlib, ext: &x11_dl::xshm::Xext, dpy: *mut Display, s: ShmImage) {
    // SAFETY: the caller's contract; the server is synced before the memory goes.
    unsafe {
        (ext.XShmDetach)(dpy, &*s.info as *const _ as *mut _);
        (x.XSync)(dpy, 0);
        (*s.image).data = std::ptr::null_mut();
        (x.XDestroyImage)(s.image);
        shmdt(s.info.shmaddr as *const std::ffi::c_void);
    }
}

/// A shared-memory image of `w` x `h` pixels of `t`'s visual, attached to the server, or
/// `None` when that fails (no segment, or the server refused it).
///
/// # Safety
/// `dpy` is open and `t.visual` is one of its visuals.
unsafe fn new_shm_image(
    x: &Xlib,
    ext: &x11_dl::xshm::Xext,
    dpy: *mut Display,
    t: &Target,
    w: i32,
    h: i32,
) -> Option<ShmImage> {
    // SAFETY: a zeroed segment description is valid (integers and a null pointer).
    let mut info: Box<x11_dl::xshm::XShmSegmentInfo> = Box::new(unsafe { std::mem::zeroed() });
    // SAFETY (whole block): Xlib/MIT-SHM calls on the open display; the segment is created,
    // attached here and to the server, and marked for removal once both detach (so it never
    // outlives the process); every failure path undoes what was done.
    unsafe {
        let image = (ext.XShmCreateImage)(
            dpy,
            t.visual as *mut xlib::Visual,
            t.depth as c_uint,
            xlib::ZPixmap,
            std::ptr::null_mut(),
            &mut *info,
            w as c_uint,
            h as c_uint,
        );
        if image.is_null() {
            return None;
        }
        let bytes = (*image).bytes_per_line as usize * h as usize;
        info.shmid = shmget(IPC_PRIVATE, bytes, IPC_CREAT | 0o600);
        if info.shmid < 0 {
            (x.XDestroyImage)(image);
            return None;
        }
        let addr = shmat(info.shmid, std::ptr::null(), 0);
        if addr as isize == -1 {
            shmctl(info.shmid, IPC_RMID, std::ptr::null_mut());
            (x.XDestroyImage)(image);
            return None;
        }
        info.shmaddr = addr as *mut c_char;
        (*image).data = info.shmaddr;
        info.readOnly = 0;
        let attached = (ext.XShmAttach)(dpy, &mut *info) != 0;
        (x.XSync)(dpy, 0);
        shmctl(info.shmid, IPC_RMID, std::ptr::null_mut());
        if !attached {
            (*image).data = std::ptr::null_mut();
            (x.XDestroyImage)(image);
            shmdt(addr);
            return None;
        }
        Some(ShmImage {
            image,
            info,
            width: w,
            height: h,
        })
    }
}

/// Presents through MIT-SHM; false when it cannot (then the caller uses `XPutImage`).
fn present_shm(x: &Xlib, t: &Target, rows: &[u8], w: i32, h: i32, gc: xlib::GC) -> bool {
    let dpy = t.dpy as *mut Display;
    let Some(ext) = xext() else { return false };
    if !shm_usable(dpy) {
        return false;
    }
    let key = (t.dpy, t.drawable);
    let mut table = shm_table().lock().unwrap_or_else(|e| e.into_inner());
    let pos = table.iter().position(|(k, _)| *k == key);
    let stale = pos.is_some_and(|i| (table[i].1.width, table[i].1.height) != (w, h));
    if stale {
        let (_, old) = table.remove(pos.unwrap_or_default());
        // SAFETY: made by new_shm_image on this display, which is open (it is being drawn to).
        unsafe { free_shm_image(x, ext, dpy, old) };
    }
    let i = match table.iter().position(|(k, _)| *k == key) {
        Some(i) => i,
        None => {
            // SAFETY: the display is open and the target's visual belongs to it.
            let Some(img) = (unsafe { new_shm_image(x, ext, dpy, t, w, h) }) else {
                return false;
            };
            if table.len() >= SHM_IMAGES {
                let ((old_dpy, _), old) = table.remove(0);
                // SAFETY: made by new_shm_image on a display still open (closing a display
                // drops its images, `forget_display`).
                unsafe { free_shm_image(x, ext, old_dpy as *mut Display, old) };
            }
            table.push((key, img));
            table.len() - 1
        }
    };
    let s = &table[i].1;
    // SAFETY: the segment holds bytes_per_line * h bytes mapped here; the previous
    // XShmPutImage finished reading it (every present syncs with the server).
    unsafe {
        let len = (*s.image).bytes_per_line as usize * h as usize;
        let data = std::slice::from_raw_parts_mut(s.info.shmaddr as *mut u8, len);
        fill_image(s.image, data, rows, w as usize, h as usize);
        (ext.XShmPutImage)(
            dpy,
            t.drawable,
            gc,
            s.image,
            0,
            0,
            0,
            0,
            w as c_uint,
            h as c_uint,
            0,
        );
    }
    true
}

/// Copies the front buffer into the drawable, through MIT-SHM when the server offers it (see
/// [`shm_usable`]), else with `XPutImage`. `sync` waits for the server (so a screenshot
/// right after a swap shows the frame).
fn present(gl: &mut Context, t: &Target, sync: bool) {
    let Some(x) = xlib() else { return };
    let (w, h, rows) = front_rows(gl);
    if w <= 0 || h <= 0 || t.visual == 0 {
        return;
    }
    let dpy = t.dpy as *mut Display;
    // SAFETY: a default GC for the drawable, freed below.
    let gc = unsafe { (x.XCreateGC)(dpy, t.drawable, 0, std::ptr::null_mut()) };
    if !present_shm(x, t, &rows, w, h, gc) {
        present_put_image(x, t, &rows, w, h, gc);
    }
    // SAFETY: the GC made above; the display is open.
    unsafe {
        (x.XFreeGC)(dpy, gc);
        if sync {
            (x.XSync)(dpy, 0);
        } else {
            (x.XFlush)(dpy);
        }
    }
}

/// Presents with `XPutImage` from a buffer of this process.
fn present_put_image(x: &Xlib, t: &Target, rows: &[u8], w: i32, h: i32, gc: xlib::GC) {
    let dpy = t.dpy as *mut Display;
    // SAFETY: `t.visual` is a Visual of this display (from XGetVisualInfo); XCreateImage with a
    // null data pointer only computes the layout (bytes_per_line, bits_per_pixel).
    let img = unsafe {
        (x.XCreateImage)(
            dpy,
            t.visual as *mut xlib::Visual,
            t.depth as c_uint,
            xlib::ZPixmap,
            0,
            std::ptr::null_mut(),
            w as c_uint,
            h as c_uint,
            32,
            0,
        )
    };
    if img.is_null() {
        return;
    }
    // SAFETY: img is a live XImage from XCreateImage.
    let bpl = unsafe { (*img).bytes_per_line as usize };
    let mut data = vec![0u8; bpl * h as usize];
    // SAFETY: `data` outlives every use of the image below and is detached before the image
    // is destroyed (XDestroyImage would free it otherwise); it holds bpl * h bytes.
    unsafe {
        (*img).data = data.as_mut_ptr() as *mut c_char;
        fill_image(img, &mut data, rows, w as usize, h as usize);
        (x.XPutImage)(
            dpy,
            t.drawable,
            gc,
            img,
            0,
            0,
            0,
            0,
            w as c_uint,
            h as c_uint,
        );
        (*img).data = std::ptr::null_mut();
        (x.XDestroyImage)(img);
    }
}

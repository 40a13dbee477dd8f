//! EGL 1.4 on X11 for desktop OpenGL (`EGL_OPENGL_API`), with the EGL 1.5 platform-display
//! and platform-window entry points that X11 programs such as xscreensaver 6 call.
//! `libEGL.so.1` (a link to this library) exports these; contexts and presentation are the
//! ones of the GLX layer (module `window`).
//!
//! One leniency: `eglChooseConfig` does not match the OpenGL ES bits of an `EGL_RENDERABLE_TYPE`
//! request (`EGL_OPENGL_ES_BIT` is EGL's default, and programs such as xscreensaver ask for it
//! and then bind `EGL_OPENGL_API`); the configurations themselves report `EGL_OPENGL_BIT` only,
//! and an OpenGL ES context still cannot be made (`eglBindAPI(EGL_OPENGL_ES_API)` fails).
//!
//! Limits, reported through `eglGetError`: only `EGL_OPENGL_API` (up to OpenGL 1.5) can be
//! bound, only window surfaces can be made (pbuffer and pixmap surfaces fail with
//! `EGL_BAD_MATCH`), multisample configurations have 2 or 4 samples (`EGL_SAMPLES`), and swaps never wait
//! (`eglSwapInterval` is recorded, `EGL_MAX_SWAP_INTERVAL` is 0).

#![allow(non_snake_case)]

use std::cell::Cell;
use std::collections::HashMap;
use std::ffi::{c_char, c_void, CStr};
use std::sync::{Mutex, OnceLock};

use x11_dl::xlib::Display;

use super::window::{self, FbConfig, Target, WindowContext};

pub type EGLint = i32;
pub type EGLBoolean = u32;
pub type EGLenum = u32;
pub type EGLAttrib = isize;
pub type EGLDisplay = *mut c_void;
pub type EGLConfig = *const FbConfig;
pub type EGLSurface = *mut c_void;
pub type EGLContext = *mut c_void;

const TRUE: EGLBoolean = 1;
const FALSE: EGLBoolean = 0;

pub const EGL_SUCCESS: EGLint = 0x3000;
pub const EGL_NOT_INITIALIZED: EGLint = 0x3001;
pub const EGL_BAD_ACCESS: EGLint = 0x3002;
pub const EGL_BAD_ATTRIBUTE: EGLint = 0x3004;
pub const EGL_BAD_CONFIG: EGLint = 0x3005;
pub const EGL_BAD_CONTEXT: EGLint = 0x3006;
pub const EGL_BAD_DISPLAY: EGLint = 0x3008;
pub const EGL_BAD_MATCH: EGLint = 0x3009;
pub const EGL_BAD_NATIVE_WINDOW: EGLint = 0x300B;
pub const EGL_BAD_PARAMETER: EGLint = 0x300C;
pub const EGL_BAD_SURFACE: EGLint = 0x300D;

pub const EGL_BUFFER_SIZE: EGLint = 0x3020;
pub const EGL_ALPHA_SIZE: EGLint = 0x3021;
pub const EGL_BLUE_SIZE: EGLint = 0x3022;
pub const EGL_GREEN_SIZE: EGLint = 0x3023;
pub const EGL_RED_SIZE: EGLint = 0x3024;
pub const EGL_DEPTH_SIZE: EGLint = 0x3025;
pub const EGL_STENCIL_SIZE: EGLint = 0x3026;
pub const EGL_CONFIG_CAVEAT: EGLint = 0x3027;
pub const EGL_CONFIG_ID: EGLint = 0x3028;
pub const EGL_LEVEL: EGLint = 0x3029;
pub const EGL_MAX_PBUFFER_HEIGHT: EGLint = 0x302A;
pub const EGL_MAX_PBUFFER_PIXELS: EGLint = 0x302B;
pub const EGL_MAX_PBUFFER_WIDTH: EGLint = 0x302C;
pub const EGL_NATIVE_RENDERABLE: EGLint = 0x302D;
pub const EGL_NATIVE_VISUAL_ID: EGLint = 0x302E;
pub const EGL_NATIVE_VISUAL_TYPE: EGLint = 0x302F;
pub const EGL_SAMPLES: EGLint = 0x3031;
pub const EGL_SAMPLE_BUFFERS: EGLint = 0x3032;
pub const EGL_SURFACE_TYPE: EGLint = 0x3033;
pub const EGL_TRANSPARENT_TYPE: EGLint = 0x3034;
pub const EGL_TRANSPARENT_BLUE_VALUE: EGLint = 0x3035;
pub const EGL_TRANSPARENT_GREEN_VALUE: EGLint = 0x3036;
pub const EGL_TRANSPARENT_RED_VALUE: EGLint = 0x3037;
pub const EGL_NONE: EGLint = 0x3038;
pub const EGL_BIND_TO_TEXTURE_RGB: EGLint = 0x3039;
pub const EGL_BIND_TO_TEXTURE_RGBA: EGLint = 0x303A;
pub const EGL_MIN_SWAP_INTERVAL: EGLint = 0x303B;
pub const EGL_MAX_SWAP_INTERVAL: EGLint = 0x303C;
pub const EGL_LUMINANCE_SIZE: EGLint = 0x303D;
pub const EGL_ALPHA_MASK_SIZE: EGLint = 0x303E;
pub const EGL_COLOR_BUFFER_TYPE: EGLint = 0x303F;
pub const EGL_RENDERABLE_TYPE: EGLint = 0x3040;
pub const EGL_MATCH_NATIVE_PIXMAP: EGLint = 0x3041;
pub const EGL_CONFORMANT: EGLint = 0x3042;
pub const EGL_RGB_BUFFER: EGLint = 0x308E;
pub const EGL_WINDOW_BIT: EGLint = 0x4;
pub const EGL_OPENGL_BIT: EGLint = 0x8;
pub const EGL_DONT_CARE: EGLint = -1;
pub const EGL_VENDOR: EGLint = 0x3053;
pub const EGL_VERSION: EGLint = 0x3054;
pub const EGL_EXTENSIONS: EGLint = 0x3055;
pub const EGL_CLIENT_APIS: EGLint = 0x308D;
pub const EGL_HEIGHT: EGLint = 0x3056;
pub const EGL_WIDTH: EGLint = 0x3057;
pub const EGL_LARGEST_PBUFFER: EGLint = 0x3058;
pub const EGL_DRAW: EGLint = 0x3059;
pub const EGL_READ: EGLint = 0x305A;
pub const EGL_RENDER_BUFFER: EGLint = 0x3086;
pub const EGL_BACK_BUFFER: EGLint = 0x3084;
pub const EGL_SWAP_BEHAVIOR: EGLint = 0x3093;
pub const EGL_BUFFER_PRESERVED: EGLint = 0x3094;
pub const EGL_HORIZONTAL_RESOLUTION: EGLint = 0x3090;
pub const EGL_VERTICAL_RESOLUTION: EGLint = 0x3091;
pub const EGL_PIXEL_ASPECT_RATIO: EGLint = 0x3092;
pub const EGL_MULTISAMPLE_RESOLVE: EGLint = 0x3099;
pub const EGL_MULTISAMPLE_RESOLVE_DEFAULT: EGLint = 0x309A;
pub const EGL_UNKNOWN: EGLint = -1;
pub const EGL_OPENGL_ES_API: EGLenum = 0x30A0;
pub const EGL_OPENGL_API: EGLenum = 0x30A2;
pub const EGL_CONTEXT_CLIENT_TYPE: EGLint = 0x3097;
pub const EGL_CONTEXT_MAJOR_VERSION: EGLint = 0x3098;
pub const EGL_CONTEXT_MINOR_VERSION: EGLint = 0x30FB;
pub const EGL_CONTEXT_FLAGS_KHR: EGLint = 0x30FC;
pub const EGL_CONTEXT_OPENGL_PROFILE_MASK: EGLint = 0x30FD;
pub const EGL_CONTEXT_OPENGL_DEBUG: EGLint = 0x31B0;
pub const EGL_PLATFORM_X11_KHR: EGLenum = 0x31D5;
pub const EGL_PLATFORM_X11_SCREEN_KHR: EGLAttrib = 0x31D6;

const CLIENT_EXTENSIONS: &CStr =
    c"EGL_EXT_client_extensions EGL_EXT_platform_base EGL_KHR_platform_x11 EGL_EXT_platform_x11";
const DISPLAY_EXTENSIONS: &CStr = c"EGL_KHR_create_context";

thread_local! {
    static ERROR: Cell<EGLint> = const { Cell::new(EGL_SUCCESS) };
    /// `EGL_NONE` until `eglBindAPI(EGL_OPENGL_API)`: OpenGL ES, EGL's default, is not offered.
    static API: Cell<EGLenum> = const { Cell::new(EGL_NONE as EGLenum) };
    /// (context, draw surface, read surface, display).
    static CURRENT: Cell<(usize, usize, usize, usize)> = const { Cell::new((0, 0, 0, 0)) };
}

fn fail<T>(e: EGLint, v: T) -> T {
    ERROR.with(|c| c.set(e));
    v
}

fn ok<T>(v: T) -> T {
    ERROR.with(|c| c.set(EGL_SUCCESS));
    v
}

struct EglDisplay {
    xdpy: *mut Display,
    screen: i32,
    initialized: bool,
}

struct EglSurface {
    window: std::ffi::c_ulong,
    config: &'static FbConfig,
    swap_interval: i32,
}

struct Objects {
    /// Boxed: an `EGLDisplay` is the address of its record, which must not move.
    #[allow(clippy::vec_box)]
    displays: Vec<Box<EglDisplay>>,
    surfaces: HashMap<usize, Box<EglSurface>>,
    contexts: HashMap<usize, Box<WindowContext>>,
}

// SAFETY: the raw pointers in these records are addresses handed to and from the program;
// they are only dereferenced by Xlib calls on the program's own display, under the lock.
unsafe impl Send for Objects {}

fn objects() -> std::sync::MutexGuard<'static, Objects> {
    static O: OnceLock<Mutex<Objects>> = OnceLock::new();
    O.get_or_init(|| {
        Mutex::new(Objects {
            displays: Vec::new(),
            surfaces: HashMap::new(),
            contexts: HashMap::new(),
        })
    })
    .lock()
    .unwrap_or_else(|e| e.into_inner())
}

/// The display record behind an `EGLDisplay`, if it is one of ours.
fn display(o: &Objects, dpy: EGLDisplay) -> Option<&EglDisplay> {
    o.displays
        .iter()
        .find(|d| std::ptr::eq(&***d, dpy as *const EglDisplay))
        .map(|d| &**d)
}

fn display_mut(o: &mut Objects, dpy: EGLDisplay) -> Option<&mut EglDisplay> {
    o.displays
        .iter_mut()
        .find(|d| std::ptr::eq(&***d, dpy as *const EglDisplay))
        .map(|d| &mut **d)
}

fn get_display(native: *mut Display, screen: i32) -> EGLDisplay {
    let Some(x) = window::xlib() else {
        return std::ptr::null_mut();
    };
    let native = if native.is_null() {
        // SAFETY: XOpenDisplay(NULL) opens $DISPLAY; the connection stays open for the process.
        let d = unsafe { (x.XOpenDisplay)(std::ptr::null()) };
        if d.is_null() {
            return std::ptr::null_mut();
        }
        d
    } else {
        native
    };
    let mut o = objects();
    if let Some(d) = o
        .displays
        .iter()
        .find(|d| d.xdpy == native && d.screen == screen)
    {
        return &**d as *const EglDisplay as EGLDisplay;
    }
    let d = Box::new(EglDisplay {
        xdpy: native,
        screen,
        initialized: false,
    });
    let p = &*d as *const EglDisplay as EGLDisplay;
    o.displays.push(d);
    p
}

/// `eglGetDisplay`: an X11 `Display*` (or `EGL_DEFAULT_DISPLAY`, which opens `$DISPLAY`).
#[no_mangle]
pub extern "C" fn eglGetDisplay(native: *mut c_void) -> EGLDisplay {
    let d = get_display(native as *mut Display, -1);
    if d.is_null() {
        return fail(EGL_BAD_DISPLAY, d);
    }
    ok(d)
}

fn platform_display(platform: EGLenum, native: *mut c_void, screen: Option<i32>) -> EGLDisplay {
    if platform != EGL_PLATFORM_X11_KHR {
        return fail(EGL_BAD_PARAMETER, std::ptr::null_mut());
    }
    let d = get_display(native as *mut Display, screen.unwrap_or(-1));
    if d.is_null() {
        return fail(EGL_BAD_DISPLAY, d);
    }
    ok(d)
}

/// `eglGetPlatformDisplay` (X11 only).
///
/// # Safety
/// `attribs` is null or an `EGL_NONE`-terminated list of pairs.
#[no_mangle]
pub unsafe extern "C" fn eglGetPlatformDisplay(
    platform: EGLenum,
    native: *mut c_void,
    attribs: *const EGLAttrib,
) -> EGLDisplay {
    let mut screen = None;
    // SAFETY: forwarded contract.
    for (a, v) in unsafe { pairs(attribs) } {
        if a == EGL_PLATFORM_X11_SCREEN_KHR {
            screen = Some(v as i32);
        } else {
            return fail(EGL_BAD_ATTRIBUTE, std::ptr::null_mut());
        }
    }
    platform_display(platform, native, screen)
}

/// `eglGetPlatformDisplayEXT` (X11 only).
///
/// # Safety
/// `attribs` is null or an `EGL_NONE`-terminated list of pairs.
#[no_mangle]
pub unsafe extern "C" fn eglGetPlatformDisplayEXT(
    platform: EGLenum,
    native: *mut c_void,
    attribs: *const EGLint,
) -> EGLDisplay {
    let mut screen = None;
    // SAFETY: forwarded contract.
    for (a, v) in unsafe { pairs(attribs) } {
        if a == EGL_PLATFORM_X11_SCREEN_KHR as EGLint {
            screen = Some(v);
        } else {
            return fail(EGL_BAD_ATTRIBUTE, std::ptr::null_mut());
        }
    }
    platform_display(platform, native, screen)
}

/// Attribute pairs up to `EGL_NONE`.
///
/// # Safety
/// `p` is null or an `EGL_NONE`-terminated list of pairs.
unsafe fn pairs<T: Copy + TryInto<i64>>(p: *const T) -> Vec<(T, T)> {
    let mut out = Vec::new();
    if p.is_null() {
        return out;
    }
    let mut i = 0;
    loop {
        // SAFETY: the list is terminated by EGL_NONE, so reads up to it are in bounds.
        let a = unsafe { *p.add(i) };
        if a.try_into().unwrap_or(EGL_NONE as i64) == EGL_NONE as i64 || out.len() > 1000 {
            break;
        }
        // SAFETY: as above; a name is followed by its value.
        out.push((a, unsafe { *p.add(i + 1) }));
        i += 2;
    }
    out
}

/// The screen of a display (its X default screen unless the platform attributes named one).
fn screen_of(d: &EglDisplay) -> i32 {
    if d.screen >= 0 {
        return d.screen;
    }
    match window::xlib() {
        // SAFETY: an open display.
        Some(x) => unsafe { (x.XDefaultScreen)(d.xdpy) },
        None => 0,
    }
}

/// `eglInitialize`: EGL 1.4.
///
/// # Safety
/// Non-null pointers are writable.
#[no_mangle]
pub unsafe extern "C" fn eglInitialize(
    dpy: EGLDisplay,
    major: *mut EGLint,
    minor: *mut EGLint,
) -> EGLBoolean {
    let mut o = objects();
    let Some(d) = display_mut(&mut o, dpy) else {
        return fail(EGL_BAD_DISPLAY, FALSE);
    };
    d.initialized = true;
    // SAFETY: null or caller-owned ints.
    unsafe {
        if let Some(m) = major.as_mut() {
            *m = 1;
        }
        if let Some(m) = minor.as_mut() {
            *m = 4;
        }
    }
    ok(TRUE)
}

/// `eglTerminate`: the display becomes uninitialized (its surfaces and contexts stay valid
/// for `eglDestroy*`, and a current context stays current, as EGL allows).
#[no_mangle]
pub extern "C" fn eglTerminate(dpy: EGLDisplay) -> EGLBoolean {
    let mut o = objects();
    let Some(d) = display_mut(&mut o, dpy) else {
        return fail(EGL_BAD_DISPLAY, FALSE);
    };
    d.initialized = false;
    ok(TRUE)
}

/// An initialized display, or the error to report.
fn initialized(o: &Objects, dpy: EGLDisplay) -> Result<(*mut Display, i32), EGLint> {
    match display(o, dpy) {
        None => Err(EGL_BAD_DISPLAY),
        Some(d) if !d.initialized => Err(EGL_NOT_INITIALIZED),
        Some(d) => Ok((d.xdpy, screen_of(d))),
    }
}

/// `eglQueryString`.
#[no_mangle]
pub extern "C" fn eglQueryString(dpy: EGLDisplay, name: EGLint) -> *const c_char {
    if dpy.is_null() {
        return if name == EGL_EXTENSIONS {
            ok(CLIENT_EXTENSIONS.as_ptr())
        } else {
            fail(EGL_BAD_DISPLAY, std::ptr::null())
        };
    }
    let o = objects();
    if let Err(e) = initialized(&o, dpy) {
        return fail(e, std::ptr::null());
    }
    ok(match name {
        EGL_VENDOR => c"tilegl".as_ptr(),
        EGL_VERSION => c"1.4 tilegl".as_ptr(),
        EGL_CLIENT_APIS => c"OpenGL".as_ptr(),
        EGL_EXTENSIONS => DISPLAY_EXTENSIONS.as_ptr(),
        _ => return fail(EGL_BAD_PARAMETER, std::ptr::null()),
    })
}

/// EGL's configurations: the double-buffered window configurations with an accumulation
/// buffer (EGL window surfaces render to a back buffer; EGL has no accumulation attribute,
/// so every configuration keeps one for the GL programs that use it).
fn egl_configs(xdpy: *mut Display, screen: i32) -> Vec<&'static FbConfig> {
    window::configs(xdpy, screen)
        .into_iter()
        .filter(|c| c.double && c.accum > 0)
        .collect()
}

fn config_attrib(c: &FbConfig, a: EGLint) -> Option<EGLint> {
    Some(match a {
        EGL_BUFFER_SIZE => c.buffer_size(),
        EGL_RED_SIZE => c.red,
        EGL_GREEN_SIZE => c.green,
        EGL_BLUE_SIZE => c.blue,
        EGL_ALPHA_SIZE => c.alpha,
        EGL_DEPTH_SIZE => c.depth_bits,
        EGL_STENCIL_SIZE => c.stencil_bits,
        EGL_CONFIG_CAVEAT => EGL_NONE,
        EGL_CONFIG_ID => c.id,
        EGL_LEVEL => 0,
        EGL_MAX_PBUFFER_HEIGHT | EGL_MAX_PBUFFER_WIDTH | EGL_MAX_PBUFFER_PIXELS => 0,
        EGL_NATIVE_RENDERABLE => TRUE as EGLint,
        EGL_NATIVE_VISUAL_ID => c.visualid as EGLint,
        EGL_NATIVE_VISUAL_TYPE => x11_dl::xlib::TrueColor,
        EGL_SAMPLES => c.samples,
        EGL_SAMPLE_BUFFERS => (c.samples > 0) as EGLint,
        EGL_SURFACE_TYPE => EGL_WINDOW_BIT,
        EGL_TRANSPARENT_TYPE => EGL_NONE,
        EGL_TRANSPARENT_RED_VALUE | EGL_TRANSPARENT_GREEN_VALUE | EGL_TRANSPARENT_BLUE_VALUE => 0,
        EGL_BIND_TO_TEXTURE_RGB | EGL_BIND_TO_TEXTURE_RGBA => FALSE as EGLint,
        EGL_MIN_SWAP_INTERVAL | EGL_MAX_SWAP_INTERVAL => 0,
        EGL_LUMINANCE_SIZE | EGL_ALPHA_MASK_SIZE => 0,
        EGL_COLOR_BUFFER_TYPE => EGL_RGB_BUFFER,
        EGL_RENDERABLE_TYPE | EGL_CONFORMANT => EGL_OPENGL_BIT,
        _ => return None,
    })
}

/// `eglGetConfigs`.
///
/// # Safety
/// `configs` is null or has room for `size` configs; `n` is writable.
#[no_mangle]
pub unsafe extern "C" fn eglGetConfigs(
    dpy: EGLDisplay,
    configs: *mut EGLConfig,
    size: EGLint,
    n: *mut EGLint,
) -> EGLBoolean {
    let o = objects();
    let (xdpy, screen) = match initialized(&o, dpy) {
        Ok(v) => v,
        Err(e) => return fail(e, FALSE),
    };
    drop(o);
    if n.is_null() {
        return fail(EGL_BAD_PARAMETER, FALSE);
    }
    let all = egl_configs(xdpy, screen);
    // SAFETY: forwarded contract.
    unsafe { write_configs(&all, configs, size, n) };
    ok(TRUE)
}

/// Writes up to `size` configs (all of them counted when `out` is null).
///
/// # Safety
/// `out` is null or has room for `size`; `n` is writable and not null.
unsafe fn write_configs(
    v: &[&'static FbConfig],
    out: *mut EGLConfig,
    size: EGLint,
    n: *mut EGLint,
) {
    let count = if out.is_null() {
        v.len()
    } else {
        v.len().min(size.max(0) as usize)
    };
    // SAFETY: the caller's contract: `out` has room for `size` entries, `n` is writable.
    unsafe {
        if !out.is_null() {
            for (i, c) in v.iter().take(count).enumerate() {
                *out.add(i) = *c as *const FbConfig;
            }
        }
        *n = count as EGLint;
    }
}

/// `eglChooseConfig`: EGL's matching rules (at-least for sizes, mask for the type bits,
/// exact for the rest) and sort order.
///
/// # Safety
/// `attribs` is null or an `EGL_NONE`-terminated list; `configs` has room for `size`; `n` is
/// writable.
#[no_mangle]
pub unsafe extern "C" fn eglChooseConfig(
    dpy: EGLDisplay,
    attribs: *const EGLint,
    configs: *mut EGLConfig,
    size: EGLint,
    n: *mut EGLint,
) -> EGLBoolean {
    let o = objects();
    let (xdpy, screen) = match initialized(&o, dpy) {
        Ok(v) => v,
        Err(e) => return fail(e, FALSE),
    };
    drop(o);
    if n.is_null() {
        return fail(EGL_BAD_PARAMETER, FALSE);
    }
    let mut req: HashMap<EGLint, EGLint> = HashMap::new();
    req.insert(EGL_SURFACE_TYPE, EGL_WINDOW_BIT);
    req.insert(EGL_RENDERABLE_TYPE, 1); // EGL_OPENGL_ES_BIT, EGL's default
    req.insert(EGL_COLOR_BUFFER_TYPE, EGL_RGB_BUFFER);
    // SAFETY: forwarded contract.
    for (a, v) in unsafe { pairs(attribs) } {
        req.insert(a, v);
    }
    let all = egl_configs(xdpy, screen);
    if let Some(&id) = req.get(&EGL_CONFIG_ID) {
        if id != EGL_DONT_CARE {
            let v: Vec<_> = all.into_iter().filter(|c| c.id == id).collect();
            // SAFETY: forwarded contract.
            unsafe { write_configs(&v, configs, size, n) };
            return ok(TRUE);
        }
    }
    let mut found = Vec::new();
    'next: for c in all {
        for (&a, &v) in &req {
            if v == EGL_DONT_CARE {
                continue;
            }
            let ok = match a {
                EGL_BUFFER_SIZE | EGL_RED_SIZE | EGL_GREEN_SIZE | EGL_BLUE_SIZE
                | EGL_ALPHA_SIZE | EGL_DEPTH_SIZE | EGL_STENCIL_SIZE | EGL_SAMPLES
                | EGL_SAMPLE_BUFFERS | EGL_LUMINANCE_SIZE | EGL_ALPHA_MASK_SIZE => {
                    config_attrib(c, a).unwrap_or(0) >= v
                }
                EGL_SURFACE_TYPE => config_attrib(c, a).unwrap_or(0) & v == v,
                EGL_RENDERABLE_TYPE | EGL_CONFORMANT => {
                    // The OpenGL ES bits (ES 1, 2, 3) are not matched: see the module docs.
                    let v = v & !(0x1 | 0x4 | 0x40);
                    config_attrib(c, a).unwrap_or(0) & v == v
                }
                EGL_MIN_SWAP_INTERVAL | EGL_MAX_SWAP_INTERVAL => true,
                EGL_MAX_PBUFFER_HEIGHT | EGL_MAX_PBUFFER_WIDTH | EGL_MAX_PBUFFER_PIXELS => true,
                EGL_NATIVE_VISUAL_TYPE | EGL_NATIVE_VISUAL_ID => true,
                EGL_MATCH_NATIVE_PIXMAP => false,
                a => match config_attrib(c, a) {
                    Some(have) => have == v,
                    None => return fail(EGL_BAD_ATTRIBUTE, FALSE),
                },
            };
            if !ok {
                continue 'next;
            }
        }
        found.push(c);
    }
    let wanted = |a: EGLint| req.get(&a).is_some_and(|&v| v != 0 && v != EGL_DONT_CARE);
    let colour = |c: &FbConfig| {
        [
            (EGL_RED_SIZE, c.red),
            (EGL_GREEN_SIZE, c.green),
            (EGL_BLUE_SIZE, c.blue),
            (EGL_ALPHA_SIZE, c.alpha),
        ]
        .iter()
        .filter(|(a, _)| wanted(*a))
        .map(|(_, b)| b)
        .sum::<i32>()
    };
    // EGL 1.4 section 3.4.1: larger requested colour bits, smaller buffer size, fewer
    // samples, smaller depth, smaller stencil, then the config id.
    found.sort_by_key(|c| {
        (
            -colour(c),
            c.buffer_size(),
            c.samples,
            c.depth_bits,
            c.stencil_bits,
            c.id,
        )
    });
    // SAFETY: forwarded contract.
    unsafe { write_configs(&found, configs, size, n) };
    ok(TRUE)
}

/// `eglGetConfigAttrib`.
///
/// # Safety
/// `value` is writable.
#[no_mangle]
pub unsafe extern "C" fn eglGetConfigAttrib(
    dpy: EGLDisplay,
    config: EGLConfig,
    attribute: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    if let Err(e) = initialized(&objects(), dpy) {
        return fail(e, FALSE);
    }
    let Some(c) = window::valid_config(config) else {
        return fail(EGL_BAD_CONFIG, FALSE);
    };
    let Some(v) = config_attrib(c, attribute) else {
        return fail(EGL_BAD_ATTRIBUTE, FALSE);
    };
    // SAFETY: null or a caller-owned int.
    match unsafe { value.as_mut() } {
        Some(p) => *p = v,
        None => return fail(EGL_BAD_PARAMETER, FALSE),
    }
    ok(TRUE)
}

fn create_window_surface(
    dpy: EGLDisplay,
    config: EGLConfig,
    window_id: std::ffi::c_ulong,
) -> EGLSurface {
    let mut o = objects();
    let (xdpy, _) = match initialized(&o, dpy) {
        Ok(v) => v,
        Err(e) => return fail(e, std::ptr::null_mut()),
    };
    let Some(c) = window::valid_config(config) else {
        return fail(EGL_BAD_CONFIG, std::ptr::null_mut());
    };
    if window_id == 0 || window::drawable_size(xdpy, window_id).is_none() {
        return fail(EGL_BAD_NATIVE_WINDOW, std::ptr::null_mut());
    }
    let s = Box::new(EglSurface {
        window: window_id,
        config: c,
        swap_interval: 1,
    });
    let p = &*s as *const EglSurface as usize;
    o.surfaces.insert(p, s);
    ok(p as EGLSurface)
}

/// `eglCreateWindowSurface` (`EGLNativeWindowType` is the X `Window`).
#[no_mangle]
pub extern "C" fn eglCreateWindowSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    win: std::ffi::c_ulong,
    _attribs: *const EGLint,
) -> EGLSurface {
    create_window_surface(dpy, config, win)
}

/// `eglCreatePlatformWindowSurface` (X11: `native` points to the `Window`).
///
/// # Safety
/// `native` points to an X `Window`.
#[no_mangle]
pub unsafe extern "C" fn eglCreatePlatformWindowSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    native: *mut c_void,
    _attribs: *const EGLAttrib,
) -> EGLSurface {
    // SAFETY: null or a pointer to the caller's Window.
    match unsafe { (native as *const std::ffi::c_ulong).as_ref() } {
        Some(&w) => create_window_surface(dpy, config, w),
        None => fail(EGL_BAD_NATIVE_WINDOW, std::ptr::null_mut()),
    }
}

/// `eglCreatePlatformWindowSurfaceEXT`.
///
/// # Safety
/// As for `eglCreatePlatformWindowSurface`.
#[no_mangle]
pub unsafe extern "C" fn eglCreatePlatformWindowSurfaceEXT(
    dpy: EGLDisplay,
    config: EGLConfig,
    native: *mut c_void,
    _attribs: *const EGLint,
) -> EGLSurface {
    // SAFETY: forwarded contract.
    unsafe { eglCreatePlatformWindowSurface(dpy, config, native, std::ptr::null()) }
}

/// `eglCreatePbufferSurface`: no configuration supports pbuffers (`EGL_BAD_MATCH`).
#[no_mangle]
pub extern "C" fn eglCreatePbufferSurface(
    _dpy: EGLDisplay,
    _config: EGLConfig,
    _attribs: *const EGLint,
) -> EGLSurface {
    fail(EGL_BAD_MATCH, std::ptr::null_mut())
}

/// `eglDestroySurface`.
#[no_mangle]
pub extern "C" fn eglDestroySurface(dpy: EGLDisplay, surface: EGLSurface) -> EGLBoolean {
    let mut o = objects();
    if display(&o, dpy).is_none() {
        return fail(EGL_BAD_DISPLAY, FALSE);
    }
    let (_, draw, read, _) = CURRENT.with(|c| c.get());
    if draw == surface as usize || read == surface as usize {
        // Still current: EGL frees it when it stops being current; keep it.
        return ok(TRUE);
    }
    match o.surfaces.remove(&(surface as usize)) {
        Some(_) => ok(TRUE),
        None => fail(EGL_BAD_SURFACE, FALSE),
    }
}

/// `eglQuerySurface`.
///
/// # Safety
/// `value` is writable.
#[no_mangle]
pub unsafe extern "C" fn eglQuerySurface(
    dpy: EGLDisplay,
    surface: EGLSurface,
    attribute: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    let o = objects();
    let (xdpy, _) = match initialized(&o, dpy) {
        Ok(v) => v,
        Err(e) => return fail(e, FALSE),
    };
    let Some(s) = o.surfaces.get(&(surface as usize)) else {
        return fail(EGL_BAD_SURFACE, FALSE);
    };
    let size = window::drawable_size(xdpy, s.window).unwrap_or((0, 0));
    let v = match attribute {
        EGL_WIDTH => size.0,
        EGL_HEIGHT => size.1,
        EGL_CONFIG_ID => s.config.id,
        EGL_RENDER_BUFFER => EGL_BACK_BUFFER,
        EGL_SWAP_BEHAVIOR => EGL_BUFFER_PRESERVED,
        EGL_HORIZONTAL_RESOLUTION | EGL_VERTICAL_RESOLUTION | EGL_PIXEL_ASPECT_RATIO => EGL_UNKNOWN,
        EGL_MULTISAMPLE_RESOLVE => EGL_MULTISAMPLE_RESOLVE_DEFAULT,
        EGL_LARGEST_PBUFFER => return ok(TRUE),
        _ => return fail(EGL_BAD_ATTRIBUTE, FALSE),
    };
    // SAFETY: null or a caller-owned int.
    match unsafe { value.as_mut() } {
        Some(p) => *p = v,
        None => return fail(EGL_BAD_PARAMETER, FALSE),
    }
    ok(TRUE)
}

/// `eglSurfaceAttrib`: `EGL_SWAP_BEHAVIOR` (the back buffer is always preserved) only.
#[no_mangle]
pub extern "C" fn eglSurfaceAttrib(
    _dpy: EGLDisplay,
    surface: EGLSurface,
    attribute: EGLint,
    value: EGLint,
) -> EGLBoolean {
    if !objects().surfaces.contains_key(&(surface as usize)) {
        return fail(EGL_BAD_SURFACE, FALSE);
    }
    match (attribute, value) {
        (EGL_SWAP_BEHAVIOR, 0x3094 | 0x3095) => ok(TRUE),
        _ => fail(EGL_BAD_MATCH, FALSE),
    }
}

/// `eglBindAPI`: `EGL_OPENGL_API` only.
#[no_mangle]
pub extern "C" fn eglBindAPI(api: EGLenum) -> EGLBoolean {
    if api != EGL_OPENGL_API {
        return fail(EGL_BAD_PARAMETER, FALSE);
    }
    API.with(|a| a.set(api));
    ok(TRUE)
}

/// `eglQueryAPI`.
#[no_mangle]
pub extern "C" fn eglQueryAPI() -> EGLenum {
    API.with(|a| a.get())
}

/// `eglCreateContext`: OpenGL up to 1.5 (`EGL_CONTEXT_MAJOR/MINOR_VERSION`).
///
/// # Safety
/// `attribs` is null or an `EGL_NONE`-terminated list of pairs.
#[no_mangle]
pub unsafe extern "C" fn eglCreateContext(
    dpy: EGLDisplay,
    config: EGLConfig,
    share: EGLContext,
    attribs: *const EGLint,
) -> EGLContext {
    let mut o = objects();
    if let Err(e) = initialized(&o, dpy) {
        return fail(e, std::ptr::null_mut());
    }
    if API.with(|a| a.get()) != EGL_OPENGL_API {
        return fail(EGL_BAD_MATCH, std::ptr::null_mut());
    }
    let Some(c) = window::valid_config(config) else {
        return fail(EGL_BAD_CONFIG, std::ptr::null_mut());
    };
    let share = if share.is_null() {
        None
    } else {
        match o.contexts.get(&(share as usize)) {
            Some(s) => Some(&**s as *const WindowContext),
            None => return fail(EGL_BAD_CONTEXT, std::ptr::null_mut()),
        }
    };
    let (mut major, mut minor) = (1, 0);
    // SAFETY: forwarded contract.
    for (a, v) in unsafe { pairs(attribs) } {
        match a {
            EGL_CONTEXT_MAJOR_VERSION => major = v,
            EGL_CONTEXT_MINOR_VERSION => minor = v,
            EGL_CONTEXT_OPENGL_PROFILE_MASK => {}
            EGL_CONTEXT_FLAGS_KHR if v & !1 == 0 => {}
            EGL_CONTEXT_OPENGL_DEBUG => {}
            _ => return fail(EGL_BAD_ATTRIBUTE, std::ptr::null_mut()),
        }
    }
    if major != 1 || !(0..=5).contains(&minor) {
        return fail(EGL_BAD_MATCH, std::ptr::null_mut());
    }
    let Some(ctx) = WindowContext::new(c, share).map(Box::new) else {
        return fail(EGL_BAD_CONTEXT, std::ptr::null_mut());
    };
    let p = &*ctx as *const WindowContext as usize;
    o.contexts.insert(p, ctx);
    ok(p as EGLContext)
}

/// `eglDestroyContext` (a current context is freed when released).
#[no_mangle]
pub extern "C" fn eglDestroyContext(dpy: EGLDisplay, ctx: EGLContext) -> EGLBoolean {
    let mut o = objects();
    if display(&o, dpy).is_none() {
        return fail(EGL_BAD_DISPLAY, FALSE);
    }
    let Some(c) = o.contexts.get_mut(&(ctx as usize)) else {
        return fail(EGL_BAD_CONTEXT, FALSE);
    };
    if c.current_on.is_some() {
        c.destroy_pending = true;
    } else {
        o.contexts.remove(&(ctx as usize));
    }
    ok(TRUE)
}

/// Releases this thread's context; frees what was destroyed while current.
fn release(o: &mut Objects) {
    let (ctx, _, _, _) = CURRENT.with(|c| c.get());
    if ctx == 0 {
        return;
    }
    // SAFETY: glFlush takes no pointers; it presents a front buffer the program drew into.
    unsafe { super::exports::glFlush() };
    window::bind(None);
    CURRENT.with(|c| c.set((0, 0, 0, 0)));
    if let Some(c) = o.contexts.get_mut(&ctx) {
        c.current_on = None;
        if c.destroy_pending {
            o.contexts.remove(&ctx);
        }
    }
}

/// `eglMakeCurrent`.
#[no_mangle]
pub extern "C" fn eglMakeCurrent(
    dpy: EGLDisplay,
    draw: EGLSurface,
    read: EGLSurface,
    ctx: EGLContext,
) -> EGLBoolean {
    let mut o = objects();
    if ctx.is_null() {
        if !draw.is_null() || !read.is_null() {
            return fail(EGL_BAD_MATCH, FALSE);
        }
        if display(&o, dpy).is_none() && !dpy.is_null() {
            return fail(EGL_BAD_DISPLAY, FALSE);
        }
        release(&mut o);
        return ok(TRUE);
    }
    let xdpy = match initialized(&o, dpy) {
        Ok((x, _)) => x,
        Err(e) => return fail(e, FALSE),
    };
    if draw.is_null() || read.is_null() {
        // No surfaceless contexts.
        return fail(EGL_BAD_MATCH, FALSE);
    }
    let (Some(ds), Some(_)) = (
        o.surfaces.get(&(draw as usize)),
        o.surfaces.get(&(read as usize)),
    ) else {
        return fail(EGL_BAD_SURFACE, FALSE);
    };
    let (window_id, visual, depth) = (ds.window, ds.config.visual, ds.config.depth);
    let read_window = o.surfaces[&(read as usize)].window;
    let me = std::thread::current().id();
    match o.contexts.get(&(ctx as usize)) {
        None => return fail(EGL_BAD_CONTEXT, FALSE),
        Some(c) if c.current_on.is_some_and(|t| t != me) => return fail(EGL_BAD_ACCESS, FALSE),
        Some(_) => {}
    }
    let (old, _, _, _) = CURRENT.with(|c| c.get());
    if old != ctx as usize {
        release(&mut o);
    }
    let Some(c) = o.contexts.get_mut(&(ctx as usize)) else {
        return fail(EGL_BAD_CONTEXT, FALSE);
    };
    c.current_on = Some(me);
    let target = Target {
        dpy: xdpy as usize,
        drawable: window_id,
        read: read_window,
        visual,
        depth,
    };
    window::bind(Some((&mut **c, target)));
    CURRENT.with(|cur| cur.set((ctx as usize, draw as usize, read as usize, dpy as usize)));
    ok(TRUE)
}

/// `eglGetCurrentContext`.
#[no_mangle]
pub extern "C" fn eglGetCurrentContext() -> EGLContext {
    CURRENT.with(|c| c.get()).0 as EGLContext
}

/// `eglGetCurrentSurface`.
#[no_mangle]
pub extern "C" fn eglGetCurrentSurface(which: EGLint) -> EGLSurface {
    let (_, d, r, _) = CURRENT.with(|c| c.get());
    match which {
        EGL_DRAW => ok(d as EGLSurface),
        EGL_READ => ok(r as EGLSurface),
        _ => fail(EGL_BAD_PARAMETER, std::ptr::null_mut()),
    }
}

/// `eglGetCurrentDisplay`.
#[no_mangle]
pub extern "C" fn eglGetCurrentDisplay() -> EGLDisplay {
    CURRENT.with(|c| c.get()).3 as EGLDisplay
}

/// `eglQueryContext`.
///
/// # Safety
/// `value` is writable.
#[no_mangle]
pub unsafe extern "C" fn eglQueryContext(
    dpy: EGLDisplay,
    ctx: EGLContext,
    attribute: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    let o = objects();
    if let Err(e) = initialized(&o, dpy) {
        return fail(e, FALSE);
    }
    let Some(c) = o.contexts.get(&(ctx as usize)) else {
        return fail(EGL_BAD_CONTEXT, FALSE);
    };
    let v = match attribute {
        EGL_CONFIG_ID => c.config.id,
        EGL_CONTEXT_CLIENT_TYPE => EGL_OPENGL_API as EGLint,
        EGL_RENDER_BUFFER => EGL_BACK_BUFFER,
        0x3098 => 1, // EGL_CONTEXT_CLIENT_VERSION
        _ => return fail(EGL_BAD_ATTRIBUTE, FALSE),
    };
    // SAFETY: null or a caller-owned int.
    match unsafe { value.as_mut() } {
        Some(p) => *p = v,
        None => return fail(EGL_BAD_PARAMETER, FALSE),
    }
    ok(TRUE)
}

/// `eglSwapBuffers`: the back buffer of the current context to its window surface.
#[no_mangle]
pub extern "C" fn eglSwapBuffers(dpy: EGLDisplay, surface: EGLSurface) -> EGLBoolean {
    let (ctx, draw, _, cur_dpy) = CURRENT.with(|c| c.get());
    {
        let o = objects();
        if let Err(e) = initialized(&o, dpy) {
            return fail(e, FALSE);
        }
        if !o.surfaces.contains_key(&(surface as usize)) {
            return fail(EGL_BAD_SURFACE, FALSE);
        }
    }
    if ctx == 0 || draw != surface as usize || cur_dpy != dpy as usize {
        return fail(EGL_BAD_SURFACE, FALSE);
    }
    super::osmesa::with_current_context(|c| window::swap_current(&mut c.gl));
    ok(TRUE)
}

/// `eglSwapInterval`: recorded on the draw surface; swaps never wait.
#[no_mangle]
pub extern "C" fn eglSwapInterval(dpy: EGLDisplay, interval: EGLint) -> EGLBoolean {
    let mut o = objects();
    if let Err(e) = initialized(&o, dpy) {
        return fail(e, FALSE);
    }
    let (ctx, draw, _, _) = CURRENT.with(|c| c.get());
    if ctx == 0 {
        return fail(EGL_BAD_CONTEXT, FALSE);
    }
    match o.surfaces.get_mut(&draw) {
        Some(s) => {
            s.swap_interval = interval.clamp(0, 0);
            ok(TRUE)
        }
        None => fail(EGL_BAD_SURFACE, FALSE),
    }
}

/// `eglWaitGL` / `eglWaitClient`: finishes GL rendering.
#[no_mangle]
pub extern "C" fn eglWaitClient() -> EGLBoolean {
    // SAFETY: glFinish takes no pointers.
    unsafe { super::exports::glFinish() };
    ok(TRUE)
}

/// `eglWaitGL`.
#[no_mangle]
pub extern "C" fn eglWaitGL() -> EGLBoolean {
    eglWaitClient()
}

/// `eglWaitNative`: waits for the X server.
#[no_mangle]
pub extern "C" fn eglWaitNative(_engine: EGLint) -> EGLBoolean {
    if let (Some(t), Some(x)) = (window::current_target(), window::xlib()) {
        // SAFETY: the current target's display is open.
        unsafe { (x.XSync)(t.dpy as *mut Display, 0) };
    }
    ok(TRUE)
}

/// `eglReleaseThread`.
#[no_mangle]
pub extern "C" fn eglReleaseThread() -> EGLBoolean {
    let mut o = objects();
    release(&mut o);
    ok(TRUE)
}

/// `eglGetError`: the last error of this thread, then `EGL_SUCCESS`.
#[no_mangle]
pub extern "C" fn eglGetError() -> EGLint {
    ERROR.with(|c| c.replace(EGL_SUCCESS))
}

/// `eglGetProcAddress`: every EGL, GLX and GL function (and GL alias) this library exports.
///
/// # Safety
/// `name` is a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn eglGetProcAddress(name: *const c_char) -> *const c_void {
    if name.is_null() {
        return std::ptr::null();
    }
    // SAFETY: the caller passes a NUL-terminated string.
    let name = unsafe { CStr::from_ptr(name) }.to_string_lossy();
    proc_address(&name)
}

/// The EGL function of this name, else the GLX or GL one.
pub(crate) fn proc_address(name: &str) -> *const c_void {
    macro_rules! table {
        ($($f:ident),* $(,)?) => {
            match name {
                $(stringify!($f) => return $f as *const c_void,)*
                _ => {}
            }
        };
    }
    table!(
        eglGetDisplay,
        eglGetPlatformDisplay,
        eglGetPlatformDisplayEXT,
        eglInitialize,
        eglTerminate,
        eglQueryString,
        eglGetConfigs,
        eglChooseConfig,
        eglGetConfigAttrib,
        eglCreateWindowSurface,
        eglCreatePlatformWindowSurface,
        eglCreatePlatformWindowSurfaceEXT,
        eglCreatePbufferSurface,
        eglDestroySurface,
        eglQuerySurface,
        eglSurfaceAttrib,
        eglBindAPI,
        eglQueryAPI,
        eglCreateContext,
        eglDestroyContext,
        eglMakeCurrent,
        eglGetCurrentContext,
        eglGetCurrentSurface,
        eglGetCurrentDisplay,
        eglQueryContext,
        eglSwapBuffers,
        eglSwapInterval,
        eglWaitClient,
        eglWaitGL,
        eglWaitNative,
        eglReleaseThread,
        eglGetError,
        eglGetProcAddress,
    );
    super::glx::proc_address(name)
}

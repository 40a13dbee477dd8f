//! GLX 1.4 over Xlib without the server's GLX extension (as Mesa's xlib "fake GLX" does): the
//! visuals are the X server's TrueColor visuals, tilegl renders into its own buffers and
//! `glXSwapBuffers` (or a flush of a front buffer) copies the picture into the window (MIT-SHM
//! or `XPutImage`, see `window`). Contexts created with a share context share its texture
//! objects, display lists and buffer objects (`state::share`). `libGL.so.1` (a link to this
//! library) exports these with the GL functions.
//!
//! Limits, reported honestly to the caller: no colour-index, stereo, auxiliary-buffer
//! or pbuffer configurations (choosing one finds none); multisample configurations have 2 or 4
//! samples (`GLX_SAMPLES`) with depth and stencil; reading from a
//! drawable other than the one drawn to (`glXMakeContextCurrent` with `read != draw`) reads the
//! draw drawable; swaps never wait for a vertical blank, so the swap-interval extensions record
//! the interval and report 0 as the interval in effect and as the maximum.

#![allow(non_snake_case, non_upper_case_globals)]

use std::collections::HashMap;
use std::ffi::{c_char, c_int, c_uchar, c_uint, c_ulong, c_void, CStr};
use std::sync::{Mutex, OnceLock};

use x11_dl::xlib::{Display, XVisualInfo};

use super::window::{self, FbConfig, Target, WindowContext};

pub type GLXContext = *mut WindowContext;
pub type GLXFBConfig = *const FbConfig;
pub type GLXDrawable = c_ulong;
type Bool = c_int;

pub const GLX_USE_GL: c_int = 1;
pub const GLX_BUFFER_SIZE: c_int = 2;
pub const GLX_LEVEL: c_int = 3;
pub const GLX_RGBA: c_int = 4;
pub const GLX_DOUBLEBUFFER: c_int = 5;
pub const GLX_STEREO: c_int = 6;
pub const GLX_AUX_BUFFERS: c_int = 7;
pub const GLX_RED_SIZE: c_int = 8;
pub const GLX_GREEN_SIZE: c_int = 9;
pub const GLX_BLUE_SIZE: c_int = 10;
pub const GLX_ALPHA_SIZE: c_int = 11;
pub const GLX_DEPTH_SIZE: c_int = 12;
pub const GLX_STENCIL_SIZE: c_int = 13;
pub const GLX_ACCUM_RED_SIZE: c_int = 14;
pub const GLX_ACCUM_GREEN_SIZE: c_int = 15;
pub const GLX_ACCUM_BLUE_SIZE: c_int = 16;
pub const GLX_ACCUM_ALPHA_SIZE: c_int = 17;
pub const GLX_BAD_SCREEN: c_int = 1;
pub const GLX_BAD_ATTRIBUTE: c_int = 2;
pub const GLX_BAD_VISUAL: c_int = 4;
pub const GLX_BAD_CONTEXT: c_int = 5;
pub const GLX_BAD_VALUE: c_int = 6;
pub const GLX_VENDOR: c_int = 1;
pub const GLX_VERSION: c_int = 2;
pub const GLX_EXTENSIONS: c_int = 3;
pub const GLX_CONFIG_CAVEAT: c_int = 0x20;
pub const GLX_DONT_CARE: c_int = -1;
pub const GLX_X_VISUAL_TYPE: c_int = 0x22;
pub const GLX_TRANSPARENT_TYPE: c_int = 0x23;
pub const GLX_TRANSPARENT_INDEX_VALUE: c_int = 0x24;
pub const GLX_TRANSPARENT_RED_VALUE: c_int = 0x25;
pub const GLX_TRANSPARENT_GREEN_VALUE: c_int = 0x26;
pub const GLX_TRANSPARENT_BLUE_VALUE: c_int = 0x27;
pub const GLX_TRANSPARENT_ALPHA_VALUE: c_int = 0x28;
pub const GLX_WINDOW_BIT: c_int = 1;
pub const GLX_PIXMAP_BIT: c_int = 2;
pub const GLX_NONE: c_int = 0x8000;
pub const GLX_TRUE_COLOR: c_int = 0x8002;
pub const GLX_VISUAL_ID: c_int = 0x800B;
pub const GLX_SCREEN: c_int = 0x800C;
pub const GLX_DRAWABLE_TYPE: c_int = 0x8010;
pub const GLX_RENDER_TYPE: c_int = 0x8011;
pub const GLX_X_RENDERABLE: c_int = 0x8012;
pub const GLX_FBCONFIG_ID: c_int = 0x8013;
pub const GLX_RGBA_TYPE: c_int = 0x8014;
pub const GLX_MAX_PBUFFER_WIDTH: c_int = 0x8016;
pub const GLX_MAX_PBUFFER_HEIGHT: c_int = 0x8017;
pub const GLX_MAX_PBUFFER_PIXELS: c_int = 0x8018;
pub const GLX_PRESERVED_CONTENTS: c_int = 0x801B;
pub const GLX_LARGEST_PBUFFER: c_int = 0x801C;
pub const GLX_WIDTH: c_int = 0x801D;
pub const GLX_HEIGHT: c_int = 0x801E;
pub const GLX_EVENT_MASK: c_int = 0x801F;
pub const GLX_RGBA_BIT: c_int = 1;
pub const GLX_SAMPLE_BUFFERS: c_int = 100000;
pub const GLX_SAMPLES: c_int = 100001;
pub const GLX_CONTEXT_MAJOR_VERSION_ARB: c_int = 0x2091;
pub const GLX_CONTEXT_MINOR_VERSION_ARB: c_int = 0x2092;
pub const GLX_CONTEXT_FLAGS_ARB: c_int = 0x2094;
pub const GLX_CONTEXT_PROFILE_MASK_ARB: c_int = 0x9126;
pub const GLX_CONTEXT_CORE_PROFILE_BIT_ARB: c_int = 1;
pub const GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB: c_int = 2;
pub const GLX_CONTEXT_DEBUG_BIT_ARB: c_int = 1;
pub const GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB: c_int = 2;
pub const GLX_SWAP_INTERVAL_EXT: c_int = 0x20F1;
pub const GLX_MAX_SWAP_INTERVAL_EXT: c_int = 0x20F2;

const TRUE: Bool = 1;
const FALSE: Bool = 0;

const VENDOR: &CStr = c"tilegl";
const VERSION: &CStr = c"1.4 tilegl";
/// Only what is implemented here.
const EXTENSIONS: &CStr = c"GLX_ARB_create_context GLX_ARB_create_context_profile GLX_ARB_get_proc_address GLX_EXT_swap_control GLX_MESA_swap_control GLX_SGI_swap_control";

/// Live contexts (addresses), to reject stale or foreign handles.
fn contexts() -> &'static Mutex<HashMap<usize, ()>> {
    static C: OnceLock<Mutex<HashMap<usize, ()>>> = OnceLock::new();
    C.get_or_init(|| Mutex::new(HashMap::new()))
}

/// The configuration `glXChooseVisual` picked for a visual (display, visual id), for
/// `glXGetConfig` and `glXCreateContext`.
fn chosen() -> &'static Mutex<HashMap<(usize, c_ulong), &'static FbConfig>> {
    static C: OnceLock<Mutex<HashMap<(usize, c_ulong), &'static FbConfig>>> = OnceLock::new();
    C.get_or_init(|| Mutex::new(HashMap::new()))
}

thread_local! {
    static CURRENT: std::cell::Cell<(GLXContext, usize)> =
        const { std::cell::Cell::new((std::ptr::null_mut(), 0)) };
}

fn current() -> (GLXContext, usize) {
    CURRENT.with(|c| c.get())
}

/// The attribute list `0`-terminated at `p` as (name, value) pairs; `bools` are the GLX 1.2
/// attributes that take no value in `glXChooseVisual` lists.
///
/// # Safety
/// `p` is null or a `None`-terminated attribute list.
unsafe fn attrib_list(p: *const c_int, bools: &[c_int]) -> Vec<(c_int, c_int)> {
    let mut out = Vec::new();
    if p.is_null() {
        return out;
    }
    let mut i = 0;
    loop {
        // SAFETY: the list is terminated by None (0), so every read up to it is in bounds.
        let name = unsafe { *p.add(i) };
        if name == 0 || out.len() > 1000 {
            break;
        }
        if bools.contains(&name) {
            out.push((name, TRUE));
            i += 1;
        } else {
            // SAFETY: as above; a name is followed by its value.
            out.push((name, unsafe { *p.add(i + 1) }));
            i += 2;
        }
    }
    out
}

/// The value of a configuration attribute, or `None` for an unknown attribute.
fn config_attrib(c: &FbConfig, attr: c_int) -> Option<c_int> {
    Some(match attr {
        GLX_USE_GL => TRUE,
        GLX_BUFFER_SIZE => c.buffer_size(),
        GLX_LEVEL => 0,
        GLX_RGBA => TRUE,
        GLX_DOUBLEBUFFER => c.double as c_int,
        GLX_STEREO => FALSE,
        GLX_AUX_BUFFERS => 0,
        GLX_RED_SIZE => c.red,
        GLX_GREEN_SIZE => c.green,
        GLX_BLUE_SIZE => c.blue,
        GLX_ALPHA_SIZE => c.alpha,
        GLX_DEPTH_SIZE => c.depth_bits,
        GLX_STENCIL_SIZE => c.stencil_bits,
        GLX_ACCUM_RED_SIZE | GLX_ACCUM_GREEN_SIZE | GLX_ACCUM_BLUE_SIZE | GLX_ACCUM_ALPHA_SIZE => {
            c.accum
        }
        GLX_CONFIG_CAVEAT => GLX_NONE,
        GLX_X_VISUAL_TYPE => GLX_TRUE_COLOR,
        GLX_TRANSPARENT_TYPE => GLX_NONE,
        GLX_TRANSPARENT_INDEX_VALUE
        | GLX_TRANSPARENT_RED_VALUE
        | GLX_TRANSPARENT_GREEN_VALUE
        | GLX_TRANSPARENT_BLUE_VALUE
        | GLX_TRANSPARENT_ALPHA_VALUE => 0,
        GLX_VISUAL_ID => c.visualid as c_int,
        GLX_SCREEN => c.screen,
        GLX_DRAWABLE_TYPE => GLX_WINDOW_BIT | GLX_PIXMAP_BIT,
        GLX_RENDER_TYPE => GLX_RGBA_BIT,
        GLX_X_RENDERABLE => TRUE,
        GLX_FBCONFIG_ID => c.id,
        GLX_MAX_PBUFFER_WIDTH | GLX_MAX_PBUFFER_HEIGHT | GLX_MAX_PBUFFER_PIXELS => 0,
        GLX_SAMPLE_BUFFERS => (c.samples > 0) as c_int,
        GLX_SAMPLES => c.samples,
        _ => return None,
    })
}

/// How an attribute of a request is matched (GLX 1.4, table 3.4).
enum Match {
    Minimum,
    Exact,
    Mask,
}

fn match_rule(attr: c_int) -> Option<Match> {
    Some(match attr {
        GLX_BUFFER_SIZE | GLX_AUX_BUFFERS | GLX_RED_SIZE | GLX_GREEN_SIZE | GLX_BLUE_SIZE
        | GLX_ALPHA_SIZE | GLX_DEPTH_SIZE | GLX_STENCIL_SIZE | GLX_ACCUM_RED_SIZE
        | GLX_ACCUM_GREEN_SIZE | GLX_ACCUM_BLUE_SIZE | GLX_ACCUM_ALPHA_SIZE
        | GLX_SAMPLE_BUFFERS | GLX_SAMPLES => Match::Minimum,
        GLX_DRAWABLE_TYPE | GLX_RENDER_TYPE => Match::Mask,
        GLX_LEVEL | GLX_DOUBLEBUFFER | GLX_STEREO | GLX_X_RENDERABLE | GLX_X_VISUAL_TYPE
        | GLX_CONFIG_CAVEAT | GLX_TRANSPARENT_TYPE | GLX_FBCONFIG_ID | GLX_VISUAL_ID
        | GLX_USE_GL | GLX_RGBA => Match::Exact,
        GLX_TRANSPARENT_INDEX_VALUE
        | GLX_TRANSPARENT_RED_VALUE
        | GLX_TRANSPARENT_GREEN_VALUE
        | GLX_TRANSPARENT_BLUE_VALUE
        | GLX_TRANSPARENT_ALPHA_VALUE => Match::Exact,
        _ => return None,
    })
}

/// The configurations of `screen` matching `request` (pairs, with defaults already in),
/// sorted as GLX sorts them; `Err(())` for an unknown attribute.
fn choose(
    dpy: *mut Display,
    screen: c_int,
    request: &HashMap<c_int, c_int>,
) -> Result<Vec<&'static FbConfig>, ()> {
    let all = window::configs(dpy, screen);
    if let Some(&id) = request.get(&GLX_FBCONFIG_ID) {
        if id != GLX_DONT_CARE {
            return Ok(all.into_iter().filter(|c| c.id == id).collect());
        }
    }
    for &a in request.keys() {
        if match_rule(a).is_none() {
            return Err(());
        }
    }
    let mut out: Vec<&'static FbConfig> = all
        .into_iter()
        .filter(|c| {
            request.iter().all(|(&a, &v)| {
                if v == GLX_DONT_CARE {
                    return true;
                }
                let Some(have) = config_attrib(c, a) else {
                    return false;
                };
                match match_rule(a) {
                    Some(Match::Minimum) => have >= v,
                    Some(Match::Exact) => have == v,
                    Some(Match::Mask) => have & v == v,
                    None => false,
                }
            })
        })
        .collect();
    let wanted = |a: c_int| {
        request
            .get(&a)
            .is_some_and(|&v| v != 0 && v != GLX_DONT_CARE)
    };
    let colour_bits = |c: &FbConfig| {
        [
            (GLX_RED_SIZE, c.red),
            (GLX_GREEN_SIZE, c.green),
            (GLX_BLUE_SIZE, c.blue),
            (GLX_ALPHA_SIZE, c.alpha),
        ]
        .iter()
        .filter(|(a, _)| wanted(*a))
        .map(|(_, b)| b)
        .sum::<i32>()
    };
    let accum_bits = |c: &FbConfig| {
        [
            GLX_ACCUM_RED_SIZE,
            GLX_ACCUM_GREEN_SIZE,
            GLX_ACCUM_BLUE_SIZE,
            GLX_ACCUM_ALPHA_SIZE,
        ]
        .iter()
        .filter(|a| wanted(**a))
        .count() as i32
            * c.accum
    };
    // Sort keys in GLX's priority order: larger requested colour bits, smaller buffer size,
    // single-buffered first, fewer samples, larger depth, smaller stencil, larger requested accumulation
    // bits, then the id. Configurations without an accumulation buffer come before those
    // with one when none is asked for (it costs memory and time).
    out.sort_by_key(|c| {
        (
            -colour_bits(c),
            c.buffer_size(),
            c.double,
            c.samples,
            -c.depth_bits,
            c.stencil_bits,
            -accum_bits(c),
            c.accum,
            c.id,
        )
    });
    Ok(out)
}

/// Copies `v` into memory from `malloc` (the caller frees it with `XFree`).
fn malloc_array<T: Copy>(v: &[T]) -> *mut T {
    extern "C" {
        fn malloc(n: usize) -> *mut c_void;
    }
    if v.is_empty() {
        return std::ptr::null_mut();
    }
    // SAFETY: malloc of the array's size; the copy fills exactly that many bytes.
    unsafe {
        let p = malloc(std::mem::size_of_val(v)) as *mut T;
        if !p.is_null() {
            std::ptr::copy_nonoverlapping(v.as_ptr(), p, v.len());
        }
        p
    }
}

/// The configuration a visual stands for: the one `glXChooseVisual` picked for it, else the
/// visual's double-buffered configuration with depth, stencil and accumulation buffers.
fn config_for_visual(dpy: *mut Display, vis: *const XVisualInfo) -> Option<&'static FbConfig> {
    // SAFETY: the caller passes an XVisualInfo (from glXChooseVisual or XGetVisualInfo).
    let vi = unsafe { vis.as_ref() }?;
    let picked = chosen().lock().unwrap_or_else(|e| e.into_inner());
    if let Some(c) = picked.get(&(dpy as usize, vi.visualid)) {
        return Some(c);
    }
    drop(picked);
    window::configs(dpy, vi.screen)
        .into_iter()
        .filter(|c| c.visualid == vi.visualid)
        .max_by_key(|c| (c.double, c.depth_bits, c.stencil_bits, c.accum, -c.samples))
}

/// `glXQueryExtension`: GLX is always there (it needs no server extension).
///
/// # Safety
/// Non-null pointers must be writable.
#[no_mangle]
pub unsafe extern "C" fn glXQueryExtension(
    dpy: *mut Display,
    error_base: *mut c_int,
    event_base: *mut c_int,
) -> Bool {
    // SAFETY: null or caller-owned ints.
    unsafe {
        if let Some(e) = error_base.as_mut() {
            *e = 0;
        }
        if let Some(e) = event_base.as_mut() {
            *e = 0;
        }
    }
    (!dpy.is_null() && window::xlib().is_some()) as Bool
}

/// `glXQueryVersion`: 1.4.
///
/// # Safety
/// Non-null pointers must be writable.
#[no_mangle]
pub unsafe extern "C" fn glXQueryVersion(
    dpy: *mut Display,
    major: *mut c_int,
    minor: *mut c_int,
) -> Bool {
    // SAFETY: null or caller-owned ints.
    unsafe {
        if let Some(m) = major.as_mut() {
            *m = 1;
        }
        if let Some(m) = minor.as_mut() {
            *m = 4;
        }
    }
    (!dpy.is_null()) as Bool
}

fn string(name: c_int) -> *const c_char {
    match name {
        GLX_VENDOR => VENDOR.as_ptr(),
        GLX_VERSION => VERSION.as_ptr(),
        GLX_EXTENSIONS => EXTENSIONS.as_ptr(),
        _ => std::ptr::null(),
    }
}

/// `glXGetClientString`.
#[no_mangle]
pub extern "C" fn glXGetClientString(_dpy: *mut Display, name: c_int) -> *const c_char {
    string(name)
}

/// `glXQueryServerString` (the "server" is this library).
#[no_mangle]
pub extern "C" fn glXQueryServerString(
    _dpy: *mut Display,
    _screen: c_int,
    name: c_int,
) -> *const c_char {
    string(name)
}

/// `glXQueryExtensionsString`.
#[no_mangle]
pub extern "C" fn glXQueryExtensionsString(_dpy: *mut Display, _screen: c_int) -> *const c_char {
    EXTENSIONS.as_ptr()
}

/// `glXChooseVisual`: the best visual for a GLX 1.2 attribute list (`GLX_RGBA` is required;
/// without `GLX_DOUBLEBUFFER` only single-buffered configurations match).
///
/// # Safety
/// `attribs` is a `None`-terminated list.
#[no_mangle]
pub unsafe extern "C" fn glXChooseVisual(
    dpy: *mut Display,
    screen: c_int,
    attribs: *mut c_int,
) -> *mut XVisualInfo {
    // SAFETY: forwarded contract.
    let list = unsafe {
        attrib_list(
            attribs,
            &[GLX_USE_GL, GLX_RGBA, GLX_DOUBLEBUFFER, GLX_STEREO],
        )
    };
    let mut request: HashMap<c_int, c_int> = HashMap::new();
    request.insert(GLX_DOUBLEBUFFER, FALSE);
    request.insert(GLX_X_VISUAL_TYPE, GLX_DONT_CARE);
    let mut rgba = false;
    for (a, v) in list {
        match a {
            GLX_RGBA => rgba = true,
            GLX_USE_GL => {}
            _ => {
                request.insert(a, v);
            }
        }
    }
    if !rgba {
        // Colour-index visuals: none.
        return std::ptr::null_mut();
    }
    let Ok(found) = choose(dpy, screen, &request) else {
        return std::ptr::null_mut();
    };
    // The sort puts configurations without an accumulation buffer first; one is taken only
    // when asked for.
    let want_accum = request.get(&GLX_ACCUM_RED_SIZE).is_some_and(|&v| v > 0);
    let Some(best) = found
        .iter()
        .copied()
        .find(|c| (c.accum > 0) == want_accum)
        .or(found.first().copied())
    else {
        return std::ptr::null_mut();
    };
    // A visual stands for one configuration (glXCreateContext only gets the visual): among the
    // visuals offering the same configuration, take one no other choice has claimed, so that a
    // program choosing, say, a single- and a double-buffered visual gets two visuals.
    let mut picked = chosen().lock().unwrap_or_else(|e| e.into_inner());
    let same = |c: &FbConfig| {
        (
            c.double,
            c.depth_bits,
            c.stencil_bits,
            c.accum,
            c.depth,
            c.samples,
        ) == (
            best.double,
            best.depth_bits,
            best.stencil_bits,
            best.accum,
            best.depth,
            best.samples,
        )
    };
    let best = found
        .iter()
        .copied()
        .filter(|c| same(c))
        .find(|c| match picked.get(&(dpy as usize, c.visualid)) {
            None => true,
            Some(p) => same(p),
        })
        .unwrap_or(best);
    picked.insert((dpy as usize, best.visualid), best);
    drop(picked);
    window::visual_info(dpy, best)
}

/// `glXGetConfig`.
///
/// # Safety
/// `vis` is an XVisualInfo; `value` is writable.
#[no_mangle]
pub unsafe extern "C" fn glXGetConfig(
    dpy: *mut Display,
    vis: *mut XVisualInfo,
    attrib: c_int,
    value: *mut c_int,
) -> c_int {
    let Some(c) = config_for_visual(dpy, vis) else {
        if attrib == GLX_USE_GL && !value.is_null() {
            // SAFETY: checked non-null.
            unsafe { *value = FALSE };
            return 0;
        }
        return GLX_BAD_VISUAL;
    };
    match config_attrib(c, attrib) {
        Some(v) => {
            // SAFETY: null or caller-owned int.
            if let Some(p) = unsafe { value.as_mut() } {
                *p = v;
            }
            0
        }
        None => GLX_BAD_ATTRIBUTE,
    }
}

/// `glXChooseFBConfig`.
///
/// # Safety
/// `attribs` is null or a `None`-terminated list of pairs; `n` is writable.
#[no_mangle]
pub unsafe extern "C" fn glXChooseFBConfig(
    dpy: *mut Display,
    screen: c_int,
    attribs: *const c_int,
    n: *mut c_int,
) -> *mut GLXFBConfig {
    let mut request: HashMap<c_int, c_int> = HashMap::new();
    request.insert(GLX_DOUBLEBUFFER, GLX_DONT_CARE);
    request.insert(GLX_RENDER_TYPE, GLX_RGBA_BIT);
    request.insert(GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT);
    // SAFETY: forwarded contract.
    for (a, v) in unsafe { attrib_list(attribs, &[]) } {
        request.insert(a, v);
    }
    let found = choose(dpy, screen, &request).unwrap_or_default();
    let ptrs: Vec<GLXFBConfig> = found.iter().map(|c| *c as *const FbConfig).collect();
    // SAFETY: null or caller-owned int.
    if let Some(n) = unsafe { n.as_mut() } {
        *n = ptrs.len() as c_int;
    }
    malloc_array(&ptrs)
}

/// `glXGetFBConfigs`.
///
/// # Safety
/// `n` is writable.
#[no_mangle]
pub unsafe extern "C" fn glXGetFBConfigs(
    dpy: *mut Display,
    screen: c_int,
    n: *mut c_int,
) -> *mut GLXFBConfig {
    let ptrs: Vec<GLXFBConfig> = window::configs(dpy, screen)
        .iter()
        .map(|c| *c as *const FbConfig)
        .collect();
    // SAFETY: null or caller-owned int.
    if let Some(n) = unsafe { n.as_mut() } {
        *n = ptrs.len() as c_int;
    }
    malloc_array(&ptrs)
}

/// `glXGetFBConfigAttrib`.
///
/// # Safety
/// `value` is writable.
#[no_mangle]
pub unsafe extern "C" fn glXGetFBConfigAttrib(
    _dpy: *mut Display,
    config: GLXFBConfig,
    attrib: c_int,
    value: *mut c_int,
) -> c_int {
    let Some(c) = window::valid_config(config) else {
        return GLX_BAD_VISUAL;
    };
    match config_attrib(c, attrib) {
        Some(v) => {
            // SAFETY: null or caller-owned int.
            if let Some(p) = unsafe { value.as_mut() } {
                *p = v;
            }
            0
        }
        None => GLX_BAD_ATTRIBUTE,
    }
}

/// `glXGetVisualFromFBConfig`.
#[no_mangle]
pub extern "C" fn glXGetVisualFromFBConfig(
    dpy: *mut Display,
    config: GLXFBConfig,
) -> *mut XVisualInfo {
    match window::valid_config(config) {
        Some(c) => {
            chosen()
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .entry((dpy as usize, c.visualid))
                .or_insert(c);
            window::visual_info(dpy, c)
        }
        None => std::ptr::null_mut(),
    }
}

fn create(config: Option<&'static FbConfig>, share: GLXContext) -> GLXContext {
    let Some(config) = config else {
        return std::ptr::null_mut();
    };
    if !share.is_null() && !live(share) {
        return std::ptr::null_mut();
    }
    let Some(wc) = WindowContext::new(config, (!share.is_null()).then_some(share as *const _))
    else {
        return std::ptr::null_mut();
    };
    let p = Box::into_raw(Box::new(wc));
    contexts()
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .insert(p as usize, ());
    p
}

fn live(ctx: GLXContext) -> bool {
    contexts()
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .contains_key(&(ctx as usize))
}

/// `glXCreateContext` (the configuration is the one the visual was chosen with).
///
/// # Safety
/// `vis` is an XVisualInfo.
#[no_mangle]
pub unsafe extern "C" fn glXCreateContext(
    dpy: *mut Display,
    vis: *mut XVisualInfo,
    share: GLXContext,
    _direct: Bool,
) -> GLXContext {
    create(config_for_visual(dpy, vis), share)
}

/// `glXCreateNewContext` (`GLX_RGBA_TYPE` only).
#[no_mangle]
pub extern "C" fn glXCreateNewContext(
    _dpy: *mut Display,
    config: GLXFBConfig,
    render_type: c_int,
    share: GLXContext,
    _direct: Bool,
) -> GLXContext {
    if render_type != GLX_RGBA_TYPE {
        return std::ptr::null_mut();
    }
    create(window::valid_config(config), share)
}

/// `glXCreateContextAttribsARB`: OpenGL 1.0 to 1.5 (compatibility) contexts only; a request for
/// a later version, a core or ES profile, a forward-compatible or unknown flag fails (null).
///
/// # Safety
/// `attribs` is null or a `None`-terminated list of pairs.
#[no_mangle]
pub unsafe extern "C" fn glXCreateContextAttribsARB(
    _dpy: *mut Display,
    config: GLXFBConfig,
    share: GLXContext,
    _direct: Bool,
    attribs: *const c_int,
) -> GLXContext {
    let (mut major, mut minor) = (1, 0);
    // SAFETY: forwarded contract.
    for (a, v) in unsafe { attrib_list(attribs, &[]) } {
        match a {
            GLX_CONTEXT_MAJOR_VERSION_ARB => major = v,
            GLX_CONTEXT_MINOR_VERSION_ARB => minor = v,
            GLX_CONTEXT_FLAGS_ARB if v & !GLX_CONTEXT_DEBUG_BIT_ARB == 0 => {}
            GLX_CONTEXT_PROFILE_MASK_ARB
                if v == GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB
                    || (v == GLX_CONTEXT_CORE_PROFILE_BIT_ARB) =>
            {
                // The profile is ignored for versions before 3.2 (ARB_create_context_profile).
            }
            GLX_RENDER_TYPE if v == GLX_RGBA_TYPE => {}
            _ => return std::ptr::null_mut(),
        }
    }
    if major != 1 || !(0..=5).contains(&minor) {
        return std::ptr::null_mut();
    }
    create(window::valid_config(config), share)
}

/// Frees a context that is current nowhere.
fn free(ctx: GLXContext) {
    contexts()
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .remove(&(ctx as usize));
    // SAFETY: a live context from Box::into_raw, removed from the registry, freed once.
    drop(unsafe { Box::from_raw(ctx) });
}

/// `glXDestroyContext`: freed now, or when released if it is current somewhere.
///
/// # Safety
/// `ctx` is a context from this library.
#[no_mangle]
pub unsafe extern "C" fn glXDestroyContext(_dpy: *mut Display, ctx: GLXContext) {
    if ctx.is_null() || !live(ctx) {
        return;
    }
    // SAFETY: a live context.
    let c = unsafe { &mut *ctx };
    if c.current_on.is_some() {
        c.destroy_pending = true;
    } else {
        free(ctx);
    }
}

/// Releases this thread's current context (its pending front-buffer work is presented).
fn release_current() {
    let (old, _) = current();
    if old.is_null() {
        return;
    }
    // SAFETY: glFlush takes no pointers; it presents a front buffer the program drew into.
    unsafe { super::exports::glFlush() };
    window::bind(None);
    CURRENT.with(|c| c.set((std::ptr::null_mut(), 0)));
    // SAFETY: the current context is live (destroying it only marks it while current).
    let c = unsafe { &mut *old };
    c.current_on = None;
    if c.destroy_pending {
        free(old);
    }
}

/// `glXMakeContextCurrent`.
///
/// # Safety
/// `ctx` is null or a context from this library; `dpy` is an open display.
#[no_mangle]
pub unsafe extern "C" fn glXMakeContextCurrent(
    dpy: *mut Display,
    draw: GLXDrawable,
    read: GLXDrawable,
    ctx: GLXContext,
) -> Bool {
    if ctx.is_null() {
        if draw != 0 || read != 0 {
            return FALSE;
        }
        release_current();
        return TRUE;
    }
    if !live(ctx) || draw == 0 || dpy.is_null() {
        return FALSE;
    }
    // SAFETY: a live context.
    let c = unsafe { &mut *ctx };
    let me = std::thread::current().id();
    if c.current_on.is_some_and(|t| t != me) || c.destroy_pending {
        return FALSE;
    }
    let (old, _) = current();
    if old != ctx {
        release_current();
    }
    c.current_on = Some(me);
    let target = Target {
        dpy: dpy as usize,
        drawable: draw,
        read: if read == 0 { draw } else { read },
        visual: c.config.visual,
        depth: c.config.depth,
    };
    window::bind(Some((c, target)));
    CURRENT.with(|cur| cur.set((ctx, dpy as usize)));
    TRUE
}

/// `glXMakeCurrent`.
///
/// # Safety
/// As for `glXMakeContextCurrent`.
#[no_mangle]
pub unsafe extern "C" fn glXMakeCurrent(
    dpy: *mut Display,
    drawable: GLXDrawable,
    ctx: GLXContext,
) -> Bool {
    // SAFETY: forwarded contract.
    unsafe { glXMakeContextCurrent(dpy, drawable, drawable, ctx) }
}

/// `glXGetCurrentContext`.
#[no_mangle]
pub extern "C" fn glXGetCurrentContext() -> GLXContext {
    current().0
}

/// `glXGetCurrentDrawable`.
#[no_mangle]
pub extern "C" fn glXGetCurrentDrawable() -> GLXDrawable {
    if current().0.is_null() {
        return 0;
    }
    window::current_target().map_or(0, |t| t.drawable)
}

/// `glXGetCurrentReadDrawable`.
#[no_mangle]
pub extern "C" fn glXGetCurrentReadDrawable() -> GLXDrawable {
    if current().0.is_null() {
        return 0;
    }
    window::current_target().map_or(0, |t| t.read)
}

/// `glXGetCurrentDisplay`.
#[no_mangle]
pub extern "C" fn glXGetCurrentDisplay() -> *mut Display {
    current().1 as *mut Display
}

/// `glXCreateWindow`: the GLX window is the X window itself.
#[no_mangle]
pub extern "C" fn glXCreateWindow(
    _dpy: *mut Display,
    config: GLXFBConfig,
    win: c_ulong,
    _attribs: *const c_int,
) -> GLXDrawable {
    if window::valid_config(config).is_none() {
        return 0;
    }
    win
}

/// `glXDestroyWindow`: nothing to free (the X window belongs to the program).
#[no_mangle]
pub extern "C" fn glXDestroyWindow(_dpy: *mut Display, _win: GLXDrawable) {}

/// `glXCreatePixmap`: the GLX pixmap is the X pixmap itself (rendering into it works like a
/// single-buffered window).
#[no_mangle]
pub extern "C" fn glXCreatePixmap(
    _dpy: *mut Display,
    config: GLXFBConfig,
    pixmap: c_ulong,
    _attribs: *const c_int,
) -> GLXDrawable {
    if window::valid_config(config).is_none() {
        return 0;
    }
    pixmap
}

/// `glXDestroyPixmap`.
#[no_mangle]
pub extern "C" fn glXDestroyPixmap(_dpy: *mut Display, _pixmap: GLXDrawable) {}

/// `glXCreateGLXPixmap` (GLX 1.2 form of `glXCreatePixmap`).
#[no_mangle]
pub extern "C" fn glXCreateGLXPixmap(
    _dpy: *mut Display,
    _vis: *mut XVisualInfo,
    pixmap: c_ulong,
) -> GLXDrawable {
    pixmap
}

/// `glXDestroyGLXPixmap`.
#[no_mangle]
pub extern "C" fn glXDestroyGLXPixmap(_dpy: *mut Display, _pixmap: GLXDrawable) {}

/// `glXSwapBuffers`: the current context's back buffer to the window (an implicit `glFlush`).
/// A drawable that is not this thread's current one has nothing to swap here.
#[no_mangle]
pub extern "C" fn glXSwapBuffers(_dpy: *mut Display, drawable: GLXDrawable) {
    if window::current_target().is_some_and(|t| t.drawable == drawable) {
        super::osmesa::with_current_context(|c| window::swap_current(&mut c.gl));
    }
}

/// `glXQueryDrawable`.
///
/// # Safety
/// `value` is writable.
#[no_mangle]
pub unsafe extern "C" fn glXQueryDrawable(
    dpy: *mut Display,
    draw: GLXDrawable,
    attribute: c_int,
    value: *mut c_uint,
) {
    let v = match attribute {
        GLX_WIDTH => window::drawable_size(dpy, draw).map(|s| s.0 as c_uint),
        GLX_HEIGHT => window::drawable_size(dpy, draw).map(|s| s.1 as c_uint),
        GLX_PRESERVED_CONTENTS => Some(TRUE as c_uint),
        GLX_LARGEST_PBUFFER => Some(0),
        GLX_FBCONFIG_ID => {
            let (ctx, _) = current();
            if !ctx.is_null() && window::current_target().is_some_and(|t| t.drawable == draw) {
                // SAFETY: the current context is live.
                Some(unsafe { (*ctx).config.id } as c_uint)
            } else {
                Some(0)
            }
        }
        GLX_SWAP_INTERVAL_EXT | GLX_MAX_SWAP_INTERVAL_EXT => Some(0),
        GLX_EVENT_MASK => Some(0),
        _ => None,
    };
    if let Some(v) = v {
        // SAFETY: null or caller-owned uint.
        if let Some(p) = unsafe { value.as_mut() } {
            *p = v;
        }
    }
}

/// `glXQueryContext`.
///
/// # Safety
/// `value` is writable.
#[no_mangle]
pub unsafe extern "C" fn glXQueryContext(
    _dpy: *mut Display,
    ctx: GLXContext,
    attribute: c_int,
    value: *mut c_int,
) -> c_int {
    if !live(ctx) {
        return GLX_BAD_CONTEXT;
    }
    // SAFETY: a live context.
    let c = unsafe { &*ctx };
    let v = match attribute {
        GLX_FBCONFIG_ID => c.config.id,
        GLX_RENDER_TYPE => GLX_RGBA_TYPE,
        GLX_SCREEN => c.config.screen,
        _ => return GLX_BAD_ATTRIBUTE,
    };
    // SAFETY: null or caller-owned int.
    if let Some(p) = unsafe { value.as_mut() } {
        *p = v;
    }
    0
}

/// `glXSelectEvent`: no GLX events are generated (no pbuffers to clobber).
#[no_mangle]
pub extern "C" fn glXSelectEvent(_dpy: *mut Display, _draw: GLXDrawable, _mask: c_ulong) {}

/// `glXGetSelectedEvent`.
///
/// # Safety
/// `mask` is writable.
#[no_mangle]
pub unsafe extern "C" fn glXGetSelectedEvent(
    _dpy: *mut Display,
    _draw: GLXDrawable,
    mask: *mut c_ulong,
) {
    // SAFETY: null or caller-owned.
    if let Some(m) = unsafe { mask.as_mut() } {
        *m = 0;
    }
}

/// `glXWaitGL`: finishes GL rendering (front-buffer pictures reach the window).
#[no_mangle]
pub extern "C" fn glXWaitGL() {
    // SAFETY: glFinish takes no pointers.
    unsafe { super::exports::glFinish() }
}

/// `glXWaitX`: waits for the X server to finish earlier requests.
#[no_mangle]
pub extern "C" fn glXWaitX() {
    let (_, dpy) = current();
    if let (Some(x), false) = (window::xlib(), dpy == 0) {
        // SAFETY: the current display is open (it was given to glXMakeCurrent).
        unsafe { (x.XSync)(dpy as *mut Display, FALSE) };
    }
}

/// `glXIsDirect`: tilegl renders in the client: always direct.
#[no_mangle]
pub extern "C" fn glXIsDirect(_dpy: *mut Display, ctx: GLXContext) -> Bool {
    live(ctx) as Bool
}

/// `glXCopyContext`: copying state between contexts is not supported (nothing is copied).
#[no_mangle]
pub extern "C" fn glXCopyContext(
    _dpy: *mut Display,
    _src: GLXContext,
    _dst: GLXContext,
    _mask: c_ulong,
) {
}

/// `glXSwapIntervalEXT`: recorded; swaps never wait (the interval in effect stays 0).
#[no_mangle]
pub extern "C" fn glXSwapIntervalEXT(_dpy: *mut Display, _draw: GLXDrawable, interval: c_int) {
    set_interval(interval);
}

fn set_interval(interval: c_int) {
    let (ctx, _) = current();
    if !ctx.is_null() {
        // SAFETY: the current context is live.
        unsafe { (*ctx).swap_interval = interval };
    }
}

/// `glXSwapIntervalMESA`: recorded; swaps never wait.
#[no_mangle]
pub extern "C" fn glXSwapIntervalMESA(interval: c_uint) -> c_int {
    if interval > i32::MAX as c_uint {
        return GLX_BAD_VALUE;
    }
    set_interval(interval as c_int);
    0
}

/// `glXGetSwapIntervalMESA`: 0, the interval in effect (swaps never wait).
#[no_mangle]
pub extern "C" fn glXGetSwapIntervalMESA() -> c_int {
    0
}

/// `glXSwapIntervalSGI`: recorded; swaps never wait.
#[no_mangle]
pub extern "C" fn glXSwapIntervalSGI(interval: c_int) -> c_int {
    if interval <= 0 {
        return GLX_BAD_VALUE;
    }
    if current().0.is_null() {
        return GLX_BAD_CONTEXT;
    }
    set_interval(interval);
    0
}

/// `glXGetProcAddress`: every GL function and alias this library exports, and the GLX ones.
///
/// # Safety
/// `name` is a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn glXGetProcAddress(name: *const c_uchar) -> *const c_void {
    if name.is_null() {
        return std::ptr::null();
    }
    // SAFETY: the caller passes a NUL-terminated string.
    let name = unsafe { CStr::from_ptr(name as *const c_char) }.to_string_lossy();
    proc_address(&name)
}

/// `glXGetProcAddressARB`.
///
/// # Safety
/// As for `glXGetProcAddress`.
#[no_mangle]
pub unsafe extern "C" fn glXGetProcAddressARB(name: *const c_uchar) -> *const c_void {
    // SAFETY: forwarded contract.
    unsafe { glXGetProcAddress(name) }
}

/// The GLX function of this name, else the GL (or OSMesa, EGL) one.
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
        glXQueryExtension,
        glXQueryVersion,
        glXGetClientString,
        glXQueryServerString,
        glXQueryExtensionsString,
        glXChooseVisual,
        glXGetConfig,
        glXChooseFBConfig,
        glXGetFBConfigs,
        glXGetFBConfigAttrib,
        glXGetVisualFromFBConfig,
        glXCreateContext,
        glXCreateNewContext,
        glXCreateContextAttribsARB,
        glXDestroyContext,
        glXMakeCurrent,
        glXMakeContextCurrent,
        glXGetCurrentContext,
        glXGetCurrentDrawable,
        glXGetCurrentReadDrawable,
        glXGetCurrentDisplay,
        glXCreateWindow,
        glXDestroyWindow,
        glXCreatePixmap,
        glXDestroyPixmap,
        glXCreateGLXPixmap,
        glXDestroyGLXPixmap,
        glXSwapBuffers,
        glXQueryDrawable,
        glXQueryContext,
        glXSelectEvent,
        glXGetSelectedEvent,
        glXWaitGL,
        glXWaitX,
        glXIsDirect,
        glXCopyContext,
        glXSwapIntervalEXT,
        glXSwapIntervalMESA,
        glXGetSwapIntervalMESA,
        glXSwapIntervalSGI,
        glXGetProcAddress,
        glXGetProcAddressARB,
    );
    if name == "glXUseXFont" {
        return super::xfont::glXUseXFont as *const c_void;
    }
    let c_name = std::ffi::CString::new(name).unwrap_or_default();
    // SAFETY: a NUL-terminated string.
    unsafe { super::osmesa::OSMesaGetProcAddress(c_name.as_ptr()) }
}

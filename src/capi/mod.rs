//! The C ABI: the GL entry points with the C signatures of `GL/gl.h`, the OSMesa context API,
//! and `ForeignGl`, which drives another GL implementation (Mesa) through C function pointers.
//! This is the only module with `unsafe` code.

pub(crate) mod client_memory;
pub mod compsize;
pub mod egl;
pub mod foreign;
pub mod glx;
pub mod osmesa;
pub mod window;

use std::ffi::c_void;

use crate::api::*;
use crate::state::Context;

pub use foreign::ForeignGl;

/// Runs `f` on the calling thread's current context; without one, GL calls do nothing and
/// return zero (as with no current context in any GL).
fn with_current<R: Default>(f: impl FnOnce(&mut Context) -> R) -> R {
    osmesa::with_current_context(|c| {
        let r = f(&mut c.gl);
        if c.gl.take_present_request() {
            c.present();
        }
        r
    })
    .unwrap_or_default()
}

/// Element count from a length parameter (negative counts are the callee's error to report).
fn count_len(n: i64) -> usize {
    n.clamp(0, i32::MAX as i64) as usize
}

/// A slice over caller memory; empty for a null pointer or zero length.
///
/// # Safety
/// `p` must point to `n` readable elements when not null.
unsafe fn slice<'a, T>(p: *const T, n: usize) -> &'a [T] {
    if p.is_null() || n == 0 {
        &[]
    } else {
        // SAFETY: the caller guarantees `n` readable elements at `p` (the C API's contract).
        unsafe { std::slice::from_raw_parts(p, n) }
    }
}

/// Like `slice`, but `None` for a null pointer (GL's "no data", e.g. `glTexImage2D(..., NULL)`).
///
/// # Safety
/// As for `slice`.
unsafe fn opt_slice<'a>(p: *const u8, n: usize) -> Option<&'a [u8]> {
    if p.is_null() {
        None
    } else {
        // SAFETY: forwarded contract.
        Some(unsafe { slice(p, n) })
    }
}

/// A mutable slice over caller memory; empty for a null pointer.
///
/// # Safety
/// `p` must point to `n` writable elements when not null.
unsafe fn slice_mut<'a, T>(p: *mut T, n: usize) -> &'a mut [T] {
    if p.is_null() || n == 0 {
        &mut []
    } else {
        // SAFETY: the caller guarantees `n` writable elements at `p`.
        unsafe { std::slice::from_raw_parts_mut(p, n) }
    }
}

/// A fixed-size array at `p`, or `None` for null.
///
/// # Safety
/// `p` must point to `N` readable elements when not null.
unsafe fn array_ref<'a, T, const N: usize>(p: *const T) -> Option<&'a [T; N]> {
    // SAFETY: the caller guarantees `N` readable elements; arrays of T have T's alignment.
    unsafe { (p as *const [T; N]).as_ref() }
}

/// A mutable fixed-size array at `p`, or `None` for null.
///
/// # Safety
/// `p` must point to `N` writable elements when not null.
unsafe fn array_mut<'a, T, const N: usize>(p: *mut T) -> Option<&'a mut [T; N]> {
    // SAFETY: as for `array_ref`.
    unsafe { (p as *mut [T; N]).as_mut() }
}

/// The exported `gl*` functions.
pub mod exports {
    #![allow(non_snake_case)]
    use super::*;
    include!(concat!(env!("OUT_DIR"), "/capi_exports.rs"));
}

//! The C ABI: the GL entry points with the C signatures of `GL/gl.h`, the OSMesa context API,
//! and `ForeignGl`, which drives another GL implementation (Mesa) through C function pointers.
//! This is the only module with `unsafe` code.

pub mod client_memory;
pub mod compsize;
pub mod egl;
pub mod foreign;
pub mod glx;
pub mod osmesa;
pub mod window;
pub mod xfont;

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
        if c.gl.take_drawable_check_request() {
            c.check_drawable_size();
        }
        r
    })
    .unwrap_or_default()
}

/// Element count from a length parameter (negative counts are the callee's error to report).
fn count_len(n: i64) -> usize {
    n.clamp(0, i32::MAX as i64) as usize
}

/// The client-buffer check of debug builds: a test declares where its buffer ends
/// ([`tilegl_debug_client_bound`]), and every pointer parameter inside that buffer is held to
/// it. A length that would reach past the end is cut at the end (so GL sees a short buffer and
/// refuses the call, as the Rust API does, instead of reading past it) and counted
/// ([`tilegl_debug_client_overruns`]). Release builds compile the check away.
mod client_bound {
    #[cfg(debug_assertions)]
    use std::cell::Cell;

    #[cfg(debug_assertions)]
    thread_local! {
        /// The declared buffer as `[start, end)` addresses; `(0, 0)` for none.
        static BOUND: Cell<(usize, usize)> = const { Cell::new((0, 0)) };
        /// Pointer parameters that would have reached past the end since the last declaration.
        static OVERRUNS: Cell<usize> = const { Cell::new(0) };
    }

    /// Whether this build checks client buffers.
    pub(super) const ENABLED: bool = cfg!(debug_assertions);

    /// Declares the buffer `[start, start + len)` and resets the overrun count.
    pub(super) fn declare(start: usize, len: usize) {
        #[cfg(debug_assertions)]
        {
            BOUND.set((start, start.saturating_add(len)));
            OVERRUNS.set(0);
        }
        let _ = (start, len);
    }

    pub(super) fn overruns() -> usize {
        #[cfg(debug_assertions)]
        return OVERRUNS.get();
        #[cfg(not(debug_assertions))]
        0
    }

    /// The bytes of `bytes` at `p` that lie inside the declared buffer when `p` does (all of
    /// them otherwise).
    #[inline]
    pub(super) fn allowed(p: usize, bytes: usize) -> usize {
        #[cfg(debug_assertions)]
        {
            let (start, end) = BOUND.get();
            if start != 0 && p >= start && p <= end && bytes > end - p {
                OVERRUNS.set(OVERRUNS.get() + 1);
                return end - p;
            }
        }
        let _ = p;
        bytes
    }
}

/// Test hook: declares that the caller's client buffer is the `len` bytes at `start`, until
/// the next call. In debug builds every pointer parameter that points into it is then held to
/// its end (see [`tilegl_debug_client_overruns`]). Returns 1 when this build checks client
/// buffers (debug assertions on), 0 otherwise.
#[no_mangle]
pub extern "C" fn tilegl_debug_client_bound(start: *const c_void, len: usize) -> GLboolean {
    client_bound::declare(start as usize, len);
    client_bound::ENABLED as GLboolean
}

/// Test hook: how many pointer parameters since the last [`tilegl_debug_client_bound`] would
/// have been read or written past the declared buffer's end (debug builds; 0 otherwise).
#[no_mangle]
pub extern "C" fn tilegl_debug_client_overruns() -> usize {
    client_bound::overruns()
}

/// Elements of `T` at `p` that GL may use out of `n` (all of them, except past the end of a
/// buffer declared to the debug check).
#[inline]
fn allowed_elements<T>(p: *const T, n: usize) -> usize {
    let size = std::mem::size_of::<T>().max(1);
    client_bound::allowed(p as usize, n.saturating_mul(size)) / size
}

/// A slice over caller memory; empty for a null pointer or zero length.
///
/// # Safety
/// `p` must point to `n` readable elements when not null.
unsafe fn slice<'a, T>(p: *const T, n: usize) -> &'a [T] {
    if p.is_null() || n == 0 {
        &[]
    } else {
        let n = allowed_elements(p, n);
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
        let n = allowed_elements(p, n);
        // SAFETY: the caller guarantees `n` writable elements at `p`.
        unsafe { std::slice::from_raw_parts_mut(p, n) }
    }
}

/// A fixed-size array at `p`, or `None` for null (or, in debug builds, when it would reach
/// past a declared buffer: the call is then not made).
///
/// # Safety
/// `p` must point to `N` readable elements when not null.
unsafe fn array_ref<'a, T, const N: usize>(p: *const T) -> Option<&'a [T; N]> {
    if !p.is_null() && allowed_elements(p, N) < N {
        return None;
    }
    // SAFETY: the caller guarantees `N` readable elements; arrays of T have T's alignment.
    unsafe { (p as *const [T; N]).as_ref() }
}

/// A mutable fixed-size array at `p`, or `None` for null (or past a declared buffer).
///
/// # Safety
/// `p` must point to `N` writable elements when not null.
unsafe fn array_mut<'a, T, const N: usize>(p: *mut T) -> Option<&'a mut [T; N]> {
    if !p.is_null() && allowed_elements(p as *const T, N) < N {
        return None;
    }
    // SAFETY: as for `array_ref`.
    unsafe { (p as *mut [T; N]).as_mut() }
}

/// The exported `gl*` functions.
pub mod exports {
    #![allow(non_snake_case, clippy::identity_op)]
    use super::*;
    include!(concat!(env!("OUT_DIR"), "/capi_exports.rs"));
}

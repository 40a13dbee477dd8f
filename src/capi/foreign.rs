//! `ForeignGl`: the `Gl` trait implemented by calling another GL implementation's C entry
//! points (Mesa's, in the conformance oracle). Generated from the same registry table as the
//! trait, so both sides always agree on every signature.

// The generated forwarding code is uniform on purpose: it binds every C return (also `()`),
// casts every argument to its C type (also same-type casts) and calls the fn pointer through
// a closure per entry point.
#![allow(
    clippy::let_unit_value,
    clippy::unnecessary_cast,
    clippy::redundant_closure_call
)]

use std::ffi::{c_void, CStr, CString};

use crate::api::*;

/// A GL implementation reached through C function pointers.
pub struct ForeignGl {
    fns: Vec<*const c_void>,
    /// Entry points called but not provided by the implementation.
    pub missing: Vec<&'static str>,
}

impl ForeignGl {
    /// Looks every GL 1.5 entry point up with `lookup` (e.g. `OSMesaGetProcAddress`).
    ///
    /// # Safety
    /// Every non-null pointer `lookup` returns must be the named GL function with the C signature
    /// of `GL/gl.h`, valid for as long as this value lives and called only while the foreign
    /// context is current on this thread. Callers of the trait methods must pass slices at least
    /// as long as the foreign GL reads or writes (it cannot check them).
    pub unsafe fn new(mut lookup: impl FnMut(&CStr) -> *const c_void) -> ForeignGl {
        let fns = FOREIGN_NAMES
            .iter()
            .map(|n| {
                let name = CString::new(*n).unwrap_or_default();
                lookup(&name)
            })
            .collect();
        ForeignGl {
            fns,
            missing: Vec::new(),
        }
    }
}

fn c_string(p: *const GLubyte) -> Option<String> {
    if p.is_null() {
        return None;
    }
    // SAFETY: GL returns a NUL-terminated static string from glGetString.
    let s = unsafe { CStr::from_ptr(p as *const std::ffi::c_char) };
    Some(s.to_string_lossy().into_owned())
}

include!(concat!(env!("OUT_DIR"), "/foreign.rs"));

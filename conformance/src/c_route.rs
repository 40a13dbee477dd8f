//! tilegl reached the way C programs reach it: a context made with the exported OSMesa
//! functions (`OSMesaCreateContextExt`, `OSMesaMakeCurrent`), every GL call going through the
//! exported `gl*` function that `OSMesaGetProcAddress` returns, driven by the same
//! [`ForeignGl`] that drives Mesa. The pointer lengths, the enum and pointer conversions and
//! the current-context handling of the C ABI are all on this route; the differential scenes
//! and the state cases run on it beside the Rust route and must give identical pictures and
//! identical answers.
//!
//! The exports are called in this process (the `tilegl` library linked into the test), which
//! is the same generated code that `libtilegl.so` exports; that the library exports each of
//! them under its C name is checked by `tests/capi.rs` in the `tilegl` crate.

use std::ffi::{c_void, CStr};
use std::ops::{Deref, DerefMut};

use tilegl::capi::osmesa::{self, OsMesaContext, OSMESA_RGBA};
use tilegl::capi::ForeignGl;
use tilegl::enums::*;

/// A tilegl context behind the C ABI, rendering into a buffer it owns. Derefs to
/// [`ForeignGl`], so `&mut *c` is a `&mut dyn Gl`. Bound to the thread that made it.
pub struct CAbiContext {
    gl: ForeignGl,
    ctx: *mut OsMesaContext,
    buffer: Vec<u8>,
}

impl CAbiContext {
    /// A `width` x `height` RGBA context with 24 depth bits, 8 stencil bits and
    /// `accum_bits` accumulation bits per channel (0 or 16: the Rust route's configurations),
    /// current on this thread. `None` if the C ABI refuses the size.
    pub fn create(width: i32, height: i32, accum_bits: i32) -> Option<CAbiContext> {
        let ctx =
            osmesa::OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, accum_bits, std::ptr::null_mut());
        if ctx.is_null() {
            return None;
        }
        let lookup = |name: &CStr| {
            // SAFETY: `name` is NUL-terminated; OSMesaGetProcAddress has no other precondition.
            unsafe { osmesa::OSMesaGetProcAddress(name.as_ptr()) }
        };
        // SAFETY: OSMesaGetProcAddress returns, for a GL name, the exported function of that
        // name with the C signature of GL/gl.h (or NULL); the functions live as long as the
        // program and act on the context current on the calling thread, made current below and
        // kept on this thread (`CAbiContext` holds raw pointers, so it is !Send). Slice lengths
        // are the trait callers' responsibility, as documented on `ForeignGl::new`.
        let gl = unsafe { ForeignGl::new(lookup) };
        let mut c = CAbiContext {
            gl,
            ctx,
            buffer: vec![0u8; width.max(0) as usize * height.max(0) as usize * 4],
        };
        // SAFETY: `ctx` is live; the buffer holds width * height RGBA pixels and is neither
        // moved nor freed before the context is destroyed (Drop destroys it first).
        let ok = unsafe {
            osmesa::OSMesaMakeCurrent(
                c.ctx,
                c.buffer.as_mut_ptr() as *mut c_void,
                GL_UNSIGNED_BYTE,
                width,
                height,
            )
        };
        (ok != 0).then_some(c)
    }
}

impl Deref for CAbiContext {
    type Target = ForeignGl;
    fn deref(&self) -> &ForeignGl {
        &self.gl
    }
}

impl DerefMut for CAbiContext {
    fn deref_mut(&mut self) -> &mut ForeignGl {
        &mut self.gl
    }
}

impl Drop for CAbiContext {
    fn drop(&mut self) {
        // SAFETY: NULL unbinds the thread's current context; `self.ctx` came from
        // OSMesaCreateContextExt and is destroyed exactly once, before the buffer is freed.
        unsafe {
            osmesa::OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0);
            osmesa::OSMesaDestroyContext(self.ctx);
        }
    }
}

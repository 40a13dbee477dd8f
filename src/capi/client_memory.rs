//! The one bridge from a [`ClientPtr`] (an address in the calling process that GL retained,
//! e.g. from `glVertexPointer`) to memory: reading client vertex arrays and index arrays at
//! draw time, storing a pointer value for `glGetPointerv`/`glGetBufferPointerv`, and writing
//! the selection and feedback records into the buffers of `glSelectBuffer`/`glFeedbackBuffer`.
//!
//! # The contract
//!
//! OpenGL's client-array contract (section 2.8 of the 1.5 specification) is that the
//! application keeps the memory named by `gl*Pointer`, `glInterleavedArrays` and client
//! `glDrawElements` indices valid and readable for every element a draw command uses, for as
//! long as the draw runs, and that `glGetPointerv` is given room for one pointer. C callers of
//! `libtilegl.so`, Mesa-style, and the trace replayer (which passes addresses of bytes it keeps
//! alive) meet it. A Rust caller that hands a [`ClientPtr`] to the `Gl` trait makes the same
//! promise; Rust code that wants no such promise sources its arrays from buffer objects
//! (`glBindBuffer(GL_ARRAY_BUFFER, ..)`, where the "pointer" is an offset into memory the
//! context owns) and reads pointers with `Context::array_pointer`.
//!
//! A null address is never dereferenced: reads give nothing, writes are skipped.

use crate::api::types::ClientPtr;
use crate::state::client_memory::ClientMemory;
use crate::state::Context;

/// The memory of this process, read and written under the contract above.
struct ProcessMemory;

impl ClientMemory for ProcessMemory {
    fn read(&self, base: ClientPtr, offset: usize, len: usize, f: &mut dyn FnMut(&[u8])) {
        with_client_bytes_from(base, offset, len, f)
    }

    fn store_pointer(&self, dest: ClientPtr, value: usize) {
        store_pointer(dest, value)
    }

    fn write(&self, dest: ClientPtr, bytes: &[u8]) {
        write_client_bytes(dest, bytes)
    }
}

/// Lets `ctx` read and write the process memory its `ClientPtr`s name. The C ABI's contexts
/// get it when created; a Rust caller that hands `ClientPtr`s to the `Gl` trait calls this.
///
/// # Safety
///
/// The caller keeps the contract above for every `ClientPtr` it hands `ctx` from now on: the
/// memory an address names is valid for what GL reads or writes there, for as long as GL
/// uses it.
pub unsafe fn attach(ctx: &mut Context) {
    ctx.set_client_memory(&ProcessMemory);
}

/// Calls `f` with the `len` bytes `offset` bytes past `base` (a client array's start: the
/// debug builds' client-buffer check holds the whole span from `base` to the declared
/// buffer's end, as for pointer parameters; see `capi::client_bound`).
pub(crate) fn with_client_bytes_from<R>(
    base: ClientPtr,
    offset: usize,
    len: usize,
    f: impl FnOnce(&[u8]) -> R,
) -> R {
    let span = super::client_bound::allowed(base.0, offset.saturating_add(len));
    let len = len.min(span.saturating_sub(offset));
    let Some(ptr) = base.0.checked_add(offset).map(ClientPtr) else {
        return f(&[]);
    };
    if base.0 == 0 || len == 0 || len > isize::MAX as usize {
        return f(&[]);
    }
    // SAFETY: by the GL client-array contract (module docs) the application guarantees that
    // the `len` bytes starting at `ptr` (the elements the current draw uses, from the smallest
    // to the largest index, as computed by the caller from the array's size, type and stride,
    // or the draw's indices) are valid and readable
    // and not written during the draw; the slice lives only for the duration of `f`, i.e. the
    // draw command. Bytes have no alignment requirement.
    let bytes = unsafe { std::slice::from_raw_parts(ptr.0 as *const u8, len) };
    f(bytes)
}

/// Stores the pointer value `value` at `dest` (`glGetPointerv(pname, params)`: `params` is a
/// `void **`), unless `dest` is null.
pub(crate) fn store_pointer(dest: ClientPtr, value: usize) {
    if dest.0 == 0 {
        return;
    }
    // SAFETY: by the GL contract of `glGetPointerv`/`glGetBufferPointerv` the application passes
    // the address of storage for one `void *`; `write_unaligned` needs no alignment.
    unsafe { std::ptr::write_unaligned(dest.0 as *mut usize, value) }
}

/// Copies `bytes` to the client memory at `dest` (the selection and feedback buffers, filled
/// when `glRenderMode` leaves the mode), unless `dest` is null.
pub(crate) fn write_client_bytes(dest: ClientPtr, bytes: &[u8]) {
    // Debug builds hold the write to a declared client buffer (see `capi::client_bound`).
    let bytes = &bytes[..super::client_bound::allowed(dest.0, bytes.len())];
    if dest.0 == 0 || bytes.is_empty() {
        return;
    }
    // SAFETY: by the GL contract of `glSelectBuffer`/`glFeedbackBuffer` the application keeps
    // the buffer it named (`size` values of 4 bytes) valid and writable until `glRenderMode`
    // returns from the mode; the caller writes at most `size` values (`bytes.len()` is at
    // most 4 * size). `copy_nonoverlapping` on bytes needs no alignment, and the source is
    // context memory, which cannot overlap the client buffer.
    unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), dest.0 as *mut u8, bytes.len()) }
}

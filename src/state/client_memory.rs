//! How the state machine reaches the client memory a [`ClientPtr`] names (client vertex and
//! index arrays at draw time, the `void **` of `glGetPointerv`, the selection and feedback
//! buffers). Dereferencing an address is the C ABI's business (`capi::client_memory`, which
//! holds the `unsafe` and its contract); the context only holds the [`ClientMemory`] it was
//! given. A context nobody gave one reads no client memory: its client arrays read as empty
//! (as a null pointer does) and its pointer and buffer writes are skipped, so a Rust caller
//! of the safe API cannot make the context dereference an arbitrary number.

use crate::gl::types::ClientPtr;

/// Access to the memory of the process that calls GL, under the GL client-memory contract
/// (the application keeps the memory it named valid while GL uses it).
pub trait ClientMemory: Sync {
    /// Calls `f` with the `len` bytes `offset` bytes past `base` (fewer, or none, where the
    /// memory is not available; none for a null `base`).
    fn read(&self, base: ClientPtr, offset: usize, len: usize, f: &mut dyn FnMut(&[u8]));

    /// Stores the pointer value `value` at `dest` (a `void *` slot), unless `dest` is null.
    fn store_pointer(&self, dest: ClientPtr, value: usize);

    /// Copies `bytes` to `dest`, unless `dest` is null.
    fn write(&self, dest: ClientPtr, bytes: &[u8]);
}

/// No client memory: reads give nothing, writes are dropped (a context's default).
pub struct NoClientMemory;

impl ClientMemory for NoClientMemory {
    fn read(&self, _: ClientPtr, _: usize, _: usize, f: &mut dyn FnMut(&[u8])) {
        f(&[]);
    }

    fn store_pointer(&self, _: ClientPtr, _: usize) {}

    fn write(&self, _: ClientPtr, _: &[u8]) {}
}

/// Calls `f` with the `len` bytes `offset` bytes past `base` in `memory` (an empty slice
/// where `memory` has none).
pub(crate) fn with_bytes_from<R>(
    memory: &dyn ClientMemory,
    base: ClientPtr,
    offset: usize,
    len: usize,
    f: impl FnOnce(&[u8]) -> R,
) -> R {
    let mut f = Some(f);
    let mut out = None;
    memory.read(base, offset, len, &mut |b| {
        if let Some(f) = f.take() {
            out = Some(f(b));
        }
    });
    match (out, f) {
        (Some(r), _) => r,
        (None, Some(f)) => f(&[]),
        // `f` ran exactly when `out` was set.
        (None, None) => unreachable!(),
    }
}

/// [`with_bytes_from`] at offset 0.
pub(crate) fn with_bytes<R>(
    memory: &dyn ClientMemory,
    ptr: ClientPtr,
    len: usize,
    f: impl FnOnce(&[u8]) -> R,
) -> R {
    with_bytes_from(memory, ptr, 0, len, f)
}

//! Target `c_calls`: structured GL call sequences through the exported C functions, in
//! process, on an OSMesa context made with the exported OSMesa functions.
//!
//! The input is a header (window width and height, pixel format and buffer bits, a seed for
//! the client memory) and then a sequence of calls: two bytes pick an entry point of
//! `FUZZ_CALLS` (every exported GL 1.5 entry point), and the call draws its arguments from the
//! following bytes through [`Source`]. Every pointer keeps the C contract:
//!
//! - a pointer that GL reads or writes during the call points to exactly as many bytes as the
//!   C ABI computes for the call's arguments and the current state (the generated call asks
//!   the same length expressions the exports use), in a region of one arena;
//! - a pointer GL keeps (client arrays, indices, selection and feedback buffers,
//!   `glGetPointerv`'s result) points into the arena, which lives until the context is
//!   destroyed, or is a small offset when a buffer object is bound (GL then reads it as one);
//! - the arena is declared to the debug builds' client-buffer check before every call, so
//!   what a draw reads through indices the fuzzer chose (a client-array read the C contract
//!   leaves to the application) is held to the arena's end instead of running past it.
//!
//! Scalars come from distributions that favour small values and GL's enums, with extremes
//! mixed in; a few parameters that only set how much work a call does (draw counts, mesh
//! sizes, object counts) are capped so one input stays fast.

use std::ffi::c_void;

use tilegl::api::types::*;
use tilegl::capi::exports::{glFinish, glGetIntegerv, FuzzArgs, FUZZ_CALLS};
use tilegl::capi::osmesa::*;
use tilegl::capi::tilegl_debug_client_bound;
use tilegl::enums::*;

/// Calls made from one input at most.
const MAX_OPS: usize = 256;
/// Largest memory one pointer parameter gets (larger calls are skipped).
const MAX_PARAM_BYTES: usize = 256 << 10;

// The arena's regions (bytes).
/// Pointer arrays (`glMultiDrawElements`' `indices`), written only here.
const PTRS: usize = 0;
/// Room for a pointer GL writes (`glGetPointerv`, `glGetBufferPointerv`).
const SCRATCH: usize = 4 << 10;
/// Client index arrays.
const INDEX: usize = 8 << 10;
const INDEX_LEN: usize = 64 << 10;
/// Client vertex arrays.
const VERTEX: usize = INDEX + INDEX_LEN;
const VERTEX_LEN: usize = 320 << 10;
/// Memory of the current call's pointer parameters.
const CALL: usize = VERTEX + VERTEX_LEN;
const CALL_LEN: usize = 1 << 20;
/// Selection and feedback buffers, at the end (writes past the end are cut by the check).
const FEEDBACK: usize = CALL + CALL_LEN;
const ARENA_LEN: usize = FEEDBACK + (16 << 10);

/// The fuzzer's bytes, read front to back; zeros once they are used up.
struct Bytes<'a> {
    data: &'a [u8],
    pos: usize,
}

impl Bytes<'_> {
    fn u8(&mut self) -> u8 {
        let b = self.data.get(self.pos).copied().unwrap_or(0);
        self.pos += 1;
        b
    }
    fn u16(&mut self) -> u16 {
        u16::from_le_bytes([self.u8(), self.u8()])
    }
    fn u32(&mut self) -> u32 {
        u32::from_le_bytes([self.u8(), self.u8(), self.u8(), self.u8()])
    }
    fn done(&self) -> bool {
        self.pos >= self.data.len()
    }
}

/// Deterministic filler for the client arrays (xorshift64).
fn fill_pattern(seed: u64, out: &mut [u8]) {
    let mut s = seed | 1;
    for chunk in out.chunks_mut(8) {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        chunk.copy_from_slice(&s.to_le_bytes()[..chunk.len()]);
    }
}

/// Interesting integers.
const EXTREME_INTS: [i64; 8] = [
    i32::MIN as i64,
    i32::MAX as i64,
    -1,
    0,
    1 << 16,
    u32::MAX as i64,
    i32::MAX as i64 - 1,
    1 << 24,
];

/// Interesting floats.
const EXTREME_FLOATS: [f64; 10] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    1e30,
    -1e30,
    f32::MAX as f64,
    f32::MIN_POSITIVE as f64,
    1e-40,
    -0.0,
    65536.5,
];

/// The argument source of one input: its bytes and the arena.
struct Source<'a> {
    bytes: Bytes<'a>,
    arena: &'a mut [u8],
    /// Bytes of the call area handed out to the current call.
    call_used: usize,
    /// Integer arguments of the current call so far.
    ints: Vec<(&'static str, i64)>,
}

impl Source<'_> {
    fn arena_ptr(&mut self, offset: usize) -> *mut u8 {
        // SAFETY: every caller passes an offset inside the arena.
        unsafe { self.arena.as_mut_ptr().add(offset) }
    }

    fn small_int(&mut self) -> i64 {
        match self.bytes.u8() {
            0..=159 => self.bytes.u8() as i64 - 2,
            160..=219 => (self.bytes.u16() % 4097) as i64,
            220..=239 => self.bytes.u32() as i32 as i64,
            _ => EXTREME_INTS[self.bytes.u8() as usize % EXTREME_INTS.len()],
        }
    }

    fn enum_value(&mut self) -> i64 {
        match self.bytes.u8() {
            0..=219 => {
                let i = self.bytes.u16() as usize % ENUMS_BY_NAME.len();
                ENUMS_BY_NAME[i].1 as i64
            }
            220..=239 => self.bytes.u16() as i64,
            _ => self.bytes.u32() as i64,
        }
    }

    fn float_value(&mut self) -> f64 {
        match self.bytes.u8() {
            0..=127 => (self.bytes.u8() as i8) as f64 / 16.0,
            128..=191 => (self.bytes.u16() as i16) as f64 / 64.0,
            192..=239 => f32::from_bits(self.bytes.u32()) as f64,
            _ => EXTREME_FLOATS[self.bytes.u8() as usize % EXTREME_FLOATS.len()],
        }
    }

    /// Whether a buffer object is bound to `binding` (then GL reads pointers as offsets).
    fn bound(&mut self, binding: GLenum) -> bool {
        let mut v: GLint = 0;
        // SAFETY: one GLint of room for a single-valued query.
        unsafe { glGetIntegerv(binding, &mut v) };
        v != 0
    }

    /// A client-array address: an offset when a buffer object is bound to `binding`, else a
    /// place in the arena region `region..region + len`.
    fn client_address(&mut self, binding: GLenum, region: usize, len: usize) -> *mut u8 {
        let choice = self.bytes.u16();
        if choice % 32 == 31 {
            return std::ptr::null_mut();
        }
        if self.bound(binding) {
            return (choice as usize % 1024) as *mut u8;
        }
        self.arena_ptr(region + (choice as usize * 4) % len)
    }
}

impl FuzzArgs for Source<'_> {
    fn int(&mut self, cmd: &'static str, param: &'static str, ty: &'static str) -> i64 {
        let v = match ty {
            "GLenum" => self.enum_value(),
            "GLbitfield" => match self.bytes.u8() {
                0..=199 => self.bytes.u32() as i64,
                _ => u32::MAX as i64,
            },
            "GLboolean" => match self.bytes.u8() {
                0..=249 => (self.bytes.u8() & 1) as i64,
                _ => self.bytes.u8() as i64,
            },
            _ => self.small_int(),
        };
        // Caps on parameters that only set how much work the call does.
        let v = match (cmd, param) {
            ("glMultiDrawArrays" | "glMultiDrawElements", "drawcount") => v.clamp(-1, 64),
            ("glDrawArrays" | "glDrawElements" | "glDrawRangeElements", "first" | "count")
            | ("glArrayElement", "i") => v.clamp(-1, 4096),
            (c, "i1" | "i2" | "j1" | "j2" | "i" | "j") if c.starts_with("glEval") => {
                v.clamp(-300, 300)
            }
            (c, "un" | "vn") if c.starts_with("glMapGrid") => v.clamp(-1, 256),
            (_, "n" | "range") => v.clamp(-1, 4096),
            (c, "depth") if c.starts_with("glTex") || c.starts_with("glCopyTex") => v.clamp(-2, 16),
            (c, "width" | "height") if c.starts_with("glTex") || c.starts_with("glCopyTex") => {
                v.clamp(-2, 1024)
            }
            _ => v,
        };
        self.ints.push((param, v));
        v
    }

    fn float(&mut self, _cmd: &'static str, _param: &'static str) -> f64 {
        self.float_value()
    }

    fn memory(
        &mut self,
        cmd: &'static str,
        param: &'static str,
        ty: &'static str,
        bytes: usize,
    ) -> Option<*mut u8> {
        if self.bytes.u8() == 255 {
            return Some(std::ptr::null_mut());
        }
        if bytes > MAX_PARAM_BYTES || self.call_used + bytes > CALL_LEN {
            return None;
        }
        let start = CALL + self.call_used;
        self.call_used = (self.call_used + bytes + 15) & !15;
        // Up to 64 elements from the input, the rest a pattern.
        let (elem, values) = match ty {
            "GLfloat" | "GLclampf" => (4, true),
            "GLdouble" | "GLclampd" => (8, true),
            "GLint" | "GLuint" | "GLsizei" | "GLenum" => (4, false),
            "GLshort" | "GLushort" => (2, false),
            _ => (1, false),
        };
        let n = (bytes / elem).min(64);
        for i in 0..n {
            let at = start + i * elem;
            let value = match (cmd, param) {
                // Draw counts and firsts: the work they set is capped like the scalars'.
                ("glMultiDrawArrays" | "glMultiDrawElements", "first" | "count") => {
                    (self.small_int().clamp(-1, 2048) as i32)
                        .to_le_bytes()
                        .to_vec()
                }
                _ if values && elem == 4 => (self.float_value() as f32).to_le_bytes().to_vec(),
                _ if values => self.float_value().to_le_bytes().to_vec(),
                _ if elem == 4 => (self.small_int() as i32).to_le_bytes().to_vec(),
                _ if elem == 2 => (self.small_int() as i16).to_le_bytes().to_vec(),
                _ => vec![self.bytes.u8()],
            };
            self.arena[at..at + elem].copy_from_slice(&value);
        }
        let seed = self.bytes.u8() as u64 + 1;
        fill_pattern(seed, &mut self.arena[start + n * elem..start + bytes]);
        Some(self.arena_ptr(start))
    }

    fn retained(&mut self, cmd: &'static str, param: &'static str) -> *mut u8 {
        match (cmd, param) {
            ("glSelectBuffer" | "glFeedbackBuffer", _) => self.arena_ptr(FEEDBACK),
            ("glDrawElements" | "glDrawRangeElements", "indices") => {
                self.client_address(GL_ELEMENT_ARRAY_BUFFER_BINDING, INDEX, INDEX_LEN)
            }
            ("glMultiDrawElements", "indices") => {
                let n = self
                    .ints
                    .iter()
                    .find(|(p, _)| *p == "drawcount")
                    .map_or(0, |&(_, v)| v.clamp(0, 512) as usize);
                let size = std::mem::size_of::<usize>();
                for i in 0..n {
                    let p = self.client_address(GL_ELEMENT_ARRAY_BUFFER_BINDING, INDEX, INDEX_LEN);
                    let at = PTRS + i * size;
                    self.arena[at..at + size].copy_from_slice(&(p as usize).to_ne_bytes());
                }
                self.arena_ptr(PTRS)
            }
            (c, "pointer") if c.ends_with("Pointer") || c == "glInterleavedArrays" => {
                self.client_address(GL_ARRAY_BUFFER_BINDING, VERTEX, VERTEX_LEN)
            }
            _ => self.arena_ptr(SCRATCH),
        }
    }
}

/// Target `c_calls` (see the module documentation).
pub fn c_calls(data: &[u8]) {
    let mut bytes = Bytes { data, pos: 0 };
    let width = 1 + (bytes.u8() % 64) as i32;
    let height = 1 + (bytes.u8() % 64) as i32;
    let config = bytes.u8();
    let seed = bytes.u32() as u64;
    let (format, bpp) = [
        (OSMESA_RGBA, 4),
        (OSMESA_BGRA, 4),
        (OSMESA_ARGB, 4),
        (OSMESA_RGB, 3),
    ][config as usize & 3];
    let depth = [0, 16, 24, 32][(config as usize >> 2) & 3];
    let stencil = if config & 16 != 0 { 8 } else { 0 };
    let accum = if config & 32 != 0 { 16 } else { 0 };

    let ctx = OSMesaCreateContextExt(format, depth, stencil, accum, std::ptr::null_mut());
    assert!(!ctx.is_null(), "a context of a supported format");
    let mut color = vec![0u8; (width * height) as usize * bpp];
    // The arena as u64s, so every region is 8-byte aligned.
    let mut arena_words = vec![0u64; ARENA_LEN / 8];
    let arena: &mut [u8] = bytemuck::cast_slice_mut(&mut arena_words);
    fill_pattern(seed, &mut arena[INDEX..INDEX + INDEX_LEN]);
    fill_pattern(seed ^ 0x9e37_79b9, &mut arena[VERTEX..VERTEX + VERTEX_LEN]);
    // Half of the indices small (they name vertices the arrays hold), half of the vertex
    // data floats in [-1.5, 1.5).
    for c in arena[INDEX..INDEX + INDEX_LEN / 2].chunks_mut(2) {
        c[1] &= 0x0f;
    }
    for c in arena[VERTEX..VERTEX + VERTEX_LEN / 2].chunks_mut(4) {
        let v = (u32::from_le_bytes([c[0], c[1], c[2], c[3]]) as f64 / u32::MAX as f64) * 3.0;
        c.copy_from_slice(&((v - 1.5) as f32).to_le_bytes());
    }

    // SAFETY: a live context and a colour buffer of width x height pixels of its format,
    // which outlives the context (destroyed below, before `color` is dropped).
    let ok = unsafe {
        OSMesaMakeCurrent(
            ctx,
            color.as_mut_ptr() as *mut c_void,
            GL_UNSIGNED_BYTE,
            width,
            height,
        )
    };
    assert_eq!(
        ok, GL_TRUE as GLboolean,
        "{width}x{height} is a valid buffer"
    );

    let mut source = Source {
        bytes,
        arena,
        call_used: 0,
        ints: Vec::new(),
    };
    for _ in 0..MAX_OPS {
        if source.bytes.done() {
            break;
        }
        let (_, call) = FUZZ_CALLS[source.bytes.u16() as usize % FUZZ_CALLS.len()];
        source.call_used = 0;
        source.ints.clear();
        tilegl_debug_client_bound(source.arena.as_ptr() as *const c_void, ARENA_LEN);
        // SAFETY: `Source` keeps the contract `FuzzArgs` asks for (module documentation):
        // every pointer spans what the C ABI uses, retained ones live in the arena until the
        // context is destroyed.
        unsafe { call(&mut source) };
    }
    // SAFETY: finishes the context's work, unbinds it and destroys it exactly once, while the
    // colour buffer and the arena are still alive.
    unsafe {
        glFinish();
        OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0);
        OSMesaDestroyContext(ctx);
    }
    drop(color);
}

//! Vertex arrays (section 2.8), buffer objects (section 2.9) and the client attribute stack
//! (`glPushClientAttrib`, section 6.1.14).
//!
//! # How a draw reads its arrays
//!
//! The specification defines `glArrayElement(i)` as the sequence of `glEdgeFlag`,
//! `glMultiTexCoord`, `glNormal`, `glColor`, `glSecondaryColor`, `glFogCoord` and `glVertex`
//! calls with element `i` of each enabled array, and `glDrawArrays`/`glDrawElements`/... as
//! `glBegin`, one `glArrayElement` per index, `glEnd`. tilegl does exactly that: a draw first
//! *fetches* the elements it uses (`Fetched`: each enabled array's components converted to
//! floating point by the same conversions as the immediate-mode calls, table 2.6), then
//! *applies* them one by one through the immediate-mode path (`Context::vertex4` and the current
//! values), so a picture drawn from arrays is the picture the same immediate-mode calls draw.
//! Fetching first also serves display lists, which keep the fetched vertices (arrays are
//! dereferenced at compile time).
//!
//! An array's data is either in a buffer object (the pointer is an offset into the buffer
//! bound to `GL_ARRAY_BUFFER` when the pointer was given; safe, owned by the context) or in
//! client memory, read through the context's `client_memory` (attached by the C ABI) under the GL client-array
//! contract.
//! Elements beyond the end of a buffer object read as zeros; a null client pointer reads as
//! zeros.

use std::collections::HashMap;
use std::sync::Arc;

use parking_lot::{MappedRwLockWriteGuard, RwLock, RwLockReadGuard, RwLockWriteGuard};

use glam::{Vec3, Vec4};

use super::client_memory;
use super::tables::PixelStore;
use super::Context;
use crate::common::limits::MAX_TEXTURE_UNITS;
use crate::common::values::{
    ArrayQuery, ArrayType, BufferAccess, BufferParam, BufferTarget, ClientArray, IndexType,
    InterleavedFormat,
};
use crate::gl::convert;
use crate::gl::enums::*;
use crate::state::get::StateValue;
use crate::vertex::immediate::{norm_i16, norm_i32, norm_i8, norm_u16, norm_u32, norm_u8};

mod buffer_objects;
mod client_attrib;
mod draw;
mod pixel_buffers;
mod pointers;

/// Current values saved across an array draw (see `Context::keep_current_values`).
struct SavedCurrent {
    current: super::tables::CurrentValues,
    materials: Option<[super::lighting::Material; 2]>,
}

/// `GL_MAX_CLIENT_ATTRIB_STACK_DEPTH`.
pub const MAX_CLIENT_ATTRIB_STACK_DEPTH: usize = 16;
/// `GL_MAX_ELEMENTS_VERTICES` / `GL_MAX_ELEMENTS_INDICES` (recommendations only).
pub const MAX_ELEMENTS: i64 = 3000;

/// A row of table 2.5: texture size, colour (size, unsigned byte?), normal, vertex size, and
/// the colour, normal and vertex offsets and the record size in bytes.
type InterleavedLayout = (
    i32,
    Option<(i32, bool)>,
    bool,
    i32,
    usize,
    usize,
    usize,
    usize,
);

/// One vertex array: `gl*Pointer` state plus its enable (table 6.8).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArrayPointer {
    pub enabled: bool,
    pub size: i32,
    pub ty: ArrayType,
    /// As given (0 means tightly packed).
    pub stride: i32,
    /// Client address, or offset into `buffer` when `buffer != 0`.
    pub pointer: ClientPtr,
    /// `GL_*_ARRAY_BUFFER_BINDING`: the array buffer bound when the pointer was given.
    pub buffer: GLuint,
    /// `GL_*_ARRAY_COUNT_EXT`: the `count` of EXT_vertex_array's `gl*PointerEXT` (the
    /// elements the program says are valid; drawing does not depend on it).
    pub count: i32,
}

impl ArrayPointer {
    fn new(size: i32, ty: ArrayType) -> ArrayPointer {
        ArrayPointer {
            enabled: false,
            size,
            ty,
            stride: 0,
            pointer: ClientPtr(0),
            buffer: 0,
            count: 0,
        }
    }

    /// Components stored per element: `size`, or 4 for `GL_BGRA` (ARB_vertex_array_bgra).
    fn components(&self) -> usize {
        if self.size == GL_BGRA as i32 {
            4
        } else {
            self.size as usize
        }
    }

    fn element_bytes(&self) -> usize {
        self.components() * self.ty.size()
    }

    fn effective_stride(&self) -> usize {
        if self.stride == 0 {
            self.element_bytes()
        } else {
            self.stride as usize
        }
    }
}

/// The vertex-array state of the client (table 6.8, without the buffer contents).
#[derive(Clone, Debug, PartialEq)]
pub struct ArrayState {
    pub vertex: ArrayPointer,
    pub normal: ArrayPointer,
    pub color: ArrayPointer,
    pub secondary_color: ArrayPointer,
    pub fog_coord: ArrayPointer,
    pub edge_flag: ArrayPointer,
    pub index: ArrayPointer,
    pub tex_coord: [ArrayPointer; MAX_TEXTURE_UNITS],
    /// `GL_ARRAY_BUFFER_BINDING`.
    pub array_buffer: GLuint,
    /// `GL_ELEMENT_ARRAY_BUFFER_BINDING`.
    pub element_array_buffer: GLuint,
}

impl Default for ArrayState {
    fn default() -> Self {
        use ArrayType::*;
        ArrayState {
            vertex: ArrayPointer::new(4, Float),
            normal: ArrayPointer::new(3, Float),
            color: ArrayPointer::new(4, Float),
            secondary_color: ArrayPointer::new(3, Float),
            fog_coord: ArrayPointer::new(1, Float),
            edge_flag: ArrayPointer::new(1, UnsignedByte),
            index: ArrayPointer::new(1, Float),
            tex_coord: [ArrayPointer::new(4, Float); MAX_TEXTURE_UNITS],
            array_buffer: 0,
            element_array_buffer: 0,
        }
    }
}

/// One buffer object (section 2.9).
#[derive(Clone, Debug)]
pub struct BufferObject {
    pub data: Vec<u8>,
    pub usage: GLenum,
    pub access: BufferAccess,
    pub mapped: bool,
    /// ARB_map_buffer_range: the mapped range (`GL_BUFFER_MAP_OFFSET`, `GL_BUFFER_MAP_LENGTH`)
    /// and the `glMapBufferRange` access bits (`GL_BUFFER_ACCESS_FLAGS`); zeros when unmapped.
    pub map_offset: usize,
    pub map_length: usize,
    pub access_flags: GLbitfield,
}

impl Default for BufferObject {
    fn default() -> Self {
        BufferObject {
            data: Vec::new(),
            usage: GL_STATIC_DRAW,
            access: BufferAccess::ReadWrite,
            mapped: false,
            map_offset: 0,
            map_length: 0,
            access_flags: 0,
        }
    }
}

/// The buffer objects of a share group, by name: `None` for a name `glGenBuffers` returned
/// that was never bound (not yet a buffer object, `glIsBuffer` is false).
#[derive(Debug, Default)]
pub struct BufferNames {
    objects: HashMap<GLuint, Option<BufferObject>>,
    next: GLuint,
}

/// A context's view of its share group's buffer objects (every context created sharing
/// objects with another holds the same `Arc`; the bindings stay per context).
#[derive(Clone, Debug, Default)]
pub struct Buffers {
    names: Arc<RwLock<BufferNames>>,
}

impl Buffers {
    /// The buffer objects (the share group's handle).
    pub(crate) fn names(&self) -> &Arc<RwLock<BufferNames>> {
        &self.names
    }

    /// Uses the buffer objects of a share group (for a new context).
    pub(crate) fn set_names(&mut self, names: Arc<RwLock<BufferNames>>) {
        self.names = names;
    }

    /// Recursive, so that a context may hold two reads at once whatever other threads wait
    /// for; writes come from `&mut` borrows, exclusive within the context.
    fn read(&self) -> RwLockReadGuard<'_, BufferNames> {
        self.names.read_recursive()
    }

    fn write(&mut self) -> RwLockWriteGuard<'_, BufferNames> {
        self.names.write()
    }
}

/// One entry of the client attribute stack.
#[derive(Clone, Debug)]
struct ClientAttribEntry {
    /// Pack and unpack modes with the pixel pack and unpack buffer bindings (issue 7 of
    /// ARB_pixel_buffer_object: they are pixel-store client state).
    pixel_store: Option<(PixelStore, PixelStore, [GLuint; 2])>,
    arrays: Option<(Box<ArrayState>, usize)>,
}

/// Everything of this module the context holds.
#[derive(Clone, Debug, Default)]
pub struct ClientState {
    pub arrays: ArrayState,
    pub buffers: Buffers,
    /// `GL_PIXEL_PACK_BUFFER_BINDING` and `GL_PIXEL_UNPACK_BUFFER_BINDING`
    /// (ARB_pixel_buffer_object).
    pub pixel_buffers: [GLuint; 2],
    stack: Vec<ClientAttribEntry>,
    /// `glLockArraysEXT` range (first, count), if locked.
    locked: Option<(GLint, GLsizei)>,
}

/// One array element, converted to the values the immediate-mode calls would set.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct ArrayVertex {
    edge_flag: bool,
    index: f32,
    tex: [Vec4; MAX_TEXTURE_UNITS],
    normal: Vec3,
    color: Vec4,
    secondary_color: Vec4,
    fog_coord: f32,
    position: Vec4,
}

/// Which arrays were enabled when the elements were fetched.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Present {
    edge_flag: bool,
    index: bool,
    tex: [bool; MAX_TEXTURE_UNITS],
    normal: bool,
    color: bool,
    secondary_color: bool,
    fog_coord: bool,
    vertex: bool,
}

/// Fetched array elements, ready to be applied in order.
#[derive(Clone, Debug, Default)]
pub(crate) struct Fetched {
    present: Present,
    vertices: Vec<ArrayVertex>,
}

/// A component of type `ty` at `off` as a float: normalized per table 2.6 when `normalize`
/// (colours and normals), else converted as the immediate-mode calls convert their arguments.
/// Bytes past the end of `b` read as zero.
fn component(b: &[u8], off: usize, ty: ArrayType, normalize: bool) -> f32 {
    let n = ty.size();
    let Some(s) = off.checked_add(n).and_then(|end| b.get(off..end)) else {
        return 0.0;
    };
    let mut x = [0u8; 8];
    x[..n].copy_from_slice(s);
    use ArrayType::*;
    match (ty, normalize) {
        (Byte, true) => norm_i8(x[0] as i8),
        (Byte, false) => x[0] as i8 as f32,
        (UnsignedByte, true) => norm_u8(x[0]),
        (UnsignedByte, false) => x[0] as f32,
        (Short, true) => norm_i16(i16::from_ne_bytes([x[0], x[1]])),
        (Short, false) => i16::from_ne_bytes([x[0], x[1]]) as f32,
        (UnsignedShort, true) => norm_u16(u16::from_ne_bytes([x[0], x[1]])),
        (UnsignedShort, false) => u16::from_ne_bytes([x[0], x[1]]) as f32,
        (Int, true) => norm_i32(i32::from_ne_bytes([x[0], x[1], x[2], x[3]])),
        (Int, false) => i32::from_ne_bytes([x[0], x[1], x[2], x[3]]) as f32,
        (UnsignedInt, true) => norm_u32(u32::from_ne_bytes([x[0], x[1], x[2], x[3]])),
        (UnsignedInt, false) => u32::from_ne_bytes([x[0], x[1], x[2], x[3]]) as f32,
        (Float, _) => f32::from_ne_bytes([x[0], x[1], x[2], x[3]]),
        (Double, _) => f64::from_ne_bytes(x) as f32,
    }
}

/// Element `i` of array `a` (whose first element starts at `b[0]`) as a vector with the
/// defaults of the immediate-mode calls for missing components.
fn element(b: &[u8], a: &ArrayPointer, i: u32, normalize: bool, default: Vec4) -> Vec4 {
    let base = (i as usize).saturating_mul(a.effective_stride());
    let mut v = default.to_array();
    for (c, out) in v.iter_mut().enumerate().take(a.components()) {
        *out = component(b, base.saturating_add(c * a.ty.size()), a.ty, normalize);
    }
    if a.size == GL_BGRA as i32 {
        // Stored blue, green, red, alpha.
        v.swap(0, 2);
    }
    Vec4::from_array(v)
}

fn index_value(b: &[u8], i: usize, ty: IndexType) -> u32 {
    let n = ty.size();
    let Some(s) = b.get(i * n..(i + 1) * n) else {
        return 0;
    };
    match ty {
        IndexType::UnsignedByte => s[0] as u32,
        IndexType::UnsignedShort => u16::from_ne_bytes([s[0], s[1]]) as u32,
        IndexType::UnsignedInt => u32::from_ne_bytes([s[0], s[1], s[2], s[3]]),
    }
}

impl Context {
    // ----- queries

    /// The value of a vertex-array, buffer-binding or display-list query.
    pub(crate) fn array_state_value(&self, q: ArrayQuery) -> StateValue {
        use StateValue::*;
        let int1 = |i: i64| Ints(vec![i]);
        match q {
            ArrayQuery::Enabled(a) => Bools(vec![self.client_array(a).enabled]),
            ArrayQuery::Size(a) => int1(self.client_array(a).size as i64),
            ArrayQuery::Type(a) => Enum(self.client_array(a).ty.to_gl()),
            ArrayQuery::Stride(a) => int1(self.client_array(a).stride as i64),
            ArrayQuery::Count(a) => int1(self.client_array(a).count as i64),
            ArrayQuery::BufferBinding(a) => int1(self.client_array(a).buffer as i64),
            ArrayQuery::ArrayBufferBinding => int1(self.client.arrays.array_buffer as i64),
            ArrayQuery::ElementArrayBufferBinding => {
                int1(self.client.arrays.element_array_buffer as i64)
            }
            ArrayQuery::PixelPackBufferBinding => int1(self.client.pixel_buffers[0] as i64),
            ArrayQuery::PixelUnpackBufferBinding => int1(self.client.pixel_buffers[1] as i64),
            ArrayQuery::MaxElementsVertices | ArrayQuery::MaxElementsIndices => int1(MAX_ELEMENTS),
            ArrayQuery::ClientAttribStackDepth => int1(self.client.stack.len() as i64),
            ArrayQuery::MaxClientAttribStackDepth => int1(MAX_CLIENT_ATTRIB_STACK_DEPTH as i64),
            ArrayQuery::ListBase => int1(self.lists.base() as i64),
            ArrayQuery::ListIndex => int1(self.lists.index() as i64),
            ArrayQuery::ListMode => Enum(self.lists.mode()),
            ArrayQuery::MaxListNesting => int1(super::lists::MAX_LIST_NESTING as i64),
            ArrayQuery::LockFirst => int1(self.client.locked.map_or(0, |l| l.0 as i64)),
            ArrayQuery::LockCount => int1(self.client.locked.map_or(0, |l| l.1 as i64)),
        }
    }
}

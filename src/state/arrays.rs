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
//! client memory, read through `capi::client_memory` under the GL client-array contract.
//! Elements beyond the end of a buffer object read as zeros; a null client pointer reads as
//! zeros.

use std::collections::HashMap;

use glam::{Vec3, Vec4};

use super::tables::PixelStore;
use super::Context;
use crate::api::convert::{
    self, ArrayQuery, ArrayType, BufferAccess, BufferParam, BufferTarget, ClientArray, IndexType,
    InterleavedFormat,
};
use crate::api::enums::*;
use crate::capi::client_memory;
use crate::state::get::StateValue;
use crate::state::tables::limits::MAX_TEXTURE_UNITS;
use crate::vertex::immediate::{norm_i16, norm_i32, norm_i8, norm_u16, norm_u32, norm_u8};

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
        }
    }

    fn element_bytes(&self) -> usize {
        self.size as usize * self.ty.size()
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
}

impl Default for BufferObject {
    fn default() -> Self {
        BufferObject {
            data: Vec::new(),
            usage: GL_STATIC_DRAW,
            access: BufferAccess::ReadWrite,
            mapped: false,
        }
    }
}

/// Buffer objects by name: `None` for a name `glGenBuffers` returned that was never bound
/// (not yet a buffer object, `glIsBuffer` is false).
#[derive(Clone, Debug, Default)]
pub struct Buffers {
    objects: HashMap<GLuint, Option<BufferObject>>,
    next: GLuint,
}

/// One entry of the client attribute stack.
#[derive(Clone, Debug)]
struct ClientAttribEntry {
    pixel_store: Option<(PixelStore, PixelStore)>,
    arrays: Option<(Box<ArrayState>, usize)>,
}

/// Everything of this module the context holds.
#[derive(Clone, Debug, Default)]
pub struct ClientState {
    pub arrays: ArrayState,
    pub buffers: Buffers,
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
    for (c, out) in v.iter_mut().enumerate().take(a.size as usize) {
        *out = component(b, base.saturating_add(c * a.ty.size()), a.ty, normalize);
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
    // ----- array pointers

    fn client_array_mut(&mut self, a: ClientArray) -> &mut ArrayPointer {
        let s = &mut self.client.arrays;
        match a {
            ClientArray::Vertex => &mut s.vertex,
            ClientArray::Normal => &mut s.normal,
            ClientArray::Color => &mut s.color,
            ClientArray::SecondaryColor => &mut s.secondary_color,
            ClientArray::FogCoord => &mut s.fog_coord,
            ClientArray::TexCoord => &mut s.tex_coord[self.client_active_texture],
            ClientArray::EdgeFlag => &mut s.edge_flag,
            ClientArray::Index => &mut s.index,
        }
    }

    fn client_array(&self, a: ClientArray) -> &ArrayPointer {
        let s = &self.client.arrays;
        match a {
            ClientArray::Vertex => &s.vertex,
            ClientArray::Normal => &s.normal,
            ClientArray::Color => &s.color,
            ClientArray::SecondaryColor => &s.secondary_color,
            ClientArray::FogCoord => &s.fog_coord,
            ClientArray::TexCoord => &s.tex_coord[self.client_active_texture],
            ClientArray::EdgeFlag => &s.edge_flag,
            ClientArray::Index => &s.index,
        }
    }

    /// The common part of the `gl*Pointer` calls: `sizes` and `types` are what the call
    /// accepts (INVALID_VALUE / INVALID_ENUM otherwise), a negative stride is INVALID_VALUE.
    fn set_pointer(
        &mut self,
        a: ClientArray,
        size: GLint,
        sizes: &[GLint],
        type_: GLenum,
        types: &[ArrayType],
        stride: GLsizei,
        pointer: ClientPtr,
    ) {
        let ty = convert::array_type(type_).filter(|t| types.contains(t));
        if !sizes.contains(&size) {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let Some(ty) = ty else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if stride < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let buffer = self.client.arrays.array_buffer;
        let p = self.client_array_mut(a);
        p.size = size;
        p.ty = ty;
        p.stride = stride;
        p.pointer = pointer;
        p.buffer = buffer;
    }

    pub(crate) fn vertex_pointer(
        &mut self,
        size: GLint,
        type_: GLenum,
        stride: GLsizei,
        pointer: ClientPtr,
    ) {
        use ArrayType::*;
        let types = [Short, Int, Float, Double];
        self.set_pointer(
            ClientArray::Vertex,
            size,
            &[2, 3, 4],
            type_,
            &types,
            stride,
            pointer,
        );
    }

    pub(crate) fn normal_pointer(&mut self, type_: GLenum, stride: GLsizei, pointer: ClientPtr) {
        use ArrayType::*;
        let types = [Byte, Short, Int, Float, Double];
        self.set_pointer(ClientArray::Normal, 3, &[3], type_, &types, stride, pointer);
    }

    pub(crate) fn color_pointer(
        &mut self,
        size: GLint,
        type_: GLenum,
        stride: GLsizei,
        pointer: ClientPtr,
    ) {
        let types = ArrayType::ALL;
        self.set_pointer(
            ClientArray::Color,
            size,
            &[3, 4],
            type_,
            &types,
            stride,
            pointer,
        );
    }

    pub(crate) fn secondary_color_pointer(
        &mut self,
        size: GLint,
        type_: GLenum,
        stride: GLsizei,
        pointer: ClientPtr,
    ) {
        let types = ArrayType::ALL;
        self.set_pointer(
            ClientArray::SecondaryColor,
            size,
            &[3],
            type_,
            &types,
            stride,
            pointer,
        );
    }

    pub(crate) fn fog_coord_pointer(&mut self, type_: GLenum, stride: GLsizei, pointer: ClientPtr) {
        use ArrayType::*;
        self.set_pointer(
            ClientArray::FogCoord,
            1,
            &[1],
            type_,
            &[Float, Double],
            stride,
            pointer,
        );
    }

    pub(crate) fn tex_coord_pointer(
        &mut self,
        size: GLint,
        type_: GLenum,
        stride: GLsizei,
        pointer: ClientPtr,
    ) {
        use ArrayType::*;
        let types = [Short, Int, Float, Double];
        self.set_pointer(
            ClientArray::TexCoord,
            size,
            &[1, 2, 3, 4],
            type_,
            &types,
            stride,
            pointer,
        );
    }

    pub(crate) fn index_pointer(&mut self, type_: GLenum, stride: GLsizei, pointer: ClientPtr) {
        use ArrayType::*;
        let types = [UnsignedByte, Short, Int, Float, Double];
        self.set_pointer(ClientArray::Index, 1, &[1], type_, &types, stride, pointer);
    }

    pub(crate) fn edge_flag_pointer(&mut self, stride: GLsizei, pointer: ClientPtr) {
        if stride < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let buffer = self.client.arrays.array_buffer;
        let p = &mut self.client.arrays.edge_flag;
        p.stride = stride;
        p.pointer = pointer;
        p.buffer = buffer;
    }

    /// `glInterleavedArrays` (section 2.8, table 2.5).
    pub(crate) fn interleaved_arrays(
        &mut self,
        format: GLenum,
        stride: GLsizei,
        pointer: ClientPtr,
    ) {
        let Some(fmt) = convert::interleaved_format(format) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if stride < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        use InterleavedFormat::*;
        const F: usize = 4;
        // c: four unsigned bytes, rounded up to a multiple of f (= f).
        const C: usize = 4;
        // (texture size, colour (size, ubyte), normal, vertex size, pc, pn, pv, s)
        let (st, col, en, sv, pc, pn, pv, s): InterleavedLayout = match fmt {
            V2f => (0, None, false, 2, 0, 0, 0, 2 * F),
            V3f => (0, None, false, 3, 0, 0, 0, 3 * F),
            C4ubV2f => (0, Some((4, true)), false, 2, 0, 0, C, C + 2 * F),
            C4ubV3f => (0, Some((4, true)), false, 3, 0, 0, C, C + 3 * F),
            C3fV3f => (0, Some((3, false)), false, 3, 0, 0, 3 * F, 6 * F),
            N3fV3f => (0, None, true, 3, 0, 0, 3 * F, 6 * F),
            C4fN3fV3f => (0, Some((4, false)), true, 3, 0, 4 * F, 7 * F, 10 * F),
            T2fV3f => (2, None, false, 3, 0, 0, 2 * F, 5 * F),
            T4fV4f => (4, None, false, 4, 0, 0, 4 * F, 8 * F),
            T2fC4ubV3f => (2, Some((4, true)), false, 3, 2 * F, 0, C + 2 * F, C + 5 * F),
            T2fC3fV3f => (2, Some((3, false)), false, 3, 2 * F, 0, 5 * F, 8 * F),
            T2fN3fV3f => (2, None, true, 3, 0, 2 * F, 5 * F, 8 * F),
            T2fC4fN3fV3f => (2, Some((4, false)), true, 3, 2 * F, 6 * F, 9 * F, 12 * F),
            T4fC4fN3fV4f => (4, Some((4, false)), true, 4, 4 * F, 8 * F, 11 * F, 15 * F),
        };
        let stride = if stride == 0 { s as i32 } else { stride };
        let at = |off: usize| ClientPtr(pointer.0.wrapping_add(off));
        let buffer = self.client.arrays.array_buffer;
        let set =
            |p: &mut ArrayPointer, enabled: bool, size: i32, ty: ArrayType, ptr: ClientPtr| {
                p.enabled = enabled;
                if enabled {
                    *p = ArrayPointer {
                        enabled,
                        size,
                        ty,
                        stride,
                        pointer: ptr,
                        buffer,
                    };
                }
            };
        let unit = self.client_active_texture;
        let a = &mut self.client.arrays;
        a.edge_flag.enabled = false;
        a.index.enabled = false;
        a.secondary_color.enabled = false;
        a.fog_coord.enabled = false;
        set(&mut a.tex_coord[unit], st > 0, st, ArrayType::Float, at(0));
        match col {
            Some((size, ub)) => {
                let ty = if ub {
                    ArrayType::UnsignedByte
                } else {
                    ArrayType::Float
                };
                set(&mut a.color, true, size, ty, at(pc));
            }
            None => a.color.enabled = false,
        }
        set(&mut a.normal, en, 3, ArrayType::Float, at(pn));
        set(&mut a.vertex, true, sv, ArrayType::Float, at(pv));
    }

    pub(crate) fn enable_client_state(&mut self, array: GLenum) {
        self.set_client_state(array, true);
    }

    pub(crate) fn disable_client_state(&mut self, array: GLenum) {
        self.set_client_state(array, false);
    }

    fn set_client_state(&mut self, array: GLenum, on: bool) {
        let Some(a) = convert::client_array(array) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.client_array_mut(a).enabled = on;
    }

    /// `glIsEnabled` of a client array (`None` for other names).
    pub(crate) fn client_array_enabled(&self, cap: GLenum) -> Option<bool> {
        convert::client_array(cap).map(|a| self.client_array(a).enabled)
    }

    /// The pointer of a vertex array (`GL_*_ARRAY_POINTER`), the safe form of `glGetPointerv`.
    /// The texture-coordinate array is that of the client active texture unit.
    pub fn array_pointer(&self, pname: GLenum) -> Option<ClientPtr> {
        convert::pointer_name(pname).map(|a| self.client_array(a).pointer)
    }

    pub(crate) fn get_pointerv(&mut self, pname: GLenum, params: ClientPtr) {
        let Some(p) = self
            .array_pointer(pname)
            .or_else(|| self.select_buffer_pointer(pname))
        else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        client_memory::store_pointer(params, p.0);
    }

    // ----- fetching and drawing

    /// The bytes of array `a` from element `min` on, covering elements `min..=max`, given to
    /// `f` (buffer contents or client memory; element `i` starts at `(i - min) * stride`).
    /// Client memory outside the elements the draw uses is never touched.
    fn with_array_bytes<R>(
        &self,
        a: &ArrayPointer,
        (min, max): (u32, u32),
        f: impl FnOnce(&[u8]) -> R,
    ) -> R {
        let start = (min as usize).saturating_mul(a.effective_stride());
        if a.buffer != 0 {
            let data = self
                .client
                .buffers
                .objects
                .get(&a.buffer)
                .and_then(|b| b.as_ref())
                .map_or(&[][..], |b| &b.data[..]);
            let from = a.pointer.0.saturating_add(start);
            return f(data.get(from..).unwrap_or(&[]));
        }
        let len = ((max - min) as usize)
            .saturating_mul(a.effective_stride())
            .saturating_add(a.element_bytes());
        client_memory::with_client_bytes_from(a.pointer, start, len, f)
    }

    fn buffer_mapped(&self, name: GLuint) -> bool {
        name != 0
            && matches!(
                self.client.buffers.objects.get(&name),
                Some(Some(BufferObject { mapped: true, .. }))
            )
    }

    /// The enabled arrays that draws read, with any mapped source (INVALID_OPERATION).
    fn enabled_arrays(&self) -> Result<Present, GLenum> {
        let s = &self.client.arrays;
        let mut p = Present {
            edge_flag: s.edge_flag.enabled,
            index: s.index.enabled,
            normal: s.normal.enabled,
            color: s.color.enabled,
            secondary_color: s.secondary_color.enabled,
            fog_coord: s.fog_coord.enabled,
            vertex: s.vertex.enabled,
            ..Present::default()
        };
        for u in 0..MAX_TEXTURE_UNITS {
            p.tex[u] = s.tex_coord[u].enabled;
        }
        let all = [
            &s.edge_flag,
            &s.index,
            &s.normal,
            &s.color,
            &s.secondary_color,
            &s.fog_coord,
            &s.vertex,
        ];
        let mapped = all
            .into_iter()
            .chain(s.tex_coord.iter())
            .any(|a| a.enabled && self.buffer_mapped(a.buffer));
        if mapped {
            return Err(GL_INVALID_OPERATION);
        }
        Ok(p)
    }

    /// Fetches the elements `indices` of every enabled array.
    pub(crate) fn fetch_elements(&self, indices: &[u32]) -> Result<Fetched, GLenum> {
        let present = self.enabled_arrays()?;
        let mut vertices = Vec::new();
        vertices
            .try_reserve_exact(indices.len())
            .map_err(|_| GL_OUT_OF_MEMORY)?;
        vertices.resize(indices.len(), ArrayVertex::default());
        let max = indices.iter().copied().max().unwrap_or(0);
        let min = indices.iter().copied().min().unwrap_or(0);
        let s = &self.client.arrays;
        type Put = fn(&mut ArrayVertex, Vec4);
        let mut jobs: Vec<(&ArrayPointer, bool, Vec4, Put)> = Vec::new();
        let zero1 = Vec4::new(0.0, 0.0, 0.0, 1.0);
        if present.edge_flag {
            jobs.push((&s.edge_flag, false, Vec4::ZERO, |v, x| {
                v.edge_flag = x.x != 0.0
            }));
        }
        if present.index {
            // glIndex: the value as is (no normalization).
            jobs.push((&s.index, false, Vec4::ZERO, |v, x| v.index = x.x));
        }
        if present.normal {
            jobs.push((&s.normal, true, Vec4::ZERO, |v, x| v.normal = x.truncate()));
        }
        if present.color {
            jobs.push((&s.color, true, Vec4::ONE, |v, x| v.color = x));
        }
        if present.secondary_color {
            // glSecondaryColor3 sets alpha 0 (as the immediate-mode calls do).
            jobs.push((&s.secondary_color, true, Vec4::ZERO, |v, x| {
                v.secondary_color = x
            }));
        }
        if present.fog_coord {
            jobs.push((&s.fog_coord, false, Vec4::ZERO, |v, x| v.fog_coord = x.x));
        }
        if present.vertex {
            jobs.push((&s.vertex, false, zero1, |v, x| v.position = x));
        }
        for (a, normalize, default, put) in jobs {
            self.with_array_bytes(a, (min, max), |b| {
                for (v, &i) in vertices.iter_mut().zip(indices) {
                    put(v, element(b, a, i - min, normalize, default));
                }
            });
        }
        for u in 0..MAX_TEXTURE_UNITS {
            if present.tex[u] {
                let a = &s.tex_coord[u];
                self.with_array_bytes(a, (min, max), |b| {
                    for (v, &i) in vertices.iter_mut().zip(indices) {
                        v.tex[u] = element(b, a, i - min, false, zero1);
                    }
                });
            }
        }
        Ok(Fetched { present, vertices })
    }

    /// `glArrayElement` for one fetched element: the current-value calls, then `glVertex`.
    fn apply_element(&mut self, p: &Present, v: &ArrayVertex) {
        if p.edge_flag {
            self.current.edge_flag = v.edge_flag;
        }
        if p.index {
            self.current.index = v.index;
        }
        for u in 0..MAX_TEXTURE_UNITS {
            if p.tex[u] {
                self.current.texcoords[u] = v.tex[u];
            }
        }
        if p.normal {
            self.current.normal = v.normal;
        }
        if p.color {
            self.set_color(v.color);
        }
        if p.secondary_color {
            self.current.secondary_color = v.secondary_color;
        }
        if p.fog_coord {
            self.current.fog_coord = v.fog_coord;
        }
        if p.vertex {
            self.vertex4(v.position);
        }
    }

    /// `glBegin(mode)`, the fetched elements, `glEnd` (mode already validated), leaving the
    /// current values as they were ([`Context::keep_current_values`]).
    fn draw_fetched(&mut self, mode: GLenum, f: &Fetched) {
        if self.reject_inside_begin_end() {
            return;
        }
        let saved = self.save_current_values(&f.present);
        self.begin(mode);
        for v in &f.vertices {
            self.apply_element(&f.present, v);
        }
        self.end();
        self.keep_current_values(saved);
    }

    /// What [`Context::keep_current_values`] restores: the current values and, when a colour
    /// array drives `GL_COLOR_MATERIAL`, the materials.
    fn save_current_values(&self, p: &Present) -> SavedCurrent {
        SavedCurrent {
            current: self.current,
            materials: (p.color && self.lighting.color_material).then_some(self.lighting.materials),
        }
    }

    /// After `glDrawArrays`, `glDrawElements` and the like the specification leaves each
    /// current value whose array is enabled indeterminate (section 2.8); Mesa leaves them, and
    /// the materials `GL_COLOR_MATERIAL` tracks, as they were before the draw (also when the
    /// draw is replayed from a display list), while `glArrayElement` sets them as the
    /// immediate-mode calls do. tilegl does the same, so a program that draws lit lines with
    /// the current normal after drawing a mesh from arrays lights them as Mesa does
    /// (xss-vigilance).
    fn keep_current_values(&mut self, saved: SavedCurrent) {
        self.current = saved.current;
        if let Some(m) = saved.materials {
            if self.lighting.materials != m {
                self.lighting.materials = m;
                self.invalidate();
            }
        }
    }

    /// Draws (or, while compiling a list, records) the elements `indices`.
    fn draw_indices(&mut self, mode: GLenum, indices: &[u32]) {
        if self.list_recording() {
            let f = match self.fetch_elements(indices) {
                Ok(f) => f,
                Err(e) => return self.list_aware_error(e),
            };
            let g = f.clone();
            self.list_record(Box::new(move |ctx: &mut Context| {
                ctx.draw_fetched(mode, &g)
            }));
            if !self.list_compile_only() {
                self.draw_fetched(mode, &f);
            }
            return;
        }
        // Executed directly: fetched and applied in chunks, so a large draw needs no second
        // full-size copy of its vertices next to the glBegin/glEnd batch.
        if let Err(e) = self.enabled_arrays() {
            return self.record_error(e);
        }
        if self.reject_inside_begin_end() {
            return;
        }
        const CHUNK: usize = 4096;
        let mut saved = None;
        self.begin(mode);
        for chunk in indices.chunks(CHUNK) {
            match self.fetch_elements(chunk) {
                Ok(f) => {
                    if saved.is_none() {
                        saved = Some(self.save_current_values(&f.present));
                    }
                    for v in &f.vertices {
                        self.apply_element(&f.present, v);
                    }
                }
                Err(e) => {
                    self.record_error(e);
                    break;
                }
            }
        }
        self.end();
        if let Some(saved) = saved {
            self.keep_current_values(saved);
        }
    }

    pub(crate) fn array_element(&mut self, i: GLint) {
        if i < 0 {
            return;
        }
        let f = match self.fetch_elements(&[i as u32]) {
            Ok(f) => f,
            Err(e) => return self.list_aware_error(e),
        };
        let apply = move |ctx: &mut Context| {
            if let Some(v) = f.vertices.first() {
                ctx.apply_element(&f.present, v);
            }
        };
        if self.list_recording() {
            let apply = apply.clone();
            self.list_record(Box::new(apply));
            if self.list_compile_only() {
                return;
            }
        }
        apply(self);
    }

    /// Validates a draw's mode and count (INVALID_ENUM, INVALID_VALUE).
    fn check_draw(&mut self, mode: GLenum, count: GLsizei) -> bool {
        if convert::primitive_mode(mode).is_none() {
            self.list_aware_error(GL_INVALID_ENUM);
            return false;
        }
        if count < 0 {
            self.list_aware_error(GL_INVALID_VALUE);
            return false;
        }
        true
    }

    pub(crate) fn draw_arrays(&mut self, mode: GLenum, first: GLint, count: GLsizei) {
        if !self.check_draw(mode, count) {
            return;
        }
        if first < 0 {
            self.list_aware_error(GL_INVALID_VALUE);
            return;
        }
        let Some(last) = (first as u64)
            .checked_add(count as u64)
            .filter(|&e| e <= u32::MAX as u64)
        else {
            self.list_aware_error(GL_INVALID_VALUE);
            return;
        };
        // Elements past the end of an enabled array's buffer object have no data (section
        // 2.9 leaves reading them undefined): the draw stops there, so a huge count over a
        // small buffer costs nothing.
        let last = last.min(self.buffer_backed_elements().max(first as u64));
        let mut indices = Vec::new();
        if indices
            .try_reserve_exact((last - first as u64) as usize)
            .is_err()
        {
            return self.list_aware_error(GL_OUT_OF_MEMORY);
        }
        indices.extend(first as u32..last as u32);
        self.draw_indices(mode, &indices);
    }

    /// How many elements every enabled array sourced from a buffer object holds completely
    /// (`u64::MAX` when none is).
    fn buffer_backed_elements(&self) -> u64 {
        let a = &self.client.arrays;
        [
            &a.vertex,
            &a.normal,
            &a.color,
            &a.secondary_color,
            &a.fog_coord,
            &a.edge_flag,
            &a.index,
        ]
        .into_iter()
        .chain(a.tex_coord.iter())
        .filter(|p| p.enabled && p.buffer != 0)
        .map(|p| {
            let len = self
                .client
                .buffers
                .objects
                .get(&p.buffer)
                .and_then(|b| b.as_ref())
                .map_or(0, |b| b.data.len());
            let (start, elem) = (p.pointer.0, p.element_bytes());
            match len.checked_sub(start).and_then(|r| r.checked_sub(elem)) {
                Some(rest) => (rest / p.effective_stride().max(1)) as u64 + 1,
                None => 0,
            }
        })
        .min()
        .unwrap_or(u64::MAX)
    }

    /// The indices of a `glDrawElements`-style call: from the element array buffer (then
    /// `indices` is an offset) or client memory.
    fn read_indices(
        &mut self,
        count: usize,
        ty: IndexType,
        indices: ClientPtr,
    ) -> Result<Vec<u32>, GLenum> {
        let eab = self.client.arrays.element_array_buffer;
        if self.buffer_mapped(eab) {
            return Err(GL_INVALID_OPERATION);
        }
        let mut out = Vec::new();
        out.try_reserve_exact(count).map_err(|_| GL_OUT_OF_MEMORY)?;
        let fill = |b: &[u8], out: &mut Vec<u32>| {
            out.extend((0..count).map(|i| index_value(b, i, ty)));
        };
        if eab != 0 {
            let data = self
                .client
                .buffers
                .objects
                .get(&eab)
                .and_then(|b| b.as_ref())
                .map_or(&[][..], |b| &b.data[..]);
            fill(data.get(indices.0..).unwrap_or(&[]), &mut out);
        } else {
            let len = count.saturating_mul(ty.size());
            client_memory::with_client_bytes(indices, len, |b| fill(b, &mut out));
        }
        Ok(out)
    }

    fn draw_elements_checked(
        &mut self,
        mode: GLenum,
        count: GLsizei,
        type_: GLenum,
        indices: ClientPtr,
    ) {
        if !self.check_draw(mode, count) {
            return;
        }
        let Some(ty) = convert::index_type(type_) else {
            return self.list_aware_error(GL_INVALID_ENUM);
        };
        match self.read_indices(count as usize, ty, indices) {
            Ok(idx) => self.draw_indices(mode, &idx),
            Err(e) => self.list_aware_error(e),
        }
    }

    pub(crate) fn draw_elements(
        &mut self,
        mode: GLenum,
        count: GLsizei,
        type_: GLenum,
        indices: ClientPtr,
    ) {
        self.draw_elements_checked(mode, count, type_, indices);
    }

    pub(crate) fn draw_range_elements(
        &mut self,
        mode: GLenum,
        start: GLuint,
        end: GLuint,
        count: GLsizei,
        type_: GLenum,
        indices: ClientPtr,
    ) {
        if end < start {
            return self.list_aware_error(GL_INVALID_VALUE);
        }
        // Indices outside [start, end] are allowed to give undefined results; tilegl draws them.
        self.draw_elements_checked(mode, count, type_, indices);
    }

    pub(crate) fn multi_draw_arrays(
        &mut self,
        mode: GLenum,
        first: &[GLint],
        count: &[GLsizei],
        drawcount: GLsizei,
    ) {
        if drawcount < 0 || first.len() < drawcount as usize || count.len() < drawcount as usize {
            return self.list_aware_error(GL_INVALID_VALUE);
        }
        let n = drawcount as usize;
        // The checks of glDrawArrays, made once for all draws.
        if convert::primitive_mode(mode).is_none() {
            return self.list_aware_error(GL_INVALID_ENUM);
        }
        if count[..n].iter().chain(&first[..n]).any(|&c| c < 0) {
            return self.list_aware_error(GL_INVALID_VALUE);
        }
        for i in 0..n {
            if count[i] > 0 {
                self.draw_arrays(mode, first[i], count[i]);
            }
        }
    }

    pub(crate) fn multi_draw_elements(
        &mut self,
        mode: GLenum,
        count: &[GLsizei],
        type_: GLenum,
        indices: ClientPtr,
        drawcount: GLsizei,
    ) {
        if drawcount < 0 || count.len() < drawcount as usize {
            return self.list_aware_error(GL_INVALID_VALUE);
        }
        if convert::primitive_mode(mode).is_none() || convert::index_type(type_).is_none() {
            return self.list_aware_error(GL_INVALID_ENUM);
        }
        if count[..drawcount as usize].iter().any(|&c| c < 0) {
            return self.list_aware_error(GL_INVALID_VALUE);
        }
        // `indices` is a client array of `drawcount` pointers (offsets when an element array
        // buffer is bound).
        let n = drawcount as usize;
        let ptrs: Vec<usize> = client_memory::with_client_bytes(
            indices,
            n.saturating_mul(std::mem::size_of::<usize>()),
            |b| {
                b.chunks_exact(std::mem::size_of::<usize>())
                    .map(|c| usize::from_ne_bytes(c.try_into().unwrap_or_default()))
                    .collect()
            },
        );
        for i in 0..n {
            let p = ptrs.get(i).copied().unwrap_or(0);
            if count[i] > 0 {
                self.draw_elements_checked(mode, count[i], type_, ClientPtr(p));
            }
        }
    }

    // ----- buffer objects

    fn bound_buffer_name(&self, target: BufferTarget) -> GLuint {
        match target {
            BufferTarget::Array => self.client.arrays.array_buffer,
            BufferTarget::ElementArray => self.client.arrays.element_array_buffer,
        }
    }

    /// The buffer object bound to `target` (INVALID_ENUM for a bad target, INVALID_OPERATION
    /// when 0 is bound).
    fn bound_buffer(&mut self, target: GLenum) -> Result<&mut BufferObject, GLenum> {
        let t = convert::buffer_target(target).ok_or(GL_INVALID_ENUM)?;
        let name = self.bound_buffer_name(t);
        if name == 0 {
            return Err(GL_INVALID_OPERATION);
        }
        self.client
            .buffers
            .objects
            .get_mut(&name)
            .and_then(|b| b.as_mut())
            .ok_or(GL_INVALID_OPERATION)
    }

    pub(crate) fn gen_buffers(&mut self, n: GLsizei, buffers: &mut [GLuint]) {
        if n < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let b = &mut self.client.buffers;
        for out in buffers.iter_mut().take(n as usize) {
            loop {
                b.next = b.next.wrapping_add(1);
                if b.next != 0 && !b.objects.contains_key(&b.next) {
                    break;
                }
            }
            b.objects.insert(b.next, None);
            *out = b.next;
        }
    }

    pub(crate) fn bind_buffer(&mut self, target: GLenum, buffer: GLuint) {
        let Some(t) = convert::buffer_target(target) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if buffer != 0 {
            // glGenBuffers continues above names bound without being generated.
            self.client.buffers.next = self.client.buffers.next.max(buffer);
            let slot = self.client.buffers.objects.entry(buffer).or_insert(None);
            if slot.is_none() {
                *slot = Some(BufferObject::default());
            }
        }
        let a = &mut self.client.arrays;
        match t {
            BufferTarget::Array => a.array_buffer = buffer,
            BufferTarget::ElementArray => a.element_array_buffer = buffer,
        }
    }

    pub(crate) fn delete_buffers(&mut self, n: GLsizei, buffers: &[GLuint]) {
        if n < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        for &name in buffers.iter().take(n as usize) {
            if name == 0 || self.client.buffers.objects.remove(&name).is_none() {
                continue;
            }
            // A deleted buffer is unbound from every binding point (section 2.9).
            let a = &mut self.client.arrays;
            for b in [&mut a.array_buffer, &mut a.element_array_buffer] {
                if *b == name {
                    *b = 0;
                }
            }
            for p in [
                &mut a.vertex,
                &mut a.normal,
                &mut a.color,
                &mut a.secondary_color,
                &mut a.fog_coord,
                &mut a.edge_flag,
                &mut a.index,
            ]
            .into_iter()
            .chain(a.tex_coord.iter_mut())
            {
                if p.buffer == name {
                    p.buffer = 0;
                }
            }
        }
    }

    pub(crate) fn is_buffer(&mut self, buffer: GLuint) -> GLboolean {
        matches!(self.client.buffers.objects.get(&buffer), Some(Some(_))) as GLboolean
    }

    pub(crate) fn buffer_data(
        &mut self,
        target: GLenum,
        size: GLsizeiptr,
        data: Option<&[u8]>,
        usage: GLenum,
    ) {
        if convert::buffer_target(target).is_none() {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        if size < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let Some(usage) = convert::buffer_usage(usage) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if data.is_some_and(|d| d.len() < size as usize) {
            // Safe callers must hand over as many bytes as they declare.
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let b = match self.bound_buffer(target) {
            Ok(b) => b,
            Err(e) => return self.record_error(e),
        };
        let mut store = Vec::new();
        if store.try_reserve_exact(size as usize).is_err() {
            self.record_error(GL_OUT_OF_MEMORY);
            return;
        }
        match data {
            Some(d) => store.extend_from_slice(&d[..size as usize]),
            None => store.resize(size as usize, 0),
        }
        // The old store goes (a mapping of it ends), the new one starts unmapped.
        *b = BufferObject {
            data: store,
            usage,
            access: BufferAccess::ReadWrite,
            mapped: false,
        };
    }

    /// The range `offset..offset + size` of the bound buffer, checked (INVALID_VALUE when out
    /// of the store, INVALID_OPERATION when mapped).
    fn buffer_range(
        &mut self,
        target: GLenum,
        offset: GLintptr,
        size: GLsizeiptr,
    ) -> Result<(&mut BufferObject, std::ops::Range<usize>), GLenum> {
        let b = self.bound_buffer(target)?;
        if offset < 0 || size < 0 || (offset as u64 + size as u64) > b.data.len() as u64 {
            return Err(GL_INVALID_VALUE);
        }
        if b.mapped {
            return Err(GL_INVALID_OPERATION);
        }
        Ok((b, offset as usize..(offset + size) as usize))
    }

    pub(crate) fn buffer_sub_data(
        &mut self,
        target: GLenum,
        offset: GLintptr,
        size: GLsizeiptr,
        data: Option<&[u8]>,
    ) {
        let (b, r) = match self.buffer_range(target, offset, size) {
            Ok(x) => x,
            Err(e) => return self.record_error(e),
        };
        let Some(d) = data else {
            return;
        };
        if d.len() < r.len() {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let n = r.len();
        b.data[r].copy_from_slice(&d[..n]);
    }

    pub(crate) fn get_buffer_sub_data(
        &mut self,
        target: GLenum,
        offset: GLintptr,
        size: GLsizeiptr,
        data: &mut [u8],
    ) {
        let (b, r) = match self.buffer_range(target, offset, size) {
            Ok(x) => x,
            Err(e) => return self.record_error(e),
        };
        if data.len() < r.len() {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let n = r.len();
        data[..n].copy_from_slice(&b.data[r]);
    }

    pub(crate) fn map_buffer(&mut self, target: GLenum, access: GLenum) -> ClientPtr {
        let Some(access) = convert::buffer_access(access) else {
            // The target is checked first (both are INVALID_ENUM anyway).
            self.record_error(GL_INVALID_ENUM);
            return ClientPtr(0);
        };
        let b = match self.bound_buffer(target) {
            Ok(b) => b,
            Err(e) => {
                self.record_error(e);
                return ClientPtr(0);
            }
        };
        if b.mapped {
            self.record_error(GL_INVALID_OPERATION);
            return ClientPtr(0);
        }
        b.mapped = true;
        b.access = access;
        // The store is not reallocated while mapped (every call that would is refused or ends
        // the mapping first), so the address stays valid until glUnmapBuffer.
        ClientPtr(b.data.as_mut_ptr() as usize)
    }

    /// The store of the buffer mapped on `target`, for Rust callers (the safe form of writing
    /// through the `glMapBuffer` pointer). `None` unless a buffer is bound there and mapped.
    pub fn mapped_buffer_mut(&mut self, target: GLenum) -> Option<&mut [u8]> {
        match self.bound_buffer(target) {
            Ok(b) if b.mapped => Some(&mut b.data[..]),
            _ => None,
        }
    }

    pub(crate) fn unmap_buffer(&mut self, target: GLenum) -> GLboolean {
        let b = match self.bound_buffer(target) {
            Ok(b) => b,
            Err(e) => {
                self.record_error(e);
                return GL_FALSE as GLboolean;
            }
        };
        if !b.mapped {
            self.record_error(GL_INVALID_OPERATION);
            return GL_FALSE as GLboolean;
        }
        b.mapped = false;
        GL_TRUE as GLboolean
    }

    pub(crate) fn get_buffer_parameteriv(
        &mut self,
        target: GLenum,
        pname: GLenum,
        params: &mut [GLint],
    ) {
        let Some(p) = convert::buffer_param(pname) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let b = match self.bound_buffer(target) {
            Ok(b) => b,
            Err(e) => return self.record_error(e),
        };
        let v = match p {
            BufferParam::Size => b.data.len().min(i32::MAX as usize) as GLint,
            BufferParam::Usage => b.usage as GLint,
            BufferParam::Access => b.access.to_gl() as GLint,
            BufferParam::Mapped => b.mapped as GLint,
        };
        match params.first_mut() {
            Some(out) => *out = v,
            None => self.record_error(GL_INVALID_VALUE),
        }
    }

    pub(crate) fn get_buffer_pointerv(&mut self, target: GLenum, pname: GLenum, params: ClientPtr) {
        if pname != GL_BUFFER_MAP_POINTER {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        let b = match self.bound_buffer(target) {
            Ok(b) => b,
            Err(e) => return self.record_error(e),
        };
        let p = if b.mapped {
            b.data.as_mut_ptr() as usize
        } else {
            0
        };
        client_memory::store_pointer(params, p);
    }

    // ----- EXT_compiled_vertex_array

    /// `glLockArraysEXT`: tilegl reads the arrays at every draw anyway, which the extension
    /// allows (locking only permits caching), so the lock is state and error checks only.
    pub(crate) fn lock_arrays_ext(&mut self, first: GLint, count: GLsizei) {
        if first < 0 || count <= 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        if self.client.locked.is_some() {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        self.client.locked = Some((first, count));
    }

    pub(crate) fn unlock_arrays_ext(&mut self) {
        if self.client.locked.take().is_none() {
            self.record_error(GL_INVALID_OPERATION);
        }
    }

    // ----- client attribute stack

    pub(crate) fn push_client_attrib(&mut self, mask: GLbitfield) {
        if self.client.stack.len() >= MAX_CLIENT_ATTRIB_STACK_DEPTH {
            self.record_error(GL_STACK_OVERFLOW);
            return;
        }
        let (pixel, arrays) = convert::client_attrib_mask(mask);
        let entry = ClientAttribEntry {
            pixel_store: pixel.then_some((self.pack, self.unpack)),
            arrays: arrays.then(|| {
                (
                    Box::new(self.client.arrays.clone()),
                    self.client_active_texture,
                )
            }),
        };
        self.client.stack.push(entry);
    }

    pub(crate) fn pop_client_attrib(&mut self) {
        let Some(e) = self.client.stack.pop() else {
            self.record_error(GL_STACK_UNDERFLOW);
            return;
        };
        if let Some((pack, unpack)) = e.pixel_store {
            self.pack = pack;
            self.unpack = unpack;
        }
        if let Some((arrays, unit)) = e.arrays {
            self.client.arrays = *arrays;
            self.client_active_texture = unit;
        }
    }

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
            ArrayQuery::BufferBinding(a) => int1(self.client_array(a).buffer as i64),
            ArrayQuery::ArrayBufferBinding => int1(self.client.arrays.array_buffer as i64),
            ArrayQuery::ElementArrayBufferBinding => {
                int1(self.client.arrays.element_array_buffer as i64)
            }
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

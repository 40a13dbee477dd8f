//! Array pointers (`gl*Pointer`, `glInterleavedArrays`), enabling arrays and `glGetPointerv`.

use super::*;

impl Context {
    pub(super) fn client_array_mut(&mut self, a: ClientArray) -> &mut ArrayPointer {
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

    pub(super) fn client_array(&self, a: ClientArray) -> &ArrayPointer {
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
    pub(super) fn set_pointer(
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

    /// `GL_BGRA` as the size of a colour array (ARB_vertex_array_bgra, Mesa offers it): only
    /// with `GL_UNSIGNED_BYTE`, INVALID_OPERATION otherwise. Whether the call may go on.
    fn bgra_type_ok(&mut self, size: GLint, type_: GLenum) -> bool {
        let ok = size != GL_BGRA as i32 || type_ == GL_UNSIGNED_BYTE;
        if !ok {
            self.record_error(GL_INVALID_OPERATION);
        }
        ok
    }

    pub(crate) fn color_pointer(
        &mut self,
        size: GLint,
        type_: GLenum,
        stride: GLsizei,
        pointer: ClientPtr,
    ) {
        if !self.bgra_type_ok(size, type_) {
            return;
        }
        let types = ArrayType::ALL;
        self.set_pointer(
            ClientArray::Color,
            size,
            &[3, 4, GL_BGRA as i32],
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
        if !self.bgra_type_ok(size, type_) {
            return;
        }
        let types = ArrayType::ALL;
        self.set_pointer(
            ClientArray::SecondaryColor,
            size,
            &[3, GL_BGRA as i32],
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
                        count: p.count,
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

    pub(crate) fn set_client_state(&mut self, array: GLenum, on: bool) {
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
        self.client_memory.store_pointer(params, p.0);
    }

    // ----- EXT_vertex_array's entry points

    /// A `gl*PointerEXT` call: `count` (the number of elements the program says are valid) is
    /// `GL_INVALID_VALUE` when negative, and recorded as `GL_*_ARRAY_COUNT_EXT` when `set`
    /// (the core call) succeeds.
    fn pointer_with_count(&mut self, a: ClientArray, count: GLsizei, set: impl FnOnce(&mut Self)) {
        if count < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        // Whether `set` fails: run it with the flag clear, then put back an unread earlier
        // error (the first error is the one GL keeps).
        let earlier = self.error.take();
        set(self);
        let failed = self.error.peek() != GL_NO_ERROR;
        if earlier != GL_NO_ERROR {
            self.error.take();
            self.error.record(earlier);
        }
        if !failed {
            self.client_array_mut(a).count = count;
        }
    }

    pub(crate) fn vertex_pointer_ext(
        &mut self,
        size: GLint,
        type_: GLenum,
        stride: GLsizei,
        count: GLsizei,
        pointer: ClientPtr,
    ) {
        self.pointer_with_count(ClientArray::Vertex, count, |c| {
            c.vertex_pointer(size, type_, stride, pointer)
        });
    }

    pub(crate) fn normal_pointer_ext(
        &mut self,
        type_: GLenum,
        stride: GLsizei,
        count: GLsizei,
        pointer: ClientPtr,
    ) {
        self.pointer_with_count(ClientArray::Normal, count, |c| {
            c.normal_pointer(type_, stride, pointer)
        });
    }

    pub(crate) fn color_pointer_ext(
        &mut self,
        size: GLint,
        type_: GLenum,
        stride: GLsizei,
        count: GLsizei,
        pointer: ClientPtr,
    ) {
        self.pointer_with_count(ClientArray::Color, count, |c| {
            c.color_pointer(size, type_, stride, pointer)
        });
    }

    pub(crate) fn index_pointer_ext(
        &mut self,
        type_: GLenum,
        stride: GLsizei,
        count: GLsizei,
        pointer: ClientPtr,
    ) {
        self.pointer_with_count(ClientArray::Index, count, |c| {
            c.index_pointer(type_, stride, pointer)
        });
    }

    pub(crate) fn tex_coord_pointer_ext(
        &mut self,
        size: GLint,
        type_: GLenum,
        stride: GLsizei,
        count: GLsizei,
        pointer: ClientPtr,
    ) {
        self.pointer_with_count(ClientArray::TexCoord, count, |c| {
            c.tex_coord_pointer(size, type_, stride, pointer)
        });
    }

    pub(crate) fn edge_flag_pointer_ext(
        &mut self,
        stride: GLsizei,
        count: GLsizei,
        pointer: ClientPtr,
    ) {
        self.pointer_with_count(ClientArray::EdgeFlag, count, |c| {
            c.edge_flag_pointer(stride, pointer)
        });
    }
}

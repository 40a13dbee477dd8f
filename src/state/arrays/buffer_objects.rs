//! Buffer objects (section 2.9): names, binding, data, mapping and their queries.

use super::*;

impl Context {
    pub(super) fn bound_buffer_name(&self, target: BufferTarget) -> GLuint {
        match target {
            BufferTarget::Array => self.client.arrays.array_buffer,
            BufferTarget::ElementArray => self.client.arrays.element_array_buffer,
        }
    }

    /// The buffer object bound to `target` (INVALID_ENUM for a bad target, INVALID_OPERATION
    /// when 0 is bound).
    pub(super) fn bound_buffer(&mut self, target: GLenum) -> Result<&mut BufferObject, GLenum> {
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
    pub(super) fn buffer_range(
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
}

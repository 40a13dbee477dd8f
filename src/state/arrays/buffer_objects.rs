//! Buffer objects (section 2.9): names, binding, data, mapping and their queries.

use super::*;

impl Context {
    pub(super) fn bound_buffer_name(&self, target: BufferTarget) -> GLuint {
        match target {
            BufferTarget::Array => self.client.arrays.array_buffer,
            BufferTarget::ElementArray => self.client.arrays.element_array_buffer,
            BufferTarget::PixelPack => self.client.pixel_buffers[0],
            BufferTarget::PixelUnpack => self.client.pixel_buffers[1],
        }
    }

    /// The buffer object bound to `target` (INVALID_ENUM for a bad target, INVALID_OPERATION
    /// when 0 is bound).
    pub(super) fn bound_buffer(
        &mut self,
        target: GLenum,
    ) -> Result<MappedRwLockWriteGuard<'_, BufferObject>, GLenum> {
        let t = convert::buffer_target(target).ok_or(GL_INVALID_ENUM)?;
        let name = self.bound_buffer_name(t);
        if name == 0 {
            return Err(GL_INVALID_OPERATION);
        }
        RwLockWriteGuard::try_map(self.client.buffers.write(), |n| {
            n.objects.get_mut(&name).and_then(|b| b.as_mut())
        })
        .map_err(|_| GL_INVALID_OPERATION)
    }

    pub(crate) fn gen_buffers(&mut self, n: GLsizei, buffers: &mut [GLuint]) {
        if n < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let mut b = self.client.buffers.write();
        for out in buffers.iter_mut().take(n as usize) {
            loop {
                b.next = b.next.wrapping_add(1);
                if b.next != 0 && !b.objects.contains_key(&b.next) {
                    break;
                }
            }
            let name = b.next;
            b.objects.insert(name, None);
            *out = name;
        }
    }

    pub(crate) fn bind_buffer(&mut self, target: GLenum, buffer: GLuint) {
        let Some(t) = convert::buffer_target(target) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if buffer != 0 {
            // glGenBuffers continues above names bound without being generated.
            let mut b = self.client.buffers.write();
            b.next = b.next.max(buffer);
            let slot = b.objects.entry(buffer).or_insert(None);
            if slot.is_none() {
                *slot = Some(BufferObject::default());
            }
        }
        let a = &mut self.client.arrays;
        match t {
            BufferTarget::Array => a.array_buffer = buffer,
            BufferTarget::ElementArray => a.element_array_buffer = buffer,
            BufferTarget::PixelPack => self.client.pixel_buffers[0] = buffer,
            BufferTarget::PixelUnpack => self.client.pixel_buffers[1] = buffer,
        }
    }

    pub(crate) fn delete_buffers(&mut self, n: GLsizei, buffers: &[GLuint]) {
        if n < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        for &name in buffers.iter().take(n as usize) {
            if name == 0 || self.client.buffers.write().objects.remove(&name).is_none() {
                continue;
            }
            // A deleted buffer is unbound from every binding point (section 2.9).
            for b in &mut self.client.pixel_buffers {
                if *b == name {
                    *b = 0;
                }
            }
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
        matches!(
            self.client.buffers.read().objects.get(&buffer),
            Some(Some(_))
        ) as GLboolean
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
        let r = self.bound_buffer(target).and_then(|mut b| {
            let mut store = Vec::new();
            store
                .try_reserve_exact(size as usize)
                .map_err(|_| GL_OUT_OF_MEMORY)?;
            match data {
                Some(d) => store.extend_from_slice(&d[..size as usize]),
                None => store.resize(size as usize, 0),
            }
            // The old store goes (a mapping of it ends), the new one starts unmapped.
            *b = BufferObject {
                data: store,
                usage,
                ..BufferObject::default()
            };
            Ok(())
        });
        if let Err(e) = r {
            self.record_error(e);
        }
    }

    /// Runs `f` on the bound buffer and the range `offset..offset + size` of it, checked
    /// (INVALID_VALUE when out of the store, INVALID_OPERATION when mapped).
    fn with_buffer_range<R>(
        &mut self,
        target: GLenum,
        offset: GLintptr,
        size: GLsizeiptr,
        f: impl FnOnce(&mut BufferObject, std::ops::Range<usize>) -> Result<R, GLenum>,
    ) -> Result<R, GLenum> {
        let mut b = self.bound_buffer(target)?;
        if offset < 0 || size < 0 || (offset as u64 + size as u64) > b.data.len() as u64 {
            return Err(GL_INVALID_VALUE);
        }
        if b.mapped {
            return Err(GL_INVALID_OPERATION);
        }
        f(&mut b, offset as usize..(offset + size) as usize)
    }

    pub(crate) fn buffer_sub_data(
        &mut self,
        target: GLenum,
        offset: GLintptr,
        size: GLsizeiptr,
        data: Option<&[u8]>,
    ) {
        let r = self.with_buffer_range(target, offset, size, |b, r| {
            let Some(d) = data else {
                return Ok(());
            };
            if d.len() < r.len() {
                return Err(GL_INVALID_VALUE);
            }
            let n = r.len();
            b.data[r].copy_from_slice(&d[..n]);
            Ok(())
        });
        if let Err(e) = r {
            self.record_error(e);
        }
    }

    pub(crate) fn get_buffer_sub_data(
        &mut self,
        target: GLenum,
        offset: GLintptr,
        size: GLsizeiptr,
        data: &mut [u8],
    ) {
        let r = self.with_buffer_range(target, offset, size, |b, r| {
            if data.len() < r.len() {
                return Err(GL_INVALID_VALUE);
            }
            let n = r.len();
            data[..n].copy_from_slice(&b.data[r]);
            Ok(())
        });
        if let Err(e) = r {
            self.record_error(e);
        }
    }

    pub(crate) fn map_buffer(&mut self, target: GLenum, access: GLenum) -> ClientPtr {
        let Some(access) = convert::buffer_access(access) else {
            // The target is checked first (both are INVALID_ENUM anyway).
            self.record_error(GL_INVALID_ENUM);
            return ClientPtr(0);
        };
        let r = self.bound_buffer(target).and_then(|mut b| {
            if b.mapped {
                return Err(GL_INVALID_OPERATION);
            }
            b.mapped = true;
            b.access = access;
            b.map_offset = 0;
            b.map_length = b.data.len();
            b.access_flags = match access {
                BufferAccess::ReadOnly => GL_MAP_READ_BIT,
                BufferAccess::WriteOnly => GL_MAP_WRITE_BIT,
                BufferAccess::ReadWrite => GL_MAP_READ_BIT | GL_MAP_WRITE_BIT,
            };
            // The store is not reallocated while mapped (every call that would is refused or
            // ends the mapping first), so the address stays valid until glUnmapBuffer.
            Ok(ClientPtr(b.data.as_mut_ptr() as usize))
        });
        r.unwrap_or_else(|e| {
            self.record_error(e);
            ClientPtr(0)
        })
    }

    /// The store of the buffer mapped on `target`, for Rust callers (the safe form of writing
    /// through the `glMapBuffer` pointer). `None` unless a buffer is bound there and mapped.
    pub fn mapped_buffer_mut(
        &mut self,
        target: GLenum,
    ) -> Option<MappedRwLockWriteGuard<'_, [u8]>> {
        let b = self.bound_buffer(target).ok()?;
        b.mapped.then(|| {
            MappedRwLockWriteGuard::map(b, |b| {
                let r = b.map_offset..b.map_offset + b.map_length;
                &mut b.data[r]
            })
        })
    }

    pub(crate) fn unmap_buffer(&mut self, target: GLenum) -> GLboolean {
        let r = self.bound_buffer(target).and_then(|mut b| {
            if !b.mapped {
                return Err(GL_INVALID_OPERATION);
            }
            b.mapped = false;
            b.map_offset = 0;
            b.map_length = 0;
            b.access_flags = 0;
            Ok(())
        });
        match r {
            Ok(()) => GL_TRUE as GLboolean,
            Err(e) => {
                self.record_error(e);
                GL_FALSE as GLboolean
            }
        }
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
        let r = self.bound_buffer(target).map(|b| match p {
            BufferParam::Size => b.data.len().min(i32::MAX as usize) as GLint,
            BufferParam::Usage => b.usage as GLint,
            BufferParam::Access => b.access.to_gl() as GLint,
            BufferParam::Mapped => b.mapped as GLint,
            BufferParam::AccessFlags => b.access_flags as GLint,
            BufferParam::MapOffset => b.map_offset.min(i32::MAX as usize) as GLint,
            BufferParam::MapLength => b.map_length.min(i32::MAX as usize) as GLint,
        });
        let v = match r {
            Ok(v) => v,
            Err(e) => return self.record_error(e),
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
        let r = self.bound_buffer(target).map(|mut b| {
            if b.mapped {
                b.data.as_mut_ptr() as usize + b.map_offset
            } else {
                0
            }
        });
        match r {
            Ok(p) => self.client_memory.store_pointer(params, p),
            Err(e) => self.record_error(e),
        }
    }

    /// `glMapBufferRange` (ARB_map_buffer_range): maps `length` bytes at `offset`.
    pub(crate) fn map_buffer_range(
        &mut self,
        target: GLenum,
        offset: GLintptr,
        length: GLsizeiptr,
        access: GLbitfield,
    ) -> ClientPtr {
        const READ_EXCLUDES: GLbitfield =
            GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_UNSYNCHRONIZED_BIT;
        const ALL: GLbitfield =
            GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | READ_EXCLUDES | GL_MAP_FLUSH_EXPLICIT_BIT;
        let r = (|| {
            let mut b = self.bound_buffer(target)?;
            if offset < 0 || length < 0 || access & !ALL != 0 {
                return Err(GL_INVALID_VALUE);
            }
            let rw = access & (GL_MAP_READ_BIT | GL_MAP_WRITE_BIT);
            if rw == 0
                || access & GL_MAP_READ_BIT != 0 && access & READ_EXCLUDES != 0
                || access & GL_MAP_FLUSH_EXPLICIT_BIT != 0 && access & GL_MAP_WRITE_BIT == 0
            {
                return Err(GL_INVALID_OPERATION);
            }
            if offset as u64 + length as u64 > b.data.len() as u64 {
                return Err(GL_INVALID_VALUE);
            }
            if b.mapped {
                return Err(GL_INVALID_OPERATION);
            }
            b.mapped = true;
            b.access = match rw {
                GL_MAP_READ_BIT => BufferAccess::ReadOnly,
                GL_MAP_WRITE_BIT => BufferAccess::WriteOnly,
                _ => BufferAccess::ReadWrite,
            };
            b.map_offset = offset as usize;
            b.map_length = length as usize;
            b.access_flags = access;
            // As for glMapBuffer: the store stays put until the mapping ends.
            Ok(ClientPtr(b.data.as_mut_ptr() as usize + offset as usize))
        })();
        r.unwrap_or_else(|e| {
            self.record_error(e);
            ClientPtr(0)
        })
    }

    /// `glFlushMappedBufferRange` (ARB_map_buffer_range). Writes through the mapping reach the
    /// store directly, so a valid flush has nothing left to do.
    pub(crate) fn flush_mapped_buffer_range(
        &mut self,
        target: GLenum,
        offset: GLintptr,
        length: GLsizeiptr,
    ) {
        let r = (|| {
            let b = self.bound_buffer(target)?;
            if offset < 0 || length < 0 {
                return Err(GL_INVALID_VALUE);
            }
            if !b.mapped || b.access_flags & GL_MAP_FLUSH_EXPLICIT_BIT == 0 {
                return Err(GL_INVALID_OPERATION);
            }
            if offset as u64 + length as u64 > b.map_length as u64 {
                return Err(GL_INVALID_VALUE);
            }
            Ok(())
        })();
        if let Err(e) = r {
            self.record_error(e);
        }
    }
}

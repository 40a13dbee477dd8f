//! Fetching array elements and drawing them (`glArrayElement`, `glDrawArrays`,
//! `glDrawElements`, `glDrawRangeElements`, `glMultiDraw*`), and EXT_compiled_vertex_array.

use super::*;

impl Context {
    /// The bytes of array `a` from element `min` on, covering elements `min..=max`, given to
    /// `f` (buffer contents or client memory; element `i` starts at `(i - min) * stride`).
    /// Client memory outside the elements the draw uses is never touched.
    pub(super) fn with_array_bytes<R>(
        &self,
        a: &ArrayPointer,
        (min, max): (u32, u32),
        f: impl FnOnce(&[u8]) -> R,
    ) -> R {
        let start = (min as usize).saturating_mul(a.effective_stride());
        if a.buffer != 0 {
            let names = self.client.buffers.read();
            let data = names
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
        client_memory::with_bytes_from(self.client_memory, a.pointer, start, len, f)
    }

    pub(super) fn buffer_mapped(&self, name: GLuint) -> bool {
        name != 0
            && matches!(
                self.client.buffers.read().objects.get(&name),
                Some(Some(BufferObject { mapped: true, .. }))
            )
    }

    /// The enabled arrays that draws read, with any mapped source (INVALID_OPERATION).
    pub(super) fn enabled_arrays(&self) -> Result<Present, GLenum> {
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
    pub(super) fn apply_element(&mut self, p: &Present, v: &ArrayVertex) {
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
    pub(super) fn draw_fetched(&mut self, mode: GLenum, f: &Fetched) {
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
    pub(super) fn save_current_values(&self, p: &Present) -> SavedCurrent {
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
    pub(super) fn keep_current_values(&mut self, saved: SavedCurrent) {
        self.current = saved.current;
        if let Some(m) = saved.materials {
            if self.lighting.materials != m {
                self.lighting.materials = m;
                self.invalidate();
            }
        }
    }

    /// Draws (or, while compiling a list, records) the elements `indices`.
    pub(super) fn draw_indices(&mut self, mode: GLenum, indices: &[u32]) {
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
    pub(super) fn check_draw(&mut self, mode: GLenum, count: GLsizei) -> bool {
        if convert::primitive_mode(mode).is_none() {
            self.list_aware_error(GL_INVALID_ENUM);
            return false;
        }
        if count < 0 {
            self.list_aware_error(GL_INVALID_VALUE);
            return false;
        }
        self.framebuffer_ready()
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
    pub(super) fn buffer_backed_elements(&self) -> u64 {
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
                .read()
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
    pub(super) fn read_indices(
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
            let names = self.client.buffers.read();
            let data = names
                .objects
                .get(&eab)
                .and_then(|b| b.as_ref())
                .map_or(&[][..], |b| &b.data[..]);
            fill(data.get(indices.0..).unwrap_or(&[]), &mut out);
        } else {
            let len = count.saturating_mul(ty.size());
            client_memory::with_bytes(self.client_memory, indices, len, |b| fill(b, &mut out));
        }
        Ok(out)
    }

    pub(super) fn draw_elements_checked(
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
        let ptrs: Vec<usize> = client_memory::with_bytes(
            self.client_memory,
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
}

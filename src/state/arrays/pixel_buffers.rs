//! Pixel buffer objects (ARB_pixel_buffer_object, EXT_pixel_buffer_object; core in OpenGL
//! 2.1): the pixel commands' data in the buffer bound to `GL_PIXEL_UNPACK_BUFFER` (commands
//! that read pixels, issue 16 of the extension) or `GL_PIXEL_PACK_BUFFER` (commands that write
//! them, issue 17), the pointer argument being an offset into that buffer.
//!
//! # Design
//!
//! Each such command has a `*_pbo` variant (`Gl::tex_image_2d_pbo`, ...) taking the offset;
//! the C exports call it instead of the plain one while a buffer is bound to the command's
//! target (`Context::pixel_buffer_bound`), since a C pointer is then an offset. The variant
//! computes the bytes the command reads or writes from its arguments and the pixel-store state
//! (`state/client_sizes.rs`, the same layouts the commands walk) and checks the access as the
//! extension asks (`GL_INVALID_OPERATION` when the buffer is mapped, when the bytes reach past
//! its store, or when the offset is not a multiple of the size of the command's data type);
//! then
//! - an unpacking command runs as if its data, copied out of the buffer, were client memory
//!   (a display list being compiled keeps that copy, as OpenGL 2.1's section 5.4 asks);
//! - a packing command runs on a copy of the buffer's bytes in the range, which goes back into
//!   the buffer afterwards (bytes the command skips, row padding for example, stay as they
//!   were).
//!
//! A call that is going to fail before touching memory (an invalid enum, a negative size) needs
//! 0 bytes: the access checks pass and the command records its own error, as Mesa does for
//! such calls.

use super::*;
use crate::gl::types::{GLfloat, GLsizei, GLushort};

/// Size in bytes of one datum of pixel type `type_` (table 3.5; packed types whole): the
/// offset of a typed pixel command must be a multiple of it. 1 for unknown types (the command
/// refuses them itself) and for `GL_BITMAP`.
fn type_alignment(type_: GLenum) -> usize {
    match type_ {
        GL_SHORT
        | GL_UNSIGNED_SHORT
        | GL_UNSIGNED_SHORT_5_6_5
        | GL_UNSIGNED_SHORT_5_6_5_REV
        | GL_UNSIGNED_SHORT_4_4_4_4
        | GL_UNSIGNED_SHORT_4_4_4_4_REV
        | GL_UNSIGNED_SHORT_5_5_5_1
        | GL_UNSIGNED_SHORT_1_5_5_5_REV => 2,
        GL_INT
        | GL_UNSIGNED_INT
        | GL_FLOAT
        | GL_UNSIGNED_INT_8_8_8_8
        | GL_UNSIGNED_INT_8_8_8_8_REV
        | GL_UNSIGNED_INT_10_10_10_2
        | GL_UNSIGNED_INT_2_10_10_10_REV
        | GL_UNSIGNED_INT_24_8_EXT => 4,
        _ => 1,
    }
}

impl Context {
    /// Whether a buffer object is bound to `GL_PIXEL_PACK_BUFFER` (`pack`) or to
    /// `GL_PIXEL_UNPACK_BUFFER`: the pointers of the pixel commands that pack (unpack) are then
    /// offsets into it.
    pub fn pixel_buffer_bound(&self, pack: bool) -> bool {
        self.client.pixel_buffers[usize::from(!pack)] != 0
    }

    /// The range `offset..offset + len` of the pixel pack (`pack`) or unpack buffer, checked:
    /// `GL_INVALID_OPERATION` when no buffer is bound there, when it is mapped, when the range
    /// leaves its store, or when `offset` is not a multiple of `align`. The name and the range.
    fn pixel_buffer_range(
        &self,
        pack: bool,
        offset: usize,
        len: usize,
        align: usize,
    ) -> Result<(GLuint, std::ops::Range<usize>), GLenum> {
        let name = self.client.pixel_buffers[usize::from(!pack)];
        let names = self.client.buffers.read();
        let b = names
            .objects
            .get(&name)
            .and_then(|b| b.as_ref())
            .ok_or(GL_INVALID_OPERATION)?;
        if len == 0 {
            return Ok((name, offset..offset));
        }
        if b.mapped || !offset.is_multiple_of(align.max(1)) {
            return Err(GL_INVALID_OPERATION);
        }
        let end = offset
            .checked_add(len)
            .filter(|&end| end <= b.data.len())
            .ok_or(GL_INVALID_OPERATION)?;
        Ok((name, offset..end))
    }

    /// The `len` bytes at `offset` of the pixel unpack buffer, after the checks of
    /// `pixel_buffer_range` (the error recorded and `None` when one fails).
    fn unpack_buffer_bytes(&mut self, offset: usize, len: usize, align: usize) -> Option<Vec<u8>> {
        match self.pixel_buffer_range(false, offset, len, align) {
            Ok((name, r)) => {
                let names = self.client.buffers.read();
                let b = names.objects.get(&name).and_then(|b| b.as_ref())?;
                Some(b.data[r].to_vec())
            }
            Err(e) => {
                self.record_error(e);
                None
            }
        }
    }

    /// Runs the packing command `f` on the `len` bytes at `offset` of the pixel pack buffer
    /// (a copy, stored back afterwards), after the checks of `pixel_buffer_range`.
    fn pack_into_buffer(
        &mut self,
        offset: usize,
        len: usize,
        align: usize,
        f: impl FnOnce(&mut Self, &mut [u8]),
    ) {
        let (name, r) = match self.pixel_buffer_range(true, offset, len, align) {
            Ok(x) => x,
            Err(e) => return self.record_error(e),
        };
        let mut bytes = {
            let names = self.client.buffers.read();
            match names.objects.get(&name).and_then(|b| b.as_ref()) {
                Some(b) => b.data[r.clone()].to_vec(),
                None => return,
            }
        };
        f(self, &mut bytes);
        let mut names = self.client.buffers.write();
        if let Some(Some(b)) = names.objects.get_mut(&name) {
            if let Some(dst) = b.data.get_mut(r) {
                dst.copy_from_slice(&bytes);
            }
        }
    }

    // ----- unpacking commands: the checked data, for the plain command

    pub(crate) fn tex_image_1d_pbo(
        &mut self,
        _target: GLenum,
        _level: GLint,
        _internalformat: GLint,
        width: GLsizei,
        _border: GLint,
        format: GLenum,
        type_: GLenum,
        pixels: usize,
    ) -> Option<Vec<u8>> {
        let len = self.tex_image_len(1, format, type_, [width, 1, 1]);
        self.unpack_buffer_bytes(pixels, len, type_alignment(type_))
    }

    pub(crate) fn tex_image_2d_pbo(
        &mut self,
        _target: GLenum,
        _level: GLint,
        _internalformat: GLint,
        width: GLsizei,
        height: GLsizei,
        _border: GLint,
        format: GLenum,
        type_: GLenum,
        pixels: usize,
    ) -> Option<Vec<u8>> {
        let len = self.tex_image_len(2, format, type_, [width, height, 1]);
        self.unpack_buffer_bytes(pixels, len, type_alignment(type_))
    }

    pub(crate) fn tex_image_3d_pbo(
        &mut self,
        _target: GLenum,
        _level: GLint,
        _internalformat: GLint,
        width: GLsizei,
        height: GLsizei,
        depth: GLsizei,
        _border: GLint,
        format: GLenum,
        type_: GLenum,
        pixels: usize,
    ) -> Option<Vec<u8>> {
        let len = self.tex_image_len(3, format, type_, [width, height, depth]);
        self.unpack_buffer_bytes(pixels, len, type_alignment(type_))
    }

    pub(crate) fn tex_sub_image_1d_pbo(
        &mut self,
        _target: GLenum,
        _level: GLint,
        _xoffset: GLint,
        width: GLsizei,
        format: GLenum,
        type_: GLenum,
        pixels: usize,
    ) -> Option<Vec<u8>> {
        let len = self.tex_image_len(1, format, type_, [width, 1, 1]);
        self.unpack_buffer_bytes(pixels, len, type_alignment(type_))
    }

    pub(crate) fn tex_sub_image_2d_pbo(
        &mut self,
        _target: GLenum,
        _level: GLint,
        _xoffset: GLint,
        _yoffset: GLint,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        type_: GLenum,
        pixels: usize,
    ) -> Option<Vec<u8>> {
        let len = self.tex_image_len(2, format, type_, [width, height, 1]);
        self.unpack_buffer_bytes(pixels, len, type_alignment(type_))
    }

    pub(crate) fn tex_sub_image_3d_pbo(
        &mut self,
        _target: GLenum,
        _level: GLint,
        _xoffset: GLint,
        _yoffset: GLint,
        _zoffset: GLint,
        width: GLsizei,
        height: GLsizei,
        depth: GLsizei,
        format: GLenum,
        type_: GLenum,
        pixels: usize,
    ) -> Option<Vec<u8>> {
        let len = self.tex_image_len(3, format, type_, [width, height, depth]);
        self.unpack_buffer_bytes(pixels, len, type_alignment(type_))
    }

    pub(crate) fn draw_pixels_pbo(
        &mut self,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        type_: GLenum,
        pixels: usize,
    ) -> Option<Vec<u8>> {
        let len = self.draw_pixels_len(format, type_, width, height);
        self.unpack_buffer_bytes(pixels, len, type_alignment(type_))
    }

    pub(crate) fn bitmap_pbo(
        &mut self,
        width: GLsizei,
        height: GLsizei,
        _xorig: GLfloat,
        _yorig: GLfloat,
        _xmove: GLfloat,
        _ymove: GLfloat,
        bitmap: usize,
    ) -> Option<Vec<u8>> {
        let len = self.bitmap_len(width, height);
        self.unpack_buffer_bytes(bitmap, len, 1)
    }

    pub(crate) fn polygon_stipple_pbo(&mut self, mask: usize) -> Option<Vec<u8>> {
        // The bytes `polygon_stipple` reads: 32 rows of 32 bits under the unpack state.
        let u = self.unpack;
        let row_bytes = if u.row_length > 0 {
            u.row_length as usize
        } else {
            32
        }
        .div_ceil(8);
        let align = u.alignment.max(1) as usize;
        let stride = row_bytes.div_ceil(align) * align;
        let last_bit = u.skip_pixels.max(0) as usize + 31;
        let len = (u.skip_rows.max(0) as usize + 31) * stride + last_bit / 8 + 1;
        self.unpack_buffer_bytes(mask, len, 1)
    }

    /// Compressed images read `image_size` bytes (none when it is negative: refused).
    fn compressed_pbo(&mut self, image_size: GLsizei, data: usize) -> Option<Vec<u8>> {
        self.unpack_buffer_bytes(data, image_size.max(0) as usize, 1)
    }

    pub(crate) fn compressed_tex_image_1d_pbo(
        &mut self,
        _target: GLenum,
        _level: GLint,
        _internalformat: GLenum,
        _width: GLsizei,
        _border: GLint,
        image_size: GLsizei,
        data: usize,
    ) -> Option<Vec<u8>> {
        self.compressed_pbo(image_size, data)
    }

    pub(crate) fn compressed_tex_image_2d_pbo(
        &mut self,
        _target: GLenum,
        _level: GLint,
        _internalformat: GLenum,
        _width: GLsizei,
        _height: GLsizei,
        _border: GLint,
        image_size: GLsizei,
        data: usize,
    ) -> Option<Vec<u8>> {
        self.compressed_pbo(image_size, data)
    }

    pub(crate) fn compressed_tex_image_3d_pbo(
        &mut self,
        _target: GLenum,
        _level: GLint,
        _internalformat: GLenum,
        _width: GLsizei,
        _height: GLsizei,
        _depth: GLsizei,
        _border: GLint,
        image_size: GLsizei,
        data: usize,
    ) -> Option<Vec<u8>> {
        self.compressed_pbo(image_size, data)
    }

    pub(crate) fn compressed_tex_sub_image_1d_pbo(
        &mut self,
        _target: GLenum,
        _level: GLint,
        _xoffset: GLint,
        _width: GLsizei,
        _format: GLenum,
        image_size: GLsizei,
        data: usize,
    ) -> Option<Vec<u8>> {
        self.compressed_pbo(image_size, data)
    }

    pub(crate) fn compressed_tex_sub_image_2d_pbo(
        &mut self,
        _target: GLenum,
        _level: GLint,
        _xoffset: GLint,
        _yoffset: GLint,
        _width: GLsizei,
        _height: GLsizei,
        _format: GLenum,
        image_size: GLsizei,
        data: usize,
    ) -> Option<Vec<u8>> {
        self.compressed_pbo(image_size, data)
    }

    pub(crate) fn compressed_tex_sub_image_3d_pbo(
        &mut self,
        _target: GLenum,
        _level: GLint,
        _xoffset: GLint,
        _yoffset: GLint,
        _zoffset: GLint,
        _width: GLsizei,
        _height: GLsizei,
        _depth: GLsizei,
        _format: GLenum,
        image_size: GLsizei,
        data: usize,
    ) -> Option<Vec<u8>> {
        self.compressed_pbo(image_size, data)
    }

    /// `mapsize` values of `N` bytes each (none when it is negative: refused), decoded.
    fn pixel_map_pbo<const N: usize, T>(
        &mut self,
        mapsize: GLsizei,
        values: usize,
        decode: fn([u8; N]) -> T,
    ) -> Option<Vec<T>> {
        let n = mapsize.max(0) as usize;
        let bytes = self.unpack_buffer_bytes(values, n.checked_mul(N)?, N)?;
        Some(
            bytes
                .chunks_exact(N)
                .map(|c| decode(c.try_into().expect("chunks of N bytes")))
                .collect(),
        )
    }

    pub(crate) fn pixel_mapfv_pbo(
        &mut self,
        _map: GLenum,
        mapsize: GLsizei,
        values: usize,
    ) -> Option<Vec<GLfloat>> {
        self.pixel_map_pbo(mapsize, values, f32::from_ne_bytes)
    }

    pub(crate) fn pixel_mapuiv_pbo(
        &mut self,
        _map: GLenum,
        mapsize: GLsizei,
        values: usize,
    ) -> Option<Vec<GLuint>> {
        self.pixel_map_pbo(mapsize, values, u32::from_ne_bytes)
    }

    pub(crate) fn pixel_mapusv_pbo(
        &mut self,
        _map: GLenum,
        mapsize: GLsizei,
        values: usize,
    ) -> Option<Vec<GLushort>> {
        self.pixel_map_pbo(mapsize, values, u16::from_ne_bytes)
    }

    // ----- packing commands

    pub(crate) fn read_pixels_pbo(
        &mut self,
        x: GLint,
        y: GLint,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        type_: GLenum,
        pixels: usize,
    ) {
        let len = self.read_pixels_len(format, type_, width, height);
        self.pack_into_buffer(pixels, len, type_alignment(type_), |ctx, out| {
            ctx.read_pixels(x, y, width, height, format, type_, out)
        });
    }

    pub(crate) fn get_tex_image_pbo(
        &mut self,
        target: GLenum,
        level: GLint,
        format: GLenum,
        type_: GLenum,
        pixels: usize,
    ) {
        let len = self.get_tex_image_len(target, level, format, type_);
        self.pack_into_buffer(pixels, len, type_alignment(type_), |ctx, out| {
            ctx.get_tex_image(target, level, format, type_, out)
        });
    }

    pub(crate) fn get_compressed_tex_image_pbo(
        &mut self,
        target: GLenum,
        level: GLint,
        img: usize,
    ) {
        let len = self.get_compressed_tex_image_len(target, level);
        self.pack_into_buffer(img, len, 1, |ctx, out| {
            ctx.get_compressed_tex_image(target, level, out)
        });
    }

    pub(crate) fn get_polygon_stipple_pbo(&mut self, mask: usize) {
        // What `get_polygon_stipple` writes: 32 rows of 4 bytes at the pack alignment.
        let align = self.pack.alignment.max(1) as usize;
        let len = 4usize.div_ceil(align) * align * 31 + 4;
        self.pack_into_buffer(mask, len, 1, |ctx, out| ctx.get_polygon_stipple(out));
    }

    /// The current values of `map` written as `N`-byte values by `write`.
    fn get_pixel_map_pbo<const N: usize, T: Default + Clone>(
        &mut self,
        map: GLenum,
        values: usize,
        get: fn(&mut Self, GLenum, &mut [T]),
        encode: fn(T) -> [u8; N],
    ) {
        let n = self.pixel_map_len(map);
        self.pack_into_buffer(values, n * N, N, |ctx, out| {
            let mut v = vec![T::default(); n];
            get(ctx, map, &mut v);
            for (o, x) in out.chunks_exact_mut(N).zip(v) {
                o.copy_from_slice(&encode(x));
            }
        });
    }

    pub(crate) fn get_pixel_mapfv_pbo(&mut self, map: GLenum, values: usize) {
        self.get_pixel_map_pbo(map, values, Self::get_pixel_mapfv, f32::to_ne_bytes);
    }

    pub(crate) fn get_pixel_mapuiv_pbo(&mut self, map: GLenum, values: usize) {
        self.get_pixel_map_pbo(map, values, Self::get_pixel_mapuiv, u32::to_ne_bytes);
    }

    pub(crate) fn get_pixel_mapusv_pbo(&mut self, map: GLenum, values: usize) {
        self.get_pixel_map_pbo(map, values, Self::get_pixel_mapusv, u16::to_ne_bytes);
    }
}

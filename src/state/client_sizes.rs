//! How many bytes (or values) a pixel command reads from or writes to client memory, computed
//! from its arguments and the current pixel-store state exactly as the command walks that
//! memory. The commands check the slices they are given against the same layouts, and the C
//! ABI sizes the caller's pointers with these functions (`capi::compsize`), so the two cannot
//! disagree: a valid call from C is never refused for its length, and nothing is read or
//! written past what the call's arguments describe.
//!
//! Every function returns 0 where the call is going to fail before it touches memory (an
//! invalid enum, a negative or over-limit size, a missing image): GL then records the call's
//! own error without reading the data, and no slice longer than the caller meant is formed.
//!
//! With a pixel buffer object bound (`ARB_pixel_buffer_object`, `state/arrays/pixel_buffers.rs`)
//! the same sizes bound the access to the buffer: the pointer is then an offset, and the C ABI
//! calls the `*_pbo` entry points instead of sizing a client pointer.

use super::Context;
use crate::common::values::{DrawPixelsFormat, TexPixelFormat, TexPixelType};
use crate::gl::convert;
use crate::gl::enums::*;
use crate::gl::types::GLsizei;
use crate::state::tables::PixelStore;
use crate::texture::object::{MAX_3D_TEXTURE_SIZE, MAX_CUBE_MAP_TEXTURE_SIZE, MAX_TEXTURE_SIZE};
use crate::texture::pixels as texpix;

/// The largest side any texture image (borders included) may have: a larger size is refused
/// before the data is read.
fn max_image_side() -> i64 {
    MAX_TEXTURE_SIZE
        .max(MAX_3D_TEXTURE_SIZE)
        .max(MAX_CUBE_MAP_TEXTURE_SIZE) as i64
        + 2
}

/// The first `dims` sizes as `usize` (1 for the others), or `None` if one is negative or
/// larger than `limit`.
fn image_size(dims: usize, size: [GLsizei; 3], limit: i64) -> Option<[usize; 3]> {
    let mut out = [1usize; 3];
    for d in 0..dims.min(3) {
        if size[d] < 0 || size[d] as i64 > limit {
            return None;
        }
        out[d] = size[d] as usize;
    }
    Some(out)
}

/// Bytes of a `format`/`type_` image of `size` under `store`, or 0 (see the module docs).
fn image_bytes(
    store: &PixelStore,
    dims: usize,
    format: TexPixelFormat,
    ty: TexPixelType,
    size: [usize; 3],
) -> usize {
    texpix::layout(store, dims, size, format, ty).map_or(0, |l| l.end)
}

/// Bytes of a `GL_DEPTH_STENCIL` rectangle (EXT_packed_depth_stencil) for `glReadPixels` and
/// `glDrawPixels`: one 32-bit word a pixel with `GL_UNSIGNED_INT_24_8`, the one type taken.
fn depth_stencil_bytes(store: &PixelStore, type_: GLenum, w: usize, h: usize) -> usize {
    if type_ != GL_UNSIGNED_INT_24_8_EXT {
        return 0;
    }
    let ty = TexPixelType::Packed(crate::common::values::PackedType::UInt248);
    image_bytes(store, 2, TexPixelFormat::DepthStencil, ty, [w, h, 1])
}

impl Context {
    /// Bytes `glTexImage{1,2,3}D` and `glTexSubImage{1,2,3}D` read at `pixels` for an image of
    /// `size` (the first `dims` entries used) under the unpack state.
    pub(crate) fn tex_image_len(
        &self,
        dims: usize,
        format: GLenum,
        type_: GLenum,
        size: [GLsizei; 3],
    ) -> usize {
        let Some(s) = image_size(dims, size, max_image_side()) else {
            return 0;
        };
        if format == GL_COLOR_INDEX {
            return convert::pixel_index_type(type_)
                .map_or(0, |t| texpix::index_image_len(&self.unpack, dims, s, t));
        }
        let (Some(f), Some(t)) = (
            convert::tex_upload_format(format),
            convert::tex_pixel_type(type_),
        ) else {
            return 0;
        };
        image_bytes(&self.unpack, dims, f, t, s)
    }

    /// Bytes `glDrawPixels` reads: colour and depth groups as for texture images, colour and
    /// stencil indices (also as `GL_BITMAP` bits) as index rows.
    pub(crate) fn draw_pixels_len(
        &self,
        format: GLenum,
        type_: GLenum,
        width: GLsizei,
        height: GLsizei,
    ) -> usize {
        let Some([w, h, _]) = image_size(2, [width, height, 1], i32::MAX as i64) else {
            return 0;
        };
        let u = &self.unpack;
        if format == GL_DEPTH_STENCIL_EXT {
            return depth_stencil_bytes(u, type_, w, h);
        }
        match convert::draw_pixels_format(format) {
            Some(DrawPixelsFormat::Color(f)) => {
                convert::tex_pixel_type(type_).map_or(0, |t| image_bytes(u, 2, f, t, [w, h, 1]))
            }
            Some(DrawPixelsFormat::Depth) => convert::tex_pixel_type(type_).map_or(0, |t| {
                image_bytes(u, 2, TexPixelFormat::DepthComponent, t, [w, h, 1])
            }),
            Some(DrawPixelsFormat::StencilIndex | DrawPixelsFormat::ColorIndex) => {
                convert::pixel_index_type(type_)
                    .map_or(0, |t| texpix::index_image_len(u, 2, [w, h, 1], t))
            }
            None => 0,
        }
    }

    /// Bytes `glBitmap` reads: `height` rows of `width` bits under the unpack state.
    pub(crate) fn bitmap_len(&self, width: GLsizei, height: GLsizei) -> usize {
        let Some([w, h, _]) = image_size(2, [width, height, 1], i32::MAX as i64) else {
            return 0;
        };
        texpix::index_rows(&self.unpack, w, h, 1, 1).map_or(0, |r| r.end)
    }

    /// Bytes `glReadPixels` writes under the pack state (packed types included).
    pub(crate) fn read_pixels_len(
        &self,
        format: GLenum,
        type_: GLenum,
        width: GLsizei,
        height: GLsizei,
    ) -> usize {
        let Some([w, h, _]) = image_size(2, [width, height, 1], i32::MAX as i64) else {
            return 0;
        };
        if format == GL_DEPTH_STENCIL_EXT {
            return depth_stencil_bytes(&self.pack, type_, w, h);
        }
        if let (Some(f), Some(t)) = (convert::pixel_format(format), convert::pixel_type(type_)) {
            return self.pack_bytes(f.components(), t.size(), w, h).unwrap_or(0);
        }
        match (
            convert::tex_pixel_format(format),
            convert::tex_pixel_type(type_),
        ) {
            (Some(f), Some(t @ TexPixelType::Packed(_))) => {
                image_bytes(&self.pack, 2, f, t, [w, h, 1])
            }
            _ => 0,
        }
    }

    /// Bytes a `w` x `h` rectangle of `components` elements of `elem_size` bytes spans under
    /// the pack state (`glReadPixels` with an unpacked type).
    pub(crate) fn pack_bytes(
        &self,
        components: usize,
        elem_size: usize,
        w: usize,
        h: usize,
    ) -> Option<usize> {
        self.pack
            .image_bytes(w, h, 1, components * elem_size, elem_size)
    }

    /// Bytes `glGetTexImage` writes for the image at `target`/`level` under the pack state
    /// (0 when there is no such image: nothing is written).
    pub(crate) fn get_tex_image_len(
        &self,
        target: GLenum,
        level: i32,
        format: GLenum,
        type_: GLenum,
    ) -> usize {
        // GL_DEPTH_STENCIL too: depth-stencil images read back packed (24_8).
        let (Some(f), Some(t)) = (
            convert::tex_upload_format(format),
            convert::tex_pixel_type(type_),
        ) else {
            return 0;
        };
        self.texture_image_size(target, level)
            .map_or(0, |(dims, size)| image_bytes(&self.pack, dims, f, t, size))
    }

    /// Bytes `glGetCompressedTexImage` writes: the stored blocks of the image.
    pub(crate) fn get_compressed_tex_image_len(&self, target: GLenum, level: i32) -> usize {
        self.texture_image_blocks_len(target, level).unwrap_or(0)
    }

    /// Values `glGetPixelMap{fv,uiv,usv}` writes: the map's current size.
    pub(crate) fn pixel_map_len(&self, map: GLenum) -> usize {
        convert::pixel_map(map).map_or(0, |m| self.pixel_transfer.maps[m.index()].len())
    }
}

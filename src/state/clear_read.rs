//! `glClear` recording and `glReadPixels`.

use super::Context;
use crate::common::fixed::{color_to_u8, depth_to_fixed};
use crate::common::values::{
    ClearMask, PackedType, PixelFormat, PixelType, TexPixelFormat, TexPixelType,
};
use crate::gl::convert;
use crate::gl::enums::*;
use crate::raster::scene::{ClearCommand, Command};
use crate::texture::pixels as texpix;

impl Context {
    /// Records a clear of the buffers in `mask`, limited by the scissor box and the write masks
    /// (section 4.2.3). Dithering does not apply to tilegl's 8-bit channels.
    pub(crate) fn record_clear(&mut self, mask: ClearMask) {
        let rect = self.scissored_window();
        let color_mask = self.color_write_mask();
        let ops = &self.fragment_ops;
        let cfg = self.framebuffer.config;
        let color = (mask.color && color_mask != [false; 4])
            .then(|| (self.clear_values.color.map(color_to_u8), color_mask));
        let depth = (mask.depth && ops.depth_mask && cfg.depth_bits > 0)
            .then(|| depth_to_fixed(self.clear_values.depth, self.framebuffer.depth_max()));
        let stencil_bits_mask = if cfg.stencil_bits >= 8 {
            0xFF
        } else {
            (1u32 << cfg.stencil_bits) - 1
        };
        let stencil = (mask.stencil && cfg.stencil_bits > 0).then_some({
            (
                (self.clear_values.stencil as u32 & stencil_bits_mask) as u8,
                (ops.stencil_writemask & stencil_bits_mask) as u8,
            )
        });
        if color.is_none() && depth.is_none() && stencil.is_none() {
            return;
        }
        if self.scene.is_full() {
            self.flush_scene();
        }
        self.scene.bin_all_planes(
            Command::Clear(ClearCommand {
                rect,
                color,
                depth,
                stencil,
            }),
            rect,
        );
    }

    pub(crate) fn read_pixels(
        &mut self,
        x: GLint,
        y: GLint,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        type_: GLenum,
        pixels: &mut [u8],
    ) {
        if self.reads_elsewhere() {
            // EXT_framebuffer_blit: pixels come from the read framebuffer.
            let read = self.fbo.read_bound;
            return self.with_framebuffer_bound(read, |c| {
                c.read_pixels(x, y, width, height, format, type_, pixels)
            });
        }
        if !self.framebuffer_ready() {
            return;
        }
        if format == GL_DEPTH_STENCIL_EXT {
            self.read_depth_stencil(x, y, width, height, type_, pixels);
            return;
        }
        let Some(f) = convert::pixel_format(format) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let Some(t) = convert::pixel_type(type_) else {
            if let Some(TexPixelType::Packed(p)) = convert::tex_pixel_type(type_) {
                self.read_pixels_packed(x, y, width, height, format, p, pixels);
            } else {
                self.record_error(GL_INVALID_ENUM);
            }
            return;
        };
        if width < 0 || height < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let cfg = self.framebuffer.config;
        if (f == PixelFormat::DepthComponent && cfg.depth_bits == 0)
            || (f == PixelFormat::StencilIndex && cfg.stencil_bits == 0)
        {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        let bpp = f.components() * t.size();
        let Some(needed) =
            self.pack_bytes(f.components(), t.size(), width as usize, height as usize)
        else {
            self.record_error(GL_INVALID_VALUE);
            return;
        };
        if pixels.len() < needed {
            // The Rust API's equivalent of a too-small client buffer.
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.flush_scene();
        let row_stride = self
            .pack
            .row_stride(width as usize, bpp, t.size())
            .unwrap_or(0);
        let start = self.pack.skip_rows.max(0) as usize * row_stride
            + self.pack.skip_pixels.max(0) as usize * bpp;
        let depth_max = self.framebuffer.depth_max() as f64;
        let swap = self.pack.swap_bytes;
        let xfer = (!self.pixel_transfer.is_identity()).then(|| self.pixel_transfer.clone());
        let xf = &self.pixel_transfer;
        let index_ops = xf.index_shift != 0 || xf.index_offset != 0 || xf.map_stencil;
        let plain_rgba8 = f == PixelFormat::Rgba && t == PixelType::UnsignedByte && xfer.is_none();
        for row in 0..height {
            for col in 0..width {
                let (wx, wy) = (x.saturating_add(col), y.saturating_add(row));
                let fb = &self.framebuffer;
                // Pixels outside the window are undefined; tilegl leaves the destination as is.
                let Some(rgba) = fb.color_at(wx, wy) else {
                    continue;
                };
                let mut c = rgba.map(|v| v as f64 / 255.0);
                if let Some(t) = &xfer {
                    // Pixel transfer on the way out (section 4.3.2), then clamped.
                    c = t.texel(false, c.map(|v| v as f32)).map(|v| v as f64);
                }
                let lum = (c[0] + c[1] + c[2]).min(1.0);
                let comps: [f64; 4];
                let values: &[f64] = match f {
                    PixelFormat::Red => &c[0..1],
                    PixelFormat::Green => &c[1..2],
                    PixelFormat::Blue => &c[2..3],
                    PixelFormat::Alpha => &c[3..4],
                    PixelFormat::Rgb => &c[0..3],
                    PixelFormat::Rgba => &c,
                    PixelFormat::Bgr => {
                        comps = [c[2], c[1], c[0], 0.0];
                        &comps[..3]
                    }
                    PixelFormat::Bgra => {
                        comps = [c[2], c[1], c[0], c[3]];
                        &comps
                    }
                    PixelFormat::Luminance => {
                        comps = [lum, 0.0, 0.0, 0.0];
                        &comps[..1]
                    }
                    PixelFormat::LuminanceAlpha => {
                        comps = [lum, c[3], 0.0, 0.0];
                        &comps[..2]
                    }
                    PixelFormat::DepthComponent => {
                        comps = [
                            {
                                let d = fb.depth_at(wx, wy).unwrap_or(0) as f64 / depth_max;
                                xfer.as_ref().map_or(d, |t| t.depth(d))
                            },
                            0.0,
                            0.0,
                            0.0,
                        ];
                        &comps[..1]
                    }
                    PixelFormat::StencilIndex => {
                        let st = fb.stencil_at(wx, wy).unwrap_or(0);
                        let st = if xfer.is_some() || index_ops {
                            self.pixel_transfer.stencil(st as i64)
                        } else {
                            st
                        };
                        comps = [st as f64, 0.0, 0.0, 0.0];
                        &comps[..1]
                    }
                };
                let o = start + row as usize * row_stride + col as usize * bpp;
                if plain_rgba8 {
                    // RGBA bytes without transfer: the stored bytes themselves (b / 255 * 255
                    // rounds back to b).
                    pixels[o..o + 4].copy_from_slice(&rgba);
                    continue;
                }
                let index = f == PixelFormat::StencilIndex;
                for (k, &v) in values.iter().enumerate() {
                    let at = o + k * t.size();
                    write_component(&mut pixels[at..at + t.size()], t, v, index, swap);
                }
            }
        }
    }
}

/// Converts one component for packing (table 4.7 inverses; indices are integers).
fn write_component(out: &mut [u8], t: PixelType, v: f64, index: bool, swap: bool) {
    // At most four bytes, built on the stack (this runs once per component read back).
    let mut buf = [0u8; 4];
    let n = t.size();
    match t {
        PixelType::UnsignedByte => {
            buf[0] = if index {
                v as u8
            } else {
                (v * 255.0).round() as u8
            };
        }
        PixelType::Byte => {
            buf[0] = if index {
                v as i8 as u8
            } else {
                ((v * 255.0 - 1.0) / 2.0).round() as i8 as u8
            };
        }
        PixelType::UnsignedShort => {
            let x = if index {
                v as u16
            } else {
                (v * 65535.0).round() as u16
            };
            buf[..2].copy_from_slice(&x.to_ne_bytes());
        }
        PixelType::Short => {
            let x = if index {
                v as i16
            } else {
                ((v * 65535.0 - 1.0) / 2.0).round() as i16
            };
            buf[..2].copy_from_slice(&x.to_ne_bytes());
        }
        PixelType::UnsignedInt => {
            let x = if index {
                v as u32
            } else {
                (v * 4294967295.0).round() as u32
            };
            buf.copy_from_slice(&x.to_ne_bytes());
        }
        PixelType::Int => {
            let x = if index {
                v as i32
            } else {
                ((v * 4294967295.0 - 1.0) / 2.0).round() as i32
            };
            buf.copy_from_slice(&x.to_ne_bytes());
        }
        PixelType::Float => buf.copy_from_slice(&(v as f32).to_ne_bytes()),
    }
    let bytes = &mut buf[..n];
    if swap {
        bytes.reverse();
    }
    out.copy_from_slice(bytes);
}

impl Context {
    /// `glReadPixels` with a packed type (`GL_UNSIGNED_SHORT_5_6_5`, ...): colour formats only,
    /// packed by the texture module's packer with the pack state.
    fn read_pixels_packed(
        &mut self,
        x: GLint,
        y: GLint,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        packed: PackedType,
        pixels: &mut [u8],
    ) {
        let Some(tf) = convert::tex_pixel_format(format) else {
            self.record_error(GL_INVALID_OPERATION);
            return;
        };
        if !packed.accepts(tf) {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        if width < 0 || height < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let (w, h) = (width as usize, height as usize);
        let ty = TexPixelType::Packed(packed);
        let Some(layout) = texpix::layout(&self.pack, 2, [w, h, 1], tf, ty) else {
            self.record_error(GL_INVALID_VALUE);
            return;
        };
        if pixels.len() < layout.end {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.flush_scene();
        let xfer = (!self.pixel_transfer.is_identity()).then(|| self.pixel_transfer.clone());
        let swap = self.pack.swap_bytes;
        for row in 0..h {
            for col in 0..w {
                let (wx, wy) = (x.saturating_add(col as i32), y.saturating_add(row as i32));
                let Some(rgba) = self.framebuffer.color_at(wx, wy) else {
                    continue;
                };
                let mut c = rgba.map(|v| v as f32 / 255.0);
                if let Some(t) = &xfer {
                    c = t.texel(false, c);
                }
                let at = layout.start + row * layout.row_stride + col * layout.group;
                texpix::pack_group(pixels, at, c, tf, ty, swap);
            }
        }
    }

    /// `glReadPixels(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8)` (EXT_packed_depth_stencil): each
    /// pixel one 32-bit word, the depth (after scale and bias) in the high 24 bits and the
    /// stencil index (after shift, offset and map) in the low 8. Another type is
    /// `GL_INVALID_ENUM`; a framebuffer without both buffers is `GL_INVALID_OPERATION`.
    fn read_depth_stencil(
        &mut self,
        x: GLint,
        y: GLint,
        width: GLsizei,
        height: GLsizei,
        type_: GLenum,
        pixels: &mut [u8],
    ) {
        if type_ != GL_UNSIGNED_INT_24_8_EXT {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        if width < 0 || height < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let cfg = self.framebuffer.config;
        if cfg.depth_bits == 0 || cfg.stencil_bits == 0 {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        let (w, h) = (width as usize, height as usize);
        let ty = TexPixelType::Packed(PackedType::UInt248);
        let Some(layout) =
            texpix::layout(&self.pack, 2, [w, h, 1], TexPixelFormat::DepthStencil, ty)
        else {
            self.record_error(GL_INVALID_VALUE);
            return;
        };
        if pixels.len() < layout.end {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.flush_scene();
        let depth_max = self.framebuffer.depth_max() as f64;
        let xfer = &self.pixel_transfer;
        let swap = self.pack.swap_bytes;
        for row in 0..h {
            for col in 0..w {
                let (wx, wy) = (x.saturating_add(col as i32), y.saturating_add(row as i32));
                // Pixels outside the window are undefined; the destination is left as is.
                let (Some(d), Some(s)) = (
                    self.framebuffer.depth_at(wx, wy),
                    self.framebuffer.stencil_at(wx, wy),
                ) else {
                    continue;
                };
                let d = xfer.depth(d as f64 / depth_max);
                let word = (depth_to_fixed(d, 0x00FF_FFFF) << 8) | xfer.stencil(s as i64) as u32;
                let at = layout.start + row * layout.row_stride + col * layout.group;
                let mut b = word.to_ne_bytes();
                if swap {
                    b.reverse();
                }
                if let Some(dst) = pixels.get_mut(at..at + 4) {
                    dst.copy_from_slice(&b);
                }
            }
        }
    }
}

//! `glBitmap` and `glDrawPixels` of colours recorded into the scene (`raster::pixels`)
//! instead of flushing it and shading each fragment on the caller's thread: the fragments are
//! the same (the twin test `tests/pixel_rect.rs`
//! `queued_pixel_rectangles_draw_what_the_per_pixel_route_draws` compares the two routes),
//! but text no longer waits for the workers at every glyph and the tiles shade it in
//! parallel.

use super::Context;
use crate::common::rect::Rect;
use crate::common::values::{PixelIndexType, TexPixelFormat, TexPixelType};
use crate::framebuffer::DrawTarget;
use crate::raster::pixels::{
    bitmap_row_bytes, direct_color, stores_directly, BitmapCommand, PixelsCommand,
};
use crate::raster::scene::Command;
use crate::raster::setup::Plane;
use crate::state::snapshot::TileDraw;
use crate::texture::pixels as texpix;

/// Coordinates past which the queued route leaves a pixel rectangle to the per-pixel route
/// (which saturates them; the window is far smaller).
const FAR: f64 = (1u64 << 40) as f64;

impl Context {
    /// Whether pixel rectangles go into the scene: not on the general path (which keeps the
    /// per-pixel route as the reference), and only when one colour buffer is drawn (the
    /// per-pixel route writes the resident buffer only, and the queued route must draw the
    /// same pixels).
    pub(super) fn pixel_rects_queued(&self) -> bool {
        !self.force_general_path && matches!(self.framebuffer.draw, DrawTarget::One(_))
    }

    /// Whether a `glDrawPixels` of colours goes into the scene: [`Context::pixel_rects_queued`],
    /// unit zoom and a raster position near the window.
    pub(super) fn color_pixels_queueable(&self) -> bool {
        let [x, y, _] = self.raster_pos.window;
        self.pixel_rects_queued()
            && self.pixel_transfer.zoom == [1.0, 1.0]
            && x.abs() < FAR
            && y.abs() < FAR
    }

    /// The clipped window pixels of a `size` rectangle at `origin`.
    fn clipped(&self, origin: [i64; 2], size: [usize; 2]) -> Rect {
        let b = self.scissored_window();
        let end = |o: i64, n: usize| o.saturating_add(n.min(i64::MAX as usize) as i64);
        let clamp = |v: i64, lo: i32, hi: i32| v.clamp(lo as i64, hi as i64) as i32;
        Rect {
            x0: clamp(origin[0], b.x0, b.x1),
            y0: clamp(origin[1], b.y0, b.y1),
            x1: clamp(end(origin[0], size[0]), b.x0, b.x1),
            y1: clamp(end(origin[1], size[1]), b.y0, b.y1),
        }
    }

    /// The constant attribute planes of a pixel-rectangle fragment of colour `color` in the
    /// scene: the last ones stored when they are the same bits, else stored now.
    fn pixel_planes(&mut self, ds: &TileDraw, color: [f32; 4]) -> u32 {
        let n = ds.attr_count;
        let mut planes = [Plane::constant(0.0); crate::common::attr::MAX_ATTRS];
        self.raster_planes_into(ds, color, &mut planes[..n]);
        let stored = &self.scene.planes;
        let bits = |p: &Plane| [p.a, p.b, p.c].map(f64::to_bits);
        if stored.len() >= n
            && stored[stored.len() - n..]
                .iter()
                .zip(&planes[..n])
                .all(|(a, b)| bits(a) == bits(b))
        {
            return (stored.len() - n) as u32;
        }
        self.scene.add_planes(&planes[..n])
    }

    /// The state index of the next queued command (after making room in the scene).
    fn queue_state(&mut self) -> (std::sync::Arc<super::snapshot::DrawState>, u32) {
        let ds = self.snapshot();
        if self.scene.is_full() {
            self.flush_scene();
        }
        self.flush_in_background();
        let state = self.scene.add_state(&ds.tile);
        (ds, state)
    }

    /// Records a bitmap whose lower left pixel is `origin`: its bits inside the window and
    /// scissor, and the raster position's attributes.
    pub(super) fn queue_bitmap(
        &mut self,
        origin: [i64; 2],
        size: [usize; 2],
        bitmap: &[u8],
        rows: &texpix::IndexRows,
    ) {
        let rect = self.clipped(origin, size);
        if rect.is_empty() {
            return;
        }
        let (ds, state) = self.queue_state();
        let color = self.raster_pos.color;
        let direct = stores_directly(&ds.tile).then(|| direct_color(color));
        let attrs = match direct {
            Some(_) => 0,
            None => self.pixel_planes(&ds.tile, color),
        };
        let u = self.unpack;
        let skip = u.skip_pixels.max(0) as usize;
        let width = (rect.x1 - rect.x0) as usize;
        let stride = bitmap_row_bytes(width);
        let bits = &mut self.scene.bitmap_bits;
        let at = bits.len();
        bits.reserve(stride * (rect.y1 - rect.y0) as usize);
        for y in rect.y0..rect.y1 {
            let row = rows.first_row + (y as i64 - origin[1]) as usize * rows.stride;
            let first = skip + (rect.x0 as i64 - origin[0]) as usize;
            let start = bits.len();
            match bitmap.get(row + first / 8..).and_then(|b| b.get(..stride)) {
                // Whole bytes in the stored order: copied.
                // (A glyph's rows are a byte or two: pushed, not a `memcpy` call each.)
                Some(src) if !u.lsb_first && first.is_multiple_of(8) => {
                    for &b in src {
                        bits.push(b);
                    }
                }
                _ => {
                    bits.resize(start + stride, 0);
                    for i in 0..width {
                        let set = texpix::read_index(
                            bitmap,
                            row,
                            first + i,
                            PixelIndexType::Bitmap,
                            false,
                            u.lsb_first,
                        );
                        bits[start + i / 8] |= (set as u8) << (7 - i % 8);
                    }
                }
            }
        }
        let z = self.raster_pos.window[2];
        if let Some(c) = BitmapCommand::new(state, rect, z, attrs, at as u32, direct) {
            self.scene.bin_all_planes(Command::Bitmap(c), rect);
        }
    }

    /// Records a `glDrawPixels` of colours (format `cf`, type `ty`) at unit zoom: the pixels
    /// inside the window and scissor, unpacked and converted now (pixel transfer included).
    /// False, with nothing drawn, when the data is shorter than the image or its layout
    /// overflows (`GL_INVALID_VALUE`).
    pub(super) fn queue_color_pixels(
        &mut self,
        data: &[u8],
        [w, h]: [usize; 2],
        cf: TexPixelFormat,
        ty: TexPixelType,
    ) -> bool {
        let u = self.unpack;
        let Some(layout) = texpix::layout(&u, 2, [w, h, 1], cf, ty) else {
            return false;
        };
        if data.len() < layout.end {
            return false;
        }
        if !self.raster_pos.valid {
            return true;
        }
        // The image starts at the raster position rounded to the nearest pixel corner (see
        // `draw_pixel_values`).
        let [xr, yr, z] = self.raster_pos.window;
        let origin = [(xr + 0.5).floor() as i64, (yr + 0.5).floor() as i64];
        let rect = self.clipped(origin, [w, h]);
        if rect.is_empty() {
            return true;
        }
        let (ds, state) = self.queue_state();
        let direct = stores_directly(&ds.tile);
        let attrs = match direct {
            true => 0,
            false => self.pixel_planes(&ds.tile, self.raster_pos.color),
        };
        let n = (rect.x1 - rect.x0) as usize;
        let first = (rect.x0 as i64 - origin[0]) as usize;
        let mut row = vec![[0f32; 4]; n];
        let t = &self.pixel_transfer;
        let identity = t.color_is_identity();
        let scene = &mut self.scene;
        let image = match direct {
            true => scene.pixel_bytes.len(),
            false => scene.pixel_colors.len(),
        };
        for y in rect.y0..rect.y1 {
            let j = (y as i64 - origin[1]) as usize;
            let at = layout.start + j * layout.row_stride + first * layout.group;
            texpix::unpack_row(data, at, layout.group, cf, ty, u.swap_bytes, &mut row);
            if !identity {
                for v in row.iter_mut() {
                    *v = t.color(*v);
                }
            }
            match direct {
                true => scene
                    .pixel_bytes
                    .extend(row.iter().map(|&c| direct_color(c))),
                false => scene.pixel_colors.extend_from_slice(&row),
            }
        }
        if let Some(c) = PixelsCommand::new(state, rect, z, attrs, image as u32, direct) {
            scene.bin_all_planes(Command::Pixels(c), rect);
        }
        true
    }
}

//! Bitmaps and colour pixel rectangles in the scene (`glBitmap`, `glDrawPixels` of colours at
//! unit zoom): recorded by the caller like any draw and shaded by the tiles in submission
//! order, so text and images no longer flush the scene and wait for the workers. Each
//! fragment is shaded as the per-pixel route shades it (the draw's span function with the
//! constant attribute planes of the raster position, the colour from the image), a row's
//! neighbouring fragments with the same values as one span. When the fragment stage would
//! only convert and store the colour ([`crate::fragment::key::FragmentKey::stores_color_only`]) the converted
//! bytes are stored directly.

use super::draw::TileDraw;
use super::scene::Scene;
use super::setup::Plane;
use crate::common::attr::{self, MAX_ATTRS};
use crate::common::fixed::color4_to_u8;
use crate::common::rect::Rect;
use crate::fragment::span::{Interpolants, PrimitiveShared, UnitLevels};
use crate::framebuffer::Tile;

use super::coarse::CoarseDepth;

/// The bytes the fragment stage stores for a pixel-rectangle colour `c` when the key
/// [`crate::fragment::key::FragmentKey::stores_color_only`]: the colour plane holds `c` clamped to [0, 1], the
/// span converts it to bytes and writes them.
#[inline]
pub fn direct_color(c: [f32; 4]) -> [u8; 4] {
    color4_to_u8(c.map(|v| v.clamp(0.0, 1.0)))
}

/// Whether fragments of `ds` with colour planes at `COLOR0..COLOR0 + 4` may be stored as
/// [`direct_color`] without running the span.
pub fn stores_directly(ds: &TileDraw) -> bool {
    ds.fragment.key.stores_color_only() && ds.attr_count >= attr::COLOR0 + 4
}

/// A `glBitmap`: the set bits of `rect` (already clipped to the window and scissor) are
/// fragments with the raster position's attributes.
#[derive(Clone, Copy, Debug)]
pub struct BitmapCommand {
    pub state: u32,
    /// The pixels (x0, y0, x1, y1), clipped.
    rect: [u16; 4],
    pub z: f64,
    /// Offset of the constant attribute planes in `Scene::planes` (unused when `direct`).
    pub attrs: u32,
    /// Offset in `Scene::bitmap_bits` of the clipped bitmap: one row per pixel row of
    /// `rect`, `(width + 7) / 8` bytes each, the first pixel in the high bit.
    pub bits: u32,
    /// The bytes every set bit stores, when the key stores colours directly.
    pub direct: Option<[u8; 4]>,
}

/// A `glDrawPixels` of colours at unit zoom: each pixel of `rect` (clipped) a fragment with
/// its own colour and the raster position's other attributes.
#[derive(Clone, Copy, Debug)]
pub struct PixelsCommand {
    pub state: u32,
    rect: [u16; 4],
    pub z: f64,
    /// Offset of the constant attribute planes in `Scene::planes` (unused when `direct`).
    pub attrs: u32,
    /// Offset of the colours, one row of `rect` after another: in `Scene::pixel_bytes` when
    /// `direct` (already converted), else in `Scene::pixel_colors`.
    pub image: u32,
    pub direct: bool,
}

fn compact(r: Rect) -> Option<[u16; 4]> {
    let b = |v: i32| u16::try_from(v).ok();
    Some([b(r.x0)?, b(r.y0)?, b(r.x1)?, b(r.y1)?])
}

fn expand(r: [u16; 4]) -> Rect {
    let [x0, y0, x1, y1] = r.map(i32::from);
    Rect { x0, y0, x1, y1 }
}

impl BitmapCommand {
    /// The command, or `None` when `rect` lies outside what the framebuffer can be.
    pub fn new(
        state: u32,
        rect: Rect,
        z: f64,
        attrs: u32,
        bits: u32,
        direct: Option<[u8; 4]>,
    ) -> Option<BitmapCommand> {
        Some(BitmapCommand {
            state,
            rect: compact(rect)?,
            z,
            attrs,
            bits,
            direct,
        })
    }

    pub fn rect(&self) -> Rect {
        expand(self.rect)
    }
}

impl PixelsCommand {
    /// The command, or `None` when `rect` lies outside what the framebuffer can be.
    pub fn new(
        state: u32,
        rect: Rect,
        z: f64,
        attrs: u32,
        image: u32,
        direct: bool,
    ) -> Option<PixelsCommand> {
        Some(PixelsCommand {
            state,
            rect: compact(rect)?,
            z,
            attrs,
            image,
            direct,
        })
    }

    pub fn rect(&self) -> Rect {
        expand(self.rect)
    }
}

/// Bytes of one row of a clipped bitmap `width` pixels wide.
#[inline]
pub fn bitmap_row_bytes(width: usize) -> usize {
    width.div_ceil(8)
}

/// Bits `i..i + n` (`n` at most 57) of a bitmap row (first pixel in the high bit of each
/// byte) as the high bits of a word, the rest zero; bytes past the row read as zero.
#[inline]
fn row_bits(row: &[u8], i: usize, n: usize) -> u64 {
    let at = i / 8;
    let mut b = [0u8; 8];
    let have = row.len().saturating_sub(at).min(8);
    b[..have].copy_from_slice(&row[at..at + have]);
    let word = u64::from_be_bytes(b) << (i % 8);
    word & !(u64::MAX >> n)
}

/// Calls `run(y, x0, x1)` for every run of set bits of the bitmap `c` inside `area` (a
/// tile's pixels), row by row.
fn bitmap_runs(c: &BitmapCommand, scene: &Scene, area: Rect, mut run: impl FnMut(i32, i32, i32)) {
    let r = c.rect();
    let part = r.intersect(&area);
    if part.is_empty() {
        return;
    }
    let stride = bitmap_row_bytes((r.x1 - r.x0) as usize);
    let bits = &scene.bitmap_bits[c.bits as usize..];
    let (i0, i1) = ((part.x0 - r.x0) as usize, (part.x1 - r.x0) as usize);
    for y in part.y0..part.y1 {
        let row = &bits[(y - r.y0) as usize * stride..][..stride];
        row_runs(row, i0, i1, |a, b| run(y, r.x0 + a as i32, r.x0 + b as i32));
    }
}

/// Calls `run(a, b)` for every run `a..b` of set bits among bits `i0..i1` of a bitmap row
/// (first pixel in the high bit of each byte), in order, 56 bits at a time.
fn row_runs(row: &[u8], i0: usize, i1: usize, mut run: impl FnMut(usize, usize)) {
    const CHUNK: usize = 56;
    // A run reaching the end of a chunk waits for the next one to end it.
    let mut open: Option<usize> = None;
    let mut i = i0;
    while i < i1 {
        let n = (i1 - i).min(CHUNK);
        let mut word = row_bits(row, i, n);
        let mut at = 0;
        while at < n {
            let zeros = (word.leading_zeros() as usize).min(n - at);
            if zeros > 0 {
                if let Some(s) = open.take() {
                    run(s, i + at);
                }
                at += zeros;
                if at == n {
                    break;
                }
                word <<= zeros;
            }
            // A set bit at `at`: its run goes on to the next clear bit (or past the chunk).
            let ones = (!word).leading_zeros() as usize;
            open.get_or_insert(i + at);
            at += ones;
            word = word.checked_shl(ones as u32).unwrap_or(0);
            if at < n {
                if let Some(s) = open.take() {
                    run(s, i + at);
                }
            }
        }
        i += n;
    }
    if let Some(s) = open {
        run(s, i1);
    }
}

/// Shades the part of bitmap `c` in `tile`.
pub fn shade_bitmap(
    c: &BitmapCommand,
    scene: &Scene,
    ds: &TileDraw,
    levels: &UnitLevels,
    coarse: &mut CoarseDepth,
    tile: &mut Tile,
) {
    let area = tile.rect();
    if let Some(rgba) = c.direct {
        bitmap_runs(c, scene, area, |y, x0, x1| {
            let i = tile.index(x0, y);
            tile.color[i..i + (x1 - x0) as usize].fill(rgba);
        });
        return;
    }
    if ds.fragment.key.depth_write {
        coarse.forget(tile, c.rect());
    }
    let at = c.attrs as usize;
    let attrs = &scene.planes[at..at + ds.attr_count];
    let shared = PrimitiveShared::new(levels);
    let it = constant_interpolants(c.z, attrs, &shared);
    bitmap_runs(c, scene, area, |y, x0, x1| {
        (ds.fragment.span)(&ds.fragment, tile, y, x0, x1, &it);
    });
}

/// Shades the part of pixel rectangle `c` in `tile`.
pub fn shade_pixels(
    c: &PixelsCommand,
    scene: &Scene,
    ds: &TileDraw,
    levels: &UnitLevels,
    coarse: &mut CoarseDepth,
    tile: &mut Tile,
) {
    let r = c.rect();
    let part = r.intersect(&tile.rect());
    if part.is_empty() {
        return;
    }
    let width = (r.x1 - r.x0) as usize;
    let n = (part.x1 - part.x0) as usize;
    let first = |y: i32| c.image as usize + (y - r.y0) as usize * width + (part.x0 - r.x0) as usize;
    if c.direct {
        for y in part.y0..part.y1 {
            let i = tile.index(part.x0, y);
            let src = first(y);
            tile.color[i..i + n].copy_from_slice(&scene.pixel_bytes[src..src + n]);
        }
        return;
    }
    if ds.fragment.key.depth_write {
        coarse.forget(tile, part);
    }
    let count = ds.attr_count.min(MAX_ATTRS);
    let at = c.attrs as usize;
    let mut planes = [Plane::constant(0.0); MAX_ATTRS];
    planes[..count].copy_from_slice(&scene.planes[at..at + count]);
    let colors = (attr::COLOR0 + 4).min(count);
    for y in part.y0..part.y1 {
        let row = &scene.pixel_colors[first(y)..first(y) + n];
        let mut i = 0;
        while i < n {
            // Neighbours with the same colour (bit for bit) are one span.
            let c0 = row[i];
            let mut e = i + 1;
            while e < n && row[e].map(f32::to_bits) == c0.map(f32::to_bits) {
                e += 1;
            }
            for k in attr::COLOR0..colors {
                planes[k] = Plane::constant(c0[k - attr::COLOR0].clamp(0.0, 1.0) as f64);
            }
            let shared = PrimitiveShared::new(levels);
            let it = constant_interpolants(c.z, &planes[..count], &shared);
            let x = part.x0 + i as i32;
            (ds.fragment.span)(&ds.fragment, tile, y, x, x + (e - i) as i32, &it);
            i = e;
        }
    }
}

/// The interpolants of a pixel-rectangle fragment: depth `z`, constant attributes.
fn constant_interpolants<'a>(
    z: f64,
    attrs: &'a [Plane],
    shared: &'a PrimitiveShared<'a>,
) -> Interpolants<'a> {
    Interpolants {
        z: Plane::constant(z),
        inv_w: Plane::constant(1.0),
        attrs,
        perspective: false,
        constant_primary: false,
        coverage: 1.0,
        shared,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `row_runs` finds exactly the runs of set bits the bits themselves give, over random
    /// rows of many widths and windows (runs across the 56-bit chunks, at the window's ends,
    /// all set, all clear).
    #[test]
    fn row_runs_are_the_runs_of_set_bits() {
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let mut runs_seen = 0;
        for case in 0..3000 {
            let width = 1 + (next() % 300) as usize;
            let bytes = bitmap_row_bytes(width);
            let row: Vec<u8> = (0..bytes)
                .map(|_| match case % 4 {
                    0 => 0xff,
                    1 => next() as u8 | next() as u8,
                    2 => next() as u8 & next() as u8,
                    _ => next() as u8,
                })
                .collect();
            let i0 = (next() % width as u64) as usize;
            let i1 = i0 + 1 + (next() % (width - i0) as u64) as usize;
            let bit = |i: usize| row[i / 8] >> (7 - i % 8) & 1 != 0;
            let mut want = Vec::new();
            let mut i = i0;
            while i < i1 {
                if bit(i) {
                    let s = i;
                    while i < i1 && bit(i) {
                        i += 1;
                    }
                    want.push((s, i));
                } else {
                    i += 1;
                }
            }
            let mut got = Vec::new();
            row_runs(&row, i0, i1, |a, b| got.push((a, b)));
            assert_eq!(got, want, "width {width}, bits {i0}..{i1}");
            runs_seen += want.len();
        }
        assert!(runs_seen > 10_000);
    }
}

//! The deferred scene: commands recorded since the last flush, each binned into the screen
//! tiles it touches. Every command refers to the `TileDraw` frozen at its draw.

use std::sync::Arc;

use super::draw::TileDraw;
use super::line::LineSetup;
use super::pixels::{BitmapCommand, PixelsCommand};
use super::prefetch;
use super::setup::{Edge, Plane};
use crate::common::rect::Rect;
use crate::framebuffer::Framebuffer;

/// A clear of part of the framebuffer.
#[derive(Clone, Copy, Debug)]
pub struct ClearCommand {
    pub rect: Rect,
    /// Colour and per-channel write mask.
    pub color: Option<([u8; 4], [bool; 4])>,
    pub depth: Option<u32>,
    /// Value and write mask.
    pub stencil: Option<(u8, u8)>,
}

/// A set-up triangle. Kept small (its planes live in `Scene::planes`, its edges are rebuilt
/// from its vertices by the worker): the caller's thread writes one per triangle into memory
/// the workers read last, and those stores miss the cache (the command was 112 bytes with its
/// edges; 40 now, equally fast when the machine's memory is idle).
#[derive(Clone, Copy, Debug)]
pub struct TriangleCommand {
    pub state: u32,
    /// Offset in `Scene::planes` of the window-z plane, then the 1/w plane, then the
    /// attribute planes (attribute/w).
    pub planes: u32,
    /// Pixels that may be covered (already inside the draw rectangle): x0, y0, x1, y1
    /// (framebuffers are at most `MAX_VIEWPORT_DIM` wide).
    bbox: [u16; 4],
    /// The snapped window positions (sub-pixel fixed point) in counter-clockwise order: inside
    /// the guard band, far from the limits of i32.
    xy: [[i32; 2]; 3],
    /// The primary colour is the same at the three vertices, its planes packed
    /// ([`TriangleCommand::constant_primary`], `Interpolants::constant_primary`).
    constant_primary: bool,
}

impl TriangleCommand {
    /// The command, or `None` when a coordinate does not fit (which clipping rules out).
    pub fn new(
        state: u32,
        planes: u32,
        bbox: Rect,
        xy: [[i64; 2]; 3],
        constant_primary: bool,
    ) -> Option<TriangleCommand> {
        let b = |v: i32| u16::try_from(v).ok();
        let p = |v: i64| i32::try_from(v).ok();
        Some(TriangleCommand {
            state,
            planes,
            bbox: [b(bbox.x0)?, b(bbox.y0)?, b(bbox.x1)?, b(bbox.y1)?],
            xy: [
                [p(xy[0][0])?, p(xy[0][1])?],
                [p(xy[1][0])?, p(xy[1][1])?],
                [p(xy[2][0])?, p(xy[2][1])?],
            ],
            constant_primary,
        })
    }

    /// Whether the primary colour is the same at the three vertices; its four live planes are
    /// then stored as two, the values packed three to a plane.
    #[inline(always)]
    pub fn constant_primary(&self) -> bool {
        self.constant_primary
    }

    /// How many planes the triangle has in `Scene::planes` (z, 1/w, the live attributes'),
    /// for its draw state `ds`.
    #[inline(always)]
    pub fn plane_count(&self, ds: &TileDraw) -> usize {
        2 + ds.live_attrs.count_ones() as usize - if self.constant_primary { 2 } else { 0 }
    }

    /// Pixels that may be covered.
    #[inline(always)]
    pub fn bbox(&self) -> Rect {
        let [x0, y0, x1, y1] = self.bbox.map(i32::from);
        Rect { x0, y0, x1, y1 }
    }

    /// The three edge functions and their biases ([`Edge::new`]).
    #[inline(always)]
    pub fn edges(&self) -> ([Edge; 3], [u8; 3]) {
        let p = self.xy.map(|v| v.map(i64::from));
        let [(e0, b0), (e1, b1), (e2, b2)] = [
            Edge::new(p[0], p[1]),
            Edge::new(p[1], p[2]),
            Edge::new(p[2], p[0]),
        ];
        ([e0, e1, e2], [b0, b1, b2])
    }
}

/// A rectangle of fragments with constant attributes: a point, a column of a line, or one
/// pixel of an antialiased point or line with its coverage.
#[derive(Clone, Copy, Debug)]
pub struct RectCommand {
    pub state: u32,
    /// Pixels covered (already inside the draw rectangle).
    pub rect: Rect,
    pub z: f64,
    /// Offset of the constant attribute planes in `Scene::planes`.
    pub attrs: u32,
    /// Coverage multiplied into the fragment alpha (1 when not antialiased; section 3.11).
    pub coverage: f32,
}

/// A line segment: its set-up is `Scene::lines[line]` (each tile draws its own part).
#[derive(Clone, Copy, Debug)]
pub struct LineCommand {
    pub state: u32,
    pub line: u32,
}

/// Work recorded for the tiles.
#[derive(Clone, Copy, Debug)]
pub enum Command {
    Clear(ClearCommand),
    Triangle(TriangleCommand),
    Rect(RectCommand),
    Line(LineCommand),
    Bitmap(BitmapCommand),
    Pixels(PixelsCommand),
}

/// Commands recorded since the last flush, per-tile bins, and what they reference.
#[derive(Debug, Default)]
pub struct Scene {
    pub commands: Vec<Command>,
    pub bins: Vec<Vec<u32>>,
    pub states: Vec<Arc<TileDraw>>,
    pub planes: Vec<Plane>,
    /// Line segments' set-ups and their end points' attributes.
    pub lines: Vec<LineSetup>,
    pub line_attrs: Vec<f32>,
    /// The clipped bits of bitmaps (`pixels::BitmapCommand`).
    pub bitmap_bits: Vec<u8>,
    /// Pixel rectangles' colours (`pixels::PixelsCommand`): converted to bytes, or as the
    /// fragments' colours.
    pub pixel_bytes: Vec<[u8; 4]>,
    pub pixel_colors: Vec<[f32; 4]>,
    tiles_x: usize,
    tiles_y: usize,
    /// log2 of the framebuffer's tile side.
    tile_shift: u32,
    /// Bins per sample plane of a multisample framebuffer (`tiles_x * tiles_y`).
    plane_tiles: usize,
    /// The first bin of the sample plane that commands are binned into now (0 but while a
    /// multisample draw records one sample's pass, `Scene::set_sample_plane`).
    bin_base: usize,
}

/// Recorded commands that force a flush: bounds the scene's memory (each command costs at most a
/// few hundred bytes plus its planes).
pub const MAX_COMMANDS: usize = 1 << 20;
/// Attribute planes that force a flush.
pub const MAX_PLANES: usize = 1 << 23;
/// Bytes of bitmap bits, and of pixel rectangles' colours, that force a flush.
pub const MAX_PIXEL_BYTES: usize = 1 << 26;

impl Scene {
    pub fn new(fb: &Framebuffer) -> Scene {
        Scene {
            // Not `fb.tiles.len()`: the tiles are away while workers shade in the background.
            bins: vec![Vec::new(); fb.plane_tiles * fb.samples],
            tiles_x: fb.tiles_x,
            tiles_y: fb.tiles_y,
            tile_shift: fb.tile_shift,
            plane_tiles: fb.plane_tiles,
            bin_base: 0,
            ..Scene::default()
        }
    }

    pub fn is_empty(&self) -> bool {
        self.commands.is_empty()
    }

    /// True when the scene should be flushed before more is recorded.
    pub fn is_full(&self) -> bool {
        self.commands.len() >= MAX_COMMANDS
            || self.planes.len() >= MAX_PLANES
            || self.line_attrs.len() >= MAX_PLANES
            || self.bitmap_bits.len() >= MAX_PIXEL_BYTES
            || self.pixel_bytes.len() * 4 + self.pixel_colors.len() * 16 >= MAX_PIXEL_BYTES
    }

    /// Index of `ds` in the state table (reused when it is the last one added).
    pub fn add_state(&mut self, ds: &Arc<TileDraw>) -> u32 {
        if let Some(last) = self.states.last() {
            if Arc::ptr_eq(last, ds) {
                return (self.states.len() - 1) as u32;
            }
        }
        self.states.push(ds.clone());
        (self.states.len() - 1) as u32
    }

    /// Stores attribute planes and returns their offset.
    pub fn add_planes(&mut self, planes: &[Plane]) -> u32 {
        let offset = self.planes.len() as u32;
        self.planes.extend_from_slice(planes);
        offset
    }

    /// Bins commands into sample plane `sample` from now on (see `Framebuffer::tiles`).
    pub fn set_sample_plane(&mut self, sample: usize) {
        self.bin_base = sample * self.plane_tiles;
    }

    /// The sample plane commands are binned into.
    pub fn sample_plane(&self) -> usize {
        self.bin_base.checked_div(self.plane_tiles).unwrap_or(0)
    }

    /// Records `cmd` in every tile that `rect` touches, in every sample plane (clears and
    /// pixel rectangles cover every sample of their pixels).
    pub fn bin_all_planes(&mut self, cmd: Command, rect: Rect) {
        if self.bins.len() <= self.plane_tiles {
            return self.bin(cmd, rect);
        }
        if rect.is_empty() {
            return;
        }
        let index = self.push(cmd);
        let base = self.bin_base;
        let planes = self.bins.len().checked_div(self.plane_tiles).unwrap_or(1);
        for p in 0..planes {
            self.bin_base = p * self.plane_tiles;
            self.bin_again(index, rect);
        }
        self.bin_base = base;
    }

    /// log2 of the tiles' side.
    pub fn tile_shift(&self) -> u32 {
        self.tile_shift
    }

    /// Records `cmd` in every tile that `rect` touches.
    #[inline(always)]
    pub fn bin(&mut self, cmd: Command, rect: Rect) {
        if rect.is_empty() {
            return;
        }
        let index = self.push(cmd);
        self.bin_again(index, rect);
    }

    /// Records a line command in no tile yet (see [`Scene::bin_again`]); returns its index.
    pub fn add_line(&mut self, cmd: Command) -> u32 {
        self.push(cmd)
    }

    #[inline(always)]
    fn push(&mut self, cmd: Command) -> u32 {
        let index = self.commands.len() as u32;
        prefetch::write_past(
            &self.commands,
            prefetch::WRITE_AHEAD,
            std::mem::size_of::<Command>(),
        );
        self.commands.push(cmd);
        index
    }

    /// Records command `index` in every tile that `rect` touches (the rectangles of one
    /// command must not share a tile).
    #[inline(always)]
    pub fn bin_again(&mut self, index: u32, rect: Rect) {
        if rect.is_empty() {
            return;
        }
        let s = self.tile_shift;
        let tx0 = (rect.x0.max(0) >> s) as usize;
        let ty0 = (rect.y0.max(0) >> s) as usize;
        let tx1 = (((rect.x1 - 1).max(0) >> s) as usize).min(self.tiles_x.saturating_sub(1));
        let ty1 = (((rect.y1 - 1).max(0) >> s) as usize).min(self.tiles_y.saturating_sub(1));
        for ty in ty0..=ty1 {
            for tx in tx0..=tx1 {
                let bin = &mut self.bins[self.bin_base + ty * self.tiles_x + tx];
                // The bin's next line (its entries are 4 bytes, written one by one).
                prefetch::write_past(bin, 64, 4);
                bin.push(index);
            }
        }
    }

    /// Forgets all recorded work (after it has been executed).
    pub fn reset(&mut self) {
        self.commands.clear();
        for b in &mut self.bins {
            b.clear();
        }
        self.states.clear();
        self.planes.clear();
        self.lines.clear();
        self.line_attrs.clear();
        self.bitmap_bits.clear();
        self.pixel_bytes.clear();
        self.pixel_colors.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn commands_stay_small() {
        // The caller writes one per triangle (see `TriangleCommand`).
        assert!(
            std::mem::size_of::<Command>() <= 48,
            "{}",
            std::mem::size_of::<Command>()
        );
    }
}

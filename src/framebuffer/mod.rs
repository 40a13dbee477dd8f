//! Tiled framebuffer storage: colour (RGBA8), depth and stencil, each split into square tiles so
//! that worker threads own disjoint memory while shading (no locks, no `unsafe`).
//!
//! Coordinates are GL window coordinates: (0, 0) is the lower-left pixel.

pub mod accum;
pub mod image;
pub mod pixels;

/// Side of a square tile in pixels.
pub const TILE: usize = 64;
/// Pixels per tile.
pub const TILE_PIXELS: usize = TILE * TILE;

/// One tile of every buffer.
#[derive(Clone, Debug, Default)]
pub struct Tile {
    /// Window x of the tile's lower-left pixel.
    pub x0: i32,
    /// Window y of the tile's lower-left pixel.
    pub y0: i32,
    /// RGBA8 pixels, bytes in R, G, B, A order; row-major from the bottom row.
    pub color: Vec<[u8; 4]>,
    /// Depth values as unsigned integers in `0..=depth_max`.
    pub depth: Vec<u32>,
    /// Stencil values.
    pub stencil: Vec<u8>,
    /// Fragments that passed the depth and stencil tests in draws counted by an occlusion
    /// query (`FragmentKey::count_samples`), summed and cleared by `glEndQuery`.
    pub samples_passed: u64,
}

impl Tile {
    /// Index of window pixel (x, y) within the tile; the pixel must lie in it.
    #[inline(always)]
    pub fn index(&self, x: i32, y: i32) -> usize {
        (y - self.y0) as usize * TILE + (x - self.x0) as usize
    }

    /// The window pixels the tile covers.
    pub fn rect(&self) -> crate::common::rect::Rect {
        let t = TILE as i32;
        crate::common::rect::Rect {
            x0: self.x0,
            y0: self.y0,
            x1: self.x0 + t,
            y1: self.y0 + t,
        }
    }
}

/// Which buffers a framebuffer has and their depths.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FramebufferConfig {
    /// Depth bits: 0, 16, 24 or 32.
    pub depth_bits: u32,
    /// Stencil bits: 0 or 8.
    pub stencil_bits: u32,
    /// Accumulation bits per channel (0 or 16, signed).
    pub accum_bits: u32,
    /// Front and back colour buffers (a GLX/EGL window); `false` is one front buffer (OSMesa).
    pub double_buffer: bool,
}

impl Default for FramebufferConfig {
    fn default() -> Self {
        FramebufferConfig {
            depth_bits: 24,
            stencil_bits: 8,
            accum_bits: 0,
            double_buffer: false,
        }
    }
}

/// One of the colour buffers of a window.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorBuffer {
    Front,
    Back,
}

/// Where drawing goes (`glDrawBuffer` resolved against the buffers that exist).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrawTarget {
    /// `GL_NONE`: no colour buffer is written (depth and stencil still are).
    None,
    /// One colour buffer.
    One(ColorBuffer),
    /// Both front and back (`GL_FRONT_AND_BACK`, `GL_LEFT` on a double-buffered window).
    Both,
}

/// The tiled colour/depth/stencil buffers of one context.
#[derive(Clone, Debug)]
pub struct Framebuffer {
    pub width: i32,
    pub height: i32,
    pub tiles_x: usize,
    pub tiles_y: usize,
    pub tiles: Vec<Tile>,
    pub config: FramebufferConfig,
    /// Which colour buffer the tiles' `color` storage holds at the moment.
    pub(crate) resident: ColorBuffer,
    /// The other colour buffer of a double-buffered framebuffer, per tile (empty otherwise).
    /// Switching buffers exchanges these vectors with the tiles' ones (no pixel copies).
    pub(crate) parked: Vec<Vec<[u8; 4]>>,
    /// Where the next flushed drawing goes.
    pub(crate) draw: DrawTarget,
    /// The buffer that reads (`color_at`, `glReadPixels`, `glCopyTexImage`) see.
    pub(crate) read: ColorBuffer,
    /// The accumulation buffer (empty without accumulation bits): RGBA as signed 16-bit
    /// fixed point over [-1, 1], row-major from the bottom row. Not tiled: only `glAccum` and
    /// its clear touch it, after the scene is flushed.
    pub accum: Vec<[i16; 4]>,
}

impl Framebuffer {
    /// A framebuffer of `width` x `height` pixels (each at least 0), cleared to zero colour,
    /// maximum depth and zero stencil.
    pub fn new(width: i32, height: i32, config: FramebufferConfig) -> Framebuffer {
        let width = width.max(0);
        let height = height.max(0);
        let tiles_x = (width as usize).div_ceil(TILE);
        let tiles_y = (height as usize).div_ceil(TILE);
        let depth_max = depth_max(config.depth_bits);
        let mut tiles = Vec::with_capacity(tiles_x * tiles_y);
        for ty in 0..tiles_y {
            for tx in 0..tiles_x {
                tiles.push(Tile {
                    x0: (tx * TILE) as i32,
                    y0: (ty * TILE) as i32,
                    color: vec![[0; 4]; TILE_PIXELS],
                    depth: vec![depth_max; TILE_PIXELS],
                    stencil: vec![0; TILE_PIXELS],
                    samples_passed: 0,
                });
            }
        }
        let (parked, initial) = if config.double_buffer {
            (
                vec![vec![[0; 4]; TILE_PIXELS]; tiles.len()],
                ColorBuffer::Back,
            )
        } else {
            (Vec::new(), ColorBuffer::Front)
        };
        let accum = if config.accum_bits > 0 {
            vec![[0; 4]; width as usize * height as usize]
        } else {
            Vec::new()
        };
        Framebuffer {
            width,
            height,
            tiles_x,
            tiles_y,
            tiles,
            config,
            resident: initial,
            parked,
            draw: DrawTarget::One(initial),
            read: initial,
            accum,
        }
    }

    /// Whether there are front and back colour buffers.
    pub fn is_double_buffered(&self) -> bool {
        self.config.double_buffer
    }

    /// Makes the tiles' colour storage hold `buffer` (exchanging it with the parked one).
    /// Single-buffered framebuffers only have the front buffer: nothing changes.
    pub(crate) fn make_resident(&mut self, buffer: ColorBuffer) {
        if self.resident == buffer || self.parked.len() != self.tiles.len() {
            return;
        }
        for (tile, parked) in self.tiles.iter_mut().zip(self.parked.iter_mut()) {
            std::mem::swap(&mut tile.color, parked);
        }
        self.resident = buffer;
    }

    /// Presents the back buffer: its content is copied to the front buffer and stays in the
    /// back buffer, which is what Mesa's software (xlib/drisw) `glXSwapBuffers` and
    /// `eglSwapBuffers` do (GLX leaves the back buffer undefined; programs that draw over
    /// the previous frame, like xscreensaver's flurry, rely on this copy). No-op when
    /// single-buffered.
    pub fn swap_buffers(&mut self) {
        if self.parked.len() != self.tiles.len() {
            return;
        }
        for (tile, parked) in self.tiles.iter_mut().zip(self.parked.iter_mut()) {
            match self.resident {
                ColorBuffer::Back => parked.copy_from_slice(&tile.color),
                ColorBuffer::Front => tile.color.copy_from_slice(parked),
            }
        }
    }

    /// Colour of window pixel (x, y) in `buffer` (the front buffer when single-buffered).
    pub fn color_in(&self, buffer: ColorBuffer, x: i32, y: i32) -> Option<[u8; 4]> {
        self.locate(x, y).map(|(t, i)| {
            if buffer == self.resident || self.parked.len() != self.tiles.len() {
                self.tiles[t].color[i]
            } else {
                self.parked[t][i]
            }
        })
    }

    /// The largest stored depth value.
    pub fn depth_max(&self) -> u32 {
        depth_max(self.config.depth_bits)
    }

    #[inline]
    fn locate(&self, x: i32, y: i32) -> Option<(usize, usize)> {
        if x < 0 || y < 0 || x >= self.width || y >= self.height {
            return None;
        }
        let (x, y) = (x as usize, y as usize);
        Some((
            (y / TILE) * self.tiles_x + x / TILE,
            (y % TILE) * TILE + x % TILE,
        ))
    }

    /// Colour of window pixel (x, y) in the read buffer (`glReadBuffer`), or `None` outside
    /// the framebuffer.
    pub fn color_at(&self, x: i32, y: i32) -> Option<[u8; 4]> {
        self.color_in(self.read, x, y)
    }

    /// The tile holding window pixel (x, y).
    pub fn tile_index(&self, x: i32, y: i32) -> Option<usize> {
        self.locate(x, y).map(|(t, _)| t)
    }

    /// The colour of window pixel (x, y), for writing.
    pub fn color_mut(&mut self, x: i32, y: i32) -> Option<&mut [u8; 4]> {
        self.locate(x, y).map(|(t, i)| &mut self.tiles[t].color[i])
    }

    /// Depth of window pixel (x, y) as stored.
    pub fn depth_at(&self, x: i32, y: i32) -> Option<u32> {
        self.locate(x, y).map(|(t, i)| self.tiles[t].depth[i])
    }

    /// Stencil of window pixel (x, y).
    pub fn stencil_at(&self, x: i32, y: i32) -> Option<u8> {
        self.locate(x, y).map(|(t, i)| self.tiles[t].stencil[i])
    }

    /// Overwrites the colour of window pixel (x, y) in the buffer the tiles hold (used by the C
    /// ABI, single-buffered, to adopt a caller's buffer).
    pub fn set_color(&mut self, x: i32, y: i32, rgba: [u8; 4]) {
        if let Some((t, i)) = self.locate(x, y) {
            self.tiles[t].color[i] = rgba;
        }
    }

    /// The colour buffer the tiles hold (the only one of a single-buffered framebuffer) as
    /// tightly packed RGBA8 rows, bottom row first.
    pub fn color_rows_bottom_up(&self) -> Vec<u8> {
        let w = self.width.max(0) as usize;
        let mut out = Vec::with_capacity(w * self.height.max(0) as usize * 4);
        for y in 0..self.height.max(0) as usize {
            for tx in 0..self.tiles_x {
                let tile = &self.tiles[(y / TILE) * self.tiles_x + tx];
                let row = (y % TILE) * TILE;
                let n = TILE.min(w - tx * TILE);
                out.extend_from_slice(bytemuck::cast_slice(&tile.color[row..row + n]));
            }
        }
        out
    }
}

/// The largest depth value for a depth buffer of `bits` bits (0 bits behaves like 24 for
/// storage; the depth test is skipped without a depth buffer).
pub fn depth_max(bits: u32) -> u32 {
    match bits {
        0 => 0x00FF_FFFF,
        32.. => u32::MAX,
        b => (1u32 << b) - 1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packed_rows_match_per_pixel_reads() {
        let mut fb = Framebuffer::new(70, 5, FramebufferConfig::default());
        for y in 0..5 {
            for x in 0..70 {
                fb.set_color(x, y, [x as u8, y as u8, (x * y) as u8, 7]);
            }
        }
        let rows = fb.color_rows_bottom_up();
        assert_eq!(rows.len(), 70 * 5 * 4);
        for y in 0..5 {
            for x in 0..70 {
                let o = ((y * 70 + x) * 4) as usize;
                assert_eq!(&rows[o..o + 4], &fb.color_at(x, y).unwrap());
            }
        }
    }
}

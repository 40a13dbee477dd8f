//! Tiled framebuffer storage: colour (RGBA8), depth and stencil, each split into square tiles so
//! that worker threads own disjoint memory while shading (no locks, no `unsafe`).
//!
//! Coordinates are GL window coordinates: (0, 0) is the lower-left pixel.

pub mod image;

/// Side of a square tile in pixels, unless [`TILE_ENV`] chooses another.
pub const TILE: usize = 64;
/// The tile sides [`TILE_ENV`] may choose.
pub const TILE_SIZES: [usize; 4] = [16, 32, 64, 128];
/// The environment variable that chooses the tile side of the framebuffers a process makes:
/// `TILEGL_TILE=16`, `32`, `64` or `128` (other values, or none, give [`TILE`]). Read once, at
/// the first framebuffer; the pictures are the same for every size
/// (`conformance/tests/determinism.rs`), only the work split changes.
pub const TILE_ENV: &str = "TILEGL_TILE";

/// log2 of the tile side framebuffers get, once known (0: not read yet).
static TILE_SHIFT: std::sync::atomic::AtomicU32 = std::sync::atomic::AtomicU32::new(0);

/// log2 of the tile side new framebuffers get ([`TILE_ENV`], else [`TILE`]).
pub fn tile_shift() -> u32 {
    match TILE_SHIFT.load(std::sync::atomic::Ordering::Relaxed) {
        0 => {
            let side = std::env::var(TILE_ENV)
                .ok()
                .and_then(|v| v.trim().parse::<usize>().ok())
                .filter(|s| TILE_SIZES.contains(s))
                .unwrap_or(TILE);
            let shift = side.trailing_zeros();
            TILE_SHIFT.store(shift, std::sync::atomic::Ordering::Relaxed);
            shift
        }
        s => s,
    }
}

/// One tile of every buffer.
#[derive(Clone, Debug, Default)]
pub struct Tile {
    /// Window x of the tile's lower-left pixel.
    pub x0: i32,
    /// Window y of the tile's lower-left pixel.
    pub y0: i32,
    /// log2 of the tile's side (its rows are `1 << shift` pixels apart).
    pub shift: u32,
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
        (((y - self.y0) as usize) << self.shift) + (x - self.x0) as usize
    }

    /// The tile's side in pixels.
    #[inline(always)]
    pub fn side(&self) -> i32 {
        1 << self.shift
    }

    /// The window pixels the tile covers.
    pub fn rect(&self) -> crate::common::rect::Rect {
        let t = self.side();
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
    /// Samples per pixel of a multisample buffer (ARB_multisample, GL 1.3): 0 or 1 for none
    /// (`GL_SAMPLE_BUFFERS` 0), else 2 or 4 ([`SAMPLE_POSITIONS`]). Each sample has its own
    /// plane of tiles (colour, depth, stencil).
    pub samples: u32,
}

impl Default for FramebufferConfig {
    fn default() -> Self {
        FramebufferConfig {
            depth_bits: 24,
            stencil_bits: 8,
            accum_bits: 0,
            double_buffer: false,
            samples: 0,
        }
    }
}

/// The sample counts a multisample framebuffer may have.
pub const SAMPLE_COUNTS: [u32; 2] = [2, 4];

/// The position of each sample within its pixel, in GL window convention (y up, (0, 0) the
/// pixel's lower-left corner), for `n` samples (`None` for a count without a pattern). 4x is
/// the standard pattern llvmpipe uses, (0.375, 0.125), (0.875, 0.375), (0.125, 0.625),
/// (0.625, 0.875) in its y-down convention, flipped; 2x the standard 2x pattern, (0.75, 0.75),
/// (0.25, 0.25) y-down, flipped.
pub fn sample_positions(n: u32) -> Option<&'static [[f64; 2]]> {
    match n {
        2 => Some(&SAMPLE_POSITIONS_2X),
        4 => Some(&SAMPLE_POSITIONS),
        _ => None,
    }
}

/// The 4x sample positions (see [`sample_positions`]).
pub const SAMPLE_POSITIONS: [[f64; 2]; 4] = [
    [0.375, 0.875],
    [0.875, 0.625],
    [0.125, 0.375],
    [0.625, 0.125],
];
/// The 2x sample positions (see [`sample_positions`]).
pub const SAMPLE_POSITIONS_2X: [[f64; 2]; 2] = [[0.75, 0.25], [0.25, 0.75]];

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
    /// log2 of the tiles' side ([`tile_shift`] when the framebuffer was made).
    pub tile_shift: u32,
    /// The tiles of every sample plane: sample `s`'s tile `t` (of `tiles_x * tiles_y`) is
    /// `tiles[s * plane_tiles + t]`. Without a multisample buffer there is one plane.
    pub tiles: Vec<Tile>,
    /// Tiles per sample plane (`tiles_x * tiles_y`).
    pub plane_tiles: usize,
    /// Sample planes (1 without a multisample buffer).
    pub samples: usize,
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
    /// The colour components the colour buffer has (R, G, B, A), when not all four: reads
    /// give 0 for a missing R, G or B and the largest value for a missing A (a framebuffer
    /// object's luminance, alpha, red, RG or RGB image, ARB_framebuffer_object section
    /// 4.3.2). The tiles hold what was drawn; the image keeps only its components.
    pub(crate) components: Option<[bool; 4]>,
}

impl Framebuffer {
    /// A framebuffer of `width` x `height` pixels (each at least 0), cleared to zero colour,
    /// maximum depth and zero stencil.
    pub fn new(width: i32, height: i32, config: FramebufferConfig) -> Framebuffer {
        let width = width.max(0);
        let height = height.max(0);
        let shift = tile_shift();
        let side = 1usize << shift;
        let pixels = side * side;
        let tiles_x = (width as usize).div_ceil(side);
        let tiles_y = (height as usize).div_ceil(side);
        let depth_max = depth_max(config.depth_bits);
        let samples = if sample_positions(config.samples).is_some() {
            config.samples as usize
        } else {
            1
        };
        let plane_tiles = tiles_x * tiles_y;
        let mut tiles = Vec::with_capacity(plane_tiles * samples);
        for _ in 0..samples {
            for ty in 0..tiles_y {
                for tx in 0..tiles_x {
                    tiles.push(Tile {
                        x0: (tx * side) as i32,
                        y0: (ty * side) as i32,
                        shift,
                        color: vec![[0; 4]; pixels],
                        depth: vec![depth_max; pixels],
                        stencil: vec![0; pixels],
                        samples_passed: 0,
                    });
                }
            }
        }
        let (parked, initial) = if config.double_buffer {
            (vec![vec![[0; 4]; pixels]; tiles.len()], ColorBuffer::Back)
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
            tile_shift: shift,
            tiles,
            plane_tiles,
            samples,
            config,
            resident: initial,
            parked,
            draw: DrawTarget::One(initial),
            read: initial,
            accum,
            components: None,
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

    /// Colour of window pixel (x, y) in `buffer` (the front buffer when single-buffered); of
    /// a multisample buffer, the average of its samples (the resolve).
    #[inline]
    pub fn color_in(&self, buffer: ColorBuffer, x: i32, y: i32) -> Option<[u8; 4]> {
        let c = if self.samples > 1 {
            self.resolved_in(buffer, x, y)?
        } else {
            let (t, i) = self.locate(x, y)?;
            if buffer == self.resident || self.parked.len() != self.tiles.len() {
                self.tiles[t].color[i]
            } else {
                self.parked[t][i]
            }
        };
        Some(match self.components {
            None => c,
            Some(has) => [
                if has[0] { c[0] } else { 0 },
                if has[1] { c[1] } else { 0 },
                if has[2] { c[2] } else { 0 },
                if has[3] { c[3] } else { 255 },
            ],
        })
    }

    /// [`Framebuffer::color_in`] of a multisample buffer.
    #[cold]
    #[inline(never)]
    fn resolved_in(&self, buffer: ColorBuffer, x: i32, y: i32) -> Option<[u8; 4]> {
        self.locate(x, y).map(|(t, i)| {
            let read = |t: usize| {
                if buffer == self.resident || self.parked.len() != self.tiles.len() {
                    self.tiles[t].color[i]
                } else {
                    self.parked[t][i]
                }
            };
            resolve(
                (0..self.samples).map(|s| read(t + s * self.plane_tiles)),
                self.samples,
            )
        })
    }

    /// The indices in `tiles` of tile `t` (of the first plane) in every sample plane.
    #[inline]
    pub fn sample_tiles(&self, t: usize) -> impl Iterator<Item = usize> {
        let plane = self.plane_tiles;
        (0..self.samples).map(move |s| t + s * plane)
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
        let (s, m) = (self.tile_shift, (1usize << self.tile_shift) - 1);
        Some(((y >> s) * self.tiles_x + (x >> s), ((y & m) << s) + (x & m)))
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
            for s in 0..self.samples {
                let t = t + s * self.plane_tiles;
                self.tiles[t].color[i] = rgba;
            }
        }
    }

    /// Overwrites the stored depth of window pixel (x, y) (framebuffer objects load their
    /// attached images so).
    pub fn set_depth(&mut self, x: i32, y: i32, depth: u32) {
        if let Some((t, i)) = self.locate(x, y) {
            for s in 0..self.samples {
                let t = t + s * self.plane_tiles;
                self.tiles[t].depth[i] = depth;
            }
        }
    }

    /// Overwrites the stencil index of window pixel (x, y).
    pub fn set_stencil(&mut self, x: i32, y: i32, stencil: u8) {
        if let Some((t, i)) = self.locate(x, y) {
            for s in 0..self.samples {
                let t = t + s * self.plane_tiles;
                self.tiles[t].stencil[i] = stencil;
            }
        }
    }

    /// The colour buffer the tiles hold (the only one of a single-buffered framebuffer) as
    /// tightly packed RGBA8 rows, bottom row first.
    pub fn color_rows_bottom_up(&self) -> Vec<u8> {
        let w = self.width.max(0) as usize;
        let mut out = Vec::with_capacity(w * self.height.max(0) as usize * 4);
        for y in 0..self.height.max(0) as usize {
            let (s, side) = (self.tile_shift, 1usize << self.tile_shift);
            for tx in 0..self.tiles_x {
                let tile = &self.tiles[(y >> s) * self.tiles_x + tx];
                let row = (y & (side - 1)) << s;
                let n = side.min(w - tx * side);
                if self.samples > 1 {
                    let t = (y >> s) * self.tiles_x + tx;
                    for i in row..row + n {
                        let rgba = resolve(
                            self.sample_tiles(t).map(|t| self.tiles[t].color[i]),
                            self.samples,
                        );
                        out.extend_from_slice(&rgba);
                    }
                } else {
                    out.extend_from_slice(bytemuck::cast_slice(&tile.color[row..row + n]));
                }
            }
        }
        out
    }
}

/// The resolved colour of a pixel's `n` samples, `samples` in sample order: each channel's
/// average, computed as llvmpipe's resolve computes it (each byte to a float c x f32(1 / 255), summed
/// in f32 in sample order, times 1 / n, times 255, rounded to nearest with ties to even), so
/// that the ties of half-covered pixels fall the same way: 255, 255, 26, 26 resolve to 141
/// but 26, 26, 255, 255 to 140, and 0, 0, 0, 26 to 7, not 6 (`tests/x11.rs`
/// `glx_multisample_frame_matches_mesa`). Within
/// half a unit of the exact average either way.
#[inline]
pub fn resolve(samples: impl Iterator<Item = [u8; 4]>, n: usize) -> [u8; 4] {
    let mut sum = [0f32; 4];
    for c in samples {
        for k in 0..4 {
            sum[k] += f32::from(c[k]) * (1.0 / 255.0);
        }
    }
    let scale = 1.0 / n.max(1) as f32;
    sum.map(|v| ((v * scale) * 255.0).round_ties_even().clamp(0.0, 255.0) as u8)
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

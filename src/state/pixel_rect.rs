//! Pixel rectangles and bitmaps: the current raster position (section 2.13, `glRasterPos`,
//! `glWindowPos`), pixel transfer and maps (3.6.3-3.6.5), `glPixelZoom`, `glDrawPixels`
//! (3.6.4), `glBitmap` (3.7) and `glCopyPixels` (4.3.3).
//!
//! These draws run immediately on the flushed framebuffer: each fragment goes through the
//! draw's span function (texturing, fog, the per-fragment operations) with constant
//! attributes, exactly as a one-pixel primitive would. Stencil-index data is written to the
//! stencil buffer directly (only the scissor and the stencil write mask apply).

use glam::Vec4;

use super::Context;
use crate::common::fixed::depth_to_fixed;
use crate::common::limits::MAX_TEXTURE_UNITS;
use crate::common::values::{
    CopyPixelsType, DrawPixelsFormat, PackedType, PixelIndexType, PixelMap, PixelRectQuery,
    PixelTransferParam, TexPixelFormat, TexPixelType,
};
use crate::fragment::span::{Interpolants, PrimitiveShared, UnitLevels};
use crate::gl::convert;
use crate::gl::enums::*;
use crate::primitive::clip::point_visible;
use crate::raster::setup::Plane;
use crate::state::get::StateValue;
use crate::state::snapshot::{attr, TileDraw};
use crate::texture::pixels as texpix;
use crate::vertex::immediate::ImmVertex;
use crate::vertex::transform;

/// `GL_MAX_PIXEL_MAP_TABLE`.
pub const MAX_PIXEL_MAP_TABLE: usize = 256;

/// The current raster position and its associated data (table 6.5).
#[derive(Clone, Copy, Debug)]
pub struct RasterPos {
    pub valid: bool,
    /// Window x, y, z (not rounded).
    pub window: [f64; 3],
    pub color: [f32; 4],
    pub secondary: [f32; 4],
    pub texcoords: [[f32; 4]; MAX_TEXTURE_UNITS],
    /// Eye distance (|z_eye|, as for fog) or the fog coordinate.
    pub distance: f32,
}

impl Default for RasterPos {
    fn default() -> Self {
        RasterPos {
            valid: true,
            window: [0.0; 3],
            color: [1.0; 4],
            secondary: [0.0, 0.0, 0.0, 1.0],
            texcoords: [[0.0, 0.0, 0.0, 1.0]; MAX_TEXTURE_UNITS],
            distance: 0.0,
        }
    }
}

/// Pixel transfer modes, maps and zoom (tables 6.17, 6.18).
#[derive(Clone, Debug)]
pub struct PixelTransfer {
    pub map_color: bool,
    pub map_stencil: bool,
    pub index_shift: i32,
    pub index_offset: i32,
    pub scale: [f32; 4],
    pub bias: [f32; 4],
    pub depth_scale: f32,
    pub depth_bias: f32,
    pub zoom: [f32; 2],
    /// The ten maps in `PixelMap::ALL` order; each has at least one entry.
    pub maps: [Vec<f32>; 10],
}

impl Default for PixelTransfer {
    fn default() -> Self {
        PixelTransfer {
            map_color: false,
            map_stencil: false,
            index_shift: 0,
            index_offset: 0,
            scale: [1.0; 4],
            bias: [0.0; 4],
            depth_scale: 1.0,
            depth_bias: 0.0,
            zoom: [1.0, 1.0],
            maps: std::array::from_fn(|_| vec![0.0]),
        }
    }
}

impl PixelTransfer {
    /// Whether colour conversion changes anything (the common case skips it).
    pub fn color_is_identity(&self) -> bool {
        !self.map_color && self.scale == [1.0; 4] && self.bias == [0.0; 4]
    }

    /// RGBA component conversion (section 3.6.5): scale and bias, then the colour maps
    /// (indexed by the component clamped to [0, 1] times the map size minus one).
    pub fn color(&self, c: [f32; 4]) -> [f32; 4] {
        let mut out = [0f32; 4];
        for k in 0..4 {
            let v = c[k] * self.scale[k] + self.bias[k];
            out[k] = if self.map_color {
                let map = &self.maps[PixelMap::RToR.index() + k];
                let v = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
                map[(v * (map.len() - 1) as f32).round() as usize]
            } else {
                v
            };
        }
        out
    }

    /// Whether colour and depth conversion change nothing.
    pub fn is_identity(&self) -> bool {
        self.color_is_identity() && self.depth_scale == 1.0 && self.depth_bias == 0.0
    }

    /// Converts an unpacked group (RGBA, or depth in R) for a texture image, clamped to
    /// [0, 1] as texture storage requires.
    pub fn texel(&self, depth: bool, v: [f32; 4]) -> [f32; 4] {
        if depth {
            [self.depth(v[0] as f64) as f32, v[1], v[2], v[3]]
        } else {
            self.color(v)
                .map(|c| if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) })
        }
    }

    /// Depth conversion: scale and bias, clamped to [0, 1].
    pub fn depth(&self, d: f64) -> f64 {
        let v = d * self.depth_scale as f64 + self.depth_bias as f64;
        if v.is_nan() {
            0.0
        } else {
            v.clamp(0.0, 1.0)
        }
    }

    /// Index shift and offset (section 3.6.5).
    pub fn shifted_index(&self, i: i64) -> i64 {
        let s = self.index_shift;
        let shifted = if s >= 0 {
            i.checked_shl(s.min(63) as u32).unwrap_or(0)
        } else {
            i >> (-(s as i64)).min(63)
        };
        shifted.wrapping_add(self.index_offset as i64)
    }

    /// A stencil index after shift, offset and the stencil map.
    pub fn stencil(&self, i: i64) -> u8 {
        let v = self.shifted_index(i);
        if self.map_stencil {
            let map = &self.maps[PixelMap::SToS.index()];
            map[(v as usize) & (map.len() - 1)] as i64 as u8
        } else {
            v as u8
        }
    }

    /// A colour index converted to RGBA through the I_TO_* maps (RGBA mode).
    pub fn index_to_color(&self, i: i64) -> [f32; 4] {
        let v = self.shifted_index(i);
        std::array::from_fn(|k| {
            let map = &self.maps[PixelMap::IToR.index() + k];
            map[(v as usize) & (map.len() - 1)]
        })
    }
}

/// One converted group of a pixel rectangle.
#[derive(Clone, Copy, Debug)]
enum PixelValue {
    Color([f32; 4]),
    Depth(f64),
    Stencil(u8),
    /// A depth and a stencil index written directly (`GL_DEPTH_STENCIL`).
    DepthStencil(f64, u8),
}

/// The window pixels a zoomed source pixel covers (section 3.6.4): those whose centres lie
/// between `a` and `b` (in either order, half-open), as first and one-past-last.
fn centre_span(a: f64, b: f64) -> (i64, i64) {
    let (lo, hi) = (a.min(b), a.max(b));
    let first = (lo - 0.5).ceil();
    let last = (hi - 0.5).ceil();
    let clamp = |v: f64| v.clamp(-(1i64 << 40) as f64, (1i64 << 40) as f64) as i64;
    (clamp(first), clamp(last))
}

/// How far below a whole pixel a raster position may be and still start a bitmap there.
pub(super) const BITMAP_MARGIN: f64 = 1e-4;

impl Context {
    // ------------------------------------------------------------------ raster position

    /// `glRasterPos`: the position is processed like a vertex (transform, lighting, texture
    /// coordinates, clipping against the view volume and the user planes).
    fn set_raster_pos(&mut self, position: Vec4) {
        let ds = self.snapshot();
        let lit = self.lighting.enabled.then(|| {
            let setup = self.light_setup();
            setup.light(position, self.current.normal, &self.lighting.materials)
        });
        let c = &self.current;
        let (color, secondary_color) = match lit {
            Some(l) => (l.front[0], l.front[1]),
            None => (c.color, c.secondary_color),
        };
        let v = ImmVertex {
            position,
            color,
            secondary_color,
            back_colors: [color, secondary_color],
            normal: c.normal,
            texcoords: c.texcoords,
            fog_coord: c.fog_coord,
            edge_flag: c.edge_flag,
        };
        let clip = transform::to_clip(&ds.vertex, &v);
        if !point_visible(&clip, &ds.viewport.clip_planes) {
            self.raster_pos.valid = false;
            return;
        }
        let p = clip.pos;
        let w = 1.0 / p.w;
        let window = [0, 1, 2].map(|k| {
            let v = p[k] * w * ds.viewport.viewport_scale[k] + ds.viewport.viewport_offset[k];
            if k == 2 {
                v.clamp(0.0, 1.0)
            } else {
                v
            }
        });
        let mut texcoords = [[0f32; 4]; MAX_TEXTURE_UNITS];
        for (u, tc) in texcoords.iter_mut().enumerate() {
            *tc = match ds.vertex.units.iter().find(|d| d.unit == u) {
                Some(_) => {
                    let a = &clip.attrs[attr::TEX + 4 * u..attr::TEX + 4 * u + 4];
                    [a[0], a[1], a[2], a[3]]
                }
                None => {
                    let m = *self.transform.texture[u]
                        .last()
                        .unwrap_or(&glam::Mat4::IDENTITY);
                    (m * c.texcoords[u]).to_array()
                }
            };
        }
        let eye = ds.vertex.modelview * position;
        let distance = if self.fog.coord_from_vertex {
            c.fog_coord
        } else {
            (eye.z / if eye.w != 0.0 { eye.w } else { 1.0 }).abs()
        };
        let clamp = |x: f32| if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
        self.raster_pos = RasterPos {
            valid: true,
            window,
            color: color.to_array().map(clamp),
            secondary: secondary_color.to_array().map(clamp),
            texcoords,
            distance,
        };
    }

    /// `glWindowPos` (section 2.13, GL 1.4): the window position directly; z through the
    /// depth range; the current colour, texture coordinates and fog coordinate unprocessed.
    fn set_window_pos(&mut self, x: f64, y: f64, z: f64) {
        let [n, f] = self.transform.depth_range;
        let z = if z.is_nan() { 0.0 } else { z.clamp(0.0, 1.0) };
        let c = &self.current;
        let clamp = |x: f32| if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
        self.raster_pos = RasterPos {
            valid: true,
            window: [x, y, n + z * (f - n)],
            color: c.color.to_array().map(clamp),
            secondary: c.secondary_color.to_array().map(clamp),
            texcoords: c.texcoords.map(|t| t.to_array()),
            distance: if self.fog.coord_from_vertex {
                c.fog_coord
            } else {
                0.0
            },
        };
    }

    // ------------------------------------------------------------------ transfer and maps

    fn pixel_transfer_value(&mut self, pname: GLenum, value: f32) {
        let Some(p) = convert::pixel_transfer_param(pname) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let t = &mut self.pixel_transfer;
        let as_int = if value.is_nan() {
            0
        } else {
            value.round().clamp(i32::MIN as f32, i32::MAX as f32) as i32
        };
        match p {
            PixelTransferParam::MapColor => t.map_color = value != 0.0,
            PixelTransferParam::MapStencil => t.map_stencil = value != 0.0,
            PixelTransferParam::IndexShift => t.index_shift = as_int,
            PixelTransferParam::IndexOffset => t.index_offset = as_int,
            PixelTransferParam::Scale(k) => t.scale[k] = value,
            PixelTransferParam::Bias(k) => t.bias[k] = value,
            PixelTransferParam::DepthScale => t.depth_scale = value,
            PixelTransferParam::DepthBias => t.depth_bias = value,
        }
    }

    pub(crate) fn pixel_transferf(&mut self, pname: GLenum, param: GLfloat) {
        self.pixel_transfer_value(pname, param);
    }

    pub(crate) fn pixel_transferi(&mut self, pname: GLenum, param: GLint) {
        self.pixel_transfer_value(pname, param as f32);
    }

    pub(crate) fn pixel_zoom(&mut self, xfactor: GLfloat, yfactor: GLfloat) {
        self.pixel_transfer.zoom = [xfactor, yfactor];
    }

    /// Stores a pixel map given as floats (colour maps clamped to [0, 1]).
    fn set_pixel_map(&mut self, map: GLenum, size: GLsizei, values: impl Fn(usize) -> f32) {
        let Some(m) = convert::pixel_map(map) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let n = size.max(0) as usize;
        if size < 1 || n > MAX_PIXEL_MAP_TABLE || (m.indexed_by_index() && !n.is_power_of_two()) {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.pixel_transfer.maps[m.index()] = (0..n)
            .map(|i| {
                let v = values(i);
                if m.holds_indices() || v.is_nan() {
                    if v.is_nan() {
                        0.0
                    } else {
                        v
                    }
                } else {
                    v.clamp(0.0, 1.0)
                }
            })
            .collect();
    }

    pub(crate) fn pixel_mapfv(&mut self, map: GLenum, mapsize: GLsizei, values: &[GLfloat]) {
        if values.len() < mapsize.max(0) as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.set_pixel_map(map, mapsize, |i| values[i]);
    }

    pub(crate) fn pixel_mapuiv(&mut self, map: GLenum, mapsize: GLsizei, values: &[GLuint]) {
        if values.len() < mapsize.max(0) as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let indices = convert::pixel_map(map).is_some_and(|m| m.holds_indices());
        self.set_pixel_map(map, mapsize, |i| {
            if indices {
                values[i] as f32
            } else {
                (values[i] as f64 / u32::MAX as f64) as f32
            }
        });
    }

    pub(crate) fn pixel_mapusv(&mut self, map: GLenum, mapsize: GLsizei, values: &[GLushort]) {
        if values.len() < mapsize.max(0) as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let indices = convert::pixel_map(map).is_some_and(|m| m.holds_indices());
        self.set_pixel_map(map, mapsize, |i| {
            if indices {
                values[i] as f32
            } else {
                values[i] as f32 / 65535.0
            }
        });
    }

    /// The map's entries, or `None` after recording the error.
    fn pixel_map_for_get(&mut self, map: GLenum, out_len: usize) -> Option<Vec<f32>> {
        let Some(m) = convert::pixel_map(map) else {
            self.record_error(GL_INVALID_ENUM);
            return None;
        };
        let values = self.pixel_transfer.maps[m.index()].clone();
        if out_len < values.len() {
            self.record_error(GL_INVALID_VALUE);
            return None;
        }
        Some(values)
    }

    pub(crate) fn get_pixel_mapfv(&mut self, map: GLenum, values: &mut [GLfloat]) {
        if let Some(v) = self.pixel_map_for_get(map, values.len()) {
            values[..v.len()].copy_from_slice(&v);
        }
    }

    pub(crate) fn get_pixel_mapuiv(&mut self, map: GLenum, values: &mut [GLuint]) {
        let indices = convert::pixel_map(map).is_some_and(|m| m.holds_indices());
        if let Some(v) = self.pixel_map_for_get(map, values.len()) {
            for (o, x) in values.iter_mut().zip(v) {
                *o = if indices {
                    x as u32
                } else {
                    (x as f64 * u32::MAX as f64).round() as u32
                };
            }
        }
    }

    pub(crate) fn get_pixel_mapusv(&mut self, map: GLenum, values: &mut [GLushort]) {
        let indices = convert::pixel_map(map).is_some_and(|m| m.holds_indices());
        if let Some(v) = self.pixel_map_for_get(map, values.len()) {
            for (o, x) in values.iter_mut().zip(v) {
                *o = if indices {
                    x as u16
                } else {
                    (x * 65535.0).round() as u16
                };
            }
        }
    }

    /// State queries of this module.
    pub(crate) fn pixel_rect_value(&self, q: PixelRectQuery) -> StateValue {
        use StateValue::*;
        let t = &self.pixel_transfer;
        let r = &self.raster_pos;
        match q {
            PixelRectQuery::Transfer(p) => match p {
                PixelTransferParam::MapColor => Bools(vec![t.map_color]),
                PixelTransferParam::MapStencil => Bools(vec![t.map_stencil]),
                PixelTransferParam::IndexShift => Ints(vec![t.index_shift as i64]),
                PixelTransferParam::IndexOffset => Ints(vec![t.index_offset as i64]),
                PixelTransferParam::Scale(k) => Floats(vec![t.scale[k] as f64]),
                PixelTransferParam::Bias(k) => Floats(vec![t.bias[k] as f64]),
                PixelTransferParam::DepthScale => Floats(vec![t.depth_scale as f64]),
                PixelTransferParam::DepthBias => Floats(vec![t.depth_bias as f64]),
            },
            PixelRectQuery::MapSize(m) => Ints(vec![t.maps[m.index()].len() as i64]),
            PixelRectQuery::MaxPixelMapTable => Ints(vec![MAX_PIXEL_MAP_TABLE as i64]),
            PixelRectQuery::ZoomX => Floats(vec![t.zoom[0] as f64]),
            PixelRectQuery::ZoomY => Floats(vec![t.zoom[1] as f64]),
            PixelRectQuery::RasterPosition => {
                Floats(vec![r.window[0], r.window[1], r.window[2], 1.0])
            }
            PixelRectQuery::RasterPositionValid => Bools(vec![r.valid]),
            PixelRectQuery::RasterColor => Normalized(r.color.iter().map(|&c| c as f64).collect()),
            PixelRectQuery::RasterTextureCoords => Floats(
                r.texcoords[self.active_texture]
                    .iter()
                    .map(|&c| c as f64)
                    .collect(),
            ),
            PixelRectQuery::RasterDistance => Floats(vec![r.distance as f64]),
            PixelRectQuery::RasterIndex => Floats(vec![1.0]),
        }
    }

    // ------------------------------------------------------------------ fragments

    /// Constant attribute planes of a pixel-rectangle fragment: `color` and the raster
    /// position's secondary colour, texture coordinates and distance.
    fn raster_planes(&self, ds: &TileDraw, color: [f32; 4], planes: &mut Vec<Plane>) {
        planes.clear();
        planes.resize(ds.attr_count, Plane::constant(0.0));
        self.raster_planes_into(ds, color, planes);
    }

    /// [`Context::raster_planes`] into `planes` (`ds.attr_count` long, other entries kept).
    pub(super) fn raster_planes_into(&self, ds: &TileDraw, color: [f32; 4], planes: &mut [Plane]) {
        let r = &self.raster_pos;
        for k in 0..4.min(ds.attr_count) {
            planes[attr::COLOR0 + k] = Plane::constant(color[k].clamp(0.0, 1.0) as f64);
        }
        for k in 0..4 {
            if attr::COLOR1 + k < ds.attr_count {
                planes[attr::COLOR1 + k] = Plane::constant(r.secondary[k] as f64);
            }
        }
        for u in &ds.fragment.units {
            for k in 0..4 {
                let i = attr::TEX + 4 * u.unit + k;
                if i < ds.attr_count {
                    planes[i] = Plane::constant(r.texcoords[u.unit][k] as f64);
                }
            }
        }
        if attr::FOG < ds.attr_count {
            planes[attr::FOG] = Plane::constant(r.distance as f64);
        }
    }

    /// Shades one fragment now (the scene has been flushed).
    fn shade_pixel_now(&mut self, ds: &TileDraw, x: i32, y: i32, z: f64, planes: &[Plane]) {
        let Some(t) = self.framebuffer.tile_index(x, y) else {
            return;
        };
        // No eight-pixel sampler tables for one-pixel spans: the texels come one by one (the
        // same values).
        let levels = UnitLevels::default();
        let shared = PrimitiveShared::new(&levels);
        let it = Interpolants {
            z: Plane::constant(z),
            inv_w: Plane::constant(1.0),
            attrs: planes,
            perspective: false,
            constant_primary: false,
            coverage: 1.0,
            shared: &shared,
        };
        // A pixel rectangle's fragment covers every sample of its pixel.
        let fb = &mut self.framebuffer;
        for s in 0..fb.samples {
            let t = t + s * fb.plane_tiles;
            (ds.fragment.span)(&ds.fragment, &mut fb.tiles[t], y, x, x + 1, &it);
        }
    }

    /// Draws a converted `width` x `height` image at the raster position with the zoom.
    fn draw_pixel_values(&mut self, width: usize, height: usize, values: &[PixelValue]) {
        if !self.raster_pos.valid || width == 0 || height == 0 {
            return;
        }
        self.flush_scene();
        let ds = self.snapshot();
        let bounds = self.scissored_window();
        let [zx, zy] = self.pixel_transfer.zoom.map(|z| z as f64);
        // The image starts at the raster position rounded to the nearest pixel corner, as
        // Mesa does (with the spec's unrounded position the pixels differ under fractional
        // zoom). Where a zoomed pixel's edge falls exactly on a pixel centre the choice is a
        // tie that implementations break differently.
        let [xr, yr, zr] = self.raster_pos.window;
        let (xr, yr) = ((xr + 0.5).floor(), (yr + 0.5).floor());
        let raster_color = self.raster_pos.color;
        let stencil_mask = self.fragment_ops.stencil_writemask as u8;
        let depth_write = self.fragment_ops.depth_mask;
        let depth_max = self.framebuffer.depth_max();
        let mut planes = Vec::with_capacity(ds.tile.attr_count);
        let mut color_planes_for: Option<[f32; 4]> = None;
        for j in 0..height {
            let (y0, y1) = centre_span(yr + zy * j as f64, yr + zy * (j + 1) as f64);
            let (y0, y1) = (y0.max(bounds.y0 as i64), y1.min(bounds.y1 as i64));
            if y0 >= y1 {
                continue;
            }
            for i in 0..width {
                let (x0, x1) = centre_span(xr + zx * i as f64, xr + zx * (i + 1) as f64);
                let (x0, x1) = (x0.max(bounds.x0 as i64), x1.min(bounds.x1 as i64));
                if x0 >= x1 {
                    continue;
                }
                let value = values[j * width + i];
                let (color, z) = match value {
                    PixelValue::Color(c) => (c, zr),
                    PixelValue::Depth(d) => (raster_color, d),
                    PixelValue::DepthStencil(d, s) => {
                        let d = depth_write.then(|| depth_to_fixed(d, depth_max));
                        for y in y0..y1 {
                            for x in x0..x1 {
                                let fb = &mut self.framebuffer;
                                if let Some(t) = fb.tile_index(x as i32, y as i32) {
                                    for k in 0..fb.samples {
                                        let tile = &mut fb.tiles[t + k * fb.plane_tiles];
                                        let idx = tile.index(x as i32, y as i32);
                                        if let Some(d) = d {
                                            tile.depth[idx] = d;
                                        }
                                        let old = tile.stencil[idx];
                                        tile.stencil[idx] =
                                            (old & !stencil_mask) | (s & stencil_mask);
                                    }
                                }
                            }
                        }
                        continue;
                    }
                    PixelValue::Stencil(s) => {
                        for y in y0..y1 {
                            for x in x0..x1 {
                                let fb = &mut self.framebuffer;
                                if let Some(t) = fb.tile_index(x as i32, y as i32) {
                                    for k in 0..fb.samples {
                                        let tile = &mut fb.tiles[t + k * fb.plane_tiles];
                                        let idx = tile.index(x as i32, y as i32);
                                        let old = tile.stencil[idx];
                                        tile.stencil[idx] =
                                            (old & !stencil_mask) | (s & stencil_mask);
                                    }
                                }
                            }
                        }
                        continue;
                    }
                };
                if color_planes_for != Some(color) {
                    self.raster_planes(&ds.tile, color, &mut planes);
                    color_planes_for = Some(color);
                }
                for y in y0..y1 {
                    for x in x0..x1 {
                        self.shade_pixel_now(&ds.tile, x as i32, y as i32, z, &planes);
                    }
                }
            }
        }
    }

    pub(crate) fn draw_pixels(
        &mut self,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        type_: GLenum,
        pixels: Option<&[u8]>,
    ) {
        if !self.framebuffer_ready() {
            return;
        }
        if format == GL_DEPTH_STENCIL_EXT {
            self.draw_depth_stencil(width, height, type_, pixels);
            return;
        }
        let f = convert::draw_pixels_format(format);
        // Section 3.6.4: the packed types need format RGB (3_3_2, 5_6_5) or RGBA/BGRA (the
        // others), else INVALID_OPERATION. A format outside the command's set also makes
        // INVALID_ENUM; of the two, GL records either, and llvmpipe (like piglit) this one.
        if let Some(TexPixelType::Packed(p)) = convert::tex_pixel_type(type_) {
            if !matches!(f, Some(DrawPixelsFormat::Color(cf)) if p.accepts(cf)) {
                self.record_error(GL_INVALID_OPERATION);
                return;
            }
        }
        let Some(f) = f else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let is_index = matches!(
            f,
            DrawPixelsFormat::StencilIndex | DrawPixelsFormat::ColorIndex
        );
        let index_ty = convert::pixel_index_type(type_);
        let color_ty = convert::tex_pixel_type(type_);
        if (is_index && index_ty.is_none()) || (!is_index && color_ty.is_none()) {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        if width < 0 || height < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let cfg = self.framebuffer.config;
        if (f == DrawPixelsFormat::StencilIndex && cfg.stencil_bits == 0)
            || (f == DrawPixelsFormat::Depth && cfg.depth_bits == 0)
        {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        if self.pixel_op_feedback(convert::FeedbackToken::DrawPixel) {
            return;
        }
        let (w, h) = (width as usize, height as usize);
        if w == 0 || h == 0 {
            return;
        }
        let Some(data) = pixels else {
            self.record_error(GL_INVALID_VALUE);
            return;
        };
        if let (DrawPixelsFormat::Color(cf), Some(ty)) = (f, color_ty) {
            if self.color_pixels_queueable() {
                if !self.queue_color_pixels(data, [w, h], cf, ty) {
                    self.record_error(GL_INVALID_VALUE);
                }
                return;
            }
        }
        let Some(values) = self.unpack_pixel_values(data, w, h, f, index_ty, color_ty) else {
            self.record_error(GL_INVALID_VALUE);
            return;
        };
        self.draw_pixel_values(w, h, &values);
    }

    /// `glDrawPixels(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8)` (EXT_packed_depth_stencil): each
    /// 32-bit word a depth (high 24 bits, then scale and bias) and a stencil index (low 8 bits,
    /// then shift, offset and map). As OpenGL 3.0 states it (section 4.3.1), the pairs are not
    /// fragments: only the pixel ownership and scissor tests apply, the depth is written
    /// unless the depth mask is off (the depth test is ignored), the stencil index through
    /// the stencil write mask, and colour is untouched. Another type is `GL_INVALID_ENUM`; a
    /// framebuffer without both buffers is `GL_INVALID_OPERATION`.
    fn draw_depth_stencil(
        &mut self,
        width: GLsizei,
        height: GLsizei,
        type_: GLenum,
        pixels: Option<&[u8]>,
    ) {
        if type_ != GL_UNSIGNED_INT_24_8_EXT {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        if width < 0 || height < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let cfg = self.read_framebuffer_config();
        if cfg.depth_bits == 0 || cfg.stencil_bits == 0 {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        if self.pixel_op_feedback(convert::FeedbackToken::DrawPixel) {
            return;
        }
        let (w, h) = (width as usize, height as usize);
        if w == 0 || h == 0 {
            return;
        }
        let ty = TexPixelType::Packed(PackedType::UInt248);
        let layout = texpix::layout(&self.unpack, 2, [w, h, 1], TexPixelFormat::DepthStencil, ty);
        let (Some(data), Some(layout)) = (pixels, layout) else {
            self.record_error(GL_INVALID_VALUE);
            return;
        };
        if data.len() < layout.end {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let t = &self.pixel_transfer;
        let swap = self.unpack.swap_bytes;
        let mut values = Vec::new();
        if values.try_reserve(w * h).is_err() {
            self.record_error(GL_OUT_OF_MEMORY);
            return;
        }
        for j in 0..h {
            for i in 0..w {
                let at = layout.start + j * layout.row_stride + i * layout.group;
                let mut b = [0u8; 4];
                b.copy_from_slice(&data[at..at + 4]);
                if swap {
                    b.reverse();
                }
                let word = u32::from_ne_bytes(b);
                let depth = t.depth((word >> 8) as f64 / 0x00FF_FFFF as f64);
                values.push(PixelValue::DepthStencil(
                    depth,
                    t.stencil((word & 0xFF) as i64),
                ));
            }
        }
        self.draw_pixel_values(w, h, &values);
    }

    /// Unpacks and converts client pixel data (`None` when `data` is too short).
    fn unpack_pixel_values(
        &self,
        data: &[u8],
        w: usize,
        h: usize,
        f: DrawPixelsFormat,
        index_ty: Option<PixelIndexType>,
        color_ty: Option<TexPixelType>,
    ) -> Option<Vec<PixelValue>> {
        let u = &self.unpack;
        let t = &self.pixel_transfer;
        let mut out = Vec::new();
        out.try_reserve(w.checked_mul(h)?).ok()?;
        match (f, index_ty, color_ty) {
            (DrawPixelsFormat::StencilIndex | DrawPixelsFormat::ColorIndex, Some(ity), _) => {
                let stencil = f == DrawPixelsFormat::StencilIndex;
                texpix::for_each_index(data, u, 2, [w, h, 1], ity, |v| {
                    out.push(if stencil {
                        PixelValue::Stencil(t.stencil(v))
                    } else {
                        PixelValue::Color(t.index_to_color(v))
                    })
                })?;
            }
            (DrawPixelsFormat::Depth, _, Some(ty)) => {
                let layout = texpix::layout(u, 2, [w, h, 1], TexPixelFormat::DepthComponent, ty)?;
                if data.len() < layout.end {
                    return None;
                }
                texpix::unpack_image(
                    data,
                    &layout,
                    [w, h, 1],
                    TexPixelFormat::DepthComponent,
                    ty,
                    u.swap_bytes,
                    |_, _, _, v| out.push(PixelValue::Depth(t.depth(v[0] as f64))),
                );
            }
            (DrawPixelsFormat::Color(cf), _, Some(ty)) => {
                let layout = texpix::layout(u, 2, [w, h, 1], cf, ty)?;
                if data.len() < layout.end {
                    return None;
                }
                let identity = t.color_is_identity();
                texpix::unpack_image(
                    data,
                    &layout,
                    [w, h, 1],
                    cf,
                    ty,
                    u.swap_bytes,
                    |_, _, _, v| out.push(PixelValue::Color(if identity { v } else { t.color(v) })),
                );
            }
            _ => return None,
        }
        Some(out)
    }

    /// `glCopyPixels(GL_DEPTH_STENCIL)` (EXT_packed_depth_stencil, which piglit's GL 1.1
    /// depth-stencil tests and Mesa use on the default framebuffer): the depth copy, then
    /// the stencil copy of the same rectangle. The copies read before they write, so
    /// doing them one after the other is doing them together unless the depth copy's
    /// fragments change stencil (a stencil test is on) inside the source rectangle.
    fn copy_depth_stencil(&mut self, x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
        if width < 0 || height < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let cfg = self.read_framebuffer_config();
        if cfg.depth_bits == 0 || cfg.stencil_bits == 0 {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        if self.pixel_op_feedback(convert::FeedbackToken::CopyPixel) {
            return;
        }
        self.copy_pixels(x, y, width, height, GL_DEPTH);
        self.copy_pixels(x, y, width, height, GL_STENCIL);
    }

    pub(crate) fn copy_pixels(
        &mut self,
        x: GLint,
        y: GLint,
        width: GLsizei,
        height: GLsizei,
        type_: GLenum,
    ) {
        if !self.framebuffer_ready() {
            return;
        }
        if self.reads_elsewhere() {
            // EXT_framebuffer_blit: the source is the read framebuffer, also checked.
            let read = self.fbo.read_bound;
            if !self.with_framebuffer_bound(read, |c| c.framebuffer_ready()) {
                return;
            }
        }
        if type_ == GL_DEPTH_STENCIL_EXT {
            self.copy_depth_stencil(x, y, width, height);
            return;
        }
        let Some(ty) = convert::copy_pixels_type(type_) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if width < 0 || height < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let cfg = self.read_framebuffer_config();
        if (ty == CopyPixelsType::Depth && cfg.depth_bits == 0)
            || (ty == CopyPixelsType::Stencil && cfg.stencil_bits == 0)
        {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        if self.pixel_op_feedback(convert::FeedbackToken::CopyPixel) {
            return;
        }
        if !self.raster_pos.valid || width == 0 || height == 0 {
            return;
        }
        let (w, h) = (width as usize, height as usize);
        let read = self.fbo.read_bound;
        let Some(values) =
            self.with_framebuffer_bound(read, |c| c.copy_pixels_source(x, y, width, height, ty))
        else {
            self.record_error(GL_OUT_OF_MEMORY);
            return;
        };
        self.draw_pixel_values(w, h, &values);
    }

    /// The config of the read framebuffer (which buffers it has).
    pub(crate) fn read_framebuffer_config(&mut self) -> crate::framebuffer::FramebufferConfig {
        let read = self.fbo.read_bound;
        self.with_framebuffer_bound(read, |c| c.framebuffer.config)
    }

    /// The values `glCopyPixels` reads from the current framebuffer, after the pixel
    /// transfer operations (`None` when they do not fit in memory).
    fn copy_pixels_source(
        &mut self,
        x: GLint,
        y: GLint,
        width: GLsizei,
        height: GLsizei,
        ty: CopyPixelsType,
    ) -> Option<Vec<PixelValue>> {
        self.flush_scene();
        let (w, h) = (width as usize, height as usize);
        let mut values = Vec::new();
        values.try_reserve(w.saturating_mul(h)).ok()?;
        let fb = &self.framebuffer;
        let t = &self.pixel_transfer;
        let depth_max = fb.depth_max() as f64;
        for j in 0..height {
            for i in 0..width {
                let (sx, sy) = (x.saturating_add(i), y.saturating_add(j));
                // Pixels outside the window read as zero (their values are undefined).
                values.push(match ty {
                    CopyPixelsType::Color => {
                        let c = fb
                            .color_at(sx, sy)
                            .unwrap_or([0; 4])
                            .map(|v| v as f32 / 255.0);
                        PixelValue::Color(if t.color_is_identity() { c } else { t.color(c) })
                    }
                    CopyPixelsType::Depth => PixelValue::Depth(
                        t.depth(fb.depth_at(sx, sy).unwrap_or(0) as f64 / depth_max),
                    ),
                    CopyPixelsType::Stencil => {
                        PixelValue::Stencil(t.stencil(fb.stencil_at(sx, sy).unwrap_or(0) as i64))
                    }
                });
            }
        }
        Some(values)
    }

    pub(crate) fn bitmap(
        &mut self,
        width: GLsizei,
        height: GLsizei,
        xorig: GLfloat,
        yorig: GLfloat,
        xmove: GLfloat,
        ymove: GLfloat,
        bitmap: &[GLubyte],
    ) {
        if !self.framebuffer_ready() {
            return;
        }
        if width < 0 || height < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        if !self.raster_pos.valid {
            return;
        }
        // Section 3.7: the bitmap starts at floor(x_r - x_o). A raster position given as a
        // whole pixel comes out of the single-precision transform a few ulps off it, and
        // below it the floor would move the bitmap a whole pixel: a margin of 1e-4 keeps it
        // (llvmpipe places bitmaps with the same margin).
        let elsewhere = self.pixel_op_feedback(convert::FeedbackToken::Bitmap);
        let (w, h) = (width as usize, height as usize);
        if !elsewhere && w > 0 && h > 0 {
            let u = self.unpack;
            let Some(rows) = texpix::index_rows(&u, w, h, 1, 1).filter(|r| bitmap.len() >= r.end)
            else {
                self.record_error(GL_INVALID_VALUE);
                return;
            };
            let [xr, yr, _] = self.raster_pos.window;
            let x0 = (xr + BITMAP_MARGIN - xorig as f64).floor() as i64;
            let y0 = (yr + BITMAP_MARGIN - yorig as f64).floor() as i64;
            if self.pixel_rects_queued() {
                self.queue_bitmap([x0, y0], [w, h], bitmap, &rows);
            } else {
                self.bitmap_now([x0, y0], [w, h], bitmap, &rows);
            }
        }
        self.raster_pos.window[0] += xmove as f64;
        self.raster_pos.window[1] += ymove as f64;
    }

    /// The set bits of a bitmap whose lower left pixel is `origin` (section 3.7: the raster
    /// position less the bitmap's origin, floored), shaded now, one fragment at a time (the
    /// per-pixel route, see [`Context::pixel_rects_queued`]).
    fn bitmap_now(
        &mut self,
        [x0, y0]: [i64; 2],
        [w, h]: [usize; 2],
        bitmap: &[GLubyte],
        rows: &texpix::IndexRows,
    ) {
        let u = self.unpack;
        let skip = u.skip_pixels.max(0) as usize;
        self.flush_scene();
        let ds = self.snapshot();
        let bounds = self.scissored_window();
        let zr = self.raster_pos.window[2];
        let mut planes = Vec::new();
        self.raster_planes(&ds.tile, self.raster_pos.color, &mut planes);
        // The origin may be far outside the window (saturated from a huge float).
        for j in 0..h {
            let y = y0.saturating_add(j as i64);
            if y < bounds.y0 as i64 || y >= bounds.y1 as i64 {
                continue;
            }
            let row = rows.first_row + j * rows.stride;
            for i in 0..w {
                let x = x0.saturating_add(i as i64);
                if x < bounds.x0 as i64 || x >= bounds.x1 as i64 {
                    continue;
                }
                let set = texpix::read_index(
                    bitmap,
                    row,
                    skip + i,
                    PixelIndexType::Bitmap,
                    false,
                    u.lsb_first,
                ) != 0;
                if set {
                    self.shade_pixel_now(&ds.tile, x as i32, y as i32, zr, &planes);
                }
            }
        }
    }
}

// The raster-position and window-position entry points, one per C signature.
macro_rules! raster_pos_entry_points {
    ($( $name:ident ( $($arg:ident : $ty:ty),* ) => [$x:expr, $y:expr, $z:expr, $w:expr]; )*) => {
        impl Context {
            $(
                pub(crate) fn $name(&mut self, $($arg: $ty),*) {
                    let p = Vec4::new($x as f32, $y as f32, $z as f32, $w as f32);
                    self.set_raster_pos(p);
                    self.raster_pos_feedback(Some(p));
                }
            )*
        }
    };
}

macro_rules! window_pos_entry_points {
    ($( $name:ident ( $($arg:ident : $ty:ty),* ) => [$x:expr, $y:expr, $z:expr]; )*) => {
        impl Context {
            $(
                pub(crate) fn $name(&mut self, $($arg: $ty),*) {
                    self.set_window_pos($x as f64, $y as f64, $z as f64);
                    self.raster_pos_feedback(None);
                }
            )*
        }
    };
}

raster_pos_entry_points! {
    raster_pos_2d(x: GLdouble, y: GLdouble) => [x, y, 0, 1];
    raster_pos_2f(x: GLfloat, y: GLfloat) => [x, y, 0, 1];
    raster_pos_2i(x: GLint, y: GLint) => [x, y, 0, 1];
    raster_pos_2s(x: GLshort, y: GLshort) => [x, y, 0, 1];
    raster_pos_3d(x: GLdouble, y: GLdouble, z: GLdouble) => [x, y, z, 1];
    raster_pos_3f(x: GLfloat, y: GLfloat, z: GLfloat) => [x, y, z, 1];
    raster_pos_3i(x: GLint, y: GLint, z: GLint) => [x, y, z, 1];
    raster_pos_3s(x: GLshort, y: GLshort, z: GLshort) => [x, y, z, 1];
    raster_pos_4d(x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) => [x, y, z, w];
    raster_pos_4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) => [x, y, z, w];
    raster_pos_4i(x: GLint, y: GLint, z: GLint, w: GLint) => [x, y, z, w];
    raster_pos_4s(x: GLshort, y: GLshort, z: GLshort, w: GLshort) => [x, y, z, w];
    raster_pos_2dv(v: &[GLdouble; 2]) => [v[0], v[1], 0, 1];
    raster_pos_2fv(v: &[GLfloat; 2]) => [v[0], v[1], 0, 1];
    raster_pos_2iv(v: &[GLint; 2]) => [v[0], v[1], 0, 1];
    raster_pos_2sv(v: &[GLshort; 2]) => [v[0], v[1], 0, 1];
    raster_pos_3dv(v: &[GLdouble; 3]) => [v[0], v[1], v[2], 1];
    raster_pos_3fv(v: &[GLfloat; 3]) => [v[0], v[1], v[2], 1];
    raster_pos_3iv(v: &[GLint; 3]) => [v[0], v[1], v[2], 1];
    raster_pos_3sv(v: &[GLshort; 3]) => [v[0], v[1], v[2], 1];
    raster_pos_4dv(v: &[GLdouble; 4]) => [v[0], v[1], v[2], v[3]];
    raster_pos_4fv(v: &[GLfloat; 4]) => [v[0], v[1], v[2], v[3]];
    raster_pos_4iv(v: &[GLint; 4]) => [v[0], v[1], v[2], v[3]];
    raster_pos_4sv(v: &[GLshort; 4]) => [v[0], v[1], v[2], v[3]];
}

window_pos_entry_points! {
    window_pos_2d(x: GLdouble, y: GLdouble) => [x, y, 0];
    window_pos_2f(x: GLfloat, y: GLfloat) => [x, y, 0];
    window_pos_2i(x: GLint, y: GLint) => [x, y, 0];
    window_pos_2s(x: GLshort, y: GLshort) => [x, y, 0];
    window_pos_3d(x: GLdouble, y: GLdouble, z: GLdouble) => [x, y, z];
    window_pos_3f(x: GLfloat, y: GLfloat, z: GLfloat) => [x, y, z];
    window_pos_3i(x: GLint, y: GLint, z: GLint) => [x, y, z];
    window_pos_3s(x: GLshort, y: GLshort, z: GLshort) => [x, y, z];
    window_pos_2dv(v: &[GLdouble; 2]) => [v[0], v[1], 0];
    window_pos_2fv(v: &[GLfloat; 2]) => [v[0], v[1], 0];
    window_pos_2iv(v: &[GLint; 2]) => [v[0], v[1], 0];
    window_pos_2sv(v: &[GLshort; 2]) => [v[0], v[1], 0];
    window_pos_3dv(v: &[GLdouble; 3]) => [v[0], v[1], v[2]];
    window_pos_3fv(v: &[GLfloat; 3]) => [v[0], v[1], v[2]];
    window_pos_3iv(v: &[GLint; 3]) => [v[0], v[1], v[2]];
    window_pos_3sv(v: &[GLshort; 3]) => [v[0], v[1], v[2]];
}

//! The rasterizer's part of a draw's frozen state: what setup, binning and tile shading read,
//! with the fragment stage's part that the tiles hand to the span functions. The scene keeps
//! one per draw for its commands (`Scene::states`).

use super::controls::RasterDraw;
use crate::common::rect::Rect;
use crate::fragment::draw::FragmentDraw;

/// The frozen state binned commands are set up and shaded with (built by `state::snapshot`).
#[derive(Clone, Debug)]
pub struct TileDraw {
    /// Pixels that may be written: viewport, scissor (when enabled) and framebuffer bounds.
    pub draw_rect: Rect,
    pub flat: bool,
    /// Interpolated attributes per vertex (a prefix of the `attr` layout).
    pub attr_count: usize,
    /// Bit i set when the fragment stage reads attribute i (below `attr_count`): the others'
    /// planes of a triangle are neither computed nor stored (they read as zero).
    pub live_attrs: u64,
    /// Whether triangles hidden behind the stored depths are dropped before rasterizing
    /// (`raster::coarse`): the key allows it (`coarse::applies`), and off on the general path,
    /// so twin tests compare both.
    pub coarse_depth: bool,
    /// Whether aliased lines whose fragments only store a colour may store it directly
    /// (`raster::line_tile`): off on the general path, so twin tests compare both.
    pub fast_lines: bool,
    /// Point, line and polygon rasterization controls.
    pub raster: RasterDraw,
    /// What the span functions read.
    pub fragment: FragmentDraw,
}

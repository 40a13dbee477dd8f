//! The rasterization controls of a draw (points, lines, polygon modes, offset, stipple,
//! smoothing), as the snapshot gathers them for the raster stage.

use crate::common::values::PolygonMode;

/// Point, line and polygon rasterization controls of a draw (sections 3.3-3.5).
#[derive(Clone, Debug, PartialEq)]
pub struct RasterDraw {
    /// `glPointSize`, before attenuation and clamping.
    pub point_size: f32,
    pub point_smooth: bool,
    /// `GL_POINT_SPRITE` on: the units whose texture coordinates the sprite replaces (bit per
    /// unit) and whether t runs down from the top (`GL_UPPER_LEFT`).
    pub point_sprite: Option<(u32, bool)>,
    /// Distance attenuation coefficients (a, b, c); `None` for the default (1, 0, 0).
    pub point_attenuation: Option<[f32; 3]>,
    /// `GL_POINT_SIZE_MIN`, `GL_POINT_SIZE_MAX`.
    pub point_size_range: [f32; 2],
    pub line_width: f32,
    pub line_smooth: bool,
    /// Repeat factor and pattern, when stippling is enabled.
    pub line_stipple: Option<(u32, u16)>,
    /// Front, back.
    pub polygon_mode: [PolygonMode; 2],
    /// Depth offset (factor, units in resolvable steps) and where it applies (fill, line,
    /// point); `None` when no mode enables it.
    pub offset: Option<PolygonOffsetDraw>,
    /// Rows bottom first; bit `1 << (31 - x % 32)` of row `y % 32`. `None` when disabled.
    pub polygon_stipple: Option<[u32; 32]>,
    /// `GL_POLYGON_SMOOTH`: filled polygons take their coverage into the alpha.
    pub polygon_smooth: bool,
}

/// `glPolygonOffset` as a draw applies it: `factor * m + units * r` with `r` the smallest
/// resolvable depth difference (one step of the fixed-point depth buffer).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolygonOffsetDraw {
    pub factor: f64,
    pub units: f64,
    /// Enabled for fill, line, point polygon modes.
    pub enabled: [bool; 3],
}

impl PolygonOffsetDraw {
    /// The window-z offset for a polygon whose depth plane has slopes `dzdx`, `dzdy`
    /// (section 3.5.5: m is the maximum of their magnitudes), when `mode` is enabled.
    pub fn for_plane(&self, mode: PolygonMode, dzdx: f64, dzdy: f64, depth_max: u32) -> f64 {
        let on = match mode {
            PolygonMode::Fill => self.enabled[0],
            PolygonMode::Line => self.enabled[1],
            PolygonMode::Point => self.enabled[2],
        };
        if !on {
            return 0.0;
        }
        let m = dzdx.abs().max(dzdy.abs());
        let o = self.factor * m + self.units / depth_max.max(1) as f64;
        if o.is_finite() {
            o
        } else {
            0.0
        }
    }
}

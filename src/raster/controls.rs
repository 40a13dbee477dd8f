//! The rasterization controls of a draw (points, lines, polygon modes, offset, stipple,
//! smoothing), as the snapshot gathers them for the raster stage.

use crate::common::values::PolygonMode;

/// How `GL_POINT_SMOOTH` points are drawn: not GL state, a choice of the context's owner
/// ([`crate::Context::set_smooth_points`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SmoothPoints {
    /// The specification's antialiasing (section 3.3.2): each pixel takes the share of its
    /// square the point's disc covers, as coverage.
    #[default]
    Coverage,
    /// As Mesa 22 draws them (llvmpipe and softpipe alike, measured): a disc without coverage,
    /// every pixel whose centre lies within max(size / 2, 1) of the point's centre taking the
    /// full colour. Replays of captures recorded on Mesa use it to give Mesa's pictures.
    Discs,
}

/// Point, line and polygon rasterization controls of a draw (sections 3.3-3.5).
#[derive(Clone, Debug, PartialEq)]
pub struct RasterDraw {
    /// `glPointSize`, before attenuation and clamping.
    pub point_size: f32,
    pub point_smooth: bool,
    /// How `GL_POINT_SMOOTH` points are drawn (a choice of the context's owner).
    pub smooth_points: SmoothPoints,
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
/// resolvable depth difference: one step of the fixed-point depth buffer, but at least
/// [`MIN_RESOLVABLE_DEPTH`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolygonOffsetDraw {
    pub factor: f64,
    pub units: f64,
    /// Enabled for fill, line, point polygon modes.
    pub enabled: [bool; 3],
}

/// The smallest depth difference tilegl resolves everywhere in the depth range: window z
/// comes out of the single-precision transform, and two surfaces one step of a 24-bit
/// buffer apart near the near plane are not always told apart, two steps are (piglit's
/// gl-1.4-polygon-offset measures this "ideal MRD" as 2^-23 on tilegl, as on llvmpipe,
/// whose offset unit is the same).
pub const MIN_RESOLVABLE_DEPTH: f64 = 1.0 / (1u32 << 23) as f64;

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
        let r = (1.0 / depth_max.max(1) as f64).max(MIN_RESOLVABLE_DEPTH);
        let o = self.factor * m + self.units * r;
        if o.is_finite() {
            o
        } else {
            0.0
        }
    }
}

//! Perspective division and the viewport transformation (section 2.11.1).

use super::clip::ClipVertex;
use crate::raster::setup::to_fixed;
use crate::state::DrawState;

/// A vertex in window coordinates.
#[derive(Clone, Copy, Debug)]
pub struct WindowVertex {
    /// Fixed-point x, y (8 sub-pixel bits).
    pub xy: [i64; 2],
    /// The same position before snapping (window coordinates). Attribute planes use it:
    /// interpolation from snapped positions extrapolates badly on long thin triangles
    /// (a perspective plane near its horizon).
    pub pos: [f64; 2],
    /// Window z in [0, 1] (depth range applied).
    pub z: f64,
    /// 1 / w_clip.
    pub inv_w: f64,
}

/// Divides by w and maps to the viewport. `v.pos.w` is positive (clipping guarantees it).
pub fn to_window(ds: &DrawState, v: &ClipVertex) -> WindowVertex {
    let inv_w = 1.0 / v.pos.w;
    let ndc = [v.pos.x * inv_w, v.pos.y * inv_w, v.pos.z * inv_w];
    let x = ndc[0] * ds.viewport_scale[0] + ds.viewport_offset[0];
    let y = ndc[1] * ds.viewport_scale[1] + ds.viewport_offset[1];
    let z = ndc[2] * ds.viewport_scale[2] + ds.viewport_offset[2];
    WindowVertex {
        xy: [to_fixed(x), to_fixed(y)],
        pos: [x, y],
        z: z.clamp(0.0, 1.0),
        inv_w,
    }
}

//! Object to clip coordinates, and the per-vertex attributes the draw needs.

use glam::DVec4;

use super::immediate::ImmVertex;
use crate::primitive::clip::ClipVertex;
use crate::state::snapshot::MAX_ATTRS;
use crate::state::DrawState;

/// Transforms one vertex. Colours are clamped to [0, 1] here (section 2.14.7; with lighting
/// off the current colour is used as is, then clamped).
pub fn to_clip(ds: &DrawState, v: &ImmVertex) -> ClipVertex {
    let pos = (ds.mvp * v.position).as_dvec4();
    let eye = if ds.clip_planes.is_empty() {
        DVec4::ZERO
    } else {
        (ds.modelview * v.position).as_dvec4()
    };
    let mut attrs = [0f32; MAX_ATTRS];
    for (a, c) in attrs.iter_mut().zip(v.color.to_array()) {
        *a = if c >= 1.0 {
            1.0
        } else if c > 0.0 {
            c
        } else {
            0.0
        };
    }
    ClipVertex { pos, eye, attrs }
}

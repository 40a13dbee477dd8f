//! The vertex stage and the front end of a draw: transform the batch, assemble, clip, map to
//! the window, cull, and hand primitives to setup and binning.

pub mod immediate;
pub mod lighting;
pub mod texgen;
pub mod transform;

use crate::common::attr::{self, MAX_ATTRS};
use crate::primitive::clip::ClipVertex;
use transform::VertexDraw;

/// Batches at least this large are transformed in parallel (below, the hand-off costs more
/// than it saves).
pub(crate) const PARALLEL_TRANSFORM_MIN: usize = 4096;
/// Vertices per parallel transform job (a multiple of the eight lanes of `to_clip_batch`).
pub(crate) const TRANSFORM_CHUNK: usize = 256;

/// Flat shading: every vertex of a primitive takes the provoking vertex's colours (front and
/// back), before clipping so that clipped vertices inherit them too.
pub(crate) fn copy_provoking_colors(ds: &VertexDraw, v: &mut ClipVertex, provoking: &ClipVertex) {
    attr::copy_colors(&mut v.attrs, &provoking.attrs);
    if ds.two_sided {
        v.attrs[attr::BACK..attr::COUNT].copy_from_slice(&provoking.attrs[attr::BACK..attr::COUNT]);
    }
}

/// Two-sided lighting: a back-facing polygon is drawn with the back colours.
pub(crate) fn use_back_colors(attrs: &mut [f32; MAX_ATTRS]) {
    for c in 0..attr::COLORS {
        attrs[attr::color(c)] = attrs[attr::BACK + c];
    }
}

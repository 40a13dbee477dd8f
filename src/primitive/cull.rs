//! Facing and culling (section 3.5.1): the sign of the window-space area decides the face.

use crate::api::convert::{Face, Winding};

/// Twice the signed area of a polygon given in fixed-point window coordinates (y up):
/// positive for counter-clockwise.
pub fn signed_area2(points: &[[i64; 2]]) -> i128 {
    let n = points.len();
    (0..n)
        .map(|i| {
            let (p, q) = (points[i], points[(i + 1) % n]);
            p[0] as i128 * q[1] as i128 - q[0] as i128 * p[1] as i128
        })
        .sum()
}

/// Whether a polygon of signed area `area2` is front-facing under `front`.
pub fn is_front(area2: i128, front: Winding) -> bool {
    match front {
        Winding::Ccw => area2 > 0,
        Winding::Cw => area2 < 0,
    }
}

/// Whether `cull` discards a polygon that is front-facing when `front_facing`.
pub fn is_culled(cull: Option<Face>, front_facing: bool) -> bool {
    match cull {
        None => false,
        Some(Face::FrontAndBack) => true,
        Some(Face::Front) => front_facing,
        Some(Face::Back) => !front_facing,
    }
}

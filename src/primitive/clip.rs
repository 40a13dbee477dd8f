//! Clipping in homogeneous clip space against the view volume `-w <= x, y, z <= w` (the near
//! plane included) and the enabled user clip planes (in eye space), in double precision.
//!
//! Stiff inputs are handled here: primitives with a non-finite coordinate are dropped, points
//! of a clipped polygon land exactly on the clipping plane, and a vertex that still has `w <= 0`
//! after clipping (only possible for the degenerate all-zero vertex) drops the primitive so that
//! nothing divides by zero.

use glam::DVec4;

use crate::state::snapshot::MAX_ATTRS;

/// A vertex in clip space with its interpolated attributes.
#[derive(Clone, Copy, Debug)]
pub struct ClipVertex {
    pub pos: DVec4,
    /// Eye-space position (needed only with user clip planes).
    pub eye: DVec4,
    pub attrs: [f32; MAX_ATTRS],
    /// Edge flag: the polygon edge starting here is a boundary edge (drawn in line and point
    /// polygon modes).
    pub edge: bool,
}

impl ClipVertex {
    /// All zero (a placeholder that is overwritten).
    pub const ZERO: ClipVertex = ClipVertex {
        pos: DVec4::ZERO,
        eye: DVec4::ZERO,
        attrs: [0.0; MAX_ATTRS],
        edge: false,
    };

    pub fn is_finite(&self) -> bool {
        self.pos.is_finite()
    }

    fn lerp(&self, o: &ClipVertex, t: f64, n_attrs: usize) -> ClipVertex {
        let mut attrs = self.attrs;
        let tf = t as f32;
        for i in 0..n_attrs {
            attrs[i] = self.attrs[i] + tf * (o.attrs[i] - self.attrs[i]);
        }
        ClipVertex {
            pos: self.pos + (o.pos - self.pos) * t,
            eye: self.eye + (o.eye - self.eye) * t,
            attrs,
            edge: self.edge,
        }
    }
}

/// Signed distance to clip plane `i` (0..6 view volume, then user planes); inside when >= 0.
#[inline]
fn distance(v: &ClipVertex, i: usize, user: &[DVec4]) -> f64 {
    let p = v.pos;
    match i {
        0 => p.w + p.x,
        1 => p.w - p.x,
        2 => p.w + p.y,
        3 => p.w - p.y,
        4 => p.w + p.z,
        5 => p.w - p.z,
        k => user[k - 6].dot(v.eye),
    }
}

/// Places a new vertex exactly on view-volume plane `i` (removes rounding from the lerp).
fn snap(v: &mut ClipVertex, i: usize) {
    let w = v.pos.w;
    match i {
        0 => v.pos.x = -w,
        1 => v.pos.x = w,
        2 => v.pos.y = -w,
        3 => v.pos.y = w,
        4 => v.pos.z = -w,
        5 => v.pos.z = w,
        _ => {}
    }
}

/// Outcode: bit i set when the vertex is outside plane i.
fn outcode(v: &ClipVertex, user: &[DVec4]) -> u32 {
    let mut code = 0;
    for i in 0..6 + user.len() {
        if !(distance(v, i, user) >= 0.0) {
            code |= 1 << i;
        }
    }
    code
}

/// Clips a convex polygon in place (Sutherland-Hodgman). Returns false when nothing is left.
pub fn clip_polygon(
    poly: &mut Vec<ClipVertex>,
    scratch: &mut Vec<ClipVertex>,
    user: &[DVec4],
    n_attrs: usize,
) -> bool {
    if poly.iter().any(|v| !v.is_finite()) {
        return false;
    }
    let (mut all_or, mut all_and) = (0u32, !0u32);
    for v in poly.iter() {
        let c = outcode(v, user);
        all_or |= c;
        all_and &= c;
    }
    if all_and != 0 {
        return false;
    }
    if all_or != 0 {
        for i in 0..6 + user.len() {
            if all_or & (1 << i) == 0 {
                continue;
            }
            scratch.clear();
            let n = poly.len();
            for k in 0..n {
                let a = &poly[k];
                let b = &poly[(k + 1) % n];
                let da = distance(a, i, user);
                let db = distance(b, i, user);
                if da >= 0.0 {
                    scratch.push(*a);
                }
                if (da >= 0.0) != (db >= 0.0) {
                    // Interpolate from the inside vertex so that the result is independent of
                    // the edge direction (shared edges clip identically).
                    let (inside, outside, di, d_o) = if da >= 0.0 {
                        (a, b, da, db)
                    } else {
                        (b, a, db, da)
                    };
                    let t = di / (di - d_o);
                    let mut v = inside.lerp(outside, t, n_attrs);
                    snap(&mut v, i);
                    // Leaving: the new edge runs along the clip plane and is not a boundary
                    // edge. Entering: the rest of the original edge a-b starts here.
                    v.edge = da < 0.0 && a.edge;
                    scratch.push(v);
                }
            }
            std::mem::swap(poly, scratch);
            if poly.len() < 3 {
                return false;
            }
        }
    }
    poly.iter().all(|v| v.pos.w > 0.0 && v.pos.is_finite())
}

/// Clips a line segment. Returns the clipped endpoints or `None`.
pub fn clip_line(
    a: &ClipVertex,
    b: &ClipVertex,
    user: &[DVec4],
    n_attrs: usize,
) -> Option<(ClipVertex, ClipVertex)> {
    if !a.is_finite() || !b.is_finite() {
        return None;
    }
    let (ca, cb) = (outcode(a, user), outcode(b, user));
    if ca & cb != 0 {
        return None;
    }
    let (mut a, mut b) = (*a, *b);
    if ca | cb != 0 {
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for i in 0..6 + user.len() {
            let da = distance(&a, i, user);
            let db = distance(&b, i, user);
            if da < 0.0 && db < 0.0 {
                return None;
            }
            if da < 0.0 {
                t0 = t0.max(da / (da - db));
            } else if db < 0.0 {
                t1 = t1.min(da / (da - db));
            }
        }
        if t0 > t1 {
            return None;
        }
        let (oa, ob) = (a, b);
        if t0 > 0.0 {
            a = oa.lerp(&ob, t0, n_attrs);
        }
        if t1 < 1.0 {
            b = oa.lerp(&ob, t1, n_attrs);
        }
    }
    (a.pos.w > 0.0 && b.pos.w > 0.0).then_some((a, b))
}

/// Whether a point lies inside every clip plane (points are clipped whole).
pub fn point_visible(v: &ClipVertex, user: &[DVec4]) -> bool {
    v.is_finite() && outcode(v, user) == 0 && v.pos.w > 0.0
}

//! Clipping in homogeneous clip space against the view volume `-w <= x, y, z <= w` (the near
//! plane included) and the enabled user clip planes (in eye space), in double precision.
//! Filled polygons inside a guard band around the viewport ([`in_guard_band`]) skip clipping:
//! the rasterizer visits only the viewport's pixels.
//!
//! Stiff inputs are handled here: primitives with a non-finite coordinate are dropped, points
//! of a clipped polygon land exactly on the clipping plane, and a vertex that still has `w <= 0`
//! after clipping (only possible for the degenerate all-zero vertex) drops the primitive so that
//! nothing divides by zero.

use glam::DVec4;

use crate::common::attr::MAX_ATTRS;

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

/// The view volume's side planes, `-w <= x, y <= w`.
pub const EXACT: [f64; 2] = [1.0, 1.0];

/// Signed distance to clip plane `i` (0..6 view volume, then user planes); inside when >= 0.
/// The side planes are moved out to `-g w <= x <= g w` (and likewise y) by `guard` = `[g_x,
/// g_y]` (a guard band; [`EXACT`] for the view volume).
#[inline]
fn distance(v: &ClipVertex, i: usize, user: &[DVec4], guard: [f64; 2]) -> f64 {
    let p = v.pos;
    match i {
        0 => p.w * guard[0] + p.x,
        1 => p.w * guard[0] - p.x,
        2 => p.w * guard[1] + p.y,
        3 => p.w * guard[1] - p.y,
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
fn outcode(v: &ClipVertex, user: &[DVec4], guard: [f64; 2]) -> u32 {
    let mut code = 0;
    for i in 0..6 + user.len() {
        if !(distance(v, i, user, guard) >= 0.0) {
            code |= 1 << i;
        }
    }
    code
}

/// Clips a convex polygon in place (Sutherland-Hodgman): nothing to do when every vertex lies
/// inside the near, far and user planes and the side planes moved out by `guard` (see
/// `distance`), else clipped against the view volume and the user planes. Returns false
/// when nothing is left.
pub fn clip_polygon(
    poly: &mut Vec<ClipVertex>,
    scratch: &mut Vec<ClipVertex>,
    user: &[DVec4],
    guard: [f64; 2],
    n_attrs: usize,
) -> bool {
    if poly.iter().any(|v| !v.is_finite()) {
        return false;
    }
    // Inside the guard band: drawn as it is. Otherwise clipped against the view volume
    // itself, as before there was a guard band (the positions of the new vertices, and so
    // the pixels along the edges that meet them, stay those Mesa's clipper gives).
    let (mut all_or, mut all_and) = (0u32, !0u32);
    for v in poly.iter() {
        all_or |= outcode(v, user, guard);
    }
    if all_or == 0 {
        return poly.iter().all(|v| v.pos.w > 0.0);
    }
    all_or = 0;
    for v in poly.iter() {
        let c = outcode(v, user, EXACT);
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
                let da = distance(a, i, user, EXACT);
                let db = distance(b, i, user, EXACT);
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
    let (ca, cb) = (outcode(a, user, EXACT), outcode(b, user, EXACT));
    if ca & cb != 0 {
        return None;
    }
    let (mut a, mut b) = (*a, *b);
    if ca | cb != 0 {
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for i in 0..6 + user.len() {
            let da = distance(&a, i, user, EXACT);
            let db = distance(&b, i, user, EXACT);
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
    v.is_finite() && outcode(v, user, EXACT) == 0 && v.pos.w > 0.0
}

/// How far from the window origin, in pixels, a filled polygon may reach and still be
/// rasterized without clipping against the side planes (a guard band): below 2^15 pixels the
/// fixed-point edge products stay far from overflow.
pub const GUARD_BAND: f64 = 32768.0;

/// The guard band's side planes for viewport scale `scale` and offset `offset` (x, y): the
/// factors g with `|x| <= g w` mapping inside [`GUARD_BAND`] pixels (never below 1, the view
/// volume itself).
pub fn guard_factors(scale: [f64; 2], offset: [f64; 2]) -> [f64; 2] {
    [0, 1].map(|d| {
        let g = (GUARD_BAND - offset[d].abs()) / scale[d].abs();
        if g.is_finite() && g > 1.0 {
            g
        } else {
            1.0
        }
    })
}

/// Whether a filled polygon's vertex needs no clipping: finite, w > 0, inside the near, far
/// and user clip planes and the guard band's side planes. The view volume's side planes need
/// no clipping: they bound the viewport, and the rasterizer visits only pixels inside it,
/// which are exactly the pixels of the clipped polygon (with the edges' exact slopes, and no
/// new vertices to snap). A polygon with a vertex outside is clipped against the same planes
/// ([`clip_polygon`] with `guard`), so the same polygon gives the same fragments whichever
/// way it is drawn (multipass invariance).
#[inline]
pub fn in_guard_band(v: &ClipVertex, user: &[DVec4], guard: [f64; 2]) -> bool {
    // `outcode(v, user, guard) == 0` with the planes written out (every vertex of a batch
    // comes here); NaN fails every comparison.
    let p = v.pos;
    let (gx, gy) = (p.w * guard[0], p.w * guard[1]);
    let inside = (p.w > 0.0)
        & (gx + p.x >= 0.0)
        & (gx - p.x >= 0.0)
        & (gy + p.y >= 0.0)
        & (gy - p.y >= 0.0)
        & (p.w + p.z >= 0.0)
        & (p.w - p.z >= 0.0);
    inside && v.is_finite() && user.iter().all(|u| u.dot(v.eye) >= 0.0)
}

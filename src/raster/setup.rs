//! Primitive setup: fixed-point window coordinates (8 sub-pixel bits), 64-bit edge functions
//! and attribute planes.

use crate::common::fixed::SUBPIXEL;

/// A linear function of window position: `a*x + b*y + c`, evaluated at pixel centres.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Plane {
    pub a: f64,
    pub b: f64,
    pub c: f64,
}

impl Plane {
    /// A constant.
    pub fn constant(v: f64) -> Plane {
        Plane {
            a: 0.0,
            b: 0.0,
            c: v,
        }
    }

    #[inline(always)]
    pub fn at(&self, x: f64, y: f64) -> f64 {
        self.a * x + self.b * y + self.c
    }

    /// The plane through three (x, y, value) points; `inv_det` is 1 / twice the signed area.
    pub fn through(p: [[f64; 2]; 3], v: [f64; 3], inv_det: f64) -> Plane {
        PlaneSetup::new(p, inv_det).plane(v)
    }
}

/// The part of [`Plane::through`] that depends only on the three points, computed once per
/// triangle for all its attribute planes (the same arithmetic, so the same planes).
#[derive(Clone, Copy, Debug)]
pub struct PlaneSetup {
    origin: [f64; 2],
    d1: [f64; 2],
    d2: [f64; 2],
    inv_det: f64,
}

impl PlaneSetup {
    pub fn new(p: [[f64; 2]; 3], inv_det: f64) -> PlaneSetup {
        PlaneSetup {
            origin: p[0],
            d1: [p[1][0] - p[0][0], p[1][1] - p[0][1]],
            d2: [p[2][0] - p[0][0], p[2][1] - p[0][1]],
            inv_det,
        }
    }

    /// The plane through the three points with values `v`.
    #[inline(always)]
    pub fn plane(&self, v: [f64; 3]) -> Plane {
        let ([dx1, dy1], [dx2, dy2]) = (self.d1, self.d2);
        let (dv1, dv2) = (v[1] - v[0], v[2] - v[0]);
        let a = (dv1 * dy2 - dv2 * dy1) * self.inv_det;
        let b = (dv2 * dx1 - dv1 * dx2) * self.inv_det;
        Plane {
            a,
            b,
            c: v[0] - a * self.origin[0] - b * self.origin[1],
        }
    }
}

/// One edge function `E(p) = a*px + b*py + c` over fixed-point positions; a pixel centre is
/// inside when `E >= bias`, with the edge's `bias` ([`Edge::new`]) kept beside it (in
/// `TriangleCommand::edges`).
#[derive(Clone, Copy, Debug)]
pub struct Edge {
    pub a: i64,
    pub b: i64,
    pub c: i64,
}

impl Edge {
    /// The edge from `p` to `q` of a counter-clockwise (positive area, y up) triangle, and
    /// its bias: 0 for top-left edges and 1 otherwise, so pixels exactly on a shared edge
    /// belong to one triangle only.
    ///
    /// Fill rule: in GL window coordinates (y up), pixel centres on an edge are included when it
    /// is a left edge (interior to its right: the edge runs downwards) or a top edge (horizontal
    /// with the interior below).
    pub fn new(p: [i64; 2], q: [i64; 2]) -> (Edge, u8) {
        let dx = q[0] - p[0];
        let dy = q[1] - p[1];
        let top_left = dy < 0 || (dy == 0 && dx < 0);
        let edge = Edge {
            a: -dy,
            b: dx,
            c: dy * p[0] - dx * p[1],
        };
        (edge, u8::from(!top_left))
    }
}

/// Pixels whose centres lie in `[lo, hi]` (fixed point): first and one-past-last index.
#[inline]
pub fn centre_range(lo: i64, hi: i64) -> (i32, i32) {
    let half = SUBPIXEL / 2;
    let first = (lo - half).div_euclid(SUBPIXEL) + i64::from((lo - half).rem_euclid(SUBPIXEL) != 0);
    let last = (hi - half).div_euclid(SUBPIXEL);
    (
        first.clamp(i32::MIN as i64, i32::MAX as i64) as i32,
        (last + 1).clamp(i32::MIN as i64, i32::MAX as i64) as i32,
    )
}

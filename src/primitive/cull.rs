//! Facing and culling (section 3.5.1): the sign of the window-space area decides the face.

use crate::common::values::{Face, Winding};

/// Twice the signed area of a polygon given in fixed-point window coordinates (y up):
/// positive for counter-clockwise.
pub fn signed_area2(points: &[[i64; 2]]) -> i128 {
    if let [a, b, c] = points {
        // A triangle (the common case): the same integer, from two edge vectors.
        let w = |v: i64| v as i128;
        return (w(b[0]) - w(a[0])) * (w(c[1]) - w(a[1]))
            - (w(c[0]) - w(a[0])) * (w(b[1]) - w(a[1]));
    }
    let n = points.len();
    (0..n)
        .map(|i| {
            let (p, q) = (points[i], points[(i + 1) % n]);
            p[0] as i128 * q[1] as i128 - q[0] as i128 * p[1] as i128
        })
        .sum()
}

/// Twice the signed area of a triangle of window vertices in the guard band (fixed point,
/// y up), in i64: there coordinates stay below 2^23 sub-pixels, so the cross product fits.
/// The same value as [`signed_area2`] of the three points.
#[inline(always)]
pub fn triangle_area2([a, b, c]: [[i64; 2]; 3]) -> i64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangle_area_matches_the_shoelace_sum() {
        let shoelace = |p: &[[i64; 2]]| -> i128 {
            (0..p.len())
                .map(|i| {
                    let (a, b) = (p[i], p[(i + 1) % p.len()]);
                    a[0] as i128 * b[1] as i128 - b[0] as i128 * a[1] as i128
                })
                .sum()
        };
        let mut seed = 7u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 16) as i64 % (1 << 40) - (1 << 39)
        };
        for _ in 0..1000 {
            let tri = [[next(), next()], [next(), next()], [next(), next()]];
            assert_eq!(signed_area2(&tri), shoelace(&tri));
        }
        // Guard-band range (below 2^23 sub-pixels): the i64 form gives the same.
        for _ in 0..1000 {
            let mut small = || next() % (1 << 23);
            let tri = [[small(), small()], [small(), small()], [small(), small()]];
            assert_eq!(i128::from(triangle_area2(tri)), shoelace(&tri));
        }
        let ccw = [[0, 0], [4, 0], [0, 4]];
        assert_eq!(signed_area2(&ccw), 16);
        let quad = [[0, 0], [4, 0], [4, 4], [0, 4]];
        assert_eq!(signed_area2(&quad), 32);
    }
}

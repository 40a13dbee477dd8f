//! Lines of width 1 (section 3.4.1), by the diamond-exit rule in its major-axis form: an
//! x-major line produces one fragment per pixel column whose diamond it leaves (the start
//! pixel is drawn, the end pixel is not), in the row that contains the line at the column's
//! centre; y-major lines likewise with rows. Attributes are interpolated perspective-correctly
//! along the line.

use super::point::emit_pixel;
use super::setup::SUBPIXEL;
use crate::primitive::viewport::WindowVertex;
use crate::raster::scene::Scene;
use crate::state::snapshot::MAX_ATTRS;
use crate::state::DrawState;

pub fn bin_line(
    ds: &DrawState,
    state: u32,
    v: [&WindowVertex; 2],
    attrs: [&[f32]; 2],
    scene: &mut Scene,
) {
    let s = SUBPIXEL as f64;
    let (x0, y0) = (v[0].xy[0] as f64 / s, v[0].xy[1] as f64 / s);
    let (x1, y1) = (v[1].xy[0] as f64 / s, v[1].xy[1] as f64 / s);
    let (dx, dy) = (x1 - x0, y1 - y0);
    if dx == 0.0 && dy == 0.0 {
        return;
    }
    let x_major = dx.abs() >= dy.abs();
    // Major-axis coordinates of the endpoints, and the minor coordinate as a function of it.
    let (a0, a1, b0, db_da) = if x_major {
        (x0, x1, y0, dy / dx)
    } else {
        (y0, y1, x0, dx / dy)
    };
    // Candidate pixels: one per major-axis row from the start's to the end's; each is kept
    // when the segment leaves that pixel's diamond (see `exits_diamond`).
    let (first, last) = (a0.min(a1).floor(), a0.max(a1).floor());
    // Bound the loop by the draw rectangle so huge lines cost only what is visible.
    let r = &ds.draw_rect;
    let (clip_lo, clip_hi) = if x_major {
        (r.x0 as f64, r.x1 as f64 - 1.0)
    } else {
        (r.y0 as f64, r.y1 as f64 - 1.0)
    };
    let first = first.max(clip_lo);
    let last = last.min(clip_hi);
    let n = ds.attr_count.min(MAX_ATTRS);
    let mut a = [0f32; MAX_ATTRS];
    let mut c = first;
    let (lo, hi) = (a0.min(a1), a0.max(a1));
    while c <= last {
        let centre = c + 0.5;
        let t = ((centre - a0) / (a1 - a0)).clamp(0.0, 1.0);
        let minor = (b0 + (centre.clamp(lo, hi) - a0) * db_da).floor();
        let (px, py) = if x_major { (c, minor) } else { (minor, c) };
        if !exits_diamond([x0, y0], [x1, y1], [px + 0.5, py + 0.5]) {
            c += 1.0;
            continue;
        }
        let z = v[0].z + t * (v[1].z - v[0].z);
        // Perspective-correct: interpolate attr/w and 1/w linearly in window space.
        let iw = v[0].inv_w + t * (v[1].inv_w - v[0].inv_w);
        for i in 0..n {
            let p = attrs[0][i] as f64 * v[0].inv_w
                + t * (attrs[1][i] as f64 * v[1].inv_w - attrs[0][i] as f64 * v[0].inv_w);
            // Flat colours are equal at both ends, so this returns them unchanged.
            a[i] = (p / iw) as f32;
        }
        emit_pixel(ds, state, px as i64, py as i64, z, &a[..n], scene);
        c += 1.0;
    }
}

/// Section 3.4.1's diamond-exit rule for the pixel centred at `c`: the segment from `p0` to
/// `p1` produces the fragment when it meets the diamond `|x - cx| + |y - cy| < 1/2` and its end
/// point lies outside it (it leaves the diamond).
fn exits_diamond(p0: [f64; 2], p1: [f64; 2], c: [f64; 2]) -> bool {
    let l1 = |p: [f64; 2]| (p[0] - c[0]).abs() + (p[1] - c[1]).abs();
    if l1(p1) < 0.5 {
        return false;
    }
    // The L1 distance is convex and piecewise linear along the segment: its minimum is at an
    // end point or where the segment crosses x = cx or y = cy.
    let mut best = l1(p0).min(l1(p1));
    for axis in 0..2 {
        let d = p1[axis] - p0[axis];
        if d != 0.0 {
            let t = (c[axis] - p0[axis]) / d;
            if (0.0..=1.0).contains(&t) {
                best = best.min(l1([
                    p0[0] + t * (p1[0] - p0[0]),
                    p0[1] + t * (p1[1] - p0[1]),
                ]));
            }
        }
    }
    best < 0.5
}

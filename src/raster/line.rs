//! Lines (section 3.4).
//!
//! Aliased lines use the diamond-exit rule in its major-axis form: an x-major line produces
//! one fragment per pixel column whose diamond it leaves (the start pixel is drawn, the end
//! pixel is not), in the row that contains the line at the column's centre; y-major lines
//! likewise with rows. A line of width `w = round(width)` is the width-1 line moved by
//! `-(w - 1) / 2` in the minor direction, each fragment replaced by a column of `w` fragments
//! in the minor direction (section 3.4.2).
//!
//! Antialiased lines cover the rectangle of the given width centred on the segment, each
//! pixel taking a box-filtered estimate of the rectangle's share of its area as coverage; a
//! fragment's data are those at its centre's position along the segment.
//!
//! Stippling (section 3.4.2) counts fragments along the line (a wide line's column counts
//! once) with the counter the caller keeps across the segments of a strip or loop.
//! Attributes are interpolated perspective-correctly along the line.

use super::point::{add_constant_planes, bin_rect, emit_rect};
use super::setup::SUBPIXEL;
use crate::primitive::viewport::WindowVertex;
use crate::raster::scene::Scene;
use crate::state::snapshot::MAX_ATTRS;
use crate::state::tables::limits;
use crate::state::DrawState;

/// Whether the stipple lets fragment number `counter` through.
#[inline]
fn stipple_passes(stipple: Option<(u32, u16)>, counter: u32) -> bool {
    match stipple {
        None => true,
        Some((factor, pattern)) => pattern & (1 << ((counter / factor.max(1)) % 16)) != 0,
    }
}

/// Attributes at parameter `t` of the segment, perspective-correct.
fn attrs_at(v: [&WindowVertex; 2], attrs: [&[f32]; 2], t: f64, n: usize, out: &mut [f32]) {
    // Interpolate attr/w and 1/w linearly in window space.
    let iw = v[0].inv_w + t * (v[1].inv_w - v[0].inv_w);
    for i in 0..n {
        let p = attrs[0][i] as f64 * v[0].inv_w
            + t * (attrs[1][i] as f64 * v[1].inv_w - attrs[0][i] as f64 * v[0].inv_w);
        // Flat colours are equal at both ends, so this returns them unchanged.
        out[i] = (p / iw) as f32;
    }
}

/// Bins one line segment. `z_offset` is a polygon offset (edges of polygons in line mode);
/// `stipple_counter` carries the stipple count from the previous segment of a strip.
pub fn bin_line(
    ds: &DrawState,
    state: u32,
    v: [&WindowVertex; 2],
    attrs: [&[f32]; 2],
    z_offset: f64,
    stipple_counter: &mut u32,
    scene: &mut Scene,
) {
    if ds.raster.line_smooth {
        bin_smooth_line(ds, state, v, attrs, z_offset, stipple_counter, scene);
        return;
    }
    let s = SUBPIXEL as f64;
    let (x0, y0) = (v[0].xy[0] as f64 / s, v[0].xy[1] as f64 / s);
    let (x1, y1) = (v[1].xy[0] as f64 / s, v[1].xy[1] as f64 / s);
    let (dx, dy) = (x1 - x0, y1 - y0);
    if dx == 0.0 && dy == 0.0 {
        return;
    }
    let [wlo, whi] = limits::LINE_WIDTH_RANGE;
    let rounded = (ds.raster.line_width as f64).round();
    let width = if rounded.is_nan() {
        1
    } else {
        rounded.max(wlo as f64).min(whi as f64) as i64
    };
    let x_major = dx.abs() >= dy.abs();
    // The width-1 line moved by -(w - 1) / 2 in the minor direction.
    let shift = (width - 1) as f64 / 2.0;
    let (p0, p1) = if x_major {
        ([x0, y0 - shift], [x1, y1 - shift])
    } else {
        ([x0 - shift, y0], [x1 - shift, y1])
    };
    // Major-axis coordinates of the endpoints, and the minor coordinate as a function of it.
    let (a0, a1, b0, db_da) = if x_major {
        (p0[0], p1[0], p0[1], dy / dx)
    } else {
        (p0[1], p1[1], p0[0], dx / dy)
    };
    // Candidate pixels: one per major-axis column from the start's to the end's, in the
    // direction of travel (the stipple counts in that order); each is kept when the segment
    // leaves that pixel's diamond. Clipping bounded the segment by the viewport, so the loop
    // is bounded too; only columns inside the draw rectangle are recorded.
    let (first, last) = (a0.min(a1).floor(), a0.max(a1).floor());
    let count = (last - first) as i64 + 1;
    let r = &ds.draw_rect;
    let (clip_lo, clip_hi) = if x_major {
        (r.x0 as f64, r.x1 as f64 - 1.0)
    } else {
        (r.y0 as f64, r.y1 as f64 - 1.0)
    };
    let n = ds.attr_count.min(MAX_ATTRS);
    let mut a = [0f32; MAX_ATTRS];
    let (lo, hi) = (a0.min(a1), a0.max(a1));
    let stipple = ds.raster.line_stipple;
    let start_counter = *stipple_counter;
    for k in 0..count.max(0) {
        let c = if a1 >= a0 {
            first + k as f64
        } else {
            last - k as f64
        };
        let centre = c + 0.5;
        // Which columns: the diamond-exit rule on the segment itself (a wide line has the
        // same columns as its width-1 line, as llvmpipe draws them); which rows: the moved
        // segment's.
        let m = b0 + (centre.clamp(lo, hi) - a0) * db_da;
        let unshifted = (m + shift).floor();
        let diamond = if x_major {
            [c + 0.5, unshifted + 0.5]
        } else {
            [unshifted + 0.5, c + 0.5]
        };
        if !exits_diamond([x0, y0], [x1, y1], diamond) {
            continue;
        }
        let minor = m.floor();
        let (px, py) = if x_major { (c, minor) } else { (minor, c) };
        // The fragment's place along the segment: where the segment leaves its pixel, in
        // whole major-axis units from the start.
        let exit = if a1 >= a0 { c + 1.0 - a0 } else { a0 - c };
        let counter = start_counter.wrapping_add(exit.max(0.0).floor() as u32);
        if c < clip_lo || c > clip_hi || !stipple_passes(stipple, counter) {
            continue;
        }
        let t = ((centre - a0) / (a1 - a0)).clamp(0.0, 1.0);
        let z = v[0].z + t * (v[1].z - v[0].z) + z_offset;
        attrs_at(v, attrs, t, n, &mut a);
        let (px, py) = (px as i64, py as i64);
        let rect = if x_major {
            [px, py, px + 1, py + width]
        } else {
            [px, py, px + width, py + 1]
        };
        emit_rect(ds, state, rect, z, &a[..n], 1.0, scene);
    }
    // The next segment of a strip continues the count after ceil(major length) fragments
    // (what the segment produces up to the end-point rounding; Mesa counts the same way).
    let advance = (a1 - a0).abs().ceil();
    *stipple_counter = start_counter.wrapping_add(advance.min(u32::MAX as f64) as u32);
}

/// An antialiased line: the rectangle of width `GL_LINE_WIDTH` centred on the segment.
fn bin_smooth_line(
    ds: &DrawState,
    state: u32,
    v: [&WindowVertex; 2],
    attrs: [&[f32]; 2],
    z_offset: f64,
    stipple_counter: &mut u32,
    scene: &mut Scene,
) {
    let s = SUBPIXEL as f64;
    let p0 = [v[0].xy[0] as f64 / s, v[0].xy[1] as f64 / s];
    let p1 = [v[1].xy[0] as f64 / s, v[1].xy[1] as f64 / s];
    let (dx, dy) = (p1[0] - p0[0], p1[1] - p0[1]);
    let len = (dx * dx + dy * dy).sqrt();
    if !(len > 0.0) {
        return;
    }
    let [wlo, whi] = limits::LINE_WIDTH_RANGE;
    let w = (ds.raster.line_width as f64)
        .max(wlo as f64)
        .min(whi as f64);
    let dir = [dx / len, dy / len];
    let x_major = dx.abs() >= dy.abs();
    let (a0, a1, b0, db_da) = if x_major {
        (p0[0], p1[0], p0[1], dy / dx)
    } else {
        (p0[1], p1[1], p0[0], dx / dy)
    };
    // Minor-direction half extent of the rectangle at one major coordinate, plus a margin for
    // the slope across a pixel.
    let slope = db_da.abs();
    let reach = w / 2.0 * (1.0 + slope * slope).sqrt() + slope + 1.0;
    let (lo, hi) = (a0.min(a1), a0.max(a1));
    let first = (lo - w / 2.0).floor() as i64;
    let last = (hi + w / 2.0).floor() as i64;
    let n = ds.attr_count.min(MAX_ATTRS);
    let mut a = [0f32; MAX_ATTRS];
    let stipple = ds.raster.line_stipple;
    let count = last - first + 1;
    for k in 0..count.max(0) {
        let c = if a1 >= a0 { first + k } else { last - k };
        let centre = c as f64 + 0.5;
        // Columns along the segment itself advance the stipple counter.
        let along = centre >= lo && centre < hi;
        let counter = *stipple_counter;
        if along {
            *stipple_counter = stipple_counter.wrapping_add(1);
        }
        if !stipple_passes(stipple, counter) {
            continue;
        }
        let m = b0 + (centre.clamp(lo, hi) - a0) * db_da;
        for r in (m - reach).floor() as i64..=(m + reach).floor() as i64 {
            let (px, py) = if x_major { (c, r) } else { (r, c) };
            let (cov, u) = rect_coverage(p0, dir, len, w, px, py);
            if cov > 0.0 {
                // Data vary over the rectangle extended by half a pixel past each end point
                // (the box filter's reach), as Mesa parameterises them: then the depth of a
                // smooth outline drawn before a polygon over the same edge decides the same
                // pixels as Mesa's (xss-stonerview).
                let t = ((u + 0.5) / (len + 1.0)).clamp(0.0, 1.0);
                attrs_at(v, attrs, t, n, &mut a);
                let z = v[0].z + t * (v[1].z - v[0].z) + z_offset;
                let o = add_constant_planes(&a[..n], scene);
                bin_rect(ds, state, [px, py, px + 1, py + 1], z, o, cov, scene);
            }
        }
    }
}

/// Coverage of pixel `(px, py)` by the rectangle along `dir` from `p0` (length `len`, width
/// `w`): the box-filtered distance of the pixel centre to the rectangle's sides, across and
/// along the segment (an analytic approximation of the covered area).
fn rect_coverage(p0: [f64; 2], dir: [f64; 2], len: f64, w: f64, px: i64, py: i64) -> (f32, f64) {
    let sx = px as f64 + 0.5 - p0[0];
    let sy = py as f64 + 0.5 - p0[1];
    let u = sx * dir[0] + sy * dir[1];
    let d = (sx * dir[1] - sy * dir[0]).abs();
    let across = (w / 2.0 + 0.5 - d).clamp(0.0, 1.0);
    let along = (u + 0.5).clamp(0.0, 1.0) * (len + 0.5 - u).clamp(0.0, 1.0);
    ((across * along) as f32, u)
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

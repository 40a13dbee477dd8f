//! Lines of width 1 (section 3.4.1). tilegl follows the diamond-exit rule in its usual
//! "half-open major axis" form: an x-major line produces one fragment per pixel column whose
//! centre lies in [x_start, x_end) (mirrored for lines drawn towards -x), in the row that
//! contains the line at that centre; y-major lines likewise with rows. Attributes are
//! interpolated perspective-correctly along the line.

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
    let forward = a1 > a0;
    let (lo, hi) = if forward { (a0, a1) } else { (a1, a0) };
    // Pixel centres c + 0.5 in [lo, hi) going forward, (lo, hi] going backward.
    let first = if forward {
        (lo - 0.5).ceil()
    } else {
        (lo - 0.5).floor() + 1.0
    };
    let last = if forward {
        (hi - 0.5).ceil() - 1.0
    } else {
        (hi - 0.5).floor()
    };
    if !(first <= last) {
        return;
    }
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
    while c <= last {
        let centre = c + 0.5;
        let t = ((centre - a0) / (a1 - a0)).clamp(0.0, 1.0);
        let minor = (b0 + (centre - a0) * db_da).floor();
        let z = v[0].z + t * (v[1].z - v[0].z);
        // Perspective-correct: interpolate attr/w and 1/w linearly in window space.
        let iw = v[0].inv_w + t * (v[1].inv_w - v[0].inv_w);
        for i in 0..n {
            let p = attrs[0][i] as f64 * v[0].inv_w
                + t * (attrs[1][i] as f64 * v[1].inv_w - attrs[0][i] as f64 * v[0].inv_w);
            a[i] = if ds.flat {
                attrs[0][i]
            } else {
                (p / iw) as f32
            };
        }
        let (px, py) = if x_major {
            (c as i64, minor as i64)
        } else {
            (minor as i64, c as i64)
        };
        emit_pixel(ds, state, px, py, z, &a[..n], scene);
        c += 1.0;
    }
}

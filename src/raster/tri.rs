//! Triangle traversal within one tile: for each row, the covered interval is solved from the
//! three edge functions directly (triangles are convex), then handed to the span function.

use super::draw::TileDraw;
use super::scene::TriangleCommand;
use super::setup::{Edge, Plane};
use crate::common::fixed::SUBPIXEL;
use crate::fragment::span::{span_stippled, Interpolants, PrimitiveShared, UnitLevels};
use crate::framebuffer::Tile;

/// A triangle's attribute planes spread over the draw's attribute layout (zero where an
/// attribute is not live), reused from triangle to triangle of a tile: while the live set
/// stays the same, only the live slots are written.
#[derive(Debug, Default)]
pub struct AttrScratch {
    planes: Vec<Plane>,
    /// The live set the zero slots are for.
    live: u64,
}

impl AttrScratch {
    /// `live_planes` (in attribute order) spread over `n` slots by `live`; with
    /// `packed_primary` the first two hold the constant primary colour three values to a
    /// plane ([`TriangleCommand::constant_primary`]), spread as constant planes.
    #[inline]
    fn spread(
        &mut self,
        n: usize,
        live: u64,
        live_planes: &[Plane],
        packed_primary: bool,
    ) -> &[Plane] {
        if self.planes.len() != n || self.live != live {
            self.planes.clear();
            self.planes.resize(n, Plane::constant(0.0));
            self.live = live;
        }
        let mut from = live_planes.iter();
        let mut mask = live & ((1u64 << n) - 1);
        if packed_primary {
            let (p, q) = (
                from.next().copied().unwrap_or(Plane::constant(0.0)),
                from.next().copied().unwrap_or(Plane::constant(0.0)),
            );
            for (k, v) in [p.a, p.b, p.c, q.a].into_iter().enumerate() {
                if let Some(slot) = self.planes.get_mut(attr::COLOR0 + k) {
                    *slot = Plane::constant(v);
                }
            }
            mask &= !(0xFu64 << attr::COLOR0);
        }
        while mask != 0 {
            let i = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            self.planes[i] = from.next().copied().unwrap_or(Plane::constant(0.0));
        }
        &self.planes
    }
}

/// Shades the part of triangle `t` inside `tile`; `planes` are its window-z plane, its 1/w
/// plane and the planes of the draw's live attributes (`TileDraw::live_attrs`), which are
/// spread over `scratch` (the others zero) unless every attribute is live.
pub fn raster_triangle<'a>(
    t: &TriangleCommand,
    ds: &'a TileDraw,
    planes: &'a [Plane],
    levels: &'a UnitLevels<'a>,
    scratch: &'a mut AttrScratch,
    tile: &mut Tile,
) {
    let tile_size = tile.side();
    let bbox = t.bbox();
    let x_lo = bbox.x0.max(tile.x0);
    let x_hi = bbox.x1.min(tile.x0 + tile_size);
    let y_lo = bbox.y0.max(tile.y0);
    let y_hi = bbox.y1.min(tile.y0 + tile_size);
    if x_lo >= x_hi || y_lo >= y_hi {
        return;
    }
    let n = ds.attr_count;
    let attrs: &[Plane] = if ds.live_attrs == (1u64 << n) - 1 && !t.constant_primary() {
        &planes[2..]
    } else {
        scratch.spread(n, ds.live_attrs, &planes[2..], t.constant_primary())
    };
    let stipple = ds.raster.polygon_stipple.as_ref();
    let shared = PrimitiveShared::new(levels).with_stipple(stipple);
    let it = Interpolants {
        z: planes[0],
        inv_w: planes[1],
        attrs,
        perspective: true,
        constant_primary: t.constant_primary(),
        coverage: 1.0,
        shared: &shared,
    };
    let (edges, bias) = t.edges();
    if ds.raster.polygon_smooth {
        smooth_rows(&edges, ds, &it, tile, [x_lo, x_hi, y_lo, y_hi], stipple);
        return;
    }
    let half = SUBPIXEL / 2;
    // The covered pixels `lo..hi` of row `y`, when there are any: the interval where all three
    // edge functions pass, solved per edge.
    let row_interval = |y: i32| -> Option<(i32, i32)> {
        let py = y as i64 * SUBPIXEL + half;
        let mut lo = x_lo as i64;
        let mut hi = x_hi as i64; // exclusive
        for (e, &bias) in edges.iter().zip(&bias) {
            // E(x) = step * x + base, with px = x * SUBPIXEL + half.
            let base = e.b * py + e.c + e.a * half;
            let step = e.a * SUBPIXEL;
            // Inside when step * x >= need.
            let need = i64::from(bias) - base;
            // Quotients by truncating division, rounded up or down by the remainder's sign
            // (one division, fewer fix-ups than the Euclidean forms).
            if step > 0 {
                // ceil(need / step)
                lo = lo.max(need / step + i64::from(need % step > 0));
            } else if step < 0 {
                // -|step| * x >= need  <=>  x <= floor(-need / |step|)
                let (n, s) = (-need, -step);
                hi = hi.min(n / s - i64::from(n % s < 0) + 1);
            } else if need > 0 {
                return None;
            }
        }
        (lo < hi).then_some((lo as i32, hi as i32))
    };
    match (stipple, ds.fragment.span_pair) {
        (_, Some(pair)) => {
            // A stippled polygon's rows all go to the pair function, which applies the
            // pattern as a lane mask (`PrimitiveShared::stipple`).
            let lone = if stipple.is_some() { i32::MAX } else { 4 };
            // Rows in pairs (even y first), gathered for one call of the pair function, which
            // then prepares what does not depend on the rows once per triangle (a tile has at
            // most 32 pairs in a tile of the default side, 64; taller tiles hand them over in
            // batches). A triangle covers no pixel twice, so shading its long lone rows on the
            // way, before the pairs, or in several batches, gives the same pixels.
            const EMPTY: (i32, i32) = (0, 0);
            let mut pairs = [(0, [EMPTY; 2]); crate::framebuffer::TILE / 2];
            let mut n = 0;
            let mut y = y_lo & !1;
            while y < y_hi {
                let lower = if y >= y_lo { row_interval(y) } else { None };
                let upper = if y + 1 < y_hi {
                    row_interval(y + 1)
                } else {
                    None
                };
                // A short lone row goes to the pair function too (a block is two quads wide);
                // a long one is shaded as a row.
                let rows = match (lower, upper) {
                    (Some(a), Some(b)) => Some([a, b]),
                    (Some(a), None) if a.1 - a.0 <= lone => Some([a, EMPTY]),
                    (None, Some(b)) if b.1 - b.0 <= lone => Some([EMPTY, b]),
                    (Some((x0, x1)), None) => {
                        (ds.fragment.span)(&ds.fragment, tile, y, x0, x1, &it);
                        None
                    }
                    (None, Some((x0, x1))) => {
                        (ds.fragment.span)(&ds.fragment, tile, y + 1, x0, x1, &it);
                        None
                    }
                    (None, None) => None,
                };
                if let Some(rows) = rows {
                    if n == pairs.len() {
                        pair(&ds.fragment, tile, &pairs, &it);
                        n = 0;
                    }
                    pairs[n] = (y, rows);
                    n += 1;
                }
                y += 2;
            }
            if n > 0 {
                pair(&ds.fragment, tile, &pairs[..n], &it);
            }
        }
        (None, None) => {
            for y in y_lo..y_hi {
                if let Some((x0, x1)) = row_interval(y) {
                    (ds.fragment.span)(&ds.fragment, tile, y, x0, x1, &it);
                }
            }
        }
        (Some(pattern), None) => {
            for y in y_lo..y_hi {
                if let Some((x0, x1)) = row_interval(y) {
                    span_stippled(&ds.fragment, tile, y, x0, x1, &it, pattern);
                }
            }
        }
    }
}

/// `GL_POLYGON_SMOOTH` (section 3.5.6 and 3.11): every pixel of the (one pixel wider)
/// bounding box gets the triangle's coverage, approximated by the box-filtered distances of
/// its centre to the three edges; runs of full coverage are shaded as spans. The polygon
/// stipple applies "regardless of the state of polygon antialiasing" (section 3.5.2).
fn smooth_rows<'a>(
    edges: &[Edge; 3],
    ds: &'a TileDraw,
    it: &Interpolants<'a>,
    tile: &mut Tile,
    [x_lo, x_hi, y_lo, y_hi]: [i32; 4],
    stipple: Option<&[u32; 32]>,
) {
    let s = SUBPIXEL as f64;
    // Edge functions in pixel units: E(p) / |(a, b)| is the signed distance in pixels.
    let edges = edges.map(|e| {
        let len = ((e.a as f64).powi(2) + (e.b as f64).powi(2))
            .sqrt()
            .max(1e-12);
        (e.a as f64 * s / len, e.b as f64 * s / len, e.c as f64 / len)
    });
    let coverage = |x: f64, y: f64| -> f32 {
        let mut c = 1.0f64;
        for &(a, b, k) in &edges {
            let d = (a * x + b * y + k) / s;
            c *= (d + 0.5).clamp(0.0, 1.0);
        }
        c as f32
    };
    for y in y_lo..y_hi {
        let yc = y as f64 + 0.5;
        let mut x = x_lo;
        while x < x_hi {
            let cov = coverage(x as f64 + 0.5, yc);
            if cov >= 1.0 {
                let start = x;
                while x < x_hi && coverage(x as f64 + 0.5, yc) >= 1.0 {
                    x += 1;
                }
                match stipple {
                    None => (ds.fragment.span)(&ds.fragment, tile, y, start, x, it),
                    Some(p) => span_stippled(&ds.fragment, tile, y, start, x, it, p),
                }
                continue;
            }
            let kept = stipple
                .is_none_or(|p| p[y.rem_euclid(32) as usize] & (1 << (31 - x.rem_euclid(32))) != 0);
            if cov > 0.0 && kept {
                let edge = Interpolants {
                    coverage: cov,
                    ..*it
                };
                (ds.fragment.span)(&ds.fragment, tile, y, x, x + 1, &edge);
            }
            x += 1;
        }
    }
}

use super::scene::{Command, Scene};
use super::setup::triangle_area2;
use super::setup::WindowVertex;
use super::setup::{centre_range, PlaneSetup};
use crate::common::attr::{self, MAX_ATTRS};
use crate::common::rect::Rect;
use crate::common::values::PolygonMode;

/// The window-z plane of a triangle (for polygon offset), or `None` when it has no area.
pub fn depth_plane(v: [&WindowVertex; 3]) -> Option<Plane> {
    let area2 = triangle_area2([v[0].xy, v[1].xy, v[2].xy]);
    if area2 == 0 {
        return None;
    }
    let s = SUBPIXEL as f64;
    let p = v.map(|w| [w.xy[0] as f64 / s, w.xy[1] as f64 / s]);
    Some(Plane::through(p, v.map(|w| w.z), (s * s) / area2 as f64))
}

/// Sets up one triangle (any winding; facing was decided before) and bins it, its depth moved
/// by the polygon offset when `GL_POLYGON_OFFSET_FILL` is on (section 3.5.5).
pub fn bin_triangle(
    ds: &TileDraw,
    state: u32,
    v: [&WindowVertex; 3],
    attrs: [&[f32]; 3],
    scene: &mut Scene,
) {
    let (mut v, mut attrs) = (v, attrs);
    let area2 = triangle_area2([v[0].xy, v[1].xy, v[2].xy]);
    if area2 == 0 {
        return;
    }
    if area2 < 0 {
        v.swap(1, 2);
        attrs.swap(1, 2);
    }
    // Arrays written out rather than built by `map` (whose iterator machinery costs more
    // than the set-up arithmetic in this hot function; the same values).
    let xs = [v[0].xy[0], v[1].xy[0], v[2].xy[0]];
    let ys = [v[0].xy[1], v[1].xy[1], v[2].xy[1]];
    let (x0, x1) = centre_range(
        *xs.iter().min().unwrap_or(&0),
        *xs.iter().max().unwrap_or(&0),
    );
    let (y0, y1) = centre_range(
        *ys.iter().min().unwrap_or(&0),
        *ys.iter().max().unwrap_or(&0),
    );
    let mut bbox = Rect { x0, y0, x1, y1 };
    if ds.raster.polygon_smooth {
        // Partly covered pixels around the edges take part too.
        bbox = Rect {
            x0: x0 - 1,
            y0: y0 - 1,
            x1: x1 + 1,
            y1: y1 + 1,
        };
    }
    let bbox = bbox.intersect(&ds.draw_rect);
    if bbox.is_empty() {
        return;
    }
    let s = SUBPIXEL as f64;
    let snapped = |w: &WindowVertex| [w.xy[0] as f64 / s, w.xy[1] as f64 / s];
    let p = [snapped(v[0]), snapped(v[1]), snapped(v[2])];
    let inv_det = (s * s) / area2.unsigned_abs() as f64;
    let mut z = Plane::through(p, [v[0].z, v[1].z, v[2].z], inv_det);
    if let Some(o) = &ds.raster.offset {
        z.c += o.for_plane(PolygonMode::Fill, z.a, z.b, ds.fragment.depth_max);
    }
    // 1/w and the attributes are interpolated over the unsnapped positions (as Mesa does):
    // snapping moves a vertex by up to half a sub-pixel, which tilts the planes of long thin
    // triangles enough to shift texture coordinates by several texels near a horizon.
    let (p, inv_det) = {
        let q = [v[0].pos, v[1].pos, v[2].pos];
        let det =
            (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[2][0] - q[0][0]) * (q[1][1] - q[0][1]);
        if det != 0.0 && det.is_finite() && (1.0 / det).is_finite() {
            (q, 1.0 / det)
        } else {
            (p, inv_det)
        }
    };
    let setup = PlaneSetup::new(p, inv_det);
    let inv_w = setup.plane([v[0].inv_w, v[1].inv_w, v[2].inv_w]);
    let n = ds.attr_count.min(MAX_ATTRS);
    // Every attribute is interpolated perspective-correctly (as attribute/w). Under flat
    // shading the colours are constant: their planes are the 1/w plane scaled by the provoking
    // vertex's value (every vertex already carries it), so dividing by 1/w gives it back.
    // Only the attributes the fragment stage reads get planes (`TileDraw::live_attrs`).
    let w = [v[0].inv_w, v[1].inv_w, v[2].inv_w];
    let (a0, a1, a2) = (&attrs[0][..n], &attrs[1][..n], &attrs[2][..n]);
    // A primary colour that is the same at the three vertices (lighting off, one glColor, or
    // flat shading) is stored as is and taken without perspective division.
    let primary = attr::COLOR0..attr::COLOR0 + 4;
    let primary_mask = 0xFu64 << attr::COLOR0;
    let constant_primary = n >= primary.end
        && ds.live_attrs & primary_mask == primary_mask
        && primary.clone().all(|i| a0[i] == a1[i] && a0[i] == a2[i]);
    let offset = scene.planes.len() as u32;
    scene.planes.reserve(n + 2);
    // A triangle's planes take two or three lines: the next triangles' asked for now.
    super::prefetch::write_past(&scene.planes, super::prefetch::WRITE_AHEAD, 192);
    scene.planes.push(z);
    scene.planes.push(inv_w);
    if constant_primary {
        // Packed three to a plane (`AttrScratch::spread` unpacks them).
        let c = |k: usize| a0[attr::COLOR0 + k] as f64;
        scene.planes.push(Plane {
            a: c(0),
            b: c(1),
            c: c(2),
        });
        scene.planes.push(Plane {
            a: c(3),
            b: 0.0,
            c: 0.0,
        });
    }
    // The live attributes in order (the planes' layout), the packed primary left out.
    let mut live = ds.live_attrs & ((1u64 << n) - 1);
    if constant_primary {
        live &= !primary_mask;
    }
    while live != 0 {
        let i = live.trailing_zeros() as usize;
        live &= live - 1;
        let (x0, x1, x2) = (a0[i], a1[i], a2[i]);
        scene.planes.push(if ds.flat && attr::is_color(i) {
            let c = x0 as f64;
            Plane {
                a: inv_w.a * c,
                b: inv_w.b * c,
                c: inv_w.c * c,
            }
        } else {
            setup.plane([x0 as f64 * w[0], x1 as f64 * w[1], x2 as f64 * w[2]])
        });
    }

    // Clipping keeps positions inside the guard band, so the command always fits.
    let xy = [v[0].xy, v[1].xy, v[2].xy];
    if let Some(t) = TriangleCommand::new(state, offset, bbox, xy, constant_primary) {
        scene.bin(Command::Triangle(t), bbox);
    }
}

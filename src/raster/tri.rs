//! Triangle traversal within one tile: for each row, the covered interval is solved from the
//! three edge functions directly (triangles are convex), then handed to the span function.

use super::draw::TileDraw;
use super::scene::TriangleCommand;
use super::setup::{Edge, Plane};
use crate::common::fixed::SUBPIXEL;
use crate::fragment::span::{span_stippled, Interpolants, PrimitiveShared, RowPair, UnitLevels};
use crate::framebuffer::Tile;

/// A triangle's attribute planes spread over the draw's attribute layout (zero where an
/// attribute is not live), reused from triangle to triangle of a tile: while the live set
/// stays the same, only the live slots are written.
#[derive(Debug)]
pub struct AttrScratch {
    planes: SpreadPlanes,
    /// The row pairs gathered for the draw's pair function (kept here: a fresh array per
    /// triangle was a 640-byte `memset` each time).
    pairs: [RowPair; crate::framebuffer::TILE / 2],
}

impl Default for AttrScratch {
    fn default() -> Self {
        AttrScratch {
            planes: SpreadPlanes::default(),
            pairs: [(0, [(0, 0); 2]); crate::framebuffer::TILE / 2],
        }
    }
}

#[derive(Debug, Default)]
struct SpreadPlanes {
    planes: Vec<Plane>,
    /// The live set the zero slots are for.
    live: u64,
}

impl SpreadPlanes {
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
    let AttrScratch {
        planes: spread,
        pairs,
    } = scratch;
    let attrs: &[Plane] = if ds.live_attrs == (1u64 << n) - 1 && !t.constant_primary() {
        &planes[2..]
    } else {
        spread.spread(n, ds.live_attrs, &planes[2..], t.constant_primary())
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
    // The covered pixels of the rows from `y_lo` up, one row at a time; nothing when an edge
    // leaves every pixel centre of the window outside.
    // A triangle whose whole box lies in the tile (most small ones) keeps its three edges
    // without the corner test: it would cost more than it saves there.
    let whole = x_lo == bbox.x0 && x_hi == bbox.x1 && y_lo == bbox.y0 && y_hi == bbox.y1;
    let Some(mut rows) = RowEdges::new(&edges, &bias, [x_lo, x_hi, y_lo, y_hi], !whole) else {
        return;
    };
    let mut next_row = move || rows.next_row();
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
            let mut n = 0;
            let mut y = y_lo & !1;
            while y < y_hi {
                let lower = if y >= y_lo { next_row() } else { None };
                let upper = if y + 1 < y_hi { next_row() } else { None };
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
                        pair(&ds.fragment, tile, &pairs[..], &it);
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
                if let Some((x0, x1)) = next_row() {
                    (ds.fragment.span)(&ds.fragment, tile, y, x0, x1, &it);
                }
            }
        }
        (Some(pattern), None) => {
            for y in y_lo..y_hi {
                if let Some((x0, x1)) = next_row() {
                    span_stippled(&ds.fragment, tile, y, x0, x1, &it, pattern);
                }
            }
        }
    }
}

/// A triangle's edges over one window of rows (its part of a tile), solved row after row as
/// [`row_interval`] solves them, with two savings that leave every row the same:
///
/// - an edge with every pixel centre of the window inside (at or past its bias: its least
///   value over the window, at a corner, is enough) cannot narrow a row, and is replaced by a
///   neutral edge (no division); a tile inside a large triangle then has none to solve. An
///   edge with every centre outside empties every row: [`RowEdges::new`] gives `None`.
/// - each edge's value at the row's first column steps by an addition from row to row
///   instead of being recomputed by two products (exact integers; no new branches: the
///   bounds are still solved per row by division).
struct RowEdges {
    /// `bias - E` at pixel column 0 of the next row, per edge (`need` of [`row_interval`]).
    need: [i64; 3],
    /// What `need` changes by from one row to the next (`-b * SUBPIXEL`).
    rise: [i64; 3],
    /// `a * SUBPIXEL`: `E` grows by it from one column to the next.
    step: [i64; 3],
    x: [i32; 2],
}

impl RowEdges {
    /// Without `test`, every edge is kept (the rows are the same either way).
    #[inline(always)]
    fn new(
        edges: &[Edge; 3],
        bias: &[u8; 3],
        [x_lo, x_hi, y_lo, y_hi]: [i32; 4],
        test: bool,
    ) -> Option<RowEdges> {
        let half = SUBPIXEL / 2;
        let py = y_lo as i64 * SUBPIXEL + half;
        let (w, h) = (
            (x_hi - 1 - x_lo) as i64 * SUBPIXEL,
            (y_hi - 1 - y_lo) as i64 * SUBPIXEL,
        );
        let px = x_lo as i64 * SUBPIXEL + half;
        let mut out = RowEdges {
            need: [0; 3],
            rise: [0; 3],
            step: [0; 3],
            x: [x_lo, x_hi],
        };
        for k in 0..3 {
            let (e, bias) = (&edges[k], i64::from(bias[k]));
            let mut keep = true;
            if test {
                // E at the window's lowest-left centre, and how far it moves to the other
                // corners.
                let corner = e.a * px + e.b * py + e.c;
                let (across, up) = (e.a * w, e.b * h);
                let least = corner + across.min(0) + up.min(0);
                let most = corner + across.max(0) + up.max(0);
                if most < bias {
                    return None;
                }
                // Kept unless every centre is inside (then need stays <= 0 with no step:
                // skipped).
                keep = least < bias;
            }
            let base = e.b * py + e.c + e.a * half;
            out.need[k] = if keep { bias - base } else { 0 };
            out.rise[k] = if keep { -e.b * SUBPIXEL } else { 0 };
            out.step[k] = if keep { e.a * SUBPIXEL } else { 0 };
        }
        Some(out)
    }

    /// The covered pixels `lo..hi` of the next row (from `y_lo` up), when there are any.
    #[inline(always)]
    fn next_row(&mut self) -> Option<(i32, i32)> {
        let mut lo = self.x[0] as i64;
        let mut hi = self.x[1] as i64; // exclusive
        let mut empty = false;
        for k in 0..3 {
            let (need, step) = (self.need[k], self.step[k]);
            self.need[k] = need + self.rise[k];
            // As in `row_interval`.
            if step > 0 {
                lo = lo.max(need / step + i64::from(need % step > 0));
            } else if step < 0 {
                let (n, s) = (-need, -step);
                hi = hi.min(n / s - i64::from(n % s < 0) + 1);
            } else if need > 0 {
                empty = true;
            }
        }
        (!empty && lo < hi).then_some((lo as i32, hi as i32))
    }
}

/// The covered pixels `lo..hi` of row `y` inside `x_lo..x_hi`, when there are any, solved
/// per edge by division (the reference for [`RowEdges`]). (Walking the bounds from row to row by additions was tried, branch
/// `smalltri`: about as many instructions, but its data-dependent branches mispredicted on
/// small triangles and made `triangles` ~25 % slower in wall time.)
#[cfg(test)]
fn row_interval(
    edges: &[Edge; 3],
    bias: &[u8; 3],
    [x_lo, x_hi]: [i32; 2],
    y: i32,
) -> Option<(i32, i32)> {
    let half = SUBPIXEL / 2;
    let py = y as i64 * SUBPIXEL + half;
    let mut lo = x_lo as i64;
    let mut hi = x_hi as i64; // exclusive
    for (e, &bias) in edges.iter().zip(bias) {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::xorshift;

    /// The edges and biases of the triangle `p` (fixed point) in counter-clockwise order, as
    /// `bin_triangle` and `TriangleCommand::edges` make them; `None` without area.
    fn edges_of(mut p: [[i64; 2]; 3]) -> Option<([Edge; 3], [u8; 3])> {
        let area2 = triangle_area2(p);
        if area2 == 0 {
            return None;
        }
        if area2 < 0 {
            p.swap(1, 2);
        }
        let [(e0, b0), (e1, b1), (e2, b2)] = [
            Edge::new(p[0], p[1]),
            Edge::new(p[1], p[2]),
            Edge::new(p[2], p[0]),
        ];
        Some(([e0, e1, e2], [b0, b1, b2]))
    }

    /// Each row's covered columns, if any.
    type Rows = Vec<Option<(i32, i32)>>;

    /// The rows `y_lo..y_hi` of `p` inside columns `x_lo..x_hi`, solved row by row by
    /// `row_interval` (the reference).
    fn rows_of(p: [[i64; 2]; 3], [x_lo, x_hi, y_lo, y_hi]: [i32; 4]) -> Option<Rows> {
        let (edges, bias) = edges_of(p)?;
        Some(
            (y_lo..y_hi)
                .map(|y| row_interval(&edges, &bias, [x_lo, x_hi], y))
                .collect(),
        )
    }

    /// The same rows as `raster_triangle` finds them (`RowEdges`: every row `None` when it
    /// rejects the window).
    fn walked_rows_of(p: [[i64; 2]; 3], w: [i32; 4]) -> Option<Rows> {
        let (edges, bias) = edges_of(p)?;
        let n = (w[3] - w[2]) as usize;
        let rows = match RowEdges::new(&edges, &bias, w, true) {
            Some(mut rows) => (0..n).map(|_| rows.next_row()).collect(),
            None => vec![None; n],
        };
        let mut all = RowEdges::new(&edges, &bias, w, false).expect("no test, no rejection");
        let kept: Rows = (0..n).map(|_| all.next_row()).collect();
        assert_eq!(rows, kept, "tested and untested edges differ");
        Some(rows)
    }

    /// Twin test of `RowEdges` (edges inside or outside the whole window dropped, values
    /// stepped by additions) against `row_interval` (every edge divided at every row): the
    /// same rows for random triangles from sub-pixel slivers to the guard band, with
    /// horizontal and vertical edges and vertices on pixel centres, in tiles of side 16-128
    /// and random windows; and the drops do happen (tiles inside large triangles, tiles
    /// their box touches but they miss).
    #[test]
    fn window_edges_give_the_divided_rows() {
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        let (mut inside, mut rejected, mut windows) = (0usize, 0usize, 0usize);
        for k in 0..40_000 {
            let r = |seed: &mut u64, m: i64| (xorshift(seed) % (m as u64)) as i64;
            // Sizes: slivers, small, tile-sized, screen-sized, guard band.
            let scale = [300i64, 3_000, 20_000, 300_000, 4_000_000][k % 5];
            let centre = [r(&mut seed, 260_000), r(&mut seed, 200_000)];
            let mut p = [[0i64; 2]; 3];
            for v in &mut p {
                for (c, o) in v.iter_mut().zip(centre) {
                    *c = o + r(&mut seed, 2 * scale) - scale;
                }
            }
            match xorshift(&mut seed) % 6 {
                // An axis-aligned right angle (a split quad).
                0 => {
                    p[1][1] = p[0][1];
                    p[2][0] = p[0][0];
                }
                // Vertices on pixel centres.
                1 => {
                    for v in &mut p {
                        for c in v.iter_mut() {
                            *c = *c & !0xFF | 0x80;
                        }
                    }
                }
                _ => {}
            }
            if triangle_area2(p) == 0 {
                continue;
            }
            for side in [16i32, 64, 128] {
                // The tiles the triangle's box touches (at most a few hundred), and one
                // random window inside the box.
                let xs = p.map(|v| v[0]);
                let ys = p.map(|v| v[1]);
                let (x0, x1) = centre_range(*xs.iter().min().unwrap(), *xs.iter().max().unwrap());
                let (y0, y1) = centre_range(*ys.iter().min().unwrap(), *ys.iter().max().unwrap());
                if x0 >= x1 || y0 >= y1 {
                    continue;
                }
                let (tx0, ty0) = (x0.div_euclid(side), y0.div_euclid(side));
                let (tx1, ty1) = ((x1 - 1).div_euclid(side), (y1 - 1).div_euclid(side));
                let mut tiles = Vec::new();
                if (tx1 - tx0 + 1) * (ty1 - ty0 + 1) <= 256 {
                    for ty in ty0..=ty1 {
                        for tx in tx0..=tx1 {
                            tiles.push(window(p, tx * side, ty * side, side));
                        }
                    }
                }
                let (wx, wy) = (
                    x0 + (xorshift(&mut seed) % (x1 - x0) as u64) as i32,
                    y0 + (xorshift(&mut seed) % (y1 - y0) as u64) as i32,
                );
                let (ww, wh) = (
                    1 + (xorshift(&mut seed) % 70) as i32,
                    1 + (xorshift(&mut seed) % 70) as i32,
                );
                tiles.push(Some([wx, (wx + ww).min(x1), wy, (wy + wh).min(y1)]));
                for w in tiles.into_iter().flatten() {
                    windows += 1;
                    let divided = rows_of(p, w);
                    let walked = walked_rows_of(p, w);
                    assert_eq!(walked, divided, "triangle {p:?} window {w:?}");
                    let (edges, bias) = edges_of(p).expect("area");
                    match RowEdges::new(&edges, &bias, w, true) {
                        None => rejected += 1,
                        Some(e) if e.step == [0; 3] && e.need == [0; 3] => inside += 1,
                        Some(_) => {}
                    }
                }
            }
        }
        assert!(
            inside > windows / 50 && rejected > windows / 50,
            "{inside} inside, {rejected} rejected of {windows}"
        );
    }

    /// The window `raster_triangle` walks: the triangle's pixel-centre box clipped to the
    /// tile of side `side` at (`tx`, `ty`).
    fn window(p: [[i64; 2]; 3], tx: i32, ty: i32, side: i32) -> Option<[i32; 4]> {
        let xs = p.map(|v| v[0]);
        let ys = p.map(|v| v[1]);
        let (x0, x1) = centre_range(*xs.iter().min()?, *xs.iter().max()?);
        let (y0, y1) = centre_range(*ys.iter().min()?, *ys.iter().max()?);
        let w = [x0.max(tx), x1.min(tx + side), y0.max(ty), y1.min(ty + side)];
        (w[0] < w[1] && w[2] < w[3]).then_some(w)
    }

    /// A mesh of jittered grid points, two triangles a cell (both diagonals, both windings):
    /// every pixel centre inside the mesh is covered by exactly one triangle (the fill rule
    /// of `Edge::new`), found row by row in tiles of 16.
    #[test]
    fn shared_edges_cover_each_pixel_once() {
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        for cell in [3i64, 5, 17, 40] {
            let n = 12usize;
            // Points in fixed point; the outer ones on a rectangle, the inner ones jittered
            // (some onto pixel centres and pixel rows, where the fill rule decides).
            let pts: Vec<Vec<[i64; 2]>> = (0..=n)
                .map(|j| {
                    (0..=n)
                        .map(|i| {
                            let mut q = [i as i64 * cell * 256, j as i64 * cell * 256];
                            if i > 0 && i < n && j > 0 && j < n {
                                for c in &mut q {
                                    let r = xorshift(&mut seed);
                                    *c += (r % (cell as u64 * 128)) as i64 - cell * 64;
                                    if r & 0x300 == 0 {
                                        *c = *c & !0xFF | 0x80;
                                    }
                                }
                            }
                            q
                        })
                        .collect()
                })
                .collect();
            let size = (n as i64 * cell) as i32;
            let mut count = vec![0u8; (size * size) as usize];
            for j in 0..n {
                for i in 0..n {
                    let (a, b, c, d) = (pts[j][i], pts[j][i + 1], pts[j + 1][i + 1], pts[j + 1][i]);
                    let tris = if (i + j) % 2 == 0 {
                        [[a, b, c], [a, c, d]]
                    } else {
                        [[b, d, a], [b, c, d]]
                    };
                    for t in tris {
                        for ty in (0..size).step_by(16) {
                            for tx in (0..size).step_by(16) {
                                let Some(w) = window(t, tx, ty, 16) else {
                                    continue;
                                };
                                let rows = rows_of(t, w).expect("area");
                                assert_eq!(walked_rows_of(t, w), Some(rows.clone()));
                                for (k, r) in rows.into_iter().enumerate() {
                                    if let Some((x0, x1)) = r {
                                        let y = w[2] + k as i32;
                                        for x in x0..x1 {
                                            count[(y * size + x) as usize] += 1;
                                        }
                                    }
                                }
                            }
                        }
                    }
                }
            }
            // The mesh's outline is the rectangle 0..size: every pixel centre is inside.
            assert!(count.iter().all(|&c| c == 1), "cell {cell}: {:?}", {
                let bad: Vec<usize> = (0..count.len()).filter(|&k| count[k] != 1).collect();
                bad.into_iter().take(8).collect::<Vec<_>>()
            });
        }
    }
}

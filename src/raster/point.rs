//! Points (section 3.3). The size is the derived size of GL 1.4's point parameters (distance
//! attenuation, then clamped to `GL_POINT_SIZE_MIN`/`MAX`). Aliased points cover the square
//! of side `round(size)` whose pixel centres lie in `[x - w/2, x + w/2)` (for width 1: the
//! pixel containing the point); antialiased points cover a disc of diameter `size`, each pixel
//! taking the disc's share of its area as coverage (section 3.11).
//!
//! The fade threshold only applies with multisampling (section 3.3.1), which tilegl does not
//! have, so it is stored and never used.

use glam::DVec4;

use super::controls::{RasterDraw, SmoothPoints};
use super::draw::TileDraw;
use super::scene::{Command, RectCommand, Scene};
use super::setup::Plane;
use super::setup::WindowVertex;
use crate::common::fixed::SUBPIXEL;
use crate::common::limits;
use crate::common::rect::Rect;

/// The derived point size for a vertex at eye position `eye` (section 3.3.1): `size *
/// sqrt(1 / (a + b d + c d^2))`, clamped to the point-size range. Non-finite or non-positive
/// attenuation leaves the largest size.
///
/// `d` is the eye distance approximated by `|z_eye|`, as for fog: the spec asks for the
/// Euclidean distance, Mesa (the reference captures are checked against) uses `|z_eye|`, and
/// the two agree on the view axis. The differential scene `point_attenuation` shows the
/// difference disappears with this choice.
pub fn derived_size(r: &RasterDraw, eye: DVec4) -> f64 {
    let mut size = r.point_size as f64;
    if let Some([a, b, c]) = r.point_attenuation {
        let p = if eye.w != 0.0 && eye.w != 1.0 {
            eye.truncate() / eye.w
        } else {
            eye.truncate()
        };
        let d = p.z.abs();
        let k = a as f64 + b as f64 * d + c as f64 * d * d;
        let scale = (1.0 / k).sqrt();
        size = if scale.is_finite() {
            size * scale
        } else {
            f64::MAX
        };
    }
    let [lo, hi] = r.point_size_range.map(|v| v as f64);
    // Written out (not `clamp`) so that min > max cannot panic: the maximum wins.
    size.max(lo).min(hi)
}

/// Width in pixels of an aliased point of derived size `size`: rounded to the nearest integer
/// (halves down, as Mesa does; the spec leaves ties open), at least 1, clamped to
/// `GL_ALIASED_POINT_SIZE_RANGE`.
pub fn aliased_width(size: f64) -> i64 {
    let [lo, hi] = limits::POINT_SIZE_RANGE;
    let w = (size - 0.5).ceil();
    let w = if w.is_nan() { 1.0 } else { w };
    w.max(lo as f64).min(hi as f64) as i64
}

/// Bins one point of derived size `size`; `z_offset` is a polygon offset (points of polygons
/// drawn in point mode).
pub fn bin_point(
    ds: &TileDraw,
    state: u32,
    v: &WindowVertex,
    size: f64,
    z_offset: f64,
    attrs: &[f32],
    scene: &mut Scene,
) {
    let s = SUBPIXEL as f64;
    let (x, y) = (v.xy[0] as f64 / s, v.xy[1] as f64 / s);
    let z = v.z + z_offset;
    if let Some((replace, upper_left)) = ds.raster.point_sprite {
        bin_sprite(
            ds,
            state,
            [x, y],
            z,
            size,
            replace,
            upper_left,
            attrs,
            scene,
        );
        return;
    }
    if !ds.raster.point_smooth {
        let w = aliased_width(size);
        let half = (w - 1) as f64 / 2.0;
        let x0 = (x - half).floor() as i64;
        let y0 = (y - half).floor() as i64;
        emit_rect(ds, state, [x0, y0, x0 + w, y0 + w], z, attrs, 1.0, scene);
        return;
    }
    // Antialiased: a disc of diameter `size` (clamped to the smooth range, which is the
    // aliased one here).
    let [lo, hi] = limits::POINT_SIZE_RANGE;
    let radius = size.max(lo as f64).min(hi as f64) / 2.0;
    if ds.raster.smooth_points == SmoothPoints::Discs {
        // Mesa's smallest disc has radius 1 (measured: sizes up to 2 light the same pixels).
        let r = radius.max(1.0);
        let (px0, px1) = ((x - r).floor() as i64, (x + r).floor() as i64);
        let (py0, py1) = ((y - r).floor() as i64, (y + r).floor() as i64);
        let offset = add_constant_planes(attrs, scene);
        for py in py0..=py1 {
            for px in px0..=px1 {
                if in_disc(x, y, r, px, py) {
                    bin_rect(ds, state, [px, py, px + 1, py + 1], z, offset, 1.0, scene);
                }
            }
        }
        return;
    }
    let (px0, px1) = ((x - radius).floor() as i64, (x + radius).floor() as i64);
    let (py0, py1) = ((y - radius).floor() as i64, (y + radius).floor() as i64);
    let offset = add_constant_planes(attrs, scene);
    for py in py0..=py1 {
        for px in px0..=px1 {
            let cov = disc_coverage(x, y, radius, px, py);
            if cov > 0.0 {
                bin_rect(ds, state, [px, py, px + 1, py + 1], z, offset, cov, scene);
            }
        }
    }
}

/// A point sprite (ARB_point_sprite, GL 2.0 section 3.4.1): the pixels whose centres lie in the
/// square of side `size` (not rounded; antialiasing does not apply) centred on `xy`, with the
/// texture coordinates of the units in `replace` replaced by s = 1/2 + (x_f + 1/2 - x) / size,
/// t = 1/2 - (y_f + 1/2 - y) / size (`upper_left`, the default) or 1/2 + (y_f + 1/2 - y) / size,
/// r = 0, q = 1: planes over the pixel centres, so the texture's level of detail follows the
/// size.
#[allow(clippy::too_many_arguments)]
fn bin_sprite(
    ds: &TileDraw,
    state: u32,
    [x, y]: [f64; 2],
    z: f64,
    size: f64,
    replace: u32,
    upper_left: bool,
    attrs: &[f32],
    scene: &mut Scene,
) {
    let [lo, hi] = limits::POINT_SIZE_RANGE;
    let size = size.max(lo as f64).min(hi as f64);
    let half = size / 2.0;
    // Pixel px is in when x - half <= px + 1/2 < x + half.
    let first = |c: f64| (c - half - 0.5).ceil() as i64;
    let r = [first(x), first(y), first(x + size), first(y + size)];
    if clip_to_draw_rect(ds, r).is_none() {
        return;
    }
    let offset = add_constant_planes(attrs, scene);
    for unit in 0..32 {
        let base = crate::common::attr::TEX + 4 * unit;
        if replace >> unit & 1 == 0 || base + 4 > attrs.len() {
            continue;
        }
        let t_sign = if upper_left { -1.0 } else { 1.0 };
        let planes = &mut scene.planes[offset as usize + base..offset as usize + base + 4];
        planes[0] = Plane {
            a: 1.0 / size,
            b: 0.0,
            c: 0.5 - x / size,
        };
        planes[1] = Plane {
            a: 0.0,
            b: t_sign / size,
            c: 0.5 - t_sign * y / size,
        };
        planes[2] = Plane::constant(0.0);
        planes[3] = Plane::constant(1.0);
    }
    bin_rect(ds, state, r, z, offset, 1.0, scene);
}

/// Coverage of pixel `(px, py)` by the disc at `(cx, cy)` of radius `r`: the box-filtered
/// distance of the pixel centre to the circle (an analytic approximation of the covered
/// area, exact to within a few percent for radii above one pixel).
pub fn disc_coverage(cx: f64, cy: f64, r: f64, px: i64, py: i64) -> f32 {
    let (dx, dy) = (px as f64 + 0.5 - cx, py as f64 + 0.5 - cy);
    let dist = (dx * dx + dy * dy).sqrt();
    // A disc narrower than a pixel covers at most its own area.
    let full = (r * r * std::f64::consts::PI).min(1.0);
    ((r + 0.5 - dist).clamp(0.0, 1.0) * full) as f32
}

/// Whether the centre of pixel `(px, py)` lies in the disc at `(cx, cy)` of radius `r`
/// ([`SmoothPoints::Discs`]).
pub fn in_disc(cx: f64, cy: f64, r: f64, px: i64, py: i64) -> bool {
    let (dx, dy) = (px as f64 + 0.5 - cx, py as f64 + 0.5 - cy);
    dx * dx + dy * dy <= r * r
}

/// Stores `attrs` as constant planes; returns their offset.
pub(crate) fn add_constant_planes(attrs: &[f32], scene: &mut Scene) -> u32 {
    let offset = scene.planes.len() as u32;
    scene
        .planes
        .extend(attrs.iter().map(|&a| Plane::constant(a as f64)));
    offset
}

/// Records the pixels `[x0, x1) x [y0, y1)` (window coordinates, any size) with constant
/// attributes, limited to the draw rectangle.
pub(crate) fn emit_rect(
    ds: &TileDraw,
    state: u32,
    r: [i64; 4],
    z: f64,
    attrs: &[f32],
    coverage: f32,
    scene: &mut Scene,
) {
    if clip_to_draw_rect(ds, r).is_none() {
        return;
    }
    let offset = add_constant_planes(attrs, scene);
    bin_rect(ds, state, r, z, offset, coverage, scene);
}

fn clip_to_draw_rect(ds: &TileDraw, r: [i64; 4]) -> Option<Rect> {
    let d = &ds.draw_rect;
    let rect = Rect {
        x0: r[0].max(d.x0 as i64) as i32,
        y0: r[1].max(d.y0 as i64) as i32,
        x1: r[2].min(d.x1 as i64) as i32,
        y1: r[3].min(d.y1 as i64) as i32,
    };
    (!rect.is_empty()).then_some(rect)
}

/// Records a rectangle whose attribute planes are already stored at `attrs`.
pub(crate) fn bin_rect(
    ds: &TileDraw,
    state: u32,
    r: [i64; 4],
    z: f64,
    attrs: u32,
    coverage: f32,
    scene: &mut Scene,
) {
    let Some(rect) = clip_to_draw_rect(ds, r) else {
        return;
    };
    scene.bin(
        Command::Rect(RectCommand {
            state,
            rect,
            z,
            attrs,
            coverage,
        }),
        rect,
    );
}

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
//! pixel taking a box-filtered estimate of the rectangle's share of its area as coverage,
//! computed the way Mesa's draw module does it (see `plan_smooth`).
//!
//! Stippling (section 3.4.2) counts fragments along the line (a wide line's column counts
//! once) with the counter the caller keeps across the segments of a strip or loop.
//! Attributes are interpolated perspective-correctly along the line.

use super::draw::TileDraw;
use super::scene::{Command, LineCommand};
use super::schedule::MAX_SIDE;
use super::setup::WindowVertex;
use crate::common::attr::MAX_ATTRS;
use crate::common::fixed::SUBPIXEL;
use crate::common::limits;
use crate::common::rect::Rect;
use crate::raster::scene::Scene;

/// Whether the stipple lets fragment number `counter` through.
#[inline]
fn stipple_passes(stipple: Option<(u32, u16)>, counter: u32) -> bool {
    match stipple {
        None => true,
        Some((factor, pattern)) => pattern & (1 << ((counter / factor.max(1)) % 16)) != 0,
    }
}

/// A segment set up for the tiles: recorded once (`Command::Line`) and binned into the tiles
/// it crosses; each tile's shading walks only the segment's columns inside it
/// ([`LineSetup::fragments`]), so the per-fragment work runs on the shading threads and the
/// scene holds one command per segment instead of one per fragment.
#[derive(Clone, Debug)]
pub struct LineSetup {
    kind: LineKind,
    /// Window z and 1/w at the two ends.
    z: [f64; 2],
    inv_w: [f64; 2],
    z_offset: f64,
    /// The end points' attributes: `n` at `attrs` in `Scene::line_attrs`, then the end's `n`.
    pub attrs: u32,
    pub n: u32,
    /// Whether the major axis is x.
    x_major: bool,
    /// Major-axis coordinates of the two ends (moved by the wide-line shift), the minor
    /// coordinate at the start and its slope along the major axis.
    a0: f64,
    a1: f64,
    b0: f64,
    db_da: f64,
    /// The major-axis interval of the segment (`min(a0, a1)`, `max(a0, a1)`).
    lo: f64,
    hi: f64,
    /// The columns (major-axis pixel coordinates) that can produce fragments.
    first: i64,
    last: i64,
    stipple: Option<(u32, u16)>,
    start_counter: u32,
    /// The ends have the same z, 1/w and attributes: every fragment then has the same values
    /// (the interpolation adds `t * 0`), so fragments of full coverage next to each other in
    /// a row may be shaded as one span.
    pub uniform: bool,
}

#[derive(Clone, Debug)]
enum LineKind {
    Aliased {
        /// The perturbed end points and the unperturbed end (see `plan_aliased`).
        p0: [f64; 2],
        p1: [f64; 2],
        end: [f64; 2],
        /// `(w - 1) / 2` and the width `w`.
        shift: f64,
        width: i64,
    },
    Smooth {
        quad: SmoothLineQuad,
        /// Minor-direction reach of the quad around the segment at one column.
        reach: f64,
        /// The draw rectangle's rows (columns for y-major lines), inclusive.
        minor_rect: (i64, i64),
        /// The columns along the segment itself (they advance the stipple counter).
        along: Option<(i64, i64)>,
    },
}

/// Sets up one line segment and records it (`Command::Line`) in the tiles it crosses.
/// `z_offset` is a polygon offset (edges of polygons in line mode); `stipple_counter` carries
/// the stipple count from the previous segment of a strip.
pub fn bin_line(
    ds: &TileDraw,
    state: u32,
    v: [&WindowVertex; 2],
    attrs: [&[f32]; 2],
    z_offset: f64,
    stipple_counter: &mut u32,
    scene: &mut Scene,
) {
    let n = ds
        .attr_count
        .min(MAX_ATTRS)
        .min(attrs[0].len())
        .min(attrs[1].len());
    let planned = if ds.raster.line_smooth {
        plan_smooth(ds, v)
    } else {
        plan_aliased(ds, v)
    };
    let Some((kind, x_major, [a0, a1, b0, db_da], (first, last))) = planned else {
        return;
    };
    if first > last {
        return;
    }
    let uniform = v[0].z == v[1].z && v[0].inv_w == v[1].inv_w && attrs[0][..n] == attrs[1][..n];
    let offset = scene.line_attrs.len() as u32;
    scene.line_attrs.extend_from_slice(&attrs[0][..n]);
    scene.line_attrs.extend_from_slice(&attrs[1][..n]);
    let line = LineSetup {
        kind,
        z: [v[0].z, v[1].z],
        inv_w: [v[0].inv_w, v[1].inv_w],
        z_offset,
        attrs: offset,
        n: n as u32,
        x_major,
        a0,
        a1,
        b0,
        db_da,
        lo: a0.min(a1),
        hi: a0.max(a1),
        first,
        last,
        stipple: ds.raster.line_stipple,
        start_counter: *stipple_counter,
        uniform,
    };
    // The tiles each band of columns one tile wide reaches (the minor coordinate is linear
    // in the column, so the band's end columns bound it).
    let s = scene.tile_shift();
    let side = 1i64 << s;
    let r = &ds.draw_rect;
    let (minor_lo, minor_hi) = if x_major {
        (r.y0 as i64, r.y1 as i64 - 1)
    } else {
        (r.x0 as i64, r.x1 as i64 - 1)
    };
    let (major_lo, major_hi) = if x_major {
        (r.x0 as i64, r.x1 as i64 - 1)
    } else {
        (r.y0 as i64, r.y1 as i64 - 1)
    };
    let (c0, c1) = (first.max(major_lo), last.min(major_hi));
    if c0 > c1 || minor_lo > minor_hi {
        // Nothing inside the draw rectangle; the stipple count still advances.
        *stipple_counter = line.end_counter();
        return;
    }
    let index = scene.add_line(Command::Line(LineCommand {
        state,
        line: scene.lines.len() as u32,
    }));
    let mut band = c0 >> s;
    while band << s <= c1 {
        let (b0c, b1c) = ((band << s).max(c0), ((band << s) + side - 1).min(c1));
        let (m0, m1) = line.minor_span(b0c, b1c);
        let (m0, m1) = (m0.max(minor_lo), m1.min(minor_hi));
        if m0 <= m1 {
            let rect = if x_major {
                Rect {
                    x0: b0c as i32,
                    y0: m0 as i32,
                    x1: b1c as i32 + 1,
                    y1: m1 as i32 + 1,
                }
            } else {
                Rect {
                    x0: m0 as i32,
                    y0: b0c as i32,
                    x1: m1 as i32 + 1,
                    y1: b1c as i32 + 1,
                }
            };
            scene.bin_again(index, rect);
        }
        band += 1;
    }
    *stipple_counter = line.end_counter();
    scene.lines.push(line);
}

/// The aliased segment's set-up: its kind, whether it is x-major, `[a0, a1, b0, db_da]` and
/// its columns; `None` for a segment of zero length.
#[allow(clippy::type_complexity)]
fn plan_aliased(
    ds: &TileDraw,
    v: [&WindowVertex; 2],
) -> Option<(LineKind, bool, [f64; 4], (i64, i64))> {
    let s = SUBPIXEL as f64;
    let p0 = [v[0].xy[0] as f64 / s, v[0].xy[1] as f64 / s];
    let p1 = [v[1].xy[0] as f64 / s, v[1].xy[1] as f64 / s];
    aliased_plan(p0, p1, ds.raster.line_width)
}

/// [`plan_aliased`] for the window positions `p0`, `p1` and the line width.
#[allow(clippy::type_complexity)]
fn aliased_plan(
    p0: [f64; 2],
    p1: [f64; 2],
    line_width: f32,
) -> Option<(LineKind, bool, [f64; 4], (i64, i64))> {
    let ([mut x0, mut y0], [mut x1, mut y1]) = (p0, p1);
    let (dx, dy) = (x1 - x0, y1 - y0);
    if dx == 0.0 && dy == 0.0 {
        return None;
    }
    // Section 3.4.1 rasterizes the segment moved by (-e, -e^2) for a tiny e, so that a segment
    // running exactly through diamond corners (a horizontal line at an integer y, a vertical
    // one at an integer x, a slope of 1/2 from a quarter-pixel start) still enters one pixel
    // per column instead of none. Across the major axis that move amounts to
    // `PERTURBATION` up for an x-major line rising to the right, down otherwise; llvmpipe
    // breaks these ties the same way. (Along the major axis llvmpipe keeps the end points
    // where they are, and so does this.)
    // The end point as given decides whether the segment ends inside a diamond: llvmpipe
    // moves the segment only for its crossings (an end point exactly on a diamond's edge, as
    // (300.6, 190.1) is on pixel (300, 190)'s in sub-pixel units, keeps its pixel there).
    let end = [x1, y1];
    if dx.abs() >= dy.abs() {
        let up = if dy / dx > 0.0 { 1.0 } else { -1.0 };
        y0 += up * PERTURBATION;
        y1 += up * PERTURBATION;
    } else {
        x0 -= PERTURBATION;
        x1 -= PERTURBATION;
    }
    let [wlo, whi] = limits::LINE_WIDTH_RANGE;
    let rounded = (line_width as f64).round();
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
    // Candidate pixels: one per major-axis column from the start's to the end's; each is
    // kept when the segment leaves that pixel's diamond. Clipping bounded the segment by the
    // viewport, so the columns are bounded too.
    let (first, last) = (a0.min(a1).floor(), a0.max(a1).floor());
    let kind = LineKind::Aliased {
        p0: [x0, y0],
        p1: [x1, y1],
        end,
        shift,
        width,
    };
    Some((
        kind,
        x_major,
        [a0, a1, b0, db_da],
        (first as i64, last as i64),
    ))
}

/// An antialiased line, drawn the way Mesa's llvmpipe and softpipe draw it (their draw
/// module's antialiased-line stage): the rectangle of half width `h = max(1, width / 2 + 1/2)`
/// around the segment, lengthened by half a pixel past each end point, is rasterized as two
/// triangles, and each fragment whose centre lies inside takes as coverage
/// `sat(h - |x|) * sat(L / 2 + 1/2 - |z|)`, where `x` (across, `+-h` on the long sides) and `z`
/// (along, `+-(L / 2 + 1/2)` at the lengthened ends) are interpolated perspective-correctly
/// over each triangle like any other varying. For `w` equal at both ends this is the
/// box-filtered distance of the pixel centre to the rectangle of the line's width (an estimate
/// of section 3.4.4's covered area). With perspective the across coordinate bends with the
/// triangle split, which Mesa makes along the diagonal from the start's left corner to the
/// end's right corner (left and right as seen from the start towards the end, y up; Mesa
/// splits in its y-down window space, where that is the diagonal through the other corners):
/// matching the split is what puts a line's coverage where Mesa puts it (with the other
/// diagonal, or with the across coordinate interpolated in window space, a receding line of
/// width 4 sits a pixel away from Mesa's).
///
/// Returns the set-up as [`plan_aliased`] does.
#[allow(clippy::type_complexity)]
fn plan_smooth(
    ds: &TileDraw,
    v: [&WindowVertex; 2],
) -> Option<(LineKind, bool, [f64; 4], (i64, i64))> {
    let s = SUBPIXEL as f64;
    let p0 = [v[0].xy[0] as f64 / s, v[0].xy[1] as f64 / s];
    let p1 = [v[1].xy[0] as f64 / s, v[1].xy[1] as f64 / s];
    let (dx, dy) = (p1[0] - p0[0], p1[1] - p0[1]);
    let len = (dx * dx + dy * dy).sqrt();
    if !(len > 0.0) {
        return None;
    }
    let quad = SmoothLineQuad::new(
        p0,
        p1,
        len,
        ds.raster.line_width as f64,
        v[0].inv_w,
        v[1].inv_w,
    );
    let x_major = dx.abs() >= dy.abs();
    let (a0, a1, b0, db_da) = if x_major {
        (p0[0], p1[0], p0[1], dy / dx)
    } else {
        (p0[1], p1[1], p0[0], dx / dy)
    };
    // Minor-direction half extent of the quad at one major coordinate, plus a margin for the
    // slope across a pixel.
    let slope = db_da.abs();
    let reach = quad.half_width * (1.0 + slope * slope).sqrt() + slope + 1.0;
    let (lo, hi) = (a0.min(a1), a0.max(a1));
    // Only pixels inside the draw rectangle can be recorded: bound both loops by it (a line
    // of width 1000 would otherwise visit a million pixels outside).
    let r = &ds.draw_rect;
    let (major_rect, minor_rect) = if x_major {
        (
            (r.x0 as i64, r.x1 as i64 - 1),
            (r.y0 as i64, r.y1 as i64 - 1),
        )
    } else {
        (
            (r.y0 as i64, r.y1 as i64 - 1),
            (r.x0 as i64, r.x1 as i64 - 1),
        )
    };
    let first = ((lo - 1.0).floor() as i64).max(major_rect.0.saturating_sub(1));
    let last = ((hi + 1.0).floor() as i64).min(major_rect.1.saturating_add(1));
    // The quad reaches half its width past the ends in the major direction too.
    let ext = quad.half_width.ceil() as i64;
    let first = first.min(((lo.floor() as i64) - ext).max(major_rect.0));
    let last = last.max(((hi.floor() as i64) + ext).min(major_rect.1));
    // Columns whose centre lies in [lo, hi) advance the stipple counter: an interval, as the
    // test is monotonic in the column.
    let along = if first <= last {
        let mut c0 = ((lo - 0.5).ceil() as i64).clamp(first, last);
        while c0 > first && (c0 - 1) as f64 + 0.5 >= lo {
            c0 -= 1;
        }
        while c0 <= last && (c0 as f64 + 0.5) < lo {
            c0 += 1;
        }
        let mut c1 = ((hi - 0.5).floor() as i64).clamp(first, last);
        while c1 < last && ((c1 + 1) as f64 + 0.5) < hi {
            c1 += 1;
        }
        while c1 >= first && (c1 as f64 + 0.5) >= hi {
            c1 -= 1;
        }
        (c0 <= c1).then_some((c0, c1))
    } else {
        None
    };
    let kind = LineKind::Smooth {
        quad,
        reach,
        minor_rect,
        along,
    };
    Some((kind, x_major, [a0, a1, b0, db_da], (first, last)))
}

impl LineSetup {
    /// The stipple counter after the segment (for the next segment of a strip).
    fn end_counter(&self) -> u32 {
        match &self.kind {
            // The next segment continues the count after ceil(major length) fragments (what
            // the segment produces up to the end-point rounding; Mesa counts the same way).
            LineKind::Aliased { .. } => {
                let advance = (self.a1 - self.a0).abs().ceil();
                self.start_counter
                    .wrapping_add(advance.min(u32::MAX as f64) as u32)
            }
            LineKind::Smooth { along, .. } => {
                let n = along.map_or(0, |(c0, c1)| c1 - c0 + 1);
                self.start_counter.wrapping_add(n as u32)
            }
        }
    }

    /// Rows (columns for y-major lines) that the fragments of columns `c0..=c1` can reach.
    fn minor_span(&self, c0: i64, c1: i64) -> (i64, i64) {
        let m =
            |c: i64| self.b0 + ((c as f64 + 0.5).clamp(self.lo, self.hi) - self.a0) * self.db_da;
        let (ma, mb) = (m(c0), m(c1));
        let (m0, m1) = (ma.min(mb), ma.max(mb));
        let (lo, hi) = match &self.kind {
            LineKind::Aliased { width, .. } => (m0.floor() - 1.0, m1.floor() + *width as f64 + 1.0),
            LineKind::Smooth { reach, .. } => {
                ((m0 - reach).floor() - 1.0, (m1 + reach).floor() + 1.0)
            }
        };
        // NaN (a degenerate slope) reaches everything.
        let clamp = |v: f64, d: i64| {
            if v.is_nan() {
                d
            } else {
                v.clamp(-1e9, 1e9) as i64
            }
        };
        (clamp(lo, i64::MIN / 2), clamp(hi, i64::MAX / 2))
    }

    /// Calls `f(rect, z, attrs, coverage)` for each fragment rectangle of the segment whose
    /// major-axis column lies in `major` and whose pixels may reach `minor` (rows for x-major
    /// segments, inclusive bounds): what the segment draws there, the same values whichever
    /// tile asks. `attrs` are the two ends' attributes (`n` each); `scratch` holds a
    /// fragment's.
    pub fn fragments(
        &self,
        ends: &[f32],
        major: (i64, i64),
        minor: (i64, i64),
        clip: (f64, f64),
        mut f: impl FnMut([i64; 4], f64, &[f32], f32),
    ) {
        let n = self.n as usize;
        let mut a = [0f32; MAX_ATTRS];
        let (e0, e1) = ends.split_at(n);
        let (c0, c1) = (self.first.max(major.0), self.last.min(major.1));
        let ascending = self.a1 >= self.a0;
        // A uniform segment's values, the same at every fragment (see `uniform_values`).
        let z_uniform = if self.uniform {
            self.uniform_values(ends, &mut a[..n])
        } else {
            0.0
        };
        match &self.kind {
            LineKind::Aliased {
                p0,
                p1,
                end,
                shift,
                width,
            } => {
                let (clip_lo, clip_hi) = clip;
                for ci in c0..=c1 {
                    let c = ci as f64;
                    if c < clip_lo || c > clip_hi {
                        continue;
                    }
                    let centre = c + 0.5;
                    // Which columns: the diamond-exit rule on the segment itself (a wide line
                    // has the same columns as its width-1 line, as llvmpipe draws them); which
                    // rows: the moved segment's.
                    let m = self.b0 + (centre.clamp(self.lo, self.hi) - self.a0) * self.db_da;
                    let minor_px = floor(m);
                    if (minor_px as i64) > minor.1 || (minor_px as i64) + width <= minor.0 {
                        continue;
                    }
                    let unshifted = floor(m + shift);
                    let diamond = if self.x_major {
                        [c + 0.5, unshifted + 0.5]
                    } else {
                        [unshifted + 0.5, c + 0.5]
                    };
                    let inner = centre > self.lo && centre < self.hi;
                    if !exits_column(*p0, *p1, *end, diamond, inner, m + shift - unshifted) {
                        continue;
                    }
                    // The fragment's place along the segment: where the segment leaves its
                    // pixel, in whole major-axis units from the start.
                    let exit = if ascending {
                        c + 1.0 - self.a0
                    } else {
                        self.a0 - c
                    };
                    let counter = self.start_counter.wrapping_add(floor(exit.max(0.0)) as u32);
                    if !stipple_passes(self.stipple, counter) {
                        continue;
                    }
                    let z = if self.uniform {
                        z_uniform
                    } else {
                        let t = ((centre - self.a0) / (self.a1 - self.a0)).clamp(0.0, 1.0);
                        self.attrs_at([e0, e1], t, &mut a[..n]);
                        self.z[0] + t * (self.z[1] - self.z[0]) + self.z_offset
                    };
                    let (px, py) = if self.x_major {
                        (ci, minor_px as i64)
                    } else {
                        (minor_px as i64, ci)
                    };
                    let rect = if self.x_major {
                        [px, py, px + 1, py + width]
                    } else {
                        [px, py, px + width, py + 1]
                    };
                    f(rect, z, &a[..n], 1.0);
                }
            }
            LineKind::Smooth {
                quad,
                reach,
                minor_rect,
                along,
            } => {
                for c in c0..=c1 {
                    let centre = c as f64 + 0.5;
                    if self.stipple.is_some() {
                        // Columns along the segment before this one in the direction of
                        // travel advance the counter.
                        let before = along.map_or(0, |(s0, s1)| {
                            if ascending {
                                (c.min(s1 + 1) - s0).max(0)
                            } else {
                                (s1 - c.max(s0 - 1)).max(0)
                            }
                        });
                        let counter = self.start_counter.wrapping_add(before as u32);
                        if !stipple_passes(self.stipple, counter) {
                            continue;
                        }
                    }
                    let m = self.b0 + (centre.clamp(self.lo, self.hi) - self.a0) * self.db_da;
                    let r0 = (floor(m - reach) as i64).max(minor_rect.0).max(minor.0);
                    let r1 = (floor(m + reach) as i64).min(minor_rect.1).min(minor.1);
                    for row in r0..=r1 {
                        let (px, py) = if self.x_major { (c, row) } else { (row, c) };
                        let Some((cov, t)) = quad.fragment(px as f64 + 0.5, py as f64 + 0.5) else {
                            continue;
                        };
                        // Data are those of the lengthened quad's vertices (the end points'
                        // own), so they vary over the lengthened rectangle: then the depth of
                        // a smooth outline drawn before a polygon over the same edge decides
                        // the same pixels as Mesa's (xss-stonerview).
                        let z = if self.uniform {
                            z_uniform
                        } else {
                            self.attrs_at([e0, e1], t, &mut a[..n]);
                            self.z[0] + t * (self.z[1] - self.z[0]) + self.z_offset
                        };
                        f([px, py, px + 1, py + 1], z, &a[..n], cov as f32);
                    }
                }
            }
        }
    }

    /// Whether [`Self::smooth_rows`] walks the segment: antialiased and not stippled.
    pub fn by_rows(&self) -> bool {
        matches!(self.kind, LineKind::Smooth { .. }) && self.stipple.is_none()
    }

    /// Whether the major axis is x.
    pub fn x_major(&self) -> bool {
        self.x_major
    }

    /// Whether the segment is aliased.
    pub fn is_aliased(&self) -> bool {
        matches!(self.kind, LineKind::Aliased { .. })
    }

    /// For a segment with [`Self::by_rows`]: the fragments [`Self::fragments`] gives for the
    /// same `major` and `minor` (at most [`MAX_SIDE`] each) whose major-axis column lies in
    /// `clip` (inclusive), row by row: `f(y, x0, coverage)` for each run of fragments next to
    /// each other in window row `y` from column `x0`, pixel `x0 + i` with the coverage
    /// `coverage[i]` that `fragments` passes for it. The pixels are those of the column walk
    /// (each column's rows `r0..=r1`, then the quad's test); their coverages come eight at a
    /// time from [`SmoothLineQuad::coverage_row`] instead of one call per pixel.
    pub fn smooth_rows(
        &self,
        major: (i64, i64),
        minor: (i64, i64),
        clip: (i64, i64),
        mut f: impl FnMut(i32, i32, &[f32]),
    ) {
        let LineKind::Smooth {
            quad,
            reach,
            minor_rect,
            ..
        } = &self.kind
        else {
            return;
        };
        let (c0, c1) = (
            self.first.max(major.0).max(clip.0),
            self.last.min(major.1).min(clip.1),
        );
        let side = MAX_SIDE as i64;
        if c0 > c1 || minor.1 < minor.0 || minor.1 - minor.0 >= side || major.1 - major.0 >= side {
            return;
        }
        // Column c's rows, as `fragments` bounds them.
        let rows = |c: i64| {
            let centre = c as f64 + 0.5;
            let m = self.b0 + (centre.clamp(self.lo, self.hi) - self.a0) * self.db_da;
            let r0 = (floor(m - reach) as i64).max(minor_rect.0).max(minor.0);
            let r1 = (floor(m + reach) as i64).min(minor_rect.1).min(minor.1);
            (r0, r1)
        };
        let mut coverage = [0f32; MAX_SIDE];
        let mut emit = |y: i64, xa: i64, xb: i64| {
            let cov = &mut coverage[..(xb - xa + 1) as usize];
            // Runs of pixels inside the quad (one: the quad is convex, and each of its
            // tests is monotonic along a row).
            let mut inside = quad.coverage_row(xa, y, cov);
            while inside != 0 {
                let start = inside.trailing_zeros();
                let len = (!(inside >> start)).trailing_zeros();
                let (a, b) = (start as usize, (start + len) as usize);
                f(y as i32, (xa + start as i64) as i32, &cov[a..b]);
                let run = if len >= 128 {
                    u128::MAX
                } else {
                    ((1u128 << len) - 1) << start
                };
                inside &= !run;
            }
        };
        if !self.x_major {
            // A column is a window row: its pixels are next to each other already.
            for c in c0..=c1 {
                let (r0, r1) = rows(c);
                if r0 <= r1 {
                    emit(c, r0, r1);
                }
            }
            return;
        }
        // A window row holds the columns whose row range contains it: an interval, since
        // both bounds are monotonic in the column, in the same direction (`m` is a rounded
        // linear function of the clamped centre, and floor, max and min keep the order).
        // Taken in the order in which the bounds do not decrease, the columns whose upper
        // bound reaches row y start at `a` and those whose lower bound does end at `b`, both
        // moving on as y grows.
        let n = (c1 - c0 + 1) as usize;
        let mut bounds = [(0i64, 0i64); MAX_SIDE];
        for (k, b) in bounds[..n].iter_mut().enumerate() {
            *b = rows(c0 + k as i64);
        }
        let rising = bounds[0].0 <= bounds[n - 1].0 && bounds[0].1 <= bounds[n - 1].1;
        let column = |i: usize| if rising { i } else { n - 1 - i };
        let (mut a, mut b) = (0usize, 0usize);
        for y in minor.0..=minor.1 {
            while a < n && bounds[column(a)].1 < y {
                a += 1;
            }
            if a == n {
                break;
            }
            while b < n && bounds[column(b)].0 <= y {
                b += 1;
            }
            // Columns a..b in the order: the lower bound reaches y before b, the upper from a.
            if a < b {
                let (i, j) = (column(a), column(b - 1));
                emit(y, c0 + i.min(j) as i64, c0 + i.max(j) as i64);
            }
        }
    }

    /// The major-axis pixel range a tile at `tile` (x0, y0, side) covers, and its minor range.
    pub fn tile_ranges(&self, x0: i32, y0: i32, side: i32) -> ((i64, i64), (i64, i64)) {
        let xs = (x0 as i64, (x0 + side) as i64 - 1);
        let ys = (y0 as i64, (y0 + side) as i64 - 1);
        if self.x_major {
            (xs, ys)
        } else {
            (ys, xs)
        }
    }

    /// For a `uniform` segment: the depth and (into `out`, `n` of them) the attributes of
    /// every fragment, computed once at `t = 0`. Its fragments' `t` lie in [0, 1], and where
    /// the ends are equal the interpolation adds `t` times a difference that is +0 (or NaN
    /// from infinite products, at every `t` alike), so each fragment's values are these,
    /// bit for bit.
    pub fn uniform_values(&self, ends: &[f32], out: &mut [f32]) -> f64 {
        let n = self.n as usize;
        let (e0, e1) = ends.split_at(n);
        self.attrs_at([e0, e1], 0.0, out);
        self.z[0] + 0.0 * (self.z[1] - self.z[0]) + self.z_offset
    }

    /// Attributes at parameter `t` of the segment, perspective-correct.
    #[inline]
    fn attrs_at(&self, ends: [&[f32]; 2], t: f64, out: &mut [f32]) {
        // Interpolate attr/w and 1/w linearly in window space.
        let [q0, q1] = self.inv_w;
        let iw = q0 + t * (q1 - q0);
        for (i, o) in out.iter_mut().enumerate() {
            let p = ends[0][i] as f64 * q0 + t * (ends[1][i] as f64 * q1 - ends[0][i] as f64 * q0);
            // Flat colours are equal at both ends, so this returns them unchanged.
            *o = (p / iw) as f32;
        }
    }

    /// The draw rectangle's major-axis bounds as the aliased rule clips columns.
    pub fn major_clip(&self, ds: &TileDraw) -> (f64, f64) {
        let r = &ds.draw_rect;
        if self.x_major {
            (r.x0 as f64, r.x1 as f64 - 1.0)
        } else {
            (r.y0 as f64, r.y1 as f64 - 1.0)
        }
    }
}

/// The quad an antialiased line is drawn as (see [`plan_smooth`]).
#[derive(Clone, Debug)]
struct SmoothLineQuad {
    p0: [f64; 2],
    /// Unit direction from the start to the end.
    dir: [f64; 2],
    len: f64,
    /// Half the quad's width: 1 for widths up to 1, else `width / 2 + 1/2`.
    half_width: f64,
    /// Half the lengthened length, `len / 2 + 1/2`.
    half_length: f64,
    /// 1 / w at the start and at the end.
    q: [f64; 2],
}

impl SmoothLineQuad {
    fn new(p0: [f64; 2], p1: [f64; 2], len: f64, width: f64, q0: f64, q1: f64) -> Self {
        let [wlo, whi] = limits::LINE_WIDTH_RANGE;
        let w = width.max(wlo as f64).min(whi as f64);
        let w = if w.is_nan() { 1.0 } else { w };
        SmoothLineQuad {
            p0,
            dir: [(p1[0] - p0[0]) / len, (p1[1] - p0[1]) / len],
            len,
            half_width: if w <= 1.0 { 1.0 } else { w / 2.0 + 0.5 },
            half_length: len / 2.0 + 0.5,
            q: [q0, q1],
        }
    }

    /// The fragment at window position `(x, y)` (a pixel centre): `None` outside the quad,
    /// else its coverage and its parameter along the lengthened quad (0 at the start's edge,
    /// 1 at the end's), which the data are interpolated at.
    fn fragment(&self, x: f64, y: f64) -> Option<(f64, f64)> {
        let (sx, sy) = (x - self.p0[0], y - self.p0[1]);
        // Distance along the segment from the start, and to its left.
        let u = sx * self.dir[0] + sy * self.dir[1];
        let left = -sx * self.dir[1] + sy * self.dir[0];
        let (h, hl) = (self.half_width, self.half_length);
        // Quad coordinates: s along (0 at the start's edge), r across (0 on the right side).
        let s = (u + 0.5) / (self.len + 1.0);
        let r = (h + left) / (2.0 * h);
        if !(0.0..1.0).contains(&s) || !(0.0..1.0).contains(&r) {
            return None;
        }
        // Perspective-correct interpolation over the triangle holding the point: the corners
        // at one end share their 1/w, so the weights only depend on s, and the triangle's
        // barycentrics are affine in (s, r).
        let [q0, q1] = self.q;
        let den = (1.0 - s) * q0 + s * q1;
        let across = if s + r <= 1.0 {
            // Start-right, start-left, end-right: barycentrics 1 - s - r, r, s.
            h * (q0 * (2.0 * r - 1.0 + s) - s * q1)
        } else {
            // End-left, start-left, end-right: barycentrics s + r - 1, 1 - s, 1 - r.
            h * (q1 * (s + 2.0 * r - 2.0) + (1.0 - s) * q0)
        } / den;
        let along = hl * (s * q1 - (1.0 - s) * q0) / den;
        let cov = (h - across.abs()).clamp(0.0, 1.0) * (hl - along.abs()).clamp(0.0, 1.0);
        Some((if cov.is_nan() { 0.0 } else { cov }, s))
    }
}

impl SmoothLineQuad {
    /// The pixels `x0 + i` of row `y` (`i < out.len() <= 128`) inside the quad, bit `i` set
    /// where [`Self::fragment`] answers `Some` at the pixel's centre, with the coverage it
    /// answers as `f32` in `out[i]` (0 for the others). Eight pixels at a time with AVX2 (the
    /// same operations on each lane, so the same bits: twin test
    /// `coverage_rows_are_the_per_pixel_coverage`), else pixel by pixel.
    fn coverage_row(&self, x0: i64, y: i64, out: &mut [f32]) -> u128 {
        #[cfg(target_arch = "x86_64")]
        {
            if crate::common::cpu::available() {
                // SAFETY: AVX2 is present (checked just above).
                return unsafe { self.coverage_row_avx2(x0, y, out) };
            }
        }
        self.coverage_row_scalar(x0, y, out)
    }

    /// [`Self::coverage_row`] pixel by pixel.
    fn coverage_row_scalar(&self, x0: i64, y: i64, out: &mut [f32]) -> u128 {
        let yc = y as f64 + 0.5;
        let mut inside = 0u128;
        for (i, o) in out.iter_mut().enumerate() {
            let xc = (x0 + i as i64) as f64 + 0.5;
            *o = match self.fragment(xc, yc) {
                Some((c, _)) => {
                    inside |= 1 << i;
                    c as f32
                }
                None => 0.0,
            };
        }
        inside
    }

    /// [`Self::coverage_row`] eight pixels at a time: [`Self::fragment`]'s operations in its
    /// order on four f64 lanes twice (no fused multiply-add, IEEE division, comparisons that
    /// fail on NaN as Rust's do, `clamp` as two selects so that NaN passes through it), both
    /// triangles' across coordinates computed and the one holding each pixel selected.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn coverage_row_avx2(&self, x0: i64, y: i64, out: &mut [f32]) -> u128 {
        use std::arch::x86_64::*;
        let yc = y as f64 + 0.5;
        let sy = yc - self.p0[1];
        let (h, hl) = (self.half_width, self.half_length);
        let [q0, q1] = self.q;
        let set = |v: f64| _mm256_set1_pd(v);
        // The products of `sy` are the same for every pixel of the row.
        let (sy_d1, sy_d0) = (set(sy * self.dir[1]), set(sy * self.dir[0]));
        let (d0, d1, px) = (set(self.dir[0]), set(self.dir[1]), set(self.p0[0]));
        let (len1, h2) = (set(self.len + 1.0), set(2.0 * h));
        let (vh, vhl, vq0, vq1) = (set(h), set(hl), set(q0), set(q1));
        let (zero, half, one, two) = (set(0.0), set(0.5), set(1.0), set(2.0));
        let sign = set(-0.0);
        let clamp01 = |v: __m256d| {
            let v = _mm256_blendv_pd(v, zero, _mm256_cmp_pd::<_CMP_LT_OQ>(v, zero));
            _mm256_blendv_pd(v, one, _mm256_cmp_pd::<_CMP_GT_OQ>(v, one))
        };
        let lanes = |xc: __m256d| {
            let sx = _mm256_sub_pd(xc, px);
            let u = _mm256_add_pd(_mm256_mul_pd(sx, d0), sy_d1);
            let left = _mm256_add_pd(_mm256_mul_pd(_mm256_xor_pd(sx, sign), d1), sy_d0);
            let s = _mm256_div_pd(_mm256_add_pd(u, half), len1);
            let r = _mm256_div_pd(_mm256_add_pd(vh, left), h2);
            let inside = _mm256_and_pd(
                _mm256_and_pd(
                    _mm256_cmp_pd::<_CMP_GE_OQ>(s, zero),
                    _mm256_cmp_pd::<_CMP_LT_OQ>(s, one),
                ),
                _mm256_and_pd(
                    _mm256_cmp_pd::<_CMP_GE_OQ>(r, zero),
                    _mm256_cmp_pd::<_CMP_LT_OQ>(r, one),
                ),
            );
            let oms = _mm256_sub_pd(one, s);
            let den = _mm256_add_pd(_mm256_mul_pd(oms, vq0), _mm256_mul_pd(s, vq1));
            let r2 = _mm256_mul_pd(two, r);
            // Start-right, start-left, end-right: h (q0 (2r - 1 + s) - s q1).
            let first = _mm256_mul_pd(
                vh,
                _mm256_sub_pd(
                    _mm256_mul_pd(vq0, _mm256_add_pd(_mm256_sub_pd(r2, one), s)),
                    _mm256_mul_pd(s, vq1),
                ),
            );
            // End-left, start-left, end-right: h (q1 (s + 2r - 2) + (1 - s) q0).
            let second = _mm256_mul_pd(
                vh,
                _mm256_add_pd(
                    _mm256_mul_pd(vq1, _mm256_sub_pd(_mm256_add_pd(s, r2), two)),
                    _mm256_mul_pd(oms, vq0),
                ),
            );
            let in_first = _mm256_cmp_pd::<_CMP_LE_OQ>(_mm256_add_pd(s, r), one);
            let across = _mm256_div_pd(_mm256_blendv_pd(second, first, in_first), den);
            let along = _mm256_div_pd(
                _mm256_mul_pd(
                    vhl,
                    _mm256_sub_pd(_mm256_mul_pd(s, vq1), _mm256_mul_pd(oms, vq0)),
                ),
                den,
            );
            let cov = _mm256_mul_pd(
                clamp01(_mm256_sub_pd(vh, _mm256_andnot_pd(sign, across))),
                clamp01(_mm256_sub_pd(vhl, _mm256_andnot_pd(sign, along))),
            );
            // NaN answers 0; so do the pixels outside.
            let cov = _mm256_and_pd(cov, _mm256_cmp_pd::<_CMP_ORD_Q>(cov, cov));
            let cov = _mm256_and_pd(cov, inside);
            (_mm256_cvtpd_ps(cov), _mm256_movemask_pd(inside) as u128)
        };
        let step = _mm256_setr_pd(0.0, 1.0, 2.0, 3.0);
        let mut mask = 0u128;
        for (k, chunk) in out.chunks_mut(8).enumerate() {
            // Pixel centres are whole numbers plus 1/2 well inside f64's exact range (the
            // window's), so adding the lane's offset is exact.
            let xc = set((x0 + 8 * k as i64) as f64 + 0.5);
            let (lo, lo_in) = lanes(_mm256_add_pd(xc, step));
            let (hi, hi_in) = lanes(_mm256_add_pd(_mm256_add_pd(xc, set(4.0)), step));
            let live = (1u128 << chunk.len()) - 1;
            mask |= ((lo_in | hi_in << 4) & live) << (8 * k);
            if let Ok(whole) = <&mut [f32; 8]>::try_from(&mut *chunk) {
                // SAFETY: `whole` holds eight f32, 32 bytes; unaligned stores.
                unsafe {
                    _mm_storeu_ps(whole.as_mut_ptr(), lo);
                    _mm_storeu_ps(whole.as_mut_ptr().add(4), hi);
                }
            } else {
                let mut v = [0f32; 8];
                // SAFETY: as above, into `v`.
                unsafe {
                    _mm_storeu_ps(v.as_mut_ptr(), lo);
                    _mm_storeu_ps(v.as_mut_ptr().add(4), hi);
                }
                chunk.copy_from_slice(&v[..chunk.len()]);
            }
        }
        mask
    }
}

/// `v.floor()`, without the libm call the baseline x86-64 target makes of it (it has no
/// rounding instruction before SSE4.1): the same value for every `v`, the sign of zero and
/// NaN included (from 2^52 on every f64 is whole). The per-column and per-pixel floors of
/// `LineSetup::fragments` were a tenth of a `lines` frame as calls.
#[inline(always)]
fn floor(v: f64) -> f64 {
    if v.abs() < (1u64 << 52) as f64 {
        let t = v as i64 as f64;
        if t > v {
            t - 1.0
        } else {
            t.copysign(v)
        }
    } else {
        v
    }
}

/// The tiny move of section 3.4.1's perturbed end points, across the major axis: far below
/// the smallest distance (2^-29 pixel) at which a segment between sub-pixel positions of a
/// 2^13-pixel window can pass a diamond without touching it, far above the rounding error
/// (2^-39) of the positions along it.
const PERTURBATION: f64 = 1.0 / (1u64 << 36) as f64;

/// How far from the middle of its pixel the segment may cross a column's centre line for
/// [`exits_column`] to take the crossing as inside the diamond without computing it: half a
/// pixel less 2^-20, where the rounding errors of the two computations of the crossing
/// (`fragments`' and [`exits_diamond`]'s, ten operations on coordinates below 2^23) stay
/// under 2^-26.
const CROSSING_MARGIN: f64 = 0.5 - 1.0 / (1u64 << 20) as f64;

/// [`exits_diamond`] for the pixel centred at `c` in a column whose centre lies strictly
/// between the segment's ends (`inner`), the segment crossing the centre line at `frac`
/// (its moved minor coordinate there less the pixel's, as `fragments` computes it): where
/// that crossing is well inside the pixel, it is inside the diamond, so the segment meets it
/// and only the end point decides; elsewhere the full test. The same verdicts (unit test
/// `column_exits_are_the_diamond_rule`).
#[inline(always)]
fn exits_column(
    p0: [f64; 2],
    p1: [f64; 2],
    end: [f64; 2],
    c: [f64; 2],
    inner: bool,
    frac: f64,
) -> bool {
    if inner && (frac - 0.5).abs() < CROSSING_MARGIN {
        return !((end[0] - c[0]).abs() + (end[1] - c[1]).abs() < 0.5);
    }
    exits_diamond(p0, p1, end, c)
}

/// Section 3.4.1's diamond-exit rule for the pixel centred at `c`: the (perturbed) segment from
/// `p0` to `p1` produces the fragment when it meets the diamond `|x - cx| + |y - cy| < 1/2` and
/// the unperturbed end point `end` lies outside it (it leaves the diamond).
fn exits_diamond(p0: [f64; 2], p1: [f64; 2], end: [f64; 2], c: [f64; 2]) -> bool {
    let l1 = |p: [f64; 2]| (p[0] - c[0]).abs() + (p[1] - c[1]).abs();
    if l1(end) < 0.5 {
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
                // On the crossing axis the point is exactly at the centre.
                let o = 1 - axis;
                let other = p0[o] + t * (p1[o] - p0[o]);
                best = best.min((other - c[o]).abs());
            }
        }
    }
    best < 0.5
}

#[cfg(test)]
mod tests {
    use super::SmoothLineQuad;

    #[test]
    fn floor_is_the_f64_floor() {
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        let mut values = vec![
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            0.999_999_999_999_999_9,
            -1e-300,
            1e-300,
            4503599627370495.5,
            -4503599627370495.5,
            4503599627370496.0,
            -4503599627370497.0,
            9.3e18,
            -9.3e18,
            1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            f64::MIN_POSITIVE,
        ];
        for _ in 0..100_000 {
            let r = crate::test_support::xorshift(&mut seed);
            // Random bit patterns (every magnitude) and values around whole numbers.
            values.push(f64::from_bits(r));
            let whole = (r >> 40) as i64 as f64 - 8_000_000.0;
            values.push(whole + [0.0, 1e-9, -1e-9, 0.5, -0.5][(r % 5) as usize]);
        }
        for v in values {
            if v.is_nan() {
                assert!(super::floor(v).is_nan());
            } else {
                assert_eq!(super::floor(v).to_bits(), v.floor().to_bits(), "{v:e}");
            }
        }
    }

    /// The eight-lane coverages are the per-pixel function's, bit for bit: random quads
    /// (widths 0.5-12, every direction, lengths from a tenth of a pixel, 1/w equal or up to
    /// twenty times apart at the ends, fractional end points) over rows of every length and
    /// start through and around them. (Without AVX2 both are the per-pixel function.)
    #[test]
    fn coverage_rows_are_the_per_pixel_coverage() {
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        let mut unit =
            || (crate::test_support::xorshift(&mut seed) >> 11) as f64 / (1u64 << 53) as f64;
        let (mut inside, mut partial) = (0usize, 0usize);
        for case in 0..3000 {
            let p0 = [200.0 * unit(), 200.0 * unit()];
            let (len, ang) = (0.1 + 60.0 * unit(), 6.3 * unit());
            let p1 = [p0[0] + len * ang.cos(), p0[1] + len * ang.sin()];
            let len = ((p1[0] - p0[0]).powi(2) + (p1[1] - p0[1]).powi(2)).sqrt();
            let (q0, q1) = if case % 3 == 0 {
                (1.0, 1.0)
            } else {
                (0.05 + unit(), 0.05 + unit())
            };
            let q = SmoothLineQuad::new(p0, p1, len, 0.5 + 11.5 * unit(), q0, q1);
            let y = (p0[1] + (p1[1] - p0[1]) * unit() - 8.0 + 16.0 * unit()).floor() as i64;
            let x0 = (p0[0].min(p1[0]) - 10.0 + 10.0 * unit()).floor() as i64;
            let n = 1 + (case % 80);
            let mut fast = vec![0f32; n];
            let mut slow = vec![0f32; n];
            let fast_in = q.coverage_row(x0, y, &mut fast);
            let slow_in = q.coverage_row_scalar(x0, y, &mut slow);
            assert_eq!(fast_in, slow_in, "case {case}");
            for i in 0..n {
                assert_eq!(
                    fast[i].to_bits(),
                    slow[i].to_bits(),
                    "case {case} pixel ({}, {y}): {} vs {}",
                    x0 + i as i64,
                    fast[i],
                    slow[i]
                );
                let c = slow[i];
                inside += (slow_in >> i & 1) as usize;
                partial += usize::from(c > 0.0 && c < 1.0);
            }
            // The per-pixel function's verdicts.
            let yc = y as f64 + 0.5;
            for i in 0..n {
                let some = q.fragment((x0 + i as i64) as f64 + 0.5, yc).is_some();
                assert_eq!(slow_in >> i & 1 == 1, some, "case {case} pixel {i}");
            }
        }
        // The rows did cross the quads, edges included.
        assert!(inside > 15_000 && partial > 5_000, "{inside} {partial}");
    }

    /// The shortcut of `exits_column` gives the diamond rule's verdicts: every column of
    /// random segments between sub-pixel positions (widths 1-5, every direction, short and
    /// long, some axis-aligned or through pixel corners), set up and walked as `fragments`
    /// does it; the shortcut must be taken for most columns.
    #[test]
    fn column_exits_are_the_diamond_rule() {
        use super::{aliased_plan, exits_column, exits_diamond, floor, LineKind};
        use crate::common::fixed::SUBPIXEL;
        let mut seed = 0x0123_4567_89AB_CDEFu64;
        let mut next = || crate::test_support::xorshift(&mut seed);
        let (mut columns, mut short) = (0usize, 0usize);
        for case in 0..20_000 {
            let s = SUBPIXEL;
            let mut pos = |spread: i64| {
                let v = (next() % (spread as u64 * 2 * s as u64)) as i64 - spread * s;
                v as f64 / s as f64
            };
            let p0 = [500.0 + pos(400), 500.0 + pos(400)];
            let reach = [3, 40, 300][case % 3];
            let mut p1 = [p0[0] + pos(reach), p0[1] + pos(reach)];
            match case % 7 {
                0 => p1[1] = p0[1],
                1 => p1[0] = p0[0],
                2 => {
                    p1 = [
                        p0[0] + (p1[0] - p0[0]).round(),
                        p0[1] + (p1[0] - p0[0]).round() / 2.0,
                    ]
                }
                _ => {}
            }
            let width = 1.0 + (case % 5) as f32;
            let Some((kind, x_major, [a0, a1, b0, db_da], (first, last))) =
                aliased_plan(p0, p1, width)
            else {
                continue;
            };
            let LineKind::Aliased {
                p0: q0,
                p1: q1,
                end,
                shift,
                ..
            } = kind
            else {
                unreachable!()
            };
            let (lo, hi) = (a0.min(a1), a0.max(a1));
            for ci in first..=last {
                let centre = ci as f64 + 0.5;
                let m = b0 + (centre.clamp(lo, hi) - a0) * db_da;
                let unshifted = floor(m + shift);
                let diamond = if x_major {
                    [centre, unshifted + 0.5]
                } else {
                    [unshifted + 0.5, centre]
                };
                let inner = centre > lo && centre < hi;
                let frac = m + shift - unshifted;
                assert_eq!(
                    exits_column(q0, q1, end, diamond, inner, frac),
                    exits_diamond(q0, q1, end, diamond),
                    "case {case}: {p0:?} -> {p1:?}, column {ci}"
                );
                columns += 1;
                short += usize::from(inner && (frac - 0.5).abs() < super::CROSSING_MARGIN);
            }
        }
        assert!(
            columns > 500_000 && short * 10 > columns * 8,
            "{columns} {short}"
        );
    }

    /// A quad from (10.25, 20.5) to (40.75, 31.5), width 4, with 1/w `q0` and `q1`.
    fn quad(q0: f64, q1: f64) -> SmoothLineQuad {
        let (p0, p1): ([f64; 2], [f64; 2]) = ([10.25, 20.5], [40.75, 31.5]);
        let len = ((p1[0] - p0[0]) * (p1[0] - p0[0]) + (p1[1] - p0[1]) * (p1[1] - p0[1])).sqrt();
        SmoothLineQuad::new(p0, p1, len, 4.0, q0, q1)
    }

    /// The point at distance `u` along the segment and `left` to its left.
    fn at(q: &SmoothLineQuad, u: f64, left: f64) -> (f64, f64) {
        (
            q.p0[0] + u * q.dir[0] - left * q.dir[1],
            q.p0[1] + u * q.dir[1] + left * q.dir[0],
        )
    }

    #[test]
    fn without_perspective_coverage_is_the_box_filtered_distance_to_the_rectangle() {
        let q = quad(1.0, 1.0);
        // Half width 4 / 2 + 1/2 = 2.5; the coverage across is 2.5 - |d| (clamped), along it
        // is u + 1/2 near the start and len + 1/2 - u near the end.
        for (u, left) in [
            (0.0, 0.0),
            (-0.3, 1.7),
            (5.0, -2.2),
            (16.0, 2.4),
            (30.0, 0.9),
        ] {
            let (x, y) = at(&q, u, left);
            let across = (2.5f64 - left.abs()).clamp(0.0, 1.0);
            let along = (u + 0.5)
                .clamp(0.0, 1.0)
                .min((q.len + 0.5 - u).clamp(0.0, 1.0));
            let (cov, t) = q.fragment(x, y).expect("inside the quad");
            assert!((cov - across * along).abs() < 1e-9, "u {u} d {left}: {cov}");
            assert!((t - (u + 0.5) / (q.len + 1.0)).abs() < 1e-12);
        }
        // Outside: past the lengthened ends and the widened sides.
        for (u, left) in [(-0.6, 0.0), (q.len + 0.6, 0.0), (3.0, 2.6), (3.0, -2.6)] {
            let (x, y) = at(&q, u, left);
            assert!(q.fragment(x, y).is_none(), "u {u} d {left}");
        }
    }

    #[test]
    fn with_perspective_the_two_triangles_agree_on_their_edges() {
        // 1/w five times smaller at the end: the across coordinate bends, but it is continuous
        // across the split diagonal and exactly +-h on the long sides (both corners of a side
        // carry the same value, so every interpolation gives it there).
        let q = quad(1.0, 0.2);
        let (h, l1) = (q.half_width, q.len + 1.0);
        for k in 1..20 {
            let s = k as f64 / 20.0;
            let u = s * l1 - 0.5;
            // On a long side the pixel is just inside: coverage across is the tiny remainder.
            for left in [h - 1e-9, -(h - 1e-9)] {
                let (x, y) = at(&q, u, left);
                let (cov, _) = q.fragment(x, y).expect("inside");
                assert!(cov < 1e-6, "s {s} left {left}: {cov}");
            }
            // Either side of the diagonal s + r = 1 (r = (h + left) / 2h).
            let left_diag = (1.0 - s) * 2.0 * h - h;
            let (xa, ya) = at(&q, u, left_diag - 1e-9);
            let (xb, yb) = at(&q, u, left_diag + 1e-9);
            let (ca, _) = q.fragment(xa, ya).expect("inside");
            let (cb, _) = q.fragment(xb, yb).expect("inside");
            assert!((ca - cb).abs() < 1e-6, "s {s}: {ca} vs {cb}");
        }
        // The bend: on the centre line the across coordinate is not 0 away from the ends, so
        // the coverage there differs from the flat case somewhere along the line.
        let flat = quad(1.0, 1.0);
        let bent = (1..20).any(|k| {
            let (x, y) = at(&q, k as f64 * q.len / 20.0, 1.5);
            let a = q.fragment(x, y).map(|f| f.0);
            let b = flat.fragment(x, y).map(|f| f.0);
            matches!((a, b), (Some(a), Some(b)) if (a - b).abs() > 0.05)
        });
        assert!(bent);
    }
}

//! One line segment's fragments in one tile (`Command::Line`): walked by
//! [`LineSetup::fragments`] and shaded as constant-attribute rectangles, the fragments of a
//! segment whose every fragment has the same values gathered into row runs first.

use super::coarse::CoarseDepth;
use super::draw::TileDraw;
use super::line::LineSetup;
use super::pixels::stores_directly;
use super::schedule::{shade_rect, MAX_SIDE};
use super::setup::Plane;
use crate::common::attr;
use crate::common::attr::MAX_ATTRS;
use crate::common::fixed::color4_to_u8;
use crate::common::rect::Rect;
use crate::fragment::span::{CoveredFn, CoveredRows, Interpolants, PrimitiveShared, UnitLevels};
use crate::framebuffer::Tile;

/// What shading a tile's line commands needs besides the tile.
pub(super) struct LineShading<'s, 'l> {
    pub(super) ds: &'s TileDraw,
    pub(super) levels: &'s UnitLevels<'l>,
    pub(super) coarse: &'s mut CoarseDepth,
    /// The coverages of the pending runs' pixels, at the pixels' places in the tile (row by
    /// row, `side` to a row); sized on first use.
    pub(super) coverage: &'s mut Vec<f32>,
}

/// A row's pending run: pixels `x0..x1` next to each other, each fully covered (`full`) or
/// with its coverage in [`LineShading::coverage`].
#[derive(Clone, Copy)]
struct Run {
    x0: i32,
    x1: i32,
    full: bool,
}

impl LineShading<'_, '_> {
    /// Shades segment `line` (its ends' attributes `ends`) in `tile`.
    pub(super) fn line(&mut self, line: &LineSetup, ends: &[f32], tile: &mut Tile) {
        let ds = self.ds;
        let n = line.n as usize;
        let (major, minor) = line.tile_ranges(tile.x0, tile.y0, tile.side());
        let mut planes = [Plane::constant(0.0); MAX_ATTRS];
        let count = ds.attr_count.min(n);
        let d = &ds.draw_rect;
        let clip = |r: [i64; 4]| Rect {
            x0: r[0].max(d.x0 as i64) as i32,
            y0: r[1].max(d.y0 as i64) as i32,
            x1: r[2].min(d.x1 as i64) as i32,
            y1: r[3].min(d.y1 as i64) as i32,
        };
        let side = tile.side() as usize;
        if !line.uniform || side > MAX_SIDE {
            line.fragments(
                ends,
                major,
                minor,
                line.major_clip(ds),
                |r, z, a, coverage| {
                    let rect = clip(r);
                    if rect.is_empty() {
                        return;
                    }
                    for (p, &v) in planes[..count].iter_mut().zip(a) {
                        *p = Plane::constant(v as f64);
                    }
                    let p = &planes[..count];
                    shade_rect(ds, tile, self.levels, self.coarse, rect, z, p, coverage);
                },
            );
            return;
        }
        // Every fragment has the same values: the pixels of each row next to each other are
        // one run, shaded as one span when all are fully covered, else (antialiased edges)
        // by the key's row function with a coverage per pixel, or pixel by pixel without
        // one. The same values per pixel as one span per fragment: a segment's fragments
        // never share a pixel, so their order does not matter.
        let mut a = [0f32; MAX_ATTRS];
        let z = line.uniform_values(ends, &mut a[..n]);
        for (p, &v) in planes[..count].iter_mut().zip(&a) {
            *p = Plane::constant(v as f64);
        }
        let p = &planes[..count];
        if line.by_rows() {
            // Antialiased: each row's pixels with their coverages at once, through the
            // key's covered row function with the segment's inputs prepared once.
            let shared = PrimitiveShared::new(self.levels);
            let it = Interpolants {
                z: Plane::constant(z),
                inv_w: Plane::constant(1.0),
                attrs: p,
                perspective: false,
                constant_primary: false,
                coverage: 1.0,
                shared: &shared,
            };
            if let Some(rows) = CoveredRows::new(&ds.fragment, &it) {
                let clip = if line.x_major() {
                    (d.x0 as i64, d.x1 as i64 - 1)
                } else {
                    (d.y0 as i64, d.y1 as i64 - 1)
                };
                let depth_write = ds.fragment.key.depth_write;
                line.smooth_rows(major, minor, clip, |y, x0, coverage| {
                    if depth_write {
                        let x1 = x0 + coverage.len() as i32;
                        let rect = Rect {
                            x0,
                            y0: y,
                            x1,
                            y1: y + 1,
                        };
                        self.coarse.forget(tile, rect);
                    }
                    rows.row(&ds.fragment, tile, y, x0, coverage);
                });
                return;
            }
        } else if line.is_aliased() && ds.fast_lines && stores_directly(ds) {
            // Aliased, and the fragment stage only stores the colour: its bytes, stored
            // directly (what the span function would store for the constant planes).
            let rgba = color4_to_u8(std::array::from_fn(|k| {
                p.get(attr::color(k)).map_or(0.0, |c| c.at(0.5, 0.5)) as f32
            }));
            line.fragments(ends, major, minor, line.major_clip(ds), |r, _, _, _| {
                let rect = clip(r).intersect(&tile.rect());
                if rect.is_empty() {
                    return;
                }
                for y in rect.y0..rect.y1 {
                    let at = tile.index(rect.x0, y);
                    tile.color[at..at + (rect.x1 - rect.x0) as usize].fill(rgba);
                }
            });
            return;
        }
        let covered = ds.fragment.span_covered;
        if covered.is_some() && self.coverage.len() < side * side {
            self.coverage.resize(side * side, 0.0);
        }
        let mut runs = [Run {
            x0: 0,
            x1: 0,
            full: true,
        }; MAX_SIDE];
        line.fragments(ends, major, minor, line.major_clip(ds), |r, _, _, cov| {
            let rect = clip(r).intersect(&tile.rect());
            if rect.is_empty() {
                return;
            }
            if cov != 1.0 && covered.is_none() {
                // An antialiased edge pixel alone with its coverage.
                shade_rect(ds, tile, self.levels, self.coarse, rect, z, p, cov);
                return;
            }
            for y in rect.y0..rect.y1 {
                let k = (y - tile.y0) as usize;
                let run = runs[k];
                if run.x0 < run.x1 && run.x1 == rect.x0 {
                    runs[k].x1 = rect.x1;
                    runs[k].full &= cov == 1.0;
                } else {
                    if run.x0 < run.x1 {
                        self.flush(tile, covered, y, run, z, p);
                    }
                    runs[k] = Run {
                        x0: rect.x0,
                        x1: rect.x1,
                        full: cov == 1.0,
                    };
                }
                if covered.is_some() {
                    let at = k * side + (rect.x0 - tile.x0) as usize;
                    let len = (rect.x1 - rect.x0) as usize;
                    self.coverage[at..at + len].fill(cov);
                }
            }
        });
        for (k, &run) in runs[..side].iter().enumerate() {
            if run.x0 < run.x1 {
                let y = tile.y0 + k as i32;
                self.flush(tile, covered, y, run, z, p);
            }
        }
    }

    /// Shades row `y`'s run `run` with depth `z` and attributes `attrs`: one span when it is
    /// fully covered, else through `covered` with the run's coverages.
    fn flush(
        &mut self,
        tile: &mut Tile,
        covered: Option<CoveredFn>,
        y: i32,
        run: Run,
        z: f64,
        attrs: &[Plane],
    ) {
        let rect = Rect {
            x0: run.x0,
            y0: y,
            x1: run.x1,
            y1: y + 1,
        };
        match covered {
            Some(f) if !run.full => {
                let ds = &self.ds.fragment;
                let shared = PrimitiveShared::new(self.levels);
                // As `shade_rect` sets up a rectangle (the coverage is the run's).
                let it = Interpolants {
                    z: Plane::constant(z),
                    inv_w: Plane::constant(1.0),
                    attrs,
                    perspective: false,
                    constant_primary: false,
                    coverage: 1.0,
                    shared: &shared,
                };
                if ds.key.depth_write {
                    self.coarse.forget(tile, rect);
                }
                let side = tile.side() as usize;
                let at = (y - tile.y0) as usize * side + (run.x0 - tile.x0) as usize;
                let coverage = &self.coverage[at..at + (run.x1 - run.x0) as usize];
                f(ds, tile, y, run.x0, coverage, &it);
            }
            _ => shade_rect(self.ds, tile, self.levels, self.coarse, rect, z, attrs, 1.0),
        }
    }
}

//! The rows of a flat affine primitive (a sprite: constant depth, 1/w, colours and fog, constant
//! q) on the eight-lane textured route, run by the pair function with what the rows share
//! prepared once per primitive instead of once per row: the level selection, the uniform
//! group, the depth function. Each row computes what [`shade_textured`] computes for it
//! (`constant_groups`), so the pixels are the same.

use super::*;

/// The rows of `pairs` in the order [`pair_by_rows`] takes them, through [`flat_row`] once the
/// primitive's shared level selection and uniform group are prepared (by the first row that
/// prepares them, as the row function would); rows before that, or all of them when the route
/// does not apply, go to the draw's row function. `unit` is the draw's first unit and `tail`
/// the draw's prepared tail (`UnitLevels::textured_tail`).
pub(super) fn flat_pairs<'a, const TEX: u8>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants<'a>,
    unit: &'a TextureUnitDraw,
    tail: &Tail8,
) {
    let mut flat: Option<Flat> = None;
    for &(y, rows) in pairs {
        for (r, (x0, x1)) in (0..).zip(rows) {
            if x0 >= x1 {
                continue;
            }
            let y = y + r;
            if flat.is_none() {
                flat = Flat::prepare(ds, y, x0, it, unit, tail);
            }
            match &flat {
                Some(f) => flat_row::<TEX>(ds, tile, y, x0, x1, it, f, tail),
                None => (ds.span)(ds, tile, y, x0, x1, it),
            }
        }
    }
}

/// What the rows of a flat affine primitive share.
struct Flat<'a> {
    unit: &'a TextureUnitDraw,
    /// Index of the unit's s plane.
    base: usize,
    affine: &'a AffineSpan<'a>,
    levels: &'a [Level8<'a>; 2],
    group: &'a GroupInputs,
    /// The primary colours as colour words, when the rows take the byte route
    /// (`simd::flat_groups_bytes`: `simd::bytes_apply` holds and every primary colour is a
    /// converted byte).
    bytes: Option<[u32; 8]>,
}

impl<'a> Flat<'a> {
    /// The shared level selection and uniform group as `shade_textured` prepares (or finds)
    /// them for row `y` from `x0` (`FastUnit::new`, `PrimitiveShared::steady`), when its
    /// constant route applies; then it applies to every row of the primitive (both are the
    /// primitive's from then on).
    #[inline(always)]
    fn prepare(
        ds: &'a FragmentDraw,
        y: i32,
        x0: i32,
        it: &Interpolants<'a>,
        unit: &'a TextureUnitDraw,
        tail: &Tail8,
    ) -> Option<Flat<'a>> {
        let yc = y as f64 + 0.5;
        let base = attr::TEX + 4 * unit.unit;
        let affine = FastUnit::affine(unit, it, base, x0 as f64 + 0.5, yc)?;
        let levels = affine.simd.as_ref()?;
        let colors = if ds.key.color_sum { 8 } else { 4 };
        let group = it
            .shared
            .steady
            .get_or_init(|| {
                SpanRun::new(it, x0, yc, colors)
                    .with_fog(ds)
                    .constant_group(ds)
            })
            .as_ref()?;
        let bytes = if simd::bytes_apply(tail, unit) {
            crate::fragment::bytenv::exact_word_array(&group.primary, 0xFF)
        } else {
            None
        };
        Some(Flat {
            unit,
            base,
            affine,
            levels,
            group,
            bytes,
        })
    }
}

/// Row `y`'s pixels `x0..x1` as `shade_textured`'s constant route shades them
/// (`constant_groups`), with the primitive's shared inputs `flat`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn flat_row<const TEX: u8>(
    ds: &FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants,
    flat: &Flat,
    tail: &Tail8,
) {
    let yc = y as f64 + 0.5;
    let (ps, pt) = (&it.attrs[flat.base], &it.attrs[flat.base + 1]);
    let by = [ps.b * yc, pt.b * yc];
    let affine = flat.affine;
    let sm = Sampling8 {
        planes: [[ps.a, by[0], ps.c], [pt.a, by[1], pt.c]],
        w: affine.w,
        q: affine.q,
        levels: flat.levels,
        linear: affine.linear,
        weight: affine.weight,
    };
    let c = flat.group;
    let row = tile.index(x0, y);
    let func = ds.key.depth_func;
    let depth_write = ds.key.depth_write;
    let d = c.depth[0];
    let mut dst = [0u32; 8];
    let mut gx = x0;
    while gx < x1 {
        if let Some(p) = &flat.bytes {
            // The byte route's groups, up to the first it leaves to the route below.
            gx = simd::flat_groups_bytes(
                &sm,
                tail,
                flat.unit,
                p,
                (func, d, depth_write),
                (gx, x0, x1, row),
                &mut tile.color,
                &mut tile.depth,
            );
            if gx >= x1 {
                break;
            }
        }
        let hi = ((x1 - gx) as usize).min(8);
        let at = row + (gx - x0) as usize;
        let whole = tile.color.len() >= at + 8;
        let pass = depth_lanes(func, d, &tile.depth, at, hi);
        let x = gx as f64 + 0.5;
        if pass != 0 && whole {
            // The eight colour words read and written in place by the kernel (lanes that
            // did not pass, those from `hi` included, get their own words back).
            let words: &mut [[u8; 4]; 8] = (&mut tile.color[at..at + 8]).try_into().unwrap();
            if let Some(passed) =
                simd::textured8_in_place(&sm, x, hi, tail, &c.primary, words, pass, &c.after)
            {
                if depth_write {
                    write_depths(&mut tile.depth, at, hi, passed, d);
                }
                gx += 8;
                continue;
            }
        }
        if pass != 0 {
            // Lanes from `hi` are not live: what they hold is not read.
            if whole {
                for (o, c) in dst.iter_mut().zip(&tile.color[at..at + 8]) {
                    *o = u32::from_le_bytes(*c);
                }
            } else {
                for (o, c) in dst.iter_mut().zip(&tile.color[at..at + hi]) {
                    *o = u32::from_le_bytes(*c);
                }
            }
            let shaded = simd::textured8(&sm, x, hi, tail, &c.primary, &dst, pass, &c.after)
                .or_else(|| {
                    let f = FastUnit {
                        unit: flat.unit,
                        base: flat.base,
                        modulate: flat.unit.env.mode == TexEnvMode::Modulate,
                        affine: Some(affine),
                        by,
                    };
                    let tex = if TEX == tex_mode::FAST_RGB {
                        f.texels_scalar::<3>(it, x, yc, hi)
                    } else {
                        f.texels_scalar::<4>(it, x, yc, hi)
                    };
                    simd::shade8(tail, &c.primary, &tex, &dst, pass, &c.after)
                });
            if let Some((words, passed)) = shaded {
                if hi == 8 {
                    for (o, w) in tile.color[at..at + 8].iter_mut().zip(&words) {
                        *o = w.to_le_bytes();
                    }
                } else {
                    for (o, w) in tile.color[at..at + hi].iter_mut().zip(&words) {
                        *o = w.to_le_bytes();
                    }
                }
                if depth_write {
                    write_depths(&mut tile.depth, at, hi, passed, d);
                }
            }
        }
        gx += 8;
    }
}

/// Depth `d` written to the lanes of `passed` among `0..hi` (pixels `at + j` of the tile's
/// depths).
#[inline(always)]
fn write_depths(depth: &mut [u32], at: usize, hi: usize, passed: u8, d: u32) {
    if passed == 0xFF {
        // (Every lane passed, so `hi` is 8.)
        depth[at..at + 8].fill(d);
    } else if passed != 0 {
        // Without a branch per lane: a lane that did not pass keeps its depth.
        for (j, o) in depth[at..at + hi].iter_mut().enumerate() {
            *o = if passed & (1 << j) != 0 { d } else { *o };
        }
    }
}

/// The lanes `0..hi` (pixels `at + j` of the tile's depths) where depth `d` passes `func`
/// against the stored depth (`depth_passes`, its function chosen once for the eight lanes).
#[inline(always)]
fn depth_lanes(func: Option<CompareFunc>, d: u32, depth: &[u32], at: usize, hi: usize) -> u8 {
    let live = ((1u32 << hi) - 1) as u8;
    let mut stored = [0u32; 8];
    if depth.len() >= at + 8 {
        // (Eight lanes read: the ones from `hi` are masked off below.)
        stored.copy_from_slice(&depth[at..at + 8]);
    } else {
        for (o, v) in stored.iter_mut().zip(&depth[at..at + hi]) {
            *o = *v;
        }
    }
    #[inline(always)]
    fn mask(stored: &[u32; 8], test: impl Fn(u32) -> bool) -> u8 {
        let mut m = 0u8;
        for (j, &s) in stored.iter().enumerate() {
            m |= u8::from(test(s)) << j;
        }
        m
    }
    let m = match func {
        None | Some(CompareFunc::Always) => 0xFF,
        Some(CompareFunc::Never) => 0,
        Some(CompareFunc::Less) => mask(&stored, |s| d < s),
        Some(CompareFunc::LessEqual) => mask(&stored, |s| d <= s),
        Some(CompareFunc::Equal) => mask(&stored, |s| d == s),
        Some(CompareFunc::NotEqual) => mask(&stored, |s| d != s),
        Some(CompareFunc::Greater) => mask(&stored, |s| d > s),
        Some(CompareFunc::GreaterEqual) => mask(&stored, |s| d >= s),
    };
    m & live
}

/// Whether the draw's row function is `span_textured` (`fragment/cache.rs` `select_span`) and
/// the primitive is aliased and unstippled (the stipple is a lane mask of `paths::blocks`'
/// 4x2 blocks, which the flat rows do not take): then its constant route is the one
/// [`flat_row`] takes.
#[inline(always)]
pub(super) fn flat_applies(ds: &FragmentDraw, it: &Interpolants) -> bool {
    let key = &ds.key;
    it.coverage == 1.0
        && it.shared.stipple.is_none()
        && key.stencil.is_none()
        && key.logic_op.is_none()
        && !key.count_samples
        && !key.alpha_to_coverage
        && !key.alpha_to_one
        && !depth_stencil_applies(key)
        && tail8_applies(key)
}

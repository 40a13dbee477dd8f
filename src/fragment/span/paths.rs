//! The span and row-pair functions `fragment/cache.rs` chooses from: the general path, its
//! monomorphised forms and the eight-lane paths.

use super::*;

/// The general path: every decision read from the key at run time.
pub fn span_general<'a>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    shade::<{ depth_mode::DYNAMIC }, false, false, false, false>(ds, tile, y, x0, x1, it)
}

/// The general path with every texture unit sampled eight pixels at a time (keys with
/// `simd_units`): the same texels, hence the same pictures.
pub fn span_sampled<'a>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    shade::<{ depth_mode::DYNAMIC }, false, false, true, false>(ds, tile, y, x0, x1, it)
}

/// The textured path: one unit on the fast 2D sampler (`TEX`), blending fixed by `BLEND`,
/// the colour mask by `FULL_MASK`; everything else read from the key (which must have
/// `fast_texture` of `TEX`'s layout, no stencil test and no logic op).
pub fn span_textured<'a, const TEX: u8, const BLEND: u8, const FULL_MASK: bool>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    shade_textured::<{ depth_mode::DYNAMIC }, FULL_MASK, false, TEX, BLEND>(ds, tile, y, x0, x1, it)
}

/// Two rows of a primitive: `y` (even) and `y + 1`, `rows[r]` the covered pixels `x0..x1`
/// of row `y + r` (empty when `x0 >= x1`; not both).
pub type RowPair = (i32, [(i32, i32); 2]);

/// Shades row pairs of one primitive in a tile (distinct rows: within a primitive no pixel is
/// covered twice, so their order does not matter). One call per primitive and tile, so that
/// what does not depend on the rows is prepared once (a tiny triangle has one to three pairs).
pub type PairFn = for<'a> fn(&'a FragmentDraw, &mut Tile, &[RowPair], &Interpolants<'a>);

/// The rows of the pairs one by one, by the draw's span function.
pub(super) fn pair_by_rows<'a>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants<'a>,
) {
    for &(y, rows) in pairs {
        for (r, (x0, x1)) in (0..).zip(rows) {
            if x0 < x1 {
                match it.shared.stipple {
                    None => (ds.span)(ds, tile, y + r, x0, x1, it),
                    Some(p) => span_stippled(ds, tile, y + r, x0, x1, it, p),
                }
            }
        }
    }
}

/// Runs the 4x2 blocks of a row pair (two whole quads each, from the even column at or left
/// of the first covered pixel): lanes 0..4 are columns `gx..gx + 4` of row `y`, lanes 4..8
/// the same columns of row `y + 1`. Each row's colour and depth are stepped from its own first
/// pixel and restarted at the same columns as on the row alone (`SpanRun`). `shade(gx,
/// group)` gets the covered lanes' inputs when one of them passes the depth and stencil tests
/// (the stencil actions done: [`stencil_lanes`]) and answers the colour words and the lanes
/// that passed every test, which are stored.
#[inline(always)]
pub(super) fn for_each_block(
    ds: &FragmentDraw,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants,
    shade: impl FnMut(i32, i32, &GroupInputs) -> Option<([u32; 8], u8)>,
) {
    shade_blocks(ds, tile, pairs, it, shade)
}

/// [`for_each_block`] with the blocks shaded by any [`BlockShade`].
#[inline(always)]
pub(super) fn shade_blocks(
    ds: &FragmentDraw,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants,
    mut shade: impl BlockShade,
) {
    #[cfg(target_arch = "x86_64")]
    if crate::common::cpu::available() {
        // SAFETY: AVX2 is present (checked just above).
        return unsafe { blocks_avx2(ds, tile, pairs, it, &mut shade) };
    }
    blocks_any(ds, tile, pairs, it, &mut shade)
}

/// [`blocks_any`] compiled for AVX2: the same operations (IEEE, no contraction into fused
/// multiply-adds: the same bits), with the eight-lane kernels it calls (`load_raw`, the
/// fused block kernels) inlined into the loop instead of called with every live register
/// spilled around them.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn blocks_avx2(
    ds: &FragmentDraw,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants,
    shade: &mut impl BlockShade,
) {
    // Unfogged draws step no fog coordinate; the rows' values are stepped as vectors where
    // they fit one (`lanes::vec::fits`).
    if lane_fog(ds).is_none() {
        blocks_vec::<false>(ds, tile, pairs, it, shade)
    } else if lanes::vec::fits::<true>(lane_colors(ds)) {
        blocks_vec::<true>(ds, tile, pairs, it, shade)
    } else {
        blocks::<true>(ds, tile, pairs, it, shade)
    }
}

/// [`blocks`] with each row's values stepped as one vector and the block's lanes
/// transposed into the group in registers (`lanes::vec`): the same values, so the same
/// pixels (`vector_blocks_are_the_recorded_blocks`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn blocks_vec<const FOG: bool>(
    ds: &FragmentDraw,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants,
    shade: &mut impl BlockShade,
) {
    use lanes::vec::{load_block, tile_row, VecRun};
    use std::arch::x86_64::*;
    let fog = if FOG { lane_fog(ds) } else { None };
    let colors = lane_colors(ds);
    let math = LaneMath::new(ds, it, FOG);
    let mut group = GroupInputs::EMPTY;
    let stride = tile.side() as usize;
    let stipple = it.shared.stipple;
    for &(y, rows) in pairs {
        let covered = |r: usize| rows[r].0 < rows[r].1;
        let (first, end) = match (covered(0), covered(1)) {
            (true, true) => (rows[0].0.min(rows[1].0), rows[0].1.max(rows[1].1)),
            (true, false) => rows[0],
            (false, true) => rows[1],
            (false, false) => continue,
        };
        let stipple_rows = stipple.map(|p| [stipple_row(p, y), stipple_row(p, y + 1)]);
        let run = |r: usize| {
            // SAFETY: AVX2 is present (this function's feature).
            unsafe { VecRun::new::<FOG>(it, rows[r].0, y as f64 + 0.5 + r as f64, colors) }
        };
        let [mut run0, mut run1] = [run(0), run(1)];
        let mut gx = first & !1;
        while gx < end {
            // Lanes 4r..4r + 4 are pixels row0 + r * stride + j.
            let row0 = tile.index(gx, y);
            let lo0 = (rows[0].0 - gx).clamp(0, 4) as usize;
            let hi0 = (rows[0].1 - gx).clamp(0, 4) as usize;
            let lo1 = (rows[1].0 - gx).clamp(0, 4) as usize;
            let hi1 = (rows[1].1 - gx).clamp(0, 4) as usize;
            let bits = |lo: usize, hi: usize| ((1u32 << hi) - (1u32 << lo)) as u8;
            // SAFETY (both rows): AVX2 is present (this function's feature).
            let (values0, z0, stored0, dst0, live0) = if lo0 < hi0 {
                let (v, z) = unsafe { run0.row(lo0, hi0) };
                let (s, d) = unsafe { tile_row(tile, row0, lo0, hi0) };
                (v, z, s, d, bits(lo0, hi0))
            } else {
                let v = _mm256_setzero_ps();
                let z = _mm256_setzero_pd();
                let s = _mm_setzero_si128();
                ([v; 4], z, s, s, 0)
            };
            let (values1, z1, stored1, dst1, live1) = if lo1 < hi1 {
                let (v, z) = unsafe { run1.row(lo1, hi1) };
                let (s, d) = unsafe { tile_row(tile, row0 + stride, lo1, hi1) };
                (v, z, s, d, bits(lo1, hi1))
            } else {
                let v = _mm256_setzero_ps();
                let z = _mm256_setzero_pd();
                let s = _mm_setzero_si128();
                ([v; 4], z, s, s, 0)
            };
            let live = live0 | (live1 << 4);
            if live == 0 {
                gx += 4;
                continue;
            }
            // SAFETY: AVX2 is present (this function's feature).
            unsafe {
                let stored = _mm256_set_m128i(stored1, stored0);
                let dst = _mm256_set_m128i(dst1, dst0);
                let values = [values0, values1];
                load_block::<FOG>(&mut group, &values, [z0, z1], stored, dst, live, &math)
            };
            finish_block(
                ds,
                tile,
                (y, gx),
                row0,
                live,
                &mut group,
                fog,
                stipple_rows,
                shade,
            );
            gx += 4;
        }
    }
}

/// A block's stipple, stencil test, shading and stores once its group is loaded (`live`:
/// its covered lanes, lane `4r + j` being pixel `row0 + r * side + j` of `tile`).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn finish_block(
    ds: &FragmentDraw,
    tile: &mut Tile,
    (y, gx): (i32, i32),
    row0: usize,
    mut live: u8,
    group: &mut GroupInputs,
    fog: Option<&FogDraw>,
    stipple_rows: Option<[u32; 2]>,
    shade: &mut impl BlockShade,
) {
    if let Some(rows) = stipple_rows {
        // The stipple discards lanes before any per-fragment operation.
        let keep = stipple_block(rows, gx);
        live &= keep;
        group.pass &= keep;
    }
    if ds.key.stencil.is_some() {
        group.pass = block_stencil(ds, tile, gx, y, live, group.pass);
    }
    if group.pass != 0 {
        group.fog_factors(fog);
        if let Some((words, passed)) = shade.shade(y, gx, group) {
            let stride = tile.side() as usize;
            write_rows(ds, tile, row0, stride, live, &words, passed, &group.depth);
        }
    }
}

/// [`for_each_block`] on any processor: fogged or not.
#[inline(always)]
fn blocks_any(
    ds: &FragmentDraw,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants,
    shade: &mut impl BlockShade,
) {
    // Unfogged draws step no fog coordinate.
    if lane_fog(ds).is_some() {
        blocks::<true>(ds, tile, pairs, it, shade)
    } else {
        blocks::<false>(ds, tile, pairs, it, shade)
    }
}

/// [`for_each_block`] for a fogged draw (`FOG`) or not.
#[inline(always)]
pub(super) fn blocks<const FOG: bool>(
    ds: &FragmentDraw,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants,
    shade: &mut impl BlockShade,
) {
    let fog = if FOG { lane_fog(ds) } else { None };
    let colors = lane_colors(ds);
    // Each lane's stepped values are recorded as the runs step them; the per-pixel arithmetic
    // of `SpanRun::next` (w, the products by it, the depth) and the depth test then run on the
    // eight lanes at once (`GroupInputs::load_raw`: the same values). A constant primary
    // colour (`Interpolants::constant_primary`) is not recorded.
    let math = LaneMath::new(ds, it, FOG);
    let reads = math.reads();
    let mut group = GroupInputs::EMPTY;
    let mut raw = RawLanes::default();
    let stride = tile.side() as usize;
    let stipple = it.shared.stipple;
    for &(y, rows) in pairs {
        let stipple_rows = stipple.map(|p| [stipple_row(p, y), stipple_row(p, y + 1)]);
        let mut runs = [
            SpanRun::new(it, rows[0].0, y as f64 + 0.5, colors),
            SpanRun::new(it, rows[1].0, y as f64 + 1.5, colors),
        ];
        if FOG {
            for run in &mut runs {
                run.fog_on();
            }
        }
        let covered = |r: usize| rows[r].0 < rows[r].1;
        let (first, end) = match (covered(0), covered(1)) {
            (true, true) => (rows[0].0.min(rows[1].0), rows[0].1.max(rows[1].1)),
            (true, false) => rows[0],
            (false, true) => rows[1],
            (false, false) => continue,
        };
        let mut gx = first & !1;
        while gx < end {
            // Lanes 4r..4r + 4 are pixels row0 + r * stride + j.
            let row0 = tile.index(gx, y);
            let [run0, run1] = &mut runs;
            let mut live = block_row::<FOG, 0>(run0, rows[0], gx, tile, row0, &mut raw, reads);
            live |= block_row::<FOG, 1>(run1, rows[1], gx, tile, row0 + stride, &mut raw, reads);
            if live == 0 {
                gx += 4;
                continue;
            }
            group.load_raw(&raw, live, &math);
            finish_block(
                ds,
                tile,
                (y, gx),
                row0,
                live,
                &mut group,
                fog,
                stipple_rows,
                shade,
            );
            gx += 4;
        }
    }
}

/// Row `R` (0 or 1) of the 4x2 block at column `gx`: the run `run` of the row, whose
/// covered pixels are `x0..x1`, recorded into lanes `4R + j` of `raw` for the columns of the
/// block it covers (a whole row of four unrolled: [`SpanRun::record4`], or lane by lane
/// around a restart column) with the stored depths and colours of pixels `row + j`
/// ([`read_row`]). Answers the row's covered lanes.
#[inline(always)]
fn block_row<const FOG: bool, const R: usize>(
    run: &mut SpanRun,
    (x0, x1): (i32, i32),
    gx: i32,
    tile: &Tile,
    row: usize,
    raw: &mut RawLanes,
    reads: Reads,
) -> u8 {
    let lo = (x0 - gx).clamp(0, 4) as usize;
    let hi = (x1 - gx).clamp(0, 4) as usize;
    if lo >= hi {
        return 0;
    }
    if lo == 0 && hi == 4 {
        if !run.record4::<FOG, R>(raw, reads) {
            // A restart column among the four: the same moves one by one (unrolled).
            for j in 0..4 {
                run.record::<FOG>(raw, 4 * R + j, reads.primary);
                run.advance::<FOG>();
            }
        }
        read_row::<R>(tile, row, 0, 4, raw);
        return 0xF << (4 * R);
    }
    for j in lo..hi {
        run.record::<FOG>(raw, 4 * R + j, reads.primary);
        run.advance::<FOG>();
    }
    read_row::<R>(tile, row, lo, hi, raw);
    (((1u32 << hi) - (1u32 << lo)) as u8) << (4 * R)
}

/// The stored depths and colour words of columns `lo..hi` (within 0..4) of a block's row
/// `R` starting at pixel `row` of `tile`, into lanes `4R + j` of `raw`: the four columns at
/// once where they lie in the tile's buffers (columns outside `lo..hi` are then read too and
/// not used), else one by one.
#[inline(always)]
fn read_row<const R: usize>(tile: &Tile, row: usize, lo: usize, hi: usize, raw: &mut RawLanes) {
    let lanes = 4 * R..4 * R + 4;
    if let (Some(depth), Some(color)) = (tile.depth.get(row..row + 4), tile.color.get(row..row + 4))
    {
        raw.stored[lanes.clone()].copy_from_slice(depth);
        // Colour words are the stored bytes in memory order (R in the low byte): one copy.
        bytemuck::cast_slice_mut::<u32, [u8; 4]>(&mut raw.dst[lanes]).copy_from_slice(color);
        return;
    }
    for j in lo..hi {
        raw.stored[4 * R + j] = tile.depth[row + j];
        raw.dst[4 * R + j] = u32::from_le_bytes(tile.color[row + j]);
    }
}

/// Stores a block's colour words for the `live` lanes (lane `4r + j` is pixel
/// `row0 + r * stride + j`; the words of lanes that did not pass are the stored ones), and
/// with depth writes the depths of the lanes of `passed`: a whole row of four at once.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn write_rows(
    ds: &FragmentDraw,
    tile: &mut Tile,
    row0: usize,
    stride: usize,
    live: u8,
    words: &[u32; 8],
    passed: u8,
    depth: &[u32; 8],
) {
    let depth_write = ds.key.depth_write;
    write_row::<0>(ds, tile, row0, live, words, passed, depth, depth_write);
    write_row::<1>(
        ds,
        tile,
        row0 + stride,
        live,
        words,
        passed,
        depth,
        depth_write,
    );
}

/// [`write_rows`] for row `R` of the block, starting at pixel `row`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn write_row<const R: usize>(
    ds: &FragmentDraw,
    tile: &mut Tile,
    row: usize,
    live: u8,
    words: &[u32; 8],
    passed: u8,
    depth: &[u32; 8],
    depth_write: bool,
) {
    let row_live = (live >> (4 * R)) & 0xF;
    if row_live == 0 {
        return;
    }
    let row_passed = (passed >> (4 * R)) & 0xF;
    let lanes = 4 * R..4 * R + 4;
    if row_live == 0xF {
        if let (Some(color), Some(d)) = (
            tile.color.get_mut(row..row + 4),
            tile.depth.get_mut(row..row + 4),
        ) {
            // Colour words are the stored bytes in memory order: one copy.
            color.copy_from_slice(bytemuck::cast_slice::<u32, [u8; 4]>(&words[lanes.clone()]));
            if depth_write {
                if row_passed == 0xF {
                    d.copy_from_slice(&depth[lanes]);
                } else {
                    for (j, (old, &new)) in d.iter_mut().zip(&depth[lanes]).enumerate() {
                        if row_passed & (1 << j) != 0 {
                            *old = new;
                        }
                    }
                }
            }
            return;
        }
    }
    for j in 0..4 {
        if row_live & (1 << j) != 0 {
            store_lane(ds, tile, 4 * R + j, row + j, words, passed, depth);
        }
    }
}

/// [`stencil_lanes`] for the live lanes of the 4x2 block at column `gx` of the row pair from
/// `y` (kept out of the block loop, which draws without stencil far more often).
#[inline(never)]
fn block_stencil(ds: &FragmentDraw, tile: &mut Tile, gx: i32, y: i32, live: u8, pass: u8) -> u8 {
    // Live lanes lie in the tile: pixel (gx + lane % 4, y + lane / 4).
    let row0 = tile.index(gx, y);
    stencil_block(ds, tile, row0, live, pass)
}

/// Window centre of lane `lane` of the block at column `gx` of the row pair from `y`.
#[inline(always)]
pub(super) fn block_lane_centre(gx: i32, y: i32, lane: usize) -> (f64, f64) {
    let lane = lane as i32;
    ((gx + lane % 4) as f64 + 0.5, (y + lane / 4) as f64 + 0.5)
}

/// `span_textured`'s eight-lane perspective path on two rows at once, in 4x2 blocks (two
/// whole quads): the spans of small triangles are two or three pixels long, so a block holds
/// about as many fragments as two eight-pixel row groups, and its texture coordinates give
/// the quads' derivatives without evaluating other rows. Every value is computed as on the
/// rows one by one (`for_each_block`, texels by `Perspective8::texels_block`), so the
/// pixels are the same; affine primitives and keys without the eight-lane tail take the rows
/// one by one.
pub fn pair_textured<'a, const TEX: u8>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants<'a>,
) {
    let (Some(unit), Some(&(first_y, _))) = (ds.units.first(), pairs.first()) else {
        return pair_by_rows(ds, tile, pairs, it);
    };
    let q = &it.attrs[attr::TEX + 4 * unit.unit + 3];
    // Constant 1/w and q: the affine path of the rows (`FastUnit::affine`).
    let affine = it.inv_w.a == 0.0 && it.inv_w.b == 0.0 && q.a == 0.0 && q.b == 0.0;
    // The tail (prepared with the levels) exists where the eight-fragment tail applies.
    let tail = it.shared.levels.textured_tail;
    // A flat sprite's rows with what they share prepared once (`flat.rs`).
    if let (true, Some(t)) = (affine && flat_applies(ds, it), &tail) {
        return flat_pairs::<TEX>(ds, tile, pairs, it, unit, t);
    }
    let sampler = match tail {
        Some(_) if !affine && it.coverage == 1.0 => Perspective8::block(unit, 0, it, first_y),
        _ => None,
    };
    let (Some(sampler), Some(tail)) = (sampler, tail) else {
        return pair_by_rows(ds, tile, pairs, it);
    };
    let shader = TexturedBlocks::<TEX> {
        unit,
        it,
        sampler,
        sampler_y: first_y,
        tail,
    };
    shade_blocks(ds, tile, pairs, it, shader);
}

/// What [`for_each_block`] asks of a block: its colour words and passing lanes from its
/// inputs ([`for_each_block`]'s `shade`), given the block's row pair `y` and column `gx`.
pub(super) trait BlockShade {
    fn shade(&mut self, y: i32, gx: i32, group: &GroupInputs) -> Option<([u32; 8], u8)>;
}

impl<F: FnMut(i32, i32, &GroupInputs) -> Option<([u32; 8], u8)>> BlockShade for F {
    #[inline(always)]
    fn shade(&mut self, y: i32, gx: i32, group: &GroupInputs) -> Option<([u32; 8], u8)> {
        self(y, gx, group)
    }
}

/// [`pair_textured`]'s blocks: the unit's block sampler on the current row pair and the tail.
/// (A type, not a closure, so that its method can be inlined into the block loop.)
struct TexturedBlocks<'a, 'i, const TEX: u8> {
    unit: &'a TextureUnitDraw,
    it: &'i Interpolants<'a>,
    sampler: Perspective8<'a>,
    sampler_y: i32,
    tail: Tail8,
}

impl<const TEX: u8> BlockShade for TexturedBlocks<'_, '_, TEX> {
    #[inline(always)]
    fn shade(&mut self, y: i32, gx: i32, group: &GroupInputs) -> Option<([u32; 8], u8)> {
        if y != self.sampler_y {
            // The same unit and levels as the first pair's: only the rows' planes move.
            if let Some(s) = Perspective8::block(self.unit, 0, self.it, y) {
                self.sampler = s;
            }
            self.sampler_y = y;
        }
        if let Some(shaded) = self
            .sampler
            .shaded_block(gx as f64 + 0.5, group, &self.tail)
        {
            return Some(shaded);
        }
        textured_block_slow::<TEX>(self.unit, self.it, &self.sampler, &self.tail, y, gx, group)
    }
}

/// [`pair_textured`]'s block where the fused kernel does not take it (kept out of the block
/// loop, so that the loop's closure stays small): the texels by
/// [`Perspective8::texels_block`], else one by one as the rows' fallback samples them, then
/// the eight-fragment tail.
#[inline(never)]
fn textured_block_slow<'a, const TEX: u8>(
    unit: &'a TextureUnitDraw,
    it: &Interpolants<'a>,
    sampler: &Perspective8,
    tail: &Tail8,
    y: i32,
    gx: i32,
    group: &GroupInputs,
) -> Option<([u32; 8], u8)> {
    let mut tex = [[0f32; 8]; 4];
    if !sampler.texels_block(gx as f64 + 0.5, group.pass, &mut tex) {
        // Not affine: the fast unit samples one by one as the rows' fallback does.
        let f = FastUnit::new(unit, it, 0.5, y as f64 + 0.5);
        for lane in (0..8).filter(|j| group.pass & (1 << j) != 0) {
            let (x, yc) = block_lane_centre(gx, y, lane);
            let t = if TEX == tex_mode::FAST_RGB {
                f.texel::<3>(it, x, yc)
            } else {
                f.texel::<4>(it, x, yc)
            };
            for c in 0..4 {
                tex[c][lane] = t[c];
            }
        }
    }
    simd::shade8(
        tail,
        &group.primary,
        &tex,
        &group.dst,
        group.pass,
        &group.after,
    )
}

/// [`span_sampled8`] on two rows at once, in 4x2 blocks (`for_each_block`): every unit
/// sampled by its block sampler (`Perspective8::texels_block`; one by one where it does not
/// apply), the cascade, then the eight-fragment tail. The same pixels as the rows one by one.
pub fn pair_sampled8<'a>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants<'a>,
) {
    let Some(&(first_y, _)) = pairs.first() else {
        return;
    };
    if it.coverage != 1.0 {
        return pair_by_rows(ds, tile, pairs, it);
    }
    #[cfg(target_arch = "x86_64")]
    if !ds.key.byte_env {
        let (single, tail) = sampled8_tail(ds);
        if let Some(fused) = fused_unit(ds, single) {
            return pair_fused(ds, tile, pairs, it, fused, single, &tail);
        }
    }
    let s = Sampled8::new(ds, it, first_y, true);
    let byte_env = ds.key.byte_env && crate::common::cpu::available();
    // A constant primary colour (every lane's in every block, `LaneMath::constant`) is
    // converted to bytes once for the primitive; one that is not converted bytes keeps the
    // primitive off the byte route (`byte_block` would answer `None` at every block).
    #[cfg(target_arch = "x86_64")]
    let mut constant_words = None;
    #[cfg(target_arch = "x86_64")]
    let mut byte_env = byte_env;
    #[cfg(target_arch = "x86_64")]
    if let (true, Some(c)) = (byte_env, constant_primary(it)) {
        // SAFETY: AVX2 is present (`byte_env` checked it).
        constant_words = unsafe { crate::fragment::bytenv::exact_words(&c.map(|v| [v; 8]), 0xFF) };
        byte_env = constant_words.is_some();
    }
    let mut blocks = SampledBlocks::<{ sampled_route::GENERAL }> {
        ds,
        it,
        fused: fused_unit(ds, s.single),
        s,
        samplers_y: first_y,
        ready: false,
        // A cascade of `GL_COMBINE` units in straight-line form (`cascade::Chain`), every
        // unit on a 2D texture's block sampler: blocks in one go (`chain_block`).
        chain: chain_of(ds),
        program: program_of(ds),
        byte_env,
        #[cfg(target_arch = "x86_64")]
        constant_words,
    };
    blocks.ready = blocks.all_2d();
    // The route the blocks try first, fixed for the primitive so that the block loop holds
    // only its kernel (the others, and the general route, are out of line).
    if blocks.chain.is_some() {
        shade_blocks(
            ds,
            tile,
            pairs,
            it,
            blocks.route::<{ sampled_route::CHAIN }>(),
        );
    } else if blocks.byte_env {
        shade_blocks(
            ds,
            tile,
            pairs,
            it,
            blocks.route::<{ sampled_route::BYTES }>(),
        );
    } else if blocks.program.is_some() {
        shade_blocks(
            ds,
            tile,
            pairs,
            it,
            blocks.route::<{ sampled_route::PROGRAM }>(),
        );
    } else {
        shade_blocks(ds, tile, pairs, it, blocks);
    }
}

/// The block routes of [`SampledBlocks`]: which kernel a primitive's blocks try first.
mod sampled_route {
    /// The general block route (each unit's `texels_block`, then `sampled8_shade`).
    pub const GENERAL: u8 = 0;
    /// `chain_block`.
    pub const CHAIN: u8 = 1;
    /// `byte_block`.
    pub const BYTES: u8 = 2;
    /// `program_block`.
    pub const PROGRAM: u8 = 3;
}

/// How [`program_block`] runs a draw's cascade on registers: every unit `MODULATE` (the
/// products of `environment8`'s MODULATE form), or the compiled program.
#[derive(Clone, Copy)]
enum Cascade8<'a> {
    Modulate,
    Program(&'a crate::fragment::cascade::Program),
}

/// The cascade form of [`program_block`] for a draw of two units or more with AVX2, as
/// `environment8` chooses it (every unit `MODULATE` first, else the compiled program).
fn program_of(ds: &FragmentDraw) -> Option<Cascade8<'_>> {
    if ds.units.len() < 2 || !crate::common::cpu::available() {
        return None;
    }
    if ds.units.iter().all(|u| u.env.mode == TexEnvMode::Modulate) {
        return Some(Cascade8::Modulate);
    }
    ds.cascade.as_ref().map(Cascade8::Program)
}

/// [`pair_sampled8`]'s blocks (a type, not a closure, so that the block loop holds only the
/// primitive's route, `ROUTE` of [`sampled_route`], with the rest out of line in
/// [`SampledBlocks::slow`]): each unit's block sampler on the current row pair, the tail and
/// what the routes need.
struct SampledBlocks<'a, 'i, const ROUTE: u8> {
    ds: &'a FragmentDraw,
    it: &'i Interpolants<'a>,
    s: Sampled8<'a>,
    samplers_y: i32,
    /// Every unit's sampler of the row pair is present and 2D (`chain_block` and
    /// `program_block` take them).
    ready: bool,
    fused: Option<Fused<'a>>,
    chain: Option<&'a crate::fragment::cascade::Chain>,
    program: Option<Cascade8<'a>>,
    byte_env: bool,
    #[cfg(target_arch = "x86_64")]
    constant_words: Option<std::arch::x86_64::__m256i>,
}

impl<'a, 'i, const ROUTE: u8> SampledBlocks<'a, 'i, ROUTE> {
    /// The same blocks on route `R`.
    #[inline(always)]
    fn route<const R: u8>(self) -> SampledBlocks<'a, 'i, R> {
        SampledBlocks {
            ds: self.ds,
            it: self.it,
            s: self.s,
            samplers_y: self.samplers_y,
            ready: self.ready,
            fused: self.fused,
            chain: self.chain,
            program: self.program,
            byte_env: self.byte_env,
            #[cfg(target_arch = "x86_64")]
            constant_words: self.constant_words,
        }
    }

    /// Whether every unit's sampler is present and 2D.
    #[inline(always)]
    fn all_2d(&self) -> bool {
        self.s.samplers[..self.ds.units.len()]
            .iter()
            .all(|s| s.as_ref().is_some_and(|s| s.cube.is_none()))
    }

    /// A block that the route's kernel did not take (kept out of the block loop): the other
    /// block kernels that apply, else each unit's texels by `texels_block` (one by one where
    /// it does not apply) and [`sampled8_shade`]. The same pixels as the rows one by one.
    #[inline(never)]
    fn slow(&mut self, y: i32, gx: i32, group: &GroupInputs) -> Option<([u32; 8], u8)> {
        let ds = self.ds;
        #[cfg(target_arch = "x86_64")]
        if let (Some(fused), Some(sampler)) = (self.fused, &self.s.samplers[0]) {
            // SAFETY: AVX2 is present (`fused_unit` checked it).
            if let Some(done) = unsafe { fused_block(fused, sampler, &self.s.tail, gx, group) } {
                return Some(done);
            }
        }
        #[cfg(target_arch = "x86_64")]
        if let (true, Some(program)) = (ROUTE != sampled_route::PROGRAM && self.ready, self.program)
        {
            let n = ds.units.len();
            // SAFETY: AVX2 is present (`program_of` checked it).
            if let Some(done) = unsafe {
                program_block(ds, program, &self.s.samplers[..n], &self.s.tail, gx, group)
            } {
                return Some(done);
            }
        }
        let it = self.it;
        for (k, unit) in ds.units.iter().enumerate() {
            let Some(out) = self.s.by_unit[unit.unit].as_mut() else {
                continue;
            };
            if self.s.samplers[k]
                .as_ref()
                .is_some_and(|p| p.texels_block(gx as f64 + 0.5, group.pass, out))
            {
                continue;
            }
            for lane in (0..8).filter(|j| group.pass & (1 << j) != 0) {
                let (x, yc) = block_lane_centre(gx, y, lane);
                let t = unit_texel(unit, it, x, yc);
                for c in 0..4 {
                    out[c][lane] = t[c];
                }
            }
        }
        sampled8_shade(ds, self.s.single, &self.s.tail, group, &self.s.by_unit)
    }
}

impl<const ROUTE: u8> BlockShade for SampledBlocks<'_, '_, ROUTE> {
    #[inline(always)]
    fn shade(&mut self, y: i32, gx: i32, group: &GroupInputs) -> Option<([u32; 8], u8)> {
        if y != self.samplers_y {
            Sampled8::place_samplers(&mut self.s.samplers, self.ds, self.it, y, true);
            self.samplers_y = y;
            self.ready = self.all_2d();
        }
        #[cfg(target_arch = "x86_64")]
        {
            let n = self.ds.units.len();
            if ROUTE == sampled_route::CHAIN && self.ready {
                if let Some(chain) = self.chain {
                    // SAFETY: AVX2 is present (`chain_of` checked it).
                    let done = unsafe {
                        chain_block(chain, &self.s.samplers[..n], &self.s.tail, gx, group)
                    };
                    if done.is_some() {
                        return done;
                    }
                }
            }
            if ROUTE == sampled_route::BYTES {
                // SAFETY: AVX2 is present (`byte_env` checked it).
                let done = unsafe {
                    byte_block(
                        self.ds,
                        &self.s.samplers,
                        &self.s.tail,
                        gx,
                        group,
                        self.constant_words,
                    )
                };
                if done.is_some() {
                    return done;
                }
            }
            if ROUTE == sampled_route::PROGRAM && self.ready {
                if let Some(program) = self.program {
                    // SAFETY: AVX2 is present (`program_of` checked it).
                    let done = unsafe {
                        program_block(
                            self.ds,
                            program,
                            &self.s.samplers[..n],
                            &self.s.tail,
                            gx,
                            group,
                        )
                    };
                    if done.is_some() {
                        return done;
                    }
                }
            }
        }
        self.slow(y, gx, group)
    }
}

/// A block of a draw of two units or more ([`program_of`]) with every unit's texels in
/// registers: each unit's texels as `texels_block` filters them (`block_words8`), the
/// cascade as `environment8` runs it (the MODULATE products, or `Program::run_regs`: the
/// bits of `Program::run_avx2`) and the tail with the result as a replacing texel, as
/// `sampled8_shade` runs them; texels the program does not read are not sampled. `None`
/// (the caller takes the general block route: the same pixels) where a unit's block filter
/// does not take the block. `samplers`: the draw's units' samplers, every one present and 2D.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn program_block(
    ds: &FragmentDraw,
    cascade: Cascade8,
    samplers: &[Option<Perspective8>],
    tail: &Tail8,
    gx: i32,
    group: &GroupInputs,
) -> Option<([u32; 8], u8)> {
    use std::arch::x86_64::*;
    use texture_simd::x86::{block_words8, texels_of_words};
    let x = gx as f64 + 0.5;
    let zero = _mm256_setzero_ps();
    let texels = |k: usize| -> Option<[__m256; 4]> {
        let s = samplers.get(k)?.as_ref()?;
        Some(
            match block_words8(&s.planes, x, group.pass, s.fixed_plan, s.lod, s.levels)? {
                (words, Some(level)) => texels_of_words(level, words),
                (_, None) => [zero; 4],
            },
        )
    };
    let color = match cascade {
        Cascade8::Modulate => {
            // `modulate8_avx2`: the clamped primary colour times each unit's texel where its
            // base format has colour and alpha, unit after unit.
            let (one, mut color) = (_mm256_set1_ps(1.0), [zero; 4]);
            for (c, v) in color.iter_mut().enumerate() {
                // SAFETY: eight f32; unaligned load.
                let p = unsafe { _mm256_loadu_ps(group.primary[c].as_ptr()) };
                // As `clamp01`: max_ps answers 0 for NaN.
                *v = _mm256_min_ps(_mm256_max_ps(p, zero), one);
            }
            for (k, u) in ds.units.iter().enumerate() {
                let t = texels(k)?;
                let (has_color, has_alpha) = crate::fragment::bytenv::has_color_alpha(u.base);
                if has_color {
                    for c in 0..3 {
                        color[c] = _mm256_mul_ps(color[c], t[c]);
                    }
                }
                if has_alpha {
                    color[3] = _mm256_mul_ps(color[3], t[3]);
                }
            }
            color
        }
        Cascade8::Program(program) => {
            let mut regs = [[zero; 4]; MAX_TEXTURE_UNITS];
            let mut n = 0;
            for (slot, unit) in regs.iter_mut().zip(program.texel_units()) {
                let k = ds.units.iter().position(|u| u.unit == unit)?;
                *slot = texels(k)?;
                n += 1;
            }
            program.run_regs(&group.primary, &regs[..n])
        }
    };
    // The tail of a cascade of two units or more (no `modulate`, `rgb_from_primary` or
    // `alpha_from_primary`) reads no primary colour.
    Some(simd::shade8_regs(
        tail,
        &group.primary,
        &color,
        &group.dst,
        group.pass,
        &group.after,
    ))
}

/// How [`pair_sampled8`] shades the blocks of a one-unit draw in one go ([`fused_block`]):
/// the texels left in registers, then the tail (one REPLACE or MODULATE unit, as
/// `pair_textured`'s blocks) or the compiled cascade and the tail.
#[derive(Clone, Copy)]
enum Fused<'a> {
    Tail,
    Program(&'a crate::fragment::cascade::Program),
}

/// The fused form of a draw's blocks: one unit on a 2D texture (a cube map's sampler does
/// not take it), AVX2 present; `None` for the other draws (the general block route).
fn fused_unit(ds: &FragmentDraw, single: SingleUnit) -> Option<Fused<'_>> {
    if ds.units.len() != 1 || !crate::common::cpu::available() {
        return None;
    }
    match (single, &ds.cascade) {
        (Some(_), _) => Some(Fused::Tail),
        // Only the unit's own texel is read (a crossbar source of an absent unit reads
        // the incoming colour: `Program::new` resolved it).
        (None, Some(p)) if p.texel_units().all(|u| u == ds.units[0].unit) => {
            Some(Fused::Program(p))
        }
        _ => None,
    }
}

/// [`pair_sampled8`] for a one-unit draw with a fused form ([`fused_unit`]) and without the
/// byte environment: the unit's block sampler alone (not the eight-unit arrays), each block
/// by [`fused_block`], else by the general block route (the unit's texels, then
/// [`sampled8_shade`]). The same pixels.
#[cfg(target_arch = "x86_64")]
#[allow(clippy::too_many_arguments)]
fn pair_fused<'a>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants<'a>,
    fused: Fused,
    single: SingleUnit,
    tail: &Tail8,
) {
    let (Some(unit), Some(&(first_y, _))) = (ds.units.first(), pairs.first()) else {
        return;
    };
    let mut sampler = Perspective8::block(unit, 0, it, first_y);
    let mut sampler_y = first_y;
    for_each_block(ds, tile, pairs, it, |y, gx, group| {
        if y != sampler_y {
            sampler = Perspective8::block(unit, 0, it, y);
            sampler_y = y;
        }
        if let Some(s) = &sampler {
            // SAFETY: AVX2 is present (`fused_unit` checked it).
            if let Some(done) = unsafe { fused_block(fused, s, tail, gx, group) } {
                return Some(done);
            }
        }
        let mut out = [[0f32; 8]; 4];
        let x = gx as f64 + 0.5;
        if !sampler
            .as_ref()
            .is_some_and(|p| p.texels_block(x, group.pass, &mut out))
        {
            for lane in (0..8).filter(|j| group.pass & (1 << j) != 0) {
                let (x, yc) = block_lane_centre(gx, y, lane);
                let t = unit_texel(unit, it, x, yc);
                for c in 0..4 {
                    out[c][lane] = t[c];
                }
            }
        }
        let mut by_unit = [None; MAX_TEXTURE_UNITS];
        by_unit[unit.unit] = Some(out);
        sampled8_shade(ds, single, tail, group, &by_unit)
    });
}

/// A block of a one-unit draw ([`fused_unit`]) with the texels in registers: the same
/// colour words as the general block route (`texels_block`, then `sampled8_shade`: the same
/// filter, the same cascade operations, the same tail). `None` (the caller takes the general
/// route) for a cube map or where the block filter does not take the block.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn fused_block(
    fused: Fused,
    sampler: &Perspective8,
    tail: &Tail8,
    gx: i32,
    group: &GroupInputs,
) -> Option<([u32; 8], u8)> {
    if sampler.cube.is_some() {
        return fused_cube_block(fused, sampler, tail, gx, group);
    }
    let x = gx as f64 + 0.5;
    match fused {
        Fused::Tail => simd::block_shaded8(
            &sampler.planes,
            x,
            group.pass,
            sampler.fixed_plan,
            sampler.lod,
            sampler.levels,
            tail,
            &group.primary,
            &group.dst,
            &group.after,
        ),
        Fused::Program(program) => simd::block_combined8(
            &sampler.planes,
            x,
            group.pass,
            sampler.fixed_plan,
            sampler.lod,
            sampler.levels,
            program,
            tail,
            &group.primary,
            &group.dst,
            &group.after,
        ),
    }
}

/// [`fused_block`] for a cube map with a fixed level plan: its texels in registers
/// (`cube_block_regs`, the texels `texels_block` gives), then the tail or the program on
/// them. Out of line, so that the 2D blocks' code in `fused_block` stays as it was.
#[cfg(target_arch = "x86_64")]
#[inline(never)]
#[target_feature(enable = "avx2")]
fn fused_cube_block(
    fused: Fused,
    sampler: &Perspective8,
    tail: &Tail8,
    gx: i32,
    group: &GroupInputs,
) -> Option<([u32; 8], u8)> {
    let x = gx as f64 + 0.5;
    let tex = sampler.cube_block_regs(x, group.pass)?;
    Some(match fused {
        Fused::Tail => simd::shade8_regs(
            tail,
            &group.primary,
            &tex,
            &group.dst,
            group.pass,
            &group.after,
        ),
        Fused::Program(program) => simd::combined8_regs(
            program,
            tex,
            tail,
            &group.primary,
            &group.dst,
            group.pass,
            &group.after,
        ),
    })
}

/// The chain form of a draw's cascade (`cascade::Chain`: two or more `GL_COMBINE` units,
/// none reading another unit's texel) when the processor has AVX2 and the draw does not take
/// the byte environment.
fn chain_of(ds: &FragmentDraw) -> Option<&crate::fragment::cascade::Chain> {
    let chain = ds.cascade.as_ref()?.chain()?;
    (!ds.key.byte_env && chain.len() == ds.units.len() && crate::common::cpu::available())
        .then_some(chain)
}

/// A block of a draw with a chain ([`chain_of`]) in one go: each unit's texels as
/// `texels_block` filters them (`block_words8`, kept in registers), the chain on them
/// (`Chain::run`: the bits of the compiled cascade) and the tail with the result as a
/// replacing texel, as `sampled8_shade` runs them. `None` (the caller takes the general
/// block route: the same pixels) where a unit's block filter does not take the block.
/// `samplers`: the draw's units' samplers, every one present and 2D.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn chain_block(
    chain: &crate::fragment::cascade::Chain,
    samplers: &[Option<Perspective8>],
    tail: &Tail8,
    gx: i32,
    group: &GroupInputs,
) -> Option<([u32; 8], u8)> {
    use std::arch::x86_64::*;
    use texture_simd::x86::{block_words8, texels_of_words};
    let x = gx as f64 + 0.5;
    let color = chain.run_with(&group.primary, |k| {
        let s = samplers.get(k)?.as_ref()?;
        Some(
            match block_words8(&s.planes, x, group.pass, s.fixed_plan, s.lod, s.levels)? {
                (words, Some(level)) => texels_of_words(level, words),
                (_, None) => [_mm256_setzero_ps(); 4],
            },
        )
    })?;
    // The tail of a cascade (no `modulate`, `rgb_from_primary` or `alpha_from_primary`)
    // reads no primary colour.
    Some(simd::shade8_regs(
        tail,
        &group.primary,
        &color,
        &group.dst,
        group.pass,
        &group.after,
    ))
}

/// A block of a `FragmentKey::byte_env` draw on bytes (`fragment::bytenv`): every unit's
/// texels as bytes from its block sampler, the cascade in 8-bit integers and the tail from the
/// colour bytes; the same colour words as the f32 route. `None` (the caller takes the f32
/// route) when the primary colour is not a converted byte at a passing lane or a unit's block
/// sampler does not take the block. `constant`: the primary colour's words when it is the
/// same converted bytes at every lane of every block (computed once per primitive).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn byte_block(
    ds: &FragmentDraw,
    samplers: &[Option<Perspective8>; MAX_TEXTURE_UNITS],
    tail: &Tail8,
    gx: i32,
    group: &GroupInputs,
    constant: Option<std::arch::x86_64::__m256i>,
) -> Option<([u32; 8], u8)> {
    let primary = match constant {
        Some(words) => words,
        None => crate::fragment::bytenv::exact_words(&group.primary, group.pass)?,
    };
    let x = gx as f64 + 0.5;
    if let Some(bytes) = ds.cascade.as_ref().and_then(|p| p.bytes()) {
        // The cascade compiled for the draw: the primary colour and each unit's texel words
        // (in an array of the draw's length where it is short: no stores of unused entries).
        let samplers = &samplers[..ds.units.len()];
        let rgba = match samplers.len() {
            1 => byte_inputs::<2>(bytes, primary, samplers, x, group.pass)?,
            2 => byte_inputs::<3>(bytes, primary, samplers, x, group.pass)?,
            3 => byte_inputs::<4>(bytes, primary, samplers, x, group.pass)?,
            _ => byte_inputs::<{ MAX_TEXTURE_UNITS + 1 }>(bytes, primary, samplers, x, group.pass)?,
        };
        return Some(simd::shade8_bytes(tail, rgba, &group.dst, group.pass));
    }
    let mut by_unit = [None; MAX_TEXTURE_UNITS];
    for (k, unit) in ds.units.iter().enumerate() {
        by_unit[unit.unit] = Some(samplers[k].as_ref()?.block_bytes(x, group.pass)?);
    }
    Some(crate::fragment::bytenv::shade(
        ds, tail, primary, &by_unit, &group.dst, group.pass,
    ))
}

/// [`byte_block`]'s compiled cascade (`Bytes::run`) on the primary colour's words `primary`
/// and the texel words of the draw's units' `samplers` (`N` at least one more than there
/// are: the inputs in an array of about the draw's length, without stores of unused
/// entries); `None` where a unit's block sampler does not take the block.
#[cfg(target_arch = "x86_64")]
#[inline]
#[target_feature(enable = "avx2")]
fn byte_inputs<const N: usize>(
    bytes: &crate::fragment::bytenv::Bytes,
    primary: std::arch::x86_64::__m256i,
    samplers: &[Option<Perspective8>],
    x: f64,
    live: u8,
) -> Option<std::arch::x86_64::__m256i> {
    let mut inputs = [primary; N];
    for (input, sampler) in inputs[1..].iter_mut().zip(samplers) {
        *input = sampler.as_ref()?.block_bytes(x, live)?;
    }
    Some(bytes.run(&inputs[..=samplers.len().min(N - 1)]))
}

/// A specialised path for simple keys (no alpha test, stencil, blending or logic op): depth
/// mode and full colour mask fixed at compile time.
pub fn span_specialised<'a, const DEPTH: u8, const FULL_MASK: bool>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    // Eight pixels at a time where it applies (`rows8.rs`: the same values).
    if simple_rows8::<DEPTH, FULL_MASK>(ds, tile, y, x0, x1, it) {
        return;
    }
    shade::<DEPTH, FULL_MASK, true, false, false>(ds, tile, y, x0, x1, it)
}

/// [`span_specialised`] with fog: keys that are simple but for fog (a fogged, untextured,
/// unblended scene).
pub fn span_fogged<'a, const DEPTH: u8, const FULL_MASK: bool>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    shade::<DEPTH, FULL_MASK, true, false, true>(ds, tile, y, x0, x1, it)
}

/// Whether [`span_untextured8`] may shade a key: untextured, and after the primary colour only
/// the alpha test, the depth test, blending (any equation and factors) and the colour mask
/// apply.
pub fn untextured8_applies(key: &FragmentKey) -> bool {
    !key.texturing && tail8_applies(key)
}

/// Untextured spans eight fragments at a time for keys with [`untextured8_applies`]: the
/// primary colours enter the eight-fragment tail ([`simd::shade8`]) as replacing texels, so
/// the alpha test, blending, colour mask and writes run on eight at once with the general
/// path's arithmetic (the same pixels). Partly covered pixels take the general path.
pub fn span_untextured8<'a>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    if it.coverage != 1.0 {
        return span_general(ds, tile, y, x0, x1, it);
    }
    untextured8(ds, tile, y, x0, x1, it, None)
}

/// A row of pixels with a coverage each: pixel `x0 + i` of row `y` has coverage
/// `coverage[i]`, and is shaded as the span function shades it alone with that coverage
/// (antialiased lines, whose edge pixels next to each other differ only in coverage).
pub type CoveredFn = for<'a> fn(&'a FragmentDraw, &mut Tile, i32, i32, &[f32], &Interpolants<'a>);

/// [`span_untextured8`] with a coverage per pixel ([`CoveredFn`]): `finish_fragment`
/// multiplies the clamped alpha by the coverage after fog, before the alpha test; the
/// eight-lane tail takes the lanes' alphas as they are at that point (fog and the colour sum
/// leave alpha alone), so each lane's alpha is multiplied here, as the general path
/// multiplies it, and the tail does the rest. `it.coverage` is not read.
pub fn span_untextured8_covered<'a>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    coverage: &[f32],
    it: &Interpolants<'a>,
) {
    let x1 = x0 + coverage.len() as i32;
    untextured8(ds, tile, y, x0, x1, it, Some(coverage))
}

/// [`span_untextured8_covered`] for a primitive whose fragments all have the same inputs (an
/// antialiased line with one colour and one depth, the constant planes of
/// `raster::line_tile`): the eight-lane inputs and the tail are prepared once
/// ([`CoveredRows::new`]) instead of per row, and each row only reads the stored colours and
/// depths, multiplies the lanes' alphas by their coverages and runs the tail, as
/// [`untextured8`] does for every lane of such a primitive.
#[derive(Debug)]
pub struct CoveredRows {
    tail: Tail8,
    /// Every lane's inputs, fog factors made (`SpanRun::constant_group`).
    group: GroupInputs,
}

impl CoveredRows {
    /// The rows' set-up for interpolants `it` (constant planes: `Plane::constant`), when the
    /// key has the covered row function (`FragmentDraw::span_covered`: none on the general
    /// path) and every pixel's evaluated and stepped inputs are the same bits.
    pub fn new(ds: &FragmentDraw, it: &Interpolants) -> Option<CoveredRows> {
        ds.span_covered?;
        // Pixel centres are positive, so the evaluation at the first one is every pixel's.
        let group = SpanRun::new(it, 0, 0.5, lane_colors(ds))
            .with_fog(ds)
            .constant_group(ds)?;
        Some(CoveredRows {
            tail: tail8(ds, false, false, false),
            group,
        })
    }

    /// Shades pixels `x0..x0 + coverage.len()` of row `y` (in `tile`), pixel `x0 + i` with
    /// coverage `coverage[i]`, as [`span_untextured8_covered`] shades them.
    pub fn row(&self, ds: &FragmentDraw, tile: &mut Tile, y: i32, x0: i32, coverage: &[f32]) {
        let row = tile.index(x0, y);
        let c = &self.group;
        // Without a depth or stencil test every lane of the row passes them.
        let tested = ds.key.depth_func.is_some() || ds.key.stencil.is_some();
        let mut dst = [0u32; 8];
        let mut primary = c.primary;
        for (g, cov) in coverage.chunks(8).enumerate() {
            let n = cov.len();
            let base = row + 8 * g;
            let mut pass = lane_bits(0..n);
            if tested {
                if stencil_rejects_all(ds, tile, base, 0..n) {
                    continue;
                }
                pass = 0;
                for j in 0..n {
                    pass |= u8::from(depth_passes(ds, c.depth[j], tile.depth[base + j])) << j;
                }
            }
            for (d, p) in dst.iter_mut().zip(&tile.color[base..base + n]) {
                *d = u32::from_le_bytes(*p);
            }
            for ((a, &k), &v) in primary[3].iter_mut().zip(cov).zip(&c.primary[3]) {
                *a = if k != 1.0 { v.clamp(0.0, 1.0) * k } else { v };
            }
            if ds.key.stencil.is_some() {
                pass = stencil_row(ds, tile, base, n, pass);
            }
            if let Some((words, passed)) =
                simd::shade8(&self.tail, &primary, &primary, &dst, pass, &c.after)
            {
                store_group(ds, tile, base, 0..n, &words, passed, &c.depth);
            }
        }
    }
}

/// [`span_untextured8`]'s eight-lane loop; with `coverage`, pixel `x0 + i`'s alpha is
/// multiplied by `coverage[i]` as `finish_fragment` does it.
#[inline(always)]
fn untextured8<'a>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
    coverage: Option<&[f32]>,
) {
    let row = tile.index(x0, y);
    let yc = y as f64 + 0.5;
    let mut run = SpanRun::new(it, x0, yc, lane_colors(ds)).with_fog(ds);
    let tail = tail8(ds, false, false, false);
    let depth_max = group_depth_max(ds);
    let fog = lane_fog(ds);
    let fogged = fog.is_some();
    let mut gx = x0;
    let mut group = GroupInputs::EMPTY;
    // Pixels of groups the stencil test rejected whole, not yet stepped over: one skip for
    // a run of them (as many steps as one skip per group), none at the end of the span.
    let mut skipped = 0;
    while gx < x1 {
        let n = ((x1 - gx) as usize).min(8);
        let base = row + (gx - x0) as usize;
        if stencil_rejects_all(ds, tile, base, 0..n) {
            skipped += n;
            gx += 8;
            continue;
        }
        if skipped != 0 {
            run.skip(skipped);
            skipped = 0;
        }
        group.refill(ds, tile, base, 0..n, |_| {
            if fogged {
                run.next::<true>(depth_max)
            } else {
                run.next::<false>(depth_max)
            }
        });
        if let Some(cov) = coverage {
            let at = (gx - x0) as usize;
            for (a, &c) in group.primary[3][..n].iter_mut().zip(&cov[at..at + n]) {
                if c != 1.0 {
                    *a = a.clamp(0.0, 1.0) * c;
                }
            }
        }
        if ds.key.stencil.is_some() {
            group.pass = stencil_row(ds, tile, base, n, group.pass);
        }
        group.fog_factors(fog);
        let g = &group;
        if let Some((words, passed)) =
            simd::shade8(&tail, &g.primary, &g.primary, &g.dst, g.pass, &g.after)
        {
            store_group(ds, tile, base, 0..n, &words, passed, &g.depth);
        }
        gx += 8;
    }
}

/// Whether [`span_depth_stencil`] may shade a key: no colour is written and no alpha test
/// reads one (a stencil shadow-volume pass, a depth-only pass), so only the fragments' depths
/// matter.
pub fn depth_stencil_applies(key: &FragmentKey) -> bool {
    key.color_mask == [false; 4] && key.alpha_func.is_none()
}

/// Spans of a key with [`depth_stencil_applies`]: the stencil and depth tests with their
/// updates and the occlusion count, eight fragments at a time and each in
/// [`finish_fragment`]'s order, without the colour, texturing and fog it would compute and
/// then not write (the depth stepped as every span path steps it).
pub fn span_depth_stencil<'a>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    // Whole groups in registers where it applies (`rows8.rs`: the same values).
    if depth_stencil_rows8(ds, tile, y, x0, x1, it) {
        return;
    }
    let key = &ds.key;
    let row = tile.index(x0, y);
    let mut run = SpanRun::new(it, x0, y as f64 + 0.5, 0);
    let end = row + (x1 - x0).max(0) as usize;
    let mut start = row;
    // Eight at a time: the depths stepped as every span steps them, rounded and tested by
    // `simd::depth8` (`depth_to_fixed` and the key's function; per lane without it), then
    // the stencil ([`stencil_lanes`]), the occlusion count and the depth writes.
    while start < end {
        let n = (end - start).min(8);
        let live = lane_bits(0..n);
        let mut z = [0f64; 8];
        let mut stored = [0u32; 8];
        for v in &mut z[..n] {
            *v = run.next_z();
        }
        if let Some(whole) = tile.depth.get(start..start + 8) {
            // One fixed-size copy (lanes past `n` are not live).
            stored.copy_from_slice(whole);
        } else {
            stored[..n].copy_from_slice(&tile.depth[start..start + n]);
        }
        let (depth, depth_pass) = simd::depth8(&z, &stored, live, ds.depth_max, key.depth_func)
            .unwrap_or_else(|| {
                let mut depth = [0u32; 8];
                let mut pass = 0u8;
                for j in 0..n {
                    depth[j] = depth_to_fixed(z[j], ds.depth_max);
                    pass |= u8::from(depth_passes(ds, depth[j], stored[j])) << j;
                }
                (depth, pass)
            });
        let pass = stencil_row(ds, tile, start, n, depth_pass);
        if key.count_samples {
            tile.samples_passed += u64::from(pass.count_ones());
        }
        if key.depth_write {
            for j in (0..n).filter(|j| pass & (1 << j) != 0) {
                tile.depth[start + j] = depth[j];
            }
        }
        start += n;
    }
}

/// Draws nothing (a key whose fragments change no buffer).
pub fn span_nothing(_: &FragmentDraw, _: &mut Tile, _: i32, _: i32, _: i32, _: &Interpolants) {}

/// Whether [`span_sampled8`] may shade a key: every unit takes the eight-pixel sampler
/// (`simd_units`), and after the texture environment only the alpha test, the depth test,
/// blending (any equation and factors) and the colour mask apply.
pub fn sampled8_applies(key: &FragmentKey) -> bool {
    key.simd_units && tail8_applies(key)
}

/// Textured spans eight pixels at a time for keys with [`sampled8_applies`]: every unit
/// sampled by its eight-pixel sampler, the environment cascade per pixel, then the alpha test,
/// blending and colour mask of eight fragments at once ([`simd::shade8`] with the environment's
/// result as a replacing texel). The same arithmetic as the general path, so the same pixels.
pub fn span_sampled8<'a>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    let yc = y as f64 + 0.5;
    let row = tile.index(x0, y);
    if it.coverage != 1.0 {
        return span_sampled(ds, tile, y, x0, x1, it);
    }
    let mut run = SpanRun::new(it, x0, yc, lane_colors(ds)).with_fog(ds);
    let fog = lane_fog(ds);
    let Sampled8 {
        mut samplers,
        single,
        tail,
        mut by_unit,
    } = Sampled8::new(ds, it, y, false);
    let depth_max = group_depth_max(ds);
    let mut gx = x0 & !1;
    let mut group = GroupInputs::EMPTY;
    while gx < x1 {
        let lo = (x0 - gx).max(0) as usize;
        let hi = ((x1 - gx) as usize).min(8);
        let first = (gx - x0) as isize;
        let base = (row as isize + first) as usize;
        if stencil_rejects_all(ds, tile, base, lo..hi) {
            run.skip(hi - lo);
            gx += 8;
            continue;
        }
        group.refill(ds, tile, base, lo..hi, |_| {
            if fog.is_some() {
                run.next::<true>(depth_max)
            } else {
                run.next::<false>(depth_max)
            }
        });
        if ds.key.stencil.is_some() {
            group.pass = stencil_lanes(ds, tile, lane_bits(lo..hi), group.pass, |j| base + j);
        }
        // Lanes failing the depth (or stencil) test change no colour or depth: only passing
        // lanes are sampled.
        if group.pass == 0 {
            gx += 8;
            continue;
        }
        group.fog_factors(fog);
        for (k, unit) in ds.units.iter().enumerate() {
            if let Some(out) = by_unit[unit.unit].as_mut() {
                sampled_texels(samplers[k].as_mut(), unit, it, gx, yc, group.pass, out);
            }
        }
        if let Some((words, passed)) = sampled8_shade(ds, single, &tail, &group, &by_unit) {
            store_group(ds, tile, base, lo..hi, &words, passed, &group.depth);
        }
        gx += 8;
    }
}

/// One REPLACE or MODULATE unit: (`MODULATE`, the base format has colour, has alpha).
pub(super) type SingleUnit = Option<(bool, bool, bool)>;

/// What the eight-lane paths of a [`sampled8_applies`] draw set up for a row or a row pair:
/// each unit's sampler (by index in `FragmentDraw::units`), the tail, and each unit's texels of
/// the current group by unit number (as the cascade reads them).
pub(super) struct Sampled8<'a> {
    pub(super) samplers: [Option<Perspective8<'a>>; MAX_TEXTURE_UNITS],
    pub(super) single: SingleUnit,
    pub(super) tail: Tail8,
    pub(super) by_unit: [Option<Texels8>; MAX_TEXTURE_UNITS],
}

impl<'a> Sampled8<'a> {
    /// For row `y`, or with `block` the 4x2 blocks of rows `y` and `y + 1`. (Inlined: built
    /// in place, not copied out, it costs nothing per row pair.)
    #[inline(always)]
    pub(super) fn new(
        ds: &'a FragmentDraw,
        it: &Interpolants<'a>,
        y: i32,
        block: bool,
    ) -> Sampled8<'a> {
        let mut samplers: [Option<Perspective8>; MAX_TEXTURE_UNITS] = Default::default();
        Self::place_samplers(&mut samplers, ds, it, y, block);
        let (single, tail) = sampled8_tail(ds);
        let mut by_unit = [None; MAX_TEXTURE_UNITS];
        for unit in &ds.units {
            by_unit[unit.unit] = Some([[0f32; 8]; 4]);
        }
        Sampled8 {
            samplers,
            single,
            tail,
            by_unit,
        }
    }

    /// Each unit's sampler for row `y`, or with `block` the 4x2 blocks of rows `y` and `y + 1`.
    #[inline(always)]
    pub(super) fn place_samplers(
        samplers: &mut [Option<Perspective8<'a>>; MAX_TEXTURE_UNITS],
        ds: &'a FragmentDraw,
        it: &Interpolants<'a>,
        y: i32,
        block: bool,
    ) {
        for (k, (slot, unit)) in samplers.iter_mut().zip(&ds.units).enumerate() {
            *slot = if block {
                Perspective8::block(unit, k, it, y)
            } else {
                Perspective8::new(unit, k, it, y)
            };
        }
    }
}

/// The eight-fragment tail of a [`sampled8_applies`] draw. With one unit under REPLACE or
/// MODULATE ([`SingleUnit`]) the environment itself runs eight fragments at a time in the
/// tail (with the base format's table: which of colour and alpha the texture has); otherwise
/// the cascade runs per fragment and enters the tail as a replacing texel.
pub(super) fn sampled8_tail(ds: &FragmentDraw) -> (SingleUnit, Tail8) {
    let single = match ds.units.as_slice() {
        [unit] if matches!(unit.env.mode, TexEnvMode::Replace | TexEnvMode::Modulate) => {
            let (has_color, has_alpha) = match unit.base {
                BaseFormat::Alpha => (false, true),
                BaseFormat::Luminance | BaseFormat::Rgb => (true, false),
                _ => (true, true),
            };
            Some((unit.env.mode == TexEnvMode::Modulate, has_color, has_alpha))
        }
        _ => None,
    };
    let tail = tail8(
        ds,
        single.is_some_and(|s| s.0),
        single.is_some_and(|s| !s.1),
        single.is_some_and(|s| !s.2),
    );
    (single, tail)
}

/// The environment (cascade or tail) and the tail of a group of a [`sampled8_applies`]
/// draw, given each unit's texels by unit number.
#[inline(always)]
pub(super) fn sampled8_shade(
    ds: &FragmentDraw,
    single: SingleUnit,
    tail: &Tail8,
    group: &GroupInputs,
    by_unit: &[Option<Texels8>; MAX_TEXTURE_UNITS],
) -> Option<([u32; 8], u8)> {
    let color = match single {
        Some(_) => group.primary,
        None => environment8(ds, &group.primary, by_unit),
    };
    // With one REPLACE/MODULATE unit `color` is the primary colour and the tail applies the
    // environment; otherwise it is the cascade's result, entering as a replacing texel.
    let tex = match single.and(ds.units.first()) {
        Some(unit) => by_unit[unit.unit].as_ref().unwrap_or(&color),
        None => &color,
    };
    simd::shade8(tail, &color, tex, &group.dst, group.pass, &group.after)
}

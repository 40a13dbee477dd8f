//! Fogged untextured spans of simple keys eight fragments at a time (`span_fogged8`): the
//! spans of a fogged height field's small triangles are about three pixels long, too short
//! for the general eight-lane tail (`span_untextured8`, `pair_*` blocks: each cost more than
//! the fragment-by-fragment `span_fogged` on them, docs/performance.md), so this route keeps
//! `span_fogged`'s stepping and does everything after it in one AVX2 kernel over the span's
//! groups of up to eight: w, the perspective colours and fog coordinates, the fog factor
//! (`simd::fog_factors8`), the blend towards the fog colour, the conversion to bytes, the
//! depth rounding and test (`simd::depth8`) and the colour mask. Each is the operation of
//! `finish_fragment` and `FogDraw::factor` in the same precision and order, so the pixels are
//! `span_fogged`'s (`tests/fog_twins.rs`).

use super::*;

/// [`span_fogged`] eight fragments at a time (keys simple but for fog: no alpha test,
/// stencil, blending, logic op, colour sum or texturing; depth handling by `DEPTH`, the
/// colour mask by `FULL_MASK`, as `span_fogged`). Takes `span_fogged` itself without AVX2,
/// for partly covered fragments, for draws without fog parameters and for depth ranges of
/// 32 bits, and for spans shorter than [`LANES8_MIN_SPAN`].
pub fn span_fogged8<'a, const DEPTH: u8, const FULL_MASK: bool>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    let fog = lane_fog(ds);
    let (Some(fog), true, true, true, true) = (
        fog,
        x1 - x0 >= LANES8_MIN_SPAN,
        it.coverage == 1.0,
        crate::common::cpu::available(),
        ds.depth_max < 1 << 31,
    ) else {
        return span_fogged::<DEPTH, FULL_MASK>(ds, tile, y, x0, x1, it);
    };
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: AVX2 is present (checked just above).
        unsafe { fogged_rows::<DEPTH, FULL_MASK>(ds, tile, y, x0, x1, it, fog) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = fog;
        span_fogged::<DEPTH, FULL_MASK>(ds, tile, y, x0, x1, it)
    }
}

/// [`span_fogged8`]'s groups: each lane's values stepped as `span_fogged` steps them
/// ([`SpanRun::record`] and [`SpanRun::advance`], the same sums and restarts as
/// `SpanRun::each_pixel`), then [`fogged8`] on the group and the passing lanes stored.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[allow(clippy::too_many_arguments)]
fn fogged_rows<const DEPTH: u8, const FULL_MASK: bool>(
    ds: &FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants,
    fog: &FogDraw,
) {
    let row = tile.index(x0, y);
    let n = (x1 - x0).max(0) as usize;
    let mut run = SpanRun::new(it, x0, y as f64 + 0.5, 4);
    run.fog_on();
    let mut raw = RawLanes::default();
    let (test, write) = match DEPTH {
        depth_mode::NONE => (None, false),
        depth_mode::LESS_WRITE => (Some(CompareFunc::Less), true),
        depth_mode::LEQUAL_WRITE => (Some(CompareFunc::LessEqual), true),
        _ => (ds.key.depth_func, ds.key.depth_write),
    };
    let tested = DEPTH != depth_mode::NONE && test.is_some();
    let mask = u32::from_le_bytes(ds.key.color_mask.map(|m| if m { 0xFF } else { 0 }));
    let params = FogParams {
        fog,
        scale: fog.linear_scale(),
        perspective: it.perspective,
        primary_perspective: it.perspective && !it.constant_primary,
    };
    let mut start = 0;
    while start < n {
        let m = (n - start).min(8);
        for j in 0..m {
            run.record::<true>(&mut raw, j, true);
            run.advance::<true>();
        }
        let base = row + start;
        let live = lane_bits(0..m);
        let words = fogged8(&raw, &params);
        let (depth, pass) = if tested || write {
            raw.stored[..m].copy_from_slice(&tile.depth[base..base + m]);
            // `depth_max` < 2^31 (checked by `span_fogged8`).
            simd::depth8(&raw.z, &raw.stored, live, ds.depth_max, test).unwrap_or_default()
        } else {
            ([0; 8], live)
        };
        let colors = &mut tile.color[base..base + m];
        for (j, c) in colors.iter_mut().enumerate() {
            if pass & (1 << j) == 0 {
                continue;
            }
            *c = if FULL_MASK {
                words[j]
            } else {
                (words[j] & mask) | (u32::from_le_bytes(*c) & !mask)
            }
            .to_le_bytes();
        }
        if write {
            for (j, d) in tile.depth[base..base + m].iter_mut().enumerate() {
                if pass & (1 << j) != 0 {
                    *d = depth[j];
                }
            }
        }
        start += m;
    }
}

/// What [`fogged8`] needs of the draw and the primitive besides the lanes.
struct FogParams<'f> {
    fog: &'f FogDraw,
    /// `FogDraw::linear_scale`.
    scale: f32,
    /// w is 1/(1/w) (else 1), and the fog coordinate is multiplied by it.
    perspective: bool,
    /// The primary colour is multiplied by w (`SpanRun::primary`).
    primary_perspective: bool,
}

/// The colour words (R in the low byte) of the eight fragments whose stepped values are in
/// `raw`, after fog, as `finish_fragment` computes each on the simple fogged path: w =
/// 1 / (1/w), the primary colour times w (`SpanRun::primary`), the fog coordinate times w
/// (`SpanRun::fog_coord`), the factor (`FogDraw::factor`, by `simd::fog_factors8`: the same
/// bits), `k * c.clamp(0, 1) + (1 - k) * fog colour` per colour channel (`fog_fragment`) and
/// `color4_to_u8`. Every operation is the IEEE single-precision one the scalar code does,
/// in the same order (no fused multiply-adds).
#[cfg(target_arch = "x86_64")]
#[inline]
#[target_feature(enable = "avx2")]
fn fogged8(raw: &RawLanes, p: &FogParams) -> [u32; 8] {
    use std::arch::x86_64::*;
    // SAFETY: each array holds eight f32; unaligned loads.
    let load = |a: &[f32; 8]| unsafe { _mm256_loadu_ps(a.as_ptr()) };
    let w = if p.perspective {
        _mm256_div_ps(_mm256_set1_ps(1.0), load(&raw.inv_w))
    } else {
        _mm256_set1_ps(1.0)
    };
    let coord = if p.perspective {
        _mm256_mul_ps(load(&raw.fog), w)
    } else {
        load(&raw.fog)
    };
    let mut c = [0f32; 8];
    // SAFETY: `c` holds eight f32; unaligned store.
    unsafe { _mm256_storeu_ps(c.as_mut_ptr(), coord) };
    let f = p.fog;
    // AVX2 is present (this function's feature), so the factors are there.
    let k = simd::fog_factors8(f.mode, f.density, f.end, p.scale, &c).unwrap_or_default();
    let k = load(&k);
    let (zero, one) = (_mm256_setzero_ps(), _mm256_set1_ps(1.0));
    let rest = _mm256_sub_ps(one, k);
    let mut bytes = [_mm256_setzero_si256(); 4];
    for (ch, b) in bytes.iter_mut().enumerate() {
        let mut v = load(&raw.color[ch]);
        if p.primary_perspective {
            v = _mm256_mul_ps(v, w);
        }
        if ch < 3 {
            // max(0, min(1, v)) is `clamp`, NaN and the sign of zero included (min_ps and
            // max_ps answer their second operand for NaN and for equal operands).
            let clamped = _mm256_max_ps(zero, _mm256_min_ps(one, v));
            v = _mm256_add_ps(
                _mm256_mul_ps(k, clamped),
                _mm256_mul_ps(rest, _mm256_set1_ps(f.color[ch])),
            );
        }
        *b = simd::to_u8(v);
    }
    let word = simd::pack_words(&bytes);
    let mut out = [0u32; 8];
    // SAFETY: `out` holds eight u32; unaligned store.
    unsafe { _mm256_storeu_si256(out.as_mut_ptr() as *mut __m256i, word) };
    out
}

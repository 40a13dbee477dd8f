//! The fragment stage's eight-lane kernels with AVX2 (x86-64, detected at run time): the
//! tail after texturing (`shade8`: environment, alpha test, blending, colour mask), the depth
//! test (`depth8`), fog factors (`fog_factors8`), and the fused kernels that filter texels
//! with `texture::simd` and shade them in one go (`textured8`, `block_shaded8`). Every lane
//! does the arithmetic of the general fragment path in the same order and precision, so the
//! pixels are identical (twin tests in `tests/raster.rs`).

use crate::common::cpu::available;
use crate::common::values::{CompareFunc, FogMode, LogicOp, TexEnvMode};
use crate::fragment::draw::TextureUnitDraw;
use crate::fragment::key::BlendKey;
use crate::texture::sample::LodSelect;
use crate::texture::simd::{Level8, Texels8};

/// A 4x2 block of a perspective textured span in one go: the texels as
/// [`block_texels8`](crate::texture::simd::block_texels8) gives them (coordinates, each live
/// quad's level plan or the draw's `fixed_plan`, the filter; kept in registers), then
/// [`shade8`] with lanes `live`. `None` without AVX2 or where
/// [`block_texels8`](crate::texture::simd::block_texels8) would answer `None`: the caller
/// takes the usual route, which gives the same pixels.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn block_shaded8(
    planes: &[[[f64; 3]; 3]; 2],
    x: f64,
    live: u8,
    fixed_plan: Option<(usize, bool)>,
    lod: &LodSelect,
    levels: &[Option<Level8>],
    tail: &Tail8,
    primary: &[[f32; 8]; 4],
    dst: &[u32; 8],
    after: &After8,
) -> Option<([u32; 8], u8)> {
    #[cfg(target_arch = "x86_64")]
    {
        if available() {
            // SAFETY: AVX2 is present (checked just above).
            return unsafe {
                x86::block_shaded8(
                    planes, x, live, fixed_plan, lod, levels, tail, primary, dst, after,
                )
            };
        }
    }
    let _ = (
        planes, x, live, fixed_plan, lod, levels, tail, primary, dst, after,
    );
    None
}

/// The blending [`shade8`] does: none, the two common cases by their own code, or any other.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TailBlend {
    None,
    /// `SRC_ALPHA`, `ONE_MINUS_SRC_ALPHA`.
    AlphaOver,
    /// `ONE`, `ONE`.
    AddOneOne,
    /// Any other blending whose factors are all bytes (no constant colour or alpha), as
    /// `fragment::blend::blend` computes it, in 16-bit integer lanes.
    Bytes(BlendKey),
    /// Any other blending (equations, factors, the constant colour), as
    /// `fragment::blend::blend` computes it.
    General(BlendKey, [f32; 4]),
    /// No blending but a logical operation (section 4.1.10: it replaces blending) on the
    /// fragments' colour bytes and the stored ones, bit by bit, as `LogicOp::apply`.
    Logic(LogicOp),
}

/// The per-fragment operations after texturing for eight RGBA8-textured fragments (see
/// [`shade8`]).
#[derive(Clone, Copy, Debug)]
pub struct Tail8 {
    /// `MODULATE` (else `REPLACE`) with an RGBA texture.
    pub modulate: bool,
    /// The alpha test's function and reference, when it applies.
    pub alpha_test: Option<(CompareFunc, f32)>,
    /// An RGB texture under `REPLACE`: the fragment keeps the primary colour's alpha.
    pub alpha_from_primary: bool,
    /// An ALPHA texture (no colour): the fragment keeps the primary colour's R, G, B.
    pub rgb_from_primary: bool,
    /// The blending.
    pub blend: TailBlend,
    /// Bytes of the colour words that may be written (the colour mask).
    pub color_mask: u32,
    /// Add the secondary colour ([`After8::secondary`]) after the environment (the colour
    /// sum, section 3.9).
    pub color_sum: bool,
    /// Fog's colour, when the fragments are fogged: each lane's colour is blended towards it
    /// by the lane's fog factor (section 3.10) after the environment, as
    /// `fragment::span::fog_fragment` does.
    pub fog: Option<[f32; 3]>,
}

/// What the tail adds to eight fragments after the environment: their secondary colours
/// (with [`Tail8::color_sum`]) and fog factors (with [`Tail8::fog`]), read for passing lanes.
#[derive(Clone, Copy, Debug, Default)]
pub struct After8 {
    pub secondary: [[f32; 8]; 3],
    pub fog: [f32; 8],
}

/// Eight fragments of a textured span after the texture lookup, as the general fragment path
/// computes them one by one: the environment on the primary colour `primary` (each channel
/// clamped to [0, 1]) and texel `tex`, the alpha test, conversion to 8 bits, blending with
/// `dst` (the colour words in the tile, R in the low byte) and the colour mask. `pass` has
/// bit j set for fragments that exist and pass the depth test. Answers the new colour words
/// (`dst` where a fragment is rejected) and the bits of the fragments that passed every test;
/// `None` without AVX2. `after` holds what the colour sum and fog add ([`After8`]).
#[inline]
pub fn shade8(
    tail: &Tail8,
    primary: &[[f32; 8]; 4],
    tex: &Texels8,
    dst: &[u32; 8],
    pass: u8,
    after: &After8,
) -> Option<([u32; 8], u8)> {
    #[cfg(target_arch = "x86_64")]
    {
        if available() {
            // SAFETY: AVX2 is present (checked just above).
            return Some(unsafe { x86::shade8(tail, primary, tex, dst, pass, after) });
        }
    }
    let _ = (tail, primary, tex, dst, pass, after);
    None
}

/// What [`textured8`] needs besides the fragments: an affine span's coordinate planes and
/// level selection.
#[derive(Clone, Copy, Debug)]
pub struct Sampling8<'a> {
    /// The s and t planes as `[a, b * y, c]` for the row.
    pub planes: [[f64; 3]; 2],
    /// The two divisors of the plane values (see [`coords8`](crate::texture::simd::coords8)), constant over the span.
    pub w: f64,
    pub q: f64,
    /// The first level and, with a weight, the second (the primitive's, read in place: a
    /// copy per span of a small sprite cost more than its groups' set-up).
    pub levels: &'a [Level8<'a>; 2],
    pub linear: bool,
    pub weight: Option<f32>,
}

/// [`coords8`](crate::texture::simd::coords8), [`filter8`](crate::texture::simd::filter8) on one or two levels and [`shade8`] in one go, for the `count`
/// pixels from centre `x`; `None` when [`coords8`](crate::texture::simd::coords8) or [`filter8`](crate::texture::simd::filter8) would answer `None`.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn textured8(
    sampling: &Sampling8,
    x: f64,
    count: usize,
    tail: &Tail8,
    primary: &[[f32; 8]; 4],
    dst: &[u32; 8],
    pass: u8,
    after: &After8,
) -> Option<([u32; 8], u8)> {
    #[cfg(target_arch = "x86_64")]
    {
        if available() {
            // SAFETY: AVX2 is present (checked just above).
            return unsafe { x86::textured8(sampling, x, count, tail, primary, dst, pass, after) };
        }
    }
    let _ = (sampling, x, count, tail, primary, dst, pass, after);
    None
}

/// The groups of eight pixels `gx, gx + 8, ..` (below `x1`) of a flat primitive's row whose
/// first pixel has index `row` in the tile's buffers at column `x0`, as `flat_row` shades
/// them with [`textured8`], but with the environment and tail on bytes: the texel words of
/// the same filter, the unit's environment on bytes with the primary colour words `primary`
/// ([`crate::fragment::bytenv::cascade`], whose results equal the f32 route's rounded ones
/// for converted bytes: `bytenv`'s proof), the tail from the bytes (`shade8_bytes`), the
/// depth test of the constant depth `d` by `func` and its write (`depth_write`). Answers the
/// first group it did not shade (`x1` or more when it shaded them all): where [`textured8`]
/// would answer `None` (the caller shades that group one pixel at a time, then calls again
/// from the next), where the group's pixels are not all in `color` and `depth`, or at once
/// without AVX2. For tails with [`bytes_apply`] and `primary` the bytes whose conversions are
/// the group's primary colours.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn flat_groups_bytes(
    sampling: &Sampling8,
    tail: &Tail8,
    unit: &TextureUnitDraw,
    primary: &[u32; 8],
    depth_test: (Option<CompareFunc>, u32, bool),
    (gx, x0, x1, row): (i32, i32, i32, usize),
    color: &mut [[u8; 4]],
    depth: &mut [u32],
) -> i32 {
    #[cfg(target_arch = "x86_64")]
    {
        if available() {
            // SAFETY: AVX2 is present (checked just above).
            return unsafe {
                x86::flat_groups_bytes(
                    sampling,
                    tail,
                    unit,
                    primary,
                    depth_test,
                    (gx, x0, x1, row),
                    color,
                    depth,
                )
            };
        }
    }
    let _ = (
        sampling, tail, unit, primary, depth_test, x0, x1, row, color, depth,
    );
    gx
}

/// Whether [`flat_groups_bytes`] may take the groups of a draw with `tail` and its one unit
/// `unit` in place of [`textured8`]: nothing after the environment reads the f32 colour (no
/// alpha test, colour sum or fog) and the environment is `REPLACE` or `MODULATE` (which the
/// byte environment computes exactly: `bytenv`'s proof).
pub fn bytes_apply(tail: &Tail8, unit: &TextureUnitDraw) -> bool {
    tail.alpha_test.is_none()
        && !tail.color_sum
        && tail.fog.is_none()
        && matches!(unit.env.mode, TexEnvMode::Replace | TexEnvMode::Modulate)
}

/// [`textured8`] on the colour words of eight pixels of a tile, `color` (R in the first
/// byte): read from there and written back there (the stored word where a lane did not
/// pass), answering the lanes that passed every test; `None` (nothing written) where
/// [`textured8`] answers `None`.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn textured8_in_place(
    sampling: &Sampling8,
    x: f64,
    count: usize,
    tail: &Tail8,
    primary: &[[f32; 8]; 4],
    color: &mut [[u8; 4]; 8],
    pass: u8,
    after: &After8,
) -> Option<u8> {
    #[cfg(target_arch = "x86_64")]
    {
        if available() {
            // SAFETY: AVX2 is present (checked just above).
            return unsafe {
                x86::textured8_in_place(sampling, x, count, tail, primary, color, pass, after)
            };
        }
    }
    let _ = (sampling, x, count, tail, primary, color, pass, after);
    None
}

/// Eight fragments' window depths `z` rounded to stored values as `depth_to_fixed` does
/// (`z * depth_max + 0.5`, NaN and negatives as 0, at most `depth_max`, truncated) and tested
/// against `stored` as `incoming OP stored` by `func` (`None` and `ALWAYS` pass): the depths
/// and the lanes of `live` that pass. `None` without AVX2 or when `depth_max` needs 32 bits.
#[inline]
pub fn depth8(
    z: &[f64; 8],
    stored: &[u32; 8],
    live: u8,
    depth_max: u32,
    func: Option<CompareFunc>,
) -> Option<([u32; 8], u8)> {
    #[cfg(target_arch = "x86_64")]
    {
        if available() && depth_max < 1 << 31 {
            // SAFETY: AVX2 is present (checked just above).
            return Some(unsafe { x86::depth8(z, stored, live, depth_max, func) });
        }
    }
    let _ = (z, stored, live, depth_max, func);
    None
}

/// The fog factors of eight fog coordinates `c`, as `FogDraw::factor` computes them one by one
/// (the same operations in the same order, `fog_exp` for EXP and EXP2): `mode` with `density`,
/// `end` and the linear scale `scale` (`FogDraw::linear_scale`). `None` without AVX2.
#[inline]
pub fn fog_factors8(
    mode: FogMode,
    density: f32,
    end: f32,
    scale: f32,
    c: &[f32; 8],
) -> Option<[f32; 8]> {
    #[cfg(target_arch = "x86_64")]
    {
        if available() {
            // SAFETY: AVX2 is present (checked just above).
            return Some(unsafe { x86::fog_factors8(mode, density, end, scale, c) });
        }
    }
    let _ = (mode, density, end, scale, c);
    None
}

#[cfg(target_arch = "x86_64")]
pub(crate) use x86::{
    block_combined8, combined8_regs, depth8 as depth8_avx2, pack_words, shade8_bytes, shade8_regs,
    to_u8,
};

#[cfg(target_arch = "x86_64")]
mod x86 {
    use std::arch::x86_64::*;

    use super::{After8, Sampling8, Tail8};
    use crate::common::limits::MAX_TEXTURE_UNITS;
    use crate::common::values::{BlendEquation, BlendFactor, CompareFunc, FogMode, LogicOp};
    use crate::fragment::bytenv::cascade;
    use crate::fragment::cascade::Program;
    use crate::fragment::draw::TextureUnitDraw;
    use crate::fragment::fog::EXP2_TAYLOR;
    use crate::fragment::key::BlendKey;
    use crate::texture::sample::LodSelect;
    use crate::texture::simd::x86::{
        block_words8, coords8, coords8_div, filter8_mix_regs, filter8_regs, filter8_words_mix,
        lane_mask, level_weights8, rgba_of_words, texels_of_words,
    };
    use crate::texture::simd::{Level8, Texels8};

    /// [`super::fog_factors8`].
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn fog_factors8(
        mode: FogMode,
        density: f32,
        end: f32,
        scale: f32,
        c: &[f32; 8],
    ) -> [f32; 8] {
        // SAFETY: `c` holds eight f32; unaligned load.
        let c = unsafe { _mm256_loadu_ps(c.as_ptr()) };
        let f = match mode {
            FogMode::Linear => {
                _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(end), c), _mm256_set1_ps(scale))
            }
            FogMode::Exp => exp8(_mm256_mul_ps(_mm256_set1_ps(-density), c)),
            FogMode::Exp2 => {
                let d = _mm256_mul_ps(_mm256_set1_ps(density), c);
                // -d by its sign bit, exactly as the scalar negation.
                let neg = _mm256_xor_ps(d, _mm256_set1_ps(-0.0));
                exp8(_mm256_mul_ps(neg, d))
            }
        };
        // f.max(0.0).min(1.0): max_ps answers its second operand (0) for NaN, as f32::max
        // ignores a NaN.
        let f = _mm256_min_ps(_mm256_max_ps(f, _mm256_setzero_ps()), _mm256_set1_ps(1.0));
        let mut out = [0f32; 8];
        // SAFETY: `out` holds eight f32; unaligned store.
        unsafe { _mm256_storeu_ps(out.as_mut_ptr(), f) };
        out
    }

    /// `fog_exp` per lane (`state::snapshot::fog_exp`: the same operations in the same order).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn exp8(x: __m256) -> __m256 {
        let t = _mm256_mul_ps(x, _mm256_set1_ps(std::f32::consts::LOG2_E));
        // max(t, -126) answers -126 for NaN, as f32::max does.
        let t = _mm256_min_ps(
            _mm256_max_ps(t, _mm256_set1_ps(-126.0)),
            _mm256_set1_ps(126.0),
        );
        let n = _mm256_floor_ps(_mm256_add_ps(t, _mm256_set1_ps(0.5)));
        let f = _mm256_sub_ps(t, n);
        let k = EXP2_TAYLOR;
        let mut p = _mm256_set1_ps(k[5]);
        for &kk in k[..5].iter().rev() {
            p = _mm256_add_ps(_mm256_mul_ps(p, f), _mm256_set1_ps(kk));
        }
        p = _mm256_add_ps(_mm256_mul_ps(p, f), _mm256_set1_ps(1.0));
        let bits = _mm256_slli_epi32::<23>(_mm256_add_epi32(
            _mm256_cvttps_epi32(n),
            _mm256_set1_epi32(127),
        ));
        _mm256_mul_ps(p, _mm256_castsi256_ps(bits))
    }

    /// `color_to_u8` per lane: `c * 255 + 0.5` clamped to [0, 255] (NaN as 0), truncated.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn to_u8(c: __m256) -> __m256i {
        let v = _mm256_add_ps(_mm256_mul_ps(c, _mm256_set1_ps(255.0)), _mm256_set1_ps(0.5));
        // max_ps answers its second operand (0) when v is NaN.
        let v = _mm256_min_ps(_mm256_max_ps(v, _mm256_setzero_ps()), _mm256_set1_ps(255.0));
        _mm256_cvttps_epi32(v)
    }

    /// Eight colour words (R in the low byte) from the four channels' bytes, one per lane.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn pack_words(b: &[__m256i; 4]) -> __m256i {
        _mm256_or_si256(
            _mm256_or_si256(b[0], _mm256_slli_epi32::<8>(b[1])),
            _mm256_or_si256(_mm256_slli_epi32::<16>(b[2]), _mm256_slli_epi32::<24>(b[3])),
        )
    }

    /// A blend factor for channel `ch` of eight fragments, as `fragment::blend` computes it
    /// (source and destination already in [0, 1]; no NaN reaches here).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn factor8(
        f: BlendFactor,
        s: &[__m256; 4],
        d: &[__m256; 4],
        c: &[f32; 4],
        ch: usize,
    ) -> __m256 {
        let one = _mm256_set1_ps(1.0);
        match f {
            BlendFactor::Zero => _mm256_setzero_ps(),
            BlendFactor::One => one,
            BlendFactor::SrcColor => s[ch],
            BlendFactor::OneMinusSrcColor => _mm256_sub_ps(one, s[ch]),
            BlendFactor::DstColor => d[ch],
            BlendFactor::OneMinusDstColor => _mm256_sub_ps(one, d[ch]),
            BlendFactor::SrcAlpha => s[3],
            BlendFactor::OneMinusSrcAlpha => _mm256_sub_ps(one, s[3]),
            BlendFactor::DstAlpha => d[3],
            BlendFactor::OneMinusDstAlpha => _mm256_sub_ps(one, d[3]),
            BlendFactor::ConstantColor => _mm256_set1_ps(c[ch]),
            BlendFactor::OneMinusConstantColor => _mm256_set1_ps(1.0 - c[ch]),
            BlendFactor::ConstantAlpha => _mm256_set1_ps(c[3]),
            BlendFactor::OneMinusConstantAlpha => _mm256_set1_ps(1.0 - c[3]),
            BlendFactor::SrcAlphaSaturate => {
                if ch == 3 {
                    one
                } else {
                    _mm256_min_ps(s[3], _mm256_sub_ps(one, d[3]))
                }
            }
        }
    }

    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn shade8(
        tail: &Tail8,
        primary: &[[f32; 8]; 4],
        tex: &Texels8,
        dst: &[u32; 8],
        pass: u8,
        after: &After8,
    ) -> ([u32; 8], u8) {
        // SAFETY: each array holds eight f32; unaligned loads.
        let load = |a: &[f32; 8]| unsafe { _mm256_loadu_ps(a.as_ptr()) };
        let mut tex_v = [_mm256_setzero_ps(); 4];
        for c in 0..4 {
            tex_v[c] = load(&tex[c]);
        }
        shade8_regs(tail, primary, &tex_v, dst, pass, after)
    }

    /// [`shade8`] with the texels in registers.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn shade8_regs(
        tail: &Tail8,
        primary: &[[f32; 8]; 4],
        tex: &[__m256; 4],
        dst: &[u32; 8],
        pass: u8,
        after: &After8,
    ) -> ([u32; 8], u8) {
        // SAFETY: each array holds eight f32; unaligned loads.
        let load = |a: &[f32; 8]| unsafe { _mm256_loadu_ps(a.as_ptr()) };
        let (zero, one) = (_mm256_setzero_ps(), _mm256_set1_ps(1.0));
        // c.max(0.0).min(1.0): max_ps answers 0 for NaN.
        // (Loops rather than `array::from_fn`/`map`: closures passed to functions without
        // AVX2 would not be inlined.)
        let mut color = [zero; 4];
        for c in 0..4 {
            let ct = tex[c];
            color[c] = if c < 3 && tail.rgb_from_primary {
                _mm256_min_ps(_mm256_max_ps(load(&primary[c]), zero), one)
            } else if tail.modulate {
                let cf = _mm256_min_ps(_mm256_max_ps(load(&primary[c]), zero), one);
                _mm256_mul_ps(cf, ct)
            } else if c == 3 && tail.alpha_from_primary {
                _mm256_min_ps(_mm256_max_ps(load(&primary[c]), zero), one)
            } else {
                ct
            };
        }
        if tail.color_sum {
            // `c.clamp(0.0, 1.0) + secondary` per colour channel, as the general path adds
            // the secondary colour (the clamp as below).
            for (c, s) in color.iter_mut().zip(&after.secondary) {
                *c = _mm256_add_ps(_mm256_max_ps(zero, _mm256_min_ps(one, *c)), load(s));
            }
        }
        if let Some(fog_color) = tail.fog {
            // `k * c.clamp(0.0, 1.0) + (1.0 - k) * fog` per colour channel, as the general
            // path computes it (max(0, min(1, c)) is `clamp`, NaN and the sign of zero
            // included: min_ps and max_ps answer their second operand for NaN and for
            // equal operands).
            let k = load(&after.fog);
            let rest = _mm256_sub_ps(one, k);
            for (c, &f) in color.iter_mut().zip(&fog_color) {
                let clamped = _mm256_max_ps(zero, _mm256_min_ps(one, *c));
                *c = _mm256_add_ps(
                    _mm256_mul_ps(k, clamped),
                    _mm256_mul_ps(rest, _mm256_set1_ps(f)),
                );
            }
        }
        let mut keep = lane_mask(pass);
        if let Some((func, reference)) = tail.alpha_test {
            // alpha.clamp(0.0, 1.0), keeping NaN (min_ps and max_ps answer their second
            // operand for NaN), then `alpha OP reference` as `CompareFunc::test`.
            let a = _mm256_max_ps(zero, _mm256_min_ps(one, color[3]));
            let r = _mm256_set1_ps(reference);
            let ok = match func {
                CompareFunc::Never => zero,
                CompareFunc::Less => _mm256_cmp_ps::<_CMP_LT_OQ>(a, r),
                CompareFunc::Equal => _mm256_cmp_ps::<_CMP_EQ_OQ>(a, r),
                CompareFunc::LessEqual => _mm256_cmp_ps::<_CMP_LE_OQ>(a, r),
                CompareFunc::Greater => _mm256_cmp_ps::<_CMP_GT_OQ>(a, r),
                CompareFunc::NotEqual => _mm256_cmp_ps::<_CMP_NEQ_UQ>(a, r),
                CompareFunc::GreaterEqual => _mm256_cmp_ps::<_CMP_GE_OQ>(a, r),
                CompareFunc::Always => _mm256_castsi256_ps(_mm256_set1_epi32(-1)),
            };
            keep = _mm256_and_ps(keep, ok);
        }
        let mut src = [_mm256_setzero_si256(); 4];
        for c in 0..4 {
            src[c] = to_u8(color[c]);
        }
        finish8(tail, &src, keep, dst)
    }

    /// [`shade8`]'s blending, colour mask and lanes for eight fragments whose colours after
    /// the environment are the bytes of `rgba` (R in the low byte), for a tail without an
    /// alpha test, colour sum or fog and whose environment was applied before (none of
    /// `modulate`, `rgb_from_primary`, `alpha_from_primary`): the colour words and the lanes
    /// of `pass`, as [`shade8`] gives them for colours whose `to_u8` are these bytes. The
    /// caller checked that the processor has AVX2.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn shade8_bytes(tail: &Tail8, rgba: __m256i, dst: &[u32; 8], pass: u8) -> ([u32; 8], u8) {
        let byte = _mm256_set1_epi32(0xFF);
        let src = [
            _mm256_and_si256(rgba, byte),
            _mm256_and_si256(_mm256_srli_epi32::<8>(rgba), byte),
            _mm256_and_si256(_mm256_srli_epi32::<16>(rgba), byte),
            _mm256_srli_epi32::<24>(rgba),
        ];
        finish8(tail, &src, lane_mask(pass), dst)
    }

    /// The tail from the fragments' colours as bytes `src` (one channel per array, 0..=255 in
    /// 32-bit lanes): blending with `dst`, the colour mask, and the lanes of `keep`.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn finish8(tail: &Tail8, src: &[__m256i; 4], keep: __m256, dst: &[u32; 8]) -> ([u32; 8], u8) {
        // SAFETY: `dst` holds eight u32; unaligned load.
        let old = unsafe { _mm256_loadu_si256(dst.as_ptr() as *const __m256i) };
        let k = _mm256_set1_ps(255.0);
        let byte = _mm256_set1_epi32(0xFF);
        let d = [
            old,
            _mm256_srli_epi32::<8>(old),
            _mm256_srli_epi32::<16>(old),
            _mm256_srli_epi32::<24>(old),
        ];
        let word = if let super::TailBlend::Logic(op) = tail.blend {
            logic8(op, pack_words(src), old)
        } else if tail.blend == super::TailBlend::AddOneOne {
            // ONE, ONE: `color_to_u8(s / 255 + d / 255)` is exactly min(s + d, 255) for bytes
            // s and d (the f32 errors stay far below the 0.5 of rounding;
            // `add_one_one_is_a_saturating_byte_add` checks every pair): bytes added with
            // saturation.
            _mm256_adds_epu8(pack_words(src), old)
        } else if tail.blend == super::TailBlend::AlphaOver {
            // Each product rounded to 8 bits, then added, as `blend::blend_alpha_over`: in
            // 16-bit lanes (`blend16`), the factors fixed here.
            alpha_over16(pack_words(src), old)
        } else if let super::TailBlend::Bytes(key) = &tail.blend {
            blend16(key, pack_words(src), old)
        } else if let super::TailBlend::General(key, constant) = &tail.blend {
            let s: [__m256; 4] = [0, 1, 2, 3].map(|c| _mm256_div_ps(_mm256_cvtepi32_ps(src[c]), k));
            let d: [__m256; 4] = [0, 1, 2, 3]
                .map(|c| _mm256_div_ps(_mm256_cvtepi32_ps(_mm256_and_si256(d[c], byte)), k));
            let mut out = [_mm256_setzero_si256(); 4];
            for ch in 0..4 {
                let (sf, df, eq) = if ch == 3 {
                    (key.src_alpha, key.dst_alpha, key.equation_alpha)
                } else {
                    (key.src_rgb, key.dst_rgb, key.equation)
                };
                let v = match eq {
                    BlendEquation::Min => _mm256_min_ps(s[ch], d[ch]),
                    BlendEquation::Max => _mm256_max_ps(s[ch], d[ch]),
                    eq => {
                        // Each product rounded to 8 bits, as `blend::product_u8`.
                        let q = |v: __m256| _mm256_div_ps(_mm256_cvtepi32_ps(to_u8(v)), k);
                        let a = q(_mm256_mul_ps(s[ch], factor8(sf, &s, &d, constant, ch)));
                        let b = q(_mm256_mul_ps(d[ch], factor8(df, &s, &d, constant, ch)));
                        match eq {
                            BlendEquation::Add => _mm256_add_ps(a, b),
                            BlendEquation::Subtract => _mm256_sub_ps(a, b),
                            _ => _mm256_sub_ps(b, a),
                        }
                    }
                };
                out[ch] = to_u8(v);
            }
            pack_words(&out)
        } else {
            pack_words(src)
        };
        let cm = _mm256_set1_epi32(tail.color_mask as i32);
        let word = _mm256_or_si256(_mm256_and_si256(word, cm), _mm256_andnot_si256(cm, old));
        let word = _mm256_blendv_epi8(old, word, _mm256_castps_si256(keep));
        let mut res = [0u32; 8];
        // SAFETY: `res` holds eight u32; unaligned store.
        unsafe { _mm256_storeu_si256(res.as_mut_ptr() as *mut __m256i, word) };
        (res, _mm256_movemask_ps(keep) as u8)
    }

    /// `round(x * f / 255)` for 16-bit lanes holding bytes `x` and `f` (the product at most
    /// 65025): `t = x f + 128`, then `(t + (t >> 8)) >> 8`, which is `t * 257 >> 16` for
    /// `t < 65536` (the high half of a multiplication by 257). The exact rounding of the
    /// quotient, which never lies halfway between integers (`2 x f` is even, `255` odd).
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn mul255(x: __m256i, f: __m256i) -> __m256i {
        let t = _mm256_add_epi16(_mm256_mullo_epi16(x, f), _mm256_set1_epi16(128));
        _mm256_mulhi_epu16(t, _mm256_set1_epi16(257))
    }

    /// The colour words `w` as 16-bit lanes: pixels 0, 1, 4, 5 and pixels 2, 3, 6, 7 (the
    /// unpacking works within 128-bit halves; `_mm256_packus_epi16` restores the order), a
    /// pixel's R, G, B, A in four consecutive lanes.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn widen16(w: __m256i) -> [__m256i; 2] {
        let zero = _mm256_setzero_si256();
        [_mm256_unpacklo_epi8(w, zero), _mm256_unpackhi_epi8(w, zero)]
    }

    /// Each pixel's alpha (its lane 3 in [`widen16`]'s layout) spread over its four lanes.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn spread_alpha(v: __m256i) -> __m256i {
        let spread = _mm256_setr_epi8(
            6, 7, 6, 7, 6, 7, 6, 7, 14, 15, 14, 15, 14, 15, 14, 15, 6, 7, 6, 7, 6, 7, 6, 7, 14, 15,
            14, 15, 14, 15, 14, 15,
        );
        _mm256_shuffle_epi8(v, spread)
    }

    /// `SRC_ALPHA`, `ONE_MINUS_SRC_ALPHA` of the colour words `src` over `dst` as
    /// `blend::blend_alpha_over` computes it (each product rounded to 8 bits, see
    /// [`blend16`], then added), in 16-bit lanes.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn alpha_over16(src: __m256i, dst: __m256i) -> __m256i {
        let (s, d) = (widen16(src), widen16(dst));
        let full = _mm256_set1_epi16(255);
        let mut out = [_mm256_setzero_si256(); 2];
        for h in 0..2 {
            let sa = spread_alpha(s[h]);
            out[h] = _mm256_add_epi16(mul255(s[h], sa), mul255(d[h], _mm256_sub_epi16(full, sa)));
        }
        // Sums above 255 saturate.
        _mm256_packus_epi16(out[0], out[1])
    }

    /// Blend factor `f` for both halves of [`widen16`]'s layout, from the sources `s`, the
    /// destinations `d` and their spread alphas ([`spread_alpha`]); `alpha`: the factor of
    /// the alpha channel (`SRC_ALPHA_SATURATE` is 1 there). Constant-colour factors are not
    /// bytes and do not reach here (`TailBlend::Bytes`).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn factor16(f: BlendFactor, alpha: bool, v: &[[__m256i; 2]; 4]) -> [__m256i; 2] {
        let full = _mm256_set1_epi16(255);
        let [s, d, sa, da] = *v;
        let (x, invert) = match f {
            BlendFactor::Zero => ([_mm256_setzero_si256(); 2], false),
            BlendFactor::SrcColor => (s, false),
            BlendFactor::OneMinusSrcColor => (s, true),
            BlendFactor::DstColor => (d, false),
            BlendFactor::OneMinusDstColor => (d, true),
            BlendFactor::SrcAlpha => (sa, false),
            BlendFactor::OneMinusSrcAlpha => (sa, true),
            BlendFactor::DstAlpha => (da, false),
            BlendFactor::OneMinusDstAlpha => (da, true),
            BlendFactor::SrcAlphaSaturate if !alpha => {
                let mut m = sa;
                for h in 0..2 {
                    m[h] = _mm256_min_epu16(sa[h], _mm256_sub_epi16(full, da[h]));
                }
                (m, false)
            }
            _ => ([full; 2], false),
        };
        if !invert {
            return x;
        }
        [_mm256_sub_epi16(full, x[0]), _mm256_sub_epi16(full, x[1])]
    }

    /// Blending by a key whose factors are all bytes (no constant colour) of the colour words
    /// `src` (the fragments') over `dst`, as `blend::blend` computes it: each product rounded
    /// to 8 bits ([`mul255`] gives exactly `color_to_u8` of the f32 product, whose exact value
    /// is never within 1/510 of a rounding tie while f32's error stays below 1e-4), their sum
    /// or difference clamped to [0, 255] (exact: the f32 sum of two byte values over 255 times
    /// 255 is within 1e-4 of an integer); `MIN` and `MAX` take no factors. Sixteen channels
    /// (four pixels) per register ([`widen16`]).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn blend16(key: &BlendKey, src: __m256i, dst: __m256i) -> __m256i {
        let (s, d) = (widen16(src), widen16(dst));
        let v = [
            s,
            d,
            [spread_alpha(s[0]), spread_alpha(s[1])],
            [spread_alpha(d[0]), spread_alpha(d[1])],
        ];
        // The factors, the alpha lanes' from the alpha factors where they differ (lanes 3
        // and 7 of each 128-bit half are alpha).
        let mut fs = factor16(key.src_rgb, false, &v);
        let mut fd = factor16(key.dst_rgb, false, &v);
        let saturate = BlendFactor::SrcAlphaSaturate;
        if key.src_alpha != key.src_rgb || key.src_rgb == saturate {
            let a = factor16(key.src_alpha, true, &v);
            for h in 0..2 {
                fs[h] = _mm256_blend_epi16::<0x88>(fs[h], a[h]);
            }
        }
        if key.dst_alpha != key.dst_rgb || key.dst_rgb == saturate {
            let a = factor16(key.dst_alpha, true, &v);
            for h in 0..2 {
                fd[h] = _mm256_blend_epi16::<0x88>(fd[h], a[h]);
            }
        }
        let mut out = [_mm256_setzero_si256(); 2];
        for h in 0..2 {
            let a = mul255(s[h], fs[h]);
            let b = mul255(d[h], fd[h]);
            let rgb = equation16(key.equation, s[h], d[h], a, b);
            out[h] = if key.equation_alpha == key.equation {
                rgb
            } else {
                let alpha = equation16(key.equation_alpha, s[h], d[h], a, b);
                _mm256_blend_epi16::<0x88>(rgb, alpha)
            };
        }
        // Sums above 255 saturate.
        _mm256_packus_epi16(out[0], out[1])
    }

    /// Equation `eq` on the products `a` (source) and `b` (destination), or on the source
    /// `s` and destination `d` themselves for `MIN` and `MAX`; differences below 0 as 0.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn equation16(eq: BlendEquation, s: __m256i, d: __m256i, a: __m256i, b: __m256i) -> __m256i {
        match eq {
            BlendEquation::Add => _mm256_add_epi16(a, b),
            BlendEquation::Subtract => _mm256_subs_epu16(a, b),
            BlendEquation::ReverseSubtract => _mm256_subs_epu16(b, a),
            BlendEquation::Min => _mm256_min_epu16(s, d),
            BlendEquation::Max => _mm256_max_epu16(s, d),
        }
    }

    /// `op` on the bytes of the colour words `s` (the fragments') and `d` (the stored ones),
    /// as `LogicOp::apply` on each byte: bitwise operations on the whole words.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn logic8(op: LogicOp, s: __m256i, d: __m256i) -> __m256i {
        let ones = _mm256_set1_epi32(-1);
        let not = |v: __m256i| _mm256_xor_si256(v, ones);
        match op {
            LogicOp::Clear => _mm256_setzero_si256(),
            LogicOp::And => _mm256_and_si256(s, d),
            LogicOp::AndReverse => _mm256_andnot_si256(d, s),
            LogicOp::Copy => s,
            LogicOp::AndInverted => _mm256_andnot_si256(s, d),
            LogicOp::Noop => d,
            LogicOp::Xor => _mm256_xor_si256(s, d),
            LogicOp::Or => _mm256_or_si256(s, d),
            LogicOp::Nor => not(_mm256_or_si256(s, d)),
            LogicOp::Equiv => not(_mm256_xor_si256(s, d)),
            LogicOp::Invert => not(d),
            LogicOp::OrReverse => _mm256_or_si256(s, not(d)),
            LogicOp::CopyInverted => not(s),
            LogicOp::OrInverted => _mm256_or_si256(not(s), d),
            LogicOp::Nand => not(_mm256_and_si256(s, d)),
            LogicOp::Set => ones,
        }
    }

    #[allow(clippy::too_many_arguments)]
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn textured8(
        sm: &Sampling8,
        x: f64,
        count: usize,
        tail: &Tail8,
        primary: &[[f32; 8]; 4],
        dst: &[u32; 8],
        pass: u8,
        after: &After8,
    ) -> Option<([u32; 8], u8)> {
        let [s, t] = coords8(sm.planes, sm.w, sm.q, x, count)?;
        // SAFETY: `s` and `t` hold eight f32 each; unaligned loads.
        let (s, t) = unsafe { (_mm256_loadu_ps(s.as_ptr()), _mm256_loadu_ps(t.as_ptr())) };
        // (The texels stay in registers: `shade8` would store and load them again.)
        let ct = match sm.weight {
            None => filter8_regs(&sm.levels[0], sm.linear, s, t)?,
            Some(w) => filter8_mix_regs(
                [&sm.levels[0], &sm.levels[1]],
                sm.linear,
                s,
                t,
                level_weights8(&[w; 8]),
            )?,
        };
        Some(shade8_regs(tail, primary, &ct, dst, pass, after))
    }

    #[allow(clippy::too_many_arguments)]
    #[target_feature(enable = "avx2")]
    pub fn textured8_in_place(
        sm: &Sampling8,
        x: f64,
        count: usize,
        tail: &Tail8,
        primary: &[[f32; 8]; 4],
        color: &mut [[u8; 4]; 8],
        pass: u8,
        after: &After8,
    ) -> Option<u8> {
        let mut dst = [0u32; 8];
        // SAFETY: `color` and `dst` are 32 bytes each; unaligned load and store.
        unsafe {
            let v = _mm256_loadu_si256(color.as_ptr() as *const __m256i);
            _mm256_storeu_si256(dst.as_mut_ptr() as *mut __m256i, v);
        }
        let (words, passed) = textured8(sm, x, count, tail, primary, &dst, pass, after)?;
        // SAFETY: as above (the words in the tile's byte order: R in the first byte).
        unsafe {
            let v = _mm256_loadu_si256(words.as_ptr() as *const __m256i);
            _mm256_storeu_si256(color.as_mut_ptr() as *mut __m256i, v);
        }
        Some(passed)
    }

    /// All ones in lanes `0..n` (n <= 8), zeros elsewhere.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn first_lanes(n: usize) -> __m256i {
        _mm256_cmpgt_epi32(
            _mm256_set1_epi32(n as i32),
            _mm256_set_epi32(7, 6, 5, 4, 3, 2, 1, 0),
        )
    }

    /// `incoming OP stored` per lane for unsigned depths, as `CompareFunc::test` (`None` and
    /// `ALWAYS` pass): all ones where the test passes.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn depth_compare8(func: Option<CompareFunc>, d: __m256i, old: __m256i) -> __m256i {
        // Unsigned order through signed comparisons: both sides with the top bit flipped.
        let flip = _mm256_set1_epi32(i32::MIN);
        let (a, b) = (_mm256_xor_si256(d, flip), _mm256_xor_si256(old, flip));
        let all = _mm256_set1_epi32(-1);
        match func {
            None | Some(CompareFunc::Always) => all,
            Some(CompareFunc::Never) => _mm256_setzero_si256(),
            Some(CompareFunc::Less) => _mm256_cmpgt_epi32(b, a),
            Some(CompareFunc::LessEqual) => _mm256_xor_si256(_mm256_cmpgt_epi32(a, b), all),
            Some(CompareFunc::Equal) => _mm256_cmpeq_epi32(a, b),
            Some(CompareFunc::Greater) => _mm256_cmpgt_epi32(a, b),
            Some(CompareFunc::GreaterEqual) => _mm256_xor_si256(_mm256_cmpgt_epi32(b, a), all),
            Some(CompareFunc::NotEqual) => _mm256_xor_si256(_mm256_cmpeq_epi32(a, b), all),
        }
    }

    /// [`super::flat_groups_bytes`].
    #[allow(clippy::too_many_arguments)]
    #[target_feature(enable = "avx2")]
    pub fn flat_groups_bytes(
        sm: &Sampling8,
        tail: &Tail8,
        unit: &TextureUnitDraw,
        primary: &[u32; 8],
        depth_test: (Option<CompareFunc>, u32, bool),
        span: (i32, i32, i32, usize),
        color: &mut [[u8; 4]],
        depth: &mut [u32],
    ) -> i32 {
        if sm.w == 1.0 && sm.q == 1.0 {
            flat_groups::<false>(sm, tail, unit, primary, depth_test, span, color, depth)
        } else {
            flat_groups::<true>(sm, tail, unit, primary, depth_test, span, color, depth)
        }
    }

    /// [`flat_groups_bytes`] with the coordinates' divisions (`coords8_div`).
    #[allow(clippy::too_many_arguments)]
    #[inline]
    #[target_feature(enable = "avx2")]
    fn flat_groups<const DIV: bool>(
        sm: &Sampling8,
        tail: &Tail8,
        unit: &TextureUnitDraw,
        primary: &[u32; 8],
        (func, d, depth_write): (Option<CompareFunc>, u32, bool),
        (mut gx, x0, x1, row): (i32, i32, i32, usize),
        color: &mut [[u8; 4]],
        depth: &mut [u32],
    ) -> i32 {
        // SAFETY: eight u32; unaligned load.
        let primary = unsafe { _mm256_loadu_si256(primary.as_ptr() as *const __m256i) };
        let tests = !matches!(func, None | Some(CompareFunc::Always));
        let dv = _mm256_set1_epi32(d as i32);
        let base = sm.levels[0].base();
        while gx < x1 {
            let hi = ((x1 - gx) as usize).min(8);
            let at = row + (gx - x0) as usize;
            if color.len() < at + hi || ((tests || depth_write) && depth.len() < at + hi) {
                return gx;
            }
            let live = first_lanes(hi);
            let mut pass = live;
            if tests {
                // SAFETY: lanes 0..hi of the mask are set, and `depth` holds `at + hi`
                // values (checked above): the masked load reads only inside it.
                let old =
                    unsafe { _mm256_maskload_epi32(depth.as_ptr().add(at) as *const i32, live) };
                pass = _mm256_and_si256(live, depth_compare8(func, dv, old));
            }
            let pass_bits = _mm256_movemask_ps(_mm256_castsi256_ps(pass)) as u8;
            if pass_bits != 0 {
                let x = gx as f64 + 0.5;
                let Some([s, t]) = coords8_div::<DIV>(sm.planes, sm.w, sm.q, x, hi) else {
                    return gx;
                };
                // SAFETY: eight f32 each; unaligned loads.
                let (s, t) = unsafe { (_mm256_loadu_ps(s.as_ptr()), _mm256_loadu_ps(t.as_ptr())) };
                let Some(words) = filter8_words_mix(sm.levels, sm.linear, s, t, sm.weight) else {
                    return gx;
                };
                let mut by_unit = [None; MAX_TEXTURE_UNITS];
                by_unit[unit.unit] = Some(rgba_of_words(base, words));
                let rgba = cascade(
                    std::iter::once((&unit.env, unit.base, unit.unit)),
                    primary,
                    &by_unit,
                );
                let ptr = color.as_mut_ptr().wrapping_add(at) as *mut i32;
                // SAFETY: `color` holds `at + hi` pixels (checked above) of four bytes each;
                // the masked load reads lanes 0..hi only. `dst` holds eight u32.
                let dst = unsafe {
                    let mut dst = [0u32; 8];
                    let old = _mm256_maskload_epi32(ptr, live);
                    _mm256_storeu_si256(dst.as_mut_ptr() as *mut __m256i, old);
                    dst
                };
                let (res, passed) = shade8_bytes(tail, rgba, &dst, pass_bits);
                // SAFETY: as the load above, lanes 0..hi only; `res` holds eight u32.
                unsafe {
                    let res = _mm256_loadu_si256(res.as_ptr() as *const __m256i);
                    _mm256_maskstore_epi32(ptr, live, res);
                }
                if depth_write && passed != 0 {
                    // SAFETY: `depth` holds `at + hi` values (checked above); the passed
                    // lanes are among 0..hi.
                    unsafe {
                        _mm256_maskstore_epi32(
                            depth.as_mut_ptr().add(at) as *mut i32,
                            lane_mask_i(passed),
                            dv,
                        )
                    };
                }
            }
            gx += 8;
        }
        gx
    }

    /// All ones in the lanes whose bit is set in `m`.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn lane_mask_i(m: u8) -> __m256i {
        _mm256_castps_si256(lane_mask(m))
    }

    #[allow(clippy::too_many_arguments)]
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn block_shaded8(
        planes: &[[[f64; 3]; 3]; 2],
        x: f64,
        live: u8,
        fixed_plan: Option<(usize, bool)>,
        lod: &LodSelect,
        levels: &[Option<Level8>],
        tail: &Tail8,
        primary: &[[f32; 8]; 4],
        dst: &[u32; 8],
        after: &After8,
    ) -> Option<([u32; 8], u8)> {
        // As `texture::simd::x86::block_texels8`, the texels left in registers.
        let tex = match block_words8(planes, x, live, fixed_plan, lod, levels)? {
            (words, Some(level)) => texels_of_words(level, words),
            (_, None) => [_mm256_setzero_ps(); 4],
        };
        Some(shade8_regs(tail, primary, &tex, dst, live, after))
    }

    /// [`block_shaded8`] for one unit whose environment is the compiled cascade `program`
    /// (reading at most that unit's texel): the texels left in registers, the program on them
    /// ([`Program::run_regs`], or its one-unit `GL_COMBINE` form `Single::run`: the bits of
    /// `Program::run_avx2`) and [`shade8`] with its
    /// result as a replacing texel (`tail` of a draw without `modulate`, `rgb_from_primary`
    /// or `alpha_from_primary`), as the general block route runs them. `None` where
    /// `block_texels8` would answer `None` (the caller takes the general route). The caller
    /// checked that the processor has AVX2.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn block_combined8(
        planes: &[[[f64; 3]; 3]; 2],
        x: f64,
        live: u8,
        fixed_plan: Option<(usize, bool)>,
        lod: &LodSelect,
        levels: &[Option<Level8>],
        program: &Program,
        tail: &Tail8,
        primary: &[[f32; 8]; 4],
        dst: &[u32; 8],
        after: &After8,
    ) -> Option<([u32; 8], u8)> {
        // (The body of `combined8_regs` written out again: called, it stays out of line.)
        let mut texel = [[_mm256_setzero_ps(); 4]; 1];
        let reads = program.texel_units().next().is_some();
        if reads {
            texel[0] = match block_words8(planes, x, live, fixed_plan, lod, levels)? {
                (words, Some(level)) => texels_of_words(level, words),
                (_, None) => [_mm256_setzero_ps(); 4],
            };
        }
        let color = match program.single() {
            Some(single) => {
                // The clamped primary colour, as `Program::run_regs` clamps it.
                let (zero, one) = (_mm256_setzero_ps(), _mm256_set1_ps(1.0));
                let mut p = [zero; 4];
                for (v, c) in p.iter_mut().zip(primary) {
                    // SAFETY: eight f32; unaligned load.
                    let c = unsafe { _mm256_loadu_ps(c.as_ptr()) };
                    *v = _mm256_min_ps(_mm256_max_ps(c, zero), one);
                }
                single.run(p, texel[0])
            }
            None => program.run_regs(primary, &texel[..usize::from(reads)]),
        };
        Some(shade8_regs(tail, primary, &color, dst, live, after))
    }

    /// The program and the tail of [`block_combined8`] on the unit's texels `texel` (in
    /// registers; read only when the program reads a texel), for the cube-map blocks: the
    /// program by `Program::run_avx2` (the bits of `Single::run` and `run_regs`; called
    /// here, those two would no longer be inlined into [`block_combined8`]).
    #[allow(clippy::too_many_arguments)]
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn combined8_regs(
        program: &Program,
        texel: [__m256; 4],
        tail: &Tail8,
        primary: &[[f32; 8]; 4],
        dst: &[u32; 8],
        live: u8,
        after: &After8,
    ) -> ([u32; 8], u8) {
        let mut by_unit = [None; MAX_TEXTURE_UNITS];
        if let Some(unit) = program.texel_units().next() {
            let mut t = [[0f32; 8]; 4];
            for (o, v) in t.iter_mut().zip(texel) {
                // SAFETY: eight f32; unaligned store.
                unsafe { _mm256_storeu_ps(o.as_mut_ptr(), v) };
            }
            by_unit[unit] = Some(t);
        }
        let color = program.run_avx2(primary, &by_unit);
        // SAFETY: eight f32 each; unaligned loads.
        let color = color.map(|c| unsafe { _mm256_loadu_ps(c.as_ptr()) });
        shade8_regs(tail, primary, &color, dst, live, after)
    }

    #[target_feature(enable = "avx2")]
    pub fn depth8(
        z: &[f64; 8],
        stored: &[u32; 8],
        live: u8,
        depth_max: u32,
        func: Option<CompareFunc>,
    ) -> ([u32; 8], u8) {
        let maxv = _mm256_set1_pd(depth_max as f64);
        let half = |z: __m256d| {
            let v = _mm256_add_pd(_mm256_mul_pd(z, maxv), _mm256_set1_pd(0.5));
            // max_pd answers its second operand (0) when v is NaN.
            _mm256_cvttpd_epi32(_mm256_min_pd(_mm256_max_pd(v, _mm256_setzero_pd()), maxv))
        };
        // SAFETY: `z` holds eight f64, `stored` eight u32; unaligned loads.
        let (lo, hi, old) = unsafe {
            (
                _mm256_loadu_pd(z.as_ptr()),
                _mm256_loadu_pd(z.as_ptr().add(4)),
                _mm256_loadu_si256(stored.as_ptr() as *const __m256i),
            )
        };
        let d = _mm256_set_m128i(half(hi), half(lo));
        let mut depth = [0u32; 8];
        // SAFETY: `depth` holds eight u32; unaligned store.
        unsafe { _mm256_storeu_si256(depth.as_mut_ptr() as *mut __m256i, d) };
        // Unsigned order through signed comparisons: both sides with the top bit flipped.
        let flip = _mm256_set1_epi32(i32::MIN);
        let (a, b) = (_mm256_xor_si256(d, flip), _mm256_xor_si256(old, flip));
        let all = _mm256_set1_epi32(-1);
        let ok = match func {
            None | Some(CompareFunc::Always) => all,
            Some(CompareFunc::Never) => _mm256_setzero_si256(),
            Some(CompareFunc::Less) => _mm256_cmpgt_epi32(b, a),
            Some(CompareFunc::LessEqual) => _mm256_xor_si256(_mm256_cmpgt_epi32(a, b), all),
            Some(CompareFunc::Equal) => _mm256_cmpeq_epi32(a, b),
            Some(CompareFunc::Greater) => _mm256_cmpgt_epi32(a, b),
            Some(CompareFunc::GreaterEqual) => _mm256_xor_si256(_mm256_cmpgt_epi32(b, a), all),
            Some(CompareFunc::NotEqual) => _mm256_xor_si256(_mm256_cmpeq_epi32(a, b), all),
        };
        let pass = _mm256_movemask_ps(_mm256_castsi256_ps(ok)) as u8;
        (depth, live & pass)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::fixed::depth_to_fixed;
    use crate::fragment::fog::{fog_exp, FogDraw};

    /// `fog_factors8` gives `FogDraw::factor`'s values bit for bit, for every mode, several
    /// parameter sets (start == end included) and coordinates from negative through huge to
    /// infinite and NaN.
    #[test]
    fn fog_factors8_match_the_scalar_factor() {
        if !available() {
            return;
        }
        let mut coords = vec![0.0, -0.0, 1e-30, -3.0, f32::INFINITY, f32::NEG_INFINITY];
        coords.extend([f32::NAN, 1e30, 87.0, 700.0, 0.5, 12.25]);
        let mut x = 0.001f32;
        while x < 2000.0 {
            coords.push(x);
            x *= 1.013;
        }
        let params = [
            (0.07, 1.0, 30.0),
            (0.3, 0.5, 7.0),
            (2.5, 4.0, 4.0),
            (0.0, -2.0, 9.0),
        ];
        for mode in [FogMode::Linear, FogMode::Exp, FogMode::Exp2] {
            for (density, start, end) in params {
                let f = FogDraw {
                    mode,
                    density,
                    start,
                    end,
                    color: [0.0; 3],
                    coord_from_vertex: false,
                };
                for chunk in coords.chunks(8) {
                    let mut c = [0f32; 8];
                    c[..chunk.len()].copy_from_slice(chunk);
                    let k = fog_factors8(mode, density, end, f.linear_scale(), &c).unwrap();
                    for j in 0..8 {
                        assert_eq!(
                            k[j].to_bits(),
                            f.factor(c[j]).to_bits(),
                            "{mode:?} {density} {start} {end}: c = {}",
                            c[j]
                        );
                    }
                }
            }
        }
    }

    /// The 16-bit integer blending (`TailBlend::Bytes`, `TailBlend::AlphaOver`) gives
    /// `blend::blend`'s f32 result for every pair of source and destination bytes, for keys
    /// covering every byte factor and equation.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn integer_blending_is_the_f32_blend_for_every_byte_pair() {
        use crate::common::values::{BlendEquation as E, BlendFactor as F};
        use crate::fragment::blend::blend;
        use std::arch::x86_64::*;
        if !available() {
            return;
        }
        let key = |equation, equation_alpha, src_rgb, dst_rgb, src_alpha, dst_alpha| BlendKey {
            equation,
            equation_alpha,
            src_rgb,
            dst_rgb,
            src_alpha,
            dst_alpha,
        };
        let keys = [
            key(
                E::Add,
                E::Add,
                F::SrcAlpha,
                F::OneMinusSrcAlpha,
                F::SrcAlpha,
                F::OneMinusSrcAlpha,
            ),
            key(E::Add, E::Add, F::DstColor, F::Zero, F::DstColor, F::Zero),
            key(
                E::Add,
                E::Add,
                F::One,
                F::OneMinusSrcAlpha,
                F::One,
                F::OneMinusSrcAlpha,
            ),
            key(
                E::Subtract,
                E::Add,
                F::SrcColor,
                F::OneMinusDstColor,
                F::DstAlpha,
                F::One,
            ),
            key(
                E::ReverseSubtract,
                E::Min,
                F::OneMinusSrcColor,
                F::DstAlpha,
                F::Zero,
                F::SrcColor,
            ),
            key(
                E::Max,
                E::Subtract,
                F::SrcAlphaSaturate,
                F::OneMinusDstAlpha,
                F::SrcAlphaSaturate,
                F::DstColor,
            ),
            key(
                E::Add,
                E::ReverseSubtract,
                F::SrcAlphaSaturate,
                F::SrcColor,
                F::OneMinusDstAlpha,
                F::OneMinusSrcColor,
            ),
        ];
        for (k, b) in keys.iter().enumerate() {
            let blend_mode = if b.is_alpha_over() {
                TailBlend::AlphaOver
            } else {
                TailBlend::Bytes(*b)
            };
            assert!(b.byte_factors());
            let tail = Tail8 {
                modulate: false,
                alpha_test: None,
                alpha_from_primary: false,
                rgb_from_primary: false,
                blend: blend_mode,
                color_mask: u32::MAX,
                color_sum: false,
                fog: None,
            };
            for s in 0..=255u8 {
                for d0 in (0..=255u8).step_by(8) {
                    let src: [[u8; 4]; 8] = std::array::from_fn(|j| {
                        let d = d0 + j as u8;
                        [s, d, s ^ d, 255 - s]
                    });
                    let dst: [[u8; 4]; 8] = std::array::from_fn(|j| {
                        let d = d0 + j as u8;
                        [d, s, 255 - d, d ^ 0x5A]
                    });
                    let words = src.map(u32::from_le_bytes);
                    // SAFETY: AVX2 is present (checked above); `words` holds eight u32.
                    let (got, _) = unsafe {
                        let rgba = _mm256_loadu_si256(words.as_ptr() as *const __m256i);
                        shade8_bytes(&tail, rgba, &dst.map(u32::from_le_bytes), 0xFF)
                    };
                    for j in 0..8 {
                        let want = blend(b, src[j], dst[j], [0.0; 4]);
                        assert_eq!(
                            got[j].to_le_bytes(),
                            want,
                            "key {k}: {:?} over {:?}",
                            src[j],
                            dst[j]
                        );
                    }
                }
            }
        }
    }

    /// `fog_exp` is e^x within 1.5e-7 absolute for fog's arguments (x <= 0: a factor in [0, 1],
    /// where an 8-bit step is 4e-3) and within 5e-6 relative (the rounding of x log2(e) to
    /// f32) where the result is a normal number, and answers a factor of 0 after clamping for
    /// NaN.
    #[test]
    fn fog_exp_is_close_to_exp() {
        let mut x = -87.0f32;
        while x < 87.0 {
            let (got, want) = (fog_exp(x) as f64, (x as f64).exp());
            assert!(
                ((got - want) / want).abs() < 5e-6,
                "x = {x}: {got} vs {want}"
            );
            if x <= 0.0 {
                assert!((got - want).abs() < 1.5e-7, "x = {x}: {got} vs {want}");
            }
            x += 0.0137;
        }
        assert!(fog_exp(f32::NAN) < 1e-37);
        assert!(fog_exp(f32::NEG_INFINITY) < 1e-37);
        assert_eq!(fog_exp(0.0), 1.0);
    }

    /// `depth8` rounds and tests as `depth_to_fixed` and `CompareFunc::test` do one by one, for
    /// every function, several depth ranges, stored values around the fragments' and z from far
    /// outside [0, 1] to NaN.
    #[test]
    fn depth8_matches_the_scalar_depth_test() {
        if !available() {
            return;
        }
        let funcs = crate::test_support::DEPTH_FUNCS;
        let specials = [
            0.0,
            -0.0,
            1.0,
            -1e30,
            1e30,
            f64::NAN,
            f64::INFINITY,
            0.5,
            1.0 - 1e-9,
        ];
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        let mut next = || crate::test_support::xorshift(&mut seed);
        for case in 0..3000 {
            let max = [0xFFFFu32, 0xFF_FFFF, (1 << 31) - 1][case % 3];
            let mut z = [0f64; 8];
            let mut stored = [0u32; 8];
            for j in 0..8 {
                let r = next();
                z[j] = if r % 5 == 0 {
                    specials[(r >> 8) as usize % specials.len()]
                } else {
                    (r >> 11) as f64 / (1u64 << 53) as f64 * 1.2 - 0.1
                };
                // Often equal to the fragment's own depth, otherwise near it or anywhere.
                let own = depth_to_fixed(z[j], max);
                stored[j] = match next() % 3 {
                    0 => own,
                    1 => own
                        .saturating_add((next() % 3) as u32)
                        .min(max)
                        .saturating_sub(1),
                    _ => (next() % (max as u64 + 1)) as u32,
                };
            }
            let live = (next() & 0xFF) as u8;
            let func = funcs[case % funcs.len()];
            let (depth, pass) = depth8(&z, &stored, live, max, func).expect("AVX2, 31 bits");
            for j in 0..8 {
                let d = depth_to_fixed(z[j], max);
                assert_eq!(depth[j], d, "case {case} lane {j}: z {}", z[j]);
                let ok = match func {
                    None | Some(CompareFunc::Always) => true,
                    Some(f) => f.test(d, stored[j]),
                };
                let want = ok && live & (1 << j) != 0;
                assert_eq!(pass & (1 << j) != 0, want, "case {case} lane {j} {func:?}");
            }
        }
    }
}

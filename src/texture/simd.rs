//! The fast 2D path's filter for eight pixels at once with AVX2 (x86-64, detected at run
//! time): one-byte texels, `REPEAT` on power-of-two sizes or `CLAMP_TO_EDGE`. Every lane does
//! the arithmetic of the general sampler
//! ([`BoundTexture::sample_grad`](super::sample::BoundTexture::sample_grad) and
//! [`BoundTexture::filter_fast`](super::sample::BoundTexture::filter_fast)), so the results
//! are identical: NEAREST by the f64 floor, LINEAR and the mix of two levels in the 8-bit fixed
//! point of [`fixed`](super::fixed) (16-bit lanes: `pmulhrsw` of the weight and the difference
//! shifted left by 7 is exactly `(w (b - a) + 128) >> 8`). `tests/eight_lane_twins.rs` and
//! `tests/raster.rs` check it.

use super::format::BaseFormat;
use super::sample::{FastLevel, LevelPlan, LodSelect};
use crate::common::cpu::available;
use crate::common::values::WrapMode;

/// Eight pixels' texels as four channel arrays (R, G, B, A).
pub type Texels8 = [[f32; 8]; 4];

/// One level prepared for [`filter8`]: unsigned-byte texels of one to four components, the
/// base format that expands them to R, G, B, A, and per-axis wrapping.
#[derive(Clone, Copy, Debug)]
pub struct Level8<'a> {
    texels: &'a [u8],
    /// Levels of fewer than four bytes are read from this zero-padded copy, so that every
    /// four-byte read stays inside the buffer.
    tiny: Option<[u8; 4]>,
    components: i32,
    base: BaseFormat,
    size: [i32; 2],
    /// Per axis: `Some(mask)` for power-of-two `REPEAT`, `None` for `CLAMP_TO_EDGE`.
    repeat_mask: [Option<i32>; 2],
    /// `size * 256` per axis as f32 (exact), the scale of LINEAR's fixed-point coordinates.
    scale256: [f32; 2],
    /// Whether `x86::pairs8` may read texel pairs: not a `tiny` level, and every byte
    /// offset fits an `i32`.
    pairs: bool,
}

impl<'a> Level8<'a> {
    /// The base format the texels expand by.
    pub fn base(&self) -> BaseFormat {
        self.base
    }

    /// `lvl` (texels of base format `base`: RGBA, RGB, LUMINANCE_ALPHA, LUMINANCE, INTENSITY
    /// or ALPHA, one byte per component) under wrap modes `wrap`, or `None` when the format,
    /// the modes or the size are not ones [`filter8`] handles.
    pub fn new(lvl: &FastLevel<'a>, wrap: [WrapMode; 2], base: BaseFormat) -> Option<Level8<'a>> {
        let components = match base {
            BaseFormat::Rgba => 4,
            BaseFormat::Rgb => 3,
            BaseFormat::LuminanceAlpha => 2,
            BaseFormat::Luminance | BaseFormat::Intensity | BaseFormat::Alpha => 1,
            _ => return None,
        };
        let size = lvl.size();
        if size[0] < 1 || size[1] < 1 || size[0] > 1 << 15 || size[1] > 1 << 15 {
            return None;
        }
        let size = [size[0] as i32, size[1] as i32];
        let texels = lvl.texels();
        let bytes = size[0] as usize * size[1] as usize * components as usize;
        if texels.len() < bytes {
            return None;
        }
        let tiny = (bytes < 4).then(|| {
            let mut t = [0u8; 4];
            t[..bytes].copy_from_slice(&texels[..bytes]);
            t
        });
        let mut repeat_mask = [None; 2];
        for d in 0..2 {
            repeat_mask[d] = match wrap[d] {
                WrapMode::Repeat if size[d] & (size[d] - 1) == 0 => Some(size[d] - 1),
                WrapMode::ClampToEdge => None,
                _ => return None,
            };
        }
        let pairs = tiny.is_none() && bytes < i32::MAX as usize - 16;
        Some(Level8 {
            texels,
            tiny,
            components,
            base,
            size,
            repeat_mask,
            scale256: size.map(|n| n as f32 * 256.0),
            pairs,
        })
    }
}

/// NEAREST or LINEAR filtering of `lvl` at eight (s, t) pairs (finite), or `None` when the
/// processor lacks AVX2 or a coordinate is too large for 32-bit texel indices (the caller
/// then filters those pixels one by one).
#[inline]
pub fn filter8(lvl: &Level8, linear: bool, s: &[f32; 8], t: &[f32; 8]) -> Option<Texels8> {
    #[cfg(target_arch = "x86_64")]
    {
        if available() {
            // SAFETY: AVX2 is present (checked just above).
            return unsafe { x86::filter8(lvl, linear, s, t) };
        }
    }
    let _ = (lvl, linear, s, t);
    None
}

/// The s and t of pixels at centres `x + j` (j < `count` <= 8) on a row of an affine span,
/// as the fragment stage computes them one by one: each plane `[a, b * y, c]` evaluated as
/// `(a * x + b * y) + c` in f64, divided by 1/w (`w`) then by q, rounded to f32, a coordinate
/// that is not finite replaced by 0. Lanes from `count` on are 0. `None` when a lane's plane
/// value divided by `w` is not finite (the caller takes the one-by-one path) or without AVX2.
#[inline]
pub fn coords8(
    planes: [[f64; 3]; 2],
    w: f64,
    q: f64,
    x: f64,
    count: usize,
) -> Option<[[f32; 8]; 2]> {
    #[cfg(target_arch = "x86_64")]
    {
        if available() {
            // SAFETY: AVX2 is present (checked just above).
            return unsafe { x86::coords8(planes, w, q, x, count) };
        }
    }
    let _ = (planes, w, q, x, count);
    None
}

/// s/q and t/q (f64) at the eight pixel centres `x + j` (j < 8) of two rows of a perspective
/// span, as the fragment stage computes them one by one: each plane `[a, b * y, c]` of
/// `planes[row]` (s, t, q) evaluated as `(a * x + b * y) + c`, then s and t divided by q.
/// Answers `[row][s or t][lane]`; `None` without AVX2.
#[inline]
pub fn perspective_rows8(planes: &[[[f64; 3]; 3]; 2], x: f64) -> Option<[[[f64; 8]; 2]; 2]> {
    #[cfg(target_arch = "x86_64")]
    {
        if available() {
            // SAFETY: AVX2 is present (checked just above).
            return Some(unsafe { x86::perspective_rows8(planes, x) });
        }
    }
    let _ = (planes, x);
    None
}

/// s/q and t/q (f64) at the pixel centres of a 4x2 block, as the fragment stage computes them
/// one by one: lanes 0..4 are `x + j` on the row of `planes[0]`, lanes 4..8 the same columns
/// on the row of `planes[1]`; each plane `[a, b * y, c]` (s, t, q) evaluated as
/// `(a * x + b * y) + c`, then s and t divided by q. Answers `[s or t][lane]`; `None` without
/// AVX2.
#[inline]
pub fn perspective_block8(planes: &[[[f64; 3]; 3]; 2], x: f64) -> Option<[[f64; 8]; 2]> {
    #[cfg(target_arch = "x86_64")]
    {
        if available() {
            // SAFETY: AVX2 is present (checked just above).
            return Some(unsafe { x86::perspective_block8(planes, x) });
        }
    }
    let _ = (planes, x);
    None
}

/// Cube-map face selection for a 4x2 block of a perspective span: lanes 0..4 the pixels
/// centred at `x + j` on row 0 of `planes` (s, t, q as `[a, b * y, c]`) and `r` (the r
/// plane), lanes 4..8 the same columns on row 1. Per lane the direction (s/q, t/q, r/q in
/// f64, each plane evaluated as `(a * x + b * y) + c`, rounded to f32, a component that is not
/// finite as 0, as `Perspective8::direction` and `unit_coords` give it), then the face and
/// face coordinates of [`cube_face`](super::sample::cube_face) (the same comparisons, ties
/// and f32 operations, eight lanes at once). Answers the faces and the s and t per lane;
/// `None` without AVX2.
#[inline]
pub fn cube_block_faces8(
    planes: &[[[f64; 3]; 3]; 2],
    r: &[[f64; 3]; 2],
    x: f64,
) -> Option<([u32; 8], [f32; 8], [f32; 8])> {
    #[cfg(target_arch = "x86_64")]
    {
        if available() {
            // SAFETY: AVX2 is present (checked just above).
            return Some(unsafe { x86::cube_block_faces8(planes, r, x) });
        }
    }
    let _ = (planes, r, x);
    None
}

/// The texels of a 4x2 block of a perspective span in one go, as `Perspective8::texels_block`
/// computes them (coordinates by [`perspective_block8`] rounded to f32, non-finite as 0;
/// each live quad's level plan from its derivatives, or the draw's `fixed_plan`; quads of one
/// plan filtered together, two levels mixed per lane) for a 2D texture whose levels are
/// `levels`; lanes outside `live` are filtered at 0. `None` without AVX2, for other targets,
/// where a level does not take the filter or [`filter8`] would answer `None` (the caller
/// then takes the usual route, which gives the same texels).
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn block_texels8(
    planes: &[[[f64; 3]; 3]; 2],
    x: f64,
    live: u8,
    fixed_plan: Option<(usize, bool)>,
    lod: &LodSelect,
    levels: &[Option<Level8>],
    out: &mut Texels8,
) -> Option<()> {
    #[cfg(target_arch = "x86_64")]
    {
        if available() {
            // SAFETY: AVX2 is present (checked just above).
            return unsafe { x86::block_texels8(planes, x, live, fixed_plan, lod, levels, out) };
        }
    }
    let _ = (planes, x, live, fixed_plan, lod, levels, out);
    None
}

/// Two levels of one texture filtered at eight (s, t) pairs and mixed per lane with the
/// second's weight `weight[j]` (quantised by
/// [`fixed::level_weight`](super::fixed::level_weight)), as the sampler mixes them; `None` as
/// for [`filter8`].
#[inline]
pub fn filter8_mix(
    levels: [&Level8; 2],
    linear: bool,
    s: &[f32; 8],
    t: &[f32; 8],
    weight: &[f32; 8],
) -> Option<Texels8> {
    #[cfg(target_arch = "x86_64")]
    {
        if available() {
            // SAFETY: AVX2 is present (checked just above).
            return unsafe { x86::filter8_mix(levels, linear, s, t, weight) };
        }
    }
    let _ = (levels, linear, s, t, weight);
    None
}

#[cfg(target_arch = "x86_64")]
pub(crate) mod x86 {
    use std::arch::x86_64::*;

    use super::{Level8, LevelPlan, LodSelect, Texels8};
    use crate::texture::format::BaseFormat;

    /// Largest |floor(u)| handled: indices and index + 1 stay far from `i32` overflow.
    const MAX_INDEX: f64 = (1 << 30) as f64;

    /// Integer floor and fraction of `s * size - offset` for eight lanes (each lane as
    /// `floor_frac` in the sampler), or `None` when a floor exceeds [`MAX_INDEX`].
    #[inline]
    #[target_feature(enable = "avx2")]
    fn floor_frac8(s: __m256, size: i32, offset: f64) -> Option<(__m256i, __m256)> {
        let n = _mm256_set1_pd(size as f64);
        let off = _mm256_set1_pd(offset);
        let limit = _mm256_set1_pd(MAX_INDEX);
        let sign = _mm256_set1_pd(-0.0);
        let half = |v: __m128| {
            let u = _mm256_sub_pd(_mm256_mul_pd(_mm256_cvtps_pd(v), n), off);
            let f = _mm256_floor_pd(u);
            let too_big = _mm256_cmp_pd::<_CMP_GE_OQ>(_mm256_andnot_pd(sign, f), limit);
            (
                _mm256_cvttpd_epi32(f),
                _mm256_cvtpd_ps(_mm256_sub_pd(u, f)),
                _mm256_movemask_pd(too_big),
            )
        };
        let (i_lo, f_lo, big_lo) = half(_mm256_castps256_ps128(s));
        let (i_hi, f_hi, big_hi) = half(_mm256_extractf128_ps::<1>(s));
        if big_lo | big_hi != 0 {
            return None;
        }
        Some((_mm256_set_m128i(i_hi, i_lo), _mm256_set_m128(f_hi, f_lo)))
    }

    /// Wraps integer texel coordinates: a power-of-two mask, or a clamp to [0, size - 1].
    #[inline]
    #[target_feature(enable = "avx2")]
    fn wrap8(i: __m256i, size: i32, mask: Option<i32>) -> __m256i {
        match mask {
            Some(m) => _mm256_and_si256(i, _mm256_set1_epi32(m)),
            None => _mm256_min_epi32(
                _mm256_max_epi32(i, _mm256_setzero_si256()),
                _mm256_set1_epi32(size - 1),
            ),
        }
    }

    /// The stored components of the texels at (x, y), as in memory: byte k of each lane is
    /// component k (the bytes past the texel's components are whatever follows it).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn words8(lvl: &Level8, x: __m256i, y: __m256i) -> __m256i {
        let idx = _mm256_add_epi32(_mm256_mullo_epi32(y, _mm256_set1_epi32(lvl.size[0])), x);
        let base_ptr = match &lvl.tiny {
            Some(t) => t.as_ptr(),
            None => lvl.texels.as_ptr(),
        };
        if lvl.components == 4 {
            // SAFETY: wrapping keeps 0 <= x < width and 0 <= y < height, so 0 <= idx < width *
            // height; `Level8::new` checked that `texels` holds width * height * 4 bytes, so
            // each 4-byte read at byte offset idx * 4 lies inside it. Gathers need no
            // alignment.
            unsafe { _mm256_i32gather_epi32::<4>(base_ptr as *const i32, idx) }
        } else {
            // A texel of c < 4 bytes at byte b is read as the four bytes ending at b + c (or
            // starting at 0), then shifted down so that its first byte is the low byte.
            let c = _mm256_set1_epi32(lvl.components);
            let b = _mm256_mullo_epi32(idx, c);
            let start = _mm256_max_epi32(
                _mm256_sub_epi32(_mm256_add_epi32(b, c), _mm256_set1_epi32(4)),
                _mm256_setzero_si256(),
            );
            let shift = _mm256_slli_epi32::<3>(_mm256_sub_epi32(b, start));
            // SAFETY: 0 <= idx < width * height as above, so b + c <= width * height * c,
            // which `Level8::new` checked is at most the length of `texels`; or, for levels
            // of fewer than four bytes, start is 0 and the read covers `tiny`'s four bytes.
            // So each 4-byte read at byte offset `start` = max(b + c - 4, 0) lies inside the
            // buffer read.
            let words = unsafe { _mm256_i32gather_epi32::<1>(base_ptr as *const i32, start) };
            _mm256_srlv_epi32(words, shift)
        }
    }

    /// Per 64-bit element of a pair read of texels of c = 1, 2, 3 bytes ([`pairs8`]): the
    /// first texel's c bytes (at 8 - 2c) into bytes 0..c, the second's (at 8 - c) into bytes
    /// 4..4 + c, the rest zero (-1 as index); indices within each 128-bit half.
    const fn pair_pick(c: i32) -> [i8; 32] {
        let mut idx = [-1i8; 32];
        let mut i = 0;
        while i < 32 {
            let (e, k) = (i / 8, i % 8);
            let (texel, b) = ((k / 4) as i32, (k % 4) as i32);
            if b < c {
                idx[i] = (8 - 2 * c + texel * c + b + 8 * (e % 2) as i32) as i8;
            }
            i += 1;
        }
        idx
    }

    /// [`pair_pick`] for c = 1, 2, 3 (index c - 1), and an unused entry.
    const PAIR_PICK: [[i8; 32]; 4] = [pair_pick(1), pair_pick(2), pair_pick(3), [-1; 32]];

    /// The texel words at (x0, y) and (x1, y) of rows y0 and y1 of a level of one to four
    /// bytes per texel, as [`words8`] reads them (the bytes past a texel's components zero
    /// instead of whatever follows it: no reader looks at them), when every lane's x1 is
    /// x0 + 1 (no lane wrapped or clamped between its two columns): then each lane's two
    /// texels are consecutive bytes, read as one 64-bit element (half the elements
    /// [`words8`] gathers, and one address per row instead of one per texel). Four-byte
    /// texels are the eight bytes at x0; texels of c < 4 bytes the eight bytes ending with
    /// the second texel, whose 2c bytes a constant byte shuffle moves into the two words,
    /// when that read starts inside the level for every lane. `None` otherwise.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn pairs8(
        lvl: &Level8,
        x0: __m256i,
        x1: __m256i,
        y0: __m256i,
        y1: __m256i,
    ) -> Option<([__m256i; 2], [__m256i; 2])> {
        if !lvl.pairs {
            return None;
        }
        let c = lvl.components;
        let next = _mm256_cmpeq_epi32(x1, _mm256_add_epi32(x0, _mm256_set1_epi32(1)));
        // Byte offsets of each lane's eight bytes: (y w + x0) c + (2c - 8) for c < 4 (the read
        // ends with the second texel), (y w + x0) 4 for c = 4.
        let pitch = _mm256_set1_epi32(lvl.size[0] * c);
        let first = match c {
            4 => _mm256_slli_epi32::<2>(x0),
            3 => _mm256_add_epi32(
                _mm256_add_epi32(x0, x0),
                _mm256_add_epi32(x0, _mm256_set1_epi32(-2)),
            ),
            2 => _mm256_add_epi32(_mm256_add_epi32(x0, x0), _mm256_set1_epi32(-4)),
            _ => _mm256_add_epi32(x0, _mm256_set1_epi32(-6)),
        };
        let start0 = _mm256_add_epi32(_mm256_mullo_epi32(y0, pitch), first);
        let start1 = _mm256_add_epi32(_mm256_mullo_epi32(y1, pitch), first);
        let ok = if c == 4 {
            next
        } else {
            // Reads that would start before the level (its first texels) take `words8`.
            let m1 = _mm256_set1_epi32(-1);
            _mm256_and_si256(
                next,
                _mm256_and_si256(
                    _mm256_cmpgt_epi32(start0, m1),
                    _mm256_cmpgt_epi32(start1, m1),
                ),
            )
        };
        if _mm256_movemask_epi8(ok) != -1 {
            return None;
        }
        let pick = match c {
            4 => None,
            // SAFETY: 32 bytes; unaligned load.
            _ => Some(unsafe {
                _mm256_loadu_si256(PAIR_PICK[(c - 1) as usize & 3].as_ptr() as *const __m256i)
            }),
        };
        let ptr = lvl.texels.as_ptr() as *const i64;
        let row = |start: __m256i| {
            // SAFETY: wrapping keeps 0 <= x0 < width and 0 <= y < height, and x1 = x0 + 1 is
            // a wrapped column too, so x0 + 1 < width: texels y w + x0 and y w + x0 + 1 both
            // lie in row y, inside the width * height * c bytes `Level8::new` checked
            // `texels` holds. The eight bytes read end with the second texel (c < 4) or are
            // the two texels (c = 4), and start at byte `start` >= 0 (checked above for
            // c < 4), so each read lies inside `texels`. Gathers need no alignment.
            let (mut lo, mut hi) = unsafe {
                (
                    _mm256_i32gather_epi64::<1>(ptr, _mm256_castsi256_si128(start)),
                    _mm256_i32gather_epi64::<1>(ptr, _mm256_extracti128_si256::<1>(start)),
                )
            };
            if let Some(p) = pick {
                lo = _mm256_shuffle_epi8(lo, p);
                hi = _mm256_shuffle_epi8(hi, p);
            }
            // Each 128-bit half: [a0, a2, b0, b2] (first texels), [a1, a3, b1, b3] (second),
            // lanes 0, 1, 4, 5 then 2, 3, 6, 7; the 64-bit quarters reordered to 0..8.
            let first = _mm256_castps_si256(_mm256_shuffle_ps::<0b10_00_10_00>(
                _mm256_castsi256_ps(lo),
                _mm256_castsi256_ps(hi),
            ));
            let second = _mm256_castps_si256(_mm256_shuffle_ps::<0b11_01_11_01>(
                _mm256_castsi256_ps(lo),
                _mm256_castsi256_ps(hi),
            ));
            [
                _mm256_permute4x64_epi64::<0b11_01_10_00>(first),
                _mm256_permute4x64_epi64::<0b11_01_10_00>(second),
            ]
        };
        Some((row(start0), row(start1)))
    }

    /// R, G, B, A of texels whose stored components are the bytes of `words` (as
    /// [`words8`] reads them): each byte as `byte as f32 * (1 / 255)`, as `TexImage::fetch`
    /// converts, expanded by the base format.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn texels_of_words(lvl: &Level8, words: __m256i) -> [__m256; 4] {
        let byte = _mm256_set1_epi32(0xFF);
        let k = _mm256_set1_ps(1.0 / 255.0);
        let ch = |v: __m256i| _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_and_si256(v, byte)), k);
        // The stored components in order (only the first `components` are read).
        let mut stored = [_mm256_setzero_ps(); 4];
        stored[0] = ch(words);
        if lvl.components > 1 {
            stored[1] = ch(_mm256_srli_epi32::<8>(words));
        }
        if lvl.components > 2 {
            stored[2] = ch(_mm256_srli_epi32::<16>(words));
        }
        if lvl.components > 3 {
            stored[3] = ch(_mm256_srli_epi32::<24>(words));
        }
        expand8(lvl.base, stored)
    }

    /// Per-lane weights (0..=255 in 32-bit lanes) as 16-bit lanes matching
    /// `_mm256_unpacklo_epi8` and `_mm256_unpackhi_epi8` of texel words: each weight four
    /// times (one per component).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn weights16(w: __m256i) -> (__m256i, __m256i) {
        let w2 = _mm256_or_si256(w, _mm256_slli_epi32::<16>(w));
        (_mm256_unpacklo_epi32(w2, w2), _mm256_unpackhi_epi32(w2, w2))
    }

    /// `a + ((w (b - a) + 128) >> 8)` in 16-bit lanes holding bytes (`fixed::lerp`): the
    /// difference times 128 fits 16 bits, and `pmulhrsw` gives `(w d 128 + 2^14) >> 15`.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn lerp16(a: __m256i, b: __m256i, w: __m256i) -> __m256i {
        let d = _mm256_slli_epi16::<7>(_mm256_sub_epi16(b, a));
        _mm256_add_epi16(a, _mm256_mulhrs_epi16(w, d))
    }

    /// Texel words `a` and `b` mixed bytewise with per-lane weights `w` (`fixed::lerp4`).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn lerp_words(a: __m256i, b: __m256i, w: __m256i) -> __m256i {
        let z = _mm256_setzero_si256();
        let (wl, wh) = weights16(w);
        let lo = lerp16(_mm256_unpacklo_epi8(a, z), _mm256_unpacklo_epi8(b, z), wl);
        let hi = lerp16(_mm256_unpackhi_epi8(a, z), _mm256_unpackhi_epi8(b, z), wh);
        _mm256_packus_epi16(lo, hi)
    }

    /// The texel indices and weights of LINEAR filtering for eight lanes, of `s` along an axis
    /// of `w` texels and of `t` along one of `h`, as
    /// [`fixed::linear_axis`](crate::texture::fixed::linear_axis) before wrapping:
    /// `k = round_even(s * (size * 256)) - 128` in f32 (`size * 256` given per axis as
    /// `Level8::scale256`), the first index `k >> 8`, the weight `k & 255`. `None` when
    /// |s w 256| or |t h 256| reaches 2^30 (one test for both; the
    /// caller filters those pixels one by one).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn fixed8x2(
        s: __m256,
        t: __m256,
        [sw, sh]: [f32; 2],
    ) -> Option<((__m256i, __m256i), (__m256i, __m256i))> {
        let xs = _mm256_mul_ps(s, _mm256_set1_ps(sw));
        let xt = _mm256_mul_ps(t, _mm256_set1_ps(sh));
        let limit = _mm256_set1_ps((1u32 << 30) as f32);
        let sign = _mm256_set1_ps(-0.0);
        let big = _mm256_or_ps(
            _mm256_cmp_ps::<_CMP_GE_OQ>(_mm256_andnot_ps(sign, xs), limit),
            _mm256_cmp_ps::<_CMP_GE_OQ>(_mm256_andnot_ps(sign, xt), limit),
        );
        if _mm256_movemask_ps(big) != 0 {
            return None;
        }
        let split = |x: __m256| {
            // `cvtps2dq` rounds by MXCSR, which Rust code runs with its default (to nearest,
            // ties to even): for |x| < 2^30 (checked above) it gives what `round_ties_even`
            // then truncation give, in one instruction instead of two (NaN as i32::MIN
            // either way).
            let k = _mm256_sub_epi32(_mm256_cvtps_epi32(x), _mm256_set1_epi32(128));
            (
                _mm256_srai_epi32::<8>(k),
                _mm256_and_si256(k, _mm256_set1_epi32(255)),
            )
        };
        Some((split(xs), split(xt)))
    }

    /// NEAREST filtering of `lvl` at `s`, `t` as texel words ([`words8`]).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn nearest8_words(lvl: &Level8, s: __m256, t: __m256) -> Option<__m256i> {
        let [w, h] = lvl.size;
        let [mx, my] = lvl.repeat_mask;
        let (x, _) = floor_frac8(s, w, 0.0)?;
        let (y, _) = floor_frac8(t, h, 0.0)?;
        Some(words8(lvl, wrap8(x, w, mx), wrap8(y, h, my)))
    }

    /// LINEAR filtering of `lvl` at `s`, `t` in the fixed point of `texture::fixed`, the
    /// stored components as 16-bit lanes before they are packed to texel words: pixels 0, 1
    /// and 4, 5 (the unpacked low halves of the 128-bit lanes), then 2, 3 and 6, 7. Each
    /// value is a byte (a lerp stays between its ends), so `_mm256_packus_epi16` of the two
    /// gives the texel words losslessly.
    /// (A macro, so that [`filter8_words2`] holds both levels' filters in one body: as a
    /// function called from two places it was compiled out of line, its results passed
    /// through memory. A `None` returns from the function it is used in.)
    macro_rules! bilinear8_halves {
        ($lvl:expr, $s:expr, $t:expr) => {{
            let (lvl, s, t): (&Level8, __m256, __m256) = ($lvl, $s, $t);
            let [w, h] = lvl.size;
            let [mx, my] = lvl.repeat_mask;
            let ((x, wx), (y, wy)) = fixed8x2(s, t, lvl.scale256)?;
            let one = _mm256_set1_epi32(1);
            let (x0, x1) = (wrap8(x, w, mx), wrap8(_mm256_add_epi32(x, one), w, mx));
            let (y0, y1) = (wrap8(y, h, my), wrap8(_mm256_add_epi32(y, one), h, my));
            let ([t00, t10], [t01, t11]) = match pairs8(lvl, x0, x1, y0, y1) {
                Some(p) => p,
                None => (
                    [words8(lvl, x0, y0), words8(lvl, x1, y0)],
                    [words8(lvl, x0, y1), words8(lvl, x1, y1)],
                ),
            };
            let z = _mm256_setzero_si256();
            let (wxl, wxh) = weights16(wx);
            let (wyl, wyh) = weights16(wy);
            // Pixels 0, 1 and 4, 5 (the low halves of the 128-bit lanes), then 2, 3 and 6, 7.
            let lo = {
                let row0 = lerp16(
                    _mm256_unpacklo_epi8(t00, z),
                    _mm256_unpacklo_epi8(t10, z),
                    wxl,
                );
                let row1 = lerp16(
                    _mm256_unpacklo_epi8(t01, z),
                    _mm256_unpacklo_epi8(t11, z),
                    wxl,
                );
                lerp16(row0, row1, wyl)
            };
            let hi = {
                let row0 = lerp16(
                    _mm256_unpackhi_epi8(t00, z),
                    _mm256_unpackhi_epi8(t10, z),
                    wxh,
                );
                let row1 = lerp16(
                    _mm256_unpackhi_epi8(t01, z),
                    _mm256_unpackhi_epi8(t11, z),
                    wxh,
                );
                lerp16(row0, row1, wyh)
            };
            (lo, hi)
        }};
    }

    /// The stored components of NEAREST or LINEAR filtering of `lvl` at `s`, `t`, as texel
    /// words ([`words8`]); LINEAR in the fixed point of `texture::fixed`.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn filter8_words(lvl: &Level8, linear: bool, s: __m256, t: __m256) -> Option<__m256i> {
        if !linear {
            return nearest8_words(lvl, s, t);
        }
        let (lo, hi) = bilinear8_halves!(lvl, s, t);
        Some(_mm256_packus_epi16(lo, hi))
    }

    /// [`filter8_words`] of `l1` and of `l2` mixed per lane with the second's weight `weight`
    /// (0..=255 per 32-bit lane), as [`lerp_words`] of the two: for LINEAR the two levels'
    /// 16-bit results are mixed before they are packed (the same bytes: packing and
    /// unpacking bytes is lossless), in one call.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn filter8_words2(
        l1: &Level8,
        l2: &Level8,
        linear: bool,
        s: __m256,
        t: __m256,
        weight: __m256i,
    ) -> Option<__m256i> {
        if !linear {
            let a = nearest8_words(l1, s, t)?;
            let b = nearest8_words(l2, s, t)?;
            return Some(lerp_words(a, b, weight));
        }
        let (alo, ahi) = bilinear8_halves!(l1, s, t);
        let (blo, bhi) = bilinear8_halves!(l2, s, t);
        let (wl, wh) = weights16(weight);
        Some(_mm256_packus_epi16(
            lerp16(alo, blo, wl),
            lerp16(ahi, bhi, wh),
        ))
    }

    /// The eight lanes' level weights `weight` quantised
    /// ([`fixed::level_weight`](crate::texture::fixed::level_weight)).
    /// Eight lanes at once: `trunc(256 w)` of `w` clamped first to [0, 255] in f32 (the
    /// minimum with 255 first, which keeps NaN, then the maximum with 0, which answers 0 for
    /// it), so every lane is what the scalar function's saturating conversion and clamp give
    /// (unit test `level_weights8_are_the_scalar_weights`). A lane-by-lane map was 176
    /// instructions a call in `sprites`.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn level_weights8(weight: &[f32; 8]) -> __m256i {
        // SAFETY: eight f32; unaligned load.
        let w = unsafe { _mm256_loadu_ps(weight.as_ptr()) };
        let x = _mm256_mul_ps(w, _mm256_set1_ps(256.0));
        let x = _mm256_max_ps(_mm256_min_ps(_mm256_set1_ps(255.0), x), _mm256_setzero_ps());
        _mm256_cvttps_epi32(x)
    }

    /// R, G, B, A from a texel's stored components by its base format. (Filtering the stored
    /// components, then expanding, gives what expanding first would: the expansion copies
    /// components or puts constants, which lerps leave as they are.)
    #[inline]
    #[target_feature(enable = "avx2")]
    fn expand8(base: BaseFormat, c: [__m256; 4]) -> [__m256; 4] {
        let (zero, one) = (_mm256_setzero_ps(), _mm256_set1_ps(1.0));
        match base {
            BaseFormat::Rgba => c,
            BaseFormat::Rgb => [c[0], c[1], c[2], one],
            BaseFormat::LuminanceAlpha => [c[0], c[0], c[0], c[1]],
            BaseFormat::Intensity => [c[0]; 4],
            BaseFormat::Alpha => [zero, zero, zero, c[0]],
            _ => [c[0], c[0], c[0], one],
        }
    }

    /// s/q and t/q at the four pixel centres `xv` of the row of `p` (its s, t and q planes
    /// `[a, b * y, c]`, each evaluated as `(a * x + b * y) + c`).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn st_over_q4(p: &[[f64; 3]; 3], xv: __m256d) -> [__m256d; 2] {
        let eval = |k: usize| {
            let (a, by, c) = (
                _mm256_set1_pd(p[k][0]),
                _mm256_set1_pd(p[k][1]),
                _mm256_set1_pd(p[k][2]),
            );
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a, xv), by), c)
        };
        let q = eval(2);
        [_mm256_div_pd(eval(0), q), _mm256_div_pd(eval(1), q)]
    }

    /// The four pixel centres from `first`.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn centres4(first: f64) -> __m256d {
        _mm256_add_pd(_mm256_set1_pd(first), _mm256_set_pd(3.0, 2.0, 1.0, 0.0))
    }

    /// All ones in the lanes whose bit is set in `m`, zeros elsewhere.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn lane_mask(m: u8) -> __m256 {
        let bits = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
        _mm256_castsi256_ps(_mm256_cmpeq_epi32(
            _mm256_and_si256(_mm256_set1_epi32(m as i32), bits),
            bits,
        ))
    }

    /// `finite_or_zero(v as f32)` per lane.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn finite_f32(v: __m256d) -> __m128 {
        let f = _mm256_cvtpd_ps(v);
        // f - f is 0 exactly when f is finite.
        _mm_and_ps(f, _mm_cmpeq_ps(_mm_sub_ps(f, f), _mm_setzero_ps()))
    }

    /// The block's coordinates (lanes outside `live` at 0) and, per quad (lanes 0 and 2),
    /// the squared scaled lengths of its x and y derivatives for a `w` x `h` texture: each
    /// coordinate and derivative `finite_or_zero` of its f64 value rounded to f32 (what the
    /// general route takes, unit test `block_coords_are_the_general_routes`). Computed
    /// without that replacement, which changes nothing when every value used is finite; the
    /// test for that runs beside the products and, when it fails (rarely: q near 0), the
    /// block is recomputed with it ([`block_coords8_finite`]). (The replacement lay on the
    /// way from the divisions to the texel addresses.)
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn block_coords8(
        planes: &[[[f64; 3]; 3]; 2],
        x: f64,
        live: u8,
        size: Option<[f32; 2]>,
    ) -> (__m256, __m256, __m128, __m128) {
        let xv = centres4(x);
        // Lanes 0..4: the lower row (planes[0]); 4..8: the upper row.
        let [s0, t0] = st_over_q4(&planes[0], xv);
        let [s1, t1] = st_over_q4(&planes[1], xv);
        let keep = lane_mask(live);
        let s = _mm256_set_m128(_mm256_cvtpd_ps(s1), _mm256_cvtpd_ps(s0));
        let t = _mm256_set_m128(_mm256_cvtpd_ps(t1), _mm256_cvtpd_ps(t0));
        // f - f is +0 exactly when f is finite, else NaN: a sum of them is 0 when all are.
        let spread = |v: __m256| _mm256_sub_ps(v, v);
        let odd = _mm256_and_ps(_mm256_add_ps(spread(s), spread(t)), keep);
        let mut bad =
            _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_NEQ_UQ>(odd, _mm256_setzero_ps())) != 0;
        let (mut ax, mut ay) = (_mm_setzero_ps(), _mm_setzero_ps());
        if let Some([w, h]) = size {
            // Quad q is columns 2q, 2q + 1: its x derivative from the upper row, its y
            // derivative from the left column (in f64, then rounded as the lanes are), in
            // lanes 0 (q = 0) and 2 (q = 1).
            let dx = |v: __m256d| _mm256_cvtpd_ps(_mm256_sub_pd(_mm256_permute_pd::<0b0101>(v), v));
            let dy = |lo: __m256d, hi: __m256d| _mm256_cvtpd_ps(_mm256_sub_pd(hi, lo));
            let (dsx, dtx, dsy, dty) = (dx(s1), dx(t1), dy(s0, s1), dy(t0, t1));
            let spread = |v: __m128| _mm_sub_ps(v, v);
            let odd = _mm_add_ps(
                _mm_add_ps(spread(dsx), spread(dtx)),
                _mm_add_ps(spread(dsy), spread(dty)),
            );
            bad |= _mm_movemask_ps(_mm_cmpneq_ps(odd, _mm_setzero_ps())) & 0b0101 != 0;
            let (wv, hv) = (_mm_set1_ps(w), _mm_set1_ps(h));
            let rho2 = |ds: __m128, dt: __m128| {
                let (u, v) = (_mm_mul_ps(ds, wv), _mm_mul_ps(dt, hv));
                _mm_add_ps(_mm_mul_ps(u, u), _mm_mul_ps(v, v))
            };
            ax = rho2(dsx, dtx);
            ay = rho2(dsy, dty);
        }
        if bad {
            return block_coords8_finite(planes, x, live, size);
        }
        (_mm256_and_ps(s, keep), _mm256_and_ps(t, keep), ax, ay)
    }

    /// [`block_coords8`] with each value that is not finite replaced by 0 as it is rounded
    /// (`finite_f32`): for the blocks where one is not.
    #[cold]
    #[inline(never)]
    #[target_feature(enable = "avx2")]
    pub(crate) fn block_coords8_finite(
        planes: &[[[f64; 3]; 3]; 2],
        x: f64,
        live: u8,
        size: Option<[f32; 2]>,
    ) -> (__m256, __m256, __m128, __m128) {
        let xv = centres4(x);
        // Lanes 0..4: the lower row (planes[0]); 4..8: the upper row.
        let [s0, t0] = st_over_q4(&planes[0], xv);
        let [s1, t1] = st_over_q4(&planes[1], xv);
        let (mut ax, mut ay) = (_mm_setzero_ps(), _mm_setzero_ps());
        if let Some([w, h]) = size {
            // Quad q is columns 2q, 2q + 1: its x derivative from the upper row, its y
            // derivative from the left column (in f64, then rounded as the lanes are), in
            // lanes 0 (q = 0) and 2 (q = 1).
            let dx = |v: __m256d| finite_f32(_mm256_sub_pd(_mm256_permute_pd::<0b0101>(v), v));
            let dy = |lo: __m256d, hi: __m256d| finite_f32(_mm256_sub_pd(hi, lo));
            let (wv, hv) = (_mm_set1_ps(w), _mm_set1_ps(h));
            let rho2 = |ds: __m128, dt: __m128| {
                let (u, v) = (_mm_mul_ps(ds, wv), _mm_mul_ps(dt, hv));
                _mm_add_ps(_mm_mul_ps(u, u), _mm_mul_ps(v, v))
            };
            ax = rho2(dx(s1), dx(t1));
            ay = rho2(dy(s0, s1), dy(t0, t1));
        }
        // Lanes outside `live` are filtered at 0 (their results are not stored).
        let keep = lane_mask(live);
        let s = _mm256_and_ps(_mm256_set_m128(finite_f32(s1), finite_f32(s0)), keep);
        let t = _mm256_and_ps(_mm256_set_m128(finite_f32(t1), finite_f32(t0)), keep);
        (s, t, ax, ay)
    }

    /// [`LodSelect::quick_lambda256`] of the ρ² of a block's two quads (lanes 0 and 1 of
    /// `m`) at once, the same f32 and integer operations in the same order: `floor(256 λ)`
    /// per quad and a mask of the quads (bit 0, bit 1) where it decides the plan.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn quick_lambda256x2(lod: &LodSelect, m: __m128) -> ([i32; 2], u8) {
        use crate::texture::sample::{QUICK_LOD_MARGIN, QUICK_LOG2, QUICK_LOG2_CELLS};
        let m = _mm_castps_si128(m);
        // Positive normal numbers: 0x0080_0000 <= bits < 0x7F80_0000 (signed: negative
        // numbers fail).
        let normal = _mm_and_si128(
            _mm_cmpgt_epi32(m, _mm_set1_epi32(0x007F_FFFF)),
            _mm_cmpgt_epi32(_mm_set1_epi32(0x7F80_0000), m),
        );
        // `quick_log2_128` of lanes 0 and 1: the cells' chords.
        let cell = |bits: i32| QUICK_LOG2[(bits as u32 >> 15) as usize & (QUICK_LOG2_CELLS - 1)];
        let [t0, s0] = cell(_mm_cvtsi128_si32(m));
        let [t1, s1] = cell(_mm_extract_epi32::<1>(m));
        let phi = _mm_mul_ps(
            _mm_cvtepi32_ps(_mm_and_si128(m, _mm_set1_epi32(0x7FFF))),
            _mm_set1_ps(1.0 / 32768.0),
        );
        let h = _mm_add_ps(
            _mm_set_ps(0.0, 0.0, t1, t0),
            _mm_mul_ps(phi, _mm_set_ps(0.0, 0.0, s1, s0)),
        );
        let q = lod.quick_terms();
        let v = _mm_add_ps(h, _mm_set1_ps(q.bias_frac));
        let f = _mm_floor_ps(v);
        let frac = _mm_sub_ps(v, f);
        let margin = (QUICK_LOD_MARGIN * 256.0) as f32;
        let e = _mm_sub_epi32(_mm_srli_epi32::<23>(m), _mm_set1_epi32(127));
        let g = _mm_add_epi32(
            _mm_add_epi32(_mm_cvttps_epi32(f), _mm_slli_epi32::<7>(e)),
            _mm_set1_epi32(q.bias_int),
        );
        // lo <= g <= hi (|lo|, |hi| <= 2^30).
        let inside = _mm_and_si128(
            _mm_cmpgt_epi32(g, _mm_set1_epi32(q.lo - 1)),
            _mm_cmpgt_epi32(_mm_set1_epi32(q.hi + 1), g),
        );
        let ok = _mm_and_ps(
            _mm_cmpgt_ps(frac, _mm_set1_ps(margin)),
            _mm_cmplt_ps(frac, _mm_set1_ps(1.0 - margin)),
        );
        let ok = _mm_and_ps(ok, _mm_castsi128_ps(_mm_and_si128(normal, inside)));
        let mask = _mm_movemask_ps(ok) & 3;
        (
            [_mm_cvtsi128_si32(g), _mm_extract_epi32::<1>(g)],
            mask as u8,
        )
    }

    /// The stored components (texel words, [`words8`]) of one level plan at `s`, `t`, two
    /// levels mixed with the quantised weight `weight` (0..=255) per lane, and the plan's
    /// first level (whose format the words have).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn plan_words8<'l, 'a>(
        levels: &'l [Option<Level8<'a>>],
        (first, second, linear): (usize, usize, bool),
        weight: __m256i,
        s: __m256,
        t: __m256,
    ) -> Option<(__m256i, &'l Level8<'a>)> {
        let level = |l: usize| levels.get(l)?.as_ref();
        let l1 = level(first)?;
        if second == first {
            return Some((filter8_words(l1, linear, s, t)?, l1));
        }
        let words = filter8_words2(l1, level(second)?, linear, s, t, weight)?;
        Some((words, l1))
    }

    /// The level plan of quad `q` (lanes 2q of `ax`, `ay`) from the sampler's λ
    /// ([`LodSelect::plan_for_rho2`]), for the quads whose `floor(256 λ)` does not decide it:
    /// out of line, so that the usual plan is computed in [`block_words8`] itself.
    #[cold]
    #[inline(never)]
    #[target_feature(enable = "avx2")]
    fn sampler_plan(
        lod: &LodSelect,
        ax: __m128,
        ay: __m128,
        q: usize,
    ) -> ((usize, usize, bool), i32) {
        let (mut axs, mut ays) = ([0f32; 4], [0f32; 4]);
        // SAFETY: four f32 each; unaligned stores.
        unsafe {
            _mm_storeu_ps(axs.as_mut_ptr(), ax);
            _mm_storeu_ps(ays.as_mut_ptr(), ay);
        }
        match lod.plan_for_rho2(axs[2 * q], ays[2 * q]) {
            LevelPlan::One { level, linear } => ((level, level, linear), 0),
            LevelPlan::Two {
                levels: [a, b],
                linear,
                weight,
            } => (
                (a, b, linear),
                crate::texture::fixed::level_weight(weight) as i32,
            ),
        }
    }

    /// [`block_texels8`] as texel words (the stored components, [`words8`]) and the level
    /// whose format they have (`None` when no lane is live: the words are then zero). The
    /// texels [`block_texels8`] gives are [`texels_of_words`] of these words.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn block_words8<'l, 'a>(
        planes: &[[[f64; 3]; 3]; 2],
        x: f64,
        live: u8,
        fixed_plan: Option<(usize, bool)>,
        lod: &LodSelect,
        levels: &'l [Option<Level8<'a>>],
    ) -> Option<(__m256i, Option<&'l Level8<'a>>)> {
        if let Some((level, linear)) = fixed_plan {
            let (s, t, _, _) = block_coords8(planes, x, live, None);
            let none = _mm256_setzero_si256();
            let (w, l) = plan_words8(levels, (level, level, linear), none, s, t)?;
            return Some((w, Some(l)));
        }
        let (threshold, size) = lod.magnified_test()?;
        let (s, t, ax, ay) = block_coords8(planes, x, live, Some(size));
        // ρ² of quads 0 and 1 in lanes 0 and 1. (`_mm_max_ps` answers `ay` where either is
        // NaN, `f32::max` the other: for a NaN `ay` the quad is neither surely magnified nor
        // a positive normal number, and takes the sampler's route, which takes the max
        // itself.)
        let m = _mm_max_ps(ax, ay);
        let m = _mm_shuffle_ps::<0b10_00_10_00>(m, m);
        let quads = (live & 0x33 != 0) as u8 | ((live & 0xCC != 0) as u8) << 1;
        // `LodSelect::plan_for_rho2`'s test: surely magnified.
        let magnified = _mm_movemask_ps(_mm_cmple_ps(m, _mm_set1_ps(threshold))) as u8 & 3;
        let mag = ((0, 0, lod.mag_linear()), 0);
        // λ only when a live quad is not surely magnified.
        let (g, quick) = if quads & !magnified == 0 {
            ([0; 2], 0)
        } else {
            quick_lambda256x2(lod, m)
        };
        // Per quad (lanes 0, 1, 4, 5 and 2, 3, 6, 7), when it has live lanes: its levels and
        // its weight between them; from floor(256 λ) where that decides them, else from
        // the sampler's λ.
        let plan = |q: usize| {
            if magnified & (1 << q) != 0 {
                return mag;
            }
            if quick & (1 << q) != 0 {
                return lod.plan_of_lambda256(g[q]);
            }
            sampler_plan(lod, ax, ay, q)
        };
        if quads == 0 {
            return Some((_mm256_setzero_si256(), None));
        }
        // A quad without live lanes takes the other's plan (its lanes are not stored). (One
        // call of `plan`, in a loop, so that it is compiled inline.)
        let mut plans = [mag; 2];
        for (q, p) in plans.iter_mut().enumerate() {
            *p = plan(if quads == 3 {
                q
            } else {
                (quads & 1 == 0) as usize
            });
        }
        let [(p0, w0), (p1, w1)] = plans;
        let first = || _mm256_castps_si256(lane_mask(0x33));
        let weight = |w0: i32, w1: i32| {
            if w0 == w1 {
                _mm256_set1_epi32(w0)
            } else {
                _mm256_blendv_epi8(_mm256_set1_epi32(w1), _mm256_set1_epi32(w0), first())
            }
        };
        let (words, level) = if p0 == p1 {
            // One plan: filtered together, each quad with its own weight.
            plan_words8(levels, p0, weight(w0, w1), s, t)?
        } else {
            let (a, level) = plan_words8(levels, p0, _mm256_set1_epi32(w0), s, t)?;
            let (b, _) = plan_words8(levels, p1, _mm256_set1_epi32(w1), s, t)?;
            (_mm256_blendv_epi8(b, a, first()), level)
        };
        Some((words, Some(level)))
    }

    /// R, G, B, A bytes of each lane (R in the low byte) from texel words of a level of base
    /// format `base` ([`words8`]): what [`texels_of_words`] gives, as bytes (1 is 255).
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn rgba_of_words(base: BaseFormat, words: __m256i) -> __m256i {
        // Per pixel, the stored byte that each of R, G, B, A takes (-1: zero), for the four
        // pixels of each 128-bit lane.
        let pick = |rgba: [i8; 4]| {
            let mut idx = [0i8; 32];
            for (i, v) in idx.iter_mut().enumerate() {
                let (pixel, c) = ((i % 16) / 4, i % 4);
                *v = if rgba[c] < 0 {
                    -1
                } else {
                    rgba[c] + 4 * pixel as i8
                };
            }
            // SAFETY: 32 bytes; unaligned load.
            unsafe { _mm256_loadu_si256(idx.as_ptr() as *const __m256i) }
        };
        let opaque = _mm256_set1_epi32(0xFF00_0000u32 as i32);
        match base {
            BaseFormat::Rgba => words,
            BaseFormat::Rgb => {
                _mm256_or_si256(_mm256_shuffle_epi8(words, pick([0, 1, 2, -1])), opaque)
            }
            BaseFormat::LuminanceAlpha => _mm256_shuffle_epi8(words, pick([0, 0, 0, 1])),
            BaseFormat::Intensity => _mm256_shuffle_epi8(words, pick([0, 0, 0, 0])),
            BaseFormat::Alpha => _mm256_shuffle_epi8(words, pick([-1, -1, -1, 0])),
            _ => _mm256_or_si256(_mm256_shuffle_epi8(words, pick([0, 0, 0, -1])), opaque),
        }
    }

    #[allow(clippy::too_many_arguments)]
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn block_texels8(
        planes: &[[[f64; 3]; 3]; 2],
        x: f64,
        live: u8,
        fixed_plan: Option<(usize, bool)>,
        lod: &LodSelect,
        levels: &[Option<Level8>],
        out: &mut Texels8,
    ) -> Option<()> {
        let tex = match block_words8(planes, x, live, fixed_plan, lod, levels)? {
            (words, Some(level)) => texels_of_words(level, words),
            (_, None) => [_mm256_setzero_ps(); 4],
        };
        for c in 0..4 {
            // SAFETY: `out[c]` holds eight f32; unaligned store.
            unsafe { _mm256_storeu_ps(out[c].as_mut_ptr(), tex[c]) };
        }
        Some(())
    }

    /// [`super::cube_block_faces8`].
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn cube_block_faces8(
        planes: &[[[f64; 3]; 3]; 2],
        r: &[[f64; 3]; 2],
        x: f64,
    ) -> ([u32; 8], [f32; 8], [f32; 8]) {
        let (face, s, t) = cube_block_faces8_regs(planes, r, x);
        let (mut fo, mut so, mut to) = ([0u32; 8], [0f32; 8], [0f32; 8]);
        // SAFETY: eight u32 / f32 each; unaligned stores.
        unsafe {
            _mm256_storeu_si256(fo.as_mut_ptr() as *mut __m256i, face);
            _mm256_storeu_ps(so.as_mut_ptr(), s);
            _mm256_storeu_ps(to.as_mut_ptr(), t);
        }
        (fo, so, to)
    }

    /// [`cube_block_faces8`] with the faces, s and t left in registers.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn cube_block_faces8_regs(
        planes: &[[[f64; 3]; 3]; 2],
        r: &[[f64; 3]; 2],
        x: f64,
    ) -> (__m256i, __m256, __m256) {
        let xv = centres4(x);
        let eval = |p: &[f64; 3]| {
            let (a, by, c) = (
                _mm256_set1_pd(p[0]),
                _mm256_set1_pd(p[1]),
                _mm256_set1_pd(p[2]),
            );
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a, xv), by), c)
        };
        // Per row (lanes 0..4, 4..8): s/q, t/q, r/q rounded, non-finite as 0.
        let mut dir = [[_mm_setzero_ps(); 2]; 3];
        for row in 0..2 {
            let p = &planes[row];
            let q = eval(&p[2]);
            let comps = [eval(&p[0]), eval(&p[1]), eval(&r[row])];
            for (d, v) in dir.iter_mut().zip(comps) {
                d[row] = finite_f32(_mm256_div_pd(v, q));
            }
        }
        let [dx, dy, dz] = dir.map(|d| _mm256_set_m128(d[1], d[0]));
        let sign = _mm256_set1_ps(-0.0);
        let neg = |v: __m256| _mm256_xor_ps(v, sign);
        let abs = |v: __m256| _mm256_andnot_ps(sign, v);
        let (ax, ay, az) = (abs(dx), abs(dy), abs(dz));
        let zero = _mm256_setzero_ps();
        // As `cube_face`: X when ax >= ay and ax >= az, else Y when ay >= az, else Z; the
        // positive face when the major component is >= 0 (-0 included).
        let is_x = _mm256_and_ps(
            _mm256_cmp_ps::<_CMP_GE_OQ>(ax, ay),
            _mm256_cmp_ps::<_CMP_GE_OQ>(ax, az),
        );
        let is_y = _mm256_andnot_ps(is_x, _mm256_cmp_ps::<_CMP_GE_OQ>(ay, az));
        let is_z = _mm256_andnot_ps(
            _mm256_or_ps(is_x, is_y),
            _mm256_castsi256_ps(_mm256_set1_epi32(-1)),
        );
        let pos_x = _mm256_cmp_ps::<_CMP_GE_OQ>(dx, zero);
        let pos_y = _mm256_cmp_ps::<_CMP_GE_OQ>(dy, zero);
        let pos_z = _mm256_cmp_ps::<_CMP_GE_OQ>(dz, zero);
        let pick = |m: __m256, a: __m256, b: __m256| _mm256_blendv_ps(b, a, m);
        // X: (-z or z, -y, ax); Y: (x, z or -z, ay); Z: (x or -x, -y, az).
        let sc_x = pick(pos_x, neg(dz), dz);
        let sc_y = dx;
        let sc_z = pick(pos_z, dx, neg(dx));
        let tc_y = pick(pos_y, dz, neg(dz));
        let sc = pick(is_x, sc_x, pick(is_y, sc_y, sc_z));
        let tc = pick(is_y, tc_y, neg(dy));
        let ma = pick(is_x, ax, pick(is_y, ay, az));
        // Faces: 0 + (x < 0) for X, 2 + (y < 0) for Y, 4 + (z < 0) for Z.
        let one = _mm256_set1_epi32(1);
        let bit = |pos: __m256| _mm256_andnot_si256(_mm256_castps_si256(pos), one);
        let face = _mm256_or_si256(
            _mm256_and_si256(_mm256_castps_si256(is_x), bit(pos_x)),
            _mm256_or_si256(
                _mm256_and_si256(
                    _mm256_castps_si256(is_y),
                    _mm256_add_epi32(_mm256_set1_epi32(2), bit(pos_y)),
                ),
                _mm256_and_si256(
                    _mm256_castps_si256(is_z),
                    _mm256_add_epi32(_mm256_set1_epi32(4), bit(pos_z)),
                ),
            ),
        );
        let half = _mm256_set1_ps(0.5);
        let onef = _mm256_set1_ps(1.0);
        let coord = |c: __m256| _mm256_mul_ps(_mm256_add_ps(_mm256_div_ps(c, ma), onef), half);
        // ma > 0, else (0.5, 0.5).
        let big = _mm256_cmp_ps::<_CMP_GT_OQ>(ma, zero);
        let s = pick(big, coord(sc), half);
        let t = pick(big, coord(tc), half);
        (face, s, t)
    }

    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn perspective_block8(planes: &[[[f64; 3]; 3]; 2], x: f64) -> [[f64; 8]; 2] {
        let xv = centres4(x);
        let mut out = [[0f64; 8]; 2];
        for (row, p) in planes.iter().enumerate() {
            for (o, v) in out.iter_mut().zip(st_over_q4(p, xv)) {
                // SAFETY: `o` holds eight f64; lanes 4row..4row+4; unaligned store.
                unsafe { _mm256_storeu_pd(o.as_mut_ptr().add(4 * row), v) };
            }
        }
        out
    }

    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn perspective_rows8(planes: &[[[f64; 3]; 3]; 2], x: f64) -> [[[f64; 8]; 2]; 2] {
        let xs = [centres4(x), centres4(x + 4.0)];
        let mut out = [[[0f64; 8]; 2]; 2];
        for (row, p) in planes.iter().enumerate() {
            for (h, &xv) in xs.iter().enumerate() {
                for (o, v) in out[row].iter_mut().zip(st_over_q4(p, xv)) {
                    // SAFETY: `o` holds eight f64; lanes 4h..4h+4; unaligned store.
                    unsafe { _mm256_storeu_pd(o.as_mut_ptr().add(4 * h), v) };
                }
            }
        }
        out
    }

    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn coords8(
        planes: [[f64; 3]; 2],
        w: f64,
        q: f64,
        x: f64,
        count: usize,
    ) -> Option<[[f32; 8]; 2]> {
        if w == 1.0 && q == 1.0 {
            coords8_div::<false>(planes, w, q, x, count)
        } else {
            coords8_div::<true>(planes, w, q, x, count)
        }
    }

    /// [`coords8`], with `DIV` false only for `w` and `q` both 1: a division by 1 is the
    /// identity (NaN stays NaN, which is refused either way), and skipping the four divisions
    /// takes the longest latency out of a group (chosen per loop by the caller, not per
    /// group: a select would still divide).
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn coords8_div<const DIV: bool>(
        planes: [[f64; 3]; 2],
        w: f64,
        q: f64,
        x: f64,
        count: usize,
    ) -> Option<[[f32; 8]; 2]> {
        let lanes =
            |first: f64| _mm256_add_pd(_mm256_set1_pd(first), _mm256_set_pd(3.0, 2.0, 1.0, 0.0));
        let xs = [lanes(x), lanes(x + 4.0)];
        // Lanes before `count`, per half.
        let live = |half: i64| {
            let j = _mm256_set_epi64x(half + 3, half + 2, half + 1, half);
            _mm256_castsi256_pd(_mm256_cmpgt_epi64(_mm256_set1_epi64x(count as i64), j))
        };
        let live = [live(0), live(4)];
        let (wv, qv, zero) = (_mm256_set1_pd(w), _mm256_set1_pd(q), _mm256_setzero_pd());
        // A division by exactly 1 is the identity in IEEE arithmetic (a NaN stays a NaN, and
        // is caught as not finite either way): skipped (affine spans have w = 1, and q = 1
        // unless the coordinates set it).
        let (by_w, by_q) = (w != 1.0, q != 1.0);
        let mut out = [[0f32; 8]; 2];
        for (k, p) in planes.iter().enumerate() {
            let (a, by, c) = (
                _mm256_set1_pd(p[0]),
                _mm256_set1_pd(p[1]),
                _mm256_set1_pd(p[2]),
            );
            let mut halves = [_mm_setzero_ps(); 2];
            for h in 0..2 {
                let v = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a, xs[h]), by), c);
                let v = if DIV && by_w { _mm256_div_pd(v, wv) } else { v };
                // v - v is 0 exactly when v is finite.
                let finite = _mm256_cmp_pd::<_CMP_EQ_OQ>(_mm256_sub_pd(v, v), zero);
                if _mm256_movemask_pd(_mm256_andnot_pd(finite, live[h])) != 0 {
                    return None;
                }
                let f = _mm256_cvtpd_ps(if DIV && by_q { _mm256_div_pd(v, qv) } else { v });
                let ok = _mm_cmpeq_ps(_mm_sub_ps(f, f), _mm_setzero_ps());
                let j = 4 * h as i32;
                let live32 = _mm_cmpgt_epi32(
                    _mm_set1_epi32(count as i32),
                    _mm_set_epi32(j + 3, j + 2, j + 1, j),
                );
                let ok = _mm_and_ps(ok, _mm_castsi128_ps(live32));
                halves[h] = _mm_and_ps(f, ok);
            }
            let v = _mm256_set_m128(halves[1], halves[0]);
            // SAFETY: `out[k]` holds eight f32; unaligned store.
            unsafe { _mm256_storeu_ps(out[k].as_mut_ptr(), v) };
        }
        Some(out)
    }

    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn filter8(
        lvl: &Level8,
        linear: bool,
        s: &[f32; 8],
        t: &[f32; 8],
    ) -> Option<Texels8> {
        // SAFETY: `s` and `t` hold eight f32 each; unaligned loads.
        let (s, t) = unsafe { (_mm256_loadu_ps(s.as_ptr()), _mm256_loadu_ps(t.as_ptr())) };
        let out = filter8_regs(lvl, linear, s, t)?;
        let mut res = [[0f32; 8]; 4];
        for c in 0..4 {
            // SAFETY: `res[c]` holds eight f32; unaligned store.
            unsafe { _mm256_storeu_ps(res[c].as_mut_ptr(), out[c]) };
        }
        Some(res)
    }

    /// [`filter8`] with coordinates and texels in registers.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn filter8_regs(
        lvl: &Level8,
        linear: bool,
        s: __m256,
        t: __m256,
    ) -> Option<[__m256; 4]> {
        Some(texels_of_words(lvl, filter8_words(lvl, linear, s, t)?))
    }

    /// The texel words ([`words8`]) of NEAREST or LINEAR filtering of `levels[0]` at `s`,
    /// `t`, or with a level weight, of both levels mixed as [`filter8_mix`] mixes them (the
    /// words [`filter8_regs`] and [`filter8_mix`] convert to f32; `levels[0]`'s format).
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn filter8_words_mix(
        levels: &[Level8; 2],
        linear: bool,
        s: __m256,
        t: __m256,
        weight: Option<f32>,
    ) -> Option<__m256i> {
        let Some(w) = weight else {
            return filter8_words(&levels[0], linear, s, t);
        };
        filter8_words2(
            &levels[0],
            &levels[1],
            linear,
            s,
            t,
            level_weights8(&[w; 8]),
        )
    }

    /// [`filter8_mix`](super::filter8_mix) with coordinates and texels in registers, the
    /// weights quantised ([`level_weights8`]).
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn filter8_mix_regs(
        levels: [&Level8; 2],
        linear: bool,
        s: __m256,
        t: __m256,
        weights: __m256i,
    ) -> Option<[__m256; 4]> {
        let words = filter8_words2(levels[0], levels[1], linear, s, t, weights)?;
        Some(texels_of_words(levels[0], words))
    }

    /// [`filter8_mix`](super::filter8_mix).
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(crate) fn filter8_mix(
        levels: [&Level8; 2],
        linear: bool,
        s: &[f32; 8],
        t: &[f32; 8],
        weight: &[f32; 8],
    ) -> Option<Texels8> {
        // SAFETY: `s` and `t` hold eight f32 each; unaligned loads.
        let (s, t) = unsafe { (_mm256_loadu_ps(s.as_ptr()), _mm256_loadu_ps(t.as_ptr())) };
        let out = filter8_mix_regs(levels, linear, s, t, level_weights8(weight))?;
        let mut res = [[0f32; 8]; 4];
        for c in 0..4 {
            // SAFETY: `res[c]` holds eight f32; unaligned store.
            unsafe { _mm256_storeu_ps(res[c].as_mut_ptr(), out[c]) };
        }
        Some(res)
    }
}

#[cfg(test)]
mod tests {
    /// A coordinate as the lanes keep it: rounded to f32, non-finite values 0.
    fn fix(v: f64) -> f32 {
        let f = v as f32;
        if f.is_finite() {
            f
        } else {
            0.0
        }
    }

    /// `block_coords8` gives the general route's coordinates and ρ² (`Perspective8::
    /// texels_block` when the block kernel declines): per lane s/q and t/q in f64
    /// (`perspective_block8`) rounded to f32 with a value that is not finite as 0, lanes
    /// outside `live` 0; per quad the x derivative from the upper row, the y derivative
    /// from the left column, each rounded and fixed up alike, and `(ds w)² + (dt h)²`. Bit
    /// for bit, over random planes and planes whose q passes through 0 inside the block or
    /// whose s is huge (values that overflow f32, NaN), every `live` mask.
    #[test]
    #[cfg(target_arch = "x86_64")]
    fn block_coords_are_the_general_routes() {
        use std::arch::x86_64::*;
        if !crate::common::cpu::available() {
            return;
        }
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        let mut unit = move || {
            let r = crate::test_support::xorshift(&mut seed);
            (r >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let (w, h) = (256.0f32, 64.0f32);
        let mut odd = 0;
        for k in 0..20_000 {
            let x = 2.0 * (unit() * 50.0).round() + 0.5;
            let mut planes = [[[0f64; 3]; 3]; 2];
            let coef = [unit() * 0.1, unit() * 0.1, unit() * 4.0];
            for (row, p) in planes.iter_mut().enumerate() {
                let y = 7.5 + row as f64;
                for (j, plane) in p.iter_mut().enumerate() {
                    let (a, b, c) = (unit(), unit(), unit() * 3.0);
                    *plane = [a, b * y, c];
                    if j == 2 {
                        // q: positive, or through 0 near the block.
                        *plane = match k % 4 {
                            0 => [coef[0] * 0.01, coef[1] * 0.01 * y, 1.0 + coef[2].abs()],
                            1 => [1.0, 0.0, -(x + (k % 5) as f64)],
                            _ => [coef[0] * 0.01, 0.0, 0.5 + unit().abs()],
                        };
                    }
                }
                match k % 7 {
                    // s of a size that overflows f32 (its differences too).
                    2 => p[0][2] = 1e39 * unit(),
                    3 => p[1][0] = f64::NAN,
                    4 if row == 1 => p[0][2] = 1e300,
                    _ => {}
                }
            }
            let live = (unit().abs() * 256.0) as u8 | ((k % 3 == 0) as u8 * 0xFF);
            let [vs, vt] = super::perspective_block8(&planes, x).unwrap();
            // SAFETY: AVX2 is present (checked above).
            let (s, t, ax, ay) =
                unsafe { super::x86::block_coords8(&planes, x, live, Some([w, h])) };
            let (mut so, mut to, mut axo, mut ayo) = ([0f32; 8], [0f32; 8], [0f32; 4], [0f32; 4]);
            // SAFETY: eight and four f32; unaligned stores.
            unsafe {
                _mm256_storeu_ps(so.as_mut_ptr(), s);
                _mm256_storeu_ps(to.as_mut_ptr(), t);
                _mm_storeu_ps(axo.as_mut_ptr(), ax);
                _mm_storeu_ps(ayo.as_mut_ptr(), ay);
            }
            for j in 0..8 {
                let on = live & (1 << j) != 0;
                let (es, et) = if on {
                    (fix(vs[j]), fix(vt[j]))
                } else {
                    (0.0, 0.0)
                };
                odd += (on && !(vs[j] as f32).is_finite()) as usize;
                assert_eq!(so[j].to_bits(), es.to_bits(), "s lane {j} k {k}");
                assert_eq!(to[j].to_bits(), et.to_bits(), "t lane {j} k {k}");
            }
            let rho2 = |ds: f32, dt: f32| {
                let (u, v) = (ds * w, dt * h);
                u * u + v * v
            };
            for q in 0..2 {
                let (l, r) = (2 * q, 2 * q + 1);
                let ex = rho2(fix(vs[4 + r] - vs[4 + l]), fix(vt[4 + r] - vt[4 + l]));
                let ey = rho2(fix(vs[4 + l] - vs[l]), fix(vt[4 + l] - vt[l]));
                assert_eq!(axo[l].to_bits(), ex.to_bits(), "ax quad {q} k {k}");
                assert_eq!(ayo[l].to_bits(), ey.to_bits(), "ay quad {q} k {k}");
            }
        }
        assert!(odd > 1000, "{odd}");
    }

    /// `quick_lambda256x2` gives `LodSelect::quick_lambda256` for both quads (lanes 0 and
    /// 1), bit patterns over the whole range (NaN, infinities, zeros, subnormal and negative
    /// numbers included) and values in the usual range.
    #[test]
    #[cfg(target_arch = "x86_64")]
    fn quick_lambdas_of_two_quads_are_the_scalar_ones() {
        if !crate::common::cpu::available() {
            return;
        }
        let mut seed = 0xA076_1D64_78BD_642Fu64;
        let specials = [f32::NAN, f32::INFINITY, 0.0, -0.0, 1e-40, -3.0, 1.0, 4.0];
        for lod in crate::texture::sample::test_lod_selects() {
            for _ in 0..1000 {
                let mut v = [0f32; 4];
                for x in v.iter_mut() {
                    let r = crate::test_support::xorshift(&mut seed);
                    *x = match r % 5 {
                        0 => f32::from_bits((r >> 32) as u32),
                        1 => specials[(r >> 40) as usize % specials.len()],
                        _ => ((r >> 40) as f32 / (1u64 << 24) as f32 * 60.0 - 30.0).exp2(),
                    };
                }
                // SAFETY: AVX2 is present (checked above); the load reads four f32.
                let (g, mask) = unsafe {
                    super::x86::quick_lambda256x2(&lod, std::arch::x86_64::_mm_loadu_ps(v.as_ptr()))
                };
                assert_eq!(mask & !3, 0);
                for q in 0..2 {
                    let got = (mask & (1 << q) != 0).then_some(g[q]);
                    assert_eq!(got, lod.quick_lambda256(v[q]), "{:e}", v[q]);
                }
            }
        }
    }

    /// The eight-lane level weights are `fixed::level_weight` lane by lane: special values
    /// (NaN, infinities, zeros of both signs, values around the steps and past the ends) and
    /// random bit patterns and fractions.
    #[test]
    #[cfg(target_arch = "x86_64")]
    fn level_weights8_are_the_scalar_weights() {
        if !crate::common::cpu::available() {
            return;
        }
        let mut values = vec![
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            0.0,
            -0.0,
            -0.001,
            -1.0,
            0.999_999_9,
            1.0,
            1.5,
            254.5 / 256.0,
            255.0 / 256.0,
            1e10,
            -1e10,
            f32::MAX,
            f32::MIN_POSITIVE,
        ];
        let mut seed = 0x5851_F42D_4C95_7F2Du64;
        for _ in 0..40_000 {
            let r = crate::test_support::xorshift(&mut seed);
            values.push(f32::from_bits(r as u32));
            values.push((r >> 40) as f32 / (1u64 << 24) as f32);
            values.push((r % 512) as f32 / 256.0 + [0.0, 1e-7, -1e-7][(r % 3) as usize]);
        }
        for chunk in values.chunks(8) {
            let mut w = [0.5f32; 8];
            w[..chunk.len()].copy_from_slice(chunk);
            // SAFETY: AVX2 is present (checked above); the store writes eight i32 into `out`.
            let out = unsafe {
                let v = super::x86::level_weights8(&w);
                let mut out = [0i32; 8];
                std::arch::x86_64::_mm256_storeu_si256(out.as_mut_ptr().cast(), v);
                out
            };
            for (j, &x) in w.iter().enumerate() {
                let want = crate::texture::fixed::level_weight(x) as i32;
                assert_eq!(out[j], want, "{x:e}");
            }
        }
    }

    /// The eight-lane cube-map face selection is the per-lane direction and `cube_face`:
    /// random planes (directions on every face, near the faces' edges and corners where the
    /// ties decide, zero, tiny and huge components, q of both signs and zero), bit for bit.
    #[test]
    fn cube_block_faces8_are_the_per_lane_faces() {
        if !crate::common::cpu::available() {
            return;
        }
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        let next = |seed: &mut u64| {
            let r = crate::test_support::xorshift(seed);
            // Mostly small whole numbers (exact ties between components), some fractions,
            // some extremes.
            match r % 8 {
                0..=2 => ((r >> 8) % 9) as f64 - 4.0,
                3 => 0.0,
                4 => ((r >> 8) % 1000) as f64 * 1e-30,
                5 => ((r >> 8) % 1000) as f64 * 1e30,
                _ => ((r >> 8) % 20001) as f64 / 1000.0 - 10.0,
            }
        };
        for _ in 0..50_000 {
            let mut planes = [[[0f64; 3]; 3]; 2];
            let mut r = [[0f64; 3]; 2];
            for row in 0..2 {
                for k in 0..3 {
                    planes[row][k] = [next(&mut seed), next(&mut seed), next(&mut seed)];
                }
                r[row] = [next(&mut seed), next(&mut seed), next(&mut seed)];
            }
            let x = (next(&mut seed).abs() % 1000.0).floor() + 0.5;
            let (faces, s, t) = super::cube_block_faces8(&planes, &r, x).unwrap();
            for j in 0..8 {
                let (row, xj) = (j / 4, x + (j % 4) as f64);
                let at = |pl: &[f64; 3]| pl[0] * xj + pl[1] + pl[2];
                let q = at(&planes[row][2]);
                let dir = [
                    fix(at(&planes[row][0]) / q),
                    fix(at(&planes[row][1]) / q),
                    fix(at(&r[row]) / q),
                ];
                let (face, st) = crate::texture::sample::cube_face(dir);
                assert_eq!(faces[j] as usize, face, "{dir:?}");
                assert_eq!(s[j].to_bits(), st[0].to_bits(), "{dir:?}");
                assert_eq!(t[j].to_bits(), st[1].to_bits(), "{dir:?}");
            }
        }
    }
}

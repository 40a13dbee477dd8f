//! The fast 2D path's filter for eight pixels at once with AVX2 (x86-64, detected at run
//! time): RGBA8 texels, `REPEAT` on power-of-two sizes or `CLAMP_TO_EDGE`. Every lane does
//! the arithmetic of [`BoundTexture::filter_fast`](super::sample::BoundTexture::filter_fast)
//! in the same order and precision (f64 scaling and floor, f32 weights and lerps, no fused
//! multiply-add), so the results are identical; `tests/raster.rs`
//! `textured_fast_paths_match_the_general_path` checks it.

use super::format::BaseFormat;
use super::sample::{FastLevel, LevelPlan, LodSelect};
use crate::api::convert::{CompareFunc, FogMode, WrapMode};
use crate::fragment::key::BlendKey;

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
}

impl<'a> Level8<'a> {
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
        Some(Level8 {
            texels,
            tiny,
            components,
            base,
            size,
            repeat_mask,
        })
    }
}

/// The environment variable that switches the AVX2 paths off: with `TILEGL_NO_SIMD=1` (any
/// value but empty or `0`) [`available`] answers `false`, so every place that picks an AVX2
/// route at run time (texture filtering, the eight-pixel spans, texgen, the viewport
/// transform, coarse depth) takes its scalar twin, on any processor. Read once, at the first
/// question; the pictures are the same either way (`conformance/tests/determinism.rs`).
pub const NO_SIMD_ENV: &str = "TILEGL_NO_SIMD";

const UNKNOWN: u8 = 0;
const ON: u8 = 1;
const OFF: u8 = 2;

/// The answer of [`available`], once known.
static STATE: std::sync::atomic::AtomicU8 = std::sync::atomic::AtomicU8::new(UNKNOWN);

/// Whether the AVX2 paths ([`filter8`] and the others) may run: the processor has AVX2 and
/// [`NO_SIMD_ENV`] does not switch them off. One relaxed load after the first call, like the
/// standard library's own feature cache.
#[inline]
pub fn available() -> bool {
    match STATE.load(std::sync::atomic::Ordering::Relaxed) {
        ON => true,
        OFF => false,
        _ => detect(),
    }
}

#[cold]
fn detect() -> bool {
    let off = std::env::var_os(NO_SIMD_ENV).is_some_and(|v| !v.is_empty() && v != "0");
    #[cfg(target_arch = "x86_64")]
    let cpu = std::arch::is_x86_feature_detected!("avx2");
    #[cfg(not(target_arch = "x86_64"))]
    let cpu = false;
    let on = cpu && !off;
    STATE.store(
        if on { ON } else { OFF },
        std::sync::atomic::Ordering::Relaxed,
    );
    on
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

/// How the quads of a block choose their level for [`block_shaded8`]: `None` when the level
/// is fixed for the draw; `Some((magnified_below, [width, height]))` when every live quad must
/// be surely magnified (`LodSelect::surely_magnified` on a 2D texture of that base size).
pub type BlockLod = Option<(f32, [f32; 2])>;

/// A 4x2 block of a perspective textured span in one go: the texture coordinates as
/// [`perspective_block8`] computes them (rounded to f32, non-finite as 0), each quad's
/// derivatives and level test as `Perspective8::texels_block` does, [`filter8`] on `level`,
/// then [`shade8`] with lanes `live`. `None` without AVX2, when a live quad is not surely
/// magnified (`lod`), or when [`filter8`] would answer `None`: the caller takes the usual
/// route, which gives the same pixels.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn block_shaded8(
    planes: &[[[f64; 3]; 3]; 2],
    x: f64,
    level: &Level8,
    linear: bool,
    lod: BlockLod,
    live: u8,
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
                    planes, x, level, linear, lod, live, tail, primary, dst, after,
                )
            };
        }
    }
    let _ = (
        planes, x, level, linear, lod, live, tail, primary, dst, after,
    );
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

/// The blending [`shade8`] does: none, the two common cases by their own code, or any other.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TailBlend {
    None,
    /// `SRC_ALPHA`, `ONE_MINUS_SRC_ALPHA`.
    AlphaOver,
    /// `ONE`, `ONE`.
    AddOneOne,
    /// Any other blending (equations, factors, the constant colour), as
    /// `fragment::blend::blend` computes it.
    General(BlendKey, [f32; 4]),
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
    /// The two divisors of the plane values (see [`coords8`]), constant over the span.
    pub w: f64,
    pub q: f64,
    /// The first level and, with a weight, the second.
    pub levels: [Level8<'a>; 2],
    pub linear: bool,
    pub weight: Option<f32>,
}

/// [`coords8`], [`filter8`] on one or two levels and [`shade8`] in one go, for the `count`
/// pixels from centre `x`; `None` when [`coords8`] or [`filter8`] would answer `None`.
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

/// `t1 + (t2 - t1) * w` per channel, as the sampler mixes two levels.
#[inline(always)]
pub fn lerp8(t1: &Texels8, t2: &Texels8, w: f32) -> Texels8 {
    let mut out = [[0f32; 8]; 4];
    for c in 0..4 {
        for i in 0..8 {
            out[c][i] = t1[c][i] + (t2[c][i] - t1[c][i]) * w;
        }
    }
    out
}

#[cfg(target_arch = "x86_64")]
mod x86 {
    use std::arch::x86_64::*;

    use super::{After8, Level8, LevelPlan, LodSelect, Sampling8, Tail8, Texels8};
    use crate::api::convert::{BlendEquation, BlendFactor, CompareFunc, FogMode};
    use crate::state::snapshot::EXP2_TAYLOR;
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

    /// The stored components of the texels at (x, y) in order, each byte as
    /// `byte as f32 * (1 / 255)` (the first `components` of the four).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn stored8(lvl: &Level8, x: __m256i, y: __m256i) -> [__m256; 4] {
        let idx = _mm256_add_epi32(_mm256_mullo_epi32(y, _mm256_set1_epi32(lvl.size[0])), x);
        let base_ptr = match &lvl.tiny {
            Some(t) => t.as_ptr(),
            None => lvl.texels.as_ptr(),
        };
        let texels = if lvl.components == 4 {
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
        };
        let byte = _mm256_set1_epi32(0xFF);
        let k = _mm256_set1_ps(1.0 / 255.0);
        let ch = |v: __m256i| _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_and_si256(v, byte)), k);
        // The stored components in order (only the first `components` are read).
        let mut stored = [_mm256_setzero_ps(); 4];
        stored[0] = ch(texels);
        if lvl.components > 1 {
            stored[1] = ch(_mm256_srli_epi32::<8>(texels));
        }
        if lvl.components > 2 {
            stored[2] = ch(_mm256_srli_epi32::<16>(texels));
        }
        if lvl.components > 3 {
            stored[3] = ch(_mm256_srli_epi32::<24>(texels));
        }
        stored
    }

    /// The texels at (x, y) as four channel vectors (R, G, B, A after the base format's
    /// expansion), each byte as `byte as f32 * (1 / 255)`, as `TexImage::fetch` converts.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn fetch8(lvl: &Level8, x: __m256i, y: __m256i) -> [__m256; 4] {
        expand8(lvl.base, stored8(lvl, x, y))
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

    #[inline]
    #[target_feature(enable = "avx2")]
    fn lerp(a: __m256, b: __m256, w: __m256) -> __m256 {
        _mm256_add_ps(a, _mm256_mul_ps(_mm256_sub_ps(b, a), w))
    }

    /// `color_to_u8` per lane: `c * 255 + 0.5` clamped to [0, 255] (NaN as 0), truncated.
    #[target_feature(enable = "avx2")]
    fn to_u8(c: __m256) -> __m256i {
        let v = _mm256_add_ps(_mm256_mul_ps(c, _mm256_set1_ps(255.0)), _mm256_set1_ps(0.5));
        // max_ps answers its second operand (0) when v is NaN.
        let v = _mm256_min_ps(_mm256_max_ps(v, _mm256_setzero_ps()), _mm256_set1_ps(255.0));
        _mm256_cvttps_epi32(v)
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
    fn shade8_regs(
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
        // SAFETY: `dst` holds eight u32; unaligned load.
        let old = unsafe { _mm256_loadu_si256(dst.as_ptr() as *const __m256i) };
        let mut src = [_mm256_setzero_si256(); 4];
        for c in 0..4 {
            src[c] = to_u8(color[c]);
        }
        let k = _mm256_set1_ps(255.0);
        let byte = _mm256_set1_epi32(0xFF);
        let d = [
            old,
            _mm256_srli_epi32::<8>(old),
            _mm256_srli_epi32::<16>(old),
            _mm256_srli_epi32::<24>(old),
        ];
        let pack = |out: &[__m256i; 4]| {
            _mm256_or_si256(
                _mm256_or_si256(out[0], _mm256_slli_epi32::<8>(out[1])),
                _mm256_or_si256(
                    _mm256_slli_epi32::<16>(out[2]),
                    _mm256_slli_epi32::<24>(out[3]),
                ),
            )
        };
        let word = if tail.blend == super::TailBlend::AddOneOne {
            // ONE, ONE: `color_to_u8(s / 255 + d / 255)` is exactly min(s + d, 255) for bytes
            // s and d (the f32 errors stay far below the 0.5 of rounding;
            // `add_one_one_is_a_saturating_byte_add` checks every pair): bytes added with
            // saturation.
            _mm256_adds_epu8(pack(&src), old)
        } else if tail.blend == super::TailBlend::AlphaOver {
            let sa = _mm256_div_ps(_mm256_cvtepi32_ps(src[3]), k);
            let inv = _mm256_sub_ps(one, sa);
            let mut out = [_mm256_setzero_si256(); 4];
            for c in 0..4 {
                let s = _mm256_div_ps(_mm256_cvtepi32_ps(src[c]), k);
                let d = _mm256_div_ps(_mm256_cvtepi32_ps(_mm256_and_si256(d[c], byte)), k);
                out[c] = to_u8(_mm256_add_ps(_mm256_mul_ps(s, sa), _mm256_mul_ps(d, inv)));
            }
            pack(&out)
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
                        let a = _mm256_mul_ps(s[ch], factor8(sf, &s, &d, constant, ch));
                        let b = _mm256_mul_ps(d[ch], factor8(df, &s, &d, constant, ch));
                        match eq {
                            BlendEquation::Add => _mm256_add_ps(a, b),
                            BlendEquation::Subtract => _mm256_sub_ps(a, b),
                            _ => _mm256_sub_ps(b, a),
                        }
                    }
                };
                out[ch] = to_u8(v);
            }
            pack(&out)
        } else {
            pack(&src)
        };
        let cm = _mm256_set1_epi32(tail.color_mask as i32);
        let word = _mm256_or_si256(_mm256_and_si256(word, cm), _mm256_andnot_si256(cm, old));
        let word = _mm256_blendv_epi8(old, word, _mm256_castps_si256(keep));
        let mut res = [0u32; 8];
        // SAFETY: `res` holds eight u32; unaligned store.
        unsafe { _mm256_storeu_si256(res.as_mut_ptr() as *mut __m256i, word) };
        (res, _mm256_movemask_ps(keep) as u8)
    }

    #[allow(clippy::too_many_arguments)]
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
        let mut ct = filter8(&sm.levels[0], sm.linear, &s, &t)?;
        if let Some(w) = sm.weight {
            let t2 = filter8(&sm.levels[1], sm.linear, &s, &t)?;
            ct = super::lerp8(&ct, &t2, w);
        }
        Some(shade8(tail, primary, &ct, dst, pass, after))
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
    fn lane_mask(m: u8) -> __m256 {
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

    #[allow(clippy::too_many_arguments)]
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn block_shaded8(
        planes: &[[[f64; 3]; 3]; 2],
        x: f64,
        level: &Level8,
        linear: bool,
        lod: super::BlockLod,
        live: u8,
        tail: &Tail8,
        primary: &[[f32; 8]; 4],
        dst: &[u32; 8],
        after: &After8,
    ) -> Option<([u32; 8], u8)> {
        let (s, t, ax, ay) = block_coords8(planes, x, live, lod.map(|(_, size)| size));
        if let Some((magnified_below, _)) = lod {
            // Both at most the threshold (false for NaN): then so is their maximum, which is
            // what `surely_magnified` compares.
            let below = _mm_set1_ps(magnified_below);
            let ok = _mm_movemask_ps(_mm_and_ps(_mm_cmple_ps(ax, below), _mm_cmple_ps(ay, below)));
            let need = (if live & 0x33 != 0 { 0b0001 } else { 0 })
                | (if live & 0xCC != 0 { 0b0100 } else { 0 });
            if ok & need != need {
                return None;
            }
        }
        let tex = filter8_regs(level, linear, s, t)?;
        Some(shade8_regs(tail, primary, &tex, dst, live, after))
    }

    /// The block's coordinates (lanes outside `live` at 0) and, per quad (lanes 0 and 2),
    /// the squared scaled lengths of its x and y derivatives for a `w` x `h` texture.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn block_coords8(
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

    /// The texels of one level plan at `s`, `t`, two levels mixed with `weight` per lane.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn filter_plan8(
        levels: &[Option<Level8>],
        (first, second, linear): (usize, usize, bool),
        weight: __m256,
        s: __m256,
        t: __m256,
    ) -> Option<[__m256; 4]> {
        let level = |l: usize| levels.get(l)?.as_ref();
        let t1 = filter8_regs(level(first)?, linear, s, t)?;
        if second == first {
            return Some(t1);
        }
        let t2 = filter8_regs(level(second)?, linear, s, t)?;
        let mut mixed = t1;
        for c in 0..4 {
            mixed[c] = _mm256_add_ps(t1[c], _mm256_mul_ps(_mm256_sub_ps(t2[c], t1[c]), weight));
        }
        Some(mixed)
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
        let store = |out: &mut Texels8, tex: [__m256; 4]| {
            for c in 0..4 {
                // SAFETY: `out[c]` holds eight f32; unaligned store.
                unsafe { _mm256_storeu_ps(out[c].as_mut_ptr(), tex[c]) };
            }
        };
        let zero = _mm256_setzero_ps();
        if let Some((level, linear)) = fixed_plan {
            let (s, t, _, _) = block_coords8(planes, x, live, None);
            store(
                out,
                filter_plan8(levels, (level, level, linear), zero, s, t)?,
            );
            return Some(());
        }
        let (_, size) = lod.magnified_test()?;
        let (s, t, ax, ay) = block_coords8(planes, x, live, Some(size));
        let (mut axs, mut ays) = ([0f32; 4], [0f32; 4]);
        // SAFETY: four f32 each; unaligned stores.
        unsafe {
            _mm_storeu_ps(axs.as_mut_ptr(), ax);
            _mm_storeu_ps(ays.as_mut_ptr(), ay);
        }
        // Per quad (lanes 0, 1, 4, 5 and 2, 3, 6, 7), when it has live lanes: its levels and
        // its weight between them.
        let plan = |q: usize| match lod.plan_for_rho2(axs[2 * q], ays[2 * q]) {
            LevelPlan::One { level, linear } => ((level, level, linear), 0.0),
            LevelPlan::Two {
                levels: [a, b],
                linear,
                weight,
            } => ((a, b, linear), weight),
        };
        let quad_lanes = [0x33u8, 0xCC];
        let plans = [0, 1].map(|q| (live & quad_lanes[q] != 0).then(|| plan(q)));
        let tex = match plans {
            [Some((p0, w0)), Some((p1, w1))] if p0 == p1 => {
                // One plan: filtered together, each quad with its own weight.
                let weight =
                    _mm256_blendv_ps(_mm256_set1_ps(w1), _mm256_set1_ps(w0), lane_mask(0x33));
                filter_plan8(levels, p0, weight, s, t)?
            }
            [Some((p0, w0)), Some((p1, w1))] => {
                let a = filter_plan8(levels, p0, _mm256_set1_ps(w0), s, t)?;
                let b = filter_plan8(levels, p1, _mm256_set1_ps(w1), s, t)?;
                let first = lane_mask(0x33);
                let mut tex = a;
                for c in 0..4 {
                    tex[c] = _mm256_blendv_ps(b[c], a[c], first);
                }
                tex
            }
            [Some((p, w)), None] | [None, Some((p, w))] => {
                filter_plan8(levels, p, _mm256_set1_ps(w), s, t)?
            }
            [None, None] => [zero; 4],
        };
        store(out, tex);
        Some(())
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
    pub fn coords8(
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
        let mut out = [[0f32; 8]; 2];
        for (k, p) in planes.iter().enumerate() {
            let (a, by, c) = (
                _mm256_set1_pd(p[0]),
                _mm256_set1_pd(p[1]),
                _mm256_set1_pd(p[2]),
            );
            let mut halves = [_mm_setzero_ps(); 2];
            for h in 0..2 {
                let v = _mm256_div_pd(
                    _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a, xs[h]), by), c),
                    wv,
                );
                // v - v is 0 exactly when v is finite.
                let finite = _mm256_cmp_pd::<_CMP_EQ_OQ>(_mm256_sub_pd(v, v), zero);
                if _mm256_movemask_pd(_mm256_andnot_pd(finite, live[h])) != 0 {
                    return None;
                }
                let f = _mm256_cvtpd_ps(_mm256_div_pd(v, qv));
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
    pub fn filter8(lvl: &Level8, linear: bool, s: &[f32; 8], t: &[f32; 8]) -> Option<Texels8> {
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
    fn filter8_regs(lvl: &Level8, linear: bool, s: __m256, t: __m256) -> Option<[__m256; 4]> {
        let [w, h] = lvl.size;
        let [mx, my] = lvl.repeat_mask;
        let out: [__m256; 4] = if !linear {
            let (x, _) = floor_frac8(s, w, 0.0)?;
            let (y, _) = floor_frac8(t, h, 0.0)?;
            fetch8(lvl, wrap8(x, w, mx), wrap8(y, h, my))
        } else {
            let (x, wx) = floor_frac8(s, w, 0.5)?;
            let (y, wy) = floor_frac8(t, h, 0.5)?;
            let one = _mm256_set1_epi32(1);
            let (x0, x1) = (wrap8(x, w, mx), wrap8(_mm256_add_epi32(x, one), w, mx));
            let (y0, y1) = (wrap8(y, h, my), wrap8(_mm256_add_epi32(y, one), h, my));
            let t00 = stored8(lvl, x0, y0);
            let t10 = stored8(lvl, x1, y0);
            let t01 = stored8(lvl, x0, y1);
            let t11 = stored8(lvl, x1, y1);
            // Only the stored components are filtered, then expanded.
            let mut out = [_mm256_setzero_ps(); 4];
            for c in 0..lvl.components as usize {
                let row0 = lerp(t00[c], t10[c], wx);
                let row1 = lerp(t01[c], t11[c], wx);
                out[c] = lerp(row0, row1, wy);
            }
            expand8(lvl.base, out)
        };
        Some(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fragment::span::depth_to_fixed;
    use crate::state::snapshot::{fog_exp, FogDraw};

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
        let funcs = [
            None,
            Some(CompareFunc::Never),
            Some(CompareFunc::Less),
            Some(CompareFunc::Equal),
            Some(CompareFunc::LessEqual),
            Some(CompareFunc::Greater),
            Some(CompareFunc::NotEqual),
            Some(CompareFunc::GreaterEqual),
            Some(CompareFunc::Always),
        ];
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

//! The fixed-point filtering tier: LINEAR filtering and the mix of two mipmap levels for
//! images of one unsigned byte per component, in 8-bit fixed point, as Mesa's llvmpipe filters
//! them on its AoS sampling path (gallivm `lp_bld_sample_aos.c`, `lp_build_lerp` of
//! `lp_bld_arit.c`). The rule, per axis of `size` texels and per component:
//!
//! - The coordinate in 1/256 texels: `k = round_even(s * (size * 256)) - 128` (the product in
//!   f32, rounded to the nearest integer, ties to even), then the first texel
//!   `i0 = k >> 8` (floor), the second `i0 + 1`, both wrapped, and the weight of the second
//!   `w = k & 255` (8 bits, so 0 <= w / 256 <= 255 / 256). `REPEAT` on a size that is not a
//!   power of two first takes the fraction `s - floor(s)` in f32 and multiplies it by the size
//!   (then by 256), and wraps as llvmpipe does ([`linear_axis`]).
//! - One lerp, in integers: `lerp(a, b, w) = a + ((w (b - a) + 128) >> 8)` (arithmetic
//!   shift: `a + round(w (b - a) / 256)`, halves up; what llvmpipe's `pmulhrsw` of `w` and
//!   `(b - a) << 7` gives), which always lies between `a` and `b`. Bilinear filtering lerps
//!   the two rows by the s weight, then the results by the t weight, each rounded to 8 bits
//!   (3D: the two slices' results by the r weight).
//! - Two levels are mixed with the weight `trunc(256 f)` (f the λ fraction), by the same
//!   lerp ([`level_weight`]).
//! - The result byte `c` becomes `c / 255` as f32 (`c as f32 * (1 / 255)`, as texels are
//!   converted everywhere else).
//!
//! Error against the specification's equations on the same texels (section 3.8.8), in
//! bytes (units of 1/255), for power-of-two sizes: the weight is `frac(u - 1/2)` rounded to
//! 1/256, off by at most 1/512 (exact products: s times a power of two), which moves a lerp
//! by at most `|b - a| / 512 <= 255 / 512`; each lerp rounds to a byte (at most 1/2). So one
//! lerp is within `255 / 512 + 1 / 2 < 1` byte, and a bilinear result, whose last lerp mixes
//! two values each within that of the exact row lerps, within
//! `(255 / 512 + 1 / 2) + 255 / 512 + 1 / 2 < 2` bytes. A mix of two levels adds the
//! truncated level weight (off by less than 1/256: under 1 byte) and its rounding (1/2):
//! within 3.5 bytes. Sizes that are not powers of two round the f32 product `s * size` too:
//! at most another 1/512 of weight (for |u| < 2^15), 1/2 byte per lerp. `tests` below and
//! `tests/fixed_filter.rs` check these bounds against the equations in f64.
//!
//! The tier applies wherever llvmpipe takes its AoS path and tilegl has byte texels: 1D, 2D,
//! 3D and cube-map images of unsigned-byte colour texels without a border, every axis wrapped
//! by `REPEAT` or `CLAMP_TO_EDGE` ([`BoundTexture`](super::sample::BoundTexture) decides;
//! the eight-lane filter of `texture::simd` only takes such images). Other images, wrap modes
//! and formats keep the f32 filter. NEAREST filtering is unchanged (a texel is a byte either
//! way).

use super::format::BaseFormat;
use super::image::{TexImage, Texels};
use super::sample::{floor_frac, lerp4 as lerp4_f32, wrap_index, BoundTexture, FastLevel};
use crate::common::values::TextureTarget;
use crate::common::values::WrapMode;

/// Bits of a filter weight (and of the level weight): 8, as llvmpipe's AoS path.
pub const WEIGHT_BITS: u32 = 8;

/// Whether a wrap mode keeps an axis on the fixed-point tier: the modes llvmpipe's AoS path
/// takes (`lp_is_simple_wrap_mode`).
#[inline(always)]
pub fn simple_wrap(mode: WrapMode) -> bool {
    matches!(mode, WrapMode::Repeat | WrapMode::ClampToEdge)
}

/// `a + round(w (b - a) / 256)`, halves up, in integers: always between `a` and `b`.
#[inline(always)]
pub fn lerp(a: u8, b: u8, w: u8) -> u8 {
    let d = b as i32 - a as i32;
    (a as i32 + ((w as i32 * d + 128) >> WEIGHT_BITS)) as u8
}

/// [`lerp`] per component.
#[inline(always)]
pub fn lerp4(a: [u8; 4], b: [u8; 4], w: u8) -> [u8; 4] {
    [
        lerp(a[0], b[0], w),
        lerp(a[1], b[1], w),
        lerp(a[2], b[2], w),
        lerp(a[3], b[3], w),
    ]
}

/// The 8-bit weight of the second of two mipmap levels for the λ fraction `f` (in [0, 1)):
/// `trunc(256 f)`, clamped to [0, 255] (NaN as 0), as llvmpipe quantises it.
#[inline(always)]
pub fn level_weight(f: f32) -> u8 {
    ((f * 256.0) as i32).clamp(0, 255) as u8
}

/// Bytes as f32 texel values: `c as f32 * (1 / 255)` (0 -> 0.0, 255 -> 1.0 exactly).
#[inline(always)]
pub fn to_f32(v: [u8; 4]) -> [f32; 4] {
    v.map(|c| c as f32 * (1.0 / 255.0))
}

/// The coordinate `s` on an axis of `size` texels (`size` at most 2^16) in 1/256 texels minus
/// one half: `round_even(s * (size * 256)) - 128`, the product in f32. Saturating; NaN as 0.
#[inline(always)]
pub fn fixed_coord(s: f32, size: i64) -> i64 {
    let x = s * (size as f32 * 256.0);
    (x.round_ties_even() as i64).saturating_sub(128)
}

/// LINEAR filtering along one axis: the wrapped indices of the two texels and the weight of
/// the second, for coordinate `s` on an axis of `size` texels (1 to 2^16) wrapped by `mode`
/// (`REPEAT` or `CLAMP_TO_EDGE`; see [`simple_wrap`]).
#[inline(always)]
pub fn linear_axis(s: f32, size: i64, mode: WrapMode) -> (i64, i64, u8) {
    let size = size.max(1);
    if mode == WrapMode::Repeat && size & (size - 1) != 0 {
        // llvmpipe's `lp_build_coord_repeat_npot_linear_int`: the fraction of s first, in
        // f32 (s - floor(s) may round to 1.0 for tiny negative s; NaN stays NaN, as 0).
        let f = s - s.floor();
        let x = (f * size as f32) * 256.0;
        let k = (x.round_ties_even() as i64) - 128;
        let i = k >> WEIGHT_BITS;
        let i = if i < 0 { size - 1 } else { i.min(size - 1) };
        let i1 = if i == size - 1 { 0 } else { i + 1 };
        return (i, i1, (k & 255) as u8);
    }
    let k = fixed_coord(s, size);
    let i = k >> WEIGHT_BITS;
    (
        wrap_index(i, size, mode, true),
        wrap_index(i.saturating_add(1), size, mode, true),
        (k & 255) as u8,
    )
}

/// The texel of `base` format at byte `i` of `v` as internal RGBA bytes: the stored
/// components in their slots (luminance and intensity in R), the others 0 and alpha 255, as
/// [`TexImage::fetch`] places them (`[0, 0, 0, 255]` past the end).
#[inline(always)]
pub fn texel_bytes(v: &[u8], base: BaseFormat, i: usize) -> [u8; 4] {
    use BaseFormat::*;
    let none = [0, 0, 0, 255];
    match base {
        Alpha => v.get(i).map_or(none, |&a| [0, 0, 0, a]),
        Luminance | Intensity | DepthComponent | Red => v.get(i).map_or(none, |&l| [l, 0, 0, 255]),
        Rg => v.get(i..i + 2).map_or(none, |s| [s[0], s[1], 0, 255]),
        LuminanceAlpha => v.get(i..i + 2).map_or(none, |s| [s[0], 0, 0, s[1]]),
        Rgb => v.get(i..i + 3).map_or(none, |s| [s[0], s[1], s[2], 255]),
        Rgba => v.get(i..i + 4).map_or(none, |s| [s[0], s[1], s[2], s[3]]),
    }
}

/// The NEAREST texel index along an axis: `wrap(floor(s * size))` with the product in f64, as
/// the f32 filter takes it.
#[inline(always)]
fn nearest_axis(s: f32, size: i64, mode: WrapMode) -> i64 {
    wrap_index(floor_frac(s as f64 * size as f64).0, size, mode, false)
}

/// Bilinear filtering of the texels `t(i, j)` at the axes' indices and weights.
#[inline(always)]
fn bilinear(
    t: impl Fn(i64, i64) -> [u8; 4],
    (x0, x1, wx): (i64, i64, u8),
    (y0, y1, wy): (i64, i64, u8),
) -> [u8; 4] {
    let row0 = lerp4(t(x0, y0), t(x1, y0), wx);
    let row1 = lerp4(t(x0, y1), t(x1, y1), wx);
    lerp4(row0, row1, wy)
}

/// NEAREST or LINEAR filtering of an image of unsigned-byte texels without a border, of
/// `dims` dimensions (a cube face is 2), each axis wrapped by `REPEAT` or `CLAMP_TO_EDGE`
/// (`wrap`), at `coords`: internal RGBA bytes (see [`texel_bytes`]).
pub fn filter_image(
    img: &TexImage,
    dims: usize,
    wrap: [WrapMode; 3],
    linear: bool,
    coords: [f32; 3],
) -> [u8; 4] {
    let Texels::U8(v) = &*img.texels else {
        return [0, 0, 0, 255];
    };
    let base = img.format.base;
    let c = base.components();
    let size = [img.width, img.height, img.depth].map(|n| n.max(1) as i64);
    let at = |i: i64, j: i64, k: i64| {
        let idx = ((k * size[1] + j) * size[0] + i) as usize * c;
        texel_bytes(v, base, idx)
    };
    if !linear {
        let i = [0, 1, 2].map(|d| {
            if d < dims {
                nearest_axis(coords[d], size[d], wrap[d])
            } else {
                0
            }
        });
        return at(i[0], i[1], i[2]);
    }
    let axis = |d: usize| linear_axis(coords[d], size[d], wrap[d]);
    match dims {
        1 => {
            let (i0, i1, w) = axis(0);
            lerp4(at(i0, 0, 0), at(i1, 0, 0), w)
        }
        2 => bilinear(|i, j| at(i, j, 0), axis(0), axis(1)),
        _ => {
            let (ax, ay, (k0, k1, wz)) = (axis(0), axis(1), axis(2));
            let s0 = bilinear(|i, j| at(i, j, k0), ax, ay);
            let s1 = bilinear(|i, j| at(i, j, k1), ax, ay);
            lerp4(s0, s1, wz)
        }
    }
}

/// NEAREST or LINEAR filtering of a fast level (`C` = 3 or 4 bytes per texel, RGB or RGBA)
/// wrapped by `REPEAT` or `CLAMP_TO_EDGE` (`wrap`): what [`filter_image`] gives for the same
/// image, as RGBA bytes.
#[inline(always)]
pub fn filter_fast<const C: usize>(
    lvl: &FastLevel,
    wrap: [WrapMode; 2],
    linear: bool,
    coords: [f32; 2],
) -> [u8; 4] {
    let [w, h] = lvl.size();
    let texels = lvl.texels();
    let base = if C == 4 {
        BaseFormat::Rgba
    } else {
        BaseFormat::Rgb
    };
    let at = |i: i64, j: i64| texel_bytes(texels, base, (j * w + i) as usize * C);
    if !linear {
        return at(
            nearest_axis(coords[0], w, wrap[0]),
            nearest_axis(coords[1], h, wrap[1]),
        );
    }
    bilinear(
        at,
        linear_axis(coords[0], w, wrap[0]),
        linear_axis(coords[1], h, wrap[1]),
    )
}

impl BoundTexture {
    /// The number of dimensions filtered when the texture's images take the fixed-point
    /// filter ([this module](self)): 1D, 2D, 3D and cube-map images of unsigned-byte colour texels
    /// without a border, every filtered axis wrapped by `REPEAT` or `CLAMP_TO_EDGE` (where
    /// llvmpipe filters in 8-bit fixed point); `None` for the f32 filter.
    #[inline]
    pub(super) fn fixed_tier(&self, img: &TexImage) -> Option<usize> {
        let dims = match self.target() {
            TextureTarget::T1D => 1,
            TextureTarget::T2D | TextureTarget::CubeMap => 2,
            TextureTarget::T3D => 3,
            TextureTarget::Rectangle => return None,
        };
        let wrap = &self.params().wrap;
        (img.border == 0
            && img.format.base != BaseFormat::DepthComponent
            && matches!(&*img.texels, Texels::U8(_))
            && wrap[..dims].iter().all(|&w| simple_wrap(w)))
        .then_some(dims)
    }

    /// Two fast levels filtered at (s, t) and mixed with `weight` (the second's), as
    /// [`BoundTexture::sample_grad`] mixes them: in 8-bit fixed point (this module) when both
    /// axes wrap by `REPEAT` or `CLAMP_TO_EDGE`, else in f32.
    #[inline(always)]
    pub fn filter_fast_mix<const C: usize>(
        &self,
        levels: [&FastLevel; 2],
        linear: bool,
        coords: [f32; 2],
        weight: f32,
    ) -> [f32; 4] {
        let wrap = self.params().wrap;
        if simple_wrap(wrap[0]) && simple_wrap(wrap[1]) {
            let wrap = [wrap[0], wrap[1]];
            let a = filter_fast::<C>(levels[0], wrap, linear, coords);
            let b = filter_fast::<C>(levels[1], wrap, linear, coords);
            return to_f32(lerp4(a, b, level_weight(weight)));
        }
        let t1 = self.filter_fast::<C>(levels[0], linear, coords);
        let t2 = self.filter_fast::<C>(levels[1], linear, coords);
        lerp4_f32(t1, t2, weight)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The integer lerp is llvmpipe's: for every pair of bytes and weight, the result equals
    /// `(a + ((w * (b - a) * 128 + 2^14) >> 15)) mod 256` (pmulhrsw of w and (b - a) << 7,
    /// masked to a byte, added bytewise), lies between a and b, and is within 1/2 of the exact
    /// `a + w (b - a) / 256`.
    #[test]
    fn lerp_is_pmulhrsw_and_within_half_a_byte() {
        for a in 0..=255u8 {
            for b in 0..=255u8 {
                for w in 0..=255u8 {
                    let r = lerp(a, b, w);
                    let d = (b as i32 - a as i32) << 7;
                    let hr = ((w as i32 * d + (1 << 14)) >> 15) & 0xFF;
                    assert_eq!(r as i32, (a as i32 + hr) & 0xFF, "{a} {b} {w}");
                    assert!(r >= a.min(b) && r <= a.max(b), "{a} {b} {w}");
                    let exact = a as f64 + w as f64 * (b as f64 - a as f64) / 256.0;
                    assert!((r as f64 - exact).abs() <= 0.5, "{a} {b} {w}");
                }
            }
        }
    }

    #[test]
    fn level_weights_truncate() {
        assert_eq!(level_weight(0.0), 0);
        assert_eq!(level_weight(0.5), 128);
        assert_eq!(level_weight(0.999), 255);
        assert_eq!(level_weight(1.0 / 256.0 - 1e-7), 0);
        assert_eq!(level_weight(f32::NAN), 0);
        assert_eq!(level_weight(-0.25), 0);
        assert_eq!(level_weight(3.0), 255);
    }

    /// Indices and weights against the specification's `floor(u - 1/2)` and `frac(u - 1/2)`
    /// (u = s * size, section 3.8.8) for power-of-two sizes: the weight is the fraction
    /// rounded to 1/256 (ties to even), and when it rounds up to a whole texel the next texel
    /// pair is taken with weight 0.
    #[test]
    fn axis_matches_the_spec_rounded_to_eighths_of_bits() {
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        for _ in 0..20000 {
            let r = crate::test_support::xorshift(&mut seed);
            let size = 1i64 << (r % 9);
            let s = ((r >> 16) % 100_000) as f32 / 12_345.0 - 3.0;
            let u = s as f64 * size as f64 - 0.5;
            let q = (u * 256.0).round_ties_even();
            let (i0, i1, w) = linear_axis(s, size, WrapMode::Repeat);
            let base = (q / 256.0).floor() as i64;
            assert_eq!(i0, base.rem_euclid(size), "s {s} size {size}");
            assert_eq!(i1, (base + 1).rem_euclid(size));
            assert_eq!(w as f64, q - 256.0 * base as f64);
            assert!((w as f64 / 256.0 - (u - u.floor())).abs() <= 1.0 / 512.0 + 1e-12 || w == 0);
            let (c0, c1, cw) = linear_axis(s, size, WrapMode::ClampToEdge);
            assert_eq!(c0, base.clamp(0, size - 1));
            assert_eq!(c1, (base + 1).clamp(0, size - 1));
            assert_eq!(cw, w);
        }
    }

    /// `REPEAT` on sizes that are not powers of two: indices always inside the image, the
    /// second the first's right neighbour (wrapping), and the same weight as the rule for
    /// s in [0, 1).
    #[test]
    fn npot_repeat_stays_inside() {
        for size in [3i64, 5, 6, 7, 100, 1000] {
            for k in -3000..3000 {
                let s = k as f32 / 997.0;
                let (i0, i1, w) = linear_axis(s, size, WrapMode::Repeat);
                assert!(
                    (0..size).contains(&i0) && (0..size).contains(&i1),
                    "{s} {size}"
                );
                assert_eq!(i1, (i0 + 1) % size);
                let f = s - s.floor();
                let kk = ((f * size as f32) * 256.0).round_ties_even() as i64 - 128;
                assert_eq!(w as i64, kk & 255);
            }
            for s in [f32::NAN, f32::INFINITY, -1e-30, 1e30] {
                let (i0, i1, _) = linear_axis(s, size, WrapMode::Repeat);
                assert!((0..size).contains(&i0) && (0..size).contains(&i1));
            }
        }
    }

    /// A random RGBA8 image of `w` x `h` texels without a border.
    fn random_image(w: i32, h: i32, seed: &mut u64) -> TexImage {
        use super::super::format::InternalFormat;
        let format = InternalFormat::new(0x8058, BaseFormat::Rgba, 8);
        let mut img = TexImage::new(2, [w, h, 1], 0, format, false).expect("small image");
        if let Texels::U8(v) = std::sync::Arc::make_mut(&mut img.texels) {
            for b in v.iter_mut() {
                *b = (crate::test_support::xorshift(seed) >> 24) as u8;
            }
        }
        img
    }

    /// The specification's bilinear equation (section 3.8.8, equation 3.23 in 2D) in f64 on
    /// the bytes of `img`, at (s, t), wrapped by `mode`: `i0 = wrap(floor(u - 1/2))`,
    /// `alpha = frac(u - 1/2)`, the four texels weighted by `(1 - alpha)(1 - beta)` etc.
    fn spec_bilinear(img: &TexImage, mode: WrapMode, s: f32, t: f32) -> [f64; 4] {
        let Texels::U8(v) = &*img.texels else {
            unreachable!()
        };
        let (w, h) = (img.width as i64, img.height as i64);
        let axis = |c: f32, n: i64| {
            let u = c as f64 * n as f64 - 0.5;
            let f = u.floor();
            let i = f as i64;
            (
                wrap_index(i, n, mode, true),
                wrap_index(i + 1, n, mode, true),
                u - f,
            )
        };
        let (x0, x1, a) = axis(s, w);
        let (y0, y1, b) = axis(t, h);
        let at = |i: i64, j: i64, c: usize| v[((j * w + i) * 4) as usize + c] as f64;
        [0, 1, 2, 3].map(|c| {
            (1.0 - a) * (1.0 - b) * at(x0, y0, c)
                + a * (1.0 - b) * at(x1, y0, c)
                + (1.0 - a) * b * at(x0, y1, c)
                + a * b * at(x1, y1, c)
        })
    }

    /// The fixed-point bilinear filter against the specification's equation in real numbers,
    /// within the bound derived in the module documentation: 2 bytes for power-of-two sizes,
    /// 3 for others (their f32 product `s * size` rounds too), and a mix of two levels within
    /// the levels' bound plus 1.5 bytes. The bounds are reached within a byte (so they are
    /// not loose), and a filter with the weights truncated instead of rounded, or a lerp
    /// without its rounding term, breaks them.
    #[test]
    fn bilinear_is_within_the_quantisation_bound_of_the_spec() {
        let mut seed = 0x0123_4567_89AB_CDEFu64;
        let mut worst = [0f64; 2];
        for (w, h) in [
            (8, 8),
            (16, 4),
            (1, 32),
            (64, 64),
            (5, 7),
            (100, 3),
            (13, 1),
        ] {
            let pot = (w as i64 & (w as i64 - 1)) == 0 && (h as i64 & (h as i64 - 1)) == 0;
            let img = random_image(w, h, &mut seed);
            for mode in [WrapMode::Repeat, WrapMode::ClampToEdge] {
                for _ in 0..3000 {
                    let r = crate::test_support::xorshift(&mut seed);
                    let s = ((r >> 8) % 40_000) as f32 / 10_000.0 - 2.0;
                    let t = ((r >> 32) % 40_000) as f32 / 10_000.0 - 2.0;
                    let got = filter_image(&img, 2, [mode; 3], true, [s, t, 0.0]);
                    let want = spec_bilinear(&img, mode, s, t);
                    let bound = if pot { 2.0 } else { 3.0 };
                    for c in 0..4 {
                        let e = (got[c] as f64 - want[c]).abs();
                        worst[pot as usize] = worst[pot as usize].max(e);
                        assert!(
                            e <= bound,
                            "{w}x{h} {mode:?} ({s}, {t}) channel {c}: {} vs {}",
                            got[c],
                            want[c]
                        );
                    }
                }
            }
        }
        assert!(worst[1] > 1.0, "power-of-two worst {}", worst[1]);
        // Two levels mixed: each within 2 bytes of its equation, the mix within 1.5 more.
        let (l0, l1) = (
            random_image(16, 16, &mut seed),
            random_image(8, 8, &mut seed),
        );
        for k in 0..5000 {
            let r = crate::test_support::xorshift(&mut seed);
            let (s, t) = (
                ((r >> 8) % 1000) as f32 / 997.0,
                ((r >> 24) % 1000) as f32 / 991.0,
            );
            let f = (k % 256) as f32 / 256.0 + ((r >> 40) % 256) as f32 / 65536.0;
            let mode = WrapMode::Repeat;
            let got = lerp4(
                filter_image(&l0, 2, [mode; 3], true, [s, t, 0.0]),
                filter_image(&l1, 2, [mode; 3], true, [s, t, 0.0]),
                level_weight(f),
            );
            let (a, b) = (
                spec_bilinear(&l0, mode, s, t),
                spec_bilinear(&l1, mode, s, t),
            );
            for c in 0..4 {
                let want = a[c] + (b[c] - a[c]) * f as f64;
                assert!((got[c] as f64 - want).abs() <= 3.5, "{s} {t} {f}: {got:?}");
            }
        }
    }
}

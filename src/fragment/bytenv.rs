//! The texture environment on bytes, for draws whose cascade gives the same colour bytes in
//! 8-bit integers as in f32 (`FragmentKey::byte_env`, decided by [`applies`]).
//!
//! The eight-lane paths filter texels as bytes and convert them to f32 (`b * (1 / 255)`); the
//! environment then runs in f32 and the tail rounds the result to bytes (`c * 255 + 0.5`,
//! clamped, truncated). When every value entering a unit is such a converted byte, the units
//! before the last only select values (REPLACE and the like, whose f32 results are converted
//! bytes again) and the last is one of REPLACE, MODULATE, ADD, SUBTRACT, ADD_SIGNED (scaled
//! by 2 or 4) with any sources, operands and scale, the rounded f32 result is a function of
//! the input bytes that integer arithmetic computes exactly: the exact result times 255 is
//! never within the f32 rounding errors of a half (MODULATE: `2 s a b = 255 (2 n + 1)` has an
//! even left side and an odd right side; sums and differences are integers), so the f32 route
//! rounds it to the nearest byte, as the integer route does. `every_byte_formula_matches_the_f32_
//! equations` checks each function over every pair of bytes, operand and scale (the proof);
//! `byte_route_equals_the_f32_route` twins the whole cascade on random draws. ADD_SIGNED with
//! scale 1 (`a + b - 127.5` then `+ 0.5`: exactly an integer before truncation, where f32
//! rounding decides) and INTERPOLATE, BLEND, DECAL of RGBA, DOT3 and COMBINE4 stay in f32.
//!
//! Values are RGBA in 16-bit lanes: a pixel's four channels in one 64-bit lane, four pixels in
//! an AVX2 register, eight pixels in two (`Px`, from `_mm256_unpacklo_epi8` and
//! `_mm256_unpackhi_epi8` of the colour words).

use super::draw::TextureUnitDraw;
use super::key::FragmentKey;
use super::texenv::TexEnv;
use crate::common::limits::MAX_TEXTURE_UNITS;
use crate::common::values::{CombineFunc, CombineOperand, CombineSource, TexEnvMode};
use crate::texture::format::BaseFormat;

/// The byte of `v` when `v` is a converted byte (`b as f32 * (1.0 / 255.0)`, or 1 for 255, as
/// the filter and the base format's expansion give them); `None` otherwise.
pub fn exact_byte(v: f32) -> Option<u8> {
    if !(0.0..=1.0).contains(&v) {
        return None;
    }
    let b = (v * 255.0).round() as u8;
    (v == b as f32 * (1.0 / 255.0) || v == 1.0).then_some(b)
}

/// Which of colour and alpha a texture of base format `base` has (table 3.22).
pub(crate) fn has_color_alpha(base: BaseFormat) -> (bool, bool) {
    match base {
        BaseFormat::Alpha => (false, true),
        BaseFormat::Luminance
        | BaseFormat::Rgb
        | BaseFormat::DepthComponent
        | BaseFormat::Red
        | BaseFormat::Rg => (true, false),
        BaseFormat::LuminanceAlpha | BaseFormat::Rgba | BaseFormat::Intensity => (true, true),
    }
}

/// Whether the unit's result is one of its inputs channel by channel (so a converted byte
/// when they are).
fn selects(env: &TexEnv, base: BaseFormat) -> bool {
    match env.mode {
        TexEnvMode::Replace => true,
        TexEnvMode::Decal => base != BaseFormat::Rgba,
        TexEnvMode::Combine => {
            let k = &env.combine;
            k.rgb == CombineFunc::Replace
                && k.alpha == CombineFunc::Replace
                && k.rgb_scale == 1
                && k.alpha_scale == 1
                && matches!(
                    k.op_rgb[0],
                    CombineOperand::SrcColor | CombineOperand::SrcAlpha
                )
                && matches!(
                    k.op_alpha[0],
                    CombineOperand::SrcColor | CombineOperand::SrcAlpha
                )
        }
        _ => false,
    }
}

/// Whether the integer route computes the unit's rounded result.
fn computes(env: &TexEnv, base: BaseFormat) -> bool {
    let func = |f: CombineFunc, scale: u8| match f {
        CombineFunc::Replace | CombineFunc::Modulate | CombineFunc::Add => true,
        CombineFunc::Subtract => true,
        CombineFunc::AddSigned => scale > 1,
        _ => false,
    };
    match env.mode {
        TexEnvMode::Replace | TexEnvMode::Modulate | TexEnvMode::Add => true,
        TexEnvMode::Decal => base != BaseFormat::Rgba,
        TexEnvMode::Combine => {
            let k = &env.combine;
            func(k.rgb, k.rgb_scale) && func(k.alpha, k.alpha_scale)
        }
        TexEnvMode::Blend | TexEnvMode::Combine4 => false,
    }
}

/// Whether unit `env` reads the constant colour.
fn reads_constant(env: &TexEnv) -> bool {
    env.mode == TexEnvMode::Blend
        || (matches!(env.mode, TexEnvMode::Combine | TexEnvMode::Combine4)
            && (env.combine.src_rgb.contains(&CombineSource::Constant)
                || env.combine.src_alpha.contains(&CombineSource::Constant)))
}

/// Whether a draw with `key` and `units` takes the byte environment: the eight-lane sampled
/// route with nothing after the environment that needs its f32 colour (no alpha test, colour
/// sum or fog), at least one unit and not one REPLACE/MODULATE unit alone (whose environment
/// runs in the tail), every unit's texture 2D, the units before the last selecting, the last
/// computed by the integer route, and every constant colour read a converted byte. (The
/// primary colour is checked per block: it must be a converted byte at the block's lanes.)
pub fn applies(key: &FragmentKey, units: &[TextureUnitDraw]) -> bool {
    key.simd_units
        && key.alpha_func.is_none()
        && !key.color_sum
        && key.fog.is_none()
        && units.iter().all(|u| u.texture.face_count() == 1)
        && cascade_applies(&units.iter().map(|u| (u.env, u.base)).collect::<Vec<_>>())
}

/// [`applies`]' conditions on the units' environments and base formats.
pub fn cascade_applies(units: &[(TexEnv, BaseFormat)]) -> bool {
    let Some(((last_env, last_base), first)) = units.split_last() else {
        return false;
    };
    let single =
        units.len() == 1 && matches!(last_env.mode, TexEnvMode::Replace | TexEnvMode::Modulate);
    !single
        && units.iter().all(|(env, _)| {
            !reads_constant(env) || env.color.iter().all(|&c| exact_byte(c).is_some())
        })
        && first.iter().all(|(env, base)| selects(env, *base))
        && computes(last_env, *last_base)
}

/// Where a byte of a compiled argument ([`Bytes`]) comes from: channel `ch` of input `input`
/// (0: the primary colour; `k + 1`: the texel of the draw's `k`-th unit), complemented
/// (`255 - v`) or not; or a constant byte.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Byte {
    Input { input: u8, ch: u8, complement: bool },
    Const(u8),
}

impl Byte {
    fn complement(self) -> Byte {
        match self {
            Byte::Input {
                input,
                ch,
                complement,
            } => Byte::Input {
                input,
                ch,
                complement: !complement,
            },
            Byte::Const(b) => Byte::Const(255 - b),
        }
    }
}

/// One argument of [`Bytes`] as colour words: the OR of `pshufb(input, control)` over the
/// inputs it reads and of its constant bytes, XORed with `complement` (0xFF in the bytes
/// that are `255 - v`: the same byte).
#[derive(Clone, Debug, PartialEq)]
struct ByteArg {
    shuffles: Vec<(usize, [i8; 32])>,
    constant: u32,
    complement: u32,
}

impl ByteArg {
    fn new(bytes: [Byte; 4]) -> ByteArg {
        let mut arg = ByteArg {
            shuffles: Vec::new(),
            constant: 0,
            complement: 0,
        };
        for (c, b) in bytes.into_iter().enumerate() {
            match b {
                Byte::Const(v) => arg.constant |= (v as u32) << (8 * c),
                Byte::Input {
                    input,
                    ch,
                    complement,
                } => {
                    if complement {
                        arg.complement |= 0xFF << (8 * c);
                    }
                    let at = match arg.shuffles.iter().position(|s| s.0 == input as usize) {
                        Some(i) => i,
                        None => {
                            arg.shuffles.push((input as usize, [-1; 32]));
                            arg.shuffles.len() - 1
                        }
                    };
                    // Within each 128-bit lane (four pixels), pixel p's channel c takes its
                    // own channel `ch`.
                    for (i, v) in arg.shuffles[at].1.iter_mut().enumerate() {
                        if i % 4 == c {
                            *v = (i % 16 - c + ch as usize) as i8;
                        }
                    }
                }
            }
        }
        arg
    }
}

/// The cascade of a [`cascade_applies`] draw compiled for the byte route once per draw
/// (`Bytes::run`): the selecting units folded into which input channel each byte of the last
/// unit's incoming colour is, the last unit's two arguments built from the inputs by byte
/// shuffles, then its RGB and alpha functions as [`cascade`] computes them. The same bytes as
/// [`cascade`] (twin `tests::byte_route_equals_the_f32_route`), without matching the modes,
/// sources and operands per block.
#[derive(Clone, Debug, PartialEq)]
pub struct Bytes {
    args: [ByteArg; 2],
    rgb: CombineFunc,
    alpha: CombineFunc,
    rgb_scale: u8,
    alpha_scale: u8,
    /// Whether the second argument is read (a function other than REPLACE).
    reads_second: bool,
}

impl Bytes {
    /// The compiled cascade of `units` (environment, base format, unit number, in unit
    /// order), when [`cascade_applies`] takes it.
    pub fn new(units: &[(TexEnv, BaseFormat, usize)]) -> Option<Bytes> {
        let pairs: Vec<_> = units.iter().map(|&(e, b, _)| (e, b)).collect();
        if !cascade_applies(&pairs) || units.len() > MAX_TEXTURE_UNITS {
            return None;
        }
        let input = |i: usize| {
            [0, 1, 2, 3].map(|ch| Byte::Input {
                input: i as u8,
                ch,
                complement: false,
            })
        };
        let primary = input(0);
        // `source` of the unit at index `k` with incoming colour `cf`.
        let source = |s: CombineSource, k: usize, env: &TexEnv, cf: [Byte; 4]| match s {
            CombineSource::Texture => input(k + 1),
            CombineSource::TextureUnit(u) => match units.iter().position(|e| e.2 == u as usize) {
                Some(i) => input(i + 1),
                None => cf,
            },
            CombineSource::Constant => env.color.map(|c| Byte::Const(exact_byte(c).unwrap_or(0))),
            CombineSource::PrimaryColor => primary,
            CombineSource::Previous => cf,
            CombineSource::Zero => [Byte::Const(0); 4],
        };
        // `argument` `i` of a COMBINE unit.
        let argument = |env: &TexEnv, k: usize, i: usize, cf: [Byte; 4]| {
            let c = &env.combine;
            let v = source(c.src_rgb[i], k, env, cf);
            let rgb = match c.op_rgb[i] {
                CombineOperand::SrcColor => [v[0], v[1], v[2]],
                CombineOperand::OneMinusSrcColor => [v[0], v[1], v[2]].map(Byte::complement),
                CombineOperand::SrcAlpha => [v[3]; 3],
                CombineOperand::OneMinusSrcAlpha => [v[3].complement(); 3],
            };
            let a = source(c.src_alpha[i], k, env, cf)[3];
            let a = match c.op_alpha[i] {
                CombineOperand::SrcAlpha | CombineOperand::SrcColor => a,
                _ => a.complement(),
            };
            [rgb[0], rgb[1], rgb[2], a]
        };
        let with_alpha = |c: [Byte; 4], a: [Byte; 4]| [c[0], c[1], c[2], a[3]];
        let mut cf = primary;
        let (last, first) = units.split_last()?;
        // The selecting units (`selects`): each byte one of the inputs'.
        for (k, (env, base, _)) in first.iter().enumerate() {
            let (has_color, has_alpha) = has_color_alpha(*base);
            let ct = input(k + 1);
            cf = match env.mode {
                TexEnvMode::Replace => with_alpha(
                    if has_color { ct } else { cf },
                    if has_alpha { ct } else { cf },
                ),
                TexEnvMode::Decal if *base == BaseFormat::Rgb => with_alpha(ct, cf),
                TexEnvMode::Decal => cf,
                // REPLACE of argument 0 at scale 1 (`selects`).
                TexEnvMode::Combine => argument(env, k, 0, cf),
                _ => return None,
            };
        }
        let k = first.len();
        let (env, base, _) = last;
        let (has_color, has_alpha) = has_color_alpha(*base);
        let ct = input(k + 1);
        let pick = |yes: bool, f: CombineFunc| if yes { f } else { CombineFunc::Replace };
        use CombineFunc as F;
        let (a0, a1, rgb, alpha, rgb_scale, alpha_scale) = match env.mode {
            TexEnvMode::Replace => {
                let a0 = with_alpha(
                    if has_color { ct } else { cf },
                    if has_alpha { ct } else { cf },
                );
                (a0, a0, F::Replace, F::Replace, 1, 1)
            }
            TexEnvMode::Modulate => (
                cf,
                ct,
                pick(has_color, F::Modulate),
                pick(has_alpha, F::Modulate),
                1,
                1,
            ),
            TexEnvMode::Add => {
                let alpha = match base {
                    BaseFormat::Intensity => F::Add,
                    _ => pick(has_alpha, F::Modulate),
                };
                (cf, ct, pick(has_color, F::Add), alpha, 1, 1)
            }
            TexEnvMode::Decal if *base == BaseFormat::Rgb => {
                let a0 = with_alpha(ct, cf);
                (a0, a0, F::Replace, F::Replace, 1, 1)
            }
            TexEnvMode::Decal => (cf, cf, F::Replace, F::Replace, 1, 1),
            TexEnvMode::Combine => {
                let c = &env.combine;
                (
                    argument(env, k, 0, cf),
                    argument(env, k, 1, cf),
                    c.rgb,
                    c.alpha,
                    c.rgb_scale,
                    c.alpha_scale,
                )
            }
            _ => return None,
        };
        Some(Bytes {
            args: [ByteArg::new(a0), ByteArg::new(a1)],
            rgb,
            alpha,
            rgb_scale,
            alpha_scale,
            reads_second: rgb != F::Replace || alpha != F::Replace,
        })
    }
}

#[cfg(target_arch = "x86_64")]
pub(crate) use x86::*;

/// [`exact_words`] as an array, when the processor has AVX2 (`None` otherwise).
pub fn exact_word_array(c: &crate::texture::simd::Texels8, live: u8) -> Option<[u32; 8]> {
    #[cfg(target_arch = "x86_64")]
    {
        if crate::common::cpu::available() {
            // SAFETY: AVX2 is present (checked just above); `out` holds eight u32, an
            // unaligned store.
            return unsafe {
                let w = exact_words(c, live)?;
                let mut out = [0u32; 8];
                std::arch::x86_64::_mm256_storeu_si256(
                    out.as_mut_ptr() as *mut std::arch::x86_64::__m256i,
                    w,
                );
                Some(out)
            };
        }
    }
    let _ = (c, live);
    None
}

#[cfg(target_arch = "x86_64")]
mod x86 {
    use std::arch::x86_64::*;

    use super::has_color_alpha;
    use crate::common::limits::MAX_TEXTURE_UNITS;
    use crate::common::values::{CombineFunc, CombineOperand, CombineSource, TexEnvMode};
    use crate::fragment::draw::FragmentDraw;
    use crate::fragment::simd::Tail8;
    use crate::fragment::texenv::{Combine, TexEnv};
    use crate::texture::format::BaseFormat;
    use crate::texture::simd::Texels8;

    /// Eight pixels' R, G, B, A in 16-bit lanes: pixels 0, 1, 4, 5 and 2, 3, 6, 7 (the
    /// unpacked low and high halves of the colour words' 128-bit lanes).
    #[derive(Clone, Copy)]
    pub struct Px(__m256i, __m256i);

    impl Px {
        /// From colour words (R in the low byte).
        #[inline]
        #[target_feature(enable = "avx2")]
        pub fn of_words(w: __m256i) -> Px {
            let z = _mm256_setzero_si256();
            Px(_mm256_unpacklo_epi8(w, z), _mm256_unpackhi_epi8(w, z))
        }

        /// To colour words, each value clamped to [0, 255].
        #[inline]
        #[target_feature(enable = "avx2")]
        pub fn words(self) -> __m256i {
            _mm256_packus_epi16(self.0, self.1)
        }

        #[inline]
        #[target_feature(enable = "avx2")]
        fn splat(rgba: [u8; 4]) -> Px {
            Px::of_words(_mm256_set1_epi32(u32::from_le_bytes(rgba) as i32))
        }

        #[inline]
        #[target_feature(enable = "avx2")]
        fn map(self, f: impl Fn(__m256i) -> __m256i) -> Px {
            Px(f(self.0), f(self.1))
        }

        #[inline]
        #[target_feature(enable = "avx2")]
        fn zip(self, o: Px, f: impl Fn(__m256i, __m256i) -> __m256i) -> Px {
            Px(f(self.0, o.0), f(self.1, o.1))
        }

        /// Each pixel's alpha in its four channels.
        #[inline]
        #[target_feature(enable = "avx2")]
        fn alpha(self) -> Px {
            self.map(|v| _mm256_shufflehi_epi16::<0xFF>(_mm256_shufflelo_epi16::<0xFF>(v)))
        }

        /// 255 - v.
        #[inline]
        #[target_feature(enable = "avx2")]
        fn complement(self) -> Px {
            self.map(|v| _mm256_sub_epi16(_mm256_set1_epi16(255), v))
        }

        /// R, G, B of `self` and A of `a`.
        #[inline]
        #[target_feature(enable = "avx2")]
        fn with_alpha(self, a: Px) -> Px {
            self.zip(a, |c, a| _mm256_blend_epi16::<0x88>(c, a))
        }
    }

    /// `round(s v / 255)` for `v` = a b (or a sum of such products) up to 255 * 255, at most
    /// 255: `min(v, ceil(65025 / s)) s + 127` stays below 2^16 (no product above the clamp
    /// rounds below 255), and `(t * 0x8081) >> 23` is `t / 255` for t < 66052.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn round_scaled(v: __m256i, scale: u8) -> __m256i {
        let v = match scale {
            1 => v,
            2 => _mm256_slli_epi16::<1>(_mm256_min_epu16(v, _mm256_set1_epi16(32513))),
            _ => _mm256_slli_epi16::<2>(_mm256_min_epu16(v, _mm256_set1_epi16(16257))),
        };
        let t = _mm256_add_epi16(v, _mm256_set1_epi16(127));
        _mm256_srli_epi16::<7>(_mm256_mulhi_epu16(t, _mm256_set1_epi16(0x8081u16 as i16)))
    }

    /// `v * scale` (1, 2 or 4) for values that stay within i16.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn times(v: __m256i, scale: u8) -> __m256i {
        match scale {
            1 => v,
            2 => _mm256_slli_epi16::<1>(v),
            _ => _mm256_slli_epi16::<2>(v),
        }
    }

    /// A combiner function on bytes, scaled (the clamp to [0, 255] comes with [`Px::words`]).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn func(f: CombineFunc, a: Px, b: Px, scale: u8) -> Px {
        match f {
            CombineFunc::Replace => a.map(|a| times(a, scale)),
            CombineFunc::Modulate => a.zip(b, |a, b| round_scaled(_mm256_mullo_epi16(a, b), scale)),
            CombineFunc::Add => a.zip(b, |a, b| times(_mm256_add_epi16(a, b), scale)),
            CombineFunc::Subtract => a.zip(b, |a, b| times(_mm256_sub_epi16(a, b), scale)),
            // Scales 2 and 4 only ([`super::applies`]): s (a + b) - 255 s / 2.
            _ => a.zip(b, |a, b| {
                let half = _mm256_set1_epi16(if scale == 2 { 255 } else { 510 });
                _mm256_sub_epi16(times(_mm256_add_epi16(a, b), scale), half)
            }),
        }
    }

    /// What a unit reads besides the previous colour.
    struct Inputs<'a> {
        primary: Px,
        /// Each unit's texel by unit number, as colour words.
        texels: &'a [Option<__m256i>; MAX_TEXTURE_UNITS],
    }

    #[inline]
    #[target_feature(enable = "avx2")]
    fn source(s: CombineSource, cf: Px, ct: Px, cc: Px, inputs: &Inputs) -> Px {
        match s {
            CombineSource::Texture => ct,
            CombineSource::TextureUnit(u) => match inputs.texels[u as usize] {
                Some(w) => Px::of_words(w),
                None => cf,
            },
            CombineSource::Constant => cc,
            CombineSource::PrimaryColor => inputs.primary,
            CombineSource::Previous => cf,
            CombineSource::Zero => Px::splat([0; 4]),
        }
    }

    /// Argument `i` (RGB in the colour channels, alpha in the alpha channel).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn argument(k: &Combine, i: usize, cf: Px, ct: Px, cc: Px, inputs: &Inputs) -> Px {
        let rgb = source(k.src_rgb[i], cf, ct, cc, inputs);
        let rgb = match k.op_rgb[i] {
            CombineOperand::SrcColor => rgb,
            CombineOperand::OneMinusSrcColor => rgb.complement(),
            CombineOperand::SrcAlpha => rgb.alpha(),
            CombineOperand::OneMinusSrcAlpha => rgb.alpha().complement(),
        };
        let a = source(k.src_alpha[i], cf, ct, cc, inputs);
        let a = match k.op_alpha[i] {
            CombineOperand::SrcAlpha | CombineOperand::SrcColor => a,
            _ => a.complement(),
        };
        rgb.with_alpha(a)
    }

    /// One unit's environment on bytes ([`super::computes`] holds for it): as
    /// `texenv::apply`, with the results of the integer route.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn apply(env: &TexEnv, base: BaseFormat, cf: Px, ct: Px, inputs: &Inputs) -> Px {
        let (has_color, has_alpha) = has_color_alpha(base);
        let pick = |yes: bool, t: Px, f: Px| if yes { t } else { f };
        match env.mode {
            TexEnvMode::Replace => pick(has_color, ct, cf).with_alpha(pick(has_alpha, ct, cf)),
            TexEnvMode::Modulate => {
                let m = func(CombineFunc::Modulate, cf, ct, 1);
                pick(has_color, m, cf).with_alpha(pick(has_alpha, m, cf))
            }
            TexEnvMode::Add => {
                let sum = func(CombineFunc::Add, cf, ct, 1);
                let a = match base {
                    BaseFormat::Intensity => sum,
                    _ if has_alpha => func(CombineFunc::Modulate, cf, ct, 1),
                    _ => cf,
                };
                pick(has_color, sum, cf).with_alpha(a)
            }
            // Not RGBA ([`super::computes`]).
            TexEnvMode::Decal if base == BaseFormat::Rgb => ct.with_alpha(cf),
            TexEnvMode::Combine => {
                let k = &env.combine;
                // Only arguments 0 and 1 are read (the functions this route computes take at
                // most two); GL's default third source is the constant colour, which costs a
                // conversion per block if asked for regardless.
                let constant = CombineSource::Constant;
                let cc =
                    if k.src_rgb[..2].contains(&constant) || k.src_alpha[..2].contains(&constant) {
                        Px::splat(env.color.map(|c| super::exact_byte(c).unwrap_or(0)))
                    } else {
                        Px::splat([0; 4])
                    };
                let a0 = argument(k, 0, cf, ct, cc, inputs);
                let a1 = argument(k, 1, cf, ct, cc, inputs);
                let rgb = func(k.rgb, a0, a1, k.rgb_scale);
                let alpha = func(k.alpha, a0, a1, k.alpha_scale);
                // (Unclamped: only the last unit computes, and the words clamp.)
                rgb.with_alpha(alpha)
            }
            _ => cf,
        }
    }

    /// The byte of each of the eight lanes' channels of `c` clamped to [0, 1], as colour
    /// words, when at every lane of `live` it is a converted byte (`super::exact_byte`).
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn exact_words(c: &Texels8, live: u8) -> Option<__m256i> {
        let (zero, one) = (_mm256_setzero_ps(), _mm256_set1_ps(1.0));
        let k = _mm256_set1_ps(1.0 / 255.0);
        let mut ok = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
        let mut words = _mm256_setzero_si256();
        for (ch, v) in c.iter().enumerate() {
            // SAFETY: eight f32; unaligned load.
            let v = unsafe { _mm256_loadu_ps(v.as_ptr()) };
            // As `clamp01`: max_ps answers 0 for NaN.
            let v = _mm256_min_ps(_mm256_max_ps(v, zero), one);
            let b = _mm256_cvtps_epi32(_mm256_mul_ps(v, _mm256_set1_ps(255.0)));
            let back = _mm256_mul_ps(_mm256_cvtepi32_ps(b), k);
            let exact = _mm256_or_ps(
                _mm256_cmp_ps::<_CMP_EQ_OQ>(back, v),
                _mm256_cmp_ps::<_CMP_EQ_OQ>(v, one),
            );
            ok = _mm256_and_ps(ok, exact);
            let shifted = match ch {
                0 => b,
                1 => _mm256_slli_epi32::<8>(b),
                2 => _mm256_slli_epi32::<16>(b),
                _ => _mm256_slli_epi32::<24>(b),
            };
            words = _mm256_or_si256(words, shifted);
        }
        let live_bits = live as i32;
        (_mm256_movemask_ps(ok) & live_bits == live_bits).then_some(words)
    }

    /// The cascade of a [`super::applies`] draw on bytes: `primary` and each unit's texel by
    /// unit number as colour words (R, G, B, A bytes), the units as (environment, base
    /// format, unit number); answers the colour words.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn cascade<'u>(
        units: impl Iterator<Item = (&'u TexEnv, BaseFormat, usize)>,
        primary: __m256i,
        by_unit: &[Option<__m256i>; MAX_TEXTURE_UNITS],
    ) -> __m256i {
        let primary = Px::of_words(primary);
        let inputs = Inputs {
            primary,
            texels: by_unit,
        };
        let mut color = primary;
        for (env, base, unit) in units {
            let ct = Px::of_words(by_unit[unit].unwrap_or(_mm256_setzero_si256()));
            color = apply(env, base, color, ct, &inputs);
        }
        color.words()
    }

    impl super::Bytes {
        /// The compiled cascade on eight pixels: `inputs[0]` the primary colour's words,
        /// `inputs[k + 1]` the texel words (`rgba_of_words`) of the draw's `k`-th unit;
        /// answers the colour words, those of [`cascade`].
        ///
        /// # Safety
        /// The processor has AVX2.
        #[inline]
        #[target_feature(enable = "avx2")]
        pub fn run(&self, inputs: &[__m256i]) -> __m256i {
            let arg = |a: &super::ByteArg| {
                let mut w = _mm256_set1_epi32(a.constant as i32);
                for (input, control) in &a.shuffles {
                    // SAFETY: 32 bytes; unaligned load.
                    let control = unsafe { _mm256_loadu_si256(control.as_ptr() as *const __m256i) };
                    let v = inputs
                        .get(*input)
                        .copied()
                        .unwrap_or(_mm256_setzero_si256());
                    w = _mm256_or_si256(w, _mm256_shuffle_epi8(v, control));
                }
                Px::of_words(_mm256_xor_si256(w, _mm256_set1_epi32(a.complement as i32)))
            };
            let a0 = arg(&self.args[0]);
            let a1 = if self.reads_second {
                arg(&self.args[1])
            } else {
                a0
            };
            if self.rgb == self.alpha && self.rgb_scale == self.alpha_scale {
                return func(self.rgb, a0, a1, self.rgb_scale).words();
            }
            let rgb = func(self.rgb, a0, a1, self.rgb_scale);
            let alpha = func(self.alpha, a0, a1, self.alpha_scale);
            rgb.with_alpha(alpha).words()
        }
    }

    /// [`cascade`] over the draw's units.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn environment(
        ds: &FragmentDraw,
        primary: __m256i,
        by_unit: &[Option<__m256i>; MAX_TEXTURE_UNITS],
    ) -> __m256i {
        cascade(
            ds.units.iter().map(|u| (&u.env, u.base, u.unit)),
            primary,
            by_unit,
        )
    }

    /// [`environment`] and the tail ([`crate::fragment::simd::shade8_bytes`]) for a group
    /// with colour words `primary` and the stored colours `dst`.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub fn shade(
        ds: &FragmentDraw,
        tail: &Tail8,
        primary: __m256i,
        by_unit: &[Option<__m256i>; MAX_TEXTURE_UNITS],
        dst: &[u32; 8],
        pass: u8,
    ) -> ([u32; 8], u8) {
        let rgba = environment(ds, primary, by_unit);
        crate::fragment::simd::shade8_bytes(tail, rgba, dst, pass)
    }
}

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use std::arch::x86_64::*;

    use super::*;
    use crate::common::fixed::color_to_u8;
    use crate::common::limits::MAX_TEXTURE_UNITS;
    use crate::fragment::texenv::{apply, CombineInputs, Lanes8};
    use CombineFunc as F;
    use CombineOperand as O;
    use CombineSource as S;

    /// A byte as the filter converts it; with `one`, 255 as 1 (as the expansions give it).
    fn conv(b: u8, one: bool) -> f32 {
        if one && b == 255 {
            1.0
        } else {
            b as f32 * (1.0 / 255.0)
        }
    }

    fn words(channels: &[[u8; 8]; 4]) -> __m256i {
        let w: [u32; 8] =
            std::array::from_fn(|j| u32::from_le_bytes(std::array::from_fn(|c| channels[c][j])));
        // SAFETY: eight u32; unaligned load.
        unsafe { _mm256_loadu_si256(w.as_ptr() as *const __m256i) }
    }

    fn unpack(w: __m256i) -> [[u8; 4]; 8] {
        let mut out = [0u32; 8];
        // SAFETY: eight u32; unaligned store.
        unsafe { _mm256_storeu_si256(out.as_mut_ptr() as *mut __m256i, w) };
        out.map(u32::to_le_bytes)
    }

    /// The f32 route's bytes: the cascade in f32 on converted bytes, then `color_to_u8`.
    fn f32_route(
        units: &[(TexEnv, BaseFormat, usize)],
        primary: [Lanes8; 4],
        texels: &[Option<[Lanes8; 4]>; 8],
    ) -> [[u8; 4]; 8] {
        let inputs = CombineInputs { primary, texels };
        let mut color = primary;
        for (env, base, unit) in units {
            let ct = texels[*unit].unwrap_or([[0.0; 8]; 4]);
            color = apply(env, *base, *unit, color, ct, &inputs);
        }
        std::array::from_fn(|j| std::array::from_fn(|c| color_to_u8(color[c][j])))
    }

    fn byte_route(
        units: &[(TexEnv, BaseFormat, usize)],
        primary: __m256i,
        by_unit: &[Option<__m256i>; MAX_TEXTURE_UNITS],
    ) -> [[u8; 4]; 8] {
        assert!(std::arch::is_x86_feature_detected!("avx2"));
        // SAFETY: AVX2 is present (asserted just above).
        unpack(unsafe { cascade(units.iter().map(|(e, b, u)| (e, *b, *u)), primary, by_unit) })
    }

    /// The proof of the integer route: for every function it computes, every scale, both
    /// operands of each argument and every pair of bytes (255 also as 1), the f32 equations
    /// of `texenv` rounded by `color_to_u8` give the integer route's byte.
    #[test]
    fn every_byte_formula_matches_the_f32_equations() {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return;
        }
        let funcs = [F::Replace, F::Modulate, F::Add, F::Subtract, F::AddSigned];
        let complements = [
            (O::SrcColor, O::SrcAlpha),
            (O::OneMinusSrcColor, O::OneMinusSrcAlpha),
        ];
        let mut checked = 0u64;
        for f in funcs {
            for scale in [1u8, 2, 4] {
                if f == F::AddSigned && scale == 1 {
                    continue;
                }
                for (op0, op1) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
                    let mut env = TexEnv {
                        mode: TexEnvMode::Combine,
                        ..TexEnv::default()
                    };
                    let k = &mut env.combine;
                    (k.rgb, k.alpha, k.rgb_scale, k.alpha_scale) = (f, f, scale, scale);
                    k.src_rgb[..2].copy_from_slice(&[S::Previous, S::Texture]);
                    k.src_alpha[..2].copy_from_slice(&[S::Previous, S::Texture]);
                    k.op_rgb[..2].copy_from_slice(&[complements[op0].0, complements[op1].0]);
                    k.op_alpha[..2].copy_from_slice(&[complements[op0].1, complements[op1].1]);
                    assert!(computes(&env, BaseFormat::Rgba));
                    let units = [(env, BaseFormat::Rgba, 0)];
                    for one in [false, true] {
                        for a in 0..=255u8 {
                            for b0 in (0..256).step_by(8) {
                                let b: [u8; 8] = std::array::from_fn(|j| (b0 + j) as u8);
                                let cf = [[a; 8], b, [a; 8], [255 - a; 8]];
                                let ct = [b, [a; 8], b.map(|b| 255 - b), b];
                                let f32s = |v: [[u8; 8]; 4]| v.map(|c| c.map(|x| conv(x, one)));
                                let mut texels = [None; 8];
                                texels[0] = Some(f32s(ct));
                                let want = f32_route(&units, f32s(cf), &texels);
                                let mut by_unit = [None; MAX_TEXTURE_UNITS];
                                by_unit[0] = Some(words(&ct));
                                let got = byte_route(&units, words(&cf), &by_unit);
                                assert_eq!(
                                    got, want,
                                    "{f:?} x{scale} ops {op0}{op1} a {a} b {b0}.."
                                );
                                checked += 32;
                            }
                        }
                    }
                }
            }
        }
        assert_eq!(checked, 14 * 4 * 2 * 65536 * 4);
    }

    /// A small deterministic generator.
    struct Gen(u64);
    impl Gen {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }
        fn byte(&mut self) -> u8 {
            (self.next() >> 32) as u8
        }
        fn pick<T: Copy>(&mut self, v: &[T]) -> T {
            v[(self.next() % v.len() as u64) as usize]
        }
    }

    /// Stored components of `base` expanded to R, G, B, A in f32, as the eight-pixel filter
    /// expands them (`texture::simd` `expand8`).
    fn expand(base: BaseFormat, s: [f32; 4]) -> [f32; 4] {
        match base {
            BaseFormat::Rgba => s,
            BaseFormat::Rgb => [s[0], s[1], s[2], 1.0],
            BaseFormat::LuminanceAlpha => [s[0], s[0], s[0], s[1]],
            BaseFormat::Intensity => [s[0]; 4],
            BaseFormat::Alpha => [0.0, 0.0, 0.0, s[0]],
            _ => [s[0], s[0], s[0], 1.0],
        }
    }

    /// Twin of the whole byte route against the f32 route on random cascades that
    /// [`cascade_applies`] takes (one to four units of random base formats, modes, combiner
    /// functions, sources, operands, scales and constant colours), random stored texels
    /// expanded by `rgba_of_words`, and random primary colours through `exact_words`.
    #[test]
    fn byte_route_equals_the_f32_route() {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return;
        }
        let mut g = Gen(0x2545_F491_4F6C_DD1D);
        let modes = [
            TexEnvMode::Replace,
            TexEnvMode::Modulate,
            TexEnvMode::Decal,
            TexEnvMode::Blend,
            TexEnvMode::Add,
            TexEnvMode::Combine,
            TexEnvMode::Combine,
            TexEnvMode::Combine,
        ];
        let bases = [
            BaseFormat::Alpha,
            BaseFormat::Luminance,
            BaseFormat::LuminanceAlpha,
            BaseFormat::Intensity,
            BaseFormat::Rgb,
            BaseFormat::Rgba,
        ];
        let funcs = [
            F::Replace,
            F::Replace,
            F::Modulate,
            F::Add,
            F::AddSigned,
            F::Subtract,
            F::Interpolate,
        ];
        let sources = [
            S::Texture,
            S::TextureUnit(0),
            S::TextureUnit(2),
            S::TextureUnit(6),
            S::Constant,
            S::PrimaryColor,
            S::Previous,
            S::Zero,
        ];
        let operands = [
            O::SrcColor,
            O::OneMinusSrcColor,
            O::SrcAlpha,
            O::OneMinusSrcAlpha,
        ];
        let (mut taken, mut multi, mut cases) = (0, 0, 0);
        while taken < 3000 {
            cases += 1;
            let n = 1 + (g.next() % 4) as usize;
            let mut units = Vec::new();
            for k in 0..n {
                let mut env = TexEnv {
                    mode: g.pick(&modes),
                    ..TexEnv::default()
                };
                env.color = [0; 4].map(|_| conv(g.byte(), g.next().is_multiple_of(2)));
                if g.next().is_multiple_of(8) {
                    env.color[0] = 0.3;
                }
                let c = &mut env.combine;
                c.rgb = g.pick(&funcs);
                c.alpha = g.pick(&funcs);
                for i in 0..3 {
                    c.src_rgb[i] = g.pick(&sources);
                    c.src_alpha[i] = g.pick(&sources);
                    c.op_rgb[i] = g.pick(&operands);
                    c.op_alpha[i] = g.pick(&operands);
                }
                // Selecting units are rare by chance: make the first ones REPLACE often.
                if k + 1 < n && g.next().is_multiple_of(2) {
                    (c.rgb, c.alpha) = (F::Replace, F::Replace);
                    c.op_rgb[0] = O::SrcColor;
                    c.op_alpha[0] = O::SrcAlpha;
                }
                c.rgb_scale = g.pick(&[1, 1, 2, 4]);
                c.alpha_scale = g.pick(&[1, 1, 2, 4]);
                if k + 1 < n && g.next().is_multiple_of(2) {
                    (c.rgb_scale, c.alpha_scale) = (1, 1);
                }
                // Units 0, 2, 3 (unit 6 is absent: crossbar reads of it give the previous
                // colour).
                units.push((env, g.pick(&bases), [0, 2, 3][k.min(2)]));
            }
            if units.len() == 4 {
                units.pop();
            }
            let pairs: Vec<_> = units.iter().map(|&(e, b, _)| (e, b)).collect();
            if !cascade_applies(&pairs) {
                continue;
            }
            taken += 1;
            multi += usize::from(units.len() > 1);
            let primary: [[u8; 8]; 4] = [0; 4].map(|_| [0; 8].map(|_| g.byte()));
            let one = g.next().is_multiple_of(2);
            let primary_f = primary.map(|c| c.map(|b| conv(b, one)));
            let mut texels_f = [None; 8];
            let mut by_unit = [None; MAX_TEXTURE_UNITS];
            for &(_, base, unit) in &units {
                let stored: [[u8; 4]; 8] = [0; 8].map(|_| [0; 4].map(|_| g.byte()));
                let w: [u32; 8] = stored.map(u32::from_le_bytes);
                // SAFETY: AVX2 is present (checked above); eight u32, unaligned load.
                let rgba = unsafe {
                    crate::texture::simd::x86::rgba_of_words(
                        base,
                        _mm256_loadu_si256(w.as_ptr() as *const __m256i),
                    )
                };
                by_unit[unit] = Some(rgba);
                let mut t = [[0f32; 8]; 4];
                for j in 0..8 {
                    let e = expand(base, stored[j].map(|b| conv(b, false)));
                    for c in 0..4 {
                        t[c][j] = e[c];
                    }
                }
                texels_f[unit] = Some(t);
            }
            let live = (g.next() as u8) | 1;
            // SAFETY: AVX2 is present (checked above).
            let primary_w = unsafe { exact_words(&primary_f, live) }.expect("converted bytes");
            let want = f32_route(&units, primary_f, &texels_f);
            let got = byte_route(&units, primary_w, &by_unit);
            assert_eq!(got, want, "case {cases}: {units:?}");
            // The cascade compiled per draw: the same bytes.
            let compiled = Bytes::new(&units).expect("compiles");
            let mut inputs = vec![primary_w];
            inputs.extend(
                units
                    .iter()
                    .map(|&(_, _, unit)| by_unit[unit].expect("texel")),
            );
            // SAFETY: AVX2 is present (checked above).
            let got = unpack(unsafe { compiled.run(&inputs) });
            assert_eq!(got, want, "case {cases}, compiled: {units:?}");
        }
        assert!(multi > 1000, "{multi} cascades of several units");
    }

    /// `exact_words` takes converted bytes (and 1, and values clamped into [0, 1]) and refuses
    /// a lane of `live` with any other value; `exact_byte` agrees.
    #[test]
    fn only_converted_bytes_are_taken_as_bytes() {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return;
        }
        let mut c = [[0.0f32; 8]; 4];
        for j in 0..8 {
            c[0][j] = conv(j as u8 * 36, false);
            c[1][j] = 1.0;
            c[2][j] = -0.5;
            c[3][j] = 2.0;
        }
        // SAFETY: AVX2 is present (checked above).
        let w = unpack(unsafe { exact_words(&c, 0xFF) }.expect("bytes"));
        for j in 0..8 {
            assert_eq!(w[j], [j as u8 * 36, 255, 0, 255]);
        }
        for (v, ok) in [
            (0.9f32, false),
            (0.95, false),
            (0.5, false),
            (1.0, true),
            (0.0, true),
        ] {
            assert_eq!(exact_byte(v).is_some(), ok, "{v}");
            c[2][5] = v;
            // SAFETY: as above.
            assert_eq!(unsafe { exact_words(&c, 0xFF) }.is_some(), ok, "{v}");
            // A lane outside `live` does not matter.
            assert!(unsafe { exact_words(&c, 0xDF) }.is_some());
        }
    }
}

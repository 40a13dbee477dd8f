//! The texture environment (section 3.8.13): each enabled unit combines the colour from the
//! previous unit (the primary colour for the first) with its texel, by the unit's mode, or by
//! the programmable `GL_COMBINE` functions (table 3.24, with ARB_texture_env_crossbar sources).

use crate::common::values::{CombineFunc, CombineOperand, CombineSource, TexEnvMode};
use crate::texture::format::BaseFormat;

/// The environment of one texture unit (table 6.21).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexEnv {
    pub mode: TexEnvMode,
    pub color: [f32; 4],
    /// `GL_TEXTURE_FILTER_CONTROL`'s `GL_TEXTURE_LOD_BIAS`.
    pub lod_bias: f32,
    pub combine: Combine,
}

/// The `GL_COMBINE` settings of a unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Combine {
    pub rgb: CombineFunc,
    pub alpha: CombineFunc,
    /// Arguments 0-2, and argument 3 of NV_texture_env_combine4's `GL_COMBINE4_NV`.
    pub src_rgb: [CombineSource; 4],
    pub src_alpha: [CombineSource; 4],
    pub op_rgb: [CombineOperand; 4],
    pub op_alpha: [CombineOperand; 4],
    /// 1, 2 or 4.
    pub rgb_scale: u8,
    pub alpha_scale: u8,
}

impl Default for TexEnv {
    fn default() -> Self {
        use CombineOperand::*;
        use CombineSource::*;
        TexEnv {
            mode: TexEnvMode::Modulate,
            color: [0.0; 4],
            lod_bias: 0.0,
            combine: Combine {
                rgb: CombineFunc::Modulate,
                alpha: CombineFunc::Modulate,
                src_rgb: [Texture, Previous, Constant, Zero],
                src_alpha: [Texture, Previous, Constant, Zero],
                op_rgb: [SrcColor, SrcColor, SrcAlpha, SrcColor],
                op_alpha: [SrcAlpha, SrcAlpha, SrcAlpha, SrcAlpha],
                rgb_scale: 1,
                alpha_scale: 1,
            },
        }
    }
}

/// The arithmetic the environment needs, on one fragment (`f32`) or on eight at once
/// ([`Lanes8`]): the same operations in the same order, so both give the same values.
pub trait Lanes: Copy {
    fn splat(v: f32) -> Self;
    fn add(self, o: Self) -> Self;
    fn sub(self, o: Self) -> Self;
    fn mul(self, o: Self) -> Self;
    /// `max(0).min(1)` (NaN becomes 0).
    fn clamp01(self) -> Self;
}

impl Lanes for f32 {
    #[inline(always)]
    fn splat(v: f32) -> f32 {
        v
    }
    #[inline(always)]
    fn add(self, o: f32) -> f32 {
        self + o
    }
    #[inline(always)]
    fn sub(self, o: f32) -> f32 {
        self - o
    }
    #[inline(always)]
    fn mul(self, o: f32) -> f32 {
        self * o
    }
    #[inline(always)]
    fn clamp01(self) -> f32 {
        self.max(0.0).min(1.0)
    }
}

/// Eight fragments' values of one channel (a plain array, so eight-pixel texels need no
/// conversion).
pub type Lanes8 = [f32; 8];

#[inline(always)]
fn zip8(a: Lanes8, b: Lanes8, f: impl Fn(f32, f32) -> f32) -> Lanes8 {
    let mut r = [0f32; 8];
    for i in 0..8 {
        r[i] = f(a[i], b[i]);
    }
    r
}

impl Lanes for Lanes8 {
    #[inline(always)]
    fn splat(v: f32) -> Lanes8 {
        [v; 8]
    }
    #[inline(always)]
    fn add(self, o: Lanes8) -> Lanes8 {
        zip8(self, o, |a, b| a + b)
    }
    #[inline(always)]
    fn sub(self, o: Lanes8) -> Lanes8 {
        zip8(self, o, |a, b| a - b)
    }
    #[inline(always)]
    fn mul(self, o: Lanes8) -> Lanes8 {
        zip8(self, o, |a, b| a * b)
    }
    #[inline(always)]
    fn clamp01(self) -> Lanes8 {
        self.map(|v| v.max(0.0).min(1.0))
    }
}

/// Eight fragments' values of one channel in an AVX2 register, for the environment compiled
/// inside an AVX2 function (`span::environment8_avx2`): the same operations as [`Lanes8`] lane by lane
/// (`clamp01` by `max` then `min` with NaN to 0, as `f32::max` and `f32::min` give it).
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
pub struct Avx8(pub std::arch::x86_64::__m256);

#[cfg(target_arch = "x86_64")]
impl Lanes for Avx8 {
    // SAFETY (every method): these run only inlined into `span::environment8_avx2`, an AVX2
    // function entered after run-time detection; they touch no memory.

    #[inline(always)]
    fn splat(v: f32) -> Avx8 {
        Avx8(unsafe { std::arch::x86_64::_mm256_set1_ps(v) })
    }
    #[inline(always)]
    fn add(self, o: Avx8) -> Avx8 {
        Avx8(unsafe { std::arch::x86_64::_mm256_add_ps(self.0, o.0) })
    }
    #[inline(always)]
    fn sub(self, o: Avx8) -> Avx8 {
        Avx8(unsafe { std::arch::x86_64::_mm256_sub_ps(self.0, o.0) })
    }
    #[inline(always)]
    fn mul(self, o: Avx8) -> Avx8 {
        Avx8(unsafe { std::arch::x86_64::_mm256_mul_ps(self.0, o.0) })
    }
    #[inline(always)]
    fn clamp01(self) -> Avx8 {
        use std::arch::x86_64::*;
        // max_ps answers its second operand (0) for NaN.
        Avx8(unsafe {
            _mm256_min_ps(
                _mm256_max_ps(self.0, _mm256_setzero_ps()),
                _mm256_set1_ps(1.0),
            )
        })
    }
}

/// R, G, B, A of one fragment or of eight.
type Rgba<L> = [L; 4];

/// Inputs a combiner may read besides the previous colour.
pub struct CombineInputs<'a, L: Lanes = f32> {
    pub primary: Rgba<L>,
    /// Texel of every unit that has a complete enabled texture (`None` otherwise).
    pub texels: &'a [Option<Rgba<L>>; 8],
}

/// Applies unit `unit`'s environment: `cf` is the incoming colour, `ct` the unit's texel,
/// `base` its base internal format (tables 3.22 and 3.23).
#[inline(always)]
pub fn apply<L: Lanes>(
    env: &TexEnv,
    base: BaseFormat,
    _unit: usize,
    cf: Rgba<L>,
    ct: Rgba<L>,
    inputs: &CombineInputs<L>,
) -> Rgba<L> {
    use BaseFormat::*;
    let (has_color, has_alpha) = match base {
        Alpha => (false, true),
        Luminance | Rgb | DepthComponent | Red | Rg => (true, false),
        LuminanceAlpha | Rgba => (true, true),
        Intensity => (true, true),
    };
    let cc = env.color.map(L::splat);
    let one = L::splat(1.0);
    let rgb = |f: &dyn Fn(usize) -> L| [f(0), f(1), f(2)];
    match env.mode {
        TexEnvMode::Replace => {
            let c = if has_color {
                rgb(&|i| ct[i])
            } else {
                rgb(&|i| cf[i])
            };
            let a = if has_alpha { ct[3] } else { cf[3] };
            [c[0], c[1], c[2], a]
        }
        TexEnvMode::Modulate => {
            let c = if has_color {
                rgb(&|i| cf[i].mul(ct[i]))
            } else {
                rgb(&|i| cf[i])
            };
            let a = if has_alpha { cf[3].mul(ct[3]) } else { cf[3] };
            [c[0], c[1], c[2], a]
        }
        TexEnvMode::Decal => match base {
            Rgb => [ct[0], ct[1], ct[2], cf[3]],
            Rgba => {
                let c = rgb(&|i| cf[i].mul(one.sub(ct[3])).add(ct[i].mul(ct[3])));
                [c[0], c[1], c[2], cf[3]]
            }
            // Undefined by the specification for other formats: the colour passes unchanged.
            _ => cf,
        },
        TexEnvMode::Blend => {
            let c = if has_color {
                rgb(&|i| cf[i].mul(one.sub(ct[i])).add(cc[i].mul(ct[i])))
            } else {
                rgb(&|i| cf[i])
            };
            let a = match base {
                Intensity => cf[3].mul(one.sub(ct[3])).add(cc[3].mul(ct[3])),
                _ if has_alpha => cf[3].mul(ct[3]),
                _ => cf[3],
            };
            [c[0], c[1], c[2], a]
        }
        TexEnvMode::Add => {
            let c = if has_color {
                rgb(&|i| cf[i].add(ct[i]).clamp01())
            } else {
                rgb(&|i| cf[i])
            };
            let a = match base {
                Intensity => cf[3].add(ct[3]).clamp01(),
                _ if has_alpha => cf[3].mul(ct[3]),
                _ => cf[3],
            };
            [c[0], c[1], c[2], a]
        }
        TexEnvMode::Combine => combine(&env.combine, false, cf, ct, cc, inputs),
        TexEnvMode::Combine4 => combine(&env.combine, true, cf, ct, cc, inputs),
    }
}

#[inline(always)]
fn source<L: Lanes>(
    s: CombineSource,
    cf: Rgba<L>,
    ct: Rgba<L>,
    cc: Rgba<L>,
    inputs: &CombineInputs<L>,
) -> Rgba<L> {
    match s {
        CombineSource::Texture => ct,
        // ARB_texture_env_crossbar: a unit without a complete enabled texture reads as the
        // incoming colour (what Mesa does; the extension leaves it undefined).
        CombineSource::TextureUnit(u) => inputs.texels[u as usize].unwrap_or(cf),
        CombineSource::Constant => cc,
        CombineSource::PrimaryColor => inputs.primary,
        CombineSource::Previous => cf,
        CombineSource::Zero => [L::splat(0.0); 4],
    }
}

#[inline(always)]
fn operand_rgb<L: Lanes>(op: CombineOperand, v: Rgba<L>) -> [L; 3] {
    let one = L::splat(1.0);
    match op {
        CombineOperand::SrcColor => [v[0], v[1], v[2]],
        CombineOperand::OneMinusSrcColor => [one.sub(v[0]), one.sub(v[1]), one.sub(v[2])],
        CombineOperand::SrcAlpha => [v[3]; 3],
        CombineOperand::OneMinusSrcAlpha => [one.sub(v[3]); 3],
    }
}

#[inline(always)]
fn operand_alpha<L: Lanes>(op: CombineOperand, v: Rgba<L>) -> L {
    match op {
        CombineOperand::SrcAlpha | CombineOperand::SrcColor => v[3],
        CombineOperand::OneMinusSrcAlpha | CombineOperand::OneMinusSrcColor => {
            L::splat(1.0).sub(v[3])
        }
    }
}

/// DOT3's `4 ((a0.r - 1/2)(a1.r - 1/2) + (a0.g - 1/2)(a1.g - 1/2) + (a0.b - 1/2)(a1.b - 1/2))`
/// (table 3.24), before the scale and the clamp; the one form of it that every route uses.
#[inline(always)]
pub(crate) fn dot3<L: Lanes>(a0: [L; 3], a1: [L; 3]) -> L {
    let half = L::splat(0.5);
    L::splat(4.0).mul(
        a0[0]
            .sub(half)
            .mul(a1[0].sub(half))
            .add(a0[1].sub(half).mul(a1[1].sub(half)))
            .add(a0[2].sub(half).mul(a1[2].sub(half))),
    )
}

#[inline(always)]
fn combine_fn<L: Lanes>(f: CombineFunc, a: L, b: L, c: L) -> L {
    match f {
        CombineFunc::Replace => a,
        CombineFunc::Modulate => a.mul(b),
        CombineFunc::Add => a.add(b),
        CombineFunc::AddSigned => a.add(b).sub(L::splat(0.5)),
        CombineFunc::Interpolate => a.mul(c).add(b.mul(L::splat(1.0).sub(c))),
        CombineFunc::Subtract => a.sub(b),
        // DOT3 is handled per vector.
        CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => a,
    }
}

/// `GL_COMBINE` (table 3.24): arguments from the sources through the operands, the function,
/// then the scale, then a clamp to [0, 1]. With `four` (NV_texture_env_combine4's
/// `GL_COMBINE4_NV`), `ADD` is `a0 a1 + a2 a3` and `ADD_SIGNED` is `a0 a1 + a2 a3 - 1/2`; the
/// other functions are those of `GL_COMBINE`.
#[inline(always)]
pub fn combine<L: Lanes>(
    k: &Combine,
    four: bool,
    cf: Rgba<L>,
    ct: Rgba<L>,
    cc: Rgba<L>,
    inputs: &CombineInputs<L>,
) -> Rgba<L> {
    // (Functions rather than closures: closures are not always inlined, and the eight-lane
    // forms must be, to stay in registers.)
    #[inline(always)]
    fn arg_rgb<L: Lanes>(
        k: &Combine,
        i: usize,
        (cf, ct, cc): (Rgba<L>, Rgba<L>, Rgba<L>),
        inputs: &CombineInputs<L>,
    ) -> [L; 3] {
        operand_rgb(k.op_rgb[i], source(k.src_rgb[i], cf, ct, cc, inputs))
    }
    #[inline(always)]
    fn arg_alpha<L: Lanes>(
        k: &Combine,
        i: usize,
        (cf, ct, cc): (Rgba<L>, Rgba<L>, Rgba<L>),
        inputs: &CombineInputs<L>,
    ) -> L {
        operand_alpha(k.op_alpha[i], source(k.src_alpha[i], cf, ct, cc, inputs))
    }
    let colors = (cf, ct, cc);
    let arg_rgb = |i: usize| arg_rgb(k, i, colors, inputs);
    let arg_a = |i: usize| arg_alpha(k, i, colors, inputs);
    // Only INTERPOLATE (and COMBINE4's sums) read the third argument.
    let third = |f: CombineFunc| f == CombineFunc::Interpolate || four;
    let (a0, a1) = (arg_rgb(0), arg_rgb(1));
    let a2 = if third(k.rgb) {
        arg_rgb(2)
    } else {
        [L::splat(0.0); 3]
    };
    let rs = L::splat(k.rgb_scale as f32);
    let as_ = L::splat(k.alpha_scale as f32);
    let zero = L::splat(0.0);
    let mut out = [zero; 4];
    match k.rgb {
        CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => {
            let d = dot3(a0, a1);
            let v = d.mul(rs).clamp01();
            out = [v, v, v, zero];
            if k.rgb == CombineFunc::Dot3Rgba {
                // The dot product also replaces alpha (the alpha function is ignored); like
                // every alpha result it is then multiplied by ALPHA_SCALE (section 3.8.13: "the
                // RGB and ALPHA results ... are multiplied by RGB_SCALE and ALPHA_SCALE,
                // respectively"), which is what Mesa does too.
                out[3] = d.mul(as_).clamp01();
                return out;
            }
        }
        f @ (CombineFunc::Add | CombineFunc::AddSigned) if four => {
            let a3 = arg_rgb(3);
            let bias = L::splat(if f == CombineFunc::AddSigned {
                0.5
            } else {
                0.0
            });
            for i in 0..3 {
                out[i] = a0[i]
                    .mul(a1[i])
                    .add(a2[i].mul(a3[i]))
                    .sub(bias)
                    .mul(rs)
                    .clamp01();
            }
        }
        f => {
            for i in 0..3 {
                out[i] = combine_fn(f, a0[i], a1[i], a2[i]).mul(rs).clamp01();
            }
        }
    }
    out[3] = match k.alpha {
        f @ (CombineFunc::Add | CombineFunc::AddSigned) if four => {
            let bias = L::splat(if f == CombineFunc::AddSigned {
                0.5
            } else {
                0.0
            });
            arg_a(0)
                .mul(arg_a(1))
                .add(arg_a(2).mul(arg_a(3)))
                .sub(bias)
                .mul(as_)
                .clamp01()
        }
        f => {
            let a2 = if third(f) { arg_a(2) } else { zero };
            combine_fn(f, arg_a(0), arg_a(1), a2).mul(as_).clamp01()
        }
    };
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::values::{CombineFunc as F, CombineOperand as O, CombineSource as S};

    /// A small deterministic generator (values in [-0.25, 1.25], to reach the clamps).
    struct Gen(u64);
    impl Gen {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }
        fn value(&mut self) -> f32 {
            (self.next() >> 40) as f32 / (1u64 << 24) as f32 * 1.5 - 0.25
        }
        fn pick<T: Copy>(&mut self, v: &[T]) -> T {
            v[(self.next() % v.len() as u64) as usize]
        }
    }

    /// Eight fragments through `apply::<Lanes8>` equal eight through `apply::<f32>`, bit for
    /// bit, for every mode, base format, combine function, source, operand and scale.
    #[test]
    fn eight_lanes_equal_eight_single_fragments() {
        use BaseFormat::*;
        let mut g = Gen(0x9E37_79B9_7F4A_7C15);
        let modes = [
            TexEnvMode::Replace,
            TexEnvMode::Modulate,
            TexEnvMode::Decal,
            TexEnvMode::Blend,
            TexEnvMode::Add,
            TexEnvMode::Combine,
            TexEnvMode::Combine4,
        ];
        let bases = [Alpha, Luminance, LuminanceAlpha, Intensity, Rgb, Rgba];
        let funcs = [
            F::Replace,
            F::Modulate,
            F::Add,
            F::AddSigned,
            F::Interpolate,
            F::Subtract,
            F::Dot3Rgb,
            F::Dot3Rgba,
        ];
        let sources = [
            S::Texture,
            S::TextureUnit(0),
            S::TextureUnit(1),
            S::TextureUnit(5),
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
        for case in 0..4000 {
            let mut env = TexEnv {
                mode: modes[case % modes.len()],
                color: [g.value(), g.value(), g.value(), g.value()],
                ..TexEnv::default()
            };
            env.combine.rgb = g.pick(&funcs);
            env.combine.alpha = g.pick(&funcs[..6]);
            for i in 0..4 {
                env.combine.src_rgb[i] = g.pick(&sources);
                env.combine.src_alpha[i] = g.pick(&sources);
                env.combine.op_rgb[i] = g.pick(&operands);
                env.combine.op_alpha[i] = g.pick(&operands);
            }
            env.combine.rgb_scale = g.pick(&[1, 2, 4]);
            env.combine.alpha_scale = g.pick(&[1, 2, 4]);
            let base = g.pick(&bases);
            let lane = |g: &mut Gen| [0; 4].map(|_| [0; 8].map(|_| g.value()));
            let (cf, ct, primary, t0, t1) = (
                lane(&mut g),
                lane(&mut g),
                lane(&mut g),
                lane(&mut g),
                lane(&mut g),
            );
            let mut texels8: [Option<[Lanes8; 4]>; 8] = [None; 8];
            texels8[0] = Some(t0);
            texels8[1] = Some(t1);
            let inputs8 = CombineInputs {
                primary,
                texels: &texels8,
            };
            let out8 = apply(&env, base, 1, cf, ct, &inputs8);
            // The AVX2 register form (`Avx8`), where the processor has it.
            #[cfg(target_arch = "x86_64")]
            let out_avx = std::arch::is_x86_feature_detected!("avx2")
                .then(|| apply_avx8(&env, base, [cf, ct, primary, t0, t1]));
            for j in 0..8 {
                let at = |v: [Lanes8; 4]| v.map(|c| c[j]);
                let mut texels: [Option<[f32; 4]>; 8] = [None; 8];
                texels[0] = Some(at(t0));
                texels[1] = Some(at(t1));
                let inputs = CombineInputs {
                    primary: at(primary),
                    texels: &texels,
                };
                let out = apply(&env, base, 1, at(cf), at(ct), &inputs);
                // Bits up to the sign of zero: `min`/`max` may return either zero for a
                // signed-zero tie, and which one depends on code generation (the colour a zero
                // becomes does not).
                let bits = |v: [f32; 4]| v.map(|c| (c + 0.0).to_bits());
                assert_eq!(
                    bits(out),
                    bits(at(out8)),
                    "case {case}, lane {j}: {env:?} {base:?}"
                );
                #[cfg(target_arch = "x86_64")]
                if let Some(avx) = out_avx {
                    assert_eq!(
                        bits(out),
                        bits(at(avx)),
                        "AVX2, case {case}, lane {j}: {env:?} {base:?}"
                    );
                }
            }
        }
    }

    /// `apply::<Avx8>` on unit 1 with texels of units 0 and 1, as `span::environment8_avx2`
    /// runs it. The caller checked that the processor has AVX2.
    #[cfg(target_arch = "x86_64")]
    fn apply_avx8(
        env: &TexEnv,
        base: BaseFormat,
        [cf, ct, primary, t0, t1]: [[Lanes8; 4]; 5],
    ) -> [Lanes8; 4] {
        use std::arch::x86_64::*;
        // SAFETY: AVX2 is present (checked by the caller); each array holds eight f32
        // (unaligned loads and stores).
        unsafe {
            let load = |v: [Lanes8; 4]| v.map(|c| Avx8(_mm256_loadu_ps(c.as_ptr())));
            let mut texels: [Option<[Avx8; 4]>; 8] = [None; 8];
            texels[0] = Some(load(t0));
            texels[1] = Some(load(t1));
            let inputs = CombineInputs {
                primary: load(primary),
                texels: &texels,
            };
            let out = apply(env, base, 1, load(cf), load(ct), &inputs);
            out.map(|c| {
                let mut a = [0f32; 8];
                _mm256_storeu_ps(a.as_mut_ptr(), c.0);
                a
            })
        }
    }
}

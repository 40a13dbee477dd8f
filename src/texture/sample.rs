//! The sampler: pure functions of a frozen texture snapshot (section 3.8.8 - 3.8.9 and 3.8.14
//! of OpenGL 1.5, EXT_texture_filter_anisotropic). No GL state is read here.
//!
//! Texel selection uses the integer-coordinate form of the wrap rules (as later GL
//! specifications state them; equivalent to OpenGL 1.5 for power-of-two sizes and defined for
//! any size): `u = s * w_t`; NEAREST takes `i = wrap(floor(u))`; LINEAR takes
//! `i0 = wrap(floor(u - 1/2))`, `i1 = wrap(floor(u - 1/2) + 1)` with weight
//! `alpha = frac(u - 1/2)`. `GL_CLAMP` first clamps `s` to [0, 1]. An index of -1 or `w_t`
//! selects the border texel (border 1) or the border colour (border 0).
//!
//! Coordinates are scaled in `f64`, so `GL_REPEAT` is exact for |s| x size up to 2^53 (any
//! `f32` product of a coordinate and a size up to 4096 is exact). Larger products saturate to
//! the largest 64-bit integer before wrapping; infinite coordinates act as the largest finite
//! value and NaN as 0. No input panics.

use std::sync::Arc;

use super::fixed;
use super::format::{BaseFormat, InternalFormat};
use super::image::{TexImage, Texels};
use super::object::{SamplerParams, MAX_TEXTURE_LOD_BIAS};
use crate::common::values::{
    DepthTextureMode, MagFilter, MinFilter, SwizzleSource, TextureTarget, WrapMode,
};

/// The frozen contents of a bound, complete texture.
#[derive(Debug)]
pub struct BoundInner {
    pub target: TextureTarget,
    pub params: SamplerParams,
    pub format: InternalFormat,
    pub base: BaseFormat,
    /// Inner size of the base level (w_b, h_b, d_b).
    pub base_size: [f32; 3],
    /// `levels[face][level - base_level]`, from the base level to the last level sampled.
    pub levels: Vec<Vec<TexImage>>,
    /// Float texels (ARB_texture_float) are filtered unclamped, then clamped to [0, 1] as
    /// they enter the texture environment (issue 7 of the extension: "the filtered texel is
    /// now clamped before it is used for texture environment blending").
    pub clamp_float: bool,
}

/// A cheap-to-clone, immutable snapshot of a complete texture, as a draw sees it. Later
/// changes to the texture object copy on write and never reach a snapshot.
#[derive(Clone, Debug)]
pub struct BoundTexture {
    inner: Arc<BoundInner>,
}

/// The texel index mirrored once about the lower edge: ..., 1, 0 | 0, 1, ...
#[inline]
fn mirror_once(i: i64) -> i64 {
    if i < 0 {
        -1 - i.max(i64::MIN + 1)
    } else {
        i
    }
}

/// The levels one λ selects (see [`BoundTexture::level_plan`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LevelPlan {
    /// One level, filtered LINEAR (`linear`) or NEAREST.
    One { level: usize, linear: bool },
    /// Two adjacent levels (the same one at the end of the chain), each filtered, then mixed
    /// as `first + (second - first) * weight`.
    Two {
        levels: [usize; 2],
        linear: bool,
        weight: f32,
    },
}

/// Entries of [`QUICK_LOG2`]: one per value of the top 8 bits of an f32 mantissa.
pub const QUICK_LOG2_CELLS: usize = 256;

/// `128 log2` of the mantissa `x = 1 + f` (f in [0, 1), f32 bits) by chords over 256 cells:
/// per cell i (x in [1 + i/256, 1 + (i + 1)/256)) the value `T = 128 log2(1 + i/256)` and the
/// rise `S` to the next cell's value, each rounded to f32 ([`quick_log2_128`]). Computed at
/// compile time (the logarithm by its series `ln x = 2 Σ u^(2j+1)/(2j+1)`, u = (x - 1)/(x + 1)
/// <= 1/3, forty terms: far below an f32 unit).
pub static QUICK_LOG2: [[f32; 2]; QUICK_LOG2_CELLS] = quick_log2_table();

/// `128 log2 x` in f64 for x in [1, 2] (the table's entries).
const fn log2_128_const(x: f64) -> f64 {
    let u = (x - 1.0) / (x + 1.0);
    let u2 = u * u;
    let mut sum = 0.0;
    let mut power = u;
    let mut j = 0;
    while j < 40 {
        sum += power / (2 * j + 1) as f64;
        power *= u2;
        j += 1;
    }
    128.0 * 2.0 * sum / std::f64::consts::LN_2
}

const fn quick_log2_table() -> [[f32; 2]; QUICK_LOG2_CELLS] {
    let mut out = [[0f32; 2]; QUICK_LOG2_CELLS];
    let mut i = 0;
    while i < QUICK_LOG2_CELLS {
        let n = QUICK_LOG2_CELLS as f64;
        let a = log2_128_const(1.0 + i as f64 / n);
        let b = log2_128_const(1.0 + (i + 1) as f64 / n);
        out[i] = [a as f32, (b - a) as f32];
        i += 1;
    }
    out
}

/// `128 log2 x` of the mantissa x in [1, 2) of the f32 bits `bits` (exponent ignored), by
/// the chord of its cell ([`QUICK_LOG2`]): `T + φ S` with φ the 15 low mantissa bits as a
/// fraction of the cell (exact), in f32. Error (unit test `quick_log2_is_within_its_bound`,
/// exhaustive over the mantissas): the chord of 128 log2 lies below it by at most
/// `h²/8 · 128/ln 2` = 3.53e-4 (h = 1/256, the curvature largest at x = 1); the roundings of
/// T and of the sum add at most 3.8e-6 each (half a unit of 64..128), those of S and the
/// product 1e-7: 3.61e-4 in all.
#[inline(always)]
pub fn quick_log2_128(bits: u32) -> f32 {
    let [t, s] = QUICK_LOG2[(bits >> 15) as usize & (QUICK_LOG2_CELLS - 1)];
    let phi = (bits & 0x7FFF) as i32 as f32 * (1.0 / 32768.0);
    t + phi * s
}

/// The terms of [`LodSelect::quick_lambda256`] that depend only on the sampler's parameters
/// (so that the per-quad work is integer and f32 arithmetic on the ρ² bits).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuickTerms {
    /// floor(256 bias) and 256 bias minus it (in [0, 1), exact: 256 bias is an f32).
    pub bias_int: i32,
    pub bias_frac: f32,
    /// The `floor(256 λ)` values g whose whole step [g, g + 1] lies inside
    /// [256 min_lod, 256 max_lod] (a NaN bound clamps nothing: [`LodSelect::lambda_from_rho`]);
    /// `lo > hi` when none does.
    pub lo: i32,
    pub hi: i32,
}

impl QuickTerms {
    /// The terms for a (clamped, finite) `bias` and the LOD clamp.
    pub fn new(bias: f32, min_lod: f32, max_lod: f32) -> QuickTerms {
        const BIG: f64 = (1 << 30) as f64;
        let b = bias as f64 * 256.0;
        let lo = if min_lod.is_nan() {
            -BIG
        } else {
            (min_lod as f64 * 256.0).ceil().clamp(-BIG, BIG)
        };
        let hi = if max_lod.is_nan() {
            BIG
        } else {
            ((max_lod as f64 * 256.0).floor() - 1.0).clamp(-BIG, BIG)
        };
        QuickTerms {
            bias_int: b.floor() as i32,
            bias_frac: (b - b.floor()) as f32,
            lo: lo as i32,
            hi: hi as i32,
        }
    }
}

/// How near a multiple of 1/256 a quickly computed λ may lie and still decide the level
/// plan ([`LodSelect::quick_lambda256`]): 2^-15.
pub const QUICK_LOD_MARGIN: f64 = 1.0 / 32768.0;

/// Wraps an integer texel coordinate (section 3.8.8; -1 and `size` mean "border").
#[inline]
pub fn wrap_index(i: i64, size: i64, mode: WrapMode, linear: bool) -> i64 {
    let size = size.max(1);
    match mode {
        WrapMode::Repeat => {
            // The common cases without a 64-bit division.
            if (0..size).contains(&i) {
                i
            } else if (size & (size - 1)) == 0 {
                i & (size - 1)
            } else {
                i.rem_euclid(size)
            }
        }
        WrapMode::ClampToEdge => i.clamp(0, size - 1),
        WrapMode::Clamp if !linear => i.clamp(0, size - 1),
        WrapMode::Clamp | WrapMode::ClampToBorder => i.clamp(-1, size),
        WrapMode::MirrorClamp if !linear => mirror_once(i).clamp(0, size - 1),
        WrapMode::MirrorClampToEdge => mirror_once(i).clamp(0, size - 1),
        WrapMode::MirrorClamp | WrapMode::MirrorClampToBorder => mirror_once(i).clamp(0, size),
        WrapMode::MirroredRepeat => {
            let m = if (0..2 * size).contains(&i) {
                i
            } else {
                i.rem_euclid(2 * size)
            };
            if m < size {
                m
            } else {
                2 * size - 1 - m
            }
        }
    }
}

/// What λ and the level plan depend on besides the derivatives (see
/// [`BoundTexture::lod_select`]): the same computations as the per-fragment sampler.
#[derive(Clone, Copy, Debug)]
pub struct LodSelect {
    /// The texture's and the unit's LOD bias, summed (NaN as 0) and clamped.
    bias: f32,
    min_lod: f32,
    max_lod: f32,
    switch_over: f32,
    mag_linear: bool,
    min_filter: MinFilter,
    last_level: usize,
    size: [f32; 3],
    target: TextureTarget,
    /// ρ² below which λ is surely at most the switch-over point (magnification) without
    /// computing it ([`LodSelect::surely_magnified`]); -1 when `min_lod` lies above it.
    magnified_below: f32,
    /// [`LodSelect::quick_lambda256`]'s terms of the bias and the LOD clamp.
    quick: QuickTerms,
}

impl LodSelect {
    /// The threshold of [`LodSelect::surely_magnified`]: λ = clamp(log2 ρ + bias, min_lod,
    /// max_lod) is at most c when log2 ρ + bias <= c and min_lod <= c (max_lod only lowers
    /// it).
    fn magnified_below(switch_over: f32, bias: f32, min_lod: f32) -> f32 {
        if min_lod <= switch_over {
            ((2.0 * (switch_over - bias)) as f64).exp2() as f32 * 0.999
        } else {
            -1.0
        }
    }

    /// Whether the quad with these derivatives is surely magnified: λ (from the same ρ² as
    /// [`LodSelect::isotropic_lambda`]) at most the switch-over point c, so that the level
    /// plan is the magnification filter on level 0, without the square root and logarithm.
    /// The threshold 2^(2 (c - bias)) is lowered by 0.1 %, far more than the rounding of
    /// sqrt, log2 and the bias sum can move λ (|bias| is at most `MAX_TEXTURE_LOD_BIAS`);
    /// values near it take the full computation, so the plan is always the one λ gives.
    #[inline(always)]
    pub fn surely_magnified(&self, d_dx: [f32; 3], d_dy: [f32; 3]) -> bool {
        let sq = |v: [f32; 3]| v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        let (ax, ay) = (sq(self.scaled(d_dx)), sq(self.scaled(d_dy)));
        ax.max(ay) <= self.magnified_below
    }

    /// What the eight-lane block kernel needs to test [`LodSelect::surely_magnified`] itself
    /// (`texture::simd::x86::block_words8`): the threshold and the base level's width and height, for 2D
    /// textures (`None` for other targets).
    #[inline(always)]
    pub fn magnified_test(&self) -> Option<(f32, [f32; 2])> {
        (self.target == TextureTarget::T2D)
            .then_some((self.magnified_below, [self.size[0], self.size[1]]))
    }

    /// The level plan of a quad whose derivatives of a 2D texture give squared scaled lengths
    /// `ax` (x) and `ay` (y): what [`LodSelect::surely_magnified`] followed by
    /// [`LodSelect::plan`] of [`LodSelect::isotropic_lambda`] give for the same derivatives
    /// (the same arithmetic after the squares).
    #[inline(always)]
    pub fn plan_for_rho2(&self, ax: f32, ay: f32) -> LevelPlan {
        let m = ax.max(ay);
        if m <= self.magnified_below {
            self.magnification()
        } else {
            self.plan(self.lambda_from_rho(m.sqrt()))
        }
    }

    /// Whether magnification filters linearly.
    #[inline(always)]
    pub fn mag_linear(&self) -> bool {
        self.mag_linear
    }

    /// The level plan of magnification (what [`LodSelect::plan`] gives for λ <= c).
    #[inline(always)]
    pub fn magnification(&self) -> LevelPlan {
        LevelPlan::One {
            level: 0,
            linear: self.mag_linear,
        }
    }

    /// The derivatives of (s, t, r) scaled to texels of the base level (u, v, w), with unused
    /// dimensions zero.
    #[inline(always)]
    fn scaled(&self, d: [f32; 3]) -> [f32; 3] {
        let [w, h, dd] = self.size;
        match self.target {
            TextureTarget::T1D => [d[0] * w, 0.0, 0.0],
            TextureTarget::T3D => [d[0] * w, d[1] * h, d[2] * dd],
            _ => [d[0] * w, d[1] * h, 0.0],
        }
    }

    /// [`BoundTexture::lambda_from_rho`].
    #[inline]
    pub fn lambda_from_rho(&self, rho: f32) -> f32 {
        let base = if rho.is_nan() {
            f32::INFINITY
        } else {
            rho.log2()
        };
        let lambda = base + self.bias;
        let lambda = if lambda > self.max_lod {
            self.max_lod
        } else {
            lambda
        };
        if lambda < self.min_lod {
            self.min_lod
        } else {
            lambda
        }
    }

    /// `floor(256 λ)` for the squared scale factor `m` = ρ² (λ = log2 ρ plus the bias,
    /// clamped to [min_lod, max_lod]) without `log2f`, when it surely equals `floor(256 λ)`
    /// of the λ that [`LodSelect::lambda_from_rho`] gives for `m.sqrt()`; `None` otherwise
    /// (`m` not a positive normal number, the estimate within [`QUICK_LOD_MARGIN`] of a
    /// multiple of 1/256, or its step not wholly inside [min_lod, max_lod]). Every step of
    /// the level plan (the switch-over point 0 or 1/2, the halves of `*_MIPMAP_NEAREST`, the
    /// levels of `*_MIPMAP_LINEAR`, the last level) and of its 8-bit weight
    /// ([`fixed::level_weight`]) lies on a multiple of 1/256, so `floor(256 λ)` decides the
    /// plan ([`LodSelect::plan_of_lambda256`]) whenever λ is not near one.
    ///
    /// The estimate, in f32 without a division: 256 λ = 128 log2 m + 256 bias = 128 e +
    /// 128 log2 x + floor(256 bias) + frac(256 bias) with m = x 2^e, x in [1, 2) from the
    /// bits; v = [`quick_log2_128`]`(x) + frac(256 bias)` (< 129), g = floor(v) + 128 e +
    /// floor(256 bias) (integers), and v's fraction is the estimate's.
    ///
    /// Bound: v is within 3.61e-4 (the chords, [`quick_log2_128`]) + 3.8e-6 (the sum's
    /// rounding, half a unit below 128; 7.6e-6 when v reaches 128) < 3.7e-4 of the exact `256 (½ log2 m + bias) - 128 e - floor(256 bias)`,
    /// that is within 1.5e-6 in λ. The sampler's λ differs from the exact ½ log2 m + bias by
    /// the rounding of sqrt (8.6e-8), of log2f (at most one unit in the last place of
    /// |log2 ρ| < 64: 3.8e-6; glibc documents 0.75) and of the sum with the bias (half a
    /// unit of |λ| < 128: 3.8e-6): within 1.2e-5. The two lie within 1.4e-5 < 2^-15 (the
    /// margin) of each other, so when the estimate's fraction is farther than the margin
    /// from 0 and 1, the sampler's 256 λ lies strictly inside (g, g + 1); when that step
    /// lies inside [256 min_lod, 256 max_lod] ([`QuickTerms`]) the clamp leaves the
    /// sampler's λ as it is, so its `floor(256 λ)` is g and λ is not a multiple of 1/256.
    #[inline(always)]
    pub fn quick_lambda256(&self, m: f32) -> Option<i32> {
        let bits = m.to_bits();
        if !(0x0080_0000..0x7F80_0000).contains(&bits) {
            return None;
        }
        let q = &self.quick;
        let v = quick_log2_128(bits) + q.bias_frac;
        let f = v.floor();
        let frac = v - f;
        let margin = (QUICK_LOD_MARGIN * 256.0) as f32;
        let g = f as i32 + (((bits >> 23) as i32 - 127) << 7) + q.bias_int;
        if frac > margin && frac < 1.0 - margin && (q.lo..=q.hi).contains(&g) {
            Some(g)
        } else {
            None
        }
    }

    /// The level plan as the block kernels use it, `((first, second, linear), weight)` with
    /// the 8-bit weight of the second level ([`fixed::level_weight`]), for `g` =
    /// `floor(256 λ)` of a λ that is not a multiple of 1/256 ([`LodSelect::quick_lambda256`]):
    /// what [`LodSelect::plan`] gives for that λ.
    #[inline(always)]
    pub fn plan_of_lambda256(&self, g: i32) -> ((usize, usize, bool), i32) {
        // λ <= c (c = 0 or 1/2, on the grid): magnification.
        if g < (self.switch_over * 256.0) as i32 {
            return ((0, 0, self.mag_linear), 0);
        }
        let linear = matches!(
            self.min_filter,
            MinFilter::Linear | MinFilter::LinearMipmapNearest | MinFilter::LinearMipmapLinear
        );
        let q = self.last_level;
        match self.min_filter {
            MinFilter::Nearest | MinFilter::Linear => ((0, 0, linear), 0),
            MinFilter::NearestMipmapNearest | MinFilter::LinearMipmapNearest => {
                // 0 for λ <= 1/2, else ceil(λ + 1/2) - 1 = floor(λ + 1/2) (not a half).
                let d = if g < 128 {
                    0
                } else {
                    (((g + 128) >> 8) as usize).min(q)
                };
                ((d, d, linear), 0)
            }
            MinFilter::NearestMipmapLinear | MinFilter::LinearMipmapLinear => {
                if g >= (q as i32) << 8 {
                    ((q, q, linear), 0)
                } else {
                    // c <= λ < q: the level floor(λ), the fraction's 8 bits.
                    let d = (g >> 8) as usize;
                    ((d, d + 1, linear), g & 255)
                }
            }
        }
    }

    /// [`LodSelect::plan`] of [`LodSelect::isotropic_lambda`] for these derivatives (after
    /// [`LodSelect::surely_magnified`]'s test) with the weight of a second level as the
    /// eight-lane filters use it, quantised to 1/256 (`fixed::level_weight` gives the same
    /// byte for both): from `floor(256 λ)` ([`LodSelect::quick_lambda256`]) where that
    /// decides the plan, else from the sampler's λ.
    #[inline(always)]
    pub fn quantised_plan(&self, d_dx: [f32; 3], d_dy: [f32; 3]) -> LevelPlan {
        let sq = |v: [f32; 3]| v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        let m = sq(self.scaled(d_dx)).max(sq(self.scaled(d_dy)));
        if m <= self.magnified_below {
            return self.magnification();
        }
        match self.quick_lambda256(m) {
            Some(g) => match self.plan_of_lambda256(g) {
                ((level, second, linear), _) if second == level => LevelPlan::One { level, linear },
                ((a, b, linear), w) => LevelPlan::Two {
                    levels: [a, b],
                    linear,
                    weight: w as f32 * (1.0 / 256.0),
                },
            },
            None => self.plan(self.lambda_from_rho(m.sqrt())),
        }
    }

    /// [`LodSelect::quick_lambda256`]'s terms of the bias and the LOD clamp.
    #[inline(always)]
    pub fn quick_terms(&self) -> &QuickTerms {
        &self.quick
    }

    /// [`BoundTexture::isotropic_lambda`].
    #[inline]
    pub fn isotropic_lambda(&self, d_dx: [f32; 3], d_dy: [f32; 3]) -> f32 {
        // max(sqrt a, sqrt b) is sqrt(max(a, b)) exactly (sqrt is correctly rounded, hence
        // monotonic; `max` ignores a NaN either way): one square root.
        let sq = |v: [f32; 3]| v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        let (ax, ay) = (sq(self.scaled(d_dx)), sq(self.scaled(d_dy)));
        self.lambda_from_rho(ax.max(ay).sqrt())
    }

    /// [`BoundTexture::level_plan`].
    #[inline]
    pub fn plan(&self, lambda: f32) -> LevelPlan {
        let q = self.last_level;
        let lambda = if lambda.is_nan() { 0.0 } else { lambda };
        if lambda <= self.switch_over {
            return LevelPlan::One {
                level: 0,
                linear: self.mag_linear,
            };
        }
        let linear = matches!(
            self.min_filter,
            MinFilter::Linear | MinFilter::LinearMipmapNearest | MinFilter::LinearMipmapLinear
        );
        match self.min_filter {
            MinFilter::Nearest | MinFilter::Linear => LevelPlan::One { level: 0, linear },
            MinFilter::NearestMipmapNearest | MinFilter::LinearMipmapNearest => {
                let d = if lambda <= 0.5 {
                    0
                } else {
                    ((lambda + 0.5).ceil() - 1.0).min(q as f32) as usize
                };
                LevelPlan::One {
                    level: d.min(q),
                    linear,
                }
            }
            MinFilter::NearestMipmapLinear | MinFilter::LinearMipmapLinear => {
                if lambda >= q as f32 {
                    LevelPlan::One { level: q, linear }
                } else {
                    // Here 0 < λ < q (λ > switch_over >= 0), so truncation is the floor
                    // and λ - floor(λ) is exact in f32.
                    let fl = lambda as usize;
                    let w = lambda - fl as f32;
                    let d1 = fl.min(q);
                    let d2 = (d1 + 1).min(q);
                    LevelPlan::Two {
                        levels: [d1, d2],
                        linear,
                        weight: w,
                    }
                }
            }
        }
    }
}

/// `floor(x)` as an integer and the fraction `x - floor(x)` in [0, 1): saturating, NaN as
/// (0, 0). Avoids the libm call `f64::floor` becomes without SSE4.1.
#[inline(always)]
pub(super) fn floor_frac(x: f64) -> (i64, f32) {
    if x.is_nan() {
        return (0, 0.0);
    }
    if x.abs() >= 4_503_599_627_370_496.0 {
        // |x| >= 2^52: already an integer.
        return (x as i64, 0.0);
    }
    let t = x as i64;
    let f = if (t as f64) > x { t - 1 } else { t };
    (f, (x - f as f64) as f32)
}

/// Cube map face selection (table 3.19 of OpenGL 1.5): the face index (+X, -X, +Y, -Y, +Z,
/// -Z), and the face coordinates (s, t) in [0, 1]. Ties go to X, then Y. A zero (or NaN)
/// direction gives face +Z... (defined, not meaningful).
pub fn cube_face(dir: [f32; 3]) -> (usize, [f32; 2]) {
    let [x, y, z] = dir;
    let (ax, ay, az) = (x.abs(), y.abs(), z.abs());
    let (face, sc, tc, ma) = if ax >= ay && ax >= az {
        if x >= 0.0 {
            (0, -z, -y, ax)
        } else {
            (1, z, -y, ax)
        }
    } else if ay >= az {
        if y >= 0.0 {
            (2, x, z, ay)
        } else {
            (3, x, -z, ay)
        }
    } else if z >= 0.0 {
        (4, x, -y, az)
    } else {
        (5, -x, -y, az)
    };
    if ma > 0.0 {
        (face, [(sc / ma + 1.0) * 0.5, (tc / ma + 1.0) * 0.5])
    } else {
        (face, [0.5, 0.5])
    }
}

/// The face coordinates of direction `dir` projected on `face` (for derivatives).
fn face_coords(face: usize, dir: [f32; 3]) -> [f32; 2] {
    let [x, y, z] = dir;
    let (sc, tc, ma) = match face {
        0 => (-z, -y, x),
        1 => (z, -y, -x),
        2 => (x, z, y),
        3 => (x, -z, -y),
        4 => (x, -y, z),
        _ => (-x, -y, -z),
    };
    let ma = ma.abs();
    if ma > 0.0 {
        [(sc / ma + 1.0) * 0.5, (tc / ma + 1.0) * 0.5]
    } else {
        [0.5, 0.5]
    }
}

/// The derivatives of a cube map sample in the coordinates of its face: `coords + d_dx` and
/// `coords + d_dy` (direction derivatives) projected on `face` (chosen for `coords`, whose
/// face coordinates are `st`), minus `st`.
#[inline]
pub fn cube_face_derivatives(
    face: usize,
    st: [f32; 2],
    coords: [f32; 3],
    d_dx: [f32; 3],
    d_dy: [f32; 3],
) -> ([f32; 3], [f32; 3]) {
    let add = |d: [f32; 3]| [coords[0] + d[0], coords[1] + d[1], coords[2] + d[2]];
    let fx = face_coords(face, add(d_dx));
    let fy = face_coords(face, add(d_dy));
    (
        [fx[0] - st[0], fx[1] - st[1], 0.0],
        [fy[0] - st[0], fy[1] - st[1], 0.0],
    )
}

#[inline]
pub(super) fn lerp4(a: [f32; 4], b: [f32; 4], w: f32) -> [f32; 4] {
    [
        a[0] + (b[0] - a[0]) * w,
        a[1] + (b[1] - a[1]) * w,
        a[2] + (b[2] - a[2]) * w,
        a[3] + (b[3] - a[3]) * w,
    ]
}

fn length(v: [f32; 3]) -> f32 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

impl BoundTexture {
    pub(crate) fn from_inner(inner: Arc<BoundInner>) -> BoundTexture {
        BoundTexture { inner }
    }

    /// Whether sampling reads the r coordinate: 3D textures, cube maps (the direction) and
    /// depth textures (compared against r).
    pub fn reads_r(&self) -> bool {
        !matches!(self.inner.target, TextureTarget::T1D | TextureTarget::T2D)
            || self.inner.base == BaseFormat::DepthComponent
    }

    /// The target sampled (the unit's highest-precedence enabled target).
    pub fn target(&self) -> TextureTarget {
        self.inner.target
    }

    /// The sampler parameters frozen with the snapshot.
    pub fn params(&self) -> &SamplerParams {
        &self.inner.params
    }

    /// The internal format of the base level.
    pub fn internal_format(&self) -> InternalFormat {
        self.inner.format
    }

    /// The base format the texture environment must use (table 3.22/3.23 of OpenGL 1.5): the
    /// base level's, except that depth textures act as `GL_DEPTH_TEXTURE_MODE` says
    /// (LUMINANCE, INTENSITY or ALPHA).
    pub fn base_format(&self) -> BaseFormat {
        match self.inner.base {
            BaseFormat::DepthComponent => match self.inner.params.depth_mode {
                DepthTextureMode::Luminance => BaseFormat::Luminance,
                DepthTextureMode::Intensity => BaseFormat::Intensity,
                DepthTextureMode::Alpha => BaseFormat::Alpha,
            },
            b => b,
        }
    }

    /// Number of mipmap levels sampled (base level to the last).
    pub fn level_count(&self) -> usize {
        self.inner.levels.first().map_or(0, |l| l.len())
    }

    /// Whether the r coordinate is used: 3D textures, cube maps and depth comparison.
    pub fn uses_r(&self) -> bool {
        matches!(
            self.inner.target,
            TextureTarget::T3D | TextureTarget::CubeMap
        ) || self.inner.params.compare
    }

    /// The switch-over point `c` between magnification and minification (section 3.8.9):
    /// 0.5 when the magnification filter is LINEAR and the minification filter is
    /// NEAREST_MIPMAP_NEAREST or NEAREST_MIPMAP_LINEAR, else 0.
    pub fn switch_over(&self) -> f32 {
        let p = &self.inner.params;
        if p.mag_filter == MagFilter::Linear
            && matches!(
                p.min_filter,
                MinFilter::NearestMipmapNearest | MinFilter::NearestMipmapLinear
            )
        {
            0.5
        } else {
            0.0
        }
    }

    /// The derivatives of (s, t, r) scaled to texels of the base level (u, v, w), with unused
    /// dimensions zero.
    fn scaled(&self, d: [f32; 3]) -> [f32; 3] {
        let [w, h, dd] = self.inner.base_size;
        match self.inner.target {
            TextureTarget::T1D => [d[0] * w, 0.0, 0.0],
            TextureTarget::T3D => [d[0] * w, d[1] * h, d[2] * dd],
            _ => [d[0] * w, d[1] * h, 0.0],
        }
    }

    /// λ from a scale factor ρ: `log2 ρ` plus the texture's and the unit's LOD bias (their
    /// sum clamped to ±`GL_MAX_TEXTURE_LOD_BIAS`), clamped to [MIN_LOD, MAX_LOD]. ρ = 0 gives
    /// MIN_LOD (magnification); an infinite or NaN ρ gives MAX_LOD (the coarsest level).
    pub fn lambda_from_rho(&self, rho: f32, unit_lod_bias: f32) -> f32 {
        self.lod_select(unit_lod_bias).lambda_from_rho(rho)
    }

    /// The parameters of λ and level selection for a unit with LOD bias `unit_lod_bias`,
    /// gathered once (per span on the fast paths) instead of per fragment.
    pub fn lod_select(&self, unit_lod_bias: f32) -> LodSelect {
        let p = &self.inner.params;
        let mut bias = p.lod_bias + unit_lod_bias;
        if bias.is_nan() {
            bias = 0.0;
        }
        let [w, h, d] = self.inner.base_size;
        let bias = bias.clamp(-MAX_TEXTURE_LOD_BIAS, MAX_TEXTURE_LOD_BIAS);
        let switch_over = self.switch_over();
        let magnified_below = LodSelect::magnified_below(switch_over, bias, p.min_lod);
        LodSelect {
            bias,
            min_lod: p.min_lod,
            max_lod: p.max_lod,
            switch_over,
            mag_linear: p.mag_filter == MagFilter::Linear,
            min_filter: p.min_filter,
            last_level: self.level_count().saturating_sub(1),
            size: [w, h, d],
            target: self.inner.target,
            magnified_below,
            quick: QuickTerms::new(bias, p.min_lod, p.max_lod),
        }
    }

    /// λ of equations 3.17-3.19 (OpenGL 1.5): ρ is the larger of the lengths of
    /// (du/dx, dv/dx, dw/dx) and (du/dy, dv/dy, dw/dy), where u, v, w are s, t, r scaled by
    /// the base level's width, height and depth (only the texture's dimensions count); then
    /// [`BoundTexture::lambda_from_rho`]. For cube maps pass face-space derivatives, or use
    /// [`BoundTexture::sample_grad`], which computes them.
    pub fn scale_factor_lambda(&self, d_dx: [f32; 3], d_dy: [f32; 3], unit_lod_bias: f32) -> f32 {
        let rho = length(self.scaled(d_dx)).max(length(self.scaled(d_dy)));
        self.lambda_from_rho(rho, unit_lod_bias)
    }

    /// λ as [`BoundTexture::sample_grad`] computes it without anisotropy, from derivatives in
    /// the sampled face's coordinates: `log2` of the larger length of the derivatives scaled
    /// to texels, plus biases, clamped ([`BoundTexture::lambda_from_rho`]).
    #[inline]
    pub fn isotropic_lambda(&self, d_dx: [f32; 3], d_dy: [f32; 3], unit_lod_bias: f32) -> f32 {
        self.lod_select(unit_lod_bias).isotropic_lambda(d_dx, d_dy)
    }

    /// Samples at `coords` (s, t, r already divided by q; for cube maps the direction) with a
    /// given λ: magnification when λ <= c ([`BoundTexture::switch_over`]), otherwise the
    /// minification filter's level selection (section 3.8.8).
    pub fn sample(&self, coords: [f32; 3], lambda: f32) -> [f32; 4] {
        if self.inner.target == TextureTarget::CubeMap {
            let (face, st) = cube_face(coords);
            self.sample_face(face, [st[0], st[1], coords[2]], lambda)
        } else {
            self.sample_face(0, coords, lambda)
        }
    }

    /// The main entry point of the fragment stage: the texture colour at `coords` (s, t, r
    /// divided by q, or the cube map direction) given the screen-space derivatives of the same
    /// coordinates and the unit's LOD bias (`GL_TEXTURE_FILTER_CONTROL`).
    ///
    /// Anisotropic filtering (EXT_texture_filter_anisotropic, which leaves the filter to the
    /// implementation): 2D textures with a `*_MIPMAP_LINEAR` minification filter take Mesa's
    /// elliptical weighted average ([`BoundTexture::sample_ewa`]), so that pictures match
    /// llvmpipe's and softpipe's. Other targets and filters take this footprint rule: with the
    /// derivatives scaled to texels, `Px = |d/dx|`, `Py = |d/dy|`, `Pmax = max(Px, Py)`,
    /// `Pmin = min(Px, Py)`. The number of samples is
    /// `N = min(ceil(Pmax / Pmin), MAX_ANISOTROPY)` (`MAX_ANISOTROPY` when `Pmin` is 0), and
    /// `λ = log2(Pmax / N)` (plus biases and clamps). The N samples, each filtered with that
    /// λ by the texture's filters, lie evenly along the major axis of the footprint, at
    /// `coords + d_major * ((i + 1/2) / N - 1/2)` for i in 0..N, and are averaged with equal
    /// weights. With `MAX_ANISOTROPY` = 1 (the default) this is exactly the isotropic λ of
    /// [`BoundTexture::scale_factor_lambda`] and one sample.
    ///
    /// Cube maps: the face is chosen from `coords`; `coords + d_dx` and `coords + d_dy` are
    /// projected on the same face to get face-space derivatives.
    pub fn sample_grad(
        &self,
        coords: [f32; 3],
        d_dx: [f32; 3],
        d_dy: [f32; 3],
        unit_lod_bias: f32,
    ) -> [f32; 4] {
        let v = self.sample_grad_unswizzled(coords, d_dx, d_dy, unit_lod_bias);
        let sw = self.inner.params.swizzle;
        if sw == SwizzleSource::IDENTITY {
            return v;
        }
        sw.map(|s| match s {
            SwizzleSource::Red => v[0],
            SwizzleSource::Green => v[1],
            SwizzleSource::Blue => v[2],
            SwizzleSource::Alpha => v[3],
            SwizzleSource::Zero => 0.0,
            SwizzleSource::One => 1.0,
        })
    }

    /// Filtering without the component swizzle.
    fn sample_grad_unswizzled(
        &self,
        coords: [f32; 3],
        d_dx: [f32; 3],
        d_dy: [f32; 3],
        unit_lod_bias: f32,
    ) -> [f32; 4] {
        // ARB_texture_rectangle: coordinates (and their derivatives) are in texels.
        let (coords, d_dx, d_dy) = if self.inner.target == TextureTarget::Rectangle {
            let [w, h, _] = self.inner.base_size;
            let n = |v: [f32; 3]| [v[0] / w.max(1.0), v[1] / h.max(1.0), v[2]];
            (n(coords), n(d_dx), n(d_dy))
        } else {
            (coords, d_dx, d_dy)
        };
        let (face, c, dx, dy) = if self.inner.target == TextureTarget::CubeMap {
            let (face, st) = cube_face(coords);
            let (dx, dy) = cube_face_derivatives(face, st, coords, d_dx, d_dy);
            (face, [st[0], st[1], coords[2]], dx, dy)
        } else {
            (0, coords, d_dx, d_dy)
        };
        let max_aniso = self.inner.params.max_anisotropy;
        if max_aniso <= 1.0 {
            let lambda = self.isotropic_lambda(dx, dy, unit_lod_bias);
            return self.sample_face(face, c, lambda);
        }
        if self.uses_ewa() {
            if let Some(v) = self.sample_ewa(c, dx, dy, max_aniso, unit_lod_bias) {
                return v;
            }
        }
        let (px, py) = (length(self.scaled(dx)), length(self.scaled(dy)));
        let (pmax, pmin, axis) = if px >= py { (px, py, dx) } else { (py, px, dy) };
        let n = if !pmax.is_finite() || pmax <= 0.0 {
            1.0
        } else if pmin > 0.0 {
            (pmax / pmin).ceil().min(max_aniso).max(1.0)
        } else {
            max_aniso.floor().max(1.0)
        };
        let n = n as usize;
        let lambda = self.lambda_from_rho(pmax / n as f32, unit_lod_bias);
        if n <= 1 {
            return self.sample_face(face, c, lambda);
        }
        let mut sum = [0.0f32; 4];
        for i in 0..n {
            let k = (i as f32 + 0.5) / n as f32 - 0.5;
            let p = [c[0] + axis[0] * k, c[1] + axis[1] * k, c[2] + axis[2] * k];
            let v = self.sample_face(face, p, lambda);
            for j in 0..4 {
                sum[j] += v[j];
            }
        }
        sum.map(|v| v / n as f32)
    }

    /// Whether anisotropic filtering takes the elliptical weighted average of
    /// [`BoundTexture::sample_ewa`]: 2D textures (and rectangles) whose minification filter
    /// interpolates between two levels (`*_MIPMAP_LINEAR`), as Mesa's llvmpipe and softpipe
    /// filter them. Other targets and filters take the footprint rule of
    /// [`BoundTexture::sample_grad`].
    fn uses_ewa(&self) -> bool {
        matches!(
            self.inner.target,
            TextureTarget::T2D | TextureTarget::Rectangle
        ) && matches!(
            self.inner.params.min_filter,
            MinFilter::NearestMipmapLinear | MinFilter::LinearMipmapLinear
        )
    }

    /// Anisotropic filtering as Mesa's llvmpipe and softpipe do it (Heckbert's elliptical
    /// weighted average), so that pictures match theirs. With the derivatives in base-level
    /// texels (`u_x, v_x` along x, `u_y, v_y` along y), `P_x^2 = u_x^2 + v_x^2`,
    /// `P_y^2 = u_y^2 + v_y^2`, the larger `Pmax^2` and the smaller `Pmin^2`, raised to
    /// `Pmax^2 / MAX_ANISOTROPY^2` when the ratio exceeds `MAX_ANISOTROPY^2`: λ =
    /// `log2(Pmin)` plus biases, clamped as usual; one level, `trunc(λ)` (at least 0). From the
    /// last level on, that level's nearest texel. Below it, the derivatives scaled to the
    /// level define the ellipse `A u^2 + B u v + C v^2 = F` with `A = v_x^2 + v_y^2 + 1`,
    /// `B = -2 (u_x v_x + u_y v_y)`, `C = u_x^2 + u_y^2 + 1`, `F = A C - B^2 / 4` (the `+ 1`s
    /// keep it at least a texel across), centred at the sample point in texel coordinates
    /// (`s w - 1/2`); every texel (u, v) of its bounding box with `q = (A U^2 + B U V +
    /// C V^2) (1023 / F) < 1024` (U, V from the centre) weighs `exp(-2 trunc(q) / 1023)`, and
    /// the result is the weighted mean of those texels (each fetched with wrapping at texture
    /// coordinate `(u / w, v / h)`). `None` when the ellipse's bounding box holds more than
    /// [`EWA_MAX_TEXELS`] texels (a footprint far larger than its level, as `GL_TEXTURE_MAX_LOD`
    /// can force): the caller then takes the footprint rule, which bounds the work per
    /// fragment.
    fn sample_ewa(
        &self,
        c: [f32; 3],
        dx: [f32; 3],
        dy: [f32; 3],
        max_aniso: f32,
        unit_lod_bias: f32,
    ) -> Option<[f32; 4]> {
        let Some(levels) = self.inner.levels.first().filter(|l| !l.is_empty()) else {
            return Some([0.0, 0.0, 0.0, 1.0]);
        };
        let [w0, h0, _] = self.inner.base_size;
        let (ux, vx) = (dx[0] * w0, dx[1] * h0);
        let (uy, vy) = (dy[0] * w0, dy[1] * h0);
        let px2 = ux * ux + vx * vx;
        let py2 = uy * uy + vy * vy;
        let (pmax2, mut pmin2) = if px2 < py2 { (py2, px2) } else { (px2, py2) };
        let max_e = max_aniso * max_aniso;
        if !(pmax2 / pmin2 <= max_e) {
            pmin2 = pmax2 / max_e;
        }
        let lambda = self.lambda_from_rho(pmin2.sqrt(), unit_lod_bias);
        let last = levels.len() - 1;
        // Truncated towards zero (a NaN λ counts as 0).
        let level = if lambda.is_nan() {
            0
        } else {
            lambda.max(-1.0).min(1e9) as i64
        };
        if level >= last as i64 {
            return Some(self.finish(self.filter(&levels[last], false, c)));
        }
        let level = level.max(0) as usize;
        let img = &levels[level];
        let scaling = 1.0 / (1u64 << level) as f32;
        let (width, height) = (
            (w0 * scaling).floor().max(1.0),
            (h0 * scaling).floor().max(1.0),
        );
        let (ux, vx, uy, vy) = (ux * scaling, vx * scaling, uy * scaling, vy * scaling);
        let a = vx * vx + vy * vy + 1.0;
        let b = -2.0 * (ux * vx + uy * vy);
        let cc = ux * ux + uy * uy + 1.0;
        let f = a * cc - b * b / 4.0;
        let d = -b * b + 4.0 * cc * a;
        let box_u = 2.0 / d * (d * cc * f).sqrt();
        let box_v = 2.0 / d * (a * d * f).sqrt();
        if !(box_u.is_finite() && box_v.is_finite() && f > 0.0) {
            return Some(self.finish(self.filter(img, false, c)));
        }
        let form = (EWA_LUT_SIZE - 1) as f64 / f as f64;
        let (a, b, cc) = (a as f64 * form, b as f64 * form, cc as f64 * form);
        let tex_u = -0.5 + c[0] * w0 * scaling;
        let tex_v = -0.5 + c[1] * h0 * scaling;
        // At the level λ selects the ellipse's minor axis spans one or two texels and its
        // major axis at most MAX_ANISOTROPY times that, unless λ was clamped.
        let (u0, u1) = ((tex_u - box_u).floor(), (tex_u + box_u).ceil());
        let (v0, v1) = ((tex_v - box_v).floor(), (tex_v + box_v).ceil());
        if !((u1 - u0 + 1.0) * (v1 - v0 + 1.0) <= EWA_MAX_TEXELS) {
            return None;
        }
        let (u0, u1, v0, v1) = (u0 as i64, u1 as i64, v0 as i64, v1 as i64);
        let mut num = [0.0f64; 4];
        let mut den = 0.0f64;
        for v in v0..=v1 {
            let vv = (v as f32 - tex_v) as f64;
            for u in u0..=u1 {
                let uu = (u as f32 - tex_u) as f64;
                let q = (cc * vv + b * uu) * vv + a * uu * uu;
                if q < EWA_LUT_SIZE as f64 {
                    let weight = ewa_weight(q.max(0.0) as usize) as f64;
                    let t = self.filter(img, false, [u as f32 / width, v as f32 / height, c[2]]);
                    for k in 0..4 {
                        num[k] += weight * t[k] as f64;
                    }
                    den += weight;
                }
            }
        }
        if !(den > 0.0) {
            return Some(self.finish(self.filter(img, false, c)));
        }
        Some(self.finish(num.map(|n| (n / den) as f32)))
    }

    /// Level selection and filtering on one face (coords: s, t, r; for cube faces r is only
    /// used for depth comparison).
    fn sample_face(&self, face: usize, coords: [f32; 3], lambda: f32) -> [f32; 4] {
        let Some(levels) = self.inner.levels.get(face) else {
            return [0.0, 0.0, 0.0, 1.0];
        };
        if levels.is_empty() {
            return [0.0, 0.0, 0.0, 1.0];
        }
        let plan = self.plan_for(lambda, levels.len() - 1);
        if let Some(dims) = self.fixed_tier(&levels[0]) {
            let wrap = self.inner.params.wrap;
            let bytes = match plan {
                LevelPlan::One { level, linear } => {
                    fixed::filter_image(&levels[level], dims, wrap, linear, coords)
                }
                LevelPlan::Two {
                    levels: [d1, d2],
                    linear,
                    weight,
                } => fixed::lerp4(
                    fixed::filter_image(&levels[d1], dims, wrap, linear, coords),
                    fixed::filter_image(&levels[d2], dims, wrap, linear, coords),
                    fixed::level_weight(weight),
                ),
            };
            return self.finish(fixed::to_f32(bytes));
        }
        let raw = match plan {
            LevelPlan::One { level, linear } => self.filter(&levels[level], linear, coords),
            LevelPlan::Two {
                levels: [d1, d2],
                linear,
                weight,
            } => {
                let t1 = self.filter(&levels[d1], linear, coords);
                let t2 = self.filter(&levels[d2], linear, coords);
                lerp4(t1, t2, weight)
            }
        };
        self.finish(raw)
    }

    /// Level selection for λ (section 3.8.8): magnification when λ <= c
    /// ([`BoundTexture::switch_over`]), otherwise the minification filter's choice of one
    /// level or two levels and the weight of the second. A NaN λ counts as 0. Levels are
    /// indices from the base level, within [`BoundTexture::level_count`] (0 when it is 0).
    pub fn level_plan(&self, lambda: f32) -> LevelPlan {
        self.plan_for(lambda, self.level_count().saturating_sub(1))
    }

    /// The level plan when it does not depend on λ (no mipmapping, and the same filter for
    /// magnification and minification), so that λ need not be computed.
    pub fn plan_without_lambda(&self) -> Option<LevelPlan> {
        let p = &self.inner.params;
        let mag_linear = p.mag_filter == MagFilter::Linear;
        match p.min_filter {
            MinFilter::Nearest if !mag_linear => Some(LevelPlan::One {
                level: 0,
                linear: false,
            }),
            MinFilter::Linear if mag_linear => Some(LevelPlan::One {
                level: 0,
                linear: true,
            }),
            _ => None,
        }
    }

    /// [`BoundTexture::level_plan`] for a chain whose last level is `q`.
    #[inline]
    fn plan_for(&self, lambda: f32, q: usize) -> LevelPlan {
        let mut select = self.lod_select(0.0);
        select.last_level = q;
        select.plan(lambda)
    }

    /// Internal RGBA after filtering -> texture source colour.
    fn finish(&self, v: [f32; 4]) -> [f32; 4] {
        let v = if self.inner.clamp_float {
            v.map(super::image::clamp01)
        } else {
            v
        };
        match self.inner.base {
            BaseFormat::DepthComponent => {
                let d = v[0];
                match self.inner.params.depth_mode {
                    DepthTextureMode::Luminance => [d, d, d, 1.0],
                    DepthTextureMode::Intensity => [d; 4],
                    DepthTextureMode::Alpha => [0.0, 0.0, 0.0, d],
                }
            }
            b => b.expand(v),
        }
    }

    /// One texel by wrapped inner indices (-1 or size: border), in internal RGBA, after depth
    /// comparison when enabled.
    #[inline(always)]
    fn texel(&self, img: &TexImage, idx: [i64; 3], inner: [i64; 3], r: f32) -> [f32; 4] {
        let b = img.borders();
        let mut outside = false;
        for d in 0..3 {
            if idx[d] < 0 || idx[d] >= inner[d] {
                outside = true;
            }
        }
        let v = if outside && img.border == 0 {
            self.inner.params.border_color
        } else {
            img.fetch(
                (idx[0] + b[0] as i64) as i32,
                (idx[1] + b[1] as i64) as i32,
                (idx[2] + b[2] as i64) as i32,
            )
        };
        let p = &self.inner.params;
        if p.compare && self.inner.base == BaseFormat::DepthComponent {
            let r = super::image::clamp01(r);
            let pass = p.compare_func.test(r, v[0]);
            let x = if pass { 1.0 } else { 0.0 };
            [x, x, x, x]
        } else {
            v
        }
    }

    /// NEAREST or LINEAR filtering of one image (1D, 2D or 3D by the target).
    fn filter(&self, img: &TexImage, linear: bool, coords: [f32; 3]) -> [f32; 4] {
        let dims = match self.inner.target {
            TextureTarget::T1D => 1,
            TextureTarget::T3D => 3,
            _ => 2,
        };
        let sz = img.inner_size();
        let inner = [
            sz[0].max(1) as i64,
            sz[1].max(1) as i64,
            sz[2].max(1) as i64,
        ];
        let wrap = self.inner.params.wrap;
        let r = coords[2];
        // Per axis: the two indices and the weight of the second.
        let mut i0 = [0i64; 3];
        let mut i1 = [0i64; 3];
        let mut w = [0.0f32; 3];
        for d in 0..dims {
            let mut s = coords[d] as f64;
            match wrap[d] {
                WrapMode::Clamp => {
                    s = s.clamp(0.0, 1.0);
                    if s.is_nan() {
                        s = 0.0;
                    }
                }
                WrapMode::MirrorClamp => {
                    s = s.abs().min(1.0);
                    if s.is_nan() {
                        s = 0.0;
                    }
                }
                WrapMode::MirrorClampToEdge | WrapMode::MirrorClampToBorder => s = s.abs(),
                _ => {}
            }
            let u = s * inner[d] as f64;
            if linear {
                let (f, frac) = floor_frac(u - 0.5);
                w[d] = frac;
                i0[d] = wrap_index(f, inner[d], wrap[d], true);
                i1[d] = wrap_index(f.saturating_add(1), inner[d], wrap[d], true);
            } else {
                i0[d] = wrap_index(floor_frac(u).0, inner[d], wrap[d], false);
                i1[d] = i0[d];
            }
        }
        if !linear {
            return self.texel(img, i0, inner, r);
        }
        match dims {
            1 => {
                let a = self.texel(img, [i0[0], 0, 0], inner, r);
                let b = self.texel(img, [i1[0], 0, 0], inner, r);
                lerp4(a, b, w[0])
            }
            2 => {
                let t = |i: i64, j: i64| self.texel(img, [i, j, 0], inner, r);
                let row0 = lerp4(t(i0[0], i0[1]), t(i1[0], i0[1]), w[0]);
                let row1 = lerp4(t(i0[0], i1[1]), t(i1[0], i1[1]), w[0]);
                lerp4(row0, row1, w[1])
            }
            _ => {
                let t = |i: i64, j: i64, k: i64| self.texel(img, [i, j, k], inner, r);
                let slice = |k: i64| {
                    let row0 = lerp4(t(i0[0], i0[1], k), t(i1[0], i0[1], k), w[0]);
                    let row1 = lerp4(t(i0[0], i1[1], k), t(i1[0], i1[1], k), w[0]);
                    lerp4(row0, row1, w[1])
                };
                lerp4(slice(i0[2]), slice(i1[2]), w[2])
            }
        }
    }
}

/// One mipmap level as the fast 2D path reads it: unsigned-byte texels with 3 (RGB) or 4
/// (RGBA) components, rows bottom to top, no border (see [`BoundTexture::fast_2d`]).
#[derive(Clone, Copy, Debug)]
pub struct FastLevel<'a> {
    texels: &'a [u8],
    width: i64,
    height: i64,
}

impl<'a> FastLevel<'a> {
    /// The texel bytes, `components` per texel, rows bottom to top.
    pub fn texels(&self) -> &'a [u8] {
        self.texels
    }

    /// Width and height in texels.
    pub fn size(&self) -> [i64; 2] {
        [self.width, self.height]
    }
}

/// The texel at (x, y) of `lvl` as internal RGBA, as [`TexImage::fetch`] converts it.
#[inline(always)]
fn fast_texel<const C: usize>(lvl: &FastLevel, x: i64, y: i64) -> [f32; 4] {
    let i = ((y * lvl.width + x) as usize) * C;
    let conv = |c: u8| c as f32 * (1.0 / 255.0);
    match lvl.texels.get(i..i + C) {
        Some(t) if C == 4 => [conv(t[0]), conv(t[1]), conv(t[2]), conv(t[3])],
        Some(t) => [conv(t[0]), conv(t[1]), conv(t[2]), 1.0],
        None => [0.0, 0.0, 0.0, 1.0],
    }
}

impl BoundTexture {
    /// Whether the fast 2D path ([`BoundTexture::fast_level`], [`BoundTexture::filter_fast`])
    /// can sample this texture: a 2D texture whose levels all hold unsigned-byte RGB or RGBA
    /// texels without a border, s and t wrapped by `REPEAT`, `CLAMP_TO_EDGE` or
    /// `MIRRORED_REPEAT` (which never select a border texel), without anisotropy. Depth
    /// comparison does not apply to colour formats. The fast path's results are those of
    /// [`BoundTexture::sample_grad`], bit for bit.
    pub fn fast_2d(&self) -> bool {
        matches!(self.inner.base, BaseFormat::Rgb | BaseFormat::Rgba) && self.byte_2d()
    }

    /// Whether the eight-pixel filter (`simd::Level8`) may sample this texture, given that
    /// each level also passes `Level8::new`: a texture the fast 2D path takes
    /// ([`BoundTexture::fast_2d`]) or one of one-byte ALPHA, LUMINANCE, LUMINANCE_ALPHA or
    /// INTENSITY texels under the same conditions; or a cube map whose faces are such
    /// images (each lane's face chosen, then filtered as a 2D image).
    pub fn simd_2d(&self) -> bool {
        self.simd_formats() && (self.byte_2d() || self.byte_cube())
    }

    /// The base formats the eight-pixel filter expands.
    fn simd_formats(&self) -> bool {
        matches!(
            self.inner.base,
            BaseFormat::Rgb
                | BaseFormat::Rgba
                | BaseFormat::Alpha
                | BaseFormat::Luminance
                | BaseFormat::LuminanceAlpha
                | BaseFormat::Intensity
        )
    }

    /// A 2D texture of unsigned-byte texels without border, wrapped by `REPEAT`,
    /// `CLAMP_TO_EDGE` or `MIRRORED_REPEAT`, without anisotropy or swizzle.
    fn byte_2d(&self) -> bool {
        self.inner.target == TextureTarget::T2D && self.byte_faces(1)
    }

    /// A cube map whose six faces are what [`BoundTexture::byte_2d`] asks of a 2D texture
    /// (the faces are sampled as 2D images once a face is chosen).
    fn byte_cube(&self) -> bool {
        self.inner.target == TextureTarget::CubeMap && self.byte_faces(6)
    }

    /// `faces` faces of unsigned-byte levels without border, s and t wrapped by `REPEAT`,
    /// `CLAMP_TO_EDGE` or `MIRRORED_REPEAT`, without anisotropy or swizzle.
    fn byte_faces(&self, faces: usize) -> bool {
        let i = &*self.inner;
        let wrap_ok = |w: WrapMode| {
            matches!(
                w,
                WrapMode::Repeat | WrapMode::ClampToEdge | WrapMode::MirroredRepeat
            )
        };
        i.params.max_anisotropy <= 1.0
            && i.params.swizzle == SwizzleSource::IDENTITY
            && wrap_ok(i.params.wrap[0])
            && wrap_ok(i.params.wrap[1])
            && i.levels.len() == faces
            && i.levels.iter().all(|face| {
                face.iter().all(|l| {
                    l.border == 0
                        && l.format.base == i.base
                        && l.width > 0
                        && l.height > 0
                        && matches!(&*l.texels, Texels::U8(_))
                })
            })
    }

    /// How many faces the eight-pixel samplers read: 6 for cube maps, else 1.
    pub fn face_count(&self) -> usize {
        if self.inner.target == TextureTarget::CubeMap {
            6
        } else {
            1
        }
    }

    /// Level `level` (from the base level) for the fast 2D path, or `None` when the texture is
    /// not eligible ([`BoundTexture::fast_2d`]) or the level does not exist.
    #[inline]
    pub fn fast_level(&self, level: usize) -> Option<FastLevel<'_>> {
        self.face_fast_level(0, level)
    }

    /// [`BoundTexture::fast_level`] of face `face` (cube maps: +X, -X, +Y, -Y, +Z, -Z).
    #[inline]
    pub fn face_fast_level(&self, face: usize, level: usize) -> Option<FastLevel<'_>> {
        let l = self.inner.levels.get(face)?.get(level)?;
        match &*l.texels {
            Texels::U8(v) if l.border == 0 => Some(FastLevel {
                texels: v,
                width: l.width.max(1) as i64,
                height: l.height.max(1) as i64,
            }),
            _ => None,
        }
    }

    /// The s and t wrap modes.
    pub fn wrap_st(&self) -> [WrapMode; 2] {
        [self.inner.params.wrap[0], self.inner.params.wrap[1]]
    }

    /// NEAREST or LINEAR filtering of a fast level at (s, t), `C` components per texel (3 or
    /// 4, the base format's): the arithmetic of the general filter for a 2D image without
    /// border (the fixed-point tier, [`fixed`], when both axes wrap by `REPEAT` or
    /// `CLAMP_TO_EDGE`), and the texture source colour it finishes into.
    #[inline(always)]
    pub fn filter_fast<const C: usize>(
        &self,
        lvl: &FastLevel,
        linear: bool,
        coords: [f32; 2],
    ) -> [f32; 4] {
        let wrap = self.inner.params.wrap;
        if fixed::simple_wrap(wrap[0]) && fixed::simple_wrap(wrap[1]) {
            let bytes = fixed::filter_fast::<C>(lvl, [wrap[0], wrap[1]], linear, coords);
            return fixed::to_f32(bytes);
        }
        let size = [lvl.width, lvl.height];
        if !linear {
            let i = [0, 1].map(|d| {
                let u = coords[d] as f64 * size[d] as f64;
                wrap_index(floor_frac(u).0, size[d], wrap[d], false)
            });
            return fast_texel::<C>(lvl, i[0], i[1]);
        }
        let mut i0 = [0i64; 2];
        let mut i1 = [0i64; 2];
        let mut w = [0f32; 2];
        for d in 0..2 {
            let u = coords[d] as f64 * size[d] as f64;
            let (f, frac) = floor_frac(u - 0.5);
            w[d] = frac;
            i0[d] = wrap_index(f, size[d], wrap[d], true);
            i1[d] = wrap_index(f.saturating_add(1), size[d], wrap[d], true);
        }
        let t = |i: i64, j: i64| fast_texel::<C>(lvl, i, j);
        let row0 = lerp4(t(i0[0], i0[1]), t(i1[0], i0[1]), w[0]);
        let row1 = lerp4(t(i0[0], i1[1]), t(i1[0], i1[1]), w[0]);
        lerp4(row0, row1, w[1])
    }
}

/// The most texels the elliptical weighted average visits for one fragment (a 64 x 64 box;
/// unclamped footprints stay below 40 x 40).
const EWA_MAX_TEXELS: f32 = 4096.0;

/// Entries of the elliptical weighted average's weight table (Mesa's `WEIGHT_LUT_SIZE`).
const EWA_LUT_SIZE: usize = 1024;

/// The Gaussian weight of table entry `i`: `exp(-2 i / 1023)` (as f32, like Mesa's table).
#[inline]
fn ewa_weight(i: usize) -> f32 {
    let r2 = i.min(EWA_LUT_SIZE - 1) as f32 / (EWA_LUT_SIZE - 1) as f32;
    (-2.0 * r2).exp()
}

/// LodSelects of 2D textures over every minification filter, both magnification filters
/// (so both switch-over points), biases, LOD clamps on and off the 1/256 grid and chain
/// lengths, for the tests of the quick level plan.
#[cfg(test)]
pub(crate) fn test_lod_selects() -> Vec<LodSelect> {
    let mut out = Vec::new();
    let filters = [
        MinFilter::Nearest,
        MinFilter::Linear,
        MinFilter::NearestMipmapNearest,
        MinFilter::LinearMipmapNearest,
        MinFilter::NearestMipmapLinear,
        MinFilter::LinearMipmapLinear,
    ];
    for min_filter in filters {
        for mag_linear in [false, true] {
            for bias in [0.0, -16.0, -2.7, 0.3, 1.0, 16.0] {
                for (min_lod, max_lod) in [
                    (-1000.0, 1000.0),
                    (-2.0, 0.25),
                    (0.4, 3.0),
                    (3.0, 9.0),
                    (2.5, 1.0),
                    (-1e30, 1e30),
                ] {
                    for last_level in [0, 1, 4, 12] {
                        let switch_over = if mag_linear
                            && matches!(
                                min_filter,
                                MinFilter::NearestMipmapNearest | MinFilter::NearestMipmapLinear
                            ) {
                            0.5
                        } else {
                            0.0
                        };
                        let lod = LodSelect {
                            bias,
                            min_lod,
                            max_lod,
                            switch_over,
                            mag_linear,
                            min_filter,
                            last_level,
                            size: [256.0, 256.0, 1.0],
                            target: TextureTarget::T2D,
                            magnified_below: LodSelect::magnified_below(switch_over, bias, min_lod),
                            quick: QuickTerms::new(bias, min_lod, max_lod),
                        };
                        out.push(lod);
                    }
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `surely_magnified` never claims a quad that λ would minify: over biases, switch-over
    /// points, LOD clamps, sizes and derivatives on both sides of the threshold (and NaN,
    /// infinite and zero ones), the plan of the full λ is magnification whenever it answers
    /// true; and it does answer true well inside the threshold.
    #[test]
    fn surely_magnified_quads_are_magnified() {
        let mut seed = 0x1234_5678_9ABC_DEF1u64;
        let mut next = move || {
            let seed = crate::test_support::xorshift(&mut seed);
            (seed >> 40) as f32 / (1u64 << 24) as f32
        };
        let (mut claimed, mut checked) = (0, 0);
        for bias in [-16.0, -3.3, 0.0, 0.7, 16.0] {
            for switch_over in [0.0, 0.5] {
                for (min_lod, max_lod) in [(-1000.0, 1000.0), (-2.0, 0.2), (0.4, 3.0), (3.0, 9.0)] {
                    for size in [64.0, 128.0, 1000.0] {
                        let lod = LodSelect {
                            bias,
                            min_lod,
                            max_lod,
                            switch_over,
                            mag_linear: true,
                            min_filter: MinFilter::LinearMipmapLinear,
                            last_level: 10,
                            size: [size, size, 1.0],
                            target: TextureTarget::T2D,
                            magnified_below: LodSelect::magnified_below(switch_over, bias, min_lod),
                            quick: QuickTerms::new(bias, min_lod, max_lod),
                        };
                        // Derivatives around ρ = 2^(c - bias) texels, the threshold.
                        let edge = ((switch_over - bias) as f64).exp2() as f32 / size;
                        for k in 0..400 {
                            let scale =
                                edge * (0.98 + 0.04 * next()) * if k % 4 == 0 { 0.3 } else { 1.0 };
                            let (a, b) = (next() * 2.0 - 1.0, next() * 2.0 - 1.0);
                            let n = (a * a + b * b).sqrt().max(1e-6);
                            let mut dx = [a / n * scale, b / n * scale, 0.0];
                            let dy = [b / n * scale * next(), a / n * scale * next(), 0.0];
                            match k % 50 {
                                0 => dx[0] = f32::NAN,
                                1 => dx[1] = f32::INFINITY,
                                2 => dx = [0.0; 3],
                                _ => {}
                            }
                            checked += 1;
                            if lod.surely_magnified(dx, dy) {
                                claimed += 1;
                                let plan = lod.plan(lod.isotropic_lambda(dx, dy));
                                assert_eq!(
                                    plan,
                                    lod.magnification(),
                                    "bias {bias}, c {switch_over}, lod {min_lod}..{max_lod}, {dx:?} {dy:?}"
                                );
                            }
                        }
                    }
                }
            }
        }
        assert!(claimed > checked / 10, "{claimed} of {checked}");
    }

    /// [`quick_log2_128`] is within 3.61e-4 of 128 log2 x (f64) for every f32 mantissa x in
    /// [1, 2) (all 2^23 of them): the bound [`LodSelect::quick_lambda256`]'s proof takes
    /// (the chords' 3.53e-4 and the roundings). It is nearly reached (the chords are the
    /// estimate's error, not a slack).
    #[test]
    fn quick_log2_is_within_its_bound() {
        let mut worst = 0f64;
        for mantissa in 0..1u32 << 23 {
            let bits = 0x3F80_0000 | mantissa;
            let x = f32::from_bits(bits) as f64;
            let err = (quick_log2_128(bits) as f64 - 128.0 * x.log2()).abs();
            worst = worst.max(err);
        }
        assert!(worst <= 3.61e-4, "{worst:e}");
        assert!(worst >= 3.0e-4, "{worst:e}");
    }

    /// Where [`LodSelect::quick_lambda256`] answers g, the exact 256 λ (f64: 128 log2 m +
    /// 256 bias, no clamp) lies inside (g, g + 1), at least the margin less the estimate's
    /// error (3.7e-4) from both ends: ρ² over the whole range of normal numbers (random
    /// bits, values next to the steps) and every bias of `test_lod_selects` without a clamp.
    #[test]
    fn quick_lambdas_are_within_the_margin_of_the_exact_ones() {
        let mut seed = 0x5851_F42D_4C95_7F2Du64;
        let margin = QUICK_LOD_MARGIN * 256.0 - 3.7e-4;
        let mut answered = 0;
        for bias in [0.0f32, -16.0, -2.7, 0.3, 1.0, 16.0, 0.1234, -7.77] {
            let mut lod = test_lod_selects()[0];
            lod.bias = bias;
            lod.min_lod = -1000.0;
            lod.max_lod = 1000.0;
            lod.quick = QuickTerms::new(bias, -1000.0, 1000.0);
            for k in 0..200_000 {
                let r = crate::test_support::xorshift(&mut seed);
                let m = if k % 2 == 0 {
                    f32::from_bits((r as u32 % 0x7F00_0000) + 0x0080_0000)
                } else {
                    // Within a few hundredths of a step of λ = j/256.
                    let j = (r >> 32) as i64 % (60 * 256) - 30 * 256;
                    let e = ((r >> 8) % 2001) as f64 / 2000.0 * 0.06 - 0.03;
                    ((2.0 * ((j as f64 + e) / 256.0 - bias as f64)).exp2()) as f32
                };
                if let Some(g) = lod.quick_lambda256(m) {
                    answered += 1;
                    let exact = 128.0 * (m as f64).log2() + 256.0 * bias as f64 - g as f64;
                    assert!(
                        exact > margin && exact < 1.0 - margin,
                        "m {m:e} bias {bias} g {g} exact {exact}"
                    );
                }
            }
        }
        assert!(answered > 1_000_000, "{answered}");
    }

    /// The level plan from [`LodSelect::quick_lambda256`] and
    /// [`LodSelect::plan_of_lambda256`] is the sampler's ([`LodSelect::plan_for_rho2`], with
    /// its weight quantised by `fixed::level_weight`) for every ρ² it answers: random bit
    /// patterns over the whole f32 range, values next to each step of the plan (λ a multiple
    /// of 1/256 give or take a few units in the last place) and random values in the usual
    /// range, under every minification filter, both switch-over points, biases, LOD clamps
    /// (on and off the 1/256 grid) and chain lengths. It must answer for most of them.
    #[test]
    fn quick_plans_are_the_samplers_plans() {
        let mut seed = 0x0DDB_1A5E_5BAD_5EEDu64;
        let mut rnd = move || crate::test_support::xorshift(&mut seed);
        let quantised = |p: LevelPlan| match p {
            LevelPlan::One { level, linear } => ((level, level, linear), 0),
            LevelPlan::Two {
                levels: [a, b],
                linear,
                weight,
            } => ((a, b, linear), fixed::level_weight(weight) as i32),
        };
        let (mut answered, mut checked) = (0u64, 0u64);
        for lod in test_lod_selects() {
            let bias = lod.bias;
            for k in 0..3000 {
                let r = rnd();
                // λ = j/256 (before the clamps) for a step j of the plan's grid.
                let j = (r >> 32) as i64 % (40 * 256) - 20 * 256;
                let at = |l: f64| (2.0 * (l - bias as f64)).exp2() as f32;
                let m = match k % 4 {
                    0 => f32::from_bits(r as u32),
                    1 => {
                        // Next to a step: a few units in the last place of ρ² off it.
                        let d = (r % 9) as i32 - 4;
                        f32::from_bits((at(j as f64 / 256.0).to_bits() as i32 + d) as u32)
                    }
                    2 => {
                        // Near a step: up to 1/20 of a step off it (ten margins).
                        let e = ((r >> 8) % 2001) as f64 / 2000.0 * 0.1 - 0.05;
                        at((j as f64 + e) / 256.0)
                    }
                    _ => ((r >> 40) as f32 / (1u64 << 24) as f32 * 40.0 - 20.0).exp2(),
                };
                checked += 1;
                if let Some(g) = lod.quick_lambda256(m) {
                    answered += 1;
                    assert_eq!(
                        lod.plan_of_lambda256(g),
                        quantised(lod.plan_for_rho2(m, 0.0)),
                        "{lod:?} m {m:e}"
                    );
                }
            }
        }
        // About 29 %: the clamps of several parameter sets put λ on a step.
        assert!(answered > checked / 5, "{answered} of {checked}");
    }

    /// `quantised_plan` is `plan(isotropic_lambda)` with the weight quantised alike, for
    /// derivatives of every scale (zero, NaN and infinite components included) under every
    /// parameter set of `test_lod_selects`.
    #[test]
    fn quantised_plans_are_the_samplers_plans() {
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        let mut unit = move || {
            let r = crate::test_support::xorshift(&mut seed);
            (r >> 40) as f32 / (1u64 << 24) as f32
        };
        let q = |p: LevelPlan| match p {
            LevelPlan::One { level, linear } => (level, level, linear, 0),
            LevelPlan::Two {
                levels: [a, b],
                linear,
                weight,
            } => (a, b, linear, fixed::level_weight(weight)),
        };
        for lod in test_lod_selects() {
            for k in 0..200 {
                let scale = (unit() * 30.0 - 20.0).exp2();
                let mut d = [0f32; 6].map(|_| (unit() * 2.0 - 1.0) * scale);
                match k % 40 {
                    0 => d[1] = f32::NAN,
                    1 => d[3] = f32::INFINITY,
                    2 => d = [0.0; 6],
                    _ => {}
                }
                let (dx, dy) = ([d[0], d[1], d[2]], [d[3], d[4], d[5]]);
                assert_eq!(
                    q(lod.quantised_plan(dx, dy)),
                    q(lod.plan(lod.isotropic_lambda(dx, dy))),
                    "{lod:?} {dx:?} {dy:?}"
                );
            }
        }
    }

    #[test]
    fn wrap_functions() {
        use WrapMode::*;
        assert_eq!(wrap_index(-1, 4, Repeat, true), 3);
        assert_eq!(wrap_index(9, 4, Repeat, true), 1);
        assert_eq!(wrap_index(-1, 4, ClampToEdge, true), 0);
        assert_eq!(wrap_index(4, 4, ClampToBorder, true), 4);
        assert_eq!(wrap_index(7, 4, ClampToBorder, true), 4);
        assert_eq!(wrap_index(4, 4, Clamp, false), 3);
        assert_eq!(wrap_index(-1, 4, Clamp, true), -1);
        // Mirrored: 0 1 2 3 | 3 2 1 0 | 0 1 ...
        let m: Vec<i64> = (-4..10)
            .map(|i| wrap_index(i, 4, MirroredRepeat, true))
            .collect();
        assert_eq!(m, vec![3, 2, 1, 0, 0, 1, 2, 3, 3, 2, 1, 0, 0, 1]);
        assert_eq!(wrap_index(i64::MAX, 3, Repeat, true), i64::MAX % 3);
        // Mirrored once, then clamped (EXT_texture_mirror_clamp): ... 1 0 | 0 1 2 3 | edge.
        let m: Vec<i64> = (-3..7)
            .map(|i| wrap_index(i, 4, MirrorClampToEdge, true))
            .collect();
        assert_eq!(m, vec![2, 1, 0, 0, 1, 2, 3, 3, 3, 3]);
        let m: Vec<i64> = (-3..7)
            .map(|i| wrap_index(i, 4, MirrorClampToBorder, true))
            .collect();
        assert_eq!(m, vec![2, 1, 0, 0, 1, 2, 3, 4, 4, 4]);
        assert_eq!(wrap_index(5, 4, MirrorClamp, false), 3);
        assert_eq!(wrap_index(5, 4, MirrorClamp, true), 4);
        assert_eq!(wrap_index(i64::MIN, 4, MirrorClampToEdge, true), 3);
    }

    #[test]
    fn cube_faces_by_major_axis() {
        assert_eq!(cube_face([1.0, 0.0, 0.0]), (0, [0.5, 0.5]));
        assert_eq!(cube_face([-1.0, 0.5, 0.0]).0, 1);
        assert_eq!(cube_face([0.1, 1.0, 0.2]).0, 2);
        assert_eq!(cube_face([0.1, -1.0, 0.2]).0, 3);
        assert_eq!(cube_face([0.1, 0.2, 1.0]).0, 4);
        assert_eq!(cube_face([0.1, 0.2, -1.0]).0, 5);
        // +X: sc = -rz, tc = -ry: direction (1, -0.5, -0.5) -> s = t = 0.75
        assert_eq!(cube_face([1.0, -0.5, -0.5]), (0, [0.75, 0.75]));
        let (_, st) = cube_face([f32::NAN; 3]);
        assert!(st[0].is_nan() || st[0] == 0.5);
    }
}

//! Fog (section 3.10): a draw's fog parameters and the fog factor, one fragment at a time
//! (the eight-lane form is `fragment::simd::fog_factors8`).

use crate::common::values::FogMode;

/// Fog parameters of a draw (section 3.10).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FogDraw {
    pub mode: FogMode,
    pub density: f32,
    pub start: f32,
    pub end: f32,
    pub color: [f32; 3],
    /// Use the vertex fog coordinate instead of the eye distance.
    pub coord_from_vertex: bool,
}

impl FogDraw {
    /// The fog factor f for fog coordinate `c`, clamped to [0, 1]. With start == end the
    /// linear factor uses a scale of 1 (as Mesa does) instead of dividing by zero.
    #[inline]
    pub fn factor(&self, c: f32) -> f32 {
        let f = match self.mode {
            FogMode::Linear => (self.end - c) * self.linear_scale(),
            FogMode::Exp => fog_exp(-self.density * c),
            FogMode::Exp2 => {
                let d = self.density * c;
                fog_exp(-d * d)
            }
        };
        f.max(0.0).min(1.0)
    }

    /// The linear factor's scale: 1 / (end - start), or 1 when start == end.
    #[inline]
    pub fn linear_scale(&self) -> f32 {
        let range = self.end - self.start;
        if range != 0.0 {
            1.0 / range
        } else {
            1.0
        }
    }
}

/// `ln(2)^k / k!` for k = 1..6: the Taylor coefficients of 2^f.
pub const EXP2_TAYLOR: [f32; 6] = [
    std::f32::consts::LN_2,
    0.240_226_5,
    0.055_504_11,
    0.009_618_129,
    0.001_333_355_8,
    0.000_154_035_3,
];

/// e^x for the fog factor, from operations that eight lanes repeat exactly
/// (`fragment::simd::fog_factors8`), so the eight-lane paths give the general path's factors:
/// t = x log2(e) clamped to [-126, 126], n = floor(t + 1/2), 2^(t - n) by its degree-6
/// Taylor polynomial (|t - n| <= 1/2: relative error below 2e-7, a thousandth of an 8-bit
/// step), times 2^n built from its exponent bits. NaN gives 2^-126 (a factor of 0, as NaN
/// clamps to 0), and below x = -87 the result stays at about 1e-38 instead of 0: both
/// mean "all fog" after 8-bit rounding.
#[inline]
pub fn fog_exp(x: f32) -> f32 {
    let t = (x * std::f32::consts::LOG2_E).max(-126.0).min(126.0);
    let n = (t + 0.5).floor();
    let f = t - n;
    let k = EXP2_TAYLOR;
    let p = (((((k[5] * f + k[4]) * f + k[3]) * f + k[2]) * f + k[1]) * f + k[0]) * f + 1.0;
    p * f32::from_bits(((n as i32 + 127) as u32) << 23)
}

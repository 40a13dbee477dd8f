//! Blending (section 4.1.8) and the logic operation (4.1.10) on 8-bit colour.

use super::key::BlendKey;
use crate::common::fixed::color_to_u8;
use crate::common::values::{BlendEquation, BlendFactor};

/// The factor for one channel; `alpha` selects the alpha channel's rule.
#[inline(always)]
fn factor(f: BlendFactor, s: [f32; 4], d: [f32; 4], c: [f32; 4], ch: usize) -> f32 {
    use BlendFactor::*;
    match f {
        Zero => 0.0,
        One => 1.0,
        SrcColor => s[ch],
        OneMinusSrcColor => 1.0 - s[ch],
        DstColor => d[ch],
        OneMinusDstColor => 1.0 - d[ch],
        SrcAlpha => s[3],
        OneMinusSrcAlpha => 1.0 - s[3],
        DstAlpha => d[3],
        OneMinusDstAlpha => 1.0 - d[3],
        ConstantColor => c[ch],
        OneMinusConstantColor => 1.0 - c[ch],
        ConstantAlpha => c[3],
        OneMinusConstantAlpha => 1.0 - c[3],
        SrcAlphaSaturate => {
            if ch == 3 {
                1.0
            } else {
                s[3].min(1.0 - d[3])
            }
        }
    }
}

/// A blend product (source or destination times its factor) rounded to 8 bits, as a value in
/// [0, 1]. Section 4.1.8 leaves the arithmetic's precision open; Mesa's llvmpipe rounds each
/// product to 8 bits before adding (measured on every source and destination byte for
/// `SRC_ALPHA, ONE_MINUS_SRC_ALPHA` and `DST_COLOR, SRC_COLOR`), and programs that stack many
/// blends and then a logic op (xscreensaver's quasicrystal) show every 1-step difference.
#[inline(always)]
pub fn product_u8(v: f32) -> f32 {
    color_to_u8(v) as f32 / 255.0
}

/// Blends source `src` over destination `dst` with constant colour `constant`: each product
/// rounded to 8 bits ([`product_u8`]), the result clamped to [0, 1] and rounded to 8 bits.
pub fn blend(key: &BlendKey, src: [u8; 4], dst: [u8; 4], constant: [f32; 4]) -> [u8; 4] {
    let s = src.map(|v| v as f32 / 255.0);
    let d = dst.map(|v| v as f32 / 255.0);
    let mut out = [0u8; 4];
    for ch in 0..4 {
        let (sf, df) = if ch == 3 {
            (key.src_alpha, key.dst_alpha)
        } else {
            (key.src_rgb, key.dst_rgb)
        };
        let equation = if ch == 3 {
            key.equation_alpha
        } else {
            key.equation
        };
        let v = match equation {
            BlendEquation::Min => s[ch].min(d[ch]),
            BlendEquation::Max => s[ch].max(d[ch]),
            eq => {
                let a = product_u8(s[ch] * factor(sf, s, d, constant, ch));
                let b = product_u8(d[ch] * factor(df, s, d, constant, ch));
                match eq {
                    BlendEquation::Add => a + b,
                    BlendEquation::Subtract => a - b,
                    _ => b - a,
                }
            }
        };
        out[ch] = color_to_u8(v);
    }
    out
}

/// `v / 255` for every 8-bit value, as [`blend`] converts its inputs.
static UNORM8: [f32; 256] = {
    let mut t = [0f32; 256];
    let mut i = 0;
    while i < 256 {
        t[i] = i as f32 / 255.0;
        i += 1;
    }
    t
};

impl BlendKey {
    /// `FUNC_ADD` with `SRC_ALPHA`, `ONE_MINUS_SRC_ALPHA` for colour and alpha: the usual
    /// "over" blend that [`blend_alpha_over`] computes.
    pub fn is_alpha_over(&self) -> bool {
        self.equation == BlendEquation::Add
            && self.equation_alpha == BlendEquation::Add
            && self.src_rgb == BlendFactor::SrcAlpha
            && self.src_alpha == BlendFactor::SrcAlpha
            && self.dst_rgb == BlendFactor::OneMinusSrcAlpha
            && self.dst_alpha == BlendFactor::OneMinusSrcAlpha
    }
}

impl BlendKey {
    /// Whether every factor is a byte of the source or destination colour (or 0 or 1): none
    /// is the constant colour's (`GL_CONSTANT_COLOR` and its kin, which are not bytes). The
    /// eight-lane tail blends such keys in 16-bit integers (`simd::TailBlend::Bytes`).
    pub fn byte_factors(&self) -> bool {
        use BlendFactor::*;
        [self.src_rgb, self.dst_rgb, self.src_alpha, self.dst_alpha]
            .iter()
            .all(|f| {
                !matches!(
                    f,
                    ConstantColor | OneMinusConstantColor | ConstantAlpha | OneMinusConstantAlpha
                )
            })
    }

    /// `FUNC_ADD` with `ONE`, `ONE` for colour and alpha: additive blending (light passes).
    pub fn is_add_one_one(&self) -> bool {
        self.equation == BlendEquation::Add
            && self.equation_alpha == BlendEquation::Add
            && self.src_rgb == BlendFactor::One
            && self.src_alpha == BlendFactor::One
            && self.dst_rgb == BlendFactor::One
            && self.dst_alpha == BlendFactor::One
    }
}

/// [`blend`] for a key with [`BlendKey::is_alpha_over`]: the same arithmetic (both products
/// rounded to 8 bits, then added), without the per-channel choice of factors.
#[inline(always)]
pub fn blend_alpha_over(src: [u8; 4], dst: [u8; 4]) -> [u8; 4] {
    let s = src.map(|v| UNORM8[v as usize]);
    let d = dst.map(|v| UNORM8[v as usize]);
    let inv = 1.0 - s[3];
    let mut out = [0u8; 4];
    for ch in 0..4 {
        out[ch] = color_to_u8(s[ch] * s[3]).saturating_add(color_to_u8(d[ch] * inv));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The eight-lane tail blends `ONE, ONE` as a saturating byte add (`simd::shade8`): that
    /// must be exactly what [`blend`] computes, for every pair of bytes.
    #[test]
    fn add_one_one_is_a_saturating_byte_add() {
        let key = BlendKey {
            equation: BlendEquation::Add,
            equation_alpha: BlendEquation::Add,
            src_rgb: BlendFactor::One,
            dst_rgb: BlendFactor::One,
            src_alpha: BlendFactor::One,
            dst_alpha: BlendFactor::One,
        };
        assert!(key.is_add_one_one());
        for s in 0..=255u8 {
            for d in 0..=255u8 {
                let src = [s, d, s, 255 - s];
                let dst = [d, s, 255 - d, d];
                let want: [u8; 4] = std::array::from_fn(|c| src[c].saturating_add(dst[c]));
                assert_eq!(blend(&key, src, dst, [0.0; 4]), want, "{src:?} + {dst:?}");
            }
        }
    }
}

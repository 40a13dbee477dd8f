//! Blending (section 4.1.8) and the logic operation (4.1.10) on 8-bit colour.

use super::key::BlendKey;
use super::span::color_to_u8;
use crate::api::convert::{BlendEquation, BlendFactor};

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

/// Blends source `src` over destination `dst` with constant colour `constant`; the result is
/// clamped to [0, 1] and rounded to 8 bits.
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
                let a = s[ch] * factor(sf, s, d, constant, ch);
                let b = d[ch] * factor(df, s, d, constant, ch);
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

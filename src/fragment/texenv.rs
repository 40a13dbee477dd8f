//! The texture environment (section 3.8.13): each enabled unit combines the colour from the
//! previous unit (the primary colour for the first) with its texel, by the unit's mode, or by
//! the programmable `GL_COMBINE` functions (table 3.24, with ARB_texture_env_crossbar sources).

use crate::api::convert::{CombineFunc, CombineOperand, CombineSource, TexEnvMode};
use crate::state::texenv::{Combine, TexEnv};
use crate::texture::format::BaseFormat;

type Rgba = [f32; 4];

fn clamp01(v: f32) -> f32 {
    v.max(0.0).min(1.0)
}

/// Inputs a combiner may read besides the previous colour.
pub struct CombineInputs<'a> {
    pub primary: Rgba,
    /// Texel of every unit that has a complete enabled texture (`None` otherwise).
    pub texels: &'a [Option<Rgba>; 8],
}

/// Applies unit `unit`'s environment: `cf` is the incoming colour, `ct` the unit's texel,
/// `base` its base internal format (tables 3.22 and 3.23).
pub fn apply(
    env: &TexEnv,
    base: BaseFormat,
    _unit: usize,
    cf: Rgba,
    ct: Rgba,
    inputs: &CombineInputs,
) -> Rgba {
    use BaseFormat::*;
    let (has_color, has_alpha) = match base {
        Alpha => (false, true),
        Luminance | Rgb | DepthComponent | Red | Rg => (true, false),
        LuminanceAlpha | Rgba => (true, true),
        Intensity => (true, true),
    };
    let cc = env.color;
    let rgb = |f: &dyn Fn(usize) -> f32| [f(0), f(1), f(2)];
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
                rgb(&|i| cf[i] * ct[i])
            } else {
                rgb(&|i| cf[i])
            };
            let a = if has_alpha { cf[3] * ct[3] } else { cf[3] };
            [c[0], c[1], c[2], a]
        }
        TexEnvMode::Decal => match base {
            Rgb => [ct[0], ct[1], ct[2], cf[3]],
            Rgba => {
                let c = rgb(&|i| cf[i] * (1.0 - ct[3]) + ct[i] * ct[3]);
                [c[0], c[1], c[2], cf[3]]
            }
            // Undefined by the specification for other formats: the colour passes unchanged.
            _ => cf,
        },
        TexEnvMode::Blend => {
            let c = if has_color {
                rgb(&|i| cf[i] * (1.0 - ct[i]) + cc[i] * ct[i])
            } else {
                rgb(&|i| cf[i])
            };
            let a = match base {
                Intensity => cf[3] * (1.0 - ct[3]) + cc[3] * ct[3],
                _ if has_alpha => cf[3] * ct[3],
                _ => cf[3],
            };
            [c[0], c[1], c[2], a]
        }
        TexEnvMode::Add => {
            let c = if has_color {
                rgb(&|i| clamp01(cf[i] + ct[i]))
            } else {
                rgb(&|i| cf[i])
            };
            let a = match base {
                Intensity => clamp01(cf[3] + ct[3]),
                _ if has_alpha => cf[3] * ct[3],
                _ => cf[3],
            };
            [c[0], c[1], c[2], a]
        }
        TexEnvMode::Combine => combine(&env.combine, false, cf, ct, cc, inputs),
        TexEnvMode::Combine4 => combine(&env.combine, true, cf, ct, cc, inputs),
    }
}

fn source(s: CombineSource, cf: Rgba, ct: Rgba, cc: Rgba, inputs: &CombineInputs) -> Rgba {
    match s {
        CombineSource::Texture => ct,
        // ARB_texture_env_crossbar: a unit without a complete enabled texture reads as the
        // incoming colour (what Mesa does; the extension leaves it undefined).
        CombineSource::TextureUnit(u) => inputs.texels[u as usize].unwrap_or(cf),
        CombineSource::Constant => cc,
        CombineSource::PrimaryColor => inputs.primary,
        CombineSource::Previous => cf,
        CombineSource::Zero => [0.0; 4],
    }
}

fn operand_rgb(op: CombineOperand, v: Rgba) -> [f32; 3] {
    match op {
        CombineOperand::SrcColor => [v[0], v[1], v[2]],
        CombineOperand::OneMinusSrcColor => [1.0 - v[0], 1.0 - v[1], 1.0 - v[2]],
        CombineOperand::SrcAlpha => [v[3]; 3],
        CombineOperand::OneMinusSrcAlpha => [1.0 - v[3]; 3],
    }
}

fn operand_alpha(op: CombineOperand, v: Rgba) -> f32 {
    match op {
        CombineOperand::SrcAlpha | CombineOperand::SrcColor => v[3],
        CombineOperand::OneMinusSrcAlpha | CombineOperand::OneMinusSrcColor => 1.0 - v[3],
    }
}

fn combine_fn(f: CombineFunc, a: f32, b: f32, c: f32) -> f32 {
    match f {
        CombineFunc::Replace => a,
        CombineFunc::Modulate => a * b,
        CombineFunc::Add => a + b,
        CombineFunc::AddSigned => a + b - 0.5,
        CombineFunc::Interpolate => a * c + b * (1.0 - c),
        CombineFunc::Subtract => a - b,
        // DOT3 is handled per vector.
        CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => a,
    }
}

/// `GL_COMBINE` (table 3.24): arguments from the sources through the operands, the function,
/// then the scale, then a clamp to [0, 1]. With `four` (NV_texture_env_combine4's
/// `GL_COMBINE4_NV`), `ADD` is `a0 a1 + a2 a3` and `ADD_SIGNED` is `a0 a1 + a2 a3 - 1/2`; the
/// other functions are those of `GL_COMBINE`.
pub fn combine(
    k: &Combine,
    four: bool,
    cf: Rgba,
    ct: Rgba,
    cc: Rgba,
    inputs: &CombineInputs,
) -> Rgba {
    let arg_rgb = |i: usize| operand_rgb(k.op_rgb[i], source(k.src_rgb[i], cf, ct, cc, inputs));
    let arg_a = |i: usize| operand_alpha(k.op_alpha[i], source(k.src_alpha[i], cf, ct, cc, inputs));
    let (a0, a1, a2) = (arg_rgb(0), arg_rgb(1), arg_rgb(2));
    let rs = k.rgb_scale as f32;
    let as_ = k.alpha_scale as f32;
    let mut out = [0.0; 4];
    match k.rgb {
        CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => {
            let d = 4.0
                * ((a0[0] - 0.5) * (a1[0] - 0.5)
                    + (a0[1] - 0.5) * (a1[1] - 0.5)
                    + (a0[2] - 0.5) * (a1[2] - 0.5));
            let v = clamp01(d * rs);
            out = [v, v, v, 0.0];
            if k.rgb == CombineFunc::Dot3Rgba {
                // The dot product also replaces alpha (the alpha function is ignored); like
                // every alpha result it is then multiplied by ALPHA_SCALE (section 3.8.13: "the
                // RGB and ALPHA results ... are multiplied by RGB_SCALE and ALPHA_SCALE,
                // respectively"), which is what Mesa does too.
                out[3] = clamp01(d * as_);
                return out;
            }
        }
        f @ (CombineFunc::Add | CombineFunc::AddSigned) if four => {
            let a3 = arg_rgb(3);
            let bias = if f == CombineFunc::AddSigned {
                0.5
            } else {
                0.0
            };
            for i in 0..3 {
                out[i] = clamp01((a0[i] * a1[i] + a2[i] * a3[i] - bias) * rs);
            }
        }
        f => {
            for i in 0..3 {
                out[i] = clamp01(combine_fn(f, a0[i], a1[i], a2[i]) * rs);
            }
        }
    }
    out[3] = match k.alpha {
        f @ (CombineFunc::Add | CombineFunc::AddSigned) if four => {
            let bias = if f == CombineFunc::AddSigned {
                0.5
            } else {
                0.0
            };
            clamp01((arg_a(0) * arg_a(1) + arg_a(2) * arg_a(3) - bias) * as_)
        }
        f => clamp01(combine_fn(f, arg_a(0), arg_a(1), arg_a(2)) * as_),
    };
    out
}

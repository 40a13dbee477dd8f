//! The accumulation buffer (section 4.2.4): `glAccum`, `glClearAccum` and its clear.
//!
//! Each channel is a signed 16-bit fixed-point value over [-1, 1] (`v * 32767`, rounded to
//! nearest; results outside [-1, 1] saturate, which is where the spec leaves overflow
//! undefined). `glAccum` works immediately on the flushed framebuffer, inside the scissor box.

use super::Context;
use crate::common::fixed::color_to_u8;
use crate::common::values::AccumOp;
use crate::gl::convert;
use crate::gl::enums::*;

/// Scale of the fixed-point accumulation values.
const ACCUM_ONE: f32 = 32767.0;

/// `x.round()` (halves away from zero) by truncation through an integer, without the libm
/// call `round` compiles to on the baseline x86-64 target (16 % of an accumulation frame). A
/// negative result that rounds to zero comes out as +0 instead of -0, which the conversion
/// to i16 does not see.
#[inline]
fn round_half_away(x: f32) -> f32 {
    // NaN, the infinities and |x| >= 2^23 are whole numbers (or not numbers) already.
    if !(x.abs() < 8_388_608.0) {
        return x;
    }
    let t = x as i32 as f32;
    // The fraction, exactly: x and its truncation share their leading bits.
    let d = x - t;
    if d >= 0.5 {
        t + 1.0
    } else if d <= -0.5 {
        t - 1.0
    } else {
        t
    }
}

#[inline]
fn to_fixed(v: f32) -> i16 {
    let v = round_half_away(v * ACCUM_ONE);
    // NaN (from a NaN value argument) becomes 0.
    if v.is_nan() {
        0
    } else {
        v.clamp(-ACCUM_ONE, ACCUM_ONE) as i16
    }
}

#[inline]
fn from_fixed(v: i16) -> f32 {
    v as f32 / ACCUM_ONE
}

impl Context {
    pub(crate) fn clear_accum(&mut self, r: GLfloat, g: GLfloat, b: GLfloat, a: GLfloat) {
        self.clear_values.accum =
            [r, g, b, a].map(|c| if c.is_nan() { 0.0 } else { c.clamp(-1.0, 1.0) });
    }

    /// `glClear(GL_ACCUM_BUFFER_BIT)`.
    pub(crate) fn clear_accum_buffer(&mut self) {
        if self.framebuffer.accum.is_empty() {
            return;
        }
        let rect = self.scissored_window();
        let value = self.clear_values.accum.map(to_fixed);
        let w = self.framebuffer.width as usize;
        for y in rect.y0..rect.y1 {
            let row = y as usize * w;
            self.framebuffer.accum[row + rect.x0 as usize..row + rect.x1 as usize].fill(value);
        }
    }

    pub(crate) fn accum(&mut self, op: GLenum, value: GLfloat) {
        let Some(op) = convert::accum_op(op) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if self.framebuffer.accum.is_empty() {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        self.flush_scene();
        let rect = self.scissored_window();
        let mask = self.fragment_ops.color_mask;
        let w = self.framebuffer.width as usize;
        for y in rect.y0..rect.y1 {
            for x in rect.x0..rect.x1 {
                let i = y as usize * w + x as usize;
                let a = self.framebuffer.accum[i];
                match op {
                    AccumOp::Accum | AccumOp::Load => {
                        let c = self.framebuffer.color_at(x, y).unwrap_or([0; 4]);
                        let mut out = [0i16; 4];
                        for k in 0..4 {
                            let add = value * (c[k] as f32 / 255.0);
                            let base = if op == AccumOp::Accum {
                                from_fixed(a[k])
                            } else {
                                0.0
                            };
                            out[k] = to_fixed(base + add);
                        }
                        self.framebuffer.accum[i] = out;
                    }
                    AccumOp::Mult => {
                        self.framebuffer.accum[i] = a.map(|v| to_fixed(from_fixed(v) * value));
                    }
                    AccumOp::Add => {
                        self.framebuffer.accum[i] = a.map(|v| to_fixed(from_fixed(v) + value));
                    }
                    AccumOp::Return => {
                        // Only the scissor and the colour mask apply (section 4.2.4).
                        if let Some(dst) = self.framebuffer.color_mut(x, y) {
                            for k in 0..4 {
                                if mask[k] {
                                    dst[k] = color_to_u8(from_fixed(a[k]) * value);
                                }
                            }
                        }
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{round_half_away, to_fixed, ACCUM_ONE};

    /// `round_half_away` is `f32::round` (up to the sign of zero) on every f32 from -2^24 to
    /// 2^24 near the halves and whole numbers, on a sweep of all magnitudes, and on NaN and the
    /// infinities; `to_fixed` therefore stores what `round` would.
    #[test]
    fn round_half_away_is_round() {
        let mut xs = vec![f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 0.0, -0.0];
        for k in -70_000i32..70_000 {
            for off in [-0.5f32, 0.0, 0.5] {
                let x = k as f32 + off;
                xs.extend([
                    x,
                    f32::from_bits(x.to_bits() + 1),
                    f32::from_bits(x.to_bits().wrapping_sub(1)),
                ]);
            }
        }
        let mut b = 1u32;
        while b < 0x7F80_0000 {
            xs.extend([f32::from_bits(b), -f32::from_bits(b)]);
            b += 0x1_2345;
        }
        for x in xs {
            let (got, want) = (round_half_away(x), x.round());
            assert!(
                got == want || (got.is_nan() && want.is_nan()),
                "{x:e}: {got:e} vs {want:e}"
            );
            let v = x / ACCUM_ONE;
            let old = {
                let r = (v * ACCUM_ONE).round();
                if r.is_nan() {
                    0
                } else {
                    r.clamp(-ACCUM_ONE, ACCUM_ONE) as i16
                }
            };
            assert_eq!(to_fixed(v), old, "{v:e}");
        }
    }
}

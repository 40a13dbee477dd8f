//! The accumulation buffer (section 4.2.4): `glAccum`, `glClearAccum` and its clear.
//!
//! Each channel is a signed 16-bit fixed-point value over [-1, 1] (`v * 32767`, rounded to
//! nearest; results outside [-1, 1] saturate, which is where the spec leaves overflow
//! undefined). `glAccum` works immediately on the flushed framebuffer, inside the scissor box.

use super::Context;
use crate::api::convert;
use crate::api::enums::*;
use crate::common::fixed::color_to_u8;
use crate::common::values::AccumOp;

/// Scale of the fixed-point accumulation values.
const ACCUM_ONE: f32 = 32767.0;

#[inline]
fn to_fixed(v: f32) -> i16 {
    let v = (v * ACCUM_ONE).round();
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

//! Entry points of the per-fragment operations (section 4.1): alpha test, stencil test,
//! blending and logic operation. Depth and masks live with the framebuffer controls.

use super::{clamp01, Context};
use crate::gl::convert;
use crate::gl::enums::*;

impl Context {
    pub(crate) fn alpha_func(&mut self, func: GLenum, ref_: GLclampf) {
        let Some(f) = convert::compare_func(func) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.fragment_ops.alpha_func = f;
        self.fragment_ops.alpha_ref = clamp01(ref_ as f64) as f32;
        self.invalidate();
    }

    pub(crate) fn stencil_func(&mut self, func: GLenum, ref_: GLint, mask: GLuint) {
        let Some(f) = convert::compare_func(func) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let ops = &mut self.fragment_ops;
        ops.stencil_func = f;
        ops.stencil_ref = ref_;
        ops.stencil_value_mask = mask;
        self.invalidate();
    }

    pub(crate) fn stencil_op(&mut self, fail: GLenum, zfail: GLenum, zpass: GLenum) {
        let (Some(a), Some(b), Some(c)) = (
            convert::stencil_op(fail),
            convert::stencil_op(zfail),
            convert::stencil_op(zpass),
        ) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let ops = &mut self.fragment_ops;
        ops.stencil_fail = a;
        ops.stencil_depth_fail = b;
        ops.stencil_depth_pass = c;
        self.invalidate();
    }

    pub(crate) fn blend_func(&mut self, sfactor: GLenum, dfactor: GLenum) {
        self.blend_func_separate(sfactor, dfactor, sfactor, dfactor);
    }

    pub(crate) fn blend_func_separate(
        &mut self,
        sfactor_rgb: GLenum,
        dfactor_rgb: GLenum,
        sfactor_alpha: GLenum,
        dfactor_alpha: GLenum,
    ) {
        let (Some(sr), Some(dr), Some(sa), Some(da)) = (
            convert::blend_factor(sfactor_rgb, true),
            convert::blend_factor(dfactor_rgb, false),
            convert::blend_factor(sfactor_alpha, true),
            convert::blend_factor(dfactor_alpha, false),
        ) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let ops = &mut self.fragment_ops;
        ops.blend_src_rgb = sr;
        ops.blend_dst_rgb = dr;
        ops.blend_src_alpha = sa;
        ops.blend_dst_alpha = da;
        self.invalidate();
    }

    pub(crate) fn blend_color(&mut self, r: GLclampf, g: GLclampf, b: GLclampf, a: GLclampf) {
        self.fragment_ops.blend_color = [r, g, b, a].map(|c| clamp01(c as f64) as f32);
        self.invalidate();
    }

    pub(crate) fn blend_equation(&mut self, mode: GLenum) {
        let Some(m) = convert::blend_equation(mode) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.fragment_ops.blend_equation = m;
        self.fragment_ops.blend_equation_alpha = m;
        self.invalidate();
    }

    /// EXT_blend_equation_separate (core in GL 2.0 as `glBlendEquationSeparate`).
    pub(crate) fn blend_equation_separate_ext(&mut self, mode_rgb: GLenum, mode_alpha: GLenum) {
        let (Some(rgb), Some(alpha)) = (
            convert::blend_equation(mode_rgb),
            convert::blend_equation(mode_alpha),
        ) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.fragment_ops.blend_equation = rgb;
        self.fragment_ops.blend_equation_alpha = alpha;
        self.invalidate();
    }

    pub(crate) fn logic_op(&mut self, opcode: GLenum) {
        let Some(op) = convert::logic_op(opcode) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.fragment_ops.logic_op = op;
        self.invalidate();
    }
}

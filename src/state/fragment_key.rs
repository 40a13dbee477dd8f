//! The fragment key and uniforms of a draw, built from the per-fragment state tables
//! (`fragment::key` defines them; the state machine fills them in).

use super::tables::FragmentOpsState;
use crate::common::values::{BlendEquation, BlendFactor, CompareFunc, LogicOp, StencilOp};
use crate::fragment::key::*;

impl FragmentKey {
    /// The key for the current per-fragment state. Simplifications (sections 4.1.3-4.1.10):
    /// a disabled test passes everything; without a depth or stencil buffer its test always
    /// passes; `ALWAYS` without writes is no test; ONE/ZERO `FUNC_ADD` blending and the COPY
    /// logic op are plain replacement.
    pub fn from_state(
        ops: &FragmentOpsState,
        has_depth_buffer: bool,
        has_stencil_buffer: bool,
        color_sum: bool,
    ) -> FragmentKey {
        let enabled = ops.depth_test && has_depth_buffer;
        let mut depth_func = enabled.then_some(ops.depth_func);
        let depth_write = enabled && ops.depth_mask;
        if depth_func == Some(CompareFunc::Always) && !depth_write {
            depth_func = None;
        }
        let alpha_func =
            (ops.alpha_test && ops.alpha_func != CompareFunc::Always).then_some(ops.alpha_func);
        let mut stencil = (ops.stencil_test && has_stencil_buffer).then_some(StencilKey {
            func: ops.stencil_func,
            fail: ops.stencil_fail,
            depth_fail: ops.stencil_depth_fail,
            depth_pass: ops.stencil_depth_pass,
        });
        if let Some(s) = stencil {
            let keeps = [s.fail, s.depth_fail, s.depth_pass]
                .iter()
                .all(|&o| o == StencilOp::Keep);
            if s.func == CompareFunc::Always && (keeps || ops.stencil_writemask & 0xFF == 0) {
                stencil = None;
            }
        }
        let logic_op =
            (ops.color_logic_op && ops.logic_op != LogicOp::Copy).then_some(ops.logic_op);
        let blend = BlendKey {
            equation: ops.blend_equation,
            equation_alpha: ops.blend_equation_alpha,
            src_rgb: ops.blend_src_rgb,
            dst_rgb: ops.blend_dst_rgb,
            src_alpha: ops.blend_src_alpha,
            dst_alpha: ops.blend_dst_alpha,
        };
        let replaces = blend.equation == BlendEquation::Add
            && blend.equation_alpha == BlendEquation::Add
            && blend.src_rgb == BlendFactor::One
            && blend.src_alpha == BlendFactor::One
            && blend.dst_rgb == BlendFactor::Zero
            && blend.dst_alpha == BlendFactor::Zero;
        let blend = (ops.blend && !ops.color_logic_op && !replaces).then_some(blend);
        FragmentKey {
            alpha_func,
            stencil,
            depth_func,
            depth_write,
            blend,
            logic_op: if ops.color_logic_op { logic_op } else { None },
            color_mask: ops.color_mask,
            color_sum,
            texturing: false,
            fast_texture: None,
            simd_units: false,
            byte_env: false,
            fog: None,
            count_samples: false,
            alpha_to_coverage: false,
            alpha_to_one: false,
        }
    }
}

impl Uniforms {
    pub fn from_state(ops: &FragmentOpsState, stencil_bits: u32) -> Uniforms {
        let max = if stencil_bits >= 8 {
            255
        } else {
            (1i32 << stencil_bits) - 1
        };
        Uniforms {
            alpha_ref: ops.alpha_ref,
            stencil_ref: ops.stencil_ref.clamp(0, max.max(0)) as u8,
            stencil_value_mask: (ops.stencil_value_mask & max.max(0) as u32) as u8,
            stencil_write_mask: (ops.stencil_writemask & max.max(0) as u32) as u8,
            blend_color: ops.blend_color,
            coverage_alpha_ref: 0.0,
        }
    }
}

//! `FragmentKey`: the static fragment state of a draw (`Copy + Eq + Hash`), simplified before
//! a span function is chosen for it; `Uniforms`: the per-draw values (references, masks,
//! constant colour) that change no code path.

use crate::common::values::{BlendEquation, BlendFactor, CompareFunc, FogMode, LogicOp, StencilOp};
use crate::state::tables::FragmentOpsState;

/// The stencil test and its three actions.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct StencilKey {
    pub func: CompareFunc,
    pub fail: StencilOp,
    pub depth_fail: StencilOp,
    pub depth_pass: StencilOp,
}

/// Blending (section 4.1.8): one equation for RGB and alpha in GL 1.5, separate factors.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BlendKey {
    /// The RGB equation (`glBlendEquation` sets both).
    pub equation: BlendEquation,
    /// The alpha equation (EXT_blend_equation_separate).
    pub equation_alpha: BlendEquation,
    pub src_rgb: BlendFactor,
    pub dst_rgb: BlendFactor,
    pub src_alpha: BlendFactor,
    pub dst_alpha: BlendFactor,
}

/// The texel layout of a texture on the fast 2D path (unsigned bytes, no border).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FastTexture {
    Rgb,
    Rgba,
}

/// What the fragment stage must do, with redundant state folded away.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FragmentKey {
    /// The alpha test, or `None` when it passes everything.
    pub alpha_func: Option<CompareFunc>,
    /// The stencil test, or `None` when disabled, absent, or unable to change anything.
    pub stencil: Option<StencilKey>,
    /// The depth test, or `None` when it cannot reject anything and writes nothing.
    pub depth_func: Option<CompareFunc>,
    /// Whether passing fragments write depth.
    pub depth_write: bool,
    /// Blending, or `None` for plain replacement.
    pub blend: Option<BlendKey>,
    /// The logic operation, or `None` (COPY, or disabled). Takes precedence over blending.
    pub logic_op: Option<LogicOp>,
    /// Per-channel colour write enables (R, G, B, A).
    pub color_mask: [bool; 4],
    /// Add the secondary colour after texturing (section 3.9).
    pub color_sum: bool,
    /// At least one texture unit applies (the units themselves are in the `DrawState`).
    pub texturing: bool,
    /// Texturing is one unit that the fast 2D sampler handles
    /// (`BoundTexture::fast_2d`) under a `REPLACE` or `MODULATE` environment, with texels of
    /// this base format.
    pub fast_texture: Option<FastTexture>,
    /// Every texture unit may be sampled eight pixels at a time
    /// (`BoundTexture::simd_2d`): the general path's `span_sampled` form applies.
    pub simd_units: bool,
    /// Fog, after the colour sum (parameters in the `DrawState`).
    pub fog: Option<FogMode>,
    /// An occlusion query is active: count the fragments that pass the depth and stencil
    /// tests (only the general path counts, so draws without a query pay nothing).
    pub count_samples: bool,
}

/// Per-draw values read by the fragment stage.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Uniforms {
    pub alpha_ref: f32,
    /// Stencil reference clamped to the stencil range.
    pub stencil_ref: u8,
    pub stencil_value_mask: u8,
    pub stencil_write_mask: u8,
    pub blend_color: [f32; 4],
}

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
            fog: None,
            count_samples: false,
        }
    }

    /// True when no fragment can change any buffer (the draw can be dropped).
    pub fn writes_nothing(&self) -> bool {
        !self.depth_write
            && self.color_mask == [false; 4]
            && self.stencil.is_none()
            && !self.count_samples
    }

    /// True when only the depth test and colour mask apply (the specialised fast paths).
    pub fn is_simple(&self) -> bool {
        self.alpha_func.is_none()
            && self.stencil.is_none()
            && self.blend.is_none()
            && self.logic_op.is_none()
            && !self.color_sum
            && !self.texturing
            && self.fog.is_none()
            && !self.count_samples
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
        }
    }
}

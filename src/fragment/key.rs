//! `FragmentKey`: the static fragment state of a draw (`Copy + Eq + Hash`), simplified before
//! a span function is chosen for it; `Uniforms`: the per-draw values (references, masks,
//! constant colour) that change no code path.

use crate::common::values::{BlendEquation, BlendFactor, CompareFunc, FogMode, LogicOp, StencilOp};

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
    /// At least one texture unit applies (the units themselves are in the `FragmentDraw`).
    pub texturing: bool,
    /// Texturing is one unit that the fast 2D sampler handles
    /// (`BoundTexture::fast_2d`) under a `REPLACE` or `MODULATE` environment, with texels of
    /// this base format.
    pub fast_texture: Option<FastTexture>,
    /// Every texture unit may be sampled eight pixels at a time
    /// (`BoundTexture::simd_2d`): the general path's `span_sampled` form applies.
    pub simd_units: bool,
    /// The texture environment runs on bytes where the primary colour allows
    /// (`fragment::bytenv::applies`; the eight-lane sampled route's blocks).
    pub byte_env: bool,
    /// Fog, after the colour sum (parameters in the `FragmentDraw`).
    pub fog: Option<FogMode>,
    /// An occlusion query is active: count the fragments that pass the depth and stencil
    /// tests (only the general path counts, so draws without a query pay nothing).
    pub count_samples: bool,
    /// GL_SAMPLE_ALPHA_TO_COVERAGE on a multisample buffer (section 4.1.3): a fragment of
    /// the sample pass whose threshold is `Uniforms::coverage_alpha_ref` passes only with a
    /// greater alpha (general path only).
    pub alpha_to_coverage: bool,
    /// GL_SAMPLE_ALPHA_TO_ONE on a multisample buffer: alpha becomes 1 before the alpha test.
    pub alpha_to_one: bool,
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
    /// The alpha a fragment must exceed to cover this sample pass's sample under
    /// `FragmentKey::alpha_to_coverage`: sample `s` of `n` is covered when alpha > s / n.
    pub coverage_alpha_ref: f32,
}

impl FragmentKey {
    /// True when no fragment can change any buffer (the draw can be dropped).
    pub fn writes_nothing(&self) -> bool {
        !self.depth_write
            && self.color_mask == [false; 4]
            && self.stencil.is_none()
            && !self.count_samples
    }

    /// True when a fragment only has its colour converted to bytes and stored: no
    /// texturing, colour sum, fog, alpha, stencil or depth test, no depth write, blending,
    /// logic op or occlusion count, and every channel written (pixel rectangles then store
    /// their colours directly, `raster::pixels`).
    pub fn stores_color_only(&self) -> bool {
        self.is_simple()
            && self.depth_func.is_none()
            && !self.depth_write
            && self.color_mask == [true; 4]
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
            && !self.alpha_to_coverage
            && !self.alpha_to_one
    }
}

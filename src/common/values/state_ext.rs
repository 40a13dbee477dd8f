//! Typed values of the server attribute stack, occlusion queries, multisample state,
//! selection and feedback (part of `values`).

/// The attribute groups of a `glPushAttrib` mask (table 6.x "attribute" column). Unknown bits
/// are ignored, as `GL_ALL_ATTRIB_BITS` sets them all.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AttribGroups {
    pub current: bool,
    pub point: bool,
    pub line: bool,
    pub polygon: bool,
    pub polygon_stipple: bool,
    pub pixel_mode: bool,
    pub lighting: bool,
    pub fog: bool,
    pub depth_buffer: bool,
    pub accum_buffer: bool,
    pub stencil_buffer: bool,
    pub viewport: bool,
    pub transform: bool,
    pub enable: bool,
    pub color_buffer: bool,
    pub hint: bool,
    pub eval: bool,
    pub list: bool,
    pub texture: bool,
    pub scissor: bool,
    pub multisample: bool,
}

/// The multisample enables (GL 1.3, section 3.2.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MultisampleCap {
    Multisample,
    AlphaToCoverage,
    AlphaToOne,
    Coverage,
}

/// `glGet*` queries of this module's state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StateExtQuery {
    AttribStackDepth,
    SampleCoverageValue,
    SampleCoverageInvert,
    RenderMode,
    NameStackDepth,
    MaxNameStackDepth,
    FeedbackBufferSize,
    FeedbackBufferType,
    SelectionBufferSize,
    /// `GL_TEXTURE_BINDING_*` of the active unit.
    TextureBinding(super::TextureTarget),
    /// ARB_sampler_objects' `GL_SAMPLER_BINDING` of the active unit.
    SamplerBinding,
    /// `GL_MAX_TEXTURE_SIZE`, `GL_MAX_3D_TEXTURE_SIZE`, `GL_MAX_CUBE_MAP_TEXTURE_SIZE`,
    /// `GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB`: the largest side for the target.
    MaxTextureSize(super::TextureTarget),
    MaxTextureLodBias,
    MaxTextureMaxAnisotropy,
    NumCompressedTextureFormats,
    CompressedTextureFormats,
}

/// `glGetQueryiv` parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QueryParam {
    CurrentQuery,
    CounterBits,
}

/// `glGetQueryObject*v` parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QueryObjectParam {
    Result,
    ResultAvailable,
}

/// `glRenderMode` modes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RenderMode {
    #[default]
    Render,
    Select,
    Feedback,
}

/// `glFeedbackBuffer` types (table 5.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FeedbackType {
    T2D,
    T3D,
    T3DColor,
    T3DColorTexture,
    T4DColorTexture,
}

/// The feedback tokens (table 5.3), as the float values written to the buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FeedbackToken {
    Point,
    Line,
    LineReset,
    Polygon,
    Bitmap,
    DrawPixel,
    CopyPixel,
    PassThrough,
}

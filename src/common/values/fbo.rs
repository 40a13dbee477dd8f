//! Typed values of EXT_framebuffer_object (attachment points, query names, renderbuffer
//! formats).

/// A framebuffer attachment point (table 1.nnn of the extension). tilegl has one colour
/// attachment point (`GL_MAX_COLOR_ATTACHMENTS_EXT` is 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FboAttachment {
    Color0,
    Depth,
    Stencil,
    /// ARB_framebuffer_object's `GL_DEPTH_STENCIL_ATTACHMENT`: the depth and the stencil
    /// points at once.
    DepthStencil,
}

/// `glGetFramebufferAttachmentParameterivEXT` parameter names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AttachmentParam {
    ObjectType,
    ObjectName,
    TextureLevel,
    CubeMapFace,
    /// `GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_3D_ZOFFSET_EXT` = ARB's `..._TEXTURE_LAYER`.
    ZOffset,
    /// ARB_framebuffer_object's queries of the attached image's format (section 6.1.3).
    ColorEncoding,
    ComponentType,
    RedSize,
    GreenSize,
    BlueSize,
    AlphaSize,
    DepthSize,
    StencilSize,
}

/// `glGetRenderbufferParameterivEXT` parameter names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RenderbufferParam {
    Width,
    Height,
    InternalFormat,
    RedSize,
    GreenSize,
    BlueSize,
    AlphaSize,
    DepthSize,
    StencilSize,
    /// ARB_framebuffer_object's `GL_RENDERBUFFER_SAMPLES` (always 0: `GL_MAX_SAMPLES` is 0).
    Samples,
}

/// What a renderbuffer's internal format stores (section 4.4.2.1): colour (with or without
/// alpha), depth of some bits, stencil, or packed depth-stencil (EXT_packed_depth_stencil).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RenderbufferKind {
    Color { alpha: bool },
    Depth { bits: u32 },
    Stencil,
    DepthStencil,
}

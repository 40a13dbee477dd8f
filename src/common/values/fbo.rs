//! Typed values of EXT_framebuffer_object (attachment points, query names, renderbuffer
//! formats).

/// A framebuffer attachment point (table 1.nnn of the extension). tilegl has one colour
/// attachment point (`GL_MAX_COLOR_ATTACHMENTS_EXT` is 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FboAttachment {
    Color0,
    Depth,
    Stencil,
}

/// `glGetFramebufferAttachmentParameterivEXT` parameter names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AttachmentParam {
    ObjectType,
    ObjectName,
    TextureLevel,
    CubeMapFace,
    ZOffset,
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

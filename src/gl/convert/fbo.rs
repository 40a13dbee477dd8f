//! EXT_framebuffer_object's enums.

use crate::common::values::*;

use super::super::enums::*;
use super::super::types::GLenum;

/// `GL_FRAMEBUFFER_EXT` and EXT_framebuffer_blit's `GL_READ_FRAMEBUFFER_EXT` and
/// `GL_DRAW_FRAMEBUFFER_EXT`.
pub fn is_framebuffer_target(e: GLenum) -> bool {
    matches!(
        e,
        GL_FRAMEBUFFER_EXT | GL_READ_FRAMEBUFFER_EXT | GL_DRAW_FRAMEBUFFER_EXT
    )
}

/// `GL_RENDERBUFFER_EXT`, the one renderbuffer target.
pub fn is_renderbuffer_target(e: GLenum) -> bool {
    e == GL_RENDERBUFFER_EXT
}

/// An attachment point tilegl has (`GL_MAX_COLOR_ATTACHMENTS_EXT` is 1).
pub fn fbo_attachment(e: GLenum) -> Option<FboAttachment> {
    Some(match e {
        GL_COLOR_ATTACHMENT0_EXT => FboAttachment::Color0,
        GL_DEPTH_ATTACHMENT_EXT => FboAttachment::Depth,
        GL_STENCIL_ATTACHMENT_EXT => FboAttachment::Stencil,
        GL_DEPTH_STENCIL_ATTACHMENT => FboAttachment::DepthStencil,
        _ => return None,
    })
}

/// The index n of `GL_COLOR_ATTACHMENTn_EXT` (0..=15), for `glDrawBuffer`/`glReadBuffer`.
pub fn color_attachment_index(e: GLenum) -> Option<u32> {
    (GL_COLOR_ATTACHMENT0_EXT..=GL_COLOR_ATTACHMENT15_EXT)
        .contains(&e)
        .then(|| e - GL_COLOR_ATTACHMENT0_EXT)
}

pub fn attachment_param(e: GLenum) -> Option<AttachmentParam> {
    Some(match e {
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT => AttachmentParam::ObjectType,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT => AttachmentParam::ObjectName,
        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT => AttachmentParam::TextureLevel,
        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE_EXT => AttachmentParam::CubeMapFace,
        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_3D_ZOFFSET_EXT => AttachmentParam::ZOffset,
        GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING => AttachmentParam::ColorEncoding,
        GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE => AttachmentParam::ComponentType,
        GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE => AttachmentParam::RedSize,
        GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE => AttachmentParam::GreenSize,
        GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE => AttachmentParam::BlueSize,
        GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE => AttachmentParam::AlphaSize,
        GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE => AttachmentParam::DepthSize,
        GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE => AttachmentParam::StencilSize,
        _ => return None,
    })
}

pub fn renderbuffer_param(e: GLenum) -> Option<RenderbufferParam> {
    use RenderbufferParam::*;
    Some(match e {
        GL_RENDERBUFFER_WIDTH_EXT => Width,
        GL_RENDERBUFFER_HEIGHT_EXT => Height,
        GL_RENDERBUFFER_INTERNAL_FORMAT_EXT => InternalFormat,
        GL_RENDERBUFFER_RED_SIZE_EXT => RedSize,
        GL_RENDERBUFFER_GREEN_SIZE_EXT => GreenSize,
        GL_RENDERBUFFER_BLUE_SIZE_EXT => BlueSize,
        GL_RENDERBUFFER_ALPHA_SIZE_EXT => AlphaSize,
        GL_RENDERBUFFER_DEPTH_SIZE_EXT => DepthSize,
        GL_RENDERBUFFER_STENCIL_SIZE_EXT => StencilSize,
        GL_RENDERBUFFER_SAMPLES => Samples,
        _ => return None,
    })
}

/// What `glRenderbufferStorageEXT(internalformat)` stores: RGB, RGBA and their sized formats
/// of table 3.16, the depth formats, the stencil formats of table 2.nnn and
/// EXT_packed_depth_stencil's; anything else is `None` (`GL_INVALID_ENUM`).
pub fn renderbuffer_kind(e: GLenum) -> Option<RenderbufferKind> {
    use RenderbufferKind::*;
    Some(match e {
        GL_RGB | GL_R3_G3_B2 | GL_RGB4 | GL_RGB5 | GL_RGB8 | GL_RGB10 | GL_RGB12 | GL_RGB16 => {
            Color { alpha: false }
        }
        GL_RGBA | GL_RGBA2 | GL_RGBA4 | GL_RGB5_A1 | GL_RGBA8 | GL_RGB10_A2 | GL_RGBA12
        | GL_RGBA16 => Color { alpha: true },
        GL_DEPTH_COMPONENT16 => Depth { bits: 16 },
        GL_DEPTH_COMPONENT | GL_DEPTH_COMPONENT24 => Depth { bits: 24 },
        GL_DEPTH_COMPONENT32 => Depth { bits: 32 },
        GL_STENCIL_INDEX
        | GL_STENCIL_INDEX1_EXT
        | GL_STENCIL_INDEX4_EXT
        | GL_STENCIL_INDEX8_EXT
        | GL_STENCIL_INDEX16_EXT => Stencil,
        GL_DEPTH_STENCIL_EXT | GL_DEPTH24_STENCIL8_EXT => DepthStencil,
        _ => return None,
    })
}

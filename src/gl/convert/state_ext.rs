//! Enums of the server attribute stack (`glPushAttrib`), occlusion queries, multisample state,
//! selection and feedback.

use crate::common::values::*;

use super::super::enums::*;
use super::super::types::GLenum;

pub fn attrib_groups(mask: u32) -> AttribGroups {
    let has = |bit: u32| mask & bit != 0;
    AttribGroups {
        current: has(GL_CURRENT_BIT),
        point: has(GL_POINT_BIT),
        line: has(GL_LINE_BIT),
        polygon: has(GL_POLYGON_BIT),
        polygon_stipple: has(GL_POLYGON_STIPPLE_BIT),
        pixel_mode: has(GL_PIXEL_MODE_BIT),
        lighting: has(GL_LIGHTING_BIT),
        fog: has(GL_FOG_BIT),
        depth_buffer: has(GL_DEPTH_BUFFER_BIT),
        accum_buffer: has(GL_ACCUM_BUFFER_BIT),
        stencil_buffer: has(GL_STENCIL_BUFFER_BIT),
        viewport: has(GL_VIEWPORT_BIT),
        transform: has(GL_TRANSFORM_BIT),
        enable: has(GL_ENABLE_BIT),
        color_buffer: has(GL_COLOR_BUFFER_BIT),
        hint: has(GL_HINT_BIT),
        eval: has(GL_EVAL_BIT),
        list: has(GL_LIST_BIT),
        texture: has(GL_TEXTURE_BIT),
        scissor: has(GL_SCISSOR_BIT),
        multisample: has(GL_MULTISAMPLE_BIT),
    }
}

pub fn multisample_cap(e: GLenum) -> Option<MultisampleCap> {
    Some(match e {
        GL_MULTISAMPLE => MultisampleCap::Multisample,
        GL_SAMPLE_ALPHA_TO_COVERAGE => MultisampleCap::AlphaToCoverage,
        GL_SAMPLE_ALPHA_TO_ONE => MultisampleCap::AlphaToOne,
        GL_SAMPLE_COVERAGE => MultisampleCap::Coverage,
        _ => return None,
    })
}

pub fn state_ext_query(e: GLenum) -> Option<StateExtQuery> {
    use StateExtQuery::*;
    Some(match e {
        GL_ATTRIB_STACK_DEPTH => AttribStackDepth,
        GL_SAMPLE_COVERAGE_VALUE => SampleCoverageValue,
        GL_SAMPLE_COVERAGE_INVERT => SampleCoverageInvert,
        GL_RENDER_MODE => RenderMode,
        GL_NAME_STACK_DEPTH => NameStackDepth,
        GL_MAX_NAME_STACK_DEPTH => MaxNameStackDepth,
        GL_FEEDBACK_BUFFER_SIZE => FeedbackBufferSize,
        GL_FEEDBACK_BUFFER_TYPE => FeedbackBufferType,
        GL_SELECTION_BUFFER_SIZE => SelectionBufferSize,
        GL_TEXTURE_BINDING_1D => TextureBinding(super::TextureTarget::T1D),
        GL_TEXTURE_BINDING_2D => TextureBinding(super::TextureTarget::T2D),
        GL_TEXTURE_BINDING_3D => TextureBinding(super::TextureTarget::T3D),
        GL_TEXTURE_BINDING_CUBE_MAP => TextureBinding(super::TextureTarget::CubeMap),
        GL_TEXTURE_BINDING_RECTANGLE_ARB => TextureBinding(super::TextureTarget::Rectangle),
        GL_SAMPLER_BINDING => SamplerBinding,
        GL_MAX_TEXTURE_SIZE => MaxTextureSize(super::TextureTarget::T2D),
        GL_MAX_3D_TEXTURE_SIZE => MaxTextureSize(super::TextureTarget::T3D),
        GL_MAX_CUBE_MAP_TEXTURE_SIZE => MaxTextureSize(super::TextureTarget::CubeMap),
        GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB => MaxTextureSize(super::TextureTarget::Rectangle),
        GL_MAX_TEXTURE_LOD_BIAS => MaxTextureLodBias,
        GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT => MaxTextureMaxAnisotropy,
        GL_NUM_COMPRESSED_TEXTURE_FORMATS => NumCompressedTextureFormats,
        GL_COMPRESSED_TEXTURE_FORMATS => CompressedTextureFormats,
        _ => return None,
    })
}

/// `glGetPointerv` names of the selection and feedback buffers.
pub fn render_buffer_pointer(e: GLenum) -> Option<RenderMode> {
    Some(match e {
        GL_SELECTION_BUFFER_POINTER => RenderMode::Select,
        GL_FEEDBACK_BUFFER_POINTER => RenderMode::Feedback,
        _ => return None,
    })
}

/// `glBeginQuery` targets: only `GL_SAMPLES_PASSED` in GL 1.5.
pub fn query_target(e: GLenum) -> Option<()> {
    (e == GL_SAMPLES_PASSED).then_some(())
}

pub fn query_param(e: GLenum) -> Option<QueryParam> {
    Some(match e {
        GL_CURRENT_QUERY => QueryParam::CurrentQuery,
        GL_QUERY_COUNTER_BITS => QueryParam::CounterBits,
        _ => return None,
    })
}

pub fn query_object_param(e: GLenum) -> Option<QueryObjectParam> {
    Some(match e {
        GL_QUERY_RESULT => QueryObjectParam::Result,
        GL_QUERY_RESULT_AVAILABLE => QueryObjectParam::ResultAvailable,
        _ => return None,
    })
}

pub fn render_mode(e: GLenum) -> Option<RenderMode> {
    Some(match e {
        GL_RENDER => RenderMode::Render,
        GL_SELECT => RenderMode::Select,
        GL_FEEDBACK => RenderMode::Feedback,
        _ => return None,
    })
}

impl RenderMode {
    pub fn to_gl(self) -> GLenum {
        match self {
            RenderMode::Render => GL_RENDER,
            RenderMode::Select => GL_SELECT,
            RenderMode::Feedback => GL_FEEDBACK,
        }
    }
}

pub fn feedback_type(e: GLenum) -> Option<FeedbackType> {
    Some(match e {
        GL_2D => FeedbackType::T2D,
        GL_3D => FeedbackType::T3D,
        GL_3D_COLOR => FeedbackType::T3DColor,
        GL_3D_COLOR_TEXTURE => FeedbackType::T3DColorTexture,
        GL_4D_COLOR_TEXTURE => FeedbackType::T4DColorTexture,
        _ => return None,
    })
}

impl FeedbackType {
    pub fn to_gl(self) -> GLenum {
        match self {
            FeedbackType::T2D => GL_2D,
            FeedbackType::T3D => GL_3D,
            FeedbackType::T3DColor => GL_3D_COLOR,
            FeedbackType::T3DColorTexture => GL_3D_COLOR_TEXTURE,
            FeedbackType::T4DColorTexture => GL_4D_COLOR_TEXTURE,
        }
    }
}

impl FeedbackToken {
    pub fn to_gl(self) -> GLenum {
        match self {
            FeedbackToken::Point => GL_POINT_TOKEN,
            FeedbackToken::Line => GL_LINE_TOKEN,
            FeedbackToken::LineReset => GL_LINE_RESET_TOKEN,
            FeedbackToken::Polygon => GL_POLYGON_TOKEN,
            FeedbackToken::Bitmap => GL_BITMAP_TOKEN,
            FeedbackToken::DrawPixel => GL_DRAW_PIXEL_TOKEN,
            FeedbackToken::CopyPixel => GL_COPY_PIXEL_TOKEN,
            FeedbackToken::PassThrough => GL_PASS_THROUGH_TOKEN,
        }
    }
}

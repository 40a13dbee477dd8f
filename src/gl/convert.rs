//! GLenum -> typed Rust values. This is the only module that matches raw GLenums; everything
//! past the entry points works with these types. Each function returns `None` for an enum the
//! call does not accept, and the caller records `GL_INVALID_ENUM`.

use super::enums::*;
use super::types::GLenum;

pub use crate::common::values::*;

mod arrays;
mod eval;
mod fbo;
mod state_ext;
mod texture;
#[allow(unused_imports)]
pub use arrays::*;
pub use eval::*;
pub use fbo::*;
#[allow(unused_imports)]
pub use state_ext::*;
#[allow(unused_imports)]
pub use texture::*;

pub fn primitive_mode(e: GLenum) -> Option<PrimitiveMode> {
    use PrimitiveMode::*;
    Some(match e {
        GL_POINTS => Points,
        GL_LINES => Lines,
        GL_LINE_LOOP => LineLoop,
        GL_LINE_STRIP => LineStrip,
        GL_TRIANGLES => Triangles,
        GL_TRIANGLE_STRIP => TriangleStrip,
        GL_TRIANGLE_FAN => TriangleFan,
        GL_QUADS => Quads,
        GL_QUAD_STRIP => QuadStrip,
        GL_POLYGON => Polygon,
        _ => return None,
    })
}

impl CompareFunc {
    pub fn to_gl(self) -> GLenum {
        match self {
            CompareFunc::Never => GL_NEVER,
            CompareFunc::Less => GL_LESS,
            CompareFunc::Equal => GL_EQUAL,
            CompareFunc::LessEqual => GL_LEQUAL,
            CompareFunc::Greater => GL_GREATER,
            CompareFunc::NotEqual => GL_NOTEQUAL,
            CompareFunc::GreaterEqual => GL_GEQUAL,
            CompareFunc::Always => GL_ALWAYS,
        }
    }
}

pub fn compare_func(e: GLenum) -> Option<CompareFunc> {
    use CompareFunc::*;
    Some(match e {
        GL_NEVER => Never,
        GL_LESS => Less,
        GL_EQUAL => Equal,
        GL_LEQUAL => LessEqual,
        GL_GREATER => Greater,
        GL_NOTEQUAL => NotEqual,
        GL_GEQUAL => GreaterEqual,
        GL_ALWAYS => Always,
        _ => return None,
    })
}

impl MatrixMode {
    pub fn to_gl(self) -> GLenum {
        match self {
            MatrixMode::ModelView => GL_MODELVIEW,
            MatrixMode::Projection => GL_PROJECTION,
            MatrixMode::Texture => GL_TEXTURE,
        }
    }
}

pub fn matrix_mode(e: GLenum) -> Option<MatrixMode> {
    Some(match e {
        GL_MODELVIEW => MatrixMode::ModelView,
        GL_PROJECTION => MatrixMode::Projection,
        GL_TEXTURE => MatrixMode::Texture,
        _ => return None,
    })
}

impl Face {
    pub fn to_gl(self) -> GLenum {
        match self {
            Face::Front => GL_FRONT,
            Face::Back => GL_BACK,
            Face::FrontAndBack => GL_FRONT_AND_BACK,
        }
    }
}

pub fn face(e: GLenum) -> Option<Face> {
    Some(match e {
        GL_FRONT => Face::Front,
        GL_BACK => Face::Back,
        GL_FRONT_AND_BACK => Face::FrontAndBack,
        _ => return None,
    })
}

impl Winding {
    pub fn to_gl(self) -> GLenum {
        match self {
            Winding::Ccw => GL_CCW,
            Winding::Cw => GL_CW,
        }
    }
}

pub fn winding(e: GLenum) -> Option<Winding> {
    Some(match e {
        GL_CCW => Winding::Ccw,
        GL_CW => Winding::Cw,
        _ => return None,
    })
}

impl ShadeModel {
    pub fn to_gl(self) -> GLenum {
        match self {
            ShadeModel::Flat => GL_FLAT,
            ShadeModel::Smooth => GL_SMOOTH,
        }
    }
}

impl ProvokingVertex {
    pub fn to_gl(self) -> GLenum {
        match self {
            ProvokingVertex::First => GL_FIRST_VERTEX_CONVENTION_EXT,
            ProvokingVertex::Last => GL_LAST_VERTEX_CONVENTION_EXT,
        }
    }
}

pub fn provoking_vertex(e: GLenum) -> Option<ProvokingVertex> {
    Some(match e {
        GL_FIRST_VERTEX_CONVENTION_EXT => ProvokingVertex::First,
        GL_LAST_VERTEX_CONVENTION_EXT => ProvokingVertex::Last,
        _ => return None,
    })
}

pub fn shade_model(e: GLenum) -> Option<ShadeModel> {
    Some(match e {
        GL_FLAT => ShadeModel::Flat,
        GL_SMOOTH => ShadeModel::Smooth,
        _ => return None,
    })
}

pub fn texture_target(e: GLenum) -> Option<TextureTarget> {
    Some(match e {
        GL_TEXTURE_1D => TextureTarget::T1D,
        GL_TEXTURE_2D => TextureTarget::T2D,
        GL_TEXTURE_3D => TextureTarget::T3D,
        GL_TEXTURE_CUBE_MAP => TextureTarget::CubeMap,
        GL_TEXTURE_RECTANGLE_ARB => TextureTarget::Rectangle,
        _ => return None,
    })
}

pub fn capability(e: GLenum) -> Option<Capability> {
    if let Some(m) = multisample_cap(e) {
        return Some(Capability::Multisample(m));
    }
    Some(match e {
        GL_DEPTH_TEST => Capability::DepthTest,
        GL_CULL_FACE => Capability::CullFace,
        GL_SCISSOR_TEST => Capability::ScissorTest,
        GL_DITHER => Capability::Dither,
        GL_NORMALIZE => Capability::Normalize,
        GL_RESCALE_NORMAL => Capability::RescaleNormal,
        e if texture_target(e).is_some() => Capability::Texture(texture_target(e)?),
        GL_ALPHA_TEST => Capability::AlphaTest,
        GL_STENCIL_TEST => Capability::StencilTest,
        GL_BLEND => Capability::Blend,
        GL_COLOR_LOGIC_OP => Capability::ColorLogicOp,
        GL_INDEX_LOGIC_OP => Capability::IndexLogicOp,
        GL_LIGHTING => Capability::Lighting,
        GL_COLOR_MATERIAL => Capability::ColorMaterial,
        GL_COLOR_SUM => Capability::ColorSum,
        GL_FOG => Capability::Fog,
        GL_POINT_SMOOTH => Capability::PointSmooth,
        GL_POINT_SPRITE => Capability::PointSprite,
        GL_LINE_SMOOTH => Capability::LineSmooth,
        GL_POLYGON_SMOOTH => Capability::PolygonSmooth,
        GL_LINE_STIPPLE => Capability::LineStipple,
        GL_POLYGON_STIPPLE => Capability::PolygonStipple,
        GL_POLYGON_OFFSET_FILL => Capability::PolygonOffsetFill,
        GL_POLYGON_OFFSET_LINE => Capability::PolygonOffsetLine,
        GL_POLYGON_OFFSET_POINT => Capability::PolygonOffsetPoint,
        GL_TEXTURE_GEN_S => Capability::TexGen(0),
        GL_TEXTURE_GEN_T => Capability::TexGen(1),
        GL_TEXTURE_GEN_R => Capability::TexGen(2),
        GL_TEXTURE_GEN_Q => Capability::TexGen(3),
        e if light_index(e).is_some() => Capability::Light(light_index(e)?),
        GL_AUTO_NORMAL => Capability::AutoNormal,
        e if map1_target(e).is_some() => Capability::Map1(map1_target(e)?),
        e if map2_target(e).is_some() => Capability::Map2(map2_target(e)?),
        // `limits::MAX_CLIP_PLANES` planes (8, as Mesa reports).
        e if (GL_CLIP_PLANE0..GL_CLIP_PLANE0 + 8).contains(&e) => {
            Capability::ClipPlane((e - GL_CLIP_PLANE0) as usize)
        }
        _ => return None,
    })
}

pub fn hint_target(e: GLenum) -> Option<HintTarget> {
    use HintTarget::*;
    Some(match e {
        GL_PERSPECTIVE_CORRECTION_HINT => PerspectiveCorrection,
        GL_POINT_SMOOTH_HINT => PointSmooth,
        GL_LINE_SMOOTH_HINT => LineSmooth,
        GL_POLYGON_SMOOTH_HINT => PolygonSmooth,
        GL_FOG_HINT => Fog,
        GL_GENERATE_MIPMAP_HINT => GenerateMipmap,
        GL_TEXTURE_COMPRESSION_HINT => TextureCompression,
        _ => return None,
    })
}

pub fn hint_mode(e: GLenum) -> Option<GLenum> {
    matches!(e, GL_FASTEST | GL_NICEST | GL_DONT_CARE).then_some(e)
}

pub fn string_name(e: GLenum) -> Option<StringName> {
    Some(match e {
        GL_VENDOR => StringName::Vendor,
        GL_RENDERER => StringName::Renderer,
        GL_VERSION => StringName::Version,
        GL_EXTENSIONS => StringName::Extensions,
        GL_SHADING_LANGUAGE_VERSION => StringName::ShadingLanguageVersion,
        _ => return None,
    })
}

pub fn pixel_format(e: GLenum) -> Option<PixelFormat> {
    use PixelFormat::*;
    Some(match e {
        GL_RED => Red,
        GL_GREEN => Green,
        GL_BLUE => Blue,
        GL_ALPHA => Alpha,
        GL_RGB => Rgb,
        GL_RGBA => Rgba,
        GL_BGR => Bgr,
        GL_BGRA => Bgra,
        GL_LUMINANCE => Luminance,
        GL_LUMINANCE_ALPHA => LuminanceAlpha,
        GL_DEPTH_COMPONENT => DepthComponent,
        GL_STENCIL_INDEX => StencilIndex,
        _ => return None,
    })
}

pub fn pixel_type(e: GLenum) -> Option<PixelType> {
    use PixelType::*;
    Some(match e {
        GL_UNSIGNED_BYTE => UnsignedByte,
        GL_BYTE => Byte,
        GL_UNSIGNED_SHORT => UnsignedShort,
        GL_SHORT => Short,
        GL_UNSIGNED_INT => UnsignedInt,
        GL_INT => Int,
        GL_FLOAT => Float,
        _ => return None,
    })
}

pub fn pixel_store_param(e: GLenum) -> Option<PixelStoreParam> {
    use PixelStoreParam::*;
    Some(match e {
        GL_PACK_ALIGNMENT => Alignment { pack: true },
        GL_UNPACK_ALIGNMENT => Alignment { pack: false },
        GL_PACK_ROW_LENGTH => RowLength { pack: true },
        GL_UNPACK_ROW_LENGTH => RowLength { pack: false },
        GL_PACK_SKIP_PIXELS => SkipPixels { pack: true },
        GL_UNPACK_SKIP_PIXELS => SkipPixels { pack: false },
        GL_PACK_SKIP_ROWS => SkipRows { pack: true },
        GL_UNPACK_SKIP_ROWS => SkipRows { pack: false },
        GL_PACK_SKIP_IMAGES => SkipImages { pack: true },
        GL_UNPACK_SKIP_IMAGES => SkipImages { pack: false },
        GL_PACK_IMAGE_HEIGHT => ImageHeight { pack: true },
        GL_UNPACK_IMAGE_HEIGHT => ImageHeight { pack: false },
        GL_PACK_SWAP_BYTES => SwapBytes { pack: true },
        GL_UNPACK_SWAP_BYTES => SwapBytes { pack: false },
        GL_PACK_LSB_FIRST => LsbFirst { pack: true },
        GL_UNPACK_LSB_FIRST => LsbFirst { pack: false },
        _ => return None,
    })
}

pub fn clear_mask(mask: u32) -> Option<ClearMask> {
    let known =
        GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
    if mask & !known != 0 {
        return None;
    }
    Some(ClearMask {
        color: mask & GL_COLOR_BUFFER_BIT != 0,
        depth: mask & GL_DEPTH_BUFFER_BIT != 0,
        stencil: mask & GL_STENCIL_BUFFER_BIT != 0,
        accum: mask & GL_ACCUM_BUFFER_BIT != 0,
    })
}

/// The `glGet*` query for `pname`.
pub fn query(e: GLenum) -> Option<Query> {
    use Query::*;
    if let Some(cap) = capability(e) {
        return Some(Enabled(cap));
    }
    if let Some(h) = hint_target(e) {
        return Some(Hint(h));
    }
    if let Some(p) = pixel_store_param(e) {
        return Some(PixelStore(p));
    }
    if let Some(q) = array_query(e) {
        return Some(Arrays(q));
    }
    if let Some(q) = state_ext_query(e) {
        return Some(StateExt(q));
    }
    if let Some(q) = eval_query(e) {
        return Some(Eval(q));
    }
    Some(match e {
        GL_VIEWPORT => Viewport,
        GL_DEPTH_RANGE => DepthRange,
        GL_MODELVIEW_MATRIX => ModelviewMatrix,
        GL_PROJECTION_MATRIX => ProjectionMatrix,
        GL_TEXTURE_MATRIX => TextureMatrix,
        GL_TRANSPOSE_MODELVIEW_MATRIX => TransposeModelviewMatrix,
        GL_TRANSPOSE_PROJECTION_MATRIX => TransposeProjectionMatrix,
        GL_TRANSPOSE_TEXTURE_MATRIX => TransposeTextureMatrix,
        GL_MODELVIEW_STACK_DEPTH => ModelviewStackDepth,
        GL_PROJECTION_STACK_DEPTH => ProjectionStackDepth,
        GL_TEXTURE_STACK_DEPTH => TextureStackDepth,
        GL_MAX_MODELVIEW_STACK_DEPTH => MaxModelviewStackDepth,
        GL_MAX_PROJECTION_STACK_DEPTH => MaxProjectionStackDepth,
        GL_MAX_TEXTURE_STACK_DEPTH => MaxTextureStackDepth,
        GL_MAX_VIEWPORT_DIMS => MaxViewportDims,
        GL_MAX_CLIP_PLANES => MaxClipPlanes,
        GL_MAX_TEXTURE_UNITS => MaxTextureUnits,
        GL_COLOR_CLEAR_VALUE => ColorClearValue,
        GL_ACCUM_CLEAR_VALUE => AccumClearValue,
        GL_DEPTH_CLEAR_VALUE => DepthClearValue,
        GL_STENCIL_CLEAR_VALUE => StencilClearValue,
        GL_DEPTH_FUNC => DepthFunc,
        GL_DEPTH_WRITEMASK => DepthWritemask,
        GL_COLOR_WRITEMASK => ColorWritemask,
        GL_STENCIL_WRITEMASK => StencilWritemask,
        GL_SCISSOR_BOX => ScissorBox,
        GL_CULL_FACE_MODE => CullFaceMode,
        GL_FRONT_FACE => FrontFace,
        GL_SHADE_MODEL => ShadeModel,
        GL_MATRIX_MODE => MatrixMode,
        GL_CURRENT_COLOR => CurrentColor,
        GL_CURRENT_SECONDARY_COLOR => CurrentSecondaryColor,
        GL_CURRENT_NORMAL => CurrentNormal,
        GL_CURRENT_TEXTURE_COORDS => CurrentTextureCoords,
        GL_CURRENT_FOG_COORD => CurrentFogCoord,
        GL_EDGE_FLAG => EdgeFlag,
        GL_RED_BITS => RedBits,
        GL_GREEN_BITS => GreenBits,
        GL_BLUE_BITS => BlueBits,
        GL_ALPHA_BITS => AlphaBits,
        GL_DEPTH_BITS => DepthBits,
        GL_STENCIL_BITS => StencilBits,
        GL_ACCUM_RED_BITS => AccumRedBits,
        GL_ACCUM_GREEN_BITS => AccumGreenBits,
        GL_ACCUM_BLUE_BITS => AccumBlueBits,
        GL_ACCUM_ALPHA_BITS => AccumAlphaBits,
        GL_INDEX_BITS => IndexBits,
        GL_SUBPIXEL_BITS => SubpixelBits,
        GL_AUX_BUFFERS => AuxBuffers,
        GL_DOUBLEBUFFER => Doublebuffer,
        GL_DRAW_BUFFER => DrawBuffer,
        GL_READ_BUFFER => ReadBuffer,
        GL_STEREO => Stereo,
        GL_RGBA_MODE => RgbaMode,
        GL_INDEX_MODE => IndexMode,
        GL_POINT_SIZE => PointSize,
        GL_POINT_SIZE_RANGE => PointSizeRange,
        GL_POINT_SIZE_GRANULARITY => PointSizeGranularity,
        GL_LINE_WIDTH => LineWidth,
        GL_LINE_WIDTH_RANGE => LineWidthRange,
        GL_LINE_WIDTH_GRANULARITY => LineWidthGranularity,
        GL_ACTIVE_TEXTURE => ActiveTexture,
        GL_CLIENT_ACTIVE_TEXTURE => ClientActiveTexture,
        GL_MAX_ATTRIB_STACK_DEPTH => MaxAttribStackDepth,
        GL_SAMPLE_BUFFERS => SampleBuffers,
        GL_SAMPLES => Samples,
        GL_ALPHA_TEST_FUNC => AlphaTestFunc,
        GL_ALPHA_TEST_REF => AlphaTestRef,
        GL_STENCIL_FUNC => StencilFunc,
        GL_STENCIL_VALUE_MASK => StencilValueMask,
        GL_STENCIL_REF => StencilRef,
        GL_STENCIL_FAIL => StencilFail,
        GL_STENCIL_PASS_DEPTH_FAIL => StencilPassDepthFail,
        GL_STENCIL_PASS_DEPTH_PASS => StencilPassDepthPass,
        // GL_BLEND_SRC and GL_BLEND_DST report the RGB factors.
        GL_BLEND_SRC | GL_BLEND_SRC_RGB => BlendSrcRgb,
        GL_BLEND_DST | GL_BLEND_DST_RGB => BlendDstRgb,
        GL_BLEND_SRC_ALPHA => BlendSrcAlpha,
        GL_BLEND_DST_ALPHA => BlendDstAlpha,
        GL_BLEND_EQUATION => BlendEquationRgb,
        GL_BLEND_EQUATION_ALPHA_EXT => BlendEquationAlpha,
        GL_PROVOKING_VERTEX_EXT => ProvokingVertex,
        GL_CURRENT_INDEX => CurrentIndex,
        GL_INDEX_CLEAR_VALUE => IndexClearValue,
        GL_INDEX_WRITEMASK => IndexWritemask,
        GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION_EXT => QuadsFollowProvokingVertex,
        GL_FRAMEBUFFER_BINDING_EXT => FramebufferBinding,
        GL_READ_FRAMEBUFFER_BINDING_EXT => ReadFramebufferBinding,
        GL_RENDERBUFFER_BINDING_EXT => RenderbufferBinding,
        GL_MAX_COLOR_ATTACHMENTS_EXT => MaxColorAttachments,
        GL_MAX_RENDERBUFFER_SIZE_EXT => MaxRenderbufferSize,
        GL_MAX_SAMPLES => MaxSamples,
        GL_BLEND_COLOR => BlendColor,
        GL_LOGIC_OP_MODE => LogicOpMode,
        GL_MAX_LIGHTS => MaxLights,
        GL_LIGHT_MODEL_AMBIENT => LightModelAmbient,
        GL_LIGHT_MODEL_LOCAL_VIEWER => LightModelLocalViewer,
        GL_LIGHT_MODEL_TWO_SIDE => LightModelTwoSide,
        GL_LIGHT_MODEL_COLOR_CONTROL => LightModelColorControl,
        GL_COLOR_MATERIAL_FACE => ColorMaterialFace,
        e if fog_param(e).is_some() => Fog(fog_param(e)?),
        e if point_param(e).is_some() => PointParam(point_param(e)?),
        e if pixel_rect_query(e).is_some() => PixelRect(pixel_rect_query(e)?),
        GL_POLYGON_MODE => PolygonMode,
        GL_POLYGON_OFFSET_FACTOR => PolygonOffsetFactor,
        GL_POLYGON_OFFSET_UNITS => PolygonOffsetUnits,
        GL_LINE_STIPPLE_PATTERN => LineStipplePattern,
        GL_LINE_STIPPLE_REPEAT => LineStippleRepeat,
        GL_ALIASED_POINT_SIZE_RANGE => AliasedPointSizeRange,
        GL_ALIASED_LINE_WIDTH_RANGE => AliasedLineWidthRange,
        GL_COLOR_MATERIAL_PARAMETER => ColorMaterialParameter,
        _ => return None,
    })
}

/// The GLenum of a texture unit index.
pub fn texture_unit_enum(unit: usize) -> GLenum {
    GL_TEXTURE0 + unit as GLenum
}

impl StencilOp {
    pub fn to_gl(self) -> GLenum {
        use StencilOp::*;
        match self {
            Keep => GL_KEEP,
            Zero => GL_ZERO,
            Replace => GL_REPLACE,
            Incr => GL_INCR,
            Decr => GL_DECR,
            Invert => GL_INVERT,
            IncrWrap => GL_INCR_WRAP,
            DecrWrap => GL_DECR_WRAP,
        }
    }
}

pub fn stencil_op(e: GLenum) -> Option<StencilOp> {
    use StencilOp::*;
    Some(match e {
        GL_KEEP => Keep,
        GL_ZERO => Zero,
        GL_REPLACE => Replace,
        GL_INCR => Incr,
        GL_DECR => Decr,
        GL_INVERT => Invert,
        GL_INCR_WRAP => IncrWrap,
        GL_DECR_WRAP => DecrWrap,
        _ => return None,
    })
}

impl BlendFactor {
    pub fn to_gl(self) -> GLenum {
        use BlendFactor::*;
        match self {
            Zero => GL_ZERO,
            One => GL_ONE,
            SrcColor => GL_SRC_COLOR,
            OneMinusSrcColor => GL_ONE_MINUS_SRC_COLOR,
            DstColor => GL_DST_COLOR,
            OneMinusDstColor => GL_ONE_MINUS_DST_COLOR,
            SrcAlpha => GL_SRC_ALPHA,
            OneMinusSrcAlpha => GL_ONE_MINUS_SRC_ALPHA,
            DstAlpha => GL_DST_ALPHA,
            OneMinusDstAlpha => GL_ONE_MINUS_DST_ALPHA,
            ConstantColor => GL_CONSTANT_COLOR,
            OneMinusConstantColor => GL_ONE_MINUS_CONSTANT_COLOR,
            ConstantAlpha => GL_CONSTANT_ALPHA,
            OneMinusConstantAlpha => GL_ONE_MINUS_CONSTANT_ALPHA,
            SrcAlphaSaturate => GL_SRC_ALPHA_SATURATE,
        }
    }
}

/// A blend factor; `source` tells which side it is for (GL 1.4+ accepts the colour factors
/// on both sides; SRC_ALPHA_SATURATE only as a source factor).
pub fn blend_factor(e: GLenum, source: bool) -> Option<BlendFactor> {
    use BlendFactor::*;
    Some(match e {
        GL_ZERO => Zero,
        GL_ONE => One,
        GL_SRC_COLOR => SrcColor,
        GL_ONE_MINUS_SRC_COLOR => OneMinusSrcColor,
        GL_DST_COLOR => DstColor,
        GL_ONE_MINUS_DST_COLOR => OneMinusDstColor,
        GL_SRC_ALPHA => SrcAlpha,
        GL_ONE_MINUS_SRC_ALPHA => OneMinusSrcAlpha,
        GL_DST_ALPHA => DstAlpha,
        GL_ONE_MINUS_DST_ALPHA => OneMinusDstAlpha,
        GL_CONSTANT_COLOR => ConstantColor,
        GL_ONE_MINUS_CONSTANT_COLOR => OneMinusConstantColor,
        GL_CONSTANT_ALPHA => ConstantAlpha,
        GL_ONE_MINUS_CONSTANT_ALPHA => OneMinusConstantAlpha,
        GL_SRC_ALPHA_SATURATE if source => SrcAlphaSaturate,
        _ => return None,
    })
}

impl BlendEquation {
    pub fn to_gl(self) -> GLenum {
        match self {
            BlendEquation::Add => GL_FUNC_ADD,
            BlendEquation::Subtract => GL_FUNC_SUBTRACT,
            BlendEquation::ReverseSubtract => GL_FUNC_REVERSE_SUBTRACT,
            BlendEquation::Min => GL_MIN,
            BlendEquation::Max => GL_MAX,
        }
    }
}

pub fn blend_equation(e: GLenum) -> Option<BlendEquation> {
    Some(match e {
        GL_FUNC_ADD => BlendEquation::Add,
        GL_FUNC_SUBTRACT => BlendEquation::Subtract,
        GL_FUNC_REVERSE_SUBTRACT => BlendEquation::ReverseSubtract,
        GL_MIN => BlendEquation::Min,
        GL_MAX => BlendEquation::Max,
        _ => return None,
    })
}

impl LogicOp {
    pub fn to_gl(self) -> GLenum {
        GL_CLEAR + self as GLenum
    }
}

pub fn logic_op(e: GLenum) -> Option<LogicOp> {
    use LogicOp::*;
    const OPS: [LogicOp; 16] = [
        Clear,
        And,
        AndReverse,
        Copy,
        AndInverted,
        Noop,
        Xor,
        Or,
        Nor,
        Equiv,
        Invert,
        OrReverse,
        CopyInverted,
        OrInverted,
        Nand,
        Set,
    ];
    // GL_CLEAR .. GL_SET are consecutive (0x1500 .. 0x150F) in table order.
    e.checked_sub(GL_CLEAR)
        .and_then(|i| OPS.get(i as usize).copied())
}

pub fn light_param(e: GLenum) -> Option<LightParam> {
    use LightParam::*;
    Some(match e {
        GL_AMBIENT => Ambient,
        GL_DIFFUSE => Diffuse,
        GL_SPECULAR => Specular,
        GL_POSITION => Position,
        GL_SPOT_DIRECTION => SpotDirection,
        GL_SPOT_EXPONENT => SpotExponent,
        GL_SPOT_CUTOFF => SpotCutoff,
        GL_CONSTANT_ATTENUATION => ConstantAttenuation,
        GL_LINEAR_ATTENUATION => LinearAttenuation,
        GL_QUADRATIC_ATTENUATION => QuadraticAttenuation,
        _ => return None,
    })
}

/// Index of `GL_LIGHTi`.
pub fn light_index(e: GLenum) -> Option<usize> {
    let i = e.checked_sub(GL_LIGHT0)? as usize;
    (i < 8).then_some(i)
}

pub fn material_param(e: GLenum) -> Option<MaterialParam> {
    use MaterialParam::*;
    Some(match e {
        GL_AMBIENT => Ambient,
        GL_DIFFUSE => Diffuse,
        GL_SPECULAR => Specular,
        GL_EMISSION => Emission,
        GL_SHININESS => Shininess,
        GL_AMBIENT_AND_DIFFUSE => AmbientAndDiffuse,
        GL_COLOR_INDEXES => ColorIndexes,
        _ => return None,
    })
}

/// `glColorMaterial` modes.
pub fn color_material_mode(e: GLenum) -> Option<MaterialParam> {
    use MaterialParam::*;
    Some(match e {
        GL_AMBIENT => Ambient,
        GL_DIFFUSE => Diffuse,
        GL_SPECULAR => Specular,
        GL_EMISSION => Emission,
        GL_AMBIENT_AND_DIFFUSE => AmbientAndDiffuse,
        _ => return None,
    })
}

impl MaterialParam {
    pub fn to_gl(self) -> GLenum {
        use MaterialParam::*;
        match self {
            Ambient => GL_AMBIENT,
            Diffuse => GL_DIFFUSE,
            Specular => GL_SPECULAR,
            Emission => GL_EMISSION,
            Shininess => GL_SHININESS,
            AmbientAndDiffuse => GL_AMBIENT_AND_DIFFUSE,
            ColorIndexes => GL_COLOR_INDEXES,
        }
    }
}

pub fn light_model_param(e: GLenum) -> Option<LightModelParam> {
    Some(match e {
        GL_LIGHT_MODEL_AMBIENT => LightModelParam::Ambient,
        GL_LIGHT_MODEL_LOCAL_VIEWER => LightModelParam::LocalViewer,
        GL_LIGHT_MODEL_TWO_SIDE => LightModelParam::TwoSide,
        GL_LIGHT_MODEL_COLOR_CONTROL => LightModelParam::ColorControl,
        _ => return None,
    })
}

/// `GL_LIGHT_MODEL_COLOR_CONTROL` values: true for `GL_SEPARATE_SPECULAR_COLOR`.
pub fn separate_specular(e: GLenum) -> Option<bool> {
    match e {
        GL_SINGLE_COLOR => Some(false),
        GL_SEPARATE_SPECULAR_COLOR => Some(true),
        _ => None,
    }
}

impl TexEnvMode {
    pub fn to_gl(self) -> GLenum {
        match self {
            TexEnvMode::Replace => GL_REPLACE,
            TexEnvMode::Modulate => GL_MODULATE,
            TexEnvMode::Decal => GL_DECAL,
            TexEnvMode::Blend => GL_BLEND,
            TexEnvMode::Add => GL_ADD,
            TexEnvMode::Combine => GL_COMBINE,
            TexEnvMode::Combine4 => GL_COMBINE4_NV,
        }
    }
}

pub fn tex_env_mode(e: GLenum) -> Option<TexEnvMode> {
    Some(match e {
        GL_REPLACE => TexEnvMode::Replace,
        GL_MODULATE => TexEnvMode::Modulate,
        GL_DECAL => TexEnvMode::Decal,
        GL_BLEND => TexEnvMode::Blend,
        GL_ADD => TexEnvMode::Add,
        GL_COMBINE => TexEnvMode::Combine,
        GL_COMBINE4_NV => TexEnvMode::Combine4,
        _ => return None,
    })
}

impl CombineFunc {
    pub fn to_gl(self) -> GLenum {
        use CombineFunc::*;
        match self {
            Replace => GL_REPLACE,
            Modulate => GL_MODULATE,
            Add => GL_ADD,
            AddSigned => GL_ADD_SIGNED,
            Interpolate => GL_INTERPOLATE,
            Subtract => GL_SUBTRACT,
            Dot3Rgb => GL_DOT3_RGB,
            Dot3Rgba => GL_DOT3_RGBA,
        }
    }
}

pub fn combine_func(e: GLenum, rgb: bool) -> Option<CombineFunc> {
    use CombineFunc::*;
    Some(match e {
        GL_REPLACE => Replace,
        GL_MODULATE => Modulate,
        GL_ADD => Add,
        GL_ADD_SIGNED => AddSigned,
        GL_INTERPOLATE => Interpolate,
        GL_SUBTRACT => Subtract,
        GL_DOT3_RGB if rgb => Dot3Rgb,
        GL_DOT3_RGBA if rgb => Dot3Rgba,
        _ => return None,
    })
}

impl CombineSource {
    pub fn to_gl(self) -> GLenum {
        match self {
            CombineSource::Texture => GL_TEXTURE,
            CombineSource::TextureUnit(u) => GL_TEXTURE0 + u as GLenum,
            CombineSource::Constant => GL_CONSTANT,
            CombineSource::PrimaryColor => GL_PRIMARY_COLOR,
            CombineSource::Previous => GL_PREVIOUS,
            CombineSource::Zero => GL_ZERO,
        }
    }
}

pub fn combine_source(e: GLenum) -> Option<CombineSource> {
    Some(match e {
        GL_TEXTURE => CombineSource::Texture,
        GL_CONSTANT => CombineSource::Constant,
        GL_PRIMARY_COLOR => CombineSource::PrimaryColor,
        GL_PREVIOUS => CombineSource::Previous,
        GL_ZERO => CombineSource::Zero,
        e if (GL_TEXTURE0..GL_TEXTURE0 + 8).contains(&e) => {
            CombineSource::TextureUnit((e - GL_TEXTURE0) as u8)
        }
        _ => return None,
    })
}

impl CombineOperand {
    pub fn to_gl(self) -> GLenum {
        match self {
            CombineOperand::SrcColor => GL_SRC_COLOR,
            CombineOperand::OneMinusSrcColor => GL_ONE_MINUS_SRC_COLOR,
            CombineOperand::SrcAlpha => GL_SRC_ALPHA,
            CombineOperand::OneMinusSrcAlpha => GL_ONE_MINUS_SRC_ALPHA,
        }
    }
}

pub fn combine_operand(e: GLenum, rgb: bool) -> Option<CombineOperand> {
    Some(match e {
        GL_SRC_COLOR if rgb => CombineOperand::SrcColor,
        GL_ONE_MINUS_SRC_COLOR if rgb => CombineOperand::OneMinusSrcColor,
        GL_SRC_ALPHA => CombineOperand::SrcAlpha,
        GL_ONE_MINUS_SRC_ALPHA => CombineOperand::OneMinusSrcAlpha,
        _ => return None,
    })
}

/// `glTexEnv(target, pname)`: target `GL_TEXTURE_ENV` takes the environment parameters,
/// `GL_TEXTURE_FILTER_CONTROL` takes `GL_TEXTURE_LOD_BIAS`.
pub fn tex_env_param(target: GLenum, pname: GLenum) -> Option<TexEnvParam> {
    use TexEnvParam::*;
    match target {
        GL_TEXTURE_FILTER_CONTROL => (pname == GL_TEXTURE_LOD_BIAS).then_some(LodBias),
        GL_TEXTURE_ENV => Some(match pname {
            GL_TEXTURE_ENV_MODE => Mode,
            GL_TEXTURE_ENV_COLOR => Color,
            GL_COMBINE_RGB => CombineRgb,
            GL_COMBINE_ALPHA => CombineAlpha,
            GL_SOURCE0_RGB => Source { rgb: true, n: 0 },
            GL_SOURCE1_RGB => Source { rgb: true, n: 1 },
            GL_SOURCE2_RGB => Source { rgb: true, n: 2 },
            GL_SOURCE3_RGB_NV => Source { rgb: true, n: 3 },
            GL_SOURCE0_ALPHA => Source { rgb: false, n: 0 },
            GL_SOURCE1_ALPHA => Source { rgb: false, n: 1 },
            GL_SOURCE2_ALPHA => Source { rgb: false, n: 2 },
            GL_SOURCE3_ALPHA_NV => Source { rgb: false, n: 3 },
            GL_OPERAND0_RGB => Operand { rgb: true, n: 0 },
            GL_OPERAND1_RGB => Operand { rgb: true, n: 1 },
            GL_OPERAND2_RGB => Operand { rgb: true, n: 2 },
            GL_OPERAND3_RGB_NV => Operand { rgb: true, n: 3 },
            GL_OPERAND0_ALPHA => Operand { rgb: false, n: 0 },
            GL_OPERAND1_ALPHA => Operand { rgb: false, n: 1 },
            GL_OPERAND2_ALPHA => Operand { rgb: false, n: 2 },
            GL_OPERAND3_ALPHA_NV => Operand { rgb: false, n: 3 },
            GL_RGB_SCALE => RgbScale,
            GL_ALPHA_SCALE => AlphaScale,
            _ => return None,
        }),
        _ => None,
    }
}

/// Index of a `GL_TEXTUREi` unit enum (`i` < 8).
pub fn texture_unit(e: GLenum) -> Option<usize> {
    let i = e.checked_sub(GL_TEXTURE0)? as usize;
    (i < 8).then_some(i)
}

impl TexGenMode {
    pub fn to_gl(self) -> GLenum {
        match self {
            TexGenMode::ObjectLinear => GL_OBJECT_LINEAR,
            TexGenMode::EyeLinear => GL_EYE_LINEAR,
            TexGenMode::SphereMap => GL_SPHERE_MAP,
            TexGenMode::ReflectionMap => GL_REFLECTION_MAP,
            TexGenMode::NormalMap => GL_NORMAL_MAP,
        }
    }
}

/// A texgen mode valid for coordinate `coord` (0..4 = s, t, r, q): sphere maps only for s and
/// t, reflection and normal maps not for q.
pub fn tex_gen_mode(e: GLenum, coord: usize) -> Option<TexGenMode> {
    Some(match e {
        GL_OBJECT_LINEAR => TexGenMode::ObjectLinear,
        GL_EYE_LINEAR => TexGenMode::EyeLinear,
        GL_SPHERE_MAP if coord < 2 => TexGenMode::SphereMap,
        GL_REFLECTION_MAP if coord < 3 => TexGenMode::ReflectionMap,
        GL_NORMAL_MAP if coord < 3 => TexGenMode::NormalMap,
        _ => return None,
    })
}

/// `GL_S`, `GL_T`, `GL_R`, `GL_Q` as 0..4.
pub fn tex_gen_coord(e: GLenum) -> Option<usize> {
    Some(match e {
        GL_S => 0,
        GL_T => 1,
        GL_R => 2,
        GL_Q => 3,
        _ => return None,
    })
}

pub fn tex_gen_param(e: GLenum) -> Option<TexGenParam> {
    Some(match e {
        GL_TEXTURE_GEN_MODE => TexGenParam::Mode,
        GL_OBJECT_PLANE => TexGenParam::ObjectPlane,
        GL_EYE_PLANE => TexGenParam::EyePlane,
        _ => return None,
    })
}

impl FogMode {
    pub fn to_gl(self) -> GLenum {
        match self {
            FogMode::Linear => GL_LINEAR,
            FogMode::Exp => GL_EXP,
            FogMode::Exp2 => GL_EXP2,
        }
    }
}

pub fn fog_mode(e: GLenum) -> Option<FogMode> {
    Some(match e {
        GL_LINEAR => FogMode::Linear,
        GL_EXP => FogMode::Exp,
        GL_EXP2 => FogMode::Exp2,
        _ => return None,
    })
}

pub fn fog_param(e: GLenum) -> Option<FogParam> {
    Some(match e {
        GL_FOG_MODE => FogParam::Mode,
        GL_FOG_DENSITY => FogParam::Density,
        GL_FOG_START => FogParam::Start,
        GL_FOG_END => FogParam::End,
        GL_FOG_INDEX => FogParam::Index,
        GL_FOG_COLOR => FogParam::Color,
        GL_FOG_COORD_SRC => FogParam::CoordSource,
        _ => return None,
    })
}

/// `GL_FOG_COORD_SRC` values: true for `GL_FOG_COORD` (the vertex fog coordinate), false for
/// `GL_FRAGMENT_DEPTH`.
pub fn fog_coord_source(e: GLenum) -> Option<bool> {
    match e {
        GL_FOG_COORD => Some(true),
        GL_FRAGMENT_DEPTH => Some(false),
        _ => None,
    }
}

impl PolygonMode {
    pub fn to_gl(self) -> GLenum {
        match self {
            PolygonMode::Point => GL_POINT,
            PolygonMode::Line => GL_LINE,
            PolygonMode::Fill => GL_FILL,
        }
    }
}

pub fn polygon_mode(e: GLenum) -> Option<PolygonMode> {
    Some(match e {
        GL_POINT => PolygonMode::Point,
        GL_LINE => PolygonMode::Line,
        GL_FILL => PolygonMode::Fill,
        _ => return None,
    })
}

pub fn point_param(e: GLenum) -> Option<PointParam> {
    Some(match e {
        GL_POINT_SIZE_MIN => PointParam::SizeMin,
        GL_POINT_SIZE_MAX => PointParam::SizeMax,
        GL_POINT_FADE_THRESHOLD_SIZE => PointParam::FadeThresholdSize,
        GL_POINT_DISTANCE_ATTENUATION => PointParam::DistanceAttenuation,
        GL_POINT_SPRITE_COORD_ORIGIN => PointParam::SpriteCoordOrigin,
        _ => return None,
    })
}

pub fn color_buffer_name(e: GLenum) -> Option<ColorBufferName> {
    use ColorBufferName::*;
    Some(match e {
        GL_NONE => None,
        GL_FRONT_LEFT => FrontLeft,
        GL_FRONT_RIGHT => FrontRight,
        GL_BACK_LEFT => BackLeft,
        GL_BACK_RIGHT => BackRight,
        GL_FRONT => Front,
        GL_BACK => Back,
        GL_LEFT => Left,
        GL_RIGHT => Right,
        GL_FRONT_AND_BACK => FrontAndBack,
        GL_AUX0..=GL_AUX3 => Aux(e - GL_AUX0),
        _ => return Option::None,
    })
}

pub fn accum_op(op: GLenum) -> Option<AccumOp> {
    Some(match op {
        GL_ACCUM => AccumOp::Accum,
        GL_LOAD => AccumOp::Load,
        GL_RETURN => AccumOp::Return,
        GL_MULT => AccumOp::Mult,
        GL_ADD => AccumOp::Add,
        _ => return None,
    })
}

pub fn pixel_transfer_param(e: GLenum) -> Option<PixelTransferParam> {
    use PixelTransferParam::*;
    Some(match e {
        GL_MAP_COLOR => MapColor,
        GL_MAP_STENCIL => MapStencil,
        GL_INDEX_SHIFT => IndexShift,
        GL_INDEX_OFFSET => IndexOffset,
        GL_RED_SCALE => Scale(0),
        GL_GREEN_SCALE => Scale(1),
        GL_BLUE_SCALE => Scale(2),
        GL_ALPHA_SCALE => Scale(3),
        GL_RED_BIAS => Bias(0),
        GL_GREEN_BIAS => Bias(1),
        GL_BLUE_BIAS => Bias(2),
        GL_ALPHA_BIAS => Bias(3),
        GL_DEPTH_SCALE => DepthScale,
        GL_DEPTH_BIAS => DepthBias,
        _ => return None,
    })
}

pub fn pixel_map(e: GLenum) -> Option<PixelMap> {
    use PixelMap::*;
    Some(match e {
        GL_PIXEL_MAP_I_TO_I => IToI,
        GL_PIXEL_MAP_S_TO_S => SToS,
        GL_PIXEL_MAP_I_TO_R => IToR,
        GL_PIXEL_MAP_I_TO_G => IToG,
        GL_PIXEL_MAP_I_TO_B => IToB,
        GL_PIXEL_MAP_I_TO_A => IToA,
        GL_PIXEL_MAP_R_TO_R => RToR,
        GL_PIXEL_MAP_G_TO_G => GToG,
        GL_PIXEL_MAP_B_TO_B => BToB,
        GL_PIXEL_MAP_A_TO_A => AToA,
        _ => return None,
    })
}

pub fn pixel_rect_query(e: GLenum) -> Option<PixelRectQuery> {
    use PixelRectQuery::*;
    if let Some(p) = pixel_transfer_param(e) {
        return Some(Transfer(p));
    }
    Some(match e {
        GL_PIXEL_MAP_I_TO_I_SIZE => MapSize(PixelMap::IToI),
        GL_PIXEL_MAP_S_TO_S_SIZE => MapSize(PixelMap::SToS),
        GL_PIXEL_MAP_I_TO_R_SIZE => MapSize(PixelMap::IToR),
        GL_PIXEL_MAP_I_TO_G_SIZE => MapSize(PixelMap::IToG),
        GL_PIXEL_MAP_I_TO_B_SIZE => MapSize(PixelMap::IToB),
        GL_PIXEL_MAP_I_TO_A_SIZE => MapSize(PixelMap::IToA),
        GL_PIXEL_MAP_R_TO_R_SIZE => MapSize(PixelMap::RToR),
        GL_PIXEL_MAP_G_TO_G_SIZE => MapSize(PixelMap::GToG),
        GL_PIXEL_MAP_B_TO_B_SIZE => MapSize(PixelMap::BToB),
        GL_PIXEL_MAP_A_TO_A_SIZE => MapSize(PixelMap::AToA),
        GL_MAX_PIXEL_MAP_TABLE => MaxPixelMapTable,
        GL_ZOOM_X => ZoomX,
        GL_ZOOM_Y => ZoomY,
        GL_CURRENT_RASTER_POSITION => RasterPosition,
        GL_CURRENT_RASTER_POSITION_VALID => RasterPositionValid,
        GL_CURRENT_RASTER_COLOR => RasterColor,
        GL_CURRENT_RASTER_TEXTURE_COORDS => RasterTextureCoords,
        GL_CURRENT_RASTER_DISTANCE => RasterDistance,
        GL_CURRENT_RASTER_INDEX => RasterIndex,
        _ => return None,
    })
}

pub fn copy_pixels_type(e: GLenum) -> Option<CopyPixelsType> {
    Some(match e {
        GL_COLOR => CopyPixelsType::Color,
        GL_DEPTH => CopyPixelsType::Depth,
        GL_STENCIL => CopyPixelsType::Stencil,
        _ => return None,
    })
}

pub fn draw_pixels_format(e: GLenum) -> Option<DrawPixelsFormat> {
    Some(match e {
        GL_DEPTH_COMPONENT => DrawPixelsFormat::Depth,
        GL_STENCIL_INDEX => DrawPixelsFormat::StencilIndex,
        GL_COLOR_INDEX => DrawPixelsFormat::ColorIndex,
        e => DrawPixelsFormat::Color(texture::tex_pixel_format(e)?),
    })
}

pub fn pixel_index_type(e: GLenum) -> Option<PixelIndexType> {
    if e == GL_BITMAP {
        return Some(PixelIndexType::Bitmap);
    }
    match texture::tex_pixel_type(e)? {
        TexPixelType::Packed(_) => None,
        t => Some(PixelIndexType::Plain(t)),
    }
}

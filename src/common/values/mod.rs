//! The typed values the API layer converts GL enums to (`gl::convert` parses them; this module
//! only defines them), used by every stage below the API: primitive modes, comparison
//! functions, blend factors, fog modes, texture environment and generation modes, ...
//! Nothing here knows a GL enum value.

mod arrays;
mod eval;
mod fbo;
mod state_ext;
mod texture;
pub use arrays::*;
pub use eval::*;
pub use fbo::*;
pub use state_ext::*;
pub use texture::*;

/// The ten primitive modes of `glBegin`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PrimitiveMode {
    Points,
    Lines,
    LineLoop,
    LineStrip,
    Triangles,
    TriangleStrip,
    TriangleFan,
    Quads,
    QuadStrip,
    Polygon,
}

/// Comparison functions of the depth, alpha and stencil tests (and texture compare).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CompareFunc {
    Never,
    Less,
    Equal,
    LessEqual,
    Greater,
    NotEqual,
    GreaterEqual,
    Always,
}

impl CompareFunc {
    /// Applies the function as `incoming OP stored`.
    #[inline(always)]
    pub fn test<T: PartialOrd>(self, incoming: T, stored: T) -> bool {
        match self {
            CompareFunc::Never => false,
            CompareFunc::Less => incoming < stored,
            CompareFunc::Equal => incoming == stored,
            CompareFunc::LessEqual => incoming <= stored,
            CompareFunc::Greater => incoming > stored,
            CompareFunc::NotEqual => incoming != stored,
            CompareFunc::GreaterEqual => incoming >= stored,
            CompareFunc::Always => true,
        }
    }
}

/// `glMatrixMode` targets.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MatrixMode {
    ModelView,
    Projection,
    Texture,
}

/// Which faces a setting applies to (`glCullFace`, `glPolygonMode`, `glMaterial`, ...).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Face {
    Front,
    Back,
    FrontAndBack,
}

/// `glFrontFace`: which winding is front-facing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Winding {
    Ccw,
    Cw,
}

/// `glShadeModel`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShadeModel {
    Flat,
    Smooth,
}

/// `glProvokingVertexEXT`: which vertex of a primitive gives a flat-shaded primitive its
/// colours. `Last` is OpenGL 1.5's table 2.9.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ProvokingVertex {
    First,
    #[default]
    Last,
}

/// Texture targets that can be enabled and bound.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TextureTarget {
    T1D = 0,
    T2D = 1,
    T3D = 2,
    CubeMap = 3,
    /// ARB_texture_rectangle: one level, coordinates in texels.
    Rectangle = 4,
}

/// Capabilities of `glEnable`/`glDisable`/`glIsEnabled` that tilegl implements.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Capability {
    DepthTest,
    CullFace,
    ScissorTest,
    ClipPlane(usize),
    Dither,
    Normalize,
    RescaleNormal,
    /// A texture target on the active unit.
    Texture(TextureTarget),
    AlphaTest,
    StencilTest,
    Blend,
    ColorLogicOp,
    IndexLogicOp,
    Lighting,
    Light(usize),
    ColorMaterial,
    ColorSum,
    /// `GL_TEXTURE_GEN_S` .. `Q` of the active unit.
    TexGen(usize),
    Fog,
    PointSmooth,
    /// `GL_POINT_SPRITE` (ARB_point_sprite).
    PointSprite,
    LineSmooth,
    PolygonSmooth,
    LineStipple,
    PolygonStipple,
    PolygonOffsetFill,
    PolygonOffsetLine,
    PolygonOffsetPoint,
    /// `GL_MULTISAMPLE` and the sample coverage enables (`convert::state_ext`).
    Multisample(MultisampleCap),
    /// `GL_MAP1_*` evaluator enables.
    Map1(EvalTarget),
    /// `GL_MAP2_*` evaluator enables.
    Map2(EvalTarget),
    AutoNormal,
}

/// `glHint` targets and modes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum HintTarget {
    PerspectiveCorrection,
    PointSmooth,
    LineSmooth,
    PolygonSmooth,
    Fog,
    GenerateMipmap,
    TextureCompression,
}

/// `glGetString` names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StringName {
    Vendor,
    Renderer,
    Version,
    Extensions,
    /// `GL_SHADING_LANGUAGE_VERSION` (OpenGL 2.0).
    ShadingLanguageVersion,
}

/// Pixel formats accepted by `glReadPixels` so far.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelFormat {
    Red,
    Green,
    Blue,
    Alpha,
    Rgb,
    Rgba,
    Bgr,
    Bgra,
    Luminance,
    LuminanceAlpha,
    DepthComponent,
    StencilIndex,
}

impl PixelFormat {
    pub fn components(self) -> usize {
        use PixelFormat::*;
        match self {
            Red | Green | Blue | Alpha | Luminance | DepthComponent | StencilIndex => 1,
            LuminanceAlpha => 2,
            Rgb | Bgr => 3,
            Rgba | Bgra => 4,
        }
    }
}

/// Component types of pixel transfers (the unpacked ones; packed types come with texturing).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelType {
    UnsignedByte,
    Byte,
    UnsignedShort,
    Short,
    UnsignedInt,
    Int,
    Float,
}

impl PixelType {
    pub fn size(self) -> usize {
        use PixelType::*;
        match self {
            UnsignedByte | Byte => 1,
            UnsignedShort | Short => 2,
            UnsignedInt | Int | Float => 4,
        }
    }
}

/// `glPixelStore` parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelStoreParam {
    Alignment { pack: bool },
    RowLength { pack: bool },
    SkipPixels { pack: bool },
    SkipRows { pack: bool },
    SkipImages { pack: bool },
    ImageHeight { pack: bool },
    SwapBytes { pack: bool },
    LsbFirst { pack: bool },
}

/// Buffers cleared by `glClear`, from its bit mask. `None` when undefined bits are set.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct ClearMask {
    pub color: bool,
    pub depth: bool,
    pub stencil: bool,
    pub accum: bool,
}

/// State readable with `glGet*` so far.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Query {
    Enabled(Capability),
    Viewport,
    DepthRange,
    ModelviewMatrix,
    ProjectionMatrix,
    TextureMatrix,
    TransposeModelviewMatrix,
    TransposeProjectionMatrix,
    TransposeTextureMatrix,
    ModelviewStackDepth,
    ProjectionStackDepth,
    TextureStackDepth,
    MaxModelviewStackDepth,
    MaxProjectionStackDepth,
    MaxTextureStackDepth,
    MaxViewportDims,
    MaxClipPlanes,
    MaxTextureUnits,
    ColorClearValue,
    AccumClearValue,
    DepthClearValue,
    StencilClearValue,
    DepthFunc,
    DepthWritemask,
    ColorWritemask,
    StencilWritemask,
    ScissorBox,
    CullFaceMode,
    FrontFace,
    ShadeModel,
    MatrixMode,
    CurrentColor,
    CurrentSecondaryColor,
    CurrentNormal,
    CurrentTextureCoords,
    CurrentFogCoord,
    EdgeFlag,
    RedBits,
    GreenBits,
    BlueBits,
    AlphaBits,
    DepthBits,
    StencilBits,
    AccumRedBits,
    AccumGreenBits,
    AccumBlueBits,
    AccumAlphaBits,
    IndexBits,
    SubpixelBits,
    AuxBuffers,
    Hint(HintTarget),
    PixelStore(PixelStoreParam),
    Doublebuffer,
    Stereo,
    DrawBuffer,
    ReadBuffer,
    RgbaMode,
    IndexMode,
    PointSize,
    PointSizeRange,
    PointSizeGranularity,
    LineWidth,
    LineWidthRange,
    LineWidthGranularity,
    ActiveTexture,
    ClientActiveTexture,
    MaxAttribStackDepth,
    SampleBuffers,
    Samples,
    AlphaTestFunc,
    AlphaTestRef,
    StencilFunc,
    StencilValueMask,
    StencilRef,
    StencilFail,
    StencilPassDepthFail,
    StencilPassDepthPass,
    BlendSrcRgb,
    BlendDstRgb,
    BlendSrcAlpha,
    BlendDstAlpha,
    BlendEquationRgb,
    BlendEquationAlpha,
    ProvokingVertex,
    QuadsFollowProvokingVertex,
    /// EXT_framebuffer_object.
    FramebufferBinding,
    /// EXT_framebuffer_blit.
    ReadFramebufferBinding,
    RenderbufferBinding,
    MaxColorAttachments,
    MaxRenderbufferSize,
    /// ARB_framebuffer_object.
    MaxSamples,
    CurrentIndex,
    IndexClearValue,
    IndexWritemask,
    BlendColor,
    LogicOpMode,
    MaxLights,
    LightModelAmbient,
    LightModelLocalViewer,
    LightModelTwoSide,
    LightModelColorControl,
    ColorMaterialFace,
    ColorMaterialParameter,
    Fog(FogParam),
    PolygonMode,
    PolygonOffsetFactor,
    PolygonOffsetUnits,
    LineStipplePattern,
    LineStippleRepeat,
    AliasedPointSizeRange,
    AliasedLineWidthRange,
    PointParam(PointParam),
    PixelRect(PixelRectQuery),
    /// Vertex arrays, buffer bindings and display lists (`convert::arrays`).
    Arrays(ArrayQuery),
    /// Attribute stack, multisample, selection and feedback (`convert::state_ext`).
    StateExt(StateExtQuery),
    /// Evaluator grids and limits (`convert::eval`).
    Eval(EvalQuery),
}

/// `glStencilOp` actions (section 4.1.5), including the wrapping ones of GL 1.4.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum StencilOp {
    Keep,
    Zero,
    Replace,
    Incr,
    Decr,
    Invert,
    IncrWrap,
    DecrWrap,
}

/// Blend factors (tables 4.1 and 4.2), including the constant-colour factors.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BlendFactor {
    Zero,
    One,
    SrcColor,
    OneMinusSrcColor,
    DstColor,
    OneMinusDstColor,
    SrcAlpha,
    OneMinusSrcAlpha,
    DstAlpha,
    OneMinusDstAlpha,
    ConstantColor,
    OneMinusConstantColor,
    ConstantAlpha,
    OneMinusConstantAlpha,
    SrcAlphaSaturate,
}

/// Blend equations (`glBlendEquation`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BlendEquation {
    Add,
    Subtract,
    ReverseSubtract,
    Min,
    Max,
}

/// The sixteen logic operations (table 4.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LogicOp {
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
}

impl LogicOp {
    /// Applies the operation to source `s` and destination `d`.
    #[inline(always)]
    pub fn apply(self, s: u8, d: u8) -> u8 {
        use LogicOp::*;
        match self {
            Clear => 0,
            And => s & d,
            AndReverse => s & !d,
            Copy => s,
            AndInverted => !s & d,
            Noop => d,
            Xor => s ^ d,
            Or => s | d,
            Nor => !(s | d),
            Equiv => !(s ^ d),
            Invert => !d,
            OrReverse => s | !d,
            CopyInverted => !s,
            OrInverted => !s | d,
            Nand => !(s & d),
            Set => 0xFF,
        }
    }
}

/// `glLight` parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightParam {
    Ambient,
    Diffuse,
    Specular,
    Position,
    SpotDirection,
    SpotExponent,
    SpotCutoff,
    ConstantAttenuation,
    LinearAttenuation,
    QuadraticAttenuation,
}

impl LightParam {
    /// Values the parameter takes.
    pub fn count(self) -> usize {
        use LightParam::*;
        match self {
            Ambient | Diffuse | Specular | Position => 4,
            SpotDirection => 3,
            _ => 1,
        }
    }

    /// Whether integer forms map the values like colours (table 2.6 style).
    pub fn is_color(self) -> bool {
        matches!(
            self,
            LightParam::Ambient | LightParam::Diffuse | LightParam::Specular
        )
    }
}

/// `glMaterial` parameters (colour indexes are accepted and ignored: no index mode).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MaterialParam {
    Ambient,
    Diffuse,
    Specular,
    Emission,
    Shininess,
    AmbientAndDiffuse,
    ColorIndexes,
}

impl MaterialParam {
    pub fn count(self) -> usize {
        match self {
            MaterialParam::Shininess => 1,
            MaterialParam::ColorIndexes => 3,
            _ => 4,
        }
    }
}

/// `glLightModel` parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightModelParam {
    Ambient,
    LocalViewer,
    TwoSide,
    ColorControl,
}

/// `GL_TEXTURE_ENV_MODE` values (section 3.8.13).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexEnvMode {
    Replace,
    Modulate,
    Decal,
    Blend,
    Add,
    Combine,
    /// NV_texture_env_combine4: `GL_COMBINE` with a fourth argument.
    Combine4,
}

/// `GL_COMBINE_RGB` / `GL_COMBINE_ALPHA` functions (DOT3 only for RGB).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CombineFunc {
    Replace,
    Modulate,
    Add,
    AddSigned,
    Interpolate,
    Subtract,
    Dot3Rgb,
    Dot3Rgba,
}

/// Combiner sources: `TEXTURE`, `TEXTUREn` (crossbar), `CONSTANT`, `PRIMARY_COLOR`, `PREVIOUS`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CombineSource {
    Texture,
    TextureUnit(u8),
    Constant,
    PrimaryColor,
    Previous,
    /// `GL_ZERO` (NV_texture_env_combine4).
    Zero,
}

/// Combiner operands: the value, its complement, or (for RGB) the alpha or its complement.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CombineOperand {
    SrcColor,
    OneMinusSrcColor,
    SrcAlpha,
    OneMinusSrcAlpha,
}

/// `glTexEnv` targets and parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TexEnvParam {
    Mode,
    Color,
    LodBias,
    CombineRgb,
    CombineAlpha,
    /// `GL_SOURCEn_RGB` / `GL_SOURCEn_ALPHA`.
    Source {
        rgb: bool,
        n: usize,
    },
    /// `GL_OPERANDn_RGB` / `GL_OPERANDn_ALPHA`.
    Operand {
        rgb: bool,
        n: usize,
    },
    RgbScale,
    AlphaScale,
}

/// `glTexGen` modes (section 2.11.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexGenMode {
    ObjectLinear,
    EyeLinear,
    SphereMap,
    ReflectionMap,
    NormalMap,
}

/// `glTexGen` parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TexGenParam {
    Mode,
    ObjectPlane,
    EyePlane,
}

/// Fog equations (section 3.10).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FogMode {
    Linear,
    Exp,
    Exp2,
}

/// `glFog` parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FogParam {
    Mode,
    Density,
    Start,
    End,
    Index,
    Color,
    CoordSource,
}

/// `glPolygonMode` modes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PolygonMode {
    Point,
    Line,
    Fill,
}

/// `glPointParameter` parameters (GL 1.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointParam {
    SizeMin,
    SizeMax,
    FadeThresholdSize,
    DistanceAttenuation,
    /// `GL_POINT_SPRITE_COORD_ORIGIN` (GL 2.0; Mesa takes it with ARB_point_sprite).
    SpriteCoordOrigin,
}

/// The colour buffer names of `glDrawBuffer` / `glReadBuffer` (table 4.4 of the GL 1.5 spec).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorBufferName {
    None,
    FrontLeft,
    FrontRight,
    BackLeft,
    BackRight,
    Front,
    Back,
    Left,
    Right,
    FrontAndBack,
    /// `GL_AUXi`.
    Aux(u32),
}

/// `glAccum` operations (section 4.2.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AccumOp {
    Accum,
    Load,
    Return,
    Mult,
    Add,
}

/// `glPixelTransfer` parameters (section 3.6.3, table 3.2; the imaging subset is absent).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelTransferParam {
    MapColor,
    MapStencil,
    IndexShift,
    IndexOffset,
    /// RGBA component index.
    Scale(usize),
    Bias(usize),
    DepthScale,
    DepthBias,
}

/// The ten pixel maps of `glPixelMap` (table 3.3), in this order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelMap {
    IToI,
    SToS,
    IToR,
    IToG,
    IToB,
    IToA,
    RToR,
    GToG,
    BToB,
    AToA,
}

impl PixelMap {
    pub const ALL: [PixelMap; 10] = [
        PixelMap::IToI,
        PixelMap::SToS,
        PixelMap::IToR,
        PixelMap::IToG,
        PixelMap::IToB,
        PixelMap::IToA,
        PixelMap::RToR,
        PixelMap::GToG,
        PixelMap::BToB,
        PixelMap::AToA,
    ];

    pub fn index(self) -> usize {
        self as usize
    }

    /// Maps indexed by a colour or stencil index: their size must be a power of two.
    pub fn indexed_by_index(self) -> bool {
        matches!(
            self,
            PixelMap::IToI
                | PixelMap::SToS
                | PixelMap::IToR
                | PixelMap::IToG
                | PixelMap::IToB
                | PixelMap::IToA
        )
    }

    /// Maps whose values are indices (integers) rather than colour components.
    pub fn holds_indices(self) -> bool {
        matches!(self, PixelMap::IToI | PixelMap::SToS)
    }
}

/// Pixel-rectangle state queries (tables 6.5, 6.17, 6.18).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelRectQuery {
    Transfer(PixelTransferParam),
    MapSize(PixelMap),
    MaxPixelMapTable,
    ZoomX,
    ZoomY,
    RasterPosition,
    RasterPositionValid,
    RasterColor,
    RasterTextureCoords,
    RasterDistance,
    RasterIndex,
}

/// `glCopyPixels` types (section 4.3.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CopyPixelsType {
    Color,
    Depth,
    Stencil,
}

/// Client data of `glDrawPixels`: a colour/depth format the texture path unpacks, or indices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrawPixelsFormat {
    Color(texture::TexPixelFormat),
    Depth,
    StencilIndex,
    ColorIndex,
}

/// Component types of index data (`GL_BITMAP` is one bit per index).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelIndexType {
    Bitmap,
    Plain(texture::TexPixelType),
}

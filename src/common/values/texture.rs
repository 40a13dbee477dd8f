//! Typed values of the texturing calls (part of `values`).

use super::*;

/// The image a `glTexImage*`/`glTexSubImage*`/`glGetTexLevelParameter` call addresses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexImageTarget {
    T1D,
    T2D,
    T3D,
    /// A cube map face, 0..6 in the order +X, -X, +Y, -Y, +Z, -Z.
    CubeFace(usize),
    Proxy1D,
    Proxy2D,
    Proxy3D,
    ProxyCube,
    /// ARB_texture_rectangle.
    Rectangle,
    ProxyRectangle,
}

impl TexImageTarget {
    /// The texture target whose object holds the image.
    pub fn texture_target(self) -> TextureTarget {
        use TexImageTarget::*;
        match self {
            T1D | Proxy1D => TextureTarget::T1D,
            T2D | Proxy2D => TextureTarget::T2D,
            T3D | Proxy3D => TextureTarget::T3D,
            CubeFace(_) | ProxyCube => TextureTarget::CubeMap,
            Rectangle | ProxyRectangle => TextureTarget::Rectangle,
        }
    }

    /// Face index inside the object (0 except for cube faces).
    pub fn face(self) -> usize {
        match self {
            TexImageTarget::CubeFace(f) => f,
            _ => 0,
        }
    }

    pub fn is_proxy(self) -> bool {
        use TexImageTarget::*;
        matches!(
            self,
            Proxy1D | Proxy2D | Proxy3D | ProxyCube | ProxyRectangle
        )
    }

    /// Number of dimensions of the image.
    pub fn dims(self) -> usize {
        match self.texture_target() {
            TextureTarget::T1D => 1,
            TextureTarget::T3D => 3,
            _ => 2,
        }
    }
}

/// `glTexParameter` minification filters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MinFilter {
    Nearest,
    Linear,
    NearestMipmapNearest,
    LinearMipmapNearest,
    NearestMipmapLinear,
    LinearMipmapLinear,
}

impl MinFilter {
    /// Whether the filter uses mipmap levels beyond the base level.
    pub fn is_mipmap(self) -> bool {
        !matches!(self, MinFilter::Nearest | MinFilter::Linear)
    }
}

/// `glTexParameter` magnification filters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MagFilter {
    Nearest,
    Linear,
}

/// Wrap modes of s, t and r.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum WrapMode {
    Repeat,
    Clamp,
    ClampToEdge,
    ClampToBorder,
    MirroredRepeat,
    /// EXT_texture_mirror_clamp (ATI_texture_mirror_once): the coordinate's magnitude, then
    /// clamped like `GL_CLAMP`, `GL_CLAMP_TO_EDGE` or `GL_CLAMP_TO_BORDER`.
    MirrorClamp,
    MirrorClampToEdge,
    MirrorClampToBorder,
}

/// `GL_DEPTH_TEXTURE_MODE`: how a depth value (or comparison result) becomes RGBA.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthTextureMode {
    Luminance,
    Intensity,
    Alpha,
}

/// `glTexParameter`/`glGetTexParameter` parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexParam {
    MinFilter,
    MagFilter,
    WrapS,
    WrapT,
    WrapR,
    BorderColor,
    Priority,
    MinLod,
    MaxLod,
    BaseLevel,
    MaxLevel,
    LodBias,
    GenerateMipmap,
    CompareMode,
    CompareFunc,
    DepthTextureMode,
    MaxAnisotropy,
    /// Query only.
    Resident,
    /// ARB_texture_storage's `GL_TEXTURE_IMMUTABLE_FORMAT`: query only.
    ImmutableFormat,
    /// `GL_TEXTURE_SWIZZLE_R/G/B/A` (EXT_texture_swizzle): the component index.
    Swizzle(usize),
    /// `GL_TEXTURE_SWIZZLE_RGBA`: all four.
    SwizzleRgba,
}

impl TexParam {
    /// Whether the parameter is sampler state, which a sampler object holds too
    /// (ARB_sampler_objects, table 6.23); the others are image state.
    pub fn is_sampler_state(self) -> bool {
        matches!(
            self,
            TexParam::MinFilter
                | TexParam::MagFilter
                | TexParam::WrapS
                | TexParam::WrapT
                | TexParam::WrapR
                | TexParam::BorderColor
                | TexParam::MinLod
                | TexParam::MaxLod
                | TexParam::LodBias
                | TexParam::CompareMode
                | TexParam::CompareFunc
                | TexParam::MaxAnisotropy
        )
    }
}

/// Where a swizzled texture component comes from (EXT_texture_swizzle).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SwizzleSource {
    Red,
    Green,
    Blue,
    Alpha,
    Zero,
    One,
}

impl SwizzleSource {
    pub const IDENTITY: [SwizzleSource; 4] = [
        SwizzleSource::Red,
        SwizzleSource::Green,
        SwizzleSource::Blue,
        SwizzleSource::Alpha,
    ];
}

/// `glGetTexLevelParameter` parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexLevelParam {
    Width,
    Height,
    Depth,
    /// `GL_TEXTURE_INTERNAL_FORMAT` (= `GL_TEXTURE_COMPONENTS`).
    InternalFormat,
    Border,
    RedSize,
    GreenSize,
    BlueSize,
    AlphaSize,
    LuminanceSize,
    IntensitySize,
    DepthSize,
    /// `GL_TEXTURE_STENCIL_SIZE` (EXT_packed_depth_stencil): 0, no format here keeps stencil.
    StencilSize,
    Compressed,
    CompressedImageSize,
    /// `GL_TEXTURE_RED_TYPE_ARB` ... `GL_TEXTURE_DEPTH_TYPE_ARB` (ARB_texture_float): how the
    /// component is stored (`GL_NONE`, `GL_UNSIGNED_NORMALIZED_ARB` or `GL_FLOAT`).
    RedType,
    GreenType,
    BlueType,
    AlphaType,
    LuminanceType,
    IntensityType,
    DepthType,
}

/// Client pixel formats of texture image transfers (section 3.6.4, table 3.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexPixelFormat {
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
    /// `GL_DEPTH_STENCIL` (EXT_packed_depth_stencil) of texture uploads: depth, then a
    /// stencil index that depth textures do not keep (unpacked to slot 3 and dropped).
    DepthStencil,
}

impl TexPixelFormat {
    /// Depth data (`GL_DEPTH_COMPONENT`, `GL_DEPTH_STENCIL`).
    pub fn is_depth(self) -> bool {
        matches!(
            self,
            TexPixelFormat::DepthComponent | TexPixelFormat::DepthStencil
        )
    }

    /// Components per group.
    pub fn components(self) -> usize {
        use TexPixelFormat::*;
        match self {
            Red | Green | Blue | Alpha | Luminance | DepthComponent => 1,
            LuminanceAlpha | DepthStencil => 2,
            Rgb | Bgr => 3,
            Rgba | Bgra => 4,
        }
    }

    /// For each component in memory order, its RGBA slot (0..4; depth uses slot 0, luminance
    /// slot 0 and is copied to G and B on unpacking).
    pub fn slots(self) -> &'static [usize] {
        use TexPixelFormat::*;
        match self {
            Red | Luminance | DepthComponent => &[0],
            Green => &[1],
            Blue => &[2],
            Alpha => &[3],
            LuminanceAlpha | DepthStencil => &[0, 3],
            Rgb => &[0, 1, 2],
            Rgba => &[0, 1, 2, 3],
            Bgr => &[2, 1, 0],
            Bgra => &[2, 1, 0, 3],
        }
    }
}

/// The packed pixel types of GL 1.2 (section 3.6.4, tables 3.8-3.11).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PackedType {
    UByte332,
    UByte233Rev,
    UShort565,
    UShort565Rev,
    UShort4444,
    UShort4444Rev,
    UShort5551,
    UShort1555Rev,
    UInt8888,
    UInt8888Rev,
    UInt1010102,
    UInt2101010Rev,
    /// `GL_UNSIGNED_INT_24_8` (EXT_packed_depth_stencil): 24 bits of depth, 8 of stencil.
    UInt248,
}

impl PackedType {
    /// Bytes of one packed element.
    pub fn size(self) -> usize {
        use PackedType::*;
        match self {
            UByte332 | UByte233Rev => 1,
            UShort565 | UShort565Rev | UShort4444 | UShort4444Rev | UShort5551 | UShort1555Rev => 2,
            UInt8888 | UInt8888Rev | UInt1010102 | UInt2101010Rev | UInt248 => 4,
        }
    }

    /// For the first, second, ... component of the format: (shift, bits) of its bit field.
    pub fn fields(self) -> &'static [(u32, u32)] {
        use PackedType::*;
        match self {
            UByte332 => &[(5, 3), (2, 3), (0, 2)],
            UByte233Rev => &[(0, 3), (3, 3), (6, 2)],
            UShort565 => &[(11, 5), (5, 6), (0, 5)],
            UShort565Rev => &[(0, 5), (5, 6), (11, 5)],
            UShort4444 => &[(12, 4), (8, 4), (4, 4), (0, 4)],
            UShort4444Rev => &[(0, 4), (4, 4), (8, 4), (12, 4)],
            UShort5551 => &[(11, 5), (6, 5), (1, 5), (0, 1)],
            UShort1555Rev => &[(0, 5), (5, 5), (10, 5), (15, 1)],
            UInt8888 => &[(24, 8), (16, 8), (8, 8), (0, 8)],
            UInt8888Rev => &[(0, 8), (8, 8), (16, 8), (24, 8)],
            UInt1010102 => &[(22, 10), (12, 10), (2, 10), (0, 2)],
            UInt2101010Rev => &[(0, 10), (10, 10), (20, 10), (30, 2)],
            UInt248 => &[(8, 24), (0, 8)],
        }
    }
}

/// Client component types of texture image transfers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexPixelType {
    UnsignedByte,
    Byte,
    UnsignedShort,
    Short,
    UnsignedInt,
    Int,
    Float,
    Packed(PackedType),
}

impl TexPixelType {
    /// Bytes of one element (one component, or one packed group).
    pub fn size(self) -> usize {
        use TexPixelType::*;
        match self {
            UnsignedByte | Byte => 1,
            UnsignedShort | Short => 2,
            UnsignedInt | Int | Float => 4,
            Packed(p) => p.size(),
        }
    }

    /// Bytes of one pixel group of `format`.
    pub fn group_size(self, format: TexPixelFormat) -> usize {
        match self {
            TexPixelType::Packed(p) => p.size(),
            t => t.size() * format.components(),
        }
    }
}

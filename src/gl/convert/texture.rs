//! GLenum conversions of the texturing calls (part of `convert`).

use crate::common::values::*;

use crate::gl::enums::*;
use crate::gl::types::{GLenum, GLint};
use crate::texture::format::{BaseFormat, InternalFormat, S3tcFormat};

/// Every image target, including proxies (`glGetTexLevelParameter`).
pub fn tex_image_target(e: GLenum) -> Option<TexImageTarget> {
    use TexImageTarget::*;
    Some(match e {
        GL_TEXTURE_1D => T1D,
        GL_TEXTURE_2D => T2D,
        GL_TEXTURE_3D => T3D,
        GL_PROXY_TEXTURE_1D => Proxy1D,
        GL_PROXY_TEXTURE_2D => Proxy2D,
        GL_PROXY_TEXTURE_3D => Proxy3D,
        GL_PROXY_TEXTURE_CUBE_MAP => ProxyCube,
        GL_TEXTURE_RECTANGLE_ARB => Rectangle,
        GL_PROXY_TEXTURE_RECTANGLE_ARB => ProxyRectangle,
        e if (GL_TEXTURE_CUBE_MAP_POSITIVE_X..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z).contains(&e) => {
            CubeFace((e - GL_TEXTURE_CUBE_MAP_POSITIVE_X) as usize)
        }
        _ => return None,
    })
}

/// Targets of `glTexImage{dims}D` (`proxy`: proxies allowed) and of the sub-image and copy
/// calls (`proxy` false).
pub fn tex_image_target_for(e: GLenum, dims: usize, proxy: bool) -> Option<TexImageTarget> {
    let t = tex_image_target(e)?;
    (t.dims() == dims && (proxy || !t.is_proxy())).then_some(t)
}

impl MinFilter {
    pub fn to_gl(self) -> GLenum {
        use MinFilter::*;
        match self {
            Nearest => GL_NEAREST,
            Linear => GL_LINEAR,
            NearestMipmapNearest => GL_NEAREST_MIPMAP_NEAREST,
            LinearMipmapNearest => GL_LINEAR_MIPMAP_NEAREST,
            NearestMipmapLinear => GL_NEAREST_MIPMAP_LINEAR,
            LinearMipmapLinear => GL_LINEAR_MIPMAP_LINEAR,
        }
    }
}

pub fn min_filter(e: GLenum) -> Option<MinFilter> {
    use MinFilter::*;
    Some(match e {
        GL_NEAREST => Nearest,
        GL_LINEAR => Linear,
        GL_NEAREST_MIPMAP_NEAREST => NearestMipmapNearest,
        GL_LINEAR_MIPMAP_NEAREST => LinearMipmapNearest,
        GL_NEAREST_MIPMAP_LINEAR => NearestMipmapLinear,
        GL_LINEAR_MIPMAP_LINEAR => LinearMipmapLinear,
        _ => return None,
    })
}

impl MagFilter {
    pub fn to_gl(self) -> GLenum {
        match self {
            MagFilter::Nearest => GL_NEAREST,
            MagFilter::Linear => GL_LINEAR,
        }
    }
}

pub fn mag_filter(e: GLenum) -> Option<MagFilter> {
    Some(match e {
        GL_NEAREST => MagFilter::Nearest,
        GL_LINEAR => MagFilter::Linear,
        _ => return None,
    })
}

impl WrapMode {
    pub fn to_gl(self) -> GLenum {
        match self {
            WrapMode::Repeat => GL_REPEAT,
            WrapMode::Clamp => GL_CLAMP,
            WrapMode::ClampToEdge => GL_CLAMP_TO_EDGE,
            WrapMode::ClampToBorder => GL_CLAMP_TO_BORDER,
            WrapMode::MirroredRepeat => GL_MIRRORED_REPEAT,
            WrapMode::MirrorClamp => GL_MIRROR_CLAMP_EXT,
            WrapMode::MirrorClampToEdge => GL_MIRROR_CLAMP_TO_EDGE_EXT,
            WrapMode::MirrorClampToBorder => GL_MIRROR_CLAMP_TO_BORDER_EXT,
        }
    }
}

pub fn wrap_mode(e: GLenum) -> Option<WrapMode> {
    Some(match e {
        GL_REPEAT => WrapMode::Repeat,
        GL_CLAMP => WrapMode::Clamp,
        GL_CLAMP_TO_EDGE => WrapMode::ClampToEdge,
        GL_CLAMP_TO_BORDER => WrapMode::ClampToBorder,
        GL_MIRRORED_REPEAT => WrapMode::MirroredRepeat,
        GL_MIRROR_CLAMP_EXT => WrapMode::MirrorClamp,
        GL_MIRROR_CLAMP_TO_EDGE_EXT => WrapMode::MirrorClampToEdge,
        GL_MIRROR_CLAMP_TO_BORDER_EXT => WrapMode::MirrorClampToBorder,
        _ => return None,
    })
}

impl DepthTextureMode {
    pub fn to_gl(self) -> GLenum {
        match self {
            DepthTextureMode::Luminance => GL_LUMINANCE,
            DepthTextureMode::Intensity => GL_INTENSITY,
            DepthTextureMode::Alpha => GL_ALPHA,
        }
    }
}

pub fn depth_texture_mode(e: GLenum) -> Option<DepthTextureMode> {
    Some(match e {
        GL_LUMINANCE => DepthTextureMode::Luminance,
        GL_INTENSITY => DepthTextureMode::Intensity,
        GL_ALPHA => DepthTextureMode::Alpha,
        _ => return None,
    })
}

/// `GL_TEXTURE_COMPARE_MODE`: `Some(true)` for `GL_COMPARE_R_TO_TEXTURE`, `Some(false)` for
/// `GL_NONE`.
pub fn texture_compare_mode(e: GLenum) -> Option<bool> {
    match e {
        GL_COMPARE_R_TO_TEXTURE => Some(true),
        GL_NONE => Some(false),
        _ => None,
    }
}

pub fn compare_mode_to_gl(on: bool) -> GLenum {
    if on {
        GL_COMPARE_R_TO_TEXTURE
    } else {
        GL_NONE
    }
}

impl SwizzleSource {
    pub fn to_gl(self) -> GLenum {
        match self {
            SwizzleSource::Red => GL_RED,
            SwizzleSource::Green => GL_GREEN,
            SwizzleSource::Blue => GL_BLUE,
            SwizzleSource::Alpha => GL_ALPHA,
            SwizzleSource::Zero => GL_ZERO,
            SwizzleSource::One => GL_ONE,
        }
    }
}

pub fn swizzle_source(e: GLenum) -> Option<SwizzleSource> {
    Some(match e {
        GL_RED => SwizzleSource::Red,
        GL_GREEN => SwizzleSource::Green,
        GL_BLUE => SwizzleSource::Blue,
        GL_ALPHA => SwizzleSource::Alpha,
        GL_ZERO => SwizzleSource::Zero,
        GL_ONE => SwizzleSource::One,
        _ => return None,
    })
}

pub fn tex_param(e: GLenum) -> Option<TexParam> {
    use TexParam::*;
    Some(match e {
        GL_TEXTURE_MIN_FILTER => MinFilter,
        GL_TEXTURE_MAG_FILTER => MagFilter,
        GL_TEXTURE_WRAP_S => WrapS,
        GL_TEXTURE_WRAP_T => WrapT,
        GL_TEXTURE_WRAP_R => WrapR,
        GL_TEXTURE_BORDER_COLOR => BorderColor,
        GL_TEXTURE_PRIORITY => Priority,
        GL_TEXTURE_MIN_LOD => MinLod,
        GL_TEXTURE_MAX_LOD => MaxLod,
        GL_TEXTURE_BASE_LEVEL => BaseLevel,
        GL_TEXTURE_MAX_LEVEL => MaxLevel,
        GL_TEXTURE_LOD_BIAS => LodBias,
        GL_GENERATE_MIPMAP => GenerateMipmap,
        GL_TEXTURE_COMPARE_MODE => CompareMode,
        GL_TEXTURE_COMPARE_FUNC => CompareFunc,
        GL_DEPTH_TEXTURE_MODE => DepthTextureMode,
        GL_TEXTURE_MAX_ANISOTROPY_EXT => MaxAnisotropy,
        GL_TEXTURE_RESIDENT => Resident,
        GL_TEXTURE_IMMUTABLE_FORMAT => ImmutableFormat,
        GL_TEXTURE_SWIZZLE_R => Swizzle(0),
        GL_TEXTURE_SWIZZLE_G => Swizzle(1),
        GL_TEXTURE_SWIZZLE_B => Swizzle(2),
        GL_TEXTURE_SWIZZLE_A => Swizzle(3),
        GL_TEXTURE_SWIZZLE_RGBA => SwizzleRgba,
        _ => return None,
    })
}

pub fn tex_level_param(e: GLenum) -> Option<TexLevelParam> {
    use TexLevelParam::*;
    Some(match e {
        GL_TEXTURE_WIDTH => Width,
        GL_TEXTURE_HEIGHT => Height,
        GL_TEXTURE_DEPTH => Depth,
        GL_TEXTURE_INTERNAL_FORMAT => InternalFormat,
        GL_TEXTURE_BORDER => Border,
        GL_TEXTURE_RED_SIZE => RedSize,
        GL_TEXTURE_GREEN_SIZE => GreenSize,
        GL_TEXTURE_BLUE_SIZE => BlueSize,
        GL_TEXTURE_ALPHA_SIZE => AlphaSize,
        GL_TEXTURE_LUMINANCE_SIZE => LuminanceSize,
        GL_TEXTURE_INTENSITY_SIZE => IntensitySize,
        GL_TEXTURE_DEPTH_SIZE => DepthSize,
        GL_TEXTURE_STENCIL_SIZE_EXT => StencilSize,
        GL_TEXTURE_COMPRESSED => Compressed,
        GL_TEXTURE_COMPRESSED_IMAGE_SIZE => CompressedImageSize,
        GL_TEXTURE_RED_TYPE_ARB => RedType,
        GL_TEXTURE_GREEN_TYPE_ARB => GreenType,
        GL_TEXTURE_BLUE_TYPE_ARB => BlueType,
        GL_TEXTURE_ALPHA_TYPE_ARB => AlphaType,
        GL_TEXTURE_LUMINANCE_TYPE_ARB => LuminanceType,
        GL_TEXTURE_INTENSITY_TYPE_ARB => IntensityType,
        GL_TEXTURE_DEPTH_TYPE_ARB => DepthType,
        _ => return None,
    })
}

/// The client format of a texture upload (`glTexImage*`, `glTexSubImage*`): those of
/// [`tex_pixel_format`] and `GL_DEPTH_STENCIL` (EXT_packed_depth_stencil, whose depth goes
/// into depth textures; piglit's GL 1.x texture tests upload depth so).
pub fn tex_upload_format(e: GLenum) -> Option<TexPixelFormat> {
    if e == GL_DEPTH_STENCIL_EXT {
        return Some(TexPixelFormat::DepthStencil);
    }
    tex_pixel_format(e)
}

pub fn tex_pixel_format(e: GLenum) -> Option<TexPixelFormat> {
    use TexPixelFormat::*;
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
        _ => return None,
    })
}

impl PackedType {
    /// Whether `format` may be used with this type (otherwise `GL_INVALID_OPERATION`).
    pub fn accepts(self, format: TexPixelFormat) -> bool {
        if self == PackedType::UInt248 || format == TexPixelFormat::DepthStencil {
            return self == PackedType::UInt248 && format == TexPixelFormat::DepthStencil;
        }
        match self.fields().len() {
            3 => format == TexPixelFormat::Rgb,
            _ => matches!(format, TexPixelFormat::Rgba | TexPixelFormat::Bgra),
        }
    }
}

pub fn tex_pixel_type(e: GLenum) -> Option<TexPixelType> {
    use PackedType::*;
    use TexPixelType::*;
    Some(match e {
        GL_UNSIGNED_BYTE => UnsignedByte,
        GL_BYTE => Byte,
        GL_UNSIGNED_SHORT => UnsignedShort,
        GL_SHORT => Short,
        GL_UNSIGNED_INT => UnsignedInt,
        GL_INT => Int,
        GL_FLOAT => Float,
        GL_UNSIGNED_BYTE_3_3_2 => Packed(UByte332),
        GL_UNSIGNED_BYTE_2_3_3_REV => Packed(UByte233Rev),
        GL_UNSIGNED_SHORT_5_6_5 => Packed(UShort565),
        GL_UNSIGNED_SHORT_5_6_5_REV => Packed(UShort565Rev),
        GL_UNSIGNED_SHORT_4_4_4_4 => Packed(UShort4444),
        GL_UNSIGNED_SHORT_4_4_4_4_REV => Packed(UShort4444Rev),
        GL_UNSIGNED_SHORT_5_5_5_1 => Packed(UShort5551),
        GL_UNSIGNED_SHORT_1_5_5_5_REV => Packed(UShort1555Rev),
        GL_UNSIGNED_INT_8_8_8_8 => Packed(UInt8888),
        GL_UNSIGNED_INT_8_8_8_8_REV => Packed(UInt8888Rev),
        GL_UNSIGNED_INT_10_10_10_2 => Packed(UInt1010102),
        GL_UNSIGNED_INT_2_10_10_10_REV => Packed(UInt2101010Rev),
        GL_UNSIGNED_INT_24_8_EXT => Packed(UInt248),
        _ => return None,
    })
}

/// The S3TC formats.
pub fn s3tc_format(e: GLenum) -> Option<S3tcFormat> {
    Some(match e {
        GL_COMPRESSED_RGB_S3TC_DXT1_EXT => S3tcFormat::RgbDxt1,
        GL_COMPRESSED_RGBA_S3TC_DXT1_EXT => S3tcFormat::RgbaDxt1,
        GL_COMPRESSED_RGBA_S3TC_DXT3_EXT => S3tcFormat::RgbaDxt3,
        GL_COMPRESSED_RGBA_S3TC_DXT5_EXT => S3tcFormat::RgbaDxt5,
        _ => None?,
    })
}

impl S3tcFormat {
    pub fn to_gl(self) -> GLenum {
        match self {
            S3tcFormat::RgbDxt1 => GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
            S3tcFormat::RgbaDxt1 => GL_COMPRESSED_RGBA_S3TC_DXT1_EXT,
            S3tcFormat::RgbaDxt3 => GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
            S3tcFormat::RgbaDxt5 => GL_COMPRESSED_RGBA_S3TC_DXT5_EXT,
        }
    }
}

/// The values of `GL_COMPRESSED_TEXTURE_FORMATS` (its length is
/// `GL_NUM_COMPRESSED_TEXTURE_FORMATS`).
pub const COMPRESSED_TEXTURE_FORMATS: [GLenum; 4] = [
    GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT1_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT5_EXT,
];

impl BaseFormat {
    pub fn to_gl(self) -> GLenum {
        match self {
            BaseFormat::Alpha => GL_ALPHA,
            BaseFormat::Luminance => GL_LUMINANCE,
            BaseFormat::LuminanceAlpha => GL_LUMINANCE_ALPHA,
            BaseFormat::Intensity => GL_INTENSITY,
            BaseFormat::Rgb => GL_RGB,
            BaseFormat::Rgba => GL_RGBA,
            BaseFormat::DepthComponent => GL_DEPTH_COMPONENT,
            BaseFormat::Red => GL_RED,
            BaseFormat::Rg => GL_RG,
        }
    }
}

/// The internal format of a texture image from the `internalformat` argument (tables 3.15,
/// 3.16, 3.17 and EXT_texture_compression_s3tc). `dims` is 1, 2 or 3: the generic compressed
/// formats compress (to S3TC) only two-dimensional images, and S3TC formats are accepted only
/// there. Returns `None` for a value the call does not accept.
pub fn internal_format(value: GLint, dims: usize) -> Option<InternalFormat> {
    use BaseFormat::*;
    let e = value as GLenum;
    let (base, bits): (BaseFormat, u8) = match e {
        1 => (Luminance, 8),
        2 => (LuminanceAlpha, 8),
        3 => (Rgb, 8),
        4 => (Rgba, 8),
        GL_ALPHA | GL_COMPRESSED_ALPHA => (Alpha, 8),
        GL_LUMINANCE | GL_COMPRESSED_LUMINANCE => (Luminance, 8),
        GL_LUMINANCE_ALPHA | GL_COMPRESSED_LUMINANCE_ALPHA => (LuminanceAlpha, 8),
        GL_INTENSITY | GL_COMPRESSED_INTENSITY => (Intensity, 8),
        GL_RGB => (Rgb, 8),
        GL_RGBA => (Rgba, 8),
        GL_ALPHA4 => (Alpha, 4),
        GL_ALPHA8 => (Alpha, 8),
        GL_ALPHA12 => (Alpha, 12),
        GL_ALPHA16 => (Alpha, 16),
        GL_LUMINANCE4 => (Luminance, 4),
        GL_LUMINANCE8 => (Luminance, 8),
        GL_LUMINANCE12 => (Luminance, 12),
        GL_LUMINANCE16 => (Luminance, 16),
        GL_LUMINANCE4_ALPHA4 => (LuminanceAlpha, 4),
        GL_LUMINANCE6_ALPHA2 => (LuminanceAlpha, 6),
        GL_LUMINANCE8_ALPHA8 => (LuminanceAlpha, 8),
        GL_LUMINANCE12_ALPHA4 | GL_LUMINANCE12_ALPHA12 => (LuminanceAlpha, 12),
        GL_LUMINANCE16_ALPHA16 => (LuminanceAlpha, 16),
        GL_INTENSITY4 => (Intensity, 4),
        GL_INTENSITY8 => (Intensity, 8),
        GL_INTENSITY12 => (Intensity, 12),
        GL_INTENSITY16 => (Intensity, 16),
        GL_R3_G3_B2 => (Rgb, 3),
        GL_RGB4 => (Rgb, 4),
        GL_RGB5 => (Rgb, 5),
        GL_RGB8 => (Rgb, 8),
        GL_RGB10 => (Rgb, 10),
        GL_RGB12 => (Rgb, 12),
        GL_RGB16 => (Rgb, 16),
        GL_RGBA2 => (Rgba, 2),
        GL_RGBA4 => (Rgba, 4),
        GL_RGB5_A1 => (Rgba, 5),
        GL_RGBA8 => (Rgba, 8),
        GL_RGB10_A2 => (Rgba, 10),
        GL_RGBA12 => (Rgba, 12),
        GL_RGBA16 => (Rgba, 16),
        GL_DEPTH_COMPONENT => (DepthComponent, 24),
        GL_DEPTH_COMPONENT16 => (DepthComponent, 16),
        GL_DEPTH_COMPONENT24 => (DepthComponent, 24),
        GL_DEPTH_COMPONENT32 => (DepthComponent, 32),
        // Beyond GL 1.5, for captures of programs run on newer drivers: ARB_texture_rg and its
        // generic compressed forms (stored uncompressed), and the depth-stencil formats
        // (depth, and a stencil index per texel that sampling does not read).
        GL_RED | GL_COMPRESSED_RED | GL_R8 => (Red, 8),
        GL_R16 => (Red, 16),
        GL_RG | GL_COMPRESSED_RG | GL_RG8 => (Rg, 8),
        GL_RG16 => (Rg, 16),
        // ARB_texture_float (and ARB_texture_rg's float formats): unclamped float components.
        GL_R16F => return Some(InternalFormat::float(value, Red, 16)),
        GL_R32F => return Some(InternalFormat::float(value, Red, 32)),
        GL_RG16F => return Some(InternalFormat::float(value, Rg, 16)),
        GL_RG32F => return Some(InternalFormat::float(value, Rg, 32)),
        GL_RGB16F_ARB => return Some(InternalFormat::float(value, Rgb, 16)),
        GL_RGB32F_ARB => return Some(InternalFormat::float(value, Rgb, 32)),
        GL_RGBA16F_ARB => return Some(InternalFormat::float(value, Rgba, 16)),
        GL_RGBA32F_ARB => return Some(InternalFormat::float(value, Rgba, 32)),
        GL_ALPHA16F_ARB => return Some(InternalFormat::float(value, Alpha, 16)),
        GL_ALPHA32F_ARB => return Some(InternalFormat::float(value, Alpha, 32)),
        GL_LUMINANCE16F_ARB => return Some(InternalFormat::float(value, Luminance, 16)),
        GL_LUMINANCE32F_ARB => return Some(InternalFormat::float(value, Luminance, 32)),
        GL_LUMINANCE_ALPHA16F_ARB => return Some(InternalFormat::float(value, LuminanceAlpha, 16)),
        GL_LUMINANCE_ALPHA32F_ARB => return Some(InternalFormat::float(value, LuminanceAlpha, 32)),
        GL_INTENSITY16F_ARB => return Some(InternalFormat::float(value, Intensity, 16)),
        GL_INTENSITY32F_ARB => return Some(InternalFormat::float(value, Intensity, 32)),
        GL_DEPTH_COMPONENT32F => (DepthComponent, 32),
        GL_DEPTH_STENCIL_EXT | GL_DEPTH24_STENCIL8_EXT => {
            return Some(InternalFormat::depth_stencil(value, 24))
        }
        GL_DEPTH32F_STENCIL8 => return Some(InternalFormat::depth_stencil(value, 32)),
        GL_COMPRESSED_RGB => {
            return Some(if dims == 2 {
                InternalFormat::s3tc(value, S3tcFormat::RgbDxt1)
            } else {
                InternalFormat::new(value, Rgb, 8)
            })
        }
        GL_COMPRESSED_RGBA => {
            return Some(if dims == 2 {
                InternalFormat::s3tc(value, S3tcFormat::RgbaDxt3)
            } else {
                InternalFormat::new(value, Rgba, 8)
            })
        }
        _ => {
            let f = s3tc_format(e)?;
            return (dims == 2).then(|| InternalFormat::s3tc(value, f));
        }
    };
    Some(InternalFormat::new(value, base, bits))
}

/// Whether `value` names an internal format of any dimensionality (used to tell a bad value,
/// `GL_INVALID_VALUE`, from a compressed format on the wrong target, `GL_INVALID_ENUM`).
pub fn is_internal_format(value: GLint) -> bool {
    internal_format(value, 2).is_some()
}

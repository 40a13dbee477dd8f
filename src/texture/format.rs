//! Internal formats (OpenGL 1.5 tables 3.15-3.17): the base format a texture behaves as, and
//! the storage tilegl picks to keep at least the precision asked for.

/// Base internal formats (table 3.15) plus depth (ARB_depth_texture).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BaseFormat {
    Alpha,
    Luminance,
    LuminanceAlpha,
    Intensity,
    Rgb,
    Rgba,
    DepthComponent,
    /// GL 3.0's one- and two-component colour formats (ARB_texture_rg), which captures of
    /// programs running on newer drivers copy into: (R, 0, 0, 1) and (R, G, 0, 1).
    Red,
    Rg,
}

impl BaseFormat {
    /// Stored components per texel.
    pub fn components(self) -> usize {
        use BaseFormat::*;
        match self {
            Alpha | Luminance | Intensity | DepthComponent | Red => 1,
            LuminanceAlpha | Rg => 2,
            Rgb => 3,
            Rgba => 4,
        }
    }

    /// For each stored component, the slot of the "internal RGBA" it lives in: luminance,
    /// intensity and depth live in R, alpha in A.
    pub fn slots(self) -> &'static [usize] {
        use BaseFormat::*;
        match self {
            Alpha => &[3],
            Luminance | Intensity | DepthComponent | Red => &[0],
            LuminanceAlpha => &[0, 3],
            Rg => &[0, 1],
            Rgb => &[0, 1, 2],
            Rgba => &[0, 1, 2, 3],
        }
    }

    /// The texture source colour (R, G, B, A) of a filtered internal value whose components sit
    /// in the slots of [`BaseFormat::slots`] (OpenGL 2.0 table 3.20: ALPHA (0,0,0,A), LUMINANCE
    /// (L,L,L,1), LUMINANCE_ALPHA (L,L,L,A), INTENSITY (I,I,I,I), RGB (R,G,B,1), RGBA). Depth is
    /// handled by the sampler (`GL_DEPTH_TEXTURE_MODE`).
    #[inline]
    pub fn expand(self, v: [f32; 4]) -> [f32; 4] {
        use BaseFormat::*;
        match self {
            Alpha => [0.0, 0.0, 0.0, v[3]],
            Luminance | DepthComponent => [v[0], v[0], v[0], 1.0],
            LuminanceAlpha => [v[0], v[0], v[0], v[3]],
            Intensity => [v[0]; 4],
            Rgb => [v[0], v[1], v[2], 1.0],
            Rgba => v,
            Red => [v[0], 0.0, 0.0, 1.0],
            Rg => [v[0], v[1], 0.0, 1.0],
        }
    }
}

/// The S3TC formats of EXT_texture_compression_s3tc.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum S3tcFormat {
    RgbDxt1,
    RgbaDxt1,
    RgbaDxt3,
    RgbaDxt5,
}

impl S3tcFormat {
    /// Bytes per 4x4 block.
    pub fn block_bytes(self) -> usize {
        match self {
            S3tcFormat::RgbDxt1 | S3tcFormat::RgbaDxt1 => 8,
            _ => 16,
        }
    }

    pub fn base(self) -> BaseFormat {
        match self {
            S3tcFormat::RgbDxt1 => BaseFormat::Rgb,
            _ => BaseFormat::Rgba,
        }
    }

    /// Bytes of a `width` x `height` image.
    pub fn image_bytes(self, width: usize, height: usize) -> usize {
        width.div_ceil(4) * height.div_ceil(4) * self.block_bytes()
    }
}

/// How texel components are stored: unsigned normalised integers of 8, 16 or 32 bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Storage {
    U8,
    U16,
    U32,
}

/// The internal format of one texture image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct InternalFormat {
    /// The value the application gave (reported by `GL_TEXTURE_INTERNAL_FORMAT`, except for
    /// generic compressed formats, which report the specific format chosen).
    pub requested: i32,
    pub base: BaseFormat,
    /// Bits per component requested (the largest component of a sized format; 8 for generic
    /// formats, 24 for generic depth).
    pub bits: u8,
    /// The S3TC format the image is stored in, if compressed.
    pub compressed: Option<S3tcFormat>,
    /// A depth-stencil format (EXT_packed_depth_stencil, ARB_depth_buffer_float): the image
    /// keeps an 8-bit stencil index per texel beside its depth (`TexImage::stencil`), which
    /// sampling does not read.
    pub stencil: bool,
}

impl InternalFormat {
    pub fn new(requested: i32, base: BaseFormat, bits: u8) -> InternalFormat {
        InternalFormat {
            requested,
            base,
            bits,
            compressed: None,
            stencil: false,
        }
    }

    /// A depth format with `bits` of depth and 8 of stencil.
    pub fn depth_stencil(requested: i32, bits: u8) -> InternalFormat {
        InternalFormat {
            stencil: true,
            ..InternalFormat::new(requested, BaseFormat::DepthComponent, bits)
        }
    }

    pub fn s3tc(requested: i32, f: S3tcFormat) -> InternalFormat {
        InternalFormat {
            requested,
            base: f.base(),
            bits: 8,
            compressed: Some(f),
            stencil: false,
        }
    }

    /// Storage with at least the requested precision: 8 bits up to 8 requested bits, 16 up to
    /// 16, 32 for 24- and 32-bit depth.
    pub fn storage(self) -> Storage {
        match self.bits {
            0..=8 => Storage::U8,
            9..=16 => Storage::U16,
            _ => Storage::U32,
        }
    }

    /// Bits actually kept per component (reported by `GL_TEXTURE_*_SIZE`): the storage size,
    /// except depth, which reports the requested 16, 24 or 32.
    pub fn component_bits(self) -> i32 {
        if self.base == BaseFormat::DepthComponent {
            return self.bits as i32;
        }
        match self.storage() {
            Storage::U8 => 8,
            Storage::U16 => 16,
            Storage::U32 => 32,
        }
    }

    /// Bytes one texel takes in storage (uncompressed).
    pub fn texel_bytes(self) -> u64 {
        let per_component = match self.storage() {
            Storage::U8 => 1,
            Storage::U16 => 2,
            Storage::U32 => 4,
        };
        per_component * self.base.components() as u64
    }

    /// The value `GL_TEXTURE_INTERNAL_FORMAT` reports.
    pub fn reported(self) -> i32 {
        match self.compressed {
            Some(f) => f.to_gl() as i32,
            None => self.requested,
        }
    }

    pub fn is_depth(self) -> bool {
        self.base == BaseFormat::DepthComponent
    }
}

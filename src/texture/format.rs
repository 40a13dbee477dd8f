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

/// How texel components are stored: unsigned normalised integers of 8, 16 or 32 bits, or
/// unclamped 32-bit floats (ARB_texture_float; the 16-bit float formats keep f32 storage
/// holding values rounded to half precision).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Storage {
    U8,
    U16,
    U32,
    F32,
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
    /// Floating-point colour components (ARB_texture_float's 16F and 32F formats, and the
    /// R/RG float formats of ARB_texture_rg): stored unclamped, `bits` 16 or 32.
    pub float: bool,
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
            float: false,
            compressed: None,
            stencil: false,
        }
    }

    /// A floating-point colour format of `bits` (16 or 32) per component.
    pub fn float(requested: i32, base: BaseFormat, bits: u8) -> InternalFormat {
        InternalFormat {
            float: true,
            ..InternalFormat::new(requested, base, bits)
        }
    }

    /// A value as a float component of this format keeps it: unchanged for 32-bit floats,
    /// rounded to the nearest half-precision value for the 16-bit ones (section 2.1.2 of
    /// ARB_texture_float; overflow gives infinity).
    #[inline]
    pub fn float_value(self, v: f32) -> f32 {
        if self.bits == 16 {
            round_to_half(v)
        } else {
            v
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
            float: false,
            compressed: Some(f),
            stencil: false,
        }
    }

    /// Storage with at least the requested precision: 8 bits up to 8 requested bits, 16 up to
    /// 16, 32 for 24- and 32-bit depth.
    pub fn storage(self) -> Storage {
        if self.float {
            return Storage::F32;
        }
        match self.bits {
            0..=8 => Storage::U8,
            9..=16 => Storage::U16,
            _ => Storage::U32,
        }
    }

    /// Bits actually kept per component (reported by `GL_TEXTURE_*_SIZE`): the storage size,
    /// except depth, which reports the requested 16, 24 or 32.
    pub fn component_bits(self) -> i32 {
        if self.base == BaseFormat::DepthComponent || self.float {
            return self.bits as i32;
        }
        match self.storage() {
            Storage::U8 => 8,
            Storage::U16 => 16,
            Storage::U32 | Storage::F32 => 32,
        }
    }

    /// Bytes one texel takes in storage (uncompressed).
    pub fn texel_bytes(self) -> u64 {
        let per_component = match self.storage() {
            Storage::U8 => 1,
            Storage::U16 => 2,
            Storage::U32 | Storage::F32 => 4,
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

/// `v` rounded to the nearest IEEE half-precision value (ties to even), as an f32: values
/// beyond the largest half (65504) round to infinity, small ones to half denormals or zero;
/// NaN stays NaN.
pub fn round_to_half(v: f32) -> f32 {
    if !v.is_finite() {
        return v;
    }
    let a = v.abs();
    // The spacing of halves around `a`: 2^(e - 10) for normal halves (e = floor(log2 a),
    // at least -14), 2^-24 for denormals.
    let e = if a >= f32::MIN_POSITIVE {
        ((a.to_bits() >> 23) as i32 - 127).max(-14)
    } else {
        -14
    };
    let ulp = f32::from_bits(((e - 10 + 127) as u32) << 23);
    let q = (a / ulp).round_ties_even() * ulp;
    let q = if q > 65504.0 {
        // Halves up to 65504 + half an ulp (16) round down to 65504, beyond to infinity.
        if a < 65520.0 {
            65504.0
        } else {
            f32::INFINITY
        }
    } else {
        q
    };
    q.copysign(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Half values from section 2.1.2: (-1)^S 2^(E-15) (1 + M/1024), denormals 2^-14 M/1024.
    #[test]
    fn half_rounding_follows_the_half_encoding() {
        let half = |s: u32, e: i32, m: u32| -> f32 {
            let sign = if s == 1 { -1.0 } else { 1.0 };
            if e == 0 {
                sign * 2f32.powi(-14) * (m as f32 / 1024.0)
            } else {
                sign * 2f32.powi(e - 15) * (1.0 + m as f32 / 1024.0)
            }
        };
        // Every half is kept.
        for e in 0..31 {
            for m in [0, 1, 2, 511, 512, 1023] {
                for s in [0, 1] {
                    let h = half(s, e, m);
                    assert_eq!(round_to_half(h), h, "{s} {e} {m}");
                }
            }
        }
        // 1 + 1/2048 is half-way between 1 and 1 + 1/1024: ties to even (1).
        assert_eq!(round_to_half(1.0 + 1.0 / 2048.0), 1.0);
        assert_eq!(round_to_half(1.0 + 3.0 / 2048.0), 1.0 + 2.0 / 1024.0);
        assert_eq!(
            round_to_half(1.0 + 1.0 / 4096.0 + 1.0 / 2048.0),
            1.0 + 1.0 / 1024.0
        );
        assert_eq!(round_to_half(0.1), half(0, 11, 614));
        assert_eq!(round_to_half(-2.5), -2.5);
        assert_eq!(round_to_half(70000.0), f32::INFINITY);
        assert_eq!(round_to_half(65519.0), 65504.0);
        assert_eq!(round_to_half(2f32.powi(-26)), 0.0);
        assert_eq!(round_to_half(3.0 * 2f32.powi(-26)), 2f32.powi(-24));
        assert!(round_to_half(f32::NAN).is_nan());
    }
}

//! Texture objects: parameters, the image array per face and level, and completeness
//! (section 3.8.10).

use std::sync::Arc;

use super::format::BaseFormat;
use super::image::TexImage;
use super::sample::{BoundInner, BoundTexture};
use crate::common::values::{
    CompareFunc, DepthTextureMode, MagFilter, MinFilter, SwizzleSource, TextureTarget, WrapMode,
};

/// Largest 1D/2D texture side (`GL_MAX_TEXTURE_SIZE`): Mesa's (llvmpipe and softpipe), so
/// programs that size their textures by the query get the same pictures. A texture too large
/// for memory gives `GL_OUT_OF_MEMORY` (allocations are fallible). Texel addresses stay far
/// inside `i32`/`i64` (the fast path takes sides up to 2^15) and the LOD is computed in
/// floating point from texel-space derivatives, so nothing depends on the size beyond the
/// level count.
pub const MAX_TEXTURE_SIZE: i32 = 16384;
/// Largest 3D texture side (`GL_MAX_3D_TEXTURE_SIZE`), Mesa's.
pub const MAX_3D_TEXTURE_SIZE: i32 = 2048;
/// Largest cube map face side (`GL_MAX_CUBE_MAP_TEXTURE_SIZE`), Mesa's.
pub const MAX_CUBE_MAP_TEXTURE_SIZE: i32 = 16384;
/// Mipmap levels of a 16384 texture (levels 0..=14).
pub const MAX_LEVELS: usize = 15;
/// `GL_MAX_TEXTURE_LOD_BIAS`.
pub const MAX_TEXTURE_LOD_BIAS: f32 = 16.0;
/// `GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT`.
pub const MAX_TEXTURE_MAX_ANISOTROPY: f32 = 16.0;

/// Largest texture image a proxy query accepts, in bytes of storage with its whole mipmap
/// chain: llvmpipe's per-resource limit (2 GiB) counted as llvmpipe's proxy check counts it,
/// so a program that probes the largest size it can have (piglit's tex3d-maxsize) settles on
/// the same one as on Mesa. Real images have their own limit, `image::MAX_IMAGE_BYTES` (1 GiB
/// for the level itself); the two agree on every size measured on Mesa.
pub const MAX_PROXY_BYTES: u64 = 2 << 30;

/// Largest side for a target.
pub fn max_size(target: TextureTarget) -> i32 {
    match target {
        TextureTarget::T3D => MAX_3D_TEXTURE_SIZE,
        TextureTarget::CubeMap => MAX_CUBE_MAP_TEXTURE_SIZE,
        _ => MAX_TEXTURE_SIZE,
    }
}

/// Number of levels a target allows (level must be below this).
pub fn level_count(target: TextureTarget) -> usize {
    if target == TextureTarget::Rectangle {
        // ARB_texture_rectangle: only level 0.
        return 1;
    }
    // log2(max size) + 1
    (31 - max_size(target).leading_zeros()) as usize + 1
}

/// The sampler state of a texture object (table 6.16).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SamplerParams {
    pub min_filter: MinFilter,
    pub mag_filter: MagFilter,
    /// s, t, r.
    pub wrap: [WrapMode; 3],
    /// Clamped to [0, 1].
    pub border_color: [f32; 4],
    pub min_lod: f32,
    pub max_lod: f32,
    pub base_level: i32,
    pub max_level: i32,
    pub lod_bias: f32,
    pub max_anisotropy: f32,
    /// `GL_TEXTURE_COMPARE_MODE` is `GL_COMPARE_R_TO_TEXTURE`.
    pub compare: bool,
    pub compare_func: CompareFunc,
    pub depth_mode: DepthTextureMode,
    pub generate_mipmap: bool,
    /// EXT_texture_swizzle: the source of each sampled component.
    pub swizzle: [SwizzleSource; 4],
}

impl SamplerParams {
    /// These parameters with the sampler state of a sampler object bound to the unit
    /// (ARB_sampler_objects, table 6.23: wrap modes, filters, border colour, LOD clamps and
    /// bias, comparison, anisotropy) taken from `s`; the image state (base and max level,
    /// depth texture mode, swizzle, mipmap generation) stays the texture's. The border colour
    /// is clamped to [0, 1] as `glTexParameter` stores it.
    pub fn with_sampler(&self, s: &SamplerParams) -> SamplerParams {
        SamplerParams {
            min_filter: s.min_filter,
            mag_filter: s.mag_filter,
            wrap: s.wrap,
            border_color: s.border_color.map(|c| c.clamp(0.0, 1.0)),
            min_lod: s.min_lod,
            max_lod: s.max_lod,
            lod_bias: s.lod_bias,
            max_anisotropy: s.max_anisotropy,
            compare: s.compare,
            compare_func: s.compare_func,
            ..*self
        }
    }

    /// Whether a rectangle texture may be sampled with these parameters
    /// (ARB_texture_rectangle: no mipmap filter, only the clamping wrap modes); a sampler
    /// object that sets another makes the texture incomplete (ARB_sampler_objects, section
    /// 3.9.2).
    pub fn fit_rectangle(&self) -> bool {
        !self.min_filter.is_mipmap()
            && self.wrap.iter().all(|w| {
                matches!(
                    w,
                    WrapMode::Clamp | WrapMode::ClampToEdge | WrapMode::ClampToBorder
                )
            })
    }
}

impl Default for SamplerParams {
    fn default() -> Self {
        SamplerParams {
            min_filter: MinFilter::NearestMipmapLinear,
            mag_filter: MagFilter::Linear,
            wrap: [WrapMode::Repeat; 3],
            border_color: [0.0; 4],
            min_lod: -1000.0,
            max_lod: 1000.0,
            base_level: 0,
            max_level: 1000,
            lod_bias: 0.0,
            max_anisotropy: 1.0,
            compare: false,
            compare_func: CompareFunc::LessEqual,
            depth_mode: DepthTextureMode::Luminance,
            generate_mipmap: false,
            swizzle: SwizzleSource::IDENTITY,
        }
    }
}

/// One texture object.
#[derive(Clone, Debug)]
pub struct TextureObject {
    /// The target it was first bound to (`None` for a name not yet bound).
    pub target: Option<TextureTarget>,
    pub params: SamplerParams,
    pub priority: f32,
    /// `images[face][level]`; face 0 for all but cube maps.
    pub images: [[Option<TexImage>; MAX_LEVELS]; 6],
    /// ARB_texture_storage: the `levels` of the `glTexStorage*` that made the texture
    /// immutable (`GL_TEXTURE_IMMUTABLE_FORMAT` is true), or `None`.
    pub immutable_levels: Option<usize>,
}

impl TextureObject {
    pub fn new(target: Option<TextureTarget>) -> TextureObject {
        let mut params = SamplerParams::default();
        if target == Some(TextureTarget::Rectangle) {
            // ARB_texture_rectangle's defaults: no mipmaps, clamped.
            params.min_filter = MinFilter::Linear;
            params.wrap = [WrapMode::ClampToEdge; 3];
        }
        TextureObject {
            target,
            params,
            priority: 1.0,
            images: std::array::from_fn(|_| std::array::from_fn(|_| None)),
            immutable_levels: None,
        }
    }

    /// `level_base`: `GL_TEXTURE_BASE_LEVEL`, clamped to `[0, levels - 1]` for an immutable
    /// texture (ARB_texture_storage, section 3.8.6).
    pub fn level_base(&self) -> usize {
        let base = self.params.base_level.max(0) as usize;
        match self.immutable_levels {
            Some(n) => base.min(n.saturating_sub(1)),
            None => base,
        }
    }

    /// `level_max`: `GL_TEXTURE_MAX_LEVEL`, clamped to `[level_base, levels - 1]` for an
    /// immutable texture.
    pub fn level_max(&self) -> i32 {
        match self.immutable_levels {
            Some(n) => (self.params.max_level.max(0) as usize)
                .clamp(self.level_base(), n.saturating_sub(1)) as i32,
            None => self.params.max_level,
        }
    }

    pub fn image(&self, face: usize, level: usize) -> Option<&TexImage> {
        self.images.get(face)?.get(level)?.as_ref()
    }

    pub fn image_mut(&mut self, face: usize, level: usize) -> Option<&mut TexImage> {
        self.images.get_mut(face)?.get_mut(level)?.as_mut()
    }

    /// The last level of the mipmap array given the base level image's inner size: `p` of
    /// section 3.8.10 (floor(log2(max side)) levels below the base), limited by MAX_LEVEL.
    pub fn last_level(&self, target: TextureTarget, base: usize, inner: [i32; 3]) -> usize {
        let dims = dims_of(target);
        let largest = inner[..dims].iter().copied().max().unwrap_or(1).max(1);
        let p = (31 - (largest as u32).leading_zeros()) as usize;
        let max_level = self.level_max().max(0) as usize;
        (base + p).min(max_level).min(level_count(target) - 1)
    }

    /// The levels `base..=last` used for sampling when the texture is complete for `target`
    /// (section 3.8.10, including cube completeness), else `None`.
    pub fn complete_range(&self, target: TextureTarget) -> Option<(usize, usize)> {
        self.complete_range_with(target, &self.params)
    }

    /// [`TextureObject::complete_range`] when sampled with `params` (its own, or with a
    /// sampler object's state: the minification filter decides whether the mipmap levels
    /// count).
    fn complete_range_with(
        &self,
        target: TextureTarget,
        params: &SamplerParams,
    ) -> Option<(usize, usize)> {
        let base = self.level_base();
        if base >= level_count(target) {
            return None;
        }
        let faces = if target == TextureTarget::CubeMap {
            6
        } else {
            1
        };
        let dims = dims_of(target);
        let b0 = self.image(0, base)?;
        let inner0 = b0.inner_size();
        if inner0[..dims].iter().any(|&s| s <= 0) {
            return None;
        }
        if target == TextureTarget::CubeMap {
            // Cube completeness: six square faces of one size, format and border.
            for f in 0..6 {
                let img = self.image(f, base)?;
                let s = img.inner_size();
                if s[0] != s[1]
                    || s[0] != inner0[0]
                    || img.format != b0.format
                    || img.border != b0.border
                {
                    return None;
                }
            }
        }
        if !params.min_filter.is_mipmap() {
            return Some((base, base));
        }
        if self.level_max() < base as i32 {
            return None;
        }
        let last = self.last_level(target, base, inner0);
        for level in base + 1..=last {
            let shift = level - base;
            for f in 0..faces {
                let img = self.image(f, level)?;
                let s = img.inner_size();
                for d in 0..dims {
                    if s[d] != (inner0[d] >> shift).max(1) {
                        return None;
                    }
                }
                if img.format != b0.format || img.border != b0.border {
                    return None;
                }
            }
        }
        Some((base, last))
    }

    /// An immutable snapshot for sampling as `target`, or `None` when incomplete.
    pub fn snapshot(&self, target: TextureTarget) -> Option<BoundTexture> {
        self.snapshot_with(target, self.params)
    }

    /// [`TextureObject::snapshot`] sampled with `params` instead of the texture's own
    /// (ARB_sampler_objects: completeness follows the sampler's filter too).
    pub fn snapshot_with(
        &self,
        target: TextureTarget,
        params: SamplerParams,
    ) -> Option<BoundTexture> {
        let (base, last) = self.complete_range_with(target, &params)?;
        let faces = if target == TextureTarget::CubeMap {
            6
        } else {
            1
        };
        let mut levels = Vec::with_capacity(faces);
        for f in 0..faces {
            let mut v = Vec::with_capacity(last - base + 1);
            for l in base..=last {
                v.push(self.image(f, l)?.clone());
            }
            levels.push(v);
        }
        let base_img = self.image(0, base)?;
        let inner = base_img.inner_size();
        Some(BoundTexture::from_inner(Arc::new(BoundInner {
            target,
            params,
            format: base_img.format,
            base: base_img.format.base,
            base_size: [inner[0] as f32, inner[1] as f32, inner[2] as f32],
            clamp_float: levels.iter().flatten().any(|l| l.format.float),
            levels,
        })))
    }

    /// The base format of the base level image, if any.
    pub fn base_format(&self) -> Option<BaseFormat> {
        let base = self.level_base();
        self.image(0, base).map(|i| i.format.base)
    }
}

/// Dimensions sampled for a target (cube faces are 2D).
pub fn dims_of(target: TextureTarget) -> usize {
    match target {
        TextureTarget::T1D => 1,
        TextureTarget::T3D => 3,
        _ => 2,
    }
}

//! Texture entry points (`glTexImage*`, `glTexParameter*`, `glBindTexture`, ...).
//!
//! Every call validates in the order of its error rules and changes nothing when it records an
//! error. Images are unpacked by `texture::pixels`; objects, completeness and sampling live in
//! `texture`.
#![allow(clippy::too_many_arguments)]

use super::pixel_rect::PixelTransfer;
use super::Context;
use crate::common::values::{
    PackedType, PixelIndexType, TexImageTarget, TexLevelParam, TexParam, TexPixelFormat,
    TexPixelType, TextureTarget,
};
use crate::gl::convert;
use crate::gl::enums::*;
use crate::texture::format::{BaseFormat, InternalFormat, S3tcFormat};
use crate::texture::image::{clamp01, TexImage};
use crate::texture::object::{level_count, max_size, MAX_PROXY_BYTES, MAX_TEXTURE_MAX_ANISOTROPY};
use crate::texture::{mipmap, pixels, ObjectMut, ObjectRef};

mod compressed;
mod copy;
mod image;
mod params;
mod samplers;
mod storage;

/// A validation failure: the error to record.
type Check<T> = Result<T, GLenum>;

/// Parameter values as given to `glTexParameter{i,f}[v]`.
#[derive(Clone, Copy)]
enum Values<'a> {
    F(&'a [GLfloat]),
    I(&'a [GLint]),
}

impl Values<'_> {
    fn len(&self) -> usize {
        match self {
            Values::F(v) => v.len(),
            Values::I(v) => v.len(),
        }
    }

    /// Value `i` as a float (integers converted directly).
    fn float(&self, i: usize) -> f32 {
        match self {
            Values::F(v) => v.get(i).copied().unwrap_or(0.0),
            Values::I(v) => v.get(i).copied().unwrap_or(0) as f32,
        }
    }

    /// Value `i` as an enum (floats truncated to an integer; NaN is 0).
    fn enumv(&self, i: usize) -> GLenum {
        match self {
            Values::F(v) => v.get(i).copied().unwrap_or(0.0) as i32 as GLenum,
            Values::I(v) => v.get(i).copied().unwrap_or(0) as GLenum,
        }
    }

    /// Value `i` as an integer (floats rounded to nearest, saturating).
    fn int(&self, i: usize) -> i32 {
        match self {
            Values::F(v) => v.get(i).copied().unwrap_or(0.0).round() as i32,
            Values::I(v) => v.get(i).copied().unwrap_or(0),
        }
    }

    /// Value `i` as a colour component: integers map by table 2.9 ((2c + 1) / (2^32 - 1)).
    fn color(&self, i: usize) -> f32 {
        match self {
            Values::F(v) => v.get(i).copied().unwrap_or(0.0),
            Values::I(v) => {
                ((2.0 * v.get(i).copied().unwrap_or(0) as f64 + 1.0) / u32::MAX as f64) as f32
            }
        }
    }
}

/// Checks a packed type against a format (`GL_INVALID_OPERATION`).
fn check_format_type(format: TexPixelFormat, ty: TexPixelType) -> Check<()> {
    match ty {
        TexPixelType::Packed(p) if !p.accepts(format) => Err(GL_INVALID_OPERATION),
        _ => Ok(()),
    }
}

/// The client format and type of a texture upload or `glGetTexImage`: the colour and depth
/// formats with their types, and
/// `GL_DEPTH_STENCIL` with `GL_UNSIGNED_INT_24_8` (EXT_packed_depth_stencil; another type
/// with it is INVALID_ENUM, as that extension says). `GL_STENCIL_INDEX`, a pixel format
/// texture images do not take, is INVALID_OPERATION (the rule GL 3.x states for formats
/// that do not match the internal format's kind).
pub(super) fn upload_format_type(
    format: GLenum,
    type_: GLenum,
) -> Check<(TexPixelFormat, TexPixelType)> {
    if format == GL_STENCIL_INDEX && convert::tex_pixel_type(type_).is_some() {
        return Err(GL_INVALID_OPERATION);
    }
    let f = convert::tex_upload_format(format).ok_or(GL_INVALID_ENUM)?;
    let t = convert::tex_pixel_type(type_).ok_or(GL_INVALID_ENUM)?;
    let packed_depth_stencil = t == TexPixelType::Packed(PackedType::UInt248);
    if (f == TexPixelFormat::DepthStencil) != packed_depth_stencil {
        return Err(if f == TexPixelFormat::DepthStencil {
            GL_INVALID_ENUM
        } else {
            GL_INVALID_OPERATION
        });
    }
    Ok((f, t))
}

/// The client data of a texture upload: groups of a pixel format, or colour indices.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum UploadSource {
    Groups(TexPixelFormat, TexPixelType),
    /// `GL_COLOR_INDEX` (also as `GL_BITMAP` bits): indices taken as `glDrawPixels` takes
    /// them and turned into RGBA by the pixel transfer's index shift and offset and the
    /// `I_TO_*` maps (sections 3.6.5 and 3.8.1).
    ColorIndex(PixelIndexType),
}

impl UploadSource {
    fn is_depth(self) -> bool {
        matches!(self, UploadSource::Groups(f, _) if f.is_depth())
    }

    /// [`check_format_type`] for groups.
    fn check_packed(self) -> Check<()> {
        match self {
            UploadSource::Groups(f, t) => check_format_type(f, t),
            UploadSource::ColorIndex(_) => Ok(()),
        }
    }
}

/// [`upload_format_type`], with `GL_COLOR_INDEX` data too (a packed type with it is
/// INVALID_OPERATION, as for any format the packed type does not fit).
pub(super) fn upload_source(format: GLenum, type_: GLenum) -> Check<UploadSource> {
    if format != GL_COLOR_INDEX {
        let (f, t) = upload_format_type(format, type_)?;
        return Ok(UploadSource::Groups(f, t));
    }
    match convert::pixel_index_type(type_) {
        Some(t) => Ok(UploadSource::ColorIndex(t)),
        None if convert::tex_pixel_type(type_).is_some() => Err(GL_INVALID_OPERATION),
        None => Err(GL_INVALID_ENUM),
    }
}

impl Context {
    /// Bytes of client data an upload of `n` texels from `src` reads (`None` on overflow).
    fn upload_len(&self, dims: usize, n: [usize; 3], src: UploadSource) -> Option<usize> {
        match src {
            UploadSource::Groups(f, t) => {
                pixels::layout(&self.unpack, dims, n, f, t).map(|l| l.end)
            }
            UploadSource::ColorIndex(t) => Some(pixels::index_image_len(&self.unpack, dims, n, t))
                .filter(|&len| len > 0 || n.contains(&0)),
        }
    }

    /// The RGBA texels of colour-index client data, x fastest (clamped to [0, 1] as texture
    /// storage requires; the maps hold values in [0, 1] already). `None` when `data` is too
    /// short.
    fn index_texels(
        &self,
        data: &[u8],
        dims: usize,
        n: [usize; 3],
        ty: PixelIndexType,
    ) -> Check<Vec<[f32; 4]>> {
        let mut out = Vec::new();
        out.try_reserve(n[0] * n[1] * n[2])
            .map_err(|_| GL_OUT_OF_MEMORY)?;
        let t = &self.pixel_transfer;
        pixels::for_each_index(data, &self.unpack, dims, n, ty, |i| {
            out.push(t.index_to_color(i).map(|c| c.clamp(0.0, 1.0)));
        })
        .ok_or(GL_INVALID_VALUE)?;
        Ok(out)
    }
}

/// The client data of a `GL_DEPTH_STENCIL` upload, whose stencil indices go into a
/// depth-stencil image beside the depth.
pub(super) struct StencilUpload<'a> {
    pub data: &'a [u8],
    pub layout: &'a pixels::Layout,
    pub pf: TexPixelFormat,
    pub pt: TexPixelType,
    pub swap: bool,
}

impl StencilUpload<'_> {
    /// Stores the indices of the `n` block at `origin` (the packed word's low 8 bits, through
    /// the index shift and offset and the stencil map, section 3.6.5); nothing for other
    /// formats or an image without stencil.
    pub fn store(&self, img: &mut TexImage, t: &PixelTransfer, origin: [usize; 3], n: [usize; 3]) {
        if self.pf != TexPixelFormat::DepthStencil || img.stencil.is_none() {
            return;
        }
        let l = self.layout;
        img.store_stencil_block(origin, n, |x, y, z| {
            let at = l.start + z * l.image_stride + y * l.row_stride + x * l.group;
            let v = pixels::unpack_group(self.data, at, self.pf, self.pt, self.swap)[3];
            t.stencil((v * 255.0).round() as i64)
        });
    }
}

fn pixel_format_type(format: GLenum, type_: GLenum) -> Check<(TexPixelFormat, TexPixelType)> {
    let f = convert::tex_pixel_format(format).ok_or(GL_INVALID_ENUM)?;
    let t = convert::tex_pixel_type(type_).ok_or(GL_INVALID_ENUM)?;
    Ok((f, t))
}

fn check_level(target: TextureTarget, level: GLint) -> Check<usize> {
    if level < 0 || level as usize >= level_count(target) {
        Err(GL_INVALID_VALUE)
    } else {
        Ok(level as usize)
    }
}

/// Whether a value names a specific S3TC format (for the compressed entry points).
fn s3tc(e: GLenum) -> Option<S3tcFormat> {
    convert::s3tc_format(e)
}

/// The internal format of a `glTexImage`/`glCopyTexImage` call.
fn check_internal_format(value: GLint, dims: usize) -> Check<InternalFormat> {
    match convert::internal_format(value, dims) {
        Some(f) => Ok(f),
        None if convert::is_internal_format(value) => Err(GL_INVALID_ENUM),
        None => Err(GL_INVALID_VALUE),
    }
}

/// Size checks of a `glTexImage`-style call: border 0 or 1, sizes (borders included) at
/// least 2 * border, inner sizes at most the target's maximum, cube faces square. Returns the
/// stored size `[w, h, d]` (1 for unused dimensions). `Err(None)` means "too large" (a proxy
/// records no error for it).
fn check_size(
    target: TexImageTarget,
    level: usize,
    size: [GLsizei; 3],
    border: GLint,
) -> Result<[i32; 3], Option<GLenum>> {
    let dims = target.dims();
    // Rectangle textures have no border (ARB_texture_rectangle).
    let rectangle = target.texture_target() == TextureTarget::Rectangle;
    if border != 0 && (border != 1 || rectangle) {
        return Err(Some(GL_INVALID_VALUE));
    }
    let mut out = [1; 3];
    for d in 0..dims {
        let inner = size[d] as i64 - 2 * border as i64;
        if size[d] < 0 || inner < 0 {
            return Err(Some(GL_INVALID_VALUE));
        }
        out[d] = size[d];
    }
    if matches!(
        target,
        TexImageTarget::CubeFace(_) | TexImageTarget::ProxyCube
    ) && size[0] != size[1]
    {
        return Err(Some(GL_INVALID_VALUE));
    }
    // Level `lod` of a mipmap holds images up to 2^(k - lod) (section 3.8.1, k the log2 of
    // the maximum size).
    let max = (max_size(target.texture_target()) >> level) as i64;
    for &s in &size[..dims] {
        if s as i64 - 2 * border as i64 > max {
            return Err(None);
        }
    }
    Ok(out)
}

/// Whether a proxy image of `size` (border included) fits: its storage with the whole mipmap
/// chain down from `size` within `MAX_PROXY_BYTES`, as llvmpipe's proxy check counts it (the
/// program may add the levels later). So a 1024 x 1024 x 2048 `GL_INTENSITY8` proxy (2 GiB,
/// 16/7 GiB with its levels) is refused on both, and 1024^3 accepted.
fn proxy_fits(size: [i32; 3], format: InternalFormat) -> bool {
    let mut level = size.map(|s| s.max(0) as u64);
    let mut bytes = 0u64;
    loop {
        let texels = level.iter().product::<u64>();
        bytes = bytes.saturating_add(texels.saturating_mul(format.texel_bytes()));
        if level.iter().all(|&s| s <= 1) {
            break;
        }
        level = level.map(|s| (s / 2).max(1));
    }
    bytes <= MAX_PROXY_BYTES
}

/// Whether client groups of `format`/`type` are, byte for byte, texels of an uncompressed
/// `internal` image with 8-bit storage (unsigned bytes, the same components in the same
/// order, no pixel transfer): then uploads copy rows instead of converting each group
/// (c / 255 stored as round(255 c / 255) is c).
pub(super) fn bytes_are_texels(
    transfer: bool,
    format: TexPixelFormat,
    ty: TexPixelType,
    internal: InternalFormat,
) -> bool {
    !transfer
        && ty == TexPixelType::UnsignedByte
        && internal.compressed.is_none()
        && internal.storage() == crate::texture::format::Storage::U8
        && format.slots() == internal.base.slots()
}

/// One client group as the texel it becomes (section 3.8.1): unpacked, through pixel transfer
/// when `xfer` is given, then clamped to [0, 1], except for the colour of a float internal
/// format (ARB_texture_float: "Otherwise, the components are not modified").
#[allow(clippy::too_many_arguments)]
pub(super) fn unpack_texel(
    data: &[u8],
    at: usize,
    pf: TexPixelFormat,
    pt: TexPixelType,
    swap: bool,
    xfer: Option<&PixelTransfer>,
    internal: InternalFormat,
) -> [f32; 4] {
    let depth = pf.is_depth();
    if internal.float && !depth {
        let rgba = pixels::unpack_group_unclamped(data, at, pf, pt, swap);
        return xfer.map_or(rgba, |t| t.color(rgba));
    }
    let rgba = pixels::unpack_group(data, at, pf, pt, swap);
    xfer.map_or(rgba, |t| t.texel(depth, rgba))
}

/// Whether an upload of unpacked `ty` components may take `TexImage::store_converted` (the
/// conversion without per-texel dispatch): no pixel transfer and no byte swapping of
/// multi-byte components.
pub(super) fn converts_directly(transfer: bool, swap: bool, ty: TexPixelType) -> bool {
    !transfer && (!swap || ty.size() == 1) && !matches!(ty, TexPixelType::Packed(_))
}

/// Whether an internal format may be used on a target (depth textures: 1D, 2D and, as
/// ARB_texture_rectangle allows with ARB_depth_texture, rectangles).
fn check_depth_target(target: TexImageTarget, f: InternalFormat) -> Check<()> {
    if f.is_depth()
        && !matches!(
            target.texture_target(),
            TextureTarget::T1D | TextureTarget::T2D | TextureTarget::Rectangle
        )
    {
        return Err(GL_INVALID_OPERATION);
    }
    Ok(())
}

impl Context {
    /// The texture snapshot unit `unit` samples for the next draw: the object bound to its
    /// highest-precedence enabled target, or `None` when no target is enabled or the texture
    /// is incomplete (see [`crate::texture::TextureState::bound_for_unit`]).
    pub fn bound_texture(&self, unit: usize) -> Option<crate::texture::BoundTexture> {
        self.textures.bound_for_unit(unit)
    }

    // ----- objects

    pub(crate) fn gen_textures(&mut self, n: GLsizei, textures: &mut [GLuint]) {
        if n < 0 || textures.len() < n as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.textures.gen_names(&mut textures[..n as usize]);
    }

    pub(crate) fn bind_texture(&mut self, target: GLenum, texture: GLuint) {
        let Some(t) = convert::texture_target(target) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if !self.textures.bind(self.active_texture, t, texture) {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        self.invalidate();
    }

    pub(crate) fn delete_textures(&mut self, n: GLsizei, textures: &[GLuint]) {
        if n < 0 || textures.len() < n as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        for &name in &textures[..n as usize] {
            self.fbo_detach_texture(name);
            self.textures.delete(name);
        }
        self.invalidate();
    }

    pub(crate) fn is_texture(&mut self, texture: GLuint) -> GLboolean {
        self.textures.is_texture(texture) as GLboolean
    }

    pub(crate) fn prioritize_textures(
        &mut self,
        n: GLsizei,
        textures: &[GLuint],
        priorities: &[GLfloat],
    ) {
        if n < 0 || textures.len() < n as usize || priorities.len() < n as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        for (&name, &p) in textures.iter().zip(priorities).take(n as usize) {
            if let Some(mut o) = self.textures.object_mut(name) {
                o.priority = clamp01(p);
            }
        }
    }

    pub(crate) fn are_textures_resident(
        &mut self,
        n: GLsizei,
        textures: &[GLuint],
        residences: &mut [GLboolean],
    ) -> GLboolean {
        if n < 0 || textures.len() < n as usize {
            self.record_error(GL_INVALID_VALUE);
            return GL_FALSE as GLboolean;
        }
        if textures[..n as usize]
            .iter()
            .any(|&t| !self.textures.is_texture(t))
        {
            self.record_error(GL_INVALID_VALUE);
            return GL_FALSE as GLboolean;
        }
        // Every texture is resident: GL_TRUE and `residences` untouched.
        let _ = residences;
        GL_TRUE as GLboolean
    }

    // ----- helpers

    /// The object a (non-proxy or proxy) image target addresses on the active unit.
    fn image_object_mut(&mut self, target: TexImageTarget) -> ObjectMut<'_> {
        let t = target.texture_target();
        if target.is_proxy() {
            ObjectMut::Own(self.textures.proxy_mut(t))
        } else {
            self.fbo_before_texture_change();
            self.textures.bound_mut(self.active_texture, t)
        }
    }

    /// `glGenerateMipmapEXT`: levels base+1 ..= q of the texture bound to `target` on the
    /// active unit, each the box-filtered level above (every face of a cube map, which must
    /// be cube complete: `GL_INVALID_OPERATION` otherwise). Nothing without a base image.
    pub(crate) fn generate_mipmaps_of_bound(&mut self, t: TextureTarget) -> Result<(), GLenum> {
        let mut obj = self.textures.bound_mut(self.active_texture, t);
        let base = obj.level_base();
        let faces = if t == TextureTarget::CubeMap { 6 } else { 1 };
        if t == TextureTarget::CubeMap {
            let first = obj.image(0, base).map(|i| (i.width, i.height, i.format));
            let cube_complete = first.is_some_and(|(w, h, f)| {
                w == h
                    && (0..6).all(|face| {
                        obj.image(face, base)
                            .is_some_and(|i| i.width == w && i.height == h && i.format == f)
                    })
            });
            if !cube_complete {
                return Err(GL_INVALID_OPERATION);
            }
        }
        for face in 0..faces {
            let Some(img) = obj.image(face, base) else {
                continue;
            };
            let last = obj
                .last_level(t, base, img.inner_size())
                .min(level_count(t) - 1);
            for l in base + 1..=last {
                let Some(parent) = obj.image(face, l - 1) else {
                    break;
                };
                match mipmap::downsample(parent) {
                    Ok(child) => obj.images[face][l] = Some(child),
                    Err(_) => return Err(GL_OUT_OF_MEMORY),
                }
            }
        }
        Ok(())
    }

    /// The image at `target`/`level` (a copy sharing the texels).
    fn image_at(&self, target: TexImageTarget, level: usize) -> Option<TexImage> {
        self.with_image(target, level, TexImage::clone)
    }

    /// `f` of the image at `target`/`level`, borrowed: what commands that then write into the
    /// image check it with, since a copy still sharing the texels during the write would make
    /// the write copy the whole image first (copy-on-write).
    fn with_image<R>(
        &self,
        target: TexImageTarget,
        level: usize,
        f: impl FnOnce(&TexImage) -> R,
    ) -> Option<R> {
        self.image_object(target).image(target.face(), level).map(f)
    }

    /// ARB_texture_storage: `glTexImage*`, `glCopyTexImage*` and `glCompressedTexImage*` of
    /// an immutable texture are `GL_INVALID_OPERATION`.
    fn check_mutable(&self, target: TexImageTarget) -> Check<()> {
        if !target.is_proxy() && self.image_object(target).immutable_levels.is_some() {
            return Err(GL_INVALID_OPERATION);
        }
        Ok(())
    }

    fn image_object(&self, target: TexImageTarget) -> ObjectRef<'_> {
        let t = target.texture_target();
        if target.is_proxy() {
            ObjectRef::Own(self.textures.proxy(t))
        } else {
            self.textures.bound(self.active_texture, t)
        }
    }

    /// Stores a new image and regenerates mipmaps when it is the base level of an object with
    /// `GL_GENERATE_MIPMAP`.
    fn install_image(&mut self, target: TexImageTarget, level: usize, img: TexImage) {
        let face = target.face();
        self.image_object_mut(target).images[face][level] = Some(img);
        if !target.is_proxy() {
            self.after_image_change(target, level);
        }
    }

    /// Generates mipmaps if needed and marks the draw state stale.
    fn after_image_change(&mut self, target: TexImageTarget, level: usize) {
        let face = target.face();
        let tt = target.texture_target();
        let mut obj = self.image_object_mut(target);
        let mut oom = false;
        if obj.params.generate_mipmap && level == obj.level_base() {
            if let Some(base) = obj.image(face, level) {
                let last = obj
                    .last_level(tt, level, base.inner_size())
                    .min(level_count(tt) - 1);
                for l in level + 1..=last {
                    let Some(parent) = obj.image(face, l - 1) else {
                        break;
                    };
                    match mipmap::downsample(parent) {
                        Ok(child) => obj.images[face][l] = Some(child),
                        Err(_) => {
                            oom = true;
                            break;
                        }
                    }
                }
            }
        }
        drop(obj);
        if oom {
            self.record_error(GL_OUT_OF_MEMORY);
        }
        self.invalidate();
    }
}

/// Sub-image bounds (section 3.8.2): `-b <= offset` and `offset + size <= inner + b` on every
/// dimension used, else `GL_INVALID_VALUE`.
fn check_sub_region(
    dims: usize,
    offset: [GLint; 3],
    size: [GLsizei; 3],
    b: [i32; 3],
    inner: [i32; 3],
) -> Check<()> {
    for d in 0..dims {
        let (o, s) = (offset[d] as i64, size[d] as i64);
        if o < -(b[d] as i64) || o + s > inner[d] as i64 + b[d] as i64 {
            return Err(GL_INVALID_VALUE);
        }
    }
    Ok(())
}

/// EXT_texture_compression_s3tc: sub-image updates of an S3TC image start on a multiple of 4
/// and cover whole blocks unless they reach the image's edge, else `GL_INVALID_OPERATION`.
fn check_compressed_alignment(img: &TexImage, offset: [GLint; 3], size: [GLsizei; 3]) -> Check<()> {
    if img.format.compressed.is_none() {
        return Ok(());
    }
    let full = [img.width, img.height];
    for d in 0..2 {
        if offset[d] % 4 != 0 || (size[d] % 4 != 0 && offset[d] + size[d] != full[d]) {
            return Err(GL_INVALID_OPERATION);
        }
    }
    Ok(())
}

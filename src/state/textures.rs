//! Texture entry points (`glTexImage*`, `glTexParameter*`, `glBindTexture`, ...).
//!
//! Every call validates in the order of its error rules and changes nothing when it records an
//! error. Images are unpacked by `texture::pixels`; objects, completeness and sampling live in
//! `texture`.
#![allow(clippy::too_many_arguments)]

use super::Context;
use crate::api::convert::{
    self, TexImageTarget, TexLevelParam, TexParam, TexPixelFormat, TexPixelType, TextureTarget,
};
use crate::api::enums::*;
use crate::texture::format::{BaseFormat, InternalFormat, S3tcFormat};
use crate::texture::image::{clamp01, TexImage};
use crate::texture::object::{level_count, max_size, TextureObject, MAX_TEXTURE_MAX_ANISOTROPY};
use crate::texture::{mipmap, pixels};

/// The texture entry points `impl Gl for Context` forwards (see `gl_forward_all!`).
macro_rules! texture_entry_points {
    () => {
        gl_forward_all!(
            gen_textures,
            bind_texture,
            delete_textures,
            is_texture,
            prioritize_textures,
            are_textures_resident,
            tex_image_1d,
            tex_image_2d,
            tex_image_3d,
            tex_sub_image_1d,
            tex_sub_image_2d,
            tex_sub_image_3d,
            copy_tex_image_1d,
            copy_tex_image_2d,
            copy_tex_sub_image_1d,
            copy_tex_sub_image_2d,
            copy_tex_sub_image_3d,
            get_tex_image,
            tex_parameterf,
            tex_parameterfv,
            tex_parameteri,
            tex_parameteriv,
            get_tex_parameterfv,
            get_tex_parameteriv,
            get_tex_level_parameterfv,
            get_tex_level_parameteriv,
            compressed_tex_image_1d,
            compressed_tex_image_2d,
            compressed_tex_image_3d,
            compressed_tex_sub_image_1d,
            compressed_tex_sub_image_2d,
            compressed_tex_sub_image_3d,
            get_compressed_tex_image,
        );
    };
}

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
    let max = max_size(target.texture_target()) as i64;
    for &s in &size[..dims] {
        if s as i64 - 2 * border as i64 > max {
            return Err(None);
        }
    }
    Ok(out)
}

/// Whether an internal format may be used on a target (depth textures: 1D and 2D only).
fn check_depth_target(target: TexImageTarget, f: InternalFormat) -> Check<()> {
    if f.is_depth()
        && !matches!(
            target.texture_target(),
            TextureTarget::T1D | TextureTarget::T2D
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
            if let Some(o) = self.textures.object_mut(name) {
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
    fn image_object_mut(&mut self, target: TexImageTarget) -> &mut TextureObject {
        let t = target.texture_target();
        if target.is_proxy() {
            self.textures.proxy_mut(t)
        } else {
            self.textures.bound_mut(self.active_texture, t)
        }
    }

    fn image_object(&self, target: TexImageTarget) -> &TextureObject {
        let t = target.texture_target();
        if target.is_proxy() {
            self.textures.proxy(t)
        } else {
            self.textures.bound(self.active_texture, t)
        }
    }

    /// Stores a new image and regenerates mipmaps when it is the base level of an object with
    /// `GL_GENERATE_MIPMAP`.
    fn install_image(&mut self, target: TexImageTarget, level: usize, img: TexImage) {
        let face = target.face();
        let obj = self.image_object_mut(target);
        obj.images[face][level] = Some(img);
        if !target.is_proxy() {
            self.after_image_change(target, level);
        }
    }

    /// Generates mipmaps if needed and marks the draw state stale.
    fn after_image_change(&mut self, target: TexImageTarget, level: usize) {
        let face = target.face();
        let tt = target.texture_target();
        let obj = self.image_object_mut(target);
        if obj.params.generate_mipmap && level == obj.params.base_level.max(0) as usize {
            let mut oom = false;
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
            if oom {
                self.record_error(GL_OUT_OF_MEMORY);
            }
        }
        self.invalidate();
    }

    // ----- image specification

    fn tex_image(
        &mut self,
        dims: usize,
        target: GLenum,
        level: GLint,
        internalformat: GLint,
        size: [GLsizei; 3],
        border: GLint,
        format: GLenum,
        type_: GLenum,
        pixels: Option<&[u8]>,
    ) {
        if let Err(e) = self.tex_image_checked(
            dims,
            target,
            level,
            internalformat,
            size,
            border,
            format,
            type_,
            pixels,
        ) {
            self.record_error(e);
        }
    }

    fn tex_image_checked(
        &mut self,
        dims: usize,
        target: GLenum,
        level: GLint,
        internalformat: GLint,
        size: [GLsizei; 3],
        border: GLint,
        format: GLenum,
        type_: GLenum,
        pixels: Option<&[u8]>,
    ) -> Check<()> {
        let target = convert::tex_image_target_for(target, dims, true).ok_or(GL_INVALID_ENUM)?;
        let (pf, pt) = pixel_format_type(format, type_)?;
        let level = check_level(target.texture_target(), level)?;
        let ifmt = check_internal_format(internalformat, dims)?;
        let stored = match check_size(target, size, border) {
            Ok(s) => s,
            Err(Some(e)) => return Err(e),
            Err(None) if target.is_proxy() => {
                self.image_object_mut(target).images[0][level] = None;
                return Ok(());
            }
            Err(None) => return Err(GL_INVALID_VALUE),
        };
        if ifmt.compressed.is_some() && border != 0 {
            return Err(GL_INVALID_OPERATION);
        }
        check_format_type(pf, pt)?;
        if (pf == TexPixelFormat::DepthComponent) != ifmt.is_depth() {
            return Err(GL_INVALID_OPERATION);
        }
        check_depth_target(target, ifmt)?;
        let usize3 = stored.map(|s| s as usize);
        let layout = pixels::layout(&self.unpack, dims, usize3, pf, pt).ok_or(GL_INVALID_VALUE)?;
        if let Some(data) = pixels {
            if data.len() < layout.end {
                return Err(GL_INVALID_VALUE);
            }
        }
        let mut img = TexImage::new(dims as u8, stored, border, ifmt, target.is_proxy())
            .map_err(|_| GL_OUT_OF_MEMORY)?;
        if let (Some(data), false) = (pixels, target.is_proxy()) {
            let swap = self.unpack.swap_bytes;
            // Pixel transfer (section 3.6.5) applies on the way in, when it changes anything.
            let xfer = (!self.pixel_transfer.is_identity()).then(|| self.pixel_transfer.clone());
            let depth = pf == TexPixelFormat::DepthComponent;
            // Bytes that are already the stored texels are copied row by row.
            if xfer.is_some()
                || !pixels::copy_bytes(&mut img, [0; 3], data, &layout, usize3, pf, pt)
            {
                pixels::unpack_image(data, &layout, usize3, pf, pt, swap, |x, y, z, rgba| {
                    let rgba = xfer.as_ref().map_or(rgba, |t| t.texel(depth, rgba));
                    img.store(x as i32, y as i32, z as i32, rgba)
                });
            }
            img.encode_region(0, 0, img.width, img.height);
        }
        self.install_image(target, level, img);
        Ok(())
    }

    fn tex_sub_image(
        &mut self,
        dims: usize,
        target: GLenum,
        level: GLint,
        offset: [GLint; 3],
        size: [GLsizei; 3],
        format: GLenum,
        type_: GLenum,
        pixels: Option<&[u8]>,
    ) {
        let r = (|| -> Check<()> {
            let target =
                convert::tex_image_target_for(target, dims, false).ok_or(GL_INVALID_ENUM)?;
            let (pf, pt) = pixel_format_type(format, type_)?;
            let level = check_level(target.texture_target(), level)?;
            if size[..dims].iter().any(|&s| s < 0) {
                return Err(GL_INVALID_VALUE);
            }
            let img = self
                .image_object(target)
                .image(target.face(), level)
                .ok_or(GL_INVALID_OPERATION)?;
            let (b, inner) = (img.borders(), img.inner_size());
            check_sub_region(dims, offset, size, b, inner)?;
            check_format_type(pf, pt)?;
            if (pf == TexPixelFormat::DepthComponent) != img.format.is_depth() {
                return Err(GL_INVALID_OPERATION);
            }
            check_compressed_alignment(img, offset, size)?;
            let mut n = [1usize; 3];
            for d in 0..dims {
                n[d] = size[d] as usize;
            }
            let layout = pixels::layout(&self.unpack, dims, n, pf, pt).ok_or(GL_INVALID_VALUE)?;
            let Some(data) = pixels else {
                return Ok(());
            };
            if data.len() < layout.end {
                return Err(GL_INVALID_VALUE);
            }
            let swap = self.unpack.swap_bytes;
            let xfer = (!self.pixel_transfer.is_identity()).then(|| self.pixel_transfer.clone());
            let depth = pf == TexPixelFormat::DepthComponent;
            let face = target.face();
            let obj = self.image_object_mut(target);
            if let Some(img) = obj.image_mut(face, level) {
                let o = [
                    offset[0] + b[0],
                    if dims >= 2 { offset[1] + b[1] } else { 0 },
                    if dims >= 3 { offset[2] + b[2] } else { 0 },
                ];
                // Bytes that are already the stored texels are copied row by row.
                if xfer.is_some() || !pixels::copy_bytes(img, o, data, &layout, n, pf, pt) {
                    pixels::unpack_image(data, &layout, n, pf, pt, swap, |x, y, z, rgba| {
                        let rgba = xfer.as_ref().map_or(rgba, |t| t.texel(depth, rgba));
                        img.store(o[0] + x as i32, o[1] + y as i32, o[2] + z as i32, rgba)
                    });
                }
                img.encode_region(o[0], o[1], o[0] + n[0] as i32, o[1] + n[1] as i32);
            }
            self.after_image_change(target, level);
            Ok(())
        })();
        if let Err(e) = r {
            self.record_error(e);
        }
    }

    pub(crate) fn tex_image_1d(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLint,
        width: GLsizei,
        border: GLint,
        format: GLenum,
        type_: GLenum,
        pixels: Option<&[u8]>,
    ) {
        self.tex_image(
            1,
            target,
            level,
            internalformat,
            [width, 1, 1],
            border,
            format,
            type_,
            pixels,
        );
    }

    pub(crate) fn tex_image_2d(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLint,
        width: GLsizei,
        height: GLsizei,
        border: GLint,
        format: GLenum,
        type_: GLenum,
        pixels: Option<&[u8]>,
    ) {
        self.tex_image(
            2,
            target,
            level,
            internalformat,
            [width, height, 1],
            border,
            format,
            type_,
            pixels,
        );
    }

    pub(crate) fn tex_image_3d(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLint,
        width: GLsizei,
        height: GLsizei,
        depth: GLsizei,
        border: GLint,
        format: GLenum,
        type_: GLenum,
        pixels: Option<&[u8]>,
    ) {
        self.tex_image(
            3,
            target,
            level,
            internalformat,
            [width, height, depth],
            border,
            format,
            type_,
            pixels,
        );
    }

    pub(crate) fn tex_sub_image_1d(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        width: GLsizei,
        format: GLenum,
        type_: GLenum,
        pixels: Option<&[u8]>,
    ) {
        self.tex_sub_image(
            1,
            target,
            level,
            [xoffset, 0, 0],
            [width, 1, 1],
            format,
            type_,
            pixels,
        );
    }

    pub(crate) fn tex_sub_image_2d(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        yoffset: GLint,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        type_: GLenum,
        pixels: Option<&[u8]>,
    ) {
        self.tex_sub_image(
            2,
            target,
            level,
            [xoffset, yoffset, 0],
            [width, height, 1],
            format,
            type_,
            pixels,
        );
    }

    pub(crate) fn tex_sub_image_3d(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        yoffset: GLint,
        zoffset: GLint,
        width: GLsizei,
        height: GLsizei,
        depth: GLsizei,
        format: GLenum,
        type_: GLenum,
        pixels: Option<&[u8]>,
    ) {
        self.tex_sub_image(
            3,
            target,
            level,
            [xoffset, yoffset, zoffset],
            [width, height, depth],
            format,
            type_,
            pixels,
        );
    }

    // ----- copies from the framebuffer

    /// The framebuffer value at (x, y) as internal RGBA: colour, or depth in R. Outside the
    /// window (undefined in GL) it reads 0.
    fn read_framebuffer(&self, x: i32, y: i32, depth: bool) -> [f32; 4] {
        let fb = &self.framebuffer;
        if depth {
            let max = fb.depth_max().max(1) as f64;
            let d = fb.depth_at(x, y).map_or(0.0, |d| (d as f64 / max) as f32);
            [d, 0.0, 0.0, 1.0]
        } else {
            fb.color_at(x, y)
                .map_or([0.0; 4], |c| c.map(|v| v as f32 / 255.0))
        }
    }

    fn copy_tex_image(
        &mut self,
        dims: usize,
        target: GLenum,
        level: GLint,
        internalformat: GLenum,
        x: GLint,
        y: GLint,
        size: [GLsizei; 2],
        border: GLint,
    ) {
        let r = (|| -> Check<()> {
            let target =
                convert::tex_image_target_for(target, dims, false).ok_or(GL_INVALID_ENUM)?;
            let level = check_level(target.texture_target(), level)?;
            if (1..=4).contains(&internalformat) {
                return Err(GL_INVALID_VALUE);
            }
            let ifmt = check_internal_format(internalformat as GLint, dims)?;
            let stored = check_size(target, [size[0], size[1], 1], border)
                .map_err(|e| e.unwrap_or(GL_INVALID_VALUE))?;
            if ifmt.compressed.is_some() && border != 0 {
                return Err(GL_INVALID_OPERATION);
            }
            check_depth_target(target, ifmt)?;
            if ifmt.is_depth() && self.framebuffer.config.depth_bits == 0 {
                return Err(GL_INVALID_OPERATION);
            }
            let mut img = TexImage::new(dims as u8, stored, border, ifmt, false)
                .map_err(|_| GL_OUT_OF_MEMORY)?;
            self.flush_scene();
            for j in 0..stored[1] {
                for i in 0..stored[0] {
                    let v = self.read_framebuffer(
                        x.saturating_add(i),
                        y.saturating_add(j),
                        ifmt.is_depth(),
                    );
                    img.store(i, j, 0, v);
                }
            }
            img.encode_region(0, 0, img.width, img.height);
            self.install_image(target, level, img);
            Ok(())
        })();
        if let Err(e) = r {
            self.record_error(e);
        }
    }

    fn copy_tex_sub_image(
        &mut self,
        dims: usize,
        target: GLenum,
        level: GLint,
        offset: [GLint; 3],
        x: GLint,
        y: GLint,
        size: [GLsizei; 2],
    ) {
        let r = (|| -> Check<()> {
            let target =
                convert::tex_image_target_for(target, dims, false).ok_or(GL_INVALID_ENUM)?;
            let level = check_level(target.texture_target(), level)?;
            if size[0] < 0 || size[1] < 0 {
                return Err(GL_INVALID_VALUE);
            }
            let img = self
                .image_object(target)
                .image(target.face(), level)
                .ok_or(GL_INVALID_OPERATION)?;
            let (b, inner) = (img.borders(), img.inner_size());
            let h = if dims >= 2 { size[1] } else { 1 };
            // The copied region is w x h x 1 at the offsets.
            let region = [size[0], h, 1];
            let mut off = offset;
            if dims < 2 {
                off[1] = 0;
            }
            if dims < 3 {
                off[2] = 0;
            }
            check_sub_region(dims, off, region, b, inner)?;
            check_compressed_alignment(img, off, region)?;
            let depth = img.format.is_depth();
            if depth && self.framebuffer.config.depth_bits == 0 {
                return Err(GL_INVALID_OPERATION);
            }
            self.flush_scene();
            let mut values = Vec::new();
            values
                .try_reserve_exact(size[0] as usize * h as usize)
                .map_err(|_| GL_OUT_OF_MEMORY)?;
            for j in 0..h {
                for i in 0..size[0] {
                    values.push(self.read_framebuffer(
                        x.saturating_add(i),
                        y.saturating_add(j),
                        depth,
                    ));
                }
            }
            let face = target.face();
            if let Some(img) = self.image_object_mut(target).image_mut(face, level) {
                let o = [
                    off[0] + b[0],
                    if dims >= 2 { off[1] + b[1] } else { 0 },
                    if dims >= 3 { off[2] + b[2] } else { 0 },
                ];
                for j in 0..h {
                    for i in 0..size[0] {
                        let v = values[(j * size[0] + i) as usize];
                        img.store(o[0] + i, o[1] + j, o[2], v);
                    }
                }
                img.encode_region(o[0], o[1], o[0] + size[0], o[1] + h);
            }
            self.after_image_change(target, level);
            Ok(())
        })();
        if let Err(e) = r {
            self.record_error(e);
        }
    }

    pub(crate) fn copy_tex_image_1d(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLenum,
        x: GLint,
        y: GLint,
        width: GLsizei,
        border: GLint,
    ) {
        self.copy_tex_image(1, target, level, internalformat, x, y, [width, 1], border);
    }

    pub(crate) fn copy_tex_image_2d(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLenum,
        x: GLint,
        y: GLint,
        width: GLsizei,
        height: GLsizei,
        border: GLint,
    ) {
        self.copy_tex_image(
            2,
            target,
            level,
            internalformat,
            x,
            y,
            [width, height],
            border,
        );
    }

    pub(crate) fn copy_tex_sub_image_1d(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        x: GLint,
        y: GLint,
        width: GLsizei,
    ) {
        self.copy_tex_sub_image(1, target, level, [xoffset, 0, 0], x, y, [width, 1]);
    }

    pub(crate) fn copy_tex_sub_image_2d(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        yoffset: GLint,
        x: GLint,
        y: GLint,
        width: GLsizei,
        height: GLsizei,
    ) {
        self.copy_tex_sub_image(
            2,
            target,
            level,
            [xoffset, yoffset, 0],
            x,
            y,
            [width, height],
        );
    }

    pub(crate) fn copy_tex_sub_image_3d(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        yoffset: GLint,
        zoffset: GLint,
        x: GLint,
        y: GLint,
        width: GLsizei,
        height: GLsizei,
    ) {
        self.copy_tex_sub_image(
            3,
            target,
            level,
            [xoffset, yoffset, zoffset],
            x,
            y,
            [width, height],
        );
    }

    // ----- reading images back

    /// The image `glGetTexImage(target, level, ..)` reads: its dimensions and stored size.
    fn image_for_get(
        &self,
        target: GLenum,
        level: GLint,
    ) -> Check<Option<(TexImageTarget, usize)>> {
        let target = convert::tex_image_target(target)
            .filter(|t| !t.is_proxy())
            .ok_or(GL_INVALID_ENUM)?;
        let level = check_level(target.texture_target(), level)?;
        Ok(self
            .image_object(target)
            .image(target.face(), level)
            .map(|_| (target, level)))
    }

    /// Dimensions and size of the image at `target`/`level`, if there is one.
    pub(crate) fn texture_image_size(
        &self,
        target: GLenum,
        level: GLint,
    ) -> Option<(usize, [usize; 3])> {
        let (target, level) = self.image_for_get(target, level).ok()??;
        let img = self.image_object(target).image(target.face(), level)?;
        let size = [img.width, img.height, img.depth].map(|s| s.max(0) as usize);
        Some((target.dims(), size))
    }

    /// Bytes of the compressed blocks of the image at `target`/`level`, if it is compressed.
    pub(crate) fn texture_image_blocks_len(&self, target: GLenum, level: GLint) -> Option<usize> {
        let (target, level) = self.image_for_get(target, level).ok()??;
        let img = self.image_object(target).image(target.face(), level)?;
        img.blocks.as_ref().map(|b| b.len())
    }

    pub(crate) fn get_tex_image(
        &mut self,
        target: GLenum,
        level: GLint,
        format: GLenum,
        type_: GLenum,
        pixels: &mut [u8],
    ) {
        let r = (|| -> Check<()> {
            let target = convert::tex_image_target(target)
                .filter(|t| !t.is_proxy())
                .ok_or(GL_INVALID_ENUM)?;
            let (pf, pt) = pixel_format_type(format, type_)?;
            let level = check_level(target.texture_target(), level)?;
            check_format_type(pf, pt)?;
            let Some(img) = self.image_object(target).image(target.face(), level) else {
                return Ok(());
            };
            if (pf == TexPixelFormat::DepthComponent) != img.format.is_depth() {
                return Err(GL_INVALID_OPERATION);
            }
            let dims = target.dims();
            let size = [img.width, img.height, img.depth].map(|s| s.max(0) as usize);
            let layout = pixels::layout(&self.pack, dims, size, pf, pt).ok_or(GL_INVALID_VALUE)?;
            if pixels.len() < layout.end {
                return Err(GL_INVALID_VALUE);
            }
            let swap = self.pack.swap_bytes;
            for z in 0..size[2] {
                for y in 0..size[1] {
                    let row = layout.start + z * layout.image_stride + y * layout.row_stride;
                    for x in 0..size[0] {
                        let v = img.fetch(x as i32, y as i32, z as i32);
                        pixels::pack_group(pixels, row + x * layout.group, v, pf, pt, swap);
                    }
                }
            }
            Ok(())
        })();
        if let Err(e) = r {
            self.record_error(e);
        }
    }

    // ----- parameters

    fn tex_parameter(&mut self, target: GLenum, pname: GLenum, v: Values, vector: bool) {
        let r = (|| -> Check<()> {
            let t = convert::texture_target(target).ok_or(GL_INVALID_ENUM)?;
            let p = convert::tex_param(pname).ok_or(GL_INVALID_ENUM)?;
            let four = matches!(p, TexParam::BorderColor | TexParam::SwizzleRgba);
            if p == TexParam::Resident || (four && !vector) {
                return Err(GL_INVALID_ENUM);
            }
            let needed = if four { 4 } else { 1 };
            if v.len() < needed {
                return Err(GL_INVALID_VALUE);
            }
            let obj = self.textures.bound_mut(self.active_texture, t);
            let mut params = obj.params;
            let mut priority = obj.priority;
            let e = v.enumv(0);
            match p {
                TexParam::MinFilter => {
                    let f = convert::min_filter(e).ok_or(GL_INVALID_ENUM)?;
                    // Rectangle textures have no mipmaps (ARB_texture_rectangle).
                    if t == TextureTarget::Rectangle && f.is_mipmap() {
                        return Err(GL_INVALID_ENUM);
                    }
                    params.min_filter = f
                }
                TexParam::MagFilter => {
                    params.mag_filter = convert::mag_filter(e).ok_or(GL_INVALID_ENUM)?
                }
                TexParam::WrapS | TexParam::WrapT | TexParam::WrapR => {
                    let i = match p {
                        TexParam::WrapS => 0,
                        TexParam::WrapT => 1,
                        _ => 2,
                    };
                    let w = convert::wrap_mode(e).ok_or(GL_INVALID_ENUM)?;
                    // Rectangle textures only clamp (ARB_texture_rectangle).
                    if t == TextureTarget::Rectangle
                        && !matches!(
                            w,
                            convert::WrapMode::Clamp
                                | convert::WrapMode::ClampToEdge
                                | convert::WrapMode::ClampToBorder
                        )
                    {
                        return Err(GL_INVALID_ENUM);
                    }
                    params.wrap[i] = w;
                }
                TexParam::BorderColor => {
                    params.border_color = [0, 1, 2, 3].map(|i| clamp01(v.color(i)));
                }
                TexParam::Priority => priority = clamp01(v.float(0)),
                TexParam::MinLod => params.min_lod = v.float(0),
                TexParam::MaxLod => params.max_lod = v.float(0),
                TexParam::BaseLevel | TexParam::MaxLevel => {
                    let n = v.int(0);
                    if n < 0 {
                        return Err(GL_INVALID_VALUE);
                    }
                    if p == TexParam::BaseLevel {
                        params.base_level = n;
                    } else {
                        params.max_level = n;
                    }
                }
                TexParam::LodBias => params.lod_bias = v.float(0),
                TexParam::GenerateMipmap => params.generate_mipmap = v.float(0) != 0.0,
                TexParam::CompareMode => {
                    params.compare = convert::texture_compare_mode(e).ok_or(GL_INVALID_ENUM)?
                }
                TexParam::CompareFunc => {
                    params.compare_func = convert::compare_func(e).ok_or(GL_INVALID_ENUM)?
                }
                TexParam::DepthTextureMode => {
                    params.depth_mode = convert::depth_texture_mode(e).ok_or(GL_INVALID_ENUM)?
                }
                TexParam::MaxAnisotropy => {
                    let a = v.float(0);
                    if a.is_nan() || a < 1.0 {
                        return Err(GL_INVALID_VALUE);
                    }
                    params.max_anisotropy = a.min(MAX_TEXTURE_MAX_ANISOTROPY);
                }
                TexParam::Resident => return Err(GL_INVALID_ENUM),
                TexParam::Swizzle(i) => {
                    params.swizzle[i] = convert::swizzle_source(e).ok_or(GL_INVALID_ENUM)?
                }
                TexParam::SwizzleRgba => {
                    let mut sw = params.swizzle;
                    for (i, s) in sw.iter_mut().enumerate() {
                        *s = convert::swizzle_source(v.enumv(i)).ok_or(GL_INVALID_ENUM)?;
                    }
                    params.swizzle = sw;
                }
            }
            obj.params = params;
            obj.priority = priority;
            Ok(())
        })();
        match r {
            Ok(()) => self.invalidate(),
            Err(e) => self.record_error(e),
        }
    }

    pub(crate) fn tex_parameterf(&mut self, target: GLenum, pname: GLenum, param: GLfloat) {
        self.tex_parameter(target, pname, Values::F(&[param]), false);
    }

    pub(crate) fn tex_parameterfv(&mut self, target: GLenum, pname: GLenum, params: &[GLfloat]) {
        self.tex_parameter(target, pname, Values::F(params), true);
    }

    pub(crate) fn tex_parameteri(&mut self, target: GLenum, pname: GLenum, param: GLint) {
        self.tex_parameter(target, pname, Values::I(&[param]), false);
    }

    pub(crate) fn tex_parameteriv(&mut self, target: GLenum, pname: GLenum, params: &[GLint]) {
        self.tex_parameter(target, pname, Values::I(params), true);
    }

    /// The values of a texture parameter: numbers, and whether they are colour components
    /// (which map to the full integer range in `glGetTexParameteriv`).
    fn tex_parameter_values(&self, target: GLenum, pname: GLenum) -> Check<(Vec<f64>, bool)> {
        let t = convert::texture_target(target).ok_or(GL_INVALID_ENUM)?;
        let p = convert::tex_param(pname).ok_or(GL_INVALID_ENUM)?;
        let obj = self.textures.bound(self.active_texture, t);
        let q = &obj.params;
        let e = |v: GLenum| vec![v as f64];
        Ok(match p {
            TexParam::MinFilter => (e(q.min_filter.to_gl()), false),
            TexParam::MagFilter => (e(q.mag_filter.to_gl()), false),
            TexParam::WrapS => (e(q.wrap[0].to_gl()), false),
            TexParam::WrapT => (e(q.wrap[1].to_gl()), false),
            TexParam::WrapR => (e(q.wrap[2].to_gl()), false),
            TexParam::BorderColor => (q.border_color.iter().map(|&c| c as f64).collect(), true),
            TexParam::Priority => (vec![obj.priority as f64], false),
            TexParam::MinLod => (vec![q.min_lod as f64], false),
            TexParam::MaxLod => (vec![q.max_lod as f64], false),
            TexParam::BaseLevel => (vec![q.base_level as f64], false),
            TexParam::MaxLevel => (vec![q.max_level as f64], false),
            TexParam::LodBias => (vec![q.lod_bias as f64], false),
            TexParam::GenerateMipmap => (vec![q.generate_mipmap as u8 as f64], false),
            TexParam::CompareMode => (e(convert::compare_mode_to_gl(q.compare)), false),
            TexParam::CompareFunc => (e(q.compare_func.to_gl()), false),
            TexParam::DepthTextureMode => (e(q.depth_mode.to_gl()), false),
            TexParam::MaxAnisotropy => (vec![q.max_anisotropy as f64], false),
            TexParam::Resident => (vec![1.0], false),
            TexParam::Swizzle(i) => (e(q.swizzle[i].to_gl()), false),
            TexParam::SwizzleRgba => (q.swizzle.iter().map(|s| s.to_gl() as f64).collect(), false),
        })
    }

    pub(crate) fn get_tex_parameterfv(
        &mut self,
        target: GLenum,
        pname: GLenum,
        params: &mut [GLfloat],
    ) {
        match self.tex_parameter_values(target, pname) {
            Ok((v, _)) if params.len() >= v.len() => {
                for (o, x) in params.iter_mut().zip(v) {
                    *o = x as f32;
                }
            }
            Ok(_) => self.record_error(GL_INVALID_VALUE),
            Err(e) => self.record_error(e),
        }
    }

    pub(crate) fn get_tex_parameteriv(
        &mut self,
        target: GLenum,
        pname: GLenum,
        params: &mut [GLint],
    ) {
        match self.tex_parameter_values(target, pname) {
            Ok((v, color)) if params.len() >= v.len() => {
                for (o, x) in params.iter_mut().zip(v) {
                    *o = if color {
                        (x * i32::MAX as f64).round() as i32
                    } else {
                        x.round() as i32
                    };
                }
            }
            Ok(_) => self.record_error(GL_INVALID_VALUE),
            Err(e) => self.record_error(e),
        }
    }

    fn tex_level_parameter(&self, target: GLenum, level: GLint, pname: GLenum) -> Check<i64> {
        let target = convert::tex_image_target(target).ok_or(GL_INVALID_ENUM)?;
        let level = check_level(target.texture_target(), level)?;
        let p = convert::tex_level_param(pname).ok_or(GL_INVALID_ENUM)?;
        let img = self.image_object(target).image(target.face(), level);
        let Some(img) = img else {
            return match p {
                TexLevelParam::InternalFormat => Ok(1),
                TexLevelParam::CompressedImageSize => Err(GL_INVALID_OPERATION),
                _ => Ok(0),
            };
        };
        let f = img.format;
        let bits = f.component_bits() as i64;
        let has = |yes: bool| if yes { bits } else { 0 };
        use BaseFormat::*;
        Ok(match p {
            TexLevelParam::Width => img.width as i64,
            TexLevelParam::Height => img.height as i64,
            TexLevelParam::Depth => img.depth as i64,
            TexLevelParam::InternalFormat => f.reported() as i64,
            TexLevelParam::Border => img.border as i64,
            TexLevelParam::RedSize | TexLevelParam::GreenSize | TexLevelParam::BlueSize => {
                has(matches!(f.base, Rgb | Rgba))
            }
            TexLevelParam::AlphaSize => has(matches!(f.base, Alpha | LuminanceAlpha | Rgba)),
            TexLevelParam::LuminanceSize => has(matches!(f.base, Luminance | LuminanceAlpha)),
            TexLevelParam::IntensitySize => has(f.base == Intensity),
            TexLevelParam::DepthSize => has(f.base == DepthComponent),
            TexLevelParam::Compressed => f.compressed.is_some() as i64,
            TexLevelParam::CompressedImageSize => match (f.compressed, &img.blocks) {
                (Some(c), _) => {
                    c.image_bytes(img.width.max(0) as usize, img.height.max(0) as usize) as i64
                }
                _ => return Err(GL_INVALID_OPERATION),
            },
        })
    }

    pub(crate) fn get_tex_level_parameterfv(
        &mut self,
        target: GLenum,
        level: GLint,
        pname: GLenum,
        params: &mut [GLfloat],
    ) {
        match self.tex_level_parameter(target, level, pname) {
            Ok(_) if params.is_empty() => self.record_error(GL_INVALID_VALUE),
            Ok(v) => params[0] = v as f32,
            Err(e) => self.record_error(e),
        }
    }

    pub(crate) fn get_tex_level_parameteriv(
        &mut self,
        target: GLenum,
        level: GLint,
        pname: GLenum,
        params: &mut [GLint],
    ) {
        match self.tex_level_parameter(target, level, pname) {
            Ok(_) if params.is_empty() => self.record_error(GL_INVALID_VALUE),
            Ok(v) => params[0] = v.clamp(i32::MIN as i64, i32::MAX as i64) as i32,
            Err(e) => self.record_error(e),
        }
    }

    // ----- compressed images

    pub(crate) fn compressed_tex_image_1d(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLenum,
        width: GLsizei,
        border: GLint,
        image_size: GLsizei,
        data: Option<&[u8]>,
    ) {
        // No one-dimensional compressed formats exist: the target or the format is refused.
        let _ = (
            target,
            level,
            internalformat,
            width,
            border,
            image_size,
            data,
        );
        self.record_error(GL_INVALID_ENUM);
    }

    pub(crate) fn compressed_tex_image_3d(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLenum,
        width: GLsizei,
        height: GLsizei,
        depth: GLsizei,
        border: GLint,
        image_size: GLsizei,
        data: Option<&[u8]>,
    ) {
        // S3TC is two-dimensional only.
        let _ = (target, level, internalformat, width, height, depth, border);
        let _ = (image_size, data);
        self.record_error(GL_INVALID_ENUM);
    }

    pub(crate) fn compressed_tex_sub_image_1d(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        width: GLsizei,
        format: GLenum,
        image_size: GLsizei,
        data: Option<&[u8]>,
    ) {
        let _ = (target, level, xoffset, width, format, image_size, data);
        self.record_error(GL_INVALID_ENUM);
    }

    pub(crate) fn compressed_tex_sub_image_3d(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        yoffset: GLint,
        zoffset: GLint,
        width: GLsizei,
        height: GLsizei,
        depth: GLsizei,
        format: GLenum,
        image_size: GLsizei,
        data: Option<&[u8]>,
    ) {
        let _ = (
            target, level, xoffset, yoffset, zoffset, width, height, depth,
        );
        let _ = (format, image_size, data);
        self.record_error(GL_INVALID_ENUM);
    }

    pub(crate) fn compressed_tex_image_2d(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLenum,
        width: GLsizei,
        height: GLsizei,
        border: GLint,
        image_size: GLsizei,
        data: Option<&[u8]>,
    ) {
        let r = (|| -> Check<()> {
            let target = convert::tex_image_target_for(target, 2, true).ok_or(GL_INVALID_ENUM)?;
            let f = s3tc(internalformat).ok_or(GL_INVALID_ENUM)?;
            let level = check_level(target.texture_target(), level)?;
            let ifmt = InternalFormat::s3tc(internalformat as GLint, f);
            let stored = match check_size(target, [width, height, 1], border) {
                Ok(s) => s,
                Err(Some(e)) => return Err(e),
                Err(None) if target.is_proxy() => {
                    self.image_object_mut(target).images[0][level] = None;
                    return Ok(());
                }
                Err(None) => return Err(GL_INVALID_VALUE),
            };
            if border != 0 {
                return Err(GL_INVALID_OPERATION);
            }
            let expected = f.image_bytes(stored[0] as usize, stored[1] as usize);
            if image_size < 0 || image_size as usize != expected {
                return Err(GL_INVALID_VALUE);
            }
            if data.is_some_and(|d| d.len() < expected) {
                return Err(GL_INVALID_VALUE);
            }
            let mut img = TexImage::new(2, stored, 0, ifmt, target.is_proxy())
                .map_err(|_| GL_OUT_OF_MEMORY)?;
            if let (Some(d), false) = (data, target.is_proxy()) {
                img.load_blocks(0, 0, img.width, img.height, d);
            }
            self.install_image(target, level, img);
            Ok(())
        })();
        if let Err(e) = r {
            self.record_error(e);
        }
    }

    pub(crate) fn compressed_tex_sub_image_2d(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        yoffset: GLint,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        image_size: GLsizei,
        data: Option<&[u8]>,
    ) {
        let r = (|| -> Check<()> {
            let target = convert::tex_image_target_for(target, 2, false).ok_or(GL_INVALID_ENUM)?;
            let f = s3tc(format).ok_or(GL_INVALID_ENUM)?;
            let level = check_level(target.texture_target(), level)?;
            if width < 0 || height < 0 {
                return Err(GL_INVALID_VALUE);
            }
            let img = self
                .image_object(target)
                .image(target.face(), level)
                .ok_or(GL_INVALID_OPERATION)?;
            if img.format.compressed != Some(f) {
                return Err(GL_INVALID_OPERATION);
            }
            let offset = [xoffset, yoffset, 0];
            let size = [width, height, 1];
            check_sub_region(2, offset, size, img.borders(), img.inner_size())?;
            check_compressed_alignment(img, offset, size)?;
            let expected = f.image_bytes(width as usize, height as usize);
            if image_size < 0 || image_size as usize != expected {
                return Err(GL_INVALID_VALUE);
            }
            let Some(d) = data else {
                return Ok(());
            };
            if d.len() < expected {
                return Err(GL_INVALID_VALUE);
            }
            let face = target.face();
            if let Some(img) = self.image_object_mut(target).image_mut(face, level) {
                img.load_blocks(xoffset, yoffset, xoffset + width, yoffset + height, d);
            }
            self.after_image_change(target, level);
            Ok(())
        })();
        if let Err(e) = r {
            self.record_error(e);
        }
    }

    pub(crate) fn get_compressed_tex_image(
        &mut self,
        target: GLenum,
        level: GLint,
        img: &mut [u8],
    ) {
        let r = (|| -> Check<()> {
            let target = convert::tex_image_target(target)
                .filter(|t| !t.is_proxy())
                .ok_or(GL_INVALID_ENUM)?;
            let level = check_level(target.texture_target(), level)?;
            let image = self
                .image_object(target)
                .image(target.face(), level)
                .ok_or(GL_INVALID_OPERATION)?;
            let blocks = image.blocks.as_ref().ok_or(GL_INVALID_OPERATION)?;
            let dst = img.get_mut(..blocks.len()).ok_or(GL_INVALID_VALUE)?;
            dst.copy_from_slice(blocks);
            Ok(())
        })();
        if let Err(e) = r {
            self.record_error(e);
        }
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

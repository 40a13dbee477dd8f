//! Texture image specification (`glTexImage*`, `glTexSubImage*`) and reading images back
//! (`glGetTexImage`).

use super::*;

impl Context {
    pub(super) fn tex_image(
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

    pub(super) fn tex_image_checked(
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
        let src = upload_source(format, type_)?;
        let level = check_level(target.texture_target(), level)?;
        let ifmt = check_internal_format(internalformat, dims)?;
        self.check_mutable(target)?;
        let stored = match check_size(target, level, size, border) {
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
        src.check_packed()?;
        if src.is_depth() != ifmt.is_depth() {
            return Err(GL_INVALID_OPERATION);
        }
        check_depth_target(target, ifmt)?;
        // (A real image over its limit is GL_OUT_OF_MEMORY from `TexImage::new`.)
        if target.is_proxy() && !proxy_fits(stored, ifmt) {
            self.image_object_mut(target).images[0][level] = None;
            return Ok(());
        }
        let usize3 = stored.map(|s| s as usize);
        let len = self.upload_len(dims, usize3, src).ok_or(GL_INVALID_VALUE)?;
        if pixels.is_some_and(|data| data.len() < len) {
            return Err(GL_INVALID_VALUE);
        }
        if let (Some(data), false, UploadSource::Groups(pf, pt)) = (pixels, target.is_proxy(), src)
        {
            // Bytes that are the texels: the image is made from the rows, not zeroed first
            // and then overwritten.
            let transfer = !self.pixel_transfer.is_identity();
            if bytes_are_texels(transfer, pf, pt, ifmt) {
                let layout =
                    pixels::layout(&self.unpack, dims, usize3, pf, pt).ok_or(GL_INVALID_VALUE)?;
                let made =
                    TexImage::from_byte_rows(dims as u8, stored, border, ifmt, data, &layout)
                        .map_err(|_| GL_OUT_OF_MEMORY)?;
                if let Some(img) = made {
                    self.install_image(target, level, img);
                    return Ok(());
                }
            }
        }
        let mut img = TexImage::new(dims as u8, stored, border, ifmt, target.is_proxy())
            .map_err(|_| GL_OUT_OF_MEMORY)?;
        if let (Some(data), false, UploadSource::ColorIndex(ty)) = (pixels, target.is_proxy(), src)
        {
            let texels = self.index_texels(data, dims, usize3, ty)?;
            let [w, h, _] = usize3;
            img.store_block([0; 3], usize3, |x, y, z| texels[(z * h + y) * w + x]);
            img.encode_region(0, 0, img.width, img.height);
        } else if let (Some(data), false, UploadSource::Groups(pf, pt)) =
            (pixels, target.is_proxy(), src)
        {
            let layout =
                pixels::layout(&self.unpack, dims, usize3, pf, pt).ok_or(GL_INVALID_VALUE)?;
            let swap = self.unpack.swap_bytes;
            // Pixel transfer (section 3.6.5) applies on the way in, when it changes anything.
            let xfer = (!self.pixel_transfer.is_identity()).then(|| self.pixel_transfer.clone());
            let copied = bytes_are_texels(xfer.is_some(), pf, pt, ifmt)
                && img.store_byte_rows(data, &layout, [0; 3], usize3)
                || converts_directly(xfer.is_some(), swap, pt)
                    && img.store_converted(data, &layout, [0; 3], usize3, pf, pt);
            if !copied {
                img.store_block([0; 3], usize3, |x, y, z| {
                    let at = layout.start
                        + z * layout.image_stride
                        + y * layout.row_stride
                        + x * layout.group;
                    unpack_texel(data, at, pf, pt, swap, xfer.as_ref(), ifmt)
                });
            }
            let stencil = StencilUpload {
                data,
                layout: &layout,
                pf,
                pt,
                swap,
            };
            stencil.store(&mut img, &self.pixel_transfer, [0; 3], usize3);
            img.encode_region(0, 0, img.width, img.height);
        }
        self.install_image(target, level, img);
        Ok(())
    }

    pub(super) fn tex_sub_image(
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
            let src = upload_source(format, type_)?;
            let level = check_level(target.texture_target(), level)?;
            if size[..dims].iter().any(|&s| s < 0) {
                return Err(GL_INVALID_VALUE);
            }
            let b = self
                .with_image(target, level, |img| -> Check<[i32; 3]> {
                    check_sub_region(dims, offset, size, img.borders(), img.inner_size())?;
                    src.check_packed()?;
                    if src.is_depth() != img.format.is_depth() {
                        return Err(GL_INVALID_OPERATION);
                    }
                    check_compressed_alignment(img, offset, size)?;
                    Ok(img.borders())
                })
                .ok_or(GL_INVALID_OPERATION)??;
            let mut n = [1usize; 3];
            for d in 0..dims {
                n[d] = size[d] as usize;
            }
            let len = self.upload_len(dims, n, src).ok_or(GL_INVALID_VALUE)?;
            let Some(data) = pixels else {
                return Ok(());
            };
            if data.len() < len {
                return Err(GL_INVALID_VALUE);
            }
            let o = [
                offset[0] + b[0],
                if dims >= 2 { offset[1] + b[1] } else { 0 },
                if dims >= 3 { offset[2] + b[2] } else { 0 },
            ];
            let (pf, pt) = match src {
                UploadSource::Groups(pf, pt) => (pf, pt),
                UploadSource::ColorIndex(ty) => {
                    let texels = self.index_texels(data, dims, n, ty)?;
                    let face = target.face();
                    let mut obj = self.image_object_mut(target);
                    if let Some(img) = obj.image_mut(face, level) {
                        let origin = o.map(|v| v.max(0) as usize);
                        img.store_block(origin, n, |x, y, z| texels[(z * n[1] + y) * n[0] + x]);
                        img.encode_region(o[0], o[1], o[0] + n[0] as i32, o[1] + n[1] as i32);
                    }
                    drop(obj);
                    self.after_image_change(target, level);
                    return Ok(());
                }
            };
            let layout = pixels::layout(&self.unpack, dims, n, pf, pt).ok_or(GL_INVALID_VALUE)?;
            let swap = self.unpack.swap_bytes;
            let xfer = (!self.pixel_transfer.is_identity()).then(|| self.pixel_transfer.clone());
            // Stencil indices take the index shift, offset and map (not in `xfer`'s test).
            let transfer = if pf == TexPixelFormat::DepthStencil {
                self.pixel_transfer.clone()
            } else {
                Default::default()
            };
            let face = target.face();
            let mut obj = self.image_object_mut(target);
            if let Some(img) = obj.image_mut(face, level) {
                let inside = o.iter().all(|&v| v >= 0);
                let at = o.map(|v| v.max(0) as usize);
                let copied = inside
                    && (bytes_are_texels(xfer.is_some(), pf, pt, img.format)
                        && img.store_byte_rows(data, &layout, at, n)
                        || converts_directly(xfer.is_some(), swap, pt)
                            && img.store_converted(data, &layout, at, n, pf, pt));
                if !copied {
                    let origin = o.map(|v| v.max(0) as usize);
                    let ifmt = img.format;
                    img.store_block(origin, n, |x, y, z| {
                        let at = layout.start
                            + z * layout.image_stride
                            + y * layout.row_stride
                            + x * layout.group;
                        unpack_texel(data, at, pf, pt, swap, xfer.as_ref(), ifmt)
                    });
                }
                let origin = o.map(|v| v.max(0) as usize);
                let stencil = StencilUpload {
                    data,
                    layout: &layout,
                    pf,
                    pt,
                    swap,
                };
                stencil.store(img, &transfer, origin, n);
                img.encode_region(o[0], o[1], o[0] + n[0] as i32, o[1] + n[1] as i32);
            }
            drop(obj);
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

    // ----- reading images back

    /// The image `glGetTexImage(target, level, ..)` reads: its dimensions and stored size.
    pub(super) fn image_for_get(
        &self,
        target: GLenum,
        level: GLint,
    ) -> Check<Option<(TexImageTarget, usize)>> {
        let target = convert::tex_image_target(target)
            .filter(|t| !t.is_proxy())
            .ok_or(GL_INVALID_ENUM)?;
        let level = check_level(target.texture_target(), level)?;
        Ok(self.image_at(target, level).map(|_| (target, level)))
    }

    /// Dimensions and size of the image at `target`/`level`, if there is one.
    pub(crate) fn texture_image_size(
        &self,
        target: GLenum,
        level: GLint,
    ) -> Option<(usize, [usize; 3])> {
        let (target, level) = self.image_for_get(target, level).ok()??;
        let img = self.image_at(target, level)?;
        let size = [img.width, img.height, img.depth].map(|s| s.max(0) as usize);
        Some((target.dims(), size))
    }

    /// Bytes of the compressed blocks of the image at `target`/`level`, if it is compressed.
    pub(crate) fn texture_image_blocks_len(&self, target: GLenum, level: GLint) -> Option<usize> {
        let (target, level) = self.image_for_get(target, level).ok()??;
        let img = self.image_at(target, level)?;
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
        self.fbo_before_texture_read();
        let r = (|| -> Check<()> {
            let target = convert::tex_image_target(target)
                .filter(|t| !t.is_proxy())
                .ok_or(GL_INVALID_ENUM)?;
            // GL_DEPTH_STENCIL reads a depth-stencil image's depth and stencil packed as
            // GL_UNSIGNED_INT_24_8 (EXT_packed_depth_stencil).
            let (pf, pt) = if format == GL_DEPTH_STENCIL_EXT {
                upload_format_type(format, type_)?
            } else {
                pixel_format_type(format, type_)?
            };
            let level = check_level(target.texture_target(), level)?;
            check_format_type(pf, pt)?;
            let Some(img) = self.image_at(target, level) else {
                return Ok(());
            };
            let fits = match pf {
                TexPixelFormat::DepthComponent => img.format.is_depth(),
                TexPixelFormat::DepthStencil => img.format.stencil,
                _ => !img.format.is_depth(),
            };
            if !fits {
                return Err(GL_INVALID_OPERATION);
            }
            let stencil = pf == TexPixelFormat::DepthStencil;
            let dims = target.dims();
            let size = [img.width, img.height, img.depth].map(|s| s.max(0) as usize);
            let layout = pixels::layout(&self.pack, dims, size, pf, pt).ok_or(GL_INVALID_VALUE)?;
            if pixels.len() < layout.end {
                return Err(GL_INVALID_VALUE);
            }
            let swap = self.pack.swap_bytes;
            // Luminance is the image's R (table 6.1 puts a luminance image's L in R), not
            // ReadPixels' R + G + B: llvmpipe returns an RGBA image's R, and piglit's
            // getteximage-luminance expects it (section 6.1.4 only points at ReadPixels).
            let luminance = matches!(
                pf,
                TexPixelFormat::Luminance | TexPixelFormat::LuminanceAlpha
            );
            // Float texels (ARB_texture_float) read back unclamped as GL_FLOAT; other types
            // are fixed-point and take values clamped to [0, 1] (section 4.3.2's final
            // conversion).
            let clamp = img.format.float && pt != TexPixelType::Float;
            for z in 0..size[2] {
                for y in 0..size[1] {
                    let row = layout.start + z * layout.image_stride + y * layout.row_stride;
                    for x in 0..size[0] {
                        let mut v = img.fetch(x as i32, y as i32, z as i32);
                        if clamp {
                            v = v.map(clamp01);
                        }
                        if luminance {
                            (v[1], v[2]) = (0.0, 0.0);
                        }
                        if stencil {
                            v[3] = img.stencil_at(x as i32, y as i32, z as i32) as f32 / 255.0;
                        }
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
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Arc;

    fn texels_ptr(ctx: &Context, target: TexImageTarget) -> *const crate::texture::image::Texels {
        Arc::as_ptr(&ctx.image_at(target, 0).unwrap().texels)
    }

    /// Sub-image uploads, copies and compressed sub-images write into the image's own
    /// storage: nothing else shares it, so no copy of the whole image is made (a 1 GiB 3D
    /// texture filled slice by slice would otherwise be copied once per slice).
    #[test]
    fn sub_image_writes_in_place() {
        let mut ctx = Context::new(8, 8);
        let t2d = TexImageTarget::T2D;
        ctx.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA8 as i32,
            4,
            4,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            None,
        );
        let before = texels_ptr(&ctx, t2d);
        ctx.tex_sub_image_2d(
            GL_TEXTURE_2D,
            0,
            1,
            1,
            2,
            2,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&[7u8; 16]),
        );
        ctx.copy_tex_sub_image_2d(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 2, 2);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(texels_ptr(&ctx, t2d), before);
        // While a copy is held (as a queued draw holds one), the write must not show in it.
        let held = ctx.image_at(t2d, 0).unwrap();
        ctx.tex_sub_image_2d(
            GL_TEXTURE_2D,
            0,
            0,
            0,
            1,
            1,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&[200u8; 4]),
        );
        assert_ne!(texels_ptr(&ctx, t2d), Arc::as_ptr(&held.texels));
        assert_eq!(held.fetch(0, 0, 0), [0.0; 4]);
    }
}

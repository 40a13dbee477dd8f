//! Compressed texture images (`glCompressedTex*`, `glGetCompressedTexImage`; S3TC).

use super::*;

impl Context {
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
            self.check_mutable(target)?;
            let stored = match check_size(target, level, [width, height, 1], border) {
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
            let offset = [xoffset, yoffset, 0];
            let size = [width, height, 1];
            self.with_image(target, level, |img| -> Check<()> {
                if img.format.compressed != Some(f) {
                    return Err(GL_INVALID_OPERATION);
                }
                check_sub_region(2, offset, size, img.borders(), img.inner_size())?;
                check_compressed_alignment(img, offset, size)
            })
            .ok_or(GL_INVALID_OPERATION)??;
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
            let image = self.image_at(target, level).ok_or(GL_INVALID_OPERATION)?;
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

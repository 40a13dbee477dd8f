//! Texture images copied from the framebuffer (`glCopyTexImage*`, `glCopyTexSubImage*`).

use super::*;

impl Context {
    /// The framebuffer value at (x, y) as internal RGBA: colour, or depth in R. Outside the
    /// window (undefined in GL) it reads 0.
    pub(super) fn read_framebuffer(&self, x: i32, y: i32, depth: bool) -> [f32; 4] {
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

    pub(super) fn copy_tex_image(
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
        if self.reads_elsewhere() {
            // EXT_framebuffer_blit: the texels come from the read framebuffer.
            let read = self.fbo.read_bound;
            return self.with_framebuffer_bound(read, |c| {
                c.copy_tex_image(dims, target, level, internalformat, x, y, size, border)
            });
        }
        if !self.framebuffer_ready() {
            return;
        }
        let r = (|| -> Check<()> {
            let target =
                convert::tex_image_target_for(target, dims, false).ok_or(GL_INVALID_ENUM)?;
            let level = check_level(target.texture_target(), level)?;
            // Section 3.8.2: not the GL 1.0 component counts 1-4 (an enum parameter, so
            // INVALID_ENUM as for any other value outside its set).
            if (1..=4).contains(&internalformat) {
                return Err(GL_INVALID_ENUM);
            }
            let ifmt = check_internal_format(internalformat as GLint, dims)?;
            self.check_mutable(target)?;
            let stored = check_size(target, level, [size[0], size[1], 1], border)
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

    pub(super) fn copy_tex_sub_image(
        &mut self,
        dims: usize,
        target: GLenum,
        level: GLint,
        offset: [GLint; 3],
        x: GLint,
        y: GLint,
        size: [GLsizei; 2],
    ) {
        if self.reads_elsewhere() {
            let read = self.fbo.read_bound;
            return self.with_framebuffer_bound(read, |c| {
                c.copy_tex_sub_image(dims, target, level, offset, x, y, size)
            });
        }
        if !self.framebuffer_ready() {
            return;
        }
        let r = (|| -> Check<()> {
            let target =
                convert::tex_image_target_for(target, dims, false).ok_or(GL_INVALID_ENUM)?;
            let level = check_level(target.texture_target(), level)?;
            if size[0] < 0 || size[1] < 0 {
                return Err(GL_INVALID_VALUE);
            }
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
            let (b, depth) = self
                .with_image(target, level, |img| -> Check<([i32; 3], bool)> {
                    check_sub_region(dims, off, region, img.borders(), img.inner_size())?;
                    check_compressed_alignment(img, off, region)?;
                    Ok((img.borders(), img.format.is_depth()))
                })
                .ok_or(GL_INVALID_OPERATION)??;
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
}

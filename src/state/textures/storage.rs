//! ARB_texture_storage: `glTexStorage{1D,2D,3D}` define every level of a texture at once and
//! make its format and sizes immutable (`GL_TEXTURE_IMMUTABLE_FORMAT`).

use super::*;

/// The base internal formats of table 3.11 (and the GL 1.0 component counts): unsized, which
/// `glTexStorage*` refuses with `GL_INVALID_ENUM`, as it does the generic compressed formats.
fn unsized_format(f: GLenum) -> bool {
    matches!(
        f,
        1 | 2
            | 3
            | 4
            | GL_ALPHA
            | GL_LUMINANCE
            | GL_LUMINANCE_ALPHA
            | GL_INTENSITY
            | GL_RGB
            | GL_RGBA
            | GL_RED
            | GL_RG
            | GL_DEPTH_COMPONENT
            | GL_DEPTH_STENCIL
            | GL_COMPRESSED_ALPHA
            | GL_COMPRESSED_LUMINANCE
            | GL_COMPRESSED_LUMINANCE_ALPHA
            | GL_COMPRESSED_INTENSITY
            | GL_COMPRESSED_RGB
            | GL_COMPRESSED_RGBA
            | GL_COMPRESSED_RED
            | GL_COMPRESSED_RG
    )
}

impl Context {
    pub(crate) fn tex_storage_1d(
        &mut self,
        target: GLenum,
        levels: GLsizei,
        internalformat: GLenum,
        width: GLsizei,
    ) {
        self.tex_storage(1, target, levels, internalformat, [width, 1, 1]);
    }

    pub(crate) fn tex_storage_2d(
        &mut self,
        target: GLenum,
        levels: GLsizei,
        internalformat: GLenum,
        width: GLsizei,
        height: GLsizei,
    ) {
        self.tex_storage(2, target, levels, internalformat, [width, height, 1]);
    }

    pub(crate) fn tex_storage_3d(
        &mut self,
        target: GLenum,
        levels: GLsizei,
        internalformat: GLenum,
        width: GLsizei,
        height: GLsizei,
        depth: GLsizei,
    ) {
        self.tex_storage(3, target, levels, internalformat, [width, height, depth]);
    }

    fn tex_storage(
        &mut self,
        dims: usize,
        target: GLenum,
        levels: GLsizei,
        internalformat: GLenum,
        size: [GLsizei; 3],
    ) {
        if let Err(e) = self.tex_storage_checked(dims, target, levels, internalformat, size) {
            self.record_error(e);
        }
    }

    /// The pseudo-code of the extension's section 3.8.4: `glTexImage*` of each level (each
    /// face of a cube map) with no data, sizes halved (at least 1) per level, after the
    /// checks of its "Errors" section, in that order.
    fn tex_storage_checked(
        &mut self,
        dims: usize,
        target: GLenum,
        levels: GLsizei,
        internalformat: GLenum,
        size: [GLsizei; 3],
    ) -> Check<()> {
        // The targets the command takes: 1D; 2D, rectangle, cube map; 3D (and their
        // proxies). tilegl has no array textures.
        let tt = convert::texture_target(target)
            .map(|t| (t, false))
            .or_else(|| {
                convert::tex_image_target(target)
                    .filter(|t| t.is_proxy())
                    .map(|t| (t.texture_target(), true))
            });
        let (tt, proxy) = tt.ok_or(GL_INVALID_ENUM)?;
        let accepted = match dims {
            1 => tt == TextureTarget::T1D,
            2 => matches!(
                tt,
                TextureTarget::T2D | TextureTarget::Rectangle | TextureTarget::CubeMap
            ),
            _ => tt == TextureTarget::T3D,
        };
        if !accepted {
            return Err(GL_INVALID_ENUM);
        }
        if unsized_format(internalformat) {
            return Err(GL_INVALID_ENUM);
        }
        let ifmt =
            convert::internal_format(internalformat as GLint, dims).ok_or(GL_INVALID_ENUM)?;
        if levels < 1 || size[..dims].iter().any(|&s| s < 1) {
            return Err(GL_INVALID_VALUE);
        }
        let largest = size[..dims].iter().copied().max().unwrap_or(1);
        let max_levels = 32 - (largest as u32).leading_zeros() as GLsizei;
        if levels > max_levels {
            return Err(GL_INVALID_OPERATION);
        }
        if !proxy
            && self
                .textures
                .bound(self.active_texture, tt)
                .immutable_levels
                .is_some()
        {
            return Err(GL_INVALID_OPERATION);
        }
        let (format, type_) = if ifmt.is_depth() && ifmt.stencil {
            (GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8)
        } else if ifmt.is_depth() {
            (GL_DEPTH_COMPONENT, GL_FLOAT)
        } else {
            (GL_RGBA, GL_UNSIGNED_BYTE)
        };
        let faces: Vec<GLenum> = if tt == TextureTarget::CubeMap && !proxy {
            (0..6).map(|f| GL_TEXTURE_CUBE_MAP_POSITIVE_X + f).collect()
        } else {
            vec![target]
        };
        // Level 0 is the largest: when it is accepted, every smaller level is.
        let mut s = size;
        for level in 0..levels {
            for &face in &faces {
                self.tex_image_checked(
                    dims,
                    face,
                    level,
                    internalformat as GLint,
                    s,
                    0,
                    format,
                    type_,
                    None,
                )?;
            }
            for d in 0..dims {
                // A rectangle or cube map keeps halving both sides.
                s[d] = (s[d] / 2).max(1);
            }
        }
        if !proxy {
            // Levels beyond the storage from earlier glTexImage calls are no longer part of
            // the texture.
            let mut obj = self.textures.bound_mut(self.active_texture, tt);
            for face in obj.images.iter_mut() {
                for img in face.iter_mut().skip(levels as usize) {
                    *img = None;
                }
            }
            obj.immutable_levels = Some(levels as usize);
        }
        self.invalidate();
        Ok(())
    }
}

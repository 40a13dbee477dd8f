//! Texture parameters (`glTexParameter*`, `glGetTexParameter*`, `glGetTexLevelParameter*`).

use super::*;
use crate::texture::SamplerParams;

/// Sets one of the sampler-state parameters (those a sampler object holds too, see
/// [`TexParam::is_sampler_state`]) in `params`, with `glTexParameter`'s value checks: an
/// unknown value is `GL_INVALID_ENUM`, an anisotropy below 1 `GL_INVALID_VALUE`. Texture
/// objects keep border colours clamped to [0, 1] (`clamp_border`); sampler objects keep them
/// as given, as Mesa does.
pub(super) fn set_sampler_state(
    params: &mut SamplerParams,
    p: TexParam,
    v: Values,
    clamp_border: bool,
) -> Check<()> {
    let e = v.enumv(0);
    match p {
        TexParam::MinFilter => params.min_filter = convert::min_filter(e).ok_or(GL_INVALID_ENUM)?,
        TexParam::MagFilter => params.mag_filter = convert::mag_filter(e).ok_or(GL_INVALID_ENUM)?,
        TexParam::WrapS | TexParam::WrapT | TexParam::WrapR => {
            let i = match p {
                TexParam::WrapS => 0,
                TexParam::WrapT => 1,
                _ => 2,
            };
            params.wrap[i] = convert::wrap_mode(e).ok_or(GL_INVALID_ENUM)?;
        }
        TexParam::BorderColor => {
            params.border_color = [0, 1, 2, 3].map(|i| {
                let c = v.color(i);
                if clamp_border {
                    clamp01(c)
                } else {
                    c
                }
            });
        }
        TexParam::MinLod => params.min_lod = v.float(0),
        TexParam::MaxLod => params.max_lod = v.float(0),
        TexParam::LodBias => params.lod_bias = v.float(0),
        TexParam::CompareMode => {
            params.compare = convert::texture_compare_mode(e).ok_or(GL_INVALID_ENUM)?
        }
        TexParam::CompareFunc => {
            params.compare_func = convert::compare_func(e).ok_or(GL_INVALID_ENUM)?
        }
        TexParam::MaxAnisotropy => {
            let a = v.float(0);
            if a.is_nan() || a < 1.0 {
                return Err(GL_INVALID_VALUE);
            }
            params.max_anisotropy = a.min(MAX_TEXTURE_MAX_ANISOTROPY);
        }
        _ => return Err(GL_INVALID_ENUM),
    }
    Ok(())
}

/// The value of a sampler-state parameter (`None` for image state): numbers, and whether
/// they are colour components (which map to the full integer range in the `iv` queries).
pub(super) fn sampler_state_values(q: &SamplerParams, p: TexParam) -> Option<(Vec<f64>, bool)> {
    let e = |v: GLenum| vec![v as f64];
    Some(match p {
        TexParam::MinFilter => (e(q.min_filter.to_gl()), false),
        TexParam::MagFilter => (e(q.mag_filter.to_gl()), false),
        TexParam::WrapS => (e(q.wrap[0].to_gl()), false),
        TexParam::WrapT => (e(q.wrap[1].to_gl()), false),
        TexParam::WrapR => (e(q.wrap[2].to_gl()), false),
        TexParam::BorderColor => (q.border_color.iter().map(|&c| c as f64).collect(), true),
        TexParam::MinLod => (vec![q.min_lod as f64], false),
        TexParam::MaxLod => (vec![q.max_lod as f64], false),
        TexParam::LodBias => (vec![q.lod_bias as f64], false),
        TexParam::CompareMode => (e(convert::compare_mode_to_gl(q.compare)), false),
        TexParam::CompareFunc => (e(q.compare_func.to_gl()), false),
        TexParam::MaxAnisotropy => (vec![q.max_anisotropy as f64], false),
        _ => return None,
    })
}

/// A query's values as `glGet*iv` answers them: colour components mapped linearly from
/// [-1, 1] to the full integer range (truncated toward zero, as the other colour queries
/// and Mesa's do), other values rounded to the nearest integer (section 6.1.2).
pub(super) fn ints_of(v: &[f64], color: bool, out: &mut [GLint]) {
    for (o, &x) in out.iter_mut().zip(v) {
        *o = if color {
            (x.clamp(-1.0, 1.0) * i32::MAX as f64) as i32
        } else {
            x.round() as i32
        };
    }
}

impl Context {
    pub(super) fn tex_parameter(&mut self, target: GLenum, pname: GLenum, v: Values, vector: bool) {
        let r = (|| -> Check<()> {
            let t = convert::texture_target(target).ok_or(GL_INVALID_ENUM)?;
            let p = convert::tex_param(pname).ok_or(GL_INVALID_ENUM)?;
            let four = matches!(p, TexParam::BorderColor | TexParam::SwizzleRgba);
            if matches!(p, TexParam::Resident | TexParam::ImmutableFormat) || (four && !vector) {
                return Err(GL_INVALID_ENUM);
            }
            let needed = if four { 4 } else { 1 };
            if v.len() < needed {
                return Err(GL_INVALID_VALUE);
            }
            let mut obj = self.textures.bound_mut(self.active_texture, t);
            let mut params = obj.params;
            let mut priority = obj.priority;
            let e = v.enumv(0);
            if p.is_sampler_state() {
                set_sampler_state(&mut params, p, v, true)?;
                // Rectangle textures have no mipmaps and only clamp (ARB_texture_rectangle).
                let shape = matches!(
                    p,
                    TexParam::MinFilter | TexParam::WrapS | TexParam::WrapT | TexParam::WrapR
                );
                if t == TextureTarget::Rectangle && shape && !params.fit_rectangle() {
                    return Err(GL_INVALID_ENUM);
                }
            }
            match p {
                TexParam::Priority => priority = clamp01(v.float(0)),
                TexParam::BaseLevel | TexParam::MaxLevel => {
                    let n = v.int(0);
                    if n < 0 {
                        return Err(GL_INVALID_VALUE);
                    }
                    // ARB_texture_storage: an immutable texture's levels are clamped to its
                    // storage, base to [0, levels - 1], max to [base, levels - 1]; the value
                    // kept is the clamped one, as Mesa and piglit's texture-storage have it
                    // (OpenGL 4.3 words it so).
                    let last = obj.immutable_levels.map(|l| l.saturating_sub(1) as i32);
                    if p == TexParam::BaseLevel {
                        params.base_level = last.map_or(n, |l| n.min(l));
                    } else {
                        params.max_level = last.map_or(n, |l| n.clamp(params.base_level.min(l), l));
                    }
                }
                TexParam::GenerateMipmap => params.generate_mipmap = v.float(0) != 0.0,
                TexParam::DepthTextureMode => {
                    params.depth_mode = convert::depth_texture_mode(e).ok_or(GL_INVALID_ENUM)?
                }
                TexParam::Resident | TexParam::ImmutableFormat => return Err(GL_INVALID_ENUM),
                // Set above.
                TexParam::MinFilter
                | TexParam::MagFilter
                | TexParam::WrapS
                | TexParam::WrapT
                | TexParam::WrapR
                | TexParam::BorderColor
                | TexParam::MinLod
                | TexParam::MaxLod
                | TexParam::LodBias
                | TexParam::CompareMode
                | TexParam::CompareFunc
                | TexParam::MaxAnisotropy => {}
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
    pub(super) fn tex_parameter_values(
        &self,
        target: GLenum,
        pname: GLenum,
    ) -> Check<(Vec<f64>, bool)> {
        let t = convert::texture_target(target).ok_or(GL_INVALID_ENUM)?;
        let p = convert::tex_param(pname).ok_or(GL_INVALID_ENUM)?;
        let obj = self.textures.bound(self.active_texture, t);
        let q = &obj.params;
        let e = |v: GLenum| vec![v as f64];
        Ok(match p {
            TexParam::Priority => (vec![obj.priority as f64], false),
            TexParam::BaseLevel => (vec![q.base_level as f64], false),
            TexParam::MaxLevel => (vec![q.max_level as f64], false),
            TexParam::GenerateMipmap => (vec![q.generate_mipmap as u8 as f64], false),
            TexParam::DepthTextureMode => (e(q.depth_mode.to_gl()), false),
            TexParam::Resident => (vec![1.0], false),
            TexParam::ImmutableFormat => (vec![obj.immutable_levels.is_some() as u8 as f64], false),
            TexParam::Swizzle(i) => (e(q.swizzle[i].to_gl()), false),
            TexParam::SwizzleRgba => (q.swizzle.iter().map(|s| s.to_gl() as f64).collect(), false),
            TexParam::MinFilter
            | TexParam::MagFilter
            | TexParam::WrapS
            | TexParam::WrapT
            | TexParam::WrapR
            | TexParam::BorderColor
            | TexParam::MinLod
            | TexParam::MaxLod
            | TexParam::LodBias
            | TexParam::CompareMode
            | TexParam::CompareFunc
            | TexParam::MaxAnisotropy => sampler_state_values(q, p).unwrap_or_default(),
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
            Ok((v, color)) if params.len() >= v.len() => ints_of(&v, color, params),
            Ok(_) => self.record_error(GL_INVALID_VALUE),
            Err(e) => self.record_error(e),
        }
    }

    pub(super) fn tex_level_parameter(
        &self,
        target: GLenum,
        level: GLint,
        pname: GLenum,
    ) -> Check<i64> {
        let target = convert::tex_image_target(target).ok_or(GL_INVALID_ENUM)?;
        let level = check_level(target.texture_target(), level)?;
        let p = convert::tex_level_param(pname).ok_or(GL_INVALID_ENUM)?;
        let img = self.image_at(target, level);
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
        // ARB_texture_float: FLOAT or UNSIGNED_NORMALIZED for a component the image has,
        // NONE for the others.
        let kind = if f.float {
            GL_FLOAT
        } else {
            GL_UNSIGNED_NORMALIZED_ARB
        };
        let type_of = |yes: bool| if yes { kind as i64 } else { GL_NONE as i64 };
        use BaseFormat::*;
        Ok(match p {
            TexLevelParam::Width => img.width as i64,
            TexLevelParam::Height => img.height as i64,
            TexLevelParam::Depth => img.depth as i64,
            TexLevelParam::InternalFormat => f.reported() as i64,
            TexLevelParam::Border => img.border as i64,
            TexLevelParam::RedSize => has(matches!(f.base, Red | Rg | Rgb | Rgba)),
            TexLevelParam::GreenSize => has(matches!(f.base, Rg | Rgb | Rgba)),
            TexLevelParam::BlueSize => has(matches!(f.base, Rgb | Rgba)),
            TexLevelParam::AlphaSize => has(matches!(f.base, Alpha | LuminanceAlpha | Rgba)),
            TexLevelParam::LuminanceSize => has(matches!(f.base, Luminance | LuminanceAlpha)),
            TexLevelParam::IntensitySize => has(f.base == Intensity),
            TexLevelParam::DepthSize => has(f.base == DepthComponent),
            TexLevelParam::StencilSize => {
                if f.stencil {
                    8
                } else {
                    0
                }
            }
            TexLevelParam::RedType => type_of(matches!(f.base, Red | Rg | Rgb | Rgba)),
            TexLevelParam::GreenType => type_of(matches!(f.base, Rg | Rgb | Rgba)),
            TexLevelParam::BlueType => type_of(matches!(f.base, Rgb | Rgba)),
            TexLevelParam::AlphaType => type_of(matches!(f.base, Alpha | LuminanceAlpha | Rgba)),
            TexLevelParam::LuminanceType => type_of(matches!(f.base, Luminance | LuminanceAlpha)),
            TexLevelParam::IntensityType => type_of(f.base == Intensity),
            // ARB_depth_buffer_float's formats hold float depth (kept here as 32-bit
            // normalised values, which depth in [0, 1] fits).
            TexLevelParam::DepthType => match f.requested as GLenum {
                GL_DEPTH_COMPONENT32F | GL_DEPTH32F_STENCIL8 => GL_FLOAT as i64,
                _ => type_of(f.base == DepthComponent),
            },
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
}

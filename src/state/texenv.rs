//! Texture units and their environments (sections 2.7, 3.8.13): `glActiveTexture`,
//! `glClientActiveTexture`, `glMultiTexCoord*`, `glTexEnv*`, `glGetTexEnv*`.

use glam::Vec4;

use super::Context;
use crate::common::values::TexEnvParam;
use crate::gl::convert;
use crate::gl::enums::*;
use crate::vertex::immediate::norm_i32;

pub use crate::fragment::texenv::{Combine, TexEnv};

impl Context {
    pub(crate) fn active_texture(&mut self, texture: GLenum) {
        let Some(u) = convert::texture_unit(texture) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.active_texture = u;
    }

    pub(crate) fn client_active_texture(&mut self, texture: GLenum) {
        let Some(u) = convert::texture_unit(texture) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.client_active_texture = u;
    }

    /// `glMultiTexCoord`: an invalid unit is `GL_INVALID_ENUM` (legal inside glBegin/glEnd).
    pub(crate) fn multi_tex_coord(&mut self, target: GLenum, v: Vec4) {
        match convert::texture_unit(target) {
            Some(u) => self.current.texcoords[u] = v,
            None => self.record_error(GL_INVALID_ENUM),
        }
    }

    fn tex_env_values(&mut self, target: GLenum, pname: GLenum, v: &[f32], vector: bool) {
        if target == GL_POINT_SPRITE {
            // ARB_point_sprite: the unit's GL_COORD_REPLACE, a boolean.
            if pname != GL_COORD_REPLACE || v.is_empty() {
                self.record_error(GL_INVALID_ENUM);
                return;
            }
            let bit = 1u32 << self.active_texture;
            let r = &mut self.raster;
            r.point_sprite_coord_replace =
                (r.point_sprite_coord_replace & !bit) | if v[0] != 0.0 { bit } else { 0 };
            self.invalidate();
            return;
        }
        let Some(p) = convert::tex_env_param(target, pname) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let need = if p == TexEnvParam::Color { 4 } else { 1 };
        if (!vector && need > 1) || v.len() < need {
            self.record_error(if vector {
                GL_INVALID_VALUE
            } else {
                GL_INVALID_ENUM
            });
            return;
        }
        let as_enum = v[0] as GLenum;
        let unit = self.active_texture;
        let env = &mut self.tex_env[unit];
        let ok = match p {
            TexEnvParam::Mode => convert::tex_env_mode(as_enum).map(|m| env.mode = m),
            TexEnvParam::Color => {
                env.color = [v[0], v[1], v[2], v[3]].map(|c| c.clamp(0.0, 1.0));
                Some(())
            }
            TexEnvParam::LodBias => {
                env.lod_bias = v[0];
                Some(())
            }
            TexEnvParam::CombineRgb => {
                convert::combine_func(as_enum, true).map(|f| env.combine.rgb = f)
            }
            TexEnvParam::CombineAlpha => {
                convert::combine_func(as_enum, false).map(|f| env.combine.alpha = f)
            }
            TexEnvParam::Source { rgb, n } => convert::combine_source(as_enum).map(|s| {
                if rgb {
                    env.combine.src_rgb[n] = s
                } else {
                    env.combine.src_alpha[n] = s
                }
            }),
            TexEnvParam::Operand { rgb, n } => convert::combine_operand(as_enum, rgb).map(|o| {
                if rgb {
                    env.combine.op_rgb[n] = o
                } else {
                    env.combine.op_alpha[n] = o
                }
            }),
            TexEnvParam::RgbScale | TexEnvParam::AlphaScale => {
                let s = v[0];
                if s != 1.0 && s != 2.0 && s != 4.0 {
                    self.record_error(GL_INVALID_VALUE);
                    return;
                }
                if p == TexEnvParam::RgbScale {
                    env.combine.rgb_scale = s as u8;
                } else {
                    env.combine.alpha_scale = s as u8;
                }
                Some(())
            }
        };
        if ok.is_none() {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        self.invalidate();
    }

    pub(crate) fn tex_envf(&mut self, target: GLenum, pname: GLenum, param: GLfloat) {
        self.tex_env_values(target, pname, &[param], false);
    }

    pub(crate) fn tex_envi(&mut self, target: GLenum, pname: GLenum, param: GLint) {
        self.tex_env_values(target, pname, &[param as f32], false);
    }

    pub(crate) fn tex_envfv(&mut self, target: GLenum, pname: GLenum, params: &[GLfloat]) {
        self.tex_env_values(target, pname, params, true);
    }

    pub(crate) fn tex_enviv(&mut self, target: GLenum, pname: GLenum, params: &[GLint]) {
        // The environment colour is a colour: integers map onto [-1, 1] (then clamp).
        let color = convert::tex_env_param(target, pname) == Some(TexEnvParam::Color);
        let v: Vec<f32> = params
            .iter()
            .map(|&x| if color { norm_i32(x) } else { x as f32 })
            .collect();
        self.tex_env_values(target, pname, &v, true);
    }

    fn tex_env_query(
        &mut self,
        target: GLenum,
        pname: GLenum,
        len: usize,
    ) -> Option<(Vec<f32>, bool)> {
        if target == GL_POINT_SPRITE && pname == GL_COORD_REPLACE {
            let on = self.raster.point_sprite_coord_replace >> self.active_texture & 1;
            return Some((vec![on as f32], false)).filter(|_| len >= 1);
        }
        let Some(p) = convert::tex_env_param(target, pname) else {
            self.record_error(GL_INVALID_ENUM);
            return None;
        };
        let env = &self.tex_env[self.active_texture];
        let e = |x: GLenum| vec![x as f32];
        let v = match p {
            TexEnvParam::Mode => e(env.mode.to_gl()),
            TexEnvParam::Color => return Some((env.color.to_vec(), true)).filter(|_| len >= 4),
            TexEnvParam::LodBias => vec![env.lod_bias],
            TexEnvParam::CombineRgb => e(env.combine.rgb.to_gl()),
            TexEnvParam::CombineAlpha => e(env.combine.alpha.to_gl()),
            TexEnvParam::Source { rgb: true, n } => e(env.combine.src_rgb[n].to_gl()),
            TexEnvParam::Source { rgb: false, n } => e(env.combine.src_alpha[n].to_gl()),
            TexEnvParam::Operand { rgb: true, n } => e(env.combine.op_rgb[n].to_gl()),
            TexEnvParam::Operand { rgb: false, n } => e(env.combine.op_alpha[n].to_gl()),
            TexEnvParam::RgbScale => vec![env.combine.rgb_scale as f32],
            TexEnvParam::AlphaScale => vec![env.combine.alpha_scale as f32],
        };
        Some((v, false)).filter(|_| len >= 1)
    }

    pub(crate) fn get_tex_envfv(&mut self, target: GLenum, pname: GLenum, params: &mut [GLfloat]) {
        match self.tex_env_query(target, pname, params.len()) {
            Some((v, _)) => params[..v.len()].copy_from_slice(&v),
            None if self.error.peek() == GL_NO_ERROR => self.record_error(GL_INVALID_VALUE),
            None => {}
        }
    }

    pub(crate) fn get_tex_enviv(&mut self, target: GLenum, pname: GLenum, params: &mut [GLint]) {
        match self.tex_env_query(target, pname, params.len()) {
            Some((v, color)) => {
                for (o, x) in params.iter_mut().zip(v) {
                    *o = if color {
                        (x as f64 * 2147483647.0) as i32
                    } else {
                        x.round() as i32
                    };
                }
            }
            None if self.error.peek() == GL_NO_ERROR => self.record_error(GL_INVALID_VALUE),
            None => {}
        }
    }
}

impl Context {
    pub(crate) fn multi_tex_coord_1d(&mut self, target: GLenum, s: GLdouble) {
        self.multi_tex_coord(target, Vec4::new(s as f32, 0.0, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_1dv(&mut self, target: GLenum, v: &[GLdouble; 1]) {
        self.multi_tex_coord(target, Vec4::new(v[0] as f32, 0.0, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_1f(&mut self, target: GLenum, s: GLfloat) {
        self.multi_tex_coord(target, Vec4::new(s, 0.0, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_1fv(&mut self, target: GLenum, v: &[GLfloat; 1]) {
        self.multi_tex_coord(target, Vec4::new(v[0], 0.0, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_1i(&mut self, target: GLenum, s: GLint) {
        self.multi_tex_coord(target, Vec4::new(s as f32, 0.0, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_1iv(&mut self, target: GLenum, v: &[GLint; 1]) {
        self.multi_tex_coord(target, Vec4::new(v[0] as f32, 0.0, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_1s(&mut self, target: GLenum, s: GLshort) {
        self.multi_tex_coord(target, Vec4::new(s as f32, 0.0, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_1sv(&mut self, target: GLenum, v: &[GLshort; 1]) {
        self.multi_tex_coord(target, Vec4::new(v[0] as f32, 0.0, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_2d(&mut self, target: GLenum, s: GLdouble, t: GLdouble) {
        self.multi_tex_coord(target, Vec4::new(s as f32, t as f32, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_2dv(&mut self, target: GLenum, v: &[GLdouble; 2]) {
        self.multi_tex_coord(target, Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_2f(&mut self, target: GLenum, s: GLfloat, t: GLfloat) {
        self.multi_tex_coord(target, Vec4::new(s, t, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_2fv(&mut self, target: GLenum, v: &[GLfloat; 2]) {
        self.multi_tex_coord(target, Vec4::new(v[0], v[1], 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_2i(&mut self, target: GLenum, s: GLint, t: GLint) {
        self.multi_tex_coord(target, Vec4::new(s as f32, t as f32, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_2iv(&mut self, target: GLenum, v: &[GLint; 2]) {
        self.multi_tex_coord(target, Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_2s(&mut self, target: GLenum, s: GLshort, t: GLshort) {
        self.multi_tex_coord(target, Vec4::new(s as f32, t as f32, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_2sv(&mut self, target: GLenum, v: &[GLshort; 2]) {
        self.multi_tex_coord(target, Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0));
    }
    pub(crate) fn multi_tex_coord_3d(
        &mut self,
        target: GLenum,
        s: GLdouble,
        t: GLdouble,
        r: GLdouble,
    ) {
        self.multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, 1.0));
    }
    pub(crate) fn multi_tex_coord_3dv(&mut self, target: GLenum, v: &[GLdouble; 3]) {
        self.multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0),
        );
    }
    pub(crate) fn multi_tex_coord_3f(
        &mut self,
        target: GLenum,
        s: GLfloat,
        t: GLfloat,
        r: GLfloat,
    ) {
        self.multi_tex_coord(target, Vec4::new(s, t, r, 1.0));
    }
    pub(crate) fn multi_tex_coord_3fv(&mut self, target: GLenum, v: &[GLfloat; 3]) {
        self.multi_tex_coord(target, Vec4::new(v[0], v[1], v[2], 1.0));
    }
    pub(crate) fn multi_tex_coord_3i(&mut self, target: GLenum, s: GLint, t: GLint, r: GLint) {
        self.multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, 1.0));
    }
    pub(crate) fn multi_tex_coord_3iv(&mut self, target: GLenum, v: &[GLint; 3]) {
        self.multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0),
        );
    }
    pub(crate) fn multi_tex_coord_3s(
        &mut self,
        target: GLenum,
        s: GLshort,
        t: GLshort,
        r: GLshort,
    ) {
        self.multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, 1.0));
    }
    pub(crate) fn multi_tex_coord_3sv(&mut self, target: GLenum, v: &[GLshort; 3]) {
        self.multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0),
        );
    }
    pub(crate) fn multi_tex_coord_4d(
        &mut self,
        target: GLenum,
        s: GLdouble,
        t: GLdouble,
        r: GLdouble,
        q: GLdouble,
    ) {
        self.multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, q as f32));
    }
    pub(crate) fn multi_tex_coord_4dv(&mut self, target: GLenum, v: &[GLdouble; 4]) {
        self.multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32),
        );
    }
    pub(crate) fn multi_tex_coord_4f(
        &mut self,
        target: GLenum,
        s: GLfloat,
        t: GLfloat,
        r: GLfloat,
        q: GLfloat,
    ) {
        self.multi_tex_coord(target, Vec4::new(s, t, r, q));
    }
    pub(crate) fn multi_tex_coord_4fv(&mut self, target: GLenum, v: &[GLfloat; 4]) {
        self.multi_tex_coord(target, Vec4::new(v[0], v[1], v[2], v[3]));
    }
    pub(crate) fn multi_tex_coord_4i(
        &mut self,
        target: GLenum,
        s: GLint,
        t: GLint,
        r: GLint,
        q: GLint,
    ) {
        self.multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, q as f32));
    }
    pub(crate) fn multi_tex_coord_4iv(&mut self, target: GLenum, v: &[GLint; 4]) {
        self.multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32),
        );
    }
    pub(crate) fn multi_tex_coord_4s(
        &mut self,
        target: GLenum,
        s: GLshort,
        t: GLshort,
        r: GLshort,
        q: GLshort,
    ) {
        self.multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, q as f32));
    }
    pub(crate) fn multi_tex_coord_4sv(&mut self, target: GLenum, v: &[GLshort; 4]) {
        self.multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32),
        );
    }
}

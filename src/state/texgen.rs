//! Texture coordinate generation state and entry points (section 2.11.4): `glTexGen*` and
//! `glGetTexGen*`, per texture unit and coordinate. The generation itself is in
//! `vertex::texgen`.

use glam::{DVec4, Mat4};

use super::Context;
use crate::common::values::{TexGenMode, TexGenParam};
use crate::gl::convert;
use crate::gl::enums::*;

/// Generation for one coordinate of one unit (table 6.16).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexGenCoord {
    pub enabled: bool,
    pub mode: TexGenMode,
    pub object_plane: [f64; 4],
    /// In eye coordinates: transformed by the inverse modelview at `glTexGen` time.
    pub eye_plane: [f64; 4],
}

/// The four coordinates of a unit.
pub type TexGenUnit = [TexGenCoord; 4];

/// Defaults: EYE_LINEAR; planes (1,0,0,0) for s, (0,1,0,0) for t, zero for r and q.
pub fn default_unit() -> TexGenUnit {
    std::array::from_fn(|i| {
        let mut plane = [0.0; 4];
        if i < 2 {
            plane[i] = 1.0;
        }
        TexGenCoord {
            enabled: false,
            mode: TexGenMode::EyeLinear,
            object_plane: plane,
            eye_plane: plane,
        }
    })
}

impl Context {
    fn tex_gen_values(&mut self, coord: GLenum, pname: GLenum, v: &[f64], vector: bool) {
        let (Some(c), Some(p)) = (convert::tex_gen_coord(coord), convert::tex_gen_param(pname))
        else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let need = if p == TexGenParam::Mode { 1 } else { 4 };
        if (!vector && need > 1) || v.len() < need {
            self.record_error(if vector {
                GL_INVALID_VALUE
            } else {
                GL_INVALID_ENUM
            });
            return;
        }
        let unit = self.active_texture;
        match p {
            TexGenParam::Mode => match convert::tex_gen_mode(v[0] as GLenum, c) {
                Some(m) => self.tex_gen[unit][c].mode = m,
                None => {
                    self.record_error(GL_INVALID_ENUM);
                    return;
                }
            },
            TexGenParam::ObjectPlane => {
                self.tex_gen[unit][c].object_plane = [v[0], v[1], v[2], v[3]];
            }
            TexGenParam::EyePlane => {
                // (p1 p2 p3 p4) M^-1 with M the modelview matrix at the call.
                let mv = *self.transform.modelview.last().unwrap_or(&Mat4::IDENTITY);
                let inv = super::matrices::inverse_or_identity(mv).as_dmat4();
                let e = inv.transpose() * DVec4::new(v[0], v[1], v[2], v[3]);
                self.tex_gen[unit][c].eye_plane = e.to_array();
            }
        }
        self.invalidate();
    }

    pub(crate) fn tex_gend(&mut self, coord: GLenum, pname: GLenum, param: GLdouble) {
        self.tex_gen_values(coord, pname, &[param], false);
    }

    pub(crate) fn tex_genf(&mut self, coord: GLenum, pname: GLenum, param: GLfloat) {
        self.tex_gen_values(coord, pname, &[param as f64], false);
    }

    pub(crate) fn tex_geni(&mut self, coord: GLenum, pname: GLenum, param: GLint) {
        self.tex_gen_values(coord, pname, &[param as f64], false);
    }

    pub(crate) fn tex_gendv(&mut self, coord: GLenum, pname: GLenum, params: &[GLdouble]) {
        self.tex_gen_values(coord, pname, params, true);
    }

    pub(crate) fn tex_genfv(&mut self, coord: GLenum, pname: GLenum, params: &[GLfloat]) {
        let v: Vec<f64> = params.iter().map(|&x| x as f64).collect();
        self.tex_gen_values(coord, pname, &v, true);
    }

    pub(crate) fn tex_geniv(&mut self, coord: GLenum, pname: GLenum, params: &[GLint]) {
        let v: Vec<f64> = params.iter().map(|&x| x as f64).collect();
        self.tex_gen_values(coord, pname, &v, true);
    }

    fn tex_gen_query(&mut self, coord: GLenum, pname: GLenum, len: usize) -> Option<Vec<f64>> {
        let (Some(c), Some(p)) = (convert::tex_gen_coord(coord), convert::tex_gen_param(pname))
        else {
            self.record_error(GL_INVALID_ENUM);
            return None;
        };
        let g = &self.tex_gen[self.active_texture][c];
        let v = match p {
            TexGenParam::Mode => vec![g.mode.to_gl() as f64],
            TexGenParam::ObjectPlane => g.object_plane.to_vec(),
            TexGenParam::EyePlane => g.eye_plane.to_vec(),
        };
        if len < v.len() {
            self.record_error(GL_INVALID_VALUE);
            return None;
        }
        Some(v)
    }

    pub(crate) fn get_tex_gendv(&mut self, coord: GLenum, pname: GLenum, params: &mut [GLdouble]) {
        if let Some(v) = self.tex_gen_query(coord, pname, params.len()) {
            params[..v.len()].copy_from_slice(&v);
        }
    }

    pub(crate) fn get_tex_genfv(&mut self, coord: GLenum, pname: GLenum, params: &mut [GLfloat]) {
        if let Some(v) = self.tex_gen_query(coord, pname, params.len()) {
            for (o, x) in params.iter_mut().zip(v) {
                *o = x as f32;
            }
        }
    }

    pub(crate) fn get_tex_geniv(&mut self, coord: GLenum, pname: GLenum, params: &mut [GLint]) {
        if let Some(v) = self.tex_gen_query(coord, pname, params.len()) {
            for (o, x) in params.iter_mut().zip(v) {
                *o = x.round().clamp(i32::MIN as f64, i32::MAX as f64) as i32;
            }
        }
    }
}

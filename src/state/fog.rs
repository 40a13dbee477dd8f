//! Fog state and entry points (section 3.10): `glFog*`, `glFogCoord*`.

use super::Context;
use crate::common::values::{FogMode, FogParam};
use crate::gl::convert;
use crate::gl::enums::*;

/// Table 6.14.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FogState {
    pub enabled: bool,
    pub mode: FogMode,
    pub density: f32,
    pub start: f32,
    pub end: f32,
    pub index: f32,
    pub color: [f32; 4],
    /// `GL_FOG_COORD` (true) or `GL_FRAGMENT_DEPTH` (false).
    pub coord_from_vertex: bool,
}

impl Default for FogState {
    fn default() -> Self {
        FogState {
            enabled: false,
            mode: FogMode::Exp,
            density: 1.0,
            start: 0.0,
            end: 1.0,
            index: 0.0,
            color: [0.0; 4],
            coord_from_vertex: false,
        }
    }
}

impl Context {
    fn fog_values(&mut self, pname: GLenum, v: &[f32], vector: bool) {
        let Some(p) = convert::fog_param(pname) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let need = if p == FogParam::Color { 4 } else { 1 };
        if (!vector && need > 1) || v.len() < need {
            self.record_error(if vector {
                GL_INVALID_VALUE
            } else {
                GL_INVALID_ENUM
            });
            return;
        }
        let f = &mut self.fog;
        match p {
            FogParam::Mode => match convert::fog_mode(v[0] as GLenum) {
                Some(m) => f.mode = m,
                None => {
                    self.record_error(GL_INVALID_ENUM);
                    return;
                }
            },
            FogParam::Density => {
                if !(v[0] >= 0.0) {
                    self.record_error(GL_INVALID_VALUE);
                    return;
                }
                f.density = v[0];
            }
            FogParam::Start => f.start = v[0],
            FogParam::End => f.end = v[0],
            FogParam::Index => f.index = v[0],
            FogParam::Color => f.color = [v[0], v[1], v[2], v[3]].map(|c| c.clamp(0.0, 1.0)),
            FogParam::CoordSource => match convert::fog_coord_source(v[0] as GLenum) {
                Some(s) => f.coord_from_vertex = s,
                None => {
                    self.record_error(GL_INVALID_ENUM);
                    return;
                }
            },
        }
        self.invalidate();
    }

    pub(crate) fn fogf(&mut self, pname: GLenum, param: GLfloat) {
        self.fog_values(pname, &[param], false);
    }

    pub(crate) fn fogi(&mut self, pname: GLenum, param: GLint) {
        self.fog_values(pname, &[param as f32], false);
    }

    pub(crate) fn fogfv(&mut self, pname: GLenum, params: &[GLfloat]) {
        self.fog_values(pname, params, true);
    }

    pub(crate) fn fogiv(&mut self, pname: GLenum, params: &[GLint]) {
        let color = pname == GL_FOG_COLOR;
        let v: Vec<f32> = params
            .iter()
            .map(|&x| {
                if color {
                    crate::vertex::immediate::norm_i32(x)
                } else {
                    x as f32
                }
            })
            .collect();
        self.fog_values(pname, &v, true);
    }

    pub(crate) fn fog_coordf(&mut self, coord: GLfloat) {
        self.current.fog_coord = coord;
    }

    pub(crate) fn fog_coordd(&mut self, coord: GLdouble) {
        self.current.fog_coord = coord as f32;
    }

    pub(crate) fn fog_coordfv(&mut self, coord: &[GLfloat; 1]) {
        self.current.fog_coord = coord[0];
    }

    pub(crate) fn fog_coorddv(&mut self, coord: &[GLdouble; 1]) {
        self.current.fog_coord = coord[0] as f32;
    }
}

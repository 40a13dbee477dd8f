//! Lighting state and its entry points (OpenGL 1.5 section 2.14): `glLight*`, `glLightModel*`,
//! `glMaterial*`, `glColorMaterial`, and the queries `glGetLight*`/`glGetMaterial*`. The
//! equations themselves are in `vertex::lighting`.

use glam::{Mat3, Vec3, Vec4};

use super::Context;
use crate::common::values::{Face, LightModelParam, LightParam, MaterialParam};
use crate::gl::convert;
use crate::gl::enums::*;

pub use crate::vertex::lighting::{Light, LightingState, Material};

fn faces(face: Face) -> &'static [usize] {
    match face {
        Face::Front => &[0],
        Face::Back => &[1],
        Face::FrontAndBack => &[0, 1],
    }
}

/// Integer parameters that are colours map like colour components (section 2.14.2).
fn int_to_float(v: i32, color: bool) -> f32 {
    if color {
        ((2.0 * v as f64 + 1.0) / 4294967295.0) as f32
    } else {
        v as f32
    }
}

impl LightingState {
    /// Applies the current colour to the tracked material properties (section 2.14.3).
    pub fn track_color(&mut self, color: Vec4) {
        if !self.color_material {
            return;
        }
        for &f in faces(self.color_material_face) {
            set_material(
                &mut self.materials[f],
                self.color_material_mode,
                &color.to_array(),
            );
        }
    }
}

fn set_material(m: &mut Material, p: MaterialParam, v: &[f32]) {
    let c = || Vec4::new(v[0], v[1], v[2], v[3]);
    match p {
        MaterialParam::Ambient => m.ambient = c(),
        MaterialParam::Diffuse => m.diffuse = c(),
        MaterialParam::Specular => m.specular = c(),
        MaterialParam::Emission => m.emission = c(),
        MaterialParam::AmbientAndDiffuse => {
            m.ambient = c();
            m.diffuse = c();
        }
        MaterialParam::Shininess => m.shininess = v[0],
        MaterialParam::ColorIndexes => {}
    }
}

impl Context {
    fn light_values(&mut self, light: GLenum, pname: GLenum, params: &[f32], vector: bool) {
        let (Some(i), Some(p)) = (convert::light_index(light), convert::light_param(pname)) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if (!vector && p.count() > 1) || params.len() < p.count() {
            self.record_error(if vector {
                GL_INVALID_VALUE
            } else {
                GL_INVALID_ENUM
            });
            return;
        }
        let v = params;
        let mv = *self
            .transform
            .modelview
            .last()
            .unwrap_or(&glam::Mat4::IDENTITY);
        let l = &mut self.lighting.lights[i];
        match p {
            LightParam::Ambient => l.ambient = Vec4::from_slice(v),
            LightParam::Diffuse => l.diffuse = Vec4::from_slice(v),
            LightParam::Specular => l.specular = Vec4::from_slice(v),
            // Transformed by the modelview matrix current at the call (section 2.14.2).
            LightParam::Position => l.position = mv * Vec4::from_slice(v),
            LightParam::SpotDirection => {
                l.spot_direction = Mat3::from_mat4(mv) * Vec3::from_slice(v)
            }
            LightParam::SpotExponent => {
                if !(0.0..=128.0).contains(&v[0]) {
                    self.record_error(GL_INVALID_VALUE);
                    return;
                }
                l.spot_exponent = v[0];
            }
            LightParam::SpotCutoff => {
                if !((0.0..=90.0).contains(&v[0]) || v[0] == 180.0) {
                    self.record_error(GL_INVALID_VALUE);
                    return;
                }
                l.spot_cutoff = v[0];
            }
            LightParam::ConstantAttenuation
            | LightParam::LinearAttenuation
            | LightParam::QuadraticAttenuation => {
                if !(v[0] >= 0.0) {
                    self.record_error(GL_INVALID_VALUE);
                    return;
                }
                let k = match p {
                    LightParam::ConstantAttenuation => 0,
                    LightParam::LinearAttenuation => 1,
                    _ => 2,
                };
                l.attenuation[k] = v[0];
            }
        }
        self.invalidate();
    }

    pub(crate) fn lightf(&mut self, light: GLenum, pname: GLenum, param: GLfloat) {
        self.light_values(light, pname, &[param], false);
    }

    pub(crate) fn lighti(&mut self, light: GLenum, pname: GLenum, param: GLint) {
        self.light_values(light, pname, &[param as f32], false);
    }

    pub(crate) fn lightfv(&mut self, light: GLenum, pname: GLenum, params: &[GLfloat]) {
        self.light_values(light, pname, params, true);
    }

    pub(crate) fn lightiv(&mut self, light: GLenum, pname: GLenum, params: &[GLint]) {
        let color = convert::light_param(pname).is_some_and(|p| p.is_color());
        let v: Vec<f32> = params.iter().map(|&x| int_to_float(x, color)).collect();
        self.light_values(light, pname, &v, true);
    }

    fn light_model_values(&mut self, pname: GLenum, v: &[f32], vector: bool) {
        let Some(p) = convert::light_model_param(pname) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let need = if p == LightModelParam::Ambient { 4 } else { 1 };
        if (!vector && need > 1) || v.len() < need {
            self.record_error(if vector {
                GL_INVALID_VALUE
            } else {
                GL_INVALID_ENUM
            });
            return;
        }
        let m = &mut self.lighting;
        match p {
            LightModelParam::Ambient => m.model_ambient = Vec4::from_slice(v),
            LightModelParam::LocalViewer => m.local_viewer = v[0] != 0.0,
            LightModelParam::TwoSide => m.two_side = v[0] != 0.0,
            LightModelParam::ColorControl => match convert::separate_specular(v[0] as GLenum) {
                Some(s) => m.separate_specular = s,
                None => {
                    self.record_error(GL_INVALID_ENUM);
                    return;
                }
            },
        }
        self.invalidate();
    }

    pub(crate) fn light_modelf(&mut self, pname: GLenum, param: GLfloat) {
        self.light_model_values(pname, &[param], false);
    }

    pub(crate) fn light_modeli(&mut self, pname: GLenum, param: GLint) {
        self.light_model_values(pname, &[param as f32], false);
    }

    pub(crate) fn light_modelfv(&mut self, pname: GLenum, params: &[GLfloat]) {
        self.light_model_values(pname, params, true);
    }

    pub(crate) fn light_modeliv(&mut self, pname: GLenum, params: &[GLint]) {
        let color = pname == GL_LIGHT_MODEL_AMBIENT;
        let v: Vec<f32> = params.iter().map(|&x| int_to_float(x, color)).collect();
        self.light_model_values(pname, &v, true);
    }

    fn material_values(&mut self, face: GLenum, pname: GLenum, v: &[f32], vector: bool) {
        let (Some(f), Some(p)) = (convert::face(face), convert::material_param(pname)) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if (!vector && p != MaterialParam::Shininess) || v.len() < p.count() {
            self.record_error(if vector {
                GL_INVALID_VALUE
            } else {
                GL_INVALID_ENUM
            });
            return;
        }
        if p == MaterialParam::Shininess && !(0.0..=128.0).contains(&v[0]) {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        // Vertices recorded so far in an open batch are lit with the materials they saw.
        self.light_recorded_vertices();
        for &i in faces(f) {
            set_material(&mut self.lighting.materials[i], p, v);
        }
        // Parameters COLOR_MATERIAL tracks follow the current colour at all times (section
        // 2.14.3), so a Material call does not change them while it is enabled.
        let c = self.current.color;
        self.lighting.track_color(c);
        // Allowed between glBegin and glEnd: the vertices recorded before were lit above with
        // the old materials, the next ones see the new.
        self.invalidate();
    }

    pub(crate) fn materialf(&mut self, face: GLenum, pname: GLenum, param: GLfloat) {
        self.material_values(face, pname, &[param], false);
    }

    pub(crate) fn materiali(&mut self, face: GLenum, pname: GLenum, param: GLint) {
        self.material_values(face, pname, &[param as f32], false);
    }

    pub(crate) fn materialfv(&mut self, face: GLenum, pname: GLenum, params: &[GLfloat]) {
        self.material_values(face, pname, params, true);
    }

    pub(crate) fn materialiv(&mut self, face: GLenum, pname: GLenum, params: &[GLint]) {
        let color = !matches!(
            convert::material_param(pname),
            Some(MaterialParam::Shininess | MaterialParam::ColorIndexes)
        );
        let v: Vec<f32> = params.iter().map(|&x| int_to_float(x, color)).collect();
        self.material_values(face, pname, &v, true);
    }

    pub(crate) fn color_material(&mut self, face: GLenum, mode: GLenum) {
        let (Some(f), Some(m)) = (convert::face(face), convert::color_material_mode(mode)) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.lighting.color_material_face = f;
        self.lighting.color_material_mode = m;
        let c = self.current.color;
        self.lighting.track_color(c);
        self.invalidate();
    }

    fn light_query(
        &mut self,
        light: GLenum,
        pname: GLenum,
        len: usize,
    ) -> Option<(Vec<f32>, bool)> {
        let (Some(i), Some(p)) = (convert::light_index(light), convert::light_param(pname)) else {
            self.record_error(GL_INVALID_ENUM);
            return None;
        };
        if len < p.count() {
            self.record_error(GL_INVALID_VALUE);
            return None;
        }
        let l = &self.lighting.lights[i];
        let v = match p {
            LightParam::Ambient => l.ambient.to_array().to_vec(),
            LightParam::Diffuse => l.diffuse.to_array().to_vec(),
            LightParam::Specular => l.specular.to_array().to_vec(),
            LightParam::Position => l.position.to_array().to_vec(),
            LightParam::SpotDirection => l.spot_direction.to_array().to_vec(),
            LightParam::SpotExponent => vec![l.spot_exponent],
            LightParam::SpotCutoff => vec![l.spot_cutoff],
            LightParam::ConstantAttenuation => vec![l.attenuation[0]],
            LightParam::LinearAttenuation => vec![l.attenuation[1]],
            LightParam::QuadraticAttenuation => vec![l.attenuation[2]],
        };
        Some((v, p.is_color()))
    }

    pub(crate) fn get_lightfv(&mut self, light: GLenum, pname: GLenum, params: &mut [GLfloat]) {
        if let Some((v, _)) = self.light_query(light, pname, params.len()) {
            params[..v.len()].copy_from_slice(&v);
        }
    }

    pub(crate) fn get_lightiv(&mut self, light: GLenum, pname: GLenum, params: &mut [GLint]) {
        if let Some((v, color)) = self.light_query(light, pname, params.len()) {
            for (o, x) in params.iter_mut().zip(v) {
                *o = float_to_int(x, color);
            }
        }
    }

    fn material_query(
        &mut self,
        face: GLenum,
        pname: GLenum,
        len: usize,
    ) -> Option<(Vec<f32>, bool)> {
        let f = match convert::face(face) {
            Some(Face::Front) => 0,
            Some(Face::Back) => 1,
            _ => {
                self.record_error(GL_INVALID_ENUM);
                return None;
            }
        };
        let p = match convert::material_param(pname) {
            Some(p) if p != MaterialParam::AmbientAndDiffuse => p,
            _ => {
                self.record_error(GL_INVALID_ENUM);
                return None;
            }
        };
        if len < p.count() {
            self.record_error(GL_INVALID_VALUE);
            return None;
        }
        let m = &self.lighting.materials[f];
        Some(match p {
            MaterialParam::Ambient => (m.ambient.to_array().to_vec(), true),
            MaterialParam::Diffuse => (m.diffuse.to_array().to_vec(), true),
            MaterialParam::Specular => (m.specular.to_array().to_vec(), true),
            MaterialParam::Emission => (m.emission.to_array().to_vec(), true),
            MaterialParam::Shininess => (vec![m.shininess], false),
            // No colour-index mode: the indexes keep their defaults (0, 1, 1).
            _ => (vec![0.0, 1.0, 1.0], false),
        })
    }

    pub(crate) fn get_materialfv(&mut self, face: GLenum, pname: GLenum, params: &mut [GLfloat]) {
        if let Some((v, _)) = self.material_query(face, pname, params.len()) {
            params[..v.len()].copy_from_slice(&v);
        }
    }

    pub(crate) fn get_materialiv(&mut self, face: GLenum, pname: GLenum, params: &mut [GLint]) {
        if let Some((v, color)) = self.material_query(face, pname, params.len()) {
            for (o, x) in params.iter_mut().zip(v) {
                *o = float_to_int(x, color);
            }
        }
    }
}

/// Integer query of a float: colours scale onto the integer range, others round.
fn float_to_int(x: f32, color: bool) -> i32 {
    if color {
        (x.clamp(-1.0, 1.0) as f64 * 2147483647.0) as i32
    } else if x.is_nan() {
        0
    } else {
        x.round().clamp(i32::MIN as f32, i32::MAX as f32) as i32
    }
}

//! ARB_sampler_objects' entry points: `glGenSamplers`, `glDeleteSamplers`, `glIsSampler`,
//! `glBindSampler`, `glSamplerParameter*` and `glGetSamplerParameter*` (section 3.9.2 and
//! 6.1.5 of the extension). The objects and the per-unit bindings live in
//! [`crate::texture::TextureState`]; a bound sampler reaches the draw through the unit's
//! texture snapshot.

use super::params::{ints_of, sampler_state_values, set_sampler_state};
use super::*;
use crate::common::limits::MAX_TEXTURE_UNITS;

/// How a `glSamplerParameter*` call gives its values.
#[derive(Clone, Copy)]
enum Given<'a> {
    /// `glSamplerParameter{i,f}[v]`: `vector` for the `v` forms.
    Plain(Values<'a>, bool),
    /// `glSamplerParameterIiv`/`Iuiv`: integers (their bits); a border colour is stored
    /// unchanged ("with an internal data type of integer").
    Integer(&'a [u32]),
}

impl Context {
    pub(crate) fn gen_samplers(&mut self, count: GLsizei, samplers: &mut [GLuint]) {
        if count < 0 || samplers.len() < count as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.textures.gen_samplers(&mut samplers[..count as usize]);
    }

    pub(crate) fn delete_samplers(&mut self, count: GLsizei, samplers: &[GLuint]) {
        if count < 0 || samplers.len() < count as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        for &name in &samplers[..count as usize] {
            self.textures.delete_sampler(name);
        }
        self.invalidate();
    }

    pub(crate) fn is_sampler(&mut self, sampler: GLuint) -> GLboolean {
        self.textures.is_sampler(sampler) as GLboolean
    }

    pub(crate) fn bind_sampler(&mut self, unit: GLuint, sampler: GLuint) {
        if unit as usize >= MAX_TEXTURE_UNITS {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        if !self.textures.bind_sampler(unit as usize, sampler) {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        self.invalidate();
    }

    fn sampler_parameter(&mut self, sampler: GLuint, pname: GLenum, given: Given) {
        let r = (|| -> Check<()> {
            let mut obj = self
                .textures
                .sampler_mut(sampler)
                .ok_or(GL_INVALID_OPERATION)?;
            let p = convert::tex_param(pname)
                .filter(|p| p.is_sampler_state())
                .ok_or(GL_INVALID_ENUM)?;
            let border = p == TexParam::BorderColor;
            let mut params = obj.params;
            match given {
                Given::Plain(_, false) if border => return Err(GL_INVALID_ENUM),
                Given::Plain(v, _) => {
                    if v.len() < if border { 4 } else { 1 } {
                        return Err(GL_INVALID_VALUE);
                    }
                    set_sampler_state(&mut params, p, v, false)?;
                }
                Given::Integer(v) if border => {
                    if v.len() < 4 {
                        return Err(GL_INVALID_VALUE);
                    }
                    params.border_color = [0, 1, 2, 3].map(|i| f32::from_bits(v[i]));
                }
                Given::Integer(v) => {
                    let ints: Vec<GLint> = v.iter().map(|&u| u as GLint).collect();
                    if ints.is_empty() {
                        return Err(GL_INVALID_VALUE);
                    }
                    set_sampler_state(&mut params, p, Values::I(&ints), false)?;
                }
            }
            obj.params = params;
            Ok(())
        })();
        match r {
            Ok(()) => self.invalidate(),
            Err(e) => self.record_error(e),
        }
    }

    pub(crate) fn sampler_parameteri(&mut self, sampler: GLuint, pname: GLenum, param: GLint) {
        self.sampler_parameter(sampler, pname, Given::Plain(Values::I(&[param]), false));
    }

    pub(crate) fn sampler_parameterf(&mut self, sampler: GLuint, pname: GLenum, param: GLfloat) {
        self.sampler_parameter(sampler, pname, Given::Plain(Values::F(&[param]), false));
    }

    pub(crate) fn sampler_parameteriv(&mut self, sampler: GLuint, pname: GLenum, param: &[GLint]) {
        self.sampler_parameter(sampler, pname, Given::Plain(Values::I(param), true));
    }

    pub(crate) fn sampler_parameterfv(
        &mut self,
        sampler: GLuint,
        pname: GLenum,
        param: &[GLfloat],
    ) {
        self.sampler_parameter(sampler, pname, Given::Plain(Values::F(param), true));
    }

    pub(crate) fn sampler_parameter_iiv(
        &mut self,
        sampler: GLuint,
        pname: GLenum,
        param: &[GLint],
    ) {
        let bits: Vec<u32> = param.iter().map(|&i| i as u32).collect();
        self.sampler_parameter(sampler, pname, Given::Integer(&bits));
    }

    pub(crate) fn sampler_parameter_iuiv(
        &mut self,
        sampler: GLuint,
        pname: GLenum,
        param: &[GLuint],
    ) {
        self.sampler_parameter(sampler, pname, Given::Integer(param));
    }

    /// The values of a sampler parameter and whether they are colour components; the
    /// errors of `glGetSamplerParameter*`.
    fn sampler_parameter_values(
        &self,
        sampler: GLuint,
        pname: GLenum,
    ) -> Check<(Vec<f64>, bool, [f32; 4])> {
        let obj = self.textures.sampler(sampler).ok_or(GL_INVALID_OPERATION)?;
        let p = convert::tex_param(pname).ok_or(GL_INVALID_ENUM)?;
        let (v, color) = sampler_state_values(&obj.params, p).ok_or(GL_INVALID_ENUM)?;
        Ok((v, color, obj.params.border_color))
    }

    pub(crate) fn get_sampler_parameteriv(
        &mut self,
        sampler: GLuint,
        pname: GLenum,
        params: &mut [GLint],
    ) {
        match self.sampler_parameter_values(sampler, pname) {
            Ok((v, color, _)) if params.len() >= v.len() => ints_of(&v, color, params),
            Ok(_) => self.record_error(GL_INVALID_VALUE),
            Err(e) => self.record_error(e),
        }
    }

    pub(crate) fn get_sampler_parameterfv(
        &mut self,
        sampler: GLuint,
        pname: GLenum,
        params: &mut [GLfloat],
    ) {
        match self.sampler_parameter_values(sampler, pname) {
            Ok((v, _, _)) if params.len() >= v.len() => {
                for (o, x) in params.iter_mut().zip(v) {
                    *o = x as f32;
                }
            }
            Ok(_) => self.record_error(GL_INVALID_VALUE),
            Err(e) => self.record_error(e),
        }
    }

    /// `glGetSamplerParameterIiv`/`Iuiv`: the border colour as the bits stored, the other
    /// parameters as `glGetSamplerParameteriv` gives them.
    fn get_sampler_parameter_integers(
        &mut self,
        sampler: GLuint,
        pname: GLenum,
        params: &mut [u32],
    ) {
        match self.sampler_parameter_values(sampler, pname) {
            Ok((v, _, _)) if params.len() < v.len() => self.record_error(GL_INVALID_VALUE),
            Ok((_, true, border)) => {
                for (o, c) in params.iter_mut().zip(border) {
                    *o = c.to_bits();
                }
            }
            Ok((v, false, _)) => {
                let mut ints = vec![0; v.len()];
                ints_of(&v, false, &mut ints);
                for (o, i) in params.iter_mut().zip(ints) {
                    *o = i as u32;
                }
            }
            Err(e) => self.record_error(e),
        }
    }

    pub(crate) fn get_sampler_parameter_iiv(
        &mut self,
        sampler: GLuint,
        pname: GLenum,
        params: &mut [GLint],
    ) {
        let mut bits: Vec<u32> = params.iter().map(|&i| i as u32).collect();
        self.get_sampler_parameter_integers(sampler, pname, &mut bits);
        for (o, b) in params.iter_mut().zip(bits) {
            *o = b as GLint;
        }
    }

    pub(crate) fn get_sampler_parameter_iuiv(
        &mut self,
        sampler: GLuint,
        pname: GLenum,
        params: &mut [GLuint],
    ) {
        self.get_sampler_parameter_integers(sampler, pname, params);
    }
}

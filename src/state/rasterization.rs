//! Rasterization controls (sections 3.3-3.5): point size and parameters, line width and
//! stipple, polygon mode, offset and stipple, edge flags.

use super::Context;
use crate::common::values::{Face, PointParam};
use crate::gl::convert;
use crate::gl::enums::*;

impl Context {
    pub(crate) fn point_size(&mut self, size: GLfloat) {
        if !(size > 0.0) {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.raster.point_size = size;
        self.invalidate();
    }

    pub(crate) fn line_width(&mut self, width: GLfloat) {
        if !(width > 0.0) {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.raster.line_width = width;
        self.invalidate();
    }

    pub(crate) fn line_stipple(&mut self, factor: GLint, pattern: GLushort) {
        // The factor is clamped to [1, 256] (section 3.4.2).
        self.raster.line_stipple_factor = factor.clamp(1, 256);
        self.raster.line_stipple_pattern = pattern;
        self.invalidate();
    }

    pub(crate) fn polygon_mode(&mut self, face: GLenum, mode: GLenum) {
        let (Some(f), Some(m)) = (convert::face(face), convert::polygon_mode(mode)) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        match f {
            Face::Front => self.raster.polygon_mode[0] = m,
            Face::Back => self.raster.polygon_mode[1] = m,
            Face::FrontAndBack => self.raster.polygon_mode = [m; 2],
        }
        self.invalidate();
    }

    pub(crate) fn polygon_offset(&mut self, factor: GLfloat, units: GLfloat) {
        self.raster.offset_factor = factor;
        self.raster.offset_units = units;
        self.invalidate();
    }

    /// `glPolygonStipple`: a 32x32 bitmap unpacked like `glBitmap` data (alignment, row length,
    /// skips, LSB first).
    pub(crate) fn polygon_stipple(&mut self, mask: &[GLubyte]) {
        let u = self.unpack;
        let row_bytes = if u.row_length > 0 {
            u.row_length as usize
        } else {
            32
        }
        .div_ceil(8);
        let align = u.alignment.max(1) as usize;
        let stride = row_bytes.div_ceil(align) * align;
        let mut rows = [0u32; 32];
        for (y, row) in rows.iter_mut().enumerate() {
            for x in 0..32usize {
                let bit = u.skip_pixels.max(0) as usize + x;
                let at = (u.skip_rows.max(0) as usize + y) * stride + bit / 8;
                let Some(&byte) = mask.get(at) else {
                    self.record_error(GL_INVALID_VALUE);
                    return;
                };
                let set = if u.lsb_first {
                    byte & (1 << (bit % 8)) != 0
                } else {
                    byte & (0x80 >> (bit % 8)) != 0
                };
                if set {
                    *row |= 1 << (31 - x);
                }
            }
        }
        self.raster.polygon_stipple_pattern = rows;
        self.invalidate();
    }

    /// `glGetPolygonStipple`: packed with the pack state's alignment, MSB first.
    pub(crate) fn get_polygon_stipple(&mut self, mask: &mut [GLubyte]) {
        let p = self.pack;
        let align = p.alignment.max(1) as usize;
        let stride = 4usize.div_ceil(align) * align;
        if mask.len() < stride * 31 + 4 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        for (y, row) in self.raster.polygon_stipple_pattern.iter().enumerate() {
            let b = row.to_be_bytes();
            for (k, byte) in b.iter().enumerate() {
                mask[y * stride + k] = if p.lsb_first {
                    byte.reverse_bits()
                } else {
                    *byte
                };
            }
        }
    }

    pub(crate) fn edge_flag(&mut self, flag: GLboolean) {
        self.current.edge_flag = flag != 0;
    }

    pub(crate) fn edge_flagv(&mut self, flag: &[GLboolean; 1]) {
        self.current.edge_flag = flag[0] != 0;
    }

    fn point_parameter_values(&mut self, pname: GLenum, v: &[f32], vector: bool) {
        let Some(p) = convert::point_param(pname) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let need = if p == PointParam::DistanceAttenuation {
            3
        } else {
            1
        };
        if (!vector && need > 1) || v.len() < need {
            self.record_error(if vector {
                GL_INVALID_VALUE
            } else {
                GL_INVALID_ENUM
            });
            return;
        }
        let r = &mut self.raster;
        match p {
            PointParam::SizeMin | PointParam::SizeMax | PointParam::FadeThresholdSize
                if !(v[0] >= 0.0) =>
            {
                self.record_error(GL_INVALID_VALUE);
                return;
            }
            PointParam::SizeMin => r.point_size_min = v[0],
            PointParam::SizeMax => r.point_size_max = v[0],
            PointParam::FadeThresholdSize => r.point_fade_threshold = v[0],
            PointParam::DistanceAttenuation => r.point_attenuation = [v[0], v[1], v[2]],
            PointParam::SpriteCoordOrigin => match v[0] as GLenum {
                GL_UPPER_LEFT if v[0].fract() == 0.0 => r.point_sprite_upper_left = true,
                GL_LOWER_LEFT if v[0].fract() == 0.0 => r.point_sprite_upper_left = false,
                _ => {
                    self.record_error(GL_INVALID_ENUM);
                    return;
                }
            },
        }
        self.invalidate();
    }

    pub(crate) fn point_parameterf(&mut self, pname: GLenum, param: GLfloat) {
        self.point_parameter_values(pname, &[param], false);
    }

    pub(crate) fn point_parameteri(&mut self, pname: GLenum, param: GLint) {
        self.point_parameter_values(pname, &[param as f32], false);
    }

    pub(crate) fn point_parameterfv(&mut self, pname: GLenum, params: &[GLfloat]) {
        self.point_parameter_values(pname, params, true);
    }

    pub(crate) fn point_parameteriv(&mut self, pname: GLenum, params: &[GLint]) {
        let v: Vec<f32> = params.iter().map(|&x| x as f32).collect();
        self.point_parameter_values(pname, &v, true);
    }
}

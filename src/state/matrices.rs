//! Matrix stacks, viewport, depth range and user clip planes (OpenGL 1.5 sections 2.11-2.12).
//! Matrices are kept in single precision like the hardware of the era (and Mesa); the double
//! entry points convert on entry.

use glam::{DMat4, DVec4, Mat4, Vec3};

use super::tables::{limits, Viewport};
use super::Context;
use crate::common::values::MatrixMode;
use crate::gl::convert;
use crate::gl::enums::*;

pub(crate) use crate::vertex::transform::inverse_or_identity;

impl Context {
    fn current_stack(&mut self) -> (&mut Vec<Mat4>, usize) {
        let unit = self.active_texture;
        let t = &mut self.transform;
        match t.mode {
            MatrixMode::ModelView => (&mut t.modelview, limits::MAX_MODELVIEW_STACK_DEPTH),
            MatrixMode::Projection => (&mut t.projection, limits::MAX_PROJECTION_STACK_DEPTH),
            MatrixMode::Texture => (&mut t.texture[unit], limits::MAX_TEXTURE_STACK_DEPTH),
        }
    }

    fn top(&mut self) -> &mut Mat4 {
        let (stack, _) = self.current_stack();
        // Stacks are never empty: pop refuses to remove the last entry.
        let last = stack.len() - 1;
        &mut stack[last]
    }

    fn set_top(&mut self, m: Mat4) {
        *self.top() = m;
        self.invalidate();
    }

    fn multiply_top(&mut self, m: Mat4) {
        let t = *self.top();
        self.set_top(t * m);
    }

    pub(crate) fn matrix_mode(&mut self, mode: GLenum) {
        let Some(m) = convert::matrix_mode(mode) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.transform.mode = m;
    }

    pub(crate) fn load_identity(&mut self) {
        self.set_top(Mat4::IDENTITY);
    }

    pub(crate) fn load_matrixf(&mut self, m: &[GLfloat; 16]) {
        self.set_top(Mat4::from_cols_array(m));
    }

    pub(crate) fn load_matrixd(&mut self, m: &[GLdouble; 16]) {
        self.set_top(DMat4::from_cols_array(m).as_mat4());
    }

    pub(crate) fn mult_matrixf(&mut self, m: &[GLfloat; 16]) {
        self.multiply_top(Mat4::from_cols_array(m));
    }

    pub(crate) fn mult_matrixd(&mut self, m: &[GLdouble; 16]) {
        self.multiply_top(DMat4::from_cols_array(m).as_mat4());
    }

    pub(crate) fn load_transpose_matrixf(&mut self, m: &[GLfloat; 16]) {
        self.set_top(Mat4::from_cols_array(m).transpose());
    }

    pub(crate) fn load_transpose_matrixd(&mut self, m: &[GLdouble; 16]) {
        self.set_top(DMat4::from_cols_array(m).transpose().as_mat4());
    }

    pub(crate) fn mult_transpose_matrixf(&mut self, m: &[GLfloat; 16]) {
        self.multiply_top(Mat4::from_cols_array(m).transpose());
    }

    pub(crate) fn mult_transpose_matrixd(&mut self, m: &[GLdouble; 16]) {
        self.multiply_top(DMat4::from_cols_array(m).transpose().as_mat4());
    }

    pub(crate) fn rotatef(&mut self, angle: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat) {
        let axis = Vec3::new(x, y, z);
        let len = axis.length();
        // A (near) zero axis leaves the matrix unchanged rather than producing NaNs.
        if !(len > 1.0e-4) || !angle.is_finite() {
            return;
        }
        self.multiply_top(Mat4::from_axis_angle(axis / len, angle.to_radians()));
    }

    pub(crate) fn rotated(&mut self, angle: GLdouble, x: GLdouble, y: GLdouble, z: GLdouble) {
        self.rotatef(angle as f32, x as f32, y as f32, z as f32);
    }

    pub(crate) fn translatef(&mut self, x: GLfloat, y: GLfloat, z: GLfloat) {
        self.multiply_top(Mat4::from_translation(Vec3::new(x, y, z)));
    }

    pub(crate) fn translated(&mut self, x: GLdouble, y: GLdouble, z: GLdouble) {
        self.translatef(x as f32, y as f32, z as f32);
    }

    pub(crate) fn scalef(&mut self, x: GLfloat, y: GLfloat, z: GLfloat) {
        self.multiply_top(Mat4::from_scale(Vec3::new(x, y, z)));
    }

    pub(crate) fn scaled(&mut self, x: GLdouble, y: GLdouble, z: GLdouble) {
        self.scalef(x as f32, y as f32, z as f32);
    }

    pub(crate) fn frustum(
        &mut self,
        l: GLdouble,
        r: GLdouble,
        b: GLdouble,
        t: GLdouble,
        n: f64,
        f: f64,
    ) {
        if n <= 0.0 || f <= 0.0 || l == r || b == t || n == f {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        // Equation 2.? of section 2.11.2, computed in double then rounded once.
        let m = DMat4::from_cols(
            DVec4::new(2.0 * n / (r - l), 0.0, 0.0, 0.0),
            DVec4::new(0.0, 2.0 * n / (t - b), 0.0, 0.0),
            DVec4::new(
                (r + l) / (r - l),
                (t + b) / (t - b),
                -(f + n) / (f - n),
                -1.0,
            ),
            DVec4::new(0.0, 0.0, -2.0 * f * n / (f - n), 0.0),
        );
        self.multiply_top(m.as_mat4());
    }

    pub(crate) fn ortho(
        &mut self,
        l: GLdouble,
        r: GLdouble,
        b: GLdouble,
        t: GLdouble,
        n: f64,
        f: f64,
    ) {
        if l == r || b == t || n == f {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let m = DMat4::from_cols(
            DVec4::new(2.0 / (r - l), 0.0, 0.0, 0.0),
            DVec4::new(0.0, 2.0 / (t - b), 0.0, 0.0),
            DVec4::new(0.0, 0.0, -2.0 / (f - n), 0.0),
            DVec4::new(
                -(r + l) / (r - l),
                -(t + b) / (t - b),
                -(f + n) / (f - n),
                1.0,
            ),
        );
        self.multiply_top(m.as_mat4());
    }

    pub(crate) fn push_matrix(&mut self) {
        let (stack, max) = self.current_stack();
        if stack.len() >= max {
            self.record_error(GL_STACK_OVERFLOW);
            return;
        }
        let top = stack[stack.len() - 1];
        stack.push(top);
    }

    pub(crate) fn pop_matrix(&mut self) {
        let (stack, _) = self.current_stack();
        if stack.len() <= 1 {
            self.record_error(GL_STACK_UNDERFLOW);
            return;
        }
        stack.pop();
        self.invalidate();
    }

    pub(crate) fn viewport(&mut self, x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
        self.drawable_check_requested = true;
        if width < 0 || height < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.transform.viewport = Viewport {
            x,
            y,
            width: width.min(limits::MAX_VIEWPORT_DIM),
            height: height.min(limits::MAX_VIEWPORT_DIM),
        };
        self.invalidate();
    }

    pub(crate) fn depth_range(&mut self, near: GLclampd, far: GLclampd) {
        self.transform.depth_range = [super::clamp01(near), super::clamp01(far)];
        self.invalidate();
    }

    pub(crate) fn clip_plane(&mut self, plane: GLenum, equation: &[GLdouble; 4]) {
        let i = plane.wrapping_sub(GL_CLIP_PLANE0) as usize;
        if i >= limits::MAX_CLIP_PLANES {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        // Section 2.12: (p1 p2 p3 p4) M^-1 with M the modelview matrix at the time of the call.
        let inv = inverse_or_identity(*self.transform.modelview.last().unwrap_or(&Mat4::IDENTITY))
            .as_dmat4();
        let p = DVec4::from_array(*equation);
        self.transform.clip_planes[i] = inv.transpose() * p;
        self.invalidate();
    }

    pub(crate) fn get_clip_plane(&mut self, plane: GLenum, equation: &mut [GLdouble; 4]) {
        let i = plane.wrapping_sub(GL_CLIP_PLANE0) as usize;
        if i >= limits::MAX_CLIP_PLANES {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        *equation = self.transform.clip_planes[i].to_array();
    }
}

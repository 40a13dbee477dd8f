//! Immediate mode (section 2.6): `glBegin`/`glEnd`, `glVertex*` and the current values
//! (`glColor*`, `glNormal*`, `glTexCoord*`), and `glRect*`.

use glam::{Vec3, Vec4};

use crate::api::convert::{self, PrimitiveMode};
use crate::api::enums::*;
use crate::state::tables::limits;
use crate::state::Context;

/// One vertex as specified: object position plus the current values at `glVertex` time.
#[derive(Clone, Copy, Debug)]
pub struct ImmVertex {
    pub position: Vec4,
    pub color: Vec4,
    pub secondary_color: Vec4,
    /// Back-face primary and secondary colours (two-sided lighting; else equal to the front).
    pub back_colors: [Vec4; 2],
    pub normal: Vec3,
    pub texcoords: [Vec4; limits::MAX_TEXTURE_UNITS],
    pub fog_coord: f32,
    pub edge_flag: bool,
}

/// The vertices recorded between `glBegin` and `glEnd`.
#[derive(Clone, Debug)]
pub struct ImmediateBatch {
    pub mode: PrimitiveMode,
    pub vertices: Vec<ImmVertex>,
}

// Table 2.6: conversion of integer colour and normal components to floating point.
pub(crate) fn norm_u8(c: u8) -> f32 {
    c as f32 / 255.0
}
pub(crate) fn norm_i8(c: i8) -> f32 {
    (2.0 * c as f32 + 1.0) / 255.0
}
pub(crate) fn norm_u16(c: u16) -> f32 {
    c as f32 / 65535.0
}
pub(crate) fn norm_i16(c: i16) -> f32 {
    (2.0 * c as f32 + 1.0) / 65535.0
}
pub(crate) fn norm_u32(c: u32) -> f32 {
    (c as f64 / 4294967295.0) as f32
}
pub(crate) fn norm_i32(c: i32) -> f32 {
    ((2.0 * c as f64 + 1.0) / 4294967295.0) as f32
}

impl Context {
    pub(crate) fn begin(&mut self, mode: GLenum) {
        let Some(mode) = convert::primitive_mode(mode) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.immediate = Some(ImmediateBatch {
            mode,
            vertices: Vec::new(),
        });
    }

    pub(crate) fn end(&mut self) {
        let Some(batch) = self.immediate.take() else {
            self.record_error(GL_INVALID_OPERATION);
            return;
        };
        self.draw_vertices(batch.mode, &batch.vertices);
        // Reuse the allocation for the next batch.
        let mut v = batch.vertices;
        v.clear();
        self.spare_vertices = v;
    }

    /// `glVertex`: outside `glBegin`/`glEnd` the specification leaves the effect undefined;
    /// tilegl ignores the call (as Mesa does).
    pub(crate) fn vertex4(&mut self, position: Vec4) {
        if self.immediate.is_none() {
            return;
        }
        let lit = self.lighting.enabled.then(|| {
            let setup = self.light_setup();
            setup.light(position, self.current.normal, &self.lighting.materials)
        });
        let c = &self.current;
        let (color, secondary_color, back_colors) = match lit {
            Some(l) => (l.front[0], l.front[1], l.back),
            None => (c.color, c.secondary_color, [c.color, c.secondary_color]),
        };
        let v = ImmVertex {
            position,
            color,
            secondary_color,
            back_colors,
            normal: c.normal,
            texcoords: c.texcoords,
            fog_coord: c.fog_coord,
            edge_flag: c.edge_flag,
        };
        if let Some(batch) = &mut self.immediate {
            if batch.vertices.capacity() == 0 {
                batch.vertices = std::mem::take(&mut self.spare_vertices);
            }
            batch.vertices.push(v);
        }
    }

    pub(crate) fn set_color(&mut self, c: Vec4) {
        self.current.color = c;
        if self.lighting.color_material {
            self.lighting.track_color(c);
        }
    }

    /// The lighting inputs for the current state (built on first use after a change).
    fn light_setup(&mut self) -> std::sync::Arc<super::lighting::LightSetup> {
        if let Some(s) = &self.light_setup {
            return s.clone();
        }
        let mv = *self
            .transform
            .modelview
            .last()
            .unwrap_or(&glam::Mat4::IDENTITY);
        let s = std::sync::Arc::new(super::lighting::LightSetup::new(
            &self.lighting,
            mv,
            self.transform.normalize,
            self.transform.rescale_normal,
        ));
        self.light_setup = Some(s.clone());
        s
    }

    /// `glRect`: a polygon with vertices (x1,y1), (x2,y1), (x2,y2), (x1,y2) at z = 0.
    fn rect(&mut self, x1: f32, y1: f32, x2: f32, y2: f32) {
        self.begin(GL_POLYGON);
        self.vertex4(Vec4::new(x1, y1, 0.0, 1.0));
        self.vertex4(Vec4::new(x2, y1, 0.0, 1.0));
        self.vertex4(Vec4::new(x2, y2, 0.0, 1.0));
        self.vertex4(Vec4::new(x1, y2, 0.0, 1.0));
        self.end();
    }
    pub(crate) fn vertex_2d(&mut self, x: GLdouble, y: GLdouble) {
        self.vertex4(Vec4::new(x as f32, y as f32, 0.0, 1.0));
    }
    pub(crate) fn vertex_2dv(&mut self, v: &[GLdouble; 2]) {
        self.vertex4(Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0));
    }
    pub(crate) fn vertex_2f(&mut self, x: GLfloat, y: GLfloat) {
        self.vertex4(Vec4::new(x as f32, y as f32, 0.0, 1.0));
    }
    pub(crate) fn vertex_2fv(&mut self, v: &[GLfloat; 2]) {
        self.vertex4(Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0));
    }
    pub(crate) fn vertex_2i(&mut self, x: GLint, y: GLint) {
        self.vertex4(Vec4::new(x as f32, y as f32, 0.0, 1.0));
    }
    pub(crate) fn vertex_2iv(&mut self, v: &[GLint; 2]) {
        self.vertex4(Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0));
    }
    pub(crate) fn vertex_2s(&mut self, x: GLshort, y: GLshort) {
        self.vertex4(Vec4::new(x as f32, y as f32, 0.0, 1.0));
    }
    pub(crate) fn vertex_2sv(&mut self, v: &[GLshort; 2]) {
        self.vertex4(Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0));
    }
    pub(crate) fn vertex_3d(&mut self, x: GLdouble, y: GLdouble, z: GLdouble) {
        self.vertex4(Vec4::new(x as f32, y as f32, z as f32, 1.0));
    }
    pub(crate) fn vertex_3dv(&mut self, v: &[GLdouble; 3]) {
        self.vertex4(Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0));
    }
    pub(crate) fn vertex_3f(&mut self, x: GLfloat, y: GLfloat, z: GLfloat) {
        self.vertex4(Vec4::new(x as f32, y as f32, z as f32, 1.0));
    }
    pub(crate) fn vertex_3fv(&mut self, v: &[GLfloat; 3]) {
        self.vertex4(Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0));
    }
    pub(crate) fn vertex_3i(&mut self, x: GLint, y: GLint, z: GLint) {
        self.vertex4(Vec4::new(x as f32, y as f32, z as f32, 1.0));
    }
    pub(crate) fn vertex_3iv(&mut self, v: &[GLint; 3]) {
        self.vertex4(Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0));
    }
    pub(crate) fn vertex_3s(&mut self, x: GLshort, y: GLshort, z: GLshort) {
        self.vertex4(Vec4::new(x as f32, y as f32, z as f32, 1.0));
    }
    pub(crate) fn vertex_3sv(&mut self, v: &[GLshort; 3]) {
        self.vertex4(Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0));
    }
    pub(crate) fn vertex_4d(&mut self, x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) {
        self.vertex4(Vec4::new(x as f32, y as f32, z as f32, w as f32));
    }
    pub(crate) fn vertex_4dv(&mut self, v: &[GLdouble; 4]) {
        self.vertex4(Vec4::new(
            v[0] as f32,
            v[1] as f32,
            v[2] as f32,
            v[3] as f32,
        ));
    }
    pub(crate) fn vertex_4f(&mut self, x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) {
        self.vertex4(Vec4::new(x as f32, y as f32, z as f32, w as f32));
    }
    pub(crate) fn vertex_4fv(&mut self, v: &[GLfloat; 4]) {
        self.vertex4(Vec4::new(
            v[0] as f32,
            v[1] as f32,
            v[2] as f32,
            v[3] as f32,
        ));
    }
    pub(crate) fn vertex_4i(&mut self, x: GLint, y: GLint, z: GLint, w: GLint) {
        self.vertex4(Vec4::new(x as f32, y as f32, z as f32, w as f32));
    }
    pub(crate) fn vertex_4iv(&mut self, v: &[GLint; 4]) {
        self.vertex4(Vec4::new(
            v[0] as f32,
            v[1] as f32,
            v[2] as f32,
            v[3] as f32,
        ));
    }
    pub(crate) fn vertex_4s(&mut self, x: GLshort, y: GLshort, z: GLshort, w: GLshort) {
        self.vertex4(Vec4::new(x as f32, y as f32, z as f32, w as f32));
    }
    pub(crate) fn vertex_4sv(&mut self, v: &[GLshort; 4]) {
        self.vertex4(Vec4::new(
            v[0] as f32,
            v[1] as f32,
            v[2] as f32,
            v[3] as f32,
        ));
    }
    pub(crate) fn color_3b(&mut self, red: GLbyte, green: GLbyte, blue: GLbyte) {
        self.set_color(Vec4::new(norm_i8(red), norm_i8(green), norm_i8(blue), 1.0));
    }
    pub(crate) fn color_3bv(&mut self, v: &[GLbyte; 3]) {
        self.set_color(Vec4::new(norm_i8(v[0]), norm_i8(v[1]), norm_i8(v[2]), 1.0));
    }
    pub(crate) fn color_3d(&mut self, red: GLdouble, green: GLdouble, blue: GLdouble) {
        self.set_color(Vec4::new(
            (|v: f64| v as f32)(red),
            (|v: f64| v as f32)(green),
            (|v: f64| v as f32)(blue),
            1.0,
        ));
    }
    pub(crate) fn color_3dv(&mut self, v: &[GLdouble; 3]) {
        self.set_color(Vec4::new(
            (|v: f64| v as f32)(v[0]),
            (|v: f64| v as f32)(v[1]),
            (|v: f64| v as f32)(v[2]),
            1.0,
        ));
    }
    pub(crate) fn color_3f(&mut self, red: GLfloat, green: GLfloat, blue: GLfloat) {
        self.set_color(Vec4::new(
            (|v: f32| v)(red),
            (|v: f32| v)(green),
            (|v: f32| v)(blue),
            1.0,
        ));
    }
    pub(crate) fn color_3fv(&mut self, v: &[GLfloat; 3]) {
        self.set_color(Vec4::new(
            (|v: f32| v)(v[0]),
            (|v: f32| v)(v[1]),
            (|v: f32| v)(v[2]),
            1.0,
        ));
    }
    pub(crate) fn color_3i(&mut self, red: GLint, green: GLint, blue: GLint) {
        self.set_color(Vec4::new(
            norm_i32(red),
            norm_i32(green),
            norm_i32(blue),
            1.0,
        ));
    }
    pub(crate) fn color_3iv(&mut self, v: &[GLint; 3]) {
        self.set_color(Vec4::new(
            norm_i32(v[0]),
            norm_i32(v[1]),
            norm_i32(v[2]),
            1.0,
        ));
    }
    pub(crate) fn color_3s(&mut self, red: GLshort, green: GLshort, blue: GLshort) {
        self.set_color(Vec4::new(
            norm_i16(red),
            norm_i16(green),
            norm_i16(blue),
            1.0,
        ));
    }
    pub(crate) fn color_3sv(&mut self, v: &[GLshort; 3]) {
        self.set_color(Vec4::new(
            norm_i16(v[0]),
            norm_i16(v[1]),
            norm_i16(v[2]),
            1.0,
        ));
    }
    pub(crate) fn color_3ub(&mut self, red: GLubyte, green: GLubyte, blue: GLubyte) {
        self.set_color(Vec4::new(norm_u8(red), norm_u8(green), norm_u8(blue), 1.0));
    }
    pub(crate) fn color_3ubv(&mut self, v: &[GLubyte; 3]) {
        self.set_color(Vec4::new(norm_u8(v[0]), norm_u8(v[1]), norm_u8(v[2]), 1.0));
    }
    pub(crate) fn color_3ui(&mut self, red: GLuint, green: GLuint, blue: GLuint) {
        self.set_color(Vec4::new(
            norm_u32(red),
            norm_u32(green),
            norm_u32(blue),
            1.0,
        ));
    }
    pub(crate) fn color_3uiv(&mut self, v: &[GLuint; 3]) {
        self.set_color(Vec4::new(
            norm_u32(v[0]),
            norm_u32(v[1]),
            norm_u32(v[2]),
            1.0,
        ));
    }
    pub(crate) fn color_3us(&mut self, red: GLushort, green: GLushort, blue: GLushort) {
        self.set_color(Vec4::new(
            norm_u16(red),
            norm_u16(green),
            norm_u16(blue),
            1.0,
        ));
    }
    pub(crate) fn color_3usv(&mut self, v: &[GLushort; 3]) {
        self.set_color(Vec4::new(
            norm_u16(v[0]),
            norm_u16(v[1]),
            norm_u16(v[2]),
            1.0,
        ));
    }
    pub(crate) fn color_4b(&mut self, red: GLbyte, green: GLbyte, blue: GLbyte, alpha: GLbyte) {
        self.set_color(Vec4::new(
            norm_i8(red),
            norm_i8(green),
            norm_i8(blue),
            norm_i8(alpha),
        ));
    }
    pub(crate) fn color_4bv(&mut self, v: &[GLbyte; 4]) {
        self.set_color(Vec4::new(
            norm_i8(v[0]),
            norm_i8(v[1]),
            norm_i8(v[2]),
            norm_i8(v[3]),
        ));
    }
    pub(crate) fn color_4d(
        &mut self,
        red: GLdouble,
        green: GLdouble,
        blue: GLdouble,
        alpha: GLdouble,
    ) {
        self.set_color(Vec4::new(
            (|v: f64| v as f32)(red),
            (|v: f64| v as f32)(green),
            (|v: f64| v as f32)(blue),
            (|v: f64| v as f32)(alpha),
        ));
    }
    pub(crate) fn color_4dv(&mut self, v: &[GLdouble; 4]) {
        self.set_color(Vec4::new(
            (|v: f64| v as f32)(v[0]),
            (|v: f64| v as f32)(v[1]),
            (|v: f64| v as f32)(v[2]),
            (|v: f64| v as f32)(v[3]),
        ));
    }
    pub(crate) fn color_4f(&mut self, red: GLfloat, green: GLfloat, blue: GLfloat, alpha: GLfloat) {
        self.set_color(Vec4::new(
            (|v: f32| v)(red),
            (|v: f32| v)(green),
            (|v: f32| v)(blue),
            (|v: f32| v)(alpha),
        ));
    }
    pub(crate) fn color_4fv(&mut self, v: &[GLfloat; 4]) {
        self.set_color(Vec4::new(
            (|v: f32| v)(v[0]),
            (|v: f32| v)(v[1]),
            (|v: f32| v)(v[2]),
            (|v: f32| v)(v[3]),
        ));
    }
    pub(crate) fn color_4i(&mut self, red: GLint, green: GLint, blue: GLint, alpha: GLint) {
        self.set_color(Vec4::new(
            norm_i32(red),
            norm_i32(green),
            norm_i32(blue),
            norm_i32(alpha),
        ));
    }
    pub(crate) fn color_4iv(&mut self, v: &[GLint; 4]) {
        self.set_color(Vec4::new(
            norm_i32(v[0]),
            norm_i32(v[1]),
            norm_i32(v[2]),
            norm_i32(v[3]),
        ));
    }
    pub(crate) fn color_4s(&mut self, red: GLshort, green: GLshort, blue: GLshort, alpha: GLshort) {
        self.set_color(Vec4::new(
            norm_i16(red),
            norm_i16(green),
            norm_i16(blue),
            norm_i16(alpha),
        ));
    }
    pub(crate) fn color_4sv(&mut self, v: &[GLshort; 4]) {
        self.set_color(Vec4::new(
            norm_i16(v[0]),
            norm_i16(v[1]),
            norm_i16(v[2]),
            norm_i16(v[3]),
        ));
    }
    pub(crate) fn color_4ub(
        &mut self,
        red: GLubyte,
        green: GLubyte,
        blue: GLubyte,
        alpha: GLubyte,
    ) {
        self.set_color(Vec4::new(
            norm_u8(red),
            norm_u8(green),
            norm_u8(blue),
            norm_u8(alpha),
        ));
    }
    pub(crate) fn color_4ubv(&mut self, v: &[GLubyte; 4]) {
        self.set_color(Vec4::new(
            norm_u8(v[0]),
            norm_u8(v[1]),
            norm_u8(v[2]),
            norm_u8(v[3]),
        ));
    }
    pub(crate) fn color_4ui(&mut self, red: GLuint, green: GLuint, blue: GLuint, alpha: GLuint) {
        self.set_color(Vec4::new(
            norm_u32(red),
            norm_u32(green),
            norm_u32(blue),
            norm_u32(alpha),
        ));
    }
    pub(crate) fn color_4uiv(&mut self, v: &[GLuint; 4]) {
        self.set_color(Vec4::new(
            norm_u32(v[0]),
            norm_u32(v[1]),
            norm_u32(v[2]),
            norm_u32(v[3]),
        ));
    }
    pub(crate) fn color_4us(
        &mut self,
        red: GLushort,
        green: GLushort,
        blue: GLushort,
        alpha: GLushort,
    ) {
        self.set_color(Vec4::new(
            norm_u16(red),
            norm_u16(green),
            norm_u16(blue),
            norm_u16(alpha),
        ));
    }
    pub(crate) fn color_4usv(&mut self, v: &[GLushort; 4]) {
        self.set_color(Vec4::new(
            norm_u16(v[0]),
            norm_u16(v[1]),
            norm_u16(v[2]),
            norm_u16(v[3]),
        ));
    }
    pub(crate) fn normal_3b(&mut self, nx: GLbyte, ny: GLbyte, nz: GLbyte) {
        self.current.normal = Vec3::new(norm_i8(nx), norm_i8(ny), norm_i8(nz));
    }
    pub(crate) fn normal_3bv(&mut self, v: &[GLbyte; 3]) {
        self.current.normal = Vec3::new(norm_i8(v[0]), norm_i8(v[1]), norm_i8(v[2]));
    }
    pub(crate) fn normal_3d(&mut self, nx: GLdouble, ny: GLdouble, nz: GLdouble) {
        self.current.normal = Vec3::new(
            (|v: f64| v as f32)(nx),
            (|v: f64| v as f32)(ny),
            (|v: f64| v as f32)(nz),
        );
    }
    pub(crate) fn normal_3dv(&mut self, v: &[GLdouble; 3]) {
        self.current.normal = Vec3::new(
            (|v: f64| v as f32)(v[0]),
            (|v: f64| v as f32)(v[1]),
            (|v: f64| v as f32)(v[2]),
        );
    }
    pub(crate) fn normal_3f(&mut self, nx: GLfloat, ny: GLfloat, nz: GLfloat) {
        self.current.normal = Vec3::new((|v: f32| v)(nx), (|v: f32| v)(ny), (|v: f32| v)(nz));
    }
    pub(crate) fn normal_3fv(&mut self, v: &[GLfloat; 3]) {
        self.current.normal = Vec3::new((|v: f32| v)(v[0]), (|v: f32| v)(v[1]), (|v: f32| v)(v[2]));
    }
    pub(crate) fn normal_3i(&mut self, nx: GLint, ny: GLint, nz: GLint) {
        self.current.normal = Vec3::new(norm_i32(nx), norm_i32(ny), norm_i32(nz));
    }
    pub(crate) fn normal_3iv(&mut self, v: &[GLint; 3]) {
        self.current.normal = Vec3::new(norm_i32(v[0]), norm_i32(v[1]), norm_i32(v[2]));
    }
    pub(crate) fn normal_3s(&mut self, nx: GLshort, ny: GLshort, nz: GLshort) {
        self.current.normal = Vec3::new(norm_i16(nx), norm_i16(ny), norm_i16(nz));
    }
    pub(crate) fn normal_3sv(&mut self, v: &[GLshort; 3]) {
        self.current.normal = Vec3::new(norm_i16(v[0]), norm_i16(v[1]), norm_i16(v[2]));
    }
    pub(crate) fn tex_coord_1d(&mut self, s: GLdouble) {
        self.current.texcoords[0] = Vec4::new(s as f32, 0.0, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_1dv(&mut self, v: &[GLdouble; 1]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, 0.0, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_1f(&mut self, s: GLfloat) {
        self.current.texcoords[0] = Vec4::new(s as f32, 0.0, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_1fv(&mut self, v: &[GLfloat; 1]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, 0.0, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_1i(&mut self, s: GLint) {
        self.current.texcoords[0] = Vec4::new(s as f32, 0.0, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_1iv(&mut self, v: &[GLint; 1]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, 0.0, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_1s(&mut self, s: GLshort) {
        self.current.texcoords[0] = Vec4::new(s as f32, 0.0, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_1sv(&mut self, v: &[GLshort; 1]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, 0.0, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_2d(&mut self, s: GLdouble, t: GLdouble) {
        self.current.texcoords[0] = Vec4::new(s as f32, t as f32, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_2dv(&mut self, v: &[GLdouble; 2]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_2f(&mut self, s: GLfloat, t: GLfloat) {
        self.current.texcoords[0] = Vec4::new(s as f32, t as f32, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_2fv(&mut self, v: &[GLfloat; 2]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_2i(&mut self, s: GLint, t: GLint) {
        self.current.texcoords[0] = Vec4::new(s as f32, t as f32, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_2iv(&mut self, v: &[GLint; 2]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_2s(&mut self, s: GLshort, t: GLshort) {
        self.current.texcoords[0] = Vec4::new(s as f32, t as f32, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_2sv(&mut self, v: &[GLshort; 2]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0);
    }
    pub(crate) fn tex_coord_3d(&mut self, s: GLdouble, t: GLdouble, r: GLdouble) {
        self.current.texcoords[0] = Vec4::new(s as f32, t as f32, r as f32, 1.0);
    }
    pub(crate) fn tex_coord_3dv(&mut self, v: &[GLdouble; 3]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0);
    }
    pub(crate) fn tex_coord_3f(&mut self, s: GLfloat, t: GLfloat, r: GLfloat) {
        self.current.texcoords[0] = Vec4::new(s as f32, t as f32, r as f32, 1.0);
    }
    pub(crate) fn tex_coord_3fv(&mut self, v: &[GLfloat; 3]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0);
    }
    pub(crate) fn tex_coord_3i(&mut self, s: GLint, t: GLint, r: GLint) {
        self.current.texcoords[0] = Vec4::new(s as f32, t as f32, r as f32, 1.0);
    }
    pub(crate) fn tex_coord_3iv(&mut self, v: &[GLint; 3]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0);
    }
    pub(crate) fn tex_coord_3s(&mut self, s: GLshort, t: GLshort, r: GLshort) {
        self.current.texcoords[0] = Vec4::new(s as f32, t as f32, r as f32, 1.0);
    }
    pub(crate) fn tex_coord_3sv(&mut self, v: &[GLshort; 3]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0);
    }
    pub(crate) fn tex_coord_4d(&mut self, s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble) {
        self.current.texcoords[0] = Vec4::new(s as f32, t as f32, r as f32, q as f32);
    }
    pub(crate) fn tex_coord_4dv(&mut self, v: &[GLdouble; 4]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32);
    }
    pub(crate) fn tex_coord_4f(&mut self, s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat) {
        self.current.texcoords[0] = Vec4::new(s as f32, t as f32, r as f32, q as f32);
    }
    pub(crate) fn tex_coord_4fv(&mut self, v: &[GLfloat; 4]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32);
    }
    pub(crate) fn tex_coord_4i(&mut self, s: GLint, t: GLint, r: GLint, q: GLint) {
        self.current.texcoords[0] = Vec4::new(s as f32, t as f32, r as f32, q as f32);
    }
    pub(crate) fn tex_coord_4iv(&mut self, v: &[GLint; 4]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32);
    }
    pub(crate) fn tex_coord_4s(&mut self, s: GLshort, t: GLshort, r: GLshort, q: GLshort) {
        self.current.texcoords[0] = Vec4::new(s as f32, t as f32, r as f32, q as f32);
    }
    pub(crate) fn tex_coord_4sv(&mut self, v: &[GLshort; 4]) {
        self.current.texcoords[0] = Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32);
    }
    pub(crate) fn rectd(&mut self, x1: GLdouble, y1: GLdouble, x2: GLdouble, y2: GLdouble) {
        self.rect(x1 as f32, y1 as f32, x2 as f32, y2 as f32);
    }
    pub(crate) fn rectdv(&mut self, v1: &[GLdouble; 2], v2: &[GLdouble; 2]) {
        self.rect(v1[0] as f32, v1[1] as f32, v2[0] as f32, v2[1] as f32);
    }
    pub(crate) fn rectf(&mut self, x1: GLfloat, y1: GLfloat, x2: GLfloat, y2: GLfloat) {
        self.rect(x1 as f32, y1 as f32, x2 as f32, y2 as f32);
    }
    pub(crate) fn rectfv(&mut self, v1: &[GLfloat; 2], v2: &[GLfloat; 2]) {
        self.rect(v1[0] as f32, v1[1] as f32, v2[0] as f32, v2[1] as f32);
    }
    pub(crate) fn recti(&mut self, x1: GLint, y1: GLint, x2: GLint, y2: GLint) {
        self.rect(x1 as f32, y1 as f32, x2 as f32, y2 as f32);
    }
    pub(crate) fn rectiv(&mut self, v1: &[GLint; 2], v2: &[GLint; 2]) {
        self.rect(v1[0] as f32, v1[1] as f32, v2[0] as f32, v2[1] as f32);
    }
    pub(crate) fn rects(&mut self, x1: GLshort, y1: GLshort, x2: GLshort, y2: GLshort) {
        self.rect(x1 as f32, y1 as f32, x2 as f32, y2 as f32);
    }
    pub(crate) fn rectsv(&mut self, v1: &[GLshort; 2], v2: &[GLshort; 2]) {
        self.rect(v1[0] as f32, v1[1] as f32, v2[0] as f32, v2[1] as f32);
    }
    pub(crate) fn secondary_color_3b(&mut self, red: GLbyte, green: GLbyte, blue: GLbyte) {
        self.current.secondary_color = Vec4::new(norm_i8(red), norm_i8(green), norm_i8(blue), 0.0);
    }
    pub(crate) fn secondary_color_3bv(&mut self, v: &[GLbyte; 3]) {
        self.current.secondary_color = Vec4::new(norm_i8(v[0]), norm_i8(v[1]), norm_i8(v[2]), 0.0);
    }
    pub(crate) fn secondary_color_3d(&mut self, red: GLdouble, green: GLdouble, blue: GLdouble) {
        self.current.secondary_color = Vec4::new(
            (|v: f64| v as f32)(red),
            (|v: f64| v as f32)(green),
            (|v: f64| v as f32)(blue),
            0.0,
        );
    }
    pub(crate) fn secondary_color_3dv(&mut self, v: &[GLdouble; 3]) {
        self.current.secondary_color = Vec4::new(
            (|v: f64| v as f32)(v[0]),
            (|v: f64| v as f32)(v[1]),
            (|v: f64| v as f32)(v[2]),
            0.0,
        );
    }
    pub(crate) fn secondary_color_3f(&mut self, red: GLfloat, green: GLfloat, blue: GLfloat) {
        self.current.secondary_color = Vec4::new(
            (|v: f32| v)(red),
            (|v: f32| v)(green),
            (|v: f32| v)(blue),
            0.0,
        );
    }
    pub(crate) fn secondary_color_3fv(&mut self, v: &[GLfloat; 3]) {
        self.current.secondary_color = Vec4::new(
            (|v: f32| v)(v[0]),
            (|v: f32| v)(v[1]),
            (|v: f32| v)(v[2]),
            0.0,
        );
    }
    pub(crate) fn secondary_color_3i(&mut self, red: GLint, green: GLint, blue: GLint) {
        self.current.secondary_color =
            Vec4::new(norm_i32(red), norm_i32(green), norm_i32(blue), 0.0);
    }
    pub(crate) fn secondary_color_3iv(&mut self, v: &[GLint; 3]) {
        self.current.secondary_color =
            Vec4::new(norm_i32(v[0]), norm_i32(v[1]), norm_i32(v[2]), 0.0);
    }
    pub(crate) fn secondary_color_3s(&mut self, red: GLshort, green: GLshort, blue: GLshort) {
        self.current.secondary_color =
            Vec4::new(norm_i16(red), norm_i16(green), norm_i16(blue), 0.0);
    }
    pub(crate) fn secondary_color_3sv(&mut self, v: &[GLshort; 3]) {
        self.current.secondary_color =
            Vec4::new(norm_i16(v[0]), norm_i16(v[1]), norm_i16(v[2]), 0.0);
    }
    pub(crate) fn secondary_color_3ub(&mut self, red: GLubyte, green: GLubyte, blue: GLubyte) {
        self.current.secondary_color = Vec4::new(norm_u8(red), norm_u8(green), norm_u8(blue), 0.0);
    }
    pub(crate) fn secondary_color_3ubv(&mut self, v: &[GLubyte; 3]) {
        self.current.secondary_color = Vec4::new(norm_u8(v[0]), norm_u8(v[1]), norm_u8(v[2]), 0.0);
    }
    pub(crate) fn secondary_color_3ui(&mut self, red: GLuint, green: GLuint, blue: GLuint) {
        self.current.secondary_color =
            Vec4::new(norm_u32(red), norm_u32(green), norm_u32(blue), 0.0);
    }
    pub(crate) fn secondary_color_3uiv(&mut self, v: &[GLuint; 3]) {
        self.current.secondary_color =
            Vec4::new(norm_u32(v[0]), norm_u32(v[1]), norm_u32(v[2]), 0.0);
    }
    pub(crate) fn secondary_color_3us(&mut self, red: GLushort, green: GLushort, blue: GLushort) {
        self.current.secondary_color =
            Vec4::new(norm_u16(red), norm_u16(green), norm_u16(blue), 0.0);
    }
    pub(crate) fn secondary_color_3usv(&mut self, v: &[GLushort; 3]) {
        self.current.secondary_color =
            Vec4::new(norm_u16(v[0]), norm_u16(v[1]), norm_u16(v[2]), 0.0);
    }
}

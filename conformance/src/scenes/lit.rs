//! The foundation scenes of lighting and the per-fragment operations (blending, alpha and
//! stencil tests, logic op, fog), listed in `BASE_SCENES`.

use super::*;
use tilegl::Gl;

/// A lit sphere of `stacks` x `slices` quads (triangle strips), unit radius, with normals.
pub(crate) fn sphere(gl: &mut dyn Gl, stacks: usize, slices: usize) {
    use std::f32::consts::PI;
    for i in 0..stacks {
        let (t0, t1) = (
            PI * i as f32 / stacks as f32,
            PI * (i + 1) as f32 / stacks as f32,
        );
        gl.begin(GL_TRIANGLE_STRIP);
        for j in 0..=slices {
            let p = 2.0 * PI * j as f32 / slices as f32;
            for t in [t1, t0] {
                let (x, y, z) = (t.sin() * p.cos(), t.cos(), t.sin() * p.sin());
                gl.normal_3f(x, y, z);
                gl.vertex_3f(x, y, z);
            }
        }
        gl.end();
    }
}

pub(super) fn lit_setup(gl: &mut dyn Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.6, 0.6, -0.6, 0.6, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    clear(gl);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.8, 0.6, 0.3, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.6, 0.6, 0.6, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0);
}

pub(super) fn lit_directional(gl: &mut dyn Gl) {
    lit_setup(gl);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[1.0, 1.0, 1.0, 0.0]);
    gl.translatef(0.0, 0.0, -3.0);
    sphere(gl, 12, 16);
}

pub(super) fn lit_positional_attenuated(gl: &mut dyn Gl) {
    lit_setup(gl);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[-1.0, 1.0, -1.0, 1.0]);
    gl.lightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.5);
    gl.lightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.3);
    gl.lightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.1);
    gl.light_modeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    gl.translatef(0.0, 0.0, -3.0);
    sphere(gl, 12, 16);
}

pub(super) fn lit_spot(gl: &mut dyn Gl) {
    lit_setup(gl);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.0, 0.0, 0.0, 1.0]);
    gl.lightfv(GL_LIGHT0, GL_SPOT_DIRECTION, &[0.1, 0.1, -1.0]);
    gl.lightf(GL_LIGHT0, GL_SPOT_CUTOFF, 12.0);
    gl.lightf(GL_LIGHT0, GL_SPOT_EXPONENT, 10.0);
    gl.light_modelfv(GL_LIGHT_MODEL_AMBIENT, &[0.1, 0.1, 0.1, 1.0]);
    gl.translatef(0.0, 0.0, -3.0);
    sphere(gl, 16, 24);
}

pub(super) fn lit_two_sided_separate_specular(gl: &mut dyn Gl) {
    lit_setup(gl);
    gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    gl.light_modeli(
        GL_LIGHT_MODEL_COLOR_CONTROL,
        GL_SEPARATE_SPECULAR_COLOR as i32,
    );
    gl.materialfv(GL_BACK, GL_DIFFUSE, &[0.2, 0.3, 0.9, 1.0]);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.0, 0.5, 1.0, 0.0]);
    gl.enable(GL_LIGHT1);
    gl.lightfv(GL_LIGHT1, GL_DIFFUSE, &[0.0, 0.8, 0.2, 1.0]);
    gl.lightfv(GL_LIGHT1, GL_POSITION, &[0.0, 0.0, -1.0, 0.0]);
    gl.translatef(0.0, 0.0, -3.5);
    gl.rotatef(25.0, 1.0, 0.0, 0.0);
    // The far half of an open cylinder: its inside (back faces) faces the viewer, and the
    // front faces of its rim show at the top.
    gl.begin(GL_QUAD_STRIP);
    for j in 0..=16 {
        let a = std::f32::consts::PI * j as f32 / 16.0;
        gl.normal_3f(a.cos(), 0.0, -a.sin());
        gl.vertex_3f(a.cos(), -0.6, -a.sin());
        gl.vertex_3f(a.cos(), 0.6, -a.sin());
    }
    gl.end();
}

pub(super) fn lit_color_material(gl: &mut dyn Gl) {
    lit_setup(gl);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[1.0, 0.5, 1.0, 0.0]);
    gl.enable(GL_COLOR_MATERIAL);
    gl.color_material(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    gl.enable(GL_NORMALIZE);
    gl.translatef(0.0, 0.0, -3.0);
    gl.scalef(1.0, 0.7, 1.3);
    gl.color_3f(0.2, 0.8, 0.4);
    sphere(gl, 10, 14);
}

pub(super) fn blend_over(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for k in 0..6 {
        let c = PALETTE[k % PALETTE.len()];
        gl.color_4f(c[0], c[1], c[2], 0.25 + 0.12 * k as f32);
        let o = 4.0 + 7.0 * k as f32;
        gl.rectf(o, o * 0.8, o + 22.0, o * 0.8 + 20.0);
    }
    gl.blend_func_separate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
    gl.blend_equation(GL_FUNC_REVERSE_SUBTRACT);
    gl.color_4f(0.3, 0.1, 0.2, 0.5);
    gl.rectf(30.0, 2.0, 62.0, 30.0);
}

pub(super) fn alpha_test_and_stencil(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.clear_stencil(0);
    gl.clear(GL_STENCIL_BUFFER_BIT);
    // Write 1 into the stencil where alpha passes (a smooth alpha ramp, cut at 0.5).
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_ALWAYS, 1, 0xFF);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
    gl.enable(GL_ALPHA_TEST);
    gl.alpha_func(GL_GREATER, 0.5);
    gl.begin(GL_QUADS);
    for (x, y) in [(4.0f32, 4.0f32), (60.0, 4.0), (60.0, 60.0), (4.0, 60.0)] {
        gl.color_4f(0.9, 0.9, 0.2, x / 64.0);
        gl.vertex_2f(x, y);
    }
    gl.end();
    gl.disable(GL_ALPHA_TEST);
    // Draw only where the stencil is 1, incrementing with wrap.
    gl.stencil_func(GL_EQUAL, 1, 0xFF);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_INCR_WRAP);
    gl.color_3f(0.1, 0.3, 0.9);
    gl.rectf(0.0, 20.0, 64.0, 44.0);
}

pub(super) fn logic_xor(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_COLOR_LOGIC_OP);
    gl.logic_op(GL_XOR);
    gl.color_3f(1.0, 0.5, 0.25);
    gl.rectf(8.0, 8.0, 40.0, 40.0);
    gl.color_3f(0.25, 1.0, 0.75);
    gl.rectf(24.0, 24.0, 56.0, 56.0);
}

/// The sixteen logic ops (section 4.1.10: applied bit by bit to the stored fixed-point values
/// of the fragment's colour and the buffer's) in 4-pixel strips over a destination of exact
/// bytes (`glDrawPixels`, no logic op): the lower half from a `REPLACE`d RGBA texture of exact
/// bytes sampled `NEAREST` at texel centres, the upper half a flat colour of exact bytes. No
/// value is rounded on the way, so every implementation must give the same bytes.
pub(super) fn logic_ops(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let dst: Vec<u8> = (0..64 * 64)
        .flat_map(|i: u32| {
            let (x, y) = (i % 64, i / 64);
            [
                (4 * x) as u8,
                (4 * y + 2) as u8,
                (x * y + 3 * x) as u8,
                255 - x as u8,
            ]
        })
        .collect();
    gl.raster_pos_2i(0, 0);
    gl.draw_pixels(64, 64, GL_RGBA, GL_UNSIGNED_BYTE, Some(&dst));
    let texels: Vec<u8> = (0..16 * 16)
        .flat_map(|i: u32| {
            let (s, t) = (i % 16, i / 16);
            [
                (s * 37 + t) as u8,
                (t * 53 + 7) as u8,
                (s * t * 7) as u8,
                (200 + s) as u8,
            ]
        })
        .collect();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        16,
        16,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_COLOR_LOGIC_OP);
    for k in 0..16u32 {
        gl.logic_op(GL_CLEAR + k);
        let (x0, x1) = (4.0 * k as f32, 4.0 * k as f32 + 4.0);
        // One texel per pixel: texel centres at the pixel centres.
        gl.enable(GL_TEXTURE_2D);
        gl.begin(GL_QUADS);
        for (x, y) in [(x0, 0.0), (x1, 0.0), (x1, 32.0), (x0, 32.0)] {
            gl.tex_coord_2f(x / 16.0, (y + 3.0) / 16.0);
            gl.vertex_2f(x, y);
        }
        gl.end();
        gl.disable(GL_TEXTURE_2D);
        gl.color_4ub((17 * k) as u8, (255 - 13 * k) as u8, 0x5A, (9 * k) as u8);
        gl.rectf(x0, 32.0, x1, 64.0);
    }
    gl.disable(GL_COLOR_LOGIC_OP);
}

// Fog.

pub(super) fn fog_scene(gl: &mut dyn Gl, mode: GLenum, coord: bool) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 30.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    clear(gl);
    gl.enable(GL_FOG);
    gl.fogi(GL_FOG_MODE, mode as i32);
    gl.fogf(GL_FOG_DENSITY, 0.15);
    gl.fogf(GL_FOG_START, 2.0);
    gl.fogf(GL_FOG_END, 20.0);
    gl.fogfv(GL_FOG_COLOR, &[0.6, 0.7, 0.8, 1.0]);
    if coord {
        gl.fogi(GL_FOG_COORD_SRC, GL_FOG_COORD as i32);
    }
    // A ground plane and two upright quads at different depths.
    gl.begin(GL_TRIANGLES);
    let quad = |gl: &mut dyn Gl, p: [[f32; 3]; 4], fc: [f32; 4], c: [f32; 3]| {
        gl.color_3f(c[0], c[1], c[2]);
        for k in [0usize, 1, 2, 0, 2, 3] {
            gl.fog_coordf(fc[k]);
            gl.vertex_3f(p[k][0], p[k][1], p[k][2]);
        }
    };
    quad(
        gl,
        [
            [-6.0, -1.0, -1.5],
            [6.0, -1.0, -1.5],
            [6.0, -1.0, -28.0],
            [-6.0, -1.0, -28.0],
        ],
        [0.0, 3.0, 30.0, 12.0],
        [0.2, 0.6, 0.2],
    );
    quad(
        gl,
        [
            [-2.0, -1.0, -4.0],
            [-0.5, -1.0, -4.0],
            [-0.5, 1.0, -4.0],
            [-2.0, 1.0, -4.0],
        ],
        [1.0, 1.0, 8.0, 8.0],
        [0.9, 0.2, 0.1],
    );
    quad(
        gl,
        [
            [0.5, -1.0, -12.0],
            [3.0, -1.0, -12.0],
            [3.0, 2.0, -12.0],
            [0.5, 2.0, -12.0],
        ],
        [20.0, 2.0, 2.0, 20.0],
        [0.9, 0.9, 0.1],
    );
    gl.end();
}

pub(super) fn fog_linear(gl: &mut dyn Gl) {
    fog_scene(gl, GL_LINEAR, false);
}

pub(super) fn fog_exp(gl: &mut dyn Gl) {
    fog_scene(gl, GL_EXP, false);
}

pub(super) fn fog_exp2(gl: &mut dyn Gl) {
    fog_scene(gl, GL_EXP2, false);
}

pub(super) fn fog_coord_linear(gl: &mut dyn Gl) {
    fog_scene(gl, GL_LINEAR, true);
}

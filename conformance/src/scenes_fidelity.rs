//! Differential scenes for the fidelity classes found replaying real programs (issue 24):
//! antialiased wide lines, all user clip planes at once, implementation limits (point sizes
//! and line widths of 1000, textures 16384 texels wide, float textures), fog on lit, textured
//! geometry receding into the distance, and anisotropic filtering towards the horizon.

use crate::compare::Scene;
use crate::scenes::{pal, scene};
use tilegl::enums::*;
use tilegl::Gl;

/// Fidelity scenes, in report order.
pub const FIDELITY_SCENES: &[Scene] = &[
    scene("smooth_lines_width_1", smooth_lines_width_1),
    scene("smooth_lines_width_2_5", smooth_lines_width_2_5),
    scene("smooth_lines_width_4", smooth_lines_width_4),
    scene("smooth_lines_width_7", smooth_lines_width_7),
    scene(
        "smooth_lines_receding_width_1",
        smooth_lines_receding_width_1,
    ),
    scene(
        "smooth_lines_receding_width_2_5",
        smooth_lines_receding_width_2_5,
    ),
    scene(
        "smooth_lines_receding_width_4",
        smooth_lines_receding_width_4,
    ),
    scene(
        "smooth_lines_receding_width_7",
        smooth_lines_receding_width_7,
    ),
];

/// Pixel space over black (the smooth-line captures blend over black).
fn black_pixel_space(gl: &mut dyn Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 64.0, 0.0, 64.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/// Antialiased lines of one width, blended over black with `GL_NICEST`, radiating from the
/// centre at twelve angles (both majors, both directions, the diagonals and shallow slopes),
/// plus short segments and segments on pixel centres and edges.
fn smooth_lines(gl: &mut dyn Gl, width: f32) {
    black_pixel_space(gl);
    gl.enable(GL_LINE_SMOOTH);
    gl.hint(GL_LINE_SMOOTH_HINT, GL_NICEST);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.line_width(width);
    gl.begin(GL_LINES);
    for k in 0..12 {
        let a = k as f32 * std::f32::consts::PI / 6.0 + 0.13;
        pal(gl, k);
        gl.vertex_2f(32.3 + 7.0 * a.cos(), 32.2 + 7.0 * a.sin());
        pal(gl, k + 3);
        gl.vertex_2f(32.3 + 28.0 * a.cos(), 32.2 + 28.0 * a.sin());
    }
    gl.end();
    // Axis-aligned segments on pixel centres and on pixel edges, and a short one.
    gl.begin(GL_LINES);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.vertex_2f(3.5, 3.5);
    gl.vertex_2f(20.5, 3.5);
    gl.vertex_2f(60.0, 4.0);
    gl.vertex_2f(60.0, 20.0);
    gl.color_3f(1.0, 1.0, 0.0);
    gl.vertex_2f(44.2, 60.3);
    gl.vertex_2f(45.1, 60.9);
    gl.end();
}

fn smooth_lines_width_1(gl: &mut dyn Gl) {
    smooth_lines(gl, 1.0);
}

fn smooth_lines_width_2_5(gl: &mut dyn Gl) {
    smooth_lines(gl, 2.5);
}

fn smooth_lines_width_4(gl: &mut dyn Gl) {
    smooth_lines(gl, 4.0);
}

fn smooth_lines_width_7(gl: &mut dyn Gl) {
    smooth_lines(gl, 7.0);
}

/// Antialiased lines of one width in perspective: six depth-tested loops of twelve segments
/// each receding from the viewer (1/w differs between the ends of every segment), plus one
/// long segment from near the eye to far away.
fn smooth_lines_receding(gl: &mut dyn Gl, width: f32) {
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.5, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -6.0);
    gl.rotatef(30.0, 1.0, 0.4, 0.1);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LINE_SMOOTH);
    gl.hint(GL_LINE_SMOOTH_HINT, GL_NICEST);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.line_width(width);
    for j in 0..6 {
        gl.begin(GL_LINE_LOOP);
        for k in 0..12 {
            pal(gl, k + j);
            let a = k as f32 * std::f32::consts::FRAC_PI_6;
            gl.vertex_3f(2.5 * a.cos(), 2.5 * a.sin(), -2.0 + 0.8 * j as f32);
        }
        gl.end();
    }
    gl.load_identity();
    gl.color_3f(1.0, 1.0, 1.0);
    gl.begin(GL_LINES);
    gl.vertex_3f(-1.3, -0.2, -1.6);
    gl.vertex_3f(5.0, 0.3, -12.0);
    gl.end();
}

fn smooth_lines_receding_width_1(gl: &mut dyn Gl) {
    smooth_lines_receding(gl, 1.0);
}

fn smooth_lines_receding_width_2_5(gl: &mut dyn Gl) {
    smooth_lines_receding(gl, 2.5);
}

fn smooth_lines_receding_width_4(gl: &mut dyn Gl) {
    smooth_lines_receding(gl, 4.0);
}

fn smooth_lines_receding_width_7(gl: &mut dyn Gl) {
    smooth_lines_receding(gl, 7.0);
}

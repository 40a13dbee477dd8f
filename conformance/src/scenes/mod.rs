//! The differential scenes: the foundation features (primitive modes, clipping, culling,
//! depth, masks, shading, matrices, viewport, clears), each as a small `fn(&mut dyn Gl)`.
//! Shared by `tests/differential.rs` and the `calibrate` binary (llvmpipe vs softpipe).
//!
//! Vertex positions avoid exact pixel-centre and edge ties where the tie is not the point of the
//! case, so the scenes measure features rather than tie-breaking conventions.

use crate::tolerance::{Tolerance, DIFFERENTIAL};
use tilegl::enums::*;
use tilegl::Gl;

use crate::compare::Scene;

mod lit;
pub(crate) use lit::sphere;
use lit::*;

const T: u8 = 1;
const F: u8 = 0;

/// Pixel-space projection: ortho(0, w, 0, h, -1, 1), identity modelview, cleared colour and
/// depth (dark grey background).
pub(crate) fn pixel_space(gl: &mut dyn Gl, w: f64, h: f64) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, w, 0.0, h, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    clear(gl);
}

pub(crate) fn clear(gl: &mut dyn Gl) {
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.clear_depth(1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/// A palette of distinct saturated colours.
pub(crate) const PALETTE: [[f32; 3]; 8] = [
    [1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, 0.0, 1.0],
    [1.0, 1.0, 0.0],
    [0.0, 1.0, 1.0],
    [1.0, 0.0, 1.0],
    [1.0, 0.5, 0.0],
    [0.5, 0.25, 1.0],
];

pub(crate) fn pal(gl: &mut dyn Gl, i: usize) {
    let c = PALETTE[i % PALETTE.len()];
    gl.color_3f(c[0], c[1], c[2]);
}

/// A colour that is an affine function of the (pixel-space) position. GL leaves open how a
/// quad or polygon is split into triangles (section 3.5.1 only asks for a convex combination of
/// the vertex values), so a polygon with arbitrary vertex colours shades differently on
/// conformant implementations (llvmpipe and softpipe split quads along different diagonals).
/// With affine colours every split gives the same picture.
fn affine(gl: &mut dyn Gl, x: f32, y: f32, blue: f32) {
    gl.color_3f(x / 64.0, y / 64.0, (blue + 0.5 * (x + y) / 128.0).min(1.0));
}

/// A vertex of a pixel-space polygon with an [`affine`] colour.
fn avertex(gl: &mut dyn Gl, x: f32, y: f32, blue: f32) {
    affine(gl, x, y, blue);
    gl.vertex_2f(x, y);
}

// ---------------------------------------------------------------- primitive modes

fn points(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.begin(GL_POINTS);
    for j in 0..10 {
        for i in 0..10 {
            pal(gl, i + j);
            // Fractions stay within 0.3..0.7 of a pixel: no rounding-rule ties.
            gl.vertex_2f(3.3 + 6.0 * i as f32, 2.4 + 6.03 * j as f32);
        }
    }
    gl.end();
}

fn line_fan_vertices() -> Vec<(f32, f32)> {
    // Lines of many slopes from a centre, endpoints off the pixel centres.
    (0..16)
        .map(|k| {
            let a = k as f32 * std::f32::consts::PI / 8.0 + 0.13;
            (32.3 + 28.0 * a.cos(), 31.8 + 28.0 * a.sin())
        })
        .collect()
}

fn lines(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.begin(GL_LINES);
    for (k, (x, y)) in line_fan_vertices().into_iter().enumerate() {
        pal(gl, k);
        gl.vertex_2f(32.3 + 0.2 * (x - 32.3), 31.8 + 0.2 * (y - 31.8));
        pal(gl, k + 3);
        gl.vertex_2f(x, y);
    }
    gl.end();
}

fn line_strip(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.begin(GL_LINE_STRIP);
    for k in 0..12 {
        pal(gl, k);
        let x = 4.3 + 5.1 * k as f32;
        let y = if k % 2 == 0 {
            8.7
        } else {
            55.2 - k as f32 * 2.0
        };
        gl.vertex_2f(x, y);
    }
    gl.end();
}

fn line_loop(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.begin(GL_LINE_LOOP);
    for k in 0..7 {
        pal(gl, k);
        let a = k as f32 * 2.0 * std::f32::consts::PI / 7.0 + 0.2;
        gl.vertex_2f(32.2 + 25.3 * a.cos(), 31.7 + 25.3 * a.sin());
    }
    gl.end();
}

/// Short lines whose two endpoints both lie inside a pixel's diamond (|dx| + |dy| < 1/2 from
/// the pixel centre). Diamond-exit (section 3.4.1): the start pixel is drawn (the line exits
/// its diamond), the end pixel is not. Endpoints are a large share of the pixels here.
fn line_endpoints(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.begin(GL_LINES);
    for j in 0..8 {
        for i in 0..8 {
            pal(gl, i + j);
            let (x, y) = (2.6 + 8.0 * i as f32, 2.4 + 8.0 * j as f32);
            // Directions in all octants, 2 to 5 pixels long.
            let a = (i * 8 + j) as f32 * 0.83;
            let len = 2.0 + ((i + 2 * j) % 4) as f32;
            let (dx, dy) = ((len * a.cos()).round(), (len * a.sin()).round());
            gl.vertex_2f(x, y);
            gl.vertex_2f(x + dx + 0.1, y + dy - 0.1);
        }
    }
    gl.end();
}

fn triangles(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.begin(GL_TRIANGLES);
    pal(gl, 0);
    gl.vertex_2f(2.3, 3.1);
    pal(gl, 1);
    gl.vertex_2f(40.7, 6.4);
    pal(gl, 2);
    gl.vertex_2f(12.2, 45.9);
    pal(gl, 3);
    gl.vertex_2f(61.1, 20.3);
    pal(gl, 4);
    gl.vertex_2f(58.6, 61.4);
    pal(gl, 5);
    gl.vertex_2f(25.4, 50.2);
    gl.end();
}

fn triangle_strip(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.begin(GL_TRIANGLE_STRIP);
    for k in 0..10 {
        pal(gl, k);
        let x = 3.2 + 6.3 * k as f32;
        let y = if k % 2 == 0 {
            10.4 + k as f32
        } else {
            50.6 - k as f32
        };
        gl.vertex_2f(x, y);
    }
    gl.end();
}

fn triangle_fan(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.begin(GL_TRIANGLE_FAN);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.vertex_2f(31.6, 32.3);
    for k in 0..8 {
        pal(gl, k);
        let a = k as f32 * std::f32::consts::PI / 4.0 + 0.1;
        gl.vertex_2f(31.6 + 27.7 * a.cos(), 32.3 + 27.7 * a.sin());
    }
    gl.end();
}

fn quads(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.begin(GL_QUADS);
    for q in 0..4 {
        let ox = 2.4 + 31.0 * (q % 2) as f32;
        let oy = 2.7 + 31.0 * (q / 2) as f32;
        let b = q as f32 * 0.25;
        avertex(gl, ox, oy, b);
        avertex(gl, ox + 27.3, oy + 2.2, b);
        avertex(gl, ox + 25.1, oy + 26.6, b);
        avertex(gl, ox + 1.3, oy + 24.2, b);
    }
    gl.end();
}

fn quad_strip(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    quad_strip_body(gl, false);
}

/// `flat`: palette colours (the provoking vertex decides); otherwise affine colours.
fn quad_strip_body(gl: &mut dyn Gl, flat: bool) {
    gl.begin(GL_QUAD_STRIP);
    for k in 0..6 {
        let (x0, y0) = (4.2 + 11.1 * k as f32, 6.3 + (k % 2) as f32 * 3.1);
        let (x1, y1) = (3.7 + 11.3 * k as f32, 57.4 - (k % 3) as f32 * 4.2);
        if flat {
            pal(gl, 2 * k);
            gl.vertex_2f(x0, y0);
            pal(gl, 2 * k + 1);
            gl.vertex_2f(x1, y1);
        } else {
            avertex(gl, x0, y0, 0.2);
            avertex(gl, x1, y1, 0.2);
        }
    }
    gl.end();
}

fn polygon(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.begin(GL_POLYGON);
    for k in 0..6 {
        let a = k as f32 * std::f32::consts::PI / 3.0 + 0.3;
        avertex(gl, 32.4 + 29.1 * a.cos(), 31.3 + 26.2 * a.sin(), 0.4);
    }
    gl.end();
}

fn rect(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.color_3f(1.0, 0.0, 0.0);
    gl.rectf(3.3, 4.6, 30.2, 28.7);
    gl.color_3f(0.0, 1.0, 0.0);
    gl.recti(34, 2, 60, 20);
    gl.color_3f(0.0, 0.0, 1.0);
    // Reversed corners: the rectangle is still drawn (winding does not matter without culling).
    gl.rectd(58.4, 61.2, 20.6, 36.3);
    gl.color_3f(1.0, 1.0, 0.0);
    gl.rectfv(&[5.5, 40.2], &[15.5, 60.7]);
}

// ---------------------------------------------------------------- clipping

fn perspective(gl: &mut dyn Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    clear(gl);
}

fn near_plane_clip(gl: &mut dyn Gl) {
    perspective(gl);
    gl.enable(GL_DEPTH_TEST);
    // A large triangle reaching from behind the eye (z = +2) to far away: crosses z = -w.
    gl.begin(GL_TRIANGLES);
    gl.color_3f(1.0, 0.0, 0.0);
    gl.vertex_3f(-0.6, -0.8, 2.0);
    gl.color_3f(0.0, 1.0, 0.0);
    gl.vertex_3f(1.3, -0.5, -6.0);
    gl.color_3f(0.0, 0.0, 1.0);
    gl.vertex_3f(-1.1, 1.4, -4.0);
    // A floor quad running under the camera out to the far plane.
    gl.end();
    // Colours affine in object space (see `affine`).
    gl.begin(GL_QUADS);
    for (x, z) in [(-3.0f32, 3.0f32), (3.0, 3.0), (3.0, -12.0), (-3.0, -12.0)] {
        gl.color_3f((x + 3.0) / 6.0, (z + 12.0) / 15.0, 1.0 - (x + 3.0) / 12.0);
        gl.vertex_3f(x, -1.0, z);
    }
    gl.end();
}

fn negative_w(gl: &mut dyn Gl) {
    clear(gl);
    // Identity matrices: clip coordinates are the vertices themselves. One vertex has w < 0,
    // so the visible part is the piece of the triangle in front of w = 0 only.
    gl.begin(GL_TRIANGLES);
    gl.color_3f(1.0, 0.0, 0.0);
    gl.vertex_4f(-0.8, -0.7, 0.0, 1.0);
    gl.color_3f(0.0, 1.0, 0.0);
    gl.vertex_4f(0.9, -0.6, 0.0, 1.0);
    gl.color_3f(0.0, 0.0, 1.0);
    gl.vertex_4f(0.3, 0.5, 0.0, -0.5);
    gl.end();
    // A triangle entirely at w < 0 whose projection would cover the centre: must not appear.
    gl.begin(GL_TRIANGLES);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.vertex_4f(0.5, 0.5, 0.0, -1.0);
    gl.vertex_4f(-0.5, 0.5, 0.0, -1.0);
    gl.vertex_4f(0.0, -0.5, 0.0, -1.0);
    gl.end();
    // A triangle with w scaled per vertex (all positive): projective positions and
    // perspective-correct colours.
    gl.begin(GL_TRIANGLES);
    gl.color_3f(1.0, 1.0, 0.0);
    gl.vertex_4f(-1.8, 0.6, 0.0, 2.0);
    gl.color_3f(0.0, 1.0, 1.0);
    gl.vertex_4f(-0.1, 0.55, 0.0, 0.5);
    gl.color_3f(1.0, 0.0, 1.0);
    gl.vertex_4f(-2.7, 2.7, 0.0, 3.0);
    gl.end();
}

fn clip_planes(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    // Planes are given in object coordinates and transformed by the modelview current at the
    // glClipPlane call: set one with a translation in effect.
    gl.push_matrix();
    gl.translatef(2.0, 0.0, 0.0);
    gl.clip_plane(GL_CLIP_PLANE0, &[1.0, 0.3, 0.0, -12.0]); // keep x' + 0.3y >= 12
    gl.pop_matrix();
    gl.clip_plane(GL_CLIP_PLANE1, &[-0.4, -1.0, 0.0, 55.0]); // keep 0.4x + y <= 55
    gl.enable(GL_CLIP_PLANE0);
    gl.enable(GL_CLIP_PLANE1);
    gl.begin(GL_TRIANGLE_FAN);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.vertex_2f(31.6, 32.3);
    for k in 0..9 {
        pal(gl, k);
        let a = k as f32 * std::f32::consts::PI / 4.0 + 0.1;
        gl.vertex_2f(31.6 + 30.2 * a.cos(), 32.3 + 30.2 * a.sin());
    }
    gl.end();
    // Lines are clipped too.
    gl.begin(GL_LINES);
    gl.color_3f(1.0, 0.5, 0.0);
    gl.vertex_2f(1.3, 60.4);
    gl.vertex_2f(62.6, 1.7);
    gl.end();
    // A third plane, enabled then disabled again: no effect.
    gl.clip_plane(GL_CLIP_PLANE2, &[0.0, 1.0, 0.0, -1000.0]);
    gl.enable(GL_CLIP_PLANE2);
    gl.disable(GL_CLIP_PLANE2);
    gl.color_3f(0.2, 0.9, 0.3);
    gl.rectf(40.3, 2.2, 62.4, 14.6);
}

// ---------------------------------------------------------------- culling

/// Two counter-clockwise and two clockwise triangles (window space).
fn culling_pair(gl: &mut dyn Gl) {
    gl.begin(GL_TRIANGLES);
    // CCW
    gl.color_3f(1.0, 0.0, 0.0);
    gl.vertex_2f(3.3, 3.6);
    gl.vertex_2f(29.4, 5.2);
    gl.vertex_2f(15.1, 29.3);
    // CW
    gl.color_3f(0.0, 1.0, 0.0);
    gl.vertex_2f(35.3, 3.6);
    gl.vertex_2f(47.1, 29.3);
    gl.vertex_2f(61.4, 5.2);
    gl.end();
    // A CCW quad and a CW polygon.
    gl.begin(GL_QUADS);
    gl.color_3f(0.0, 0.0, 1.0);
    gl.vertex_2f(3.2, 35.3);
    gl.vertex_2f(29.6, 34.7);
    gl.vertex_2f(28.3, 60.1);
    gl.vertex_2f(4.4, 61.2);
    gl.end();
    gl.begin(GL_POLYGON);
    gl.color_3f(1.0, 1.0, 0.0);
    gl.vertex_2f(35.2, 35.3);
    gl.vertex_2f(36.4, 61.2);
    gl.vertex_2f(60.3, 60.1);
    gl.vertex_2f(61.6, 34.7);
    gl.end();
}

fn cull_back(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_CULL_FACE);
    culling_pair(gl);
}

fn cull_front(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_CULL_FACE);
    gl.cull_face(GL_FRONT);
    culling_pair(gl);
}

fn cull_front_and_back(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_CULL_FACE);
    gl.cull_face(GL_FRONT_AND_BACK);
    culling_pair(gl);
    // Lines and points are not culled.
    gl.begin(GL_LINES);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.vertex_2f(2.3, 32.4);
    gl.vertex_2f(61.7, 31.6);
    gl.end();
}

fn front_face_cw(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.front_face(GL_CW);
    gl.enable(GL_CULL_FACE);
    gl.cull_face(GL_BACK);
    culling_pair(gl);
}

fn cull_mirrored(gl: &mut dyn Gl) {
    // A negative scale flips the window-space winding.
    pixel_space(gl, 64.0, 64.0);
    gl.translatef(64.0, 0.0, 0.0);
    gl.scalef(-1.0, 1.0, 1.0);
    gl.enable(GL_CULL_FACE);
    culling_pair(gl);
}

// ---------------------------------------------------------------- depth

/// Triangle A (red) tilting one way, B (green) the other, then A again (blue) with the same
/// vertices, all under `func`. The first draw of A uses GL_LESS against the cleared depth.
fn depth_scene(gl: &mut dyn Gl, func: GLenum) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_DEPTH_TEST);
    let tri_a = |gl: &mut dyn Gl| {
        gl.begin(GL_TRIANGLES);
        gl.vertex_3f(2.3, 4.1, -0.8);
        gl.vertex_3f(61.2, 9.7, 0.7);
        gl.vertex_3f(30.6, 60.8, 0.1);
        gl.end();
    };
    gl.depth_func(GL_LESS);
    gl.color_3f(1.0, 0.0, 0.0);
    tri_a(gl);
    gl.depth_func(func);
    gl.begin(GL_TRIANGLES);
    gl.color_3f(0.0, 1.0, 0.0);
    gl.vertex_3f(5.4, 50.2, 0.6);
    gl.vertex_3f(58.3, 55.1, -0.7);
    gl.vertex_3f(33.1, 2.6, 0.05);
    gl.end();
    gl.color_3f(0.0, 0.0, 1.0);
    tri_a(gl);
}

fn depth_never(gl: &mut dyn Gl) {
    depth_scene(gl, GL_NEVER);
}
fn depth_less(gl: &mut dyn Gl) {
    depth_scene(gl, GL_LESS);
}
fn depth_equal(gl: &mut dyn Gl) {
    depth_scene(gl, GL_EQUAL);
}
fn depth_lequal(gl: &mut dyn Gl) {
    depth_scene(gl, GL_LEQUAL);
}
fn depth_greater(gl: &mut dyn Gl) {
    depth_scene(gl, GL_GREATER);
}
fn depth_notequal(gl: &mut dyn Gl) {
    depth_scene(gl, GL_NOTEQUAL);
}
fn depth_gequal(gl: &mut dyn Gl) {
    depth_scene(gl, GL_GEQUAL);
}
fn depth_always(gl: &mut dyn Gl) {
    depth_scene(gl, GL_ALWAYS);
}

fn depth_mask(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_DEPTH_TEST);
    // Near rectangle drawn with depth writes off: a far one drawn later still covers it.
    gl.depth_mask(F);
    gl.color_3f(1.0, 0.0, 0.0);
    gl.begin(GL_QUADS);
    gl.vertex_3f(4.2, 4.3, -0.5);
    gl.vertex_3f(40.1, 4.3, -0.5);
    gl.vertex_3f(40.1, 40.6, -0.5);
    gl.vertex_3f(4.2, 40.6, -0.5);
    gl.end();
    gl.depth_mask(T);
    gl.color_3f(0.0, 1.0, 0.0);
    gl.begin(GL_QUADS);
    gl.vertex_3f(20.3, 20.2, 0.5);
    gl.vertex_3f(60.4, 20.2, 0.5);
    gl.vertex_3f(60.4, 60.7, 0.5);
    gl.vertex_3f(20.3, 60.7, 0.5);
    gl.end();
    // Depth clear is also masked by glDepthMask.
    gl.depth_mask(F);
    gl.clear(GL_DEPTH_BUFFER_BIT);
    gl.depth_mask(T);
    gl.color_3f(0.0, 0.0, 1.0);
    gl.begin(GL_TRIANGLES);
    gl.vertex_3f(2.6, 62.1, 0.7);
    gl.vertex_3f(62.3, 1.4, 0.7);
    gl.vertex_3f(62.1, 62.4, 0.7);
    gl.end();
}

// ---------------------------------------------------------------- masks, scissor

fn scissor(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(10, 7, 37, 29);
    triangle_fan_body(gl);
    // A scissored clear.
    gl.scissor(40, 40, 20, 15);
    gl.clear_color(0.9, 0.8, 0.1, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    // Disabled scissor: full-window drawing again.
    gl.disable(GL_SCISSOR_TEST);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.rectf(1.2, 55.3, 30.4, 62.6);
}

fn triangle_fan_body(gl: &mut dyn Gl) {
    gl.begin(GL_TRIANGLE_FAN);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.vertex_2f(31.6, 32.3);
    for k in 0..9 {
        pal(gl, k);
        let a = k as f32 * std::f32::consts::PI / 4.0 + 0.1;
        gl.vertex_2f(31.6 + 30.7 * a.cos(), 32.3 + 30.7 * a.sin());
    }
    gl.end();
}

fn color_mask(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.color_mask(T, F, T, F);
    triangle_fan_body(gl);
    gl.color_mask(F, T, F, T);
    gl.color_4f(0.3, 0.9, 0.3, 0.5);
    gl.rectf(5.2, 5.3, 30.6, 30.4);
    gl.color_mask(T, T, T, T);
}

fn clear_masks(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_DEPTH_TEST);
    gl.color_3f(1.0, 0.0, 0.0);
    gl.rectf(2.0, 2.0, 62.0, 62.0);
    // Clear colour with a colour mask: only green and alpha change.
    gl.color_mask(F, T, F, T);
    gl.clear_color(0.7, 0.6, 0.5, 0.25);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.color_mask(T, T, T, T);
    // Scissored depth clear to 0: nothing draws there afterwards with GL_LESS.
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(8, 8, 20, 40);
    gl.clear_depth(0.0);
    gl.clear(GL_DEPTH_BUFFER_BIT);
    gl.disable(GL_SCISSOR_TEST);
    gl.color_3f(0.0, 0.0, 1.0);
    gl.begin(GL_QUADS);
    gl.vertex_3f(4.3, 4.4, 0.9);
    gl.vertex_3f(50.2, 4.4, 0.9);
    gl.vertex_3f(50.2, 50.7, 0.9);
    gl.vertex_3f(4.3, 50.7, 0.9);
    gl.end();
}

fn clear_partial_depth_value(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_DEPTH_TEST);
    // Depth cleared to 0.5 (window z): a ramp from z_ndc -1..1 is visible on the near half.
    gl.clear_depth(0.5);
    gl.clear(GL_DEPTH_BUFFER_BIT);
    gl.begin(GL_QUADS);
    for (x, y, z) in [
        (2.2f32, 3.3f32, -1.0f32),
        (61.3, 3.3, 1.0),
        (61.3, 60.6, 1.0),
        (2.2, 60.6, -1.0),
    ] {
        affine(gl, x, y, 0.3);
        gl.vertex_3f(x, y, z);
    }
    gl.end();
}

// ---------------------------------------------------------------- shading

fn flat_triangles(gl: &mut dyn Gl) {
    gl.shade_model(GL_FLAT);
    triangles(gl);
}

fn flat_strip_fan(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.shade_model(GL_FLAT);
    gl.begin(GL_TRIANGLE_STRIP);
    for k in 0..8 {
        pal(gl, k);
        gl.vertex_2f(3.2 + 7.9 * k as f32, if k % 2 == 0 { 3.4 } else { 28.6 });
    }
    gl.end();
    gl.begin(GL_TRIANGLE_FAN);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.vertex_2f(31.6, 33.3);
    for k in 0..6 {
        pal(gl, k + 2);
        let a = k as f32 * std::f32::consts::PI / 5.0 + 0.1;
        gl.vertex_2f(31.6 + 29.2 * a.cos(), 33.3 + 29.2 * a.sin());
    }
    gl.end();
}

fn flat_quads_polygon(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.shade_model(GL_FLAT);
    // Quads: the fourth vertex of each quad provokes.
    gl.begin(GL_QUADS);
    for q in 0..4 {
        let ox = 2.4 + 31.0 * (q % 2) as f32;
        let oy = 2.7 + 31.0 * (q / 2) as f32;
        pal(gl, q);
        gl.vertex_2f(ox, oy);
        pal(gl, q + 1);
        gl.vertex_2f(ox + 27.3, oy + 2.2);
        pal(gl, q + 2);
        gl.vertex_2f(ox + 25.1, oy + 26.6);
        pal(gl, q + 3);
        gl.vertex_2f(ox + 1.3, oy + 24.2);
    }
    gl.end();
    gl.begin(GL_POLYGON);
    // Polygon: the first vertex provokes.
    for k in 0..5 {
        pal(gl, k + 4);
        let a = k as f32 * 2.0 * std::f32::consts::PI / 5.0 + 0.3;
        gl.vertex_2f(32.4 + 12.1 * a.cos(), 31.3 + 12.2 * a.sin());
    }
    gl.end();
}

fn flat_quad_strip(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.shade_model(GL_FLAT);
    quad_strip_body(gl, true);
}

fn flat_lines(gl: &mut dyn Gl) {
    gl.shade_model(GL_FLAT);
    lines(gl);
    gl.begin(GL_LINE_LOOP);
    for k in 0..5 {
        pal(gl, k + 1);
        let a = k as f32 * 2.0 * std::f32::consts::PI / 5.0 + 0.3;
        gl.vertex_2f(32.3 + 30.1 * a.cos(), 31.6 + 30.1 * a.sin());
    }
    gl.end();
}

fn smooth_then_flat(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    // The shade model in effect when each primitive is drawn counts.
    gl.begin(GL_TRIANGLES);
    gl.color_3f(1.0, 0.0, 0.0);
    gl.vertex_2f(2.2, 2.3);
    gl.color_3f(0.0, 1.0, 0.0);
    gl.vertex_2f(61.3, 2.9);
    gl.color_3f(0.0, 0.0, 1.0);
    gl.vertex_2f(2.8, 61.4);
    gl.end();
    gl.shade_model(GL_FLAT);
    gl.begin(GL_TRIANGLES);
    gl.color_3f(1.0, 1.0, 0.0);
    gl.vertex_2f(62.2, 8.3);
    gl.color_3f(0.0, 1.0, 1.0);
    gl.vertex_2f(61.3, 61.7);
    gl.color_3f(1.0, 0.0, 1.0);
    gl.vertex_2f(8.8, 62.4);
    gl.end();
}

// ---------------------------------------------------------------- matrices

/// A unit square around the origin with colours affine in object space (see `affine`).
fn unit_square(gl: &mut dyn Gl, c: usize) {
    let b = (c % 8) as f32 / 7.0;
    gl.begin(GL_QUADS);
    for (x, y) in [(-0.5f32, -0.5f32), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)] {
        gl.color_3f(0.5 + x, 0.5 + y, b);
        gl.vertex_2f(x, y);
    }
    gl.end();
}

fn matrix_stack(gl: &mut dyn Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-2.0, 2.0, -2.0, 2.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    clear(gl);
    gl.push_matrix();
    gl.translatef(-1.0, -1.0, 0.0);
    gl.rotatef(30.0, 0.0, 0.0, 1.0);
    unit_square(gl, 0);
    gl.push_matrix();
    gl.translatef(1.9, 0.1, 0.0);
    gl.scalef(0.5, 1.5, 1.0);
    unit_square(gl, 2);
    gl.pop_matrix();
    gl.translated(0.1, 2.0, 0.0);
    gl.rotated(-60.0, 0.0, 0.0, 1.0);
    gl.scaled(1.2, 0.6, 1.0);
    unit_square(gl, 4);
    gl.pop_matrix();
    // Rotation about a non-axis direction.
    gl.translatef(1.0, 1.0, 0.0);
    gl.rotatef(50.0, 1.0, 1.0, 1.0);
    unit_square(gl, 6);
}

fn ortho_frustum(gl: &mut dyn Gl) {
    clear(gl);
    gl.enable(GL_DEPTH_TEST);
    // Left half: an off-centre frustum with a rotated cube-ish pair of quads.
    gl.viewport(0, 0, 32, 64);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.6, 0.4, -0.7, 0.9, 1.5, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -4.0);
    gl.rotatef(35.0, 0.3, 1.0, 0.2);
    unit_square(gl, 0);
    gl.rotatef(90.0, 0.0, 1.0, 0.0);
    unit_square(gl, 3);
    // Right half: an asymmetric ortho.
    gl.viewport(32, 0, 32, 64);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-1.0, 3.0, -0.5, 2.5, -5.0, 5.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(1.0, 1.0, 0.0);
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
    unit_square(gl, 5);
}

fn load_mult_matrix(gl: &mut dyn Gl) {
    clear(gl);
    gl.matrix_mode(GL_PROJECTION);
    // Column-major ortho(-2, 2, -2, 2, -1, 1).
    gl.load_matrixf(&[
        0.5, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);
    gl.matrix_mode(GL_MODELVIEW);
    // Translate (-1, 0.8) then a shear, via column-major and transpose (row-major) loads.
    gl.load_matrixd(&[
        1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, 0.8, 0.0, 1.0,
    ]);
    gl.mult_transpose_matrixf(&[
        1.0, 0.6, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);
    unit_square(gl, 0);
    gl.load_transpose_matrixd(&[
        0.8, 0.0, 0.0, 0.9, 0.0, 1.2, 0.0, -1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);
    gl.mult_matrixf(&[
        0.866, 0.5, 0.0, 0.0, -0.5, 0.866, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);
    unit_square(gl, 2);
    gl.load_transpose_matrixf(&[
        0.5, 0.0, 0.0, 0.9, 0.0, 0.5, 0.0, 0.9, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);
    gl.mult_matrixd(&[
        1.0, 0.0, 0.0, 0.0, -0.4, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);
    unit_square(gl, 4);
    gl.mult_transpose_matrixd(&[
        1.0, 0.0, 0.0, -2.2, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);
    unit_square(gl, 6);
}

// ---------------------------------------------------------------- viewport, depth range

fn viewport(gl: &mut dyn Gl) {
    clear(gl);
    // A viewport partly outside the window, and a small one.
    gl.viewport(-20, 10, 70, 60);
    gl.begin(GL_TRIANGLES);
    gl.color_3f(1.0, 0.0, 0.0);
    gl.vertex_2f(-0.93, -0.91);
    gl.color_3f(0.0, 1.0, 0.0);
    gl.vertex_2f(0.96, -0.42);
    gl.color_3f(0.0, 0.0, 1.0);
    gl.vertex_2f(0.11, 0.97);
    gl.end();
    gl.viewport(40, 3, 21, 17);
    gl.color_3f(1.0, 1.0, 0.0);
    gl.rectf(-0.95, -0.93, 0.97, 0.91);
}

fn depth_range(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_DEPTH_TEST);
    // A far range for the first quad; a reversed range for the second makes its near side
    // far. The overlap shows which wins.
    gl.depth_range(0.5, 1.0);
    gl.begin(GL_QUADS);
    gl.color_3f(1.0, 0.0, 0.0);
    gl.vertex_3f(2.3, 2.4, -1.0);
    gl.vertex_3f(45.4, 2.4, -1.0);
    gl.vertex_3f(45.4, 45.6, 1.0);
    gl.vertex_3f(2.3, 45.6, 1.0);
    gl.end();
    gl.depth_range(1.0, 0.0);
    gl.begin(GL_QUADS);
    gl.color_3f(0.0, 1.0, 0.0);
    gl.vertex_3f(18.3, 18.4, -1.0);
    gl.vertex_3f(61.4, 18.4, 1.0);
    gl.vertex_3f(61.4, 61.6, 1.0);
    gl.vertex_3f(18.3, 61.6, -1.0);
    gl.end();
    gl.depth_range(0.0, 0.25);
    gl.color_3f(0.0, 0.0, 1.0);
    gl.rectf(30.2, 5.1, 40.3, 58.6);
}

fn big_viewport_128(gl: &mut dyn Gl) {
    // A larger framebuffer, several features at once: perspective, depth, culling, scissor.
    clear(gl);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_CULL_FACE);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.5, 0.5, -0.4, 0.4, 1.0, 30.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -3.0);
    gl.rotatef(25.0, 1.0, 0.0, 0.0);
    gl.rotatef(40.0, 0.0, 1.0, 0.0);
    // A cube of six CCW faces.
    let faces: [[[f32; 3]; 4]; 6] = [
        [[-1., -1., 1.], [1., -1., 1.], [1., 1., 1.], [-1., 1., 1.]],
        [
            [1., -1., -1.],
            [-1., -1., -1.],
            [-1., 1., -1.],
            [1., 1., -1.],
        ],
        [[1., -1., 1.], [1., -1., -1.], [1., 1., -1.], [1., 1., 1.]],
        [
            [-1., -1., -1.],
            [-1., -1., 1.],
            [-1., 1., 1.],
            [-1., 1., -1.],
        ],
        [[-1., 1., 1.], [1., 1., 1.], [1., 1., -1.], [-1., 1., -1.]],
        [
            [-1., -1., -1.],
            [1., -1., -1.],
            [1., -1., 1.],
            [-1., -1., 1.],
        ],
    ];
    gl.begin(GL_QUADS);
    for face in &faces {
        for p in face {
            // Colour affine in object space (see `affine`).
            gl.color_3f((p[0] + 1.0) / 2.0, (p[1] + 1.0) / 2.0, (p[2] + 1.0) / 2.0);
            gl.vertex_3f(p[0] * 0.7, p[1] * 0.7, p[2] * 0.7);
        }
    }
    gl.end();
}

/// The scenes defined in this file.
pub const BASE_SCENES: &[Scene] = &[
    scene("points", points),
    scene("lines", lines),
    scene("line_strip", line_strip),
    scene("line_loop", line_loop),
    scene("line_endpoints", line_endpoints),
    scene("triangles", triangles),
    scene("triangle_strip", triangle_strip),
    scene("triangle_fan", triangle_fan),
    scene("quads", quads),
    scene("quad_strip", quad_strip),
    scene("polygon", polygon),
    scene("rect", rect),
    scene("near_plane_clip", near_plane_clip),
    scene("negative_w", negative_w),
    scene("clip_planes", clip_planes),
    scene("cull_back", cull_back),
    scene("cull_front", cull_front),
    scene("cull_front_and_back", cull_front_and_back),
    scene("front_face_cw", front_face_cw),
    scene("cull_mirrored", cull_mirrored),
    scene("depth_never", depth_never),
    scene("depth_less", depth_less),
    scene("depth_equal", depth_equal),
    scene("depth_lequal", depth_lequal),
    scene("depth_greater", depth_greater),
    scene("depth_notequal", depth_notequal),
    scene("depth_gequal", depth_gequal),
    scene("depth_always", depth_always),
    scene("depth_mask", depth_mask),
    scene("scissor", scissor),
    scene("color_mask", color_mask),
    scene("clear_masks", clear_masks),
    scene("clear_depth_value", clear_partial_depth_value),
    scene("flat_triangles", flat_triangles),
    scene("flat_strip_fan", flat_strip_fan),
    scene("flat_quads_polygon", flat_quads_polygon),
    scene("flat_quad_strip", flat_quad_strip),
    scene("flat_lines", flat_lines),
    scene("smooth_then_flat", smooth_then_flat),
    scene("matrix_stack", matrix_stack),
    scene("ortho_frustum", ortho_frustum),
    scene("load_mult_matrix", load_mult_matrix),
    scene("viewport", viewport),
    scene("depth_range", depth_range),
    scene("lit_directional", lit_directional),
    scene("lit_positional_attenuated", lit_positional_attenuated),
    scene("lit_spot", lit_spot),
    scene(
        "lit_two_sided_separate_specular",
        lit_two_sided_separate_specular,
    ),
    scene("lit_color_material", lit_color_material),
    scene("blend_over", blend_over),
    scene("alpha_test_and_stencil", alpha_test_and_stencil),
    scene("logic_xor", logic_xor),
    scene("logic_ops", logic_ops),
    scene("fog_linear", fog_linear),
    scene("fog_exp", fog_exp),
    scene("fog_exp2", fog_exp2),
    scene("fog_coord_linear", fog_coord_linear),
    Scene {
        name: "cube_128",
        width: 128,
        height: 128,
        draw: big_viewport_128,
        tolerance: DIFFERENTIAL,
    },
];

pub(crate) const fn scene(name: &'static str, draw: fn(&mut dyn Gl)) -> Scene {
    scene_with(name, draw, DIFFERENTIAL)
}

/// A scene with its own tolerance: the bad-pixel share llvmpipe and softpipe themselves show on
/// it (measured with `--bin calibrate`, recorded in TOLERANCE.md).
pub(crate) const fn scene_with(
    name: &'static str,
    draw: fn(&mut dyn Gl),
    tolerance: Tolerance,
) -> Scene {
    Scene {
        name,
        width: 64,
        height: 64,
        draw,
        tolerance,
    }
}

/// Texture scenes: same channel threshold, bad share as measured between the Mesa drivers.
pub(crate) const fn spread(max_bad_share: f64) -> Tolerance {
    Tolerance {
        channel: DIFFERENTIAL.channel,
        max_bad_share,
    }
}

/// Every list of differential scenes with its feature area, in report order. Each list's test
/// (`conformance/tests/differential*.rs`) runs the whole list; the report and [`SCENES`] take
/// their scenes from here, so a scene is declared once, in its list.
pub const SCENE_LISTS: &[(&str, &[Scene])] = &[
    ("lighting and per-fragment", BASE_SCENES),
    ("texturing", crate::scenes_texture::TEXTURE_SCENES),
    ("arrays and lists", crate::scenes_arrays::ARRAY_SCENES),
    ("rasterization", crate::scenes_raster::RASTER_SCENES),
    ("teaching examples", crate::scenes_examples::EXAMPLE_SCENES),
    (
        "teaching techniques",
        crate::scenes_techniques::TECHNIQUE_SCENES,
    ),
    ("state", crate::scenes_state::STATE_SCENES),
    (
        "texture matrix",
        crate::scenes_texture_matrix::TEXTURE_MATRIX_SCENES,
    ),
    ("evaluators", crate::scenes_eval::EVAL_SCENES),
    ("texenv cascade", crate::scenes_cascade::CASCADE_SCENES),
    ("fidelity", crate::scenes_fidelity::FIDELITY_SCENES),
    ("extreme cases", crate::scenes_extremes::EXTREME_SCENES),
];

/// Every differential scene, in report order (the lists of [`SCENE_LISTS`] one after another).
pub static SCENES: std::sync::LazyLock<Vec<Scene>> = std::sync::LazyLock::new(|| {
    SCENE_LISTS
        .iter()
        .flat_map(|(_, list)| list.iter().copied())
        .collect()
});

/// The scene called `name`.
pub fn find(name: &str) -> Option<&'static Scene> {
    SCENES.iter().find(|s| s.name == name)
}

//! Extreme cases of clipping and lighting (in [`super::EXTREME_SCENES`]): coordinates near
//! 1e30, w near zero and negative, slivers and degenerate triangles, non-finite vertices;
//! zero-length normals under `GL_NORMALIZE`, spot cut-offs 90 and 180, shininess 0 and 128,
//! huge eye-plane coefficients, a sphere map with m = 0 and q = 0 from texture-coordinate
//! generation. (`tests/extremes.rs` and `tests/cascade_extremes.rs` check the same inputs
//! against the specification's equations.)
//!
//! Where Mesa is known to be less exact than tilegl, the case is listed in
//! [`crate::known_failures::MESA_LESS_EXACT`] with the reason, and the report shows it.

use crate::scenes::{clear, pal, pixel_space};
use tilegl::enums::*;
use tilegl::Gl;

/// Triangles with vertices near 1e30 and 1e20 (in object space) that still cover the right
/// half-planes, and a quad far outside every clip plane.
pub(super) fn huge_coordinates(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.begin(GL_TRIANGLES);
    pal(gl, 0);
    gl.vertex_2f(32.0, -1e30);
    gl.vertex_2f(1e30, 32.0);
    gl.vertex_2f(32.0, 32.0);
    pal(gl, 1);
    gl.vertex_2f(-1e20, 40.0);
    gl.vertex_2f(20.0, 40.0);
    gl.vertex_2f(20.0, 1e20);
    pal(gl, 2);
    gl.vertex_2f(1e30, 1e30);
    gl.vertex_2f(2e30, 1e30);
    gl.vertex_2f(1e30, 2e30);
    gl.end();
    // A line from far outside to the centre.
    gl.begin(GL_LINES);
    pal(gl, 3);
    gl.vertex_2f(-1e25, -1e25);
    gl.vertex_2f(30.0, 30.0);
    gl.end();
}

/// Vertices with w = 1e-6, w = -1 and w = 0 (clip-space input through an identity
/// projection): the clipper must cut, not divide by zero.
pub(super) fn w_near_zero(gl: &mut dyn Gl) {
    clear(gl);
    gl.begin(GL_TRIANGLES);
    gl.color_3f(1.0, 0.5, 0.0);
    gl.vertex_4f(-0.9, -0.9, 0.0, 1.0);
    gl.vertex_4f(1e-6, 0.0, 0.0, 1e-6);
    gl.vertex_4f(-0.9, 0.9, 0.0, 1.0);
    gl.color_3f(0.0, 0.8, 1.0);
    gl.vertex_4f(0.2, -0.8, 0.0, 1.0);
    gl.vertex_4f(0.9, -0.8, 0.0, 1.0);
    gl.vertex_4f(0.5, 0.5, 0.0, -1.0);
    gl.color_3f(0.8, 0.0, 0.8);
    gl.vertex_4f(0.2, 0.3, 0.0, 1.0);
    gl.vertex_4f(0.9, 0.3, 0.0, 1.0);
    gl.vertex_4f(0.6, 0.9, 0.0, 0.0);
    gl.end();
}

/// Slivers one hundredth of a pixel wide, a triangle with all three vertices on a line, one
/// with two equal vertices, and long thin triangles across the picture.
pub(super) fn slivers(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.begin(GL_TRIANGLES);
    for i in 0..8 {
        pal(gl, i);
        let y = 4.0 + 7.0 * i as f32;
        gl.vertex_2f(1.3, y + 0.37);
        gl.vertex_2f(62.7, y + 0.5 + 0.01 * i as f32);
        gl.vertex_2f(1.3, y + 0.38 + 0.6 * (i % 3) as f32);
    }
    gl.color_3f(1.0, 1.0, 1.0);
    gl.vertex_2f(5.0, 5.0);
    gl.vertex_2f(30.0, 30.0);
    gl.vertex_2f(55.0, 55.0);
    gl.vertex_2f(10.0, 50.0);
    gl.vertex_2f(10.0, 50.0);
    gl.vertex_2f(40.0, 20.0);
    gl.end();
}

/// Triangles, lines and points with a NaN or infinite coordinate, each followed by a good
/// primitive; a NaN in the modelview matrix for one rectangle.
pub(super) fn non_finite_vertices(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    for (i, bad) in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY]
        .into_iter()
        .enumerate()
    {
        let x = 4.0 + 20.0 * i as f32;
        pal(gl, i);
        gl.begin(GL_TRIANGLES);
        gl.vertex_2f(x, 4.0);
        gl.vertex_2f(x + 16.0, bad);
        gl.vertex_2f(x, 30.0);
        gl.vertex_2f(x, 34.0);
        gl.vertex_2f(x + 16.0, 34.0);
        gl.vertex_2f(x, 50.0);
        gl.end();
        gl.begin(GL_LINES);
        gl.vertex_2f(bad, 56.0);
        gl.vertex_2f(x + 10.0, 60.0);
        gl.vertex_2f(x, 56.5);
        gl.vertex_2f(x + 16.0, 56.5);
        gl.end();
        gl.point_size(3.0);
        gl.begin(GL_POINTS);
        gl.vertex_4f(x + 8.0, 62.0, 0.0, bad);
        gl.vertex_2f(x + 12.5, 61.5);
        gl.end();
    }
    gl.push_matrix();
    gl.scalef(f32::NAN, 1.0, 1.0);
    gl.rectf(0.0, 0.0, 64.0, 64.0);
    gl.pop_matrix();
}

/// A lit context in pixel space: no global ambient, material components zero, light 0 white.
pub(super) fn lit(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.light_modelfv(GL_LIGHT_MODEL_AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
    for p in [GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION] {
        gl.materialfv(GL_FRONT_AND_BACK, p, &[0.0, 0.0, 0.0, 1.0]);
    }
}

/// Zero-length normals under `GL_NORMALIZE` (left) and `GL_RESCALE_NORMAL` (right): only
/// emission and ambient light them; above, strips of normals from 1e-18 to 1 long. (Lengths
/// whose squares leave the float range, 1e-22 or 1e-30 for example, are in
/// `scenes_extremes::normals_1e_minus_20`: llvmpipe flushes or underflows them to zero and
/// leaves such a normal unlit, tilegl normalizes them to a unit normal, as the spec asks.)
pub(super) fn zero_normals(gl: &mut dyn Gl) {
    lit(gl);
    gl.materialfv(GL_FRONT_AND_BACK, GL_EMISSION, &[0.2, 0.1, 0.0, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_AMBIENT, &[0.4, 0.4, 0.4, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.8, 0.9, 1.0, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 0.0);
    gl.lightfv(GL_LIGHT0, GL_AMBIENT, &[0.5, 0.5, 0.5, 1.0]);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.0, 0.0, 1.0, 0.0]);
    for (i, mode) in [GL_NORMALIZE, GL_RESCALE_NORMAL].into_iter().enumerate() {
        gl.enable(mode);
        let x = 32.0 * i as f32;
        gl.normal_3f(0.0, 0.0, 0.0);
        gl.rectf(x, 0.0, x + 32.0, 32.0);
        // Normals 1e-18 .. 1 long along +z, one strip each.
        for (k, length) in [1e-18f32, 1e-15, 1e-12, 1e-9, 1e-6, 1e-3, 1.0]
            .into_iter()
            .enumerate()
        {
            gl.normal_3f(0.0, 0.0, length);
            let xs = x + 4.0 * k as f32;
            gl.rectf(xs, 32.0, xs + 4.0, 64.0);
        }
        gl.disable(mode);
    }
}

/// A spot light pointing along +x over a plane, cut-offs 90 (top) and 180 (bottom), exponent
/// 0 and 8. (The light sits between two columns of vertices: at a vertex exactly at 90 degrees
/// the spot factor is 0^0, which llvmpipe's pow evaluates to 0 and tilegl to 1; the
/// specification does not settle 0^0.)
pub(super) fn spot_cutoffs(gl: &mut dyn Gl) {
    lit(gl);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[1.0, 1.0, 1.0, 1.0]);
    gl.lightfv(GL_LIGHT0, GL_SPOT_DIRECTION, &[1.0, 0.0, 0.0]);
    gl.normal_3f(0.0, 0.0, 1.0);
    for (i, (cutoff, exponent)) in [(180.0, 0.0), (180.0, 8.0), (90.0, 0.0), (90.0, 8.0)]
        .into_iter()
        .enumerate()
    {
        let y = 16.0 * i as f32;
        gl.lightfv(GL_LIGHT0, GL_POSITION, &[32.7, y + 8.0, 6.0, 1.0]);
        gl.lightf(GL_LIGHT0, GL_SPOT_CUTOFF, cutoff);
        gl.lightf(GL_LIGHT0, GL_SPOT_EXPONENT, exponent);
        // A fine mesh, so the per-vertex lighting shows the cone's edge.
        for row in 0..4 {
            gl.begin(GL_QUAD_STRIP);
            for col in 0..=32 {
                let x = 2.0 * col as f32;
                gl.vertex_2f(x, y + 4.0 * row as f32);
                gl.vertex_2f(x, y + 4.0 * (row + 1) as f32);
            }
            gl.end();
        }
    }
}

/// Specular highlights on a tilted mesh under a directional light: shininess 0, 1, 64 and 128.
pub(super) fn shininess(gl: &mut dyn Gl) {
    lit(gl);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.9, 0.8, 0.7, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.1, 0.1, 0.2, 1.0]);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 0.2, 1.0, 0.0]);
    for (i, s) in [0.0f32, 1.0, 64.0, 128.0].into_iter().enumerate() {
        gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, s);
        let y = 16.0 * i as f32;
        gl.begin(GL_QUAD_STRIP);
        for col in 0..=32 {
            let x = 2.0 * col as f32;
            let t = (x - 32.0) / 40.0;
            gl.normal_3f(t, 0.1 * (i as f32 - 1.5), 1.0);
            gl.vertex_2f(x, y);
            gl.vertex_2f(x, y + 16.0);
        }
        gl.end();
    }
}

/// Shininess 0 under attenuated positional lights: the specular term is the full attenuated
/// specular colour wherever n . VP > 0 (section 2.14.1: (n . h)^0 = 1).
pub(super) fn shininess_0_positional(gl: &mut dyn Gl) {
    lit(gl);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 0.0);
    gl.normal_3f(0.0, 0.0, 1.0);
    for (i, (x, att)) in [(-40.0f32, 2.0f32), (100.0, 1.0)].into_iter().enumerate() {
        gl.lightfv(
            GL_LIGHT0,
            GL_POSITION,
            &[x, 16.0 + 32.0 * i as f32, 3.0, 1.0],
        );
        gl.lightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, att);
        let y = 32.0 * i as f32;
        gl.rectf(0.0, y, 64.0, y + 32.0);
    }
}

/// Texture-coordinate generation at its edges on a 2x2 checker: eye planes with coefficients
/// of 1e20 (left), a sphere map whose reflection vector is (0, 0, -1), m = 0 (middle), and
/// object-linear q = 0 on part of a quad (right).
pub(super) fn texgen(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let checker: [u8; 16] = [
        230, 40, 40, 255, 40, 230, 40, 255, 40, 40, 230, 255, 230, 230, 40, 255,
    ];
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&checker),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    // Huge eye planes: s = 1e20 x + 0.25, wrapping to the repeat of the fraction.
    for c in [GL_S, GL_T] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR as i32);
    }
    gl.tex_genfv(GL_S, GL_EYE_PLANE, &[0.0, 0.0, 1e20, 0.25]);
    gl.tex_genfv(GL_T, GL_EYE_PLANE, &[0.0, 1.0 / 32.0, 0.0, 0.1]);
    gl.rectf(2.0, 2.0, 20.0, 62.0);
    // Sphere map with normals facing away from the viewer: r = (0, 0, -1) gives m = 0.
    for c in [GL_S, GL_T] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    }
    gl.normal_3f(0.0, 0.0, -1.0);
    gl.rectf(22.0, 2.0, 40.0, 30.0);
    gl.normal_3f(0.0, 0.0, 1.0);
    gl.rectf(22.0, 34.0, 40.0, 62.0);
    // Object-linear q crossing zero: q = x / 32 - 1.4 is 0 at x = 44.8.
    gl.enable(GL_TEXTURE_GEN_Q);
    for c in [GL_S, GL_T, GL_Q] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR as i32);
    }
    gl.tex_genfv(GL_S, GL_OBJECT_PLANE, &[1.0 / 16.0, 0.0, 0.0, 0.0]);
    gl.tex_genfv(GL_T, GL_OBJECT_PLANE, &[0.0, 1.0 / 16.0, 0.0, 0.0]);
    gl.tex_genfv(GL_Q, GL_OBJECT_PLANE, &[0.0, 0.0, 0.0, 0.0]);
    gl.rectf(42.0, 2.0, 62.0, 30.0);
    gl.tex_genfv(GL_Q, GL_OBJECT_PLANE, &[1.0 / 32.0, 0.0, 0.0, -1.4]);
    gl.rectf(42.0, 34.0, 62.0, 62.0);
}

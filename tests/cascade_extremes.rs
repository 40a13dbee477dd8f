//! Extreme inputs to lighting and texture coordinate generation, with expectations derived
//! from the specification (OpenGL 1.5 sections 2.11.4 and 2.14.1): zero-length normals under
//! `GL_NORMALIZE`, spot cut-offs 90 and 180, shininess 0 and 128, huge eye-plane coefficients,
//! a sphere map whose reflection vector is (0, 0, -1) (m = 0), reflection vectors exactly along
//! each axis of a cube map, and q = 0 from texgen. Nothing may panic and no NaN may reach the
//! picture.

mod common;

use common::{pixel, read_rgba, window_ortho};
use tilegl::enums::*;
use tilegl::{Context, Gl};

fn close(got: [u8; 4], want: [f32; 4], what: &str) {
    for i in 0..4 {
        assert!(
            (got[i] as f32 - want[i] * 255.0).abs() <= 1.5,
            "{what}: {got:?} vs {:?}",
            want.map(|v| v * 255.0)
        );
    }
}

/// A lit context in window coordinates: no global ambient, material with only the given
/// components, light 0 white.
fn lit(w: i32, h: i32) -> Context {
    let mut gl = Context::new(w, h);
    window_ortho(&mut gl);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.light_modelfv(GL_LIGHT_MODEL_AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.0, 0.0, 0.0, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.0, 0.0, 0.0, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_EMISSION, &[0.0, 0.0, 0.0, 1.0]);
    gl
}

#[test]
fn zero_length_normals_under_normalize_light_only_ambient_and_emission() {
    // n = 0: n . VP = 0, so the diffuse term is 0 and f = 0 removes the specular term; what
    // is left is emission + ambient (section 2.14.1), never a NaN.
    for normalize in [GL_NORMALIZE, GL_RESCALE_NORMAL] {
        let mut gl = lit(8, 8);
        gl.enable(normalize);
        gl.materialfv(GL_FRONT_AND_BACK, GL_EMISSION, &[0.2, 0.1, 0.0, 1.0]);
        gl.materialfv(GL_FRONT_AND_BACK, GL_AMBIENT, &[0.4, 0.4, 0.4, 1.0]);
        gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[1.0, 1.0, 1.0, 1.0]);
        gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
        gl.lightfv(GL_LIGHT0, GL_AMBIENT, &[0.5, 0.5, 0.5, 1.0]);
        gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.0, 0.0, 1.0, 0.0]);
        gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 0.0);
        gl.normal_3f(0.0, 0.0, 0.0);
        gl.rectf(0.0, 0.0, 8.0, 8.0);
        let want = [0.2 + 0.2, 0.1 + 0.2, 0.2, 1.0];
        for p in read_rgba(&mut gl) {
            close(p, want, "zero normal");
        }
    }
}

#[test]
fn zero_length_normal_under_normalize_with_sphere_map_draws_a_texel() {
    let mut gl = Context::new(8, 8);
    window_ortho(&mut gl);
    gl.enable(GL_NORMALIZE);
    let texel = [90u8, 180, 30, 255];
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texel),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    for c in [GL_S, GL_T] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    }
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    gl.normal_3f(0.0, 0.0, 0.0);
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    for p in read_rgba(&mut gl) {
        assert_eq!(p, texel);
    }
}

/// Light 0 a spot at (4, 4, 0.5) in window space pointing along +x, exponent 0, over a
/// rectangle at z = 0 facing the viewer (normal +z): left half x < 4, right half x > 4.
fn spot_halves(cutoff: f32) -> ([u8; 4], [u8; 4]) {
    let mut gl = lit(64, 8);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[1.0, 1.0, 1.0, 1.0]);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[32.0, 4.0, 0.5, 1.0]);
    gl.lightfv(GL_LIGHT0, GL_SPOT_DIRECTION, &[1.0, 0.0, 0.0]);
    gl.lightf(GL_LIGHT0, GL_SPOT_CUTOFF, cutoff);
    gl.lightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0.0);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.normal_3f(0.0, 0.0, 1.0);
    // Two separate rectangles far from the light, so n . VP is small but positive and the
    // same for both (mirror images).
    gl.rectf(0.0, 0.0, 4.0, 8.0);
    gl.rectf(60.0, 0.0, 64.0, 8.0);
    (pixel(&mut gl, 2, 4), pixel(&mut gl, 62, 4))
}

#[test]
fn spot_cutoff_90_lights_the_half_space_and_180_everything() {
    // Spot factor (2.14.1): 0 when the angle between the spot direction and the light-to-
    // vertex vector exceeds the cut-off, else (max(s . d, 0))^exponent = 1 with exponent 0;
    // cut-off 180 is a point light.
    let (left90, right90) = spot_halves(90.0);
    let (left180, right180) = spot_halves(180.0);
    assert_eq!(left90[..3], [0, 0, 0], "behind a 90-degree spot is dark");
    assert!(right90[0] > 0, "in front of a 90-degree spot is lit");
    assert_eq!(right90, right180, "inside the cone the spot factor is 1");
    assert_eq!(
        left180, right180,
        "cut-off 180: no cone, mirror images match"
    );
    // n . VP for the vertex at x = 62 (the pixel read is at the rectangle's centre, and the
    // rectangle's vertices give n . VP between these values).
    let dot = |x: f32, y: f32| {
        let v = [32.0 - x, 4.0 - y, 0.5f32];
        v[2] / (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
    };
    let (lo, hi) = (dot(64.0, 0.0), dot(60.0, 4.0));
    let r = right90[0] as f32 / 255.0;
    assert!(
        r >= lo - 1.0 / 255.0 && r <= hi + 1.0 / 255.0,
        "{r} outside [{lo}, {hi}]"
    );
}

/// Specular only, directional light along +z, infinite viewer: h = (0, 0, 1), so n . h is
/// cos a for a normal tilted by a.
fn specular(shininess: f32, tilt_degrees: f32) -> [u8; 4] {
    let mut gl = lit(8, 8);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.0, 0.0, 1.0, 0.0]);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let a = tilt_degrees.to_radians();
    gl.normal_3f(0.0, a.sin(), a.cos());
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    pixel(&mut gl, 4, 4)
}

#[test]
fn shininess_0_gives_the_full_specular_colour_wherever_lit() {
    // (n . h)^0 = 1 while n . VP > 0.
    for tilt in [0.0, 30.0, 80.0] {
        close(specular(0.0, tilt), [0.5, 0.5, 0.5, 1.0], "shininess 0");
    }
    // Facing away from the light: f = 0, no specular even at shininess 0.
    close(
        specular(0.0, 120.0),
        [0.0, 0.0, 0.0, 1.0],
        "shininess 0, unlit",
    );
}

#[test]
fn shininess_128_is_a_sharp_power() {
    for tilt in [0.0f32, 3.0, 5.0, 10.0, 20.0] {
        let want = 0.5 * tilt.to_radians().cos().powf(128.0);
        close(
            specular(128.0, tilt),
            [want, want, want, 1.0],
            &format!("shininess 128 tilt {tilt}"),
        );
    }
    // Out of range is an error and leaves the value.
    let mut gl = Context::new(1, 1);
    gl.materialf(GL_FRONT, GL_SHININESS, 128.5);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
}

fn uniform_texture(gl: &mut Context, target: GLenum, texel: [u8; 4]) {
    gl.tex_image_2d(
        target,
        0,
        GL_RGBA as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texel),
    );
}

#[test]
fn huge_eye_plane_coefficients_still_sample_the_texture() {
    // s and t are enormous (or overflow to infinity); with a one-texel texture every lookup
    // is that texel, so the rectangle must show it: no dropped fragment, no NaN colour.
    for k in [1e20f32, 1e30, 1e38, f32::MAX] {
        let mut gl = Context::new(8, 8);
        window_ortho(&mut gl);
        let texel = [10u8, 200, 120, 255];
        uniform_texture(&mut gl, GL_TEXTURE_2D, texel);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
        gl.enable(GL_TEXTURE_2D);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
        gl.tex_genfv(GL_S, GL_EYE_PLANE, &[k, k, 0.0, k]);
        gl.tex_genfv(GL_T, GL_EYE_PLANE, &[-k, k, 0.0, 0.0]);
        for c in [GL_S, GL_T] {
            gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR as i32);
        }
        gl.enable(GL_TEXTURE_GEN_S);
        gl.enable(GL_TEXTURE_GEN_T);
        gl.color_3f(1.0, 0.0, 1.0);
        gl.rectf(0.0, 0.0, 8.0, 8.0);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        for p in read_rgba(&mut gl) {
            assert_eq!(p, texel, "plane coefficient {k}");
        }
    }
}

/// A point at eye (0, 0, -2), straight ahead (u = (0, 0, -1)), with normal `n`, under a
/// perspective projection; the window-centre pixel is returned.
fn point_ahead(gl: &mut Context, n: [f32; 3]) -> [u8; 4] {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.point_size(3.0);
    gl.begin(GL_POINTS);
    gl.normal_3f(n[0], n[1], n[2]);
    gl.vertex_3f(0.0, 0.0, -2.0);
    gl.end();
    pixel(gl, 4, 4)
}

#[test]
fn sphere_map_with_reflection_straight_away_from_the_viewer() {
    // u = (0, 0, -1) and n = (1, 0, 0): r = u - 2 n (n . u) = (0, 0, -1), so
    // m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2) = 0 and s = rx / m + 1/2 is 0/0. The specification
    // gives no value; the picture must still show one of the texture's texels.
    let mut gl = Context::new(9, 9);
    let texels = [
        [255u8, 0, 0, 255],
        [0, 255, 0, 255],
        [0, 0, 255, 255],
        [255, 255, 0, 255],
    ];
    let flat: Vec<u8> = texels.iter().flatten().copied().collect();
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&flat),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    for c in [GL_S, GL_T] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    }
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    let got = point_ahead(&mut gl, [1.0, 0.0, 0.0]);
    assert!(texels.contains(&got), "{got:?} is no texel");
    // The neighbouring case n = (0, 0, 1), r = (0, 0, 1): m = 4, s = t = 1/2 exactly, the
    // texel corner; NEAREST picks the texel at floor(1/2 * 2) = 1 in both: texel (1, 1).
    let got = point_ahead(&mut gl, [0.0, 0.0, 1.0]);
    assert_eq!(got, texels[3]);
}

#[test]
fn reflection_map_exactly_along_each_axis_selects_that_face() {
    // Table 3.19: the major axis is the coordinate of largest magnitude. For r exactly along
    // +-x, +-y, +-z there is no tie: each face (one colour per face) must show. The normal
    // n = (u - r) / |u - r| reflects u = (0, 0, -1) into r.
    let colours: [[u8; 4]; 6] = [
        [255, 0, 0, 255],
        [0, 255, 255, 255],
        [0, 255, 0, 255],
        [255, 0, 255, 255],
        [0, 0, 255, 255],
        [255, 255, 0, 255],
    ];
    let mut gl = Context::new(9, 9);
    for (f, c) in colours.iter().enumerate() {
        uniform_texture(&mut gl, GL_TEXTURE_CUBE_MAP_POSITIVE_X + f as GLenum, *c);
    }
    gl.tex_parameteri(
        GL_TEXTURE_CUBE_MAP,
        GL_TEXTURE_MIN_FILTER,
        GL_NEAREST as i32,
    );
    gl.enable(GL_TEXTURE_CUBE_MAP);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    for c in [GL_S, GL_T, GL_R] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP as i32);
    }
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    gl.enable(GL_TEXTURE_GEN_R);
    let axes = [
        [1.0f32, 0.0, 0.0],
        [-1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -1.0],
    ];
    for (f, r) in axes.iter().enumerate() {
        let n = if f == 5 {
            // r = u: any normal perpendicular to u.
            [1.0, 0.0, 0.0]
        } else {
            [-r[0], -r[1], -1.0 - r[2]]
        };
        assert_eq!(point_ahead(&mut gl, n), colours[f], "r = {r:?}");
    }
    // A tie (|rx| = |ry|) is the implementation's to break, but deterministically.
    let tie = [-0.5f32.sqrt(), -0.5f32.sqrt(), -1.0];
    let first = point_ahead(&mut gl, tie);
    assert!(colours[..4].contains(&first), "{first:?}");
    assert_eq!(point_ahead(&mut gl, tie), first);
}

#[test]
fn q_zero_from_texgen_still_covers_and_shows_a_texel() {
    // Q generated by an all-zero object plane: q = 0 and s/q, t/q are undefined (not a
    // reason to drop fragments). Every covered pixel must show one of the texels.
    let mut gl = Context::new(16, 16);
    window_ortho(&mut gl);
    let texels = [[200u8, 30, 30, 255], [30, 200, 30, 255]];
    let flat: Vec<u8> = texels.iter().flatten().copied().collect();
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        2,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&flat),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.tex_geni(GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR as i32);
    gl.tex_genfv(GL_Q, GL_OBJECT_PLANE, &[0.0, 0.0, 0.0, 0.0]);
    gl.enable(GL_TEXTURE_GEN_Q);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.begin(GL_TRIANGLES);
    for (s, x, y) in [(0.2, 1.0, 1.0), (0.9, 15.0, 1.0), (0.5, 8.0, 15.0)] {
        gl.tex_coord_2f(s, 0.5);
        gl.vertex_2f(x, y);
    }
    gl.end();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut covered = 0;
    for p in read_rgba(&mut gl) {
        if p != [0, 0, 0, 0] {
            covered += 1;
            assert!(texels.contains(&p), "{p:?} is no texel");
        }
    }
    // The triangle's area is 14 * 14 / 2 = 98 pixels.
    assert!((80..=120).contains(&covered), "{covered} pixels covered");
}

#[test]
fn shininess_0_under_an_attenuated_positional_light_is_the_full_attenuated_specular() {
    // (n . h)^0 = 1 wherever n . VP > 0, times the attenuation 1 / k_c = 1/2: 0.5 * 0.5.
    // (Mesa 22's fixed-function program raises n . h to the power n . VP here instead.)
    let mut gl = lit(8, 8);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 0.0);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[-40.0, 4.0, 3.0, 1.0]);
    gl.lightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 2.0);
    gl.normal_3f(0.0, 0.0, 1.0);
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    for p in read_rgba(&mut gl) {
        close(p, [0.25, 0.25, 0.25, 1.0], "shininess 0, positional");
    }
}

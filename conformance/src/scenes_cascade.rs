//! Differential scenes for the texture-unit cascade: `GL_COMBINE` on two units (every function x
//! every source, the `TEXTUREn` crossbar included, x every operand, packed as a grid of tiles with
//! their own environment), every texgen mode on a lit tessellated sphere and on a plane, and
//! lighting cases packed as spheres in sub-viewports (spot cut-offs and exponents, attenuation,
//! local viewer, separate specular, two-sided lighting of back faces, colour material on each
//! face). They extend the `lit_*`, `texgen_*` and `multitexture_combine` scenes.
//!
//! Tiles are axis-aligned quads whose primary colour and texture coordinates are affine in
//! window position, so every split of a quad into triangles gives the same picture.

use crate::compare::Scene;
use crate::scenes::{clear, sphere};
use crate::tolerance::DIFFERENTIAL;
use tilegl::enums::*;
use tilegl::Gl;

const fn big(name: &'static str, draw: fn(&mut dyn Gl)) -> Scene {
    Scene {
        name,
        width: 128,
        height: 128,
        draw,
        tolerance: DIFFERENTIAL,
    }
}

/// The cascade scenes, in report order.
pub const CASCADE_SCENES: &[Scene] = &[
    big("cascade_combine_replace", combine_replace),
    big("cascade_combine_modulate", combine_modulate),
    big("cascade_combine_add", combine_add),
    big("cascade_combine_add_signed", combine_add_signed),
    big("cascade_combine_interpolate", combine_interpolate),
    big("cascade_combine_subtract", combine_subtract),
    big("cascade_combine_dot3_rgb", combine_dot3_rgb),
    big("cascade_combine_dot3_rgba", combine_dot3_rgba),
    big("cascade_texgen_sphere_lit", texgen_sphere_lit),
    big("cascade_texgen_plane", texgen_plane),
    big("cascade_lit_spots", lit_spots),
    big("cascade_lit_models", lit_models),
    big("cascade_lit_color_material", lit_color_material),
];

// ---------------------------------------------------------------------------------------------
// GL_COMBINE on two units.

const SOURCES: [GLenum; 5] = [
    GL_TEXTURE,
    GL_TEXTURE0, // replaced by the other unit's TEXTUREn (the crossbar)
    GL_CONSTANT,
    GL_PRIMARY_COLOR,
    GL_PREVIOUS,
];
const OPERANDS: [GLenum; 4] = [
    GL_SRC_COLOR,
    GL_ONE_MINUS_SRC_COLOR,
    GL_SRC_ALPHA,
    GL_ONE_MINUS_SRC_ALPHA,
];

/// A 4x4 RGBA texture of well-spread values, different per `seed`.
fn texture4(seed: u32) -> Vec<u8> {
    let mut out = Vec::with_capacity(64);
    let mut x = seed.wrapping_mul(2_654_435_761).wrapping_add(12345);
    for _ in 0..64 {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        out.push((x >> 8) as u8);
    }
    out
}

fn two_unit_textures(gl: &mut dyn Gl) {
    clear(gl);
    let mut names = [0u32; 2];
    gl.gen_textures(2, &mut names);
    for (u, unit) in [GL_TEXTURE0, GL_TEXTURE1].into_iter().enumerate() {
        gl.active_texture(unit);
        gl.bind_texture(GL_TEXTURE_2D, names[u]);
        let px = texture4(u as u32 + 7);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            4,
            4,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&px),
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
        gl.enable(GL_TEXTURE_2D);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
        let c = if u == 0 {
            [0.3, 0.7, 0.55, 0.35]
        } else {
            [0.8, 0.2, 0.45, 0.65]
        };
        gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &c);
    }
    gl.active_texture(GL_TEXTURE0);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 128.0, 0.0, 128.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

/// Sets one unit's combiner: function `func` (alpha: the same, or MODULATE for DOT3), the
/// three arguments' sources and operands, scales.
fn set_combiner(
    gl: &mut dyn Gl,
    unit: usize,
    func: GLenum,
    src: [GLenum; 3],
    op: [GLenum; 3],
    scales: [f32; 2],
) {
    gl.active_texture(GL_TEXTURE0 + unit as GLenum);
    let other = GL_TEXTURE0 + (1 - unit) as GLenum;
    let src = src.map(|s| if s == GL_TEXTURE0 { other } else { s });
    let alpha_func = if func == GL_DOT3_RGB || func == GL_DOT3_RGBA {
        GL_MODULATE
    } else {
        func
    };
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, func as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, alpha_func as i32);
    let names = [
        (
            GL_SOURCE0_RGB,
            GL_SOURCE0_ALPHA,
            GL_OPERAND0_RGB,
            GL_OPERAND0_ALPHA,
        ),
        (
            GL_SOURCE1_RGB,
            GL_SOURCE1_ALPHA,
            GL_OPERAND1_RGB,
            GL_OPERAND1_ALPHA,
        ),
        (
            GL_SOURCE2_RGB,
            GL_SOURCE2_ALPHA,
            GL_OPERAND2_RGB,
            GL_OPERAND2_ALPHA,
        ),
    ];
    for (k, &(sr, sa, or, oa)) in names.iter().enumerate() {
        gl.tex_envi(GL_TEXTURE_ENV, sr, src[k] as i32);
        gl.tex_envi(GL_TEXTURE_ENV, sa, src[k] as i32);
        gl.tex_envi(GL_TEXTURE_ENV, or, op[k] as i32);
        // Alpha takes only the alpha operands: the colour ones map to their alpha twin.
        let a = match op[k] {
            GL_SRC_COLOR | GL_SRC_ALPHA => GL_SRC_ALPHA,
            _ => GL_ONE_MINUS_SRC_ALPHA,
        };
        gl.tex_envi(GL_TEXTURE_ENV, oa, a as i32);
    }
    gl.tex_envf(GL_TEXTURE_ENV, GL_RGB_SCALE, scales[0]);
    gl.tex_envf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, scales[1]);
    gl.active_texture(GL_TEXTURE0);
}

/// One 8x8 tile at grid cell `n` (16 per row): primary colour and both units' texture
/// coordinates affine in position.
fn tile(gl: &mut dyn Gl, n: usize) {
    let (x0, y0) = ((n % 16) as f32 * 8.0, (n / 16) as f32 * 8.0);
    let hue = n as f32 * 0.37;
    gl.begin(GL_QUADS);
    for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        gl.color_4f(
            0.2 + 0.6 * u,
            0.5 + 0.4 * (hue.sin() * 0.5) * v,
            0.8 - 0.5 * v,
            0.3 + 0.5 * (u + v) * 0.5,
        );
        gl.multi_tex_coord_2f(GL_TEXTURE0, u, v);
        gl.multi_tex_coord_2f(GL_TEXTURE1, 1.0 - v, u);
        gl.vertex_2f(x0 + 8.0 * u, y0 + 8.0 * v);
    }
    gl.end();
}

/// Every (unit, argument, source, operand) of `func` as its own tile: 2 x 3 x 5 x 4 = 120
/// tiles. The tested unit's other arguments and the other unit rotate through sources and
/// operands too, and the scales through 1, 2 and 4.
fn combine_grid(gl: &mut dyn Gl, func: GLenum) {
    two_unit_textures(gl);
    let scales = [1.0, 2.0, 4.0];
    let mut n = 0;
    for unit in 0..2 {
        for arg in 0..3 {
            for (si, &s) in SOURCES.iter().enumerate() {
                for (oi, &o) in OPERANDS.iter().enumerate() {
                    let mut src = [0, 1, 2].map(|k| SOURCES[(n + 2 * k + 1) % 5]);
                    let mut op = [0, 1, 2].map(|k| OPERANDS[(n / 5 + k) % 4]);
                    src[arg] = s;
                    op[arg] = o;
                    // Large scales on functions that already saturate teach little: keep them
                    // mostly to scale 1 and 2, with every fifth tile at 4.
                    let rs = if n % 5 == 4 { 4.0 } else { scales[n % 2] };
                    let as_ = scales[(n / 2 + si + oi) % 3];
                    set_combiner(gl, unit, func, src, op, [rs, as_]);
                    let other_func = [GL_MODULATE, GL_ADD_SIGNED, GL_INTERPOLATE][n % 3];
                    let other_src = [0, 1, 2].map(|k| SOURCES[(n + k) % 5]);
                    let other_op = [0, 1, 2].map(|k| OPERANDS[(n + 3 * k) % 4]);
                    set_combiner(gl, 1 - unit, other_func, other_src, other_op, [1.0, 1.0]);
                    tile(gl, n);
                    n += 1;
                }
            }
        }
    }
}

fn combine_replace(gl: &mut dyn Gl) {
    combine_grid(gl, GL_REPLACE);
}
fn combine_modulate(gl: &mut dyn Gl) {
    combine_grid(gl, GL_MODULATE);
}
fn combine_add(gl: &mut dyn Gl) {
    combine_grid(gl, GL_ADD);
}
fn combine_add_signed(gl: &mut dyn Gl) {
    combine_grid(gl, GL_ADD_SIGNED);
}
fn combine_interpolate(gl: &mut dyn Gl) {
    combine_grid(gl, GL_INTERPOLATE);
}
fn combine_subtract(gl: &mut dyn Gl) {
    combine_grid(gl, GL_SUBTRACT);
}
fn combine_dot3_rgb(gl: &mut dyn Gl) {
    combine_grid(gl, GL_DOT3_RGB);
}
fn combine_dot3_rgba(gl: &mut dyn Gl) {
    combine_grid(gl, GL_DOT3_RGBA);
}

// ---------------------------------------------------------------------------------------------
// Texture coordinate generation, lit.

/// A smooth 16x16 2D texture (unit 0) and a 4x4-per-face cube map (unit 1), both LINEAR.
fn texgen_textures(gl: &mut dyn Gl) {
    clear(gl);
    let mut names = [0u32; 2];
    gl.gen_textures(2, &mut names);
    gl.bind_texture(GL_TEXTURE_2D, names[0]);
    let mut px = Vec::with_capacity(16 * 16 * 4);
    for y in 0..16 {
        for x in 0..16 {
            let on = (x / 4 + y / 4) % 2 == 0;
            px.extend_from_slice(&[
                (x * 16) as u8,
                (y * 16) as u8,
                if on { 230 } else { 40 },
                255,
            ]);
        }
    }
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        16,
        16,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&px),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.active_texture(GL_TEXTURE1);
    gl.bind_texture(GL_TEXTURE_CUBE_MAP, names[1]);
    for face in 0..6u32 {
        let mut p = Vec::with_capacity(64);
        for y in 0..4u32 {
            for x in 0..4u32 {
                p.extend_from_slice(&[
                    (40 + face * 40) as u8,
                    (x * 60 + 20) as u8,
                    (y * 60 + 20) as u8,
                    255,
                ]);
            }
        }
        gl.tex_image_2d(
            GL_TEXTURE_CUBE_MAP_POSITIVE_X + face,
            0,
            GL_RGBA as i32,
            4,
            4,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&p),
        );
    }
    gl.tex_parameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.tex_parameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.tex_parameteri(
        GL_TEXTURE_CUBE_MAP,
        GL_TEXTURE_WRAP_S,
        GL_CLAMP_TO_EDGE as i32,
    );
    gl.tex_parameteri(
        GL_TEXTURE_CUBE_MAP,
        GL_TEXTURE_WRAP_T,
        GL_CLAMP_TO_EDGE as i32,
    );
    gl.active_texture(GL_TEXTURE0);
}

fn lighting_on(gl: &mut dyn Gl) {
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.6, 0.8, 1.0, 0.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.9, 0.85, 0.8, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0);
}

/// Sets texgen `mode` on `coords` of the active unit and enables it.
fn texgen(gl: &mut dyn Gl, coords: &[GLenum], mode: GLenum) {
    for &c in coords {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, mode as i32);
        let cap = match c {
            GL_S => GL_TEXTURE_GEN_S,
            GL_T => GL_TEXTURE_GEN_T,
            GL_R => GL_TEXTURE_GEN_R,
            _ => GL_TEXTURE_GEN_Q,
        };
        gl.enable(cap);
    }
}

fn texgen_off(gl: &mut dyn Gl) {
    for cap in [
        GL_TEXTURE_GEN_S,
        GL_TEXTURE_GEN_T,
        GL_TEXTURE_GEN_R,
        GL_TEXTURE_GEN_Q,
    ] {
        gl.disable(cap);
    }
}

fn perspective(gl: &mut dyn Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.6, 0.6, -0.6, 0.6, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

/// Planes (object and eye) for S, T, R, Q; eye planes under a rotated modelview.
fn planes(gl: &mut dyn Gl) {
    gl.push_matrix();
    gl.rotatef(15.0, 0.0, 0.0, 1.0);
    for (c, o, e) in [
        (GL_S, [0.6, 0.2, 0.0, 0.5], [0.5, 0.0, 0.3, 0.2]),
        (GL_T, [0.0, 0.5, 0.6, 0.5], [0.1, 0.6, 0.0, 0.3]),
        (GL_R, [0.2, 0.1, 0.3, 0.0], [0.0, 0.2, 0.1, 0.4]),
        (GL_Q, [0.1, 0.0, 0.2, 1.0], [0.05, 0.1, -0.1, 1.2]),
    ] {
        gl.tex_genfv(c, GL_OBJECT_PLANE, &o);
        gl.tex_genfv(c, GL_EYE_PLANE, &e);
    }
    gl.pop_matrix();
}

/// One case of [`texgen_sphere_lit`] or [`texgen_plane`]: unit 0 (2D) and unit 1 (cube map)
/// settings, MODULATE on both.
#[derive(Clone, Copy)]
enum Gen {
    /// Unit 0, S and T (and R, Q where given) in the mode.
    Flat(GLenum, bool),
    /// Unit 1 cube map with S, T, R in the mode.
    Cube(GLenum),
}

fn draw_cases(gl: &mut dyn Gl, cases: &[Gen], object: fn(&mut dyn Gl)) {
    texgen_textures(gl);
    perspective(gl);
    gl.enable(GL_DEPTH_TEST);
    lighting_on(gl);
    planes(gl);
    for (i, &case) in cases.iter().enumerate() {
        gl.viewport((i % 3) as i32 * 42 + 1, (i / 3) as i32 * 42 + 1, 42, 42);
        gl.active_texture(GL_TEXTURE0);
        gl.disable(GL_TEXTURE_2D);
        texgen_off(gl);
        gl.active_texture(GL_TEXTURE1);
        gl.disable(GL_TEXTURE_CUBE_MAP);
        texgen_off(gl);
        match case {
            Gen::Flat(mode, strq) => {
                gl.active_texture(GL_TEXTURE0);
                gl.enable(GL_TEXTURE_2D);
                gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
                if strq {
                    texgen(gl, &[GL_S, GL_T, GL_R, GL_Q], mode);
                } else {
                    texgen(gl, &[GL_S, GL_T], mode);
                }
            }
            Gen::Cube(mode) => {
                gl.active_texture(GL_TEXTURE1);
                gl.enable(GL_TEXTURE_CUBE_MAP);
                gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
                texgen(gl, &[GL_S, GL_T, GL_R], mode);
            }
        }
        gl.active_texture(GL_TEXTURE0);
        gl.load_identity();
        object(gl);
    }
}

fn lit_sphere(gl: &mut dyn Gl) {
    gl.translatef(0.0, 0.0, -3.0);
    gl.rotatef(30.0, 1.0, 1.0, 0.0);
    sphere(gl, 14, 18);
}

/// Every texgen mode on a lit, tessellated sphere: sphere map, object linear (S, T and
/// projective S, T, R, Q), eye linear (likewise), reflection and normal map into a cube map.
fn texgen_sphere_lit(gl: &mut dyn Gl) {
    draw_cases(
        gl,
        &[
            Gen::Flat(GL_SPHERE_MAP, false),
            Gen::Flat(GL_OBJECT_LINEAR, false),
            Gen::Flat(GL_OBJECT_LINEAR, true),
            Gen::Flat(GL_EYE_LINEAR, false),
            Gen::Flat(GL_EYE_LINEAR, true),
            Gen::Cube(GL_REFLECTION_MAP),
            Gen::Cube(GL_NORMAL_MAP),
        ],
        lit_sphere,
    );
}

/// A lit plane in perspective, tessellated as triangle strips, normal slightly tilted per
/// vertex so the sphere and reflection maps vary across it.
fn lit_plane(gl: &mut dyn Gl) {
    gl.translatef(0.0, -0.2, -2.5);
    gl.rotatef(-60.0, 1.0, 0.0, 0.0);
    for i in 0..8 {
        gl.begin(GL_TRIANGLE_STRIP);
        for j in 0..=8 {
            for y in [i + 1, i] {
                let (x, yy) = (j as f32 / 4.0 - 1.0, y as f32 / 4.0 - 1.0);
                gl.normal_3f(0.3 * x, 0.3 * yy, 1.0);
                gl.vertex_3f(x, yy, 0.0);
            }
        }
        gl.end();
    }
}

fn texgen_plane(gl: &mut dyn Gl) {
    draw_cases(
        gl,
        &[
            Gen::Flat(GL_SPHERE_MAP, false),
            Gen::Flat(GL_OBJECT_LINEAR, false),
            Gen::Flat(GL_OBJECT_LINEAR, true),
            Gen::Flat(GL_EYE_LINEAR, false),
            Gen::Flat(GL_EYE_LINEAR, true),
            Gen::Cube(GL_REFLECTION_MAP),
            Gen::Cube(GL_NORMAL_MAP),
        ],
        lit_plane,
    );
}

// ---------------------------------------------------------------------------------------------
// Lighting, packed as 4x4 spheres of 32x32 pixels.

fn lit_grid_setup(gl: &mut dyn Gl) {
    clear(gl);
    perspective(gl);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.8, 0.6, 0.3, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.6, 0.6, 0.6, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0);
    gl.light_modelfv(GL_LIGHT_MODEL_AMBIENT, &[0.1, 0.1, 0.1, 1.0]);
}

fn cell(gl: &mut dyn Gl, i: usize) {
    gl.viewport((i % 4) as i32 * 32, (i / 4) as i32 * 32, 32, 32);
    gl.load_identity();
}

/// Spot lights: cut-offs 10, 25, 45 and 90 degrees x exponents 0, 2, 16 and 128, the light at
/// the eye pointing slightly off the sphere's centre.
fn lit_spots(gl: &mut dyn Gl) {
    lit_grid_setup(gl);
    let mut i = 0;
    for cutoff in [10.0, 25.0, 45.0, 90.0] {
        for exponent in [0.0, 2.0, 16.0, 128.0] {
            cell(gl, i);
            gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 0.2, 0.0, 1.0]);
            gl.lightfv(GL_LIGHT0, GL_SPOT_DIRECTION, &[-0.05, -0.03, -1.0]);
            gl.lightf(GL_LIGHT0, GL_SPOT_CUTOFF, cutoff);
            gl.lightf(GL_LIGHT0, GL_SPOT_EXPONENT, exponent);
            gl.translatef(0.0, 0.0, -3.0);
            sphere(gl, 16, 20);
            i += 1;
        }
    }
}

/// Light models and light kinds: directional, positional with constant / linear / quadratic
/// attenuation, local viewer on and off, separate specular on and off, shininess 0 and 128,
/// two lights of different colours, and a spot with cut-off 180 (an ordinary point light).
fn lit_models(gl: &mut dyn Gl) {
    lit_grid_setup(gl);
    for i in 0..16 {
        cell(gl, i);
        let local = i & 1 != 0;
        let separate = i & 2 != 0;
        gl.light_modeli(GL_LIGHT_MODEL_LOCAL_VIEWER, local as i32);
        gl.light_modeli(
            GL_LIGHT_MODEL_COLOR_CONTROL,
            if separate {
                GL_SEPARATE_SPECULAR_COLOR
            } else {
                GL_SINGLE_COLOR
            } as i32,
        );
        let kind = i / 4;
        let (pos, att) = match kind {
            0 => ([1.0, 1.0, 1.0, 0.0], [1.0, 0.0, 0.0]),
            1 => ([-1.0, 1.0, -1.0, 1.0], [0.5, 0.3, 0.0]),
            2 => ([1.0, -0.5, -1.5, 1.0], [0.2, 0.0, 0.3]),
            _ => ([0.0, 1.5, -2.0, 1.0], [0.3, 0.2, 0.1]),
        };
        gl.lightfv(GL_LIGHT0, GL_POSITION, &pos);
        gl.lightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, att[0]);
        gl.lightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, att[1]);
        gl.lightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, att[2]);
        gl.lightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0);
        // Shininess 0 only under the directional light: with an attenuated (positional) light
        // Mesa's fixed-function vertex program overwrites the exponent with n . VP (its
        // `material_shininess_is_zero` path writes the DP3 to every component of `dots`), so
        // its specular term is (n . VP)^(n . VP) instead of 1 (TOLERANCE.md); the
        // specification's value is tested in tests/cascade_extremes.rs.
        let shininess = match (i / 2) % 4 {
            0 => 24.0,
            1 if kind == 0 => 0.0,
            1 => 64.0,
            2 => 128.0,
            _ => 5.0,
        };
        gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
        if kind == 3 {
            gl.enable(GL_LIGHT1);
            gl.lightfv(GL_LIGHT1, GL_DIFFUSE, &[0.1, 0.6, 0.9, 1.0]);
            gl.lightfv(GL_LIGHT1, GL_SPECULAR, &[0.9, 0.3, 0.1, 1.0]);
            gl.lightfv(GL_LIGHT1, GL_POSITION, &[-1.0, -0.3, 0.5, 0.0]);
        }
        gl.translatef(0.0, 0.0, -3.0);
        sphere(gl, 12, 16);
    }
}

/// The far half of an open cylinder, two-sided lighting: back faces (inside) face the viewer,
/// per-vertex colours that vary around it.
fn half_cylinder(gl: &mut dyn Gl) {
    gl.translatef(0.0, 0.0, -3.5);
    gl.rotatef(25.0, 1.0, 0.0, 0.0);
    gl.begin(GL_TRIANGLE_STRIP);
    for j in 0..=16 {
        let a = std::f32::consts::PI * j as f32 / 16.0;
        gl.color_4f(
            0.2 + 0.7 * (j as f32 / 16.0),
            0.8,
            0.9 - 0.05 * j as f32,
            1.0,
        );
        gl.normal_3f(a.cos(), 0.0, -a.sin());
        gl.vertex_3f(a.cos(), -0.6, -a.sin());
        gl.vertex_3f(a.cos(), 0.6, -a.sin());
    }
    gl.end();
}

/// GL_COLOR_MATERIAL on each face (FRONT, BACK, FRONT_AND_BACK) x each mode (EMISSION,
/// AMBIENT, DIFFUSE, SPECULAR, AMBIENT_AND_DIFFUSE), two-sided with back faces visible, and a
/// sixteenth cell with two-sided lighting, separate specular and no colour material.
fn lit_color_material(gl: &mut dyn Gl) {
    lit_grid_setup(gl);
    gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    gl.materialfv(GL_BACK, GL_DIFFUSE, &[0.2, 0.3, 0.9, 1.0]);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.0, 0.5, 1.0, 0.0]);
    gl.enable(GL_LIGHT1);
    gl.lightfv(GL_LIGHT1, GL_DIFFUSE, &[0.0, 0.8, 0.2, 1.0]);
    gl.lightfv(GL_LIGHT1, GL_POSITION, &[0.0, 0.0, -1.0, 0.0]);
    let mut i = 0;
    for face in [GL_FRONT, GL_BACK, GL_FRONT_AND_BACK] {
        for mode in [
            GL_EMISSION,
            GL_AMBIENT,
            GL_DIFFUSE,
            GL_SPECULAR,
            GL_AMBIENT_AND_DIFFUSE,
        ] {
            cell(gl, i);
            // Reset what an earlier cell's colour material wrote.
            gl.disable(GL_COLOR_MATERIAL);
            gl.materialfv(GL_FRONT_AND_BACK, GL_EMISSION, &[0.0, 0.0, 0.0, 1.0]);
            gl.materialfv(GL_FRONT_AND_BACK, GL_AMBIENT, &[0.2, 0.2, 0.2, 1.0]);
            gl.materialfv(GL_FRONT, GL_DIFFUSE, &[0.8, 0.6, 0.3, 1.0]);
            gl.materialfv(GL_BACK, GL_DIFFUSE, &[0.2, 0.3, 0.9, 1.0]);
            gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.6, 0.6, 0.6, 1.0]);
            gl.color_material(face, mode);
            gl.enable(GL_COLOR_MATERIAL);
            if i % 2 == 0 {
                half_cylinder(gl);
            } else {
                gl.translatef(0.0, 0.0, -3.0);
                gl.rotatef(20.0 * i as f32, 0.0, 1.0, 0.0);
                gl.begin(GL_TRIANGLES);
                gl.end();
                sphere_coloured(gl);
            }
            i += 1;
        }
    }
    cell(gl, 15);
    gl.disable(GL_COLOR_MATERIAL);
    gl.light_modeli(
        GL_LIGHT_MODEL_COLOR_CONTROL,
        GL_SEPARATE_SPECULAR_COLOR as i32,
    );
    half_cylinder(gl);
}

/// A sphere whose per-vertex colour varies with position (for colour material).
fn sphere_coloured(gl: &mut dyn Gl) {
    use std::f32::consts::PI;
    let (stacks, slices) = (10, 14);
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
                gl.color_4f(0.5 + 0.5 * x, 0.5 + 0.5 * y, 0.5 + 0.5 * z, 1.0);
                gl.normal_3f(x, y, z);
                gl.vertex_3f(x, y, z);
            }
        }
        gl.end();
    }
}

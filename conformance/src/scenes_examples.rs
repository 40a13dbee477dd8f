//! The scenes of the teaching examples (`examples/*.rs`, run with
//! `cargo run --release -p tilegl-conformance --example NAME`): classic OpenGL 1.x
//! fixed-function techniques (Haeberli & Segal, "Texture mapping as a fundamental drawing
//! primitive", 1993; McReynolds & Blythe, "Advanced Graphics Programming Using OpenGL";
//! Akenine-Möller et al., "Real-Time Rendering"). Each is a differential scene like the others,
//! so `tests/differential_examples.rs` checks it against Mesa, and each marks its intermediate
//! stages with [`crate::example_support`]'s `snap_*` calls (no-ops outside the examples).
//!
//! Geometry whose vertex colours are not affine in position (lighting, per-vertex shading) is
//! drawn as explicit triangles, never `GL_QUADS`, so the diagonal a quad is split along (left
//! open by GL) does not matter.

use crate::compare::Scene;
use crate::example_support::{self, snap_color, snap_depth, snap_stencil, snap_texture, unit_on};
use crate::prng::XorShift;
use crate::tolerance::{Tolerance, DIFFERENTIAL};
use tilegl::enums::*;
use tilegl::Gl;

const fn ex(name: &'static str, draw: fn(&mut dyn Gl), w: i32, h: i32, tol: Tolerance) -> Scene {
    Scene {
        name,
        width: w,
        height: h,
        draw,
        tolerance: tol,
    }
}

/// The mipmapping scenes' tolerances: channel threshold 24 and the bad-pixel share llvmpipe and
/// softpipe show at that threshold (`--bin calibrate`), set when tilegl still took λ per pixel;
/// with λ per 2x2 quad (as Mesa) the level-blend weights agree to within 10/255 and a few
/// level switches remain; whole-level or whole-texel errors exceed 24. Reasoning and figures in
/// `conformance/TOLERANCE.md` ("Example scenes").
const MIP_FILTERS: Tolerance = Tolerance {
    channel: 24,
    max_bad_share: 0.00537,
};
const MIP_LEVELS: Tolerance = Tolerance {
    channel: 24,
    max_bad_share: 0.00146,
};

/// `ex_magnify_anisotropic`: the one documented exception to "no looser than llvmpipe against
/// softpipe". Three panels (NEAREST and LINEAR magnification, trilinear) agree with Mesa; the
/// anisotropic panel used to differ: EXT_texture_filter_anisotropic leaves the footprint
/// filter to the implementation, and tilegl averaged up to 16 trilinear probes along the
/// longer axis (2.99 % of the pixels off by more than 24, all in that panel; the allowance is
/// 3.5 %). Since tilegl filters as Mesa does (the elliptical weighted average of
/// `BoundTexture::sample_ewa`) the whole scene is 0 % off by more than 24 (max 7), so the
/// allowance could return to the normal rule (left to the tolerance owners). That panel is checked instead against a 4x4-supersampled rendering
/// (`conformance/tests/differential_examples.rs`
/// `anisotropic_panel_is_closer_to_the_supersampled_plane_than_trilinear`).
const MAGNIFY_ANISOTROPIC: Tolerance = Tolerance {
    channel: 24,
    max_bad_share: 0.035,
};

/// The example scenes, in the order of the examples.
pub const EXAMPLE_SCENES: &[Scene] = &[
    ex(
        "ex_mipmap_filters",
        ex_mipmap_filters,
        256,
        256,
        MIP_FILTERS,
    ),
    ex("ex_mipmap_levels", ex_mipmap_levels, 128, 128, MIP_LEVELS),
    ex(
        "ex_magnify_anisotropic",
        ex_magnify_anisotropic,
        256,
        256,
        MAGNIFY_ANISOTROPIC,
    ),
    ex("ex_wrap_modes", ex_wrap_modes, 320, 64, DIFFERENTIAL),
    ex(
        "ex_dxt_compression",
        ex_dxt_compression,
        384,
        128,
        DIFFERENTIAL,
    ),
    ex(
        "ex_lightmap_multitexture",
        ex_lightmap_multitexture,
        128,
        128,
        DIFFERENTIAL,
    ),
    ex(
        "ex_lightmap_multipass",
        ex_lightmap_multipass,
        128,
        128,
        DIFFERENTIAL,
    ),
    ex("ex_gloss_map", ex_gloss_map, 128, 128, DIFFERENTIAL),
    ex("ex_sphere_map", ex_sphere_map, 128, 128, DIFFERENTIAL),
    ex("ex_cube_map", ex_cube_map, 128, 128, DIFFERENTIAL),
    ex(
        "ex_cube_map_dynamic",
        ex_cube_map_dynamic,
        128,
        128,
        DIFFERENTIAL,
    ),
    ex("ex_emboss_bump", ex_emboss_bump, 128, 128, DIFFERENTIAL),
    ex("ex_dot3_bump", ex_dot3_bump, 128, 128, DIFFERENTIAL),
    ex(
        "ex_projective_texture",
        ex_projective_texture,
        128,
        128,
        DIFFERENTIAL,
    ),
    ex("ex_shadow_map", ex_shadow_map, 128, 128, DIFFERENTIAL),
    ex(
        "ex_shadow_map_alpha_test",
        ex_shadow_map_alpha_test,
        128,
        128,
        DIFFERENTIAL,
    ),
    ex("ex_contour", ex_contour, 128, 128, DIFFERENTIAL),
    ex("ex_volume_3d", ex_volume_3d, 128, 128, DIFFERENTIAL),
    ex("ex_text", ex_text, 256, 128, DIFFERENTIAL),
    ex("ex_cross_tree", ex_cross_tree, 128, 128, DIFFERENTIAL),
    ex("ex_decal", ex_decal, 128, 128, DIFFERENTIAL),
    ex("ex_fog_terrain", ex_fog_terrain, 384, 128, DIFFERENTIAL),
    ex(
        "ex_planar_reflection",
        ex_planar_reflection,
        128,
        128,
        DIFFERENTIAL,
    ),
    ex("ex_hsv_lookup", ex_hsv_lookup, 128, 128, DIFFERENTIAL),
];

// ---------------------------------------------------------------------------------------------
// Helpers: matrices, textures, geometry.

pub(crate) type V3 = [f32; 3];

pub(crate) fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub(crate) fn dot(a: V3, b: V3) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn norm(a: V3) -> V3 {
    let l = dot(a, a).sqrt().max(1e-12);
    [a[0] / l, a[1] / l, a[2] / l]
}

/// `gluLookAt`: multiplies the current matrix by the viewing transform.
pub(crate) fn look_at(gl: &mut dyn Gl, eye: V3, center: V3, up: V3) {
    let f = norm(sub(center, eye));
    let s = norm(cross(f, up));
    let u = cross(s, f);
    gl.mult_matrixf(&[
        s[0], u[0], -f[0], 0.0, s[1], u[1], -f[1], 0.0, s[2], u[2], -f[2], 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);
    gl.translatef(-eye[0], -eye[1], -eye[2]);
}

/// `gluPerspective`: multiplies the current matrix by a perspective projection.
pub(crate) fn perspective(gl: &mut dyn Gl, fovy: f64, aspect: f64, near: f64, far: f64) {
    let top = near * (fovy.to_radians() / 2.0).tan();
    gl.frustum(-top * aspect, top * aspect, -top, top, near, far);
}

/// Projection and modelview for a camera at `eye` looking at `center` (y up).
pub(crate) fn camera(gl: &mut dyn Gl, fovy: f64, aspect: f64, eye: V3, center: V3) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    perspective(gl, fovy, aspect, 0.5, 30.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    look_at(gl, eye, center, [0.0, 1.0, 0.0]);
}

pub(crate) fn clear_to(gl: &mut dyn Gl, c: [f32; 3]) {
    gl.clear_color(c[0], c[1], c[2], 1.0);
    gl.clear_depth(1.0);
    gl.clear_stencil(0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

/// A new 2D texture object with `GL_GENERATE_MIPMAP` on (so every level exists whatever the
/// filter), bound to the active unit. `format` is also the internal format.
pub(crate) fn tex2d(gl: &mut dyn Gl, w: i32, h: i32, format: GLenum, px: &[u8]) -> u32 {
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_2D, name[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        format as i32,
        w,
        h,
        0,
        format,
        GL_UNSIGNED_BYTE,
        Some(px),
    );
    name[0]
}

/// Filters and wrap mode (S, T and R) of the texture bound to `target`.
pub(crate) fn sampling(gl: &mut dyn Gl, target: GLenum, min: GLenum, mag: GLenum, wrap: GLenum) {
    gl.tex_parameteri(target, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_parameteri(target, GL_TEXTURE_MAG_FILTER, mag as i32);
    gl.tex_parameteri(target, GL_TEXTURE_WRAP_S, wrap as i32);
    gl.tex_parameteri(target, GL_TEXTURE_WRAP_T, wrap as i32);
    gl.tex_parameteri(target, GL_TEXTURE_WRAP_R, wrap as i32);
}

pub(crate) fn to_u8(v: f32) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// An RGB(A) picture from a function of the texel centre (u, v in 0..1).
pub(crate) fn paint(
    w: usize,
    h: usize,
    channels: usize,
    f: impl Fn(f32, f32) -> [f32; 4],
) -> Vec<u8> {
    let mut p = Vec::with_capacity(w * h * channels);
    for y in 0..h {
        for x in 0..w {
            let c = f((x as f32 + 0.5) / w as f32, (y as f32 + 0.5) / h as f32);
            p.extend(c[..channels].iter().map(|&v| to_u8(v)));
        }
    }
    p
}

/// Bricks: 4 rows of 2 bricks per tile, mortar lines, a per-brick tint.
pub(crate) fn bricks(size: usize) -> Vec<u8> {
    paint(size, size, 3, |u, v| {
        let row = (v * 4.0).floor();
        let uu = u * 2.0 + if row as i32 % 2 == 1 { 0.5 } else { 0.0 };
        let (fu, fv) = (uu.fract(), (v * 4.0).fract());
        if fu < 0.06 || fv < 0.12 {
            return [0.78, 0.76, 0.7, 1.0];
        }
        let k = ((uu.floor() as i32 * 7 + row as i32 * 13) % 5) as f32 / 5.0;
        [0.62 + 0.15 * k, 0.25 + 0.06 * k, 0.18, 1.0]
    })
}

/// Round bumps on a 4x4 grid per tile: height 0..1 (a hemisphere profile).
fn bump_height(u: f32, v: f32) -> f32 {
    let (fu, fv) = ((u * 4.0).fract() - 0.5, (v * 4.0).fract() - 0.5);
    let r2 = (fu * fu + fv * fv) / (0.38 * 0.38);
    (1.0 - r2).max(0.0).sqrt()
}

/// A triangulated grid over (u, v) in [0, 1]^2: `n` x `n` cells as triangle strips; `vert`
/// issues each vertex's attributes and position.
pub(crate) fn grid(gl: &mut dyn Gl, n: usize, vert: &dyn Fn(&mut dyn Gl, f32, f32)) {
    for j in 0..n {
        gl.begin(GL_TRIANGLE_STRIP);
        for i in 0..=n {
            let u = i as f32 / n as f32;
            vert(gl, u, (j + 1) as f32 / n as f32);
            vert(gl, u, j as f32 / n as f32);
        }
        gl.end();
    }
}

/// A torus around the y axis with normals (and 2D texture coordinates u, v).
pub(crate) fn torus(gl: &mut dyn Gl, big: f32, small: f32, nu: usize, nv: usize) {
    use std::f32::consts::TAU;
    for i in 0..nu {
        gl.begin(GL_TRIANGLE_STRIP);
        for j in 0..=nv {
            for k in [i + 1, i] {
                let (a, b) = (TAU * k as f32 / nu as f32, TAU * j as f32 / nv as f32);
                let n = [b.cos() * a.cos(), b.sin(), b.cos() * a.sin()];
                gl.normal_3f(n[0], n[1], n[2]);
                gl.tex_coord_2f(k as f32 / nu as f32 * 4.0, j as f32 / nv as f32);
                let r = big + small * b.cos();
                gl.vertex_3f(r * a.cos(), small * b.sin(), r * a.sin());
            }
        }
        gl.end();
    }
}

/// An axis-aligned box as triangles with face normals.
pub(crate) fn cuboid(gl: &mut dyn Gl, c: V3, h: V3) {
    let faces: [(V3, V3, V3); 6] = [
        ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
        ([-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]),
        ([0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]),
        ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
        ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]),
    ];
    gl.begin(GL_TRIANGLES);
    for (n, a, b) in faces {
        gl.normal_3f(n[0], n[1], n[2]);
        let p = |s: f32, t: f32| -> V3 {
            let mut v = [0.0; 3];
            for k in 0..3 {
                v[k] = c[k] + h[k] * (n[k] + s * a[k] + t * b[k]);
            }
            v
        };
        for (s, t) in [
            (-1.0, -1.0),
            (1.0, -1.0),
            (1.0, 1.0),
            (-1.0, -1.0),
            (1.0, 1.0),
            (-1.0, 1.0),
        ] {
            let v = p(s, t);
            gl.tex_coord_2f(0.5 + 0.5 * s, 0.5 + 0.5 * t);
            gl.vertex_3f(v[0], v[1], v[2]);
        }
    }
    gl.end();
}

/// Light 0 at `pos` (w = 0: directional), white, with a default grey material.
pub(crate) fn lamp(gl: &mut dyn Gl, pos: [f32; 4]) {
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &pos);
    gl.light_modelfv(GL_LIGHT_MODEL_AMBIENT, &[0.25, 0.25, 0.25, 1.0]);
}

pub(crate) fn material(gl: &mut dyn Gl, diffuse: [f32; 4], specular: f32, shininess: f32) {
    gl.materialfv(GL_FRONT_AND_BACK, GL_AMBIENT, &diffuse);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &diffuse);
    gl.materialfv(
        GL_FRONT_AND_BACK,
        GL_SPECULAR,
        &[specular, specular, specular, 1.0],
    );
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
}

/// A textured quad in the plane y = 0 over x in [x0, x1], z in [z0, z1] (z1 nearer), with
/// texture coordinates (0, 0)..(s, t) on each listed unit. Texture coordinates are affine in
/// position, so any split of the quad gives the same picture.
pub(crate) fn floor_quad(gl: &mut dyn Gl, x: [f32; 2], z: [f32; 2], st: &[(GLenum, f32, f32)]) {
    gl.normal_3f(0.0, 1.0, 0.0);
    gl.begin(GL_QUADS);
    for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        for &(unit, s, t) in st {
            gl.multi_tex_coord_2f(unit, u * s, v * t);
        }
        gl.vertex_3f(x[0] + u * (x[1] - x[0]), 0.0, z[1] + v * (z[0] - z[1]));
    }
    gl.end();
}

// ---------------------------------------------------------------------------------------------
// Mipmapping.

/// A black-and-white checkerboard, 4 texels a square, with a thin red line every 16 texels.
fn fine_checker(size: usize) -> Vec<u8> {
    paint(size, size, 3, |u, v| {
        let (x, y) = ((u * size as f32) as usize, (v * size as f32) as usize);
        if x % 16 == 0 || y % 16 == 0 {
            [0.9, 0.1, 0.1, 1.0]
        } else if (x / 4 + y / 4) % 2 == 0 {
            [0.95, 0.95, 0.95, 1.0]
        } else {
            [0.05, 0.05, 0.1, 1.0]
        }
    })
}

fn receding_plane(gl: &mut dyn Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 60.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.color_3f(1.0, 1.0, 1.0);
    gl.begin(GL_QUADS);
    for (s, t, x, z) in [
        (0.0, 0.0, -3.0, -1.3),
        (3.0, 0.0, 3.0, -1.3),
        (3.0, 30.0, 3.0, -41.3),
        (0.0, 30.0, -3.0, -41.3),
    ] {
        gl.tex_coord_2f(s, t);
        gl.vertex_3f(x, -1.0, z);
    }
    gl.end();
}

/// Four filters on the same receding plane (2x2 viewports): NEAREST, LINEAR,
/// NEAREST_MIPMAP_NEAREST, LINEAR_MIPMAP_LINEAR.
fn ex_mipmap_filters(gl: &mut dyn Gl) {
    clear_to(gl, [0.3, 0.4, 0.6]);
    let px = fine_checker(64);
    tex2d(gl, 64, 64, GL_RGB, &px);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    snap_texture(gl, "texture_level0", GL_TEXTURE_2D, 0, [64, 64, 1]);
    snap_texture(gl, "texture_level2", GL_TEXTURE_2D, 2, [16, 16, 1]);
    let filters = [
        (GL_NEAREST, GL_NEAREST),
        (GL_LINEAR, GL_LINEAR),
        (GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST),
        (GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR),
    ];
    for (i, (min, mag)) in filters.into_iter().enumerate() {
        example_support::viewport(gl, (i % 2) as i32 * 128, (1 - i / 2) as i32 * 128, 128, 128);
        sampling(gl, GL_TEXTURE_2D, min, mag, GL_REPEAT);
        receding_plane(gl);
    }
}

/// Magnification and anisotropy (2x2 viewports): an 8x8 texture stretched over a close quad
/// under NEAREST (top left) and LINEAR (top right); the receding plane under
/// LINEAR_MIPMAP_LINEAR (bottom left) and the same with 16x anisotropic filtering
/// (EXT_texture_filter_anisotropic, bottom right).
fn ex_magnify_anisotropic(gl: &mut dyn Gl) {
    clear_to(gl, [0.3, 0.4, 0.6]);
    let small = paint(8, 8, 3, |u, v| {
        let (x, y) = ((u * 8.0) as i32, (v * 8.0) as i32);
        let k = ((x + y) % 2) as f32;
        [
            0.2 + 0.7 * k,
            0.3 + 0.08 * x as f32,
            0.9 - 0.1 * y as f32,
            1.0,
        ]
    });
    tex2d(gl, 8, 8, GL_RGB, &small);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    for (i, filter) in [GL_NEAREST, GL_LINEAR].into_iter().enumerate() {
        example_support::viewport(gl, i as i32 * 128, 128, 128, 128);
        sampling(gl, GL_TEXTURE_2D, filter, filter, GL_REPEAT);
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        gl.ortho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        gl.begin(GL_QUADS);
        // Slightly off the texel grid, so that both filters show their character.
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.tex_coord_2f(0.03 + u * 0.97, 0.05 + v * 0.93);
            gl.vertex_2f(u, v);
        }
        gl.end();
    }
    for (i, aniso) in [1.0f32, 16.0].into_iter().enumerate() {
        example_support::viewport(gl, i as i32 * 128, 0, 128, 128);
        receding_checker(gl, aniso);
    }
}

/// The receding checkerboard plane of the mipmapping scenes, trilinear with maximum
/// anisotropy `aniso`, drawn into the current viewport (the anisotropic panel of
/// `ex_magnify_anisotropic`; also rendered supersampled by the test that checks it).
pub fn receding_checker(gl: &mut dyn Gl, aniso: f32) {
    let px = fine_checker(64);
    tex2d(gl, 64, 64, GL_RGB, &px);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    sampling(
        gl,
        GL_TEXTURE_2D,
        GL_LINEAR_MIPMAP_LINEAR,
        GL_LINEAR,
        GL_REPEAT,
    );
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, aniso);
    receding_plane(gl);
}

/// Each mipmap level a different solid colour: the picture shows which level (and, with
/// LINEAR_MIPMAP_LINEAR, which blend of two levels) every pixel samples.
fn ex_mipmap_levels(gl: &mut dyn Gl) {
    clear_to(gl, [0.3, 0.4, 0.6]);
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_2D, name[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    const LEVEL_COLOURS: [[f32; 3]; 7] = [
        [1.0, 0.2, 0.2],
        [1.0, 0.6, 0.1],
        [1.0, 1.0, 0.2],
        [0.2, 0.9, 0.2],
        [0.2, 0.8, 1.0],
        [0.3, 0.3, 1.0],
        [0.8, 0.3, 1.0],
    ];
    for (level, c) in LEVEL_COLOURS.iter().enumerate() {
        let s = 64usize >> level;
        let px = paint(s, s, 3, |u, v| {
            // A faint checker on top of the level colour so each level still shows texels.
            let k = if ((u * 8.0) as i32 + (v * 8.0) as i32) % 2 == 0 {
                1.0
            } else {
                0.8
            };
            [c[0] * k, c[1] * k, c[2] * k, 1.0]
        });
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            level as i32,
            GL_RGB as i32,
            s as i32,
            s as i32,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            Some(&px),
        );
    }
    sampling(
        gl,
        GL_TEXTURE_2D,
        GL_LINEAR_MIPMAP_LINEAR,
        GL_LINEAR,
        GL_REPEAT,
    );
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    receding_plane(gl);
}

// ---------------------------------------------------------------------------------------------
// Wrap modes.

/// The same quad with texture coordinates -0.75..1.75 under REPEAT, CLAMP, CLAMP_TO_EDGE,
/// CLAMP_TO_BORDER and MIRRORED_REPEAT (left to right); a 4x4 texture with a green border
/// colour and LINEAR filtering, which is where CLAMP and CLAMP_TO_EDGE differ.
fn ex_wrap_modes(gl: &mut dyn Gl) {
    clear_to(gl, [0.15, 0.15, 0.2]);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 320.0, 0.0, 64.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    let px = paint(4, 4, 4, |u, v| {
        let (x, y) = ((u * 4.0) as usize, (v * 4.0) as usize);
        match (x, y) {
            (0, _) | (_, 0) => [1.0, 0.85, 0.2, 1.0],
            _ if (x + y) % 2 == 0 => [0.9, 0.2, 0.3, 1.0],
            _ => [0.2, 0.3, 0.9, 1.0],
        }
    });
    tex2d(gl, 4, 4, GL_RGBA, &px);
    gl.tex_parameterfv(
        GL_TEXTURE_2D,
        GL_TEXTURE_BORDER_COLOR,
        &[0.1, 0.7, 0.2, 1.0],
    );
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    let modes = [
        GL_REPEAT,
        GL_CLAMP,
        GL_CLAMP_TO_EDGE,
        GL_CLAMP_TO_BORDER,
        GL_MIRRORED_REPEAT,
    ];
    for (i, mode) in modes.into_iter().enumerate() {
        sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, mode);
        let x0 = 64.0 * i as f32 + 4.0;
        gl.begin(GL_QUADS);
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.tex_coord_2f(-0.75 + 2.5 * u, -0.75 + 2.5 * v);
            gl.vertex_2f(x0 + 56.0 * u, 4.0 + 56.0 * v);
        }
        gl.end();
    }
}

// ---------------------------------------------------------------------------------------------
// Light maps.

/// A light map: three coloured pools of light on a dim ambient level.
fn light_map(size: usize) -> Vec<u8> {
    paint(size, size, 3, |u, v| {
        let spots = [
            (0.3, 0.3, [1.0, 0.8, 0.5]),
            (0.72, 0.6, [0.5, 0.7, 1.0]),
            (0.35, 0.8, [0.8, 1.0, 0.6]),
        ];
        let mut c = [0.18f32; 3];
        for (x, y, col) in spots {
            let d2 = (u - x) * (u - x) + (v - y) * (v - y);
            let k = (-d2 / 0.02).exp();
            for i in 0..3 {
                c[i] += col[i] * k;
            }
        }
        [c[0], c[1], c[2], 1.0]
    })
}

fn lightmap_camera(gl: &mut dyn Gl) {
    clear_to(gl, [0.05, 0.05, 0.08]);
    camera(gl, 50.0, 1.0, [0.0, 2.4, 2.2], [0.0, 0.0, -0.8]);
    gl.enable(GL_DEPTH_TEST);
}

const LM_X: [f32; 2] = [-2.0, 2.0];
const LM_Z: [f32; 2] = [-3.5, 1.0];

/// Light map by multitexture: unit 0 the bricks (repeated 4x), unit 1 the light map (once over
/// the floor), both MODULATE: colour = bricks x light.
fn ex_lightmap_multitexture(gl: &mut dyn Gl) {
    lightmap_camera(gl);
    let b = bricks(64);
    tex2d(gl, 64, 64, GL_RGB, &b);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    snap_texture(gl, "base_texture", GL_TEXTURE_2D, 0, [64, 64, 1]);
    gl.active_texture(GL_TEXTURE1);
    let l = light_map(32);
    tex2d(gl, 32, 32, GL_RGB, &l);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    if unit_on(1) {
        gl.enable(GL_TEXTURE_2D);
    }
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    snap_texture(gl, "light_map", GL_TEXTURE_2D, 0, [32, 32, 1]);
    gl.active_texture(GL_TEXTURE0);
    gl.color_3f(1.0, 1.0, 1.0);
    floor_quad(
        gl,
        LM_X,
        LM_Z,
        &[(GL_TEXTURE0, 4.0, 4.0), (GL_TEXTURE1, 1.0, 1.0)],
    );
}

/// The same picture in two passes on one unit: the bricks, then the light map multiplied into
/// the framebuffer with glBlendFunc(GL_DST_COLOR, GL_ZERO) (dst = src x dst) on the same
/// geometry (depth test GL_LEQUAL: the second pass's fragments have the same depths).
fn ex_lightmap_multipass(gl: &mut dyn Gl) {
    lightmap_camera(gl);
    let b = bricks(64);
    let bricks_tex = tex2d(gl, 64, 64, GL_RGB, &b);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    let l = light_map(32);
    let light_tex = tex2d(gl, 32, 32, GL_RGB, &l);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.bind_texture(GL_TEXTURE_2D, bricks_tex);
    floor_quad(gl, LM_X, LM_Z, &[(GL_TEXTURE0, 4.0, 4.0)]);
    snap_color(gl, "pass1_bricks", 128, 128);
    gl.bind_texture(GL_TEXTURE_2D, light_tex);
    gl.depth_func(GL_LEQUAL);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_DST_COLOR, GL_ZERO);
    floor_quad(gl, LM_X, LM_Z, &[(GL_TEXTURE0, 1.0, 1.0)]);
}

// ---------------------------------------------------------------------------------------------
// Gloss map.

/// Tiles: polished metal (gloss 1) and rough stone (gloss 0.08).
fn metal_tile(u: f32, v: f32) -> bool {
    ((u * 4.0) as i32 + (v * 4.0) as i32) % 2 == 0
}

fn gloss_plane(gl: &mut dyn Gl) {
    grid(gl, 24, &|gl, u, v| {
        gl.normal_3f(0.0, 0.0, 1.0);
        gl.tex_coord_2f(u, v);
        gl.vertex_3f(-1.5 + 3.0 * u, -1.5 + 3.0 * v, 0.0);
    });
}

/// Gloss map in two passes: pass 1 the diffuse-lit base texture; pass 2 only the specular term
/// of the lighting (material ambient and diffuse black), modulated by the gloss map and added
/// with glBlendFunc(GL_ONE, GL_ONE): highlights appear only on the shiny tiles.
fn ex_gloss_map(gl: &mut dyn Gl) {
    clear_to(gl, [0.08, 0.08, 0.1]);
    camera(gl, 45.0, 1.0, [0.0, -2.6, 2.8], [0.0, 0.0, 0.0]);
    gl.enable(GL_DEPTH_TEST);
    lamp(gl, [0.3, 0.2, 1.0, 1.0]);
    gl.light_modeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    let base = paint(64, 64, 3, |u, v| {
        if metal_tile(u, v) {
            [0.55, 0.6, 0.7, 1.0]
        } else {
            let n = ((u * 97.0).sin() * (v * 113.0).sin()).abs();
            [0.55 + 0.2 * n, 0.4 + 0.1 * n, 0.25, 1.0]
        }
    });
    let gloss = paint(64, 64, 1, |u, v| {
        let g = if metal_tile(u, v) { 1.0 } else { 0.08 };
        [g, g, g, 1.0]
    });
    let base_tex = tex2d(gl, 64, 64, GL_RGB, &base);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    let gloss_tex = tex2d(gl, 64, 64, GL_LUMINANCE, &gloss);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    snap_texture(gl, "gloss_map", GL_TEXTURE_2D, 0, [64, 64, 1]);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    // Pass 1: ambient + diffuse, no specular.
    gl.bind_texture(GL_TEXTURE_2D, base_tex);
    material(gl, [1.0, 1.0, 1.0, 1.0], 0.0, 1.0);
    gloss_plane(gl);
    snap_color(gl, "pass1_diffuse", 128, 128);
    // Pass 2: specular only, times the gloss map, added.
    gl.bind_texture(GL_TEXTURE_2D, gloss_tex);
    gl.light_modelfv(GL_LIGHT_MODEL_AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.0, 0.0, 0.0, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[1.0, 1.0, 0.9, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0);
    gl.depth_func(GL_LEQUAL);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_ONE, GL_ONE);
    gloss_plane(gl);
}

// ---------------------------------------------------------------------------------------------
// Environment maps.

/// The environment seen in direction `d`: a sky gradient with a sun above the horizon, a
/// checkered ground below, and a red marker on +x and a blue one on -z to show orientation.
fn environment(d: V3) -> [f32; 4] {
    let d = norm(d);
    if dot(d, norm([1.0, 0.15, 0.0])) > 0.985 {
        return [0.9, 0.1, 0.1, 1.0];
    }
    if dot(d, norm([0.0, 0.15, -1.0])) > 0.985 {
        return [0.1, 0.2, 0.95, 1.0];
    }
    if d[1] >= 0.0 {
        if dot(d, norm([-0.5, 0.6, -0.6])) > 0.97 {
            return [1.0, 0.95, 0.7, 1.0];
        }
        let k = d[1].sqrt();
        [0.85 - 0.6 * k, 0.9 - 0.45 * k, 1.0 - 0.1 * k, 1.0]
    } else {
        let (x, z) = (d[0] / -d[1], d[2] / -d[1]);
        let c = if (x.floor() as i32 + z.floor() as i32) % 2 == 0 {
            [0.45, 0.3, 0.2]
        } else {
            [0.75, 0.6, 0.4]
        };
        let f = (-d[1] * 4.0).min(1.0);
        [
            c[0] * f + 0.85 * (1.0 - f),
            c[1] * f + 0.9 * (1.0 - f),
            c[2] * f + 1.0 * (1.0 - f),
            1.0,
        ]
    }
}

fn env_object(gl: &mut dyn Gl) {
    clear_to(gl, [0.2, 0.2, 0.25]);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    perspective(gl, 40.0, 1.0, 1.0, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.enable(GL_DEPTH_TEST);
    gl.translatef(0.0, 0.0, -4.0);
    gl.rotatef(55.0, 1.0, 0.0, 0.0);
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
}

/// Sphere mapping: the texture is the environment as reflected in a mirror ball seen from far
/// away; GL_SPHERE_MAP texgen computes (s, t) from the eye-space reflection vector.
fn ex_sphere_map(gl: &mut dyn Gl) {
    let px = paint(128, 128, 3, |s, t| {
        let (x, y) = (2.0 * s - 1.0, 2.0 * t - 1.0);
        let r2 = x * x + y * y;
        if r2 > 1.0 {
            return [0.0, 0.0, 0.0, 1.0];
        }
        let z = (1.0 - r2).sqrt();
        // The reflection of the view direction (0, 0, -1) about the normal (x, y, z).
        environment([2.0 * z * x, 2.0 * z * y, 2.0 * z * z - 1.0])
    });
    env_object(gl);
    tex2d(gl, 128, 128, GL_RGB, &px);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "sphere_map", GL_TEXTURE_2D, 0, [128, 128, 1]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    torus(gl, 1.0, 0.42, 40, 20);
}

/// Cube environment mapping: six faces of the environment; GL_REFLECTION_MAP texgen on s, t, r
/// gives the eye-space reflection vector, which selects the face and the texel.
fn ex_cube_map(gl: &mut dyn Gl) {
    env_object(gl);
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_CUBE_MAP, name[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    const N: usize = 64;
    // Direction of texel (sc, tc) of each face (GL 1.5 table 3.19, inverted).
    let faces: [fn(f32, f32) -> V3; 6] = [
        |s, t| [1.0, -t, -s],
        |s, t| [-1.0, -t, s],
        |s, t| [s, 1.0, t],
        |s, t| [s, -1.0, -t],
        |s, t| [s, -t, 1.0],
        |s, t| [-s, -t, -1.0],
    ];
    for (i, dir) in faces.iter().enumerate() {
        let px = paint(N, N, 3, |u, v| {
            environment(dir(2.0 * u - 1.0, 2.0 * v - 1.0))
        });
        gl.tex_image_2d(
            GL_TEXTURE_CUBE_MAP_POSITIVE_X + i as GLenum,
            0,
            GL_RGB as i32,
            N as i32,
            N as i32,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            Some(&px),
        );
    }
    sampling(
        gl,
        GL_TEXTURE_CUBE_MAP,
        GL_LINEAR,
        GL_LINEAR,
        GL_CLAMP_TO_EDGE,
    );
    for (i, face) in ["px", "nx", "py", "ny", "pz", "nz"].iter().enumerate() {
        snap_texture(
            gl,
            &format!("face_{face}"),
            GL_TEXTURE_CUBE_MAP_POSITIVE_X + i as GLenum,
            0,
            [N as i32, N as i32, 1],
        );
    }
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_CUBE_MAP);
    for c in [GL_S, GL_T, GL_R] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP as i32);
    }
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    gl.enable(GL_TEXTURE_GEN_R);
    torus(gl, 1.0, 0.42, 40, 20);
}

/// The world of the dynamic cube map: a lit checkered floor and coloured boxes in a ring.
fn dyn_world(gl: &mut dyn Gl, checker: u32) {
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.4, 1.0, 0.7, 0.0]);
    material(gl, [1.0, 1.0, 1.0, 1.0], 0.0, 1.0);
    gl.bind_texture(GL_TEXTURE_2D, checker);
    gl.enable(GL_TEXTURE_2D);
    grid(gl, 8, &|gl, u, v| {
        gl.normal_3f(0.0, 1.0, 0.0);
        gl.tex_coord_2f(6.0 * u, 6.0 * v);
        gl.vertex_3f(-4.0 + 8.0 * u, 0.0, 4.0 - 8.0 * v);
    });
    gl.disable(GL_TEXTURE_2D);
    // Boxes in a ring, leaving a gap towards the camera (+z).
    let colours = [
        [0.9, 0.2, 0.2],
        [0.9, 0.8, 0.2],
        [0.2, 0.8, 0.3],
        [0.2, 0.7, 0.9],
        [0.3, 0.3, 0.9],
        [0.8, 0.3, 0.8],
    ];
    for (k, c) in colours.iter().enumerate() {
        let a = (10.0 + 40.0 * k as f32).to_radians() + std::f32::consts::PI;
        material(gl, [c[0], c[1], c[2], 1.0], 0.0, 1.0);
        let h = 0.4 + 0.15 * k as f32;
        cuboid(gl, [2.07 * a.cos(), h, 2.07 * a.sin()], [0.3, h, 0.3]);
    }
    gl.disable(GL_LIGHTING);
}

const DYN_CENTRE: V3 = [0.0, 0.6, 0.0];
const DYN_EYE: V3 = [0.3, 1.9, 3.3];

/// A dynamic cube map: the world is rendered six times from the reflecting object's centre
/// (90-degree frustum, one view per face) and each view copied into its face with
/// glCopyTexSubImage2D; the sphere then reflects it with GL_REFLECTION_MAP texgen, the texture
/// matrix turning the eye-space reflection vector back into world space.
fn ex_cube_map_dynamic(gl: &mut dyn Gl) {
    clear_to(gl, [0.45, 0.6, 0.85]);
    gl.enable(GL_DEPTH_TEST);
    let checker_px = paint(32, 32, 3, |u, v| {
        if ((u * 8.0) as i32 + (v * 8.0) as i32) % 2 == 0 {
            [0.85, 0.85, 0.8, 1.0]
        } else {
            [0.35, 0.35, 0.4, 1.0]
        }
    });
    let checker = tex2d(gl, 32, 32, GL_RGB, &checker_px);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_CUBE_MAP, name[0]);
    const N: i32 = 64;
    for i in 0..6 {
        let face = GL_TEXTURE_CUBE_MAP_POSITIVE_X + i;
        gl.tex_image_2d(
            face,
            0,
            GL_RGB as i32,
            N,
            N,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            None,
        );
    }
    sampling(
        gl,
        GL_TEXTURE_CUBE_MAP,
        GL_LINEAR,
        GL_LINEAR,
        GL_CLAMP_TO_EDGE,
    );
    // The six views: looking along +x, -x, +y, -y, +z, -z with the "up" vectors that make
    // window coordinates match the faces' (s, t) orientation (GL 1.5 table 3.19).
    let views: [(V3, V3); 6] = [
        ([1.0, 0.0, 0.0], [0.0, -1.0, 0.0]),
        ([-1.0, 0.0, 0.0], [0.0, -1.0, 0.0]),
        ([0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
        ([0.0, -1.0, 0.0], [0.0, 0.0, -1.0]),
        ([0.0, 0.0, 1.0], [0.0, -1.0, 0.0]),
        ([0.0, 0.0, -1.0], [0.0, -1.0, 0.0]),
    ];
    gl.viewport(0, 0, N, N);
    for (i, (dir, up)) in views.into_iter().enumerate() {
        gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        perspective(gl, 90.0, 1.0, 0.1, 20.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        let c = DYN_CENTRE;
        look_at(gl, c, [c[0] + dir[0], c[1] + dir[1], c[2] + dir[2]], up);
        dyn_world(gl, checker);
        let face = GL_TEXTURE_CUBE_MAP_POSITIVE_X + i as GLenum;
        gl.bind_texture(GL_TEXTURE_CUBE_MAP, name[0]);
        gl.copy_tex_sub_image_2d(face, 0, 0, 0, 0, 0, N, N);
    }
    for (i, face) in ["px", "nx", "py", "ny", "pz", "nz"].iter().enumerate() {
        snap_texture(
            gl,
            &format!("face_{face}"),
            GL_TEXTURE_CUBE_MAP_POSITIVE_X + i as GLenum,
            0,
            [N, N, 1],
        );
    }
    // The camera's view: the world, then the mirror sphere.
    example_support::viewport(gl, 0, 0, 128, 128);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    camera(gl, 50.0, 1.0, DYN_EYE, DYN_CENTRE);
    dyn_world(gl, checker);
    // Texture matrix: the inverse of the camera's rotation (its transpose).
    let f = norm(sub(DYN_CENTRE, DYN_EYE));
    let s = norm(cross(f, [0.0, 1.0, 0.0]));
    let u = cross(s, f);
    gl.matrix_mode(GL_TEXTURE);
    gl.load_matrixf(&[
        s[0], s[1], s[2], 0.0, u[0], u[1], u[2], 0.0, -f[0], -f[1], -f[2], 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);
    gl.matrix_mode(GL_MODELVIEW);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_CUBE_MAP);
    for c in [GL_S, GL_T, GL_R] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP as i32);
    }
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    gl.enable(GL_TEXTURE_GEN_R);
    gl.enable(GL_NORMALIZE);
    gl.translatef(DYN_CENTRE[0], DYN_CENTRE[1], DYN_CENTRE[2]);
    gl.scalef(0.6, 0.6, 0.6);
    crate::scenes::sphere(gl, 24, 32);
}

// ---------------------------------------------------------------------------------------------
// Bump mapping.

const BUMP_X: [f32; 2] = [-1.3, 1.3];
const BUMP_Z: [f32; 2] = [-1.3, 1.3];

fn bump_camera(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.12]);
    camera(gl, 45.0, 1.0, [0.0, 2.6, 2.2], [0.0, 0.0, 0.0]);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_LEQUAL);
}

fn stone(size: usize) -> Vec<u8> {
    paint(size, size, 3, |u, v| {
        let n = (u * 31.0).sin() * (v * 23.0).cos() * 0.5 + 0.5;
        [0.75 + 0.1 * n, 0.7 + 0.08 * n, 0.6, 1.0]
    })
}

/// Emboss bump mapping (Real-Time Rendering; McReynolds & Blythe): the height map H drawn, the
/// same map drawn with texture coordinates shifted towards the light and subtracted
/// (glBlendEquation(GL_FUNC_REVERSE_SUBTRACT)), which leaves 0.5 + (H(p) - H(p + shift)) / 2,
/// an estimate of the slope along the light direction; then the base colour multiplied in with
/// glBlendFunc(GL_DST_COLOR, GL_SRC_COLOR) (2 x src x dst).
fn ex_emboss_bump(gl: &mut dyn Gl) {
    bump_camera(gl);
    let h = paint(64, 64, 1, |u, v| {
        let b = bump_height(u, v);
        [b, b, b, 1.0]
    });
    let height_tex = tex2d(gl, 64, 64, GL_LUMINANCE, &h);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    snap_texture(gl, "height_map", GL_TEXTURE_2D, 0, [64, 64, 1]);
    let s = stone(64);
    let base_tex = tex2d(gl, 64, 64, GL_RGB, &s);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.enable(GL_TEXTURE_2D);
    // The light direction in the plane's tangent space: s along +x, t along -z.
    let light = norm([-0.7, 0.5, -0.5]);
    let shift = 2.0 / 64.0; // two texels of the height map
    let (ds, dt) = (light[0] * shift, -light[2] * shift);
    // Pass 1: 0.5 + H/2, by GL_COMBINE INTERPOLATE(texture, constant white, primary 0.5).
    gl.bind_texture(GL_TEXTURE_2D, height_tex);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_CONSTANT as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_PRIMARY_COLOR as i32);
    // The third operand defaults to GL_SRC_ALPHA (which is 1 here): use the colour.
    gl.tex_envi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_COLOR as i32);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[1.0, 1.0, 1.0, 1.0]);
    gl.color_3f(0.5, 0.5, 0.5);
    floor_quad(gl, BUMP_X, BUMP_Z, &[(GL_TEXTURE0, 2.0, 2.0)]);
    snap_color(gl, "pass1_height", 128, 128);
    // Pass 2: subtract H(p + shift) / 2 (MODULATE by 0.5, reverse-subtract blending).
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_BLEND);
    gl.blend_equation(GL_FUNC_REVERSE_SUBTRACT);
    gl.blend_func(GL_ONE, GL_ONE);
    gl.matrix_mode(GL_TEXTURE);
    gl.translatef(ds, dt, 0.0);
    gl.matrix_mode(GL_MODELVIEW);
    floor_quad(gl, BUMP_X, BUMP_Z, &[(GL_TEXTURE0, 2.0, 2.0)]);
    snap_color(gl, "pass2_embossed", 128, 128);
    gl.matrix_mode(GL_TEXTURE);
    gl.load_identity();
    gl.matrix_mode(GL_MODELVIEW);
    // Pass 3: base colour x diffuse factor, times 2 x the embossed term.
    gl.bind_texture(GL_TEXTURE_2D, base_tex);
    gl.blend_equation(GL_FUNC_ADD);
    gl.blend_func(GL_DST_COLOR, GL_SRC_COLOR);
    let diffuse = light[1];
    gl.color_3f(diffuse, diffuse, diffuse);
    floor_quad(gl, BUMP_X, BUMP_Z, &[(GL_TEXTURE0, 1.0, 1.0)]);
}

/// The light position of the DOT3 scene.
const DOT3_LIGHT: V3 = [0.5, 0.6, -0.3];

/// DOT3 bump mapping: a normal map (tangent-space normals packed as 0.5 + n/2) on unit 0,
/// combined with the light vector carried in the primary colour by GL_COMBINE DOT3_RGB
/// (4 x ((r0-0.5)(r1-0.5) + ...) = N.L); unit 1 modulates the base texture.
fn ex_dot3_bump(gl: &mut dyn Gl) {
    bump_camera(gl);
    let nm = paint(64, 64, 3, |u, v| {
        let e = 1.0 / 64.0;
        let k = 0.12; // height scale in texture units
        let dhdu = (bump_height(u + e, v) - bump_height(u - e, v)) / (2.0 * e) * k / 4.0;
        let dhdv = (bump_height(u, v + e) - bump_height(u, v - e)) / (2.0 * e) * k / 4.0;
        let n = norm([-dhdu, -dhdv, 1.0]);
        [0.5 + 0.5 * n[0], 0.5 + 0.5 * n[1], 0.5 + 0.5 * n[2], 1.0]
    });
    tex2d(gl, 64, 64, GL_RGB, &nm);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    snap_texture(gl, "normal_map", GL_TEXTURE_2D, 0, [64, 64, 1]);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGB as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PRIMARY_COLOR as i32);
    gl.active_texture(GL_TEXTURE1);
    let s = stone(64);
    tex2d(gl, 64, 64, GL_RGB, &s);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.active_texture(GL_TEXTURE0);
    let plane = |gl: &mut dyn Gl| {
        grid(gl, 16, &|gl, u, v| {
            let p = [
                BUMP_X[0] + u * (BUMP_X[1] - BUMP_X[0]),
                0.0,
                BUMP_Z[1] + v * (BUMP_Z[0] - BUMP_Z[1]),
            ];
            // The light vector in tangent space (T = +x, B = -z, N = +y), packed in the colour.
            let l = norm(sub(DOT3_LIGHT, p));
            let lt = [l[0], -l[2], l[1]];
            gl.color_3f(0.5 + 0.5 * lt[0], 0.5 + 0.5 * lt[1], 0.5 + 0.5 * lt[2]);
            gl.multi_tex_coord_2f(GL_TEXTURE0, 2.0 * u, 2.0 * v);
            gl.multi_tex_coord_2f(GL_TEXTURE1, u, v);
            gl.vertex_3f(p[0], p[1], p[2]);
        });
    };
    // Stage: the DOT3 term alone (unit 1 off), then the full picture over it.
    plane(gl);
    snap_color(gl, "dot3_only", 128, 128);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.active_texture(GL_TEXTURE1);
    gl.enable(GL_TEXTURE_2D);
    gl.active_texture(GL_TEXTURE0);
    plane(gl);
}

// ---------------------------------------------------------------------------------------------
// Projective texture (slide projector).

const PROJECTOR_EYE: V3 = [-1.8, 2.6, 1.4];
const PROJECTOR_AT: V3 = [0.2, 0.3, -1.2];

/// Eye-linear texgen with the identity planes, specified while the modelview holds the camera's
/// viewing transform: the generated (s, t, r, q) are then world coordinates (the planes are
/// multiplied by the inverse of that modelview, GL 1.5 section 2.11.4).
fn world_texgen(gl: &mut dyn Gl) {
    for (c, plane, cap) in [
        (GL_S, [1.0, 0.0, 0.0, 0.0], GL_TEXTURE_GEN_S),
        (GL_T, [0.0, 1.0, 0.0, 0.0], GL_TEXTURE_GEN_T),
        (GL_R, [0.0, 0.0, 1.0, 0.0], GL_TEXTURE_GEN_R),
        (GL_Q, [0.0, 0.0, 0.0, 1.0], GL_TEXTURE_GEN_Q),
    ] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR as i32);
        gl.tex_genfv(c, GL_EYE_PLANE, &plane);
        gl.enable(cap);
    }
}

/// The texture matrix that maps world coordinates to the projector's (or light's) window:
/// bias and scale [-1, 1] to [0, 1], then its projection and viewing transform.
fn projector_matrix(gl: &mut dyn Gl, fovy: f64, near: f64, far: f64, eye: V3, at: V3) {
    gl.matrix_mode(GL_TEXTURE);
    gl.load_identity();
    gl.translatef(0.5, 0.5, 0.5);
    gl.scalef(0.5, 0.5, 0.5);
    perspective(gl, fovy, 1.0, near, far);
    look_at(gl, eye, at, [0.0, 1.0, 0.0]);
    gl.matrix_mode(GL_MODELVIEW);
}

fn stage_set(gl: &mut dyn Gl) {
    material(gl, [0.9, 0.9, 0.9, 1.0], 0.0, 1.0);
    // Floor and back wall as lit grids (triangles), a box and a second, lower box.
    grid(gl, 8, &|gl, u, v| {
        gl.normal_3f(0.0, 1.0, 0.0);
        gl.vertex_3f(-2.5 + 5.0 * u, 0.0, 1.5 - 4.5 * v);
    });
    grid(gl, 8, &|gl, u, v| {
        gl.normal_3f(0.0, 0.0, 1.0);
        gl.vertex_3f(-2.5 + 5.0 * u, 3.0 * v, -3.0);
    });
    material(gl, [0.9, 0.8, 0.6, 1.0], 0.0, 1.0);
    cuboid(gl, [0.3, 0.5, -1.0], [0.5, 0.5, 0.5]);
    material(gl, [0.6, 0.8, 0.9, 1.0], 0.0, 1.0);
    cuboid(gl, [-0.9, 0.25, 0.2], [0.3, 0.25, 0.4]);
}

/// A slide: a smiley with a white frame; outside it, CLAMP_TO_BORDER gives the dim border colour.
fn slide(size: usize) -> Vec<u8> {
    paint(size, size, 3, |u, v| {
        let (x, y) = (u - 0.5, v - 0.5);
        if x.abs() > 0.46 || y.abs() > 0.46 {
            return [1.0, 1.0, 1.0, 1.0];
        }
        let r = (x * x + y * y).sqrt();
        let eye = |ex: f32| ((x - ex).powi(2) + (y - 0.1).powi(2)).sqrt() < 0.06;
        if r < 0.36 {
            if eye(-0.12) || eye(0.12) || (r > 0.2 && r < 0.26 && y < -0.05) {
                [0.1, 0.1, 0.1, 1.0]
            } else {
                [1.0, 0.85, 0.1, 1.0]
            }
        } else {
            [0.3, 0.5, 1.0, 1.0]
        }
    })
}

/// Projective texturing: the scene's world coordinates, generated by eye-linear texgen, go
/// through a texture matrix holding the projector's frustum; s/q, t/q index the slide.
fn ex_projective_texture(gl: &mut dyn Gl) {
    clear_to(gl, [0.0, 0.0, 0.0]);
    camera(gl, 50.0, 1.0, [0.6, 2.2, 3.6], [0.0, 0.6, -0.8]);
    gl.enable(GL_DEPTH_TEST);
    lamp(gl, [0.3, 1.0, 0.6, 0.0]);
    gl.lightfv(GL_LIGHT0, GL_DIFFUSE, &[0.5, 0.5, 0.5, 1.0]);
    let px = slide(64);
    tex2d(gl, 64, 64, GL_RGB, &px);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_BORDER);
    gl.tex_parameterfv(
        GL_TEXTURE_2D,
        GL_TEXTURE_BORDER_COLOR,
        &[0.4, 0.4, 0.4, 1.0],
    );
    snap_texture(gl, "slide", GL_TEXTURE_2D, 0, [64, 64, 1]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    world_texgen(gl);
    projector_matrix(gl, 35.0, 0.5, 10.0, PROJECTOR_EYE, PROJECTOR_AT);
    stage_set(gl);
}

// ---------------------------------------------------------------------------------------------
// Shadow maps.

const LIGHT_EYE: V3 = [1.8, 3.4, -2.4];
const LIGHT_AT: V3 = [0.0, 0.0, -0.2];
const SHADOW_FOV: f64 = 70.0;

fn shadow_world(gl: &mut dyn Gl) {
    material(gl, [0.85, 0.85, 0.8, 1.0], 0.0, 1.0);
    grid(gl, 8, &|gl, u, v| {
        gl.normal_3f(0.0, 1.0, 0.0);
        gl.vertex_3f(-2.0 + 4.0 * u, 0.0, 1.2 - 3.6 * v);
    });
    material(gl, [0.9, 0.5, 0.3, 1.0], 0.0, 1.0);
    cuboid(gl, [0.0, 0.45, -0.5], [0.35, 0.45, 0.35]);
    material(gl, [0.3, 0.6, 0.9, 1.0], 0.0, 1.0);
    gl.push_matrix();
    gl.translatef(-0.7, 0.9, 0.2);
    gl.rotatef(60.0, 1.0, 0.0, 0.0);
    torus(gl, 0.3, 0.1, 24, 10);
    gl.pop_matrix();
}

/// Pass 1 of both shadow scenes: the scene from the light, depth only, with polygon offset (so
/// lit surfaces do not shadow themselves), copied into a GL_DEPTH_COMPONENT texture.
fn shadow_pass1(gl: &mut dyn Gl) {
    clear_to(gl, [0.0, 0.0, 0.0]);
    // The light's view is the shadow map: its own size, whatever the window's.
    gl.viewport(0, 0, 128, 128);
    gl.enable(GL_DEPTH_TEST);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    perspective(gl, SHADOW_FOV, 1.0, 2.0, 8.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    look_at(gl, LIGHT_EYE, LIGHT_AT, [0.0, 1.0, 0.0]);
    gl.color_mask(0, 0, 0, 0);
    gl.enable(GL_POLYGON_OFFSET_FILL);
    gl.polygon_offset(2.0, 4.0);
    shadow_world(gl);
    gl.disable(GL_POLYGON_OFFSET_FILL);
    gl.color_mask(1, 1, 1, 1);
    snap_depth(gl, "light_view_depth", 128, 128);
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_2D, name[0]);
    gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, 128, 128, 0);
    sampling(gl, GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_COMPARE_MODE,
        GL_COMPARE_R_TO_TEXTURE as i32,
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL as i32);
    snap_texture(gl, "shadow_map", GL_TEXTURE_2D, 0, [128, 128, 1]);
    // Pass 2 set-up: the camera, lighting, texgen into the light's window coordinates.
    example_support::viewport(gl, 0, 0, 128, 128);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    camera(gl, 50.0, 1.0, [-1.4, 2.4, 3.4], [0.0, 0.4, -0.3]);
    lamp(gl, [LIGHT_EYE[0], LIGHT_EYE[1], LIGHT_EYE[2], 1.0]);
    world_texgen(gl);
    projector_matrix(gl, SHADOW_FOV, 2.0, 8.0, LIGHT_EYE, LIGHT_AT);
}

/// Shadow mapping (Williams 1978; ARB_shadow in GL 1.4): r/q, the fragment's depth as the light
/// sees it, is compared with the stored depth (GL_TEXTURE_COMPARE_MODE =
/// GL_COMPARE_R_TO_TEXTURE, GL_LEQUAL); the 0/1 result as LUMINANCE modulates the lit colour.
fn ex_shadow_map(gl: &mut dyn Gl) {
    shadow_pass1(gl);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    shadow_world(gl);
}

/// The alpha-test variant: pass A draws the scene with ambient light only; pass B draws it fully
/// lit with the comparison result in alpha (GL_DEPTH_TEXTURE_MODE = GL_ALPHA) and the alpha test
/// discarding shadowed fragments, so shadows keep the ambient picture.
fn ex_shadow_map_alpha_test(gl: &mut dyn Gl) {
    shadow_pass1(gl);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.disable(GL_LIGHT0);
    shadow_world(gl);
    snap_color(gl, "passA_ambient", 128, 128);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_TEXTURE_2D);
    gl.depth_func(GL_LEQUAL);
    gl.enable(GL_ALPHA_TEST);
    gl.alpha_func(GL_GREATER, 0.5);
    shadow_world(gl);
}

// ---------------------------------------------------------------------------------------------
// Contouring.

fn terrain_height(x: f32, z: f32) -> f32 {
    0.45 * (1.3 * x + 0.4).sin() * (1.1 * z).cos() + 0.25 * (2.3 * x - 1.7 * z).sin()
}

fn terrain_normal(x: f32, z: f32) -> V3 {
    let e = 0.01;
    let dx = (terrain_height(x + e, z) - terrain_height(x - e, z)) / (2.0 * e);
    let dz = (terrain_height(x, z + e) - terrain_height(x, z - e)) / (2.0 * e);
    norm([-dx, 1.0, -dz])
}

/// Terrain over x in [-3, 3], z in [z0, 1.5], coloured by height and shaded by a fixed light
/// (colours computed here, so no GL lighting is needed).
fn terrain(gl: &mut dyn Gl, n: usize, z0: f32) {
    let light = norm([0.5, 0.8, 0.3]);
    grid(gl, n, &|gl, u, v| {
        let (x, z) = (-3.0 + 6.0 * u, 1.5 + (z0 - 1.5) * v);
        let h = terrain_height(x, z);
        let k = 0.35 + 0.65 * dot(terrain_normal(x, z), light).max(0.0);
        let c = if h > 0.45 {
            [0.95, 0.95, 0.95]
        } else if h > 0.1 {
            [0.55, 0.45, 0.3]
        } else {
            [0.3, 0.6, 0.25]
        };
        gl.color_3f(c[0] * k, c[1] * k, c[2] * k);
        gl.vertex_3f(x, h, z);
    });
}

/// Contour lines (Haeberli & Segal): object-linear texgen turns the height y into the 1D
/// texture coordinate s = 5y; a repeating 1D texture that is white except one dark texel
/// draws a line wherever the height crosses a multiple of 1/5.
fn ex_contour(gl: &mut dyn Gl) {
    clear_to(gl, [0.6, 0.7, 0.85]);
    camera(gl, 50.0, 1.0, [0.0, 2.6, 3.2], [0.0, 0.0, -0.6]);
    gl.enable(GL_DEPTH_TEST);
    let stripe: Vec<u8> = (0..16)
        .flat_map(|i| {
            if i == 0 {
                [40, 20, 10]
            } else {
                [255, 255, 255]
            }
        })
        .collect();
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_1D, name[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_1d(
        GL_TEXTURE_1D,
        0,
        GL_RGB as i32,
        16,
        0,
        GL_RGB,
        GL_UNSIGNED_BYTE,
        Some(&stripe),
    );
    sampling(gl, GL_TEXTURE_1D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_1D);
    gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR as i32);
    gl.tex_genfv(GL_S, GL_OBJECT_PLANE, &[0.0, 5.0, 0.0, 0.0]);
    gl.enable(GL_TEXTURE_GEN_S);
    terrain(gl, 32, -3.5);
}

// ---------------------------------------------------------------------------------------------
// Volume rendering with a 3D texture.

/// Volume rendering by texture slicing: view-aligned quads drawn back to front through a 3D
/// texture, composited with glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA). The texture
/// matrix rotates the volume about its centre; CLAMP_TO_BORDER with a transparent border keeps
/// the slices' corners outside the volume empty.
fn ex_volume_3d(gl: &mut dyn Gl) {
    clear_to(gl, [0.0, 0.0, 0.0]);
    const N: usize = 32;
    let mut px = Vec::with_capacity(N * N * N * 4);
    for z in 0..N {
        for y in 0..N {
            for x in 0..N {
                let p = [x, y, z].map(|c| (c as f32 + 0.5) / N as f32 * 2.0 - 1.0);
                // A torus-shaped shell and a dense core.
                let q = ((p[0] * p[0] + p[2] * p[2]).sqrt() - 0.6).hypot(p[1]);
                let shell = (1.0 - ((q - 0.2) / 0.12).powi(2)).max(0.0);
                let core = (1.0 - (dot(p, p) / 0.12)).max(0.0);
                let a = (0.45 * shell + 0.7 * core).min(1.0);
                px.extend_from_slice(&[
                    to_u8(0.5 + 0.5 * p[0] + core),
                    to_u8(0.4 + 0.5 * p[1]),
                    to_u8(0.9 - 0.6 * core),
                    to_u8(a),
                ]);
            }
        }
    }
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_3D, name[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_3d(
        GL_TEXTURE_3D,
        0,
        GL_RGBA as i32,
        N as i32,
        N as i32,
        N as i32,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&px),
    );
    sampling(gl, GL_TEXTURE_3D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_BORDER);
    gl.tex_parameterfv(
        GL_TEXTURE_3D,
        GL_TEXTURE_BORDER_COLOR,
        &[0.0, 0.0, 0.0, 0.0],
    );
    snap_texture(gl, "volume_slices", GL_TEXTURE_3D, 0, [32, 32, 32]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_3D);
    gl.matrix_mode(GL_TEXTURE);
    gl.translatef(0.5, 0.5, 0.5);
    gl.rotatef(35.0, 1.0, 0.0, 0.0);
    gl.rotatef(25.0, 0.0, 1.0, 0.0);
    gl.translatef(-0.5, -0.5, -0.5);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-1.0, 1.0, -1.0, 1.0, -2.0, 2.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    // The volume is the cube [-0.6, 0.6]^3 in eye space; slices cover its rotated extent.
    let (half, reach, slices) = (0.6f32, 1.04f32, 48);
    for i in 0..slices {
        let z = -reach + 2.0 * reach * (i as f32 + 0.5) / slices as f32;
        gl.begin(GL_QUADS);
        for (x, y) in [
            (-reach, -reach),
            (reach, -reach),
            (reach, reach),
            (-reach, reach),
        ] {
            let t = |c: f32| 0.5 + c / (2.0 * half);
            gl.tex_coord_3f(t(x), t(y), t(z));
            gl.vertex_3f(x, y, z);
        }
        gl.end();
        if i == slices / 2 {
            snap_color(gl, "half_the_slices", 128, 128);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Anti-aliased text.

/// Stroke glyphs on a 4 x 6 grid.
const GLYPHS: &[(char, &[[f32; 4]])] = &[
    ('A', &[[0., 0., 2., 6.], [2., 6., 4., 0.], [1., 3., 3., 3.]]),
    (
        'E',
        &[
            [4., 6., 0., 6.],
            [0., 6., 0., 0.],
            [0., 0., 4., 0.],
            [0., 3., 3., 3.],
        ],
    ),
    (
        'G',
        &[
            [4., 5., 3., 6.],
            [3., 6., 1., 6.],
            [1., 6., 0., 5.],
            [0., 5., 0., 1.],
            [0., 1., 1., 0.],
            [1., 0., 3., 0.],
            [3., 0., 4., 1.],
            [4., 1., 4., 3.],
            [4., 3., 2., 3.],
        ],
    ),
    ('H', &[[0., 0., 0., 6.], [4., 0., 4., 6.], [0., 3., 4., 3.]]),
    ('I', &[[2., 0., 2., 6.], [1., 6., 3., 6.], [1., 0., 3., 0.]]),
    ('L', &[[0., 6., 0., 0.], [0., 0., 4., 0.]]),
    ('N', &[[0., 0., 0., 6.], [0., 6., 4., 0.], [4., 0., 4., 6.]]),
    (
        'O',
        &[
            [1., 6., 3., 6.],
            [3., 6., 4., 5.],
            [4., 5., 4., 1.],
            [4., 1., 3., 0.],
            [3., 0., 1., 0.],
            [1., 0., 0., 1.],
            [0., 1., 0., 5.],
            [0., 5., 1., 6.],
        ],
    ),
    (
        'P',
        &[
            [0., 0., 0., 6.],
            [0., 6., 3., 6.],
            [3., 6., 4., 5.],
            [4., 5., 4., 4.],
            [4., 4., 3., 3.],
            [3., 3., 0., 3.],
        ],
    ),
    ('T', &[[0., 6., 4., 6.], [2., 6., 2., 0.]]),
    ('X', &[[0., 0., 4., 6.], [0., 6., 4., 0.]]),
];

const CELL: usize = 32;
const ATLAS_W: usize = 8 * CELL;
const ATLAS_H: usize = 2 * CELL;

fn seg_dist(p: [f32; 2], s: &[f32; 4]) -> f32 {
    let (ax, ay, bx, by) = (s[0], s[1], s[2], s[3]);
    let (dx, dy) = (bx - ax, by - ay);
    let t = (((p[0] - ax) * dx + (p[1] - ay) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
    ((p[0] - ax - t * dx).powi(2) + (p[1] - ay - t * dy).powi(2)).sqrt()
}

/// The font texture: each glyph's strokes rasterised with 4x4 supersampling into the alpha of a
/// 32x32 cell (coverage = alpha: the texture is the anti-aliased glyph).
fn font_atlas() -> Vec<u8> {
    let mut a = vec![0u8; ATLAS_W * ATLAS_H];
    for (g, (_, strokes)) in GLYPHS.iter().enumerate() {
        let (cx, cy) = ((g % 8) * CELL, (g / 8) * CELL);
        for y in 0..CELL {
            for x in 0..CELL {
                let mut hits = 0;
                for sy in 0..4 {
                    for sx in 0..4 {
                        let px = x as f32 + (sx as f32 + 0.5) / 4.0;
                        let py = y as f32 + (sy as f32 + 0.5) / 4.0;
                        // Grid unit: 5 texels across, 4.3 up; 6-texel left and 3-texel bottom margins.
                        let p = [(px - 6.0) / 5.0, (py - 3.0) / 4.3];
                        let d = strokes
                            .iter()
                            .map(|s| seg_dist(p, s))
                            .fold(f32::MAX, f32::min);
                        if d * 4.6 < 1.9 {
                            hits += 1;
                        }
                    }
                }
                a[(cy + y) * ATLAS_W + cx + x] = (hits * 255 / 16) as u8;
            }
        }
    }
    a
}

/// Draws `text` with glyph cells `size` units high from (x, y), one textured quad per glyph.
fn draw_text(gl: &mut dyn Gl, text: &str, x: f32, y: f32, size: f32) {
    gl.begin(GL_QUADS);
    let mut pen = x;
    for ch in text.chars() {
        if let Some(g) = GLYPHS.iter().position(|(c, _)| *c == ch) {
            let s0 = ((g % 8) * CELL) as f32 / ATLAS_W as f32;
            let t0 = ((g / 8) * CELL) as f32 / ATLAS_H as f32;
            let (ds, dt) = (CELL as f32 / ATLAS_W as f32, CELL as f32 / ATLAS_H as f32);
            for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
                gl.tex_coord_2f(s0 + u * ds, t0 + v * dt);
                gl.vertex_2f(pen + u * size, y + v * size);
            }
        }
        pen += size * 0.78;
    }
    gl.end();
}

/// Anti-aliased text as texture-mapped quads (Haeberli & Segal): the glyphs' coverage is in
/// an ALPHA texture; GL_MODULATE takes the colour from glColor and the alpha from the texture,
/// and glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) blends the edges. Filtering (with
/// mipmaps for the small sizes) keeps the text smooth at any size, angle and perspective.
fn ex_text(gl: &mut dyn Gl) {
    clear_to(gl, [0.12, 0.16, 0.3]);
    let atlas = font_atlas();
    tex2d(gl, ATLAS_W as i32, ATLAS_H as i32, GL_ALPHA, &atlas);
    sampling(
        gl,
        GL_TEXTURE_2D,
        GL_LINEAR_MIPMAP_LINEAR,
        GL_LINEAR,
        GL_CLAMP_TO_EDGE,
    );
    snap_texture(
        gl,
        "font_texture",
        GL_TEXTURE_2D,
        0,
        [ATLAS_W as i32, ATLAS_H as i32, 1],
    );
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 256.0, 0.0, 128.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.color_3f(1.0, 0.95, 0.6);
    draw_text(gl, "TILEGL", 6.3, 82.4, 40.0);
    gl.color_3f(0.7, 0.9, 1.0);
    draw_text(gl, "ALPHA TEXT", 8.2, 60.3, 20.0);
    gl.color_3f(1.0, 1.0, 1.0);
    draw_text(gl, "OPENGL ALPHA TEXT", 8.6, 48.2, 10.0);
    gl.push_matrix();
    gl.translatef(150.0, 10.0, 0.0);
    gl.rotatef(25.0, 0.0, 0.0, 1.0);
    gl.color_3f(1.0, 0.6, 0.5);
    draw_text(gl, "OPENGL", 0.3, 0.2, 16.0);
    gl.pop_matrix();
    // Text on a plane receding in perspective.
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -0.5, 0.5, 1.0, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(-1.3, -0.45, -1.4);
    gl.rotatef(-70.0, 1.0, 0.0, 0.0);
    gl.scalef(0.02, 0.02, 0.02);
    gl.color_3f(0.6, 1.0, 0.6);
    draw_text(gl, "TEXT TEXT TEXT", 0.0, 0.0, 16.0);
}

// ---------------------------------------------------------------------------------------------
// Cut-outs and decals.

/// A tree: a trunk and a leafy crown with holes; alpha 0 elsewhere.
fn tree_texture(size: usize) -> Vec<u8> {
    let mut rng = XorShift::new(7);
    let noise: Vec<f32> = (0..size * size).map(|_| rng.next_f32()).collect();
    let mut p = Vec::with_capacity(size * size * 4);
    for y in 0..size {
        for x in 0..size {
            let (u, v) = (
                (x as f32 + 0.5) / size as f32,
                (y as f32 + 0.5) / size as f32,
            );
            let n = noise[(y / 2) * size + x / 2];
            let crown = ((u - 0.5) / 0.42).powi(2) + ((v - 0.62) / 0.36).powi(2);
            let c = if crown < 1.0 && n > 0.25 {
                [(40.0 + 60.0 * n) as u8, (110.0 + 90.0 * n) as u8, 40, 255]
            } else if (u - 0.5).abs() < 0.06 && v < 0.4 {
                [100, 70, 40, 255]
            } else {
                [0, 0, 0, 0]
            };
            p.extend_from_slice(&c);
        }
    }
    p
}

/// Cut-out "cross trees": two perpendicular quads with an RGBA tree texture; the alpha test
/// (glAlphaFunc(GL_GREATER, 0.5)) discards the transparent texels, so the depth buffer sees only
/// the leaves and trunk and the quads need no sorting.
fn ex_cross_tree(gl: &mut dyn Gl) {
    clear_to(gl, [0.6, 0.75, 0.95]);
    camera(gl, 50.0, 1.0, [0.4, 1.3, 3.6], [0.0, 0.7, 0.0]);
    gl.enable(GL_DEPTH_TEST);
    gl.color_3f(0.35, 0.55, 0.25);
    floor_quad(gl, [-3.0, 3.0], [-4.0, 2.0], &[]);
    let px = tree_texture(64);
    tex2d(gl, 64, 64, GL_RGBA, &px);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "tree_texture", GL_TEXTURE_2D, 0, [64, 64, 1]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_ALPHA_TEST);
    gl.alpha_func(GL_GREATER, 0.5);
    for (x, z, h, a) in [
        (-0.8, -0.6, 1.8, 10.0),
        (0.9, -1.4, 2.2, 35.0),
        (0.1, 0.6, 1.4, 70.0),
    ] {
        gl.push_matrix();
        gl.translatef(x, 0.0, z);
        gl.rotatef(a, 0.0, 1.0, 0.0);
        gl.begin(GL_QUADS);
        for plane in 0..2 {
            for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
                gl.tex_coord_2f(u, v);
                let w = (u - 0.5) * h;
                if plane == 0 {
                    gl.vertex_3f(w, v * h, 0.0);
                } else {
                    gl.vertex_3f(0.0, v * h, w);
                }
            }
        }
        gl.end();
        gl.pop_matrix();
    }
}

/// A decal with a clamped transparent border (Haeberli & Segal): unit 1 holds an RGBA target
/// in GL_DECAL mode (colour = previous x (1 - At) + texture x At) with CLAMP_TO_BORDER and a
/// border colour of alpha 0, so outside the decal's square the wall shows through. The texture
/// matrix places, scales and rotates the decal on the wall.
fn ex_decal(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.1]);
    camera(gl, 45.0, 1.0, [0.8, 0.3, 3.0], [0.0, 0.0, 0.0]);
    gl.enable(GL_DEPTH_TEST);
    let b = bricks(64);
    tex2d(gl, 64, 64, GL_RGB, &b);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.active_texture(GL_TEXTURE1);
    let d = paint(32, 32, 4, |u, v| {
        let r = ((u - 0.5).powi(2) + (v - 0.5).powi(2)).sqrt() * 2.0;
        let ring = ((r * 4.0) as i32) % 2 == 0;
        let a = ((1.0 - r) * 12.0).clamp(0.0, 1.0);
        if ring {
            [0.95, 0.15, 0.1, a]
        } else {
            [1.0, 1.0, 0.95, a]
        }
    });
    tex2d(gl, 32, 32, GL_RGBA, &d);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_BORDER);
    gl.tex_parameterfv(
        GL_TEXTURE_2D,
        GL_TEXTURE_BORDER_COLOR,
        &[0.0, 0.0, 0.0, 0.0],
    );
    snap_texture(gl, "decal_texture", GL_TEXTURE_2D, 0, [32, 32, 1]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL as i32);
    if unit_on(1) {
        gl.enable(GL_TEXTURE_2D);
    }
    gl.matrix_mode(GL_TEXTURE);
    gl.translatef(0.5, 0.5, 0.0);
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
    gl.scalef(2.4, 3.0, 1.0);
    gl.translatef(-0.62, -0.45, 0.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.active_texture(GL_TEXTURE0);
    gl.color_3f(0.95, 0.95, 0.9);
    gl.begin(GL_QUADS);
    for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        gl.multi_tex_coord_2f(GL_TEXTURE0, 3.0 * u, 2.4 * v);
        gl.multi_tex_coord_2f(GL_TEXTURE1, u, v);
        gl.vertex_3f(-1.5 + 3.0 * u, -1.2 + 2.4 * v, 0.0);
    }
    gl.end();
}

// ---------------------------------------------------------------------------------------------
// Fog.

const FOG: [f32; 4] = [0.7, 0.75, 0.82, 1.0];

fn fog_panels(gl: &mut dyn Gl, fogged: bool) {
    for (i, mode) in [GL_LINEAR, GL_EXP, GL_EXP2].into_iter().enumerate() {
        example_support::viewport(gl, 128 * i as i32, 0, 128, 128);
        camera(gl, 50.0, 1.0, [0.0, 1.6, 1.8], [0.0, 0.0, -3.0]);
        if fogged {
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, mode as i32);
            gl.fogfv(GL_FOG_COLOR, &FOG);
            gl.fogf(GL_FOG_START, 1.5);
            gl.fogf(GL_FOG_END, 9.0);
            gl.fogf(GL_FOG_DENSITY, if mode == GL_EXP { 0.3 } else { 0.22 });
        }
        terrain(gl, 32, -10.0);
    }
}

/// Fog over a terrain: GL_LINEAR ((end - z) / (end - start)), GL_EXP (e^(-density z)) and
/// GL_EXP2 (e^(-(density z)^2)) side by side; the fragment colour is blended towards the fog
/// colour by that factor of the eye distance. The clear colour is the fog colour.
fn ex_fog_terrain(gl: &mut dyn Gl) {
    clear_to(gl, [FOG[0], FOG[1], FOG[2]]);
    gl.enable(GL_DEPTH_TEST);
    fog_panels(gl, false);
    snap_color(gl, "without_fog", 384, 128);
    example_support::viewport(gl, 0, 0, 384, 128);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    fog_panels(gl, true);
}

// ---------------------------------------------------------------------------------------------
// Planar reflection with the stencil buffer.

fn mirror_floor(gl: &mut dyn Gl) {
    gl.begin(GL_QUADS);
    for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        gl.tex_coord_2f(4.0 * u, 4.0 * v);
        gl.vertex_3f(-1.5 + 3.0 * u, 0.0, 1.5 - 3.0 * v);
    }
    gl.end();
}

fn reflected_object(gl: &mut dyn Gl) {
    material(gl, [0.9, 0.4, 0.2, 1.0], 0.6, 30.0);
    gl.push_matrix();
    gl.translatef(0.0, 0.75, 0.0);
    gl.rotatef(50.0, 1.0, 0.0, 0.0);
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
    torus(gl, 0.5, 0.2, 32, 14);
    gl.pop_matrix();
}

/// Planar reflection (McReynolds & Blythe; Kilgard): the mirror's pixels are marked in the
/// stencil buffer; the object is drawn mirrored (glScalef(1, -1, 1), which flips the winding, so
/// glFrontFace(GL_CW)) only where the stencil is 1; the floor is blended over it; then the
/// object is drawn normally. The light is re-specified under the mirrored modelview.
fn ex_planar_reflection(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.15]);
    camera(gl, 45.0, 1.0, [0.0, 1.7, 3.4], [0.0, 0.3, 0.0]);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_CULL_FACE);
    let light = [1.0, 2.5, 1.5, 1.0];
    // 1. The mirror into the stencil buffer only.
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_ALWAYS, 1, 0xff);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
    gl.color_mask(0, 0, 0, 0);
    gl.depth_mask(0);
    mirror_floor(gl);
    gl.color_mask(1, 1, 1, 1);
    gl.depth_mask(1);
    snap_stencil(gl, "stencil_mirror", 128, 128);
    // 2. The reflection, where the stencil is 1.
    gl.stencil_func(GL_EQUAL, 1, 0xff);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
    gl.push_matrix();
    gl.scalef(1.0, -1.0, 1.0);
    lamp(gl, light);
    gl.front_face(GL_CW);
    reflected_object(gl);
    gl.front_face(GL_CCW);
    gl.pop_matrix();
    gl.disable(GL_STENCIL_TEST);
    snap_color(gl, "reflection", 128, 128);
    // 3. The floor, translucent, over the reflection.
    gl.lightfv(GL_LIGHT0, GL_POSITION, &light);
    gl.disable(GL_LIGHTING);
    let checker = paint(8, 8, 3, |u, v| {
        if ((u * 8.0) as i32 + (v * 8.0) as i32) % 2 == 0 {
            [0.8, 0.8, 0.85, 1.0]
        } else {
            [0.3, 0.35, 0.5, 1.0]
        }
    });
    tex2d(gl, 8, 8, GL_RGB, &checker);
    sampling(gl, GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.color_4f(1.0, 1.0, 1.0, 0.7);
    mirror_floor(gl);
    gl.disable(GL_BLEND);
    gl.disable(GL_TEXTURE_2D);
    snap_color(gl, "floor_blended", 128, 128);
    // 4. The object itself.
    gl.enable(GL_LIGHTING);
    reflected_object(gl);
}

// ---------------------------------------------------------------------------------------------
// S3TC (DXT) compression.

/// A 64x64 RGBA picture with smooth gradients, hard edges and a soft alpha disc: what block
/// compression keeps (gradients within a block) and loses (several colours in one block).
fn dxt_source() -> Vec<u8> {
    paint(64, 64, 4, |u, v| {
        let ring = (((u - 0.5).powi(2) + (v - 0.5).powi(2)).sqrt() * 9.0).floor() as i32;
        let stripe = ((u * 8.0).floor() as i32 + (v * 3.0).floor() as i32) % 3;
        let base = [u, 0.3 + 0.5 * v, 1.0 - u * v, 1.0];
        let mut c = match (ring % 2, stripe) {
            (0, 0) => [0.95, 0.9, 0.2, 1.0],
            (0, _) => base,
            _ => [base[2], base[0], base[1], 1.0],
        };
        let d = ((u - 0.5).powi(2) + (v - 0.5).powi(2)).sqrt();
        c[3] = (1.2 - 2.0 * d).clamp(0.0, 1.0);
        c
    })
}

/// RGB565 of a colour, and back.
fn to_565(c: [u8; 3]) -> u16 {
    ((c[0] as u16 >> 3) << 11) | ((c[1] as u16 >> 2) << 5) | (c[2] as u16 >> 3)
}

fn from_565(v: u16) -> [i32; 3] {
    let (r, g, b) = ((v >> 11) & 31, (v >> 5) & 63, v & 31);
    [
        (r as i32 * 255 + 15) / 31,
        (g as i32 * 255 + 31) / 63,
        (b as i32 * 255 + 15) / 31,
    ]
}

/// A simple DXT colour block (EXT_texture_compression_s3tc): the two endpoints are the
/// block's darkest and brightest texels, each texel takes the nearest of the four palette
/// colours (c0 > c1: the 1/3 and 2/3 blends). The same bytes go to every implementation, so
/// the pictures compare the decoders, not the encoders (which the extension leaves open).
fn dxt_color_block(texels: &[[u8; 4]; 16]) -> [u8; 8] {
    let luma = |c: &[u8; 4]| c[0] as u32 * 3 + c[1] as u32 * 6 + c[2] as u32;
    let lo = texels
        .iter()
        .min_by_key(|c| luma(c))
        .copied()
        .unwrap_or([0; 4]);
    let hi = texels
        .iter()
        .max_by_key(|c| luma(c))
        .copied()
        .unwrap_or([0; 4]);
    let (mut c0, mut c1) = (to_565([hi[0], hi[1], hi[2]]), to_565([lo[0], lo[1], lo[2]]));
    if c0 < c1 {
        std::mem::swap(&mut c0, &mut c1);
    }
    if c0 == c1 {
        // Four-colour mode needs c0 > c1; with one colour every index 0 is exact.
        c1 = c0.saturating_sub(1);
    }
    let (p0, p1) = (from_565(c0), from_565(c1));
    let palette = [
        p0,
        p1,
        [0, 1, 2].map(|k| (2 * p0[k] + p1[k]) / 3),
        [0, 1, 2].map(|k| (p0[k] + 2 * p1[k]) / 3),
    ];
    let mut bits = 0u32;
    for (i, t) in texels.iter().enumerate() {
        let dist = |p: &[i32; 3]| (0..3).map(|k| (p[k] - t[k] as i32).pow(2)).sum::<i32>();
        let best = (0..4).min_by_key(|&j| dist(&palette[j])).unwrap_or(0) as u32;
        bits |= best << (2 * i);
    }
    let mut out = [0u8; 8];
    out[..2].copy_from_slice(&c0.to_le_bytes());
    out[2..4].copy_from_slice(&c1.to_le_bytes());
    out[4..].copy_from_slice(&bits.to_le_bytes());
    out
}

/// A DXT5 alpha block: endpoints max and min alpha (a0 > a1: six interpolated steps), each
/// texel the nearest of the eight.
fn dxt5_alpha_block(texels: &[[u8; 4]; 16]) -> [u8; 8] {
    let a0 = texels.iter().map(|t| t[3]).max().unwrap_or(0);
    let a1 = texels.iter().map(|t| t[3]).min().unwrap_or(0);
    let (a0, a1) = if a0 == a1 {
        (a0.max(1), a0.max(1) - 1)
    } else {
        (a0, a1)
    };
    let level = |j: u64| -> i32 {
        let (a0, a1) = (a0 as i32, a1 as i32);
        match j {
            0 => a0,
            1 => a1,
            j => ((8 - j as i32) * a0 + (j as i32 - 1) * a1) / 7,
        }
    };
    let mut bits = 0u64;
    for (i, t) in texels.iter().enumerate() {
        let best = (0..8u64)
            .min_by_key(|&j| (level(j) - t[3] as i32).abs())
            .unwrap_or(0);
        bits |= best << (3 * i);
    }
    let mut out = [0u8; 8];
    out[0] = a0;
    out[1] = a1;
    out[2..].copy_from_slice(&bits.to_le_bytes()[..6]);
    out
}

/// The blocks of a 64x64 RGBA picture: DXT1 (8 bytes a block) or DXT5 (16).
fn dxt_blocks(px: &[u8], dxt5: bool) -> Vec<u8> {
    let mut out = Vec::new();
    for by in 0..16 {
        for bx in 0..16 {
            let mut texels = [[0u8; 4]; 16];
            for (i, t) in texels.iter_mut().enumerate() {
                let (x, y) = (bx * 4 + i % 4, by * 4 + i / 4);
                let k = (y * 64 + x) * 4;
                t.copy_from_slice(&px[k..k + 4]);
            }
            if dxt5 {
                out.extend_from_slice(&dxt5_alpha_block(&texels));
            }
            out.extend_from_slice(&dxt_color_block(&texels));
        }
    }
    out
}

/// The original texture, its DXT1 and its DXT5 compression, magnified side by side over a
/// checker (alpha blended) so the block artefacts and DXT5's smooth alpha show.
fn ex_dxt_compression(gl: &mut dyn Gl) {
    clear_to(gl, [0.2, 0.2, 0.25]);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 384.0, 0.0, 128.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    // A checker behind, to show alpha.
    for j in 0..16 {
        for i in 0..48 {
            let g = if (i + j) % 2 == 0 { 0.35 } else { 0.5 };
            gl.color_3f(g, g, g);
            gl.rectf(
                i as f32 * 8.0,
                j as f32 * 8.0,
                i as f32 * 8.0 + 8.0,
                j as f32 * 8.0 + 8.0,
            );
        }
    }
    let px = dxt_source();
    let mut names = [0u32; 3];
    gl.gen_textures(3, &mut names);
    gl.bind_texture(GL_TEXTURE_2D, names[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        64,
        64,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&px),
    );
    let dxt1 = dxt_blocks(&px, false);
    gl.bind_texture(GL_TEXTURE_2D, names[1]);
    gl.compressed_tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
        64,
        64,
        0,
        dxt1.len() as i32,
        Some(&dxt1),
    );
    let dxt5 = dxt_blocks(&px, true);
    gl.bind_texture(GL_TEXTURE_2D, names[2]);
    gl.compressed_tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_COMPRESSED_RGBA_S3TC_DXT5_EXT,
        64,
        64,
        0,
        dxt5.len() as i32,
        Some(&dxt5),
    );
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    for (k, name) in names.into_iter().enumerate() {
        gl.bind_texture(GL_TEXTURE_2D, name);
        sampling(gl, GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
        snap_texture(
            gl,
            ["original", "dxt1", "dxt5"][k],
            GL_TEXTURE_2D,
            0,
            [64, 64, 1],
        );
        // Off-integer corners and scale: no pixel centre falls exactly on a texel edge
        // (NEAREST would then be a tie implementations break differently).
        let x0 = 128.0 * k as f32 + 4.37;
        gl.begin(GL_QUADS);
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.tex_coord_2f(u, v);
            gl.vertex_2f(x0 + 117.3 * u, 4.41 + 117.3 * v);
        }
        gl.end();
    }
    gl.disable(GL_BLEND);
}

// ---------------------------------------------------------------------------------------------
// HSV colour interpolation through a 3D lookup texture.

/// HSV (each in 0..1, hue wrapping) to RGB.
fn hsv_to_rgb(h: f32, s: f32, v: f32) -> [f32; 3] {
    let h6 = h.rem_euclid(1.0) * 6.0;
    let f = |n: f32| {
        let k = (n + h6) % 6.0;
        v - v * s * k.min(4.0 - k).clamp(0.0, 1.0)
    };
    [f(5.0), f(3.0), f(1.0)]
}

/// Gouraud shading interpolates RGB; here the rasterizer interpolates (hue, saturation, value)
/// as texture coordinates instead and a 24 x 8 x 8 3D texture turns them into RGB. HSV to RGB
/// is piecewise multilinear with hue breakpoints every 1/6, so with texel centres on hue
/// multiples of 1/24 (the texture matrix maps values onto texel centres) trilinear filtering
/// reproduces it exactly; `GL_REPEAT` on the hue axis makes hue wrap, so 1.08 -> 0.8 goes the
/// short way through red. Top: three pairs of bars, RGB-interpolated above HSV-interpolated;
/// bottom: a triangle with red, green and blue corners both ways.
fn ex_hsv_lookup(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.12]);
    const H: usize = 24;
    const S: usize = 8;
    const V: usize = 8;
    let mut px = Vec::with_capacity(H * S * V * 3);
    for k in 0..V {
        for j in 0..S {
            for i in 0..H {
                let c = hsv_to_rgb(
                    i as f32 / H as f32,
                    j as f32 / (S - 1) as f32,
                    k as f32 / (V - 1) as f32,
                );
                px.extend(c.iter().map(|&x| to_u8(x)));
            }
        }
    }
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_3D, name[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_3d(
        GL_TEXTURE_3D,
        0,
        GL_RGB as i32,
        H as i32,
        S as i32,
        V as i32,
        0,
        GL_RGB,
        GL_UNSIGNED_BYTE,
        Some(&px),
    );
    sampling(gl, GL_TEXTURE_3D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    gl.tex_parameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_REPEAT as i32);
    snap_texture(
        gl,
        "hsv_lut",
        GL_TEXTURE_3D,
        0,
        [H as i32, S as i32, V as i32],
    );
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    // Values to texel centres: hue h -> h + 1/48 (texel i's centre is (i + 1/2) / 24),
    // saturation and value x -> (7 x + 1/2) / 8.
    gl.matrix_mode(GL_TEXTURE);
    gl.load_identity();
    gl.translatef(0.5 / H as f32, 0.5 / S as f32, 0.5 / V as f32);
    gl.scalef(1.0, (S - 1) as f32 / S as f32, (V - 1) as f32 / V as f32);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 128.0, 0.0, 128.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();

    // (hue, saturation, value) at the left and right ends of each pair of bars.
    let pairs: [([f32; 3], [f32; 3]); 3] = [
        ([1.0, 1.0, 1.0], [2.0 / 3.0, 1.0, 1.0]), // red -> blue through magenta
        ([1.0 / 6.0, 1.0, 1.0], [2.0 / 3.0, 1.0, 1.0]), // yellow -> blue through green
        ([1.08, 1.0, 1.0], [0.8, 0.4, 0.6]),      // orange -> dull violet through red
    ];
    let bar = |gl: &mut dyn Gl, y: f32, ends: ([f32; 3], [f32; 3]), hsv: bool| {
        gl.begin(GL_QUADS);
        for (x, dy, e) in [
            (4.0, 0.0, ends.0),
            (124.0, 0.0, ends.1),
            (124.0, 11.0, ends.1),
            (4.0, 11.0, ends.0),
        ] {
            if hsv {
                gl.tex_coord_3f(e[0], e[1], e[2]);
            } else {
                let c = hsv_to_rgb(e[0], e[1], e[2]);
                gl.color_3f(c[0], c[1], c[2]);
            }
            gl.vertex_2f(x, y + dy);
        }
        gl.end();
    };
    for (k, &ends) in pairs.iter().enumerate() {
        bar(gl, 114.0 - 28.0 * k as f32, ends, false);
    }
    let corners = [(4.3, 4.4), (59.7, 4.4), (32.2, 40.6)];
    let hues = [0.0, 1.0 / 3.0, 2.0 / 3.0];
    gl.begin(GL_TRIANGLES);
    for (&(x, y), &h) in corners.iter().zip(&hues) {
        let c = hsv_to_rgb(h, 1.0, 1.0);
        gl.color_3f(c[0], c[1], c[2]);
        gl.vertex_2f(x, y);
    }
    gl.end();
    snap_color(gl, "rgb_interpolation", 128, 128);
    gl.enable(GL_TEXTURE_3D);
    for (k, &ends) in pairs.iter().enumerate() {
        bar(gl, 101.0 - 28.0 * k as f32, ends, true);
    }
    gl.begin(GL_TRIANGLES);
    for (&(x, y), &h) in corners.iter().zip(&hues) {
        gl.tex_coord_3f(h, 1.0, 1.0);
        gl.vertex_2f(x + 64.0, y);
    }
    gl.end();
}

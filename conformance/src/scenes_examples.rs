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

mod effects;
mod projection;
mod texturing;
use effects::*;
use projection::*;
pub use texturing::receding_checker;
use texturing::*;

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

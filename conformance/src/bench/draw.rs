//! The benchmark's scenes: the workloads' set-up and per-frame drawing, their textures and
//! the state toggles.

#[allow(unused_imports)]
use super::*;

/// Lighting with `n` lights: light 0 as in [`light_toggle`], the others alternately
/// positional (attenuated) and directional, each in its own colour.
pub(super) fn lights_toggle(gl: &mut dyn Gl, n: usize) {
    light_toggle(gl);
    for i in 1..n {
        let light = GL_LIGHT0 + i as GLenum;
        let a = i as f32 * 0.8;
        let w = if i % 2 == 1 { 1.0 } else { 0.0 };
        gl.enable(light);
        gl.lightfv(light, GL_POSITION, &[a.cos(), a.sin(), -4.0 * w, w]);
        let c = [
            0.3 + 0.1 * (i % 3) as f32,
            0.25,
            0.35 - 0.04 * i as f32,
            1.0,
        ];
        gl.lightfv(light, GL_DIFFUSE, &c);
        gl.lightfv(light, GL_SPECULAR, &c);
        if w == 1.0 {
            gl.lightf(light, GL_LINEAR_ATTENUATION, 0.15);
        }
    }
}

/// Texture coordinates generated on s and t of unit 0 in `mode` (planes for the linear modes:
/// about one repeat per two units, as the tunnel's own coordinates).
pub(super) fn texgen_toggle(gl: &mut dyn Gl, mode: GLenum) {
    for (c, cap, plane) in [
        (GL_S, GL_TEXTURE_GEN_S, [0.5f32, 0.0, 0.5, 0.0]),
        (GL_T, GL_TEXTURE_GEN_T, [0.0, 0.5, 0.5, 0.0]),
    ] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, mode as i32);
        gl.tex_genfv(c, GL_OBJECT_PLANE, &plane);
        gl.tex_genfv(c, GL_EYE_PLANE, &plane);
        gl.enable(cap);
    }
}

/// `units` texture units in all: the units after 0 each with the bench texture (trilinear),
/// `MODULATE`, and their own constant coordinate.
pub(super) fn units_toggle(gl: &mut dyn Gl, units: usize) {
    for u in 1..units {
        gl.active_texture(GL_TEXTURE0 + u as GLenum);
        bench_texture_setup(gl, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 1.0);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    }
    gl.active_texture(GL_TEXTURE0);
}

/// Unit 0 through `GL_COMBINE` with `func` on RGB: the texture, the vertex colour and a
/// constant colour as its arguments.
pub(super) fn combine_toggle(gl: &mut dyn Gl, func: GLenum) {
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, func as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PRIMARY_COLOR as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_CONSTANT as i32);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.6, 0.5, 0.4, 0.5]);
}

/// Fog of `mode` with the `tunnel` workload's parameters.
pub(super) fn fog_toggle(gl: &mut dyn Gl, mode: GLenum) {
    gl.enable(GL_FOG);
    gl.fogi(GL_FOG_MODE, mode as i32);
    gl.fogf(GL_FOG_DENSITY, 0.07);
    gl.fogf(GL_FOG_START, 1.0);
    gl.fogf(GL_FOG_END, 30.0);
    gl.fogfv(GL_FOG_COLOR, &[0.25, 0.22, 0.2, 1.0]);
}

/// Lighting with one directional light and a specular material (the tunnel's normals point
/// inwards).
pub(super) fn light_toggle(gl: &mut dyn Gl) {
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 0.8, 1.0, 0.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.8, 0.8, 0.8, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 16.0);
}

/// A torus about the y axis as triangle strips with normals and texture coordinates (s four
/// times around the ring, t twice around the tube).
pub(super) fn textured_torus(gl: &mut dyn Gl, rings: usize, sides: usize, big: f32, small: f32) {
    use std::f32::consts::TAU;
    for i in 0..rings {
        gl.begin(GL_TRIANGLE_STRIP);
        for j in 0..=sides {
            let b = TAU * j as f32 / sides as f32;
            for ii in [i + 1, i] {
                let a = TAU * ii as f32 / rings as f32;
                let n = [a.cos() * b.cos(), b.sin(), a.sin() * b.cos()];
                gl.normal_3fv(&n);
                gl.tex_coord_2f(
                    4.0 * ii as f32 / rings as f32,
                    2.0 * j as f32 / sides as f32,
                );
                gl.vertex_3f(
                    a.cos() * (big + small * b.cos()),
                    small * b.sin(),
                    a.sin() * (big + small * b.cos()),
                );
            }
        }
        gl.end();
    }
}

/// The tunnel's tube (radius 1.5 about the z axis, from z = 0.5 to 47.5 units deep), as quad
/// strips with inward normals, texture coordinates (s twice around, t one repeat per two
/// units) and a smooth colour that darkens with the angle (its alpha varies too).
pub(super) fn tunnel(gl: &mut dyn Gl, sides: usize, segments: usize) {
    use std::f32::consts::TAU;
    let r = 1.5f32;
    for i in 0..segments {
        let (z0, z1) = (0.5 - i as f32, 0.5 - (i + 1) as f32);
        gl.begin(GL_QUAD_STRIP);
        for j in 0..=sides {
            let a = TAU * j as f32 / sides as f32;
            let (c, s) = (a.cos(), a.sin());
            let shade = 0.75 + 0.25 * s;
            // Alpha from 0.1 to 1 around the tube, for the alpha test and blending toggles.
            gl.color_4f(shade, shade * 0.95, shade * 0.9, 0.55 + 0.45 * c);
            gl.normal_3f(-c, -s, 0.0);
            for z in [z0, z1] {
                gl.tex_coord_2f(2.0 * j as f32 / sides as f32, -z * 0.5);
                gl.vertex_3f(r * c, r * s, z);
            }
        }
        gl.end();
    }
}

/// A 64x64 luminance light map: a bright pool of light with a soft falloff and a dimmer
/// second lamp, on a dark ambient floor.
pub(super) fn light_map_texture() -> Vec<u8> {
    let mut p = Vec::with_capacity(64 * 64);
    for y in 0..64 {
        for x in 0..64 {
            let (u, v) = ((x as f32 + 0.5) / 64.0, (y as f32 + 0.5) / 64.0);
            let d1 = (u - 0.35).powi(2) + (v - 0.6).powi(2);
            let d2 = (u - 0.75).powi(2) + (v - 0.3).powi(2);
            let l = 0.15 + 0.85 * (-d1 * 18.0).exp() + 0.5 * (-d2 * 40.0).exp();
            p.push((l.min(1.0) * 255.0) as u8);
        }
    }
    p
}

/// A 128x128 RGB environment for the sphere map: sky above, ground below, a sun.
pub(super) fn environment_texture() -> Vec<u8> {
    let mut p = Vec::with_capacity(128 * 128 * 3);
    for y in 0..128 {
        for x in 0..128 {
            let (u, v) = ((x as f32 + 0.5) / 64.0 - 1.0, (y as f32 + 0.5) / 64.0 - 1.0);
            let sun = (-((u - 0.3).powi(2) + (v - 0.4).powi(2)) * 30.0).exp();
            let c = if v > 0.0 {
                [0.3 + 0.4 * v, 0.45 + 0.4 * v, 0.9]
            } else {
                [0.35 - 0.2 * v, 0.3, 0.2]
            };
            p.extend(c.map(|c| ((c + sun).min(1.0) * 160.0) as u8));
        }
    }
    p
}

/// A torus about the y axis (`big` and `small` radii) as triangle strips with normals.
pub(crate) fn torus(gl: &mut dyn Gl, rings: usize, sides: usize, big: f32, small: f32) {
    use std::f32::consts::TAU;
    for i in 0..rings {
        gl.begin(GL_TRIANGLE_STRIP);
        for j in 0..=sides {
            let b = TAU * j as f32 / sides as f32;
            for ii in [i + 1, i] {
                let a = TAU * ii as f32 / rings as f32;
                let n = [a.cos() * b.cos(), b.sin(), a.sin() * b.cos()];
                gl.normal_3fv(&n);
                gl.vertex_3f(
                    a.cos() * (big + small * b.cos()),
                    small * b.sin(),
                    a.sin() * (big + small * b.cos()),
                );
            }
        }
        gl.end();
    }
}

/// A unit sphere as triangle strips with normals (2 x stacks x slices triangles).
pub(super) fn bench_sphere(gl: &mut dyn Gl, stacks: usize, slices: usize) {
    use std::f32::consts::{PI, TAU};
    for i in 0..stacks {
        let (t0, t1) = (
            PI * i as f32 / stacks as f32,
            PI * (i + 1) as f32 / stacks as f32,
        );
        gl.begin(GL_TRIANGLE_STRIP);
        for j in 0..=slices {
            let p = TAU * j as f32 / slices as f32;
            for t in [t1, t0] {
                let n = [t.sin() * p.cos(), t.cos(), t.sin() * p.sin()];
                gl.normal_3fv(&n);
                gl.vertex_3fv(&n);
            }
        }
        gl.end();
    }
}

/// A 256x256 RGBA test texture: a checkerboard of colour ramps with fine lines (it aliases
/// visibly when under-filtered).
pub fn bench_texture() -> Vec<u8> {
    let mut p = Vec::with_capacity(256 * 256 * 4);
    for y in 0..256u32 {
        for x in 0..256u32 {
            let check = ((x / 32) + (y / 32)) % 2 == 0;
            let line = x % 16 == 0 || y % 16 == 0;
            let (r, g, b) = if line {
                (20, 20, 20)
            } else if check {
                (230, (x % 32 * 6) as u8, 60)
            } else {
                (40, 120 + (y % 32 * 4) as u8, 220)
            };
            p.extend_from_slice(&[r, g, b, 255]);
        }
    }
    p
}

/// Texture quality settings of the ladder: (name, min filter, mag filter, max anisotropy).
pub const LADDER: [(&str, GLenum, GLenum, f32); 7] = [
    ("nearest", GL_NEAREST, GL_NEAREST, 1.0),
    ("bilinear", GL_LINEAR, GL_LINEAR, 1.0),
    ("trilinear", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 1.0),
    ("aniso 2x", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 2.0),
    ("aniso 4x", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 4.0),
    ("aniso 8x", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 8.0),
    ("aniso 16x", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 16.0),
];

/// Creates and binds the bench texture with the given filtering.
pub fn bench_texture_setup(gl: &mut dyn Gl, min: GLenum, mag: GLenum, aniso: f32) {
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_2D, name[0]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        256,
        256,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&bench_texture()),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT as i32);
    if aniso > 1.0 {
        gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, aniso);
    }
    gl.enable(GL_TEXTURE_2D);
}

/// A 64x64 RGBA sprite texture: a soft disc (alpha falls to 0 at the rim) with rings.
pub(super) fn sprite_texture() -> Vec<u8> {
    let mut p = Vec::with_capacity(64 * 64 * 4);
    for y in 0..64 {
        for x in 0..64 {
            let (dx, dy) = (x as f32 - 31.5, y as f32 - 31.5);
            let r = (dx * dx + dy * dy).sqrt() / 32.0;
            let a = (1.0 - r).clamp(0.0, 1.0);
            let ring = 0.75 + 0.25 * (r * 20.0).cos();
            let v = (255.0 * ring) as u8;
            p.extend_from_slice(&[v, v, 255, (255.0 * a) as u8]);
        }
    }
    p
}

/// One vertex: window-space position (pixels, z in [-1, 1]) and colour.
#[derive(Clone, Copy, Debug)]
pub struct BenchVertex {
    pub pos: [f32; 3],
    pub color: [f32; 3],
}

/// The fixed-seed random triangles: each within a ~16-pixel box anywhere on the screen, with
/// a random depth slope and three random vertex colours.
pub fn triangles(cfg: &BenchConfig) -> Vec<BenchVertex> {
    let mut rng = XorShift::new(cfg.seed);
    let mut out = Vec::with_capacity(cfg.triangles * 3);
    for _ in 0..cfg.triangles {
        let cx = rng.range(-8.0, cfg.width as f32 + 8.0);
        let cy = rng.range(-8.0, cfg.height as f32 + 8.0);
        let cz = rng.range(-0.95, 0.95);
        for _ in 0..3 {
            out.push(BenchVertex {
                pos: [
                    cx + rng.range(-9.0, 9.0),
                    cy + rng.range(-9.0, 9.0),
                    (cz + rng.range(-0.04, 0.04)).clamp(-1.0, 1.0),
                ],
                color: [rng.next_f32(), rng.next_f32(), rng.next_f32()],
            });
        }
    }
    out
}

/// The state set once per context.
pub fn setup(gl: &mut dyn Gl, cfg: &BenchConfig) {
    gl.viewport(0, 0, cfg.width, cfg.height);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_LESS);
    gl.shade_model(GL_SMOOTH);
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear_depth(1.0);
    match cfg.workload {
        Workload::Triangles
        | Workload::Sprites
        | Workload::LitTriangles
        | Workload::Lines
        | Workload::Text
        | Workload::Uploads => {
            gl.matrix_mode(GL_PROJECTION);
            gl.ortho(0.0, cfg.width as f64, 0.0, cfg.height as f64, -1.0, 1.0);
            gl.matrix_mode(GL_MODELVIEW);
        }
        Workload::Fog
        | Workload::Horizon
        | Workload::Lightmap
        | Workload::Spheremap
        | Workload::Tunnel
        | Workload::TunnelNoFog
        | Workload::Objects
        | Workload::ObjectsNoFog
        | Workload::Combine4
        | Workload::Cubemap
        | Workload::Shadow
        | Workload::Accum
        | Workload::Lighting => {
            gl.matrix_mode(GL_PROJECTION);
            let aspect = cfg.width as f64 / cfg.height as f64;
            let far = if matches!(cfg.workload, Workload::Horizon | Workload::Accum) {
                2000.0
            } else {
                40.0
            };
            gl.frustum(-0.1 * aspect, 0.1 * aspect, -0.1, 0.1, 0.2, far);
            gl.matrix_mode(GL_MODELVIEW);
        }
        Workload::Overdraw => {
            gl.matrix_mode(GL_PROJECTION);
            gl.ortho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
            gl.matrix_mode(GL_MODELVIEW);
        }
    }
    if matches!(
        cfg.workload,
        Workload::Overdraw | Workload::Horizon | Workload::Accum
    ) {
        let (_, min, mag, aniso) = LADDER[cfg.quality.min(LADDER.len() - 1)];
        bench_texture_setup(gl, min, mag, aniso);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
        // The overdraw layers are depth-tested (each nearer than the last, so all are drawn).
        if cfg.workload != Workload::Overdraw {
            gl.disable(GL_DEPTH_TEST);
        }
        gl.clear_color(0.55, 0.7, 0.9, 1.0);
    }
    match cfg.workload {
        Workload::LitTriangles => bench_scenes::setup_lit_triangles(gl, cfg.width, cfg.height),
        Workload::Combine4 => bench_scenes::setup_combine4(
            gl,
            &bench_texture(),
            &light_map_texture(),
            &environment_texture(),
        ),
        Workload::Cubemap => bench_scenes::setup_cubemap(gl),
        Workload::Lines => bench_scenes::setup_lines(gl, cfg.width, cfg.height),
        Workload::Shadow => bench_scenes::setup_shadow(gl),
        Workload::Text => bench_scenes::setup_text(gl, cfg.width, cfg.height),
        Workload::Uploads => {
            if let WorkData::Uploads(px, _, _) = work_data(cfg) {
                bench_scenes::setup_uploads(gl, cfg.width, cfg.height, &px);
            }
        }
        _ => {}
    }
    if cfg.workload == Workload::Sprites {
        let mut name = [0u32];
        gl.gen_textures(1, &mut name);
        gl.bind_texture(GL_TEXTURE_2D, name[0]);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
        gl.tex_parameteri(
            GL_TEXTURE_2D,
            GL_TEXTURE_MIN_FILTER,
            GL_LINEAR_MIPMAP_LINEAR as i32,
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA8 as i32,
            64,
            64,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&sprite_texture()),
        );
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
        gl.enable(GL_TEXTURE_2D);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        gl.enable(GL_ALPHA_TEST);
        gl.alpha_func(GL_GREATER, 0.05);
        gl.depth_mask(0);
        gl.clear_color(0.1, 0.1, 0.15, 1.0);
    }
    if cfg.workload == Workload::Lightmap {
        let (_, min, mag, aniso) = LADDER[cfg.quality.min(LADDER.len() - 1)];
        gl.active_texture(GL_TEXTURE0);
        bench_texture_setup(gl, min, mag, aniso);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
        gl.active_texture(GL_TEXTURE1);
        let mut name = [0u32];
        gl.gen_textures(1, &mut name);
        gl.bind_texture(GL_TEXTURE_2D, name[0]);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_LUMINANCE as i32,
            64,
            64,
            0,
            GL_LUMINANCE,
            GL_UNSIGNED_BYTE,
            Some(&light_map_texture()),
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE as i32);
        gl.enable(GL_TEXTURE_2D);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_MODULATE as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_PREVIOUS as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_TEXTURE as i32);
        gl.tex_envf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0);
        gl.active_texture(GL_TEXTURE0);
        gl.clear_color(0.0, 0.0, 0.0, 1.0);
    }
    if cfg.workload == Workload::Spheremap {
        let mut name = [0u32];
        gl.gen_textures(1, &mut name);
        gl.bind_texture(GL_TEXTURE_2D, name[0]);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGB as i32,
            128,
            128,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            Some(&environment_texture()),
        );
        gl.tex_parameteri(
            GL_TEXTURE_2D,
            GL_TEXTURE_MIN_FILTER,
            GL_LINEAR_MIPMAP_LINEAR as i32,
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
        gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
        gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
        gl.depth_func(GL_LEQUAL);
        gl.blend_func(GL_ONE, GL_ONE);
        gl.materialfv(GL_FRONT, GL_DIFFUSE, &[0.6, 0.25, 0.15, 1.0]);
        gl.materialfv(GL_FRONT, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
        gl.materialf(GL_FRONT, GL_SHININESS, 32.0);
        gl.enable(GL_LIGHT0);
        gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.4, 1.0, 0.8, 0.0]);
        gl.clear_color(0.1, 0.1, 0.12, 1.0);
    }
    if cfg.workload == Workload::Lighting {
        gl.materialfv(GL_FRONT, GL_DIFFUSE, &[0.7, 0.6, 0.4, 1.0]);
        gl.materialfv(GL_FRONT, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
        gl.materialf(GL_FRONT, GL_SHININESS, 24.0);
        gl.enable(GL_LIGHT0);
        gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.4, 1.0, 0.8, 0.0]);
        gl.enable(GL_LIGHT1);
        gl.lightfv(GL_LIGHT1, GL_POSITION, &[-1.0, 0.5, -2.0, 1.0]);
        gl.lightfv(GL_LIGHT1, GL_DIFFUSE, &[0.3, 0.4, 0.9, 1.0]);
        gl.lightfv(GL_LIGHT1, GL_SPECULAR, &[0.3, 0.4, 0.9, 1.0]);
        gl.lightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2);
        gl.clear_color(0.1, 0.1, 0.12, 1.0);
    }
    if matches!(cfg.workload, Workload::Tunnel | Workload::TunnelNoFog) {
        let (_, min, mag, aniso) = LADDER[cfg.quality.min(LADDER.len() - 1)];
        bench_texture_setup(gl, min, mag, aniso);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
        gl.clear_color(0.25, 0.22, 0.2, 1.0);
        if cfg.workload == Workload::Tunnel {
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_EXP2 as i32);
            gl.fogf(GL_FOG_DENSITY, 0.07);
            gl.fogfv(GL_FOG_COLOR, &[0.25, 0.22, 0.2, 1.0]);
        }
        if let Some(t) = cfg.toggle {
            (TOGGLES[t.min(TOGGLES.len() - 1)].1)(gl);
        }
    }
    if matches!(cfg.workload, Workload::Objects | Workload::ObjectsNoFog) {
        let (_, min, mag, aniso) = LADDER[cfg.quality.min(LADDER.len() - 1)];
        bench_texture_setup(gl, min, mag, aniso);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
        gl.enable(GL_LIGHTING);
        gl.enable(GL_LIGHT0);
        gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 1.0, 0.6, 0.0]);
        gl.materialfv(GL_FRONT, GL_AMBIENT, &[0.3, 0.3, 0.3, 1.0]);
        gl.materialfv(GL_FRONT, GL_DIFFUSE, &[0.9, 0.85, 0.8, 1.0]);
        gl.materialfv(GL_FRONT, GL_SPECULAR, &[0.4, 0.4, 0.4, 1.0]);
        gl.materialf(GL_FRONT, GL_SHININESS, 20.0);
        gl.enable(GL_CULL_FACE);
        gl.clear_color(0.5, 0.55, 0.6, 1.0);
        if cfg.workload == Workload::Objects {
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_LINEAR as i32);
            gl.fogf(GL_FOG_START, 3.0);
            gl.fogf(GL_FOG_END, 16.0);
            gl.fogfv(GL_FOG_COLOR, &[0.5, 0.55, 0.6, 1.0]);
        }
        let list = gl.gen_lists(1);
        gl.new_list(list, GL_COMPILE);
        textured_torus(gl, 48, 24, 0.8, 0.35);
        gl.end_list();
    }
    if cfg.workload == Workload::Fog {
        gl.enable(GL_LIGHTING);
        gl.enable(GL_LIGHT0);
        gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 1.0, 0.5, 0.0]);
        gl.enable(GL_COLOR_MATERIAL);
        gl.enable(GL_NORMALIZE);
        gl.enable(GL_FOG);
        gl.fogi(GL_FOG_MODE, GL_EXP2 as i32);
        gl.fogf(GL_FOG_DENSITY, 0.09);
        gl.fogfv(GL_FOG_COLOR, &[0.6, 0.65, 0.75, 1.0]);
        gl.clear_color(0.6, 0.65, 0.75, 1.0);
    }
    if cfg.tiny_viewport {
        // `--tiny-viewport`: every primitive lands in one pixel (clears still cover the window).
        gl.viewport(0, 0, 1, 1);
    }
}

/// Segment `k` of the `lightmap` corridor (4 wide, 3 high, 2 long): floor, ceiling and two
/// walls, each a quad.
pub(crate) fn corridor_walls(k: usize) -> [[[f32; 3]; 4]; 4] {
    let (z0, z1) = (-2.0 * k as f32, -2.0 * (k + 1) as f32);
    [
        [
            [-2.0, -1.5, z0],
            [2.0, -1.5, z0],
            [2.0, -1.5, z1],
            [-2.0, -1.5, z1],
        ],
        [
            [-2.0, 1.5, z1],
            [2.0, 1.5, z1],
            [2.0, 1.5, z0],
            [-2.0, 1.5, z0],
        ],
        [
            [-2.0, -1.5, z1],
            [-2.0, -1.5, z0],
            [-2.0, 1.5, z0],
            [-2.0, 1.5, z1],
        ],
        [
            [2.0, -1.5, z0],
            [2.0, -1.5, z1],
            [2.0, 1.5, z1],
            [2.0, 1.5, z0],
        ],
    ]
}

/// The `horizon` ground plane: 800 wide, from 0.3 to 1500 units deep, the texture repeating
/// every 4 units.
pub(super) fn horizon_plane(gl: &mut dyn Gl) {
    gl.color_3f(1.0, 1.0, 1.0);
    gl.begin(GL_QUADS);
    let (w, near, far) = (400.0f32, -0.3f32, -1500.0f32);
    for (x, z) in [(-w, near), (w, near), (w, far), (-w, far)] {
        gl.tex_coord_2f(x / 4.0, z / 4.0);
        gl.vertex_3f(x, -1.0, z);
    }
    gl.end();
}

/// One frame: clear, the workload in immediate mode, glFinish.
pub fn frame(gl: &mut dyn Gl, data: &WorkData) {
    let sprites = matches!(data, WorkData::Sprites(_));
    if sprites {
        // glClear honours the depth mask: clear with writes on, draw with them off.
        gl.depth_mask(1);
    }
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if sprites {
        gl.depth_mask(0);
    }
    match data {
        WorkData::Triangles(verts) => {
            gl.begin(GL_TRIANGLES);
            for v in verts {
                gl.color_3fv(&v.color);
                gl.vertex_3fv(&v.pos);
            }
            gl.end();
        }
        WorkData::Sprites(sprites) => {
            gl.begin(GL_QUADS);
            for s in sprites {
                let [x, y] = s.centre;
                let h = s.half;
                gl.color_4fv(&s.color);
                gl.tex_coord_2f(0.0, 0.0);
                gl.vertex_3f(x - h, y - h, s.z);
                gl.tex_coord_2f(1.0, 0.0);
                gl.vertex_3f(x + h, y - h, s.z);
                gl.tex_coord_2f(1.0, 1.0);
                gl.vertex_3f(x + h, y + h, s.z);
                gl.tex_coord_2f(0.0, 1.0);
                gl.vertex_3f(x - h, y + h, s.z);
            }
            gl.end();
        }
        WorkData::Terrain(h) => {
            let n = TERRAIN_CELLS + 1;
            let step = 24.0 / TERRAIN_CELLS as f32;
            gl.load_identity();
            gl.rotatef(18.0, 1.0, 0.0, 0.0);
            gl.translatef(-12.0, -1.6, -26.0);
            let at = |i: usize, j: usize| h[j * n + i];
            let normal = |i: usize, j: usize| {
                let dx = at((i + 1).min(n - 1), j) - at(i.saturating_sub(1), j);
                let dz = at(i, (j + 1).min(n - 1)) - at(i, j.saturating_sub(1));
                [-dx, 2.0 * step, -dz]
            };
            for j in 0..TERRAIN_CELLS {
                gl.begin(GL_TRIANGLE_STRIP);
                for i in 0..n {
                    for jj in [j + 1, j] {
                        let y = at(i, jj);
                        gl.color_3f(0.35 + 0.3 * y, 0.55 + 0.2 * y, 0.3);
                        gl.normal_3fv(&normal(i, jj));
                        gl.vertex_3f(i as f32 * step, y, jj as f32 * step);
                    }
                }
                gl.end();
            }
        }
        WorkData::Overdraw(layers) => {
            gl.begin(GL_QUADS);
            for k in 0..*layers {
                // Each layer a different scale and rotation: minification from 1x to 8x.
                let scale = 1.0 + k as f32;
                let a = 0.2 * k as f32;
                let (c, s) = (a.cos() * scale, a.sin() * scale);
                gl.color_4f(1.0, 1.0 - 0.05 * k as f32, 0.8 + 0.02 * k as f32, 1.0);
                // Back to front: each layer nearer than the last passes the depth test.
                let z = -0.9 + 0.2 * k as f32;
                for (x, y) in [(-1.0f32, -1.0f32), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                    gl.tex_coord_2f(c * x - s * y, s * x + c * y);
                    gl.vertex_3f(x, y, z);
                }
            }
            gl.end();
        }
        WorkData::Horizon => {
            gl.load_identity();
            gl.rotatef(6.0, 1.0, 0.0, 0.0);
            horizon_plane(gl);
        }
        WorkData::Accum(passes) => {
            // Motion blur: the horizon turning a little between passes, averaged.
            for p in 0..*passes {
                if p > 0 {
                    gl.clear(GL_COLOR_BUFFER_BIT);
                }
                gl.load_identity();
                gl.rotatef(6.0, 1.0, 0.0, 0.0);
                gl.rotatef(1.5 * p as f32, 0.0, 1.0, 0.0);
                horizon_plane(gl);
                let op = if p == 0 { GL_LOAD } else { GL_ACCUM };
                gl.accum(op, 1.0 / *passes as f32);
            }
            gl.accum(GL_RETURN, 1.0);
        }
        WorkData::LitTriangles(verts) => bench_scenes::frame_lit_triangles(gl, verts),
        WorkData::Combine4(segments) => bench_scenes::frame_combine4(gl, *segments),
        WorkData::Cubemap(rings, sides) => bench_scenes::frame_cubemap(gl, *rings, *sides),
        WorkData::Lines(segs) => bench_scenes::frame_lines(gl, segs),
        WorkData::Shadow => bench_scenes::frame_shadow(gl),
        WorkData::Text(px, height) => bench_scenes::frame_text(gl, px, *height),
        WorkData::Uploads(px, width, height) => {
            bench_scenes::frame_uploads(gl, px, *width, *height)
        }
        WorkData::Lightmap(segments) => {
            gl.load_identity();
            gl.translatef(0.0, 0.0, -0.5);
            gl.color_3f(1.0, 1.0, 1.0);
            // A corridor 4 wide, 3 high, `segments` x 2 long: floor, ceiling and two walls,
            // each segment its own quad with its own light-map square.
            gl.begin(GL_QUADS);
            for k in 0..*segments {
                let walls = corridor_walls(k);
                for w in walls {
                    for (c, v) in w.iter().enumerate() {
                        let (u, t) = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)][c];
                        gl.multi_tex_coord_2f(GL_TEXTURE0, u * 2.0, t * 1.5);
                        gl.multi_tex_coord_2f(GL_TEXTURE1, u, t);
                        gl.vertex_3fv(v);
                    }
                }
            }
            gl.end();
        }
        WorkData::Spheremap(rings, sides) => {
            gl.load_identity();
            gl.translatef(0.0, 0.0, -4.0);
            gl.rotatef(35.0, 1.0, 0.0, 0.0);
            gl.rotatef(20.0, 0.0, 0.0, 1.0);
            // Pass 1: lit.
            gl.enable(GL_LIGHTING);
            torus(gl, *rings, *sides, 1.2, 0.5);
            // Pass 2: the environment, added.
            gl.disable(GL_LIGHTING);
            gl.enable(GL_TEXTURE_2D);
            gl.enable(GL_TEXTURE_GEN_S);
            gl.enable(GL_TEXTURE_GEN_T);
            gl.enable(GL_BLEND);
            gl.depth_mask(0);
            torus(gl, *rings, *sides, 1.2, 0.5);
            gl.depth_mask(1);
            gl.disable(GL_BLEND);
            gl.disable(GL_TEXTURE_GEN_S);
            gl.disable(GL_TEXTURE_GEN_T);
            gl.disable(GL_TEXTURE_2D);
        }
        WorkData::Sphere(stacks, slices, lit) => {
            gl.load_identity();
            gl.translatef(0.0, 0.0, -4.0);
            if *lit {
                gl.enable(GL_LIGHTING);
            } else {
                gl.disable(GL_LIGHTING);
                gl.color_3f(0.7, 0.6, 0.4);
            }
            bench_sphere(gl, *stacks, *slices);
        }
        WorkData::Tunnel(sides, segments) => {
            gl.load_identity();
            // Looking a little off the axis, so the far end is not centred.
            gl.rotatef(4.0, 0.0, 1.0, 0.0);
            gl.rotatef(3.0, 1.0, 0.0, 0.0);
            tunnel(gl, *sides, *segments);
        }
        WorkData::Objects(cols, rows) => {
            // Rows recede: the nearest at 4 units, the farthest at 13 (fog 3..16).
            for r in 0..*rows {
                for c in 0..*cols {
                    gl.load_identity();
                    let z = -4.0 - 3.0 * r as f32;
                    let x = (c as f32 - (*cols as f32 - 1.0) / 2.0) * (0.55 * -z);
                    let y = (r as f32 - (*rows as f32 - 1.0) / 2.0) * 0.5 * -z * 0.45;
                    gl.translatef(x, y, z);
                    gl.rotatef(25.0 + 17.0 * c as f32, 1.0, 0.0, 0.0);
                    gl.rotatef(11.0 * r as f32, 0.0, 0.0, 1.0);
                    gl.call_list(OBJECT_LIST);
                }
            }
        }
    }
    gl.finish();
}

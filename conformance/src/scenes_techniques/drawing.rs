//! Technique scenes of drawing with textures and buffers: antialiased points and lines, an
//! air-brush, CSG with the stencil buffer, Phong highlights, a reflection with a clip plane,
//! particles, environment-mapped bump mapping.

use super::*;

// ---------------------------------------------------------------------------------------------
// Antialiased points and lines through textures.

pub(super) const AA_POINTS: [(f32, f32); 6] = [
    (20.3, 100.4),
    (43.7, 108.2),
    (70.2, 96.6),
    (95.4, 111.3),
    (30.6, 80.7),
    (84.1, 79.3),
];
pub(super) const AA_LINES: [((f32, f32), (f32, f32)); 5] = [
    ((8.3, 10.4), (118.7, 30.2)),
    ((10.6, 60.3), (117.4, 18.7)),
    ((20.2, 8.6), (50.7, 66.1)),
    ((64.3, 5.2), (71.6, 68.4)),
    ((90.8, 12.3), (112.2, 64.7)),
];

pub(super) fn ex_antialiased_points_lines(gl: &mut dyn Gl) {
    clear_to(gl, [0.08, 0.08, 0.12]);
    ortho(gl, 256.0, 128.0);
    let colour = |gl: &mut dyn Gl, i: usize, a: f32| {
        let c = [
            [1.0, 0.4, 0.3],
            [0.4, 1.0, 0.5],
            [0.4, 0.6, 1.0],
            [1.0, 0.9, 0.3],
        ][i % 4];
        gl.color_4f(c[0], c[1], c[2], a);
    };
    // Left: aliased.
    gl.point_size(5.0);
    gl.begin(GL_POINTS);
    for (i, &(x, y)) in AA_POINTS.iter().enumerate() {
        colour(gl, i, 1.0);
        gl.vertex_2f(x, y);
    }
    gl.end();
    gl.line_width(3.0);
    gl.begin(GL_LINES);
    for (i, &(a, b)) in AA_LINES.iter().enumerate() {
        colour(gl, i, 1.0);
        gl.vertex_2f(a.0, a.1);
        gl.vertex_2f(b.0, b.1);
    }
    gl.end();
    // Right: textured quads, coverage in the texture's alpha.
    let disc = soft_disc(16, 0.55);
    tex2d(gl, 16, 16, GL_RGBA, &disc);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "disc", GL_TEXTURE_2D, 0, [16, 16, 1]);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (i, &(x, y)) in AA_POINTS.iter().enumerate() {
        colour(gl, i, 1.0);
        rect(gl, 128.0 + x - 4.0, y - 4.0, 128.0 + x + 4.0, y + 4.0);
    }
    // A profile across the line: alpha 1 in the middle, falling to 0 at the edges.
    let profile = paint(4, 16, 4, |_, v| {
        let x = (1.0 - (2.0 * v - 1.0).abs() * 1.0).clamp(0.0, 1.0);
        [1.0, 1.0, 1.0, (x * 1.6).min(1.0)]
    });
    tex2d(gl, 4, 16, GL_RGBA, &profile);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    for (i, &(a, b)) in AA_LINES.iter().enumerate() {
        colour(gl, i, 1.0);
        let d = [b.0 - a.0, b.1 - a.1];
        let l = (d[0] * d[0] + d[1] * d[1]).sqrt();
        let n = [-d[1] / l * 2.5, d[0] / l * 2.5];
        gl.begin(GL_QUADS);
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            let s = 2.0 * v - 1.0;
            gl.tex_coord_2f(u, v);
            gl.vertex_2f(128.0 + a.0 + u * d[0] + s * n[0], a.1 + u * d[1] + s * n[1]);
        }
        gl.end();
    }
    gl.disable(GL_BLEND);
    gl.disable(GL_TEXTURE_2D);
}

// ---------------------------------------------------------------------------------------------
// Air-brush.

pub(super) fn ex_airbrush(gl: &mut dyn Gl) {
    clear_to(gl, [0.93, 0.91, 0.85]);
    ortho(gl, 256.0, 128.0);
    let brush = gaussian_brush(32);
    tex2d(gl, 32, 32, GL_RGBA, &brush);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "brush", GL_TEXTURE_2D, 0, [32, 32, 1]);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    type Path<'a> = &'a dyn Fn(f32) -> (f32, f32);
    let strokes: [([f32; 3], Path); 3] = [
        ([0.85, 0.2, 0.15], &|t| {
            (12.3 + 104.0 * t, 90.2 + 18.0 * (t * 7.0).sin())
        }),
        ([0.15, 0.35, 0.8], &|t| {
            (64.1 + 40.0 * (t * TAU).cos(), 60.3 + 34.0 * (t * TAU).sin())
        }),
        ([0.2, 0.6, 0.2], &|t| {
            (14.2 + 100.0 * t, 18.4 + 60.0 * t * t)
        }),
    ];
    for (c, path) in strokes {
        gl.color_4f(c[0], c[1], c[2], 0.6);
        for k in 0..36 {
            let (x, y) = path(k as f32 / 35.0);
            rect(gl, x - 8.0, y - 8.0, x + 8.0, y + 8.0);
        }
    }
    gl.disable(GL_BLEND);
    snap_color(gl, "canvas", 256, 128);
    // The canvas as a texture, on a tilted sheet.
    let mut t = [0u32];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 128, 128, 0);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    panel(gl, 128, 0, 128, 128);
    gl.clear_color(0.2, 0.22, 0.28, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    camera(gl, 40.0, 1.0, [0.0, 0.0, 3.0], [0.0, 0.0, 0.0]);
    gl.rotatef(-35.0, 0.0, 1.0, 0.0);
    gl.rotatef(-20.0, 1.0, 0.0, 0.0);
    gl.begin(GL_QUADS);
    for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        gl.tex_coord_2f(u, v);
        gl.vertex_3f(2.0 * u - 1.0, 2.0 * v - 1.0, 0.0);
    }
    gl.end();
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// CSG with the stencil buffer.

pub(super) type Solid<'a> = &'a dyn Fn(&mut dyn Gl);

/// Colours the faces of `a` not culled by `cull` where they are inside (`inside`) or outside
/// the convex solid `b`: `a`'s depth, then `b`'s front faces +1 and back faces -1 where nearer,
/// then `a`'s colour where the count is right.
pub(super) fn csg_pass(
    gl: &mut dyn Gl,
    a: Solid,
    b: Solid,
    cull: GLenum,
    inside: bool,
    snap: Option<&str>,
) {
    gl.clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.enable(GL_CULL_FACE);
    gl.enable(GL_DEPTH_TEST);
    gl.color_mask(0, 0, 0, 0);
    gl.depth_mask(1);
    gl.depth_func(GL_LESS);
    gl.disable(GL_STENCIL_TEST);
    gl.cull_face(cull);
    a(gl);
    gl.depth_mask(0);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_ALWAYS, 0, 0xff);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_INCR);
    gl.cull_face(GL_BACK);
    b(gl);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_DECR);
    gl.cull_face(GL_FRONT);
    b(gl);
    if let Some(name) = snap {
        snap_stencil(gl, name, 256, 128);
    }
    gl.color_mask(1, 1, 1, 1);
    gl.depth_mask(1);
    gl.depth_func(GL_LEQUAL);
    gl.stencil_func(if inside { GL_NOTEQUAL } else { GL_EQUAL }, 0, 0xff);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
    gl.cull_face(cull);
    a(gl);
    gl.disable(GL_STENCIL_TEST);
}

pub(super) fn ex_csg_stencil(gl: &mut dyn Gl) {
    clear_to(gl, [0.12, 0.12, 0.16]);
    gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    let cube: Solid = &|gl| {
        material(gl, [0.85, 0.3, 0.2, 1.0], 0.0, 1.0);
        cuboid(gl, [0.0, 0.0, 0.0], [0.7, 0.7, 0.7]);
    };
    let ball: Solid = &|gl| {
        material(gl, [0.25, 0.45, 0.9, 1.0], 0.0, 1.0);
        sphere(gl, [0.45, 0.4, 0.5], 0.68, (24, 12), None);
    };
    for k in 0..2 {
        panel(gl, k * 128, 0, 128, 128);
        camera(gl, 38.0, 1.0, [1.8, 1.5, 3.0], [0.0, 0.0, 0.0]);
        lamp(gl, [0.3, 0.8, 1.0, 0.0]);
        if k == 0 {
            // Difference: the ball's back faces inside the cube, then the cube's front faces
            // outside the ball (they win wherever they are valid).
            csg_pass(gl, ball, cube, GL_FRONT, true, None);
            csg_pass(gl, cube, ball, GL_BACK, false, Some("count_cube_in_ball"));
        } else {
            csg_pass(gl, ball, cube, GL_BACK, true, None);
            csg_pass(gl, cube, ball, GL_BACK, true, None);
        }
    }
    gl.disable(GL_CULL_FACE);
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Phong highlights through a texture.

/// The highlight sphere map: (R . L)^shininess for the reflection direction each texel stands
/// for (GL 1.5 section 2.11.4: the texel at (s, t) holds the direction whose sphere-map
/// coordinates are (s, t)).
pub(super) fn highlight_map(size: usize, light: V3, shininess: f32) -> Vec<u8> {
    let l = norm(light);
    paint(size, size, 3, |s, t| {
        let (x, y) = (2.0 * s - 1.0, 2.0 * t - 1.0);
        let r2 = x * x + y * y;
        if r2 > 1.0 {
            return [0.0, 0.0, 0.0, 1.0];
        }
        let z = (1.0 - r2).sqrt();
        let r = [2.0 * z * x, 2.0 * z * y, 2.0 * z * z - 1.0];
        let h = dot(r, l).max(0.0).powf(shininess);
        [h, h, h * 0.95, 1.0]
    })
}

pub(super) fn ex_phong_highlight_texture(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.14]);
    gl.enable(GL_DEPTH_TEST);
    let light = [0.6, 0.7, 1.0];
    // The light is set with an identity modelview: its direction is in eye space.
    let setup = |gl: &mut dyn Gl, diffuse: [f32; 4], specular: f32| {
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        lamp(gl, [light[0], light[1], light[2], 0.0]);
        gl.lightfv(GL_LIGHT0, GL_SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
        material(gl, diffuse, specular, 40.0);
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        gl.frustum(-0.4, 0.4, -0.4, 0.4, 1.0, 10.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.translatef(0.0, 0.0, -3.0);
        gl.rotatef(25.0, 1.0, 0.0, 0.0);
    };
    let coords = |t: &Tri, k: usize| [t[k].0 * 4.0, t[k].1 * 2.0];
    // Left: per-vertex specular.
    panel(gl, 0, 0, 128, 128);
    setup(gl, [0.6, 0.36, 0.22, 1.0], 1.0);
    sphere(gl, [0.0; 3], 1.0, (12, 8), Some(&coords));
    // Right: base texture on unit 0, highlight sphere map added on unit 1.
    panel(gl, 128, 0, 128, 128);
    setup(gl, [0.75, 0.75, 0.75, 1.0], 0.0);
    let base = paint(16, 16, 3, |u, v| {
        let k = ((u * 4.0) as i32 + (v * 4.0) as i32) % 2;
        if k == 0 {
            [0.9, 0.55, 0.3, 1.0]
        } else {
            [0.75, 0.35, 0.25, 1.0]
        }
    });
    tex2d(gl, 16, 16, GL_RGB, &base);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    if unit_on(0) {
        gl.enable(GL_TEXTURE_2D);
    }
    gl.active_texture(GL_TEXTURE1);
    let h = highlight_map(64, light, 40.0);
    tex2d(gl, 64, 64, GL_RGB, &h);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "highlight_sphere_map", GL_TEXTURE_2D, 0, [64, 64, 1]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD as i32);
    gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    if unit_on(1) {
        gl.enable(GL_TEXTURE_2D);
    }
    gl.active_texture(GL_TEXTURE0);
    sphere(gl, [0.0; 3], 1.0, (12, 8), Some(&coords));
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Reflections with the stencil buffer and a clip plane.

pub(super) fn water_objects(gl: &mut dyn Gl) {
    material(gl, [0.9, 0.55, 0.2, 1.0], 0.4, 20.0);
    gl.push_matrix();
    gl.translatef(-0.3, 0.2, 0.0);
    gl.rotatef(70.0, 1.0, 0.0, 0.0);
    torus(gl, 0.6, 0.2, 24, 12);
    gl.pop_matrix();
    material(gl, [0.3, 0.7, 0.4, 1.0], 0.2, 10.0);
    sphere(gl, [0.95, 0.05, -0.3], 0.32, (16, 8), None);
}

pub(super) fn water(gl: &mut dyn Gl) {
    gl.begin(GL_TRIANGLES);
    gl.normal_3f(0.0, 1.0, 0.0);
    for (x, z) in [
        (-2.0, -2.0),
        (-2.0, 2.0),
        (2.0, 2.0),
        (-2.0, -2.0),
        (2.0, 2.0),
        (2.0, -2.0),
    ] {
        gl.vertex_3f(x, 0.0, z);
    }
    gl.end();
}

pub(super) fn ex_reflection_clip_plane(gl: &mut dyn Gl) {
    clear_to(gl, [0.55, 0.65, 0.8]);
    let light = [0.5, 1.0, 0.7, 0.0];
    for k in 0..2 {
        panel(gl, k * 128, 0, 128, 128);
        camera(gl, 40.0, 1.0, [0.0, 1.4, 3.4], [0.0, 0.0, 0.0]);
        gl.enable(GL_DEPTH_TEST);
        gl.enable(GL_CULL_FACE);
        // 1. Mark the water in the stencil buffer.
        gl.enable(GL_STENCIL_TEST);
        gl.stencil_func(GL_ALWAYS, 1, 0xff);
        gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
        gl.color_mask(0, 0, 0, 0);
        gl.depth_mask(0);
        water(gl);
        gl.color_mask(1, 1, 1, 1);
        gl.depth_mask(1);
        // 2. The mirrored objects where the water is, clipped at the water level.
        gl.stencil_func(GL_EQUAL, 1, 0xff);
        gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
        gl.push_matrix();
        gl.scalef(1.0, -1.0, 1.0);
        lamp(gl, light);
        if k == 1 {
            gl.clip_plane(GL_CLIP_PLANE0, &[0.0, 1.0, 0.0, 0.0]);
            gl.enable(GL_CLIP_PLANE0);
        }
        gl.front_face(GL_CW);
        water_objects(gl);
        gl.front_face(GL_CCW);
        gl.disable(GL_CLIP_PLANE0);
        gl.pop_matrix();
        gl.disable(GL_STENCIL_TEST);
        if k == 1 {
            snap_color(gl, "reflection_clipped", 256, 128);
        }
        // 3. The objects, then the water blended over (it hides their submerged parts).
        gl.lightfv(GL_LIGHT0, GL_POSITION, &light);
        water_objects(gl);
        gl.disable(GL_LIGHTING);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        gl.color_4f(0.15, 0.35, 0.55, 0.6);
        water(gl);
        gl.disable(GL_BLEND);
    }
    gl.disable(GL_CULL_FACE);
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Particle systems.

pub(super) fn ex_particles(gl: &mut dyn Gl) {
    clear_to(gl, [0.02, 0.02, 0.05]);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    let disc = soft_disc(16, 0.0);
    tex2d(gl, 16, 16, GL_RGBA, &disc);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_mask(0);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE);
    let mut rng = XorShift::new(7);
    let life = 1.6;
    let g = -2.0;
    gl.begin(GL_QUADS);
    for _ in 0..300 {
        let age = rng.range(0.0, life);
        let v = [
            rng.range(-0.35, 0.35),
            rng.range(1.9, 2.4),
            rng.range(-0.35, 0.35),
        ];
        let p = [
            v[0] * age,
            -0.9 + v[1] * age + 0.5 * g * age * age,
            -3.0 + v[2] * age,
        ];
        let f = age / life;
        gl.color_4f(1.0, 0.9 - 0.7 * f, 0.3 - 0.25 * f, 0.5 * (1.0 - f));
        let s = 0.05 + 0.05 * f;
        for (u, w) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.tex_coord_2f(u, w);
            gl.vertex_3f(p[0] + (2.0 * u - 1.0) * s, p[1] + (2.0 * w - 1.0) * s, p[2]);
        }
    }
    gl.end();
    gl.depth_mask(1);
    gl.disable(GL_BLEND);
}

// ---------------------------------------------------------------------------------------------
// Environment-mapped bump mapping.

/// Ripples around two centres: the height and its gradient over the unit square.
pub(super) fn ripples(u: f32, v: f32) -> (f32, f32, f32) {
    let mut h = (0.0, 0.0, 0.0);
    for (cu, cv, f) in [(0.3, 0.35, 26.0), (0.72, 0.7, 34.0)] {
        let (du, dv) = (u - cu, v - cv);
        let r = (du * du + dv * dv).sqrt().max(1e-4);
        let fall = (-r * 3.0).exp();
        h.0 += (f * r).sin() * fall;
        let d = (f * (f * r).cos() - 3.0 * (f * r).sin()) * fall;
        h.1 += d * du / r;
        h.2 += d * dv / r;
    }
    h
}

pub(super) fn ex_env_bump(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.14]);
    gl.enable(GL_DEPTH_TEST);
    // The sphere map: texel (s, t) holds the environment in the direction it stands for.
    let map = paint(128, 128, 3, |s, t| {
        let (x, y) = (2.0 * s - 1.0, 2.0 * t - 1.0);
        let r2 = x * x + y * y;
        if r2 > 1.0 {
            return [0.0, 0.0, 0.0, 1.0];
        }
        let z = (1.0 - r2).sqrt();
        let c = environment([2.0 * z * x, 2.0 * z * y, 2.0 * z * z - 1.0]);
        [c[0], c[1], c[2], 1.0]
    });
    tex2d(gl, 128, 128, GL_RGB, &map);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "sphere_map", GL_TEXTURE_2D, 0, [128, 128, 1]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    for k in 0..2 {
        panel(gl, k * 128, 0, 128, 128);
        camera(gl, 40.0, 1.0, [0.0, 0.0, 2.9], [0.0, 0.0, 0.0]);
        gl.rotatef(-12.0, 1.0, 0.0, 0.0);
        gl.rotatef(18.0, 0.0, 1.0, 0.0);
        let bump = if k == 1 { 0.008 } else { 0.0 };
        // The plate: z = 0 over x, y in [-1, 1]; T = +x, B = +y, N = +z.
        grid(gl, 64, &|gl, u, v| {
            let (_, du, dv) = ripples(u, v);
            let n = norm([-bump * du, -bump * dv, 1.0]);
            gl.normal_3f(n[0], n[1], n[2]);
            gl.vertex_3f(2.0 * u - 1.0, 2.0 * v - 1.0, 0.0);
        });
    }
    gl.disable(GL_TEXTURE_GEN_S);
    gl.disable(GL_TEXTURE_GEN_T);
    gl.disable(GL_SCISSOR_TEST);
}

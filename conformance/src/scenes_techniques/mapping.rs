//! Technique scenes of texture mapping: the environment modes, projector mappings, mipmaps,
//! ripmaps and summed-area tables, environment maps, texture-matrix animation, image warping,
//! detail textures, billboards and impostors.

use super::*;

// ---------------------------------------------------------------------------------------------
// Texture environment modes.

pub(super) fn ex_texenv_modes(gl: &mut dyn Gl) {
    clear_to(gl, [0.12, 0.12, 0.16]);
    let tex = paint(32, 32, 4, |u, v| {
        let d = ((u - 0.5).powi(2) + (v - 0.5).powi(2)).sqrt();
        let a = if d < 0.33 { 1.0 } else { 0.3 };
        if (u * 4.0) as i32 % 2 == 0 {
            [0.95, 0.8 + 0.15 * v, 0.2, a]
        } else {
            [0.15, 0.3 + 0.4 * v, 0.85, a]
        }
    });
    tex2d(gl, 32, 32, GL_RGBA, &tex);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "texture", GL_TEXTURE_2D, 0, [32, 32, 1]);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.95, 0.6, 0.1, 1.0]);
    let modes = [
        GL_REPLACE,
        GL_MODULATE,
        GL_DECAL,
        GL_BLEND,
        GL_ADD,
        GL_COMBINE,
    ];
    for (i, &mode) in modes.iter().enumerate() {
        panel(gl, (i as i32 % 3) * 96, (1 - i as i32 / 3) * 96, 96, 96);
        ortho(gl, 1.0, 1.0);
        // The checker backdrop.
        gl.disable(GL_TEXTURE_2D);
        gl.disable(GL_BLEND);
        gl.begin(GL_QUADS);
        for j in 0..6 {
            for k in 0..6 {
                let g = if (j + k) % 2 == 0 { 0.75 } else { 0.35 };
                gl.color_3f(g, g, g);
                let (x, y) = (k as f32 / 6.0, j as f32 / 6.0);
                gl.vertex_2f(x, y);
                gl.vertex_2f(x + 1.0 / 6.0, y);
                gl.vertex_2f(x + 1.0 / 6.0, y + 1.0 / 6.0);
                gl.vertex_2f(x, y + 1.0 / 6.0);
            }
        }
        gl.end();
        gl.enable(GL_TEXTURE_2D);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        if mode == GL_COMBINE {
            combine(
                gl,
                GL_INTERPOLATE,
                &[GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR],
            );
            gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_MODULATE as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_TEXTURE as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_PRIMARY_COLOR as i32);
        } else {
            gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, mode as i32);
        }
        // Colours and alpha affine in position (any split of the quad gives the same picture).
        let col = |x: f32, y: f32| [0.2 + 0.7 * x, 0.9 - 0.6 * y, 0.3 + 0.5 * y, 0.45 + 0.5 * x];
        gl.begin(GL_QUADS);
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            let (x, y) = (0.08 + 0.84 * u, 0.08 + 0.84 * v);
            let c = col(x, y);
            gl.color_4f(c[0], c[1], c[2], c[3]);
            gl.tex_coord_2f(u, v);
            gl.vertex_2f(x, y);
        }
        gl.end();
    }
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Projector mappings.

pub(super) fn grid_texture() -> Vec<u8> {
    paint(64, 64, 3, |u, v| {
        let (x, y) = ((u * 64.0) as i32, (v * 64.0) as i32);
        if x % 8 == 0 || y % 8 == 0 {
            return [0.95, 0.95, 0.95, 1.0];
        }
        match (u < 0.5, v < 0.5) {
            (true, true) => [0.85, 0.2, 0.15, 1.0],
            (false, true) => [0.2, 0.65, 0.25, 1.0],
            (true, false) => [0.2, 0.35, 0.85, 1.0],
            (false, false) => [0.9, 0.75, 0.15, 1.0],
        }
    })
}

pub(super) fn ex_projector_mappings(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.14]);
    let t = grid_texture();
    tex2d(gl, 64, 64, GL_RGB, &t);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_DEPTH_TEST);
    let cyl = |t: &Tri, k: usize| -> [f32; 2] {
        // The angle around the axis; the poles take their triangle's other corners' mean.
        let (u, _, p) = t[k];
        let s = if p[1].abs() > 0.9999 {
            let others: Vec<f32> = (0..3).filter(|&i| i != k).map(|i| t[i].0).collect();
            others.iter().sum::<f32>() / others.len() as f32
        } else {
            u
        };
        [s, 0.5 + 0.5 * p[1]]
    };
    let sph = |t: &Tri, k: usize| -> [f32; 2] { [cyl(t, k)[0], t[k].1] };
    let boxm = |t: &Tri, k: usize| -> [f32; 2] {
        let n = cross(sub(t[1].2, t[0].2), sub(t[2].2, t[0].2));
        let p = t[k].2;
        let (a, b) = if n[0].abs() >= n[1].abs() && n[0].abs() >= n[2].abs() {
            (p[2], p[1])
        } else if n[1].abs() >= n[2].abs() {
            (p[0], p[2])
        } else {
            (p[0], p[1])
        };
        [0.5 + 0.5 * a, 0.5 + 0.5 * b]
    };
    for i in 0..4 {
        panel(gl, (i % 2) * 128, (1 - i / 2) * 128, 128, 128);
        camera(gl, 34.0, 1.0, [1.2, 1.6, 3.6], [0.0, 0.0, 0.0]);
        lamp(gl, [0.5, 1.0, 1.0, 0.0]);
        material(gl, [1.0, 1.0, 1.0, 1.0], 0.0, 1.0);
        gl.color_3f(1.0, 1.0, 1.0);
        if i == 0 {
            for (c, plane) in [(GL_S, [0.5, 0.0, 0.0, 0.5]), (GL_T, [0.0, 0.5, 0.0, 0.5])] {
                gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR as i32);
                gl.tex_genfv(c, GL_OBJECT_PLANE, &plane);
            }
            gl.enable(GL_TEXTURE_GEN_S);
            gl.enable(GL_TEXTURE_GEN_T);
            sphere(gl, [0.0; 3], 1.0, (24, 12), None);
            gl.disable(GL_TEXTURE_GEN_S);
            gl.disable(GL_TEXTURE_GEN_T);
        } else {
            let f: Coords = match i {
                1 => &cyl,
                2 => &sph,
                _ => &boxm,
            };
            sphere(gl, [0.0; 3], 1.0, (24, 12), Some(f));
        }
    }
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Mipmaps, ripmaps, summed-area tables.

pub(super) const PF: usize = 128;

pub(super) fn stripes_texture() -> Vec<u8> {
    paint(PF, PF, 3, |u, v| {
        let (x, y) = ((u * PF as f32) as usize, (v * PF as f32) as usize);
        if x % 16 == 7 {
            return [0.05, 0.05, 0.05, 1.0];
        }
        let band = (y / 2) % 3;
        let c = [[0.95, 0.3, 0.2], [0.95, 0.95, 0.9], [0.2, 0.4, 0.9]][band];
        [c[0], c[1], c[2], 1.0]
    })
}

/// The rows of the prefilter scene: (bottom, height) in pixels.
pub(super) const PF_ROWS: [(f32, f32); 3] = [(72.0, 48.0), (36.0, 24.0), (12.0, 12.0)];

pub(super) fn ex_prefilter_mip_rip_sat(gl: &mut dyn Gl) {
    clear_to(gl, [0.12, 0.12, 0.16]);
    ortho(gl, 384.0, 128.0);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    let src = stripes_texture();
    // Mipmaps.
    tex2d(gl, PF as i32, PF as i32, GL_RGB, &src);
    sampling(
        gl,
        GL_TEXTURE_2D,
        GL_LINEAR_MIPMAP_LINEAR,
        GL_LINEAR,
        GL_CLAMP_TO_EDGE,
    );
    for (y, h) in PF_ROWS {
        rect(gl, 0.0, y, 128.0, y + h);
    }
    // Ripmaps: reductions by 2^j in y only (x needs none here).
    let mut rip = src.clone();
    let mut rows = PF;
    let mut levels = vec![(rows, rip.clone())];
    while rows > 1 {
        let next: Vec<u8> = (0..rows / 2)
            .flat_map(|y| {
                let rip = &rip;
                (0..PF * 3).map(move |i| {
                    let a = rip[2 * y * PF * 3 + i] as u32;
                    let b = rip[(2 * y + 1) * PF * 3 + i] as u32;
                    (a + b).div_ceil(2) as u8
                })
            })
            .collect();
        rows /= 2;
        rip = next;
        levels.push((rows, rip.clone()));
    }
    for (y, h) in PF_ROWS {
        let squeeze = PF as f32 / h;
        let j = (squeeze.log2().round() as usize).min(levels.len() - 1);
        let (r, px) = &levels[j];
        tex2d(gl, PF as i32, *r as i32, GL_RGB, px);
        sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
        rect(gl, 128.0, y, 256.0, y + h);
    }
    // Summed-area table: sat[(y, x)] = sum of the texels below and left, per channel.
    let w = PF + 1;
    let mut sat = vec![0u32; w * w * 3];
    for y in 0..PF {
        for x in 0..PF {
            for c in 0..3 {
                sat[((y + 1) * w + x + 1) * 3 + c] = src[(y * PF + x) * 3 + c] as u32
                    + sat[(y * w + x + 1) * 3 + c]
                    + sat[((y + 1) * w + x) * 3 + c]
                    - sat[(y * w + x) * 3 + c];
            }
        }
    }
    let area = |x0: usize, y0: usize, x1: usize, y1: usize, c: usize| -> f32 {
        let s = |x: usize, y: usize| sat[(y * w + x) * 3 + c] as i64;
        let sum = s(x1, y1) - s(x0, y1) - s(x1, y0) + s(x0, y0);
        sum as f32 / ((x1 - x0) * (y1 - y0)) as f32
    };
    for (y, h) in PF_ROWS {
        let squeeze = PF as f32 / h;
        let mut px = Vec::with_capacity(PF * PF * 3);
        for ty in 0..PF {
            let centre = ty as f32 + 0.5;
            let y0 = (centre - squeeze / 2.0).round().clamp(0.0, PF as f32 - 1.0) as usize;
            let y1 = ((centre + squeeze / 2.0).round() as usize).clamp(y0 + 1, PF);
            for tx in 0..PF {
                for c in 0..3 {
                    px.push(area(tx, y0, tx + 1, y1, c).round() as u8);
                }
            }
        }
        tex2d(gl, PF as i32, PF as i32, GL_RGB, &px);
        sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
        if h == PF_ROWS[1].1 {
            snap_texture(
                gl,
                "sat_filtered_5x",
                GL_TEXTURE_2D,
                0,
                [PF as i32, PF as i32, 1],
            );
        }
        rect(gl, 256.0, y, 384.0, y + h);
    }
}

// ---------------------------------------------------------------------------------------------
// Latitude-longitude and dual-paraboloid environment maps.

/// The environment, by direction (eye space: y up, +z towards the viewer).
pub(super) fn environment(d: V3) -> [f32; 3] {
    let d = norm(d);
    let sun = norm([0.5, 0.6, -0.6]);
    if dot(d, sun) > 0.97 {
        return [1.0, 0.95, 0.7];
    }
    let az = d[0].atan2(d[2]);
    if d[1].abs() < 0.25 {
        let k = ((az / (PI / 4.0)).round() as i32).rem_euclid(8);
        if (az - k as f32 * PI / 4.0).abs() < 0.12 || (az + TAU - k as f32 * PI / 4.0).abs() < 0.12
        {
            let c = [
                [0.9, 0.2, 0.2],
                [0.2, 0.8, 0.3],
                [0.3, 0.4, 0.95],
                [0.95, 0.85, 0.2],
            ];
            return c[k as usize % 4];
        }
    }
    if d[1] >= 0.0 {
        let t = d[1];
        [0.55 - 0.4 * t, 0.75 - 0.45 * t, 1.0 - 0.3 * t]
    } else {
        let check = ((az * 4.0 / PI).floor() as i32 + ((-d[1]) * 6.0) as i32).rem_euclid(2);
        if check == 0 {
            [0.45, 0.33, 0.2]
        } else {
            [0.3, 0.22, 0.14]
        }
    }
}

pub(super) fn ex_env_latlong_paraboloid(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.14]);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    let eye = [0.0, 0.0, 3.0];
    // Left: latitude-longitude, coordinates per vertex on the CPU.
    let ll = paint(128, 64, 3, |s, t| {
        let (az, el) = ((s - 0.5) * TAU, (t - 0.5) * PI);
        let c = environment([el.cos() * az.sin(), el.sin(), el.cos() * az.cos()]);
        [c[0], c[1], c[2], 1.0]
    });
    tex2d(gl, 128, 64, GL_RGB, &ll);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE as i32);
    snap_texture(gl, "latlong_map", GL_TEXTURE_2D, 0, [128, 64, 1]);
    panel(gl, 0, 0, 128, 128);
    camera(gl, 40.0, 1.0, eye, [0.0, 0.0, 0.0]);
    let reflect = |p: V3| -> V3 {
        let v = norm(sub(p, eye));
        let k = 2.0 * dot(p, v);
        [v[0] - k * p[0], v[1] - k * p[1], v[2] - k * p[2]]
    };
    let latlong = |t: &Tri, k: usize| -> [f32; 2] {
        let st: Vec<[f32; 2]> = t
            .iter()
            .map(|&(_, _, p)| {
                let r = reflect(p);
                [
                    0.5 + r[0].atan2(r[2]) / TAU,
                    0.5 + r[1].clamp(-1.0, 1.0).asin() / PI,
                ]
            })
            .collect();
        // The seam: a triangle spanning more than half the azimuths crosses it.
        let (lo, hi) = st
            .iter()
            .fold((f32::MAX, f32::MIN), |(a, b), v| (a.min(v[0]), b.max(v[0])));
        let mut s = st[k][0];
        if hi - lo > 0.5 && s < 0.5 {
            s += 1.0;
        }
        [s, st[k][1]]
    };
    sphere(gl, [0.0; 3], 1.0, (32, 16), Some(&latlong));
    // Right: dual paraboloid, reflection vector by GL.
    let para = |front: bool| -> Vec<u8> {
        paint(64, 64, 4, move |s, t| {
            let (x, y) = (2.0 * s - 1.0, 2.0 * t - 1.0);
            let r2 = x * x + y * y;
            let z = (1.0 - r2) / (1.0 + r2);
            let d = [
                2.0 * x / (1.0 + r2),
                2.0 * y / (1.0 + r2),
                if front { z } else { -z },
            ];
            let c = environment(d);
            [
                c[0],
                c[1],
                c[2],
                if !front || r2 <= 1.0 { 1.0 } else { 0.0 },
            ]
        })
    };
    let back = tex2d(gl, 64, 64, GL_RGBA, &para(false));
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "paraboloid_back", GL_TEXTURE_2D, 0, [64, 64, 1]);
    let front = tex2d(gl, 64, 64, GL_RGBA, &para(true));
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "paraboloid_front", GL_TEXTURE_2D, 0, [64, 64, 1]);
    panel(gl, 128, 0, 128, 128);
    for c in [GL_S, GL_T, GL_R] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP as i32);
    }
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    gl.enable(GL_TEXTURE_GEN_R);
    gl.tex_coord_4f(0.0, 0.0, 0.0, 1.0);
    gl.depth_func(GL_LEQUAL);
    for (tex, sign) in [(back, -1.0f32), (front, 1.0)] {
        // s = (rx / (1 + sign rz) + 1) / 2, t likewise: q = 1 + sign rz.
        gl.matrix_mode(GL_TEXTURE);
        gl.load_matrixf(&[
            0.5,
            0.0,
            0.0,
            0.0,
            0.0,
            0.5,
            0.0,
            0.0,
            0.5 * sign,
            0.5 * sign,
            0.0,
            sign,
            0.5,
            0.5,
            0.0,
            1.0,
        ]);
        gl.matrix_mode(GL_MODELVIEW);
        gl.bind_texture(GL_TEXTURE_2D, tex);
        if sign > 0.0 {
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_GREATER, 0.5);
        }
        sphere(gl, [0.0; 3], 1.0, (32, 16), None);
        if sign < 0.0 {
            snap_color(gl, "back_pass", 256, 128);
        }
    }
    gl.disable(GL_ALPHA_TEST);
    gl.matrix_mode(GL_TEXTURE);
    gl.load_identity();
    gl.matrix_mode(GL_MODELVIEW);
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Texture matrix animation.

pub(super) fn caustics() -> Vec<u8> {
    paint(32, 32, 3, |u, v| {
        let a = (TAU * (u * 2.0 + 0.3 * (TAU * v).sin())).sin();
        let b = (TAU * (v * 2.0 + 0.3 * (TAU * u).cos())).sin();
        let w = (0.5 + 0.25 * (a + b)).clamp(0.0, 1.0);
        [0.1 + 0.3 * w * w, 0.25 + 0.45 * w * w, 0.45 + 0.4 * w, 1.0]
    })
}

pub(super) fn ex_texture_matrix_animation(gl: &mut dyn Gl) {
    clear_to(gl, [0.0, 0.0, 0.0]);
    let c = caustics();
    tex2d(gl, 32, 32, GL_RGB, &c);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.active_texture(GL_TEXTURE1);
    tex2d(gl, 32, 32, GL_RGB, &c);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD as i32);
    if unit_on(1) {
        gl.enable(GL_TEXTURE_2D);
    }
    gl.active_texture(GL_TEXTURE0);
    for frame in 0..4 {
        let f = frame as f32;
        panel(gl, frame * 64, 0, 64, 64);
        ortho(gl, 1.0, 1.0);
        gl.matrix_mode(GL_TEXTURE);
        gl.active_texture(GL_TEXTURE0);
        gl.load_identity();
        gl.translatef(0.5 + 0.13 * f, 0.5 + 0.05 * f, 0.0);
        gl.rotatef(11.0 * f, 0.0, 0.0, 1.0);
        gl.translatef(-0.5, -0.5, 0.0);
        gl.active_texture(GL_TEXTURE1);
        gl.load_identity();
        gl.translatef(-0.07 * f, -0.17 * f, 0.0);
        gl.scalef(1.7, 1.7, 1.0);
        gl.active_texture(GL_TEXTURE0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.color_3f(1.0, 1.0, 1.0);
        gl.begin(GL_QUADS);
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.multi_tex_coord_2f(GL_TEXTURE0, u * 1.5, v * 1.5);
            gl.multi_tex_coord_2f(GL_TEXTURE1, u, v);
            gl.vertex_2f(u, v);
        }
        gl.end();
    }
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Image warping.

pub(super) fn picture() -> Vec<u8> {
    paint(64, 64, 3, |u, v| {
        let (x, y) = (u - 0.5, v - 0.5);
        let r = (x * x + y * y).sqrt();
        let check = ((u * 8.0) as i32 + (v * 8.0) as i32) % 2 == 0;
        let base = if check {
            [0.85, 0.85, 0.8]
        } else {
            [0.3, 0.45, 0.6]
        };
        if r < 0.22 {
            [0.95, 0.75, 0.2, 1.0]
        } else if (r - 0.3).abs() < 0.03 {
            [0.8, 0.15, 0.15, 1.0]
        } else {
            [base[0], base[1], base[2], 1.0]
        }
    })
}

/// The swirl: a point of the unit square turned about the centre by an angle falling off with
/// the distance.
pub(super) fn swirl(u: f32, v: f32, amount: f32) -> (f32, f32) {
    let (x, y) = (u - 0.5, v - 0.5);
    let r = (x * x + y * y).sqrt();
    let a = amount * (1.0 - (r / 0.5).min(1.0)).powi(2);
    let (s, c) = a.sin_cos();
    (0.5 + c * x - s * y, 0.5 + s * x + c * y)
}

pub(super) fn ex_image_warp(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.14]);
    let p = picture();
    tex2d(gl, 64, 64, GL_RGB, &p);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    for k in 0..3 {
        panel(gl, k * 128, 0, 128, 128);
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        gl.ortho(-0.05, 1.05, -0.05, 1.05, -1.0, 1.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        grid(gl, 16, &|gl, u, v| {
            let (w, z) = swirl(u, v, 2.2);
            match k {
                0 => {
                    gl.tex_coord_2f(u, v);
                    gl.vertex_2f(u, v);
                }
                1 => {
                    gl.tex_coord_2f(u, v);
                    gl.vertex_2f(w, z);
                }
                _ => {
                    gl.tex_coord_2f(w, z);
                    gl.vertex_2f(u, v);
                }
            }
        });
    }
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Detail textures.

pub(super) fn ex_detail_texture(gl: &mut dyn Gl) {
    clear_to(gl, [0.55, 0.7, 0.9]);
    camera(gl, 50.0, 1.0, [0.0, 0.9, 2.6], [0.0, 0.0, -1.0]);
    gl.enable(GL_DEPTH_TEST);
    let base = paint(16, 16, 3, |u, v| {
        let a = (TAU * u).sin() * (TAU * v).cos();
        [0.35 + 0.15 * a, 0.5 + 0.2 * (TAU * (u + v)).sin(), 0.2, 1.0]
    });
    tex2d(gl, 16, 16, GL_RGB, &base);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    snap_texture(gl, "base", GL_TEXTURE_2D, 0, [16, 16, 1]);
    gl.active_texture(GL_TEXTURE1);
    let mut rng = XorShift::new(25);
    let noise: Vec<u8> = (0..32 * 32)
        .flat_map(|_| {
            let g = (0.5 + rng.range(-0.22, 0.22)) * 255.0;
            [g as u8; 3]
        })
        .collect();
    tex2d(gl, 32, 32, GL_RGB, &noise);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    combine(gl, GL_ADD_SIGNED, &[GL_PREVIOUS, GL_TEXTURE]);
    snap_texture(gl, "detail", GL_TEXTURE_2D, 0, [32, 32, 1]);
    if unit_on(1) {
        gl.enable(GL_TEXTURE_2D);
    }
    gl.active_texture(GL_TEXTURE0);
    gl.color_3f(1.0, 1.0, 1.0);
    floor_quad(
        gl,
        [-4.0, 4.0],
        [-8.0, 2.5],
        &[(GL_TEXTURE0, 1.0, 1.0), (GL_TEXTURE1, 16.0, 16.0)],
    );
}

// ---------------------------------------------------------------------------------------------
// Billboards and impostors.

pub(super) fn tree_texture() -> Vec<u8> {
    paint(32, 64, 4, |u, v| {
        let trunk = (u - 0.5).abs() < 0.07 && v < 0.3;
        let crown = v >= 0.2 && (u - 0.5).abs() < 0.45 * (1.0 - (v - 0.2) / 0.8);
        if trunk {
            [0.4, 0.25, 0.1, 1.0]
        } else if crown {
            let shade = if ((v * 10.0) as i32) % 2 == 0 {
                0.0
            } else {
                0.12
            };
            [0.1 + shade, 0.5 + shade, 0.15, 1.0]
        } else {
            [0.0, 0.0, 0.0, 0.0]
        }
    })
}

pub(super) fn ex_billboards_impostors(gl: &mut dyn Gl) {
    // 1. The impostor: one lit torus rendered into a 64x64 corner, alpha 0 around it.
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.viewport(0, 0, 64, 64);
    camera(gl, 40.0, 1.0, [0.0, 1.2, 2.6], [0.0, 0.0, 0.0]);
    gl.enable(GL_DEPTH_TEST);
    lamp(gl, [0.4, 1.0, 0.8, 0.0]);
    material(gl, [0.9, 0.5, 0.2, 1.0], 0.5, 20.0);
    torus(gl, 0.75, 0.3, 24, 12);
    gl.disable(GL_LIGHTING);
    let mut t = [0u32];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 64, 64, 0);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "impostor", GL_TEXTURE_2D, 0, [64, 64, 1]);
    let impostor = t[0];
    let tree = tree_texture();
    let tree_tex = tex2d(gl, 32, 64, GL_RGBA, &tree);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    // 2. The scene.
    example_support::viewport(gl, 0, 0, 256, 128);
    clear_to(gl, [0.55, 0.72, 0.92]);
    let eye = [0.3, 1.6, 5.0];
    camera(gl, 40.0, 2.0, eye, [0.0, 0.4, 0.0]);
    gl.color_3f(0.35, 0.55, 0.25);
    gl.begin(GL_TRIANGLES);
    for (x, z) in [
        (-6.0, -6.0),
        (6.0, -6.0),
        (6.0, 4.0),
        (-6.0, -6.0),
        (6.0, 4.0),
        (-6.0, 4.0),
    ] {
        gl.vertex_3f(x, 0.0, z);
    }
    gl.end();
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_ALPHA_TEST);
    gl.alpha_func(GL_GREATER, 0.5);
    let billboard = |gl: &mut dyn Gl, p: V3, w: f32, h: f32| {
        gl.push_matrix();
        gl.translatef(p[0], p[1], p[2]);
        let yaw = (eye[0] - p[0]).atan2(eye[2] - p[2]).to_degrees();
        gl.rotatef(yaw, 0.0, 1.0, 0.0);
        gl.begin(GL_QUADS);
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.tex_coord_2f(u, v);
            gl.vertex_3f((u - 0.5) * w, v * h, 0.0);
        }
        gl.end();
        gl.pop_matrix();
    };
    gl.bind_texture(GL_TEXTURE_2D, tree_tex);
    for (i, p) in [
        [-2.6, 0.0, -1.0],
        [-1.4, 0.0, 0.6],
        [-3.4, 0.0, -3.5],
        [-0.7, 0.0, -2.8],
        [-2.0, 0.0, 2.0],
    ]
    .into_iter()
    .enumerate()
    {
        billboard(gl, p, 0.8 + 0.1 * i as f32, 1.7 + 0.2 * i as f32);
    }
    gl.bind_texture(GL_TEXTURE_2D, impostor);
    for p in [
        [1.3, 0.0, 0.8],
        [2.6, 0.0, -1.2],
        [1.0, 0.0, -3.0],
        [3.4, 0.0, 1.6],
    ] {
        billboard(gl, p, 1.2, 1.2);
    }
    gl.disable(GL_ALPHA_TEST);
}

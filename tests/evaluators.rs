//! Evaluators (section 5.1) against the specification: Bernstein sums evaluated in the test,
//! `glEvalMesh*`/`glEvalPoint*` against the `glBegin`/`glEvalCoord`/`glEnd` loops the
//! specification defines them as (bit for bit), the current values left alone, the analytic
//! normal, the state queries and the errors.

mod common;

use std::collections::BTreeSet;

use common::{pixel, read_rgba, threaded_context, window_ortho};
use tilegl::enums::*;
use tilegl::{Context, Gl};

fn context(w: i32, h: i32) -> Context {
    let mut gl = threaded_context(w, h, 2);
    window_ortho(&mut gl);
    gl
}

fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

/// B_i^n(t) from the closed form.
fn bern(n: usize, i: usize, t: f64) -> f64 {
    binomial(n, i) * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32)
}

/// A one-dimensional map of `k`-component points at `u` over [u1, u2].
fn curve(points: &[f64], k: usize, u1: f64, u2: f64, u: f64) -> Vec<f64> {
    let order = points.len() / k;
    let t = (u - u1) / (u2 - u1);
    (0..k)
        .map(|c| {
            (0..order)
                .map(|i| bern(order - 1, i, t) * points[i * k + c])
                .sum()
        })
        .collect()
}

/// A two-dimensional map (points (i, j) at (i * vorder + j) * k) at (u, v) over [0, 1]^2.
fn patch(points: &[f64], k: usize, uorder: usize, vorder: usize, u: f64, v: f64) -> Vec<f64> {
    (0..k)
        .map(|c| {
            let mut s = 0.0;
            for i in 0..uorder {
                for j in 0..vorder {
                    s += bern(uorder - 1, i, u)
                        * bern(vorder - 1, j, v)
                        * points[(i * vorder + j) * k + c];
                }
            }
            s
        })
        .collect()
}

fn lit_pixels(gl: &mut Context) -> BTreeSet<(i32, i32)> {
    let (w, _) = gl.size();
    read_rgba(gl)
        .iter()
        .enumerate()
        .filter(|(_, p)| p[0] > 0 || p[1] > 0 || p[2] > 0)
        .map(|(i, _)| (i as i32 % w, i as i32 / w))
        .collect()
}

/// Away from pixel edges, so that the pixel a size-1 point lands in is certain.
fn clear_of_edges(x: f64, y: f64) -> bool {
    let f = |a: f64| (a - a.floor() - 0.5).abs() < 0.45;
    f(x) && f(y)
}

#[test]
fn cubic_curve_points_land_on_the_bernstein_sum() {
    let mut gl = context(64, 64);
    // Stride 4: a padding value after each point.
    let ctrl = [
        4.3, 5.2, 0.0, 99.0, 12.7, 58.1, 0.0, 99.0, 50.2, 60.6, 0.0, 99.0, 59.4, 3.9, 0.0, 99.0f32,
    ];
    gl.map_1f(GL_MAP1_VERTEX_3, 0.25, 2.0, 4, 4, &ctrl);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid_1d(37, 0.25, 2.0);
    gl.eval_mesh_1(GL_POINT, 0, 37);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let packed: Vec<f64> = ctrl
        .chunks(4)
        .flat_map(|c| [c[0] as f64, c[1] as f64, c[2] as f64])
        .collect();
    let lit = lit_pixels(&mut gl);
    let mut checked = 0;
    for i in 0..=37 {
        let u = if i == 37 {
            2.0
        } else {
            i as f64 * (1.75 / 37.0) + 0.25
        };
        let p = curve(&packed, 3, 0.25, 2.0, u);
        if clear_of_edges(p[0], p[1]) {
            let at = (p[0].floor() as i32, p[1].floor() as i32);
            assert!(lit.contains(&at), "point {i} at {p:?} not drawn");
            checked += 1;
        }
    }
    assert!(checked > 25);
    assert!(lit.len() <= 38);
}

#[test]
fn bicubic_patch_points_land_on_the_tensor_product() {
    let mut gl = context(96, 96);
    let mut ctrl = Vec::new();
    for i in 0..4 {
        for j in 0..4 {
            let x = 6.0 + 26.0 * i as f64 + 3.7 * (j as f64 - 1.5).powi(2);
            let y = 5.0 + 27.0 * j as f64 + 2.9 * ((i * j) % 3) as f64;
            ctrl.extend_from_slice(&[x, y, 0.1 * (i + j) as f64]);
        }
    }
    // glMap2d with ustride 12 (points (i, j) at i * 12 + j * 3).
    gl.map_2d(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &ctrl);
    gl.enable(GL_MAP2_VERTEX_3);
    gl.map_grid_2f(9, 0.0, 1.0, 7, 0.0, 1.0);
    gl.eval_mesh_2(GL_POINT, 0, 9, 0, 7);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let lit = lit_pixels(&mut gl);
    let mut checked = 0;
    for i in 0..=9 {
        for j in 0..=7 {
            let p = patch(&ctrl, 3, 4, 4, i as f64 / 9.0, j as f64 / 7.0);
            if clear_of_edges(p[0], p[1]) {
                assert!(
                    lit.contains(&(p[0].floor() as i32, p[1].floor() as i32)),
                    "({i}, {j}) at {p:?}"
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 40, "{checked}");
    assert!(lit.len() <= 80);
}

/// A lit, coloured, textured bicubic patch: MAP2_VERTEX_4 (rational), colour, texture
/// coordinates and AUTO_NORMAL.
fn patch_state(gl: &mut Context) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.5, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -3.0);
    gl.rotatef(-35.0, 1.0, 0.0, 0.0);
    let mut ctrl = Vec::new();
    for i in 0..4 {
        for j in 0..4 {
            let (x, y) = (i as f32 / 1.5 - 1.0, j as f32 / 1.5 - 1.0);
            let z = if (i == 1 || i == 2) && (j == 1 || j == 2) {
                0.9
            } else {
                -0.2
            };
            let w = 1.0 + 0.3 * ((i + 2 * j) % 3) as f32;
            ctrl.extend_from_slice(&[x * w, y * w, z * w, w]);
        }
    }
    gl.map_2f(GL_MAP2_VERTEX_4, 0.0, 1.0, 16, 4, 0.0, 1.0, 4, 4, &ctrl);
    let colors = [
        1.0, 0.2, 0.2, 1.0, 0.2, 1.0, 0.2, 1.0, 0.2, 0.2, 1.0, 1.0, 1.0, 1.0, 0.2, 1.0f32,
    ];
    gl.map_2f(GL_MAP2_COLOR_4, 0.0, 1.0, 8, 2, 0.0, 1.0, 4, 2, &colors);
    let tc = [0.0, 0.0, 0.0, 2.0, 2.0, 0.0, 2.0, 2.0f32];
    gl.map_2f(GL_MAP2_TEXTURE_COORD_2, 0.0, 1.0, 4, 2, 0.0, 1.0, 2, 2, &tc);
    for t in [
        GL_MAP2_VERTEX_4,
        GL_MAP2_COLOR_4,
        GL_MAP2_TEXTURE_COORD_2,
        GL_AUTO_NORMAL,
        GL_LIGHTING,
        GL_LIGHT0,
        GL_COLOR_MATERIAL,
        GL_DEPTH_TEST,
        GL_TEXTURE_2D,
    ] {
        gl.enable(t);
    }
    gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 0.5, 1.0, 0.0]);
    let mut tex = [0u32];
    gl.gen_textures(1, &mut tex);
    gl.bind_texture(GL_TEXTURE_2D, tex[0]);
    let px: Vec<u8> = (0..16)
        .flat_map(|i| {
            if (i % 4 + i / 4) % 2 == 0 {
                [255u8, 255, 255, 255]
            } else {
                [120, 120, 200, 255]
            }
        })
        .collect();
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
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/// u at grid index i of n segments from a to b, as section 5.1 defines it.
fn grid(i: i32, n: i32, a: f64, b: f64) -> f64 {
    if i == n {
        b
    } else {
        i as f64 * ((b - a) / n as f64) + a
    }
}

#[test]
fn eval_mesh_2_is_the_specification_loop_bit_for_bit() {
    let (n, m) = (11, 8);
    let (u1, u2, v1, v2) = (0.1, 0.95, 0.0, 1.0);
    for (mode, poly, shade) in [
        (GL_FILL, GL_FILL, GL_SMOOTH),
        (GL_LINE, GL_FILL, GL_SMOOTH),
        (GL_POINT, GL_FILL, GL_SMOOTH),
        (GL_FILL, GL_LINE, GL_SMOOTH),
        // Flat shading: one colour per quad of the quad strips (the provoking vertex).
        (GL_FILL, GL_FILL, GL_FLAT),
    ] {
        let mut a = context(80, 80);
        patch_state(&mut a);
        a.shade_model(shade);
        a.polygon_mode(GL_FRONT_AND_BACK, poly);
        a.map_grid_2d(n, u1, u2, m, v1, v2);
        a.eval_mesh_2(mode, 1, n, 0, m - 1);
        assert_eq!(a.get_error(), GL_NO_ERROR);

        let mut b = context(80, 80);
        patch_state(&mut b);
        b.shade_model(shade);
        b.polygon_mode(GL_FRONT_AND_BACK, poly);
        b.map_grid_2d(n, u1, u2, m, v1, v2);
        let (p1, p2, q1, q2) = (1, n, 0, m - 1);
        let u = |i| grid(i, n, u1, u2);
        let v = |j| grid(j, m, v1, v2);
        match mode {
            GL_FILL => {
                for j in q1..q2 {
                    b.begin(GL_QUAD_STRIP);
                    for i in p1..=p2 {
                        b.eval_coord_2d(u(i), v(j));
                        b.eval_coord_2d(u(i), v(j + 1));
                    }
                    b.end();
                }
            }
            GL_LINE => {
                for j in q1..=q2 {
                    b.begin(GL_LINE_STRIP);
                    for i in p1..=p2 {
                        b.eval_coord_2dv(&[u(i), v(j)]);
                    }
                    b.end();
                }
                for i in p1..=p2 {
                    b.begin(GL_LINE_STRIP);
                    for j in q1..=q2 {
                        b.eval_coord_2d(u(i), v(j));
                    }
                    b.end();
                }
            }
            _ => {
                b.begin(GL_POINTS);
                for j in q1..=q2 {
                    for i in p1..=p2 {
                        // glEvalPoint2 is the same evaluation at the grid point.
                        b.eval_point_2(i, j);
                    }
                }
                b.end();
            }
        }
        let pa = read_rgba(&mut a);
        let pb = read_rgba(&mut b);
        assert!(
            pa.iter().filter(|p| p[0] > 0).count() > 50,
            "mode {mode:#x}"
        );
        assert!(
            pa == pb,
            "mode {mode:#x} polygon mode {poly:#x} shading {shade:#x}"
        );
    }
}

/// `MeshFill::TriangleStrips` (what Mesa draws, used by replays of Mesa captures) is the
/// same loop with `GL_TRIANGLE_STRIP`: bit for bit, and under flat shading not the
/// specification's quad strips (each triangle takes its own last vertex's colour).
#[test]
fn triangle_strip_meshes_are_the_loop_with_triangle_strips() {
    let (n, m) = (9, 6);
    let draw = |fill: tilegl::MeshFill, explicit: Option<GLenum>| {
        let mut gl = context(80, 80);
        gl.set_mesh_fill(fill);
        patch_state(&mut gl);
        gl.shade_model(GL_FLAT);
        gl.map_grid_2d(n, 0.0, 1.0, m, 0.0, 1.0);
        match explicit {
            None => gl.eval_mesh_2(GL_FILL, 0, n, 0, m),
            Some(prim) => {
                for j in 0..m {
                    gl.begin(prim);
                    for i in 0..=n {
                        gl.eval_coord_2d(grid(i, n, 0.0, 1.0), grid(j, m, 0.0, 1.0));
                        gl.eval_coord_2d(grid(i, n, 0.0, 1.0), grid(j + 1, m, 0.0, 1.0));
                    }
                    gl.end();
                }
            }
        }
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        read_rgba(&mut gl)
    };
    let triangles = draw(tilegl::MeshFill::TriangleStrips, None);
    assert!(triangles.iter().filter(|p| p[0] > 0).count() > 50);
    assert!(triangles == draw(tilegl::MeshFill::QuadStrips, Some(GL_TRIANGLE_STRIP)));
    let quads = draw(tilegl::MeshFill::QuadStrips, None);
    assert!(quads == draw(tilegl::MeshFill::TriangleStrips, Some(GL_QUAD_STRIP)));
    let differing = triangles.iter().zip(&quads).filter(|(a, b)| a != b).count();
    assert!(
        differing > 100,
        "flat-shaded triangle strips colour half of each quad differently ({differing} pixels)"
    );
}

#[test]
fn eval_mesh_1_is_the_specification_loop_bit_for_bit() {
    let ctrl = [
        5.0, 5.0, 0.0, 20.0, 60.0, 0.0, 40.0, -10.0, 0.0, 58.0, 50.0, 0.0f64,
    ];
    let colors = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0f64];
    for mode in [GL_LINE, GL_POINT] {
        let setup = |gl: &mut Context| {
            gl.map_1d(GL_MAP1_VERTEX_3, -1.0, 1.0, 3, 4, &ctrl);
            gl.map_1d(GL_MAP1_COLOR_4, -1.0, 1.0, 4, 2, &colors);
            gl.enable(GL_MAP1_VERTEX_3);
            gl.enable(GL_MAP1_COLOR_4);
            gl.map_grid_1f(23, -1.0, 1.0);
        };
        let mut a = context(64, 64);
        setup(&mut a);
        a.eval_mesh_1(mode, 2, 23);
        let mut b = context(64, 64);
        setup(&mut b);
        b.begin(if mode == GL_LINE {
            GL_LINE_STRIP
        } else {
            GL_POINTS
        });
        for i in 2..=23 {
            if i % 2 == 0 {
                b.eval_point_1(i);
            } else {
                b.eval_coord_1fv(&[grid(i, 23, -1.0, 1.0) as f32]);
            }
        }
        b.end();
        assert_eq!(a.get_error(), GL_NO_ERROR);
        assert!(read_rgba(&mut a) == read_rgba(&mut b), "mode {mode:#x}");
    }
}

#[test]
fn evaluated_colour_follows_the_map_and_leaves_the_current_values() {
    let mut gl = context(32, 32);
    let colors = [
        1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0f32,
    ];
    gl.map_1f(GL_MAP1_COLOR_4, 0.0, 1.0, 4, 3, &colors);
    gl.map_1f(
        GL_MAP1_VERTEX_3,
        0.0,
        1.0,
        3,
        2,
        &[0.0, 0.0, 0.0, 32.0, 0.0, 0.0],
    );
    gl.map_1f(GL_MAP1_NORMAL, 0.0, 1.0, 3, 1, &[1.0, 0.0, 0.0]);
    gl.map_1f(GL_MAP1_TEXTURE_COORD_2, 0.0, 1.0, 2, 1, &[0.5, 0.25]);
    gl.map_1f(
        GL_MAP1_TEXTURE_COORD_4,
        0.0,
        1.0,
        4,
        1,
        &[0.1, 0.2, 0.3, 0.4],
    );
    for t in [
        GL_MAP1_COLOR_4,
        GL_MAP1_VERTEX_3,
        GL_MAP1_NORMAL,
        GL_MAP1_TEXTURE_COORD_2,
    ] {
        gl.enable(t);
    }
    gl.color_4f(0.2, 0.4, 0.6, 0.8);
    gl.normal_3f(0.0, 1.0, 0.0);
    gl.tex_coord_2f(3.0, 4.0);
    // One point per pixel column at y = 10.5.
    gl.translatef(0.5, 10.5, 0.0);
    gl.begin(GL_POINTS);
    for x in 0..32 {
        gl.eval_coord_1f(x as f32 / 32.0);
    }
    // A glVertex after evaluation takes the current colour, not the evaluated one.
    gl.vertex_2f(5.0, 5.0);
    gl.end();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    for x in 0..32 {
        let u = x as f64 / 32.0;
        let c = curve(&colors.map(|v| v as f64), 4, 0.0, 1.0, u);
        let p = pixel(&mut gl, x, 10);
        for ch in 0..3 {
            let want = (c[ch] * 255.0).round() as i32;
            assert!((p[ch] as i32 - want).abs() <= 1, "x {x} {p:?} {c:?}");
        }
    }
    assert_eq!(pixel(&mut gl, 5, 15), [51, 102, 153, 204]);
    let mut v = [0f32; 4];
    gl.get_floatv(GL_CURRENT_COLOR, &mut v);
    assert_eq!(v, [0.2, 0.4, 0.6, 0.8]);
    gl.get_floatv(GL_CURRENT_NORMAL, &mut v[..3]);
    assert_eq!(&v[..3], &[0.0, 1.0, 0.0]);
    gl.get_floatv(GL_CURRENT_TEXTURE_COORDS, &mut v);
    assert_eq!(v, [3.0, 4.0, 0.0, 1.0]);
}

/// The colour a directional light along `l` gives a white diffuse surface with normal `n`
/// (no ambient, no specular).
fn diffuse(n: [f64; 3], l: [f64; 3]) -> u8 {
    let ll = (l[0] * l[0] + l[1] * l[1] + l[2] * l[2]).sqrt();
    let d = (n[0] * l[0] + n[1] * l[1] + n[2] * l[2]) / ll;
    (d.max(0.0) * 255.0).round() as u8
}

#[test]
fn auto_normal_is_the_normalized_cross_product_of_the_partials() {
    // A tilted plane z = 0.5 x + 0.25 y as a biquadratic (rational for VERTEX_4) patch: the
    // normal is (-0.5, -0.25, 1) normalized everywhere.
    let l = [0.2, 0.3, 1.0];
    let want_n = {
        let m: f64 = (0.25f64 + 0.0625 + 1.0).sqrt();
        [-0.5 / m, -0.25 / m, 1.0 / m]
    };
    // (target, k, u and v swapped, u domain reversed)
    for (target, k, swap, reversed) in [
        (GL_MAP2_VERTEX_3, 3, false, false),
        (GL_MAP2_VERTEX_4, 4, false, false),
        (GL_MAP2_VERTEX_3, 3, true, false),
        (GL_MAP2_VERTEX_3, 3, false, true),
    ] {
        let mut gl = context(32, 32);
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        gl.ortho(-1.0, 1.0, -1.0, 1.0, -5.0, 5.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        gl.enable(GL_LIGHTING);
        gl.enable(GL_LIGHT0);
        gl.light_modelfv(GL_LIGHT_MODEL_AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
        gl.materialfv(GL_FRONT_AND_BACK, GL_AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
        gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[1.0, 1.0, 1.0, 1.0]);
        gl.lightfv(
            GL_LIGHT0,
            GL_POSITION,
            &[l[0] as f32, l[1] as f32, l[2] as f32, 0.0],
        );
        let mut ctrl = Vec::new();
        for i in 0..3 {
            for j in 0..3 {
                let (mut x, mut y) = (i as f32 - 1.0, j as f32 - 1.0);
                if swap {
                    std::mem::swap(&mut x, &mut y);
                }
                let z = 0.5 * x + 0.25 * y;
                let w = if k == 4 {
                    1.0 + 0.5 * ((i + j) % 2) as f32
                } else {
                    1.0
                };
                ctrl.extend_from_slice(&[x * w, y * w, z * w, w][..k]);
            }
        }
        // A domain from 1 to 0 walks the same points, but dp/du changes sign (the chain
        // rule's 1 / (u2 - u1)), and so does the normal. Mesa differentiates in the
        // normalized u' instead and keeps the normal.
        let (u1, u2) = if reversed { (1.0, 0.0) } else { (0.0, 1.0) };
        gl.map_2f(
            target,
            u1,
            u2,
            3 * k as i32,
            3,
            0.0,
            1.0,
            k as i32,
            3,
            &ctrl,
        );
        gl.enable(target);
        gl.enable(GL_AUTO_NORMAL);
        gl.map_grid_2f(6, u1, u2, 6, 0.0, 1.0);
        gl.eval_mesh_2(GL_FILL, 0, 6, 0, 6);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        // Swapping u and v reverses the cross product: the normal faces away, unlit.
        let expect = if swap || reversed {
            diffuse([-want_n[0], -want_n[1], -want_n[2]], l)
        } else {
            diffuse(want_n, l)
        };
        let p = pixel(&mut gl, 16, 16);
        assert!(
            (p[0] as i32 - expect as i32).abs() <= 1,
            "{target:#x} swap {swap} reversed {reversed}: {p:?} want {expect}"
        );
    }
}

#[test]
fn no_vertex_map_no_vertex_and_highest_dimension_wins() {
    let mut gl = context(16, 16);
    gl.map_1f(GL_MAP1_COLOR_4, 0.0, 1.0, 4, 1, &[1.0, 0.0, 0.0, 1.0]);
    gl.enable(GL_MAP1_COLOR_4);
    gl.begin(GL_POINTS);
    gl.eval_coord_1f(0.5);
    gl.end();
    assert!(lit_pixels(&mut gl).is_empty());
    // VERTEX_4 over VERTEX_3: (4, 4, 0, 1) vs (10, 10, 0, 2) -> (5, 5).
    gl.map_1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 1, &[4.5, 4.5, 0.0]);
    gl.map_1f(GL_MAP1_VERTEX_4, 0.0, 1.0, 4, 1, &[11.0, 11.0, 0.0, 2.0]);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.enable(GL_MAP1_VERTEX_4);
    gl.begin(GL_POINTS);
    gl.eval_coord_1d(0.3);
    gl.end();
    assert_eq!(lit_pixels(&mut gl), BTreeSet::from([(5, 5)]));
    assert_eq!(pixel(&mut gl, 5, 5), [255, 0, 0, 255]);
}

#[test]
fn display_lists_store_maps_and_meshes() {
    let ctrl = [2.0, 2.0, 0.0, 30.0, 10.0, 0.0, 5.0, 28.0, 0.0f32];
    let mut a = context(32, 32);
    a.map_1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 3, &ctrl);
    a.enable(GL_MAP1_VERTEX_3);
    a.map_grid_1f(12, 0.0, 1.0);
    a.eval_mesh_1(GL_LINE, 0, 12);
    let mut b = context(32, 32);
    let list = b.gen_lists(1);
    b.new_list(list, GL_COMPILE);
    b.map_1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 3, &ctrl);
    b.enable(GL_MAP1_VERTEX_3);
    b.map_grid_1f(12, 0.0, 1.0);
    b.eval_mesh_1(GL_LINE, 0, 12);
    b.end_list();
    assert!(lit_pixels(&mut b).is_empty());
    b.call_list(list);
    assert_eq!(b.get_error(), GL_NO_ERROR);
    assert!(read_rgba(&mut a) == read_rgba(&mut b));
}

#[test]
fn queries_report_maps_grids_and_defaults() {
    let mut gl = context(8, 8);
    let mut i = [0i32; 4];
    gl.get_integerv(GL_MAX_EVAL_ORDER, &mut i);
    assert_eq!(i[0], 30);
    let mut f = [0f32; 4];
    gl.get_floatv(GL_MAP2_GRID_DOMAIN, &mut f);
    assert_eq!(f, [0.0, 1.0, 0.0, 1.0]);
    gl.get_integerv(GL_MAP2_GRID_SEGMENTS, &mut i);
    assert_eq!(&i[..2], &[1, 1]);
    // Defaults of every map: order 1, domain [0, 1], the initial current value.
    let defaults: [(GLenum, GLenum, &[f32]); 9] = [
        (GL_MAP1_VERTEX_3, GL_MAP2_VERTEX_3, &[0.0, 0.0, 0.0]),
        (GL_MAP1_VERTEX_4, GL_MAP2_VERTEX_4, &[0.0, 0.0, 0.0, 1.0]),
        (GL_MAP1_INDEX, GL_MAP2_INDEX, &[1.0]),
        (GL_MAP1_COLOR_4, GL_MAP2_COLOR_4, &[1.0, 1.0, 1.0, 1.0]),
        (GL_MAP1_NORMAL, GL_MAP2_NORMAL, &[0.0, 0.0, 1.0]),
        (GL_MAP1_TEXTURE_COORD_1, GL_MAP2_TEXTURE_COORD_1, &[0.0]),
        (
            GL_MAP1_TEXTURE_COORD_2,
            GL_MAP2_TEXTURE_COORD_2,
            &[0.0, 0.0],
        ),
        (
            GL_MAP1_TEXTURE_COORD_3,
            GL_MAP2_TEXTURE_COORD_3,
            &[0.0, 0.0, 0.0],
        ),
        (
            GL_MAP1_TEXTURE_COORD_4,
            GL_MAP2_TEXTURE_COORD_4,
            &[0.0, 0.0, 0.0, 1.0],
        ),
    ];
    for (m1, m2, coeff) in defaults {
        for (t, dims) in [(m1, 1), (m2, 2)] {
            assert_eq!(gl.is_enabled(t), 0);
            let mut v = [-7f32; 4];
            gl.get_mapfv(t, GL_COEFF, &mut v);
            assert_eq!(&v[..coeff.len()], coeff, "{t:#x}");
            let mut o = [0i32; 2];
            gl.get_mapiv(t, GL_ORDER, &mut o);
            assert_eq!(&o[..dims], &[1, 1][..dims]);
            let mut d = [0f64; 4];
            gl.get_mapdv(t, GL_DOMAIN, &mut d);
            assert_eq!(&d[..2 * dims], &[0.0, 1.0, 0.0, 1.0][..2 * dims]);
            gl.enable(t);
            assert_eq!(gl.is_enabled(t), 1);
            let mut b = [0u8; 1];
            gl.get_booleanv(t, &mut b);
            assert_eq!(b[0], 1);
        }
    }
    assert_eq!(gl.is_enabled(GL_AUTO_NORMAL), 0);
    gl.enable(GL_AUTO_NORMAL);
    assert_eq!(gl.is_enabled(GL_AUTO_NORMAL), 1);

    // A 2D map with strides: COEFF comes back packed, u-major.
    let mut pts = vec![0f64; 40];
    for i in 0..2 {
        for j in 0..3 {
            for c in 0..2 {
                pts[i * 20 + j * 5 + c] = (100 * i + 10 * j + c) as f64 + 0.4;
            }
        }
    }
    gl.map_2d(
        GL_MAP2_TEXTURE_COORD_2,
        -1.0,
        2.5,
        20,
        2,
        3.0,
        4.0,
        5,
        3,
        &pts,
    );
    let mut out = [0f64; 12];
    gl.get_mapdv(GL_MAP2_TEXTURE_COORD_2, GL_COEFF, &mut out);
    let want: Vec<f64> = (0..2)
        .flat_map(|i| {
            (0..3).flat_map(move |j| (0..2).map(move |c| (100 * i + 10 * j + c) as f64 + 0.4))
        })
        .collect();
    assert_eq!(out.to_vec(), want);
    let mut oi = [0i32; 12];
    gl.get_mapiv(GL_MAP2_TEXTURE_COORD_2, GL_COEFF, &mut oi);
    assert_eq!(oi[5], 21);
    gl.get_mapiv(GL_MAP2_TEXTURE_COORD_2, GL_ORDER, &mut oi);
    assert_eq!(&oi[..2], &[2, 3]);
    gl.get_mapiv(GL_MAP2_TEXTURE_COORD_2, GL_DOMAIN, &mut oi);
    assert_eq!(&oi[..4], &[-1, 3, 3, 4]);
    gl.map_grid_1d(5, 2.0, -3.0);
    let mut g = [0f64; 2];
    gl.get_doublev(GL_MAP1_GRID_DOMAIN, &mut g);
    assert_eq!(g, [2.0, -3.0]);
    gl.get_integerv(GL_MAP1_GRID_SEGMENTS, &mut i);
    assert_eq!(i[0], 5);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn errors_are_recorded_and_change_nothing() {
    let pts = [0.5f32; 64];
    type Call = fn(&mut Context, &[f32]);
    let cases: &[(&str, Call, GLenum)] = &[
        (
            "bad target",
            |gl, p| gl.map_1f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 2, p),
            GL_INVALID_ENUM,
        ),
        (
            "bad 2D target",
            |gl, p| gl.map_2f(GL_MAP1_COLOR_4, 0.0, 1.0, 4, 2, 0.0, 1.0, 8, 2, p),
            GL_INVALID_ENUM,
        ),
        (
            "u1 == u2",
            |gl, p| gl.map_1f(GL_MAP1_VERTEX_3, 1.0, 1.0, 3, 2, p),
            GL_INVALID_VALUE,
        ),
        (
            "v1 == v2",
            |gl, p| gl.map_2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 2, 2.0, 2.0, 6, 2, p),
            GL_INVALID_VALUE,
        ),
        (
            "order 0",
            |gl, p| gl.map_1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 0, p),
            GL_INVALID_VALUE,
        ),
        (
            "order 31",
            |gl, _| gl.map_1f(GL_MAP1_INDEX, 0.0, 1.0, 1, 31, &[0.0; 31]),
            GL_INVALID_VALUE,
        ),
        (
            "vorder 31",
            |gl, _| gl.map_2f(GL_MAP2_INDEX, 0.0, 1.0, 31, 1, 0.0, 1.0, 1, 31, &[0.0; 31]),
            GL_INVALID_VALUE,
        ),
        (
            "stride < k",
            |gl, p| gl.map_1f(GL_MAP1_COLOR_4, 0.0, 1.0, 3, 2, p),
            GL_INVALID_VALUE,
        ),
        (
            "vstride < k",
            |gl, p| gl.map_2f(GL_MAP2_NORMAL, 0.0, 1.0, 6, 2, 0.0, 1.0, 2, 2, p),
            GL_INVALID_VALUE,
        ),
        (
            "too few points",
            |gl, p| gl.map_1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &p[..11]),
            GL_INVALID_VALUE,
        ),
        (
            "grid 1 n = 0",
            |gl, _| gl.map_grid_1f(0, 0.0, 1.0),
            GL_INVALID_VALUE,
        ),
        (
            "grid 2 m < 0",
            |gl, _| gl.map_grid_2f(2, 0.0, 1.0, -1, 0.0, 1.0),
            GL_INVALID_VALUE,
        ),
        (
            "mesh 1 fill",
            |gl, _| gl.eval_mesh_1(GL_FILL, 0, 1),
            GL_INVALID_ENUM,
        ),
        (
            "mesh 2 bad mode",
            |gl, _| gl.eval_mesh_2(GL_LINE_STRIP, 0, 1, 0, 1),
            GL_INVALID_ENUM,
        ),
        (
            "get bad query",
            |gl, _| gl.get_mapfv(GL_MAP1_VERTEX_3, GL_ORDER + 7, &mut [0.0; 4]),
            GL_INVALID_ENUM,
        ),
        (
            "get bad target",
            |gl, _| gl.get_mapfv(GL_VERTEX_ARRAY, GL_ORDER, &mut [0.0; 4]),
            GL_INVALID_ENUM,
        ),
        (
            "map on unit 1",
            |gl, p| {
                gl.active_texture(GL_TEXTURE1);
                gl.map_1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 2, p);
                gl.active_texture(GL_TEXTURE0);
            },
            GL_INVALID_OPERATION,
        ),
        (
            "map inside begin",
            |gl, p| {
                gl.begin(GL_POINTS);
                gl.map_1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 2, p);
                gl.end();
            },
            GL_INVALID_OPERATION,
        ),
        (
            "map 2 inside begin",
            |gl, p| {
                gl.begin(GL_POINTS);
                gl.map_2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 2, 0.0, 1.0, 6, 2, p);
                gl.end();
            },
            GL_INVALID_OPERATION,
        ),
        (
            "grid inside begin",
            |gl, _| {
                gl.begin(GL_POINTS);
                gl.map_grid_1d(4, 0.0, 3.0);
                gl.end();
            },
            GL_INVALID_OPERATION,
        ),
        (
            "mesh inside begin",
            |gl, _| {
                gl.begin(GL_POINTS);
                gl.eval_mesh_2(GL_FILL, 0, 1, 0, 1);
                gl.end();
            },
            GL_INVALID_OPERATION,
        ),
        (
            "get map inside begin",
            |gl, _| {
                gl.begin(GL_POINTS);
                gl.get_mapfv(GL_MAP1_VERTEX_3, GL_ORDER, &mut [0.0; 4]);
                gl.end();
            },
            GL_INVALID_OPERATION,
        ),
    ];
    let snapshot = |gl: &mut Context| {
        let mut s = Vec::new();
        for t in [
            GL_MAP1_VERTEX_3,
            GL_MAP1_COLOR_4,
            GL_MAP2_VERTEX_3,
            GL_MAP2_NORMAL,
            GL_MAP1_INDEX,
            GL_MAP2_INDEX,
        ] {
            for q in [GL_COEFF, GL_ORDER, GL_DOMAIN] {
                let mut v = [0f64; 64];
                gl.get_mapdv(t, q, &mut v);
                s.push(v.to_vec());
            }
        }
        for q in [
            GL_MAP1_GRID_DOMAIN,
            GL_MAP1_GRID_SEGMENTS,
            GL_MAP2_GRID_DOMAIN,
            GL_MAP2_GRID_SEGMENTS,
        ] {
            let mut v = [0f64; 4];
            gl.get_doublev(q, &mut v);
            s.push(v.to_vec());
        }
        s
    };
    for (name, call, err) in cases {
        let mut gl = context(8, 8);
        let before = snapshot(&mut gl);
        call(&mut gl, &pts);
        assert_eq!(gl.get_error(), *err, "{name}");
        assert_eq!(gl.get_error(), GL_NO_ERROR, "{name}");
        assert_eq!(snapshot(&mut gl), before, "{name}");
    }
    // glEvalCoord and glEvalPoint are legal inside glBegin/glEnd.
    let mut gl = context(8, 8);
    gl.begin(GL_POINTS);
    gl.eval_coord_1f(0.5);
    gl.eval_coord_2d(0.5, 0.5);
    gl.eval_point_1(0);
    gl.eval_point_2(0, 1);
    gl.end();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

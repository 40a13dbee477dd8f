//! Rasterization checked against values derived independently in the test: coverage from
//! point-in-triangle tests on pixel centres, interpolation from the specification's equations,
//! and invariants (shared edges covered once, thread count and fast paths change nothing).

mod common;

use common::{pixel, random_texture, read_depth, read_rgba, threaded_context, window_ortho, Rng};
use tilegl::enums::*;
use tilegl::{Context, Gl};

/// Twice the signed area of (a, b, p).
fn orient(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
}

#[test]
fn coverage_matches_point_in_triangle_away_from_edges() {
    let mut rng = Rng(0x1234_5678);
    for _ in 0..60 {
        let mut gl = Context::new(64, 64);
        window_ortho(&mut gl);
        gl.clear(GL_COLOR_BUFFER_BIT);
        let v: Vec<[f64; 2]> = (0..3)
            .map(|_| [rng.range(-8.0, 72.0) as f64, rng.range(-8.0, 72.0) as f64])
            .collect();
        gl.begin(GL_TRIANGLES);
        gl.color_3f(1.0, 1.0, 1.0);
        for p in &v {
            gl.vertex_2f(p[0] as f32, p[1] as f32);
        }
        gl.end();
        let img = read_rgba(&mut gl);
        let area = orient(v[0], v[1], v[2]);
        for y in 0..64 {
            for x in 0..64 {
                let c = [x as f64 + 0.5, y as f64 + 0.5];
                // Normalised edge distances (in pixels); skip centres within 1/64 pixel of an
                // edge, where vertex snapping may legitimately decide either way.
                let d: Vec<f64> = (0..3)
                    .map(|i| {
                        let (a, b) = (v[i], v[(i + 1) % 3]);
                        let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
                        orient(a, b, c) * area.signum() / len.max(1e-9)
                    })
                    .collect();
                let covered = img[(y * 64 + x) as usize][0] == 255;
                if d.iter().all(|&e| e > 1.0 / 64.0) {
                    assert!(covered, "pixel ({x},{y}) inside {v:?} not covered");
                } else if d.iter().any(|&e| e < -1.0 / 64.0) {
                    assert!(!covered, "pixel ({x},{y}) outside {v:?} covered");
                }
            }
        }
    }
}

/// A jittered grid of triangles: lower triangles write only red, upper only green. Lower
/// triangles are adjacent only to upper ones, so a pixel with both channels was covered twice
/// and a black pixel inside the grid was missed: the fill rule must leave neither. Vertices sit
/// on pixel centres (whole-pixel jitter), so many edges pass exactly through pixel centres,
/// where the tie-breaking rule decides.
#[test]
fn shared_edges_are_covered_exactly_once() {
    let mut rng = Rng(99);
    let n = 9;
    let cell = 8.0f32;
    let mut grid = vec![[0f32; 2]; n * n];
    for j in 0..n {
        for i in 0..n {
            let mut jitter = |k: usize| {
                if k == 0 || k == n - 1 {
                    0.0
                } else {
                    (rng.next_u64() % 5) as f32 - 2.0
                }
            };
            let (jx, jy) = (jitter(i), jitter(j));
            // Border vertices at the framebuffer edge, inner ones on pixel centres.
            let at = |k: usize, d: f32| {
                if k == 0 || k == n - 1 {
                    k as f32 * cell
                } else {
                    k as f32 * cell + 0.5 + d
                }
            };
            grid[j * n + i] = [at(i, jx), at(j, jy)];
        }
    }
    let mut gl = Context::new(64, 64);
    window_ortho(&mut gl);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.color_3f(1.0, 1.0, 1.0);
    for (mask, upper) in [([1, 0, 0], false), ([0, 1, 0], true)] {
        gl.color_mask(mask[0], mask[1], mask[2], 1);
        gl.begin(GL_TRIANGLES);
        for j in 0..n - 1 {
            for i in 0..n - 1 {
                let (a, b, c, d) = (
                    grid[j * n + i],
                    grid[j * n + i + 1],
                    grid[(j + 1) * n + i + 1],
                    grid[(j + 1) * n + i],
                );
                let tri = if upper { [a, c, d] } else { [a, b, c] };
                for p in tri {
                    gl.vertex_2f(p[0], p[1]);
                }
            }
        }
        gl.end();
    }
    let img = read_rgba(&mut gl);
    for (i, p) in img.iter().enumerate() {
        assert!(!(p[0] == 255 && p[1] == 255), "pixel {} covered twice", i);
        assert!(p[0] == 255 || p[1] == 255, "pixel {} not covered", i);
    }
}

/// Colour on a quad seen in perspective must be the perspective-correct interpolation: the
/// expected value is computed by intersecting each pixel's eye ray with the quad's plane.
#[test]
fn interpolation_is_perspective_correct() {
    let mut gl = Context::new(64, 64);
    gl.matrix_mode(GL_PROJECTION);
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 100.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.clear(GL_COLOR_BUFFER_BIT);
    // A floor-like quad from z = -1.5 (near, red = 0) to z = -20 (far, red = 1).
    let (z_near, z_far) = (-1.5f64, -20.0f64);
    gl.begin(GL_QUADS);
    gl.color_3f(0.0, 0.0, 1.0);
    gl.vertex_3f(-4.0, -1.0, z_near as f32);
    gl.vertex_3f(4.0, -1.0, z_near as f32);
    gl.color_3f(1.0, 0.0, 1.0);
    gl.vertex_3f(4.0, -1.0, z_far as f32);
    gl.vertex_3f(-4.0, -1.0, z_far as f32);
    gl.end();
    let mut checked = 0;
    for y in 0..64 {
        let yc = y as f64 + 0.5;
        let ndc_y = yc / 32.0 - 1.0; // eye ray direction (ndc_y, -1) scaled by near = 1
        if ndc_y >= -0.06 {
            continue; // above the horizon of the quad or too close to it
        }
        // Ray (x*t, ndc_y*t, -t) meets the plane y = -1 at t = -1/ndc_y, z = 1/ndc_y.
        let z = 1.0 / ndc_y;
        if z > z_near - 0.05 || z < z_far + 0.05 {
            continue;
        }
        let expected = (z - z_near) / (z_far - z_near);
        let p = pixel(&mut gl, 32, y);
        let got = p[0] as f64 / 255.0;
        assert!(
            (got - expected).abs() <= 1.5 / 255.0,
            "row {y}: red {got}, expected {expected}"
        );
        checked += 1;
    }
    assert!(checked > 10, "too few rows checked ({checked})");
}

/// Flat shading takes the colour of the provoking vertex of each primitive (table 2.9).
#[test]
fn flat_shading_uses_the_provoking_vertex() {
    let colors = [
        [255u8, 0, 0],
        [0, 255, 0],
        [0, 0, 255],
        [255, 255, 0],
        [0, 255, 255],
        [255, 0, 255],
    ];
    // (mode, vertex count, index of the provoking vertex of the first primitive)
    let cases = [
        (GL_TRIANGLES, 3, 2),
        (GL_TRIANGLE_STRIP, 3, 2),
        (GL_TRIANGLE_FAN, 3, 2),
        (GL_QUADS, 4, 3),
        (GL_QUAD_STRIP, 4, 3),
        (GL_POLYGON, 4, 0),
    ];
    for (mode, count, provoking) in cases {
        let mut gl = Context::new(32, 32);
        window_ortho(&mut gl);
        gl.shade_model(GL_FLAT);
        gl.clear(GL_COLOR_BUFFER_BIT);
        // A square (quad strip order differs: 0,1 bottom, 2,3 top).
        let pts: [[f32; 2]; 4] = if mode == GL_QUAD_STRIP {
            [[4.0, 4.0], [28.0, 4.0], [4.0, 28.0], [28.0, 28.0]]
        } else {
            [[4.0, 4.0], [28.0, 4.0], [28.0, 28.0], [4.0, 28.0]]
        };
        gl.begin(mode);
        for i in 0..count {
            let c = colors[i];
            gl.color_3ub(c[0], c[1], c[2]);
            gl.vertex_2f(pts[i][0], pts[i][1]);
        }
        gl.end();
        let c = colors[provoking];
        let p = pixel(&mut gl, 20, 10);
        assert_eq!(p, [c[0], c[1], c[2], 255], "mode {mode:#x}");
    }
}

/// Every depth function against a reference plane at depth 0.5, for a plane at 0.25 and 0.75.
#[test]
fn depth_functions_follow_the_comparison() {
    let funcs = [
        (GL_NEVER, [false, false, false]),
        (GL_LESS, [true, false, false]),
        (GL_EQUAL, [false, true, false]),
        (GL_LEQUAL, [true, true, false]),
        (GL_GREATER, [false, false, true]),
        (GL_NOTEQUAL, [true, false, true]),
        (GL_GEQUAL, [false, true, true]),
        (GL_ALWAYS, [true, true, true]),
    ];
    for (func, expect) in funcs {
        for (k, z) in [-0.5f32, 0.0, 0.5].into_iter().enumerate() {
            let mut gl = Context::new(16, 16);
            gl.enable(GL_DEPTH_TEST);
            gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            gl.color_3f(0.0, 0.0, 1.0);
            gl.rectf(-1.0, -1.0, 1.0, 1.0); // z = 0 -> window depth 0.5
            gl.depth_func(func);
            gl.color_3f(1.0, 0.0, 0.0);
            gl.begin(GL_QUADS);
            for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                gl.vertex_3f(x, y, z);
            }
            gl.end();
            let p = pixel(&mut gl, 8, 8);
            let red = p[0] == 255;
            assert_eq!(red, expect[k], "func {func:#x}, z {z}");
        }
    }
}

/// Attributes at a user-clip-plane boundary: with an orthographic projection, colour is linear
/// in window x, so every pixel equals the analytic value after clipping.
#[test]
fn clipped_attributes_are_interpolated_exactly() {
    let mut gl = Context::new(64, 8);
    window_ortho(&mut gl);
    gl.clip_plane(GL_CLIP_PLANE0, &[-1.0, 0.0, 0.0, 40.0]); // keep x <= 40
    gl.enable(GL_CLIP_PLANE0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.begin(GL_QUADS);
    gl.color_3f(0.0, 0.0, 0.0);
    gl.vertex_2f(0.0, 0.0);
    gl.color_3f(1.0, 0.0, 0.0);
    gl.vertex_2f(64.0, 0.0);
    gl.vertex_2f(64.0, 8.0);
    gl.color_3f(0.0, 0.0, 0.0);
    gl.vertex_2f(0.0, 8.0);
    gl.end();
    for x in 0..64 {
        let p = pixel(&mut gl, x, 4);
        if x < 40 {
            let expected = (x as f64 + 0.5) / 64.0 * 255.0;
            assert!(
                (p[0] as f64 - expected).abs() <= 1.0,
                "x {x}: {} vs {expected}",
                p[0]
            );
        } else {
            assert_eq!(p, [0, 0, 0, 0], "x {x} should be clipped");
        }
    }
}

fn busy_scene(gl: &mut Context) {
    let mut rng = Rng(7);
    gl.enable(GL_DEPTH_TEST);
    gl.clear_color(0.2, 0.1, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.begin(GL_TRIANGLES);
    for _ in 0..600 {
        let (cx, cy, cz) = (
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-9.0, -0.5),
        );
        for _ in 0..3 {
            gl.color_3f(
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
            );
            gl.vertex_3f(
                cx + rng.range(-1.0, 1.0),
                cy + rng.range(-1.0, 1.0),
                cz + rng.range(-1.0, 1.0),
            );
        }
    }
    gl.end();
    gl.begin(GL_LINES);
    for _ in 0..100 {
        gl.vertex_3f(
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-9.0, -0.5),
        );
    }
    gl.end();
    gl.begin(GL_POINTS);
    for _ in 0..100 {
        gl.vertex_3f(
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-9.0, -0.5),
        );
    }
    gl.end();
}

#[test]
fn output_is_identical_for_1_2_and_8_threads() {
    let render = |threads| {
        let mut gl = threaded_context(200, 150, threads);
        busy_scene(&mut gl);
        let depth = read_depth(&mut gl);
        (read_rgba(&mut gl), depth)
    };
    let one = render(1);
    assert_eq!(one, render(2));
    assert_eq!(one, render(8));
    assert!(one.0.iter().any(|p| *p != one.0[0]), "scene drew nothing");
}

/// The specialised span functions and the general path give identical pixels.
#[test]
fn fast_paths_match_the_general_path() {
    let keys: [(GLenum, u8, [u8; 4]); 5] = [
        (GL_LESS, 1, [1, 1, 1, 1]),
        (GL_LEQUAL, 1, [1, 1, 1, 1]),
        (GL_GREATER, 1, [1, 0, 1, 1]),
        (GL_LESS, 0, [1, 1, 0, 1]),
        (GL_ALWAYS, 1, [1, 1, 1, 1]),
    ];
    // No fog (the specialised spans), then each fog mode (the fogged spans).
    let fogs = [None, Some(GL_LINEAR), Some(GL_EXP), Some(GL_EXP2)];
    for (func, mask, cmask) in keys {
        for depth_test in [true, false] {
            for fog in fogs {
                let render = |general| {
                    let mut gl = Context::new(96, 96);
                    gl.set_force_general_path(general);
                    busy_scene(&mut gl);
                    if !depth_test {
                        gl.disable(GL_DEPTH_TEST);
                    }
                    if let Some(mode) = fog {
                        gl.enable(GL_FOG);
                        gl.fogi(GL_FOG_MODE, mode as i32);
                        gl.fogf(GL_FOG_DENSITY, 0.3);
                        gl.fogf(GL_FOG_START, 1.0);
                        gl.fogf(GL_FOG_END, 8.0);
                        gl.fogfv(GL_FOG_COLOR, &[0.2, 0.5, 0.9, 1.0]);
                    }
                    gl.depth_func(func);
                    gl.depth_mask(mask);
                    gl.color_mask(cmask[0], cmask[1], cmask[2], cmask[3]);
                    busy_scene_again(&mut gl);
                    read_rgba(&mut gl)
                };
                let general = render(true);
                assert_eq!(
                    general,
                    render(false),
                    "func {func:#x} mask {mask} cmask {cmask:?} fog {fog:?}"
                );
                if fog.is_some() && cmask == [1; 4] {
                    assert_ne!(
                        general,
                        {
                            let mut gl = Context::new(96, 96);
                            busy_scene(&mut gl);
                            if !depth_test {
                                gl.disable(GL_DEPTH_TEST);
                            }
                            gl.depth_func(func);
                            gl.depth_mask(mask);
                            busy_scene_again(&mut gl);
                            read_rgba(&mut gl)
                        },
                        "fog changed nothing"
                    );
                }
            }
        }
    }
}

fn busy_scene_again(gl: &mut Context) {
    random_strip(gl, 11, false);
}

/// A strip of 200 random vertices with random colours (and, when `translucent`, random
/// alphas) spread through the view volume of [`busy_scene`].
fn random_strip(gl: &mut Context, seed: u64, translucent: bool) {
    let mut rng = Rng(seed);
    gl.begin(GL_TRIANGLE_STRIP);
    for _ in 0..200 {
        let (r, g, b) = (
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
        );
        if translucent {
            gl.color_4f(r, g, b, rng.range(0.0, 1.0));
        } else {
            gl.color_3f(r, g, b);
        }
        gl.vertex_3f(
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-9.0, -0.5),
        );
    }
    gl.end();
}

#[test]
fn scissor_and_color_mask_limit_writes() {
    let mut gl = Context::new(32, 32);
    gl.clear_color(0.0, 0.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(8, 8, 8, 8);
    gl.color_mask(1, 0, 1, 1);
    gl.color_3f(1.0, 1.0, 0.0);
    gl.rectf(-1.0, -1.0, 1.0, 1.0);
    assert_eq!(pixel(&mut gl, 10, 10), [255, 0, 0, 255]);
    assert_eq!(pixel(&mut gl, 20, 10), [0, 0, 255, 255]);
    assert_eq!(pixel(&mut gl, 7, 10), [0, 0, 255, 255]);
    // Clear obeys the scissor and the colour mask too.
    gl.clear_color(0.0, 1.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    assert_eq!(pixel(&mut gl, 10, 10), [0, 0, 0, 0]);
    assert_eq!(pixel(&mut gl, 20, 20), [0, 0, 255, 255]);
}

#[test]
fn culling_and_front_face() {
    // (cull face, front face, clockwise?, drawn?)
    let cases = [
        (GL_BACK, GL_CCW, false, true),
        (GL_BACK, GL_CCW, true, false),
        (GL_FRONT, GL_CCW, false, false),
        (GL_FRONT, GL_CW, false, true),
        (GL_FRONT_AND_BACK, GL_CCW, false, false),
        (GL_BACK, GL_CW, false, false),
    ];
    for (cull, front, cw, drawn) in cases {
        let mut gl = Context::new(16, 16);
        gl.enable(GL_CULL_FACE);
        gl.cull_face(cull);
        gl.front_face(front);
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.color_3f(1.0, 1.0, 1.0);
        gl.begin(GL_TRIANGLES);
        let mut v = vec![[-1.0f32, -1.0], [1.0, -1.0], [0.0, 1.0]];
        if cw {
            v.swap(1, 2);
        }
        for p in v {
            gl.vertex_2f(p[0], p[1]);
        }
        gl.end();
        assert_eq!(
            pixel(&mut gl, 8, 6)[0] == 255,
            drawn,
            "cull {cull:#x} front {front:#x} cw {cw}"
        );
    }
}

#[test]
fn get_converts_types_per_section_6_1_2() {
    let mut gl = Context::new(16, 16);
    gl.clear_color(1.0, 0.0, 0.5, -1.0);
    let mut i = [0i32; 4];
    gl.get_integerv(GL_COLOR_CLEAR_VALUE, &mut i);
    // Colours (clamped by glClearColor) map [-1, 1] linearly onto the integer range:
    // c * (2^31 - 1), truncated (table 4.9's mapping as Mesa applies it).
    assert_eq!(i, [i32::MAX, 0, 1073741823, 0]);
    let mut b = [9u8; 4];
    gl.get_booleanv(GL_COLOR_CLEAR_VALUE, &mut b);
    assert_eq!(b, [1, 0, 1, 0]);
    gl.viewport(1, 2, 30, 40);
    let mut f = [0f32; 4];
    gl.get_floatv(GL_VIEWPORT, &mut f);
    assert_eq!(f, [1.0, 2.0, 30.0, 40.0]);
    gl.depth_func(GL_GEQUAL);
    let mut e = [0i32];
    gl.get_integerv(GL_DEPTH_FUNC, &mut e);
    assert_eq!(e[0] as u32, GL_GEQUAL);
    let mut m = [0f64; 16];
    gl.translated(1.0, 2.0, 3.0);
    gl.get_doublev(GL_MODELVIEW_MATRIX, &mut m);
    assert_eq!(&m[12..15], &[1.0, 2.0, 3.0]);
    gl.get_doublev(GL_TRANSPOSE_MODELVIEW_MATRIX, &mut m);
    assert_eq!([m[3], m[7], m[11]], [1.0, 2.0, 3.0]);
}

/// Scenes long enough to be shaded in the background while the next part is recorded (more
/// than `BACKGROUND_COMMANDS` triangles, several times over), with texture edits, blending
/// changes and a read-back in between: the pictures and depth must equal those of one
/// synchronous worker, bit for bit, and later edits must not reach earlier draws.
#[test]
fn background_shading_changes_nothing() {
    let per_part = tilegl::raster::schedule::BACKGROUND_COMMANDS + 700;
    let render = |threads| {
        let mut gl = threaded_context(160, 120, threads);
        let mut rng = Rng(0xB6);
        let mut name = [0u32];
        gl.gen_textures(1, &mut name);
        gl.bind_texture(GL_TEXTURE_2D, name[0]);
        let texels: Vec<u8> = (0..16 * 16 * 4).map(|i| (i * 37 % 251) as u8).collect();
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            16,
            16,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&texels),
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        gl.enable(GL_DEPTH_TEST);
        gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        window_ortho(&mut gl);
        let mut mid = Vec::new();
        for part in 0..3 {
            match part {
                1 => {
                    gl.enable(GL_TEXTURE_2D);
                    gl.enable(GL_BLEND);
                    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                }
                2 => {
                    // Edits after recorded draws: the draws keep what they were given.
                    gl.tex_sub_image_2d(
                        GL_TEXTURE_2D,
                        0,
                        0,
                        0,
                        2,
                        2,
                        GL_RGBA,
                        GL_UNSIGNED_BYTE,
                        Some(&[255u8; 16]),
                    );
                    gl.blend_func(GL_ONE, GL_ONE);
                }
                _ => {}
            }
            gl.begin(GL_TRIANGLES);
            for _ in 0..per_part {
                gl.color_4f(
                    rng.range(0.0, 1.0),
                    rng.range(0.0, 1.0),
                    rng.range(0.0, 1.0),
                    0.5,
                );
                let (cx, cy) = (rng.range(-5.0, 165.0), rng.range(-5.0, 125.0));
                for _ in 0..3 {
                    gl.tex_coord_2f(rng.range(0.0, 1.0), rng.range(0.0, 1.0));
                    gl.vertex_3f(
                        cx + rng.range(-6.0, 6.0),
                        cy + rng.range(-6.0, 6.0),
                        rng.range(-0.9, 0.9),
                    );
                }
            }
            gl.end();
            if part == 1 {
                mid = read_rgba(&mut gl);
            }
        }
        let depth = read_depth(&mut gl);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        (mid, read_rgba(&mut gl), depth)
    };
    let one = render(1);
    assert_eq!(one, render(2));
    assert_eq!(one, render(8));
    assert_ne!(one.0, one.1, "the last part drew nothing");
}

/// More background scenes than may be in flight at once, all over the same six tiles, with
/// order-sensitive blending and depth writes: every tile must shade its queued scenes in the
/// order they were recorded, whichever thread takes it, so 2, 3 and 8 threads give the
/// pictures and depth of one synchronous worker bit for bit.
#[test]
fn queued_background_scenes_keep_each_tiles_order() {
    let per_scene = tilegl::raster::schedule::BACKGROUND_COMMANDS + 10;
    let render = |threads| {
        let mut gl = threaded_context(130, 70, threads);
        let mut rng = Rng(0x51);
        gl.enable(GL_DEPTH_TEST);
        gl.depth_func(GL_LEQUAL);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        window_ortho(&mut gl);
        gl.begin(GL_TRIANGLES);
        for scene in 0..10 {
            for _ in 0..per_scene {
                // Each scene's triangles have their own colour, nearer scene after scene.
                gl.color_4f(
                    scene as f32 / 10.0,
                    rng.range(0.0, 1.0),
                    1.0 - scene as f32 / 10.0,
                    rng.range(0.3, 0.8),
                );
                let (cx, cy) = (rng.range(0.0, 130.0), rng.range(0.0, 70.0));
                for _ in 0..3 {
                    gl.vertex_3f(
                        cx + rng.range(-8.0, 8.0),
                        cy + rng.range(-8.0, 8.0),
                        0.9 - scene as f32 * 0.15 + rng.range(-0.2, 0.2),
                    );
                }
            }
        }
        gl.end();
        let depth = read_depth(&mut gl);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        (read_rgba(&mut gl), depth)
    };
    let one = render(1);
    assert_eq!(one, render(2));
    assert_eq!(one, render(3));
    assert_eq!(one, render(8));
}

/// Filled triangles reaching past the viewport are rasterized unclipped inside a guard band
/// and clipped beyond it: either way exactly the viewport's pixels under the triangle are
/// drawn, and none outside the viewport (which is smaller than the window here).
#[test]
fn triangles_past_the_viewport_draw_only_inside_it() {
    for reach in [3.0f32, 200.0, 1.0e6] {
        let mut gl = Context::new(64, 64);
        gl.viewport(8, 12, 40, 30);
        gl.begin(GL_TRIANGLES);
        gl.color_3f(1.0, 1.0, 1.0);
        // Everything below the line x + y = 0.3 (NDC) that crosses the viewport, the corners
        // `reach` out.
        gl.vertex_2f(-reach, -reach);
        gl.vertex_2f(0.3 + reach, -reach);
        gl.vertex_2f(-reach, 0.3 + reach);
        gl.end();
        let px = read_rgba(&mut gl);
        let mut count = 0;
        for y in 0..64 {
            for x in 0..64 {
                let inside = (8..48).contains(&x) && (12..42).contains(&y);
                let ndc = [
                    (x as f64 + 0.5 - 8.0) / 20.0 - 1.0,
                    (y as f64 + 0.5 - 12.0) / 15.0 - 1.0,
                ];
                // The line through the corners as given (0.3 + reach rounded to f32).
                let under = ndc[0] + ndc[1] < (0.3 + reach) as f64 - reach as f64;
                let lit = px[(y * 64 + x) as usize][0] == 255;
                assert_eq!(lit, inside && under, "reach {reach}: pixel ({x}, {y})");
                count += usize::from(lit);
            }
        }
        assert!(count > 400, "reach {reach}: {count} pixels");
    }
}

/// The untextured eight-fragment span (blending, alpha test, other depth functions, colour
/// masks) draws exactly what the general path draws.
#[test]
fn untextured_blended_spans_match_the_general_path() {
    type Setup = (&'static str, fn(&mut Context));
    let states: [Setup; 9] = [
        ("over", |gl| {
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        }),
        ("additive, depth writes off", |gl| {
            gl.enable(GL_BLEND);
            gl.blend_func(GL_ONE, GL_ONE);
            gl.depth_mask(0);
        }),
        ("subtract with constant colour", |gl| {
            gl.enable(GL_BLEND);
            gl.blend_color(0.3, 0.6, 0.9, 0.5);
            gl.blend_func(GL_DST_COLOR, GL_CONSTANT_ALPHA);
            gl.blend_equation(GL_FUNC_REVERSE_SUBTRACT);
        }),
        ("min, alpha test", |gl| {
            gl.enable(GL_BLEND);
            gl.blend_equation(GL_MIN);
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_GREATER, 0.45);
        }),
        ("alpha test alone, greater depth", |gl| {
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_LEQUAL, 0.6);
            gl.depth_func(GL_GREATER);
        }),
        ("saturate, colour mask", |gl| {
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA_SATURATE, GL_ONE_MINUS_DST_ALPHA);
            gl.color_mask(1, 0, 1, 0);
        }),
        ("not equal depth, no blending", |gl| {
            gl.depth_func(GL_NOTEQUAL);
        }),
        // Fog on the eight-fragment tail.
        ("over, EXP2 fog", |gl| {
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_EXP2 as i32);
            gl.fogf(GL_FOG_DENSITY, 0.3);
            gl.fogfv(GL_FOG_COLOR, &[0.2, 0.5, 0.9, 1.0]);
        }),
        ("alpha test, LINEAR fog", |gl| {
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_GREATER, 0.3);
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_LINEAR as i32);
            gl.fogf(GL_FOG_START, 1.0);
            gl.fogf(GL_FOG_END, 8.0);
            gl.fogfv(GL_FOG_COLOR, &[0.9, 0.5, 0.1, 1.0]);
        }),
    ];
    for (name, state) in states {
        let render = |general: bool| {
            let mut gl = Context::new(96, 96);
            gl.set_force_general_path(general);
            busy_scene(&mut gl);
            state(&mut gl);
            random_strip(&mut gl, 23, true);
            read_rgba(&mut gl)
        };
        let general = render(true);
        assert_eq!(general, render(false), "{name}");
        let mut plain = Context::new(96, 96);
        busy_scene(&mut plain);
        assert_ne!(
            general,
            read_rgba(&mut plain),
            "{name}: the second draw changed nothing"
        );
    }
}

/// A colour that is the same at every vertex is the same at every fragment (section 3.5.1:
/// interpolating equal values gives that value), also under a strong perspective where
/// dividing colour/w by 1/w would round: 0.5 lies exactly halfway between two 8-bit values,
/// so any rounding below it would show as 127 instead of 128.
#[test]
fn constant_colours_stay_exact_under_perspective() {
    for general in [false, true] {
        let mut gl = Context::new(96, 64);
        gl.set_force_general_path(general);
        gl.matrix_mode(GL_PROJECTION);
        gl.frustum(-1.0, 1.0, -0.7, 0.7, 1.0, 1000.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.clear(GL_COLOR_BUFFER_BIT);
        // A floor from near the eye to far away, in a few strips of small triangles.
        gl.color_4f(0.5, 0.5, 0.5, 0.5);
        for k in 0..40 {
            let (z0, z1) = (-1.5 - k as f32 * 10.0, -1.5 - (k + 1) as f32 * 10.0);
            gl.begin(GL_TRIANGLE_STRIP);
            for i in 0..=20 {
                let x = -40.0 + 4.0 * i as f32;
                gl.vertex_3f(x, -1.0, z0);
                gl.vertex_3f(x + 0.7, -1.0, z1);
            }
            gl.end();
        }
        let picture = read_rgba(&mut gl);
        let floor: Vec<_> = picture.iter().filter(|p| **p != [0, 0, 0, 0]).collect();
        assert!(floor.len() > 1000, "{}", floor.len());
        let wrong = floor.iter().filter(|p| ***p != [128; 4]).count();
        assert_eq!(
            wrong, 0,
            "general path {general}: {wrong} fragments not 128"
        );
    }
}

/// Keys that write no colour and run no alpha test take the depth-and-stencil span, which
/// skips the colour, texturing and fog the general path computes and then does not write:
/// shadow-volume passes (both cull faces, `INCR`/`DECR` and the wrapping forms, depth writes
/// off), stencil with every fail action and depth writes on, depth-only passes with textures
/// and fog, and a disabled depth test; the depth and stencil values after the pass are the
/// general path's, and so is the picture of a final pass that shows the stencil values.
#[test]
fn depth_stencil_spans_match_the_general_path() {
    type Setup = (&'static str, fn(&mut Context));
    let states: [Setup; 5] = [
        ("z-pass volumes", |gl| {
            gl.depth_mask(0);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_ALWAYS, 0, 0xFF);
            gl.enable(GL_CULL_FACE);
            gl.cull_face(GL_BACK);
            gl.stencil_op(GL_KEEP, GL_KEEP, GL_INCR);
            random_strip(gl, 31, false);
            gl.cull_face(GL_FRONT);
            gl.stencil_op(GL_KEEP, GL_KEEP, GL_DECR);
            random_strip(gl, 31, false);
            gl.disable(GL_CULL_FACE);
        }),
        ("z-fail volumes, wrapping", |gl| {
            gl.depth_mask(0);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_ALWAYS, 0, 0xFF);
            gl.stencil_op(GL_KEEP, GL_DECR_WRAP, GL_KEEP);
            random_strip(gl, 32, false);
            gl.stencil_op(GL_KEEP, GL_INCR_WRAP, GL_INVERT);
            random_strip(gl, 33, false);
        }),
        ("stencil test failing, depth writes", |gl| {
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_LESS, 0x21, 0x3F);
            gl.stencil_mask(0xF7);
            gl.stencil_op(GL_REPLACE, GL_INCR, GL_ZERO);
            random_strip(gl, 34, false);
            random_strip(gl, 35, false);
        }),
        ("depth-only pass, textured and fogged, LEQUAL", |gl| {
            random_texture(gl, &mut Rng(5), GL_RGBA, 16, 16);
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
            gl.enable(GL_TEXTURE_2D);
            gl.enable(GL_FOG);
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            gl.depth_func(GL_LEQUAL);
            random_strip(gl, 36, true);
            gl.disable(GL_TEXTURE_2D);
            gl.disable(GL_FOG);
            gl.disable(GL_BLEND);
        }),
        ("no depth test, stencil counting", |gl| {
            gl.disable(GL_DEPTH_TEST);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_ALWAYS, 0, 0xFF);
            gl.stencil_op(GL_KEEP, GL_KEEP, GL_INCR);
            random_strip(gl, 37, false);
            gl.enable(GL_DEPTH_TEST);
        }),
    ];
    for (name, state) in states {
        let render = |general: bool| {
            let mut gl = Context::new(96, 96);
            gl.set_force_general_path(general);
            busy_scene(&mut gl);
            gl.clear_stencil(0x10);
            gl.clear(GL_STENCIL_BUFFER_BIT);
            gl.color_mask(0, 0, 0, 0);
            state(&mut gl);
            gl.color_mask(1, 1, 1, 1);
            gl.depth_mask(1);
            gl.stencil_mask(0xFF);
            let depth = read_depth(&mut gl);
            let mut stencil = vec![0u8; 96 * 96];
            gl.read_pixels(
                0,
                0,
                96,
                96,
                GL_STENCIL_INDEX,
                GL_UNSIGNED_BYTE,
                &mut stencil,
            );
            // The stencil values shown: a quad over the window wherever they are not 0x10.
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_NOTEQUAL, 0x10, 0xFF);
            gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
            gl.disable(GL_DEPTH_TEST);
            gl.color_3f(1.0, 1.0, 1.0);
            gl.begin(GL_QUADS);
            for (x, y) in [(-9.0, -9.0), (9.0, -9.0), (9.0, 9.0), (-9.0, 9.0)] {
                gl.vertex_3f(x, y, -1.5);
            }
            gl.end();
            assert_eq!(gl.get_error(), GL_NO_ERROR, "{name}");
            (depth, stencil, read_rgba(&mut gl))
        };
        let general = render(true);
        let fast = render(false);
        assert!(general.0 == fast.0, "{name}: depth");
        assert!(general.1 == fast.1, "{name}: stencil");
        assert!(general.2 == fast.2, "{name}: picture");
        // The pass did something: the stencil or the depth moved.
        let mut plain = Context::new(96, 96);
        busy_scene(&mut plain);
        let moved = general.1.iter().any(|&s| s != 0x10) || general.0 != read_depth(&mut plain);
        assert!(moved, "{name}: the pass changed nothing");
    }
}

/// Lines whose two ends carry the same values shade the fully covered neighbours of a row as
/// one span (`Command::Line`, `LineSetup::uniform`); the picture is the one of the same
/// lines drawn fragment by fragment. Here the second drawing gives each segment's ends
/// different depths (the depth test is off, so depth changes nothing but the route), and a
/// third takes the general fragment path: aliased widths 1 and 3, smooth widths 1.5 and 2.5
/// with "over" blending, stippled and not, in every direction, over tile borders.
#[test]
fn lines_with_equal_ends_draw_what_per_fragment_lines_draw() {
    let draw = |z_apart: bool, general: bool| {
        let mut gl = Context::new(150, 140);
        gl.set_force_general_path(general);
        window_ortho(&mut gl);
        gl.clear_color(0.1, 0.2, 0.3, 1.0);
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        let mut rng = Rng(0x11E5_0001);
        for (smooth, width, stipple) in [
            (false, 1.0, false),
            (false, 3.0, false),
            (false, 3.0, true),
            (true, 1.5, false),
            (true, 2.5, false),
            (true, 2.5, true),
        ] {
            if smooth {
                gl.enable(GL_LINE_SMOOTH);
                gl.enable(GL_BLEND);
            } else {
                gl.disable(GL_LINE_SMOOTH);
                gl.disable(GL_BLEND);
            }
            if stipple {
                gl.enable(GL_LINE_STIPPLE);
                gl.line_stipple(2, 0x39CF);
            } else {
                gl.disable(GL_LINE_STIPPLE);
            }
            gl.line_width(width);
            gl.begin(GL_LINES);
            for _ in 0..40 {
                gl.color_4f(
                    rng.range(0.2, 1.0),
                    rng.range(0.2, 1.0),
                    rng.range(0.2, 1.0),
                    0.7,
                );
                let (x, y) = (rng.range(-10.0, 160.0), rng.range(-10.0, 150.0));
                let (len, ang) = (rng.range(3.0, 120.0), rng.range(0.0, std::f32::consts::TAU));
                let z = if z_apart { 0.25 } else { 0.0 };
                gl.vertex_3f(x, y, z);
                gl.vertex_3f(x + len * ang.cos(), y + len * ang.sin(), -z);
            }
            gl.end();
        }
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        read_rgba(&mut gl)
    };
    let merged = draw(false, false);
    let background = merged.iter().filter(|&&p| p == [26, 51, 77, 255]).count();
    assert!(background < merged.len() * 9 / 10, "the lines drew little");
    assert!(
        merged == draw(true, false),
        "equal ends against depths apart"
    );
    assert!(merged == draw(false, true), "against the general path");
}

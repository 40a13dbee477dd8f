//! Points, lines and polygon controls (sections 3.3-3.5) against the spec's rules computed in
//! the test: point squares, attenuation, wide lines, stippling, polygon modes and edge flags,
//! polygon offset, polygon stipple, antialiasing coverage and extreme values.

mod common;

use common::{read_rgba, window_ortho};
use tilegl::enums::*;
use tilegl::{Context, Gl};

const W: i32 = 64;

fn setup() -> Context {
    let mut gl = Context::new(W, W);
    window_ortho(&mut gl);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.color_4f(1.0, 1.0, 1.0, 1.0);
    gl
}

/// Pixels whose red channel is set, as (x, y).
fn lit(gl: &mut Context) -> Vec<(i32, i32)> {
    read_rgba(gl)
        .iter()
        .enumerate()
        .filter(|(_, p)| p[0] > 0)
        .map(|(i, _)| (i as i32 % W, i as i32 / W))
        .collect()
}

fn square(x0: i32, y0: i32, w: i32) -> Vec<(i32, i32)> {
    let mut v: Vec<(i32, i32)> = (y0..y0 + w)
        .flat_map(|y| (x0..x0 + w).map(move |x| (x, y)))
        .collect();
    v.sort_by_key(|&(x, y)| (y, x));
    v
}

#[test]
fn aliased_points_cover_the_spec_square() {
    // Section 3.3: width w = round(size); the square's pixel centres lie within w/2 of the
    // point, i.e. the first pixel is floor(x - (w - 1) / 2).
    for (size, x, y) in [
        (1.0f32, 10.3f32, 20.7f32),
        (2.0, 10.3, 20.7),
        (3.0, 30.6, 30.2),
        (4.0, 30.6, 30.2),
        (5.0, 40.1, 12.9),
        (8.0, 33.4, 33.6),
    ] {
        let mut gl = setup();
        gl.point_size(size);
        gl.begin(GL_POINTS);
        gl.vertex_2f(x, y);
        gl.end();
        let w = size.round() as i32;
        let x0 = (x - (w - 1) as f32 / 2.0).floor() as i32;
        let y0 = (y - (w - 1) as f32 / 2.0).floor() as i32;
        assert_eq!(lit(&mut gl), square(x0, y0, w), "size {size} at ({x}, {y})");
    }
}

#[test]
fn point_size_is_attenuated_and_clamped() {
    // On the view axis d = |z_eye|: size * sqrt(1 / (a + b d + c d^2)), clamped to min/max.
    let (a, b, c) = (0.5f32, 0.25f32, 0.0625f32);
    for (z, min, max) in [
        (-2.0f32, 0.0f32, 64.0f32),
        (-6.0, 0.0, 64.0),
        (-1.0, 0.0, 5.0),
    ] {
        let mut gl = setup();
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        gl.ortho(-32.0, 32.0, -32.0, 32.0, 0.0, 100.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.point_size(16.0);
        gl.point_parameterfv(GL_POINT_DISTANCE_ATTENUATION, &[a, b, c]);
        gl.point_parameterf(GL_POINT_SIZE_MIN, min);
        gl.point_parameterf(GL_POINT_SIZE_MAX, max);
        gl.begin(GL_POINTS);
        gl.vertex_3f(0.3, 0.2, z);
        gl.end();
        let d = -z;
        let derived = (16.0 * (1.0 / (a + b * d + c * d * d)).sqrt()).clamp(min, max);
        let w = (derived - 0.5).ceil() as i32;
        let pixels = lit(&mut gl);
        assert_eq!(pixels.len() as i32, w * w, "z {z}: derived size {derived}");
    }
}

#[test]
fn wide_lines_are_columns_of_w_fragments() {
    // An x-major line of width w: every column of the width-1 line becomes w pixels, the
    // lowest at floor(y - (w - 1) / 2).
    for w in [1, 2, 3, 6] {
        let mut gl = setup();
        gl.line_width(w as f32);
        gl.begin(GL_LINES);
        gl.vertex_2f(4.2, 30.3);
        gl.vertex_2f(50.2, 30.3);
        gl.end();
        let y0 = (30.3 - (w - 1) as f32 / 2.0).floor() as i32;
        let mut expect: Vec<(i32, i32)> = (y0..y0 + w)
            .flat_map(|y| (4..50).map(move |x| (x, y)))
            .collect();
        expect.sort_by_key(|&(x, y)| (y, x));
        assert_eq!(lit(&mut gl), expect, "width {w}");
    }
    // A y-major line widens in x.
    let mut gl = setup();
    gl.line_width(3.0);
    gl.begin(GL_LINES);
    gl.vertex_2f(20.5, 5.2);
    gl.vertex_2f(20.5, 40.2);
    gl.end();
    let mut expect: Vec<(i32, i32)> = (5..40)
        .flat_map(|y| (19..22).map(move |x| (x, y)))
        .collect();
    expect.sort_by_key(|&(x, y)| (y, x));
    assert_eq!(lit(&mut gl), expect);
}

#[test]
fn line_stipple_follows_the_pattern_and_factor() {
    // Section 3.4.2: fragment s is drawn when bit floor(s / r) mod 16 of the pattern is set.
    for (factor, pattern) in [(1, 0x00FFu16), (2, 0x0F0F), (3, 0xA5C3)] {
        let mut gl = setup();
        gl.enable(GL_LINE_STIPPLE);
        gl.line_stipple(factor, pattern);
        gl.begin(GL_LINES);
        gl.vertex_2f(0.2, 10.5);
        gl.vertex_2f(63.2, 10.5);
        gl.end();
        let drawn: Vec<i32> = lit(&mut gl).iter().map(|p| p.0).collect();
        let expect: Vec<i32> = (0..63)
            .filter(|&s| pattern & (1 << ((s / factor) % 16)) != 0)
            .collect();
        assert_eq!(drawn, expect, "factor {factor} pattern {pattern:#06x}");
    }
}

#[test]
fn stipple_counter_restarts_for_independent_lines_and_runs_on_in_strips() {
    let draw = |mode: GLenum| {
        let mut gl = setup();
        gl.enable(GL_LINE_STIPPLE);
        gl.line_stipple(1, 0x000F);
        gl.begin(mode);
        // Two collinear 8-pixel segments.
        gl.vertex_2f(0.5, 10.5);
        gl.vertex_2f(8.5, 10.5);
        if mode == GL_LINES {
            gl.vertex_2f(8.5, 10.5);
        }
        gl.vertex_2f(16.5, 10.5);
        gl.end();
        lit(&mut gl).iter().map(|p| p.0).collect::<Vec<i32>>()
    };
    // Independent: each segment restarts at bit 0 (pixels 0-3 and 8-11).
    assert_eq!(draw(GL_LINES), vec![0, 1, 2, 3, 8, 9, 10, 11]);
    // Strip: the second segment continues at fragment 8 (bits 8-15 are off).
    assert_eq!(draw(GL_LINE_STRIP), vec![0, 1, 2, 3]);
}

#[test]
fn polygon_line_mode_draws_the_outline_without_diagonals() {
    let mut gl = setup();
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    gl.begin(GL_QUADS);
    gl.vertex_2f(10.5, 10.5);
    gl.vertex_2f(40.5, 10.5);
    gl.vertex_2f(40.5, 40.5);
    gl.vertex_2f(10.5, 40.5);
    gl.end();
    let px = lit(&mut gl);
    let on = |x, y| px.contains(&(x, y));
    // The four sides are there, the diagonal and the interior are not.
    assert!(on(20, 10) && on(40, 20) && on(20, 40) && on(10, 20));
    assert!(!on(25, 25) && !on(30, 30) && !on(15, 15));
    // Every lit pixel is on a side.
    assert!(px
        .iter()
        .all(|&(x, y)| x == 10 || x == 40 || y == 10 || y == 40));
}

#[test]
fn edge_flags_hide_edges_and_points() {
    let mut gl = setup();
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    gl.begin(GL_TRIANGLES);
    gl.edge_flag(1);
    gl.vertex_2f(10.5, 10.5);
    gl.edge_flag(0); // the edge from here to the third vertex is hidden
    gl.vertex_2f(50.5, 10.5);
    gl.edge_flag(1);
    gl.vertex_2f(10.5, 50.5);
    gl.end();
    let px = lit(&mut gl);
    assert!(px.contains(&(30, 10)) && px.contains(&(10, 30)));
    // The hypotenuse from (50.5, 10.5) to (10.5, 50.5) is not drawn.
    assert!(!px.contains(&(30, 30)) && !px.contains(&(29, 31)));
    // Point mode: only vertices that start a boundary edge.
    let mut gl = setup();
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_POINT);
    gl.begin(GL_TRIANGLES);
    gl.edge_flag(1);
    gl.vertex_2f(10.5, 10.5);
    gl.edge_flag(0);
    gl.vertex_2f(50.5, 10.5);
    gl.edge_flag(1);
    gl.vertex_2f(10.5, 50.5);
    gl.end();
    assert_eq!(lit(&mut gl), vec![(10, 10), (10, 50)]);
}

fn read_depth(gl: &mut Context, x: i32, y: i32) -> f32 {
    let mut d = [0u8; 4];
    gl.read_pixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &mut d);
    f32::from_ne_bytes(d)
}

#[test]
fn polygon_offset_moves_depth_by_factor_times_slope_plus_units() {
    // Section 3.5.5: o = factor * m + units * r, m = max(|dz/dx|, |dz/dy|), r = 1 / (2^24 - 1).
    let quad = |gl: &mut Context| {
        gl.begin(GL_QUADS);
        // z runs from -0.5 to 0.5 across x: window z from 0.25 to 0.75 over 64 pixels.
        gl.vertex_3f(0.0, 0.0, 0.5);
        gl.vertex_3f(64.0, 0.0, -0.5);
        gl.vertex_3f(64.0, 64.0, -0.5);
        gl.vertex_3f(0.0, 64.0, 0.5);
        gl.end();
    };
    let mut gl = setup();
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_ALWAYS);
    quad(&mut gl);
    let base = read_depth(&mut gl, 31, 20);
    // window z = 0.5 * z_ndc + 0.5 with z_ndc = -z_eye (ortho near 0 far... [-1, 1]).
    let (factor, units) = (2.0f32, 100.0f32);
    gl.enable(GL_POLYGON_OFFSET_FILL);
    gl.polygon_offset(factor, units);
    quad(&mut gl);
    let moved = read_depth(&mut gl, 31, 20);
    let m = 0.5 / 64.0;
    let r = 1.0 / ((1u32 << 24) - 1) as f32;
    let expect = factor * m + units * r;
    assert!(
        ((moved - base) - expect).abs() < 2.0 * r,
        "offset {} expected {expect}",
        moved - base
    );
    // Huge offsets clamp to the depth range instead of wrapping.
    gl.polygon_offset(1e30, 1e30);
    quad(&mut gl);
    assert_eq!(read_depth(&mut gl, 31, 20), 1.0);
    gl.polygon_offset(-1e30, -1e30);
    quad(&mut gl);
    assert_eq!(read_depth(&mut gl, 31, 20), 0.0);
}

#[test]
fn polygon_stipple_masks_by_window_position() {
    let mut gl = setup();
    let pattern: Vec<u8> = (0..128u32)
        .map(|k| (k.wrapping_mul(97) ^ (k >> 2)) as u8)
        .collect();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.polygon_stipple(&pattern);
    gl.enable(GL_POLYGON_STIPPLE);
    gl.rectf(0.0, 0.0, 64.0, 64.0);
    let px = lit(&mut gl);
    let mut expect = Vec::new();
    for y in 0..W {
        for x in 0..W {
            // Row y % 32, byte x % 32 / 8, most significant bit first.
            let byte = pattern[(y % 32 * 4 + x % 32 / 8) as usize];
            if byte & (0x80 >> (x % 8)) != 0 {
                expect.push((x, y));
            }
        }
    }
    assert_eq!(px, expect);
}

#[test]
fn smooth_point_coverage_adds_up_to_the_disc_area() {
    // With additive blending of alpha, the summed coverage is the disc's area (invariant of
    // any area-based antialiasing).
    for size in [3.0f32, 6.0, 11.0] {
        let mut gl = setup();
        gl.enable(GL_POINT_SMOOTH);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_ONE, GL_ONE);
        gl.point_size(size);
        gl.begin(GL_POINTS);
        gl.vertex_2f(31.3, 30.8);
        gl.end();
        let total: f32 = read_rgba(&mut gl).iter().map(|p| p[3] as f32 / 255.0).sum();
        let area = std::f32::consts::PI * size * size / 4.0;
        assert!(
            (total - area).abs() < 0.05 * area,
            "size {size}: coverage {total}, area {area}"
        );
    }
}

#[test]
fn smooth_line_coverage_adds_up_to_the_rectangle_area() {
    for (w, angle) in [(1.0f32, 0.3f32), (2.5, 1.1), (4.0, 2.0)] {
        let mut gl = setup();
        gl.enable(GL_LINE_SMOOTH);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_ONE, GL_ONE);
        gl.line_width(w);
        let len = 40.0f32;
        let (c, s) = (angle.cos(), angle.sin());
        gl.begin(GL_LINES);
        gl.vertex_2f(32.0 - c * len / 2.0, 32.0 - s * len / 2.0);
        gl.vertex_2f(32.0 + c * len / 2.0, 32.0 + s * len / 2.0);
        gl.end();
        let total: f32 = read_rgba(&mut gl).iter().map(|p| p[3] as f32 / 255.0).sum();
        let area = w * len;
        assert!(
            (total - area).abs() < 0.06 * area,
            "width {w}: coverage {total}, area {area}"
        );
    }
}

#[test]
fn extreme_sizes_and_widths_are_clamped_to_the_reported_range() {
    let mut range = [0f32; 2];
    let mut gl = setup();
    gl.get_floatv(GL_ALIASED_POINT_SIZE_RANGE, &mut range);
    let max_point = range[1] as usize;
    gl.point_size(1e30);
    gl.begin(GL_POINTS);
    // The first pixel is floor(32 - (64 - 1) / 2) = 0: a 64-wide point fills the window.
    gl.vertex_2f(32.0, 32.0);
    gl.end();
    let n = lit(&mut gl).len();
    assert_eq!(n, max_point.min(W as usize).pow(2));

    let mut gl = setup();
    gl.get_floatv(GL_ALIASED_LINE_WIDTH_RANGE, &mut range);
    gl.line_width(f32::INFINITY);
    gl.begin(GL_LINES);
    // The lowest row is floor(32.3 - (64 - 1) / 2) = 0.
    gl.vertex_2f(0.0, 32.3);
    gl.vertex_2f(64.0, 32.3);
    gl.end();
    let rows: std::collections::BTreeSet<i32> = lit(&mut gl).iter().map(|p| p.1).collect();
    assert_eq!(rows.len(), (range[1] as usize).min(W as usize));

    // Degenerate attenuation (a = b = c = 0): the size goes to the maximum, no NaN.
    let mut gl = setup();
    gl.point_parameterfv(GL_POINT_DISTANCE_ATTENUATION, &[0.0, 0.0, 0.0]);
    gl.point_parameterf(GL_POINT_SIZE_MAX, 4.0);
    gl.begin(GL_POINTS);
    gl.vertex_2f(32.5, 32.5);
    gl.end();
    assert_eq!(lit(&mut gl).len(), 16);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn smooth_polygon_coverage_adds_up_to_the_area_and_shared_edges_to_one() {
    // One triangle: the summed coverage is its area.
    let mut gl = setup();
    gl.enable(GL_POLYGON_SMOOTH);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_ONE, GL_ONE);
    let p = [(5.3f32, 7.1f32), (58.2, 12.6), (21.7, 55.4)];
    gl.begin(GL_TRIANGLES);
    for (x, y) in p {
        gl.vertex_2f(x, y);
    }
    gl.end();
    let total: f32 = read_rgba(&mut gl).iter().map(|c| c[3] as f32 / 255.0).sum();
    let area =
        ((p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1)).abs() / 2.0;
    assert!(
        (total - area).abs() < 0.01 * area,
        "coverage {total}, area {area}"
    );
    // A quad split into two triangles: along the shared diagonal the coverages add up to 1,
    // so the interior is fully covered and no seam shows.
    let mut gl = setup();
    gl.enable(GL_POLYGON_SMOOTH);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_ONE, GL_ONE);
    gl.begin(GL_QUADS);
    gl.vertex_2f(10.0, 10.0);
    gl.vertex_2f(50.0, 14.0);
    gl.vertex_2f(46.0, 52.0);
    gl.vertex_2f(12.0, 48.0);
    gl.end();
    let px = read_rgba(&mut gl);
    for (x, y) in [(30, 30), (20, 20), (40, 40), (25, 35), (35, 25)] {
        let a = px[(y * W + x) as usize][3];
        assert!(a >= 254, "({x}, {y}): alpha {a}");
    }
}

/// Point sprites (ARB_point_sprite; GL 2.0 section 3.4.1): the state, its errors and attribute
/// group, and a sprite's square of side `size` (not rounded) with s = 1/2 + (x_f + 1/2 - x) /
/// size and t = 1/2 - (y_f + 1/2 - y) / size (upper-left origin) or + (lower-left).
#[test]
fn point_sprites_replace_texture_coordinates_across_the_square() {
    let mut gl = Context::new(16, 16);
    window_ortho(&mut gl);
    let int = |gl: &mut Context, pname: GLenum| {
        let mut v = [0i32];
        gl.get_integerv(pname, &mut v);
        v[0]
    };
    let coord_replace = |gl: &mut Context| {
        let mut v = [7i32];
        gl.get_tex_enviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &mut v);
        v[0]
    };
    assert_eq!(gl.is_enabled(GL_POINT_SPRITE), 0);
    assert_eq!(coord_replace(&mut gl), 0);
    assert_eq!(
        int(&mut gl, GL_POINT_SPRITE_COORD_ORIGIN),
        GL_UPPER_LEFT as i32
    );
    // Errors change nothing.
    gl.point_parameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_FRONT as i32);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.tex_envi(GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    assert_eq!(
        int(&mut gl, GL_POINT_SPRITE_COORD_ORIGIN),
        GL_UPPER_LEFT as i32
    );
    // GL_COORD_REPLACE is per unit; the point attribute group saves all three.
    gl.push_attrib(GL_POINT_BIT);
    gl.enable(GL_POINT_SPRITE);
    gl.tex_envi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE as i32);
    gl.point_parameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT as i32);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(coord_replace(&mut gl), 1);
    gl.active_texture(GL_TEXTURE1);
    assert_eq!(coord_replace(&mut gl), 0);
    gl.active_texture(GL_TEXTURE0);
    gl.pop_attrib();
    assert_eq!(gl.is_enabled(GL_POINT_SPRITE), 0);
    assert_eq!(coord_replace(&mut gl), 0);
    assert_eq!(
        int(&mut gl, GL_POINT_SPRITE_COORD_ORIGIN),
        GL_UPPER_LEFT as i32
    );

    // A 4 x 4 texture of distinct texels (red the column, green the row), NEAREST.
    let mut texels = Vec::new();
    for j in 0..4u8 {
        for i in 0..4u8 {
            texels.extend_from_slice(&[40 + 60 * i, 40 + 60 * j, 0, 255]);
        }
    }
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        4,
        4,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_POINT_SPRITE);
    gl.tex_envi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE as i32);
    // POINT_SMOOTH is ignored for sprites.
    gl.enable(GL_POINT_SMOOTH);
    for upper_left in [true, false] {
        let origin = if upper_left {
            GL_UPPER_LEFT
        } else {
            GL_LOWER_LEFT
        };
        gl.point_parameteri(GL_POINT_SPRITE_COORD_ORIGIN, origin as i32);
        gl.clear_color(0.0, 0.0, 0.0, 0.0);
        gl.clear(GL_COLOR_BUFFER_BIT);
        // Size 3.6 at (8.3, 7.9): pixel centres in [6.5, 10.1) x [6.1, 9.7): columns 6-9, rows
        // 6-9 (the size is not rounded to 4).
        let (x, y, size) = (8.3f64, 7.9f64, 3.6f64);
        gl.point_size(size as f32);
        gl.begin(GL_POINTS);
        gl.vertex_2f(x as f32, y as f32);
        gl.end();
        let img = read_rgba(&mut gl);
        for py in 0..16 {
            for px in 0..16 {
                let got = img[py * 16 + px];
                let (cx, cy) = (px as f64 + 0.5, py as f64 + 0.5);
                let inside = (x - size / 2.0..x + size / 2.0).contains(&cx)
                    && (y - size / 2.0..y + size / 2.0).contains(&cy);
                let want = if inside {
                    let s = 0.5 + (cx - x) / size;
                    let t = if upper_left {
                        0.5 - (cy - y) / size
                    } else {
                        0.5 + (cy - y) / size
                    };
                    let (i, j) = ((4.0 * s).floor() as u8, (4.0 * t).floor() as u8);
                    [40 + 60 * i, 40 + 60 * j, 0, 255]
                } else {
                    [0, 0, 0, 0]
                };
                assert_eq!(got, want, "origin {origin:#x}, pixel ({px}, {py})");
            }
        }
    }
}

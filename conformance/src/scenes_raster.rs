//! Differential scenes for the rasterization controls: point size and parameters, wide and
//! stippled lines, antialiased points and lines, polygon modes with edge flags, polygon offset
//! and polygon stipple (the fragment-operations issue).

use crate::compare::Scene;
use crate::prng::XorShift;
use crate::scenes::{clear, pal, pixel_space, scene, scene_with, spread};
use tilegl::enums::*;
use tilegl::Gl;

/// Rasterization-control scenes, in report order.
pub const RASTER_SCENES: &[Scene] = &[
    scene("wide_points", wide_points),
    scene("point_attenuation", point_attenuation),
    scene("wide_lines", wide_lines),
    // Mesa stipples by splitting each segment into on/off sub-segments (counting ceil(length)
    // per segment) instead of counting fragments; llvmpipe vs softpipe: 0.757 % and 2.856 % of
    // pixels off by more than 8 (tilegl vs llvmpipe: 0.098 %, 0.146 %).
    scene_with("line_stipple", line_stipple, spread(0.00757)),
    scene_with("line_stipple_wide", line_stipple_wide, spread(0.02856)),
    scene("polygon_mode_line", polygon_mode_line),
    scene("polygon_mode_point", polygon_mode_point),
    scene("edge_flags", edge_flags),
    scene("polygon_offset_fill", polygon_offset_fill),
    scene("polygon_offset_line", polygon_offset_line),
    scene("polygon_stipple", polygon_stipple),
    // Mesa 22 (llvmpipe and softpipe alike) draws GL_POINT_SMOOTH points as aliased discs
    // without coverage; tilegl applies the covered area (section 3.11). The pictures can only
    // differ on the discs' rims: about pi * size pixels per point, 3 * pi * (1.5 + 3 + 4.5 + 7
    // + 10) = 245 pixels = 6.0 % of the picture.
    scene_with("smooth_points", smooth_points, spread(0.060)),
    // The same at 25 sizes from 0.5 to 11 and sub-pixel positions; with
    // `SmoothPoints::Discs` tilegl must give Mesa's picture exactly
    // (`conformance/tests/differential_raster.rs`). With the specification's coverage the rims
    // differ: measured 8.1 % of the picture (332 pixels).
    scene_with("smooth_point_sizes", smooth_point_sizes, spread(0.085)),
    scene("smooth_lines", smooth_lines),
    // Mesa 22's llvmpipe and softpipe ignore GL_POLYGON_SMOOTH (aliased polygons); tilegl
    // applies edge coverage. The pictures differ only where coverage is partial: pixels whose
    // centres lie within half a pixel of an edge, a band one pixel wide along the outline. The
    // three triangles' perimeters add up to 286 pixels = 7.0 % of the picture.
    scene_with("smooth_polygons", smooth_polygons, spread(0.070)),
    scene("additive_faint_layers", additive_faint_layers),
    scene("blend_equation_separate", blend_equation_separate),
    scene("flat_textured_fogged", flat_textured_fogged),
    scene("accum_motion_blur", accum_motion_blur),
    scene("accum_ops", accum_ops),
    scene("draw_pixels_color", draw_pixels_color),
    scene("draw_pixels_zoom_transfer", draw_pixels_zoom_transfer),
    scene("draw_pixels_depth_stencil", draw_pixels_depth_stencil),
    scene("bitmap_text", bitmap_text),
    scene("copy_pixels", copy_pixels),
    scene(
        "window_pos_and_invalid_raster",
        window_pos_and_invalid_raster,
    ),
];

/// Points of sizes 1..=8 at fractional positions (no rounding ties).
fn wide_points(gl: &mut dyn Gl) {
    clear(gl);
    pixel_space(gl, 64.0, 64.0);
    for (k, size) in [1.0f32, 2.0, 3.0, 4.0, 5.0, 6.0, 7.5, 8.0]
        .iter()
        .enumerate()
    {
        gl.point_size(*size);
        gl.begin(GL_POINTS);
        for j in 0..3 {
            pal(gl, k + j);
            gl.vertex_2f(
                5.3 + 7.6 * k as f32,
                8.4 + 18.2 * j as f32 + 0.17 * k as f32,
            );
        }
        gl.end();
    }
}

/// GL 1.4 point parameters: size attenuated with eye distance, clamped to min/max.
fn point_attenuation(gl: &mut dyn Gl) {
    clear(gl);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.point_size(12.0);
    gl.point_parameterfv(GL_POINT_DISTANCE_ATTENUATION, &[0.0, 0.5, 0.02]);
    gl.point_parameterf(GL_POINT_SIZE_MIN, 2.0);
    gl.point_parameterf(GL_POINT_SIZE_MAX, 9.0);
    gl.begin(GL_POINTS);
    for k in 0..12 {
        pal(gl, k);
        let z = -1.3 - 1.4 * k as f32;
        // Points near the view axis: |z| and the full distance stay close.
        let x = (-0.5 + 0.09 * k as f32) * -z * 0.9;
        let y = (0.35 - 0.07 * k as f32) * -z * 0.9;
        gl.vertex_3f(x + 0.013, y + 0.021, z);
    }
    gl.end();
}

/// Lines of widths 2..5 over many slopes.
fn wide_lines(gl: &mut dyn Gl) {
    clear(gl);
    pixel_space(gl, 64.0, 64.0);
    for (k, w) in [2.0f32, 3.0, 4.0, 5.0].iter().enumerate() {
        gl.line_width(*w);
        gl.begin(GL_LINES);
        for j in 0..4 {
            let a = (k * 4 + j) as f32 * std::f32::consts::PI / 8.0 + 0.21;
            let (cx, cy) = (16.3 + 31.0 * (k % 2) as f32, 16.2 + 31.0 * (k / 2) as f32);
            pal(gl, k + j);
            gl.vertex_2f(cx + 2.1 * a.cos(), cy + 2.1 * a.sin());
            pal(gl, k + j + 3);
            gl.vertex_2f(cx + 13.3 * a.cos(), cy + 13.3 * a.sin());
        }
        gl.end();
    }
}

fn stipple_fan(gl: &mut dyn Gl, mode: GLenum) {
    gl.begin(mode);
    for k in 0..9 {
        let a = k as f32 * 0.37 + 0.11;
        pal(gl, k);
        gl.vertex_2f(4.3 + 5.2 * k as f32, 32.2 + 24.1 * a.sin());
    }
    gl.end();
}

/// Stippled lines: a strip (the counter runs on), independent lines (it restarts), and a
/// repeat factor.
fn line_stipple(gl: &mut dyn Gl) {
    clear(gl);
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_LINE_STIPPLE);
    gl.line_stipple(1, 0x3F07);
    stipple_fan(gl, GL_LINE_STRIP);
    gl.line_stipple(3, 0xA3C5);
    gl.begin(GL_LINES);
    for k in 0..6 {
        pal(gl, k + 2);
        gl.vertex_2f(2.4, 3.3 + 4.1 * k as f32);
        gl.vertex_2f(61.2, 5.6 + 4.1 * k as f32);
    }
    gl.end();
    gl.line_stipple(2, 0x0FF0);
    gl.begin(GL_LINE_LOOP);
    pal(gl, 5);
    gl.vertex_2f(40.3, 40.2);
    gl.vertex_2f(60.7, 44.6);
    gl.vertex_2f(50.1, 61.4);
    gl.end();
}

fn line_stipple_wide(gl: &mut dyn Gl) {
    clear(gl);
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_LINE_STIPPLE);
    gl.line_stipple(2, 0x33CF);
    gl.line_width(3.0);
    stipple_fan(gl, GL_LINE_STRIP);
}

fn star_polygon(gl: &mut dyn Gl, cx: f32, cy: f32, r: f32, n: usize) {
    gl.begin(GL_POLYGON);
    for k in 0..n {
        let a = k as f32 * std::f32::consts::TAU / n as f32 + 0.3;
        pal(gl, k);
        gl.vertex_2f(cx + r * a.cos(), cy + r * a.sin());
    }
    gl.end();
}

/// `glPolygonMode(GL_LINE)`: the outlines of a polygon, quads and a strip (no diagonals),
/// front faces filled and back faces outlined.
fn polygon_mode_line(gl: &mut dyn Gl) {
    clear(gl);
    pixel_space(gl, 64.0, 64.0);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    star_polygon(gl, 16.3, 16.2, 12.1, 7);
    gl.begin(GL_QUADS);
    pal(gl, 1);
    gl.vertex_2f(34.3, 4.2);
    gl.vertex_2f(60.6, 6.1);
    pal(gl, 2);
    gl.vertex_2f(58.2, 28.7);
    gl.vertex_2f(36.1, 26.4);
    gl.end();
    gl.polygon_mode(GL_FRONT, GL_FILL);
    gl.polygon_mode(GL_BACK, GL_LINE);
    gl.begin(GL_TRIANGLE_STRIP);
    for k in 0..6 {
        pal(gl, k);
        gl.vertex_2f(4.2 + 10.4 * k as f32, if k % 2 == 0 { 36.3 } else { 58.6 });
    }
    gl.end();
}

/// `glPolygonMode(GL_POINT)` with wide points.
fn polygon_mode_point(gl: &mut dyn Gl) {
    clear(gl);
    pixel_space(gl, 64.0, 64.0);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_POINT);
    gl.point_size(3.0);
    star_polygon(gl, 20.3, 20.2, 14.1, 9);
    gl.begin(GL_QUAD_STRIP);
    for k in 0..8 {
        pal(gl, k);
        gl.vertex_2f(
            6.2 + 7.4 * (k / 2) as f32,
            if k % 2 == 0 { 44.3 } else { 58.6 },
        );
    }
    gl.end();
}

/// Edge flags hide marked edges of polygons, triangles and quads in line mode.
fn edge_flags(gl: &mut dyn Gl) {
    clear(gl);
    pixel_space(gl, 64.0, 64.0);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    gl.begin(GL_POLYGON);
    for k in 0..6 {
        let a = k as f32 * std::f32::consts::TAU / 6.0 + 0.2;
        pal(gl, k);
        gl.edge_flag(u8::from(k % 2 == 0));
        gl.vertex_2f(18.3 + 13.2 * a.cos(), 18.1 + 13.2 * a.sin());
    }
    gl.end();
    gl.begin(GL_TRIANGLES);
    gl.edge_flag(1);
    pal(gl, 3);
    gl.vertex_2f(36.2, 4.3);
    gl.edge_flag(0);
    gl.vertex_2f(60.4, 8.1);
    gl.edge_flag(1);
    gl.vertex_2f(48.3, 30.2);
    gl.end();
    gl.begin(GL_QUADS);
    pal(gl, 4);
    gl.edge_flagv(&[0]);
    gl.vertex_2f(6.2, 38.3);
    gl.edge_flagv(&[1]);
    gl.vertex_2f(58.1, 36.4);
    gl.vertex_2f(56.3, 60.2);
    gl.edge_flagv(&[0]);
    gl.vertex_2f(8.4, 58.1);
    gl.end();
}

/// A tilted quad drawn twice at the same depth: the second pass with a polygon offset
/// towards the viewer wins everywhere under `GL_LESS`, the third (offset away) nowhere.
fn polygon_offset_fill(gl: &mut dyn Gl) {
    clear(gl);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -3.0);
    gl.rotatef(55.0, 1.0, 0.3, 0.0);
    gl.enable(GL_DEPTH_TEST);
    let quad = |gl: &mut dyn Gl, x0: f32, x1: f32| {
        gl.begin(GL_QUADS);
        gl.vertex_3f(x0, -1.5, 0.0);
        gl.vertex_3f(x1, -1.5, 0.0);
        gl.vertex_3f(x1, 1.5, 0.0);
        gl.vertex_3f(x0, 1.5, 0.0);
        gl.end();
    };
    gl.color_3f(0.8, 0.2, 0.2);
    quad(gl, -1.5, 1.5);
    gl.enable(GL_POLYGON_OFFSET_FILL);
    gl.polygon_offset(-1.0, -2.0);
    gl.color_3f(0.2, 0.8, 0.2);
    quad(gl, -1.5, 0.2);
    gl.polygon_offset(1.0, 2.0);
    gl.color_3f(0.2, 0.2, 0.9);
    quad(gl, -0.2, 1.5);
}

/// Hidden-line outlines: a filled pass pushed back with `GL_POLYGON_OFFSET_FILL`, then the
/// outlines in line mode at the unmodified depth, and point mode pulled forward with
/// `GL_POLYGON_OFFSET_POINT`.
fn polygon_offset_line(gl: &mut dyn Gl) {
    clear(gl);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.1, 0.05, -3.2);
    gl.rotatef(35.0, 1.0, 0.6, 0.2);
    gl.enable(GL_DEPTH_TEST);
    let grid = |gl: &mut dyn Gl| {
        for j in 0..4 {
            gl.begin(GL_QUAD_STRIP);
            for i in 0..5 {
                for dj in 0..2 {
                    let (x, y) = (-1.2 + 0.6 * i as f32, -1.2 + 0.6 * (j + dj) as f32);
                    gl.vertex_3f(x, y, 0.3 * (x * 1.3).sin() * y.cos());
                }
            }
            gl.end();
        }
    };
    gl.enable(GL_POLYGON_OFFSET_FILL);
    gl.polygon_offset(1.0, 1.0);
    gl.color_3f(0.3, 0.3, 0.5);
    grid(gl);
    gl.disable(GL_POLYGON_OFFSET_FILL);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    gl.color_3f(1.0, 1.0, 0.2);
    gl.depth_func(GL_LEQUAL);
    grid(gl);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_POINT);
    gl.point_size(3.0);
    gl.enable(GL_POLYGON_OFFSET_POINT);
    gl.polygon_offset(-1.0, -4.0);
    gl.color_3f(1.0, 0.2, 0.2);
    grid(gl);
}

/// `glPolygonStipple` over filled polygons, with the pattern unpacked LSB first too.
fn polygon_stipple(gl: &mut dyn Gl) {
    clear(gl);
    pixel_space(gl, 64.0, 64.0);
    let pattern: Vec<u8> = (0..128u32)
        .map(|k| {
            let (row, byte) = (k / 4, k % 4);
            ((row * 7 + byte * 13) as u8).rotate_left(row % 8) ^ 0x5A
        })
        .collect();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 4);
    gl.enable(GL_POLYGON_STIPPLE);
    gl.polygon_stipple(&pattern);
    star_polygon(gl, 20.3, 20.2, 17.1, 7);
    gl.pixel_storei(GL_UNPACK_LSB_FIRST, 1);
    gl.polygon_stipple(&pattern);
    gl.color_3f(0.9, 0.9, 0.2);
    gl.rectf(30.2, 28.3, 61.6, 61.2);
    gl.pixel_storei(GL_UNPACK_LSB_FIRST, 0);
}

/// `GL_POINT_SMOOTH` with blending: coverage in the alpha.
fn smooth_points(gl: &mut dyn Gl) {
    clear(gl);
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_POINT_SMOOTH);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (k, size) in [1.5f32, 3.0, 4.5, 7.0, 10.0].iter().enumerate() {
        gl.point_size(*size);
        gl.begin(GL_POINTS);
        for j in 0..3 {
            pal(gl, k + j);
            gl.vertex_2f(6.3 + 12.6 * k as f32, 10.4 + 20.2 * j as f32);
        }
        gl.end();
    }
}

/// Sizes of the points of [`smooth_point_sizes`], from below Mesa's smallest disc (radius 1)
/// to 11.
pub const SMOOTH_POINT_SIZES: [f32; 25] = [
    0.5, 0.8, 1.0, 1.3, 1.6, 1.9, 2.0, 2.2, 2.5, 2.8, 3.0, 3.3, 3.7, 4.0, 4.4, 5.0, 5.5, 6.0, 6.6,
    7.2, 8.0, 8.5, 9.0, 10.0, 11.0,
];

/// One smooth point of each of [`SMOOTH_POINT_SIZES`] on a 5 x 5 grid, centres at sub-pixel
/// positions that differ from cell to cell, blended.
fn smooth_point_sizes(gl: &mut dyn Gl) {
    clear(gl);
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_POINT_SMOOTH);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (i, size) in SMOOTH_POINT_SIZES.iter().enumerate() {
        let (col, row) = ((i % 5) as f32, (i / 5) as f32);
        let fx = (i as f32 * 0.37).fract() - 0.5;
        let fy = (i as f32 * 0.61).fract() - 0.5;
        gl.point_size(*size);
        pal(gl, i);
        gl.begin(GL_POINTS);
        gl.vertex_2f(6.4 + 12.8 * col + fx, 6.4 + 12.8 * row + fy);
        gl.end();
    }
}

/// `GL_LINE_SMOOTH` with blending.
fn smooth_lines(gl: &mut dyn Gl) {
    clear(gl);
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_LINE_SMOOTH);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (k, w) in [1.0f32, 2.0, 3.5].iter().enumerate() {
        gl.line_width(*w);
        gl.begin(GL_LINES);
        for j in 0..5 {
            let a = (k * 5 + j) as f32 * 0.41 + 0.07;
            pal(gl, k + j);
            gl.vertex_2f(32.2 + 6.0 * a.cos(), 32.1 + 6.0 * a.sin());
            gl.vertex_2f(32.2 + 29.0 * a.cos(), 32.1 + 29.0 * a.sin());
        }
        gl.end();
    }
}

/// Motion blur with the accumulation buffer: eight positions of a moving shape, each
/// accumulated with weight 1/8, returned once.
fn accum_motion_blur(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.clear_accum(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_ACCUM_BUFFER_BIT);
    for k in 0..8 {
        clear(gl);
        gl.color_3f(1.0, 0.8 - 0.05 * k as f32, 0.2);
        let x = 6.3 + 4.1 * k as f32;
        gl.rectf(x, 20.2, x + 18.4, 44.6);
        gl.accum(GL_ACCUM, 1.0 / 8.0);
    }
    gl.accum(GL_RETURN, 1.0);
}

/// Every operation: LOAD, ACCUM with a negative weight, MULT, ADD, RETURN with a scale
/// above 1 (clamped), a scissored accumulation clear, and the colour mask on RETURN.
fn accum_ops(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    // Values stay inside [-1, 1]: overflow is undefined (Mesa wraps, tilegl saturates).
    gl.clear_accum(0.25, -0.5, 0.5, 0.75);
    gl.clear(GL_ACCUM_BUFFER_BIT);
    gl.begin(GL_QUADS);
    gl.color_3f(1.0, 0.0, 0.0);
    gl.vertex_2f(0.0, 0.0);
    gl.color_3f(0.0, 1.0, 0.0);
    gl.vertex_2f(64.0, 0.0);
    gl.color_3f(0.0, 0.0, 1.0);
    gl.vertex_2f(64.0, 64.0);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.vertex_2f(0.0, 64.0);
    gl.end();
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(0, 0, 32, 64);
    gl.accum(GL_LOAD, 0.75);
    gl.scissor(32, 0, 32, 32);
    gl.accum(GL_ACCUM, -0.25);
    gl.accum(GL_MULT, 0.5);
    gl.scissor(0, 32, 64, 32);
    gl.accum(GL_ADD, 0.125);
    gl.disable(GL_SCISSOR_TEST);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.color_mask(1, 1, 0, 1);
    gl.accum(GL_RETURN, 1.5);
    gl.color_mask(1, 1, 1, 1);
}

/// An RGBA test image: colour ramps with a varying alpha.
fn rgba_image(w: usize, h: usize) -> Vec<u8> {
    let mut p = Vec::with_capacity(w * h * 4);
    for y in 0..h {
        for x in 0..w {
            p.extend_from_slice(&[
                (x * 255 / w.max(1)) as u8,
                (y * 255 / h.max(1)) as u8,
                ((x ^ y) * 37 % 256) as u8,
                (128 + (x * y) % 128) as u8,
            ]);
        }
    }
    p
}

/// `glDrawPixels` of RGBA, RGB (unaligned rows), luminance and packed-type images at several
/// raster positions, with blending on the last.
fn draw_pixels_color(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let img = rgba_image(20, 14);
    gl.raster_pos_2f(2.3, 3.6);
    gl.draw_pixels(20, 14, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
    // RGB rows of 3 * 13 = 39 bytes, alignment 1.
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    let rgb: Vec<u8> = (0..13 * 11 * 3).map(|k| (k * 7 % 256) as u8).collect();
    gl.raster_pos_2i(30, 4);
    gl.draw_pixels(13, 11, GL_RGB, GL_UNSIGNED_BYTE, Some(&rgb));
    let lum: Vec<u8> = (0..16 * 9).map(|k| (k * 5 % 256) as u8).collect();
    gl.raster_pos_2f(46.3, 20.2);
    gl.draw_pixels(16, 9, GL_LUMINANCE, GL_UNSIGNED_BYTE, Some(&lum));
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 4);
    let packed: Vec<u8> = (0..12 * 10)
        .flat_map(|k: u16| (k.wrapping_mul(2654) ^ 0x5a5a).to_ne_bytes())
        .collect();
    gl.raster_pos_2f(4.2, 30.3);
    gl.draw_pixels(12, 10, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, Some(&packed));
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.raster_pos_2f(24.4, 26.7);
    gl.draw_pixels(20, 14, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
}

/// Zoom (2, 1.6, negative, fractional) and scale/bias on the way in. The zoom
/// factors are even tenths, so no zoomed pixel edge falls exactly on a pixel centre (a tie
/// implementations break differently).
fn draw_pixels_zoom_transfer(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let img = rgba_image(8, 6);
    gl.pixel_zoom(2.0, 1.6);
    gl.raster_pos_2f(1.3, 1.2);
    gl.draw_pixels(8, 6, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
    gl.pixel_zoom(-1.4, -2.0);
    gl.raster_pos_2f(40.6, 30.4);
    gl.draw_pixels(8, 6, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
    gl.pixel_zoom(2.2, 0.8);
    gl.pixel_transferf(GL_RED_SCALE, 0.5);
    gl.pixel_transferf(GL_GREEN_BIAS, 0.25);
    gl.pixel_transferf(GL_BLUE_SCALE, -1.0);
    gl.pixel_transferf(GL_BLUE_BIAS, 1.0);
    gl.raster_pos_2f(20.2, 34.3);
    gl.draw_pixels(8, 6, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
    gl.pixel_zoom(1.0, 1.0);
    gl.pixel_transferf(GL_RED_SCALE, 1.0);
    gl.pixel_transferf(GL_GREEN_BIAS, 0.0);
    gl.pixel_transferf(GL_BLUE_SCALE, 1.0);
    gl.pixel_transferf(GL_BLUE_BIAS, 0.0);
    // GL_MAP_COLOR is left out here: Mesa 22 looks the maps up through a texture (index
    // by truncation, some entries off by several steps) where section 3.6.5 rounds
    // `c * (size - 1)`; tests/pixel_rect.rs checks tilegl's maps against the equations.
    let big = rgba_image(24, 20);
    gl.pixel_transferf(GL_ALPHA_SCALE, 0.5);
    gl.pixel_transferf(GL_RED_BIAS, -0.25);
    gl.raster_pos_2f(38.1, 40.2);
    gl.draw_pixels(24, 20, GL_RGBA, GL_UNSIGNED_BYTE, Some(&big));
    gl.pixel_transferf(GL_ALPHA_SCALE, 1.0);
    gl.pixel_transferf(GL_RED_BIAS, 0.0);
}

/// Depth and stencil rectangles, then geometry tested against them.
fn draw_pixels_depth_stencil(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.clear_stencil(0);
    gl.clear(GL_STENCIL_BUFFER_BIT);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_ALWAYS);
    gl.color_mask(0, 0, 0, 0);
    // A depth ramp written as floats.
    let depth: Vec<u8> = (0..40 * 40)
        .flat_map(|k| ((k % 40) as f32 / 40.0).to_ne_bytes())
        .collect();
    gl.raster_pos_2i(4, 4);
    gl.draw_pixels(40, 40, GL_DEPTH_COMPONENT, GL_FLOAT, Some(&depth));
    gl.color_mask(1, 1, 1, 1);
    gl.depth_func(GL_LESS);
    // A flat quad at window z = 0.5 shows where the ramp is farther.
    gl.color_3f(0.9, 0.4, 0.1);
    gl.rectf(0.0, 0.0, 64.0, 64.0);
    gl.disable(GL_DEPTH_TEST);
    // Stencil: a checker of bytes, then a stencil test. (No index offset: Mesa 22 ignores
    // GL_INDEX_SHIFT/OFFSET for stencil in glDrawPixels, which section 3.6.5 applies;
    // tests/pixel_rect.rs checks tilegl's index arithmetic.)
    let st: Vec<u8> = (0..32 * 32)
        .map(|k| (((k % 32) / 4 + (k / 32) / 4) % 2) as u8)
        .collect();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.raster_pos_2i(28, 28);
    gl.draw_pixels(32, 32, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, Some(&st));
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_EQUAL, 1, 0xFF);
    gl.color_3f(0.2, 0.3, 1.0);
    gl.rectf(0.0, 0.0, 64.0, 64.0);
    gl.disable(GL_STENCIL_TEST);
}

/// Text with `glBitmap`: glyphs from a small procedural font, the raster position advancing,
/// colours taken at `glRasterPos` time, LSB-first data, and a scissor.
fn bitmap_text(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let mut rng = XorShift::new(7);
    let glyphs: Vec<Vec<u8>> = (0..8)
        .map(|_| (0..10).map(|_| (rng.next_u64() & 0xFE) as u8).collect())
        .collect();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    for line in 0..4 {
        pal(gl, line);
        gl.raster_pos_2f(2.4, 52.7 - 13.0 * line as f32);
        if line == 2 {
            gl.pixel_storei(GL_UNPACK_LSB_FIRST, 1);
        }
        if line == 3 {
            gl.enable(GL_SCISSOR_TEST);
            gl.scissor(10, 0, 30, 64);
        }
        for k in 0..8 {
            gl.bitmap(7, 10, 0.5, 1.5, 7.5, 0.25, &glyphs[(k + line) % 8]);
        }
        gl.pixel_storei(GL_UNPACK_LSB_FIRST, 0);
    }
    gl.disable(GL_SCISSOR_TEST);
    // A bitmap with no bits only moves the raster position.
    gl.raster_pos_2f(50.0, 4.0);
    gl.bitmap(0, 0, 0.0, 0.0, -40.0, 2.0, &[]);
    gl.bitmap(7, 10, 0.0, 0.0, 0.0, 0.0, &glyphs[0]);
}

/// `glCopyPixels` of colour (overlapping, zoomed) and of depth.
fn copy_pixels(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.begin(GL_TRIANGLES);
    for k in 0..3 {
        pal(gl, k);
        gl.vertex_2f([2.2, 28.4, 10.1][k], [2.3, 6.1, 27.7][k]);
    }
    gl.end();
    gl.raster_pos_2i(12, 8);
    gl.copy_pixels(0, 0, 30, 30, GL_COLOR);
    gl.pixel_zoom(1.0, -1.0);
    gl.raster_pos_2i(34, 63);
    gl.copy_pixels(0, 0, 30, 30, GL_COLOR);
    gl.pixel_zoom(1.0, 1.0);
    // Depth: a tilted quad, its depth copied to the right, then a flat quad tested against it.
    gl.enable(GL_DEPTH_TEST);
    gl.color_3f(0.3, 0.3, 0.3);
    gl.begin(GL_QUADS);
    gl.vertex_3f(0.0, 40.0, -0.9);
    gl.vertex_3f(30.0, 40.0, 0.9);
    gl.vertex_3f(30.0, 64.0, 0.9);
    gl.vertex_3f(0.0, 64.0, -0.9);
    gl.end();
    gl.raster_pos_2i(34, 2);
    gl.copy_pixels(0, 40, 30, 24, GL_DEPTH);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.rectf(34.0, 2.0, 64.0, 26.0);
}

/// `glWindowPos` ignores the transforms; a raster position outside the view volume is
/// invalid and draws nothing; lighting colours the raster position.
fn window_pos_and_invalid_raster(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let img = rgba_image(10, 10);
    gl.matrix_mode(GL_MODELVIEW);
    gl.translatef(100.0, 0.0, 0.0);
    gl.window_pos_2f(3.3, 3.4);
    gl.draw_pixels(10, 10, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
    // Translated out of the view volume: invalid, nothing drawn.
    gl.raster_pos_2f(5.0, 5.0);
    gl.draw_pixels(10, 10, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
    gl.load_identity();
    // The raster colour is lit when lighting is on.
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.normal_3f(0.0, 0.0, 1.0);
    gl.raster_pos_2f(30.2, 30.7);
    gl.disable(GL_LIGHTING);
    let bits = [0xAAu8; 8 * 4]; // rows of 2 bytes padded to the alignment of 4
    gl.bitmap(16, 8, 0.0, 0.0, 0.0, 0.0, &bits);
    gl.window_pos_3f(40.0, 10.0, 0.5);
    gl.color_3f(0.0, 1.0, 0.5);
    gl.bitmap(16, 8, 0.0, 0.0, 0.0, 0.0, &bits);
}

/// `GL_POLYGON_SMOOTH` with blending: separate triangles (no shared edges).
fn smooth_polygons(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_POLYGON_SMOOTH);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.begin(GL_TRIANGLES);
    pal(gl, 0);
    gl.vertex_2f(4.3, 3.2);
    gl.vertex_2f(30.6, 8.1);
    gl.vertex_2f(12.2, 33.7);
    pal(gl, 1);
    gl.vertex_2f(36.1, 5.4);
    gl.vertex_2f(61.3, 20.2);
    gl.vertex_2f(40.7, 30.9);
    pal(gl, 2);
    gl.vertex_2f(8.8, 40.2);
    gl.vertex_2f(58.9, 36.6);
    gl.vertex_2f(30.2, 61.3);
    gl.end();
}

/// Many faint additive layers (as xscreensaver's flurry draws its smoke): a luminance-alpha
/// texture modulated by a dim colour, blended with SRC_ALPHA/ONE, each layer adding less than
/// one 8-bit step before rounding, plus a fading rectangle.
fn additive_faint_layers(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let texels: Vec<u8> = (0..16 * 16)
        .flat_map(|k| [40 + (k % 16) as u8 * 10, 30 + (k / 16) as u8 * 12])
        .collect();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        2,
        16,
        16,
        0,
        GL_LUMINANCE_ALPHA,
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.tex_envf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as f32);
    gl.enable(GL_ALPHA_TEST);
    gl.alpha_func(GL_GREATER, 0.0);
    gl.enable(GL_BLEND);
    // The destination alpha after repeated SRC_ALPHA blending differs between
    // implementations (llvmpipe and softpipe disagree on a third of the pixels); only the
    // colour is compared.
    gl.color_mask(1, 1, 1, 0);
    for layer in 0..40 {
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        gl.disable(GL_TEXTURE_2D);
        gl.color_4f(0.0, 0.0, 0.0, 0.05);
        gl.rectd(0.0, 0.0, 64.0, 64.0);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE);
        gl.enable(GL_TEXTURE_2D);
        let k = layer as f32;
        gl.begin(GL_QUADS);
        gl.color_4f(0.07 + 0.002 * k, 0.056, 0.024, 0.367);
        gl.tex_coord_2f(0.0, 0.0);
        gl.vertex_2f(2.0 + k * 0.3, 3.0);
        gl.tex_coord_2f(1.0, 0.0);
        gl.vertex_2f(60.0, 4.0 + k * 0.2);
        gl.tex_coord_2f(1.0, 1.0);
        gl.vertex_2f(58.0, 61.0);
        gl.tex_coord_2f(0.0, 1.0);
        gl.vertex_2f(3.0, 59.0 - k * 0.4);
        gl.end();
    }
}

/// Flat shading with texturing and fog: colours from the provoking vertex, texture and fog
/// coordinates still interpolated (flurry's smoke sprites relied on this).
fn flat_textured_fogged(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let texels: Vec<u8> = (0..8 * 8)
        .flat_map(|k| {
            let on = (k % 8 + k / 8) % 2 == 0;
            if on {
                [250, 240, 200, 255]
            } else {
                [40, 60, 90, 255]
            }
        })
        .collect();
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        8,
        8,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_FOG);
    gl.fogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE as i32);
    gl.fogi(GL_FOG_MODE, GL_LINEAR as i32);
    gl.fogf(GL_FOG_START, 0.0);
    gl.fogf(GL_FOG_END, 1.0);
    gl.fogfv(GL_FOG_COLOR, &[0.2, 0.5, 0.3, 1.0]);
    gl.shade_model(GL_FLAT);
    // Two explicit triangles: how a quad is split is left to the implementation.
    let corners = [
        (4.3f32, 4.2f32, 0.0f32, 0.0f32, 0.0f32),
        (60.1, 6.7, 1.0, 0.0, 0.3),
        (57.8, 59.9, 1.0, 1.0, 0.9),
        (5.6, 58.3, 0.0, 1.0, 0.5),
    ];
    gl.begin(GL_TRIANGLES);
    for (k, &i) in [0usize, 1, 2, 0, 2, 3].iter().enumerate() {
        let (x, y, s, t, f) = corners[i];
        pal(gl, k + 1);
        gl.tex_coord_2f(s, t);
        gl.fog_coordf(f);
        gl.vertex_2f(x, y);
    }
    gl.end();
}

/// EXT_blend_equation_separate: different equations for colour and alpha, alpha shown by a
/// second pass that writes destination alpha as colour.
fn blend_equation_separate(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.clear_color(0.3, 0.5, 0.2, 0.6);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_ONE, GL_ONE);
    let modes = [
        (GL_FUNC_ADD, GL_MIN),
        (GL_FUNC_SUBTRACT, GL_MAX),
        (GL_FUNC_REVERSE_SUBTRACT, GL_FUNC_ADD),
        (GL_MAX, GL_FUNC_SUBTRACT),
    ];
    for (k, (rgb, alpha)) in modes.into_iter().enumerate() {
        gl.blend_equation_separate_ext(rgb, alpha);
        gl.color_4f(0.6, 0.2 + 0.1 * k as f32, 0.5, 0.2 + 0.2 * k as f32);
        gl.rectf(16.0 * k as f32, 0.0, 16.0 * k as f32 + 16.0, 64.0);
    }
    // Show destination alpha in the upper half: colour = dst alpha (blend DST_ALPHA, ZERO).
    gl.blend_equation(GL_FUNC_ADD);
    gl.blend_func(GL_DST_ALPHA, GL_ZERO);
    gl.color_4f(1.0, 1.0, 1.0, 1.0);
    gl.rectf(0.0, 32.0, 64.0, 64.0);
}

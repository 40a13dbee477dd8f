//! Differential scenes for the fidelity classes found replaying real programs (issue 24):
//! antialiased wide lines, all user clip planes at once, implementation limits (point sizes
//! and line widths of 1000, textures 16384 texels wide, float textures), fog on lit, textured
//! geometry receding into the distance, and anisotropic filtering towards the horizon.

use crate::compare::Scene;
use crate::scenes::{pal, scene, scene_with, spread};
use tilegl::enums::*;
use tilegl::Gl;

/// Fidelity scenes, in report order.
pub const FIDELITY_SCENES: &[Scene] = &[
    scene("smooth_lines_width_1", smooth_lines_width_1),
    scene("smooth_lines_width_2_5", smooth_lines_width_2_5),
    scene("smooth_lines_width_4", smooth_lines_width_4),
    scene("smooth_lines_width_7", smooth_lines_width_7),
    scene(
        "smooth_lines_receding_width_1",
        smooth_lines_receding_width_1,
    ),
    scene(
        "smooth_lines_receding_width_2_5",
        smooth_lines_receding_width_2_5,
    ),
    scene(
        "smooth_lines_receding_width_4",
        smooth_lines_receding_width_4,
    ),
    scene(
        "smooth_lines_receding_width_7",
        smooth_lines_receding_width_7,
    ),
    big("points_and_lines_of_1000", points_and_lines_of_1000),
    big("smooth_lines_of_1000", smooth_lines_of_1000),
    scene("six_clip_planes", six_clip_planes),
    Scene {
        width: 256,
        height: 256,
        ..scene("clip_plane_subsets", clip_plane_subsets)
    },
    scene("float_texture_16384_wide", float_texture_16384_wide),
    scene("tunnel_exp_fog", tunnel_exp_fog),
    scene("tube_sphere_map_linear_fog", tube_sphere_map_linear_fog),
    // llvmpipe vs softpipe: 0.977 % of the pixels off by more than 8 (tilegl vs llvmpipe
    // 0.073 %, vs softpipe 1.050 %; `--bin calibrate`).
    scene_with("aniso_horizon", aniso_horizon, spread(0.00977)),
    scene("lit_after_arrays", lit_after_arrays),
    scene("point_sprites", point_sprites),
    scene("smooth_line_joints", smooth_line_joints),
    scene("quad_splits", quad_splits),
];

/// The six user clip planes of [`six_clip_planes`], in object coordinates of the box
/// `[-0.6, 0.6]^3` tilted towards the viewer (each plane keeps one side of a box face).
const SIX_PLANES: [[f64; 4]; 6] = [
    [1.0, 0.0, 0.0, 0.6],
    [-1.0, 0.0, 0.0, 0.55],
    [0.0, 1.0, 0.0, 0.5],
    [0.0, -1.0, 0.0, 0.6],
    [0.3, 0.2, 1.0, 0.45],
    [0.1, -0.3, -1.0, 0.5],
];

/// Sets the scene's projection, modelview and the planes of `mask` (bit i: `GL_CLIP_PLANEi`).
fn clip_plane_setup(gl: &mut dyn Gl, mask: u32) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -3.0);
    gl.rotatef(25.0, 1.0, 1.0, 0.0);
    for (i, p) in SIX_PLANES.iter().enumerate() {
        gl.clip_plane(GL_CLIP_PLANE0 + i as GLenum, p);
        if mask & (1 << i) != 0 {
            gl.enable(GL_CLIP_PLANE0 + i as GLenum);
        } else {
            gl.disable(GL_CLIP_PLANE0 + i as GLenum);
        }
    }
}

/// All six user clip planes at once on a lit sphere, quads through the box, lines, points
/// (wide ones too) and a bitmap at a clipped raster position.
fn six_clip_planes(gl: &mut dyn Gl) {
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    clip_plane_setup(gl, 0x3F);
    clipped_content(gl);
}

/// Every subset of the six planes, one per 32 x 32 viewport of an 8 x 8 grid (the subset's
/// number is the cell's index, row by row from the bottom left).
fn clip_plane_subsets(gl: &mut dyn Gl) {
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for mask in 0..64 {
        gl.viewport(32 * (mask as i32 % 8), 32 * (mask as i32 / 8), 32, 32);
        clip_plane_setup(gl, mask);
        clipped_content(gl);
    }
}

/// What the clip-plane scenes draw: a lit sphere, quads through the box, wide lines, wide
/// points.
fn clipped_content(gl: &mut dyn Gl) {
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_NORMALIZE);
    crate::scenes::sphere(gl, 12, 16);
    gl.disable(GL_LIGHTING);
    gl.begin(GL_QUADS);
    for k in 0..3 {
        pal(gl, k);
        let z = -0.7 + 0.7 * k as f32;
        gl.vertex_3f(-1.0, -1.0, z);
        gl.vertex_3f(1.0, -1.0, z);
        gl.vertex_3f(1.0, 1.0, z);
        gl.vertex_3f(-1.0, 1.0, z);
    }
    gl.end();
    gl.line_width(3.0);
    gl.begin(GL_LINES);
    for k in 0..8 {
        pal(gl, k + 3);
        let a = k as f32 * 0.8;
        gl.vertex_3f(-1.2 * a.cos(), -1.2 * a.sin(), 0.9);
        gl.vertex_3f(1.2 * a.cos(), 1.2 * a.sin(), -0.9);
    }
    gl.end();
    gl.point_size(5.0);
    gl.begin(GL_POINTS);
    for k in 0..25 {
        pal(gl, k);
        gl.vertex_3f(
            -1.0 + 0.083 * k as f32,
            0.9 - 0.075 * k as f32,
            0.58 - 0.05 * k as f32,
        );
    }
    gl.end();
}

/// A 320 x 320 scene: room for the edges of primitives 255 pixels wide.
const fn big(name: &'static str, draw: fn(&mut dyn Gl)) -> Scene {
    Scene {
        width: 320,
        height: 320,
        ..scene(name, draw)
    }
}

/// Pixel space of the 320 x 320 scenes, over black.
fn big_pixel_space(gl: &mut dyn Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 320.0, 0.0, 320.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/// `glPointSize(1000)` and `glLineWidth(1000)`: both are clamped to the implementation's
/// largest size (Mesa: 255, `GL_POINT_SIZE_RANGE` and `GL_LINE_WIDTH_RANGE`), so the edges of
/// the squares and bands fall inside the window; overlapping primitives are added.
fn points_and_lines_of_1000(gl: &mut dyn Gl) {
    big_pixel_space(gl);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_ONE, GL_ONE);
    gl.point_size(1000.0);
    gl.begin(GL_POINTS);
    gl.color_3f(0.5, 0.0, 0.0);
    gl.vertex_2f(60.3, 70.6);
    gl.color_3f(0.0, 0.5, 0.0);
    gl.vertex_2f(250.7, 240.2);
    gl.end();
    gl.line_width(1000.0);
    gl.begin(GL_LINES);
    // x-major: a vertical band 255 rows tall; y-major: 255 columns wide.
    gl.color_3f(0.0, 0.0, 0.5);
    gl.vertex_2f(20.2, 150.4);
    gl.vertex_2f(300.6, 190.1);
    gl.color_3f(0.25, 0.25, 0.0);
    gl.vertex_2f(140.3, 10.7);
    gl.vertex_2f(170.9, 300.2);
    gl.end();
}

/// Antialiased lines of width 1000 (clamped to 255): the quad's sides and ends show inside
/// the window.
fn smooth_lines_of_1000(gl: &mut dyn Gl) {
    big_pixel_space(gl);
    gl.enable(GL_LINE_SMOOTH);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE);
    gl.line_width(1000.0);
    gl.begin(GL_LINES);
    gl.color_4f(1.0, 0.0, 0.0, 0.5);
    gl.vertex_2f(100.2, 150.4);
    gl.vertex_2f(220.6, 170.1);
    gl.color_4f(0.0, 1.0, 0.0, 0.5);
    gl.vertex_2f(160.3, 120.7);
    gl.vertex_2f(150.9, 200.2);
    gl.end();
}

/// Pixel space over black (the smooth-line captures blend over black).
fn black_pixel_space(gl: &mut dyn Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 64.0, 0.0, 64.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/// Antialiased lines of one width, blended over black with `GL_NICEST`, radiating from the
/// centre at twelve angles (both majors, both directions, the diagonals and shallow slopes),
/// plus short segments and segments on pixel centres and edges.
fn smooth_lines(gl: &mut dyn Gl, width: f32) {
    black_pixel_space(gl);
    gl.enable(GL_LINE_SMOOTH);
    gl.hint(GL_LINE_SMOOTH_HINT, GL_NICEST);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.line_width(width);
    gl.begin(GL_LINES);
    for k in 0..12 {
        let a = k as f32 * std::f32::consts::PI / 6.0 + 0.13;
        pal(gl, k);
        gl.vertex_2f(32.3 + 7.0 * a.cos(), 32.2 + 7.0 * a.sin());
        pal(gl, k + 3);
        gl.vertex_2f(32.3 + 28.0 * a.cos(), 32.2 + 28.0 * a.sin());
    }
    gl.end();
    // Axis-aligned segments on pixel centres and on pixel edges, and a short one.
    gl.begin(GL_LINES);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.vertex_2f(3.5, 3.5);
    gl.vertex_2f(20.5, 3.5);
    gl.vertex_2f(60.0, 4.0);
    gl.vertex_2f(60.0, 20.0);
    gl.color_3f(1.0, 1.0, 0.0);
    gl.vertex_2f(44.2, 60.3);
    gl.vertex_2f(45.1, 60.9);
    gl.end();
}

fn smooth_lines_width_1(gl: &mut dyn Gl) {
    smooth_lines(gl, 1.0);
}

fn smooth_lines_width_2_5(gl: &mut dyn Gl) {
    smooth_lines(gl, 2.5);
}

fn smooth_lines_width_4(gl: &mut dyn Gl) {
    smooth_lines(gl, 4.0);
}

fn smooth_lines_width_7(gl: &mut dyn Gl) {
    smooth_lines(gl, 7.0);
}

/// Antialiased lines of one width in perspective: six depth-tested loops of twelve segments
/// each receding from the viewer (1/w differs between the ends of every segment), plus one
/// long segment from near the eye to far away.
fn smooth_lines_receding(gl: &mut dyn Gl, width: f32) {
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.5, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -6.0);
    gl.rotatef(30.0, 1.0, 0.4, 0.1);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LINE_SMOOTH);
    gl.hint(GL_LINE_SMOOTH_HINT, GL_NICEST);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.line_width(width);
    for j in 0..6 {
        gl.begin(GL_LINE_LOOP);
        for k in 0..12 {
            pal(gl, k + j);
            let a = k as f32 * std::f32::consts::FRAC_PI_6;
            gl.vertex_3f(2.5 * a.cos(), 2.5 * a.sin(), -2.0 + 0.8 * j as f32);
        }
        gl.end();
    }
    gl.load_identity();
    gl.color_3f(1.0, 1.0, 1.0);
    gl.begin(GL_LINES);
    gl.vertex_3f(-1.3, -0.2, -1.6);
    gl.vertex_3f(5.0, 0.3, -12.0);
    gl.end();
}

fn smooth_lines_receding_width_1(gl: &mut dyn Gl) {
    smooth_lines_receding(gl, 1.0);
}

fn smooth_lines_receding_width_2_5(gl: &mut dyn Gl) {
    smooth_lines_receding(gl, 2.5);
}

fn smooth_lines_receding_width_4(gl: &mut dyn Gl) {
    smooth_lines_receding(gl, 4.0);
}

fn smooth_lines_receding_width_7(gl: &mut dyn Gl) {
    smooth_lines_receding(gl, 7.0);
}

/// A 16384 x 2 `GL_RGBA32F` texture (`GL_FLOAT` data in [0, 1], neighbours differing) drawn
/// twice: the far end magnified with `GL_NEAREST` (the top half), the whole width minified
/// with generated mipmaps and `GL_LINEAR_MIPMAP_LINEAR` (the bottom half, LOD about 8).
fn float_texture_16384_wide(gl: &mut dyn Gl) {
    const TW: usize = 16384;
    let mut bytes = Vec::with_capacity(TW * 2 * 16);
    for _row in 0..2 {
        for i in 0..TW {
            let t = [
                (i % 251) as f32 / 250.0,
                ((i / 7) % 239) as f32 / 238.0,
                (i / 64) as f32 / 255.0,
                1.0,
            ];
            for c in t {
                bytes.extend_from_slice(&c.to_ne_bytes());
            }
        }
    }
    black_pixel_space(gl);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE as i32);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA32F_ARB as i32,
        TW as i32,
        2,
        0,
        GL_RGBA,
        GL_FLOAT,
        Some(&bytes),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    let quad = |gl: &mut dyn Gl, s0: f32, s1: f32, y0: f32, y1: f32| {
        gl.begin(GL_QUADS);
        gl.tex_coord_2f(s0, 0.5);
        gl.vertex_2f(0.0, y0);
        gl.tex_coord_2f(s1, 0.5);
        gl.vertex_2f(64.0, y0);
        gl.tex_coord_2f(s1, 0.5);
        gl.vertex_2f(64.0, y1);
        gl.tex_coord_2f(s0, 0.5);
        gl.vertex_2f(0.0, y1);
        gl.end();
    };
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    // 64 pixels over 32 texels at the far end: each texel two pixels wide, its edges between
    // pixel centres (no ties).
    quad(gl, 16351.75 / 16384.0, 16383.75 / 16384.0, 32.0, 64.0);
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    quad(gl, 0.0, 1.0, 0.0, 32.0);
}

/// A lit, textured tunnel receding into the distance under fog (`mode`, `GL_NICEST` hints):
/// the walls are quads of a 16-sided tube from z = -1 to z = -40, a checker texture modulated
/// by the lighting.
fn fogged_tunnel(gl: &mut dyn Gl, mode: GLenum, sphere_map: bool) {
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.6, 0.6, -0.6, 0.6, 1.0, 60.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.rotatef(7.0, 0.3, 1.0, 0.0);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.0, 0.0, 0.0, 1.0]);
    gl.enable(GL_FOG);
    gl.fogi(GL_FOG_MODE, mode as i32);
    gl.fogf(GL_FOG_DENSITY, 0.3);
    gl.fogf(GL_FOG_START, 2.0);
    gl.fogf(GL_FOG_END, 30.0);
    gl.fogfv(GL_FOG_COLOR, &[0.2, 0.3, 0.4, 1.0]);
    gl.hint(GL_FOG_HINT, GL_NICEST);
    gl.hint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    let mut texels = Vec::with_capacity(16 * 16 * 4);
    for y in 0..16 {
        for x in 0..16 {
            let on = (x / 4 + y / 4) % 2 == 0;
            texels.extend_from_slice(if on {
                &[255, 230, 200, 255]
            } else {
                &[90, 120, 60, 255]
            });
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
        Some(&texels),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    if sphere_map {
        gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
        gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
        gl.enable(GL_TEXTURE_GEN_S);
        gl.enable(GL_TEXTURE_GEN_T);
    }
    let n = 16;
    for ring in 0..13 {
        let (z0, z1) = (-1.0 - 3.0 * ring as f32, -4.0 - 3.0 * ring as f32);
        gl.begin(GL_QUAD_STRIP);
        for k in 0..=n {
            let a = k as f32 * std::f32::consts::TAU / n as f32;
            let (c, s) = (a.cos(), a.sin());
            gl.normal_3f(-c, -s, 0.0);
            gl.tex_coord_2f(k as f32 / 4.0, ring as f32);
            gl.vertex_3f(2.0 * c, 2.0 * s, z0);
            gl.tex_coord_2f(k as f32 / 4.0, ring as f32 + 1.0);
            gl.vertex_3f(2.0 * c, 2.0 * s, z1);
        }
        gl.end();
    }
}

fn tunnel_exp_fog(gl: &mut dyn Gl) {
    fogged_tunnel(gl, GL_EXP, false);
}

fn tube_sphere_map_linear_fog(gl: &mut dyn Gl) {
    fogged_tunnel(gl, GL_LINEAR, true);
}

/// A mipmapped checker floor receding to the horizon under `GL_TEXTURE_MAX_ANISOTROPY_EXT` 16
/// (`GL_LINEAR_MIPMAP_LINEAR`). tilegl vs llvmpipe: 33.96 % of the pixels off by more than 8
/// with tilegl's own footprint rule, 0.073 % (3 pixels, max 17) with Mesa's elliptical
/// weighted average; tilegl vs softpipe 1.05 %.
fn aniso_horizon(gl: &mut dyn Gl) {
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 500.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    // Looking down a little, the floor turned: the footprints' long axes are diagonal in
    // texture space and the floor reaches from the bottom edge to the horizon.
    gl.rotatef(12.0, 1.0, 0.0, 0.0);
    gl.rotatef(33.0, 0.0, 1.0, 0.0);
    let size = 64usize;
    let mut texels = Vec::with_capacity(size * size * 4);
    for y in 0..size {
        for x in 0..size {
            let on = (x / 4 + y / 4) % 2 == 0;
            texels.extend_from_slice(if on {
                &[250, 240, 220, 255]
            } else {
                &[40, 60, 120, 255]
            });
        }
    }
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE as i32);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        size as i32,
        size as i32,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 16.0);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.begin(GL_QUADS);
    for (s, t, x, z) in [
        (0.0, 0.0, -300.0, 300.0),
        (150.0, 0.0, 300.0, 300.0),
        (150.0, 150.0, 300.0, -300.0),
        (0.0, 150.0, -300.0, -300.0),
    ] {
        gl.tex_coord_2f(s, t);
        gl.vertex_3f(x, -1.0, z);
    }
    gl.end();
}

/// A lit mesh drawn from normal and colour arrays (`GL_COLOR_MATERIAL` on), then lit
/// triangles and lines drawn with the current normal and colour, in immediate mode, again
/// from a display list holding a `glDrawArrays`, and after `glArrayElement`: the current
/// values after each (left as they were by array draws, set by `glArrayElement`) decide the
/// later primitives' lighting.
fn lit_after_arrays(gl: &mut dyn Gl) {
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 0.2, 1.0, 0.0]);
    gl.enable(GL_COLOR_MATERIAL);
    gl.normal_3f(0.0, 0.0, 1.0);
    gl.color_3f(0.9, 0.8, 0.2);
    // Six vertices: xyz, normal, rgba; normals facing away from the light at the end.
    static VERTS: [f32; 18] = [
        -0.9, 0.5, 0.0, -0.5, 0.5, 0.0, -0.9, 0.9, 0.0, -0.5, 0.9, 0.0, -0.1, 0.5, 0.0, -0.1, 0.9,
        0.0,
    ];
    static NORMALS: [f32; 18] = [
        0.0, 0.0, 1.0, 0.3, 0.0, 1.0, 0.0, 0.3, 1.0, 0.0, 0.0, -1.0, 0.0, 0.0, -1.0, 0.0, 0.0, -1.0,
    ];
    static COLORS: [f32; 24] = [
        1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.2, 0.2, 0.2, 1.0, 0.1, 0.1,
        0.1, 1.0, 0.3, 0.0, 0.3, 1.0,
    ];
    let ptr = |v: &'static [f32]| tilegl::ClientPtr(v.as_ptr() as usize);
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.enable_client_state(GL_NORMAL_ARRAY);
    gl.enable_client_state(GL_COLOR_ARRAY);
    gl.vertex_pointer(3, GL_FLOAT, 0, ptr(&VERTS));
    gl.normal_pointer(GL_FLOAT, 0, ptr(&NORMALS));
    gl.color_pointer(4, GL_FLOAT, 0, ptr(&COLORS));
    gl.draw_arrays(GL_TRIANGLE_STRIP, 0, 6);
    let lit_shapes = |gl: &mut dyn Gl, y: f32| {
        gl.begin(GL_TRIANGLES);
        gl.vertex_2f(-0.9, y);
        gl.vertex_2f(-0.3, y);
        gl.vertex_2f(-0.6, y + 0.3);
        gl.end();
        gl.line_width(3.0);
        gl.begin(GL_LINES);
        gl.vertex_2f(0.0, y);
        gl.vertex_2f(0.9, y + 0.3);
        gl.end();
    };
    lit_shapes(gl, 0.0);
    gl.new_list(1, GL_COMPILE);
    gl.draw_arrays(GL_TRIANGLE_STRIP, 0, 6);
    gl.end_list();
    gl.translatef(1.0, 0.0, 0.0);
    gl.call_list(1);
    gl.load_identity();
    lit_shapes(gl, -0.45);
    gl.begin(GL_POINTS);
    gl.array_element(4);
    gl.end();
    lit_shapes(gl, -0.9);
}

/// Point sprites (ARB_point_sprite, which Mesa offers and captures use): a mipmapped texture
/// of a different colour per level and a checkerboard at level 0, on sprites of sizes 1.5 to
/// 40 (not rounded), both coordinate origins, GL_COORD_REPLACE on unit 0 only (unit 1 keeps
/// the vertex's coordinates) and with POINT_SMOOTH on, which sprites ignore.
fn point_sprites(gl: &mut dyn Gl) {
    black_pixel_space(gl);
    let mut names = [0u32; 2];
    gl.gen_textures(2, &mut names);
    gl.bind_texture(GL_TEXTURE_2D, names[0]);
    for level in 0..6 {
        let n = 32usize >> level;
        let mut texels = Vec::with_capacity(n * n * 4);
        for j in 0..n {
            for i in 0..n {
                let c: [u8; 4] = match level {
                    0 if (i / 4 + j / 4) % 2 == 0 => [255, 255, 255, 255],
                    0 => [40, 40, 200, 255],
                    1 => [255, 0, 0, 255],
                    2 => [0, 255, 0, 255],
                    3 => [255, 255, 0, 255],
                    4 => [0, 255, 255, 255],
                    _ => [255, 0, 255, 255],
                };
                // The top-left quarter of level 0 marks the origin.
                let c = if level == 0 && i < n / 4 && j >= 3 * n / 4 {
                    [255, 128, 0, 255]
                } else {
                    c
                };
                texels.extend_from_slice(&c);
            }
        }
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            level,
            GL_RGBA as i32,
            n as i32,
            n as i32,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&texels),
        );
    }
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_NEAREST_MIPMAP_NEAREST as i32,
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_POINT_SPRITE);
    gl.tex_envi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE as i32);
    gl.color_3f(1.0, 1.0, 1.0);
    let sprite = |gl: &mut dyn Gl, size: f32, x: f32, y: f32| {
        gl.point_size(size);
        gl.begin(GL_POINTS);
        gl.vertex_2f(x, y);
        gl.end();
    };
    // Upper-left origin (the default), then lower-left.
    sprite(gl, 27.3, 16.0, 48.0);
    sprite(gl, 13.7, 40.3, 52.6);
    sprite(gl, 6.5, 56.0, 56.0);
    sprite(gl, 1.5, 56.2, 43.8);
    gl.point_parameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT as i32);
    sprite(gl, 21.2, 16.5, 18.4);
    gl.enable(GL_POINT_SMOOTH);
    sprite(gl, 9.9, 40.0, 22.0);
    gl.disable(GL_POINT_SMOOTH);
    // Unit 1 textured too, without GL_COORD_REPLACE: its coordinate is the vertex's.
    gl.active_texture(GL_TEXTURE1);
    gl.bind_texture(GL_TEXTURE_2D, names[1]);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        2,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[255, 255, 255, 255, 255, 60, 60, 255]),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.multi_tex_coord_2f(GL_TEXTURE1, 0.75, 0.5);
    sprite(gl, 12.0, 54.0, 10.0);
    gl.active_texture(GL_TEXTURE0);
}

/// Antialiased lines of width 2 drawn as separate GL_LINES segments a few pixels long that
/// meet end to end, depth-tested (a far grid line of xscreensaver's vigilance, a known failure
/// of the shared captures): each segment's coverage reaches half a pixel past its ends, so
/// with blending the joints are covered twice, on Mesa and on tilegl.
fn smooth_line_joints(gl: &mut dyn Gl) {
    black_pixel_space(gl);
    gl.enable(GL_LINE_SMOOTH);
    gl.hint(GL_LINE_SMOOTH_HINT, GL_NICEST);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.line_width(2.0);
    gl.color_3f(0.1, 0.9, 0.2);
    // The depth test on, as in the hack: the second segment at a joint has the first's depth
    // there.
    gl.enable(GL_DEPTH_TEST);
    for (row, step) in [(0, 3.7f32), (1, 2.3), (2, 5.1), (3, 1.6)] {
        gl.begin(GL_LINES);
        let y0 = 8.0 + 15.0 * row as f32;
        let mut x = 1.3f32;
        while x + step < 63.0 {
            gl.vertex_3f(x, y0 + x * 0.07, 0.9 - x / 40.0);
            gl.vertex_3f(x + step, y0 + (x + step) * 0.07, 0.9 - (x + step) / 40.0);
            x += step;
        }
        gl.end();
    }
}

/// Smooth quads whose corner colours are not affine, so the diagonal a quad is split along
/// shows: drawn directly inside the view volume (Mesa splits at vertices 0-2), with a vertex
/// outside it (the batch goes through Mesa's clipper, which splits at 1-3), and from a display
/// list (compiled into triangles split at 1-3); non-convex quads likewise.
fn quad_splits(gl: &mut dyn Gl) {
    black_pixel_space(gl);
    let quad = |gl: &mut dyn Gl, x: f32, y: f32, far: f32| {
        gl.begin(GL_QUADS);
        gl.color_3f(1.0, 0.0, 0.0);
        gl.vertex_2f(x + 2.0, y + 2.0);
        gl.color_3f(0.0, 1.0, 0.0);
        gl.vertex_2f(x + 18.0, y + 4.0);
        gl.color_3f(0.0, 0.0, 1.0);
        gl.vertex_2f(x + far, y + far);
        gl.color_3f(1.0, 1.0, 1.0);
        gl.vertex_2f(x + 3.0, y + 17.0);
        // Non-convex: vertex 2 inside the triangle of the others.
        gl.color_3f(1.0, 1.0, 0.0);
        gl.vertex_2f(x + 2.0, y + 21.0);
        gl.color_3f(0.0, 1.0, 1.0);
        gl.vertex_2f(x + 19.0, y + 21.5);
        gl.color_3f(1.0, 0.0, 1.0);
        gl.vertex_2f(x + 7.0, y + 25.0);
        gl.color_3f(0.2, 0.2, 0.2);
        gl.vertex_2f(x + 3.0, y + 30.5);
        gl.end();
    };
    quad(gl, 0.0, 0.0, 14.0);
    // Mesa decides the split per buffered draw, and merges consecutive glBegin/glEnd pairs
    // with no state change between them into one: glFlush ends the draw, as tilegl's
    // decision per glBegin/glEnd assumes.
    gl.flush();
    // The third vertex far outside the window: clipped.
    quad(gl, 22.0, 0.0, 140.0);
    let list = gl.gen_lists(1);
    gl.new_list(list, GL_COMPILE);
    quad(gl, 42.0, 32.0, 14.0);
    gl.end_list();
    gl.call_list(list);
}

//! Twin test of the queued pixel rectangles (`raster::pixels`, `state::pixel_queue`):
//! `glBitmap` and `glDrawPixels` of colours recorded into the scene, with runs of equal
//! fragments as one span and colours stored directly where the key only stores them, against
//! the per-pixel route that shades each fragment at once on the flushed framebuffer (taken
//! on the general path, `set_force_general_path`). Colour, depth and stencil, and occlusion
//! counts, must be the same bit for bit under every fragment state tried, on one thread and
//! on two.

mod common;

use common::{read_depth, read_rgba, threaded_context, Rng};
use tilegl::enums::*;
use tilegl::{Context, Gl};

const W: i32 = 150;
const H: i32 = 110;

/// A fragment state to draw the pixel rectangles under (each a reason for the span to do
/// more than store the colour, or not).
type Setup = fn(&mut Context);

fn texture(gl: &mut Context, min: GLenum, env: GLenum) {
    let mut rng = Rng(99);
    common::random_texture(gl, &mut rng, GL_RGBA, 16, 8);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, env as i32);
}

const SETUPS: [(&str, Setup); 16] = [
    ("plain (direct stores)", |_| {}),
    ("depth LESS, writes", |gl| {
        gl.enable(GL_DEPTH_TEST);
        gl.depth_func(GL_LESS);
    }),
    ("depth GEQUAL, no writes", |gl| {
        gl.enable(GL_DEPTH_TEST);
        gl.depth_func(GL_GEQUAL);
        gl.depth_mask(0);
    }),
    ("blend over", |gl| {
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }),
    ("alpha test", |gl| {
        gl.enable(GL_ALPHA_TEST);
        gl.alpha_func(GL_GREATER, 0.5);
    }),
    ("texture NEAREST_MIPMAP_LINEAR, modulate", |gl| {
        texture(gl, GL_NEAREST_MIPMAP_LINEAR, GL_MODULATE);
    }),
    ("texture LINEAR, replace", |gl| {
        texture(gl, GL_LINEAR, GL_REPLACE)
    }),
    ("fog", |gl| {
        gl.enable(GL_FOG);
        gl.fogi(GL_FOG_MODE, GL_LINEAR as i32);
        gl.fogf(GL_FOG_START, 0.0);
        gl.fogf(GL_FOG_END, 3.0);
        gl.fogfv(GL_FOG_COLOR, &[0.1, 0.8, 0.3, 1.0]);
    }),
    ("stencil", |gl| {
        gl.enable(GL_STENCIL_TEST);
        gl.stencil_func(GL_NOTEQUAL, 1, 0xff);
        gl.stencil_op(GL_KEEP, GL_INCR, GL_INVERT);
    }),
    ("colour mask", |gl| gl.color_mask(1, 0, 1, 0)),
    ("logic op XOR", |gl| {
        gl.enable(GL_COLOR_LOGIC_OP);
        gl.logic_op(GL_XOR);
    }),
    ("scissor", |gl| {
        gl.enable(GL_SCISSOR_TEST);
        gl.scissor(13, 9, 101, 77);
    }),
    ("colour sum", |gl| {
        gl.enable(GL_COLOR_SUM);
        gl.secondary_color_3f(0.3, 0.1, 0.6);
    }),
    ("pixel transfer scale and bias", |gl| {
        gl.pixel_transferf(GL_RED_SCALE, 2.5);
        gl.pixel_transferf(GL_GREEN_BIAS, -0.4);
        gl.pixel_transferf(GL_ALPHA_SCALE, -1.0);
        gl.pixel_transferf(GL_ALPHA_BIAS, 1.2);
    }),
    ("colour map", |gl| {
        gl.pixel_transferi(GL_MAP_COLOR, 1);
        gl.pixel_mapfv(GL_PIXEL_MAP_R_TO_R, 4, &[0.9, 0.1, 0.7, 0.3]);
    }),
    ("occlusion query", |gl| {
        gl.enable(GL_DEPTH_TEST);
        gl.depth_func(GL_LEQUAL);
        let mut q = [0u32];
        gl.gen_queries(1, &mut q);
        gl.begin_query(GL_SAMPLES_PASSED, q[0]);
    }),
];

/// Glyph-like bitmaps and images drawn between triangles, so the order of the queued
/// rectangles against draws (and against each other) shows; unpack settings that take the
/// byte copy and the bit-by-bit route; rectangles partly outside the window.
fn scene(gl: &mut Context, setup: Setup) {
    let mut rng = Rng(5);
    let bytes = |rng: &mut Rng, n: usize| -> Vec<u8> {
        (0..n).map(|_| (rng.next_u64() >> 56) as u8).collect()
    };
    gl.matrix_mode(GL_PROJECTION);
    gl.ortho(0.0, W as f64, 0.0, H as f64, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.clear_color(0.3, 0.2, 0.1, 0.5);
    gl.clear_stencil(1);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    // A triangle before anything, drawn with depth (it sets depth for the depth states).
    gl.enable(GL_DEPTH_TEST);
    gl.begin(GL_TRIANGLES);
    gl.color_4f(0.2, 0.9, 0.4, 0.7);
    gl.vertex_3f(-10.0, -5.0, 0.2);
    gl.color_4f(0.9, 0.1, 0.8, 0.2);
    gl.vertex_3f(140.0, 20.0, -0.6);
    gl.vertex_3f(40.0, 120.0, 0.0);
    gl.end();
    gl.disable(GL_DEPTH_TEST);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    setup(gl);
    // Images: RGBA bytes, BGR bytes, luminance-alpha bytes, floats out of range (and NaN),
    // at raster positions that round, partly outside the window on each side.
    let rgba = bytes(&mut rng, 37 * 23 * 4);
    let mut floats: Vec<u8> = Vec::new();
    for k in 0..19 * 17 * 4 {
        let v = match k % 11 {
            0 => f32::NAN,
            1 => -0.5,
            2 => 1.7,
            3 => -0.0,
            _ => rng.range(0.0, 1.0),
        };
        floats.extend_from_slice(&v.to_ne_bytes());
    }
    gl.color_4f(0.6, 0.5, 0.9, 0.8);
    // glWindowPos places the first two partly outside (a raster position there is clipped).
    gl.window_pos_3f(-9.3, 30.6, 0.45);
    gl.draw_pixels(37, 23, GL_RGBA, GL_UNSIGNED_BYTE, Some(&rgba));
    gl.window_pos_3f(130.5, -6.4, 0.65);
    gl.draw_pixels(23, 37, GL_BGR, GL_UNSIGNED_BYTE, Some(&rgba));
    gl.raster_pos_3f(60.0, 95.2, 0.5);
    gl.draw_pixels(30, 20, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, Some(&rgba));
    gl.raster_pos_3f(20.4, 70.0, -0.8);
    gl.draw_pixels(19, 17, GL_RGBA, GL_FLOAT, Some(&floats));
    // A row length and skips (the unpack layout), then an image drawn twice at one place.
    gl.pixel_storei(GL_UNPACK_ROW_LENGTH, 37);
    gl.pixel_storei(GL_UNPACK_SKIP_PIXELS, 3);
    gl.pixel_storei(GL_UNPACK_SKIP_ROWS, 2);
    gl.raster_pos_2i(90, 40);
    gl.draw_pixels(30, 18, GL_RGBA, GL_UNSIGNED_BYTE, Some(&rgba));
    gl.pixel_storei(GL_UNPACK_ROW_LENGTH, 0);
    gl.pixel_storei(GL_UNPACK_SKIP_PIXELS, 0);
    gl.pixel_storei(GL_UNPACK_SKIP_ROWS, 0);
    // Runs of equal colours (one span each on the queued route).
    let flat: Vec<u8> = (0..40 * 6)
        .flat_map(|k| [200, 100, ((k / 7) * 9) as u8, 255])
        .collect();
    assert_eq!(gl.get_error(), GL_NO_ERROR, "after the images");
    gl.raster_pos_2i(5, 5);
    gl.draw_pixels(40, 6, GL_RGBA, GL_UNSIGNED_BYTE, Some(&flat));
    // A triangle over the images.
    gl.begin(GL_TRIANGLES);
    gl.color_4f(0.1, 0.3, 1.0, 0.6);
    gl.vertex_3f(30.0, 10.0, 0.4);
    gl.vertex_3f(100.0, 60.0, 0.4);
    gl.vertex_3f(10.0, 100.0, 0.4);
    gl.end();
    // Bitmaps: rows of glyphs in changing colours (one pixel apart and overlapping), with
    // fractional origins and moves, LSB-first and skipped pixels, a wide one across tiles.
    let glyphs: Vec<Vec<u8>> = (0..12).map(|_| bytes(&mut rng, 13 * 2)).collect();
    for row in 0..9 {
        gl.color_4f(
            0.1 * row as f32,
            0.9 - 0.1 * row as f32,
            0.5,
            0.3 + 0.07 * row as f32,
        );
        // The first glyph starts left of the window (its origin is right of the position).
        gl.raster_pos_3f(2.0, 4.0 + 12.0 * row as f32, 0.6 - 0.15 * row as f32);
        if row == 3 {
            gl.pixel_storei(GL_UNPACK_LSB_FIRST, 1);
        }
        if row == 5 {
            gl.pixel_storei(GL_UNPACK_SKIP_PIXELS, 3);
        }
        if row == 7 {
            gl.pixel_storei(GL_UNPACK_LSB_FIRST, 0);
            gl.pixel_storei(GL_UNPACK_SKIP_PIXELS, 0);
        }
        for col in 0..24 {
            let g = &glyphs[(row * 5 + col) % glyphs.len()];
            let (xo, yo) = if row % 2 == 0 {
                (6.0, 0.0)
            } else {
                (7.5, -0.25)
            };
            gl.bitmap(11, 13, xo, yo, 6.5, 0.25, g);
        }
    }
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 4);
    let wide = bytes(&mut rng, 24 * 40);
    gl.color_3f(1.0, 1.0, 0.2);
    gl.raster_pos_2f(1.0, 50.0);
    gl.bitmap(190, 40, 31.0, 0.0, 0.0, 0.0, &wide);
    gl.color_3f(0.0, 0.5, 0.5);
    gl.raster_pos_2f(70.0, 109.0);
    gl.bitmap(190, 40, 0.0, 20.0, 0.0, 0.0, &wide);
}

struct Picture {
    color: Vec<[u8; 4]>,
    depth: Vec<u8>,
    stencil: Vec<u8>,
    samples: u32,
}

fn render((name, setup): (&str, Setup), per_pixel: bool, threads: usize) -> Picture {
    let mut gl = threaded_context(W, H, threads);
    gl.set_force_general_path(per_pixel);
    scene(&mut gl, setup);
    gl.finish();
    let mut samples = [0u32];
    if name == "occlusion query" {
        gl.end_query(GL_SAMPLES_PASSED);
        gl.get_query_objectuiv(1, GL_QUERY_RESULT, &mut samples);
    }
    assert_eq!(gl.get_error(), GL_NO_ERROR, "{name}: after the scene");
    let mut stencil = vec![0u8; (W * H) as usize];
    gl.pixel_storei(GL_PACK_ALIGNMENT, 1);
    gl.read_pixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &mut stencil);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    Picture {
        color: read_rgba(&mut gl),
        depth: read_depth(&mut gl),
        stencil,
        samples: samples[0],
    }
}

#[test]
fn queued_pixel_rectangles_draw_what_the_per_pixel_route_draws() {
    for (name, setup) in SETUPS {
        let reference = render((name, setup), true, 1);
        for threads in [1, 2] {
            let queued = render((name, setup), false, threads);
            let off = reference
                .color
                .iter()
                .zip(&queued.color)
                .filter(|(a, b)| a != b)
                .count();
            assert_eq!(off, 0, "{name}, {threads} threads: {off} pixels differ");
            assert!(reference.depth == queued.depth, "{name}: depth differs");
            assert!(
                reference.stencil == queued.stencil,
                "{name}: stencil differs"
            );
            assert_eq!(reference.samples, queued.samples, "{name}: samples differ");
        }
    }
}

/// The scene draws something of every kind: the images and glyphs change the picture under
/// the plain state (so the comparison above is not between two empty pictures).
#[test]
fn the_twin_scene_draws_images_and_glyphs() {
    let plain = render(SETUPS[0], false, 1);
    let mut gl = threaded_context(W, H, 1);
    gl.matrix_mode(GL_PROJECTION);
    gl.ortho(0.0, W as f64, 0.0, H as f64, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.clear_color(0.3, 0.2, 0.1, 0.5);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let cleared = read_rgba(&mut gl);
    let drawn = plain
        .color
        .iter()
        .zip(&cleared)
        .filter(|(a, b)| a != b)
        .count();
    assert!(drawn > (W * H) as usize / 2, "{drawn}");
    // The glyph colours of the last rows appear.
    assert!(plain.color.contains(&[255, 255, 51, 255]));
    assert!(plain.color.contains(&[0, 128, 128, 255]));
}

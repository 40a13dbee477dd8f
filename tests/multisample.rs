//! ARB_multisample (OpenGL 1.3, sections 3.2.1 and 4.1.3) on a framebuffer with a multisample
//! buffer: coverage at each sample position, the sample coverage and alpha-to-coverage masks,
//! alpha-to-one, the resolve (the average of the samples) on reads and copies, depth and
//! stencil reads from sample 0, the queries, and single-sample rendering left as it was. The
//! expected values are computed here from the sample positions and the specification's rules,
//! not read back from tilegl.

mod common;

use common::{pixel, read_rgba, window_ortho};
use tilegl::enums::*;
use tilegl::{Context, ContextConfig, FramebufferConfig, Gl};

/// The 4x positions in GL window convention (y up): llvmpipe's standard pattern
/// (0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875) in its y-down convention,
/// flipped. Written out here, not taken from the library.
const POS4: [[f64; 2]; 4] = [
    [0.375, 0.875],
    [0.875, 0.625],
    [0.125, 0.375],
    [0.625, 0.125],
];
const POS2: [[f64; 2]; 2] = [[0.75, 0.25], [0.25, 0.75]];

fn context(samples: u32, w: i32, h: i32) -> Context {
    let mut gl = Context::with_config(ContextConfig {
        width: w,
        height: h,
        framebuffer: FramebufferConfig {
            samples,
            ..FramebufferConfig::default()
        },
        ..ContextConfig::default()
    });
    window_ortho(&mut gl);
    gl
}

fn integer(gl: &mut Context, pname: GLenum) -> i32 {
    let mut v = [0i32];
    gl.get_integerv(pname, &mut v);
    v[0]
}

/// The exact average of `covered` samples of `value` and `n - covered` of `background`.
fn average(value: u8, background: u8, covered: usize, n: usize) -> f64 {
    (value as f64 * covered as f64 + background as f64 * (n - covered) as f64) / n as f64
}

/// Whether a resolved byte is the average rounded to nearest (either way on a tie: the
/// specification leaves the resolve's rounding to the implementation).
fn resolves_to(got: u8, want: f64) -> bool {
    (got as f64 - want).abs() <= 0.5
}

fn quad(gl: &mut Context, x0: f32, y0: f32, x1: f32, y1: f32, z: f32) {
    gl.begin(GL_QUADS);
    gl.vertex_3f(x0, y0, z);
    gl.vertex_3f(x1, y0, z);
    gl.vertex_3f(x1, y1, z);
    gl.vertex_3f(x0, y1, z);
    gl.end();
}

#[test]
fn queries_answer_the_configuration() {
    for (samples, buffers, count) in [(0, 0, 0), (1, 0, 0), (2, 1, 2), (4, 1, 4)] {
        let mut gl = context(samples, 8, 8);
        assert_eq!(integer(&mut gl, GL_SAMPLE_BUFFERS), buffers, "{samples}");
        assert_eq!(integer(&mut gl, GL_SAMPLES), count, "{samples}");
        let mut on = [0u8];
        gl.get_booleanv(GL_MULTISAMPLE, &mut on);
        assert_eq!(on[0], 1, "GL_MULTISAMPLE is enabled by default");
    }
    let mut gl = context(4, 8, 8);
    let ext = gl.get_string(GL_EXTENSIONS).unwrap_or_default();
    assert!(ext.contains("GL_ARB_multisample"));
}

/// A triangle's edge crosses pixels at many sub-pixel offsets: each pixel's resolved colour
/// is the share of sample positions inside the triangle (edge functions evaluated here).
#[test]
fn edge_pixels_average_the_covered_samples() {
    for (samples, pos) in [(4u32, &POS4[..]), (2, &POS2[..])] {
        let (w, h) = (24, 20);
        let mut gl = context(samples, w, h);
        gl.clear_color(0.0, 0.0, 0.0, 0.0);
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.color_3f(1.0, 1.0, 1.0);
        // Vertices chosen off every sample grid line: no sample lies on an edge.
        let v = [[1.3f64, 0.7], [22.9, 3.1], [6.2, 18.45]];
        gl.begin(GL_TRIANGLES);
        for p in v {
            gl.vertex_2f(p[0] as f32, p[1] as f32);
        }
        gl.end();
        let img = read_rgba(&mut gl);
        let inside = |x: f64, y: f64| {
            (0..3).all(|i| {
                let (a, b) = (v[i], v[(i + 1) % 3]);
                (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]) > 0.0
            })
        };
        let mut partial = 0;
        for y in 0..h {
            for x in 0..w {
                let covered = pos
                    .iter()
                    .filter(|s| inside(x as f64 + s[0], y as f64 + s[1]))
                    .count();
                if covered != 0 && covered != pos.len() {
                    partial += 1;
                }
                let want = average(255, 0, covered, pos.len());
                let got = img[(y * w + x) as usize];
                assert!(
                    resolves_to(got[0], want),
                    "{samples}x pixel ({x}, {y}): {covered} covered, {} for {want}",
                    got[0]
                );
            }
        }
        assert!(partial > 20, "the edges cross many pixels ({partial})");
    }
}

#[test]
fn sample_coverage_covers_the_lowest_samples_or_the_others() {
    // floor(value x 4) samples of 4: 0.3 -> 1, 0.5 -> 2, 0.8 -> 3, 1.0 -> 4.
    for (value, n) in [(0.3f32, 1usize), (0.5, 2), (0.8, 3), (1.0, 4), (0.0, 0)] {
        for invert in [false, true] {
            let mut gl = context(4, 8, 8);
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            gl.clear(GL_COLOR_BUFFER_BIT);
            gl.enable(GL_SAMPLE_COVERAGE);
            gl.sample_coverage(value, invert as u8);
            gl.color_3f(1.0, 1.0, 1.0);
            quad(&mut gl, 0.0, 0.0, 8.0, 8.0, 0.0);
            let covered = if invert { 4 - n } else { n };
            let got = pixel(&mut gl, 3, 3)[0];
            let want = average(255, 0, covered, 4);
            assert!(
                resolves_to(got, want),
                "value {value} invert {invert}: {got} for {want}"
            );
        }
    }
    // A mask and its inverse cover complementary samples: red then green gives half of each.
    let mut gl = context(4, 8, 8);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.enable(GL_SAMPLE_COVERAGE);
    gl.sample_coverage(0.5, 0);
    gl.color_3f(1.0, 0.0, 0.0);
    quad(&mut gl, 0.0, 0.0, 8.0, 8.0, 0.0);
    gl.sample_coverage(0.5, 1);
    gl.color_3f(0.0, 1.0, 0.0);
    quad(&mut gl, 0.0, 0.0, 8.0, 8.0, 0.0);
    assert_eq!(pixel(&mut gl, 2, 2), [128, 128, 0, 255]);
    // With GL_MULTISAMPLE off the mask does not apply.
    gl.disable(GL_MULTISAMPLE);
    gl.sample_coverage(0.25, 0);
    gl.color_3f(0.0, 0.0, 1.0);
    quad(&mut gl, 0.0, 0.0, 8.0, 8.0, 0.0);
    assert_eq!(pixel(&mut gl, 2, 2), [0, 0, 255, 255]);
}

#[test]
fn alpha_to_coverage_and_alpha_to_one() {
    for alpha in [0.0f32, 0.1, 0.25, 0.3, 0.5, 0.6, 0.75, 0.9, 1.0] {
        for one in [false, true] {
            let mut gl = context(4, 8, 8);
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            gl.clear(GL_COLOR_BUFFER_BIT);
            gl.enable(GL_SAMPLE_ALPHA_TO_COVERAGE);
            if one {
                gl.enable(GL_SAMPLE_ALPHA_TO_ONE);
            }
            gl.color_4f(1.0, 1.0, 1.0, alpha);
            quad(&mut gl, 0.0, 0.0, 8.0, 8.0, 0.0);
            // Sample s of n covered when alpha > s / n (llvmpipe's thresholds; the
            // specification asks for a number of samples that grows with alpha).
            let covered = (0..4).filter(|&s| alpha > s as f32 / 4.0).count();
            let stored_alpha = if one {
                255
            } else {
                (alpha * 255.0).round() as u8
            };
            let got = pixel(&mut gl, 4, 4);
            let want = [255, 255, 255, stored_alpha].map(|v| average(v, 0, covered, 4));
            assert!(
                (0..4).all(|k| resolves_to(got[k], want[k])),
                "alpha {alpha} to-one {one}: {got:?} for {want:?}"
            );
        }
    }
    // Alpha-to-one acts before the alpha test (section 4.1.3 precedes 4.1.4): a fragment of
    // alpha 0.2 passes GL_GREATER 0.5.
    let mut gl = context(4, 8, 8);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.enable(GL_SAMPLE_ALPHA_TO_ONE);
    gl.enable(GL_ALPHA_TEST);
    gl.alpha_func(GL_GREATER, 0.5);
    gl.color_4f(0.0, 1.0, 0.0, 0.2);
    quad(&mut gl, 0.0, 0.0, 8.0, 8.0, 0.0);
    assert_eq!(pixel(&mut gl, 1, 1), [0, 255, 0, 255]);
}

/// Depth and stencil reads see sample 0, whose position is (0.375, 0.875) in the pixel: a
/// quad whose lower edge lies at y = 5.7 covers only sample 0 in row 5.
#[test]
fn depth_and_stencil_reads_take_sample_zero() {
    let mut gl = context(4, 8, 8);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear_depth(1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_ALWAYS, 7, 0xFF);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
    gl.color_3f(1.0, 1.0, 1.0);
    // z = 0 in the ortho projection (-1..1) is window depth 0.5.
    quad(&mut gl, 0.0, 5.7, 8.0, 8.0, 0.0);
    // Row 5: one sample of four covered.
    assert!(resolves_to(pixel(&mut gl, 3, 5)[0], average(255, 0, 1, 4)));
    let d = depth(&mut gl, 3, 5);
    assert!((d - 0.5).abs() < 1e-6, "depth {d}");
    let mut s = [0u8; 1];
    gl.read_pixels(3, 5, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &mut s);
    assert_eq!(s[0], 7);
    // Row 4: no sample covered.
    assert_eq!(depth(&mut gl, 3, 4), 1.0);
    // A quad whose upper edge is at y = 5.3 covers samples 2 and 3 of row 5, not sample 0.
    let mut gl = context(4, 8, 8);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.enable(GL_DEPTH_TEST);
    gl.color_3f(1.0, 1.0, 1.0);
    quad(&mut gl, 0.0, 0.0, 8.0, 5.3, 0.0);
    assert!(resolves_to(pixel(&mut gl, 3, 5)[0], average(255, 0, 1, 4)));
    assert_eq!(depth(&mut gl, 3, 5), 1.0, "sample 0 is not covered");
}

/// The depth of window pixel (x, y) as a float.
fn depth(gl: &mut Context, x: i32, y: i32) -> f32 {
    let mut b = [0u8; 4];
    gl.read_pixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &mut b);
    f32::from_ne_bytes(b)
}

/// Copies read the resolved colour and write it to every sample.
#[test]
fn copies_take_the_resolved_colour() {
    let mut gl = context(4, 16, 16);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.color_3f(1.0, 1.0, 1.0);
    // Column 3: samples with x offset < 0.5 covered (two of four).
    quad(&mut gl, 0.0, 0.0, 3.5, 4.0, 0.0);
    let half = pixel(&mut gl, 3, 1)[0];
    assert!(resolves_to(half, average(255, 0, 2, 4)));
    // glCopyPixels to (8, 8): every sample of the destination gets the resolved value.
    gl.raster_pos_2i(8, 8);
    gl.copy_pixels(0, 0, 4, 4, GL_COLOR);
    assert_eq!(pixel(&mut gl, 11, 9)[0], half);
    assert_eq!(pixel(&mut gl, 10, 9)[0], 255);
    // glCopyTexImage2D takes the resolved colours too.
    let mut tex = [0u32];
    gl.gen_textures(1, &mut tex);
    gl.bind_texture(GL_TEXTURE_2D, tex[0]);
    gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
    let mut texels = [0u8; 64];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut texels);
    assert_eq!(texels[(4 + 3) * 4], half);
    assert_eq!(texels[(4 + 2) * 4], 255);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

/// With GL_MULTISAMPLE off every sample takes the pixel-centre fragments, so the resolved
/// picture is the single-sample one, bit for bit; and a context without a multisample buffer
/// ignores the multisample enables.
#[test]
fn single_sample_rendering_is_unaffected() {
    let scene = |gl: &mut Context, extra: bool| {
        gl.clear_color(0.1, 0.2, 0.3, 0.4);
        gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        gl.enable(GL_DEPTH_TEST);
        if extra {
            gl.enable(GL_SAMPLE_ALPHA_TO_COVERAGE);
            gl.enable(GL_SAMPLE_COVERAGE);
            gl.sample_coverage(0.25, 0);
        }
        gl.begin(GL_TRIANGLES);
        gl.color_4f(1.0, 0.0, 0.0, 0.5);
        gl.vertex_3f(1.3, 0.7, 0.5);
        gl.color_4f(0.0, 1.0, 0.0, 0.7);
        gl.vertex_3f(30.9, 3.1, -0.5);
        gl.color_4f(0.0, 0.0, 1.0, 0.9);
        gl.vertex_3f(6.2, 28.45, 0.0);
        gl.end();
        gl.point_size(3.0);
        gl.begin(GL_POINTS);
        gl.vertex_2f(20.3, 20.6);
        gl.end();
        gl.begin(GL_LINES);
        gl.vertex_2f(2.2, 30.1);
        gl.vertex_2f(29.7, 12.4);
        gl.end();
        read_rgba(gl)
    };
    let mut single = context(0, 32, 32);
    let want = scene(&mut single, false);
    let mut single_enables = context(0, 32, 32);
    assert_eq!(scene(&mut single_enables, true), want);
    let mut off = context(4, 32, 32);
    off.disable(GL_MULTISAMPLE);
    assert_eq!(scene(&mut off, true), want);
    // And multisampled with it on, the picture differs (its edges are smoothed).
    let mut on = context(4, 32, 32);
    assert_ne!(scene(&mut on, false), want);
}

/// Many small triangles (past the background hand-off threshold, so scenes are handed to the
/// workers in the middle of a sample pass): two shading threads give the one-thread picture.
#[test]
fn background_shading_keeps_each_sample_plane() {
    let draw = |threads: usize| {
        let mut gl = Context::with_config(ContextConfig {
            width: 96,
            height: 80,
            threads,
            framebuffer: FramebufferConfig {
                samples: 4,
                ..FramebufferConfig::default()
            },
        });
        window_ortho(&mut gl);
        gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        gl.enable(GL_DEPTH_TEST);
        let mut rng = common::Rng(7);
        gl.begin(GL_TRIANGLES);
        for _ in 0..6000 {
            gl.color_3f(
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
            );
            let (x, y) = (rng.range(0.0, 96.0), rng.range(0.0, 80.0));
            for _ in 0..3 {
                gl.vertex_3f(
                    x + rng.range(-4.0, 4.0),
                    y + rng.range(-4.0, 4.0),
                    rng.range(-1.0, 1.0),
                );
            }
        }
        gl.end();
        read_rgba(&mut gl)
    };
    assert_eq!(draw(2), draw(1));
}

/// Multisample rasterization ignores GL_POLYGON_SMOOTH and GL_LINE_SMOOTH (sections 3.5.7 and
/// 3.4.4): with GL_MULTISAMPLE on they change no pixel; with it off they apply.
#[test]
fn smooth_polygons_and_lines_are_multisampled() {
    let draw = |smooth: bool, multisample: bool| {
        let mut gl = context(4, 32, 32);
        if !multisample {
            gl.disable(GL_MULTISAMPLE);
        }
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        if smooth {
            gl.enable(GL_POLYGON_SMOOTH);
            gl.enable(GL_LINE_SMOOTH);
        }
        gl.color_3f(1.0, 1.0, 1.0);
        gl.begin(GL_TRIANGLES);
        gl.vertex_2f(1.3, 0.7);
        gl.vertex_2f(20.9, 3.1);
        gl.vertex_2f(6.2, 18.45);
        gl.end();
        gl.begin(GL_LINES);
        gl.vertex_2f(2.2, 30.1);
        gl.vertex_2f(29.7, 12.4);
        gl.end();
        read_rgba(&mut gl)
    };
    assert_eq!(draw(true, true), draw(false, true));
    assert_ne!(draw(true, false), draw(false, false));
}

//! Occlusion queries (section 4.1.6, 6.1.12): exact `GL_SAMPLES_PASSED` counts against pixel
//! counts computed here, and every error of the query commands.

mod common;

use common::{read_rgba, window_ortho, Rng};
use tilegl::enums::*;
use tilegl::{Context, ContextConfig, FramebufferConfig, Gl};

fn result(gl: &mut Context, id: u32) -> u32 {
    let mut v = [0u32];
    gl.get_query_objectuiv(id, GL_QUERY_RESULT, &mut v);
    let mut a = [0i32];
    gl.get_query_objectiv(id, GL_QUERY_RESULT_AVAILABLE, &mut a);
    assert_eq!(a[0], 1);
    let mut i = [0i32];
    gl.get_query_objectiv(id, GL_QUERY_RESULT, &mut i);
    assert_eq!(i[0] as u32, v[0]);
    v[0]
}

/// Pixels whose centre lies in the half-open window rectangle [x0, x1) x [y0, y1).
fn in_rect(x: i32, y: i32, r: [f32; 4]) -> bool {
    let (cx, cy) = (x as f32 + 0.5, y as f32 + 0.5);
    cx >= r[0] && cx < r[2] && cy >= r[1] && cy < r[3]
}

fn context(threads: usize, double_buffer: bool) -> Context {
    Context::with_config(ContextConfig {
        width: 96,
        height: 80,
        framebuffer: FramebufferConfig {
            double_buffer,
            ..FramebufferConfig::default()
        },
        threads,
    })
}

#[test]
fn counts_fragments_passing_the_depth_test() {
    for threads in [1, 3] {
        let mut gl = context(threads, false);
        window_ortho(&mut gl);
        gl.enable(GL_DEPTH_TEST);
        gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        let mut ids = [0u32; 3];
        gl.gen_queries(3, &mut ids);
        // An occluder at depth 0 (window z 0.5), outside any query.
        let near = [10.0, 12.0, 50.0, 40.0];
        gl.rectf(near[0], near[1], near[2], near[3]);
        // A farther rectangle (z = -0.5 in eye space is window z 0.75) partly behind it.
        let far = [30.0, 20.25, 90.0, 70.25];
        gl.begin_query(GL_SAMPLES_PASSED, ids[0]);
        gl.push_matrix();
        gl.translatef(0.0, 0.0, -0.5);
        gl.rectf(far[0], far[1], far[2], far[3]);
        gl.pop_matrix();
        gl.end_query(GL_SAMPLES_PASSED);
        let mut expected = 0;
        for y in 0..80 {
            for x in 0..96 {
                if in_rect(x, y, far) && !in_rect(x, y, near) {
                    expected += 1;
                }
            }
        }
        assert_eq!(result(&mut gl, ids[0]), expected);
        // The same rectangle again: nothing passes GL_LESS against itself.
        gl.begin_query(GL_SAMPLES_PASSED, ids[1]);
        gl.translatef(0.0, 0.0, -0.5);
        gl.rectf(far[0], far[1], far[2], far[3]);
        gl.load_identity();
        gl.end_query(GL_SAMPLES_PASSED);
        assert_eq!(result(&mut gl, ids[1]), 0);
        // With writes masked off fragments still count (they pass the tests).
        gl.color_mask(0, 0, 0, 0);
        gl.depth_mask(0);
        gl.depth_func(GL_ALWAYS);
        gl.begin_query(GL_SAMPLES_PASSED, ids[2]);
        gl.rectf(0.0, 0.0, 96.0, 80.0);
        gl.end_query(GL_SAMPLES_PASSED);
        assert_eq!(result(&mut gl, ids[2]), 96 * 80);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }
}

#[test]
fn counts_equal_written_pixels_for_random_triangles() {
    let mut gl = context(0, false);
    window_ortho(&mut gl);
    gl.enable(GL_DEPTH_TEST);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    let mut rng = Rng(0x5eed);
    let mut id = [0u32];
    gl.gen_queries(1, &mut id);
    for i in 0..40u32 {
        // Each triangle in a colour of its own: the pixels it wrote are the pixels that
        // passed, since with GL_LESS and colour writes every passing fragment writes.
        let c = [(i * 37 % 251 + 4) as u8, (i * 11 % 253) as u8, 200];
        let before = read_rgba(&mut gl);
        gl.begin_query(GL_SAMPLES_PASSED, id[0]);
        gl.color_3ub(c[0], c[1], c[2]);
        gl.begin(GL_TRIANGLES);
        for _ in 0..3 {
            gl.vertex_3f(
                rng.range(-10.0, 106.0),
                rng.range(-10.0, 90.0),
                rng.range(-0.9, 0.9),
            );
        }
        gl.end();
        gl.end_query(GL_SAMPLES_PASSED);
        let after = read_rgba(&mut gl);
        let written = before
            .iter()
            .zip(&after)
            .filter(|(b, a)| a[..3] == c && b[..3] != c)
            .count() as u32;
        assert_eq!(result(&mut gl, id[0]), written, "triangle {i}");
    }
}

#[test]
fn stencil_and_alpha_rejections_do_not_count() {
    let mut gl = context(0, false);
    window_ortho(&mut gl);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_ALWAYS, 1, 0xFF);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
    let mark = [0.0, 0.0, 20.0, 80.0];
    gl.rectf(mark[0], mark[1], mark[2], mark[3]);
    gl.stencil_func(GL_NOTEQUAL, 1, 0xFF);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
    let mut id = [0u32; 2];
    gl.gen_queries(2, &mut id);
    gl.begin_query(GL_SAMPLES_PASSED, id[0]);
    let r = [5.0, 5.0, 45.0, 25.0];
    gl.rectf(r[0], r[1], r[2], r[3]);
    gl.end_query(GL_SAMPLES_PASSED);
    let expected = (0..80)
        .flat_map(|y| (0..96).map(move |x| (x, y)))
        .filter(|&(x, y)| in_rect(x, y, r) && !in_rect(x, y, mark))
        .count() as u32;
    assert_eq!(result(&mut gl, id[0]), expected);
    gl.disable(GL_STENCIL_TEST);
    gl.enable(GL_ALPHA_TEST);
    gl.alpha_func(GL_GREATER, 0.5);
    gl.begin_query(GL_SAMPLES_PASSED, id[1]);
    gl.color_4f(1.0, 1.0, 1.0, 0.25);
    gl.rectf(0.0, 0.0, 10.0, 10.0);
    gl.color_4f(1.0, 1.0, 1.0, 0.75);
    gl.rectf(0.0, 0.0, 7.0, 3.0);
    gl.end_query(GL_SAMPLES_PASSED);
    assert_eq!(result(&mut gl, id[1]), 21);
}

#[test]
fn pixel_rectangles_and_bitmaps_count_their_fragments() {
    let mut gl = context(0, false);
    let mut id = [0u32];
    gl.gen_queries(1, &mut id);
    gl.window_pos_2i(3, 4);
    gl.begin_query(GL_SAMPLES_PASSED, id[0]);
    gl.draw_pixels(7, 5, GL_RGBA, GL_UNSIGNED_BYTE, Some(&[255u8; 7 * 5 * 4]));
    gl.end_query(GL_SAMPLES_PASSED);
    assert_eq!(result(&mut gl, id[0]), 35);
    // An 8x2 bitmap with 5 bits set.
    gl.begin_query(GL_SAMPLES_PASSED, id[0]);
    gl.bitmap(
        8,
        2,
        0.0,
        0.0,
        0.0,
        0.0,
        &[0b1010_0000, 0, 0, 0, 0b0000_0111, 0, 0, 0],
    );
    gl.end_query(GL_SAMPLES_PASSED);
    assert_eq!(result(&mut gl, id[0]), 5);
}

#[test]
fn both_colour_buffers_count_each_fragment_once() {
    let mut gl = context(2, true);
    window_ortho(&mut gl);
    gl.draw_buffer(GL_FRONT_AND_BACK);
    let mut id = [0u32];
    gl.gen_queries(1, &mut id);
    gl.begin_query(GL_SAMPLES_PASSED, id[0]);
    gl.rectf(0.0, 0.0, 10.0, 10.0);
    gl.end_query(GL_SAMPLES_PASSED);
    assert_eq!(result(&mut gl, id[0]), 100);
}

#[test]
fn query_errors_and_names() {
    let mut gl = context(0, false);
    let mut ids = [0u32; 2];
    gl.gen_queries(-1, &mut ids);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.gen_queries(2, &mut ids);
    assert!(ids[0] != 0 && ids[1] != 0 && ids[0] != ids[1]);
    // Names become query objects at their first glBeginQuery.
    assert_eq!(gl.is_query(ids[0]), 0);
    assert_eq!(gl.is_query(0), 0);
    let mut v = [7i32];
    gl.get_query_objectiv(ids[0], GL_QUERY_RESULT, &mut v);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.begin_query(GL_TEXTURE_2D, ids[0]);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.begin_query(GL_SAMPLES_PASSED, 0);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.end_query(GL_SAMPLES_PASSED);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.get_queryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &mut v);
    assert_eq!(v[0], 0);
    gl.begin_query(GL_SAMPLES_PASSED, ids[0]);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(gl.is_query(ids[0]), 1);
    gl.get_queryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &mut v);
    assert_eq!(v[0], ids[0] as i32);
    gl.get_queryiv(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS, &mut v);
    assert!(v[0] >= 32);
    gl.get_queryiv(GL_SAMPLES_PASSED, GL_QUERY_RESULT, &mut v);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.get_queryiv(GL_TEXTURE_2D, GL_CURRENT_QUERY, &mut v);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    // A second begin while one is active, and results of the active query.
    gl.begin_query(GL_SAMPLES_PASSED, ids[1]);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.get_query_objectiv(ids[0], GL_QUERY_RESULT_AVAILABLE, &mut v);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    // Inside glBegin/glEnd every query command is an error.
    gl.begin(GL_POINTS);
    gl.end_query(GL_SAMPLES_PASSED);
    gl.end();
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.end_query(GL_TEXTURE_2D);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.end_query(GL_SAMPLES_PASSED);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.get_query_objectiv(ids[0], GL_TEXTURE_2D, &mut v);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    assert_eq!(result(&mut gl, ids[0]), 0);
    // Deleting the active query ends it.
    gl.begin_query(GL_SAMPLES_PASSED, ids[1]);
    gl.delete_queries(1, &ids[1..]);
    gl.get_queryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &mut v);
    assert_eq!(v[0], 0);
    assert_eq!(gl.is_query(ids[1]), 0);
    gl.delete_queries(-1, &ids);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn textured_blended_draws_are_counted_too() {
    // A key the textured fast path would take (one RGBA8 2D unit, MODULATE, alpha-over blend):
    // with a query active the fragments must still be counted.
    let mut gl = tilegl::Context::new(32, 32);
    common::window_ortho(&mut gl);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[255; 16]),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    let mut q = [0u32];
    gl.gen_queries(1, &mut q);
    gl.begin_query(GL_SAMPLES_PASSED, q[0]);
    gl.rectf(4.0, 4.0, 14.0, 10.0);
    gl.end_query(GL_SAMPLES_PASSED);
    let mut n = [0u32];
    gl.get_query_objectuiv(q[0], GL_QUERY_RESULT, &mut n);
    assert_eq!(n[0], 10 * 6);
}

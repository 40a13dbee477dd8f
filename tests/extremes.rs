//! Stiff and extreme inputs: nothing panics, nothing loops forever, results stay sensible.

mod common;

use common::{pixel, read_rgba, window_ortho};
use tilegl::enums::*;
use tilegl::{Context, Gl};

fn count_lit(gl: &mut Context) -> usize {
    read_rgba(gl).iter().filter(|p| p[0] != 0).count()
}

#[test]
fn non_finite_vertices_drop_the_primitive() {
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let mut gl = Context::new(16, 16);
        gl.color_3f(1.0, 0.0, 0.0);
        gl.begin(GL_TRIANGLES);
        gl.vertex_2f(-1.0, -1.0);
        gl.vertex_2f(1.0, bad);
        gl.vertex_2f(0.0, 1.0);
        // A good triangle after the bad one still draws.
        gl.vertex_2f(-1.0, -1.0);
        gl.vertex_2f(0.0, -1.0);
        gl.vertex_2f(-1.0, 0.0);
        gl.end();
        gl.begin(GL_LINES);
        gl.vertex_2f(bad, 0.0);
        gl.vertex_2f(1.0, 1.0);
        gl.end();
        gl.begin(GL_POINTS);
        gl.vertex_4f(0.5, 0.5, 0.0, bad);
        gl.end();
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert_eq!(
            pixel(&mut gl, 12, 8),
            [0, 0, 0, 0],
            "bad triangle drew ({bad})"
        );
        assert_eq!(
            pixel(&mut gl, 1, 1),
            [255, 0, 0, 255],
            "good triangle missing ({bad})"
        );
    }
    // Non-finite matrices too.
    let mut gl = Context::new(16, 16);
    gl.scalef(f32::NAN, 1.0, 1.0);
    gl.rectf(-1.0, -1.0, 1.0, 1.0);
    assert_eq!(count_lit(&mut gl), 0);
}

#[test]
fn huge_coordinates_clip_correctly() {
    // A triangle with vertices near 1e30 still covers the right half-plane.
    let mut gl = Context::new(32, 32);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.begin(GL_TRIANGLES);
    gl.vertex_2f(0.0, -1e30);
    gl.vertex_2f(1e30, 0.0);
    gl.vertex_2f(0.0, 1e30);
    gl.end();
    for y in [0, 15, 31] {
        assert_eq!(pixel(&mut gl, 20, y)[0], 255, "right half at row {y}");
        assert_eq!(pixel(&mut gl, 10, y)[0], 0, "left half at row {y}");
    }
}

#[test]
fn w_zero_and_negative_w_are_clipped() {
    let mut gl = Context::new(32, 32);
    gl.color_3f(1.0, 1.0, 1.0);
    // All w < 0 with x, y inside: -w <= x <= w fails, so nothing is drawn (no wrap-around).
    gl.begin(GL_TRIANGLES);
    gl.vertex_4f(-0.5, -0.5, 0.0, -1.0);
    gl.vertex_4f(0.5, -0.5, 0.0, -1.0);
    gl.vertex_4f(0.0, 0.5, 0.0, -1.0);
    gl.end();
    assert_eq!(count_lit(&mut gl), 0);
    // One vertex at w = 0 (a point at infinity): the visible part is finite and drawn.
    gl.begin(GL_TRIANGLES);
    gl.vertex_4f(-0.5, -0.5, 0.0, 1.0);
    gl.vertex_4f(0.5, -0.5, 0.0, 1.0);
    gl.vertex_4f(0.0, 1.0, 0.0, 0.0);
    gl.end();
    assert!(count_lit(&mut gl) > 0);
    // The all-zero vertex.
    gl.begin(GL_TRIANGLES);
    gl.vertex_4f(0.0, 0.0, 0.0, 0.0);
    gl.vertex_4f(0.5, -0.5, 0.0, 1.0);
    gl.vertex_4f(0.0, 1.0, 0.0, 1.0);
    gl.end();
    gl.begin(GL_LINES);
    gl.vertex_4f(0.0, 0.0, 0.0, 0.0);
    gl.vertex_4f(0.0, 0.0, 0.0, 0.0);
    gl.end();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn slivers_and_degenerate_triangles() {
    let mut gl = Context::new(32, 32);
    window_ortho(&mut gl);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.begin(GL_TRIANGLES);
    // Zero area.
    gl.vertex_2f(1.0, 1.0);
    gl.vertex_2f(30.0, 30.0);
    gl.vertex_2f(15.5, 15.5);
    // Thinner than a sub-pixel step.
    gl.vertex_2f(0.0, 10.0);
    gl.vertex_2f(32.0, 10.001);
    gl.vertex_2f(0.0, 10.002);
    gl.end();
    assert!(count_lit(&mut gl) <= 32);
    // Singular modelview: everything collapses to a point.
    gl.scalef(0.0, 0.0, 0.0);
    gl.rectf(0.0, 0.0, 32.0, 32.0);
    gl.clip_plane(GL_CLIP_PLANE0, &[1.0, 0.0, 0.0, 0.0]);
    assert!(count_lit(&mut gl) <= 32);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn largest_viewport_and_far_away_viewports() {
    let mut max = [0i32; 2];
    let mut gl = Context::new(64, 64);
    gl.get_integerv(GL_MAX_VIEWPORT_DIMS, &mut max);
    assert!(max[0] >= 4096 && max[1] >= 4096);
    // A viewport larger than the limit is clamped to it.
    gl.viewport(0, 0, max[0] + 100, max[1] + 100);
    let mut vp = [0i32; 4];
    gl.get_integerv(GL_VIEWPORT, &mut vp);
    assert_eq!(vp, [0, 0, max[0], max[1]]);
    // Window coordinates span the whole viewport; the framebuffer shows its corner.
    gl.color_3f(1.0, 1.0, 1.0);
    gl.rectf(-1.0, -1.0, -0.99, -0.99);
    let lit = count_lit(&mut gl);
    let side = (max[0] as f64 * 0.005).round() as usize;
    assert_eq!(lit, side.min(64) * side.min(64));
    // Viewports far outside the framebuffer draw nothing and do not overflow.
    for (x, y) in [(i32::MAX - 10, 0), (i32::MIN, i32::MIN), (-max[0] * 4, 5)] {
        let mut gl = Context::new(16, 16);
        gl.viewport(x, y, max[0], max[1]);
        gl.color_3f(1.0, 1.0, 1.0);
        gl.rectf(-1.0, -1.0, 1.0, 1.0);
        assert_eq!(count_lit(&mut gl), 0);
    }
}

#[test]
fn zero_sized_framebuffer_and_huge_batches() {
    let mut gl = Context::new(0, 0);
    gl.rectf(-1.0, -1.0, 1.0, 1.0);
    gl.finish();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    // Many primitives in one batch stay bounded (the scene flushes at its cap).
    let mut gl = Context::new(8, 8);
    gl.begin(GL_POINTS);
    for i in 0..200_000 {
        gl.vertex_2f((i % 8) as f32 / 4.0 - 0.9, 0.0);
    }
    gl.end();
    gl.finish();
    assert!(count_lit(&mut gl) > 0);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

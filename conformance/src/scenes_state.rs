//! Differential scenes for the server attribute stack, occlusion queries, multisample state
//! and the selection and feedback render modes: pictures drawn after `glPopAttrib`, occlusion
//! counts drawn as colours, and draws in selection/feedback mode that must leave no pixel.
//! The value comparisons (hit records, feedback buffers, query answers) are in
//! `tests/differential_state.rs`.

use crate::compare::Scene;
use crate::scenes::{pal, pixel_space, scene};
use tilegl::enums::*;
use tilegl::{ClientPtr, Gl};

/// Attribute-stack, query and render-mode scenes, in report order.
pub const STATE_SCENES: &[Scene] = &[
    scene(
        "attrib_pop_restores_drawing_state",
        attrib_pop_restores_drawing_state,
    ),
    scene(
        "attrib_groups_restore_separately",
        attrib_groups_restore_separately,
    ),
    scene("occlusion_counts_as_colours", occlusion_counts_as_colours),
    scene("select_feedback_draw_nothing", select_feedback_draw_nothing),
];

fn tri(gl: &mut dyn Gl, x: f32, y: f32, s: f32, z: f32) {
    gl.begin(GL_TRIANGLES);
    gl.vertex_3f(x + 0.3, y + 0.2, z);
    gl.vertex_3f(x + s + 0.1, y + 0.4, z);
    gl.vertex_3f(x + 0.2, y + s + 0.3, z);
    gl.end();
}

/// A state set touching most groups, a draw with it; a push of everything, other state and a
/// draw; the pop and the first draw's state again.
fn attrib_pop_restores_drawing_state(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_LEQUAL);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.color_4f(1.0, 0.5, 0.0, 0.5);
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(2, 2, 60, 60);
    gl.shade_model(GL_FLAT);
    tri(gl, 2.0, 2.0, 28.0, 0.0);
    gl.push_attrib(GL_ALL_ATTRIB_BITS);
    gl.disable(GL_BLEND);
    gl.depth_func(GL_GREATER);
    gl.scissor(0, 0, 64, 64);
    gl.color_4f(0.0, 1.0, 1.0, 1.0);
    gl.viewport(0, 0, 32, 32);
    gl.enable(GL_POLYGON_STIPPLE);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    gl.line_width(3.0);
    gl.color_mask(1, 0, 1, 1);
    gl.enable(GL_FOG);
    gl.clear_color(1.0, 1.0, 1.0, 1.0);
    tri(gl, 34.0, 2.0, 28.0, 0.5);
    gl.pop_attrib();
    // Restored: LEQUAL, blending, scissor, full viewport, fill, no fog, the half-alpha orange
    // (current colour), all channels.
    tri(gl, 34.0, 34.0, 28.0, 0.0);
    tri(gl, 2.0, 2.0, 28.0, 0.0);
    gl.begin(GL_TRIANGLES);
    gl.color_3f(0.2, 0.9, 0.4);
    gl.vertex_2f(0.5, 40.0);
    gl.vertex_2f(30.0, 40.0);
    gl.vertex_2f(15.0, 62.0);
    gl.end();
}

/// Single groups: each pop restores its group and leaves the others.
fn attrib_groups_restore_separately(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    type Change = fn(&mut dyn Gl);
    let cases: [(u32, Change); 8] = [
        (GL_LINE_BIT, |gl| gl.line_width(5.0)),
        (GL_POINT_BIT, |gl| gl.point_size(6.0)),
        (GL_POLYGON_BIT, |gl| {
            gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE)
        }),
        (GL_ENABLE_BIT, |gl| gl.enable(GL_BLEND)),
        (GL_COLOR_BUFFER_BIT, |gl| gl.color_mask(0, 1, 0, 1)),
        (GL_CURRENT_BIT, |gl| gl.color_3f(0.0, 0.0, 1.0)),
        (GL_VIEWPORT_BIT, |gl| gl.viewport(0, 0, 16, 16)),
        (GL_TRANSFORM_BIT, |gl| {
            gl.clip_plane(GL_CLIP_PLANE0, &[1.0, 0.0, 0.0, -8.0]);
            gl.enable(GL_CLIP_PLANE0);
        }),
    ];
    gl.blend_func(GL_ONE, GL_ONE);
    for (i, (bit, change)) in cases.iter().enumerate() {
        let (x, y) = ((i % 4) as f32 * 16.0, (i / 4) as f32 * 16.0);
        pal(gl, i);
        gl.push_attrib(*bit);
        change(gl);
        gl.pop_attrib();
        // Drawn with the state from before the push (the line width and point size are set
        // before the other groups' draws only by their own case).
        gl.begin(GL_TRIANGLES);
        gl.vertex_2f(x + 1.0, y + 1.0);
        gl.vertex_2f(x + 15.0, y + 1.5);
        gl.vertex_2f(x + 2.0, y + 14.5);
        gl.end();
        gl.begin(GL_LINES);
        gl.vertex_2f(x + 1.0, y + 15.5);
        gl.vertex_2f(x + 15.0, y + 15.5);
        gl.end();
    }
    // A group that is not pushed keeps its change.
    gl.push_attrib(GL_LINE_BIT);
    gl.point_size(4.0);
    gl.line_width(7.0);
    gl.pop_attrib();
    gl.color_3f(1.0, 1.0, 1.0);
    gl.begin(GL_POINTS);
    gl.vertex_2f(40.0, 48.0);
    gl.end();
    gl.begin(GL_LINES);
    gl.vertex_2f(4.0, 56.5);
    gl.vertex_2f(60.0, 56.5);
    gl.end();
}

/// Occlusion counts of partly hidden triangles, written as the colour of a bar per query
/// (low byte red, next byte green), so a wrong count changes the picture.
fn occlusion_counts_as_colours(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.enable(GL_DEPTH_TEST);
    gl.color_3f(0.3, 0.3, 0.3);
    gl.begin(GL_TRIANGLES);
    gl.vertex_3f(0.0, 0.0, 0.0);
    gl.vertex_3f(64.0, 0.0, 0.0);
    gl.vertex_3f(0.0, 64.0, 0.0);
    gl.end();
    let mut ids = [0u32; 4];
    gl.gen_queries(4, &mut ids);
    for (i, &id) in ids.iter().enumerate() {
        let z = [-0.5, 0.5, -0.2, 0.7][i];
        gl.begin_query(GL_SAMPLES_PASSED, id);
        pal(gl, i);
        gl.begin(GL_TRIANGLES);
        gl.vertex_3f(8.0 + 10.0 * i as f32, 4.3, z);
        gl.vertex_3f(60.7, 20.1 + 9.0 * i as f32, z);
        gl.vertex_3f(20.2, 58.9 - 5.0 * i as f32, z);
        gl.end();
        gl.end_query(GL_SAMPLES_PASSED);
    }
    gl.disable(GL_DEPTH_TEST);
    for (i, &id) in ids.iter().enumerate() {
        let mut n = [0u32];
        gl.get_query_objectuiv(id, GL_QUERY_RESULT, &mut n);
        gl.color_3ub((n[0] & 0xFF) as u8, ((n[0] >> 8) & 0xFF) as u8, 128);
        gl.rectf(0.0, 60.0 - 4.0 * i as f32, 64.0, 64.0 - 4.0 * i as f32);
    }
}

/// Draws, clears and pixel rectangles in selection and feedback mode change nothing.
fn select_feedback_draw_nothing(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let mut select = vec![0u32; 64];
    let mut feedback = vec![0f32; 256];
    gl.select_buffer(64, ClientPtr(select.as_mut_ptr() as usize));
    gl.render_mode(GL_SELECT);
    gl.init_names();
    gl.push_name(1);
    gl.clear_color(1.0, 0.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.color_3f(0.0, 1.0, 0.0);
    gl.rectf(4.0, 4.0, 40.0, 40.0);
    gl.render_mode(GL_RENDER);
    gl.feedback_buffer(256, GL_3D_COLOR, ClientPtr(feedback.as_mut_ptr() as usize));
    gl.render_mode(GL_FEEDBACK);
    gl.rectf(20.0, 20.0, 60.0, 60.0);
    gl.window_pos_2i(10, 10);
    gl.draw_pixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, Some(&[255u8; 16]));
    gl.render_mode(GL_RENDER);
    // Back in render mode: this one is drawn.
    gl.color_3f(0.0, 0.0, 1.0);
    gl.rectf(30.0, 2.0, 62.0, 20.0);
    drop((select, feedback));
}

//! Selection and feedback (sections 5.2, 5.3): hit records and feedback values computed from
//! the specification's rules, buffer overflow, the name stack and every error.

mod common;

use common::{read_rgba, window_ortho};
use tilegl::enums::*;
use tilegl::{ClientPtr, Context, Gl};

const NULL: ClientPtr = ClientPtr(0);

/// Window z scaled to an unsigned integer as a hit record holds it.
fn zscale(z: f64) -> u32 {
    (z * 4294967295.0).round() as u32
}

fn integer(gl: &mut Context, pname: GLenum) -> i32 {
    let mut v = [0i32; 4];
    gl.get_integerv(pname, &mut v);
    v[0]
}

/// A 64 x 64 context in which object x, y are window x, y and window z = (1 - z_obj) / 2.
fn context() -> Context {
    let mut gl = client_context(64, 64);
    window_ortho(&mut gl);
    gl
}

#[test]
fn selection_hit_records() {
    let mut gl = context();
    gl.select_buffer(64, NULL);
    assert_eq!(gl.render_mode(GL_SELECT), 0);
    assert_eq!(integer(&mut gl, GL_RENDER_MODE), GL_SELECT as i32);
    gl.init_names();
    gl.push_name(1);
    // A triangle at z = 0.5: window z 0.25.
    gl.begin(GL_TRIANGLES);
    gl.vertex_3f(10.0, 10.0, 0.5);
    gl.vertex_3f(30.0, 10.0, 0.5);
    gl.vertex_3f(10.0, 30.0, 0.5);
    gl.end();
    // Outside the view volume: no hit for name 2.
    gl.load_name(2);
    gl.rectf(100.0, 100.0, 120.0, 120.0);
    // Two points: window z 0.75 and 0.5, under names 3 and 7.
    gl.load_name(3);
    gl.push_name(7);
    assert_eq!(integer(&mut gl, GL_NAME_STACK_DEPTH), 2);
    gl.begin(GL_POINTS);
    gl.vertex_3f(5.0, 5.0, -0.5);
    gl.vertex_3f(6.0, 5.0, 0.0);
    gl.end();
    // A line clipped by the near plane (z = 2 is in front of it): z from 0 to 0.75.
    gl.pop_name();
    gl.begin(GL_LINES);
    gl.vertex_3f(20.0, 20.0, 2.0);
    gl.vertex_3f(40.0, 20.0, -0.5);
    gl.end();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(gl.render_mode(GL_RENDER), 3);
    let expected = vec![
        1,
        zscale(0.25),
        zscale(0.25),
        1,
        2,
        zscale(0.5),
        zscale(0.75),
        3,
        7,
        1,
        zscale(0.0),
        zscale(0.75),
        3,
    ];
    assert_eq!(gl.select_buffer_contents(), &expected[..]);
    // The name stack is emptied on leaving selection mode.
    assert_eq!(integer(&mut gl, GL_NAME_STACK_DEPTH), 0);
}

#[test]
fn culled_polygons_and_raster_positions() {
    let mut gl = context();
    gl.select_buffer(16, NULL);
    gl.render_mode(GL_SELECT);
    gl.enable(GL_CULL_FACE);
    gl.push_name(4);
    // Clockwise: back-facing, culled, no hit.
    gl.begin(GL_TRIANGLES);
    gl.vertex_2f(10.0, 10.0);
    gl.vertex_2f(10.0, 30.0);
    gl.vertex_2f(30.0, 10.0);
    gl.end();
    gl.load_name(5);
    // A valid raster position is a hit at its z.
    gl.raster_pos_3f(3.0, 3.0, 0.0);
    gl.load_name(6);
    gl.raster_pos_3f(300.0, 3.0, 0.0);
    assert_eq!(gl.render_mode(GL_RENDER), 1);
    assert_eq!(
        gl.select_buffer_contents(),
        &[1, zscale(0.5), zscale(0.5), 5]
    );
}

#[test]
fn selection_overflow_returns_minus_one() {
    let mut gl = context();
    gl.select_buffer(5, NULL);
    gl.render_mode(GL_SELECT);
    gl.push_name(1);
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    gl.load_name(2);
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    assert_eq!(gl.render_mode(GL_RENDER), -1);
    let z = zscale(0.5);
    assert_eq!(gl.select_buffer_contents(), &[1, z, z, 1, 1]);
    // Exactly full is not an overflow.
    gl.select_buffer(4, NULL);
    gl.render_mode(GL_SELECT);
    gl.push_name(1);
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    assert_eq!(gl.render_mode(GL_RENDER), 1);
}

#[test]
fn selection_and_feedback_errors() {
    let mut gl = context();
    gl.render_mode(GL_SELECT);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION, "no select buffer yet");
    gl.render_mode(GL_FEEDBACK);
    assert_eq!(
        gl.get_error(),
        GL_INVALID_OPERATION,
        "no feedback buffer yet"
    );
    assert_eq!(integer(&mut gl, GL_RENDER_MODE), GL_RENDER as i32);
    gl.render_mode(GL_POINTS);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.select_buffer(-1, NULL);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.feedback_buffer(-1, GL_2D, NULL);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.feedback_buffer(4, GL_RGBA, NULL);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    // Name commands outside selection mode are ignored.
    gl.pop_name();
    gl.load_name(3);
    gl.push_name(3);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(integer(&mut gl, GL_NAME_STACK_DEPTH), 0);
    gl.select_buffer(8, NULL);
    assert_eq!(integer(&mut gl, GL_SELECTION_BUFFER_SIZE), 8);
    gl.render_mode(GL_SELECT);
    gl.select_buffer(8, NULL);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.load_name(1);
    assert_eq!(
        gl.get_error(),
        GL_INVALID_OPERATION,
        "load with an empty stack"
    );
    gl.pop_name();
    assert_eq!(gl.get_error(), GL_STACK_UNDERFLOW);
    let max = integer(&mut gl, GL_MAX_NAME_STACK_DEPTH);
    assert!(max >= 64);
    for i in 0..max {
        gl.push_name(i as u32);
    }
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.push_name(0);
    assert_eq!(gl.get_error(), GL_STACK_OVERFLOW);
    assert_eq!(integer(&mut gl, GL_NAME_STACK_DEPTH), max);
    gl.begin(GL_POINTS);
    gl.render_mode(GL_RENDER);
    gl.push_name(1);
    gl.end();
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    assert_eq!(gl.render_mode(GL_RENDER), 0, "no hits");
    gl.feedback_buffer(8, GL_3D, NULL);
    assert_eq!(integer(&mut gl, GL_FEEDBACK_BUFFER_SIZE), 8);
    assert_eq!(integer(&mut gl, GL_FEEDBACK_BUFFER_TYPE), GL_3D as i32);
    gl.render_mode(GL_FEEDBACK);
    gl.feedback_buffer(8, GL_3D, NULL);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    assert_eq!(gl.render_mode(GL_RENDER), 0);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn feedback_tokens_and_vertices() {
    let mut gl = context();
    gl.feedback_buffer(200, GL_3D_COLOR, NULL);
    gl.render_mode(GL_FEEDBACK);
    gl.color_4f(1.0, 0.5, 0.25, 0.75);
    gl.begin(GL_POINTS);
    gl.vertex_3f(10.5, 20.5, 0.0);
    gl.end();
    gl.pass_through(7.0);
    gl.shade_model(GL_FLAT);
    gl.begin(GL_LINE_STRIP);
    gl.color_3f(1.0, 0.0, 0.0);
    gl.vertex_2f(1.0, 2.0);
    gl.color_3f(0.0, 1.0, 0.0);
    gl.vertex_2f(3.0, 4.0);
    gl.color_3f(0.0, 0.0, 1.0);
    gl.vertex_2f(5.0, 6.0);
    gl.end();
    gl.shade_model(GL_SMOOTH);
    gl.begin(GL_TRIANGLES);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.vertex_3f(10.0, 10.0, -1.0);
    gl.vertex_3f(20.0, 10.0, -1.0);
    gl.vertex_3f(10.0, 20.0, -1.0);
    gl.end();
    let n = gl.render_mode(GL_RENDER);
    let red = [1.0, 0.0, 0.0, 1.0];
    let green = [0.0, 1.0, 0.0, 1.0];
    let blue = [0.0, 0.0, 1.0, 1.0];
    let white = [1.0; 4];
    let v = |x: f32, y: f32, z: f32, c: [f32; 4]| [vec![x, y, z], c.to_vec()].concat();
    let mut expected = vec![GL_POINT_TOKEN as f32];
    expected.extend(v(10.5, 20.5, 0.5, [1.0, 0.5, 0.25, 0.75]));
    expected.extend([GL_PASS_THROUGH_TOKEN as f32, 7.0]);
    // Flat shading: each segment takes its last vertex's colour; the strip resets the
    // stipple only at its first segment.
    expected.push(GL_LINE_RESET_TOKEN as f32);
    expected.extend(v(1.0, 2.0, 0.5, green));
    expected.extend(v(3.0, 4.0, 0.5, green));
    expected.push(GL_LINE_TOKEN as f32);
    expected.extend(v(3.0, 4.0, 0.5, blue));
    expected.extend(v(5.0, 6.0, 0.5, blue));
    expected.extend([GL_POLYGON_TOKEN as f32, 3.0]);
    expected.extend(v(10.0, 10.0, 1.0, white));
    expected.extend(v(20.0, 10.0, 1.0, white));
    expected.extend(v(10.0, 20.0, 1.0, white));
    let _ = red;
    assert_eq!(gl.feedback_buffer_contents(), &expected[..]);
    assert_eq!(n as usize, expected.len());
}

/// A triangle of zero area (collinear vertices, or two equal) is still a primitive: feedback
/// reports it, selection counts its hit (section 5.3: what would be rasterized), and the sign
/// test of section 3.5.1 makes it back-facing (a = 0 is not positive), so culling back faces
/// removes it and culling front faces keeps it.
#[test]
fn zero_area_triangles_are_back_facing_primitives() {
    let tris: [[[f32; 2]; 3]; 2] = [
        [[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]],
        [[10.0, 10.0], [10.0, 10.0], [20.0, 30.0]],
    ];
    let draw = |gl: &mut Context| {
        for t in &tris {
            gl.begin(GL_TRIANGLES);
            for v in t {
                gl.vertex_2f(v[0], v[1]);
            }
            gl.end();
        }
    };
    let mut expected = Vec::new();
    for t in &tris {
        expected.extend([GL_POLYGON_TOKEN as f32, 3.0]);
        expected.extend(t.iter().flatten());
    }
    for (cull, kept) in [(None, true), (Some(GL_BACK), false), (Some(GL_FRONT), true)] {
        let mut gl = context();
        if let Some(face) = cull {
            gl.enable(GL_CULL_FACE);
            gl.cull_face(face);
        }
        gl.feedback_buffer(64, GL_2D, NULL);
        gl.render_mode(GL_FEEDBACK);
        draw(&mut gl);
        let n = gl.render_mode(GL_RENDER);
        let want: &[f32] = if kept { &expected } else { &[] };
        assert_eq!(gl.feedback_buffer_contents(), want, "cull {cull:?}");
        assert_eq!(n as usize, want.len(), "cull {cull:?}");
        gl.select_buffer(16, NULL);
        gl.render_mode(GL_SELECT);
        gl.push_name(3);
        draw(&mut gl);
        assert_eq!(gl.render_mode(GL_RENDER), kept as i32, "cull {cull:?}");
    }
}

#[test]
fn feedback_types_sizes_w_and_texture_coordinates() {
    for (ty, size) in [
        (GL_2D, 2),
        (GL_3D, 3),
        (GL_3D_COLOR, 7),
        (GL_3D_COLOR_TEXTURE, 11),
        (GL_4D_COLOR_TEXTURE, 12),
    ] {
        let mut gl = client_context(64, 64);
        gl.matrix_mode(GL_PROJECTION);
        gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
        gl.matrix_mode(GL_TEXTURE);
        gl.scalef(2.0, 2.0, 2.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.feedback_buffer(100, ty, NULL);
        gl.render_mode(GL_FEEDBACK);
        gl.tex_coord_2f(0.25, 0.5);
        gl.color_3f(0.0, 1.0, 0.0);
        gl.begin(GL_POINTS);
        gl.vertex_3f(0.0, 0.0, -4.0);
        gl.end();
        assert_eq!(gl.render_mode(GL_RENDER), 1 + size);
        let out = gl.feedback_buffer_contents().to_vec();
        assert_eq!(out[0], GL_POINT_TOKEN as f32);
        assert_eq!(&out[1..3], &[32.0, 32.0]);
        if size >= 3 {
            // z_ndc = (f + n) / (f - n) + 2 f n / ((f - n) z_eye), window z = (z_ndc + 1) / 2.
            let (n, f, ze) = (1.0f64, 10.0f64, -4.0f64);
            let z_ndc = (f + n) / (f - n) + 2.0 * f * n / ((f - n) * ze);
            assert!((out[3] as f64 - (z_ndc + 1.0) / 2.0).abs() < 1e-6);
        }
        if size == 12 {
            assert_eq!(out[4], 4.0, "w is the clip w = -z_eye");
        }
        if size >= 7 {
            let c = if size == 12 { 5 } else { 4 };
            assert_eq!(&out[c..c + 4], &[0.0, 1.0, 0.0, 1.0]);
        }
        if size >= 11 {
            assert_eq!(&out[size as usize - 3..], &[0.5, 1.0, 0.0, 1.0]);
        }
    }
}

#[test]
fn pixel_operations_in_feedback_and_selection() {
    let mut gl = context();
    gl.clear_color(0.0, 0.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let before = read_rgba(&mut gl);
    gl.feedback_buffer(100, GL_2D, NULL);
    gl.render_mode(GL_FEEDBACK);
    gl.window_pos_2f(5.0, 6.0);
    gl.bitmap(8, 1, 0.0, 0.0, 3.0, 1.0, &[0xFF]);
    gl.draw_pixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, Some(&[255, 0, 0, 255]));
    gl.copy_pixels(0, 0, 4, 4, GL_COLOR);
    // Nothing is drawn or cleared in feedback mode.
    gl.clear_color(1.0, 0.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.rectf(0.0, 0.0, 64.0, 64.0);
    let n = gl.render_mode(GL_RENDER);
    let polygon = [GL_POLYGON_TOKEN as f32, 3.0];
    let mut expected = vec![
        GL_BITMAP_TOKEN as f32,
        5.0,
        6.0,
        GL_DRAW_PIXEL_TOKEN as f32,
        8.0,
        7.0,
        GL_COPY_PIXEL_TOKEN as f32,
        8.0,
        7.0,
    ];
    // The rectangle, as two triangles.
    expected.extend(polygon);
    expected.extend([0.0, 0.0, 64.0, 0.0, 64.0, 64.0]);
    expected.extend(polygon);
    expected.extend([0.0, 0.0, 64.0, 64.0, 0.0, 64.0]);
    assert_eq!(gl.feedback_buffer_contents(), &expected[..]);
    assert_eq!(n as usize, expected.len());
    assert_eq!(read_rgba(&mut gl), before);
    // Overflow: the buffer keeps what fits.
    gl.feedback_buffer(4, GL_2D, NULL);
    gl.render_mode(GL_FEEDBACK);
    gl.pass_through(1.0);
    gl.pass_through(2.0);
    gl.pass_through(3.0);
    assert_eq!(gl.render_mode(GL_RENDER), -1);
    let pt = GL_PASS_THROUGH_TOKEN as f32;
    assert_eq!(gl.feedback_buffer_contents(), &[pt, 1.0, pt, 2.0]);
}

#[test]
fn client_buffers_are_written_when_the_mode_ends() {
    let mut gl = context();
    let mut select = vec![0u32; 8];
    let mut feedback = vec![0f32; 8];
    gl.select_buffer(8, ClientPtr(select.as_mut_ptr() as usize));
    gl.render_mode(GL_SELECT);
    gl.push_name(9);
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    assert_eq!(gl.render_mode(GL_RENDER), 1);
    assert_eq!(&select[..4], gl.select_buffer_contents());
    gl.feedback_buffer(8, GL_2D, ClientPtr(feedback.as_mut_ptr() as usize));
    gl.render_mode(GL_FEEDBACK);
    gl.pass_through(5.0);
    assert_eq!(gl.render_mode(GL_RENDER), 2);
    assert_eq!(&feedback[..2], &[GL_PASS_THROUGH_TOKEN as f32, 5.0]);
}

#[test]
fn far_plane_depth_scales_to_the_largest_unsigned_integer() {
    let mut gl = context();
    gl.select_buffer(8, NULL);
    gl.render_mode(GL_SELECT);
    gl.push_name(1);
    // Window z 1 (on the far plane) and 0 (near plane).
    gl.begin(GL_POINTS);
    gl.vertex_3f(8.0, 8.0, -1.0);
    gl.vertex_3f(9.0, 8.0, 1.0);
    gl.end();
    assert_eq!(gl.render_mode(GL_RENDER), 1);
    assert_eq!(gl.select_buffer_contents(), &[1, 0, u32::MAX, 1]);
}

#[test]
fn buffer_pointers_are_queryable() {
    let mut gl = context();
    gl.select_buffer(4, ClientPtr(0x1000));
    gl.feedback_buffer(4, GL_2D, ClientPtr(0x2000));
    let mut p = [0usize; 2];
    gl.get_pointerv(
        GL_SELECTION_BUFFER_POINTER,
        ClientPtr(p.as_mut_ptr() as usize),
    );
    gl.get_pointerv(
        GL_FEEDBACK_BUFFER_POINTER,
        ClientPtr(p[1..].as_mut_ptr() as usize),
    );
    assert_eq!(p, [0x1000, 0x2000]);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn extreme_vertices_never_panic_in_either_mode() {
    let values = [
        0.0,
        1.0,
        -1.0,
        1e30,
        -1e30,
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        0.5,
    ];
    let mut rng = common::Rng(7);
    let pick = |rng: &mut common::Rng| values[(rng.next_u64() % values.len() as u64) as usize];
    for mode in [GL_SELECT, GL_FEEDBACK] {
        let mut gl = context();
        gl.select_buffer(1000, NULL);
        gl.feedback_buffer(1000, GL_4D_COLOR_TEXTURE, NULL);
        gl.enable(GL_CLIP_PLANE0);
        gl.clip_plane(GL_CLIP_PLANE0, &[1.0, 0.5, 0.0, -3.0]);
        gl.render_mode(mode);
        gl.push_name(1);
        for (i, prim) in [
            GL_POINTS,
            GL_LINE_LOOP,
            GL_TRIANGLE_FAN,
            GL_QUAD_STRIP,
            GL_POLYGON,
        ]
        .into_iter()
        .enumerate()
        {
            gl.polygon_mode(GL_FRONT_AND_BACK, [GL_FILL, GL_LINE, GL_POINT][i % 3]);
            gl.begin(prim);
            for _ in 0..9 {
                gl.vertex_4f(
                    pick(&mut rng),
                    pick(&mut rng),
                    pick(&mut rng),
                    pick(&mut rng),
                );
            }
            gl.end();
        }
        gl.raster_pos_4f(f32::NAN, 1.0, 0.0, 0.0);
        gl.bitmap(0, 0, 0.0, 0.0, 1.0, 1.0, &[]);
        let n = gl.render_mode(GL_RENDER);
        assert!(n >= -1);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }
}

/// A context that reads the client arrays and writes the buffers these tests name by address.
fn client_context(width: i32, height: i32) -> Context {
    let mut gl = Context::new(width, height);
    // SAFETY: every `ClientPtr` these tests pass names a live local array or variable, valid
    // for as long as the calls that read or write it, or an offset into a bound buffer object.
    unsafe { tilegl::capi::client_memory::attach(&mut gl) };
    gl
}

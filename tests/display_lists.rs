//! Display lists (OpenGL 1.5 section 5.4).
//!
//! A list is defined by the specification as the recorded sequence of its commands, so the
//! expectations are the same calls made directly: calling a list must give the picture and
//! the state that making its calls gives, bit for bit. Commands the specification executes
//! immediately, nesting, `glCallLists` name decoding and the error rules are checked one by
//! one.

mod common;

use common::{read_rgba, state_fingerprint, window_ortho};
use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::{ClientPtr, Context, Gl};

fn no_error(gl: &mut Context) {
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

/// Pictures equal (reports the number of differing pixels, not the pictures).
fn same(a: &[[u8; 4]], b: &[[u8; 4]]) {
    let n = a.iter().zip(b).filter(|(x, y)| x != y).count();
    assert_eq!(n, 0, "{n} pixels differ");
    assert_eq!(a.len(), b.len());
}

fn geti(gl: &mut Context, p: GLenum) -> i32 {
    let mut v = [0i32];
    gl.get_integerv(p, &mut v);
    v[0]
}

fn modelview(gl: &mut Context) -> [f32; 16] {
    let mut m = [0f32; 16];
    gl.get_floatv(GL_MODELVIEW_MATRIX, &mut m);
    m
}

/// A gear-like piece (as glxgears builds it): lit, material changes inside glBegin/glEnd,
/// state changes, matrices.
fn lit_piece(gl: &mut dyn Gl) {
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_DEPTH_TEST);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[5.0, 5.0, 10.0, 0.0]);
    gl.shade_model(GL_FLAT);
    gl.push_matrix();
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
    gl.materialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, &[0.8, 0.1, 0.0, 1.0]);
    gl.begin(GL_QUAD_STRIP);
    for i in 0..=12 {
        let a = i as f32 * std::f32::consts::TAU / 12.0;
        if i == 6 {
            gl.materialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, &[0.0, 0.8, 0.2, 1.0]);
        }
        gl.normal_3f(a.cos(), a.sin(), 0.5);
        gl.vertex_3f(0.3 * a.cos(), 0.3 * a.sin(), 0.1);
        gl.vertex_3f(0.8 * a.cos(), 0.8 * a.sin(), -0.1);
    }
    gl.end();
    gl.pop_matrix();
    gl.shade_model(GL_SMOOTH);
    gl.color_3f(0.2, 0.4, 1.0);
    gl.disable(GL_LIGHTING);
    gl.begin(GL_TRIANGLES);
    gl.vertex_2f(-0.9, -0.9);
    gl.color_3f(1.0, 1.0, 0.0);
    gl.vertex_2f(0.9, -0.8);
    gl.vertex_2f(0.0, -0.2);
    gl.end();
    gl.translatef(0.1, 0.05, 0.0);
}

fn fresh() -> Context {
    let mut gl = client_context(48, 48);
    gl.clear_color(0.0, 0.1, 0.1, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl
}

#[test]
fn calling_a_list_equals_making_its_calls() {
    let mut direct = fresh();
    lit_piece(&mut direct);
    lit_piece(&mut direct);
    no_error(&mut direct);
    let want = read_rgba(&mut direct);
    let want_state = state_fingerprint(&mut direct);

    // GL_COMPILE: nothing happens until the list is called.
    let mut gl = fresh();
    let before = read_rgba(&mut gl);
    let before_state = state_fingerprint(&mut gl);
    let l = gl.gen_lists(1);
    gl.new_list(l, GL_COMPILE);
    lit_piece(&mut gl);
    gl.end_list();
    no_error(&mut gl);
    same(&read_rgba(&mut gl), &before);
    assert_eq!(state_fingerprint(&mut gl), before_state);
    gl.call_list(l);
    gl.call_list(l);
    no_error(&mut gl);
    same(&read_rgba(&mut gl), &want);
    assert_eq!(state_fingerprint(&mut gl), want_state);

    // GL_COMPILE_AND_EXECUTE: executed while compiled, and again when called.
    let mut gl = fresh();
    gl.new_list(7, GL_COMPILE_AND_EXECUTE);
    lit_piece(&mut gl);
    gl.end_list();
    gl.call_list(7);
    no_error(&mut gl);
    same(&read_rgba(&mut gl), &want);
    assert_eq!(state_fingerprint(&mut gl), want_state);
}

#[test]
fn nested_lists_and_the_nesting_limit() {
    // List k translates by 1 and calls list k + 1: a chain of 100 lists. Execution nests at
    // most GL_MAX_LIST_NESTING = 64 levels, so one call translates by 64.
    let mut gl = fresh();
    assert_eq!(geti(&mut gl, GL_MAX_LIST_NESTING), 64);
    let base = gl.gen_lists(100);
    for k in 0..100 {
        gl.new_list(base + k, GL_COMPILE);
        gl.translatef(1.0, 0.0, 0.0);
        gl.call_list(base + k + 1);
        gl.end_list();
    }
    gl.call_list(base);
    no_error(&mut gl);
    assert_eq!(modelview(&mut gl)[12], 64.0);
    // A list calling itself stops at the limit too.
    gl.load_identity();
    gl.new_list(500, GL_COMPILE);
    gl.translatef(0.0, 1.0, 0.0);
    gl.call_list(500);
    gl.end_list();
    gl.call_list(500);
    assert_eq!(modelview(&mut gl)[13], 64.0);
    // A list calls the definition current at execution time.
    gl.load_identity();
    gl.new_list(600, GL_COMPILE);
    gl.call_list(601);
    gl.end_list();
    gl.new_list(601, GL_COMPILE);
    gl.scalef(2.0, 3.0, 4.0);
    gl.end_list();
    gl.call_list(600);
    assert_eq!(modelview(&mut gl)[5], 3.0);
    no_error(&mut gl);
}

#[test]
fn call_lists_decodes_every_name_type_and_adds_the_base() {
    let mut gl = fresh();
    // List n multiplies the modelview x scale by a prime unique to n, so the product says
    // exactly which lists ran (and how often).
    let primes = [2.0f32, 3.0, 5.0, 7.0, 11.0, 13.0];
    let names: [u32; 6] = [10, 11, 266, 0x10203 + 10, 0x01020304 + 10, 20];
    for (n, p) in names.iter().zip(primes) {
        gl.new_list(*n, GL_COMPILE);
        gl.scalef(p, 1.0, 1.0);
        gl.end_list();
    }
    gl.list_base(10);
    assert_eq!(geti(&mut gl, GL_LIST_BASE), 10);
    let run = |gl: &mut Context, ty: GLenum, bytes: &[u8], n: i32| -> f32 {
        gl.load_identity();
        gl.call_lists(n, ty, Some(bytes));
        assert_eq!(gl.get_error(), GL_NO_ERROR, "type {ty:#x}");
        modelview(gl)[0]
    };
    // offsets 0, 1, 10 -> lists 10, 11, 20 -> 2 * 3 * 13
    assert_eq!(run(&mut gl, GL_UNSIGNED_BYTE, &[0, 1, 10], 3), 78.0);
    assert_eq!(run(&mut gl, GL_BYTE, &[0, 1, 10], 3), 78.0);
    let shorts: Vec<u8> = [0i16, 256].iter().flat_map(|v| v.to_ne_bytes()).collect();
    assert_eq!(run(&mut gl, GL_SHORT, &shorts, 2), 10.0);
    let ushorts: Vec<u8> = [1u16, 256].iter().flat_map(|v| v.to_ne_bytes()).collect();
    assert_eq!(run(&mut gl, GL_UNSIGNED_SHORT, &ushorts, 2), 15.0);
    let ints: Vec<u8> = [0x10203i32, 10]
        .iter()
        .flat_map(|v| v.to_ne_bytes())
        .collect();
    assert_eq!(run(&mut gl, GL_INT, &ints, 2), 7.0 * 13.0);
    let uints: Vec<u8> = [0x01020304u32]
        .iter()
        .flat_map(|v| v.to_ne_bytes())
        .collect();
    assert_eq!(run(&mut gl, GL_UNSIGNED_INT, &uints, 1), 11.0);
    let floats: Vec<u8> = [1.0f32, 256.0]
        .iter()
        .flat_map(|v| v.to_ne_bytes())
        .collect();
    assert_eq!(run(&mut gl, GL_FLOAT, &floats, 2), 15.0);
    // Multi-byte names are most significant byte first.
    assert_eq!(run(&mut gl, GL_2_BYTES, &[1, 0, 0, 1], 2), 15.0);
    assert_eq!(run(&mut gl, GL_3_BYTES, &[1, 2, 3], 1), 7.0);
    assert_eq!(run(&mut gl, GL_4_BYTES, &[1, 2, 3, 4, 0, 0, 0, 0], 2), 22.0);
    // A negative signed offset reaches below the base.
    gl.list_base(21);
    assert_eq!(run(&mut gl, GL_BYTE, &[0xFF], 1), 13.0);
    // Undefined names are skipped.
    assert_eq!(run(&mut gl, GL_UNSIGNED_BYTE, &[100], 1), 1.0);
}

#[test]
fn commands_executed_at_compile_time_are_not_recorded() {
    let mut gl = fresh();
    gl.new_list(1, GL_COMPILE);
    assert_eq!(geti(&mut gl, GL_LIST_INDEX), 1);
    assert_eq!(geti(&mut gl, GL_LIST_MODE), GL_COMPILE as i32);
    // Executed now (section 5.4) ...
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 2);
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.client_active_texture(GL_TEXTURE1);
    let l = gl.gen_lists(2);
    assert_eq!(gl.is_list(l), 1);
    let mut t = [0u32];
    gl.gen_textures(1, &mut t);
    let mut b = [0u32];
    gl.gen_buffers(1, &mut b);
    gl.bind_buffer(GL_ARRAY_BUFFER, b[0]);
    gl.buffer_data(GL_ARRAY_BUFFER, 8, None, GL_STATIC_DRAW);
    assert_eq!(gl.is_enabled(GL_VERTEX_ARRAY), 1);
    gl.flush();
    // ... recorded, not executed:
    gl.enable(GL_BLEND);
    gl.list_base(5);
    gl.color_3f(0.5, 0.5, 0.5);
    assert_eq!(gl.is_enabled(GL_BLEND), 0);
    gl.end_list();
    no_error(&mut gl);
    assert_eq!(geti(&mut gl, GL_LIST_INDEX), 0);
    assert_eq!(geti(&mut gl, GL_LIST_MODE), 0);
    assert_eq!(geti(&mut gl, GL_UNPACK_ALIGNMENT), 2);
    assert_eq!(geti(&mut gl, GL_CLIENT_ACTIVE_TEXTURE), GL_TEXTURE1 as i32);
    assert_eq!(geti(&mut gl, GL_LIST_BASE), 0);
    // Calling the list performs only the recorded calls.
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 4);
    gl.disable_client_state(GL_VERTEX_ARRAY);
    gl.call_list(1);
    assert_eq!(gl.is_enabled(GL_BLEND), 1);
    assert_eq!(geti(&mut gl, GL_LIST_BASE), 5);
    assert_eq!(geti(&mut gl, GL_UNPACK_ALIGNMENT), 4);
    assert_eq!(gl.is_enabled(GL_VERTEX_ARRAY), 0);
    let mut c = [0f32; 4];
    gl.get_floatv(GL_CURRENT_COLOR, &mut c);
    assert_eq!(c, [0.5, 0.5, 0.5, 1.0]);
    no_error(&mut gl);
}

#[test]
fn draw_arrays_in_a_list_keeps_the_vertices_of_compile_time() {
    let pos: [f32; 6] = [4.0, 4.0, 40.0, 6.0, 20.0, 40.0];
    let col: [u8; 12] = [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255];
    let bytes: Vec<u8> = pos.iter().flat_map(|v| v.to_ne_bytes()).collect();
    // Reference: immediate mode.
    let mut want = fresh();
    window_ortho(&mut want);
    want.begin(GL_TRIANGLES);
    for i in 0..3 {
        want.color_4ubv(&col[4 * i..4 * i + 4].try_into().unwrap());
        want.vertex_2fv(&pos[2 * i..2 * i + 2].try_into().unwrap());
    }
    want.end();
    let want = read_rgba(&mut want);

    let mut gl = fresh();
    window_ortho(&mut gl);
    let mut b = [0u32];
    gl.gen_buffers(1, &mut b);
    gl.bind_buffer(GL_ARRAY_BUFFER, b[0]);
    gl.buffer_data(GL_ARRAY_BUFFER, 24, Some(&bytes), GL_STATIC_DRAW);
    gl.vertex_pointer(2, GL_FLOAT, 0, ClientPtr(0));
    // Colours from client memory: with no buffer bound the pointer is an address.
    gl.bind_buffer(GL_ARRAY_BUFFER, 0);
    gl.color_pointer(4, GL_UNSIGNED_BYTE, 0, ClientPtr(col.as_ptr() as usize));
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.enable_client_state(GL_COLOR_ARRAY);
    gl.new_list(3, GL_COMPILE);
    gl.draw_arrays(GL_TRIANGLES, 0, 3);
    gl.end_list();
    gl.new_list(4, GL_COMPILE);
    gl.draw_elements(
        GL_TRIANGLES,
        3,
        GL_UNSIGNED_BYTE,
        ClientPtr([0u8, 1, 2].as_ptr() as usize),
    );
    gl.end_list();
    // Change everything the draw read; the lists keep what they fetched.
    gl.bind_buffer(GL_ARRAY_BUFFER, b[0]);
    gl.buffer_data(GL_ARRAY_BUFFER, 24, Some(&[0u8; 24]), GL_STATIC_DRAW);
    gl.disable_client_state(GL_COLOR_ARRAY);
    gl.disable_client_state(GL_VERTEX_ARRAY);
    gl.call_list(3);
    no_error(&mut gl);
    same(&read_rgba(&mut gl), &want);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.call_list(4);
    no_error(&mut gl);
    same(&read_rgba(&mut gl), &want);
}

#[test]
fn gen_delete_and_is_list() {
    let mut gl = fresh();
    assert_eq!(gl.gen_lists(0), 0);
    let a = gl.gen_lists(3);
    assert!(a > 0);
    for n in a..a + 3 {
        assert_eq!(gl.is_list(n), 1, "generated names are empty lists");
    }
    // The next range avoids defined names.
    gl.new_list(a + 5, GL_COMPILE);
    gl.end_list();
    let b = gl.gen_lists(4);
    assert!(b >= a + 6 || b + 4 <= a, "{b} overlaps");
    gl.delete_lists(a, 2);
    assert_eq!(gl.is_list(a), 0);
    assert_eq!(gl.is_list(a + 1), 0);
    assert_eq!(gl.is_list(a + 2), 1);
    // Deleting unused names is fine.
    gl.delete_lists(1000, 50);
    assert_eq!(gl.is_list(0), 0);
    no_error(&mut gl);
    // Redefining replaces the old contents.
    gl.new_list(a + 2, GL_COMPILE);
    gl.translatef(3.0, 0.0, 0.0);
    gl.end_list();
    gl.new_list(a + 2, GL_COMPILE);
    gl.translatef(5.0, 0.0, 0.0);
    gl.end_list();
    gl.call_list(a + 2);
    assert_eq!(modelview(&mut gl)[12], 5.0);
    no_error(&mut gl);
}

#[test]
fn errors_of_compiled_commands_are_raised_when_the_list_executes() {
    let mut gl = fresh();
    gl.new_list(9, GL_COMPILE);
    gl.enable(0xDEAD);
    gl.end_list();
    no_error(&mut gl);
    gl.call_list(9);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    // A compiled draw with a bad mode likewise.
    gl.new_list(10, GL_COMPILE);
    gl.draw_arrays(GL_LINE, 0, 3);
    gl.end_list();
    no_error(&mut gl);
    gl.call_list(10);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    // With GL_COMPILE_AND_EXECUTE the error also happens now.
    gl.new_list(11, GL_COMPILE_AND_EXECUTE);
    gl.matrix_mode(GL_TEXTURE_2D);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.end_list();
    gl.call_list(11);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    // glCallList is legal between glBegin and glEnd; a list holding glVertex works there.
    gl.new_list(12, GL_COMPILE);
    gl.vertex_2f(0.0, 0.0);
    gl.end_list();
    gl.begin(GL_POINTS);
    gl.call_list(12);
    gl.end();
    no_error(&mut gl);
}

type Call = fn(&mut Context);

#[test]
fn every_list_error_is_recorded_and_changes_nothing() {
    fn none(_: &mut Context) {}
    fn compiling(g: &mut Context) {
        g.new_list(1, GL_COMPILE);
    }
    let cases: Vec<(&str, Call, Call, GLenum)> = vec![
        (
            "newList 0",
            none,
            |g| g.new_list(0, GL_COMPILE),
            GL_INVALID_VALUE,
        ),
        (
            "newList mode",
            none,
            |g| g.new_list(1, GL_EXECUTE_AND_COMPILE_BAD),
            GL_INVALID_ENUM,
        ),
        (
            "newList inside newList",
            compiling,
            |g| g.new_list(2, GL_COMPILE),
            GL_INVALID_OPERATION,
        ),
        (
            "endList without newList",
            none,
            |g| g.end_list(),
            GL_INVALID_OPERATION,
        ),
        (
            "genLists negative",
            none,
            |g| {
                g.gen_lists(-1);
            },
            GL_INVALID_VALUE,
        ),
        (
            "genLists absurd",
            none,
            |g| {
                g.gen_lists(i32::MAX);
            },
            GL_OUT_OF_MEMORY,
        ),
        (
            "deleteLists negative",
            none,
            |g| g.delete_lists(1, -1),
            GL_INVALID_VALUE,
        ),
        (
            "callLists negative",
            none,
            |g| g.call_lists(-1, GL_UNSIGNED_BYTE, Some(&[])),
            GL_INVALID_VALUE,
        ),
        (
            "callLists type",
            none,
            |g| g.call_lists(1, GL_DOUBLE, Some(&[0; 8])),
            GL_INVALID_ENUM,
        ),
        (
            "newList in begin",
            |g| g.begin(GL_POINTS),
            |g| g.new_list(1, GL_COMPILE),
            GL_INVALID_OPERATION,
        ),
    ];
    for (what, setup, call, expected) in cases {
        let mut gl = fresh();
        setup(&mut gl);
        let inside = what.contains("in begin");
        let before = (!inside).then(|| state_fingerprint(&mut gl));
        call(&mut gl);
        if inside {
            gl.end();
        }
        assert_eq!(gl.get_error(), expected, "{what}");
        if let Some(before) = before {
            assert_eq!(state_fingerprint(&mut gl), before, "{what}: state changed");
        }
    }
}

/// Not a GL enum: a mode glNewList must reject.
const GL_EXECUTE_AND_COMPILE_BAD: GLenum = GL_COMPILE_AND_EXECUTE + 1;

/// A display list holding `glBegin(GL_LINE_STRIP)`, `glColor3f(1, 1, 0)`, `glEvalCoord1f`s of
/// a `MAP1_VERTEX_3` curve and `glEnd` (piglit's dlist-fdo31590) draws the curve yellow: the
/// list's commands execute in order (section 5.4), after the white set before `glCallList`.
/// Mesa 22 draws it white, which is why the capture is a known failure.
#[test]
fn evaluated_strip_in_a_list_takes_the_lists_colour() {
    let mut gl = client_context(50, 50);
    gl.matrix_mode(GL_PROJECTION);
    gl.ortho(-5.0, 5.0, -5.0, 5.0, -5.0, 5.0);
    gl.matrix_mode(GL_MODELVIEW);
    let points = [
        -4.0f32, -4.0, 0.0, -2.0, 4.0, 0.0, 2.0, -4.0, 0.0, 4.0, 4.0, 0.0,
    ];
    gl.map_1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &points);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.new_list(5, GL_COMPILE);
    gl.begin(GL_LINE_STRIP);
    gl.color_3f(1.0, 1.0, 0.0);
    for i in 0..=30 {
        gl.eval_coord_1f(i as f32 / 30.0);
    }
    gl.end();
    gl.end_list();
    gl.color_3f(1.0, 1.0, 1.0);
    gl.call_list(5);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let drawn: Vec<[u8; 4]> = read_rgba(&mut gl)
        .into_iter()
        .filter(|p| p[..3] != [0, 0, 0])
        .collect();
    assert!(drawn.len() > 40, "only {} pixels drawn", drawn.len());
    assert!(drawn.iter().all(|p| *p == [255, 255, 0, 255]), "{drawn:?}");
}

/// A context that reads the client arrays and writes the buffers these tests name by address.
fn client_context(width: i32, height: i32) -> Context {
    let mut gl = Context::new(width, height);
    // SAFETY: every `ClientPtr` these tests pass names a live local array or variable, valid
    // for as long as the calls that read or write it, or an offset into a bound buffer object.
    unsafe { tilegl::capi::client_memory::attach(&mut gl) };
    gl
}

//! Vertex arrays and buffer objects (OpenGL 1.5 sections 2.8 and 2.9).
//!
//! The expectations come from the specification's definition of the array commands as
//! sequences of immediate-mode calls: `glArrayElement(i)` is `glEdgeFlag`, `glMultiTexCoord`,
//! `glNormal`, `glColor`, `glSecondaryColor`, `glFogCoord`, `glVertex` with element `i`, and
//! the draw commands are `glBegin`, `glArrayElement`s, `glEnd`. So every test renders or
//! queries the same thing twice, once through arrays and once through the typed immediate-mode
//! calls, and asks for the identical answer (bit for bit).

mod common;

use common::{read_rgba, window_ortho, Rng};
use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::{ClientPtr, Context, Gl};

fn f32_bytes(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_ne_bytes()).collect()
}

fn no_error(gl: &mut Context) {
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

/// Creates a buffer bound to `target` holding `data`.
fn buffer(gl: &mut Context, target: GLenum, data: &[u8]) -> u32 {
    let mut b = [0u32];
    gl.gen_buffers(1, &mut b);
    gl.bind_buffer(target, b[0]);
    gl.buffer_data(target, data.len() as isize, Some(data), GL_STATIC_DRAW);
    b[0]
}

// ------------------------------------------------------------------ conversions (table 2.6)

/// Raw test values, representable in every signed type.
const RAW: [f64; 4] = [-100.0, 57.0, 127.0, 3.0];

/// `RAW` as the bytes of an array of `ty`.
fn raw_bytes(ty: GLenum, n: usize) -> Vec<u8> {
    RAW[..n]
        .iter()
        .flat_map(|&v| match ty {
            GL_BYTE => (v as i8).to_ne_bytes().to_vec(),
            GL_UNSIGNED_BYTE => ((v as i32 + 128) as u8).to_ne_bytes().to_vec(),
            GL_SHORT => ((v * 250.0) as i16).to_ne_bytes().to_vec(),
            GL_UNSIGNED_SHORT => ((v * 250.0 + 32768.0) as u16).to_ne_bytes().to_vec(),
            GL_INT => ((v * 1.0e7) as i32).to_ne_bytes().to_vec(),
            GL_UNSIGNED_INT => ((v * 1.0e7 + 2.0e9) as u32).to_ne_bytes().to_vec(),
            GL_FLOAT => ((v / 128.0) as f32).to_ne_bytes().to_vec(),
            GL_DOUBLE => (v / 128.0 + 1e-9).to_ne_bytes().to_vec(),
            _ => unreachable!(),
        })
        .collect()
}

macro_rules! typed {
    ($b:expr, $t:ty, $n:literal) => {{
        let s = std::mem::size_of::<$t>();
        let v: [$t; $n] = std::array::from_fn(|i| {
            <$t>::from_ne_bytes($b[i * s..(i + 1) * s].try_into().unwrap())
        });
        v
    }};
}

/// The immediate-mode route: the typed `glColor`/`glNormal`/... call the array element stands
/// for, with the same raw bytes.
fn immediate_call(gl: &mut Context, what: GLenum, ty: GLenum, size: usize, b: &[u8]) {
    match (what, ty, size) {
        (GL_COLOR_ARRAY, GL_BYTE, 3) => gl.color_3bv(&typed!(b, i8, 3)),
        (GL_COLOR_ARRAY, GL_BYTE, 4) => gl.color_4bv(&typed!(b, i8, 4)),
        (GL_COLOR_ARRAY, GL_UNSIGNED_BYTE, 3) => gl.color_3ubv(&typed!(b, u8, 3)),
        (GL_COLOR_ARRAY, GL_UNSIGNED_BYTE, 4) => gl.color_4ubv(&typed!(b, u8, 4)),
        (GL_COLOR_ARRAY, GL_SHORT, 3) => gl.color_3sv(&typed!(b, i16, 3)),
        (GL_COLOR_ARRAY, GL_SHORT, 4) => gl.color_4sv(&typed!(b, i16, 4)),
        (GL_COLOR_ARRAY, GL_UNSIGNED_SHORT, 3) => gl.color_3usv(&typed!(b, u16, 3)),
        (GL_COLOR_ARRAY, GL_UNSIGNED_SHORT, 4) => gl.color_4usv(&typed!(b, u16, 4)),
        (GL_COLOR_ARRAY, GL_INT, 3) => gl.color_3iv(&typed!(b, i32, 3)),
        (GL_COLOR_ARRAY, GL_INT, 4) => gl.color_4iv(&typed!(b, i32, 4)),
        (GL_COLOR_ARRAY, GL_UNSIGNED_INT, 3) => gl.color_3uiv(&typed!(b, u32, 3)),
        (GL_COLOR_ARRAY, GL_UNSIGNED_INT, 4) => gl.color_4uiv(&typed!(b, u32, 4)),
        (GL_COLOR_ARRAY, GL_FLOAT, 3) => gl.color_3fv(&typed!(b, f32, 3)),
        (GL_COLOR_ARRAY, GL_FLOAT, 4) => gl.color_4fv(&typed!(b, f32, 4)),
        (GL_COLOR_ARRAY, GL_DOUBLE, 3) => gl.color_3dv(&typed!(b, f64, 3)),
        (GL_COLOR_ARRAY, GL_DOUBLE, 4) => gl.color_4dv(&typed!(b, f64, 4)),
        (GL_SECONDARY_COLOR_ARRAY, GL_BYTE, 3) => gl.secondary_color_3bv(&typed!(b, i8, 3)),
        (GL_SECONDARY_COLOR_ARRAY, GL_UNSIGNED_BYTE, 3) => {
            gl.secondary_color_3ubv(&typed!(b, u8, 3))
        }
        (GL_SECONDARY_COLOR_ARRAY, GL_SHORT, 3) => gl.secondary_color_3sv(&typed!(b, i16, 3)),
        (GL_SECONDARY_COLOR_ARRAY, GL_UNSIGNED_SHORT, 3) => {
            gl.secondary_color_3usv(&typed!(b, u16, 3))
        }
        (GL_SECONDARY_COLOR_ARRAY, GL_INT, 3) => gl.secondary_color_3iv(&typed!(b, i32, 3)),
        (GL_SECONDARY_COLOR_ARRAY, GL_UNSIGNED_INT, 3) => {
            gl.secondary_color_3uiv(&typed!(b, u32, 3))
        }
        (GL_SECONDARY_COLOR_ARRAY, GL_FLOAT, 3) => gl.secondary_color_3fv(&typed!(b, f32, 3)),
        (GL_SECONDARY_COLOR_ARRAY, GL_DOUBLE, 3) => gl.secondary_color_3dv(&typed!(b, f64, 3)),
        (GL_NORMAL_ARRAY, GL_BYTE, 3) => gl.normal_3bv(&typed!(b, i8, 3)),
        (GL_NORMAL_ARRAY, GL_SHORT, 3) => gl.normal_3sv(&typed!(b, i16, 3)),
        (GL_NORMAL_ARRAY, GL_INT, 3) => gl.normal_3iv(&typed!(b, i32, 3)),
        (GL_NORMAL_ARRAY, GL_FLOAT, 3) => gl.normal_3fv(&typed!(b, f32, 3)),
        (GL_NORMAL_ARRAY, GL_DOUBLE, 3) => gl.normal_3dv(&typed!(b, f64, 3)),
        (GL_FOG_COORD_ARRAY, GL_FLOAT, 1) => gl.fog_coordfv(&typed!(b, f32, 1)),
        (GL_FOG_COORD_ARRAY, GL_DOUBLE, 1) => gl.fog_coorddv(&typed!(b, f64, 1)),
        (GL_TEXTURE_COORD_ARRAY, GL_SHORT, 1) => gl.tex_coord_1sv(&typed!(b, i16, 1)),
        (GL_TEXTURE_COORD_ARRAY, GL_SHORT, 2) => gl.tex_coord_2sv(&typed!(b, i16, 2)),
        (GL_TEXTURE_COORD_ARRAY, GL_SHORT, 3) => gl.tex_coord_3sv(&typed!(b, i16, 3)),
        (GL_TEXTURE_COORD_ARRAY, GL_SHORT, 4) => gl.tex_coord_4sv(&typed!(b, i16, 4)),
        (GL_TEXTURE_COORD_ARRAY, GL_INT, 1) => gl.tex_coord_1iv(&typed!(b, i32, 1)),
        (GL_TEXTURE_COORD_ARRAY, GL_INT, 2) => gl.tex_coord_2iv(&typed!(b, i32, 2)),
        (GL_TEXTURE_COORD_ARRAY, GL_INT, 3) => gl.tex_coord_3iv(&typed!(b, i32, 3)),
        (GL_TEXTURE_COORD_ARRAY, GL_INT, 4) => gl.tex_coord_4iv(&typed!(b, i32, 4)),
        (GL_TEXTURE_COORD_ARRAY, GL_FLOAT, 1) => gl.tex_coord_1fv(&typed!(b, f32, 1)),
        (GL_TEXTURE_COORD_ARRAY, GL_FLOAT, 2) => gl.tex_coord_2fv(&typed!(b, f32, 2)),
        (GL_TEXTURE_COORD_ARRAY, GL_FLOAT, 3) => gl.tex_coord_3fv(&typed!(b, f32, 3)),
        (GL_TEXTURE_COORD_ARRAY, GL_FLOAT, 4) => gl.tex_coord_4fv(&typed!(b, f32, 4)),
        (GL_TEXTURE_COORD_ARRAY, GL_DOUBLE, 1) => gl.tex_coord_1dv(&typed!(b, f64, 1)),
        (GL_TEXTURE_COORD_ARRAY, GL_DOUBLE, 2) => gl.tex_coord_2dv(&typed!(b, f64, 2)),
        (GL_TEXTURE_COORD_ARRAY, GL_DOUBLE, 3) => gl.tex_coord_3dv(&typed!(b, f64, 3)),
        (GL_TEXTURE_COORD_ARRAY, GL_DOUBLE, 4) => gl.tex_coord_4dv(&typed!(b, f64, 4)),
        other => panic!("no immediate call for {other:?}"),
    }
}

fn set_pointer(gl: &mut Context, what: GLenum, size: i32, ty: GLenum, ptr: ClientPtr) {
    match what {
        GL_COLOR_ARRAY => gl.color_pointer(size, ty, 0, ptr),
        GL_SECONDARY_COLOR_ARRAY => gl.secondary_color_pointer(size, ty, 0, ptr),
        GL_NORMAL_ARRAY => gl.normal_pointer(ty, 0, ptr),
        GL_FOG_COORD_ARRAY => gl.fog_coord_pointer(ty, 0, ptr),
        GL_TEXTURE_COORD_ARRAY => gl.tex_coord_pointer(size, ty, 0, ptr),
        _ => unreachable!(),
    }
}

fn current(gl: &mut Context, what: GLenum) -> Vec<f32> {
    let pname = match what {
        GL_COLOR_ARRAY => GL_CURRENT_COLOR,
        GL_SECONDARY_COLOR_ARRAY => GL_CURRENT_SECONDARY_COLOR,
        GL_NORMAL_ARRAY => GL_CURRENT_NORMAL,
        GL_FOG_COORD_ARRAY => GL_CURRENT_FOG_COORD,
        GL_TEXTURE_COORD_ARRAY => GL_CURRENT_TEXTURE_COORDS,
        _ => unreachable!(),
    };
    let mut v = vec![0f32; 4];
    gl.get_floatv(pname, &mut v);
    v
}

#[test]
fn array_element_sets_what_the_typed_immediate_calls_set() {
    let all = [
        GL_BYTE,
        GL_UNSIGNED_BYTE,
        GL_SHORT,
        GL_UNSIGNED_SHORT,
        GL_INT,
        GL_UNSIGNED_INT,
        GL_FLOAT,
        GL_DOUBLE,
    ];
    let cases: Vec<(GLenum, Vec<usize>, Vec<GLenum>)> = vec![
        (GL_COLOR_ARRAY, vec![3, 4], all.to_vec()),
        (GL_SECONDARY_COLOR_ARRAY, vec![3], all.to_vec()),
        (
            GL_NORMAL_ARRAY,
            vec![3],
            vec![GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE],
        ),
        (GL_FOG_COORD_ARRAY, vec![1], vec![GL_FLOAT, GL_DOUBLE]),
        (
            GL_TEXTURE_COORD_ARRAY,
            vec![1, 2, 3, 4],
            vec![GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE],
        ),
    ];
    let mut checked = 0;
    for (what, sizes, types) in cases {
        for &size in &sizes {
            for &ty in &types {
                let bytes = raw_bytes(ty, size);
                // Route 1: a buffer-object array and glArrayElement (outside glBegin/glEnd:
                // only the current values change).
                let mut a = client_context(8, 8);
                buffer(&mut a, GL_ARRAY_BUFFER, &bytes);
                set_pointer(&mut a, what, size as i32, ty, ClientPtr(0));
                a.enable_client_state(what);
                a.array_element(0);
                no_error(&mut a);
                // Route 2: the same bytes from client memory.
                let mut c = client_context(8, 8);
                set_pointer(
                    &mut c,
                    what,
                    size as i32,
                    ty,
                    ClientPtr(bytes.as_ptr() as usize),
                );
                c.enable_client_state(what);
                c.array_element(0);
                no_error(&mut c);
                // Route 3: the typed immediate-mode call.
                let mut b = client_context(8, 8);
                immediate_call(&mut b, what, ty, size, &bytes);
                no_error(&mut b);
                let (ra, rb, rc) = (
                    current(&mut a, what),
                    current(&mut b, what),
                    current(&mut c, what),
                );
                assert_eq!(
                    ra.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                    rb.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                    "{what:#x} size {size} type {ty:#x}"
                );
                assert_eq!(ra, rc);
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 16 + 8 + 5 + 2 + 16);
}

// ------------------------------------------------------------------ pictures

const N: usize = 36;

/// Random triangle data: positions, colours, normals, secondary colours, fog coordinates,
/// texture coordinates.
struct Mesh {
    pos: Vec<[f32; 3]>,
    color: Vec<[f32; 4]>,
    normal: Vec<[f32; 3]>,
    secondary: Vec<[f32; 3]>,
    fog: Vec<f32>,
    tex: Vec<[f32; 2]>,
}

fn mesh() -> Mesh {
    let mut r = Rng(0x1234_5678_9abc_def1);
    let mut m = Mesh {
        pos: vec![],
        color: vec![],
        normal: vec![],
        secondary: vec![],
        fog: vec![],
        tex: vec![],
    };
    for _ in 0..N {
        m.pos
            .push([r.range(2.0, 62.0), r.range(2.0, 62.0), r.range(-0.9, 0.9)]);
        m.color.push([
            r.range(0.0, 1.0),
            r.range(0.0, 1.0),
            r.range(0.0, 1.0),
            r.range(0.5, 1.0),
        ]);
        m.normal
            .push([r.range(-1.0, 1.0), r.range(-1.0, 1.0), r.range(0.2, 1.0)]);
        m.secondary
            .push([r.range(0.0, 0.5), r.range(0.0, 0.5), r.range(0.0, 0.5)]);
        m.fog.push(r.range(0.0, 1.0));
        m.tex.push([r.range(-1.0, 2.0), r.range(-1.0, 2.0)]);
    }
    m
}

/// Lighting with colour material, colour sum, fog from the fog coordinate, depth test and a
/// 2x2 texture: every per-vertex value shows in the picture.
fn setup(gl: &mut Context) {
    window_ortho(gl);
    gl.clear_color(0.1, 0.2, 0.3, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_NORMALIZE);
    gl.enable(GL_COLOR_MATERIAL);
    gl.enable(GL_COLOR_SUM);
    gl.enable(GL_FOG);
    gl.fogi(GL_FOG_MODE, GL_LINEAR as i32);
    gl.fogi(GL_FOG_COORD_SRC, GL_FOG_COORD as i32);
    gl.fogf(GL_FOG_END, 1.5);
    let mut t = [0u32];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    let texels: [u8; 16] = [
        255, 255, 255, 255, 128, 255, 128, 255, 255, 128, 128, 255, 200, 200, 255, 255,
    ];
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    no_error(gl);
}

fn immediate_vertex(gl: &mut Context, m: &Mesh, i: usize) {
    gl.tex_coord_2fv(&m.tex[i]);
    gl.normal_3fv(&m.normal[i]);
    gl.color_4fv(&m.color[i]);
    gl.secondary_color_3fv(&m.secondary[i]);
    gl.fog_coordf(m.fog[i]);
    gl.vertex_3fv(&m.pos[i]);
}

/// The reference: immediate mode, vertices in `order`.
fn immediate_picture(m: &Mesh, order: &[usize]) -> Vec<[u8; 4]> {
    let mut gl = client_context(64, 64);
    setup(&mut gl);
    gl.begin(GL_TRIANGLES);
    for &i in order {
        immediate_vertex(&mut gl, m, i);
    }
    gl.end();
    no_error(&mut gl);
    read_rgba(&mut gl)
}

/// Separate arrays, one buffer object each, all enabled.
fn buffer_arrays(gl: &mut Context, m: &Mesh) {
    let flat = |v: &dyn Fn(usize) -> Vec<f32>| (0..N).flat_map(v).collect::<Vec<f32>>();
    buffer(
        gl,
        GL_ARRAY_BUFFER,
        &f32_bytes(&flat(&|i| m.pos[i].to_vec())),
    );
    gl.vertex_pointer(3, GL_FLOAT, 0, ClientPtr(0));
    buffer(
        gl,
        GL_ARRAY_BUFFER,
        &f32_bytes(&flat(&|i| m.color[i].to_vec())),
    );
    gl.color_pointer(4, GL_FLOAT, 0, ClientPtr(0));
    buffer(
        gl,
        GL_ARRAY_BUFFER,
        &f32_bytes(&flat(&|i| m.normal[i].to_vec())),
    );
    gl.normal_pointer(GL_FLOAT, 0, ClientPtr(0));
    // Secondary colours with a stride and an offset: [pad, r, g, b] per element.
    buffer(
        gl,
        GL_ARRAY_BUFFER,
        &f32_bytes(&flat(&|i| {
            vec![9.0, m.secondary[i][0], m.secondary[i][1], m.secondary[i][2]]
        })),
    );
    gl.secondary_color_pointer(3, GL_FLOAT, 16, ClientPtr(4));
    buffer(gl, GL_ARRAY_BUFFER, &f32_bytes(&m.fog));
    gl.fog_coord_pointer(GL_FLOAT, 0, ClientPtr(0));
    buffer(
        gl,
        GL_ARRAY_BUFFER,
        &f32_bytes(&flat(&|i| m.tex[i].to_vec())),
    );
    gl.tex_coord_pointer(2, GL_FLOAT, 0, ClientPtr(0));
    gl.bind_buffer(GL_ARRAY_BUFFER, 0);
    for a in [
        GL_VERTEX_ARRAY,
        GL_COLOR_ARRAY,
        GL_NORMAL_ARRAY,
        GL_SECONDARY_COLOR_ARRAY,
        GL_FOG_COORD_ARRAY,
        GL_TEXTURE_COORD_ARRAY,
    ] {
        gl.enable_client_state(a);
    }
    no_error(gl);
}

fn arrays_picture(draw: impl FnOnce(&mut Context)) -> Vec<[u8; 4]> {
    let m = mesh();
    let mut gl = client_context(64, 64);
    setup(&mut gl);
    buffer_arrays(&mut gl, &m);
    draw(&mut gl);
    no_error(&mut gl);
    read_rgba(&mut gl)
}

fn assert_same(a: &[[u8; 4]], b: &[[u8; 4]], what: &str) {
    let differing = a.iter().zip(b).filter(|(x, y)| x != y).count();
    assert_eq!(differing, 0, "{what}: {differing} pixels differ");
}

fn assert_drawn(p: &[[u8; 4]]) {
    let bg = p[0];
    let drawn = p.iter().filter(|&&c| c != bg).count();
    assert!(drawn > 500, "only {drawn} pixels drawn");
}

/// A permutation of 0..N used as the element order.
fn order() -> Vec<usize> {
    (0..N).map(|i| (i * 7 + 3) % N).collect()
}

#[test]
fn draw_arrays_from_buffers_equals_immediate_mode() {
    let m = mesh();
    let reference = immediate_picture(&m, &(0..N).collect::<Vec<_>>());
    assert_drawn(&reference);
    let p = arrays_picture(|gl| gl.draw_arrays(GL_TRIANGLES, 0, N as i32));
    assert_same(&p, &reference, "glDrawArrays");
    let p = arrays_picture(|gl| {
        gl.multi_draw_arrays(GL_TRIANGLES, &[0, 12, 30], &[12, 18, 6], 3);
    });
    assert_same(&p, &reference, "glMultiDrawArrays");
    let p = arrays_picture(|gl| {
        gl.begin(GL_TRIANGLES);
        for i in 0..N as i32 {
            gl.array_element(i);
        }
        gl.end();
    });
    assert_same(&p, &reference, "glArrayElement");
}

#[test]
fn draw_elements_with_every_index_type_equals_immediate_mode() {
    let m = mesh();
    let ord = order();
    let reference = immediate_picture(&m, &ord);
    assert_drawn(&reference);
    for ty in [GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT] {
        let bytes: Vec<u8> = ord
            .iter()
            .flat_map(|&i| match ty {
                GL_UNSIGNED_BYTE => vec![i as u8],
                GL_UNSIGNED_SHORT => (i as u16).to_ne_bytes().to_vec(),
                _ => (i as u32).to_ne_bytes().to_vec(),
            })
            .collect();
        let isz = bytes.len() / N;
        // Indices in an element array buffer, after 2 leading padding indices.
        let mut padded = vec![0u8; 2 * isz];
        padded.extend_from_slice(&bytes);
        let p = arrays_picture(|gl| {
            buffer(gl, GL_ELEMENT_ARRAY_BUFFER, &padded);
            gl.draw_elements(GL_TRIANGLES, N as i32, ty, ClientPtr(2 * isz));
        });
        assert_same(
            &p,
            &reference,
            &format!("glDrawElements type {ty:#x} buffer"),
        );
        // Client-memory indices.
        let p = arrays_picture(|gl| {
            gl.draw_elements(
                GL_TRIANGLES,
                N as i32,
                ty,
                ClientPtr(bytes.as_ptr() as usize),
            );
        });
        assert_same(
            &p,
            &reference,
            &format!("glDrawElements type {ty:#x} client"),
        );
        let p = arrays_picture(|gl| {
            gl.draw_range_elements(
                GL_TRIANGLES,
                0,
                N as u32 - 1,
                N as i32,
                ty,
                ClientPtr(bytes.as_ptr() as usize),
            );
        });
        assert_same(&p, &reference, &format!("glDrawRangeElements type {ty:#x}"));
        // Two draws through glMultiDrawElements: a client array of index pointers.
        let split = 12 * isz;
        let ptrs: Vec<u8> = [bytes.as_ptr() as usize, bytes.as_ptr() as usize + split]
            .iter()
            .flat_map(|p| p.to_ne_bytes())
            .collect();
        let p = arrays_picture(|gl| {
            gl.multi_draw_elements(
                GL_TRIANGLES,
                &[12, N as i32 - 12],
                ty,
                ClientPtr(ptrs.as_ptr() as usize),
                2,
            );
        });
        assert_same(&p, &reference, &format!("glMultiDrawElements type {ty:#x}"));
    }
}

#[test]
fn client_memory_arrays_equal_buffer_arrays() {
    let m = mesh();
    let reference = immediate_picture(&m, &(0..N).collect::<Vec<_>>());
    let pos: Vec<f32> = m.pos.iter().flatten().copied().collect();
    let col: Vec<u8> = m
        .color
        .iter()
        .flatten()
        .map(|&c| (c * 255.0).round() as u8)
        .collect();
    // Client memory vertex and ubyte colour arrays against immediate glColor4ubv.
    let mut gl = client_context(64, 64);
    setup(&mut gl);
    gl.disable(GL_LIGHTING);
    gl.vertex_pointer(3, GL_FLOAT, 0, ClientPtr(pos.as_ptr() as usize));
    gl.color_pointer(4, GL_UNSIGNED_BYTE, 0, ClientPtr(col.as_ptr() as usize));
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.enable_client_state(GL_COLOR_ARRAY);
    gl.draw_arrays(GL_TRIANGLES, 0, N as i32);
    no_error(&mut gl);
    let p = read_rgba(&mut gl);
    let mut gl = client_context(64, 64);
    setup(&mut gl);
    gl.disable(GL_LIGHTING);
    gl.begin(GL_TRIANGLES);
    for i in 0..N {
        gl.color_4ubv(&col[4 * i..4 * i + 4].try_into().unwrap());
        gl.vertex_3fv(&m.pos[i]);
    }
    gl.end();
    let q = read_rgba(&mut gl);
    assert_drawn(&q);
    assert_same(&p, &q, "client arrays");
    assert!(reference != q);
}

// ------------------------------------------------------------------ interleaved arrays

/// Table 2.5: (format, has texture (size), colour (size, ubyte?), normal, vertex size).
type Layout = (GLenum, usize, Option<(usize, bool)>, bool, usize);
const INTERLEAVED: [Layout; 14] = [
    (GL_V2F, 0, None, false, 2),
    (GL_V3F, 0, None, false, 3),
    (GL_C4UB_V2F, 0, Some((4, true)), false, 2),
    (GL_C4UB_V3F, 0, Some((4, true)), false, 3),
    (GL_C3F_V3F, 0, Some((3, false)), false, 3),
    (GL_N3F_V3F, 0, None, true, 3),
    (GL_C4F_N3F_V3F, 0, Some((4, false)), true, 3),
    (GL_T2F_V3F, 2, None, false, 3),
    (GL_T4F_V4F, 4, None, false, 4),
    (GL_T2F_C4UB_V3F, 2, Some((4, true)), false, 3),
    (GL_T2F_C3F_V3F, 2, Some((3, false)), false, 3),
    (GL_T2F_N3F_V3F, 2, None, true, 3),
    (GL_T2F_C4F_N3F_V3F, 2, Some((4, false)), true, 3),
    (GL_T4F_C4F_N3F_V4F, 4, Some((4, false)), true, 4),
];

#[test]
fn every_interleaved_format_equals_immediate_mode() {
    let m = mesh();
    for (fmt, ts, col, norm, vs) in INTERLEAVED {
        // Build the interleaved record by hand from table 2.5's order: T, C, N, V.
        let mut rec: Vec<u8> = Vec::new();
        let tex4 = |i: usize| [m.tex[i][0], m.tex[i][1], 0.25, 1.25];
        let pos4 = |i: usize| [m.pos[i][0], m.pos[i][1], m.pos[i][2], 1.0];
        let ub = |i: usize| m.color[i].map(|c| (c * 255.0) as u8);
        for i in 0..N {
            rec.extend(f32_bytes(&tex4(i)[..ts]));
            match col {
                Some((4, true)) => rec.extend(ub(i)),
                Some((n, _)) => rec.extend(f32_bytes(&m.color[i][..n])),
                None => {}
            }
            if norm {
                rec.extend(f32_bytes(&m.normal[i]));
            }
            rec.extend(f32_bytes(&pos4(i)[..vs]));
        }
        let mut a = client_context(64, 64);
        setup(&mut a);
        // Stale state that glInterleavedArrays must disable.
        a.enable_client_state(GL_SECONDARY_COLOR_ARRAY);
        a.enable_client_state(GL_FOG_COORD_ARRAY);
        a.enable_client_state(GL_EDGE_FLAG_ARRAY);
        a.enable_client_state(GL_INDEX_ARRAY);
        buffer(&mut a, GL_ARRAY_BUFFER, &rec);
        a.interleaved_arrays(fmt, 0, ClientPtr(0));
        a.draw_arrays(GL_TRIANGLES, 0, N as i32);
        no_error(&mut a);
        let pa = read_rgba(&mut a);
        let mut stride = [0i32];
        a.get_integerv(GL_VERTEX_ARRAY_STRIDE, &mut stride);
        assert_eq!(stride[0] as usize, rec.len() / N, "{fmt:#x} stride");
        for (arr, on) in [
            (GL_TEXTURE_COORD_ARRAY, ts > 0),
            (GL_COLOR_ARRAY, col.is_some()),
            (GL_NORMAL_ARRAY, norm),
            (GL_VERTEX_ARRAY, true),
            (GL_SECONDARY_COLOR_ARRAY, false),
            (GL_FOG_COORD_ARRAY, false),
            (GL_EDGE_FLAG_ARRAY, false),
            (GL_INDEX_ARRAY, false),
        ] {
            assert_eq!(a.is_enabled(arr) != 0, on, "{fmt:#x} enable of {arr:#x}");
        }

        let mut b = client_context(64, 64);
        setup(&mut b);
        b.begin(GL_TRIANGLES);
        for i in 0..N {
            match ts {
                2 => b.tex_coord_2fv(&m.tex[i]),
                4 => b.tex_coord_4fv(&tex4(i)),
                _ => {}
            }
            if norm {
                b.normal_3fv(&m.normal[i]);
            }
            match col {
                Some((4, true)) => b.color_4ubv(&ub(i)),
                Some((3, false)) => b.color_3fv(&m.color[i][..3].try_into().unwrap()),
                Some(_) => b.color_4fv(&m.color[i]),
                None => {}
            }
            match vs {
                2 => b.vertex_2fv(&[m.pos[i][0], m.pos[i][1]]),
                3 => b.vertex_3fv(&m.pos[i]),
                _ => b.vertex_4fv(&pos4(i)),
            }
        }
        b.end();
        no_error(&mut b);
        let pb = read_rgba(&mut b);
        assert_drawn(&pb);
        assert_same(&pa, &pb, &format!("interleaved format {fmt:#x}"));
    }
}

#[test]
fn interleaved_arrays_with_explicit_stride_set_offsets_and_queries() {
    let mut gl = client_context(8, 8);
    let mut b = [0u32];
    gl.gen_buffers(1, &mut b);
    gl.bind_buffer(GL_ARRAY_BUFFER, b[0]);
    gl.interleaved_arrays(GL_T2F_C4UB_V3F, 40, ClientPtr(100));
    no_error(&mut gl);
    let geti = |gl: &mut Context, p: GLenum| {
        let mut v = [0i32];
        gl.get_integerv(p, &mut v);
        v[0]
    };
    assert_eq!(geti(&mut gl, GL_COLOR_ARRAY_STRIDE), 40);
    assert_eq!(geti(&mut gl, GL_COLOR_ARRAY_SIZE), 4);
    assert_eq!(geti(&mut gl, GL_COLOR_ARRAY_TYPE), GL_UNSIGNED_BYTE as i32);
    assert_eq!(geti(&mut gl, GL_TEXTURE_COORD_ARRAY_SIZE), 2);
    assert_eq!(geti(&mut gl, GL_VERTEX_ARRAY_SIZE), 3);
    assert_eq!(geti(&mut gl, GL_VERTEX_ARRAY_BUFFER_BINDING), b[0] as i32);
    assert_eq!(
        gl.array_pointer(GL_TEXTURE_COORD_ARRAY_POINTER),
        Some(ClientPtr(100))
    );
    assert_eq!(
        gl.array_pointer(GL_COLOR_ARRAY_POINTER),
        Some(ClientPtr(108))
    );
    assert_eq!(
        gl.array_pointer(GL_VERTEX_ARRAY_POINTER),
        Some(ClientPtr(112))
    );
    // glGetPointerv stores through the given address.
    let mut out = 0usize;
    gl.get_pointerv(
        GL_VERTEX_ARRAY_POINTER,
        ClientPtr(&mut out as *mut usize as usize),
    );
    assert_eq!(out, 112);
    no_error(&mut gl);
}

// ------------------------------------------------------------------ state and errors

#[test]
fn array_state_defaults_match_table_6_8() {
    let mut gl = client_context(8, 8);
    let expect: &[(GLenum, i32)] = &[
        (GL_VERTEX_ARRAY, 0),
        (GL_VERTEX_ARRAY_SIZE, 4),
        (GL_VERTEX_ARRAY_TYPE, GL_FLOAT as i32),
        (GL_VERTEX_ARRAY_STRIDE, 0),
        (GL_NORMAL_ARRAY_TYPE, GL_FLOAT as i32),
        (GL_COLOR_ARRAY_SIZE, 4),
        (GL_SECONDARY_COLOR_ARRAY_SIZE, 3),
        (GL_FOG_COORD_ARRAY_TYPE, GL_FLOAT as i32),
        (GL_TEXTURE_COORD_ARRAY_SIZE, 4),
        (GL_EDGE_FLAG_ARRAY_STRIDE, 0),
        (GL_INDEX_ARRAY, 0),
        (GL_INDEX_ARRAY_TYPE, GL_FLOAT as i32),
        (GL_INDEX_ARRAY_STRIDE, 0),
        (GL_ARRAY_BUFFER_BINDING, 0),
        (GL_ELEMENT_ARRAY_BUFFER_BINDING, 0),
        (GL_CLIENT_ATTRIB_STACK_DEPTH, 0),
        (GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, 16),
    ];
    for &(p, v) in expect {
        let mut out = [-1i32];
        gl.get_integerv(p, &mut out);
        assert_eq!(out[0], v, "{p:#x}");
    }
    no_error(&mut gl);
    // Texture-coordinate array state is per client active unit.
    gl.client_active_texture(GL_TEXTURE1);
    gl.tex_coord_pointer(2, GL_SHORT, 6, ClientPtr(0));
    gl.enable_client_state(GL_TEXTURE_COORD_ARRAY);
    gl.client_active_texture(GL_TEXTURE0);
    assert_eq!(gl.is_enabled(GL_TEXTURE_COORD_ARRAY), 0);
    let mut out = [0i32];
    gl.get_integerv(GL_TEXTURE_COORD_ARRAY_SIZE, &mut out);
    assert_eq!(out[0], 4);
    gl.client_active_texture(GL_TEXTURE1);
    assert_eq!(gl.is_enabled(GL_TEXTURE_COORD_ARRAY), 1);
    gl.get_integerv(GL_TEXTURE_COORD_ARRAY_STRIDE, &mut out);
    assert_eq!(out[0], 6);
    no_error(&mut gl);
}

// ------------------------------------------------------------------ buffer objects

#[test]
fn buffer_objects_store_map_and_report() {
    let mut gl = client_context(8, 8);
    let mut names = [0u32; 2];
    gl.gen_buffers(2, &mut names);
    assert!(names[0] != 0 && names[1] != 0 && names[0] != names[1]);
    // Names become buffer objects when first bound.
    assert_eq!(gl.is_buffer(names[0]), 0);
    gl.bind_buffer(GL_ARRAY_BUFFER, names[0]);
    assert_eq!(gl.is_buffer(names[0]), 1);
    let geti = |gl: &mut Context, p: GLenum| {
        let mut v = [0i32];
        gl.get_buffer_parameteriv(GL_ARRAY_BUFFER, p, &mut v);
        v[0]
    };
    assert_eq!(geti(&mut gl, GL_BUFFER_SIZE), 0);
    assert_eq!(geti(&mut gl, GL_BUFFER_USAGE), GL_STATIC_DRAW as i32);
    assert_eq!(geti(&mut gl, GL_BUFFER_ACCESS), GL_READ_WRITE as i32);
    assert_eq!(geti(&mut gl, GL_BUFFER_MAPPED), 0);
    let data: Vec<u8> = (0..32).collect();
    gl.buffer_data(GL_ARRAY_BUFFER, 32, Some(&data), GL_DYNAMIC_DRAW);
    assert_eq!(geti(&mut gl, GL_BUFFER_SIZE), 32);
    assert_eq!(geti(&mut gl, GL_BUFFER_USAGE), GL_DYNAMIC_DRAW as i32);
    gl.buffer_sub_data(GL_ARRAY_BUFFER, 4, 3, Some(&[200, 201, 202]));
    let mut out = [0u8; 8];
    gl.get_buffer_sub_data(GL_ARRAY_BUFFER, 2, 8, &mut out);
    assert_eq!(out, [2, 3, 200, 201, 202, 7, 8, 9]);
    // Mapping: the pointer, the access, writes through the (safe) mapping.
    let p = gl.map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
    assert_ne!(p, ClientPtr(0));
    assert_eq!(geti(&mut gl, GL_BUFFER_MAPPED), 1);
    assert_eq!(geti(&mut gl, GL_BUFFER_ACCESS), GL_WRITE_ONLY as i32);
    let mut q = 0usize;
    gl.get_buffer_pointerv(
        GL_ARRAY_BUFFER,
        GL_BUFFER_MAP_POINTER,
        ClientPtr(&mut q as *mut usize as usize),
    );
    assert_eq!(q, p.0);
    gl.mapped_buffer_mut(GL_ARRAY_BUFFER).unwrap()[0] = 99;
    assert_eq!(gl.unmap_buffer(GL_ARRAY_BUFFER), GL_TRUE as u8);
    assert!(gl.mapped_buffer_mut(GL_ARRAY_BUFFER).is_none());
    gl.get_buffer_pointerv(
        GL_ARRAY_BUFFER,
        GL_BUFFER_MAP_POINTER,
        ClientPtr(&mut q as *mut usize as usize),
    );
    assert_eq!(q, 0);
    gl.get_buffer_sub_data(GL_ARRAY_BUFFER, 0, 2, &mut out[..2]);
    assert_eq!(out[..2], [99, 1]);
    // glBufferData with no data: zero-filled store of the size.
    gl.buffer_data(GL_ARRAY_BUFFER, 4, None, GL_STREAM_DRAW);
    gl.get_buffer_sub_data(GL_ARRAY_BUFFER, 0, 4, &mut out[..4]);
    assert_eq!(out[..4], [0; 4]);
    no_error(&mut gl);
    // Deleting unbinds it from the target and from the arrays that source from it.
    gl.vertex_pointer(2, GL_FLOAT, 0, ClientPtr(0));
    gl.delete_buffers(1, &names[..1]);
    assert_eq!(gl.is_buffer(names[0]), 0);
    let mut v = [7i32];
    gl.get_integerv(GL_ARRAY_BUFFER_BINDING, &mut v);
    assert_eq!(v[0], 0);
    gl.get_integerv(GL_VERTEX_ARRAY_BUFFER_BINDING, &mut v);
    assert_eq!(v[0], 0);
    no_error(&mut gl);
}

#[test]
fn push_and_pop_client_attrib_restore_their_groups() {
    let mut gl = client_context(8, 8);
    gl.push_client_attrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    gl.enable_client_state(GL_COLOR_ARRAY);
    gl.color_pointer(3, GL_UNSIGNED_BYTE, 12, ClientPtr(64));
    gl.client_active_texture(GL_TEXTURE2);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    let mut b = [0u32];
    gl.gen_buffers(1, &mut b);
    gl.bind_buffer(GL_ARRAY_BUFFER, b[0]);
    let mut depth = [0i32];
    gl.get_integerv(GL_CLIENT_ATTRIB_STACK_DEPTH, &mut depth);
    assert_eq!(depth[0], 1);
    gl.pop_client_attrib();
    let geti = |gl: &mut Context, p: GLenum| {
        let mut v = [0i32];
        gl.get_integerv(p, &mut v);
        v[0]
    };
    assert_eq!(gl.is_enabled(GL_COLOR_ARRAY), 0);
    assert_eq!(geti(&mut gl, GL_COLOR_ARRAY_SIZE), 4);
    assert_eq!(geti(&mut gl, GL_COLOR_ARRAY_STRIDE), 0);
    assert_eq!(geti(&mut gl, GL_ARRAY_BUFFER_BINDING), 0);
    assert_eq!(geti(&mut gl, GL_CLIENT_ACTIVE_TEXTURE), GL_TEXTURE0 as i32);
    // Pixel store was not in the mask.
    assert_eq!(geti(&mut gl, GL_UNPACK_ALIGNMENT), 1);
    gl.push_client_attrib(GL_CLIENT_PIXEL_STORE_BIT);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 8);
    gl.pixel_storei(GL_PACK_ROW_LENGTH, 5);
    gl.enable_client_state(GL_NORMAL_ARRAY);
    gl.pop_client_attrib();
    assert_eq!(geti(&mut gl, GL_UNPACK_ALIGNMENT), 1);
    assert_eq!(geti(&mut gl, GL_PACK_ROW_LENGTH), 0);
    assert_eq!(gl.is_enabled(GL_NORMAL_ARRAY), 1);
    no_error(&mut gl);
}

/// The specification leaves a current value indeterminate after `glDrawArrays` when its array
/// is enabled (section 2.8); tilegl, like Mesa (llvmpipe and softpipe, queried through the
/// oracle: `GL_CURRENT_COLOR` stays (1, 1, 1, 1) here), leaves it as it was, while
/// `glArrayElement` sets it.
#[test]
fn disabled_vertex_array_draws_nothing_and_leaves_current_values() {
    let mut gl = client_context(16, 16);
    window_ortho(&mut gl);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let col: [f32; 4] = [0.25, 0.5, 0.75, 1.0];
    buffer(&mut gl, GL_ARRAY_BUFFER, &f32_bytes(&col));
    gl.color_pointer(4, GL_FLOAT, 0, ClientPtr(0));
    gl.enable_client_state(GL_COLOR_ARRAY);
    gl.draw_arrays(GL_POINTS, 0, 1);
    no_error(&mut gl);
    assert!(read_rgba(&mut gl).iter().all(|&p| p == [0, 0, 0, 0]));
    let mut c = [0f32; 4];
    gl.get_floatv(GL_CURRENT_COLOR, &mut c);
    assert_eq!(c, [1.0; 4]);
    gl.array_element(0);
    gl.get_floatv(GL_CURRENT_COLOR, &mut c);
    assert_eq!(c, col);
}

/// glEnable/glDisable of an array's name switch the array as glEnableClientState does
/// (EXT_vertex_array's form, kept by Mesa's compatibility contexts and relied on by piglit's
/// GL 1.x tests): the same picture and the same glIsEnabled answers.
#[test]
fn enable_of_an_array_name_enables_the_client_array() {
    let arrays = [
        GL_VERTEX_ARRAY,
        GL_COLOR_ARRAY,
        GL_NORMAL_ARRAY,
        GL_SECONDARY_COLOR_ARRAY,
        GL_FOG_COORD_ARRAY,
        GL_TEXTURE_COORD_ARRAY,
    ];
    let via_client_state = arrays_picture(|gl| gl.draw_arrays(GL_TRIANGLES, 0, N as i32));
    let via_enable = arrays_picture(|gl| {
        for a in arrays {
            gl.disable_client_state(a);
            gl.enable(a);
        }
        gl.draw_arrays(GL_TRIANGLES, 0, N as i32);
    });
    assert_drawn(&via_client_state);
    assert_same(
        &via_enable,
        &via_client_state,
        "arrays enabled with glEnable",
    );
    let mut gl = client_context(4, 4);
    for a in [
        GL_VERTEX_ARRAY,
        GL_COLOR_ARRAY,
        GL_EDGE_FLAG_ARRAY,
        GL_FOG_COORD_ARRAY,
    ] {
        gl.enable(a);
        assert_eq!(gl.is_enabled(a), GL_TRUE as GLboolean);
        gl.disable(a);
        assert_eq!(gl.is_enabled(a), GL_FALSE as GLboolean);
    }
    no_error(&mut gl);
}

#[test]
fn edge_flag_and_second_unit_texture_coordinate_arrays_set_their_current_values() {
    let mut gl = client_context(8, 8);
    let flags: [u8; 2] = [1, 0];
    let tex: [f32; 6] = [9.0, 9.0, 9.0, 0.5, -2.0, 7.0];
    gl.edge_flag_pointer(0, ClientPtr(flags.as_ptr() as usize));
    gl.enable_client_state(GL_EDGE_FLAG_ARRAY);
    gl.client_active_texture(GL_TEXTURE1);
    buffer(&mut gl, GL_ARRAY_BUFFER, &f32_bytes(&tex));
    gl.tex_coord_pointer(3, GL_FLOAT, 0, ClientPtr(0));
    gl.enable_client_state(GL_TEXTURE_COORD_ARRAY);
    gl.array_element(1);
    no_error(&mut gl);
    let mut e = [7u8];
    gl.get_booleanv(GL_EDGE_FLAG, &mut e);
    assert_eq!(e[0], 0);
    // Unit 1 got (s, t, r, 1); unit 0 kept its default (0, 0, 0, 1).
    let mut t = [0f32; 4];
    gl.active_texture(GL_TEXTURE1);
    gl.get_floatv(GL_CURRENT_TEXTURE_COORDS, &mut t);
    assert_eq!(t, [0.5, -2.0, 7.0, 1.0]);
    gl.active_texture(GL_TEXTURE0);
    gl.get_floatv(GL_CURRENT_TEXTURE_COORDS, &mut t);
    assert_eq!(t, [0.0, 0.0, 0.0, 1.0]);
    // The same through the immediate-mode call.
    let mut b = client_context(8, 8);
    b.edge_flag(0);
    b.multi_tex_coord_3fv(GL_TEXTURE1, &[0.5, -2.0, 7.0]);
    b.active_texture(GL_TEXTURE1);
    let mut u = [0f32; 4];
    b.get_floatv(GL_CURRENT_TEXTURE_COORDS, &mut u);
    assert_eq!(t.len(), u.len());
    assert_eq!(u, [0.5, -2.0, 7.0, 1.0]);
}

#[test]
fn buffer_access_survives_unmap_and_buffer_data_resets_it() {
    // GL 1.5 section 2.9: glMapBuffer sets GL_BUFFER_ACCESS; glUnmapBuffer only clears the
    // mapping; glBufferData creates a store with access GL_READ_WRITE.
    let mut gl = client_context(8, 8);
    buffer(&mut gl, GL_ARRAY_BUFFER, &[1, 2, 3, 4]);
    let access = |gl: &mut Context| {
        let mut v = [0];
        gl.get_buffer_parameteriv(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS, &mut v);
        v[0] as GLenum
    };
    gl.map_buffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
    gl.unmap_buffer(GL_ARRAY_BUFFER);
    assert_eq!(access(&mut gl), GL_READ_ONLY);
    gl.map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
    // glBufferData on a mapped buffer ends the mapping.
    gl.buffer_data(GL_ARRAY_BUFFER, 2, None, GL_STATIC_DRAW);
    assert!(gl.mapped_buffer_mut(GL_ARRAY_BUFFER).is_none());
    assert_eq!(access(&mut gl), GL_READ_WRITE);
    no_error(&mut gl);
}

#[test]
fn locked_arrays_report_their_range_and_still_draw_current_data() {
    let m = mesh();
    let reference = immediate_picture(&m, &(0..N).collect::<Vec<_>>());
    let p = arrays_picture(|gl| {
        gl.lock_arrays_ext(0, N as i32);
        let mut v = [0i32; 2];
        gl.get_integerv(GL_ARRAY_ELEMENT_LOCK_FIRST_EXT, &mut v[..1]);
        gl.get_integerv(GL_ARRAY_ELEMENT_LOCK_COUNT_EXT, &mut v[1..]);
        assert_eq!(v, [0, N as i32]);
        gl.draw_arrays(GL_TRIANGLES, 0, N as i32);
        gl.unlock_arrays_ext();
        gl.get_integerv(GL_ARRAY_ELEMENT_LOCK_COUNT_EXT, &mut v[1..]);
        assert_eq!(v[1], 0);
    });
    assert_same(&p, &reference, "locked arrays");
}

#[test]
fn a_draw_larger_than_one_fetch_chunk_equals_immediate_mode() {
    // 3 x 3400 vertices: more than two of the 4096-element chunks a direct draw is fetched in.
    let mut r = Rng(77);
    let n = 3 * 3400;
    let pos: Vec<f32> = (0..n)
        .flat_map(|_| [r.range(0.0, 64.0), r.range(0.0, 64.0)])
        .collect();
    let col: Vec<u8> = (0..n * 4).map(|_| (r.next_u64() >> 56) as u8).collect();
    let mut a = client_context(64, 64);
    window_ortho(&mut a);
    buffer(&mut a, GL_ARRAY_BUFFER, &f32_bytes(&pos));
    a.vertex_pointer(2, GL_FLOAT, 0, ClientPtr(0));
    buffer(&mut a, GL_ARRAY_BUFFER, &col);
    a.color_pointer(4, GL_UNSIGNED_BYTE, 0, ClientPtr(0));
    a.enable_client_state(GL_VERTEX_ARRAY);
    a.enable_client_state(GL_COLOR_ARRAY);
    a.draw_arrays(GL_TRIANGLES, 0, n as i32);
    no_error(&mut a);
    let mut b = client_context(64, 64);
    window_ortho(&mut b);
    b.begin(GL_TRIANGLES);
    for i in 0..n {
        b.color_4ubv(&col[4 * i..4 * i + 4].try_into().unwrap());
        b.vertex_2fv(&pos[2 * i..2 * i + 2].try_into().unwrap());
    }
    b.end();
    let (pa, pb) = (read_rgba(&mut a), read_rgba(&mut b));
    assert_drawn(&pb);
    assert_same(&pa, &pb, "large glDrawArrays");
}

/// ARB_vertex_array_bgra: `GL_BGRA` as the size of a colour or secondary colour array reads four
/// unsigned bytes per element as blue, green, red, alpha (normalised); any other type is
/// INVALID_OPERATION and changes nothing; the size query returns `GL_BGRA`.
#[test]
fn bgra_colour_and_secondary_colour_arrays_swap_red_and_blue() {
    let mut gl = client_context(8, 8);
    let bytes = [10u8, 60, 200, 255, 255, 128, 0, 64];
    buffer(&mut gl, GL_ARRAY_BUFFER, &bytes);
    for (what, query, pname, type_pname) in [
        (
            GL_COLOR_ARRAY,
            GL_CURRENT_COLOR,
            GL_COLOR_ARRAY_SIZE,
            GL_COLOR_ARRAY_TYPE,
        ),
        (
            GL_SECONDARY_COLOR_ARRAY,
            GL_CURRENT_SECONDARY_COLOR,
            GL_SECONDARY_COLOR_ARRAY_SIZE,
            GL_SECONDARY_COLOR_ARRAY_TYPE,
        ),
    ] {
        gl.enable_client_state(what);
        set_pointer(
            &mut gl,
            what,
            GL_BGRA as i32,
            GL_UNSIGNED_BYTE,
            ClientPtr(0),
        );
        no_error(&mut gl);
        let mut size = [0i32];
        gl.get_integerv(pname, &mut size);
        assert_eq!(size[0], GL_BGRA as i32);
        for (i, [b, g, r, a]) in [[10u8, 60, 200, 255], [255, 128, 0, 64]]
            .into_iter()
            .enumerate()
        {
            gl.array_element(i as i32);
            let mut v = [0f32; 4];
            gl.get_floatv(query, &mut v);
            let want = [r, g, b].map(|x| f32::from(x) / 255.0);
            assert_eq!(v[..3], want, "{what:#x} element {i}");
            if what == GL_COLOR_ARRAY {
                assert_eq!(v[3], f32::from(a) / 255.0);
            }
        }
        // Only unsigned bytes: INVALID_OPERATION, the array stays as it was.
        set_pointer(&mut gl, what, GL_BGRA as i32, GL_FLOAT, ClientPtr(4));
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        let mut ty = [0i32];
        gl.get_integerv(type_pname, &mut ty);
        assert_eq!(
            ty[0], GL_UNSIGNED_BYTE as i32,
            "{what:#x}: type after the refused call"
        );
        gl.disable_client_state(what);
    }
}

/// EXT_vertex_array's `gl*PointerEXT`: the core array state plus `count`, read back as
/// `GL_*_ARRAY_COUNT_EXT` (its state table; initially 0); a negative count or stride and the
/// core call's own errors are errors that change nothing; the arrays draw as the core
/// calls' do.
#[test]
fn ext_vertex_array_pointers_set_the_arrays_and_their_counts() {
    let mut gl = Context::new(4, 4);
    let data = [0u8; 64];
    let p = ClientPtr(data.as_ptr() as usize);
    let count_of = |gl: &mut Context, pname: GLenum| {
        let mut v = [0i32];
        gl.get_integerv(pname, &mut v);
        v[0]
    };
    let counts = [
        GL_VERTEX_ARRAY_COUNT_EXT,
        GL_NORMAL_ARRAY_COUNT_EXT,
        GL_COLOR_ARRAY_COUNT_EXT,
        GL_INDEX_ARRAY_COUNT_EXT,
        GL_TEXTURE_COORD_ARRAY_COUNT_EXT,
        GL_EDGE_FLAG_ARRAY_COUNT_EXT,
    ];
    for c in counts {
        assert_eq!(count_of(&mut gl, c), 0);
    }
    gl.vertex_pointer_ext(3, GL_FLOAT, 12, 5, p);
    gl.normal_pointer_ext(GL_SHORT, 0, 6, p);
    gl.color_pointer_ext(4, GL_UNSIGNED_BYTE, 0, 7, p);
    gl.index_pointer_ext(GL_INT, 0, 8, p);
    gl.tex_coord_pointer_ext(2, GL_DOUBLE, 0, 9, p);
    gl.edge_flag_pointer_ext(3, 10, p);
    no_error(&mut gl);
    for (c, want) in counts.iter().zip(5..) {
        assert_eq!(count_of(&mut gl, *c), want, "{c:#x}");
    }
    assert_eq!(count_of(&mut gl, GL_VERTEX_ARRAY_SIZE), 3);
    assert_eq!(count_of(&mut gl, GL_VERTEX_ARRAY_STRIDE), 12);
    assert_eq!(
        count_of(&mut gl, GL_COLOR_ARRAY_TYPE),
        GL_UNSIGNED_BYTE as i32
    );
    assert_eq!(count_of(&mut gl, GL_EDGE_FLAG_ARRAY_STRIDE), 3);
    assert_eq!(gl.array_pointer(GL_TEXTURE_COORD_ARRAY_POINTER), Some(p));

    // Errors change nothing: a negative count or stride, a size or type the core call refuses.
    gl.vertex_pointer_ext(3, GL_FLOAT, 0, -1, ClientPtr(8));
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.vertex_pointer_ext(1, GL_FLOAT, 0, 2, ClientPtr(8));
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.normal_pointer_ext(GL_UNSIGNED_BYTE, 0, 2, ClientPtr(8));
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.edge_flag_pointer_ext(-4, 2, ClientPtr(8));
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    assert_eq!(count_of(&mut gl, GL_VERTEX_ARRAY_COUNT_EXT), 5);
    assert_eq!(count_of(&mut gl, GL_NORMAL_ARRAY_COUNT_EXT), 6);
    assert_eq!(count_of(&mut gl, GL_EDGE_FLAG_ARRAY_COUNT_EXT), 10);
    assert_eq!(count_of(&mut gl, GL_VERTEX_ARRAY_SIZE), 3);
    assert_eq!(gl.array_pointer(GL_VERTEX_ARRAY_POINTER), Some(p));

    // An unread earlier error stays the one glGetError returns; the call still takes effect.
    gl.enable(0xFFFF);
    gl.color_pointer_ext(3, GL_FLOAT, 0, 11, p);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(count_of(&mut gl, GL_COLOR_ARRAY_COUNT_EXT), 11);
    assert_eq!(count_of(&mut gl, GL_COLOR_ARRAY_SIZE), 3);

    // The count is client state: glPushClientAttrib / glPopClientAttrib keep it.
    gl.push_client_attrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    gl.vertex_pointer_ext(2, GL_FLOAT, 0, 99, p);
    gl.pop_client_attrib();
    assert_eq!(count_of(&mut gl, GL_VERTEX_ARRAY_COUNT_EXT), 5);
    no_error(&mut gl);

    // Drawing: the mesh's arrays given through the EXT calls draw the core calls' picture.
    let m = mesh();
    let reference = arrays_picture(|gl| gl.draw_arrays(GL_TRIANGLES, 0, N as i32));
    let pos: Vec<f32> = (0..N).flat_map(|i| m.pos[i]).collect();
    let col: Vec<f32> = (0..N).flat_map(|i| m.color[i]).collect();
    let p = arrays_picture(|gl| {
        gl.vertex_pointer_ext(3, GL_FLOAT, 0, N as i32, ClientPtr(pos.as_ptr() as usize));
        gl.color_pointer_ext(4, GL_FLOAT, 0, N as i32, ClientPtr(col.as_ptr() as usize));
        gl.draw_arrays(GL_TRIANGLES, 0, N as i32);
    });
    assert_same(&p, &reference, "arrays from gl*PointerEXT");
}

/// A context that reads the client arrays and writes the buffers these tests name by address.
fn client_context(width: i32, height: i32) -> Context {
    let mut gl = Context::new(width, height);
    // SAFETY: every `ClientPtr` these tests pass names a live local array or variable, valid
    // for as long as the calls that read or write it, or an offset into a bound buffer object.
    unsafe { tilegl::capi::client_memory::attach(&mut gl) };
    gl
}

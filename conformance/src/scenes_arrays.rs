//! Differential scenes for vertex arrays, buffer objects and display lists.
//!
//! Client-memory arrays pass real addresses ([`ClientPtr`] of a `Vec` that lives until the
//! scene function returns, i.e. past every draw that reads it), so Mesa reads the same bytes
//! through `ForeignGl` as tilegl does; most scenes source their arrays from buffer objects.
//! Triangles only (no quads) wherever colours vary across a primitive, so the pictures do not
//! depend on how an implementation splits quads.

use crate::compare::Scene;
use crate::scenes::{pixel_space, scene};
use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::{ClientPtr, Gl};

/// Array, buffer-object and display-list scenes, in report order.
pub const ARRAY_SCENES: &[Scene] = &[
    scene("arrays_draw_arrays_vbo", arrays_draw_arrays_vbo),
    scene(
        "arrays_draw_elements_index_types",
        arrays_draw_elements_index_types,
    ),
    scene("arrays_client_memory_types", arrays_client_memory_types),
    scene("arrays_interleaved_formats", arrays_interleaved_formats),
    scene("arrays_multi_draw_and_range", arrays_multi_draw_and_range),
    scene("arrays_buffer_updates", arrays_buffer_updates),
    scene("lists_compile_and_execute", lists_compile_and_execute),
    scene("lists_nested_and_call_lists", lists_nested_and_call_lists),
    scene("lists_state_changes", lists_state_changes),
    scene("lists_with_arrays", lists_with_arrays),
    scene("lists_nesting_limit", lists_nesting_limit),
];

fn f32_bytes(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_ne_bytes()).collect()
}

/// A new buffer object bound to `target` holding `data`.
fn vbo(gl: &mut dyn Gl, target: GLenum, data: &[u8]) -> u32 {
    let mut b = [0u32];
    gl.gen_buffers(1, &mut b);
    gl.bind_buffer(target, b[0]);
    gl.buffer_data(target, data.len() as isize, Some(data), GL_STATIC_DRAW);
    b[0]
}

fn addr<T>(v: &[T]) -> ClientPtr {
    ClientPtr(v.as_ptr() as usize)
}

/// A triangle in pixel space at cell (cx, cy) of a grid of `cell`-pixel cells:
/// interleaved x, y, r, g, b, a per vertex.
fn cell_triangle(cx: usize, cy: usize, cell: f32, tint: f32) -> Vec<f32> {
    let (x, y) = (cx as f32 * cell, cy as f32 * cell);
    vec![
        x + 1.3,
        y + 1.2,
        1.0,
        tint,
        0.1,
        1.0, //
        x + cell - 1.4,
        y + 2.3,
        0.1,
        1.0,
        tint,
        1.0, //
        x + 0.4 * cell,
        y + cell - 1.3,
        tint,
        0.2,
        1.0,
        1.0,
    ]
}

// ---------------------------------------------------------------- arrays

fn arrays_draw_arrays_vbo(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let mut data = Vec::new();
    for k in 0..16 {
        data.extend(cell_triangle(k % 4, k / 4, 16.0, k as f32 / 15.0));
    }
    vbo(gl, GL_ARRAY_BUFFER, &f32_bytes(&data));
    gl.vertex_pointer(2, GL_FLOAT, 24, ClientPtr(0));
    gl.color_pointer(4, GL_FLOAT, 24, ClientPtr(8));
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.enable_client_state(GL_COLOR_ARRAY);
    gl.draw_arrays(GL_TRIANGLES, 0, 24);
    // The rest as a strip (first = 24): the same vertices, other triangles.
    gl.draw_arrays(GL_TRIANGLE_STRIP, 24, 24);
}

fn arrays_draw_elements_index_types(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    // A 5x5 lattice of vertices with colours; indices pick triangles.
    let mut data = Vec::new();
    for j in 0..5 {
        for i in 0..5 {
            let (x, y) = (1.3 + 15.1 * i as f32, 1.2 + 15.2 * j as f32);
            data.extend([x, y, i as f32 / 4.0, j as f32 / 4.0, 0.5, 1.0]);
        }
    }
    vbo(gl, GL_ARRAY_BUFFER, &f32_bytes(&data));
    gl.vertex_pointer(2, GL_FLOAT, 24, ClientPtr(0));
    gl.color_pointer(4, GL_FLOAT, 24, ClientPtr(8));
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.enable_client_state(GL_COLOR_ARRAY);
    let tri = |i: u32, j: u32| -> [u32; 6] {
        let v = j * 5 + i;
        [v, v + 1, v + 6, v, v + 6, v + 5]
    };
    let cells: [Vec<u32>; 4] = [
        [tri(0, 0), tri(1, 0), tri(0, 1)].concat(),
        [tri(3, 0), tri(2, 1), tri(3, 1)].concat(),
        [tri(0, 2), tri(1, 3), tri(0, 3)].concat(),
        [tri(3, 2), tri(2, 3), tri(3, 3)].concat(),
    ];
    let n = cells[0].len() as i32;
    // Element array buffers of each index type, with a leading offset.
    let ub: Vec<u8> = [vec![0u8; 3], cells[0].iter().map(|&i| i as u8).collect()].concat();
    vbo(gl, GL_ELEMENT_ARRAY_BUFFER, &ub);
    gl.draw_elements(GL_TRIANGLES, n, GL_UNSIGNED_BYTE, ClientPtr(3));
    let us: Vec<u8> = cells[1]
        .iter()
        .flat_map(|&i| (i as u16).to_ne_bytes())
        .collect();
    vbo(gl, GL_ELEMENT_ARRAY_BUFFER, &us);
    gl.draw_elements(GL_TRIANGLES, n, GL_UNSIGNED_SHORT, ClientPtr(0));
    let ui: Vec<u8> = cells[2].iter().flat_map(|&i| i.to_ne_bytes()).collect();
    vbo(gl, GL_ELEMENT_ARRAY_BUFFER, &ui);
    gl.draw_elements(GL_TRIANGLES, n, GL_UNSIGNED_INT, ClientPtr(0));
    // Client-memory indices.
    gl.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    let client: Vec<u16> = cells[3].iter().map(|&i| i as u16).collect();
    gl.draw_elements(GL_TRIANGLES, n, GL_UNSIGNED_SHORT, addr(&client));
}

/// Component values in [0, 1] as the bytes of an array of `ty` (normalized for integers).
fn typed(ty: GLenum, v: &[f32]) -> Vec<u8> {
    v.iter()
        .flat_map(|&x| match ty {
            GL_UNSIGNED_BYTE => vec![(x * 255.0).round() as u8],
            GL_BYTE => vec![(x * 127.0).round() as i8 as u8],
            GL_UNSIGNED_SHORT => ((x * 65535.0).round() as u16).to_ne_bytes().to_vec(),
            GL_SHORT => ((x * 32767.0).round() as i16).to_ne_bytes().to_vec(),
            GL_UNSIGNED_INT => ((x as f64 * 4294967295.0).round() as u32)
                .to_ne_bytes()
                .to_vec(),
            GL_INT => ((x as f64 * 2147483647.0).round() as i32)
                .to_ne_bytes()
                .to_vec(),
            GL_FLOAT => x.to_ne_bytes().to_vec(),
            _ => (x as f64).to_ne_bytes().to_vec(),
        })
        .collect()
}

/// Pixel coordinates as the bytes of a vertex array of `ty` (integers exact).
fn positions(ty: GLenum, v: &[f32]) -> Vec<u8> {
    v.iter()
        .flat_map(|&x| match ty {
            GL_SHORT => (x.round() as i16).to_ne_bytes().to_vec(),
            GL_INT => (x.round() as i32).to_ne_bytes().to_vec(),
            GL_FLOAT => (x + 0.3).to_ne_bytes().to_vec(),
            _ => (x as f64 + 0.2).to_ne_bytes().to_vec(),
        })
        .collect()
}

fn arrays_client_memory_types(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let color_types = [
        GL_UNSIGNED_BYTE,
        GL_BYTE,
        GL_UNSIGNED_SHORT,
        GL_SHORT,
        GL_UNSIGNED_INT,
        GL_INT,
        GL_FLOAT,
        GL_DOUBLE,
    ];
    let vertex_types = [GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE];
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.enable_client_state(GL_COLOR_ARRAY);
    for k in 0..16 {
        let t = cell_triangle(k % 4, k / 4, 16.0, 0.6);
        let pos: Vec<f32> = t.chunks(6).flat_map(|v| [v[0], v[1]]).collect();
        let size = if k % 2 == 0 { 4 } else { 3 };
        let col: Vec<f32> = t.chunks(6).flat_map(|v| v[2..2 + size].to_vec()).collect();
        let (ct, vt) = (color_types[k % 8], vertex_types[k / 4]);
        let p = positions(vt, &pos);
        let c = typed(ct, &col);
        gl.vertex_pointer(2, vt, 0, addr(&p));
        gl.color_pointer(size as i32, ct, 0, addr(&c));
        gl.draw_arrays(GL_TRIANGLES, 0, 3);
    }
}

/// Table 2.5 rows: (format, texture size, colour (size, ubyte), normal, vertex size).
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

fn arrays_interleaved_formats(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    // A 2x2 texture, nearest: each cell samples one texel centre (constant coordinates).
    let mut t = [0u32];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    let texels: [u8; 16] = [
        255, 255, 255, 255, 255, 128, 64, 255, 64, 255, 128, 255, 160, 160, 255, 255,
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
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 0.4, 1.0, 0.0]);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_COLOR_MATERIAL);
    // Keep all the data alive until the end of the scene.
    let mut keep: Vec<Vec<u8>> = Vec::new();
    for (k, (fmt, ts, col, norm, vs)) in INTERLEAVED.into_iter().enumerate() {
        let t = cell_triangle(k % 4, k / 4, 16.0, k as f32 / 13.0);
        let tex = [
            [0.25f32, 0.25, 0.0, 1.0],
            [0.75, 0.25, 0.0, 1.0],
            [0.5, 1.5, 0.0, 2.0],
        ][k % 3];
        let mut rec = Vec::new();
        for (v, vert) in t.chunks(6).enumerate() {
            rec.extend(f32_bytes(&tex[..ts]));
            match col {
                Some((4, true)) => rec.extend(vert[2..6].iter().map(|&c| (c * 255.0) as u8)),
                Some((n, _)) => rec.extend(f32_bytes(&vert[2..2 + n])),
                None => {}
            }
            if norm {
                let n = [[0.0f32, 0.0, 1.0], [0.5, 0.2, 1.0], [-0.3, 0.6, 0.8]][v];
                rec.extend(f32_bytes(&n));
            }
            let pos = [vert[0], vert[1], 0.1 * v as f32, 1.0];
            rec.extend(f32_bytes(&pos[..vs]));
        }
        if ts > 0 {
            gl.enable(GL_TEXTURE_2D);
        } else {
            gl.disable(GL_TEXTURE_2D);
        }
        if norm {
            gl.enable(GL_LIGHTING);
        } else {
            gl.disable(GL_LIGHTING);
        }
        gl.color_4f(0.9, 0.6, 0.3, 1.0);
        if k % 2 == 0 {
            // From a buffer object, tightly packed.
            vbo(gl, GL_ARRAY_BUFFER, &rec);
            gl.interleaved_arrays(fmt, 0, ClientPtr(0));
            gl.bind_buffer(GL_ARRAY_BUFFER, 0);
        } else {
            // From client memory, with an explicit stride and 4 bytes of padding per record.
            let size = rec.len() / 3;
            let mut padded = Vec::new();
            for r in rec.chunks(size) {
                padded.extend_from_slice(r);
                padded.extend_from_slice(&[0xEE; 4]);
            }
            gl.interleaved_arrays(fmt, (size + 4) as i32, addr(&padded));
            keep.push(padded);
        }
        gl.draw_arrays(GL_TRIANGLES, 0, 3);
    }
    drop(keep);
}

fn arrays_multi_draw_and_range(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let mut data = Vec::new();
    for k in 0..16 {
        data.extend(cell_triangle(k % 4, k / 4, 16.0, 1.0 - k as f32 / 15.0));
    }
    vbo(gl, GL_ARRAY_BUFFER, &f32_bytes(&data));
    gl.vertex_pointer(2, GL_FLOAT, 24, ClientPtr(0));
    gl.color_pointer(3, GL_FLOAT, 24, ClientPtr(8));
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.enable_client_state(GL_COLOR_ARRAY);
    // Cells 0-2 and 4 in one glMultiDrawArrays (a zero count in between).
    gl.multi_draw_arrays(GL_TRIANGLES, &[0, 3, 6, 9, 12], &[3, 3, 3, 0, 3], 5);
    // Cells 5, 6 and 8 through glMultiDrawElements with offsets into an element buffer.
    let idx: Vec<u8> = [15u16, 16, 17, 18, 19, 20, 24, 25, 26]
        .iter()
        .flat_map(|i| i.to_ne_bytes())
        .collect();
    vbo(gl, GL_ELEMENT_ARRAY_BUFFER, &idx);
    let offsets: Vec<usize> = vec![0, 6, 12];
    gl.multi_draw_elements(
        GL_TRIANGLES,
        &[3, 3, 3],
        GL_UNSIGNED_SHORT,
        addr(&offsets),
        3,
    );
    // Cells 9 and 10 with glDrawRangeElements.
    gl.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    let range: Vec<u32> = vec![27, 28, 29, 30, 31, 32];
    gl.draw_range_elements(GL_TRIANGLES, 27, 32, 6, GL_UNSIGNED_INT, addr(&range));
    // Cells 12-15 with glArrayElement between glBegin and glEnd, mixed with glColor.
    gl.begin(GL_TRIANGLES);
    for i in 36..48 {
        gl.array_element(i);
    }
    gl.end();
    gl.disable_client_state(GL_COLOR_ARRAY);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.begin(GL_LINES);
    gl.array_element(0);
    gl.array_element(47);
    gl.end();
}

fn arrays_buffer_updates(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let mut data = Vec::new();
    for k in 0..8 {
        data.extend(cell_triangle(k % 4, k / 4, 16.0, 0.3));
    }
    let b = vbo(gl, GL_ARRAY_BUFFER, &f32_bytes(&data));
    gl.vertex_pointer(2, GL_FLOAT, 24, ClientPtr(0));
    gl.color_pointer(4, GL_FLOAT, 24, ClientPtr(8));
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.enable_client_state(GL_COLOR_ARRAY);
    // Recolour the second vertex of every triangle with glBufferSubData.
    for k in 0..8 {
        let off = (k * 3 + 1) * 24 + 8;
        gl.buffer_sub_data(
            GL_ARRAY_BUFFER,
            off as isize,
            16,
            Some(&f32_bytes(&[1.0, 1.0, 1.0, 1.0])),
        );
    }
    gl.draw_arrays(GL_TRIANGLES, 0, 24);
    // Replace the store with triangles in the upper half (the pointers stay offsets).
    let mut upper = Vec::new();
    for k in 8..16 {
        upper.extend(cell_triangle(k % 4, k / 4, 16.0, 0.8));
    }
    gl.bind_buffer(GL_ARRAY_BUFFER, b);
    gl.buffer_data(
        GL_ARRAY_BUFFER,
        (upper.len() * 4) as isize,
        Some(&f32_bytes(&upper)),
        GL_DYNAMIC_DRAW,
    );
    gl.draw_arrays(GL_TRIANGLES, 0, 24);
    // Mapping and unmapping without writes keeps the contents.
    gl.map_buffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
    gl.unmap_buffer(GL_ARRAY_BUFFER);
    gl.draw_arrays(GL_LINE_LOOP, 0, 3);
}

// ---------------------------------------------------------------- display lists

fn lists_compile_and_execute(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let l = gl.gen_lists(1);
    gl.new_list(l, GL_COMPILE_AND_EXECUTE);
    gl.begin(GL_TRIANGLES);
    gl.color_3f(1.0, 0.2, 0.1);
    gl.vertex_2f(2.3, 2.2);
    gl.color_3f(0.1, 1.0, 0.2);
    gl.vertex_2f(28.6, 4.1);
    gl.color_3f(0.2, 0.3, 1.0);
    gl.vertex_2f(12.4, 27.3);
    gl.end();
    gl.translatef(30.0, 3.0, 0.0);
    gl.end_list();
    // The list left the modelview translated; calling it draws the next copy further on.
    gl.call_list(l);
    gl.call_list(l);
    // A GL_COMPILE list draws nothing until called.
    gl.load_identity();
    gl.new_list(l + 1, GL_COMPILE);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.rectf(40.0, 40.0, 60.0, 60.0);
    gl.end_list();
    gl.color_3f(0.5, 0.5, 0.0);
    gl.rectf(2.0, 40.0, 20.0, 60.0);
    gl.translatef(-15.0, 0.0, 0.0);
    gl.call_list(l + 1);
}

fn lists_nested_and_call_lists(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    // Leaves 1..=4: one coloured triangle each, then a move to the next cell.
    let base = gl.gen_lists(8);
    for k in 0..4 {
        gl.new_list(base + k, GL_COMPILE);
        gl.color_3f(k as f32 / 3.0, 1.0 - k as f32 / 3.0, 0.5);
        gl.begin(GL_TRIANGLES);
        gl.vertex_2f(1.3, 1.2);
        gl.vertex_2f(13.6, 2.4);
        gl.vertex_2f(6.2, 13.7);
        gl.end();
        gl.translatef(16.0, 0.0, 0.0);
        gl.end_list();
    }
    // A row: push, four leaves by glCallLists, pop, move up.
    gl.new_list(base + 4, GL_COMPILE);
    gl.push_matrix();
    gl.list_base(base);
    gl.call_lists(4, GL_UNSIGNED_BYTE, Some(&[0, 1, 2, 3]));
    gl.pop_matrix();
    gl.translatef(0.0, 16.0, 0.0);
    gl.end_list();
    // Nested: a list calling the row list twice.
    gl.new_list(base + 5, GL_COMPILE);
    gl.call_list(base + 4);
    gl.call_list(base + 4);
    gl.end_list();
    gl.call_list(base + 5);
    // Third row: names of other types with the base set outside the list.
    gl.list_base(base + 1);
    gl.push_matrix();
    gl.call_lists(2, GL_2_BYTES, Some(&[0, 2, 0, 0]));
    gl.call_lists(1, GL_INT, Some(&1i32.to_ne_bytes()));
    gl.call_lists(1, GL_FLOAT, Some(&(-1.0f32).to_ne_bytes()));
    gl.pop_matrix();
    gl.translatef(0.0, 16.0, 0.0);
    // Fourth row: signed bytes, 4-byte names, an undefined name skipped.
    gl.call_lists(3, GL_BYTE, Some(&[0xFF, 50, 2]));
    gl.call_lists(1, GL_4_BYTES, Some(&[0, 0, 0, 1]));
}

/// A glxgears-style gear: flat-shaded lit quad strips with material changes, compiled once.
fn gear(gl: &mut dyn Gl, inner: f32, outer: f32, teeth: usize) {
    let da = std::f32::consts::TAU / teeth as f32 / 4.0;
    gl.shade_model(GL_FLAT);
    gl.normal_3f(0.0, 0.0, 1.0);
    gl.begin(GL_QUAD_STRIP);
    for i in 0..=teeth {
        let a = i as f32 * std::f32::consts::TAU / teeth as f32;
        gl.vertex_3f(inner * a.cos(), inner * a.sin(), 0.5);
        gl.vertex_3f(outer * a.cos(), outer * a.sin(), 0.5);
        if i < teeth {
            gl.vertex_3f(inner * a.cos(), inner * a.sin(), 0.5);
            gl.vertex_3f(
                outer * (a + 3.0 * da).cos(),
                outer * (a + 3.0 * da).sin(),
                0.5,
            );
        }
    }
    gl.end();
    gl.begin(GL_QUADS);
    for i in 0..teeth {
        let a = i as f32 * std::f32::consts::TAU / teeth as f32;
        let r2 = outer + 0.6;
        gl.normal_3f(a.cos(), a.sin(), 0.3);
        gl.vertex_3f(outer * a.cos(), outer * a.sin(), 0.5);
        gl.vertex_3f(r2 * (a + da).cos(), r2 * (a + da).sin(), 0.5);
        gl.vertex_3f(r2 * (a + 2.0 * da).cos(), r2 * (a + 2.0 * da).sin(), 0.5);
        gl.vertex_3f(
            outer * (a + 3.0 * da).cos(),
            outer * (a + 3.0 * da).sin(),
            0.5,
        );
    }
    gl.end();
}

fn lists_state_changes(gl: &mut dyn Gl) {
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 5.0, 60.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -40.0);
    // The set-up itself in a list: lights, depth test, normalisation.
    let setup = gl.gen_lists(1);
    gl.new_list(setup, GL_COMPILE);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[5.0, 5.0, 10.0, 0.0]);
    gl.enable(GL_CULL_FACE);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_NORMALIZE);
    gl.end_list();
    let gears = gl.gen_lists(3);
    let colors = [
        [0.8, 0.1, 0.0, 1.0],
        [0.0, 0.8, 0.2, 1.0],
        [0.2, 0.2, 1.0, 1.0],
    ];
    for (k, c) in colors.iter().enumerate() {
        gl.new_list(gears + k as u32, GL_COMPILE);
        gl.materialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, c);
        gear(gl, 1.0 + k as f32 * 0.5, 4.0 - k as f32, 10 + 3 * k);
        gl.end_list();
    }
    gl.call_list(setup);
    for (k, (x, y, rot)) in [(-3.0, -2.0, 10.0), (3.1, -2.0, -19.0), (-3.1, 4.2, -30.0)]
        .into_iter()
        .enumerate()
    {
        gl.push_matrix();
        gl.translatef(x, y, 0.0);
        gl.rotatef(rot, 0.0, 0.0, 1.0);
        gl.call_list(gears + k as u32);
        gl.pop_matrix();
    }
}

fn lists_with_arrays(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let mut data = Vec::new();
    for k in 0..4 {
        data.extend(cell_triangle(k, 0, 16.0, 0.2 * k as f32));
    }
    vbo(gl, GL_ARRAY_BUFFER, &f32_bytes(&data));
    gl.vertex_pointer(2, GL_FLOAT, 24, ClientPtr(0));
    gl.color_pointer(4, GL_FLOAT, 24, ClientPtr(8));
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.enable_client_state(GL_COLOR_ARRAY);
    let l = gl.gen_lists(3);
    gl.new_list(l, GL_COMPILE);
    gl.draw_arrays(GL_TRIANGLES, 0, 6);
    gl.end_list();
    let idx: Vec<u8> = vec![6, 7, 8, 9, 10, 11];
    gl.new_list(l + 1, GL_COMPILE_AND_EXECUTE);
    gl.translatef(0.0, 16.0, 0.0);
    gl.draw_elements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, addr(&idx));
    gl.end_list();
    gl.new_list(l + 2, GL_COMPILE);
    gl.begin(GL_TRIANGLES);
    gl.array_element(3);
    gl.array_element(4);
    gl.array_element(5);
    gl.end();
    gl.end_list();
    // Overwrite the buffer and disable the arrays: the lists keep what they read.
    gl.buffer_data(GL_ARRAY_BUFFER, 8, None, GL_STATIC_DRAW);
    gl.disable_client_state(GL_VERTEX_ARRAY);
    gl.disable_client_state(GL_COLOR_ARRAY);
    gl.translatef(0.0, 16.0, 0.0);
    gl.call_list(l);
    gl.call_list(l + 1);
    gl.translatef(-20.0, 0.0, 0.0);
    gl.call_list(l + 2);
}

fn lists_nesting_limit(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    // List k draws a point, moves right by 0.9 and calls list k + 1: the number of points
    // drawn shows how deep execution nests (GL_MAX_LIST_NESTING, 64 on both).
    let base = gl.gen_lists(80);
    for k in 0..80 {
        gl.new_list(base + k, GL_COMPILE);
        gl.begin(GL_POINTS);
        gl.color_3f(1.0, (k % 7) as f32 / 6.0, 0.3);
        gl.vertex_2f(0.37, 10.3);
        gl.end();
        gl.translatef(0.9, 0.0, 0.0);
        gl.call_list(base + k + 1);
        gl.end_list();
    }
    gl.call_list(base);
    // A list that calls itself.
    gl.load_identity();
    gl.new_list(200, GL_COMPILE);
    gl.begin(GL_POINTS);
    gl.vertex_2f(0.37, 30.3);
    gl.end();
    gl.translatef(0.9, 0.0, 0.0);
    gl.call_list(200);
    gl.end_list();
    gl.color_3f(0.2, 1.0, 1.0);
    gl.call_list(200);
}

//! Vertex-array pointers, interleaved arrays, buffer objects, display lists and their errors,
//! answer by answer against Mesa, exactly.

use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::{ClientPtr, Gl};
// ---------------------------------------------------------------- queries and errors

type Answers = Vec<(String, Vec<i64>)>;

fn ints(gl: &mut dyn Gl, out: &mut Answers, pnames: &[GLenum]) {
    for &p in pnames {
        let mut v = [0x5a5a_5a5a; 1];
        gl.get_integerv(p, &mut v);
        out.push((format!("get_integerv(0x{p:04x})"), vec![v[0] as i64]));
    }
    err(gl, out, "queries");
}

fn err(gl: &mut dyn Gl, out: &mut Answers, label: &str) {
    let e = gl.get_error();
    out.push((format!("glGetError after {label}"), vec![e as i64]));
}

mod scripts {
    use super::*;

    const ARRAY_STATE: &[GLenum] = &[
        GL_VERTEX_ARRAY,
        GL_VERTEX_ARRAY_SIZE,
        GL_VERTEX_ARRAY_TYPE,
        GL_VERTEX_ARRAY_STRIDE,
        GL_VERTEX_ARRAY_BUFFER_BINDING,
        GL_NORMAL_ARRAY,
        GL_NORMAL_ARRAY_TYPE,
        GL_NORMAL_ARRAY_STRIDE,
        GL_NORMAL_ARRAY_BUFFER_BINDING,
        GL_COLOR_ARRAY,
        GL_COLOR_ARRAY_SIZE,
        GL_COLOR_ARRAY_TYPE,
        GL_COLOR_ARRAY_STRIDE,
        GL_COLOR_ARRAY_BUFFER_BINDING,
        GL_SECONDARY_COLOR_ARRAY,
        GL_SECONDARY_COLOR_ARRAY_SIZE,
        GL_SECONDARY_COLOR_ARRAY_TYPE,
        GL_SECONDARY_COLOR_ARRAY_STRIDE,
        GL_FOG_COORD_ARRAY,
        GL_FOG_COORD_ARRAY_TYPE,
        GL_FOG_COORD_ARRAY_STRIDE,
        GL_TEXTURE_COORD_ARRAY,
        GL_TEXTURE_COORD_ARRAY_SIZE,
        GL_TEXTURE_COORD_ARRAY_TYPE,
        GL_TEXTURE_COORD_ARRAY_STRIDE,
        GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING,
        GL_EDGE_FLAG_ARRAY,
        GL_EDGE_FLAG_ARRAY_STRIDE,
        GL_INDEX_ARRAY,
        GL_INDEX_ARRAY_TYPE,
        GL_INDEX_ARRAY_STRIDE,
        GL_INDEX_ARRAY_BUFFER_BINDING,
        GL_ARRAY_BUFFER_BINDING,
        GL_ELEMENT_ARRAY_BUFFER_BINDING,
        GL_CLIENT_ACTIVE_TEXTURE,
        GL_CLIENT_ATTRIB_STACK_DEPTH,
        GL_MAX_CLIENT_ATTRIB_STACK_DEPTH,
    ];

    pub fn pointer(gl: &mut dyn Gl, out: &mut Answers, pname: GLenum) {
        let mut p = 0usize;
        gl.get_pointerv(pname, ClientPtr(&mut p as *mut usize as usize));
        out.push((format!("get_pointerv(0x{pname:04x})"), vec![p as i64]));
    }

    pub fn state_array_pointers(gl: &mut dyn Gl, out: &mut Answers) {
        ints(gl, out, ARRAY_STATE);
        let mut b = [0u32; 2];
        gl.gen_buffers(2, &mut b);
        gl.bind_buffer(GL_ARRAY_BUFFER, b[0]);
        gl.vertex_pointer(3, GL_SHORT, 12, ClientPtr(4));
        gl.normal_pointer(GL_BYTE, 0, ClientPtr(8));
        gl.bind_buffer(GL_ARRAY_BUFFER, b[1]);
        gl.color_pointer(3, GL_UNSIGNED_INT, 20, ClientPtr(12));
        gl.secondary_color_pointer(3, GL_DOUBLE, 0, ClientPtr(16));
        gl.fog_coord_pointer(GL_DOUBLE, 8, ClientPtr(24));
        gl.client_active_texture(GL_TEXTURE1);
        gl.tex_coord_pointer(1, GL_INT, 4, ClientPtr(32));
        gl.edge_flag_pointer(2, ClientPtr(40));
        gl.index_pointer(GL_SHORT, 6, ClientPtr(48));
        gl.enable_client_state(GL_INDEX_ARRAY);
        for a in [
            GL_VERTEX_ARRAY,
            GL_NORMAL_ARRAY,
            GL_FOG_COORD_ARRAY,
            GL_TEXTURE_COORD_ARRAY,
        ] {
            gl.enable_client_state(a);
        }
        err(gl, out, "pointers");
        ints(gl, out, ARRAY_STATE);
        for p in [
            GL_VERTEX_ARRAY_POINTER,
            GL_NORMAL_ARRAY_POINTER,
            GL_COLOR_ARRAY_POINTER,
            GL_SECONDARY_COLOR_ARRAY_POINTER,
            GL_FOG_COORD_ARRAY_POINTER,
            GL_TEXTURE_COORD_ARRAY_POINTER,
            GL_EDGE_FLAG_ARRAY_POINTER,
            GL_INDEX_ARRAY_POINTER,
        ] {
            pointer(gl, out, p);
        }
        for e in [GL_VERTEX_ARRAY, GL_COLOR_ARRAY, GL_TEXTURE_COORD_ARRAY] {
            let v = gl.is_enabled(e);
            out.push((format!("is_enabled(0x{e:04x})"), vec![v as i64]));
        }
        // The client attribute stack restores all of it.
        gl.push_client_attrib(GL_CLIENT_VERTEX_ARRAY_BIT);
        gl.disable_client_state(GL_FOG_COORD_ARRAY); // see state_interleaved_arrays
        gl.interleaved_arrays(GL_T4F_C4F_N3F_V4F, 0, ClientPtr(64));
        ints(gl, out, ARRAY_STATE);
        gl.pop_client_attrib();
        ints(gl, out, ARRAY_STATE);
        gl.delete_buffers(1, &b[1..]);
        ints(gl, out, ARRAY_STATE);
    }

    pub fn state_interleaved_arrays(gl: &mut dyn Gl, out: &mut Answers) {
        let formats = [
            GL_V2F,
            GL_V3F,
            GL_C4UB_V2F,
            GL_C4UB_V3F,
            GL_C3F_V3F,
            GL_N3F_V3F,
            GL_C4F_N3F_V3F,
            GL_T2F_V3F,
            GL_T4F_V4F,
            GL_T2F_C4UB_V3F,
            GL_T2F_C3F_V3F,
            GL_T2F_N3F_V3F,
            GL_T2F_C4F_N3F_V3F,
            GL_T4F_C4F_N3F_V4F,
        ];
        let mut b = [0u32];
        gl.gen_buffers(1, &mut b);
        gl.bind_buffer(GL_ARRAY_BUFFER, b[0]);
        for (k, f) in formats.into_iter().enumerate() {
            // Only the edge-flag and index arrays are enabled beforehand: section 2.8 also
            // disables the secondary-colour and fog-coordinate arrays (tilegl,
            // tests/vertex_arrays.rs); Mesa leaves those enabled.
            gl.enable_client_state(GL_EDGE_FLAG_ARRAY);
            gl.enable_client_state(GL_INDEX_ARRAY);
            gl.interleaved_arrays(f, if k % 2 == 0 { 0 } else { 64 }, ClientPtr(1000));
            err(gl, out, "glInterleavedArrays");
            ints(gl, out, ARRAY_STATE);
            for p in [
                GL_VERTEX_ARRAY_POINTER,
                GL_NORMAL_ARRAY_POINTER,
                GL_COLOR_ARRAY_POINTER,
                GL_TEXTURE_COORD_ARRAY_POINTER,
            ] {
                pointer(gl, out, p);
            }
        }
    }

    pub fn state_buffer_objects(gl: &mut dyn Gl, out: &mut Answers) {
        let mut b = [0u32; 3];
        gl.gen_buffers(3, &mut b);
        let is = |gl: &mut dyn Gl, out: &mut Answers, n: u32| {
            let v = gl.is_buffer(n);
            out.push((format!("is_buffer({n})"), vec![v as i64]));
        };
        is(gl, out, b[0]);
        gl.bind_buffer(GL_ARRAY_BUFFER, b[0]);
        is(gl, out, b[0]);
        let params = |gl: &mut dyn Gl, out: &mut Answers, access: bool| {
            for p in [
                GL_BUFFER_SIZE,
                GL_BUFFER_USAGE,
                GL_BUFFER_ACCESS,
                GL_BUFFER_MAPPED,
            ] {
                if p == GL_BUFFER_ACCESS && !access {
                    continue;
                }
                let mut v = [-7];
                gl.get_buffer_parameteriv(GL_ARRAY_BUFFER, p, &mut v);
                out.push((
                    format!("get_buffer_parameteriv(0x{p:04x})"),
                    vec![v[0] as i64],
                ));
            }
            err(gl, out, "buffer parameters");
        };
        params(gl, out, true);
        let data: Vec<u8> = (0..64).collect();
        gl.buffer_data(GL_ARRAY_BUFFER, 64, Some(&data), GL_STREAM_COPY);
        params(gl, out, true);
        gl.buffer_sub_data(GL_ARRAY_BUFFER, 10, 4, Some(&[9, 8, 7, 6]));
        let mut back = [0u8; 16];
        gl.get_buffer_sub_data(GL_ARRAY_BUFFER, 4, 16, &mut back);
        out.push((
            "get_buffer_sub_data".into(),
            back.iter().map(|&x| x as i64).collect(),
        ));
        let p = gl.map_buffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
        out.push(("map_buffer non-null".into(), vec![(p.0 != 0) as i64]));
        params(gl, out, true);
        let mut q = 0usize;
        gl.get_buffer_pointerv(
            GL_ARRAY_BUFFER,
            GL_BUFFER_MAP_POINTER,
            ClientPtr(&mut q as *mut usize as usize),
        );
        out.push(("map pointer agrees".into(), vec![(q == p.0) as i64]));
        // Errors while mapped.
        gl.map_buffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
        err(gl, out, "second map");
        gl.buffer_sub_data(GL_ARRAY_BUFFER, 0, 1, Some(&[1]));
        err(gl, out, "sub data while mapped");
        let r = gl.unmap_buffer(GL_ARRAY_BUFFER);
        out.push(("unmap".into(), vec![r as i64]));
        let r = gl.unmap_buffer(GL_ARRAY_BUFFER);
        out.push(("unmap again".into(), vec![r as i64]));
        err(gl, out, "unmap again");
        // GL_BUFFER_ACCESS after glUnmapBuffer differs by version: GL 1.5 keeps the last
        // access (tilegl), GL 3.0 and later reset it (Mesa's 4.5 profile); ask the others.
        params(gl, out, false);
        // Range errors.
        gl.buffer_sub_data(GL_ARRAY_BUFFER, 60, 8, Some(&[0; 8]));
        err(gl, out, "sub data past the end");
        gl.get_buffer_sub_data(GL_ARRAY_BUFFER, -1, 2, &mut back[..2]);
        err(gl, out, "get sub data negative offset");
        gl.buffer_data(GL_ARRAY_BUFFER, -1, None, GL_STATIC_DRAW);
        err(gl, out, "negative size");
        gl.buffer_data(GL_ARRAY_BUFFER, 4, None, GL_RGBA);
        err(gl, out, "bad usage");
        gl.bind_buffer(GL_TEXTURE_2D, b[1]);
        err(gl, out, "bad target");
        gl.bind_buffer(GL_ARRAY_BUFFER, 0);
        gl.buffer_data(GL_ARRAY_BUFFER, 4, None, GL_STATIC_DRAW);
        err(gl, out, "buffer 0");
        gl.map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
        err(gl, out, "map buffer 0");
        // Deletion unbinds.
        gl.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, b[2]);
        gl.delete_buffers(3, &b);
        ints(
            gl,
            out,
            &[GL_ARRAY_BUFFER_BINDING, GL_ELEMENT_ARRAY_BUFFER_BINDING],
        );
        is(gl, out, b[2]);
    }

    pub fn errors_arrays(gl: &mut dyn Gl, out: &mut Answers) {
        gl.vertex_pointer(1, GL_FLOAT, 0, ClientPtr(0));
        err(gl, out, "vertex pointer size 1");
        gl.vertex_pointer(2, GL_UNSIGNED_BYTE, 0, ClientPtr(0));
        err(gl, out, "vertex pointer ubyte");
        gl.vertex_pointer(2, GL_FLOAT, -1, ClientPtr(0));
        err(gl, out, "vertex pointer stride");
        gl.normal_pointer(GL_UNSIGNED_SHORT, 0, ClientPtr(0));
        err(gl, out, "normal pointer ushort");
        gl.color_pointer(5, GL_FLOAT, 0, ClientPtr(0));
        err(gl, out, "color pointer size 5");
        // (Size 4 for glSecondaryColorPointer is left out: GL 1.5 allows only 3, tilegl
        // records INVALID_VALUE (tests/vertex_arrays.rs); Mesa accepts 4, a later extension.)
        gl.fog_coord_pointer(GL_SHORT, 0, ClientPtr(0));
        err(gl, out, "fog coord short");
        gl.tex_coord_pointer(0, GL_FLOAT, 0, ClientPtr(0));
        err(gl, out, "tex coord size 0");
        gl.index_pointer(GL_BYTE, 0, ClientPtr(0));
        err(gl, out, "index pointer byte");
        gl.edge_flag_pointer(-2, ClientPtr(0));
        err(gl, out, "edge flag stride");
        gl.interleaved_arrays(GL_RGB, 0, ClientPtr(0));
        err(gl, out, "interleaved format");
        gl.enable_client_state(GL_LIGHTING);
        err(gl, out, "enable client state");
        // (glEnable(GL_COLOR_ARRAY) is left out: GL 1.5 has no such capability, tilegl
        // records INVALID_ENUM; Mesa accepts it as a legacy glEnableClientState.)
        gl.draw_arrays(GL_QUADS + 10, 0, 0);
        err(gl, out, "draw arrays mode");
        gl.draw_arrays(GL_POINTS, 0, -1);
        err(gl, out, "draw arrays count");
        gl.draw_elements(GL_POINTS, 1, GL_SHORT, ClientPtr(0));
        err(gl, out, "draw elements type");
        gl.multi_draw_arrays(GL_QUADS + 100, &[0], &[3], 1);
        err(gl, out, "multi draw arrays mode");
        gl.multi_draw_arrays(GL_POINTS, &[0, 0], &[0, -1], 2);
        err(gl, out, "multi draw arrays negative count");
        gl.multi_draw_arrays(GL_POINTS, &[0], &[0], -1);
        err(gl, out, "multi draw arrays negative drawcount");
        let no_indices = [0usize];
        let ptrs = ClientPtr(no_indices.as_ptr() as usize);
        gl.multi_draw_elements(GL_POINTS, &[0], GL_FLOAT, ptrs, 1);
        err(gl, out, "multi draw elements type");
        gl.draw_range_elements(GL_POINTS, 3, 1, 0, GL_UNSIGNED_BYTE, ClientPtr(0));
        err(gl, out, "draw range end < start");
        gl.begin(GL_POINTS);
        gl.draw_arrays(GL_POINTS, 0, 0);
        gl.end();
        err(gl, out, "draw arrays inside begin");
        gl.pop_client_attrib();
        err(gl, out, "pop client attrib");
        // EXT_compiled_vertex_array.
        gl.lock_arrays_ext(0, 0);
        err(gl, out, "lock count 0");
        gl.lock_arrays_ext(2, 5);
        ints(
            gl,
            out,
            &[
                GL_ARRAY_ELEMENT_LOCK_FIRST_EXT,
                GL_ARRAY_ELEMENT_LOCK_COUNT_EXT,
            ],
        );
        gl.lock_arrays_ext(0, 1);
        err(gl, out, "lock twice");
        gl.unlock_arrays_ext();
        gl.unlock_arrays_ext();
        err(gl, out, "unlock twice");
        for _ in 0..17 {
            gl.push_client_attrib(GL_CLIENT_ALL_ATTRIB_BITS);
        }
        err(gl, out, "17 client attrib pushes");
    }

    pub fn state_lists(gl: &mut dyn Gl, out: &mut Answers) {
        const L: &[GLenum] = &[
            GL_LIST_BASE,
            GL_LIST_INDEX,
            GL_LIST_MODE,
            GL_MAX_LIST_NESTING,
        ];
        ints(gl, out, L);
        let a = gl.gen_lists(3);
        out.push(("gen_lists(3)".into(), vec![a as i64]));
        let z = gl.gen_lists(0);
        out.push(("gen_lists(0)".into(), vec![z as i64]));
        for n in [a, a + 2, a + 3, 0] {
            let v = gl.is_list(n);
            out.push((format!("is_list({n})"), vec![v as i64]));
        }
        gl.new_list(a + 1, GL_COMPILE_AND_EXECUTE);
        ints(gl, out, L);
        gl.new_list(a + 2, GL_COMPILE);
        err(gl, out, "nested new list");
        gl.list_base(7);
        gl.enable(0x1234);
        err(gl, out, "bad enum in compile-and-execute");
        gl.end_list();
        ints(gl, out, L);
        gl.new_list(a, GL_COMPILE);
        ints(gl, out, L);
        gl.list_base(9);
        gl.enable(0x1234);
        err(gl, out, "bad enum compiled");
        gl.end_list();
        ints(gl, out, L);
        gl.call_list(a);
        err(gl, out, "bad enum executed");
        ints(gl, out, L);
        gl.end_list();
        err(gl, out, "end list without new list");
        gl.new_list(0, GL_COMPILE);
        err(gl, out, "new list 0");
        gl.new_list(5, GL_RGBA);
        err(gl, out, "new list bad mode");
        gl.gen_lists(-1);
        err(gl, out, "gen lists -1");
        gl.delete_lists(a, -1);
        err(gl, out, "delete lists -1");
        gl.call_lists(-1, GL_BYTE, Some(&[]));
        err(gl, out, "call lists -1");
        gl.call_lists(1, GL_RGBA, Some(&[0, 0, 0, 0]));
        err(gl, out, "call lists bad type");
        gl.delete_lists(a, 2);
        for n in [a, a + 1, a + 2] {
            let v = gl.is_list(n);
            out.push((format!("is_list({n}) after delete"), vec![v as i64]));
        }
        // Names used at compile time are executed immediately (glGenLists inside a list).
        gl.new_list(100, GL_COMPILE);
        let g = gl.gen_lists(2);
        out.push(("gen_lists inside a list".into(), vec![g as i64]));
        let v = gl.is_list(g);
        out.push(("is_list inside a list".into(), vec![v as i64]));
        gl.end_list();
        err(gl, out, "end");
    }
}

use scripts::*;

super::state_case_list!(source = include_str!("arrays.rs"), agree = |a: &(String, Vec<i64>), b| a == b;
    state_array_pointers: "Section 2.8 and table 6.6: each gl*Pointer call sets its array's size, type and stride (0 stays 0) and buffer binding; the client attribute stack restores them.",
    state_interleaved_arrays: "Section 2.8: glInterleavedArrays enables exactly the arrays its format names (and disables the others of the list it covers), with the format's sizes, types and strides.",
    state_buffer_objects: "Section 2.9 (GL 1.5): buffer sizes, usage, access and mapped state read back; mapping twice, using a mapped buffer and bad ranges record errors; deleting a bound buffer unbinds it.",
    errors_arrays: "Sections 2.8 and 2.9: bad sizes, types, strides, modes and counts of the array commands record GL_INVALID_VALUE or GL_INVALID_ENUM and change nothing.",
    state_lists: "Section 5.4: glGenLists reserves consecutive names, glIsList is true once a list exists, glDeleteLists frees them; negative counts record GL_INVALID_VALUE, a bad type of glCallLists GL_INVALID_ENUM; glGenLists inside a list executes immediately.",
);

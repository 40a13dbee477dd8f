//! Vertex array and buffer object errors (OpenGL 1.5 sections 2.8 and 2.9), table-driven: every
//! bad call records the expected error and changes nothing else (the whole observable state
//! compared before and after).

mod common;

use common::state_fingerprint;
use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::{ClientPtr, Context, Gl};
type Call = fn(&mut Context);

fn error_cases() -> Vec<(&'static str, Call, Call, GLenum)> {
    fn none(_: &mut Context) {}
    fn bound(g: &mut Context) {
        let mut b = [0u32];
        g.gen_buffers(1, &mut b);
        g.bind_buffer(GL_ARRAY_BUFFER, b[0]);
        g.buffer_data(GL_ARRAY_BUFFER, 16, None, GL_STATIC_DRAW);
    }
    fn mapped_vertex_source(g: &mut Context) {
        bound(g);
        g.vertex_pointer(2, GL_FLOAT, 0, ClientPtr(0));
        g.enable_client_state(GL_VERTEX_ARRAY);
        g.map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
    }
    fn in_begin(g: &mut Context) {
        g.begin(GL_POINTS);
    }
    fn locked(g: &mut Context) {
        g.lock_arrays_ext(0, 4);
    }
    vec![
        (
            "indexPointer type byte",
            none,
            |g| g.index_pointer(GL_BYTE, 0, ClientPtr(0)),
            GL_INVALID_ENUM,
        ),
        (
            "indexPointer stride",
            none,
            |g| g.index_pointer(GL_FLOAT, -1, ClientPtr(0)),
            GL_INVALID_VALUE,
        ),
        (
            "multiDrawArrays mode",
            none,
            |g| g.multi_draw_arrays(GL_QUADS + 100, &[0], &[3], 1),
            GL_INVALID_ENUM,
        ),
        (
            "multiDrawArrays negative count",
            none,
            |g| g.multi_draw_arrays(GL_TRIANGLES, &[0, 0], &[3, -1], 2),
            GL_INVALID_VALUE,
        ),
        (
            "multiDrawElements type",
            none,
            |g| g.multi_draw_elements(GL_TRIANGLES, &[3], GL_FLOAT, ClientPtr(0), 1),
            GL_INVALID_ENUM,
        ),
        (
            "multiDrawElements negative count",
            none,
            |g| g.multi_draw_elements(GL_TRIANGLES, &[-3], GL_UNSIGNED_INT, ClientPtr(0), 1),
            GL_INVALID_VALUE,
        ),
        (
            "lockArraysEXT count 0",
            none,
            |g| g.lock_arrays_ext(0, 0),
            GL_INVALID_VALUE,
        ),
        (
            "lockArraysEXT first -1",
            none,
            |g| g.lock_arrays_ext(-1, 3),
            GL_INVALID_VALUE,
        ),
        (
            "lockArraysEXT twice",
            locked,
            |g| g.lock_arrays_ext(0, 4),
            GL_INVALID_OPERATION,
        ),
        (
            "unlockArraysEXT unlocked",
            none,
            |g| g.unlock_arrays_ext(),
            GL_INVALID_OPERATION,
        ),
        (
            "vertexPointer size 1",
            none,
            |g| g.vertex_pointer(1, GL_FLOAT, 0, ClientPtr(0)),
            GL_INVALID_VALUE,
        ),
        (
            "vertexPointer type byte",
            none,
            |g| g.vertex_pointer(3, GL_BYTE, 0, ClientPtr(0)),
            GL_INVALID_ENUM,
        ),
        (
            "vertexPointer stride -1",
            none,
            |g| g.vertex_pointer(3, GL_FLOAT, -1, ClientPtr(0)),
            GL_INVALID_VALUE,
        ),
        (
            "normalPointer type ubyte",
            none,
            |g| g.normal_pointer(GL_UNSIGNED_BYTE, 0, ClientPtr(0)),
            GL_INVALID_ENUM,
        ),
        (
            "normalPointer stride",
            none,
            |g| g.normal_pointer(GL_FLOAT, -4, ClientPtr(0)),
            GL_INVALID_VALUE,
        ),
        (
            "colorPointer size 2",
            none,
            |g| g.color_pointer(2, GL_FLOAT, 0, ClientPtr(0)),
            GL_INVALID_VALUE,
        ),
        (
            "colorPointer type",
            none,
            |g| g.color_pointer(4, GL_2_BYTES, 0, ClientPtr(0)),
            GL_INVALID_ENUM,
        ),
        (
            "secondaryColorPointer size 4",
            none,
            |g| g.secondary_color_pointer(4, GL_FLOAT, 0, ClientPtr(0)),
            GL_INVALID_VALUE,
        ),
        (
            "fogCoordPointer type int",
            none,
            |g| g.fog_coord_pointer(GL_INT, 0, ClientPtr(0)),
            GL_INVALID_ENUM,
        ),
        (
            "texCoordPointer size 5",
            none,
            |g| g.tex_coord_pointer(5, GL_FLOAT, 0, ClientPtr(0)),
            GL_INVALID_VALUE,
        ),
        (
            "texCoordPointer type ubyte",
            none,
            |g| g.tex_coord_pointer(2, GL_UNSIGNED_BYTE, 0, ClientPtr(0)),
            GL_INVALID_ENUM,
        ),
        (
            "edgeFlagPointer stride",
            none,
            |g| g.edge_flag_pointer(-1, ClientPtr(0)),
            GL_INVALID_VALUE,
        ),
        (
            "interleavedArrays format",
            none,
            |g| g.interleaved_arrays(GL_RGBA, 0, ClientPtr(0)),
            GL_INVALID_ENUM,
        ),
        (
            "interleavedArrays stride",
            none,
            |g| g.interleaved_arrays(GL_V3F, -1, ClientPtr(0)),
            GL_INVALID_VALUE,
        ),
        (
            "enableClientState bad",
            none,
            |g| g.enable_client_state(GL_DEPTH_TEST),
            GL_INVALID_ENUM,
        ),
        (
            "disableClientState bad",
            none,
            |g| g.disable_client_state(GL_INDEX_ARRAY + 1000),
            GL_INVALID_ENUM,
        ),
        (
            "drawArrays mode",
            none,
            |g| g.draw_arrays(GL_LINE, 0, 3),
            GL_INVALID_ENUM,
        ),
        (
            "drawArrays count",
            none,
            |g| g.draw_arrays(GL_TRIANGLES, 0, -1),
            GL_INVALID_VALUE,
        ),
        (
            "drawArrays in begin",
            in_begin,
            |g| g.draw_arrays(GL_TRIANGLES, 0, 3),
            GL_INVALID_OPERATION,
        ),
        (
            "drawElements type",
            none,
            |g| g.draw_elements(GL_TRIANGLES, 3, GL_INT, ClientPtr(0)),
            GL_INVALID_ENUM,
        ),
        (
            "drawElements count",
            none,
            |g| g.draw_elements(GL_TRIANGLES, -3, GL_UNSIGNED_INT, ClientPtr(0)),
            GL_INVALID_VALUE,
        ),
        (
            "drawElements mode",
            none,
            |g| g.draw_elements(99, 3, GL_UNSIGNED_INT, ClientPtr(0)),
            GL_INVALID_ENUM,
        ),
        (
            "drawRangeElements end < start",
            none,
            |g| g.draw_range_elements(GL_TRIANGLES, 5, 4, 3, GL_UNSIGNED_INT, ClientPtr(0)),
            GL_INVALID_VALUE,
        ),
        (
            "multiDrawArrays drawcount",
            none,
            |g| g.multi_draw_arrays(GL_TRIANGLES, &[], &[], -1),
            GL_INVALID_VALUE,
        ),
        (
            "draw from a mapped buffer",
            mapped_vertex_source,
            |g| g.draw_arrays(GL_TRIANGLES, 0, 3),
            GL_INVALID_OPERATION,
        ),
        (
            "genBuffers n",
            none,
            |g| g.gen_buffers(-1, &mut []),
            GL_INVALID_VALUE,
        ),
        (
            "deleteBuffers n",
            none,
            |g| g.delete_buffers(-1, &[]),
            GL_INVALID_VALUE,
        ),
        (
            "bindBuffer target",
            none,
            |g| g.bind_buffer(GL_TEXTURE_2D, 1),
            GL_INVALID_ENUM,
        ),
        (
            "bufferData target",
            bound,
            |g| g.buffer_data(GL_TEXTURE_2D, 4, None, GL_STATIC_DRAW),
            GL_INVALID_ENUM,
        ),
        (
            "bufferData size",
            bound,
            |g| g.buffer_data(GL_ARRAY_BUFFER, -4, None, GL_STATIC_DRAW),
            GL_INVALID_VALUE,
        ),
        (
            "bufferData usage",
            bound,
            |g| g.buffer_data(GL_ARRAY_BUFFER, 4, None, GL_STATIC_DRAW + 3),
            GL_INVALID_ENUM,
        ),
        (
            "bufferData no buffer",
            none,
            |g| g.buffer_data(GL_ARRAY_BUFFER, 4, None, GL_STATIC_DRAW),
            GL_INVALID_OPERATION,
        ),
        (
            "bufferData absurd size",
            bound,
            |g| g.buffer_data(GL_ARRAY_BUFFER, isize::MAX, None, GL_STATIC_DRAW),
            GL_OUT_OF_MEMORY,
        ),
        (
            "bufferSubData past end",
            bound,
            |g| g.buffer_sub_data(GL_ARRAY_BUFFER, 12, 8, Some(&[0; 8])),
            GL_INVALID_VALUE,
        ),
        (
            "bufferSubData negative offset",
            bound,
            |g| g.buffer_sub_data(GL_ARRAY_BUFFER, -1, 1, Some(&[0])),
            GL_INVALID_VALUE,
        ),
        (
            "bufferSubData mapped",
            |g| {
                bound(g);
                g.map_buffer(GL_ARRAY_BUFFER, GL_READ_WRITE);
            },
            |g| g.buffer_sub_data(GL_ARRAY_BUFFER, 0, 1, Some(&[0])),
            GL_INVALID_OPERATION,
        ),
        (
            "getBufferSubData past end",
            bound,
            |g| g.get_buffer_sub_data(GL_ARRAY_BUFFER, 0, 17, &mut [0; 17]),
            GL_INVALID_VALUE,
        ),
        (
            "getBufferSubData no buffer",
            none,
            |g| g.get_buffer_sub_data(GL_ARRAY_BUFFER, 0, 0, &mut []),
            GL_INVALID_OPERATION,
        ),
        (
            "mapBuffer access",
            bound,
            |g| {
                g.map_buffer(GL_ARRAY_BUFFER, GL_READ_ONLY + 7);
            },
            GL_INVALID_ENUM,
        ),
        (
            "mapBuffer twice",
            |g| {
                bound(g);
                g.map_buffer(GL_ARRAY_BUFFER, GL_READ_WRITE);
            },
            |g| {
                g.map_buffer(GL_ARRAY_BUFFER, GL_READ_WRITE);
            },
            GL_INVALID_OPERATION,
        ),
        (
            "mapBuffer no buffer",
            none,
            |g| {
                g.map_buffer(GL_ELEMENT_ARRAY_BUFFER, GL_READ_WRITE);
            },
            GL_INVALID_OPERATION,
        ),
        (
            "unmapBuffer not mapped",
            bound,
            |g| {
                g.unmap_buffer(GL_ARRAY_BUFFER);
            },
            GL_INVALID_OPERATION,
        ),
        (
            "getBufferParameteriv pname",
            bound,
            |g| g.get_buffer_parameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &mut [0]),
            GL_INVALID_ENUM,
        ),
        (
            "getBufferParameteriv no buffer",
            none,
            |g| g.get_buffer_parameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &mut [0]),
            GL_INVALID_OPERATION,
        ),
        (
            "getBufferPointerv pname",
            bound,
            |g| g.get_buffer_pointerv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, ClientPtr(0)),
            GL_INVALID_ENUM,
        ),
        (
            "getPointerv pname",
            none,
            |g| g.get_pointerv(GL_VERTEX_ARRAY_SIZE, ClientPtr(0)),
            GL_INVALID_ENUM,
        ),
        (
            "popClientAttrib empty",
            none,
            |g| g.pop_client_attrib(),
            GL_STACK_UNDERFLOW,
        ),
        (
            "pushClientAttrib overflow",
            |g| {
                for _ in 0..16 {
                    g.push_client_attrib(GL_CLIENT_ALL_ATTRIB_BITS);
                }
            },
            |g| g.push_client_attrib(GL_CLIENT_ALL_ATTRIB_BITS),
            GL_STACK_OVERFLOW,
        ),
        (
            "vertexPointer in begin",
            in_begin,
            |g| g.vertex_pointer(3, GL_FLOAT, 0, ClientPtr(0)),
            GL_INVALID_OPERATION,
        ),
    ]
}

#[test]
fn every_array_and_buffer_error_is_recorded_and_changes_nothing() {
    for (what, setup, call, expected) in error_cases() {
        let mut gl = client_context(8, 8);
        setup(&mut gl);
        assert_eq!(gl.get_error(), GL_NO_ERROR, "{what}: set-up failed");
        let inside = what.contains("in begin");
        let before = (!inside).then(|| state_fingerprint(&mut gl));
        call(&mut gl);
        if inside {
            // glGetError itself is illegal between glBegin and glEnd.
            gl.end();
        }
        assert_eq!(gl.get_error(), expected, "{what}");
        if let Some(before) = before {
            assert_eq!(state_fingerprint(&mut gl), before, "{what}: state changed");
        }
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

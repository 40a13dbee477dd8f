//! Hostile but memory-safe C input through the exported functions: calls with no current
//! context, after the current context was destroyed, `NULL` where GL expects memory, buffer
//! object offsets past the end of the buffer, `glCallLists` with huge counts, and `glBegin`/
//! `glEnd` split across display lists. Each must record the GL error the specification gives
//! or do nothing; none may crash or disturb later calls.

use std::ffi::c_void;

use tilegl::api::types::*;
use tilegl::capi::exports::*;
use tilegl::capi::osmesa::*;
use tilegl::enums::*;

/// A 32x32 RGBA context, current on this thread until dropped.
struct Current {
    ctx: *mut OsMesaContext,
    buffer: Vec<u8>,
}

impl Current {
    fn new() -> Current {
        let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, std::ptr::null_mut());
        assert!(!ctx.is_null());
        let mut c = Current {
            ctx,
            buffer: vec![0u8; 32 * 32 * 4],
        };
        c.bind();
        c
    }

    fn bind(&mut self) {
        // SAFETY: a live context and its 32x32 RGBA buffer, which lives as long as `self`.
        let ok = unsafe {
            OSMesaMakeCurrent(
                self.ctx,
                self.buffer.as_mut_ptr() as *mut c_void,
                GL_UNSIGNED_BYTE,
                32,
                32,
            )
        };
        assert_eq!(ok, GL_TRUE as GLboolean);
    }

    /// The red channel of pixel (x, y) after `glFinish`.
    fn red(&self, x: usize, y: usize) -> u8 {
        // SAFETY: the context is current; no arguments.
        unsafe { glFinish() };
        self.buffer[(y * 32 + x) * 4]
    }
}

impl Drop for Current {
    fn drop(&mut self) {
        // SAFETY: destroys the context made in `new` exactly once (also when current).
        unsafe { OSMesaDestroyContext(self.ctx) };
    }
}

fn error() -> GLenum {
    // SAFETY: no arguments.
    unsafe { glGetError() }
}

/// Every fixed-length entry point, then a few sized ones, with no current context: nothing
/// happens, queries answer zero, nothing crashes.
#[test]
fn calls_without_a_current_context_do_nothing() {
    let mut scratch = vec![0u8; 4096];
    for &(_, _, call) in FIXED_LENGTH_CALLS {
        // SAFETY: the buffer holds more than any fixed-length parameter.
        unsafe { call(scratch.as_mut_ptr()) };
    }
    // SAFETY: plain calls with valid or null pointers; without a context none touches memory.
    unsafe {
        assert_eq!(glGetError(), GL_NO_ERROR);
        assert!(glGetString(GL_VERSION).is_null());
        assert_eq!(glIsEnabled(GL_DEPTH_TEST), 0);
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as GLint,
            4,
            4,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            scratch.as_ptr() as *const c_void,
        );
        glReadPixels(
            0,
            0,
            4,
            4,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            scratch.as_mut_ptr() as *mut c_void,
        );
        glBegin(GL_TRIANGLES);
        glEnd();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glFinish();
    }
    assert!(
        scratch.iter().all(|&b| b == 0),
        "memory written without a context"
    );
}

/// A context destroyed while current is no longer current: later calls do nothing, and a new
/// context works normally.
#[test]
fn a_context_destroyed_while_current_leaves_no_current_context() {
    let c = Current::new();
    drop(c);
    assert!(OSMesaGetCurrentContext().is_null());
    // SAFETY: plain calls; no context is current.
    unsafe {
        glClearColor(1.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        assert!(glGetString(GL_RENDERER).is_null());
    }
    let c = Current::new();
    // SAFETY: plain calls on the new current context.
    unsafe {
        glClearColor(1.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    assert_eq!(c.red(3, 3), 255);
    assert_eq!(error(), GL_NO_ERROR);
}

/// `NULL` where GL reads or writes memory: no crash, no memory touched; the commands that
/// need their data record `GL_INVALID_VALUE` (what tilegl's API does for a missing buffer),
/// those given "no data" by GL (`glTexImage2D(.., NULL)`) succeed.
#[test]
fn null_pointers_where_gl_expects_memory() {
    let _c = Current::new();
    let null = std::ptr::null_mut::<u8>();
    // SAFETY: every pointer is NULL or valid; the calls are the hostile part.
    unsafe {
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as GLint,
            4,
            4,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            std::ptr::null(),
        );
        assert_eq!(error(), GL_NO_ERROR, "glTexImage2D with NULL is 'no data'");
        glTexSubImage2D(
            GL_TEXTURE_2D,
            0,
            0,
            0,
            2,
            2,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            std::ptr::null(),
        );
        assert_eq!(
            error(),
            GL_NO_ERROR,
            "glTexSubImage2D with NULL changes nothing"
        );
        glReadPixels(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, null as *mut c_void);
        assert_eq!(error(), GL_INVALID_VALUE);
        glGetTexImage(
            GL_TEXTURE_2D,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            null as *mut c_void,
        );
        assert_eq!(error(), GL_INVALID_VALUE);
        glRasterPos2i(0, 0);
        glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, std::ptr::null());
        assert_eq!(error(), GL_INVALID_VALUE);
        glBitmap(8, 8, 0.0, 0.0, 0.0, 0.0, std::ptr::null());
        assert_eq!(error(), GL_INVALID_VALUE);
        glGetIntegerv(GL_VIEWPORT, null as *mut GLint);
        glGetFloatv(GL_MODELVIEW_MATRIX, null as *mut GLfloat);
        glLightfv(GL_LIGHT0, GL_POSITION, std::ptr::null());
        glColor4fv(std::ptr::null());
        glLoadMatrixf(std::ptr::null());
        glGenTextures(3, null as *mut GLuint);
        glDeleteTextures(3, std::ptr::null());
        glCallLists(4, GL_UNSIGNED_BYTE, std::ptr::null());
        glPolygonStipple(std::ptr::null());
        glGetPolygonStipple(null);
        glSelectBuffer(16, null as *mut GLuint);
        glFeedbackBuffer(16, GL_2D, null as *mut GLfloat);
        glGetPointerv(GL_VERTEX_ARRAY_POINTER, std::ptr::null_mut());
        glVertexPointer(2, GL_FLOAT, 0, std::ptr::null());
        glEnableClientState(GL_VERTEX_ARRAY);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, std::ptr::null());
        glDisableClientState(GL_VERTEX_ARRAY);
        while glGetError() != GL_NO_ERROR {}
        // The context still works.
        glClearColor(0.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glColor3f(1.0, 0.0, 0.0);
        glRectf(-1.0, -1.0, 1.0, 1.0);
    }
    assert_eq!(_c.red(16, 16), 255);
    assert_eq!(error(), GL_NO_ERROR);
}

/// Vertex and index arrays in a buffer object whose offsets, or whose indices, reach past the
/// buffer's end: nothing outside the buffer is read (the draw records an error or draws
/// nothing) and the context keeps working.
#[test]
fn buffer_offsets_past_the_end() {
    let c = Current::new();
    let verts: [f32; 6] = [-1.0, -1.0, 3.0, -1.0, -1.0, 3.0];
    let indices: [u8; 3] = [0, 1, 200];
    // SAFETY: valid pointers to the arrays above; the offsets are the hostile part.
    unsafe {
        let mut names = [0u32; 2];
        glGenBuffers(2, names.as_mut_ptr());
        glBindBuffer(GL_ARRAY_BUFFER, names[0]);
        glBufferData(
            GL_ARRAY_BUFFER,
            24,
            verts.as_ptr() as *const c_void,
            GL_STATIC_DRAW,
        );
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, names[1]);
        glBufferData(
            GL_ELEMENT_ARRAY_BUFFER,
            3,
            indices.as_ptr() as *const c_void,
            GL_STATIC_DRAW,
        );
        glEnableClientState(GL_VERTEX_ARRAY);
        // An offset far past the 24-byte buffer.
        glVertexPointer(2, GL_FLOAT, 0, 1_000_000usize as *const c_void);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDrawArrays(GL_TRIANGLES, 0, i32::MAX);
        // In range, but the draw reads past the end.
        glVertexPointer(2, GL_FLOAT, 0, std::ptr::null());
        glDrawArrays(GL_TRIANGLES, 2, 3);
        // An index (200) past the end of the vertex buffer, and an index offset past the end
        // of the element buffer.
        glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, std::ptr::null());
        glDrawElements(
            GL_TRIANGLES,
            3,
            GL_UNSIGNED_BYTE,
            1000usize as *const c_void,
        );
        glDrawRangeElements(
            GL_TRIANGLES,
            0,
            2,
            3,
            GL_UNSIGNED_BYTE,
            2usize as *const c_void,
        );
        glBufferSubData(GL_ARRAY_BUFFER, 20, 8, verts.as_ptr() as *const c_void);
        assert_eq!(error(), GL_INVALID_VALUE, "glBufferSubData past the end");
        let mut back = [0u8; 8];
        glGetBufferSubData(
            GL_ARRAY_BUFFER,
            1 << 40,
            8,
            back.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(error(), GL_INVALID_VALUE, "glGetBufferSubData past the end");
        while glGetError() != GL_NO_ERROR {}
        // A draw in range still works.
        glClearColor(0.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glColor3f(1.0, 0.0, 0.0);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    assert_eq!(
        c.red(8, 8),
        255,
        "the in-range draw covers the window's lower left"
    );
    assert_eq!(error(), GL_NO_ERROR);
}

/// `glCallLists` over ten million names, none of them lists, and a list that calls itself:
/// quick no-ops (the nesting limit stops the recursion).
#[test]
fn call_lists_with_huge_counts_and_recursion() {
    let c = Current::new();
    let names = vec![7u8; 10_000_000];
    // SAFETY: `names` holds the 10^7 bytes the call reads.
    unsafe {
        glCallLists(
            10_000_000,
            GL_UNSIGNED_BYTE,
            names.as_ptr() as *const c_void,
        );
        glCallLists(-5, GL_UNSIGNED_BYTE, names.as_ptr() as *const c_void);
        assert_eq!(error(), GL_INVALID_VALUE, "negative count");
        glCallLists(3, 0x1234, names.as_ptr() as *const c_void);
        assert_eq!(error(), GL_INVALID_ENUM, "bad type");
        let list = glGenLists(1);
        glNewList(list, GL_COMPILE);
        glCallList(list);
        glEndList();
        glCallList(list);
        assert_eq!(error(), GL_NO_ERROR, "recursion stops at the nesting limit");
        glClearColor(1.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    assert_eq!(c.red(0, 0), 255);
}

/// `glBegin` in one display list, the vertices in another, `glEnd` in a third: legal, and
/// draws as the same calls made directly (section 5.4 records commands, not primitives); an
/// unmatched `glEnd`, and a list ended inside `glBegin`, record `GL_INVALID_OPERATION` when
/// executed and leave the context usable.
#[test]
fn begin_and_end_across_display_lists() {
    let c = Current::new();
    // SAFETY: plain calls on the current context.
    unsafe {
        let base = glGenLists(3);
        glNewList(base, GL_COMPILE);
        glColor3f(1.0, 0.0, 0.0);
        glBegin(GL_TRIANGLES);
        glEndList();
        glNewList(base + 1, GL_COMPILE);
        glVertex2f(-1.0, -1.0);
        glVertex2f(3.0, -1.0);
        glVertex2f(-1.0, 3.0);
        glEndList();
        glNewList(base + 2, GL_COMPILE);
        glEnd();
        glEndList();
        assert_eq!(error(), GL_NO_ERROR);
        glClearColor(0.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glCallList(base);
        glCallList(base + 1);
        glCallList(base + 2);
        assert_eq!(error(), GL_NO_ERROR);
        assert_eq!(c.red(4, 4), 255, "the split primitive was drawn");
        // glEnd alone, twice.
        glCallList(base + 2);
        assert_eq!(error(), GL_INVALID_OPERATION);
        glEnd();
        assert_eq!(error(), GL_INVALID_OPERATION);
        // glBegin left open by a list: commands not allowed inside Begin/End then fail, and
        // glEnd closes it.
        // (glGetError itself is illegal there and answers 0, so the error is read after glEnd.)
        glCallList(base);
        glClear(GL_COLOR_BUFFER_BIT);
        glEnd();
        assert_eq!(error(), GL_INVALID_OPERATION, "glClear inside glBegin");
        glClearColor(0.0, 1.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    assert_eq!(c.red(4, 4), 0);
    assert_eq!(error(), GL_NO_ERROR);
}

/// A context pointer handed to another thread, as a C program would.
#[derive(Clone, Copy)]
struct SendPtr(*mut OsMesaContext);
// SAFETY: only the pointer value crosses threads; every use goes through the OSMesa functions,
// whose rules (one thread at a time, deferred destruction) are what these tests check.
unsafe impl Send for SendPtr {}

/// A context is current on one thread at a time: another thread's `OSMesaMakeCurrent` of it
/// fails (it would race), and succeeds once the first thread lets it go.
#[test]
fn a_context_is_current_on_one_thread_at_a_time() {
    let mut c = Current::new();
    let ptr = SendPtr(c.ctx);
    let try_bind = move || {
        let p = ptr;
        let mut buf = vec![0u8; 32 * 32 * 4];
        // SAFETY: a live context; the buffer outlives the binding (released right after).
        unsafe {
            let ok = OSMesaMakeCurrent(
                p.0,
                buf.as_mut_ptr() as *mut c_void,
                GL_UNSIGNED_BYTE,
                32,
                32,
            );
            OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0);
            ok
        }
    };
    assert_eq!(
        std::thread::spawn(try_bind).join().unwrap(),
        GL_FALSE as GLboolean
    );
    // SAFETY: releases this thread's binding.
    unsafe { OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0) };
    assert_eq!(
        std::thread::spawn(try_bind).join().unwrap(),
        GL_TRUE as GLboolean
    );
    c.bind();
    assert_eq!(error(), GL_NO_ERROR);
}

/// A context destroyed by one thread while current on another keeps working there and is
/// freed when that thread lets it go (no use after free, no double free).
#[test]
fn destroying_a_context_current_on_another_thread_defers_the_free() {
    let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, std::ptr::null_mut());
    let ptr = SendPtr(ctx);
    let (bound_tx, bound_rx) = std::sync::mpsc::channel();
    let (destroyed_tx, destroyed_rx) = std::sync::mpsc::channel::<()>();
    let worker = std::thread::spawn(move || {
        let p = ptr;
        let mut buf = vec![0u8; 16 * 16 * 4];
        // SAFETY: a live context and a buffer that outlives the binding.
        unsafe {
            assert_eq!(
                OSMesaMakeCurrent(
                    p.0,
                    buf.as_mut_ptr() as *mut c_void,
                    GL_UNSIGNED_BYTE,
                    16,
                    16
                ),
                GL_TRUE as GLboolean
            );
        }
        bound_tx.send(()).unwrap();
        destroyed_rx.recv().unwrap();
        // Destroyed by the other thread meanwhile: still usable here.
        // SAFETY: plain calls on this thread's current context.
        unsafe {
            glClearColor(0.0, 1.0, 0.0, 1.0);
            glClear(GL_COLOR_BUFFER_BIT);
            glFinish();
            assert_eq!(glGetError(), GL_NO_ERROR);
            OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0);
        }
        buf[1]
    });
    bound_rx.recv().unwrap();
    // SAFETY: the context is live (current on the worker); the call is the hostile part.
    unsafe { OSMesaDestroyContext(ctx) };
    destroyed_tx.send(()).unwrap();
    assert_eq!(
        worker.join().unwrap(),
        255,
        "the worker drew green after the destroy"
    );
}

//! The audit of the C ABI's pointer lengths: for every exported entry point with a pointer
//! that GL sizes at call time, a valid call whose buffer is exactly as long as the
//! specification says (the lengths are worked out here by hand from the call's arguments and
//! the pixel-store state, section 3.6.4 / 4.3.2) raises no error and stays inside the buffer,
//! and the same call with the buffer one element short is caught by the debug build's bound
//! check instead of being read or written past its end.
//!
//! The calls go through the exported `extern "C"` functions themselves (the code
//! `libtilegl.so` exports) on an OSMesa context made with the exported OSMesa functions. The
//! buffers are parts of a larger allocation, so a length computed too long is counted by the
//! check, never a real out-of-bounds access.

use std::collections::BTreeSet;
use std::ffi::c_void;

use tilegl::api::types::*;
use tilegl::capi::exports::*;
use tilegl::capi::osmesa::*;
use tilegl::capi::{tilegl_debug_client_bound, tilegl_debug_client_overruns};
use tilegl::enums::*;

/// One audited pointer: the entry point, the parameter, the bytes a valid call uses, the size
/// of one element, the state the call needs and the call with the parameter at `p`.
struct Case {
    name: &'static str,
    param: &'static str,
    bytes: usize,
    elem: usize,
    /// The error the valid call gives (GL_NO_ERROR except where GL 1.5 has no valid call).
    error: GLenum,
    setup: unsafe fn(),
    call: unsafe fn(*mut u8),
}

unsafe fn no_setup() {}

/// A 64x64 RGBA context with depth, stencil and accumulation buffers, current on this thread.
struct Current {
    ctx: *mut OsMesaContext,
    _buffer: Vec<u8>,
}

impl Current {
    fn new() -> Current {
        let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, std::ptr::null_mut());
        assert!(!ctx.is_null());
        let mut buffer = vec![0u8; 64 * 64 * 4];
        // SAFETY: a live context and a 64x64 RGBA buffer that outlives it (dropped after).
        let ok = unsafe {
            OSMesaMakeCurrent(
                ctx,
                buffer.as_mut_ptr() as *mut c_void,
                GL_UNSIGNED_BYTE,
                64,
                64,
            )
        };
        assert_eq!(ok, GL_TRUE as GLboolean);
        Current {
            ctx,
            _buffer: buffer,
        }
    }
}

impl Drop for Current {
    fn drop(&mut self) {
        // SAFETY: unbinds, then destroys the context made in `new`, exactly once.
        unsafe {
            OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0);
            OSMesaDestroyContext(self.ctx);
        }
    }
}

/// Runs `case` with a declared buffer of `len` bytes; returns (error, overruns).
fn run(case: &Case, len: usize) -> (GLenum, usize) {
    let _current = Current::new();
    // 64 KiB of scratch; the audited buffer starts 4 KiB in, the rest is real memory, so a
    // length computed too long is caught by the bound, never a fault.
    // Zeros are valid contents for every audited call (the calls that need other values
    // write them into their buffer first).
    let mut scratch = vec![0u8; 1 << 16];
    let p = scratch[4096..].as_mut_ptr();
    // SAFETY: each setup and call makes valid GL calls on the current context; `p` points to
    // 60 KiB of writable memory, at least 8-byte aligned (4096 into a heap allocation).
    unsafe {
        (case.setup)();
        while glGetError() != GL_NO_ERROR {}
        assert_eq!(
            tilegl_debug_client_bound(p as *const c_void, len),
            1,
            "the client-buffer check is compiled into debug builds only: run the audit in the \
             test profile (debug assertions on)"
        );
        (case.call)(p);
        let overruns = tilegl_debug_client_overruns();
        tilegl_debug_client_bound(std::ptr::null(), 0);
        (glGetError(), overruns)
    }
}

// ------------------------------------------------------------------ set-ups

unsafe fn texture_2d_rgba_4x2() {
    let texels = [200u8; 4 * 2 * 4];
    glTexImage2D(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as GLint,
        4,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        texels.as_ptr() as *const c_void,
    );
}

/// One sampler object, named 1 (the first name of a new context).
unsafe fn one_sampler() {
    let mut s = 0;
    glGenSamplers(1, &mut s);
    assert_eq!(s, 1);
}

unsafe fn texture_1d_rgb_5() {
    glTexImage1D(
        GL_TEXTURE_1D,
        0,
        GL_RGB as GLint,
        8,
        0,
        GL_RGB,
        GL_UNSIGNED_BYTE,
        std::ptr::null(),
    );
}

unsafe fn texture_3d_4x4x2() {
    glTexImage3D(
        GL_TEXTURE_3D,
        0,
        GL_RGBA as GLint,
        4,
        4,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        std::ptr::null(),
    );
}

/// An 8x8 DXT1 level: 4 blocks of 8 bytes.
unsafe fn texture_dxt1_8x8() {
    let blocks = [0x55u8; 32];
    glCompressedTexImage2D(
        GL_TEXTURE_2D,
        0,
        GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
        8,
        8,
        0,
        32,
        blocks.as_ptr() as *const c_void,
    );
}

/// Unpack state with every mode away from its default.
unsafe fn odd_unpack() {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 5);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
}

unsafe fn odd_unpack_texture_2d() {
    texture_2d_rgba_4x2();
    odd_unpack();
}

unsafe fn odd_pack() {
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glPixelStorei(GL_PACK_ROW_LENGTH, 5);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_PACK_SKIP_ROWS, 2);
}

unsafe fn odd_pack_texture_2d() {
    texture_2d_rgba_4x2();
    odd_pack();
}

unsafe fn unpack_3d_images() {
    texture_3d_4x4x2();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 3);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
}

unsafe fn raster_pos() {
    glRasterPos2i(0, 0);
}

unsafe fn raster_pos_odd_unpack() {
    raster_pos();
    odd_unpack();
}

unsafe fn buffer_64() {
    let mut name = 0;
    glGenBuffers(1, &mut name);
    glBindBuffer(GL_ARRAY_BUFFER, name);
    glBufferData(GL_ARRAY_BUFFER, 64, std::ptr::null(), GL_STATIC_DRAW);
}

unsafe fn three_textures() {
    let names = [1u32, 2, 3];
    for n in names {
        glBindTexture(GL_TEXTURE_2D, n);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
}

unsafe fn three_lists() {
    for n in 1..=3 {
        glNewList(n, GL_COMPILE);
        glEndList();
    }
}

unsafe fn three_queries() {
    let mut ids = [0u32; 3];
    glGenQueries(3, ids.as_mut_ptr());
}

/// A bound framebuffer object with an RGBA8 renderbuffer (bound too) at its colour point.
unsafe fn framebuffer_with_renderbuffer() {
    glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, 1);
    glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_RGBA8, 2, 2);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 1);
    glFramebufferRenderbufferEXT(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_RENDERBUFFER_EXT,
        1,
    );
}

unsafe fn finished_query() {
    glBeginQuery(GL_SAMPLES_PASSED, 1);
    glEndQuery(GL_SAMPLES_PASSED);
}

unsafe fn maps() {
    let points = [0.5f32; 4 * 3 * 2];
    glMap1f(GL_MAP1_VERTEX_4, 0.0, 1.0, 4, 3, points.as_ptr());
    glMap2f(
        GL_MAP2_VERTEX_3,
        0.0,
        1.0,
        3,
        2,
        0.0,
        1.0,
        6,
        2,
        points.as_ptr(),
    );
}

unsafe fn pixel_map_of_5() {
    let v = [0.25f32; 5];
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 5, v.as_ptr());
}

unsafe fn vertex_array() {
    static VERTS: [f32; 12] = [0.0; 12];
    glVertexPointer(2, GL_FLOAT, 0, VERTS.as_ptr() as *const c_void);
    glEnableClientState(GL_VERTEX_ARRAY);
}

macro_rules! case {
    ($name:literal, $param:literal, $bytes:expr, $elem:expr, $setup:expr, |$p:ident| $call:expr) => {
        Case {
            name: $name,
            param: $param,
            bytes: $bytes,
            elem: $elem,
            error: GL_NO_ERROR,
            setup: $setup,
            call: |$p| unsafe {
                let _ = $call;
            },
        }
    };
}

/// The cases, with each length worked out by hand.
fn cases() -> Vec<Case> {
    const F: usize = 4; // GLfloat, GLint, GLuint
    const D: usize = 8; // GLdouble
    let mut v = vec![
        // glTexImage2D 3x2 RGB bytes, alignment 4: rows of 9 bytes padded to 12; 12 + 9.
        case!("glTexImage2D", "pixels", 21, 1, no_setup, |p| glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGB as GLint,
            3,
            2,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            p as *const c_void
        )),
        // 1D, 8 RGBA shorts: 8 * 8 bytes.
        case!("glTexImage1D", "pixels", 64, 1, no_setup, |p| glTexImage1D(
            GL_TEXTURE_1D,
            0,
            GL_RGBA as GLint,
            8,
            0,
            GL_RGBA,
            GL_UNSIGNED_SHORT,
            p as *const c_void
        )),
        // 3D 2x2x2 luminance floats, alignment 4: 8-byte rows, 16-byte images: 16 + 8 + 8.
        case!("glTexImage3D", "pixels", 32, 1, no_setup, |p| glTexImage3D(
            GL_TEXTURE_3D,
            0,
            GL_LUMINANCE as GLint,
            2,
            2,
            2,
            0,
            GL_LUMINANCE,
            GL_FLOAT,
            p as *const c_void
        )),
        // Sub-image 2x2 of RGBA 4444 (2-byte groups) under odd unpack: row 5*2 = 10 padded to
        // 16; start 2 rows + 1 group = 34; end 34 + 16 + 2*2 = 54.
        case!(
            "glTexSubImage2D",
            "pixels",
            54,
            1,
            odd_unpack_texture_2d,
            |p| glTexSubImage2D(
                GL_TEXTURE_2D,
                0,
                1,
                0,
                2,
                2,
                GL_RGBA,
                GL_UNSIGNED_SHORT_4_4_4_4,
                p as *const c_void
            )
        ),
        // 1D sub-image of 3 RGB bytes: 9 bytes.
        case!("glTexSubImage1D", "pixels", 9, 1, texture_1d_rgb_5, |p| {
            glTexSubImage1D(
                GL_TEXTURE_1D,
                0,
                2,
                3,
                GL_RGB,
                GL_UNSIGNED_BYTE,
                p as *const c_void,
            )
        }),
        // 3D sub-image 2x2x2 RGBA bytes, alignment 1, image height 3, skip 1 image: row 8,
        // image 24; start 24; end 24 + 24 + 8 + 8 = 64.
        case!("glTexSubImage3D", "pixels", 64, 1, unpack_3d_images, |p| {
            glTexSubImage3D(
                GL_TEXTURE_3D,
                0,
                0,
                0,
                0,
                2,
                2,
                2,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                p as *const c_void,
            )
        }),
        // DrawPixels 3x2 RGBA floats: 48-byte rows: 96.
        case!("glDrawPixels", "pixels", 96, 1, raster_pos, |p| {
            glDrawPixels(3, 2, GL_RGBA, GL_FLOAT, p as *const c_void)
        }),
        // DrawPixels of stencil indices as bits, 10x2 under odd unpack (row 5 bits -> 1 byte,
        // padded to 8; skip 2 rows = 16; last row: bits 1..11 -> 2 bytes): 16 + 8 + 2 = 26.
        // Width 10 with row length 5 reads past each row into the next, as GL defines.
        case!(
            "glDrawPixels",
            "pixels",
            26,
            1,
            raster_pos_odd_unpack,
            |p| glDrawPixels(10, 2, GL_STENCIL_INDEX, GL_BITMAP, p as *const c_void)
        ),
        // DrawPixels depth as unsigned ints, 2x2: 16 bytes.
        case!("glDrawPixels", "pixels", 16, 1, raster_pos, |p| {
            glDrawPixels(
                2,
                2,
                GL_DEPTH_COMPONENT,
                GL_UNSIGNED_INT,
                p as *const c_void,
            )
        }),
        // DrawPixels depth-stencil words (EXT_packed_depth_stencil), 3x2: 24 bytes.
        case!("glDrawPixels", "pixels", 24, 1, raster_pos, |p| {
            glDrawPixels(
                3,
                2,
                GL_DEPTH_STENCIL_EXT,
                GL_UNSIGNED_INT_24_8_EXT,
                p as *const c_void,
            )
        }),
        // Bitmap 12x3, alignment 4: 2-byte rows padded to 4: 4 + 4 + 2.
        case!("glBitmap", "bitmap", 10, 1, raster_pos, |p| glBitmap(
            12,
            3,
            0.0,
            0.0,
            1.0,
            0.0,
            p as *const GLubyte
        )),
        // ReadPixels 3x2 RGB bytes, alignment 4: 12 + 9.
        case!("glReadPixels", "pixels", 21, 1, no_setup, |p| glReadPixels(
            0,
            0,
            3,
            2,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            p as *mut c_void
        )),
        // ReadPixels 2x2 of a packed type (4 bytes a pixel) under odd pack: row 20 -> 24;
        // start 48 + 4; end 52 + 24 + 8 = 84.
        case!("glReadPixels", "pixels", 84, 1, odd_pack, |p| glReadPixels(
            0,
            0,
            2,
            2,
            GL_BGRA,
            GL_UNSIGNED_INT_8_8_8_8_REV,
            p as *mut c_void
        )),
        // ReadPixels 2x2 depth-stencil words under odd pack, as the packed type above: 84.
        case!("glReadPixels", "pixels", 84, 1, odd_pack, |p| glReadPixels(
            0,
            0,
            2,
            2,
            GL_DEPTH_STENCIL_EXT,
            GL_UNSIGNED_INT_24_8_EXT,
            p as *mut c_void
        )),
        // GetTexImage of the 4x2 RGBA level as floats under odd pack: group 16, row 5*16 = 80
        // (aligned); start 160 + 16; end 176 + 80 + 64 = 320.
        case!(
            "glGetTexImage",
            "pixels",
            320,
            1,
            odd_pack_texture_2d,
            |p| glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, p as *mut c_void)
        ),
        // The 8x8 DXT1 level's blocks: 32 bytes.
        case!(
            "glGetCompressedTexImage",
            "img",
            32,
            1,
            texture_dxt1_8x8,
            |p| glGetCompressedTexImage(GL_TEXTURE_2D, 0, p as *mut c_void)
        ),
        case!("glCompressedTexImage2D", "data", 32, 1, no_setup, |p| {
            glCompressedTexImage2D(
                GL_TEXTURE_2D,
                0,
                GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
                8,
                8,
                0,
                32,
                p as *const c_void,
            )
        }),
        // A 4x4 DXT1 sub-region: one 8-byte block.
        case!(
            "glCompressedTexSubImage2D",
            "data",
            8,
            1,
            texture_dxt1_8x8,
            |p| glCompressedTexSubImage2D(
                GL_TEXTURE_2D,
                0,
                4,
                4,
                4,
                4,
                GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
                8,
                p as *const c_void
            )
        ),
        case!("glBufferData", "data", 24, 1, buffer_64, |p| glBufferData(
            GL_ARRAY_BUFFER,
            24,
            p as *const c_void,
            GL_STATIC_DRAW
        )),
        case!("glBufferSubData", "data", 24, 1, buffer_64, |p| {
            glBufferSubData(GL_ARRAY_BUFFER, 8, 24, p as *const c_void)
        }),
        case!("glGetBufferSubData", "data", 24, 1, buffer_64, |p| {
            glGetBufferSubData(GL_ARRAY_BUFFER, 8, 24, p as *mut c_void)
        }),
        // CallLists of 3 names as GL_2_BYTES (2 bytes each), then as shorts and ints.
        case!("glCallLists", "lists", 6, 1, three_lists, |p| glCallLists(
            3,
            GL_2_BYTES,
            p as *const c_void
        )),
        case!("glCallLists", "lists", 12, 1, three_lists, |p| glCallLists(
            3,
            GL_UNSIGNED_INT,
            p as *const c_void
        )),
        case!("glCallLists", "lists", 9, 1, three_lists, |p| glCallLists(
            3,
            GL_3_BYTES,
            p as *const c_void
        )),
        case!("glGenTextures", "textures", 3 * F, F, no_setup, |p| {
            glGenTextures(3, p as *mut GLuint)
        }),
        case!("glDeleteTextures", "textures", 3 * F, F, no_setup, |p| {
            glDeleteTextures(3, p as *const GLuint)
        }),
        case!(
            "glGenFramebuffersEXT",
            "framebuffers",
            3 * F,
            F,
            no_setup,
            |p| { glGenFramebuffersEXT(3, p as *mut GLuint) }
        ),
        case!(
            "glDeleteFramebuffersEXT",
            "framebuffers",
            3 * F,
            F,
            no_setup,
            |p| { glDeleteFramebuffersEXT(3, p as *const GLuint) }
        ),
        case!(
            "glGenRenderbuffersEXT",
            "renderbuffers",
            3 * F,
            F,
            no_setup,
            |p| { glGenRenderbuffersEXT(3, p as *mut GLuint) }
        ),
        case!(
            "glDeleteRenderbuffersEXT",
            "renderbuffers",
            3 * F,
            F,
            no_setup,
            |p| { glDeleteRenderbuffersEXT(3, p as *const GLuint) }
        ),
        case!(
            "glGetRenderbufferParameterivEXT",
            "params",
            F,
            F,
            framebuffer_with_renderbuffer,
            |p| glGetRenderbufferParameterivEXT(
                GL_RENDERBUFFER_EXT,
                GL_RENDERBUFFER_WIDTH_EXT,
                p as *mut GLint
            )
        ),
        case!(
            "glGetFramebufferAttachmentParameterivEXT",
            "params",
            F,
            F,
            framebuffer_with_renderbuffer,
            |p| glGetFramebufferAttachmentParameterivEXT(
                GL_FRAMEBUFFER_EXT,
                GL_COLOR_ATTACHMENT0_EXT,
                GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT,
                p as *mut GLint
            )
        ),
        case!("glGenBuffers", "buffers", 3 * F, F, no_setup, |p| {
            glGenBuffers(3, p as *mut GLuint)
        }),
        case!("glDeleteBuffers", "buffers", 3 * F, F, no_setup, |p| {
            glDeleteBuffers(3, p as *const GLuint)
        }),
        case!("glGenQueries", "ids", 3 * F, F, no_setup, |p| glGenQueries(
            3,
            p as *mut GLuint
        )),
        case!("glDeleteQueries", "ids", 3 * F, F, three_queries, |p| {
            glDeleteQueries(3, p as *const GLuint)
        }),
        case!(
            "glAreTexturesResident",
            "textures",
            3 * F,
            F,
            three_textures,
            |p| {
                let mut r = [0u8; 3];
                *(p as *mut [GLuint; 3]) = [1, 2, 3];
                glAreTexturesResident(3, p as *const GLuint, r.as_mut_ptr())
            }
        ),
        case!(
            "glAreTexturesResident",
            "residences",
            3,
            1,
            three_textures,
            |p| {
                let t = [1u32, 2, 3];
                glAreTexturesResident(3, t.as_ptr(), p as *mut GLboolean)
            }
        ),
        case!(
            "glPrioritizeTextures",
            "textures",
            3 * F,
            F,
            three_textures,
            |p| {
                let q = [0.5f32; 3];
                glPrioritizeTextures(3, p as *const GLuint, q.as_ptr())
            }
        ),
        case!(
            "glPrioritizeTextures",
            "priorities",
            3 * F,
            F,
            three_textures,
            |p| {
                let t = [1u32, 2, 3];
                glPrioritizeTextures(3, t.as_ptr(), p as *const GLfloat)
            }
        ),
        // Queries: the values each pname has (table 6.x).
        case!("glGetIntegerv", "data", 4 * F, F, no_setup, |p| {
            glGetIntegerv(GL_VIEWPORT, p as *mut GLint)
        }),
        case!("glGetIntegerv", "data", F, F, no_setup, |p| glGetIntegerv(
            GL_MAX_LIGHTS,
            p as *mut GLint
        )),
        case!("glGetFloatv", "data", 16 * F, F, no_setup, |p| glGetFloatv(
            GL_MODELVIEW_MATRIX,
            p as *mut GLfloat
        )),
        case!("glGetFloatv", "data", 2 * F, F, no_setup, |p| glGetFloatv(
            GL_DEPTH_RANGE,
            p as *mut GLfloat
        )),
        case!(
            "glGetDoublev",
            "data",
            4 * D,
            D,
            no_setup,
            |p| glGetDoublev(GL_CURRENT_COLOR, p as *mut GLdouble)
        ),
        case!("glGetBooleanv", "data", 4, 1, no_setup, |p| glGetBooleanv(
            GL_COLOR_WRITEMASK,
            p as *mut GLboolean
        )),
        case!("glGetBufferParameteriv", "params", F, F, buffer_64, |p| {
            glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, p as *mut GLint)
        }),
        case!("glGetQueryiv", "params", F, F, no_setup, |p| glGetQueryiv(
            GL_SAMPLES_PASSED,
            GL_QUERY_COUNTER_BITS,
            p as *mut GLint
        )),
        case!("glGetQueryObjectiv", "params", F, F, finished_query, |p| {
            glGetQueryObjectiv(1, GL_QUERY_RESULT, p as *mut GLint)
        }),
        case!("glGetQueryObjectuiv", "params", F, F, finished_query, |p| {
            glGetQueryObjectuiv(1, GL_QUERY_RESULT_AVAILABLE, p as *mut GLuint)
        }),
        case!("glLightfv", "params", 4 * F, F, no_setup, |p| glLightfv(
            GL_LIGHT0,
            GL_POSITION,
            p as *const GLfloat
        )),
        case!("glLightfv", "params", 3 * F, F, no_setup, |p| glLightfv(
            GL_LIGHT0,
            GL_SPOT_DIRECTION,
            p as *const GLfloat
        )),
        case!("glLightiv", "params", F, F, no_setup, |p| glLightiv(
            GL_LIGHT1,
            GL_SPOT_EXPONENT,
            p as *const GLint
        )),
        case!("glGetLightfv", "params", 4 * F, F, no_setup, |p| {
            glGetLightfv(GL_LIGHT0, GL_DIFFUSE, p as *mut GLfloat)
        }),
        case!("glGetLightiv", "params", 3 * F, F, no_setup, |p| {
            glGetLightiv(GL_LIGHT0, GL_SPOT_DIRECTION, p as *mut GLint)
        }),
        case!("glLightModelfv", "params", 4 * F, F, no_setup, |p| {
            glLightModelfv(GL_LIGHT_MODEL_AMBIENT, p as *const GLfloat)
        }),
        case!("glLightModeliv", "params", F, F, no_setup, |p| {
            glLightModeliv(GL_LIGHT_MODEL_TWO_SIDE, p as *const GLint)
        }),
        case!("glMaterialfv", "params", 4 * F, F, no_setup, |p| {
            glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, p as *const GLfloat)
        }),
        case!("glMaterialfv", "params", 3 * F, F, no_setup, |p| {
            glMaterialfv(GL_FRONT, GL_COLOR_INDEXES, p as *const GLfloat)
        }),
        case!("glMaterialiv", "params", F, F, no_setup, |p| glMaterialiv(
            GL_BACK,
            GL_SHININESS,
            p as *const GLint
        )),
        case!("glGetMaterialfv", "params", 4 * F, F, no_setup, |p| {
            glGetMaterialfv(GL_FRONT, GL_EMISSION, p as *mut GLfloat)
        }),
        case!("glGetMaterialiv", "params", F, F, no_setup, |p| {
            glGetMaterialiv(GL_FRONT, GL_SHININESS, p as *mut GLint)
        }),
        case!("glFogfv", "params", 4 * F, F, no_setup, |p| glFogfv(
            GL_FOG_COLOR,
            p as *const GLfloat
        )),
        case!("glFogiv", "params", F, F, no_setup, |p| glFogiv(
            GL_FOG_START,
            p as *const GLint
        )),
        case!("glTexEnvfv", "params", 4 * F, F, no_setup, |p| glTexEnvfv(
            GL_TEXTURE_ENV,
            GL_TEXTURE_ENV_COLOR,
            p as *const GLfloat
        )),
        case!("glTexEnviv", "params", F, F, no_setup, |p| {
            *(p as *mut GLint) = GL_ADD as GLint;
            glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, p as *const GLint)
        }),
        case!("glGetTexEnvfv", "params", 4 * F, F, no_setup, |p| {
            glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, p as *mut GLfloat)
        }),
        case!(
            "glGetTexEnviv",
            "params",
            F,
            F,
            no_setup,
            |p| glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, p as *mut GLint)
        ),
        case!("glTexGenfv", "params", 4 * F, F, no_setup, |p| glTexGenfv(
            GL_S,
            GL_OBJECT_PLANE,
            p as *const GLfloat
        )),
        case!("glTexGendv", "params", 4 * D, D, no_setup, |p| glTexGendv(
            GL_T,
            GL_EYE_PLANE,
            p as *const GLdouble
        )),
        case!("glTexGeniv", "params", F, F, no_setup, |p| {
            *(p as *mut GLint) = GL_SPHERE_MAP as GLint;
            glTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, p as *const GLint)
        }),
        case!("glGetTexGenfv", "params", 4 * F, F, no_setup, |p| {
            glGetTexGenfv(GL_S, GL_EYE_PLANE, p as *mut GLfloat)
        }),
        case!("glGetTexGendv", "params", 4 * D, D, no_setup, |p| {
            glGetTexGendv(GL_R, GL_OBJECT_PLANE, p as *mut GLdouble)
        }),
        case!(
            "glGetTexGeniv",
            "params",
            F,
            F,
            no_setup,
            |p| glGetTexGeniv(GL_Q, GL_TEXTURE_GEN_MODE, p as *mut GLint)
        ),
        case!("glTexParameterfv", "params", 4 * F, F, no_setup, |p| {
            glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, p as *const GLfloat)
        }),
        case!("glTexParameteriv", "params", F, F, no_setup, |p| {
            *(p as *mut GLint) = GL_CLAMP as GLint;
            glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, p as *const GLint)
        }),
        // EXT_texture_swizzle's RGBA parameter is four values too.
        case!("glTexParameteriv", "params", 4 * F, F, no_setup, |p| {
            let swizzle = [GL_BLUE, GL_RED, GL_GREEN, GL_ALPHA].map(|e| e as GLint);
            std::ptr::copy_nonoverlapping(swizzle.as_ptr(), p as *mut GLint, 4);
            glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, p as *const GLint)
        }),
        case!("glGetTexParameteriv", "params", 4 * F, F, no_setup, |p| {
            glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, p as *mut GLint)
        }),
        case!("glGetTexParameterfv", "params", 4 * F, F, no_setup, |p| {
            glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, p as *mut GLfloat)
        }),
        case!("glGetTexParameteriv", "params", F, F, no_setup, |p| {
            glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, p as *mut GLint)
        }),
        // ARB_sampler_objects: sampler 1 (made by `one_sampler`); the border colour is four
        // values, the others one.
        case!("glGenSamplers", "samplers", 3 * F, F, no_setup, |p| {
            glGenSamplers(3, p as *mut GLuint)
        }),
        case!("glDeleteSamplers", "samplers", 3 * F, F, no_setup, |p| {
            glDeleteSamplers(3, p as *const GLuint)
        }),
        case!("glSamplerParameteriv", "param", F, F, one_sampler, |p| {
            *(p as *mut GLint) = GL_CLAMP as GLint;
            glSamplerParameteriv(1, GL_TEXTURE_WRAP_S, p as *const GLint)
        }),
        case!(
            "glSamplerParameterfv",
            "param",
            4 * F,
            F,
            one_sampler,
            |p| { glSamplerParameterfv(1, GL_TEXTURE_BORDER_COLOR, p as *const GLfloat) }
        ),
        case!(
            "glSamplerParameterIiv",
            "param",
            4 * F,
            F,
            one_sampler,
            |p| { glSamplerParameterIiv(1, GL_TEXTURE_BORDER_COLOR, p as *const GLint) }
        ),
        case!("glSamplerParameterIuiv", "param", F, F, one_sampler, |p| {
            *(p as *mut GLuint) = GL_NEAREST;
            glSamplerParameterIuiv(1, GL_TEXTURE_MAG_FILTER, p as *const GLuint)
        }),
        case!(
            "glGetSamplerParameteriv",
            "params",
            4 * F,
            F,
            one_sampler,
            |p| { glGetSamplerParameteriv(1, GL_TEXTURE_BORDER_COLOR, p as *mut GLint) }
        ),
        case!(
            "glGetSamplerParameterfv",
            "params",
            F,
            F,
            one_sampler,
            |p| { glGetSamplerParameterfv(1, GL_TEXTURE_MIN_LOD, p as *mut GLfloat) }
        ),
        case!(
            "glGetSamplerParameterIiv",
            "params",
            F,
            F,
            one_sampler,
            |p| { glGetSamplerParameterIiv(1, GL_TEXTURE_WRAP_T, p as *mut GLint) }
        ),
        case!(
            "glGetSamplerParameterIuiv",
            "params",
            4 * F,
            F,
            one_sampler,
            |p| { glGetSamplerParameterIuiv(1, GL_TEXTURE_BORDER_COLOR, p as *mut GLuint) }
        ),
        case!(
            "glGetTexLevelParameterfv",
            "params",
            F,
            F,
            texture_2d_rgba_4x2,
            |p| glGetTexLevelParameterfv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, p as *mut GLfloat)
        ),
        case!(
            "glGetTexLevelParameteriv",
            "params",
            F,
            F,
            texture_2d_rgba_4x2,
            |p| glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, p as *mut GLint)
        ),
        case!("glPointParameterfv", "params", 3 * F, F, no_setup, |p| {
            glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, p as *const GLfloat)
        }),
        case!("glPointParameteriv", "params", F, F, no_setup, |p| {
            glPointParameteriv(GL_POINT_SIZE_MIN, p as *const GLint)
        }),
        // 32x32 bits.
        case!("glPolygonStipple", "mask", 128, 1, no_setup, |p| {
            glPolygonStipple(p as *const GLubyte)
        }),
        case!("glGetPolygonStipple", "mask", 128, 1, no_setup, |p| {
            glGetPolygonStipple(p as *mut GLubyte)
        }),
        // Evaluator maps: order * stride values (1D); the last control point ends at
        // (uorder-1)*ustride + (vorder-1)*vstride + k (2D, k = 3 for MAP2_VERTEX_3).
        case!("glMap1f", "points", 3 * 4 * F, F, no_setup, |p| glMap1f(
            GL_MAP1_VERTEX_4,
            0.0,
            1.0,
            4,
            3,
            p as *const GLfloat
        )),
        case!("glMap1d", "points", (2 * 5 + 3) * D, D, no_setup, |p| {
            glMap1d(GL_MAP1_NORMAL, 0.0, 1.0, 5, 3, p as *const GLdouble)
        }),
        case!("glMap2f", "points", (3 + 6 + 3) * F, F, no_setup, |p| {
            glMap2f(
                GL_MAP2_VERTEX_3,
                0.0,
                1.0,
                3,
                2,
                0.0,
                1.0,
                6,
                2,
                p as *const GLfloat,
            )
        }),
        case!(
            "glMap2d",
            "points",
            (4 * 2 + 2 * 12 + 4) * D,
            D,
            no_setup,
            |p| glMap2d(
                GL_MAP2_COLOR_4,
                0.0,
                1.0,
                4,
                3,
                0.0,
                1.0,
                12,
                3,
                p as *const GLdouble
            )
        ),
        // GetMap: COEFF gives order * k values, ORDER 1 (1D) or 2 (2D), DOMAIN 2 or 4.
        case!("glGetMapfv", "v", 3 * 4 * F, F, maps, |p| glGetMapfv(
            GL_MAP1_VERTEX_4,
            GL_COEFF,
            p as *mut GLfloat
        )),
        case!("glGetMapdv", "v", 2 * 2 * 3 * D, D, maps, |p| glGetMapdv(
            GL_MAP2_VERTEX_3,
            GL_COEFF,
            p as *mut GLdouble
        )),
        case!("glGetMapiv", "v", 2 * F, F, maps, |p| glGetMapiv(
            GL_MAP2_VERTEX_3,
            GL_ORDER,
            p as *mut GLint
        )),
        case!("glGetMapfv", "v", 4 * F, F, maps, |p| glGetMapfv(
            GL_MAP2_VERTEX_3,
            GL_DOMAIN,
            p as *mut GLfloat
        )),
        case!("glPixelMapfv", "values", 4 * F, F, no_setup, |p| {
            glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, p as *const GLfloat)
        }),
        case!("glPixelMapuiv", "values", 2 * F, F, no_setup, |p| {
            glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 2, p as *const GLuint)
        }),
        case!("glPixelMapusv", "values", 8 * 2, 2, no_setup, |p| {
            glPixelMapusv(GL_PIXEL_MAP_I_TO_G, 8, p as *const GLushort)
        }),
        // GetPixelMap: the map's current size (5 after the set-up; 1 for a default map).
        case!("glGetPixelMapfv", "values", 5 * F, F, pixel_map_of_5, |p| {
            glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, p as *mut GLfloat)
        }),
        case!(
            "glGetPixelMapuiv",
            "values",
            5 * F,
            F,
            pixel_map_of_5,
            |p| glGetPixelMapuiv(GL_PIXEL_MAP_R_TO_R, p as *mut GLuint)
        ),
        case!("glGetPixelMapusv", "values", 2, 2, no_setup, |p| {
            glGetPixelMapusv(GL_PIXEL_MAP_A_TO_A, p as *mut GLushort)
        }),
        case!("glMultiDrawArrays", "first", 2 * F, F, vertex_array, |p| {
            let c = [3i32, 3];
            *(p as *mut [GLint; 2]) = [0, 3];
            glMultiDrawArrays(GL_TRIANGLES, p as *const GLint, c.as_ptr(), 2)
        }),
        case!("glMultiDrawArrays", "count", 2 * F, F, vertex_array, |p| {
            let f = [0i32, 3];
            *(p as *mut [GLint; 2]) = [3, 3];
            glMultiDrawArrays(GL_TRIANGLES, f.as_ptr(), p as *const GLsizei, 2)
        }),
        case!(
            "glMultiDrawElements",
            "count",
            2 * F,
            F,
            vertex_array,
            |p| {
                static IDX: [u8; 3] = [0, 1, 2];
                let ptrs = [IDX.as_ptr() as *const c_void; 2];
                *(p as *mut [GLint; 2]) = [3, 3];
                glMultiDrawElements(
                    GL_TRIANGLES,
                    p as *const GLsizei,
                    GL_UNSIGNED_BYTE,
                    ptrs.as_ptr() as *const c_void,
                    2,
                )
            }
        ),
    ];
    // OpenGL 1.5 has no one- or three-dimensional compressed formats: these always record
    // GL_INVALID_ENUM and never read their data.
    for (name, call) in [
        (
            "glCompressedTexImage1D",
            (|p| unsafe {
                glCompressedTexImage1D(
                    GL_TEXTURE_1D,
                    0,
                    GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
                    4,
                    0,
                    8,
                    p as *const c_void,
                )
            }) as unsafe fn(*mut u8),
        ),
        ("glCompressedTexImage3D", |p| unsafe {
            glCompressedTexImage3D(
                GL_TEXTURE_3D,
                0,
                GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
                4,
                4,
                4,
                0,
                8,
                p as *const c_void,
            )
        }),
        ("glCompressedTexSubImage1D", |p| unsafe {
            glCompressedTexSubImage1D(
                GL_TEXTURE_1D,
                0,
                0,
                4,
                GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
                8,
                p as *const c_void,
            )
        }),
        ("glCompressedTexSubImage3D", |p| unsafe {
            glCompressedTexSubImage3D(
                GL_TEXTURE_3D,
                0,
                0,
                0,
                0,
                4,
                4,
                4,
                GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
                8,
                p as *const c_void,
            )
        }),
    ] {
        v.push(Case {
            name,
            param: "data",
            bytes: 8,
            elem: 1,
            error: GL_INVALID_ENUM,
            setup: no_setup,
            call,
        });
    }
    v
}

#[test]
fn every_sized_pointer_has_an_audit_case() {
    let audited: BTreeSet<(&str, &str)> = cases().iter().map(|c| (c.name, c.param)).collect();
    let fixed: BTreeSet<&str> = FIXED_LENGTH_CALLS.iter().map(|c| c.0).collect();
    let missing: Vec<_> = SIZED_POINTER_PARAMS
        .iter()
        .filter(|(name, param, _)| !audited.contains(&(*name, *param)) && !fixed.contains(name))
        .collect();
    assert!(
        missing.is_empty(),
        "pointer parameters without an audit case: {missing:?}"
    );
    // And every audit case names a real exported pointer parameter.
    for c in cases() {
        assert!(
            SIZED_POINTER_PARAMS
                .iter()
                .any(|(n, p, _)| (*n, *p) == (c.name, c.param)),
            "{}({}) is not a sized pointer parameter",
            c.name,
            c.param
        );
    }
}

#[test]
fn valid_calls_fit_their_buffers_and_short_buffers_are_caught() {
    let mut failures = Vec::new();
    for c in cases() {
        let (error, overruns) = run(&c, c.bytes);
        if error != c.error || overruns != 0 {
            failures.push(format!(
                "{}({}) with its {} bytes: error 0x{error:04x} (expected 0x{:04x}), {overruns} overruns",
                c.name, c.param, c.bytes, c.error
            ));
        }
        let (_, overruns) = run(&c, c.bytes - c.elem);
        if c.error == GL_NO_ERROR && overruns == 0 {
            failures.push(format!(
                "{}({}) one element short ({} bytes): not caught",
                c.name,
                c.param,
                c.bytes - c.elem
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn fixed_length_pointers_fit_and_short_ones_are_caught() {
    assert!(
        FIXED_LENGTH_CALLS.len() > 100,
        "the generated table is too small"
    );
    let mut failures = Vec::new();
    for &(name, bytes, call) in FIXED_LENGTH_CALLS {
        // glIndex* set the current colour index (state in RGBA contexts too): no error.
        let error = GL_NO_ERROR;
        let case = Case {
            name,
            param: "",
            bytes,
            elem: 1,
            error,
            setup: no_setup,
            call,
        };
        let (error, overruns) = run(&case, bytes);
        if error != case.error || overruns != 0 {
            failures.push(format!(
                "{name} with {bytes} bytes: error 0x{error:04x}, {overruns} overruns"
            ));
        }
        let (_, overruns) = run(&case, bytes - 1);
        if overruns == 0 {
            failures.push(format!("{name} one byte short: not caught"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Pointers GL keeps are held to a declared buffer too, when a draw reads them: a client
/// vertex array and a client index array read for more elements than the buffer holds are
/// counted as overruns (and cut at its end), the same draws within it are not. The fuzzer's
/// `c_calls` target relies on this for draws whose indices it chose.
#[test]
fn retained_client_arrays_are_held_to_a_declared_buffer() {
    let _current = Current::new();
    // One buffer: three 2D vertices (24 bytes), then six indices (12 bytes), then room, so the
    // vertices lie before a bound declared on the indices and the reads past either are real
    // memory.
    let mut memory = [0u8; 64];
    for (i, v) in [-1.0f32, -1.0, 1.0, -1.0, 0.0, 1.0].iter().enumerate() {
        memory[i * 4..i * 4 + 4].copy_from_slice(&v.to_ne_bytes());
    }
    for (i, x) in [0u16, 1, 2, 2, 1, 0].iter().enumerate() {
        memory[24 + i * 2..26 + i * 2].copy_from_slice(&x.to_ne_bytes());
    }
    let vertices = memory.as_ptr() as *const c_void;
    // SAFETY: 24 is inside the 64-byte buffer.
    let indices = unsafe { memory.as_ptr().add(24) } as *const c_void;
    let draws = |declared: usize, count: GLsizei, elements: bool| -> (GLenum, usize) {
        // SAFETY: the vertex array and the indices (in `memory`) outlive the draw; the
        // declared length is at most what they hold, and reads past it are cut by the check
        // under test (never past `memory`).
        unsafe {
            glEnableClientState(GL_VERTEX_ARRAY);
            glVertexPointer(2, GL_FLOAT, 0, vertices);
            let start = if elements { indices } else { vertices };
            assert_eq!(tilegl_debug_client_bound(start, declared), 1);
            if elements {
                glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_SHORT, indices);
            } else {
                glDrawArrays(GL_TRIANGLES, 0, count);
            }
            let overruns = tilegl_debug_client_overruns();
            tilegl_debug_client_bound(std::ptr::null(), 0);
            glDisableClientState(GL_VERTEX_ARRAY);
            (glGetError(), overruns)
        }
    };
    assert_eq!(draws(24, 3, false), (GL_NO_ERROR, 0));
    assert!(
        draws(24, 6, false).1 > 0,
        "6 vertices from a 3-vertex array"
    );
    assert_eq!(draws(12, 6, true), (GL_NO_ERROR, 0));
    assert!(draws(6, 6, true).1 > 0, "6 indices from a 3-index buffer");
}

//! The copy of the finished picture into an OSMesa caller's buffer at `glFinish` (each tile's
//! rows written straight to their place, the tiles split over the shading threads): every
//! pixel lands where OSMesa's rules put it, in the caller's byte order, for every format, both
//! row orders and a row length wider than the image, and the bytes past each row's pixels are
//! left alone.

use std::ffi::c_void;

use tilegl::api::types::*;
use tilegl::capi::exports::*;
use tilegl::capi::osmesa::*;
use tilegl::enums::*;

/// Width and height: neither a multiple of any tile side, several tiles each way.
const W: usize = 150;
const H: usize = 83;
/// The row length the caller asks for (pixels): wider than the image.
const ROW: usize = W + 7;
/// What the caller's buffer held before: bytes no pixel may overwrite keep it.
const SENTINEL: u8 = 0xA5;

/// The colour drawn at window pixel (x, y), distinct in every channel along rows and columns.
fn drawn(x: usize, y: usize) -> [u8; 4] {
    [
        (x * 7 + y) as u8,
        (y * 3 + x * 5) as u8,
        (x ^ (y << 2)) as u8,
        (255 - x - y) as u8,
    ]
}

/// OSMesa's byte order for each format (the OSMesa header's names), as the caller reads it.
fn in_format(format: GLenum, [r, g, b, a]: [u8; 4]) -> Vec<u8> {
    match format {
        OSMESA_RGBA => vec![r, g, b, a],
        OSMESA_BGRA => vec![b, g, r, a],
        OSMESA_ARGB => vec![a, r, g, b],
        OSMESA_RGB => vec![r, g, b],
        OSMESA_BGR => vec![b, g, r],
        _ => unreachable!(),
    }
}

/// The pixel the second picture changes, and its colour there.
const SPOT: (usize, usize) = (3, 3);
const SPOT_COLOR: [u8; 4] = [1, 2, 3, 4];

/// Checks the whole caller's buffer against the picture `at` describes.
fn check(
    buffer: &[u8],
    format: GLenum,
    y_up: bool,
    at: impl Fn(usize, usize) -> [u8; 4],
    what: &str,
) {
    let bpp = in_format(format, [0; 4]).len();
    for y in 0..H {
        // OSMesa: row 0 of the buffer is the bottom row unless OSMESA_Y_UP is 0.
        let row = if y_up { y } else { H - 1 - y };
        let line = &buffer[row * ROW * bpp..(row + 1) * ROW * bpp];
        for x in 0..W {
            assert_eq!(
                &line[x * bpp..(x + 1) * bpp],
                &in_format(format, at(x, y))[..],
                "{what}: format {format:#x}, y_up {y_up}, pixel ({x}, {y})"
            );
        }
        assert!(
            line[W * bpp..].iter().all(|&b| b == SENTINEL),
            "{what}: format {format:#x}, y_up {y_up}: bytes past row {y}'s pixels written"
        );
    }
}

/// Three finished pictures in one caller's buffer (refilled with the sentinel before each
/// finish, so each must be copied whole): every pixel's colour drawn as a point (every tile
/// shaded); then one point more (most tiles with nothing to shade); then a `glFinish` with
/// nothing drawn.
fn render_and_check(format: GLenum, y_up: bool) {
    let bpp = in_format(format, [0; 4]).len();
    let mut buffer = vec![SENTINEL; ROW * H * bpp];
    let ctx = OSMesaCreateContextExt(format, 24, 8, 0, std::ptr::null_mut());
    assert!(!ctx.is_null());
    let spot = |x: usize, y: usize| {
        if (x, y) == SPOT {
            SPOT_COLOR
        } else {
            drawn(x, y)
        }
    };
    // SAFETY: a live context and a buffer of ROW x H pixels of `bpp` bytes, alive until the
    // context is destroyed below and not touched by this thread while GL calls run; the GL
    // calls take plain values.
    unsafe {
        let ok = OSMesaMakeCurrent(
            ctx,
            buffer.as_mut_ptr() as *mut c_void,
            GL_UNSIGNED_BYTE,
            W as GLsizei,
            H as GLsizei,
        );
        assert_eq!(ok, GL_TRUE as GLboolean);
        OSMesaPixelStore(OSMESA_ROW_LENGTH, ROW as GLint);
        OSMesaPixelStore(OSMESA_Y_UP, y_up as GLint);
        glViewport(0, 0, W as GLsizei, H as GLsizei);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0.0, W as f64, 0.0, H as f64, -1.0, 1.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glBegin(GL_POINTS);
        for y in 0..H {
            for x in 0..W {
                let [r, g, b, a] = drawn(x, y);
                glColor4ub(r, g, b, a);
                glVertex2f(x as f32 + 0.5, y as f32 + 0.5);
            }
        }
        glEnd();
        glFinish();
        assert_eq!(glGetError(), GL_NO_ERROR);
    }
    check(&buffer, format, y_up, drawn, "every pixel drawn");
    buffer.fill(SENTINEL);
    // SAFETY: as above.
    unsafe {
        let [r, g, b, a] = SPOT_COLOR;
        glBegin(GL_POINTS);
        glColor4ub(r, g, b, a);
        glVertex2f(SPOT.0 as f32 + 0.5, SPOT.1 as f32 + 0.5);
        glEnd();
        glFinish();
    }
    check(&buffer, format, y_up, spot, "one point drawn");
    buffer.fill(SENTINEL);
    // SAFETY: as above; the context is destroyed once.
    unsafe {
        glFinish();
        assert_eq!(glGetError(), GL_NO_ERROR);
        check(&buffer, format, y_up, spot, "nothing drawn");
        OSMesaDestroyContext(ctx);
    }
}

#[test]
fn finished_pictures_land_in_the_callers_buffer_in_its_format_and_row_order() {
    for format in [
        OSMESA_RGBA,
        OSMESA_BGRA,
        OSMESA_ARGB,
        OSMESA_RGB,
        OSMESA_BGR,
    ] {
        for y_up in [true, false] {
            render_and_check(format, y_up);
        }
    }
}

//! `glXUseXFont` (GLX 1.4 section 3.3.10): one display list per glyph of an X font, each a
//! single `glBitmap` of the glyph.
//!
//! The glyphs are rendered by the X server: each is drawn (`XDrawString16`) into a depth-1
//! pixmap at its left bearing and ascent and read back (`XGetImage`). The bitmap's origin is
//! (-lbearing, descent - 1), the reference page's formula: X counts the baseline's own row in
//! the descent, so the baseline row lands on the raster position's row. Each list moves the
//! raster position by the glyph's width. Glyphs the font does not define get empty lists;
//! defined glyphs without pixels (a space) still move it.
//!
//! The lists hold the glyph bits themselves: each replays `glBitmap` with GL's default unpack
//! state and an alignment of 1, whatever the unpack state when the list runs (GL unpacks a
//! list's images when it is compiled; tilegl's recorded pixel calls unpack when they run, so
//! the bits are tied to the unpack state they were written for).

use std::ffi::{c_int, c_uint, c_ulong};

use x11_dl::xlib::{self, Display, XChar2b, XCharStruct};

use super::window;
use crate::api::enums::*;
use crate::state::tables::PixelStore;
use crate::state::Context;

/// A glyph's metrics, or `None` when the font does not define it.
fn glyph_metrics(fs: &xlib::XFontStruct, c: u32) -> Option<XCharStruct> {
    let (b1, b2) = ((c >> 8) as c_uint, (c & 0xff) as c_uint);
    let (min1, max1) = (fs.min_byte1, fs.max_byte1);
    let (min2, max2) = (fs.min_char_or_byte2, fs.max_char_or_byte2);
    let index = if min1 == 0 && max1 == 0 {
        // A linear (one-byte) font: the whole code is the index.
        if c < min2 || c > max2 {
            return None;
        }
        (c - min2) as usize
    } else {
        if b1 < min1 || b1 > max1 || b2 < min2 || b2 > max2 {
            return None;
        }
        ((b1 - min1) * (max2 - min2 + 1) + (b2 - min2)) as usize
    };
    if fs.per_char.is_null() {
        // Every glyph has the font's maximum metrics.
        return Some(fs.max_bounds);
    }
    // SAFETY: XQueryFont returned `per_char` with one entry per code in the font's range, and
    // `index` is inside that range.
    let m = unsafe { *fs.per_char.add(index) };
    let nonexistent =
        m.width == 0 && m.lbearing == 0 && m.rbearing == 0 && m.ascent == 0 && m.descent == 0;
    (!nonexistent).then_some(m)
}

/// The glyph's bitmap for `glBitmap`: rows bottom first, each `ceil(w / 8)` bytes, most
/// significant bit leftmost.
struct Glyph {
    width: i32,
    height: i32,
    xorig: f32,
    yorig: f32,
    xmove: f32,
    bits: Vec<u8>,
}

/// `glXUseXFont`: does nothing without a current context, or while a list is being compiled
/// (GLX's `GLXBadContextState`, which tilegl cannot raise without the server's GLX).
#[no_mangle]
pub extern "C" fn glXUseXFont(font: c_ulong, first: c_int, count: c_int, list_base: c_int) {
    let Some(x) = window::xlib() else { return };
    let Some(target) = window::current_target() else {
        return;
    };
    let compiling = super::osmesa::with_current_context(|c| c.gl.lists.index() != 0);
    if compiling != Some(false) || count <= 0 {
        return;
    }
    let dpy = target.dpy as *mut Display;
    // SAFETY: the current display is open (it was given to glXMakeCurrent); a bad font id is
    // reported as BadFont through the program's X error handler and returns null.
    let fs = unsafe { (x.XQueryFont)(dpy, font) };
    if fs.is_null() {
        return;
    }
    // SAFETY: non-null, from XQueryFont; freed with XFreeFontInfo below.
    let glyphs = unsafe { render_glyphs(x, dpy, font, &*fs, first, count) };
    // SAFETY: `fs` came from XQueryFont (one struct, its per_char array).
    unsafe { (x.XFreeFontInfo)(std::ptr::null_mut(), fs, 1) };
    super::osmesa::with_current_context(|c| {
        for (i, g) in glyphs.into_iter().enumerate() {
            compile_glyph_list(&mut c.gl, (list_base as u32).wrapping_add(i as u32), g);
        }
    });
}

/// Makes list `name` hold one `glBitmap` of `glyph` (empty for `None`).
fn compile_glyph_list(gl: &mut Context, name: u32, glyph: Option<Glyph>) {
    gl.new_list(name, GL_COMPILE);
    if let Some(g) = glyph {
        gl.list_record(Box::new(move |ctx: &mut Context| {
            let unpack = std::mem::replace(
                &mut ctx.unpack,
                PixelStore {
                    alignment: 1,
                    ..PixelStore::default()
                },
            );
            ctx.bitmap(g.width, g.height, g.xorig, g.yorig, g.xmove, 0.0, &g.bits);
            ctx.unpack = unpack;
        }));
    }
    gl.end_list();
}

/// Draws glyphs `first..first + count` of `font` with the server and reads them back.
///
/// # Safety
/// `dpy` is open; `fs` describes `font`.
unsafe fn render_glyphs(
    x: &xlib::Xlib,
    dpy: *mut Display,
    font: c_ulong,
    fs: &xlib::XFontStruct,
    first: c_int,
    count: c_int,
) -> Vec<Option<Glyph>> {
    // The largest glyph box: the pixmap every glyph is drawn into.
    let pw = (fs.max_bounds.rbearing as i32 - fs.min_bounds.lbearing as i32).max(1);
    let ph = (fs.max_bounds.ascent as i32 + fs.max_bounds.descent as i32).max(1);
    // SAFETY (whole block): Xlib calls on the open display with objects created here and freed
    // at the end; images come from XGetImage and are destroyed after reading.
    unsafe {
        let root = (x.XDefaultRootWindow)(dpy);
        let pixmap = (x.XCreatePixmap)(dpy, root, pw as c_uint, ph as c_uint, 1);
        let gc = (x.XCreateGC)(dpy, pixmap, 0, std::ptr::null_mut());
        (x.XSetFont)(dpy, gc, font);
        let mut out = Vec::with_capacity(count as usize);
        for i in 0..count {
            let c = first.wrapping_add(i);
            let metrics = if c < 0 {
                None
            } else {
                glyph_metrics(fs, c as u32)
            };
            let Some(m) = metrics else {
                out.push(None);
                continue;
            };
            let w = m.rbearing as i32 - m.lbearing as i32;
            let h = m.ascent as i32 + m.descent as i32;
            let mut glyph = Glyph {
                width: 0,
                height: 0,
                xorig: 0.0,
                yorig: 0.0,
                xmove: m.width as f32,
                bits: Vec::new(),
            };
            if w > 0 && h > 0 && w <= pw && h <= ph {
                (x.XSetForeground)(dpy, gc, 0);
                (x.XFillRectangle)(dpy, pixmap, gc, 0, 0, w as c_uint, h as c_uint);
                (x.XSetForeground)(dpy, gc, 1);
                let mut ch = XChar2b {
                    byte1: (c >> 8) as u8,
                    byte2: (c & 0xff) as u8,
                };
                (x.XDrawString16)(
                    dpy,
                    pixmap,
                    gc,
                    -(m.lbearing as c_int),
                    m.ascent as c_int,
                    &mut ch,
                    1,
                );
                let img = (x.XGetImage)(
                    dpy,
                    pixmap,
                    0,
                    0,
                    w as c_uint,
                    h as c_uint,
                    1,
                    xlib::ZPixmap,
                );
                if !img.is_null() {
                    let row_bytes = (w as usize).div_ceil(8);
                    let mut bits = vec![0u8; row_bytes * h as usize];
                    if let Some(get) = (*img).funcs.get_pixel {
                        for y in 0..h {
                            // glBitmap's first row is the bottom one.
                            let row = &mut bits[(h - 1 - y) as usize * row_bytes..][..row_bytes];
                            for xx in 0..w {
                                if get(img, xx, y) != 0 {
                                    row[xx as usize / 8] |= 0x80 >> (xx % 8);
                                }
                            }
                        }
                    }
                    (x.XDestroyImage)(img);
                    glyph = Glyph {
                        width: w,
                        height: h,
                        xorig: -(m.lbearing as f32),
                        yorig: m.descent as f32 - 1.0,
                        bits,
                        ..glyph
                    };
                }
            }
            out.push(Some(glyph));
        }
        (x.XFreeGC)(dpy, gc);
        (x.XFreePixmap)(dpy, pixmap);
        out
    }
}

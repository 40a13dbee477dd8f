//! ARB_pixel_buffer_object and ARB_map_buffer_range: the same calls on Mesa and on tilegl
//! (Rust API through the `*_pbo` methods, C ABI through the exports, which take the pointer
//! as an offset while a pixel buffer is bound). Bindings and their queries, every pixel command
//! unpacking from `GL_PIXEL_UNPACK_BUFFER` or packing into `GL_PIXEL_PACK_BUFFER`, the
//! `GL_INVALID_OPERATION` rules (a range past the buffer's end, a mapped buffer), display lists
//! keeping the buffer's data of compile time, and `glMapBufferRange`/`glFlushMappedBufferRange`
//! with their flag errors and the mapping queries. Every answer equals Mesa's.
//!
//! Left out, where Mesa 22 departs from the extension texts (tilegl follows the texts, checked
//! by `tests/pixel_buffers.rs`):
//! - `glPopClientAttrib(GL_CLIENT_PIXEL_STORE_BIT)` after the bound pixel buffer was deleted:
//!   Mesa binds the deleted buffer's name again (its reference keeps the object alive), where
//!   section 2.9 says a deleted name is unbound everywhere and names no buffer any more;
//! - `glMapBufferRange` with a zero length: ARB_map_buffer_range (and OpenGL 3.0) allow it,
//!   Mesa records `GL_INVALID_OPERATION` as OpenGL 4.5 does;
//! - `glGetPixelMapuiv` of an index map (`GL_PIXEL_MAP_I_TO_I`), into the buffer or client
//!   memory: Mesa converts the indices as if they were colour components (1 comes back as
//!   0xffffffff), where section 6.1.3 returns indices unchanged.
//!
//! The order of errors also differs where a call has two: Mesa checks the command's own
//! arguments first, tilegl the buffer access first (a bad level with a range past the buffer's
//! end is `GL_INVALID_VALUE` on Mesa, `GL_INVALID_OPERATION` on tilegl); the cases give each
//! call one error.

super::state_case_list!(source = include_str!("pbo.rs"), agree = |a: &Answer, b: &Answer| {
    a.values.len() == b.values.len()
        && a.values
            .iter()
            .zip(&b.values)
            .all(|(x, y)| (x - y).abs() <= a.tolerance)
};
    pbo_bindings: "GL_PIXEL_PACK_BUFFER and GL_PIXEL_UNPACK_BUFFER as buffer targets (glBindBuffer, glBufferData, glBufferSubData, glGetBufferSubData, glGetBufferParameteriv), their binding queries, the client attribute stack saving them with GL_CLIENT_PIXEL_STORE_BIT (not with GL_CLIENT_VERTEX_ARRAY_BIT), deletion unbinding them, and GL_INVALID_OPERATION for data calls while 0 is bound. Every answer equals Mesa's.",
    pbo_tex_image_unpack: "glTexImage1D/2D/3D and glTexSubImage2D unpacking from the bound pixel unpack buffer at an offset (0 too: the buffer's start, not an unspecified image), under row length and skips, unsigned byte and float data; read back through glGetTexImage into client memory. Every answer equals Mesa's.",
    pbo_read_pixels_pack: "glReadPixels packing into the bound pixel pack buffer at an offset, colour (RGBA and RGB with 8-byte row alignment, the padding bytes left as they were) and depth as floats, with a pack row length; the buffer read back with glGetBufferSubData. Every answer equals Mesa's.",
    pbo_get_tex_image_pack: "glGetTexImage of 1D, 2D, 3D and cube-map face images packing into the bound pixel pack buffer at offsets, in RGBA and luminance, and glGetPolygonStipple and glGetPixelMapfv/uiv/usv writing into it; the buffer read back with glGetBufferSubData. Every answer equals Mesa's.",
    pbo_draw_pixels_bitmap_stipple: "glDrawPixels (unsigned byte and float), glBitmap, glPolygonStipple and glPixelMapfv/usv unpacking from the bound pixel unpack buffer; the framebuffer and the pixel maps read back. Every answer equals Mesa's.",
    pbo_errors: "GL_INVALID_OPERATION for a pixel command whose data would reach past the end of the bound buffer (glTexImage2D, glTexSubImage2D, glDrawPixels, glBitmap, glPolygonStipple, glCompressedTexImage2D, glReadPixels, glGetTexImage, glGetPolygonStipple) or whose buffer is mapped, with nothing changed; a bad enum keeps its own error. Every answer equals Mesa's.",
    pbo_display_lists: "Unpacking commands (glTexImage2D, glDrawPixels, glBitmap) compiled into a display list while a pixel unpack buffer is bound take the buffer's data when the list is compiled: the buffer changed and unbound afterwards, the list draws the compiled data. Every answer equals Mesa's.",
    map_buffer_range: "glMapBufferRange: the mapped state (GL_BUFFER_MAPPED, GL_BUFFER_ACCESS, GL_BUFFER_ACCESS_FLAGS, GL_BUFFER_MAP_OFFSET, GL_BUFFER_MAP_LENGTH, GL_BUFFER_MAP_POINTER at the range's start) and its reset by glUnmapBuffer, glMapBuffer's flags, the errors of the access bits, ranges, targets and buffer 0, and glFlushMappedBufferRange's errors (not mapped, mapped without GL_MAP_FLUSH_EXPLICIT_BIT, range outside the mapping). Every answer equals Mesa's.",
);

use super::fbo::{err, exact, floats, int, pixel_space, quad, read_rgba, Answer, Answers};
use tilegl::api::{ClientPtr, GLenum};
use tilegl::enums::*;
use tilegl::Gl;

/// A new buffer bound to `target` holding `data`.
fn buffer(gl: &mut dyn Gl, target: GLenum, data: &[u8]) -> u32 {
    let mut b = [0];
    gl.gen_buffers(1, &mut b);
    gl.bind_buffer(target, b[0]);
    gl.buffer_data(target, data.len() as isize, Some(data), GL_STREAM_DRAW);
    b[0]
}

/// `n` bytes of a pattern that differs at every byte.
fn pattern(n: usize, seed: u8) -> Vec<u8> {
    (0..n)
        .map(|i| (i as u8).wrapping_mul(37).wrapping_add(seed))
        .collect()
}

/// The buffer bound to `target`, read back whole.
fn buffer_bytes(gl: &mut dyn Gl, out: &mut Answers, target: GLenum, label: &str, n: usize) {
    let mut b = vec![0u8; n];
    gl.get_buffer_sub_data(target, 0, n as isize, &mut b);
    exact(
        out,
        format!("buffer {label}"),
        b.iter().map(|&v| v as f64).collect(),
    );
    err(gl, out, label);
}

fn buffer_param(gl: &mut dyn Gl, out: &mut Answers, target: GLenum, pname: GLenum) {
    let mut v = [-7];
    gl.get_buffer_parameteriv(target, pname, &mut v);
    exact(
        out,
        format!("glGetBufferParameteriv(0x{target:04x}, 0x{pname:04x})"),
        vec![v[0] as f64],
    );
}

/// The 2D image of level 0 read back into client memory as RGBA bytes.
fn tex_image_rgba(gl: &mut dyn Gl, out: &mut Answers, target: GLenum, label: &str, n: usize) {
    let mut px = vec![0u8; n * 4];
    gl.get_tex_image(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    exact(
        out,
        format!("glGetTexImage {label}"),
        px.iter().map(|&v| v as f64).collect(),
    );
    err(gl, out, label);
}

fn texture(gl: &mut dyn Gl, target: GLenum) -> u32 {
    let mut t = [0];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(target, t[0]);
    gl.tex_parameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    t[0]
}

fn pbo_bindings(gl: &mut dyn Gl, out: &mut Answers) {
    let bindings = |gl: &mut dyn Gl, out: &mut Answers| {
        int(gl, out, GL_PIXEL_PACK_BUFFER_BINDING);
        int(gl, out, GL_PIXEL_UNPACK_BUFFER_BINDING);
    };
    bindings(gl, out);
    let mut b = [0; 3];
    gl.gen_buffers(3, &mut b);
    gl.bind_buffer(GL_PIXEL_PACK_BUFFER, b[0]);
    gl.bind_buffer(GL_PIXEL_UNPACK_BUFFER, b[1]);
    err(gl, out, "binding the pixel targets");
    bindings(gl, out);
    int(gl, out, GL_ARRAY_BUFFER_BINDING);
    gl.buffer_data(GL_PIXEL_PACK_BUFFER, 100, None, GL_STREAM_READ);
    gl.buffer_data(
        GL_PIXEL_UNPACK_BUFFER,
        48,
        Some(&pattern(48, 3)),
        GL_STATIC_DRAW,
    );
    err(gl, out, "glBufferData on the pixel targets");
    for t in [GL_PIXEL_PACK_BUFFER, GL_PIXEL_UNPACK_BUFFER] {
        for p in [GL_BUFFER_SIZE, GL_BUFFER_USAGE, GL_BUFFER_MAPPED] {
            buffer_param(gl, out, t, p);
        }
    }
    gl.buffer_sub_data(GL_PIXEL_UNPACK_BUFFER, 4, 4, Some(&[1, 2, 3, 4]));
    buffer_bytes(gl, out, GL_PIXEL_UNPACK_BUFFER, "unpack after sub data", 48);
    let is = gl.is_buffer(b[0]);
    exact(out, "glIsBuffer(pack)".into(), vec![is as f64]);
    // The pixel-store bit saves the bindings; the vertex-array bit does not.
    gl.push_client_attrib(GL_CLIENT_PIXEL_STORE_BIT);
    gl.bind_buffer(GL_PIXEL_PACK_BUFFER, 0);
    gl.bind_buffer(GL_PIXEL_UNPACK_BUFFER, b[2]);
    bindings(gl, out);
    gl.pop_client_attrib();
    err(gl, out, "push and pop of the pixel-store bit");
    bindings(gl, out);
    gl.push_client_attrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    gl.bind_buffer(GL_PIXEL_PACK_BUFFER, b[2]);
    gl.pop_client_attrib();
    bindings(gl, out);
    // Deletion unbinds; data calls on 0 are errors.
    gl.delete_buffers(3, &b);
    bindings(gl, out);
    gl.buffer_data(GL_PIXEL_PACK_BUFFER, 4, None, GL_STREAM_READ);
    err(gl, out, "glBufferData with 0 bound");
    let mut v = [-7];
    gl.get_buffer_parameteriv(GL_PIXEL_UNPACK_BUFFER, GL_BUFFER_SIZE, &mut v);
    err(gl, out, "glGetBufferParameteriv with 0 bound");
    gl.map_buffer(GL_PIXEL_PACK_BUFFER, GL_READ_ONLY);
    err(gl, out, "glMapBuffer with 0 bound");
}

fn pbo_tex_image_unpack(gl: &mut dyn Gl, out: &mut Answers) {
    let data = pattern(1024, 11);
    buffer(gl, GL_PIXEL_UNPACK_BUFFER, &data);
    // 2D at an offset, then at offset 0.
    texture(gl, GL_TEXTURE_2D);
    gl.tex_image_2d_pbo(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        4,
        4,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        64,
    );
    err(gl, out, "glTexImage2D at offset 64");
    tex_image_rgba(gl, out, GL_TEXTURE_2D, "2D from offset 64", 16);
    gl.tex_image_2d_pbo(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        4,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        0,
    );
    tex_image_rgba(gl, out, GL_TEXTURE_2D, "2D from offset 0", 8);
    // A sub-image under row length and skips.
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        8,
        8,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    gl.pixel_storei(GL_UNPACK_ROW_LENGTH, 12);
    gl.pixel_storei(GL_UNPACK_SKIP_PIXELS, 1);
    gl.pixel_storei(GL_UNPACK_SKIP_ROWS, 2);
    gl.tex_sub_image_2d_pbo(GL_TEXTURE_2D, 0, 2, 1, 5, 3, GL_RGBA, GL_UNSIGNED_BYTE, 8);
    err(gl, out, "glTexSubImage2D with row length and skips");
    gl.pixel_storei(GL_UNPACK_ROW_LENGTH, 0);
    gl.pixel_storei(GL_UNPACK_SKIP_PIXELS, 0);
    gl.pixel_storei(GL_UNPACK_SKIP_ROWS, 0);
    let mut px = vec![0u8; 8 * 8 * 4];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    // Only the sub-image's texels are defined (the rest was specified without data).
    let mut sub = Vec::new();
    for y in 1..4 {
        for x in 2..7 {
            sub.extend(
                px[(y * 8 + x) * 4..(y * 8 + x + 1) * 4]
                    .iter()
                    .map(|&v| v as f64),
            );
        }
    }
    exact(out, "sub-image texels".into(), sub);
    // Floats (offset a multiple of 4), as luminance.
    let fl: Vec<u8> = (0..16)
        .flat_map(|i| (i as f32 / 15.0).to_ne_bytes())
        .collect();
    gl.buffer_sub_data(GL_PIXEL_UNPACK_BUFFER, 512, 64, Some(&fl));
    gl.tex_image_2d_pbo(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE8 as i32,
        4,
        4,
        0,
        GL_LUMINANCE,
        GL_FLOAT,
        512,
    );
    err(gl, out, "glTexImage2D float luminance");
    tex_image_rgba(gl, out, GL_TEXTURE_2D, "2D luminance from floats", 16);
    // 1D and 3D.
    texture(gl, GL_TEXTURE_1D);
    gl.tex_image_1d_pbo(
        GL_TEXTURE_1D,
        0,
        GL_RGB8 as i32,
        8,
        0,
        GL_RGB,
        GL_UNSIGNED_BYTE,
        100,
    );
    err(gl, out, "glTexImage1D at offset 100");
    tex_image_rgba(gl, out, GL_TEXTURE_1D, "1D from offset 100", 8);
    texture(gl, GL_TEXTURE_3D);
    gl.tex_image_3d_pbo(
        GL_TEXTURE_3D,
        0,
        GL_RGBA8 as i32,
        2,
        2,
        4,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        300,
    );
    err(gl, out, "glTexImage3D at offset 300");
    tex_image_rgba(gl, out, GL_TEXTURE_3D, "3D from offset 300", 16);
    // Unbound again: client memory as before.
    gl.bind_buffer(GL_PIXEL_UNPACK_BUFFER, 0);
    gl.bind_texture(GL_TEXTURE_2D, 0);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&data[..16]),
    );
    tex_image_rgba(gl, out, GL_TEXTURE_2D, "client memory after unbinding", 4);
}

/// Colour and depth pictures to read: a clear and two flat quads at different depths.
fn draw_scene(gl: &mut dyn Gl) {
    pixel_space(gl, super::SIZE, super::SIZE);
    gl.clear_color(0.2, 0.4, 0.6, 0.8);
    gl.clear_depth(1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.enable(GL_DEPTH_TEST);
    gl.color_4ub(255, 0, 128, 255);
    quad(gl, 2.0, 2.0, 6.0, 5.0, 0.5);
    gl.color_4ub(0, 255, 64, 32);
    quad(gl, 4.0, 0.0, 8.0, 8.0, -0.25);
    gl.disable(GL_DEPTH_TEST);
}

fn pbo_read_pixels_pack(gl: &mut dyn Gl, out: &mut Answers) {
    draw_scene(gl);
    let n = 800;
    buffer(gl, GL_PIXEL_PACK_BUFFER, &vec![0xaa; n]);
    gl.read_pixels_pbo(0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, 16);
    err(gl, out, "glReadPixels RGBA at offset 16");
    buffer_bytes(gl, out, GL_PIXEL_PACK_BUFFER, "RGBA at 16", n);
    // RGB rows of 15 bytes padded to 16: the padding stays.
    gl.buffer_data(
        GL_PIXEL_PACK_BUFFER,
        n as isize,
        Some(&vec![0x55; n]),
        GL_STREAM_READ,
    );
    gl.pixel_storei(GL_PACK_ALIGNMENT, 8);
    gl.read_pixels_pbo(1, 1, 5, 6, GL_RGB, GL_UNSIGNED_BYTE, 3);
    err(gl, out, "glReadPixels RGB aligned to 8");
    buffer_bytes(gl, out, GL_PIXEL_PACK_BUFFER, "RGB aligned to 8", n);
    gl.pixel_storei(GL_PACK_ALIGNMENT, 4);
    // Depth as floats, with a row length.
    gl.buffer_data(
        GL_PIXEL_PACK_BUFFER,
        n as isize,
        Some(&vec![0; n]),
        GL_STREAM_READ,
    );
    gl.pixel_storei(GL_PACK_ROW_LENGTH, 10);
    gl.read_pixels_pbo(0, 0, 8, 4, GL_DEPTH_COMPONENT, GL_FLOAT, 40);
    gl.pixel_storei(GL_PACK_ROW_LENGTH, 0);
    err(gl, out, "glReadPixels depth");
    let mut b = vec![0u8; 40 + 4 * 10 * 4];
    gl.get_buffer_sub_data(GL_PIXEL_PACK_BUFFER, 0, b.len() as isize, &mut b);
    out.push(Answer {
        label: "depth floats".into(),
        values: floats(&b).iter().map(|&d| d as f64).collect(),
        tolerance: 2.0 / 16777215.0,
    });
    // Unbound again: client memory as before.
    gl.bind_buffer(GL_PIXEL_PACK_BUFFER, 0);
    read_rgba(gl, out, "client memory after unbinding", 3, 3, 2, 2);
}

fn pbo_get_tex_image_pack(gl: &mut dyn Gl, out: &mut Answers) {
    let n = 1024;
    buffer(gl, GL_PIXEL_PACK_BUFFER, &vec![0x11; n]);
    texture(gl, GL_TEXTURE_1D);
    gl.tex_image_1d(
        GL_TEXTURE_1D,
        0,
        GL_RGBA8 as i32,
        8,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&pattern(32, 1)),
    );
    texture(gl, GL_TEXTURE_2D);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        4,
        4,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&pattern(64, 2)),
    );
    texture(gl, GL_TEXTURE_3D);
    gl.tex_image_3d(
        GL_TEXTURE_3D,
        0,
        GL_RGBA8 as i32,
        2,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&pattern(32, 3)),
    );
    texture(gl, GL_TEXTURE_CUBE_MAP);
    gl.tex_image_2d(
        GL_TEXTURE_CUBE_MAP_NEGATIVE_Y,
        0,
        GL_RGBA8 as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&pattern(16, 4)),
    );
    err(gl, out, "making the textures");
    gl.get_tex_image_pbo(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, 0);
    gl.get_tex_image_pbo(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, 40);
    gl.get_tex_image_pbo(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, 120);
    gl.get_tex_image_pbo(
        GL_TEXTURE_CUBE_MAP_NEGATIVE_Y,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        160,
    );
    gl.get_tex_image_pbo(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, 181);
    gl.get_tex_image_pbo(GL_TEXTURE_2D, 0, GL_RGB, GL_FLOAT, 200);
    err(gl, out, "glGetTexImage into the buffer");
    buffer_bytes(gl, out, GL_PIXEL_PACK_BUFFER, "after glGetTexImage", 400);
    // The stipple and the pixel maps.
    let stipple: Vec<u8> = pattern(128, 9);
    gl.polygon_stipple(&stipple);
    gl.pixel_mapfv(GL_PIXEL_MAP_R_TO_R, 3, &[0.0, 0.25, 1.0]);
    gl.pixel_mapusv(GL_PIXEL_MAP_I_TO_I, 4, &[1, 5, 9, 200]);
    gl.get_polygon_stipple_pbo(500);
    gl.get_pixel_mapfv_pbo(GL_PIXEL_MAP_R_TO_R, 640);
    gl.get_pixel_mapusv_pbo(GL_PIXEL_MAP_I_TO_I, 680);
    err(gl, out, "stipple and pixel maps into the buffer");
    let mut b = vec![0u8; 200];
    gl.get_buffer_sub_data(GL_PIXEL_PACK_BUFFER, 500, 200, &mut b);

    exact(
        out,
        "stipple and maps".into(),
        b.iter().map(|&v| v as f64).collect(),
    );
}

fn pbo_draw_pixels_bitmap_stipple(gl: &mut dyn Gl, out: &mut Answers) {
    pixel_space(gl, super::SIZE, super::SIZE);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let mut data = pattern(1024, 5);
    let fl: Vec<u8> = (0..12)
        .flat_map(|i| [(i % 5) as f32 / 4.0, 0.5, 1.0 - i as f32 / 11.0, 1.0])
        .flat_map(f32::to_ne_bytes)
        .collect();
    data[256..256 + fl.len()].copy_from_slice(&fl);
    buffer(gl, GL_PIXEL_UNPACK_BUFFER, &data);
    gl.window_pos_2i(1, 1);
    gl.draw_pixels_pbo(5, 4, GL_RGBA, GL_UNSIGNED_BYTE, 7);
    gl.window_pos_2i(10, 1);
    gl.draw_pixels_pbo(4, 3, GL_RGBA, GL_FLOAT, 256);
    err(gl, out, "glDrawPixels from the buffer");
    read_rgba(gl, out, "after glDrawPixels", 0, 0, 16, 6);
    // A bitmap 12 x 5 (2 bytes a row at alignment 1).
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.color_4ub(250, 200, 10, 255);
    gl.window_pos_2i(2, 8);
    gl.bitmap_pbo(12, 5, 0.0, 0.0, 3.0, 0.0, 33);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 4);
    err(gl, out, "glBitmap from the buffer");
    read_rgba(gl, out, "after glBitmap", 0, 7, 16, 7);
    // The polygon stipple from offset 500.
    gl.polygon_stipple_pbo(500);
    err(gl, out, "glPolygonStipple from the buffer");
    gl.enable(GL_POLYGON_STIPPLE);
    gl.color_4ub(20, 40, 250, 255);
    quad(gl, 0.0, 16.0, 40.0, 24.0, 0.0);
    gl.disable(GL_POLYGON_STIPPLE);
    read_rgba(gl, out, "after the stippled quad", 0, 16, 40, 8);
    let mut mask = vec![0u8; 128];
    gl.bind_buffer(GL_PIXEL_UNPACK_BUFFER, 0);
    gl.get_polygon_stipple(&mut mask);
    exact(
        out,
        "stipple".into(),
        mask.iter().map(|&v| v as f64).collect(),
    );
    // Pixel maps.
    let maps: Vec<u8> = [0.0f32, 0.5, 0.75, 1.0]
        .iter()
        .flat_map(|v| v.to_ne_bytes())
        .chain([7u16, 3, 1, 0].iter().flat_map(|v| v.to_ne_bytes()))
        .collect();
    buffer(gl, GL_PIXEL_UNPACK_BUFFER, &maps);
    gl.pixel_mapfv_pbo(GL_PIXEL_MAP_G_TO_G, 4, 0);
    gl.pixel_mapusv_pbo(GL_PIXEL_MAP_I_TO_I, 4, 16);
    err(gl, out, "glPixelMap from the buffer");
    let mut f = [0.0f32; 4];
    gl.get_pixel_mapfv(GL_PIXEL_MAP_G_TO_G, &mut f);
    let mut u = [0u16; 4];
    gl.get_pixel_mapusv(GL_PIXEL_MAP_I_TO_I, &mut u);
    exact(
        out,
        "pixel maps".into(),
        f.iter()
            .map(|&v| v as f64)
            .chain(u.iter().map(|&v| v as f64))
            .collect(),
    );
}

fn pbo_errors(gl: &mut dyn Gl, out: &mut Answers) {
    let n = 256usize;
    let unpack = buffer(gl, GL_PIXEL_UNPACK_BUFFER, &pattern(n, 7));
    texture(gl, GL_TEXTURE_2D);
    gl.tex_image_2d_pbo(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        4,
        4,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        0,
    );
    err(gl, out, "a 4x4 image from the buffer");
    // Past the end: 64 bytes at 200 of 256.
    gl.tex_image_2d_pbo(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        8,
        8,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        200,
    );
    err(gl, out, "glTexImage2D past the end");
    let mut w = [-1];
    gl.get_tex_level_parameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &mut w);
    exact(out, "width kept".into(), vec![w[0] as f64]);
    gl.tex_sub_image_2d_pbo(
        GL_TEXTURE_2D,
        0,
        0,
        0,
        4,
        4,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        256 - 60,
    );
    err(gl, out, "glTexSubImage2D past the end");
    gl.tex_sub_image_2d_pbo(
        GL_TEXTURE_2D,
        0,
        0,
        0,
        4,
        4,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        1000,
    );
    err(gl, out, "glTexSubImage2D at an offset past the end");
    tex_image_rgba(gl, out, GL_TEXTURE_2D, "image kept", 16);
    gl.draw_pixels_pbo(9, 8, GL_RGBA, GL_UNSIGNED_BYTE, 0);
    err(gl, out, "glDrawPixels past the end");
    gl.bitmap_pbo(64, 64, 0.0, 0.0, 0.0, 0.0, 0);
    err(gl, out, "glBitmap past the end");
    gl.polygon_stipple_pbo(200);
    err(gl, out, "glPolygonStipple past the end");
    gl.compressed_tex_image_2d_pbo(
        GL_TEXTURE_2D,
        0,
        GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
        8,
        8,
        0,
        32,
        240,
    );
    err(gl, out, "glCompressedTexImage2D past the end");
    gl.tex_image_2d_pbo(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        4,
        4,
        0,
        GL_RGBA,
        GL_BYTE + 100,
        0,
    );
    err(gl, out, "glTexImage2D with a bad type");
    // Offsets that are not a multiple of the data type's size (issue 14).
    gl.tex_image_2d_pbo(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_FLOAT,
        2,
    );
    err(gl, out, "glTexImage2D of floats at offset 2");
    gl.tex_sub_image_2d_pbo(
        GL_TEXTURE_2D,
        0,
        0,
        0,
        1,
        1,
        GL_RGB,
        GL_UNSIGNED_SHORT_5_6_5,
        3,
    );
    err(gl, out, "glTexSubImage2D of 5_6_5 at offset 3");
    gl.tex_sub_image_2d_pbo(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 3);
    err(gl, out, "glTexSubImage2D of bytes at offset 3");
    // Mapped.
    gl.map_buffer(GL_PIXEL_UNPACK_BUFFER, GL_WRITE_ONLY);
    gl.tex_sub_image_2d_pbo(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 0);
    err(gl, out, "glTexSubImage2D from a mapped buffer");
    gl.unmap_buffer(GL_PIXEL_UNPACK_BUFFER);
    // Packing.
    buffer(gl, GL_PIXEL_PACK_BUFFER, &[0x33; 64]);
    gl.read_pixels_pbo(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, 4);
    err(gl, out, "glReadPixels past the end");
    gl.get_tex_image_pbo(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, 0);
    err(gl, out, "glGetTexImage past the end");
    gl.get_polygon_stipple_pbo(0);
    err(gl, out, "glGetPolygonStipple past the end");
    gl.read_pixels_pbo(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT, 1);
    err(gl, out, "glReadPixels of shorts at offset 1");
    gl.map_buffer(GL_PIXEL_PACK_BUFFER, GL_READ_ONLY);
    gl.read_pixels_pbo(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 0);
    err(gl, out, "glReadPixels into a mapped buffer");
    gl.unmap_buffer(GL_PIXEL_PACK_BUFFER);
    buffer_bytes(gl, out, GL_PIXEL_PACK_BUFFER, "pack buffer kept", 64);
    gl.read_pixels_pbo(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, 0);
    err(gl, out, "glReadPixels that fits");
    gl.delete_buffers(1, &[unpack]);
}

fn pbo_display_lists(gl: &mut dyn Gl, out: &mut Answers) {
    pixel_space(gl, super::SIZE, super::SIZE);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    buffer(gl, GL_PIXEL_UNPACK_BUFFER, &pattern(256, 21));
    texture(gl, GL_TEXTURE_2D);
    let list = gl.gen_lists(1);
    gl.new_list(list, GL_COMPILE);
    gl.tex_image_2d_pbo(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        16,
    );
    gl.window_pos_2i(1, 1);
    gl.draw_pixels_pbo(3, 3, GL_RGBA, GL_UNSIGNED_BYTE, 40);
    gl.color_4ub(255, 255, 0, 255);
    gl.window_pos_2i(6, 1);
    gl.bitmap_pbo(8, 3, 0.0, 0.0, 0.0, 0.0, 100);
    gl.end_list();
    err(gl, out, "compiling the list");
    // Changed and unbound: the list keeps the compiled data.
    gl.buffer_sub_data(GL_PIXEL_UNPACK_BUFFER, 0, 256, Some(&[0u8; 256]));
    gl.bind_buffer(GL_PIXEL_UNPACK_BUFFER, 0);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[9, 9, 9, 9]),
    );
    gl.call_list(list);
    err(gl, out, "calling the list");
    tex_image_rgba(gl, out, GL_TEXTURE_2D, "texture from the list", 4);
    read_rgba(gl, out, "pixels and bitmap from the list", 0, 0, 16, 5);
}

fn map_buffer_range(gl: &mut dyn Gl, out: &mut Answers) {
    let state = |gl: &mut dyn Gl, out: &mut Answers, target: GLenum| {
        for p in [
            GL_BUFFER_MAPPED,
            GL_BUFFER_ACCESS,
            GL_BUFFER_ACCESS_FLAGS,
            GL_BUFFER_MAP_OFFSET,
            GL_BUFFER_MAP_LENGTH,
        ] {
            buffer_param(gl, out, target, p);
        }
        err(gl, out, "buffer parameters");
    };
    let b = buffer(gl, GL_ARRAY_BUFFER, &pattern(64, 1));
    let p = gl.map_buffer_range(GL_ARRAY_BUFFER, 16, 32, GL_MAP_READ_BIT | GL_MAP_WRITE_BIT);
    err(gl, out, "glMapBufferRange(16, 32, read and write)");
    exact(
        out,
        "pointer not null".into(),
        vec![(p.0 != 0) as i32 as f64],
    );
    state(gl, out, GL_ARRAY_BUFFER);
    let mut q = 0usize;
    gl.get_buffer_pointerv(
        GL_ARRAY_BUFFER,
        GL_BUFFER_MAP_POINTER,
        ClientPtr(&mut q as *mut usize as usize),
    );
    exact(
        out,
        "GL_BUFFER_MAP_POINTER is the range's start".into(),
        vec![(q == p.0) as i32 as f64],
    );
    gl.map_buffer_range(GL_ARRAY_BUFFER, 0, 8, GL_MAP_READ_BIT);
    err(gl, out, "mapping a mapped buffer");
    gl.flush_mapped_buffer_range(GL_ARRAY_BUFFER, 0, 4);
    err(gl, out, "flushing without GL_MAP_FLUSH_EXPLICIT_BIT");
    let r = gl.unmap_buffer(GL_ARRAY_BUFFER);
    exact(out, "glUnmapBuffer".into(), vec![r as f64]);
    state(gl, out, GL_ARRAY_BUFFER);
    gl.flush_mapped_buffer_range(GL_ARRAY_BUFFER, 0, 4);
    err(gl, out, "flushing an unmapped buffer");
    // Explicit flushes.
    gl.map_buffer_range(
        GL_ARRAY_BUFFER,
        8,
        40,
        GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT | GL_MAP_INVALIDATE_RANGE_BIT,
    );
    err(gl, out, "mapping for explicit flushes");
    state(gl, out, GL_ARRAY_BUFFER);
    gl.flush_mapped_buffer_range(GL_ARRAY_BUFFER, 0, 8);
    err(gl, out, "flush inside");
    gl.flush_mapped_buffer_range(GL_ARRAY_BUFFER, 36, 4);
    err(gl, out, "flush at the end");
    gl.flush_mapped_buffer_range(GL_ARRAY_BUFFER, 36, 8);
    err(gl, out, "flush past the mapping");
    gl.flush_mapped_buffer_range(GL_ARRAY_BUFFER, -1, 4);
    err(gl, out, "flush at a negative offset");
    gl.flush_mapped_buffer_range(GL_ARRAY_BUFFER, 0, -4);
    err(gl, out, "flush of a negative length");
    gl.unmap_buffer(GL_ARRAY_BUFFER);
    // glMapBuffer's flags.
    for access in [GL_READ_ONLY, GL_WRITE_ONLY, GL_READ_WRITE] {
        gl.map_buffer(GL_ARRAY_BUFFER, access);
        state(gl, out, GL_ARRAY_BUFFER);
        gl.unmap_buffer(GL_ARRAY_BUFFER);
    }
    // Errors, each leaving the buffer unmapped.
    let bad: [(isize, isize, u32, &str); 9] = [
        (-1, 4, GL_MAP_READ_BIT, "negative offset"),
        (0, -4, GL_MAP_READ_BIT, "negative length"),
        (60, 8, GL_MAP_READ_BIT, "range past the end"),
        (0, 4, 0, "neither read nor write"),
        (
            0,
            4,
            GL_MAP_READ_BIT | GL_MAP_INVALIDATE_RANGE_BIT,
            "read with invalidate range",
        ),
        (
            0,
            4,
            GL_MAP_READ_BIT | GL_MAP_INVALIDATE_BUFFER_BIT,
            "read with invalidate buffer",
        ),
        (
            0,
            4,
            GL_MAP_READ_BIT | GL_MAP_UNSYNCHRONIZED_BIT,
            "read unsynchronized",
        ),
        (
            0,
            4,
            GL_MAP_READ_BIT | GL_MAP_FLUSH_EXPLICIT_BIT,
            "explicit flush without write",
        ),
        (0, 4, GL_MAP_WRITE_BIT | 0x100, "an unknown bit"),
    ];
    for (offset, length, access, what) in bad {
        let p = gl.map_buffer_range(GL_ARRAY_BUFFER, offset, length, access);
        err(gl, out, what);
        exact(out, format!("{what}: null"), vec![(p.0 == 0) as i32 as f64]);
        buffer_param(gl, out, GL_ARRAY_BUFFER, GL_BUFFER_MAPPED);
    }
    // A pixel target, a bad target, buffer 0.
    buffer(gl, GL_PIXEL_UNPACK_BUFFER, &pattern(32, 2));
    gl.map_buffer_range(
        GL_PIXEL_UNPACK_BUFFER,
        4,
        4,
        GL_MAP_WRITE_BIT | GL_MAP_UNSYNCHRONIZED_BIT,
    );
    err(gl, out, "mapping a range of the unpack buffer");
    state(gl, out, GL_PIXEL_UNPACK_BUFFER);
    gl.unmap_buffer(GL_PIXEL_UNPACK_BUFFER);
    gl.map_buffer_range(GL_TEXTURE_2D, 0, 4, GL_MAP_READ_BIT);
    err(gl, out, "a bad target");
    gl.flush_mapped_buffer_range(GL_TEXTURE_2D, 0, 4);
    err(gl, out, "flush of a bad target");
    gl.bind_buffer(GL_ARRAY_BUFFER, 0);
    gl.map_buffer_range(GL_ARRAY_BUFFER, 0, 4, GL_MAP_READ_BIT);
    err(gl, out, "buffer 0");
    gl.flush_mapped_buffer_range(GL_ARRAY_BUFFER, 0, 4);
    err(gl, out, "flush of buffer 0");
    gl.delete_buffers(1, &[b]);
}

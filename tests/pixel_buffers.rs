//! ARB_pixel_buffer_object and ARB_map_buffer_range where the extension texts and Mesa 22
//! differ (the agreeing cases are in `conformance/src/state_cases/pbo.rs`), each expected value
//! from the text quoted beside it; and properties of the `*_pbo` route that hold for any data:
//! a pixel command from a buffer gives what the same command from client memory gives, and an
//! access refused by the range rule changes nothing.

use tilegl::api::ClientPtr;
use tilegl::enums::*;
use tilegl::{Context, Gl};

fn ctx() -> Context {
    Context::new(16, 16)
}

fn buffer(gl: &mut Context, target: GLenum, data: &[u8]) -> u32 {
    let mut b = [0];
    gl.gen_buffers(1, &mut b);
    gl.bind_buffer(target, b[0]);
    gl.buffer_data(target, data.len() as isize, Some(data), GL_STREAM_DRAW);
    b[0]
}

fn binding(gl: &mut Context, pname: GLenum) -> i32 {
    let mut v = [-1];
    gl.get_integerv(pname, &mut v);
    v[0]
}

fn pattern(n: usize) -> Vec<u8> {
    (0..n).map(|i| (i * 29 + 7) as u8).collect()
}

/// Section 2.9 (as ARB_pixel_buffer_object words it): deleting a bound buffer "reverts to zero"
/// every binding to it, and a deleted name names no buffer. A pixel-store stack entry saved
/// before the deletion does not bring the name back (Mesa 22 rebinds the deleted name).
#[test]
fn popping_the_pixel_store_bit_does_not_rebind_a_deleted_buffer() {
    let mut gl = ctx();
    let pack = buffer(&mut gl, GL_PIXEL_PACK_BUFFER, &[0; 16]);
    let unpack = buffer(&mut gl, GL_PIXEL_UNPACK_BUFFER, &[0; 16]);
    gl.push_client_attrib(GL_CLIENT_PIXEL_STORE_BIT);
    gl.delete_buffers(1, &[pack]);
    assert_eq!(binding(&mut gl, GL_PIXEL_PACK_BUFFER_BINDING), 0);
    gl.pop_client_attrib();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(binding(&mut gl, GL_PIXEL_PACK_BUFFER_BINDING), 0);
    // The live one is restored.
    assert_eq!(
        binding(&mut gl, GL_PIXEL_UNPACK_BUFFER_BINDING),
        unpack as i32
    );
}

/// ARB_map_buffer_range: "INVALID_VALUE is generated if <offset> or <length> is negative, or
/// if offset+length is greater than the value of BUFFER_SIZE"; a zero length is none of the
/// listed errors (Mesa 22 refuses it with GL_INVALID_OPERATION, as OpenGL 4.5 does).
#[test]
fn a_zero_length_range_maps() {
    let mut gl = ctx();
    buffer(&mut gl, GL_ARRAY_BUFFER, &[1; 16]);
    let p = gl.map_buffer_range(GL_ARRAY_BUFFER, 16, 0, GL_MAP_READ_BIT);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_ne!(p, ClientPtr(0));
    let mut v = [-1];
    gl.get_buffer_parameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_OFFSET, &mut v);
    assert_eq!(v[0], 16);
    gl.get_buffer_parameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_LENGTH, &mut v);
    assert_eq!(v[0], 0);
    assert_eq!(gl.unmap_buffer(GL_ARRAY_BUFFER), GL_TRUE as u8);
}

/// Section 6.1.3: `GetPixelMapuiv` of an index map returns the indices (Mesa 22 converts them
/// as colour components, 1 becoming 0xffffffff); into a pack buffer as into client memory.
#[test]
fn index_maps_read_back_as_indices_into_a_pack_buffer() {
    let mut gl = ctx();
    gl.pixel_mapuiv(GL_PIXEL_MAP_I_TO_I, 4, &[1, 5, 9, 200]);
    buffer(&mut gl, GL_PIXEL_PACK_BUFFER, &[0xee; 24]);
    gl.get_pixel_mapuiv_pbo(GL_PIXEL_MAP_I_TO_I, 4);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut b = [0u8; 24];
    gl.get_buffer_sub_data(GL_PIXEL_PACK_BUFFER, 0, 24, &mut b);
    let mut want = vec![0xee; 4];
    for v in [1u32, 5, 9, 200] {
        want.extend(v.to_ne_bytes());
    }
    want.extend([0xee; 4]);
    assert_eq!(b.to_vec(), want);
}

/// A write through the `glMapBufferRange` mapping lands at the range's offset of the store
/// (the Rust form of the pointer: `Context::mapped_buffer_mut`), and the bytes outside the
/// range are untouched.
#[test]
fn writes_through_a_mapped_range_land_at_its_offset() {
    let mut gl = ctx();
    buffer(&mut gl, GL_PIXEL_UNPACK_BUFFER, &[0; 32]);
    gl.map_buffer_range(GL_PIXEL_UNPACK_BUFFER, 8, 4, GL_MAP_WRITE_BIT);
    {
        let mut m = gl
            .mapped_buffer_mut(GL_PIXEL_UNPACK_BUFFER)
            .expect("mapped");
        assert_eq!(m.len(), 4);
        m.copy_from_slice(&[1, 2, 3, 4]);
    }
    gl.unmap_buffer(GL_PIXEL_UNPACK_BUFFER);
    let mut b = [9u8; 32];
    gl.get_buffer_sub_data(GL_PIXEL_UNPACK_BUFFER, 0, 32, &mut b);
    let mut want = [0u8; 32];
    want[8..12].copy_from_slice(&[1, 2, 3, 4]);
    assert_eq!(b, want);
}

/// For several unpack states and offsets: the texture a buffer gives is the texture the same
/// bytes in client memory give, and `glReadPixels` into a buffer writes exactly the bytes it
/// writes into client memory at the offset, leaving the others.
#[test]
fn buffer_routes_equal_client_routes() {
    for (row_length, skip_pixels, skip_rows, alignment, offset) in
        [(0, 0, 0, 4, 0usize), (9, 2, 1, 1, 12), (11, 1, 3, 8, 40)]
    {
        let data = pattern(2048);
        let setup = |gl: &mut Context| {
            gl.pixel_storei(GL_UNPACK_ROW_LENGTH, row_length);
            gl.pixel_storei(GL_UNPACK_SKIP_PIXELS, skip_pixels);
            gl.pixel_storei(GL_UNPACK_SKIP_ROWS, skip_rows);
            gl.pixel_storei(GL_UNPACK_ALIGNMENT, alignment);
            gl.pixel_storei(GL_PACK_ROW_LENGTH, row_length);
            gl.pixel_storei(GL_PACK_ALIGNMENT, alignment);
            let mut t = [0];
            gl.gen_textures(1, &mut t);
            gl.bind_texture(GL_TEXTURE_2D, t[0]);
        };
        let mut a = ctx();
        setup(&mut a);
        a.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGB8 as i32,
            5,
            7,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            Some(&data[offset..]),
        );
        let mut b = ctx();
        setup(&mut b);
        buffer(&mut b, GL_PIXEL_UNPACK_BUFFER, &data);
        b.tex_image_2d_pbo(
            GL_TEXTURE_2D,
            0,
            GL_RGB8 as i32,
            5,
            7,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            offset,
        );
        assert_eq!(b.get_error(), GL_NO_ERROR);
        let (mut ta, mut tb) = (vec![0u8; 5 * 7 * 4], vec![0u8; 5 * 7 * 4]);
        a.pixel_storei(GL_PACK_ROW_LENGTH, 0);
        b.pixel_storei(GL_PACK_ROW_LENGTH, 0);
        a.pixel_storei(GL_PACK_ALIGNMENT, 4);
        b.pixel_storei(GL_PACK_ALIGNMENT, 4);
        a.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut ta);
        b.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut tb);
        assert_eq!(
            ta, tb,
            "texture, unpack state {row_length} {skip_pixels} {skip_rows}"
        );
        // Read back the textured window both ways.
        for gl in [&mut a, &mut b] {
            gl.pixel_storei(GL_PACK_ROW_LENGTH, row_length);
            gl.pixel_storei(GL_PACK_ALIGNMENT, alignment);
            gl.clear_color(0.1, 0.5, 0.9, 1.0);
            gl.clear(GL_COLOR_BUFFER_BIT);
            gl.window_pos_2i(2, 3);
            gl.bind_buffer(GL_PIXEL_UNPACK_BUFFER, 0);
            gl.draw_pixels(5, 7, GL_RGB, GL_UNSIGNED_BYTE, Some(&data[offset..]));
        }
        let mut client = vec![0x77u8; 1024];
        a.read_pixels(1, 1, 6, 8, GL_RGBA, GL_UNSIGNED_BYTE, &mut client[offset..]);
        buffer(&mut b, GL_PIXEL_PACK_BUFFER, &[0x77; 1024]);
        b.read_pixels_pbo(1, 1, 6, 8, GL_RGBA, GL_UNSIGNED_BYTE, offset);
        assert_eq!(b.get_error(), GL_NO_ERROR);
        let mut packed = vec![0u8; 1024];
        b.get_buffer_sub_data(GL_PIXEL_PACK_BUFFER, 0, 1024, &mut packed);
        assert_eq!(
            client, packed,
            "read-back, pack state {row_length} {alignment}"
        );
    }
}

/// Issue 10 of ARB_pixel_buffer_object: a command whose access would leave the buffer is
/// ignored whole; for every end of the access from one byte short to one byte over, the call
/// either succeeds fully or records GL_INVALID_OPERATION and changes neither the buffer nor
/// the texture.
#[test]
fn the_range_rule_is_exact_and_refusals_change_nothing() {
    let image = 4 * 3 * 4; // 4 x 3 RGBA bytes
    for size in [image - 1, image, image + 1] {
        let mut gl = ctx();
        let mut t = [0];
        gl.gen_textures(1, &mut t);
        gl.bind_texture(GL_TEXTURE_2D, t[0]);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA8 as i32,
            4,
            3,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&[5; 48]),
        );
        buffer(&mut gl, GL_PIXEL_UNPACK_BUFFER, &pattern(size));
        gl.tex_sub_image_2d_pbo(GL_TEXTURE_2D, 0, 0, 0, 4, 3, GL_RGBA, GL_UNSIGNED_BYTE, 0);
        let e = gl.get_error();
        let mut tex = vec![0u8; 48];
        gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut tex);
        if size < image {
            assert_eq!(e, GL_INVALID_OPERATION, "size {size}");
            assert_eq!(tex, vec![5; 48]);
        } else {
            assert_eq!(e, GL_NO_ERROR, "size {size}");
            assert_eq!(tex, pattern(size)[..48].to_vec());
        }
        buffer(&mut gl, GL_PIXEL_PACK_BUFFER, &vec![0xcc; size]);
        gl.get_tex_image_pbo(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, 0);
        let e = gl.get_error();
        let mut back = vec![0u8; size];
        gl.get_buffer_sub_data(GL_PIXEL_PACK_BUFFER, 0, size as isize, &mut back);
        if size < image {
            assert_eq!(e, GL_INVALID_OPERATION);
            assert_eq!(back, vec![0xcc; size]);
        } else {
            assert_eq!(e, GL_NO_ERROR);
            assert_eq!(&back[..48], &tex[..]);
        }
    }
}

/// The `*_pbo` methods with no buffer bound have nothing to read or write: GL_INVALID_OPERATION
/// (the C ABI never calls them then), and no panic for offsets near `usize::MAX`.
#[test]
fn offsets_without_a_buffer_or_past_usize_are_refused() {
    let mut gl = ctx();
    gl.draw_pixels_pbo(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 0);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.read_pixels_pbo(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 0);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    buffer(&mut gl, GL_PIXEL_UNPACK_BUFFER, &[0; 8]);
    buffer(&mut gl, GL_PIXEL_PACK_BUFFER, &[0; 8]);
    gl.draw_pixels_pbo(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, usize::MAX - 1);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.read_pixels_pbo(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, usize::MAX - 3);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.pixel_mapfv_pbo(GL_PIXEL_MAP_R_TO_R, i32::MAX, 0);
    assert_ne!(gl.get_error(), GL_NO_ERROR);
}

//! Colour-index texture uploads (`GL_COLOR_INDEX`, also as `GL_BITMAP` bits, through the index
//! shift/offset and the `I_TO_*` maps, sections 3.6.5 and 3.8.1) and depth-stencil textures
//! that keep their stencil, checked against values computed from the specification here.

use tilegl::enums::*;
mod common;
use common::{ctx, level_param, read_rgba_f32};
use tilegl::{Context, Gl};

/// Colour-index texture images (section 3.8.1 takes the client data as glDrawPixels does,
/// section 3.6.4; the indices are shifted, offset and converted by the I_TO_* maps, 3.6.5):
/// every texel computed here from those rules, for GL_BITMAP rows under ROW_LENGTH,
/// SKIP_PIXELS, SKIP_ROWS and LSB_FIRST, byte indices of a 3D image under SKIP_IMAGES and
/// IMAGE_HEIGHT, and a sub-image.
#[test]
fn color_index_images_go_through_the_index_maps() {
    let mut gl = ctx();
    // Maps of 8 entries (indices wrap modulo 8): R = i/7, G = 1 - i/7, B = (i % 2), A = 1.
    let r: Vec<f32> = (0..8).map(|i| i as f32 / 7.0).collect();
    let g: Vec<f32> = (0..8).map(|i| 1.0 - i as f32 / 7.0).collect();
    let b: Vec<f32> = (0..8).map(|i| (i % 2) as f32).collect();
    gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_R, 8, &r);
    gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_G, 8, &g);
    gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_B, 8, &b);
    gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_A, 1, &[1.0]);
    let texel = |i: i64| {
        let k = (i & 7) as usize;
        [r[k], g[k], b[k], 1.0]
    };
    let close = |got: &[f32], want: &[[f32; 4]]| {
        assert_eq!(got.len(), want.len() * 4);
        for (n, (g, w)) in got.chunks(4).zip(want).enumerate() {
            for k in 0..4 {
                assert!(
                    (g[k] - w[k]).abs() < 1.0 / 255.0,
                    "texel {n}: {g:?} vs {w:?}"
                );
            }
        }
    };
    // Bitmap: 6x3 bits, rows of ROW_LENGTH 20 bits padded to ALIGNMENT 2 (4 bytes), SKIP_ROWS
    // 1, SKIP_PIXELS 5, LSB first; bit set = index 1 (shifted by 2: index 4), clear = 0 + 2.
    let bits: Vec<u8> = (0..16u8).map(|i| i.wrapping_mul(73) ^ 0x5A).collect();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 2);
    gl.pixel_storei(GL_UNPACK_ROW_LENGTH, 20);
    gl.pixel_storei(GL_UNPACK_SKIP_ROWS, 1);
    gl.pixel_storei(GL_UNPACK_SKIP_PIXELS, 5);
    gl.pixel_storei(GL_UNPACK_LSB_FIRST, 1);
    gl.pixel_transferi(GL_INDEX_SHIFT, 2);
    gl.pixel_transferi(GL_INDEX_OFFSET, 2);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        6,
        3,
        0,
        GL_COLOR_INDEX,
        GL_BITMAP,
        Some(&bits),
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let want: Vec<[f32; 4]> = (0..3)
        .flat_map(|y| (0..6).map(move |x| (y, x)))
        .map(|(y, x)| {
            let bit = 5 + x;
            let byte = bits[(1 + y) * 4 + bit / 8];
            texel(((byte >> (bit % 8)) & 1) as i64 * 4 + 2)
        })
        .collect();
    close(&read_rgba_f32(&mut gl, GL_TEXTURE_2D, 18), &want);
    for p in [
        GL_UNPACK_ROW_LENGTH,
        GL_UNPACK_SKIP_ROWS,
        GL_UNPACK_SKIP_PIXELS,
        GL_UNPACK_LSB_FIRST,
    ] {
        gl.pixel_storei(p, 0);
    }
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    // A sub-image of signed bytes (shift -1: arithmetic right shift, offset 2) at (2, 1).
    let sub: [i8; 4] = [-5, 9, 3, 14];
    gl.pixel_transferi(GL_INDEX_SHIFT, -1);
    gl.tex_sub_image_2d(
        GL_TEXTURE_2D,
        0,
        2,
        1,
        2,
        2,
        GL_COLOR_INDEX,
        GL_BYTE,
        Some(&sub.map(|v| v as u8)),
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut want2 = want.clone();
    for (k, &v) in sub.iter().enumerate() {
        want2[(1 + k / 2) * 6 + 2 + k % 2] = texel((v as i64 >> 1) + 2);
    }
    close(&read_rgba_f32(&mut gl, GL_TEXTURE_2D, 18), &want2);
    // 3D: 2x2x2 bytes, IMAGE_HEIGHT 3 rows per image, SKIP_IMAGES 1; no shift, offset 0.
    gl.pixel_transferi(GL_INDEX_SHIFT, 0);
    gl.pixel_transferi(GL_INDEX_OFFSET, 0);
    gl.pixel_storei(GL_UNPACK_IMAGE_HEIGHT, 3);
    gl.pixel_storei(GL_UNPACK_SKIP_IMAGES, 1);
    let vol: Vec<u8> = (0..3 * 6u8).collect();
    gl.tex_image_3d(
        GL_TEXTURE_3D,
        0,
        GL_RGBA as i32,
        2,
        2,
        2,
        0,
        GL_COLOR_INDEX,
        GL_UNSIGNED_BYTE,
        Some(&vol),
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let want3: Vec<[f32; 4]> = (0..8)
        .map(|n| {
            let (x, y, z) = (n % 2, n / 2 % 2, n / 4);
            texel(vol[(1 + z) * 6 + y * 2 + x] as i64)
        })
        .collect();
    close(&read_rgba_f32(&mut gl, GL_TEXTURE_3D, 8), &want3);
    // Too little data for the skipped image: GL_INVALID_VALUE (the Rust API's length check).
    gl.tex_image_3d(
        GL_TEXTURE_3D,
        0,
        GL_RGBA as i32,
        2,
        2,
        2,
        0,
        GL_COLOR_INDEX,
        GL_UNSIGNED_BYTE,
        Some(&vol[..14]),
    );
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
}

/// Errors of colour-index uploads: a packed type with GL_COLOR_INDEX is INVALID_OPERATION (the
/// packed types take RGB/RGBA formats only), a depth internal format INVALID_OPERATION (index
/// data is colour data), GL_BITMAP with a colour format INVALID_ENUM; GL_COLOR_INDEX is not a
/// format glGetTexImage returns (INVALID_ENUM). Each leaves the image as it was.
#[test]
fn color_index_upload_errors() {
    let mut gl = ctx();
    let data = [1u8; 64];
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&data[..16]),
    );
    let calls: [(GLenum, GLenum, i32, GLenum); 4] = [
        (
            GL_COLOR_INDEX,
            GL_UNSIGNED_SHORT_5_6_5,
            GL_RGB as i32,
            GL_INVALID_OPERATION,
        ),
        (
            GL_COLOR_INDEX,
            GL_UNSIGNED_BYTE,
            GL_DEPTH_COMPONENT as i32,
            GL_INVALID_OPERATION,
        ),
        (GL_RGBA, GL_BITMAP, GL_RGBA as i32, GL_INVALID_ENUM),
        (GL_COLOR_INDEX, GL_DOUBLE, GL_RGBA as i32, GL_INVALID_ENUM),
    ];
    for (format, ty, internal, err) in calls {
        gl.tex_image_2d(GL_TEXTURE_2D, 0, internal, 4, 4, 0, format, ty, Some(&data));
        assert_eq!(gl.get_error(), err, "format {format:#x} type {ty:#x}");
        assert_eq!(level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 2);
    }
    let mut out = [0u8; 16];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, &mut out);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
}

/// Depth-stencil textures (EXT_packed_depth_stencil, ARB_depth_buffer_float) keep 8 stencil
/// bits per texel: GL_TEXTURE_STENCIL_SIZE is 8, a GL_DEPTH_STENCIL upload's low byte (through
/// the index offset, section 3.6.5) reads back through glGetTexImage(GL_DEPTH_STENCIL), also
/// after a sub-image; a depth-only texture has no stencil to read (INVALID_OPERATION).
#[test]
fn depth_stencil_textures_keep_their_stencil() {
    let mut gl = ctx();
    let words = |w: &[u32]| -> Vec<u8> { w.iter().flat_map(|v| v.to_ne_bytes()).collect() };
    let read = |gl: &mut Context| -> Vec<u32> {
        let mut out = [0u8; 16];
        gl.get_tex_image(
            GL_TEXTURE_2D,
            0,
            GL_DEPTH_STENCIL_EXT,
            GL_UNSIGNED_INT_24_8_EXT,
            &mut out,
        );
        out.chunks(4)
            .map(|c| u32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
            .collect()
    };
    for (internal, depth_bits) in [
        (GL_DEPTH24_STENCIL8_EXT, 24),
        (GL_DEPTH32F_STENCIL8, 32),
        (GL_DEPTH_STENCIL_EXT, 24),
    ] {
        let data = words(&[0x0000_0103, 0x8000_00fe, 0xffff_ff40, 0x1234_5600]);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            internal as i32,
            2,
            2,
            0,
            GL_DEPTH_STENCIL_EXT,
            GL_UNSIGNED_INT_24_8_EXT,
            Some(&data),
        );
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert_eq!(
            level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE_EXT),
            8
        );
        assert_eq!(
            level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE),
            depth_bits
        );
        assert_eq!(
            read(&mut gl),
            [0x0000_0103, 0x8000_00fe, 0xffff_ff40, 0x1234_5600]
        );
        // A sub-image of the top row with an index offset of 5 (stencil wraps to 8 bits).
        gl.pixel_transferi(GL_INDEX_OFFSET, 5);
        let row = words(&[0x4000_00fd, 0x2000_0010]);
        gl.tex_sub_image_2d(
            GL_TEXTURE_2D,
            0,
            0,
            1,
            2,
            1,
            GL_DEPTH_STENCIL_EXT,
            GL_UNSIGNED_INT_24_8_EXT,
            Some(&row),
        );
        gl.pixel_transferi(GL_INDEX_OFFSET, 0);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert_eq!(
            read(&mut gl),
            [0x0000_0103, 0x8000_00fe, 0x4000_0002, 0x2000_0015]
        );
    }
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_DEPTH_COMPONENT24 as i32,
        2,
        2,
        0,
        GL_DEPTH_COMPONENT,
        GL_FLOAT,
        Some(&[0u8; 16]),
    );
    assert_eq!(
        level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE_EXT),
        0
    );
    read(&mut gl);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
}

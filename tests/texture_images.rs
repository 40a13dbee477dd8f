//! Texture images through the `Gl` trait: unpacking every packed type, component type and
//! format from hand-computed layouts, the pixel-store state, sub-images and `glGetTexImage`
//! packing, copies from the colour and depth buffers, compressed images, proxies.

use tilegl::enums::*;
mod common;
use common::{ctx, level_param, read_rgba_f32};
use tilegl::Gl;

/// Every packed type, unpacked from a hand-built bit pattern and read back as floats.
#[test]
fn unpack_packed_types_from_hand_computed_bit_layouts() {
    // (type, format, element value, expected RGBA)
    let cases: Vec<(GLenum, GLenum, u32, [f32; 4])> = vec![
        (
            GL_UNSIGNED_BYTE_3_3_2,
            GL_RGB,
            (0b101 << 5) | (0b010 << 2) | 0b11,
            [5.0 / 7.0, 2.0 / 7.0, 1.0, 1.0],
        ),
        (
            GL_UNSIGNED_BYTE_2_3_3_REV,
            GL_RGB,
            (0b10 << 6) | (0b011 << 3) | 0b001,
            [1.0 / 7.0, 3.0 / 7.0, 2.0 / 3.0, 1.0],
        ),
        (
            GL_UNSIGNED_SHORT_5_6_5,
            GL_RGB,
            (3 << 11) | (60 << 5) | 31,
            [3.0 / 31.0, 60.0 / 63.0, 1.0, 1.0],
        ),
        (
            GL_UNSIGNED_SHORT_5_6_5_REV,
            GL_RGB,
            (3 << 11) | (60 << 5) | 31,
            [1.0, 60.0 / 63.0, 3.0 / 31.0, 1.0],
        ),
        (
            GL_UNSIGNED_SHORT_4_4_4_4,
            GL_RGBA,
            0x1234,
            [1.0 / 15.0, 2.0 / 15.0, 3.0 / 15.0, 4.0 / 15.0],
        ),
        (
            GL_UNSIGNED_SHORT_4_4_4_4_REV,
            GL_RGBA,
            0x1234,
            [4.0 / 15.0, 3.0 / 15.0, 2.0 / 15.0, 1.0 / 15.0],
        ),
        (
            GL_UNSIGNED_SHORT_4_4_4_4,
            GL_BGRA,
            0x1234,
            [3.0 / 15.0, 2.0 / 15.0, 1.0 / 15.0, 4.0 / 15.0],
        ),
        (
            GL_UNSIGNED_SHORT_5_5_5_1,
            GL_RGBA,
            (1 << 11) | (2 << 6) | (3 << 1) | 1,
            [1.0 / 31.0, 2.0 / 31.0, 3.0 / 31.0, 1.0],
        ),
        (
            GL_UNSIGNED_SHORT_1_5_5_5_REV,
            GL_RGBA,
            1 | (2 << 5) | (3 << 10),
            [1.0 / 31.0, 2.0 / 31.0, 3.0 / 31.0, 0.0],
        ),
        (
            GL_UNSIGNED_INT_8_8_8_8,
            GL_RGBA,
            0x11223344,
            [17.0 / 255.0, 34.0 / 255.0, 51.0 / 255.0, 68.0 / 255.0],
        ),
        (
            GL_UNSIGNED_INT_8_8_8_8_REV,
            GL_RGBA,
            0x11223344,
            [68.0 / 255.0, 51.0 / 255.0, 34.0 / 255.0, 17.0 / 255.0],
        ),
        (
            GL_UNSIGNED_INT_10_10_10_2,
            GL_RGBA,
            (1 << 22) | (2 << 12) | (3 << 2) | 2,
            [1.0 / 1023.0, 2.0 / 1023.0, 3.0 / 1023.0, 2.0 / 3.0],
        ),
        (
            GL_UNSIGNED_INT_2_10_10_10_REV,
            GL_RGBA,
            1 | (2 << 10) | (3 << 20) | (1 << 30),
            [1.0 / 1023.0, 2.0 / 1023.0, 3.0 / 1023.0, 1.0 / 3.0],
        ),
    ];
    for (ty, fmt, v, want) in cases {
        let bytes: Vec<u8> = match ty {
            GL_UNSIGNED_BYTE_3_3_2 | GL_UNSIGNED_BYTE_2_3_3_REV => vec![v as u8],
            GL_UNSIGNED_INT_8_8_8_8
            | GL_UNSIGNED_INT_8_8_8_8_REV
            | GL_UNSIGNED_INT_10_10_10_2
            | GL_UNSIGNED_INT_2_10_10_10_REV => v.to_ne_bytes().to_vec(),
            _ => (v as u16).to_ne_bytes().to_vec(),
        };
        let mut gl = ctx();
        // RGBA16 keeps 10-bit components exactly enough (error < 1/65535 * 0.5).
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA16 as i32,
            1,
            1,
            0,
            fmt,
            ty,
            Some(&bytes),
        );
        assert_eq!(gl.get_error(), GL_NO_ERROR, "{ty:#x}");
        let got = read_rgba_f32(&mut gl, GL_TEXTURE_2D, 1);
        for c in 0..4 {
            assert!(
                (got[c] - want[c]).abs() < 1e-4,
                "{ty:#x} {fmt:#x}: {got:?} vs {want:?}"
            );
        }
        // Byte-swapped input gives the same result.
        let mut swapped = bytes.clone();
        swapped.reverse();
        gl.pixel_storei(GL_UNPACK_SWAP_BYTES, 1);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA16 as i32,
            1,
            1,
            0,
            fmt,
            ty,
            Some(&swapped),
        );
        let got = read_rgba_f32(&mut gl, GL_TEXTURE_2D, 1);
        for c in 0..4 {
            assert!((got[c] - want[c]).abs() < 1e-4, "swapped {ty:#x}");
        }
    }
}

#[test]
fn pixel_store_alignment_row_length_and_skips() {
    let mut gl = ctx();
    // A 2x2 RGB image inside a 3-pixel-wide client image, skipping 1 row and 1 pixel,
    // alignment 4: row stride = ceil(9 / 4) * 4 = 12 bytes.
    gl.pixel_storei(GL_UNPACK_ROW_LENGTH, 3);
    gl.pixel_storei(GL_UNPACK_SKIP_ROWS, 1);
    gl.pixel_storei(GL_UNPACK_SKIP_PIXELS, 1);
    let mut data = vec![0u8; 12 * 3];
    let put = |data: &mut Vec<u8>, x: usize, y: usize, v: u8| {
        let at = y * 12 + x * 3;
        data[at..at + 3].copy_from_slice(&[v, v, v]);
    };
    put(&mut data, 1, 1, 10);
    put(&mut data, 2, 1, 20);
    put(&mut data, 1, 2, 30);
    put(&mut data, 2, 2, 40);
    // Bytes needed: start 12 + 3, plus one row (12) plus 2 pixels (6) = 33.
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE as i32,
        2,
        2,
        0,
        GL_RGB,
        GL_UNSIGNED_BYTE,
        Some(&data[..32]),
    );
    assert_eq!(gl.get_error(), GL_INVALID_VALUE, "one byte short");
    assert_eq!(level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 0);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE as i32,
        2,
        2,
        0,
        GL_RGB,
        GL_UNSIGNED_BYTE,
        Some(&data[..33]),
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut out = [0u8; 4];
    gl.pixel_storei(GL_PACK_ALIGNMENT, 1);
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, &mut out);
    assert_eq!(out, [10, 20, 30, 40]);
    // 3D: skip images and image height.
    let mut gl = ctx();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.pixel_storei(GL_UNPACK_IMAGE_HEIGHT, 3);
    gl.pixel_storei(GL_UNPACK_SKIP_IMAGES, 1);
    // Image stride 2 * 3 = 6 bytes; image k (after the skipped one) starts at 6 * (k + 1).
    let mut data = vec![0u8; 6 * 3];
    for k in 0..2 {
        for j in 0..2 {
            for i in 0..2 {
                data[6 * (k + 1) + 2 * j + i] = (100 + 10 * k + 2 * j + i) as u8;
            }
        }
    }
    gl.tex_image_3d(
        GL_TEXTURE_3D,
        0,
        GL_LUMINANCE as i32,
        2,
        2,
        2,
        0,
        GL_LUMINANCE,
        GL_UNSIGNED_BYTE,
        Some(&data),
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut out = [0u8; 8];
    gl.pixel_storei(GL_PACK_ALIGNMENT, 1);
    gl.get_tex_image(GL_TEXTURE_3D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, &mut out);
    assert_eq!(out, [100, 101, 102, 103, 110, 111, 112, 113]);
}

#[test]
fn sub_images_and_get_tex_image_packing() {
    let mut gl = ctx();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.pixel_storei(GL_PACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        4,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[0; 32]),
    );
    gl.tex_sub_image_2d(
        GL_TEXTURE_2D,
        0,
        1,
        1,
        2,
        1,
        GL_BGRA,
        GL_UNSIGNED_BYTE,
        Some(&[1, 2, 3, 4, 5, 6, 7, 8]),
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut out = [0u8; 32];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut out);
    assert_eq!(&out[20..28], &[3, 2, 1, 4, 7, 6, 5, 8]);
    assert!(out[..20].iter().all(|&b| b == 0));
    // Packed output: 5_6_5 of (3/255 ...) -> rounding c * 31.
    let mut o = [0u8; 2];
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGB as i32,
        1,
        1,
        0,
        GL_RGB,
        GL_UNSIGNED_BYTE,
        Some(&[255, 128, 0]),
    );
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &mut o);
    let g = ((128.0f64 / 255.0) * 63.0).round() as u16;
    assert_eq!(u16::from_ne_bytes(o), (31 << 11) | (g << 5));
    // Out of range sub-image, negative size, missing level.
    for (x, y, w, h, err) in [
        (3, 0, 2, 1, GL_INVALID_VALUE),
        (-1, 0, 1, 1, GL_INVALID_VALUE),
        (0, 0, -1, 1, GL_INVALID_VALUE),
    ] {
        gl.tex_sub_image_2d(
            GL_TEXTURE_2D,
            0,
            x,
            y,
            w,
            h,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            Some(&[0; 64]),
        );
        assert_eq!(gl.get_error(), err);
    }
    gl.tex_sub_image_2d(
        GL_TEXTURE_2D,
        2,
        0,
        0,
        1,
        1,
        GL_RGB,
        GL_UNSIGNED_BYTE,
        Some(&[0; 3]),
    );
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn copy_tex_image_from_colour_and_depth_buffers() {
    let mut gl = ctx();
    gl.clear_color(1.0, 0.0, 0.0, 1.0);
    gl.clear_depth(0.25);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA, 2, 3, 4, 4, 0);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let px = read_rgba_f32(&mut gl, GL_TEXTURE_2D, 16);
    assert_eq!(&px[..4], &[1.0, 0.0, 0.0, 1.0]);
    // Sub-copy after a clear to green.
    gl.clear_color(0.0, 1.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.copy_tex_sub_image_2d(GL_TEXTURE_2D, 0, 1, 1, 0, 0, 2, 2);
    let px = read_rgba_f32(&mut gl, GL_TEXTURE_2D, 16);
    assert_eq!(&px[(4 + 1) * 4..(4 + 1) * 4 + 4], &[0.0, 1.0, 0.0, 1.0]);
    assert_eq!(&px[..4], &[1.0, 0.0, 0.0, 1.0]);
    // Depth.
    gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 0, 0, 2, 2, 0);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut out = [0u8; 16];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &mut out);
    let d = f32::from_ne_bytes([out[0], out[1], out[2], out[3]]);
    assert!((d - 0.25).abs() < 1e-6, "{d}");
    // 1D and 3D.
    gl.copy_tex_image_1d(GL_TEXTURE_1D, 0, GL_RGB8, 0, 0, 4, 0);
    assert_eq!(level_param(&mut gl, GL_TEXTURE_1D, 0, GL_TEXTURE_WIDTH), 4);
    gl.tex_image_3d(
        GL_TEXTURE_3D,
        0,
        GL_RGBA as i32,
        2,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    gl.copy_tex_sub_image_3d(GL_TEXTURE_3D, 0, 0, 0, 1, 0, 0, 2, 2);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut out = [0u8; 32];
    gl.get_tex_image(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut out);
    assert_eq!(&out[16..20], &[0, 255, 0, 255]);
    // Errors: 1..4 components (not among internalformat's values, an enum: section 2.5's
    // INVALID_ENUM, as llvmpipe), bad border.
    gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, 3, 0, 0, 2, 2, 0);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 2, 2, 2);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
}

#[test]
fn compressed_textures_round_trip_and_decode() {
    let mut gl = ctx();
    let mut n = [0i32; 1];
    let _ = &mut n;
    // A DXT1 block: color0 = red 0xF800, color1 = blue 0x001F, all indices 2.
    let mut block = vec![0x00, 0xF8, 0x1F, 0x00];
    block.extend_from_slice(&0xAAAA_AAAAu32.to_le_bytes());
    gl.compressed_tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
        4,
        4,
        0,
        8,
        Some(&block),
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(
        level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED),
        1
    );
    assert_eq!(
        level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE),
        8
    );
    assert_eq!(
        level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT),
        GL_COMPRESSED_RGB_S3TC_DXT1_EXT as i32
    );
    let mut back = [0u8; 8];
    gl.get_compressed_tex_image(GL_TEXTURE_2D, 0, &mut back);
    assert_eq!(&back[..], &block[..]);
    // Decoded: (2 red + blue) / 3.
    let mut px = [0u8; 64];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    assert_eq!(&px[..4], &[170, 0, 85, 255]);
    // Uncompressed data with a compressed internal format is encoded on upload.
    let mut img = Vec::new();
    for k in 0..16 {
        img.extend_from_slice(if k % 3 == 0 {
            &[0, 255, 0, 255]
        } else {
            &[255, 255, 255, 255]
        });
    }
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_COMPRESSED_RGBA_S3TC_DXT5_EXT as i32,
        4,
        4,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&img),
    );
    assert_eq!(
        level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE),
        16
    );
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    assert_eq!(&px[..], &img[..], "two-colour blocks encode exactly");
    // Generic compressed RGB picks DXT1.
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_COMPRESSED_RGB as i32,
        5,
        3,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[9; 60]),
    );
    assert_eq!(
        level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT),
        GL_COMPRESSED_RGB_S3TC_DXT1_EXT as i32
    );
    assert_eq!(
        level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE),
        2 * 8
    );
    // Sub-image rules: 4-aligned offsets; size multiple of 4 unless reaching the edge.
    gl.compressed_tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
        8,
        6,
        0,
        2 * 2 * 16,
        None,
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let blk = [0u8; 32];
    gl.compressed_tex_sub_image_2d(
        GL_TEXTURE_2D,
        0,
        4,
        4,
        4,
        2,
        GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
        16,
        Some(&blk),
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR, "reaches the bottom edge");
    gl.compressed_tex_sub_image_2d(
        GL_TEXTURE_2D,
        0,
        2,
        0,
        4,
        4,
        GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
        16,
        Some(&blk),
    );
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.compressed_tex_sub_image_2d(
        GL_TEXTURE_2D,
        0,
        0,
        0,
        4,
        4,
        GL_COMPRESSED_RGBA_S3TC_DXT1_EXT,
        8,
        Some(&blk),
    );
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION, "format differs");
    gl.compressed_tex_sub_image_2d(
        GL_TEXTURE_2D,
        0,
        0,
        0,
        4,
        4,
        GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
        15,
        Some(&blk),
    );
    assert_eq!(gl.get_error(), GL_INVALID_VALUE, "image size");
    gl.compressed_tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
        4,
        4,
        1,
        16,
        None,
    );
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION, "border");
    gl.compressed_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, 16, None);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.tex_image_1d(
        GL_TEXTURE_1D,
        0,
        GL_COMPRESSED_RGBA_S3TC_DXT1_EXT as i32,
        4,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    // Uncompressed image: no compressed data.
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        1,
        GL_RGBA as i32,
        4,
        3,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    gl.get_compressed_tex_image(GL_TEXTURE_2D, 1, &mut back);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn proxies_report_without_storing() {
    let mut gl = ctx();
    gl.tex_image_2d(
        GL_PROXY_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        64,
        32,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(
        level_param(&mut gl, GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH),
        64
    );
    assert_eq!(level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 0);
    gl.tex_image_2d(
        GL_PROXY_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        32768,
        32,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(
        level_param(&mut gl, GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH),
        0
    );
    gl.tex_image_3d(
        GL_PROXY_TEXTURE_3D,
        0,
        GL_RGBA8 as i32,
        4096,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    assert_eq!(
        level_param(&mut gl, GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH),
        0
    );
}

//! Pixel rectangles (sections 2.13, 3.6, 3.7, 4.3): raster position, glDrawPixels with zoom
//! and pixel transfer, glBitmap, glCopyPixels and glWindowPos, against the spec's rules
//! computed in the test; extreme zooms and errors.

mod common;

use common::{pixel, read_rgba, window_ortho};
use tilegl::enums::*;
use tilegl::{Context, Gl};

const W: i32 = 32;

fn setup() -> Context {
    let mut gl = Context::new(W, W);
    window_ortho(&mut gl);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl
}

fn image(w: usize, h: usize) -> Vec<u8> {
    (0..w * h)
        .flat_map(|k| {
            let (x, y) = (k % w, k / w);
            [(x * 40) as u8, (y * 50) as u8, (x * 7 + y * 13) as u8, 200]
        })
        .collect()
}

#[test]
fn draw_pixels_copies_the_image_at_the_raster_position() {
    let mut gl = setup();
    let img = image(5, 4);
    gl.raster_pos_2f(3.2, 6.7); // rounds to (3, 7)
    gl.draw_pixels(5, 4, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
    for y in 0..4 {
        for x in 0..5 {
            let k = (y * 5 + x) * 4;
            assert_eq!(
                pixel(&mut gl, 3 + x as i32, 7 + y as i32),
                [img[k], img[k + 1], img[k + 2], img[k + 3]]
            );
        }
    }
    assert_eq!(pixel(&mut gl, 2, 7), [0; 4]);
    assert_eq!(pixel(&mut gl, 8, 7), [0; 4]);
}

#[test]
fn zoom_replicates_and_flips_by_pixel_centres() {
    // Section 3.6.4: source pixel (i, j) covers the window pixels whose centres lie in
    // [x + zx * i, x + zx * (i + 1)) x [y + zy * j, y + zy * (j + 1)).
    for (zx, zy) in [(2.0f32, 3.0f32), (-1.0, 1.0), (1.6, -2.2)] {
        let mut gl = setup();
        let img = image(4, 3);
        gl.pixel_zoom(zx, zy);
        gl.raster_pos_2i(12, 12);
        gl.draw_pixels(4, 3, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
        let got = read_rgba(&mut gl);
        for py in 0..W {
            for px in 0..W {
                let (cx, cy) = (px as f32 + 0.5 - 12.0, py as f32 + 0.5 - 12.0);
                let (i, j) = ((cx / zx).floor(), (cy / zy).floor());
                let want = if (0.0..4.0).contains(&i) && (0.0..3.0).contains(&j) {
                    let k = (j as usize * 4 + i as usize) * 4;
                    [img[k], img[k + 1], img[k + 2], img[k + 3]]
                } else {
                    [0; 4]
                };
                assert_eq!(
                    got[(py * W + px) as usize],
                    want,
                    "zoom ({zx}, {zy}) at ({px}, {py})"
                );
            }
        }
    }
}

#[test]
fn scale_bias_and_color_maps_follow_section_3_6_5() {
    let mut gl = setup();
    let img = [100u8, 200, 30, 255];
    gl.pixel_transferf(GL_RED_SCALE, 0.5);
    gl.pixel_transferf(GL_GREEN_BIAS, 0.5);
    gl.pixel_transferf(GL_BLUE_SCALE, -2.0);
    gl.pixel_transferf(GL_BLUE_BIAS, 1.0);
    gl.raster_pos_2i(1, 1);
    gl.draw_pixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
    // Reading back applies the transfer too: reset it first.
    gl.pixel_transferf(GL_RED_SCALE, 1.0);
    gl.pixel_transferf(GL_GREEN_BIAS, 0.0);
    gl.pixel_transferf(GL_BLUE_SCALE, 1.0);
    gl.pixel_transferf(GL_BLUE_BIAS, 0.0);
    let f = |c: u8| c as f32 / 255.0;
    let q = |v: f32| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
    assert_eq!(
        pixel(&mut gl, 1, 1),
        [q(f(100) * 0.5), q(f(200) + 0.5), q(f(30) * -2.0 + 1.0), 255]
    );
    // Maps: the component (after scale and bias, clamped) times size - 1, rounded.
    let mut gl = setup();
    let map = [0.0f32, 0.3, 0.6, 0.9];
    for m in [
        GL_PIXEL_MAP_R_TO_R,
        GL_PIXEL_MAP_G_TO_G,
        GL_PIXEL_MAP_B_TO_B,
        GL_PIXEL_MAP_A_TO_A,
    ] {
        gl.pixel_mapfv(m, 4, &map);
    }
    gl.pixel_transferi(GL_MAP_COLOR, 1);
    let img = [40u8, 90, 170, 250];
    gl.raster_pos_2i(2, 2);
    gl.draw_pixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
    gl.pixel_transferi(GL_MAP_COLOR, 0);
    let want = img.map(|c| q(map[(f(c) * 3.0).round() as usize]));
    assert_eq!(pixel(&mut gl, 2, 2), want);
    let mut size = [0i32];
    gl.get_integerv(GL_PIXEL_MAP_G_TO_G_SIZE, &mut size);
    assert_eq!(size[0], 4);
    let mut back = [0f32; 4];
    gl.get_pixel_mapfv(GL_PIXEL_MAP_G_TO_G, &mut back);
    assert_eq!(back, map);
}

#[test]
fn stencil_and_depth_rectangles_use_index_arithmetic_and_depth_transfer() {
    let mut gl = setup();
    // Index: (v << 1) + 3, then through S_TO_S (size 8: masked by 7).
    gl.pixel_transferi(GL_INDEX_SHIFT, 1);
    gl.pixel_transferi(GL_INDEX_OFFSET, 3);
    let data = [0u8, 1, 2, 5];
    gl.raster_pos_2i(0, 0);
    gl.draw_pixels(4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, Some(&data));
    let read = |gl: &mut Context| {
        // Index arithmetic also applies on the way out: read with it off.
        let mut st = [0u8; 4];
        let mut saved = [0i32; 3];
        gl.get_integerv(GL_INDEX_SHIFT, &mut saved[0..1]);
        gl.get_integerv(GL_INDEX_OFFSET, &mut saved[1..2]);
        gl.get_integerv(GL_MAP_STENCIL, &mut saved[2..3]);
        gl.pixel_transferi(GL_INDEX_SHIFT, 0);
        gl.pixel_transferi(GL_INDEX_OFFSET, 0);
        gl.pixel_transferi(GL_MAP_STENCIL, 0);
        gl.read_pixels(0, 0, 4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &mut st);
        gl.pixel_transferi(GL_INDEX_SHIFT, saved[0]);
        gl.pixel_transferi(GL_INDEX_OFFSET, saved[1]);
        gl.pixel_transferi(GL_MAP_STENCIL, saved[2]);
        st
    };
    assert_eq!(read(&mut gl), data.map(|v| (v << 1) + 3));
    let map: Vec<u32> = (0..8).map(|k| 100 + k).collect();
    gl.pixel_mapuiv(GL_PIXEL_MAP_S_TO_S, 8, &map);
    gl.pixel_transferi(GL_MAP_STENCIL, 1);
    gl.draw_pixels(4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, Some(&data));
    let st = read(&mut gl);
    assert_eq!(st, data.map(|v| 100 + (((v << 1) + 3) & 7)));
    // Stencil bits given as GL_BITMAP, most significant bit first.
    let mut gl = setup();
    gl.raster_pos_2i(0, 1);
    gl.draw_pixels(8, 1, GL_STENCIL_INDEX, GL_BITMAP, Some(&[0b1011_0001]));
    let mut st = [0u8; 8];
    gl.read_pixels(0, 1, 8, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &mut st);
    assert_eq!(st, [1, 0, 1, 1, 0, 0, 0, 1]);
    // Depth: d * scale + bias, clamped; written through the depth test.
    let mut gl = setup();
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_ALWAYS);
    gl.pixel_transferf(GL_DEPTH_SCALE, 0.5);
    gl.pixel_transferf(GL_DEPTH_BIAS, 0.25);
    let depths: Vec<u8> = [0.0f32, 0.5, 1.0, 3.0]
        .iter()
        .flat_map(|d| d.to_ne_bytes())
        .collect();
    gl.raster_pos_2i(4, 4);
    gl.draw_pixels(4, 1, GL_DEPTH_COMPONENT, GL_FLOAT, Some(&depths));
    gl.pixel_transferf(GL_DEPTH_SCALE, 1.0);
    gl.pixel_transferf(GL_DEPTH_BIAS, 0.0);
    let mut out = [0u8; 16];
    gl.read_pixels(4, 4, 4, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &mut out);
    let got: Vec<f32> = out
        .chunks(4)
        .map(|c| f32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    for (g, d) in got.iter().zip([0.0f32, 0.5, 1.0, 1.0]) {
        let want = (d * 0.5 + 0.25).clamp(0.0, 1.0);
        assert!((g - want).abs() < 1e-6, "{g} vs {want}");
    }
}

#[test]
fn bitmap_draws_set_bits_in_the_raster_colour_and_moves_the_raster_position() {
    let mut gl = setup();
    gl.color_3f(1.0, 0.0, 0.0);
    gl.raster_pos_2f(5.7, 9.2);
    gl.color_3f(0.0, 1.0, 0.0); // too late: the raster colour was taken at glRasterPos
    let rows = [0b1100_0000u8, 0b0010_0000];
    gl.bitmap(3, 2, 1.0, 0.0, 4.5, -1.25, &rows);
    // The lower-left corner is (floor(5.7 - 1), floor(9.2 - 0)) = (4, 9).
    let red = [255, 0, 0, 255];
    assert_eq!(pixel(&mut gl, 4, 9), red);
    assert_eq!(pixel(&mut gl, 5, 9), red);
    assert_eq!(pixel(&mut gl, 6, 9), [0; 4]);
    assert_eq!(pixel(&mut gl, 6, 10), red);
    assert_eq!(pixel(&mut gl, 4, 10), [0; 4]);
    let mut pos = [0f32; 4];
    gl.get_floatv(GL_CURRENT_RASTER_POSITION, &mut pos);
    assert!((pos[0] - 10.2).abs() < 1e-5 && (pos[1] - 7.95).abs() < 1e-5);
}

/// Under a window-sized ortho projection a whole raster position comes out of the projection
/// and viewport a rounding error below the integer (y = 26 of 768 gives 25.99999); the glyph
/// still lands on that row, as Mesa draws it (llvmpipe and softpipe put every row of the bench's
/// `text` workload on its integer row).
#[test]
fn bitmaps_at_whole_raster_positions_land_on_that_row() {
    let mut gl = Context::new(1024, 768);
    window_ortho(&mut gl);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.color_3f(1.0, 0.0, 0.0);
    let mut hit = 0;
    for y in (12..760).step_by(14) {
        gl.raster_pos_2i(4, y);
        let mut pos = [0f32; 4];
        gl.get_floatv(GL_CURRENT_RASTER_POSITION, &mut pos);
        hit += usize::from(pos[1] != y as f32);
        gl.bitmap(1, 1, 0.0, 0.0, 0.0, 0.0, &[0x80]);
        assert_eq!(
            pixel(&mut gl, 4, y),
            [255, 0, 0, 255],
            "row {y} ({})",
            pos[1]
        );
        assert_eq!(pixel(&mut gl, 4, y - 1), [0, 0, 0, 0], "row {y}");
    }
    // The case this guards: some rows' positions are not exact.
    assert!(
        hit > 0,
        "every raster position was exact: the test checks nothing"
    );
}

#[test]
fn bitmaps_at_whole_pixel_raster_positions_start_there() {
    // piglit's scissor-bitmap: an orthographic projection of a 400-pixel window, raster
    // positions at whole pixels. The transform rounds some of them a few ulps low; section
    // 3.7's floor(x_r - x_o) is of the exact position, so the bitmap's first bit lands on x_r.
    let mut gl = Context::new(400, 400);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 400.0, 0.0, 400.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.color_3f(1.0, 0.0, 0.0);
    let rows = [0b1000_0000u8];
    let mut misplaced = Vec::new();
    for i in 0..40 {
        let (x, y) = (5 + 9 * i, 3 + 7 * i);
        gl.raster_pos_2f(x as f32, y as f32);
        gl.bitmap(1, 1, 0.0, 0.0, 0.0, 0.0, &rows);
        let row = common::read_rgba(&mut gl)
            .chunks(400)
            .nth(y as usize)
            .map(|r| r.iter().position(|p| p[0] != 0))
            .unwrap();
        if row != Some(x as usize) {
            misplaced.push((x, y, row));
        }
    }
    assert!(
        misplaced.is_empty(),
        "(x_r, y_r, first lit x): {misplaced:?}"
    );
}

#[test]
fn copy_pixels_reads_before_writing_overlapping_regions() {
    let mut gl = setup();
    let img = image(6, 6);
    gl.raster_pos_2i(0, 0);
    gl.draw_pixels(6, 6, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
    gl.raster_pos_2i(2, 1);
    gl.copy_pixels(0, 0, 6, 6, GL_COLOR);
    for y in 0..6 {
        for x in 0..6 {
            let k = (y * 6 + x) * 4;
            assert_eq!(
                pixel(&mut gl, 2 + x as i32, 1 + y as i32),
                [img[k], img[k + 1], img[k + 2], img[k + 3]]
            );
        }
    }
}

#[test]
fn raster_position_is_transformed_clipped_and_window_pos_is_direct() {
    let mut gl = setup();
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.raster_pos_3f(0.5, -0.25, -2.0);
    // Clip: x_c = 0.5, y_c = -0.25, w_c = 2, z_c = (-(11/9) * -2) - 20/9 = 2/9.
    let (xn, yn, zn) = (0.25f32, -0.125f32, (2.0f32 / 9.0) / 2.0);
    let mut pos = [0f32; 4];
    gl.get_floatv(GL_CURRENT_RASTER_POSITION, &mut pos);
    let want = [(xn + 1.0) * 16.0, (yn + 1.0) * 16.0, (zn + 1.0) / 2.0];
    for k in 0..3 {
        assert!((pos[k] - want[k]).abs() < 1e-4, "{pos:?} vs {want:?}");
    }
    let mut valid = [0u8];
    gl.get_booleanv(GL_CURRENT_RASTER_POSITION_VALID, &mut valid);
    assert_eq!(valid[0], 1);
    // Behind the eye: invalid, and drawing does nothing.
    gl.raster_pos_3f(0.0, 0.0, 5.0);
    gl.get_booleanv(GL_CURRENT_RASTER_POSITION_VALID, &mut valid);
    assert_eq!(valid[0], 0);
    gl.draw_pixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, Some(&[255; 4]));
    gl.bitmap(8, 1, 0.0, 0.0, 3.0, 0.0, &[0xFF]);
    assert!(read_rgba(&mut gl).iter().all(|p| *p == [0; 4]));
    // glWindowPos: valid again, z through the depth range.
    gl.depth_range(0.2, 0.6);
    gl.window_pos_3f(7.25, 8.5, 0.5);
    gl.get_floatv(GL_CURRENT_RASTER_POSITION, &mut pos);
    assert_eq!(&pos[..3], &[7.25, 8.5, 0.4]);
    gl.get_booleanv(GL_CURRENT_RASTER_POSITION_VALID, &mut valid);
    assert_eq!(valid[0], 1);
}

#[test]
fn extreme_zooms_and_bad_input_are_handled() {
    let mut gl = setup();
    let img = image(2, 2);
    // Zoom 1e4: the first source pixel covers the rest of the window; nothing panics.
    gl.pixel_zoom(1e4, 1e4);
    gl.raster_pos_2i(10, 10);
    gl.draw_pixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
    assert_eq!(pixel(&mut gl, 31, 31), [img[0], img[1], img[2], img[3]]);
    assert_eq!(pixel(&mut gl, 9, 9), [0; 4]);
    // NaN and infinite zooms draw nothing and raise no error.
    for z in [f32::NAN, f32::INFINITY] {
        let mut gl = setup();
        gl.pixel_zoom(z, 1.0);
        gl.raster_pos_2i(3, 3);
        gl.draw_pixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }
    let mut gl = setup();
    type Case = (&'static str, Box<dyn Fn(&mut Context)>, GLenum);
    let cases: Vec<Case> = vec![
        (
            "bad format",
            Box::new(|g| g.draw_pixels(1, 1, GL_TEXTURE_2D, GL_UNSIGNED_BYTE, Some(&[0; 4]))),
            GL_INVALID_ENUM,
        ),
        (
            "GL_BITMAP with RGBA",
            Box::new(|g| g.draw_pixels(1, 1, GL_RGBA, GL_BITMAP, Some(&[0; 4]))),
            GL_INVALID_ENUM,
        ),
        (
            "packed type with the wrong format",
            Box::new(|g| g.draw_pixels(1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, Some(&[0; 4]))),
            GL_INVALID_OPERATION,
        ),
        (
            "negative size",
            Box::new(|g| g.draw_pixels(-1, 1, GL_RGBA, GL_UNSIGNED_BYTE, Some(&[0; 4]))),
            GL_INVALID_VALUE,
        ),
        (
            "short slice",
            Box::new(|g| g.draw_pixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, Some(&[0; 60]))),
            GL_INVALID_VALUE,
        ),
        (
            "copy type",
            Box::new(|g| g.copy_pixels(0, 0, 1, 1, GL_RGBA)),
            GL_INVALID_ENUM,
        ),
        (
            "I_TO_R size not a power of two",
            Box::new(|g| g.pixel_mapfv(GL_PIXEL_MAP_I_TO_R, 3, &[0.0; 3])),
            GL_INVALID_VALUE,
        ),
        (
            "map larger than the maximum",
            Box::new(|g| g.pixel_mapfv(GL_PIXEL_MAP_R_TO_R, 257, &[0.0; 257])),
            GL_INVALID_VALUE,
        ),
        (
            "bad transfer parameter",
            Box::new(|g| g.pixel_transferf(GL_TEXTURE_2D, 1.0)),
            GL_INVALID_ENUM,
        ),
        (
            "bitmap too short",
            Box::new(|g| g.bitmap(16, 4, 0.0, 0.0, 0.0, 0.0, &[0; 7])),
            GL_INVALID_VALUE,
        ),
    ];
    for (name, call, want) in cases {
        call(&mut gl);
        assert_eq!(gl.get_error(), want, "{name}");
    }
    assert!(read_rgba(&mut gl).iter().all(|p| *p == [0; 4]));
}

#[test]
fn pixel_transfer_applies_to_texture_uploads_and_reads() {
    let mut gl = setup();
    gl.pixel_transferf(GL_RED_SCALE, 0.5);
    gl.pixel_transferf(GL_BLUE_BIAS, 0.25);
    let texel = [200u8, 100, 40, 255];
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texel),
    );
    gl.pixel_transferf(GL_RED_SCALE, 1.0);
    gl.pixel_transferf(GL_BLUE_BIAS, 0.0);
    let mut back = [0u8; 4];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut back);
    let q = |v: f32| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
    assert_eq!(
        back,
        [q(200.0 / 255.0 * 0.5), 100, q(40.0 / 255.0 + 0.25), 255]
    );
    // glReadPixels: transfer on the way out.
    gl.clear_color(0.4, 0.2, 0.8, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.pixel_transferf(GL_GREEN_SCALE, 2.0);
    gl.pixel_transferf(GL_ALPHA_BIAS, -0.5);
    let mut px = [0u8; 4];
    gl.read_pixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    assert_eq!(px, [102, q(51.0 / 255.0 * 2.0), 204, q(0.5)]);
}

#[test]
fn read_pixels_packs_every_packed_type() {
    let mut gl = setup();
    let c = [0.8f32, 0.3, 0.55, 0.4];
    gl.clear_color(c[0], c[1], c[2], c[3]);
    gl.clear(GL_COLOR_BUFFER_BIT);
    // The stored 8-bit values, then each field rounded to its own width (section 4.3.2).
    let stored = c.map(|v| (v * 255.0 + 0.5) as u32 as f32 / 255.0);
    let field = |v: f32, bits: u32| (v * ((1u32 << bits) - 1) as f32 + 0.5) as u32;
    let [r, g, b, a] = stored;
    let mut two = [0u8; 2];
    gl.read_pixels(0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &mut two);
    assert_eq!(
        u16::from_ne_bytes(two) as u32,
        field(r, 5) << 11 | field(g, 6) << 5 | field(b, 5)
    );
    gl.read_pixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, &mut two);
    assert_eq!(
        u16::from_ne_bytes(two) as u32,
        field(r, 4) << 12 | field(g, 4) << 8 | field(b, 4) << 4 | field(a, 4)
    );
    gl.read_pixels(0, 0, 1, 1, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, &mut two);
    assert_eq!(
        u16::from_ne_bytes(two) as u32,
        field(a, 1) << 15 | field(r, 5) << 10 | field(g, 5) << 5 | field(b, 5)
    );
    let mut four = [0u8; 4];
    gl.read_pixels(0, 0, 1, 1, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, &mut four);
    assert_eq!(
        u32::from_ne_bytes(four),
        field(a, 8) << 24 | field(r, 8) << 16 | field(g, 8) << 8 | field(b, 8)
    );
    gl.read_pixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, &mut four);
    assert_eq!(
        u32::from_ne_bytes(four),
        field(r, 10) << 22 | field(g, 10) << 12 | field(b, 10) << 2 | field(a, 2)
    );
    let mut one = [0u8; 1];
    gl.read_pixels(0, 0, 1, 1, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, &mut one);
    assert_eq!(
        one[0] as u32,
        field(r, 3) << 5 | field(g, 3) << 2 | field(b, 2)
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    // A packed type with a format of the wrong size, and a short slice.
    gl.read_pixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, &mut two);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.read_pixels(0, 0, 4, 4, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &mut two);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
}

/// Reads `w` x 1 pixels at (x, y) as GL_DEPTH_STENCIL / GL_UNSIGNED_INT_24_8 words.
fn read_depth_stencil_words(gl: &mut Context, x: i32, y: i32, w: usize) -> Vec<u32> {
    let mut b = vec![0u8; 4 * w];
    gl.read_pixels(
        x,
        y,
        w as i32,
        1,
        GL_DEPTH_STENCIL_EXT,
        GL_UNSIGNED_INT_24_8_EXT,
        &mut b,
    );
    b.chunks(4)
        .map(|c| u32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
        .collect()
}

#[test]
fn depth_stencil_rectangles_process_each_half_as_depth_and_stencil_index() {
    // EXT_packed_depth_stencil: a GL_DEPTH_STENCIL group's depth goes through the depth
    // transfer and its stencil index through the index arithmetic, as the same values drawn
    // as GL_DEPTH_COMPONENT and GL_STENCIL_INDEX would (llvmpipe skips the index arithmetic
    // on glDrawPixels' stencil; conformance's piglit_depth_stencil_pixels compares the rest
    // with Mesa).
    let pairs: [(u32, u8); 4] = [(0, 0), (0xff_ffff, 0x7f), (0x80_0000, 5), (0x12_3456, 0xf0)];
    let words: Vec<u8> = pairs
        .iter()
        .flat_map(|&(d, s)| ((d << 8) | s as u32).to_ne_bytes())
        .collect();
    let transfer = |gl: &mut Context| {
        gl.pixel_transferi(GL_INDEX_SHIFT, 1);
        gl.pixel_transferi(GL_INDEX_OFFSET, 3);
        gl.pixel_transferf(GL_DEPTH_SCALE, 0.5);
        gl.pixel_transferf(GL_DEPTH_BIAS, 0.25);
    };
    let mut packed = setup();
    transfer(&mut packed);
    packed.raster_pos_2i(2, 3);
    packed.draw_pixels(
        4,
        1,
        GL_DEPTH_STENCIL_EXT,
        GL_UNSIGNED_INT_24_8_EXT,
        Some(&words),
    );
    assert_eq!(packed.get_error(), GL_NO_ERROR);

    let mut separate = setup();
    transfer(&mut separate);
    separate.enable(GL_DEPTH_TEST);
    separate.depth_func(GL_ALWAYS);
    let depths: Vec<u8> = pairs
        .iter()
        .flat_map(|&(d, _)| d.wrapping_shl(8).to_ne_bytes())
        .collect();
    let indices: Vec<u8> = pairs.iter().map(|&(_, s)| s).collect();
    separate.raster_pos_2i(2, 3);
    separate.draw_pixels(4, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, Some(&depths));
    separate.draw_pixels(4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, Some(&indices));

    for gl in [&mut packed, &mut separate] {
        gl.pixel_transferi(GL_INDEX_SHIFT, 0);
        gl.pixel_transferi(GL_INDEX_OFFSET, 0);
        gl.pixel_transferf(GL_DEPTH_SCALE, 1.0);
        gl.pixel_transferf(GL_DEPTH_BIAS, 0.0);
    }
    let got = read_depth_stencil_words(&mut packed, 2, 3, 4);
    assert_eq!(got, read_depth_stencil_words(&mut separate, 2, 3, 4));
    for (w, &(d, s)) in got.iter().zip(&pairs) {
        // Spec equations: depth d / (2^24 - 1) * 0.5 + 0.25 in 24 bits, index (s << 1) + 3.
        let want_d = ((d as f64 / 0xff_ffff as f64 * 0.5 + 0.25) * 0xff_ffff as f64).round();
        assert!(
            ((w >> 8) as f64 - want_d).abs() <= 1.0,
            "{w:#x} vs {want_d}"
        );
        assert_eq!(w & 0xff, ((s as u32) << 1).wrapping_add(3) & 0xff);
    }
    // Colour untouched: the pairs are not fragments (OpenGL 3.0, section 4.3.1).
    assert_eq!(pixel(&mut packed, 2, 3), [0; 4]);

    // Read back through the transfer, byte-swapped, with a skip: the words of the buffer.
    let mut gl = setup();
    gl.raster_pos_2i(0, 0);
    gl.draw_pixels(
        4,
        1,
        GL_DEPTH_STENCIL_EXT,
        GL_UNSIGNED_INT_24_8_EXT,
        Some(&words),
    );
    gl.pixel_transferi(GL_INDEX_OFFSET, 1);
    gl.pixel_storei(GL_PACK_SWAP_BYTES, 1);
    gl.pixel_storei(GL_PACK_SKIP_PIXELS, 1);
    let mut b = [0xaau8; 20];
    gl.read_pixels(
        0,
        0,
        4,
        1,
        GL_DEPTH_STENCIL_EXT,
        GL_UNSIGNED_INT_24_8_EXT,
        &mut b,
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(b[..4], [0xaa; 4]);
    for (k, &(d, s)) in pairs.iter().enumerate() {
        let c = &b[4 + 4 * k..8 + 4 * k];
        let w = u32::from_be_bytes([c[0], c[1], c[2], c[3]]);
        let w = if cfg!(target_endian = "little") {
            w
        } else {
            w.swap_bytes()
        };
        assert_eq!(w, (d << 8) | (s as u32 + 1) & 0xff, "word {k}");
    }

    // Scissor and zoom apply; a framebuffer without stencil refuses both commands.
    let mut gl = setup();
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(0, 0, 3, 32);
    gl.pixel_zoom(2.0, 1.0);
    gl.raster_pos_2i(0, 0);
    gl.draw_pixels(
        2,
        1,
        GL_DEPTH_STENCIL_EXT,
        GL_UNSIGNED_INT_24_8_EXT,
        Some(&words[4..12]),
    );
    gl.disable(GL_SCISSOR_TEST);
    let got: Vec<u32> = read_depth_stencil_words(&mut gl, 0, 0, 4)
        .iter()
        .map(|w| w & 0xff)
        .collect();
    assert_eq!(got, [0x7f, 0x7f, 5, 0]);
    for (depth_bits, stencil_bits) in [(24, 0), (0, 8)] {
        let mut gl = Context::with_config(tilegl::ContextConfig {
            width: 8,
            height: 8,
            framebuffer: tilegl::FramebufferConfig {
                depth_bits,
                stencil_bits,
                ..tilegl::FramebufferConfig::default()
            },
            ..tilegl::ContextConfig::default()
        });
        gl.draw_pixels(
            1,
            1,
            GL_DEPTH_STENCIL_EXT,
            GL_UNSIGNED_INT_24_8_EXT,
            Some(&words),
        );
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        let mut b = [0u8; 4];
        gl.read_pixels(
            0,
            0,
            1,
            1,
            GL_DEPTH_STENCIL_EXT,
            GL_UNSIGNED_INT_24_8_EXT,
            &mut b,
        );
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    }
}

//! Internal formats beyond GL 1.5 that captures from newer drivers use (ARB_texture_rg,
//! ARB_texture_float, depth-stencil): RED is (R, 0, 0, 1), RG is (R, G, 0, 1), float formats
//! keep [0, 1] data exactly, generic compressed RED/RG are accepted.

mod common;

use common::{pixel, window_ortho};
use tilegl::enums::*;
use tilegl::{Context, Gl};

fn sample(internal: GLenum) -> [u8; 4] {
    let mut gl = Context::new(8, 8);
    window_ortho(&mut gl);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        internal as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[200, 100, 50, 25]),
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR, "{internal:#x}");
    let mut reported = [0i32];
    gl.get_tex_level_parameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &mut reported);
    assert_eq!(reported[0], internal as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    pixel(&mut gl, 4, 4)
}

#[test]
fn red_and_rg_expand_with_zero_and_one() {
    for f in [GL_RED, GL_R8, GL_R16, GL_COMPRESSED_RED, GL_R16F, GL_R32F] {
        // REPLACE with a colour-only base format keeps the fragment's alpha (white, 255).
        assert_eq!(sample(f), [200, 0, 0, 255], "{f:#x}");
    }
    for f in [GL_RG, GL_RG8, GL_RG16, GL_COMPRESSED_RG, GL_RG16F, GL_RG32F] {
        assert_eq!(sample(f), [200, 100, 0, 255], "{f:#x}");
    }
    for f in [GL_RGBA16F_ARB, GL_RGBA32F_ARB] {
        assert_eq!(sample(f), [200, 100, 50, 25], "{f:#x}");
    }
    for f in [GL_RGB16F_ARB, GL_RGB32F_ARB] {
        assert_eq!(sample(f), [200, 100, 50, 255], "{f:#x}");
    }
}

#[test]
fn depth_stencil_formats_take_depth() {
    let mut gl = Context::new(8, 8);
    for f in [
        GL_DEPTH24_STENCIL8_EXT,
        GL_DEPTH_COMPONENT32F,
        GL_DEPTH32F_STENCIL8,
    ] {
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            f as i32,
            1,
            1,
            0,
            GL_DEPTH_COMPONENT,
            GL_FLOAT,
            Some(&0.25f32.to_ne_bytes()),
        );
        assert_eq!(gl.get_error(), GL_NO_ERROR, "{f:#x}");
        let mut bits = [0i32];
        gl.get_tex_level_parameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &mut bits);
        assert!(bits[0] >= 24, "{f:#x}: {} depth bits", bits[0]);
    }
}

#[test]
fn rectangle_textures_take_texel_coordinates() {
    // ARB_texture_rectangle: s in [0, w], t in [0, h]; one level, no border, clamped.
    let mut gl = Context::new(16, 8);
    window_ortho(&mut gl);
    let texels: Vec<u8> = (0..4 * 2)
        .flat_map(|k| [(k * 30) as u8, (200 - k * 20) as u8, (k * 7) as u8, 255])
        .collect();
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_RECTANGLE_ARB, name[0]);
    let mut q = [0i32; 2];
    gl.get_tex_parameteriv(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, &mut q[..1]);
    gl.get_tex_parameteriv(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, &mut q[1..]);
    assert_eq!(q, [GL_CLAMP_TO_EDGE as i32, GL_LINEAR as i32]);
    gl.tex_image_2d(
        GL_TEXTURE_RECTANGLE_ARB,
        0,
        GL_RGBA8 as i32,
        4,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    gl.tex_parameteri(
        GL_TEXTURE_RECTANGLE_ARB,
        GL_TEXTURE_MIN_FILTER,
        GL_NEAREST as i32,
    );
    gl.tex_parameteri(
        GL_TEXTURE_RECTANGLE_ARB,
        GL_TEXTURE_MAG_FILTER,
        GL_NEAREST as i32,
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    // Errors: mipmap levels, borders, mipmap filters, repeating wraps.
    gl.tex_image_2d(
        GL_TEXTURE_RECTANGLE_ARB,
        1,
        GL_RGBA8 as i32,
        2,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.tex_image_2d(
        GL_TEXTURE_RECTANGLE_ARB,
        0,
        GL_RGBA8 as i32,
        6,
        4,
        1,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[0; 96]),
    );
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.tex_parameteri(
        GL_TEXTURE_RECTANGLE_ARB,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.tex_parameteri(
        GL_TEXTURE_RECTANGLE_ARB,
        GL_TEXTURE_WRAP_S,
        GL_REPEAT as i32,
    );
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    let mut b = [0i32; 2];
    gl.get_integerv(GL_TEXTURE_BINDING_RECTANGLE_ARB, &mut b[..1]);
    gl.get_integerv(GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB, &mut b[1..]);
    assert_eq!(b[0], name[0] as i32);
    assert!(b[1] >= 1024);
    // Drawn over the whole 16x8 window with s 0..4, t 0..2: each texel covers 4x4 pixels.
    // The rectangle target takes precedence over an enabled 2D target.
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_TEXTURE_RECTANGLE_ARB);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.begin(GL_QUADS);
    for (s, t, x, y) in [
        (0.0f32, 0.0f32, 0.0f32, 0.0f32),
        (4.0, 0.0, 16.0, 0.0),
        (4.0, 2.0, 16.0, 8.0),
        (0.0, 2.0, 0.0, 8.0),
    ] {
        gl.tex_coord_2f(s, t);
        gl.vertex_2f(x, y);
    }
    gl.end();
    for ty in 0..2 {
        for tx in 0..4 {
            let k = ty * 4 + tx;
            let want = [(k * 30) as u8, (200 - k * 20) as u8, (k * 7) as u8, 255];
            assert_eq!(pixel(&mut gl, tx * 4 + 1, ty * 4 + 2), want);
        }
    }
    // Texture limits are queryable.
    let mut m = [0i32; 3];
    gl.get_integerv(GL_MAX_TEXTURE_SIZE, &mut m[..1]);
    gl.get_integerv(GL_MAX_3D_TEXTURE_SIZE, &mut m[1..2]);
    gl.get_integerv(GL_NUM_COMPRESSED_TEXTURE_FORMATS, &mut m[2..]);
    assert!(m[0] >= 4096 && m[1] >= 256 && m[2] == 4, "{m:?}");
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

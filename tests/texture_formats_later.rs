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

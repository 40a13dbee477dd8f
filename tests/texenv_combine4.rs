//! NV_texture_env_combine4 (`GL_COMBINE4_NV`): `ADD` = a0 a1 + a2 a3 and `ADD_SIGNED` =
//! a0 a1 + a2 a3 - 1/2, with `GL_ZERO` as a source (its complement is 1), computed in the test.

mod common;

use common::{pixel, window_ortho};
use tilegl::enums::*;
use tilegl::{Context, Gl};

fn draw(func: GLenum, sources: [GLenum; 4], operands: [GLenum; 4]) -> [u8; 4] {
    let mut gl = Context::new(8, 8);
    window_ortho(&mut gl);
    let texel = [200u8, 100, 50, 180];
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texel),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE4_NV as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, func as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, func as i32);
    gl.tex_envfv(
        GL_TEXTURE_ENV,
        GL_TEXTURE_ENV_COLOR,
        &[0.25, 0.5, 0.75, 0.4],
    );
    let src = [
        GL_SOURCE0_RGB,
        GL_SOURCE1_RGB,
        GL_SOURCE2_RGB,
        GL_SOURCE3_RGB_NV,
    ];
    let src_a = [
        GL_SOURCE0_ALPHA,
        GL_SOURCE1_ALPHA,
        GL_SOURCE2_ALPHA,
        GL_SOURCE3_ALPHA_NV,
    ];
    let op = [
        GL_OPERAND0_RGB,
        GL_OPERAND1_RGB,
        GL_OPERAND2_RGB,
        GL_OPERAND3_RGB_NV,
    ];
    let op_a = [
        GL_OPERAND0_ALPHA,
        GL_OPERAND1_ALPHA,
        GL_OPERAND2_ALPHA,
        GL_OPERAND3_ALPHA_NV,
    ];
    for k in 0..4 {
        gl.tex_envi(GL_TEXTURE_ENV, src[k], sources[k] as i32);
        gl.tex_envi(GL_TEXTURE_ENV, src_a[k], sources[k] as i32);
        gl.tex_envi(GL_TEXTURE_ENV, op[k], operands[k] as i32);
        let alpha_op = if operands[k] == GL_ONE_MINUS_SRC_COLOR {
            GL_ONE_MINUS_SRC_ALPHA
        } else {
            GL_SRC_ALPHA
        };
        gl.tex_envi(GL_TEXTURE_ENV, op_a[k], alpha_op as i32);
    }
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.color_4f(0.6, 0.3, 0.9, 0.5);
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    pixel(&mut gl, 4, 4)
}

#[test]
fn add_products_follow_the_extension() {
    let t = [200.0f32, 100.0, 50.0, 180.0].map(|v| v / 255.0);
    let p = [0.6f32, 0.3, 0.9, 0.5];
    let c = [0.25f32, 0.5, 0.75, 0.4];
    let q = |v: f32| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
    // ADD: texture * primary + constant * (1 - zero).
    let got = draw(
        GL_ADD,
        [GL_TEXTURE, GL_PRIMARY_COLOR, GL_CONSTANT, GL_ZERO],
        [
            GL_SRC_COLOR,
            GL_SRC_COLOR,
            GL_SRC_COLOR,
            GL_ONE_MINUS_SRC_COLOR,
        ],
    );
    let want: Vec<u8> = (0..3).map(|i| q(t[i] * p[i] + c[i])).collect();
    assert_eq!(&got[..3], &want[..]);
    assert_eq!(got[3], q(t[3] * p[3] + c[3]));
    // ADD_SIGNED: texture * (1 - primary) + constant * texture - 1/2.
    let got = draw(
        GL_ADD_SIGNED,
        [GL_TEXTURE, GL_PRIMARY_COLOR, GL_CONSTANT, GL_TEXTURE],
        [
            GL_SRC_COLOR,
            GL_ONE_MINUS_SRC_COLOR,
            GL_SRC_COLOR,
            GL_SRC_COLOR,
        ],
    );
    for i in 0..3 {
        // Within one step: the sum lands near a rounding tie.
        let want = q(t[i] * (1.0 - p[i]) + c[i] * t[i] - 0.5);
        assert!(got[i].abs_diff(want) <= 1, "{i}: {} vs {want}", got[i]);
    }
    // MODULATE keeps its GL_COMBINE meaning (the fourth argument is unused).
    let got = draw(
        GL_MODULATE,
        [GL_TEXTURE, GL_PRIMARY_COLOR, GL_CONSTANT, GL_CONSTANT],
        [GL_SRC_COLOR; 4],
    );
    let want: Vec<u8> = (0..3).map(|i| q(t[i] * p[i])).collect();
    assert_eq!(&got[..3], &want[..]);
}

#[test]
fn texture_swizzle_routes_components() {
    // EXT_texture_swizzle: each sampled component comes from the named one, zero or one.
    let mut gl = Context::new(8, 8);
    window_ortho(&mut gl);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[10, 20, 30, 40]),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteriv(
        GL_TEXTURE_2D,
        GL_TEXTURE_SWIZZLE_RGBA,
        &[
            GL_ALPHA as i32,
            GL_ZERO as i32,
            GL_RED as i32,
            GL_ONE as i32,
        ],
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_G, GL_BLUE as i32);
    let mut q = [0i32; 4];
    gl.get_tex_parameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, &mut q);
    assert_eq!(q, [GL_ALPHA, GL_BLUE, GL_RED, GL_ONE].map(|e| e as i32));
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    assert_eq!(pixel(&mut gl, 3, 3), [40, 30, 10, 255]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_R, GL_TEXTURE_2D as i32);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
}

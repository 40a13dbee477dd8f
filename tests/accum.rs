//! The accumulation buffer (section 4.2.4) against the operations' equations computed in the
//! test, with extreme values (overflow, negative values) and errors.

mod common;

use common::{pixel, window_ortho};
use tilegl::enums::*;
use tilegl::{Context, ContextConfig, FramebufferConfig, Gl};

fn context(accum_bits: u32) -> Context {
    let mut gl = Context::with_config(ContextConfig {
        width: 16,
        height: 16,
        framebuffer: FramebufferConfig {
            accum_bits,
            ..FramebufferConfig::default()
        },
        ..ContextConfig::default()
    });
    window_ortho(&mut gl);
    gl
}

fn fill(gl: &mut Context, c: [u8; 4]) {
    gl.clear_color(
        c[0] as f32 / 255.0,
        c[1] as f32 / 255.0,
        c[2] as f32 / 255.0,
        c[3] as f32 / 255.0,
    );
    gl.clear(GL_COLOR_BUFFER_BIT);
}

/// What RETURN writes for accumulation value `a` (in [-1, 1]) and scale `v`.
fn returned(a: f32, v: f32) -> u8 {
    ((a * v).clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

#[test]
fn operations_follow_the_equations() {
    let mut gl = context(16);
    let c1 = [200u8, 100, 50, 255];
    let c2 = [20u8, 60, 255, 128];
    let f = |c: u8| c as f32 / 255.0;
    // A = 0.5 C1; A += -0.25 C2; A *= 1.5; A += 0.1; C = 1.2 A.
    fill(&mut gl, c1);
    gl.accum(GL_LOAD, 0.5);
    fill(&mut gl, c2);
    gl.accum(GL_ACCUM, -0.25);
    gl.accum(GL_MULT, 1.5);
    gl.accum(GL_ADD, 0.1);
    fill(&mut gl, [0, 0, 0, 0]);
    gl.accum(GL_RETURN, 1.2);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let got = pixel(&mut gl, 5, 5);
    for k in 0..4 {
        let a = (0.5 * f(c1[k]) - 0.25 * f(c2[k])) * 1.5 + 0.1;
        let want = returned(a, 1.2);
        assert!(
            got[k].abs_diff(want) <= 1,
            "channel {k}: {} vs {want}",
            got[k]
        );
    }
}

#[test]
fn clear_scissor_and_color_mask_apply() {
    let mut gl = context(16);
    gl.clear_accum(0.5, 2.0, -3.0, 0.25); // clamped to [-1, 1]
    let mut v = [0f32; 4];
    gl.get_floatv(GL_ACCUM_CLEAR_VALUE, &mut v);
    assert_eq!(v, [0.5, 1.0, -1.0, 0.25]);
    gl.clear(GL_ACCUM_BUFFER_BIT);
    fill(&mut gl, [9, 9, 9, 9]);
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(0, 0, 8, 16);
    gl.color_mask(1, 1, 1, 0);
    gl.accum(GL_RETURN, 1.0);
    gl.disable(GL_SCISSOR_TEST);
    gl.color_mask(1, 1, 1, 1);
    // Inside the scissor: returned (alpha masked); outside: untouched.
    assert_eq!(pixel(&mut gl, 2, 2), [returned(0.5, 1.0), 255, 0, 9]);
    assert_eq!(pixel(&mut gl, 12, 2), [9, 9, 9, 9]);
}

#[test]
fn overflow_saturates_and_negative_values_return_black() {
    let mut gl = context(16);
    fill(&mut gl, [255, 255, 255, 255]);
    gl.accum(GL_LOAD, 1.0);
    gl.accum(GL_ADD, 1e6);
    gl.accum(GL_RETURN, 0.5);
    assert_eq!(pixel(&mut gl, 1, 1), [128; 4]); // saturated at 1.0, times 0.5
    gl.accum(GL_MULT, -1.0);
    gl.accum(GL_RETURN, 1.0);
    assert_eq!(pixel(&mut gl, 1, 1), [0; 4]);
    // A negative accumulation returned with a negative scale is positive.
    gl.accum(GL_RETURN, -0.25);
    assert_eq!(pixel(&mut gl, 1, 1), [returned(-1.0, -0.25); 4]);
    // NaN values never produce garbage.
    gl.accum(GL_MULT, f32::NAN);
    gl.accum(GL_RETURN, 1.0);
    assert_eq!(pixel(&mut gl, 1, 1), [0; 4]);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn errors() {
    let mut gl = context(0);
    gl.accum(GL_ACCUM, 1.0);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    let mut gl = context(16);
    gl.accum(GL_TEXTURE_2D, 1.0);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    let mut bits = [0i32];
    gl.get_integerv(GL_ACCUM_RED_BITS, &mut bits);
    assert_eq!(bits[0], 16);
}

//! `GL_COMBINE` against the equations of the specification (OpenGL 1.5 section 3.8.13, table
//! 3.24; the glTexEnv reference page): every function, every operand of the RGB and alpha
//! arguments, every source, `ADD_SIGNED`'s bias of 1/2, `INTERPOLATE`'s weights `Arg2` and
//! `1 - Arg2`, `DOT3`'s expansion `4 ((r0 - 1/2)(r1 - 1/2) + (g0 - 1/2)(g1 - 1/2) +
//! (b0 - 1/2)(b1 - 1/2))`, `RGB_SCALE` / `ALPHA_SCALE` 1, 2 and 4, and the clamp to [0, 1]
//! after the scale. Inputs are a 1x1 texture, the primary colour and the constant colour, all
//! exact multiples of 1/255; the expected colour is computed here in floating point and the
//! picture read back with `glReadPixels` (1/255 allowed for rounding).

mod common;

use common::{pixel, window_ortho, Rng};
use tilegl::enums::*;
use tilegl::{Context, Gl};

type Rgba = [f32; 4];

const FUNCS: [GLenum; 6] = [
    GL_REPLACE,
    GL_MODULATE,
    GL_ADD,
    GL_ADD_SIGNED,
    GL_INTERPOLATE,
    GL_SUBTRACT,
];
const RGB_OPERANDS: [GLenum; 4] = [
    GL_SRC_COLOR,
    GL_ONE_MINUS_SRC_COLOR,
    GL_SRC_ALPHA,
    GL_ONE_MINUS_SRC_ALPHA,
];
const ALPHA_OPERANDS: [GLenum; 2] = [GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA];
const SOURCES: [GLenum; 4] = [GL_TEXTURE, GL_PRIMARY_COLOR, GL_CONSTANT, GL_PREVIOUS];
const SRC_RGB: [GLenum; 3] = [GL_SOURCE0_RGB, GL_SOURCE1_RGB, GL_SOURCE2_RGB];
const SRC_ALPHA: [GLenum; 3] = [GL_SOURCE0_ALPHA, GL_SOURCE1_ALPHA, GL_SOURCE2_ALPHA];
const OP_RGB: [GLenum; 3] = [GL_OPERAND0_RGB, GL_OPERAND1_RGB, GL_OPERAND2_RGB];
const OP_ALPHA: [GLenum; 3] = [GL_OPERAND0_ALPHA, GL_OPERAND1_ALPHA, GL_OPERAND2_ALPHA];

/// One combiner set-up on texture unit 0 (so `PREVIOUS` is the primary colour).
#[derive(Clone, Copy)]
struct Case {
    texel: [u8; 4],
    primary: [u8; 4],
    constant: [u8; 4],
    rgb: GLenum,
    alpha: GLenum,
    src_rgb: [GLenum; 3],
    src_alpha: [GLenum; 3],
    op_rgb: [GLenum; 3],
    op_alpha: [GLenum; 3],
    rgb_scale: f32,
    alpha_scale: f32,
}

impl Case {
    fn new(rgb: GLenum, alpha: GLenum) -> Case {
        Case {
            texel: [200, 100, 50, 180],
            primary: [153, 77, 230, 128],
            constant: [64, 128, 191, 102],
            rgb,
            alpha,
            src_rgb: [GL_TEXTURE, GL_PRIMARY_COLOR, GL_CONSTANT],
            src_alpha: [GL_TEXTURE, GL_PRIMARY_COLOR, GL_CONSTANT],
            op_rgb: [GL_SRC_COLOR; 3],
            op_alpha: [GL_SRC_ALPHA; 3],
            rgb_scale: 1.0,
            alpha_scale: 1.0,
        }
    }
}

fn unit(v: [u8; 4]) -> Rgba {
    v.map(|c| c as f32 / 255.0)
}

/// The picture: a window-filling rectangle through the combiner, pixel (4, 4) read back.
fn render(c: &Case) -> [u8; 4] {
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
        Some(&c.texel),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, c.rgb as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, c.alpha as i32);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &unit(c.constant));
    for k in 0..3 {
        gl.tex_envi(GL_TEXTURE_ENV, SRC_RGB[k], c.src_rgb[k] as i32);
        gl.tex_envi(GL_TEXTURE_ENV, SRC_ALPHA[k], c.src_alpha[k] as i32);
        gl.tex_envi(GL_TEXTURE_ENV, OP_RGB[k], c.op_rgb[k] as i32);
        gl.tex_envi(GL_TEXTURE_ENV, OP_ALPHA[k], c.op_alpha[k] as i32);
    }
    gl.tex_envf(GL_TEXTURE_ENV, GL_RGB_SCALE, c.rgb_scale);
    gl.tex_envf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, c.alpha_scale);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let p = c.primary;
    gl.color_4ub(p[0], p[1], p[2], p[3]);
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    pixel(&mut gl, 4, 4)
}

/// Table 3.24, written out independently of the implementation.
fn expected(c: &Case) -> Rgba {
    let (t, p, k) = (unit(c.texel), unit(c.primary), unit(c.constant));
    let src = |s: GLenum| match s {
        GL_TEXTURE | GL_TEXTURE0 => t,
        GL_PRIMARY_COLOR | GL_PREVIOUS => p,
        GL_CONSTANT => k,
        _ => panic!("source {s:#x}"),
    };
    let arg_rgb = |i: usize| -> [f32; 3] {
        let v = src(c.src_rgb[i]);
        match c.op_rgb[i] {
            GL_SRC_COLOR => [v[0], v[1], v[2]],
            GL_ONE_MINUS_SRC_COLOR => [1.0 - v[0], 1.0 - v[1], 1.0 - v[2]],
            GL_SRC_ALPHA => [v[3]; 3],
            GL_ONE_MINUS_SRC_ALPHA => [1.0 - v[3]; 3],
            o => panic!("operand {o:#x}"),
        }
    };
    let arg_a = |i: usize| -> f32 {
        let v = src(c.src_alpha[i])[3];
        match c.op_alpha[i] {
            GL_SRC_ALPHA => v,
            GL_ONE_MINUS_SRC_ALPHA => 1.0 - v,
            o => panic!("operand {o:#x}"),
        }
    };
    let f = |func: GLenum, a0: f32, a1: f32, a2: f32| match func {
        GL_REPLACE => a0,
        GL_MODULATE => a0 * a1,
        GL_ADD => a0 + a1,
        GL_ADD_SIGNED => a0 + a1 - 0.5,
        GL_INTERPOLATE => a0 * a2 + a1 * (1.0 - a2),
        GL_SUBTRACT => a0 - a1,
        _ => panic!("function {func:#x}"),
    };
    let clamp = |v: f32| v.clamp(0.0, 1.0);
    let (a0, a1, a2) = (arg_rgb(0), arg_rgb(1), arg_rgb(2));
    if c.rgb == GL_DOT3_RGB || c.rgb == GL_DOT3_RGBA {
        let d = 4.0
            * ((a0[0] - 0.5) * (a1[0] - 0.5)
                + (a0[1] - 0.5) * (a1[1] - 0.5)
                + (a0[2] - 0.5) * (a1[2] - 0.5));
        let v = clamp(d * c.rgb_scale);
        let a = if c.rgb == GL_DOT3_RGBA {
            // "the alpha value computed by COMBINE_ALPHA is ignored": alpha is the dot product,
            // scaled like every alpha result by ALPHA_SCALE.
            clamp(d * c.alpha_scale)
        } else {
            clamp(f(c.alpha, arg_a(0), arg_a(1), arg_a(2)) * c.alpha_scale)
        };
        return [v, v, v, a];
    }
    let mut out = [0.0; 4];
    for i in 0..3 {
        out[i] = clamp(f(c.rgb, a0[i], a1[i], a2[i]) * c.rgb_scale);
    }
    out[3] = clamp(f(c.alpha, arg_a(0), arg_a(1), arg_a(2)) * c.alpha_scale);
    out
}

fn check(c: &Case, what: &str) {
    let got = render(c);
    let want = expected(c);
    for i in 0..4 {
        let w = want[i] * 255.0;
        assert!(
            (got[i] as f32 - w).abs() <= 1.0 + 1e-3,
            "{what}: channel {i} is {} where the specification gives {w:.2} \
             (got {got:?}, want {:?})",
            got[i],
            want.map(|v| v * 255.0)
        );
    }
}

#[test]
fn every_function_with_every_rgb_operand_on_every_argument() {
    for &func in &FUNCS {
        for (k, _) in RGB_OPERANDS.iter().enumerate() {
            let mut c = Case::new(func, GL_REPLACE);
            // Argument i takes operand k + i, so each argument sees every operand.
            c.op_rgb = [0, 1, 2].map(|i| RGB_OPERANDS[(k + i) % 4]);
            check(&c, &format!("rgb {func:#x} operands {:x?}", c.op_rgb));
        }
    }
}

#[test]
fn every_function_with_every_alpha_operand_combination() {
    for &func in &FUNCS {
        for bits in 0..8usize {
            let mut c = Case::new(GL_REPLACE, func);
            c.op_alpha = [0, 1, 2].map(|i| ALPHA_OPERANDS[(bits >> i) & 1]);
            check(&c, &format!("alpha {func:#x} operands {:x?}", c.op_alpha));
        }
    }
}

#[test]
fn every_source_in_every_argument_slot() {
    for &func in &FUNCS {
        for (k, _) in SOURCES.iter().enumerate() {
            let mut c = Case::new(func, func);
            c.src_rgb = [0, 1, 2].map(|i| SOURCES[(k + i) % 4]);
            c.src_alpha = [0, 1, 2].map(|i| SOURCES[(k + 2 * i + 1) % 4]);
            c.op_rgb = [GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA];
            c.op_alpha = [GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA];
            check(&c, &format!("{func:#x} sources {:x?}", c.src_rgb));
        }
    }
}

#[test]
fn scales_one_two_four_then_clamp() {
    for &func in &FUNCS {
        for rs in [1.0, 2.0, 4.0] {
            for as_ in [1.0, 2.0, 4.0] {
                let mut c = Case::new(func, func);
                c.rgb_scale = rs;
                c.alpha_scale = as_;
                check(&c, &format!("{func:#x} scale {rs} / {as_}"));
            }
        }
    }
}

#[test]
fn add_signed_bias_and_its_clamp_below_zero() {
    // 0.2 + 0.1 - 0.5 < 0 clamps to 0; 0.8 + 0.4 - 0.5 = 0.7; scale 2 gives 1.4, clamped.
    let mut c = Case::new(GL_ADD_SIGNED, GL_ADD_SIGNED);
    c.texel = [51, 204, 128, 51];
    c.primary = [26, 102, 128, 26];
    c.src_rgb = [GL_TEXTURE, GL_PRIMARY_COLOR, GL_CONSTANT];
    check(&c, "add_signed");
    let got = render(&c);
    assert_eq!(got[0], 0, "0.2 + 0.1 - 0.5 clamps to 0");
    assert_eq!(got[3], 0, "alpha 0.2 + 0.1 - 0.5 clamps to 0");
    assert!((got[2] as i32 - 128).abs() <= 1, "0.5 + 0.5 - 0.5 = 0.5");
    c.rgb_scale = 2.0;
    check(&c, "add_signed scale 2");
    assert_eq!(render(&c)[1], 255, "(0.8 + 0.4 - 0.5) * 2 clamps to 1");
}

#[test]
fn interpolate_weights_are_arg2_and_its_complement() {
    for w in [0u8, 64, 128, 191, 255] {
        let mut c = Case::new(GL_INTERPOLATE, GL_INTERPOLATE);
        c.texel = [255, 0, 200, 255];
        c.primary = [0, 255, 40, 0];
        c.constant = [w, w, w, w];
        check(&c, &format!("interpolate weight {w}"));
        let got = render(&c);
        assert!((got[0] as i32 - w as i32).abs() <= 1, "red follows Arg2");
        assert!(
            (got[1] as i32 - (255 - w) as i32).abs() <= 1,
            "green 1 - Arg2"
        );
    }
}

#[test]
fn subtract_clamps_at_zero_and_add_at_one() {
    let mut c = Case::new(GL_SUBTRACT, GL_ADD);
    c.texel = [50, 200, 255, 200];
    c.primary = [100, 100, 0, 200];
    check(&c, "subtract / add");
    let got = render(&c);
    assert_eq!(got[0], 0);
    assert_eq!(got[3], 255);
}

#[test]
fn dot3_expands_both_vectors_and_replicates() {
    for func in [GL_DOT3_RGB, GL_DOT3_RGBA] {
        for scale in [1.0, 2.0, 4.0] {
            for (t, p) in [
                ([255, 128, 128, 10], [255, 128, 128, 20]), // parallel along x: 4 * 0.25 = 1
                ([128, 255, 128, 10], [255, 128, 128, 20]), // orthogonal: 1/2-ish
                ([0, 128, 128, 10], [255, 128, 128, 20]),   // opposite: clamps to 0
                ([200, 160, 90, 10], [150, 220, 180, 20]),
            ] {
                let mut c = Case::new(func, GL_MODULATE);
                c.texel = t;
                c.primary = p;
                c.rgb_scale = scale;
                c.alpha_scale = 2.0;
                check(&c, &format!("{func:#x} scale {scale} {t:?}.{p:?}"));
                for op in RGB_OPERANDS {
                    c.op_rgb = [op, GL_SRC_COLOR, GL_SRC_COLOR];
                    check(&c, &format!("{func:#x} operand {op:#x}"));
                }
            }
        }
    }
}

#[test]
fn dot3_rgba_ignores_the_alpha_function() {
    let mut c = Case::new(GL_DOT3_RGBA, GL_REPLACE);
    c.texel = [255, 128, 128, 0];
    c.primary = [255, 128, 128, 0];
    let got = render(&c);
    assert!(
        got[3] >= 254,
        "alpha is the dot product (1), not REPLACE's 0: {got:?}"
    );
    c.rgb = GL_DOT3_RGB;
    assert_eq!(render(&c)[3], 0, "DOT3_RGB keeps the alpha function");
}

#[test]
fn random_cases_match_the_table() {
    let mut rng = Rng(0x5eed_c0b1);
    let funcs_rgb = [
        GL_REPLACE,
        GL_MODULATE,
        GL_ADD,
        GL_ADD_SIGNED,
        GL_INTERPOLATE,
        GL_SUBTRACT,
        GL_DOT3_RGB,
        GL_DOT3_RGBA,
    ];
    let pick = |rng: &mut Rng, n: usize| (rng.next_u64() % n as u64) as usize;
    let byte = |rng: &mut Rng| (rng.next_u64() % 256) as u8;
    for _ in 0..150 {
        let mut c = Case::new(
            funcs_rgb[pick(&mut rng, 8)],
            FUNCS[pick(&mut rng, FUNCS.len())],
        );
        c.texel = [0; 4].map(|_| byte(&mut rng));
        c.primary = [0; 4].map(|_| byte(&mut rng));
        c.constant = [0; 4].map(|_| byte(&mut rng));
        for i in 0..3 {
            c.src_rgb[i] = SOURCES[pick(&mut rng, 4)];
            c.src_alpha[i] = SOURCES[pick(&mut rng, 4)];
            c.op_rgb[i] = RGB_OPERANDS[pick(&mut rng, 4)];
            c.op_alpha[i] = ALPHA_OPERANDS[pick(&mut rng, 2)];
        }
        c.rgb_scale = [1.0, 2.0, 4.0][pick(&mut rng, 3)];
        c.alpha_scale = [1.0, 2.0, 4.0][pick(&mut rng, 3)];
        check(&c, "random case");
    }
}

#[test]
fn second_unit_reads_previous_and_crossbar_texture0() {
    // Unit 0 MODULATEs texel 0 with the primary colour; unit 1 SUBTRACTs TEXTURE0 (crossbar)
    // from PREVIOUS, ALPHA_SCALE 2 on ADD of PREVIOUS and TEXTURE1.
    let mut gl = Context::new(8, 8);
    window_ortho(&mut gl);
    let t0 = [200u8, 100, 50, 100];
    let t1 = [30u8, 60, 90, 120];
    for (u, t) in [(GL_TEXTURE0, t0), (GL_TEXTURE1, t1)] {
        gl.active_texture(u);
        let mut name = [0u32];
        gl.gen_textures(1, &mut name);
        gl.bind_texture(GL_TEXTURE_2D, name[0]);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            1,
            1,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&t),
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        gl.enable(GL_TEXTURE_2D);
    }
    gl.active_texture(GL_TEXTURE0);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.active_texture(GL_TEXTURE1);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_SUBTRACT as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE0 as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PREVIOUS as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_ADD as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_PREVIOUS as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_TEXTURE as i32);
    gl.tex_envf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 2.0);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let p = [128u8, 255, 64, 200];
    gl.color_4ub(p[0], p[1], p[2], p[3]);
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    let got = pixel(&mut gl, 4, 4);
    let (t0, t1, p) = (unit(t0), unit(t1), unit(p));
    let prev: Rgba = [0, 1, 2, 3].map(|i| t0[i] * p[i]);
    let want = [
        (t0[0] - prev[0]).clamp(0.0, 1.0),
        (t0[1] - prev[1]).clamp(0.0, 1.0),
        (t0[2] - prev[2]).clamp(0.0, 1.0),
        ((prev[3] + t1[3]) * 2.0).clamp(0.0, 1.0),
    ];
    for i in 0..4 {
        assert!(
            (got[i] as f32 - want[i] * 255.0).abs() <= 1.0 + 1e-3,
            "channel {i}: {got:?} vs {:?}",
            want.map(|v| v * 255.0)
        );
    }
}

#[test]
fn dot3_rgba_alpha_is_scaled_by_alpha_scale() {
    // Section 3.8.13: the RGB and ALPHA results are multiplied by RGB_SCALE and ALPHA_SCALE
    // respectively; for DOT3_RGBA the alpha result is the dot product. Dot = 4 (0.5 * 0.125)
    // = 0.25: RGB at scale 1 is 0.25, alpha at scale 4 is 1 (Mesa agrees).
    let mut c = Case::new(GL_DOT3_RGBA, GL_REPLACE);
    c.texel = [255, 128, 128, 0];
    c.primary = [160, 128, 128, 0];
    c.rgb_scale = 1.0;
    c.alpha_scale = 4.0;
    check(&c, "dot3_rgba alpha scale");
    let got = render(&c);
    assert!(got[3] >= 250 && got[0] < 80, "{got:?}");
}

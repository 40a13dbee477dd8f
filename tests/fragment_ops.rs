//! Per-fragment operations against the specification's equations, computed in the test
//! (sections 4.1.4-4.1.10).

mod common;

use common::{pixel, Rng};
use tilegl::enums::*;
use tilegl::{Context, Gl};

const FACTORS: [GLenum; 15] = [
    GL_ZERO,
    GL_ONE,
    GL_SRC_COLOR,
    GL_ONE_MINUS_SRC_COLOR,
    GL_DST_COLOR,
    GL_ONE_MINUS_DST_COLOR,
    GL_SRC_ALPHA,
    GL_ONE_MINUS_SRC_ALPHA,
    GL_DST_ALPHA,
    GL_ONE_MINUS_DST_ALPHA,
    GL_CONSTANT_COLOR,
    GL_ONE_MINUS_CONSTANT_COLOR,
    GL_CONSTANT_ALPHA,
    GL_ONE_MINUS_CONSTANT_ALPHA,
    GL_SRC_ALPHA_SATURATE,
];

/// Table 4.1/4.2 written out independently of the implementation.
fn spec_factor(f: GLenum, s: [f64; 4], d: [f64; 4], c: [f64; 4], ch: usize) -> f64 {
    match f {
        GL_ZERO => 0.0,
        GL_ONE => 1.0,
        GL_SRC_COLOR => s[ch],
        GL_ONE_MINUS_SRC_COLOR => 1.0 - s[ch],
        GL_DST_COLOR => d[ch],
        GL_ONE_MINUS_DST_COLOR => 1.0 - d[ch],
        GL_SRC_ALPHA => s[3],
        GL_ONE_MINUS_SRC_ALPHA => 1.0 - s[3],
        GL_DST_ALPHA => d[3],
        GL_ONE_MINUS_DST_ALPHA => 1.0 - d[3],
        GL_CONSTANT_COLOR => c[ch],
        GL_ONE_MINUS_CONSTANT_COLOR => 1.0 - c[ch],
        GL_CONSTANT_ALPHA => c[3],
        GL_ONE_MINUS_CONSTANT_ALPHA => 1.0 - c[3],
        GL_SRC_ALPHA_SATURATE => {
            if ch == 3 {
                1.0
            } else {
                s[3].min(1.0 - d[3])
            }
        }
        _ => unreachable!(),
    }
}

fn quantize(v: [f32; 4]) -> [f64; 4] {
    v.map(|c| (c as f64 * 255.0).round() / 255.0)
}

#[test]
fn every_blend_factor_and_equation() {
    let mut rng = Rng(5);
    let equations = [
        GL_FUNC_ADD,
        GL_FUNC_SUBTRACT,
        GL_FUNC_REVERSE_SUBTRACT,
        GL_MIN,
        GL_MAX,
    ];
    for &eq in &equations {
        for &sf in &FACTORS {
            for &df in FACTORS.iter().filter(|&&f| f != GL_SRC_ALPHA_SATURATE) {
                let src = [0; 4].map(|_: u8| rng.range(0.0, 1.0));
                let dst = [0; 4].map(|_: u8| rng.range(0.0, 1.0));
                let con = [0; 4].map(|_: u8| rng.range(0.0, 1.0));
                let mut gl = Context::new(4, 4);
                gl.clear_color(dst[0], dst[1], dst[2], dst[3]);
                gl.clear(GL_COLOR_BUFFER_BIT);
                gl.enable(GL_BLEND);
                gl.blend_func(sf, df);
                gl.blend_equation(eq);
                gl.blend_color(con[0], con[1], con[2], con[3]);
                gl.color_4f(src[0], src[1], src[2], src[3]);
                gl.rectf(-1.0, -1.0, 1.0, 1.0);
                assert_eq!(gl.get_error(), GL_NO_ERROR);
                let got = pixel(&mut gl, 1, 1);
                let (s, d, c) = (quantize(src), quantize(dst), con.map(|v| v as f64));
                for ch in 0..4 {
                    let a = s[ch] * spec_factor(sf, s, d, c, ch);
                    let b = d[ch] * spec_factor(df, s, d, c, ch);
                    let v = match eq {
                        GL_FUNC_ADD => a + b,
                        GL_FUNC_SUBTRACT => a - b,
                        GL_FUNC_REVERSE_SUBTRACT => b - a,
                        GL_MIN => s[ch].min(d[ch]),
                        _ => s[ch].max(d[ch]),
                    };
                    let expected = v.clamp(0.0, 1.0) * 255.0;
                    assert!(
                        (got[ch] as f64 - expected).abs() <= 1.0,
                        "eq {eq:#x} sf {sf:#x} df {df:#x} ch {ch}: got {} expected {expected}",
                        got[ch]
                    );
                }
            }
        }
    }
}

#[test]
fn blend_errors() {
    let mut gl = Context::new(4, 4);
    gl.blend_func(GL_ONE, GL_SRC_ALPHA_SATURATE);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.blend_equation(GL_ONE);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    let mut v = [0i32; 2];
    gl.get_integerv(GL_BLEND_SRC, &mut v[..1]);
    gl.get_integerv(GL_BLEND_DST, &mut v[1..]);
    assert_eq!(v, [GL_ONE as i32, GL_ZERO as i32]);
}

#[test]
fn alpha_test_functions() {
    let funcs = [
        GL_NEVER,
        GL_LESS,
        GL_EQUAL,
        GL_LEQUAL,
        GL_GREATER,
        GL_NOTEQUAL,
        GL_GEQUAL,
        GL_ALWAYS,
    ];
    for &func in &funcs {
        for (alpha, ref_) in [(0.25f32, 0.5f32), (0.5, 0.5), (0.75, 0.5), (0.5, 2.0)] {
            let mut gl = Context::new(4, 4);
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(func, ref_);
            gl.color_4f(1.0, 1.0, 1.0, alpha);
            gl.rectf(-1.0, -1.0, 1.0, 1.0);
            let r = ref_.clamp(0.0, 1.0); // the reference is clamped (section 4.1.4)
            let pass = match func {
                GL_NEVER => false,
                GL_LESS => alpha < r,
                GL_EQUAL => alpha == r,
                GL_LEQUAL => alpha <= r,
                GL_GREATER => alpha > r,
                GL_NOTEQUAL => alpha != r,
                GL_GEQUAL => alpha >= r,
                _ => true,
            };
            assert_eq!(
                pixel(&mut gl, 1, 1)[0] == 255,
                pass,
                "func {func:#x} alpha {alpha} ref {ref_}"
            );
        }
    }
}

fn stencil_after(
    clear: i32,
    func: GLenum,
    ref_: i32,
    mask: u32,
    ops: [GLenum; 3],
    depth_pass: bool,
    writemask: u32,
) -> (u8, bool) {
    let mut gl = Context::new(4, 4);
    gl.clear_stencil(clear);
    gl.clear_depth(if depth_pass { 1.0 } else { 0.0 });
    gl.clear(GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    gl.enable(GL_STENCIL_TEST);
    gl.enable(GL_DEPTH_TEST);
    gl.stencil_func(func, ref_, mask);
    gl.stencil_op(ops[0], ops[1], ops[2]);
    gl.stencil_mask(writemask);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.rectf(-1.0, -1.0, 1.0, 1.0);
    let mut s = [0u8];
    gl.read_pixels(1, 1, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &mut s);
    (s[0], pixel(&mut gl, 1, 1)[0] == 255)
}

fn spec_stencil_op(op: GLenum, s: u8, r: u8) -> u8 {
    match op {
        GL_KEEP => s,
        GL_ZERO => 0,
        GL_REPLACE => r,
        GL_INCR => s.saturating_add(1),
        GL_DECR => s.saturating_sub(1),
        GL_INVERT => !s,
        GL_INCR_WRAP => s.wrapping_add(1),
        _ => s.wrapping_sub(1),
    }
}

#[test]
fn stencil_functions_and_operations() {
    let all_ops = [
        GL_KEEP,
        GL_ZERO,
        GL_REPLACE,
        GL_INCR,
        GL_DECR,
        GL_INVERT,
        GL_INCR_WRAP,
        GL_DECR_WRAP,
    ];
    // Wrap and saturation at both ends of the 8-bit range.
    for &clear in &[0, 1, 128, 254, 255] {
        for &op in &all_ops {
            for depth_pass in [true, false] {
                let (got, drawn) = stencil_after(
                    clear,
                    GL_ALWAYS,
                    77,
                    0xFF,
                    [GL_KEEP, GL_KEEP, op],
                    depth_pass,
                    0xFF,
                );
                let expected = if depth_pass {
                    spec_stencil_op(op, clear as u8, 77)
                } else {
                    clear as u8
                };
                assert_eq!(
                    got, expected,
                    "op {op:#x} on {clear}, depth pass {depth_pass}"
                );
                assert_eq!(drawn, depth_pass);
                let (got, _) = stencil_after(
                    clear,
                    GL_ALWAYS,
                    77,
                    0xFF,
                    [GL_KEEP, op, GL_KEEP],
                    depth_pass,
                    0xFF,
                );
                let expected = if depth_pass {
                    clear as u8
                } else {
                    spec_stencil_op(op, clear as u8, 77)
                };
                assert_eq!(got, expected, "zfail op {op:#x} on {clear}");
            }
        }
    }
    // Comparison of masked reference against masked stored value; fail action; write mask.
    let funcs = [
        GL_NEVER,
        GL_LESS,
        GL_EQUAL,
        GL_LEQUAL,
        GL_GREATER,
        GL_NOTEQUAL,
        GL_GEQUAL,
        GL_ALWAYS,
    ];
    for &func in &funcs {
        for (clear, ref_, mask) in [
            (5, 5, 0xFF),
            (5, 6, 0xFF),
            (5, 6, 0xFE),
            (200, 3, 0x0F),
            (9, 300, 0xFF),
        ] {
            let (got, drawn) = stencil_after(
                clear,
                func,
                ref_,
                mask,
                [GL_INVERT, GL_KEEP, GL_REPLACE],
                true,
                0xF0,
            );
            let r = ref_.clamp(0, 255) as u8;
            let (a, b) = (r & mask as u8, clear as u8 & mask as u8);
            let pass = match func {
                GL_NEVER => false,
                GL_LESS => a < b,
                GL_EQUAL => a == b,
                GL_LEQUAL => a <= b,
                GL_GREATER => a > b,
                GL_NOTEQUAL => a != b,
                GL_GEQUAL => a >= b,
                _ => true,
            };
            let new = if pass { r } else { !(clear as u8) };
            let expected = (clear as u8 & 0x0F) | (new & 0xF0);
            assert_eq!(drawn, pass, "func {func:#x} {clear} {ref_} {mask:#x}");
            assert_eq!(got, expected, "func {func:#x} {clear} {ref_} {mask:#x}");
        }
    }
}

#[test]
fn every_logic_op() {
    let (s, d) = (0b1100_1010u8, 0b1010_0110u8);
    let expected: [u8; 16] = [
        0,
        s & d,
        s & !d,
        s,
        !s & d,
        d,
        s ^ d,
        s | d,
        !(s | d),
        !(s ^ d),
        !d,
        s | !d,
        !s,
        !s | d,
        !(s & d),
        0xFF,
    ];
    for (i, &e) in expected.iter().enumerate() {
        let mut gl = Context::new(4, 4);
        let f = |v: u8| v as f32 / 255.0;
        gl.clear_color(f(d), f(d), f(d), f(d));
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.enable(GL_COLOR_LOGIC_OP);
        gl.enable(GL_BLEND); // ignored while the logic op is enabled
        gl.blend_func(GL_ZERO, GL_ZERO);
        gl.logic_op(GL_CLEAR + i as GLenum);
        gl.color_4ub(s, s, s, s);
        gl.rectf(-1.0, -1.0, 1.0, 1.0);
        assert_eq!(pixel(&mut gl, 2, 2), [e; 4], "logic op {i}");
    }
}

#[test]
fn fragment_state_queries_round_trip() {
    let mut gl = Context::new(4, 4);
    gl.alpha_func(GL_GEQUAL, 1.5);
    gl.stencil_func(GL_NOTEQUAL, 3, 0x7);
    gl.stencil_op(GL_INCR_WRAP, GL_ZERO, GL_INVERT);
    gl.blend_func_separate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
    gl.blend_equation(GL_MAX);
    gl.logic_op(GL_XOR);
    let q = |gl: &mut Context, e| {
        let mut v = [0i32];
        gl.get_integerv(e, &mut v);
        v[0] as GLenum
    };
    assert_eq!(q(&mut gl, GL_ALPHA_TEST_FUNC), GL_GEQUAL);
    let mut r = [0f32];
    gl.get_floatv(GL_ALPHA_TEST_REF, &mut r);
    assert_eq!(r[0], 1.0);
    assert_eq!(q(&mut gl, GL_STENCIL_FUNC), GL_NOTEQUAL);
    assert_eq!(q(&mut gl, GL_STENCIL_VALUE_MASK), 7);
    assert_eq!(q(&mut gl, GL_STENCIL_FAIL), GL_INCR_WRAP);
    assert_eq!(q(&mut gl, GL_STENCIL_PASS_DEPTH_PASS), GL_INVERT);
    assert_eq!(q(&mut gl, GL_BLEND_SRC_RGB), GL_SRC_ALPHA);
    assert_eq!(q(&mut gl, GL_BLEND_DST_ALPHA), GL_ZERO);
    assert_eq!(q(&mut gl, GL_BLEND_EQUATION), GL_MAX);
    assert_eq!(q(&mut gl, GL_LOGIC_OP_MODE), GL_XOR);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

/// Fog (section 3.10): f from the equations, C = f C_r + (1 - f) C_f, with the eye distance
/// |z_eye| as fog coordinate, or the vertex fog coordinate.
#[test]
fn fog_equations() {
    let color = [0.8f32, 0.2, 0.4];
    let fog = [0.1f32, 0.5, 0.9];
    // (mode, density, start, end, eye depth, use fog coordinate)
    let cases = [
        (GL_LINEAR, 1.0, 2.0, 10.0, 5.0, false),
        (GL_LINEAR, 1.0, 2.0, 10.0, 12.0, false),
        (GL_LINEAR, 1.0, 4.0, 4.0, 3.0, false), // start == end
        (GL_EXP, 0.3, 0.0, 1.0, 4.0, false),
        (GL_EXP, 0.0, 0.0, 1.0, 4.0, false), // density 0: no fog
        (GL_EXP, 1e6, 0.0, 1.0, 4.0, false), // all fog
        (GL_EXP2, 0.2, 0.0, 1.0, 3.0, false),
        (GL_LINEAR, 1.0, 0.0, 8.0, 6.0, true),
        (GL_EXP, 0.5, 0.0, 1.0, -2.0, true), // negative fog coordinate
    ];
    for (mode, density, start, end, d, coord) in cases {
        let mut gl = Context::new(4, 4);
        gl.matrix_mode(GL_PROJECTION);
        gl.ortho(-1.0, 1.0, -1.0, 1.0, 0.0, 100.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.enable(GL_FOG);
        gl.fogi(GL_FOG_MODE, mode as i32);
        gl.fogf(GL_FOG_DENSITY, density);
        gl.fogf(GL_FOG_START, start);
        gl.fogf(GL_FOG_END, end);
        gl.fogfv(GL_FOG_COLOR, &[fog[0], fog[1], fog[2], 1.0]);
        let z = if coord {
            gl.fogi(GL_FOG_COORD_SRC, GL_FOG_COORD as i32);
            gl.fog_coordf(d);
            -50.0
        } else {
            -d
        };
        gl.color_3f(color[0], color[1], color[2]);
        gl.begin(GL_QUADS);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            gl.vertex_3f(x, y, z);
        }
        gl.end();
        let c = if coord { d } else { d.abs() };
        let f: f32 = match mode {
            GL_LINEAR => {
                if end == start {
                    (end - c).clamp(0.0, 1.0)
                } else {
                    ((end - c) / (end - start)).clamp(0.0, 1.0)
                }
            }
            GL_EXP => (-density * c).exp().clamp(0.0, 1.0),
            _ => (-(density * c) * (density * c)).exp().clamp(0.0, 1.0),
        };
        let got = pixel(&mut gl, 2, 2);
        for ch in 0..3 {
            let e = (f * color[ch] + (1.0 - f) * fog[ch]) * 255.0;
            assert!(
                (got[ch] as f32 - e).abs() <= 1.0,
                "mode {mode:#x} d {d}: ch {ch} got {} expected {e}",
                got[ch]
            );
        }
    }
}

#[test]
fn blend_equation_separate_applies_one_equation_to_colour_and_one_to_alpha() {
    // EXT_blend_equation_separate: RGB = src - dst (FUNC_SUBTRACT), A = max(src, dst).
    let mut gl = tilegl::Context::new(4, 4);
    gl.clear_color(0.2, 0.3, 0.1, 0.6);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_ONE, GL_ONE);
    gl.blend_equation_separate_ext(GL_FUNC_SUBTRACT, GL_MAX);
    let mut q = [0i32; 2];
    gl.get_integerv(GL_BLEND_EQUATION, &mut q[..1]);
    gl.get_integerv(GL_BLEND_EQUATION_ALPHA_EXT, &mut q[1..]);
    assert_eq!(q, [GL_FUNC_SUBTRACT as i32, GL_MAX as i32]);
    gl.color_4f(0.7, 0.2, 0.5, 0.4);
    gl.rectf(-1.0, -1.0, 1.0, 1.0);
    let mut px = [0u8; 4];
    gl.read_pixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    let q8 = |v: f32| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
    let d = [0.2f32, 0.3, 0.1, 0.6].map(|c| q8(c) as f32 / 255.0);
    let s = [0.7f32, 0.2, 0.5, 0.4].map(|c| q8(c) as f32 / 255.0);
    assert_eq!(
        px,
        [
            q8(s[0] - d[0]),
            q8(s[1] - d[1]),
            q8(s[2] - d[2]),
            q8(s[3].max(d[3]))
        ]
    );
    // glBlendEquation sets both again; a bad mode changes nothing.
    gl.blend_equation_separate_ext(GL_FUNC_ADD, GL_TEXTURE_2D);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.get_integerv(GL_BLEND_EQUATION_ALPHA_EXT, &mut q[1..]);
    assert_eq!(q[1], GL_MAX as i32);
    gl.blend_equation(GL_MIN);
    gl.get_integerv(GL_BLEND_EQUATION_ALPHA_EXT, &mut q[1..]);
    assert_eq!(q[1], GL_MIN as i32);
}

/// llvmpipe's blend arithmetic, written out here from measurements, not from tilegl's code:
/// each product (a byte times a byte factor) is rounded to 8 bits, then the two are added with
/// saturation. Measured on Mesa 22.3.6 llvmpipe through OSMesa for every source and destination
/// byte (`glDrawPixels` of both, 65536 pairs): 100 % of the pixels for `SRC_ALPHA,
/// ONE_MINUS_SRC_ALPHA` with alpha 15 and for `DST_COLOR, SRC_COLOR`; rounding the exact sum
/// instead (what softpipe does) matches 75.3 % and 58.2 %.
fn llvmpipe_blend(s: u32, sf: u32, d: u32, df: u32) -> u8 {
    let r8 = |x: u32| (x + 127) / 255;
    (r8(s * sf) + r8(d * df)).min(255) as u8
}

/// Every source byte (row y) over every destination byte (column x), blended as llvmpipe blends
/// (section 4.1.8 leaves the precision open): the capture xss-quasicrystal stacks seventeen
/// `SRC_ALPHA` layers, a `DST_COLOR, SRC_COLOR` quad and a logic op, which shows every 1-step
/// difference. Drawn twice: with `glDrawPixels` (the general fragment path) and as an RGBA
/// texture under `MODULATE` (the textured spans, eight fragments at a time with AVX2).
#[test]
fn blending_rounds_each_product_to_8_bits_as_llvmpipe() {
    const N: usize = 256;
    let dst: Vec<u8> = (0..N * N)
        .flat_map(|i| [(i % N) as u8, (i % N) as u8, (255 - i % N) as u8, 255])
        .collect();
    for (sf, df, alphas) in [
        (
            GL_SRC_ALPHA,
            GL_ONE_MINUS_SRC_ALPHA,
            &[0u8, 1, 15, 100, 128, 200, 255][..],
        ),
        (GL_DST_COLOR, GL_SRC_COLOR, &[255u8, 77][..]),
    ] {
        for &a in alphas {
            let src: Vec<u8> = (0..N * N)
                .flat_map(|i| [(i / N) as u8, (255 - i / N) as u8, (i / N) as u8, a])
                .collect();
            for textured in [false, true] {
                let mut gl = Context::new(N as i32, N as i32);
                gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
                gl.raster_pos_2f(-1.0, -1.0);
                gl.draw_pixels(N as i32, N as i32, GL_RGBA, GL_UNSIGNED_BYTE, Some(&dst));
                gl.enable(GL_BLEND);
                gl.blend_func(sf, df);
                if textured {
                    gl.tex_image_2d(
                        GL_TEXTURE_2D,
                        0,
                        GL_RGBA8 as i32,
                        N as i32,
                        N as i32,
                        0,
                        GL_RGBA,
                        GL_UNSIGNED_BYTE,
                        Some(&src),
                    );
                    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
                    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
                    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
                    gl.enable(GL_TEXTURE_2D);
                    gl.color_4f(1.0, 1.0, 1.0, 1.0);
                    gl.begin(GL_QUADS);
                    for (x, y) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
                        gl.tex_coord_2f(x, y);
                        gl.vertex_2f(2.0 * x - 1.0, 2.0 * y - 1.0);
                    }
                    gl.end();
                } else {
                    gl.draw_pixels(N as i32, N as i32, GL_RGBA, GL_UNSIGNED_BYTE, Some(&src));
                }
                assert_eq!(gl.get_error(), GL_NO_ERROR);
                let mut out = vec![0u8; N * N * 4];
                gl.read_pixels(
                    0,
                    0,
                    N as i32,
                    N as i32,
                    GL_RGBA,
                    GL_UNSIGNED_BYTE,
                    &mut out,
                );
                let mut wrong = 0;
                for i in 0..N * N {
                    for ch in 0..4 {
                        let (s, d) = (src[4 * i + ch] as u32, dst[4 * i + ch] as u32);
                        let sa = src[4 * i + 3] as u32;
                        let expected = if sf == GL_SRC_ALPHA {
                            llvmpipe_blend(s, sa, d, 255 - sa)
                        } else {
                            llvmpipe_blend(s, d, d, s)
                        };
                        if out[4 * i + ch] != expected {
                            wrong += 1;
                        }
                    }
                }
                assert_eq!(
                    wrong, 0,
                    "sf {sf:#x} df {df:#x} alpha {a} textured {textured}: {wrong} channels differ"
                );
            }
        }
    }
}

//! ARB_texture_float: float internal formats keep unclamped values (TexImage, TexSubImage,
//! pixel transfer, GetTexImage, mipmap generation), filter them unclamped, clamp the filtered
//! texel to [0, 1] as it enters the texture environment (issue 7 of the extension, with a
//! fixed-point colour buffer), and answer the component type queries. Expected values come
//! from the extension's text (section 2.1.2's half-float encoding, table 3.16, issue 7).

mod common;

use common::{level_param, pixel, window_ortho};
use tilegl::enums::*;
use tilegl::{Context, Gl};

fn f32_bytes(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|f| f.to_ne_bytes()).collect()
}

fn floats(b: &[u8]) -> Vec<f32> {
    b.chunks(4)
        .map(|c| f32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
        .collect()
}

/// A `w` x `h` 2D texture of `internal` from RGBA floats, bound and enabled.
fn texture(gl: &mut Context, internal: GLenum, w: i32, h: i32, rgba: &[f32]) {
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        internal as i32,
        w,
        h,
        0,
        GL_RGBA,
        GL_FLOAT,
        Some(&f32_bytes(rgba)),
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR, "{internal:#x}");
}

fn get_rgba(gl: &mut Context, level: i32, n: usize) -> Vec<f32> {
    let mut out = vec![0u8; n * 16];
    gl.get_tex_image(GL_TEXTURE_2D, level, GL_RGBA, GL_FLOAT, &mut out);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    floats(&out)
}

/// The half value (-1)^S 2^(E-15) (1 + M/1024) of section 2.1.2.
fn half(s: u32, e: i32, m: u32) -> f32 {
    let sign = if s == 1 { -1.0 } else { 1.0 };
    sign * 2f32.powi(e - 15) * (1.0 + m as f32 / 1024.0)
}

#[test]
fn extension_is_listed() {
    let mut gl = Context::new(4, 4);
    let ext = gl.get_string(GL_EXTENSIONS).unwrap_or_default();
    assert!(ext.split(' ').any(|e| e == "GL_ARB_texture_float"));
}

#[test]
fn values_outside_zero_one_round_trip() {
    let mut gl = Context::new(4, 4);
    let data = [2.5, -1.25, 0.5, 1.0e6, -0.0, 1.0e-3, 7.0, -300.0];
    texture(&mut gl, GL_RGBA32F_ARB, 2, 1, &data);
    assert_eq!(get_rgba(&mut gl, 0, 2), data);
    // 16-bit floats: values a half holds come back exactly; others round to the nearest half;
    // beyond 65504 is infinity.
    texture(
        &mut gl,
        GL_RGBA16F_ARB,
        2,
        1,
        &[2.5, -1.25, 0.1, 7.0e4, -3.0, 1024.5, 0.25, 0.0],
    );
    let got = get_rgba(&mut gl, 0, 2);
    // 0.1 = 2^-4 * 1.6: E = 11, M = round(0.6 * 1024) = 614; 1024.5 is half-way between the
    // halves 1024 and 1025 (spacing 1 from 1024 up), ties to even: 1024.
    assert_eq!(
        got,
        [
            2.5,
            -1.25,
            half(0, 11, 614),
            f32::INFINITY,
            -3.0,
            1024.0,
            0.25,
            0.0
        ]
    );
    // Luminance/alpha and intensity keep their components unclamped too (GetTexImage as
    // RGBA: L in R, G and B 0, as for fixed-point images).
    texture(
        &mut gl,
        GL_LUMINANCE_ALPHA32F_ARB,
        1,
        1,
        &[3.0, 9.0, 9.0, -4.0],
    );
    assert_eq!(get_rgba(&mut gl, 0, 1), [3.0, 0.0, 0.0, -4.0]);
    texture(&mut gl, GL_INTENSITY32F_ARB, 1, 1, &[-8.0, 0.0, 0.0, 0.0]);
    assert_eq!(get_rgba(&mut gl, 0, 1), [-8.0, 0.0, 0.0, 1.0]);
    texture(&mut gl, GL_ALPHA16F_ARB, 1, 1, &[0.0, 0.0, 0.0, 12.0]);
    assert_eq!(get_rgba(&mut gl, 0, 1), [0.0, 0.0, 0.0, 12.0]);
    texture(&mut gl, GL_R32F, 1, 1, &[-5.0, 2.0, 2.0, 2.0]);
    assert_eq!(get_rgba(&mut gl, 0, 1), [-5.0, 0.0, 0.0, 1.0]);
}

#[test]
fn fixed_point_reads_and_formats_clamp() {
    let mut gl = Context::new(4, 4);
    texture(&mut gl, GL_RGBA32F_ARB, 1, 1, &[2.5, -1.25, 0.5, 1.0]);
    let mut bytes = [0u8; 4];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut bytes);
    assert_eq!(bytes, [255, 0, 128, 255]);
    // The same floats into a fixed-point format are clamped on the way in.
    texture(&mut gl, GL_RGBA16, 1, 1, &[2.5, -1.25, 0.5, 1.0]);
    let got = get_rgba(&mut gl, 0, 1);
    let want = [1.0, 0.0, 32768.0 / 65535.0, 1.0];
    for k in 0..4 {
        assert!((got[k] - want[k]).abs() < 1e-6, "{got:?}");
    }
}

#[test]
fn sub_images_and_pixel_transfer_keep_values_unclamped() {
    let mut gl = Context::new(4, 4);
    texture(&mut gl, GL_RGBA32F_ARB, 2, 1, &[0.0; 8]);
    gl.tex_sub_image_2d(
        GL_TEXTURE_2D,
        0,
        1,
        0,
        1,
        1,
        GL_RGBA,
        GL_FLOAT,
        Some(&f32_bytes(&[4.0, -4.0, 0.25, 2.0])),
    );
    assert_eq!(
        get_rgba(&mut gl, 0, 2),
        [0.0, 0.0, 0.0, 0.0, 4.0, -4.0, 0.25, 2.0]
    );
    // Scale and bias (section 3.6.5) then no clamp: 1.5 * 2 + 0 = 3, 0.5 * 1 - 2 = -1.5.
    gl.pixel_transferf(GL_RED_SCALE, 2.0);
    gl.pixel_transferf(GL_GREEN_BIAS, -2.0);
    texture(&mut gl, GL_RGBA32F_ARB, 1, 1, &[1.5, 0.5, 0.75, 1.0]);
    assert_eq!(get_rgba(&mut gl, 0, 1), [3.0, -1.5, 0.75, 1.0]);
    // Byte data takes the same route: 255 / 255 * 2 = 2.
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA32F_ARB as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[255, 0, 0, 255]),
    );
    assert_eq!(get_rgba(&mut gl, 0, 1), [2.0, -2.0, 0.0, 1.0]);
}

#[test]
fn generated_mipmaps_average_unclamped_values() {
    let mut gl = Context::new(4, 4);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE as i32);
    // Level 1 is the mean of the four texels: (8 - 2 + 0.5 - 2.5) / 4 = 1 (clamping first
    // would give (1 + 0 + 0.5 + 0) / 4).
    texture(
        &mut gl,
        GL_LUMINANCE32F_ARB,
        2,
        2,
        &[
            8.0, 0.0, 0.0, 1.0, -2.0, 0.0, 0.0, 1.0, 0.5, 0.0, 0.0, 1.0, -2.5, 0.0, 0.0, 1.0,
        ],
    );
    assert_eq!(get_rgba(&mut gl, 1, 1), [1.0, 0.0, 0.0, 1.0]);
}

/// One row of a 2x1 GL_LINEAR texture stretched over an 8x1 strip: window x maps to
/// u = (x + 1/2) / 8 * 2 - 1/2, filtered as (1 - a) T[i0] + a T[i1] (section 3.8.8,
/// CLAMP_TO_EDGE), then clamped to [0, 1] for the texture environment (REPLACE).
#[test]
fn linear_filtering_of_unclamped_texels_then_environment_clamp() {
    let mut gl = Context::new(8, 1);
    window_ortho(&mut gl);
    let (t0, t1) = (2.0f32, -0.5f32);
    texture(
        &mut gl,
        GL_LUMINANCE32F_ARB,
        2,
        1,
        &[t0, 0.0, 0.0, 1.0, t1, 0.0, 0.0, 1.0],
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.begin(GL_QUADS);
    gl.tex_coord_2f(0.0, 0.0);
    gl.vertex_2f(0.0, 0.0);
    gl.tex_coord_2f(1.0, 0.0);
    gl.vertex_2f(8.0, 0.0);
    gl.tex_coord_2f(1.0, 1.0);
    gl.vertex_2f(8.0, 1.0);
    gl.tex_coord_2f(0.0, 1.0);
    gl.vertex_2f(0.0, 1.0);
    gl.end();
    let mut distinct_from_clamp_first = 0;
    for x in 0..8 {
        let u = (x as f32 + 0.5) / 8.0 * 2.0 - 0.5;
        let (i0, a) = (u.floor(), u - u.floor());
        let at = |i: f32| if i <= 0.0 { t0 } else { t1 };
        let filtered = (1.0 - a) * at(i0) + a * at(i0 + 1.0);
        let want = (filtered.clamp(0.0, 1.0) * 255.0).round() as i32;
        let clamp_first = ((1.0 - a) * t0.clamp(0.0, 1.0) + a * t1.clamp(0.0, 1.0)) * 255.0;
        if (clamp_first.round() as i32 - want).abs() > 2 {
            distinct_from_clamp_first += 1;
        }
        let got = pixel(&mut gl, x, 0)[0] as i32;
        assert!((got - want).abs() <= 1, "x {x}: {got} want {want}");
    }
    // The row tells unclamped filtering from filtering of clamped texels.
    assert!(distinct_from_clamp_first >= 3);
}

/// Issue 7: "the filtered texel is now clamped before it is used for texture environment
/// blending": MODULATE of a texel of 4 with a colour of 0.5 gives 0.5, not 1.
#[test]
fn texels_clamp_before_the_environment() {
    let mut gl = Context::new(4, 4);
    window_ortho(&mut gl);
    texture(&mut gl, GL_RGBA32F_ARB, 1, 1, &[4.0, -3.0, 0.5, 2.0]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.color_4f(0.5, 0.5, 1.0, 0.5);
    gl.rectf(0.0, 0.0, 4.0, 4.0);
    // (0.5 * 1, 0.5 * 0, 1 * 0.5, 0.5 * 1) in 8 bits.
    assert_eq!(pixel(&mut gl, 2, 2), [128, 0, 128, 128]);
}

#[test]
fn component_type_queries() {
    let mut gl = Context::new(4, 4);
    let types = [
        GL_TEXTURE_RED_TYPE_ARB,
        GL_TEXTURE_GREEN_TYPE_ARB,
        GL_TEXTURE_BLUE_TYPE_ARB,
        GL_TEXTURE_ALPHA_TYPE_ARB,
        GL_TEXTURE_LUMINANCE_TYPE_ARB,
        GL_TEXTURE_INTENSITY_TYPE_ARB,
        GL_TEXTURE_DEPTH_TYPE_ARB,
    ];
    let (f, u, n) = (
        GL_FLOAT as i32,
        GL_UNSIGNED_NORMALIZED_ARB as i32,
        GL_NONE as i32,
    );
    // Per table 3.16: which of R, G, B, A, L, I, D the format has, and the sizes (the actual
    // resolution: 32 and 16 for the float formats).
    let cases: [(GLenum, [i32; 7], i32); 9] = [
        (GL_RGBA32F_ARB, [f, f, f, f, n, n, n], 32),
        (GL_RGB16F_ARB, [f, f, f, n, n, n, n], 16),
        (GL_ALPHA32F_ARB, [n, n, n, f, n, n, n], 32),
        (GL_LUMINANCE16F_ARB, [n, n, n, n, f, n, n], 16),
        (GL_LUMINANCE_ALPHA32F_ARB, [n, n, n, f, f, n, n], 32),
        (GL_INTENSITY16F_ARB, [n, n, n, n, n, f, n], 16),
        (GL_RG32F, [f, f, n, n, n, n, n], 32),
        (GL_RGBA8, [u, u, u, u, n, n, n], 8),
        (GL_LUMINANCE8_ALPHA8, [n, n, n, u, u, n, n], 8),
    ];
    for (internal, want, size) in cases {
        texture(&mut gl, internal, 1, 1, &[0.0; 4]);
        for (k, &t) in types.iter().enumerate() {
            assert_eq!(
                level_param(&mut gl, GL_TEXTURE_2D, 0, t),
                want[k],
                "{internal:#x} {t:#x}"
            );
        }
        let sizes = [
            GL_TEXTURE_RED_SIZE,
            GL_TEXTURE_GREEN_SIZE,
            GL_TEXTURE_BLUE_SIZE,
            GL_TEXTURE_ALPHA_SIZE,
            GL_TEXTURE_LUMINANCE_SIZE,
            GL_TEXTURE_INTENSITY_SIZE,
            GL_TEXTURE_DEPTH_SIZE,
        ];
        for (k, &s) in sizes.iter().enumerate() {
            let expect = if want[k] == n { 0 } else { size };
            assert_eq!(
                level_param(&mut gl, GL_TEXTURE_2D, 0, s),
                expect,
                "{internal:#x}"
            );
        }
        assert_eq!(
            level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT),
            internal as i32
        );
    }
    // Depth formats.
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_DEPTH_COMPONENT24 as i32,
        1,
        1,
        0,
        GL_DEPTH_COMPONENT,
        GL_FLOAT,
        Some(&f32_bytes(&[0.5])),
    );
    assert_eq!(
        level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_TYPE_ARB),
        u
    );
    assert_eq!(
        level_param(&mut gl, GL_TEXTURE_2D, 0, GL_TEXTURE_RED_TYPE_ARB),
        n
    );
    // A level without an image, and a proxy that does not fit: NONE.
    assert_eq!(
        level_param(&mut gl, GL_TEXTURE_2D, 3, GL_TEXTURE_RED_TYPE_ARB),
        n
    );
    gl.tex_image_2d(
        GL_PROXY_TEXTURE_2D,
        0,
        GL_RGBA32F_ARB as i32,
        16384,
        16384,
        0,
        GL_RGBA,
        GL_FLOAT,
        None,
    );
    // (16384^2 RGBA32F texels are 4 GiB, over the 1 GiB images are allowed.)
    gl.get_error();
    assert_eq!(
        level_param(&mut gl, GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_RED_TYPE_ARB),
        n
    );
    gl.tex_image_2d(
        GL_PROXY_TEXTURE_2D,
        0,
        GL_RGBA32F_ARB as i32,
        4,
        4,
        0,
        GL_RGBA,
        GL_FLOAT,
        None,
    );
    assert_eq!(
        level_param(&mut gl, GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_RED_TYPE_ARB),
        f
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    // The type enums are level parameters only.
    let mut v = [0i32];
    gl.get_tex_parameteriv(GL_TEXTURE_2D, GL_TEXTURE_RED_TYPE_ARB, &mut v);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.get_tex_level_parameteriv(GL_TEXTURE_2D, -1, GL_TEXTURE_RED_TYPE_ARB, &mut v);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
}

//! The sampler against the specification's equations (OpenGL 1.5 sections 3.8.8-3.8.9,
//! 3.8.14), computed independently in the test: wrap functions, bilinear weights, λ from ρ,
//! mipmap level selection, the switch-over constant, cube face selection, 3D, depth
//! comparison, border colour and border texels, anisotropy, extreme inputs.
//!
//! Textures are specified through the `Gl` trait; the snapshot a draw would sample comes from
//! `Context::bound_texture`.

use tilegl::enums::*;
use tilegl::texture::BoundTexture;
use tilegl::{Context, Gl};

const EPS: f32 = 1e-4;

/// LINEAR filtering of unsigned-byte textures wrapped by `REPEAT` or `CLAMP_TO_EDGE` runs in
/// 8-bit fixed point, as llvmpipe filters them (`tilegl::texture::fixed`): weights rounded to
/// 1/256 and every lerp rounded to a byte. Against the equation in real numbers one lerp is
/// then off by at most 255/512 + 1/2 < 1 byte (the weight's rounding times the largest texel
/// difference, plus the rounding of the result), so 1D filtering is within 1/255...
const LERP_EPS: f32 = 1.0 / 255.0;
/// ...a bilinear result (two row lerps, then a lerp of the rounded rows) within
/// 2 x (255/512 + 1/2) < 2 bytes...
const BILINEAR_EPS: f32 = 2.0 / 255.0;
/// ...and the mix of two levels adds the truncation of the level weight to 1/256 (under one
/// byte) and one rounding (1/2 byte) to the levels' own error (none for the uniform levels of
/// [`mip_chain`], whose bilinear results are exact).
const LEVEL_MIX_EPS: f32 = 1.5 / 255.0;

fn ctx() -> Context {
    Context::new(16, 16)
}

/// Uploads a `w` x `h` LUMINANCE8 texture with the given texel bytes on 2D, sets filters and
/// wraps and returns the snapshot.
fn lum_2d(
    gl: &mut Context,
    w: i32,
    h: i32,
    texels: &[u8],
    min: GLenum,
    mag: GLenum,
    wrap: GLenum,
) -> BoundTexture {
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE8 as i32,
        w,
        h,
        0,
        GL_LUMINANCE,
        GL_UNSIGNED_BYTE,
        Some(texels),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap as i32);
    gl.enable(GL_TEXTURE_2D);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.bound_texture(0).expect("complete texture")
}

/// The wrap functions written out from the specification (integer form), independently.
fn spec_wrap(i: i64, n: i64, wrap: GLenum, linear: bool) -> i64 {
    match wrap {
        GL_REPEAT => ((i % n) + n) % n,
        GL_CLAMP_TO_EDGE => i.max(0).min(n - 1),
        GL_CLAMP if !linear => i.max(0).min(n - 1),
        GL_CLAMP | GL_CLAMP_TO_BORDER => i.max(-1).min(n),
        GL_MIRRORED_REPEAT => {
            let m = ((i % (2 * n)) + 2 * n) % (2 * n);
            if m >= n {
                2 * n - 1 - m
            } else {
                m
            }
        }
        _ => unreachable!(),
    }
}

/// 1D-along-s expected value of a row texture `row` (values 0..1) at `s` with a border colour
/// value `border` (luminance).
fn spec_1d(row: &[f32], s: f32, wrap: GLenum, linear: bool, border: f32) -> f32 {
    let n = row.len() as i64;
    let s = if wrap == GL_CLAMP {
        s.clamp(0.0, 1.0)
    } else {
        s
    } as f64;
    let u = s * n as f64;
    let tex = |i: i64| {
        if i < 0 || i >= n {
            border
        } else {
            row[i as usize]
        }
    };
    if !linear {
        return tex(spec_wrap(u.floor() as i64, n, wrap, false));
    }
    let i0 = (u - 0.5).floor() as i64;
    let a = ((u - 0.5) - (u - 0.5).floor()) as f32;
    (1.0 - a) * tex(spec_wrap(i0, n, wrap, true)) + a * tex(spec_wrap(i0 + 1, n, wrap, true))
}

#[test]
fn wrap_modes_nearest_and_linear_match_the_spec() {
    let bytes = [0u8, 40, 100, 255, 7];
    let row: Vec<f32> = bytes.iter().map(|&b| b as f32 / 255.0).collect();
    let border = [0.25f32, 0.5, 0.75, 1.0];
    for wrap in [
        GL_REPEAT,
        GL_CLAMP,
        GL_CLAMP_TO_EDGE,
        GL_CLAMP_TO_BORDER,
        GL_MIRRORED_REPEAT,
    ] {
        for (filter, linear) in [(GL_NEAREST, false), (GL_LINEAR, true)] {
            let mut gl = ctx();
            gl.tex_parameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, &border);
            // A 5x1 texture: t is constant along the single row under every wrap only for
            // REPEAT/MIRRORED/EDGE; use a 5x1 texture with t = 0.5 so t always hits row 0
            // with weight 0 (u = 0.5 * 1 - 0.5 = 0).
            let tex = lum_2d(&mut gl, 5, 1, &bytes, filter, filter, wrap);
            for k in -40..=40 {
                let s = k as f32 * 0.0731;
                let got = tex.sample([s, 0.5, 0.0], 0.0)[0];
                let want = spec_1d(&row, s, wrap, linear, border[0]);
                // The fixed-point tier (see LERP_EPS) filters REPEAT and CLAMP_TO_EDGE; the
                // other modes keep the f32 filter and the tight bound.
                let eps = if linear && matches!(wrap, GL_REPEAT | GL_CLAMP_TO_EDGE) {
                    LERP_EPS
                } else {
                    EPS
                };
                assert!(
                    (got - want).abs() <= eps,
                    "wrap {wrap:#x} linear {linear} s {s}: {got} vs {want}"
                );
            }
        }
    }
}

#[test]
fn bilinear_weights_follow_the_spec_formula() {
    let mut gl = ctx();
    let bytes = [10u8, 200, 60, 130];
    let tex = lum_2d(
        &mut gl,
        2,
        2,
        &bytes,
        GL_LINEAR,
        GL_LINEAR,
        GL_CLAMP_TO_EDGE,
    );
    let t = |i: usize, j: usize| bytes[j * 2 + i] as f32 / 255.0;
    for (s, tt) in [(0.3f32, 0.6f32), (0.5, 0.5), (0.71, 0.27), (0.25, 0.75)] {
        let u = s * 2.0 - 0.5;
        let v = tt * 2.0 - 0.5;
        let (a, b) = (u - u.floor(), v - v.floor());
        let (i0, j0) = (u.floor() as i64, v.floor() as i64);
        let c = |i: i64| i.clamp(0, 1) as usize;
        let want = (1.0 - a) * (1.0 - b) * t(c(i0), c(j0))
            + a * (1.0 - b) * t(c(i0 + 1), c(j0))
            + (1.0 - a) * b * t(c(i0), c(j0 + 1))
            + a * b * t(c(i0 + 1), c(j0 + 1));
        let got = tex.sample([s, tt, 0.0], -1.0);
        // A LUMINANCE8 texture under CLAMP_TO_EDGE: the fixed-point tier (BILINEAR_EPS).
        assert!(
            (got[0] - want).abs() <= BILINEAR_EPS,
            "{s},{tt}: {got:?} vs {want}"
        );
        assert_eq!(got[0], got[1]);
        assert_eq!(got[3], 1.0, "luminance has alpha 1");
    }
}

/// A mip chain 8x8, 4x4, 2x2, 1x1 where level l is uniformly (l + 1) * 50.
fn mip_chain(gl: &mut Context, min: GLenum, mag: GLenum) -> BoundTexture {
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    for l in 0..4i32 {
        let n = 8usize >> l;
        let data = vec![((l + 1) * 50) as u8; n * n];
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            l,
            GL_LUMINANCE as i32,
            n as i32,
            n as i32,
            0,
            GL_LUMINANCE,
            GL_UNSIGNED_BYTE,
            Some(&data),
        );
    }
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag as i32);
    gl.enable(GL_TEXTURE_2D);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.bound_texture(0).expect("mipmap complete")
}

fn level_value(l: usize) -> f32 {
    ((l + 1) * 50) as f32 / 255.0
}

#[test]
fn lambda_from_rho_for_known_derivatives() {
    let mut gl = ctx();
    let tex = mip_chain(&mut gl, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    // ds/dx = 0.5 on an 8-wide base: du/dx = 4, dv/dy = 1 -> rho = 4 -> lambda = 2.
    let l = tex.scale_factor_lambda([0.5, 0.0, 0.0], [0.0, 0.125, 0.0], 0.0);
    assert!((l - 2.0).abs() < EPS, "{l}");
    // Length, not max of components: (3/8, 4/8) * 8 = (3, 4) -> rho 5.
    let l = tex.scale_factor_lambda([0.375, 0.5, 0.0], [0.0, 0.0, 0.0], 0.0);
    assert!((l - 5f32.log2()).abs() < EPS);
    // Unit bias adds; MIN/MAX_LOD clamp.
    let l = tex.scale_factor_lambda([0.5, 0.0, 0.0], [0.0; 3], 0.5);
    assert!((l - 2.5).abs() < EPS);
    // Zero derivatives: log2 0 = -inf, clamped to MIN_LOD (-1000).
    assert_eq!(tex.scale_factor_lambda([0.0; 3], [0.0; 3], 0.0), -1000.0);
    // Infinite or NaN: the coarsest allowed (MAX_LOD = 1000).
    assert_eq!(
        tex.scale_factor_lambda([f32::INFINITY, 0.0, 0.0], [0.0; 3], 0.0),
        1000.0
    );
    assert_eq!(
        tex.scale_factor_lambda([f32::NAN; 3], [f32::NAN; 3], 0.0),
        1000.0
    );
    let mut gl = ctx();
    mip_chain(&mut gl, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 0.5);
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 1.5);
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.0);
    let tex = gl.bound_texture(0).expect("complete");
    assert_eq!(tex.scale_factor_lambda([0.0; 3], [0.0; 3], 0.0), 0.5);
    assert_eq!(tex.scale_factor_lambda([0.5, 0.0, 0.0], [0.0; 3], 0.0), 1.5);
    let l = tex.scale_factor_lambda([0.125, 0.0, 0.0], [0.0; 3], -0.75);
    assert!((l - 0.5).abs() < EPS); // log2(1) + 1 - 0.75 = 0.25 -> clamped to 0.5
}

#[test]
fn mipmap_level_selection_for_every_filter() {
    for lambda in [
        -1.0f32, 0.0, 0.3, 0.5, 0.51, 1.2, 1.5, 1.7, 2.5, 2.9, 3.0, 7.0,
    ] {
        // NEAREST_MIPMAP_NEAREST: d = 0 if lambda <= 1/2 else ceil(lambda + 1/2) - 1, <= q.
        let mut gl = ctx();
        let tex = mip_chain(&mut gl, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
        let d = if lambda <= 0.5 {
            0
        } else {
            (((lambda + 0.5).ceil() - 1.0) as usize).min(3)
        };
        let want = if lambda <= 0.0 {
            level_value(0)
        } else {
            level_value(d)
        };
        let got = tex.sample([0.3, 0.3, 0.0], lambda)[0];
        assert!(
            (got - want).abs() < EPS,
            "NMN lambda {lambda}: {got} vs {want}"
        );
        // LINEAR_MIPMAP_LINEAR: (1 - frac) level floor + frac level floor + 1.
        let mut gl = ctx();
        let tex = mip_chain(&mut gl, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
        let want = if lambda <= 0.0 {
            level_value(0)
        } else if lambda >= 3.0 {
            level_value(3)
        } else {
            let f = lambda - lambda.floor();
            let d1 = lambda.floor() as usize;
            (1.0 - f) * level_value(d1) + f * level_value(d1 + 1)
        };
        let got = tex.sample([0.3, 0.3, 0.0], lambda)[0];
        // Byte texels under the default REPEAT: levels mixed in fixed point (LEVEL_MIX_EPS).
        assert!(
            (got - want).abs() <= LEVEL_MIX_EPS,
            "LML lambda {lambda}: {got} vs {want}"
        );
    }
}

#[test]
fn switch_over_constant_is_one_half_only_for_linear_mag_and_nearest_mipmap_min() {
    let cases = [
        (GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR, 0.5),
        (GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR, 0.5),
        (GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, 0.0),
        (GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 0.0),
        (GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, 0.0),
        (GL_LINEAR, GL_LINEAR, 0.0),
    ];
    for (min, mag, c) in cases {
        let mut gl = ctx();
        let tex = mip_chain(&mut gl, min, mag);
        assert_eq!(tex.switch_over(), c, "min {min:#x} mag {mag:#x}");
    }
    // With c = 0.5, lambda = 0.4 is magnification: base level, LINEAR.
    let mut gl = ctx();
    let tex = mip_chain(&mut gl, GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR);
    assert!((tex.sample([0.5, 0.5, 0.0], 0.4)[0] - level_value(0)).abs() < EPS);
    // lambda = 0.6 is minification: NEAREST_MIPMAP_LINEAR blends levels 0 and 1 with 0.6.
    let want = 0.4 * level_value(0) + 0.6 * level_value(1);
    assert!((tex.sample([0.5, 0.5, 0.0], 0.6)[0] - want).abs() < EPS);
}

#[test]
fn border_texels_are_used_by_clamp_and_border_colour_otherwise() {
    // A 2x2 texture with a 1-texel border (4x4 stored): inner 255, border 0.
    let mut gl = ctx();
    let mut data = vec![0u8; 16];
    for j in 1..3 {
        for i in 1..3 {
            data[j * 4 + i] = 255;
        }
    }
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE as i32,
        4,
        4,
        1,
        GL_LUMINANCE,
        GL_UNSIGNED_BYTE,
        Some(&data),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP as i32);
    gl.tex_parameterfv(
        GL_TEXTURE_2D,
        GL_TEXTURE_BORDER_COLOR,
        &[1.0, 1.0, 1.0, 1.0],
    );
    gl.enable(GL_TEXTURE_2D);
    let tex = gl.bound_texture(0).expect("complete");
    // At s = 0 (u = 0, u - 1/2 = -1/2): half the border texel (0), half texel 0 (1) -> 0.5 in s;
    // t = 0.5 is inside, so 0.5 overall; the border colour (white) is not used.
    let v = tex.sample([0.0, 0.5, 0.0], 0.0)[0];
    assert!((v - 0.5).abs() < EPS, "{v}");
    // Without a border, GL_CLAMP blends with the border colour (here 0.2).
    let mut gl = ctx();
    gl.tex_parameterfv(
        GL_TEXTURE_2D,
        GL_TEXTURE_BORDER_COLOR,
        &[0.2, 0.2, 0.2, 0.2],
    );
    let tex = lum_2d(&mut gl, 2, 2, &[255; 4], GL_LINEAR, GL_LINEAR, GL_CLAMP);
    let v = tex.sample([0.0, 0.5, 0.0], 0.0)[0];
    assert!((v - 0.6).abs() < EPS, "{v}");
    // ... and at the corner two axes blend: (1/2 * 1/2) texel, 3/4 border.
    let v = tex.sample([0.0, 1.0, 0.0], 0.0)[0];
    assert!((v - (0.25 + 0.75 * 0.2)).abs() < EPS, "{v}");
    // CLAMP_TO_EDGE never sees the border colour.
    let mut gl = ctx();
    gl.tex_parameterfv(
        GL_TEXTURE_2D,
        GL_TEXTURE_BORDER_COLOR,
        &[0.2, 0.2, 0.2, 0.2],
    );
    let tex = lum_2d(
        &mut gl,
        2,
        2,
        &[255; 4],
        GL_LINEAR,
        GL_LINEAR,
        GL_CLAMP_TO_EDGE,
    );
    assert_eq!(tex.sample([-5.0, 9.0, 0.0], 0.0)[0], 1.0);
}

#[test]
fn base_formats_expand_to_rgba_per_table() {
    let cases: [(GLenum, GLenum, Vec<u8>, [f32; 4]); 6] = [
        (GL_ALPHA, GL_ALPHA, vec![51], [0.0, 0.0, 0.0, 0.2]),
        (GL_LUMINANCE, GL_LUMINANCE, vec![51], [0.2, 0.2, 0.2, 1.0]),
        (
            GL_LUMINANCE_ALPHA,
            GL_LUMINANCE_ALPHA,
            vec![51, 102],
            [0.2, 0.2, 0.2, 0.4],
        ),
        (GL_INTENSITY, GL_LUMINANCE, vec![51], [0.2, 0.2, 0.2, 0.2]),
        (GL_RGB, GL_RGB, vec![51, 102, 153], [0.2, 0.4, 0.6, 1.0]),
        (
            GL_RGBA,
            GL_RGBA,
            vec![51, 102, 153, 204],
            [0.2, 0.4, 0.6, 0.8],
        ),
    ];
    for (ifmt, fmt, data, want) in cases {
        let mut gl = ctx();
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            ifmt as i32,
            1,
            1,
            0,
            fmt,
            GL_UNSIGNED_BYTE,
            Some(&data),
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        gl.enable(GL_TEXTURE_2D);
        let tex = gl.bound_texture(0).expect("complete");
        let got = tex.sample([0.5, 0.5, 0.0], 0.0);
        for c in 0..4 {
            assert!(
                (got[c] - want[c]).abs() < EPS,
                "{ifmt:#x}: {got:?} vs {want:?}"
            );
        }
    }
}

#[test]
fn cube_maps_select_faces_by_major_axis() {
    let mut gl = ctx();
    for f in 0..6u32 {
        // Face f: 2x2, texel (i, j) = 40 * f + 10 * (2j + i).
        let data: Vec<u8> = (0..4).map(|k| (40 * f + 10 * k) as u8).collect();
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        gl.tex_image_2d(
            GL_TEXTURE_CUBE_MAP_POSITIVE_X + f,
            0,
            GL_LUMINANCE as i32,
            2,
            2,
            0,
            GL_LUMINANCE,
            GL_UNSIGNED_BYTE,
            Some(&data),
        );
    }
    gl.tex_parameteri(
        GL_TEXTURE_CUBE_MAP,
        GL_TEXTURE_MIN_FILTER,
        GL_NEAREST as i32,
    );
    gl.tex_parameteri(
        GL_TEXTURE_CUBE_MAP,
        GL_TEXTURE_MAG_FILTER,
        GL_NEAREST as i32,
    );
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_TEXTURE_CUBE_MAP);
    let tex = gl.bound_texture(0).expect("cube complete");
    // Table 3.19: (face, sc, tc, ma) for a direction; s = (sc/|ma| + 1)/2.
    let dirs: [[f32; 3]; 6] = [
        [1.0, 0.4, -0.3],
        [-1.0, -0.4, 0.3],
        [0.2, 1.0, -0.6],
        [-0.2, -1.0, 0.6],
        [0.7, -0.3, 1.0],
        [-0.7, 0.3, -1.0],
    ];
    for (f, d) in dirs.iter().enumerate() {
        let [x, y, z] = *d;
        let (sc, tc, ma) = match f {
            0 => (-z, -y, x),
            1 => (z, -y, x),
            2 => (x, z, y),
            3 => (x, -z, y),
            4 => (x, -y, z),
            _ => (-x, -y, z),
        };
        let s = (sc / ma.abs() + 1.0) / 2.0;
        let t = (tc / ma.abs() + 1.0) / 2.0;
        let (i, j) = ((s * 2.0).floor() as u32, (t * 2.0).floor() as u32);
        let want = (40 * f as u32 + 10 * (2 * j + i)) as f32 / 255.0;
        let got = tex.sample(*d, 0.0)[0];
        assert!((got - want).abs() < EPS, "face {f}: {got} vs {want}");
    }
}

#[test]
fn cube_map_incomplete_without_all_faces() {
    let mut gl = ctx();
    gl.tex_image_2d(
        GL_TEXTURE_CUBE_MAP_POSITIVE_X,
        0,
        GL_RGBA as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[0; 16]),
    );
    gl.tex_parameteri(
        GL_TEXTURE_CUBE_MAP,
        GL_TEXTURE_MIN_FILTER,
        GL_NEAREST as i32,
    );
    gl.enable(GL_TEXTURE_CUBE_MAP);
    assert!(gl.bound_texture(0).is_none());
    // Precedence: the incomplete cube map disables the unit even with a complete 2D texture.
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[0; 4]),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    assert!(gl.bound_texture(0).is_none());
    gl.disable(GL_TEXTURE_CUBE_MAP);
    assert!(gl.bound_texture(0).is_some());
}

#[test]
fn three_d_trilinear_weights() {
    let mut gl = ctx();
    // 2x2x2, texel (i,j,k) = 30 * (4k + 2j + i).
    let data: Vec<u8> = (0..8).map(|n| (30 * n) as u8).collect();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
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
    gl.tex_parameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    for p in [GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R] {
        gl.tex_parameteri(GL_TEXTURE_3D, p, GL_CLAMP_TO_EDGE as i32);
    }
    gl.enable(GL_TEXTURE_3D);
    let tex = gl.bound_texture(0).expect("complete");
    let (s, t, r) = (0.4f32, 0.6f32, 0.55f32);
    let w = |c: f32| c * 2.0 - 0.5; // floor is 0 for all three here
    let (a, b, g) = (w(s), w(t), w(r));
    let tx = |i: usize, j: usize, k: usize| (30 * (4 * k + 2 * j + i)) as f32 / 255.0;
    let mut want = 0.0;
    for k in 0..2 {
        for j in 0..2 {
            for i in 0..2 {
                let wi = if i == 0 { 1.0 - a } else { a };
                let wj = if j == 0 { 1.0 - b } else { b };
                let wk = if k == 0 { 1.0 - g } else { g };
                want += wi * wj * wk * tx(i, j, k);
            }
        }
    }
    let got = tex.sample([s, t, r], 0.0)[0];
    assert!((got - want).abs() < EPS, "{got} vs {want}");
}

#[test]
fn depth_comparison_all_functions_and_pcf() {
    let funcs = [
        (GL_NEVER, [0.0, 0.0]),
        (GL_ALWAYS, [1.0, 1.0]),
        (GL_LEQUAL, [1.0, 0.0]),
        (GL_GEQUAL, [0.0, 1.0]),
        (GL_LESS, [1.0, 0.0]),
        (GL_GREATER, [0.0, 1.0]),
        (GL_EQUAL, [0.0, 0.0]),
        (GL_NOTEQUAL, [1.0, 1.0]),
    ];
    // Depth texture 2x1: texel 0 = 0.75, texel 1 = 0.25; r = 0.5.
    for (func, want) in funcs {
        let mut gl = ctx();
        let d = [0.75f32, 0.25];
        let bytes: Vec<u8> = d.iter().flat_map(|v| v.to_ne_bytes()).collect();
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_DEPTH_COMPONENT24 as i32,
            2,
            1,
            0,
            GL_DEPTH_COMPONENT,
            GL_FLOAT,
            Some(&bytes),
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
        gl.tex_parameteri(
            GL_TEXTURE_2D,
            GL_TEXTURE_COMPARE_MODE,
            GL_COMPARE_R_TO_TEXTURE as i32,
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, func as i32);
        gl.enable(GL_TEXTURE_2D);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let tex = gl.bound_texture(0).expect("complete");
        for (i, s) in [0.25f32, 0.75].iter().enumerate() {
            let v = tex.sample([*s, 0.5, 0.5], 0.0);
            assert_eq!(
                v,
                [want[i], want[i], want[i], 1.0],
                "func {func:#x} texel {i}"
            );
        }
        // PCF: LINEAR at the midpoint averages the two comparison results.
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA as i32);
        let tex = gl.bound_texture(0).expect("complete");
        let v = tex.sample([0.5, 0.5, 0.5], 0.0);
        assert_eq!(
            v,
            [0.0, 0.0, 0.0, (want[0] + want[1]) / 2.0],
            "pcf {func:#x}"
        );
    }
    // Compare off: depth as INTENSITY.
    let mut gl = ctx();
    let bytes: Vec<u8> = 0.75f32.to_ne_bytes().to_vec();
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_DEPTH_COMPONENT as i32,
        1,
        1,
        0,
        GL_DEPTH_COMPONENT,
        GL_FLOAT,
        Some(&bytes),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY as i32);
    gl.enable(GL_TEXTURE_2D);
    let v = gl
        .bound_texture(0)
        .expect("complete")
        .sample([0.5, 0.5, 0.0], 0.0);
    for c in v {
        assert!((c - 0.75).abs() < 1e-6);
    }
}

#[test]
fn anisotropic_footprint_rule() {
    // 16x16 texture, columns alternate 0/255 in s with period 2 ... use a ramp in s instead:
    // texel (i, j) = 16 * i. Derivatives: d/dx = (8/16, 0), d/dy = (0, 1/16) -> Px = 8, Py = 1.
    let mut gl = ctx();
    let mut data = vec![0u8; 256];
    for j in 0..16 {
        for i in 0..16 {
            data[j * 16 + i] = (16 * i) as u8;
        }
    }
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE as i32,
        16,
        16,
        0,
        GL_LUMINANCE,
        GL_UNSIGNED_BYTE,
        Some(&data),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 4.0);
    gl.enable(GL_TEXTURE_2D);
    let tex = gl.bound_texture(0).expect("complete");
    let (dx, dy) = ([0.5f32, 0.0, 0.0], [0.0f32, 1.0 / 16.0, 0.0]);
    let c = [0.5f32, 0.5, 0.0];
    // N = min(ceil(8/1), 4) = 4 samples at c + dx * ((i + 1/2)/4 - 1/2), lambda = log2(8/4) = 1
    // (> 0: minification, LINEAR on the base level).
    let mut want = [0.0f32; 4];
    for i in 0..4 {
        let k = (i as f32 + 0.5) / 4.0 - 0.5;
        let v = tex.sample([c[0] + dx[0] * k, c[1], 0.0], 1.0);
        for ch in 0..4 {
            want[ch] += v[ch] / 4.0;
        }
    }
    let got = tex.sample_grad(c, dx, dy, 0.0);
    for ch in 0..4 {
        assert!((got[ch] - want[ch]).abs() < EPS);
    }
    // With MAX_ANISOTROPY 1, sample_grad is sample at the isotropic lambda.
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 1.0);
    let tex = gl.bound_texture(0).expect("complete");
    let l = tex.scale_factor_lambda(dx, dy, 0.0);
    assert_eq!(tex.sample_grad(c, dx, dy, 0.0), tex.sample(c, l));
}

#[test]
fn extreme_coordinates_and_derivatives_are_defined() {
    let data: Vec<u8> = (0..16).map(|i| (i * 16) as u8).collect();
    let mut gl = ctx();
    let tex = lum_2d(&mut gl, 4, 4, &data, GL_NEAREST, GL_NEAREST, GL_REPEAT);
    // REPEAT at +-1e6 (|s| * size < 2^24) is exact: 1e6 + 0.3 rounds in f32, so compute from
    // the f32 value itself.
    for s in [1.0e6f32 + 0.3, -1.0e6 - 0.3, 12345.678, -0.001] {
        let u = s as f64 * 4.0;
        let i = (u.floor() as i64).rem_euclid(4) as usize;
        let got = tex.sample([s, 0.1, 0.0], 0.0)[0];
        assert!((got - data[i] as f32 / 255.0).abs() < EPS, "s {s}");
    }
    for c in [
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::MAX,
        -f32::MAX,
    ] {
        for w in [
            GL_REPEAT,
            GL_CLAMP,
            GL_CLAMP_TO_EDGE,
            GL_CLAMP_TO_BORDER,
            GL_MIRRORED_REPEAT,
        ] {
            let mut gl = ctx();
            let tex = lum_2d(&mut gl, 4, 4, &data, GL_LINEAR, GL_LINEAR, w);
            let v = tex.sample_grad([c, c, c], [c; 3], [c; 3], c);
            assert!(v.iter().all(|x| x.is_finite()), "{c} {w:#x}: {v:?}");
            let v = tex.sample([c, 0.5, c], c);
            assert!(v.iter().all(|x| x.is_finite()));
        }
    }
}

#[test]
fn incomplete_textures_disable_the_unit() {
    let mut gl = ctx();
    gl.enable(GL_TEXTURE_2D);
    // Default min filter is NEAREST_MIPMAP_LINEAR: one level is incomplete.
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        4,
        4,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[0; 64]),
    );
    assert!(gl.bound_texture(0).is_none());
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        1,
        GL_RGBA as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[0; 16]),
    );
    assert!(gl.bound_texture(0).is_none());
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        2,
        GL_RGBA as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[0; 4]),
    );
    assert!(gl.bound_texture(0).is_some());
    // Wrong size at level 1 -> incomplete; MAX_LEVEL 0 makes it complete again.
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        1,
        GL_RGBA as i32,
        1,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[0; 8]),
    );
    assert!(gl.bound_texture(0).is_none());
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    assert!(gl.bound_texture(0).is_some());
    // Different internal format in the chain -> incomplete.
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        1,
        GL_RGB as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[0; 16]),
    );
    assert!(gl.bound_texture(0).is_none());
    // BASE_LEVEL 2 with the 1x1 level alone is complete.
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2);
    let t = gl.bound_texture(0).expect("complete from level 2");
    assert_eq!(t.level_count(), 1);
    // Non-power-of-two chains: 5x3 -> 2x1 -> 1x1.
    let mut gl = ctx();
    gl.enable(GL_TEXTURE_2D);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE as i32,
        5,
        3,
        0,
        GL_LUMINANCE,
        GL_UNSIGNED_BYTE,
        Some(&[0; 15]),
    );
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        1,
        GL_LUMINANCE as i32,
        2,
        1,
        0,
        GL_LUMINANCE,
        GL_UNSIGNED_BYTE,
        Some(&[0; 2]),
    );
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        2,
        GL_LUMINANCE as i32,
        1,
        1,
        0,
        GL_LUMINANCE,
        GL_UNSIGNED_BYTE,
        Some(&[0; 1]),
    );
    assert_eq!(gl.bound_texture(0).map(|t| t.level_count()), Some(3));
}

#[test]
fn generate_mipmap_box_filters_and_snapshots_are_copy_on_write() {
    let mut gl = ctx();
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE as i32);
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_NEAREST_MIPMAP_NEAREST as i32,
    );
    gl.enable(GL_TEXTURE_2D);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    // 2x2: 0, 100, 200, 40 -> 1x1 = 85.
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE as i32,
        2,
        2,
        0,
        GL_LUMINANCE,
        GL_UNSIGNED_BYTE,
        Some(&[0, 100, 200, 40]),
    );
    let before = gl.bound_texture(0).expect("generated chain is complete");
    assert_eq!(before.level_count(), 2);
    assert!((before.sample([0.5, 0.5, 0.0], 5.0)[0] - 85.0 / 255.0).abs() < EPS);
    // A later write regenerates level 1 and does not reach the earlier snapshot.
    gl.tex_sub_image_2d(
        GL_TEXTURE_2D,
        0,
        0,
        0,
        2,
        2,
        GL_LUMINANCE,
        GL_UNSIGNED_BYTE,
        Some(&[255; 4]),
    );
    let after = gl.bound_texture(0).expect("complete");
    assert_eq!(after.sample([0.5, 0.5, 0.0], 5.0)[0], 1.0);
    assert!((before.sample([0.5, 0.5, 0.0], 5.0)[0] - 85.0 / 255.0).abs() < EPS);
    assert!((before.sample([0.25, 0.25, 0.0], -1.0)[0]).abs() < EPS);
}

/// Throughput of `sample_grad` (trilinear, RGBA8, 256x256 with mipmaps); run with
/// `cargo test --release --test texture_sampling -- --ignored --nocapture`.
#[test]
#[ignore]
fn sampler_throughput() {
    let mut gl = ctx();
    let data: Vec<u8> = (0..256 * 256 * 4).map(|i| (i * 7) as u8).collect();
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        256,
        256,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&data),
    );
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
    gl.enable(GL_TEXTURE_2D);
    let tex = gl.bound_texture(0).expect("complete");
    let n = 2_000_000;
    let start = std::time::Instant::now();
    let mut acc = 0.0f32;
    for k in 0..n {
        let s = (k % 1000) as f32 * 0.00137;
        let v = tex.sample_grad([s, s * 0.7, 0.0], [0.011, 0.0, 0.0], [0.0, 0.013, 0.0], 0.0);
        acc += v[0];
    }
    let ns = start.elapsed().as_nanos() as f64 / n as f64;
    println!("trilinear sample_grad: {ns:.1} ns/sample (checksum {acc})");
}

/// Texture coordinates on a plane receding to the horizon follow the perspective-correct
/// interpolation of section 3.5.1 (equation 3.4: a/w and 1/w interpolated linearly in window
/// space, at the pixel centre) up to the floating-point rounding of the evaluation, also in the
/// last rows before the horizon, where t changes by ~50 per pixel row. Regression: the planes
/// were set up from the snapped (1/256 pixel) vertex positions, which tilted the long thin
/// clipped triangles enough to shift t by up to a whole repeat there.
///
/// The texture is 1 x 256 LUMINANCE with texel j = j (NEAREST, REPEAT), so a pixel shows
/// floor(256 t) mod 256; the expected t is computed here from the projection: the pixel centre
/// (xw, yw) lies on the plane y_eye = -1 at distance d = -1 / y_near, with
/// y_near = b + (t - b) (yw / 64) of the frustum (b = -1, t = 0.25), and t = -0.4 + (d - 1.05) / 2.
#[test]
fn horizon_texture_coordinates_follow_the_exact_perspective_interpolation() {
    let mut gl = Context::new(64, 64);
    let ramp: Vec<u8> = (0..=255u8).collect();
    lum_2d(&mut gl, 1, 256, &ramp, GL_NEAREST, GL_NEAREST, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.matrix_mode(GL_PROJECTION);
    gl.frustum(-1.0, 1.0, -1.0, 0.25, 1.0, 400.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.begin(GL_QUADS);
    for (x, z) in [
        (-80.0f32, -1.05f32),
        (80.0, -1.05),
        (80.0, -380.0),
        (-80.0, -380.0),
    ] {
        gl.tex_coord_2f(0.5 + 1.2 * x, -0.4 + 0.5 * (-z - 1.05));
        gl.vertex_3f(x, -1.0, z);
    }
    gl.end();
    let mut px = vec![0u8; 64 * 64 * 4];
    gl.read_pixels(0, 0, 64, 64, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    let mut checked = 0;
    for y in 0..64 {
        let y_near = -1.0 + 1.25 * (y as f64 + 0.5) / 64.0;
        if y_near >= 0.0 {
            continue;
        }
        let d = -1.0 / y_near;
        if !(1.1..=370.0).contains(&d) {
            continue;
        }
        let t = -0.4 + 0.5 * (d - 1.05);
        let expected = (t * 256.0).floor().rem_euclid(256.0) as i32;
        for x in (0..64).step_by(7) {
            let got = px[(y * 64 + x) * 4] as i32;
            let off = (got - expected)
                .rem_euclid(256)
                .min((expected - got).rem_euclid(256));
            assert!(
                off <= 1,
                "pixel ({x}, {y}): d = {d:.2}, t = {t:.5}: expected L {expected}, got {got}"
            );
            checked += 1;
        }
    }
    assert!(checked > 200, "{checked}");
}

/// Anisotropic filtering of 2D textures with a `*_MIPMAP_LINEAR` minification filter is the
/// elliptical weighted average Mesa's llvmpipe and softpipe compute (Heckbert's EWA with a
/// Gaussian of the ellipse's quadratic form), recomputed here from its equations for
/// footprints that select level 0: λ = log2(Pmin) with Pmin raised to Pmax / MAX_ANISOTROPY,
/// the ellipse `A u^2 + B u v + C v^2 = F` from the derivatives in texels plus one texel, and
/// the weighted mean of the texels inside with weight `exp(-2 trunc(q) / 1023)`, q the form
/// scaled so that F = 1023.
#[test]
fn anisotropic_mipmap_linear_is_the_elliptical_weighted_average() {
    let mut data = vec![0u8; 16 * 16];
    let mut r = 0x9e37_79b9u32;
    for t in data.iter_mut() {
        r ^= r << 13;
        r ^= r >> 17;
        r ^= r << 5;
        *t = (r >> 24) as u8;
    }
    let mut gl = ctx();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE as i32);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE as i32,
        16,
        16,
        0,
        GL_LUMINANCE,
        GL_UNSIGNED_BYTE,
        Some(&data),
    );
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 8.0);
    gl.enable(GL_TEXTURE_2D);
    let tex = gl.bound_texture(0).expect("complete");
    let texel = |u: i64, v: i64| data[(v.rem_euclid(16) * 16 + u.rem_euclid(16)) as usize] as f64;
    // (centre, d/dx, d/dy) in texture coordinates; each footprint's Pmin is below 2 texels.
    let cases = [
        ([0.4f32, 0.55], [6.0f32 / 16.0, 0.0], [0.0f32, 1.5 / 16.0]),
        (
            [0.71, 0.23],
            [3.0 / 16.0, 3.0 / 16.0],
            [-0.7 / 16.0, 0.7 / 16.0],
        ),
        (
            [0.02, 0.97],
            [0.2 / 16.0, 0.1 / 16.0],
            [0.05 / 16.0, 0.3 / 16.0],
        ),
        // Eccentricity 100 > 8^2: Pmin raised to 12 / 8 = 1.5 texels.
        ([0.5, 0.5], [12.0 / 16.0, 0.0], [0.0, 0.12 / 16.0]),
    ];
    for (c, dx, dy) in cases {
        let (ux, vx, uy, vy) = (
            dx[0] as f64 * 16.0,
            dx[1] as f64 * 16.0,
            dy[0] as f64 * 16.0,
            dy[1] as f64 * 16.0,
        );
        let (px2, py2) = (ux * ux + vx * vx, uy * uy + vy * vy);
        let (pmax2, pmin2) = (px2.max(py2), px2.min(py2).max(px2.max(py2) / 64.0));
        assert!(pmin2.sqrt().log2() < 1.0, "level 0 only: {pmax2} {pmin2}");
        let a = vx * vx + vy * vy + 1.0;
        let b = -2.0 * (ux * vx + uy * vy);
        let cc = ux * ux + uy * uy + 1.0;
        let f = a * cc - b * b / 4.0;
        let (cu, cv) = (c[0] as f64 * 16.0 - 0.5, c[1] as f64 * 16.0 - 0.5);
        let (mut num, mut den) = (0.0, 0.0);
        for v in -40i64..40 {
            for u in -40i64..40 {
                let (du, dv) = (u as f64 - cu, v as f64 - cv);
                let q = (a * du * du + b * du * dv + cc * dv * dv) * 1023.0 / f;
                if q < 1024.0 {
                    let w = (-2.0 * q.max(0.0).floor() / 1023.0).exp();
                    num += w * texel(u, v);
                    den += w;
                }
            }
        }
        let want = num / den / 255.0;
        let got = tex.sample_grad(
            [c[0], c[1], 0.0],
            [dx[0], dx[1], 0.0],
            [dy[0], dy[1], 0.0],
            0.0,
        );
        assert!(
            (got[0] as f64 - want).abs() < 2e-3,
            "centre {c:?}: {} vs {want}",
            got[0]
        );
    }
    // A constant texture stays constant, whatever the footprint.
    let mut gl = ctx();
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE as i32);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE as i32,
        16,
        16,
        0,
        GL_LUMINANCE,
        GL_UNSIGNED_BYTE,
        Some(&[153u8; 256]),
    );
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_NEAREST_MIPMAP_LINEAR as i32,
    );
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 16.0);
    gl.enable(GL_TEXTURE_2D);
    let tex = gl.bound_texture(0).expect("complete");
    for (dx, dy) in [
        ([3.0f32, 0.1, 0.0], [0.0f32, 0.02, 0.0]),
        ([0.01, 0.0, 0.0], [0.0, 0.3, 0.0]),
    ] {
        let got = tex.sample_grad([0.3, 0.6, 0.0], dx, dy, 0.0);
        assert!((got[0] - 0.6).abs() < EPS, "{got:?}");
    }
    // λ clamped to level 0 under a footprint of 10^4 texels: the ellipse's box would hold
    // millions of texels; the bounded footprint rule answers instead (still the constant).
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 0.0);
    let tex = gl.bound_texture(0).expect("complete");
    let got = tex.sample_grad(
        [0.3, 0.6, 0.0],
        [600.0, 20.0, 0.0],
        [-30.0, 500.0, 0.0],
        0.0,
    );
    assert!((got[0] - 0.6).abs() < EPS, "{got:?}");
}

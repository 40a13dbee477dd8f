//! Texture objects, image specification, pixel unpacking/packing, parameters and queries
//! through the `Gl` trait, with error rules checked table-driven: every bad call records the
//! expected error and leaves the texture state (parameters and level parameters) unchanged.

use tilegl::enums::*;
mod common;
use common::{ctx, level_param, read_rgba_f32, tex_param};
use tilegl::{Context, Gl};

#[test]
fn objects_gen_bind_delete() {
    let mut gl = ctx();
    let mut names = [0u32; 3];
    gl.gen_textures(3, &mut names);
    assert!(names.iter().all(|&n| n != 0));
    assert!(names[0] != names[1] && names[1] != names[2]);
    // Generated but never bound: not yet a texture.
    assert_eq!(gl.is_texture(names[0]), 0);
    gl.bind_texture(GL_TEXTURE_2D, names[0]);
    assert_eq!(gl.is_texture(names[0]), 1);
    assert_eq!(gl.is_texture(0), 0);
    // Target mismatch.
    gl.bind_texture(GL_TEXTURE_3D, names[0]);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    // Parameters are per object; the default object keeps its own.
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.bind_texture(GL_TEXTURE_2D, 0);
    assert_eq!(
        tex_param(&mut gl, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER),
        GL_NEAREST_MIPMAP_LINEAR as i32
    );
    gl.bind_texture(GL_TEXTURE_2D, names[0]);
    assert_eq!(
        tex_param(&mut gl, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER),
        GL_LINEAR as i32
    );
    // Deleting a bound texture reverts the binding to the default object.
    gl.delete_textures(1, &names[..1]);
    assert_eq!(gl.is_texture(names[0]), 0);
    assert_eq!(
        tex_param(&mut gl, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER),
        GL_NEAREST_MIPMAP_LINEAR as i32
    );
    // Names need not come from glGenTextures; generated names skip used ones.
    gl.bind_texture(GL_TEXTURE_1D, 1000);
    assert_eq!(gl.is_texture(1000), 1);
    // Priorities and residency.
    gl.prioritize_textures(1, &[1000], &[2.0]);
    gl.bind_texture(GL_TEXTURE_1D, 1000);
    let mut p = [0f32];
    gl.get_tex_parameterfv(GL_TEXTURE_1D, GL_TEXTURE_PRIORITY, &mut p);
    assert_eq!(p[0], 1.0);
    let mut res = [7u8];
    assert_eq!(
        gl.are_textures_resident(1, &[1000], &mut res),
        GL_TRUE as u8
    );
    assert_eq!(
        gl.are_textures_resident(1, &[5555], &mut res),
        GL_FALSE as u8
    );
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.gen_textures(-1, &mut names);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
}

#[test]
fn level_parameters_and_internal_format_precision() {
    let mut gl = ctx();
    let cases: [(GLenum, [i32; 7]); 8] = [
        // R, G, B, A, L, I, depth sizes
        (GL_RGBA8, [8, 8, 8, 8, 0, 0, 0]),
        (GL_RGB16, [16, 16, 16, 0, 0, 0, 0]),
        (GL_R3_G3_B2, [8, 8, 8, 0, 0, 0, 0]),
        (GL_LUMINANCE12_ALPHA4, [0, 0, 0, 16, 16, 0, 0]),
        (GL_INTENSITY16, [0, 0, 0, 0, 0, 16, 0]),
        (GL_ALPHA4, [0, 0, 0, 8, 0, 0, 0]),
        (GL_DEPTH_COMPONENT16, [0, 0, 0, 0, 0, 0, 16]),
        (GL_DEPTH_COMPONENT32, [0, 0, 0, 0, 0, 0, 32]),
    ];
    for (ifmt, sizes) in cases {
        let fmt = if ifmt == GL_DEPTH_COMPONENT16 || ifmt == GL_DEPTH_COMPONENT32 {
            GL_DEPTH_COMPONENT
        } else {
            GL_RGBA
        };
        gl.tex_image_2d(GL_TEXTURE_2D, 0, ifmt as i32, 3, 5, 0, fmt, GL_FLOAT, None);
        assert_eq!(gl.get_error(), GL_NO_ERROR, "{ifmt:#x}");
        let q = |gl: &mut Context, p| level_param(gl, GL_TEXTURE_2D, 0, p);
        assert_eq!(q(&mut gl, GL_TEXTURE_WIDTH), 3);
        assert_eq!(q(&mut gl, GL_TEXTURE_HEIGHT), 5);
        assert_eq!(q(&mut gl, GL_TEXTURE_DEPTH), 1);
        assert_eq!(q(&mut gl, GL_TEXTURE_INTERNAL_FORMAT), ifmt as i32);
        let got = [
            GL_TEXTURE_RED_SIZE,
            GL_TEXTURE_GREEN_SIZE,
            GL_TEXTURE_BLUE_SIZE,
            GL_TEXTURE_ALPHA_SIZE,
            GL_TEXTURE_LUMINANCE_SIZE,
            GL_TEXTURE_INTENSITY_SIZE,
            GL_TEXTURE_DEPTH_SIZE,
        ]
        .map(|p| q(&mut gl, p));
        assert_eq!(got, sizes, "{ifmt:#x}");
    }
    // 16-bit formats keep 16 bits: 0x1234 / 65535 survives a round trip.
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE16 as i32,
        1,
        1,
        0,
        GL_LUMINANCE,
        GL_UNSIGNED_SHORT,
        Some(&0x1234u16.to_ne_bytes()),
    );
    let mut out = [0u8; 2];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_SHORT, &mut out);
    assert_eq!(u16::from_ne_bytes(out), 0x1234);
    // Undefined level: zeros, internal format 1.
    assert_eq!(level_param(&mut gl, GL_TEXTURE_2D, 3, GL_TEXTURE_WIDTH), 0);
    assert_eq!(
        level_param(&mut gl, GL_TEXTURE_2D, 3, GL_TEXTURE_INTERNAL_FORMAT),
        1
    );
    // Borders count in the width.
    gl.tex_image_1d(GL_TEXTURE_1D, 0, 3, 6, 1, GL_RGB, GL_UNSIGNED_BYTE, None);
    assert_eq!(level_param(&mut gl, GL_TEXTURE_1D, 0, GL_TEXTURE_WIDTH), 6);
    assert_eq!(level_param(&mut gl, GL_TEXTURE_1D, 0, GL_TEXTURE_BORDER), 1);
    assert_eq!(
        level_param(&mut gl, GL_TEXTURE_1D, 0, GL_TEXTURE_INTERNAL_FORMAT),
        3
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn unpack_component_types_and_formats() {
    let mut gl = ctx();
    // Signed types: (2c + 1) / (2^b - 1), negative clamps to 0.
    let b: [i8; 4] = [-128, 0, 63, 127];
    let bytes: Vec<u8> = b.iter().map(|&x| x as u8).collect();
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA16 as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_BYTE,
        Some(&bytes),
    );
    let got = read_rgba_f32(&mut gl, GL_TEXTURE_2D, 1);
    let want = [0.0, 1.0 / 255.0, 127.0 / 255.0, 1.0];
    for c in 0..4 {
        assert!((got[c] - want[c]).abs() < 1e-4, "{got:?}");
    }
    // Single-channel formats fill the others with 0 (alpha 1); BGR reorders; LUMINANCE fills RGB.
    let cases: [(GLenum, &[u8], [f32; 4]); 6] = [
        (GL_RED, &[255], [1.0, 0.0, 0.0, 1.0]),
        (GL_GREEN, &[255], [0.0, 1.0, 0.0, 1.0]),
        (GL_BLUE, &[255], [0.0, 0.0, 1.0, 1.0]),
        (GL_ALPHA, &[0], [0.0, 0.0, 0.0, 0.0]),
        (GL_BGR, &[255, 0, 51], [0.2, 0.0, 1.0, 1.0]),
        (GL_LUMINANCE_ALPHA, &[51, 102], [0.2, 0.2, 0.2, 0.4]),
    ];
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    for (fmt, data, want) in cases {
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            1,
            1,
            0,
            fmt,
            GL_UNSIGNED_BYTE,
            Some(data),
        );
        let got = read_rgba_f32(&mut gl, GL_TEXTURE_2D, 1);
        for c in 0..4 {
            assert!((got[c] - want[c]).abs() < 1e-6, "{fmt:#x}: {got:?}");
        }
    }
    // Int and unsigned int, float.
    let v: [u32; 4] = [0, u32::MAX, u32::MAX / 2, 0];
    let bytes: Vec<u8> = v.iter().flat_map(|x| x.to_ne_bytes()).collect();
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA16 as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_INT,
        Some(&bytes),
    );
    let got = read_rgba_f32(&mut gl, GL_TEXTURE_2D, 1);
    assert!((got[1] - 1.0).abs() < 1e-6 && (got[2] - 0.5).abs() < 1e-4 && got[0] == 0.0);
}

/// A snapshot of the observable state of the bound 2D/1D/3D/cube textures.
fn observe(gl: &mut Context) -> Vec<i32> {
    let mut v = Vec::new();
    for t in [
        GL_TEXTURE_1D,
        GL_TEXTURE_2D,
        GL_TEXTURE_3D,
        GL_TEXTURE_CUBE_MAP,
    ] {
        for p in [
            GL_TEXTURE_MIN_FILTER,
            GL_TEXTURE_MAG_FILTER,
            GL_TEXTURE_WRAP_S,
            GL_TEXTURE_WRAP_T,
            GL_TEXTURE_WRAP_R,
            GL_TEXTURE_BASE_LEVEL,
            GL_TEXTURE_MAX_LEVEL,
            GL_TEXTURE_MIN_LOD,
            GL_TEXTURE_MAX_LOD,
            GL_TEXTURE_COMPARE_MODE,
            GL_TEXTURE_COMPARE_FUNC,
            GL_DEPTH_TEXTURE_MODE,
            GL_GENERATE_MIPMAP,
            GL_TEXTURE_MAX_ANISOTROPY_EXT,
        ] {
            v.push(tex_param(gl, t, p));
        }
        let mut bc = [0i32; 4];
        gl.get_tex_parameteriv(t, GL_TEXTURE_BORDER_COLOR, &mut bc);
        v.extend_from_slice(&bc);
    }
    for t in [
        GL_TEXTURE_1D,
        GL_TEXTURE_2D,
        GL_TEXTURE_3D,
        GL_TEXTURE_CUBE_MAP_POSITIVE_X,
    ] {
        for level in 0..2 {
            for p in [
                GL_TEXTURE_WIDTH,
                GL_TEXTURE_HEIGHT,
                GL_TEXTURE_DEPTH,
                GL_TEXTURE_INTERNAL_FORMAT,
                GL_TEXTURE_BORDER,
            ] {
                v.push(level_param(gl, t, level, p));
            }
        }
    }
    let mut px = [0u8; 16];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    v.extend(px.iter().map(|&b| b as i32));
    assert_eq!(
        gl.get_error(),
        GL_NO_ERROR,
        "observation itself is error-free"
    );
    v
}

type BadCall = (&'static str, GLenum, fn(&mut Context));

#[test]
fn every_error_is_recorded_and_changes_nothing() {
    let calls: Vec<BadCall> = vec![
        ("bind bad target", GL_INVALID_ENUM, |gl| {
            gl.bind_texture(GL_TEXTURE, 5)
        }),
        ("teximage bad target", GL_INVALID_ENUM, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_3D,
                0,
                GL_RGBA as i32,
                1,
                1,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 4]),
            )
        }),
        ("teximage bad format", GL_INVALID_ENUM, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                1,
                1,
                0,
                GL_RGBA8,
                GL_UNSIGNED_BYTE,
                Some(&[1; 4]),
            )
        }),
        ("teximage bad type", GL_INVALID_ENUM, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                1,
                1,
                0,
                GL_RGBA,
                GL_RGBA,
                Some(&[1; 4]),
            )
        }),
        ("teximage bitmap type", GL_INVALID_ENUM, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                1,
                1,
                0,
                GL_RGBA,
                GL_BITMAP,
                Some(&[1; 4]),
            )
        }),
        ("teximage negative level", GL_INVALID_VALUE, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                -1,
                GL_RGBA as i32,
                1,
                1,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 4]),
            )
        }),
        ("teximage level too large", GL_INVALID_VALUE, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                15,
                GL_RGBA as i32,
                1,
                1,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 4]),
            )
        }),
        ("teximage bad internal format", GL_INVALID_VALUE, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                0,
                5,
                1,
                1,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 4]),
            )
        }),
        ("teximage negative width", GL_INVALID_VALUE, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                -1,
                1,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 4]),
            )
        }),
        ("teximage too wide", GL_INVALID_VALUE, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                16385,
                1,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                None,
            )
        }),
        ("teximage3d too deep", GL_INVALID_VALUE, |gl| {
            gl.tex_image_3d(
                GL_TEXTURE_3D,
                0,
                GL_RGBA as i32,
                1,
                1,
                2049,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                None,
            )
        }),
        ("teximage bad border", GL_INVALID_VALUE, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                1,
                1,
                2,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 4]),
            )
        }),
        ("teximage border too big for size", GL_INVALID_VALUE, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                1,
                1,
                1,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 4]),
            )
        }),
        ("teximage non-square cube face", GL_INVALID_VALUE, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_CUBE_MAP_POSITIVE_X,
                0,
                GL_RGBA as i32,
                2,
                1,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 8]),
            )
        }),
        ("teximage short slice", GL_INVALID_VALUE, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                2,
                2,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 15]),
            )
        }),
        (
            "teximage packed type and format",
            GL_INVALID_OPERATION,
            |gl| {
                gl.tex_image_2d(
                    GL_TEXTURE_2D,
                    0,
                    GL_RGBA as i32,
                    1,
                    1,
                    0,
                    GL_RGBA,
                    GL_UNSIGNED_SHORT_5_6_5,
                    Some(&[1; 4]),
                )
            },
        ),
        ("teximage 4444 with RGB", GL_INVALID_OPERATION, |gl| {
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                1,
                1,
                0,
                GL_RGB,
                GL_UNSIGNED_SHORT_4_4_4_4,
                Some(&[1; 4]),
            )
        }),
        (
            "teximage depth data, colour format",
            GL_INVALID_OPERATION,
            |gl| {
                gl.tex_image_2d(
                    GL_TEXTURE_2D,
                    0,
                    GL_RGBA as i32,
                    1,
                    1,
                    0,
                    GL_DEPTH_COMPONENT,
                    GL_FLOAT,
                    Some(&[1; 4]),
                )
            },
        ),
        (
            "teximage colour data, depth format",
            GL_INVALID_OPERATION,
            |gl| {
                gl.tex_image_2d(
                    GL_TEXTURE_2D,
                    0,
                    GL_DEPTH_COMPONENT as i32,
                    1,
                    1,
                    0,
                    GL_RGBA,
                    GL_FLOAT,
                    Some(&[1; 16]),
                )
            },
        ),
        ("teximage3d depth", GL_INVALID_OPERATION, |gl| {
            gl.tex_image_3d(
                GL_TEXTURE_3D,
                0,
                GL_DEPTH_COMPONENT as i32,
                1,
                1,
                1,
                0,
                GL_DEPTH_COMPONENT,
                GL_FLOAT,
                Some(&[1; 4]),
            )
        }),
        ("teximage1d 2d target", GL_INVALID_ENUM, |gl| {
            gl.tex_image_1d(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                1,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 4]),
            )
        }),
        ("texsubimage proxy", GL_INVALID_ENUM, |gl| {
            gl.tex_sub_image_2d(
                GL_PROXY_TEXTURE_2D,
                0,
                0,
                0,
                1,
                1,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 4]),
            )
        }),
        ("texsubimage outside", GL_INVALID_VALUE, |gl| {
            gl.tex_sub_image_2d(
                GL_TEXTURE_2D,
                0,
                1,
                1,
                1,
                1,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 4]),
            )
        }),
        ("texsubimage short", GL_INVALID_VALUE, |gl| {
            gl.tex_sub_image_2d(
                GL_TEXTURE_2D,
                0,
                0,
                0,
                1,
                1,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 3]),
            )
        }),
        ("texsubimage undefined level", GL_INVALID_OPERATION, |gl| {
            gl.tex_sub_image_2d(
                GL_TEXTURE_2D,
                1,
                0,
                0,
                1,
                1,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[1; 4]),
            )
        }),
        ("copyteximage cube target", GL_INVALID_ENUM, |gl| {
            gl.copy_tex_image_2d(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 0, 0, 1, 1, 0)
        }),
        ("copytexsubimage undefined", GL_INVALID_OPERATION, |gl| {
            gl.copy_tex_sub_image_2d(GL_TEXTURE_2D, 3, 0, 0, 0, 0, 1, 1)
        }),
        ("parameter bad pname", GL_INVALID_ENUM, |gl| {
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WIDTH, 1)
        }),
        ("parameter bad target", GL_INVALID_ENUM, |gl| {
            gl.tex_parameteri(
                GL_TEXTURE_CUBE_MAP_POSITIVE_X,
                GL_TEXTURE_MIN_FILTER,
                GL_LINEAR as i32,
            )
        }),
        ("min filter bad", GL_INVALID_ENUM, |gl| {
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_REPEAT as i32)
        }),
        ("mag filter mipmap", GL_INVALID_ENUM, |gl| {
            gl.tex_parameteri(
                GL_TEXTURE_2D,
                GL_TEXTURE_MAG_FILTER,
                GL_LINEAR_MIPMAP_LINEAR as i32,
            )
        }),
        ("wrap bad", GL_INVALID_ENUM, |gl| {
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R, GL_LINEAR as i32)
        }),
        ("base level negative", GL_INVALID_VALUE, |gl| {
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1)
        }),
        ("max level negative", GL_INVALID_VALUE, |gl| {
            gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, -1.0)
        }),
        ("border colour scalar", GL_INVALID_ENUM, |gl| {
            gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1.0)
        }),
        ("border colour short", GL_INVALID_VALUE, |gl| {
            gl.tex_parameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, &[1.0; 3])
        }),
        ("compare mode bad", GL_INVALID_ENUM, |gl| {
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_LEQUAL as i32)
        }),
        ("compare func bad", GL_INVALID_ENUM, |gl| {
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_NONE as i32)
        }),
        ("depth mode bad", GL_INVALID_ENUM, |gl| {
            gl.tex_parameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_RGB as i32)
        }),
        ("anisotropy below 1", GL_INVALID_VALUE, |gl| {
            gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 0.5)
        }),
        ("resident is read-only", GL_INVALID_ENUM, |gl| {
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_RESIDENT, 1)
        }),
        ("get level bad target", GL_INVALID_ENUM, |gl| {
            gl.get_tex_level_parameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &mut [0])
        }),
        ("get level bad level", GL_INVALID_VALUE, |gl| {
            gl.get_tex_level_parameteriv(GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, &mut [0])
        }),
        ("get level bad pname", GL_INVALID_ENUM, |gl| {
            gl.get_tex_level_parameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_MIN_FILTER, &mut [0])
        }),
        (
            "compressed size of uncompressed",
            GL_INVALID_OPERATION,
            |gl| {
                gl.get_tex_level_parameteriv(
                    GL_TEXTURE_2D,
                    0,
                    GL_TEXTURE_COMPRESSED_IMAGE_SIZE,
                    &mut [0],
                )
            },
        ),
        ("get tex image proxy", GL_INVALID_ENUM, |gl| {
            gl.get_tex_image(
                GL_PROXY_TEXTURE_2D,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                &mut [0; 16],
            )
        }),
        ("get tex image short", GL_INVALID_VALUE, |gl| {
            gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut [0; 3])
        }),
        (
            "get tex image depth of colour",
            GL_INVALID_OPERATION,
            |gl| gl.get_tex_image(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &mut [0; 16]),
        ),
        ("get tex parameter bad", GL_INVALID_ENUM, |gl| {
            gl.get_tex_parameteriv(GL_TEXTURE_2D, GL_TEXTURE_WIDTH, &mut [0])
        }),
        ("delete negative", GL_INVALID_VALUE, |gl| {
            gl.delete_textures(-1, &[])
        }),
        ("tex image inside begin/end", GL_INVALID_OPERATION, |gl| {
            gl.begin(GL_POINTS);
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                1,
                1,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&[9; 4]),
            );
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
            gl.end();
        }),
    ];
    for (name, err, call) in calls {
        let mut gl = ctx();
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
        gl.tex_image_1d(
            GL_TEXTURE_1D,
            0,
            GL_RGB as i32,
            2,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            Some(&[1; 8]),
        );
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let before = observe(&mut gl);
        call(&mut gl);
        assert_eq!(gl.get_error(), err, "{name}");
        assert_eq!(observe(&mut gl), before, "{name}: state changed");
    }
}

#[test]
fn parameters_round_trip() {
    let mut gl = ctx();
    gl.tex_parameterfv(
        GL_TEXTURE_2D,
        GL_TEXTURE_BORDER_COLOR,
        &[0.5, -1.0, 2.0, 0.25],
    );
    let mut f = [0f32; 4];
    gl.get_tex_parameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, &mut f);
    assert_eq!(f, [0.5, 0.0, 1.0, 0.25]);
    let mut i = [0i32; 4];
    gl.get_tex_parameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, &mut i);
    assert_eq!(i[2], i32::MAX);
    gl.tex_parameteriv(
        GL_TEXTURE_2D,
        GL_TEXTURE_BORDER_COLOR,
        &[i32::MAX, 0, i32::MAX, 0],
    );
    gl.get_tex_parameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, &mut f);
    assert_eq!(f[0], 1.0);
    assert!(f[1] < 1e-9);
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 64.0);
    gl.get_tex_parameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &mut f);
    assert_eq!(f[0], 16.0);
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -2.5);
    gl.get_tex_parameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, &mut f);
    assert_eq!(f[0], -2.5);
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as f32);
    assert_eq!(
        tex_param(&mut gl, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER),
        GL_LINEAR as i32
    );
    assert_eq!(tex_param(&mut gl, GL_TEXTURE_2D, GL_TEXTURE_RESIDENT), 1);
    assert_eq!(
        tex_param(&mut gl, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE),
        GL_NONE as i32
    );
    assert_eq!(
        tex_param(&mut gl, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC),
        GL_LEQUAL as i32
    );
    assert_eq!(
        tex_param(&mut gl, GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE),
        GL_LUMINANCE as i32
    );
    assert_eq!(
        tex_param(&mut gl, GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL),
        1000
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn out_of_memory_and_huge_sizes_do_not_abort() {
    let mut gl = ctx();
    // The largest allowed 3D texture (2048^3 RGBA8 = 32 GiB, over the 1 GiB an image may
    // take) reports GL_OUT_OF_MEMORY, without an abort; a 256^3 one (64 MiB) allocates.
    let mut max = [0i32];
    gl.get_integerv(GL_MAX_3D_TEXTURE_SIZE, &mut max);
    assert_eq!(max[0], 2048);
    for (side, want) in [(2048, GL_OUT_OF_MEMORY), (256, GL_NO_ERROR)] {
        gl.tex_image_3d(
            GL_TEXTURE_3D,
            0,
            GL_RGBA as i32,
            side,
            side,
            side,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            None,
        );
        assert_eq!(gl.get_error(), want, "{side}^3");
    }
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        i32::MAX,
        i32::MAX,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[0; 4]),
    );
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.pixel_storei(GL_UNPACK_ROW_LENGTH, i32::MAX);
    gl.pixel_storei(GL_UNPACK_SKIP_ROWS, i32::MAX);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        4,
        4,
        0,
        GL_RGBA,
        GL_FLOAT,
        Some(&[0; 64]),
    );
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
}

/// Unsigned bytes into 8-bit images are copied row by row (a fast path); the same values
/// as unsigned shorts (c * 257, converted texel by texel) must give the same texels, and
/// both the bytes given (c / 255 stored in 8 bits is c): glTexImage and glTexSubImage,
/// with row length and skips in the unpack state.
#[test]
fn byte_uploads_into_8_bit_images_keep_every_byte() {
    let (w, h) = (7usize, 5usize);
    let mut seed = 0x9e37_79b9u32;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        (seed >> 24) as u8
    };
    for (internal, format, comps) in [
        (GL_RGBA8, GL_RGBA, 4usize),
        (GL_RGB8, GL_RGB, 3),
        (GL_LUMINANCE8, GL_LUMINANCE, 1),
        (GL_LUMINANCE8_ALPHA8, GL_LUMINANCE_ALPHA, 2),
        (GL_ALPHA8, GL_ALPHA, 1),
        (GL_INTENSITY8, GL_LUMINANCE, 1),
    ] {
        // Rows of 9 groups, the image starting 1 row and 2 groups in.
        let (row_len, skip_rows, skip_pixels) = (9usize, 1usize, 2usize);
        let bytes: Vec<u8> = (0..row_len * (h + skip_rows) * comps)
            .map(|_| next())
            .collect();
        let shorts: Vec<u8> = bytes
            .iter()
            .flat_map(|&c| (c as u16 * 257).to_ne_bytes())
            .collect();
        let upload = |ty: GLenum, data: &[u8], sub: bool| {
            let mut gl = ctx();
            gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
            gl.pixel_storei(GL_UNPACK_ROW_LENGTH, row_len as i32);
            gl.pixel_storei(GL_UNPACK_SKIP_ROWS, skip_rows as i32);
            gl.pixel_storei(GL_UNPACK_SKIP_PIXELS, skip_pixels as i32);
            if sub {
                gl.tex_image_2d(
                    GL_TEXTURE_2D,
                    0,
                    internal as i32,
                    w as i32 + 3,
                    h as i32 + 2,
                    0,
                    format,
                    ty,
                    None,
                );
                gl.tex_sub_image_2d(
                    GL_TEXTURE_2D,
                    0,
                    2,
                    1,
                    w as i32,
                    h as i32,
                    format,
                    ty,
                    Some(data),
                );
            } else {
                gl.tex_image_2d(
                    GL_TEXTURE_2D,
                    0,
                    internal as i32,
                    w as i32,
                    h as i32,
                    0,
                    format,
                    ty,
                    Some(data),
                );
            }
            assert_eq!(gl.get_error(), GL_NO_ERROR);
            let (tw, th) = if sub { (w + 3, h + 2) } else { (w, h) };
            let mut back = vec![0u8; tw * th * comps];
            gl.pixel_storei(GL_PACK_ALIGNMENT, 1);
            gl.get_tex_image(GL_TEXTURE_2D, 0, format, GL_UNSIGNED_BYTE, &mut back);
            // The uploaded block only.
            let (ox, oy) = if sub { (2, 1) } else { (0, 0) };
            (0..h)
                .flat_map(|y| {
                    let at = ((oy + y) * tw + ox) * comps;
                    back[at..at + w * comps].to_vec()
                })
                .collect::<Vec<u8>>()
        };
        let given: Vec<u8> = (0..h)
            .flat_map(|y| {
                let at = ((skip_rows + y) * row_len + skip_pixels) * comps;
                bytes[at..at + w * comps].to_vec()
            })
            .collect();
        for sub in [false, true] {
            let from_bytes = upload(GL_UNSIGNED_BYTE, &bytes, sub);
            let from_shorts = upload(GL_UNSIGNED_SHORT, &shorts, sub);
            assert_eq!(from_bytes, from_shorts, "0x{internal:04x} sub {sub}");
            if internal != GL_INTENSITY8 {
                assert_eq!(from_bytes, given, "0x{internal:04x} sub {sub}");
            }
        }
    }
}

/// Byte uploads whose groups are the stored components (RGBA into RGBA8, RGB into RGB8,
/// LUMINANCE, ALPHA, LUMINANCE_ALPHA into their own) are copied row by row; the texels are the
/// ones the per-texel route stores, for whole images and sub-images under row lengths,
/// alignments and skips: checked against the client bytes picked out by the unpack rules in
/// the test, and against the same data sent through the per-texel route (the same upload with
/// a pixel-transfer scale of 1.0001, which stores the same bytes but cannot take the copy).
#[test]
fn byte_uploads_copied_by_rows_store_what_the_general_path_stores() {
    let cases = [
        (GL_RGBA, GL_RGBA8, 4),
        (GL_RGB, GL_RGB8, 3),
        (GL_LUMINANCE, GL_LUMINANCE8, 1),
        (GL_ALPHA, GL_ALPHA8, 1),
        (GL_LUMINANCE_ALPHA, GL_LUMINANCE8_ALPHA8, 2),
    ];
    let (w, h) = (13usize, 7usize);
    let (sub_x, sub_y, sw, sh) = (3usize, 2usize, 9usize, 4usize);
    for (format, internal, c) in cases {
        for (align, row_length, skip_px, skip_rows) in [(1, 0, 0, 0), (4, 17, 2, 1), (8, 0, 1, 3)] {
            // Bytes per client row of an image `width` texels wide (section 3.6.4).
            let row = |width: usize| {
                let px = if row_length > 0 { row_length } else { width };
                (px * c).div_ceil(align) * align
            };
            let len = (skip_rows + h + 1) * row(w) + 64;
            let data: Vec<u8> = (0..len).map(|i| (i * 37 + 11) as u8).collect();
            // The bytes of texel (x, y) of a `width`-wide image unpacked from `data`.
            let texel = |width: usize, x: usize, y: usize| {
                let at = (skip_rows + y) * row(width) + (skip_px + x) * c;
                data[at..at + c].to_vec()
            };
            let read = |transfer_scale: f32| {
                let mut gl = ctx();
                gl.pixel_storei(GL_UNPACK_ALIGNMENT, align as i32);
                gl.pixel_storei(GL_UNPACK_ROW_LENGTH, row_length as i32);
                gl.pixel_storei(GL_UNPACK_SKIP_PIXELS, skip_px as i32);
                gl.pixel_storei(GL_UNPACK_SKIP_ROWS, skip_rows as i32);
                for scale in [GL_RED_SCALE, GL_GREEN_SCALE, GL_BLUE_SCALE, GL_ALPHA_SCALE] {
                    gl.pixel_transferf(scale, transfer_scale);
                }
                gl.tex_image_2d(
                    GL_TEXTURE_2D,
                    0,
                    internal as i32,
                    w as i32,
                    h as i32,
                    0,
                    format,
                    GL_UNSIGNED_BYTE,
                    Some(&data),
                );
                let whole = get_bytes(&mut gl, format, w * h * c);
                // A sub-image from the same client bytes (its own rows start at the skips).
                gl.tex_sub_image_2d(
                    GL_TEXTURE_2D,
                    0,
                    sub_x as i32,
                    sub_y as i32,
                    sw as i32,
                    sh as i32,
                    format,
                    GL_UNSIGNED_BYTE,
                    Some(&data),
                );
                let after = get_bytes(&mut gl, format, w * h * c);
                assert_eq!(gl.get_error(), GL_NO_ERROR);
                (whole, after)
            };
            let (whole, after) = read(1.0);
            let mut expect_whole = Vec::new();
            let mut expect_after = Vec::new();
            for y in 0..h {
                for x in 0..w {
                    expect_whole.extend(texel(w, x, y));
                    let inside =
                        (sub_x..sub_x + sw).contains(&x) && (sub_y..sub_y + sh).contains(&y);
                    expect_after.extend(if inside {
                        texel(sw, x - sub_x, y - sub_y)
                    } else {
                        texel(w, x, y)
                    });
                }
            }
            let case =
                format!("format {format:#x}, unpack {align} {row_length} {skip_px} {skip_rows}");
            assert_eq!(whole, expect_whole, "{case}: whole image");
            assert_eq!(after, expect_after, "{case}: after the sub-image");
            assert_eq!(read(1.0001), (whole, after), "{case}: per-texel route");
        }
    }
}

fn get_bytes(gl: &mut Context, format: GLenum, n: usize) -> Vec<u8> {
    gl.pixel_storei(GL_PACK_ALIGNMENT, 1);
    let mut out = vec![0u8; n];
    gl.get_tex_image(GL_TEXTURE_2D, 0, format, GL_UNSIGNED_BYTE, &mut out);
    out
}

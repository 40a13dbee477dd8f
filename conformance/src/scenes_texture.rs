//! Differential scenes for texturing: filters, wrap modes, formats, mipmaps, texture
//! coordinate generation and the texture environment (the texturing and texture-unit issues).

use crate::compare::Scene;
use crate::scenes::{clear, pixel_space, scene, scene_with, sphere, spread};
use tilegl::enums::*;
use tilegl::Gl;

/// Texturing scenes, in report order.
pub const TEXTURE_SCENES: &[Scene] = &[
    scene("tex_nearest_replace", tex_nearest_replace),
    scene("tex_linear_modulate_clamp", tex_linear_modulate_clamp),
    // llvmpipe vs softpipe: 2.124 %, 9.351 %, 5.640 % of pixels off by more than 8.
    scene_with("tex_floor_nearest", tex_floor_nearest, spread(0.02124)),
    // Within the normal rule since λ is taken per 2x2 quad (spread 9.351 %).
    scene("tex_floor_trilinear", tex_floor_trilinear),
    scene_with(
        "tex_floor_mipmap_nearest",
        tex_floor_mipmap_nearest,
        spread(0.05640),
    ),
    scene("texgen_sphere_map", texgen_sphere_map),
    scene("texgen_object_linear", texgen_object_linear),
    scene("texgen_eye_linear", texgen_eye_linear),
    scene("multitexture_combine", multitexture_combine),
    scene("texture_rectangle", texture_rectangle),
    scene("tex_color_index_uploads", tex_color_index_uploads),
];

/// An RGBA checkerboard with a colour ramp, `size` x `size`.
fn checker_pixels(size: usize) -> Vec<u8> {
    let mut p = Vec::with_capacity(size * size * 4);
    for y in 0..size {
        for x in 0..size {
            let on = ((x * 8 / size) + (y * 8 / size)).is_multiple_of(2);
            let r = (x * 255 / size.max(1)) as u8;
            let g = (y * 255 / size.max(1)) as u8;
            if on {
                p.extend_from_slice(&[r, g, 255, 255]);
            } else {
                p.extend_from_slice(&[255 - r, 40, g, 160]);
            }
        }
    }
    p
}

fn textured_setup(gl: &mut dyn Gl, min: GLenum, mag: GLenum, wrap: GLenum, size: usize) {
    clear(gl);
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_2D, name[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    let px = checker_pixels(size);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        size as i32,
        size as i32,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&px),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 0);
    if min != GL_NEAREST && min != GL_LINEAR {
        // Explicit mipmaps: each level a box-filtered checker of its own size.
        let mut s = size / 2;
        let mut level = 1;
        while s >= 1 {
            let p = checker_pixels(s);
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                level,
                GL_RGBA as i32,
                s as i32,
                s as i32,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&p),
            );
            s /= 2;
            level += 1;
        }
    }
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap as i32);
    gl.enable(GL_TEXTURE_2D);
}

/// A floor in perspective, texture repeated: exercises minification and level selection.
fn textured_floor(gl: &mut dyn Gl, min: GLenum, mag: GLenum, env: GLenum) {
    textured_setup(gl, min, mag, GL_REPEAT, 32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, env as i32);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 50.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.begin(GL_QUADS);
    gl.color_3f(0.9, 0.7, 0.5);
    for (s, t, x, z) in [
        (0.0, 0.0, -4.0, -1.2),
        (6.0, 0.0, 4.0, -1.2),
        (6.0, 20.0, 4.0, -40.0),
        (0.0, 20.0, -4.0, -40.0),
    ] {
        gl.tex_coord_2f(s, t);
        gl.vertex_3f(x, -1.0, z);
    }
    gl.end();
}

fn tex_nearest_replace(gl: &mut dyn Gl) {
    textured_setup(gl, GL_NEAREST, GL_NEAREST, GL_REPEAT, 16);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    pixel_space_keep(gl);
    gl.begin(GL_QUADS);
    // A parallelogram with affine texture coordinates: every quad split gives the same picture.
    for (s, t, x, y) in [
        (0.0, 0.0, 4.0, 4.0),
        (1.5, 0.0, 56.0, 10.0),
        (1.5, 1.5, 60.0, 60.0),
        (0.0, 1.5, 8.0, 54.0),
    ] {
        gl.tex_coord_2f(s, t);
        gl.vertex_2f(x, y);
    }
    gl.end();
}

fn tex_linear_modulate_clamp(gl: &mut dyn Gl) {
    textured_setup(gl, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, 8);
    pixel_space_keep(gl);
    gl.begin(GL_QUADS);
    gl.color_3f(1.0, 0.8, 0.6);
    for (s, t, x, y) in [
        (-0.2, -0.2, 4.0, 4.0),
        (1.2, -0.2, 60.0, 4.0),
        (1.2, 1.2, 60.0, 60.0),
        (-0.2, 1.2, 4.0, 60.0),
    ] {
        gl.tex_coord_2f(s, t);
        gl.vertex_2f(x, y);
    }
    gl.end();
}

fn tex_floor_nearest(gl: &mut dyn Gl) {
    textured_floor(gl, GL_NEAREST, GL_NEAREST, GL_REPLACE);
}

fn tex_floor_trilinear(gl: &mut dyn Gl) {
    textured_floor(gl, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_MODULATE);
}

fn tex_floor_mipmap_nearest(gl: &mut dyn Gl) {
    textured_floor(gl, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR, GL_DECAL);
}

/// Orthographic pixel space without clearing (the texture set-up already cleared).
fn pixel_space_keep(gl: &mut dyn Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 64.0, 0.0, 64.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

// Texture coordinate generation.

fn texgen_scene(gl: &mut dyn Gl, modes: [GLenum; 2], planes: bool) {
    textured_setup(gl, GL_LINEAR, GL_LINEAR, GL_REPEAT, 16);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.6, 0.6, -0.6, 0.6, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.enable(GL_DEPTH_TEST);
    if planes {
        // Eye planes are transformed by the modelview current at glTexGen time.
        gl.rotatef(20.0, 0.0, 0.0, 1.0);
        gl.tex_genfv(GL_S, GL_OBJECT_PLANE, &[0.7, 0.2, 0.0, 0.1]);
        gl.tex_genfv(GL_T, GL_OBJECT_PLANE, &[0.0, 0.5, 0.6, 0.0]);
        gl.tex_genfv(GL_S, GL_EYE_PLANE, &[0.5, 0.0, 0.3, 0.2]);
        gl.tex_genfv(GL_T, GL_EYE_PLANE, &[0.1, 0.6, 0.0, 0.0]);
        gl.load_identity();
    }
    gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, modes[0] as i32);
    gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, modes[1] as i32);
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    gl.translatef(0.0, 0.0, -3.0);
    gl.rotatef(30.0, 1.0, 1.0, 0.0);
    sphere(gl, 12, 16);
}

fn texgen_sphere_map(gl: &mut dyn Gl) {
    texgen_scene(gl, [GL_SPHERE_MAP, GL_SPHERE_MAP], false);
}

fn texgen_object_linear(gl: &mut dyn Gl) {
    texgen_scene(gl, [GL_OBJECT_LINEAR, GL_OBJECT_LINEAR], true);
}

fn texgen_eye_linear(gl: &mut dyn Gl) {
    texgen_scene(gl, [GL_EYE_LINEAR, GL_EYE_LINEAR], true);
}

/// Two units: a base texture modulated by a second unit through GL_COMBINE (ADD_SIGNED with
/// RGB_SCALE 2, the light-map recipe), texture matrix on unit 1.
fn multitexture_combine(gl: &mut dyn Gl) {
    textured_setup(gl, GL_LINEAR, GL_LINEAR, GL_REPEAT, 16);
    gl.active_texture(GL_TEXTURE1);
    textured_setup(gl, GL_NEAREST, GL_LINEAR, GL_REPEAT, 8);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD_SIGNED as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_PREVIOUS as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_TEXTURE as i32);
    gl.tex_envi(
        GL_TEXTURE_ENV,
        GL_OPERAND1_RGB,
        GL_ONE_MINUS_SRC_COLOR as i32,
    );
    gl.tex_envf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_MODULATE as i32);
    gl.matrix_mode(GL_TEXTURE);
    gl.rotatef(30.0, 0.0, 0.0, 1.0);
    gl.active_texture(GL_TEXTURE0);
    pixel_space_keep(gl);
    gl.begin(GL_QUADS);
    gl.color_3f(0.8, 0.9, 1.0);
    for (s, t, x, y) in [
        (0.0, 0.0, 4.0, 4.0),
        (1.0, 0.0, 60.0, 4.0),
        (1.0, 1.0, 60.0, 60.0),
        (0.0, 1.0, 4.0, 60.0),
    ] {
        gl.multi_tex_coord_2f(GL_TEXTURE0, s, t);
        gl.multi_tex_coord_2f(GL_TEXTURE1, s * 2.0, t * 2.0);
        gl.vertex_2f(x, y);
    }
    gl.end();
}

/// ARB_texture_rectangle: texel coordinates, LINEAR and NEAREST, clamped to the edge, GL_CLAMP
/// and clamped to the border.
fn texture_rectangle(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    let px = checker_pixels(12);
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_RECTANGLE_ARB, name[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_RECTANGLE_ARB,
        0,
        GL_RGBA8 as i32,
        12,
        12,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&px),
    );
    gl.tex_parameterfv(
        GL_TEXTURE_RECTANGLE_ARB,
        GL_TEXTURE_BORDER_COLOR,
        &[0.9, 0.2, 0.6, 1.0],
    );
    gl.enable(GL_TEXTURE_RECTANGLE_ARB);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    let panels = [
        (GL_LINEAR, GL_CLAMP_TO_EDGE, 2.3f32, 2.2f32),
        (GL_NEAREST, GL_CLAMP_TO_BORDER, 33.1, 2.4),
        (GL_LINEAR, GL_CLAMP, 2.6, 33.3),
        (GL_LINEAR, GL_CLAMP_TO_BORDER, 33.4, 33.2),
    ];
    for (filter, wrap, x0, y0) in panels {
        gl.tex_parameteri(
            GL_TEXTURE_RECTANGLE_ARB,
            GL_TEXTURE_MIN_FILTER,
            filter as i32,
        );
        gl.tex_parameteri(
            GL_TEXTURE_RECTANGLE_ARB,
            GL_TEXTURE_MAG_FILTER,
            filter as i32,
        );
        gl.tex_parameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, wrap as i32);
        gl.tex_parameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_T, wrap as i32);
        gl.begin(GL_TRIANGLES);
        for (s, t, x, y) in [
            // Corners off the pixel centres (an edge through a centre is a tie the fill
            // conventions break differently).
            (-2.3f32, -1.7f32, 0.0f32, 0.0f32),
            (14.1, -1.7, 28.63, 0.0),
            (14.1, 13.9, 28.63, 28.17),
            (-2.3, -1.7, 0.0, 0.0),
            (14.1, 13.9, 28.63, 28.17),
            (-2.3, 13.9, 0.0, 28.17),
        ] {
            gl.tex_coord_2f(s, t);
            gl.vertex_2f(x0 + x, y0 + y);
        }
        gl.end();
    }
}

/// A texture of `w` x `h` texels drawn with REPLACE, NEAREST, as a rectangle of the window.
fn index_textured_rect(gl: &mut dyn Gl, target: GLenum, rect: [f32; 4]) {
    gl.tex_parameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.enable(target);
    let [x0, y0, x1, y1] = rect;
    gl.begin(GL_QUADS);
    for (s, t, x, y) in [
        (0.0, 0.0, x0, y0),
        (1.0, 0.0, x1, y0),
        (1.0, 1.0, x1, y1),
        (0.0, 1.0, x0, y1),
    ] {
        gl.tex_coord_3f(s, t, 0.6);
        gl.vertex_2f(x, y);
    }
    gl.end();
    gl.disable(target);
}

/// Colour-index texture images (`GL_COLOR_INDEX` client data, section 3.8.1): indices through
/// the index shift and offset and the I_TO_R/G/B/A maps, as `GL_BITMAP` bits (LSB first or
/// not), unsigned bytes, shorts and floats, in glTexImage1D/2D/3D and
/// glTexSubImage2D.
fn tex_color_index_uploads(gl: &mut dyn Gl) {
    pixel_space(gl, 64.0, 64.0);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    // 16-entry maps: distinct colours per index, alpha varying too (shown through blending).
    let map = |k: usize, i: usize| ((i * (3 + 2 * k) + k * 5) % 16) as f32 / 15.0;
    for (k, m) in [
        GL_PIXEL_MAP_I_TO_R,
        GL_PIXEL_MAP_I_TO_G,
        GL_PIXEL_MAP_I_TO_B,
        GL_PIXEL_MAP_I_TO_A,
    ]
    .into_iter()
    .enumerate()
    {
        let v: Vec<f32> = (0..16).map(|i| map(k, i)).collect();
        gl.pixel_mapfv(m, 16, &v);
    }
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    // GL_BITMAP: 8x8 bits, MSB first, then LSB first with SKIP_PIXELS 3 and SKIP_ROWS 1.
    let bits: Vec<u8> = (0..20u8).map(|i| i.wrapping_mul(37) ^ 0xA5).collect();
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        8,
        8,
        0,
        GL_COLOR_INDEX,
        GL_BITMAP,
        Some(&bits[..8]),
    );
    index_textured_rect(gl, GL_TEXTURE_2D, [0.0, 0.0, 16.0, 16.0]);
    // (Not with GL_UNPACK_ROW_LENGTH or GL_UNPACK_SKIP_PIXELS: Mesa 22 reads bitmap texture
    // rows with a row length wrongly, rows 5-7 of an 8-row image with ROW_LENGTH 16 come back
    // 0 from 20 bytes that hold them, and with SKIP_PIXELS 3 the last row's bits past its
    // first byte change from run to run; tests/texture_state.rs checks tilegl against
    // section 3.6.4. Nor with GL_UNPACK_SKIP_ROWS: with SKIP_ROWS 1 Mesa 22 drew the last
    // row's bits 0 and 4 as index 0 in about one run of five (tilegl's picture the same in
    // every run, through Rust and C); tests/texture_index_stencil.rs checks SKIP_ROWS on
    // bitmaps against the spec. The rows from the second byte are what SKIP_ROWS 1 selects.)
    gl.pixel_storei(GL_UNPACK_LSB_FIRST, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        8,
        8,
        0,
        GL_COLOR_INDEX,
        GL_BITMAP,
        Some(&bits[1..9]),
    );
    index_textured_rect(gl, GL_TEXTURE_2D, [16.0, 0.0, 32.0, 16.0]);
    gl.pixel_storei(GL_UNPACK_LSB_FIRST, 0);
    // Unsigned bytes with an index shift of 1 and offset 3 (indices wrap through the 16-entry
    // maps), into an RGB texture.
    let bytes: Vec<u8> = (0..64u32).map(|i| (i * 7 % 251) as u8).collect();
    gl.pixel_transferi(GL_INDEX_SHIFT, 1);
    gl.pixel_transferi(GL_INDEX_OFFSET, 3);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGB as i32,
        8,
        8,
        0,
        GL_COLOR_INDEX,
        GL_UNSIGNED_BYTE,
        Some(&bytes),
    );
    index_textured_rect(gl, GL_TEXTURE_2D, [32.0, 0.0, 48.0, 16.0]);
    // A negative shift (right shift), shorts, into a luminance-alpha texture.
    gl.pixel_transferi(GL_INDEX_SHIFT, -2);
    gl.pixel_transferi(GL_INDEX_OFFSET, 0);
    let shorts: Vec<u8> = (0..64u16).flat_map(|i| (i * 13).to_ne_bytes()).collect();
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE_ALPHA as i32,
        8,
        8,
        0,
        GL_COLOR_INDEX,
        GL_UNSIGNED_SHORT,
        Some(&shorts),
    );
    index_textured_rect(gl, GL_TEXTURE_2D, [48.0, 0.0, 64.0, 16.0]);
    gl.pixel_transferi(GL_INDEX_SHIFT, 0);
    // A sub-image of float indices into an RGBA texture.
    let base = vec![200u8; 8 * 8 * 4];
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        8,
        8,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&base),
    );
    let floats: Vec<u8> = (0..15)
        .flat_map(|i| (i as f32 + 0.25).to_ne_bytes())
        .collect();
    gl.tex_sub_image_2d(
        GL_TEXTURE_2D,
        0,
        2,
        1,
        5,
        3,
        GL_COLOR_INDEX,
        GL_FLOAT,
        Some(&floats),
    );
    index_textured_rect(gl, GL_TEXTURE_2D, [0.0, 16.0, 16.0, 32.0]);
    // 1D: 16 byte indices.
    let line: Vec<u8> = (0..16u8).map(|i| i * 5).collect();
    gl.tex_image_1d(
        GL_TEXTURE_1D,
        0,
        GL_RGBA as i32,
        16,
        0,
        GL_COLOR_INDEX,
        GL_UNSIGNED_BYTE,
        Some(&line),
    );
    index_textured_rect(gl, GL_TEXTURE_1D, [16.0, 16.0, 32.0, 32.0]);
    // 3D: 4x4x4 byte indices with IMAGE_HEIGHT 5, sampled at r = 0.6. (Not with
    // GL_UNPACK_SKIP_IMAGES: Mesa 22 then stores zeros and stray values for colour-index
    // volumes; tests/texture_state.rs checks tilegl against section 3.8.1.)
    gl.pixel_storei(GL_UNPACK_IMAGE_HEIGHT, 5);
    let vol: Vec<u8> = (0..4 * 5 * 5u32).map(|i| (i * 11 % 97) as u8).collect();
    gl.tex_image_3d(
        GL_TEXTURE_3D,
        0,
        GL_RGBA as i32,
        4,
        4,
        4,
        0,
        GL_COLOR_INDEX,
        GL_UNSIGNED_BYTE,
        Some(&vol),
    );
    index_textured_rect(gl, GL_TEXTURE_3D, [32.0, 16.0, 48.0, 32.0]);
    gl.pixel_storei(GL_UNPACK_IMAGE_HEIGHT, 0);
    // MAP_COLOR on: RGBA-to-RGBA maps do not apply to indices (they are converted by the
    // I_TO_* maps), so this texture matches the one above drawn at 32..48 x 0..16.
    gl.pixel_transferi(GL_MAP_COLOR, 1);
    gl.pixel_mapfv(GL_PIXEL_MAP_R_TO_R, 2, &[1.0, 0.0]);
    gl.pixel_transferi(GL_INDEX_SHIFT, 1);
    gl.pixel_transferi(GL_INDEX_OFFSET, 3);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGB as i32,
        8,
        8,
        0,
        GL_COLOR_INDEX,
        GL_UNSIGNED_BYTE,
        Some(&bytes),
    );
    index_textured_rect(gl, GL_TEXTURE_2D, [48.0, 16.0, 64.0, 32.0]);
}

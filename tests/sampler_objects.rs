//! ARB_sampler_objects by the rules of its specification (section 3.9.2 "Sampler Objects",
//! 6.1.5 "Sampler Queries", table 6.23, the Errors section and issues 5, 6, 8 and 9). The
//! same calls compared with Mesa are in `conformance/src/state_cases/samplers.rs`.

mod common;

use common::{pixel, window_ortho};
use tilegl::enums::*;
use tilegl::{Context, Gl};

const RED: [u8; 4] = [255, 0, 0, 255];
const GREEN: [u8; 4] = [0, 255, 0, 255];
/// The primary colour the quads are drawn with: what a fragment keeps when its unit's
/// texture is incomplete (the unit acts as disabled, section 3.8.10).
const GREY: [u8; 4] = [128, 128, 128, 255];

fn samplers(gl: &mut Context, n: usize) -> Vec<u32> {
    let mut s = vec![0; n];
    gl.gen_samplers(n as i32, &mut s);
    s
}

/// A 2D texture bound to `GL_TEXTURE_2D` of the active unit: level 0 a 2x2 red image and,
/// with `two_levels`, level 1 a 1x1 green one; its own filters NEAREST (so it samples level
/// 0 only, and is complete without level 1).
fn two_level_texture(gl: &mut Context, two_levels: bool) -> u32 {
    let mut t = [0];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    let red: Vec<u8> = RED.repeat(4);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&red),
    );
    if two_levels {
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            1,
            GL_RGBA8 as i32,
            1,
            1,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&GREEN),
        );
    }
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    t[0]
}

/// Draws a grey quad over the window with the enabled texture targets replacing the colour
/// (`GL_REPLACE` on unit 0, as set up by [`context`]), texture coordinates [0, 64] over the
/// 16-pixel window (so the 2-texel level 0 minifies by 8: λ = 3), and returns the centre
/// pixel.
fn draw(gl: &mut Context) -> [u8; 4] {
    window_ortho(gl);
    let (w, h) = gl.size();
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.color_4ub(128, 128, 128, 255);
    gl.begin(GL_QUADS);
    for (x, y) in [(0, 0), (w, 0), (w, h), (0, h)] {
        let (s, t) = ((64 * x / w) as f32, (64 * y / h) as f32);
        gl.multi_tex_coord_2f(GL_TEXTURE0, s, t);
        gl.multi_tex_coord_2f(GL_TEXTURE1, s, t);
        gl.vertex_2f(x as f32, y as f32);
    }
    gl.end();
    pixel(gl, w / 2, h / 2)
}

fn context() -> Context {
    let mut gl = Context::new(16, 16);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl
}

fn geti(gl: &mut Context, pname: GLenum) -> i32 {
    let mut v = [-7];
    gl.get_integerv(pname, &mut v);
    v[0]
}

fn sampler_i(gl: &mut Context, s: u32, pname: GLenum) -> i32 {
    let mut v = [-7];
    gl.get_sampler_parameteriv(s, pname, &mut v);
    v[0]
}

fn sampler_f(gl: &mut Context, s: u32, pname: GLenum) -> f32 {
    let mut v = [-7.0];
    gl.get_sampler_parameterfv(s, pname, &mut v);
    v[0]
}

#[test]
fn names_and_initial_state() {
    let mut gl = context();
    let s = samplers(&mut gl, 3);
    assert!(s.iter().all(|&n| n != 0));
    assert!(s[0] != s[1] && s[1] != s[2] && s[0] != s[2]);
    // Issue 10: "as if they start existing when GenSamplers creates their names".
    for &n in &s {
        assert_eq!(gl.is_sampler(n), GL_TRUE as u8);
    }
    // "Zero is not the name of a sampler object."
    assert_eq!(gl.is_sampler(0), GL_FALSE as u8);
    assert_eq!(gl.is_sampler(s[2] + 100), GL_FALSE as u8);
    // Sampler names are not texture names (their own name space).
    assert_eq!(gl.is_texture(s[0]), GL_FALSE as u8);
    assert_eq!(gl.get_error(), GL_NO_ERROR);

    // Table 6.23's initial values.
    let n = s[0];
    let expect_i = [
        (GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR as i32),
        (GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32),
        (GL_TEXTURE_WRAP_S, GL_REPEAT as i32),
        (GL_TEXTURE_WRAP_T, GL_REPEAT as i32),
        (GL_TEXTURE_WRAP_R, GL_REPEAT as i32),
        (GL_TEXTURE_COMPARE_MODE, GL_NONE as i32),
        (GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL as i32),
    ];
    for (p, v) in expect_i {
        assert_eq!(sampler_i(&mut gl, n, p), v, "pname 0x{p:04x}");
    }
    let expect_f = [
        (GL_TEXTURE_MIN_LOD, -1000.0),
        (GL_TEXTURE_MAX_LOD, 1000.0),
        (GL_TEXTURE_LOD_BIAS, 0.0),
        (GL_TEXTURE_MAX_ANISOTROPY_EXT, 1.0),
    ];
    for (p, v) in expect_f {
        assert_eq!(sampler_f(&mut gl, n, p), v, "pname 0x{p:04x}");
    }
    let mut border = [-1.0f32; 4];
    gl.get_sampler_parameterfv(n, GL_TEXTURE_BORDER_COLOR, &mut border);
    assert_eq!(border, [0.0; 4]);
    // SAMPLER_BINDING: 0 on every unit.
    for unit in 0..8 {
        gl.active_texture(GL_TEXTURE0 + unit);
        assert_eq!(geti(&mut gl, GL_SAMPLER_BINDING), 0);
    }
    assert_eq!(gl.get_error(), GL_NO_ERROR);

    // "Unused names in <samplers> are silently ignored, as is the reserved name zero."
    gl.delete_samplers(3, &[0, s[1], 999]);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(gl.is_sampler(s[1]), GL_FALSE as u8);
    assert_eq!(gl.is_sampler(s[0]), GL_TRUE as u8);
    // A deleted name is unused again: binding it fails as for any name not generated.
    gl.bind_sampler(0, s[1]);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn errors_change_nothing() {
    let mut gl = context();
    let s = samplers(&mut gl, 1)[0];
    let mut out = [0u32; 2];
    gl.gen_samplers(-1, &mut out);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.delete_samplers(-1, &[s]);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    assert_eq!(gl.is_sampler(s), GL_TRUE as u8);

    // BindSampler: INVALID_VALUE for a unit past the last, INVALID_OPERATION for a name
    // GenSamplers did not return; the binding stays.
    gl.bind_sampler(0, s);
    gl.bind_sampler(8, s);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.bind_sampler(0, s + 1);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    assert_eq!(geti(&mut gl, GL_SAMPLER_BINDING), s as i32);

    // SamplerParameter*/GetSamplerParameter*: INVALID_OPERATION for a name that is not a
    // sampler (0 included), INVALID_ENUM for a pname outside table 6.23 (texture image
    // state such as BASE_LEVEL or PRIORITY stays in the texture) or a bad value, and
    // TexParameter's INVALID_VALUE for an anisotropy below 1.
    gl.sampler_parameteri(0, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.sampler_parameteri(s + 1, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    for p in [
        GL_TEXTURE_BASE_LEVEL,
        GL_TEXTURE_MAX_LEVEL,
        GL_TEXTURE_PRIORITY,
        GL_GENERATE_MIPMAP,
        GL_DEPTH_TEXTURE_MODE,
        GL_TEXTURE_2D,
    ] {
        gl.sampler_parameteri(s, p, 0);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM, "pname 0x{p:04x}");
        let mut v = [-7];
        gl.get_sampler_parameteriv(s, p, &mut v);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM, "query of 0x{p:04x}");
        assert_eq!(v, [-7], "a failed query writes nothing");
    }
    let mut v = [-7];
    gl.get_sampler_parameteriv(s + 1, GL_TEXTURE_MIN_FILTER, &mut v);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    assert_eq!(v, [-7]);
    let bad_values = [
        (GL_TEXTURE_MIN_FILTER, GL_REPEAT as i32),
        (GL_TEXTURE_MAG_FILTER, GL_NEAREST_MIPMAP_NEAREST as i32),
        (GL_TEXTURE_WRAP_S, GL_NEAREST as i32),
        (GL_TEXTURE_WRAP_R, 0),
        (GL_TEXTURE_COMPARE_MODE, GL_LESS as i32),
        (GL_TEXTURE_COMPARE_FUNC, GL_REPEAT as i32),
    ];
    for (p, value) in bad_values {
        gl.sampler_parameteri(s, p, value);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM, "0x{p:04x} = 0x{value:x}");
    }
    gl.sampler_parameterf(s, GL_TEXTURE_MAX_ANISOTROPY_EXT, 0.5);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    // The border colour has four values: not settable by the scalar commands.
    gl.sampler_parameterf(s, GL_TEXTURE_BORDER_COLOR, 1.0);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    // Nothing changed.
    assert_eq!(
        sampler_i(&mut gl, s, GL_TEXTURE_MIN_FILTER),
        GL_NEAREST_MIPMAP_LINEAR as i32
    );
    assert_eq!(sampler_i(&mut gl, s, GL_TEXTURE_WRAP_S), GL_REPEAT as i32);
    assert_eq!(sampler_f(&mut gl, s, GL_TEXTURE_MAX_ANISOTROPY_EXT), 1.0);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn parameters_round_trip_and_convert() {
    let mut gl = context();
    let s = samplers(&mut gl, 1)[0];
    gl.sampler_parameterf(s, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST as f32);
    gl.sampler_parameteriv(s, GL_TEXTURE_WRAP_T, &[GL_MIRRORED_REPEAT as i32]);
    gl.sampler_parameter_iiv(s, GL_TEXTURE_WRAP_R, &[GL_CLAMP_TO_BORDER as i32]);
    gl.sampler_parameter_iuiv(s, GL_TEXTURE_COMPARE_MODE, &[GL_COMPARE_R_TO_TEXTURE]);
    gl.sampler_parameteri(s, GL_TEXTURE_MIN_LOD, -3);
    gl.sampler_parameterfv(s, GL_TEXTURE_MAX_LOD, &[2.5]);
    gl.sampler_parameterf(s, GL_TEXTURE_LOD_BIAS, -1.25);
    gl.sampler_parameterf(s, GL_TEXTURE_MAX_ANISOTROPY_EXT, 4.0);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(
        sampler_i(&mut gl, s, GL_TEXTURE_MIN_FILTER),
        GL_LINEAR_MIPMAP_NEAREST as i32
    );
    assert_eq!(
        sampler_f(&mut gl, s, GL_TEXTURE_WRAP_T),
        GL_MIRRORED_REPEAT as f32
    );
    let mut u = [0u32];
    gl.get_sampler_parameter_iuiv(s, GL_TEXTURE_WRAP_R, &mut u);
    assert_eq!(u, [GL_CLAMP_TO_BORDER]);
    let mut i = [0];
    gl.get_sampler_parameter_iiv(s, GL_TEXTURE_COMPARE_MODE, &mut i);
    assert_eq!(i, [GL_COMPARE_R_TO_TEXTURE as i32]);
    assert_eq!(sampler_f(&mut gl, s, GL_TEXTURE_MIN_LOD), -3.0);
    assert_eq!(sampler_f(&mut gl, s, GL_TEXTURE_MAX_LOD), 2.5);
    assert_eq!(sampler_f(&mut gl, s, GL_TEXTURE_LOD_BIAS), -1.25);
    assert_eq!(sampler_f(&mut gl, s, GL_TEXTURE_MAX_ANISOTROPY_EXT), 4.0);

    // Border colour: SamplerParameteriv converts by equation 2.2, f = (2c + 1) / (2^32 - 1);
    // SamplerParameterfv stores the floats unmodified; the integer forms store the integers,
    // which the integer queries return unchanged.
    gl.sampler_parameteriv(s, GL_TEXTURE_BORDER_COLOR, &[i32::MAX, 0, -1, i32::MIN]);
    let mut f = [0.0f32; 4];
    gl.get_sampler_parameterfv(s, GL_TEXTURE_BORDER_COLOR, &mut f);
    let eq22 = |c: i32| ((2.0 * c as f64 + 1.0) / u32::MAX as f64) as f32;
    assert_eq!(f, [eq22(i32::MAX), eq22(0), eq22(-1), eq22(i32::MIN)]);
    gl.sampler_parameterfv(s, GL_TEXTURE_BORDER_COLOR, &[0.25, 1.5, -0.5, 1.0]);
    gl.get_sampler_parameterfv(s, GL_TEXTURE_BORDER_COLOR, &mut f);
    assert_eq!(f, [0.25, 1.5, -0.5, 1.0]);
    let mut iv = [0; 4];
    gl.get_sampler_parameteriv(s, GL_TEXTURE_BORDER_COLOR, &mut iv);
    // Colours in integer queries map [-1, 1] linearly to the full range (section 6.1.2),
    // truncated: 0.25 (2^31 - 1) = 536870911.75; values past the ends saturate.
    assert_eq!(iv, [536870911, i32::MAX, -1073741823, i32::MAX]);
    gl.sampler_parameter_iiv(s, GL_TEXTURE_BORDER_COLOR, &[-5, 7, 1 << 20, 0]);
    gl.get_sampler_parameter_iiv(s, GL_TEXTURE_BORDER_COLOR, &mut iv);
    assert_eq!(iv, [-5, 7, 1 << 20, 0]);
    gl.sampler_parameter_iuiv(s, GL_TEXTURE_BORDER_COLOR, &[u32::MAX, 3, 0, 1]);
    let mut uv = [0u32; 4];
    gl.get_sampler_parameter_iuiv(s, GL_TEXTURE_BORDER_COLOR, &mut uv);
    assert_eq!(uv, [u32::MAX, 3, 0, 1]);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn a_bound_sampler_supersedes_the_texture_state_which_stays() {
    let mut gl = context();
    let tex = two_level_texture(&mut gl, true);
    gl.enable(GL_TEXTURE_2D);
    // The texture's own NEAREST filter: level 0.
    assert_eq!(draw(&mut gl), RED);
    let s = samplers(&mut gl, 1)[0];
    gl.sampler_parameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST as i32);
    gl.sampler_parameteri(s, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    // Setting a sampler that is not bound changes nothing drawn.
    assert_eq!(draw(&mut gl), RED);
    gl.bind_sampler(0, s);
    // λ = 3 with the sampler's mipmap filter: the last level (1), green.
    assert_eq!(draw(&mut gl), GREEN);
    // "Calling TexParameter has no effect on the sampler object bound to the active texture
    // unit"; the texture keeps its own state, and queries of it answer that state.
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    assert_eq!(draw(&mut gl), GREEN);
    assert_eq!(
        sampler_i(&mut gl, s, GL_TEXTURE_MIN_FILTER),
        GL_NEAREST_MIPMAP_NEAREST as i32
    );
    let mut v = [0];
    gl.get_tex_parameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &mut v);
    assert_eq!(v[0], GL_LINEAR as i32);
    // Image state stays the texture's: MAX_LEVEL 0 leaves only level 0 to sample.
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    assert_eq!(draw(&mut gl), RED);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
    // Sampler LOD clamps apply: MAX_LOD 0 keeps λ at 0.
    gl.sampler_parameterf(s, GL_TEXTURE_MAX_LOD, 0.0);
    assert_eq!(draw(&mut gl), RED);
    gl.sampler_parameterf(s, GL_TEXTURE_MAX_LOD, 1000.0);
    // And the sampler's LOD bias: -3 brings λ to 0.
    gl.sampler_parameterf(s, GL_TEXTURE_LOD_BIAS, -3.0);
    assert_eq!(draw(&mut gl), RED);
    gl.sampler_parameterf(s, GL_TEXTURE_LOD_BIAS, 0.0);
    assert_eq!(draw(&mut gl), GREEN);
    // Issue 5: the sampler stays the source while textures are switched in and out,
    // the default texture included.
    gl.bind_texture(GL_TEXTURE_2D, 0);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        1,
        1,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&GREEN),
    );
    assert_eq!(draw(&mut gl), GREEN);
    gl.sampler_parameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.bind_texture(GL_TEXTURE_2D, tex);
    assert_eq!(draw(&mut gl), RED);
    // Unbinding (sampler 0) restores the texture's state: LINEAR, level 0.
    gl.sampler_parameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST as i32);
    assert_eq!(draw(&mut gl), GREEN);
    gl.bind_sampler(0, 0);
    assert_eq!(draw(&mut gl), RED);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn completeness_follows_the_sampler() {
    let mut gl = context();
    // Level 0 only: complete with the texture's NEAREST filter.
    two_level_texture(&mut gl, false);
    gl.enable(GL_TEXTURE_2D);
    assert_eq!(draw(&mut gl), RED);
    // "if the texture is not mipmap complete and the sampler object specifies a MIN_FILTER
    // requiring mipmaps, the texture will be considered incomplete for the purposes of that
    // texture unit".
    let s = samplers(&mut gl, 2);
    gl.bind_sampler(0, s[0]);
    assert_eq!(draw(&mut gl), GREY);
    // "However, if the sampler object does not require mipmaps, the texture object will be
    // considered complete" even when its own filter does.
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
    gl.bind_sampler(0, 0);
    assert_eq!(draw(&mut gl), GREY);
    gl.sampler_parameteri(s[1], GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.bind_sampler(0, s[1]);
    assert_eq!(draw(&mut gl), RED);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn a_rectangle_texture_with_state_it_refuses_is_incomplete() {
    // "if TEXTURE_WRAP_S ... is set to REPEAT or MIRRORED_REPEAT on the sampler object bound
    // to a texture unit and the texture bound to that unit is a TEXTURE_RECTANGLE, the
    // texture will be considered incomplete" (and likewise a mipmap filter, which
    // TexParameter refuses for rectangles).
    let mut gl = context();
    let mut t = [0];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_RECTANGLE_ARB, t[0]);
    let red: Vec<u8> = RED.repeat(4);
    gl.tex_image_2d(
        GL_TEXTURE_RECTANGLE_ARB,
        0,
        GL_RGBA8 as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&red),
    );
    gl.enable(GL_TEXTURE_RECTANGLE_ARB);
    assert_eq!(draw(&mut gl), RED);
    let s = samplers(&mut gl, 1)[0];
    gl.sampler_parameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.bind_sampler(0, s);
    // The sampler's default REPEAT wraps.
    assert_eq!(draw(&mut gl), GREY);
    gl.sampler_parameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
    assert_eq!(draw(&mut gl), GREY);
    gl.sampler_parameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE as i32);
    gl.sampler_parameteri(s, GL_TEXTURE_WRAP_R, GL_CLAMP as i32);
    assert_eq!(draw(&mut gl), RED);
    gl.sampler_parameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST as i32);
    assert_eq!(draw(&mut gl), GREY);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn one_sampler_on_two_units_and_deletion_unbinds() {
    let mut gl = context();
    // The same mipmapped texture on units 0 and 1 (unit 1 modulates unit 0's result).
    let tex = two_level_texture(&mut gl, true);
    gl.enable(GL_TEXTURE_2D);
    gl.active_texture(GL_TEXTURE1);
    gl.bind_texture(GL_TEXTURE_2D, tex);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    // red * red.
    assert_eq!(draw(&mut gl), RED);
    let s = samplers(&mut gl, 1)[0];
    gl.bind_sampler(0, s);
    gl.bind_sampler(1, s);
    // SAMPLER_BINDING is per unit, of the active one.
    assert_eq!(geti(&mut gl, GL_SAMPLER_BINDING), s as i32);
    // Issue 6: a change to the sampler reaches every unit it is bound to: green * green.
    gl.sampler_parameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST as i32);
    assert_eq!(draw(&mut gl), GREEN);
    // Only unit 1's sampler unbound: green (unit 0) * red (unit 1) = black.
    gl.bind_sampler(1, 0);
    assert_eq!(draw(&mut gl), [0, 0, 0, 255]);
    assert_eq!(geti(&mut gl, GL_SAMPLER_BINDING), 0);
    gl.active_texture(GL_TEXTURE0);
    assert_eq!(geti(&mut gl, GL_SAMPLER_BINDING), s as i32);
    // "If a sampler object that is currently bound to a sampler unit is deleted, it is as
    // though BindSampler is called with <unit> set to the unit the sampler is bound to and
    // <sampler> zero."
    gl.delete_samplers(1, &[s]);
    assert_eq!(geti(&mut gl, GL_SAMPLER_BINDING), 0);
    assert_eq!(draw(&mut gl), RED);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn attribute_stack_leaves_samplers_alone() {
    // Section 6.1.20 as amended: "The bindings and state for sampler objects are not pushed
    // or popped."
    let mut gl = context();
    let s = samplers(&mut gl, 2);
    gl.bind_sampler(0, s[0]);
    gl.push_attrib(GL_ALL_ATTRIB_BITS);
    gl.bind_sampler(0, s[1]);
    gl.sampler_parameteri(s[0], GL_TEXTURE_WRAP_S, GL_CLAMP as i32);
    gl.pop_attrib();
    assert_eq!(geti(&mut gl, GL_SAMPLER_BINDING), s[1] as i32);
    assert_eq!(sampler_i(&mut gl, s[0], GL_TEXTURE_WRAP_S), GL_CLAMP as i32);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn display_lists_hold_binds_and_parameters_not_gen_or_delete() {
    // GenSamplers and DeleteSamplers join the commands not usable in display lists (section
    // 5.4.1: executed immediately while compiling); BindSampler and SamplerParameter* are
    // ordinary commands, compiled.
    let mut gl = context();
    let s = samplers(&mut gl, 2);
    let list = gl.gen_lists(1);
    gl.new_list(list, GL_COMPILE);
    gl.bind_sampler(0, s[0]);
    gl.sampler_parameteri(s[0], GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
    gl.delete_samplers(1, &[s[1]]);
    let mut made = [0];
    gl.gen_samplers(1, &mut made);
    gl.end_list();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(
        gl.is_sampler(s[1]),
        GL_FALSE as u8,
        "deleted while compiling"
    );
    assert_eq!(
        gl.is_sampler(made[0]),
        GL_TRUE as u8,
        "generated while compiling"
    );
    assert_eq!(
        geti(&mut gl, GL_SAMPLER_BINDING),
        0,
        "the bind was only compiled"
    );
    assert_eq!(
        sampler_i(&mut gl, s[0], GL_TEXTURE_WRAP_S),
        GL_REPEAT as i32
    );
    gl.call_list(list);
    assert_eq!(geti(&mut gl, GL_SAMPLER_BINDING), s[0] as i32);
    assert_eq!(
        sampler_i(&mut gl, s[0], GL_TEXTURE_WRAP_S),
        GL_CLAMP_TO_EDGE as i32
    );
    // Errors of compiled commands are raised when the list executes.
    let bad = gl.gen_lists(1);
    gl.new_list(bad, GL_COMPILE);
    gl.bind_sampler(0, 12345);
    gl.end_list();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.call_list(bad);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn samplers_are_shared_as_textures_are() {
    // Issue 8: "The semantics of sharing a sampler object between contexts is the same as
    // that of sharing texture objects."
    let mut a = context();
    let mut b = context();
    let mut c = context();
    b.join_share_group(&a.share_group());
    let s = samplers(&mut a, 1)[0];
    a.sampler_parameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST as i32);
    assert_eq!(b.is_sampler(s), GL_TRUE as u8);
    assert_eq!(c.is_sampler(s), GL_FALSE as u8);
    assert_eq!(
        sampler_i(&mut b, s, GL_TEXTURE_MIN_FILTER),
        GL_NEAREST_MIPMAP_NEAREST as i32
    );
    // Bindings stay per context; b samples through the shared sampler.
    two_level_texture(&mut b, true);
    b.enable(GL_TEXTURE_2D);
    b.bind_sampler(0, s);
    assert_eq!(geti(&mut a, GL_SAMPLER_BINDING), 0);
    assert_eq!(draw(&mut b), GREEN);
    // A name from b's group is new in a's too (one name space).
    let t = samplers(&mut b, 1)[0];
    assert_ne!(t, s);
    assert_eq!(a.is_sampler(t), GL_TRUE as u8);
    // Deleted in a: b's binding no longer supplies state (its texture's own applies).
    a.delete_samplers(1, &[s]);
    assert_eq!(b.is_sampler(s), GL_FALSE as u8);
    b.refresh_shared_objects();
    assert_eq!(draw(&mut b), RED);
}

#[test]
fn listed_and_found() {
    let mut gl = context();
    let ext = gl.get_string(GL_EXTENSIONS).unwrap_or_default();
    assert!(ext.split(' ').any(|e| e == "GL_ARB_sampler_objects"));
    // No shading language: a parseable version string all the same (piglit reads it from
    // GL 1.x contexts).
    assert_eq!(
        gl.get_string(GL_SHADING_LANGUAGE_VERSION).as_deref(),
        Some("0.0")
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

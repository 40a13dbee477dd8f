//! ARB_sampler_objects: the same calls on Mesa and on tilegl (Rust API and C ABI), every
//! answer (names, `glIsSampler`, every sampler parameter through the four query forms,
//! `GL_SAMPLER_BINDING`, GL errors, pictures drawn through bound samplers) equal to Mesa's.
//! The unit limit of `glBindSampler` is only probed far past both implementations' units
//! (tilegl's is `GL_MAX_TEXTURE_UNITS`, Mesa's its combined image units).

super::state_case_list!(source = include_str!("samplers.rs"), agree = |a: &Answer, b: &Answer| {
    a.values.len() == b.values.len()
        && a.values
            .iter()
            .zip(&b.values)
            .all(|(x, y)| (x - y).abs() <= a.tolerance)
};
    sampler_objects_state_and_errors: "Names from glGenSamplers (glIsSampler true, 0 and unused names false), the initial state of table 6.23 through glGetSamplerParameteriv/fv/Iiv/Iuiv, each parameter set through each glSamplerParameter form and read back (the border colour converted by equation 2.2 from integers, kept as given from floats and as integers from the I forms), the errors (INVALID_OPERATION for a name glGenSamplers did not return, INVALID_ENUM for image-state or unknown pnames and bad values, INVALID_VALUE for an anisotropy below 1 and a unit far past the last), GL_SAMPLER_BINDING per unit, deletion unbinding, the attribute stack leaving bindings alone, and display lists holding glBindSampler and glSamplerParameter* but executing glDeleteSamplers at once. Every answer equals Mesa's.",
    sampler_objects_sampling: "A mipmapped texture (each level its own colour) drawn through sampler objects: the sampler's filters, LOD clamps, LOD bias and wrap modes with its border colour replace the texture's while bound (the texture's own queries unchanged) and stop applying when unbound or deleted; completeness follows the sampler's minification filter both ways; one sampler on two units; a depth texture compared through the sampler's compare mode and function. Every answer equals Mesa's.",
);

use super::fbo::{err, exact, int, pixel_space, read_rgba, Answer, Answers};
use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::Gl;

/// Every sampler parameter of table 6.23, four-valued border colour first.
const PNAMES: [GLenum; 12] = [
    GL_TEXTURE_BORDER_COLOR,
    GL_TEXTURE_MIN_FILTER,
    GL_TEXTURE_MAG_FILTER,
    GL_TEXTURE_WRAP_S,
    GL_TEXTURE_WRAP_T,
    GL_TEXTURE_WRAP_R,
    GL_TEXTURE_MIN_LOD,
    GL_TEXTURE_MAX_LOD,
    GL_TEXTURE_LOD_BIAS,
    GL_TEXTURE_COMPARE_MODE,
    GL_TEXTURE_COMPARE_FUNC,
    GL_TEXTURE_MAX_ANISOTROPY_EXT,
];

/// `pname` of sampler `s` through glGetSamplerParameteriv and fv (and, for the integer
/// parameters, Iiv and Iuiv, which answer as iv for them), with the error after each.
fn query(gl: &mut dyn Gl, out: &mut Answers, s: u32, pname: GLenum, label: &str) {
    let n = if pname == GL_TEXTURE_BORDER_COLOR {
        4
    } else {
        1
    };
    let mut iv = [-7i32; 4];
    gl.get_sampler_parameteriv(s, pname, &mut iv[..n]);
    exact(
        out,
        format!("glGetSamplerParameteriv(0x{pname:04x}) {label}"),
        iv[..n].iter().map(|&v| v as f64).collect(),
    );
    err(gl, out, "glGetSamplerParameteriv");
    let mut fv = [-7.0f32; 4];
    gl.get_sampler_parameterfv(s, pname, &mut fv[..n]);
    exact(
        out,
        format!("glGetSamplerParameterfv(0x{pname:04x}) {label}"),
        fv[..n].iter().map(|&v| v as f64).collect(),
    );
    err(gl, out, "glGetSamplerParameterfv");
    // The integer forms of the float parameters and of a border colour given as floats are
    // what the implementation makes of them (undefined for the colour); asked for the enums.
    let enum_valued = !matches!(
        pname,
        GL_TEXTURE_BORDER_COLOR
            | GL_TEXTURE_MIN_LOD
            | GL_TEXTURE_MAX_LOD
            | GL_TEXTURE_LOD_BIAS
            | GL_TEXTURE_MAX_ANISOTROPY_EXT
    );
    if enum_valued {
        let mut i = [-7i32];
        gl.get_sampler_parameter_iiv(s, pname, &mut i);
        let mut u = [7u32];
        gl.get_sampler_parameter_iuiv(s, pname, &mut u);
        exact(
            out,
            format!("glGetSamplerParameterIiv/Iuiv(0x{pname:04x}) {label}"),
            vec![i[0] as f64, u[0] as f64],
        );
        err(gl, out, "glGetSamplerParameterIiv/Iuiv");
    }
}

fn all_params(gl: &mut dyn Gl, out: &mut Answers, s: u32, label: &str) {
    for p in PNAMES {
        query(gl, out, s, p, label);
    }
}

fn is_sampler(gl: &mut dyn Gl, out: &mut Answers, s: u32, label: &str) {
    let v = gl.is_sampler(s);
    exact(out, format!("glIsSampler {label}"), vec![v as f64]);
}

/// Names, state, errors, bindings, the attribute stack and display lists.
fn sampler_objects_state_and_errors(gl: &mut dyn Gl, out: &mut Answers) {
    let mut s = [0u32; 3];
    gl.gen_samplers(3, &mut s);
    err(gl, out, "glGenSamplers");
    exact(
        out,
        "names distinct and not 0".into(),
        vec![
            (s.iter().all(|&n| n != 0) && s[0] != s[1] && s[1] != s[2] && s[0] != s[2]) as u8
                as f64,
        ],
    );
    for (i, &n) in s.iter().enumerate() {
        is_sampler(gl, out, n, &format!("of generated name {i}"));
    }
    is_sampler(gl, out, 0, "of 0");
    is_sampler(gl, out, s[2] + 1000, "of an unused name");
    let mut t = [0u32];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    let texture_is_sampler = gl.is_sampler(t[0]) != 0 && !s.contains(&t[0]);
    exact(
        out,
        "a texture name is not a sampler".into(),
        vec![texture_is_sampler as u8 as f64],
    );
    all_params(gl, out, s[0], "initially");

    // Each form of glSamplerParameter.
    let a = s[0];
    gl.sampler_parameteri(a, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST as i32);
    gl.sampler_parameterf(a, GL_TEXTURE_MAG_FILTER, GL_NEAREST as f32);
    gl.sampler_parameteriv(a, GL_TEXTURE_WRAP_S, &[GL_MIRRORED_REPEAT as i32]);
    gl.sampler_parameterfv(a, GL_TEXTURE_WRAP_T, &[GL_CLAMP_TO_BORDER as f32]);
    gl.sampler_parameter_iiv(a, GL_TEXTURE_WRAP_R, &[GL_CLAMP_TO_EDGE as i32]);
    gl.sampler_parameter_iuiv(a, GL_TEXTURE_COMPARE_MODE, &[GL_COMPARE_R_TO_TEXTURE]);
    gl.sampler_parameteri(a, GL_TEXTURE_COMPARE_FUNC, GL_GREATER as i32);
    gl.sampler_parameterf(a, GL_TEXTURE_MIN_LOD, -2.25);
    gl.sampler_parameteri(a, GL_TEXTURE_MAX_LOD, 7);
    gl.sampler_parameterfv(a, GL_TEXTURE_LOD_BIAS, &[1.5]);
    gl.sampler_parameterf(a, GL_TEXTURE_MAX_ANISOTROPY_EXT, 4.0);
    gl.sampler_parameterfv(a, GL_TEXTURE_BORDER_COLOR, &[0.25, 0.5, 0.75, 1.0]);
    err(gl, out, "setting every parameter");
    all_params(gl, out, a, "after setting each");
    // Rounding of float values in the integer query, and values past the range.
    gl.sampler_parameterf(a, GL_TEXTURE_MIN_LOD, 2.5);
    gl.sampler_parameterf(a, GL_TEXTURE_MAX_LOD, -3.7);
    gl.sampler_parameterf(a, GL_TEXTURE_LOD_BIAS, 100.0);
    gl.sampler_parameterf(a, GL_TEXTURE_MAX_ANISOTROPY_EXT, 1000.0);
    err(gl, out, "LODs, bias and anisotropy past their ranges");
    for p in [
        GL_TEXTURE_MIN_LOD,
        GL_TEXTURE_MAX_LOD,
        GL_TEXTURE_LOD_BIAS,
        GL_TEXTURE_MAX_ANISOTROPY_EXT,
    ] {
        query(gl, out, a, p, "past the ranges");
    }
    // Border colours: integers by equation 2.2, floats outside [0, 1] kept.
    gl.sampler_parameteriv(
        a,
        GL_TEXTURE_BORDER_COLOR,
        &[i32::MAX, 0, i32::MAX / 2, -i32::MAX],
    );
    err(gl, out, "an integer border colour");
    query(gl, out, a, GL_TEXTURE_BORDER_COLOR, "given as integers");
    // Kept unclamped (the integer query of a colour past 1 overflows on Mesa: floats only).
    gl.sampler_parameterfv(a, GL_TEXTURE_BORDER_COLOR, &[-0.5, 2.0, 0.125, 1.0]);
    let mut fv = [0.0f32; 4];
    gl.get_sampler_parameterfv(a, GL_TEXTURE_BORDER_COLOR, &mut fv);
    exact(
        out,
        "border colour given out of range, read by fv".into(),
        fv.iter().map(|&v| v as f64).collect(),
    );
    gl.sampler_parameterfv(a, GL_TEXTURE_BORDER_COLOR, &[-0.5, -1.0, 0.125, 0.999]);
    query(gl, out, a, GL_TEXTURE_BORDER_COLOR, "given in [-1, 1]");
    gl.sampler_parameter_iiv(a, GL_TEXTURE_BORDER_COLOR, &[-3, 0, 77, 1 << 30]);
    let mut iv = [0i32; 4];
    gl.get_sampler_parameter_iiv(a, GL_TEXTURE_BORDER_COLOR, &mut iv);
    exact(
        out,
        "border colour by glSamplerParameterIiv, read by Iiv".into(),
        iv.iter().map(|&v| v as f64).collect(),
    );
    gl.sampler_parameter_iuiv(a, GL_TEXTURE_BORDER_COLOR, &[u32::MAX, 5, 0, 1 << 31]);
    let mut uv = [0u32; 4];
    gl.get_sampler_parameter_iuiv(a, GL_TEXTURE_BORDER_COLOR, &mut uv);
    exact(
        out,
        "border colour by glSamplerParameterIuiv, read by Iuiv".into(),
        uv.iter().map(|&v| v as f64).collect(),
    );
    err(gl, out, "integer border colours");

    // Errors.
    let b = s[1];
    let unused = s[2] + 1000;
    gl.sampler_parameteri(unused, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    err(gl, out, "glSamplerParameteri of an unused name");
    gl.sampler_parameteri(0, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    err(gl, out, "glSamplerParameteri of 0");
    let mut v = [-7];
    gl.get_sampler_parameteriv(unused, GL_TEXTURE_MIN_FILTER, &mut v);
    err(gl, out, "glGetSamplerParameteriv of an unused name");
    for p in [
        GL_TEXTURE_BASE_LEVEL,
        GL_TEXTURE_MAX_LEVEL,
        GL_TEXTURE_PRIORITY,
        GL_GENERATE_MIPMAP,
        GL_DEPTH_TEXTURE_MODE,
        GL_TEXTURE_RESIDENT,
        GL_TEXTURE_2D,
    ] {
        gl.sampler_parameteri(b, p, 0);
        err(gl, out, &format!("glSamplerParameteri(0x{p:04x})"));
        gl.get_sampler_parameteriv(b, p, &mut v);
        err(gl, out, &format!("glGetSamplerParameteriv(0x{p:04x})"));
    }
    for (p, value) in [
        (GL_TEXTURE_MIN_FILTER, GL_REPEAT as i32),
        (GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR as i32),
        (GL_TEXTURE_WRAP_S, GL_LINEAR as i32),
        (GL_TEXTURE_WRAP_T, 0),
        (GL_TEXTURE_COMPARE_MODE, GL_LEQUAL as i32),
        (GL_TEXTURE_COMPARE_FUNC, GL_CLAMP as i32),
    ] {
        gl.sampler_parameteri(b, p, value);
        err(
            gl,
            out,
            &format!("glSamplerParameteri(0x{p:04x}, 0x{value:x})"),
        );
    }
    gl.sampler_parameterf(b, GL_TEXTURE_MAX_ANISOTROPY_EXT, 0.5);
    err(gl, out, "an anisotropy of 0.5");
    gl.sampler_parameteri(b, GL_TEXTURE_BORDER_COLOR, 0);
    err(gl, out, "glSamplerParameteri(GL_TEXTURE_BORDER_COLOR)");
    all_params(gl, out, b, "after the errors");
    let mut none = [0u32; 1];
    gl.gen_samplers(-1, &mut none);
    err(gl, out, "glGenSamplers(-1)");
    gl.delete_samplers(-1, &s);
    err(gl, out, "glDeleteSamplers(-1)");

    // Bindings.
    int(gl, out, GL_SAMPLER_BINDING);
    gl.bind_sampler(0, a);
    gl.bind_sampler(2, b);
    err(gl, out, "glBindSampler of units 0 and 2");
    gl.bind_sampler(100_000, a);
    err(gl, out, "glBindSampler of unit 100000");
    gl.bind_sampler(1, unused);
    err(gl, out, "glBindSampler of an unused name");
    for unit in 0..3 {
        gl.active_texture(GL_TEXTURE0 + unit);
        int(gl, out, GL_SAMPLER_BINDING);
    }
    gl.active_texture(GL_TEXTURE0);
    // The attribute stack leaves bindings and sampler state alone.
    gl.push_attrib(GL_ALL_ATTRIB_BITS);
    gl.bind_sampler(0, b);
    gl.sampler_parameteri(b, GL_TEXTURE_WRAP_S, GL_CLAMP as i32);
    gl.pop_attrib();
    err(gl, out, "push, bind, set, pop");
    int(gl, out, GL_SAMPLER_BINDING);
    query(gl, out, b, GL_TEXTURE_WRAP_S, "after the pop");
    // Deleting unbinds from every unit; unused names and 0 are ignored.
    gl.delete_samplers(3, &[b, 0, unused]);
    err(gl, out, "glDeleteSamplers");
    is_sampler(gl, out, b, "after deletion");
    for unit in [0, 2] {
        gl.active_texture(GL_TEXTURE0 + unit);
        int(gl, out, GL_SAMPLER_BINDING);
    }
    gl.active_texture(GL_TEXTURE0);
    gl.bind_sampler(0, b);
    err(gl, out, "glBindSampler of a deleted name");

    // Display lists.
    let c = s[2];
    let list = gl.gen_lists(1);
    gl.new_list(list, GL_COMPILE);
    gl.bind_sampler(3, c);
    gl.sampler_parameteri(c, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.delete_samplers(1, &[a]);
    gl.bind_sampler(0, 4242);
    gl.end_list();
    err(gl, out, "compiling");
    is_sampler(gl, out, a, "deleted while compiling");
    gl.active_texture(GL_TEXTURE3);
    int(gl, out, GL_SAMPLER_BINDING);
    query(gl, out, c, GL_TEXTURE_MAG_FILTER, "after compiling");
    gl.call_list(list);
    err(gl, out, "glCallList");
    int(gl, out, GL_SAMPLER_BINDING);
    query(gl, out, c, GL_TEXTURE_MAG_FILTER, "after the list");
    gl.active_texture(GL_TEXTURE0);
}

const LEVEL_COLOURS: [[u8; 4]; 4] = [
    [255, 0, 0, 255],
    [0, 255, 0, 255],
    [0, 0, 255, 255],
    [255, 255, 0, 255],
];

/// An 8x8 2D texture, each of its four levels one colour of [`LEVEL_COLOURS`], its own
/// filters NEAREST and wrap CLAMP_TO_EDGE, bound to `GL_TEXTURE_2D` of the active unit.
fn mip_texture(gl: &mut dyn Gl, levels: usize) -> u32 {
    let mut t = [0];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    for (level, c) in LEVEL_COLOURS.iter().enumerate().take(levels) {
        let side = 8 >> level;
        let px: Vec<u8> = (0..side * side).flat_map(|_| *c).collect();
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            level as i32,
            GL_RGBA8 as i32,
            side,
            side,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&px),
        );
    }
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE as i32);
    t[0]
}

/// A `w` x `h` quad at (`x`, 0) whose texture coordinates run from `s0` to `s1` (both
/// directions, units 0 and 1), in grey.
fn tex_quad(gl: &mut dyn Gl, x: f32, w: f32, h: f32, s0: f32, s1: f32) {
    gl.color_4ub(128, 128, 128, 255);
    gl.begin(GL_QUADS);
    for (dx, dy, s, t) in [
        (0.0, 0.0, s0, s0),
        (w, 0.0, s1, s0),
        (w, h, s1, s1),
        (0.0, h, s0, s1),
    ] {
        gl.multi_tex_coord_2f(GL_TEXTURE0, s, t);
        gl.multi_tex_coord_2f(GL_TEXTURE1, s, t);
        gl.vertex_2f(x + dx, dy);
    }
    gl.end();
}

/// Draws a row of four 4x4 quads over which the 8 texels of level 0 make λ 0, 1, 2 and 3, and
/// an 8x8 one with coordinates from -0.5 to 1.5 (λ 1; the wrap modes and border colour show),
/// then reads the row.
fn minification_row(gl: &mut dyn Gl, out: &mut Answers, label: &str) {
    gl.clear(GL_COLOR_BUFFER_BIT);
    // 4x4 pixels each, texture coordinates 0..k: 8k texels over 4 pixels, λ = log2(2k).
    for (i, k) in [0.5f32, 1.0, 2.0, 4.0].into_iter().enumerate() {
        tex_quad(gl, i as f32 * 8.0, 4.0, 4.0, 0.0, k);
    }
    // And one quad reaching outside [0, 1] (wrap modes, border colour).
    tex_quad(gl, 32.0, 8.0, 8.0, -0.5, 1.5);
    err(gl, out, &format!("drawing {label}"));
    read_rgba(gl, out, label, 0, 0, 40, 8);
}

/// Sampling through sampler objects.
fn sampler_objects_sampling(gl: &mut dyn Gl, out: &mut Answers) {
    pixel_space(gl, 64, 64);
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    let tex = mip_texture(gl, 4);
    gl.enable(GL_TEXTURE_2D);
    minification_row(gl, out, "the texture's own NEAREST");
    let mut s = [0u32; 3];
    gl.gen_samplers(3, &mut s);
    gl.bind_sampler(0, s[0]);
    // The default sampler: NEAREST_MIPMAP_LINEAR, LINEAR, REPEAT.
    minification_row(gl, out, "the default sampler");
    gl.sampler_parameteri(
        s[0],
        GL_TEXTURE_MIN_FILTER,
        GL_NEAREST_MIPMAP_NEAREST as i32,
    );
    gl.sampler_parameteri(s[0], GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    minification_row(gl, out, "NEAREST_MIPMAP_NEAREST");
    gl.sampler_parameterf(s[0], GL_TEXTURE_MIN_LOD, 1.0);
    gl.sampler_parameterf(s[0], GL_TEXTURE_MAX_LOD, 2.0);
    minification_row(gl, out, "LOD clamped to [1, 2]");
    gl.sampler_parameterf(s[0], GL_TEXTURE_MIN_LOD, -1000.0);
    gl.sampler_parameterf(s[0], GL_TEXTURE_MAX_LOD, 1000.0);
    gl.sampler_parameterf(s[0], GL_TEXTURE_LOD_BIAS, 1.0);
    minification_row(gl, out, "LOD bias 1");
    gl.sampler_parameterf(s[0], GL_TEXTURE_LOD_BIAS, 0.0);
    gl.sampler_parameteri(s[0], GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER as i32);
    gl.sampler_parameteri(s[0], GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT as i32);
    gl.sampler_parameterfv(s[0], GL_TEXTURE_BORDER_COLOR, &[0.0, 0.0, 1.0, 1.0]);
    minification_row(gl, out, "border and mirrored wraps");
    // The texture's own state is unchanged by all this.
    for p in [GL_TEXTURE_MIN_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_MIN_LOD] {
        let mut v = [-1.0f32];
        gl.get_tex_parameterfv(GL_TEXTURE_2D, p, &mut v);
        exact(
            out,
            format!("glGetTexParameterfv(0x{p:04x}) with a sampler bound"),
            vec![v[0] as f64],
        );
    }
    // Image state stays the texture's.
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
    minification_row(gl, out, "base level 1 (the texture's)");
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    // Unbound: the texture's state again.
    gl.bind_sampler(0, 0);
    minification_row(gl, out, "unbound");

    // Completeness both ways: levels 0 and 1 only of an 8x8 texture.
    let partial = mip_texture(gl, 2);
    minification_row(gl, out, "partial mipmap, NEAREST");
    gl.bind_sampler(0, s[1]);
    minification_row(gl, out, "partial mipmap, a sampler that needs mipmaps");
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
    gl.sampler_parameteri(s[1], GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    minification_row(
        gl,
        out,
        "partial mipmap, texture needs mipmaps, sampler not",
    );
    gl.bind_sampler(0, 0);
    minification_row(gl, out, "partial mipmap, texture needs mipmaps, unbound");

    // One sampler on two units: unit 1 modulates unit 0.
    gl.bind_texture(GL_TEXTURE_2D, tex);
    gl.active_texture(GL_TEXTURE1);
    gl.bind_texture(GL_TEXTURE_2D, tex);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.active_texture(GL_TEXTURE0);
    gl.sampler_parameteri(
        s[2],
        GL_TEXTURE_MIN_FILTER,
        GL_NEAREST_MIPMAP_NEAREST as i32,
    );
    gl.sampler_parameteri(s[2], GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.bind_sampler(0, s[2]);
    gl.bind_sampler(1, s[2]);
    minification_row(gl, out, "one sampler on units 0 and 1");
    gl.sampler_parameterf(s[2], GL_TEXTURE_LOD_BIAS, -1.0);
    minification_row(gl, out, "its bias changed");
    gl.delete_samplers(1, &[s[2]]);
    minification_row(gl, out, "deleted");
    gl.active_texture(GL_TEXTURE1);
    gl.disable(GL_TEXTURE_2D);
    gl.active_texture(GL_TEXTURE0);
    gl.delete_textures(2, &[tex, partial]);

    // A depth texture compared through the sampler: 2x2 depths 0.25 and 0.75 by column.
    let mut d = [0];
    gl.gen_textures(1, &mut d);
    gl.bind_texture(GL_TEXTURE_2D, d[0]);
    let depths = [0.25f32, 0.75, 0.25, 0.75];
    let bytes: Vec<u8> = depths.iter().flat_map(|v| v.to_ne_bytes()).collect();
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_DEPTH_COMPONENT24 as i32,
        2,
        2,
        0,
        GL_DEPTH_COMPONENT,
        GL_FLOAT,
        Some(&bytes),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.sampler_parameteri(s[1], GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.sampler_parameteri(s[1], GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.sampler_parameteri(
        s[1],
        GL_TEXTURE_COMPARE_MODE,
        GL_COMPARE_R_TO_TEXTURE as i32,
    );
    gl.sampler_parameteri(s[1], GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL as i32);
    gl.bind_sampler(0, s[1]);
    let depth_row = |gl: &mut dyn Gl, out: &mut Answers, label: &str| {
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.begin(GL_QUADS);
        for (x, y, s) in [
            (0.0, 0.0, 0.0),
            (8.0, 0.0, 1.0),
            (8.0, 4.0, 1.0),
            (0.0, 4.0, 0.0),
        ] {
            gl.tex_coord_3f(s, 0.5, 0.5);
            gl.vertex_2f(x, y);
        }
        gl.end();
        err(gl, out, &format!("drawing {label}"));
        read_rgba(gl, out, label, 0, 0, 8, 4);
    };
    depth_row(gl, out, "depth compared by the sampler, LEQUAL");
    gl.sampler_parameteri(s[1], GL_TEXTURE_COMPARE_FUNC, GL_GREATER as i32);
    depth_row(gl, out, "depth compared by the sampler, GREATER");
    gl.sampler_parameteri(s[1], GL_TEXTURE_COMPARE_MODE, GL_NONE as i32);
    depth_row(gl, out, "depth not compared");
    gl.bind_sampler(0, 0);
    gl.disable(GL_TEXTURE_2D);
}

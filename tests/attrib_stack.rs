//! `glPushAttrib`/`glPopAttrib` (section 6.1.14): every queryable value comes back after a pop
//! of the groups that hold it, values of other groups stay, and the stack limits and errors.

mod common;

use common::state_fingerprint;
use tilegl::enums::*;
use tilegl::{Context, Gl};

type Fingerprint = Vec<(GLenum, Vec<f64>)>;

/// The `glGet` fingerprint plus the state read by the other query commands: lights,
/// materials, texture coordinate generation, texture environments and parameters of every
/// unit, clip planes, the polygon stipple.
fn deep_state(gl: &mut Context) -> Fingerprint {
    let mut out = state_fingerprint(gl);
    let mut f;
    let mut d = [0f64; 4];
    let mut push = |k: u32, v: Vec<f64>| out.push((k, v));
    for l in 0..8 {
        for (i, p) in [
            GL_AMBIENT,
            GL_DIFFUSE,
            GL_SPECULAR,
            GL_POSITION,
            GL_SPOT_DIRECTION,
            GL_SPOT_EXPONENT,
            GL_SPOT_CUTOFF,
            GL_CONSTANT_ATTENUATION,
            GL_LINEAR_ATTENUATION,
            GL_QUADRATIC_ATTENUATION,
        ]
        .into_iter()
        .enumerate()
        {
            f = [0.0; 16];
            gl.get_lightfv(GL_LIGHT0 + l, p, &mut f);
            push(l * 100 + i as u32, f.iter().map(|&v| v as f64).collect());
        }
    }
    for (fi, face) in [GL_FRONT, GL_BACK].into_iter().enumerate() {
        for p in [
            GL_AMBIENT,
            GL_DIFFUSE,
            GL_SPECULAR,
            GL_EMISSION,
            GL_SHININESS,
        ] {
            f = [0.0; 16];
            gl.get_materialfv(face, p, &mut f);
            push(
                10_000 + fi as u32 * 100 + p,
                f.iter().map(|&v| v as f64).collect(),
            );
        }
    }
    let mut active = [0i32];
    gl.get_integerv(GL_ACTIVE_TEXTURE, &mut active);
    for unit in 0..8u32 {
        gl.active_texture(GL_TEXTURE0 + unit);
        for coord in [GL_S, GL_T, GL_R, GL_Q] {
            for p in [GL_OBJECT_PLANE, GL_EYE_PLANE] {
                gl.get_tex_gendv(coord, p, &mut d);
                push(20_000 + unit * 1000 + coord + p, d.to_vec());
            }
            let mut m = [0f64];
            gl.get_tex_gendv(coord, GL_TEXTURE_GEN_MODE, &mut m);
            push(30_000 + unit * 1000 + coord, m.to_vec());
        }
        for p in [
            GL_TEXTURE_ENV_MODE,
            GL_TEXTURE_ENV_COLOR,
            GL_COMBINE_RGB,
            GL_SOURCE0_RGB,
            GL_OPERAND1_ALPHA,
            GL_RGB_SCALE,
        ] {
            f = [0.0; 16];
            gl.get_tex_envfv(GL_TEXTURE_ENV, p, &mut f);
            push(
                40_000 + unit * 1000 + p,
                f.iter().map(|&v| v as f64).collect(),
            );
        }
        for target in [
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
                GL_TEXTURE_BORDER_COLOR,
                GL_TEXTURE_PRIORITY,
                GL_TEXTURE_MAX_LEVEL,
                GL_TEXTURE_MIN_LOD,
                GL_GENERATE_MIPMAP,
            ] {
                f = [0.0; 16];
                gl.get_tex_parameterfv(target, p, &mut f);
                push(
                    50_000 + unit * 1000 + target + p,
                    f.iter().map(|&v| v as f64).collect(),
                );
            }
        }
    }
    gl.active_texture(active[0] as u32);
    for p in 0..6 {
        gl.get_clip_plane(GL_CLIP_PLANE0 + p, &mut d);
        push(60_000 + p, d.to_vec());
    }
    let mut stipple = [0u8; 128];
    gl.get_polygon_stipple(&mut stipple);
    push(70_000, stipple.iter().map(|&v| v as f64).collect());
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    out
}

/// Changes state of every attribute group.
fn change_everything(gl: &mut Context) {
    // current
    gl.color_4f(0.1, 0.2, 0.3, 0.4);
    gl.secondary_color_3f(0.5, 0.6, 0.7);
    gl.normal_3f(0.0, 1.0, 0.0);
    gl.multi_tex_coord_4f(GL_TEXTURE2, 1.0, 2.0, 3.0, 4.0);
    gl.fog_coordf(3.0);
    gl.edge_flag(0);
    gl.raster_pos_2f(0.25, -0.5);
    // point, line, polygon, stipple
    gl.point_size(4.0);
    gl.point_parameterf(GL_POINT_SIZE_MIN, 2.0);
    gl.point_parameterfv(GL_POINT_DISTANCE_ATTENUATION, &[1.0, 0.5, 0.25]);
    gl.line_width(3.0);
    gl.line_stipple(3, 0xF0F0);
    gl.cull_face(GL_FRONT);
    gl.front_face(GL_CW);
    gl.polygon_mode(GL_FRONT, GL_LINE);
    gl.polygon_offset(2.0, 3.0);
    gl.polygon_stipple(&[0x5Au8; 128]);
    // pixel mode
    gl.pixel_transferf(GL_RED_SCALE, 2.0);
    gl.pixel_transferf(GL_DEPTH_BIAS, 0.25);
    gl.pixel_transferi(GL_MAP_COLOR, 1);
    gl.pixel_zoom(2.0, -1.0);
    // lighting
    gl.lightfv(GL_LIGHT3, GL_DIFFUSE, &[0.2, 0.3, 0.4, 0.5]);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[1.0, 2.0, 3.0, 0.0]);
    gl.lightf(GL_LIGHT1, GL_SPOT_CUTOFF, 30.0);
    gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    gl.light_modeli(
        GL_LIGHT_MODEL_COLOR_CONTROL,
        GL_SEPARATE_SPECULAR_COLOR as i32,
    );
    gl.materialfv(GL_BACK, GL_EMISSION, &[0.1, 0.1, 0.2, 1.0]);
    gl.materialf(GL_FRONT, GL_SHININESS, 20.0);
    gl.color_material(GL_BACK, GL_SPECULAR);
    gl.shade_model(GL_FLAT);
    gl.provoking_vertex_ext(GL_FIRST_VERTEX_CONVENTION_EXT);
    // fog
    gl.fogi(GL_FOG_MODE, GL_EXP2 as i32);
    gl.fogf(GL_FOG_DENSITY, 0.5);
    gl.fogfv(GL_FOG_COLOR, &[0.3, 0.2, 0.1, 0.0]);
    gl.fogi(GL_FOG_COORD_SRC, GL_FOG_COORD as i32);
    // depth, accum, stencil
    gl.depth_func(GL_GEQUAL);
    gl.depth_mask(0);
    gl.clear_depth(0.25);
    gl.clear_accum(0.5, -0.5, 0.25, 1.0);
    gl.stencil_func(GL_NOTEQUAL, 3, 0x0F);
    gl.stencil_op(GL_INCR, GL_DECR, GL_INVERT);
    gl.stencil_mask(0x33);
    gl.clear_stencil(7);
    // viewport, transform
    gl.viewport(3, 4, 50, 60);
    gl.depth_range(0.2, 0.7);
    gl.matrix_mode(GL_TEXTURE);
    gl.clip_plane(GL_CLIP_PLANE2, &[1.0, 2.0, 3.0, 4.0]);
    // enables
    for cap in [
        GL_ALPHA_TEST,
        GL_BLEND,
        GL_CLIP_PLANE2,
        GL_COLOR_MATERIAL,
        GL_CULL_FACE,
        GL_DEPTH_TEST,
        GL_FOG,
        GL_LIGHT5,
        GL_LIGHTING,
        GL_LINE_SMOOTH,
        GL_LINE_STIPPLE,
        GL_COLOR_LOGIC_OP,
        GL_NORMALIZE,
        GL_POINT_SMOOTH,
        GL_POLYGON_OFFSET_LINE,
        GL_POLYGON_SMOOTH,
        GL_POLYGON_STIPPLE,
        GL_RESCALE_NORMAL,
        GL_SCISSOR_TEST,
        GL_STENCIL_TEST,
        GL_TEXTURE_2D,
        GL_TEXTURE_GEN_T,
        GL_COLOR_SUM,
        GL_SAMPLE_ALPHA_TO_COVERAGE,
        GL_SAMPLE_COVERAGE,
    ] {
        gl.enable(cap);
    }
    gl.disable(GL_DITHER);
    gl.disable(GL_MULTISAMPLE);
    // colour buffer
    gl.alpha_func(GL_GREATER, 0.5);
    gl.blend_func_separate(GL_SRC_ALPHA, GL_ONE, GL_ZERO, GL_DST_COLOR);
    gl.blend_equation_separate_ext(GL_FUNC_SUBTRACT, GL_MAX);
    gl.blend_color(0.1, 0.2, 0.3, 0.4);
    gl.logic_op(GL_XOR);
    gl.clear_color(0.9, 0.8, 0.7, 0.6);
    gl.color_mask(1, 0, 1, 0);
    gl.draw_buffer(GL_NONE);
    // hints, list
    gl.hint(GL_FOG_HINT, GL_NICEST);
    gl.hint(GL_PERSPECTIVE_CORRECTION_HINT, GL_FASTEST);
    gl.list_base(42);
    // texture: a unit, its bindings, generation, environment and parameters
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameterfv(
        GL_TEXTURE_2D,
        GL_TEXTURE_BORDER_COLOR,
        &[0.5, 0.5, 0.0, 1.0],
    );
    gl.active_texture(GL_TEXTURE1);
    gl.bind_texture(GL_TEXTURE_2D, 9);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
    gl.enable(GL_TEXTURE_CUBE_MAP);
    gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.tex_genfv(GL_T, GL_EYE_PLANE, &[0.0, 0.5, 0.0, 1.0]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGB as i32);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.2, 0.4, 0.6, 0.8]);
    // evaluators: enables and grids (the maps themselves are in no group)
    gl.enable(GL_MAP1_VERTEX_3);
    gl.enable(GL_MAP2_TEXTURE_COORD_2);
    gl.enable(GL_AUTO_NORMAL);
    gl.map_grid_1d(7, 0.25, 0.75);
    gl.map_grid_2f(3, 0.0, 2.0, 5, -1.0, 1.0);
    // scissor, multisample
    gl.scissor(1, 2, 3, 4);
    gl.sample_coverage(0.5, 1);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

fn integer(gl: &mut Context, pname: GLenum) -> i32 {
    let mut v = [0i32; 16];
    gl.get_integerv(pname, &mut v);
    v[0]
}

fn float(gl: &mut Context, pname: GLenum) -> f32 {
    let mut v = [0f32; 16];
    gl.get_floatv(pname, &mut v);
    v[0]
}

#[test]
fn all_attrib_bits_restores_every_queryable_value() {
    let mut gl = Context::new(64, 64);
    // Start from non-default state too, so that restoring defaults is not enough.
    gl.bind_texture(GL_TEXTURE_2D, 5);
    gl.line_width(2.0);
    let before = deep_state(&mut gl);
    gl.push_attrib(GL_ALL_ATTRIB_BITS);
    assert_eq!(integer(&mut gl, GL_ATTRIB_STACK_DEPTH), 1);
    change_everything(&mut gl);
    assert_ne!(deep_state(&mut gl), before);
    gl.pop_attrib();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let after = deep_state(&mut gl);
    for (a, b) in before.iter().zip(&after) {
        assert_eq!(
            a,
            b,
            "{} differs after the pop",
            tilegl::enums::enum_name(a.0).unwrap_or("?")
        );
    }
    assert_eq!(before, after);
}

#[test]
fn the_union_of_all_groups_equals_all_attrib_bits() {
    let groups = [
        GL_CURRENT_BIT,
        GL_POINT_BIT,
        GL_LINE_BIT,
        GL_POLYGON_BIT,
        GL_POLYGON_STIPPLE_BIT,
        GL_PIXEL_MODE_BIT,
        GL_LIGHTING_BIT,
        GL_FOG_BIT,
        GL_DEPTH_BUFFER_BIT,
        GL_ACCUM_BUFFER_BIT,
        GL_STENCIL_BUFFER_BIT,
        GL_VIEWPORT_BIT,
        GL_TRANSFORM_BIT,
        GL_ENABLE_BIT,
        GL_COLOR_BUFFER_BIT,
        GL_HINT_BIT,
        GL_EVAL_BIT,
        GL_LIST_BIT,
        GL_TEXTURE_BIT,
        GL_SCISSOR_BIT,
        GL_MULTISAMPLE_BIT,
    ];
    let mut gl = Context::new(64, 64);
    let before = deep_state(&mut gl);
    // One entry per group, popped in reverse: the whole state comes back.
    for &g in &groups {
        gl.push_attrib(g);
    }
    assert_eq!(
        gl.get_error(),
        GL_STACK_OVERFLOW,
        "21 groups exceed a depth of 16"
    );
    let mut gl = Context::new(64, 64);
    gl.push_attrib(groups[..16].iter().fold(0, |m, g| m | g));
    gl.push_attrib(groups[16..].iter().fold(0, |m, g| m | g));
    change_everything(&mut gl);
    gl.pop_attrib();
    gl.pop_attrib();
    assert_eq!(deep_state(&mut gl), before);
}

#[test]
fn a_group_restores_its_own_state_only() {
    let mut gl = Context::new(64, 64);
    gl.push_attrib(GL_LINE_BIT);
    gl.line_width(5.0);
    gl.enable(GL_LINE_STIPPLE);
    gl.point_size(6.0);
    gl.enable(GL_POINT_SMOOTH);
    gl.pop_attrib();
    assert_eq!(float(&mut gl, GL_LINE_WIDTH), 1.0);
    assert_eq!(gl.is_enabled(GL_LINE_STIPPLE), 0);
    assert_eq!(
        float(&mut gl, GL_POINT_SIZE),
        6.0,
        "point state is not in GL_LINE_BIT"
    );
    assert_eq!(gl.is_enabled(GL_POINT_SMOOTH), 1);

    // GL_ENABLE_BIT restores enables but not the values they enable.
    gl.push_attrib(GL_ENABLE_BIT);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_ONE, GL_ONE);
    gl.enable(GL_LIGHT7);
    gl.enable(GL_TEXTURE_3D);
    gl.disable(GL_MULTISAMPLE);
    gl.pop_attrib();
    assert_eq!(gl.is_enabled(GL_BLEND), 0);
    assert_eq!(gl.is_enabled(GL_LIGHT7), 0);
    assert_eq!(gl.is_enabled(GL_TEXTURE_3D), 0);
    assert_eq!(gl.is_enabled(GL_MULTISAMPLE), 1);
    assert_eq!(integer(&mut gl, GL_BLEND_DST_RGB), GL_ONE as i32);

    // GL_COLOR_BUFFER_BIT holds the blend enable too, but not the depth test.
    gl.push_attrib(GL_COLOR_BUFFER_BIT);
    gl.enable(GL_BLEND);
    gl.enable(GL_DEPTH_TEST);
    gl.pop_attrib();
    assert_eq!(gl.is_enabled(GL_BLEND), 0);
    assert_eq!(gl.is_enabled(GL_DEPTH_TEST), 1);

    // The colour sum enable is in the fog group, not the lighting group.
    gl.push_attrib(GL_LIGHTING_BIT);
    gl.enable(GL_COLOR_SUM);
    gl.shade_model(GL_FLAT);
    gl.provoking_vertex_ext(GL_FIRST_VERTEX_CONVENTION_EXT);
    gl.pop_attrib();
    assert_eq!(gl.is_enabled(GL_COLOR_SUM), 1);
    assert_eq!(integer(&mut gl, GL_SHADE_MODEL), GL_SMOOTH as i32);
    // EXT_provoking_vertex's state table puts the convention in the lighting group (Mesa 22
    // keeps it out of every group).
    assert_eq!(
        integer(&mut gl, GL_PROVOKING_VERTEX_EXT),
        GL_LAST_VERTEX_CONVENTION_EXT as i32
    );
    for other in [
        GL_POLYGON_BIT,
        GL_TRANSFORM_BIT,
        GL_ENABLE_BIT,
        GL_CURRENT_BIT,
    ] {
        gl.push_attrib(other);
        gl.provoking_vertex_ext(GL_FIRST_VERTEX_CONVENTION_EXT);
        gl.pop_attrib();
        assert_eq!(
            integer(&mut gl, GL_PROVOKING_VERTEX_EXT),
            GL_FIRST_VERTEX_CONVENTION_EXT as i32,
            "group {other:#x} does not hold the convention"
        );
        gl.provoking_vertex_ext(GL_LAST_VERTEX_CONVENTION_EXT);
    }
    gl.push_attrib(GL_FOG_BIT);
    gl.disable(GL_COLOR_SUM);
    gl.pop_attrib();
    assert_eq!(gl.is_enabled(GL_COLOR_SUM), 1);

    // Matrices and pixel maps belong to no group.
    gl.push_attrib(GL_ALL_ATTRIB_BITS);
    gl.translatef(1.0, 2.0, 3.0);
    gl.pixel_mapfv(GL_PIXEL_MAP_R_TO_R, 2, &[1.0, 0.0]);
    gl.pop_attrib();
    let mut m = [0f32; 16];
    gl.get_floatv(GL_MODELVIEW_MATRIX, &mut m);
    assert_eq!(m[12..15], [1.0, 2.0, 3.0]);
    assert_eq!(integer(&mut gl, GL_PIXEL_MAP_R_TO_R_SIZE), 2);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn texture_bit_restores_bindings_and_the_bound_objects_parameters() {
    let mut gl = Context::new(64, 64);
    gl.bind_texture(GL_TEXTURE_2D, 5);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.bind_texture(GL_TEXTURE_2D, 6);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.bind_texture(GL_TEXTURE_2D, 5);
    gl.push_attrib(GL_TEXTURE_BIT);
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
    gl.bind_texture(GL_TEXTURE_2D, 6);
    // Texture 6 was not bound at the push: its change survives.
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_NEAREST_MIPMAP_NEAREST as i32,
    );
    gl.active_texture(GL_TEXTURE3);
    gl.pop_attrib();
    assert_eq!(integer(&mut gl, GL_ACTIVE_TEXTURE), GL_TEXTURE0 as i32);
    assert_eq!(integer(&mut gl, GL_TEXTURE_BINDING_2D), 5);
    let mut v = [0i32];
    gl.get_tex_parameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &mut v);
    assert_eq!(v[0], GL_LINEAR as i32);
    gl.bind_texture(GL_TEXTURE_2D, 6);
    gl.get_tex_parameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &mut v);
    assert_eq!(v[0], GL_NEAREST_MIPMAP_NEAREST as i32);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn stack_depth_overflow_and_underflow() {
    let mut gl = Context::new(16, 16);
    assert_eq!(integer(&mut gl, GL_ATTRIB_STACK_DEPTH), 0);
    let max = integer(&mut gl, GL_MAX_ATTRIB_STACK_DEPTH);
    assert!(max >= 16);
    gl.pop_attrib();
    assert_eq!(gl.get_error(), GL_STACK_UNDERFLOW);
    for i in 0..max {
        gl.line_width(1.0 + i as f32);
        gl.push_attrib(GL_LINE_BIT);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }
    assert_eq!(integer(&mut gl, GL_ATTRIB_STACK_DEPTH), max);
    gl.line_width(40.0);
    gl.push_attrib(GL_LINE_BIT);
    assert_eq!(gl.get_error(), GL_STACK_OVERFLOW);
    assert_eq!(integer(&mut gl, GL_ATTRIB_STACK_DEPTH), max);
    for i in (0..max).rev() {
        gl.pop_attrib();
        assert_eq!(float(&mut gl, GL_LINE_WIDTH), 1.0 + i as f32);
    }
    gl.pop_attrib();
    assert_eq!(gl.get_error(), GL_STACK_UNDERFLOW);
    // Illegal between glBegin and glEnd.
    gl.begin(GL_POINTS);
    gl.push_attrib(GL_ALL_ATTRIB_BITS);
    gl.end();
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    assert_eq!(integer(&mut gl, GL_ATTRIB_STACK_DEPTH), 0);
}

#[test]
fn push_and_pop_compile_into_display_lists() {
    let mut gl = Context::new(16, 16);
    gl.new_list(1, GL_COMPILE);
    gl.push_attrib(GL_POINT_BIT);
    gl.point_size(7.0);
    gl.end_list();
    gl.new_list(2, GL_COMPILE);
    gl.pop_attrib();
    gl.end_list();
    assert_eq!(integer(&mut gl, GL_ATTRIB_STACK_DEPTH), 0);
    gl.call_list(1);
    assert_eq!(float(&mut gl, GL_POINT_SIZE), 7.0);
    gl.call_list(2);
    assert_eq!(float(&mut gl, GL_POINT_SIZE), 1.0);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn multisample_state_without_multisample_buffers() {
    let mut gl = Context::new(16, 16);
    assert_eq!(integer(&mut gl, GL_SAMPLE_BUFFERS), 0);
    assert_eq!(integer(&mut gl, GL_SAMPLES), 0);
    assert_eq!(gl.is_enabled(GL_MULTISAMPLE), 1);
    for cap in [
        GL_SAMPLE_ALPHA_TO_COVERAGE,
        GL_SAMPLE_ALPHA_TO_ONE,
        GL_SAMPLE_COVERAGE,
    ] {
        assert_eq!(gl.is_enabled(cap), 0);
        gl.enable(cap);
        assert_eq!(gl.is_enabled(cap), 1);
    }
    assert_eq!(float(&mut gl, GL_SAMPLE_COVERAGE_VALUE), 1.0);
    let mut b = [1u8];
    gl.get_booleanv(GL_SAMPLE_COVERAGE_INVERT, &mut b);
    assert_eq!(b[0], 0);
    gl.push_attrib(GL_MULTISAMPLE_BIT);
    // The value is clamped to [0, 1].
    gl.sample_coverage(1.5, 1);
    assert_eq!(float(&mut gl, GL_SAMPLE_COVERAGE_VALUE), 1.0);
    gl.sample_coverage(-0.25, 1);
    assert_eq!(float(&mut gl, GL_SAMPLE_COVERAGE_VALUE), 0.0);
    gl.get_booleanv(GL_SAMPLE_COVERAGE_INVERT, &mut b);
    assert_eq!(b[0], 1);
    gl.disable(GL_SAMPLE_COVERAGE);
    gl.pop_attrib();
    assert_eq!(float(&mut gl, GL_SAMPLE_COVERAGE_VALUE), 1.0);
    assert_eq!(gl.is_enabled(GL_SAMPLE_COVERAGE), 1);
    // No multisample buffer: the coverage state changes no pixel.
    let draw = |gl: &mut Context| {
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.color_4f(1.0, 0.5, 0.25, 0.5);
        gl.rectf(-0.5, -0.5, 0.5, 0.5);
        common::read_rgba(gl)
    };
    gl.sample_coverage(0.25, 1);
    let with = draw(&mut gl);
    for cap in [
        GL_SAMPLE_ALPHA_TO_COVERAGE,
        GL_SAMPLE_ALPHA_TO_ONE,
        GL_SAMPLE_COVERAGE,
    ] {
        gl.disable(cap);
    }
    assert_eq!(draw(&mut gl), with);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn popping_the_draw_buffer_sends_earlier_work_to_the_buffer_it_was_drawn_for() {
    let mut gl = Context::with_config(tilegl::ContextConfig {
        width: 16,
        height: 16,
        framebuffer: tilegl::FramebufferConfig {
            double_buffer: true,
            ..tilegl::FramebufferConfig::default()
        },
        threads: 1,
    });
    assert_eq!(integer(&mut gl, GL_DRAW_BUFFER), GL_BACK as i32);
    gl.push_attrib(GL_COLOR_BUFFER_BIT);
    gl.draw_buffer(GL_FRONT);
    gl.color_3f(1.0, 0.0, 0.0);
    gl.rectf(-1.0, -1.0, 1.0, 1.0);
    gl.pop_attrib();
    assert_eq!(integer(&mut gl, GL_DRAW_BUFFER), GL_BACK as i32);
    gl.read_buffer(GL_FRONT);
    assert_eq!(common::pixel(&mut gl, 8, 8), [255, 0, 0, 255]);
    gl.read_buffer(GL_BACK);
    assert_eq!(common::pixel(&mut gl, 8, 8), [0, 0, 0, 0]);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

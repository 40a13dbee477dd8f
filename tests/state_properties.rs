//! Property tests of the GL state machine (proptest), over random sequences of state calls:
//! - an erroneous call records its error and changes nothing else (every `glGet` value equal);
//! - `glPushAttrib(GL_ALL_ATTRIB_BITS)`, any changes, `glPopAttrib` restores every value;
//! - a display list of calls, called, gives the state and picture the calls give directly.

use proptest::prelude::*;
use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::{Context, Gl};

mod common;
use common::{read_rgba, state_fingerprint};

/// One state-setting call with valid arguments.
#[derive(Clone, Debug)]
enum Op {
    Enable(GLenum, bool),
    DepthFunc(GLenum),
    BlendFunc(GLenum, GLenum),
    ColorMask([bool; 4]),
    DepthMask(bool),
    ClearColor([f32; 4]),
    Color([f32; 4]),
    LineWidth(f32),
    PointSize(f32),
    FogMode(GLenum),
    FogDensity(f32),
    Light(u32, GLenum, [f32; 4]),
    Material(GLenum, [f32; 4]),
    Translate([f32; 3]),
    Rotate(f32),
    MatrixMode(GLenum),
    ShadeModel(GLenum),
    CullFace(GLenum),
    PolygonMode(GLenum, GLenum),
    Scissor(i32, i32, i32, i32),
    StencilFunc(GLenum, i32, u32),
    StencilOps(GLenum, GLenum, GLenum),
    AlphaFunc(GLenum, f32),
    TexEnvMode(GLenum),
    Hint(GLenum, GLenum),
    Triangle([f32; 6]),
}

const CAPS: [GLenum; 10] = [
    GL_DEPTH_TEST,
    GL_BLEND,
    GL_LIGHTING,
    GL_LIGHT0,
    GL_LIGHT1,
    GL_FOG,
    GL_CULL_FACE,
    GL_SCISSOR_TEST,
    GL_STENCIL_TEST,
    GL_ALPHA_TEST,
];
const FUNCS: [GLenum; 8] = [
    GL_NEVER,
    GL_LESS,
    GL_EQUAL,
    GL_LEQUAL,
    GL_GREATER,
    GL_NOTEQUAL,
    GL_GEQUAL,
    GL_ALWAYS,
];
const FACTORS: [GLenum; 6] = [
    GL_ZERO,
    GL_ONE,
    GL_SRC_ALPHA,
    GL_ONE_MINUS_SRC_ALPHA,
    GL_DST_COLOR,
    GL_SRC_ALPHA_SATURATE,
];
const STENCIL_OPS: [GLenum; 6] = [GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT];

fn pick<T: Copy + std::fmt::Debug + 'static>(v: &'static [T]) -> impl Strategy<Value = T> {
    (0..v.len()).prop_map(move |i| v[i])
}

fn unit() -> impl Strategy<Value = f32> {
    0.0f32..1.0
}

fn op() -> impl Strategy<Value = Op> {
    prop_oneof![
        (pick(&CAPS), any::<bool>()).prop_map(|(c, on)| Op::Enable(c, on)),
        pick(&FUNCS).prop_map(Op::DepthFunc),
        (pick(&FACTORS), pick(&FACTORS[..4])).prop_map(|(s, d)| Op::BlendFunc(s, d)),
        any::<[bool; 4]>().prop_map(Op::ColorMask),
        any::<bool>().prop_map(Op::DepthMask),
        [unit(), unit(), unit(), unit()].prop_map(Op::ClearColor),
        [unit(), unit(), unit(), unit()].prop_map(Op::Color),
        (0.5f32..8.0).prop_map(Op::LineWidth),
        (0.5f32..8.0).prop_map(Op::PointSize),
        pick(&[GL_LINEAR, GL_EXP, GL_EXP2]).prop_map(Op::FogMode),
        (0.0f32..4.0).prop_map(Op::FogDensity),
        (
            0u32..2,
            pick(&[GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION]),
            [unit(), unit(), unit(), unit()]
        )
            .prop_map(|(l, p, v)| Op::Light(l, p, v)),
        (
            pick(&[GL_AMBIENT, GL_DIFFUSE, GL_EMISSION]),
            [unit(), unit(), unit(), unit()]
        )
            .prop_map(|(p, v)| Op::Material(p, v)),
        [-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0].prop_map(Op::Translate),
        (-180.0f32..180.0).prop_map(Op::Rotate),
        pick(&[GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE]).prop_map(Op::MatrixMode),
        pick(&[GL_FLAT, GL_SMOOTH]).prop_map(Op::ShadeModel),
        pick(&[GL_FRONT, GL_BACK, GL_FRONT_AND_BACK]).prop_map(Op::CullFace),
        (
            pick(&[GL_FRONT, GL_BACK, GL_FRONT_AND_BACK]),
            pick(&[GL_POINT, GL_LINE, GL_FILL])
        )
            .prop_map(|(f, m)| Op::PolygonMode(f, m)),
        (0i32..16, 0i32..16, 1i32..32, 1i32..32).prop_map(|(x, y, w, h)| Op::Scissor(x, y, w, h)),
        (pick(&FUNCS), 0i32..255, any::<u32>()).prop_map(|(f, r, m)| Op::StencilFunc(f, r, m)),
        (pick(&STENCIL_OPS), pick(&STENCIL_OPS), pick(&STENCIL_OPS))
            .prop_map(|(a, b, c)| Op::StencilOps(a, b, c)),
        (pick(&FUNCS), unit()).prop_map(|(f, r)| Op::AlphaFunc(f, r)),
        pick(&[GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD]).prop_map(Op::TexEnvMode),
        (
            pick(&[
                GL_FOG_HINT,
                GL_LINE_SMOOTH_HINT,
                GL_PERSPECTIVE_CORRECTION_HINT
            ]),
            pick(&[GL_FASTEST, GL_NICEST, GL_DONT_CARE])
        )
            .prop_map(|(t, m)| Op::Hint(t, m)),
        [
            -1.0f32..1.0,
            -1.0f32..1.0,
            -1.0f32..1.0,
            -1.0f32..1.0,
            -1.0f32..1.0,
            -1.0f32..1.0
        ]
        .prop_map(Op::Triangle),
    ]
}

fn apply(gl: &mut dyn Gl, op: &Op) {
    match *op {
        Op::Enable(c, true) => gl.enable(c),
        Op::Enable(c, false) => gl.disable(c),
        Op::DepthFunc(f) => gl.depth_func(f),
        Op::BlendFunc(s, d) => gl.blend_func(s, d),
        Op::ColorMask(m) => gl.color_mask(m[0] as u8, m[1] as u8, m[2] as u8, m[3] as u8),
        Op::DepthMask(m) => gl.depth_mask(m as u8),
        Op::ClearColor(c) => gl.clear_color(c[0], c[1], c[2], c[3]),
        Op::Color(c) => gl.color_4f(c[0], c[1], c[2], c[3]),
        Op::LineWidth(w) => gl.line_width(w),
        Op::PointSize(s) => gl.point_size(s),
        Op::FogMode(m) => gl.fogi(GL_FOG_MODE, m as i32),
        Op::FogDensity(d) => gl.fogf(GL_FOG_DENSITY, d),
        Op::Light(l, p, v) => gl.lightfv(GL_LIGHT0 + l, p, &v),
        Op::Material(p, v) => gl.materialfv(GL_FRONT_AND_BACK, p, &v),
        Op::Translate(t) => gl.translatef(t[0], t[1], t[2]),
        Op::Rotate(a) => gl.rotatef(a, 0.3, 0.5, 0.8),
        Op::MatrixMode(m) => gl.matrix_mode(m),
        Op::ShadeModel(m) => gl.shade_model(m),
        Op::CullFace(f) => gl.cull_face(f),
        Op::PolygonMode(f, m) => gl.polygon_mode(f, m),
        Op::Scissor(x, y, w, h) => gl.scissor(x, y, w, h),
        Op::StencilFunc(f, r, m) => gl.stencil_func(f, r, m),
        Op::StencilOps(a, b, c) => gl.stencil_op(a, b, c),
        Op::AlphaFunc(f, r) => gl.alpha_func(f, r),
        Op::TexEnvMode(m) => gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, m as i32),
        Op::Hint(t, m) => gl.hint(t, m),
        Op::Triangle(v) => {
            gl.begin(GL_TRIANGLES);
            gl.normal_3f(0.0, 0.0, 1.0);
            gl.vertex_2f(v[0], v[1]);
            gl.vertex_2f(v[2], v[3]);
            gl.vertex_2f(v[4], v[5]);
            gl.end();
        }
    }
}

/// Calls with an invalid argument: each must record its error and change nothing.
fn bad_call(gl: &mut dyn Gl, i: usize) -> GLenum {
    match i {
        0 => {
            gl.depth_func(0x1234);
            GL_INVALID_ENUM
        }
        1 => {
            gl.blend_func(GL_SRC_ALPHA, 0x1234);
            GL_INVALID_ENUM
        }
        2 => {
            gl.line_width(-1.0);
            GL_INVALID_VALUE
        }
        3 => {
            gl.enable(0x1234);
            GL_INVALID_ENUM
        }
        4 => {
            gl.scissor(0, 0, -1, 4);
            GL_INVALID_VALUE
        }
        5 => {
            gl.stencil_op(GL_KEEP, 0x1234, GL_KEEP);
            GL_INVALID_ENUM
        }
        6 => {
            gl.polygon_mode(GL_FRONT, 0x1234);
            GL_INVALID_ENUM
        }
        7 => {
            gl.matrix_mode(0x1234);
            GL_INVALID_ENUM
        }
        8 => {
            gl.lightfv(GL_LIGHT0, GL_SPOT_CUTOFF, &[120.0, 0.0, 0.0, 0.0]);
            GL_INVALID_VALUE
        }
        9 => {
            gl.point_size(0.0);
            GL_INVALID_VALUE
        }
        10 => {
            gl.fogi(GL_FOG_MODE, 0x1234);
            GL_INVALID_ENUM
        }
        _ => {
            gl.pop_attrib(); // nothing pushed
            GL_STACK_UNDERFLOW
        }
    }
}

fn context() -> Context {
    let mut gl = common::threaded_context(32, 32, 1);
    gl.matrix_mode(GL_MODELVIEW);
    gl
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    #[test]
    fn an_erroneous_call_changes_nothing_but_the_error(ops in prop::collection::vec(op(), 0..24), bad in 0usize..12) {
        let mut gl = context();
        for o in &ops {
            apply(&mut gl, o);
        }
        prop_assert_eq!(gl.get_error(), GL_NO_ERROR);
        let before = state_fingerprint(&mut gl);
        let expected = bad_call(&mut gl, bad);
        prop_assert_eq!(gl.get_error(), expected);
        prop_assert!(state_fingerprint(&mut gl) == before, "call {} changed state", bad);
    }

    #[test]
    fn push_and_pop_attrib_restore_every_value(before_ops in prop::collection::vec(op(), 0..12), ops in prop::collection::vec(op(), 1..24)) {
        let mut gl = context();
        for o in &before_ops {
            apply(&mut gl, o);
        }
        let before = state_fingerprint(&mut gl);
        gl.push_attrib(GL_ALL_ATTRIB_BITS);
        // Matrices belong to no attribute group (their stacks are their own): left out.
        for o in ops.iter().filter(|o| !matches!(o, Op::Translate(_) | Op::Rotate(_))) {
            apply(&mut gl, o);
        }
        gl.pop_attrib();
        prop_assert_eq!(gl.get_error(), GL_NO_ERROR);
        let after = state_fingerprint(&mut gl);
        let differing: Vec<_> = before.iter().zip(&after).filter(|(a, b)| a != b).map(|(a, _)| a.0).collect();
        prop_assert!(before.len() == after.len() && differing.is_empty(), "differ: {:x?}", differing);
    }

    #[test]
    fn a_display_list_replays_like_its_calls(ops in prop::collection::vec(op(), 1..32)) {
        let mut direct = context();
        direct.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        for o in &ops {
            apply(&mut direct, o);
        }
        let mut listed = context();
        listed.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        let list = listed.gen_lists(1);
        listed.new_list(list, GL_COMPILE);
        for o in &ops {
            apply(&mut listed, o);
        }
        listed.end_list();
        listed.call_list(list);
        prop_assert_eq!(direct.get_error(), listed.get_error());
        direct.finish();
        listed.finish();
        prop_assert!(read_rgba(&mut direct) == read_rgba(&mut listed), "pictures differ");
        // The list's own state (GL_LIST_INDEX etc.) aside, every value is the same.
        let (a, b) = (state_fingerprint(&mut direct), state_fingerprint(&mut listed));
        let differing: Vec<_> = a.iter().zip(&b).filter(|(x, y)| x != y && x.0 != GL_LIST_INDEX && x.0 != GL_LIST_BASE).map(|(x, _)| x.0).collect();
        prop_assert!(differing.is_empty(), "state differs: {:x?}", differing);
    }
}

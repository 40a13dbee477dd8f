//! State queries, matrices and the errors of bad enums, values, begin/end and stack limits,
//! answer by answer against Mesa: floats to 1e-5 relative, integer queries of normalised values
//! to one unit, everything else exactly.

use tilegl::enums::*;
use tilegl::Gl;

use scripts::*;

super::state_case_list!(source = include_str!("basic.rs"), agree = |(_, a): &(String, Answer), (_, b)| agree(a, b);
    state_defaults: "The initial values of the state tables (chapter 6): viewport and scissor box the window (0 0 64 64), depth LESS, cull BACK, front CCW, shading SMOOTH, MODELVIEW mode at stack depth 1, identity matrices, depth range [0, 1], clear colour 0, clear depth 1, write masks all true, every capability off, current colour (1, 1, 1, 1); no error.",
    state_viewport_depth_range: "Section 2.11.1: the viewport as given (negative x allowed), in integer and float queries; glDepthRange clamps both values to [0, 1] and allows reversed ranges; no error.",
    state_matrices: "Section 2.11.2: glFrustum, glOrtho, glTranslate, glRotate, glScale, glLoadTransposeMatrix, glMultMatrix and glMultTransposeMatrix build the products of their equations (column-major; transpose queries give the transpose); float and double queries agree to 1e-5.",
    state_matrix_stacks: "Section 2.11.2: glPushMatrix copies the top, glPopMatrix restores it; each mode has its own stack and depth.",
    state_fragment_ops: "Sections 4.1, 4.2 and 6.1: each value set reads back (glClearColor and glClearDepth clamp to [0, 1]); glIsEnabled and glGetBooleanv agree.",
    state_clip_planes: "Section 2.12: a clip plane is stored in eye coordinates, multiplied by the inverse of the modelview at the time of the call; unset planes are (0, 0, 0, 0).",
    state_type_conversions: "Section 6.1.2: colours and depth values map to the full integer range in integer queries; booleans are false exactly for 0; enums read as floats or doubles are the enum value.",
    errors_bad_enums: "Section 2.5: a bad enum records GL_INVALID_ENUM and has no other effect; the first error sticks until glGetError reads it, then GL_NO_ERROR.",
    errors_bad_values: "Section 2.5: negative sizes, a zero near plane, far < near and equal bounds record GL_INVALID_VALUE and change nothing.",
    errors_begin_end: "Section 2.6.3: state commands between glBegin and glEnd (and glEnd without glBegin, glBegin inside glBegin, glGetError inside) record GL_INVALID_OPERATION and are ignored; vertex and colour calls inside are legal.",
    state_provoking_vertex: "EXT_provoking_vertex: GL_PROVOKING_VERTEX_EXT starts as GL_LAST_VERTEX_CONVENTION_EXT and reads back what glProvokingVertexEXT set; GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION_EXT is implementation-dependent (false on both); another enum is GL_INVALID_ENUM and the call between glBegin and glEnd GL_INVALID_OPERATION, neither changing the convention; the call is compiled into display lists (executed by glCallList, not while compiling).",
    errors_stack_limits: "Section 2.11.2 and the implementation-dependent state table: pushing a full stack records GL_STACK_OVERFLOW, popping at depth 1 GL_STACK_UNDERFLOW, neither changes the matrix; stacks hold at least 32 modelview and 2 projection and texture matrices.",
);

/// One answer of a query, in the type it was asked in.
#[derive(Clone, Debug, PartialEq)]
pub enum Answer {
    Ints(Vec<i32>),
    Floats(Vec<f32>),
    Doubles(Vec<f64>),
    Bools(Vec<u8>),
    Error(GLenum),
}

#[derive(Clone, Copy)]
enum Q {
    I(GLenum, usize),
    F(GLenum, usize),
    D(GLenum, usize),
    B(GLenum, usize),
    Enabled(GLenum),
    ClipPlane(GLenum),
}

fn ask(gl: &mut dyn Gl, q: Q) -> (String, Answer) {
    match q {
        Q::I(p, n) => {
            let mut v = vec![0x5a5a_5a5a; n];
            gl.get_integerv(p, &mut v);
            (format!("get_integerv(0x{p:04x})"), Answer::Ints(v))
        }
        Q::F(p, n) => {
            let mut v = vec![-12345.0; n];
            gl.get_floatv(p, &mut v);
            (format!("get_floatv(0x{p:04x})"), Answer::Floats(v))
        }
        Q::D(p, n) => {
            let mut v = vec![-12345.0; n];
            gl.get_doublev(p, &mut v);
            (format!("get_doublev(0x{p:04x})"), Answer::Doubles(v))
        }
        Q::B(p, n) => {
            let mut v = vec![7u8; n];
            gl.get_booleanv(p, &mut v);
            (format!("get_booleanv(0x{p:04x})"), Answer::Bools(v))
        }
        Q::Enabled(c) => (
            format!("is_enabled(0x{c:04x})"),
            Answer::Bools(vec![gl.is_enabled(c)]),
        ),
        Q::ClipPlane(p) => {
            let mut v = [0.0; 4];
            gl.get_clip_plane(p, &mut v);
            (
                format!("get_clip_plane(0x{p:04x})"),
                Answer::Doubles(v.to_vec()),
            )
        }
    }
}

/// Floats agree to 1e-5 relative (matrix products may round differently); everything else
/// exactly, except integer queries of normalised values, which may differ by one.
fn agree(a: &Answer, b: &Answer) -> bool {
    let close = |x: f64, y: f64| (x - y).abs() <= 1e-5 * (1.0 + x.abs().max(y.abs()));
    match (a, b) {
        (Answer::Floats(x), Answer::Floats(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|(&p, &q)| close(p as f64, q as f64))
        }
        (Answer::Doubles(x), Answer::Doubles(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|(&p, &q)| close(p, q))
        }
        // Normalised values mapped to the full integer range keep the precision the
        // implementation stores them in (Mesa: f32), so allow a relative 1e-6.
        (Answer::Ints(x), Answer::Ints(y)) => {
            x.len() == y.len()
                && x.iter().zip(y).all(|(&p, &q)| {
                    let (p, q) = (p as f64, q as f64);
                    (p - q).abs() <= 1.0 + 1e-6 * p.abs().max(q.abs())
                })
        }
        _ => a == b,
    }
}

fn err(gl: &mut dyn Gl, out: &mut Vec<(String, Answer)>, label: &str) {
    let e = gl.get_error();
    out.push((format!("glGetError after {label}"), Answer::Error(e)));
}

fn queries(gl: &mut dyn Gl, out: &mut Vec<(String, Answer)>, qs: &[Q]) {
    for &q in qs {
        out.push(ask(gl, q));
    }
    err(gl, out, "queries");
}

mod scripts {
    use super::*;

    type Out = Vec<(String, Answer)>;

    pub fn state_defaults(gl: &mut dyn Gl, out: &mut Out) {
        queries(
            gl,
            out,
            &[
                Q::I(GL_VIEWPORT, 4),
                Q::I(GL_SCISSOR_BOX, 4),
                Q::I(GL_DEPTH_FUNC, 1),
                Q::I(GL_CULL_FACE_MODE, 1),
                Q::I(GL_FRONT_FACE, 1),
                Q::I(GL_SHADE_MODEL, 1),
                Q::I(GL_MATRIX_MODE, 1),
                Q::I(GL_MODELVIEW_STACK_DEPTH, 1),
                Q::I(GL_PROJECTION_STACK_DEPTH, 1),
                Q::F(GL_MODELVIEW_MATRIX, 16),
                Q::F(GL_PROJECTION_MATRIX, 16),
                Q::F(GL_DEPTH_RANGE, 2),
                Q::F(GL_COLOR_CLEAR_VALUE, 4),
                Q::F(GL_DEPTH_CLEAR_VALUE, 1),
                Q::B(GL_COLOR_WRITEMASK, 4),
                Q::B(GL_DEPTH_WRITEMASK, 1),
                Q::Enabled(GL_DEPTH_TEST),
                Q::Enabled(GL_CULL_FACE),
                Q::Enabled(GL_SCISSOR_TEST),
                Q::Enabled(GL_CLIP_PLANE0),
                Q::F(GL_CURRENT_COLOR, 4),
            ],
        );
    }

    pub fn state_viewport_depth_range(gl: &mut dyn Gl, out: &mut Out) {
        gl.viewport(-7, 5, 40, 23);
        gl.depth_range(0.25, 0.75);
        queries(
            gl,
            out,
            &[
                Q::I(GL_VIEWPORT, 4),
                Q::F(GL_VIEWPORT, 4),
                Q::F(GL_DEPTH_RANGE, 2),
                Q::D(GL_DEPTH_RANGE, 2),
            ],
        );
        // Depth range values are clamped to [0, 1]; reversed ranges are allowed.
        gl.depth_range(1.5, -0.5);
        err(gl, out, "depth_range(1.5, -0.5)");
        queries(gl, out, &[Q::F(GL_DEPTH_RANGE, 2)]);
        gl.depth_range(0.9, 0.1);
        queries(gl, out, &[Q::D(GL_DEPTH_RANGE, 2)]);
    }

    pub fn state_matrices(gl: &mut dyn Gl, out: &mut Out) {
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        gl.frustum(-1.0, 2.0, -0.5, 1.5, 0.75, 30.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        gl.translatef(1.0, -2.0, 3.0);
        gl.rotatef(33.0, 0.2, 0.9, -0.4);
        gl.scalef(1.5, -0.5, 2.0);
        queries(
            gl,
            out,
            &[
                Q::I(GL_MATRIX_MODE, 1),
                Q::F(GL_MODELVIEW_MATRIX, 16),
                Q::D(GL_MODELVIEW_MATRIX, 16),
                Q::F(GL_PROJECTION_MATRIX, 16),
                Q::F(GL_TRANSPOSE_MODELVIEW_MATRIX, 16),
                Q::D(GL_TRANSPOSE_PROJECTION_MATRIX, 16),
            ],
        );
        gl.load_transpose_matrixf(&[
            1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0, 16.0,
        ]);
        gl.mult_matrixd(&[
            0.5, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 1.0, 1.0,
        ]);
        gl.mult_transpose_matrixd(&[
            1.0, 0.0, 0.0, 3.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        ]);
        queries(gl, out, &[Q::F(GL_MODELVIEW_MATRIX, 16)]);
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        gl.ortho(-3.0, 5.0, -1.0, 7.0, -2.0, 9.0);
        gl.rotated(-70.0, 1.0, 0.0, 0.0);
        queries(
            gl,
            out,
            &[Q::F(GL_PROJECTION_MATRIX, 16), Q::I(GL_MATRIX_MODE, 1)],
        );
    }

    pub fn state_matrix_stacks(gl: &mut dyn Gl, out: &mut Out) {
        gl.matrix_mode(GL_MODELVIEW);
        gl.translatef(1.0, 2.0, 3.0);
        gl.push_matrix();
        gl.push_matrix();
        gl.scalef(2.0, 2.0, 2.0);
        queries(
            gl,
            out,
            &[
                Q::I(GL_MODELVIEW_STACK_DEPTH, 1),
                Q::F(GL_MODELVIEW_MATRIX, 16),
            ],
        );
        gl.pop_matrix();
        queries(
            gl,
            out,
            &[
                Q::I(GL_MODELVIEW_STACK_DEPTH, 1),
                Q::F(GL_MODELVIEW_MATRIX, 16),
            ],
        );
        gl.matrix_mode(GL_PROJECTION);
        gl.push_matrix();
        gl.ortho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
        queries(
            gl,
            out,
            &[
                Q::I(GL_PROJECTION_STACK_DEPTH, 1),
                Q::I(GL_MODELVIEW_STACK_DEPTH, 1),
                Q::F(GL_PROJECTION_MATRIX, 16),
            ],
        );
        gl.pop_matrix();
        gl.matrix_mode(GL_TEXTURE);
        gl.push_matrix();
        gl.translatef(0.5, 0.0, 0.0);
        queries(
            gl,
            out,
            &[
                Q::I(GL_TEXTURE_STACK_DEPTH, 1),
                Q::F(GL_TEXTURE_MATRIX, 16),
                Q::I(GL_MATRIX_MODE, 1),
            ],
        );
    }

    pub fn state_fragment_ops(gl: &mut dyn Gl, out: &mut Out) {
        gl.enable(GL_DEPTH_TEST);
        gl.depth_func(GL_GEQUAL);
        gl.depth_mask(0);
        gl.color_mask(1, 0, 1, 0);
        gl.enable(GL_SCISSOR_TEST);
        gl.scissor(3, 4, 50, 60);
        gl.enable(GL_CULL_FACE);
        gl.cull_face(GL_FRONT_AND_BACK);
        gl.front_face(GL_CW);
        gl.shade_model(GL_FLAT);
        gl.clear_color(0.25, -0.5, 1.5, 0.75);
        gl.clear_depth(0.125);
        gl.clear_stencil(5);
        queries(
            gl,
            out,
            &[
                Q::Enabled(GL_DEPTH_TEST),
                Q::I(GL_DEPTH_FUNC, 1),
                Q::B(GL_DEPTH_WRITEMASK, 1),
                Q::B(GL_COLOR_WRITEMASK, 4),
                Q::I(GL_COLOR_WRITEMASK, 4),
                Q::Enabled(GL_SCISSOR_TEST),
                Q::B(GL_SCISSOR_TEST, 1),
                Q::I(GL_SCISSOR_BOX, 4),
                Q::Enabled(GL_CULL_FACE),
                Q::I(GL_CULL_FACE_MODE, 1),
                Q::I(GL_FRONT_FACE, 1),
                Q::I(GL_SHADE_MODEL, 1),
                Q::F(GL_COLOR_CLEAR_VALUE, 4),
                Q::F(GL_DEPTH_CLEAR_VALUE, 1),
                Q::I(GL_STENCIL_CLEAR_VALUE, 1),
            ],
        );
        gl.disable(GL_DEPTH_TEST);
        gl.disable(GL_SCISSOR_TEST);
        queries(
            gl,
            out,
            &[Q::Enabled(GL_DEPTH_TEST), Q::B(GL_SCISSOR_TEST, 1)],
        );
    }

    pub fn state_clip_planes(gl: &mut dyn Gl, out: &mut Out) {
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        gl.translatef(1.0, 2.0, -3.0);
        gl.rotatef(45.0, 0.0, 0.0, 1.0);
        // Stored in eye coordinates: multiplied by the inverse of the modelview.
        gl.clip_plane(GL_CLIP_PLANE0, &[1.0, 0.0, 0.0, -0.5]);
        gl.scalef(2.0, 4.0, 1.0);
        gl.clip_plane(GL_CLIP_PLANE3, &[0.0, 1.0, 1.0, 2.0]);
        gl.enable(GL_CLIP_PLANE3);
        queries(
            gl,
            out,
            &[
                Q::ClipPlane(GL_CLIP_PLANE0),
                Q::ClipPlane(GL_CLIP_PLANE3),
                Q::ClipPlane(GL_CLIP_PLANE1),
                Q::Enabled(GL_CLIP_PLANE3),
                Q::Enabled(GL_CLIP_PLANE0),
                Q::B(GL_CLIP_PLANE3, 1),
            ],
        );
    }

    pub fn state_type_conversions(gl: &mut dyn Gl, out: &mut Out) {
        gl.clear_color(0.25, 0.5, 1.0, 0.0);
        gl.depth_range(0.2, 0.6);
        gl.translatef(0.4, 0.6, -1.5);
        queries(
            gl,
            out,
            &[
                // Colours and depth range map to the full integer range (table 4.9 / 6.1.2).
                Q::I(GL_COLOR_CLEAR_VALUE, 4),
                Q::I(GL_DEPTH_RANGE, 2),
                Q::I(GL_DEPTH_CLEAR_VALUE, 1),
                // (Integer queries of matrices are checked against the spec below: Mesa maps
                // them like colours instead of rounding.)
                Q::B(GL_MODELVIEW_MATRIX, 16),
                Q::B(GL_COLOR_CLEAR_VALUE, 4),
                Q::D(GL_DEPTH_FUNC, 1),
                Q::F(GL_DEPTH_WRITEMASK, 1),
                Q::D(GL_SCISSOR_BOX, 4),
            ],
        );
    }

    pub fn errors_bad_enums(gl: &mut dyn Gl, out: &mut Out) {
        err(gl, out, "nothing");
        gl.depth_func(0x1234);
        err(gl, out, "depth_func(bad)");
        queries(gl, out, &[Q::I(GL_DEPTH_FUNC, 1)]);
        gl.matrix_mode(GL_RGBA);
        err(gl, out, "matrix_mode(bad)");
        gl.enable(0x1234);
        err(gl, out, "enable(bad)");
        gl.disable(GL_RGBA);
        err(gl, out, "disable(bad)");
        gl.cull_face(GL_LINE);
        err(gl, out, "cull_face(GL_LINE)");
        gl.front_face(GL_FRONT);
        err(gl, out, "front_face(GL_FRONT)");
        gl.shade_model(GL_LINE);
        err(gl, out, "shade_model(GL_LINE)");
        gl.begin(0x1234);
        err(gl, out, "begin(bad)");
        gl.clip_plane(GL_CLIP_PLANE0 + 100, &[0.0; 4]);
        err(gl, out, "clip_plane(bad plane)");
        let mut px = [0u8; 64];
        gl.read_pixels(0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, &mut px);
        err(gl, out, "read_pixels(bad format)");
        gl.read_pixels(0, 0, 1, 1, GL_RGBA, 0x1234, &mut px);
        err(gl, out, "read_pixels(bad type)");
        // The first error sticks until read; state is unchanged by the failing calls.
        gl.depth_func(0x1234);
        gl.viewport(0, 0, -1, -1);
        err(gl, out, "depth_func(bad) + viewport(-1)");
        err(gl, out, "(read again)");
        queries(
            gl,
            out,
            &[
                Q::I(GL_MATRIX_MODE, 1),
                Q::I(GL_CULL_FACE_MODE, 1),
                Q::I(GL_FRONT_FACE, 1),
                Q::I(GL_SHADE_MODEL, 1),
                Q::I(GL_VIEWPORT, 4),
            ],
        );
    }

    pub fn errors_bad_values(gl: &mut dyn Gl, out: &mut Out) {
        gl.viewport(0, 0, -1, 5);
        err(gl, out, "viewport(w < 0)");
        gl.scissor(0, 0, 4, -1);
        err(gl, out, "scissor(h < 0)");
        gl.clear(0x8000_0000);
        err(gl, out, "clear(bad bits)");
        gl.frustum(-1.0, 1.0, -1.0, 1.0, 0.0, 10.0);
        err(gl, out, "frustum(near = 0)");
        gl.frustum(-1.0, 1.0, -1.0, 1.0, 2.0, 1.0);
        err(gl, out, "frustum(far < near)");
        gl.frustum(1.0, 1.0, -1.0, 1.0, 1.0, 2.0);
        err(gl, out, "frustum(left = right)");
        gl.ortho(-1.0, 1.0, 2.0, 2.0, -1.0, 1.0);
        err(gl, out, "ortho(bottom = top)");
        gl.ortho(-1.0, 1.0, -1.0, 1.0, 3.0, 3.0);
        err(gl, out, "ortho(near = far)");
        let mut px = [0u8; 64];
        gl.read_pixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
        err(gl, out, "read_pixels(w < 0)");
        queries(
            gl,
            out,
            &[
                Q::F(GL_MODELVIEW_MATRIX, 16),
                Q::I(GL_VIEWPORT, 4),
                Q::I(GL_SCISSOR_BOX, 4),
            ],
        );
    }

    pub fn errors_begin_end(gl: &mut dyn Gl, out: &mut Out) {
        gl.end();
        err(gl, out, "end() outside begin");
        gl.begin(GL_TRIANGLES);
        gl.begin(GL_POINTS);
        gl.end();
        err(gl, out, "begin inside begin");
        gl.begin(GL_TRIANGLES);
        gl.load_identity();
        gl.end();
        err(gl, out, "load_identity inside begin");
        gl.begin(GL_TRIANGLES);
        gl.viewport(0, 0, 5, 5);
        gl.end();
        err(gl, out, "viewport inside begin");
        gl.begin(GL_LINES);
        let e = gl.get_error();
        out.push(("get_error inside begin".into(), Answer::Error(e)));
        gl.end();
        err(gl, out, "after get_error inside begin");
        gl.begin(GL_QUADS);
        gl.enable(GL_DEPTH_TEST);
        gl.end();
        err(gl, out, "enable inside begin");
        // Vertex, colour and rect calls... rect is illegal inside begin/end.
        gl.begin(GL_TRIANGLES);
        gl.rectf(0.0, 0.0, 1.0, 1.0);
        gl.end();
        err(gl, out, "rect inside begin");
        gl.begin(GL_POINTS);
        gl.color_3f(0.5, 0.25, 1.0);
        gl.vertex_2f(0.0, 0.0);
        gl.end();
        err(gl, out, "legal calls inside begin");
        queries(
            gl,
            out,
            &[
                Q::I(GL_VIEWPORT, 4),
                Q::Enabled(GL_DEPTH_TEST),
                Q::F(GL_CURRENT_COLOR, 4),
            ],
        );
    }

    pub fn state_provoking_vertex(gl: &mut dyn Gl, out: &mut Out) {
        let pv = |gl: &mut dyn Gl, out: &mut Out| {
            queries(
                gl,
                out,
                &[
                    Q::I(GL_PROVOKING_VERTEX_EXT, 1),
                    Q::F(GL_PROVOKING_VERTEX_EXT, 1),
                ],
            )
        };
        pv(gl, out);
        queries(
            gl,
            out,
            &[Q::B(GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION_EXT, 1)],
        );
        gl.provoking_vertex_ext(GL_FIRST_VERTEX_CONVENTION_EXT);
        err(gl, out, "provoking_vertex_ext(FIRST)");
        pv(gl, out);
        gl.provoking_vertex_ext(GL_FLAT);
        err(gl, out, "provoking_vertex_ext(GL_FLAT)");
        pv(gl, out);
        gl.begin(GL_TRIANGLES);
        gl.provoking_vertex_ext(GL_LAST_VERTEX_CONVENTION_EXT);
        gl.end();
        err(gl, out, "provoking_vertex_ext between begin and end");
        pv(gl, out);
        gl.new_list(1, GL_COMPILE);
        gl.provoking_vertex_ext(GL_LAST_VERTEX_CONVENTION_EXT);
        gl.end_list();
        pv(gl, out);
        gl.call_list(1);
        pv(gl, out);
        gl.delete_lists(1, 1);
    }

    pub fn errors_stack_limits(gl: &mut dyn Gl, out: &mut Out) {
        // Limits are implementation-dependent: read them from each implementation and test at
        // its own limit.
        for (mode, max_q) in [
            (GL_MODELVIEW, GL_MAX_MODELVIEW_STACK_DEPTH),
            (GL_PROJECTION, GL_MAX_PROJECTION_STACK_DEPTH),
            (GL_TEXTURE, GL_MAX_TEXTURE_STACK_DEPTH),
        ] {
            gl.matrix_mode(mode);
            gl.pop_matrix();
            err(gl, out, "pop_matrix at depth 1");
            let mut max = [0];
            gl.get_integerv(max_q, &mut max);
            let spec_min = if mode == GL_MODELVIEW { 32 } else { 2 };
            out.push((
                format!("max stack depth of 0x{mode:04x} >= {spec_min}"),
                Answer::Bools(vec![(max[0] >= spec_min) as u8]),
            ));
            for _ in 1..max[0].clamp(1, 1024) {
                gl.push_matrix();
            }
            err(gl, out, "push_matrix up to the limit");
            gl.translatef(1.0, 0.0, 0.0);
            gl.push_matrix();
            err(gl, out, "push_matrix beyond the limit");
            let mut depth = [0];
            let dq = match mode {
                GL_MODELVIEW => GL_MODELVIEW_STACK_DEPTH,
                GL_PROJECTION => GL_PROJECTION_STACK_DEPTH,
                _ => GL_TEXTURE_STACK_DEPTH,
            };
            gl.get_integerv(dq, &mut depth);
            out.push((
                format!("stack depth of 0x{mode:04x} == max"),
                Answer::Bools(vec![(depth[0] == max[0]) as u8]),
            ));
            gl.pop_matrix();
            queries(gl, out, &[Q::F(GL_MODELVIEW_MATRIX, 16)]);
        }
    }
}

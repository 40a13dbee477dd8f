//! The attribute stack, occlusion queries, multisample state, selection and feedback, answer by
//! answer against Mesa. Window z in hit records and feedback coordinates are computed in
//! floating point by both implementations (Mesa in single precision), so those values agree
//! within a tolerance: 2^-20 of the z range for hit records, 1/1024 for feedback values.
//! Everything else is exact.

use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::{ClientPtr, Gl};

/// One answer: a label, the values, and how far they may differ.
#[derive(Debug)]
struct Answer {
    label: String,
    values: Vec<f64>,
    tolerance: f64,
}

type Answers = Vec<Answer>;

fn exact(out: &mut Answers, label: String, values: Vec<f64>) {
    out.push(Answer {
        label,
        values,
        tolerance: 0.0,
    });
}

fn ints(gl: &mut dyn Gl, out: &mut Answers, pnames: &[GLenum]) {
    for &p in pnames {
        let mut v = [0x5a5a_5a5a; 4];
        gl.get_integerv(p, &mut v);
        let n = if p == GL_VIEWPORT || p == GL_SCISSOR_BOX || p == GL_COLOR_WRITEMASK {
            4
        } else {
            1
        };
        exact(
            out,
            format!("answer {}: get_integerv(0x{p:04x})", out.len()),
            v[..n].iter().map(|&x| x as f64).collect(),
        );
    }
    err(gl, out, "queries");
}

fn floats(gl: &mut dyn Gl, out: &mut Answers, pnames: &[GLenum]) {
    for &p in pnames {
        let mut v = [0f32; 4];
        gl.get_floatv(p, &mut v);
        out.push(Answer {
            label: format!("get_floatv(0x{p:04x})"),
            values: v.iter().map(|&x| x as f64).collect(),
            tolerance: 1e-6,
        });
    }
    err(gl, out, "float queries");
}

fn err(gl: &mut dyn Gl, out: &mut Answers, label: &str) {
    let e = gl.get_error();
    exact(out, format!("glGetError after {label}"), vec![e as f64]);
}

impl super::Recorded for Answer {
    fn label(&self) -> String {
        self.label.clone()
    }
    fn value(&self) -> String {
        format!("{:?}", self.values)
    }
}

/// Values agree within the answer's own tolerance.
fn agree(a: &Answer, b: &Answer) -> bool {
    a.values.len() == b.values.len()
        && a.values
            .iter()
            .zip(&b.values)
            .all(|(x, y)| (x - y).abs() <= a.tolerance)
}

super::state_case_list!(source = include_str!("attrib.rs"), agree = agree;
    state_attrib_stack: "Section 6.1.14: glPushAttrib saves the groups its mask names and glPopAttrib restores exactly those; popping an empty stack records GL_STACK_UNDERFLOW and changes nothing.",
    state_occlusion_queries: "Section 4.1.6 (GL 1.5): GL_SAMPLES_PASSED counts the fragments that pass the depth and stencil tests between glBeginQuery and glEndQuery; ids from glGenQueries become queries at glBeginQuery; glEndQuery without an active query and glBeginQuery with id 0 record GL_INVALID_OPERATION, a bad target GL_INVALID_ENUM.",
    state_selection_hits: "Section 5.2: in GL_SELECT mode each primitive that survives clipping makes a hit; a hit record holds the name-stack depth, the minimum and maximum window z scaled to 2^32 - 1, and the names; glRenderMode returns the hit count, -1 on overflow; name-stack calls outside select mode or on an empty stack record errors.",
    state_feedback_buffer: "Section 5.3: in GL_FEEDBACK mode every primitive writes a token and its vertices in the buffer's type (2D, 3D, 3D_COLOR, 3D_COLOR_TEXTURE, 4D_COLOR_TEXTURE), glPassThrough writes its token; glRenderMode returns the value count, -1 on overflow; glFeedbackBuffer in feedback mode records GL_INVALID_OPERATION.",
);

const STATE: &[GLenum] = &[
    GL_ATTRIB_STACK_DEPTH,
    GL_LINE_WIDTH,
    GL_POINT_SIZE,
    GL_DEPTH_FUNC,
    GL_BLEND,
    GL_BLEND_SRC,
    GL_BLEND_DST,
    GL_CULL_FACE,
    GL_CULL_FACE_MODE,
    GL_FRONT_FACE,
    GL_SHADE_MODEL,
    GL_LIGHTING,
    GL_LIGHT3,
    GL_FOG,
    GL_FOG_MODE,
    GL_STENCIL_FUNC,
    GL_STENCIL_REF,
    GL_STENCIL_VALUE_MASK,
    GL_STENCIL_WRITEMASK,
    GL_STENCIL_CLEAR_VALUE,
    GL_VIEWPORT,
    GL_SCISSOR_BOX,
    GL_SCISSOR_TEST,
    GL_MATRIX_MODE,
    GL_NORMALIZE,
    GL_CLIP_PLANE1,
    GL_COLOR_WRITEMASK,
    GL_LOGIC_OP_MODE,
    GL_COLOR_LOGIC_OP,
    GL_DRAW_BUFFER,
    GL_READ_BUFFER,
    GL_FOG_HINT,
    GL_LIST_BASE,
    GL_ACTIVE_TEXTURE,
    GL_TEXTURE_BINDING_2D,
    GL_TEXTURE_2D,
    GL_TEXTURE_GEN_S,
    GL_TEXTURE_ENV_MODE,
    GL_LINE_STIPPLE_PATTERN,
    GL_LINE_STIPPLE_REPEAT,
    GL_POLYGON_MODE,
    GL_MULTISAMPLE,
    GL_SAMPLE_COVERAGE,
    GL_SAMPLE_ALPHA_TO_COVERAGE,
    GL_SAMPLE_ALPHA_TO_ONE,
    GL_SAMPLE_BUFFERS,
    GL_SAMPLES,
    GL_SAMPLE_COVERAGE_INVERT,
    GL_MAX_ATTRIB_STACK_DEPTH,
    GL_NAME_STACK_DEPTH,
    GL_RENDER_MODE,
    GL_MAP1_VERTEX_3,
    GL_MAP2_COLOR_4,
    GL_AUTO_NORMAL,
    GL_MAP1_GRID_SEGMENTS,
    GL_MAP2_GRID_SEGMENTS,
    // Not GL_BLEND_EQUATION_ALPHA_EXT: Mesa 22's glPopAttrib(GL_COLOR_BUFFER_BIT) leaves it
    // as set after the push, where EXT_blend_equation_separate puts it in the colour-buffer
    // group (tilegl restores it; `tests/attrib_stack.rs` checks that).
];

const FLOAT_STATE: &[GLenum] = &[
    GL_CURRENT_COLOR,
    GL_CURRENT_RASTER_POSITION,
    GL_FOG_DENSITY,
    GL_DEPTH_CLEAR_VALUE,
    GL_ACCUM_CLEAR_VALUE,
    GL_COLOR_CLEAR_VALUE,
    GL_POLYGON_OFFSET_FACTOR,
    GL_ALPHA_TEST_REF,
    GL_SAMPLE_COVERAGE_VALUE,
    GL_ZOOM_X,
    GL_RED_SCALE,
    GL_DEPTH_RANGE,
];

fn change_state(gl: &mut dyn Gl) {
    gl.line_width(3.0);
    gl.point_size(5.0);
    gl.depth_func(GL_GEQUAL);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE);
    gl.enable(GL_CULL_FACE);
    gl.cull_face(GL_FRONT);
    gl.front_face(GL_CW);
    gl.shade_model(GL_FLAT);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT3);
    gl.enable(GL_FOG);
    gl.fogi(GL_FOG_MODE, GL_LINEAR as i32);
    gl.fogf(GL_FOG_DENSITY, 0.25);
    gl.stencil_func(GL_LESS, 5, 0x0F);
    gl.stencil_mask(0x3C);
    gl.clear_stencil(9);
    gl.viewport(4, 5, 30, 20);
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(1, 2, 3, 4);
    gl.matrix_mode(GL_PROJECTION);
    gl.enable(GL_NORMALIZE);
    gl.enable(GL_CLIP_PLANE1);
    gl.color_mask(0, 1, 0, 1);
    gl.logic_op(GL_XOR);
    gl.enable(GL_COLOR_LOGIC_OP);
    gl.draw_buffer(GL_NONE);
    gl.read_buffer(GL_FRONT);
    gl.hint(GL_FOG_HINT, GL_NICEST);
    gl.list_base(17);
    gl.bind_texture(GL_TEXTURE_2D, 3);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_TEXTURE_GEN_S);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL as i32);
    gl.active_texture(GL_TEXTURE1);
    gl.line_stipple(3, 0x0F0F);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_POINT);
    gl.disable(GL_MULTISAMPLE);
    gl.enable(GL_SAMPLE_COVERAGE);
    gl.enable(GL_SAMPLE_ALPHA_TO_ONE);
    gl.sample_coverage(0.25, 1);
    gl.color_4f(0.1, 0.2, 0.3, 0.4);
    gl.raster_pos_2f(0.5, 0.25);
    gl.clear_depth(0.5);
    gl.clear_accum(0.25, 0.5, -0.5, 1.0);
    gl.clear_color(0.5, 0.25, 0.75, 1.0);
    gl.polygon_offset(2.0, 1.0);
    gl.alpha_func(GL_LESS, 0.75);
    gl.pixel_zoom(2.0, 3.0);
    gl.pixel_transferf(GL_RED_SCALE, 0.5);
    gl.depth_range(0.25, 0.5);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.enable(GL_MAP2_COLOR_4);
    gl.enable(GL_AUTO_NORMAL);
    gl.map_grid_1f(9, 0.0, 2.0);
    gl.map_grid_2d(4, 0.0, 1.0, 6, -1.0, 1.0);
    gl.blend_equation_separate_ext(GL_FUNC_ADD, GL_MIN);
}

fn state_attrib_stack(gl: &mut dyn Gl, out: &mut Answers) {
    // Mesa reports the all-ones default masks cut to the stencil bits: start from others.
    gl.stencil_func(GL_ALWAYS, 0, 0x7F);
    gl.stencil_mask(0xF0);
    ints(gl, out, STATE);
    floats(gl, out, FLOAT_STATE);
    gl.pop_attrib();
    err(gl, out, "pop of an empty stack");
    gl.push_attrib(GL_ALL_ATTRIB_BITS);
    change_state(gl);
    ints(gl, out, STATE);
    floats(gl, out, FLOAT_STATE);
    gl.pop_attrib();
    ints(gl, out, STATE);
    floats(gl, out, FLOAT_STATE);
    // Group by group: each entry restores only its own group.
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
    for g in groups {
        gl.push_attrib(g);
        change_state(gl);
        gl.pop_attrib();
        err(gl, out, &format!("group 0x{g:x}"));
        ints(gl, out, STATE);
        floats(gl, out, FLOAT_STATE);
    }
    // Depth limit.
    for _ in 0..16 {
        gl.push_attrib(GL_LINE_BIT);
    }
    err(gl, out, "16 pushes");
    ints(gl, out, &[GL_ATTRIB_STACK_DEPTH]);
    gl.push_attrib(GL_LINE_BIT);
    err(gl, out, "17th push");
    ints(gl, out, &[GL_ATTRIB_STACK_DEPTH]);
}

fn state_occlusion_queries(gl: &mut dyn Gl, out: &mut Answers) {
    gl.matrix_mode(GL_PROJECTION);
    gl.ortho(0.0, 64.0, 0.0, 64.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.enable(GL_DEPTH_TEST);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    let mut ids = [0u32; 10];
    gl.gen_queries(10, &mut ids);
    err(gl, out, "glGenQueries");
    exact(
        out,
        "is_query before begin".into(),
        vec![gl.is_query(ids[0]) as f64],
    );
    gl.end_query(GL_SAMPLES_PASSED);
    err(gl, out, "glEndQuery without a query");
    gl.begin_query(GL_SAMPLES_PASSED, 0);
    err(gl, out, "glBeginQuery(0)");
    gl.begin_query(GL_TEXTURE_2D, ids[0]);
    err(gl, out, "glBeginQuery(bad target)");
    let draws: [fn(&mut dyn Gl); 8] = [
        |gl| gl.rectf(3.3, 4.6, 40.2, 30.7),
        |gl| {
            gl.begin(GL_TRIANGLES);
            gl.vertex_3f(0.0, 0.0, 0.5);
            gl.vertex_3f(63.0, 5.0, -0.5);
            gl.vertex_3f(20.0, 60.0, 0.2);
            gl.end();
        },
        |gl| {
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_ALWAYS, 1, 0xFF);
            gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
            gl.depth_func(GL_ALWAYS);
            gl.rectf(10.0, 10.0, 50.0, 50.0);
            gl.depth_func(GL_LESS);
            gl.disable(GL_STENCIL_TEST);
        },
        |gl| {
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_EQUAL, 1, 0xFF);
            gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
            gl.depth_func(GL_ALWAYS);
            gl.rectf(0.0, 0.0, 30.0, 64.0);
            gl.depth_func(GL_LESS);
            gl.disable(GL_STENCIL_TEST);
        },
        |gl| {
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_GREATER, 0.5);
            gl.begin(GL_TRIANGLES);
            gl.color_4f(1.0, 1.0, 1.0, 0.0);
            gl.vertex_3f(0.0, 0.0, -0.9);
            gl.color_4f(1.0, 1.0, 1.0, 1.0);
            gl.vertex_3f(64.0, 0.0, -0.9);
            gl.vertex_3f(0.0, 64.0, -0.9);
            gl.end();
            gl.disable(GL_ALPHA_TEST);
        },
        |gl| {
            gl.color_mask(0, 0, 0, 0);
            gl.depth_mask(0);
            gl.begin(GL_POINTS);
            for i in 0..20 {
                gl.vertex_3f(2.5 + 3.0 * i as f32, 62.5, -0.95);
            }
            gl.end();
            gl.begin(GL_LINES);
            gl.vertex_3f(0.5, 61.5, -0.95);
            gl.vertex_3f(60.5, 61.5, -0.95);
            gl.end();
            gl.color_mask(1, 1, 1, 1);
            gl.depth_mask(1);
        },
        |gl| {
            gl.window_pos_3f(3.0, 5.0, 0.0);
            gl.draw_pixels(9, 7, GL_RGBA, GL_UNSIGNED_BYTE, Some(&[200u8; 9 * 7 * 4]));
        },
        |gl| {
            gl.window_pos_3f(40.0, 45.0, 0.0);
            gl.bitmap(
                16,
                2,
                0.0,
                0.0,
                0.0,
                0.0,
                &[0xA5, 0x0F, 0, 0, 0xFF, 0x81, 0, 0],
            );
        },
    ];
    for (i, draw) in draws.iter().enumerate() {
        gl.begin_query(GL_SAMPLES_PASSED, ids[i]);
        let mut cur = [0i32];
        gl.get_queryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &mut cur);
        exact(
            out,
            format!("current query {i}"),
            vec![(cur[0] as u32 == ids[i]) as i32 as f64],
        );
        gl.begin_query(GL_SAMPLES_PASSED, ids[9]);
        err(gl, out, "nested glBeginQuery");
        draw(gl);
        gl.end_query(GL_SAMPLES_PASSED);
        let mut n = [0u32];
        gl.get_query_objectuiv(ids[i], GL_QUERY_RESULT, &mut n);
        let mut avail = [0i32];
        gl.get_query_objectiv(ids[i], GL_QUERY_RESULT_AVAILABLE, &mut avail);
        exact(
            out,
            format!("query {i} result"),
            vec![n[0] as f64, avail[0] as f64],
        );
        err(gl, out, &format!("query {i}"));
    }
    exact(
        out,
        "is_query after begin".into(),
        vec![gl.is_query(ids[0]) as f64],
    );
    let mut v = [0i32];
    gl.get_query_objectiv(ids[9], GL_QUERY_RESULT, &mut v);
    err(gl, out, "result of a never-begun name");
    gl.get_query_objectiv(ids[0], GL_TEXTURE_2D, &mut v);
    err(gl, out, "bad query object pname");
    gl.get_queryiv(GL_SAMPLES_PASSED, GL_QUERY_RESULT, &mut v);
    err(gl, out, "bad query pname");
    gl.begin_query(GL_SAMPLES_PASSED, ids[8]);
    gl.get_query_objectiv(ids[8], GL_QUERY_RESULT, &mut v);
    err(gl, out, "result of the active query");
    gl.end_query(GL_SAMPLES_PASSED);
    gl.delete_queries(1, &ids[..1]);
    exact(
        out,
        "is_query after delete".into(),
        vec![gl.is_query(ids[0]) as f64],
    );
    gl.gen_queries(-1, &mut ids);
    err(gl, out, "glGenQueries(-1)");
}

/// Window z of hit records differ by floating-point rounding: 2^-20 of the range.
const HIT_Z_TOLERANCE: f64 = 4096.0;

fn state_selection_hits(gl: &mut dyn Gl, out: &mut Answers) {
    gl.matrix_mode(GL_PROJECTION);
    gl.ortho(0.0, 64.0, 0.0, 64.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    let mut buf = vec![0u32; 128];
    gl.render_mode(GL_SELECT);
    err(gl, out, "select without a buffer");
    // Mesa enters selection mode despite that error (tilegl, per section 2.5, ignores the
    // command): leave it, with no hits either way.
    let r = gl.render_mode(GL_RENDER);
    exact(out, "render mode after the error".into(), vec![r as f64]);
    gl.select_buffer(128, ClientPtr(buf.as_mut_ptr() as usize));
    let mut p = 0usize;
    gl.get_pointerv(
        GL_SELECTION_BUFFER_POINTER,
        ClientPtr(&mut p as *mut usize as usize),
    );
    exact(
        out,
        "selection buffer pointer".into(),
        vec![(p == buf.as_ptr() as usize) as i32 as f64],
    );
    gl.render_mode(GL_SELECT);
    gl.load_name(1);
    err(gl, out, "load name with an empty stack");
    gl.pop_name();
    err(gl, out, "pop of an empty name stack");
    gl.init_names();
    gl.push_name(10);
    gl.begin(GL_TRIANGLES);
    gl.vertex_3f(5.0, 5.0, 0.5);
    gl.vertex_3f(30.0, 8.0, -0.25);
    gl.vertex_3f(9.0, 40.0, 0.0);
    gl.end();
    gl.load_name(11);
    gl.rectf(100.0, 100.0, 120.0, 130.0);
    gl.load_name(12);
    gl.push_name(13);
    gl.begin(GL_POINTS);
    gl.vertex_3f(3.0, 3.0, 0.75);
    gl.vertex_3f(60.0, 60.0, -0.5);
    gl.end();
    gl.pop_name();
    // Clipped by the near plane.
    gl.begin(GL_LINES);
    gl.vertex_3f(20.0, 20.0, 2.0);
    gl.vertex_3f(40.0, 20.0, -0.5);
    gl.end();
    gl.load_name(14);
    gl.enable(GL_CULL_FACE);
    gl.begin(GL_TRIANGLES);
    gl.vertex_2f(10.0, 10.0);
    gl.vertex_2f(10.0, 30.0);
    gl.vertex_2f(30.0, 10.0);
    gl.end();
    // Zero area: a hit, back-facing (culled by GL_BACK, kept by GL_FRONT).
    gl.load_name(16);
    for face in [GL_BACK, GL_FRONT] {
        gl.cull_face(face);
        gl.begin(GL_TRIANGLES);
        gl.vertex_2f(1.0, 2.0);
        gl.vertex_2f(3.0, 4.0);
        gl.vertex_2f(5.0, 6.0);
        gl.end();
    }
    gl.cull_face(GL_BACK);
    gl.disable(GL_CULL_FACE);
    gl.load_name(17);
    gl.begin(GL_TRIANGLES);
    gl.vertex_2f(10.0, 10.0);
    gl.vertex_2f(10.0, 10.0);
    gl.vertex_2f(20.0, 30.0);
    gl.end();
    // A quad clipped by the view volume's sides. (Not at the far plane: Mesa 22 converts a
    // window z of 1 to 2^32 in single precision and stores 0, where section 5.2 asks for
    // 2^32 - 1, which tilegl writes; `tests/select_feedback.rs` checks that case.)
    gl.load_name(15);
    gl.begin(GL_QUADS);
    gl.vertex_3f(-10.0, 30.0, -0.9);
    gl.vertex_3f(50.0, 30.0, 0.0);
    gl.vertex_3f(50.0, 80.0, 0.0);
    gl.vertex_3f(-10.0, 80.0, -0.9);
    gl.end();
    ints(gl, out, &[GL_NAME_STACK_DEPTH, GL_RENDER_MODE]);
    let hits = gl.render_mode(GL_RENDER);
    exact(out, "hits".into(), vec![hits as f64]);
    // Walk the records: counts and names exact, z within the tolerance.
    let mut i = 0;
    for h in 0..hits.max(0) as usize {
        let n = buf[i] as usize;
        exact(out, format!("hit {h} name count"), vec![n as f64]);
        out.push(Answer {
            label: format!("hit {h} z range"),
            values: vec![buf[i + 1] as f64, buf[i + 2] as f64],
            tolerance: HIT_Z_TOLERANCE,
        });
        exact(
            out,
            format!("hit {h} names"),
            buf[i + 3..i + 3 + n].iter().map(|&v| v as f64).collect(),
        );
        i += 3 + n;
    }
    // Overflow.
    gl.select_buffer(6, ClientPtr(buf.as_mut_ptr() as usize));
    gl.render_mode(GL_SELECT);
    gl.push_name(1);
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    gl.load_name(2);
    gl.rectf(0.0, 0.0, 8.0, 8.0);
    let r = gl.render_mode(GL_RENDER);
    exact(out, "overflowed hits".into(), vec![r as f64]);
    exact(
        out,
        "overflowed names".into(),
        vec![buf[0] as f64, buf[3] as f64, buf[4] as f64, buf[5] as f64],
    );
    err(gl, out, "selection");
    drop(buf);
}

fn state_feedback_buffer(gl: &mut dyn Gl, out: &mut Answers) {
    gl.matrix_mode(GL_PROJECTION);
    gl.ortho(0.0, 64.0, 0.0, 64.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    for ty in [
        GL_2D,
        GL_3D,
        GL_3D_COLOR,
        GL_3D_COLOR_TEXTURE,
        GL_4D_COLOR_TEXTURE,
    ] {
        let mut buf = vec![0f32; 1024];
        gl.feedback_buffer(1024, ty, ClientPtr(buf.as_mut_ptr() as usize));
        gl.render_mode(GL_FEEDBACK);
        gl.feedback_buffer(1024, ty, ClientPtr(buf.as_mut_ptr() as usize));
        err(gl, out, "feedback buffer in feedback mode");
        gl.color_4f(1.0, 0.5, 0.25, 0.75);
        gl.tex_coord_4f(0.1, 0.2, 0.3, 1.0);
        gl.begin(GL_POINTS);
        gl.vertex_3f(10.5, 20.5, 0.0);
        gl.vertex_3f(70.0, 20.5, 0.0);
        gl.end();
        gl.pass_through(42.0);
        gl.begin(GL_LINES);
        gl.color_3f(1.0, 0.0, 0.0);
        gl.vertex_3f(1.0, 2.0, 0.5);
        gl.color_3f(0.0, 1.0, 0.0);
        gl.vertex_3f(30.0, 40.0, -0.5);
        gl.end();
        gl.begin(GL_LINE_STRIP);
        gl.vertex_2f(5.0, 5.0);
        gl.vertex_2f(10.0, 5.0);
        gl.vertex_2f(10.0, 12.0);
        gl.end();
        gl.begin(GL_TRIANGLES);
        gl.color_3f(0.0, 0.0, 1.0);
        gl.vertex_3f(10.0, 10.0, 0.25);
        gl.color_3f(1.0, 1.0, 0.0);
        gl.vertex_3f(40.0, 12.0, 0.5);
        gl.color_3f(0.0, 1.0, 1.0);
        gl.vertex_3f(20.0, 50.0, -0.25);
        gl.end();
        // Zero area (collinear, and two equal vertices): reported, as back-facing.
        gl.begin(GL_TRIANGLES);
        gl.vertex_2f(1.0, 2.0);
        gl.vertex_2f(3.0, 4.0);
        gl.vertex_2f(5.0, 6.0);
        gl.vertex_2f(10.0, 10.0);
        gl.vertex_2f(10.0, 10.0);
        gl.vertex_2f(20.0, 30.0);
        gl.end();
        gl.enable(GL_CULL_FACE);
        for face in [GL_BACK, GL_FRONT] {
            gl.cull_face(face);
            gl.begin(GL_TRIANGLES);
            gl.vertex_2f(2.0, 1.0);
            gl.vertex_2f(4.0, 3.0);
            gl.vertex_2f(6.0, 5.0);
            gl.end();
        }
        gl.cull_face(GL_BACK);
        gl.disable(GL_CULL_FACE);
        gl.window_pos_2f(7.0, 9.0);
        gl.bitmap(0, 0, 0.0, 0.0, 2.0, 3.0, &[]);
        gl.draw_pixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, Some(&[0u8; 4]));
        gl.copy_pixels(0, 0, 2, 2, GL_COLOR);
        let n = gl.render_mode(GL_RENDER);
        exact(out, format!("feedback 0x{ty:x} count"), vec![n as f64]);
        // Mesa 22 reports every line segment with GL_LINE_TOKEN; tilegl marks the segments
        // where the stipple counter restarts (section 3.4.2) with GL_LINE_RESET_TOKEN, as
        // section 5.3 describes. The two tokens compare equal here.
        let reset = GL_LINE_RESET_TOKEN as f32;
        let values = buf[..n.max(0) as usize].iter().map(|&v| {
            if v == reset {
                GL_LINE_TOKEN as f64
            } else {
                v as f64
            }
        });
        out.push(Answer {
            label: format!("feedback 0x{ty:x} values"),
            values: values.collect(),
            tolerance: 1.0 / 1024.0,
        });
        err(gl, out, "feedback");
    }
    // A quad and a pentagon are reported as triangles; which triangles is the
    // implementation's choice (Mesa 22 splits a quad along the other diagonal than tilegl), so
    // only the number of values and the set of distinct vertices are compared.
    let mut buf = vec![0f32; 256];
    gl.feedback_buffer(256, GL_2D, ClientPtr(buf.as_mut_ptr() as usize));
    gl.render_mode(GL_FEEDBACK);
    gl.begin(GL_QUADS);
    gl.vertex_2f(40.0, 40.0);
    gl.vertex_2f(60.0, 40.0);
    gl.vertex_2f(60.0, 60.0);
    gl.vertex_2f(40.0, 60.0);
    gl.end();
    gl.begin(GL_POLYGON);
    for k in 0..5 {
        let a = k as f32 * 1.2566371;
        gl.vertex_2f(20.0 + 10.0 * a.cos(), 20.0 + 10.0 * a.sin());
    }
    gl.end();
    let n = gl.render_mode(GL_RENDER).max(0) as usize;
    let mut vertices: Vec<(i64, i64)> = buf[..n]
        .chunks(8)
        .flat_map(|t| {
            t[2..]
                .chunks(2)
                .map(|v| ((v[0] * 256.0).round() as i64, (v[1] * 256.0).round() as i64))
                .collect::<Vec<_>>()
        })
        .collect();
    vertices.sort_unstable();
    vertices.dedup();
    exact(out, "quad and polygon value count".into(), vec![n as f64]);
    exact(
        out,
        "quad and polygon vertices".into(),
        vertices
            .iter()
            .flat_map(|&(x, y)| [x as f64, y as f64])
            .collect(),
    );
    // Overflow keeps what fits and returns -1.
    let mut buf = vec![0f32; 3];
    gl.feedback_buffer(3, GL_2D, ClientPtr(buf.as_mut_ptr() as usize));
    gl.render_mode(GL_FEEDBACK);
    gl.pass_through(1.0);
    gl.pass_through(2.0);
    let n = gl.render_mode(GL_RENDER);
    exact(
        out,
        "overflowed feedback".into(),
        vec![n as f64, buf[0] as f64, buf[1] as f64, buf[2] as f64],
    );
    gl.feedback_buffer(-1, GL_2D, ClientPtr(buf.as_mut_ptr() as usize));
    err(gl, out, "negative feedback size");
    gl.feedback_buffer(4, GL_RGB, ClientPtr(buf.as_mut_ptr() as usize));
    err(gl, out, "bad feedback type");
    gl.render_mode(GL_LINES);
    err(gl, out, "bad render mode");
    drop(buf);
}

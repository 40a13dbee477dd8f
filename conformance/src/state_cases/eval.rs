//! Evaluator state and errors, answer by answer against Mesa.

use tilegl::enums::*;
use tilegl::Gl;

/// One recorded answer: a label and its values as doubles (errors as their enum value).
type Answers = Vec<(String, Vec<f64>)>;

const MAP1: [GLenum; 9] = [
    GL_MAP1_VERTEX_3,
    GL_MAP1_VERTEX_4,
    GL_MAP1_INDEX,
    GL_MAP1_COLOR_4,
    GL_MAP1_NORMAL,
    GL_MAP1_TEXTURE_COORD_1,
    GL_MAP1_TEXTURE_COORD_2,
    GL_MAP1_TEXTURE_COORD_3,
    GL_MAP1_TEXTURE_COORD_4,
];
const MAP2: [GLenum; 9] = [
    GL_MAP2_VERTEX_3,
    GL_MAP2_VERTEX_4,
    GL_MAP2_INDEX,
    GL_MAP2_COLOR_4,
    GL_MAP2_NORMAL,
    GL_MAP2_TEXTURE_COORD_1,
    GL_MAP2_TEXTURE_COORD_2,
    GL_MAP2_TEXTURE_COORD_3,
    GL_MAP2_TEXTURE_COORD_4,
];

fn error(gl: &mut dyn Gl, out: &mut Answers, label: &str) {
    let e = gl.get_error();
    out.push((format!("glGetError after {label}"), vec![e as f64]));
}

/// COEFF, ORDER and DOMAIN of `target` through all three glGetMap variants (only the values
/// the query defines: `n` coefficients).
fn get_map(gl: &mut dyn Gl, out: &mut Answers, target: GLenum, n: usize, dims: usize) {
    for (q, len) in [(GL_COEFF, n), (GL_ORDER, dims), (GL_DOMAIN, 2 * dims)] {
        let mut f = vec![-7.0f32; len];
        gl.get_mapfv(target, q, &mut f);
        out.push((
            format!("get_mapfv({target:#x}, {q:#x})"),
            f.iter().map(|&v| v as f64).collect(),
        ));
        let mut d = vec![-7.0f64; len];
        gl.get_mapdv(target, q, &mut d);
        out.push((format!("get_mapdv({target:#x}, {q:#x})"), d));
        let mut i = vec![-7i32; len];
        gl.get_mapiv(target, q, &mut i);
        out.push((
            format!("get_mapiv({target:#x}, {q:#x})"),
            i.iter().map(|&v| v as f64).collect(),
        ));
    }
    error(gl, out, "glGetMap");
}

fn get(gl: &mut dyn Gl, out: &mut Answers, pname: GLenum, n: usize) {
    let mut d = vec![-7.0f64; n];
    gl.get_doublev(pname, &mut d);
    out.push((format!("get_doublev({pname:#x})"), d));
    let mut i = vec![-7i32; n];
    gl.get_integerv(pname, &mut i);
    out.push((
        format!("get_integerv({pname:#x})"),
        i.iter().map(|&v| v as f64).collect(),
    ));
    let mut b = vec![7u8; n];
    gl.get_booleanv(pname, &mut b);
    out.push((
        format!("get_booleanv({pname:#x})"),
        b.iter().map(|&v| v as f64).collect(),
    ));
    error(gl, out, "glGet");
}

/// Defaults, maps defined with strides, grids, enables and the limit.
fn state_eval_queries(gl: &mut dyn Gl, out: &mut Answers) {
    let k = [3, 4, 1, 4, 3, 1, 2, 3, 4];
    for t in 0..9 {
        get_map(gl, out, MAP1[t], k[t], 1);
        get_map(gl, out, MAP2[t], k[t], 2);
    }
    get(gl, out, GL_MAX_EVAL_ORDER, 1);
    for p in [GL_MAP1_GRID_DOMAIN, GL_MAP2_GRID_DOMAIN] {
        get(gl, out, p, if p == GL_MAP1_GRID_DOMAIN { 2 } else { 4 });
    }
    get(gl, out, GL_MAP1_GRID_SEGMENTS, 1);
    get(gl, out, GL_MAP2_GRID_SEGMENTS, 2);
    // Maps of several orders with padding in the strides; values that round both ways.
    let pts: Vec<f64> = (0..400).map(|i| (i as f64) * 0.37 - 20.6).collect();
    let pf: Vec<f32> = pts.iter().map(|&v| v as f32).collect();
    for t in 0..9 {
        let order = 1 + (t * 3) % 8;
        gl.map_1d(MAP1[t], -1.5, 2.25, k[t] as i32 + 1, order as i32, &pts);
        get_map(gl, out, MAP1[t], order * k[t], 1);
        let (uo, vo) = (1 + t % 4, 2 + t % 3);
        let vstride = k[t] + 2;
        let ustride = vstride * vo + 1;
        gl.map_2f(
            MAP2[t],
            0.5,
            -3.0,
            ustride as i32,
            uo as i32,
            10.0,
            12.5,
            vstride as i32,
            vo as i32,
            &pf,
        );
        get_map(gl, out, MAP2[t], uo * vo * k[t], 2);
    }
    // The largest order.
    gl.map_1f(GL_MAP1_INDEX, 0.0, 1.0, 1, 30, &pf[..30]);
    get_map(gl, out, GL_MAP1_INDEX, 30, 1);
    gl.map_grid_1d(7, 2.5, -1.25);
    gl.map_grid_2f(3, 0.25, 0.75, 9, -4.0, 4.5);
    for p in [GL_MAP1_GRID_DOMAIN, GL_MAP2_GRID_DOMAIN] {
        get(gl, out, p, if p == GL_MAP1_GRID_DOMAIN { 2 } else { 4 });
    }
    get(gl, out, GL_MAP1_GRID_SEGMENTS, 1);
    get(gl, out, GL_MAP2_GRID_SEGMENTS, 2);
    for c in MAP1.iter().chain(&MAP2).chain(&[GL_AUTO_NORMAL]) {
        out.push((
            format!("is_enabled({c:#x})"),
            vec![gl.is_enabled(*c) as f64],
        ));
        gl.enable(*c);
        out.push((
            format!("is_enabled({c:#x}) on"),
            vec![gl.is_enabled(*c) as f64],
        ));
        get(gl, out, *c, 1);
        if c % 2 == 0 {
            gl.disable(*c);
        }
    }
    // What evaluation leaves behind: the current values are unchanged.
    gl.color_4f(0.25, 0.5, 0.75, 1.0);
    gl.normal_3f(0.0, 0.6, 0.8);
    gl.tex_coord_4f(1.0, 2.0, 3.0, 4.0);
    gl.begin(GL_POINTS);
    gl.eval_coord_1f(0.3);
    gl.eval_coord_2f(0.6, 0.2);
    gl.end();
    for p in [GL_CURRENT_COLOR, GL_CURRENT_TEXTURE_COORDS] {
        get(gl, out, p, 4);
    }
    get(gl, out, GL_CURRENT_NORMAL, 3);
}

/// One error per call, and what each leaves behind.
fn errors_eval(gl: &mut dyn Gl, out: &mut Answers) {
    let p = [0.5f32; 200];
    let pd = [0.5f64; 200];
    gl.map_1f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 2, &p);
    error(gl, out, "map1 with a MAP2 target");
    gl.map_1f(GL_TEXTURE_2D, 0.0, 1.0, 3, 2, &p);
    error(gl, out, "map1 with a bad target");
    gl.map_2d(GL_MAP1_COLOR_4, 0.0, 1.0, 4, 2, 0.0, 1.0, 8, 2, &pd);
    error(gl, out, "map2 with a MAP1 target");
    gl.map_1f(GL_MAP1_VERTEX_3, 1.0, 1.0, 3, 2, &p);
    error(gl, out, "map1 u1 == u2");
    gl.map_2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 2, 2.0, 2.0, 6, 2, &p);
    error(gl, out, "map2 v1 == v2");
    gl.map_1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 0, &p);
    error(gl, out, "map1 order 0");
    gl.map_1d(GL_MAP1_INDEX, 0.0, 1.0, 1, 31, &pd);
    error(gl, out, "map1 order 31");
    gl.map_2f(GL_MAP2_INDEX, 0.0, 1.0, 1, 31, 0.0, 1.0, 31, 1, &p);
    error(gl, out, "map2 uorder 31");
    gl.map_2f(GL_MAP2_INDEX, 0.0, 1.0, 31, 1, 0.0, 1.0, 1, 0, &p);
    error(gl, out, "map2 vorder 0");
    gl.map_1f(GL_MAP1_COLOR_4, 0.0, 1.0, 3, 2, &p);
    error(gl, out, "map1 stride < k");
    gl.map_2f(GL_MAP2_NORMAL, 0.0, 1.0, 2, 2, 0.0, 1.0, 6, 2, &p);
    error(gl, out, "map2 ustride < k");
    gl.map_2f(GL_MAP2_NORMAL, 0.0, 1.0, 6, 2, 0.0, 1.0, 2, 2, &p);
    error(gl, out, "map2 vstride < k");
    gl.active_texture(GL_TEXTURE1);
    gl.map_1f(GL_MAP1_TEXTURE_COORD_2, 0.0, 1.0, 2, 2, &p);
    error(gl, out, "map1 with active texture 1");
    gl.active_texture(GL_TEXTURE0);
    gl.map_grid_1f(0, 0.0, 1.0);
    error(gl, out, "map grid 1 n = 0");
    gl.map_grid_2d(3, 0.0, 1.0, -2, 0.0, 1.0);
    error(gl, out, "map grid 2 m < 0");
    gl.map_grid_1d(4, 1.0, 1.0);
    error(gl, out, "map grid 1 u1 == u2 (legal)");
    gl.eval_mesh_1(GL_FILL, 0, 1);
    error(gl, out, "eval mesh 1 FILL");
    gl.eval_mesh_2(GL_LINE_LOOP, 0, 1, 0, 1);
    error(gl, out, "eval mesh 2 bad mode");
    gl.get_mapfv(GL_MAP1_VERTEX_3, GL_COEFF + 5, &mut [0.0; 8]);
    error(gl, out, "get map bad query");
    gl.get_mapiv(GL_TEXTURE_2D, GL_ORDER, &mut [0; 8]);
    error(gl, out, "get map bad target");
    gl.begin(GL_POINTS);
    gl.map_1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 2, &p);
    gl.end();
    error(gl, out, "map1 inside begin");
    gl.begin(GL_POINTS);
    gl.map_grid_2f(2, 0.0, 1.0, 2, 0.0, 1.0);
    gl.end();
    error(gl, out, "map grid inside begin");
    gl.begin(GL_POINTS);
    gl.eval_mesh_1(GL_POINT, 0, 1);
    gl.end();
    error(gl, out, "eval mesh inside begin");
    gl.begin(GL_POINTS);
    gl.eval_coord_1f(0.5);
    gl.eval_coord_2dv(&[0.5, 0.25]);
    gl.eval_point_1(1);
    gl.eval_point_2(1, 0);
    gl.end();
    error(gl, out, "eval coord and eval point inside begin (legal)");
    gl.enable(GL_MAP1_VERTEX_3);
    gl.eval_mesh_1(GL_LINE, 3, 1);
    error(gl, out, "eval mesh with i2 < i1 (legal)");
    // Nothing changed by the rejected calls.
    for t in [GL_MAP1_VERTEX_3, GL_MAP1_COLOR_4, GL_MAP1_INDEX] {
        get_map(gl, out, t, 4, 1);
    }
    for t in [GL_MAP2_VERTEX_3, GL_MAP2_NORMAL, GL_MAP2_INDEX] {
        get_map(gl, out, t, 3, 2);
    }
    get(gl, out, GL_MAP1_GRID_DOMAIN, 2);
    get(gl, out, GL_MAP1_GRID_SEGMENTS, 1);
    get(gl, out, GL_MAP2_GRID_DOMAIN, 4);
    get(gl, out, GL_MAP2_GRID_SEGMENTS, 2);
}

/// Doubles agree to 1e-6 relative (Mesa stores map coefficients and domains as f32).
fn agree(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(&x, &y)| (x - y).abs() <= 1e-6 * (1.0 + x.abs().max(y.abs())))
}

super::state_case_list!(source = include_str!("eval.rs"), agree = |(_, a): &(String, Vec<f64>), (_, b)| agree(a, b);
    state_eval_queries: "Section 5.1 and glGetMap: every map's coefficients, order and domain read back as given (float, double and integer variants); grids and enables read back; defaults are order 1 with the default coefficients.",
    errors_eval: "Section 5.1: bad targets, orders outside [1, GL_MAX_EVAL_ORDER], u1 = u2, strides below k, n <= 0 grids, bad mesh modes and map calls between glBegin and glEnd record GL_INVALID_ENUM, GL_INVALID_VALUE or GL_INVALID_OPERATION and change nothing; glEvalCoord and glEvalPoint inside glBegin are legal.",
);

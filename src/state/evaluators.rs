//! Evaluators (section 5.1): `glMap1`/`glMap2`, `glEvalCoord*`, `glMapGrid*`, `glEvalMesh*`,
//! `glEvalPoint*` and `glGetMap*`.
//!
//! A map is a polynomial of degree `order - 1` in Bernstein form over its domain: with
//! u' = (u - u1) / (u2 - u1), p(u) = sum_i B_i(u') R_i, where B_i is the i-th Bernstein
//! polynomial of degree n = order - 1 and R_i the control points (and the tensor product for
//! two-dimensional maps). Evaluation is in f64.
//!
//! `glEvalCoord` issues, for the enabled maps of its dimension, the commands the map stands for
//! with the evaluated values: `glColor`, `glNormal`, `glTexCoord`, `glIndex`, then `glVertex`
//! (the vertex map of the highest dimension, and the texture map of the highest dimension, when
//! several are enabled). The evaluated colour, normal, texture coordinates and index are used
//! for the generated vertex only: the current values stay what they were ("the evaluated
//! values do not update the current values"). With no vertex map enabled no vertex results.
//! `GL_AUTO_NORMAL` gives two-dimensional vertex maps the normal
//! m / |m|, m = dp/du x dp/dv (for `GL_MAP2_VERTEX_4` of p = (x/w, y/w, z/w)). The partial
//! derivatives are in the domain coordinates u and v, so a reversed domain (u2 < u1) reverses
//! the normal; Mesa 22 differentiates in the normalized u', v' and does not.
//!
//! `glEvalMesh*` and `glEvalPoint*` are the `glBegin`/`glEvalCoord`/`glEnd` loops the
//! specification defines them as, over the grid of `glMapGrid*` (u = i * du + u1, exactly u2 at
//! i = n). A context can be told to connect fill meshes with triangle strips instead, as Mesa
//! does ([`MeshFill`]), so that replays of Mesa captures give Mesa's flat-shaded pictures.
#![allow(clippy::too_many_arguments)]

use glam::{Vec3, Vec4};

use super::get::StateValue;
use super::Context;
use crate::common::values::{AnyMap, EvalMeshMode, EvalQuery, EvalTarget, GetMapQuery};
use crate::gl::convert;
use crate::gl::enums::*;

/// `GL_MAX_EVAL_ORDER` (the specification asks for at least 8; Mesa has 30).
pub const MAX_EVAL_ORDER: i32 = 30;

/// A one-dimensional map: domain, order and `order` control points of k values each.
#[derive(Clone, Debug, PartialEq)]
pub struct Map1 {
    pub u1: f64,
    pub u2: f64,
    pub order: usize,
    pub points: Vec<f64>,
}

/// A two-dimensional map: control point (i, j) (i along u) at `(i * vorder + j) * k`.
#[derive(Clone, Debug, PartialEq)]
pub struct Map2 {
    pub u1: f64,
    pub u2: f64,
    pub v1: f64,
    pub v2: f64,
    pub uorder: usize,
    pub vorder: usize,
    pub points: Vec<f64>,
}

/// How `glEvalMesh2(GL_FILL, ...)` connects the grid: not GL state, a choice of the
/// context's owner ([`Context::set_mesh_fill`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MeshFill {
    /// One `GL_QUAD_STRIP` per grid row, as the specification defines the command: a
    /// flat-shaded quad takes one colour.
    #[default]
    QuadStrips,
    /// One `GL_TRIANGLE_STRIP` per row with the same vertices, as Mesa draws it: a flat-shaded
    /// quad takes the colours of its two triangles' last vertices. Replays of captures
    /// recorded on Mesa use it to give Mesa's pictures.
    TriangleStrips,
}

/// The evaluator state (table 6.24).
#[derive(Clone, Debug)]
pub struct EvalState {
    pub map1: [Map1; 9],
    pub map2: [Map2; 9],
    pub map1_enabled: [bool; 9],
    pub map2_enabled: [bool; 9],
    pub auto_normal: bool,
    /// `glMapGrid1`: n, u1, u2.
    pub grid1: (i32, f64, f64),
    /// `glMapGrid2`: n, u1, u2, m, v1, v2.
    pub grid2: (i32, f64, f64, i32, f64, f64),
}

/// The initial control point of each map (order 1): the initial current values.
fn initial_point(t: EvalTarget) -> &'static [f64] {
    match t {
        EvalTarget::Vertex3 => &[0.0, 0.0, 0.0],
        EvalTarget::Vertex4 => &[0.0, 0.0, 0.0, 1.0],
        EvalTarget::Index => &[1.0],
        EvalTarget::Color4 => &[1.0, 1.0, 1.0, 1.0],
        EvalTarget::Normal => &[0.0, 0.0, 1.0],
        EvalTarget::TexCoord1 => &[0.0],
        EvalTarget::TexCoord2 => &[0.0, 0.0],
        EvalTarget::TexCoord3 => &[0.0, 0.0, 0.0],
        EvalTarget::TexCoord4 => &[0.0, 0.0, 0.0, 1.0],
    }
}

impl Default for EvalState {
    fn default() -> Self {
        EvalState {
            map1: EvalTarget::ALL.map(|t| Map1 {
                u1: 0.0,
                u2: 1.0,
                order: 1,
                points: initial_point(t).to_vec(),
            }),
            map2: EvalTarget::ALL.map(|t| Map2 {
                u1: 0.0,
                u2: 1.0,
                v1: 0.0,
                v2: 1.0,
                uorder: 1,
                vorder: 1,
                points: initial_point(t).to_vec(),
            }),
            map1_enabled: [false; 9],
            map2_enabled: [false; 9],
            auto_normal: false,
            grid1: (1, 0.0, 1.0),
            grid2: (1, 0.0, 1.0, 1, 0.0, 1.0),
        }
    }
}

/// The Bernstein polynomials of degree `order - 1` at `t`, and their derivatives in `t`.
pub fn bernstein(order: usize, t: f64) -> (Vec<f64>, Vec<f64>) {
    // de Casteljau's triangle on the basis: b holds the degree-d polynomials.
    let mut b = vec![0.0; order];
    let mut d = vec![0.0; order];
    b[0] = 1.0;
    let s = 1.0 - t;
    for deg in 1..order {
        if deg == order - 1 {
            // Derivative of B_i^n = n (B_{i-1}^{n-1} - B_i^{n-1}).
            let n = deg as f64;
            for i in 0..=deg {
                let prev = if i > 0 { b[i - 1] } else { 0.0 };
                let cur = if i < deg { b[i] } else { 0.0 };
                d[i] = n * (prev - cur);
            }
        }
        let mut carry = 0.0;
        for bi in b.iter_mut().take(deg + 1) {
            let v = *bi;
            *bi = s * v + t * carry;
            carry = v;
        }
    }
    (b, d)
}

/// Number of values `glMap1` reads: (order - 1) * stride + k, or 0 for arguments it rejects.
pub fn map1_len(target: GLenum, stride: i64, order: i64) -> usize {
    let Some(t) = convert::map1_target(target) else {
        return 0;
    };
    let k = t.components() as i64;
    if !(1..=MAX_EVAL_ORDER as i64).contains(&order) || stride < k {
        return 0;
    }
    ((order - 1) * stride + k) as usize
}

/// Number of values `glMap2` reads (0 for arguments it rejects).
pub fn map2_len(target: GLenum, ustride: i64, uorder: i64, vstride: i64, vorder: i64) -> usize {
    let Some(t) = convert::map2_target(target) else {
        return 0;
    };
    let k = t.components() as i64;
    let orders = 1..=MAX_EVAL_ORDER as i64;
    if !orders.contains(&uorder) || !orders.contains(&vorder) || ustride < k || vstride < k {
        return 0;
    }
    ((uorder - 1) * ustride + (vorder - 1) * vstride + k) as usize
}

/// The values evaluated at one domain point, by target (`None` for maps not enabled).
#[derive(Default)]
struct Evaluated {
    values: [Option<[f64; 4]>; 9],
    /// The analytic normal (`GL_AUTO_NORMAL`).
    auto_normal: Option<[f64; 3]>,
}

impl Context {
    /// The number of values `glGetMap*` writes for `target` and `query` (0 when invalid).
    pub fn get_map_len(&self, target: GLenum, query: GLenum) -> usize {
        let (Some(map), Some(q)) = (
            convert::any_map_target(target),
            convert::get_map_query(query),
        ) else {
            return 0;
        };
        match (map, q) {
            (AnyMap::Map1(t), GetMapQuery::Coeff) => self.eval.map1[t.index()].points.len(),
            (AnyMap::Map2(t), GetMapQuery::Coeff) => self.eval.map2[t.index()].points.len(),
            (AnyMap::Map1(_), GetMapQuery::Order) => 1,
            (AnyMap::Map2(_), GetMapQuery::Order) => 2,
            (AnyMap::Map1(_), GetMapQuery::Domain) => 2,
            (AnyMap::Map2(_), GetMapQuery::Domain) => 4,
        }
    }

    pub(crate) fn eval_state_value(&self, q: EvalQuery) -> StateValue {
        let e = &self.eval;
        match q {
            EvalQuery::MaxEvalOrder => StateValue::Ints(vec![MAX_EVAL_ORDER as i64]),
            EvalQuery::Map1GridDomain => StateValue::Floats(vec![e.grid1.1, e.grid1.2]),
            EvalQuery::Map1GridSegments => StateValue::Ints(vec![e.grid1.0 as i64]),
            EvalQuery::Map2GridDomain => {
                StateValue::Floats(vec![e.grid2.1, e.grid2.2, e.grid2.4, e.grid2.5])
            }
            EvalQuery::Map2GridSegments => {
                StateValue::Ints(vec![e.grid2.0 as i64, e.grid2.3 as i64])
            }
        }
    }

    // ----- glMap1 / glMap2

    fn map1(&mut self, target: GLenum, u1: f64, u2: f64, stride: i32, order: i32, p: &[f64]) {
        let Some(t) = convert::map1_target(target) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let k = t.components();
        if u1 == u2
            || !(1..=MAX_EVAL_ORDER).contains(&order)
            || stride < k as i32
            || p.len() < map1_len(target, stride as i64, order as i64)
        {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        // Texture-coordinate maps belong to unit 0 (GL 1.3, section F.2.13; as Mesa).
        if self.active_texture != 0 {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        let (order, stride) = (order as usize, stride as usize);
        let mut points = Vec::with_capacity(order * k);
        for i in 0..order {
            points.extend_from_slice(&p[i * stride..i * stride + k]);
        }
        self.eval.map1[t.index()] = Map1 {
            u1,
            u2,
            order,
            points,
        };
    }

    fn map2(
        &mut self,
        target: GLenum,
        (u1, u2, ustride, uorder): (f64, f64, i32, i32),
        (v1, v2, vstride, vorder): (f64, f64, i32, i32),
        p: &[f64],
    ) {
        let Some(t) = convert::map2_target(target) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let k = t.components();
        let orders = 1..=MAX_EVAL_ORDER;
        if u1 == u2
            || v1 == v2
            || !orders.contains(&uorder)
            || !orders.contains(&vorder)
            || ustride < k as i32
            || vstride < k as i32
            || p.len()
                < map2_len(
                    target,
                    ustride as i64,
                    uorder as i64,
                    vstride as i64,
                    vorder as i64,
                )
        {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        if self.active_texture != 0 {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        let (uorder, vorder) = (uorder as usize, vorder as usize);
        let (ustride, vstride) = (ustride as usize, vstride as usize);
        let mut points = Vec::with_capacity(uorder * vorder * k);
        for i in 0..uorder {
            for j in 0..vorder {
                let at = i * ustride + j * vstride;
                points.extend_from_slice(&p[at..at + k]);
            }
        }
        self.eval.map2[t.index()] = Map2 {
            u1,
            u2,
            v1,
            v2,
            uorder,
            vorder,
            points,
        };
    }

    pub(crate) fn map_1f(
        &mut self,
        target: GLenum,
        u1: GLfloat,
        u2: GLfloat,
        stride: GLint,
        order: GLint,
        points: &[GLfloat],
    ) {
        let p: Vec<f64> = points.iter().map(|&v| v as f64).collect();
        self.map1(target, u1 as f64, u2 as f64, stride, order, &p);
    }

    pub(crate) fn map_1d(
        &mut self,
        target: GLenum,
        u1: GLdouble,
        u2: GLdouble,
        stride: GLint,
        order: GLint,
        points: &[GLdouble],
    ) {
        self.map1(target, u1, u2, stride, order, points);
    }

    pub(crate) fn map_2f(
        &mut self,
        target: GLenum,
        u1: GLfloat,
        u2: GLfloat,
        ustride: GLint,
        uorder: GLint,
        v1: GLfloat,
        v2: GLfloat,
        vstride: GLint,
        vorder: GLint,
        points: &[GLfloat],
    ) {
        let p: Vec<f64> = points.iter().map(|&v| v as f64).collect();
        self.map2(
            target,
            (u1 as f64, u2 as f64, ustride, uorder),
            (v1 as f64, v2 as f64, vstride, vorder),
            &p,
        );
    }

    pub(crate) fn map_2d(
        &mut self,
        target: GLenum,
        u1: GLdouble,
        u2: GLdouble,
        ustride: GLint,
        uorder: GLint,
        v1: GLdouble,
        v2: GLdouble,
        vstride: GLint,
        vorder: GLint,
        points: &[GLdouble],
    ) {
        self.map2(
            target,
            (u1, u2, ustride, uorder),
            (v1, v2, vstride, vorder),
            points,
        );
    }

    // ----- glGetMap

    /// The values of a `glGetMap*` query, or `None` after recording `GL_INVALID_ENUM`.
    fn get_map(&mut self, target: GLenum, query: GLenum) -> Option<Vec<f64>> {
        let (Some(map), Some(q)) = (
            convert::any_map_target(target),
            convert::get_map_query(query),
        ) else {
            self.record_error(GL_INVALID_ENUM);
            return None;
        };
        Some(match map {
            AnyMap::Map1(t) => {
                let m = &self.eval.map1[t.index()];
                match q {
                    GetMapQuery::Coeff => m.points.clone(),
                    GetMapQuery::Order => vec![m.order as f64],
                    GetMapQuery::Domain => vec![m.u1, m.u2],
                }
            }
            AnyMap::Map2(t) => {
                let m = &self.eval.map2[t.index()];
                match q {
                    GetMapQuery::Coeff => m.points.clone(),
                    GetMapQuery::Order => vec![m.uorder as f64, m.vorder as f64],
                    GetMapQuery::Domain => vec![m.u1, m.u2, m.v1, m.v2],
                }
            }
        })
    }

    pub(crate) fn get_mapdv(&mut self, target: GLenum, query: GLenum, v: &mut [GLdouble]) {
        if let Some(vals) = self.get_map(target, query) {
            for (o, x) in v.iter_mut().zip(vals) {
                *o = x;
            }
        }
    }

    pub(crate) fn get_mapfv(&mut self, target: GLenum, query: GLenum, v: &mut [GLfloat]) {
        if let Some(vals) = self.get_map(target, query) {
            for (o, x) in v.iter_mut().zip(vals) {
                *o = x as f32;
            }
        }
    }

    pub(crate) fn get_mapiv(&mut self, target: GLenum, query: GLenum, v: &mut [GLint]) {
        if let Some(vals) = self.get_map(target, query) {
            for (o, x) in v.iter_mut().zip(vals) {
                // Section 6.1.2: floating-point values are rounded to the nearest integer.
                *o = if x.is_nan() {
                    0
                } else {
                    x.round().clamp(i32::MIN as f64, i32::MAX as f64) as i32
                };
            }
        }
    }

    // ----- evaluation

    fn evaluate1(&self, u: f64) -> Evaluated {
        let mut out = Evaluated::default();
        for t in EvalTarget::ALL {
            if !self.eval.map1_enabled[t.index()] {
                continue;
            }
            let m = &self.eval.map1[t.index()];
            let k = t.components();
            let (b, _) = bernstein(m.order, (u - m.u1) / (m.u2 - m.u1));
            let mut val = [0.0; 4];
            for (i, bi) in b.iter().enumerate() {
                for (c, v) in val.iter_mut().enumerate().take(k) {
                    *v += bi * m.points[i * k + c];
                }
            }
            out.values[t.index()] = Some(val);
        }
        out
    }

    fn evaluate2(&self, u: f64, v: f64) -> Evaluated {
        let mut out = Evaluated::default();
        for t in EvalTarget::ALL {
            if !self.eval.map2_enabled[t.index()] {
                continue;
            }
            let m = &self.eval.map2[t.index()];
            let k = t.components();
            let (du_scale, dv_scale) = (1.0 / (m.u2 - m.u1), 1.0 / (m.v2 - m.v1));
            let (bu, dbu) = bernstein(m.uorder, (u - m.u1) * du_scale);
            let (bv, dbv) = bernstein(m.vorder, (v - m.v1) * dv_scale);
            let mut val = [0.0; 4];
            let mut pu = [0.0; 4];
            let mut pv = [0.0; 4];
            for i in 0..m.uorder {
                for j in 0..m.vorder {
                    let at = (i * m.vorder + j) * k;
                    for c in 0..k {
                        let r = m.points[at + c];
                        val[c] += bu[i] * bv[j] * r;
                        pu[c] += dbu[i] * bv[j] * r;
                        pv[c] += bu[i] * dbv[j] * r;
                    }
                }
            }
            out.values[t.index()] = Some(val);
            let vertex = matches!(t, EvalTarget::Vertex3 | EvalTarget::Vertex4);
            if vertex && self.eval.auto_normal {
                // Derivatives in u and v (not u', v'): the chain rule's 1 / (u2 - u1).
                for c in 0..4 {
                    pu[c] *= du_scale;
                    pv[c] *= dv_scale;
                }
                if t == EvalTarget::Vertex4 {
                    // d(x/w) = (dx w - x dw) / w^2; the positive 1 / w^2 drops out in the
                    // normalization.
                    let w = val[3];
                    for c in 0..3 {
                        pu[c] = pu[c] * w - val[c] * pu[3];
                        pv[c] = pv[c] * w - val[c] * pv[3];
                    }
                }
                let m = [
                    pu[1] * pv[2] - pu[2] * pv[1],
                    pu[2] * pv[0] - pu[0] * pv[2],
                    pu[0] * pv[1] - pu[1] * pv[0],
                ];
                let len = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt();
                // A degenerate patch point (zero cross product) keeps the zero vector.
                let n = if len > 0.0 {
                    [m[0] / len, m[1] / len, m[2] / len]
                } else {
                    m
                };
                // With both vertex maps enabled the 4-component one wins.
                if t == EvalTarget::Vertex4 || out.auto_normal.is_none() {
                    out.auto_normal = Some(n);
                }
            }
        }
        out
    }

    /// Issues the commands of the evaluated values: attributes for this vertex, then the
    /// vertex; the current values are restored afterwards.
    fn emit_evaluated(&mut self, e: Evaluated) {
        let get = |t: EvalTarget| e.values[t.index()];
        let vertex = match (get(EvalTarget::Vertex4), get(EvalTarget::Vertex3)) {
            (Some(p), _) => Vec4::new(p[0] as f32, p[1] as f32, p[2] as f32, p[3] as f32),
            (None, Some(p)) => Vec4::new(p[0] as f32, p[1] as f32, p[2] as f32, 1.0),
            // No vertex map: no vertex, and (the current values being kept) no effect.
            (None, None) => return,
        };
        let saved_current = self.current;
        let saved_materials = self.lighting.materials;
        if let Some(c) = get(EvalTarget::Color4) {
            self.set_color(Vec4::new(
                c[0] as f32,
                c[1] as f32,
                c[2] as f32,
                c[3] as f32,
            ));
        }
        if let Some(i) = get(EvalTarget::Index) {
            self.current.index = i[0] as f32;
        }
        if let Some(n) = e
            .auto_normal
            .or(get(EvalTarget::Normal).map(|n| [n[0], n[1], n[2]]))
        {
            self.current.normal = Vec3::new(n[0] as f32, n[1] as f32, n[2] as f32);
        }
        let tex = [
            (EvalTarget::TexCoord4, 4),
            (EvalTarget::TexCoord3, 3),
            (EvalTarget::TexCoord2, 2),
            (EvalTarget::TexCoord1, 1),
        ]
        .into_iter()
        .find_map(|(t, n)| get(t).map(|v| (v, n)));
        if let Some((v, n)) = tex {
            let c = |i: usize, d: f32| if i < n { v[i] as f32 } else { d };
            self.current.texcoords[0] = Vec4::new(c(0, 0.0), c(1, 0.0), c(2, 0.0), c(3, 1.0));
        }
        self.vertex4(vertex);
        self.current = saved_current;
        self.lighting.materials = saved_materials;
    }

    fn eval_coord1(&mut self, u: f64) {
        let e = self.evaluate1(u);
        self.emit_evaluated(e);
    }

    fn eval_coord2(&mut self, u: f64, v: f64) {
        let e = self.evaluate2(u, v);
        self.emit_evaluated(e);
    }

    pub(crate) fn eval_coord_1f(&mut self, u: GLfloat) {
        self.eval_coord1(u as f64);
    }
    pub(crate) fn eval_coord_1fv(&mut self, u: &[GLfloat; 1]) {
        self.eval_coord1(u[0] as f64);
    }
    pub(crate) fn eval_coord_1d(&mut self, u: GLdouble) {
        self.eval_coord1(u);
    }
    pub(crate) fn eval_coord_1dv(&mut self, u: &[GLdouble; 1]) {
        self.eval_coord1(u[0]);
    }
    pub(crate) fn eval_coord_2f(&mut self, u: GLfloat, v: GLfloat) {
        self.eval_coord2(u as f64, v as f64);
    }
    pub(crate) fn eval_coord_2fv(&mut self, u: &[GLfloat; 2]) {
        self.eval_coord2(u[0] as f64, u[1] as f64);
    }
    pub(crate) fn eval_coord_2d(&mut self, u: GLdouble, v: GLdouble) {
        self.eval_coord2(u, v);
    }
    pub(crate) fn eval_coord_2dv(&mut self, u: &[GLdouble; 2]) {
        self.eval_coord2(u[0], u[1]);
    }

    // ----- grids and meshes

    fn map_grid1(&mut self, un: i32, u1: f64, u2: f64) {
        if un <= 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.eval.grid1 = (un, u1, u2);
    }

    fn map_grid2(&mut self, un: i32, u1: f64, u2: f64, vn: i32, v1: f64, v2: f64) {
        if un <= 0 || vn <= 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.eval.grid2 = (un, u1, u2, vn, v1, v2);
    }

    pub(crate) fn map_grid_1f(&mut self, un: GLint, u1: GLfloat, u2: GLfloat) {
        self.map_grid1(un, u1 as f64, u2 as f64);
    }
    pub(crate) fn map_grid_1d(&mut self, un: GLint, u1: GLdouble, u2: GLdouble) {
        self.map_grid1(un, u1, u2);
    }
    pub(crate) fn map_grid_2f(
        &mut self,
        un: GLint,
        u1: GLfloat,
        u2: GLfloat,
        vn: GLint,
        v1: GLfloat,
        v2: GLfloat,
    ) {
        self.map_grid2(un, u1 as f64, u2 as f64, vn, v1 as f64, v2 as f64);
    }
    pub(crate) fn map_grid_2d(
        &mut self,
        un: GLint,
        u1: GLdouble,
        u2: GLdouble,
        vn: GLint,
        v1: GLdouble,
        v2: GLdouble,
    ) {
        self.map_grid2(un, u1, u2, vn, v1, v2);
    }

    /// Grid coordinate i of `n` segments from `a` to `b`: i * (b - a) / n + a, exactly `b` at
    /// i = n.
    fn grid_value(i: i32, n: i32, a: f64, b: f64) -> f64 {
        if i == n {
            b
        } else {
            i as f64 * ((b - a) / n as f64) + a
        }
    }

    fn grid_u1(&self, i: i32) -> f64 {
        let (n, a, b) = self.eval.grid1;
        Self::grid_value(i, n, a, b)
    }

    fn grid_u2(&self, i: i32) -> f64 {
        let (n, a, b, ..) = self.eval.grid2;
        Self::grid_value(i, n, a, b)
    }

    fn grid_v2(&self, j: i32) -> f64 {
        let (_, _, _, m, a, b) = self.eval.grid2;
        Self::grid_value(j, m, a, b)
    }

    pub(crate) fn eval_mesh_1(&mut self, mode: GLenum, i1: GLint, i2: GLint) {
        let Some(mode) = convert::eval_mesh_mode(mode, false) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.begin(if mode == EvalMeshMode::Point {
            GL_POINTS
        } else {
            GL_LINE_STRIP
        });
        for i in i1..=i2 {
            let u = self.grid_u1(i);
            self.eval_coord1(u);
        }
        self.end();
    }

    pub(crate) fn eval_mesh_2(&mut self, mode: GLenum, i1: GLint, i2: GLint, j1: GLint, j2: GLint) {
        let Some(mode) = convert::eval_mesh_mode(mode, true) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        match mode {
            EvalMeshMode::Point => {
                self.begin(GL_POINTS);
                for j in j1..=j2 {
                    for i in i1..=i2 {
                        let (u, v) = (self.grid_u2(i), self.grid_v2(j));
                        self.eval_coord2(u, v);
                    }
                }
                self.end();
            }
            EvalMeshMode::Line => {
                for j in j1..=j2 {
                    self.begin(GL_LINE_STRIP);
                    for i in i1..=i2 {
                        let (u, v) = (self.grid_u2(i), self.grid_v2(j));
                        self.eval_coord2(u, v);
                    }
                    self.end();
                }
                for i in i1..=i2 {
                    self.begin(GL_LINE_STRIP);
                    for j in j1..=j2 {
                        let (u, v) = (self.grid_u2(i), self.grid_v2(j));
                        self.eval_coord2(u, v);
                    }
                    self.end();
                }
            }
            EvalMeshMode::Fill => {
                let strip = match self.mesh_fill {
                    MeshFill::QuadStrips => GL_QUAD_STRIP,
                    MeshFill::TriangleStrips => GL_TRIANGLE_STRIP,
                };
                for j in j1..j2 {
                    self.begin(strip);
                    for i in i1..=i2 {
                        let (u, v, v_next) =
                            (self.grid_u2(i), self.grid_v2(j), self.grid_v2(j + 1));
                        self.eval_coord2(u, v);
                        self.eval_coord2(u, v_next);
                    }
                    self.end();
                }
            }
        }
    }

    /// Chooses how `glEvalMesh2(GL_FILL, ...)` connects its grid (quad strips, the
    /// specification's definition, unless changed).
    pub fn set_mesh_fill(&mut self, fill: MeshFill) {
        self.mesh_fill = fill;
    }

    /// Chooses how `GL_POINT_SMOOTH` points are drawn (the specification's coverage unless
    /// changed).
    pub fn set_smooth_points(&mut self, points: crate::raster::controls::SmoothPoints) {
        self.smooth_points = points;
    }

    pub(crate) fn eval_point_1(&mut self, i: GLint) {
        let u = self.grid_u1(i);
        self.eval_coord1(u);
    }

    pub(crate) fn eval_point_2(&mut self, i: GLint, j: GLint) {
        let (u, v) = (self.grid_u2(i), self.grid_v2(j));
        self.eval_coord2(u, v);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn binomial(n: usize, k: usize) -> f64 {
        (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
    }

    #[test]
    fn bernstein_basis_and_derivatives_match_the_closed_form() {
        for order in 1..=MAX_EVAL_ORDER as usize {
            let n = order - 1;
            for &t in &[0.0, 0.1, 0.37, 0.5, 0.9, 1.0, -0.5, 1.5] {
                let (b, d) = bernstein(order, t);
                let mut sum = 0.0;
                for i in 0..order {
                    let want = binomial(n, i) * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32);
                    assert!(
                        (b[i] - want).abs() < 1e-9 * want.abs().max(1.0),
                        "B {order} {i} {t}"
                    );
                    sum += b[i];
                    // d/dt t^i (1-t)^(n-i) = i t^(i-1) (1-t)^(n-i) - (n-i) t^i (1-t)^(n-i-1)
                    let a = if i > 0 {
                        i as f64 * t.powi(i as i32 - 1) * (1.0 - t).powi((n - i) as i32)
                    } else {
                        0.0
                    };
                    let c = if i < n {
                        (n - i) as f64 * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32 - 1)
                    } else {
                        0.0
                    };
                    let want_d = binomial(n, i) * (a - c);
                    assert!(
                        (d[i] - want_d).abs() < 1e-7 * want_d.abs().max(1.0),
                        "dB {order} {i} {t}: {} vs {want_d}",
                        d[i]
                    );
                }
                // Outside [0, 1] the terms alternate in sign and grow like (|t| + |1 - t|)^n.
                let scale = (t.abs() + (1.0 - t).abs()).powi(n as i32);
                assert!(
                    (sum - 1.0).abs() < 1e-13 * scale.max(1.0),
                    "{order} {t}: {sum}"
                );
            }
        }
    }

    #[test]
    fn lengths_follow_stride_and_order() {
        assert_eq!(map1_len(GL_MAP1_VERTEX_3, 3, 4), 12);
        assert_eq!(map1_len(GL_MAP1_VERTEX_3, 5, 4), 18);
        assert_eq!(map1_len(GL_MAP1_VERTEX_3, 2, 4), 0);
        assert_eq!(map1_len(GL_MAP1_VERTEX_3, 3, 31), 0);
        assert_eq!(map2_len(GL_MAP2_COLOR_4, 4, 2, 8, 3), 4 + 16 + 4);
        assert_eq!(map2_len(GL_MAP1_COLOR_4, 4, 2, 8, 3), 0);
    }
}

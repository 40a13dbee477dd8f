//! Selection and feedback (OpenGL 1.5 sections 5.2 and 5.3).
//!
//! In `GL_SELECT` and `GL_FEEDBACK` render modes primitives are transformed, lit, clipped and
//! culled as for rendering, then recorded instead of rasterized: selection keeps the smallest
//! and largest window z of every primitive that survives until the name stack changes (a hit
//! record), feedback writes a token and the window-coordinate vertices per primitive.
//!
//! The records are kept in the context and copied to the client's buffer (the pointer given
//! to `glSelectBuffer`/`glFeedbackBuffer`) when `glRenderMode` leaves the mode, where the
//! specification makes the buffer's contents defined. Rust callers may pass a null
//! `ClientPtr` and read the records with [`Context::select_buffer_contents`] and
//! [`Context::feedback_buffer_contents`].

use super::Context;
use crate::common::values::{FeedbackToken, FeedbackType, PrimitiveMode, RenderMode};
use crate::common::values::{PolygonMode, StateExtQuery};
use crate::gl::convert;
use crate::gl::enums::*;
use crate::primitive::assemble::{self, assemble, Primitive};
use crate::primitive::clip::{clip_line, clip_polygon, point_visible, ClipVertex, EXACT};
use crate::primitive::cull::{is_culled, is_front, signed_area2};
use crate::primitive::viewport::to_window;
use crate::state::snapshot::attr;
use crate::state::DrawState;
use crate::vertex::immediate::ImmVertex;
use crate::vertex::transform;

/// `GL_MAX_NAME_STACK_DEPTH`.
pub const MAX_NAME_STACK_DEPTH: usize = 64;

/// Render mode, name stack, buffers and the records of the current or last session.
#[derive(Clone, Debug)]
pub struct SelectState {
    pub(crate) mode: RenderMode,
    select_ptr: ClientPtr,
    select_size: usize,
    select_specified: bool,
    feedback_ptr: ClientPtr,
    feedback_size: usize,
    feedback_type: Option<FeedbackType>,
    names: Vec<GLuint>,
    /// Smallest and largest window z since the last hit record.
    hit: Option<(f64, f64)>,
    hits: i32,
    /// Values generated in this session (may exceed the buffer size: then it overflowed).
    count: usize,
    select_data: Vec<GLuint>,
    feedback_data: Vec<GLfloat>,
    /// Clip w of the current raster position (1 after `glWindowPos`).
    pub(crate) raster_w: f32,
}

impl Default for SelectState {
    fn default() -> Self {
        SelectState {
            mode: RenderMode::Render,
            select_ptr: ClientPtr(0),
            select_size: 0,
            select_specified: false,
            feedback_ptr: ClientPtr(0),
            feedback_size: 0,
            feedback_type: None,
            names: Vec::new(),
            hit: None,
            hits: 0,
            count: 0,
            select_data: Vec::new(),
            feedback_data: Vec::new(),
            raster_w: 1.0,
        }
    }
}

/// A vertex as feedback reports it: window x, y, z, clip w, colour, texture coordinates.
#[derive(Clone, Copy, Debug)]
struct FeedbackVertex {
    win: [f64; 4],
    color: [f32; 4],
    tex: [f32; 4],
}

fn window_coords(ds: &DrawState, c: &ClipVertex) -> [f64; 4] {
    let w = c.pos.w;
    let inv = 1.0 / w;
    [
        c.pos.x * inv * ds.viewport.viewport_scale[0] + ds.viewport.viewport_offset[0],
        c.pos.y * inv * ds.viewport.viewport_scale[1] + ds.viewport.viewport_offset[1],
        c.pos.z * inv * ds.viewport.viewport_scale[2] + ds.viewport.viewport_offset[2],
        w,
    ]
}

fn feedback_vertex(ds: &DrawState, c: &ClipVertex) -> FeedbackVertex {
    let a = &c.attrs;
    let clamp = |v: f32| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
    FeedbackVertex {
        win: window_coords(ds, c),
        color: [a[0], a[1], a[2], a[3]].map(clamp),
        tex: [
            a[attr::TEX],
            a[attr::TEX + 1],
            a[attr::TEX + 2],
            a[attr::TEX + 3],
        ],
    }
}

impl Context {
    // ------------------------------------------------------------------ entry points

    pub(crate) fn select_buffer(&mut self, size: GLsizei, buffer: ClientPtr) {
        if size < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        if self.select.mode == RenderMode::Select {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        let s = &mut self.select;
        s.select_ptr = buffer;
        s.select_size = size as usize;
        s.select_specified = true;
    }

    pub(crate) fn feedback_buffer(&mut self, size: GLsizei, type_: GLenum, buffer: ClientPtr) {
        let Some(t) = convert::feedback_type(type_) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if size < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        if self.select.mode == RenderMode::Feedback {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        let s = &mut self.select;
        s.feedback_ptr = buffer;
        s.feedback_size = size as usize;
        s.feedback_type = Some(t);
    }

    pub(crate) fn render_mode(&mut self, mode: GLenum) -> GLint {
        let Some(new) = convert::render_mode(mode) else {
            self.record_error(GL_INVALID_ENUM);
            return 0;
        };
        let missing_buffer = match new {
            RenderMode::Render => false,
            RenderMode::Select => !self.select.select_specified,
            RenderMode::Feedback => self.select.feedback_type.is_none(),
        };
        if missing_buffer {
            self.record_error(GL_INVALID_OPERATION);
            return 0;
        }
        let result = match self.select.mode {
            RenderMode::Render => 0,
            RenderMode::Select => {
                self.write_hit_record();
                let s = &self.select;
                let bytes: Vec<u8> = s.select_data.iter().flat_map(|v| v.to_ne_bytes()).collect();
                self.client_memory.write(s.select_ptr, &bytes);
                if s.count > s.select_size {
                    -1
                } else {
                    s.hits
                }
            }
            RenderMode::Feedback => {
                let s = &self.select;
                let bytes: Vec<u8> = s
                    .feedback_data
                    .iter()
                    .flat_map(|v| v.to_ne_bytes())
                    .collect();
                self.client_memory.write(s.feedback_ptr, &bytes);
                if s.count > s.feedback_size {
                    -1
                } else {
                    s.count.min(i32::MAX as usize) as GLint
                }
            }
        };
        let s = &mut self.select;
        s.count = 0;
        s.hits = 0;
        s.hit = None;
        s.names.clear();
        match new {
            RenderMode::Select => s.select_data.clear(),
            RenderMode::Feedback => s.feedback_data.clear(),
            RenderMode::Render => {}
        }
        s.mode = new;
        self.invalidate();
        result
    }

    pub(crate) fn init_names(&mut self) {
        if self.select.mode != RenderMode::Select {
            return;
        }
        self.write_hit_record();
        self.select.names.clear();
    }

    pub(crate) fn push_name(&mut self, name: GLuint) {
        if self.select.mode != RenderMode::Select {
            return;
        }
        self.write_hit_record();
        if self.select.names.len() >= MAX_NAME_STACK_DEPTH {
            self.record_error(GL_STACK_OVERFLOW);
            return;
        }
        self.select.names.push(name);
    }

    pub(crate) fn pop_name(&mut self) {
        if self.select.mode != RenderMode::Select {
            return;
        }
        self.write_hit_record();
        if self.select.names.pop().is_none() {
            self.record_error(GL_STACK_UNDERFLOW);
        }
    }

    pub(crate) fn load_name(&mut self, name: GLuint) {
        if self.select.mode != RenderMode::Select {
            return;
        }
        if self.select.names.is_empty() {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        self.write_hit_record();
        if let Some(top) = self.select.names.last_mut() {
            *top = name;
        }
    }

    pub(crate) fn pass_through(&mut self, token: GLfloat) {
        if self.select.mode == RenderMode::Feedback {
            self.feedback_value(FeedbackToken::PassThrough.to_gl() as f32);
            self.feedback_value(token);
        }
    }

    // ------------------------------------------------------------------ Rust access

    /// The render mode (`GL_RENDER`, `GL_SELECT` or `GL_FEEDBACK`).
    pub fn render_mode_enum(&self) -> GLenum {
        self.select.mode.to_gl()
    }

    /// The selection records of the current or last selection session, as written to the
    /// select buffer (at most its size).
    pub fn select_buffer_contents(&self) -> &[GLuint] {
        &self.select.select_data
    }

    /// The feedback values of the current or last feedback session, as written to the
    /// feedback buffer (at most its size).
    pub fn feedback_buffer_contents(&self) -> &[GLfloat] {
        &self.select.feedback_data
    }

    /// `GL_SELECTION_BUFFER_POINTER` and `GL_FEEDBACK_BUFFER_POINTER` for `glGetPointerv`.
    pub(crate) fn select_buffer_pointer(&self, pname: GLenum) -> Option<ClientPtr> {
        Some(match convert::render_buffer_pointer(pname)? {
            RenderMode::Select => self.select.select_ptr,
            _ => self.select.feedback_ptr,
        })
    }

    pub(crate) fn select_state_value(&self, q: StateExtQuery) -> super::get::StateValue {
        use super::get::StateValue::*;
        let s = &self.select;
        match q {
            StateExtQuery::RenderMode => Enum(s.mode.to_gl()),
            StateExtQuery::NameStackDepth => Ints(vec![s.names.len() as i64]),
            StateExtQuery::MaxNameStackDepth => Ints(vec![MAX_NAME_STACK_DEPTH as i64]),
            StateExtQuery::FeedbackBufferSize => Ints(vec![s.feedback_size as i64]),
            StateExtQuery::FeedbackBufferType => {
                Enum(s.feedback_type.unwrap_or(FeedbackType::T2D).to_gl())
            }
            StateExtQuery::SelectionBufferSize => Ints(vec![s.select_size as i64]),
            _ => Ints(vec![0]),
        }
    }

    // ------------------------------------------------------------------ records

    fn select_value(&mut self, v: GLuint) {
        let s = &mut self.select;
        if s.count < s.select_size {
            s.select_data.push(v);
        }
        s.count += 1;
    }

    fn feedback_value(&mut self, v: GLfloat) {
        let s = &mut self.select;
        if s.count < s.feedback_size {
            s.feedback_data.push(v);
        }
        s.count += 1;
    }

    /// Writes the pending hit record, if there was a hit: the name count, the smallest and
    /// largest window z times 2^32 - 1 rounded to the nearest integer, the names from the
    /// bottom of the stack.
    fn write_hit_record(&mut self) {
        let Some((lo, hi)) = self.select.hit.take() else {
            return;
        };
        let scale = |z: f64| (z.clamp(0.0, 1.0) * 4294967295.0).round() as GLuint;
        let names = self.select.names.clone();
        self.select_value(names.len() as GLuint);
        self.select_value(scale(lo));
        self.select_value(scale(hi));
        for n in names {
            self.select_value(n);
        }
        self.select.hits += 1;
    }

    fn record_hit(&mut self, z: f64) {
        let s = &mut self.select;
        s.hit = Some(match s.hit {
            Some((lo, hi)) => (lo.min(z), hi.max(z)),
            None => (z, z),
        });
    }

    fn emit_vertex(&mut self, v: &FeedbackVertex) {
        let Some(t) = self.select.feedback_type else {
            return;
        };
        let [x, y, z, w] = v.win.map(|c| c as f32);
        let (coords, color, tex): (&[f32], bool, bool) = match t {
            FeedbackType::T2D => (&[x, y], false, false),
            FeedbackType::T3D => (&[x, y, z], false, false),
            FeedbackType::T3DColor => (&[x, y, z], true, false),
            FeedbackType::T3DColorTexture => (&[x, y, z], true, true),
            FeedbackType::T4DColorTexture => (&[x, y, z, w], true, true),
        };
        for &c in coords {
            self.feedback_value(c);
        }
        if color {
            for c in v.color {
                self.feedback_value(c);
            }
        }
        if tex {
            for c in v.tex {
                self.feedback_value(c);
            }
        }
    }

    /// One primitive's vertices: a hit with their z range, or a feedback token (and for
    /// polygons the vertex count) followed by the vertices.
    fn emit_primitive(&mut self, token: FeedbackToken, verts: &[FeedbackVertex]) {
        match self.select.mode {
            RenderMode::Select => {
                for v in verts {
                    self.record_hit(v.win[2]);
                }
            }
            RenderMode::Feedback => {
                self.feedback_value(token.to_gl() as f32);
                if token == FeedbackToken::Polygon {
                    self.feedback_value(verts.len() as f32);
                }
                for v in verts {
                    self.emit_vertex(v);
                }
            }
            RenderMode::Render => {}
        }
    }

    // ------------------------------------------------------------------ hooks

    /// `glDrawPixels`, `glCopyPixels` and `glBitmap` outside render mode: a hit at the raster
    /// position's z or the token with the raster position, when it is valid. Returns true
    /// when the caller must not draw.
    pub(crate) fn pixel_op_feedback(&mut self, token: FeedbackToken) -> bool {
        if self.select.mode == RenderMode::Render {
            return false;
        }
        if self.raster_pos.valid {
            let r = self.raster_pos;
            let v = FeedbackVertex {
                win: [
                    r.window[0],
                    r.window[1],
                    r.window[2],
                    self.select.raster_w as f64,
                ],
                color: r.color,
                tex: r.texcoords[0],
            };
            self.emit_primitive(token, std::slice::from_ref(&v));
        }
        true
    }

    /// After `glRasterPos`/`glWindowPos`: remembers the clip w (`None` for a window position)
    /// and, in selection mode, a valid position is a hit.
    pub(crate) fn raster_pos_feedback(&mut self, position: Option<glam::Vec4>) {
        self.select.raster_w = match position {
            Some(p) => (self.snapshot().vertex.mvp * p).w,
            None => 1.0,
        };
        if self.select.mode == RenderMode::Select && self.raster_pos.valid {
            let z = self.raster_pos.window[2];
            self.record_hit(z);
        }
    }

    /// A batch of vertices in selection or feedback mode: transformed, clipped, culled and
    /// recorded instead of rasterized.
    pub(crate) fn select_feedback_vertices(&mut self, mode: PrimitiveMode, verts: &[ImmVertex]) {
        let ds = self.snapshot();
        let mut clip: Vec<ClipVertex> = verts
            .iter()
            .map(|v| transform::to_clip(&ds.vertex, v))
            .collect();
        // Feedback reports unit 0's texture coordinates even when the unit does not texture.
        if !ds.vertex.units.iter().any(|u| u.unit == 0) {
            let m = *self.transform.texture[0]
                .last()
                .unwrap_or(&glam::Mat4::IDENTITY);
            for (c, v) in clip.iter_mut().zip(verts) {
                let t = (m * v.texcoords[0]).to_array();
                c.attrs[attr::TEX..attr::TEX + 4].copy_from_slice(&t);
            }
        }
        let n_attrs = ds.clip_attr_count.max(attr::TEX + 4);
        let user = ds.viewport.clip_planes.clone();
        let edge_flags = assemble::uses_edge_flags(mode);
        let mut reset = true;
        for prim in assemble(mode, clip.len()) {
            match prim {
                Primitive::Point(i) => {
                    if point_visible(&clip[i], &user) {
                        let v = feedback_vertex(&ds, &clip[i]);
                        self.emit_primitive(FeedbackToken::Point, &[v]);
                    }
                }
                Primitive::Line { v, provoking } => {
                    let (mut a, mut b) = (clip[v[0]], clip[v[1]]);
                    if ds.tile.flat {
                        copy_colors(&mut a, &clip[provoking]);
                        copy_colors(&mut b, &clip[provoking]);
                    }
                    if mode == PrimitiveMode::Lines {
                        reset = true;
                    }
                    if let Some((a, b)) = clip_line(&a, &b, &user, n_attrs) {
                        let token = if std::mem::take(&mut reset) {
                            FeedbackToken::LineReset
                        } else {
                            FeedbackToken::Line
                        };
                        let vs = [feedback_vertex(&ds, &a), feedback_vertex(&ds, &b)];
                        self.emit_primitive(token, &vs);
                    }
                }
                Primitive::Triangle {
                    v,
                    provoking,
                    edges,
                } => {
                    let mut poly: Vec<ClipVertex> = v.iter().map(|&i| clip[i]).collect();
                    for (k, p) in poly.iter_mut().enumerate() {
                        p.edge = edges[k] && (p.edge || !edge_flags);
                        if ds.tile.flat {
                            copy_colors(p, &clip[provoking]);
                        }
                    }
                    let mut scratch = Vec::new();
                    if !clip_polygon(&mut poly, &mut scratch, &user, EXACT, n_attrs)
                        || poly.len() < 3
                    {
                        continue;
                    }
                    let xy: Vec<[i64; 2]> =
                        poly.iter().map(|p| to_window(&ds.viewport, p).xy).collect();
                    // A polygon of zero area is still a primitive (section 5.3 reports what
                    // would be rasterized): back-facing, as the sign test of section 3.5.1
                    // gives for a = 0 (Mesa reports and culls it so too).
                    let front = is_front(signed_area2(&xy), ds.front_face);
                    if is_culled(ds.cull, front) {
                        continue;
                    }
                    if ds.vertex.two_sided && !front {
                        for p in poly.iter_mut() {
                            crate::vertex::use_back_colors(&mut p.attrs);
                        }
                    }
                    let fv: Vec<FeedbackVertex> =
                        poly.iter().map(|p| feedback_vertex(&ds, p)).collect();
                    match ds.tile.raster.polygon_mode[usize::from(!front)] {
                        PolygonMode::Fill => {
                            // As a fan of triangles, the way Mesa's pipeline reports them.
                            for k in 1..fv.len() - 1 {
                                let tri = [fv[0], fv[k], fv[k + 1]];
                                self.emit_primitive(FeedbackToken::Polygon, &tri);
                            }
                        }
                        PolygonMode::Line => {
                            let n = fv.len();
                            let mut first = true;
                            for k in 0..n {
                                if !poly[k].edge {
                                    continue;
                                }
                                let token = if std::mem::take(&mut first) {
                                    FeedbackToken::LineReset
                                } else {
                                    FeedbackToken::Line
                                };
                                let j = (k + 1) % n;
                                self.emit_primitive(token, &[fv[k], fv[j]]);
                            }
                        }
                        PolygonMode::Point => {
                            for (k, v) in fv.iter().enumerate() {
                                if poly[k].edge {
                                    self.emit_primitive(FeedbackToken::Point, &[*v]);
                                }
                            }
                        }
                    }
                }
            }
        }
    }
}

/// Flat shading: the provoking vertex's colours (front and back).
fn copy_colors(v: &mut ClipVertex, provoking: &ClipVertex) {
    attr::copy_colors(&mut v.attrs, &provoking.attrs);
    v.attrs[attr::BACK..attr::COUNT].copy_from_slice(&provoking.attrs[attr::BACK..attr::COUNT]);
}

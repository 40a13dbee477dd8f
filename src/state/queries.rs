//! Occlusion queries (OpenGL 1.5 section 4.1.6, 6.1.12): `GL_SAMPLES_PASSED` counts the
//! fragments (there is no multisample buffer: one sample each) that pass the depth and stencil
//! tests between `glBeginQuery` and `glEndQuery`.
//!
//! While a query is active the snapshot's `FragmentKey::count_samples` is set: such draws take
//! the general span path, which adds each passing fragment to its tile's counter (tiles are
//! shaded in parallel, each owning its counter). `glBeginQuery` and `glEndQuery` flush the
//! scene; the end sums and clears the tile counters, so a result is available at once.

use std::collections::{HashMap, HashSet};

use super::Context;
use crate::common::values::{QueryObjectParam, QueryParam};
use crate::gl::convert;
use crate::gl::enums::*;

/// `GL_QUERY_COUNTER_BITS`: results are kept in 64 bits.
pub const QUERY_COUNTER_BITS: i32 = 64;

/// Query object names and results.
#[derive(Clone, Debug, Default)]
pub struct QueryState {
    /// Objects that have been begun at least once: name -> last result.
    objects: HashMap<GLuint, u64>,
    /// Names from `glGenQueries` not yet used by `glBeginQuery`.
    reserved: HashSet<GLuint>,
    next_name: GLuint,
    /// The active `GL_SAMPLES_PASSED` query.
    pub(crate) active: Option<GLuint>,
}

impl Context {
    /// Sums and clears the per-tile sample counters after finishing pending work.
    fn take_samples_passed(&mut self) -> u64 {
        self.flush_scene();
        self.framebuffer
            .tiles
            .iter_mut()
            .map(|t| std::mem::take(&mut t.samples_passed))
            .sum()
    }

    pub(crate) fn gen_queries(&mut self, n: GLsizei, ids: &mut [GLuint]) {
        if n < 0 || ids.len() < n as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let q = &mut self.queries;
        for slot in &mut ids[..n as usize] {
            loop {
                q.next_name = q.next_name.wrapping_add(1);
                let name = q.next_name;
                if name != 0 && !q.objects.contains_key(&name) && !q.reserved.contains(&name) {
                    break;
                }
            }
            q.reserved.insert(q.next_name);
            *slot = q.next_name;
        }
    }

    pub(crate) fn delete_queries(&mut self, n: GLsizei, ids: &[GLuint]) {
        if n < 0 || ids.len() < n as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        for &id in &ids[..n as usize] {
            if id == 0 {
                continue;
            }
            if self.queries.active == Some(id) {
                // Deleting the active query ends it (as Mesa does).
                self.take_samples_passed();
                self.queries.active = None;
                self.invalidate();
            }
            self.queries.objects.remove(&id);
            self.queries.reserved.remove(&id);
        }
    }

    pub(crate) fn is_query(&mut self, id: GLuint) -> GLboolean {
        // A generated name becomes a query object at its first glBeginQuery.
        (id != 0 && self.queries.objects.contains_key(&id)) as GLboolean
    }

    pub(crate) fn begin_query(&mut self, target: GLenum, id: GLuint) {
        if convert::query_target(target).is_none() {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        if id == 0 || self.queries.active.is_some() {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        // Work drawn before the query must not count.
        self.take_samples_passed();
        self.queries.reserved.remove(&id);
        self.queries.objects.insert(id, 0);
        self.queries.active = Some(id);
        self.invalidate();
    }

    pub(crate) fn end_query(&mut self, target: GLenum) {
        // The generated guard lets glEnd* through inside glBegin/glEnd; this one may not be.
        if self.reject_inside_begin_end() {
            return;
        }
        if convert::query_target(target).is_none() {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        let Some(id) = self.queries.active else {
            self.record_error(GL_INVALID_OPERATION);
            return;
        };
        let samples = self.take_samples_passed();
        self.queries.objects.insert(id, samples);
        self.queries.active = None;
        self.invalidate();
    }

    pub(crate) fn get_queryiv(&mut self, target: GLenum, pname: GLenum, params: &mut [GLint]) {
        let (Some(()), Some(p)) = (convert::query_target(target), convert::query_param(pname))
        else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let v = match p {
            QueryParam::CurrentQuery => self.queries.active.unwrap_or(0) as GLint,
            QueryParam::CounterBits => QUERY_COUNTER_BITS,
        };
        if let Some(out) = params.first_mut() {
            *out = v;
        }
    }

    /// The value of `glGetQueryObject*v`, or the error.
    fn query_object_value(&mut self, id: GLuint, pname: GLenum) -> Option<u64> {
        let Some(p) = convert::query_object_param(pname) else {
            self.record_error(GL_INVALID_ENUM);
            return None;
        };
        let Some(&result) = self.queries.objects.get(&id) else {
            self.record_error(GL_INVALID_OPERATION);
            return None;
        };
        if self.queries.active == Some(id) {
            self.record_error(GL_INVALID_OPERATION);
            return None;
        }
        Some(match p {
            QueryObjectParam::Result => result,
            // Results are computed at glEndQuery.
            QueryObjectParam::ResultAvailable => 1,
        })
    }

    pub(crate) fn get_query_objectiv(&mut self, id: GLuint, pname: GLenum, params: &mut [GLint]) {
        if let Some(v) = self.query_object_value(id, pname) {
            if let Some(out) = params.first_mut() {
                *out = v.min(i32::MAX as u64) as GLint;
            }
        }
    }

    pub(crate) fn get_query_objectuiv(&mut self, id: GLuint, pname: GLenum, params: &mut [GLuint]) {
        if let Some(v) = self.query_object_value(id, pname) {
            if let Some(out) = params.first_mut() {
                *out = v.min(u32::MAX as u64) as GLuint;
            }
        }
    }

    /// The result of query `id` (Rust convenience; `None` for no such query or an active one).
    pub fn query_result(&self, id: GLuint) -> Option<u64> {
        if self.queries.active == Some(id) {
            return None;
        }
        self.queries.objects.get(&id).copied()
    }
}

//! Display lists (section 5.4): `glNewList`/`glEndList`, `glCallList(s)`, `glGenLists`,
//! `glDeleteLists`, `glIsList`, `glListBase`.
//!
//! # Design
//!
//! A display list is a sequence of boxed closures, each holding a copy of one call's argument
//! values and replaying that call through the `Gl` trait on the context. The recording is
//! generated: `build.rs` gives every forwarded entry point that section 5.4 lets a list hold a
//! prologue that, while a list is being compiled, copies the arguments (slices and arrays by
//! value) into such a closure (`Context::list_record`) and, in `GL_COMPILE` mode, returns
//! without executing. Commands the specification executes immediately (`glGen*`, `glIs*`,
//! `glGet*`, `glReadPixels`, `glPixelStore`, client state and pointer calls, buffer object
//! calls, `glFlush`/`glFinish`, `glNewList`/`glEndList`/`glDeleteLists`, ...) have no prologue.
//! The vertex-array draw commands (`glArrayElement`, `glDrawArrays`, `glDrawElements`, ...)
//! record themselves (`state::arrays`): the arrays are dereferenced at compile time and the list
//! keeps the resulting vertices.
//!
//! Because a recorded call goes through the same trait method as a direct call, executing a
//! list is exactly the same as making its calls, errors included (they are raised at execution,
//! as the specification asks). Entry points not implemented yet (the trait's default) record
//! their `GL_INVALID_OPERATION` immediately instead of at execution.
//!
//! Calls made while a list executes are never recorded (so `glCallList` inside a list compiled
//! with `GL_COMPILE_AND_EXECUTE` is recorded once, as a call). Execution nests up to
//! `GL_MAX_LIST_NESTING` (64) levels; deeper `glCallList`s are ignored.
//!
//! Known simplification: pixel data of `glTexImage*`/`glPolygonStipple`-style calls is copied
//! as bytes at compile time and unpacked at execution time, so a `glPixelStore` change between
//! compiling and executing such a list changes how its image is read.

use std::collections::BTreeMap;
use std::sync::Arc;

use parking_lot::RwLock;

use super::Context;
use crate::common::values::ListNameType;
use crate::gl::convert;
use crate::gl::enums::*;

/// `GL_MAX_LIST_NESTING`.
pub const MAX_LIST_NESTING: u32 = 64;

/// Largest `range` of one `glGenLists` (larger requests are `GL_OUT_OF_MEMORY`).
const MAX_GEN_LISTS: i64 = 1 << 22;

/// One recorded command of a display list.
pub(crate) type ListCommand = Box<dyn Fn(&mut Context) + Send + Sync>;

/// A compiled display list.
pub(crate) type List = Arc<Vec<ListCommand>>;

/// The display lists of a share group: every context created sharing objects with another
/// holds the same `Arc`. A list runs from its own `Arc` after the lookup, so the lock is held
/// only to find, define or delete lists.
#[derive(Default)]
pub struct ListNames {
    lists: BTreeMap<GLuint, List>,
    /// The largest name ever defined or generated: `glGenLists` hands out names above it
    /// while it can (deleted names are not reused at once, as in Mesa).
    high: GLuint,
}

/// Display-list state: the lists, the one being compiled, `glListBase`, execution depth.
#[derive(Default)]
pub struct ListState {
    names: Arc<RwLock<ListNames>>,
    /// The list being compiled: name, `GL_COMPILE_AND_EXECUTE`, commands so far.
    compiling: Option<(GLuint, bool, Vec<ListCommand>)>,
    /// Nesting depth of list execution (0 outside `glCallList`).
    depth: u32,
    base: GLuint,
}

impl std::fmt::Debug for ListState {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ListState")
            .field("lists", &self.names.read().lists.len())
            .field("compiling", &self.compiling.as_ref().map(|c| (c.0, c.1)))
            .field("depth", &self.depth)
            .field("base", &self.base)
            .finish()
    }
}

impl ListState {
    /// The display lists (the share group's handle).
    pub(crate) fn names(&self) -> &Arc<RwLock<ListNames>> {
        &self.names
    }

    /// Uses the display lists of a share group (for a new context).
    pub(crate) fn set_names(&mut self, names: Arc<RwLock<ListNames>>) {
        self.names = names;
    }

    /// `GL_LIST_BASE`.
    pub fn base(&self) -> GLuint {
        self.base
    }

    /// `GL_LIST_INDEX`: the name of the list being compiled, or 0.
    pub fn index(&self) -> GLuint {
        self.compiling.as_ref().map_or(0, |c| c.0)
    }

    /// `GL_LIST_MODE`: `GL_COMPILE`, `GL_COMPILE_AND_EXECUTE`, or 0 when not compiling.
    pub fn mode(&self) -> GLenum {
        match &self.compiling {
            None => 0,
            Some((_, false, _)) => GL_COMPILE,
            Some((_, true, _)) => GL_COMPILE_AND_EXECUTE,
        }
    }
}

impl Context {
    /// True while a display list executes (inside `glCallList`/`glCallLists`).
    #[inline]
    pub(crate) fn list_executing(&self) -> bool {
        self.lists.depth > 0
    }

    /// True while calls are recorded into a list (compiling, and not executing a list).
    #[inline]
    pub(crate) fn list_recording(&self) -> bool {
        self.lists.compiling.is_some() && self.lists.depth == 0
    }

    /// True when the list being compiled is `GL_COMPILE` (record only, do not execute).
    #[inline]
    pub(crate) fn list_compile_only(&self) -> bool {
        matches!(self.lists.compiling, Some((_, false, _)))
    }

    /// Appends a command to the list being compiled.
    pub(crate) fn list_record(&mut self, cmd: ListCommand) {
        if let Some((_, _, cmds)) = &mut self.lists.compiling {
            cmds.push(cmd);
        }
    }

    /// Records an error for a call that is compiled: when compiling, the list raises it when
    /// executed (and, with `GL_COMPILE_AND_EXECUTE`, it is raised now too); otherwise now.
    pub(crate) fn list_aware_error(&mut self, error: GLenum) {
        if self.list_recording() {
            self.list_record(Box::new(move |ctx: &mut Context| ctx.record_error(error)));
            if self.list_compile_only() {
                return;
            }
        }
        self.record_error(error);
    }

    pub(crate) fn gen_lists(&mut self, range: GLsizei) -> GLuint {
        if range < 0 {
            self.record_error(GL_INVALID_VALUE);
            return 0;
        }
        if range == 0 {
            return 0;
        }
        if range as i64 > MAX_GEN_LISTS {
            self.record_error(GL_OUT_OF_MEMORY);
            return 0;
        }
        // Above every name used so far; when that overflows, the first run of `range` unused
        // names (names are used once defined or generated).
        let mut names = self.lists.names.write();
        let mut start: u64 = names.high as u64 + 1;
        if start + range as u64 - 1 > u32::MAX as u64 {
            start = 1;
        }
        loop {
            let end = start + range as u64 - 1;
            if end > u32::MAX as u64 {
                drop(names);
                self.record_error(GL_OUT_OF_MEMORY);
                return 0;
            }
            match names.lists.range(start as u32..=end as u32).next_back() {
                Some((&used, _)) => start = used as u64 + 1,
                None => break,
            }
        }
        let empty: List = Arc::new(Vec::new());
        for name in start..start + range as u64 {
            names.lists.insert(name as u32, empty.clone());
        }
        names.high = names.high.max((start + range as u64 - 1) as GLuint);
        start as GLuint
    }

    pub(crate) fn new_list(&mut self, list: GLuint, mode: GLenum) {
        if list == 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let Some(execute) = convert::list_mode(mode) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if self.lists.compiling.is_some() {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        self.lists.compiling = Some((list, execute, Vec::new()));
    }

    pub(crate) fn end_list(&mut self) {
        let Some((name, _, cmds)) = self.lists.compiling.take() else {
            self.record_error(GL_INVALID_OPERATION);
            return;
        };
        let mut names = self.lists.names.write();
        names.lists.insert(name, Arc::new(cmds));
        names.high = names.high.max(name);
    }

    pub(crate) fn call_list(&mut self, list: GLuint) {
        if self.lists.depth >= MAX_LIST_NESTING {
            return;
        }
        let Some(l) = self.lists.names.read().lists.get(&list).cloned() else {
            return;
        };
        self.lists.depth += 1;
        for cmd in l.iter() {
            cmd(self);
        }
        self.lists.depth -= 1;
    }

    pub(crate) fn call_lists(&mut self, n: GLsizei, type_: GLenum, lists: Option<&[u8]>) {
        if n < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let Some(ty) = convert::list_name_type(type_) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let Some(bytes) = lists else {
            return;
        };
        let size = ty.size();
        if bytes.len() / size < n as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        for i in 0..n as usize {
            let b = &bytes[i * size..(i + 1) * size];
            let name = list_name(ty, b);
            self.call_list(self.lists.base.wrapping_add(name));
        }
    }

    pub(crate) fn list_base(&mut self, base: GLuint) {
        self.lists.base = base;
    }

    pub(crate) fn delete_lists(&mut self, list: GLuint, range: GLsizei) {
        if range < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        if range == 0 {
            return;
        }
        let end = (list as u64 + range as u64 - 1).min(u32::MAX as u64) as u32;
        let mut names = self.lists.names.write();
        let doomed: Vec<GLuint> = names.lists.range(list..=end).map(|(&k, _)| k).collect();
        for k in doomed {
            names.lists.remove(&k);
        }
    }

    pub(crate) fn is_list(&mut self, list: GLuint) -> GLboolean {
        self.lists.names.read().lists.contains_key(&list) as GLboolean
    }
}

/// A `glCallLists` name (before adding the list base) from its bytes.
fn list_name(ty: ListNameType, b: &[u8]) -> GLuint {
    use ListNameType::*;
    match ty {
        Byte => b[0] as i8 as i32 as u32,
        UnsignedByte => b[0] as u32,
        Short => i16::from_ne_bytes([b[0], b[1]]) as i32 as u32,
        UnsignedShort => u16::from_ne_bytes([b[0], b[1]]) as u32,
        Int => i32::from_ne_bytes([b[0], b[1], b[2], b[3]]) as u32,
        UnsignedInt => u32::from_ne_bytes([b[0], b[1], b[2], b[3]]),
        Float => f32::from_ne_bytes([b[0], b[1], b[2], b[3]]) as i64 as u32,
        // Section 5.4: the bytes are most significant first.
        Bytes(_) => b.iter().fold(0u32, |acc, &x| (acc << 8) | x as u32),
    }
}

//! The GL API surface: the `Gl` trait (one method per GL 1.5 entry point, generated from the
//! Khronos registry), the entry-point table, and `Context`'s implementation of the trait.
//! The GL vocabulary (types, enums, their conversion, the error flag) is in `crate::gl`,
//! re-exported here under its old paths.

pub use crate::gl::types::*;
pub use crate::gl::{convert, enums, error, types};

include!(concat!(env!("OUT_DIR"), "/commands.rs"));

/// One parameter of a GL entry point, as the registry declares it.
#[derive(Clone, Copy, Debug)]
pub struct ParamInfo {
    /// Parameter name in the registry.
    pub name: &'static str,
    /// C type, e.g. `const GLfloat *`.
    pub c_type: &'static str,
    /// Registry enum group, where given.
    pub group: Option<&'static str>,
    /// Registry length expression for pointers (`"3"`, `"n"`, `"COMPSIZE(pname)"`).
    pub len: Option<&'static str>,
}

/// One GL entry point.
#[derive(Clone, Copy, Debug)]
pub struct CommandInfo {
    /// GL name, e.g. `glTexImage2D`.
    pub name: &'static str,
    /// The `Gl` trait method name, e.g. `tex_image_2d`.
    pub rust_name: &'static str,
    /// Parameters in order.
    pub params: &'static [ParamInfo],
    /// C return type.
    pub returns: &'static str,
    /// ARB/EXT names of the same function.
    pub aliases: &'static [&'static str],
    /// Whether the call is legal between `glBegin` and `glEnd`.
    pub allowed_in_begin_end: bool,
}

/// Looks an entry point up by its GL name or one of its ARB/EXT aliases.
pub fn command(name: &str) -> Option<&'static CommandInfo> {
    if let Ok(i) = COMMANDS.binary_search_by(|c| c.name.cmp(name)) {
        return Some(&COMMANDS[i]);
    }
    COMMANDS.iter().find(|c| c.aliases.contains(&name))
}

// After the generated `gl_forward_all!` it uses (macros are in scope from their definition on).
mod context;

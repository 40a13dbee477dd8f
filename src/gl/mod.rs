//! The GL vocabulary the state machine speaks: the C types of `GL/gl.h`, the enum constants,
//! their conversion to the typed values of `common::values`, and the sticky error flag.
//!
//! Only `api` (the entry-point surface) and `state` (the state machine behind it) use this
//! module: the pipeline stages below them see typed values, never a GL enum
//! (`tests/module_deps.rs` ranks it between `state` and `vertex`).

pub mod convert;
pub mod enums;
pub mod error;
pub mod types;

pub use types::*;

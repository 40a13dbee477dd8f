//! Primitive assembly, clipping, culling and the viewport mapping.

pub mod assemble;
pub mod clip;
pub mod cull;
pub mod viewport;

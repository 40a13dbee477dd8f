//! What every stage shares, below all of them in the dependency order: run-time CPU features,
//! implementation limits, fixed-point conversions, pixel rectangles and the typed values of GL
//! state. It uses no other module of the crate.

pub mod cpu;
pub mod fixed;
pub mod limits;
pub mod rect;
pub mod values;

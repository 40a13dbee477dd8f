//! What every stage shares, below all of them in the dependency order: run-time CPU features
//! and the typed values of GL state.

pub mod cpu;
pub mod values;

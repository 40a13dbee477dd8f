//! What every stage shares, below all of them in the dependency order: run-time CPU features.

pub mod cpu;

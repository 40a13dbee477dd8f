//! The fragment stage: per-draw specialised span functions that test and write fragments.
//! A stage that the draw's state disables is absent from the chosen function.

pub mod blend;
pub mod bytenv;
pub mod cache;
pub mod cascade;
pub mod draw;
pub mod fog;
pub mod key;
pub mod plane;
pub mod simd;
pub mod span;
pub mod texenv;

//! The differential tolerance: when a tilegl picture counts as matching Mesa's.
//! The rule and the llvmpipe-vs-softpipe measurements behind it are in `conformance/TOLERANCE.md`.

pub use tilegl::compare::Tolerance;

/// The tolerance of the differential suite (see TOLERANCE.md).
pub const DIFFERENTIAL: Tolerance = Tolerance {
    channel: 8,
    max_bad_share: 0.001,
};

//! The differential tolerance: when a tilegl picture counts as matching Mesa's.
//! The rule and the llvmpipe-vs-softpipe measurements behind it are in `conformance/TOLERANCE.md`.

use std::fmt;

use crate::compare::Diff;

/// A pixel is bad when its largest channel difference exceeds `channel`; a picture matches when
/// at most `max_bad_share` of its pixels are bad.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// Per-channel threshold (0-255).
    pub channel: u8,
    /// Largest accepted share (0-1) of bad pixels.
    pub max_bad_share: f64,
}

impl Tolerance {
    /// Whether `diff` (computed with this tolerance's threshold) is acceptable.
    pub fn accepts(&self, diff: &Diff) -> bool {
        diff.threshold <= self.channel && diff.bad_share <= self.max_bad_share
    }
}

impl fmt::Display for Tolerance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "bad(>{}) <= {:.3}%",
            self.channel,
            self.max_bad_share * 100.0
        )
    }
}

/// The tolerance of the differential suite (see TOLERANCE.md).
pub const DIFFERENTIAL: Tolerance = Tolerance {
    channel: 8,
    max_bad_share: 0.001,
};

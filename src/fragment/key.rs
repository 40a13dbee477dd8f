//! `FragmentKey`: the static fragment state of a draw (`Copy + Eq + Hash`), simplified before
//! a span function is chosen for it.

use crate::api::convert::CompareFunc;
use crate::state::tables::FragmentOpsState;

/// What the fragment stage must do, with redundant state folded away.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FragmentKey {
    /// The depth test, or `None` when it cannot reject anything and writes nothing.
    pub depth_func: Option<CompareFunc>,
    /// Whether passing fragments write depth.
    pub depth_write: bool,
    /// Per-channel colour write enables (R, G, B, A).
    pub color_mask: [bool; 4],
}

impl FragmentKey {
    /// The key for the current per-fragment state. Simplifications (section 4.1.5 and 4.2.2):
    /// a disabled depth test neither tests nor writes; without a depth buffer the test always
    /// passes; `ALWAYS` without writes is no test at all.
    pub fn from_state(ops: &FragmentOpsState, has_depth_buffer: bool) -> FragmentKey {
        let enabled = ops.depth_test && has_depth_buffer;
        let mut depth_func = enabled.then_some(ops.depth_func);
        let depth_write = enabled && ops.depth_mask;
        if depth_func == Some(CompareFunc::Always) && !depth_write {
            depth_func = None;
        }
        FragmentKey {
            depth_func,
            depth_write,
            color_mask: ops.color_mask,
        }
    }

    /// True when no fragment can change any buffer (the draw can be dropped).
    pub fn writes_nothing(&self) -> bool {
        !self.depth_write && self.color_mask == [false; 4]
    }
}

//! Picks the span function for a `FragmentKey`. The set of keys is small and closed today, so
//! the "cache" is a match over monomorphised functions.

use super::key::FragmentKey;
use super::span::{depth_mode, span_general, span_nothing, span_specialised, SpanFn};
use crate::api::convert::CompareFunc;

/// The span function for `key`; `force_general` always answers the general path.
pub fn select_span(key: &FragmentKey, force_general: bool) -> SpanFn {
    if key.writes_nothing() {
        return span_nothing;
    }
    if force_general || !key.is_simple() {
        return span_general;
    }
    let full = key.color_mask == [true; 4];
    match (key.depth_func, key.depth_write, full) {
        (None, _, true) => span_specialised::<{ depth_mode::NONE }, true>,
        (None, _, false) => span_specialised::<{ depth_mode::NONE }, false>,
        (Some(CompareFunc::Less), true, true) => {
            span_specialised::<{ depth_mode::LESS_WRITE }, true>
        }
        (Some(CompareFunc::LessEqual), true, true) => {
            span_specialised::<{ depth_mode::LEQUAL_WRITE }, true>
        }
        _ => span_general,
    }
}

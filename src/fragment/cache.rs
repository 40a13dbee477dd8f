//! Picks the span function for a `FragmentKey`. The set of keys is small and closed today, so
//! the "cache" is a match over monomorphised functions.

use super::key::{FastTexture, FragmentKey};
use super::span::{
    blend_mode, depth_mode, depth_stencil_applies, pair_sampled8, pair_textured, sampled8_applies,
    span_depth_stencil, span_fogged8, span_general, span_nothing, span_sampled, span_sampled8,
    span_specialised, span_textured, span_untextured8, span_untextured8_covered, tail8_applies,
    tex_mode, untextured8_applies, CoveredFn, PairFn, SpanFn,
};
use crate::common::values::CompareFunc;

/// The span function for `key`; `force_general` always answers the general path.
pub fn select_span(key: &FragmentKey, force_general: bool) -> SpanFn {
    if key.writes_nothing() {
        return span_nothing;
    }
    if force_general || key.alpha_to_coverage || key.alpha_to_one {
        return span_general;
    }
    if depth_stencil_applies(key) {
        return span_depth_stencil;
    }
    if let Some(layout) = key.fast_texture {
        // The textured span neither tests stencil, runs logic ops nor counts samples for an
        // occlusion query: those keys take the general path.
        if key.stencil.is_none() && key.logic_op.is_none() && !key.count_samples {
            return select_textured(key, layout);
        }
    }
    let simple_but_fog = key.fog.is_some() && FragmentKey { fog: None, ..*key }.is_simple();
    if simple_but_fog {
        return select_fogged(key);
    }
    if !key.is_simple() {
        if untextured8_applies(key) {
            return span_untextured8;
        }
        if sampled8_applies(key) {
            return span_sampled8;
        }
        if key.simd_units && crate::common::cpu::available() {
            return span_sampled;
        }
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
        _ if untextured8_applies(key) => span_untextured8,
        _ => span_general,
    }
}

/// The two-row function for `key`, when it has one: keys of the one-unit textured span and
/// of `span_sampled8` whose fragments finish eight at a time (`force_general`: none).
pub fn select_pair(key: &FragmentKey, force_general: bool) -> Option<PairFn> {
    // The eight-fragment tail (no stencil, logic op, colour sum, fog or sample counting) and
    // eight-pixel samplers for every unit.
    if force_general
        || key.writes_nothing()
        || !key.simd_units
        || !tail8_applies(key)
        || key.alpha_to_coverage
        || key.alpha_to_one
    {
        return None;
    }
    match key.fast_texture {
        Some(FastTexture::Rgba) => Some(pair_textured::<{ tex_mode::FAST_RGBA }>),
        Some(FastTexture::Rgb) => Some(pair_textured::<{ tex_mode::FAST_RGB }>),
        // As `select_span` picks `span_sampled8`.
        None if !key.is_simple() && !untextured8_applies(key) && sampled8_applies(key) => {
            Some(pair_sampled8)
        }
        None => None,
    }
}

/// The row function with a coverage per pixel for `key`, when it has one: untextured keys
/// whose fragments finish eight at a time (`force_general`: none, so each pixel goes to the
/// general path alone).
pub fn select_covered(key: &FragmentKey, force_general: bool) -> Option<CoveredFn> {
    if force_general
        || key.writes_nothing()
        || !untextured8_applies(key)
        || key.alpha_to_coverage
        || key.alpha_to_one
    {
        return None;
    }
    Some(span_untextured8_covered)
}

/// The fogged span for a key that is simple but for fog (`span_fogged8`: eight fragments at
/// a time with AVX2, else `span_fogged`).
fn select_fogged(key: &FragmentKey) -> SpanFn {
    let full = key.color_mask == [true; 4];
    match (key.depth_func, key.depth_write, full) {
        (None, _, true) => span_fogged8::<{ depth_mode::NONE }, true>,
        (None, _, false) => span_fogged8::<{ depth_mode::NONE }, false>,
        (Some(CompareFunc::Less), true, true) => span_fogged8::<{ depth_mode::LESS_WRITE }, true>,
        (Some(CompareFunc::LessEqual), true, true) => {
            span_fogged8::<{ depth_mode::LEQUAL_WRITE }, true>
        }
        _ => span_general,
    }
}

/// The textured span for a key with `fast_texture` (no stencil test, no logic op).
fn select_textured(key: &FragmentKey, layout: FastTexture) -> SpanFn {
    use blend_mode::{ALPHA_OVER, DYNAMIC};
    use tex_mode::{FAST_RGB, FAST_RGBA};
    let over = key.blend.is_some_and(|b| b.is_alpha_over());
    let full = key.color_mask == [true; 4];
    match (layout, over, full) {
        (FastTexture::Rgba, true, true) => span_textured::<FAST_RGBA, ALPHA_OVER, true>,
        (FastTexture::Rgba, true, false) => span_textured::<FAST_RGBA, ALPHA_OVER, false>,
        (FastTexture::Rgba, false, true) => span_textured::<FAST_RGBA, DYNAMIC, true>,
        (FastTexture::Rgba, false, false) => span_textured::<FAST_RGBA, DYNAMIC, false>,
        (FastTexture::Rgb, true, true) => span_textured::<FAST_RGB, ALPHA_OVER, true>,
        (FastTexture::Rgb, true, false) => span_textured::<FAST_RGB, ALPHA_OVER, false>,
        (FastTexture::Rgb, false, true) => span_textured::<FAST_RGB, DYNAMIC, true>,
        (FastTexture::Rgb, false, false) => span_textured::<FAST_RGB, DYNAMIC, false>,
    }
}

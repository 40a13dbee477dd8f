//! Attribute layout of a vertex after the vertex stage. Rasterization interpolates the first
//! `attr_count` of them; the back-face colours travel only through clipping and are swapped in
//! for back-facing polygons under two-sided lighting.

use crate::common::limits::MAX_TEXTURE_UNITS;

/// Primary colour RGBA.
pub const COLOR0: usize = 0;
/// Fog coordinate (right after the primary colour, so that a fogged draw without colour
/// sum or texturing interpolates 5 attributes rather than 9 or 41).
pub const FOG: usize = 4;
/// Secondary colour RGBA.
pub const COLOR1: usize = FOG + 1;
/// How many attributes the two colours take.
pub const COLORS: usize = 8;
/// Texture coordinates (s, t, r, q) per unit.
pub const TEX: usize = COLOR1 + 4;
/// Back-face primary and secondary colours (8, in that order).
pub const BACK: usize = TEX + 4 * MAX_TEXTURE_UNITS;
/// All attributes.
pub const COUNT: usize = BACK + COLORS;

/// Whether attribute `i` is a component of the primary or the secondary colour.
#[inline]
pub fn is_color(i: usize) -> bool {
    (COLOR0..COLOR0 + 4).contains(&i) || (COLOR1..COLOR1 + 4).contains(&i)
}

/// The attribute of component `c` (0..8) of the two colours, primary then secondary.
#[inline]
pub fn color(c: usize) -> usize {
    if c < 4 {
        COLOR0 + c
    } else {
        COLOR1 + c - 4
    }
}

/// Copies the two colours (primary and secondary) of `from` into `to`.
#[inline]
pub fn copy_colors(to: &mut [f32], from: &[f32]) {
    for c in 0..COLORS {
        to[color(c)] = from[color(c)];
    }
}

/// Number of interpolated colour attributes (primary RGBA).
pub const COLOR_ATTRS: usize = 4;
/// The most attributes a vertex can carry.
pub const MAX_ATTRS: usize = COUNT;

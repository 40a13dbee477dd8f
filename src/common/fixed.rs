//! Fixed-point conversions every stage agrees on: window coordinates to sub-pixel units, window
//! depth to stored depth, colour components to 8 bits.

use super::limits::SUBPIXEL_BITS;

/// Sub-pixel units per pixel.
pub const SUBPIXEL: i64 = 1 << SUBPIXEL_BITS;

/// Snaps a window coordinate to fixed point. Callers pass clipped coordinates, which are finite
/// and bounded by the viewport.
#[inline]
pub fn to_fixed(v: f64) -> i64 {
    // `f64::round` (halves away from zero) without the libm call it becomes on x86-64
    // without SSE4.1: shift by a half towards the sign, then truncate. Exact for |t| < 2^52,
    // which clipping guarantees.
    let t = v * SUBPIXEL as f64;
    if t >= 0.0 {
        (t + 0.5) as i64
    } else {
        (t - 0.5) as i64
    }
}

/// Converts window z to a stored depth value (round to nearest, clamped): `z * max + 0.5`
/// truncated, NaN and negatives as 0, at most `depth_max` (Rust's `as` saturates, without
/// branches).
#[inline(always)]
pub fn depth_to_fixed(z: f64, depth_max: u32) -> u32 {
    ((z * depth_max as f64 + 0.5) as u32).min(depth_max)
}

/// Converts a colour component to 8 bits (section 2.14.9: round to nearest after clamping):
/// `c * 255 + 0.5` truncated, NaN and negatives as 0, at most 255 (Rust's `as` saturates).
#[inline(always)]
pub fn color_to_u8(c: f32) -> u8 {
    (c * 255.0 + 0.5) as u8
}

/// [`color_to_u8`] of four components at once, with SSE2 (part of every x86-64 processor):
/// the fragment paths convert every fragment's colour.
#[inline(always)]
pub fn color4_to_u8(c: [f32; 4]) -> [u8; 4] {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: SSE and SSE2 are part of the x86-64 baseline; no memory is accessed.
    unsafe {
        use std::arch::x86_64::*;
        let v = _mm_add_ps(
            _mm_mul_ps(_mm_setr_ps(c[0], c[1], c[2], c[3]), _mm_set1_ps(255.0)),
            _mm_set1_ps(0.5),
        );
        // max_ps answers its second operand (0) when v is NaN.
        let v = _mm_min_ps(_mm_max_ps(v, _mm_setzero_ps()), _mm_set1_ps(255.0));
        let i = _mm_cvttps_epi32(v);
        let bytes = _mm_packus_epi16(_mm_packs_epi32(i, i), _mm_setzero_si128());
        (_mm_cvtsi128_si32(bytes) as u32).to_le_bytes()
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        c.map(color_to_u8)
    }
}

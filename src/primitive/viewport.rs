//! Perspective division and the viewport transformation (section 2.11.1).

use glam::DVec4;

use super::clip::ClipVertex;
use crate::common::fixed::to_fixed;
pub use crate::raster::setup::WindowVertex;

/// The primitive stage's part of a draw's frozen state (built by `state::snapshot`).
#[derive(Clone, Debug)]
pub struct ViewportDraw {
    /// Enabled user clip planes, in eye coordinates.
    pub clip_planes: Vec<DVec4>,
    /// Viewport mapping: window = ndc * scale + offset, per axis (z uses the depth range).
    pub viewport_scale: [f64; 3],
    pub viewport_offset: [f64; 3],
    /// The guard band's side planes (`clip::guard_factors`) when both faces are filled, else
    /// the view volume's (`clip::EXACT`).
    pub guard: [f64; 2],
}

/// Divides by w and maps to the viewport. `v.pos.w` is positive (clipping guarantees it).
pub fn to_window(ds: &ViewportDraw, v: &ClipVertex) -> WindowVertex {
    let inv_w = 1.0 / v.pos.w;
    let ndc = [v.pos.x * inv_w, v.pos.y * inv_w, v.pos.z * inv_w];
    let x = ndc[0] * ds.viewport_scale[0] + ds.viewport_offset[0];
    let y = ndc[1] * ds.viewport_scale[1] + ds.viewport_offset[1];
    let z = ndc[2] * ds.viewport_scale[2] + ds.viewport_offset[2];
    WindowVertex {
        xy: [to_fixed(x), to_fixed(y)],
        pos: [x, y],
        z: z.clamp(0.0, 1.0),
        inv_w,
    }
}

/// The window positions of a batch's vertices for filled one-sided polygons:
/// `out[i] = in_guard_band(clip[i]).then(|| to_window(clip[i]))`
/// ([`super::clip::in_guard_band`], [`to_window`]). Without user clip planes and with AVX2,
/// four vertices at a time in f64 lanes: the same operations in the same order (IEEE
/// arithmetic is exact per lane), so the same values; the scalar form costs about 130
/// instructions a vertex, most of them the guard band's branches.
pub fn guard_band_windows(
    ds: &ViewportDraw,
    clip: &[ClipVertex],
    out: &mut [Option<WindowVertex>],
) {
    let scalar = |c: &ClipVertex| {
        super::clip::in_guard_band(c, &ds.clip_planes, ds.guard).then(|| to_window(ds, c))
    };
    let mut done = 0;
    #[cfg(target_arch = "x86_64")]
    {
        if ds.clip_planes.is_empty() && crate::common::cpu::available() {
            for (c, o) in clip.chunks_exact(4).zip(out.chunks_exact_mut(4)) {
                // SAFETY: AVX2 is present (checked just above).
                if !unsafe { x86::windows4(ds, c, o) } {
                    for (c, o) in c.iter().zip(o.iter_mut()) {
                        *o = scalar(c);
                    }
                }
            }
            done = clip.len() / 4 * 4;
        }
    }
    for (c, o) in clip[done..].iter().zip(&mut out[done..]) {
        *o = scalar(c);
    }
}

#[cfg(target_arch = "x86_64")]
mod x86 {
    use super::{ClipVertex, ViewportDraw, WindowVertex};
    use crate::common::fixed::SUBPIXEL;
    use std::arch::x86_64::*;

    /// [`super::guard_band_windows`] of four vertices (`clip` and `out` hold four), without
    /// user clip planes; `false` (nothing written) when a vertex inside the guard band has a
    /// fixed-point coordinate beyond 32 bits (a viewport far from the origin), which the
    /// caller then computes one by one.
    #[target_feature(enable = "avx2")]
    pub fn windows4(
        ds: &ViewportDraw,
        clip: &[ClipVertex],
        out: &mut [Option<WindowVertex>],
    ) -> bool {
        let (add, sub, mul) = (_mm256_add_pd, _mm256_sub_pd, _mm256_mul_pd);
        let ge = |a: __m256d, b: __m256d| _mm256_cmp_pd::<_CMP_GE_OQ>(a, b);
        let rows: [__m256d; 4] = std::array::from_fn(|k| {
            let p = clip[k].pos.to_array();
            // SAFETY: `p` holds four f64; unaligned load.
            unsafe { _mm256_loadu_pd(p.as_ptr()) }
        });
        // Transposed: one register per coordinate, one lane per vertex.
        let (t0, t1) = (
            _mm256_unpacklo_pd(rows[0], rows[1]),
            _mm256_unpackhi_pd(rows[0], rows[1]),
        );
        let (t2, t3) = (
            _mm256_unpacklo_pd(rows[2], rows[3]),
            _mm256_unpackhi_pd(rows[2], rows[3]),
        );
        let x = _mm256_permute2f128_pd::<0x20>(t0, t2);
        let z = _mm256_permute2f128_pd::<0x31>(t0, t2);
        let y = _mm256_permute2f128_pd::<0x20>(t1, t3);
        let w = _mm256_permute2f128_pd::<0x31>(t1, t3);
        let zero = _mm256_setzero_pd();
        // `in_guard_band`: NaN fails every ordered comparison.
        let gx = mul(w, _mm256_set1_pd(ds.guard[0]));
        let gy = mul(w, _mm256_set1_pd(ds.guard[1]));
        let finite = |v: __m256d| {
            _mm256_cmp_pd::<_CMP_LT_OQ>(
                _mm256_andnot_pd(_mm256_set1_pd(-0.0), v),
                _mm256_set1_pd(f64::INFINITY),
            )
        };
        let tests = [
            _mm256_cmp_pd::<_CMP_GT_OQ>(w, zero),
            ge(add(gx, x), zero),
            ge(sub(gx, x), zero),
            ge(add(gy, y), zero),
            ge(sub(gy, y), zero),
            ge(add(w, z), zero),
            ge(sub(w, z), zero),
            finite(x),
            finite(y),
            finite(z),
            finite(w),
        ];
        let inside = tests
            .into_iter()
            .reduce(|a, b| _mm256_and_pd(a, b))
            .unwrap_or(zero);
        let inside = _mm256_movemask_pd(inside);
        if inside == 0 {
            out[..4].fill(None);
            return true;
        }
        // `to_window`.
        let inv_w = _mm256_div_pd(_mm256_set1_pd(1.0), w);
        let map = |c: __m256d, d: usize| {
            add(
                mul(mul(c, inv_w), _mm256_set1_pd(ds.viewport_scale[d])),
                _mm256_set1_pd(ds.viewport_offset[d]),
            )
        };
        let (wx, wy, wz) = (map(x, 0), map(y, 1), map(z, 2));
        // `f64::clamp(0, 1)`: NaN stays NaN.
        let wz = _mm256_blendv_pd(wz, zero, _mm256_cmp_pd::<_CMP_LT_OQ>(wz, zero));
        let one = _mm256_set1_pd(1.0);
        let wz = _mm256_blendv_pd(wz, one, _mm256_cmp_pd::<_CMP_GT_OQ>(wz, one));
        // `to_fixed`: t + 1/2 towards t's sign (NaN: -1/2), truncated; exact in 32 bits
        // below 2^31 (checked).
        let fixed = |v: __m256d| {
            let t = mul(v, _mm256_set1_pd(SUBPIXEL as f64));
            let half = _mm256_blendv_pd(_mm256_set1_pd(-0.5), _mm256_set1_pd(0.5), ge(t, zero));
            let u = add(t, half);
            let limit = _mm256_set1_pd(2147483647.0);
            let fits =
                _mm256_cmp_pd::<_CMP_LT_OQ>(_mm256_andnot_pd(_mm256_set1_pd(-0.0), u), limit);
            (_mm256_cvttpd_epi32(u), _mm256_movemask_pd(fits))
        };
        let ((fx, fits_x), (fy, fits_y)) = (fixed(wx), fixed(wy));
        if inside & fits_x & fits_y != inside {
            return false;
        }
        let mut lanes = [[0f64; 4]; 4];
        for (l, v) in lanes.iter_mut().zip([wx, wy, wz, inv_w]) {
            // SAFETY: `l` holds four f64; unaligned store.
            unsafe { _mm256_storeu_pd(l.as_mut_ptr(), v) };
        }
        let mut ints = [[0i32; 4]; 2];
        for (l, v) in ints.iter_mut().zip([fx, fy]) {
            // SAFETY: `l` holds four i32; unaligned store.
            unsafe { _mm_storeu_si128(l.as_mut_ptr() as *mut __m128i, v) };
        }
        for (k, o) in out[..4].iter_mut().enumerate() {
            *o = (inside & (1 << k) != 0).then(|| WindowVertex {
                xy: [ints[0][k] as i64, ints[1][k] as i64],
                pos: [lanes[0][k], lanes[1][k]],
                z: lanes[2][k],
                inv_w: lanes[3][k],
            });
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::api::enums::*;
    use crate::state::Context;
    use glam::DVec4;

    fn bits(w: &Option<WindowVertex>) -> Option<([i64; 2], [u64; 4])> {
        w.map(|w| (w.xy, [w.pos[0], w.pos[1], w.z, w.inv_w].map(f64::to_bits)))
    }

    /// The four-lane form gives `in_guard_band` + `to_window` bit for bit, on random vertices
    /// around the view volume and the guard band, with NaN, infinities, w at or below 0, tiny
    /// and huge w, under several viewports (one far from the origin, where fixed-point values
    /// pass 32 bits) and depth ranges, for batch lengths that are not multiples of four.
    #[test]
    fn four_lane_windows_match_one_by_one() {
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || crate::test_support::xorshift(&mut seed);
        let specials = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            1e-300,
            1e300,
            5e-324,
        ];
        let viewports = [
            (0, 0, 64, 48, 0.0, 1.0),
            (-30, 7, 1024, 768, 1.0, 0.0),
            (1 << 24, -(1 << 24), 512, 512, 0.25, 0.75),
            (3, 5, 1, 1, 0.5, 0.5),
        ];
        for (vx, vy, vw, vh, n, f) in viewports {
            let mut gl = Context::new(64, 48);
            gl.viewport(vx, vy, vw, vh);
            gl.depth_range(n, f);
            gl.begin(GL_TRIANGLES);
            gl.end();
            let ds = gl.snapshot();
            for len in [0usize, 1, 3, 4, 7, 64, 257] {
                let clip: Vec<ClipVertex> = (0..len)
                    .map(|_| {
                        let mut c = ClipVertex::ZERO;
                        let w = match next() % 6 {
                            0 => specials[(next() % specials.len() as u64) as usize],
                            1 => (next() % 1000) as f64 * 1e-6,
                            _ => 0.1 + (next() % 10_000) as f64 / 1000.0,
                        };
                        let coord = |r: u64| match r % 9 {
                            0 => specials[(r >> 8) as usize % specials.len()],
                            // Near the guard band (g w) and the view volume (w).
                            1 => {
                                w * ds.viewport.guard[0]
                                    * (1.0 + ((r >> 8) % 3) as f64 * 1e-16 - 1e-16)
                            }
                            2 => -w,
                            _ => ((r >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0) * w * 3.0,
                        };
                        c.pos = DVec4::new(coord(next()), coord(next()), coord(next()), w);
                        c
                    })
                    .collect();
                let mut out = vec![None; len];
                guard_band_windows(&ds.viewport, &clip, &mut out);
                for (c, o) in clip.iter().zip(&out) {
                    let expected = super::super::clip::in_guard_band(c, &[], ds.viewport.guard)
                        .then(|| to_window(&ds.viewport, c));
                    assert_eq!(bits(o), bits(&expected), "{:?}", c.pos);
                }
            }
        }
    }
}

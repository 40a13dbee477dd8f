//! The accumulation buffer (section 4.2.4): `glAccum`, `glClearAccum` and its clear.
//!
//! Each channel is a signed 16-bit fixed-point value over [-1, 1] (`v * 32767`, rounded to
//! nearest; results outside [-1, 1] saturate, which is where the spec leaves overflow
//! undefined). `glAccum` works immediately on the flushed framebuffer, inside the scissor box:
//! one band of tiles per task on the shading threads, each tile's part of a row at a time,
//! eight channels (two pixels) at once with AVX2 and its scalar twin for the rest.

use rayon::prelude::*;

use super::Context;
use crate::common::fixed::color_to_u8;
use crate::common::rect::Rect;
use crate::common::values::AccumOp;
use crate::framebuffer::Framebuffer;
use crate::gl::convert;
use crate::gl::enums::*;

/// Scale of the fixed-point accumulation values.
const ACCUM_ONE: f32 = 32767.0;

/// `x.round()` (halves away from zero) by truncation through an integer, without the libm
/// call `round` compiles to on the baseline x86-64 target (16 % of an accumulation frame). A
/// negative result that rounds to zero comes out as +0 instead of -0, which the conversion
/// to i16 does not see.
#[inline]
fn round_half_away(x: f32) -> f32 {
    // NaN, the infinities and |x| >= 2^23 are whole numbers (or not numbers) already.
    if !(x.abs() < 8_388_608.0) {
        return x;
    }
    let t = x as i32 as f32;
    // The fraction, exactly: x and its truncation share their leading bits.
    let d = x - t;
    if d >= 0.5 {
        t + 1.0
    } else if d <= -0.5 {
        t - 1.0
    } else {
        t
    }
}

#[inline]
fn to_fixed(v: f32) -> i16 {
    let v = round_half_away(v * ACCUM_ONE);
    // NaN (from a NaN value argument) becomes 0.
    if v.is_nan() {
        0
    } else {
        v.clamp(-ACCUM_ONE, ACCUM_ONE) as i16
    }
}

#[inline]
fn from_fixed(v: i16) -> f32 {
    v as f32 / ACCUM_ONE
}

impl Context {
    pub(crate) fn clear_accum(&mut self, r: GLfloat, g: GLfloat, b: GLfloat, a: GLfloat) {
        self.clear_values.accum =
            [r, g, b, a].map(|c| if c.is_nan() { 0.0 } else { c.clamp(-1.0, 1.0) });
    }

    /// `glClear(GL_ACCUM_BUFFER_BIT)`.
    pub(crate) fn clear_accum_buffer(&mut self) {
        if self.framebuffer.accum.is_empty() {
            return;
        }
        let rect = self.scissored_window();
        let value = self.clear_values.accum.map(to_fixed);
        let w = self.framebuffer.width as usize;
        for y in rect.y0..rect.y1 {
            let row = y as usize * w;
            self.framebuffer.accum[row + rect.x0 as usize..row + rect.x1 as usize].fill(value);
        }
    }

    pub(crate) fn accum(&mut self, op: GLenum, value: GLfloat) {
        let Some(op) = convert::accum_op(op) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if !self.framebuffer_ready() {
            return;
        }
        if self.framebuffer.accum.is_empty() {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        self.flush_scene();
        let rect = self.scissored_window();
        if rect.is_empty() {
            return;
        }
        let kernels = Kernels::pick();
        let mask = self.fragment_ops.color_mask;
        let fb = &mut self.framebuffer;
        match &self.pool {
            Some(pool) => pool.install(|| accum_bands(fb, rect, op, value, mask, kernels)),
            None => accum_bands(fb, rect, op, value, mask, kernels),
        }
    }
}

/// A row of colours (RGBA8) and a row of accumulation values.
type Colors<'a> = &'a [[u8; 4]];
type Accums<'a> = &'a [[i16; 4]];

/// The row kernels of one `glAccum`: the AVX2 ones or their scalar twins, which store the same
/// values (the same IEEE operations in the same order on every channel).
#[derive(Clone, Copy)]
struct Kernels {
    /// `GL_LOAD` (false) or `GL_ACCUM` (true) of a row of colours into accumulation values.
    load: fn(&mut [[i16; 4]], Colors, f32, bool),
    /// `GL_MULT` (true) or `GL_ADD` (false) on a row of accumulation values.
    scale: fn(&mut [[i16; 4]], f32, bool),
    /// `GL_RETURN` of a row into colours, under the colour mask.
    ret: fn(&mut [[u8; 4]], Accums, f32, [bool; 4]),
}

impl Kernels {
    fn pick() -> Kernels {
        #[cfg(target_arch = "x86_64")]
        if crate::common::cpu::available() {
            return Kernels {
                load: avx2::load,
                scale: avx2::scale,
                ret: avx2::ret,
            };
        }
        Kernels::SCALAR
    }

    const SCALAR: Kernels = Kernels {
        load: load_scalar,
        scale: scale_scalar,
        ret: ret_scalar,
    };
}

fn load_scalar(acc: &mut [[i16; 4]], src: &[[u8; 4]], value: f32, keep: bool) {
    for (a, c) in acc.iter_mut().zip(src) {
        let old = *a;
        *a = std::array::from_fn(|k| {
            let add = value * (c[k] as f32 / 255.0);
            let base = if keep { from_fixed(old[k]) } else { 0.0 };
            to_fixed(base + add)
        });
    }
}

fn scale_scalar(acc: &mut [[i16; 4]], value: f32, mult: bool) {
    for a in acc {
        *a = a.map(|v| {
            let f = from_fixed(v);
            to_fixed(if mult { f * value } else { f + value })
        });
    }
}

fn ret_scalar(dst: &mut [[u8; 4]], acc: &[[i16; 4]], value: f32, mask: [bool; 4]) {
    for (d, a) in dst.iter_mut().zip(acc) {
        for k in 0..4 {
            if mask[k] {
                d[k] = color_to_u8(from_fixed(a[k]) * value);
            }
        }
    }
}

/// Runs `op` over `rect` (inside the framebuffer): each band of tiles (a tile row and its rows
/// of the accumulation buffer) is a task for the current thread pool.
fn accum_bands(
    fb: &mut Framebuffer,
    rect: Rect,
    op: AccumOp,
    value: f32,
    mask: [bool; 4],
    k: Kernels,
) {
    let w = fb.width.max(0) as usize;
    let h = fb.height.max(0) as usize;
    let shift = fb.tile_shift;
    let side = 1usize << shift;
    let tiles_x = fb.tiles_x;
    if w == 0 || fb.accum.len() < w * h || fb.tiles.len() < tiles_x * h.div_ceil(side) {
        return;
    }
    let (x0, x1) = (rect.x0.max(0) as usize, (rect.x1.max(0) as usize).min(w));
    let (y0, y1) = (rect.y0.max(0) as usize, (rect.y1.max(0) as usize).min(h));
    if x0 >= x1 || y0 >= y1 {
        return;
    }
    let accum = &mut fb.accum[..w * h];
    // The rows of band `ty` inside the rectangle, and for each the pieces of the row that lie
    // in one tile: (tile column, first pixel in the tile's row, first accumulation index in
    // the band, pixel count).
    let pieces = move |ty: usize, f: &mut dyn FnMut(usize, usize, usize, usize)| {
        let band = ty * side;
        for y in y0.max(band)..y1.min(band + side) {
            let row = (y - band) * w;
            for tx in x0 >> shift..=(x1 - 1) >> shift {
                let (xs, xe) = (x0.max(tx * side), x1.min((tx + 1) * side));
                f(
                    tx,
                    ((y - band) << shift) + xs - tx * side,
                    row + xs,
                    xe - xs,
                );
            }
        }
    };
    match op {
        AccumOp::Load | AccumOp::Accum => {
            // Read from the read buffer: the tiles' colours, or the parked buffer's.
            let parked = fb.read != fb.resident && fb.parked.len() == fb.tiles.len();
            let mut sources: Vec<&[[u8; 4]]> = if parked {
                fb.parked.iter().map(|c| &c[..]).collect()
            } else {
                fb.tiles.iter().map(|t| &t.color[..]).collect()
            };
            // A multisample buffer's colours are read resolved (the samples' average).
            let resolved: Vec<Vec<[u8; 4]>>;
            if fb.samples > 1 {
                let plane = fb.plane_tiles;
                resolved = (0..plane)
                    .map(|t| {
                        (0..sources[t].len())
                            .map(|i| {
                                let each = (0..fb.samples).map(|s| sources[t + s * plane][i]);
                                crate::framebuffer::resolve(each, fb.samples)
                            })
                            .collect()
                    })
                    .collect();
                sources = resolved.iter().map(|c| &c[..]).collect();
            }
            let keep = op == AccumOp::Accum;
            accum
                .par_chunks_mut(side * w)
                .zip(sources.par_chunks(tiles_x))
                .enumerate()
                .for_each(|(ty, (acc, src))| {
                    pieces(ty, &mut |tx, t, a, n| {
                        (k.load)(&mut acc[a..a + n], &src[tx][t..t + n], value, keep)
                    })
                });
        }
        AccumOp::Mult | AccumOp::Add => {
            let mult = op == AccumOp::Mult;
            accum
                .par_chunks_mut(side * w)
                .enumerate()
                .for_each(|(ty, acc)| {
                    pieces(ty, &mut |_, _, a, n| {
                        (k.scale)(&mut acc[a..a + n], value, mult)
                    })
                });
        }
        AccumOp::Return => {
            // Only the scissor and the colour mask apply (section 4.2.4).
            if mask == [false; 4] {
                return;
            }
            // Every sample of a multisample buffer gets the returned value.
            for plane in fb.tiles.chunks_mut(fb.plane_tiles.max(1)) {
                plane
                    .par_chunks_mut(tiles_x)
                    .zip(accum.par_chunks(side * w))
                    .enumerate()
                    .for_each(|(ty, (tiles, acc))| {
                        pieces(ty, &mut |tx, t, a, n| {
                            (k.ret)(&mut tiles[tx].color[t..t + n], &acc[a..a + n], value, mask)
                        })
                    });
            }
        }
    }
}

/// The AVX2 twins of the row kernels: two pixels (eight channels) per step, the remainder
/// through the scalar kernels.
#[cfg(target_arch = "x86_64")]
mod avx2 {
    use super::ACCUM_ONE;
    use std::arch::x86_64::*;

    /// `to_fixed` of eight values, as eight i16. Clamping before rounding gives what rounding
    /// before clamping gives (the bounds are whole numbers); NaN lanes become 0.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn fixed8(v: __m256) -> __m128i {
        let x = _mm256_mul_ps(v, _mm256_set1_ps(ACCUM_ONE));
        let ordered = _mm256_cmp_ps::<_CMP_ORD_Q>(x, x);
        let x = _mm256_min_ps(
            _mm256_max_ps(x, _mm256_set1_ps(-ACCUM_ONE)),
            _mm256_set1_ps(ACCUM_ONE),
        );
        // round_half_away: the truncation, plus or minus one when the (exact) fraction
        // reaches a half.
        let t = _mm256_round_ps::<{ _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC }>(x);
        let d = _mm256_sub_ps(x, t);
        let one = _mm256_set1_ps(1.0);
        let up = _mm256_and_ps(_mm256_cmp_ps::<_CMP_GE_OQ>(d, _mm256_set1_ps(0.5)), one);
        let down = _mm256_and_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(d, _mm256_set1_ps(-0.5)), one);
        let r = _mm256_sub_ps(_mm256_add_ps(t, up), down);
        let i = _mm256_and_si256(_mm256_cvttps_epi32(r), _mm256_castps_si256(ordered));
        _mm_packs_epi32(_mm256_castsi256_si128(i), _mm256_extracti128_si256::<1>(i))
    }

    /// `from_fixed` of two pixels' accumulation values.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn unfixed8(a: &[[i16; 4]]) -> __m256 {
        debug_assert!(a.len() >= 2);
        // SAFETY: `a` holds two [i16; 4], 16 bytes, read unaligned.
        let v = unsafe { _mm_loadu_si128(a.as_ptr() as *const __m128i) };
        _mm256_div_ps(
            _mm256_cvtepi32_ps(_mm256_cvtepi16_epi32(v)),
            _mm256_set1_ps(ACCUM_ONE),
        )
    }

    #[inline]
    #[target_feature(enable = "avx2")]
    fn store8(a: &mut [[i16; 4]], v: __m128i) {
        debug_assert!(a.len() >= 2);
        // SAFETY: `a` holds two [i16; 4], 16 bytes, written unaligned.
        unsafe { _mm_storeu_si128(a.as_mut_ptr() as *mut __m128i, v) }
    }

    pub(super) fn load(acc: &mut [[i16; 4]], src: &[[u8; 4]], value: f32, keep: bool) {
        // SAFETY: chosen by `Kernels::pick` only when the processor has AVX2.
        unsafe { load_avx2(acc, src, value, keep) }
    }

    #[target_feature(enable = "avx2")]
    fn load_avx2(acc: &mut [[i16; 4]], src: &[[u8; 4]], value: f32, keep: bool) {
        let n = acc.len().min(src.len());
        let pairs = n & !1;
        let v = _mm256_set1_ps(value);
        for p in (0..pairs).step_by(2) {
            // SAFETY: src[p..p + 2] is 8 bytes, read unaligned.
            let bytes = unsafe { _mm_loadl_epi64(src[p..p + 2].as_ptr() as *const __m128i) };
            let c = _mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(bytes));
            let add = _mm256_mul_ps(v, _mm256_div_ps(c, _mm256_set1_ps(255.0)));
            let base = if keep {
                unfixed8(&acc[p..p + 2])
            } else {
                _mm256_setzero_ps()
            };
            store8(&mut acc[p..p + 2], fixed8(_mm256_add_ps(base, add)));
        }
        super::load_scalar(&mut acc[pairs..n], &src[pairs..n], value, keep);
    }

    pub(super) fn scale(acc: &mut [[i16; 4]], value: f32, mult: bool) {
        // SAFETY: chosen by `Kernels::pick` only when the processor has AVX2.
        unsafe { scale_avx2(acc, value, mult) }
    }

    #[target_feature(enable = "avx2")]
    fn scale_avx2(acc: &mut [[i16; 4]], value: f32, mult: bool) {
        let pairs = acc.len() & !1;
        let v = _mm256_set1_ps(value);
        for p in (0..pairs).step_by(2) {
            let f = unfixed8(&acc[p..p + 2]);
            let r = if mult {
                _mm256_mul_ps(f, v)
            } else {
                _mm256_add_ps(f, v)
            };
            store8(&mut acc[p..p + 2], fixed8(r));
        }
        super::scale_scalar(&mut acc[pairs..], value, mult);
    }

    pub(super) fn ret(dst: &mut [[u8; 4]], acc: &[[i16; 4]], value: f32, mask: [bool; 4]) {
        // SAFETY: chosen by `Kernels::pick` only when the processor has AVX2.
        unsafe { ret_avx2(dst, acc, value, mask) }
    }

    #[target_feature(enable = "avx2")]
    fn ret_avx2(dst: &mut [[u8; 4]], acc: &[[i16; 4]], value: f32, mask: [bool; 4]) {
        let n = dst.len().min(acc.len());
        let pairs = n & !1;
        let v = _mm256_set1_ps(value);
        // The written bytes of two pixels.
        let m = u32::from_le_bytes(mask.map(|b| if b { 0xFF } else { 0 }));
        let m = (m as u64) | ((m as u64) << 32);
        for p in (0..pairs).step_by(2) {
            let c = _mm256_mul_ps(
                _mm256_mul_ps(unfixed8(&acc[p..p + 2]), v),
                _mm256_set1_ps(255.0),
            );
            let c = _mm256_add_ps(c, _mm256_set1_ps(0.5));
            // color_to_u8's saturating conversion: NaN (max's second operand) and negatives to
            // 0, at most 255.
            let c = _mm256_min_ps(_mm256_max_ps(c, _mm256_setzero_ps()), _mm256_set1_ps(255.0));
            let i = _mm256_cvttps_epi32(c);
            let w = _mm_packs_epi32(_mm256_castsi256_si128(i), _mm256_extracti128_si256::<1>(i));
            let bytes = _mm_cvtsi128_si64(_mm_packus_epi16(w, w)) as u64;
            let d = &mut dst[p..p + 2];
            let old = u64::from_le_bytes(bytemuck::cast([d[0], d[1]]));
            let new = (bytes & m) | (old & !m);
            let px: [[u8; 4]; 2] = bytemuck::cast(new.to_le_bytes());
            d.copy_from_slice(&px);
        }
        super::ret_scalar(&mut dst[pairs..n], &acc[pairs..n], value, mask);
    }
}

#[cfg(test)]
mod tests {
    use super::{round_half_away, to_fixed, Kernels, ACCUM_ONE};

    /// The AVX2 row kernels store what their scalar twins store, byte for byte: random
    /// colours and accumulation values (every i16, so saturation and both signs), odd and even
    /// row lengths, and values that saturate, round at halves, are zero, negative, NaN or
    /// infinite; every colour mask.
    #[test]
    #[cfg(target_arch = "x86_64")]
    fn avx2_kernels_store_what_the_scalar_ones_store() {
        if !std::arch::is_x86_feature_detected!("avx2") {
            // Nothing to compare on this processor; CI's runners have AVX2.
            assert!(std::env::var_os("CI").is_none(), "no AVX2 to test");
            return;
        }
        let simd = Kernels {
            load: super::avx2::load,
            scale: super::avx2::scale,
            ret: super::avx2::ret,
        };
        let scalar = Kernels::SCALAR;
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let values = [
            0.25,
            1.0,
            -1.0,
            0.5,
            0.1,
            1.5,
            -0.7,
            0.0,
            -0.0,
            3.0e38,
            -3.0e38,
            1.0e-30,
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            1.0 / 255.0,
            0.999,
            2.0,
        ];
        let mut compared = 0;
        for n in [0usize, 1, 2, 3, 7, 64, 65] {
            for &value in &values {
                let colors: Vec<[u8; 4]> = (0..n).map(|_| (next() as u32).to_le_bytes()).collect();
                let acc: Vec<[i16; 4]> = (0..n)
                    .map(|_| {
                        let v = next();
                        [
                            v as i16,
                            (v >> 16) as i16,
                            (v >> 32) as i16,
                            (v >> 48) as i16,
                        ]
                        .map(|c| c.max(-32767))
                    })
                    .collect();
                for keep in [false, true] {
                    let (mut a, mut b) = (acc.clone(), acc.clone());
                    (simd.load)(&mut a, &colors, value, keep);
                    (scalar.load)(&mut b, &colors, value, keep);
                    assert_eq!(a, b, "load/accum {value} keep {keep} n {n}");
                }
                for mult in [false, true] {
                    let (mut a, mut b) = (acc.clone(), acc.clone());
                    (simd.scale)(&mut a, value, mult);
                    (scalar.scale)(&mut b, value, mult);
                    assert_eq!(a, b, "mult/add {value} mult {mult} n {n}");
                }
                for m in 0..16u32 {
                    let mask = [0, 1, 2, 3].map(|k| m & (1 << k) != 0);
                    let (mut a, mut b) = (colors.clone(), colors.clone());
                    (simd.ret)(&mut a, &acc, value, mask);
                    (scalar.ret)(&mut b, &acc, value, mask);
                    assert_eq!(a, b, "return {value} mask {mask:?} n {n}");
                }
                compared += n;
            }
        }
        assert!(compared > 0);
    }

    /// `round_half_away` is `f32::round` (up to the sign of zero) on every f32 from -2^24 to
    /// 2^24 near the halves and whole numbers, on a sweep of all magnitudes, and on NaN and the
    /// infinities; `to_fixed` therefore stores what `round` would.
    #[test]
    fn round_half_away_is_round() {
        let mut xs = vec![f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 0.0, -0.0];
        for k in -70_000i32..70_000 {
            for off in [-0.5f32, 0.0, 0.5] {
                let x = k as f32 + off;
                xs.extend([
                    x,
                    f32::from_bits(x.to_bits() + 1),
                    f32::from_bits(x.to_bits().wrapping_sub(1)),
                ]);
            }
        }
        let mut b = 1u32;
        while b < 0x7F80_0000 {
            xs.extend([f32::from_bits(b), -f32::from_bits(b)]);
            b += 0x1_2345;
        }
        for x in xs {
            let (got, want) = (round_half_away(x), x.round());
            assert!(
                got == want || (got.is_nan() && want.is_nan()),
                "{x:e}: {got:e} vs {want:e}"
            );
            let v = x / ACCUM_ONE;
            let old = {
                let r = (v * ACCUM_ONE).round();
                if r.is_nan() {
                    0
                } else {
                    r.clamp(-ACCUM_ONE, ACCUM_ONE) as i16
                }
            };
            assert_eq!(to_fixed(v), old, "{v:e}");
        }
    }
}

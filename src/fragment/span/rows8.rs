//! Untextured rows eight pixels at a time for the keys of [`span_specialised`] (the depth test
//! and colour mask only: a lit, untextured scene, the `shadow` workload's floor and plates).
//! Each lane gets the values the per-fragment path computes for its pixel: the depth and
//! colours stepped as [`SpanRun`] steps them (`SpanRun::z_lanes`, `SpanRun::primary_lanes`),
//! then the per-pixel arithmetic (w, the perspective colours, the conversion to bytes, the
//! depth's fixed point and test) on eight lanes with the same IEEE operations, so the pixels
//! are the same bits (twin tests in `tests/shadow_twins.rs`).

use super::*;

/// The shortest span the untextured eight-lane rows take ([`simple_rows8`] here,
/// `span_fogged8` in `fogged.rs`). Shorter spans (small triangles: `triangles` and `fog`
/// average a few pixels) stay on the per-fragment paths: the lanes' values are stepped one by
/// one into memory and read back as vectors, and on short spans that store-forwarding stall
/// plus the masked stores cost more wall time than the scalar loop, though fewer instructions
/// (perf, 1 thread: `triangles` 62 -> 75-93 ms and `fog` 37 -> 45 ms per frame with every
/// span on these routes).
pub(super) const LANES8_MIN_SPAN: i32 = 16;

/// [`span_specialised`]'s row eight pixels at a time, when it applies: a span of at least
/// [`LANES8_MIN_SPAN`] pixels, aliased (coverage 1),
/// AVX2 present, a depth range that `simd::depth8` converts, and a fixed depth mode. Answers
/// false (nothing done) otherwise.
#[inline(always)]
pub(super) fn simple_rows8<const DEPTH: u8, const FULL_MASK: bool>(
    ds: &FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants,
) -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        if DEPTH != depth_mode::DYNAMIC
            && x1 - x0 >= LANES8_MIN_SPAN
            && it.coverage == 1.0
            && ds.depth_max < 1 << 31
            && crate::common::cpu::available()
        {
            // SAFETY: AVX2 is present (checked just above).
            unsafe { x86::simple8::<DEPTH, FULL_MASK>(ds, tile, y, x0, x1, it) };
            return true;
        }
    }
    let _ = (ds, tile, y, x0, x1, it);
    false
}

/// [`span_depth_stencil`]'s row eight pixels at a time in registers, when it applies (AVX2
/// present, a depth range `simd::depth8` converts): the depths stepped eight at a time
/// (`SpanRun::z_lanes`), converted and tested together, the stencil test and actions on the
/// eight stored values as one word (`stencil8_word`), the occlusion count and the depth writes
/// as masked stores; groups at the end of the tile's buffers lane by lane. Answers false
/// (nothing done) otherwise.
#[inline(always)]
pub(super) fn depth_stencil_rows8(
    ds: &FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants,
) -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        if ds.depth_max < 1 << 31 && crate::common::cpu::available() {
            // SAFETY: AVX2 is present (checked just above).
            unsafe { x86::depth_stencil8(ds, tile, y, x0, x1, it) };
            return true;
        }
    }
    let _ = (ds, tile, y, x0, x1, it);
    false
}

#[cfg(target_arch = "x86_64")]
mod x86 {
    use std::arch::x86_64::*;

    use super::*;

    /// The lanes of `bits` as 32-bit masks (all ones where set).
    #[inline(always)]
    fn lane_masks(bits: u8) -> __m256i {
        // SAFETY: AVX2 is enabled in every caller (target_feature functions only).
        unsafe {
            let b = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
            _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(i32::from(bits)), b), b)
        }
    }

    /// Eight colour words from the lanes' stepped primary colours (`raw.color[0..4]`) as
    /// `finish_fragment` converts one: times w (`1 / (1/w)`) under `perspective`, then
    /// `color4_to_u8` (times 255, plus 0.5, clamped to [0, 255] with NaN as 0, truncated).
    #[target_feature(enable = "avx2")]
    fn words8(raw: &RawLanes, perspective: bool) -> __m256i {
        // SAFETY: each array holds eight f32; unaligned loads.
        let load = |a: &[f32; 8]| unsafe { _mm256_loadu_ps(a.as_ptr()) };
        let w = if perspective {
            _mm256_div_ps(_mm256_set1_ps(1.0), load(&raw.inv_w))
        } else {
            _mm256_set1_ps(1.0)
        };
        let byte = |c: usize| {
            let v = load(&raw.color[c]);
            simd::to_u8(if perspective { _mm256_mul_ps(v, w) } else { v })
        };
        simd::pack_words(&[byte(0), byte(1), byte(2), byte(3)])
    }

    /// [`simple_rows8`] with AVX2.
    #[target_feature(enable = "avx2")]
    pub(super) fn simple8<const DEPTH: u8, const FULL_MASK: bool>(
        ds: &FragmentDraw,
        tile: &mut Tile,
        y: i32,
        x0: i32,
        x1: i32,
        it: &Interpolants,
    ) {
        let func = match DEPTH {
            depth_mode::LESS_WRITE => Some(CompareFunc::Less),
            depth_mode::LEQUAL_WRITE => Some(CompareFunc::LessEqual),
            _ => None,
        };
        let tested = DEPTH != depth_mode::NONE;
        let n = (x1 - x0).max(0) as usize;
        let row = tile.index(x0, y);
        let mut run = SpanRun::new(it, x0, y as f64 + 0.5, 4);
        // A constant primary colour is the same word at every pixel (its steps of 0 change
        // at most the sign of a zero, which converts to the same byte).
        let constant = it.constant_primary.then(|| {
            let c = color4_to_u8([run.color[0], run.color[1], run.color[2], run.color[3]]);
            _mm256_set1_epi32(u32::from_le_bytes(c) as i32)
        });
        let perspective = run.primary_perspective;
        let cm =
            _mm256_set1_epi32(u32::from_le_bytes(
                ds.key.color_mask.map(|m| if m { 0xFF } else { 0 }),
            ) as i32);
        let mut raw = RawLanes::default();
        let mut z = [0f64; 8];
        let mut i = 0;
        while i < n {
            let m = (n - i).min(8);
            let at = row + i;
            let live = lane_bits(0..m);
            i += m;
            let words = match constant {
                Some(c) => {
                    // (Untested, nothing else is read: no steps.)
                    if tested {
                        run.z_lanes(&mut z, m);
                    }
                    c
                }
                None => {
                    run.primary_lanes(&mut raw, m);
                    z = raw.z;
                    words8(&raw, perspective)
                }
            };
            let whole = tile.color.len() >= at + 8 && (!tested || tile.depth.len() >= at + 8);
            let (depth, pass) = if tested {
                let mut stored = [0u32; 8];
                if whole {
                    stored.copy_from_slice(&tile.depth[at..at + 8]);
                } else {
                    stored[..m].copy_from_slice(&tile.depth[at..at + m]);
                }
                // (AVX2 is this function's feature; `depth_max` < 2^31, checked by the caller,
                // as `simd::depth8` requires it.)
                simd::depth8_avx2(&z, &stored, live, ds.depth_max, func)
            } else {
                ([0u32; 8], live)
            };
            if pass == 0 {
                continue;
            }
            let mask = lane_masks(pass);
            if whole {
                // SAFETY: pixels `at..at + 8` lie in the colour (and, when tested, depth)
                // buffers; masked unaligned loads and stores of eight 32-bit lanes.
                unsafe {
                    let cp = tile.color.as_mut_ptr().add(at) as *mut i32;
                    let out = if FULL_MASK {
                        words
                    } else {
                        let dst = _mm256_loadu_si256(cp as *const __m256i);
                        _mm256_or_si256(_mm256_andnot_si256(cm, dst), _mm256_and_si256(words, cm))
                    };
                    _mm256_maskstore_epi32(cp, mask, out);
                    if tested {
                        let dp = tile.depth.as_mut_ptr().add(at) as *mut i32;
                        let d = _mm256_loadu_si256(depth.as_ptr() as *const __m256i);
                        _mm256_maskstore_epi32(dp, mask, d);
                    }
                }
            } else {
                let mut w = [0u32; 8];
                // SAFETY: `w` holds eight u32; unaligned store.
                unsafe { _mm256_storeu_si256(w.as_mut_ptr() as *mut __m256i, words) };
                let cmask = u32::from_le_bytes(ds.key.color_mask.map(|m| if m { 0xFF } else { 0 }));
                for j in (0..m).filter(|j| pass & (1 << j) != 0) {
                    let dst = u32::from_le_bytes(tile.color[at + j]);
                    let v = if FULL_MASK {
                        w[j]
                    } else {
                        (dst & !cmask) | (w[j] & cmask)
                    };
                    tile.color[at + j] = v.to_le_bytes();
                    if tested {
                        tile.depth[at + j] = depth[j];
                    }
                }
            }
        }
    }

    /// The depths along a row as [`SpanRun`] steps them (its `z` alone: evaluated from the
    /// plane at the first pixel and at every [`RESTART`] column, stepped in between), for
    /// the colourless spans, which read nothing else.
    struct ZRun<'a> {
        plane: &'a Plane,
        z: f64,
        left: u32,
        restart_x: f64,
        yc: f64,
    }

    impl ZRun<'_> {
        #[inline(always)]
        fn new(plane: &Plane, x0: i32, yc: f64) -> ZRun<'_> {
            let into = x0.rem_euclid(RESTART);
            ZRun {
                plane,
                z: plane.at(x0 as f64 + 0.5, yc),
                left: (RESTART - into) as u32,
                restart_x: (x0 - into + RESTART) as f64 + 0.5,
                yc,
            }
        }

        /// The next eight pixels' depths (`SpanRun::next_z` eight times).
        #[inline(always)]
        fn lanes(&mut self, out: &mut [f64; 8]) {
            let dz = self.plane.a;
            for o in out.iter_mut() {
                *o = self.z;
                self.left -= 1;
                if self.left == 0 {
                    self.z = self.plane.at(self.restart_x, self.yc);
                    self.restart_x += RESTART as f64;
                    self.left = RESTART as u32;
                } else {
                    self.z += dz;
                }
            }
        }
    }

    /// [`depth_stencil_rows8`] with AVX2: the stencil kernel chosen once per span. The
    /// z-pass volumes' keys (test ALWAYS, KEEP on both failures, every bit written) change
    /// the passing lanes by one action on the bytes; others take `stencil8_word`.
    #[target_feature(enable = "avx2")]
    pub(super) fn depth_stencil8(
        ds: &FragmentDraw,
        tile: &mut Tile,
        y: i32,
        x0: i32,
        x1: i32,
        it: &Interpolants,
    ) {
        let one = _mm_set1_epi8(1);
        let z_pass = ds.key.stencil.filter(|st| {
            st.func == CompareFunc::Always
                && st.fail == StencilOp::Keep
                && st.depth_fail == StencilOp::Keep
                && ds.uniforms.stencil_write_mask == 0xFF
        });
        // `o`: the stored values; `dp`: 0xFF in the lanes that pass the depth test (all
        // of them pass the stencil test).
        match z_pass.map(|st| st.depth_pass) {
            Some(StencilOp::Incr) => rows(ds, tile, y, x0, x1, it, |o, dp| {
                _mm_adds_epu8(o, _mm_and_si128(dp, one))
            }),
            Some(StencilOp::Decr) => rows(ds, tile, y, x0, x1, it, |o, dp| {
                _mm_subs_epu8(o, _mm_and_si128(dp, one))
            }),
            Some(StencilOp::IncrWrap) => rows(ds, tile, y, x0, x1, it, |o, dp| {
                _mm_add_epi8(o, _mm_and_si128(dp, one))
            }),
            Some(StencilOp::DecrWrap) => rows(ds, tile, y, x0, x1, it, |o, dp| {
                _mm_sub_epi8(o, _mm_and_si128(dp, one))
            }),
            _ => rows(ds, tile, y, x0, x1, it, |_, _| _mm_setzero_si128()),
        }
    }

    /// The groups of [`depth_stencil8`] with the z-pass action `z_pass` (the new values from
    /// the stored ones and the depth-pass byte mask), used when the key is a z-pass key
    /// (see there); other keys with a stencil test take `stencil8_word`.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn rows(
        ds: &FragmentDraw,
        tile: &mut Tile,
        y: i32,
        x0: i32,
        x1: i32,
        it: &Interpolants,
        z_pass: impl Fn(__m128i, __m128i) -> __m128i,
    ) {
        let key = &ds.key;
        let simple = key.stencil.is_some_and(|st| {
            st.func == CompareFunc::Always
                && st.fail == StencilOp::Keep
                && st.depth_fail == StencilOp::Keep
                && ds.uniforms.stencil_write_mask == 0xFF
                && matches!(
                    st.depth_pass,
                    StencilOp::Incr | StencilOp::Decr | StencilOp::IncrWrap | StencilOp::DecrWrap
                )
        });
        let n = (x1 - x0).max(0) as usize;
        let row = tile.index(x0, y);
        let mut run = ZRun::new(&it.z, x0, y as f64 + 0.5);
        let mut z = [0f64; 8];
        // SAFETY: SSE2 is part of the x86-64 baseline; a register constant.
        let bits = unsafe { _mm_set_epi64x(0, 0x8040_2010_0804_0201u64 as i64) };
        let mut i = 0;
        while i < n {
            let m = (n - i).min(8);
            let at = row + i;
            let live = lane_bits(0..m);
            i += m;
            // (Lanes past `m` are stepped too and not used; the run ends with the span.)
            run.lanes(&mut z);
            let whole = tile.depth.len() >= at + 8
                && (key.stencil.is_none() || tile.stencil.len() >= at + 8);
            let mut stored = [0u32; 8];
            if whole {
                stored.copy_from_slice(&tile.depth[at..at + 8]);
            } else {
                stored[..m].copy_from_slice(&tile.depth[at..at + m]);
            }
            // (AVX2 is this function's feature; `depth_max` < 2^31, checked by the caller.)
            // SAFETY: AVX2 is enabled in every caller (`depth_stencil8`).
            let (depth, depth_pass) =
                unsafe { simd::depth8_avx2(&z, &stored, live, ds.depth_max, key.depth_func) };
            let pass = match key.stencil {
                Some(_) if whole && simple => {
                    let values: &mut [u8; 8] = (&mut tile.stencil[at..at + 8]).try_into().unwrap();
                    // SAFETY: SSE2 is part of the x86-64 baseline; registers only.
                    unsafe {
                        let o = _mm_cvtsi64_si128(u64::from_le_bytes(*values) as i64);
                        let dp_bits = _mm_set1_epi8(depth_pass as i8);
                        let dp = _mm_cmpeq_epi8(_mm_and_si128(dp_bits, bits), bits);
                        let new = z_pass(o, dp);
                        *values = (_mm_cvtsi128_si64(new) as u64).to_le_bytes();
                    }
                    depth_pass
                }
                Some(st) if whole => {
                    let values: &mut [u8; 8] = (&mut tile.stencil[at..at + 8]).try_into().unwrap();
                    let (new, pass) = stencil8_word(
                        &st,
                        &ds.uniforms,
                        u64::from_le_bytes(*values),
                        depth_pass,
                        live,
                    );
                    *values = new.to_le_bytes();
                    pass
                }
                _ => stencil_row(ds, tile, at, m, depth_pass),
            };
            if key.count_samples {
                tile.samples_passed += u64::from(pass.count_ones());
            }
            if key.depth_write && pass != 0 {
                if whole {
                    // SAFETY: pixels `at..at + 8` lie in the depth buffer; a masked unaligned
                    // store of eight 32-bit lanes (AVX2: every caller's feature).
                    unsafe {
                        let d = _mm256_loadu_si256(depth.as_ptr() as *const __m256i);
                        let dp = tile.depth.as_mut_ptr().add(at) as *mut i32;
                        _mm256_maskstore_epi32(dp, lane_masks(pass), d);
                    }
                } else {
                    for j in (0..m).filter(|j| pass & (1 << j) != 0) {
                        tile.depth[at + j] = depth[j];
                    }
                }
            }
        }
    }
}

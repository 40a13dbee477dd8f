//! A 4x2 block's inputs from the values its runs stepped ([`RawLanes`]): the per-pixel
//! arithmetic of [`SpanRun::next`] (w from 1/w, the perspective colours and fog coordinate,
//! the stored depth) and the depth test, eight lanes at once with AVX2 or lane by lane; the
//! same operations in the same precision, so the same bits
//! (`lane_inputs_are_the_per_lane_inputs` below).

use super::*;

/// The values a block's lanes were stepped to, before [`SpanRun::next`]'s per-pixel
/// arithmetic ([`SpanRun::record`]), and what the tile holds at the lanes' pixels.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct RawLanes {
    pub(super) z: [f64; 8],
    pub(super) inv_w: [f32; 8],
    /// Primary R, G, B, A as stepped (attribute/w under perspective), then secondary R, G, B.
    pub(super) color: [[f32; 8]; 7],
    /// The fog coordinate as stepped.
    pub(super) fog: [f32; 8],
    /// Stored depths and colour words of the lanes' pixels.
    pub(super) stored: [u32; 8],
    pub(super) dst: [u32; 8],
}

/// How a draw's lanes turn [`RawLanes`] into [`GroupInputs`] (fixed for a primitive).
#[derive(Clone, Copy, Debug)]
pub(super) struct LaneMath {
    /// w is 1/(1/w) (else 1).
    pub(super) perspective: bool,
    /// The primary colour is multiplied by w.
    pub(super) primary_perspective: bool,
    /// A constant primary colour (`Interpolants::constant_primary`): every lane's, not read
    /// from the raw lanes.
    pub(super) constant: Option<[f32; 4]>,
    /// The secondary colour is stepped (the colour sum).
    pub(super) secondary: bool,
    /// The fog coordinate is stepped (a fogged draw).
    pub(super) fog: bool,
    /// The depth range depths are converted to (`group_depth_max`), and the depth test
    /// (none without a depth range).
    pub(super) depth_max: Option<u32>,
    pub(super) depth_func: Option<CompareFunc>,
}

impl LaneMath {
    /// For the runs of primitive `it` in draw `ds`, fogged or not.
    pub(super) fn new(ds: &FragmentDraw, it: &Interpolants, fog: bool) -> LaneMath {
        let constant = constant_primary(it);
        LaneMath {
            perspective: it.perspective,
            primary_perspective: it.perspective && !it.constant_primary,
            constant,
            secondary: lane_colors(ds) == 8,
            fog,
            depth_max: group_depth_max(ds),
            depth_func: ds.key.depth_func,
        }
    }
}

impl LaneMath {
    /// The run values these lanes read (`load_raw` and `load_raw_lanes` read no others).
    pub(super) fn reads(&self) -> Reads {
        Reads {
            z: self.depth_max.is_some(),
            inv_w: self.perspective && (self.primary_perspective || self.secondary || self.fog),
            primary: self.constant.is_none(),
        }
    }
}

/// Every lane's primary colour of primitive `it` when it is constant
/// (`Interpolants::constant_primary`): the run's constant colour (`SpanRun::new`), which steps
/// of 0 keep.
pub(super) fn constant_primary(it: &Interpolants) -> Option<[f32; 4]> {
    it.constant_primary.then(|| {
        let run = SpanRun::new(it, 0, 0.5, 4);
        [run.color[0], run.color[1], run.color[2], run.color[3]]
    })
}

impl GroupInputs {
    /// The group of the lanes `live` from their stepped values `raw`, as [`GroupInputs::add`]
    /// with [`SpanRun::next`] gives it lane by lane: colours, depth, fog coordinate, secondary
    /// colour, stored colour and the depth test (lanes outside `live`: zero colour, depth
    /// and stored colour, not passing).
    #[inline(always)]
    pub(super) fn load_raw(&mut self, raw: &RawLanes, live: u8, m: &LaneMath) {
        #[cfg(target_arch = "x86_64")]
        if crate::common::cpu::available() {
            // SAFETY: AVX2 is present (checked just above).
            unsafe { x86::load_raw(self, raw, live, m) };
            return;
        }
        self.load_raw_lanes(raw, live, m)
    }

    /// [`GroupInputs::load_raw`] lane by lane.
    #[inline(always)]
    pub(super) fn load_raw_lanes(&mut self, raw: &RawLanes, live: u8, m: &LaneMath) {
        self.primary = [[0f32; 8]; 4];
        if let Some(c) = m.constant {
            self.primary = c.map(|v| [v; 8]);
        }
        self.depth = [0; 8];
        self.dst = [0; 8];
        self.pass = 0;
        for j in (0..8).filter(|j| live & (1 << j) != 0) {
            let w = if m.perspective {
                1.0 / raw.inv_w[j]
            } else {
                1.0
            };
            if m.constant.is_none() {
                for c in 0..4 {
                    let v = raw.color[c][j];
                    self.primary[c][j] = if m.primary_perspective { v * w } else { v };
                }
            }
            if m.secondary {
                for c in 0..3 {
                    self.after.secondary[c][j] = raw.color[4 + c][j] * w;
                }
            }
            self.after.fog[j] = match (m.fog, m.perspective) {
                (false, _) => 0.0,
                (true, true) => raw.fog[j] * w,
                (true, false) => raw.fog[j],
            };
            let d = m.depth_max.map_or(0, |max| depth_to_fixed(raw.z[j], max));
            self.depth[j] = d;
            let ok = match m.depth_func {
                None | Some(CompareFunc::Always) => true,
                Some(func) => func.test(d, raw.stored[j]),
            };
            self.pass |= u8::from(ok) << j;
            self.dst[j] = raw.dst[j];
        }
    }
}

#[cfg(target_arch = "x86_64")]
mod x86 {
    use std::arch::x86_64::*;

    use super::{depth_to_fixed, CompareFunc, GroupInputs, LaneMath, RawLanes};
    use crate::fragment::simd;
    use crate::texture::simd::x86::lane_mask;

    /// [`GroupInputs::load_raw`] with AVX2: `1 / (1/w)`, the products by w, and the depths
    /// by `simd::depth8` (lane by lane for a 32-bit depth range), all IEEE operations as the
    /// scalar ones.
    #[target_feature(enable = "avx2")]
    pub(super) fn load_raw(g: &mut GroupInputs, raw: &RawLanes, live: u8, m: &LaneMath) {
        // SAFETY: each array holds eight f32 (u32); unaligned loads and stores.
        let load = |a: &[f32; 8]| unsafe { _mm256_loadu_ps(a.as_ptr()) };
        let store = |a: &mut [f32; 8], v: __m256| unsafe { _mm256_storeu_ps(a.as_mut_ptr(), v) };
        let keep = lane_mask(live);
        // w is read by the perspective colours, the secondary colour and the perspective fog
        // coordinate only (a constant unfogged colour needs no division).
        let needs_w = m.primary_perspective || m.secondary || m.fog;
        let w = if m.perspective && needs_w {
            _mm256_div_ps(_mm256_set1_ps(1.0), load(&raw.inv_w))
        } else {
            _mm256_set1_ps(1.0)
        };
        match m.constant {
            Some(c) => {
                for (p, v) in g.primary.iter_mut().zip(c) {
                    store(p, _mm256_set1_ps(v));
                }
            }
            None => {
                for (p, v) in g.primary.iter_mut().zip(&raw.color) {
                    let v = load(v);
                    let v = if m.primary_perspective {
                        _mm256_mul_ps(v, w)
                    } else {
                        v
                    };
                    store(p, _mm256_and_ps(v, keep));
                }
            }
        }
        if m.secondary {
            for (s, v) in g.after.secondary.iter_mut().zip(&raw.color[4..]) {
                store(s, _mm256_mul_ps(load(v), w));
            }
        }
        let fog = if !m.fog {
            _mm256_setzero_ps()
        } else if m.perspective {
            _mm256_mul_ps(load(&raw.fog), w)
        } else {
            load(&raw.fog)
        };
        store(&mut g.after.fog, fog);
        // SAFETY: `dst` and `raw.dst` hold eight u32; unaligned load and store.
        unsafe {
            let dst = _mm256_loadu_si256(raw.dst.as_ptr() as *const __m256i);
            let dst = _mm256_and_si256(dst, _mm256_castps_si256(keep));
            _mm256_storeu_si256(g.dst.as_mut_ptr() as *mut __m256i, dst);
        }
        let Some(max) = m.depth_max else {
            g.depth = [0; 8];
            g.pass = live;
            return;
        };
        if let Some((depth, pass)) = simd::depth8(&raw.z, &raw.stored, live, max, m.depth_func) {
            // Lanes outside `live` at 0.
            let mut d = [0u32; 8];
            for j in 0..8 {
                d[j] = if live & (1 << j) != 0 { depth[j] } else { 0 };
            }
            g.depth = d;
            g.pass = pass;
            return;
        }
        g.depth = [0; 8];
        g.pass = 0;
        for j in (0..8).filter(|j| live & (1 << j) != 0) {
            let d = depth_to_fixed(raw.z[j], max);
            g.depth[j] = d;
            let ok = match m.depth_func {
                None | Some(CompareFunc::Always) => true,
                Some(func) => func.test(d, raw.stored[j]),
            };
            g.pass |= u8::from(ok) << j;
        }
    }
}

/// The block loop's rows with AVX2: each row's stepped values in one vector, its four
/// lanes' values transposed into the eight-lane group in registers (`VecRun`,
/// `load_block`); the same sums and products as [`SpanRun::record4`] / [`SpanRun::advance`]
/// and [`GroupInputs::load_raw`], so the same bits (`vector_rows_are_the_recorded_rows`).
#[cfg(target_arch = "x86_64")]
pub(super) mod vec {
    use std::arch::x86_64::*;

    use super::RESTART;
    use super::{attr, depth_to_fixed, CompareFunc, GroupInputs, Interpolants, LaneMath, Plane};
    use crate::framebuffer::Tile;
    use crate::texture::simd::x86::lane_mask;

    /// Whether a run's stepped values fit one vector of eight channels (`VecRun`): 1/w, the
    /// primary colour, then the fog coordinate (`FOG`) or the secondary colour, not both.
    #[inline(always)]
    pub(in crate::fragment::span) fn fits<const FOG: bool>(colors: usize) -> bool {
        !(FOG && colors == 8)
    }

    /// A row's run as [`SpanRun`] steps it (from its first pixel, restarted at the same
    /// columns), its 1/w, colours and fog coordinate stepped together as the eight channels
    /// of one vector: 1/w, R, G, B, A, then the fog coordinate (`FOG`) or the secondary R,
    /// then the secondary G and B. Each channel is the running sum the run's own steps give
    /// (one `vaddps` is eight such additions), and a restart column's channels are the
    /// planes' values there, evaluated eight at once (`Plane::at`'s products and sums in
    /// f64, then rounded to f32); z is stepped alone, in f64.
    #[derive(Clone, Copy)]
    pub(in crate::fragment::span) struct VecRun {
        s: __m256,
        d: __m256,
        z: f64,
        dz: f64,
        /// Steps left before the current pixel is a restart column, the centre of the next
        /// restart column (as in `SpanRun`).
        left: u32,
        restart_x: f64,
        /// The channels' planes: a, and b * yc + ... as `Plane::at` sums them: `a * x` then
        /// `+ b * yc` then `+ c` (channels 0..4, then 4..8).
        a: [__m256d; 2],
        by: [__m256d; 2],
        c: [__m256d; 2],
        /// z's plane a, b * yc, c.
        za: f64,
        zby: f64,
        zc: f64,
    }

    impl VecRun {
        /// The run of `colors` colours (4 or 8) from pixel `x0` of the row centred at `yc`
        /// of primitive `it`, fogged with `FOG` (as `SpanRun::new`, then `SpanRun::fog_on`
        /// with `FOG`).
        ///
        /// # Safety
        /// AVX2 must be present (as for every function here: inlined into the AVX2 block
        /// loop, a `#[target_feature]` function could not be forced inline).
        #[inline(always)]
        pub(in crate::fragment::span) unsafe fn new<const FOG: bool>(
            it: &Interpolants,
            x0: i32,
            yc: f64,
            colors: usize,
        ) -> VecRun {
            let zero = Plane {
                a: 0.0,
                b: 0.0,
                c: 0.0,
            };
            // A constant primary colour is c + 0 at every pixel (`SpanRun::new`): its plane
            // as 0 x + 0 y + c gives that (x and y positive), with steps of 0.
            let color = |c: usize| {
                let p = it.attrs[attr::color(c)];
                if c < 4 && it.constant_primary {
                    Plane {
                        a: 0.0,
                        b: 0.0,
                        c: p.c,
                    }
                } else if c < colors {
                    p
                } else {
                    zero
                }
            };
            let x5 = if FOG { it.attrs[attr::FOG] } else { color(4) };
            let planes = [
                it.inv_w,
                color(0),
                color(1),
                color(2),
                color(3),
                x5,
                color(5),
                color(6),
            ];
            let half = |k: usize, f: fn(&Plane) -> f64| {
                let p = &planes[4 * k..4 * k + 4];
                _mm256_setr_pd(f(&p[0]), f(&p[1]), f(&p[2]), f(&p[3]))
            };
            let yv = _mm256_set1_pd(yc);
            let a = [half(0, |p| p.a), half(1, |p| p.a)];
            let by = [
                _mm256_mul_pd(half(0, |p| p.b), yv),
                _mm256_mul_pd(half(1, |p| p.b), yv),
            ];
            let c = [half(0, |p| p.c), half(1, |p| p.c)];
            // The steps: each plane's a as f32.
            let d = _mm256_set_m128(_mm256_cvtpd_ps(a[1]), _mm256_cvtpd_ps(a[0]));
            let into = x0.rem_euclid(RESTART);
            let mut run = VecRun {
                s: d,
                d,
                z: 0.0,
                dz: it.z.a,
                left: (RESTART - into) as u32,
                restart_x: (x0 - into + RESTART) as f64 + 0.5,
                a,
                by,
                c,
                za: it.z.a,
                zby: it.z.b * yc,
                zc: it.z.c,
            };
            (run.s, run.z) = run.at(x0 as f64 + 0.5);
            run
        }

        /// The channels and z at the pixel centred at `x` of the row.
        ///
        /// # Safety
        /// AVX2 must be present.
        #[inline(always)]
        unsafe fn at(&self, x: f64) -> (__m256, f64) {
            let xv = _mm256_set1_pd(x);
            let v = |k: usize| {
                _mm256_cvtpd_ps(_mm256_add_pd(
                    _mm256_add_pd(_mm256_mul_pd(self.a[k], xv), self.by[k]),
                    self.c[k],
                ))
            };
            (
                _mm256_set_m128(v(1), v(0)),
                self.za * x + self.zby + self.zc,
            )
        }

        /// The next restart column's values, moving the restart on (`SpanRun::restart`).
        ///
        /// # Safety
        /// AVX2 must be present.
        #[inline(always)]
        unsafe fn restart(&mut self) -> (__m256, f64) {
            let x = self.restart_x;
            self.restart_x = x + RESTART as f64;
            self.left = RESTART as u32;
            self.at(x)
        }

        /// The values of lanes `lo..hi` (within 0..4, not empty) of a block's row, moving
        /// past them as `hi - lo` calls of `SpanRun::advance` do: lane j's channels and its
        /// z (lanes outside `lo..hi` hold any values).
        ///
        /// # Safety
        /// AVX2 must be present.
        #[inline(always)]
        pub(in crate::fragment::span) unsafe fn row(
            &mut self,
            lo: usize,
            hi: usize,
        ) -> ([__m256; 4], __m256d) {
            let n = (hi - lo) as u32;
            let (d, dz) = (self.d, self.dz);
            let a0 = self.s;
            let a1 = _mm256_add_ps(a0, d);
            let a2 = _mm256_add_ps(a1, d);
            let a3 = _mm256_add_ps(a2, d);
            let z0 = self.z;
            let z1 = z0 + dz;
            let z2 = z1 + dz;
            let z3 = z2 + dz;
            if n <= self.left {
                // No restart column among the lanes after the first: the running sums.
                if n == self.left {
                    // The next pixel is one.
                    (self.s, self.z) = self.restart();
                } else {
                    self.left -= n;
                    (self.s, self.z) = match n {
                        1 => (a1, z1),
                        2 => (a2, z2),
                        3 => (a3, z3),
                        _ => (_mm256_add_ps(a3, d), z3 + dz),
                    };
                }
                let (v, z) = match lo {
                    0 => ([a0, a1, a2, a3], [z0, z1, z2, z3]),
                    1 => ([a0, a0, a1, a2], [z0, z0, z1, z2]),
                    2 => ([a0, a0, a0, a1], [z0, z0, z0, z1]),
                    _ => ([a0; 4], [z0; 4]),
                };
                return (v, _mm256_setr_pd(z[0], z[1], z[2], z[3]));
            }
            if n == 4 && self.left == 2 {
                // A whole row whose lane 2 is a restart column (blocks start at even columns,
                // restart columns are multiples of 16: the only place one falls inside a
                // whole row): the sums from the run's values, then from the restart column's.
                let (b0, y0) = self.restart();
                let b1 = _mm256_add_ps(b0, d);
                let y1 = y0 + dz;
                // Then two steps from the restart column (the last one past the row).
                self.left = RESTART as u32 - 2;
                self.s = _mm256_add_ps(b1, d);
                self.z = y1 + dz;
                return ([a0, a1, b0, b1], _mm256_setr_pd(z0, z1, y0, y1));
            }
            // A restart column elsewhere among the lanes (a partial row): lane by lane.
            let mut v = [a0; 4];
            let mut z = [z0; 4];
            for j in lo..hi {
                v[j] = self.s;
                z[j] = self.z;
                self.left -= 1;
                if self.left == 0 {
                    (self.s, self.z) = self.restart();
                } else {
                    self.s = _mm256_add_ps(self.s, d);
                    self.z += dz;
                }
            }
            (v, _mm256_setr_pd(z[0], z[1], z[2], z[3]))
        }
    }

    /// The stored depths and colour words of columns `lo..hi` (within 0..4) of a block's row
    /// starting at pixel `row` of `tile` (other columns: any values): the four at once where
    /// they lie in the tile's buffers, else one by one.
    ///
    /// # Safety
    /// AVX2 must be present.
    #[inline(always)]
    pub(in crate::fragment::span) unsafe fn tile_row(
        tile: &Tile,
        row: usize,
        lo: usize,
        hi: usize,
    ) -> (__m128i, __m128i) {
        if let (Some(depth), Some(color)) =
            (tile.depth.get(row..row + 4), tile.color.get(row..row + 4))
        {
            // SAFETY: each slice holds four 4-byte values; unaligned loads.
            return unsafe {
                (
                    _mm_loadu_si128(depth.as_ptr() as *const __m128i),
                    _mm_loadu_si128(color.as_ptr() as *const __m128i),
                )
            };
        }
        let (mut depth, mut color) = ([0u32; 4], [0u32; 4]);
        for j in lo..hi {
            depth[j] = tile.depth[row + j];
            color[j] = u32::from_le_bytes(tile.color[row + j]);
        }
        // SAFETY: each array holds four u32; unaligned loads.
        unsafe {
            (
                _mm_loadu_si128(depth.as_ptr() as *const __m128i),
                _mm_loadu_si128(color.as_ptr() as *const __m128i),
            )
        }
    }

    /// Channel k of lanes 0..4 (row 0) and 4..8 (row 1) from each lane's channel vector.
    ///
    /// # Safety
    /// AVX2 must be present.
    #[inline(always)]
    unsafe fn transpose(r0: &[__m256; 4], r1: &[__m256; 4]) -> [__m256; 8] {
        // Lanes' channels 0..4 (low halves: row 0, high: row 1), then 4..8.
        let lo: [__m256; 4] = std::array::from_fn(|j| _mm256_permute2f128_ps(r0[j], r1[j], 0x20));
        let hi: [__m256; 4] = std::array::from_fn(|j| _mm256_permute2f128_ps(r0[j], r1[j], 0x31));
        // A 4x4 transpose within each 128-bit half.
        let t4 = |x: &[__m256; 4]| {
            let t0 = _mm256_unpacklo_ps(x[0], x[1]);
            let t1 = _mm256_unpackhi_ps(x[0], x[1]);
            let t2 = _mm256_unpacklo_ps(x[2], x[3]);
            let t3 = _mm256_unpackhi_ps(x[2], x[3]);
            [
                _mm256_shuffle_ps::<0x44>(t0, t2),
                _mm256_shuffle_ps::<0xEE>(t0, t2),
                _mm256_shuffle_ps::<0x44>(t1, t3),
                _mm256_shuffle_ps::<0xEE>(t1, t3),
            ]
        };
        let [a, b, c, d] = t4(&lo);
        let [e, f, g, h] = t4(&hi);
        [a, b, c, d, e, f, g, h]
    }

    /// A block's row values as [`GroupInputs::load_raw`] gives them: `rows[r]` and `z[r]`
    /// are row r's lanes ([`VecRun::row`]), `stored` and `dst` the tile's depths and colour
    /// words of the eight lanes, `live` the covered lanes.
    ///
    /// # Safety
    /// AVX2 must be present.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(in crate::fragment::span) unsafe fn load_block<const FOG: bool>(
        g: &mut GroupInputs,
        rows: &[[__m256; 4]; 2],
        z: [__m256d; 2],
        stored: __m256i,
        dst: __m256i,
        live: u8,
        m: &LaneMath,
    ) {
        // SAFETY: each array holds eight f32 (u32); unaligned stores.
        let store = |a: &mut [f32; 8], v: __m256| unsafe { _mm256_storeu_ps(a.as_mut_ptr(), v) };
        // A constant colour without fog, secondary colour or products by w reads no channel
        // (as `horizon`'s ground): no transposition.
        let reads = m.reads();
        let t = if reads.primary || reads.inv_w || m.fog || m.secondary {
            transpose(&rows[0], &rows[1])
        } else {
            [_mm256_setzero_ps(); 8]
        };
        let keep = lane_mask(live);
        let needs_w = m.primary_perspective || m.secondary || m.fog;
        let w = if m.perspective && needs_w {
            _mm256_div_ps(_mm256_set1_ps(1.0), t[0])
        } else {
            _mm256_set1_ps(1.0)
        };
        match m.constant {
            Some(c) => {
                for (p, v) in g.primary.iter_mut().zip(c) {
                    store(p, _mm256_set1_ps(v));
                }
            }
            None => {
                for (c, p) in g.primary.iter_mut().enumerate() {
                    let v = t[1 + c];
                    let v = if m.primary_perspective {
                        _mm256_mul_ps(v, w)
                    } else {
                        v
                    };
                    store(p, _mm256_and_ps(v, keep));
                }
            }
        }
        if m.secondary {
            for (c, s) in g.after.secondary.iter_mut().enumerate() {
                store(s, _mm256_mul_ps(t[5 + c], w));
            }
        }
        let fog = if !m.fog {
            _mm256_setzero_ps()
        } else if m.perspective {
            _mm256_mul_ps(t[5], w)
        } else {
            t[5]
        };
        // Unfogged blocks (`FOG` off) have no fog coordinate in channel 5.
        let fog = if FOG { fog } else { _mm256_setzero_ps() };
        store(&mut g.after.fog, fog);
        let keep_i = _mm256_castps_si256(keep);
        // SAFETY: `dst` holds eight u32; unaligned store.
        unsafe {
            _mm256_storeu_si256(
                g.dst.as_mut_ptr() as *mut __m256i,
                _mm256_and_si256(dst, keep_i),
            )
        };
        let Some(max) = m.depth_max else {
            g.depth = [0; 8];
            g.pass = live;
            return;
        };
        if max < 1 << 31 {
            // As `simd::depth8`.
            let maxv = _mm256_set1_pd(max as f64);
            let half = |z: __m256d| {
                let v = _mm256_add_pd(_mm256_mul_pd(z, maxv), _mm256_set1_pd(0.5));
                // max_pd answers its second operand (0) when v is NaN.
                _mm256_cvttpd_epi32(_mm256_min_pd(_mm256_max_pd(v, _mm256_setzero_pd()), maxv))
            };
            let d = _mm256_set_m128i(half(z[1]), half(z[0]));
            let d = _mm256_and_si256(d, keep_i);
            // SAFETY: `depth` holds eight u32; unaligned store.
            unsafe { _mm256_storeu_si256(g.depth.as_mut_ptr() as *mut __m256i, d) };
            // Unsigned order through signed comparisons: both sides with the top bit flipped.
            let flip = _mm256_set1_epi32(i32::MIN);
            let (a, b) = (_mm256_xor_si256(d, flip), _mm256_xor_si256(stored, flip));
            let all = _mm256_set1_epi32(-1);
            let ok = match m.depth_func {
                None | Some(CompareFunc::Always) => all,
                Some(CompareFunc::Never) => _mm256_setzero_si256(),
                Some(CompareFunc::Less) => _mm256_cmpgt_epi32(b, a),
                Some(CompareFunc::LessEqual) => _mm256_xor_si256(_mm256_cmpgt_epi32(a, b), all),
                Some(CompareFunc::Equal) => _mm256_cmpeq_epi32(a, b),
                Some(CompareFunc::Greater) => _mm256_cmpgt_epi32(a, b),
                Some(CompareFunc::GreaterEqual) => _mm256_xor_si256(_mm256_cmpgt_epi32(b, a), all),
                Some(CompareFunc::NotEqual) => _mm256_xor_si256(_mm256_cmpeq_epi32(a, b), all),
            };
            g.pass = live & _mm256_movemask_ps(_mm256_castsi256_ps(ok)) as u8;
            return;
        }
        // A 32-bit depth range: lane by lane.
        let (mut zs, mut old) = ([0f64; 8], [0u32; 8]);
        // SAFETY: `zs` holds eight f64 and `old` eight u32; unaligned stores.
        unsafe {
            _mm256_storeu_pd(zs.as_mut_ptr(), z[0]);
            _mm256_storeu_pd(zs.as_mut_ptr().add(4), z[1]);
            _mm256_storeu_si256(old.as_mut_ptr() as *mut __m256i, stored);
        }
        g.depth = [0; 8];
        g.pass = 0;
        for j in (0..8).filter(|j| live & (1 << j) != 0) {
            let d = depth_to_fixed(zs[j], max);
            g.depth[j] = d;
            let ok = match m.depth_func {
                None | Some(CompareFunc::Always) => true,
                Some(func) => func.test(d, old[j]),
            };
            g.pass |= u8::from(ok) << j;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A group's bits, for comparing: every field the tail reads.
    fn bits(g: &GroupInputs) -> Vec<u32> {
        let mut v: Vec<u32> = g.primary.iter().flatten().map(|f| f.to_bits()).collect();
        v.extend(g.depth);
        v.push(u32::from(g.pass));
        v.extend(g.dst);
        v.extend(g.after.fog.map(f32::to_bits));
        v.extend(g.after.secondary.iter().flatten().map(|f| f.to_bits()));
        v
    }

    /// The eight-lane inputs are the lane-by-lane ones bit for bit, for every combination of
    /// perspective, constant colour, secondary colour, fog, depth range and depth function,
    /// with 1/w from tiny through negative to zero and infinite, colours and fog coordinates
    /// of every sign, and z outside [0, 1] and NaN.
    #[test]
    fn lane_inputs_are_the_per_lane_inputs() {
        if !crate::common::cpu::available() {
            return;
        }
        let funcs = crate::test_support::DEPTH_FUNCS;
        let specials = [
            0.0f32,
            -0.0,
            1e-30,
            -2.5,
            f32::INFINITY,
            f32::NAN,
            3e38,
            0.37,
        ];
        let mut seed = 0x1234_5678_9ABC_DEF1u64;
        let mut next = || crate::test_support::xorshift(&mut seed);
        let mut checked = 0;
        for case in 0..20_000 {
            let r = next();
            let perspective = r & 1 != 0;
            let mut m = LaneMath {
                perspective,
                primary_perspective: perspective && r & 2 != 0,
                constant: (r & 4 != 0).then_some([0.25, -0.5, 1.5, 0.75]),
                secondary: r & 8 != 0,
                fog: r & 16 != 0,
                depth_max: [None, Some(0xFFFF), Some(0xFF_FFFF), Some(u32::MAX)]
                    [(r >> 5) as usize % 4],
                depth_func: funcs[(r >> 8) as usize % funcs.len()],
            };
            // No depth range means no depth test (`group_depth_max`).
            if m.depth_max.is_none() {
                m.depth_func = None;
            }
            let mut value = || {
                let r = next();
                if r % 6 == 0 {
                    specials[(r >> 8) as usize % specials.len()]
                } else {
                    ((r >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 1.0) as f32
                }
            };
            let mut raw = RawLanes::default();
            for j in 0..8 {
                raw.inv_w[j] = value();
                raw.fog[j] = value();
                for c in 0..7 {
                    raw.color[c][j] = value();
                }
                raw.z[j] = value() as f64 * 0.7 + 0.3;
            }
            for j in 0..8 {
                let r = next();
                let max = m.depth_max.unwrap_or(0xFFFF);
                raw.stored[j] = match r % 3 {
                    0 => depth_to_fixed(raw.z[j], max),
                    1 => depth_to_fixed(raw.z[j], max).wrapping_add(1),
                    _ => (r >> 8) as u32 % max.saturating_add(1).max(1),
                };
                raw.dst[j] = (r >> 20) as u32;
            }
            let live = (next() & 0xFF) as u8;
            let mut fast = GroupInputs::EMPTY;
            let mut slow = GroupInputs::EMPTY;
            fast.load_raw(&raw, live, &m);
            slow.load_raw_lanes(&raw, live, &m);
            // Lanes outside `live`: their fog coordinates and secondary colours are not read
            // (`GroupInputs::refill` leaves them stale too).
            for j in (0..8).filter(|j| live & (1 << j) == 0) {
                fast.after.fog[j] = 0.0;
                slow.after.fog[j] = 0.0;
                for c in 0..3 {
                    fast.after.secondary[c][j] = 0.0;
                    slow.after.secondary[c][j] = 0.0;
                }
            }
            assert_eq!(
                bits(&fast),
                bits(&slow),
                "case {case}: {m:?} live {live:#x} {raw:?}"
            );
            checked += 1;
        }
        assert_eq!(checked, 20_000);
    }

    /// One case of `vector_rows_are_the_recorded_rows`: a row pair's blocks from runs started
    /// at `x0s` (covering to `x1s`) of primitive `it`, recorded lane by lane and loaded
    /// (`SpanRun::record4` / `record` / `advance`, `load_raw_lanes`, as the scalar block loop
    /// does) and stepped as vectors (`VecRun::row`, `load_block`); answers the blocks compared.
    #[cfg(target_arch = "x86_64")]
    fn vector_case<const FOG: bool>(
        it: &Interpolants,
        colors: usize,
        m: &LaneMath,
        rows: [(i32, i32); 2],
        y: i32,
        next: &mut dyn FnMut() -> u64,
    ) -> usize {
        use std::arch::x86_64::*;
        let reads = m.reads();
        let new_run = |r: usize| {
            let mut run = SpanRun::new(it, rows[r].0, y as f64 + 0.5 + r as f64, colors);
            if FOG {
                run.fog_on();
            }
            run
        };
        let mut scalar = [new_run(0), new_run(1)];
        let vector_run = |r: usize| {
            // SAFETY: AVX2 is present (checked by the caller).
            unsafe { vec::VecRun::new::<FOG>(it, rows[r].0, y as f64 + 0.5 + r as f64, colors) }
        };
        let mut vector = [vector_run(0), vector_run(1)];
        let first = rows[0].0.min(rows[1].0);
        let end = rows[0].1.max(rows[1].1);
        let mut blocks = 0;
        let mut gx = first & !1;
        while gx < end {
            let mut raw = RawLanes::default();
            let mut live = 0u8;
            let mut values = [[unsafe { _mm256_setzero_ps() }; 4]; 2];
            let mut z = [unsafe { _mm256_setzero_pd() }; 2];
            for r in 0..2 {
                let lo = (rows[r].0 - gx).clamp(0, 4) as usize;
                let hi = (rows[r].1 - gx).clamp(0, 4) as usize;
                if lo >= hi {
                    continue;
                }
                let run = &mut scalar[r];
                let whole = lo == 0 && hi == 4;
                let done = whole
                    && if r == 0 {
                        run.record4::<FOG, 0>(&mut raw, reads)
                    } else {
                        run.record4::<FOG, 1>(&mut raw, reads)
                    };
                if !done {
                    for j in lo..hi {
                        run.record::<FOG>(&mut raw, 4 * r + j, reads.primary);
                        run.advance::<FOG>();
                    }
                }
                // SAFETY: AVX2 is present.
                (values[r], z[r]) = unsafe { vector[r].row(lo, hi) };
                live |= (((1u32 << hi) - (1u32 << lo)) as u8) << (4 * r);
            }
            if live != 0 {
                let max = m.depth_max.unwrap_or(0xFFFF);
                for j in 0..8 {
                    let r = next();
                    raw.stored[j] = match r % 3 {
                        0 => depth_to_fixed(raw.z[j], max),
                        1 => depth_to_fixed(raw.z[j], max).wrapping_add(1),
                        _ => (r >> 8) as u32 % max.saturating_add(1).max(1),
                    };
                    raw.dst[j] = (r >> 20) as u32;
                }
                let mut slow = GroupInputs::EMPTY;
                slow.load_raw_lanes(&raw, live, m);
                let mut fast = GroupInputs::EMPTY;
                // SAFETY: AVX2 is present; `raw`'s arrays hold eight u32.
                unsafe {
                    let stored = _mm256_loadu_si256(raw.stored.as_ptr() as *const __m256i);
                    let dst = _mm256_loadu_si256(raw.dst.as_ptr() as *const __m256i);
                    vec::load_block::<FOG>(&mut fast, &values, z, stored, dst, live, m);
                }
                for j in (0..8).filter(|j| live & (1 << j) == 0) {
                    for g in [&mut fast, &mut slow] {
                        g.after.fog[j] = 0.0;
                        for c in 0..3 {
                            g.after.secondary[c][j] = 0.0;
                        }
                    }
                }
                assert_eq!(
                    bits(&fast),
                    bits(&slow),
                    "gx {gx} rows {rows:?} y {y} {m:?} live {live:#x} {raw:?}"
                );
                blocks += 1;
            }
            gx += 4;
        }
        blocks
    }

    /// The block loop's vector rows (`vec::VecRun`, `vec::load_block`) give the group the
    /// recorded rows give (`SpanRun::record4` and `record`, then `load_raw_lanes`) bit for
    /// bit: rows starting and ending anywhere (partial rows, restart columns inside and at
    /// the edge of blocks), fogged or not, with and without perspective, a constant or
    /// secondary colour, every depth range and function.
    #[test]
    #[cfg(target_arch = "x86_64")]
    fn vector_rows_are_the_recorded_rows() {
        if !crate::common::cpu::available() {
            return;
        }
        let funcs = crate::test_support::DEPTH_FUNCS;
        let mut seed = 0x0DDB_1A5E_5BAD_5EEDu64;
        let mut next = move || crate::test_support::xorshift(&mut seed);
        let mut blocks = 0;
        for case in 0..3000 {
            let r = next();
            let unit = |k: u64| (k >> 11) as f64 / (1u64 << 53) as f64;
            let mut plane = |scale: f64| Plane {
                a: (unit(next()) - 0.5) * 0.05 * scale,
                b: (unit(next()) - 0.5) * 0.05 * scale,
                c: unit(next()) * scale,
            };
            let attrs: Vec<Plane> = (0..attr::TEX).map(|_| plane(1.0)).collect();
            let z = plane(1.0);
            let inv_w = Plane {
                c: 0.2 + plane(1.0).c,
                ..plane(0.1)
            };
            let perspective = r & 1 != 0;
            let constant = r & 2 != 0;
            let mut attrs = attrs;
            if constant {
                for c in 0..4 {
                    attrs[attr::color(c)].a = 0.0;
                    attrs[attr::color(c)].b = 0.0;
                }
            }
            let levels = UnitLevels::default();
            let shared = PrimitiveShared::new(&levels);
            let it = Interpolants {
                z,
                inv_w,
                attrs: &attrs,
                perspective,
                constant_primary: constant,
                coverage: 1.0,
                shared: &shared,
            };
            let fog = r & 4 != 0;
            let colors = if r & 8 != 0 && !fog { 8 } else { 4 };
            let mut m = LaneMath {
                perspective,
                primary_perspective: perspective && !constant,
                constant: constant_primary(&it),
                secondary: colors == 8,
                fog,
                depth_max: [None, Some(0xFFFF), Some(0xFF_FFFF), Some(u32::MAX)]
                    [(r >> 5) as usize % 4],
                depth_func: funcs[(r >> 8) as usize % funcs.len()],
            };
            if m.depth_max.is_none() {
                m.depth_func = None;
            }
            let span = |k: u64| {
                let x0 = (k % 70) as i32;
                (x0, x0 + ((k >> 8) % 60) as i32)
            };
            let rows = [span(next()), span(next())];
            let y = (next() % 64) as i32 * 2;
            blocks += if fog {
                vector_case::<true>(&it, colors, &m, rows, y, &mut next)
            } else {
                vector_case::<false>(&it, colors, &m, rows, y, &mut next)
            };
            let _ = case;
        }
        assert!(blocks > 10_000, "{blocks}");
    }
}

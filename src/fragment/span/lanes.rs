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
        let funcs = [
            None,
            Some(CompareFunc::Never),
            Some(CompareFunc::Less),
            Some(CompareFunc::Equal),
            Some(CompareFunc::LessEqual),
            Some(CompareFunc::Greater),
            Some(CompareFunc::NotEqual),
            Some(CompareFunc::GreaterEqual),
            Some(CompareFunc::Always),
        ];
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
}

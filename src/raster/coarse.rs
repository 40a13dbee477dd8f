//! Coarse depth: the largest depth of each of a tile's 8x8 blocks (8x8 pixels each in a tile
//! of the default side, 64; a tile of side S has blocks of S/8 pixels), so that a triangle whose
//! fragments are all farther than everything stored in the blocks it covers is dropped before
//! it is rasterized. Under a `LESS`, `LEQUAL` or `EQUAL` depth test such fragments all fail,
//! and without a stencil test (`FragmentKey::stencil` is `None`) a failing fragment changes
//! nothing, so dropping them leaves every pixel as it was. The hidden surfaces of a multipass
//! effect (the second pass of an environment-mapped model, drawn with `LEQUAL` over the
//! first pass's depths) cost nothing beyond their setup.
//!
//! The block maxima live with the worker shading one tile of one scene (the tile is its alone
//! then), are computed on first use and forgotten for the blocks a command may write depth to.

use super::draw::TileDraw;
use super::setup::Plane;
use crate::common::fixed::depth_to_fixed;
use crate::common::rect::Rect;
use crate::common::values::CompareFunc;
use crate::fragment::key::FragmentKey;
use crate::framebuffer::Tile;

/// Pixels per side of a block in a tile of the default side (the AVX2 maximum's shape).
const BLOCK: usize = 8;
/// Blocks per side of a tile.
const BLOCKS: usize = 8;

/// The largest stored depth of each block of one tile, where known.
#[derive(Clone, Debug)]
pub struct CoarseDepth {
    max: [u32; BLOCKS * BLOCKS],
    /// Bit `b` set: `max[b]` is the largest depth of block `b` (row-major from the bottom).
    known: u64,
    /// Tests in a row that hid nothing (see [`CoarseDepth::hides`]).
    misses: u32,
    /// Tests still to be skipped (answered "not hidden") after a run of misses.
    skip: u32,
}

/// Misses in a row after which the test is skipped for the next [`SKIP`] triangles: in a
/// scene drawn back to front (`fog`'s terrain) it hides nothing and costs its block maxima
/// (recomputed after every depth write) at every triangle. A skipped test only rasterizes a
/// triangle that the depth test then rejects everywhere: the pixels are the same.
const MISSES: u32 = 16;
/// Triangles whose test is skipped after [`MISSES`] misses in a row; one test in `SKIP + 1`
/// is still made while nothing is hidden, and the first hit makes every test again.
const SKIP: u32 = 8;

impl Default for CoarseDepth {
    fn default() -> Self {
        CoarseDepth {
            max: [0; BLOCKS * BLOCKS],
            known: 0,
            misses: 0,
            skip: 0,
        }
    }
}

impl CoarseDepth {
    /// The blocks of `tile` that the window rectangle `rect` touches (none when it misses the
    /// tile).
    fn blocks(tile: &Tile, rect: Rect) -> u64 {
        let t = tile.side();
        let (x0, x1) = (rect.x0.max(tile.x0), rect.x1.min(tile.x0 + t));
        let (y0, y1) = (rect.y0.max(tile.y0), rect.y1.min(tile.y0 + t));
        if x0 >= x1 || y0 >= y1 {
            return 0;
        }
        // Offsets inside the tile (not negative): blocks by shifting (a block is 1/8 of the
        // tile's side, a power of two).
        let b = tile.shift - 3;
        let (bx0, bx1) = ((x0 - tile.x0) as u32 >> b, (x1 - 1 - tile.x0) as u32 >> b);
        let (by0, by1) = ((y0 - tile.y0) as u32 >> b, (y1 - 1 - tile.y0) as u32 >> b);
        // Block columns bx0..=bx1 of one block row (eight bits), then a marker bit at the
        // start of each block row by0..=by1: their product repeats the row on those rows.
        const _: () = assert!(BLOCKS == 8);
        let row = (0xFFu64 >> (7 - bx1)) & (0xFFu64 << bx0);
        let rows =
            0x0101_0101_0101_0101u64 & (u64::MAX >> (8 * (7 - by1))) & (u64::MAX << (8 * by0));
        rows * row
    }

    /// Forgets the blocks that a command writing depth over `rect` may change.
    pub fn forget(&mut self, tile: &Tile, rect: Rect) {
        self.known &= !Self::blocks(tile, rect);
    }

    /// The largest stored depth of block `b`.
    fn block_max(&mut self, tile: &Tile, b: usize) -> u32 {
        if self.known & (1 << b) == 0 {
            let (bx, by) = (b % BLOCKS, b / BLOCKS);
            let side = tile.side() as usize;
            let block = side / BLOCKS;
            self.max[b] = if block == BLOCK {
                // The block's rows `side` apart, one slice from its first to its last depth.
                let start = by * BLOCK * side + bx * BLOCK;
                match tile.depth.get(start..start + (BLOCK - 1) * side + BLOCK) {
                    Some(rows) => block_max(rows, side),
                    None => u32::MAX,
                }
            } else {
                (0..block)
                    .flat_map(|row| {
                        let start = (by * block + row) * side + bx * block;
                        &tile.depth[start..start + block]
                    })
                    .fold(0, |m, &d| m.max(d))
            };
            self.known |= 1 << b;
        }
        self.max[b]
    }

    /// Whether every fragment of a triangle of draw `ds` with window-z plane `z` whose
    /// fragments lie in `rect` (inside `tile`) fails the depth test.
    /// (Inlined, `rect` by value: built just before the call, it would otherwise be passed
    /// through memory and read back by wide loads its narrow stores cannot forward to.)
    #[inline(always)]
    pub fn hides(&mut self, tile: &Tile, ds: &TileDraw, z: &Plane, rect: Rect) -> bool {
        if !ds.coarse_depth || !z.a.is_finite() || !z.b.is_finite() || !z.c.is_finite() {
            return false;
        }
        if self.skip > 0 {
            self.skip -= 1;
            return false;
        }
        let hidden = self.test(tile, ds, z, rect);
        if hidden {
            self.misses = 0;
        } else {
            self.misses += 1;
            if self.misses >= MISSES {
                self.skip = SKIP;
            }
        }
        hidden
    }

    /// The test of [`CoarseDepth::hides`] made every time (`z` finite).
    #[inline(always)]
    fn test(&mut self, tile: &Tile, ds: &TileDraw, z: &Plane, rect: Rect) -> bool {
        // The plane is smallest at a corner of the rectangle of pixel centres. The spans
        // evaluate it at each row's first pixel and at every 16th column and step z by `a`
        // in between (fewer than 16 steps, bounded here by a tile's side), so their depths
        // differ from the corners' by rounding: each evaluation by a few ulps of its largest
        // term, each step by an ulp of the running value. The margin bounds that with room to
        // spare; it must scale with the terms (a vertex thousands of pixels away makes
        // `b * y` and `c` large while z stays in [0, 1]).
        let (xa, xb) = (rect.x0 as f64 + 0.5, rect.x1 as f64 - 0.5);
        let (ya, yb) = (rect.y0 as f64 + 0.5, rect.y1 as f64 - 0.5);
        let zmin = lowest_corner(z, xa, xb, ya, yb);
        let most = |p: f64, q: f64| if q > p { q } else { p };
        let terms = z.a.abs() * most(xa.abs(), xb.abs())
            + z.b.abs() * most(ya.abs(), yb.abs())
            + z.c.abs()
            + z.a.abs() * tile.side() as f64;
        let margin = 1e-9 + 256.0 * f64::EPSILON * terms;
        if !zmin.is_finite() || !margin.is_finite() {
            return false;
        }
        // depth_to_fixed does not decrease with z: no fragment is nearer than this.
        let nearest = depth_to_fixed(zmin - margin, ds.fragment.depth_max);
        let mut blocks = Self::blocks(tile, rect);
        while blocks != 0 {
            let b = blocks.trailing_zeros() as usize;
            blocks &= blocks - 1;
            if self.block_max(tile, b) >= nearest {
                return false;
            }
        }
        true
    }
}

/// The least of `z` at the four corners (`Plane::at`) of `xa..=xb` x `ya..=yb`, evaluated once:
/// rounded addition does not decrease in either argument, so the smaller products give exactly
/// the least of the four evaluations.
#[inline(always)]
fn lowest_corner(z: &Plane, xa: f64, xb: f64, ya: f64, yb: f64) -> f64 {
    // Plain comparisons, not `f64::min` (whose NaN handling costs more): the callers pass
    // finite planes and corners, whose products are not NaN.
    let least = |p: f64, q: f64| if q < p { q } else { p };
    least(z.a * xa, z.a * xb) + least(z.b * ya, z.b * yb) + z.c
}

/// Whether a key's fragments that fail the depth test change nothing, and a triangle whose
/// fragments are all farther than the stored depths therefore fails everywhere: a `LESS`,
/// `LEQUAL` or `EQUAL` depth test and no stencil test.
pub fn applies(key: &FragmentKey) -> bool {
    key.stencil.is_none()
        && matches!(
            key.depth_func,
            Some(CompareFunc::Less | CompareFunc::LessEqual | CompareFunc::Equal)
        )
}

/// The largest of a block's depths: its `BLOCK` rows of `BLOCK` depths start `stride` apart
/// in `rows` (which ends with the last row; `stride >= BLOCK`). AVX2 where the processor has
/// it: without SSE4.1 the unsigned maximum is not vectorized, and blocks are recomputed after
/// every depth write.
#[inline]
fn block_max(rows: &[u32], stride: usize) -> u32 {
    if stride < BLOCK || rows.len() < (BLOCK - 1) * stride + BLOCK {
        return u32::MAX;
    }
    #[cfg(target_arch = "x86_64")]
    {
        if crate::common::cpu::available() {
            // SAFETY: AVX2 is present (checked just above); the length was checked above.
            return unsafe { block_max_avx2(rows, stride) };
        }
    }
    (0..BLOCK)
        .flat_map(|r| &rows[r * stride..r * stride + BLOCK])
        .fold(0, |m, &d| m.max(d))
}

/// # Safety
/// AVX2 is present, and `rows.len() >= (BLOCK - 1) * stride + BLOCK`.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn block_max_avx2(rows: &[u32], stride: usize) -> u32 {
    use std::arch::x86_64::*;
    let mut m = _mm256_setzero_si256();
    for r in 0..BLOCK {
        // SAFETY: row `r` is the BLOCK = 8 u32 (32 bytes) from `r * stride`, inside `rows`
        // by the caller's length guarantee; unaligned load.
        let v = unsafe { _mm256_loadu_si256(rows.as_ptr().add(r * stride) as *const __m256i) };
        m = _mm256_max_epu32(m, v);
    }
    let m = _mm_max_epu32(_mm256_castsi256_si128(m), _mm256_extracti128_si256::<1>(m));
    let m = _mm_max_epu32(m, _mm_shuffle_epi32::<0b01_00_11_10>(m));
    let m = _mm_max_epu32(m, _mm_shuffle_epi32::<0b10_11_00_01>(m));
    _mm_cvtsi128_si32(m) as u32
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tile() -> Tile {
        Tile {
            x0: 64,
            y0: 128,
            shift: 6,
            color: vec![[0; 4]; 64 * 64],
            depth: vec![0; 64 * 64],
            stencil: vec![0; 64 * 64],
            samples_passed: 0,
        }
    }

    #[test]
    fn blocks_of_a_rectangle() {
        let t = tile();
        let r = |x0, y0, x1, y1| Rect { x0, y0, x1, y1 };
        // The tile's first block only.
        assert_eq!(CoarseDepth::blocks(&t, r(64, 128, 72, 136)), 1);
        // Pixels 71..73 x 135..137 straddle four blocks.
        assert_eq!(
            CoarseDepth::blocks(&t, r(71, 135, 73, 137)),
            0b11 | 0b11 << 8
        );
        // The whole tile, and a rectangle beyond it.
        assert_eq!(CoarseDepth::blocks(&t, r(0, 0, 1000, 1000)), u64::MAX);
        assert_eq!(CoarseDepth::blocks(&t, r(0, 0, 64, 1000)), 0);
    }

    #[test]
    fn block_max_finds_the_largest_depth_anywhere_in_the_block() {
        // Every position in turn holds the largest value, including values above 2^31
        // (unsigned order).
        // Rows `stride` apart; the depths between them (larger still) are not the block's.
        for stride in [8usize, 11, 64] {
            for big in [1u32, 77, 0x00FF_FFFF, 0x8000_0001, u32::MAX] {
                for at in 0..BLOCK * BLOCK {
                    let mut data = vec![u32::MAX; (BLOCK - 1) * stride + BLOCK];
                    for r in 0..BLOCK {
                        data[r * stride..r * stride + BLOCK].fill(3);
                    }
                    data[(at / BLOCK) * stride + at % BLOCK] = big;
                    assert_eq!(block_max(&data, stride), big.max(3), "{big} at {at}");
                }
            }
        }
    }

    #[test]
    fn blocks_of_every_rectangle_inside_a_tile() {
        let t = tile();
        let naive = |x0: i32, x1: i32, y0: i32, y1: i32| {
            let mut m = 0u64;
            for y in y0..y1 {
                for x in x0..x1 {
                    m |= 1 << ((y / 8) * 8 + x / 8);
                }
            }
            m
        };
        let ranges: Vec<(i32, i32)> = (0..64)
            .flat_map(|a| (a + 1..=64).map(move |b| (a, b)))
            .collect();
        let block_ranges: Vec<(i32, i32)> = ranges
            .iter()
            .copied()
            .filter(|&(a, b)| a % 3 == 0 || b % 5 == 0)
            .collect();
        for &(x0, x1) in &ranges {
            for &(y0, y1) in &block_ranges {
                let r = Rect {
                    x0: t.x0 + x0,
                    y0: t.y0 + y0,
                    x1: t.x0 + x1,
                    y1: t.y0 + y1,
                };
                assert_eq!(
                    CoarseDepth::blocks(&t, r),
                    naive(x0, x1, y0, y1),
                    "{x0}..{x1} x {y0}..{y1}"
                );
            }
        }
    }

    #[test]
    fn lowest_corner_is_the_least_of_the_four_evaluations() {
        // Planes of every sign and magnitude (tiny to huge, cancelling terms), random corners.
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            let seed = crate::test_support::xorshift(&mut seed);
            let unit = (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            unit * 10f64.powi((seed % 17) as i32 - 8)
        };
        for _ in 0..100_000 {
            let z = Plane {
                a: next(),
                b: next(),
                c: next(),
            };
            let (x, y) = (next().abs() * 1e-3, next().abs() * 1e-3);
            let (xa, xb, ya, yb) = (x, x + next().abs(), y, y + next().abs());
            let four = [z.at(xa, ya), z.at(xb, ya), z.at(xa, yb), z.at(xb, yb)]
                .into_iter()
                .fold(f64::INFINITY, f64::min);
            assert_eq!(
                lowest_corner(&z, xa, xb, ya, yb),
                four,
                "{z:?} {xa} {xb} {ya} {yb}"
            );
        }
    }

    #[test]
    fn block_maxima_follow_forgotten_writes() {
        let mut t = tile();
        let mut c = CoarseDepth::default();
        t.depth[64 * 9 + 10] = 77; // block (1, 1)
        assert_eq!(c.block_max(&t, 9), 77);
        t.depth[64 * 9 + 11] = 99;
        // Not forgotten: the stale maximum.
        assert_eq!(c.block_max(&t, 9), 77);
        c.forget(
            &t,
            Rect {
                x0: 75,
                y0: 137,
                x1: 76,
                y1: 138,
            },
        );
        assert_eq!(c.block_max(&t, 9), 99);
    }
}

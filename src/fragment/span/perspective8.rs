//! One RGBA8 unit along a perspective span eight pixels at a time with AVX2 (`Perspective8`),
//! and its 4x2 block form for row pairs.

use super::*;

/// Most mipmap levels a fast texture can have (sizes below 2^16).
pub(super) const MAX_FAST_LEVELS: usize = 17;

/// One RGBA8 unit over one row of a perspective span, eight pixels at a time with AVX2: the
/// s, t and q planes on the pixel's row and on the other row of its 2x2 quads, and the
/// levels prepared for [`texture_simd::filter8`] (on first use). Texels equal those of [`FastUnit::texel`] (the
/// general path): the same coordinates, the same per-quad derivatives, λ and level plan
/// (computed per quad by the sampler's own functions), the same filter arithmetic.
pub(super) struct Perspective8<'a> {
    /// `[row][s, t, q] = [a, b * y, c]`: row 0 is the pixel's row, row 1 the quad's other.
    pub(super) planes: [[[f64; 3]; 3]; 2],
    /// Whether the pixel's row is the upper row of its quads.
    pub(super) own_is_upper: bool,
    /// The level and filter when they do not depend on λ (which is then not computed).
    pub(super) fixed_plan: Option<(usize, bool)>,
    /// λ and level selection, gathered once for the draw.
    pub(super) lod: &'a LodSelect,
    /// The texture's levels prepared for the filter ([`UnitLevels`]; a cube map's first face).
    pub(super) levels: &'a [Option<Level8<'a>>; MAX_FAST_LEVELS],
    /// A cube map's r planes and faces (`None` for 2D textures).
    pub(super) cube: Option<Cube8<'a>>,
}

/// What a cube map adds to [`Perspective8`]: each lane's direction needs r, and each lane
/// samples the face its direction selects.
#[derive(Clone, Copy)]
pub(super) struct Cube8<'a> {
    /// The r plane on the sampler's two rows, as `Perspective8::planes`.
    r: [[f64; 3]; 2],
    /// The six faces' levels (+X, -X, +Y, -Y, +Z, -Z).
    faces: &'a [[Option<Level8<'a>>; MAX_FAST_LEVELS]],
}

impl<'a> Perspective8<'a> {
    /// The eight-pixel sampler on row `y` of the unit at index `k` of the draw's units, when
    /// every level of its texture takes the eight-pixel filter (the draw's key has
    /// `simd_units`: every unit's texture passes `BoundTexture::simd_2d`).
    #[inline(always)]
    pub(super) fn new(
        unit: &'a TextureUnitDraw,
        k: usize,
        it: &Interpolants<'a>,
        y: i32,
    ) -> Option<Perspective8<'a>> {
        let yc = y as f64 + 0.5;
        // Quads start on even rows (`quad_origin`): an odd row is the upper one.
        let own_is_upper = y & 1 != 0;
        let other = if own_is_upper { yc - 1.0 } else { yc + 1.0 };
        Self::on_rows(unit, k, it, [yc, other], own_is_upper)
    }

    /// The sampler with its planes on rows (centres) `rows`; `own_is_upper` says whether the
    /// first is the upper row of its quads.
    #[inline(always)]
    pub(super) fn on_rows(
        unit: &'a TextureUnitDraw,
        k: usize,
        it: &Interpolants<'a>,
        rows: [f64; 2],
        own_is_upper: bool,
    ) -> Option<Perspective8<'a>> {
        // No table (no `simd_units` or no AVX2), or a base level that does not take the
        // filter: sampled one by one.
        let faces = it.shared.levels.faces(k)?;
        let levels = &faces[0];
        levels[0]?;
        let base = attr::TEX + 4 * unit.unit;
        let p = [&it.attrs[base], &it.attrs[base + 1], &it.attrs[base + 3]];
        let row = |y: f64| p.map(|pl| [pl.a, pl.b * y, pl.c]);
        let cube = (faces.len() == 6).then(|| {
            let r = &it.attrs[base + 2];
            Cube8 {
                r: rows.map(|y| [r.a, r.b * y, r.c]),
                faces,
            }
        });
        Some(Perspective8 {
            planes: [row(rows[0]), row(rows[1])],
            own_is_upper,
            lod: &unit.lod,
            fixed_plan: unit.fixed_plan,
            levels,
            cube,
        })
    }

    /// Level `l` prepared for the eight-pixel filter, or `None` when it does not take it.
    #[inline(always)]
    pub(super) fn level(&self, l: usize) -> Option<&'a Level8<'a>> {
        // A reference into the table, not a copy: the filter reads the level right away, and
        // a fresh copy's stores would not forward to its wider loads.
        self.levels.get(l)?.as_ref()
    }

    /// The texels of the eight pixels centred at `x + j`, `x - 0.5` even (so lanes 2k and
    /// 2k + 1 form a quad's row), written into `out`; only lanes whose bit is set in `live`
    /// matter. False when a coordinate is beyond the filter's range (the caller samples one by
    /// one).
    pub(super) fn texels_into(&mut self, x: f64, live: u8, out: &mut Texels8) -> bool {
        if self.cube.is_some() {
            return self.cube_row(x, live, out).is_some();
        }
        let Some(rows) = texture_simd::perspective_rows8(&self.planes, x) else {
            return false;
        };
        self.texels_at(&rows, live, out).is_some()
    }

    pub(super) fn texels_at(
        &self,
        rows: &[[[f64; 8]; 2]; 2],
        live: u8,
        out: &mut Texels8,
    ) -> Option<()> {
        let (upper, lower) = if self.own_is_upper {
            (&rows[0], &rows[1])
        } else {
            (&rows[1], &rows[0])
        };
        let fix = |v: f64| finite_or_zero(v as f32);
        let mut s = [0f32; 8];
        let mut t = [0f32; 8];
        for j in 0..8 {
            s[j] = fix(rows[0][0][j]);
            t[j] = fix(rows[0][1][j]);
        }
        // Quad k is lanes 2k and 2k + 1; its derivatives from its upper row and left column.
        let derivatives = |k: usize| {
            let (l, r) = (2 * k, 2 * k + 1);
            let dx = [
                fix(upper[0][r] - upper[0][l]),
                fix(upper[1][r] - upper[1][l]),
                0.0,
            ];
            let dy = [
                fix(upper[0][l] - lower[0][l]),
                fix(upper[1][l] - lower[1][l]),
                0.0,
            ];
            (dx, dy)
        };
        self.filter_quads(&s, &t, [0x03, 0x0C, 0x30, 0xC0], derivatives, live, out)
    }

    /// The sampler of the 4x2 blocks of rows `y` (even) and `y + 1` of the unit at index `k`
    /// of the draw's units ([`Perspective8::texels_block`]), when [`Perspective8::new`] would
    /// give one. (Inlined: built in place, the sampler is not copied through memory, whose
    /// stores the block kernels' loads of the planes would wait for.)
    #[inline(always)]
    pub(super) fn block(
        unit: &'a TextureUnitDraw,
        k: usize,
        it: &Interpolants<'a>,
        y: i32,
    ) -> Option<Perspective8<'a>> {
        // Row 0 is row y, row 1 row y + 1 (the upper row of the block's quads).
        Self::on_rows(unit, k, it, [y as f64 + 0.5, y as f64 + 1.5], false)
    }

    /// The texels of a 4x2 block from a sampler made by [`Perspective8::block`]: lanes 0..4 are
    /// the pixels centred at `x + j` on the lower row, lanes 4..8 the same columns on the upper
    /// row, `x - 0.5` even (two whole quads). The same texels as [`Perspective8::texels_into`]
    /// gives each pixel on its own row. False when a coordinate is beyond the filter's range.
    pub(super) fn texels_block(&self, x: f64, live: u8, out: &mut Texels8) -> bool {
        if self.cube.is_some() {
            return self.cube_block(x, live, out).is_some();
        }
        // A 2D texture (or a fixed plan) in one go: the same texels.
        let levels: &[Option<Level8>] = self.levels;
        if texture_simd::block_texels8(
            &self.planes,
            x,
            live,
            self.fixed_plan,
            self.lod,
            levels,
            out,
        )
        .is_some()
        {
            return true;
        }
        let Some([vs, vt]) = texture_simd::perspective_block8(&self.planes, x) else {
            return false;
        };
        let fix = |v: f64| finite_or_zero(v as f32);
        let mut s = [0f32; 8];
        let mut t = [0f32; 8];
        for j in 0..8 {
            s[j] = fix(vs[j]);
            t[j] = fix(vt[j]);
        }
        // Quad q is columns 2q and 2q + 1 of both rows: lanes 2q, 2q + 1, 2q + 4 and 2q + 5.
        let derivatives = |q: usize| {
            let (l, r) = (2 * q, 2 * q + 1);
            let dx = [fix(vs[4 + r] - vs[4 + l]), fix(vt[4 + r] - vt[4 + l]), 0.0];
            let dy = [fix(vs[4 + l] - vs[l]), fix(vt[4 + l] - vt[l]), 0.0];
            (dx, dy)
        };
        self.filter_quads(&s, &t, [0x33, 0xCC], derivatives, live, out)
            .is_some()
    }

    /// [`Perspective8::texels_block`] as R, G, B, A bytes per lane (colour words: the texels
    /// are these bytes converted, `b * (1 / 255)`), for a 2D texture; `None` for a cube map or
    /// where [`Perspective8::texels_block`] would not take the block kernel. The caller
    /// checked that the processor has AVX2.
    #[cfg(target_arch = "x86_64")]
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(super) fn block_bytes(&self, x: f64, live: u8) -> Option<std::arch::x86_64::__m256i> {
        if self.cube.is_some() {
            return None;
        }
        let levels: &[Option<Level8>] = self.levels;
        let (words, level) = texture_simd::x86::block_words8(
            &self.planes,
            x,
            live,
            self.fixed_plan,
            self.lod,
            levels,
        )?;
        Some(match level {
            Some(l) => texture_simd::x86::rgba_of_words(l.base(), words),
            None => words,
        })
    }

    /// [`Perspective8::texels_block`] and the tail in one go ([`simd::block_shaded8`]) for a
    /// 2D texture. `None` for a cube map or where the block kernel does not take the block
    /// (the caller takes the usual route: the same pixels).
    #[inline(always)]
    pub(super) fn shaded_block(
        &self,
        x: f64,
        group: &GroupInputs,
        tail: &Tail8,
    ) -> Option<([u32; 8], u8)> {
        if self.cube.is_some() {
            return None;
        }
        simd::block_shaded8(
            &self.planes,
            x,
            group.pass,
            self.fixed_plan,
            self.lod,
            self.levels,
            tail,
            &group.primary,
            &group.dst,
            &group.after,
        )
    }

    /// The texels at lane coordinates `s`, `t` into `out` (lanes set in `live`), quad k (lanes
    /// `quads[k]`, x and y derivatives `derivatives(k)`, asked only when λ is needed) with its
    /// own λ and level plan, quads of one plan filtered together.
    #[inline(always)]
    pub(super) fn filter_quads<const N: usize>(
        &self,
        s: &[f32; 8],
        t: &[f32; 8],
        quads: [u8; N],
        derivatives: impl Fn(usize) -> ([f32; 3], [f32; 3]),
        live: u8,
        out: &mut Texels8,
    ) -> Option<()> {
        // Per quad: the level plan; per lane: its weight between the plan's two levels.
        let mut plan = [(0usize, 0usize, false); N];
        let mut weight = [0f32; 8];
        let fixed = self.fixed_plan;
        for (k, (pl, &lanes)) in plan.iter_mut().zip(&quads).enumerate() {
            if let Some((level, linear)) = fixed {
                *pl = (level, level, linear);
                continue;
            }
            if live & lanes == 0 {
                continue;
            }
            let (dx, dy) = derivatives(k);
            // The weight quantised as `filter8_mix` quantises it.
            let plan = self.lod.quantised_plan(dx, dy);
            *pl = match plan {
                LevelPlan::One { level, linear } => (level, level, linear),
                LevelPlan::Two {
                    levels,
                    linear,
                    weight: w,
                } => {
                    let mut m = lanes;
                    while m != 0 {
                        weight[m.trailing_zeros() as usize] = w;
                        m &= m - 1;
                    }
                    (levels[0], levels[1], linear)
                }
            };
        }
        let mut done = !live;
        for (k, &quad_lanes) in quads.iter().enumerate() {
            if done & quad_lanes == quad_lanes {
                continue;
            }
            let (d1, d2, linear) = plan[k];
            // The lanes of every quad with this plan.
            let mut lanes = 0u8;
            for (other, &m) in plan.iter().zip(&quads) {
                if *other == plan[k] {
                    lanes |= m;
                }
            }
            lanes &= !done;
            done |= lanes;
            let all = done == 0xFF && lanes == live;
            let texels = if d2 == d1 {
                texture_simd::filter8(self.level(d1)?, linear, s, t)?
            } else {
                let levels = [self.level(d1)?, self.level(d2)?];
                texture_simd::filter8_mix(levels, linear, s, t, &weight)?
            };
            // One plan for every live lane (the usual case): no merging.
            if all {
                *out = texels;
                return Some(());
            }
            for j in 0..8 {
                if lanes & (1 << j) != 0 {
                    for c in 0..4 {
                        out[c][j] = texels[c][j];
                    }
                }
            }
        }
        Some(())
    }
}

/// A direction or its derivative as the general path rounds it (`unit_coords`).
#[inline(always)]
fn fix3(v: [f64; 3]) -> [f32; 3] {
    v.map(|c| finite_or_zero(c as f32))
}

impl Perspective8<'_> {
    /// The direction (s/q, t/q, r/q in f64) at pixel centre `x` on the sampler's row `row`,
    /// as `coords_at` evaluates it.
    #[inline(always)]
    fn direction(&self, cube: &Cube8, row: usize, x: f64) -> [f64; 3] {
        let p = &self.planes[row];
        let at = |pl: &[f64; 3]| pl[0] * x + pl[1] + pl[2];
        let q = at(&p[2]);
        [at(&p[0]) / q, at(&p[1]) / q, at(&cube.r[row]) / q]
    }

    /// [`Perspective8::texels_into`] for a cube map: the pixels centred at `x + j` on the
    /// sampler's own row.
    fn cube_row(&self, x: f64, live: u8, out: &mut Texels8) -> Option<()> {
        let cube = self.cube.as_ref()?;
        let mut coords = [[0f32; 3]; 8];
        let mut grads = [([0f32; 3], [0f32; 3]); 8];
        let need_lambda = self.fixed_plan.is_none();
        let (upper, lower) = if self.own_is_upper { (0, 1) } else { (1, 0) };
        for k in 0..4 {
            let quad = 0b11u8 << (2 * k);
            if live & quad == 0 {
                continue;
            }
            let (l, r) = (2 * k, 2 * k + 1);
            for j in [l, r] {
                if live & (1 << j) != 0 {
                    coords[j] = fix3(self.direction(cube, 0, x + j as f64));
                }
            }
            if need_lambda {
                // The quad's derivatives from its upper row and left column.
                let ul = self.direction(cube, upper, x + l as f64);
                let ur = self.direction(cube, upper, x + r as f64);
                let ll = self.direction(cube, lower, x + l as f64);
                let dx = fix3([0, 1, 2].map(|c| ur[c] - ul[c]));
                let dy = fix3([0, 1, 2].map(|c| ul[c] - ll[c]));
                grads[l] = (dx, dy);
                grads[r] = (dx, dy);
            }
        }
        self.cube_filter(cube, &coords, &grads, live, out)
    }

    /// [`Perspective8::texels_block`] for a cube map: lanes 0..4 the pixels centred at
    /// `x + j` on the lower row, lanes 4..8 the same columns on the upper row.
    fn cube_block(&self, x: f64, live: u8, out: &mut Texels8) -> Option<()> {
        let cube = self.cube.as_ref()?;
        if let Some((level, linear)) = self.fixed_plan {
            // No λ: the eight lanes' directions and faces at once (AVX2), then the lanes of
            // each face filtered together, as `cube_filter` does with a fixed plan.
            if let Some((faces, s, t)) = texture_simd::cube_block_faces8(&self.planes, &cube.r, x) {
                return cube_faces_filter(cube, &faces, &s, &t, level, linear, live, out);
            }
        }
        let mut coords = [[0f32; 3]; 8];
        let mut grads = [([0f32; 3], [0f32; 3]); 8];
        let need_lambda = self.fixed_plan.is_none();
        for q in 0..2 {
            let lanes = [2 * q, 2 * q + 1, 2 * q + 4, 2 * q + 5];
            let quad = lanes.iter().fold(0u8, |m, j| m | 1 << j);
            if live & quad == 0 {
                continue;
            }
            let mut dirs = [[0f64; 3]; 4];
            for (d, &j) in dirs.iter_mut().zip(&lanes) {
                if need_lambda || live & (1 << j) != 0 {
                    *d = self.direction(cube, j / 4, x + (j % 4) as f64);
                    coords[j] = fix3(*d);
                }
            }
            if need_lambda {
                // Lanes: lower left, lower right, upper left, upper right.
                let dx = fix3([0, 1, 2].map(|c| dirs[3][c] - dirs[2][c]));
                let dy = fix3([0, 1, 2].map(|c| dirs[2][c] - dirs[0][c]));
                for j in lanes {
                    grads[j] = (dx, dy);
                }
            }
        }
        self.cube_filter(cube, &coords, &grads, live, out)
    }

    /// [`Perspective8::texels_block`] for a cube map with a fixed level plan, the texels left
    /// in registers: the eight lanes' faces and face coordinates at once
    /// (`cube_block_faces8_regs`), then the lanes of each face filtered together
    /// (`filter8_regs`, what `filter8` stores) and merged by lane mask, as
    /// [`Perspective8::cube_block`] gives them through `cube_faces_filter` (the same faces,
    /// groups, filter and texels at every lane of `live`; the other lanes are any value).
    /// `None` for a 2D texture, without a fixed plan, or where `cube_block` would answer
    /// `None` (the caller then takes the usual route, which gives the same texels). The
    /// caller checked that the processor has AVX2.
    #[cfg(target_arch = "x86_64")]
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(super) fn cube_block_regs(
        &self,
        x: f64,
        live: u8,
    ) -> Option<[std::arch::x86_64::__m256; 4]> {
        use std::arch::x86_64::*;
        use texture_simd::x86::{cube_block_faces8_regs, filter8_regs, lane_mask};
        let cube = self.cube.as_ref()?;
        let (level, linear) = self.fixed_plan?;
        let (face, s, t) = cube_block_faces8_regs(&self.planes, &cube.r, x);
        let mut faces = [0u32; 8];
        // SAFETY: eight u32; unaligned store.
        unsafe { _mm256_storeu_si256(faces.as_mut_ptr() as *mut __m256i, face) };
        let lanes_of = |f: u32| {
            let eq = _mm256_cmpeq_epi32(face, _mm256_set1_epi32(f as i32));
            _mm256_movemask_ps(_mm256_castsi256_ps(eq)) as u8
        };
        let filter = |f: u32| {
            let lvl = cube.faces.get(f as usize)?.get(level)?.as_ref()?;
            filter8_regs(lvl, linear, s, t)
        };
        let first = faces[live.trailing_zeros() as usize & 7];
        let mut lanes = lanes_of(first) & live;
        let mut out = filter(first)?;
        let mut left = live & !lanes;
        while left != 0 {
            let f = faces[left.trailing_zeros() as usize];
            lanes = lanes_of(f) & left;
            left &= !lanes;
            let texels = filter(f)?;
            let m = lane_mask(lanes);
            for (o, v) in out.iter_mut().zip(texels) {
                *o = _mm256_blendv_ps(*o, v, m);
            }
        }
        Some(out)
    }

    /// The texels of a cube map at the lanes' directions `coords` (lanes set in `live`), as
    /// `BoundTexture::sample_grad` samples each: the face and its coordinates by
    /// `cube_face`, λ from the quad's derivatives `grads` projected on that face (unless the
    /// plan is fixed), the level plan, then the face's levels filtered eight lanes at a time
    /// for the lanes that share a face and plan.
    fn cube_filter(
        &self,
        cube: &Cube8,
        coords: &[[f32; 3]; 8],
        grads: &[([f32; 3], [f32; 3]); 8],
        live: u8,
        out: &mut Texels8,
    ) -> Option<()> {
        use crate::texture::sample::{cube_face, cube_face_derivatives};
        let mut s = [0f32; 8];
        let mut t = [0f32; 8];
        let mut weight = [0f32; 8];
        // Per lane: face, first and second level, linear.
        let mut plan = [(0usize, 0usize, 0usize, false); 8];
        let mut m = live;
        while m != 0 {
            let j = m.trailing_zeros() as usize;
            m &= m - 1;
            let (face, st) = cube_face(coords[j]);
            (s[j], t[j]) = (st[0], st[1]);
            plan[j] = match self.fixed_plan {
                Some((level, linear)) => (face, level, level, linear),
                None => {
                    let (dx, dy) =
                        cube_face_derivatives(face, st, coords[j], grads[j].0, grads[j].1);
                    // The weight quantised as `filter8_mix` quantises it.
                    match self.lod.quantised_plan(dx, dy) {
                        LevelPlan::One { level, linear } => (face, level, level, linear),
                        LevelPlan::Two {
                            levels: [a, b],
                            linear,
                            weight: w,
                        } => {
                            weight[j] = w;
                            (face, a, b, linear)
                        }
                    }
                }
            };
        }
        let mut left = live;
        while left != 0 {
            let first = plan[left.trailing_zeros() as usize];
            let mut lanes = 0u8;
            let mut m = left;
            while m != 0 {
                let j = m.trailing_zeros() as usize;
                m &= m - 1;
                if plan[j] == first {
                    lanes |= 1 << j;
                }
            }
            left &= !lanes;
            let (face, d1, d2, linear) = first;
            let level = |l: usize| cube.faces.get(face)?.get(l)?.as_ref();
            let texels = if d2 == d1 {
                texture_simd::filter8(level(d1)?, linear, &s, &t)?
            } else {
                texture_simd::filter8_mix([level(d1)?, level(d2)?], linear, &s, &t, &weight)?
            };
            if put_lanes(out, texels, lanes, live) {
                return Some(());
            }
        }
        Some(())
    }
}

/// The lanes `lanes` of `texels` into `out`; whether they are all of `live` (then `out` is
/// `texels` and the block is done).
#[inline(always)]
fn put_lanes(out: &mut Texels8, texels: Texels8, lanes: u8, live: u8) -> bool {
    if lanes == live {
        *out = texels;
        return true;
    }
    for j in 0..8 {
        if lanes & (1 << j) != 0 {
            for c in 0..4 {
                out[c][j] = texels[c][j];
            }
        }
    }
    false
}

/// The texels of a cube map at lanes whose faces and face coordinates are `faces`, `s`, `t`
/// (lanes set in `live`), level `level` of each face filtered (`linear` or not) for the lanes
/// that share a face: what [`Perspective8::cube_filter`] gives with a fixed plan.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn cube_faces_filter(
    cube: &Cube8,
    faces: &[u32; 8],
    s: &[f32; 8],
    t: &[f32; 8],
    level: usize,
    linear: bool,
    live: u8,
    out: &mut Texels8,
) -> Option<()> {
    let mut left = live;
    while left != 0 {
        let face = faces[left.trailing_zeros() as usize];
        let mut lanes = 0u8;
        for (j, &f) in faces.iter().enumerate() {
            lanes |= u8::from(f == face) << j;
        }
        lanes &= left;
        left &= !lanes;
        let lvl = cube.faces.get(face as usize)?.get(level)?.as_ref()?;
        let texels = texture_simd::filter8(lvl, linear, s, t)?;
        if put_lanes(out, texels, lanes, live) {
            return Some(());
        }
    }
    Some(())
}

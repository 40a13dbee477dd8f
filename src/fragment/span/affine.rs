//! The fast 2D texture path of one unit over one span (`FastUnit`), with the level selection
//! shared by a whole affine span (`AffineSpan`).

use super::*;

/// One unit on the fast 2D path over one span: the texture, the coordinate planes and, for
/// an affine span, the level selection shared by all its pixels.
pub(super) struct FastUnit<'a> {
    pub(super) unit: &'a TextureUnitDraw,
    /// Index of the unit's s plane.
    pub(super) base: usize,
    pub(super) modulate: bool,
    /// The primitive's shared level selection, for an affine span.
    pub(super) affine: Option<&'a AffineSpan<'a>>,
    /// `b * y` of the s and t planes on the span's row.
    pub(super) by: [f64; 2],
}

/// A span whose 1/w and q planes are constant (as under an orthographic projection): the
/// derivatives of s and t, hence λ and the levels, are the same at every pixel where s and t
/// (before the division by q) are finite.
#[derive(Clone, Copy, Debug)]
pub struct AffineSpan<'a> {
    /// 1 and the q plane's value (s/q is the s plane divided by 1, then by q; non-zero and
    /// finite), the form [`texture_simd::coords8`] takes.
    pub(super) w: f64,
    pub(super) q: f64,
    pub(super) levels: [FastLevel<'a>; 2],
    pub(super) linear: bool,
    /// The second level's weight, when two levels are mixed.
    pub(super) weight: Option<f32>,
    /// The levels for the eight-pixel filter, when the processor, format and wrap modes
    /// allow it.
    pub(super) simd: Option<[Level8<'a>; 2]>,
}

/// The general path's fix-up of a coordinate that is not finite (q = 0 and the like).
#[inline(always)]
pub(super) fn finite_or_zero(x: f32) -> f32 {
    if x.is_finite() {
        x
    } else {
        0.0
    }
}

impl<'a> FastUnit<'a> {
    pub(super) fn new(
        u: &'a TextureUnitDraw,
        it: &Interpolants<'a>,
        xc0: f64,
        yc: f64,
    ) -> FastUnit<'a> {
        let base = attr::TEX + 4 * u.unit;
        let p = &it.attrs[base..base + 2];
        FastUnit {
            unit: u,
            base,
            modulate: u.env.mode == TexEnvMode::Modulate,
            affine: Self::affine(u, it, base, xc0, yc),
            by: [p[0].b * yc, p[1].b * yc],
        }
    }

    /// The span's shared level selection, when its 1/w and q planes are constant and its
    /// first pixel's s and t are finite (then every pixel with finite s and t has the first
    /// pixel's derivatives, up to the sign of zeros, which λ squares away). Prepared once per
    /// primitive (`Interpolants::fast`).
    pub(super) fn affine(
        u: &'a TextureUnitDraw,
        it: &Interpolants<'a>,
        base: usize,
        xc0: f64,
        yc: f64,
    ) -> Option<&'a AffineSpan<'a>> {
        let p = &it.attrs[base..base + 4];
        // (Tested before the shared selection is read: that copies a few hundred bytes, and
        // only affine primitives have one.)
        if it.inv_w.a != 0.0 || it.inv_w.b != 0.0 || p[3].a != 0.0 || p[3].b != 0.0 {
            return None;
        }
        let shared: &'a PrimitiveShared<'a> = it.shared;
        if let Some(a) = shared.fast.get() {
            return Some(a);
        }
        // The coordinates are the s and t planes divided by the q plane ([`coords_at`]).
        let w = 1.0;
        let q = p[3].at(xc0, yc);
        if !q.is_finite() || q == 0.0 {
            return None;
        }
        if !p[0].at(xc0, yc).is_finite() || !p[1].at(xc0, yc).is_finite() {
            return None;
        }
        let tex = &u.texture;
        let (_, dx, dy) = unit_coords(it, base, xc0, yc);
        let lambda = tex.isotropic_lambda(dx, dy, u.env.lod_bias);
        let (levels, linear, weight) = match tex.level_plan(lambda) {
            LevelPlan::One { level, linear } => ([level, level], linear, None),
            LevelPlan::Two {
                levels,
                linear,
                weight,
            } => (levels, linear, Some(weight)),
        };
        let levels = [tex.fast_level(levels[0])?, tex.fast_level(levels[1])?];
        let simd = if crate::common::cpu::available() {
            let wrap = tex.wrap_st();
            match (
                Level8::new(&levels[0], wrap, u.base),
                Level8::new(&levels[1], wrap, u.base),
            ) {
                (Some(a), Some(b)) => Some([a, b]),
                _ => None,
            }
        } else {
            None
        };
        let a = AffineSpan {
            w,
            q,
            levels,
            linear,
            weight,
            simd,
        };
        Some(shared.fast.get_or_init(|| a))
    }

    /// The texel at pixel centre (x, y), as the general path samples it.
    #[inline(always)]
    pub(super) fn texel<const C: usize>(&self, it: &Interpolants, x: f64, y: f64) -> [f32; 4] {
        let tex = &self.unit.texture;
        if let Some(a) = self.affine {
            let (s, t) = (&it.attrs[self.base], &it.attrs[self.base + 1]);
            let vs = (s.a * x + self.by[0] + s.c) / a.w;
            let vt = (t.a * x + self.by[1] + t.c) / a.w;
            if vs.is_finite() && vt.is_finite() {
                let c = [
                    finite_or_zero((vs / a.q) as f32),
                    finite_or_zero((vt / a.q) as f32),
                ];
                return match a.weight {
                    None => tex.filter_fast::<C>(&a.levels[0], a.linear, c),
                    Some(w) => {
                        tex.filter_fast_mix::<C>([&a.levels[0], &a.levels[1]], a.linear, c, w)
                    }
                };
            }
        }
        let (c, dx, dy) = unit_coords(it, self.base, x, y);
        let lambda = tex.isotropic_lambda(dx, dy, self.unit.env.lod_bias);
        let c2 = [c[0], c[1]];
        match tex.level_plan(lambda) {
            LevelPlan::One { level, linear } => match tex.fast_level(level) {
                Some(l) => tex.filter_fast::<C>(&l, linear, c2),
                None => tex.sample_grad(c, dx, dy, self.unit.env.lod_bias),
            },
            LevelPlan::Two {
                levels,
                linear,
                weight,
            } => match (tex.fast_level(levels[0]), tex.fast_level(levels[1])) {
                (Some(l1), Some(l2)) => tex.filter_fast_mix::<C>([&l1, &l2], linear, c2, weight),
                _ => tex.sample_grad(c, dx, dy, self.unit.env.lod_bias),
            },
        }
    }

    /// The texels of the `count` (at most 8) pixels from centre `x` on row `y`, into
    /// `out[..count]`: eight at once when the span allows it, else one by one.
    #[inline(always)]
    pub(super) fn texels8<const C: usize>(
        &self,
        it: &Interpolants,
        x: f64,
        y: f64,
        count: usize,
        out: &mut [[f32; 4]; 8],
    ) {
        if let Some(a) = self.affine {
            if let Some(levels) = &a.simd {
                let (ps, pt) = (&it.attrs[self.base], &it.attrs[self.base + 1]);
                let planes = [[ps.a, self.by[0], ps.c], [pt.a, self.by[1], pt.c]];
                if let Some([s, t]) = texture_simd::coords8(planes, a.w, a.q, x, count) {
                    let ct = match a.weight {
                        None => texture_simd::filter8(&levels[0], a.linear, &s, &t),
                        Some(w) => texture_simd::filter8_mix(
                            [&levels[0], &levels[1]],
                            a.linear,
                            &s,
                            &t,
                            &[w; 8],
                        ),
                    };
                    if let Some(ct) = ct {
                        for (j, o) in out.iter_mut().enumerate().take(count) {
                            *o = [ct[0][j], ct[1][j], ct[2][j], ct[3][j]];
                        }
                        return;
                    }
                }
            }
        }
        for (j, o) in out.iter_mut().enumerate().take(count) {
            *o = self.texel::<C>(it, x + j as f64, y);
        }
    }

    /// The span's sampling for [`simd::textured8`], when it is affine and the eight-pixel
    /// filter applies.
    pub(super) fn sampling8(&self, it: &Interpolants) -> Option<Sampling8<'a>> {
        let a = self.affine?;
        let levels = a.simd.as_ref()?;
        let (ps, pt) = (&it.attrs[self.base], &it.attrs[self.base + 1]);
        Some(Sampling8 {
            planes: [[ps.a, self.by[0], ps.c], [pt.a, self.by[1], pt.c]],
            w: a.w,
            q: a.q,
            levels,
            linear: a.linear,
            weight: a.weight,
        })
    }

    /// The texels of the `count` (at most 8) pixels from centre `x` on row `y` of a texture
    /// of `C` components (3 or 4), one by one, as channel arrays (lanes from `count` on are 0).
    pub(super) fn texels_scalar<const C: usize>(
        &self,
        it: &Interpolants,
        x: f64,
        y: f64,
        count: usize,
    ) -> Texels8 {
        let mut out = [[0f32; 8]; 4];
        for j in 0..count {
            let t = self.texel::<C>(it, x + j as f64, y);
            for c in 0..4 {
                out[c][j] = t[c];
            }
        }
        out
    }

    /// The environment (`REPLACE` or `MODULATE`) on primary colour `primary` and texel `ct`,
    /// as [`texenv::apply`] computes it for RGB (`C` = 3) and RGBA (`C` = 4) textures.
    #[inline(always)]
    pub(super) fn env<const C: usize>(&self, primary: [f32; 4], ct: [f32; 4]) -> [f32; 4] {
        let cf = primary.map(|c| c.max(0.0).min(1.0));
        let a = if C == 4 {
            if self.modulate {
                cf[3] * ct[3]
            } else {
                ct[3]
            }
        } else {
            cf[3]
        };
        if self.modulate {
            [cf[0] * ct[0], cf[1] * ct[1], cf[2] * ct[2], a]
        } else {
            [ct[0], ct[1], ct[2], a]
        }
    }

    /// [`texture_fragment`] for this unit: the texel combined with the primary colour by a
    /// `REPLACE` or `MODULATE` environment (RGB texels keep the fragment's alpha).
    #[inline(always)]
    pub(super) fn fragment<const C: usize>(
        &self,
        it: &Interpolants,
        x: f64,
        y: f64,
        primary: [f32; 4],
    ) -> [f32; 4] {
        self.env::<C>(primary, self.texel::<C>(it, x, y))
    }
}

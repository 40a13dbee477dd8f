//! What the eight-lane paths share: the depth, 1/w and colours stepped along a span
//! (`SpanRun`), a group's inputs (`GroupInputs`), and the eight-fragment tail (`tail8`).

use super::*;

/// The window depth, 1/w and colours along a span, stepped pixel by pixel from its first
/// pixel: every span path steps them this way, so all see the same values.
pub(super) struct SpanRun {
    pub(super) z: f64,
    pub(super) dz: f64,
    pub(super) inv_w: f32,
    pub(super) dinv_w: f32,
    /// Primary colour, then the secondary colour (attribute/w under perspective).
    pub(super) color: [f32; 8],
    pub(super) dcolor: [f32; 8],
    /// How many of `color` are interpolated: 4 (primary) or 8 (with the secondary colour).
    pub(super) count: usize,
    pub(super) perspective: bool,
    /// The primary colour is divided by 1/w (not for `Interpolants::constant_primary`).
    pub(super) primary_perspective: bool,
    /// The fog coordinate (divided by w under perspective), when the draw is fogged.
    pub(super) fog: Option<(f32, f32)>,
}

impl SpanRun {
    #[inline(always)]
    pub(super) fn new(it: &Interpolants, xc0: f64, yc: f64, count: usize) -> SpanRun {
        let mut run = SpanRun {
            z: it.z.at(xc0, yc),
            dz: it.z.a,
            inv_w: it.inv_w.at(xc0, yc) as f32,
            dinv_w: it.inv_w.a as f32,
            color: [0.0; 8],
            dcolor: [0.0; 8],
            count,
            perspective: it.perspective,
            primary_perspective: it.perspective && !it.constant_primary,
            fog: None,
        };
        // A constant primary colour's planes are 0 x + 0 y + c, which is c + 0 at any pixel
        // centre (x and y finite and positive): no evaluation needed.
        let evaluated = if it.constant_primary {
            for c in 0..count.min(4) {
                run.color[c] = (it.attrs[attr::color(c)].c + 0.0) as f32;
            }
            count.min(4)..count
        } else {
            0..count
        };
        for c in evaluated {
            run.color[c] = it.attrs[attr::color(c)].at(xc0, yc) as f32;
            run.dcolor[c] = it.attrs[attr::color(c)].a as f32;
        }
        run
    }

    /// Steps the fog coordinate too (for a fogged draw).
    #[inline(always)]
    pub(super) fn with_fog(
        mut self,
        ds: &FragmentDraw,
        it: &Interpolants,
        xc0: f64,
        yc: f64,
    ) -> SpanRun {
        if ds.key.fog.is_some() && ds.fog.is_some() {
            self.fog = Some(Self::fog_at(it, xc0, yc));
        }
        self
    }

    /// The fog coordinate's plane value at (`xc0`, `yc`) and its step along the row.
    #[inline(always)]
    pub(super) fn fog_at(it: &Interpolants, xc0: f64, yc: f64) -> (f32, f32) {
        let p = &it.attrs[attr::FOG];
        (p.at(xc0, yc) as f32, p.a as f32)
    }

    /// The fog coordinate at the current pixel (0 unless fogged); `w` as from [`Self::w`].
    #[inline(always)]
    pub(super) fn fog_coord(&self, w: f32) -> f32 {
        match self.fog {
            Some((c, _)) if self.perspective => c * w,
            Some((c, _)) => c,
            None => 0.0,
        }
    }

    /// Whether z, 1/w and the primary colour do not change along the span (a flat, facing
    /// primitive).
    pub(super) fn is_steady(&self) -> bool {
        self.dz == 0.0
            && self.dinv_w == 0.0
            && self.dcolor[..self.count].iter().all(|&d| d == 0.0)
            && self.fog.is_none_or(|(_, dc)| dc == 0.0)
    }

    /// w at the current pixel (1 without perspective).
    #[inline(always)]
    pub(super) fn w(&self) -> f32 {
        if self.perspective {
            1.0 / self.inv_w
        } else {
            1.0
        }
    }

    #[inline(always)]
    pub(super) fn primary(&self, w: f32) -> [f32; 4] {
        if !self.primary_perspective {
            return [self.color[0], self.color[1], self.color[2], self.color[3]];
        }
        [
            self.color[0] * w,
            self.color[1] * w,
            self.color[2] * w,
            self.color[3] * w,
        ]
    }

    #[inline(always)]
    pub(super) fn secondary(&self, w: f32) -> [f32; 3] {
        [self.color[4] * w, self.color[5] * w, self.color[6] * w]
    }

    /// Moves to the next pixel.
    #[inline(always)]
    pub(super) fn step(&mut self) {
        self.z += self.dz;
        self.inv_w += self.dinv_w;
        for c in 0..self.count {
            self.color[c] += self.dcolor[c];
        }
        if let Some((c, dc)) = &mut self.fog {
            *c += *dc;
        }
    }

    /// For the eight-lane paths: the current pixel's primary colour, stored depth (0 without
    /// `depth_max`), fog coordinate (0 unless fogged) and secondary colour (`None` unless the run
    /// has it: a count of 8), then a step of z, 1/w, the primary colour (a fixed four, which
    /// keeps the loop unrolled), the secondary colour when there is one, and with `FOG` the
    /// fog coordinate (without it the coordinate is neither read nor stepped: the lanes' fog
    /// is then unused). The values and steps are those of `step`, `primary`, `secondary`
    /// and `fog_coord`, which must not follow on the same run.
    #[inline(always)]
    pub(super) fn next<const FOG: bool>(&mut self, depth_max: Option<u32>) -> Lane {
        let w = self.w();
        let color = self.primary(w);
        let fog = if FOG { self.fog_coord(w) } else { 0.0 };
        let depth = depth_max.map_or(0, |max| depth_to_fixed(self.z, max));
        self.z += self.dz;
        self.inv_w += self.dinv_w;
        for c in 0..4 {
            self.color[c] += self.dcolor[c];
        }
        if FOG {
            if let Some((c, dc)) = &mut self.fog {
                *c += *dc;
            }
        }
        // The secondary colour, when the run has it (the colour sum).
        let mut secondary = None;
        if self.count == 8 {
            secondary = Some(self.secondary(w));
            for c in 4..8 {
                self.color[c] += self.dcolor[c];
            }
        }
        (color, depth, fog, secondary)
    }
}

/// One fragment's inputs to the eight-lane paths: primary colour, stored depth, fog
/// coordinate, secondary colour ([`SpanRun::next`]).
pub(super) type Lane = ([f32; 4], u32, f32, Option<[f32; 3]>);

/// The colours the eight-lane paths step ([`SpanRun::new`]'s count): the primary, and the
/// secondary with the colour sum.
#[inline(always)]
pub(super) fn lane_colors(ds: &FragmentDraw) -> usize {
    if ds.key.color_sum {
        8
    } else {
        4
    }
}

/// The fog the eight-lane paths apply: the draw's parameters when its key is fogged.
#[inline(always)]
pub(super) fn lane_fog(ds: &FragmentDraw) -> Option<&FogDraw> {
    ds.key.fog.and(ds.fog.as_ref())
}

/// What the eight-fragment tail needs of a group besides the texels: the primary colours and
/// depths of lanes `lo..hi`, which of them pass the depth test, and the stored colours.
pub(super) struct GroupInputs {
    pub(super) primary: Texels8,
    pub(super) depth: [u32; 8],
    pub(super) pass: u8,
    pub(super) dst: [u32; 8],
    /// Fog coordinates, then (after [`GroupInputs::fog_factors`]) the fog factors of the
    /// passing lanes.
    /// The lanes' secondary colours and fog coordinates, then (after
    /// [`GroupInputs::fog_factors`]) the fog factors of the passing lanes.
    pub(super) after: After8,
}

impl GroupInputs {
    pub(super) const EMPTY: GroupInputs = GroupInputs {
        primary: [[0f32; 8]; 4],
        depth: [0u32; 8],
        pass: 0,
        dst: [0u32; 8],
        after: After8 {
            secondary: [[0f32; 8]; 3],
            fog: [0f32; 8],
        },
    };

    /// Turns the passing lanes' fog coordinates into fog factors (`FogDraw::factor`, as the
    /// general path computes them) for a fogged draw (`fog`, from [`lane_fog`]).
    #[inline(always)]
    pub(super) fn fog_factors(&mut self, fog: Option<&FogDraw>) {
        if let Some(f) = fog {
            if let Some(k) =
                simd::fog_factors8(f.mode, f.density, f.end, f.linear_scale(), &self.after.fog)
            {
                self.after.fog = k;
                return;
            }
            let mut m = self.pass;
            while m != 0 {
                let j = m.trailing_zeros() as usize;
                self.after.fog[j] = f.factor(self.after.fog[j]);
                m &= m - 1;
            }
        }
    }

    /// Lane `j` (in `lanes`) is pixel `base + j` of `tile`; `value(j)` gives its colour and
    /// depth, called in lane order.
    #[inline(always)]
    pub(super) fn gather(
        ds: &FragmentDraw,
        tile: &Tile,
        base: usize,
        lanes: std::ops::Range<usize>,
        mut value: impl FnMut(usize) -> Lane,
    ) -> GroupInputs {
        let mut g = GroupInputs::EMPTY;
        for j in lanes {
            g.add(ds, tile, j, base + j, value(j));
        }
        g
    }

    /// Lane `j` is pixel `index` of `tile`, with colour and depth `value`.
    #[inline(always)]
    pub(super) fn add(
        &mut self,
        ds: &FragmentDraw,
        tile: &Tile,
        j: usize,
        index: usize,
        value: Lane,
    ) {
        let (color, d, fog, secondary) = value;
        if let Some(secondary) = secondary {
            for c in 0..3 {
                self.after.secondary[c][j] = secondary[c];
            }
        }
        for c in 0..4 {
            self.primary[c][j] = color[c];
        }
        self.depth[j] = d;
        self.after.fog[j] = fog;
        self.pass |= u8::from(depth_passes(ds, d, tile.depth[index])) << j;
        self.dst[j] = u32::from_le_bytes(tile.color[index]);
    }
}

/// Whether a fragment of stored depth `d` passes the eight-lane paths' depth test against
/// `stored` (no test, or `ALWAYS`: it passes).
#[inline(always)]
pub(super) fn depth_passes(ds: &FragmentDraw, d: u32, stored: u32) -> bool {
    match ds.key.depth_func {
        None | Some(CompareFunc::Always) => true,
        Some(func) => func.test(d, stored),
    }
}

/// Writes the tail's colour words of lanes `lanes` (pixel `base + j`), and with depth writes
/// the depth of each lane set in `passed`.
#[inline(always)]
pub(super) fn store_group(
    ds: &FragmentDraw,
    tile: &mut Tile,
    base: usize,
    lanes: std::ops::Range<usize>,
    words: &[u32; 8],
    passed: u8,
    depth: &[u32; 8],
) {
    for j in lanes {
        store_lane(ds, tile, j, base + j, words, passed, depth);
    }
}

/// Writes lane `j`'s colour word to pixel `index`, and its depth when it passed and depth
/// writes are on.
#[inline(always)]
pub(super) fn store_lane(
    ds: &FragmentDraw,
    tile: &mut Tile,
    j: usize,
    index: usize,
    words: &[u32; 8],
    passed: u8,
    depth: &[u32; 8],
) {
    tile.color[index] = words[j].to_le_bytes();
    if ds.key.depth_write && passed & (1 << j) != 0 {
        tile.depth[index] = depth[j];
    }
}

/// The eight-fragment tail for the draw's key (its alpha test, blending and colour mask) with
/// the texture environment's part as given.
pub(super) fn tail8(
    ds: &FragmentDraw,
    modulate: bool,
    rgb_from_primary: bool,
    alpha_from_primary: bool,
) -> Tail8 {
    let key = &ds.key;
    Tail8 {
        modulate,
        rgb_from_primary,
        alpha_from_primary,
        alpha_test: key.alpha_func.map(|func| (func, ds.uniforms.alpha_ref)),
        blend: tail_blend(ds),
        color_mask: u32::from_le_bytes(key.color_mask.map(|m| if m { 0xFF } else { 0 })),
        color_sum: key.color_sum,
        fog: lane_fog(ds).map(|f| f.color),
    }
}

/// The depth range the eight-lane paths convert depths to: none without a depth test or
/// depth writes (the values would be unused).
pub(super) fn group_depth_max(ds: &FragmentDraw) -> Option<u32> {
    (ds.key.depth_func.is_some() || ds.key.depth_write).then_some(ds.depth_max)
}

/// Whether the eight-fragment tail covers everything after the colour for `key` (the colour
/// sum and fog included: the lanes' secondary colours and fog factors are computed as the
/// general path computes them, then added and blended in the tail): no stencil test, logic op
/// or occlusion counting, and AVX2 present.
pub fn tail8_applies(key: &FragmentKey) -> bool {
    key.stencil.is_none()
        && key.logic_op.is_none()
        && !key.count_samples
        && crate::common::cpu::available()
}

/// The eight-fragment tail's blending for the draw's key.
pub(super) fn tail_blend(ds: &FragmentDraw) -> simd::TailBlend {
    match ds.key.blend {
        None => simd::TailBlend::None,
        Some(b) if b.is_add_one_one() => simd::TailBlend::AddOneOne,
        Some(b) if b.is_alpha_over() => simd::TailBlend::AlphaOver,
        Some(b) => simd::TailBlend::General(b, ds.uniforms.blend_color),
    }
}

//! What the eight-lane paths share: the depth, 1/w and colours stepped along a span
//! (`SpanRun`), a group's inputs (`GroupInputs`), and the eight-fragment tail (`tail8`).

use super::*;

/// Columns between the restarts of a span's stepping: every pixel whose x is a multiple of
/// this (from window x = 0) has its values evaluated from the planes, not stepped. Each tile's
/// side is a multiple of it, so a span cut at a tile boundary restarts where the uncut span
/// would: the pictures do not depend on the tile size (`conformance/tests/determinism.rs`).
pub const RESTART: i32 = 16;

/// The window depth, 1/w and colours along a span, evaluated from the planes at its first
/// pixel and at every pixel whose x is a multiple of [`RESTART`], and stepped pixel by pixel
/// in between: every span path does it this way, so all see the same values.
#[derive(Clone)]
pub(super) struct SpanRun<'i> {
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
    /// The planes, for the restarts: z, 1/w, and the attributes'.
    z_plane: &'i Plane,
    inv_w_plane: &'i Plane,
    attrs: &'i [Plane],
    constant_primary: bool,
    /// Steps left before the current pixel is a restart column.
    pub(super) left: u32,
    /// The centre of the next restart column, and of the row.
    restart_x: f64,
    yc: f64,
}

impl<'i> SpanRun<'i> {
    /// The run from pixel `x0` of the row centred at `yc`.
    #[inline(always)]
    pub(super) fn new(it: &'i Interpolants<'_>, x0: i32, yc: f64, count: usize) -> SpanRun<'i> {
        let into = x0.rem_euclid(RESTART);
        let mut run = SpanRun {
            z: 0.0,
            dz: it.z.a,
            inv_w: 0.0,
            dinv_w: it.inv_w.a as f32,
            color: [0.0; 8],
            dcolor: [0.0; 8],
            count,
            perspective: it.perspective,
            primary_perspective: it.perspective && !it.constant_primary,
            fog: None,
            z_plane: &it.z,
            inv_w_plane: &it.inv_w,
            attrs: it.attrs,
            constant_primary: it.constant_primary,
            left: (RESTART - into) as u32,
            restart_x: (x0 - into + RESTART) as f64 + 0.5,
            yc,
        };
        // A constant primary colour's planes are 0 x + 0 y + c, which is c + 0 at any pixel
        // centre (x and y finite and positive): no evaluation needed, and its steps are 0.
        // (Constant indices, as in `evaluate`.)
        for c in 0..8 {
            if c < count {
                let p = &it.attrs[attr::color(c)];
                if c < 4 && it.constant_primary {
                    run.color[c] = (p.c + 0.0) as f32;
                } else {
                    run.dcolor[c] = p.a as f32;
                }
            }
        }
        run.evaluate(x0 as f64 + 0.5);
        run
    }

    /// The values at the pixel centred at (`xc`, the row's centre) from the planes.
    #[inline(always)]
    fn evaluate(&mut self, xc: f64) {
        let yc = self.yc;
        self.z = self.z_plane.at(xc, yc);
        self.inv_w = self.inv_w_plane.at(xc, yc) as f32;
        // Over all eight with a test, not over a range with a variable start: with constant
        // indices the colours stay in registers (a variable index keeps them in memory, which
        // doubled the cost of short spans).
        for c in 0..8 {
            if c < self.count && (c >= 4 || !self.constant_primary) {
                self.color[c] = self.attrs[attr::color(c)].at(xc, yc) as f32;
            }
        }
        if self.fog.is_some() {
            self.fog = Some(Self::fog_at(self.attrs, xc, yc));
        }
    }

    /// Moves to the next pixel by a restart (returns true: the values are set) or not (the
    /// caller steps them).
    #[inline(always)]
    fn restarts(&mut self) -> bool {
        self.left -= 1;
        if self.left != 0 {
            return false;
        }
        self.restart();
        true
    }

    /// The restart column's values, from the planes. (Inlined: an out-of-line call taking
    /// the run by reference kept the whole run in memory, twice the instructions per span of
    /// small triangles; docs/performance.md.)
    #[inline(always)]
    pub(super) fn restart(&mut self) {
        let x = self.restart_x;
        self.evaluate(x);
        self.restart_x = x + RESTART as f64;
        self.left = RESTART as u32;
    }

    /// Steps the fog coordinate too (for a fogged draw).
    #[inline(always)]
    pub(super) fn with_fog(mut self, ds: &FragmentDraw) -> SpanRun<'i> {
        if ds.key.fog.is_some() && ds.fog.is_some() {
            self.fog_on();
        }
        self
    }

    /// Steps the fog coordinate too, from the current pixel (at the start of the run).
    #[inline(always)]
    pub(super) fn fog_on(&mut self) {
        // The next restart column is `left` pixels on.
        let xc = self.restart_x - self.left as f64;
        self.fog = Some(Self::fog_at(self.attrs, xc, self.yc));
    }

    /// The fog coordinate's plane value at (`xc0`, `yc`) and its step along the row.
    #[inline(always)]
    fn fog_at(attrs: &[Plane], xc0: f64, yc: f64) -> (f32, f32) {
        let p = &attrs[attr::FOG];
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
    /// primitive): their planes are constant along rows.
    pub(super) fn is_steady(&self) -> bool {
        let flat = |p: &Plane| p.a == 0.0;
        let color = |c: usize| flat(&self.attrs[attr::color(c)]);
        flat(self.z_plane)
            && flat(self.inv_w_plane)
            && (self.constant_primary || (0..self.count.min(4)).all(color))
            && (4..self.count).all(color)
            && (self.fog.is_none() || flat(&self.attrs[attr::FOG]))
    }

    /// Whether z, 1/w, the colours and the fog coordinate are the same over the whole
    /// primitive (their planes are 0 x + 0 y + c, as on a flat sprite): then every pixel's
    /// evaluated values are the same bits (pixel centres are positive, so the products by x
    /// and y are zeros of fixed signs), and so are the stepped ones.
    pub(super) fn is_constant(&self) -> bool {
        let flat = |p: &Plane| p.a == 0.0 && p.b == 0.0;
        let color = |c: usize| flat(&self.attrs[attr::color(c)]);
        flat(self.z_plane)
            && flat(self.inv_w_plane)
            && (self.constant_primary || (0..self.count.min(4)).all(color))
            && (4..self.count).all(color)
            && (self.fog.is_none() || flat(&self.attrs[attr::FOG]))
    }

    /// For a run with [`Self::is_constant`] whose evaluated and stepped inputs are the same
    /// bits: the group whose eight lanes all have them, fogged as the steady shortcut fogs
    /// them ([`GroupInputs::uniform`]), which is then every group of every span of the
    /// primitive (`PrimitiveShared::steady`). `None` otherwise.
    pub(super) fn constant_group(&self, ds: &FragmentDraw) -> Option<GroupInputs> {
        if !self.is_constant() {
            return None;
        }
        let v = self.steady_values::<true>(Some(ds.depth_max));
        same_bits(&v[0], &v[1]).then(|| GroupInputs::uniform(v[1], lane_fog(ds)))
    }

    /// For a run with [`Self::is_steady`]: the inputs ([`Self::next`]) of the pixels where
    /// the run is evaluated (its first pixel and the restart columns), then of the others
    /// (the evaluation plus a step of zero, which changes at most the sign of a zero).
    pub(super) fn steady_values<const FOG: bool>(&self, depth_max: Option<u32>) -> [Lane; 2] {
        let mut run = self.clone();
        run.left = u32::MAX;
        [run.next::<FOG>(depth_max), run.next::<FOG>(depth_max)]
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

    /// Moves `n` pixels on, as `n` steps (or `n` calls of [`Self::next`]) do: to the last
    /// restart column passed, if any, then stepped from there.
    #[inline(always)]
    pub(super) fn skip(&mut self, n: usize) {
        let n = n as u32;
        let rest = if n < self.left {
            n
        } else {
            // Past the next restart column: to the last one at or before the target.
            let beyond = n - self.left;
            self.restart_x += (beyond / RESTART as u32 * RESTART as u32) as f64;
            self.restart();
            beyond % RESTART as u32
        };
        for _ in 0..rest {
            self.step_within();
        }
        self.left -= rest;
    }

    /// Runs `pixel(i, run)` for the pixels `i` in `0..n` from the current one, the run at
    /// pixel `i`: stepped in between, restarted at the restart columns. (Segments between
    /// restart columns, so that the stepping in between counts nothing: short spans, most of
    /// them inside one segment, then cost what they cost without restarts.)
    #[inline(always)]
    pub(super) fn each_pixel(&mut self, n: usize, mut pixel: impl FnMut(usize, &SpanRun<'i>)) {
        let mut i = 0;
        while i < n {
            let end = n.min(i + self.left as usize);
            loop {
                pixel(i, self);
                i += 1;
                if i == end {
                    break;
                }
                self.step_within();
            }
            if i < n {
                self.restart();
            }
        }
    }

    /// A step to the next pixel, which is not a restart column ([`Self::each_pixel`]).
    #[inline(always)]
    fn step_within(&mut self) {
        self.z += self.dz;
        self.inv_w += self.dinv_w;
        for c in 0..self.count {
            self.color[c] += self.dcolor[c];
        }
        if let Some((c, dc)) = &mut self.fog {
            *c += *dc;
        }
    }

    /// The current pixel's depth, then a move to the next pixel (for runs whose other
    /// values are not read: a constant colour, no fog).
    #[inline(always)]
    pub(super) fn next_z(&mut self) -> f64 {
        let z = self.z;
        if !self.restarts() {
            self.z += self.dz;
        }
        z
    }

    /// The depths of the next `m` pixels (at most 8) into `z[..m]`, moving past them: what
    /// `m` calls of [`Self::next_z`] give, eight at a time without a restart test per pixel
    /// when none of the eight moves restarts.
    #[inline(always)]
    pub(super) fn z_lanes(&mut self, z: &mut [f64; 8], m: usize) {
        if m == 8 && self.left > 8 {
            self.left -= 8;
            let mut v = self.z;
            for o in z.iter_mut() {
                *o = v;
                v += self.dz;
            }
            self.z = v;
        } else {
            for o in &mut z[..m] {
                *o = self.next_z();
            }
        }
    }

    /// The depth, 1/w and primary colour (as stepped) of the next `m` pixels (at most 8) into
    /// lanes `0..m` of `raw`, moving past them: [`Self::record`] and [`Self::advance`] `m`
    /// times (unfogged, the primary colour only: a run of count 4), unrolled when none of the
    /// eight moves restarts.
    #[inline(always)]
    pub(super) fn primary_lanes(&mut self, raw: &mut RawLanes, m: usize) {
        if m == 8 && self.left > 8 && self.count == 4 {
            self.left -= 8;
            let (mut z, mut inv_w, mut c) = (self.z, self.inv_w, self.color);
            for j in 0..8 {
                raw.z[j] = z;
                raw.inv_w[j] = inv_w;
                for k in 0..4 {
                    raw.color[k][j] = c[k];
                }
                z += self.dz;
                inv_w += self.dinv_w;
                for k in 0..4 {
                    c[k] += self.dcolor[k];
                }
            }
            (self.z, self.inv_w, self.color) = (z, inv_w, c);
        } else {
            for j in 0..m {
                self.record::<false>(raw, j, true);
                self.advance::<false>();
            }
        }
    }

    /// For the eight-lane paths: the current pixel's primary colour, stored depth (0 without
    /// `depth_max`), fog coordinate (0 unless fogged) and secondary colour (`None` unless the run
    /// has it: a count of 8), then a move to the next pixel: a step of z, 1/w, the primary
    /// colour (a fixed four, which keeps the loop unrolled), the secondary colour when there
    /// is one, and with `FOG` the fog coordinate (without it the coordinate is neither read
    /// nor stepped: the lanes' fog is then unused), or a restart. The values and steps are
    /// those of `step`, `primary`, `secondary` and `fog_coord`, which must not follow on the
    /// same run.
    #[inline(always)]
    pub(super) fn next<const FOG: bool>(&mut self, depth_max: Option<u32>) -> Lane {
        let w = self.w();
        let color = self.primary(w);
        let fog = if FOG { self.fog_coord(w) } else { 0.0 };
        let depth = depth_max.map_or(0, |max| depth_to_fixed(self.z, max));
        // The secondary colour, when the run has it (the colour sum).
        let secondary = (self.count == 8).then(|| self.secondary(w));
        self.advance::<FOG>();
        (color, depth, fog, secondary)
    }

    /// The move to the next pixel that [`Self::next`] makes: a step of z, 1/w, the primary
    /// colour, the secondary colour when the run has it, and with `FOG` the fog coordinate;
    /// or a restart.
    #[inline(always)]
    pub(super) fn advance<const FOG: bool>(&mut self) {
        if self.restarts() {
            return;
        }
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
        if self.count == 8 {
            for c in 4..8 {
                self.color[c] += self.dcolor[c];
            }
        }
    }

    /// Four [`Self::record`] and [`Self::advance`] pairs into lanes `4 * ROW..4 * ROW + 4`
    /// of `raw`, when none of the four moves restarts (else false and nothing done): the same
    /// sums in the same order, on copies kept in registers. Values the draw's lanes never
    /// read ([`Reads`]) are neither recorded nor stepped (they are wrong from then on, and
    /// must stay unread on this run).
    #[inline(always)]
    pub(super) fn record4<const FOG: bool, const ROW: usize>(
        &mut self,
        raw: &mut RawLanes,
        reads: Reads,
    ) -> bool {
        if self.left <= 4 {
            return false;
        }
        self.left -= 4;
        let primary = reads.primary;
        let lanes = 4 * ROW..4 * ROW + 4;
        let (mut z, mut inv_w) = (self.z, self.inv_w);
        if reads.z {
            for z_lane in &mut raw.z[lanes.clone()] {
                *z_lane = z;
                z += self.dz;
            }
            self.z = z;
        }
        if reads.inv_w {
            for w_lane in &mut raw.inv_w[lanes.clone()] {
                *w_lane = inv_w;
                inv_w += self.dinv_w;
            }
            self.inv_w = inv_w;
        }
        let channel = |c: usize, v: &mut f32, out: &mut [f32; 8]| {
            let mut x = *v;
            for o in &mut out[lanes.clone()] {
                *o = x;
                x += self.dcolor[c];
            }
            *v = x;
        };
        let mut color = self.color;
        if primary {
            for c in 0..4 {
                channel(c, &mut color[c], &mut raw.color[c]);
            }
        }
        if self.count == 8 {
            for c in 4..7 {
                channel(c, &mut color[c], &mut raw.color[c]);
            }
            for _ in 0..4 {
                color[7] += self.dcolor[7];
            }
        }
        self.color = color;
        if FOG {
            match &mut self.fog {
                Some((c, dc)) => {
                    let mut x = *c;
                    for o in &mut raw.fog[lanes] {
                        *o = x;
                        x += *dc;
                    }
                    *c = x;
                }
                None => raw.fog[lanes].fill(0.0),
            }
        }
        true
    }

    /// The current pixel's values before the per-pixel arithmetic of [`Self::next`] (z, 1/w,
    /// the colours as stepped, the fog coordinate), into lane `lane` of `raw`; the primary
    /// colour only when `primary` (a constant primary colour is not read per lane).
    #[inline(always)]
    pub(super) fn record<const FOG: bool>(&self, raw: &mut RawLanes, lane: usize, primary: bool) {
        raw.z[lane] = self.z;
        raw.inv_w[lane] = self.inv_w;
        if primary {
            for c in 0..4 {
                raw.color[c][lane] = self.color[c];
            }
        }
        if self.count == 8 {
            for c in 4..7 {
                raw.color[c][lane] = self.color[c];
            }
        }
        if FOG {
            raw.fog[lane] = match self.fog {
                Some((c, _)) => c,
                None => 0.0,
            };
        }
    }
}

/// Which of a run's stepped values a draw's lanes read (`LaneMath`): the depth (a depth
/// range), 1/w (a product by w) and the primary colour (not constant). The others need not be
/// recorded or stepped ([`SpanRun::record4`]).
#[derive(Clone, Copy, Debug)]
pub(super) struct Reads {
    pub(super) z: bool,
    pub(super) inv_w: bool,
    pub(super) primary: bool,
}

/// Whether two lanes' inputs are the same bits.
pub(super) fn same_bits(a: &Lane, b: &Lane) -> bool {
    let bits = |l: &Lane| {
        let mut v = [0u32; 10];
        for c in 0..4 {
            v[c] = l.0[c].to_bits();
        }
        v[4] = l.1;
        v[5] = l.2.to_bits();
        for (c, s) in l.3.unwrap_or([0.0; 3]).iter().enumerate() {
            v[6 + c] = s.to_bits();
        }
        v[9] = u32::from(l.3.is_some());
        v
    };
    bits(a) == bits(b)
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
#[derive(Debug)]
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

    /// Refills the group in place (a fresh group would be a memset and its return a
    /// memcpy per eight pixels): lane `j` (in `lanes`) is pixel `base + j` of `tile`;
    /// `value(j)` gives its colour and depth, called in lane order. The other lanes' colours
    /// and depths are 0 and they do not pass; their secondary colours and fog coordinates
    /// are stale (read only for live lanes).
    #[inline(always)]
    pub(super) fn refill(
        &mut self,
        ds: &FragmentDraw,
        tile: &Tile,
        base: usize,
        lanes: std::ops::Range<usize>,
        mut value: impl FnMut(usize) -> Lane,
    ) {
        self.primary = [[0f32; 8]; 4];
        self.depth = [0; 8];
        self.pass = 0;
        self.dst = [0; 8];
        for j in lanes {
            self.add(ds, tile, j, base + j, value(j));
        }
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
        let d = value.1;
        self.set_inputs(j, value);
        self.pass |= u8::from(depth_passes(ds, d, tile.depth[index])) << j;
        self.dst[j] = u32::from_le_bytes(tile.color[index]);
    }

    /// Lane `j`'s colours, depth and fog coordinate.
    #[inline(always)]
    pub(super) fn set_inputs(&mut self, j: usize, value: Lane) {
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
    }

    /// A group whose eight lanes all have the inputs `value`, fog factors made (for the
    /// groups of a steady run: see `shade_textured`); it neither passes nor has stored colours
    /// until [`GroupInputs::retest`].
    pub(super) fn uniform(value: Lane, fog: Option<&FogDraw>) -> GroupInputs {
        let mut g = GroupInputs::EMPTY;
        for j in 0..8 {
            g.set_inputs(j, value);
        }
        g.pass = 0xFF;
        g.fog_factors(fog);
        g.pass = 0;
        g
    }

    /// Keeps the lanes' inputs and reads lanes `lanes` (pixel `base + j`) afresh: their stored
    /// colours and the depth test against their stored depths.
    #[inline(always)]
    pub(super) fn retest(
        &mut self,
        ds: &FragmentDraw,
        tile: &Tile,
        base: usize,
        lanes: std::ops::Range<usize>,
    ) {
        self.pass = 0;
        for j in lanes {
            let index = base + j;
            self.pass |= u8::from(depth_passes(ds, self.depth[j], tile.depth[index])) << j;
            self.dst[j] = u32::from_le_bytes(tile.color[index]);
        }
    }
}

/// The stencil test and its actions (section 4.1.5, in `finish_fragment`'s order) for the
/// lanes of `live`, lane j being pixel `index(j)` of `tile` with depth test results
/// `depth_pass` (a subset of `live`): the lanes that pass both tests. Without a stencil test,
/// `depth_pass`. The eight-lane paths take stencil keys only without an alpha test
/// ([`tail8_applies`]), so every lane reaching the tests here is one the general path would
/// test; lanes are distinct pixels, so their order does not matter.
#[inline(always)]
pub(super) fn stencil_lanes(
    ds: &FragmentDraw,
    tile: &mut Tile,
    live: u8,
    depth_pass: u8,
    index: impl Fn(usize) -> usize,
) -> u8 {
    let Some(st) = ds.key.stencil else {
        return depth_pass;
    };
    let mut old = [0u8; 8];
    for (j, o) in old.iter_mut().enumerate() {
        if live & (1 << j) != 0 {
            *o = tile.stencil[index(j)];
        }
    }
    let (new, pass) = stencil8(&st, &ds.uniforms, &old, depth_pass);
    for (j, &v) in new.iter().enumerate() {
        if live & (1 << j) != 0 {
            tile.stencil[index(j)] = v;
        }
    }
    pass
}

/// [`stencil_lanes`] for the live lanes of a 4x2 block whose lanes 0..4 are pixels
/// `row0..row0 + 4` of `tile` and lanes 4..8 the four from `row0 + side`: the stored values read
/// and written as two four-byte words, the lanes outside `live` written back as they were
/// (lanes past the tile's right edge are the next row's first pixels, which nothing else
/// changes meanwhile). Lane by lane where the upper word would run past the buffer (a block
/// hanging over the right edge of the tile's top row).
#[inline(always)]
pub(super) fn stencil_block(
    ds: &FragmentDraw,
    tile: &mut Tile,
    row0: usize,
    live: u8,
    depth_pass: u8,
) -> u8 {
    let Some(st) = ds.key.stencil else {
        return depth_pass;
    };
    let upper = row0 + tile.side() as usize;
    let values = &mut tile.stencil;
    if upper + 4 > values.len() {
        let stride = tile.side() as usize;
        return stencil_lanes(ds, tile, live, depth_pass, |lane| {
            row0 + lane / 4 * stride + lane % 4
        });
    }
    // The two words joined in a register, not through an array (two four-byte stores read
    // back by one eight-byte load stall the store forwarding).
    let word = |v: &[u8]| u32::from_le_bytes([v[0], v[1], v[2], v[3]]);
    let old =
        u64::from(word(&values[row0..row0 + 4])) | u64::from(word(&values[upper..upper + 4])) << 32;
    #[cfg(target_arch = "x86_64")]
    // SAFETY: SSE2 is part of the x86-64 baseline.
    let (new, pass) = stencil8_word_sse2(&st, &ds.uniforms, old, depth_pass, live);
    #[cfg(not(target_arch = "x86_64"))]
    let (new, pass) = {
        let (new, pass) = stencil8_live(&st, &ds.uniforms, &old.to_le_bytes(), depth_pass, live);
        (u64::from_le_bytes(new), pass)
    };
    values[row0..row0 + 4].copy_from_slice(&(new as u32).to_le_bytes());
    values[upper..upper + 4].copy_from_slice(&((new >> 32) as u32).to_le_bytes());
    pass
}

/// The lanes whose stored stencil values `old` pass the stencil test (every lane tested):
/// SSE2 (every x86-64 has it) or lane by lane ([`stencil_test8_lanes`], the same integer
/// comparisons).
#[inline(always)]
pub(super) fn stencil_test8(st: &StencilKey, u: &Uniforms, old: &[u8; 8]) -> u8 {
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: SSE2 is part of the x86-64 baseline.
        unsafe { stencil_test8_sse2(st, u, old) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        stencil_test8_lanes(st, u, old)
    }
}

/// [`stencil_test8`] lane by lane, as `finish_fragment` tests one fragment.
#[cfg_attr(target_arch = "x86_64", allow(dead_code))]
#[inline(always)]
pub(super) fn stencil_test8_lanes(st: &StencilKey, u: &Uniforms, old: &[u8; 8]) -> u8 {
    let mask = u.stencil_value_mask;
    let reference = u.stencil_ref & mask;
    let mut bits = 0u8;
    for (j, &o) in old.iter().enumerate() {
        bits |= u8::from(st.func.test(reference, o & mask)) << j;
    }
    bits
}

/// Eight stencil values after the test and the action each lane takes (`apply_stencil_op`
/// lane by lane: the fail action where the test fails, else the depth-pass action for lanes
/// in `depth_pass` and the depth-fail action for the others), and the lanes that pass both
/// tests. SSE2 (every x86-64 has it) or lane by lane: the same integer operations.
#[inline(always)]
pub(super) fn stencil8(
    st: &StencilKey,
    u: &Uniforms,
    old: &[u8; 8],
    depth_pass: u8,
) -> ([u8; 8], u8) {
    stencil8_live(st, u, old, depth_pass, 0xFF)
}

/// [`stencil8`] for the lanes of `live` (a superset of `depth_pass`): the other lanes keep
/// their values in `old`.
#[inline(always)]
pub(super) fn stencil8_live(
    st: &StencilKey,
    u: &Uniforms,
    old: &[u8; 8],
    depth_pass: u8,
    live: u8,
) -> ([u8; 8], u8) {
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: SSE2 is part of the x86-64 baseline.
        unsafe { stencil8_sse2(st, u, old, depth_pass, live) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        stencil8_lanes(st, u, old, depth_pass, live)
    }
}

/// [`stencil8_live`] lane by lane, in `finish_fragment`'s order.
#[cfg_attr(target_arch = "x86_64", allow(dead_code))]
#[inline(always)]
pub(super) fn stencil8_lanes(
    st: &StencilKey,
    u: &Uniforms,
    old: &[u8; 8],
    depth_pass: u8,
    live: u8,
) -> ([u8; 8], u8) {
    let test = stencil_test8_lanes(st, u, old);
    let mut new = *old;
    for j in 0..8 {
        let bit = 1u8 << j;
        if live & bit == 0 {
            continue;
        }
        let op = if test & bit == 0 {
            st.fail
        } else if depth_pass & bit != 0 {
            st.depth_pass
        } else {
            st.depth_fail
        };
        new[j] = apply_stencil_op(op, old[j], u);
    }
    (new, test & depth_pass)
}

/// [`stencil8`] on the low eight bytes of SSE2 registers: unsigned byte comparisons through
/// `max_epu8`, saturating and wrapping byte adds for the actions.
#[cfg(target_arch = "x86_64")]
#[inline]
#[target_feature(enable = "sse2")]
fn stencil8_sse2(
    st: &StencilKey,
    u: &Uniforms,
    old: &[u8; 8],
    depth_pass: u8,
    live: u8,
) -> ([u8; 8], u8) {
    let (new, pass) = stencil8_word_sse2(st, u, u64::from_le_bytes(*old), depth_pass, live);
    (new.to_le_bytes(), pass)
}

/// [`stencil8_live`] on the eight values as the bytes of a word (lane j in byte j), inlined
/// into the caller's loop (SSE2 on x86-64, its baseline; else lane by lane).
#[inline(always)]
pub(super) fn stencil8_word(
    st: &StencilKey,
    u: &Uniforms,
    old: u64,
    depth_pass: u8,
    live: u8,
) -> (u64, u8) {
    #[cfg(target_arch = "x86_64")]
    {
        stencil8_word_sse2(st, u, old, depth_pass, live)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let (new, pass) = stencil8_live(st, u, &old.to_le_bytes(), depth_pass, live);
        (u64::from_le_bytes(new), pass)
    }
}

/// [`stencil8_sse2`] on the eight values as the bytes of a word (lane j in byte j). (Without
/// `#[target_feature]`: SSE2 is in the x86-64 baseline, so the function inlines.)
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn stencil8_word_sse2(
    st: &StencilKey,
    u: &Uniforms,
    old: u64,
    depth_pass: u8,
    live: u8,
) -> (u64, u8) {
    // SAFETY: SSE2 is part of the x86-64 baseline; registers only, no memory access.
    unsafe {
        use std::arch::x86_64::*;
        let splat = |b: u8| _mm_set1_epi8(b as i8);
        let ones = splat(0xFF);
        let o = _mm_cvtsi64_si128(old as i64);
        let test = stencil_test_sse2(st, u, o);
        let wm = splat(u.stencil_write_mask);
        let action = |op: StencilOp| {
            let one = splat(1);
            let v = match op {
                StencilOp::Keep => return o,
                StencilOp::Zero => _mm_setzero_si128(),
                StencilOp::Replace => splat(u.stencil_ref),
                StencilOp::Incr => _mm_adds_epu8(o, one),
                StencilOp::Decr => _mm_subs_epu8(o, one),
                StencilOp::Invert => _mm_xor_si128(o, ones),
                StencilOp::IncrWrap => _mm_add_epi8(o, one),
                StencilOp::DecrWrap => _mm_sub_epi8(o, one),
            };
            _mm_or_si128(_mm_andnot_si128(wm, o), _mm_and_si128(v, wm))
        };
        // The depth test's bits as byte masks.
        let bits = _mm_set_epi64x(0, 0x8040_2010_0804_0201u64 as i64);
        let dp = _mm_cmpeq_epi8(_mm_and_si128(splat(depth_pass), bits), bits);
        let select = |mask: __m128i, a: __m128i, b: __m128i| {
            _mm_or_si128(_mm_and_si128(mask, a), _mm_andnot_si128(mask, b))
        };
        let both = _mm_and_si128(test, dp);
        let new = if st.fail == StencilOp::Keep && st.depth_fail == StencilOp::Keep {
            // Only the lanes passing both tests change (`depth_pass` is within `live`): one
            // action, one selection (the z-pass volumes and REPLACE-on-pass marking).
            select(both, action(st.depth_pass), o)
        } else {
            let passed = select(dp, action(st.depth_pass), action(st.depth_fail));
            let new = select(test, passed, action(st.fail));
            // Lanes outside `live` keep their stored values.
            let lm = _mm_cmpeq_epi8(_mm_and_si128(splat(live), bits), bits);
            select(lm, new, o)
        };
        let pass = _mm_movemask_epi8(both) as u8;
        (_mm_cvtsi128_si64(new) as u64, pass)
    }
}

/// The stencil test of the low eight bytes of `o` (stored values) as byte masks (0xFF where
/// `reference OP value` holds, both masked): unsigned comparisons through `max_epu8`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn stencil_test_sse2(
    st: &StencilKey,
    u: &Uniforms,
    o: std::arch::x86_64::__m128i,
) -> std::arch::x86_64::__m128i {
    // SAFETY: SSE2 is part of the x86-64 baseline; registers only, no memory access.
    unsafe {
        use std::arch::x86_64::*;
        let splat = |b: u8| _mm_set1_epi8(b as i8);
        let ones = splat(0xFF);
        let m = _mm_and_si128(o, splat(u.stencil_value_mask));
        let r = splat(u.stencil_ref & u.stencil_value_mask);
        let max = _mm_max_epu8(r, m);
        // Per lane: reference OP masked value.
        let (r_ge, m_ge) = (_mm_cmpeq_epi8(max, r), _mm_cmpeq_epi8(max, m));
        let eq = _mm_cmpeq_epi8(r, m);
        match st.func {
            CompareFunc::Never => _mm_setzero_si128(),
            CompareFunc::Less => _mm_xor_si128(r_ge, ones),
            CompareFunc::Equal => eq,
            CompareFunc::LessEqual => m_ge,
            CompareFunc::Greater => _mm_xor_si128(m_ge, ones),
            CompareFunc::NotEqual => _mm_xor_si128(eq, ones),
            CompareFunc::GreaterEqual => r_ge,
            CompareFunc::Always => ones,
        }
    }
}

/// [`stencil_test8`] on SSE2.
#[cfg(target_arch = "x86_64")]
#[inline]
#[target_feature(enable = "sse2")]
fn stencil_test8_sse2(st: &StencilKey, u: &Uniforms, old: &[u8; 8]) -> u8 {
    use std::arch::x86_64::*;
    // SAFETY: `old` holds eight bytes; an unaligned 64-bit load.
    let o = unsafe { _mm_loadl_epi64(old.as_ptr() as *const __m128i) };
    (_mm_movemask_epi8(stencil_test_sse2(st, u, o)) & 0xFF) as u8
}

/// [`stencil_lanes`] for the lanes `0..n` (at most 8) of a row, lane `j` being pixel
/// `base + j` of `tile`: the stored values read and written as one slice.
#[inline(always)]
pub(super) fn stencil_row(
    ds: &FragmentDraw,
    tile: &mut Tile,
    base: usize,
    n: usize,
    depth_pass: u8,
) -> u8 {
    let Some(st) = ds.key.stencil else {
        return depth_pass;
    };
    let mut old = [0u8; 8];
    if let Some(whole) = tile
        .stencil
        .get_mut(base..base + 8)
        .and_then(|v| <&mut [u8; 8]>::try_from(v).ok())
    {
        // One eight-byte load and store, also for a shorter group while eight bytes lie in
        // the tile (the lanes past `n` written back as they were: nothing else changes them
        // meanwhile).
        let (new, pass) = stencil8_live(&st, &ds.uniforms, whole, depth_pass, lane_bits(0..n));
        *whole = new;
        return pass;
    }
    let values = &mut tile.stencil[base..base + n];
    old[..n].copy_from_slice(values);
    let (new, pass) = stencil8(&st, &ds.uniforms, &old, depth_pass);
    values.copy_from_slice(&new[..n]);
    pass
}

/// For a stencil key, whether every lane of `lanes` (pixel `base + j`) fails the stencil
/// test; if so, the fail action is applied to them (nothing else happens to a fragment that
/// fails it), and the caller skips the group.
#[inline(always)]
pub(super) fn stencil_rejects_all(
    ds: &FragmentDraw,
    tile: &mut Tile,
    base: usize,
    lanes: std::ops::Range<usize>,
) -> bool {
    let Some(st) = ds.key.stencil else {
        return false;
    };
    let mut old = [0u8; 8];
    let n = lanes.end - lanes.start;
    let values = &mut tile.stencil[base + lanes.start..base + lanes.end];
    old[..n].copy_from_slice(values);
    if stencil_test8(&st, &ds.uniforms, &old) & lane_bits(0..n) != 0 {
        return false;
    }
    if st.fail != StencilOp::Keep {
        for v in values {
            *v = apply_stencil_op(st.fail, *v, &ds.uniforms);
        }
    }
    true
}

/// Row `y` of a polygon stipple pattern (`PrimitiveShared::stipple`) with the bit of column
/// `x mod 32` at `1 << (x mod 32)` (section 3.5.2: a fragment at window (x, y) is kept when bit
/// (x mod 32, y mod 32) of the pattern is 1).
#[inline(always)]
pub(super) fn stipple_row(pattern: &[u32; 32], y: i32) -> u32 {
    pattern[y.rem_euclid(32) as usize].reverse_bits()
}

/// The lanes of the 4x2 block at column `gx` of a row pair (lanes 0..4 row `y`, 4..8 row
/// `y + 1`) that the stipple keeps, from the two rows' [`stipple_row`]s.
#[inline(always)]
pub(super) fn stipple_block(rows: [u32; 2], gx: i32) -> u8 {
    let s = gx.rem_euclid(32) as u32;
    ((rows[0].rotate_right(s) & 0xF) | ((rows[1].rotate_right(s) & 0xF) << 4)) as u8
}

/// Pixels `x0..x1` of row `y` of a polygon stippled by `pattern`, by the draw's span
/// function (for the spans that take no lane mask): the whole row is shaded as it would be
/// unstippled, then the pixels the stipple discards get their colour, depth and stencil back,
/// so the kept pixels have exactly the values of the unstippled row (a span's values depend on
/// where it starts: shading each run of kept pixels alone would round differently). Keys that
/// count samples for an occlusion query, whose count must leave the discarded fragments out,
/// take one call per run of kept pixels.
pub fn span_stippled<'a>(
    ds: &'a FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
    pattern: &[u32; 32],
) {
    const MAX: usize = 128;
    let row = stipple_row(pattern, y);
    let bit = |x: i32| row & (1 << x.rem_euclid(32)) != 0;
    let n = (x1 - x0).max(0) as usize;
    let kept = (x0..x1).filter(|&x| bit(x)).count();
    if kept == 0 {
        return;
    }
    if kept == n {
        return (ds.span)(ds, tile, y, x0, x1, it);
    }
    if ds.key.count_samples || n > MAX {
        let mut x = x0;
        while x < x1 {
            while x < x1 && !bit(x) {
                x += 1;
            }
            let start = x;
            while x < x1 && bit(x) {
                x += 1;
            }
            if start < x {
                (ds.span)(ds, tile, y, start, x, it);
            }
        }
        return;
    }
    let at = tile.index(x0, y);
    let mut color = [[0u8; 4]; MAX];
    let mut depth = [0u32; MAX];
    let mut stencil = [0u8; MAX];
    let range = at..at + n;
    color[..n].copy_from_slice(&tile.color[range.clone()]);
    let (has_depth, has_stencil) = (!tile.depth.is_empty(), !tile.stencil.is_empty());
    if has_depth {
        depth[..n].copy_from_slice(&tile.depth[range.clone()]);
    }
    if has_stencil {
        stencil[..n].copy_from_slice(&tile.stencil[range]);
    }
    (ds.span)(ds, tile, y, x0, x1, it);
    for (i, x) in (x0..x1).enumerate() {
        if !bit(x) {
            tile.color[at + i] = color[i];
            if has_depth {
                tile.depth[at + i] = depth[i];
            }
            if has_stencil {
                tile.stencil[at + i] = stencil[i];
            }
        }
    }
}

/// The lanes `lanes` as a mask.
#[inline(always)]
pub(super) fn lane_bits(lanes: std::ops::Range<usize>) -> u8 {
    // Bits start..end (end at most 8).
    ((1u16 << lanes.end) - (1u16 << lanes.start.min(lanes.end))) as u8
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
/// general path computes them, then added and blended in the tail; the stencil test ahead of
/// it by [`stencil_lanes`]): no stencil test together with an alpha test (which comes before
/// it and would decide which fragments update the stencil; a logic op in place of blending,
/// [`tail_blend`]), no occlusion counting, and AVX2 present.
pub fn tail8_applies(key: &FragmentKey) -> bool {
    (key.stencil.is_none() || key.alpha_func.is_none())
        && !key.count_samples
        && crate::common::cpu::available()
}

/// The eight-fragment tail's blending for the draw's key.
pub(super) fn tail_blend(ds: &FragmentDraw) -> simd::TailBlend {
    if let Some(op) = ds.key.logic_op {
        // A logic op replaces blending (`finish_fragment`'s order).
        return simd::TailBlend::Logic(op);
    }
    match ds.key.blend {
        None => simd::TailBlend::None,
        Some(b) if b.is_add_one_one() => simd::TailBlend::AddOneOne,
        Some(b) if b.is_alpha_over() => simd::TailBlend::AlphaOver,
        Some(b) if b.byte_factors() => simd::TailBlend::Bytes(b),
        Some(b) => simd::TailBlend::General(b, ds.uniforms.blend_color),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The values at column `x` of a run started at `x0` (fogged, both colours), stepped one
    /// pixel at a time.
    fn values_at(it: &Interpolants, x0: i32, x: i32, yc: f64) -> (f64, f32, [f32; 8], f32) {
        let mut run = SpanRun::new(it, x0, yc, 8);
        run.fog_on();
        let mut at_x = None;
        run.each_pixel((x - x0 + 1) as usize, |i, r| {
            if i as i32 == x - x0 {
                at_x = Some((r.z, r.inv_w, r.color, r.fog.map_or(0.0, |f| f.0)));
            }
        });
        at_x.unwrap()
    }

    /// A span cut anywhere at a multiple of `RESTART` (where a tile of any side ends) gives the
    /// values of the uncut span at every pixel: a column's values depend only on the span's
    /// start and the last restart column before it, never on where the span was cut.
    #[test]
    fn a_span_cut_at_a_restart_column_has_the_uncut_values() {
        // Steps that are not exact in binary, so that running sums round.
        let plane = |k: f64| Plane {
            a: 0.013_717_421 * k,
            b: -0.007_3 * k,
            c: 0.1 + 0.37 * k,
        };
        let attrs: Vec<Plane> = (0..attr::TEX)
            .map(|i| plane(1.0 + i as f64 / 3.0))
            .collect();
        let levels = UnitLevels::default();
        let shared = PrimitiveShared::new(&levels);
        let it = Interpolants {
            z: plane(0.011),
            inv_w: plane(0.9),
            attrs: &attrs,
            perspective: true,
            constant_primary: false,
            coverage: 1.0,
            shared: &shared,
        };
        let yc = 37.5;
        let mut restarted_differs = false;
        for x0 in 0..3 * RESTART {
            for x in x0..x0 + 5 * RESTART {
                let whole = values_at(&it, x0, x, yc);
                // The span cut at the last restart column at or before x (a tile's edge).
                let cut = (x - x.rem_euclid(RESTART)).max(x0);
                assert_eq!(
                    whole,
                    values_at(&it, cut, x, yc),
                    "x0 {x0}, x {x}, cut {cut}"
                );
                // Stepping all the way without restarts rounds differently somewhere
                // (otherwise this test would show nothing).
                let mut run = SpanRun::new(&it, x0, yc, 8);
                for _ in x0..x {
                    run.step_within();
                }
                restarted_differs |= run.color != whole.2 || run.z != whole.0;
            }
        }
        assert!(restarted_differs);
    }

    /// The eight-lane stencil kernel gives `apply_stencil_op` lane by lane, for every test
    /// function and every triple of actions, with value and write masks, references above
    /// and below the values, and random depth results.
    #[test]
    fn stencil8_is_the_per_lane_stencil() {
        use CompareFunc::*;
        use StencilOp::*;
        let funcs = [
            Never,
            Less,
            Equal,
            LessEqual,
            Greater,
            NotEqual,
            GreaterEqual,
            Always,
        ];
        let ops = [Keep, Zero, Replace, Incr, Decr, Invert, IncrWrap, DecrWrap];
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        let mut checked = 0;
        for func in funcs {
            for (i, &fail) in ops.iter().enumerate() {
                for &depth_fail in &ops {
                    for &depth_pass in &ops {
                        let r = crate::test_support::xorshift(&mut seed);
                        let u = Uniforms {
                            stencil_ref: [0, 0x80, 0xFF, r as u8][i % 4],
                            stencil_value_mask: [0xFF, 0x3F, (r >> 8) as u8][i % 3],
                            stencil_write_mask: [0xFF, 0xF5, (r >> 16) as u8][(i / 3) % 3],
                            ..Uniforms::default()
                        };
                        let st = StencilKey {
                            func,
                            fail,
                            depth_fail,
                            depth_pass,
                        };
                        let mut old = (r >> 24).to_le_bytes();
                        old[0] = 0;
                        old[1] = 0xFF;
                        old[2] = u.stencil_ref;
                        let dp = (r >> 40) as u8;
                        assert_eq!(
                            stencil8(&st, &u, &old, dp),
                            stencil8_lanes(&st, &u, &old, dp, 0xFF),
                            "{st:?} {u:?} {old:?} {dp:#x}"
                        );
                        // Some lanes not live: they keep their values.
                        let live = (r >> 48) as u8 | dp;
                        let (new, pass) = stencil8_live(&st, &u, &old, dp, live);
                        assert_eq!(
                            (new, pass),
                            stencil8_lanes(&st, &u, &old, dp, live),
                            "{st:?} {u:?} {old:?} {dp:#x} {live:#x}"
                        );
                        for j in (0..8).filter(|j| live & (1 << j) == 0) {
                            assert_eq!(new[j], old[j]);
                        }
                        assert_eq!(
                            stencil_test8(&st, &u, &old),
                            stencil_test8_lanes(&st, &u, &old),
                            "{st:?} {u:?} {old:?}"
                        );
                        checked += 1;
                    }
                }
            }
        }
        assert_eq!(checked, 8 * 512);
    }
}

//! Span functions: shade the covered pixels `x0..x1` of one row of a tile. The general path
//! reads the key at run time; specialised paths are the same code monomorphised on the key,
//! so a disabled stage is compiled out instead of skipped by a branch.
//!
//! A map for reading (`fragment/cache.rs` picks one row function and, for some keys, one
//! two-row function per draw):
//! - per fragment, in the specification's order: [`span_general`] (every key), its
//!   monomorphised forms [`span_specialised`] and [`span_fogged`], and [`span_sampled`]
//!   (texels eight at a time, the rest per fragment); all of them run `shade` /
//!   `finish_fragment`;
//! - eight fragments at a time through one tail (`tail8`, `simd::shade8`: environment, alpha
//!   test, blending, colour mask): [`span_textured`] (one `REPLACE`/`MODULATE` unit),
//!   [`span_sampled8`] (any units, the cascade eight at a time), [`span_untextured8`];
//! - two rows at a time in 4x2 blocks for the eight-lane textured keys: [`pair_textured`] and
//!   [`pair_sampled8`] over `for_each_block` (triangles only; `raster/tri.rs` pairs the rows).
//!
//! Every fast path computes each value as the general path does, so pictures are identical
//! (twin tests in `tests/raster.rs` and `tests/state_combinations.rs`). Texture coordinates and
//! their per-quad derivatives come from `unit_coords` (one fragment) or `Perspective8` (eight).

use std::cell::Cell;

use super::blend::{blend, blend_alpha_over};
use super::key::{FragmentKey, Uniforms};
use super::texenv::{self, CombineInputs};
use crate::api::convert::{CompareFunc, StencilOp, TexEnvMode};
use crate::framebuffer::Tile;
use crate::raster::setup::Plane;
use crate::state::snapshot::{attr, FogDraw, TextureUnitDraw};
use crate::state::tables::limits::MAX_TEXTURE_UNITS;
use crate::state::DrawState;
use crate::texture::format::BaseFormat;
use crate::texture::sample::{FastLevel, LevelPlan, LodSelect};
use crate::texture::simd::{self, lerp8, After8, Level8, Sampling8, Tail8, Texels8};

/// The interpolants of one primitive for the fragment stage.
#[derive(Clone, Debug)]
pub struct Interpolants<'a> {
    /// Window z in [0, 1].
    pub z: Plane,
    /// 1/w_clip, for perspective correction.
    pub inv_w: Plane,
    /// Attribute planes: attribute/w when `perspective`, else the attribute itself.
    pub attrs: &'a [Plane],
    pub perspective: bool,
    /// The primary colour's planes hold the colour itself, not colour/w: it is the same at
    /// the three vertices, so it is the same at every fragment (no division by 1/w, which
    /// would round it).
    pub constant_primary: bool,
    /// Antialiasing coverage, multiplied into the alpha after fog (1 for aliased primitives).
    pub coverage: f32,
    /// What the primitive's spans share beyond the planes. (A reference: a larger
    /// `Interpolants` measurably slows the other paths.)
    pub shared: &'a PrimitiveShared<'a>,
}

/// What the spans of one primitive share: prepared once, not per span.
#[derive(Debug)]
pub struct PrimitiveShared<'a> {
    /// The fast textured path's level selection where the primitive's 1/w and q are constant
    /// (then λ is the same at every fragment with finite coordinates): prepared by the first
    /// span that needs it and reused by the others.
    pub fast: Cell<Option<AffineSpan<'a>>>,
    /// The draw's texture levels prepared for the eight-pixel filter.
    pub levels: &'a UnitLevels<'a>,
}

impl<'a> PrimitiveShared<'a> {
    pub fn new(levels: &'a UnitLevels<'a>) -> PrimitiveShared<'a> {
        PrimitiveShared {
            fast: Cell::new(None),
            levels,
        }
    }
}

/// Every level of each unit's texture prepared for the eight-pixel filter ([`Level8`]; `None`
/// where a level does not take it), by the unit's index in `DrawState::units`. Prepared once
/// per tile and draw state ([`UnitLevels::prepare`]) instead of in every span: the spans of
/// small triangles are a few pixels long. Empty (and not allocated) for draws without
/// eight-pixel samplers.
#[derive(Clone, Debug, Default)]
pub struct UnitLevels<'a> {
    units: Vec<[Option<Level8<'a>>; MAX_FAST_LEVELS]>,
    /// `pair_textured`'s tail for the draw (one REPLACE/MODULATE unit on the fast 2D path,
    /// fragments finishing eight at a time), built once here instead of per row pair.
    textured_tail: Option<Tail8>,
}

impl<'a> UnitLevels<'a> {
    /// Replaces the table with the levels of `ds`'s units (none unless the draw's key has
    /// `simd_units`, which the eight-pixel samplers require).
    pub fn prepare(&mut self, ds: &'a DrawState) {
        self.units.clear();
        self.textured_tail = None;
        if !ds.key.simd_units || !simd::available() {
            return;
        }
        if let (Some(layout), Some(unit)) = (ds.key.fast_texture, ds.units.first()) {
            if tail8_applies(&ds.key) {
                let modulate = unit.env.mode == TexEnvMode::Modulate;
                let rgb = layout == super::key::FastTexture::Rgb;
                self.textured_tail = Some(tail8(ds, modulate, false, rgb));
            }
        }
        for unit in &ds.units {
            let tex = &unit.texture;
            let (wrap, base) = (tex.wrap_st(), tex.base_format());
            let mut levels = [None; MAX_FAST_LEVELS];
            for (l, level) in levels.iter_mut().enumerate().take(tex.level_count()) {
                *level = tex.fast_level(l).and_then(|f| Level8::new(&f, wrap, base));
            }
            self.units.push(levels);
        }
    }
}

/// Shades pixels `x0..x1` of row `y` (window coordinates, inside `tile`).
pub type SpanFn = for<'a> fn(&'a DrawState, &mut Tile, i32, i32, i32, &Interpolants<'a>);

/// Converts window z to a stored depth value (round to nearest, clamped): `z * max + 0.5`
/// truncated, NaN and negatives as 0, at most `depth_max` (Rust's `as` saturates, without
/// branches).
#[inline(always)]
pub fn depth_to_fixed(z: f64, depth_max: u32) -> u32 {
    ((z * depth_max as f64 + 0.5) as u32).min(depth_max)
}

/// Converts a colour component to 8 bits (section 2.14.9: round to nearest after clamping):
/// `c * 255 + 0.5` truncated, NaN and negatives as 0, at most 255 (Rust's `as` saturates).
#[inline(always)]
pub fn color_to_u8(c: f32) -> u8 {
    (c * 255.0 + 0.5) as u8
}

/// [`color_to_u8`] of four components at once, with SSE2 (part of every x86-64 processor):
/// the fragment paths convert every fragment's colour.
#[inline(always)]
pub fn color4_to_u8(c: [f32; 4]) -> [u8; 4] {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: SSE and SSE2 are part of the x86-64 baseline; no memory is accessed.
    unsafe {
        use std::arch::x86_64::*;
        let v = _mm_add_ps(
            _mm_mul_ps(_mm_setr_ps(c[0], c[1], c[2], c[3]), _mm_set1_ps(255.0)),
            _mm_set1_ps(0.5),
        );
        // max_ps answers its second operand (0) when v is NaN.
        let v = _mm_min_ps(_mm_max_ps(v, _mm_setzero_ps()), _mm_set1_ps(255.0));
        let i = _mm_cvttps_epi32(v);
        let bytes = _mm_packus_epi16(_mm_packs_epi32(i, i), _mm_setzero_si128());
        (_mm_cvtsi128_si32(bytes) as u32).to_le_bytes()
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        c.map(color_to_u8)
    }
}

/// Depth handling chosen at compile time: `DYNAMIC` reads the key, others are fixed.
pub mod depth_mode {
    pub const DYNAMIC: u8 = 0;
    pub const NONE: u8 = 1;
    pub const LESS_WRITE: u8 = 2;
    pub const LEQUAL_WRITE: u8 = 3;
}

/// Texturing chosen at compile time: `DYNAMIC` reads the key (every unit through the general
/// sampler); `FAST_RGB` and `FAST_RGBA` are the one-unit fast 2D path for keys with
/// `fast_texture` (texels of 3 or 4 unsigned bytes).
pub mod tex_mode {
    pub const DYNAMIC: u8 = 0;
    pub const FAST_RGB: u8 = 3;
    pub const FAST_RGBA: u8 = 4;
}

/// Blending chosen at compile time: `DYNAMIC` reads the key; `ALPHA_OVER` is a key whose
/// blending `BlendKey::is_alpha_over`.
pub mod blend_mode {
    pub const DYNAMIC: u8 = 0;
    pub const ALPHA_OVER: u8 = 1;
}

/// Applies a stencil action to `old` under the write mask (section 4.1.5; 8-bit buffer).
#[inline(always)]
pub fn apply_stencil_op(op: StencilOp, old: u8, u: &Uniforms) -> u8 {
    let v = match op {
        StencilOp::Keep => return old,
        StencilOp::Zero => 0,
        StencilOp::Replace => u.stencil_ref,
        StencilOp::Incr => old.saturating_add(1),
        StencilOp::Decr => old.saturating_sub(1),
        StencilOp::Invert => !old,
        StencilOp::IncrWrap => old.wrapping_add(1),
        StencilOp::DecrWrap => old.wrapping_sub(1),
    };
    (old & !u.stencil_write_mask) | (v & u.stencil_write_mask)
}

/// Fog (section 3.10) on a fragment's colour: the factor for its fog coordinate `c`, and
/// the blend towards the fog colour.
#[inline(always)]
fn fog_fragment(f: &FogDraw, c: f32, color: &mut [f32; 4]) {
    let k = f.factor(c);
    for ch in 0..3 {
        color[ch] = k * color[ch].clamp(0.0, 1.0) + (1.0 - k) * f.color[ch];
    }
}

/// The per-fragment operations after texturing, in the specification's order: colour sum
/// (`secondary`: the interpolated secondary colour), fog (`fog_coord`), antialiasing
/// coverage, alpha test, stencil and depth tests with their updates, occlusion counting,
/// blending or logic op, colour mask; `z` is the fragment's window depth and `idx` its index
/// in `tile`. The const parameters are [`shade`]'s (`FOG` keeps fog on a `SIMPLE` path) and
/// `BLEND` fixes the blending ([`blend_mode`]).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn finish_fragment<
    const DEPTH: u8,
    const FULL_MASK: bool,
    const SIMPLE: bool,
    const FOG: bool,
    const BLEND: u8,
>(
    ds: &DrawState,
    tile: &mut Tile,
    it: &Interpolants,
    idx: usize,
    fog_coord: f32,
    mut color: [f32; 4],
    secondary: [f32; 3],
    z: f64,
) {
    let key = &ds.key;
    let u = &ds.uniforms;
    if !SIMPLE && key.color_sum {
        for c in 0..3 {
            color[c] = color[c].clamp(0.0, 1.0) + secondary[c];
        }
    }
    if (FOG || !SIMPLE) && key.fog.is_some() {
        if let Some(f) = &ds.fog {
            fog_fragment(f, fog_coord, &mut color);
        }
    }
    if it.coverage != 1.0 {
        color[3] = color[3].clamp(0.0, 1.0) * it.coverage;
    }
    if !SIMPLE {
        if let Some(f) = key.alpha_func {
            if !f.test(color[3].clamp(0.0, 1.0), u.alpha_ref) {
                return;
            }
        }
    }
    let depth = depth_to_fixed(z, ds.depth_max);
    let depth_pass = match DEPTH {
        depth_mode::NONE => true,
        depth_mode::LESS_WRITE => depth < tile.depth[idx],
        depth_mode::LEQUAL_WRITE => depth <= tile.depth[idx],
        _ => match key.depth_func {
            None => true,
            Some(CompareFunc::Always) => true,
            Some(f) => f.test(depth, tile.depth[idx]),
        },
    };
    if !SIMPLE {
        if let Some(st) = key.stencil {
            let old = tile.stencil[idx];
            let mask = u.stencil_value_mask;
            let action = if !st.func.test(u.stencil_ref & mask, old & mask) {
                tile.stencil[idx] = apply_stencil_op(st.fail, old, u);
                return;
            } else if depth_pass {
                st.depth_pass
            } else {
                st.depth_fail
            };
            tile.stencil[idx] = apply_stencil_op(action, old, u);
        }
    }
    if !depth_pass {
        return;
    }
    if !SIMPLE && key.count_samples {
        tile.samples_passed += 1;
    }
    let write_depth = match DEPTH {
        depth_mode::NONE => false,
        depth_mode::LESS_WRITE | depth_mode::LEQUAL_WRITE => true,
        _ => key.depth_write,
    };
    if write_depth {
        tile.depth[idx] = depth;
    }
    let mut rgba = color4_to_u8(color);
    if !SIMPLE {
        let dst = tile.color[idx];
        if let Some(op) = key.logic_op {
            for c in 0..4 {
                rgba[c] = op.apply(rgba[c], dst[c]);
            }
        } else if let Some(b) = &key.blend {
            rgba = if BLEND == blend_mode::ALPHA_OVER {
                blend_alpha_over(rgba, dst)
            } else {
                blend(b, rgba, dst, u.blend_color)
            };
        }
    }
    if FULL_MASK {
        tile.color[idx] = rgba;
    } else {
        let dst = &mut tile.color[idx];
        for c in 0..4 {
            if key.color_mask[c] {
                dst[c] = rgba[c];
            }
        }
    }
}

/// The per-fragment pipeline in the specification's order: alpha test, stencil test, depth
/// test (with the stencil actions), blending or logic op, colour mask. `SIMPLE` paths have no
/// alpha test, stencil, blending or logic op (the key says so); their depth handling is fixed
/// by `DEPTH` and the colour mask by `FULL_MASK`.
///
/// `SAMPLED` samples every texture unit eight pixels at a time ([`Perspective8`]) ahead of
/// the per-fragment environment; the key must have `simd_units`.
#[inline(always)]
fn shade<
    'a,
    const DEPTH: u8,
    const FULL_MASK: bool,
    const SIMPLE: bool,
    const SAMPLED: bool,
    const FOG: bool,
>(
    ds: &'a DrawState,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    let key = &ds.key;
    let yc = y as f64 + 0.5;
    let row = tile.index(x0, y);
    let n = (x1 - x0) as usize;
    let xc0 = x0 as f64 + 0.5;
    // Primary colour, then the secondary colour when the colour sum needs it.
    let colors = if !SIMPLE && (key.color_sum || key.texturing) {
        8
    } else {
        4
    };
    let mut run = SpanRun::new(it, xc0, yc, colors).with_fog(ds, it, xc0, yc);
    // The sampled path: per unit, its eight-pixel sampler and the texels of the current
    // group of eight pixels (groups start on even columns, as quads do).
    let mut samplers: [Option<Perspective8>; MAX_TEXTURE_UNITS] = Default::default();
    let mut group_texels = [[[0f32; 8]; 4]; MAX_TEXTURE_UNITS];
    let group0 = x0 & !1;
    if SAMPLED {
        for (k, (slot, u)) in samplers.iter_mut().zip(&ds.units).enumerate() {
            *slot = Perspective8::new(u, k, it, y);
        }
    }
    for i in 0..n {
        let idx = row + i;
        let w = run.w();
        let mut color = run.primary(w);
        if SAMPLED && key.texturing {
            let x = x0 + i as i32;
            let lane = ((x - group0) % 8) as usize;
            if lane == 0 || i == 0 {
                let gx = x - lane as i32;
                let live = ((1u32 << ((x1 - gx).min(8) as u32)) - (1u32 << lane)) as u8;
                for (k, u) in ds.units.iter().enumerate() {
                    sampled_texels(
                        samplers[k].as_mut(),
                        u,
                        it,
                        gx,
                        yc,
                        live,
                        &mut group_texels[k],
                    );
                }
            }
            let mut texels: [Option<[f32; 4]>; MAX_TEXTURE_UNITS] = [None; MAX_TEXTURE_UNITS];
            for (k, u) in ds.units.iter().enumerate() {
                let t = &group_texels[k];
                texels[u.unit] = Some([t[0][lane], t[1][lane], t[2][lane], t[3][lane]]);
            }
            color = environment(ds, color, &texels);
        } else if !SIMPLE && key.texturing {
            color = texture_fragment(ds, it, x0 as f64 + i as f64 + 0.5, yc, color);
        }
        let secondary = if !SIMPLE && key.color_sum {
            run.secondary(w)
        } else {
            [0.0; 3]
        };
        let z_here = run.z;
        let fog_coord = run.fog_coord(w);
        run.step();
        finish_fragment::<DEPTH, FULL_MASK, SIMPLE, FOG, { blend_mode::DYNAMIC }>(
            ds, tile, it, idx, fog_coord, color, secondary, z_here,
        );
    }
}

/// [`shade`] with the texturing and blending fixed at compile time ([`tex_mode`],
/// [`blend_mode`]) for `span_textured`: the same per-fragment pipeline in the specification's order: alpha test, stencil test, depth
/// test (with the stencil actions), blending or logic op, colour mask. `SIMPLE` paths have no
/// alpha test, stencil, blending or logic op (the key says so); their depth handling is fixed
/// by `DEPTH` and the colour mask by `FULL_MASK`. `TEX` and `BLEND` fix the texturing and
/// the blending ([`tex_mode`], [`blend_mode`]); the key must agree with them.
#[inline(always)]
fn shade_textured<
    'a,
    const DEPTH: u8,
    const FULL_MASK: bool,
    const SIMPLE: bool,
    const TEX: u8,
    const BLEND: u8,
>(
    ds: &'a DrawState,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    let key = &ds.key;
    let yc = y as f64 + 0.5;
    let row = tile.index(x0, y);
    let n = (x1 - x0) as usize;
    let xc0 = x0 as f64 + 0.5;
    // Primary colour, then the secondary colour when the colour sum needs it (the eight-lane
    // route steps it only then: `SpanRun::next`).
    let colors = if !SIMPLE && key.color_sum { 8 } else { 4 };
    let mut run = SpanRun::new(it, xc0, yc, colors).with_fog(ds, it, xc0, yc);
    let fast = match TEX {
        tex_mode::FAST_RGB | tex_mode::FAST_RGBA => {
            ds.units.first().map(|u| FastUnit::new(u, it, xc0, yc))
        }
        _ => None,
    };
    if (TEX == tex_mode::FAST_RGBA || TEX == tex_mode::FAST_RGB)
        && tail8_applies(key)
        && it.coverage == 1.0
    {
        if let Some(f) = &fast {
            let sampling = f.sampling8(it);
            let mut perspective = if sampling.is_none() && f.affine.is_none() {
                Perspective8::new(f.unit, 0, it, y)
            } else {
                None
            };
            if sampling.is_some() || perspective.is_some() {
                let tail = tail8(ds, f.modulate, false, TEX == tex_mode::FAST_RGB);
                // With zero steps for z, 1/w and the colour (a flat, facing primitive), the
                // values from the second pixel on are those of the second pixel (adding a zero
                // changes at most the sign of a zero, and only once): two pixels are stepped.
                let steady = run.is_steady();
                let mut steady_values = [([0f32; 4], 0u32, 0f32, None); 2];
                if steady {
                    for v in &mut steady_values {
                        *v = run.next::<true>(Some(ds.depth_max));
                    }
                }
                let depth_max = group_depth_max(ds);
                let fog = lane_fog(ds);
                let fogged = fog.is_some();
                // Groups of eight lanes from `gx`; the perspective sampler needs groups that
                // start on an even column (quads), so its first group may begin one pixel
                // early with lane 0 not live.
                let mut gx = if perspective.is_some() { x0 & !1 } else { x0 };
                while gx < x1 {
                    let lo = (x0 - gx).max(0) as usize;
                    let hi = ((x1 - gx) as usize).min(8);
                    let first = (gx - x0) as isize;
                    let base = (row as isize + first) as usize;
                    let mut group = GroupInputs::gather(ds, tile, base, lo..hi, |j| {
                        if steady {
                            steady_values[((first + j as isize) as usize).min(1)]
                        } else if fogged {
                            run.next::<true>(depth_max)
                        } else {
                            run.next::<false>(depth_max)
                        }
                    });
                    // Lanes failing the depth test change nothing (no stencil here): a group
                    // without a passing lane is not sampled, and only passing quads choose
                    // levels.
                    if group.pass == 0 {
                        gx += 8;
                        continue;
                    }
                    group.fog_factors(fog);
                    let GroupInputs {
                        primary,
                        depth,
                        pass,
                        dst,
                        after,
                    } = group;
                    let x = gx as f64 + 0.5;
                    let live = pass;
                    // `shade8` always answers: AVX2 was detected above.
                    let shaded = match (&sampling, &mut perspective) {
                        (Some(sm), _) => {
                            simd::textured8(sm, x, hi, &tail, &primary, &dst, pass, &after)
                        }
                        (None, Some(p)) => {
                            let mut tex = [[0f32; 8]; 4];
                            if p.texels_into(x, live, &mut tex) {
                                simd::shade8(&tail, &primary, &tex, &dst, pass, &after)
                            } else {
                                None
                            }
                        }
                        _ => None,
                    }
                    .or_else(|| {
                        let tex = if TEX == tex_mode::FAST_RGB {
                            f.texels_scalar::<3>(it, x, yc, hi)
                        } else {
                            f.texels_scalar::<4>(it, x, yc, hi)
                        };
                        simd::shade8(&tail, &primary, &tex, &dst, pass, &after)
                    });
                    if let Some((words, passed)) = shaded {
                        store_group(ds, tile, base, lo..hi, &words, passed, &depth);
                    }
                    gx += 8;
                }
                return;
            }
        }
    }
    let mut texel_buf = [[0f32; 4]; 8];
    for i in 0..n {
        let idx = row + i;
        let w = run.w();
        let mut color = run.primary(w);
        match (TEX, &fast) {
            (tex_mode::FAST_RGB, Some(f)) => {
                color = f.fragment::<3>(it, x0 as f64 + i as f64 + 0.5, yc, color);
            }
            (tex_mode::FAST_RGBA, Some(f)) => {
                if i % 8 == 0 {
                    let x = x0 as f64 + i as f64 + 0.5;
                    f.texels8::<4>(it, x, yc, (n - i).min(8), &mut texel_buf);
                }
                color = f.env::<4>(color, texel_buf[i % 8]);
            }
            _ => {
                if !SIMPLE && key.texturing {
                    color = texture_fragment(ds, it, x0 as f64 + i as f64 + 0.5, yc, color);
                }
            }
        }
        let secondary = if !SIMPLE && key.color_sum {
            run.secondary(w)
        } else {
            [0.0; 3]
        };
        let z_here = run.z;
        let fog_coord = run.fog_coord(w);
        run.step();
        finish_fragment::<DEPTH, FULL_MASK, SIMPLE, false, BLEND>(
            ds, tile, it, idx, fog_coord, color, secondary, z_here,
        );
    }
}

/// Texture coordinates (s, t, r divided by q) of one unit at window point (x, y), in f64.
/// Under perspective the planes hold s/w ... q/w, and (s/w) / (q/w) is s/q: one division.
#[inline(always)]
fn coords_at(it: &Interpolants, base: usize, x: f64, y: f64) -> [f64; 3] {
    let p = &it.attrs[base..base + 4];
    let q = p[3].at(x, y);
    [0, 1, 2].map(|k| p[k].at(x, y) / q)
}

/// The centre coordinate of the first pixel of the 2x2 quad (aligned to even window
/// coordinates) holding the pixel centred at `c`.
#[inline(always)]
fn quad_origin(c: f64) -> f64 {
    ((c - 0.5) * 0.5).floor() * 2.0 + 0.5
}

/// Texture coordinates of one unit at the pixel centred at (x, y), with the screen
/// derivatives λ is computed from: finite differences over the pixel's 2x2 quad (section
/// 3.8.8 allows them; this is what hardware and Mesa do, so mipmap level choices agree). The
/// quads are aligned to even window coordinates; the x difference is taken along the quad's
/// upper row and the y difference along its left column, and all four pixels share them.
fn unit_coords(it: &Interpolants, base: usize, x: f64, y: f64) -> ([f32; 3], [f32; 3], [f32; 3]) {
    let c = coords_at(it, base, x, y);
    let qx = quad_origin(x);
    let qy = quad_origin(y);
    let upper = qy + 1.0;
    let ref_ = coords_at(it, base, qx, upper);
    let right = coords_at(it, base, qx + 1.0, upper);
    let below = coords_at(it, base, qx, qy);
    let dx = [0, 1, 2].map(|k| right[k] - ref_[k]);
    let dy = [0, 1, 2].map(|k| ref_[k] - below[k]);
    // q = 0 (or non-finite input) gives no usable coordinate: sample at the origin.
    let fix = |a: [f64; 3]| {
        a.map(|v| {
            let v = v as f32;
            if v.is_finite() {
                v
            } else {
                0.0
            }
        })
    };
    (fix(c), fix(dx), fix(dy))
}

/// Samples every unit and runs the texture environment cascade on the primary colour.
#[inline(never)]
fn texture_fragment(
    ds: &DrawState,
    it: &Interpolants,
    x: f64,
    y: f64,
    primary: [f32; 4],
) -> [f32; 4] {
    let mut texels: [Option<[f32; 4]>; MAX_TEXTURE_UNITS] = [None; MAX_TEXTURE_UNITS];
    for u in &ds.units {
        texels[u.unit] = Some(unit_texel(u, it, x, y));
    }
    environment(ds, primary, &texels)
}

/// The texel of unit `u` at the pixel centred at (x, y), as the general path samples it.
#[inline(always)]
fn unit_texel(u: &TextureUnitDraw, it: &Interpolants, x: f64, y: f64) -> [f32; 4] {
    let (c, dx, dy) = unit_coords(it, attr::TEX + 4 * u.unit, x, y);
    u.texture.sample_grad(c, dx, dy, u.env.lod_bias)
}

/// The eight texels of unit `u` for the pixels centred at `gx + j + 0.5` on row `yc` (`gx`
/// even; lanes whose bit is clear in `live` are not needed): from its eight-pixel sampler, or
/// one by one as the general path samples them.
fn sampled_texels(
    sampler: Option<&mut Perspective8>,
    u: &TextureUnitDraw,
    it: &Interpolants,
    gx: i32,
    yc: f64,
    live: u8,
    out: &mut Texels8,
) {
    let x = gx as f64 + 0.5;
    if sampler.is_some_and(|p| p.texels_into(x, live, out)) {
        return;
    }
    for j in 0..8 {
        if live & (1 << j) != 0 {
            let t = unit_texel(u, it, x + j as f64, yc);
            for c in 0..4 {
                out[c][j] = t[c];
            }
        }
    }
}

/// The texture environment cascade on the primary colour, given each unit's texel.
#[inline(never)]
fn environment(
    ds: &DrawState,
    primary: [f32; 4],
    texels: &[Option<[f32; 4]>; MAX_TEXTURE_UNITS],
) -> [f32; 4] {
    let primary = primary.map(|c| c.max(0.0).min(1.0));
    let inputs = CombineInputs { primary, texels };
    let mut color = primary;
    for u in &ds.units {
        let ct = texels[u.unit].unwrap_or([0.0; 4]);
        color = texenv::apply(&u.env, u.base, u.unit, color, ct, &inputs);
    }
    color
}

/// [`environment`] for eight fragments at once: primary colours `primary` (channel arrays) and
/// the texels of every unit with a texture in `by_unit` (indexed by unit number).
fn environment8(
    ds: &DrawState,
    primary: &Texels8,
    by_unit: &[Option<Texels8>; MAX_TEXTURE_UNITS],
) -> Texels8 {
    #[cfg(target_arch = "x86_64")]
    {
        if simd::available() {
            // SAFETY: AVX2 is present (checked just above).
            return unsafe { environment8_avx2(ds, primary, by_unit) };
        }
    }
    environment8_arrays(ds, primary, by_unit)
}

/// [`environment8`] on AVX2 registers ([`texenv::Avx8`]): the same operations in the same
/// order, eight lanes at a time and without the arrays' round trips through memory.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn environment8_avx2(
    ds: &DrawState,
    primary: &Texels8,
    by_unit: &[Option<Texels8>; MAX_TEXTURE_UNITS],
) -> Texels8 {
    use std::arch::x86_64::*;
    use texenv::{Avx8, Lanes};
    // SAFETY: each array holds eight f32; unaligned loads and stores.
    let load = |a: &[f32; 8]| Avx8(unsafe { _mm256_loadu_ps(a.as_ptr()) });
    let rgba = |t: &Texels8| [load(&t[0]), load(&t[1]), load(&t[2]), load(&t[3])];
    let primary = rgba(primary).map(|c| c.clamp01());
    let mut texels: [Option<[Avx8; 4]>; MAX_TEXTURE_UNITS] = [None; MAX_TEXTURE_UNITS];
    for (slot, t) in texels.iter_mut().zip(by_unit) {
        *slot = t.as_ref().map(rgba);
    }
    let inputs = CombineInputs {
        primary,
        texels: &texels,
    };
    let mut color = primary;
    for u in &ds.units {
        let ct = texels[u.unit].unwrap_or([Avx8::splat(0.0); 4]);
        color = texenv::apply(&u.env, u.base, u.unit, color, ct, &inputs);
    }
    let mut out = [[0f32; 8]; 4];
    for (o, c) in out.iter_mut().zip(color) {
        unsafe { _mm256_storeu_ps(o.as_mut_ptr(), c.0) };
    }
    out
}

#[inline(always)]
fn environment8_arrays(
    ds: &DrawState,
    primary: &Texels8,
    by_unit: &[Option<Texels8>; MAX_TEXTURE_UNITS],
) -> Texels8 {
    use texenv::Lanes;
    let primary = primary.map(|c| c.clamp01());
    let inputs = CombineInputs {
        primary,
        texels: by_unit,
    };
    let mut color = primary;
    for u in &ds.units {
        let ct = by_unit[u.unit].unwrap_or([[0.0; 8]; 4]);
        color = texenv::apply(&u.env, u.base, u.unit, color, ct, &inputs);
    }
    color
}

/// One unit on the fast 2D path over one span: the texture, the coordinate planes and, for
/// an affine span, the level selection shared by all its pixels.
struct FastUnit<'a> {
    unit: &'a TextureUnitDraw,
    /// Index of the unit's s plane.
    base: usize,
    modulate: bool,
    affine: Option<AffineSpan<'a>>,
}

/// A span whose 1/w and q planes are constant (as under an orthographic projection): the
/// derivatives of s and t, hence λ and the levels, are the same at every pixel where s and t
/// (before the division by q) are finite.
#[derive(Clone, Copy, Debug)]
pub struct AffineSpan<'a> {
    /// 1 and the q plane's value (s/q is the s plane divided by 1, then by q; non-zero and
    /// finite), the form [`simd::coords8`] takes.
    w: f64,
    q: f64,
    /// `b * y` of the s and t planes on the span's row.
    by: [f64; 2],
    levels: [FastLevel<'a>; 2],
    linear: bool,
    /// The second level's weight, when two levels are mixed.
    weight: Option<f32>,
    /// The levels for the eight-pixel filter, when the processor, format and wrap modes
    /// allow it.
    simd: Option<[Level8<'a>; 2]>,
}

/// The general path's fix-up of a coordinate that is not finite (q = 0 and the like).
#[inline(always)]
fn finite_or_zero(x: f32) -> f32 {
    if x.is_finite() {
        x
    } else {
        0.0
    }
}

impl<'a> FastUnit<'a> {
    fn new(u: &'a TextureUnitDraw, it: &Interpolants<'a>, xc0: f64, yc: f64) -> FastUnit<'a> {
        let base = attr::TEX + 4 * u.unit;
        FastUnit {
            unit: u,
            base,
            modulate: u.env.mode == TexEnvMode::Modulate,
            affine: Self::affine(u, it, base, xc0, yc),
        }
    }

    /// The span's shared level selection, when its 1/w and q planes are constant and its
    /// first pixel's s and t are finite (then every pixel with finite s and t has the first
    /// pixel's derivatives, up to the sign of zeros, which λ squares away). Prepared once per
    /// primitive (`Interpolants::fast`).
    fn affine(
        u: &'a TextureUnitDraw,
        it: &Interpolants<'a>,
        base: usize,
        xc0: f64,
        yc: f64,
    ) -> Option<AffineSpan<'a>> {
        let p = &it.attrs[base..base + 4];
        // (Tested before the shared selection is read: that copies a few hundred bytes, and
        // only affine primitives have one.)
        if it.inv_w.a != 0.0 || it.inv_w.b != 0.0 || p[3].a != 0.0 || p[3].b != 0.0 {
            return None;
        }
        if let Some(mut a) = it.shared.fast.get() {
            a.by = [p[0].b * yc, p[1].b * yc];
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
        let simd = if simd::available() {
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
            by: [p[0].b * yc, p[1].b * yc],
            levels,
            linear,
            weight,
            simd,
        };
        it.shared.fast.set(Some(a));
        Some(a)
    }

    /// The texel at pixel centre (x, y), as the general path samples it.
    #[inline(always)]
    fn texel<const C: usize>(&self, it: &Interpolants, x: f64, y: f64) -> [f32; 4] {
        let tex = &self.unit.texture;
        if let Some(a) = &self.affine {
            let (s, t) = (&it.attrs[self.base], &it.attrs[self.base + 1]);
            let vs = (s.a * x + a.by[0] + s.c) / a.w;
            let vt = (t.a * x + a.by[1] + t.c) / a.w;
            if vs.is_finite() && vt.is_finite() {
                let c = [
                    finite_or_zero((vs / a.q) as f32),
                    finite_or_zero((vt / a.q) as f32),
                ];
                let t1 = tex.filter_fast::<C>(&a.levels[0], a.linear, c);
                return match a.weight {
                    None => t1,
                    Some(w) => {
                        let t2 = tex.filter_fast::<C>(&a.levels[1], a.linear, c);
                        lerp4(t1, t2, w)
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
                (Some(l1), Some(l2)) => {
                    let t1 = tex.filter_fast::<C>(&l1, linear, c2);
                    let t2 = tex.filter_fast::<C>(&l2, linear, c2);
                    lerp4(t1, t2, weight)
                }
                _ => tex.sample_grad(c, dx, dy, self.unit.env.lod_bias),
            },
        }
    }

    /// The texels of the `count` (at most 8) pixels from centre `x` on row `y`, into
    /// `out[..count]`: eight at once when the span allows it, else one by one.
    #[inline(always)]
    fn texels8<const C: usize>(
        &self,
        it: &Interpolants,
        x: f64,
        y: f64,
        count: usize,
        out: &mut [[f32; 4]; 8],
    ) {
        if let Some(a) = &self.affine {
            if let Some(levels) = &a.simd {
                let (ps, pt) = (&it.attrs[self.base], &it.attrs[self.base + 1]);
                let planes = [[ps.a, a.by[0], ps.c], [pt.a, a.by[1], pt.c]];
                if let Some([s, t]) = simd::coords8(planes, a.w, a.q, x, count) {
                    let t1 = simd::filter8(&levels[0], a.linear, &s, &t);
                    let ct = match (t1, a.weight) {
                        (Some(t1), None) => Some(t1),
                        (Some(t1), Some(w)) => {
                            simd::filter8(&levels[1], a.linear, &s, &t).map(|t2| lerp8(&t1, &t2, w))
                        }
                        _ => None,
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
    fn sampling8(&self, it: &Interpolants) -> Option<Sampling8<'a>> {
        let a = self.affine.as_ref()?;
        let levels = a.simd?;
        let (ps, pt) = (&it.attrs[self.base], &it.attrs[self.base + 1]);
        Some(Sampling8 {
            planes: [[ps.a, a.by[0], ps.c], [pt.a, a.by[1], pt.c]],
            w: a.w,
            q: a.q,
            levels,
            linear: a.linear,
            weight: a.weight,
        })
    }

    /// The texels of the `count` (at most 8) pixels from centre `x` on row `y` of a texture
    /// of `C` components (3 or 4), one by one, as channel arrays (lanes from `count` on are 0).
    fn texels_scalar<const C: usize>(
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
    fn env<const C: usize>(&self, primary: [f32; 4], ct: [f32; 4]) -> [f32; 4] {
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
    fn fragment<const C: usize>(
        &self,
        it: &Interpolants,
        x: f64,
        y: f64,
        primary: [f32; 4],
    ) -> [f32; 4] {
        self.env::<C>(primary, self.texel::<C>(it, x, y))
    }
}

/// Most mipmap levels a fast texture can have (sizes below 2^16).
const MAX_FAST_LEVELS: usize = 17;

/// One RGBA8 unit over one row of a perspective span, eight pixels at a time with AVX2: the
/// s, t and q planes on the pixel's row and on the other row of its 2x2 quads, and the
/// levels prepared for [`simd::filter8`] (on first use). Texels equal those of [`FastUnit::texel`] (the
/// general path): the same coordinates, the same per-quad derivatives, λ and level plan
/// (computed per quad by the sampler's own functions), the same filter arithmetic.
struct Perspective8<'a> {
    /// `[row][s, t, q] = [a, b * y, c]`: row 0 is the pixel's row, row 1 the quad's other.
    planes: [[[f64; 3]; 3]; 2],
    /// Whether the pixel's row is the upper row of its quads.
    own_is_upper: bool,
    /// The level and filter when they do not depend on λ (which is then not computed).
    fixed_plan: Option<(usize, bool)>,
    /// λ and level selection, gathered once for the draw.
    lod: &'a LodSelect,
    /// The texture's levels prepared for the filter ([`UnitLevels`]).
    levels: &'a [Option<Level8<'a>>; MAX_FAST_LEVELS],
}

impl<'a> Perspective8<'a> {
    /// The eight-pixel sampler on row `y` of the unit at index `k` of the draw's units, when
    /// every level of its texture takes the eight-pixel filter (the draw's key has
    /// `simd_units`: every unit's texture passes `BoundTexture::simd_2d`).
    #[inline(always)]
    fn new(
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
    fn on_rows(
        unit: &'a TextureUnitDraw,
        k: usize,
        it: &Interpolants<'a>,
        rows: [f64; 2],
        own_is_upper: bool,
    ) -> Option<Perspective8<'a>> {
        // No table (no `simd_units` or no AVX2), or a base level that does not take the
        // filter: sampled one by one.
        let levels = it.shared.levels.units.get(k)?;
        levels[0]?;
        let base = attr::TEX + 4 * unit.unit;
        let p = [&it.attrs[base], &it.attrs[base + 1], &it.attrs[base + 3]];
        let row = |y: f64| p.map(|pl| [pl.a, pl.b * y, pl.c]);
        Some(Perspective8 {
            planes: [row(rows[0]), row(rows[1])],
            own_is_upper,
            lod: &unit.lod,
            fixed_plan: unit.fixed_plan,
            levels,
        })
    }

    /// Level `l` prepared for the eight-pixel filter, or `None` when it does not take it.
    #[inline(always)]
    fn level(&self, l: usize) -> Option<&'a Level8<'a>> {
        // A reference into the table, not a copy: the filter reads the level right away, and
        // a fresh copy's stores would not forward to its wider loads.
        self.levels.get(l)?.as_ref()
    }

    /// The texels of the eight pixels centred at `x + j`, `x - 0.5` even (so lanes 2k and
    /// 2k + 1 form a quad's row), written into `out`; only lanes whose bit is set in `live`
    /// matter. False when a coordinate is beyond the filter's range (the caller samples one by
    /// one).
    fn texels_into(&mut self, x: f64, live: u8, out: &mut Texels8) -> bool {
        let Some(rows) = simd::perspective_rows8(&self.planes, x) else {
            return false;
        };
        self.texels_at(&rows, live, out).is_some()
    }

    fn texels_at(&self, rows: &[[[f64; 8]; 2]; 2], live: u8, out: &mut Texels8) -> Option<()> {
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
    fn block(
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
    fn texels_block(&self, x: f64, live: u8, out: &mut Texels8) -> bool {
        // A 2D texture (or a fixed plan) in one go: the same texels.
        let levels: &[Option<Level8>] = self.levels;
        if simd::block_texels8(
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
        let Some([vs, vt]) = simd::perspective_block8(&self.planes, x) else {
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

    /// [`Perspective8::texels_block`] and the tail in one go ([`simd::block_shaded8`]) for a
    /// block whose live quads take one level: the draw's fixed plan, or magnification of a 2D
    /// texture. `None` otherwise (the caller takes the usual route: the same pixels).
    #[inline(always)]
    fn shaded_block(&self, x: f64, group: &GroupInputs, tail: &Tail8) -> Option<([u32; 8], u8)> {
        let (level, linear, lod) = match self.fixed_plan {
            Some((level, linear)) => (level, linear, None),
            None => (0, self.lod.mag_linear(), Some(self.lod.magnified_test()?)),
        };
        simd::block_shaded8(
            &self.planes,
            x,
            self.level(level)?,
            linear,
            lod,
            group.pass,
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
    fn filter_quads<const N: usize>(
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
            let plan = if self.lod.surely_magnified(dx, dy) {
                self.lod.magnification()
            } else {
                self.lod.plan(self.lod.isotropic_lambda(dx, dy))
            };
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
            let t1 = simd::filter8(self.level(d1)?, linear, s, t)?;
            let texels = if d2 == d1 {
                t1
            } else {
                let t2 = simd::filter8(self.level(d2)?, linear, s, t)?;
                let mut mixed = [[0f32; 8]; 4];
                for c in 0..4 {
                    for j in 0..8 {
                        mixed[c][j] = t1[c][j] + (t2[c][j] - t1[c][j]) * weight[j];
                    }
                }
                mixed
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

#[inline(always)]
fn lerp4(a: [f32; 4], b: [f32; 4], w: f32) -> [f32; 4] {
    [
        a[0] + (b[0] - a[0]) * w,
        a[1] + (b[1] - a[1]) * w,
        a[2] + (b[2] - a[2]) * w,
        a[3] + (b[3] - a[3]) * w,
    ]
}

/// The window depth, 1/w and colours along a span, stepped pixel by pixel from its first
/// pixel: every span path steps them this way, so all see the same values.
struct SpanRun {
    z: f64,
    dz: f64,
    inv_w: f32,
    dinv_w: f32,
    /// Primary colour, then the secondary colour (attribute/w under perspective).
    color: [f32; 8],
    dcolor: [f32; 8],
    /// How many of `color` are interpolated: 4 (primary) or 8 (with the secondary colour).
    count: usize,
    perspective: bool,
    /// The primary colour is divided by 1/w (not for `Interpolants::constant_primary`).
    primary_perspective: bool,
    /// The fog coordinate (divided by w under perspective), when the draw is fogged.
    fog: Option<(f32, f32)>,
}

impl SpanRun {
    #[inline(always)]
    fn new(it: &Interpolants, xc0: f64, yc: f64, count: usize) -> SpanRun {
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
    fn with_fog(mut self, ds: &DrawState, it: &Interpolants, xc0: f64, yc: f64) -> SpanRun {
        if ds.key.fog.is_some() && ds.fog.is_some() {
            self.fog = Some(Self::fog_at(it, xc0, yc));
        }
        self
    }

    /// The fog coordinate's plane value at (`xc0`, `yc`) and its step along the row.
    #[inline(always)]
    fn fog_at(it: &Interpolants, xc0: f64, yc: f64) -> (f32, f32) {
        let p = &it.attrs[attr::FOG];
        (p.at(xc0, yc) as f32, p.a as f32)
    }

    /// The fog coordinate at the current pixel (0 unless fogged); `w` as from [`Self::w`].
    #[inline(always)]
    fn fog_coord(&self, w: f32) -> f32 {
        match self.fog {
            Some((c, _)) if self.perspective => c * w,
            Some((c, _)) => c,
            None => 0.0,
        }
    }

    /// Whether z, 1/w and the primary colour do not change along the span (a flat, facing
    /// primitive).
    fn is_steady(&self) -> bool {
        self.dz == 0.0
            && self.dinv_w == 0.0
            && self.dcolor[..self.count].iter().all(|&d| d == 0.0)
            && self.fog.is_none_or(|(_, dc)| dc == 0.0)
    }

    /// w at the current pixel (1 without perspective).
    #[inline(always)]
    fn w(&self) -> f32 {
        if self.perspective {
            1.0 / self.inv_w
        } else {
            1.0
        }
    }

    #[inline(always)]
    fn primary(&self, w: f32) -> [f32; 4] {
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
    fn secondary(&self, w: f32) -> [f32; 3] {
        [self.color[4] * w, self.color[5] * w, self.color[6] * w]
    }

    /// Moves to the next pixel.
    #[inline(always)]
    fn step(&mut self) {
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
    fn next<const FOG: bool>(&mut self, depth_max: Option<u32>) -> Lane {
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
type Lane = ([f32; 4], u32, f32, Option<[f32; 3]>);

/// The colours the eight-lane paths step ([`SpanRun::new`]'s count): the primary, and the
/// secondary with the colour sum.
#[inline(always)]
fn lane_colors(ds: &DrawState) -> usize {
    if ds.key.color_sum {
        8
    } else {
        4
    }
}

/// The fog the eight-lane paths apply: the draw's parameters when its key is fogged.
#[inline(always)]
fn lane_fog(ds: &DrawState) -> Option<&FogDraw> {
    ds.key.fog.and(ds.fog.as_ref())
}

/// What the eight-fragment tail needs of a group besides the texels: the primary colours and
/// depths of lanes `lo..hi`, which of them pass the depth test, and the stored colours.
struct GroupInputs {
    primary: Texels8,
    depth: [u32; 8],
    pass: u8,
    dst: [u32; 8],
    /// Fog coordinates, then (after [`GroupInputs::fog_factors`]) the fog factors of the
    /// passing lanes.
    /// The lanes' secondary colours and fog coordinates, then (after
    /// [`GroupInputs::fog_factors`]) the fog factors of the passing lanes.
    after: After8,
}

impl GroupInputs {
    const EMPTY: GroupInputs = GroupInputs {
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
    fn fog_factors(&mut self, fog: Option<&FogDraw>) {
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
    fn gather(
        ds: &DrawState,
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
    fn add(&mut self, ds: &DrawState, tile: &Tile, j: usize, index: usize, value: Lane) {
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
fn depth_passes(ds: &DrawState, d: u32, stored: u32) -> bool {
    match ds.key.depth_func {
        None | Some(CompareFunc::Always) => true,
        Some(func) => func.test(d, stored),
    }
}

/// Writes the tail's colour words of lanes `lanes` (pixel `base + j`), and with depth writes
/// the depth of each lane set in `passed`.
#[inline(always)]
fn store_group(
    ds: &DrawState,
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
fn store_lane(
    ds: &DrawState,
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
fn tail8(
    ds: &DrawState,
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
fn group_depth_max(ds: &DrawState) -> Option<u32> {
    (ds.key.depth_func.is_some() || ds.key.depth_write).then_some(ds.depth_max)
}

/// Whether the eight-fragment tail covers everything after the colour for `key` (the colour
/// sum and fog included: the lanes' secondary colours and fog factors are computed as the
/// general path computes them, then added and blended in the tail): no stencil test, logic op
/// or occlusion counting, and AVX2 present.
pub fn tail8_applies(key: &FragmentKey) -> bool {
    key.stencil.is_none() && key.logic_op.is_none() && !key.count_samples && simd::available()
}

/// The eight-fragment tail's blending for the draw's key.
fn tail_blend(ds: &DrawState) -> simd::TailBlend {
    match ds.key.blend {
        None => simd::TailBlend::None,
        Some(b) if b.is_add_one_one() => simd::TailBlend::AddOneOne,
        Some(b) if b.is_alpha_over() => simd::TailBlend::AlphaOver,
        Some(b) => simd::TailBlend::General(b, ds.uniforms.blend_color),
    }
}

/// The general path: every decision read from the key at run time.
pub fn span_general<'a>(
    ds: &'a DrawState,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    shade::<{ depth_mode::DYNAMIC }, false, false, false, false>(ds, tile, y, x0, x1, it)
}

/// The general path with every texture unit sampled eight pixels at a time (keys with
/// `simd_units`): the same texels, hence the same pictures.
pub fn span_sampled<'a>(
    ds: &'a DrawState,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    shade::<{ depth_mode::DYNAMIC }, false, false, true, false>(ds, tile, y, x0, x1, it)
}

/// The textured path: one unit on the fast 2D sampler (`TEX`), blending fixed by `BLEND`,
/// the colour mask by `FULL_MASK`; everything else read from the key (which must have
/// `fast_texture` of `TEX`'s layout, no stencil test and no logic op).
pub fn span_textured<'a, const TEX: u8, const BLEND: u8, const FULL_MASK: bool>(
    ds: &'a DrawState,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    shade_textured::<{ depth_mode::DYNAMIC }, FULL_MASK, false, TEX, BLEND>(ds, tile, y, x0, x1, it)
}

/// Two rows of a primitive: `y` (even) and `y + 1`, `rows[r]` the covered pixels `x0..x1`
/// of row `y + r` (empty when `x0 >= x1`; not both).
pub type RowPair = (i32, [(i32, i32); 2]);

/// Shades row pairs of one primitive in a tile (distinct rows: within a primitive no pixel is
/// covered twice, so their order does not matter). One call per primitive and tile, so that
/// what does not depend on the rows is prepared once (a tiny triangle has one to three pairs).
pub type PairFn = for<'a> fn(&'a DrawState, &mut Tile, &[RowPair], &Interpolants<'a>);

/// The rows of the pairs one by one, by the draw's span function.
fn pair_by_rows<'a>(ds: &'a DrawState, tile: &mut Tile, pairs: &[RowPair], it: &Interpolants<'a>) {
    for &(y, rows) in pairs {
        for (r, (x0, x1)) in (0..).zip(rows) {
            if x0 < x1 {
                (ds.span)(ds, tile, y + r, x0, x1, it);
            }
        }
    }
}

/// Runs the 4x2 blocks of a row pair (two whole quads each, from the even column at or left
/// of the first covered pixel): lanes 0..4 are columns `gx..gx + 4` of row `y`, lanes 4..8
/// the same columns of row `y + 1`. Each row's colour and depth are stepped from its own first
/// pixel, as on the row alone. `shade(gx, group)` gets the covered lanes' inputs when one of
/// them passes the depth test (the others change nothing: no stencil on these paths) and
/// answers the colour words and the lanes that passed every test, which are stored.
#[inline(always)]
fn for_each_block(
    ds: &DrawState,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants,
    mut shade: impl FnMut(i32, i32, &GroupInputs) -> Option<([u32; 8], u8)>,
) {
    // Unfogged draws step no fog coordinate.
    if lane_fog(ds).is_some() {
        blocks::<true>(ds, tile, pairs, it, &mut shade)
    } else {
        blocks::<false>(ds, tile, pairs, it, &mut shade)
    }
}

/// [`for_each_block`] for a fogged draw (`FOG`) or not.
#[inline(always)]
fn blocks<const FOG: bool>(
    ds: &DrawState,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants,
    shade: &mut impl FnMut(i32, i32, &GroupInputs) -> Option<([u32; 8], u8)>,
) {
    let depth_max = group_depth_max(ds);
    let fog = if FOG { lane_fog(ds) } else { None };
    // With the colour sum the secondary colour is stepped too (no constant shortcut).
    let colors = lane_colors(ds);
    // A constant primary colour (`Interpolants::constant_primary`: its steps are zero, so
    // every pixel has the first one's) leaves only z to step per pixel (unless fogged: then
    // the fog coordinate and 1/w are stepped too, by `SpanRun::next`); the lanes' depths are
    // then rounded and tested eight at a time, and the colour written to the lanes whole.
    let constant = (it.constant_primary && fog.is_none() && colors == 4).then(|| {
        let (y, rows) = pairs.first().copied().unwrap_or_default();
        let run = SpanRun::new(it, rows[0].0 as f64 + 0.5, y as f64 + 0.5, 4);
        [0, 1, 2, 3].map(|c| [run.color[c]; 8])
    });
    // With a constant colour every lane's inputs are written for each block (the colour
    // once): lanes outside a block's covered ones keep stale values, which nothing reads.
    let mut group = GroupInputs::EMPTY;
    if let Some(primary) = constant {
        group.primary = primary;
    }
    let mut lane_z = [0f64; 8];
    let mut stored = [0u32; 8];
    for &(y, rows) in pairs {
        let mut runs = [
            SpanRun::new(it, rows[0].0 as f64 + 0.5, y as f64 + 0.5, colors),
            SpanRun::new(it, rows[1].0 as f64 + 0.5, y as f64 + 1.5, colors),
        ];
        if FOG {
            for (r, run) in runs.iter_mut().enumerate() {
                let (xc0, yc) = (rows[r].0 as f64 + 0.5, y as f64 + 0.5 + r as f64);
                run.fog = Some(SpanRun::fog_at(it, xc0, yc));
            }
        }
        let covered = |r: usize| rows[r].0 < rows[r].1;
        let (first, end) = match (covered(0), covered(1)) {
            (true, true) => (rows[0].0.min(rows[1].0), rows[0].1.max(rows[1].1)),
            (true, false) => rows[0],
            (false, true) => rows[1],
            (false, false) => continue,
        };
        let mut z = [runs[0].z, runs[1].z];
        let mut gx = first & !1;
        while gx < end {
            let mut live = 0u8;
            if constant.is_some() {
                for (r, &(x0, x1)) in rows.iter().enumerate() {
                    let row = tile.index(gx, y + r as i32);
                    for j in (x0 - gx).clamp(0, 4)..(x1 - gx).clamp(0, 4) {
                        let (lane, j) = (4 * r + j as usize, j as usize);
                        // As `SpanRun::next` steps it.
                        lane_z[lane] = z[r];
                        z[r] += runs[r].dz;
                        stored[lane] = tile.depth[row + j];
                        group.dst[lane] = u32::from_le_bytes(tile.color[row + j]);
                        live |= 1 << lane;
                    }
                }
                (group.depth, group.pass) = match depth_max {
                    None => ([0; 8], live),
                    Some(max) => simd::depth8(&lane_z, &stored, live, max, ds.key.depth_func)
                        .unwrap_or_else(|| {
                            let mut depth = [0u32; 8];
                            let mut pass = 0u8;
                            for lane in (0..8).filter(|j| live & (1 << j) != 0) {
                                depth[lane] = depth_to_fixed(lane_z[lane], max);
                                let ok = depth_passes(ds, depth[lane], stored[lane]);
                                pass |= u8::from(ok) << lane;
                            }
                            (depth, pass)
                        }),
                };
            } else {
                // (Not `after`: a whole copy of `EMPTY` is a call to memset, and a lane's
                // secondary colour and fog are read only when it is live.)
                group.primary = GroupInputs::EMPTY.primary;
                group.depth = [0; 8];
                group.pass = 0;
                group.dst = [0; 8];
                for (r, &(x0, x1)) in rows.iter().enumerate() {
                    let row = tile.index(gx, y + r as i32);
                    for j in (x0 - gx).clamp(0, 4)..(x1 - gx).clamp(0, 4) {
                        let (lane, j) = (4 * r + j as usize, j as usize);
                        group.add(ds, tile, lane, row + j, runs[r].next::<FOG>(depth_max));
                        live |= 1 << lane;
                    }
                }
            }
            if group.pass != 0 {
                group.fog_factors(fog);
                if let Some((words, passed)) = shade(y, gx, &group) {
                    for lane in 0..8 {
                        if live & (1 << lane) != 0 {
                            let index = tile.index(gx + lane as i32 % 4, y + lane as i32 / 4);
                            store_lane(ds, tile, lane, index, &words, passed, &group.depth);
                        }
                    }
                }
            }
            gx += 4;
        }
    }
}

/// Window centre of lane `lane` of the block at column `gx` of the row pair from `y`.
#[inline(always)]
fn block_lane_centre(gx: i32, y: i32, lane: usize) -> (f64, f64) {
    let lane = lane as i32;
    ((gx + lane % 4) as f64 + 0.5, (y + lane / 4) as f64 + 0.5)
}

/// `span_textured`'s eight-lane perspective path on two rows at once, in 4x2 blocks (two
/// whole quads): the spans of small triangles are two or three pixels long, so a block holds
/// about as many fragments as two eight-pixel row groups, and its texture coordinates give
/// the quads' derivatives without evaluating other rows. Every value is computed as on the
/// rows one by one (`for_each_block`, texels by `Perspective8::texels_block`), so the
/// pixels are the same; affine primitives and keys without the eight-lane tail take the rows
/// one by one.
pub fn pair_textured<'a, const TEX: u8>(
    ds: &'a DrawState,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants<'a>,
) {
    let (Some(unit), Some(&(first_y, _))) = (ds.units.first(), pairs.first()) else {
        return pair_by_rows(ds, tile, pairs, it);
    };
    let q = &it.attrs[attr::TEX + 4 * unit.unit + 3];
    // Constant 1/w and q: the affine path of the rows (`FastUnit::affine`).
    let affine = it.inv_w.a == 0.0 && it.inv_w.b == 0.0 && q.a == 0.0 && q.b == 0.0;
    // The tail (prepared with the levels) exists where the eight-fragment tail applies.
    let tail = it.shared.levels.textured_tail;
    let sampler = match tail {
        Some(_) if !affine && it.coverage == 1.0 => Perspective8::block(unit, 0, it, first_y),
        _ => None,
    };
    let (Some(mut sampler), Some(tail)) = (sampler, tail) else {
        return pair_by_rows(ds, tile, pairs, it);
    };
    let mut sampler_y = first_y;
    for_each_block(ds, tile, pairs, it, |y, gx, group| {
        if y != sampler_y {
            // The same unit and levels as the first pair's: only the rows' planes move.
            if let Some(s) = Perspective8::block(unit, 0, it, y) {
                sampler = s;
            }
            sampler_y = y;
        }
        if let Some(shaded) = sampler.shaded_block(gx as f64 + 0.5, group, &tail) {
            return Some(shaded);
        }
        let mut tex = [[0f32; 8]; 4];
        if !sampler.texels_block(gx as f64 + 0.5, group.pass, &mut tex) {
            // Not affine: the fast unit samples one by one as the rows' fallback does.
            let f = FastUnit::new(unit, it, 0.5, y as f64 + 0.5);
            for lane in (0..8).filter(|j| group.pass & (1 << j) != 0) {
                let (x, yc) = block_lane_centre(gx, y, lane);
                let t = if TEX == tex_mode::FAST_RGB {
                    f.texel::<3>(it, x, yc)
                } else {
                    f.texel::<4>(it, x, yc)
                };
                for c in 0..4 {
                    tex[c][lane] = t[c];
                }
            }
        }
        simd::shade8(
            &tail,
            &group.primary,
            &tex,
            &group.dst,
            group.pass,
            &group.after,
        )
    });
}

/// [`span_sampled8`] on two rows at once, in 4x2 blocks (`for_each_block`): every unit
/// sampled by its block sampler (`Perspective8::texels_block`; one by one where it does not
/// apply), the cascade, then the eight-fragment tail. The same pixels as the rows one by one.
pub fn pair_sampled8<'a>(
    ds: &'a DrawState,
    tile: &mut Tile,
    pairs: &[RowPair],
    it: &Interpolants<'a>,
) {
    let Some(&(first_y, _)) = pairs.first() else {
        return;
    };
    if it.coverage != 1.0 {
        return pair_by_rows(ds, tile, pairs, it);
    }
    let Sampled8 {
        mut samplers,
        single,
        tail,
        mut by_unit,
    } = Sampled8::new(ds, it, first_y, true);
    let mut samplers_y = first_y;
    for_each_block(ds, tile, pairs, it, |y, gx, group| {
        if y != samplers_y {
            Sampled8::place_samplers(&mut samplers, ds, it, y, true);
            samplers_y = y;
        }
        for (k, unit) in ds.units.iter().enumerate() {
            let Some(out) = by_unit[unit.unit].as_mut() else {
                continue;
            };
            if samplers[k]
                .as_ref()
                .is_some_and(|p| p.texels_block(gx as f64 + 0.5, group.pass, out))
            {
                continue;
            }
            for lane in (0..8).filter(|j| group.pass & (1 << j) != 0) {
                let (x, yc) = block_lane_centre(gx, y, lane);
                let t = unit_texel(unit, it, x, yc);
                for c in 0..4 {
                    out[c][lane] = t[c];
                }
            }
        }
        sampled8_shade(ds, single, &tail, group, &by_unit)
    });
}

/// A specialised path for simple keys (no alpha test, stencil, blending or logic op): depth
/// mode and full colour mask fixed at compile time.
pub fn span_specialised<'a, const DEPTH: u8, const FULL_MASK: bool>(
    ds: &'a DrawState,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    shade::<DEPTH, FULL_MASK, true, false, false>(ds, tile, y, x0, x1, it)
}

/// [`span_specialised`] with fog: keys that are simple but for fog (a fogged, untextured,
/// unblended scene).
pub fn span_fogged<'a, const DEPTH: u8, const FULL_MASK: bool>(
    ds: &'a DrawState,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    shade::<DEPTH, FULL_MASK, true, false, true>(ds, tile, y, x0, x1, it)
}

/// Whether [`span_untextured8`] may shade a key: untextured, and after the primary colour only
/// the alpha test, the depth test, blending (any equation and factors) and the colour mask
/// apply.
pub fn untextured8_applies(key: &FragmentKey) -> bool {
    !key.texturing && tail8_applies(key)
}

/// Untextured spans eight fragments at a time for keys with [`untextured8_applies`]: the
/// primary colours enter the eight-fragment tail ([`simd::shade8`]) as replacing texels, so
/// the alpha test, blending, colour mask and writes run on eight at once with the general
/// path's arithmetic (the same pixels). Partly covered pixels take the general path.
pub fn span_untextured8<'a>(
    ds: &'a DrawState,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    if it.coverage != 1.0 {
        return span_general(ds, tile, y, x0, x1, it);
    }
    let row = tile.index(x0, y);
    let (xc0, yc) = (x0 as f64 + 0.5, y as f64 + 0.5);
    let mut run = SpanRun::new(it, xc0, yc, lane_colors(ds)).with_fog(ds, it, xc0, yc);
    let tail = tail8(ds, false, false, false);
    let depth_max = group_depth_max(ds);
    let fog = lane_fog(ds);
    let fogged = fog.is_some();
    let mut gx = x0;
    while gx < x1 {
        let n = ((x1 - gx) as usize).min(8);
        let base = row + (gx - x0) as usize;
        let mut group = GroupInputs::gather(ds, tile, base, 0..n, |_| {
            if fogged {
                run.next::<true>(depth_max)
            } else {
                run.next::<false>(depth_max)
            }
        });
        group.fog_factors(fog);
        let GroupInputs {
            primary,
            depth,
            pass,
            dst,
            after,
        } = group;
        if let Some((words, passed)) = simd::shade8(&tail, &primary, &primary, &dst, pass, &after) {
            store_group(ds, tile, base, 0..n, &words, passed, &depth);
        }
        gx += 8;
    }
}

/// Draws nothing (a key whose fragments change no buffer).
pub fn span_nothing(_: &DrawState, _: &mut Tile, _: i32, _: i32, _: i32, _: &Interpolants) {}

/// Whether [`span_sampled8`] may shade a key: every unit takes the eight-pixel sampler
/// (`simd_units`), and after the texture environment only the alpha test, the depth test,
/// blending (any equation and factors) and the colour mask apply.
pub fn sampled8_applies(key: &FragmentKey) -> bool {
    key.simd_units && tail8_applies(key)
}

/// Textured spans eight pixels at a time for keys with [`sampled8_applies`]: every unit
/// sampled by its eight-pixel sampler, the environment cascade per pixel, then the alpha test,
/// blending and colour mask of eight fragments at once ([`simd::shade8`] with the environment's
/// result as a replacing texel). The same arithmetic as the general path, so the same pixels.
pub fn span_sampled8<'a>(
    ds: &'a DrawState,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants<'a>,
) {
    let yc = y as f64 + 0.5;
    let row = tile.index(x0, y);
    let xc0 = x0 as f64 + 0.5;
    if it.coverage != 1.0 {
        return span_sampled(ds, tile, y, x0, x1, it);
    }
    let mut run = SpanRun::new(it, xc0, yc, lane_colors(ds)).with_fog(ds, it, xc0, yc);
    let fog = lane_fog(ds);
    let Sampled8 {
        mut samplers,
        single,
        tail,
        mut by_unit,
    } = Sampled8::new(ds, it, y, false);
    let depth_max = group_depth_max(ds);
    let mut gx = x0 & !1;
    while gx < x1 {
        let lo = (x0 - gx).max(0) as usize;
        let hi = ((x1 - gx) as usize).min(8);
        let first = (gx - x0) as isize;
        let base = (row as isize + first) as usize;
        let mut group = GroupInputs::gather(ds, tile, base, lo..hi, |_| {
            if fog.is_some() {
                run.next::<true>(depth_max)
            } else {
                run.next::<false>(depth_max)
            }
        });
        // Lanes failing the depth test change nothing (no stencil here): only passing lanes
        // are sampled.
        if group.pass == 0 {
            gx += 8;
            continue;
        }
        group.fog_factors(fog);
        for (k, unit) in ds.units.iter().enumerate() {
            if let Some(out) = by_unit[unit.unit].as_mut() {
                sampled_texels(samplers[k].as_mut(), unit, it, gx, yc, group.pass, out);
            }
        }
        if let Some((words, passed)) = sampled8_shade(ds, single, &tail, &group, &by_unit) {
            store_group(ds, tile, base, lo..hi, &words, passed, &group.depth);
        }
        gx += 8;
    }
}

/// One REPLACE or MODULATE unit: (`MODULATE`, the base format has colour, has alpha).
type SingleUnit = Option<(bool, bool, bool)>;

/// What the eight-lane paths of a [`sampled8_applies`] draw set up for a row or a row pair:
/// each unit's sampler (by index in `DrawState::units`), the tail, and each unit's texels of
/// the current group by unit number (as the cascade reads them).
struct Sampled8<'a> {
    samplers: [Option<Perspective8<'a>>; MAX_TEXTURE_UNITS],
    single: SingleUnit,
    tail: Tail8,
    by_unit: [Option<Texels8>; MAX_TEXTURE_UNITS],
}

impl<'a> Sampled8<'a> {
    /// For row `y`, or with `block` the 4x2 blocks of rows `y` and `y + 1`. (Inlined: built
    /// in place, not copied out, it costs nothing per row pair.)
    #[inline(always)]
    fn new(ds: &'a DrawState, it: &Interpolants<'a>, y: i32, block: bool) -> Sampled8<'a> {
        let mut samplers: [Option<Perspective8>; MAX_TEXTURE_UNITS] = Default::default();
        Self::place_samplers(&mut samplers, ds, it, y, block);
        let (single, tail) = sampled8_tail(ds);
        let mut by_unit = [None; MAX_TEXTURE_UNITS];
        for unit in &ds.units {
            by_unit[unit.unit] = Some([[0f32; 8]; 4]);
        }
        Sampled8 {
            samplers,
            single,
            tail,
            by_unit,
        }
    }

    /// Each unit's sampler for row `y`, or with `block` the 4x2 blocks of rows `y` and `y + 1`.
    #[inline(always)]
    fn place_samplers(
        samplers: &mut [Option<Perspective8<'a>>; MAX_TEXTURE_UNITS],
        ds: &'a DrawState,
        it: &Interpolants<'a>,
        y: i32,
        block: bool,
    ) {
        for (k, (slot, unit)) in samplers.iter_mut().zip(&ds.units).enumerate() {
            *slot = if block {
                Perspective8::block(unit, k, it, y)
            } else {
                Perspective8::new(unit, k, it, y)
            };
        }
    }
}

/// The eight-fragment tail of a [`sampled8_applies`] draw. With one unit under REPLACE or
/// MODULATE ([`SingleUnit`]) the environment itself runs eight fragments at a time in the
/// tail (with the base format's table: which of colour and alpha the texture has); otherwise
/// the cascade runs per fragment and enters the tail as a replacing texel.
fn sampled8_tail(ds: &DrawState) -> (SingleUnit, Tail8) {
    let single = match ds.units.as_slice() {
        [unit] if matches!(unit.env.mode, TexEnvMode::Replace | TexEnvMode::Modulate) => {
            let (has_color, has_alpha) = match unit.base {
                BaseFormat::Alpha => (false, true),
                BaseFormat::Luminance | BaseFormat::Rgb => (true, false),
                _ => (true, true),
            };
            Some((unit.env.mode == TexEnvMode::Modulate, has_color, has_alpha))
        }
        _ => None,
    };
    let tail = tail8(
        ds,
        single.is_some_and(|s| s.0),
        single.is_some_and(|s| !s.1),
        single.is_some_and(|s| !s.2),
    );
    (single, tail)
}

/// The environment (cascade or tail) and the tail of a group of a [`sampled8_applies`]
/// draw, given each unit's texels by unit number.
#[inline(always)]
fn sampled8_shade(
    ds: &DrawState,
    single: SingleUnit,
    tail: &Tail8,
    group: &GroupInputs,
    by_unit: &[Option<Texels8>; MAX_TEXTURE_UNITS],
) -> Option<([u32; 8], u8)> {
    let color = match single {
        Some(_) => group.primary,
        None => environment8(ds, &group.primary, by_unit),
    };
    // With one REPLACE/MODULATE unit `color` is the primary colour and the tail applies the
    // environment; otherwise it is the cascade's result, entering as a replacing texel.
    let tex = match single.and(ds.units.first()) {
        Some(unit) => by_unit[unit.unit].as_ref().unwrap_or(&color),
        None => &color,
    };
    simd::shade8(tail, &color, tex, &group.dst, group.pass, &group.after)
}

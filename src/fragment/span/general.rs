//! The per-fragment path in the specification's order (`finish_fragment`, `shade`,
//! `shade_textured`), which every span function runs for the fragments it does not take eight
//! at a time.

use super::*;

/// The per-fragment operations after texturing, in the specification's order: colour sum
/// (`secondary`: the interpolated secondary colour), fog (`fog_coord`), antialiasing
/// coverage, alpha test, stencil and depth tests with their updates, occlusion counting,
/// blending or logic op, colour mask; `z` is the fragment's window depth and `idx` its index
/// in `tile`. The const parameters are [`shade`]'s (`FOG` keeps fog on a `SIMPLE` path) and
/// `BLEND` fixes the blending ([`blend_mode`]).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(super) fn finish_fragment<
    const DEPTH: u8,
    const FULL_MASK: bool,
    const SIMPLE: bool,
    const FOG: bool,
    const BLEND: u8,
>(
    ds: &FragmentDraw,
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
    if !SIMPLE && (key.alpha_to_coverage || key.alpha_to_one) {
        // Multisample fragment operations (section 4.1.3), before the alpha test.
        if key.alpha_to_coverage && color[3].clamp(0.0, 1.0) <= u.coverage_alpha_ref {
            return;
        }
        if key.alpha_to_one {
            color[3] = 1.0;
        }
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
pub(super) fn shade<
    'a,
    const DEPTH: u8,
    const FULL_MASK: bool,
    const SIMPLE: bool,
    const SAMPLED: bool,
    const FOG: bool,
>(
    ds: &'a FragmentDraw,
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
    // Primary colour, then the secondary colour when the colour sum needs it.
    let colors = if !SIMPLE && (key.color_sum || key.texturing) {
        8
    } else {
        4
    };
    let mut run = SpanRun::new(it, x0, yc, colors).with_fog(ds);
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
    run.each_pixel(n, |i, run| {
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
        finish_fragment::<DEPTH, FULL_MASK, SIMPLE, FOG, { blend_mode::DYNAMIC }>(
            ds, tile, it, idx, fog_coord, color, secondary, z_here,
        );
    });
}

/// [`shade`] with the texturing and blending fixed at compile time ([`tex_mode`],
/// [`blend_mode`]) for `span_textured`: the same per-fragment pipeline in the specification's order: alpha test, stencil test, depth
/// test (with the stencil actions), blending or logic op, colour mask. `SIMPLE` paths have no
/// alpha test, stencil, blending or logic op (the key says so); their depth handling is fixed
/// by `DEPTH` and the colour mask by `FULL_MASK`. `TEX` and `BLEND` fix the texturing and
/// the blending ([`tex_mode`], [`blend_mode`]); the key must agree with them.
#[inline(always)]
pub(super) fn shade_textured<
    'a,
    const DEPTH: u8,
    const FULL_MASK: bool,
    const SIMPLE: bool,
    const TEX: u8,
    const BLEND: u8,
>(
    ds: &'a FragmentDraw,
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
                // The draw's tail, built once per tile and draw state when the levels were
                // prepared (the same arguments: the key's first unit and layout).
                let tail = match it.shared.levels.textured_tail {
                    Some(t) => t,
                    None => tail8(ds, f.modulate, false, TEX == tex_mode::FAST_RGB),
                };
                if let Some(sm) = &sampling {
                    // A flat sprite: every fragment of the primitive has the same inputs,
                    // prepared by its first span.
                    let constant = it.shared.steady.get_or_init(|| {
                        SpanRun::new(it, x0, yc, colors)
                            .with_fog(ds)
                            .constant_group(ds)
                    });
                    if let Some(c) = constant {
                        constant_groups::<TEX>(ds, tile, y, x0, x1, it, f, sm, &tail, c);
                        return;
                    }
                }
                let mut run = SpanRun::new(it, x0, yc, colors).with_fog(ds);
                // With zero steps for z, 1/w and the colour (a flat, facing primitive), every
                // pixel has the first pixel's values where they are evaluated (the first pixel
                // and the restart columns) and the second pixel's elsewhere (adding a zero
                // changes at most the sign of a zero, and only once).
                let steady = run.is_steady();
                let steady_values = if steady {
                    run.steady_values::<true>(Some(ds.depth_max))
                } else {
                    [([0f32; 4], 0u32, 0f32, None); 2]
                };
                // Almost always the two are the same bits (no value is -0): then one for all.
                let one_value = steady && same_bits(&steady_values[0], &steady_values[1]);
                let depth_max = group_depth_max(ds);
                let fog = lane_fog(ds);
                let fogged = fog.is_some();
                // Groups of eight lanes from `gx`; the perspective sampler needs groups that
                // start on an even column (quads), so its first group may begin one pixel
                // early with lane 0 not live.
                let mut gx = if perspective.is_some() { x0 & !1 } else { x0 };
                let mut group = GroupInputs::EMPTY;
                // A steady run's groups past its first pixel, when the evaluated and stepped
                // inputs are the same bits: every lane has them, set (and fogged) once; each
                // group only reads the stored colours and depths.
                let mut uniform = one_value.then(|| GroupInputs::uniform(steady_values[1], fog));
                while gx < x1 {
                    let lo = (x0 - gx).max(0) as usize;
                    let hi = ((x1 - gx) as usize).min(8);
                    let first = (gx - x0) as isize;
                    let base = (row as isize + first) as usize;
                    let g = match &mut uniform {
                        Some(u) if first + lo as isize >= 1 => {
                            u.retest(ds, tile, base, lo..hi);
                            &*u
                        }
                        _ => {
                            group.refill(ds, tile, base, lo..hi, |j| {
                                if steady {
                                    let i = first + j as isize;
                                    let evaluated = i == 0 || (gx + j as i32) % RESTART == 0;
                                    steady_values[usize::from(!evaluated)]
                                } else if fogged {
                                    run.next::<true>(depth_max)
                                } else {
                                    run.next::<false>(depth_max)
                                }
                            });
                            if group.pass != 0 {
                                group.fog_factors(fog);
                            }
                            &group
                        }
                    };
                    // Lanes failing the depth test change nothing (no stencil here): a group
                    // without a passing lane is not sampled, and only passing quads choose
                    // levels.
                    if g.pass == 0 {
                        gx += 8;
                        continue;
                    }
                    let GroupInputs {
                        primary,
                        depth,
                        pass,
                        dst,
                        after,
                    } = g;
                    let pass = *pass;
                    let x = gx as f64 + 0.5;
                    let live = pass;
                    // `shade8` always answers: AVX2 was detected above.
                    let shaded = match (&sampling, &mut perspective) {
                        (Some(sm), _) => {
                            simd::textured8(sm, x, hi, &tail, primary, dst, pass, after)
                        }
                        (None, Some(p)) => {
                            let mut tex = [[0f32; 8]; 4];
                            if p.texels_into(x, live, &mut tex) {
                                simd::shade8(&tail, primary, &tex, dst, pass, after)
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
                        simd::shade8(&tail, primary, &tex, dst, pass, after)
                    });
                    if let Some((words, passed)) = shaded {
                        store_group(ds, tile, base, lo..hi, &words, passed, depth);
                    }
                    gx += 8;
                }
                return;
            }
        }
    }
    let mut texel_buf = [[0f32; 4]; 8];
    let mut run = SpanRun::new(it, x0, yc, colors).with_fog(ds);
    run.each_pixel(n, |i, run| {
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
        finish_fragment::<DEPTH, FULL_MASK, SIMPLE, false, BLEND>(
            ds, tile, it, idx, fog_coord, color, secondary, z_here,
        );
    });
}

/// The eight-lane route of [`shade_textured`] for an affine span of a primitive whose
/// fragments all have the inputs of `c` (`SpanRun::constant_group`): per group only the
/// stored colours and the depth test are read (the steady shortcut's groups, from the span's
/// first pixel on: its evaluated inputs are the stepped ones' bits).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn constant_groups<const TEX: u8>(
    ds: &FragmentDraw,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants,
    f: &FastUnit,
    sm: &Sampling8,
    tail: &Tail8,
    c: &GroupInputs,
) {
    let row = tile.index(x0, y);
    let yc = y as f64 + 0.5;
    // Lanes from `hi` keep the last group's stored colours, which nothing reads.
    let mut dst = [0u32; 8];
    let mut gx = x0;
    while gx < x1 {
        let hi = ((x1 - gx) as usize).min(8);
        let base = row + (gx - x0) as usize;
        let mut pass = 0u8;
        for j in 0..hi {
            pass |= u8::from(depth_passes(ds, c.depth[j], tile.depth[base + j])) << j;
            dst[j] = u32::from_le_bytes(tile.color[base + j]);
        }
        if pass != 0 {
            let x = gx as f64 + 0.5;
            let shaded = simd::textured8(sm, x, hi, tail, &c.primary, &dst, pass, &c.after)
                .or_else(|| {
                    let tex = if TEX == tex_mode::FAST_RGB {
                        f.texels_scalar::<3>(it, x, yc, hi)
                    } else {
                        f.texels_scalar::<4>(it, x, yc, hi)
                    };
                    simd::shade8(tail, &c.primary, &tex, &dst, pass, &c.after)
                });
            if let Some((words, passed)) = shaded {
                store_group(ds, tile, base, 0..hi, &words, passed, &c.depth);
            }
        }
        gx += 8;
    }
}

//! Texture coordinates and their per-quad derivatives for one fragment (`unit_coords`),
//! sampling every unit, and the texture environment cascade (one fragment and eight).

use super::*;

/// Texture coordinates (s, t, r divided by q) of one unit at window point (x, y), in f64.
/// Under perspective the planes hold s/w ... q/w, and (s/w) / (q/w) is s/q: one division.
#[inline(always)]
pub(super) fn coords_at(it: &Interpolants, base: usize, x: f64, y: f64) -> [f64; 3] {
    let p = &it.attrs[base..base + 4];
    let q = p[3].at(x, y);
    [0, 1, 2].map(|k| p[k].at(x, y) / q)
}

/// The centre coordinate of the first pixel of the 2x2 quad (aligned to even window
/// coordinates) holding the pixel centred at `c`.
#[inline(always)]
pub(super) fn quad_origin(c: f64) -> f64 {
    ((c - 0.5) * 0.5).floor() * 2.0 + 0.5
}

/// Texture coordinates of one unit at the pixel centred at (x, y), with the screen
/// derivatives λ is computed from: finite differences over the pixel's 2x2 quad (section
/// 3.8.8 allows them; this is what hardware and Mesa do, so mipmap level choices agree). The
/// quads are aligned to even window coordinates; the x difference is taken along the quad's
/// upper row and the y difference along its left column, and all four pixels share them.
pub(super) fn unit_coords(
    it: &Interpolants,
    base: usize,
    x: f64,
    y: f64,
) -> ([f32; 3], [f32; 3], [f32; 3]) {
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
pub(super) fn texture_fragment(
    ds: &FragmentDraw,
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
pub(super) fn unit_texel(u: &TextureUnitDraw, it: &Interpolants, x: f64, y: f64) -> [f32; 4] {
    let (c, dx, dy) = unit_coords(it, attr::TEX + 4 * u.unit, x, y);
    u.texture.sample_grad(c, dx, dy, u.env.lod_bias)
}

/// The eight texels of unit `u` for the pixels centred at `gx + j + 0.5` on row `yc` (`gx`
/// even; lanes whose bit is clear in `live` are not needed): from its eight-pixel sampler, or
/// one by one as the general path samples them.
pub(super) fn sampled_texels(
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
pub(super) fn environment(
    ds: &FragmentDraw,
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
pub(super) fn environment8(
    ds: &FragmentDraw,
    primary: &Texels8,
    by_unit: &[Option<Texels8>; MAX_TEXTURE_UNITS],
) -> Texels8 {
    #[cfg(target_arch = "x86_64")]
    {
        if crate::common::cpu::available() {
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
pub(super) fn environment8_avx2(
    ds: &FragmentDraw,
    primary: &Texels8,
    by_unit: &[Option<Texels8>; MAX_TEXTURE_UNITS],
) -> Texels8 {
    use std::arch::x86_64::*;
    use texenv::{Avx8, Lanes};
    // MODULATE on every unit (the usual cascade of several units): `texenv::apply`'s
    // products on registers, without the compiled program's register file and dispatch.
    if ds
        .units
        .iter()
        .all(|u| u.env.mode == crate::common::values::TexEnvMode::Modulate)
    {
        return modulate8_avx2(ds, primary, by_unit);
    }
    // The draw's compiled cascade: the same bits (`fragment::cascade`).
    if let Some(program) = &ds.cascade {
        return program.run_avx2(primary, by_unit);
    }
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

/// [`environment8_avx2`] for a draw whose units are all `MODULATE`: the clamped primary
/// colour times each unit's texel where its base format has colour (R, G, B) and alpha (A),
/// as `texenv::apply` (the same f32 products in the same order).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn modulate8_avx2(
    ds: &FragmentDraw,
    primary: &Texels8,
    by_unit: &[Option<Texels8>; MAX_TEXTURE_UNITS],
) -> Texels8 {
    use std::arch::x86_64::*;
    use texenv::{Avx8, Lanes};
    // SAFETY: each array holds eight f32; unaligned loads and stores.
    let load = |a: &[f32; 8]| Avx8(unsafe { _mm256_loadu_ps(a.as_ptr()) });
    let mut color = [0, 1, 2, 3].map(|c| load(&primary[c]).clamp01());
    for u in &ds.units {
        let (has_color, has_alpha) = crate::fragment::bytenv::has_color_alpha(u.base);
        let ct = |c: usize| match &by_unit[u.unit] {
            Some(t) => load(&t[c]),
            None => Avx8::splat(0.0),
        };
        if has_color {
            for (c, v) in color.iter_mut().enumerate().take(3) {
                *v = v.mul(ct(c));
            }
        }
        if has_alpha {
            color[3] = color[3].mul(ct(3));
        }
    }
    let mut out = [[0f32; 8]; 4];
    for (o, c) in out.iter_mut().zip(color) {
        // SAFETY: eight f32; unaligned store.
        unsafe { _mm256_storeu_ps(o.as_mut_ptr(), c.0) };
    }
    out
}

#[inline(always)]
pub(super) fn environment8_arrays(
    ds: &FragmentDraw,
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

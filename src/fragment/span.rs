//! Span functions: shade the covered pixels `x0..x1` of one row of a tile. The general path
//! reads the key at run time; specialised paths are the same code monomorphised on the key,
//! so a disabled stage is compiled out instead of skipped by a branch.

use super::blend::blend;
use super::key::Uniforms;
use super::texenv::{self, CombineInputs};
use crate::api::convert::{CompareFunc, StencilOp};
use crate::framebuffer::Tile;
use crate::raster::setup::Plane;
use crate::state::snapshot::attr;
use crate::state::DrawState;

/// The interpolants of one primitive for the fragment stage.
#[derive(Clone, Copy, Debug)]
pub struct Interpolants<'a> {
    /// Window z in [0, 1].
    pub z: Plane,
    /// 1/w_clip, for perspective correction.
    pub inv_w: Plane,
    /// Attribute planes: attribute/w when `perspective`, else the attribute itself.
    pub attrs: &'a [Plane],
    pub perspective: bool,
    /// Antialiasing coverage, multiplied into the alpha after fog (1 for aliased primitives).
    pub coverage: f32,
}

/// Shades pixels `x0..x1` of row `y` (window coordinates, inside `tile`).
pub type SpanFn = fn(&DrawState, &mut Tile, i32, i32, i32, &Interpolants);

/// Converts window z to a stored depth value (round to nearest, clamped).
#[inline(always)]
pub fn depth_to_fixed(z: f64, depth_max: u32) -> u32 {
    let v = z * depth_max as f64 + 0.5;
    if v >= depth_max as f64 {
        depth_max
    } else if v > 0.0 {
        v as u32
    } else {
        0
    }
}

/// Converts a colour component to 8 bits (section 2.14.9: round to nearest after clamping).
#[inline(always)]
pub fn color_to_u8(c: f32) -> u8 {
    let v = c * 255.0 + 0.5;
    if v >= 255.0 {
        255
    } else if v > 0.0 {
        v as u8
    } else {
        0
    }
}

/// Depth handling chosen at compile time: `DYNAMIC` reads the key, others are fixed.
pub mod depth_mode {
    pub const DYNAMIC: u8 = 0;
    pub const NONE: u8 = 1;
    pub const LESS_WRITE: u8 = 2;
    pub const LEQUAL_WRITE: u8 = 3;
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

/// The per-fragment pipeline in the specification's order: alpha test, stencil test, depth
/// test (with the stencil actions), blending or logic op, colour mask. `SIMPLE` paths have no
/// alpha test, stencil, blending or logic op (the key says so); their depth handling is fixed
/// by `DEPTH` and the colour mask by `FULL_MASK`.
#[inline(always)]
fn shade<const DEPTH: u8, const FULL_MASK: bool, const SIMPLE: bool>(
    ds: &DrawState,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants,
) {
    let key = &ds.key;
    let u = &ds.uniforms;
    let yc = y as f64 + 0.5;
    let row = tile.index(x0, y);
    let n = (x1 - x0) as usize;
    let xc0 = x0 as f64 + 0.5;
    let mut z = it.z.at(xc0, yc);
    let dz = it.z.a;
    let mut inv_w = it.inv_w.at(xc0, yc) as f32;
    let dinv_w = it.inv_w.a as f32;
    // Primary colour, then the secondary colour when the colour sum needs it.
    let na = if !SIMPLE && (key.color_sum || key.texturing) {
        8
    } else {
        4
    };
    let mut attr = [0f32; 8];
    let mut dattr = [0f32; 8];
    for c in 0..na {
        attr[c] = it.attrs[c].at(xc0, yc) as f32;
        dattr[c] = it.attrs[c].a as f32;
    }
    for i in 0..n {
        let idx = row + i;
        let w = if it.perspective { 1.0 / inv_w } else { 1.0 };
        let mut color = [attr[0] * w, attr[1] * w, attr[2] * w, attr[3] * w];
        if !SIMPLE && key.texturing {
            color = texture_fragment(ds, it, x0 as f64 + i as f64 + 0.5, yc, color);
        }
        if !SIMPLE && key.color_sum {
            for c in 0..3 {
                color[c] = color[c].clamp(0.0, 1.0) + attr[4 + c] * w;
            }
        }
        if !SIMPLE && key.fog.is_some() {
            if let Some(f) = &ds.fog {
                let xc = x0 as f64 + i as f64 + 0.5;
                let p = &it.attrs[attr::FOG];
                let c = if it.perspective {
                    (p.at(xc, yc) / it.inv_w.at(xc, yc)) as f32
                } else {
                    p.at(xc, yc) as f32
                };
                let k = f.factor(c);
                for ch in 0..3 {
                    color[ch] = k * color[ch].clamp(0.0, 1.0) + (1.0 - k) * f.color[ch];
                }
            }
        }
        if it.coverage != 1.0 {
            color[3] = color[3].clamp(0.0, 1.0) * it.coverage;
        }
        let z_here = z;
        // Step the interpolants now, so that every `continue` below moves to the next pixel.
        z += dz;
        inv_w += dinv_w;
        for c in 0..na {
            attr[c] += dattr[c];
        }
        if !SIMPLE {
            if let Some(f) = key.alpha_func {
                if !f.test(color[3].clamp(0.0, 1.0), u.alpha_ref) {
                    continue;
                }
            }
        }
        let depth = depth_to_fixed(z_here, ds.depth_max);
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
                    continue;
                } else if depth_pass {
                    st.depth_pass
                } else {
                    st.depth_fail
                };
                tile.stencil[idx] = apply_stencil_op(action, old, u);
            }
        }
        if !depth_pass {
            continue;
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
        let mut rgba = color.map(color_to_u8);
        if !SIMPLE {
            let dst = tile.color[idx];
            if let Some(op) = key.logic_op {
                for c in 0..4 {
                    rgba[c] = op.apply(rgba[c], dst[c]);
                }
            } else if let Some(b) = &key.blend {
                rgba = blend(b, rgba, dst, u.blend_color);
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
}

/// Texture coordinates (s, t, r divided by q) of one unit at window point (x, y), in f64.
#[inline(always)]
fn coords_at(it: &Interpolants, base: usize, x: f64, y: f64) -> [f64; 3] {
    let p = &it.attrs[base..base + 4];
    let w = if it.perspective {
        it.inv_w.at(x, y)
    } else {
        1.0
    };
    let q = p[3].at(x, y) / w;
    [0, 1, 2].map(|k| p[k].at(x, y) / w / q)
}

/// Texture coordinates of one unit at the pixel centred at (x, y), with the screen
/// derivatives λ is computed from: finite differences over the pixel's 2x2 quad (section
/// 3.8.8 allows them; this is what hardware and Mesa do, so mipmap level choices agree). The
/// quads are aligned to even window coordinates; the x difference is taken along the quad's
/// upper row and the y difference along its left column, and all four pixels share them.
fn unit_coords(it: &Interpolants, base: usize, x: f64, y: f64) -> ([f32; 3], [f32; 3], [f32; 3]) {
    let c = coords_at(it, base, x, y);
    let qx = (x - 0.5).div_euclid(2.0) * 2.0 + 0.5;
    let qy = (y - 0.5).div_euclid(2.0) * 2.0 + 0.5;
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
    let primary = primary.map(|c| c.max(0.0).min(1.0));
    let mut texels: [Option<[f32; 4]>; 8] = [None; 8];
    for u in &ds.units {
        let (c, dx, dy) = unit_coords(it, attr::TEX + 4 * u.unit, x, y);
        texels[u.unit] = Some(u.texture.sample_grad(c, dx, dy, u.env.lod_bias));
    }
    let inputs = CombineInputs {
        primary,
        texels: &texels,
    };
    let mut color = primary;
    for u in &ds.units {
        let ct = texels[u.unit].unwrap_or([0.0; 4]);
        color = texenv::apply(&u.env, u.base, u.unit, color, ct, &inputs);
    }
    color
}

/// The general path: every decision read from the key at run time.
pub fn span_general(ds: &DrawState, tile: &mut Tile, y: i32, x0: i32, x1: i32, it: &Interpolants) {
    shade::<{ depth_mode::DYNAMIC }, false, false>(ds, tile, y, x0, x1, it)
}

/// A specialised path for simple keys (no alpha test, stencil, blending or logic op): depth
/// mode and full colour mask fixed at compile time.
pub fn span_specialised<const DEPTH: u8, const FULL_MASK: bool>(
    ds: &DrawState,
    tile: &mut Tile,
    y: i32,
    x0: i32,
    x1: i32,
    it: &Interpolants,
) {
    shade::<DEPTH, FULL_MASK, true>(ds, tile, y, x0, x1, it)
}

/// Draws nothing (a key whose fragments change no buffer).
pub fn span_nothing(_: &DrawState, _: &mut Tile, _: i32, _: i32, _: i32, _: &Interpolants) {}

//! Span functions: shade the covered pixels `x0..x1` of one row of a tile. The general path
//! reads the key at run time; specialised paths are the same code monomorphised on the key,
//! so a disabled stage is compiled out instead of skipped by a branch.
//!
//! A map for reading (`fragment/cache.rs` picks one row function and, for some keys, one
//! two-row function per draw):
//! - per fragment, in the specification's order: [`span_general`] (every key), its
//!   monomorphised forms [`span_specialised`] and [`span_fogged`] (whose fogged fragments
//!   [`span_fogged8`] finishes eight at a time with AVX2), and [`span_sampled`]
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

use std::cell::OnceCell;

use super::blend::{blend, blend_alpha_over};
use super::key::{FragmentKey, StencilKey, Uniforms};
use super::texenv::{self, CombineInputs};
use crate::common::attr;
use crate::common::limits::MAX_TEXTURE_UNITS;
use crate::common::values::{CompareFunc, StencilOp, TexEnvMode};
use crate::fragment::draw::{FragmentDraw, TextureUnitDraw};
use crate::fragment::fog::FogDraw;
use crate::fragment::plane::Plane;
use crate::fragment::simd::{self, After8, Sampling8, Tail8};
use crate::framebuffer::Tile;
use crate::texture::format::BaseFormat;
use crate::texture::sample::{FastLevel, LevelPlan, LodSelect};
use crate::texture::simd::{self as texture_simd, Level8, Texels8};

use crate::common::fixed::{color4_to_u8, depth_to_fixed};

mod affine;
mod coords;
mod flat;
mod fogged;
mod general;
mod lanes;
mod paths;
mod perspective8;
mod rows8;
mod tail;
pub use affine::*;
use coords::*;
use flat::*;
pub use fogged::*;
use general::*;
use lanes::*;
pub use paths::*;
use perspective8::*;
use rows8::*;
pub use tail::*;

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
    /// span that needs it and read in place by the others (a copy per span cost more than
    /// the span's set-up arithmetic for small sprites).
    pub fast: OnceCell<AffineSpan<'a>>,
    /// The eight-lane inputs every fragment of the primitive has, when its depth, 1/w,
    /// colour and fog planes are constant (a flat sprite): prepared by the first span of the
    /// eight-lane textured route, `None` when they are not (`SpanRun::constant_group`).
    steady: OnceCell<Option<GroupInputs>>,
    /// The draw's texture levels prepared for the eight-pixel filter.
    pub levels: &'a UnitLevels<'a>,
    /// The polygon stipple pattern of a stippled polygon (`RasterDraw::polygon_stipple`: row
    /// `y mod 32`, the bit of column `x mod 32` at `1 << (31 - x mod 32)`), which the row-pair
    /// functions apply as a lane mask ([`stipple_block`]); `None` for everything else.
    pub stipple: Option<&'a [u32; 32]>,
}

impl<'a> PrimitiveShared<'a> {
    pub fn new(levels: &'a UnitLevels<'a>) -> PrimitiveShared<'a> {
        PrimitiveShared {
            fast: OnceCell::new(),
            steady: OnceCell::new(),
            levels,
            stipple: None,
        }
    }

    /// The same, for a polygon stippled by `pattern` (when it is `Some`).
    pub fn with_stipple(self, pattern: Option<&'a [u32; 32]>) -> PrimitiveShared<'a> {
        PrimitiveShared {
            stipple: pattern,
            ..self
        }
    }
}

/// Every level of each unit's texture prepared for the eight-pixel filter ([`Level8`]; `None`
/// where a level does not take it), by the unit's index in `FragmentDraw::units`. Prepared once
/// per tile and draw state ([`UnitLevels::prepare`]) instead of in every span: the spans of
/// small triangles are a few pixels long. Empty (and not allocated) for draws without
/// eight-pixel samplers.
#[derive(Clone, Debug, Default)]
pub struct UnitLevels<'a> {
    /// Each face's levels (one face, or a cube map's six from `first[k]`).
    units: Vec<[Option<Level8<'a>>; MAX_FAST_LEVELS]>,
    /// The index in `units` of each unit's first face, and its face count.
    first: [(usize, usize); MAX_TEXTURE_UNITS],
    /// `pair_textured`'s tail for the draw (one REPLACE/MODULATE unit on the fast 2D path,
    /// fragments finishing eight at a time), built once here instead of per row pair.
    textured_tail: Option<Tail8>,
}

impl<'a> UnitLevels<'a> {
    /// Replaces the table with the levels of `ds`'s units (none unless the draw's key has
    /// `simd_units`, which the eight-pixel samplers require).
    pub fn prepare(&mut self, ds: &'a FragmentDraw) {
        self.units.clear();
        self.first = [(0, 0); MAX_TEXTURE_UNITS];
        self.textured_tail = None;
        if !ds.key.simd_units || !crate::common::cpu::available() {
            return;
        }
        if let (Some(layout), Some(unit)) = (ds.key.fast_texture, ds.units.first()) {
            if tail8_applies(&ds.key) {
                let modulate = unit.env.mode == TexEnvMode::Modulate;
                let rgb = layout == super::key::FastTexture::Rgb;
                self.textured_tail = Some(tail8(ds, modulate, false, rgb));
            }
        }
        for (k, unit) in ds.units.iter().enumerate() {
            let tex = &unit.texture;
            let (wrap, base) = (tex.wrap_st(), tex.base_format());
            let faces = tex.face_count();
            self.first[k] = (self.units.len(), faces);
            for face in 0..faces {
                let mut levels = [None; MAX_FAST_LEVELS];
                for (l, level) in levels.iter_mut().enumerate().take(tex.level_count()) {
                    *level = tex
                        .face_fast_level(face, l)
                        .and_then(|f| Level8::new(&f, wrap, base));
                }
                self.units.push(levels);
            }
        }
    }

    /// The faces of the unit at index `k` of the draw's units (one, or a cube map's six), when
    /// the table was prepared.
    #[inline(always)]
    fn faces(&self, k: usize) -> Option<&[[Option<Level8<'a>>; MAX_FAST_LEVELS]]> {
        let &(first, count) = self.first.get(k)?;
        self.units
            .get(first..first + count)
            .filter(|f| !f.is_empty())
    }
}

/// Shades pixels `x0..x1` of row `y` (window coordinates, inside `tile`).
pub type SpanFn = for<'a> fn(&'a FragmentDraw, &mut Tile, i32, i32, i32, &Interpolants<'a>);

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

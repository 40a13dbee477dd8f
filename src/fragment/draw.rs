//! The fragment stage's part of a draw's frozen state: what the span functions read.

use super::cascade::Program;
use super::fog::FogDraw;
use super::key::{FragmentKey, Uniforms};
use super::span::{CoveredFn, PairFn, SpanFn};
use super::texenv::TexEnv;
use crate::texture::format::BaseFormat;
use crate::texture::sample::{BoundTexture, LodSelect};

/// One texture unit that takes part in a draw: it has an enabled, complete texture.
#[derive(Clone, Debug)]
pub struct TextureUnitDraw {
    pub unit: usize,
    pub texture: BoundTexture,
    /// Base format as the environment sees it (depth textures per `GL_DEPTH_TEXTURE_MODE`).
    pub base: BaseFormat,
    pub env: TexEnv,
    /// The texture's level-of-detail selection with this unit's bias, gathered once per draw.
    pub lod: LodSelect,
    /// The level and filter when they do not depend on λ (`plan_without_lambda`).
    pub fixed_plan: Option<(usize, bool)>,
}

/// The fragment stage's frozen state of one draw (built by `state::snapshot`).
#[derive(Clone, Debug)]
pub struct FragmentDraw {
    /// Texture units in use, in unit order (empty: no texturing).
    pub units: Vec<TextureUnitDraw>,
    /// Fog, when enabled (the mode is in the key; these are its parameters).
    pub fog: Option<FogDraw>,
    /// The largest stored depth value.
    pub depth_max: u32,
    pub key: FragmentKey,
    pub uniforms: Uniforms,
    /// The fragment function chosen for `key`.
    pub span: SpanFn,
    /// The function that shades the rows of a triangle together, for keys that have one.
    pub span_pair: Option<PairFn>,
    /// The function that shades a row of pixels with a coverage each (antialiased lines),
    /// for keys that have one; otherwise each such pixel is a span of its own.
    pub span_covered: Option<CoveredFn>,
    /// The units' environments compiled for the eight-lane cascade (`None` without units).
    pub cascade: Option<Program>,
}

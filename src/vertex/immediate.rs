//! The vertex record of immediate mode (`ImmVertex`, the batch of recorded vertices), the
//! integer-to-float conversions of table 2.6, and the lanes lit together at `glEnd`. The entry
//! points (`glBegin`/`glEnd`, `glVertex*`, the current values, `glRect*`) are in
//! `state/immediate.rs`.

use glam::{Vec3, Vec4};

use crate::common::limits;
use crate::common::values::PrimitiveMode;
use crate::vertex::lighting::{LitLanes, VertexLanes};

/// One vertex as specified: object position plus the current values at `glVertex` time; with
/// lighting on, the colours become the lit colours at `glEnd` (see
/// [`ImmediateBatch::unlit_from`]).
#[derive(Clone, Copy, Debug)]
pub struct ImmVertex {
    pub position: Vec4,
    pub color: Vec4,
    pub secondary_color: Vec4,
    /// Back-face primary and secondary colours (two-sided lighting; else equal to the front).
    pub back_colors: [Vec4; 2],
    pub normal: Vec3,
    pub texcoords: [Vec4; limits::MAX_TEXTURE_UNITS],
    pub fog_coord: f32,
    pub edge_flag: bool,
}

/// The vertices recorded between `glBegin` and `glEnd`.
#[derive(Clone, Debug)]
pub struct ImmediateBatch {
    pub mode: PrimitiveMode,
    pub vertices: Vec<ImmVertex>,
    /// With lighting on, vertices from this index on are recorded unlit (their colours are
    /// the current ones) and lit together at `glEnd`, eight at a time; `None` when each
    /// vertex is lit at `glVertex` (lighting off, or a `glMaterial` came inside the batch).
    pub unlit_from: Option<usize>,
}

// Table 2.6: conversion of integer colour and normal components to floating point.
pub(crate) fn norm_u8(c: u8) -> f32 {
    c as f32 / 255.0
}
pub(crate) fn norm_i8(c: i8) -> f32 {
    (2.0 * c as f32 + 1.0) / 255.0
}
pub(crate) fn norm_u16(c: u16) -> f32 {
    c as f32 / 65535.0
}
pub(crate) fn norm_i16(c: i16) -> f32 {
    (2.0 * c as f32 + 1.0) / 65535.0
}
pub(crate) fn norm_u32(c: u32) -> f32 {
    (c as f64 / 4294967295.0) as f32
}
pub(crate) fn norm_i32(c: i32) -> f32 {
    ((2.0 * c as f64 + 1.0) / 4294967295.0) as f32
}

/// Vertices of independent primitives drawn together while a batch is still open.
pub(crate) const BATCH_PIECE: usize = 4096;

/// Vertices lit together at `glEnd` (a batch's last few one by one).
pub(crate) const LIGHT_LANES: usize = 8;

/// The lighting inputs of `N` recorded (unlit) vertices.
pub(crate) fn lanes_of<const N: usize>(verts: &[ImmVertex]) -> VertexLanes<N> {
    let mut l = VertexLanes {
        position: [[0.0; N]; 4],
        normal: [[0.0; N]; 3],
        color: [[0.0; N]; 4],
    };
    for (j, v) in verts.iter().enumerate().take(N) {
        for c in 0..4 {
            l.position[c][j] = v.position[c];
            l.color[c][j] = v.color[c];
        }
        for c in 0..3 {
            l.normal[c][j] = v.normal[c];
        }
    }
    l
}

pub(crate) fn store_lit<const N: usize>(verts: &mut [ImmVertex], lit: &LitLanes<N>) {
    let color = |c: &[[f32; N]; 4], j: usize| Vec4::new(c[0][j], c[1][j], c[2][j], c[3][j]);
    for (j, v) in verts.iter_mut().enumerate().take(N) {
        v.color = color(&lit.front[0], j);
        v.secondary_color = color(&lit.front[1], j);
        v.back_colors = [color(&lit.back[0], j), color(&lit.back[1], j)];
    }
}

//! The draw driver: a batch of vertices through the pipeline, from transform (`vertex`) through
//! assembly, clipping, culling and the viewport (`primitive`) to binning (`raster`).

use crate::common::values::{PolygonMode, PrimitiveMode};
use crate::primitive::assemble::{self, Primitive};
use crate::primitive::clip::{clip_line, clip_polygon, point_visible, ClipVertex};
use crate::primitive::cull::{is_culled, is_front, signed_area2, triangle_area2};
use crate::primitive::viewport::WindowVertex;
use crate::primitive::viewport::{guard_band_windows, to_window};
use crate::raster::{line, point, tri};
use crate::state::{Context, DrawState};
use crate::vertex::immediate::ImmVertex;
use crate::vertex::{
    copy_provoking_colors, transform, use_back_colors, PARALLEL_TRANSFORM_MIN, TRANSFORM_CHUNK,
};
use std::sync::Arc;

impl Context {
    /// Draws a batch of vertices of one primitive mode.
    pub(crate) fn draw_vertices(&mut self, mode: PrimitiveMode, verts: &[ImmVertex]) {
        if verts.is_empty() {
            return;
        }
        if self.select.mode != crate::common::values::RenderMode::Render {
            return self.select_feedback_vertices(mode, verts);
        }
        let ds = self.snapshot();
        if ds.tile.draw_rect.is_empty() || ds.tile.fragment.key.writes_nothing() {
            return;
        }
        // Reuse the clip-space buffer across draws: large batches would otherwise fault in
        // fresh pages every frame. Every element is overwritten below (in place: a clip
        // vertex is 264 bytes), so only elements beyond the old length are initialised.
        let mut clip = std::mem::take(&mut self.clip_buffer);
        clip.resize(verts.len(), ClipVertex::ZERO);
        // Filled one-sided polygons whose vertices lie in the guard band (`in_guard_band`)
        // need no clipping, only the window positions: each vertex's is computed once here,
        // not once per triangle that shares it (a strip's vertex belongs to three).
        let mut windows = std::mem::take(&mut self.window_buffer);
        windows.clear();
        let multisample = self.framebuffer.samples > 1;
        let shared = ds.tile.raster.polygon_mode == [PolygonMode::Fill; 2]
            && !ds.vertex.two_sided
            && !matches!(
                mode,
                PrimitiveMode::Points
                    | PrimitiveMode::Lines
                    | PrimitiveMode::LineLoop
                    | PrimitiveMode::LineStrip
            );
        // A multisample framebuffer takes each sample's window positions in its own pass.
        let shared_windows = shared && !multisample;
        // Large batches are transformed on the worker threads too (each vertex independently,
        // results in order, so the output does not depend on the thread count).
        match &self.pool {
            Some(pool)
                if verts.len() >= PARALLEL_TRANSFORM_MIN && pool.current_num_threads() > 1 =>
            {
                use rayon::prelude::*;
                pool.install(|| {
                    clip.par_chunks_mut(TRANSFORM_CHUNK)
                        .zip(verts.par_chunks(TRANSFORM_CHUNK))
                        .for_each(|(c, v)| transform::to_clip_batch(&ds.vertex, v, c));
                    if shared_windows {
                        windows.resize(clip.len(), None);
                        windows
                            .par_chunks_mut(TRANSFORM_CHUNK)
                            .zip(clip.par_chunks(TRANSFORM_CHUNK))
                            .for_each(|(w, c)| guard_band_windows(&ds.viewport, c, w));
                    }
                });
            }
            _ => {
                transform::to_clip_batch(&ds.vertex, verts, &mut clip);
                if shared_windows {
                    windows.resize(clip.len(), None);
                    guard_band_windows(&ds.viewport, &clip, &mut windows);
                }
            }
        }
        if multisample {
            self.draw_sample_passes(&ds, mode, &clip, shared, &mut windows);
        } else {
            self.draw_clipped(&ds, mode, &clip, shared_windows.then_some(&windows[..]));
        }
        self.clip_buffer = clip;
        self.window_buffer = windows;
    }

    /// Draws the primitives of `clip` once per sample of the multisample framebuffer, each
    /// pass with the viewport shifted so that the pixel centres the rasterizer tests fall on
    /// the sample's position, into that sample's plane of tiles. Samples outside the sample
    /// coverage mask get no pass. With `GL_MULTISAMPLE` off every sample gets the unshifted
    /// fragments (section 3.2.1: single-sample rasterization, values to every sample).
    fn draw_sample_passes(
        &mut self,
        ds: &Arc<DrawState>,
        mode: PrimitiveMode,
        clip: &[ClipVertex],
        shared: bool,
        windows: &mut Vec<Option<WindowVertex>>,
    ) {
        let passes = match &self.sample_passes {
            Some(p) if Arc::ptr_eq(&p.base, ds) => p.passes.clone(),
            _ => {
                let p = SamplePasses::new(
                    ds,
                    &self.multisample,
                    self.framebuffer.samples,
                    self.force_general_path,
                );
                let passes = p.passes.clone();
                self.sample_passes = Some(p);
                passes
            }
        };
        for (sample, pass) in &passes {
            if shared {
                windows.clear();
                windows.resize(clip.len(), None);
                guard_band_windows(&pass.viewport, clip, windows);
            }
            self.scene.set_sample_plane(*sample);
            self.draw_clipped(pass, mode, clip, shared.then_some(&windows[..]));
        }
        self.scene.set_sample_plane(0);
    }

    /// Assembles, clips and bins the primitives of `clip`. `windows`, when given, holds each
    /// vertex's window position (`None` outside the guard band); only filled one-sided
    /// polygons take it.
    fn draw_clipped(
        &mut self,
        ds: &Arc<DrawState>,
        mode: PrimitiveMode,
        clip: &[ClipVertex],
        windows: Option<&[Option<WindowVertex>]>,
    ) {
        let n_attrs = ds.tile.attr_count;
        let clip_attrs = ds.clip_attr_count;
        let user = &ds.viewport.clip_planes;
        let mut poly = Vec::with_capacity(16);
        let mut scratch = Vec::with_capacity(16);
        let mut win = Vec::with_capacity(16);
        let mut xy = Vec::with_capacity(16);
        // Line stipple: the counter restarts with each independent segment (GL_LINES) and
        // runs on along a strip or loop (section 3.4.2).
        let mut stipple_counter = 0u32;
        let independent_lines = mode == PrimitiveMode::Lines;
        let edge_flags = assemble::uses_edge_flags(mode);
        let mut prims = std::mem::take(&mut self.primitive_buffer);
        assemble::assemble_into(mode, clip.len(), ds.provoking, &mut prims);
        if mode == PrimitiveMode::Quads
            && (self.list_executing() || clip.iter().any(|v| !point_visible(v, user)))
        {
            // As Mesa does for quads from a display list (compiled into triangles) and for a
            // batch that needs clipping; the reference pictures are its.
            assemble::split_quads_through_1_3(&mut prims);
        }
        for &prim in &prims {
            if self.scene.is_full() {
                self.flush_scene();
            }
            self.flush_in_background();
            let state = self.scene.add_state(&ds.tile);
            match prim {
                Primitive::Point(i) => {
                    if point_visible(&clip[i], user) {
                        let w = to_window(&ds.viewport, &clip[i]);
                        let size = point::derived_size(&ds.tile.raster, clip[i].eye);
                        point::bin_point(
                            &ds.tile,
                            state,
                            &w,
                            size,
                            0.0,
                            &clip[i].attrs[..n_attrs],
                            &mut self.scene,
                        );
                    }
                }
                Primitive::Line { v, provoking } => {
                    let (mut a, mut b) = (clip[v[0]], clip[v[1]]);
                    if ds.tile.flat {
                        copy_provoking_colors(&ds.vertex, &mut a, &clip[provoking]);
                        copy_provoking_colors(&ds.vertex, &mut b, &clip[provoking]);
                    }
                    if independent_lines {
                        stipple_counter = 0;
                    }
                    if let Some((a, b)) = clip_line(&a, &b, user, clip_attrs) {
                        let wa = to_window(&ds.viewport, &a);
                        let wb = to_window(&ds.viewport, &b);
                        line::bin_line(
                            &ds.tile,
                            state,
                            [&wa, &wb],
                            [&a.attrs[..n_attrs], &b.attrs[..n_attrs]],
                            0.0,
                            &mut stipple_counter,
                            &mut self.scene,
                        );
                    }
                }
                Primitive::Triangle {
                    v,
                    provoking,
                    edges,
                } => {
                    let tri = [&clip[v[0]], &clip[v[1]], &clip[v[2]]];
                    let inside = windows.and_then(|w| {
                        Some([w[v[0]].as_ref()?, w[v[1]].as_ref()?, w[v[2]].as_ref()?])
                    });
                    if let Some(w) = inside {
                        // Filled and inside the guard band (the common case): no clipping, no
                        // copies.
                        let area = triangle_area2([w[0].xy, w[1].xy, w[2].xy]) as i128;
                        if area == 0 || is_culled(ds.cull, is_front(area, ds.front_face)) {
                            continue;
                        }
                        // Flat shading takes the provoking vertex's colours only; texture and
                        // fog coordinates still vary across the triangle.
                        let flat;
                        let verts = if ds.tile.flat {
                            let mut copies = [*tri[0], *tri[1], *tri[2]];
                            for v in copies.iter_mut() {
                                copy_provoking_colors(&ds.vertex, v, &clip[provoking]);
                            }
                            flat = copies;
                            [&flat[0], &flat[1], &flat[2]]
                        } else {
                            tri
                        };
                        tri::bin_triangle(
                            &ds.tile,
                            state,
                            w,
                            verts.map(|c| &c.attrs[..n_attrs]),
                            &mut self.scene,
                        );
                        continue;
                    }
                    poly.clear();
                    poly.extend(tri.iter().map(|&c| *c));
                    for (k, p) in poly.iter_mut().enumerate() {
                        // Diagonals of split quads and polygons are never boundary edges.
                        p.edge = edges[k] && (p.edge || !edge_flags);
                    }
                    if ds.tile.flat {
                        for p in poly.iter_mut() {
                            copy_provoking_colors(&ds.vertex, p, &clip[provoking]);
                        }
                    }
                    if !clip_polygon(&mut poly, &mut scratch, user, ds.viewport.guard, clip_attrs) {
                        continue;
                    }
                    win.clear();
                    win.extend(poly.iter().map(|p| to_window(&ds.viewport, p)));
                    xy.clear();
                    xy.extend(win.iter().map(|w| w.xy));
                    let area = signed_area2(&xy);
                    if area == 0 {
                        continue;
                    }
                    let front = is_front(area, ds.front_face);
                    if is_culled(ds.cull, front) {
                        continue;
                    }
                    if ds.vertex.two_sided && !front {
                        for p in poly.iter_mut() {
                            use_back_colors(&mut p.attrs);
                        }
                    }
                    let polygon_mode = ds.tile.raster.polygon_mode[usize::from(!front)];
                    if polygon_mode != PolygonMode::Fill {
                        self.draw_polygon_outline(ds, state, polygon_mode, &poly, &win);
                        continue;
                    }
                    for k in 1..poly.len() - 1 {
                        tri::bin_triangle(
                            &ds.tile,
                            state,
                            [&win[0], &win[k], &win[k + 1]],
                            [
                                &poly[0].attrs[..n_attrs],
                                &poly[k].attrs[..n_attrs],
                                &poly[k + 1].attrs[..n_attrs],
                            ],
                            &mut self.scene,
                        );
                    }
                }
            }
        }
        self.primitive_buffer = prims;
    }

    /// A polygon in `GL_POINT` or `GL_LINE` mode (section 3.5.4): its boundary vertices as
    /// points, or its boundary edges as lines, with the polygon's depth offset when the mode's
    /// offset is enabled.
    fn draw_polygon_outline(
        &mut self,
        ds: &Arc<DrawState>,
        state: u32,
        mode: PolygonMode,
        poly: &[ClipVertex],
        win: &[WindowVertex],
    ) {
        let n_attrs = ds.tile.attr_count;
        let z_offset = match (
            &ds.tile.raster.offset,
            tri::depth_plane([&win[0], &win[1], &win[2]]),
        ) {
            (Some(o), Some(z)) => o.for_plane(mode, z.a, z.b, ds.tile.fragment.depth_max),
            _ => 0.0,
        };
        let n = poly.len();
        for k in 0..n {
            if !poly[k].edge {
                continue;
            }
            match mode {
                PolygonMode::Point => {
                    let size = point::derived_size(&ds.tile.raster, poly[k].eye);
                    point::bin_point(
                        &ds.tile,
                        state,
                        &win[k],
                        size,
                        z_offset,
                        &poly[k].attrs[..n_attrs],
                        &mut self.scene,
                    );
                }
                _ => {
                    let j = (k + 1) % n;
                    let mut stipple_counter = 0;
                    line::bin_line(
                        &ds.tile,
                        state,
                        [&win[k], &win[j]],
                        [&poly[k].attrs[..n_attrs], &poly[j].attrs[..n_attrs]],
                        z_offset,
                        &mut stipple_counter,
                        &mut self.scene,
                    );
                }
            }
        }
    }
}

/// The per-sample draw states of one snapshot (see `Context::draw_sample_passes`).
#[derive(Clone, Debug)]
pub(crate) struct SamplePasses {
    /// The snapshot they were made from.
    base: Arc<DrawState>,
    /// Each covered sample's plane and draw state.
    passes: Vec<(usize, Arc<DrawState>)>,
}

impl SamplePasses {
    fn new(
        ds: &Arc<DrawState>,
        ms: &super::attrib::MultisampleState,
        samples: usize,
        force_general: bool,
    ) -> SamplePasses {
        let positions = crate::framebuffer::sample_positions(samples as u32).unwrap_or(&[]);
        let mask = if ms.multisample {
            sample_coverage_mask(ms, samples)
        } else {
            u32::MAX
        };
        let mut passes = Vec::with_capacity(samples);
        for (s, &[sx, sy]) in positions.iter().enumerate() {
            if mask & (1 << s) == 0 {
                continue;
            }
            let mut pass = (**ds).clone();
            if ms.multisample {
                let vp = &mut pass.viewport;
                vp.viewport_offset[0] += 0.5 - sx;
                vp.viewport_offset[1] += 0.5 - sy;
                if vp.guard != crate::primitive::clip::EXACT {
                    vp.guard = crate::primitive::clip::guard_factors(
                        [vp.viewport_scale[0], vp.viewport_scale[1]],
                        [vp.viewport_offset[0], vp.viewport_offset[1]],
                    );
                }
            }
            let key = ds.tile.fragment.key;
            let raster = &ds.tile.raster;
            // Multisample rasterization of polygons and lines ignores POLYGON_SMOOTH and
            // LINE_SMOOTH (sections 3.5.7, 3.4.4): the samples are the antialiasing.
            let smooth = ms.multisample && (raster.polygon_smooth || raster.line_smooth);
            if key.alpha_to_coverage || smooth {
                let mut tile = (*ds.tile).clone();
                tile.fragment.uniforms.coverage_alpha_ref = s as f32 / samples as f32;
                debug_assert!(
                    force_general || !key.alpha_to_coverage || tile.fragment.span_pair.is_none()
                );
                if ms.multisample {
                    tile.raster.polygon_smooth = false;
                    tile.raster.line_smooth = false;
                }
                pass.tile = Arc::new(tile);
            }
            passes.push((s, Arc::new(pass)));
        }
        SamplePasses {
            base: ds.clone(),
            passes,
        }
    }
}

/// The samples `GL_SAMPLE_COVERAGE` leaves covered (bit `s` for sample `s`; all when it is
/// off): the lowest floor(value x samples) samples, or the others when inverted (section
/// 4.1.3 leaves the choice of bits to the implementation; this is Mesa's).
pub(crate) fn sample_coverage_mask(ms: &super::attrib::MultisampleState, samples: usize) -> u32 {
    let all = (1u32 << samples.min(31)) - 1;
    if !ms.coverage {
        return all;
    }
    let bits = ((ms.coverage_value * samples as f32) as u32).min(samples as u32);
    let mask = (1u32 << bits) - 1;
    if ms.coverage_invert {
        all & !mask
    } else {
        mask
    }
}

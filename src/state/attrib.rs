//! The server attribute stack (`glPushAttrib`/`glPopAttrib`, section 6.1.14) and the
//! multisample state of GL 1.3 (section 3.2.1).
//!
//! A push copies the state of the context's sub-structs that the mask's groups touch; a pop
//! writes back, group by group, exactly the values the state tables list under that group's
//! name in their "attribute" column. Values that belong to several groups (for example the
//! enables, which are also in `GL_ENABLE_BIT`) are restored by each of them. Matrix stacks,
//! pixel maps, texture images and client state are not part of any group.

use glam::DVec4;

use super::tables::{limits, ClearValues, CurrentValues, FragmentOpsState, Hints, RasterState};
use super::tables::{TransformState, Viewport};
use super::Context;
use crate::common::values::{AttribGroups, MatrixMode, MultisampleCap};
use crate::gl::convert;
use crate::gl::enums::*;

/// Multisample state (table 6.x "multisample"). It acts on a framebuffer with a multisample
/// buffer (`GL_SAMPLE_BUFFERS` 1: a GLX/EGL configuration with samples) and is ignored
/// otherwise (section 3.2.1); the sample passes are made in `state::draw`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MultisampleState {
    pub multisample: bool,
    pub alpha_to_coverage: bool,
    pub alpha_to_one: bool,
    pub coverage: bool,
    /// `glSampleCoverage` value, clamped to [0, 1].
    pub coverage_value: f32,
    pub coverage_invert: bool,
}

impl Default for MultisampleState {
    fn default() -> Self {
        MultisampleState {
            multisample: true,
            alpha_to_coverage: false,
            alpha_to_one: false,
            coverage: false,
            coverage_value: 1.0,
            coverage_invert: false,
        }
    }
}

impl MultisampleState {
    pub fn enable(&mut self, cap: MultisampleCap) -> &mut bool {
        match cap {
            MultisampleCap::Multisample => &mut self.multisample,
            MultisampleCap::AlphaToCoverage => &mut self.alpha_to_coverage,
            MultisampleCap::AlphaToOne => &mut self.alpha_to_one,
            MultisampleCap::Coverage => &mut self.coverage,
        }
    }

    pub fn enabled(&self, cap: MultisampleCap) -> bool {
        match cap {
            MultisampleCap::Multisample => self.multisample,
            MultisampleCap::AlphaToCoverage => self.alpha_to_coverage,
            MultisampleCap::AlphaToOne => self.alpha_to_one,
            MultisampleCap::Coverage => self.coverage,
        }
    }
}

/// The transformation state of `GL_TRANSFORM_BIT` and `GL_VIEWPORT_BIT` (not the matrices).
#[derive(Clone, Copy, Debug)]
struct TransformAttrib {
    mode: MatrixMode,
    viewport: Viewport,
    depth_range: [f64; 2],
    clip_planes: [DVec4; limits::MAX_CLIP_PLANES],
    clip_plane_enabled: [bool; limits::MAX_CLIP_PLANES],
    normalize: bool,
    rescale_normal: bool,
}

impl TransformAttrib {
    fn of(t: &TransformState) -> TransformAttrib {
        TransformAttrib {
            mode: t.mode,
            viewport: t.viewport,
            depth_range: t.depth_range,
            clip_planes: t.clip_planes,
            clip_plane_enabled: t.clip_plane_enabled,
            normalize: t.normalize,
            rescale_normal: t.rescale_normal,
        }
    }
}

/// Evaluator state of `GL_EVAL_BIT` (the map enables and `GL_AUTO_NORMAL` also belong to
/// `GL_ENABLE_BIT`); the maps' control points belong to no group.
#[derive(Clone, Copy, Debug)]
struct EvalAttrib {
    map1_enabled: [bool; 9],
    map2_enabled: [bool; 9],
    auto_normal: bool,
    grid1: (i32, f64, f64),
    grid2: (i32, f64, f64, i32, f64, f64),
}

/// One entry of the attribute stack: the mask's groups and the state they save.
#[derive(Clone, Debug)]
pub(crate) struct AttribEntry {
    groups: AttribGroups,
    raster: RasterState,
    ops: FragmentOpsState,
    clear: ClearValues,
    current: CurrentValues,
    raster_pos: super::pixel_rect::RasterPos,
    hints: Hints,
    transform: TransformAttrib,
    fog: super::fog::FogState,
    multisample: MultisampleState,
    buffers: super::color_buffers::BufferSelection,
    list_base: GLuint,
    /// `GL_COLOR_SUM` (fog and enable groups).
    color_sum: bool,
    active_texture: usize,
    /// Lighting (`GL_LIGHTING_BIT` or `GL_ENABLE_BIT`).
    lighting: Option<super::lighting::LightingState>,
    /// Pixel transfer modes and zoom, without the maps (`GL_PIXEL_MODE_BIT`).
    pixel_transfer: Option<super::pixel_rect::PixelTransfer>,
    /// Texture enables, bindings and parameters (`GL_TEXTURE_BIT` or `GL_ENABLE_BIT`).
    textures: Option<crate::texture::TextureAttrib>,
    tex_gen: [super::texgen::TexGenUnit; limits::MAX_TEXTURE_UNITS],
    tex_env: [super::texenv::TexEnv; limits::MAX_TEXTURE_UNITS],
    eval: EvalAttrib,
}

impl Context {
    pub(crate) fn push_attrib(&mut self, mask: GLbitfield) {
        if self.attrib_stack.len() >= limits::MAX_ATTRIB_STACK_DEPTH {
            self.record_error(GL_STACK_OVERFLOW);
            return;
        }
        let g = convert::attrib_groups(mask);
        let pixel_transfer = g.pixel_mode.then(|| {
            let mut p = self.pixel_transfer.clone();
            p.maps = Default::default();
            p
        });
        let entry = AttribEntry {
            groups: g,
            raster: self.raster,
            ops: self.fragment_ops,
            clear: self.clear_values,
            current: self.current,
            raster_pos: self.raster_pos,
            hints: self.hints,
            transform: TransformAttrib::of(&self.transform),
            fog: self.fog,
            multisample: self.multisample,
            buffers: self.buffers,
            list_base: self.lists.base(),
            color_sum: self.lighting.color_sum,
            active_texture: self.active_texture,
            lighting: (g.lighting || g.enable).then(|| self.lighting.clone()),
            pixel_transfer,
            textures: (g.texture || g.enable).then(|| self.textures.save_attrib()),
            tex_gen: self.tex_gen,
            tex_env: self.tex_env,
            eval: EvalAttrib {
                map1_enabled: self.eval.map1_enabled,
                map2_enabled: self.eval.map2_enabled,
                auto_normal: self.eval.auto_normal,
                grid1: self.eval.grid1,
                grid2: self.eval.grid2,
            },
        };
        self.attrib_stack.push(Box::new(entry));
    }

    pub(crate) fn pop_attrib(&mut self) {
        let Some(e) = self.attrib_stack.pop() else {
            self.record_error(GL_STACK_UNDERFLOW);
            return;
        };
        let g = e.groups;
        if g.color_buffer && e.buffers.draw != self.buffers.draw {
            // Work recorded so far goes to the buffer it was drawn for (as `glDrawBuffer`).
            self.flush_scene();
        }
        let r = &mut self.raster;
        let ops = &mut self.fragment_ops;
        if g.current {
            self.current = e.current;
            self.raster_pos = e.raster_pos;
        }
        if g.point {
            r.point_smooth = e.raster.point_smooth;
            r.point_size = e.raster.point_size;
            r.point_size_min = e.raster.point_size_min;
            r.point_size_max = e.raster.point_size_max;
            r.point_fade_threshold = e.raster.point_fade_threshold;
            r.point_attenuation = e.raster.point_attenuation;
            r.point_sprite = e.raster.point_sprite;
            r.point_sprite_coord_replace = e.raster.point_sprite_coord_replace;
            r.point_sprite_upper_left = e.raster.point_sprite_upper_left;
        }
        if g.line {
            r.line_smooth = e.raster.line_smooth;
            r.line_stipple = e.raster.line_stipple;
            r.line_stipple_factor = e.raster.line_stipple_factor;
            r.line_stipple_pattern = e.raster.line_stipple_pattern;
            r.line_width = e.raster.line_width;
        }
        if g.polygon {
            r.cull_enabled = e.raster.cull_enabled;
            r.cull_face = e.raster.cull_face;
            r.front_face = e.raster.front_face;
            r.polygon_mode = e.raster.polygon_mode;
            r.polygon_smooth = e.raster.polygon_smooth;
            r.polygon_stipple = e.raster.polygon_stipple;
            r.offset_factor = e.raster.offset_factor;
            r.offset_units = e.raster.offset_units;
            r.offset_enabled = e.raster.offset_enabled;
        }
        if g.polygon_stipple {
            r.polygon_stipple_pattern = e.raster.polygon_stipple_pattern;
        }
        if let Some(p) = &e.pixel_transfer {
            let t = &mut self.pixel_transfer;
            t.map_color = p.map_color;
            t.map_stencil = p.map_stencil;
            t.index_shift = p.index_shift;
            t.index_offset = p.index_offset;
            t.scale = p.scale;
            t.bias = p.bias;
            t.depth_scale = p.depth_scale;
            t.depth_bias = p.depth_bias;
            t.zoom = p.zoom;
            self.buffers.read = e.buffers.read;
        }
        if g.lighting {
            if let Some(l) = &e.lighting {
                // The colour sum enable belongs to the fog and enable groups.
                let color_sum = self.lighting.color_sum;
                self.lighting = l.clone();
                self.lighting.color_sum = color_sum;
            }
            r.shade_model = e.raster.shade_model;
            r.provoking_vertex = e.raster.provoking_vertex;
        }
        if g.fog {
            self.fog = e.fog;
            self.lighting.color_sum = e.color_sum;
        }
        if g.depth_buffer {
            ops.depth_test = e.ops.depth_test;
            ops.depth_func = e.ops.depth_func;
            ops.depth_mask = e.ops.depth_mask;
            self.clear_values.depth = e.clear.depth;
        }
        if g.accum_buffer {
            self.clear_values.accum = e.clear.accum;
        }
        if g.stencil_buffer {
            ops.stencil_test = e.ops.stencil_test;
            ops.stencil_func = e.ops.stencil_func;
            ops.stencil_value_mask = e.ops.stencil_value_mask;
            ops.stencil_ref = e.ops.stencil_ref;
            ops.stencil_fail = e.ops.stencil_fail;
            ops.stencil_depth_fail = e.ops.stencil_depth_fail;
            ops.stencil_depth_pass = e.ops.stencil_depth_pass;
            ops.stencil_writemask = e.ops.stencil_writemask;
            self.clear_values.stencil = e.clear.stencil;
        }
        let t = &mut self.transform;
        if g.viewport {
            t.viewport = e.transform.viewport;
            t.depth_range = e.transform.depth_range;
        }
        if g.transform {
            t.mode = e.transform.mode;
            t.normalize = e.transform.normalize;
            t.rescale_normal = e.transform.rescale_normal;
            t.clip_planes = e.transform.clip_planes;
            t.clip_plane_enabled = e.transform.clip_plane_enabled;
        }
        if g.enable {
            ops.alpha_test = e.ops.alpha_test;
            ops.blend = e.ops.blend;
            ops.depth_test = e.ops.depth_test;
            ops.dither = e.ops.dither;
            ops.color_logic_op = e.ops.color_logic_op;
            ops.index_logic_op = e.ops.index_logic_op;
            ops.scissor_enabled = e.ops.scissor_enabled;
            ops.stencil_test = e.ops.stencil_test;
            t.clip_plane_enabled = e.transform.clip_plane_enabled;
            t.normalize = e.transform.normalize;
            t.rescale_normal = e.transform.rescale_normal;
            r.cull_enabled = e.raster.cull_enabled;
            r.line_smooth = e.raster.line_smooth;
            r.line_stipple = e.raster.line_stipple;
            r.point_smooth = e.raster.point_smooth;
            r.point_sprite = e.raster.point_sprite;
            r.polygon_smooth = e.raster.polygon_smooth;
            r.polygon_stipple = e.raster.polygon_stipple;
            r.offset_enabled = e.raster.offset_enabled;
            self.fog.enabled = e.fog.enabled;
            self.lighting.color_sum = e.color_sum;
            if let Some(l) = &e.lighting {
                self.lighting.enabled = l.enabled;
                self.lighting.color_material = l.color_material;
                for (light, saved) in self.lighting.lights.iter_mut().zip(&l.lights) {
                    light.enabled = saved.enabled;
                }
            }
            if let Some(tx) = &e.textures {
                self.textures.restore_enables(tx);
            }
            for (unit, saved) in self.tex_gen.iter_mut().zip(&e.tex_gen) {
                for (c, s) in unit.iter_mut().zip(saved) {
                    c.enabled = s.enabled;
                }
            }
            self.eval.map1_enabled = e.eval.map1_enabled;
            self.eval.map2_enabled = e.eval.map2_enabled;
            self.eval.auto_normal = e.eval.auto_normal;
            let m = &mut self.multisample;
            m.multisample = e.multisample.multisample;
            m.alpha_to_coverage = e.multisample.alpha_to_coverage;
            m.alpha_to_one = e.multisample.alpha_to_one;
            m.coverage = e.multisample.coverage;
        }
        if g.color_buffer {
            ops.alpha_test = e.ops.alpha_test;
            ops.alpha_func = e.ops.alpha_func;
            ops.alpha_ref = e.ops.alpha_ref;
            ops.blend = e.ops.blend;
            ops.blend_src_rgb = e.ops.blend_src_rgb;
            ops.blend_dst_rgb = e.ops.blend_dst_rgb;
            ops.blend_src_alpha = e.ops.blend_src_alpha;
            ops.blend_dst_alpha = e.ops.blend_dst_alpha;
            ops.blend_equation = e.ops.blend_equation;
            ops.blend_equation_alpha = e.ops.blend_equation_alpha;
            ops.blend_color = e.ops.blend_color;
            ops.dither = e.ops.dither;
            ops.color_logic_op = e.ops.color_logic_op;
            ops.index_logic_op = e.ops.index_logic_op;
            ops.logic_op = e.ops.logic_op;
            ops.color_mask = e.ops.color_mask;
            ops.index_writemask = e.ops.index_writemask;
            self.clear_values.color = e.clear.color;
            self.clear_values.index = e.clear.index;
            self.buffers.draw = e.buffers.draw;
        }
        if g.hint {
            self.hints = e.hints;
        }
        if g.eval {
            self.eval.map1_enabled = e.eval.map1_enabled;
            self.eval.map2_enabled = e.eval.map2_enabled;
            self.eval.auto_normal = e.eval.auto_normal;
            self.eval.grid1 = e.eval.grid1;
            self.eval.grid2 = e.eval.grid2;
        }
        if g.list {
            self.list_base(e.list_base);
        }
        if g.texture {
            self.active_texture = e.active_texture;
            if let Some(tx) = &e.textures {
                self.textures.restore_attrib(tx);
            }
            self.tex_gen = e.tex_gen;
            self.tex_env = e.tex_env;
        }
        if g.scissor {
            self.fragment_ops.scissor_enabled = e.ops.scissor_enabled;
            self.fragment_ops.scissor = e.ops.scissor;
        }
        if g.multisample {
            self.multisample = e.multisample;
        }
        if g.pixel_mode || g.color_buffer {
            self.apply_buffer_selection();
        }
        self.invalidate();
    }

    pub(crate) fn sample_coverage(&mut self, value: GLfloat, invert: GLboolean) {
        self.multisample.coverage_value = super::clamp01(value as f64) as f32;
        self.multisample.coverage_invert = invert != 0;
        self.invalidate();
    }

    /// Depth of the attribute stack (`GL_ATTRIB_STACK_DEPTH`).
    pub fn attrib_stack_depth(&self) -> usize {
        self.attrib_stack.len()
    }
}

impl Context {
    /// Values of the `convert::StateExtQuery` queries.
    pub(crate) fn state_ext_value(&self, q: convert::StateExtQuery) -> super::get::StateValue {
        use super::get::StateValue::*;
        use convert::StateExtQuery::*;
        match q {
            AttribStackDepth => Ints(vec![self.attrib_stack.len() as i64]),
            SampleCoverageValue => Floats(vec![self.multisample.coverage_value as f64]),
            SampleCoverageInvert => Bools(vec![self.multisample.coverage_invert]),
            TextureBinding(t) => Ints(vec![self.textures.binding(self.active_texture, t) as i64]),
            SamplerBinding => Ints(vec![
                self.textures.sampler_binding(self.active_texture) as i64
            ]),
            MaxTextureSize(t) => Ints(vec![crate::texture::object::max_size(t) as i64]),
            MaxTextureLodBias => Floats(vec![crate::texture::object::MAX_TEXTURE_LOD_BIAS as f64]),
            MaxTextureMaxAnisotropy => Floats(vec![
                crate::texture::object::MAX_TEXTURE_MAX_ANISOTROPY as f64,
            ]),
            NumCompressedTextureFormats => {
                Ints(vec![convert::COMPRESSED_TEXTURE_FORMATS.len() as i64])
            }
            CompressedTextureFormats => Ints(
                convert::COMPRESSED_TEXTURE_FORMATS
                    .iter()
                    .map(|&f| f as i64)
                    .collect(),
            ),
            RenderMode | NameStackDepth | MaxNameStackDepth | FeedbackBufferSize
            | FeedbackBufferType | SelectionBufferSize => self.select_state_value(q),
        }
    }
}

//! `glGet{Boolean,Integer,Float,Double}v` with the type conversions of section 6.1.2.

use super::tables::limits;
use super::Context;
use crate::common::values::{PixelStoreParam, Query};
use crate::gl::convert;
use crate::gl::enums::*;
use glam::Mat4;

/// A state value in its natural type, before conversion to the requested one.
#[derive(Clone, Debug, PartialEq)]
pub enum StateValue {
    Bools(Vec<bool>),
    Ints(Vec<i64>),
    Enum(GLenum),
    /// Several enums (e.g. `GL_POLYGON_MODE`: front, back).
    Enums(Vec<GLenum>),
    Floats(Vec<f64>),
    /// Colours, normals, depth range and clear depth: integer queries map [-1, 1] onto the
    /// full integer range (table 4.9) instead of rounding.
    Normalized(Vec<f64>),
}

impl StateValue {
    pub fn len(&self) -> usize {
        match self {
            StateValue::Bools(v) => v.len(),
            StateValue::Ints(v) => v.len(),
            StateValue::Enum(_) => 1,
            StateValue::Enums(v) => v.len(),
            StateValue::Floats(v) | StateValue::Normalized(v) => v.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    fn as_f64(&self) -> Vec<f64> {
        match self {
            StateValue::Bools(v) => v.iter().map(|&b| b as i32 as f64).collect(),
            StateValue::Ints(v) => v.iter().map(|&i| i as f64).collect(),
            StateValue::Enum(e) => vec![*e as f64],
            StateValue::Enums(v) => v.iter().map(|&e| e as f64).collect(),
            StateValue::Floats(v) | StateValue::Normalized(v) => v.clone(),
        }
    }

    fn as_bool(&self) -> Vec<bool> {
        match self {
            StateValue::Bools(v) => v.clone(),
            StateValue::Ints(v) => v.iter().map(|&i| i != 0).collect(),
            StateValue::Enum(e) => vec![*e != 0],
            StateValue::Enums(v) => v.iter().map(|&e| e != 0).collect(),
            StateValue::Floats(v) | StateValue::Normalized(v) => {
                v.iter().map(|&f| f != 0.0).collect()
            }
        }
    }

    fn as_i32(&self) -> Vec<i32> {
        match self {
            StateValue::Bools(v) => v.iter().map(|&b| b as i32).collect(),
            StateValue::Ints(v) => v
                .iter()
                .map(|&i| i.clamp(i32::MIN as i64, i32::MAX as i64) as i32)
                .collect(),
            StateValue::Enum(e) => vec![*e as i32],
            StateValue::Enums(v) => v.iter().map(|&e| e as i32).collect(),
            StateValue::Floats(v) => v.iter().map(|&f| round_to_i32(f)).collect(),
            StateValue::Normalized(v) => v
                .iter()
                // Table 4.9 maps [-1, 1] onto the integer range; tilegl uses f * (2^31 - 1)
                // truncated, as Mesa does, so queries agree exactly with the reference.
                .map(|&f| (f.clamp(-1.0, 1.0) * 2147483647.0) as i32)
                .collect(),
        }
    }
}

fn round_to_i32(f: f64) -> i32 {
    if f.is_nan() {
        0
    } else {
        f.round().clamp(i32::MIN as f64, i32::MAX as f64) as i32
    }
}

fn matrix(m: &Mat4) -> StateValue {
    StateValue::Floats(m.to_cols_array().iter().map(|&v| v as f64).collect())
}

impl Context {
    /// The value of a query in its natural type.
    pub fn state_value(&self, q: Query) -> StateValue {
        use StateValue::*;
        let t = &self.transform;
        let ops = &self.fragment_ops;
        let cfg = self.framebuffer.config;
        let top = |s: &Vec<Mat4>| *s.last().unwrap_or(&Mat4::IDENTITY);
        let unit = self.active_texture;
        let bool1 = |b: bool| Bools(vec![b]);
        let int1 = |i: i64| Ints(vec![i]);
        match q {
            Query::Enabled(cap) => bool1(self.capability_enabled(cap)),
            Query::Viewport => {
                let v = t.viewport;
                Ints(vec![
                    v.x as i64,
                    v.y as i64,
                    v.width as i64,
                    v.height as i64,
                ])
            }
            Query::DepthRange => Normalized(t.depth_range.to_vec()),
            Query::ModelviewMatrix => matrix(&top(&t.modelview)),
            Query::ProjectionMatrix => matrix(&top(&t.projection)),
            Query::TextureMatrix => matrix(&top(&t.texture[unit])),
            Query::TransposeModelviewMatrix => matrix(&top(&t.modelview).transpose()),
            Query::TransposeProjectionMatrix => matrix(&top(&t.projection).transpose()),
            Query::TransposeTextureMatrix => matrix(&top(&t.texture[unit]).transpose()),
            Query::ModelviewStackDepth => int1(t.modelview.len() as i64),
            Query::ProjectionStackDepth => int1(t.projection.len() as i64),
            Query::TextureStackDepth => int1(t.texture[unit].len() as i64),
            Query::MaxModelviewStackDepth => int1(limits::MAX_MODELVIEW_STACK_DEPTH as i64),
            Query::MaxProjectionStackDepth => int1(limits::MAX_PROJECTION_STACK_DEPTH as i64),
            Query::MaxTextureStackDepth => int1(limits::MAX_TEXTURE_STACK_DEPTH as i64),
            Query::MaxViewportDims => Ints(vec![limits::MAX_VIEWPORT_DIM as i64; 2]),
            Query::MaxClipPlanes => int1(limits::MAX_CLIP_PLANES as i64),
            Query::MaxTextureUnits => int1(limits::MAX_TEXTURE_UNITS as i64),
            Query::ColorClearValue => {
                Normalized(self.clear_values.color.iter().map(|&c| c as f64).collect())
            }
            Query::PixelRect(q) => self.pixel_rect_value(q),
            Query::AccumClearValue => {
                Normalized(self.clear_values.accum.iter().map(|&c| c as f64).collect())
            }
            Query::DepthClearValue => Normalized(vec![self.clear_values.depth]),
            Query::StencilClearValue => int1(self.clear_values.stencil as i64),
            Query::DepthFunc => Enum(ops.depth_func.to_gl()),
            Query::DepthWritemask => bool1(ops.depth_mask),
            Query::ColorWritemask => Bools(ops.color_mask.to_vec()),
            Query::StencilWritemask => int1(ops.stencil_writemask as i32 as i64),
            Query::ScissorBox => {
                let s = ops.scissor;
                Ints(vec![
                    s.x as i64,
                    s.y as i64,
                    s.width as i64,
                    s.height as i64,
                ])
            }
            Query::CullFaceMode => Enum(self.raster.cull_face.to_gl()),
            Query::FrontFace => Enum(self.raster.front_face.to_gl()),
            Query::ShadeModel => Enum(self.raster.shade_model.to_gl()),
            Query::MatrixMode => Enum(t.mode.to_gl()),
            Query::CurrentColor => {
                Normalized(self.current.color.to_array().map(|v| v as f64).to_vec())
            }
            Query::CurrentSecondaryColor => Normalized(
                self.current
                    .secondary_color
                    .to_array()
                    .map(|v| v as f64)
                    .to_vec(),
            ),
            Query::CurrentNormal => {
                Normalized(self.current.normal.to_array().map(|v| v as f64).to_vec())
            }
            Query::CurrentTextureCoords => Floats(
                self.current.texcoords[unit]
                    .to_array()
                    .map(|v| v as f64)
                    .to_vec(),
            ),
            Query::CurrentFogCoord => Floats(vec![self.current.fog_coord as f64]),
            Query::EdgeFlag => bool1(self.current.edge_flag),
            Query::RedBits | Query::GreenBits | Query::BlueBits | Query::AlphaBits => int1(8),
            Query::DepthBits => int1(cfg.depth_bits as i64),
            Query::StencilBits => int1(cfg.stencil_bits as i64),
            Query::AccumRedBits
            | Query::AccumGreenBits
            | Query::AccumBlueBits
            | Query::AccumAlphaBits => int1(cfg.accum_bits as i64),
            Query::IndexBits => int1(0),
            Query::SubpixelBits => int1(limits::SUBPIXEL_BITS as i64),
            Query::AuxBuffers => int1(0),
            Query::Hint(h) => {
                use crate::common::values::HintTarget::*;
                let hs = &self.hints;
                Enum(match h {
                    PerspectiveCorrection => hs.perspective_correction,
                    PointSmooth => hs.point_smooth,
                    LineSmooth => hs.line_smooth,
                    PolygonSmooth => hs.polygon_smooth,
                    Fog => hs.fog,
                    GenerateMipmap => hs.generate_mipmap,
                    TextureCompression => hs.texture_compression,
                })
            }
            Query::PixelStore(p) => {
                use PixelStoreParam::*;
                let s = |pack: bool| if pack { &self.pack } else { &self.unpack };
                match p {
                    Alignment { pack } => int1(s(pack).alignment as i64),
                    RowLength { pack } => int1(s(pack).row_length as i64),
                    SkipPixels { pack } => int1(s(pack).skip_pixels as i64),
                    SkipRows { pack } => int1(s(pack).skip_rows as i64),
                    SkipImages { pack } => int1(s(pack).skip_images as i64),
                    ImageHeight { pack } => int1(s(pack).image_height as i64),
                    SwapBytes { pack } => bool1(s(pack).swap_bytes),
                    LsbFirst { pack } => bool1(s(pack).lsb_first),
                }
            }
            Query::Doublebuffer => bool1(cfg.double_buffer),
            Query::DrawBuffer => Enum(self.buffers.draw),
            Query::ReadBuffer => Enum(self.read_buffer_selected()),
            Query::Stereo | Query::IndexMode => bool1(false),
            Query::RgbaMode => bool1(true),
            Query::PointSize => Floats(vec![self.raster.point_size as f64]),
            Query::PointSizeRange => Floats(limits::POINT_SIZE_RANGE.map(|v| v as f64).to_vec()),
            Query::PointSizeGranularity | Query::LineWidthGranularity => {
                Floats(vec![limits::SIZE_GRANULARITY])
            }
            Query::LineWidth => Floats(vec![self.raster.line_width as f64]),
            Query::LineWidthRange => Floats(limits::LINE_WIDTH_RANGE.map(|v| v as f64).to_vec()),
            Query::ActiveTexture => Enum(convert::texture_unit_enum(unit)),
            Query::ClientActiveTexture => {
                Enum(convert::texture_unit_enum(self.client_active_texture))
            }
            Query::MaxAttribStackDepth => int1(limits::MAX_ATTRIB_STACK_DEPTH as i64),
            Query::SampleBuffers => int1((self.framebuffer.samples > 1) as i64),
            Query::Samples => int1(if self.framebuffer.samples > 1 {
                self.framebuffer.samples as i64
            } else {
                0
            }),
            Query::AlphaTestFunc => Enum(ops.alpha_func.to_gl()),
            // The alpha reference is a colour-like value: integer queries scale it.
            Query::AlphaTestRef => Normalized(vec![ops.alpha_ref as f64]),
            Query::StencilFunc => Enum(ops.stencil_func.to_gl()),
            Query::StencilValueMask => int1(ops.stencil_value_mask as i32 as i64),
            Query::StencilRef => int1(ops.stencil_ref as i64),
            Query::StencilFail => Enum(ops.stencil_fail.to_gl()),
            Query::StencilPassDepthFail => Enum(ops.stencil_depth_fail.to_gl()),
            Query::StencilPassDepthPass => Enum(ops.stencil_depth_pass.to_gl()),
            Query::BlendSrcRgb => Enum(ops.blend_src_rgb.to_gl()),
            Query::BlendDstRgb => Enum(ops.blend_dst_rgb.to_gl()),
            Query::BlendSrcAlpha => Enum(ops.blend_src_alpha.to_gl()),
            Query::BlendDstAlpha => Enum(ops.blend_dst_alpha.to_gl()),
            Query::BlendEquationRgb => Enum(ops.blend_equation.to_gl()),
            Query::BlendEquationAlpha => Enum(ops.blend_equation_alpha.to_gl()),
            Query::CurrentIndex => Floats(vec![self.current.index as f64]),
            Query::IndexClearValue => Floats(vec![self.clear_values.index as f64]),
            Query::IndexWritemask => int1(ops.index_writemask as i32 as i64),
            Query::ProvokingVertex => Enum(self.raster.provoking_vertex.to_gl()),
            Query::FramebufferBinding => int1(self.fbo.bound as i64),
            Query::ReadFramebufferBinding => int1(self.fbo.read_bound as i64),
            Query::RenderbufferBinding => int1(self.fbo.bound_renderbuffer as i64),
            Query::MaxColorAttachments => int1(super::fbo::MAX_COLOR_ATTACHMENTS as i64),
            Query::MaxRenderbufferSize => int1(super::fbo::MAX_RENDERBUFFER_SIZE as i64),
            Query::MaxSamples => int1(super::fbo::MAX_SAMPLES as i64),
            Query::QuadsFollowProvokingVertex => {
                bool1(crate::primitive::assemble::QUADS_FOLLOW_PROVOKING_VERTEX)
            }
            Query::BlendColor => Normalized(ops.blend_color.iter().map(|&c| c as f64).collect()),
            Query::LogicOpMode => Enum(ops.logic_op.to_gl()),
            Query::MaxLights => int1(8),
            Query::LightModelAmbient => Normalized(
                self.lighting
                    .model_ambient
                    .to_array()
                    .map(|v| v as f64)
                    .to_vec(),
            ),
            Query::LightModelLocalViewer => bool1(self.lighting.local_viewer),
            Query::LightModelTwoSide => bool1(self.lighting.two_side),
            Query::LightModelColorControl => Enum(if self.lighting.separate_specular {
                GL_SEPARATE_SPECULAR_COLOR
            } else {
                GL_SINGLE_COLOR
            }),
            Query::Fog(p) => {
                use crate::common::values::FogParam;
                let f = &self.fog;
                match p {
                    FogParam::Mode => Enum(f.mode.to_gl()),
                    FogParam::Density => Floats(vec![f.density as f64]),
                    FogParam::Start => Floats(vec![f.start as f64]),
                    FogParam::End => Floats(vec![f.end as f64]),
                    FogParam::Index => Floats(vec![f.index as f64]),
                    FogParam::Color => Normalized(f.color.iter().map(|&c| c as f64).collect()),
                    FogParam::CoordSource => Enum(if f.coord_from_vertex {
                        GL_FOG_COORD
                    } else {
                        GL_FRAGMENT_DEPTH
                    }),
                }
            }
            Query::PolygonMode => Enums(self.raster.polygon_mode.map(|m| m.to_gl()).to_vec()),
            Query::PolygonOffsetFactor => Floats(vec![self.raster.offset_factor as f64]),
            Query::PolygonOffsetUnits => Floats(vec![self.raster.offset_units as f64]),
            Query::LineStipplePattern => int1(self.raster.line_stipple_pattern as i64),
            Query::LineStippleRepeat => int1(self.raster.line_stipple_factor as i64),
            Query::AliasedPointSizeRange => {
                Floats(limits::POINT_SIZE_RANGE.map(|v| v as f64).to_vec())
            }
            Query::AliasedLineWidthRange => {
                Floats(limits::LINE_WIDTH_RANGE.map(|v| v as f64).to_vec())
            }
            Query::PointParam(p) => {
                use crate::common::values::PointParam;
                let r = &self.raster;
                match p {
                    PointParam::SizeMin => Floats(vec![r.point_size_min as f64]),
                    PointParam::SizeMax => Floats(vec![r.point_size_max as f64]),
                    PointParam::FadeThresholdSize => Floats(vec![r.point_fade_threshold as f64]),
                    PointParam::DistanceAttenuation => {
                        Floats(r.point_attenuation.map(|v| v as f64).to_vec())
                    }
                    PointParam::SpriteCoordOrigin => Enum(if r.point_sprite_upper_left {
                        GL_UPPER_LEFT
                    } else {
                        GL_LOWER_LEFT
                    }),
                }
            }
            Query::ColorMaterialFace => Enum(self.lighting.color_material_face.to_gl()),
            Query::ColorMaterialParameter => Enum(self.lighting.color_material_mode.to_gl()),
            Query::Arrays(q) => self.array_state_value(q),
            Query::StateExt(q) => self.state_ext_value(q),
            Query::Eval(q) => self.eval_state_value(q),
        }
    }

    /// Number of values `glGet*v(pname)` writes (1 for unknown names, so callers of the C ABI
    /// are never asked for more than one element before the error is recorded).
    pub fn query_count(&self, pname: GLenum) -> usize {
        convert::query(pname).map_or(1, |q| self.state_value(q).len().max(1))
    }

    fn query_checked(&mut self, pname: GLenum, out_len: usize) -> Option<StateValue> {
        let Some(q) = convert::query(pname) else {
            self.record_error(GL_INVALID_ENUM);
            return None;
        };
        // Framebuffer-dependent values (GL_DEPTH_BITS...) follow the bound object's images.
        self.fbo_refresh();
        let v = self.state_value(q);
        if out_len < v.len() {
            self.record_error(GL_INVALID_VALUE);
            return None;
        }
        Some(v)
    }

    pub(crate) fn get_booleanv(&mut self, pname: GLenum, data: &mut [GLboolean]) {
        if let Some(v) = self.query_checked(pname, data.len()) {
            for (d, b) in data.iter_mut().zip(v.as_bool()) {
                *d = b as GLboolean;
            }
        }
    }

    pub(crate) fn get_integerv(&mut self, pname: GLenum, data: &mut [GLint]) {
        if let Some(v) = self.query_checked(pname, data.len()) {
            for (d, i) in data.iter_mut().zip(v.as_i32()) {
                *d = i;
            }
        }
    }

    pub(crate) fn get_floatv(&mut self, pname: GLenum, data: &mut [GLfloat]) {
        if let Some(v) = self.query_checked(pname, data.len()) {
            for (d, f) in data.iter_mut().zip(v.as_f64()) {
                *d = f as f32;
            }
        }
    }

    pub(crate) fn get_doublev(&mut self, pname: GLenum, data: &mut [GLdouble]) {
        if let Some(v) = self.query_checked(pname, data.len()) {
            for (d, f) in data.iter_mut().zip(v.as_f64()) {
                *d = f;
            }
        }
    }
}

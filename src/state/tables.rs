//! GL state as plain data, grouped like the specification's state tables (OpenGL 1.5, section
//! 6.2), with the defaults those tables give.

use crate::common::values::{
    BlendEquation, BlendFactor, CompareFunc, Face, LogicOp, MatrixMode, PolygonMode, ShadeModel,
    StencilOp, Winding,
};
use crate::gl::enums::GL_DONT_CARE;
use crate::gl::GLenum;
use glam::{DVec4, Mat4, Vec3, Vec4};

/// Implementation limits reported by `glGet` (defined in the leaf module, where every stage
/// reads them).
pub use crate::common::limits;

/// Table 6.6 / 6.7: transformation state.
#[derive(Clone, Debug)]
pub struct TransformState {
    pub mode: MatrixMode,
    pub modelview: Vec<Mat4>,
    pub projection: Vec<Mat4>,
    /// One stack per texture unit.
    pub texture: Vec<Vec<Mat4>>,
    pub viewport: Viewport,
    pub depth_range: [f64; 2],
    /// User clip planes in eye coordinates (transformed at `glClipPlane` time).
    pub clip_planes: [DVec4; limits::MAX_CLIP_PLANES],
    pub clip_plane_enabled: [bool; limits::MAX_CLIP_PLANES],
    pub normalize: bool,
    pub rescale_normal: bool,
}

impl Default for TransformState {
    fn default() -> Self {
        TransformState {
            mode: MatrixMode::ModelView,
            modelview: vec![Mat4::IDENTITY],
            projection: vec![Mat4::IDENTITY],
            texture: vec![vec![Mat4::IDENTITY]; limits::MAX_TEXTURE_UNITS],
            viewport: Viewport::default(),
            depth_range: [0.0, 1.0],
            clip_planes: [DVec4::ZERO; limits::MAX_CLIP_PLANES],
            clip_plane_enabled: [false; limits::MAX_CLIP_PLANES],
            normalize: false,
            rescale_normal: false,
        }
    }
}

/// `glViewport` rectangle (lower-left corner, size).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Viewport {
    pub x: i32,
    pub y: i32,
    pub width: i32,
    pub height: i32,
}

impl Viewport {
    /// The box's pixels (saturating, so huge sizes do not wrap).
    pub fn rect(&self) -> crate::common::rect::Rect {
        crate::common::rect::Rect {
            x0: self.x,
            y0: self.y,
            x1: self.x.saturating_add(self.width),
            y1: self.y.saturating_add(self.height),
        }
    }
}

/// Table 6.8 (rasterization of polygons) and related state.
#[derive(Clone, Copy, Debug)]
pub struct RasterState {
    pub cull_enabled: bool,
    pub cull_face: Face,
    pub front_face: Winding,
    pub shade_model: ShadeModel,
    pub point_size: f32,
    pub line_width: f32,
    pub point_smooth: bool,
    pub line_smooth: bool,
    pub polygon_smooth: bool,
    pub line_stipple: bool,
    pub line_stipple_factor: i32,
    pub line_stipple_pattern: u16,
    pub polygon_stipple: bool,
    /// 32 rows of 32 bits, bottom row first; bit x of a row is `1 << (31 - x)`.
    pub polygon_stipple_pattern: [u32; 32],
    /// Front, back.
    pub polygon_mode: [PolygonMode; 2],
    pub offset_factor: f32,
    pub offset_units: f32,
    /// Fill, line, point.
    pub offset_enabled: [bool; 3],
    pub point_size_min: f32,
    pub point_size_max: f32,
    pub point_fade_threshold: f32,
    pub point_attenuation: [f32; 3],
    /// `GL_POINT_SPRITE` (ARB_point_sprite), the units whose `GL_COORD_REPLACE` is on (bit
    /// per unit) and `GL_POINT_SPRITE_COORD_ORIGIN` (`GL_UPPER_LEFT`: true, the default).
    pub point_sprite: bool,
    pub point_sprite_coord_replace: u32,
    pub point_sprite_upper_left: bool,
}

impl Default for RasterState {
    fn default() -> Self {
        RasterState {
            cull_enabled: false,
            cull_face: Face::Back,
            front_face: Winding::Ccw,
            shade_model: ShadeModel::Smooth,
            point_size: 1.0,
            line_width: 1.0,
            point_smooth: false,
            line_smooth: false,
            polygon_smooth: false,
            line_stipple: false,
            line_stipple_factor: 1,
            line_stipple_pattern: 0xFFFF,
            polygon_stipple: false,
            polygon_stipple_pattern: [!0; 32],
            polygon_mode: [PolygonMode::Fill; 2],
            offset_factor: 0.0,
            offset_units: 0.0,
            offset_enabled: [false; 3],
            point_size_min: 0.0,
            point_size_max: limits::POINT_SIZE_RANGE[1],
            point_fade_threshold: 1.0,
            point_attenuation: [1.0, 0.0, 0.0],
            point_sprite: false,
            point_sprite_coord_replace: 0,
            point_sprite_upper_left: true,
        }
    }
}

/// Tables 6.19-6.21: per-fragment operations and framebuffer control.
#[derive(Clone, Copy, Debug)]
pub struct FragmentOpsState {
    pub scissor_enabled: bool,
    pub scissor: Viewport,
    pub depth_test: bool,
    pub depth_func: CompareFunc,
    pub depth_mask: bool,
    pub color_mask: [bool; 4],
    pub dither: bool,
    pub stencil_writemask: u32,
    pub alpha_test: bool,
    pub alpha_func: CompareFunc,
    /// Alpha reference, clamped to [0, 1] at `glAlphaFunc`.
    pub alpha_ref: f32,
    pub stencil_test: bool,
    pub stencil_func: CompareFunc,
    /// Stencil reference as given (clamped to the buffer's range when used and queried).
    pub stencil_ref: i32,
    pub stencil_value_mask: u32,
    pub stencil_fail: StencilOp,
    pub stencil_depth_fail: StencilOp,
    pub stencil_depth_pass: StencilOp,
    pub blend: bool,
    pub blend_src_rgb: BlendFactor,
    pub blend_dst_rgb: BlendFactor,
    pub blend_src_alpha: BlendFactor,
    pub blend_dst_alpha: BlendFactor,
    pub blend_equation: BlendEquation,
    /// EXT_blend_equation_separate's alpha equation.
    pub blend_equation_alpha: BlendEquation,
    pub blend_color: [f32; 4],
    pub color_logic_op: bool,
    pub index_logic_op: bool,
    pub logic_op: LogicOp,
}

impl Default for FragmentOpsState {
    fn default() -> Self {
        FragmentOpsState {
            scissor_enabled: false,
            scissor: Viewport::default(),
            depth_test: false,
            depth_func: CompareFunc::Less,
            depth_mask: true,
            color_mask: [true; 4],
            dither: true,
            stencil_writemask: !0,
            alpha_test: false,
            alpha_func: CompareFunc::Always,
            alpha_ref: 0.0,
            stencil_test: false,
            stencil_func: CompareFunc::Always,
            stencil_ref: 0,
            stencil_value_mask: !0,
            stencil_fail: StencilOp::Keep,
            stencil_depth_fail: StencilOp::Keep,
            stencil_depth_pass: StencilOp::Keep,
            blend: false,
            blend_src_rgb: BlendFactor::One,
            blend_dst_rgb: BlendFactor::Zero,
            blend_src_alpha: BlendFactor::One,
            blend_dst_alpha: BlendFactor::Zero,
            blend_equation: BlendEquation::Add,
            blend_equation_alpha: BlendEquation::Add,
            blend_color: [0.0; 4],
            color_logic_op: false,
            index_logic_op: false,
            logic_op: LogicOp::Copy,
        }
    }
}

/// Clear values (table 6.21).
#[derive(Clone, Copy, Debug)]
pub struct ClearValues {
    pub color: [f32; 4],
    pub depth: f64,
    pub stencil: i32,
    /// `glClearAccum`, clamped to [-1, 1].
    pub accum: [f32; 4],
}

impl Default for ClearValues {
    fn default() -> Self {
        ClearValues {
            color: [0.0; 4],
            depth: 1.0,
            stencil: 0,
            accum: [0.0; 4],
        }
    }
}

/// Table 6.5: current values.
#[derive(Clone, Copy, Debug)]
pub struct CurrentValues {
    pub color: Vec4,
    pub secondary_color: Vec4,
    pub normal: Vec3,
    pub texcoords: [Vec4; limits::MAX_TEXTURE_UNITS],
    pub fog_coord: f32,
    pub edge_flag: bool,
    pub index: f32,
}

impl Default for CurrentValues {
    fn default() -> Self {
        CurrentValues {
            color: Vec4::ONE,
            secondary_color: Vec4::new(0.0, 0.0, 0.0, 1.0),
            normal: Vec3::Z,
            texcoords: [Vec4::new(0.0, 0.0, 0.0, 1.0); limits::MAX_TEXTURE_UNITS],
            fog_coord: 0.0,
            edge_flag: true,
            index: 1.0,
        }
    }
}

/// Table 6.30: hints.
#[derive(Clone, Copy, Debug)]
pub struct Hints {
    pub perspective_correction: GLenum,
    pub point_smooth: GLenum,
    pub line_smooth: GLenum,
    pub polygon_smooth: GLenum,
    pub fog: GLenum,
    pub generate_mipmap: GLenum,
    pub texture_compression: GLenum,
}

impl Default for Hints {
    fn default() -> Self {
        Hints {
            perspective_correction: GL_DONT_CARE,
            point_smooth: GL_DONT_CARE,
            line_smooth: GL_DONT_CARE,
            polygon_smooth: GL_DONT_CARE,
            fog: GL_DONT_CARE,
            generate_mipmap: GL_DONT_CARE,
            texture_compression: GL_DONT_CARE,
        }
    }
}

/// Table 6.17: pixel storage modes (defined in `texture::pixels`, which interprets them).
pub use crate::texture::pixels::PixelStore;

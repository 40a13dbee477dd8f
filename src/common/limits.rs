//! Implementation limits reported by `glGet`, which every stage sizes its arrays by.

pub const MAX_MODELVIEW_STACK_DEPTH: usize = 32;
pub const MAX_PROJECTION_STACK_DEPTH: usize = 4;
pub const MAX_TEXTURE_STACK_DEPTH: usize = 4;
/// User clip planes: 8, as Mesa reports (`GL_MAX_CLIP_PLANES`; the spec asks for at least
/// 6). `gl/convert.rs` accepts `GL_CLIP_PLANE0 + 0..8` to match.
pub const MAX_CLIP_PLANES: usize = 8;
pub const MAX_TEXTURE_UNITS: usize = 8;
/// Largest viewport and framebuffer side.
pub const MAX_VIEWPORT_DIM: i32 = 8192;
/// Sub-pixel precision of window coordinates: 8 bits (1/256 pixel). With 64-bit edge
/// functions no product overflows for any coordinate inside `MAX_VIEWPORT_DIM` plus the
/// largest viewport offset.
pub const SUBPIXEL_BITS: i32 = 8;
pub const MAX_ATTRIB_STACK_DEPTH: usize = 16;
/// Point sizes and line widths rasterized (larger values are clamped to the maximum):
/// Mesa's (llvmpipe and softpipe report [1, 255] for aliased and smooth points and lines
/// alike), so a program asking for a size of 1000 gets the same picture on both.
pub const POINT_SIZE_RANGE: [f32; 2] = [1.0, 255.0];
pub const LINE_WIDTH_RANGE: [f32; 2] = [1.0, 255.0];
/// `GL_POINT_SIZE_GRANULARITY` and `GL_LINE_WIDTH_GRANULARITY`, as Mesa reports them
/// (sizes are not quantised: any granularity is honest).
pub const SIZE_GRANULARITY: f64 = 0.1;

//! tilegl: an OpenGL 1.5 fixed-function driver emulated by a tile-based, multi-threaded
//! software rasterizer.
//!
//! A draw flows through the modules in pipeline order: [`api`] (the `Gl` trait and its entry
//! points) -> [`state`] (the state machine, composing the frozen per-draw snapshot from each
//! stage's part) -> [`gl`] (the GL vocabulary `api` and `state` speak: types, enums, their
//! conversion, errors; no stage below uses it) -> [`vertex`] (transform) -> [`primitive`] (assembly, clipping, culling, viewport) -> [`raster`] (setup,
//! binning into tiles, parallel tile shading) -> [`fragment`] (specialised span functions) ->
//! [`texture`] (objects, formats, sampling) -> [`framebuffer`] (tiled buffers), each using only
//! the modules after it; [`common`] (CPU features, limits, fixed point, rectangles, the typed
//! values of GL state) is the leaf they all share. `tests/module_deps.rs` checks the order.
//!
//! ```
//! use tilegl::{Context, Gl, enums::*};
//! let mut gl = Context::new(64, 64);
//! gl.clear_color(0.0, 0.0, 1.0, 1.0);
//! gl.clear(GL_COLOR_BUFFER_BIT);
//! gl.begin(GL_TRIANGLES);
//! gl.color_3f(1.0, 0.0, 0.0);
//! gl.vertex_2f(-1.0, -1.0);
//! gl.vertex_2f(1.0, -1.0);
//! gl.vertex_2f(0.0, 1.0);
//! gl.end();
//! let mut px = [0u8; 4];
//! gl.read_pixels(32, 16, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
//! assert_eq!(px, [255, 0, 0, 255]);
//! ```

// Lints this crate opts out of, deliberately:
// - `!(x >= lo)` rejects NaN together with out-of-range values, which GL argument checks need;
// - manual clamps keep NaN handling explicit (and never panic on min > max);
// - the numeric kernels index several parallel arrays by one loop counter;
// - some span and pixel-transfer kernels take many scalar arguments on purpose.
#![allow(
    clippy::neg_cmp_op_on_partial_ord,
    clippy::manual_clamp,
    clippy::needless_range_loop,
    clippy::too_many_arguments,
    clippy::redundant_closure_call
)]

#[macro_use]
pub mod api;
pub mod capi;
pub mod common;
pub mod compare;
pub mod fragment;
pub mod framebuffer;
pub mod gl;
pub mod primitive;
pub mod raster;
pub mod replay;
pub mod state;
pub mod texture;
pub mod vertex;

pub use api::enums;
pub use api::types::*;
pub use api::Gl;
pub use framebuffer::{Framebuffer, FramebufferConfig};
pub use raster::controls::SmoothPoints;
pub use state::evaluators::MeshFill;
pub use state::{Context, ContextConfig};

/// Helpers shared by the unit tests.
#[cfg(test)]
pub(crate) mod test_support {
    /// One step of the xorshift64 generator the randomized unit tests draw from: advances
    /// `state` and answers it.
    pub fn xorshift(state: &mut u64) -> u64 {
        *state ^= *state << 13;
        *state ^= *state >> 7;
        *state ^= *state << 17;
        *state
    }

    /// Every depth-test setting of the eight-lane tests: none (no depth test) and each
    /// comparison function.
    pub const DEPTH_FUNCS: [Option<crate::common::values::CompareFunc>; 9] = {
        use crate::common::values::CompareFunc::*;
        [
            None,
            Some(Never),
            Some(Less),
            Some(Equal),
            Some(LessEqual),
            Some(Greater),
            Some(NotEqual),
            Some(GreaterEqual),
            Some(Always),
        ]
    };
}

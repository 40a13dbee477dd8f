//! Texture objects, image specification, mipmaps and sampling (OpenGL 1.5 section 3.8).

use crate::api::convert::TextureTarget;
use crate::state::tables::limits::MAX_TEXTURE_UNITS;

/// All texture state of a context (objects, bindings, per-unit enables).
#[derive(Clone, Debug, Default)]
pub struct TextureState {
    /// Per unit: enabled targets.
    enabled: [[bool; 4]; MAX_TEXTURE_UNITS],
}

impl TextureState {
    /// `glEnable`/`glDisable` of a texture target on `unit`.
    pub fn set_enabled(&mut self, unit: usize, target: TextureTarget, on: bool) {
        self.enabled[unit][target as usize] = on;
    }

    /// Whether `target` is enabled on `unit`.
    pub fn is_enabled(&self, unit: usize, target: TextureTarget) -> bool {
        self.enabled[unit][target as usize]
    }
}

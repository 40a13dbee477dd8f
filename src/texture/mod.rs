//! Texture objects, image specification, mipmaps and sampling (OpenGL 1.5 section 3.8).
//!
//! - [`format`](mod@format): internal formats and their storage.
//! - [`image`]: one texture image (texels in `Arc`s, copy on write).
//! - [`object`]: texture objects, parameters, completeness, snapshots.
//! - [`pixels`]: unpacking client images and packing for `glGetTexImage`.
//! - [`mipmap`]: `GL_GENERATE_MIPMAP`'s box filter.
//! - [`s3tc`]: DXT1/3/5 decoding and encoding.
//! - [`sample`]: the sampler ([`BoundTexture`]): wrap, filters, λ, cube maps, 3D, depth
//!   comparison, anisotropy.
//!
//! The entry points live in `state/textures.rs`.

pub mod format;
pub mod image;
pub mod mipmap;
pub mod object;
pub mod pixels;
pub mod s3tc;
pub mod sample;
pub mod simd;

use std::collections::{HashMap, HashSet};

use crate::common::limits::MAX_TEXTURE_UNITS;
use crate::common::values::TextureTarget;

pub use format::{BaseFormat, InternalFormat, S3tcFormat};
pub use image::TexImage;
pub use object::{SamplerParams, TextureObject};
pub use sample::BoundTexture;

/// Number of texture targets (1D, 2D, 3D, cube map, rectangle).
pub const TARGET_COUNT: usize = 5;

/// Targets in order of precedence, highest first (section 3.8.15).
pub const TARGET_PRECEDENCE: [TextureTarget; TARGET_COUNT] = [
    TextureTarget::CubeMap,
    TextureTarget::T3D,
    // ARB_texture_rectangle: between 3D and 2D.
    TextureTarget::Rectangle,
    TextureTarget::T2D,
    TextureTarget::T1D,
];

/// All texture state of a context (objects, bindings, per-unit enables).
#[derive(Clone, Debug)]
pub struct TextureState {
    /// Per unit: enabled targets.
    enabled: [[bool; TARGET_COUNT]; MAX_TEXTURE_UNITS],
    /// Per unit and target: the bound name (0 = the default texture of the target).
    bindings: [[u32; TARGET_COUNT]; MAX_TEXTURE_UNITS],
    /// Named objects (created by their first bind).
    objects: HashMap<u32, TextureObject>,
    /// Names returned by `glGenTextures` and not yet bound or deleted.
    reserved: HashSet<u32>,
    /// The default texture of each target (name 0).
    defaults: [TextureObject; TARGET_COUNT],
    /// The proxy texture of each target (image parameters only, no texels).
    pub(crate) proxies: [TextureObject; TARGET_COUNT],
    next_name: u32,
}

impl Default for TextureState {
    fn default() -> Self {
        let targets = [
            TextureTarget::T1D,
            TextureTarget::T2D,
            TextureTarget::T3D,
            TextureTarget::CubeMap,
            TextureTarget::Rectangle,
        ];
        TextureState {
            enabled: [[false; TARGET_COUNT]; MAX_TEXTURE_UNITS],
            bindings: [[0; TARGET_COUNT]; MAX_TEXTURE_UNITS],
            objects: HashMap::new(),
            reserved: HashSet::new(),
            defaults: targets.map(|t| TextureObject::new(Some(t))),
            proxies: targets.map(|t| TextureObject::new(Some(t))),
            next_name: 1,
        }
    }
}

impl TextureState {
    /// `glEnable`/`glDisable` of a texture target on `unit`.
    pub fn set_enabled(&mut self, unit: usize, target: TextureTarget, on: bool) {
        if let Some(u) = self.enabled.get_mut(unit) {
            u[target as usize] = on;
        }
    }

    /// Whether `target` is enabled on `unit`.
    pub fn is_enabled(&self, unit: usize, target: TextureTarget) -> bool {
        self.enabled.get(unit).is_some_and(|u| u[target as usize])
    }

    /// The name bound to `target` on `unit`.
    pub fn binding(&self, unit: usize, target: TextureTarget) -> u32 {
        self.bindings.get(unit).map_or(0, |b| b[target as usize])
    }

    /// The object bound to `target` on `unit`.
    pub fn bound(&self, unit: usize, target: TextureTarget) -> &TextureObject {
        let name = self.binding(unit, target);
        self.objects
            .get(&name)
            .unwrap_or(&self.defaults[target as usize])
    }

    /// The object bound to `target` on `unit`, mutably.
    pub fn bound_mut(&mut self, unit: usize, target: TextureTarget) -> &mut TextureObject {
        let name = self.binding(unit, target);
        match self.objects.get_mut(&name) {
            Some(o) => o,
            None => &mut self.defaults[target as usize],
        }
    }

    /// The snapshot of what `unit` samples: the object bound to the unit's highest-precedence
    /// enabled target (cube map > 3D > 2D > 1D), or `None` when no target is enabled or that
    /// texture is incomplete (the unit then behaves as disabled).
    pub fn bound_for_unit(&self, unit: usize) -> Option<BoundTexture> {
        let target = TARGET_PRECEDENCE
            .into_iter()
            .find(|&t| self.is_enabled(unit, t))?;
        self.bound(unit, target).snapshot(target)
    }

    /// `glGenTextures`: `n` unused names.
    pub fn gen_names(&mut self, out: &mut [u32]) {
        for slot in out.iter_mut() {
            while self.next_name == 0
                || self.objects.contains_key(&self.next_name)
                || self.reserved.contains(&self.next_name)
            {
                self.next_name = self.next_name.wrapping_add(1);
            }
            *slot = self.next_name;
            self.reserved.insert(self.next_name);
            self.next_name = self.next_name.wrapping_add(1);
        }
    }

    /// The object named `name`, if it exists (was bound).
    pub fn object(&self, name: u32) -> Option<&TextureObject> {
        self.objects.get(&name)
    }

    pub fn object_mut(&mut self, name: u32) -> Option<&mut TextureObject> {
        self.objects.get_mut(&name)
    }

    /// `glBindTexture` after validation: creates the object on first bind. Returns false when
    /// the object exists with another target (`GL_INVALID_OPERATION`).
    pub fn bind(&mut self, unit: usize, target: TextureTarget, name: u32) -> bool {
        if name != 0 {
            match self.objects.get(&name) {
                Some(o) if o.target.is_some_and(|t| t != target) => return false,
                Some(_) => {}
                None => {
                    self.reserved.remove(&name);
                    self.objects.insert(name, TextureObject::new(Some(target)));
                }
            }
        }
        if let Some(b) = self.bindings.get_mut(unit) {
            b[target as usize] = name;
        }
        true
    }

    /// `glDeleteTextures` of one name: unbinds it from every unit, then deletes it.
    pub fn delete(&mut self, name: u32) {
        if name == 0 {
            return;
        }
        self.reserved.remove(&name);
        if self.objects.remove(&name).is_some() {
            for unit in self.bindings.iter_mut() {
                for b in unit.iter_mut() {
                    if *b == name {
                        *b = 0;
                    }
                }
            }
        }
    }

    /// Whether `name` names a texture object (`glIsTexture`).
    pub fn is_texture(&self, name: u32) -> bool {
        name != 0 && self.objects.contains_key(&name)
    }

    /// The proxy object of a target.
    pub fn proxy(&self, target: TextureTarget) -> &TextureObject {
        &self.proxies[target as usize]
    }

    pub fn proxy_mut(&mut self, target: TextureTarget) -> &mut TextureObject {
        &mut self.proxies[target as usize]
    }
}

/// What `GL_TEXTURE_BIT` saves of the texture objects (table 6.15, 6.16): per unit the enables
/// and bindings of each target, and the parameters of every bound object (including the
/// defaults), keyed by name so that they are restored to the same objects.
#[derive(Clone, Debug)]
pub struct TextureAttrib {
    enabled: [[bool; TARGET_COUNT]; MAX_TEXTURE_UNITS],
    bindings: [[u32; TARGET_COUNT]; MAX_TEXTURE_UNITS],
    params: Vec<(u32, usize, SamplerParams, f32)>,
}

impl TextureState {
    /// The state `GL_TEXTURE_BIT` pushes.
    pub fn save_attrib(&self) -> TextureAttrib {
        let mut params = Vec::new();
        for unit in 0..MAX_TEXTURE_UNITS {
            for t in 0..TARGET_COUNT {
                let name = self.bindings[unit][t];
                if params
                    .iter()
                    .any(|p: &(u32, usize, _, _)| p.0 == name && p.1 == t)
                {
                    continue;
                }
                let o = self.objects.get(&name).unwrap_or(&self.defaults[t]);
                params.push((name, t, o.params, o.priority));
            }
        }
        TextureAttrib {
            enabled: self.enabled,
            bindings: self.bindings,
            params,
        }
    }

    /// Restores the per-unit target enables (`GL_ENABLE_BIT` and `GL_TEXTURE_BIT`).
    pub fn restore_enables(&mut self, a: &TextureAttrib) {
        self.enabled = a.enabled;
    }

    /// Restores bindings and the saved objects' parameters. An object deleted since the push
    /// is not recreated: its binding reverts to the default texture.
    pub fn restore_attrib(&mut self, a: &TextureAttrib) {
        self.enabled = a.enabled;
        for (unit, targets) in a.bindings.iter().enumerate() {
            for (t, &name) in targets.iter().enumerate() {
                self.bindings[unit][t] = if name == 0 || self.objects.contains_key(&name) {
                    name
                } else {
                    0
                };
            }
        }
        for (name, t, params, priority) in &a.params {
            let o = if *name == 0 {
                Some(&mut self.defaults[*t])
            } else {
                self.objects.get_mut(name)
            };
            if let Some(o) = o {
                o.params = *params;
                o.priority = *priority;
            }
        }
    }
}

//! Texture objects, image specification, mipmaps and sampling (OpenGL 1.5 section 3.8).
//!
//! - [`format`](mod@format): internal formats and their storage.
//! - [`image`]: one texture image (texels in `Arc`s, copy on write).
//! - [`object`]: texture objects, parameters, completeness, snapshots.
//! - [`pixels`]: unpacking client images and packing for `glGetTexImage`.
//! - [`mipmap`]: `GL_GENERATE_MIPMAP`'s box filter.
//! - [`s3tc`]: DXT1/3/5 decoding and encoding.
//! - [`fixed`]: the fixed-point filtering tier (8-bit weights, as llvmpipe).
//! - [`sample`]: the sampler ([`BoundTexture`]): wrap, filters, λ, cube maps, 3D, depth
//!   comparison, anisotropy.
//! - [`sampler`]: ARB_sampler_objects' named sampler objects.
//!
//! The entry points live in `state/textures.rs`.

pub mod fixed;
pub mod format;
pub mod image;
pub mod mipmap;
pub mod object;
pub mod pixels;
pub mod s3tc;
pub mod sample;
pub mod sampler;
pub mod simd;

use std::collections::{HashMap, HashSet};
use std::ops::{Deref, DerefMut};
use std::sync::Arc;

use parking_lot::{
    MappedRwLockReadGuard, MappedRwLockWriteGuard, RwLock, RwLockReadGuard, RwLockWriteGuard,
};

use crate::common::limits::MAX_TEXTURE_UNITS;
use crate::common::values::TextureTarget;

pub use format::{BaseFormat, InternalFormat, S3tcFormat};
pub use image::TexImage;
pub use object::{SamplerParams, TextureObject};
pub use sample::BoundTexture;
pub use sampler::{SamplerNames, SamplerObject};

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

/// The named texture objects of a share group: every context created sharing objects with
/// another holds the same `Arc` (GLX 1.4 section 2.3: texture objects are shared, the default
/// textures of name 0 are not).
#[derive(Debug)]
pub struct TextureNames {
    /// Named objects (created by their first bind).
    objects: HashMap<u32, TextureObject>,
    /// Names returned by `glGenTextures` and not yet bound or deleted.
    reserved: HashSet<u32>,
    next_name: u32,
    /// ARB_sampler_objects' sampler objects, shared as the textures are (their own names).
    samplers: SamplerNames,
}

impl Default for TextureNames {
    fn default() -> Self {
        TextureNames {
            objects: HashMap::new(),
            reserved: HashSet::new(),
            next_name: 1,
            samplers: SamplerNames::default(),
        }
    }
}

/// A texture object borrowed from a context: its own default texture or proxy, or a named
/// object behind the share group's lock (held while this lives).
pub enum ObjectRef<'a> {
    Own(&'a TextureObject),
    Named(MappedRwLockReadGuard<'a, TextureObject>),
}

impl Deref for ObjectRef<'_> {
    type Target = TextureObject;
    fn deref(&self) -> &TextureObject {
        match self {
            ObjectRef::Own(o) => o,
            ObjectRef::Named(g) => g,
        }
    }
}

/// A texture object borrowed mutably (see [`ObjectRef`]).
pub enum ObjectMut<'a> {
    Own(&'a mut TextureObject),
    Named(MappedRwLockWriteGuard<'a, TextureObject>),
}

impl Deref for ObjectMut<'_> {
    type Target = TextureObject;
    fn deref(&self) -> &TextureObject {
        match self {
            ObjectMut::Own(o) => o,
            ObjectMut::Named(g) => g,
        }
    }
}

impl DerefMut for ObjectMut<'_> {
    fn deref_mut(&mut self) -> &mut TextureObject {
        match self {
            ObjectMut::Own(o) => o,
            ObjectMut::Named(g) => g,
        }
    }
}

/// All texture state of a context (objects, bindings, per-unit enables).
#[derive(Debug)]
pub struct TextureState {
    /// Per unit: enabled targets.
    enabled: [[bool; TARGET_COUNT]; MAX_TEXTURE_UNITS],
    /// Per unit and target: the bound name (0 = the default texture of the target).
    bindings: [[u32; TARGET_COUNT]; MAX_TEXTURE_UNITS],
    /// Per unit: the bound sampler object (ARB_sampler_objects; 0 = none, the texture's own
    /// sampler state applies). Not part of any attribute group.
    sampler_bindings: [u32; MAX_TEXTURE_UNITS],
    /// The named objects, shared with the contexts of the share group. Reads take the lock
    /// recursively (a context may hold two objects at once; borrows keep a writer exclusive
    /// within the context), and nothing below `state` reads it: snapshots hold the texels'
    /// `Arc`s.
    names: Arc<RwLock<TextureNames>>,
    /// The default texture of each target (name 0).
    defaults: [TextureObject; TARGET_COUNT],
    /// The proxy texture of each target (image parameters only, no texels).
    pub(crate) proxies: [TextureObject; TARGET_COUNT],
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
            sampler_bindings: [0; MAX_TEXTURE_UNITS],
            names: Default::default(),
            defaults: targets.map(|t| TextureObject::new(Some(t))),
            proxies: targets.map(|t| TextureObject::new(Some(t))),
        }
    }
}

impl TextureState {
    /// The named objects (the share group's handle).
    pub(crate) fn names(&self) -> &Arc<RwLock<TextureNames>> {
        &self.names
    }

    /// Uses the named objects of a share group (for a new context: its own names are dropped).
    pub(crate) fn set_names(&mut self, names: Arc<RwLock<TextureNames>>) {
        self.names = names;
    }

    fn read(&self) -> RwLockReadGuard<'_, TextureNames> {
        self.names.read_recursive()
    }

    fn write(&self) -> RwLockWriteGuard<'_, TextureNames> {
        self.names.write()
    }

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
    /// A name another context of the share group deleted reads as the default texture.
    pub fn bound(&self, unit: usize, target: TextureTarget) -> ObjectRef<'_> {
        let name = self.binding(unit, target);
        if name != 0 {
            if let Some(o) = self.object(name) {
                return ObjectRef::Named(o);
            }
        }
        ObjectRef::Own(&self.defaults[target as usize])
    }

    /// The object bound to `target` on `unit`, mutably.
    pub fn bound_mut(&mut self, unit: usize, target: TextureTarget) -> ObjectMut<'_> {
        let name = self.binding(unit, target);
        if name != 0 {
            if let Ok(o) =
                RwLockWriteGuard::try_map(self.names.write(), |n| n.objects.get_mut(&name))
            {
                return ObjectMut::Named(o);
            }
        }
        ObjectMut::Own(&mut self.defaults[target as usize])
    }

    /// The snapshot of what `unit` samples: the object bound to the unit's highest-precedence
    /// enabled target (cube map > 3D > 2D > 1D), or `None` when no target is enabled or that
    /// texture is incomplete (the unit then behaves as disabled).
    ///
    /// With a sampler object bound to the unit, the snapshot takes the sampler's state in
    /// place of the texture's (once per draw-state rebuild, never per fragment); the texture
    /// is then complete or not by that state, and incomplete when a rectangle texture gets
    /// state its `glTexParameter` would refuse (ARB_sampler_objects, section 3.9.2). A
    /// sampler name another context of the share group deleted counts as none.
    pub fn bound_for_unit(&self, unit: usize) -> Option<BoundTexture> {
        let target = TARGET_PRECEDENCE
            .into_iter()
            .find(|&t| self.is_enabled(unit, t))?;
        let obj = self.bound(unit, target);
        let sampler = self.sampler_binding(unit);
        if sampler == 0 {
            return obj.snapshot(target);
        }
        let params = match self.read().samplers.get(sampler) {
            Some(s) => obj.params.with_sampler(&s.params),
            None => return obj.snapshot(target),
        };
        if target == TextureTarget::Rectangle && !params.fit_rectangle() {
            return None;
        }
        obj.snapshot_with(target, params)
    }

    // ----- ARB_sampler_objects

    /// The sampler object bound to `unit` (0 for none).
    pub fn sampler_binding(&self, unit: usize) -> u32 {
        self.sampler_bindings.get(unit).copied().unwrap_or(0)
    }

    /// `glGenSamplers`: `out.len()` new sampler objects.
    pub fn gen_samplers(&mut self, out: &mut [u32]) {
        self.write().samplers.gen(out);
    }

    /// `glDeleteSamplers` of one name: deletes it and unbinds it from every unit of this
    /// context (as `glBindSampler(unit, 0)`). Names that are no sampler and 0 are ignored.
    pub fn delete_sampler(&mut self, name: u32) {
        if name == 0 || !self.write().samplers.delete(name) {
            return;
        }
        for b in self.sampler_bindings.iter_mut() {
            if *b == name {
                *b = 0;
            }
        }
    }

    /// Whether `name` names a sampler object (`glIsSampler`).
    pub fn is_sampler(&self, name: u32) -> bool {
        name != 0 && self.read().samplers.contains(name)
    }

    /// `glBindSampler` after the unit check: false when `name` is neither 0 nor a sampler
    /// object (`GL_INVALID_OPERATION`).
    pub fn bind_sampler(&mut self, unit: usize, name: u32) -> bool {
        if name != 0 && !self.is_sampler(name) {
            return false;
        }
        if let Some(b) = self.sampler_bindings.get_mut(unit) {
            *b = name;
        }
        true
    }

    /// The sampler object `name`, if it exists.
    pub fn sampler(&self, name: u32) -> Option<MappedRwLockReadGuard<'_, SamplerObject>> {
        RwLockReadGuard::try_map(self.read(), |n| n.samplers.get(name)).ok()
    }

    /// The sampler object `name`, mutably, if it exists.
    pub fn sampler_mut(&mut self, name: u32) -> Option<MappedRwLockWriteGuard<'_, SamplerObject>> {
        RwLockWriteGuard::try_map(self.write(), |n| n.samplers.get_mut(name)).ok()
    }

    /// `glGenTextures`: `n` unused names.
    pub fn gen_names(&mut self, out: &mut [u32]) {
        let mut n = self.write();
        for slot in out.iter_mut() {
            while n.next_name == 0
                || n.objects.contains_key(&n.next_name)
                || n.reserved.contains(&n.next_name)
            {
                n.next_name = n.next_name.wrapping_add(1);
            }
            *slot = n.next_name;
            let name = n.next_name;
            n.reserved.insert(name);
            n.next_name = name.wrapping_add(1);
        }
    }

    /// The object named `name`, if it exists (was bound).
    pub fn object(&self, name: u32) -> Option<MappedRwLockReadGuard<'_, TextureObject>> {
        RwLockReadGuard::try_map(self.read(), |n| n.objects.get(&name)).ok()
    }

    pub fn object_mut(&mut self, name: u32) -> Option<MappedRwLockWriteGuard<'_, TextureObject>> {
        RwLockWriteGuard::try_map(self.write(), |n| n.objects.get_mut(&name)).ok()
    }

    /// `glBindTexture` after validation: creates the object on first bind. Returns false when
    /// the object exists with another target (`GL_INVALID_OPERATION`).
    pub fn bind(&mut self, unit: usize, target: TextureTarget, name: u32) -> bool {
        if name != 0 {
            let mut n = self.write();
            match n.objects.get(&name) {
                Some(o) if o.target.is_some_and(|t| t != target) => return false,
                Some(_) => {}
                None => {
                    n.reserved.remove(&name);
                    n.objects.insert(name, TextureObject::new(Some(target)));
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
        let removed = {
            let mut n = self.write();
            n.reserved.remove(&name);
            n.objects.remove(&name).is_some()
        };
        if removed {
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
        name != 0 && self.read().objects.contains_key(&name)
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
        let names = self.read();
        for unit in 0..MAX_TEXTURE_UNITS {
            for t in 0..TARGET_COUNT {
                let name = self.bindings[unit][t];
                if params
                    .iter()
                    .any(|p: &(u32, usize, _, _)| p.0 == name && p.1 == t)
                {
                    continue;
                }
                let o = names.objects.get(&name).unwrap_or(&self.defaults[t]);
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
        let mut names = self.names.write();
        for (unit, targets) in a.bindings.iter().enumerate() {
            for (t, &name) in targets.iter().enumerate() {
                self.bindings[unit][t] = if name == 0 || names.objects.contains_key(&name) {
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
                names.objects.get_mut(name)
            };
            if let Some(o) = o {
                o.params = *params;
                o.priority = *priority;
            }
        }
    }
}

//! ARB_sampler_objects: named sampler objects, the sampling state of a texture object
//! (table 6.23) without its images. A sampler bound to a texture unit supplies that state in
//! place of the bound texture's (see [`super::TextureState::bound_for_unit`]); the names live
//! with the texture names of the share group (the extension's issue 8: shared as textures
//! are).

use std::collections::HashMap;

use super::object::SamplerParams;

/// One sampler object.
#[derive(Clone, Debug, Default)]
pub struct SamplerObject {
    /// The sampler state (only the fields [`SamplerParams::with_sampler`] takes mean
    /// anything). The border colour is kept as given (clamped when it is applied); one given
    /// as integers (`glSamplerParameterIiv`/`Iuiv`) is kept as the integers' bits, which the
    /// integer queries return unchanged (a query of another type is undefined by the
    /// extension; Mesa answers alike).
    pub params: SamplerParams,
}

/// The sampler objects of a share group.
#[derive(Debug)]
pub struct SamplerNames {
    objects: HashMap<u32, SamplerObject>,
    next_name: u32,
}

impl Default for SamplerNames {
    fn default() -> Self {
        SamplerNames {
            objects: HashMap::new(),
            next_name: 1,
        }
    }
}

impl SamplerNames {
    /// `glGenSamplers`: `out.len()` unused names, each a sampler object with the initial
    /// state from now on (issue 10: "as if they start existing when GenSamplers creates
    /// their names").
    pub fn gen(&mut self, out: &mut [u32]) {
        for slot in out.iter_mut() {
            while self.next_name == 0 || self.objects.contains_key(&self.next_name) {
                self.next_name = self.next_name.wrapping_add(1);
            }
            let name = self.next_name;
            self.objects.insert(name, SamplerObject::default());
            *slot = name;
            self.next_name = name.wrapping_add(1);
        }
    }

    /// Deletes `name`; whether it was a sampler object.
    pub fn delete(&mut self, name: u32) -> bool {
        self.objects.remove(&name).is_some()
    }

    pub fn get(&self, name: u32) -> Option<&SamplerObject> {
        self.objects.get(&name)
    }

    pub fn get_mut(&mut self, name: u32) -> Option<&mut SamplerObject> {
        self.objects.get_mut(&name)
    }

    /// Whether `name` names a sampler object (never 0).
    pub fn contains(&self, name: u32) -> bool {
        self.objects.contains_key(&name)
    }
}

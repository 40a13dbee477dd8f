//! Share groups (GLX 1.4 section 2.3, EGL 1.4 section 3.7.1, `OSMesaCreateContextExt`'s
//! `sharelist`): contexts created sharing with another see the same texture objects, display
//! lists, buffer objects and EXT_framebuffer_object's framebuffer and renderbuffer objects,
//! names and contents (a renderbuffer's content as last stored by the context drawing into it:
//! at a change of its binding or attachments). Everything else (bindings, the default
//! textures of name 0, the list being compiled, the framebuffer) stays per context.
//!
//! Each namespace sits behind its own `Arc<RwLock<..>>` in its module, held by every context
//! of the group; an unshared context takes the same uncontended locks. The application
//! synchronises use across threads (GL leaves concurrent changes undefined); the locks only
//! keep each namespace consistent. A context sees another's change to an object it has
//! bound after binding it again or being made current again (the rule of GL 3.2's
//! appendix D.3): its cached draw snapshot holds the texels it sampled.

use std::sync::Arc;

use parking_lot::RwLock;

use super::arrays::BufferNames;
use super::lists::ListNames;
use super::Context;
use crate::texture::TextureNames;

/// The shared namespaces of one share group (cheap to clone: four `Arc`s).
#[derive(Clone)]
pub struct ShareGroup {
    textures: Arc<RwLock<TextureNames>>,
    lists: Arc<RwLock<ListNames>>,
    buffers: Arc<RwLock<BufferNames>>,
    framebuffers: Arc<RwLock<super::fbo::FboNames>>,
}

impl ShareGroup {
    /// Whether `a` and `b` are the same group.
    pub fn same(a: &ShareGroup, b: &ShareGroup) -> bool {
        Arc::ptr_eq(&a.textures, &b.textures)
            && Arc::ptr_eq(&a.lists, &b.lists)
            && Arc::ptr_eq(&a.buffers, &b.buffers)
            && Arc::ptr_eq(&a.framebuffers, &b.framebuffers)
    }
}

impl Context {
    /// This context's share group.
    pub fn share_group(&self) -> ShareGroup {
        ShareGroup {
            textures: self.textures.names().clone(),
            lists: self.lists.names().clone(),
            buffers: self.client.buffers.names().clone(),
            framebuffers: self.fbo.shared().clone(),
        }
    }

    /// Joins `group` (for a context just created: the named objects it had are dropped).
    pub fn join_share_group(&mut self, group: &ShareGroup) {
        self.textures.set_names(group.textures.clone());
        self.lists.set_names(group.lists.clone());
        self.client.buffers.set_names(group.buffers.clone());
        self.fbo.set_shared(group.framebuffers.clone());
        self.invalidate();
    }

    /// Forgets the cached draw snapshot, so that the next draw samples the shared objects as
    /// they are now (the window-system layers call it when the context is made current).
    pub fn refresh_shared_objects(&mut self) {
        self.invalidate();
    }
}

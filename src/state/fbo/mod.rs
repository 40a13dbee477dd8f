//! EXT_framebuffer_object and ARB_framebuffer_object: framebuffer and renderbuffer objects,
//! attachments, completeness (section 4.4 of the extensions) and `glGenerateMipmap`.
//!
//! ARB_framebuffer_object is EXT_framebuffer_object, EXT_framebuffer_blit,
//! EXT_framebuffer_multisample and EXT_packed_depth_stencil in one, with these differences,
//! which tilegl applies whichever name a command is called by (one context has one set of
//! rules; Mesa does the same): attachments of different sizes are complete (drawing is
//! limited to the common rectangle), ALPHA, LUMINANCE, LUMINANCE_ALPHA, INTENSITY, RED and RG
//! images are colour-renderable, `GL_DEPTH_STENCIL_ATTACHMENT` names both the depth and the
//! stencil points, and attachment queries report the image's format. Only the unsuffixed
//! `glBindFramebuffer`/`glBindRenderbuffer` refuse names `glGen*` did not return (the EXT
//! commands create objects for any name). `GL_MAX_SAMPLES` is 0 (the state table's minimum:
//! no multisample renderbuffers).
//!
//! How drawing reaches an attached image: while a framebuffer object is bound, the context's
//! tiled [`Framebuffer`] (what the scene, clears and pixel commands write and read) is one
//! made from the object's attachments, and the window's framebuffer is parked beside it. The
//! tiles are loaded from the attached images when the object becomes current or after
//! anything may have changed them (`FboState::stale`), and stored back into the images before
//! anything else can look at them: a change of binding or attachment, a texture command on
//! the active unit, `glGetTexImage`, a deletion, `glRenderbufferStorageEXT`. Tiles hold RGBA8
//! colour, so a colour attachment keeps 8 bits per component of what is drawn into it.
//!
//! A texture sampled while it is attached to the framebuffer being drawn (the feedback loop
//! of section 4.4.3) samples its content as of the last store: undefined by the
//! specification, and never a crash.

mod blit;
mod images;

use std::collections::{HashMap, HashSet};
use std::sync::Arc;

use parking_lot::{RwLock, RwLockReadGuard, RwLockWriteGuard};

use super::color_buffers::BufferSelection;
use super::Context;
use crate::common::values::{
    AttachmentParam, FboAttachment, RenderbufferKind, RenderbufferParam, TexImageTarget,
    TextureTarget,
};
use crate::framebuffer::{Framebuffer, FramebufferConfig};
use crate::gl::convert;
use crate::gl::enums::*;
use crate::texture::object::{level_count, MAX_3D_TEXTURE_SIZE};

/// `GL_MAX_RENDERBUFFER_SIZE_EXT`: the largest framebuffer tilegl makes (the viewport limit).
pub const MAX_RENDERBUFFER_SIZE: i32 = crate::common::limits::MAX_VIEWPORT_DIM;
/// `GL_MAX_COLOR_ATTACHMENTS_EXT` (without ARB_draw_buffers one colour buffer is drawn).
pub const MAX_COLOR_ATTACHMENTS: i32 = 1;
/// `GL_MAX_SAMPLES` (ARB_framebuffer_object): 0, no multisample renderbuffers.
pub const MAX_SAMPLES: i32 = 0;

/// What an attachment point holds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) enum Attachment {
    #[default]
    None,
    Texture {
        name: u32,
        /// The image target given (`textarget`): selects the face of a cube map.
        target: TexImageTarget,
        level: usize,
        zoffset: i32,
    },
    Renderbuffer(u32),
}

/// A framebuffer object: its three attachment points and its draw and read buffers (the
/// extension moves `GL_DRAW_BUFFER` and `GL_READ_BUFFER` into the object).
#[derive(Clone, Copy, Debug)]
pub(crate) struct FramebufferObject {
    pub color: Attachment,
    pub depth: Attachment,
    pub stencil: Attachment,
    pub buffers: BufferSelection,
}

impl Default for FramebufferObject {
    fn default() -> Self {
        FramebufferObject {
            color: Attachment::None,
            depth: Attachment::None,
            stencil: Attachment::None,
            buffers: BufferSelection {
                draw: GL_COLOR_ATTACHMENT0_EXT,
                read: GL_COLOR_ATTACHMENT0_EXT,
            },
        }
    }
}

impl FramebufferObject {
    /// Sets the attachment point `a` (both points for `GL_DEPTH_STENCIL_ATTACHMENT`).
    pub(crate) fn attach(&mut self, a: FboAttachment, value: Attachment) {
        match a {
            FboAttachment::Color0 => self.color = value,
            FboAttachment::Depth => self.depth = value,
            FboAttachment::Stencil => self.stencil = value,
            FboAttachment::DepthStencil => {
                self.depth = value;
                self.stencil = value;
            }
        }
    }

    /// What the point `a` holds; `None` for `GL_DEPTH_STENCIL_ATTACHMENT` when the depth and
    /// stencil points hold different images.
    fn attachment(&self, a: FboAttachment) -> Option<Attachment> {
        match a {
            FboAttachment::Color0 => Some(self.color),
            FboAttachment::Depth => Some(self.depth),
            FboAttachment::Stencil => Some(self.stencil),
            FboAttachment::DepthStencil => (self.depth == self.stencil).then_some(self.depth),
        }
    }
}

/// A renderbuffer object and its image (row-major from the bottom row).
#[derive(Clone, Debug)]
pub(crate) struct Renderbuffer {
    /// The `internalformat` given (`GL_RGBA` before any storage, as the state table says).
    pub internal_format: GLenum,
    pub kind: RenderbufferKind,
    pub width: i32,
    pub height: i32,
    pub color: Vec<[u8; 4]>,
    /// Depth values in `0..=depth_max(bits)`.
    pub depth: Vec<u32>,
    pub stencil: Vec<u8>,
}

impl Default for Renderbuffer {
    fn default() -> Self {
        Renderbuffer {
            internal_format: GL_RGBA,
            kind: RenderbufferKind::Color { alpha: true },
            width: 0,
            height: 0,
            color: Vec::new(),
            depth: Vec::new(),
            stencil: Vec::new(),
        }
    }
}

/// The framebuffer and renderbuffer objects of a share group (the extension's objects are
/// shared like textures: `state::share`).
#[derive(Debug, Default)]
pub struct FboNames {
    framebuffers: HashMap<u32, FramebufferObject>,
    framebuffer_names: HashSet<u32>,
    renderbuffers: HashMap<u32, Renderbuffer>,
    renderbuffer_names: HashSet<u32>,
}

/// Framebuffer and renderbuffer objects, the bindings and the parked window framebuffer.
#[derive(Debug, Default)]
pub(crate) struct FboState {
    names: Arc<RwLock<FboNames>>,
    /// `GL_FRAMEBUFFER_BINDING_EXT` (= `GL_DRAW_FRAMEBUFFER_BINDING_EXT`): the object drawn
    /// into, whose images the context's tiles hold.
    pub bound: u32,
    /// `GL_READ_FRAMEBUFFER_BINDING_EXT` (EXT_framebuffer_blit): the object read from. When it
    /// differs from `bound`, read commands make it current for their duration
    /// (`Context::with_framebuffer_bound`).
    pub read_bound: u32,
    /// `GL_RENDERBUFFER_BINDING_EXT`.
    pub bound_renderbuffer: u32,
    /// The window's framebuffer and buffer selection while an object is bound.
    window: Option<(Framebuffer, BufferSelection)>,
    /// The tiles no longer show the attached images: reload before the next use.
    pub stale: bool,
    /// The status of the bound object when its tiles were loaded.
    status: GLenum,
}

impl FboState {
    pub(crate) fn names(&self) -> RwLockReadGuard<'_, FboNames> {
        self.names.read_recursive()
    }

    pub(crate) fn names_mut(&self) -> RwLockWriteGuard<'_, FboNames> {
        self.names.write()
    }

    /// The shared namespace (for `state::share`).
    pub(crate) fn shared(&self) -> &Arc<RwLock<FboNames>> {
        &self.names
    }

    /// Uses a share group's objects (for a new context: its own are dropped).
    pub(crate) fn set_shared(&mut self, names: Arc<RwLock<FboNames>>) {
        self.names = names;
    }

    /// The bound object's state (a copy), if it exists.
    pub(crate) fn bound_object(&self) -> Option<FramebufferObject> {
        self.names().framebuffers.get(&self.bound).copied()
    }
}

fn gen_names(used: impl Fn(u32) -> bool, reserved: &mut HashSet<u32>, out: &mut [GLuint]) {
    let mut next = 1u32;
    for slot in out.iter_mut() {
        while used(next) || reserved.contains(&next) {
            next += 1;
        }
        reserved.insert(next);
        *slot = next;
        next += 1;
    }
}

impl Context {
    // ----- framebuffer objects

    pub(crate) fn gen_framebuffers_ext(&mut self, n: GLsizei, framebuffers: &mut [GLuint]) {
        if n < 0 || framebuffers.len() < n as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let mut guard = self.fbo.names_mut();
        let s = &mut *guard;
        let objects = &s.framebuffers;
        gen_names(
            |k| objects.contains_key(&k),
            &mut s.framebuffer_names,
            &mut framebuffers[..n as usize],
        );
    }

    pub(crate) fn is_framebuffer_ext(&mut self, framebuffer: GLuint) -> GLboolean {
        self.fbo.names().framebuffers.contains_key(&framebuffer) as GLboolean
    }

    pub(crate) fn bind_framebuffer_ext(&mut self, target: GLenum, framebuffer: GLuint) {
        if !convert::is_framebuffer_target(target) {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        if framebuffer != 0 {
            let mut names = self.fbo.names_mut();
            names.framebuffer_names.remove(&framebuffer);
            names.framebuffers.entry(framebuffer).or_default();
        }
        // EXT_framebuffer_blit: GL_FRAMEBUFFER_EXT binds both the draw and the read target.
        if target != GL_READ_FRAMEBUFFER_EXT {
            self.switch_framebuffer(framebuffer);
        }
        if target != GL_DRAW_FRAMEBUFFER_EXT {
            self.fbo.read_bound = framebuffer;
        }
    }

    /// ARB_framebuffer_object's `glBindFramebuffer`: as `glBindFramebufferEXT`, but a name
    /// that `glGenFramebuffers` did not return (or that was deleted since) is
    /// `GL_INVALID_OPERATION` (section 4.4.1).
    pub(crate) fn bind_framebuffer(&mut self, target: GLenum, framebuffer: GLuint) {
        if !convert::is_framebuffer_target(target) {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        let known = framebuffer == 0 || {
            let names = self.fbo.names();
            names.framebuffers.contains_key(&framebuffer)
                || names.framebuffer_names.contains(&framebuffer)
        };
        if !known {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        self.bind_framebuffer_ext(target, framebuffer);
    }

    /// Runs `f` with the framebuffer `name` (0: the window) current, as drawn and read
    /// framebuffer, then makes the previous draw framebuffer current again. Read commands
    /// use it when the read binding differs from the draw binding (EXT_framebuffer_blit):
    /// the tiles are the draw framebuffer's only, so the read one is loaded for the command.
    pub(crate) fn with_framebuffer_bound<R>(
        &mut self,
        name: u32,
        f: impl FnOnce(&mut Context) -> R,
    ) -> R {
        let draw = self.fbo.bound;
        if name == draw {
            return f(self);
        }
        self.switch_framebuffer(name);
        let r = f(self);
        self.switch_framebuffer(draw);
        r
    }

    /// Whether the read binding differs from the draw binding (the read commands then run
    /// through [`Context::with_framebuffer_bound`]).
    #[inline]
    pub(crate) fn reads_elsewhere(&self) -> bool {
        self.fbo.read_bound != self.fbo.bound
    }

    /// `GL_READ_BUFFER`: the read buffer of the read framebuffer.
    pub(crate) fn read_buffer_selected(&self) -> GLenum {
        if !self.reads_elsewhere() {
            return self.buffers.read;
        }
        match (self.fbo.read_bound, &self.fbo.window) {
            (0, Some((_, b))) => b.read,
            (0, None) => self.buffers.read,
            (n, _) => self
                .fbo
                .names()
                .framebuffers
                .get(&n)
                .map_or(GL_COLOR_ATTACHMENT0_EXT, |f| f.buffers.read),
        }
    }

    /// The binding a framebuffer target names when it is not the draw binding (the tiles):
    /// `Some(read binding)` for `GL_READ_FRAMEBUFFER_EXT` while it differs.
    fn other_binding(&self, target: GLenum) -> Option<u32> {
        (target == GL_READ_FRAMEBUFFER_EXT && self.reads_elsewhere()).then_some(self.fbo.read_bound)
    }

    pub(crate) fn delete_framebuffers_ext(&mut self, n: GLsizei, framebuffers: &[GLuint]) {
        if n < 0 || framebuffers.len() < n as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        for &name in &framebuffers[..n as usize] {
            if name == 0 {
                continue;
            }
            if name == self.fbo.bound {
                self.switch_framebuffer(0);
            }
            if name == self.fbo.read_bound {
                self.fbo.read_bound = 0;
            }
            let mut names = self.fbo.names_mut();
            names.framebuffers.remove(&name);
            names.framebuffer_names.remove(&name);
        }
    }

    /// Makes `name` (0: the window) the framebuffer drawn and read: the current object's
    /// tiles go back to its images, the window's framebuffer is parked or restored, and the
    /// new object's tiles are loaded.
    fn switch_framebuffer(&mut self, name: u32) {
        let old = self.fbo.bound;
        if old == name {
            return;
        }
        self.fbo_store();
        if old == 0 {
            let cfg = self.framebuffer.config;
            let window = self.replace_framebuffer(Framebuffer::new(0, 0, cfg));
            self.fbo.window = Some((window, self.buffers));
        }
        self.fbo.bound = name;
        if name == 0 {
            if let Some((window, buffers)) = self.fbo.window.take() {
                self.replace_framebuffer(window);
                self.buffers = buffers;
            }
            self.fbo.stale = false;
        } else {
            self.buffers = self
                .fbo
                .bound_object()
                .map_or(FramebufferObject::default().buffers, |f| f.buffers);
            self.fbo_load();
        }
    }

    /// Installs `fb` as the framebuffer drawn and read (after finishing pending work) and
    /// returns the previous one.
    pub(crate) fn replace_framebuffer(&mut self, fb: Framebuffer) -> Framebuffer {
        self.flush_scene();
        let old = std::mem::replace(&mut self.framebuffer, fb);
        self.scene = crate::raster::scene::Scene::new(&self.framebuffer);
        self.spare_scene = None;
        self.recycle.clear();
        self.invalidate();
        old
    }

    /// The window's framebuffer, wherever it is (parked while an object is bound).
    pub(crate) fn window_framebuffer(&self) -> &Framebuffer {
        match &self.fbo.window {
            Some((fb, _)) => fb,
            None => &self.framebuffer,
        }
    }

    /// The window's framebuffer, for writing.
    pub(crate) fn window_framebuffer_mut(&mut self) -> &mut Framebuffer {
        match &mut self.fbo.window {
            Some((fb, _)) => fb,
            None => &mut self.framebuffer,
        }
    }

    /// `glColorMask` limited to the components the drawn colour buffer has (a framebuffer
    /// object's luminance, alpha, red, RG or RGB image keeps only its own: the others hold
    /// 0, alpha 1, as loaded, and are never written).
    pub(crate) fn color_write_mask(&self) -> [bool; 4] {
        let m = self.fragment_ops.color_mask;
        match self.framebuffer.components {
            None => m,
            Some(has) => [
                m[0] && has[0],
                m[1] && has[1],
                m[2] && has[2],
                m[3] && has[3],
            ],
        }
    }

    /// Whether a framebuffer object is bound.
    #[inline]
    pub(crate) fn fbo_bound(&self) -> bool {
        self.fbo.bound != 0
    }

    /// The check of section 4.4.4.3 for commands that draw into or read from the framebuffer:
    /// loads stale tiles, and records `GL_INVALID_FRAMEBUFFER_OPERATION_EXT` and returns
    /// false when the bound object is not complete.
    #[inline]
    pub(crate) fn framebuffer_ready(&mut self) -> bool {
        if self.fbo.bound == 0 {
            return true;
        }
        self.framebuffer_ready_slow()
    }

    /// Reloads stale tiles (after an attachment or image change), without the error.
    pub(crate) fn fbo_refresh(&mut self) {
        if self.fbo.bound != 0 && self.fbo.stale {
            self.fbo_load();
        }
    }

    #[inline(never)]
    fn framebuffer_ready_slow(&mut self) -> bool {
        if self.fbo.stale {
            self.fbo_load();
        }
        if self.fbo.status != GL_FRAMEBUFFER_COMPLETE_EXT {
            self.record_error(GL_INVALID_FRAMEBUFFER_OPERATION_EXT);
            return false;
        }
        true
    }

    /// Before a texture command changes texels or images of the active unit's textures while
    /// an object is bound: what was drawn goes into the attached images first, and the tiles
    /// are reloaded before the next use.
    pub(crate) fn fbo_before_texture_change(&mut self) {
        if self.fbo.bound != 0 {
            self.fbo_store();
            self.fbo.stale = true;
        }
    }

    /// Before a texture image is read (`glGetTexImage`): what was drawn is stored.
    pub(crate) fn fbo_before_texture_read(&mut self) {
        if self.fbo.bound != 0 {
            self.fbo_store();
        }
    }

    /// `glDeleteTextures`: an image attached to the bound object is first detached from it
    /// (section 4.4.2.3); other objects keep naming it.
    pub(crate) fn fbo_detach_texture(&mut self, name: u32) {
        let bound = self.fbo.bound;
        if bound == 0 || name == 0 {
            return;
        }
        self.fbo_store();
        self.fbo.stale = true;
        if let Some(f) = self.fbo.names_mut().framebuffers.get_mut(&bound) {
            for a in [&mut f.color, &mut f.depth, &mut f.stencil] {
                if matches!(*a, Attachment::Texture { name: n, .. } if n == name) {
                    *a = Attachment::None;
                }
            }
        }
    }

    pub(crate) fn check_framebuffer_status_ext(&mut self, target: GLenum) -> GLenum {
        if !convert::is_framebuffer_target(target) {
            self.record_error(GL_INVALID_ENUM);
            return 0;
        }
        if let Some(read) = self.other_binding(target) {
            return self.with_framebuffer_bound(read, |c| {
                c.check_framebuffer_status_ext(GL_FRAMEBUFFER_EXT)
            });
        }
        if self.fbo.bound == 0 {
            return GL_FRAMEBUFFER_COMPLETE_EXT;
        }
        self.fbo_status().0
    }

    /// The attachment point `attachment` of the object bound to `target`, after the checks
    /// every attaching command shares.
    fn attach_point(&mut self, target: GLenum, attachment: GLenum) -> Option<FboAttachment> {
        if !convert::is_framebuffer_target(target) {
            self.record_error(GL_INVALID_ENUM);
            return None;
        }
        let Some(a) = convert::fbo_attachment(attachment) else {
            self.record_error(GL_INVALID_ENUM);
            return None;
        };
        if self.fbo.bound == 0 {
            self.record_error(GL_INVALID_OPERATION);
            return None;
        }
        Some(a)
    }

    fn set_attachment(&mut self, point: FboAttachment, value: Attachment) {
        self.fbo_store();
        self.fbo.stale = true;
        let bound = self.fbo.bound;
        if let Some(f) = self.fbo.names_mut().framebuffers.get_mut(&bound) {
            f.attach(point, value);
        }
    }

    fn framebuffer_texture(
        &mut self,
        dims: usize,
        target: GLenum,
        attachment: GLenum,
        textarget: GLenum,
        texture: GLuint,
        level: GLint,
        zoffset: GLint,
    ) {
        if let Some(read) = self.other_binding(target) {
            return self.with_framebuffer_bound(read, |c| {
                c.framebuffer_texture(
                    dims,
                    GL_FRAMEBUFFER_EXT,
                    attachment,
                    textarget,
                    texture,
                    level,
                    zoffset,
                )
            });
        }
        let Some(point) = self.attach_point(target, attachment) else {
            return;
        };
        if texture == 0 {
            self.set_attachment(point, Attachment::None);
            return;
        }
        let r = (|| -> Result<Attachment, GLenum> {
            // A target outside the command's set names no texture of that target.
            let t = convert::tex_image_target(textarget)
                .filter(|t| !t.is_proxy())
                .ok_or(GL_INVALID_OPERATION)?;
            let accepted = match dims {
                1 => t == TexImageTarget::T1D,
                2 => matches!(
                    t,
                    TexImageTarget::T2D | TexImageTarget::Rectangle | TexImageTarget::CubeFace(_)
                ),
                _ => t == TexImageTarget::T3D,
            };
            if !accepted {
                return Err(GL_INVALID_OPERATION);
            }
            let object_target = self
                .textures
                .object(texture)
                .map(|o| o.target)
                .ok_or(GL_INVALID_OPERATION)?;
            if object_target != Some(t.texture_target()) {
                return Err(GL_INVALID_OPERATION);
            }
            if level < 0 || level as usize >= level_count(t.texture_target()) {
                return Err(GL_INVALID_VALUE);
            }
            if t == TexImageTarget::T3D && !(0..MAX_3D_TEXTURE_SIZE).contains(&zoffset) {
                return Err(GL_INVALID_VALUE);
            }
            Ok(Attachment::Texture {
                name: texture,
                target: t,
                level: level as usize,
                zoffset: if t == TexImageTarget::T3D { zoffset } else { 0 },
            })
        })();
        match r {
            Ok(a) => self.set_attachment(point, a),
            Err(e) => self.record_error(e),
        }
    }

    pub(crate) fn framebuffer_texture_1dext(
        &mut self,
        target: GLenum,
        attachment: GLenum,
        textarget: GLenum,
        texture: GLuint,
        level: GLint,
    ) {
        self.framebuffer_texture(1, target, attachment, textarget, texture, level, 0);
    }

    pub(crate) fn framebuffer_texture_2dext(
        &mut self,
        target: GLenum,
        attachment: GLenum,
        textarget: GLenum,
        texture: GLuint,
        level: GLint,
    ) {
        self.framebuffer_texture(2, target, attachment, textarget, texture, level, 0);
    }

    pub(crate) fn framebuffer_texture_3dext(
        &mut self,
        target: GLenum,
        attachment: GLenum,
        textarget: GLenum,
        texture: GLuint,
        level: GLint,
        zoffset: GLint,
    ) {
        self.framebuffer_texture(3, target, attachment, textarget, texture, level, zoffset);
    }

    /// `glFramebufferTextureLayer`: a layer of a 3D texture (tilegl has no array textures),
    /// as `glFramebufferTexture3D` without the `textarget`.
    pub(crate) fn framebuffer_texture_layer(
        &mut self,
        target: GLenum,
        attachment: GLenum,
        texture: GLuint,
        level: GLint,
        layer: GLint,
    ) {
        if let Some(read) = self.other_binding(target) {
            return self.with_framebuffer_bound(read, |c| {
                c.framebuffer_texture_layer(GL_FRAMEBUFFER_EXT, attachment, texture, level, layer)
            });
        }
        let Some(point) = self.attach_point(target, attachment) else {
            return;
        };
        if texture == 0 {
            self.set_attachment(point, Attachment::None);
            return;
        }
        let object_target = self.textures.object(texture).map(|o| o.target);
        if object_target != Some(Some(TextureTarget::T3D)) {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        if layer < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.framebuffer_texture(3, target, attachment, GL_TEXTURE_3D, texture, level, layer);
    }

    pub(crate) fn framebuffer_renderbuffer_ext(
        &mut self,
        target: GLenum,
        attachment: GLenum,
        renderbuffertarget: GLenum,
        renderbuffer: GLuint,
    ) {
        if let Some(read) = self.other_binding(target) {
            return self.with_framebuffer_bound(read, |c| {
                c.framebuffer_renderbuffer_ext(
                    GL_FRAMEBUFFER_EXT,
                    attachment,
                    renderbuffertarget,
                    renderbuffer,
                )
            });
        }
        let Some(point) = self.attach_point(target, attachment) else {
            return;
        };
        if renderbuffer == 0 {
            self.set_attachment(point, Attachment::None);
            return;
        }
        if !convert::is_renderbuffer_target(renderbuffertarget) {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        if !self.fbo.names().renderbuffers.contains_key(&renderbuffer) {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        self.set_attachment(point, Attachment::Renderbuffer(renderbuffer));
    }

    pub(crate) fn get_framebuffer_attachment_parameteriv_ext(
        &mut self,
        target: GLenum,
        attachment: GLenum,
        pname: GLenum,
        params: &mut [GLint],
    ) {
        if let Some(read) = self.other_binding(target) {
            return self.with_framebuffer_bound(read, |c| {
                c.get_framebuffer_attachment_parameteriv_ext(
                    GL_FRAMEBUFFER_EXT,
                    attachment,
                    pname,
                    params,
                )
            });
        }
        if !convert::is_framebuffer_target(target) {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        let Some(p) = convert::attachment_param(pname) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let r = if self.fbo.bound == 0 {
            self.default_attachment_parameter(attachment, p)
        } else {
            self.object_attachment_parameter(attachment, p)
        };
        match r {
            Ok(value) => {
                if let Some(out) = params.first_mut() {
                    *out = value;
                }
            }
            Err(e) => self.record_error(e),
        }
    }

    /// An attachment query on a framebuffer object (section 6.1.3 of ARB_framebuffer_object).
    fn object_attachment_parameter(
        &self,
        attachment: GLenum,
        p: AttachmentParam,
    ) -> Result<GLint, GLenum> {
        let point = convert::fbo_attachment(attachment).ok_or(GL_INVALID_ENUM)?;
        let f = self.fbo.bound_object().ok_or(GL_INVALID_OPERATION)?;
        // Different images at the depth and stencil points: the combined query fails.
        let a = f.attachment(point).ok_or(GL_INVALID_OPERATION)?;
        if let Some(v) = self.format_parameter(a, point, p)? {
            return Ok(v);
        }
        Ok(match (a, p) {
            (Attachment::None, AttachmentParam::ObjectType) => GL_NONE as GLint,
            (Attachment::None, AttachmentParam::ObjectName) => 0,
            // Anything else of an empty point (ARB_framebuffer_object section 6.1.3).
            (Attachment::None, _) => return Err(GL_INVALID_OPERATION),
            (Attachment::Renderbuffer(_), AttachmentParam::ObjectType) => {
                GL_RENDERBUFFER_EXT as GLint
            }
            (Attachment::Renderbuffer(n), AttachmentParam::ObjectName) => n as GLint,
            (Attachment::Renderbuffer(_), _) => return Err(GL_INVALID_ENUM),
            (
                Attachment::Texture {
                    name,
                    target,
                    level,
                    zoffset,
                },
                p,
            ) => match p {
                AttachmentParam::ObjectType => GL_TEXTURE as GLint,
                AttachmentParam::ObjectName => name as GLint,
                AttachmentParam::TextureLevel => level as GLint,
                AttachmentParam::CubeMapFace => match target {
                    TexImageTarget::CubeFace(f) => {
                        (GL_TEXTURE_CUBE_MAP_POSITIVE_X + f as GLenum) as GLint
                    }
                    _ => 0,
                },
                AttachmentParam::ZOffset => zoffset,
                _ => return Err(GL_INVALID_ENUM),
            },
        })
    }

    /// The format queries (`GL_FRAMEBUFFER_ATTACHMENT_*_SIZE`, `_COMPONENT_TYPE`,
    /// `_COLOR_ENCODING`) of an attached image; `Ok(None)` for the other queries.
    fn format_parameter(
        &self,
        a: Attachment,
        point: FboAttachment,
        p: AttachmentParam,
    ) -> Result<Option<GLint>, GLenum> {
        use AttachmentParam::*;
        if !matches!(
            p,
            ColorEncoding
                | ComponentType
                | RedSize
                | GreenSize
                | BlueSize
                | AlphaSize
                | DepthSize
                | StencilSize
        ) {
            return Ok(None);
        }
        if a == Attachment::None {
            return Err(GL_INVALID_OPERATION);
        }
        let bits = self.attachment_bits(a);
        let value = match p {
            ColorEncoding => GL_LINEAR as GLint,
            ComponentType => {
                // Stencil indices are unsigned integers; colour and depth are normalised.
                let stencil_only = point == FboAttachment::Stencil && bits.depth == 0;
                if stencil_only {
                    GL_UNSIGNED_INT as GLint
                } else {
                    GL_UNSIGNED_NORMALIZED as GLint
                }
            }
            RedSize => bits.rgba[0],
            GreenSize => bits.rgba[1],
            BlueSize => bits.rgba[2],
            AlphaSize => bits.rgba[3],
            DepthSize => bits.depth,
            _ => bits.stencil,
        };
        Ok(Some(value))
    }

    /// An attachment query on the window's framebuffer (ARB_framebuffer_object: its buffers
    /// are `GL_FRONT_LEFT`, `GL_BACK_LEFT`, ..., `GL_DEPTH` and `GL_STENCIL`, of type
    /// `GL_FRAMEBUFFER_DEFAULT`).
    fn default_attachment_parameter(
        &self,
        attachment: GLenum,
        p: AttachmentParam,
    ) -> Result<GLint, GLenum> {
        let cfg = self.window_framebuffer().config;
        let present = match attachment {
            GL_FRONT_LEFT => true,
            GL_BACK_LEFT => cfg.double_buffer,
            GL_FRONT_RIGHT | GL_BACK_RIGHT => false,
            GL_DEPTH => cfg.depth_bits > 0,
            GL_STENCIL => cfg.stencil_bits > 0,
            _ => return Err(GL_INVALID_ENUM),
        };
        use AttachmentParam::*;
        if !present {
            return match p {
                ObjectType => Ok(GL_NONE as GLint),
                ObjectName => Ok(0),
                _ => Err(GL_INVALID_OPERATION),
            };
        }
        let color = !matches!(attachment, GL_DEPTH | GL_STENCIL);
        let stencil = attachment == GL_STENCIL;
        Ok(match p {
            ObjectType => GL_FRAMEBUFFER_DEFAULT as GLint,
            ObjectName => 0,
            ColorEncoding => GL_LINEAR as GLint,
            ComponentType if stencil => GL_UNSIGNED_INT as GLint,
            ComponentType => GL_UNSIGNED_NORMALIZED as GLint,
            RedSize | GreenSize | BlueSize | AlphaSize => {
                if color {
                    8
                } else {
                    0
                }
            }
            DepthSize if attachment == GL_DEPTH => cfg.depth_bits as GLint,
            StencilSize if stencil => cfg.stencil_bits as GLint,
            DepthSize | StencilSize => 0,
            _ => return Err(GL_INVALID_ENUM),
        })
    }

    // ----- renderbuffer objects

    pub(crate) fn gen_renderbuffers_ext(&mut self, n: GLsizei, renderbuffers: &mut [GLuint]) {
        if n < 0 || renderbuffers.len() < n as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let mut guard = self.fbo.names_mut();
        let s = &mut *guard;
        let objects = &s.renderbuffers;
        gen_names(
            |k| objects.contains_key(&k),
            &mut s.renderbuffer_names,
            &mut renderbuffers[..n as usize],
        );
    }

    pub(crate) fn is_renderbuffer_ext(&mut self, renderbuffer: GLuint) -> GLboolean {
        self.fbo.names().renderbuffers.contains_key(&renderbuffer) as GLboolean
    }

    pub(crate) fn bind_renderbuffer_ext(&mut self, target: GLenum, renderbuffer: GLuint) {
        if !convert::is_renderbuffer_target(target) {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        if renderbuffer != 0 {
            let mut names = self.fbo.names_mut();
            names.renderbuffer_names.remove(&renderbuffer);
            names.renderbuffers.entry(renderbuffer).or_default();
        }
        self.fbo.bound_renderbuffer = renderbuffer;
    }

    /// ARB_framebuffer_object's `glBindRenderbuffer`: names not returned by
    /// `glGenRenderbuffers` are `GL_INVALID_OPERATION` (section 4.4.2.1).
    pub(crate) fn bind_renderbuffer(&mut self, target: GLenum, renderbuffer: GLuint) {
        if !convert::is_renderbuffer_target(target) {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        let known = renderbuffer == 0 || {
            let names = self.fbo.names();
            names.renderbuffers.contains_key(&renderbuffer)
                || names.renderbuffer_names.contains(&renderbuffer)
        };
        if !known {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        self.bind_renderbuffer_ext(target, renderbuffer);
    }

    pub(crate) fn delete_renderbuffers_ext(&mut self, n: GLsizei, renderbuffers: &[GLuint]) {
        if n < 0 || renderbuffers.len() < n as usize {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        for &name in &renderbuffers[..n as usize] {
            if name == 0 {
                continue;
            }
            if self.fbo.bound_renderbuffer == name {
                self.fbo.bound_renderbuffer = 0;
            }
            // Detached from the bound framebuffer only (section 4.4.2.2).
            let bound = self.fbo.bound;
            if bound != 0 {
                self.fbo_store();
                self.fbo.stale = true;
                if let Some(f) = self.fbo.names_mut().framebuffers.get_mut(&bound) {
                    for a in [&mut f.color, &mut f.depth, &mut f.stencil] {
                        if *a == Attachment::Renderbuffer(name) {
                            *a = Attachment::None;
                        }
                    }
                }
            }
            let mut names = self.fbo.names_mut();
            names.renderbuffers.remove(&name);
            names.renderbuffer_names.remove(&name);
        }
    }

    pub(crate) fn renderbuffer_storage_ext(
        &mut self,
        target: GLenum,
        internalformat: GLenum,
        width: GLsizei,
        height: GLsizei,
    ) {
        if !convert::is_renderbuffer_target(target) {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        let Some(kind) = convert::renderbuffer_kind(internalformat) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        if !(0..=MAX_RENDERBUFFER_SIZE).contains(&width)
            || !(0..=MAX_RENDERBUFFER_SIZE).contains(&height)
        {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let name = self.fbo.bound_renderbuffer;
        if name == 0 {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        let n = width as usize * height as usize;
        let (mut color, mut depth, mut stencil) = (Vec::new(), Vec::new(), Vec::new());
        let ok = match kind {
            RenderbufferKind::Color { .. } => color.try_reserve_exact(n).is_ok(),
            RenderbufferKind::Depth { .. } => depth.try_reserve_exact(n).is_ok(),
            RenderbufferKind::Stencil => stencil.try_reserve_exact(n).is_ok(),
            RenderbufferKind::DepthStencil => {
                depth.try_reserve_exact(n).is_ok() && stencil.try_reserve_exact(n).is_ok()
            }
        };
        if !ok {
            self.record_error(GL_OUT_OF_MEMORY);
            return;
        }
        // The contents are undefined; tilegl starts them at zero colour, the largest depth
        // and zero stencil (what a cleared window framebuffer holds).
        let depth_max = match kind {
            RenderbufferKind::Depth { bits } => crate::framebuffer::depth_max(bits),
            _ => crate::framebuffer::depth_max(24),
        };
        if matches!(kind, RenderbufferKind::Color { .. }) {
            color.resize(n, [0; 4]);
        }
        if matches!(
            kind,
            RenderbufferKind::Depth { .. } | RenderbufferKind::DepthStencil
        ) {
            depth.resize(n, depth_max);
        }
        if matches!(
            kind,
            RenderbufferKind::Stencil | RenderbufferKind::DepthStencil
        ) {
            stencil.resize(n, 0);
        }
        self.fbo_store();
        self.fbo.stale = self.fbo.bound != 0;
        self.fbo.names_mut().renderbuffers.insert(
            name,
            Renderbuffer {
                internal_format: internalformat,
                kind,
                width,
                height,
                color,
                depth,
                stencil,
            },
        );
    }

    /// `glRenderbufferStorageMultisample`: `samples` above `GL_MAX_SAMPLES` (0) is
    /// `GL_INVALID_VALUE`; 0 is `glRenderbufferStorage`.
    pub(crate) fn renderbuffer_storage_multisample(
        &mut self,
        target: GLenum,
        samples: GLsizei,
        internalformat: GLenum,
        width: GLsizei,
        height: GLsizei,
    ) {
        if !convert::is_renderbuffer_target(target)
            || convert::renderbuffer_kind(internalformat).is_none()
        {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        if !(0..=MAX_RENDERBUFFER_SIZE).contains(&width)
            || !(0..=MAX_RENDERBUFFER_SIZE).contains(&height)
            || !(0..=MAX_SAMPLES).contains(&samples)
        {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.renderbuffer_storage_ext(target, internalformat, width, height);
    }

    pub(crate) fn get_renderbuffer_parameteriv_ext(
        &mut self,
        target: GLenum,
        pname: GLenum,
        params: &mut [GLint],
    ) {
        if !convert::is_renderbuffer_target(target) {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        let Some(p) = convert::renderbuffer_param(pname) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let names = self.fbo.names();
        let Some(rb) = names.renderbuffers.get(&self.fbo.bound_renderbuffer) else {
            drop(names);
            self.record_error(GL_INVALID_OPERATION);
            return;
        };
        // Sizes are of the allocated image: none before storage is given.
        let allocated = rb.width > 0 && rb.height > 0;
        let sized = |bits: i32| if allocated { bits } else { 0 };
        let (color, alpha, depth, stencil) = match rb.kind {
            RenderbufferKind::Color { alpha } => (8, if alpha { 8 } else { 0 }, 0, 0),
            RenderbufferKind::Depth { bits } => (0, 0, bits as i32, 0),
            RenderbufferKind::Stencil => (0, 0, 0, 8),
            RenderbufferKind::DepthStencil => (0, 0, 24, 8),
        };
        let value = match p {
            RenderbufferParam::Width => rb.width,
            RenderbufferParam::Height => rb.height,
            RenderbufferParam::InternalFormat => rb.internal_format as GLint,
            RenderbufferParam::RedSize
            | RenderbufferParam::GreenSize
            | RenderbufferParam::BlueSize => sized(color),
            RenderbufferParam::AlphaSize => sized(alpha),
            RenderbufferParam::DepthSize => sized(depth),
            RenderbufferParam::StencilSize => sized(stencil),
            RenderbufferParam::Samples => 0,
        };
        if let Some(out) = params.first_mut() {
            *out = value;
        }
    }

    // ----- draw and read buffers of a bound object

    /// `glDrawBuffer`/`glReadBuffer` while an object is bound: `GL_NONE` or an existing
    /// colour attachment point; other buffer names are `GL_INVALID_OPERATION`.
    pub(crate) fn fbo_select_buffer(&mut self, mode: GLenum, draw: bool) {
        let known = convert::color_buffer_name(mode).is_some();
        let ok = match convert::color_attachment_index(mode) {
            Some(i) if (i as i32) < MAX_COLOR_ATTACHMENTS => true,
            Some(_) => {
                self.record_error(GL_INVALID_OPERATION);
                return;
            }
            None if mode == GL_NONE => true,
            None if known => {
                self.record_error(GL_INVALID_OPERATION);
                return;
            }
            None => false,
        };
        if !ok {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        self.flush_scene();
        if draw {
            self.buffers.draw = mode;
        } else {
            self.buffers.read = mode;
        }
        let bound = self.fbo.bound;
        if let Some(f) = self.fbo.names_mut().framebuffers.get_mut(&bound) {
            f.buffers = self.buffers;
        }
        self.fbo_store();
        self.fbo.stale = true;
    }

    // ----- glGenerateMipmapEXT

    pub(crate) fn generate_mipmap_ext(&mut self, target: GLenum) {
        let t = match convert::texture_target(target) {
            Some(
                t @ (TextureTarget::T1D
                | TextureTarget::T2D
                | TextureTarget::T3D
                | TextureTarget::CubeMap),
            ) => t,
            _ => {
                self.record_error(GL_INVALID_ENUM);
                return;
            }
        };
        self.fbo_before_texture_change();
        if let Err(e) = self.generate_mipmaps_of_bound(t) {
            self.record_error(e);
        }
        self.invalidate();
    }

    /// A framebuffer configuration for an object's tiles.
    pub(crate) fn fbo_config(depth_bits: u32, stencil: bool) -> FramebufferConfig {
        FramebufferConfig {
            depth_bits,
            stencil_bits: if stencil { 8 } else { 0 },
            accum_bits: 0,
            double_buffer: false,
            // Multisample renderbuffers (EXT_framebuffer_multisample) would set this.
            samples: 0,
        }
    }
}

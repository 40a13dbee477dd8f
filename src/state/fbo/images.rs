//! Completeness of the bound framebuffer object (section 4.4.4) and the copies between its
//! attached images and the context's tiles (section 4.4.6: window (x, y) is texel
//! (x + b, y + b) of a texture image with border b, at slice zoffset + b of a 3D one).

use super::{Attachment, Renderbuffer, MAX_RENDERBUFFER_SIZE};
use crate::common::values::{RenderbufferKind, TexImageTarget};
use crate::framebuffer::{depth_max, ColorBuffer, DrawTarget, Framebuffer};
use crate::gl::enums::*;
use crate::state::Context;
use crate::texture::BaseFormat;

/// What an attached image offers.
#[derive(Clone, Copy, Debug)]
struct ImageInfo {
    width: i32,
    height: i32,
    color: bool,
    depth: bool,
    stencil: bool,
    /// Depth bits of a depth image.
    depth_bits: u32,
}

/// The size and buffers of a complete object's tiles.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Layout {
    pub width: i32,
    pub height: i32,
    pub depth_bits: u32,
    pub stencil: bool,
}

fn renderbuffer_info(rb: &Renderbuffer) -> ImageInfo {
    let (color, depth, stencil, depth_bits) = match rb.kind {
        RenderbufferKind::Color { .. } => (true, false, false, 0),
        RenderbufferKind::Depth { bits } => (false, true, false, bits),
        RenderbufferKind::Stencil => (false, false, true, 0),
        RenderbufferKind::DepthStencil => (false, true, true, 24),
    };
    ImageInfo {
        width: rb.width,
        height: rb.height,
        color,
        depth,
        stencil,
        depth_bits,
    }
}

/// The bits of each component of an attached image (ARB_framebuffer_object's
/// `GL_FRAMEBUFFER_ATTACHMENT_*_SIZE`): 0 for a component the image lacks.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct ImageBits {
    pub rgba: [i32; 4],
    pub depth: i32,
    pub stencil: i32,
}

impl Context {
    /// The component sizes of the image `a` names (all 0 without one).
    pub(crate) fn attachment_bits(&self, a: Attachment) -> ImageBits {
        let mut b = ImageBits::default();
        match a {
            Attachment::None => {}
            Attachment::Renderbuffer(n) => {
                let names = self.fbo.names();
                let Some(rb) = names.renderbuffers.get(&n) else {
                    return b;
                };
                if rb.width <= 0 || rb.height <= 0 {
                    return b;
                }
                match rb.kind {
                    RenderbufferKind::Color { alpha } => {
                        b.rgba = [8, 8, 8, if alpha { 8 } else { 0 }];
                    }
                    RenderbufferKind::Depth { bits } => b.depth = bits as i32,
                    RenderbufferKind::Stencil => b.stencil = 8,
                    RenderbufferKind::DepthStencil => {
                        b.depth = 24;
                        b.stencil = 8;
                    }
                }
            }
            Attachment::Texture {
                name,
                target,
                level,
                ..
            } => {
                let Some(obj) = self.textures.object(name) else {
                    return b;
                };
                let Some(img) = obj.image(target.face(), level) else {
                    return b;
                };
                let f = img.format;
                if f.is_depth() {
                    b.depth = (f.bits as i32).clamp(16, 32);
                    b.stencil = if f.stencil { 8 } else { 0 };
                } else {
                    // Colour is drawn through 8-bit tiles; luminance and intensity are
                    // the red component of a framebuffer (section 4.3.2).
                    let bits = (f.bits as i32).min(8);
                    for &slot in f.base.slots() {
                        b.rgba[slot] = bits;
                    }
                }
            }
        }
        b
    }

    /// The image an attachment names, or `Err(())` when the attachment is not "framebuffer
    /// attachment complete" for want of an object or an image (section 4.4.4.1), `Ok(None)`
    /// when nothing is attached.
    fn attached_image(&self, a: Attachment) -> Result<Option<ImageInfo>, ()> {
        let info = match a {
            Attachment::None => return Ok(None),
            Attachment::Renderbuffer(n) => {
                renderbuffer_info(self.fbo.names().renderbuffers.get(&n).ok_or(())?)
            }
            Attachment::Texture {
                name,
                target,
                level,
                zoffset,
            } => {
                let obj = self.textures.object(name).ok_or(())?;
                if obj.target != Some(target.texture_target()) {
                    return Err(());
                }
                let img = obj.image(target.face(), level).ok_or(())?;
                let inner = img.inner_size();
                if target == TexImageTarget::T3D && zoffset >= inner[2] {
                    return Err(());
                }
                let f = img.format;
                ImageInfo {
                    width: inner[0],
                    height: if img.dims >= 2 { inner[1] } else { 1 },
                    // ARB_framebuffer_object section 4.4.4: every uncompressed colour
                    // base format is colour-renderable.
                    color: f.base != BaseFormat::DepthComponent && f.compressed.is_none(),
                    depth: f.is_depth(),
                    stencil: f.is_depth() && f.stencil,
                    depth_bits: (f.bits as u32).clamp(16, 32),
                }
            }
        };
        if info.width <= 0 || info.height <= 0 {
            return Err(());
        }
        Ok(Some(info))
    }

    /// The status of the bound object (`glCheckFramebufferStatusEXT`) and, when complete, the
    /// layout of its tiles. Rules in the order of section 4.4.4.2.
    pub(crate) fn fbo_status(&self) -> (GLenum, Option<Layout>) {
        let Some(f) = self.fbo.bound_object() else {
            return (GL_FRAMEBUFFER_COMPLETE_EXT, None);
        };
        let mut images = [None; 3];
        for (k, (a, slot)) in [(f.color, 0), (f.depth, 1), (f.stencil, 2)]
            .into_iter()
            .enumerate()
        {
            let Ok(info) = self.attached_image(a) else {
                return (GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_EXT, None);
            };
            if let Some(i) = info {
                let renderable = match slot {
                    0 => i.color,
                    1 => i.depth,
                    _ => i.stencil,
                };
                if !renderable {
                    return (GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_EXT, None);
                }
            }
            images[k] = info;
        }
        if images.iter().flatten().next().is_none() {
            return (GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_EXT, None);
        }
        // ARB_framebuffer_object section 4.4.1: images of different sizes are complete, and
        // drawing is limited to the rectangle common to all of them.
        let width = images.iter().flatten().map(|i| i.width).min().unwrap_or(0);
        let height = images.iter().flatten().map(|i| i.height).min().unwrap_or(0);
        // One colour attachment point: GL_FRAMEBUFFER_INCOMPLETE_FORMATS_EXT cannot arise.
        let color = images[0].is_some();
        if f.buffers.draw != GL_NONE && !color {
            return (GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER_EXT, None);
        }
        if f.buffers.read != GL_NONE && !color {
            return (GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER_EXT, None);
        }
        if images
            .iter()
            .flatten()
            .any(|i| i.width > MAX_RENDERBUFFER_SIZE || i.height > MAX_RENDERBUFFER_SIZE)
        {
            return (GL_FRAMEBUFFER_UNSUPPORTED_EXT, None);
        }
        (
            GL_FRAMEBUFFER_COMPLETE_EXT,
            Some(Layout {
                width,
                height,
                depth_bits: images[1].map_or(0, |i| i.depth_bits),
                stencil: images[2].is_some(),
            }),
        )
    }

    /// Makes the tiles show the bound object's attached images (an incomplete object gets
    /// an empty framebuffer: nothing can be drawn or read).
    pub(crate) fn fbo_load(&mut self) {
        let (status, layout) = self.fbo_status();
        self.fbo.status = status;
        self.fbo.stale = false;
        let Some(l) = layout else {
            let cfg = Context::fbo_config(0, false);
            self.replace_framebuffer(Framebuffer::new(0, 0, cfg));
            return;
        };
        let Some(f) = self.fbo.bound_object() else {
            return;
        };
        let mut fb = Framebuffer::new(
            l.width,
            l.height,
            Context::fbo_config(l.depth_bits, l.stencil),
        );
        fb.draw = if f.buffers.draw == GL_NONE {
            DrawTarget::None
        } else {
            DrawTarget::One(ColorBuffer::Front)
        };
        fb.read = ColorBuffer::Front;
        fb.components = self.color_components(f.color);
        let dmax = depth_max(l.depth_bits) as f64;
        let has = fb.components.unwrap_or([true; 4]);
        self.for_each_texel(f.color, l, |x, y, t| {
            if let Some(c) = t.color {
                // Components the image lacks: 0, alpha 1 (what blending and reads see).
                let c = [0, 1, 2, 3].map(|k| match (has[k], k) {
                    (true, _) => c[k],
                    (false, 3) => 255,
                    (false, _) => 0,
                });
                fb.set_color(x, y, c);
            }
        });
        self.for_each_texel(f.depth, l, |x, y, t| {
            if let Some(d) = t.depth {
                fb.set_depth(x, y, d.unwrap_or_else(|v| (v * dmax).round() as u32));
            }
        });
        self.for_each_texel(f.stencil, l, |x, y, t| {
            if let Some(s) = t.stencil {
                fb.set_stencil(x, y, s);
            }
        });
        self.replace_framebuffer(fb);
    }

    /// The components of the colour image `a` when it lacks some of R, G, B and A (what
    /// reads of the tiles keep: [`Framebuffer::components`]).
    fn color_components(&self, a: Attachment) -> Option<[bool; 4]> {
        let mut has = [false; 4];
        match a {
            Attachment::None => return None,
            Attachment::Renderbuffer(n) => match self.fbo.names().renderbuffers.get(&n)?.kind {
                RenderbufferKind::Color { alpha: false } => has = [true, true, true, false],
                _ => return None,
            },
            Attachment::Texture {
                name,
                target,
                level,
                ..
            } => {
                let obj = self.textures.object(name)?;
                let img = obj.image(target.face(), level)?;
                for &slot in img.format.base.slots() {
                    has[slot] = true;
                }
            }
        }
        (has != [true; 4]).then_some(has)
    }

    /// Calls `each(x, y, value)` for every pixel of the attached image of `a`.
    fn for_each_texel(&self, a: Attachment, l: Layout, mut each: impl FnMut(i32, i32, Texel)) {
        match a {
            Attachment::None => {}
            Attachment::Renderbuffer(n) => {
                let names = self.fbo.names();
                let Some(rb) = names.renderbuffers.get(&n) else {
                    return;
                };
                for y in 0..l.height {
                    for x in 0..l.width {
                        let i = (y * rb.width + x) as usize;
                        each(
                            x,
                            y,
                            Texel {
                                color: rb.color.get(i).copied(),
                                depth: rb.depth.get(i).map(|&d| Ok(d)),
                                stencil: rb.stencil.get(i).copied(),
                            },
                        );
                    }
                }
            }
            Attachment::Texture {
                name,
                target,
                level,
                zoffset,
            } => {
                let Some(obj) = self.textures.object(name) else {
                    return;
                };
                let Some(img) = obj.image(target.face(), level) else {
                    return;
                };
                let b = img.borders();
                let depth = img.format.is_depth();
                for y in 0..l.height {
                    for x in 0..l.width {
                        let (i, j, k) = (x + b[0], y + b[1], zoffset + b[2]);
                        let v = img.fetch(i, j, k);
                        each(
                            x,
                            y,
                            Texel {
                                color: (!depth)
                                    .then(|| v.map(|c| (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8)),
                                depth: depth.then_some(Err(v[0] as f64)),
                                stencil: img.format.stencil.then(|| img.stencil_at(i, j, k)),
                            },
                        );
                    }
                }
            }
        }
    }

    /// Writes the tiles back into the bound object's attached images (after finishing
    /// pending work). Nothing when no complete object's tiles are current.
    pub(crate) fn fbo_store(&mut self) {
        if self.fbo.bound == 0 || self.fbo.stale || self.fbo.status != GL_FRAMEBUFFER_COMPLETE_EXT {
            return;
        }
        self.flush_scene();
        let Some(f) = self.fbo.bound_object() else {
            return;
        };
        let fb = &self.framebuffer;
        let (w, h) = (fb.width, fb.height);
        let dmax = fb.depth_max().max(1) as f64;
        for (a, what) in [(f.color, 0), (f.depth, 1), (f.stencil, 2)] {
            match a {
                Attachment::None => {}
                Attachment::Renderbuffer(n) => {
                    let mut names = self.fbo.names_mut();
                    let Some(rb) = names.renderbuffers.get_mut(&n) else {
                        continue;
                    };
                    let opaque = rb.kind == RenderbufferKind::Color { alpha: false };
                    for y in 0..h.min(rb.height) {
                        for x in 0..w.min(rb.width) {
                            let i = (y * rb.width + x) as usize;
                            match what {
                                0 => {
                                    if let (Some(c), Some(d)) =
                                        (fb.color_at(x, y), rb.color.get_mut(i))
                                    {
                                        *d = if opaque { [c[0], c[1], c[2], 255] } else { c };
                                    }
                                }
                                1 => {
                                    if let (Some(v), Some(d)) =
                                        (fb.depth_at(x, y), rb.depth.get_mut(i))
                                    {
                                        *d = v;
                                    }
                                }
                                _ => {
                                    if let (Some(v), Some(d)) =
                                        (fb.stencil_at(x, y), rb.stencil.get_mut(i))
                                    {
                                        *d = v;
                                    }
                                }
                            }
                        }
                    }
                }
                Attachment::Texture {
                    name,
                    target,
                    level,
                    zoffset,
                } => {
                    let Some(mut obj) = self.textures.object_mut(name) else {
                        continue;
                    };
                    let Some(img) = obj.image_mut(target.face(), level) else {
                        continue;
                    };
                    let b = img.borders();
                    let z = zoffset + b[2];
                    match what {
                        0 => {
                            for y in 0..h {
                                for x in 0..w {
                                    if let Some(c) = fb.color_at(x, y) {
                                        img.store(
                                            x + b[0],
                                            y + b[1],
                                            z,
                                            c.map(|v| v as f32 / 255.0),
                                        );
                                    }
                                }
                            }
                        }
                        1 => {
                            for y in 0..h {
                                for x in 0..w {
                                    if let Some(d) = fb.depth_at(x, y) {
                                        let v = (d as f64 / dmax) as f32;
                                        img.store(x + b[0], y + b[1], z, [v, 0.0, 0.0, 1.0]);
                                    }
                                }
                            }
                        }
                        _ => {
                            let (x0, y0) = ((b[0]) as usize, (b[1]) as usize);
                            img.store_stencil_block(
                                [x0, y0, z.max(0) as usize],
                                [w as usize, h as usize, 1],
                                |x, y, _| fb.stencil_at(x as i32, y as i32).unwrap_or(0),
                            );
                        }
                    }
                }
            }
        }
        self.invalidate();
    }
}

/// One pixel of an attached image: colour, depth (stored integer `Ok`, or [0, 1] `Err`) and
/// stencil, as the image has them.
struct Texel {
    color: Option<[u8; 4]>,
    depth: Option<Result<u32, f64>>,
    stencil: Option<u8>,
}

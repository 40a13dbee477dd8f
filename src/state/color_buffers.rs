//! Colour buffer selection: `glDrawBuffer`, `glReadBuffer` and the buffer swap of a
//! double-buffered window (section 4.2.1 and 4.3.2 of the GL 1.5 spec).
//!
//! A context made with `FramebufferConfig::double_buffer` has a front and a back colour buffer
//! (depth and stencil are shared, as in a GLX visual); others (OSMesa) have only the front
//! buffer. There are no stereo (right) or auxiliary buffers: naming one is
//! `GL_INVALID_OPERATION`, as is naming the back buffer of a single-buffered context.
//! The defaults are `GL_BACK` for a double-buffered context and `GL_FRONT` otherwise.

use super::Context;
use crate::common::values::ColorBufferName;
use crate::framebuffer::{ColorBuffer, DrawTarget};
use crate::gl::convert;
use crate::gl::enums::*;

/// The `glDrawBuffer` and `glReadBuffer` settings as given (what the queries return).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BufferSelection {
    pub draw: GLenum,
    pub read: GLenum,
}

impl BufferSelection {
    /// The defaults for a context with or without a back buffer.
    pub fn new(double_buffer: bool) -> BufferSelection {
        let b = if double_buffer { GL_BACK } else { GL_FRONT };
        BufferSelection { draw: b, read: b }
    }
}

/// Where `glDrawBuffer(name)` draws, or `Err(error)`.
fn draw_target(name: GLenum, double: bool) -> Result<DrawTarget, GLenum> {
    use ColorBufferName::*;
    let name = convert::color_buffer_name(name).ok_or(GL_INVALID_ENUM)?;
    let both = if double {
        DrawTarget::Both
    } else {
        DrawTarget::One(ColorBuffer::Front)
    };
    Ok(match name {
        None => DrawTarget::None,
        FrontLeft | Front => DrawTarget::One(ColorBuffer::Front),
        BackLeft | Back if double => DrawTarget::One(ColorBuffer::Back),
        Left | FrontAndBack => both,
        BackLeft | Back | FrontRight | BackRight | Right | Aux(_) => {
            return Err(GL_INVALID_OPERATION)
        }
    })
}

/// Which buffer `glReadBuffer(name)` reads, or `Err(error)`.
fn read_source(name: GLenum, double: bool) -> Result<ColorBuffer, GLenum> {
    use ColorBufferName::*;
    let name = convert::color_buffer_name(name).ok_or(GL_INVALID_ENUM)?;
    Ok(match name {
        FrontLeft | Front | Left => ColorBuffer::Front,
        BackLeft | Back if double => ColorBuffer::Back,
        None | FrontAndBack => return Err(GL_INVALID_ENUM),
        BackLeft | Back | FrontRight | BackRight | Right | Aux(_) => {
            return Err(GL_INVALID_OPERATION)
        }
    })
}

/// The colour buffer `fb` draws into (the back buffer for `GL_FRONT_AND_BACK` and `GL_NONE`
/// when there is one).
fn drawn_buffer(fb: &crate::framebuffer::Framebuffer) -> ColorBuffer {
    match fb.draw {
        DrawTarget::One(b) => b,
        _ if fb.is_double_buffered() => ColorBuffer::Back,
        _ => ColorBuffer::Front,
    }
}

impl Context {
    pub(crate) fn draw_buffer(&mut self, mode: GLenum) {
        if self.fbo_bound() {
            self.fbo_select_buffer(mode, true);
            return;
        }
        if convert::color_attachment_index(mode).is_some() {
            // EXT_framebuffer_object: no window buffer has these names.
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        match draw_target(mode, self.framebuffer.is_double_buffered()) {
            Ok(target) => {
                // Work recorded so far goes to the previous buffer.
                self.flush_scene();
                self.framebuffer.draw = target;
                self.buffers.draw = mode;
                self.make_draw_buffer_resident();
            }
            Err(e) => self.record_error(e),
        }
    }

    pub(crate) fn read_buffer(&mut self, mode: GLenum) {
        if self.reads_elsewhere() {
            // EXT_framebuffer_blit: the read buffer of the read framebuffer.
            let read = self.fbo.read_bound;
            self.with_framebuffer_bound(read, |c| c.read_buffer(mode));
            return;
        }
        if self.fbo_bound() {
            self.fbo_select_buffer(mode, false);
            return;
        }
        if convert::color_attachment_index(mode).is_some() {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        match read_source(mode, self.framebuffer.is_double_buffered()) {
            Ok(source) => {
                self.framebuffer.read = source;
                self.buffers.read = mode;
            }
            Err(e) => self.record_error(e),
        }
    }

    /// Keeps the tiles' colour storage on the draw buffer, so that code writing tiles directly
    /// (not through the scene) writes the buffer drawn to (the back buffer for
    /// `GL_FRONT_AND_BACK` and `GL_NONE`).
    pub(crate) fn make_draw_buffer_resident(&mut self) {
        let b = drawn_buffer(&self.framebuffer);
        self.framebuffer.make_resident(b);
    }

    /// Re-applies the draw and read buffer settings to a new framebuffer (after a resize).
    pub(crate) fn apply_buffer_selection(&mut self) {
        if self.fbo_bound() {
            // An object's buffers (restored by glPopAttrib) are its only colour attachment.
            self.framebuffer.draw = match self.buffers.draw {
                GL_NONE => DrawTarget::None,
                _ => DrawTarget::One(ColorBuffer::Front),
            };
            return;
        }
        let double = self.framebuffer.is_double_buffered();
        if let Ok(t) = draw_target(self.buffers.draw, double) {
            self.framebuffer.draw = t;
        }
        self.make_draw_buffer_resident();
        if let Ok(s) = read_source(self.buffers.read, double) {
            self.framebuffer.read = s;
        }
    }

    /// The colour buffer a snapshot of "the draw buffer" shows: the one drawn to, the back
    /// buffer for `GL_FRONT_AND_BACK` and `GL_NONE` on a double-buffered context.
    /// The window's, also while a framebuffer object is bound.
    pub fn draw_color_buffer(&self) -> ColorBuffer {
        drawn_buffer(self.window_framebuffer())
    }

    /// Whether the context has a back buffer.
    pub fn is_double_buffered(&self) -> bool {
        self.window_framebuffer().is_double_buffered()
    }

    /// The window-system buffer swap (`glXSwapBuffers`, `eglSwapBuffers`): finishes pending
    /// rendering and copies the back buffer to the front buffer; the back buffer keeps its
    /// content (see [`crate::framebuffer::Framebuffer::swap_buffers`]). No effect on a
    /// single-buffered context other than the flush.
    pub fn swap_buffers(&mut self) {
        self.flush_scene();
        self.window_framebuffer_mut().swap_buffers();
    }

    /// The colour of `buffer` as an RGBA image, top row first (after finishing pending
    /// rendering). A single-buffered context shows its front buffer for either.
    pub fn color_image(&mut self, buffer: ColorBuffer) -> image::RgbaImage {
        self.flush_scene();
        crate::framebuffer::image::to_rgba_image_of(self.window_framebuffer(), buffer)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::FramebufferConfig;
    use crate::{ContextConfig, Gl};

    fn ctx(double: bool) -> Context {
        Context::with_config(ContextConfig {
            width: 8,
            height: 8,
            framebuffer: FramebufferConfig {
                double_buffer: double,
                ..FramebufferConfig::default()
            },
            threads: 1,
        })
    }

    fn clear_to(c: &mut Context, rgb: [f32; 3]) {
        c.clear_color(rgb[0], rgb[1], rgb[2], 1.0);
        Gl::clear(c, GL_COLOR_BUFFER_BIT);
    }

    fn px(c: &mut Context, b: ColorBuffer) -> [u8; 4] {
        c.flush_scene();
        c.framebuffer.color_in(b, 3, 3).unwrap()
    }

    fn get_int(c: &mut Context, pname: GLenum) -> i32 {
        let mut v = [0];
        Gl::get_integerv(c, pname, &mut v);
        v[0]
    }

    #[test]
    fn defaults_and_queries_follow_the_buffer_count() {
        let mut d = ctx(true);
        assert_eq!(get_int(&mut d, GL_DRAW_BUFFER), GL_BACK as i32);
        assert_eq!(get_int(&mut d, GL_READ_BUFFER), GL_BACK as i32);
        assert_eq!(get_int(&mut d, GL_DOUBLEBUFFER), 1);
        let mut s = ctx(false);
        assert_eq!(get_int(&mut s, GL_DRAW_BUFFER), GL_FRONT as i32);
        assert_eq!(get_int(&mut s, GL_READ_BUFFER), GL_FRONT as i32);
        assert_eq!(get_int(&mut s, GL_DOUBLEBUFFER), 0);
        Gl::draw_buffer(&mut d, GL_FRONT_LEFT);
        Gl::read_buffer(&mut d, GL_FRONT);
        assert_eq!(get_int(&mut d, GL_DRAW_BUFFER), GL_FRONT_LEFT as i32);
        assert_eq!(get_int(&mut d, GL_READ_BUFFER), GL_FRONT as i32);
        assert_eq!(Gl::get_error(&mut d), GL_NO_ERROR);
    }

    #[test]
    fn errors_name_missing_buffers_and_bad_enums() {
        let mut s = ctx(false);
        for (mode, err) in [
            (GL_BACK, GL_INVALID_OPERATION),
            (GL_BACK_LEFT, GL_INVALID_OPERATION),
            (GL_RIGHT, GL_INVALID_OPERATION),
            (GL_AUX0, GL_INVALID_OPERATION),
            (GL_TEXTURE_2D, GL_INVALID_ENUM),
        ] {
            Gl::draw_buffer(&mut s, mode);
            assert_eq!(Gl::get_error(&mut s), err, "draw 0x{mode:x}");
            Gl::read_buffer(&mut s, mode);
            assert_eq!(Gl::get_error(&mut s), err, "read 0x{mode:x}");
        }
        assert_eq!(get_int(&mut s, GL_DRAW_BUFFER), GL_FRONT as i32);
        // FRONT_AND_BACK and NONE draw, but are not read sources.
        Gl::draw_buffer(&mut s, GL_FRONT_AND_BACK);
        Gl::draw_buffer(&mut s, GL_NONE);
        assert_eq!(Gl::get_error(&mut s), GL_NO_ERROR);
        Gl::read_buffer(&mut s, GL_FRONT_AND_BACK);
        assert_eq!(Gl::get_error(&mut s), GL_INVALID_ENUM);
        Gl::read_buffer(&mut s, GL_NONE);
        assert_eq!(Gl::get_error(&mut s), GL_INVALID_ENUM);
        // Inside glBegin/glEnd both are illegal.
        Gl::begin(&mut s, GL_POINTS);
        Gl::draw_buffer(&mut s, GL_FRONT);
        Gl::end(&mut s);
        assert_eq!(Gl::get_error(&mut s), GL_INVALID_OPERATION);
    }

    #[test]
    fn drawing_reading_and_swapping_address_the_chosen_buffer() {
        use ColorBuffer::{Back, Front};
        let mut c = ctx(true);
        clear_to(&mut c, [1.0, 0.0, 0.0]);
        assert_eq!(px(&mut c, Back), [255, 0, 0, 255]);
        assert_eq!(px(&mut c, Front), [0, 0, 0, 0]);
        // The swap copies back to front and keeps the back content.
        c.swap_buffers();
        assert_eq!(px(&mut c, Front), [255, 0, 0, 255]);
        assert_eq!(px(&mut c, Back), [255, 0, 0, 255]);
        Gl::draw_buffer(&mut c, GL_FRONT);
        clear_to(&mut c, [0.0, 1.0, 0.0]);
        assert_eq!(px(&mut c, Front), [0, 255, 0, 255]);
        assert_eq!(px(&mut c, Back), [255, 0, 0, 255]);
        // glReadPixels reads the read buffer, whatever is drawn to.
        let mut rgba = [0u8; 4];
        Gl::read_pixels(&mut c, 3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut rgba);
        assert_eq!(rgba, [255, 0, 0, 255]);
        Gl::read_buffer(&mut c, GL_FRONT);
        Gl::read_pixels(&mut c, 3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut rgba);
        assert_eq!(rgba, [0, 255, 0, 255]);
        // Both buffers at once; each blends with its own content.
        Gl::draw_buffer(&mut c, GL_FRONT_AND_BACK);
        Gl::enable(&mut c, GL_BLEND);
        Gl::blend_func(&mut c, GL_ONE, GL_ONE);
        Gl::enable(&mut c, GL_DEPTH_TEST);
        Gl::color_3f(&mut c, 0.0, 0.0, 1.0);
        Gl::rectf(&mut c, -1.0, -1.0, 1.0, 1.0);
        assert_eq!(px(&mut c, Front), [0, 255, 255, 255]);
        assert_eq!(px(&mut c, Back), [255, 0, 255, 255]);
        // GL_NONE: no colour written.
        Gl::draw_buffer(&mut c, GL_NONE);
        Gl::disable(&mut c, GL_DEPTH_TEST);
        clear_to(&mut c, [1.0, 1.0, 1.0]);
        assert_eq!(px(&mut c, Front), [0, 255, 255, 255]);
        assert_eq!(px(&mut c, Back), [255, 0, 255, 255]);
        assert_eq!(Gl::get_error(&mut c), GL_NO_ERROR);
    }

    #[test]
    fn single_buffered_front_and_back_draws_once() {
        let mut c = ctx(false);
        Gl::draw_buffer(&mut c, GL_FRONT_AND_BACK);
        Gl::enable(&mut c, GL_BLEND);
        Gl::blend_func(&mut c, GL_ONE, GL_ONE);
        Gl::color_3f(&mut c, 0.0, 0.0, 0.5);
        Gl::rectf(&mut c, -1.0, -1.0, 1.0, 1.0);
        assert_eq!(px(&mut c, ColorBuffer::Front)[2], 128);
    }
}

//! EXT_framebuffer_blit's `glBlitFramebufferEXT`: a rectangle of the read framebuffer copied,
//! scaled and mirrored as the two rectangles say, into the draw framebuffer.
//!
//! The source buffers are captured first (the read framebuffer is made current for that when
//! it is not the draw one), then every destination pixel whose centre lies in the destination
//! rectangle, inside the draw framebuffer and the scissor box (the only fragment operations
//! that apply to a blit) takes the source value at the matching point: the pixel holding it
//! (`GL_NEAREST`), or the bilinear mix of the four nearest (`GL_LINEAR`, colour only, clamped
//! to the edge of the read buffer). Destination pixels whose source pixel lies outside the
//! read framebuffer are left unwritten (their value is undefined; Mesa clips them so).

use super::super::Context;
use crate::framebuffer::{DrawTarget, Framebuffer};
use crate::gl::enums::*;

/// The source buffers of a blit: the read framebuffer's whole colour, depth and stencil.
struct Source {
    width: i32,
    height: i32,
    color: Option<Vec<[u8; 4]>>,
    depth: Option<Vec<u32>>,
    stencil: Option<Vec<u8>>,
    depth_bits: u32,
    stencil_bits: u32,
}

impl Source {
    fn capture(fb: &Framebuffer, color: bool, depth: bool, stencil: bool) -> Source {
        let (w, h) = (fb.width.max(0), fb.height.max(0));
        let cfg = fb.config;
        let grab = |want: bool, f: &dyn Fn(i32, i32) -> Option<u32>| {
            want.then(|| {
                (0..h)
                    .flat_map(|y| (0..w).map(move |x| (x, y)))
                    .map(|(x, y)| f(x, y).unwrap_or(0))
                    .collect::<Vec<u32>>()
            })
        };
        let color = color.then(|| {
            (0..h)
                .flat_map(|y| (0..w).map(move |x| (x, y)))
                .map(|(x, y)| fb.color_at(x, y).unwrap_or([0; 4]))
                .collect()
        });
        let depth = grab(depth && cfg.depth_bits > 0, &|x, y| fb.depth_at(x, y));
        let stencil = grab(stencil && cfg.stencil_bits > 0, &|x, y| {
            fb.stencil_at(x, y).map(u32::from)
        })
        .map(|v| v.into_iter().map(|s| s as u8).collect());
        Source {
            width: w,
            height: h,
            color,
            depth,
            stencil,
            depth_bits: cfg.depth_bits,
            stencil_bits: cfg.stencil_bits,
        }
    }

    fn index(&self, x: i32, y: i32) -> Option<usize> {
        (x >= 0 && y >= 0 && x < self.width && y < self.height)
            .then(|| (y * self.width + x) as usize)
    }

    /// Bilinear colour at source point (u, v) (window coordinates), texels clamped to the
    /// buffer's edge.
    fn linear(&self, color: &[[u8; 4]], u: f64, v: f64) -> [u8; 4] {
        let (u, v) = (u - 0.5, v - 0.5);
        let (i0, j0) = (u.floor(), v.floor());
        let (a, b) = (u - i0, v - j0);
        let cx = |i: f64| (i as i64).clamp(0, self.width as i64 - 1) as i32;
        let cy = |j: f64| (j as i64).clamp(0, self.height as i64 - 1) as i32;
        let at = |i: f64, j: f64| color[(cy(j) * self.width + cx(i)) as usize];
        let (t00, t10, t01, t11) = (
            at(i0, j0),
            at(i0 + 1.0, j0),
            at(i0, j0 + 1.0),
            at(i0 + 1.0, j0 + 1.0),
        );
        let mut out = [0u8; 4];
        for k in 0..4 {
            let bottom = t00[k] as f64 * (1.0 - a) + t10[k] as f64 * a;
            let top = t01[k] as f64 * (1.0 - a) + t11[k] as f64 * a;
            out[k] = (bottom * (1.0 - b) + top * b).round().clamp(0.0, 255.0) as u8;
        }
        out
    }
}

/// One axis of the mapping: the source coordinate of destination pixel centre `d + 0.5`.
#[derive(Clone, Copy)]
struct Axis {
    s0: f64,
    d0: f64,
    scale: f64,
    lo: i32,
    hi: i32,
}

impl Axis {
    fn new(s0: i32, s1: i32, d0: i32, d1: i32) -> Option<Axis> {
        if s0 == s1 || d0 == d1 {
            return None;
        }
        Some(Axis {
            s0: s0 as f64,
            d0: d0 as f64,
            scale: (s1 as f64 - s0 as f64) / (d1 as f64 - d0 as f64),
            lo: d0.min(d1),
            hi: d0.max(d1),
        })
    }

    fn source(&self, d: i32) -> f64 {
        self.s0 + (d as f64 + 0.5 - self.d0) * self.scale
    }
}

impl Context {
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn blit_framebuffer_ext(
        &mut self,
        src_x0: GLint,
        src_y0: GLint,
        src_x1: GLint,
        src_y1: GLint,
        dst_x0: GLint,
        dst_y0: GLint,
        dst_x1: GLint,
        dst_y1: GLint,
        mask: GLbitfield,
        filter: GLenum,
    ) {
        // Both framebuffers must be complete (INVALID_FRAMEBUFFER_OPERATION_EXT).
        if !self.framebuffer_ready() {
            return;
        }
        let read = self.fbo.read_bound;
        if self.reads_elsewhere() && !self.with_framebuffer_bound(read, |c| c.framebuffer_ready()) {
            return;
        }
        if filter != GL_NEAREST && filter != GL_LINEAR {
            self.record_error(GL_INVALID_ENUM);
            return;
        }
        let all = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT;
        if mask & !all != 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let ds = mask & (GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT) != 0;
        if ds && filter == GL_LINEAR {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        let want_color = mask & GL_COLOR_BUFFER_BIT != 0;
        let want_depth = mask & GL_DEPTH_BUFFER_BIT != 0;
        let want_stencil = mask & GL_STENCIL_BUFFER_BIT != 0;
        let src = self.with_framebuffer_bound(read, |c| {
            c.flush_scene();
            let color = want_color && c.buffers.read != GL_NONE;
            Source::capture(&c.framebuffer, color, want_depth, want_stencil)
        });
        self.flush_scene();
        let dcfg = self.framebuffer.config;
        // A buffer present on both sides must have the same format (depth bits, stencil bits).
        if (src.depth.is_some() && dcfg.depth_bits > 0 && src.depth_bits != dcfg.depth_bits)
            || (src.stencil.is_some()
                && dcfg.stencil_bits > 0
                && src.stencil_bits != dcfg.stencil_bits)
        {
            self.record_error(GL_INVALID_OPERATION);
            return;
        }
        let (Some(ax), Some(ay)) = (
            Axis::new(src_x0, src_x1, dst_x0, dst_x1),
            Axis::new(src_y0, src_y1, dst_y0, dst_y1),
        ) else {
            return;
        };
        let color = src
            .color
            .as_ref()
            .filter(|_| self.framebuffer.draw != DrawTarget::None);
        let depth = src.depth.as_ref().filter(|_| dcfg.depth_bits > 0);
        let stencil = src.stencil.as_ref().filter(|_| dcfg.stencil_bits > 0);
        if color.is_none() && depth.is_none() && stencil.is_none() {
            return;
        }
        if color.is_some() {
            self.make_draw_buffer_resident();
        }
        let bounds = self.scissored_window();
        let (x_lo, x_hi) = (ax.lo.max(bounds.x0), ax.hi.min(bounds.x1));
        let (y_lo, y_hi) = (ay.lo.max(bounds.y0), ay.hi.min(bounds.y1));
        let linear = filter == GL_LINEAR;
        let fb = &mut self.framebuffer;
        for y in y_lo..y_hi {
            let v = ay.source(y);
            let sy = v.floor() as i64;
            for x in x_lo..x_hi {
                let u = ax.source(x);
                let sx = u.floor() as i64;
                let Some(i) = src.index(
                    sx.clamp(-1, i32::MAX as i64) as i32,
                    sy.clamp(-1, i32::MAX as i64) as i32,
                ) else {
                    continue;
                };
                if let Some(c) = color {
                    let value = if linear { src.linear(c, u, v) } else { c[i] };
                    fb.set_color(x, y, value);
                }
                if let Some(d) = depth {
                    fb.set_depth(x, y, d[i]);
                }
                if let Some(s) = stencil {
                    fb.set_stencil(x, y, s[i]);
                }
            }
        }
    }
}

//! EXT_framebuffer_blit: the same calls on Mesa and on tilegl (Rust API and C ABI): the
//! separate read and draw bindings and their queries, read commands on the read framebuffer,
//! `glBlitFramebufferEXT` between the window and framebuffer objects both ways, and its
//! errors. Every answer equal to Mesa's, except `GL_LINEAR` scaled blits, compared within one
//! unit of 8 bits: the bilinear weights are a fraction of a pixel, and llvmpipe quantises
//! them to 8 bits (its texture filter's fixed-point lerp) where tilegl mixes in double
//! precision and rounds once, so the two can round a mix to neighbouring values.

super::state_case_list!(source = include_str!("fbo_blit.rs"), agree = |a: &Answer, b: &Answer| {
    a.values.len() == b.values.len()
        && a.values
            .iter()
            .zip(&b.values)
            .all(|(x, y)| (x - y).abs() <= a.tolerance)
};
    fbo_blit_bindings_and_errors: "The read and draw bindings (GL_FRAMEBUFFER_EXT binds both), their queries, attachments and statuses through GL_READ_FRAMEBUFFER_EXT and GL_DRAW_FRAMEBUFFER_EXT, glReadPixels and GL_READ_BUFFER following the read binding, and the errors of glBlitFramebufferEXT: a bad mask bit (GL_INVALID_VALUE), a bad filter (GL_INVALID_ENUM), GL_LINEAR with depth or stencil and depth formats that differ (GL_INVALID_OPERATION), an incomplete read or draw framebuffer (GL_INVALID_FRAMEBUFFER_OPERATION_EXT); a buffer one side lacks is ignored. Every answer equals Mesa's.",
    fbo_blit_color: "Colour blits from the window into a renderbuffer and back: 1:1, magnified 2x, mirrored in x and y, scissored (the scissor box applies to the destination only), then glCopyPixels, glCopyTexImage2D, glCopyTexSubImage2D and glReadPixels from the read framebuffer while another is drawn, and a blit compiled into a display list. GL_NEAREST answers equal Mesa's; GL_LINEAR magnified and minified blits within one unit of 8 bits.",
    fbo_blit_depth_stencil: "Depth and stencil blits (GL_NEAREST) between the window's 24/8-bit buffers and a GL_DEPTH24_STENCIL8_EXT renderbuffer, each mask alone and both, 1:1 and mirrored, and a colour-only blit leaving depth and stencil alone. Every answer equals Mesa's.",
);

use super::fbo::{err, exact, floats, int, pixel_space, quad, read_rgba, Answer, Answers};
use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::Gl;

fn status_of(gl: &mut dyn Gl, out: &mut Answers, target: GLenum, label: &str) {
    let s = gl.check_framebuffer_status_ext(target);
    exact(
        out,
        format!("status of 0x{target:04x} {label}"),
        vec![s as f64],
    );
}

fn renderbuffer(gl: &mut dyn Gl, format: GLenum, w: i32, h: i32) -> u32 {
    let mut rb = [0];
    gl.gen_renderbuffers_ext(1, &mut rb);
    gl.bind_renderbuffer_ext(GL_RENDERBUFFER_EXT, rb[0]);
    gl.renderbuffer_storage_ext(GL_RENDERBUFFER_EXT, format, w, h);
    rb[0]
}

/// A framebuffer object with an RGBA8 colour renderbuffer and, if `depth` is not 0, a depth
/// (and stencil, for GL_DEPTH24_STENCIL8_EXT) renderbuffer, bound to `target`.
fn framebuffer(gl: &mut dyn Gl, target: GLenum, depth: GLenum, w: i32, h: i32) -> u32 {
    let mut fb = [0];
    gl.gen_framebuffers_ext(1, &mut fb);
    gl.bind_framebuffer_ext(target, fb[0]);
    let c = renderbuffer(gl, GL_RGBA8, w, h);
    gl.framebuffer_renderbuffer_ext(target, GL_COLOR_ATTACHMENT0_EXT, GL_RENDERBUFFER_EXT, c);
    if depth != 0 {
        let d = renderbuffer(gl, depth, w, h);
        gl.framebuffer_renderbuffer_ext(target, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, d);
        if depth == GL_DEPTH24_STENCIL8_EXT {
            gl.framebuffer_renderbuffer_ext(
                target,
                GL_STENCIL_ATTACHMENT_EXT,
                GL_RENDERBUFFER_EXT,
                d,
            );
        }
    }
    fb[0]
}

/// A 16x16 picture with a different colour at every pixel, drawn at (x, y).
fn picture(gl: &mut dyn Gl, x: i32, y: i32) {
    let mut px = vec![0u8; 16 * 16 * 4];
    for (i, p) in px.chunks_mut(4).enumerate() {
        let (u, v) = (i % 16, i / 16);
        p.copy_from_slice(&[
            (u * 16 + 8) as u8,
            (v * 16 + 4) as u8,
            ((u ^ v) * 15) as u8,
            255 - (u * v) as u8,
        ]);
    }
    gl.window_pos_2i(x, y);
    gl.draw_pixels(16, 16, GL_RGBA, GL_UNSIGNED_BYTE, Some(&px));
}

fn read_rgba_within(
    gl: &mut dyn Gl,
    out: &mut Answers,
    label: &str,
    rect: [i32; 4],
    tolerance: f64,
) {
    let [x, y, w, h] = rect;
    let mut px = vec![0u8; (w * h * 4) as usize];
    gl.read_pixels(x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    out.push(Answer {
        label: format!("glReadPixels {label}"),
        values: px.iter().map(|&v| v as f64).collect(),
        tolerance,
    });
    err(gl, out, label);
}

fn read_depth_stencil(gl: &mut dyn Gl, out: &mut Answers, label: &str, w: i32, h: i32) {
    let mut bytes = vec![0u8; (w * h * 4) as usize];
    gl.read_pixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, &mut bytes);
    out.push(Answer {
        label: format!("depth {label}"),
        values: floats(&bytes).iter().map(|&d| d as f64).collect(),
        tolerance: 2.0 / 16777215.0,
    });
    let mut stencil = vec![0u8; (w * h) as usize];
    gl.read_pixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &mut stencil);
    exact(
        out,
        format!("stencil {label}"),
        stencil.iter().map(|&s| s as f64).collect(),
    );
    err(gl, out, label);
}

/// Bindings, queries and the errors of glBlitFramebufferEXT.
fn fbo_blit_bindings_and_errors(gl: &mut dyn Gl, out: &mut Answers) {
    int(gl, out, GL_READ_FRAMEBUFFER_BINDING_EXT);
    int(gl, out, GL_DRAW_FRAMEBUFFER_BINDING_EXT);
    let a = framebuffer(gl, GL_READ_FRAMEBUFFER_EXT, 0, 8, 8);
    let b = framebuffer(gl, GL_DRAW_FRAMEBUFFER_EXT, GL_DEPTH24_STENCIL8_EXT, 8, 8);
    err(gl, out, "attaching through the read and draw targets");
    int(gl, out, GL_READ_FRAMEBUFFER_BINDING_EXT);
    int(gl, out, GL_DRAW_FRAMEBUFFER_BINDING_EXT);
    int(gl, out, GL_FRAMEBUFFER_BINDING_EXT);
    status_of(gl, out, GL_READ_FRAMEBUFFER_EXT, "colour only");
    status_of(gl, out, GL_DRAW_FRAMEBUFFER_EXT, "colour, depth, stencil");
    let mut v = [-1];
    gl.get_framebuffer_attachment_parameteriv_ext(
        GL_READ_FRAMEBUFFER_EXT,
        GL_DEPTH_ATTACHMENT_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT,
        &mut v,
    );
    exact(
        out,
        "read framebuffer's depth attachment".into(),
        vec![v[0] as f64],
    );
    gl.get_framebuffer_attachment_parameteriv_ext(
        GL_DRAW_FRAMEBUFFER_EXT,
        GL_DEPTH_ATTACHMENT_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT,
        &mut v,
    );
    exact(
        out,
        "draw framebuffer's depth attachment".into(),
        vec![v[0] as f64],
    );
    int(gl, out, GL_DEPTH_BITS);
    int(gl, out, GL_STENCIL_BITS);
    // Clears go to the draw framebuffer; glReadPixels reads the read framebuffer.
    gl.clear_color(1.0, 0.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    read_rgba(
        gl,
        out,
        "of the read framebuffer (never cleared)",
        0,
        0,
        2,
        1,
    );
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, b);
    read_rgba(gl, out, "of the draw framebuffer (cleared)", 0, 0, 2, 1);
    gl.read_buffer(GL_NONE);
    int(gl, out, GL_READ_BUFFER);
    gl.read_buffer(GL_COLOR_ATTACHMENT0_EXT);
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, 0);
    int(gl, out, GL_READ_BUFFER);
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, a);
    // Errors.
    gl.blit_framebuffer_ext(0, 0, 8, 8, 0, 0, 8, 8, 0x1, GL_NEAREST);
    err(gl, out, "a mask bit outside colour, depth and stencil");
    gl.blit_framebuffer_ext(
        0,
        0,
        8,
        8,
        0,
        0,
        8,
        8,
        GL_COLOR_BUFFER_BIT,
        GL_LINEAR_MIPMAP_LINEAR,
    );
    err(gl, out, "filter GL_LINEAR_MIPMAP_LINEAR");
    gl.blit_framebuffer_ext(0, 0, 8, 8, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT, GL_LINEAR);
    err(gl, out, "GL_LINEAR with depth");
    gl.blit_framebuffer_ext(0, 0, 8, 8, 0, 0, 8, 8, GL_STENCIL_BUFFER_BIT, GL_LINEAR);
    err(gl, out, "GL_LINEAR with stencil");
    // The read framebuffer has no depth or stencil: those bits are ignored.
    gl.blit_framebuffer_ext(
        0,
        0,
        8,
        8,
        0,
        0,
        8,
        8,
        GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
        GL_NEAREST,
    );
    err(gl, out, "depth and stencil the read framebuffer lacks");
    // Depth formats that differ.
    let c = framebuffer(gl, GL_READ_FRAMEBUFFER_EXT, GL_DEPTH_COMPONENT16, 8, 8);
    status_of(gl, out, GL_READ_FRAMEBUFFER_EXT, "colour and 16-bit depth");
    gl.blit_framebuffer_ext(0, 0, 8, 8, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    err(gl, out, "16-bit depth into 24-bit depth");
    gl.blit_framebuffer_ext(0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    err(gl, out, "colour beside depth formats that differ");
    // Incomplete framebuffers.
    let mut empty = [0];
    gl.gen_framebuffers_ext(1, &mut empty);
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, empty[0]);
    status_of(gl, out, GL_READ_FRAMEBUFFER_EXT, "no attachment");
    gl.blit_framebuffer_ext(0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    err(gl, out, "an incomplete read framebuffer");
    let mut px = [0u8; 4];
    gl.read_pixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    err(gl, out, "glReadPixels of an incomplete read framebuffer");
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, a);
    gl.bind_framebuffer_ext(GL_DRAW_FRAMEBUFFER_EXT, empty[0]);
    gl.blit_framebuffer_ext(0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    err(gl, out, "an incomplete draw framebuffer");
    gl.read_pixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    err(
        gl,
        out,
        "glReadPixels of a complete read framebuffer, incomplete draw",
    );
    // GL_FRAMEBUFFER_EXT binds both; deleting the read framebuffer unbinds it.
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, b);
    int(gl, out, GL_READ_FRAMEBUFFER_BINDING_EXT);
    int(gl, out, GL_DRAW_FRAMEBUFFER_BINDING_EXT);
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, c);
    gl.delete_framebuffers_ext(1, &[c]);
    int(gl, out, GL_READ_FRAMEBUFFER_BINDING_EXT);
    int(gl, out, GL_DRAW_FRAMEBUFFER_BINDING_EXT);
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, 0);
    gl.delete_framebuffers_ext(3, &[a, b, empty[0]]);
    err(gl, out, "the end");
}

/// Colour blits between the window and a renderbuffer, and read commands on the read
/// framebuffer.
fn fbo_blit_color(gl: &mut dyn Gl, out: &mut Answers) {
    pixel_space(gl, 64, 64);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    picture(gl, 0, 0);
    let fb = framebuffer(gl, GL_DRAW_FRAMEBUFFER_EXT, 0, 32, 32);
    gl.clear_color(0.5, 0.5, 0.5, 0.5);
    gl.clear(GL_COLOR_BUFFER_BIT);
    // Window -> object: 1:1, 2x magnified, mirrored in x, mirrored in y.
    let c = GL_COLOR_BUFFER_BIT;
    gl.blit_framebuffer_ext(0, 0, 16, 16, 0, 0, 16, 16, c, GL_NEAREST);
    gl.blit_framebuffer_ext(4, 4, 12, 12, 16, 0, 32, 16, c, GL_NEAREST);
    gl.blit_framebuffer_ext(0, 0, 16, 16, 16, 16, 0, 32, c, GL_NEAREST);
    gl.blit_framebuffer_ext(16, 16, 0, 0, 16, 16, 32, 32, c, GL_NEAREST);
    err(gl, out, "blits into the object");
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, fb);
    read_rgba(gl, out, "of the object", 0, 0, 32, 32);
    // Scissored, and partly outside the source (1:1: those pixels are not written).
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, 0);
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(4, 6, 8, 20);
    gl.blit_framebuffer_ext(0, 0, 16, 16, 0, 0, 16, 16, c, GL_NEAREST);
    gl.disable(GL_SCISSOR_TEST);
    gl.clear_color(0.0, 0.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(4, 6, 8, 20);
    gl.blit_framebuffer_ext(8, 8, 24, 24, 2, 2, 18, 18, c, GL_NEAREST);
    gl.disable(GL_SCISSOR_TEST);
    err(gl, out, "a scissored blit");
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, fb);
    read_rgba(gl, out, "after the scissored blit", 0, 0, 32, 32);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, 0);
    gl.blit_framebuffer_ext(0, 0, 16, 16, 0, 0, 16, 16, c, GL_NEAREST);
    // Object -> window, 1:1 and linear magnified (3x) and minified (16 -> 6).
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, fb);
    gl.bind_framebuffer_ext(GL_DRAW_FRAMEBUFFER_EXT, 0);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.blit_framebuffer_ext(0, 0, 16, 16, 48, 48, 64, 64, c, GL_NEAREST);
    gl.blit_framebuffer_ext(2, 2, 10, 10, 0, 16, 24, 40, c, GL_LINEAR);
    gl.blit_framebuffer_ext(0, 0, 16, 16, 30, 40, 36, 46, c, GL_LINEAR);
    err(gl, out, "blits into the window");
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, 0);
    read_rgba(gl, out, "of the window, 1:1 part", 48, 48, 16, 16);
    read_rgba_within(gl, out, "of the window, linear 3x", [0, 16, 24, 24], 1.0);
    read_rgba_within(
        gl,
        out,
        "of the window, linear minified",
        [30, 40, 6, 6],
        1.0,
    );
    // Read commands on the object while the window is drawn.
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, fb);
    gl.window_pos_2i(40, 0);
    gl.copy_pixels(2, 3, 10, 9, GL_COLOR);
    err(gl, out, "glCopyPixels from the object into the window");
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, 0);
    read_rgba(gl, out, "of the window after glCopyPixels", 40, 0, 12, 12);
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, fb);
    let mut t = [0];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 2, 8, 8, 0);
    gl.copy_tex_sub_image_2d(GL_TEXTURE_2D, 0, 4, 4, 20, 20, 4, 4);
    err(gl, out, "glCopyTex[Sub]Image2D from the object");
    let mut texels = vec![0u8; 8 * 8 * 4];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut texels);
    exact(
        out,
        "the texture copied from the read framebuffer".into(),
        texels.iter().map(|&v| v as f64).collect(),
    );
    gl.delete_textures(1, &t);
    // A blit compiled into a display list runs when the list is called.
    gl.bind_framebuffer_ext(GL_DRAW_FRAMEBUFFER_EXT, 0);
    let list = gl.gen_lists(1);
    gl.new_list(list, GL_COMPILE);
    gl.blit_framebuffer_ext(0, 0, 4, 4, 60, 60, 64, 64, c, GL_NEAREST);
    gl.end_list();
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, 0);
    read_rgba(
        gl,
        out,
        "of the window after compiling a blit",
        60,
        60,
        4,
        4,
    );
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, fb);
    gl.call_list(list);
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, 0);
    read_rgba(gl, out, "of the window after calling it", 60, 60, 4, 4);
    gl.delete_lists(list, 1);
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, 0);
    gl.delete_framebuffers_ext(1, &[fb]);
    err(gl, out, "the end");
}

/// Depth and stencil blits between the window and a packed depth-stencil renderbuffer.
fn fbo_blit_depth_stencil(gl: &mut dyn Gl, out: &mut Answers) {
    pixel_space(gl, 64, 64);
    gl.clear_depth(1.0);
    gl.clear_stencil(0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    // Depth: quads at three depths; stencil: scissored clears.
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_ALWAYS);
    quad(gl, 0.0, 0.0, 8.0, 16.0, -0.5);
    quad(gl, 8.0, 0.0, 16.0, 8.0, 0.25);
    quad(gl, 4.0, 10.0, 14.0, 14.0, 0.75);
    gl.disable(GL_DEPTH_TEST);
    gl.enable(GL_SCISSOR_TEST);
    for (i, (x, y, w, h)) in [(0, 0, 6, 6), (5, 3, 8, 4), (2, 9, 3, 7)]
        .into_iter()
        .enumerate()
    {
        gl.scissor(x, y, w, h);
        gl.clear_stencil(i as i32 * 60 + 7);
        gl.clear(GL_STENCIL_BUFFER_BIT);
    }
    gl.disable(GL_SCISSOR_TEST);
    let fb = framebuffer(gl, GL_FRAMEBUFFER_EXT, GL_DEPTH24_STENCIL8_EXT, 16, 16);
    status_of(gl, out, GL_FRAMEBUFFER_EXT, "colour and depth-stencil");
    gl.clear_depth(0.5);
    gl.clear_stencil(3);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, 0);
    gl.blit_framebuffer_ext(0, 0, 16, 16, 0, 0, 16, 16, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    err(gl, out, "depth blit into the object");
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, fb);
    read_depth_stencil(gl, out, "after the depth blit", 16, 16);
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, 0);
    gl.blit_framebuffer_ext(
        0,
        0,
        16,
        16,
        16,
        0,
        0,
        16,
        GL_STENCIL_BUFFER_BIT,
        GL_NEAREST,
    );
    err(gl, out, "mirrored stencil blit into the object");
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, fb);
    read_depth_stencil(gl, out, "after the stencil blit", 16, 16);
    // Object -> window: both, mirrored in y, into the window's (32, 32).
    gl.bind_framebuffer_ext(GL_DRAW_FRAMEBUFFER_EXT, 0);
    gl.blit_framebuffer_ext(
        0,
        0,
        16,
        16,
        32,
        48,
        48,
        32,
        GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
        GL_NEAREST,
    );
    // Colour only: depth and stencil stay.
    gl.blit_framebuffer_ext(0, 0, 16, 16, 0, 0, 16, 16, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    err(gl, out, "blits into the window");
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, 0);
    let mut bytes = vec![0u8; 16 * 16 * 4];
    gl.read_pixels(32, 32, 16, 16, GL_DEPTH_COMPONENT, GL_FLOAT, &mut bytes);
    out.push(Answer {
        label: "window depth after the blit".into(),
        values: floats(&bytes).iter().map(|&d| d as f64).collect(),
        tolerance: 2.0 / 16777215.0,
    });
    let mut stencil = vec![0u8; 16 * 16];
    gl.read_pixels(
        32,
        32,
        16,
        16,
        GL_STENCIL_INDEX,
        GL_UNSIGNED_BYTE,
        &mut stencil,
    );
    exact(
        out,
        "window stencil after the blit".into(),
        stencil.iter().map(|&s| s as f64).collect(),
    );
    read_depth_stencil(
        gl,
        out,
        "of the window's corner after the colour blit",
        16,
        16,
    );
    gl.delete_framebuffers_ext(1, &[fb]);
    err(gl, out, "the end");
}

//! EXT_framebuffer_object where the extension and Mesa 22 differ (Mesa follows OpenGL 3.0 and
//! later there; the agreeing cases are in `conformance/src/state_cases/fbo.rs`): each expected
//! value is the extension's text, quoted beside it, or ARB_framebuffer_object's where that
//! extension (listed too, one set of rules per context) replaced it. Also the undefined cases that must not
//! crash (a texture sampled while it is drawn into) and the window's buffers surviving a
//! framebuffer object.

use tilegl::enums::*;
use tilegl::{Context, Gl};

fn ctx() -> Context {
    Context::new(16, 16)
}

fn texture(gl: &mut Context, format: GLenum, w: i32, h: i32) -> u32 {
    let mut t = [0];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        format as i32,
        w,
        h,
        0,
        if format == GL_DEPTH_COMPONENT24 {
            GL_DEPTH_COMPONENT
        } else {
            GL_RGBA
        },
        GL_UNSIGNED_BYTE,
        None,
    );
    t[0]
}

fn bound_fbo(gl: &mut Context) -> u32 {
    let mut f = [0];
    gl.gen_framebuffers_ext(1, &mut f);
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, f[0]);
    f[0]
}

fn renderbuffer(gl: &mut Context, format: GLenum, w: i32, h: i32) -> u32 {
    let mut r = [0];
    gl.gen_renderbuffers_ext(1, &mut r);
    gl.bind_renderbuffer_ext(GL_RENDERBUFFER_EXT, r[0]);
    gl.renderbuffer_storage_ext(GL_RENDERBUFFER_EXT, format, w, h);
    r[0]
}

fn status(gl: &mut Context) -> GLenum {
    gl.check_framebuffer_status_ext(GL_FRAMEBUFFER_EXT)
}

#[test]
fn images_of_different_sizes_draw_into_the_common_rectangle() {
    // EXT_framebuffer_object made this FRAMEBUFFER_INCOMPLETE_DIMENSIONS_EXT; with
    // ARB_framebuffer_object listed its section 4.4.1 applies: "If the attachment sizes are
    // not all identical, rendering will be limited to the largest area that can fit in all of
    // the attachments".
    let mut gl = ctx();
    let t = texture(&mut gl, GL_RGBA8, 8, 8);
    bound_fbo(&mut gl);
    gl.framebuffer_texture_2dext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_TEXTURE_2D,
        t,
        0,
    );
    let rb = renderbuffer(&mut gl, GL_DEPTH_COMPONENT24, 8, 4);
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER_EXT,
        GL_DEPTH_ATTACHMENT_EXT,
        GL_RENDERBUFFER_EXT,
        rb,
    );
    assert_eq!(status(&mut gl), GL_FRAMEBUFFER_COMPLETE_EXT);
    gl.clear_color(1.0, 0.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut px = vec![0u8; 8 * 4 * 4];
    gl.read_pixels(0, 0, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    assert!(px.chunks(4).all(|p| p == [255, 0, 0, 255]));
    // The texture got the common 8 x 4 rectangle; its upper half keeps its zeros.
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, 0);
    let mut img = vec![0u8; 8 * 8 * 4];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut img);
    assert!(img[..8 * 4 * 4].chunks(4).all(|p| p == [255, 0, 0, 255]));
    assert!(img[8 * 4 * 4..].iter().all(|&v| v == 0));
}

#[test]
fn draw_and_read_buffers_need_a_colour_attachment() {
    // "The value of FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT must not be NONE for any color
    // attachment point(s) named by DRAW_BUFFERi. { FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER_EXT }"
    // "If READ_BUFFER is not NONE, then ... { FRAMEBUFFER_INCOMPLETE_READ_BUFFER_EXT }"
    let mut gl = ctx();
    bound_fbo(&mut gl);
    let rb = renderbuffer(&mut gl, GL_DEPTH_COMPONENT16, 4, 4);
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER_EXT,
        GL_DEPTH_ATTACHMENT_EXT,
        GL_RENDERBUFFER_EXT,
        rb,
    );
    assert_eq!(status(&mut gl), GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER_EXT);
    gl.draw_buffer(GL_NONE);
    assert_eq!(status(&mut gl), GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER_EXT);
    gl.read_buffer(GL_NONE);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(status(&mut gl), GL_FRAMEBUFFER_COMPLETE_EXT);
    // A depth-only object draws depth.
    gl.clear_depth(0.25);
    gl.clear(GL_DEPTH_BUFFER_BIT);
    let mut d = [0u8; 4];
    gl.read_pixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &mut d);
    assert_eq!(f32::from_ne_bytes(d), 16384.0 / 65535.0);
    let mut q = [0];
    gl.get_integerv(GL_DEPTH_BITS, &mut q);
    assert_eq!(q[0], 16);
}

#[test]
fn only_color_renderable_formats_attach_to_the_colour_point() {
    // ARB_framebuffer_object 4.4.4: "The following base internal formats ... are
    // color-renderable: ALPHA, LUMINANCE, LUMINANCE_ALPHA, INTENSITY, RED, RG, RGB, RGBA ...
    // No other formats, including compressed internal formats, are color-renderable."
    let mut gl = ctx();
    let depth = texture(&mut gl, GL_DEPTH_COMPONENT24, 4, 4);
    bound_fbo(&mut gl);
    gl.framebuffer_texture_2dext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_TEXTURE_2D,
        depth,
        0,
    );
    assert_eq!(status(&mut gl), GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_EXT);
    for format in [
        GL_LUMINANCE8,
        GL_ALPHA8,
        GL_LUMINANCE8_ALPHA8,
        GL_INTENSITY8,
        GL_RGB8,
    ] {
        let t = texture(&mut gl, format, 4, 4);
        gl.framebuffer_texture_2dext(
            GL_FRAMEBUFFER_EXT,
            GL_COLOR_ATTACHMENT0_EXT,
            GL_TEXTURE_2D,
            t,
            0,
        );
        assert_eq!(status(&mut gl), GL_FRAMEBUFFER_COMPLETE_EXT, "0x{format:x}");
    }
    // Errors: "INVALID_ENUM is generated if RenderbufferStorage is called with an
    // <internalformat> that is not RGB, RGBA, DEPTH_COMPONENT, STENCIL_INDEX, DEPTH_STENCIL,
    // or one of the internal formats from table 3.16 or table 2.nnn that has a base internal
    // format of RGB, RGBA, DEPTH_COMPONENT, STENCIL_INDEX, or DEPTH_STENCIL."
    let _ = renderbuffer(&mut gl, GL_RGB5, 4, 4);
    gl.renderbuffer_storage_ext(GL_RENDERBUFFER_EXT, GL_LUMINANCE_ALPHA, 4, 4);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.renderbuffer_storage_ext(GL_RENDERBUFFER_EXT, 4, 4, 4);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
}

#[test]
fn error_codes_of_the_extension_text() {
    let mut gl = ctx();
    // With the window bound, ARB_framebuffer_object section 6.1.3: "If the default
    // framebuffer is bound to <target>, then <attachment> must be one of FRONT_LEFT,
    // FRONT_RIGHT, BACK_LEFT, BACK_RIGHT, or AUXi, ...; DEPTH, ...; or STENCIL" (the
    // extension's own INVALID_OPERATION applied before ARB_framebuffer_object).
    let mut v = [0];
    gl.get_framebuffer_attachment_parameteriv_ext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT,
        &mut v,
    );
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    bound_fbo(&mut gl);
    // "INVALID_ENUM is generated if FramebufferRenderbufferEXT or
    // FramebufferTexture{1D|2D|3D}EXT is called with an <attachment> that is not an accepted
    // attachment point" (GL_MAX_COLOR_ATTACHMENTS_EXT is 1).
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT1_EXT,
        GL_RENDERBUFFER_EXT,
        0,
    );
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    let mut m = [0];
    gl.get_integerv(GL_MAX_COLOR_ATTACHMENTS_EXT, &mut m);
    assert_eq!(m[0], 1);
    // "INVALID_ENUM ... GetFramebufferAttachmentParameterivEXT is called with a <pname>
    // other than FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT when the type of the attached object
    // at the named attachment point is RENDERBUFFER_EXT."
    let rb = renderbuffer(&mut gl, GL_RGBA8, 2, 2);
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_RENDERBUFFER_EXT,
        rb,
    );
    gl.get_framebuffer_attachment_parameteriv_ext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT,
        &mut v,
    );
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    // "INVALID_OPERATION ... DrawBuffer ... or ReadBuffer is called with a <buf> constant
    // (other than NONE) that is not in the range COLOR_ATTACHMENT0_EXT through
    // COLOR_ATTACHMENTn_EXT"
    gl.read_buffer(GL_COLOR_ATTACHMENT1_EXT);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.draw_buffer(0x1234);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    // Section 5.4: the commands are executed immediately while a list is compiled.
    gl.new_list(1, GL_COMPILE);
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, 0);
    gl.end_list();
    let mut b = [-1];
    gl.get_integerv(GL_FRAMEBUFFER_BINDING_EXT, &mut b);
    assert_eq!(b[0], 0);
    // "If CheckFramebufferStatusEXT is called within a Begin/End pair, INVALID_OPERATION is
    // generated ... 0 is returned."
    gl.begin(GL_POINTS);
    assert_eq!(gl.check_framebuffer_status_ext(GL_FRAMEBUFFER_EXT), 0);
    gl.end();
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn a_texture_sampled_while_drawn_into_does_not_crash() {
    // Section 4.4.3: the fragments are undefined; tilegl samples the texture as last stored.
    let mut gl = ctx();
    let t = texture(&mut gl, GL_RGBA8, 8, 8);
    bound_fbo(&mut gl);
    gl.framebuffer_texture_2dext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_TEXTURE_2D,
        t,
        0,
    );
    gl.viewport(0, 0, 8, 8);
    gl.clear_color(0.0, 1.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.enable(GL_TEXTURE_2D);
    for _ in 0..3 {
        gl.begin(GL_TRIANGLES);
        gl.tex_coord_2f(0.0, 0.0);
        gl.vertex_2f(-1.0, -1.0);
        gl.tex_coord_2f(1.0, 0.0);
        gl.vertex_2f(1.0, -1.0);
        gl.tex_coord_2f(0.0, 1.0);
        gl.vertex_2f(-1.0, 1.0);
        gl.end();
        // A texture upload while attached and bound: stored first, then reloaded.
        gl.tex_sub_image_2d(
            GL_TEXTURE_2D,
            0,
            0,
            0,
            1,
            1,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&[255, 0, 0, 255]),
        );
    }
    gl.finish();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut p = [0u8; 4];
    gl.read_pixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut p);
    assert_eq!(p, [255, 0, 0, 255], "the uploaded texel shows in the tiles");
    gl.read_pixels(7, 7, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut p);
    assert_eq!(
        p,
        [0, 255, 0, 255],
        "the cleared texel outside the triangle"
    );
}

#[test]
fn the_window_keeps_its_buffers_while_an_object_is_bound() {
    let mut gl = Context::new(16, 16);
    gl.clear_color(0.0, 0.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let t = texture(&mut gl, GL_RGBA8, 4, 4);
    bound_fbo(&mut gl);
    gl.framebuffer_texture_2dext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_TEXTURE_2D,
        t,
        0,
    );
    gl.clear_color(1.0, 0.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    // The window-system view (OSMesa, GLX) still sees the window.
    assert_eq!(gl.size(), (16, 16));
    assert_eq!(gl.framebuffer().color_at(15, 15), Some([0, 0, 255, 255]));
    let mut q = [0];
    gl.get_integerv(GL_DRAW_BUFFER, &mut q);
    assert_eq!(q[0], GL_COLOR_ATTACHMENT0_EXT as i32);
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, 0);
    gl.get_integerv(GL_DRAW_BUFFER, &mut q);
    assert_eq!(q[0], GL_FRONT as i32);
    let mut p = [0u8; 4];
    gl.read_pixels(15, 15, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut p);
    assert_eq!(p, [0, 0, 255, 255]);
}

#[test]
fn framebuffer_and_renderbuffer_objects_are_shared_like_textures() {
    // "Framebuffer objects created with the commands defined by the
    // GL_EXT_framebuffer_object extension are defined to be shared".
    let mut a = Context::new(8, 8);
    let mut b = Context::new(8, 8);
    b.join_share_group(&a.share_group());
    let fb = bound_fbo(&mut a);
    let rb = renderbuffer(&mut a, GL_RGBA8, 4, 4);
    a.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_RENDERBUFFER_EXT,
        rb,
    );
    a.clear_color(1.0, 0.0, 1.0, 1.0);
    a.clear(GL_COLOR_BUFFER_BIT);
    // The drawing reaches the renderbuffer when A's binding changes.
    a.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, 0);
    assert_eq!(b.is_framebuffer_ext(fb), GL_TRUE as u8);
    assert_eq!(b.is_renderbuffer_ext(rb), GL_TRUE as u8);
    b.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, fb);
    assert_eq!(
        b.check_framebuffer_status_ext(GL_FRAMEBUFFER_EXT),
        GL_FRAMEBUFFER_COMPLETE_EXT
    );
    let mut p = [0u8; 4];
    b.read_pixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut p);
    assert_eq!(p, [255, 0, 255, 255]);
    // Deleted in one context, gone in the other; B's binding to it draws nothing, no panic.
    a.delete_framebuffers_ext(1, &[fb]);
    assert_eq!(b.is_framebuffer_ext(fb), GL_FALSE as u8);
    b.clear(GL_COLOR_BUFFER_BIT);
    b.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, 0);
    assert_eq!(b.get_error(), GL_NO_ERROR);
}

#[test]
fn linear_blit_is_the_bilinear_mix_clamped_to_the_edge() {
    // EXT_framebuffer_blit: "LINEAR filtering ... as though CLAMP_TO_EDGE texture sampling
    // were being performed"; the mix is section 3.8.8's (1 - a) t0 + a t1, and destination
    // pixel i of a 4x magnification samples source point (i + 0.5) / 4. Colours chosen so
    // that every mix is a whole number (no rounding question). The source is the last two
    // pixels of the window's row: right of it is the buffer's edge; left of it, where the
    // implementation may or may not clamp to the source rectangle, a pixel equal to the
    // first one.
    let mut gl = ctx();
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let px = [0u8, 0, 0, 255, 160, 80, 40, 255];
    gl.window_pos_2i(14, 0);
    gl.draw_pixels(2, 1, GL_RGBA, GL_UNSIGNED_BYTE, Some(&px));
    gl.blit_framebuffer_ext(14, 0, 16, 1, 0, 4, 8, 5, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut out = [0u8; 8 * 4];
    gl.read_pixels(0, 4, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut out);
    let mix = |a: f64| [(160.0 * a) as u8, (80.0 * a) as u8, (40.0 * a) as u8, 255];
    // Sample points minus one half: -0.375, -0.125 (clamped: pixel 0), 0.125 ... 0.875,
    // 1.125, 1.375 (clamped: pixel 1).
    let expected: Vec<u8> = [0.0, 0.0, 0.125, 0.375, 0.625, 0.875, 1.0, 1.0]
        .into_iter()
        .flat_map(mix)
        .collect();
    assert_eq!(out.to_vec(), expected);
}

#[test]
fn read_commands_follow_the_read_binding() {
    // EXT_framebuffer_blit: "ReadPixels, CopyPixels, CopyTex{Sub}Image* ... read from the
    // framebuffer bound to READ_FRAMEBUFFER_EXT"; drawing goes to DRAW_FRAMEBUFFER_EXT.
    let mut gl = ctx();
    gl.clear_color(0.0, 0.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let fb = bound_fbo(&mut gl);
    let rb = renderbuffer(&mut gl, GL_RGBA8, 4, 4);
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_RENDERBUFFER_EXT,
        rb,
    );
    gl.clear_color(1.0, 0.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.bind_framebuffer_ext(GL_DRAW_FRAMEBUFFER_EXT, 0);
    let mut px = [0u8; 4];
    gl.read_pixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    assert_eq!(px, [255, 0, 0, 255], "read from the object");
    // glCopyPixels: from the object into the window.
    gl.window_pos_2i(8, 8);
    gl.copy_pixels(0, 0, 2, 2, GL_COLOR);
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, 0);
    gl.read_pixels(9, 9, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    assert_eq!(px, [255, 0, 0, 255], "copied into the window");
    gl.read_pixels(7, 7, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    assert_eq!(px, [0, 0, 255, 255], "the window around it");
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut b = [0];
    gl.get_integerv(GL_DRAW_FRAMEBUFFER_BINDING_EXT, &mut b);
    assert_eq!(b[0], 0);
    gl.bind_framebuffer_ext(GL_READ_FRAMEBUFFER_EXT, fb);
    gl.get_integerv(GL_READ_FRAMEBUFFER_BINDING_EXT, &mut b);
    assert_eq!(b[0], fb as i32);
}

//! ARB_framebuffer_object where its text decides and Mesa 22 is not the reference (the
//! agreeing cases are in `conformance/src/state_cases/arb_fbo.rs`): each expected value is
//! the extension's text, quoted beside it.

use tilegl::enums::*;
use tilegl::{Context, Gl};

fn ctx() -> Context {
    Context::new(16, 16)
}

#[test]
fn a_depth_stencil_texture_attaches_to_both_points() {
    // 4.4.2.3: "Setting <attachment> to the value DEPTH_STENCIL_ATTACHMENT is a special case
    // causing both the depth and stencil attachments of the framebuffer object to be set to
    // <texture>."
    let mut gl = ctx();
    let mut t = [0];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_DEPTH_STENCIL as i32,
        8,
        8,
        0,
        GL_DEPTH_STENCIL,
        GL_UNSIGNED_INT_24_8,
        None,
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut f = [0];
    gl.gen_framebuffers_ext(1, &mut f);
    gl.bind_framebuffer(GL_FRAMEBUFFER, f[0]);
    gl.framebuffer_texture_2dext(
        GL_DRAW_FRAMEBUFFER,
        GL_DEPTH_STENCIL_ATTACHMENT,
        GL_TEXTURE_2D,
        t[0],
        0,
    );
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    for point in [
        GL_DEPTH_ATTACHMENT,
        GL_STENCIL_ATTACHMENT,
        GL_DEPTH_STENCIL_ATTACHMENT,
    ] {
        let mut v = [0];
        gl.get_framebuffer_attachment_parameteriv_ext(
            GL_FRAMEBUFFER,
            point,
            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
            &mut v,
        );
        assert_eq!(v[0], GL_TEXTURE as i32);
        gl.get_framebuffer_attachment_parameteriv_ext(
            GL_FRAMEBUFFER,
            point,
            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
            &mut v,
        );
        assert_eq!(v[0], t[0] as i32);
        assert_eq!(gl.get_error(), GL_NO_ERROR, "0x{point:x}");
    }
}

#[test]
fn the_arb_bind_commands_take_only_generated_names() {
    // 4.4.1: "BindFramebuffer fails and an INVALID_OPERATION error is generated if
    // <framebuffer> is not zero or a name returned from a previous call to GenFramebuffers,
    // or if such a name has since been deleted with DeleteFramebuffers." 4.4.2.1 says the
    // same of BindRenderbuffer. (Mesa's compatibility profile accepts any name here, so this
    // is not among the cases compared with Mesa.) The EXT commands still create objects for
    // any name (EXT_framebuffer_object section 4.4.1).
    let mut gl = ctx();
    let mut b = [-1];
    gl.bind_framebuffer(GL_FRAMEBUFFER, 7);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.get_integerv(GL_FRAMEBUFFER_BINDING, &mut b);
    assert_eq!(b[0], 0);
    gl.bind_renderbuffer(GL_RENDERBUFFER, 7);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.get_integerv(GL_RENDERBUFFER_BINDING, &mut b);
    assert_eq!(b[0], 0);
    let (mut f, mut r) = ([0], [0]);
    gl.gen_framebuffers_ext(1, &mut f);
    gl.gen_renderbuffers_ext(1, &mut r);
    gl.bind_framebuffer(GL_READ_FRAMEBUFFER, f[0]);
    gl.bind_renderbuffer(GL_RENDERBUFFER, r[0]);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.get_integerv(GL_READ_FRAMEBUFFER_BINDING, &mut b);
    assert_eq!(b[0], f[0] as i32);
    gl.get_integerv(GL_DRAW_FRAMEBUFFER_BINDING, &mut b);
    assert_eq!(b[0], 0);
    // Deleted names are refused again.
    gl.delete_framebuffers_ext(1, &f);
    gl.delete_renderbuffers_ext(1, &r);
    gl.bind_framebuffer(GL_FRAMEBUFFER, f[0]);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.bind_renderbuffer(GL_RENDERBUFFER, r[0]);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    // A name the EXT command created is an object, which the ARB command binds.
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, 9);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.bind_framebuffer(GL_FRAMEBUFFER, 0);
    gl.bind_framebuffer(GL_FRAMEBUFFER, 9);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    // The target is checked first: "INVALID_ENUM ... BindFramebuffer ... <target> is not
    // DRAW_FRAMEBUFFER, READ_FRAMEBUFFER or FRAMEBUFFER".
    gl.bind_framebuffer(GL_TEXTURE_2D, 12345);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
}

#[test]
fn no_multisample_renderbuffers() {
    // New state: "MAX_SAMPLES ... Minimum Value 0"; 4.4.2.1: "If either <width> or <height>
    // is greater than MAX_RENDERBUFFER_SIZE, or if <samples> is greater than MAX_SAMPLES,
    // then the error INVALID_VALUE is generated." RenderbufferStorage "is equivalent to
    // calling RenderbufferStorageMultisample with <samples> equal to zero".
    let mut gl = ctx();
    let mut v = [-1];
    gl.get_integerv(GL_MAX_SAMPLES, &mut v);
    assert_eq!(v[0], 0);
    let mut r = [0];
    gl.gen_renderbuffers_ext(1, &mut r);
    gl.bind_renderbuffer(GL_RENDERBUFFER, r[0]);
    gl.renderbuffer_storage_multisample(GL_RENDERBUFFER, 4, GL_RGBA8, 8, 8);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.get_renderbuffer_parameteriv_ext(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &mut v);
    assert_eq!(v[0], 0, "a failed command changes nothing");
    gl.renderbuffer_storage_multisample(GL_RENDERBUFFER, 0, GL_RGBA8, 8, 4);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    for (pname, want) in [
        (GL_RENDERBUFFER_WIDTH, 8),
        (GL_RENDERBUFFER_HEIGHT, 4),
        (GL_RENDERBUFFER_SAMPLES, 0),
        (GL_RENDERBUFFER_INTERNAL_FORMAT, GL_RGBA8 as i32),
    ] {
        gl.get_renderbuffer_parameteriv_ext(GL_RENDERBUFFER, pname, &mut v);
        assert_eq!(v[0], want, "0x{pname:x}");
    }
}

#[test]
fn a_layer_of_a_3d_texture_is_drawn_into() {
    // 4.4.2.3: "FramebufferTextureLayer ... operates identically to FramebufferTexture3D,
    // except that it attaches a single layer of a three-dimensional texture ... The error
    // INVALID_VALUE is generated if <layer> is negative. The error INVALID_OPERATION is
    // generated if <texture> is non-zero and is not the name of a three dimensional
    // texture".
    let mut gl = ctx();
    let mut t = [0; 2];
    gl.gen_textures(2, &mut t);
    gl.bind_texture(GL_TEXTURE_3D, t[0]);
    gl.tex_image_3d(
        GL_TEXTURE_3D,
        0,
        GL_RGBA8 as i32,
        4,
        4,
        3,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    gl.bind_texture(GL_TEXTURE_2D, t[1]);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        4,
        4,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    let mut f = [0];
    gl.gen_framebuffers_ext(1, &mut f);
    gl.bind_framebuffer(GL_FRAMEBUFFER, f[0]);
    gl.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t[1], 0, 0);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t[0], 0, -1);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t[0], 0, 1);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut v = [-1];
    gl.get_framebuffer_attachment_parameteriv_ext(
        GL_FRAMEBUFFER,
        GL_COLOR_ATTACHMENT0,
        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER,
        &mut v,
    );
    assert_eq!(v[0], 1);
    assert_eq!(
        gl.check_framebuffer_status_ext(GL_FRAMEBUFFER),
        GL_FRAMEBUFFER_COMPLETE
    );
    gl.clear_color(0.0, 1.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.bind_framebuffer(GL_FRAMEBUFFER, 0);
    let mut img = vec![0u8; 4 * 4 * 3 * 4];
    gl.bind_texture(GL_TEXTURE_3D, t[0]);
    gl.get_tex_image(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut img);
    let slice = 4 * 4 * 4;
    assert!(img[..slice].iter().all(|&v| v == 0), "layer 0 untouched");
    assert!(img[slice..2 * slice]
        .chunks(4)
        .all(|p| p == [0, 255, 0, 255]));
    assert!(
        img[2 * slice..].iter().all(|&v| v == 0),
        "layer 2 untouched"
    );
}

#[test]
fn a_luminance_alpha_image_reads_back_as_red_and_alpha() {
    // 4.4.4: LUMINANCE_ALPHA is colour-renderable; what a framebuffer of it holds reads back
    // through the luminance as red (OpenGL 3.0 section 4.3.2, table 3.20's L -> R): what was
    // drawn keeps L = R and A, green and blue read 0.
    let mut gl = ctx();
    let mut t = [0];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_LUMINANCE8_ALPHA8 as i32,
        4,
        4,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    let mut f = [0];
    gl.gen_framebuffers_ext(1, &mut f);
    gl.bind_framebuffer(GL_FRAMEBUFFER, f[0]);
    gl.framebuffer_texture_2dext(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t[0], 0);
    gl.clear_color(0.4, 0.6, 0.8, 0.2);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let mut px = [0u8; 4];
    gl.read_pixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    assert_eq!(px, [102, 0, 0, 51]);
    let mut bits = [-1];
    for (pname, want) in [
        (GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, 8),
        (GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE, 0),
        (GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE, 8),
        (
            GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE,
            GL_UNSIGNED_NORMALIZED as i32,
        ),
        (GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, GL_LINEAR as i32),
    ] {
        gl.get_framebuffer_attachment_parameteriv_ext(
            GL_FRAMEBUFFER,
            GL_COLOR_ATTACHMENT0,
            pname,
            &mut bits,
        );
        assert_eq!(bits[0], want, "0x{pname:x}");
    }
}

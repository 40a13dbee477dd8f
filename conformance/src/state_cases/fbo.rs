//! EXT_framebuffer_object: the same calls on Mesa and on tilegl (Rust API and C ABI), every
//! answer (status, queries, GL errors, read-backs of rendered images) equal to Mesa's.
//! Where Mesa 22 follows OpenGL 3.0/4.5 rather than the extension (mixed sizes, draw and read
//! buffers without an attachment, luminance renderbuffers, the error of an unknown attachment
//! point and of attachment queries on the window) tilegl keeps the extension, checked by its
//! own tests (`tests/fbo.rs`).

super::state_case_list!(source = include_str!("fbo.rs"), agree = |a: &Answer, b: &Answer| {
    a.values.len() == b.values.len()
        && a.values
            .iter()
            .zip(&b.values)
            .all(|(x, y)| (x - y).abs() <= a.tolerance)
};
    fbo_render_to_texture: "Render to texture: an RGBA8 texture attached to GL_COLOR_ATTACHMENT0_EXT is cleared and drawn into (flat quads on whole pixels, a scissored clear), read back through glReadPixels while bound and glGetTexImage after, then drawn into the window with GL_REPLACE and read back there. Every answer equals Mesa's.",
    fbo_objects_and_errors: "Framebuffer and renderbuffer objects: names, glIs*, bindings, the attachment queries, renderbuffer sizes, the completeness statuses both specifications agree on (missing attachment, an attachment without image, a depth image at the colour point and a colour image at the depth point) and the errors of section 'Errors' of the extension. Every answer equals Mesa's.",
    fbo_depth_stencil: "A colour renderbuffer with a packed depth-stencil renderbuffer (EXT_packed_depth_stencil) at both the depth and stencil points: depth-tested and stencilled quads, colour, depth and stencil read back. Every answer equals Mesa's (depths within two units of 24 bits).",
    fbo_pixels_and_mipmaps: "Pixel commands on a framebuffer object: glDrawPixels, glCopyPixels and glCopyTexSubImage2D from it, a depth texture as the depth attachment, and glGenerateMipmapEXT of the rendered texture (level 1 read back). Every answer equals Mesa's (depths within two units of 24 bits).",
);

use tilegl::api::GLenum;
use tilegl::enums::*;
use tilegl::Gl;

/// One answer: a label, the values, and how far they may differ from Mesa's.
#[derive(Debug)]
pub struct Answer {
    pub(super) label: String,
    pub(super) values: Vec<f64>,
    pub(super) tolerance: f64,
}

pub(super) type Answers = Vec<Answer>;

impl super::Recorded for Answer {
    fn label(&self) -> String {
        self.label.clone()
    }
    fn value(&self) -> String {
        format!("{:?}", self.values)
    }
}

pub(super) fn exact(out: &mut Answers, label: String, values: Vec<f64>) {
    out.push(Answer {
        label,
        values,
        tolerance: 0.0,
    });
}

pub(super) fn err(gl: &mut dyn Gl, out: &mut Answers, label: &str) {
    let e = gl.get_error();
    exact(out, format!("glGetError after {label}"), vec![e as f64]);
}

pub(super) fn status(gl: &mut dyn Gl, out: &mut Answers, label: &str) {
    let s = gl.check_framebuffer_status_ext(GL_FRAMEBUFFER_EXT);
    exact(out, format!("status {label}"), vec![s as f64]);
}

pub(super) fn int(gl: &mut dyn Gl, out: &mut Answers, pname: GLenum) {
    let mut v = [-1];
    gl.get_integerv(pname, &mut v);
    exact(
        out,
        format!("glGetIntegerv(0x{pname:04x})"),
        vec![v[0] as f64],
    );
}

fn attachment(gl: &mut dyn Gl, out: &mut Answers, point: GLenum, pname: GLenum) {
    let mut v = [-1];
    gl.get_framebuffer_attachment_parameteriv_ext(GL_FRAMEBUFFER_EXT, point, pname, &mut v);
    exact(
        out,
        format!("attachment 0x{point:04x} 0x{pname:04x}"),
        vec![v[0] as f64],
    );
    err(gl, out, "glGetFramebufferAttachmentParameterivEXT");
}

pub(super) fn read_rgba(
    gl: &mut dyn Gl,
    out: &mut Answers,
    label: &str,
    x: i32,
    y: i32,
    w: i32,
    h: i32,
) {
    let mut px = vec![0u8; (w * h * 4) as usize];
    gl.read_pixels(x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    exact(
        out,
        format!("glReadPixels {label}"),
        px.iter().map(|&v| v as f64).collect(),
    );
    err(gl, out, label);
}

pub(super) fn floats(bytes: &[u8]) -> Vec<f32> {
    bytes
        .chunks_exact(4)
        .map(|b| f32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
        .collect()
}

pub(super) fn quad(gl: &mut dyn Gl, x0: f32, y0: f32, x1: f32, y1: f32, z: f32) {
    gl.begin(GL_QUADS);
    gl.tex_coord_2f(0.0, 0.0);
    gl.vertex_3f(x0, y0, z);
    gl.tex_coord_2f(1.0, 0.0);
    gl.vertex_3f(x1, y0, z);
    gl.tex_coord_2f(1.0, 1.0);
    gl.vertex_3f(x1, y1, z);
    gl.tex_coord_2f(0.0, 1.0);
    gl.vertex_3f(x0, y1, z);
    gl.end();
}

/// Window coordinates = object coordinates over a `w` x `h` target.
pub(super) fn pixel_space(gl: &mut dyn Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, w as f64, 0.0, h as f64, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn texture_2d(gl: &mut dyn Gl, format: GLenum, w: i32, h: i32) -> u32 {
    let mut t = [0];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    let data_format = if format == GL_DEPTH_COMPONENT24 {
        GL_DEPTH_COMPONENT
    } else {
        GL_RGBA
    };
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        format as i32,
        w,
        h,
        0,
        data_format,
        GL_UNSIGNED_BYTE,
        None,
    );
    t[0]
}

/// Render to texture: an RGBA8 texture attached to GL_COLOR_ATTACHMENT0_EXT is cleared and
/// drawn into, read back while bound and through glGetTexImage, then drawn into the window.
fn fbo_render_to_texture(gl: &mut dyn Gl, out: &mut Answers) {
    let tex = texture_2d(gl, GL_RGBA8, 16, 8);
    let mut fb = [0];
    gl.gen_framebuffers_ext(1, &mut fb);
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, fb[0]);
    gl.framebuffer_texture_2dext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_TEXTURE_2D,
        tex,
        0,
    );
    err(gl, out, "attach");
    status(gl, out, "RGBA8 texture");
    pixel_space(gl, 16, 8);
    gl.clear_color(0.2, 0.4, 0.6, 0.8);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(1, 1, 3, 2);
    gl.clear_color(1.0, 1.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.disable(GL_SCISSOR_TEST);
    gl.color_4f(1.0, 0.0, 0.0, 1.0);
    quad(gl, 8.0, 0.0, 12.0, 4.0, 0.0);
    gl.color_4f(0.0, 0.0, 1.0, 0.5);
    quad(gl, 10.0, 2.0, 16.0, 8.0, 0.0);
    err(gl, out, "drawing into the texture");
    read_rgba(gl, out, "of the framebuffer object", 0, 0, 16, 8);
    int(gl, out, GL_FRAMEBUFFER_BINDING_EXT);
    int(gl, out, GL_DRAW_BUFFER);
    int(gl, out, GL_READ_BUFFER);
    // Back to the window: the texture holds the picture.
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, 0);
    int(gl, out, GL_DRAW_BUFFER);
    let mut texels = vec![0u8; 16 * 8 * 4];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut texels);
    exact(
        out,
        "glGetTexImage of the rendered texture".into(),
        texels.iter().map(|&v| v as f64).collect(),
    );
    pixel_space(gl, 64, 64);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    quad(gl, 0.0, 0.0, 32.0, 16.0, 0.0);
    gl.disable(GL_TEXTURE_2D);
    read_rgba(
        gl,
        out,
        "of the window after drawing the texture",
        0,
        0,
        32,
        16,
    );
    // Drawing into it again after rebinding keeps what is there.
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, fb[0]);
    pixel_space(gl, 16, 8);
    gl.color_4f(0.0, 1.0, 0.0, 1.0);
    quad(gl, 0.0, 4.0, 4.0, 8.0, 0.0);
    read_rgba(gl, out, "after drawing again", 0, 0, 16, 8);
    gl.delete_framebuffers_ext(1, &fb);
    int(gl, out, GL_FRAMEBUFFER_BINDING_EXT);
    let mut texels = vec![0u8; 16 * 8 * 4];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut texels);
    exact(
        out,
        "glGetTexImage after deleting the framebuffer".into(),
        texels.iter().map(|&v| v as f64).collect(),
    );
    err(gl, out, "the end");
}

/// Names, bindings, attachment queries, renderbuffer sizes, the statuses both specifications
/// agree on and the errors of the extension.
fn fbo_objects_and_errors(gl: &mut dyn Gl, out: &mut Answers) {
    let mut fbs = [0; 2];
    gl.gen_framebuffers_ext(2, &mut fbs);
    let mut rbs = [0; 3];
    gl.gen_renderbuffers_ext(3, &mut rbs);
    let is = |gl: &mut dyn Gl, out: &mut Answers, label: &str| {
        let v = vec![
            gl.is_framebuffer_ext(fbs[0]) as f64,
            gl.is_renderbuffer_ext(rbs[0]) as f64,
        ];
        exact(out, format!("glIs* {label}"), v);
    };
    is(gl, out, "after glGen*");
    // Without a bound object.
    status(gl, out, "of the window");
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_RENDERBUFFER_EXT,
        rbs[0],
    );
    err(gl, out, "glFramebufferRenderbufferEXT with framebuffer 0");
    gl.renderbuffer_storage_ext(GL_RENDERBUFFER_EXT, GL_RGBA8, 4, 4);
    err(gl, out, "glRenderbufferStorageEXT with renderbuffer 0");
    let mut v = [-1];
    gl.get_renderbuffer_parameteriv_ext(GL_RENDERBUFFER_EXT, GL_RENDERBUFFER_WIDTH_EXT, &mut v);
    err(gl, out, "renderbuffer query with renderbuffer 0");
    gl.bind_framebuffer_ext(GL_TEXTURE_2D, fbs[0]);
    err(gl, out, "glBindFramebufferEXT(GL_TEXTURE_2D)");
    gl.bind_renderbuffer_ext(GL_FRAMEBUFFER_EXT, rbs[0]);
    err(gl, out, "glBindRenderbufferEXT(GL_FRAMEBUFFER_EXT)");
    gl.draw_buffer(GL_COLOR_ATTACHMENT0_EXT);
    err(
        gl,
        out,
        "glDrawBuffer(GL_COLOR_ATTACHMENT0_EXT) on the window",
    );

    // Renderbuffers.
    gl.bind_renderbuffer_ext(GL_RENDERBUFFER_EXT, rbs[0]);
    int(gl, out, GL_RENDERBUFFER_BINDING_EXT);
    let rb_params = [
        GL_RENDERBUFFER_WIDTH_EXT,
        GL_RENDERBUFFER_HEIGHT_EXT,
        GL_RENDERBUFFER_INTERNAL_FORMAT_EXT,
        GL_RENDERBUFFER_RED_SIZE_EXT,
        GL_RENDERBUFFER_GREEN_SIZE_EXT,
        GL_RENDERBUFFER_BLUE_SIZE_EXT,
        GL_RENDERBUFFER_ALPHA_SIZE_EXT,
        GL_RENDERBUFFER_DEPTH_SIZE_EXT,
        GL_RENDERBUFFER_STENCIL_SIZE_EXT,
    ];
    let rb_query = |gl: &mut dyn Gl, out: &mut Answers, label: &str| {
        let values = rb_params
            .iter()
            .map(|&p| {
                let mut v = [-1];
                gl.get_renderbuffer_parameteriv_ext(GL_RENDERBUFFER_EXT, p, &mut v);
                v[0] as f64
            })
            .collect();
        exact(out, format!("renderbuffer parameters {label}"), values);
        err(gl, out, label);
    };
    rb_query(gl, out, "before storage");
    for (format, w, h) in [
        (GL_RGBA8, 8, 4),
        (GL_DEPTH_COMPONENT24, 8, 4),
        (GL_DEPTH_COMPONENT16, 3, 5),
        (GL_STENCIL_INDEX8_EXT, 2, 2),
        (GL_DEPTH24_STENCIL8_EXT, 8, 4),
    ] {
        gl.renderbuffer_storage_ext(GL_RENDERBUFFER_EXT, format, w, h);
        err(
            gl,
            out,
            &format!("glRenderbufferStorageEXT(0x{format:04x})"),
        );
        rb_query(gl, out, &format!("of 0x{format:04x}"));
    }
    gl.renderbuffer_storage_ext(GL_RENDERBUFFER_EXT, GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, 4, 4);
    err(gl, out, "glRenderbufferStorageEXT(DXT1)");
    gl.renderbuffer_storage_ext(GL_RENDERBUFFER_EXT, GL_RGBA8, -1, 4);
    err(gl, out, "glRenderbufferStorageEXT(width -1)");
    gl.renderbuffer_storage_ext(GL_RENDERBUFFER_EXT, GL_RGBA8, 4, 1 << 20);
    err(gl, out, "glRenderbufferStorageEXT(height 2^20)");
    gl.get_renderbuffer_parameteriv_ext(GL_RENDERBUFFER_EXT, GL_TEXTURE_WIDTH, &mut v);
    err(gl, out, "renderbuffer query of GL_TEXTURE_WIDTH");

    // A framebuffer object.
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, fbs[0]);
    is(gl, out, "after binding");
    int(gl, out, GL_FRAMEBUFFER_BINDING_EXT);
    status(gl, out, "with no attachment");
    attachment(
        gl,
        out,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT,
    );
    attachment(
        gl,
        out,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT,
    );
    gl.clear(GL_COLOR_BUFFER_BIT);
    err(gl, out, "glClear of an incomplete framebuffer");
    let mut px = [0u8; 4];
    gl.read_pixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
    err(gl, out, "glReadPixels of an incomplete framebuffer");
    gl.begin(GL_POINTS);
    gl.vertex_2f(0.0, 0.0);
    gl.end();
    err(gl, out, "glBegin on an incomplete framebuffer");
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_RENDERBUFFER_EXT,
        999,
    );
    err(
        gl,
        out,
        "glFramebufferRenderbufferEXT(unknown renderbuffer)",
    );
    // A colour renderbuffer without storage: an attachment without an image.
    gl.bind_renderbuffer_ext(GL_RENDERBUFFER_EXT, rbs[1]);
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_RENDERBUFFER_EXT,
        rbs[1],
    );
    err(gl, out, "attaching a renderbuffer");
    status(gl, out, "with an empty renderbuffer");
    attachment(
        gl,
        out,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT,
    );
    attachment(
        gl,
        out,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT,
    );
    gl.renderbuffer_storage_ext(GL_RENDERBUFFER_EXT, GL_RGBA8, 8, 4);
    status(gl, out, "with an RGBA8 renderbuffer");
    // Depth image at the colour point, colour image at the depth point.
    gl.bind_renderbuffer_ext(GL_RENDERBUFFER_EXT, rbs[2]);
    gl.renderbuffer_storage_ext(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, 8, 4);
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER_EXT,
        GL_DEPTH_ATTACHMENT_EXT,
        GL_RENDERBUFFER_EXT,
        rbs[1],
    );
    status(gl, out, "with a colour image at the depth point");
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER_EXT,
        GL_DEPTH_ATTACHMENT_EXT,
        GL_RENDERBUFFER_EXT,
        rbs[2],
    );
    status(gl, out, "with colour and depth renderbuffers");
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_RENDERBUFFER_EXT,
        rbs[2],
    );
    status(gl, out, "with a depth image at the colour point");
    gl.framebuffer_renderbuffer_ext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_RENDERBUFFER_EXT,
        0,
    );
    attachment(
        gl,
        out,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT,
    );
    attachment(
        gl,
        out,
        GL_DEPTH_ATTACHMENT_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT,
    );

    // Textures.
    let tex = texture_2d(gl, GL_RGBA8, 8, 4);
    let mut empty = [0];
    gl.gen_textures(1, &mut empty);
    gl.framebuffer_texture_2dext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_TEXTURE_2D,
        4321,
        0,
    );
    err(gl, out, "glFramebufferTexture2DEXT(unknown texture)");
    gl.framebuffer_texture_2dext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_TEXTURE_2D,
        tex,
        -1,
    );
    err(gl, out, "glFramebufferTexture2DEXT(level -1)");
    gl.framebuffer_texture_2dext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_TEXTURE_CUBE_MAP_POSITIVE_X,
        tex,
        0,
    );
    err(
        gl,
        out,
        "glFramebufferTexture2DEXT(a 2D texture as a cube face)",
    );
    gl.framebuffer_texture_2dext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_TEXTURE_2D,
        tex,
        2,
    );
    err(gl, out, "attaching level 2, which has no image");
    status(gl, out, "with a texture level without image");
    attachment(
        gl,
        out,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT,
    );
    gl.framebuffer_texture_2dext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_TEXTURE_2D,
        tex,
        0,
    );
    status(gl, out, "with texture and depth renderbuffer");
    for p in [
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE_EXT,
    ] {
        attachment(gl, out, GL_COLOR_ATTACHMENT0_EXT, p);
    }
    int(gl, out, GL_DRAW_BUFFER);
    gl.draw_buffer(GL_BACK);
    err(gl, out, "glDrawBuffer(GL_BACK) on a framebuffer object");
    gl.read_buffer(GL_FRONT);
    err(gl, out, "glReadBuffer(GL_FRONT) on a framebuffer object");
    gl.draw_buffer(GL_COLOR_ATTACHMENT0_EXT);
    err(gl, out, "glDrawBuffer(GL_COLOR_ATTACHMENT0_EXT)");
    // Deleting the attached texture detaches it from the bound framebuffer.
    gl.delete_textures(1, &[tex]);
    attachment(
        gl,
        out,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT,
    );
    // Deleting the bound renderbuffer unbinds it and detaches it.
    gl.delete_renderbuffers_ext(1, &[rbs[2]]);
    int(gl, out, GL_RENDERBUFFER_BINDING_EXT);
    attachment(
        gl,
        out,
        GL_DEPTH_ATTACHMENT_EXT,
        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT,
    );
    status(gl, out, "after deleting both attachments");
    gl.check_framebuffer_status_ext(GL_TEXTURE_2D);
    err(gl, out, "glCheckFramebufferStatusEXT(GL_TEXTURE_2D)");
    gl.generate_mipmap_ext(GL_TEXTURE_RECTANGLE_ARB);
    err(gl, out, "glGenerateMipmapEXT(GL_TEXTURE_RECTANGLE)");
    gl.delete_framebuffers_ext(2, &fbs);
    int(gl, out, GL_FRAMEBUFFER_BINDING_EXT);
    is(gl, out, "after deleting");
    err(gl, out, "the end");
}

/// Colour and packed depth-stencil renderbuffers: depth-tested and stencilled quads.
fn fbo_depth_stencil(gl: &mut dyn Gl, out: &mut Answers) {
    let mut rbs = [0; 2];
    gl.gen_renderbuffers_ext(2, &mut rbs);
    gl.bind_renderbuffer_ext(GL_RENDERBUFFER_EXT, rbs[0]);
    gl.renderbuffer_storage_ext(GL_RENDERBUFFER_EXT, GL_RGBA8, 12, 10);
    gl.bind_renderbuffer_ext(GL_RENDERBUFFER_EXT, rbs[1]);
    gl.renderbuffer_storage_ext(GL_RENDERBUFFER_EXT, GL_DEPTH24_STENCIL8_EXT, 12, 10);
    let mut fb = [0];
    gl.gen_framebuffers_ext(1, &mut fb);
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, fb[0]);
    for (point, rb) in [
        (GL_COLOR_ATTACHMENT0_EXT, rbs[0]),
        (GL_DEPTH_ATTACHMENT_EXT, rbs[1]),
        (GL_STENCIL_ATTACHMENT_EXT, rbs[1]),
    ] {
        gl.framebuffer_renderbuffer_ext(GL_FRAMEBUFFER_EXT, point, GL_RENDERBUFFER_EXT, rb);
    }
    status(gl, out, "colour + depth-stencil");
    int(gl, out, GL_DEPTH_BITS);
    int(gl, out, GL_STENCIL_BITS);
    pixel_space(gl, 12, 10);
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear_depth(0.5);
    gl.clear_stencil(3);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_LESS);
    // z = -0.5 is depth 0.75 (behind), z = 0.5 is depth 0.25 (in front).
    gl.color_3f(1.0, 0.0, 0.0);
    quad(gl, 0.0, 0.0, 6.0, 10.0, -0.5);
    gl.color_3f(0.0, 1.0, 0.0);
    quad(gl, 6.0, 0.0, 12.0, 10.0, 0.5);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_ALWAYS, 7, 0xff);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
    gl.color_3f(0.0, 0.0, 1.0);
    quad(gl, 3.0, 3.0, 9.0, 7.0, 0.0);
    gl.stencil_func(GL_EQUAL, 3, 0xff);
    gl.disable(GL_DEPTH_TEST);
    gl.color_3f(1.0, 1.0, 1.0);
    quad(gl, 0.0, 0.0, 12.0, 2.0, 0.0);
    gl.disable(GL_STENCIL_TEST);
    err(gl, out, "drawing");
    read_rgba(gl, out, "colour", 0, 0, 12, 10);
    let mut bytes = vec![0u8; 12 * 10 * 4];
    gl.read_pixels(0, 0, 12, 10, GL_DEPTH_COMPONENT, GL_FLOAT, &mut bytes);
    let depth = floats(&bytes);
    out.push(Answer {
        label: "depth".into(),
        values: depth.iter().map(|&d| d as f64).collect(),
        tolerance: 2.0 / 16777215.0,
    });
    let mut stencil = vec![0u8; 12 * 10];
    gl.read_pixels(
        0,
        0,
        12,
        10,
        GL_STENCIL_INDEX,
        GL_UNSIGNED_BYTE,
        &mut stencil,
    );
    exact(
        out,
        "stencil".into(),
        stencil.iter().map(|&s| s as f64).collect(),
    );
    err(gl, out, "reading");
    // Through the window and back: the renderbuffers keep their content.
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, 0);
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, fb[0]);
    read_rgba(gl, out, "colour after rebinding", 0, 0, 12, 10);
    gl.read_pixels(
        0,
        0,
        12,
        10,
        GL_STENCIL_INDEX,
        GL_UNSIGNED_BYTE,
        &mut stencil,
    );
    exact(
        out,
        "stencil after rebinding".into(),
        stencil.iter().map(|&s| s as f64).collect(),
    );
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, 0);
    gl.delete_framebuffers_ext(1, &fb);
    gl.delete_renderbuffers_ext(2, &rbs);
    err(gl, out, "the end");
}

/// Pixel commands on a framebuffer object, a depth texture attachment and
/// glGenerateMipmapEXT.
fn fbo_pixels_and_mipmaps(gl: &mut dyn Gl, out: &mut Answers) {
    let color = texture_2d(gl, GL_RGBA8, 8, 8);
    let depth = texture_2d(gl, GL_DEPTH_COMPONENT24, 8, 8);
    let mut fb = [0];
    gl.gen_framebuffers_ext(1, &mut fb);
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, fb[0]);
    gl.framebuffer_texture_2dext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_TEXTURE_2D,
        color,
        0,
    );
    gl.framebuffer_texture_2dext(
        GL_FRAMEBUFFER_EXT,
        GL_DEPTH_ATTACHMENT_EXT,
        GL_TEXTURE_2D,
        depth,
        0,
    );
    status(gl, out, "colour and depth textures");
    pixel_space(gl, 8, 8);
    gl.clear_color(0.0, 0.0, 1.0, 1.0);
    gl.clear_depth(1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // 2x2 blocks of one colour, so that the box filter of level 1 is exact.
    let mut block = vec![0u8; 4 * 4 * 4];
    for (i, p) in block.chunks_mut(4).enumerate() {
        let (x, y) = (i % 4, i / 4);
        p.copy_from_slice(&[(x / 2 * 200) as u8, (y / 2 * 100) as u8, 40, 255]);
    }
    gl.window_pos_2i(0, 0);
    gl.draw_pixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, Some(&block));
    gl.copy_pixels(0, 0, 4, 4, GL_COLOR);
    gl.window_pos_2i(4, 4);
    gl.copy_pixels(0, 0, 4, 4, GL_COLOR);
    gl.enable(GL_DEPTH_TEST);
    gl.color_3f(1.0, 1.0, 0.0);
    quad(gl, 4.0, 0.0, 8.0, 4.0, 0.5);
    gl.disable(GL_DEPTH_TEST);
    err(gl, out, "pixel commands");
    read_rgba(gl, out, "after the pixel commands", 0, 0, 8, 8);
    let mut bytes = vec![0u8; 8 * 4];
    gl.read_pixels(0, 1, 8, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &mut bytes);
    let d = floats(&bytes);
    out.push(Answer {
        label: "a row of depth".into(),
        values: d.iter().map(|&v| v as f64).collect(),
        tolerance: 2.0 / 16777215.0,
    });
    // Copied into another texture from the framebuffer object.
    let copy = texture_2d(gl, GL_RGBA8, 4, 4);
    gl.copy_tex_sub_image_2d(GL_TEXTURE_2D, 0, 0, 0, 2, 2, 4, 4);
    err(gl, out, "glCopyTexSubImage2D");
    let mut texels = vec![0u8; 4 * 4 * 4];
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut texels);
    exact(
        out,
        "the copied texture".into(),
        texels.iter().map(|&v| v as f64).collect(),
    );
    gl.delete_textures(1, &[copy]);
    gl.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, 0);
    gl.bind_texture(GL_TEXTURE_2D, color);
    gl.generate_mipmap_ext(GL_TEXTURE_2D);
    err(gl, out, "glGenerateMipmapEXT");
    let mut level1 = vec![0u8; 4 * 4 * 4];
    gl.get_tex_image(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut level1);
    exact(
        out,
        "level 1 of the rendered texture".into(),
        level1.iter().map(|&v| v as f64).collect(),
    );
    let mut w = [-1];
    gl.get_tex_level_parameteriv(GL_TEXTURE_2D, 3, GL_TEXTURE_WIDTH, &mut w);
    exact(out, "width of level 3".into(), vec![w[0] as f64]);
    let mut bytes = vec![0u8; 64 * 4];
    gl.bind_texture(GL_TEXTURE_2D, depth);
    gl.get_tex_image(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &mut bytes);
    let dt = floats(&bytes);
    out.push(Answer {
        label: "the depth texture".into(),
        values: dt.iter().map(|&v| v as f64).collect(),
        tolerance: 2.0 / 16777215.0,
    });
    gl.delete_framebuffers_ext(1, &fb);
    err(gl, out, "the end");
}

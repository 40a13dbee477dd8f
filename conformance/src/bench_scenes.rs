//! The benchmark workloads added for issue 23's classes beyond the first eleven (see
//! [`crate::bench`]): 200k small lit triangles through immediate-mode calls, a `GL_COMBINE`
//! cascade over four units, cube-map reflection, wide and smooth lines, stencil shadow volumes,
//! `glBitmap`/`glDrawPixels` text, texture uploads every frame and accumulation-buffer motion
//! blur. Each has its state (`setup`, once per context) and its frame (`frame`, ending before
//! `glFinish`), drawn through `&mut dyn Gl`, so the same calls reach tilegl's C exports and Mesa.

use tilegl::enums::*;
use tilegl::Gl;

use crate::prng::XorShift;

/// Triangles per frame of the `lit-triangles` workload.
pub const LIT_TRIANGLES: usize = 200_000;
/// Segments per frame of the `lines` workload (half smooth and blended, half wide and aliased).
pub const LINES: usize = 20_000;
/// Glyph rows and glyphs per row of the `text` workload.
pub const TEXT: (usize, usize) = (56, 126);
/// Floating plates (columns, rows) casting stencil shadows in the `shadow` workload.
pub const PLATES: (usize, usize) = (4, 4);
/// Jittered passes summed in the accumulation buffer per `accum` frame.
pub const ACCUM_PASSES: usize = 4;

/// One lit vertex: window position (pixels, z in [-1, 1]) and normal.
#[derive(Clone, Copy, Debug)]
pub struct LitVertex {
    pub pos: [f32; 3],
    pub normal: [f32; 3],
}

/// One line segment: ends (pixels) and colour with alpha.
#[derive(Clone, Copy, Debug)]
pub struct Segment {
    pub a: [f32; 2],
    pub b: [f32; 2],
    pub color: [f32; 4],
}

/// Pixel data the `text` and `uploads` workloads hand to GL every frame.
#[derive(Clone, Debug)]
pub struct Pixels {
    /// 96 glyphs of 8x13 bits, one byte a row (`text`).
    pub glyphs: Vec<[u8; 13]>,
    /// A 256x192 RGBA picture drawn with `glDrawPixels` (`text`).
    pub picture: Vec<u8>,
    /// Four 256x256 RGBA frames for `glTexSubImage2D` and one 512x512 RGB picture for
    /// `glTexImage2D` (`uploads`).
    pub frames: Vec<Vec<u8>>,
    pub big: Vec<u8>,
}

/// 200k random small triangles (each in a ~12-pixel box) with random normals facing the viewer.
pub fn lit_triangles(width: i32, height: i32, seed: u64) -> Vec<LitVertex> {
    let mut rng = XorShift::new(seed ^ 0x1175);
    let mut out = Vec::with_capacity(LIT_TRIANGLES * 3);
    for _ in 0..LIT_TRIANGLES {
        let cx = rng.range(-6.0, width as f32 + 6.0);
        let cy = rng.range(-6.0, height as f32 + 6.0);
        let cz = rng.range(-0.95, 0.95);
        for _ in 0..3 {
            let (nx, ny) = (rng.range(-0.7, 0.7), rng.range(-0.7, 0.7));
            let nz = (1.0 - nx * nx - ny * ny).max(0.0).sqrt();
            out.push(LitVertex {
                pos: [
                    cx + rng.range(-6.0, 6.0),
                    cy + rng.range(-6.0, 6.0),
                    (cz + rng.range(-0.03, 0.03)).clamp(-1.0, 1.0),
                ],
                normal: [nx, ny, nz],
            });
        }
    }
    out
}

/// Random segments 8-60 pixels long anywhere on the screen.
pub fn segments(width: i32, height: i32, seed: u64) -> Vec<Segment> {
    let mut rng = XorShift::new(seed ^ 0x11E5);
    (0..LINES)
        .map(|_| {
            let a = [rng.range(0.0, width as f32), rng.range(0.0, height as f32)];
            let len = rng.range(8.0, 60.0);
            let ang = rng.range(0.0, std::f32::consts::TAU);
            Segment {
                a,
                b: [a[0] + len * ang.cos(), a[1] + len * ang.sin()],
                color: [
                    rng.range(0.3, 1.0),
                    rng.range(0.3, 1.0),
                    rng.range(0.3, 1.0),
                    rng.range(0.5, 1.0),
                ],
            }
        })
        .collect()
}

/// The glyphs, the picture and the upload frames.
pub fn pixels(seed: u64) -> Pixels {
    let mut rng = XorShift::new(seed ^ 0x7E47);
    let glyphs = (0..96)
        .map(|_| {
            let mut g = [0u8; 13];
            // Rows 2..11 carry ink, the rest are the line spacing.
            for row in g.iter_mut().take(11).skip(2) {
                *row = (rng.next_u64() as u8) & 0x7E;
            }
            g
        })
        .collect();
    let picture = (0..192)
        .flat_map(|y: u32| {
            (0..256u32).flat_map(move |x| {
                [
                    (x ^ y) as u8,
                    (x * 2 / 3) as u8,
                    (y * 4 / 3) as u8,
                    if (x / 16 + y / 16).is_multiple_of(3) {
                        128
                    } else {
                        255
                    },
                ]
            })
        })
        .collect();
    let frames = (0..4u32)
        .map(|k| {
            (0..256u32)
                .flat_map(|y| {
                    (0..256u32).flat_map(move |x| {
                        let v = ((x + 40 * k) / 8 + y / 8) % 2;
                        [
                            (x + 60 * k) as u8,
                            if v == 0 { 200 } else { 40 },
                            (y ^ (k * 50)) as u8,
                            255,
                        ]
                    })
                })
                .collect()
        })
        .collect();
    let big = (0..512u32)
        .flat_map(|y| {
            (0..512u32).flat_map(move |x| [(x / 2) as u8, (y / 2) as u8, ((x + y) / 4) as u8])
        })
        .collect();
    Pixels {
        glyphs,
        picture,
        frames,
        big,
    }
}

/// Window-space ortho projection (`0..width`, `0..height`) on an identity modelview.
fn window_ortho(gl: &mut dyn Gl, width: i32, height: i32) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, width as f64, 0.0, height as f64, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

/// `lit-triangles`: one directional light, a specular material, window-space ortho projection.
pub fn setup_lit_triangles(gl: &mut dyn Gl, width: i32, height: i32) {
    window_ortho(gl, width, height);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 0.5, 1.0, 0.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.8, 0.6, 0.4, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.4, 0.4, 0.4, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 16.0);
    gl.clear_color(0.1, 0.1, 0.12, 1.0);
}

/// `lit-triangles`: every vertex through `glNormal3f` and `glVertex3f`, one `glBegin`.
pub fn frame_lit_triangles(gl: &mut dyn Gl, verts: &[LitVertex]) {
    gl.begin(GL_TRIANGLES);
    for v in verts {
        let [nx, ny, nz] = v.normal;
        gl.normal_3f(nx, ny, nz);
        let [x, y, z] = v.pos;
        gl.vertex_3f(x, y, z);
    }
    gl.end();
}

/// A 64x64 luminance noise texture for the detail unit of `combine4`.
fn detail_texture() -> Vec<u8> {
    let mut rng = XorShift::new(0xDE7A);
    (0..64 * 64)
        .map(|_| 96 + (rng.next_u64() % 64) as u8)
        .collect()
}

/// Binds `name` on `unit` as a 2D texture with the given pixels and filtering, enabled.
#[allow(clippy::too_many_arguments)]
fn unit_texture(
    gl: &mut dyn Gl,
    unit: GLenum,
    name: GLuint,
    size: i32,
    format: GLenum,
    pixels: &[u8],
    min: GLenum,
    wrap: GLenum,
) {
    gl.active_texture(unit);
    gl.bind_texture(GL_TEXTURE_2D, name);
    if min != GL_LINEAR && min != GL_NEAREST {
        gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
    }
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        format as i32,
        size,
        size,
        0,
        format,
        GL_UNSIGNED_BYTE,
        Some(pixels),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap as i32);
    gl.enable(GL_TEXTURE_2D);
}

/// `combine4`: four units, each through `GL_COMBINE`: the base texture (trilinear) times the
/// vertex colour; times a light map, doubled; plus a signed detail texture (trilinear);
/// interpolated with an environment texture by the constant colour's alpha.
pub fn setup_combine4(gl: &mut dyn Gl, base: &[u8], light_map: &[u8], environment: &[u8]) {
    let combine = |gl: &mut dyn Gl, func: GLenum, sources: &[GLenum]| {
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, func as i32);
        for (k, &s) in sources.iter().enumerate() {
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + k as GLenum, s as i32);
        }
    };
    unit_texture(
        gl,
        GL_TEXTURE0,
        201,
        256,
        GL_RGBA,
        base,
        GL_LINEAR_MIPMAP_LINEAR,
        GL_REPEAT,
    );
    combine(gl, GL_MODULATE, &[GL_TEXTURE, GL_PRIMARY_COLOR]);
    unit_texture(
        gl,
        GL_TEXTURE1,
        202,
        64,
        GL_LUMINANCE,
        light_map,
        GL_LINEAR,
        GL_CLAMP_TO_EDGE,
    );
    combine(gl, GL_MODULATE, &[GL_PREVIOUS, GL_TEXTURE]);
    gl.tex_envf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0);
    unit_texture(
        gl,
        GL_TEXTURE2,
        203,
        64,
        GL_LUMINANCE,
        &detail_texture(),
        GL_LINEAR_MIPMAP_LINEAR,
        GL_REPEAT,
    );
    combine(gl, GL_ADD_SIGNED, &[GL_PREVIOUS, GL_TEXTURE]);
    unit_texture(
        gl,
        GL_TEXTURE3,
        204,
        128,
        GL_RGB,
        environment,
        GL_LINEAR,
        GL_REPEAT,
    );
    combine(gl, GL_INTERPOLATE, &[GL_PREVIOUS, GL_TEXTURE, GL_CONSTANT]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_ALPHA as i32);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.0, 0.0, 0.0, 0.8]);
    gl.active_texture(GL_TEXTURE0);
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
}

/// `combine4`: the `lightmap` corridor with coordinates for the four units.
pub fn frame_combine4(gl: &mut dyn Gl, segments: usize) {
    gl.load_identity();
    gl.translatef(0.0, 0.0, -0.5);
    gl.begin(GL_QUADS);
    for k in 0..segments {
        for (w, wall) in crate::bench::corridor_walls(k).iter().enumerate() {
            gl.color_3f(1.0, 0.95 - 0.05 * w as f32, 0.9);
            for (c, v) in wall.iter().enumerate() {
                let (u, t) = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)][c];
                gl.multi_tex_coord_2f(GL_TEXTURE0, u * 2.0, t * 1.5);
                gl.multi_tex_coord_2f(GL_TEXTURE1, u, t);
                gl.multi_tex_coord_2f(GL_TEXTURE2, u * 8.0, t * 6.0);
                gl.multi_tex_coord_2f(GL_TEXTURE3, 0.5 * u + 0.13 * k as f32, 0.5 * t);
                gl.vertex_3fv(v);
            }
        }
    }
    gl.end();
}

/// A 128x128 RGB face of the `cubemap` environment seen in direction `dir`: sky, ground, a sun.
fn environment_face(dir: impl Fn(f32, f32) -> [f32; 3]) -> Vec<u8> {
    let mut p = Vec::with_capacity(128 * 128 * 3);
    for y in 0..128 {
        for x in 0..128 {
            let d = dir((x as f32 + 0.5) / 64.0 - 1.0, (y as f32 + 0.5) / 64.0 - 1.0);
            let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            let [u, v, w] = d.map(|c| c / l);
            let sun = ((u * 0.48 + v * 0.64 + w * 0.6).max(0.0)).powi(40);
            let c = if v > 0.0 {
                [0.3 + 0.5 * v, 0.45 + 0.4 * v, 0.95]
            } else {
                let check = ((u / v.min(-0.05) * 4.0).floor() + (w / v.min(-0.05) * 4.0).floor())
                    .rem_euclid(2.0);
                [0.35 + 0.2 * check, 0.3, 0.2]
            };
            p.extend(c.map(|c| ((c + sun).min(1.0) * 255.0) as u8));
        }
    }
    p
}

/// `cubemap`: a cube-map environment reflected by `GL_REFLECTION_MAP` texgen on s, t and r,
/// modulating a lit material.
pub fn setup_cubemap(gl: &mut dyn Gl) {
    gl.bind_texture(GL_TEXTURE_CUBE_MAP, 301);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    // Direction of texel (s, t) in [-1, 1] of each face (GL 1.5 table 3.19, inverted).
    let faces: [fn(f32, f32) -> [f32; 3]; 6] = [
        |s, t| [1.0, -t, -s],
        |s, t| [-1.0, -t, s],
        |s, t| [s, 1.0, t],
        |s, t| [s, -1.0, -t],
        |s, t| [s, -t, 1.0],
        |s, t| [-s, -t, -1.0],
    ];
    for (i, dir) in faces.iter().enumerate() {
        gl.tex_image_2d(
            GL_TEXTURE_CUBE_MAP_POSITIVE_X + i as GLenum,
            0,
            GL_RGB as i32,
            128,
            128,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            Some(&environment_face(dir)),
        );
    }
    for (p, v) in [
        (GL_TEXTURE_MIN_FILTER, GL_LINEAR),
        (GL_TEXTURE_MAG_FILTER, GL_LINEAR),
        (GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE),
        (GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE),
        (GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE),
    ] {
        gl.tex_parameteri(GL_TEXTURE_CUBE_MAP, p, v as i32);
    }
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_CUBE_MAP);
    for c in [GL_S, GL_T, GL_R] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP as i32);
    }
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    gl.enable(GL_TEXTURE_GEN_R);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.4, 1.0, 0.8, 0.0]);
    gl.materialfv(GL_FRONT, GL_AMBIENT, &[0.4, 0.4, 0.4, 1.0]);
    gl.materialfv(GL_FRONT, GL_DIFFUSE, &[0.9, 0.9, 0.9, 1.0]);
    gl.clear_color(0.1, 0.1, 0.12, 1.0);
}

/// `cubemap`: the `spheremap` torus, once, reflecting the environment.
pub fn frame_cubemap(gl: &mut dyn Gl, rings: usize, sides: usize) {
    gl.load_identity();
    gl.translatef(0.0, 0.0, -3.6);
    gl.rotatef(35.0, 1.0, 0.0, 0.0);
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
    crate::bench::torus(gl, rings, sides, 1.2, 0.5);
}

/// `lines`: window-space ortho, no depth test, "over" blending for the smooth half.
pub fn setup_lines(gl: &mut dyn Gl, width: i32, height: i32) {
    window_ortho(gl, width, height);
    gl.disable(GL_DEPTH_TEST);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.clear_color(0.05, 0.05, 0.1, 1.0);
}

/// `lines`: the first half smooth (`GL_LINE_SMOOTH`, width 2.5, blended), the second wide
/// and aliased (width 3).
pub fn frame_lines(gl: &mut dyn Gl, segs: &[Segment]) {
    let (smooth, wide) = segs.split_at(segs.len() / 2);
    gl.enable(GL_LINE_SMOOTH);
    gl.enable(GL_BLEND);
    gl.line_width(2.5);
    gl.begin(GL_LINES);
    for s in smooth {
        gl.color_4fv(&s.color);
        gl.vertex_2fv(&s.a);
        gl.vertex_2fv(&s.b);
    }
    gl.end();
    gl.disable(GL_LINE_SMOOTH);
    gl.disable(GL_BLEND);
    gl.line_width(3.0);
    gl.begin(GL_LINES);
    for s in wide {
        gl.color_4fv(&s.color);
        gl.vertex_2fv(&s.a);
        gl.vertex_2fv(&s.b);
    }
    gl.end();
}

/// Direction towards the `shadow` workload's light (not normalised; y > 0).
const SHADOW_LIGHT: [f32; 3] = [0.55, 0.6, 0.25];
/// The floor's height and the height the shadow volumes reach below it.
const FLOOR_Y: f32 = 0.0;
const VOLUME_BOTTOM: f32 = -2.0;

/// The corners of plate (`i`, `j`): a unit square at a height of 0.8-1.6, counter-clockwise seen
/// from above.
fn plate(i: usize, j: usize) -> [[f32; 3]; 4] {
    let x = -5.0 + 3.0 * i as f32;
    let z = -5.0 - 3.5 * j as f32;
    let y = 0.8 + 0.25 * ((i + 2 * j) % 4) as f32;
    [
        [x, y, z],
        [x + 1.2, y, z],
        [x + 1.2, y, z - 1.2],
        [x, y, z - 1.2],
    ]
}

/// `shadow`: a lit floor and plates, one directional light, perspective.
pub fn setup_shadow(gl: &mut dyn Gl) {
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    let [x, y, z] = SHADOW_LIGHT;
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[x, y, z, 0.0]);
    gl.enable(GL_COLOR_MATERIAL);
    gl.color_material(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    gl.clear_color(0.3, 0.35, 0.45, 1.0);
    gl.clear_stencil(0);
}

/// `shadow`: the scene; the shadow volumes of the plates counted into the stencil buffer
/// (front faces increment, back faces decrement: z-pass); the stencilled pixels darkened by a
/// blended full-screen quad.
pub fn frame_shadow(gl: &mut dyn Gl) {
    gl.clear(GL_STENCIL_BUFFER_BIT);
    gl.load_identity();
    gl.rotatef(24.0, 1.0, 0.0, 0.0);
    gl.translatef(0.5, -3.4, 0.0);
    gl.lightfv(
        GL_LIGHT0,
        GL_POSITION,
        &[SHADOW_LIGHT[0], SHADOW_LIGHT[1], SHADOW_LIGHT[2], 0.0],
    );
    // The scene.
    gl.begin(GL_QUADS);
    gl.normal_3f(0.0, 1.0, 0.0);
    gl.color_3f(0.75, 0.7, 0.6);
    for (x, z) in [(-12.0, 2.0), (12.0, 2.0), (12.0, -26.0), (-12.0, -26.0)] {
        gl.vertex_3f(x, FLOOR_Y, z);
    }
    for j in 0..PLATES.1 {
        for i in 0..PLATES.0 {
            gl.color_3f(0.3 + 0.15 * i as f32, 0.4, 0.7 - 0.1 * j as f32);
            for v in plate(i, j) {
                gl.vertex_3fv(&v);
            }
        }
    }
    gl.end();
    // The shadow volumes into the stencil buffer.
    gl.disable(GL_LIGHTING);
    gl.color_mask(0, 0, 0, 0);
    gl.depth_mask(0);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_ALWAYS, 0, !0);
    gl.enable(GL_CULL_FACE);
    for (face, op) in [(GL_BACK, GL_INCR), (GL_FRONT, GL_DECR)] {
        gl.cull_face(face);
        gl.stencil_op(GL_KEEP, GL_KEEP, op);
        shadow_volumes(gl);
    }
    gl.disable(GL_CULL_FACE);
    // Darken where the count is not zero.
    gl.color_mask(1, 1, 1, 1);
    gl.stencil_func(GL_NOTEQUAL, 0, !0);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
    gl.disable(GL_DEPTH_TEST);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.matrix_mode(GL_PROJECTION);
    gl.push_matrix();
    gl.load_identity();
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.color_4f(0.0, 0.0, 0.05, 0.55);
    gl.rectf(-1.0, -1.0, 1.0, 1.0);
    gl.matrix_mode(GL_PROJECTION);
    gl.pop_matrix();
    gl.matrix_mode(GL_MODELVIEW);
    gl.disable(GL_BLEND);
    gl.disable(GL_STENCIL_TEST);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_mask(1);
    gl.enable(GL_LIGHTING);
}

/// Each plate's volume: the plate (top cap), its projection along the light below the floor
/// (bottom cap) and the four sides, all faces counter-clockwise seen from outside.
fn shadow_volumes(gl: &mut dyn Gl) {
    let [lx, ly, lz] = SHADOW_LIGHT;
    gl.begin(GL_QUADS);
    for j in 0..PLATES.1 {
        for i in 0..PLATES.0 {
            let top = plate(i, j);
            let bottom = top.map(|[x, y, z]| {
                let k = (y - VOLUME_BOTTOM) / ly;
                [x - lx * k, VOLUME_BOTTOM, z - lz * k]
            });
            for v in top {
                gl.vertex_3fv(&v);
            }
            for v in bottom.iter().rev() {
                gl.vertex_3fv(v);
            }
            for e in 0..4 {
                let f = (e + 1) % 4;
                for v in [top[e], bottom[e], bottom[f], top[f]] {
                    gl.vertex_3fv(&v);
                }
            }
        }
    }
    gl.end();
}

/// `text`: window-space ortho, no depth test, byte-aligned bitmaps.
pub fn setup_text(gl: &mut dyn Gl, width: i32, height: i32) {
    window_ortho(gl, width, height);
    gl.disable(GL_DEPTH_TEST);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.clear_color(0.95, 0.95, 0.9, 1.0);
}

/// `text`: a picture drawn four times with `glDrawPixels`, then rows of 8x13 glyphs with
/// `glBitmap`, each row in its own colour.
pub fn frame_text(gl: &mut dyn Gl, px: &Pixels, height: i32) {
    for k in 0..4 {
        gl.raster_pos_2i(40 + 250 * k, 60 + 120 * (k % 2));
        gl.draw_pixels(256, 192, GL_RGBA, GL_UNSIGNED_BYTE, Some(&px.picture));
    }
    let (rows, cols) = TEXT;
    for row in 0..rows {
        gl.color_3f(0.1 + 0.01 * row as f32, 0.1, 0.4 - 0.005 * row as f32);
        gl.raster_pos_2i(4, height - 14 * (row as i32 + 1));
        for col in 0..cols {
            let g = &px.glyphs[(row * 7 + col * 13) % px.glyphs.len()];
            gl.bitmap(8, 13, 0.0, 0.0, 8.0, 0.0, g);
        }
    }
}

/// `uploads`: window-space ortho, no depth test, four 256x256 RGBA textures and one 512x512
/// RGB, bilinear without mipmaps, `REPLACE`.
pub fn setup_uploads(gl: &mut dyn Gl, width: i32, height: i32, px: &Pixels) {
    window_ortho(gl, width, height);
    gl.disable(GL_DEPTH_TEST);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    for k in 0..5u32 {
        gl.bind_texture(GL_TEXTURE_2D, 101 + k);
        let (size, format, data) = if k < 4 {
            (256, GL_RGBA, &px.frames[k as usize])
        } else {
            (512, GL_RGB, &px.big)
        };
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            format as i32,
            size,
            size,
            0,
            format,
            GL_UNSIGNED_BYTE,
            Some(data),
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE as i32);
    }
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
}

/// Draws `[x0, x1] x [y0, y1]` with the whole texture.
fn textured_rect(gl: &mut dyn Gl, x0: f32, y0: f32, x1: f32, y1: f32) {
    gl.begin(GL_QUADS);
    for (x, y, s, t) in [
        (x0, y0, 0.0, 0.0),
        (x1, y0, 1.0, 0.0),
        (x1, y1, 1.0, 1.0),
        (x0, y1, 0.0, 1.0),
    ] {
        gl.tex_coord_2f(s, t);
        gl.vertex_2f(x, y);
    }
    gl.end();
}

/// `uploads`: each 256x256 texture replaced with `glTexSubImage2D` and drawn over a quarter of
/// the window; the 512x512 one re-specified with `glTexImage2D` and drawn in the middle.
pub fn frame_uploads(gl: &mut dyn Gl, px: &Pixels, width: i32, height: i32) {
    let (w, h) = (width as f32 / 2.0, height as f32 / 2.0);
    for k in 0..4u32 {
        gl.bind_texture(GL_TEXTURE_2D, 101 + k);
        // Each quarter shows the next frame, so every upload changes the texture.
        let data = &px.frames[(k as usize + 1) % 4];
        gl.tex_sub_image_2d(
            GL_TEXTURE_2D,
            0,
            0,
            0,
            256,
            256,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(data),
        );
        let (x, y) = ((k % 2) as f32 * w, (k / 2) as f32 * h);
        textured_rect(gl, x, y, x + w, y + h);
    }
    gl.bind_texture(GL_TEXTURE_2D, 105);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGB as i32,
        512,
        512,
        0,
        GL_RGB,
        GL_UNSIGNED_BYTE,
        Some(&px.big),
    );
    textured_rect(gl, w - 256.0, h - 192.0, w + 256.0, h + 192.0);
}

//! The texturing issue's verification matrix as differential scenes:
//!
//! 1. every minification filter x wrap mode x base format on a perspective plane receding to
//!    the horizon (`texmat_<filter>_<wrap>`: one scene per filter and wrap mode, the six base
//!    formats side by side as six 64x64 viewports, ALPHA LUMINANCE LUMINANCE_ALPHA on the bottom
//!    row, INTENSITY RGB RGBA on the top row). Filters: `nearest`, `linear`, `nmn`
//!    (NEAREST_MIPMAP_NEAREST), `lmn` (LINEAR_MIPMAP_NEAREST), `nml` (NEAREST_MIPMAP_LINEAR),
//!    `lml` (LINEAR_MIPMAP_LINEAR); the magnification filter is the filter within a level
//!    (NEAREST for `nearest`, `nmn`, `nml`). Wrap modes: `repeat`, `clamp` (GL_CLAMP), `edge`
//!    (CLAMP_TO_EDGE), `border` (CLAMP_TO_BORDER), `mirror` (MIRRORED_REPEAT); every texture
//!    has a border colour, which CLAMP and CLAMP_TO_BORDER show.
//! 2. cube maps (`cube_*`), 3D textures (`tex3d_*`), depth textures with
//!    `GL_TEXTURE_COMPARE_MODE` (`depth_cmp_*`) and S3TC (`dxt_*`).
//!
//! Tolerances: the normal rule, except `cube_reflection_mipmap`, held to the
//! llvmpipe-versus-softpipe spread measured with `--bin calibrate --filter` (see the
//! texture-matrix section of `conformance/TOLERANCE.md`).

use crate::compare::Scene;
use crate::scenes::{clear, scene_with, sphere, spread};
use crate::tolerance::{Tolerance, DIFFERENTIAL};
use tilegl::enums::*;
use tilegl::Gl;

/// The normal rule, or the measured llvmpipe-vs-softpipe bad share when that is larger.
const fn tol(measured: f64) -> Tolerance {
    if measured <= DIFFERENTIAL.max_bad_share {
        DIFFERENTIAL
    } else {
        spread(measured)
    }
}

/// A scene of `w` x `h` pixels.
const fn sized(name: &'static str, w: i32, h: i32, draw: fn(&mut dyn Gl), measured: f64) -> Scene {
    Scene {
        width: w,
        height: h,
        ..scene_with(name, draw, tol(measured))
    }
}

/// The six base formats of part 1, in viewport order.
const FORMATS: [GLenum; 6] = [
    GL_ALPHA,
    GL_LUMINANCE,
    GL_LUMINANCE_ALPHA,
    GL_INTENSITY,
    GL_RGB,
    GL_RGBA,
];

const BORDER: [f32; 4] = [0.9, 0.25, 0.6, 0.35];

/// Level 0 of the matrix texture (RGBA8, `w` x `h`): R a 2x2-texel checker (what LUMINANCE and
/// INTENSITY show), G and B ramps, A a diagonal pattern, so every format shows orientation.
fn matrix_level0(w: usize, h: usize) -> Vec<u8> {
    let mut p = Vec::with_capacity(w * h * 4);
    for y in 0..h {
        for x in 0..w {
            let on = ((x / 2) + (y / 2)) % 2 == 0;
            p.extend_from_slice(&[
                if on { 235 } else { 25 },
                (x * 255 / (w - 1).max(1)) as u8,
                (40 + y * 200 / (h - 1).max(1)) as u8,
                (((x + 2 * y) % 5) * 60 + 10) as u8,
            ]);
        }
    }
    p
}

/// The next mipmap level: a 2x2 box filter (1-wide dimensions averaged along the other).
fn box_down(p: &[u8], w: usize, h: usize) -> (Vec<u8>, usize, usize) {
    let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
    let mut out = Vec::with_capacity(nw * nh * 4);
    for y in 0..nh {
        for x in 0..nw {
            for c in 0..4 {
                let xs = [2 * x, (2 * x + 1).min(w - 1)];
                let ys = [2 * y, (2 * y + 1).min(h - 1)];
                let mut sum = 0u32;
                for yy in ys {
                    for xx in xs {
                        sum += p[(yy * w + xx) * 4 + c] as u32;
                    }
                }
                out.push(((sum + 2) / 4) as u8);
            }
        }
    }
    (out, nw, nh)
}

/// The mipmap chain of a `w` x `h` texture: level 0 from `level0`, then box-filtered levels
/// with a blue tint growing per level (so a wrong level choice shows).
fn chain(level0: Vec<u8>, w: usize, h: usize) -> Vec<(Vec<u8>, usize, usize)> {
    let mut levels = vec![(level0, w, h)];
    while {
        let (_, lw, lh) = levels[levels.len() - 1];
        lw > 1 || lh > 1
    } {
        let (p, lw, lh) = &levels[levels.len() - 1];
        let (mut n, nw, nh) = box_down(p, *lw, *lh);
        let k = levels.len() as u32;
        for t in n.chunks_mut(4) {
            t[2] = ((t[2] as u32 * 3 / 4) + 28 * k).min(255) as u8;
        }
        levels.push((n, nw, nh));
    }
    levels
}

fn is_mipmap(min: GLenum) -> bool {
    min != GL_NEAREST && min != GL_LINEAR
}

/// The magnification filter paired with a minification filter: the filter within a level.
fn mag_of(min: GLenum) -> GLenum {
    match min {
        GL_NEAREST | GL_NEAREST_MIPMAP_NEAREST | GL_NEAREST_MIPMAP_LINEAR => GL_NEAREST,
        _ => GL_LINEAR,
    }
}

fn new_texture(gl: &mut dyn Gl, target: GLenum) -> u32 {
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(target, name[0]);
    name[0]
}

fn filters_and_wrap(gl: &mut dyn Gl, target: GLenum, min: GLenum, wrap: GLenum) {
    gl.tex_parameteri(target, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_parameteri(target, GL_TEXTURE_MAG_FILTER, mag_of(min) as i32);
    gl.tex_parameteri(target, GL_TEXTURE_WRAP_S, wrap as i32);
    gl.tex_parameteri(target, GL_TEXTURE_WRAP_T, wrap as i32);
    gl.tex_parameteri(target, GL_TEXTURE_WRAP_R, wrap as i32);
    gl.tex_parameterfv(target, GL_TEXTURE_BORDER_COLOR, &BORDER);
}

/// A 2D texture of `internal` format from RGBA8 levels.
fn texture_2d(gl: &mut dyn Gl, internal: GLenum, levels: &[(Vec<u8>, usize, usize)]) -> u32 {
    let name = new_texture(gl, GL_TEXTURE_2D);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    for (level, (p, w, h)) in levels.iter().enumerate() {
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            level as i32,
            internal as i32,
            *w as i32,
            *h as i32,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(p),
        );
    }
    name
}

/// The perspective projection of the horizon plane: the horizon near the top of the viewport.
fn horizon_projection(gl: &mut dyn Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -1.0, 0.25, 1.0, 400.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

/// A ground plane y = -1 from just in front of the near plane to z = -150, its texture
/// coordinates affine in object space: s in about [-0.3, 1.3] across the nearest row and t
/// from -0.15 there to 1 at mid-height (texels magnified, the whole [0, 1] square in the lower
/// half, flanked by the wrapped or clamped coordinates), |s| up to ~60 and t up to ~105 at the
/// far edge (strong minification). `r` is given as a function of t (3D textures).
fn horizon_plane(gl: &mut dyn Gl, r_of_t: Option<(f32, f32)>) {
    gl.begin(GL_QUADS);
    for (x, z) in [
        (-80.0f32, -1.05f32),
        (80.0, -1.05),
        (80.0, -150.0),
        (-80.0, -150.0),
    ] {
        // Coefficients off round numbers: with s = 0.5 + 0.75 x the pixel centres of whole
        // rows and columns landed exactly on texel boundaries (ties, which GL leaves open).
        let s = 0.5137 + 0.7519 * x;
        let t = -0.1437 + 0.7093 * (-z - 1.05);
        match r_of_t {
            Some((r0, dr)) => gl.tex_coord_3f(s, t, r0 + dr * t),
            None => gl.tex_coord_2f(s, t),
        }
        gl.vertex_3f(x, -1.0, z);
    }
    gl.end();
}

/// Part 1: one filter and wrap mode, the six base formats in six viewports (192x128).
fn horizon_formats(gl: &mut dyn Gl, min: GLenum, wrap: GLenum) {
    clear(gl);
    let (w, h) = (16, 8);
    let levels = chain(matrix_level0(w, h), w, h);
    let levels = if is_mipmap(min) {
        &levels[..]
    } else {
        &levels[..1]
    };
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.color_4f(0.8, 0.5, 0.3, 1.0);
    gl.enable(GL_TEXTURE_2D);
    horizon_projection(gl);
    for (i, &f) in FORMATS.iter().enumerate() {
        texture_2d(gl, f, levels);
        filters_and_wrap(gl, GL_TEXTURE_2D, min, wrap);
        gl.viewport(64 * (i as i32 % 3), 64 * (i as i32 / 3), 64, 64);
        horizon_plane(gl, None);
    }
}

macro_rules! matrix {
    ($( $name:ident = $min:ident, $wrap:ident, $measured:expr; )* ; extra: [$($extra:expr),* $(,)?]) => {
        $(
            fn $name(gl: &mut dyn Gl) {
                horizon_formats(gl, $min, $wrap);
            }
        )*
        /// The texture-matrix scenes, in report order: part 1 (filter x wrap, six formats
        /// each), then part 2.
        pub const TEXTURE_MATRIX_SCENES: &[Scene] = &[
            // With λ per 2x2 quad (as Mesa computes it) every plane scene is within the
            // normal rule of llvmpipe; the measured llvmpipe-vs-softpipe figures stay in the
            // table for reference (and in conformance/TOLERANCE.md).
            $( sized(stringify!($name), 192, 128, $name, { let _ = $measured; 0.0 }), )*
            $( $extra, )*
        ];
    };
}

// The figures are the llvmpipe-vs-softpipe bad(>8) shares measured by `calibrate`.
matrix! {
    texmat_nearest_repeat = GL_NEAREST, GL_REPEAT, 0.00004;
    texmat_nearest_clamp = GL_NEAREST, GL_CLAMP, 0.0;
    texmat_nearest_edge = GL_NEAREST, GL_CLAMP_TO_EDGE, 0.0;
    texmat_nearest_border = GL_NEAREST, GL_CLAMP_TO_BORDER, 0.0;
    texmat_nearest_mirror = GL_NEAREST, GL_MIRRORED_REPEAT, 0.00004;
    texmat_linear_repeat = GL_LINEAR, GL_REPEAT, 0.0;
    texmat_linear_clamp = GL_LINEAR, GL_CLAMP, 0.0;
    texmat_linear_edge = GL_LINEAR, GL_CLAMP_TO_EDGE, 0.0;
    texmat_linear_border = GL_LINEAR, GL_CLAMP_TO_BORDER, 0.0;
    texmat_linear_mirror = GL_LINEAR, GL_MIRRORED_REPEAT, 0.0;
    texmat_nmn_repeat = GL_NEAREST_MIPMAP_NEAREST, GL_REPEAT, 0.03821;
    texmat_nmn_clamp = GL_NEAREST_MIPMAP_NEAREST, GL_CLAMP, 0.03898;
    texmat_nmn_edge = GL_NEAREST_MIPMAP_NEAREST, GL_CLAMP_TO_EDGE, 0.03898;
    texmat_nmn_border = GL_NEAREST_MIPMAP_NEAREST, GL_CLAMP_TO_BORDER, 0.0;
    texmat_nmn_mirror = GL_NEAREST_MIPMAP_NEAREST, GL_MIRRORED_REPEAT, 0.03796;
    texmat_lmn_repeat = GL_LINEAR_MIPMAP_NEAREST, GL_REPEAT, 0.0363;
    texmat_lmn_clamp = GL_LINEAR_MIPMAP_NEAREST, GL_CLAMP, 0.03377;
    texmat_lmn_edge = GL_LINEAR_MIPMAP_NEAREST, GL_CLAMP_TO_EDGE, 0.03882;
    texmat_lmn_border = GL_LINEAR_MIPMAP_NEAREST, GL_CLAMP_TO_BORDER, 0.0;
    texmat_lmn_mirror = GL_LINEAR_MIPMAP_NEAREST, GL_MIRRORED_REPEAT, 0.03707;
    texmat_nml_repeat = GL_NEAREST_MIPMAP_LINEAR, GL_REPEAT, 0.08724;
    texmat_nml_clamp = GL_NEAREST_MIPMAP_LINEAR, GL_CLAMP, 0.09733;
    texmat_nml_edge = GL_NEAREST_MIPMAP_LINEAR, GL_CLAMP_TO_EDGE, 0.09627;
    texmat_nml_border = GL_NEAREST_MIPMAP_LINEAR, GL_CLAMP_TO_BORDER, 0.0;
    texmat_nml_mirror = GL_NEAREST_MIPMAP_LINEAR, GL_MIRRORED_REPEAT, 0.08915;
    texmat_lml_repeat = GL_LINEAR_MIPMAP_LINEAR, GL_REPEAT, 0.0592;
    texmat_lml_clamp = GL_LINEAR_MIPMAP_LINEAR, GL_CLAMP, 0.01701;
    texmat_lml_edge = GL_LINEAR_MIPMAP_LINEAR, GL_CLAMP_TO_EDGE, 0.09652;
    texmat_lml_border = GL_LINEAR_MIPMAP_LINEAR, GL_CLAMP_TO_BORDER, 0.0;
    texmat_lml_mirror = GL_LINEAR_MIPMAP_LINEAR, GL_MIRRORED_REPEAT, 0.06185;
    ;
    extra: [
        sized("cube_reflection_sphere", 64, 64, cube_reflection_sphere, 0.0),
        sized("cube_reflection_mipmap", 64, 64, cube_reflection_mipmap, 0.10596),
        sized("cube_faces_nearest", 96, 64, cube_faces_nearest, 0.0),
        sized("cube_faces_linear", 96, 64, cube_faces_linear, 0.0),
        sized("tex3d_linear_slices", 64, 64, tex3d_linear_slices, 0.0),
        // Within the rule since λ is taken per 2x2 quad (spread 7.861 % and 5.176 %).
        sized("tex3d_mipmap_linear", 64, 64, tex3d_mipmap_linear, 0.0),
        sized("tex3d_mipmap_nearest", 64, 64, tex3d_mipmap_nearest, 0.0),
        sized("tex3d_wrap_r", 96, 64, tex3d_wrap_r, 0.0),
        sized("depth_cmp_nearest_luminance", 64, 64, depth_cmp_nearest_luminance, 0.0),
        sized("depth_cmp_nearest_intensity", 64, 64, depth_cmp_nearest_intensity, 0.0),
        sized("depth_cmp_nearest_alpha", 64, 64, depth_cmp_nearest_alpha, 0.0),
        // llvmpipe filters depth comparisons per texel (percentage-closer) as tilegl does;
        // softpipe (5.957 % apart) does not, so these keep the normal rule.
        sized("depth_cmp_linear_luminance", 64, 64, depth_cmp_linear_luminance, 0.0),
        sized("depth_cmp_linear_intensity", 64, 64, depth_cmp_linear_intensity, 0.0),
        sized("depth_cmp_linear_alpha", 64, 64, depth_cmp_linear_alpha, 0.0),
        sized("dxt_compressed_nearest", 64, 64, dxt_compressed_nearest, 0.0),
        sized("dxt_compressed_linear", 64, 64, dxt_compressed_linear, 0.0),
        sized("dxt_uncompressed_upload", 64, 64, dxt_uncompressed_upload, 0.0),
        sized("dxt_compressed_mipmaps", 192, 128, dxt_compressed_mipmaps, 0.0),
    ]
}

/// Orthographic pixel space of `w` x `h` (does not clear).
fn pixel_ortho(gl: &mut dyn Gl, w: f64, h: f64) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, w, 0.0, h, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

/// An axis-aligned pixel-space rectangle whose texture coordinates at its corners are given
/// (bottom-left, bottom-right, top-right, top-left); coordinates affine in position, so any
/// split of the quad gives the same picture.
fn patch(gl: &mut dyn Gl, x0: f32, y0: f32, x1: f32, y1: f32, tc: [[f32; 3]; 4]) {
    gl.begin(GL_QUADS);
    for (k, (x, y)) in [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        .into_iter()
        .enumerate()
    {
        gl.tex_coord_3f(tc[k][0], tc[k][1], tc[k][2]);
        gl.vertex_2f(x, y);
    }
    gl.end();
}

// ------------------------------------------------------------------------------- cube maps

const CUBE_FACES: [GLenum; 6] = [
    GL_TEXTURE_CUBE_MAP_POSITIVE_X,
    GL_TEXTURE_CUBE_MAP_NEGATIVE_X,
    GL_TEXTURE_CUBE_MAP_POSITIVE_Y,
    GL_TEXTURE_CUBE_MAP_NEGATIVE_Y,
    GL_TEXTURE_CUBE_MAP_POSITIVE_Z,
    GL_TEXTURE_CUBE_MAP_NEGATIVE_Z,
];

/// Face `f` of the cube map, `n` x `n`: a face colour, a 2x2-texel checker and a red ramp in
/// s, so the face, its orientation and the texels all show.
fn cube_face_pixels(f: usize, n: usize) -> Vec<u8> {
    const BASE: [[u32; 3]; 6] = [
        [250, 60, 60],
        [60, 250, 60],
        [60, 60, 250],
        [250, 250, 60],
        [60, 250, 250],
        [250, 60, 250],
    ];
    let mut p = Vec::with_capacity(n * n * 4);
    for y in 0..n {
        for x in 0..n {
            let on = ((x / 2) + (y / 2)) % 2 == 0;
            let k = if on { 4 } else { 2 };
            let c = BASE[f];
            p.extend_from_slice(&[
                ((c[0] * k / 4) as usize + x * 40 / n).min(255) as u8,
                (c[1] * k / 4) as u8,
                ((c[2] * k / 4) as usize + y * 30 / n).min(255) as u8,
                255,
            ]);
        }
    }
    p
}

fn cube_texture(gl: &mut dyn Gl, min: GLenum) {
    new_texture(gl, GL_TEXTURE_CUBE_MAP);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    for (f, &face) in CUBE_FACES.iter().enumerate() {
        let levels = chain(cube_face_pixels(f, 16), 16, 16);
        let levels = if is_mipmap(min) {
            &levels[..]
        } else {
            &levels[..1]
        };
        for (level, (p, w, h)) in levels.iter().enumerate() {
            gl.tex_image_2d(
                face,
                level as i32,
                GL_RGBA as i32,
                *w as i32,
                *h as i32,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(p),
            );
        }
    }
    filters_and_wrap(gl, GL_TEXTURE_CUBE_MAP, min, GL_CLAMP_TO_EDGE);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_CUBE_MAP);
}

/// A sphere in perspective with reflection-map texture coordinates (S, T and R).
fn cube_reflection(gl: &mut dyn Gl, min: GLenum) {
    clear(gl);
    cube_texture(gl, min);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.6, 0.6, -0.6, 0.6, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.enable(GL_DEPTH_TEST);
    for c in [GL_S, GL_T, GL_R] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP as i32);
    }
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    gl.enable(GL_TEXTURE_GEN_R);
    gl.translatef(0.0, 0.0, -2.6);
    gl.rotatef(35.0, 1.0, 0.4, 0.0);
    sphere(gl, 16, 24);
}

fn cube_reflection_sphere(gl: &mut dyn Gl) {
    cube_reflection(gl, GL_LINEAR);
}

fn cube_reflection_mipmap(gl: &mut dyn Gl) {
    cube_reflection(gl, GL_LINEAR_MIPMAP_LINEAR);
}

/// Six 32x32 patches (96x64), one per face: the direction is the face's major axis plus
/// +-1.5 along its two other axes at the corners, so each patch shows its face in the middle
/// and crosses all four seams into the neighbouring faces.
fn cube_faces(gl: &mut dyn Gl, min: GLenum) {
    clear(gl);
    cube_texture(gl, min);
    pixel_ortho(gl, 96.0, 64.0);
    let axes: [([f32; 3], [f32; 3], [f32; 3]); 6] = [
        ([1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, -1.0, 0.0]),
        ([-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]),
        ([0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
        ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]),
        ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, -1.0, 0.0]),
        ([0.0, 0.0, -1.0], [-1.0, 0.0, 0.0], [0.0, -1.0, 0.0]),
    ];
    for (f, (m, u, v)) in axes.into_iter().enumerate() {
        let dir = |a: f32, b: f32| {
            // Slightly off-centre (0.07) so the seams do not fall on pixel centres.
            let (a, b) = (1.5 * a + 0.07, 1.5 * b - 0.05);
            [0, 1, 2].map(|i| m[i] + a * u[i] + b * v[i])
        };
        let (x0, y0) = (32.0 * (f % 3) as f32, 32.0 * (f / 3) as f32);
        patch(
            gl,
            x0,
            y0,
            x0 + 32.0,
            y0 + 32.0,
            [
                dir(-1.0, -1.0),
                dir(1.0, -1.0),
                dir(1.0, 1.0),
                dir(-1.0, 1.0),
            ],
        );
    }
}

fn cube_faces_nearest(gl: &mut dyn Gl) {
    cube_faces(gl, GL_NEAREST);
}

fn cube_faces_linear(gl: &mut dyn Gl) {
    cube_faces(gl, GL_LINEAR);
}

// ------------------------------------------------------------------------------ 3D textures

/// An 8x8x8 volume: R ramps in x, G a checker in x and y, B the slice, A ramps in z.
fn volume_level0(n: usize) -> Vec<u8> {
    let mut p = Vec::with_capacity(n * n * n * 4);
    for z in 0..n {
        for y in 0..n {
            for x in 0..n {
                let on = ((x / 2) + (y / 2)) % 2 == 0;
                p.extend_from_slice(&[
                    (20 + x * 220 / (n - 1)) as u8,
                    if on { 230 } else { 40 },
                    ((z * 97) % 256) as u8,
                    (60 + z * 190 / (n - 1)) as u8,
                ]);
            }
        }
    }
    p
}

/// The next level of an `n`-cube: 2x2x2 box filter.
fn volume_down(p: &[u8], n: usize) -> Vec<u8> {
    let m = (n / 2).max(1);
    let mut out = Vec::with_capacity(m * m * m * 4);
    for z in 0..m {
        for y in 0..m {
            for x in 0..m {
                for c in 0..4 {
                    let mut sum = 0u32;
                    for dz in 0..2 {
                        for dy in 0..2 {
                            for dx in 0..2 {
                                let (xx, yy, zz) = (2 * x + dx, 2 * y + dy, 2 * z + dz);
                                sum += p[((zz * n + yy) * n + xx) * 4 + c] as u32;
                            }
                        }
                    }
                    out.push(((sum + 4) / 8) as u8);
                }
            }
        }
    }
    out
}

fn volume_texture(gl: &mut dyn Gl, min: GLenum, wrap: GLenum) {
    new_texture(gl, GL_TEXTURE_3D);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    let mut n = 8;
    let mut p = volume_level0(n);
    let mut level = 0;
    loop {
        gl.tex_image_3d(
            GL_TEXTURE_3D,
            level,
            GL_RGBA as i32,
            n as i32,
            n as i32,
            n as i32,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&p),
        );
        if n == 1 || !is_mipmap(min) {
            break;
        }
        p = volume_down(&p, n);
        n /= 2;
        level += 1;
    }
    filters_and_wrap(gl, GL_TEXTURE_3D, min, wrap);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_3D);
}

/// Four slices through the volume (LINEAR, REPEAT): three at constant r (between slices, so
/// r is interpolated) and one oblique, r from -0.4 to 1.6.
fn tex3d_linear_slices(gl: &mut dyn Gl) {
    clear(gl);
    volume_texture(gl, GL_LINEAR, GL_REPEAT);
    pixel_ortho(gl, 64.0, 64.0);
    for (k, r) in [0.11f32, 0.43, 0.77].into_iter().enumerate() {
        let (x0, y0) = (32.0 * (k % 2) as f32, 32.0 * (k / 2) as f32);
        patch(
            gl,
            x0 + 1.0,
            y0 + 1.0,
            x0 + 31.0,
            y0 + 31.0,
            [
                [-0.1, -0.1, r],
                [1.1, -0.1, r],
                [1.1, 1.1, r],
                [-0.1, 1.1, r],
            ],
        );
    }
    patch(
        gl,
        33.0,
        33.0,
        63.0,
        63.0,
        [
            [0.0, 0.0, -0.4],
            [1.0, 0.0, 0.6],
            [1.0, 1.0, 1.6],
            [0.0, 1.0, 0.6],
        ],
    );
}

/// The horizon plane cutting obliquely through the repeated volume: r grows with t.
fn tex3d_mipmap(gl: &mut dyn Gl, min: GLenum) {
    clear(gl);
    volume_texture(gl, min, GL_REPEAT);
    horizon_projection(gl);
    horizon_plane(gl, Some((0.1, 0.37)));
}

fn tex3d_mipmap_linear(gl: &mut dyn Gl) {
    tex3d_mipmap(gl, GL_LINEAR_MIPMAP_LINEAR);
}

fn tex3d_mipmap_nearest(gl: &mut dyn Gl) {
    tex3d_mipmap(gl, GL_NEAREST_MIPMAP_NEAREST);
}

/// Six patches (96x64) with r from -1.3 to 2.3 across each: the r wrap modes REPEAT, CLAMP,
/// CLAMP_TO_EDGE, CLAMP_TO_BORDER, MIRRORED_REPEAT under LINEAR, and MIRRORED_REPEAT under
/// NEAREST (s and t wrap the same way; s in [0, 1] up each patch, t constant).
fn tex3d_wrap_r(gl: &mut dyn Gl) {
    clear(gl);
    pixel_ortho(gl, 96.0, 64.0);
    let cases = [
        (GL_LINEAR, GL_REPEAT),
        (GL_LINEAR, GL_CLAMP),
        (GL_LINEAR, GL_CLAMP_TO_EDGE),
        (GL_LINEAR, GL_CLAMP_TO_BORDER),
        (GL_LINEAR, GL_MIRRORED_REPEAT),
        (GL_NEAREST, GL_MIRRORED_REPEAT),
    ];
    for (k, (min, wrap)) in cases.into_iter().enumerate() {
        volume_texture(gl, min, wrap);
        let (x0, y0) = (32.0 * (k % 3) as f32, 32.0 * (k / 3) as f32);
        patch(
            gl,
            x0 + 1.0,
            y0 + 1.0,
            x0 + 31.0,
            y0 + 31.0,
            [
                [0.03, 0.41, -1.3],
                [0.03, 0.41, 2.3],
                [0.97, 0.41, 2.3],
                [0.97, 0.41, -1.3],
            ],
        );
    }
}

// --------------------------------------------------------------------------- depth textures

const COMPARE_FUNCS: [GLenum; 8] = [
    GL_NEVER,
    GL_LESS,
    GL_EQUAL,
    GL_LEQUAL,
    GL_GREATER,
    GL_NOTEQUAL,
    GL_GEQUAL,
    GL_ALWAYS,
];

/// An 8x8 depth texture: the bottom row 0, the top row 1 (exact in any depth format), the
/// rows between a ramp in t with an alternating offset in s.
fn depth_texels() -> Vec<f32> {
    let mut d = Vec::with_capacity(64);
    for y in 0..8 {
        for x in 0..8 {
            d.push(match y {
                0 => 0.0,
                7 => 1.0,
                _ => y as f32 / 7.0 - 0.06 + if x % 2 == 0 { 0.1 } else { 0.0 },
            });
        }
    }
    d
}

/// Eight 32x16 patches, one per compare function; in each, s and t span the texture and r
/// goes from -0.1 to 1.1 left to right (clamped to [0, 1] before the comparison). The bottom
/// strip of each patch has r = 0 exactly (against texels of depth 0, so EQUAL passes there),
/// the top strip r = 1 exactly.
fn depth_compare(gl: &mut dyn Gl, filter: GLenum, mode: GLenum) {
    clear(gl);
    pixel_ortho(gl, 64.0, 64.0);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.color_4f(0.7, 0.4, 0.9, 1.0);
    let texels = depth_texels();
    let bytes: Vec<u8> = texels.iter().flat_map(|v| v.to_ne_bytes()).collect();
    gl.enable(GL_TEXTURE_2D);
    for (k, &func) in COMPARE_FUNCS.iter().enumerate() {
        new_texture(gl, GL_TEXTURE_2D);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_DEPTH_COMPONENT as i32,
            8,
            8,
            0,
            GL_DEPTH_COMPONENT,
            GL_FLOAT,
            Some(&bytes),
        );
        filters_and_wrap(gl, GL_TEXTURE_2D, filter, GL_CLAMP_TO_EDGE);
        gl.tex_parameteri(
            GL_TEXTURE_2D,
            GL_TEXTURE_COMPARE_MODE,
            GL_COMPARE_R_TO_TEXTURE as i32,
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, func as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, mode as i32);
        let (x0, y0) = (32.0 * (k % 2) as f32, 16.0 * (k / 2) as f32);
        // Main area: s, t over the texture, r ramping.
        patch(
            gl,
            x0,
            y0 + 3.0,
            x0 + 32.0,
            y0 + 13.0,
            [
                [0.0, 0.13, -0.1],
                [1.0, 0.13, 1.1],
                [1.0, 0.87, 1.1],
                [0.0, 0.87, -0.1],
            ],
        );
        // r = 0 on the depth-0 row, r = 1 on the depth-1 row.
        patch(
            gl,
            x0,
            y0,
            x0 + 32.0,
            y0 + 3.0,
            [
                [0.0, 0.02, 0.0],
                [1.0, 0.02, 0.0],
                [1.0, 0.05, 0.0],
                [0.0, 0.05, 0.0],
            ],
        );
        patch(
            gl,
            x0,
            y0 + 13.0,
            x0 + 32.0,
            y0 + 16.0,
            [
                [0.0, 0.95, 1.0],
                [1.0, 0.95, 1.0],
                [1.0, 0.98, 1.0],
                [0.0, 0.98, 1.0],
            ],
        );
    }
}

fn depth_cmp_nearest_luminance(gl: &mut dyn Gl) {
    depth_compare(gl, GL_NEAREST, GL_LUMINANCE);
}

fn depth_cmp_nearest_intensity(gl: &mut dyn Gl) {
    depth_compare(gl, GL_NEAREST, GL_INTENSITY);
}

fn depth_cmp_nearest_alpha(gl: &mut dyn Gl) {
    depth_compare(gl, GL_NEAREST, GL_ALPHA);
}

fn depth_cmp_linear_luminance(gl: &mut dyn Gl) {
    depth_compare(gl, GL_LINEAR, GL_LUMINANCE);
}

fn depth_cmp_linear_intensity(gl: &mut dyn Gl) {
    depth_compare(gl, GL_LINEAR, GL_INTENSITY);
}

fn depth_cmp_linear_alpha(gl: &mut dyn Gl) {
    depth_compare(gl, GL_LINEAR, GL_ALPHA);
}

// -------------------------------------------------------------------------------------- S3TC

const DXT_FORMATS: [GLenum; 4] = [
    GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT1_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT5_EXT,
];

/// A DXT colour block: endpoints and 2-bit indices (texel k at bits 2k).
fn color_block(c0: u16, c1: u16, idx: impl Fn(usize) -> u32) -> [u8; 8] {
    let mut bits = 0u32;
    for k in 0..16 {
        bits |= (idx(k) & 3) << (2 * k);
    }
    let mut b = [0u8; 8];
    b[0..2].copy_from_slice(&c0.to_le_bytes());
    b[2..4].copy_from_slice(&c1.to_le_bytes());
    b[4..8].copy_from_slice(&bits.to_le_bytes());
    b
}

/// Hand-built 8x8 images (2x2 blocks) of format `f`: the four blocks use four-colour mode
/// (color0 > color1) and three-colour mode (color0 <= color1) in turn, every index pattern,
/// and for DXT3 every 4-bit alpha, for DXT5 both alpha modes.
fn dxt_blocks(f: GLenum) -> Vec<u8> {
    let colors: [(u16, u16); 4] = [
        (0xF800, 0x001F), // red > blue: four colours
        (0x07E0, 0xF81F), // green <= magenta: three colours (+ black or transparent)
        (0xFFE0, 0x0410), // yellow > dark green: four colours
        (0x001F, 0x001F), // equal: three-colour mode, index 2 the same colour
    ];
    let mut out = Vec::new();
    for (b, &(c0, c1)) in colors.iter().enumerate() {
        let color = color_block(c0, c1, |k| ((k + b + k / 4) % 4) as u32);
        match f {
            GL_COMPRESSED_RGBA_S3TC_DXT3_EXT => {
                let mut a = 0u64;
                for k in 0..16u64 {
                    a |= ((k + 5 * b as u64) % 16) << (4 * k);
                }
                out.extend_from_slice(&a.to_le_bytes());
                out.extend_from_slice(&color);
            }
            GL_COMPRESSED_RGBA_S3TC_DXT5_EXT => {
                let (a0, a1) = if b % 2 == 0 { (230u8, 20u8) } else { (40, 210) };
                let mut bits = 0u64;
                for k in 0..16u64 {
                    bits |= ((k + b as u64) % 8) << (3 * k);
                }
                out.extend_from_slice(&[a0, a1]);
                out.extend_from_slice(&bits.to_le_bytes()[..6]);
                out.extend_from_slice(&color);
            }
            _ => out.extend_from_slice(&color),
        }
    }
    out
}

/// Four patches, one per S3TC format, of hand-built blocks uploaded with
/// glCompressedTexImage2D; `lo..hi` the texture coordinate range (REPEAT).
fn dxt_compressed(gl: &mut dyn Gl, filter: GLenum, lo: f32, hi: f32) {
    clear(gl);
    pixel_ortho(gl, 64.0, 64.0);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    for (k, &f) in DXT_FORMATS.iter().enumerate() {
        new_texture(gl, GL_TEXTURE_2D);
        let data = dxt_blocks(f);
        gl.compressed_tex_image_2d(GL_TEXTURE_2D, 0, f, 8, 8, 0, data.len() as i32, Some(&data));
        filters_and_wrap(gl, GL_TEXTURE_2D, filter, GL_REPEAT);
        let (x0, y0) = (32.0 * (k % 2) as f32, 32.0 * (k / 2) as f32);
        patch(
            gl,
            x0,
            y0,
            x0 + 32.0,
            y0 + 32.0,
            [[lo, lo, 0.0], [hi, lo, 0.0], [hi, hi, 0.0], [lo, hi, 0.0]],
        );
    }
}

fn dxt_compressed_nearest(gl: &mut dyn Gl) {
    dxt_compressed(gl, GL_NEAREST, 0.0, 1.0);
}

fn dxt_compressed_linear(gl: &mut dyn Gl) {
    dxt_compressed(gl, GL_LINEAR, -0.3, 1.45);
}

/// Uncompressed RGBA data uploaded with each S3TC internal format (the driver compresses).
/// Each 4x4 block holds two colours exactly representable in 5:6:5 (any encoder keeps them
/// exactly), alphas 0/255 (DXT1 RGBA: transparent texels black), multiples of 17 (DXT3) or two
/// values per block (DXT5).
fn dxt_uncompressed_upload(gl: &mut dyn Gl) {
    clear(gl);
    pixel_ortho(gl, 64.0, 64.0);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    // 5:6:5-exact colours: 5-bit v -> (v << 3) | (v >> 2); 6-bit v -> (v << 2) | (v >> 4).
    let pairs: [([u8; 3], [u8; 3]); 4] = [
        ([255, 0, 0], [0, 0, 255]),
        ([132, 255, 0], [0, 65, 66]),
        ([255, 255, 255], [0, 0, 0]),
        ([41, 130, 214], [214, 20, 99]),
    ];
    for (k, &f) in DXT_FORMATS.iter().enumerate() {
        let mut p = Vec::with_capacity(8 * 8 * 4);
        for y in 0..8usize {
            for x in 0..8usize {
                let b = (y / 4) * 2 + x / 4;
                let second = (x + y + b) % 3 == 0;
                let c = if second { pairs[b].1 } else { pairs[b].0 };
                let a = match (f, second) {
                    (GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, true) => 0,
                    (GL_COMPRESSED_RGBA_S3TC_DXT3_EXT, _) => (((x + 3 * y) % 16) * 17) as u8,
                    (GL_COMPRESSED_RGBA_S3TC_DXT5_EXT, true) => 30,
                    (GL_COMPRESSED_RGBA_S3TC_DXT5_EXT, false) => 200,
                    _ => 255,
                };
                let c = if f == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT && a == 0 {
                    [0, 0, 0]
                } else {
                    c
                };
                p.extend_from_slice(&[c[0], c[1], c[2], a]);
            }
        }
        new_texture(gl, GL_TEXTURE_2D);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            f as i32,
            8,
            8,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&p),
        );
        filters_and_wrap(gl, GL_TEXTURE_2D, GL_NEAREST, GL_REPEAT);
        let (x0, y0) = (32.0 * (k % 2) as f32, 32.0 * (k / 2) as f32);
        patch(
            gl,
            x0,
            y0,
            x0 + 32.0,
            y0 + 32.0,
            [
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [1.0, 1.0, 0.0],
                [0.0, 1.0, 0.0],
            ],
        );
    }
}

/// One hand-built block of format `f` for block `b` of mipmap level `level`: endpoints and
/// alphas vary with both, so each level looks different; the colour mode alternates.
fn mip_block(f: GLenum, level: usize, b: usize) -> Vec<u8> {
    const ENDS: [(u16, u16); 6] = [
        (0xF800, 0x07E0),
        (0x001F, 0xFFE0),
        (0xF81F, 0x07FF),
        (0x8410, 0xFC00),
        (0x041F, 0xA145),
        (0xFFFF, 0x39E7),
    ];
    let (mut c0, mut c1) = ENDS[(level + b) % 6];
    if (level + b) % 2 == 1 {
        // Three-colour mode (color0 <= color1) for DXT1.
        (c0, c1) = (c0.min(c1), c0.max(c1));
    } else {
        (c0, c1) = (c0.max(c1), c0.min(c1).saturating_sub(1));
    }
    let color = color_block(c0, c1, |k| ((k * 3 + k / 4 + level + b) % 4) as u32);
    let mut out = Vec::new();
    match f {
        GL_COMPRESSED_RGBA_S3TC_DXT3_EXT => {
            let mut a = 0u64;
            for k in 0..16u64 {
                a |= ((k * 7 + 3 * level as u64 + b as u64) % 16) << (4 * k);
            }
            out.extend_from_slice(&a.to_le_bytes());
            out.extend_from_slice(&color);
        }
        GL_COMPRESSED_RGBA_S3TC_DXT5_EXT => {
            let a0 = (40 * level + 30) as u8;
            let a1 = (250 - 35 * level) as u8;
            let mut bits = 0u64;
            for k in 0..16u64 {
                bits |= ((k * 5 + b as u64) % 8) << (3 * k);
            }
            out.extend_from_slice(&[a0, a1]);
            out.extend_from_slice(&bits.to_le_bytes()[..6]);
            out.extend_from_slice(&color);
        }
        _ => out.extend_from_slice(&color),
    }
    out
}

/// Compressed mipmap chains (32x32 down to 1x1, the 2x2 and 1x1 levels partial blocks) through
/// glCompressedTexImage2D, one row per S3TC format (192x128). Column k is a 32x32 quad with s
/// and t over [0, 2^k] under NEAREST_MIPMAP_NEAREST: λ = k exactly and every pixel centre falls
/// on a texel centre of level k, so each column shows one whole level.
fn dxt_compressed_mipmaps(gl: &mut dyn Gl) {
    clear(gl);
    pixel_ortho(gl, 192.0, 128.0);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    for (row, &f) in DXT_FORMATS.iter().enumerate() {
        new_texture(gl, GL_TEXTURE_2D);
        for level in 0..6usize {
            let n = 32usize >> level;
            let blocks = n.div_ceil(4) * n.div_ceil(4);
            let data: Vec<u8> = (0..blocks).flat_map(|b| mip_block(f, level, b)).collect();
            gl.compressed_tex_image_2d(
                GL_TEXTURE_2D,
                level as i32,
                f,
                n as i32,
                n as i32,
                0,
                data.len() as i32,
                Some(&data),
            );
        }
        filters_and_wrap(gl, GL_TEXTURE_2D, GL_NEAREST_MIPMAP_NEAREST, GL_REPEAT);
        for k in 0..6 {
            let (x0, y0) = (32.0 * k as f32, 32.0 * row as f32);
            let e = (1u32 << k) as f32;
            patch(
                gl,
                x0,
                y0,
                x0 + 32.0,
                y0 + 32.0,
                [[0.0, 0.0, 0.0], [e, 0.0, 0.0], [e, e, 0.0], [0.0, e, 0.0]],
            );
        }
    }
}

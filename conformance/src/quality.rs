//! Error against run time for every quality knob a fixed-function program can turn: each knob
//! is a scene drawn under each of its settings on tilegl and on Mesa llvmpipe (in this
//! process), timed per frame, and compared with a reference: the same scene at its best
//! setting rendered by tilegl at 4x4 the size and box-filtered down (so both implementations
//! are measured against one ideal, not against each other). Each knob gives a table and a
//! labelled PNG chart (mean error against milliseconds per frame, a point per setting, tilegl's
//! and Mesa's series side by side).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use plotters::prelude::*;
use tilegl::enums::*;
use tilegl::{Context, ContextConfig, FramebufferConfig, Gl};

use crate::compare::{diff, Image};
use crate::mesa::{MesaContext, Oracle};

/// Size of the timed pictures.
pub const SIZE: i32 = 256;

/// One knob: its settings and the scene.
pub struct Knob {
    /// File-name friendly name.
    pub id: &'static str,
    /// Chart title.
    pub title: &'static str,
    /// What the knob is and what the scene shows.
    pub what: &'static str,
    pub settings: &'static [&'static str],
    /// The setting the reference uses.
    pub best: usize,
    /// Once per context: textures and state for `setting`.
    pub setup: fn(&mut dyn Gl, usize),
    /// One frame (after a clear of colour, depth and accumulation buffers).
    pub frame: fn(&mut dyn Gl, usize),
}

/// The measurement of one setting on one implementation.
#[derive(Clone, Debug)]
pub struct Point {
    pub setting: &'static str,
    /// Median milliseconds per frame.
    pub ms: f64,
    /// Mean absolute channel difference from the reference (0-255).
    pub mean_error: f64,
    pub psnr: f64,
}

/// One knob's results.
#[derive(Clone, Debug)]
pub struct KnobResult {
    pub id: &'static str,
    pub title: &'static str,
    pub what: &'static str,
    pub tilegl: Vec<Point>,
    pub llvmpipe: Vec<Point>,
}

// ------------------------------------------------------------------ scenes

fn checker_texture(size: i32) -> Vec<u8> {
    let mut p = Vec::with_capacity((size * size * 4) as usize);
    for y in 0..size {
        for x in 0..size {
            let c = ((x * 8 / size) + (y * 8 / size)) % 2 == 0;
            let fine = ((x * 64 / size) + (y * 64 / size)) % 2 == 0;
            let v: u8 = if c { 230 } else { 40 };
            let w: u8 = if fine { 25 } else { 0 };
            p.extend_from_slice(&[v, v.saturating_add(w), 255 - v, 255]);
        }
    }
    p
}

/// A box-filtered level below `src` (`size` x `size` RGBA).
fn box_down(src: &[u8], size: i32) -> Vec<u8> {
    let h = size / 2;
    let mut out = Vec::with_capacity((h * h * 4) as usize);
    for y in 0..h {
        for x in 0..h {
            for c in 0..4 {
                let at = |xx: i32, yy: i32| src[((yy * size + xx) * 4 + c) as usize] as u32;
                let s = at(2 * x, 2 * y)
                    + at(2 * x + 1, 2 * y)
                    + at(2 * x, 2 * y + 1)
                    + at(2 * x + 1, 2 * y + 1);
                out.push(((s + 2) / 4) as u8);
            }
        }
    }
    out
}

/// Binds a new `size` x `size` checker texture; `box_levels` uploads box-filtered mipmaps,
/// otherwise GL_GENERATE_MIPMAP makes them.
pub(crate) fn texture(gl: &mut dyn Gl, size: i32, internal: GLenum, box_levels: bool) {
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_2D, name[0]);
    let mut level = checker_texture(size);
    if !box_levels {
        gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
    }
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        internal as i32,
        size,
        size,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&level),
    );
    if box_levels {
        let (mut s, mut l) = (size, 0);
        while s > 1 {
            level = box_down(&level, s);
            s /= 2;
            l += 1;
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                l,
                internal as i32,
                s,
                s,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&level),
            );
        }
    }
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
}

fn perspective(gl: &mut dyn Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.1, 0.1, -0.1, 0.1, 0.1, 100.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

/// A textured ground plane receding to the horizon.
fn horizon(gl: &mut dyn Gl) {
    gl.begin(GL_QUADS);
    gl.tex_coord_2f(0.0, 0.0);
    gl.vertex_3f(-20.0, -1.0, -0.2);
    gl.tex_coord_2f(24.0, 0.0);
    gl.vertex_3f(20.0, -1.0, -0.2);
    gl.tex_coord_2f(24.0, 96.0);
    gl.vertex_3f(20.0, -1.0, -80.0);
    gl.tex_coord_2f(0.0, 96.0);
    gl.vertex_3f(-20.0, -1.0, -80.0);
    gl.end();
}

const FILTERS: [(GLenum, f32); 10] = [
    (GL_NEAREST, 1.0),
    (GL_LINEAR, 1.0),
    (GL_NEAREST_MIPMAP_NEAREST, 1.0),
    (GL_LINEAR_MIPMAP_NEAREST, 1.0),
    (GL_NEAREST_MIPMAP_LINEAR, 1.0),
    (GL_LINEAR_MIPMAP_LINEAR, 1.0),
    (GL_LINEAR_MIPMAP_LINEAR, 2.0),
    (GL_LINEAR_MIPMAP_LINEAR, 4.0),
    (GL_LINEAR_MIPMAP_LINEAR, 8.0),
    (GL_LINEAR_MIPMAP_LINEAR, 16.0),
];

fn filter_setup(gl: &mut dyn Gl, s: usize) {
    texture(gl, 256, GL_RGBA8, true);
    let (min, aniso) = FILTERS[s];
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, aniso);
    perspective(gl);
}

fn horizon_frame(gl: &mut dyn Gl, _: usize) {
    horizon(gl);
}

const BIASES: [f32; 7] = [-2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0];

fn bias_setup(gl: &mut dyn Gl, s: usize) {
    texture(gl, 256, GL_RGBA8, true);
    gl.tex_envf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, BIASES[s]);
    perspective(gl);
}

fn mipgen_setup(gl: &mut dyn Gl, s: usize) {
    texture(gl, 256, GL_RGBA8, s == 0);
    perspective(gl);
}

const SIZES: [i32; 6] = [16, 32, 64, 128, 256, 512];

fn size_setup(gl: &mut dyn Gl, s: usize) {
    texture(gl, SIZES[s], GL_RGBA8, true);
    perspective(gl);
}

const FORMATS: [GLenum; 3] = [
    GL_RGBA8,
    GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT5_EXT,
];

fn s3tc_setup(gl: &mut dyn Gl, s: usize) {
    texture(gl, 256, FORMATS[s], false);
    perspective(gl);
}

fn perspective_hint_setup(gl: &mut dyn Gl, s: usize) {
    texture(gl, 256, GL_RGBA8, true);
    gl.hint(
        GL_PERSPECTIVE_CORRECTION_HINT,
        if s == 0 { GL_FASTEST } else { GL_NICEST },
    );
    perspective(gl);
}

fn fog_setup(gl: &mut dyn Gl, s: usize) {
    gl.hint(GL_FOG_HINT, if s == 0 { GL_FASTEST } else { GL_NICEST });
    gl.enable(GL_FOG);
    gl.fogi(GL_FOG_MODE, GL_EXP2 as i32);
    gl.fogf(GL_FOG_DENSITY, 0.08);
    gl.fogfv(GL_FOG_COLOR, &[0.7, 0.75, 0.8, 1.0]);
    gl.enable(GL_DEPTH_TEST);
    perspective(gl);
}

/// Large triangles receding into fog: per-vertex and per-fragment fog differ across them.
fn fog_frame(gl: &mut dyn Gl, _: usize) {
    gl.begin(GL_TRIANGLES);
    for i in 0..6 {
        let z0 = -0.5 - 6.0 * i as f32;
        let z1 = z0 - 6.0;
        let c = if i % 2 == 0 {
            [0.2, 0.6, 0.2]
        } else {
            [0.6, 0.3, 0.1]
        };
        gl.color_3f(c[0], c[1], c[2]);
        gl.vertex_3f(-8.0, -1.0, z0);
        gl.vertex_3f(8.0, -1.0, z0);
        gl.vertex_3f(0.0, 2.0, z1);
    }
    gl.end();
}

fn lines_setup(gl: &mut dyn Gl, s: usize) {
    crate::scenes::pixel_space(gl, SIZE as f64, SIZE as f64);
    if s >= 1 {
        gl.enable(GL_LINE_SMOOTH);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    gl.hint(
        GL_LINE_SMOOTH_HINT,
        if s == 2 { GL_NICEST } else { GL_FASTEST },
    );
    gl.line_width(1.5);
}

fn lines_frame(gl: &mut dyn Gl, _: usize) {
    gl.color_3f(1.0, 1.0, 0.8);
    gl.begin(GL_LINES);
    for i in 0..24 {
        let a = i as f32 * std::f32::consts::PI / 24.0;
        let (c, s) = (a.cos(), a.sin());
        gl.vertex_2f(128.0 + 20.0 * c, 128.0 + 20.0 * s);
        gl.vertex_2f(128.0 + 120.0 * c, 128.0 + 120.0 * s);
    }
    gl.end();
}

fn points_setup(gl: &mut dyn Gl, s: usize) {
    crate::scenes::pixel_space(gl, SIZE as f64, SIZE as f64);
    if s == 1 {
        gl.enable(GL_POINT_SMOOTH);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    gl.point_size(5.0);
}

fn points_frame(gl: &mut dyn Gl, _: usize) {
    gl.color_3f(0.9, 0.9, 1.0);
    gl.begin(GL_POINTS);
    for i in 0..20 {
        for j in 0..20 {
            gl.vertex_2f(8.3 + i as f32 * 12.37, 8.1 + j as f32 * 12.29);
        }
    }
    gl.end();
}

const PASSES: [usize; 5] = [1, 2, 4, 8, 16];

fn accum_setup(gl: &mut dyn Gl, _: usize) {
    crate::scenes::pixel_space(gl, SIZE as f64, SIZE as f64);
}

/// Thin slanted triangles, drawn `n` times with sub-pixel jitter into the accumulation buffer.
fn accum_aa_frame(gl: &mut dyn Gl, s: usize) {
    let n = PASSES[s];
    for p in 0..n {
        // A rotated-grid jitter (n points in the unit square).
        let (jx, jy) = (
            ((p as f32 + 0.5) / n as f32 * 7.0).fract(),
            (p as f32 + 0.5) / n as f32,
        );
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        gl.translatef(jx - 0.5, jy - 0.5, 0.0);
        gl.begin(GL_TRIANGLES);
        for i in 0..12 {
            let x = 10.0 + 20.0 * i as f32;
            gl.color_3f(1.0, 0.5 + 0.04 * i as f32, 0.2);
            gl.vertex_2f(x, 10.0);
            gl.vertex_2f(x + 3.0 + i as f32 * 0.3, 10.0);
            gl.vertex_2f(x + 40.0, 246.0);
        }
        gl.end();
        gl.accum(if p == 0 { GL_LOAD } else { GL_ACCUM }, 1.0 / n as f32);
    }
    gl.accum(GL_RETURN, 1.0);
}

/// A square moving across the window, `n` time samples averaged in the accumulation buffer.
fn motion_blur_frame(gl: &mut dyn Gl, s: usize) {
    let n = PASSES[s];
    for p in 0..n {
        let t = (p as f32 + 0.5) / n as f32;
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.color_3f(0.3, 0.8, 1.0);
        let x = 30.0 + 150.0 * t;
        gl.rectf(x, 90.0, x + 50.0, 166.0);
        gl.accum(if p == 0 { GL_LOAD } else { GL_ACCUM }, 1.0 / n as f32);
    }
    gl.accum(GL_RETURN, 1.0);
}

/// Every knob.
pub fn knobs() -> Vec<Knob> {
    vec![
        Knob {
            id: "min_filter",
            title: "Minification filter and anisotropy",
            what: "A checkerboard plane receding to the horizon under each GL_TEXTURE_MIN_FILTER, then trilinear with GL_TEXTURE_MAX_ANISOTROPY_EXT 2-16.",
            settings: &["NEAREST", "LINEAR", "N_MIP_N", "L_MIP_N", "N_MIP_L", "trilinear", "aniso 2", "aniso 4", "aniso 8", "aniso 16"],
            best: 9,
            setup: filter_setup,
            frame: horizon_frame,
        },
        Knob {
            id: "lod_bias",
            title: "LOD bias (GL_TEXTURE_LOD_BIAS)",
            what: "The trilinear horizon with the texture environment's LOD bias from -2 (sharper, aliased) to +2 (blurrier).",
            settings: &["-2", "-1", "-0.5", "0", "+0.5", "+1", "+2"],
            best: 3,
            setup: bias_setup,
            frame: horizon_frame,
        },
        Knob {
            id: "mipmap_generation",
            title: "Mipmap generation",
            what: "Levels box-filtered on the CPU and uploaded, against GL_GENERATE_MIPMAP.",
            settings: &["box levels", "GENERATE_MIPMAP"],
            best: 0,
            setup: mipgen_setup,
            frame: horizon_frame,
        },
        Knob {
            id: "texture_size",
            title: "Texture size",
            what: "The same checkerboard pattern stored at 16x16 to 512x512 texels.",
            settings: &["16", "32", "64", "128", "256", "512"],
            best: 5,
            setup: size_setup,
            frame: horizon_frame,
        },
        Knob {
            id: "s3tc",
            title: "S3TC compression",
            what: "The texture uploaded uncompressed, or compressed by the driver to DXT1 or DXT5.",
            settings: &["RGBA8", "DXT1", "DXT5"],
            best: 0,
            setup: s3tc_setup,
            frame: horizon_frame,
        },
        Knob {
            id: "perspective_hint",
            title: "Perspective-correction hint",
            what: "GL_PERSPECTIVE_CORRECTION_HINT FASTEST against NICEST on the horizon.",
            settings: &["FASTEST", "NICEST"],
            best: 1,
            setup: perspective_hint_setup,
            frame: horizon_frame,
        },
        Knob {
            id: "fog_hint",
            title: "Fog hint (per-vertex or per-fragment fog)",
            what: "Large triangles receding into EXP2 fog under GL_FOG_HINT FASTEST and NICEST.",
            settings: &["FASTEST", "NICEST"],
            best: 1,
            setup: fog_setup,
            frame: fog_frame,
        },
        Knob {
            id: "line_smooth",
            title: "Line smoothing",
            what: "A fan of 1.5-pixel lines: aliased, GL_LINE_SMOOTH with blending (FASTEST, NICEST); reference: 16 jittered aliased passes.",
            settings: &["aliased", "smooth FASTEST", "smooth NICEST"],
            best: 0,
            setup: lines_setup,
            frame: lines_frame,
        },
        Knob {
            id: "point_smooth",
            title: "Point smoothing",
            what: "A grid of 5-pixel points, aliased and with GL_POINT_SMOOTH and blending.",
            settings: &["aliased", "smooth"],
            best: 0,
            setup: points_setup,
            frame: points_frame,
        },
        Knob {
            id: "accum_aa",
            title: "Accumulation-buffer antialiasing",
            what: "Thin triangles drawn N times with sub-pixel jitter and averaged with glAccum.",
            settings: &["1 pass", "2", "4", "8", "16"],
            best: 4,
            setup: accum_setup,
            frame: accum_aa_frame,
        },
        Knob {
            id: "motion_blur",
            title: "Accumulation-buffer motion blur",
            what: "A moving square sampled at N instants and averaged with glAccum.",
            settings: &["1 pass", "2", "4", "8", "16"],
            best: 4,
            setup: accum_setup,
            frame: motion_blur_frame,
        },
    ]
}

// ------------------------------------------------------------------ measuring

fn draw_frame(gl: &mut dyn Gl, knob: &Knob, s: usize) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);
    (knob.frame)(gl, s);
    gl.finish();
}

/// Times frames of `knob` at `s` on `gl` (a fresh `size` x `size` context) for at least
/// `min_time` and 3 frames; returns the median ms and the last picture.
fn time_frames(
    gl: &mut dyn Gl,
    knob: &Knob,
    s: usize,
    size: i32,
    min_time: Duration,
) -> (f64, Image) {
    gl.clear_color(0.05, 0.05, 0.1, 1.0);
    (knob.setup)(gl, s);
    draw_frame(gl, knob, s); // warm-up: texture uploads, first snapshots
    let mut times = Vec::new();
    let start = Instant::now();
    while times.len() < 3 || (start.elapsed() < min_time && times.len() < 200) {
        let t = Instant::now();
        draw_frame(gl, knob, s);
        times.push(t.elapsed().as_secs_f64() * 1000.0);
    }
    times.sort_by(f64::total_cmp);
    (times[times.len() / 2], Image::read(gl, size, size))
}

pub(crate) fn tilegl_context(size: i32, threads: usize) -> Context {
    crate::client_context(ContextConfig {
        width: size,
        height: size,
        framebuffer: FramebufferConfig {
            accum_bits: 16,
            ..FramebufferConfig::default()
        },
        threads,
    })
}

/// Box-filters `img` down by `f` in each direction.
pub fn downsample(img: &Image, f: i32) -> Image {
    let (w, h) = (img.width / f, img.height / f);
    let mut pixels = Vec::with_capacity((w * h * 4) as usize);
    for y in 0..h {
        for x in 0..w {
            for c in 0..4 {
                let mut s = 0u32;
                for dy in 0..f {
                    for dx in 0..f {
                        s += img.pixels[(((y * f + dy) * img.width + x * f + dx) * 4 + c) as usize]
                            as u32;
                    }
                }
                pixels.push(((s + (f * f / 2) as u32) / (f * f) as u32) as u8);
            }
        }
    }
    Image {
        width: w,
        height: h,
        pixels,
    }
}

/// The reference: the best setting at 4x4 the size on tilegl, box-filtered down. Pixel-space
/// scenes are scaled with the projection so they cover the same area.
fn reference(knob: &Knob) -> Image {
    let big = SIZE * 4;
    let mut ctx = tilegl_context(big, 0);
    ctx.clear_color(0.05, 0.05, 0.1, 1.0);
    (knob.setup)(&mut ctx, knob.best);
    // The scenes draw in a SIZE x SIZE pixel space or a perspective; the larger viewport
    // keeps the same picture. Line widths and point sizes scale with the pixels.
    ctx.viewport(0, 0, big, big);
    let mut width = [1.0f32; 1];
    ctx.get_floatv(GL_LINE_WIDTH, &mut width);
    ctx.line_width(width[0] * 4.0);
    let mut size = [1.0f32; 1];
    ctx.get_floatv(GL_POINT_SIZE, &mut size);
    ctx.point_size(size[0] * 4.0);
    draw_frame(&mut ctx, knob, knob.best);
    downsample(&Image::read(&mut ctx, big, big), 4)
}

/// Measures every setting of `knob` on tilegl (default threads) and, when `with_mesa`, on
/// Mesa llvmpipe in this process.
pub fn measure(knob: &Knob, min_time: Duration, with_mesa: bool) -> KnobResult {
    let reference = reference(knob);
    let point = |setting, ms: f64, img: &Image| {
        let d = diff(img, &reference, 8);
        Point {
            setting,
            ms,
            mean_error: d.mean,
            psnr: d.psnr,
        }
    };
    let mut tilegl = Vec::new();
    let mut llvmpipe = Vec::new();
    for (s, &setting) in knob.settings.iter().enumerate() {
        let mut ctx = tilegl_context(SIZE, 0);
        let (ms, img) = time_frames(&mut ctx, knob, s, SIZE, min_time);
        tilegl.push(point(setting, ms, &img));
        if with_mesa {
            if let Ok(mut m) = MesaContext::create(SIZE, SIZE) {
                let (ms, img) = time_frames(&mut *m, knob, s, SIZE, min_time);
                llvmpipe.push(point(setting, ms, &img));
            }
        }
    }
    KnobResult {
        id: knob.id,
        title: knob.title,
        what: knob.what,
        tilegl,
        llvmpipe,
    }
}

// ------------------------------------------------------------------ output

/// Where the chart font comes from (Debian package fonts-dejavu-core).
pub const FONT: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

pub(crate) fn register_font() -> Result<(), String> {
    use std::sync::OnceLock;
    static DONE: OnceLock<Result<(), String>> = OnceLock::new();
    DONE.get_or_init(|| {
        let bytes = std::fs::read(FONT)
            .map_err(|e| format!("chart font {FONT} (Debian package fonts-dejavu-core): {e}"))?;
        let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
        plotters::style::register_font("sans-serif", FontStyle::Normal, bytes)
            .map_err(|_| format!("{FONT} is not a usable TrueType font"))
    })
    .clone()
}

/// Draws the chart of `r` into `path` (PNG, 900x560): mean error (y) against ms per frame
/// (x), a labelled point per setting, tilegl and llvmpipe as two series.
pub fn chart(r: &KnobResult, path: &Path) -> Result<(), String> {
    register_font()?;
    let e = |e: &dyn std::fmt::Display| e.to_string();
    let all: Vec<&Point> = r.tilegl.iter().chain(&r.llvmpipe).collect();
    let max_ms = all.iter().map(|p| p.ms).fold(0.1, f64::max) * 1.5;
    let min_ms = all
        .iter()
        .map(|p| p.ms)
        .fold(f64::INFINITY, f64::min)
        .min(max_ms / 10.0)
        / 1.5;
    // Headroom above the highest point for the legend.
    let max_err = all.iter().map(|p| p.mean_error).fold(0.1, f64::max) * 1.5;
    let root = BitMapBackend::new(path, (900, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let mut c = ChartBuilder::on(&root)
        .caption(r.title, ("sans-serif", 24))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(64)
        .build_cartesian_2d((min_ms..max_ms).log_scale(), 0.0..max_err)
        .map_err(|x| e(&x))?;
    c.configure_mesh()
        .x_desc("time per frame (ms, 256x256, median; logarithmic)")
        .x_label_formatter(&|v| {
            let s = format!("{v:.3}");
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        })
        .y_desc("mean error vs 4x4-supersampled reference (0-255)")
        .axis_desc_style(("sans-serif", 16))
        .draw()
        .map_err(|x| e(&x))?;
    // tilegl's labels above their points, Mesa's below, so close points stay readable.
    for (points, colour, name, dy) in [
        (&r.tilegl, BLUE, "tilegl", -16),
        (&r.llvmpipe, RED, "Mesa llvmpipe", 4),
    ] {
        if points.is_empty() {
            continue;
        }
        c.draw_series(points.iter().map(|p| {
            EmptyElement::at((p.ms, p.mean_error))
                + Circle::new((0, 0), 5, colour.filled())
                + Text::new(
                    p.setting.to_string(),
                    (7, dy),
                    ("sans-serif", 13).into_font().color(&colour),
                )
        }))
        .map_err(|x| e(&x))?
        .label(name)
        .legend(move |(x, y)| Circle::new((x + 10, y), 5, colour.filled()));
    }
    c.configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .label_font(("sans-serif", 15))
        .draw()
        .map_err(|x| e(&x))?;
    root.present().map_err(|x| e(&x))
}

/// Measures `knobs` (all when empty: ids), writes `DIR/quality-ID.png` charts and
/// `DIR/quality.html` (each chart with its table). Returns the page.
pub fn write_quality(
    dir: &Path,
    only: &[&str],
    min_time: Duration,
    with_mesa: bool,
) -> Result<(PathBuf, Vec<KnobResult>), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut results = Vec::new();
    let mut h = String::from("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>tilegl: error against run time</title><style>body{font-family:sans-serif;margin:1em}table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 6px;font-size:13px}td.num{text-align:right}</style></head><body>\n<h1>Error against run time for every quality knob</h1>\n<p>Each knob's scene is drawn at 256x256 under each setting on tilegl and on Mesa llvmpipe; the time is the median per frame, the error the mean absolute channel difference (and PSNR) from one reference: the best setting drawn by tilegl at 1024x1024 and box-filtered down.</p>\n");
    for knob in knobs()
        .iter()
        .filter(|k| only.is_empty() || only.contains(&k.id))
    {
        eprintln!("quality: {}", knob.title);
        let r = measure(knob, min_time, with_mesa);
        let png = format!("quality-{}.png", r.id);
        chart(&r, &dir.join(&png))?;
        let _ = writeln!(h, "<h2>{}</h2>\n<p>{}</p>\n<img src=\"{png}\" alt=\"{}\" width=\"900\">\n<table><tr><th>setting</th><th>tilegl ms</th><th>tilegl mean error</th><th>tilegl PSNR dB</th><th>llvmpipe ms</th><th>llvmpipe mean error</th><th>llvmpipe PSNR dB</th></tr>", r.title, r.what, r.title);
        for (i, t) in r.tilegl.iter().enumerate() {
            let m = r.llvmpipe.get(i);
            let f = |v: Option<f64>, d: usize| {
                v.map_or("-".to_string(), |v| {
                    if v.is_infinite() {
                        "inf".into()
                    } else {
                        format!("{v:.d$}")
                    }
                })
            };
            let _ = writeln!(
                h,
                "<tr><td>{}</td><td class=num>{:.2}</td><td class=num>{:.3}</td><td class=num>{}</td><td class=num>{}</td><td class=num>{}</td><td class=num>{}</td></tr>",
                t.setting,
                t.ms,
                t.mean_error,
                f(Some(t.psnr), 2),
                f(m.map(|m| m.ms), 2),
                f(m.map(|m| m.mean_error), 3),
                f(m.map(|m| m.psnr), 2)
            );
        }
        h.push_str("</table>\n");
        results.push(r);
    }
    h.push_str("</body></html>\n");
    let page = dir.join("quality.html");
    std::fs::write(&page, h).map_err(|e| format!("{}: {e}", page.display()))?;
    Ok((page, results))
}

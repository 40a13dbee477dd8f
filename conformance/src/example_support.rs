//! Shared code of the teaching examples in the top-level `examples/` folder (built as examples
//! of this crate, which has both tilegl and the Mesa oracle).
//!
//! An example names one or more scenes of [`crate::scenes_examples`]; [`run`] renders each on
//! tilegl and on Mesa (OSMesa, llvmpipe by default), writes the pictures as PNG files into
//! `out/EXAMPLE/`, prints how far they differ and how long each side took, and, where Mesa's
//! other software driver (softpipe) is installed, how far the two Mesa drivers differ on the
//! same calls (the spread two conformant drivers show).
//!
//! Scenes mark their intermediate stages with the `snap_*` functions (a pass of a multipass
//! technique, a texture the scene built, the shadow map's depth, the stencil mask). In the
//! differential tests nothing is recording and the calls do nothing; in an example every stage
//! is read back (with `glReadPixels` / `glGetTexImage`, which change no rendering state) and
//! written next to the final picture, for both implementations.

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use tilegl::enums::*;
use tilegl::Gl;

use crate::compare::{self, diff, Image, Scene};
use crate::mesa::{self, MesaContext, Oracle};
use crate::scenes::{find, SCENES};

/// One intermediate picture of a scene.
#[derive(Clone, Debug)]
pub struct Stage {
    pub name: String,
    pub image: Image,
}

thread_local! {
    static RECORDER: RefCell<Option<Vec<Stage>>> = const { RefCell::new(None) };
    static FRAME_SCALE: std::cell::Cell<(f64, f64)> = const { std::cell::Cell::new((1.0, 1.0)) };
}

/// Runs `f` (which draws a scene) with the scene's window regions scaled by `sx` x `sy`: the
/// gallery renders a scene at another size than its own this way. Viewports and scissor boxes
/// the scene sets through [`viewport`] and [`scissor`] cover the same share of the window;
/// passes that render into a texture keep their own size.
pub fn with_frame_scale<R>(sx: f64, sy: f64, f: impl FnOnce() -> R) -> R {
    let before = FRAME_SCALE.with(|s| s.replace((sx, sy)));
    let out = f();
    FRAME_SCALE.with(|s| s.set(before));
    out
}

/// A window rectangle scaled by the frame scale (unchanged at the scene's own size): corners
/// rounded to the nearest pixel, so neighbouring panels still tile the window.
fn scaled(x: i32, y: i32, w: i32, h: i32) -> (i32, i32, i32, i32) {
    let (sx, sy) = FRAME_SCALE.with(|s| s.get());
    let fx = |v: i32| (v as f64 * sx).round() as i32;
    let fy = |v: i32| (v as f64 * sy).round() as i32;
    (fx(x), fy(y), fx(x + w) - fx(x), fy(y + h) - fy(y))
}

/// `glViewport` of a region of the scene's window (scaled with the frame, see
/// [`with_frame_scale`]).
pub fn viewport(gl: &mut dyn Gl, x: i32, y: i32, w: i32, h: i32) {
    let (x, y, w, h) = scaled(x, y, w, h);
    gl.viewport(x, y, w, h);
}

/// `glScissor` of a region of the scene's window (scaled with the frame).
pub fn scissor(gl: &mut dyn Gl, x: i32, y: i32, w: i32, h: i32) {
    let (x, y, w, h) = scaled(x, y, w, h);
    gl.scissor(x, y, w, h);
}

fn recording() -> bool {
    RECORDER.with(|r| r.borrow().is_some())
}

fn push(name: &str, image: Image) {
    RECORDER.with(|r| {
        if let Some(v) = r.borrow_mut().as_mut() {
            v.push(Stage {
                name: name.to_string(),
                image,
            });
        }
    });
}

/// Runs `f` with stage recording on and returns the stages it snapped.
pub fn record<R>(f: impl FnOnce() -> R) -> (R, Vec<Stage>) {
    RECORDER.with(|r| *r.borrow_mut() = Some(Vec::new()));
    let out = f();
    let stages = RECORDER.with(|r| r.borrow_mut().take()).unwrap_or_default();
    (out, stages)
}

thread_local! {
    static UNIT_LIMIT: std::cell::Cell<Option<usize>> = const { std::cell::Cell::new(None) };
}

/// Whether a multitexture scene should enable texture unit `unit` (0-based). Always true,
/// except inside [`with_units`], which limits the cascade to its first units: the stage view
/// of a multitexture scene renders it with units `0..k` enabled for each `k`, so each picture
/// shows the output of unit `k - 1` of the cascade.
pub fn unit_on(unit: usize) -> bool {
    UNIT_LIMIT.with(|l| l.get().is_none_or(|n| unit < n))
}

/// Runs `f` with only the first `units` texture units of the scenes' cascades enabled (see
/// [`unit_on`]).
pub fn with_units<R>(units: usize, f: impl FnOnce() -> R) -> R {
    let old = UNIT_LIMIT.with(|l| l.replace(Some(units)));
    let out = f();
    UNIT_LIMIT.with(|l| l.set(old));
    out
}

/// Snaps the colour buffer (`w` x `h` from the origin).
pub fn snap_color(gl: &mut dyn Gl, name: &str, w: i32, h: i32) {
    if recording() {
        push(name, Image::read(gl, w, h));
    }
}

/// Maps values in 0..1 to a grey picture, stretching `lo..hi` to the full range so a depth
/// buffer's small differences become visible.
fn grey(values: &[f32], w: i32, h: i32, stretch: bool) -> Image {
    let (mut lo, mut hi) = (f32::MAX, f32::MIN);
    for &v in values {
        if v < 1.0 {
            lo = lo.min(v);
            hi = hi.max(v);
        }
    }
    if !stretch || hi <= lo {
        (lo, hi) = (0.0, 1.0);
    }
    let mut pixels = Vec::with_capacity(values.len() * 4);
    for &v in values {
        let g = if v >= 1.0 && stretch {
            255
        } else {
            (((v - lo) / (hi - lo)).clamp(0.0, 1.0) * 255.0).round() as u8
        };
        pixels.extend_from_slice(&[g, g, g, 255]);
    }
    Image {
        width: w,
        height: h,
        pixels,
    }
}

/// Snaps the depth buffer as a grey picture (the depths in use stretched to black..white; the
/// cleared far value stays white).
pub fn snap_depth(gl: &mut dyn Gl, name: &str, w: i32, h: i32) {
    if recording() {
        let mut bytes = vec![0u8; (w * h * 4) as usize];
        gl.read_pixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, &mut bytes);
        let v: Vec<f32> = bytes
            .chunks(4)
            .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
            .collect();
        push(name, grey(&v, w, h, true));
    }
}

/// Snaps the stencil buffer: value 0 black, every other value a bright colour.
pub fn snap_stencil(gl: &mut dyn Gl, name: &str, w: i32, h: i32) {
    if recording() {
        let mut bytes = vec![0u8; (w * h * 4) as usize];
        gl.read_pixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_INT, &mut bytes);
        let mut pixels = Vec::with_capacity((w * h * 4) as usize);
        for c in bytes.chunks(4) {
            let s = u32::from_le_bytes([c[0], c[1], c[2], c[3]]);
            let v = if s == 0 {
                0
            } else {
                96 + (s.min(5) * 32) as u8
            };
            pixels.extend_from_slice(&[v, v / 2, 0, 255]);
        }
        push(
            name,
            Image {
                width: w,
                height: h,
                pixels,
            },
        );
    }
}

/// Snaps level `level` of the texture bound to `target` on the active unit (`target` may be a
/// cube-map face). `depth` > 1 (3D textures) lays the slices out side by side. Depth textures
/// are read as `GL_DEPTH_COMPONENT` and shown in grey.
pub fn snap_texture(gl: &mut dyn Gl, name: &str, target: GLenum, level: i32, size: [i32; 3]) {
    if !recording() {
        return;
    }
    let [w, h, d] = size;
    let n = (w * h * d) as usize;
    let mut bytes = vec![0u8; n * 4];
    let mut q = [0i32];
    gl.get_tex_level_parameteriv(target, level, GL_TEXTURE_INTERNAL_FORMAT, &mut q);
    let fmt = q[0];
    let fmt = fmt as GLenum;
    let is = |list: &[GLenum]| list.contains(&fmt);
    let floats = |bytes: &[u8]| -> Vec<f32> {
        bytes
            .chunks(4)
            .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
            .collect()
    };
    let image = if is(&[
        GL_DEPTH_COMPONENT,
        GL_DEPTH_COMPONENT16,
        GL_DEPTH_COMPONENT24,
        GL_DEPTH_COMPONENT32,
    ]) {
        gl.get_tex_image(target, level, GL_DEPTH_COMPONENT, GL_FLOAT, &mut bytes);
        grey(&floats(&bytes), w, h * d, true)
    } else if is(&[
        GL_LUMINANCE,
        GL_LUMINANCE4,
        GL_LUMINANCE8,
        GL_LUMINANCE12,
        GL_LUMINANCE16,
        GL_INTENSITY,
        GL_INTENSITY4,
        GL_INTENSITY8,
        GL_INTENSITY12,
        GL_INTENSITY16,
        GL_ALPHA,
        GL_ALPHA4,
        GL_ALPHA8,
        GL_ALPHA12,
        GL_ALPHA16,
    ]) {
        // One-channel textures: read that channel as floats and show it in grey (read as RGBA
        // they would come back as (L, 0, 0, 1) or (0, 0, 0, A), GL 1.5 section 6.1.4).
        let alpha = is(&[GL_ALPHA, GL_ALPHA4, GL_ALPHA8, GL_ALPHA12, GL_ALPHA16]);
        let format = if alpha { GL_ALPHA } else { GL_LUMINANCE };
        gl.get_tex_image(target, level, format, GL_FLOAT, &mut bytes);
        grey(&floats(&bytes), w, h * d, false)
    } else {
        gl.get_tex_image(target, level, GL_RGBA, GL_UNSIGNED_BYTE, &mut bytes);
        Image {
            width: w,
            height: h * d,
            pixels: bytes,
        }
    };
    // Slices of a 3D texture: stacked bottom-up as read; lay them out in a row instead.
    let image = if d > 1 {
        let mut pixels = vec![0u8; n * 4];
        for z in 0..d {
            for y in 0..h {
                for x in 0..w {
                    let src = (((z * h + y) * w + x) * 4) as usize;
                    let dst = ((y * w * d + z * w + x) * 4) as usize;
                    pixels[dst..dst + 4].copy_from_slice(&image.pixels[src..src + 4]);
                }
            }
        }
        Image {
            width: w * d,
            height: h,
            pixels,
        }
    } else {
        image
    };
    push(name, image);
}

/// Writes an RGBA picture (rows bottom-up, as read back) as a PNG. Alpha is written as is;
/// `opaque` forces it to 255 (colour buffers whose alpha is not meant to be seen).
pub fn write_png(image: &Image, path: &Path, opaque: bool) -> Result<(), image::ImageError> {
    let (w, h) = (image.width.max(0) as u32, image.height.max(0) as u32);
    let mut out = image::RgbaImage::new(w, h);
    for y in 0..image.height {
        for x in 0..image.width {
            let mut p = image.pixel(x, y);
            if opaque {
                p[3] = 255;
            }
            out.put_pixel(x as u32, (image.height - 1 - y) as u32, image::Rgba(p));
        }
    }
    out.save(path)
}

/// The per-channel difference of two pictures, multiplied by 8 so small differences show.
pub fn diff_image(a: &Image, b: &Image) -> Image {
    let pixels = a
        .pixels
        .chunks(4)
        .zip(b.pixels.chunks(4))
        .flat_map(|(p, q)| {
            let d = |c: usize| (p[c].abs_diff(q[c]) as u32 * 8).min(255) as u8;
            let m = d(3);
            [d(0).max(m), d(1).max(m), d(2).max(m), 255]
        })
        .collect();
    Image {
        width: a.width,
        height: a.height,
        pixels,
    }
}

/// One implementation's run of a scene: the picture, the stages, the `glGetError` result and
/// the time the GL calls took (best of a few runs, each on a fresh context, up to `glFinish`;
/// it includes the scene's own CPU work such as building procedural textures, the same on both
/// sides, and on Mesa llvmpipe's shader compilation for each new state).
pub struct Run {
    pub image: Image,
    pub stages: Vec<Stage>,
    pub error: GLenum,
    pub time: Duration,
}

const TIMED_RUNS: usize = 3;

fn timed(gl: &mut dyn Gl, scene: &Scene) -> Duration {
    let start = Instant::now();
    (scene.draw)(gl);
    gl.finish();
    start.elapsed()
}

/// Renders `scene` on tilegl: timed runs on fresh contexts, then one recording run.
pub fn run_tilegl(scene: &Scene) -> Run {
    let mut time = Duration::MAX;
    for _ in 0..TIMED_RUNS {
        let mut ctx = crate::client_context(tilegl::ContextConfig {
            width: scene.width,
            height: scene.height,
            ..Default::default()
        });
        time = time.min(timed(&mut ctx, scene));
    }
    let (r, stages) = record(|| compare::render_tilegl(scene));
    Run {
        image: r.image,
        stages,
        error: r.error,
        time,
    }
}

/// Renders `scene` on Mesa, as [`run_tilegl`].
pub fn run_mesa(scene: &Scene) -> Result<(Run, String), mesa::OracleError> {
    let mut time = Duration::MAX;
    for _ in 0..TIMED_RUNS {
        let mut m = MesaContext::create(scene.width, scene.height)?;
        time = time.min(timed(&mut *m, scene));
    }
    let (r, stages) = record(|| compare::render_mesa(scene));
    let (r, info) = r?;
    Ok((
        Run {
            image: r.image,
            stages,
            error: r.error,
            time,
        },
        info.to_string(),
    ))
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1000.0
}

fn file_name(stem: &str, prefix: &str, side: &str) -> String {
    if prefix.is_empty() {
        format!("{stem}{side}.png")
    } else {
        format!("{prefix}-{stem}{side}.png")
    }
}

/// Renders the named scenes on tilegl and Mesa, writes `out/EXAMPLE/` and prints the figures.
/// With one scene the files are `tilegl.png`, `mesa.png`, `diff.png` and `stageNN-NAME-*.png`;
/// with several, each name is prefixed with the scene's name. Call it first thing in `main`: it
/// also serves the child process that renders with softpipe.
pub fn run(example: &str, scenes: &[&str]) {
    if compare::serve_child_request(&SCENES) {
        return;
    }
    let dir = std::env::args_os()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("out").join(example));
    if let Err(e) = std::fs::create_dir_all(&dir) {
        eprintln!("{example}: cannot create {}: {e}", dir.display());
        std::process::exit(1);
    }
    let mesa_ok = match mesa::mesa_available() {
        Ok(()) => true,
        Err(e) => {
            println!("Mesa not available ({e}): rendering with tilegl only");
            false
        }
    };
    let write = |img: &Image, name: String, opaque: bool| {
        let path = dir.join(name);
        match write_png(img, &path, opaque) {
            Ok(()) => println!("  wrote {}", path.display()),
            Err(e) => eprintln!("  cannot write {}: {e}", path.display()),
        }
    };
    for &name in scenes {
        let Some(scene) = find(name) else {
            eprintln!("{example}: no scene {name}");
            std::process::exit(2);
        };
        let prefix = if scenes.len() == 1 { "" } else { name };
        println!(
            "{name} ({}x{}, tolerance {}):",
            scene.width, scene.height, scene.tolerance
        );
        let t = run_tilegl(scene);
        println!(
            "  tilegl {:8.2} ms   glGetError 0x{:04x}",
            ms(t.time),
            t.error
        );
        write(&t.image, file_name("tilegl", prefix, ""), true);
        for (i, s) in t.stages.iter().enumerate() {
            write(
                &s.image,
                file_name(&format!("stage{:02}-{}", i + 1, s.name), prefix, "-tilegl"),
                false,
            );
        }
        if !mesa_ok {
            continue;
        }
        let (m, renderer) = match run_mesa(scene) {
            Ok(x) => x,
            Err(e) => {
                println!("  Mesa failed: {e}");
                continue;
            }
        };
        println!(
            "  mesa   {:8.2} ms   glGetError 0x{:04x}   ({renderer})",
            ms(m.time),
            m.error
        );
        write(&m.image, file_name("mesa", prefix, ""), true);
        write(
            &diff_image(&t.image, &m.image),
            file_name("diff", prefix, ""),
            true,
        );
        for (i, s) in m.stages.iter().enumerate() {
            write(
                &s.image,
                file_name(&format!("stage{:02}-{}", i + 1, s.name), prefix, "-mesa"),
                false,
            );
        }
        let d = diff(&t.image, &m.image, scene.tolerance.channel);
        println!(
            "  tilegl vs Mesa: {d} -> {}",
            if scene.tolerance.accepts(&d) && t.error == m.error {
                "within tolerance"
            } else {
                "OUTSIDE tolerance"
            }
        );
        for (a, b) in t.stages.iter().zip(&m.stages) {
            println!(
                "    stage {:<24} {}",
                a.name,
                diff(&a.image, &b.image, scene.tolerance.channel)
            );
        }
        if renderer.contains("llvmpipe") {
            match compare::render_scene_with_driver("softpipe", scene, &[]) {
                Ok((soft, _)) => println!(
                    "  llvmpipe vs softpipe (two Mesa drivers): {}",
                    diff(&m.image, &soft, scene.tolerance.channel)
                ),
                Err(e) => println!("  (softpipe not available: {e})"),
            }
        }
        println!(
            "  error against run time: tilegl {:.2} ms, Mesa {:.2} ms, PSNR {:.2} dB \
             (fresh context per run: Mesa's time includes llvmpipe compiling its shaders)",
            ms(t.time),
            ms(m.time),
            d.psnr
        );
    }
}

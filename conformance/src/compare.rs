//! Running one scene on tilegl and on Mesa, reading both back and measuring the difference.

use std::fmt;
use std::path::{Path, PathBuf};

use tilegl::enums::*;
use tilegl::{ContextConfig, FramebufferConfig, Gl};

use crate::c_route::CAbiContext;
use crate::mesa::{self, MesaContext, Oracle, OracleError, OracleInfo};
use crate::tolerance::Tolerance;

/// A scene: a fixed framebuffer size and the GL calls that draw it, written against the `Gl`
/// trait so it runs on every implementation.
#[derive(Clone, Copy)]
pub struct Scene {
    /// Unique name (also the test name and the known-failures key).
    pub name: &'static str,
    pub width: i32,
    pub height: i32,
    /// The GL calls. The framebuffer starts in the default state of a new context.
    pub draw: fn(&mut dyn Gl),
    /// When the picture matches: `tolerance::DIFFERENTIAL`, or, for scenes where llvmpipe and
    /// softpipe themselves differ more (texture filtering), that measured spread.
    pub tolerance: crate::tolerance::Tolerance,
}

impl Scene {
    /// What the report should show next to this scene's figures beyond pass or fail: why its
    /// picture differs from Mesa's and which answer is exact
    /// ([`crate::scenes_extremes::NOTES`]).
    pub fn note(&self) -> Option<&'static str> {
        crate::scenes_extremes::note(self.name)
    }
}

impl fmt::Debug for Scene {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Scene({} {}x{})", self.name, self.width, self.height)
    }
}

/// An RGBA8 picture as `glReadPixels` returns it: rows bottom-up.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    pub width: i32,
    pub height: i32,
    pub pixels: Vec<u8>,
}

const IMAGE_MAGIC: &[u8; 8] = b"TGLRGBA1";

impl Image {
    /// Reads the whole `width` x `height` colour buffer with `glReadPixels(GL_RGBA,
    /// GL_UNSIGNED_BYTE)` (pack alignment 4 is fine for RGBA8).
    pub fn read(gl: &mut dyn Gl, width: i32, height: i32) -> Image {
        let mut pixels = vec![0u8; width.max(0) as usize * height.max(0) as usize * 4];
        gl.read_pixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, &mut pixels);
        Image {
            width,
            height,
            pixels,
        }
    }

    /// The RGBA value at (x, y), y counted from the bottom.
    pub fn pixel(&self, x: i32, y: i32) -> [u8; 4] {
        let i = ((y * self.width + x) * 4) as usize;
        [
            self.pixels[i],
            self.pixels[i + 1],
            self.pixels[i + 2],
            self.pixels[i + 3],
        ]
    }

    /// Serialises to a small raw format (magic, width, height, RGBA bytes).
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(16 + self.pixels.len());
        out.extend_from_slice(IMAGE_MAGIC);
        out.extend_from_slice(&(self.width as u32).to_le_bytes());
        out.extend_from_slice(&(self.height as u32).to_le_bytes());
        out.extend_from_slice(&self.pixels);
        out
    }

    /// Parses [`Image::to_bytes`] output.
    pub fn from_bytes(b: &[u8]) -> Option<Image> {
        if b.len() < 16 || &b[..8] != IMAGE_MAGIC {
            return None;
        }
        let width = u32::from_le_bytes(b[8..12].try_into().ok()?) as i32;
        let height = u32::from_le_bytes(b[12..16].try_into().ok()?) as i32;
        let pixels = b[16..].to_vec();
        (pixels.len() == width as usize * height as usize * 4).then_some(Image {
            width,
            height,
            pixels,
        })
    }

    /// Writes a binary PPM (RGB, top-down) for looking at a failure.
    pub fn write_ppm(&self, path: &Path) -> std::io::Result<()> {
        let mut out = format!("P6\n{} {}\n255\n", self.width, self.height).into_bytes();
        for y in (0..self.height).rev() {
            for x in 0..self.width {
                out.extend_from_slice(&self.pixel(x, y)[..3]);
            }
        }
        std::fs::write(path, out)
    }
}

pub use tilegl::compare::Diff;

/// Compares two pictures of the same size over all four channels (R, G, B, A); `threshold` is
/// the per-channel difference above which a pixel counts as bad. Pictures of different sizes
/// compare as totally different.
pub fn diff(a: &Image, b: &Image, threshold: u8) -> Diff {
    if a.width != b.width || a.height != b.height || a.pixels.len() != b.pixels.len() {
        return Diff::total(
            a.width.max(b.width).max(0) as u32,
            a.height.max(b.height).max(0) as u32,
            threshold,
        );
    }
    tilegl::compare::diff_pixels(&a.pixels, &b.pixels, 4, a.width.max(1) as u32, threshold)
}

/// A picture plus the error state GL reported after drawing it.
#[derive(Clone, Debug)]
pub struct Rendered {
    pub image: Image,
    /// `glGetError` right after the scene (before the read-back).
    pub error: GLenum,
}

/// Runs a scene on any `Gl` implementation with a framebuffer of the scene's size.
pub fn run_scene(gl: &mut dyn Gl, scene: &Scene) -> Rendered {
    (scene.draw)(gl);
    let error = gl.get_error();
    gl.finish();
    let image = Image::read(gl, scene.width, scene.height);
    Rendered { image, error }
}

/// Renders a scene on a fresh tilegl context.
pub fn render_tilegl(scene: &Scene) -> Rendered {
    render_tilegl_with_threads(scene, 0)
}

/// Renders a scene on a fresh tilegl context shading with `threads` threads (0: one per core).
pub fn render_tilegl_with_threads(scene: &Scene, threads: usize) -> Rendered {
    // The same buffers as the Mesa side: 24 depth, 8 stencil, 16 accumulation bits.
    let mut ctx = crate::client_context(ContextConfig {
        width: scene.width,
        height: scene.height,
        framebuffer: FramebufferConfig {
            accum_bits: 16,
            ..FramebufferConfig::default()
        },
        threads,
    });
    run_scene(&mut ctx, scene)
}

/// Renders a scene on a fresh tilegl context reached through the C ABI (the exported OSMesa
/// and `gl*` functions, [`crate::c_route`]), with the buffers [`render_tilegl`] uses.
pub fn render_c_abi(scene: &Scene) -> Rendered {
    let mut c = CAbiContext::create(scene.width, scene.height, 16).unwrap_or_else(|| {
        panic!(
            "{}: the C ABI refused a {}x{} context",
            scene.name, scene.width, scene.height
        )
    });
    run_scene(&mut *c, scene)
}

/// Asserts that the C ABI route gives exactly the Rust route's picture and error for `scene`
/// (`rust` is the Rust route's result). Any difference is a defect of the C ABI: the two run
/// the same renderer on the same calls.
pub fn assert_c_abi_matches(scene: &Scene, rust: &Rendered) {
    let c = render_c_abi(scene);
    assert_eq!(
        c.error, rust.error,
        "{}: glGetError through the C ABI 0x{:04x}, through the Rust API 0x{:04x}",
        scene.name, c.error, rust.error
    );
    if c.image != rust.image {
        let d = diff(&c.image, &rust.image, 0);
        panic!(
            "{}: the C ABI's picture differs from the Rust API's: {d}",
            scene.name
        );
    }
}

/// Renders a scene on a fresh Mesa context of this process (its driver is whatever
/// `GALLIUM_DRIVER` selected at the first context creation).
pub fn render_mesa(scene: &Scene) -> Result<(Rendered, OracleInfo), OracleError> {
    render_mesa_with_clear(scene).map(|(r, info, _)| (r, info))
}

/// [`render_mesa`], plus Mesa's clear colour after the scene (`GL_COLOR_CLEAR_VALUE`, 8-bit).
fn render_mesa_with_clear(scene: &Scene) -> Result<(Rendered, OracleInfo, [u8; 4]), OracleError> {
    let mut mesa = MesaContext::create(scene.width, scene.height)?;
    let r = run_scene(&mut *mesa, scene);
    let mut clear = [0f32; 4];
    mesa.get_floatv(GL_COLOR_CLEAR_VALUE, &mut clear);
    let _ = mesa.get_error();
    let clear = clear.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
    Ok((r, mesa.info().clone(), clear))
}

/// Scenes whose right picture is one colour: the clear colour (or black) because nothing may
/// be drawn. Every other scene must show Mesa drawing something ([`mesa_drew_nothing`]), so
/// that an oracle that silently draws nothing (a broken driver, a lost context) cannot make
/// a scene pass on a tilegl that draws nothing too. Each entry says why nothing is drawn.
pub const DRAWS_NOTHING: &[(&str, &str)] = &[];

/// Why Mesa's picture of `scene` cannot be trusted, if it cannot: the picture is one colour,
/// black or Mesa's clear colour `clear`, and the scene is not one of [`DRAWS_NOTHING`]; or it
/// is listed there and Mesa drew something after all (the list must stay true).
pub fn mesa_drew_nothing(scene: &str, mesa: &Image, clear: [u8; 4]) -> Option<String> {
    let empty = tilegl::compare::uniform_colour(&mesa.pixels, 4)
        .filter(|c| c[..3] == [0, 0, 0] || tilegl::compare::same_colour(c, &clear))
        .map(|c| c.to_vec());
    let listed = DRAWS_NOTHING.iter().any(|(n, _)| *n == scene);
    match (empty, listed) {
        (Some(c), false) => Some(format!(
            "Mesa drew nothing: every pixel of its picture is {c:?} (black or its clear \
             colour); list the scene in compare::DRAWS_NOTHING if that is the right picture"
        )),
        (None, true) => Some(
            "listed in compare::DRAWS_NOTHING but Mesa drew something: remove it from the list"
                .to_string(),
        ),
        _ => None,
    }
}

const CHILD_SCENE_ENV: &str = "TILEGL_CHILD_SCENE";
const CHILD_OUT_ENV: &str = "TILEGL_CHILD_OUT";

/// In a child started by [`render_scene_with_driver`], renders the requested scene with Mesa,
/// writes it where the parent expects it and returns `true` (the caller should then return
/// without doing anything else). Returns `false` in a normal run.
pub fn serve_child_request(scenes: &[Scene]) -> bool {
    if !mesa::is_oracle_child() {
        return false;
    }
    let (Ok(name), Ok(out)) = (std::env::var(CHILD_SCENE_ENV), std::env::var(CHILD_OUT_ENV)) else {
        return false;
    };
    let Some(scene) = scenes.iter().find(|s| s.name == name) else {
        return false;
    };
    match render_mesa(scene) {
        Ok((r, info)) => {
            let bytes = r.image.to_bytes();
            if let Err(e) = std::fs::write(&out, bytes) {
                eprintln!("child: cannot write {out}: {e}");
                std::process::exit(3);
            }
            println!("TILEGL_CHILD_RENDERER={}", info.renderer);
        }
        Err(e) => {
            eprintln!("child: {e}");
            std::process::exit(2);
        }
    }
    true
}

fn temp_path(tag: &str) -> PathBuf {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static N: AtomicUsize = AtomicUsize::new(0);
    std::env::temp_dir().join(format!(
        "tilegl-oracle-{}-{}-{}.raw",
        std::process::id(),
        N.fetch_add(1, Ordering::Relaxed),
        tag
    ))
}

/// Renders `scene` with Mesa under another Gallium driver by re-running the current executable
/// with `GALLIUM_DRIVER=driver`. `args` must make the child reach a call of
/// [`serve_child_request`] with a scene list containing `scene` (for a libtest binary:
/// `[test_name, "--exact", "--nocapture"]`). Returns the picture and the child's renderer.
pub fn render_scene_with_driver(
    driver: &str,
    scene: &Scene,
    args: &[&str],
) -> Result<(Image, String), OracleError> {
    let out = temp_path(scene.name);
    let out_s = out.to_string_lossy().into_owned();
    let output = mesa::run_self_with_driver(
        driver,
        args,
        &[(CHILD_SCENE_ENV, scene.name), (CHILD_OUT_ENV, &out_s)],
    )?;
    let bytes = std::fs::read(&out).map_err(|e| {
        OracleError::Subprocess(format!(
            "no picture from the {driver} child ({e}); stdout: {}",
            String::from_utf8_lossy(&output.stdout)
        ))
    })?;
    let _ = std::fs::remove_file(&out);
    let image = Image::from_bytes(&bytes)
        .ok_or_else(|| OracleError::Subprocess("bad picture from child".into()))?;
    let stdout = String::from_utf8_lossy(&output.stdout);
    let renderer = stdout
        .lines()
        .find_map(|l| l.strip_prefix("TILEGL_CHILD_RENDERER="))
        .unwrap_or("")
        .to_string();
    Ok((image, renderer))
}

/// The outcome of one differential case.
#[derive(Clone, Debug)]
pub struct Comparison {
    pub scene: &'static str,
    pub tilegl: Rendered,
    pub mesa: Rendered,
    pub mesa_info: OracleInfo,
    pub diff: Diff,
    pub tolerance: Tolerance,
    /// Set when Mesa's picture shows nothing drawn ([`mesa_drew_nothing`]): the case fails.
    pub mesa_empty: Option<String>,
}

impl Comparison {
    /// Within tolerance, the same `glGetError` result on both sides, and a Mesa picture that
    /// shows something drawn.
    pub fn passed(&self) -> bool {
        self.tolerance.accepts(&self.diff)
            && self.tilegl.error == self.mesa.error
            && self.mesa_empty.is_none()
    }

    /// One line for logs.
    pub fn summary(&self) -> String {
        format!(
            "{}: {} [{}]; glGetError tilegl 0x{:04x} mesa 0x{:04x}; tolerance {}{}",
            self.scene,
            self.diff,
            self.mesa_info,
            self.tilegl.error,
            self.mesa.error,
            self.tolerance,
            self.mesa_empty
                .as_ref()
                .map_or(String::new(), |why| format!("; {why}"))
        )
    }

    /// Writes both pictures as PPM files into `dir` (for looking at a failure).
    pub fn dump(&self, dir: &Path) -> std::io::Result<()> {
        std::fs::create_dir_all(dir)?;
        self.tilegl
            .image
            .write_ppm(&dir.join(format!("{}-tilegl.ppm", self.scene)))?;
        self.mesa
            .image
            .write_ppm(&dir.join(format!("{}-mesa.ppm", self.scene)))
    }
}

/// Runs `scene` on tilegl and on Mesa and compares the pictures under `tolerance`.
pub fn compare_scene(scene: &Scene, tolerance: Tolerance) -> Result<Comparison, OracleError> {
    let (mesa, mesa_info, clear) = render_mesa_with_clear(scene)?;
    let tilegl = render_tilegl(scene);
    let diff = diff(&tilegl.image, &mesa.image, tolerance.channel);
    let mesa_empty = mesa_drew_nothing(scene.name, &mesa.image, clear);
    Ok(Comparison {
        scene: scene.name,
        tilegl,
        mesa,
        mesa_info,
        diff,
        tolerance,
        mesa_empty,
    })
}

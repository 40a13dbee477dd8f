//! Helpers shared by the integration tests.
#![allow(dead_code)]

use tilegl::enums::*;
use tilegl::{Context, ContextConfig, Gl};

/// A `width` x `height` context shading with `threads` threads (0: the global pool).
pub fn threaded_context(width: i32, height: i32, threads: usize) -> Context {
    Context::with_config(ContextConfig {
        width,
        height,
        threads,
        ..ContextConfig::default()
    })
}

/// Reads the whole colour buffer as RGBA8, bottom row first.
pub fn read_rgba(gl: &mut Context) -> Vec<[u8; 4]> {
    let (w, h) = gl.size();
    let mut buf = vec![0u8; (w * h * 4) as usize];
    gl.read_pixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, &mut buf);
    buf.chunks(4).map(|c| [c[0], c[1], c[2], c[3]]).collect()
}

/// Reads the whole depth buffer as `GL_UNSIGNED_INT` values (native-endian bytes), bottom
/// row first.
pub fn read_depth(gl: &mut Context) -> Vec<u8> {
    let (w, h) = gl.size();
    let mut buf = vec![0u8; (w * h * 4) as usize];
    gl.read_pixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &mut buf);
    buf
}

/// The colour, depth and stencil buffers (as [`read_rgba`], [`read_depth`] and stencil indices
/// as bytes), bottom row first.
pub fn read_buffers(gl: &mut Context) -> (Vec<[u8; 4]>, Vec<u8>, Vec<u8>) {
    let (w, h) = gl.size();
    let mut stencil = vec![0u8; (w * h) as usize];
    gl.read_pixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &mut stencil);
    (read_rgba(gl), read_depth(gl), stencil)
}

/// One pixel.
pub fn pixel(gl: &mut Context, x: i32, y: i32) -> [u8; 4] {
    let mut p = [0u8; 4];
    gl.read_pixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut p);
    p
}

/// Sets up a projection in which object coordinates are window coordinates.
pub fn window_ortho(gl: &mut Context) {
    let (w, h) = gl.size();
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, w as f64, 0.0, h as f64, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

/// A small deterministic PRNG (xorshift64*), so tests need no extra crates.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        let u = (self.next_u64() >> 40) as f32 / (1u64 << 24) as f32;
        lo + (hi - lo) * u
    }
}

/// Every value of every `glGet` state, as doubles: a fingerprint of the queryable state.
pub fn state_fingerprint(gl: &mut Context) -> Vec<(GLenum, Vec<f64>)> {
    assert_eq!(
        gl.get_error(),
        GL_NO_ERROR,
        "fingerprint taken with an error pending"
    );
    let mut out = Vec::new();
    for &(_, value) in tilegl::enums::ENUMS_BY_NAME {
        let n = gl.query_count(value);
        let mut v = vec![0f64; n.max(16)];
        gl.get_doublev(value, &mut v);
        if gl.get_error() == GL_NO_ERROR {
            v.truncate(n);
            out.push((value, v));
        }
    }
    out.sort_by_key(|a| a.0);
    out.dedup_by(|a, b| a.0 == b.0);
    out
}

use tilegl::api::GLenum;

/// The environment variable naming another folder of captures than the repository's
/// `conformance/traces` (used to check that the tests fail when their input is missing).
pub const TRACES_ENV: &str = "TILEGL_TRACES";

/// The repository's captures: `conformance/traces` holds the project's own (its MANIFEST.md),
/// `conformance/traces/shared` a copy of the shared corpus (`../shared/traces`, with its
/// MANIFEST.md and TOLERANCE.md), so the tests need nothing outside the checkout.
/// [`TRACES_ENV`] names another root.
pub fn traces_root() -> std::path::PathBuf {
    match std::env::var_os(TRACES_ENV) {
        Some(d) if !d.is_empty() => std::path::PathBuf::from(d),
        _ => std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("conformance/traces"),
    }
}

/// The project's own captures (panics, naming the folder, when it is missing).
pub fn own_traces() -> std::path::PathBuf {
    require(&traces_root())
}

/// The copy of the shared captures (panics, naming the folder, when it is missing).
pub fn shared_traces() -> std::path::PathBuf {
    require(&traces_root().join("shared"))
}

/// `path` when it exists; otherwise the test fails with a message naming it. A test whose
/// input is missing fails: it never passes without checking anything.
pub fn require(path: &std::path::Path) -> std::path::PathBuf {
    assert!(
        path.exists(),
        "test input missing: {} (the captures are part of the repository, under \
         conformance/traces; `git checkout -- conformance/traces` restores them)",
        path.display()
    );
    path.to_path_buf()
}

/// Replays capture `dir/NAME.trace` and compares it with Mesa's pictures in `dir/NAME.frames`
/// (the shared tolerance rule), printing one line per picture. Panics when it does not match,
/// unless the folder's `KNOWN_FAILURES.tsv` lists it (with the reason), and when a listed
/// capture now matches, so that the list stays true.
pub fn check_capture(dir: &std::path::Path, name: &str) {
    use tilegl::replay::player::Player;
    use tilegl::replay::reference::compare_replay;
    use tilegl::replay::trace::TraceReader;

    let trace = require(&dir.join(format!("{name}.trace")));
    let frames = require(&dir.join(format!("{name}.frames")));
    require(&frames.join("frames.tsv"));
    let mut reader = TraceReader::open(&trace).expect("open capture");
    // Two workers: the pictures do not depend on the count, and the machine is shared.
    let mut player = Player::new(2);
    let report =
        compare_replay(&mut reader, &mut player, &frames, None, &mut |_| {}).expect("compare");
    let mut text = String::new();
    for p in &report.pictures {
        text.push_str(&format!("  {}\n", p.line()));
    }
    for l in report.stats.report_lines() {
        text.push_str(&format!("  replay: {l}\n"));
    }
    if let Some(e) = &report.error {
        text.push_str(&format!("  replay stopped: {e}\n"));
    }
    text.push_str(&format!("  {}\n", report.summary()));
    eprintln!("{name}:\n{text}");
    let known_failures = tilegl::replay::reference::known_failures(dir).unwrap();
    let known = known_failures.iter().find(|(n, _)| n == name);
    match (report.all_ok(), known) {
        (true, None) | (false, Some(_)) => {}
        (true, Some((_, why))) => panic!(
            "{name} now matches the reference (listed as a known failure: {why}); \
             remove it from KNOWN_FAILURES.tsv\n{text}"
        ),
        (false, None) => panic!("{name} does not match the reference:\n{text}"),
    }
}

/// A random texture of `format` (`w` x `h`, unsigned bytes, mipmaps generated) bound to the
/// active unit's 2D target, which is enabled.
pub fn random_texture(gl: &mut Context, rng: &mut Rng, format: GLenum, w: i32, h: i32) {
    let comps = match format {
        GL_RGBA => 4,
        GL_RGB => 3,
        GL_LUMINANCE_ALPHA => 2,
        _ => 1,
    };
    let texels: Vec<u8> = (0..w * h * comps)
        .map(|_| (rng.next_u64() >> 56) as u8)
        .collect();
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_2D, name[0]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        format as i32,
        w,
        h,
        0,
        // INTENSITY is an internal format only; its pixels arrive as luminance.
        if format == GL_INTENSITY {
            GL_LUMINANCE
        } else {
            format
        },
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    gl.enable(GL_TEXTURE_2D);
}

/// Asserts that the captures (`NAME.trace`) in `dir` are exactly `all`, and that every known
/// failure (the folder's `KNOWN_FAILURES.tsv`) names one of them.
pub fn assert_every_capture_listed(dir: &std::path::Path, all: &[&str]) {
    let mut on_disk: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("test input missing: {}: {e}", dir.display()))
        .filter_map(|e| {
            let p = e.ok()?.path();
            if p.extension()? != "trace" {
                return None;
            }
            Some(p.file_stem()?.to_string_lossy().into_owned())
        })
        .collect();
    on_disk.sort();
    let mut listed: Vec<String> = all.iter().map(|s| s.to_string()).collect();
    listed.sort();
    assert_eq!(
        on_disk, listed,
        "add a line to captures! for each new capture"
    );
    for (name, _) in tilegl::replay::reference::known_failures(dir).unwrap() {
        assert!(
            all.contains(&name.as_str()),
            "known failure {name} is not a capture"
        );
    }
}

/// A 16 x 16 context for texture tests.
pub fn ctx() -> Context {
    Context::new(16, 16)
}

/// A texture level parameter of `target`.
pub fn level_param(gl: &mut Context, target: GLenum, level: i32, pname: GLenum) -> i32 {
    let mut v = [0i32];
    gl.get_tex_level_parameteriv(target, level, pname, &mut v);
    v[0]
}

/// A texture parameter of `target`.
pub fn tex_param(gl: &mut Context, target: GLenum, pname: GLenum) -> i32 {
    let mut v = [0i32];
    gl.get_tex_parameteriv(target, pname, &mut v);
    v[0]
}

/// Reads level 0 of the bound 2D texture back as RGBA floats.
pub fn read_rgba_f32(gl: &mut Context, target: GLenum, n: usize) -> Vec<f32> {
    let mut out = vec![0u8; n * 16];
    gl.get_tex_image(target, 0, GL_RGBA, GL_FLOAT, &mut out);
    out.chunks(4)
        .map(|c| f32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
        .collect()
}

/// `n` depth-tested-scene triangles in the perspective view volume of the twin tests: each
/// around a random centre (x, y in [-3, 3], z in [-9, -0.5]), vertices within 1.5 (x, y) and
/// 1 (z) of it, each vertex with a random colour.
pub fn random_triangles(gl: &mut Context, rng: &mut Rng, n: usize) {
    gl.begin(GL_TRIANGLES);
    for _ in 0..n {
        let c = [
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-9.0, -0.5),
        ];
        for _ in 0..3 {
            gl.color_3f(
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
            );
            gl.vertex_3f(
                c[0] + rng.range(-1.5, 1.5),
                c[1] + rng.range(-1.5, 1.5),
                c[2] + rng.range(-1.0, 1.0),
            );
        }
    }
    gl.end();
}

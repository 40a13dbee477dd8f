//! Determinism as a matrix: every differential scene (`scenes::SCENES`) rendered on tilegl
//! gives the same bytes for 1, 2, 3 and 8 shading threads, for tiles of 16, 32, 64 and 128
//! pixels (`TILEGL_TILE`), and with the AVX2 paths switched off (`TILEGL_NO_SIMD=1`) as with
//! them on. Binned tiles replay their commands in submission
//! order whichever thread takes them (DESIGN.md, "How a draw call flows" step 6), and every
//! AVX2 route does the arithmetic of its scalar twin in the same order and precision
//! (`src/texture/simd.rs`, `src/fragment/simd.rs`), and spans restart their stepped values
//! at fixed columns that every tile size honours (`RESTART` in `src/fragment/span/tail.rs`),
//! so nothing may differ, not even by one step.
//!
//! The SIMD switch and the tile size are read once per process, so the scalar pictures and
//! those of the other tile sizes come from child processes of this test binary started with
//! `TILEGL_NO_SIMD=1` or `TILEGL_TILE=N`.

use std::io::Write;

use tilegl::common::cpu as simd;
use tilegl::framebuffer::{tile_shift, TILE, TILE_ENV, TILE_SIZES};
use tilegl_conformance::compare::{render_tilegl_with_threads, Rendered};
use tilegl_conformance::scenes::SCENES;
use tilegl_conformance::Image;

/// Set in the child: where to write its pictures.
const CHILD_OUT_ENV: &str = "TILEGL_DETERMINISM_OUT";

fn same(a: &Rendered, b: &Rendered) -> bool {
    a.image == b.image && a.error == b.error
}

/// The first differing pixel of two pictures of the same size, for the failure message.
fn first_difference(a: &Image, b: &Image) -> String {
    if a.pixels.len() != b.pixels.len() {
        return format!(
            "sizes {}x{} and {}x{}",
            a.width, a.height, b.width, b.height
        );
    }
    let n = a
        .pixels
        .chunks(4)
        .zip(b.pixels.chunks(4))
        .filter(|(p, q)| p != q)
        .count();
    match a
        .pixels
        .chunks(4)
        .zip(b.pixels.chunks(4))
        .position(|(p, q)| p != q)
    {
        Some(i) => format!(
            "{n} pixels differ, the first at ({}, {}): {:?} vs {:?}",
            i as i32 % a.width,
            i as i32 / a.width,
            &a.pixels[i * 4..i * 4 + 4],
            &b.pixels[i * 4..i * 4 + 4]
        ),
        None => "same pixels, different glGetError".to_string(),
    }
}

#[test]
fn every_scene_is_bit_identical_for_1_2_3_and_8_threads() {
    if std::env::var_os(CHILD_OUT_ENV).is_some() {
        return;
    }
    let mut failures = Vec::new();
    for scene in SCENES.iter() {
        let one = render_tilegl_with_threads(scene, 1);
        for threads in [2, 3, 8] {
            let other = render_tilegl_with_threads(scene, threads);
            if !same(&one, &other) {
                failures.push(format!(
                    "{} with {threads} threads: {}",
                    scene.name,
                    first_difference(&one.image, &other.image)
                ));
            }
        }
    }
    println!("{} scenes x 1, 2, 3, 8 threads", SCENES.len());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The pictures of every scene, with 2 threads, as bytes: per scene its error (4 bytes) and
/// its picture (`Image::to_bytes`, length-prefixed).
fn render_all() -> Vec<u8> {
    let mut out = Vec::new();
    for scene in SCENES.iter() {
        let r = render_tilegl_with_threads(scene, 2);
        let img = r.image.to_bytes();
        out.extend_from_slice(&r.error.to_le_bytes());
        out.extend_from_slice(&(img.len() as u64).to_le_bytes());
        out.extend_from_slice(&img);
    }
    out
}

fn parse_all(mut b: &[u8]) -> Option<Vec<Rendered>> {
    let mut out = Vec::new();
    while !b.is_empty() {
        let error = u32::from_le_bytes(b.get(..4)?.try_into().ok()?);
        let n = u64::from_le_bytes(b.get(4..12)?.try_into().ok()?) as usize;
        let image = Image::from_bytes(b.get(12..12 + n)?)?;
        out.push(Rendered { image, error });
        b = &b[12 + n..];
    }
    Some(out)
}

/// The pictures of every scene ([`render_all`]) from a child process of this test binary that
/// runs only the test `name`, with the environment variable `var` set to `value`.
fn child_pictures(name: &str, var: &str, value: &str) -> Vec<Rendered> {
    let path = std::env::temp_dir().join(format!(
        "tilegl-determinism-{}-{var}-{value}.raw",
        std::process::id()
    ));
    let exe = std::env::current_exe().expect("test binary");
    let child = std::process::Command::new(exe)
        .args([name, "--exact", "--nocapture", "--test-threads", "1"])
        .env(var, value)
        .env(CHILD_OUT_ENV, &path)
        .output()
        .expect("start the child");
    assert!(
        child.status.success(),
        "child with {var}={value} failed: {}{}",
        String::from_utf8_lossy(&child.stdout),
        String::from_utf8_lossy(&child.stderr)
    );
    let bytes = std::fs::read(&path).expect("the child's pictures");
    let _ = std::fs::remove_file(&path);
    let pictures = parse_all(&bytes).expect("well-formed pictures from the child");
    assert_eq!(pictures.len(), SCENES.len());
    pictures
}

#[test]
fn every_scene_is_bit_identical_for_tiles_of_16_32_64_and_128_pixels() {
    const NAME: &str = "every_scene_is_bit_identical_for_tiles_of_16_32_64_and_128_pixels";
    if let Some(out) = std::env::var_os(CHILD_OUT_ENV) {
        // The child: TILEGL_TILE must have chosen its tile side.
        let asked: usize = std::env::var(TILE_ENV).unwrap().parse().unwrap();
        assert_eq!(
            1usize << tile_shift(),
            asked,
            "{TILE_ENV}={asked} not in force"
        );
        std::fs::write(&out, render_all()).expect("write the child's pictures");
        return;
    }
    // This process renders with the default side (the matrix's reference).
    assert_eq!(1usize << tile_shift(), TILE, "run without {TILE_ENV}");
    let reference = render_all();
    let reference = parse_all(&reference).expect("well-formed pictures");
    let mut failures = Vec::new();
    for side in TILE_SIZES.into_iter().filter(|&s| s != TILE) {
        let other = child_pictures(NAME, TILE_ENV, &side.to_string());
        for (scene, (a, b)) in SCENES.iter().zip(reference.iter().zip(&other)) {
            if !same(a, b) {
                failures.push(format!(
                    "{}: tiles of {side} vs {TILE}: {}",
                    scene.name,
                    first_difference(&b.image, &a.image)
                ));
            }
        }
    }
    println!("{} scenes x tiles of {TILE_SIZES:?} pixels", SCENES.len());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn every_scene_is_bit_identical_with_simd_off() {
    const NAME: &str = "every_scene_is_bit_identical_with_simd_off";
    if let Some(out) = std::env::var_os(CHILD_OUT_ENV) {
        // The child: TILEGL_NO_SIMD=1 must have switched the AVX2 paths off.
        assert!(!simd::available(), "TILEGL_NO_SIMD=1 left SIMD on");
        std::fs::write(&out, render_all()).expect("write the child's pictures");
        return;
    }
    let scalar = child_pictures(NAME, simd::NO_SIMD_ENV, "1");
    let vector = parse_all(&render_all()).expect("well-formed pictures");
    assert_eq!(scalar.len(), SCENES.len());
    let on = simd::available();
    let _ = writeln!(
        std::io::stderr(),
        "determinism: {} scenes, SIMD {} here vs off in the child",
        SCENES.len(),
        if on {
            "on (AVX2)"
        } else {
            "also off (this processor has no AVX2: both routes are scalar)"
        }
    );
    let failures: Vec<String> = SCENES
        .iter()
        .zip(scalar.iter().zip(&vector))
        .filter(|(_, (s, v))| !same(s, v))
        .map(|(scene, (s, v))| {
            format!(
                "{}: SIMD off vs on: {}",
                scene.name,
                first_difference(&s.image, &v.image)
            )
        })
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

//! Determinism as a matrix: every differential scene (`scenes::SCENES`) rendered on tilegl
//! gives the same bytes for 1, 2, 3 and 8 shading threads, and with the AVX2 paths switched
//! off (`TILEGL_NO_SIMD=1`) as with them on. Binned tiles replay their commands in submission
//! order whichever thread takes them (DESIGN.md, "How a draw call flows" step 6), and every
//! AVX2 route does the arithmetic of its scalar twin in the same order and precision
//! (`src/texture/simd.rs`, `src/fragment/simd.rs`), so nothing may differ, not even by one step.
//!
//! The SIMD switch is read once per process, so the scalar pictures come from a child process
//! of this test binary started with `TILEGL_NO_SIMD=1`.
//!
//! The tile size is not part of the matrix: it is a compile-time constant
//! (`tilegl::framebuffer::TILE`, 64) that the tiled storage and the shading loops are built
//! around; making it a run-time value would slow the default path.

use std::io::Write;

use tilegl::common::cpu as simd;
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

#[test]
fn every_scene_is_bit_identical_with_simd_off() {
    const NAME: &str = "every_scene_is_bit_identical_with_simd_off";
    if let Some(out) = std::env::var_os(CHILD_OUT_ENV) {
        // The child: TILEGL_NO_SIMD=1 must have switched the AVX2 paths off.
        assert!(!simd::available(), "TILEGL_NO_SIMD=1 left SIMD on");
        std::fs::write(&out, render_all()).expect("write the child's pictures");
        return;
    }
    let path = std::env::temp_dir().join(format!("tilegl-determinism-{}.raw", std::process::id()));
    let exe = std::env::current_exe().expect("test binary");
    let child = std::process::Command::new(exe)
        .args([NAME, "--exact", "--nocapture", "--test-threads", "1"])
        .env(simd::NO_SIMD_ENV, "1")
        .env(CHILD_OUT_ENV, &path)
        .output()
        .expect("start the scalar child");
    assert!(
        child.status.success(),
        "scalar child failed: {}{}",
        String::from_utf8_lossy(&child.stdout),
        String::from_utf8_lossy(&child.stderr)
    );
    let bytes = std::fs::read(&path).expect("the scalar child's pictures");
    let _ = std::fs::remove_file(&path);
    let scalar = parse_all(&bytes).expect("well-formed pictures from the child");
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

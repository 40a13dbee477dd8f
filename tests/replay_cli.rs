//! `tilegl replay` end to end: the compare path on a capture that matches and on one that does
//! not (exit status and one line per picture), writing frames, and bad input.

use std::path::PathBuf;
use std::process::Command;

mod common;

/// The repository's copy of the shared captures (the test fails when it is missing).
fn traces_dir() -> PathBuf {
    common::shared_traces()
}

fn tilegl() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tilegl"))
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tilegl-replay-cli-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn compare_reports_each_picture_and_passes_within_tolerance() {
    let dir = traces_dir();
    let out = temp_dir("compare");
    let o = tilegl()
        .arg("replay")
        .arg(common::require(&dir.join("xss-timetunnel.trace")))
        .arg("--compare")
        .arg(common::require(&dir.join("xss-timetunnel.frames")))
        .arg("-o")
        .arg(&out)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines.len(), 4, "{stdout}");
    for (line, f) in lines
        .iter()
        .zip(["frame-0007.png", "frame-0008.png", "frame-0009.png"])
    {
        assert!(
            line.starts_with(f) && line.contains("PSNR") && line.ends_with("ok"),
            "{line}"
        );
        let png = image::open(out.join(f)).unwrap();
        assert_eq!((png.width(), png.height()), (320, 240));
    }
    assert!(
        lines[3].starts_with("3/3 pictures within tolerance"),
        "{}",
        lines[3]
    );
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn compare_fails_when_a_picture_is_out_of_tolerance() {
    let dir = traces_dir();
    // glxgears against references that are solid magenta: every picture fails.
    let name = "glxgears";
    let refs = temp_dir("bad-refs");
    let src = common::require(&dir.join(format!("{name}.frames")));
    let tsv = std::fs::read_to_string(src.join("frames.tsv")).unwrap();
    std::fs::write(refs.join("frames.tsv"), &tsv).unwrap();
    for line in tsv.lines().skip(1) {
        let file = line.split('\t').next().unwrap();
        let size = image::image_dimensions(src.join(file)).unwrap();
        image::RgbImage::from_pixel(size.0, size.1, image::Rgb([255, 0, 255]))
            .save(refs.join(file))
            .unwrap();
    }
    let o = tilegl()
        .arg("replay")
        .arg(common::require(&dir.join(format!("{name}.trace"))))
        .arg("--compare")
        .arg(&refs)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{stdout}\n{stderr}");
    assert!(
        stdout.lines().filter(|l| l.ends_with("FAIL")).count() == 3,
        "{stdout}"
    );
    let _ = std::fs::remove_dir_all(&refs);
}

#[test]
fn each_gl_error_source_is_reported_once_with_its_first_call() {
    let dir = traces_dir();
    // piglit queries GL 3 state that GL 1.5 does not have: glGetIntegerv raises
    // GL_INVALID_ENUM hundreds of times, reported on one line.
    let name = "piglit-nv_texture_env_combine4-combine";
    let o = tilegl()
        .arg("replay")
        .arg(common::require(&dir.join(format!("{name}.trace"))))
        .arg("--compare")
        .arg(common::require(&dir.join(format!("{name}.frames"))))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{stdout}\n{stderr}");
    let raised: Vec<&str> = stderr.lines().filter(|l| l.contains(" raised ")).collect();
    assert!(!raised.is_empty(), "{stderr}");
    let mut keys: Vec<&str> = raised
        .iter()
        .map(|l| l.split(" (").next().unwrap_or(l))
        .collect();
    let n = keys.len();
    keys.sort_unstable();
    keys.dedup();
    assert_eq!(keys.len(), n, "{stderr}");
    assert!(
        raised.iter().all(|l| l.contains("first at call")),
        "{stderr}"
    );
}

#[test]
fn replay_writes_the_requested_frames_and_calls() {
    let dir = traces_dir();
    let out = temp_dir("frames");
    let o = tilegl()
        .arg("replay")
        .arg(common::require(&dir.join("xss-cage.trace")))
        .args(["--frames", "28..30", "--calls", "100", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut files: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    files.sort();
    assert_eq!(
        files,
        ["call-0000000100.png", "frame-0028.png", "frame-0029.png"]
    );
    // The frame is the reference picture (within tolerance, checked in replay_compare.rs).
    let ours = image::open(out.join("frame-0029.png")).unwrap().to_rgb8();
    let reference = image::open(common::require(&dir.join("xss-cage.frames/frame-0029.png")))
        .unwrap()
        .to_rgb8();
    let d = tilegl::replay::reference::diff_rgb(&ours, &reference, 8);
    assert!(d.bad_share < 0.001, "{d}");
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn bad_input_fails_with_a_message_naming_the_call() {
    let dir = traces_dir();
    let tmp = temp_dir("bad");
    // Several snappy chunks: the cut falls after many good calls.
    let bytes = std::fs::read(common::require(&dir.join("xss-atlantis.trace"))).unwrap();
    let cut = tmp.join("cut.trace");
    std::fs::write(&cut, &bytes[..bytes.len() * 9 / 10]).unwrap();
    let o = tilegl()
        .arg("replay")
        .arg(&cut)
        .arg("-o")
        .arg(&tmp)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains(": call "), "{stderr}");
    let missing = tilegl()
        .args(["replay", "/nonexistent.trace"])
        .output()
        .unwrap();
    assert_eq!(missing.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&tmp);
}

/// Replays `NAME.trace` of `dir` with `--compare` against `NAME.frames`: it must match with
/// the replay's default and fail (exit status 1) with `spec_flag`, which switches a Mesa
/// convention back to the specification's.
fn matches_mesa_only_by_default(dir: &std::path::Path, name: &str, spec_flag: &str) {
    let run = |spec: bool| {
        let mut c = tilegl();
        c.arg("replay")
            .arg(common::require(&dir.join(format!("{name}.trace"))))
            .arg("--compare")
            .arg(common::require(&dir.join(format!("{name}.frames"))));
        if spec {
            c.arg(spec_flag);
        }
        c.output().unwrap()
    };
    let default = run(false);
    assert!(
        default.status.success(),
        "{}",
        String::from_utf8_lossy(&default.stdout)
    );
    let spec = run(true);
    assert_eq!(
        spec.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&spec.stdout)
    );
}

/// The xscreensaver starwars capture (smooth points of sizes 0.5 to 3) matches Mesa with the
/// replay's default (Mesa's full-colour discs) and not with `--spec-points` (the
/// specification's coverage shades the discs' rims: 0.37 % of the pixels off).
#[test]
fn spec_points_switches_smooth_points_to_coverage() {
    let dir = common::traces_root().join("corpus");
    matches_mesa_only_by_default(&dir, "xss-starwars", "--spec-points");
}

/// The evaluator teapot of tilegl's own capture matches Mesa with the replay's default
/// (Mesa's triangle-strip meshes) and not with `--spec-meshes` (the specification's quad
/// strips colour each flat-shaded quad once).
#[test]
fn spec_meshes_switches_evaluator_meshes_to_quad_strips() {
    matches_mesa_only_by_default(&common::own_traces(), "xss-polyhedra", "--spec-meshes");
}

//! Call scripts: `tilegl dump` of shared captures replays to the same pixels as the captures
//! themselves, and a hand-written script (examples/scripts) replays through the CLI.

use std::path::{Path, PathBuf};
use std::process::Command;

use tilegl::replay::player::{CallSource, FrameSelection, Picture, Player, Want};
use tilegl::replay::script::{dump, ScriptReader};
use tilegl::replay::trace::TraceReader;

mod common;

/// The repository's copy of the shared captures (the test fails when it is missing).
fn traces_dir() -> PathBuf {
    common::shared_traces()
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tilegl-script-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn pictures(source: &mut dyn CallSource, want: &Want, auto_window: bool) -> Vec<Picture> {
    let mut player = Player::new(2);
    player.auto_window = auto_window;
    let mut out = Vec::new();
    player
        .play(
            source,
            want,
            &mut |p| {
                out.push(p);
                Ok(())
            },
            &mut |_| {},
        )
        .unwrap();
    out
}

#[test]
fn dumped_captures_replay_to_the_same_pixels() {
    let dir = traces_dir();
    let tmp = temp_dir("dump");
    // Display lists, client-array blobs in fake calls, texture images (large blobs in files),
    // EGL and GLX.
    for (name, calls) in [
        ("glxgears", vec![]),
        ("xss-flurry", vec![]),
        ("piglit-s3tc-teximage", vec![768]),
        ("piglit-texwrap-2D-GL_RGBA8", vec![567, 973]),
    ] {
        let trace = common::require(&dir.join(format!("{name}.trace")));
        let header = "test dump";
        let (script, n) =
            dump(&mut TraceReader::open(&trace).unwrap(), &tmp, name, header).unwrap();
        assert!(n > 0);
        let want = Want {
            frames: FrameSelection::All,
            calls: calls.into_iter().collect(),
            stop_early: false,
        };
        let a = pictures(&mut TraceReader::open(&trace).unwrap(), &want, false);
        let b = pictures(&mut ScriptReader::open(&script).unwrap(), &want, true);
        assert!(!a.is_empty(), "{name}");
        assert_eq!(a.len(), b.len(), "{name}");
        for (x, y) in a.iter().zip(&b) {
            assert_eq!((&x.file, x.call_no), (&y.file, y.call_no), "{name}");
            assert!(x.image == y.image, "{name}: {} differs", x.file);
        }
    }
    let _ = std::fs::remove_dir_all(&tmp);
}

#[test]
fn hand_written_script_replays_through_the_cli() {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scripts/checker_quad.gl");
    let out = temp_dir("cli");
    let o = Command::new(env!("CARGO_BIN_EXE_tilegl"))
        .arg("replay")
        .arg(&script)
        .args(["--calls", "4", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{stderr}");
    assert!(
        !stderr.contains("raised"),
        "the script is valid GL: {stderr}"
    );
    // --calls alone: no frames, the picture after statement 4 (statements count from 0:
    // window, glClearColor, glClear, glBegin, glColor3f), which shows the clear.
    let after_clear = image::open(out.join("call-0000000004.png"))
        .unwrap()
        .to_rgb8();
    assert_eq!((after_clear.width(), after_clear.height()), (128, 96));
    assert_eq!(after_clear.get_pixel(5, 5).0, [26, 26, 51]);
    let o = Command::new(env!("CARGO_BIN_EXE_tilegl"))
        .arg("replay")
        .arg(&script)
        .arg("-o")
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success());
    let f0 = image::open(out.join("frame-0000.png")).unwrap().to_rgb8();
    let f1 = image::open(out.join("frame-0001.png")).unwrap().to_rgb8();
    // Frame 0: the triangle's centre is a mix of the three colours; the corner is the clear.
    let c = f0.get_pixel(64, 55).0;
    assert!(c.iter().all(|&v| v > 40), "{c:?}");
    assert_eq!(f0.get_pixel(1, 1).0, [26, 26, 51]);
    // Frame 1: the checkerboard quad (8x8 texels over 64x48 pixels, from window pixel
    // (32, 24)) on top; texel (0, 0), white, is at the quad's lower left (PNG rows top-down).
    let texel = |x: u32, y: u32| f1.get_pixel(x, y).0;
    assert_eq!(texel(36, 95 - 27), [255, 255, 255]);
    assert_eq!(texel(36 + 8, 95 - 27), [0, 0, 0]);
    assert_eq!(texel(36, 95 - 27 - 6), [0, 0, 0]);
    assert_eq!(texel(1, 1), [26, 26, 51]);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn script_errors_name_the_line() {
    let out = temp_dir("err");
    let bad = out.join("bad.gl");
    std::fs::write(
        &bad,
        "window(8, 8);\nglClear(GL_COLOR_BUFFER_BIT);\nglClear(GL_NOPE);\n",
    )
    .unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_tilegl"))
        .arg("replay")
        .arg(&bad)
        .arg("-o")
        .arg(&out)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("line 3") && stderr.contains("GL_NOPE"),
        "{stderr}"
    );
    let _ = std::fs::remove_dir_all(&out);
}

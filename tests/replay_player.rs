//! The replay driver on damaged and unusual input: never a panic, errors name the call, GL
//! calls without a current context are ignored and counted, and frame selection stops early.

use std::io::Cursor;
use std::path::{Path, PathBuf};

use tilegl::replay::player::{FrameSelection, Player, Want};
use tilegl::replay::script::ScriptReader;
use tilegl::replay::trace::TraceReader;

mod common;

/// The repository's copy of the shared captures (the test fails when it is missing).
fn traces_dir() -> PathBuf {
    common::shared_traces()
}

fn all_frames() -> Want {
    Want {
        frames: FrameSelection::All,
        calls: Default::default(),
        stop_early: false,
    }
}

/// The decompressed stream of an apitrace snappy container.
fn unsnap(bytes: &[u8]) -> Vec<u8> {
    assert_eq!(&bytes[..2], b"at");
    let mut out = Vec::new();
    let mut at = 2;
    while at + 4 <= bytes.len() {
        let n = u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap()) as usize;
        at += 4;
        if n == 0 || at + n > bytes.len() {
            break;
        }
        out.extend(
            snap::raw::Decoder::new()
                .decompress_vec(&bytes[at..at + n])
                .unwrap(),
        );
        at += n;
    }
    out
}

fn gzip(bytes: &[u8]) -> Vec<u8> {
    use std::io::Write;
    let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    e.write_all(bytes).unwrap();
    e.finish().unwrap()
}

#[test]
fn corrupted_captures_replay_or_fail_with_a_call_number() {
    let dir = traces_dir();
    for name in ["glxgears", "piglit-tex-border-1"] {
        // Damage the decompressed call stream (re-wrapped as gzip, which the reader also
        // takes), so that the player sees readable but wrong calls and values.
        let stream =
            unsnap(&std::fs::read(common::require(&dir.join(format!("{name}.trace")))).unwrap());
        let mut state = 0x9e37_79b9_u32;
        let mut errors = 0;
        for _ in 0..40 {
            let mut damaged = stream.clone();
            for _ in 0..3 {
                state ^= state << 13;
                state ^= state >> 17;
                state ^= state << 5;
                let at = 64 + state as usize % (damaged.len() - 64);
                damaged[at] ^= (state >> 8) as u8 | 1;
            }
            let Ok(mut reader) = TraceReader::new(Box::new(Cursor::new(gzip(&damaged)))) else {
                continue;
            };
            let mut player = Player::new(1);
            match player.play(&mut reader, &all_frames(), &mut |_| Ok(()), &mut |_| {}) {
                Ok(stats) => assert!(stats.calls > 0),
                Err(e) => {
                    errors += 1;
                    assert!(
                        e.call.is_some() && e.to_string().starts_with("call "),
                        "{e}"
                    )
                }
            }
        }
        eprintln!("{name}: {errors} of 40 damaged streams ended with an error");
    }
}

#[test]
fn calls_without_a_context_are_ignored_and_counted() {
    // A capture-like stream: GL calls before any make-current and after the release.
    let text = "glClear(GL_COLOR_BUFFER_BIT);\n\
                glXMakeCurrent(ptr(0x1), 7, ptr(0x2));\n\
                fake glViewport(0, 0, 20, 10);\n\
                glClearColor(1.0f, 0.0f, 0.0f, 1.0f);\n\
                glClear(GL_COLOR_BUFFER_BIT);\n\
                glXSwapBuffers(ptr(0x1), 7);\n\
                glXMakeCurrent(ptr(0x1), 0, NULL);\n\
                glClear(GL_COLOR_BUFFER_BIT);\n\
                glXSwapBuffers(ptr(0x1), 7);\n";
    let mut player = Player::new(1);
    let mut frames = Vec::new();
    let stats = player
        .play(
            &mut ScriptReader::new(text, Path::new(".")),
            &all_frames(),
            &mut |p| {
                frames.push(p);
                Ok(())
            },
            &mut |_| {},
        )
        .unwrap();
    assert_eq!(stats.without_context, 2);
    assert_eq!(stats.frames, 2);
    assert_eq!(stats.size, Some((20, 10)));
    // Only the first swap had a context to show.
    assert_eq!(frames.len(), 1);
    assert_eq!(frames[0].file, "frame-0000.png");
    assert_eq!(frames[0].call_no, 5);
    assert_eq!(frames[0].image.dimensions(), (20, 10));
    assert_eq!(frames[0].image.get_pixel(0, 0).0, [255, 0, 0]);
    assert!(stats.gl_errors.is_empty() && stats.unknown.is_empty());
}

#[test]
fn unknown_calls_and_gl_errors_are_counted_once_each() {
    let text = "window(4, 4);\n\
                glNotAFunction(1);\n\
                glNotAFunction(2);\n\
                glEnable(GL_TEXTURE_2D);\n\
                glEnable(GL_LINEAR);\n\
                glEnable(GL_LINEAR);\n";
    let mut player = Player::new(1);
    player.auto_window = true;
    let stats = player
        .play(
            &mut ScriptReader::new(text, Path::new(".")),
            &all_frames(),
            &mut |_| Ok(()),
            &mut |_| {},
        )
        .unwrap();
    assert_eq!(stats.unknown.get("glNotAFunction"), Some(&2));
    let e = stats.gl_errors[&("glEnable".to_string(), 0x0500)];
    assert_eq!((e.count, e.first_call), (2, 4));
    let lines = stats.report_lines();
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[1].contains("GL_INVALID_ENUM (2x, first at call 4)"),
        "{lines:?}"
    );
}

#[test]
fn a_frame_range_stops_the_replay_early() {
    let dir = traces_dir();
    let mut player = Player::new(2);
    let want = Want {
        frames: FrameSelection::Range {
            start: 2,
            end: Some(4),
        },
        calls: Default::default(),
        stop_early: true,
    };
    let mut files = Vec::new();
    let stats = player
        .play(
            &mut TraceReader::open(&common::require(&dir.join("xss-cage.trace"))).unwrap(),
            &want,
            &mut |p| {
                files.push(p.file);
                Ok(())
            },
            &mut |_| {},
        )
        .unwrap();
    assert_eq!(files, ["frame-0002.png", "frame-0003.png"]);
    assert_eq!(stats.frames, 4);
    assert!(stats.calls < 21924 / 2, "{}", stats.calls);
}

#[test]
fn each_thread_has_its_own_current_context() {
    use tilegl::replay::player::CallSource;
    // Thread 0 draws red into a 4x4 window, thread 1 green into an 8x2 one, interleaved.
    let text = "glXMakeCurrent(ptr(0x1), 7, ptr(0xa));\n\
                fake glViewport(0, 0, 4, 4);\n\
                glXMakeCurrent(ptr(0x1), 8, ptr(0xb));\n\
                fake glViewport(0, 0, 8, 2);\n\
                glClearColor(1.0f, 0.0f, 0.0f, 1.0f);\n\
                glClearColor(0.0f, 1.0f, 0.0f, 1.0f);\n\
                glClear(GL_COLOR_BUFFER_BIT);\n\
                glClear(GL_COLOR_BUFFER_BIT);\n\
                glXSwapBuffers(ptr(0x1), 7);\n\
                glXSwapBuffers(ptr(0x1), 8);\n";
    let threads = [0, 0, 1, 1, 0, 1, 0, 1, 0, 1];
    let mut reader = ScriptReader::new(text, Path::new("."));
    let mut player = Player::new(1);
    let mut pictures = Vec::new();
    let mut i = 0;
    while let Some(mut call) = reader.next_call().unwrap() {
        call.thread = threads[i];
        i += 1;
        pictures.extend(player.play_call(&call, &all_frames()).unwrap());
    }
    assert_eq!(pictures.len(), 2);
    assert_eq!(pictures[0].image.dimensions(), (4, 4));
    assert_eq!(pictures[0].image.get_pixel(0, 0).0, [255, 0, 0]);
    assert_eq!(pictures[1].image.dimensions(), (8, 2));
    assert_eq!(pictures[1].image.get_pixel(0, 0).0, [0, 255, 0]);
}

/// ARB_pixel_buffer_object in a call stream: while a buffer is bound to a pixel command's
/// target, the pointer the capture holds as a number (apitrace writes the offset so) is an
/// offset into that buffer, for unpacking (`glDrawPixels` from offset 8) and packing
/// (`glReadPixels` into offset 4 of another buffer, then drawn from there); without a buffer
/// the same kind of number would be a dead client address.
#[test]
fn pixel_commands_take_buffer_offsets_while_a_buffer_is_bound() {
    let text = "window(4, 2);\n\
                glGenBuffers(2, {1, 2});\n\
                glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 1);\n\
                glBufferData(GL_PIXEL_UNPACK_BUFFER, 16, hex(\"0000000000000000ff0000ff00ff00ff\"), GL_STATIC_DRAW);\n\
                glWindowPos2i(0, 0);\n\
                glDrawPixels(2, 1, GL_RGBA, GL_UNSIGNED_BYTE, ptr(0x8));\n\
                glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);\n\
                glBindBuffer(GL_PIXEL_PACK_BUFFER, 2);\n\
                glBufferData(GL_PIXEL_PACK_BUFFER, 12, NULL, GL_STREAM_READ);\n\
                glReadPixels(0, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, ptr(0x4));\n\
                glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);\n\
                glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 2);\n\
                glWindowPos2i(1, 1);\n\
                glDrawPixels(2, 1, GL_RGBA, GL_UNSIGNED_BYTE, ptr(0x4));\n\
                swap();\n";
    let mut player = Player::new(1);
    player.auto_window = true;
    let mut frames = Vec::new();
    let stats = player
        .play(
            &mut ScriptReader::new(text, Path::new(".")),
            &all_frames(),
            &mut |p| {
                frames.push(p);
                Ok(())
            },
            &mut |_| {},
        )
        .unwrap();
    assert!(
        stats.gl_errors.is_empty() && stats.unknown.is_empty(),
        "{:?}",
        stats.report_lines()
    );
    assert_eq!(frames.len(), 1);
    let img = &frames[0].image;
    let row = |y: u32| (0..4).map(|x| img.get_pixel(x, y).0).collect::<Vec<_>>();
    let (red, green, black) = ([255, 0, 0], [0, 255, 0], [0, 0, 0]);
    // Top row first: window row 1 holds the read-back drawn one pixel right, row 0 the first
    // rectangle.
    assert_eq!(row(0), vec![black, red, green, black]);
    assert_eq!(row(1), vec![red, green, black, black]);
}

/// Sampler names are remapped like texture names: a capture whose program got sampler 7 binds
/// and sets the replaying context's own sampler through that number.
#[test]
fn sampler_names_are_remapped() {
    // A 2x2 red level 0 and a 1x1 green level 1, the texture's own filter NEAREST; the
    // traced sampler 7 (a mipmap filter, LOD clamped to 1) makes the quad green.
    let text = "window(4, 4);\n\
                glGenSamplers(1, {7});\n\
                glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, hex(\"ff0000ffff0000ffff0000ffff0000ff\"));\n\
                glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, hex(\"00ff00ff\"));\n\
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);\n\
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);\n\
                glSamplerParameteri(7, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);\n\
                glSamplerParameterf(7, GL_TEXTURE_MIN_LOD, 1.0f);\n\
                glBindSampler(0, 7);\n\
                glEnable(GL_TEXTURE_2D);\n\
                glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);\n\
                glBegin(GL_QUADS);\n\
                glTexCoord2f(0.0f, 0.0f); glVertex2f(-1.0f, -1.0f);\n\
                glTexCoord2f(8.0f, 0.0f); glVertex2f(1.0f, -1.0f);\n\
                glTexCoord2f(8.0f, 8.0f); glVertex2f(1.0f, 1.0f);\n\
                glTexCoord2f(0.0f, 8.0f); glVertex2f(-1.0f, 1.0f);\n\
                glEnd();\n\
                swap();\n";
    let mut player = Player::new(1);
    player.auto_window = true;
    let mut frames = Vec::new();
    let stats = player
        .play(
            &mut ScriptReader::new(text, Path::new(".")),
            &all_frames(),
            &mut |p| {
                frames.push(p);
                Ok(())
            },
            &mut |_| {},
        )
        .unwrap();
    assert!(
        stats.gl_errors.is_empty() && stats.unknown.is_empty(),
        "{:?}",
        stats.report_lines()
    );
    assert_eq!(frames[0].image.get_pixel(2, 2).0, [0, 255, 0]);
}

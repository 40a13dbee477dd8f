//! Comparing a replay with reference pictures: a folder laid out like the shared captures'
//! `NAME.frames/` (PNG files and `frames.tsv` with the columns file, frame_index, call_no,
//! snapshot_of; optionally `softpipe/` with the same pictures from a second Mesa driver).
//!
//! Each listed picture is rendered (frames by swap number, call snapshots by call number) and
//! compared over RGB, and over alpha too where the reference has an alpha channel (the shared
//! captures' references have none: apitrace writes RGB). It matches when the share of pixels
//! whose largest channel difference exceeds 8 is at most 0.1 % ([`crate::compare::PROJECT`]),
//! or at most the share measured between Mesa's llvmpipe and softpipe on the same picture, when
//! `softpipe/FILE` exists (the shared TOLERANCE.md rule), but never more than
//! [`crate::compare::SPREAD_CAP`] (5 %).
//!
//! A reference that shows nothing drawn fails whatever the replay shows: every pixel black, or
//! every pixel the clear colour current at the snapshot. Such a picture cannot tell a working
//! replay from one that draws nothing. (A reference of one other colour is a real check: piglit
//! probes often fill the window with the one colour under test.) The exception is a capture
//! whose output is not a picture: programs that draw in `GL_SELECT` or `GL_FEEDBACK` mode,
//! where nothing drawn is Mesa's correct picture. Their check is the results of `glRenderMode`
//! (hit and value counts) the capture recorded ([`super::player::CHECKED_RESULTS`]): a
//! reference of nothing drawn passes when the results replayed up to the snapshot all match
//! and at least one of them is not zero (counted something).
//! A result that differs from the capture's fails every picture of the replay.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use crate::compare::{diff_pixels, same_colour, uniform_colour, Diff, Tolerance, PROJECT};

use super::player::{CallSource, FrameSelection, Picture, Player, ReplayError, ReplayStats, Want};

/// One row of `frames.tsv`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RefEntry {
    /// PNG file name in the folder.
    pub file: String,
    /// Swap number for frame pictures.
    pub frame: Option<u64>,
    /// The call of the snapshot (the swap call for frames).
    pub call_no: u64,
    /// The function of that call, as recorded.
    pub snapshot_of: String,
}

/// The file of a capture folder that lists its known failures.
pub const KNOWN_FAILURES_FILE: &str = "KNOWN_FAILURES.tsv";

/// The captures of folder `dir` that do not match their references yet, each with why:
/// `DIR/KNOWN_FAILURES.tsv`, one `NAME<TAB>reason` per line (`#` starts a comment line). The
/// capture tests and the conformance report read the same list; a folder without the file
/// has no known failures. A malformed line is an error naming the file and line.
pub fn known_failures(dir: &Path) -> Result<Vec<(String, String)>, String> {
    let path = dir.join(KNOWN_FAILURES_FILE);
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => return Err(format!("{}: {e}", path.display())),
    };
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if line.trim().is_empty() || line.starts_with('#') {
            continue;
        }
        match line.split_once('\t') {
            Some((name, why)) if !name.is_empty() && !why.trim().is_empty() => {
                out.push((name.to_string(), why.trim().to_string()))
            }
            _ => {
                return Err(format!(
                    "{}:{}: expected NAME<TAB>reason",
                    path.display(),
                    i + 1
                ))
            }
        }
    }
    Ok(out)
}

/// Reads `DIR/frames.tsv`.
pub fn read_frames_tsv(dir: &Path) -> Result<Vec<RefEntry>, String> {
    let path = dir.join("frames.tsv");
    let text = std::fs::read_to_string(&path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if i == 0 && line.starts_with("file") || line.trim().is_empty() {
            continue;
        }
        let bad = |what: &str| format!("{} line {}: {what}", path.display(), i + 1);
        let cols: Vec<&str> = line.split('\t').collect();
        if cols.len() < 3 {
            return Err(bad("expected file, frame_index, call_no, snapshot_of"));
        }
        let file = cols[0].trim().to_string();
        if file.is_empty() || file.contains('/') || file.contains("..") {
            return Err(bad("bad file name"));
        }
        let frame = match cols[1].trim() {
            "" => None,
            f => Some(f.parse::<u64>().map_err(|_| bad("bad frame_index"))?),
        };
        let call_no = cols[2]
            .trim()
            .parse::<u64>()
            .map_err(|_| bad("bad call_no"))?;
        out.push(RefEntry {
            file,
            frame,
            call_no,
            snapshot_of: cols.get(3).unwrap_or(&"").trim().to_string(),
        });
    }
    Ok(out)
}

/// What to render for these entries: frames by number, the other pictures by call.
pub fn want_for(entries: &[RefEntry]) -> Want {
    let frames: BTreeSet<u64> = entries.iter().filter_map(|e| e.frame).collect();
    let calls: BTreeSet<u64> = entries
        .iter()
        .filter(|e| e.frame.is_none())
        .map(|e| e.call_no)
        .collect();
    Want {
        frames: FrameSelection::List(frames),
        calls,
        stop_early: true,
    }
}

/// The comparison of one picture.
#[derive(Clone, Debug)]
pub struct PictureResult {
    pub file: String,
    /// `None` when the replay did not produce the picture.
    pub diff: Option<Diff>,
    /// Reference against `softpipe/FILE`, when present.
    pub softpipe: Option<Diff>,
    /// The tolerance applied.
    pub tolerance: Tolerance,
    /// Whether alpha was compared too (the reference has an alpha channel).
    pub alpha: bool,
    pub ok: bool,
    /// Why a picture failed without figures, or a size mismatch.
    pub note: String,
}

impl PictureResult {
    /// One line: file, PSNR, max difference, bad share, allowed share, verdict.
    pub fn line(&self) -> String {
        let verdict = if self.ok { "ok" } else { "FAIL" };
        match &self.diff {
            Some(d) => format!(
                "{:<22} PSNR {:>7} dB  max {:>3}  bad(>{}) {:>7.3}%  allowed {:.3}%{}  {verdict}{}",
                self.file,
                if d.psnr.is_infinite() {
                    "inf".to_string()
                } else {
                    format!("{:.2}", d.psnr)
                },
                d.max,
                d.threshold,
                d.bad_share * 100.0,
                self.tolerance.max_bad_share * 100.0,
                if self.alpha { " (RGBA)" } else { "" },
                if self.note.is_empty() {
                    String::new()
                } else {
                    format!(" ({})", self.note)
                }
            ),
            None => format!("{:<22} {verdict}: {}", self.file, self.note),
        }
    }
}

/// A replay compared with a reference folder.
#[derive(Clone, Debug)]
pub struct CompareReport {
    pub pictures: Vec<PictureResult>,
    pub stats: ReplayStats,
    /// Set when the replay stopped on an error.
    pub error: Option<ReplayError>,
}

impl CompareReport {
    /// Whether every picture matched.
    pub fn all_ok(&self) -> bool {
        !self.pictures.is_empty() && self.pictures.iter().all(|p| p.ok)
    }

    /// The summary line.
    pub fn summary(&self) -> String {
        let ok = self.pictures.iter().filter(|p| p.ok).count();
        let worst = self
            .pictures
            .iter()
            .filter_map(|p| p.diff.map(|d| d.psnr))
            .fold(f64::INFINITY, f64::min);
        let worst_bad = self
            .pictures
            .iter()
            .filter_map(|p| p.diff.map(|d| d.bad_share))
            .fold(0.0, f64::max);
        format!(
            "{ok}/{} pictures within tolerance; min PSNR {} dB, max bad(>8) {:.3}%; {} calls, {} frames",
            self.pictures.len(),
            if worst.is_infinite() {
                "inf".to_string()
            } else {
                format!("{worst:.2}")
            },
            worst_bad * 100.0,
            self.stats.calls,
            self.stats.frames
        )
    }
}

fn load(path: &Path) -> Result<image::DynamicImage, String> {
    image::open(path).map_err(|e| format!("cannot read {}: {e}", path.display()))
}

/// A picture's pixels with alpha (`alpha`: RGBA) or without (RGB), top row first.
fn raw_pixels(image: &image::DynamicImage, alpha: bool) -> Vec<u8> {
    if alpha {
        image.to_rgba8().into_raw()
    } else {
        image.to_rgb8().into_raw()
    }
}

/// Why a reference (`channels` bytes per pixel) cannot check anything, if it cannot: every
/// pixel black, or every pixel `clear` (the clear colour at the snapshot, when known).
pub fn empty_reference(pixels: &[u8], channels: usize, clear: Option<[u8; 4]>) -> Option<String> {
    let c = uniform_colour(pixels, channels)?;
    let what = if c[..3] == [0, 0, 0] {
        "black"
    } else if clear.is_some_and(|k| same_colour(c, &k)) {
        "the clear colour"
    } else {
        return None;
    };
    Some(format!(
        "the reference shows nothing drawn: every pixel is {c:?}, {what}"
    ))
}

/// Compares a rendered picture with a reference (RGB, top row first).
pub fn diff_rgb(ours: &image::RgbImage, reference: &image::RgbImage, threshold: u8) -> Diff {
    if ours.dimensions() != reference.dimensions() {
        let (w, h) = reference.dimensions();
        return Diff::total(w, h, threshold);
    }
    diff_pixels(
        ours.as_raw(),
        reference.as_raw(),
        3,
        ours.width(),
        threshold,
    )
}

/// `image` (rows top-down) placed at the lower left of a black `width` x `height` picture,
/// as GL's window origin is the lower-left corner.
pub fn embed_lower_left<P: image::Pixel>(
    image: &image::ImageBuffer<P, Vec<P::Subpixel>>,
    width: u32,
    height: u32,
) -> image::ImageBuffer<P, Vec<P::Subpixel>> {
    let mut out = image::ImageBuffer::new(width, height);
    let dy = height.saturating_sub(image.height());
    for (x, y, px) in image.enumerate_pixels() {
        if x < width && y + dy < height {
            out.put_pixel(x, y + dy, *px);
        }
    }
    out
}

/// The tolerance for a picture of `dir`: the project rule, widened to the llvmpipe-vs-softpipe
/// spread when `dir/softpipe/FILE` exists, up to [`crate::compare::SPREAD_CAP`]. Returns the
/// softpipe figures too (uncapped). Alpha is compared when the reference has it.
pub fn tolerance_for(
    dir: &Path,
    file: &str,
    reference: &image::DynamicImage,
) -> (Tolerance, Option<Diff>) {
    let alpha = reference.color().has_alpha();
    let sp_path = dir.join("softpipe").join(file);
    let softpipe = sp_path
        .is_file()
        .then(|| load(&sp_path).ok())
        .flatten()
        .map(|sp| {
            if sp.width() != reference.width() || sp.height() != reference.height() {
                return Diff::total(reference.width(), reference.height(), PROJECT.channel);
            }
            diff_pixels(
                &raw_pixels(&sp, alpha),
                &raw_pixels(reference, alpha),
                if alpha { 4 } else { 3 },
                reference.width(),
                PROJECT.channel,
            )
        });
    let tolerance = softpipe.map_or(PROJECT, |d| PROJECT.widened_to(d.bad_share));
    (tolerance, softpipe)
}

/// A rendered picture as RGBA (its RGB and alpha planes joined), top row first.
fn picture_rgba(p: &Picture) -> image::RgbaImage {
    let (w, h) = p.image.dimensions();
    image::RgbaImage::from_fn(w, h, |x, y| {
        let [r, g, b] = p.image.get_pixel(x, y).0;
        let a = p.alpha.get_pixel_checked(x, y).map_or(255, |a| a.0[0]);
        image::Rgba([r, g, b, a])
    })
}

/// Replays `source` on `player` with the pictures listed in `dir/frames.tsv` and compares
/// them. Rendered pictures are also written into `out` when given. The replay stops after the
/// last listed picture.
pub fn compare_replay(
    source: &mut dyn CallSource,
    player: &mut Player,
    dir: &Path,
    out: Option<&Path>,
    progress: &mut dyn FnMut(&ReplayStats),
) -> Result<CompareReport, String> {
    let entries = read_frames_tsv(dir)?;
    if entries.is_empty() {
        return Err(format!(
            "{}: no pictures listed",
            dir.join("frames.tsv").display()
        ));
    }
    let want = want_for(&entries);
    let mut rendered: Vec<Picture> = Vec::new();
    let mut sink = |p: Picture| -> Result<(), String> {
        if let Some(out) = out {
            p.image
                .save_with_format(out.join(&p.file), image::ImageFormat::Png)
                .map_err(|e| e.to_string())?;
        }
        rendered.push(p);
        Ok(())
    };
    let result = player.play(source, &want, &mut sink, progress);
    let (stats, error) = match result {
        Ok(s) => (s, None),
        Err(e) => (player.stats(), Some(e)),
    };
    let mut pictures = Vec::new();
    for e in &entries {
        let found = rendered.iter().find(|p| match e.frame {
            Some(f) => p.frame == Some(f),
            None => p.frame.is_none() && p.call_no == e.call_no,
        });
        let ref_path: PathBuf = dir.join(&e.file);
        let reference = match load(&ref_path) {
            Ok(r) => r,
            Err(msg) => {
                pictures.push(PictureResult {
                    file: e.file.clone(),
                    diff: None,
                    softpipe: None,
                    tolerance: PROJECT,
                    alpha: false,
                    ok: false,
                    note: msg,
                });
                continue;
            }
        };
        let alpha = reference.color().has_alpha();
        let channels = if alpha { 4 } else { 3 };
        let ref_pixels = raw_pixels(&reference, alpha);
        let (tolerance, softpipe) = tolerance_for(dir, &e.file, &reference);
        let Some(p) = found else {
            pictures.push(PictureResult {
                file: e.file.clone(),
                diff: None,
                softpipe,
                tolerance,
                alpha,
                ok: false,
                note: match &error {
                    Some(err) => format!("not rendered: the replay stopped at {err}"),
                    None => format!(
                        "not rendered: the replay has no {} (no current context or too few calls/frames)",
                        e.frame.map_or(format!("call {}", e.call_no), |f| format!("frame {f}"))
                    ),
                },
            });
            continue;
        };
        let mut note = String::new();
        if e.frame.is_some() && p.call_no != e.call_no {
            note = format!(
                "swap at call {} here, {} in frames.tsv",
                p.call_no, e.call_no
            );
        }
        let (w, h) = p.image.dimensions();
        let (rw, rh) = (reference.width(), reference.height());
        let mut ours = picture_rgba(p);
        let mut comparable = true;
        if (w, h) != (rw, rh) {
            if w <= rw && h <= rh {
                // The reference was read from a bigger window than the traced one (glretrace's
                // replay window; see the shared MANIFEST.md): the traced window is its
                // lower-left part and the rest shows nothing drawn.
                ours = embed_lower_left(&ours, rw, rh);
                note = format!(
                    "window {w}x{h} in a {rw}x{rh} reference: lower-left aligned, outside black"
                );
            } else {
                note = format!("size {w}x{h}, reference {rw}x{rh}");
                comparable = false;
            }
        }
        let diff = if comparable {
            let ours = raw_pixels(&image::DynamicImage::ImageRgba8(ours), alpha);
            diff_pixels(&ours, &ref_pixels, channels, rw, tolerance.channel)
        } else {
            Diff::total(rw, rh, tolerance.channel)
        };
        let mut ok = tolerance.accepts(&diff);
        // Results up to the snapshot; a zero (entering a mode, or nothing counted) shows no
        // work done, so only the others count as checks.
        let results: Vec<_> = stats
            .results
            .iter()
            .filter(|r| r.call_no <= p.call_no)
            .collect();
        let checked = results.iter().filter(|r| r.traced != 0).count();
        let mismatched = results.iter().filter(|r| !r.matches()).count();
        let mut add_note = |why: String| {
            note = if note.is_empty() {
                why
            } else {
                format!("{note}; {why}")
            };
        };
        if let Some(why) = empty_reference(&ref_pixels, channels, Some(p.clear_color)) {
            if checked > 0 && mismatched == 0 {
                add_note(format!(
                    "nothing drawn, as in the reference; checked by {checked} glRenderMode results equal to the capture's"
                ));
            } else {
                ok = false;
                add_note(why);
            }
        }
        if mismatched > 0 {
            ok = false;
            add_note(format!(
                "{mismatched} of {} glRenderMode results differ from the capture's",
                results.len()
            ));
        }
        pictures.push(PictureResult {
            file: e.file.clone(),
            diff: Some(diff),
            softpipe,
            tolerance,
            alpha,
            ok,
            note,
        });
    }
    Ok(CompareReport {
        pictures,
        stats,
        error,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_smaller_window_sits_at_the_lower_left() {
        let mut small = image::RgbImage::new(2, 1);
        small.put_pixel(0, 0, image::Rgb([9, 8, 7]));
        let big = embed_lower_left(&small, 3, 2);
        // PNG rows are top-down: the window's only row is the picture's last.
        assert_eq!(big.get_pixel(0, 1).0, [9, 8, 7]);
        assert_eq!(big.get_pixel(0, 0).0, [0, 0, 0]);
        assert_eq!(big.get_pixel(2, 1).0, [0, 0, 0]);
    }

    #[test]
    fn frames_tsv_rows_name_frames_or_calls() {
        let dir = std::env::temp_dir().join(format!("tilegl-tsv-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("frames.tsv"),
            "file\tframe_index\tcall_no\tsnapshot_of\n\
             frame-0017.png\t17\t1744\tglXSwapBuffers\n\
             call-0000000831.png\t\t831\tglReadPixels\n",
        )
        .unwrap();
        let e = read_frames_tsv(&dir).unwrap();
        assert_eq!(e.len(), 2);
        assert_eq!((e[0].frame, e[0].call_no), (Some(17), 1744));
        assert_eq!((e[1].frame, e[1].call_no), (None, 831));
        let want = want_for(&e);
        assert_eq!(
            want.frames,
            FrameSelection::List([17].into_iter().collect())
        );
        assert_eq!(want.calls, [831].into_iter().collect());
        std::fs::write(
            dir.join("frames.tsv"),
            "file\tframe_index\tcall_no\n../x.png\t\t1\n",
        )
        .unwrap();
        assert!(read_frames_tsv(&dir).unwrap_err().contains("line 2"));
        let _ = std::fs::remove_dir_all(&dir);
    }
}

//! Picture comparison shared by the conformance suite (tilegl against Mesa) and trace replay
//! (`tilegl replay --compare`, tilegl against Mesa's reference pictures): per-picture error
//! figures ([`Diff`]) and the rule that decides whether a picture matches ([`Tolerance`]).

use std::fmt;

/// How far two pictures differ. Channel figures are over the channels compared (RGBA for
/// the conformance suite, RGB for reference pictures without alpha).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Diff {
    /// PSNR in dB over the compared channels (infinite when identical).
    pub psnr: f64,
    /// Largest channel difference (0-255).
    pub max: u8,
    /// Mean absolute channel difference.
    pub mean: f64,
    /// Share (0-1) of pixels whose largest channel difference exceeds the threshold.
    pub bad_share: f64,
    /// Number of such pixels.
    pub bad_pixels: usize,
    /// The threshold `bad_share` was computed with.
    pub threshold: u8,
    /// The first pixel (x, y) over the threshold (in the pixel order given), for reports.
    pub first_bad: Option<(i32, i32)>,
}

impl fmt::Display for Diff {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "PSNR {:.2} dB, max {}, mean {:.4}, bad(>{}) {:.3}% ({} px)",
            self.psnr,
            self.max,
            self.mean,
            self.threshold,
            self.bad_share * 100.0,
            self.bad_pixels
        )?;
        if let Some((x, y)) = self.first_bad {
            write!(f, ", first at ({x},{y})")?;
        }
        Ok(())
    }
}

impl Diff {
    /// The figures of two pictures that cannot be compared (different sizes): everything bad.
    pub fn total(width: u32, height: u32, threshold: u8) -> Diff {
        Diff {
            psnr: 0.0,
            max: 255,
            mean: 255.0,
            bad_share: 1.0,
            bad_pixels: width as usize * height as usize,
            threshold,
            first_bad: Some((0, 0)),
        }
    }
}

/// Compares two pictures stored the same way: `channels` bytes per pixel, `width` pixels per
/// row, rows in the same order. A pixel is bad when its largest channel difference exceeds
/// `threshold`. Buffers of different lengths compare as totally different.
pub fn diff_pixels(a: &[u8], b: &[u8], channels: usize, width: u32, threshold: u8) -> Diff {
    let channels = channels.max(1);
    let width = width.max(1) as usize;
    if a.len() != b.len() || !a.len().is_multiple_of(channels) {
        let px = (a.len().max(b.len()) / channels) as u32;
        return Diff::total(px, 1, threshold);
    }
    let mut sq = 0u64;
    let mut sum = 0u64;
    let mut max = 0u8;
    let mut bad = 0usize;
    let mut first_bad = None;
    for (i, (pa, pb)) in a.chunks(channels).zip(b.chunks(channels)).enumerate() {
        let mut pmax = 0u8;
        for c in 0..channels {
            let d = pa[c].abs_diff(pb[c]);
            pmax = pmax.max(d);
            sum += d as u64;
            sq += d as u64 * d as u64;
        }
        max = max.max(pmax);
        if pmax > threshold {
            bad += 1;
            if first_bad.is_none() {
                first_bad = Some(((i % width) as i32, (i / width) as i32));
            }
        }
    }
    let n = a.len().max(1) as f64;
    let mse = sq as f64 / n;
    let psnr = if mse == 0.0 {
        f64::INFINITY
    } else {
        10.0 * (255.0f64 * 255.0 / mse).log10()
    };
    let px = (a.len() / channels).max(1);
    Diff {
        psnr,
        max,
        mean: sum as f64 / n,
        bad_share: bad as f64 / px as f64,
        bad_pixels: bad,
        threshold,
        first_bad,
    }
}

/// A pixel is bad when its largest channel difference exceeds `channel`; a picture matches when
/// at most `max_bad_share` of its pixels are bad.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// Per-channel threshold (0-255).
    pub channel: u8,
    /// Largest accepted share (0-1) of bad pixels.
    pub max_bad_share: f64,
}

impl Tolerance {
    /// Whether `diff` (computed with this tolerance's threshold) is acceptable.
    pub fn accepts(&self, diff: &Diff) -> bool {
        diff.threshold <= self.channel && diff.bad_share <= self.max_bad_share
    }
}

impl fmt::Display for Tolerance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "bad(>{}) <= {:.3}%",
            self.channel,
            self.max_bad_share * 100.0
        )
    }
}

/// The project rule (conformance/TOLERANCE.md, shared traces/TOLERANCE.md): at most 0.1 % of
/// the pixels may differ by more than 8 in some channel.
pub const PROJECT: Tolerance = Tolerance {
    channel: 8,
    max_bad_share: 0.001,
};

/// The largest share of bad pixels a picture may have however far Mesa's two drivers
/// (llvmpipe and softpipe) differ on it: 5 %.
///
/// Why 5 %: the shared TOLERANCE.md measures llvmpipe against softpipe on every reference
/// picture. The largest spread at threshold 8 among its 55 calibrated pictures is 3.767 %
/// (xss-glblur frame-0029: rounding accumulated over a CopyTexImage blur feedback loop), and
/// its advice is "~4 % for glblur-like feedback/blur scenes"; every other picture is within
/// 0.3 %. 5 % keeps the worst legitimate case with a margin of a third, while a picture the two
/// drivers render very differently (xss-quasicrystal, about 19 %: logic op and DST_COLOR
/// blending over a 1D texture) can no longer excuse a fifth of the picture being wrong: there,
/// tilegl must agree with llvmpipe within 5 % like everywhere else.
pub const SPREAD_CAP: f64 = 0.05;

impl Tolerance {
    /// This tolerance widened to `spread`, the bad share measured between two conformant
    /// drivers on the same picture, but never beyond [`SPREAD_CAP`] (and never narrowed).
    pub fn widened_to(self, spread: f64) -> Tolerance {
        let spread = if spread.is_nan() { 0.0 } else { spread };
        Tolerance {
            channel: self.channel,
            max_bad_share: self.max_bad_share.max(spread.min(SPREAD_CAP)),
        }
    }
}

/// The colour of every pixel when a picture (`channels` bytes per pixel) has only one, else
/// `None`. A picture with no pixels has none.
pub fn uniform_colour(pixels: &[u8], channels: usize) -> Option<&[u8]> {
    let channels = channels.max(1);
    let first = pixels.get(..channels)?;
    pixels.chunks(channels).all(|p| p == first).then_some(first)
}

/// Whether two colours are the same within one step per channel (a float colour converted to
/// 8 bits may round either way), comparing the channels both have.
pub fn same_colour(a: &[u8], b: &[u8]) -> bool {
    a.iter().zip(b).all(|(x, y)| x.abs_diff(*y) <= 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identical_pictures_have_infinite_psnr() {
        let a = [1u8, 2, 3, 4, 5, 6];
        let d = diff_pixels(&a, &a, 3, 2, 8);
        assert_eq!(d.psnr, f64::INFINITY);
        assert_eq!((d.max, d.bad_pixels), (0, 0));
        assert!(PROJECT.accepts(&d));
    }

    #[test]
    fn bad_pixels_are_counted_by_their_largest_channel() {
        let a = [0u8; 12];
        let b = [0u8, 0, 9, 0, 8, 0, 0, 0, 0, 255, 0, 0];
        let d = diff_pixels(&a, &b, 3, 2, 8);
        assert_eq!(d.bad_pixels, 2);
        assert_eq!(d.first_bad, Some((0, 0)));
        assert_eq!(d.max, 255);
        assert!((d.bad_share - 0.5).abs() < 1e-12);
        let mse = (81.0 + 64.0 + 255.0 * 255.0) / 12.0;
        assert!((d.psnr - 10.0 * (255.0f64 * 255.0 / mse).log10()).abs() < 1e-9);
        assert!(!PROJECT.accepts(&d));
        assert_eq!(diff_pixels(&a, &b[..9], 3, 2, 8).bad_share, 1.0);
    }

    #[test]
    fn a_measured_spread_widens_the_tolerance_up_to_the_cap() {
        // Below the project rule: no change; between: the spread; above the cap: the cap.
        assert_eq!(PROJECT.widened_to(0.0004).max_bad_share, 0.001);
        assert_eq!(PROJECT.widened_to(0.03767).max_bad_share, 0.03767);
        assert_eq!(PROJECT.widened_to(0.19).max_bad_share, 0.05);
        assert_eq!(PROJECT.widened_to(1.0).max_bad_share, 0.05);
        assert_eq!(PROJECT.widened_to(f64::NAN).max_bad_share, 0.001);
        assert_eq!(PROJECT.widened_to(0.19).channel, PROJECT.channel);
        // A picture 10 % off is refused even where the drivers differ on all pixels; 4 % is
        // accepted there and refused where they agree.
        let a = [0u8; 300];
        let mut b = [0u8; 300];
        b[..30].fill(255);
        let ten = diff_pixels(&a, &b, 3, 10, 8);
        assert!(!PROJECT.widened_to(1.0).accepts(&ten));
        let mut c = [0u8; 300 * 3];
        c[..36].fill(255);
        let four = diff_pixels(&[0u8; 900], &c, 3, 30, 8);
        assert!((four.bad_share - 0.04).abs() < 1e-12);
        assert!(PROJECT.widened_to(1.0).accepts(&four));
        assert!(!PROJECT.widened_to(0.0).accepts(&four));
    }

    #[test]
    fn one_colour_pictures_are_recognised() {
        assert_eq!(
            uniform_colour(&[5, 6, 7, 5, 6, 7], 3),
            Some(&[5u8, 6, 7][..])
        );
        assert_eq!(uniform_colour(&[5, 6, 7, 5, 6, 8], 3), None);
        assert_eq!(uniform_colour(&[], 3), None);
        assert!(same_colour(&[128, 0, 255], &[127, 1, 255, 9]));
        assert!(!same_colour(&[128, 0, 255], &[126, 0, 255]));
    }
}

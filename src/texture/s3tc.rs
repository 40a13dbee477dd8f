//! S3TC (DXT1, DXT3, DXT5) block decoding and a simple encoder (EXT_texture_compression_s3tc).
//!
//! A block covers 4x4 texels; texel k = 4 * row + column, rows bottom to top in GL's image
//! order. Decoded values are the specification's real-valued formulas rounded to 8 bits.
//!
//! The encoder is deliberately simple and exact about the format rather than about quality:
//! the colour endpoints are the two texels of the block farthest apart (squared RGB distance,
//! quantised to 5:6:5 and ordered so `color0 > color1`, the four-colour mode), and each texel
//! takes the nearest of the palette entries. Blocks of one or two colours (exactly
//! representable in 5:6:5) therefore round-trip exactly. DXT1 with alpha uses the three-colour
//! mode (`color0 <= color1`) when any texel has alpha below 128, and those texels get the
//! transparent index 3. DXT3 stores alpha rounded to 4 bits; DXT5 uses the
//! block's alpha maximum and minimum as endpoints (eight-value mode) and the nearest index.

use super::format::S3tcFormat;

/// 5:6:5 colour to normalised RGB.
fn rgb565(c: u16) -> [f32; 3] {
    [
        ((c >> 11) & 31) as f32 / 31.0,
        ((c >> 5) & 63) as f32 / 63.0,
        (c & 31) as f32 / 31.0,
    ]
}

fn to_u8(v: f32) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// The four-entry RGBA palette of a colour block. `four_color` forces the four-colour mode
/// (DXT3/DXT5); `transparent_black` makes entry 3 of the three-colour mode (0,0,0,0) instead
/// of opaque black (RGBA versus RGB DXT1).
fn palette(c0: u16, c1: u16, four_color: bool, transparent_black: bool) -> [[u8; 4]; 4] {
    let (a, b) = (rgb565(c0), rgb565(c1));
    let mix = |wa: f32, wb: f32, d: f32| -> [u8; 4] {
        [
            to_u8((wa * a[0] + wb * b[0]) / d),
            to_u8((wa * a[1] + wb * b[1]) / d),
            to_u8((wa * a[2] + wb * b[2]) / d),
            255,
        ]
    };
    let p0 = mix(1.0, 0.0, 1.0);
    let p1 = mix(0.0, 1.0, 1.0);
    if four_color || c0 > c1 {
        [p0, p1, mix(2.0, 1.0, 3.0), mix(1.0, 2.0, 3.0)]
    } else {
        let black = if transparent_black {
            [0, 0, 0, 0]
        } else {
            [0, 0, 0, 255]
        };
        [p0, p1, mix(1.0, 1.0, 2.0), black]
    }
}

fn u16_at(b: &[u8], i: usize) -> u16 {
    u16::from_le_bytes([
        b.get(i).copied().unwrap_or(0),
        b.get(i + 1).copied().unwrap_or(0),
    ])
}

fn u32_at(b: &[u8], i: usize) -> u32 {
    u32::from_le_bytes([0, 1, 2, 3].map(|k| b.get(i + k).copied().unwrap_or(0)))
}

fn decode_colors(f: S3tcFormat, b: &[u8], out: &mut [[u8; 4]; 16]) {
    let four = !matches!(f, S3tcFormat::RgbDxt1 | S3tcFormat::RgbaDxt1);
    let pal = palette(u16_at(b, 0), u16_at(b, 2), four, f == S3tcFormat::RgbaDxt1);
    let bits = u32_at(b, 4);
    for (k, o) in out.iter_mut().enumerate() {
        *o = pal[((bits >> (2 * k)) & 3) as usize];
    }
}

/// The eight DXT5 alpha values of endpoints `a0`, `a1`.
fn alpha_palette(a0: u8, a1: u8) -> [u8; 8] {
    let (x, y) = (a0 as f32, a1 as f32);
    let mut p = [a0, a1, 0, 0, 0, 0, 0, 0];
    if a0 > a1 {
        for i in 1..7 {
            p[i + 1] = (((7 - i) as f32 * x + i as f32 * y) / 7.0).round() as u8;
        }
    } else {
        for i in 1..5 {
            p[i + 1] = (((5 - i) as f32 * x + i as f32 * y) / 5.0).round() as u8;
        }
        p[6] = 0;
        p[7] = 255;
    }
    p
}

/// Decodes one block (8 bytes for DXT1, 16 for DXT3/5; missing bytes read as 0) to RGBA8.
pub fn decode_block(f: S3tcFormat, block: &[u8]) -> [[u8; 4]; 16] {
    let mut out = [[0u8; 4]; 16];
    match f {
        S3tcFormat::RgbDxt1 | S3tcFormat::RgbaDxt1 => decode_colors(f, block, &mut out),
        S3tcFormat::RgbaDxt3 => {
            decode_colors(f, block.get(8..).unwrap_or(&[]), &mut out);
            let bits = u32_at(block, 0) as u64 | (u32_at(block, 4) as u64) << 32;
            for (k, o) in out.iter_mut().enumerate() {
                o[3] = ((bits >> (4 * k)) & 15) as u8 * 17;
            }
        }
        S3tcFormat::RgbaDxt5 => {
            decode_colors(f, block.get(8..).unwrap_or(&[]), &mut out);
            let pal = alpha_palette(
                block.first().copied().unwrap_or(0),
                block.get(1).copied().unwrap_or(0),
            );
            let mut bits = 0u64;
            for i in 0..6 {
                bits |= (block.get(2 + i).copied().unwrap_or(0) as u64) << (8 * i);
            }
            for (k, o) in out.iter_mut().enumerate() {
                o[3] = pal[((bits >> (3 * k)) & 7) as usize];
            }
        }
    }
    out
}

fn to565(c: [u8; 4]) -> u16 {
    let q = |v: u8, max: u32| ((v as u32 * max + 127) / 255) as u16;
    (q(c[0], 31) << 11) | (q(c[1], 63) << 5) | q(c[2], 31)
}

fn dist2(a: [u8; 4], b: [u8; 4]) -> i32 {
    (0..3)
        .map(|i| {
            let d = a[i] as i32 - b[i] as i32;
            d * d
        })
        .sum()
}

/// Encodes one block from RGBA8 texels; `present` marks texels inside the image (the others
/// are ignored). Returns 16 bytes, of which DXT1 uses the first 8.
pub fn encode_block(f: S3tcFormat, px: &[[u8; 4]; 16], present: &[bool; 16]) -> [u8; 16] {
    let dxt1a = f == S3tcFormat::RgbaDxt1;
    let transparent = |k: usize| dxt1a && px[k][3] < 128;
    let opaque: Vec<usize> = (0..16).filter(|&k| present[k] && !transparent(k)).collect();
    let any_transparent = (0..16).any(|k| present[k] && transparent(k));
    // Endpoints: the two opaque texels farthest apart.
    let (mut e0, mut e1) = ([0u8; 4], [0u8; 4]);
    if let Some(&first) = opaque.first() {
        (e0, e1) = (px[first], px[first]);
        let mut best = -1;
        for (n, &a) in opaque.iter().enumerate() {
            for &b in &opaque[n..] {
                let d = dist2(px[a], px[b]);
                if d > best {
                    best = d;
                    (e0, e1) = (px[a], px[b]);
                }
            }
        }
    }
    let (mut c0, mut c1) = (to565(e0), to565(e1));
    // Four-colour mode needs color0 > color1, DXT1's transparent mode color0 <= color1.
    if (any_transparent && c0 > c1) || (!any_transparent && c0 < c1) {
        std::mem::swap(&mut c0, &mut c1);
    }
    let four = !matches!(f, S3tcFormat::RgbDxt1 | S3tcFormat::RgbaDxt1);
    let pal = palette(c0, c1, four, dxt1a);
    let usable = if four || c0 > c1 { 4 } else { 3 };
    let mut idx = 0u32;
    for k in 0..16 {
        let i = if !present[k] {
            0
        } else if transparent(k) {
            3
        } else {
            (0..usable)
                .min_by_key(|&i| dist2(px[k], pal[i]))
                .unwrap_or(0)
        };
        idx |= (i as u32) << (2 * k);
    }
    let mut color = [0u8; 8];
    color[0..2].copy_from_slice(&c0.to_le_bytes());
    color[2..4].copy_from_slice(&c1.to_le_bytes());
    color[4..8].copy_from_slice(&idx.to_le_bytes());
    let mut out = [0u8; 16];
    match f {
        S3tcFormat::RgbDxt1 | S3tcFormat::RgbaDxt1 => out[..8].copy_from_slice(&color),
        S3tcFormat::RgbaDxt3 => {
            let mut bits = 0u64;
            for k in 0..16 {
                let a = if present[k] {
                    (px[k][3] as u32 * 15 + 127) / 255
                } else {
                    0
                };
                bits |= (a as u64) << (4 * k);
            }
            out[..8].copy_from_slice(&bits.to_le_bytes());
            out[8..].copy_from_slice(&color);
        }
        S3tcFormat::RgbaDxt5 => {
            let (mut amin, mut amax) = (255u8, 0u8);
            for k in 0..16 {
                if present[k] {
                    amin = amin.min(px[k][3]);
                    amax = amax.max(px[k][3]);
                }
            }
            if amin > amax {
                amin = 0;
                amax = 0;
            }
            let pal = alpha_palette(amax, amin);
            let mut bits = 0u64;
            for k in 0..16 {
                let i = if present[k] && amax > amin {
                    (0..8)
                        .min_by_key(|&i| (pal[i] as i32 - px[k][3] as i32).abs())
                        .unwrap_or(0)
                } else {
                    0
                };
                bits |= (i as u64) << (3 * k);
            }
            out[0] = amax;
            out[1] = amin;
            out[2..8].copy_from_slice(&bits.to_le_bytes()[..6]);
            out[8..].copy_from_slice(&color);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dxt1_four_color_block_by_hand() {
        // color0 = pure red (31,0,0) = 0xF800, color1 = pure blue (0,0,31) = 0x001F.
        // Indices: texel k uses k % 4.
        let mut idx = 0u32;
        for k in 0..16 {
            idx |= ((k % 4) as u32) << (2 * k);
        }
        let mut b = vec![0x00, 0xF8, 0x1F, 0x00];
        b.extend_from_slice(&idx.to_le_bytes());
        let d = decode_block(S3tcFormat::RgbDxt1, &b);
        assert_eq!(d[0], [255, 0, 0, 255]);
        assert_eq!(d[1], [0, 0, 255, 255]);
        // (2*c0 + c1)/3 = (2/3, 0, 1/3) -> 170, 0, 85
        assert_eq!(d[2], [170, 0, 85, 255]);
        assert_eq!(d[3], [85, 0, 170, 255]);
    }

    #[test]
    fn dxt1_three_color_block_and_transparency() {
        // color0 = 0x001F (blue) <= color1 = 0xF800 (red): three-colour mode.
        let idx: u32 = 0b11_10_01_00;
        let mut b = vec![0x1F, 0x00, 0x00, 0xF8];
        b.extend_from_slice(&idx.to_le_bytes());
        let rgb = decode_block(S3tcFormat::RgbDxt1, &b);
        assert_eq!(rgb[2], [128, 0, 128, 255]); // (c0 + c1) / 2 = 0.5 -> 127.5 -> 128
        assert_eq!(rgb[3], [0, 0, 0, 255]);
        let rgba = decode_block(S3tcFormat::RgbaDxt1, &b);
        assert_eq!(rgba[3], [0, 0, 0, 0]);
    }

    #[test]
    fn dxt3_and_dxt5_alpha_by_hand() {
        // DXT3: texel k alpha = k (4 bits) -> k * 17.
        let mut bits = 0u64;
        for k in 0..16u64 {
            bits |= k << (4 * k);
        }
        let mut b = bits.to_le_bytes().to_vec();
        b.extend_from_slice(&[0xFF, 0xFF, 0, 0, 0, 0, 0, 0]);
        let d = decode_block(S3tcFormat::RgbaDxt3, &b);
        for (k, t) in d.iter().enumerate() {
            assert_eq!(t[3] as usize, k * 17);
            assert_eq!(t[0], 255);
        }
        // DXT5: a0 = 200 > a1 = 10: index 2 = (6*200 + 10)/7 = 172.857 -> 173.
        let mut b = vec![200, 10];
        let idx: u64 = 2 | (1 << 3) | (7 << 6);
        b.extend_from_slice(&idx.to_le_bytes()[..6]);
        b.extend_from_slice(&[0; 8]);
        let d = decode_block(S3tcFormat::RgbaDxt5, &b);
        assert_eq!(d[0][3], 173);
        assert_eq!(d[1][3], 10);
        assert_eq!(d[2][3], 37); // (200 + 6*10)/7 = 37.14
                                 // a0 <= a1: six-value mode, 6 -> 0, 7 -> 255.
        let mut b = vec![10, 200];
        let idx: u64 = 6 | (7 << 3) | (2 << 6);
        b.extend_from_slice(&idx.to_le_bytes()[..6]);
        b.extend_from_slice(&[0; 8]);
        let d = decode_block(S3tcFormat::RgbaDxt5, &b);
        assert_eq!(d[0][3], 0);
        assert_eq!(d[1][3], 255);
        assert_eq!(d[2][3], 48); // (4*10 + 200)/5 = 48
    }

    #[test]
    fn encoder_round_trips_two_color_blocks() {
        let mut px = [[0u8; 4]; 16];
        for (k, p) in px.iter_mut().enumerate() {
            *p = if k % 2 == 0 {
                [255, 0, 0, 255]
            } else {
                [0, 255, 0, 0]
            };
        }
        let present = [true; 16];
        for f in [
            S3tcFormat::RgbDxt1,
            S3tcFormat::RgbaDxt1,
            S3tcFormat::RgbaDxt3,
            S3tcFormat::RgbaDxt5,
        ] {
            let d = decode_block(f, &encode_block(f, &px, &present));
            assert_eq!(d[0], [255, 0, 0, 255], "{f:?}");
            match f {
                S3tcFormat::RgbDxt1 => assert_eq!(d[1], [0, 255, 0, 255]),
                S3tcFormat::RgbaDxt1 => assert_eq!(d[1], [0, 0, 0, 0]),
                _ => assert_eq!(d[1], [0, 255, 0, 0], "{f:?}"),
            }
        }
    }
}

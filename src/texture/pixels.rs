//! Pixel unpacking (client memory -> RGBA, section 3.6.4) for texture images, and packing
//! (texture -> client memory, section 4.3.2 as used by `glGetTexImage`).
//!
//! Client data is in the machine's byte order; `GL_UNPACK_SWAP_BYTES` reverses the bytes of
//! each element (a component, or a whole packed group). `GL_UNPACK_LSB_FIRST` concerns only
//! `GL_BITMAP` data, which texture images do not take. Signed and unsigned integers become
//! floats by table 2.9 of OpenGL 1.5: unsigned `c / (2^b - 1)`, signed `(2c + 1) / (2^b - 1)`.

use std::sync::Arc;

use crate::common::values::{TexPixelFormat, TexPixelType};
use crate::state::tables::PixelStore;
use crate::texture::image::{TexImage, Texels};

/// Where the pixels of an image lie in client memory.
#[derive(Clone, Copy, Debug)]
pub struct Layout {
    /// Offset of the first group.
    pub start: usize,
    pub row_stride: usize,
    pub image_stride: usize,
    /// Bytes of one group.
    pub group: usize,
    /// Bytes the whole image spans from offset 0.
    pub end: usize,
}

/// The layout of a `width` x `height` x `depth` image of `dims` dimensions (SKIP_IMAGES and
/// IMAGE_HEIGHT apply to three-dimensional images only). `None` on arithmetic overflow.
pub fn layout(
    store: &PixelStore,
    dims: usize,
    size: [usize; 3],
    format: TexPixelFormat,
    ty: TexPixelType,
) -> Option<Layout> {
    let group = ty.group_size(format);
    let row_stride = store.row_stride(size[0], group, ty.size())?;
    let rows_per_image = if dims == 3 && store.image_height > 0 {
        store.image_height as usize
    } else {
        size[1]
    };
    let image_stride = row_stride.checked_mul(rows_per_image)?;
    let skip_images = if dims == 3 {
        store.skip_images.max(0) as usize
    } else {
        0
    };
    let start = image_stride
        .checked_mul(skip_images)?
        .checked_add(row_stride.checked_mul(store.skip_rows.max(0) as usize)?)?
        .checked_add((store.skip_pixels.max(0) as usize).checked_mul(group)?)?;
    let end = if size.contains(&0) {
        0
    } else {
        start
            .checked_add(image_stride.checked_mul(size[2] - 1)?)?
            .checked_add(row_stride.checked_mul(size[1] - 1)?)?
            .checked_add(size[0].checked_mul(group)?)?
    };
    Some(Layout {
        start,
        row_stride,
        image_stride,
        group,
        end,
    })
}

/// Where rows of index data lie in client memory: colour or stencil indices of
/// `glDrawPixels`, and the bits of `glBitmap` (`elem_bits` 1, packed eight to a byte).
#[derive(Clone, Copy, Debug)]
pub struct IndexRows {
    /// Distance in bytes between the starts of two rows.
    pub stride: usize,
    /// Offset of the first row (SKIP_ROWS rows in).
    pub first_row: usize,
    /// Bytes the whole rectangle spans from offset 0.
    pub end: usize,
}

/// The layout of a `width` x `height` rectangle of indices of `elem_bits` bits each
/// (`elem_size` bytes, 1 for bitmaps) under the storage modes `store` (section 3.6.4: rows of
/// ROW_LENGTH elements, SKIP_PIXELS elements and SKIP_ROWS rows skipped, each row padded to
/// ALIGNMENT unless the element is at least that large). `None` on arithmetic overflow.
pub fn index_rows(
    store: &PixelStore,
    width: usize,
    height: usize,
    elem_bits: usize,
    elem_size: usize,
) -> Option<IndexRows> {
    let row_len = if store.row_length > 0 {
        store.row_length as usize
    } else {
        width
    };
    let row_bytes = row_len.checked_mul(elem_bits)?.div_ceil(8);
    let align = store.alignment.max(1) as usize;
    let stride = if elem_size >= align {
        row_bytes
    } else {
        row_bytes.div_ceil(align).checked_mul(align)?
    };
    let first_row = stride.checked_mul(store.skip_rows.max(0) as usize)?;
    let end = if width == 0 || height == 0 {
        0
    } else {
        let skip = store.skip_pixels.max(0) as usize;
        first_row
            .checked_add(stride.checked_mul(height - 1)?)?
            .checked_add(skip.checked_add(width)?.checked_mul(elem_bits)?.div_ceil(8))?
    };
    Some(IndexRows {
        stride,
        first_row,
        end,
    })
}

/// Reads an element of `n` bytes at `at` in machine order, optionally byte-swapped.
#[inline]
fn read_uint(data: &[u8], at: usize, n: usize, swap: bool) -> u32 {
    let mut b = [0u8; 4];
    if let Some(src) = data.get(at..at + n) {
        b[..n].copy_from_slice(src);
    }
    if swap {
        b[..n].reverse();
    }
    match n {
        1 => b[0] as u32,
        2 => u16::from_ne_bytes([b[0], b[1]]) as u32,
        _ => u32::from_ne_bytes(b),
    }
}

/// Unpacks one group at `at` to RGBA (luminance copied to R, G and B; missing colour
/// components 0, missing alpha 1; depth in R), clamped to [0, 1].
#[inline]
pub fn unpack_group(
    data: &[u8],
    at: usize,
    format: TexPixelFormat,
    ty: TexPixelType,
    swap: bool,
) -> [f32; 4] {
    let mut rgba = [0.0f32, 0.0, 0.0, 1.0];
    let slots = format.slots();
    match ty {
        TexPixelType::Packed(p) => {
            let v = read_uint(data, at, p.size(), swap);
            for (&slot, &(shift, bits)) in slots.iter().zip(p.fields()) {
                let max = (1u32 << bits) - 1;
                rgba[slot] = ((v >> shift) & max) as f32 / max as f32;
            }
        }
        _ => {
            let n = ty.size();
            for (k, &slot) in slots.iter().enumerate() {
                let raw = read_uint(data, at + k * n, n, swap);
                rgba[slot] = match ty {
                    TexPixelType::UnsignedByte => raw as f32 / 255.0,
                    TexPixelType::Byte => (2.0 * (raw as u8 as i8) as f32 + 1.0) / 255.0,
                    TexPixelType::UnsignedShort => raw as f32 / 65535.0,
                    TexPixelType::Short => (2.0 * (raw as u16 as i16) as f32 + 1.0) / 65535.0,
                    TexPixelType::UnsignedInt => (raw as f64 / u32::MAX as f64) as f32,
                    TexPixelType::Int => {
                        ((2.0 * (raw as i32) as f64 + 1.0) / u32::MAX as f64) as f32
                    }
                    TexPixelType::Float => f32::from_bits(raw),
                    TexPixelType::Packed(_) => 0.0,
                };
            }
        }
    }
    if matches!(
        format,
        TexPixelFormat::Luminance | TexPixelFormat::LuminanceAlpha
    ) {
        rgba[1] = rgba[0];
        rgba[2] = rgba[0];
    }
    rgba.map(super::image::clamp01)
}

/// Calls `f(x, y, z, rgba)` for every pixel of the image described by `layout` (the caller
/// has checked that `data` holds `layout.end` bytes).
pub fn unpack_image(
    data: &[u8],
    layout: &Layout,
    size: [usize; 3],
    format: TexPixelFormat,
    ty: TexPixelType,
    swap: bool,
    mut f: impl FnMut(usize, usize, usize, [f32; 4]),
) {
    for z in 0..size[2] {
        for y in 0..size[1] {
            let row = layout.start + z * layout.image_stride + y * layout.row_stride;
            for x in 0..size[0] {
                f(
                    x,
                    y,
                    z,
                    unpack_group(data, row + x * layout.group, format, ty, swap),
                );
            }
        }
    }
}

/// Stores unsigned-byte groups into `img` (at stored coordinates `origin`) by copying rows,
/// when the groups hold exactly the image's stored components in order (RGBA into an RGBA
/// image, RGB into RGB, and LUMINANCE, ALPHA, LUMINANCE_ALPHA into their own) and the image
/// keeps uncompressed 8-bit texels. The general path turns a byte c into c / 255 and stores
/// it back as c, so the texels are the same. Returns false, having written nothing, in every
/// other case (and when the region does not fit the image or the data).
pub fn copy_bytes(
    img: &mut TexImage,
    origin: [i32; 3],
    data: &[u8],
    layout: &Layout,
    size: [usize; 3],
    format: TexPixelFormat,
    ty: TexPixelType,
) -> bool {
    use crate::texture::format::BaseFormat as B;
    use TexPixelFormat as F;
    let matches = matches!(
        (format, img.format.base),
        (F::Rgba, B::Rgba)
            | (F::Rgb, B::Rgb)
            | (F::Luminance, B::Luminance)
            | (F::Alpha, B::Alpha)
            | (F::LuminanceAlpha, B::LuminanceAlpha)
    );
    let c = img.format.base.components();
    if !matches
        || ty != TexPixelType::UnsignedByte
        || layout.group != c
        || img.format.compressed.is_some()
        || !matches!(*img.texels, Texels::U8(_))
        || origin.iter().any(|&o| o < 0)
    {
        return false;
    }
    let (w, h, d) = (
        img.width.max(0) as usize,
        img.height.max(0) as usize,
        img.depth.max(0) as usize,
    );
    let o = origin.map(|v| v as usize);
    if o[0] + size[0] > w || o[1] + size[1] > h || o[2] + size[2] > d {
        return false;
    }
    let row_bytes = size[0] * c;
    let last = |z: usize, y: usize| layout.start + z * layout.image_stride + y * layout.row_stride;
    if size.contains(&0) || data.len() < last(size[2] - 1, size[1] - 1) + row_bytes {
        return size.contains(&0);
    }
    let Texels::U8(texels) = Arc::make_mut(&mut img.texels) else {
        return false;
    };
    for z in 0..size[2] {
        for y in 0..size[1] {
            let src = last(z, y);
            let dst = (((o[2] + z) * h + o[1] + y) * w + o[0]) * c;
            texels[dst..dst + row_bytes].copy_from_slice(&data[src..src + row_bytes]);
        }
    }
    true
}

#[inline]
fn write_uint(out: &mut [u8], at: usize, n: usize, v: u32, swap: bool) {
    let mut b = match n {
        1 => [v as u8, 0, 0, 0],
        2 => {
            let x = (v as u16).to_ne_bytes();
            [x[0], x[1], 0, 0]
        }
        _ => v.to_ne_bytes(),
    };
    if swap {
        b[..n].reverse();
    }
    if let Some(dst) = out.get_mut(at..at + n) {
        dst.copy_from_slice(&b[..n]);
    }
}

/// Packs one RGBA value (components in [0, 1]; depth in R) as a group at `at` (section 4.3.2:
/// LUMINANCE is R + G + B clamped to 1; signed integers by `((2^b - 1) c - 1) / 2`).
#[inline]
pub fn pack_group(
    out: &mut [u8],
    at: usize,
    rgba: [f32; 4],
    format: TexPixelFormat,
    ty: TexPixelType,
    swap: bool,
) {
    let mut v = rgba;
    if matches!(
        format,
        TexPixelFormat::Luminance | TexPixelFormat::LuminanceAlpha
    ) {
        v[0] = (v[0] + v[1] + v[2]).min(1.0);
    }
    let slots = format.slots();
    match ty {
        TexPixelType::Packed(p) => {
            let mut word = 0u32;
            for (&slot, &(shift, bits)) in slots.iter().zip(p.fields()) {
                let max = (1u32 << bits) - 1;
                word |= ((v[slot] as f64 * max as f64).round() as u32 & max) << shift;
            }
            write_uint(out, at, p.size(), word, swap);
        }
        _ => {
            let n = ty.size();
            for (k, &slot) in slots.iter().enumerate() {
                let c = v[slot] as f64;
                let raw = match ty {
                    TexPixelType::UnsignedByte => (c * 255.0).round() as u32,
                    TexPixelType::Byte => ((255.0 * c - 1.0) / 2.0).round() as i8 as u8 as u32,
                    TexPixelType::UnsignedShort => (c * 65535.0).round() as u32,
                    TexPixelType::Short => ((65535.0 * c - 1.0) / 2.0).round() as i16 as u16 as u32,
                    TexPixelType::UnsignedInt => (c * u32::MAX as f64).round() as u32,
                    TexPixelType::Int => ((u32::MAX as f64 * c - 1.0) / 2.0).round() as i32 as u32,
                    TexPixelType::Float => (c as f32).to_bits(),
                    TexPixelType::Packed(_) => 0,
                };
                write_uint(out, at + k * n, n, raw, swap);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::values::PackedType;

    #[test]
    fn packed_layouts_by_hand() {
        // 5_6_5: R = bits 15..11, G = 10..5, B = 4..0. 0b10000_100000_00001.
        let v: u16 = (16 << 11) | (32 << 5) | 1;
        let d = v.to_ne_bytes();
        let t = TexPixelType::Packed(PackedType::UShort565);
        let c = unpack_group(&d, 0, TexPixelFormat::Rgb, t, false);
        assert_eq!(c, [16.0 / 31.0, 32.0 / 63.0, 1.0 / 31.0, 1.0]);
        // 2_10_10_10_REV with BGRA: first component (B) in bits 9..0, A in 31..30.
        let v: u32 = 1023 | (512 << 20) | (1 << 30); // G = 0
        let t = TexPixelType::Packed(PackedType::UInt2101010Rev);
        let c = unpack_group(&v.to_ne_bytes(), 0, TexPixelFormat::Bgra, t, false);
        assert_eq!(c, [512.0 / 1023.0, 0.0, 1.0, 1.0 / 3.0]);
    }

    #[test]
    fn signed_conversion_is_table_2_9() {
        let d = [(-128i8) as u8, 127u8];
        let c = unpack_group(
            &d,
            0,
            TexPixelFormat::LuminanceAlpha,
            TexPixelType::Byte,
            false,
        );
        // (2 * -128 + 1) / 255 = -1 -> clamped 0; (2 * 127 + 1) / 255 = 1.
        assert_eq!(c, [0.0, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn pack_round_trips() {
        for t in [
            TexPixelType::UnsignedByte,
            TexPixelType::UnsignedShort,
            TexPixelType::UnsignedInt,
            TexPixelType::Float,
            TexPixelType::Packed(PackedType::UInt8888Rev),
        ] {
            let mut out = [0u8; 16];
            let c = [0.0, 1.0, 0.2, 0.6];
            pack_group(&mut out, 0, c, TexPixelFormat::Rgba, t, true);
            let back = unpack_group(&out, 0, TexPixelFormat::Rgba, t, true);
            for i in 0..4 {
                assert!((back[i] - c[i]).abs() < 1.0 / 255.0, "{t:?}");
            }
        }
    }
}

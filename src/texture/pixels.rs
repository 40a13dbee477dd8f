//! Pixel unpacking (client memory -> RGBA, section 3.6.4) for texture images, and packing
//! (texture -> client memory, section 4.3.2 as used by `glGetTexImage`).
//!
//! Client data is in the machine's byte order; `GL_UNPACK_SWAP_BYTES` reverses the bytes of
//! each element (a component, or a whole packed group). `GL_UNPACK_LSB_FIRST` concerns only
//! `GL_BITMAP` data (colour indices, [`for_each_index`]). Signed and unsigned integers become
//! floats by table 2.9 of OpenGL 1.5: unsigned `c / (2^b - 1)`, signed `(2c + 1) / (2^b - 1)`.

use crate::common::values::{PixelIndexType, TexPixelFormat, TexPixelType};

/// Table 6.17: pixel storage modes of one direction (pack or unpack).
#[derive(Clone, Copy, Debug)]
pub struct PixelStore {
    pub alignment: i32,
    pub row_length: i32,
    pub skip_pixels: i32,
    pub skip_rows: i32,
    pub skip_images: i32,
    pub image_height: i32,
    pub swap_bytes: bool,
    pub lsb_first: bool,
}

impl Default for PixelStore {
    fn default() -> Self {
        PixelStore {
            alignment: 4,
            row_length: 0,
            skip_pixels: 0,
            skip_rows: 0,
            skip_images: 0,
            image_height: 0,
            swap_bytes: false,
            lsb_first: false,
        }
    }
}

impl PixelStore {
    /// Bytes spanned by an image of `width` x `height` x `depth` pixels of `bytes_per_pixel`
    /// (components times component size) under these storage modes, counting skips (section
    /// 3.6.4). Returns `None` on overflow.
    pub fn image_bytes(
        &self,
        width: usize,
        height: usize,
        depth: usize,
        bytes_per_pixel: usize,
        component_size: usize,
    ) -> Option<usize> {
        if width == 0 || height == 0 || depth == 0 {
            return Some(0);
        }
        let row = self.row_stride(width, bytes_per_pixel, component_size)?;
        let rows_per_image = if self.image_height > 0 {
            self.image_height as usize
        } else {
            height
        };
        let image = row.checked_mul(rows_per_image)?;
        let first = image
            .checked_mul(self.skip_images.max(0) as usize)?
            .checked_add(row.checked_mul(self.skip_rows.max(0) as usize)?)?
            .checked_add((self.skip_pixels.max(0) as usize).checked_mul(bytes_per_pixel)?)?;
        let last_row_end = width.checked_mul(bytes_per_pixel)?;
        first
            .checked_add(image.checked_mul(depth - 1)?)?
            .checked_add(row.checked_mul(height - 1)?)?
            .checked_add(last_row_end)
    }

    /// Distance in bytes between the starts of two rows.
    pub fn row_stride(
        &self,
        width: usize,
        bytes_per_pixel: usize,
        component_size: usize,
    ) -> Option<usize> {
        let pixels = if self.row_length > 0 {
            self.row_length as usize
        } else {
            width
        };
        let raw = pixels.checked_mul(bytes_per_pixel)?;
        let align = self.alignment.max(1) as usize;
        if component_size >= align {
            Some(raw)
        } else {
            Some(raw.div_ceil(align) * align)
        }
    }
}

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

/// Bits and bytes of one index element (`GL_BITMAP`: one bit; bytes 1 for row alignment).
fn index_element(ty: PixelIndexType) -> (usize, usize) {
    match ty {
        PixelIndexType::Bitmap => (1, 1),
        PixelIndexType::Plain(t) => (8 * t.size(), t.size()),
    }
}

/// Where a `size` image of indices of type `ty` lies under `store`: its rows
/// ([`index_rows`]), the distance between two images (3D images: IMAGE_HEIGHT rows, or the
/// height) and the offset of the first (SKIP_IMAGES images in), and the bytes it spans.
/// `None` on arithmetic overflow.
fn index_image(
    store: &PixelStore,
    dims: usize,
    size: [usize; 3],
    ty: PixelIndexType,
) -> Option<(IndexRows, usize, usize, usize)> {
    let (bits, bytes) = index_element(ty);
    let rows = index_rows(store, size[0], size[1], bits, bytes)?;
    let (rows_per_image, skip_images) = if dims == 3 {
        let h = if store.image_height > 0 {
            store.image_height as usize
        } else {
            size[1]
        };
        (h, store.skip_images.max(0) as usize)
    } else {
        (size[1], 0)
    };
    let image_stride = rows.stride.checked_mul(rows_per_image)?;
    let first_image = image_stride.checked_mul(skip_images)?;
    let end = if size.contains(&0) {
        0
    } else {
        first_image
            .checked_add(image_stride.checked_mul(size[2] - 1)?)?
            .checked_add(rows.end)?
    };
    Some((rows, image_stride, first_image, end))
}

/// Bytes an image of indices (colour or stencil indices, or `GL_BITMAP` bits) of `size` spans
/// under `store` (0 on overflow).
pub fn index_image_len(
    store: &PixelStore,
    dims: usize,
    size: [usize; 3],
    ty: PixelIndexType,
) -> usize {
    index_image(store, dims, size, ty).map_or(0, |(.., end)| end)
}

/// Calls `visit` with every index of a `size` image of type `ty` in client memory, x fastest,
/// then y, then z (section 3.6.4's unpacking of index groups, shared by `glDrawPixels` and
/// colour-index texture images). `None`, visiting nothing, when `data` is shorter than the
/// image or its layout overflows.
pub fn for_each_index(
    data: &[u8],
    store: &PixelStore,
    dims: usize,
    size: [usize; 3],
    ty: PixelIndexType,
    mut visit: impl FnMut(i64),
) -> Option<()> {
    let (rows, image_stride, first_image, end) = index_image(store, dims, size, ty)?;
    if data.len() < end {
        return None;
    }
    let skip = store.skip_pixels.max(0) as usize;
    let (_, elem_size) = index_element(ty);
    for z in 0..size[2] {
        for y in 0..size[1] {
            let row = first_image + z * image_stride + rows.first_row + y * rows.stride;
            for x in 0..size[0] {
                let (start, n) = match ty {
                    PixelIndexType::Bitmap => (row, skip + x),
                    PixelIndexType::Plain(_) => (row + skip * elem_size, x),
                };
                visit(read_index(
                    data,
                    start,
                    n,
                    ty,
                    store.swap_bytes,
                    store.lsb_first,
                ));
            }
        }
    }
    Some(())
}

/// Reads index `n` (0-based, in row `row_start`) of index data.
pub fn read_index(
    data: &[u8],
    row_start: usize,
    n: usize,
    ty: PixelIndexType,
    swap: bool,
    lsb_first: bool,
) -> i64 {
    match ty {
        PixelIndexType::Bitmap => {
            let byte = data.get(row_start + n / 8).copied().unwrap_or(0);
            let bit = if lsb_first {
                byte >> (n % 8)
            } else {
                byte >> (7 - n % 8)
            };
            (bit & 1) as i64
        }
        PixelIndexType::Plain(t) => {
            let size = t.size();
            let at = row_start + n * size;
            let Some(bytes) = data.get(at..at + size) else {
                return 0;
            };
            let mut b = [0u8; 4];
            b[..size].copy_from_slice(bytes);
            if swap {
                b[..size].reverse();
            }
            match t {
                TexPixelType::UnsignedByte => b[0] as i64,
                TexPixelType::Byte => b[0] as i8 as i64,
                TexPixelType::UnsignedShort => u16::from_ne_bytes([b[0], b[1]]) as i64,
                TexPixelType::Short => i16::from_ne_bytes([b[0], b[1]]) as i64,
                TexPixelType::UnsignedInt => u32::from_ne_bytes(b) as i64,
                TexPixelType::Int => i32::from_ne_bytes(b) as i64,
                TexPixelType::Float => {
                    let f = f32::from_ne_bytes(b);
                    if f.is_finite() {
                        f as i64
                    } else {
                        0
                    }
                }
                TexPixelType::Packed(_) => 0,
            }
        }
    }
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
    unpack_group_unclamped(data, at, format, ty, swap).map(super::image::clamp01)
}

/// [`unpack_group`] without the final clamp: what a float texture (ARB_texture_float) stores
/// of a group ("Otherwise, the components are not modified"). Only `GL_FLOAT` and the signed
/// types (down to -1 - 1/255 by table 2.9) give values outside [0, 1].
#[inline]
pub fn unpack_group_unclamped(
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
    rgba
}

/// Unpacks `out.len()` consecutive groups from `at` (each `group` bytes apart): what
/// [`unpack_group`] gives for each, with the format and type looked up once per row.
/// Unsigned bytes (the common `glDrawPixels` data) take a loop of their own; other types
/// go group by group through `unpack_group`.
pub fn unpack_row(
    data: &[u8],
    at: usize,
    group: usize,
    format: TexPixelFormat,
    ty: TexPixelType,
    swap: bool,
    out: &mut [[f32; 4]],
) {
    let bytes = data
        .get(at..)
        .and_then(|d| d.get(..out.len().checked_mul(group)?));
    match (ty, bytes) {
        (TexPixelType::UnsignedByte, Some(bytes))
            if format == TexPixelFormat::Rgba && group == 4 =>
        {
            // Each byte to its own slot: four divisions side by side.
            for (o, g) in out.iter_mut().zip(bytes.chunks_exact(4)) {
                let g = [g[0], g[1], g[2], g[3]];
                *o = g.map(|b| b as f32 / 255.0);
            }
        }
        (TexPixelType::UnsignedByte, Some(bytes)) if group == format.components() => {
            let slots = format.slots();
            let luminance = matches!(
                format,
                TexPixelFormat::Luminance | TexPixelFormat::LuminanceAlpha
            );
            // Every value `c / 255` of a byte is in [0, 1]: `clamp01` keeps it.
            for (o, g) in out.iter_mut().zip(bytes.chunks_exact(group)) {
                let mut rgba = [0.0f32, 0.0, 0.0, 1.0];
                for (&slot, &b) in slots.iter().zip(g) {
                    rgba[slot] = b as f32 / 255.0;
                }
                if luminance {
                    rgba[1] = rgba[0];
                    rgba[2] = rgba[0];
                }
                *o = rgba;
            }
        }
        _ => {
            for (x, o) in out.iter_mut().enumerate() {
                *o = unpack_group(data, at + x * group, format, ty, swap);
            }
        }
    }
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
    let mut row_values = vec![[0f32; 4]; size[0]];
    for z in 0..size[2] {
        for y in 0..size[1] {
            let row = layout.start + z * layout.image_stride + y * layout.row_stride;
            unpack_row(data, row, layout.group, format, ty, swap, &mut row_values);
            for (x, &v) in row_values.iter().enumerate() {
                f(x, y, z, v);
            }
        }
    }
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

    /// `unpack_row` (with its unsigned-byte loop) gives what `unpack_group` gives for each
    /// group: every format, every type, with and without byte swapping, from an offset, over
    /// random bytes; and the same for a row that runs past the data (groups read as zero).
    #[test]
    fn unpack_row_is_unpack_group_of_each_group() {
        use crate::common::values::PackedType;
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let data: Vec<u8> = (0..4096)
            .map(|_| {
                seed ^= seed << 13;
                seed ^= seed >> 7;
                seed ^= seed << 17;
                seed as u8
            })
            .collect();
        let formats = [
            TexPixelFormat::Red,
            TexPixelFormat::Green,
            TexPixelFormat::Blue,
            TexPixelFormat::Alpha,
            TexPixelFormat::Luminance,
            TexPixelFormat::LuminanceAlpha,
            TexPixelFormat::Rgb,
            TexPixelFormat::Rgba,
            TexPixelFormat::Bgr,
            TexPixelFormat::Bgra,
        ];
        let types = [
            TexPixelType::UnsignedByte,
            TexPixelType::Byte,
            TexPixelType::UnsignedShort,
            TexPixelType::Short,
            TexPixelType::UnsignedInt,
            TexPixelType::Int,
            TexPixelType::Float,
            TexPixelType::Packed(PackedType::UByte332),
            TexPixelType::Packed(PackedType::UShort565),
            TexPixelType::Packed(PackedType::UInt8888Rev),
        ];
        let mut checked = 0;
        for f in formats {
            for t in types {
                let group = t.group_size(f);
                for swap in [false, true] {
                    for (at, n) in [(0, 37), (5, 100), (data.len() - 3 * group, 6)] {
                        let mut row = vec![[9f32; 4]; n];
                        unpack_row(&data, at, group, f, t, swap, &mut row);
                        for (x, v) in row.iter().enumerate() {
                            let want = unpack_group(&data, at + x * group, f, t, swap);
                            assert_eq!(
                                v.map(f32::to_bits),
                                want.map(f32::to_bits),
                                "{f:?} {t:?} swap {swap} at {at} x {x}"
                            );
                            checked += 1;
                        }
                    }
                }
            }
        }
        assert!(checked > 10_000);
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

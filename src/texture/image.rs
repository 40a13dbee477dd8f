//! One texture image (one level of one face): its size, border, internal format and texels,
//! held in `Arc`s so that draw snapshots share them and a later write copies on write.

use std::sync::Arc;

use super::format::{InternalFormat, Storage};
use super::s3tc;
use crate::common::values::{TexPixelFormat, TexPixelType};

/// Texel components, unsigned normalised or (float formats) unclamped floats, `components`
/// per texel, rows bottom to top, images (3D slices) front to back, borders included.
#[derive(Clone, Debug, PartialEq)]
pub enum Texels {
    U8(Vec<u8>),
    U16(Vec<u16>),
    U32(Vec<u32>),
    F32(Vec<f32>),
}

/// A block of an image being stored (see [`TexImage::store_block`]).
struct Block {
    dims: [usize; 3],
    origin: [usize; 3],
    /// One past the last stored coordinate, clipped to the image.
    end: [usize; 3],
    slots: &'static [usize],
}

impl Block {
    fn fill<T>(
        &self,
        t: &mut [T],
        mut texel: impl FnMut(usize, usize, usize) -> [f32; 4],
        to: impl Fn(f32) -> T,
    ) {
        let (o, c) = (self.origin, self.slots.len());
        for z in o[2]..self.end[2] {
            for y in o[1]..self.end[1] {
                let row = (z * self.dims[1] + y) * self.dims[0];
                for x in o[0]..self.end[0] {
                    let v = texel(x - o[0], y - o[1], z - o[2]);
                    let at = (row + x) * c;
                    for (k, &slot) in self.slots.iter().enumerate() {
                        if let Some(d) = t.get_mut(at + k) {
                            *d = to(v[slot]);
                        }
                    }
                }
            }
        }
    }
}

/// A block of client groups being converted (see [`TexImage::store_converted`]).
struct Converted<'a> {
    dims: [usize; 3],
    origin: [usize; 3],
    size: [usize; 3],
    layout: &'a super::pixels::Layout,
    data: &'a [u8],
    /// Per stored component: the byte offset of its client component in a group, or the
    /// constant it takes.
    sources: &'a [Result<usize, f32>],
    /// Bytes of one client component.
    elem: usize,
}

impl Converted<'_> {
    /// Stores every texel: `value(bytes)` of the client component a stored component comes
    /// from, `constant(v)` of the others.
    #[inline(always)]
    fn fill<T: Copy>(&self, t: &mut [T], value: impl Fn(&[u8]) -> T, constant: &impl Fn(f32) -> T) {
        let c = self.sources.len();
        let (o, n, l) = (self.origin, self.size, self.layout);
        let row_bytes = n[0] * l.group;
        let sources: Vec<Result<usize, T>> =
            self.sources.iter().map(|s| s.map_err(constant)).collect();
        let in_order = c * self.elem == l.group
            && (self.sources.iter().enumerate()).all(|(k, s)| *s == Ok(k * self.elem));
        for z in 0..n[2] {
            for y in 0..n[1] {
                let src = l.start + z * l.image_stride + y * l.row_stride;
                let dst = (((o[2] + z) * self.dims[1] + o[1] + y) * self.dims[0] + o[0]) * c;
                let (Some(src), Some(dst)) = (
                    self.data.get(src..src + row_bytes),
                    t.get_mut(dst..dst + n[0] * c),
                ) else {
                    continue;
                };
                if in_order {
                    // Each client component is the next stored one: one flat loop.
                    for (d, b) in dst.iter_mut().zip(src.chunks_exact(self.elem)) {
                        *d = value(b);
                    }
                    continue;
                }
                for (g, out) in src.chunks_exact(l.group).zip(dst.chunks_exact_mut(c)) {
                    for (d, s) in out.iter_mut().zip(&sources) {
                        *d = match *s {
                            Ok(at) => value(&g[at..at + self.elem]),
                            Err(v) => v,
                        };
                    }
                }
            }
        }
    }
}

/// Allocation failed (`GL_OUT_OF_MEMORY`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OutOfMemory;

/// The largest texture image tilegl allocates: 1 GiB (a 16384x16384 RGBA8 image). Larger
/// requests are `GL_OUT_OF_MEMORY` before any memory is taken, instead of zero-filling
/// gigabytes (which the operating system may grant lazily and then kill the process for).
/// The figure is Mesa's: llvmpipe (Mesa 22.3.6) accepts a 16384x16384 `GL_RGBA8` image
/// (1 GiB) and refuses `GL_RGBA16` (2 GiB) and `GL_RGBA32F` (4 GiB) of that size with
/// `GL_OUT_OF_MEMORY`, and accepts an 8192x8192 `GL_RGBA32F` one (1 GiB), measured with
/// `glTexImage2D(..., NULL)` and `glGetError`.
pub const MAX_IMAGE_BYTES: usize = 1 << 30;

fn alloc<T: Clone + Default>(n: usize) -> Result<Vec<T>, OutOfMemory> {
    if n.checked_mul(std::mem::size_of::<T>())
        .is_none_or(|bytes| bytes > MAX_IMAGE_BYTES)
    {
        return Err(OutOfMemory);
    }
    let mut v = Vec::new();
    v.try_reserve_exact(n).map_err(|_| OutOfMemory)?;
    v.resize(n, T::default());
    Ok(v)
}

impl Texels {
    /// `n` zeroed components of `storage`.
    pub fn zeroed(storage: Storage, n: usize) -> Result<Texels, OutOfMemory> {
        Ok(match storage {
            Storage::U8 => Texels::U8(alloc(n)?),
            Storage::U16 => Texels::U16(alloc(n)?),
            Storage::U32 => Texels::U32(alloc(n)?),
            Storage::F32 => Texels::F32(alloc(n)?),
        })
    }

    /// Component `i` as a value in [0, 1] (float storage: as stored); 0 past the end.
    #[inline]
    pub fn get(&self, i: usize) -> f32 {
        match self {
            Texels::U8(v) => v.get(i).map_or(0.0, |&c| c as f32 * (1.0 / 255.0)),
            Texels::U16(v) => v.get(i).map_or(0.0, |&c| c as f32 * (1.0 / 65535.0)),
            Texels::U32(v) => v
                .get(i)
                .map_or(0.0, |&c| (c as f64 / u32::MAX as f64) as f32),
            Texels::F32(v) => v.get(i).copied().unwrap_or(0.0),
        }
    }

    /// Stores `value` (clamped to [0, 1], NaN as 0) rounded to the nearest representable value;
    /// float storage keeps `value` as it is (the caller rounds 16-bit float formats).
    #[inline]
    pub fn set(&mut self, i: usize, value: f32) {
        let v = clamp01(value) as f64;
        match self {
            Texels::U8(t) => {
                if let Some(c) = t.get_mut(i) {
                    *c = (v * 255.0).round() as u8;
                }
            }
            Texels::U16(t) => {
                if let Some(c) = t.get_mut(i) {
                    *c = (v * 65535.0).round() as u16;
                }
            }
            Texels::U32(t) => {
                if let Some(c) = t.get_mut(i) {
                    *c = (v * u32::MAX as f64).round() as u32;
                }
            }
            Texels::F32(t) => {
                if let Some(c) = t.get_mut(i) {
                    *c = value;
                }
            }
        }
    }

    pub fn len(&self) -> usize {
        match self {
            Texels::U8(v) => v.len(),
            Texels::U16(v) => v.len(),
            Texels::U32(v) => v.len(),
            Texels::F32(v) => v.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Clamps to [0, 1]; NaN becomes 0.
#[inline]
pub fn clamp01(v: f32) -> f32 {
    if v >= 1.0 {
        1.0
    } else if v > 0.0 {
        v
    } else {
        0.0
    }
}

/// One texture image.
#[derive(Clone, Debug)]
pub struct TexImage {
    /// Stored size, borders included (height 1 for 1D, depth 1 for 1D and 2D).
    pub width: i32,
    pub height: i32,
    pub depth: i32,
    /// 0 or 1.
    pub border: i32,
    /// 1, 2 or 3.
    pub dims: u8,
    pub format: InternalFormat,
    /// Decoded texels (for compressed images, the decoded blocks).
    pub texels: Arc<Texels>,
    /// The S3TC blocks of a compressed image.
    pub blocks: Option<Arc<Vec<u8>>>,
    /// The stencil indices of a depth-stencil image, one per stored texel (x fastest).
    pub stencil: Option<Arc<Vec<u8>>>,
}

impl TexImage {
    /// A zeroed image of the given stored size; `proxy` images hold no texels.
    pub fn new(
        dims: u8,
        size: [i32; 3],
        border: i32,
        format: InternalFormat,
        proxy: bool,
    ) -> Result<TexImage, OutOfMemory> {
        let n = if proxy {
            0
        } else {
            (size[0].max(0) as usize)
                .checked_mul(size[1].max(0) as usize)
                .and_then(|n| n.checked_mul(size[2].max(0) as usize))
                .and_then(|n| n.checked_mul(format.base.components()))
                .ok_or(OutOfMemory)?
        };
        let blocks = match format.compressed {
            Some(f) if !proxy => {
                let bytes = f.image_bytes(size[0].max(0) as usize, size[1].max(0) as usize);
                Some(Arc::new(alloc::<u8>(bytes)?))
            }
            _ => None,
        };
        Ok(TexImage {
            width: size[0],
            height: size[1],
            depth: size[2],
            border,
            dims,
            format,
            texels: Arc::new(Texels::zeroed(format.storage(), n)?),
            blocks,
            stencil: match format.stencil && !proxy {
                true => Some(Arc::new(alloc::<u8>(n)?)),
                false => None,
            },
        })
    }

    /// A whole image made of rows of client bytes that already are its texels (what
    /// [`TexImage::new`] then [`TexImage::store_byte_rows`] of the whole image store), without
    /// zeroing the texels first. `Ok(None)` where `store_byte_rows` would refuse (not 8-bit
    /// storage, a group that is not one texel, compressed or stencil formats, `data` shorter
    /// than `layout.end`).
    pub fn from_byte_rows(
        dims: u8,
        size: [i32; 3],
        border: i32,
        format: InternalFormat,
        data: &[u8],
        layout: &super::pixels::Layout,
    ) -> Result<Option<TexImage>, OutOfMemory> {
        let c = format.base.components();
        let d = size.map(|s| s.max(0) as usize);
        if format.storage() != Storage::U8
            || format.compressed.is_some()
            || format.stencil
            || layout.group != c
            || data.len() < layout.end
        {
            return Ok(None);
        }
        let row = d[0].checked_mul(c).ok_or(OutOfMemory)?;
        let n = row
            .checked_mul(d[1])
            .and_then(|n| n.checked_mul(d[2]))
            .filter(|&n| n <= MAX_IMAGE_BYTES)
            .ok_or(OutOfMemory)?;
        let mut t = Vec::new();
        t.try_reserve_exact(n).map_err(|_| OutOfMemory)?;
        for z in 0..d[2] {
            for y in 0..d[1] {
                let src = layout.start + z * layout.image_stride + y * layout.row_stride;
                t.extend_from_slice(&data[src..src + row]);
            }
        }
        Ok(Some(TexImage {
            width: size[0],
            height: size[1],
            depth: size[2],
            border,
            dims,
            format,
            texels: Arc::new(Texels::U8(t)),
            blocks: None,
            stencil: None,
        }))
    }

    /// The stencil index at stored coordinates (0 outside the image or without stencil).
    pub fn stencil_at(&self, x: i32, y: i32, z: i32) -> u8 {
        if x < 0 || y < 0 || z < 0 || x >= self.width || y >= self.height || z >= self.depth {
            return 0;
        }
        let i = self.index(x, y, z);
        self.stencil
            .as_ref()
            .and_then(|s| s.get(i).copied())
            .unwrap_or(0)
    }

    /// Stores the stencil indices of the `size` block at `origin` (stored coordinates), as
    /// [`TexImage::store_block`] stores texels; nothing for an image without stencil.
    pub fn store_stencil_block(
        &mut self,
        origin: [usize; 3],
        size: [usize; 3],
        mut index: impl FnMut(usize, usize, usize) -> u8,
    ) {
        let dims = [self.width, self.height, self.depth].map(|s| s.max(0) as usize);
        let Some(s) = self.stencil.as_mut() else {
            return;
        };
        let s = Arc::make_mut(s);
        for z in 0..size[2] {
            for y in 0..size[1] {
                for x in 0..size[0] {
                    let p = [origin[0] + x, origin[1] + y, origin[2] + z];
                    if p[0] < dims[0] && p[1] < dims[1] && p[2] < dims[2] {
                        s[(p[2] * dims[1] + p[1]) * dims[0] + p[0]] = index(x, y, z);
                    }
                }
            }
        }
    }

    /// Border width along each axis.
    #[inline]
    pub fn borders(&self) -> [i32; 3] {
        let b = self.border;
        [
            b,
            if self.dims >= 2 { b } else { 0 },
            if self.dims >= 3 { b } else { 0 },
        ]
    }

    /// Size without borders (w_t, h_t, d_t of the specification).
    #[inline]
    pub fn inner_size(&self) -> [i32; 3] {
        let b = self.borders();
        [
            self.width - 2 * b[0],
            self.height - 2 * b[1],
            self.depth - 2 * b[2],
        ]
    }

    #[inline]
    fn index(&self, x: i32, y: i32, z: i32) -> usize {
        let (w, h) = (self.width.max(0) as usize, self.height.max(0) as usize);
        ((z.max(0) as usize * h + y.max(0) as usize) * w + x.max(0) as usize)
            * self.format.base.components()
    }

    /// The texel at stored coordinates (borders included, 0-based) as "internal RGBA": the
    /// stored components in their slots (luminance, intensity and depth in R), the others
    /// (0, 0, 0, 1). Out-of-range coordinates read 0.
    #[inline]
    pub fn fetch(&self, x: i32, y: i32, z: i32) -> [f32; 4] {
        if x < 0 || y < 0 || z < 0 || x >= self.width || y >= self.height || z >= self.depth {
            return [0.0, 0.0, 0.0, 1.0];
        }
        let i = self.index(x, y, z);
        let base = self.format.base;
        match &*self.texels {
            Texels::U8(v) => gather(base, v, i, |c| c as f32 * (1.0 / 255.0)),
            Texels::U16(v) => gather(base, v, i, |c| c as f32 * (1.0 / 65535.0)),
            Texels::U32(v) => gather(base, v, i, |c| (c as f64 / u32::MAX as f64) as f32),
            Texels::F32(v) => gather(base, v, i, |c| c),
        }
    }

    /// Writes the texel at stored coordinates from internal RGBA (copy on write when a
    /// snapshot shares the texels).
    #[inline]
    /// Stores rows of client bytes that already are this image's texels (8-bit storage, a
    /// group of `layout` being one texel's components in their stored order): what `store`
    /// of every converted group gives, a row at a time. The `size` block at `origin` (stored
    /// coordinates) must lie inside the image and `data` hold `layout.end` bytes; otherwise,
    /// or for other storage, nothing is stored and the answer is false.
    pub fn store_byte_rows(
        &mut self,
        data: &[u8],
        layout: &super::pixels::Layout,
        origin: [usize; 3],
        size: [usize; 3],
    ) -> bool {
        let c = self.format.base.components();
        let dims = [self.width, self.height, self.depth].map(|s| s.max(0) as usize);
        let fits = (0..3).all(|k| origin[k] + size[k] <= dims[k]);
        if !matches!(*self.texels, Texels::U8(_))
            || layout.group != c
            || !fits
            || data.len() < layout.end
        {
            return false;
        }
        let row = size[0] * c;
        let Texels::U8(t) = Arc::make_mut(&mut self.texels) else {
            return false;
        };
        for z in 0..size[2] {
            for y in 0..size[1] {
                let src = layout.start + z * layout.image_stride + y * layout.row_stride;
                let dst = (((origin[2] + z) * dims[1] + origin[1] + y) * dims[0] + origin[0]) * c;
                t[dst..dst + row].copy_from_slice(&data[src..src + row]);
            }
        }
        true
    }

    /// Stores the `size` block at `origin` (stored coordinates) from client groups of
    /// `format` whose components are of the unpacked type `ty`, without byte swapping or pixel
    /// transfer: what [`super::pixels::unpack_group`] then `store_block` store, with the
    /// client type, the storage and each stored component's source looked up once per call
    /// instead of per texel (float uploads were ten times slower than Mesa's). False, with
    /// nothing stored, for packed types, depth data, compressed images, a block outside the
    /// image or `data` shorter than `layout.end`.
    pub fn store_converted(
        &mut self,
        data: &[u8],
        layout: &super::pixels::Layout,
        origin: [usize; 3],
        size: [usize; 3],
        format: TexPixelFormat,
        ty: TexPixelType,
    ) -> bool {
        let dims = [self.width, self.height, self.depth].map(|s| s.max(0) as usize);
        let fits = (0..3).all(|k| origin[k].checked_add(size[k]).is_some_and(|e| e <= dims[k]));
        let elem = ty.size();
        if matches!(ty, TexPixelType::Packed(_))
            || format.is_depth()
            || self.format.is_depth()
            || self.format.compressed.is_some()
            || !fits
            || data.len() < layout.end
            || layout.group != elem * format.components()
        {
            return false;
        }
        // Each stored component: the client component whose slot it takes (luminance also
        // gives G and B; a later component wins a slot, as in `unpack_group`), or the
        // missing components' 0 (alpha 1).
        let client = format.slots();
        let luminance = matches!(
            format,
            TexPixelFormat::Luminance | TexPixelFormat::LuminanceAlpha
        );
        let sources: Vec<Result<usize, f32>> = self
            .format
            .base
            .slots()
            .iter()
            .map(|&slot| {
                let slot = if luminance && (slot == 1 || slot == 2) {
                    0
                } else {
                    slot
                };
                match client.iter().rposition(|&s| s == slot) {
                    Some(j) => Ok(j * elem),
                    None => Err(if slot == 3 { 1.0 } else { 0.0 }),
                }
            })
            .collect();
        let block = Converted {
            dims,
            origin,
            size,
            layout,
            data,
            sources: &sources,
            elem,
        };
        let texels = Arc::make_mut(&mut self.texels);
        // `value` of a client component (table 2.9 as `unpack_group` computes it) into the
        // storage (as `store_block` rounds).
        macro_rules! by_type {
            ($t:expr, $to:expr) => {{
                let to = $to;
                match ty {
                    TexPixelType::UnsignedByte => block.fill($t, |b| to(b[0] as f32 / 255.0), &to),
                    TexPixelType::Byte => {
                        block.fill($t, |b| to((2.0 * (b[0] as i8) as f32 + 1.0) / 255.0), &to)
                    }
                    TexPixelType::UnsignedShort => block.fill(
                        $t,
                        |b| to(u16::from_ne_bytes([b[0], b[1]]) as f32 / 65535.0),
                        &to,
                    ),
                    TexPixelType::Short => block.fill(
                        $t,
                        |b| to((2.0 * i16::from_ne_bytes([b[0], b[1]]) as f32 + 1.0) / 65535.0),
                        &to,
                    ),
                    TexPixelType::UnsignedInt => block.fill(
                        $t,
                        |b| {
                            to((u32::from_ne_bytes([b[0], b[1], b[2], b[3]]) as f64
                                / u32::MAX as f64) as f32)
                        },
                        &to,
                    ),
                    TexPixelType::Int => block.fill(
                        $t,
                        |b| {
                            let raw = i32::from_ne_bytes([b[0], b[1], b[2], b[3]]);
                            to(((2.0 * raw as f64 + 1.0) / u32::MAX as f64) as f32)
                        },
                        &to,
                    ),
                    TexPixelType::Float => block.fill(
                        $t,
                        |b| to(f32::from_ne_bytes([b[0], b[1], b[2], b[3]])),
                        &to,
                    ),
                    TexPixelType::Packed(_) => {}
                }
            }};
        }
        match texels {
            Texels::U8(t) => {
                if ty == TexPixelType::UnsignedByte {
                    // A byte's value c / 255 stores as c again (`bytes_store_as_themselves`).
                    block.fill(t, |b| b[0], &|v: f32| {
                        (clamp01(v) as f64 * 255.0 + 0.5) as u8
                    });
                } else {
                    by_type!(t, |v: f32| (clamp01(v) as f64 * 255.0 + 0.5) as u8)
                }
            }
            Texels::U16(t) => by_type!(t, |v: f32| (clamp01(v) as f64 * 65535.0 + 0.5) as u16),
            Texels::U32(t) => {
                by_type!(t, |v: f32| (clamp01(v) as f64 * u32::MAX as f64 + 0.5)
                    as u32)
            }
            Texels::F32(t) => {
                // Unclamped (ARB_texture_float): 32-bit floats as they are, 16-bit ones
                // rounded to half precision.
                let f = self.format;
                by_type!(t, move |v: f32| f.float_value(v))
            }
        }
        true
    }

    /// Stores the `size` block at `origin` (stored coordinates), its texel (x, y, z) being
    /// `texel(x, y, z)`: what `store` of each texel does, with the storage looked up once
    /// (the uploads' general path). Texels outside the image are skipped.
    pub fn store_block(
        &mut self,
        origin: [usize; 3],
        size: [usize; 3],
        texel: impl FnMut(usize, usize, usize) -> [f32; 4],
    ) {
        let dims = [self.width, self.height, self.depth].map(|s| s.max(0) as usize);
        let end = [0, 1, 2].map(|k| origin[k].saturating_add(size[k]).min(dims[k]));
        let slots = self.format.base.slots();
        let block = Block {
            dims,
            origin,
            end,
            slots,
        };
        // Clamped to [0, 1], truncating v * max + 1/2 rounds as `set` does (half away from
        // zero), without a call to `round` per component. Float storage keeps the value
        // unclamped (16-bit float formats rounded to half precision).
        let f = self.format;
        match Arc::make_mut(&mut self.texels) {
            Texels::U8(t) => block.fill(t, texel, |v| (clamp01(v) as f64 * 255.0 + 0.5) as u8),
            Texels::U16(t) => block.fill(t, texel, |v| (clamp01(v) as f64 * 65535.0 + 0.5) as u16),
            Texels::U32(t) => block.fill(t, texel, |v| {
                (clamp01(v) as f64 * u32::MAX as f64 + 0.5) as u32
            }),
            Texels::F32(t) => block.fill(t, texel, |v| f.float_value(v)),
        }
    }

    pub fn store(&mut self, x: i32, y: i32, z: i32, rgba: [f32; 4]) {
        if x < 0 || y < 0 || z < 0 || x >= self.width || y >= self.height || z >= self.depth {
            return;
        }
        let i = self.index(x, y, z);
        let f = self.format;
        let texels = Arc::make_mut(&mut self.texels);
        for (k, &slot) in f.base.slots().iter().enumerate() {
            texels.set(
                i + k,
                if f.float {
                    f.float_value(rgba[slot])
                } else {
                    rgba[slot]
                },
            );
        }
    }

    /// Re-encodes the S3TC blocks covering the stored rectangle `[x0, x1) x [y0, y1)` from the
    /// texels, then replaces those texels by the decoded blocks (so sampling sees exactly what
    /// the compressed image holds).
    pub fn encode_region(&mut self, x0: i32, y0: i32, x1: i32, y1: i32) {
        let Some(f) = self.format.compressed else {
            return;
        };
        let (w, h) = (self.width.max(0), self.height.max(0));
        let bx0 = (x0.max(0) / 4) as usize;
        let by0 = (y0.max(0) / 4) as usize;
        let bx1 = ((x1.min(w) + 3) / 4).max(0) as usize;
        let by1 = ((y1.min(h) + 3) / 4).max(0) as usize;
        let bw = (w as usize).div_ceil(4);
        let bb = f.block_bytes();
        for by in by0..by1 {
            for bx in bx0..bx1 {
                let mut px = [[0u8; 4]; 16];
                let mut present = [false; 16];
                for (k, p) in px.iter_mut().enumerate() {
                    let (x, y) = (
                        bx as i32 * 4 + (k % 4) as i32,
                        by as i32 * 4 + (k / 4) as i32,
                    );
                    if x < w && y < h {
                        let c = self.fetch(x, y, 0);
                        *p = c.map(|v| (clamp01(v) * 255.0).round() as u8);
                        present[k] = true;
                    }
                }
                let block = s3tc::encode_block(f, &px, &present);
                let decoded = s3tc::decode_block(f, &block);
                if let Some(blocks) = self.blocks.as_mut() {
                    let off = (by * bw + bx) * bb;
                    if let Some(dst) = Arc::make_mut(blocks).get_mut(off..off + bb) {
                        dst.copy_from_slice(&block[..bb]);
                    }
                }
                for (k, c) in decoded.iter().enumerate() {
                    if present[k] {
                        let (x, y) = (
                            bx as i32 * 4 + (k % 4) as i32,
                            by as i32 * 4 + (k / 4) as i32,
                        );
                        self.store(x, y, 0, c.map(|v| v as f32 / 255.0));
                    }
                }
            }
        }
    }

    /// Replaces the blocks covering `[x0, x1) x [y0, y1)` (block-aligned) by `data` (a
    /// rectangle of blocks, rows bottom to top) and decodes them into the texels.
    pub fn load_blocks(&mut self, x0: i32, y0: i32, x1: i32, y1: i32, data: &[u8]) {
        let Some(f) = self.format.compressed else {
            return;
        };
        let bb = f.block_bytes();
        let bw = (self.width.max(0) as usize).div_ceil(4);
        let (bx0, by0) = ((x0.max(0) / 4) as usize, (y0.max(0) / 4) as usize);
        let rw = ((x1 - x0).max(0) as usize).div_ceil(4);
        let rh = ((y1 - y0).max(0) as usize).div_ceil(4);
        for ry in 0..rh {
            for rx in 0..rw {
                let src_off = (ry * rw + rx) * bb;
                let Some(src) = data.get(src_off..src_off + bb) else {
                    return;
                };
                let (bx, by) = (bx0 + rx, by0 + ry);
                if let Some(blocks) = self.blocks.as_mut() {
                    let off = (by * bw + bx) * bb;
                    if let Some(dst) = Arc::make_mut(blocks).get_mut(off..off + bb) {
                        dst.copy_from_slice(src);
                    }
                }
                let decoded = s3tc::decode_block(f, src);
                for (k, c) in decoded.iter().enumerate() {
                    let (x, y) = (
                        bx as i32 * 4 + (k % 4) as i32,
                        by as i32 * 4 + (k / 4) as i32,
                    );
                    if x < self.width && y < self.height {
                        self.store(x, y, 0, c.map(|v| v as f32 / 255.0));
                    }
                }
            }
        }
    }
}

/// The texel at component index `i` as internal RGBA (see [`TexImage::fetch`]), specialised
/// per base format; out-of-range reads give (0, 0, 0, 1).
#[inline(always)]
fn gather<T: Copy>(
    base: super::format::BaseFormat,
    v: &[T],
    i: usize,
    conv: impl Fn(T) -> f32,
) -> [f32; 4] {
    use super::format::BaseFormat::*;
    let none = [0.0, 0.0, 0.0, 1.0];
    match base {
        Alpha => v.get(i).map_or(none, |&a| [0.0, 0.0, 0.0, conv(a)]),
        Luminance | Intensity | DepthComponent | Red => {
            v.get(i).map_or(none, |&l| [conv(l), 0.0, 0.0, 1.0])
        }
        Rg => v
            .get(i..i + 2)
            .map_or(none, |s| [conv(s[0]), conv(s[1]), 0.0, 1.0]),
        LuminanceAlpha => v
            .get(i..i + 2)
            .map_or(none, |s| [conv(s[0]), 0.0, 0.0, conv(s[1])]),
        Rgb => v
            .get(i..i + 3)
            .map_or(none, |s| [conv(s[0]), conv(s[1]), conv(s[2]), 1.0]),
        Rgba => v
            .get(i..i + 4)
            .map_or(none, |s| [conv(s[0]), conv(s[1]), conv(s[2]), conv(s[3])]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An unsigned byte stores as itself in 8-bit storage (`store_converted` copies it).
    #[test]
    fn bytes_store_as_themselves() {
        for c in 0..=255u8 {
            assert_eq!((clamp01(c as f32 / 255.0) as f64 * 255.0 + 0.5) as u8, c);
        }
    }

    /// `store_converted` stores what the per-texel route (`unpack_group` of each group into
    /// `store_block`) stores: every unpacked client type and colour format, into 8-, 16- and
    /// 32-bit storage of every colour base format, whole images and sub-blocks under row
    /// lengths, alignments and skips; client bytes pseudo-random (so floats include NaN,
    /// infinities, negatives and values above 1).
    #[test]
    fn converted_uploads_store_what_the_per_texel_route_stores() {
        use crate::texture::format::BaseFormat;
        use crate::texture::pixels::{layout, unpack_group, unpack_group_unclamped, PixelStore};
        use TexPixelFormat as F;
        use TexPixelType as T;
        let formats = [
            F::Red,
            F::Green,
            F::Blue,
            F::Alpha,
            F::Rgb,
            F::Rgba,
            F::Bgr,
            F::Bgra,
            F::Luminance,
            F::LuminanceAlpha,
        ];
        let types = [
            T::UnsignedByte,
            T::Byte,
            T::UnsignedShort,
            T::Short,
            T::UnsignedInt,
            T::Int,
            T::Float,
        ];
        let bases = [
            BaseFormat::Alpha,
            BaseFormat::Luminance,
            BaseFormat::LuminanceAlpha,
            BaseFormat::Intensity,
            BaseFormat::Rgb,
            BaseFormat::Rgba,
            BaseFormat::Red,
            BaseFormat::Rg,
        ];
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        let data: Vec<u8> = (0..4096)
            .map(|_| {
                seed ^= seed << 13;
                seed ^= seed >> 7;
                seed ^= seed << 17;
                // Some floats near [0, 1]: exponent bytes 0x3F / 0x3E in the high byte.
                match seed % 5 {
                    0 => 0x3F,
                    1 => 0x3E,
                    _ => (seed >> 24) as u8,
                }
            })
            .collect();
        let (w, h) = (7usize, 5usize);
        let mut checked = 0;
        for format in formats {
            for ty in types {
                for base in bases {
                    for (bits, float) in [
                        (8u8, false),
                        (16, false),
                        (32, false),
                        (16, true),
                        (32, true),
                    ] {
                        let ifmt = if float {
                            InternalFormat::float(0, base, bits)
                        } else {
                            InternalFormat::new(0, base, bits)
                        };
                        for (align, row_length, skip_px, skip_rows) in
                            [(1, 0, 0, 0), (4, 11, 2, 1), (8, 0, 1, 2)]
                        {
                            let store = PixelStore {
                                alignment: align,
                                row_length,
                                skip_pixels: skip_px,
                                skip_rows,
                                ..PixelStore::default()
                            };
                            for (origin, size) in [([0, 0, 0], [w, h, 1]), ([2, 1, 0], [4, 3, 1])] {
                                let lay = layout(&store, 2, size, format, ty).unwrap();
                                assert!(lay.end <= data.len());
                                let image = || {
                                    let mut img =
                                        TexImage::new(2, [w as i32, h as i32, 1], 0, ifmt, false)
                                            .unwrap();
                                    // A non-zero background, so skipped texels show.
                                    img.store_block([0; 3], [w, h, 1], |x, y, _| {
                                        [x as f32 / 8.0, y as f32 / 8.0, 0.5, 0.25]
                                    });
                                    img
                                };
                                let mut fast = image();
                                assert!(fast.store_converted(&data, &lay, origin, size, format, ty));
                                let mut slow = image();
                                slow.store_block(origin, size, |x, y, z| {
                                    let at = lay.start
                                        + z * lay.image_stride
                                        + y * lay.row_stride
                                        + x * lay.group;
                                    if float {
                                        unpack_group_unclamped(&data, at, format, ty, false)
                                    } else {
                                        unpack_group(&data, at, format, ty, false)
                                    }
                                });
                                // Float storage compared bit for bit (NaN included).
                                let bits_of = |t: &Texels| match t {
                                    Texels::F32(v) => v.iter().map(|f| f.to_bits()).collect(),
                                    _ => vec![],
                                };
                                assert_eq!(bits_of(&fast.texels), bits_of(&slow.texels));
                                assert!(
                                    float || fast.texels == slow.texels,
                                    "{format:?} {ty:?} into {base:?}/{bits}, unpack {align} \
                                     {row_length} {skip_px} {skip_rows}, block {origin:?} {size:?}"
                                );
                                checked += 1;
                            }
                        }
                    }
                }
            }
        }
        assert_eq!(checked, 10 * 7 * 8 * 5 * 3 * 2);
    }

    #[test]
    fn images_over_the_byte_limit_are_out_of_memory_without_allocating() {
        // The limit counts bytes, whatever the size of one stored component.
        assert_eq!(
            Texels::zeroed(Storage::U8, MAX_IMAGE_BYTES + 1),
            Err(OutOfMemory)
        );
        assert_eq!(
            Texels::zeroed(Storage::U16, MAX_IMAGE_BYTES / 2 + 1),
            Err(OutOfMemory)
        );
        assert_eq!(
            Texels::zeroed(Storage::U32, MAX_IMAGE_BYTES / 4 + 1),
            Err(OutOfMemory)
        );
        assert_eq!(Texels::zeroed(Storage::U32, usize::MAX), Err(OutOfMemory));
        // A 16384x16384 RGBA32F-sized image (four 32-bit components per texel).
        let n = 16384usize * 16384 * 4;
        assert_eq!(Texels::zeroed(Storage::U32, n), Err(OutOfMemory));
        assert_eq!(Texels::zeroed(Storage::U8, 16).map(|t| t.len()), Ok(16));
    }
}

//! `GL_GENERATE_MIPMAP`: each level is a box filter of the one above (section 3.8.8,
//! "Automatic Mipmap Generation").
//!
//! Level `l + 1` has inner size `max(1, floor(size / 2))` per dimension. Texel `i` averages
//! parent texels `2i` and `2i + 1` along every dimension that shrinks (the second index
//! clamped to the parent's last texel, so odd sizes drop their last row or column, like a 2x2
//! box); a dimension of size 1 is copied. Border texels (index -1 and `size`) average the
//! parent's border texels the same way, so a bordered texture keeps its border.

use super::image::{OutOfMemory, TexImage};

/// The next level below `parent`.
pub fn downsample(parent: &TexImage) -> Result<TexImage, OutOfMemory> {
    let dims = parent.dims as usize;
    let pin = parent.inner_size();
    let b = parent.borders();
    let mut cin = [1i32; 3];
    for d in 0..dims {
        cin[d] = (pin[d] / 2).max(1);
    }
    let size = [cin[0] + 2 * b[0], cin[1] + 2 * b[1], cin[2] + 2 * b[2]];
    let mut child = TexImage::new(parent.dims, size, parent.border, parent.format, false)?;
    // Parent indices (inner coordinates) feeding child inner index i along dimension d.
    let sources = |d: usize, i: i32| -> [i32; 2] {
        if i < 0 {
            return [-1, -1];
        }
        if i >= cin[d] {
            return [pin[d], pin[d]];
        }
        if pin[d] == cin[d] {
            return [i, i];
        }
        [2 * i, (2 * i + 1).min(pin[d] - 1)]
    };
    for z in -b[2]..cin[2] + b[2] {
        let sz = sources(2, z);
        for y in -b[1]..cin[1] + b[1] {
            let sy = sources(1, y);
            for x in -b[0]..cin[0] + b[0] {
                let sx = sources(0, x);
                let mut acc = [0.0f32; 4];
                for &pz in &sz {
                    for &py in &sy {
                        for &px in &sx {
                            let t = parent.fetch(px + b[0], py + b[1], pz + b[2]);
                            for k in 0..4 {
                                acc[k] += t[k];
                            }
                        }
                    }
                }
                child.store(x + b[0], y + b[1], z + b[2], acc.map(|v| v / 8.0));
            }
        }
    }
    if child.format.compressed.is_some() {
        child.encode_region(0, 0, child.width, child.height);
    }
    Ok(child)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::format::{BaseFormat, InternalFormat};

    #[test]
    fn box_filter_halves() {
        let f = InternalFormat::new(0x1909, BaseFormat::Luminance, 8);
        let mut img = TexImage::new(2, [4, 2, 1], 0, f, false).unwrap_or_else(|_| panic!());
        let vals = [0.0, 0.2, 0.4, 0.6, 1.0, 0.8, 0.6, 0.4];
        for (k, v) in vals.iter().enumerate() {
            img.store((k % 4) as i32, (k / 4) as i32, 0, [*v, 0.0, 0.0, 1.0]);
        }
        let c = downsample(&img).unwrap_or_else(|_| panic!());
        assert_eq!(c.inner_size(), [2, 1, 1]);
        // (0 + 0.2 + 1 + 0.8) / 4 = 0.5 ; (0.4 + 0.6 + 0.6 + 0.4) / 4 = 0.5
        assert!((c.fetch(0, 0, 0)[0] - 0.5).abs() < 1.0 / 255.0);
        assert!((c.fetch(1, 0, 0)[0] - 0.5).abs() < 1.0 / 255.0);
    }
}

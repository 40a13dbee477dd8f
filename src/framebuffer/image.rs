//! Writing the colour buffer as a PNG (top row first, as image files are).

use std::path::Path;

use super::{ColorBuffer, Framebuffer};

/// The read colour buffer as an RGBA image, top row first.
pub fn to_rgba_image(fb: &Framebuffer) -> image::RgbaImage {
    let (w, h) = (fb.width.max(0) as u32, fb.height.max(0) as u32);
    image::RgbaImage::from_fn(w, h, |x, y| {
        image::Rgba(
            fb.color_at(x as i32, (h - 1 - y) as i32)
                .unwrap_or_default(),
        )
    })
}

/// Saves the colour buffer as a PNG file.
pub fn save_png(fb: &Framebuffer, path: &Path) -> Result<(), image::ImageError> {
    to_rgba_image(fb).save_with_format(path, image::ImageFormat::Png)
}

/// One colour buffer (front or back) as an RGBA image, top row first.
pub fn to_rgba_image_of(fb: &Framebuffer, buffer: ColorBuffer) -> image::RgbaImage {
    let (w, h) = (fb.width.max(0) as u32, fb.height.max(0) as u32);
    image::RgbaImage::from_fn(w, h, |x, y| {
        image::Rgba(
            fb.color_in(buffer, x as i32, (h - 1 - y) as i32)
                .unwrap_or_default(),
        )
    })
}

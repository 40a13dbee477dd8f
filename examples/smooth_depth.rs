//! Smooth shading and depth testing under a perspective projection.
//!
//! What it teaches:
//! - `glFrustum` builds a perspective projection: farther geometry is smaller, and every
//!   vertex attribute (here the colour) is interpolated perspective-correctly across each
//!   triangle.
//! - With `glShadeModel(GL_SMOOTH)` each vertex's `glColor` is blended across the primitive:
//!   the colour cube's eight corner colours flow into each other.
//! - With `glEnable(GL_DEPTH_TEST)` and `glDepthFunc(GL_LESS)` each pixel keeps the nearest
//!   fragment whatever the drawing order: the cube's hidden faces disappear, and two
//!   triangles tilted against each other cut through one another along the line where their
//!   depths are equal.
//!
//! The scene is `scenes::smooth_depth` in `src/bin/tilegl/scenes.rs` (shared with the
//! `tilegl` command's gallery). It is written against `&mut dyn tilegl::Gl`, so the same
//! function can draw on another GL implementation behind the trait (e.g. Mesa, as the
//! conformance crate does).
//!
//! Run: `cargo run --release --example smooth_depth [OUT.png]` (default
//! `out/smooth_depth.png`).

#[allow(dead_code)]
#[path = "../src/bin/tilegl/scenes.rs"]
mod scenes;

use std::path::PathBuf;

use tilegl::enums::*;
use tilegl::{Context, Gl};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args_os()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("out/smooth_depth.png"));
    let (width, height) = (640, 480);

    let mut ctx = Context::new(width, height);
    let gl: &mut dyn Gl = &mut ctx;
    scenes::smooth_depth(gl, width, height);
    gl.finish();
    let error = gl.get_error();
    if error != GL_NO_ERROR {
        return Err(format!("GL error 0x{error:04X}").into());
    }

    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)?;
    }
    tilegl::framebuffer::image::save_png(ctx.framebuffer(), &path)?;
    println!("wrote {}", path.display());
    Ok(())
}

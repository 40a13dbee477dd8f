//! Points of size 1 (section 3.3): the fragment whose pixel contains the point's window
//! position, i.e. (floor(x), floor(y)). Wider and smooth points arrive with the
//! fragment-operations issue.

use super::scene::{Command, PixelCommand, Scene};
use super::setup::{Plane, Rect, SUBPIXEL};
use crate::primitive::viewport::WindowVertex;
use crate::state::DrawState;

pub fn bin_point(ds: &DrawState, state: u32, v: &WindowVertex, attrs: &[f32], scene: &mut Scene) {
    let x = v.xy[0].div_euclid(SUBPIXEL);
    let y = v.xy[1].div_euclid(SUBPIXEL);
    emit_pixel(ds, state, x, y, v.z, attrs, scene);
}

/// Records one fragment with constant attributes, if it lies in the draw rectangle.
pub(crate) fn emit_pixel(
    ds: &DrawState,
    state: u32,
    x: i64,
    y: i64,
    z: f64,
    attrs: &[f32],
    scene: &mut Scene,
) {
    let r = &ds.draw_rect;
    if x < r.x0 as i64 || x >= r.x1 as i64 || y < r.y0 as i64 || y >= r.y1 as i64 {
        return;
    }
    let (x, y) = (x as i32, y as i32);
    let offset = scene.planes.len() as u32;
    scene
        .planes
        .extend(attrs.iter().map(|&a| Plane::constant(a as f64)));
    scene.bin(
        Command::Pixel(PixelCommand {
            state,
            x,
            y,
            z,
            attrs: offset,
        }),
        Rect {
            x0: x,
            y0: y,
            x1: x + 1,
            y1: y + 1,
        },
    );
}

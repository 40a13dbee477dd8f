//! User clip planes (section 2.12) against the plane equations computed here: every subset of
//! the first six planes (64 combinations) and all eight at once, on a quad whose eye z varies
//! across the window, with the planes given under a rotated modelview.

mod common;

use common::{read_rgba, threaded_context};
use glam::{DMat4, DVec3, DVec4};
use tilegl::enums::*;
use tilegl::Gl;

const W: i32 = 64;

/// The planes in object coordinates (the coordinates the quad's vertices are given in), each
/// cutting the window somewhere, at different angles, and two (4 and 5) depending on z.
const PLANES: [[f64; 4]; 8] = [
    [1.0, 0.0, 0.0, -6.3],
    [-1.0, 0.1, 0.0, 58.2],
    [0.05, 1.0, 0.0, -5.7],
    [0.2, -1.0, 0.0, 57.6],
    [0.0, 0.0, 1.0, 0.31],
    [0.0, 0.0, -1.0, 0.27],
    [1.0, 1.0, 0.0, -30.4],
    [1.0, -1.0, 0.0, 41.3],
];

/// Object z of the quad at window position (x, y): an affine ramp from -0.5 to 0.5 along x.
fn quad_z(x: f64, _y: f64) -> f64 {
    -0.5 + x / W as f64
}

/// Draws the window-filling quad (object = window coordinates, with a rotation about z
/// applied to both the planes and the quad so the planes pass through the modelview inverse)
/// with the planes of `mask` enabled; returns which pixels were drawn.
fn drawn(mask: u32) -> Vec<bool> {
    let mut gl = threaded_context(W, W, 1);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, W as f64, 0.0, W as f64, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    // Rotate by 90 degrees about the window centre: the picture is the object picture turned.
    gl.load_identity();
    gl.translatef(32.0, 32.0, 0.0);
    gl.rotatef(90.0, 0.0, 0.0, 1.0);
    gl.translatef(-32.0, -32.0, 0.0);
    for (i, p) in PLANES.iter().enumerate() {
        gl.clip_plane(GL_CLIP_PLANE0 + i as GLenum, p);
        if mask & (1 << i) != 0 {
            gl.enable(GL_CLIP_PLANE0 + i as GLenum);
        }
    }
    gl.color_3f(1.0, 1.0, 1.0);
    gl.begin(GL_QUADS);
    for (x, y) in [(-4.0, -4.0), (68.0, -4.0), (68.0, 68.0), (-4.0, 68.0)] {
        gl.vertex_3f(x as f32, y as f32, quad_z(x, y) as f32);
    }
    gl.end();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    read_rgba(&mut gl).iter().map(|p| p[0] > 0).collect()
}

/// Compares `drawn(mask)` with the plane equations at each pixel centre, mapped back to object
/// coordinates through the inverse of the rotation; pixels within 0.75 pixel of an enabled
/// plane's edge are left out (the rasterization rules decide those). Returns the number of
/// pixels checked.
fn check(mask: u32) -> usize {
    let got = drawn(mask);
    let rot = DMat4::from_translation(DVec3::new(32.0, 32.0, 0.0))
        * DMat4::from_rotation_z(std::f64::consts::FRAC_PI_2)
        * DMat4::from_translation(DVec3::new(-32.0, -32.0, 0.0));
    let inv = rot.inverse();
    let mut checked = 0;
    for py in 0..W {
        for px in 0..W {
            let win = DVec4::new(px as f64 + 0.5, py as f64 + 0.5, 0.0, 1.0);
            let obj = inv * win;
            let o = DVec4::new(obj.x, obj.y, quad_z(obj.x, obj.y), 1.0);
            let mut inside = true;
            let mut near_edge = false;
            for (i, p) in PLANES.iter().enumerate() {
                if mask & (1 << i) == 0 {
                    continue;
                }
                let p = DVec4::from_array(*p);
                let d = p.dot(o);
                // The plane's value changes by |grad| per pixel (window and object units agree;
                // z adds 1/64 per unit x).
                let grad = (p.x + p.z / W as f64).hypot(p.y);
                if d.abs() < 0.75 * grad.max(1e-9) {
                    near_edge = true;
                }
                inside &= d >= 0.0;
            }
            if near_edge {
                continue;
            }
            checked += 1;
            assert_eq!(
                got[(py * W + px) as usize],
                inside,
                "planes {mask:#04x}: pixel ({px}, {py}), object {o:?}"
            );
        }
    }
    checked
}

#[test]
fn every_subset_of_six_planes_clips_by_the_plane_equations() {
    for mask in 0..64 {
        let checked = check(mask);
        // Every subset leaves most pixels away from the edges (the check did something).
        assert!(
            checked > (W * W) as usize / 2,
            "planes {mask:#04x}: {checked}"
        );
    }
}

#[test]
fn all_eight_planes_clip_by_the_plane_equations() {
    let mut max = [0i32; 1];
    let mut gl = threaded_context(8, 8, 1);
    gl.get_integerv(GL_MAX_CLIP_PLANES, &mut max);
    assert_eq!(max[0], 8, "Mesa reports 8 user clip planes");
    check(0xFF);
    // Some pixel is drawn and some is clipped with all eight (the planes leave a region).
    let got = drawn(0xFF);
    assert!(got.iter().any(|&d| d) && got.iter().any(|&d| !d));
}

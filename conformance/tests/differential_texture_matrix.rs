//! Differential tests of the texturing verification matrix (scenes in
//! `tilegl_conformance::scenes_texture_matrix`): every filter x wrap mode x base format on a
//! perspective plane, cube maps, 3D textures, depth comparison and S3TC, each under its
//! measured tolerance.

use tilegl_conformance::scenes_texture_matrix::TEXTURE_MATRIX_SCENES;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn texture_matrix_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("TEXTURE_MATRIX_SCENES", TEXTURE_MATRIX_SCENES);
}

/// The exact picture of `texmat_nearest_<wrap>` where the plane covers a pixel centre (away
/// from its edges): the pixel centre projected on the plane y_eye = -1 in f64 (frustum
/// (-1, 1, -1, 0.25, 1, 400), 64x64 viewports), s = 0.5137 + 0.7519 x_eye,
/// t = -0.1437 + 0.7093 (d - 1.05), the NEAREST texel of the 16x8 level-0 texture after the wrap,
/// expanded by the viewport's base format under GL_REPLACE (primary colour (0.8, 0.5, 0.3)).
fn exact_nearest(wrap_mirror: bool, x: i32, y: i32) -> Option<[u8; 4]> {
    let (vx, vy) = (x / 64, y / 64);
    let xn = (x % 64) as f64 / 32.0 + 1.0 / 64.0 - 1.0;
    let yn = (y % 64) as f64 / 32.0 + 1.0 / 64.0 - 1.0;
    let y_near = -0.375 + 0.625 * yn;
    if y_near >= 0.0 {
        return None;
    }
    let d = -1.0 / y_near;
    let xe = xn * d;
    if !(1.07..149.0).contains(&d) || xe.abs() > 79.0 {
        return None;
    }
    let (s, t) = (0.5137 + 0.7519 * xe, -0.1437 + 0.7093 * (d - 1.05));
    // Pixel centres whose coordinate lies within 1/1000 texel of a texel boundary are ties
    // (several rows and columns fall exactly on boundaries: d = 512/7 on row 50): skipped.
    let (u, v) = (s * 16.0, t * 8.0);
    let near_tie = |c: f64| (c - c.round()).abs() < 1e-3;
    if near_tie(u) || near_tie(v) {
        return None;
    }
    let wrap = |i: i64, n: i64| {
        if wrap_mirror {
            let m = i.rem_euclid(2 * n);
            if m >= n {
                2 * n - 1 - m
            } else {
                m
            }
        } else {
            i.rem_euclid(n)
        }
    };
    let i = wrap(u.floor() as i64, 16) as usize;
    let j = wrap(v.floor() as i64, 8) as usize;
    // The level-0 texel of scenes_texture_matrix::matrix_level0.
    let on = ((i / 2) + (j / 2)).is_multiple_of(2);
    let (r, g, b, a) = (
        if on { 235u8 } else { 25 },
        (i * 255 / 15) as u8,
        (40 + j * 200 / 7) as u8,
        (((i + 2 * j) % 5) * 60 + 10) as u8,
    );
    Some(match vy * 3 + vx {
        0 => [204, 128, 77, a],
        1 => [r, r, r, 255],
        2 => [r, r, r, a],
        3 => [r, r, r, r],
        4 => [r, g, b, 255],
        _ => [r, g, b, a],
    })
}

/// Share of the plane's pixels of `picture` that differ from the exact picture by more than 8.
fn off_exact(name: &str, picture: &tilegl_conformance::Image) -> f64 {
    let mirror = name.ends_with("mirror");
    let (mut bad, mut n) = (0, 0);
    for y in 0..picture.height {
        for x in 0..picture.width {
            if let Some(e) = exact_nearest(mirror, x, y) {
                let p = picture.pixel(x, y);
                n += 1;
                if (0..4).any(|k| p[k].abs_diff(e[k]) > 8) {
                    bad += 1;
                }
            }
        }
    }
    assert!(n > 10_000, "{n}");
    bad as f64 / n as f64
}

/// The tolerance of `texmat_nearest_repeat` and `_mirror` (see TOLERANCE.md): under NEAREST
/// minification a pixel shows whichever texel its coordinate falls in, so rounding in the
/// coordinate evaluation flips texels at boundaries. tilegl evaluates in f64 and stays within
/// the normal rule of the exact picture; llvmpipe (f32) is further off, which is what the two
/// differ by. Prints llvmpipe's figure when Mesa is there.
#[test]
fn texmat_nearest_is_within_the_rule_of_the_exact_picture() {
    for name in ["texmat_nearest_repeat", "texmat_nearest_mirror"] {
        let scene = tilegl_conformance::scenes::find(name).expect("scene");
        let t = tilegl_conformance::compare::render_tilegl(scene);
        let share = off_exact(name, &t.image);
        println!(
            "{name}: tilegl off the exact picture {:.3} %",
            share * 100.0
        );
        assert!(share <= 0.001, "{name}: {:.3} %", share * 100.0);
        if tilegl_conformance::mesa::mesa_available().is_ok() {
            if let Ok((m, _)) = tilegl_conformance::compare::render_mesa(scene) {
                let share = off_exact(name, &m.image);
                println!("{name}: Mesa off the exact picture {:.3} %", share * 100.0);
            }
        }
    }
}

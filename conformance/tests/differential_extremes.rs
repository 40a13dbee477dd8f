//! Differential tests of the extreme cases (scenes in `tilegl_conformance::scenes_extremes`):
//! stiff and extreme inputs against Mesa, and, where Mesa is less exact than the
//! specification, the exact values computed here and asserted on tilegl (the cases of
//! clipping and lighting where Mesa is less exact are listed in
//! `tilegl_conformance::known_failures::MESA_LESS_EXACT`, with where the spec value is
//! checked).

use tilegl_conformance::scenes_extremes::EXTREME_SCENES;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn extreme_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("EXTREME_SCENES", EXTREME_SCENES);
}

/// Every case listed as one where Mesa is less exact is a scene of some list (most are
/// extreme cases; `eval_coords_colour_in_a_list` is an evaluator scene).
#[test]
fn mesa_less_exact_cases_exist() {
    for (name, why) in tilegl_conformance::known_failures::MESA_LESS_EXACT {
        assert!(
            scenes::find(name).is_some(),
            "MESA_LESS_EXACT lists unknown case {name}"
        );
        assert!(
            why.contains("tests/"),
            "{name}: say where the spec value is checked"
        );
    }
}

use tilegl_conformance::compare::{render_mesa, render_tilegl};
use tilegl_conformance::{mesa, scenes, Image};

fn tilegl_picture(name: &str) -> Image {
    let scene = scenes::find(name).unwrap_or_else(|| panic!("no scene {name}"));
    let r = render_tilegl(scene);
    assert_eq!(r.error, 0, "{name}: glGetError");
    r.image
}

/// Asserts the RGB of pixel (x, y) is within `tol` of `want` (components in 0..=1).
fn assert_rgb(img: &Image, x: i32, y: i32, want: [f64; 3], tol: f64, what: &str) {
    let got = img.pixel(x, y);
    for c in 0..3 {
        let w = want[c] * 255.0;
        assert!(
            (f64::from(got[c]) - w).abs() <= tol,
            "{what} at ({x}, {y}): got {got:?}, want {:?}",
            want.map(|v| v * 255.0)
        );
    }
}

/// The exact coverage and colours of the triangles with vertices of 1e30: barycentric
/// coordinates of each pixel centre computed in double precision (section 3.5.1).
#[test]
fn coordinates_1e30_are_exact() {
    let img = tilegl_picture("extreme_coordinates_1e30");
    // Left half, viewport (0, 0, 32, 64): V0 = (-1e30, -1e30) red, V1 = (3e30, -1e30) green,
    // V2 = (-1e30, 3e30) blue enclose the viewport.
    for y in 0..64 {
        for x in 0..32 {
            let (px, py) = ((x as f64 + 0.5) / 16.0 - 1.0, (y as f64 + 0.5) / 32.0 - 1.0);
            let l1 = (px + 1e30) / 4e30;
            let l2 = (py + 1e30) / 4e30;
            assert_rgb(
                &img,
                x,
                y,
                [1.0 - l1 - l2, l1, l2],
                1.0,
                "enclosing triangle",
            );
        }
    }
    // Right half, viewport (32, 0, 32, 64): V0 = (-1e30, -0.5) red, V1 = (1e30, -0.5) green,
    // V2 = (0, 0.5) blue. At height y the triangle spans |x| <= 1e30 (0.5 - y): the whole
    // viewport for y in [-0.5, 0.5); the colour is blue y + 0.5, red = green = the rest / 2
    // (to within 1e-30). The triangle of 1e-30 at the centre covers no pixel centre.
    for y in 0..64 {
        for x in 32..64 {
            let (px, py) = (
                (x as f64 - 32.0 + 0.5) / 16.0 - 1.0,
                (y as f64 + 0.5) / 32.0 - 1.0,
            );
            let l2 = py + 0.5;
            let inside = (0.0..1.0).contains(&l2) && px.abs() <= 1e30 * (1.0 - l2);
            let want = if inside {
                let l1 = (1.0 - l2) / 2.0 + px / 2e30 * (1.0 - l2);
                [1.0 - l1 - l2, l1, l2]
            } else {
                [0.0; 3]
            };
            assert_rgb(&img, x, y, want, 1.0, "band");
        }
    }
}

/// Normals scaled by 1e-20, 1e-30 and 1e25 under GL_NORMALIZE normalise to the unit normals
/// (section 2.11.3), so each of those spheres is the unit-normal one, pixel for pixel (that one
/// matches Mesa in the differential test; Mesa lights the others as if the normal were zero).
#[test]
fn scaled_normals_light_like_unit_normals() {
    use tilegl_conformance::scenes_extremes::NORMAL_SCALES;
    // The squared lengths a single-precision normalisation would take: subnormal, zero, and
    // infinite.
    let squares = NORMAL_SCALES.map(|s| s * s);
    assert_eq!(NORMAL_SCALES[0], 1.0);
    assert!(squares[1] < f32::MIN_POSITIVE && squares[2] == 0.0 && squares[3].is_infinite());
    let img = tilegl_picture("extreme_normals_1e_minus_20");
    if mesa::require_mesa("scaled_normals_light_like_unit_normals") {
        // The unit-normal cell is Mesa's.
        let scene = scenes::find("extreme_normals_1e_minus_20").unwrap();
        let (mesa, _) = render_mesa(scene).expect("Mesa renders");
        for y in 0..32 {
            for x in 0..32 {
                let (a, b) = (img.pixel(x, y), mesa.image.pixel(x, y));
                assert!(
                    (0..4).all(|c| a[c].abs_diff(b[c]) <= 8),
                    "unit normals at ({x}, {y}): tilegl {a:?}, Mesa {b:?}"
                );
            }
        }
    }
    for cell in 1..4 {
        let (ox, oy) = (32 * (cell % 2), 32 * (cell / 2));
        let mut lit = 0;
        for y in 0..32 {
            for x in 0..32 {
                let (a, b) = (img.pixel(x, y), img.pixel(x + ox, y + oy));
                for c in 0..3 {
                    assert!(
                        a[c].abs_diff(b[c]) <= 1,
                        "({x}, {y}): unit normals give {a:?}, normals scaled by {} {b:?}",
                        NORMAL_SCALES[cell as usize]
                    );
                }
                lit += usize::from(b[0] > 120);
            }
        }
        // The diffuse term is there (a zero normal leaves the ambient 0.2 x 0.8 only).
        assert!(lit > 50, "only {lit} brightly lit pixels");
    }
}

/// The texel grid of the texture scenes: texel (i, j) is (16 i + 8, 16 j + 8, 16 (i ^ j)).
fn texel(i: i64, j: i64) -> [f64; 3] {
    let (i, j) = (i.rem_euclid(16), j.rem_euclid(16));
    [
        (16 * i + 8) as f64 / 255.0,
        (16 * j + 8) as f64 / 255.0,
        (16 * (i ^ j)) as f64 / 255.0,
    ]
}

/// Texture coordinates near +-2^20 with REPEAT: the exact texel (NEAREST) and the exact
/// bilinear blend (LINEAR, sections 3.8.7 and 3.8.8) at each pixel's coordinates as single
/// precision holds them (the specification asks for 1 part in 10^5; Mesa's LINEAR rows are one
/// flat grey).
#[test]
fn texcoords_near_2_20_sample_exactly_at_the_float_coordinates() {
    let img = tilegl_picture("extreme_texcoords_2_20_repeat");
    for row in 0..4 {
        let linear = row % 2 == 1;
        for y in 16 * row..16 * row + 16 {
            for x in 0..64 {
                // s runs over one repeat across the 64 pixels, t over a quarter up the 16 rows;
                // the fraction of base + a is a for base = +-2^20.
                let fs = (x as f64 + 0.5) / 64.0;
                let ft = 0.25 * ((y - 16 * row) as f64 + 0.5) / 16.0;
                // The coordinates as floats hold them (to 1/8 of a repeat at 2^20, 1/16 at
                // -2^20: two texels and one); the samples are exact at those.
                let base = if row < 2 { 1_048_576.0 } else { -1_048_576.0 };
                let held = |f: f64| f64::from((base + f) as f32) - base;
                let (fs, ft) = (held(fs), held(ft));
                let want = if linear {
                    let (u, v) = (16.0 * fs - 0.5, 16.0 * ft - 0.5);
                    let (i0, j0) = (u.floor() as i64, v.floor() as i64);
                    let (a, b) = (u - u.floor(), v - v.floor());
                    let mut c = [0.0; 3];
                    for (di, dj, w) in [
                        (0, 0, (1.0 - a) * (1.0 - b)),
                        (1, 0, a * (1.0 - b)),
                        (0, 1, (1.0 - a) * b),
                        (1, 1, a * b),
                    ] {
                        let t = texel(i0 + di, j0 + dj);
                        for k in 0..3 {
                            c[k] += w * t[k];
                        }
                    }
                    c
                } else {
                    texel((16.0 * fs).floor() as i64, (16.0 * ft).floor() as i64)
                };
                assert_rgb(
                    &img,
                    x,
                    y,
                    want,
                    2.0,
                    if linear { "LINEAR" } else { "NEAREST" },
                );
            }
        }
    }
}

/// The good squares drawn after each triangle with a NaN or an infinity (in an attribute or a
/// matrix) match Mesa's: a bad value leaves no trace in later primitives.
#[test]
fn good_primitives_after_nan_and_inf_match_mesa() {
    if !mesa::require_mesa("good_primitives_after_nan_and_inf_match_mesa") {
        return;
    }
    for name in ["extreme_nan_inf_attributes", "extreme_nan_inf_matrices"] {
        let scene = scenes::find(name).unwrap();
        let ours = tilegl_picture(name);
        let (theirs, _) = render_mesa(scene).expect("Mesa renders");
        for cell in 0..16 {
            // The square spans [0.2, 0.9] of the 16-pixel cell: pixels 10 to 14.
            let (cx, cy) = (16 * (cell % 4), 16 * (cell / 4));
            for y in cy + 10..cy + 15 {
                for x in cx + 10..cx + 15 {
                    let (a, b) = (ours.pixel(x, y), theirs.image.pixel(x, y));
                    assert!(
                        (0..4).all(|c| a[c].abs_diff(b[c]) <= 8),
                        "{name}, cell {cell}, ({x}, {y}): tilegl {a:?}, Mesa {b:?}"
                    );
                }
            }
        }
    }
}

//! Twin tests of the state toggles that moved onto the eight-lane routes (issue 23): the
//! polygon stipple as a lane mask of the row-pair blocks, the logic op in the eight-fragment
//! tail, and the stencil of a 4x2 block read and written as two words.
//!
//! The stipple is checked against the specification itself (section 3.5.2: a polygon's
//! fragment at window (x, y) is kept if and only if bit (x mod 32, y mod 32) of the pattern
//! is 1, the pattern unpacked as a 32x32 bitmap, most significant bit first): the stippled
//! picture must be the unstippled one where the bit is set and the background elsewhere, on
//! the chosen route and on the general path. The logic op and stencil states are drawn on the
//! general path (forced) and on the chosen route: every buffer must be identical, and each
//! draw must change the picture.

mod common;

use common::{random_texture, read_buffers, Rng};
use tilegl::enums::*;
use tilegl::{Context, Gl};

/// Wider and taller than a tile (64), and not a multiple of 32: blocks hang over the tiles'
/// edges and the pattern wraps inside tiles.
const SIZE: i32 = 100;

/// Clears to a known background (colour, depth 1, stencil 0x10) with a perspective view.
fn clear(gl: &mut Context) {
    gl.clear_color(0.2, 0.1, 0.0, 1.0);
    gl.clear_stencil(0x10);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
}

/// `count` random triangles through the view volume (depth-tested where the state enables
/// it), with random colours and alphas, texture coordinates and normals.
fn triangles(gl: &mut Context, rng: &mut Rng, count: usize) {
    gl.begin(GL_TRIANGLES);
    for _ in 0..count {
        let c = [
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-9.0, -0.5),
        ];
        for _ in 0..3 {
            gl.color_4f(
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
                rng.range(0.0, 1.0),
                rng.range(0.3, 1.0),
            );
            gl.tex_coord_2f(rng.range(-2.0, 2.0), rng.range(-2.0, 2.0));
            gl.multi_tex_coord_2f(GL_TEXTURE1, rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
            gl.vertex_3f(
                c[0] + rng.range(-2.5, 2.5),
                c[1] + rng.range(-2.5, 2.5),
                c[2] + rng.range(-1.0, 1.0),
            );
        }
    }
    gl.end();
}

/// A screen-covering quad in window space (constant colour, no depth test), for keys whose
/// rows are long.
fn cover(gl: &mut Context, color: [f32; 4]) {
    gl.matrix_mode(GL_PROJECTION);
    gl.push_matrix();
    gl.load_identity();
    gl.matrix_mode(GL_MODELVIEW);
    gl.push_matrix();
    gl.load_identity();
    gl.disable(GL_DEPTH_TEST);
    gl.color_4f(color[0], color[1], color[2], color[3]);
    gl.rectf(-0.9, -0.95, 0.97, 0.9);
    gl.matrix_mode(GL_PROJECTION);
    gl.pop_matrix();
    gl.matrix_mode(GL_MODELVIEW);
    gl.pop_matrix();
}

type Setup = (&'static str, fn(&mut Context, &mut Rng));

/// The texturing states the twins run under: none, one RGBA unit (the textured row pairs),
/// one RGB unit, two units with fog (the sampled row pairs).
const TEXTURING: [Setup; 4] = [
    ("untextured", |_, _| {}),
    ("one RGBA unit, trilinear", |gl, rng| {
        random_texture(gl, rng, GL_RGBA, 32, 32);
        gl.tex_parameteri(
            GL_TEXTURE_2D,
            GL_TEXTURE_MIN_FILTER,
            GL_LINEAR_MIPMAP_LINEAR as i32,
        );
        gl.enable(GL_TEXTURE_2D);
    }),
    ("one RGB unit, REPLACE", |gl, rng| {
        random_texture(gl, rng, GL_RGB, 16, 16);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
        gl.enable(GL_TEXTURE_2D);
    }),
    ("two units, EXP fog", |gl, rng| {
        random_texture(gl, rng, GL_RGBA, 16, 16);
        gl.tex_parameteri(
            GL_TEXTURE_2D,
            GL_TEXTURE_MIN_FILTER,
            GL_NEAREST_MIPMAP_LINEAR as i32,
        );
        gl.enable(GL_TEXTURE_2D);
        gl.active_texture(GL_TEXTURE1);
        random_texture(gl, rng, GL_LUMINANCE, 8, 8);
        gl.enable(GL_TEXTURE_2D);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD as i32);
        gl.active_texture(GL_TEXTURE0);
        gl.enable(GL_FOG);
        gl.fogi(GL_FOG_MODE, GL_EXP as i32);
        gl.fogf(GL_FOG_DENSITY, 0.2);
    }),
];

/// Whether the stipple `pattern` (as given to `glPolygonStipple`, default unpacking: rows of
/// four bytes, the first pixel in the most significant bit) keeps window pixel (x, y).
fn stipple_keeps(pattern: &[u8; 128], x: i32, y: i32) -> bool {
    let (x, y) = (x.rem_euclid(32) as usize, y.rem_euclid(32) as usize);
    pattern[4 * y + x / 8] & (0x80 >> (x % 8)) != 0
}

/// A stippled picture is the unstippled one where the pattern's bit is set and the background
/// elsewhere (colour, depth and stencil), for every texturing state, with the depth test,
/// stencil actions, blending, a logic op and antialiased polygons, on the chosen route and on
/// the general path.
#[test]
fn stippled_pictures_are_unstippled_ones_masked_by_the_pattern() {
    let extras: [Setup; 5] = [
        ("depth test", |gl, _| gl.enable(GL_DEPTH_TEST)),
        ("depth test, stencil INCR on pass", |gl, _| {
            gl.enable(GL_DEPTH_TEST);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_ALWAYS, 0, 0xFF);
            gl.stencil_op(GL_INVERT, GL_DECR, GL_INCR);
        }),
        ("blended, no depth test", |gl, _| {
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        }),
        ("depth test, logic op XOR", |gl, _| {
            gl.enable(GL_DEPTH_TEST);
            gl.enable(GL_COLOR_LOGIC_OP);
            gl.logic_op(GL_XOR);
        }),
        ("antialiased polygons", |gl, _| {
            gl.enable(GL_POLYGON_SMOOTH);
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE);
        }),
    ];
    let mut rng = Rng(0x5717);
    let mut pattern = [0u8; 128];
    for b in pattern.iter_mut() {
        *b = rng.next_u64() as u8;
    }
    // A row of all ones and one of all zeros too.
    pattern[..4].fill(0xFF);
    pattern[4..8].fill(0);
    let (mut kept, mut dropped) = (0, 0);
    for (tname, texturing) in TEXTURING {
        for (ename, extra) in extras {
            let render = |general: bool, stippled: bool| {
                let mut gl = Context::new(SIZE, SIZE);
                gl.set_force_general_path(general);
                clear(&mut gl);
                let mut rng = Rng(0x5EED);
                texturing(&mut gl, &mut rng);
                extra(&mut gl, &mut rng);
                if stippled {
                    gl.polygon_stipple(&pattern);
                    gl.enable(GL_POLYGON_STIPPLE);
                }
                triangles(&mut gl, &mut rng, 120);
                cover(&mut gl, [0.9, 0.5, 0.2, 0.4]);
                assert_eq!(gl.get_error(), GL_NO_ERROR, "{tname}, {ename}");
                read_buffers(&mut gl)
            };
            let background = {
                let mut gl = Context::new(SIZE, SIZE);
                clear(&mut gl);
                read_buffers(&mut gl)
            };
            for general in [false, true] {
                let plain = render(general, false);
                let stippled = render(general, true);
                assert_ne!(plain.0, background.0, "{tname}, {ename}: nothing drawn");
                for y in 0..SIZE {
                    for x in 0..SIZE {
                        let i = (y * SIZE + x) as usize;
                        let (want, keep) = if stipple_keeps(&pattern, x, y) {
                            (&plain, true)
                        } else {
                            (&background, false)
                        };
                        let what = format!("{tname}, {ename}, general {general}, ({x}, {y})");
                        assert_eq!(stippled.0[i], want.0[i], "{what}: colour");
                        assert_eq!(
                            stippled.1[4 * i..4 * i + 4],
                            want.1[4 * i..4 * i + 4],
                            "{what}: depth"
                        );
                        assert_eq!(stippled.2[i], want.2[i], "{what}: stencil");
                        if plain.0[i] != background.0[i] {
                            if keep {
                                kept += 1;
                            } else {
                                dropped += 1;
                            }
                        }
                    }
                }
            }
        }
    }
    // Both kinds of pixels were seen in numbers.
    assert!(kept > 10_000 && dropped > 10_000, "{kept} {dropped}");
}

/// Draws `setup` over the triangles of [`clear`] and [`triangles`] (depth-tested, the stencil
/// holding a few values) on the general path and on the chosen route: the three buffers must
/// be identical and the draw must change the picture.
fn twins(name: &str, setup: impl Fn(&mut Context, &mut Rng)) {
    let render = |general: bool, draw: bool| {
        let mut gl = Context::new(SIZE, SIZE);
        gl.set_force_general_path(general);
        clear(&mut gl);
        let mut rng = Rng(0x5EED);
        gl.enable(GL_DEPTH_TEST);
        gl.enable(GL_STENCIL_TEST);
        gl.stencil_func(GL_ALWAYS, 0x13, 0xFF);
        gl.stencil_op(GL_KEEP, GL_INCR, GL_REPLACE);
        triangles(&mut gl, &mut rng, 60);
        gl.disable(GL_STENCIL_TEST);
        if draw {
            setup(&mut gl, &mut rng);
            triangles(&mut gl, &mut rng, 120);
            cover(&mut gl, [0.3, 0.6, 0.9, 0.5]);
        }
        assert_eq!(gl.get_error(), GL_NO_ERROR, "{name}");
        read_buffers(&mut gl)
    };
    let general = render(true, true);
    let fast = render(false, true);
    let off = general
        .0
        .iter()
        .zip(&fast.0)
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(off, 0, "{name}: {off} pixels differ");
    assert!(general.1 == fast.1, "{name}: depth");
    assert!(general.2 == fast.2, "{name}: stencil");
    let before = render(true, false);
    assert!(
        general.0 != before.0 || general.1 != before.1 || general.2 != before.2,
        "{name}: the draw changed nothing"
    );
}

/// Every logic op (section 4.1.10) in the eight-fragment tail, for every texturing state, with
/// the depth test: the same buffers as the general path's `LogicOp::apply` per fragment; with
/// a colour mask, a stencil test and alpha blending enabled too (which the logic op replaces).
#[test]
fn logic_ops_in_the_eight_lane_tail_match_the_general_path() {
    for (tname, texturing) in TEXTURING {
        for op in GL_CLEAR..=GL_SET {
            twins(&format!("{tname}, logic op {op:#x}"), |gl, rng| {
                texturing(gl, rng);
                gl.enable(GL_COLOR_LOGIC_OP);
                gl.logic_op(op);
            });
        }
        twins(&format!("{tname}, XOR, colour mask, stencil"), |gl, rng| {
            texturing(gl, rng);
            gl.enable(GL_COLOR_LOGIC_OP);
            gl.logic_op(GL_XOR);
            gl.color_mask(1, 0, 1, 0);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_NOTEQUAL, 0x10, 0xFF);
            gl.stencil_op(GL_KEEP, GL_KEEP, GL_INCR);
        });
        twins(&format!("{tname}, AND_REVERSE over blending"), |gl, rng| {
            texturing(gl, rng);
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            gl.enable(GL_COLOR_LOGIC_OP);
            gl.logic_op(GL_AND_REVERSE);
        });
    }
}

/// The stencil of the row-pair blocks (two words per block, lanes outside the primitive
/// written back as they were) and its one-action form (`KEEP`, `KEEP`, op): the toggle's
/// `ALWAYS`/`REPLACE`, the shadow volumes' `INCR`/`DECR` on pass, and a full set of actions
/// with masks, for every texturing state.
#[test]
fn block_stencil_matches_the_general_path() {
    for (tname, texturing) in TEXTURING {
        twins(&format!("{tname}, ALWAYS, REPLACE on pass"), |gl, rng| {
            texturing(gl, rng);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_ALWAYS, 1, 0xFF);
            gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
        });
        twins(&format!("{tname}, LEQUAL, INCR on pass"), |gl, rng| {
            texturing(gl, rng);
            gl.enable(GL_STENCIL_TEST);
            gl.stencil_func(GL_LEQUAL, 0x11, 0xFF);
            gl.stencil_op(GL_KEEP, GL_KEEP, GL_INCR);
        });
        twins(
            &format!("{tname}, GREATER, masks, three actions"),
            |gl, rng| {
                texturing(gl, rng);
                gl.enable(GL_STENCIL_TEST);
                gl.stencil_func(GL_GREATER, 0x12, 0x1F);
                gl.stencil_mask(0xF5);
                gl.stencil_op(GL_ZERO, GL_INCR_WRAP, GL_DECR_WRAP);
            },
        );
    }
}

/// Blending in the eight-lane tail in 16-bit integer lanes (every factor that is a byte of the
/// source or destination, every equation, separate alpha factors and equation), the alpha
/// test before it and with fog, and the constant colour's factors (which stay in f32), for
/// every texturing state: the same buffers as the general path's `blend::blend` per fragment.
#[test]
fn blending_in_the_eight_lane_tail_matches_the_general_path() {
    let factors = [
        GL_ZERO,
        GL_ONE,
        GL_SRC_COLOR,
        GL_ONE_MINUS_SRC_COLOR,
        GL_DST_COLOR,
        GL_ONE_MINUS_DST_COLOR,
        GL_SRC_ALPHA,
        GL_ONE_MINUS_SRC_ALPHA,
        GL_DST_ALPHA,
        GL_ONE_MINUS_DST_ALPHA,
        GL_SRC_ALPHA_SATURATE,
    ];
    for (tname, texturing) in TEXTURING {
        // Each source factor against two destination factors (all of them met; the
        // saturate factor is a source factor only), under ADD.
        for (i, &src) in factors.iter().enumerate() {
            for k in [3, 7] {
                let dst = factors[(i + k) % (factors.len() - 1)];
                twins(&format!("{tname}, {src:#x}, {dst:#x}"), |gl, rng| {
                    texturing(gl, rng);
                    gl.enable(GL_BLEND);
                    gl.blend_func(src, dst);
                });
            }
        }
        for eq in [
            GL_FUNC_ADD,
            GL_FUNC_SUBTRACT,
            GL_FUNC_REVERSE_SUBTRACT,
            GL_MIN,
            GL_MAX,
        ] {
            twins(&format!("{tname}, equation {eq:#x}"), |gl, rng| {
                texturing(gl, rng);
                gl.enable(GL_BLEND);
                gl.blend_equation(eq);
                gl.blend_func(GL_SRC_ALPHA, GL_DST_COLOR);
            });
        }
        twins(&format!("{tname}, separate"), |gl, rng| {
            texturing(gl, rng);
            gl.enable(GL_BLEND);
            gl.blend_equation_separate_ext(GL_FUNC_REVERSE_SUBTRACT, GL_FUNC_ADD);
            gl.blend_func_separate(
                GL_SRC_ALPHA_SATURATE,
                GL_ONE_MINUS_DST_COLOR,
                GL_DST_ALPHA,
                GL_ONE_MINUS_SRC_ALPHA,
            );
        });
        twins(&format!("{tname}, constant colour"), |gl, rng| {
            texturing(gl, rng);
            gl.enable(GL_BLEND);
            gl.blend_color(0.3, 0.55, 0.8, 0.45);
            gl.blend_func(GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA);
        });
        twins(&format!("{tname}, alpha test and alpha over"), |gl, rng| {
            texturing(gl, rng);
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_GREATER, 0.45);
            gl.enable(GL_BLEND);
            gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        });
        twins(&format!("{tname}, EXP2 fog and alpha test"), |gl, rng| {
            texturing(gl, rng);
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_EXP2 as i32);
            gl.fogf(GL_FOG_DENSITY, 0.15);
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_LEQUAL, 0.6);
        });
    }
}

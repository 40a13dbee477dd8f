//! Multipass invariance (appendix A of the spec, rules 1-3): the same geometry drawn with a
//! different fragment state produces exactly the same fragments and depths, so a second pass
//! with `GL_EQUAL` (or `GL_LEQUAL`) touches every pixel of the first and nothing else.

mod common;

use common::{read_rgba, Rng};
use tilegl::enums::*;
use tilegl::{Context, Gl};

const W: i32 = 96;

fn geometry(gl: &mut Context) {
    let mut rng = Rng(0x1234_5678_9ABC_DEF1);
    gl.begin(GL_TRIANGLES);
    for _ in 0..60 {
        let (cx, cy, cz) = (
            rng.range(-1.3, 1.3),
            rng.range(-1.3, 1.3),
            rng.range(-6.0, -1.5),
        );
        for _ in 0..3 {
            gl.normal_3f(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 1.0);
            gl.tex_coord_2f(rng.range(0.0, 2.0), rng.range(0.0, 2.0));
            gl.vertex_3f(
                cx + rng.range(-0.9, 0.9),
                cy + rng.range(-0.9, 0.9),
                cz + rng.range(-1.5, 1.5),
            );
        }
    }
    gl.end();
}

fn setup() -> Context {
    let mut gl = Context::new(W, W);
    gl.matrix_mode(GL_PROJECTION);
    gl.frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 8.0);
    gl.matrix_mode(GL_MODELVIEW);
    // A user clip plane cuts some triangles in both passes.
    gl.clip_plane(GL_CLIP_PLANE0, &[1.0, 0.2, 0.0, 0.8]);
    gl.enable(GL_CLIP_PLANE0);
    gl.enable(GL_DEPTH_TEST);
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl
}

fn texture(gl: &mut Context) {
    let px: Vec<u8> = (0..16 * 16 * 4).map(|k| (k * 29 % 251) as u8).collect();
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        16,
        16,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&px),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
}

#[test]
fn second_passes_with_equal_depth_touch_exactly_the_first_pass_pixels() {
    // Second-pass states: texturing + fog + blending; lighting two-sided (another assembly
    // route); alpha test and stencil; polygon stipple off but a colour mask.
    type SecondPass = (&'static str, Box<dyn Fn(&mut Context)>);
    let second_passes: Vec<SecondPass> = vec![
        (
            "texture, fog, blend",
            Box::new(|gl| {
                texture(gl);
                gl.enable(GL_TEXTURE_2D);
                gl.enable(GL_FOG);
                gl.enable(GL_BLEND);
                gl.blend_func(GL_ONE, GL_ZERO);
            }),
        ),
        (
            "two-sided lighting",
            Box::new(|gl| {
                gl.enable(GL_LIGHTING);
                gl.enable(GL_LIGHT0);
                gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
                gl.enable(GL_COLOR_MATERIAL);
            }),
        ),
        (
            "alpha test, stencil, flat shading",
            Box::new(|gl| {
                gl.enable(GL_ALPHA_TEST);
                gl.alpha_func(GL_ALWAYS, 0.0);
                gl.enable(GL_STENCIL_TEST);
                gl.stencil_func(GL_ALWAYS, 1, 0xFF);
                gl.shade_model(GL_FLAT);
            }),
        ),
    ];
    for (name, state) in second_passes {
        for func in [GL_EQUAL, GL_LEQUAL] {
            let mut gl = setup();
            gl.color_3f(1.0, 0.0, 0.0);
            geometry(&mut gl);
            let first = read_rgba(&mut gl);
            let mut depth_before = vec![0u8; (W * W * 4) as usize];
            gl.read_pixels(
                0,
                0,
                W,
                W,
                GL_DEPTH_COMPONENT,
                GL_UNSIGNED_INT,
                &mut depth_before,
            );
            state(&mut gl);
            gl.depth_func(func);
            gl.depth_mask(0);
            gl.color_3f(0.0, 1.0, 0.0);
            geometry(&mut gl);
            let second = read_rgba(&mut gl);
            let mut depth_after = vec![0u8; (W * W * 4) as usize];
            gl.read_pixels(
                0,
                0,
                W,
                W,
                GL_DEPTH_COMPONENT,
                GL_UNSIGNED_INT,
                &mut depth_after,
            );
            assert_eq!(depth_before, depth_after, "{name}");
            let covered = first.iter().filter(|p| p[0] == 255).count();
            assert!(
                covered > 1000,
                "{name}: the first pass covers {covered} pixels"
            );
            for (i, (a, b)) in first.iter().zip(&second).enumerate() {
                if a[0] == 255 {
                    // Every first-pass pixel was redrawn (with EQUAL: by its own fragment).
                    assert_ne!(b, a, "{name} {func:#x}: pixel {i} not redrawn");
                } else {
                    assert_eq!(b, a, "{name} {func:#x}: pixel {i} outside the first pass");
                }
            }
        }
    }
}

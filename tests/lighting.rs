#![allow(clippy::needless_range_loop)] // the lighting sums index several colour arrays per channel
//! Lighting (section 2.14.1) checked against the equations evaluated in the test.

mod common;

use common::pixel;
use tilegl::enums::*;
use tilegl::{Context, Gl};

type V3 = [f64; 3];
fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn norm(a: V3) -> V3 {
    let l = dot(a, a).sqrt();
    [a[0] / l, a[1] / l, a[2] / l]
}

struct L {
    amb: [f64; 4],
    dif: [f64; 4],
    spe: [f64; 4],
    pos: [f64; 4],
    spot_dir: V3,
    spot_exp: f64,
    cutoff: f64,
    att: [f64; 3],
}

struct M {
    amb: [f64; 4],
    dif: [f64; 4],
    spe: [f64; 4],
    emi: [f64; 4],
    shin: f64,
}

/// The specification's equation for one face, eye-space vertex `v`, unit normal `n`,
/// infinite viewer, single colour; returns RGB clamped.
fn spec_light(
    v: V3,
    n: V3,
    m: &M,
    lights: &[L],
    model_amb: [f64; 4],
    local_viewer: bool,
) -> [f64; 3] {
    let mut c = [0.0; 3];
    for i in 0..3 {
        c[i] = m.emi[i] + m.amb[i] * model_amb[i];
    }
    for l in lights {
        let (vp, att) = if l.pos[3] == 0.0 {
            (norm([l.pos[0], l.pos[1], l.pos[2]]), 1.0)
        } else {
            let d = sub(
                [
                    l.pos[0] / l.pos[3],
                    l.pos[1] / l.pos[3],
                    l.pos[2] / l.pos[3],
                ],
                v,
            );
            let dist = dot(d, d).sqrt();
            (
                norm(d),
                1.0 / (l.att[0] + l.att[1] * dist + l.att[2] * dist * dist),
            )
        };
        let spot = if l.cutoff == 180.0 {
            1.0
        } else {
            let s = dot([-vp[0], -vp[1], -vp[2]], norm(l.spot_dir));
            if s >= l.cutoff.to_radians().cos() {
                s.powf(l.spot_exp)
            } else {
                0.0
            }
        };
        let ndvp = dot(n, vp).max(0.0);
        let eye = if local_viewer {
            norm([-v[0], -v[1], -v[2]])
        } else {
            [0.0, 0.0, 1.0]
        };
        let h = norm([vp[0] + eye[0], vp[1] + eye[1], vp[2] + eye[2]]);
        let spec = if ndvp > 0.0 && dot(n, h) > 0.0 {
            dot(n, h).powf(m.shin)
        } else {
            0.0
        };
        for i in 0..3 {
            c[i] += att
                * spot
                * (m.amb[i] * l.amb[i] + ndvp * m.dif[i] * l.dif[i] + spec * m.spe[i] * l.spe[i]);
        }
    }
    c.map(|x| x.clamp(0.0, 1.0))
}

fn set_light(gl: &mut Context, i: u32, l: &L) {
    let f = |v: [f64; 4]| v.map(|x| x as f32);
    let light = GL_LIGHT0 + i;
    gl.enable(light);
    gl.lightfv(light, GL_AMBIENT, &f(l.amb));
    gl.lightfv(light, GL_DIFFUSE, &f(l.dif));
    gl.lightfv(light, GL_SPECULAR, &f(l.spe));
    gl.lightfv(light, GL_POSITION, &f(l.pos));
    gl.lightfv(light, GL_SPOT_DIRECTION, &l.spot_dir.map(|x| x as f32));
    gl.lightf(light, GL_SPOT_EXPONENT, l.spot_exp as f32);
    gl.lightf(light, GL_SPOT_CUTOFF, l.cutoff as f32);
    gl.lightf(light, GL_CONSTANT_ATTENUATION, l.att[0] as f32);
    gl.lightf(light, GL_LINEAR_ATTENUATION, l.att[1] as f32);
    gl.lightf(light, GL_QUADRATIC_ATTENUATION, l.att[2] as f32);
}

fn set_material(gl: &mut Context, face: GLenum, m: &M) {
    let f = |v: [f64; 4]| v.map(|x| x as f32);
    gl.materialfv(face, GL_AMBIENT, &f(m.amb));
    gl.materialfv(face, GL_DIFFUSE, &f(m.dif));
    gl.materialfv(face, GL_SPECULAR, &f(m.spe));
    gl.materialfv(face, GL_EMISSION, &f(m.emi));
    gl.materialf(face, GL_SHININESS, m.shin as f32);
}

/// Draws a tiny quad around eye-space point `p` (identity modelview, orthographic projection
/// of [-2, 2]^2, z from +10 to -10) with normal `n`, and returns the colour at its pixel.
fn lit_pixel(gl: &mut Context, p: V3, n: V3, back_facing: bool) -> [u8; 4] {
    // Put the quad's centre on a pixel centre.
    let snap = |c: f64| (((c + 2.0) / 4.0 * 64.0).floor() + 0.5) / 64.0 * 4.0 - 2.0;
    let p = [snap(p[0]), snap(p[1]), p[2]];
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-2.0, 2.0, -2.0, 2.0, -10.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.normal_3f(n[0] as f32, n[1] as f32, n[2] as f32);
    let e = 0.03f32;
    let (x, y, z) = (p[0] as f32, p[1] as f32, p[2] as f32);
    gl.begin(GL_QUADS);
    let mut q = vec![
        (x - e, y - e),
        (x + e, y - e),
        (x + e, y + e),
        (x - e, y + e),
    ];
    if back_facing {
        q.reverse();
    }
    for (a, b) in q {
        gl.vertex_3f(a, b, z);
    }
    gl.end();
    let px = ((x + 2.0) / 4.0 * 64.0) as i32;
    let py = ((y + 2.0) / 4.0 * 64.0) as i32;
    pixel(gl, px, py)
}

fn close(got: [u8; 4], expected: [f64; 3], tol: f64, what: &str) {
    for i in 0..3 {
        let e = expected[i] * 255.0;
        assert!(
            (got[i] as f64 - e).abs() <= tol,
            "{what}: channel {i} got {} expected {e:.2} ({got:?})",
            got[i]
        );
    }
}

fn material() -> M {
    M {
        amb: [0.3, 0.2, 0.1, 1.0],
        dif: [0.6, 0.5, 0.4, 0.75],
        spe: [0.5, 0.5, 0.5, 1.0],
        emi: [0.05, 0.0, 0.1, 1.0],
        shin: 20.0,
    }
}

fn light(pos: [f64; 4]) -> L {
    L {
        amb: [0.1, 0.1, 0.1, 1.0],
        dif: [0.8, 0.7, 0.9, 1.0],
        spe: [0.6, 0.6, 0.6, 1.0],
        pos,
        spot_dir: [0.0, 0.0, -1.0],
        spot_exp: 0.0,
        cutoff: 180.0,
        att: [1.0, 0.0, 0.0],
    }
}

#[test]
fn directional_positional_attenuated_and_spot_lights() {
    let model_amb = [0.2, 0.2, 0.2, 1.0];
    let n = norm([0.3, 0.2, 1.0]);
    let cases: Vec<(&str, Vec<L>, V3, bool)> = vec![
        (
            "directional",
            vec![light([0.5, 0.8, 1.0, 0.0])],
            [0.0, 0.0, 0.0],
            false,
        ),
        (
            "positional attenuated",
            vec![L {
                att: [0.5, 0.2, 0.1],
                ..light([1.0, 1.0, 2.0, 1.0])
            }],
            [0.5, -0.5, 0.0],
            false,
        ),
        (
            "spot inside cutoff",
            vec![L {
                spot_dir: [0.0, -0.2, -1.0],
                spot_exp: 8.0,
                cutoff: 30.0,
                ..light([0.0, 0.5, 3.0, 1.0])
            }],
            [0.1, 0.0, 0.0],
            false,
        ),
        (
            "spot outside cutoff",
            vec![L {
                spot_dir: [1.0, 0.0, -1.0],
                cutoff: 10.0,
                ..light([0.0, 0.5, 3.0, 1.0])
            }],
            [-1.0, 0.0, 0.0],
            false,
        ),
        (
            "two lights, local viewer",
            vec![light([0.5, 0.8, 1.0, 0.0]), light([-1.0, 1.0, 3.0, 1.0])],
            [0.3, 0.3, 0.0],
            true,
        ),
    ];
    for (name, lights, p, local_viewer) in cases {
        let mut gl = Context::new(64, 64);
        gl.enable(GL_LIGHTING);
        gl.light_modelfv(GL_LIGHT_MODEL_AMBIENT, &model_amb.map(|x| x as f32));
        gl.light_modeli(GL_LIGHT_MODEL_LOCAL_VIEWER, local_viewer as i32);
        gl.enable(GL_NORMALIZE);
        for (i, l) in lights.iter().enumerate() {
            set_light(&mut gl, i as u32, l);
        }
        set_material(&mut gl, GL_FRONT_AND_BACK, &material());
        assert_eq!(gl.get_error(), GL_NO_ERROR, "{name}");
        let got = lit_pixel(&mut gl, p, n, false);
        let snap = |c: f64| (((c + 2.0) / 4.0 * 64.0).floor() + 0.5) / 64.0 * 4.0 - 2.0;
        let p = [snap(p[0]), snap(p[1]), p[2]];
        let expected = spec_light(p, n, &material(), &lights, model_amb, local_viewer);
        close(got, expected, 1.5, name);
        // Alpha is the material's diffuse alpha.
        assert_eq!(got[3], (0.75f64 * 255.0).round() as u8, "{name}: alpha");
    }
}

#[test]
fn two_sided_lighting_uses_the_back_material() {
    let mut gl = Context::new(64, 64);
    gl.enable(GL_LIGHTING);
    gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    let l = light([0.0, 0.0, 1.0, 0.0]);
    set_light(&mut gl, 0, &l);
    let front = material();
    let back = M {
        dif: [0.1, 0.9, 0.2, 1.0],
        amb: [0.0, 0.0, 0.5, 1.0],
        ..material()
    };
    set_material(&mut gl, GL_FRONT, &front);
    set_material(&mut gl, GL_BACK, &back);
    // The normal points away from the viewer, so the back face (drawn clockwise) sees the
    // light along -n.
    let n = [0.0, 0.0, -1.0];
    let got = lit_pixel(&mut gl, [0.0, 0.0, 0.0], n, true);
    let expected = spec_light(
        [0.0; 3],
        [0.0, 0.0, 1.0],
        &back,
        &[l],
        [0.2, 0.2, 0.2, 1.0],
        false,
    );
    close(got, expected, 1.5, "back face");
    // Without two-sided lighting the front material is used with the original normal.
    gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, 0);
    let got = lit_pixel(&mut gl, [0.0, 0.0, 0.0], n, true);
    let l = light([0.0, 0.0, 1.0, 0.0]);
    let expected = spec_light([0.0; 3], n, &front, &[l], [0.2, 0.2, 0.2, 1.0], false);
    close(got, expected, 1.5, "one-sided");
}

/// Lighting with one directional light and a specular material, untextured; with
/// `separate`, `GL_SEPARATE_SPECULAR_COLOR`.
fn specular_scene(separate: bool) -> Context {
    let mut gl = Context::new(64, 64);
    gl.enable(GL_LIGHTING);
    if separate {
        gl.light_modeli(
            GL_LIGHT_MODEL_COLOR_CONTROL,
            GL_SEPARATE_SPECULAR_COLOR as i32,
        );
    }
    set_light(
        &mut gl,
        0,
        &L {
            dif: [0.3, 0.3, 0.3, 1.0],
            ..light([0.2, 0.3, 1.0, 0.0])
        },
    );
    set_material(
        &mut gl,
        GL_FRONT,
        &M {
            dif: [0.4, 0.3, 0.2, 1.0],
            ..material()
        },
    );
    gl
}

#[test]
fn separate_specular_equals_single_colour_without_texturing() {
    let render = |separate: bool| {
        let mut gl = specular_scene(separate);
        lit_pixel(&mut gl, [0.0, 0.0, 0.0], [0.0, 0.0, 1.0], false)
    };
    let single = render(false);
    let separate = render(true);
    for i in 0..3 {
        assert!(
            (single[i] as i32 - separate[i] as i32).abs() <= 1,
            "{single:?} vs {separate:?}"
        );
    }
}

#[test]
fn fog_with_separate_specular_and_no_texture() {
    // Fog, the colour sum (separate specular) and no texture unit together: the draw carries
    // the fog coordinate and the secondary colour. Exponential fog of density 0 has factor 1,
    // so the picture must equal the unfogged one (it once panicked instead).
    let render = |fog: bool| {
        let mut gl = specular_scene(true);
        if fog {
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_EXP as i32);
            gl.fogf(GL_FOG_DENSITY, 0.0);
            gl.fogfv(GL_FOG_COLOR, &[1.0, 0.0, 1.0, 1.0]);
        }
        let p = lit_pixel(&mut gl, [0.0, 0.0, 0.0], [0.0, 0.0, 1.0], false);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        p
    };
    let plain = render(false);
    assert!(plain[..3].iter().any(|&c| c > 0), "{plain:?}");
    assert_eq!(render(true), plain);
}

#[test]
fn color_material_tracks_the_current_colour() {
    let mut gl = Context::new(64, 64);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_COLOR_MATERIAL);
    gl.color_material(GL_FRONT, GL_DIFFUSE);
    let l = light([0.0, 0.0, 1.0, 0.0]);
    set_light(&mut gl, 0, &l);
    set_material(&mut gl, GL_FRONT, &material());
    gl.color_4f(0.2, 0.9, 0.4, 1.0); // becomes the diffuse colour
    let got = lit_pixel(&mut gl, [0.0; 3], [0.0, 0.0, 1.0], false);
    let m = M {
        dif: [0.2, 0.9, 0.4, 1.0],
        ..material()
    };
    close(
        got,
        spec_light(
            [0.0; 3],
            [0.0, 0.0, 1.0],
            &m,
            &[l],
            [0.2, 0.2, 0.2, 1.0],
            false,
        ),
        1.5,
        "colour material",
    );
    let mut d = [0f32; 4];
    gl.get_materialfv(GL_FRONT, GL_DIFFUSE, &mut d);
    assert_eq!(d, [0.2, 0.9, 0.4, 1.0]);
}

#[test]
fn light_position_is_transformed_at_specification_time() {
    let mut gl = Context::new(8, 8);
    gl.translatef(1.0, 2.0, 3.0);
    gl.lightfv(GL_LIGHT1, GL_POSITION, &[1.0, 1.0, 1.0, 1.0]);
    gl.load_identity();
    let mut p = [0f32; 4];
    gl.get_lightfv(GL_LIGHT1, GL_POSITION, &mut p);
    assert_eq!(p, [2.0, 3.0, 4.0, 1.0]);
    // Errors: cutoff out of range, exponent out of range, bad light, vector pname to lightf.
    gl.lightf(GL_LIGHT0, GL_SPOT_CUTOFF, 95.0);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.lightf(GL_LIGHT0, GL_SPOT_EXPONENT, 129.0);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    gl.lightf(GL_LIGHT0 + 8, GL_SPOT_EXPONENT, 1.0);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.lightf(GL_LIGHT0, GL_POSITION, 1.0);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.materialf(GL_FRONT, GL_SHININESS, 200.0);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    let mut c = [0f32];
    gl.get_lightfv(GL_LIGHT0, GL_SPOT_CUTOFF, &mut c);
    assert_eq!(c[0], 180.0);
}

#[test]
fn material_calls_do_not_change_parameters_color_material_tracks() {
    // Section 2.14.3: tracked material parameters follow the current colour at all times.
    let mut gl = Context::new(8, 8);
    gl.color_material(GL_FRONT_AND_BACK, GL_DIFFUSE);
    gl.enable(GL_COLOR_MATERIAL);
    gl.color_4f(0.0, 1.0, 0.0, 1.0);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[1.0, 0.0, 0.0, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    let mut v = [0f32; 4];
    gl.get_materialfv(GL_BACK, GL_DIFFUSE, &mut v);
    assert_eq!(v, [0.0, 1.0, 0.0, 1.0]);
    gl.get_materialfv(GL_FRONT, GL_SPECULAR, &mut v);
    assert_eq!(v, [0.5, 0.5, 0.5, 1.0]);
    // Untracked once disabled.
    gl.disable(GL_COLOR_MATERIAL);
    gl.materialfv(GL_FRONT, GL_DIFFUSE, &[1.0, 0.0, 0.0, 1.0]);
    gl.get_materialfv(GL_FRONT, GL_DIFFUSE, &mut v);
    assert_eq!(v, [1.0, 0.0, 0.0, 1.0]);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

/// Lighting at `glEnd`, eight vertices at a time, gives the colours lighting at `glVertex`
/// gives: a batch whose first call is a `glMaterial` (after which each vertex is lit as it
/// comes) draws the same pixels as the batch without it, under every kind of light, both
/// faces, local viewer, separate specular and each colour-material mode; and a `glMaterial`
/// between two triangles of a batch applies from the next vertex on, as if the batch had
/// ended before it and another begun after it.
#[test]
fn batch_lighting_equals_lighting_vertex_by_vertex() {
    let modes = [
        None,
        Some(GL_AMBIENT_AND_DIFFUSE),
        Some(GL_DIFFUSE),
        Some(GL_SPECULAR),
        Some(GL_EMISSION),
        Some(GL_AMBIENT),
    ];
    #[derive(Clone, Copy, PartialEq)]
    enum Route {
        Batch,
        Eager,
        Split,
    }
    for (case, color_material) in modes.into_iter().enumerate() {
        let draw = |route: Route| {
            let mut gl = Context::new(64, 64);
            gl.matrix_mode(GL_PROJECTION);
            gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
            gl.matrix_mode(GL_MODELVIEW);
            gl.translatef(0.0, 0.0, -1.8);
            gl.enable(GL_LIGHTING);
            gl.enable(GL_NORMALIZE);
            gl.enable(GL_DEPTH_TEST);
            gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, (case % 2) as i32);
            gl.light_modeli(GL_LIGHT_MODEL_LOCAL_VIEWER, (case / 2 % 2) as i32);
            if case >= 3 {
                gl.light_modeli(
                    GL_LIGHT_MODEL_COLOR_CONTROL,
                    GL_SEPARATE_SPECULAR_COLOR as i32,
                );
            }
            gl.enable(GL_LIGHT0);
            gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 0.6, 1.0, 0.0]);
            gl.enable(GL_LIGHT1);
            gl.lightfv(GL_LIGHT1, GL_POSITION, &[0.5, -0.4, 1.5, 1.0]);
            gl.lightfv(GL_LIGHT1, GL_DIFFUSE, &[0.9, 0.5, 0.2, 1.0]);
            gl.lightfv(GL_LIGHT1, GL_SPECULAR, &[0.6, 0.7, 0.9, 1.0]);
            gl.lightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.3);
            gl.lightf(GL_LIGHT1, GL_SPOT_CUTOFF, 50.0);
            gl.lightf(GL_LIGHT1, GL_SPOT_EXPONENT, 3.0);
            gl.lightfv(GL_LIGHT1, GL_SPOT_DIRECTION, &[-0.2, 0.2, -1.0]);
            gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
            gl.materialf(GL_FRONT, GL_SHININESS, 20.0);
            gl.materialfv(GL_BACK, GL_DIFFUSE, &[0.2, 0.8, 0.3, 1.0]);
            if let Some(mode) = color_material {
                gl.color_material(GL_FRONT_AND_BACK, mode);
                gl.enable(GL_COLOR_MATERIAL);
            }
            // Triangles along a folded band (both faces show), colours and normals changing
            // per vertex; 20 x 6 vertices, not a multiple of eight before the change.
            let vertex = |gl: &mut Context, i: usize, k: usize| {
                let x = -0.9 + 0.09 * i as f32;
                let z = 0.4 * (x * 3.0).sin();
                let y = if k == 0 { -0.8 } else { 0.8 };
                gl.color_4f(0.3 + 0.03 * i as f32, 0.9 - 0.4 * k as f32, 0.5, 0.7);
                gl.normal_3f(-(x * 3.0).cos(), 0.2 * k as f32, 1.0);
                gl.vertex_3f(x, y * (1.0 - 0.3 * x), z);
            };
            gl.begin(GL_TRIANGLES);
            if route == Route::Eager {
                gl.materialf(GL_BACK, GL_SHININESS, 0.0);
            }
            for i in 0..20 {
                if i == 13 {
                    if route == Route::Split {
                        gl.end();
                    }
                    gl.materialfv(GL_FRONT_AND_BACK, GL_EMISSION, &[0.1, 0.0, 0.2, 1.0]);
                    if route == Route::Split {
                        gl.begin(GL_TRIANGLES);
                    }
                }
                for (a, b) in [(i, 0), (i + 1, 0), (i, 1), (i, 1), (i + 1, 0), (i + 1, 1)] {
                    vertex(&mut gl, a, b);
                }
            }
            gl.end();
            assert_eq!(gl.get_error(), GL_NO_ERROR);
            common::read_rgba(&mut gl)
        };
        let batch = draw(Route::Batch);
        let lit = batch.iter().filter(|p| p[..3] != [0; 3]).count();
        assert!(lit > 500, "case {case}: {lit} pixels");
        assert!(
            batch == draw(Route::Eager),
            "case {case}: {color_material:?}"
        );
        assert!(
            batch == draw(Route::Split),
            "case {case}: {color_material:?}"
        );
    }
}

//! Differential scenes for the evaluators (section 5.1): a lit Bezier vase with
//! `GL_AUTO_NORMAL`, curves as line strips, colour and texture maps on a patch, a rational
//! (`MAP2_VERTEX_4`) patch with a normal map, and the grid meshes of every mode.

use crate::compare::Scene;
use crate::scenes::{clear, scene};
use tilegl::enums::*;
use tilegl::Gl;

/// Evaluator scenes, in report order.
pub const EVAL_SCENES: &[Scene] = &[
    scene_128("eval_lit_vase_auto_normal", eval_lit_vase_auto_normal),
    scene_128("eval_curves_line_strips", eval_curves_line_strips),
    scene_128("eval_color_texture_patch", eval_color_texture_patch),
    scene_128(
        "eval_rational_patch_normal_map",
        eval_rational_patch_normal_map,
    ),
    scene_128("eval_grid_meshes", eval_grid_meshes),
    scene_128("eval_other_targets", eval_other_targets),
    // Mesa 22 draws this one wrongly (`known_failures::MESA_LESS_EXACT`).
    scene_128("eval_coords_colour_in_a_list", eval_coords_colour_in_a_list),
];

/// piglit `dlist-fdo31590`'s calls (section 5.4: a list's commands run as if issued in
/// order): a display list holding `glBegin(GL_LINE_STRIP)`, `glColor3f(1, 1, 0)` and 31
/// `glEvalCoord1f` of a cubic `MAP1_VERTEX_3`, called while the current colour is white: the
/// strip is yellow, and so is the current colour afterwards, which a rectangle drawn after the
/// call shows.
fn eval_coords_colour_in_a_list(gl: &mut dyn Gl) {
    clear(gl);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-5.0, 5.0, -5.0, 5.0, -5.0, 5.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    let cubic = [
        -4.0, -4.0, 0.0, -2.0, 4.0, 0.0, 2.0, -4.0, 0.0, 4.0, 4.0, 0.0f32,
    ];
    gl.map_1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &cubic);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.new_list(5, GL_COMPILE);
    gl.begin(GL_LINE_STRIP);
    gl.color_3f(1.0, 1.0, 0.0);
    for i in 0..=30 {
        gl.eval_coord_1f(i as f32 / 30.0);
    }
    gl.end();
    gl.end_list();
    gl.color_3f(1.0, 1.0, 1.0);
    gl.call_list(5);
    gl.rectf(3.0, -4.5, 4.5, -3.0);
}

const fn scene_128(name: &'static str, draw: fn(&mut dyn Gl)) -> Scene {
    let s = scene(name, draw);
    Scene {
        width: 128,
        height: 128,
        ..s
    }
}

fn perspective(gl: &mut dyn Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.6, 0.6, -0.6, 0.6, 1.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    clear(gl);
}

/// cubic Bezier approximation of a quarter circle: the inner control points' distance.
const KAPPA: f32 = 0.552_284_8;

/// The control points of the four bicubic patches of a surface of revolution around z whose
/// profile is the cubic Bezier `profile` ((radius, z) pairs): patch q covers the quarter turn
/// from q * 90 degrees; u runs along the profile, v around.
fn revolution_patches(profile: &[[f32; 2]; 4]) -> Vec<Vec<f32>> {
    // Unit quarter circle from (1, 0) to (0, 1).
    let quarter = [[1.0, 0.0], [1.0, KAPPA], [KAPPA, 1.0], [0.0, 1.0]];
    (0..4)
        .map(|q| {
            let (s, c) = ((q as f32) * std::f32::consts::FRAC_PI_2).sin_cos();
            let mut pts = Vec::new();
            for p in profile {
                for qc in &quarter {
                    let (x, y) = (qc[0] * c - qc[1] * s, qc[0] * s + qc[1] * c);
                    pts.extend_from_slice(&[p[0] * x, p[0] * y, p[1]]);
                }
            }
            pts
        })
        .collect()
}

/// A lit vase of eight bicubic patches (body and lid), normals from `GL_AUTO_NORMAL`.
fn eval_lit_vase_auto_normal(gl: &mut dyn Gl) {
    perspective(gl);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_AUTO_NORMAL);
    gl.enable(GL_MAP2_VERTEX_3);
    gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[1.0, 1.5, 2.0, 0.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.8, 0.55, 0.3, 1.0]);
    gl.materialfv(GL_BACK, GL_DIFFUSE, &[0.3, 0.5, 0.8, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.7, 0.7, 0.7, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0);
    gl.translatef(0.0, -0.1, -3.2);
    gl.rotatef(-70.0, 1.0, 0.0, 0.0);
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
    // Body: bulging profile from the foot to the neck; lid: a dome on top.
    let body = [[0.45, -0.8], [1.3, -0.4], [0.2, 0.3], [0.45, 0.7]];
    let lid = [[0.45, 0.7], [0.5, 0.95], [0.2, 1.0], [0.0, 1.05]];
    gl.map_grid_2f(16, 0.0, 1.0, 12, 0.0, 1.0);
    for profile in [body, lid] {
        for pts in revolution_patches(&profile) {
            gl.map_2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &pts);
            gl.eval_mesh_2(GL_FILL, 0, 16, 0, 12);
        }
    }
}

/// Curves: a cubic with a colour ramp by `glEvalMesh1(GL_LINE)`, a quartic by a
/// `glBegin(GL_LINE_STRIP)` loop of `glEvalCoord1d`, a rational quadratic circle arc
/// (`MAP1_VERTEX_4`) by `glEvalPoint1`, and points of a line by `glEvalMesh1(GL_POINT)`.
fn eval_curves_line_strips(gl: &mut dyn Gl) {
    clear(gl);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 128.0, 0.0, 128.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.enable(GL_MAP1_VERTEX_3);
    gl.enable(GL_MAP1_COLOR_4);
    let cubic = [
        8.0, 10.0, 0.0, 30.0, 120.0, 0.0, 90.0, -40.0, 0.0, 120.0, 70.0, 0.0f32,
    ];
    gl.map_1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &cubic);
    let ramp = [
        1.0, 0.2, 0.1, 1.0, 0.1, 1.0, 0.2, 1.0, 0.2, 0.3, 1.0, 1.0f32,
    ];
    gl.map_1f(GL_MAP1_COLOR_4, 0.0, 1.0, 4, 3, &ramp);
    gl.map_grid_1f(40, 0.0, 1.0);
    gl.eval_mesh_1(GL_LINE, 0, 40);

    // Quartic over [-2, 3] with a stride of 5 doubles.
    let quartic = [
        5.0, 120.0, 0.0, 0.0, 0.0, 40.0, 60.0, 0.0, 0.0, 0.0, 64.0, 126.0, 0.0, 0.0, 0.0, 90.0,
        70.0, 0.0, 0.0, 0.0, 124.0, 118.0, 0.0, 0.0, 0.0f64,
    ];
    gl.map_1d(GL_MAP1_VERTEX_3, -2.0, 3.0, 5, 5, &quartic);
    gl.disable(GL_MAP1_COLOR_4);
    gl.color_3f(1.0, 1.0, 0.3);
    gl.begin(GL_LINE_STRIP);
    for i in 0..=30 {
        gl.eval_coord_1d(-2.0 + 5.0 * i as f64 / 30.0);
    }
    gl.end();

    // A quarter circle of radius 50 around (64, 20) as a rational quadratic.
    let w = std::f32::consts::FRAC_1_SQRT_2;
    let arc = [
        114.0,
        20.0,
        0.0,
        1.0,
        114.0 * w,
        70.0 * w,
        0.0,
        w,
        64.0,
        70.0,
        0.0,
        1.0,
    ];
    gl.map_1f(GL_MAP1_VERTEX_4, 0.0, 1.0, 4, 3, &arc);
    gl.enable(GL_MAP1_VERTEX_4);
    gl.color_3f(0.3, 1.0, 1.0);
    gl.map_grid_1d(24, 0.0, 1.0);
    gl.begin(GL_LINE_STRIP);
    for i in 0..=24 {
        gl.eval_point_1(i);
    }
    gl.end();
    gl.disable(GL_MAP1_VERTEX_4);

    // Points along a line, every other grid point of a sub-range.
    gl.map_1f(
        GL_MAP1_VERTEX_3,
        0.0,
        1.0,
        3,
        2,
        &[10.0, 100.0, 0.0, 60.0, 126.0, 0.0],
    );
    gl.point_size(3.0);
    gl.map_grid_1f(12, 0.0, 1.0);
    gl.color_3f(1.0, 0.5, 1.0);
    gl.eval_mesh_1(GL_POINT, 2, 12);
}

fn checker_texture(gl: &mut dyn Gl) {
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_2D, name[0]);
    let mut px = Vec::new();
    for y in 0..8 {
        for x in 0..8 {
            if (x + y) % 2 == 0 {
                px.extend_from_slice(&[255u8, 255, 255, 255]);
            } else {
                px.extend_from_slice(&[60, 60, 60, 255]);
            }
        }
    }
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        8,
        8,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&px),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
}

/// A wavy bicubic patch with a bilinear colour map and a biquadratic texture-coordinate map
/// (MODULATE over a checker), unlit.
fn eval_color_texture_patch(gl: &mut dyn Gl) {
    perspective(gl);
    gl.enable(GL_DEPTH_TEST);
    checker_texture(gl);
    gl.translatef(0.0, 0.0, -3.0);
    gl.rotatef(-50.0, 1.0, 0.0, 0.0);
    gl.rotatef(15.0, 0.0, 0.0, 1.0);
    let mut pts = Vec::new();
    for i in 0..4 {
        for j in 0..4 {
            let z = if (i + j) % 2 == 0 { 0.35 } else { -0.25 };
            pts.extend_from_slice(&[i as f32 * 0.6 - 0.9, j as f32 * 0.6 - 0.9, z]);
        }
    }
    gl.map_2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &pts);
    let colors = [
        1.0, 0.3, 0.3, 1.0, 0.3, 1.0, 0.3, 1.0, 0.3, 0.3, 1.0, 1.0, 1.0, 1.0, 0.3, 1.0f32,
    ];
    gl.map_2f(GL_MAP2_COLOR_4, 0.0, 1.0, 8, 2, 0.0, 1.0, 4, 2, &colors);
    let tc = [
        0.0, 0.0, 0.0, 1.0, 0.0, 3.0, 1.5, 0.0, 1.0, 1.5, 1.5, 3.0, 3.0, 0.0, 2.5, 1.0, 3.0, 3.0f32,
    ];
    gl.map_2f(GL_MAP2_TEXTURE_COORD_2, 0.0, 1.0, 6, 3, 0.0, 1.0, 2, 3, &tc);
    gl.enable(GL_MAP2_VERTEX_3);
    gl.enable(GL_MAP2_COLOR_4);
    gl.enable(GL_MAP2_TEXTURE_COORD_2);
    gl.map_grid_2d(32, 0.0, 1.0, 32, 0.0, 1.0);
    gl.eval_mesh_2(GL_FILL, 0, 32, 0, 32);
}

/// A rational biquadratic patch (`MAP2_VERTEX_4`: a piece of a cylinder) lit with normals from
/// a `MAP2_NORMAL` map, and `COLOR_MATERIAL` fed by a colour map; then the same shape with
/// `GL_AUTO_NORMAL` beside it.
fn eval_rational_patch_normal_map(gl: &mut dyn Gl) {
    perspective(gl);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_COLOR_MATERIAL);
    gl.enable(GL_NORMALIZE);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.5, 1.0, 2.0, 0.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 16.0);
    // Quarter cylinder of radius 0.7 around y: u around (rational quadratic), v along y.
    let w = std::f32::consts::FRAC_1_SQRT_2;
    let arc = [[0.7, 0.0, 1.0], [0.7, 0.7, w], [0.0, 0.7, 1.0]];
    let mut pts = Vec::new();
    for a in &arc {
        for y in [-0.6f32, 0.0, 0.6] {
            let wt = a[2];
            pts.extend_from_slice(&[a[0] * wt, y * wt, a[1] * wt, wt]);
        }
    }
    let normals = [
        1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0f32,
    ];
    let colors = [
        0.9, 0.4, 0.2, 1.0, 0.9, 0.9, 0.2, 1.0, 0.2, 0.5, 0.9, 1.0, 0.5, 0.9, 0.5, 1.0f32,
    ];
    gl.map_2f(GL_MAP2_VERTEX_4, 0.0, 1.0, 12, 3, 0.0, 1.0, 4, 3, &pts);
    gl.map_2f(GL_MAP2_NORMAL, 0.0, 1.0, 6, 2, 0.0, 1.0, 3, 2, &normals);
    gl.map_2f(GL_MAP2_COLOR_4, 0.0, 1.0, 8, 2, 0.0, 1.0, 4, 2, &colors);
    gl.enable(GL_MAP2_VERTEX_4);
    gl.enable(GL_MAP2_NORMAL);
    gl.enable(GL_MAP2_COLOR_4);
    gl.map_grid_2f(20, 0.0, 1.0, 8, 0.0, 1.0);
    gl.push_matrix();
    gl.translatef(-0.9, 0.0, -3.0);
    gl.rotatef(-60.0, 0.0, 1.0, 0.0);
    gl.eval_mesh_2(GL_FILL, 0, 20, 0, 8);
    gl.pop_matrix();
    // The normals from the partial derivatives instead (v x u order: faces outward).
    gl.disable(GL_MAP2_NORMAL);
    gl.enable(GL_AUTO_NORMAL);
    gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    gl.translatef(0.5, 0.0, -3.0);
    gl.rotatef(-60.0, 0.0, 1.0, 0.0);
    gl.eval_mesh_2(GL_FILL, 0, 20, 0, 8);
}

/// Every mesh mode of the same bicubic patch in four places: `glEvalMesh2` `GL_POINT`,
/// `GL_LINE`, `GL_FILL` (smooth, a sub-grid) and `GL_LINE` over a grid wider than the map's
/// domain (extrapolated).
///
/// Not here: flat shading and `glPolygonMode(GL_LINE)` on `GL_FILL` meshes. The specification
/// defines `GL_FILL` meshes as quad strips, which tilegl draws; Mesa draws triangle strips
/// instead (`vbo_exec_EvalMesh2`), so its outlines show the diagonals and its flat colours
/// change per triangle. `tests/evaluators.rs` checks those cases against the specification's
/// loop.
fn eval_grid_meshes(gl: &mut dyn Gl) {
    clear(gl);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 128.0, 0.0, 128.0, -100.0, 100.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    let mut pts = Vec::new();
    for i in 0..4 {
        for j in 0..4 {
            let x = 2.0 + 19.0 * i as f32 + if j == 2 { 5.0 } else { 0.0 };
            let y = 2.0 + 19.0 * j as f32 + if i == 1 { 6.0 } else { 0.0 };
            pts.extend_from_slice(&[x, y, (i * j) as f32]);
        }
    }
    gl.map_2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &pts);
    let colors = [
        1.0, 0.2, 0.2, 1.0, 0.2, 1.0, 0.2, 1.0, 0.2, 0.2, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0f32,
    ];
    gl.map_2f(GL_MAP2_COLOR_4, 0.0, 1.0, 8, 2, 0.0, 1.0, 4, 2, &colors);
    gl.enable(GL_MAP2_VERTEX_3);
    gl.enable(GL_MAP2_COLOR_4);
    gl.map_grid_2f(10, 0.0, 1.0, 8, 0.0, 1.0);
    gl.point_size(2.0);
    gl.eval_mesh_2(GL_POINT, 0, 10, 0, 8);
    gl.translatef(64.0, 0.0, 0.0);
    gl.eval_mesh_2(GL_LINE, 0, 10, 0, 8);
    gl.translatef(-64.0, 64.0, 0.0);
    gl.eval_mesh_2(GL_FILL, 2, 9, 1, 7);
    gl.translatef(64.0, 0.0, 0.0);
    // A grid over a wider domain than the map's: extrapolated.
    gl.map_grid_2f(6, -0.1, 1.1, 5, 0.0, 1.0);
    gl.eval_mesh_2(GL_LINE, 0, 6, 0, 5);
}

/// The remaining map targets: `MAP2_TEXTURE_COORD_1` into a 1D texture,
/// `MAP2_TEXTURE_COORD_3` into a 3D texture, `MAP2_TEXTURE_COORD_4` (projective) into a 2D
/// texture, `MAP1_NORMAL` and `MAP1_COLOR_4` (with `COLOR_MATERIAL`) on lit curves,
/// `MAP1_TEXTURE_COORD_2` on a curve, and `MAP1_INDEX`/`MAP2_INDEX` (no effect in RGBA mode).
fn eval_other_targets(gl: &mut dyn Gl) {
    clear(gl);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 128.0, 0.0, 128.0, -100.0, 100.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    let mut tex = [0u32; 3];
    gl.gen_textures(3, &mut tex);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    // 1D: eight colour bands.
    let bands: Vec<u8> = (0..8u8)
        .flat_map(|i| [i * 32, 255 - i * 32, (i % 2) * 255, 255])
        .collect();
    gl.bind_texture(GL_TEXTURE_1D, tex[0]);
    gl.tex_image_1d(
        GL_TEXTURE_1D,
        0,
        GL_RGBA as i32,
        8,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&bands),
    );
    gl.tex_parameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    // 3D: 4 x 4 x 2 cells.
    let cells: Vec<u8> = (0..32u8)
        .flat_map(|i| [(i % 4) * 80, ((i / 4) % 4) * 80, (i / 16) * 255, 255])
        .collect();
    gl.bind_texture(GL_TEXTURE_3D, tex[1]);
    gl.tex_image_3d(
        GL_TEXTURE_3D,
        0,
        GL_RGBA as i32,
        4,
        4,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&cells),
    );
    gl.tex_parameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    // 2D: a checker.
    let checker: Vec<u8> = (0..64)
        .flat_map(|i| {
            if (i % 8 + i / 8) % 2 == 0 {
                [250u8, 250, 250, 255]
            } else {
                [40, 90, 160, 255]
            }
        })
        .collect();
    gl.bind_texture(GL_TEXTURE_2D, tex[2]);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        8,
        8,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&checker),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);

    // A flat bilinear square of 56 x 56, placed three times.
    let square = [
        0.0, 0.0, 0.0, 0.0, 56.0, 0.0, 56.0, 0.0, 0.0, 56.0, 56.0, 0.0f32,
    ];
    gl.map_2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 6, 2, 0.0, 1.0, 3, 2, &square);
    gl.enable(GL_MAP2_VERTEX_3);
    gl.map_2f(GL_MAP2_INDEX, 0.0, 1.0, 1, 1, 0.0, 1.0, 1, 1, &[5.0]);
    gl.enable(GL_MAP2_INDEX);
    gl.map_grid_2f(14, 0.0, 1.0, 14, 0.0, 1.0);

    gl.push_matrix();
    gl.translatef(4.0, 68.0, 0.0);
    gl.enable(GL_TEXTURE_1D);
    // s quadratic in u alone (uorder 3, vorder 1): bands of varying width. The texture-
    // coordinate maps here have no twist (no uv term), so the picture does not depend on how
    // a quad of the mesh is split into triangles (Mesa: triangle strips; tilegl: quad strips).
    let s1 = [0.0, 1.6, 0.4f32];
    gl.map_2f(GL_MAP2_TEXTURE_COORD_1, 0.0, 1.0, 1, 3, 0.0, 1.0, 1, 1, &s1);
    gl.enable(GL_MAP2_TEXTURE_COORD_1);
    gl.eval_mesh_2(GL_FILL, 0, 14, 0, 14);
    gl.disable(GL_MAP2_TEXTURE_COORD_1);
    gl.disable(GL_TEXTURE_1D);
    gl.pop_matrix();

    gl.push_matrix();
    gl.translatef(68.0, 68.0, 0.0);
    gl.enable(GL_TEXTURE_3D);
    let s3 = [
        0.0, 0.0, 0.1, 0.0, 1.0, 0.9, 1.0, 0.0, 0.1, 1.0, 1.0, 0.9f32,
    ];
    gl.map_2f(GL_MAP2_TEXTURE_COORD_3, 0.0, 1.0, 6, 2, 0.0, 1.0, 3, 2, &s3);
    gl.enable(GL_MAP2_TEXTURE_COORD_3);
    gl.eval_mesh_2(GL_FILL, 0, 14, 0, 14);
    gl.disable(GL_MAP2_TEXTURE_COORD_3);
    gl.disable(GL_TEXTURE_3D);
    gl.pop_matrix();

    gl.push_matrix();
    gl.translatef(4.0, 4.0, 0.0);
    gl.enable(GL_TEXTURE_2D);
    // Projective: q grows along u, so the checker compresses towards u = 1.
    let s4 = [
        0.0, 0.0, 0.0, 1.0, 0.0, 4.0, 0.0, 1.0, 4.0, 0.0, 0.0, 2.0, 4.0, 4.0, 0.0, 2.0f32,
    ];
    gl.map_2f(GL_MAP2_TEXTURE_COORD_4, 0.0, 1.0, 8, 2, 0.0, 1.0, 4, 2, &s4);
    gl.enable(GL_MAP2_TEXTURE_COORD_4);
    // Also enabled, lower dimension: ignored.
    gl.map_2f(
        GL_MAP2_TEXTURE_COORD_2,
        0.0,
        1.0,
        2,
        1,
        0.0,
        1.0,
        2,
        1,
        &[0.5, 0.5],
    );
    gl.enable(GL_MAP2_TEXTURE_COORD_2);
    gl.eval_mesh_2(GL_FILL, 0, 14, 0, 14);
    gl.disable(GL_MAP2_TEXTURE_COORD_4);
    // Curves textured by MAP1_TEXTURE_COORD_2 along the square's top edge.
    gl.map_1f(
        GL_MAP1_VERTEX_3,
        0.0,
        1.0,
        3,
        3,
        &[0.0, 58.0, 0.0, 28.0, 66.0, 0.0, 56.0, 58.0, 0.0],
    );
    gl.map_1f(
        GL_MAP1_TEXTURE_COORD_2,
        0.0,
        1.0,
        2,
        2,
        &[0.0, 0.5, 1.0, 0.5],
    );
    gl.enable(GL_MAP1_VERTEX_3);
    gl.enable(GL_MAP1_TEXTURE_COORD_2);
    gl.map_grid_1f(16, 0.0, 1.0);
    gl.eval_mesh_1(GL_LINE, 0, 16);
    gl.disable(GL_MAP1_TEXTURE_COORD_2);
    gl.disable(GL_TEXTURE_2D);
    gl.pop_matrix();

    // Lit curves: normals from MAP1_NORMAL, diffuse colour from MAP1_COLOR_4 through
    // COLOR_MATERIAL, index map enabled (no effect).
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_COLOR_MATERIAL);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.0, 0.0, 1.0, 0.0]);
    gl.map_1f(
        GL_MAP1_NORMAL,
        0.0,
        1.0,
        3,
        3,
        &[-1.0, 0.0, 0.2, 0.0, 0.0, 1.0, 1.0, 0.0, 0.2],
    );
    gl.map_1f(
        GL_MAP1_COLOR_4,
        0.0,
        1.0,
        4,
        2,
        &[1.0, 1.0, 0.2, 1.0, 0.2, 1.0, 1.0, 1.0],
    );
    gl.map_1f(GL_MAP1_INDEX, 0.0, 1.0, 1, 1, &[3.0]);
    gl.enable(GL_MAP1_NORMAL);
    gl.enable(GL_MAP1_COLOR_4);
    gl.enable(GL_MAP1_INDEX);
    gl.enable(GL_NORMALIZE);
    for k in 0..5 {
        let y = 8.0 + 12.0 * k as f32;
        gl.map_1f(
            GL_MAP1_VERTEX_3,
            0.0,
            1.0,
            3,
            4,
            &[
                68.0,
                y,
                0.0,
                84.0,
                y + 20.0,
                0.0,
                108.0,
                y - 10.0,
                0.0,
                124.0,
                y + 4.0,
                0.0,
            ],
        );
        gl.eval_mesh_1(GL_LINE, 0, 16);
    }
}

//! Differential tests of the evaluators (scenes in `tilegl_conformance::scenes_eval`): maps,
//! meshes, curves and analytic normals against Mesa, under the differential tolerance.

use tilegl_conformance::differential;
use tilegl_conformance::scenes_eval::EVAL_SCENES;

differential!(
    eval_lit_vase_auto_normal,
    eval_curves_line_strips,
    eval_color_texture_patch,
    eval_rational_patch_normal_map,
    eval_grid_meshes,
);

#[test]
fn every_eval_scene_has_a_test() {
    let mut names: Vec<&str> = EVAL_SCENES.iter().map(|s| s.name).collect();
    let mut cases = CASES.to_vec();
    names.sort_unstable();
    cases.sort_unstable();
    assert_eq!(names, cases);
}

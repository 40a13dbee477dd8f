//! Differential tests of the evaluators (scenes in `tilegl_conformance::scenes_eval`): maps,
//! meshes, curves and analytic normals against Mesa, under the differential tolerance, and
//! the evaluator state and error scripts of `tilegl_conformance::state_cases::eval`.

use tilegl_conformance::scenes_eval::EVAL_SCENES;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn eval_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("EVAL_SCENES", EVAL_SCENES);
}

/// The state and error cases of `state_cases::eval` against Mesa (`TILEGL_CASE` narrows them).
#[test]
fn eval_state_cases_agree_with_mesa() {
    tilegl_conformance::state_cases::run_list(
        "state_cases::eval",
        tilegl_conformance::state_cases::eval::CASES,
    );
}

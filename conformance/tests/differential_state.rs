//! Differential tests of the attribute stack, occlusion queries, multisample state, selection
//! and feedback: the pictures of `tilegl_conformance::scenes_state`, and the scripts of
//! `tilegl_conformance::state_cases::attrib` whose answers (queries, errors, occlusion counts,
//! hit records, feedback values) must agree with Mesa's.

use tilegl_conformance::scenes_state::STATE_SCENES;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn state_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("STATE_SCENES", STATE_SCENES);
}

/// The state and error cases of `state_cases::attrib` against Mesa (`TILEGL_CASE` narrows them).
#[test]
fn attrib_state_cases_agree_with_mesa() {
    tilegl_conformance::state_cases::run_list(
        "state_cases::attrib",
        tilegl_conformance::state_cases::attrib::CASES,
    );
}

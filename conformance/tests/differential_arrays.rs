//! Differential tests of vertex arrays, buffer objects and display lists (scenes in
//! `tilegl_conformance::scenes_arrays`), plus the query-and-error scripts of
//! `tilegl_conformance::state_cases::arrays`, whose answers must agree with Mesa's.

use tilegl_conformance::scenes_arrays::ARRAY_SCENES;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn array_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("ARRAY_SCENES", ARRAY_SCENES);
}

/// The state and error cases of `state_cases::arrays` against Mesa (`TILEGL_CASE` narrows them).
#[test]
fn arrays_state_cases_agree_with_mesa() {
    tilegl_conformance::state_cases::run_list(
        "state_cases::arrays",
        tilegl_conformance::state_cases::arrays::CASES,
    );
}

/// ARB_pixel_buffer_object and ARB_map_buffer_range (the cases in
/// `tilegl_conformance::state_cases::pbo`) against Mesa (`TILEGL_CASE` narrows them).
#[test]
fn pbo_state_cases_agree_with_mesa() {
    tilegl_conformance::state_cases::run_list(
        "state_cases::pbo",
        tilegl_conformance::state_cases::pbo::CASES,
    );
}

//! Differential tests of the texture-unit cascade: GL_COMBINE on two units (every function x
//! source x operand), texgen on a lit sphere and a plane, and packed lighting cases (scenes in
//! `tilegl_conformance::scenes_cascade`).

use tilegl_conformance::scenes_cascade::CASCADE_SCENES;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn cascade_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("CASCADE_SCENES", CASCADE_SCENES);
}

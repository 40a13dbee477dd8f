//! Differential tests of the fidelity classes found replaying real programs (scenes in
//! `tilegl_conformance::scenes_fidelity`): antialiased wide lines flat and receding; point sizes and line widths of 1000; all six user clip planes and every subset of them; a 16384-wide float texture;
//! lit, textured, fogged tunnels receding into the distance; anisotropy 16 towards the horizon;
//! lit primitives drawn with the current values an array draw left; point sprites; smooth
//! line segments meeting end to end; the diagonal quads are split along.

use tilegl_conformance::scenes_fidelity::FIDELITY_SCENES;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn fidelity_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("FIDELITY_SCENES", FIDELITY_SCENES);
}

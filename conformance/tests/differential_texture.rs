//! Differential tests of texturing, texture coordinate generation and the texture environment
//! (scenes in `tilegl_conformance::scenes_texture`), under each scene's tolerance.

use tilegl_conformance::scenes_texture::TEXTURE_SCENES;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn texture_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("TEXTURE_SCENES", TEXTURE_SCENES);
}

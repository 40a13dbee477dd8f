//! Differential tests of the rasterization controls (scenes in
//! `tilegl_conformance::scenes_raster`): point size and parameters, wide, stippled and
//! antialiased lines, polygon modes, edge flags, polygon offset and stipple.

use tilegl_conformance::scenes_raster::RASTER_SCENES;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn raster_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("RASTER_SCENES", RASTER_SCENES);
}

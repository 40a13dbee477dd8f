//! Differential tests of the rasterization controls (scenes in
//! `tilegl_conformance::scenes_raster`): point size and parameters, wide, stippled and
//! antialiased lines, polygon modes, edge flags, polygon offset and stipple.

use tilegl_conformance::differential;
use tilegl_conformance::scenes_raster::RASTER_SCENES;

differential!(
    wide_points,
    point_attenuation,
    wide_lines,
    line_stipple,
    line_stipple_wide,
    polygon_mode_line,
    polygon_mode_point,
    edge_flags,
    polygon_offset_fill,
    polygon_offset_line,
    polygon_stipple,
    smooth_points,
    smooth_lines,
    smooth_polygons,
    additive_faint_layers,
    blend_equation_separate,
    flat_textured_fogged,
    accum_motion_blur,
    accum_ops,
    draw_pixels_color,
    draw_pixels_zoom_transfer,
    draw_pixels_depth_stencil,
    bitmap_text,
    copy_pixels,
    window_pos_and_invalid_raster,
);

#[test]
fn every_raster_scene_has_a_test() {
    tilegl_conformance::assert_every_scene_has_a_test(RASTER_SCENES, CASES);
}

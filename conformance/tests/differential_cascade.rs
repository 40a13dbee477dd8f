//! Differential tests of the texture-unit cascade: GL_COMBINE on two units (every function x
//! source x operand), texgen on a lit sphere and a plane, and packed lighting cases (scenes in
//! `tilegl_conformance::scenes_cascade`).

use tilegl_conformance::differential;
use tilegl_conformance::scenes_cascade::CASCADE_SCENES;

differential!(
    cascade_combine_replace,
    cascade_combine_modulate,
    cascade_combine_add,
    cascade_combine_add_signed,
    cascade_combine_interpolate,
    cascade_combine_subtract,
    cascade_combine_dot3_rgb,
    cascade_combine_dot3_rgba,
    cascade_texgen_sphere_lit,
    cascade_texgen_plane,
    cascade_lit_spots,
    cascade_lit_models,
    cascade_lit_color_material,
);

#[test]
fn every_cascade_scene_has_a_test() {
    tilegl_conformance::assert_every_scene_has_a_test(CASCADE_SCENES, CASES);
}

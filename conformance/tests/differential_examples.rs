//! Differential tests of the teaching examples' scenes (`tilegl_conformance::scenes_examples`,
//! run by `examples/*.rs`), under each scene's tolerance.

use tilegl_conformance::differential;
use tilegl_conformance::scenes_examples::EXAMPLE_SCENES;

differential!(
    ex_mipmap_filters,
    ex_mipmap_levels,
    ex_wrap_modes,
    ex_lightmap_multitexture,
    ex_lightmap_multipass,
    ex_gloss_map,
    ex_sphere_map,
    ex_cube_map,
    ex_cube_map_dynamic,
    ex_emboss_bump,
    ex_dot3_bump,
    ex_projective_texture,
    ex_shadow_map,
    ex_shadow_map_alpha_test,
    ex_contour,
    ex_volume_3d,
    ex_text,
    ex_cross_tree,
    ex_decal,
    ex_fog_terrain,
    ex_planar_reflection,
);

#[test]
fn every_example_scene_has_a_test() {
    let mut names: Vec<&str> = EXAMPLE_SCENES.iter().map(|s| s.name).collect();
    let mut cases = CASES.to_vec();
    names.sort_unstable();
    cases.sort_unstable();
    assert_eq!(names, cases);
}

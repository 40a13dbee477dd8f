//! Differential tests of texturing, texture coordinate generation and the texture environment
//! (scenes in `tilegl_conformance::scenes_texture`), under each scene's tolerance.

use tilegl_conformance::differential;
use tilegl_conformance::scenes_texture::TEXTURE_SCENES;

differential!(
    tex_nearest_replace,
    tex_linear_modulate_clamp,
    tex_floor_nearest,
    tex_floor_trilinear,
    tex_floor_mipmap_nearest,
    texgen_sphere_map,
    texgen_object_linear,
    texgen_eye_linear,
    multitexture_combine,
    texture_rectangle,
);

#[test]
fn every_texture_scene_has_a_test() {
    tilegl_conformance::assert_every_scene_has_a_test(TEXTURE_SCENES, CASES);
}

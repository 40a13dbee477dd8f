//! Differential tests of the texturing verification matrix (scenes in
//! `tilegl_conformance::scenes_texture_matrix`): every filter x wrap mode x base format on a
//! perspective plane, cube maps, 3D textures, depth comparison and S3TC, each under its
//! measured tolerance.

use tilegl_conformance::differential;
use tilegl_conformance::scenes_texture_matrix::TEXTURE_MATRIX_SCENES;

differential!(
    texmat_nearest_repeat,
    texmat_nearest_clamp,
    texmat_nearest_edge,
    texmat_nearest_border,
    texmat_nearest_mirror,
    texmat_linear_repeat,
    texmat_linear_clamp,
    texmat_linear_edge,
    texmat_linear_border,
    texmat_linear_mirror,
    texmat_nmn_repeat,
    texmat_nmn_clamp,
    texmat_nmn_edge,
    texmat_nmn_border,
    texmat_nmn_mirror,
    texmat_lmn_repeat,
    texmat_lmn_clamp,
    texmat_lmn_edge,
    texmat_lmn_border,
    texmat_lmn_mirror,
    texmat_nml_repeat,
    texmat_nml_clamp,
    texmat_nml_edge,
    texmat_nml_border,
    texmat_nml_mirror,
    texmat_lml_repeat,
    texmat_lml_clamp,
    texmat_lml_edge,
    texmat_lml_border,
    texmat_lml_mirror,
    cube_reflection_sphere,
    cube_reflection_mipmap,
    cube_faces_nearest,
    cube_faces_linear,
    tex3d_linear_slices,
    tex3d_mipmap_linear,
    tex3d_mipmap_nearest,
    tex3d_wrap_r,
    depth_cmp_nearest_luminance,
    depth_cmp_nearest_intensity,
    depth_cmp_nearest_alpha,
    depth_cmp_linear_luminance,
    depth_cmp_linear_intensity,
    depth_cmp_linear_alpha,
    dxt_compressed_nearest,
    dxt_compressed_linear,
    dxt_uncompressed_upload,
);

#[test]
fn every_texture_matrix_scene_has_a_test() {
    let mut names: Vec<&str> = TEXTURE_MATRIX_SCENES.iter().map(|s| s.name).collect();
    let mut cases = CASES.to_vec();
    names.sort_unstable();
    cases.sort_unstable();
    assert_eq!(names, cases);
}

//! Differential tests of the fidelity classes found replaying real programs (scenes in
//! `tilegl_conformance::scenes_fidelity`): antialiased wide lines flat and receding; point sizes and line widths of 1000; all six user clip planes and every subset of them; a 16384-wide float texture;
//! lit, textured, fogged tunnels receding into the distance; anisotropy 16 towards the horizon;
//! lit primitives drawn with the current values an array draw left; point sprites; smooth
//! line segments meeting end to end; the diagonal quads are split along.

use tilegl_conformance::differential;
use tilegl_conformance::scenes_fidelity::FIDELITY_SCENES;

differential!(
    smooth_lines_width_1,
    smooth_lines_width_2_5,
    smooth_lines_width_4,
    smooth_lines_width_7,
    smooth_lines_receding_width_1,
    smooth_lines_receding_width_2_5,
    smooth_lines_receding_width_4,
    smooth_lines_receding_width_7,
    points_and_lines_of_1000,
    smooth_lines_of_1000,
    six_clip_planes,
    clip_plane_subsets,
    float_texture_16384_wide,
    tunnel_exp_fog,
    tube_sphere_map_linear_fog,
    aniso_horizon,
    lit_after_arrays,
    point_sprites,
    smooth_line_joints,
    quad_splits,
);

#[test]
fn every_fidelity_scene_has_a_test() {
    tilegl_conformance::assert_every_scene_has_a_test(FIDELITY_SCENES, CASES);
}

//! Differential tests of the gallery's technique scenes (`tilegl_conformance::scenes_techniques`)
//! under each scene's tolerance, and checks of their stage views.

use tilegl_conformance::differential;
use tilegl_conformance::scenes_techniques::{TECHNIQUE_SCENES, TECHNIQUE_TEXTS};

differential!(
    ex_texenv_modes,
    ex_projector_mappings,
    ex_prefilter_mip_rip_sat,
    ex_env_latlong_paraboloid,
    ex_texture_matrix_animation,
    ex_image_warp,
    ex_detail_texture,
    ex_billboards_impostors,
    ex_antialiased_points_lines,
    ex_airbrush,
    ex_csg_stencil,
    ex_phong_highlight_texture,
    ex_reflection_clip_plane,
    ex_particles,
    ex_env_bump,
);

#[test]
fn every_technique_scene_has_a_test_and_a_text() {
    tilegl_conformance::assert_every_scene_has_a_test(TECHNIQUE_SCENES, CASES);
    let mut texts: Vec<&str> = TECHNIQUE_TEXTS.iter().map(|t| t.0).collect();
    texts.sort_unstable();
    let mut cases = CASES.to_vec();
    cases.sort_unstable();
    assert_eq!(texts, cases);
    for (name, title, teaches, state) in TECHNIQUE_TEXTS {
        assert!(
            !title.is_empty() && teaches.len() > 80 && state.contains("GL_"),
            "{name}"
        );
    }
}

/// Recording the stages, as the gallery does, must not change the pictures (the `snap_*`
/// calls only read back).
#[test]
fn recording_stages_changes_nothing() {
    use tilegl_conformance::{compare, example_support};
    for scene in TECHNIQUE_SCENES {
        let plain = compare::render_tilegl(scene);
        let (recorded, _) = example_support::record(|| compare::render_tilegl(scene));
        assert_eq!(plain.image, recorded.image, "{}", scene.name);
        assert_eq!(plain.error, recorded.error, "{}", scene.name);
    }
}

//! Differential tests of the gallery's technique scenes (`tilegl_conformance::scenes_techniques`)
//! under each scene's tolerance, and checks of their stage views.

use tilegl_conformance::scenes_techniques::{TECHNIQUE_SCENES, TECHNIQUE_TEXTS};

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn technique_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("TECHNIQUE_SCENES", TECHNIQUE_SCENES);
}

#[test]
fn every_technique_scene_has_a_text() {
    let mut texts: Vec<&str> = TECHNIQUE_TEXTS.iter().map(|t| t.0).collect();
    texts.sort_unstable();
    let mut scenes: Vec<&str> = TECHNIQUE_SCENES.iter().map(|s| s.name).collect();
    scenes.sort_unstable();
    assert_eq!(texts, scenes);
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

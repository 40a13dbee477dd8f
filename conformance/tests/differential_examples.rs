//! Differential tests of the teaching examples' scenes (`tilegl_conformance::scenes_examples`,
//! run by `examples/*.rs`), under each scene's tolerance.

use tilegl_conformance::differential;
use tilegl_conformance::scenes_examples::EXAMPLE_SCENES;

differential!(
    ex_mipmap_filters,
    ex_mipmap_levels,
    ex_wrap_modes,
    ex_dxt_compression,
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
    ex_hsv_lookup,
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

/// Recording the stages, as the examples do, must not change the pictures: the `snap_*` calls
/// only read back (`glReadPixels`, `glGetTexImage`, `glGetTexLevelParameteriv`). Checked on
/// tilegl, and on Mesa where it is installed.
#[test]
fn recording_stages_changes_nothing() {
    use tilegl_conformance::{compare, example_support, mesa};
    let mesa_ok = mesa::mesa_available().is_ok();
    for scene in EXAMPLE_SCENES {
        let plain = compare::render_tilegl(scene);
        let (recorded, stages) = example_support::record(|| compare::render_tilegl(scene));
        assert_eq!(
            plain.image, recorded.image,
            "{}: picture changed",
            scene.name
        );
        assert_eq!(plain.error, recorded.error, "{}", scene.name);
        for s in &stages {
            let i = &s.image;
            assert_eq!(
                i.pixels.len(),
                (i.width * i.height * 4) as usize,
                "{}",
                s.name
            );
        }
        if mesa_ok {
            let (plain, _) = compare::render_mesa(scene).unwrap();
            let (recorded, mesa_stages) =
                example_support::record(|| compare::render_mesa(scene).unwrap());
            assert_eq!(
                plain.image, recorded.0.image,
                "{}: Mesa picture",
                scene.name
            );
            let names = |v: &[example_support::Stage]| -> Vec<String> {
                v.iter().map(|s| s.name.clone()).collect()
            };
            assert_eq!(names(&stages), names(&mesa_stages), "{}", scene.name);
        }
    }
}

#[test]
fn multipass_scenes_record_their_stages() {
    use tilegl_conformance::{compare, example_support, scenes};
    let stages = |name: &str| -> Vec<String> {
        let scene = scenes::find(name).unwrap();
        let (_, s) = example_support::record(|| compare::render_tilegl(scene));
        s.into_iter().map(|s| s.name).collect()
    };
    assert_eq!(
        stages("ex_emboss_bump"),
        ["height_map", "pass1_height", "pass2_embossed"]
    );
    assert_eq!(stages("ex_shadow_map"), ["light_view_depth", "shadow_map"]);
    assert_eq!(
        stages("ex_planar_reflection"),
        ["stencil_mirror", "reflection", "floor_blended"]
    );
    // Outside `record` nothing is kept.
    let scene = scenes::find("ex_emboss_bump").unwrap();
    let _ = compare::render_tilegl(scene);
    let (_, none) = example_support::record(|| ());
    assert!(none.is_empty());
}

//! Differential tests of the extreme cases (scenes in `tilegl_conformance::scenes_extreme`):
//! stiff and extreme numerics against Mesa; cases where Mesa is known to be less exact are
//! listed in `tilegl_conformance::known_failures::MESA_LESS_EXACT`.

use tilegl_conformance::scenes_extreme::EXTREME_SCENES;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn extreme_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("EXTREME_SCENES", EXTREME_SCENES);
}

/// Every case listed as one where Mesa is less exact is an extreme-case scene.
#[test]
fn mesa_less_exact_cases_exist() {
    for (name, why) in tilegl_conformance::known_failures::MESA_LESS_EXACT {
        assert!(
            EXTREME_SCENES.iter().any(|s| s.name == *name),
            "MESA_LESS_EXACT lists unknown case {name}"
        );
        assert!(
            why.contains("tests/"),
            "{name}: say where the spec value is checked"
        );
    }
}

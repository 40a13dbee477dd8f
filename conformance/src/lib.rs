//! The tilegl conformance crate: the Mesa oracle ([`mesa`]), scene comparison ([`compare`]),
//! the differential tolerance ([`tolerance`]), the shared differential scenes ([`scenes`]), the
//! known-failures list ([`known_failures`]) and the triangle benchmark ([`bench`]).

pub mod bench;
pub mod bench_scenes;
pub mod c_route;
pub mod compare;
pub mod example_support;
pub mod gallery;
pub mod known_failures;
pub mod machine;
pub mod mesa;
pub mod prng;
pub mod quality;
pub mod report;
pub mod scaling;
pub mod scenes;
pub mod scenes_arrays;
pub mod scenes_cascade;
pub mod scenes_eval;
pub mod scenes_examples;
pub mod scenes_fidelity;
pub mod scenes_raster;
pub mod scenes_state;
pub mod scenes_techniques;
pub mod scenes_texture;
pub mod scenes_texture_matrix;
pub mod state_cases;
pub mod tolerance;

pub use compare::{Diff, Image, Scene};
pub use mesa::{MesaContext, Oracle, OracleError, OracleInfo};

/// Runs one differential scene: the same calls on tilegl and on Mesa, compared under the
/// scene's tolerance, with the known-failure rule applied; and on tilegl through its C ABI,
/// which must give the Rust route's picture and error exactly. Serves the child-process request
/// when this process was started as the other Gallium driver's helper.
pub fn run_differential_case(name: &str) {
    if compare::serve_child_request(&scenes::SCENES) {
        return;
    }
    if !mesa::require_mesa(name) {
        return;
    }
    let scene = scenes::find(name).unwrap_or_else(|| panic!("no scene {name}"));
    let c = compare::compare_scene(scene, scene.tolerance)
        .unwrap_or_else(|e| panic!("{name}: oracle error: {e}"));
    // The same calls through the C ABI: identical picture and error, whatever Mesa drew.
    compare::assert_c_abi_matches(scene, &c.tilegl);
    if !c.passed() {
        if let Some(dir) = std::env::var_os("TILEGL_CONFORMANCE_DUMP") {
            let _ = c.dump(std::path::Path::new(&dir));
        }
    }
    known_failures::check_outcome(name, c.passed(), &c.summary());
}

/// Asserts that the declared test cases are exactly the scenes of a list (each scene has a
/// test, each test a scene).
pub fn assert_every_scene_has_a_test(scenes: &[compare::Scene], cases: &[&str]) {
    let mut names: Vec<&str> = scenes.iter().map(|s| s.name).collect();
    let mut cases = cases.to_vec();
    names.sort_unstable();
    cases.sort_unstable();
    assert_eq!(names, cases);
}

/// Declares one `#[test]` per named scene (running [`run_differential_case`]) and a `CASES`
/// list of the names.
#[macro_export]
macro_rules! differential {
    ($($name:ident),* $(,)?) => {
        $(
            #[test]
            fn $name() {
                $crate::run_differential_case(stringify!($name));
            }
        )*
        const CASES: &[&str] = &[$(stringify!($name)),*];
    };
}

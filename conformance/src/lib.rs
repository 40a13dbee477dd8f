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
pub mod piglit;
pub mod prng;
pub mod quality;
pub mod report;
pub mod scaling;
pub mod scenes;
pub mod scenes_arrays;
pub mod scenes_cascade;
pub mod scenes_eval;
pub mod scenes_examples;
pub mod scenes_extremes;
pub mod scenes_fidelity;
pub mod scenes_raster;
pub mod scenes_state;
pub mod scenes_techniques;
pub mod scenes_texture;
pub mod scenes_texture_matrix;
pub mod state_cases;
pub mod tolerance;

pub use compare::{Diff, Image, Scene};

/// A tilegl context (Rust API) that reads the client arrays and writes the buffers the scenes
/// and state cases name by address, as a C caller's context does.
pub fn client_context(config: tilegl::ContextConfig) -> tilegl::Context {
    let mut gl = tilegl::Context::with_config(config);
    // SAFETY: every `ClientPtr` the scenes, state cases, examples and bench workloads pass
    // names a live slice, static or local they keep for as long as the calls that read or
    // write it (or is an offset into a bound buffer object), the GL client-memory contract.
    unsafe { tilegl::capi::client_memory::attach(&mut gl) };
    gl
}

pub use mesa::{MesaContext, Oracle, OracleError, OracleInfo};

/// The environment variable that narrows a list test to the cases whose names contain its
/// value (`TILEGL_CASE=fog cargo test -p tilegl-conformance --test differential`).
pub const CASE_FILTER_ENV: &str = "TILEGL_CASE";

/// One differential scene: the same calls on tilegl and on Mesa, compared under the scene's
/// tolerance, with the known-failure rule applied; and on tilegl through its C ABI, which must
/// give the Rust route's picture and error exactly. `Ok` with the figures, `Err` with why it
/// failed (a panic inside counts as a failure of this scene only).
pub fn differential_outcome(scene: &Scene) -> Result<String, String> {
    let name = scene.name;
    let run = || {
        let c = compare::compare_scene(scene, scene.tolerance)
            .map_err(|e| format!("{name}: oracle error: {e}"))?;
        // The same calls through the C ABI: identical picture and error, whatever Mesa drew.
        compare::assert_c_abi_matches(scene, &c.tilegl);
        if !c.passed() {
            if let Some(dir) = std::env::var_os("TILEGL_CONFORMANCE_DUMP") {
                let _ = c.dump(std::path::Path::new(&dir));
            }
        }
        known_failures::outcome(name, c.passed(), &c.summary())
    };
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(run))
        .unwrap_or_else(|p| Err(format!("{name} panicked: {}", panic_text(&p))))
}

fn panic_text(p: &Box<dyn std::any::Any + Send>) -> String {
    p.downcast_ref::<String>()
        .cloned()
        .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
        .unwrap_or_else(|| "(no message)".into())
}

/// Runs every case of a list (those whose names contain `$TILEGL_CASE` when it is set) on a
/// few threads, prints one line per case as it finishes ("ok NAME figures" or "FAIL NAME
/// why"), and panics at the end listing every failing case with its message. `run` must not
/// panic (catch inside, as [`differential_outcome`] does).
pub fn run_case_list<T: Sync>(
    what: &str,
    cases: &[T],
    name: fn(&T) -> &str,
    run: fn(&T) -> Result<String, String>,
) {
    let filter = std::env::var(CASE_FILTER_ENV).unwrap_or_default();
    let chosen: Vec<&T> = cases
        .iter()
        .filter(|c| name(c).contains(filter.as_str()))
        .collect();
    assert!(
        !chosen.is_empty(),
        "{what}: no case matches {CASE_FILTER_ENV}={filter:?}"
    );
    let threads = std::env::var("RUST_TEST_THREADS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(2, |n| n.get()))
        .clamp(1, chosen.len());
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(case) = chosen.get(i) else { break };
                let r = run(case);
                match &r {
                    Ok(figures) => println!("ok   {}: {figures}", name(case)),
                    Err(why) => println!("FAIL {}: {why}", name(case)),
                }
                results.lock().unwrap().push((i, r));
            });
        }
    });
    let mut results = results.into_inner().unwrap();
    results.sort_by_key(|(i, _)| *i);
    let failures: Vec<String> = results
        .iter()
        .filter_map(|(i, r)| {
            r.as_ref()
                .err()
                .map(|e| format!("- {}: {e}", name(chosen[*i])))
        })
        .collect();
    println!("{what}: {} cases, {} failed", chosen.len(), failures.len());
    assert!(
        failures.is_empty(),
        "{what}: {} of {} cases failed:\n{}",
        failures.len(),
        chosen.len(),
        failures.join("\n")
    );
}

/// The differential test of a scene list: serves the child-process request when this process
/// was started as the other Gallium driver's helper, requires Mesa (a skip outside CI), then
/// runs [`differential_outcome`] for every scene through [`run_case_list`].
pub fn run_differential_list(what: &str, scenes: &[Scene]) {
    if compare::serve_child_request(&scenes::SCENES) || !mesa::require_mesa(what) {
        return;
    }
    run_case_list(what, scenes, |s| s.name, differential_outcome);
}

//! Scripts from piglit's GL 1.x tests that tilegl failed (the cases in
//! `tilegl_conformance::state_cases::piglit`): every answer on Mesa and on tilegl (Rust API and
//! C ABI) compared.

/// Every case of the list against Mesa, one line per case, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the cases whose names contain NAME).
#[test]
fn piglit_state_cases_agree_with_mesa() {
    tilegl_conformance::state_cases::run_list(
        "state_cases::piglit",
        tilegl_conformance::state_cases::piglit::CASES,
    );
}

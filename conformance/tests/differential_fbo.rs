//! EXT_framebuffer_object, EXT_framebuffer_blit and ARB_framebuffer_object (the cases in
//! `tilegl_conformance::state_cases::{fbo, fbo_blit, arb_fbo}`): every answer on Mesa and on
//! tilegl (Rust API and C ABI) compared.

/// Every case of the list against Mesa, one line per case, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the cases whose names contain NAME).
#[test]
fn fbo_state_cases_agree_with_mesa() {
    tilegl_conformance::state_cases::run_list(
        "state_cases::fbo",
        tilegl_conformance::state_cases::fbo::CASES,
    );
}

/// EXT_framebuffer_blit (the cases in `tilegl_conformance::state_cases::fbo_blit`).
#[test]
fn fbo_blit_state_cases_agree_with_mesa() {
    tilegl_conformance::state_cases::run_list(
        "state_cases::fbo_blit",
        tilegl_conformance::state_cases::fbo_blit::CASES,
    );
}

/// ARB_framebuffer_object (the cases in `tilegl_conformance::state_cases::arb_fbo`).
#[test]
fn arb_fbo_state_cases_agree_with_mesa() {
    tilegl_conformance::state_cases::run_list(
        "state_cases::arb_fbo",
        tilegl_conformance::state_cases::arb_fbo::CASES,
    );
}

/// ARB_texture_storage (the cases in `tilegl_conformance::state_cases::tex_storage`; with
/// the framebuffer objects as piglit's tex-miplevel-selection needs both).
#[test]
fn tex_storage_state_cases_agree_with_mesa() {
    tilegl_conformance::state_cases::run_list(
        "state_cases::tex_storage",
        tilegl_conformance::state_cases::tex_storage::CASES,
    );
}

/// ARB_sampler_objects (the cases in `tilegl_conformance::state_cases::samplers`; piglit's
/// tex-miplevel-selection sets its sampling state through sampler objects).
#[test]
fn sampler_objects_state_cases_agree_with_mesa() {
    tilegl_conformance::state_cases::run_list(
        "state_cases::samplers",
        tilegl_conformance::state_cases::samplers::CASES,
    );
}

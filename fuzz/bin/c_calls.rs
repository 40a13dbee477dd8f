//! libFuzzer entry of the `c_calls` target (see `fuzz/src/lib.rs`); built by `fuzz/run`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| tilegl_fuzz::c_calls(data));

//! libFuzzer entry of the `replay` target (see `fuzz/src/lib.rs`); built by `fuzz/run`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| tilegl_fuzz::replay(data));

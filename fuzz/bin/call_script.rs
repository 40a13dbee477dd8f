//! libFuzzer entry of the `call_script` target (see `fuzz/src/lib.rs`); built by `fuzz/run`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| tilegl_fuzz::call_script(data));

//! libFuzzer entry of the `trace_reader` target (see `fuzz/src/lib.rs`); built by `fuzz/run`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| tilegl_fuzz::trace_reader(data));

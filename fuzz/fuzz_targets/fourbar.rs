//! cargo-fuzz target `fourbar`: see `burmester_fuzz::fourbar`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| burmester_fuzz::fourbar(data));

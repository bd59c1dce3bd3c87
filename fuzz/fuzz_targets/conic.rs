//! cargo-fuzz target `conic`: see `burmester_fuzz::conic`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| burmester_fuzz::conic(data));

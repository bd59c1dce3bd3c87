//! cargo-fuzz target `atlas`: see `burmester_fuzz::atlas`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| burmester_fuzz::atlas(data));

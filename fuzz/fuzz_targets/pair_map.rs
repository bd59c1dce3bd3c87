//! cargo-fuzz target `pair_map`: see `burmester_fuzz::pair_map`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| burmester_fuzz::pair_map(data));

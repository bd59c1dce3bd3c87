//! cargo-fuzz target `solution_map`: see `burmester_fuzz::solution_map`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| burmester_fuzz::solution_map(data));

//! cargo-fuzz target `burmester_points`: see `burmester_fuzz::burmester_points`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| burmester_fuzz::burmester_points(data));

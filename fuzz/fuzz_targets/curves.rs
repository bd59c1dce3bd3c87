//! cargo-fuzz target `curves`: see `burmester_fuzz::curves`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| burmester_fuzz::curves(data));

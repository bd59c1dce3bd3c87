//! cargo-fuzz target `conic_polylines`: see `burmester_fuzz::conic_polylines`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| burmester_fuzz::conic_polylines(data));

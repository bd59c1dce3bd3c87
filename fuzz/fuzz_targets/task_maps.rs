//! cargo-fuzz target `task_maps`: see `burmester_fuzz::task_maps`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| burmester_fuzz::task_maps(data));

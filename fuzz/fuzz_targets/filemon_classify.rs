//! cargo-fuzz target `filemon_classify`: see `burmester_fuzz::filemon_classify`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| burmester_fuzz::filemon_classify(data));

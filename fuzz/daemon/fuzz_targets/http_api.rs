#![no_main]
//! libFuzzer target `http_api`: the harness of the same name in `skyluxd::fuzzing`.

libfuzzer_sys::fuzz_target!(|data: &[u8]| skyluxd::fuzzing::http_api(data));

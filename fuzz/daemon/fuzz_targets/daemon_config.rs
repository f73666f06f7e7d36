#![no_main]
//! libFuzzer target `daemon_config`: the harness of the same name in `skyluxd::fuzzing`.

libfuzzer_sys::fuzz_target!(|data: &[u8]| skyluxd::fuzzing::daemon_config(data));

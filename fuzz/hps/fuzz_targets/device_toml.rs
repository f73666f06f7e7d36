#![no_main]
//! libFuzzer target `device_toml`: the harness of the same name in `skylux_hps::fuzzing`.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    skylux_hps::fuzzing::harness("device_toml").expect("a harness of that name")(data)
});

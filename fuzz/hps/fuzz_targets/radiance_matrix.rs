#![no_main]
//! libFuzzer target `radiance_matrix`: the harness of the same name in `skylux_hps::fuzzing`.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    skylux_hps::fuzzing::harness("radiance_matrix").expect("a harness of that name")(data)
});

#![no_main]
//! libFuzzer target `known_source`: the harness of the same name in `skylux_hps::fuzzing`.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    skylux_hps::fuzzing::harness("known_source").expect("a harness of that name")(data)
});

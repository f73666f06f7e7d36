#![no_main]
//! libFuzzer target `cal`: the harness of the same name in `skylux_hps::fuzzing`.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    skylux_hps::fuzzing::harness("cal").expect("a harness of that name")(data)
});

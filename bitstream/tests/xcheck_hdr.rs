//! The HDR selection's Verilog (exported from a fresh instance) against its rust-hdl
//! simulation: a recorded trace of random sets (thresholds, exposure indices, flags, idle
//! cycles with garbage on the inputs), replayed in Icarus; and a tampered Verilog caught.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rust_hdl::prelude::*;
use skylux_bitstream::xcheck::{self, Tool};
use skylux_regmap::words::grouped;
use skylux_rtl::hdr::bench::HdrBench;
use skylux_rtl::hdr::golden::{FilledMask, HdrConfig, SetFrame};
use skylux_rtl::hdr::HdrSelect;

#[test]
fn hdr_select_verilog_equals_rust_hdl() {
    if !xcheck::require(&[Tool::Iverilog, Tool::Vvp]) {
        return;
    }
    let mut rng = StdRng::seed_from_u64(22);
    let mut bench = HdrBench::new(7);
    let mut mask = FilledMask::default();
    bench.driver.record();
    bench.idle(3);
    let mut masked = 0;
    // The Verilog's mask is X at power-up (the simulation's is zero): a first frame longer
    // than the sets writes every position they read, including the one after their last
    // word, which is read on the edge that takes it.
    let groups = 40;
    let config = HdrConfig::default();
    bench.configure(&config);
    let prime = vec![grouped::pack(1, false, false); groups + 8];
    let f = SetFrame {
        exposure_index: 0,
        first_of_set: true,
        words: &prime,
    };
    assert_eq!(bench.frame(&f, || 0), mask.frame(&config, &f));
    for set in 0..4 {
        let config = HdrConfig {
            min_q11: rng.gen_range(0..1 << 13),
            max_q11: rng.gen_range(1 << 23..1 << 26),
        };
        bench.configure(&config);
        for k in 0..5u8 {
            let words: Vec<u32> = (0..groups)
                .map(|_| {
                    let l = rng.gen_range(0..grouped::LUMA_MAX_Q14 as u32);
                    grouped::pack(l, rng.gen_bool(0.1), rng.gen_bool(0.4))
                })
                .collect();
            let f = SetFrame {
                exposure_index: (set + k) & 7,
                first_of_set: k == 0,
                words: &words,
            };
            bench.idle(1);
            let got = bench.frame(&f, || usize::from(rng.gen_bool(0.3)) * 2);
            // The recorded run is itself right, so the replay compares against a meaningful
            // trace.
            assert_eq!(
                got,
                mask.frame(&config, &f),
                "rust-hdl vs golden, set {set}"
            );
            masked += got.iter().filter(|w| !w.1).count();
        }
    }
    assert!(masked > 100, "too few masked writes: {masked}");

    let trace = bench.driver.take_trace();
    let mut fresh = HdrSelect::default();
    fresh.connect_all();
    let verilog = generate_verilog(&fresh);
    let report = xcheck::replay("hdr_select", &verilog, &trace).unwrap();
    println!("{}", report.summary());
    assert!(
        report.steps > 1000,
        "trace too short: {} steps",
        report.steps
    );
    assert!(report.is_clean(), "{}", report.summary());

    // The exposure index shifted to bit 26 instead of 27 must be caught on the map word.
    let tampered = verilog.replacen("<< 32'h1b", "<< 32'h1a", 1);
    assert!(
        tampered != verilog,
        "the shift is not where the test expects it:\n{verilog}"
    );
    let report = xcheck::replay("hdr_select_tampered", &tampered, &trace).unwrap();
    assert!(
        report.mismatches.iter().any(|m| m.port == "map_word"),
        "tampering not caught"
    );
}

//! The sun accumulators' Verilog (exported from a fresh instance) against their rust-hdl
//! simulation: a recorded trace of random frames (armed and not, windows, thresholds, flags,
//! idle cycles with garbage on the inputs), replayed in Icarus; and a tampered Verilog caught.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rust_hdl::prelude::*;
use skylux_bitstream::xcheck::{self, Tool};
use skylux_regmap::words::grouped;
use skylux_rtl::sun::bench::SunBench;
use skylux_rtl::sun::golden::{accumulate, SunConfig};
use skylux_rtl::sun::{SunAccumulators, SUN_LATENCY};

#[test]
fn sun_accumulators_verilog_equals_rust_hdl() {
    if !xcheck::require(&[Tool::Iverilog, Tool::Vvp]) {
        return;
    }
    let mut rng = StdRng::seed_from_u64(22);
    let mut bench = SunBench::new(7);
    bench.driver.record();
    bench.idle(3);
    let mut counted = 0;
    for frame in 0..8 {
        let per_line = rng.gen_range(4..12u16);
        let threshold_q14 = rng.gen_range(1 << 20..1 << 28);
        let config = SunConfig {
            groups_per_line: per_line,
            threshold_q14,
            x_min: rng.gen_range(0..3),
            x_max: rng.gen_range(5..12),
            y_min: rng.gen_range(0..2),
            y_max: rng.gen_range(3..8),
        };
        let words: Vec<u32> = (0..usize::from(per_line) * 6)
            .map(|_| {
                let l = if rng.gen_bool(0.5) {
                    rng.gen_range(threshold_q14..=grouped::LUMA_MAX_Q14 as u32)
                } else {
                    rng.gen_range(0..threshold_q14)
                };
                grouped::pack(l, rng.gen_bool(0.1), rng.gen_bool(0.2))
            })
            .collect();
        let armed = frame % 4 != 3;
        bench.configure(&config);
        bench.idle(1);
        bench.frame(&words, armed, || usize::from(rng.gen_bool(0.3)) * 2);
        bench.idle(SUN_LATENCY);
        if armed {
            // The recorded run is itself right, so the replay compares against a meaningful
            // trace.
            let expected = accumulate(&config, &words);
            assert_eq!(bench.sums(), expected, "rust-hdl vs golden, frame {frame}");
            counted += expected.count;
        }
    }
    assert!(counted > 50, "too few groups counted: {counted}");

    let trace = bench.driver.take_trace();
    let mut fresh = SunAccumulators::default();
    fresh.connect_all();
    let verilog = generate_verilog(&fresh);
    let report = xcheck::replay("sun_accumulators", &verilog, &trace).unwrap();
    println!("{}", report.summary());
    assert!(
        report.steps > 1000,
        "trace too short: {} steps",
        report.steps
    );
    assert!(report.is_clean(), "{}", report.summary());

    // The low product's shift changed from 15 to 14 bits must be caught on the x sums.
    let tampered = verilog.replacen("<< 32'hf)", "<< 32'he)", 1);
    assert!(
        tampered != verilog,
        "the shift is not where the test expects it:\n{verilog}"
    );
    let report = xcheck::replay("sun_accumulators_tampered", &tampered, &trace).unwrap();
    assert!(
        report.mismatches.iter().any(|m| m.port == "sum_xl"),
        "tampering not caught"
    );
}

//! The Bayer grouping block's Verilog (exported from a fresh instance) against its rust-hdl
//! simulation: a recorded trace of small random frames in both modes and all four phases,
//! with idle cycles and garbage on the inputs between pixels, replayed in Icarus.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rust_hdl::prelude::*;
use skylux_bitstream::xcheck::{self, Tool};
use skylux_rtl::bayer::golden::{expected_words, BayerConfig, Frame, Phase};
use skylux_rtl::bayer::{BayerGrouper, GROUPED_LATENCY};
use skylux_rtl::drive::Driver;

fn clock(d: &mut BayerGrouper) -> &mut Signal<In, Clock> {
    &mut d.clock
}

fn configure(d: &mut BayerGrouper, c: &BayerConfig) {
    d.phase.next = (c.phase as u64).into();
    d.black.next = u64::from(c.black).into();
    d.valid_min.next = u64::from(c.valid_min).into();
    d.valid_max.next = u64::from(c.valid_max).into();
    d.weight_r.next = u64::from(c.weight_r).into();
    d.weight_g.next = u64::from(c.weight_g).into();
    d.weight_b.next = u64::from(c.weight_b).into();
    d.raw.next = c.raw;
}

/// One cycle; returns the word emitted after it, if any.
fn cycle(driver: &mut Driver<BayerGrouper>) -> Option<u32> {
    driver.cycle(clock).unwrap();
    driver
        .dut
        .word_valid
        .val()
        .then(|| driver.dut.word.val().to_u64() as u32)
}

fn idle(driver: &mut Driver<BayerGrouper>, rng: &mut StdRng, n: usize, words: &mut Vec<u32>) {
    for _ in 0..n {
        let d = &mut driver.dut;
        d.pixel_valid.next = false;
        d.pixel.next = rng.gen_range(0..4096u64).into();
        d.line_start.next = rng.gen_bool(0.5);
        d.frame_start.next = rng.gen_bool(0.5);
        words.extend(cycle(driver));
    }
}

#[test]
fn bayer_grouper_verilog_equals_rust_hdl() {
    if !xcheck::require(&[Tool::Iverilog, Tool::Vvp]) {
        return;
    }
    let mut rng = StdRng::seed_from_u64(2024);
    let mut driver = Driver::new(BayerGrouper::default());
    driver.record();
    let mut words = vec![];
    let mut expected = vec![];
    idle(&mut driver, &mut rng, 3, &mut words);
    // Every phase in grouped mode, then raw mode.
    for (i, raw) in [false, false, false, false, true].into_iter().enumerate() {
        let (w, h) = (24, 8);
        let frame = Frame {
            width: w,
            height: h,
            samples: (0..w * h)
                .map(|_| match rng.gen_range(0..8) {
                    0 => 0,
                    1 => 4095,
                    _ => rng.gen_range(0..4096),
                })
                .collect(),
        };
        let config = BayerConfig {
            phase: Phase::ALL[i % 4],
            black: rng.gen_range(0..400),
            valid_min: rng.gen_range(0..600),
            valid_max: rng.gen_range(3500..4096),
            weight_r: rng.gen(),
            weight_g: rng.gen(),
            weight_b: rng.gen(),
            raw,
        };
        configure(&mut driver.dut, &config);
        idle(&mut driver, &mut rng, 2, &mut words);
        for y in 0..h {
            for x in 0..w {
                let gap = if rng.gen_bool(0.3) {
                    rng.gen_range(1..3)
                } else {
                    0
                };
                idle(&mut driver, &mut rng, gap, &mut words);
                let d = &mut driver.dut;
                d.pixel_valid.next = true;
                d.pixel.next = u64::from(frame.at(x, y)).into();
                d.line_start.next = x == 0;
                d.frame_start.next = x == 0 && y == 0;
                words.extend(cycle(&mut driver));
            }
            let gap = rng.gen_range(0..4);
            idle(&mut driver, &mut rng, gap, &mut words);
        }
        idle(&mut driver, &mut rng, GROUPED_LATENCY + 2, &mut words);
        expected.extend(expected_words(&frame, &config));
    }
    // The recorded run is itself right, so the replay compares against a meaningful trace.
    assert_eq!(words, expected, "rust-hdl simulation vs golden model");
    assert!(words.iter().any(|w| w >> 30 != 0), "no flag was exercised");

    let trace = driver.take_trace();
    let mut fresh = BayerGrouper::default();
    fresh.connect_all();
    let verilog = generate_verilog(&fresh);
    let report = xcheck::replay("bayer_grouper", &verilog, &trace).unwrap();
    println!("{}", report.summary());
    assert!(
        report.steps > 3000,
        "trace too short: {} steps",
        report.steps
    );
    assert!(report.is_clean(), "{}", report.summary());

    // A one-bit change in the Verilog's under-range flag must be caught on `word`.
    let tampered = verilog.replace("under_flag = 32'h40000000", "under_flag = 32'h20000000");
    assert!(
        tampered != verilog,
        "the constant is not where the test expects it"
    );
    let report = xcheck::replay("bayer_grouper_tampered", &tampered, &trace).unwrap();
    assert!(
        report.mismatches.iter().any(|m| m.port == "word"),
        "tampering not caught"
    );
}

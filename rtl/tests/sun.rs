//! The sun accumulators against their golden model: random frames of grouped words (flags,
//! luminances around the threshold), windows, thresholds, line widths, armed and unarmed
//! frames, and idle cycles with garbage on the inputs between words (back-pressure).

use proptest::prelude::*;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use skylux_regmap::words::grouped;
use skylux_rtl::sun::bench::SunBench;
use skylux_rtl::sun::golden::{accumulate, SunConfig, SunSums};
use skylux_rtl::sun::SUN_LATENCY;

/// Words around the threshold: dark, just below, at, above, the largest, with flags at random.
fn words(rng: &mut StdRng, n: usize, threshold_q14: u32) -> Vec<u32> {
    let top = grouped::LUMA_MAX_Q14 as u32;
    (0..n)
        .map(|_| {
            let l = match rng.gen_range(0..6) {
                0 => rng.gen_range(0..1000),
                1 => threshold_q14.saturating_sub(1),
                2 => threshold_q14,
                3 => top,
                _ => rng.gen_range(threshold_q14..=top),
            };
            grouped::pack(l, rng.gen_bool(0.1), rng.gen_bool(0.15))
        })
        .collect()
}

/// A random configuration and frame (partial last lines too).
fn random_frame(rng: &mut StdRng) -> (SunConfig, Vec<u32>) {
    let per_line = rng.gen_range(0..14u16);
    let threshold_q14 = rng.gen_range(1..grouped::LUMA_MAX_Q14 as u32);
    let (x_a, x_b) = (rng.gen_range(0..16u16), rng.gen_range(0..16u16));
    let (y_a, y_b) = (rng.gen_range(0..10u16), rng.gen_range(0..10u16));
    let config = SunConfig {
        groups_per_line: per_line,
        threshold_q14,
        x_min: x_a.min(x_b),
        x_max: x_a.max(x_b),
        y_min: y_a.min(y_b),
        y_max: y_a.max(y_b),
    };
    let width = usize::from(per_line.max(1));
    let n = width * rng.gen_range(1..9usize) - rng.gen_range(0..width);
    let words = words(rng, n, threshold_q14);
    (config, words)
}

/// Runs `frames` random frames on one block, checks the outputs after each, and returns the
/// groups counted.
fn run(seed: u64, frames: usize, gap_percent: u32) -> usize {
    let mut rng = StdRng::seed_from_u64(seed);
    let mut gaps = StdRng::seed_from_u64(seed ^ 0x5eed);
    let mut bench = SunBench::new(seed ^ 0xbeef);
    bench.idle(2);
    let (mut expected, mut armed_frames, mut counted) = (SunSums::default(), 0, 0);
    for _ in 0..frames {
        let (config, words) = random_frame(&mut rng);
        let armed = rng.gen_bool(0.7);
        bench.configure(&config);
        bench.idle(1);
        bench.frame(&words, armed, || {
            if gaps.gen_range(0..100) < gap_percent {
                gaps.gen_range(1..=3)
            } else {
                0
            }
        });
        bench.idle(SUN_LATENCY);
        if armed {
            expected = accumulate(&config, &words);
            armed_frames += 1;
            counted += expected.count as usize;
        }
        assert_eq!(bench.sums(), expected, "seed {seed}, {config:?}");
        assert_eq!(bench.armed_frames(), armed_frames);
    }
    counted
}

#[test]
fn random_frames_equal_the_golden_model() {
    let counted: usize = (0..8).map(|seed| run(seed, 24, 30)).sum();
    assert!(
        counted > 200,
        "too few groups counted to mean anything: {counted}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn any_seed_and_back_pressure(seed in any::<u64>(), gap_percent in 0u32..90) {
        run(seed, 4, gap_percent);
    }
}

/// The first word of an armed frame restarts the sums from itself, not from the previous
/// frame's, even back to back with no idle cycle.
#[test]
fn back_to_back_armed_frames_restart_the_sums() {
    let mut bench = SunBench::new(1);
    let config = SunConfig {
        groups_per_line: 3,
        threshold_q14: 10,
        x_min: 0,
        x_max: 2,
        y_min: 0,
        y_max: 2,
    };
    bench.configure(&config);
    let a: Vec<u32> = (0..9)
        .map(|i| grouped::pack(100 + i, false, false))
        .collect();
    let b: Vec<u32> = (0..6)
        .map(|i| grouped::pack(50 * i + 20, false, i == 2))
        .collect();
    bench.frame(&a, true, || 0);
    bench.frame(&b, true, || 0);
    bench.idle(SUN_LATENCY);
    assert_eq!(bench.sums(), accumulate(&config, &b));
    assert_eq!(bench.sums().count, 6);
    assert_eq!(bench.armed_frames(), 2);
}

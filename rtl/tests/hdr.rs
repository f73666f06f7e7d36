//! The HDR selection against its golden model: random sets of frames of grouped words (flags,
//! luminances around the thresholds), thresholds, exposure indices, sets of several frames
//! and frames of different lengths, and idle cycles with garbage on the inputs between words
//! (back-pressure).

use proptest::prelude::*;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use skylux_regmap::words::grouped;
use skylux_rtl::hdr::bench::HdrBench;
use skylux_rtl::hdr::golden::{apply, select, FilledMask, HdrConfig, SetFrame};

/// Words around the thresholds (which compare the luminance without its last three bits):
/// below, at the floor's first and last step below, at the ceiling's last step and above,
/// inside, with flags at random.
fn words(rng: &mut StdRng, n: usize, c: &HdrConfig) -> Vec<u32> {
    let top = grouped::LUMA_MAX_Q14 as u32;
    let (lo, hi) = ((c.min_q11 << 3).min(top), ((c.max_q11 << 3) | 7).min(top));
    (0..n)
        .map(|_| {
            let l = match rng.gen_range(0..7) {
                0 => rng.gen_range(0..=lo),
                1 => lo.saturating_sub(1),
                2 => lo,
                3 => hi,
                4 => (hi + 1).min(top),
                5 => rng.gen_range(hi..=top),
                _ => rng.gen_range(lo..=hi),
            };
            grouped::pack(l, rng.gen_bool(0.15), rng.gen_bool(0.2))
        })
        .collect()
}

fn random_config(rng: &mut StdRng) -> HdrConfig {
    if rng.gen_bool(0.3) {
        return HdrConfig::default();
    }
    let top = (grouped::LUMA_MAX_Q14 >> 3) as u32;
    let (a, b) = (rng.gen_range(0..top), rng.gen_range(0..top));
    HdrConfig {
        min_q11: a.min(b),
        max_q11: a.max(b),
    }
}

/// Runs `sets` random sets on one block, checks every word's map word and write flag, and
/// that the writes leave the declarative selection in memory. Returns the writes masked.
fn run(seed: u64, sets: usize, gap_percent: u32) -> usize {
    let mut rng = StdRng::seed_from_u64(seed);
    let mut gaps = StdRng::seed_from_u64(seed ^ 0x5eed);
    let mut bench = HdrBench::new(seed ^ 0xbeef);
    let mut mask = FilledMask::default();
    let mut masked = 0;
    bench.idle(2);
    for _ in 0..sets {
        let config = random_config(&mut rng);
        bench.configure(&config);
        let groups = rng.gen_range(1..80usize);
        let count = rng.gen_range(1..=6usize);
        let first_index = rng.gen_range(0..8u8);
        let all: Vec<Vec<u32>> = (0..count)
            .map(|_| words(&mut rng, groups, &config))
            .collect();
        let frames: Vec<SetFrame> = all
            .iter()
            .enumerate()
            .map(|(k, w)| SetFrame {
                exposure_index: first_index.wrapping_add(k as u8) & 7,
                first_of_set: k == 0,
                words: w,
            })
            .collect();
        let mut memory = vec![0u32; groups];
        for f in &frames {
            bench.idle(rng.gen_range(0..3));
            let got = bench.frame(f, || {
                if gaps.gen_range(0..100) < gap_percent {
                    gaps.gen_range(1..=3)
                } else {
                    0
                }
            });
            let expected = mask.frame(&config, f);
            assert_eq!(got, expected, "seed {seed}, {config:?}");
            masked += got.iter().filter(|w| !w.1).count();
            apply(&mut memory, &got);
        }
        assert_eq!(
            memory,
            select(&config, &frames),
            "seed {seed}: the map left"
        );
        // A stray shorter frame (a window change) reads and writes only its own groups.
        if rng.gen_bool(0.2) {
            let w = words(&mut rng, groups / 2, &config);
            let f = SetFrame {
                exposure_index: 7,
                first_of_set: false,
                words: &w,
            };
            assert_eq!(bench.frame(&f, || 0), mask.frame(&config, &f));
        }
    }
    masked
}

#[test]
fn random_sets_equal_the_golden_model() {
    let masked: usize = (0..8).map(|seed| run(seed, 12, 30)).sum();
    assert!(
        masked > 500,
        "too few masked writes to mean anything: {masked}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn any_seed_and_back_pressure(seed in any::<u64>(), gap_percent in 0u32..90) {
        run(seed, 3, gap_percent);
    }
}

/// Back to back: a frame's first word taken the cycle after its restart, and the next frame's
/// restart the cycle after the last word, with one-group frames (the read of position 0 comes
/// one edge after its write).
#[test]
fn one_group_frames_back_to_back() {
    let mut bench = HdrBench::new(3);
    let c = HdrConfig::default();
    bench.configure(&c);
    let mut mask = FilledMask::default();
    let usable = [grouped::pack(900, false, false)];
    let over = [grouped::pack(900, false, true)];
    for (k, w) in [&over, &usable, &over, &usable].into_iter().enumerate() {
        let f = SetFrame {
            exposure_index: k as u8,
            first_of_set: k == 0,
            words: w,
        };
        let got = bench.frame(&f, || 0);
        assert_eq!(got, mask.frame(&c, &f));
        assert_eq!(got[0].1, k <= 1, "frame {k}");
    }
}

/// Positions past 2^20 live in the second block RAM: a set of two frames of 2^20 + 3000 groups
/// (as many as a full 2592 x 1944 frame's 1,259,712 would not add much but time), the second
/// frame's writes equal to the golden model's on both sides of the boundary.
#[test]
fn positions_past_two_to_the_twenty_use_the_second_ram() {
    let mut rng = StdRng::seed_from_u64(20);
    let mut bench = HdrBench::new(4);
    let c = HdrConfig::default();
    bench.configure(&c);
    let mut mask = FilledMask::default();
    let n = (1 << 20) + 3000;
    let frames: Vec<Vec<u32>> = (0..2).map(|_| words(&mut rng, n, &c)).collect();
    for (k, w) in frames.iter().enumerate() {
        let f = SetFrame {
            exposure_index: k as u8,
            first_of_set: k == 0,
            words: w,
        };
        let got = bench.frame(&f, || 0);
        let expected = mask.frame(&c, &f);
        assert!(got == expected, "frame {k} differs from the golden model");
        if k == 1 {
            let tail = &got[1 << 20..];
            let masked = tail.iter().filter(|w| !w.1).count();
            assert!(masked > 500 && masked < 2900, "past 2^20: {masked} masked");
        }
    }
}

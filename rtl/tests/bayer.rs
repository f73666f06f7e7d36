//! The Bayer grouping block against its golden model (random windows, configurations and
//! input gaps, and a full 2592x1944 frame), and the golden model against the formula on
//! hand-computed cases.

use proptest::prelude::*;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rust_hdl::prelude::*;
use skylux_regmap::words::{grouped, raw};
use skylux_rtl::bayer::golden::{expected_words, BayerConfig, Frame, Phase};
use skylux_rtl::bayer::{BayerGrouper, GROUPED_LATENCY, RAW_LATENCY};
use skylux_rtl::drive::Driver;
use std::time::Instant;

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

/// Idle cycles to insert: before each pixel and after each line.
trait Gaps {
    fn before_pixel(&mut self) -> usize;
    fn after_line(&mut self) -> usize;
}

struct NoGaps;
impl Gaps for NoGaps {
    fn before_pixel(&mut self) -> usize {
        0
    }
    fn after_line(&mut self) -> usize {
        0
    }
}

/// Random idle cycles: before a pixel with probability `pixel_gap_percent`, 1 to 3 of them;
/// 0 to 8 at each line end.
struct RandomGaps {
    rng: StdRng,
    pixel_gap_percent: u32,
}
impl Gaps for RandomGaps {
    fn before_pixel(&mut self) -> usize {
        if self.rng.gen_range(0..100) < self.pixel_gap_percent {
            self.rng.gen_range(1..=3)
        } else {
            0
        }
    }
    fn after_line(&mut self) -> usize {
        self.rng.gen_range(0..=8)
    }
}

/// A running block and the words it has emitted, with the cycle each one appeared after.
struct Bench {
    driver: Driver<BayerGrouper>,
    cycles: u64,
    words: Vec<u32>,
    word_cycles: Vec<u64>,
    /// Garbage for the data and marker inputs on idle cycles: they must be ignored.
    noise: StdRng,
}

impl Bench {
    fn new(config: &BayerConfig) -> Self {
        let mut driver = Driver::new(BayerGrouper::default());
        configure(&mut driver.dut, config);
        Bench {
            driver,
            cycles: 0,
            words: vec![],
            word_cycles: vec![],
            noise: StdRng::seed_from_u64(99),
        }
    }

    fn cycle(&mut self) {
        self.driver.cycle(clock).unwrap();
        self.cycles += 1;
        if self.driver.dut.word_valid.val() {
            self.words.push(self.driver.dut.word.val().to_u64() as u32);
            self.word_cycles.push(self.cycles);
        }
    }

    fn idle(&mut self, n: usize) {
        for _ in 0..n {
            let d = &mut self.driver.dut;
            d.pixel_valid.next = false;
            d.pixel.next = self.noise.gen_range(0..4096u64).into();
            d.line_start.next = self.noise.gen_bool(0.5);
            d.frame_start.next = self.noise.gen_bool(0.5);
            self.cycle();
        }
    }

    fn pixel(&mut self, value: u16, line_start: bool, frame_start: bool) {
        let d = &mut self.driver.dut;
        d.pixel_valid.next = true;
        d.pixel.next = u64::from(value).into();
        d.line_start.next = line_start;
        d.frame_start.next = frame_start;
        self.cycle();
    }

    fn frame(&mut self, frame: &Frame, gaps: &mut dyn Gaps) {
        for y in 0..frame.height {
            for x in 0..frame.width {
                let n = gaps.before_pixel();
                self.idle(n);
                // frame_start implies line_start: on a frame's first pixel line_start is
                // random, to cover both encodings.
                let first = x == 0 && y == 0;
                let line_start = if first {
                    self.noise.gen_bool(0.5)
                } else {
                    x == 0
                };
                self.pixel(frame.at(x, y), line_start, first);
            }
            let n = gaps.after_line();
            self.idle(n);
        }
    }

    /// Idle long enough for the last word to leave the pipeline.
    fn drain(&mut self) {
        self.idle(GROUPED_LATENCY + 2);
    }
}

fn run(frames: &[Frame], config: &BayerConfig, gaps: &mut dyn Gaps) -> Vec<u32> {
    let mut bench = Bench::new(config);
    bench.idle(3);
    for f in frames {
        bench.frame(f, gaps);
    }
    bench.drain();
    bench.words
}

fn expected(frames: &[Frame], config: &BayerConfig) -> Vec<u32> {
    frames
        .iter()
        .flat_map(|f| expected_words(f, config))
        .collect()
}

fn uniform(width: usize, height: usize, value: u16) -> Frame {
    Frame {
        width,
        height,
        samples: vec![value; width * height],
    }
}

fn words_differ(got: &[u32], want: &[u32]) -> Option<String> {
    if got == want {
        return None;
    }
    let first = got.iter().zip(want).position(|(g, w)| g != w);
    Some(format!(
        "{} words from the RTL, {} expected; first difference at {:?}: rtl {:08x?} golden {:08x?}",
        got.len(),
        want.len(),
        first,
        first.map(|i| got[i]),
        first.map(|i| want[i]),
    ))
}

// ---- random windows against the golden model ------------------------------------------

fn config_strategy() -> impl Strategy<Value = BayerConfig> {
    let level = prop_oneof![Just(0u16), Just(4095u16), 0u16..4096];
    let weight = prop_oneof![Just(0u16), Just(0x4000u16), Just(0xFFFFu16), any::<u16>()];
    (
        0usize..4,
        level.clone(),
        level.clone(),
        level,
        weight.clone(),
        weight.clone(),
        weight,
        prop::bool::weighted(0.25),
    )
        .prop_map(|(phase, black, a, b, wr, wg, wb, raw)| BayerConfig {
            phase: Phase::ALL[phase],
            black,
            // Mostly ordered ranges, but an inverted one is a legal register setting too.
            valid_min: if a % 8 == 0 { a.max(b) } else { a.min(b) },
            valid_max: if a % 8 == 0 { a.min(b) } else { a.max(b) },
            weight_r: wr,
            weight_g: wg,
            weight_b: wb,
            raw,
        })
}

/// A frame whose samples hit the interesting values often: the ends of the ADC range, the
/// valid range's bounds and their neighbours, and the black level.
fn frame_strategy(config: BayerConfig) -> impl Strategy<Value = Frame> {
    let c = config;
    let sample = prop_oneof![
        Just(0u16),
        Just(4095u16),
        Just(c.valid_min),
        Just(c.valid_max),
        Just(c.valid_min.saturating_sub(1)),
        Just((c.valid_max + 1).min(4095)),
        Just(c.black),
        0u16..4096,
        0u16..4096,
        0u16..4096,
    ];
    (1usize..=32, 1usize..=8).prop_flat_map(move |(half_w, half_h)| {
        let (w, h) = (2 * half_w, 2 * half_h);
        prop::collection::vec(sample.clone(), w * h).prop_map(move |samples| Frame {
            width: w,
            height: h,
            samples,
        })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    /// Two frames back to back (the second the first's samples reversed), with random idle
    /// cycles between pixels and at line ends: the RTL's words are the golden model's, bit
    /// for bit.
    #[test]
    fn rtl_equals_golden_model(
        (config, frame) in config_strategy().prop_flat_map(|c| (Just(c), frame_strategy(c))),
        gap_seed in any::<u64>(),
        pixel_gap_percent in prop_oneof![Just(0u32), 0u32..60],
    ) {
        let mut second = frame.clone();
        second.samples.reverse();
        let frames = [frame, second];
        let mut gaps = RandomGaps { rng: StdRng::seed_from_u64(gap_seed), pixel_gap_percent };
        let got = run(&frames, &config, &mut gaps);
        let want = expected(&frames, &config);
        prop_assert!(words_differ(&got, &want).is_none(), "{}", words_differ(&got, &want).unwrap());
    }
}

// ---- hand-computed cases: the golden model (and the RTL) against the formula -----------

/// Checks the golden model against hand-computed words, and the RTL against both.
fn check_by_hand(frame: &Frame, config: &BayerConfig, by_hand: &[u32]) {
    let golden = expected_words(frame, config);
    assert_eq!(golden, by_hand, "golden model vs hand computation");
    let rtl = run(std::slice::from_ref(frame), config, &mut NoGaps);
    assert_eq!(rtl, by_hand, "RTL vs hand computation");
}

#[test]
fn uniform_grey_frame() {
    // 0.25 R + 0.5 (G1+G2)/2 + 0.25 B of 1000 - 64 = 936 everywhere: 936 in Q16.14.
    let config = BayerConfig {
        black: 64,
        ..BayerConfig::default()
    };
    assert_eq!(
        (config.weight_r, config.weight_g, config.weight_b),
        (0x1000, 0x2000, 0x1000),
        "the registers' reset weights changed; update the hand computation"
    );
    check_by_hand(&uniform(8, 4, 1000), &config, &[936 << 14; 8]);
    assert_eq!(936 << 14, 0x00EA_0000);
}

#[test]
fn single_bright_red_pixel() {
    // 4x4 GRBG frame, black everywhere except 4000 at (1, 0): the red sample of block (0, 0).
    let mut frame = uniform(4, 4, 0);
    frame.samples[1] = 4000;
    let mut config = BayerConfig {
        weight_r: 0x4000, // 1.0
        weight_g: 0x2000, // 0.5
        weight_b: 0x8000, // 2.0
        valid_max: 3999,
        ..BayerConfig::default()
    };
    // GRBG: 1.0 x 4000 = 4000, and 4000 > valid_max sets OVER; the other blocks are 0.
    check_by_hand(&frame, &config, &[0x83E8_0000, 0, 0, 0]);
    // RGGB: the same position is green: 0.5 x (4000 + 0) / 2 = 1000.
    config.phase = Phase::Rggb;
    check_by_hand(&frame, &config, &[0x80FA_0000, 0, 0, 0]);
    // GBRG: the position is blue: 2.0 x 4000 = 8000 (and 4000 is in range now).
    config.phase = Phase::Gbrg;
    config.valid_max = 4095;
    check_by_hand(&frame, &config, &[8000 << 14, 0, 0, 0]);
}

#[test]
fn range_flags_at_and_beyond_the_bounds() {
    // One 8x2 row pair, four blocks, weights 0 so only the flags show.
    let config = BayerConfig {
        valid_min: 100,
        valid_max: 4094,
        weight_r: 0,
        weight_g: 0,
        weight_b: 0,
        ..BayerConfig::default()
    };
    let row0 = [100, 4094, 4095, 200, 99, 200, 200, 200];
    let row1 = [200, 200, 200, 200, 200, 200, 0, 4095];
    let frame = Frame {
        width: 8,
        height: 2,
        samples: row0.iter().chain(&row1).copied().collect(),
    };
    check_by_hand(
        &frame,
        &config,
        &[
            0,                              // exactly at both bounds: in range
            grouped::OVER,                  // 4095 > 4094
            grouped::UNDER,                 // 99 < 100
            grouped::UNDER | grouped::OVER, // 0 and 4095 in one block
        ],
    );
    assert_eq!((grouped::UNDER, grouped::OVER), (0x4000_0000, 0x8000_0000));
}

#[test]
fn black_level_saturates_and_truncation_rounds_down() {
    // Samples below black contribute 0 and are not negative.
    let config = BayerConfig {
        black: 64,
        ..BayerConfig::default()
    };
    check_by_hand(&uniform(2, 2, 50), &config, &[0]);

    // w_g = 3 (3 x 2^-14) on G1 + G2 = 1 + 0: exactly 1.5 x 2^-14, truncated to 1.
    let frame = Frame {
        width: 2,
        height: 2,
        samples: vec![1, 0, 0, 0], // GRBG: G1 = 1, R = 0, B = 0, G2 = 0
    };
    let config = BayerConfig {
        weight_r: 0,
        weight_g: 3,
        weight_b: 0,
        ..BayerConfig::default()
    };
    check_by_hand(&frame, &config, &[1]);
}

#[test]
fn largest_value_fits_without_touching_the_flags() {
    // All samples 4095, all weights 0xFFFF: 4095 w + 0xFFFF (4095 + 4095)/2 + 4095 w.
    let config = BayerConfig {
        weight_r: 0xFFFF,
        weight_g: 0xFFFF,
        weight_b: 0xFFFF,
        ..BayerConfig::default()
    };
    check_by_hand(&uniform(2, 2, 4095), &config, &[3 * 4095 * 0xFFFF]);
    assert_eq!(3 * 4095 * 0xFFFF, 0x2FFC_D003);
}

#[test]
fn raw_mode_stores_samples_unchanged() {
    // Every row, two samples a word, even column in the low half; config otherwise ignored.
    let frame = Frame {
        width: 4,
        height: 2,
        samples: vec![0x001, 0x002, 0xFFF, 0x004, 0x005, 0x006, 0x007, 0x800],
    };
    let config = BayerConfig {
        raw: true,
        black: 4095,
        valid_min: 4095,
        valid_max: 0,
        ..BayerConfig::default()
    };
    check_by_hand(
        &frame,
        &config,
        &[0x0002_0001, 0x0004_0FFF, 0x0006_0005, 0x0800_0007],
    );
    assert_eq!(raw::pack(0xFFF, 0x004), 0x0004_0FFF);
}

// ---- timing ------------------------------------------------------------------------------

#[test]
fn latency_and_one_word_per_two_clocks() {
    // A 4x2 window without gaps: each word appears GROUPED_LATENCY (RAW_LATENCY) edges after
    // the pixel that completes its block (pair), two cycles apart.
    for (raw, latency) in [(false, GROUPED_LATENCY), (true, RAW_LATENCY)] {
        let config = BayerConfig {
            raw,
            ..BayerConfig::default()
        };
        let mut bench = Bench::new(&config);
        bench.idle(3);
        let start = bench.cycles;
        bench.frame(&uniform(4, 2, 500), &mut NoGaps);
        bench.drain();
        // Pixel k (0-based) is taken on the edge of cycle start + k + 1, so a word it
        // completes is out after cycle start + k + latency. Bottom-line odd columns complete
        // blocks (k = 5, 7); in raw mode every odd column completes a pair.
        let completing: Vec<u64> = if raw { vec![1, 3, 5, 7] } else { vec![5, 7] };
        let want: Vec<u64> = completing
            .iter()
            .map(|k| start + k + latency as u64)
            .collect();
        assert_eq!(bench.word_cycles, want, "raw = {raw}");
    }
}

#[test]
fn widest_line_buffer_row() {
    // 4096 columns, the line buffer's full depth, with a different frame after it.
    let mut rng = StdRng::seed_from_u64(3);
    let frame = Frame {
        width: 4096,
        height: 4,
        samples: (0..4096 * 4).map(|_| rng.gen_range(0..4096)).collect(),
    };
    let small = uniform(6, 2, 4000);
    let config = BayerConfig {
        black: 168,
        valid_min: 200,
        valid_max: 3900,
        ..BayerConfig::default()
    };
    let frames = [frame, small];
    let got = run(&frames, &config, &mut NoGaps);
    assert_eq!(words_differ(&got, &expected(&frames, &config)), None);
}

/// A full MT9P031 frame (hardware-facts.md §1.1: 2592 x 1944 active), one pixel per clock
/// with no blanking at all (harder than the sensor's: lines back to back). In CI (issue 23
/// item 5): about 16 s at the workspace's opt-level 3 (5.0 M cycles, ~320 k cycles/s).
#[test]
fn full_frame_one_pixel_per_clock() {
    let (w, h) = (2592, 1944);
    let mut rng = StdRng::seed_from_u64(5);
    let frame = Frame {
        width: w,
        height: h,
        samples: (0..w * h).map(|_| rng.gen_range(0..4096)).collect(),
    };
    let config = BayerConfig {
        phase: Phase::Grbg,
        black: 168,
        valid_min: 180,
        valid_max: 4000,
        weight_r: 0x1366,
        weight_g: 0x2591,
        weight_b: 0x0750,
        raw: false,
    };
    let t0 = Instant::now();
    let mut bench = Bench::new(&config);
    bench.frame(&frame, &mut NoGaps);
    bench.drain();
    let dt = t0.elapsed().as_secs_f64();
    let want = expected_words(&frame, &config);
    assert_eq!(bench.words.len(), (w / 2) * (h / 2));
    assert_eq!(words_differ(&bench.words, &want), None);
    println!(
        "full frame: {} cycles in {:.2} s = {:.0} cycles/s",
        bench.cycles,
        dt,
        bench.cycles as f64 / dt
    );
}

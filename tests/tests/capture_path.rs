//! The capture path end to end: pixel bus -> rust-hdl CapturePath (capture, Bayer grouper,
//! clock-domain FIFO, frame DMA) -> the SDRAM model (`AvalonMemory`) -> the HPS frame reader, on small windows.
//! Every frame is checked against the Bayer golden model and its descriptor; every injected
//! fault must end in a flagged frame or status bit, and no write may leave the window.

use proptest::prelude::*;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use skylux_hps::fpga::frames::{CapturedFrame, RingLayout};
use skylux_regmap::descriptor::flag;
use skylux_rtl::bayer::golden::{expected_words, BayerConfig, Frame, Phase};
use skylux_sim::bus::WaitPolicy;
use skylux_sim::capture_path::{CapturePathSim, PathConfig};
use skylux_sim::pixel_bus::{Blanking, Fault};

fn random_frame(width: usize, height: usize, rng: &mut StdRng) -> Frame {
    Frame {
        width,
        height,
        samples: (0..width * height)
            .map(|_| match rng.gen_range(0..10) {
                0 => 0,
                1 => 4095,
                _ => rng.gen_range(0..4096),
            })
            .collect(),
    }
}

fn ring(config: &PathConfig) -> RingLayout {
    RingLayout {
        window_base: u64::from(config.window_base),
        slot_stride_bytes: config.slot_stride_bytes,
        slots: config.slots,
    }
}

/// Sends `frames` (each with its faults), tagging frame `k` with number `100 + k` and
/// exposure `k % 8`, and runs until the DMA is idle. Returns the harness.
fn run(
    config: PathConfig,
    policy: WaitPolicy,
    frames: &[(Frame, Vec<Fault>)],
    seed: u64,
) -> CapturePathSim {
    let mut sim = CapturePathSim::new(config, policy, seed);
    let blanking = Blanking::default();
    sim.bus.push_idle(8);
    sim.run_sys_cycles(20).unwrap();
    for (k, (frame, faults)) in frames.iter().enumerate() {
        sim.set_tags((k % 8) as u8, 100 + k as u32);
        sim.push_frame(&frame.samples, frame.width, frame.height, &blanking, faults);
        assert!(
            sim.run_until_idle(1500, 2_000_000).unwrap(),
            "frame {k} never finished"
        );
    }
    sim
}

fn read(sim: &mut CapturePathSim, slot: u8) -> Option<CapturedFrame> {
    let layout = ring(&sim.config);
    layout.read_slot(&mut sim.memory, slot).unwrap()
}

fn assert_no_violations(sim: &CapturePathSim) {
    assert!(
        sim.memory.violations.is_empty(),
        "bus violations: {:?}",
        &sim.memory.violations[..sim.memory.violations.len().min(5)]
    );
}

#[test]
fn clean_frames_equal_the_golden_model_under_random_waitrequest() {
    let mut rng = StdRng::seed_from_u64(1);
    let (w, h) = (64, 48);
    let mut config = PathConfig::fitted(w as u16, h as u16, 2);
    config.bayer = BayerConfig {
        phase: Phase::Rggb,
        black: 100,
        valid_min: 200,
        valid_max: 3900,
        weight_r: 0x1234,
        weight_g: 0x2345,
        weight_b: 0x0F00,
        raw: false,
    };
    let frames: Vec<(Frame, Vec<Fault>)> = (0..3)
        .map(|_| (random_frame(w, h, &mut rng), vec![]))
        .collect();
    let mut sim = run(config, WaitPolicy::random(0.3), &frames, 7);
    assert_no_violations(&sim);
    assert_eq!(sim.status.frames_done, 3);
    assert!(
        sim.memory.stall_cycles > 0,
        "waitrequest never stalled the DMA"
    );
    assert!(!sim.status.fifo_overflow && !sim.status.line_short && !sim.status.frame_short);
    // Frame 2 wrapped into slot 0; frame 1 is in slot 1.
    for (slot, k) in [(0u8, 2usize), (1, 1)] {
        let got = read(&mut sim, slot).expect("a frame in the slot");
        let want = expected_words(&frames[k].0, &config.bayer);
        let d = got.descriptor;
        assert_eq!(got.flag_names(), Vec::<&str>::new(), "slot {slot}");
        assert_eq!(d.frame_number, 100 + k as u32);
        assert_eq!(d.exposure_index, k as u8);
        assert_eq!((d.lines as usize, d.last_line_pixels as usize), (h, w));
        assert_eq!(d.payload_words as usize, want.len());
        assert!(
            got.words == want,
            "slot {slot}: payload differs from the golden model"
        );
        assert_eq!(got.checksum_ok(), Some(true));
        assert!(d.timestamp_cycles > 0 && d.timestamp_cycles < sim.counters.sys_cycles);
    }
}

/// Sends one frame, waits for the DMA, and reads slot 0 (rings of one slot).
/// Which status bits a fault must raise.
type StatusCheck = fn(&skylux_sim::capture_path::StatusSeen) -> bool;

fn one_frame(
    sim: &mut CapturePathSim,
    frame: &Frame,
    faults: &[Fault],
    number: u32,
) -> Option<CapturedFrame> {
    sim.set_tags(1, number);
    let blanking = Blanking::default();
    sim.push_frame(&frame.samples, frame.width, frame.height, &blanking, faults);
    assert!(
        sim.run_until_idle(1500, 2_000_000).unwrap(),
        "frame {number} never finished"
    );
    read(sim, 0)
}

#[test]
fn every_injected_fault_ends_in_a_flagged_frame_and_a_status_bit() {
    let mut rng = StdRng::seed_from_u64(3);
    let (w, h) = (32, 16);
    let config = PathConfig::fitted(w as u16, h as u16, 1);
    let mut sim = CapturePathSim::new(config, WaitPolicy::random(0.3), 11);
    sim.bus.push_idle(8);
    let cases: Vec<(Fault, u32, StatusCheck)> = vec![
        (
            Fault::FvDropMidLine { row: 5, column: 10 },
            flag::LINE_SHORT | flag::FRAME_SHORT,
            |s| s.line_short && s.frame_short,
        ),
        (
            Fault::LvGlitch {
                row: 3,
                column: 7,
                pixclk: 2,
            },
            flag::LINE_SHORT | flag::FRAME_LONG,
            |s| s.line_short && s.frame_long,
        ),
        (Fault::ExtraLines { count: 2 }, flag::FRAME_LONG, |s| {
            s.frame_long
        }),
        (Fault::MissingLines { count: 2 }, flag::FRAME_SHORT, |s| {
            s.frame_short
        }),
        (
            Fault::ShortLine { row: 2, pixels: 4 },
            flag::LINE_SHORT,
            |s| s.line_short,
        ),
        (
            Fault::LongLine { row: 2, pixels: 4 },
            flag::LINE_LONG,
            |s| s.line_long,
        ),
        (
            Fault::PixclkStop {
                row: 4,
                column: 8,
                pixclk: 3000,
            },
            flag::PIXCLK_STOPPED,
            |s| s.pixclk_stopped,
        ),
    ];
    for (k, (fault, flags, status)) in cases.into_iter().enumerate() {
        sim.status = Default::default();
        let frame = random_frame(w, h, &mut rng);
        let got = one_frame(&mut sim, &frame, &[fault], k as u32)
            .unwrap_or_else(|| panic!("{fault:?}: no descriptor"));
        let d = got.descriptor;
        assert_eq!(d.frame_number, k as u32, "{fault:?}: stale slot");
        assert_eq!(
            d.flags & flags,
            flags,
            "{fault:?}: flags {:?}",
            got.flag_names()
        );
        assert!(status(&sim.status), "{fault:?}: status {:?}", sim.status);
        assert!(
            sim.status.capture_error_irqs > 0,
            "{fault:?}: no capture-error interrupt"
        );
        // What was delivered is what is in memory.
        assert_eq!(got.checksum_ok(), Some(true), "{fault:?}");
        let golden = expected_words(&frame, &config.bayer);
        match fault {
            // Extra pixels and lines are dropped at the window: the payload is the frame's.
            Fault::ExtraLines { .. } | Fault::LongLine { .. } => assert!(got.words == golden),
            _ => assert!(got.words.len() <= golden.len()),
        }
        assert_no_violations(&sim);

        // The path recovers: the next clean frame is exact.
        sim.status = Default::default();
        let clean = random_frame(w, h, &mut rng);
        let got = one_frame(&mut sim, &clean, &[], 1000 + k as u32).expect("a frame");
        assert!(got.is_good(), "after {fault:?}: {:?}", got.flag_names());
        assert_eq!(got.descriptor.frame_number, 1000 + k as u32);
        assert!(
            got.words == expected_words(&clean, &config.bayer),
            "after {fault:?}"
        );
    }
}

#[test]
fn back_pressure_beyond_the_fifo_flags_the_frame_overflowed() {
    let mut rng = StdRng::seed_from_u64(4);
    // Raw mode: 1536 words, more than the FIFO and the beat buffer hold together (640).
    let (w, h) = (64, 48);
    let mut config = PathConfig::fitted(w as u16, h as u16, 1);
    config.bayer.raw = true;
    config.bus_timeout_cycles = 500;
    let policy = WaitPolicy {
        hold_from_cycle: 0,
        hold_cycles: 30_000,
        ..WaitPolicy::NONE
    };
    let mut sim = CapturePathSim::new(config, policy, 5);
    sim.bus.push_idle(8);
    let frame = random_frame(w, h, &mut rng);
    let got = one_frame(&mut sim, &frame, &[], 7).expect("a descriptor");
    let d = got.descriptor;
    let golden = expected_words(&frame, &config.bayer);
    assert!(d.raw);
    assert!(
        (d.payload_words as usize) < golden.len(),
        "{} of {} words: nothing was lost?",
        d.payload_words,
        golden.len()
    );
    assert_ne!(
        d.flags & flag::FIFO_OVERFLOW,
        0,
        "short frame without FIFO_OVERFLOW"
    );
    assert_ne!(d.flags & flag::BUS_TIMEOUT, 0);
    assert!(sim.status.fifo_overflow && sim.status.dma_overflow && sim.status.bus_timeout);
    assert_eq!(got.checksum_ok(), Some(true));
    // The words that did arrive are the frame's first ones, in order.
    assert!(got.words[..256] == golden[..256]);
    assert!(
        sim.counters.fifo_high_water >= skylux_rtl::capture::fifo_entry::FIFO_DEPTH / 2,
        "{}",
        sim.counters.fifo_high_water
    );
    assert_no_violations(&sim);
}

#[test]
fn the_dma_never_writes_outside_its_window() {
    let mut rng = StdRng::seed_from_u64(5);
    let (w, h) = (32, 16);
    let frame = random_frame(w, h, &mut rng);
    let golden = expected_words(&frame, &BayerConfig::default());

    // A slot too small for the payload: truncated, flagged, the descriptor still written.
    let mut config = PathConfig::fitted(w as u16, h as u16, 2);
    config.slot_stride_bytes = 64 + 4 * 40;
    config.window_size_bytes = 2 * config.slot_stride_bytes;
    let mut sim = CapturePathSim::new(config, WaitPolicy::random(0.2), 6);
    sim.bus.push_idle(8);
    for _ in 0..3 {
        one_frame_raw(&mut sim, &frame);
    }
    assert_no_violations(&sim);
    assert!(sim.status.out_of_window);
    for slot in 0..2 {
        let got = read(&mut sim, slot).expect("a descriptor");
        assert_ne!(got.descriptor.flags & flag::TRUNCATED, 0);
        assert_eq!(got.descriptor.payload_words as usize, golden.len());
        assert_eq!(got.checksum_ok(), None);
        assert!(got.words.len() <= 40 && got.words[..] == golden[..got.words.len()]);
    }

    // Unusable windows: nothing is written at all, and the status says why.
    for (what, edit) in [
        (
            "misaligned base",
            (|c: &mut PathConfig| c.window_base += 4) as fn(&mut PathConfig),
        ),
        ("window smaller than a slot", |c| {
            c.window_size_bytes = c.slot_stride_bytes - 8
        }),
        ("stride below the minimum slot", |c| {
            c.slot_stride_bytes = 64
        }),
        ("window past 4 GiB", |c| {
            c.window_base = 0xFFFF_F000;
            c.window_size_bytes = 0x2000;
        }),
    ] {
        let mut config = PathConfig::fitted(w as u16, h as u16, 1);
        edit(&mut config);
        let mut sim = CapturePathSim::new(config, WaitPolicy::NONE, 6);
        sim.bus.push_idle(8);
        one_frame_raw(&mut sim, &frame);
        assert_eq!(sim.memory.beats, 0, "{what}: the DMA wrote");
        assert!(sim.status.out_of_window, "{what}: no OUT_OF_WINDOW");
        assert_eq!(sim.status.frames_done, 0, "{what}");
        assert_no_violations(&sim);
    }
}

/// One frame without reading it back (the ring may be unreadable).
fn one_frame_raw(sim: &mut CapturePathSim, frame: &Frame) {
    let blanking = Blanking::default();
    sim.push_frame(&frame.samples, frame.width, frame.height, &blanking, &[]);
    assert!(sim.run_until_idle(1500, 2_000_000).unwrap());
}

fn config_strategy() -> impl Strategy<Value = BayerConfig> {
    (
        0usize..4,
        0u16..4096,
        0u16..4096,
        0u16..4096,
        any::<u16>(),
        any::<u16>(),
        any::<u16>(),
        prop::bool::weighted(0.3),
    )
        .prop_map(|(phase, black, a, b, wr, wg, wb, raw)| BayerConfig {
            phase: Phase::ALL[phase],
            black: black / 8,
            valid_min: a.min(b),
            valid_max: a.max(b),
            weight_r: wr,
            weight_g: wg,
            weight_b: wb,
            raw,
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]

    /// Random windows, settings, Bayer phases, modes and waitrequest rates: the words in
    /// memory are the golden model's, bit for bit, and the descriptor matches them.
    #[test]
    fn memory_equals_golden_model(
        bayer in config_strategy(),
        half_w in 1usize..=16,
        half_h in 1usize..=4,
        wait_percent in 0u32..60,
        seed in any::<u64>(),
    ) {
        let (w, h) = (2 * half_w, 2 * half_h);
        let mut rng = StdRng::seed_from_u64(seed);
        let mut config = PathConfig::fitted(w as u16, h as u16, 1);
        config.bayer = bayer;
        let mut sim = CapturePathSim::new(config, WaitPolicy::random(f64::from(wait_percent) / 100.0), seed);
        sim.bus.push_idle(8);
        let frame = random_frame(w, h, &mut rng);
        let got = one_frame(&mut sim, &frame, &[], 5).expect("a descriptor");
        let golden = expected_words(&frame, &bayer);
        prop_assert!(got.is_good(), "{:?}", got.flag_names());
        prop_assert_eq!(&got.words, &golden);
        prop_assert_eq!(got.descriptor.raw, bayer.raw);
        prop_assert!(sim.memory.violations.is_empty());
    }
}

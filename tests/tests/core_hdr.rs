//! HDR in the fabric end to end (issue 22 item 1): the cycle-accurate core (`SkyluxCore`) with
//! an MT9P031 model on the camera pins and the SDRAM model with random waitrequest, driven by
//! the HPS drivers: a 5-exposure sequence, long to short, over a window of a log-ramp scene
//! that each exposure sees differently, written as one map into one ring slot.
//! The 256 x 192 window takes about 10 minutes of one core (each frame is 217 rows of 1156
//! PIXCLK at that width), so it is `#[ignore]`d and run by hand
//! (`cargo test -p skylux-tests --test core_hdr -- --ignored`); a 32 x 16 window runs always.
//! The map equals the golden model's selection over the frames the sensor sent; the HPS reads
//! it into the same `LuminanceMap` its merge makes, with the same flags and the luminance of
//! the merge of the same frames within quantisation.

use skylux_hps::camera::{CameraModel, DeviceConfig};
use skylux_hps::campaign::{BayerPattern, RawFrame, Readout};
use skylux_hps::fpga::sensor::{I2cTiming, SensorConfig};
use skylux_hps::fpga::sequence::ShieldConfig;
use skylux_hps::fpga::{CaptureConfig, ExposureSlot, Fabric};
use skylux_hps::hdr::{
    fabric_map, merge, Exposure, FabricMap, GroupGeometry, MapExposure, MapFlag,
};
use skylux_regmap::hdr_values::HdrConfig;
use skylux_regmap::words::hdr_map;
use skylux_rtl::bayer::golden::{expected_words, BayerConfig, Frame, Phase};
use skylux_rtl::hdr::golden::{select, FilledMask, SetFrame};
use skylux_sim::core_rig::{sim_core, CoreRigConfig};
use skylux_sim::mt9p031::frame::FrameSettings;
use skylux_sim::mt9p031::{Mt9p031, PixelSource};
use std::sync::{Arc, Mutex};

const WINDOW_BASE: u64 = 0x3000_1000;
const PIXCLK_HZ: f64 = 96e6;
const BLACK_DN: u16 = 5;
const VALID_MIN_DN: u16 = 20;
const VALID_MAX_DN: u16 = 3000;

/// Long to short: shutter rows halving, one slot at twice the gain (code 16, unity is 8).
fn slots() -> Vec<ExposureSlot> {
    [(16, 8), (8, 8), (4, 8), (2, 16), (1, 8)]
        .iter()
        .map(|&(rows, gain_code)| ExposureSlot {
            shutter_width_rows: rows,
            shutter_delay: 0,
            gain_code,
        })
        .collect()
}

/// A grey log ramp: the signal rate spans 5 decades across the window, so the darkest groups
/// are under-range in every exposure, the brightest over-range in every one, and most are
/// usable in several. Records each frame's exposure and gain for the calibration.
struct LogRamp {
    settings: Arc<Mutex<Vec<(u64, f64)>>>,
}

impl PixelSource for LogRamp {
    fn frame(&mut self, s: &FrameSettings, _pixclk_hz: f64, _frame_index: u64) -> RawFrame {
        self.settings
            .lock()
            .unwrap()
            .push((s.exposure_pixclk, s.gain));
        let (w, h) = (s.geometry.width as usize, s.geometry.height as usize);
        // The longest exposure (16 rows of 1156 PIXCLK less the shutter overhead, about 18,000
        // PIXCLK at 256 pixels a line; 972-PIXCLK rows at 32) spans about 2 to 200,000 DN.
        let longest_pixclk = 18_000.0;
        let samples_dn = (0..w * h)
            .map(|i| {
                let u = ((i % w) as f64 + 0.3 * (i / w) as f64) / (w as f64 + 0.3 * h as f64);
                let rate = 2.0 * 100_000f64.powf(u) / longest_pixclk;
                let dn = f64::from(BLACK_DN) + rate * s.exposure_pixclk as f64 * s.gain;
                dn.min(4095.0) as u16
            })
            .collect();
        RawFrame {
            width: w,
            height: h,
            samples_dn,
        }
    }
}

#[test]
#[ignore = "about 10 minutes: run with --ignored"]
fn the_core_writes_the_golden_map_of_a_five_exposure_set_256_by_192() {
    run_set(256, 192, false);
}

/// The set split over two sequences (as two shield openings are): the exposure tags restart,
/// the set does not.
#[test]
fn the_core_writes_the_golden_map_of_a_five_exposure_set_over_two_sequences_32_by_16() {
    run_set(32, 16, true);
}

/// One set over a `WIDTH` x `HEIGHT` window, in one sequence or in two (3 + 2 exposures),
/// checked end to end.
#[allow(non_snake_case)]
fn run_set(WIDTH: u32, HEIGHT: u32, split: bool) {
    let groups = (WIDTH / 2 * HEIGHT / 2) as usize;
    let settings = Arc::new(Mutex::new(vec![]));
    let capture = {
        let mut c = CaptureConfig::fitted(WIDTH, HEIGHT, WINDOW_BASE, 1);
        c.grouping.black_level_dn = BLACK_DN.into();
        c.grouping.valid_min_dn = VALID_MIN_DN.into();
        c.grouping.valid_max_dn = VALID_MAX_DN.into();
        c
    };
    let sensor = Mt9p031::new(
        Box::new(LogRamp {
            settings: settings.clone(),
        }),
        PIXCLK_HZ,
    );
    let memory_bytes = 0x1000 + capture.window_size_bytes as usize + 0x1000;
    let (shared, regs, mut memory, _raybox) =
        sim_core(sensor, CoreRigConfig::new(memory_bytes, 4096, 0.3));
    let mut f = Fabric::bring_up(regs).expect("bring-up of the whole core");
    f.sensor_bus_setup(I2cTiming {
        half_period_cycles: 4,
        timeout_cycles: 5_000,
    })
    .unwrap();
    f.sensor_reset_release(true).unwrap();
    f.sensor_configure(&SensorConfig {
        row_start: 54,
        col_start: 16,
        height: HEIGHT,
        width: WIDTH,
        shutter_width_rows: 3,
        global_gain_code: 8,
        ..SensorConfig::default()
    })
    .unwrap();
    f.capture_configure(&capture).unwrap();
    f.configure_shield(&ShieldConfig {
        steps: 3,
        step_period_cycles: 40,
        limit_cycles: 20_000_000,
        trigger_pulse_cycles: 4,
    })
    .unwrap();
    let config = HdrConfig::default();
    f.hdr_configure(&config, true).unwrap();
    f.hdr_new_set().unwrap();
    // The exposures of each sequence, as ranges of `slots()`.
    let sequences: Vec<std::ops::Range<usize>> = if split {
        vec![0..3, 3..5]
    } else {
        std::iter::once(0..5).collect()
    };
    for range in sequences.clone() {
        f.set_exposures(&slots()[range.clone()]).unwrap();
        let outcome = f.run_sequence(2_000_000).unwrap();
        assert_eq!(outcome.frames as usize, range.len());
        let mut written = 0;
        for _ in 0..200_000 {
            written = f.frames_written().unwrap();
            if written as usize >= range.end {
                break;
            }
        }
        assert_eq!(written as usize, range.end, "the DMA finished every frame");
    }
    let faults = f.capture_take_faults().unwrap();
    assert!(!faults.any(), "{faults:?}");

    // The one slot holds the map, its descriptor the last (shortest) frame's.
    let got = capture
        .ring
        .read_slot(&mut memory, 0)
        .expect("slot readable")
        .expect("slot 0 holds the map");
    let d = &got.descriptor;
    assert!(d.hdr_map && !d.raw, "{d:?}");
    // The last frame's own tag: its index in its sequence.
    let last_tag = sequences.last().map_or(0, |r| r.len() - 1);
    assert_eq!((usize::from(d.exposure_index), d.flags), (last_tag, 0));
    assert_eq!(
        got.checksum_ok(),
        None,
        "a map's checksum is not a payload sum"
    );

    // The golden model over the frames the sensor sent.
    let rig = shared.lock().unwrap();
    assert_eq!(rig.log.frames.len(), 5);
    let bayer = BayerConfig {
        phase: Phase::from_register(capture.grouping.phase),
        black: BLACK_DN,
        valid_min: VALID_MIN_DN,
        valid_max: VALID_MAX_DN,
        ..BayerConfig::default()
    };
    let grouped: Vec<Vec<u32>> = rig
        .log
        .frames
        .iter()
        .map(|s| {
            let frame = Frame {
                width: s.width,
                height: s.height,
                samples: s.samples_dn.clone(),
            };
            expected_words(&frame, &bayer)
        })
        .collect();
    let set: Vec<SetFrame> = grouped
        .iter()
        .enumerate()
        .map(|(k, words)| SetFrame {
            exposure_index: k as u8,
            first_of_set: k == 0,
            words,
        })
        .collect();
    let golden = select(&config, &set);
    assert_eq!(got.words.len(), golden.len());
    let differing = got
        .words
        .iter()
        .zip(&golden)
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(
        differing, 0,
        "the map differs from the golden model in {differing} groups"
    );
    // The set's checksum: the sum of the usable words, as the HPS recomputes it.
    assert_eq!(d.checksum, config.map_checksum(&golden));
    assert_eq!(got.map_checksum_ok(&config), Some(true));

    // The case exercises the selection: groups from every exposure, groups no exposure covers
    // both ways, and writes masked after a group was filled.
    let mut from = [0usize; 5];
    for w in &golden {
        from[usize::from(hdr_map::exposure_index(*w))] += 1;
    }
    assert!(from.iter().all(|&n| n > 0), "groups per exposure: {from:?}");
    assert!(golden.iter().any(|&w| hdr_map::over(w)));
    let mut mask = FilledMask::default();
    let masked: usize = set
        .iter()
        .map(|s| mask.frame(&config, s).iter().filter(|w| !w.1).count())
        .sum();
    assert!(
        masked > groups / 2,
        "masked writes: {masked} of {groups} groups"
    );
    let end = WINDOW_BASE + u64::from(capture.window_size_bytes);
    for a in rig.frame_writes() {
        assert!(
            a.write && a.address >= WINDOW_BASE && a.address + a.bytes <= end,
            "{a:?}"
        );
    }

    // The HPS: the map into a LuminanceMap, against the merge of the frames the sensor sent.
    let recorded = settings.lock().unwrap().clone();
    assert_eq!(recorded.len(), 5);
    let exposures: Vec<MapExposure> = recorded
        .iter()
        .map(|&(pixclk, gain)| MapExposure {
            exposure_s: pixclk as f64 / PIXCLK_HZ,
            gain,
        })
        .collect();
    let mut device = DeviceConfig::default();
    device.sensor.black_level_dn = BLACK_DN.into();
    device.sensor.valid_min_dn = VALID_MIN_DN.into();
    device.sensor.valid_max_dn = VALID_MAX_DN.into();
    // The fabric's reset weights, 0x1000, 0x2000, 0x1000 in Q2.14.
    device.response.weights = [0.25, 0.5, 0.25];
    let camera = CameraModel::new(device.clone());
    let readout = Readout {
        col_start: 1296 - WIDTH / 2,
        row_start: 972 - HEIGHT / 2,
        skip: 1,
        bin: 1,
    };
    let geometry = GroupGeometry::new(&camera, &readout, WIDTH as usize, HEIGHT as usize);
    let map = FabricMap {
        width: WIDTH as usize / 2,
        height: HEIGHT as usize / 2,
        words: got.words.clone(),
    };
    let from_fabric = fabric_map(
        &map,
        &exposures,
        &config,
        &device,
        BayerPattern::GRBG,
        &geometry,
    )
    .unwrap();
    let raw: Vec<Exposure> = rig
        .log
        .frames
        .iter()
        .zip(&exposures)
        .map(|(frame, e)| Exposure {
            frame,
            exposure_s: e.exposure_s,
            gain: e.gain,
        })
        .collect();
    let from_merge = merge(&raw, &device, BayerPattern::GRBG, &geometry).unwrap();
    assert_eq!(from_fabric.flags, from_merge.flags);
    let valid = from_fabric
        .flags
        .iter()
        .filter(|f| **f == MapFlag::Valid)
        .count();
    assert!(valid > groups / 2, "valid groups: {valid} of {groups}");
    let mut worst: f64 = 0.0;
    for (i, (a, b)) in from_fabric
        .luminance_cd_m2
        .iter()
        .zip(&from_merge.luminance_cd_m2)
        .enumerate()
    {
        if from_fabric.flags[i] == MapFlag::Valid {
            worst = worst.max((f64::from(*a) / f64::from(*b) - 1.0).abs());
        }
    }
    // No noise here: the two differ by the sensor's quantisation of the exposures the merge
    // adds, at most 0.5 DN in the 15 DN of the dimmest usable group.
    assert!(
        worst < 0.035,
        "worst relative difference to the merge: {worst}"
    );
    println!("fabric map vs merge: worst relative difference {worst:.2e}, {valid} valid groups");
}

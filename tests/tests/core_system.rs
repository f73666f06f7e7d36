//! The whole fabric core (`SkyluxCore`: register file, sensor control, capture path, ray-box
//! unit, wired from the register map) driven by the HPS drivers through the bus traits, with
//! an MT9P031 model on the camera pins and SDRAM models with random back-pressure on both
//! f2sdram ports: configure the sensor, run a 5-exposure sequence, read every frame and
//! descriptor back, and compare the payloads with the golden Bayer model bit for bit, and the
//! sun accumulators' registers with their golden model over the armed exposure.

use skylux_bus::RegisterAccess;
use skylux_hps::fpga::frames::CapturedFrame;
use skylux_hps::fpga::sensor::{I2cTiming, SensorConfig, SensorError};
use skylux_hps::fpga::sequence::ShieldConfig;
use skylux_hps::fpga::{CaptureConfig, ExposureSlot, Fabric};
use skylux_regmap::sun_values::SunConfig;
use skylux_regmap::{sys, VERSION_MINOR};
use skylux_rtl::bayer::golden::{expected_words, BayerConfig, Frame, Phase};
use skylux_rtl::sun::golden::accumulate;
use skylux_sim::core_rig::{sim_core, CoreRigConfig, SharedCore, SimCoreMemory, SimCoreRegisters};
use skylux_sim::mt9p031::{Mt9p031, RampSource, CHIP_VERSION};

const FAST_I2C: I2cTiming = I2cTiming {
    half_period_cycles: 4,
    timeout_cycles: 5_000,
};

const SHIELD: ShieldConfig = ShieldConfig {
    steps: 3,
    step_period_cycles: 40,
    limit_cycles: 2_000_000,
    trigger_pulse_cycles: 4,
};

const WIDTH: u32 = 16;
const HEIGHT: u32 = 8;
/// Frame memory: the ring sits 4 KiB into it, with 4 KiB of guard after it.
const WINDOW_BASE: u64 = 0x3000_1000;

fn sensor_window() -> SensorConfig {
    SensorConfig {
        row_start: 54,
        col_start: 16,
        height: HEIGHT,
        width: WIDTH,
        shutter_width_rows: 3,
        global_gain_code: 0x0010,
        ..SensorConfig::default()
    }
}

fn slots() -> Vec<ExposureSlot> {
    (0..5)
        .map(|i| ExposureSlot {
            shutter_width_rows: 1 + 3 * i,
            shutter_delay: 0,
            gain_code: 8 + i,
        })
        .collect()
}

struct Bench {
    shared: SharedCore,
    fabric: Fabric<SimCoreRegisters>,
    memory: SimCoreMemory,
    capture: CaptureConfig,
}

fn bench(waitrequest_probability: f64, ring_slots: u8) -> Bench {
    bench_sized(waitrequest_probability, ring_slots, WIDTH, HEIGHT)
}

fn bench_sized(waitrequest_probability: f64, ring_slots: u8, width: u32, height: u32) -> Bench {
    let capture = CaptureConfig::fitted(width, height, WINDOW_BASE, ring_slots);
    let memory_bytes = 0x1000 + capture.window_size_bytes as usize + 0x1000;
    let sensor = Mt9p031::new(Box::new(RampSource), 96e6);
    let (shared, regs, memory, _raybox) = sim_core(
        sensor,
        CoreRigConfig::new(memory_bytes, 4096, waitrequest_probability),
    );
    let fabric = Fabric::bring_up(regs).expect("bring-up of the whole core");
    Bench {
        shared,
        fabric,
        memory,
        capture,
    }
}

fn read_frames(b: &mut Bench, n: u8) -> Vec<CapturedFrame> {
    (0..n)
        .map(|slot| {
            b.capture
                .ring
                .read_slot(&mut b.memory, slot)
                .expect("slot readable")
                .unwrap_or_else(|| panic!("slot {slot} holds no frame"))
        })
        .collect()
}

fn wait_frames_written(f: &mut Fabric<SimCoreRegisters>, n: u32) -> u32 {
    let mut written = 0;
    for _ in 0..20_000 {
        written = f.frames_written().unwrap();
        if written >= n {
            break;
        }
    }
    written
}

#[test]
fn the_whole_core_captures_a_five_exposure_sequence_bit_for_bit() {
    let mut b = bench(0.3, 5);
    let f = &mut b.fabric;
    assert_eq!(f.info().version_minor, VERSION_MINOR);

    // The sensor powers up held in reset: it does not answer until RESET_BAR is released.
    f.sensor_bus_setup(FAST_I2C).unwrap();
    match f.sensor_read(0x00) {
        Err(SensorError::Nack { reg: 0 }) => {}
        other => panic!("a sensor in reset answered: {other:?}"),
    }
    assert!(!b.shared.lock().unwrap().log.reset_released);
    f.sensor_reset_release(true).unwrap();
    assert_eq!(f.sensor_configure(&sensor_window()).unwrap(), CHIP_VERSION);
    assert!(b.shared.lock().unwrap().log.reset_released);

    // A black level and a valid range that flag some of the ramp's groups both ways.
    b.capture.grouping.black_level_dn = 5;
    b.capture.grouping.valid_min_dn = 20;
    b.capture.grouping.valid_max_dn = 150;
    f.capture_configure(&b.capture).unwrap();
    f.set_exposures(&slots()).unwrap();
    f.configure_shield(&SHIELD).unwrap();
    // The sun accumulators armed on the third exposure, over part of the frame.
    f.sun_configure(&SUN, SUN_EXPOSURE, true).unwrap();
    let bus = f.bus();
    bus.write_reg(&sys::irq_enable::REG, 0, sys::irq_enable::FRAME_DONE.mask())
        .unwrap();
    let outcome = f.run_sequence(200_000).unwrap();
    assert_eq!(outcome.frames, 5);
    assert_eq!(wait_frames_written(f, 5), 5, "the DMA finished every frame");
    let faults = f.capture_take_faults().unwrap();
    assert!(!faults.any(), "{faults:?}");
    let irq = f.bus().read_reg(&sys::irq_status::REG, 0).unwrap();
    assert_ne!(sys::irq_status::FRAME_DONE.get(irq), 0);
    assert_ne!(sys::irq_status::SEQUENCE_DONE.get(irq), 0);

    let frames = read_frames(&mut b, 5);
    sun_sums_are_the_armed_frames(&mut b.fabric, &frames);
    let rig = b.shared.lock().unwrap();
    assert_eq!(rig.log.frames.len(), 5, "one sensor frame per trigger");
    let mut previous_timestamp = 0;
    for (i, (got, sent)) in frames.iter().zip(&rig.log.frames).enumerate() {
        let d = &got.descriptor;
        assert_eq!(d.frame_number, i as u32, "frame {i}");
        assert_eq!(d.exposure_index, i as u8, "frame {i}");
        assert_eq!(d.flags, 0, "frame {i}: {:?}", got.flag_names());
        assert_eq!(
            (u32::from(d.last_line_pixels), u32::from(d.lines)),
            (WIDTH, HEIGHT)
        );
        assert_eq!(got.checksum_ok(), Some(true), "frame {i}");
        assert!(d.timestamp_cycles > previous_timestamp);
        previous_timestamp = d.timestamp_cycles;
        let golden = expected_words(
            &Frame {
                width: sent.width,
                height: sent.height,
                samples: sent.samples_dn.clone(),
            },
            &BayerConfig {
                phase: Phase::from_register(b.capture.grouping.phase),
                black: 5,
                valid_min: 20,
                valid_max: 150,
                ..BayerConfig::default()
            },
        );
        assert_eq!(
            got.words, golden,
            "frame {i}: payload differs from the golden model"
        );
    }
    hdr_from_words_equals_hdr_from_samples(&frames, &rig.log.frames);

    // Nothing outside the DMA window, the shield closed and within its limit.
    let end = WINDOW_BASE + u64::from(b.capture.window_size_bytes);
    for a in rig.frame_writes() {
        assert!(
            a.write && a.address >= WINDOW_BASE && a.address + a.bytes <= end,
            "{a:?}"
        );
    }
    assert_eq!(rig.log.shield_position, 0);
    assert!(rig.log.shield_open_cycles_max > 0);
    assert!(rig.log.shield_open_cycles_max <= u64::from(SHIELD.limit_cycles));
    assert_eq!(rig.log.triggers, 5);
}

#[test]
fn a_ring_smaller_than_the_sequence_flags_nothing_and_keeps_the_newest() {
    // Three slots for five frames: the ring wraps, slots hold frames 3, 4, 2.
    let mut b = bench(0.0, 3);
    let f = &mut b.fabric;
    f.sensor_bus_setup(FAST_I2C).unwrap();
    f.sensor_reset_release(true).unwrap();
    f.sensor_configure(&sensor_window()).unwrap();
    f.capture_configure(&b.capture).unwrap();
    f.set_exposures(&slots()).unwrap();
    f.configure_shield(&SHIELD).unwrap();
    f.run_sequence(200_000).unwrap();
    assert_eq!(wait_frames_written(f, 5), 5);
    let frames = read_frames(&mut b, 3);
    for c in &frames {
        assert_eq!(c.descriptor.flags, 0, "{:?}", c.flag_names());
        assert_eq!(c.checksum_ok(), Some(true));
    }
    let numbers: Vec<u32> = frames.iter().map(|c| c.descriptor.frame_number).collect();
    assert_eq!(numbers, vec![3, 4, 2]);
}

/// The HDR merge of `frames` taken at 1, 2, 4, ... ms (the `slots()` exposures), unit gain.
fn merge_doubling<F: skylux_hps::hdr::ExposureFrame>(
    frames: &[F],
    device: &skylux_hps::camera::DeviceConfig,
    geometry: &skylux_hps::hdr::GroupGeometry,
) -> skylux_hps::hdr::LuminanceMap {
    let exposures: Vec<_> = frames
        .iter()
        .enumerate()
        .map(|(i, frame)| skylux_hps::hdr::Exposure {
            frame,
            exposure_s: 1e-3 * (1 << i) as f64,
            gain: 1.0,
        })
        .collect();
    skylux_hps::hdr::merge(
        &exposures,
        device,
        skylux_hps::campaign::BayerPattern::GRBG,
        geometry,
    )
    .expect("merge")
}

/// The HDR merge of the fabric's grouped words equals the merge of the raw frames the sensor
/// sent, when the device's black level, valid range and weights are the fabric's.
/// The exposure the sun accumulators are armed on, and their settings: a window of part of
/// the 8 x 4 groups, a threshold in the ramp's range.
const SUN_EXPOSURE: u8 = 2;
const SUN: SunConfig = SunConfig {
    groups_per_line: (WIDTH / 2) as u16,
    threshold_q14: 80 << 14,
    x_min: 1,
    x_max: 6,
    y_min: 1,
    y_max: 3,
};

/// The sums the HPS reads from `sun.*` are the golden model's over the armed exposure's
/// words as the DMA wrote them (equal to the golden grouping: checked below), one frame.
fn sun_sums_are_the_armed_frames(f: &mut Fabric<SimCoreRegisters>, frames: &[CapturedFrame]) {
    let (sums, armed_frames) = f.sun_read().unwrap();
    let expected = accumulate(&SUN, &frames[usize::from(SUN_EXPOSURE)].words);
    assert_eq!(sums, expected, "sun.* against the golden model");
    assert_eq!(armed_frames, 1);
    let in_window = 6 * 3;
    assert!(
        sums.count > 0 && sums.count < in_window,
        "the threshold must split the window's groups: {sums:?}"
    );
    // Another exposure's words would give other sums: the arming picked its frame.
    assert_ne!(
        sums,
        accumulate(&SUN, &frames[usize::from(SUN_EXPOSURE) + 1].words)
    );
}

fn hdr_from_words_equals_hdr_from_samples(
    captured: &[CapturedFrame],
    sent: &[skylux_hps::campaign::RawFrame],
) {
    use skylux_hps::camera::{CameraModel, DeviceConfig};
    use skylux_hps::campaign::Readout;
    use skylux_hps::hdr::{GroupGeometry, GroupedFrame, MapFlag};
    let mut device = DeviceConfig::default();
    device.sensor.black_level_dn = 5.0;
    device.sensor.valid_min_dn = 20.0;
    device.sensor.valid_max_dn = 150.0;
    // The fabric's reset weights, 0x1000, 0x2000, 0x1000 in Q2.14.
    device.response.weights = [0.25, 0.5, 0.25];
    let camera = CameraModel::new(device.clone());
    let readout = Readout {
        col_start: 1288,
        row_start: 968,
        skip: 1,
        bin: 1,
    };
    let geometry = GroupGeometry::new(&camera, &readout, WIDTH as usize, HEIGHT as usize);
    let grouped: Vec<GroupedFrame> = captured
        .iter()
        .map(|c| GroupedFrame {
            width: WIDTH as usize / 2,
            height: HEIGHT as usize / 2,
            words: c.words.clone(),
        })
        .collect();
    let from_words = merge_doubling(&grouped, &device, &geometry);
    let from_samples = merge_doubling(sent, &device, &geometry);
    assert_eq!(from_words.flags, from_samples.flags);
    let valid = from_words
        .flags
        .iter()
        .filter(|f| **f == MapFlag::Valid)
        .count();
    assert!(
        valid > 0 && valid < from_words.flags.len(),
        "the case must hold valid and flagged groups: {valid}"
    );
    for (i, (a, b)) in from_words
        .luminance_cd_m2
        .iter()
        .zip(&from_samples.luminance_cd_m2)
        .enumerate()
    {
        if from_words.flags[i] == MapFlag::Valid {
            assert!(((a / b) - 1.0).abs() < 1e-5, "group {i}: {a} vs {b}");
        }
    }
}

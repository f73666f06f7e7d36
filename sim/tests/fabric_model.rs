//! The behavioural fabric model (`skylux_sim::fabric_model`) through the HPS drivers, block by
//! block: the I2C master's watchdog and refusal, the grouped words (the RTL's golden model),
//! the ring's window checks (`OUT_OF_WINDOW`, `TRUNCATED`), ABORT, and no panic whatever the
//! HPS writes. The daemon-level tests (faults, cross-check with the cycle-accurate core) are
//! in hps/daemon/tests/fabric_model.rs.

use skylux_bus::{RegisterAccess, RegisterBus};
use skylux_hps::fpga::sensor::{I2cTiming, SensorConfig, SensorError};
use skylux_hps::fpga::sequence::{SequenceError, ShieldConfig};
use skylux_hps::fpga::{CaptureConfig, ExposureSlot, Fabric};
use skylux_regmap::descriptor::flag;
use skylux_regmap::{dma, seq, MAP};
use skylux_sim::fabric_model::{fabric_model, FabricModelConfig, HardwareFault, SharedFabric};
use skylux_sim::fabric_model::{ModelMemory, ModelRegisters};
use skylux_sim::mt9p031::{Mt9p031, RampSource};

const I2C: I2cTiming = I2cTiming {
    half_period_cycles: 4,
    timeout_cycles: 5_000,
};
const SHIELD: ShieldConfig = ShieldConfig {
    steps: 3,
    step_period_cycles: 40,
    limit_cycles: 55_000_000,
    trigger_pulse_cycles: 4,
};

/// A 32 x 16 window (skip 1), configured, with one exposure of 2 rows.
fn rig() -> (
    SharedFabric,
    Fabric<ModelRegisters>,
    ModelMemory,
    CaptureConfig,
) {
    let sensor = Mt9p031::new(Box::new(RampSource), 96e6);
    let (shared, regs, memory) = fabric_model(sensor, FabricModelConfig::new(1 << 16));
    let mut f = Fabric::bring_up(regs).unwrap();
    f.sensor_bus_setup(I2C).unwrap();
    f.sensor_reset_release(true).unwrap();
    f.sensor_configure(&SensorConfig {
        row_start: 0,
        col_start: 0,
        width: 32,
        height: 16,
        ..SensorConfig::default()
    })
    .unwrap();
    f.configure_shield(&SHIELD).unwrap();
    f.set_exposures(&[ExposureSlot {
        shutter_width_rows: 2,
        shutter_delay: 0,
        gain_code: 8,
    }])
    .unwrap();
    let ring = CaptureConfig::fitted(32, 16, 0x3000_0000, 2);
    (shared, f, memory, ring)
}

#[test]
fn i2c_watchdog_and_refusal() {
    let (shared, mut f, _, _) = rig();
    shared.lock().unwrap().inject(HardwareFault::SclStuckLow);
    let before = shared.lock().unwrap().now;
    assert!(matches!(
        f.sensor_read(0),
        Err(SensorError::Timeout { reg: 0 })
    ));
    // The watchdog ended it after `timeout_cycles`, not before.
    assert!(shared.lock().unwrap().now - before >= 5_000);
    shared.lock().unwrap().clear_faults();
    assert_eq!(f.sensor_read(0).unwrap(), 0x1801);
    // The sequencer owns the master while it runs: an HPS transaction is refused.
    f.bus()
        .strobe(&seq::ctrl::REG, 0, &seq::ctrl::START)
        .unwrap();
    assert!(matches!(
        f.sensor_read(0),
        Err(SensorError::Refused { reg: 0 })
    ));
    f.bus()
        .strobe(&seq::ctrl::REG, 0, &seq::ctrl::ABORT)
        .unwrap();
}

#[test]
fn grouped_words_are_the_golden_models_and_raw_the_samples() {
    for raw in [false, true] {
        let (shared, mut f, mut memory, mut ring) = rig();
        ring.grouping.raw = raw;
        let stride = ring.slot_bytes_needed() as u32;
        ring.ring.slot_stride_bytes = stride;
        ring.window_size_bytes = 2 * stride;
        f.capture_configure(&ring).unwrap();
        f.run_sequence(1_000_000).unwrap();
        // The last bursts and the descriptor may follow the shield's closing.
        for _ in 0..100_000 {
            if f.frames_written().unwrap() >= 1 {
                break;
            }
        }
        let got = ring.ring.read_slot(&mut memory, 0).unwrap().unwrap();
        assert!(got.is_good(), "{:?}", got.descriptor);
        let m = shared.lock().unwrap();
        let sent = &m.log.frames[0];
        let frame = skylux_rtl::bayer::golden::Frame {
            width: sent.width,
            height: sent.height,
            samples: sent.samples_dn.clone(),
        };
        let config = skylux_rtl::bayer::golden::BayerConfig {
            raw,
            ..Default::default()
        };
        assert_eq!(
            got.words,
            skylux_rtl::bayer::golden::expected_words(&frame, &config)
        );
        assert_eq!(got.descriptor.raw, raw);
        assert_eq!(
            (got.descriptor.last_line_pixels, got.descriptor.lines),
            (32, 16)
        );
    }
}

#[test]
fn ring_window_checks_truncation_and_abort() {
    let (shared, mut f, mut memory, ring) = rig();
    f.capture_configure(&ring).unwrap();
    // A window one byte short of the second slot: the first frame lands, then the ring
    // reaches a slot outside the window: nothing written, OUT_OF_WINDOW, no count.
    f.bus()
        .write_reg(&dma::window_size::REG, 0, ring.window_size_bytes - 8)
        .unwrap();
    f.run_sequence(1_000_000).unwrap();
    f.run_sequence(1_000_000).unwrap();
    for _ in 0..1000 {
        f.frames_written().unwrap();
    }
    assert_eq!(f.frames_written().unwrap(), 1);
    let faults = f.capture_take_faults().unwrap();
    assert!(faults.dma_out_of_window, "{faults:?}");
    assert!(ring.ring.read_slot(&mut memory, 1).unwrap().is_none());
    // A stride one beat short of a frame: the payload is cut at the slot's end.
    let mut small = ring;
    small.ring.slot_stride_bytes -= 8;
    f.bus()
        .write_reg(&dma::slot_stride::REG, 0, small.ring.slot_stride_bytes)
        .unwrap();
    f.bus()
        .write_reg(&dma::window_size::REG, 0, ring.window_size_bytes)
        .unwrap();
    f.bus()
        .strobe(&dma::ctrl::REG, 0, &dma::ctrl::RESET)
        .unwrap();
    f.run_sequence(1_000_000).unwrap();
    for _ in 0..100_000 {
        if f.frames_written().unwrap() >= 2 {
            break;
        }
    }
    let got = small.ring.read_slot(&mut memory, 0).unwrap().unwrap();
    assert_ne!(got.descriptor.flags & flag::TRUNCATED, 0);
    assert_eq!(got.checksum_ok(), None);
    // ABORT closes the shield and ends the sequence as ABORTED.
    f.set_exposures(&[ExposureSlot {
        shutter_width_rows: 50_000,
        shutter_delay: 0,
        gain_code: 8,
    }])
    .unwrap();
    f.bus()
        .strobe(&seq::ctrl::REG, 0, &seq::ctrl::START)
        .unwrap();
    f.bus()
        .strobe(&seq::ctrl::REG, 0, &seq::ctrl::ABORT)
        .unwrap();
    assert!(matches!(
        f.run_sequence(1_000_000),
        Err(SequenceError::Refused) | Err(SequenceError::Aborted { .. })
    ));
    let status = f.bus().read_reg(&seq::status::REG, 0).unwrap();
    assert_eq!(seq::status::SHIELD_OPEN.get(status), 0);
    assert_eq!(shared.lock().unwrap().log.stuck_events, 0);
}

#[test]
fn no_register_value_panics_the_model() {
    let (shared, mut f, _, _) = rig();
    let bus = f.bus();
    let mut x = 0x2545_F491_u32;
    for block in MAP {
        for reg in block.registers {
            for i in 0..reg.count {
                let Some(o) = reg.offset_of(i) else { continue };
                for v in [0, u32::MAX, x] {
                    bus.write32(o, v).unwrap();
                    bus.read32(o).unwrap();
                    x ^= x << 13;
                    x ^= x >> 17;
                    x ^= x << 5;
                }
            }
        }
    }
    // Unmapped offsets and whatever the blocks now hold: still answers.
    assert_eq!(
        bus.read32(0x0FF0).unwrap(),
        skylux_regmap::UNMAPPED_READ_VALUE
    );
    let m = shared.lock().unwrap();
    assert_eq!(m.log.stuck_events, 0);
}

#[test]
fn a_failed_exposure_write_closes_the_shield_and_is_flagged() {
    let (shared, mut f, _, ring) = rig();
    f.capture_configure(&ring).unwrap();
    // Global_Gain (0x35), the sequencer's fourth write per exposure, is not acknowledged.
    shared
        .lock()
        .unwrap()
        .inject(HardwareFault::NackRegister(0x35));
    match f.run_sequence(1_000_000) {
        Err(SequenceError::I2c {
            frames: 0,
            i2c_status,
        }) => {
            assert_ne!(skylux_regmap::i2c::status::NACK.get(i2c_status), 0)
        }
        other => panic!("{other:?}"),
    }
    let status = f.bus().read_reg(&seq::status::REG, 0).unwrap();
    assert_eq!(seq::status::SHIELD_OPEN.get(status), 0);
    assert!(shared.lock().unwrap().log.frames.is_empty());
}

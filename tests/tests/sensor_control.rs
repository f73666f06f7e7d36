//! The HPS sensor driver on the sensor-control RTL (register file, I2C master, exposure
//! sequencer) with a cycle-level MT9P031 on its two-wire bus: configuration with read-back,
//! a 5-exposure sequence with its tags and shield, and every injected fault flagged and
//! survived.

use skylux_bus::RegisterAccess;
use skylux_hps::fpga::sensor::{reg, I2cTiming, PllConfig, SensorConfig, SensorError};
use skylux_hps::fpga::sequence::{SequenceError, ShieldConfig};
use skylux_hps::fpga::{ExposureSlot, Fabric};
use skylux_regmap::{i2c, seq};
use skylux_sim::mt9p031::registers::{addr, Registers};
use skylux_sim::mt9p031::rig::SensorRig;
use skylux_sim::mt9p031::{I2cFault, Mt9p031, RampSource, CHIP_VERSION};

/// Fast SCL for simulation: 4 clocks per half period.
const FAST_I2C: I2cTiming = I2cTiming {
    half_period_cycles: 4,
    timeout_cycles: 5_000,
};

fn fabric() -> Fabric<SensorRig> {
    let sensor = Mt9p031::new(Box::new(RampSource), 96e6);
    let mut f = Fabric::bring_up(SensorRig::new(sensor)).expect("bring-up");
    f.sensor_bus_setup(FAST_I2C).unwrap();
    f
}

/// A small snapshot window so that frames are short in simulation.
fn small_window() -> SensorConfig {
    SensorConfig {
        row_start: 54,
        col_start: 16,
        height: 4,
        width: 8,
        shutter_width_rows: 3,
        global_gain_code: 0x0010,
        mirror_column: true,
        ..SensorConfig::default()
    }
}

#[test]
fn driver_configures_the_sensor_through_the_i2c_master_and_reads_the_chip_version() {
    let mut f = fabric();
    let mut config = small_window();
    config.pll = Some(PllConfig { m: 24, n: 2, p1: 1 });
    let version = f.sensor_configure(&config).unwrap();
    assert_eq!(version, CHIP_VERSION);
    let rig = f.bus();
    // The sensor model holds what the driver wrote, received bit by bit over SCL/SDA.
    let r = &rig.sensor.registers;
    assert_eq!(r.read(addr::ROW_SIZE), 3);
    assert_eq!(r.read(addr::COLUMN_SIZE), 7);
    assert_eq!(r.read(addr::GLOBAL_GAIN), 0x0010);
    assert_eq!(
        r.read(addr::RED_GAIN),
        0x0010,
        "Global_Gain writes the colour gains"
    );
    assert_eq!(r.read(addr::PLL_CONFIG_1), (24 << 8) | 1);
    assert_eq!(r.read(addr::PLL_CONTROL), 0x0053);
    assert!(r.snapshot_mode() && r.mirror_column() && !r.mirror_row());
    assert_eq!(r.shutter_width_rows(), 3);
    let stats = rig.sensor.i2c.stats;
    // The configuration's writes, the soft reset (2) and the PLL (4); Chip_Version and a
    // read-back of every configuration and PLL register; a read is START, repeated START, STOP.
    let n = config.register_writes().len() as u32;
    assert_eq!(stats.register_writes, n + 2 + 4, "{stats:?}");
    assert_eq!(stats.register_reads, 1 + n + 3, "{stats:?}");
    assert_eq!(stats.stops, stats.register_writes + stats.register_reads);
    assert_eq!(
        stats.starts,
        stats.register_writes + 2 * stats.register_reads
    );
    // The PLL wait is timed by the fabric's counter: at least 1 ms at 100 MHz passed.
    assert!(rig.cycles() > 100_000, "{} cycles", rig.cycles());
    // An out-of-range setting is refused by name before anything is written.
    let writes = rig.sensor.i2c.stats.register_writes;
    let bad = SensorConfig {
        row_start: 55,
        ..small_window()
    };
    match f.sensor_configure(&bad) {
        Err(SensorError::OutOfRange { field, .. }) => assert_eq!(field, "row_start"),
        other => panic!("{other:?}"),
    }
    assert_eq!(f.bus().sensor.i2c.stats.register_writes, writes);
}

fn slots() -> Vec<ExposureSlot> {
    (0..5)
        .map(|i| ExposureSlot {
            shutter_width_rows: 1 + 2 * i,
            shutter_delay: i,
            gain_code: 8 + 8 * i,
        })
        .collect()
}

const SHIELD: ShieldConfig = ShieldConfig {
    steps: 3,
    step_period_cycles: 40,
    limit_cycles: 1_000_000,
    trigger_pulse_cycles: 4,
};

#[test]
fn five_exposure_sequence_exposes_tags_and_closes_the_shield() {
    let mut f = fabric();
    f.sensor_configure(&small_window()).unwrap();
    let slots = slots();
    f.set_exposures(&slots).unwrap();
    f.configure_shield(&SHIELD).unwrap();
    let outcome = f.run_sequence(100_000).unwrap();
    assert_eq!(outcome.frames, 5);
    assert_eq!(outcome.first_frame_number, 0);
    assert_eq!(seq::status::BUSY.get(outcome.status), 0);
    let rig = f.bus();
    let log = &rig.log;
    assert_eq!(
        log.sensor_frames.len(),
        5,
        "the sensor produced one frame per trigger"
    );
    for (i, (frame, slot)) in log.sensor_frames.iter().zip(&slots).enumerate() {
        assert_eq!(
            frame.shutter_width_rows, slot.shutter_width_rows,
            "frame {i}"
        );
        assert_eq!(
            frame.gain,
            Registers::gain_of_code(slot.gain_code as u16),
            "frame {i}"
        );
        assert!(frame.mirror_column);
    }
    // Longer shutter widths expose longer (the §1.5 formula through the model).
    assert!(log
        .sensor_frames
        .windows(2)
        .all(|w| w[1].exposure_pixclk > w[0].exposure_pixclk));
    assert_eq!(log.tags.len(), 5);
    for (i, tag) in log.tags.iter().enumerate() {
        assert_eq!(tag.exposure_index, i as u32);
        assert_eq!(tag.frame_number, i as u32);
        // The timestamp is the counter at the clock edge that raised TRIGGER: the rig's
        // counter is the cycle count before that edge.
        assert_eq!(tag.timestamp_cycles + 1, tag.trigger_cycle, "tag {i}");
        assert!(tag.frame_valid_cycle > tag.trigger_cycle);
    }
    // The shield opened fully, closed again, and stayed within its limit.
    assert_eq!(log.shield_max_position, SHIELD.steps as i64);
    assert_eq!(log.shield_position, 0);
    assert!(log.shield_open_cycles_max <= u64::from(SHIELD.limit_cycles));
    assert!(log.shield_open_cycles_max > 0);
    let frame_number = f.bus().read_reg(&seq::frame_number::REG, 0).unwrap();
    assert_eq!(frame_number, 5);
}

#[test]
fn every_injected_i2c_fault_ends_in_a_flagged_status_bit_and_is_survived() {
    let mut f = fabric();
    let cases = [
        (I2cFault::Absent, i2c::status::NACK),
        (I2cFault::NackRegister, i2c::status::NACK),
        (I2cFault::SdaStuckLow, i2c::status::BUS_STUCK),
        (I2cFault::SclStuckLow, i2c::status::TIMEOUT),
    ];
    for (fault, flag) in cases {
        f.bus().sensor.i2c.fault = fault;
        let err = f.sensor_read(reg::CHIP_VERSION).unwrap_err();
        let expected = match fault {
            I2cFault::SdaStuckLow => matches!(err, SensorError::BusStuck { .. }),
            I2cFault::SclStuckLow => matches!(err, SensorError::Timeout { .. }),
            _ => matches!(err, SensorError::Nack { .. }),
        };
        assert!(expected, "{fault:?}: {err}");
        let status = f.bus().read_reg(&i2c::status::REG, 0).unwrap();
        assert_ne!(flag.get(status), 0, "{fault:?}: status {status:#x}");
        assert_eq!(i2c::status::BUSY.get(status), 0, "{fault:?}: still busy");
        // The fault removed, the next transaction works.
        f.bus().sensor.i2c.fault = I2cFault::None;
        assert_eq!(
            f.sensor_read(reg::CHIP_VERSION).unwrap(),
            CHIP_VERSION,
            "after {fault:?}"
        );
    }
    // With clock stretching the transactions still complete.
    f.bus().sensor.i2c.stretch_cycles = 25;
    f.sensor_write(reg::SHUTTER_DELAY, 0x0123).unwrap();
    assert_eq!(f.sensor_read(reg::SHUTTER_DELAY).unwrap(), 0x0123);
}

#[test]
fn a_fault_during_a_sequence_closes_the_shield_and_is_flagged() {
    let mut f = fabric();
    f.sensor_configure(&small_window()).unwrap();
    f.set_exposures(&slots()).unwrap();
    f.configure_shield(&SHIELD).unwrap();
    f.bus().sensor.i2c.fault = I2cFault::NackRegister;
    match f.run_sequence(100_000) {
        Err(SequenceError::I2c { frames, i2c_status }) => {
            assert_eq!(frames, 0);
            assert_ne!(i2c::status::NACK.get(i2c_status), 0);
        }
        other => panic!("{other:?}"),
    }
    let status = f.bus().read_reg(&seq::status::REG, 0).unwrap();
    assert_ne!(seq::status::I2C_ERROR.get(status), 0);
    assert_eq!(seq::status::SHIELD_OPEN.get(status), 0);
    assert_eq!(f.bus().log.shield_position, 0);
}

#[test]
fn a_sensor_that_never_delivers_a_frame_hits_the_shield_limit() {
    let mut f = fabric();
    // Not in snapshot mode: the sensor ignores TRIGGER, so FRAME_VALID never comes.
    let config = SensorConfig {
        snapshot: false,
        ..small_window()
    };
    f.sensor_configure(&config).unwrap();
    f.set_exposures(&slots()).unwrap();
    let limit = 20_000;
    f.configure_shield(&ShieldConfig {
        limit_cycles: limit,
        ..SHIELD
    })
    .unwrap();
    match f.run_sequence(100_000) {
        Err(SequenceError::ShieldLimit { frames }) => assert_eq!(frames, 1),
        other => panic!("{other:?}"),
    }
    let log = &f.bus().log;
    assert_eq!(log.shield_position, 0);
    assert!(
        log.shield_open_cycles_max <= u64::from(limit),
        "open {} cycles, limit {limit}",
        log.shield_open_cycles_max
    );
    // Close to the limit, not far below: the hardware used the budget before closing.
    assert!(
        log.shield_open_cycles_max > u64::from(limit) - 4 * u64::from(SHIELD.step_period_cycles)
    );
    // Software cannot raise the limit above the ceiling.
    let err = f
        .configure_shield(&ShieldConfig {
            limit_cycles: seq::shield_limit::CYCLES.reset + 1,
            ..SHIELD
        })
        .unwrap_err();
    assert!(matches!(
        err,
        SequenceError::OutOfRange {
            field: "limit_cycles",
            ..
        }
    ));
}

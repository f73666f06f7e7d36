//! The sensor-control top's Verilog (exported from a fresh instance) against its rust-hdl
//! simulation: a trace of HPS register transactions (a write, a read, a NACK from an absent
//! sensor) against the MT9P031 model on the open-drain bus, then a 1-exposure sequence with
//! the shield and a forced limit, replayed in Icarus; plus lint, structural check and the
//! Cyclone V resources of the three blocks.

use rust_hdl::prelude::*;
use skylux_bitstream::xcheck::{self, Tool};
use skylux_rtl::drive::Driver;
use skylux_rtl::i2c::I2cMaster;
use skylux_rtl::sequencer::{ExposureSequencer, SensorControl};
use skylux_sim::mt9p031::registers::addr;
use skylux_sim::mt9p031::{I2cFault, Mt9p031, RampSource, CHIP_VERSION};

fn clock(d: &mut SensorControl) -> &mut Signal<In, Clock> {
    &mut d.clock
}

struct Bench {
    d: Driver<SensorControl>,
    sensor: Mt9p031,
    cycles: u64,
    scl: bool,
    sda: bool,
    fv: bool,
}

impl Bench {
    fn cycle(&mut self) {
        let c = &mut self.d.dut;
        c.time_cycles.next = (0x1_0000_0000 + self.cycles).into();
        c.scl_in.next = self.scl;
        c.sda_in.next = self.sda;
        c.frame_valid.next = self.fv;
        self.d.cycle(clock).unwrap();
        self.cycles += 1;
        let c = &self.d.dut;
        let (scl, sda) = self.sensor.step_i2c(c.scl_low.val(), c.sda_low.val());
        let bus = self.sensor.tick_pixclk(c.trigger.val());
        (self.scl, self.sda, self.fv) = (scl, sda, bus.timing.frame_valid);
    }

    /// One HPS transaction; returns (read data, nack) once done.
    fn transaction(&mut self, read: bool, reg: u8, data: u16) -> (u16, bool) {
        let c = &mut self.d.dut;
        c.i2c_ctrl_read.next = read;
        c.i2c_reg_addr_addr.next = u64::from(reg).into();
        c.i2c_write_data_data.next = u64::from(data).into();
        c.i2c_ctrl_start.next = true;
        self.cycle();
        self.d.dut.i2c_ctrl_start.next = false;
        let mut nack = false;
        for _ in 0..5_000 {
            self.cycle();
            nack |= self.d.dut.i2c_status_nack_set.val();
            if self.d.dut.i2c_status_done_set.val() {
                return (self.d.dut.i2c_read_data_data.val().index() as u16, nack);
            }
        }
        let c = &self.d.dut;
        panic!(
            "transaction {read} {reg:#x} did not finish at cycle {}: busy {} scl {} sda {}",
            self.cycles,
            c.i2c_status_busy.val(),
            self.scl,
            self.sda
        );
    }
}

#[test]
fn sensor_control_verilog_equals_rust_hdl() {
    if !xcheck::require(&[Tool::Iverilog, Tool::Vvp, Tool::Yosys, Tool::Verilator]) {
        return;
    }
    let mut d = Driver::new(SensorControl::default());
    d.record();
    let c = &mut d.dut;
    c.i2c_target_addr7.next = 0x5D.into();
    c.i2c_clock_div_half_period.next = 4.into();
    c.i2c_timeout_cycles.next = 3_000.into();
    let mut b = Bench {
        d,
        sensor: Mt9p031::new(Box::new(RampSource), 96e6),
        cycles: 0,
        scl: true,
        sda: true,
        fv: false,
    };
    b.cycle();
    // Configuration port: a small snapshot window, then read the chip version.
    for (reg, value) in [
        (addr::ROW_SIZE, 3),
        (addr::COLUMN_SIZE, 7),
        (addr::READ_MODE_1, 0x4100),
    ] {
        assert_eq!(b.transaction(false, reg, value), (0, false));
    }
    assert_eq!(
        b.transaction(true, addr::CHIP_VERSION, 0),
        (CHIP_VERSION, false)
    );
    b.sensor.i2c.fault = I2cFault::Absent;
    assert!(
        b.transaction(true, addr::CHIP_VERSION, 0).1,
        "absent sensor: NACK"
    );
    b.sensor.i2c.fault = I2cFault::None;
    // A 1-exposure sequence (frames are long: keep the trace short).
    let c = &mut b.d.dut;
    c.seq_count_exposures.next = 1.into();
    c.seq_shield_steps_steps.next = 3.into();
    c.seq_shield_step_period_cycles.next = 6.into();
    c.seq_shield_limit_cycles.next = 200_000.into();
    c.seq_trigger_pulse_cycles.next = 3.into();
    c.seq_exp_shutter_width_rows[0].next = 2.into();
    c.seq_exp_shutter_delay_value[0].next = 5.into();
    c.seq_exp_gain_code[0].next = 9.into();
    c.seq_ctrl_start.next = true;
    b.cycle();
    b.d.dut.seq_ctrl_start.next = false;
    let mut done = false;
    for _ in 0..60_000 {
        b.cycle();
        if b.d.dut.seq_status_done_set.val() {
            done = true;
            break;
        }
    }
    assert!(done, "sequence did not finish");
    assert_eq!(b.d.dut.seq_frame_number_value.val().index(), 1);
    assert_eq!(b.sensor.timing.settings().shutter_width_rows, 2);
    assert_eq!(b.sensor.registers.read(addr::SHUTTER_DELAY), 5);

    let trace = b.d.take_trace();
    let mut fresh = SensorControl::default();
    fresh.connect_all();
    let verilog = generate_verilog(&fresh);
    let report = xcheck::replay("sensor_control_replay", &verilog, &trace).unwrap();
    println!("{}", report.summary());
    assert!(report.steps > 20_000, "trace too short: {}", report.steps);
    assert!(report.is_clean(), "{}", report.summary());

    // A one-bit change of the Verilog's register address for the shutter delay is caught.
    let tampered = verilog.replace("i2c_reg_addr = 32'hc;", "i2c_reg_addr = 32'hd;");
    assert!(
        tampered != verilog,
        "the constant is not where the test expects it"
    );
    let report = xcheck::replay("sensor_control_replay_tampered", &tampered, &trace).unwrap();
    assert!(!report.is_clean(), "tampering not caught");
}

fn fresh_verilog<B: Block + Default>() -> String {
    let mut b = B::default();
    b.connect_all();
    generate_verilog(&b)
}

#[test]
fn sensor_blocks_lint_check_and_synthesise() {
    if !xcheck::require(&[Tool::Yosys, Tool::Verilator]) {
        return;
    }
    for (name, v) in [
        ("i2c_master", fresh_verilog::<I2cMaster>()),
        ("exposure_sequencer", fresh_verilog::<ExposureSequencer>()),
        ("sensor_control", fresh_verilog::<SensorControl>()),
    ] {
        xcheck::lint(name, &v).unwrap_or_else(|e| panic!("{name}: {e}"));
        xcheck::structural_check(name, &v).unwrap_or_else(|e| panic!("{name}: {e}"));
        let r = xcheck::synthesize(name, &v).unwrap_or_else(|e| panic!("{name}: {e}"));
        println!("{name}: {r:?}, ~{} ALMs", r.alm_estimate());
        assert!(r.flip_flops > 0, "{name}: no registers");
    }
}

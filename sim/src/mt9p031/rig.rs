//! The sensor-control RTL with its register file and an MT9P031 on its pins, behind
//! `skylux_bus::RegisterBus`: the backend the HPS sensor driver is tested on.
//!
//! The register file and `SensorControl` run as two direct-drive designs in lockstep on one
//! system clock; each cycle the ports between them are copied before the rising edge. That
//! equals wiring them because every port crossing between the two is driven from flip-flops
//! only (no combinational path from an input of one to an output of the other). The sensor
//! steps once per system clock: one two-wire sample (open drain, wired-AND with pull-ups) and
//! one PIXCLK (PIXCLK runs at the system clock in the rig; exposures in seconds use
//! [`Mt9p031::pixclk_hz`]).

use super::sensor::Mt9p031;
use rust_hdl::prelude::*;
use skylux_bus::{check_access, BusError, RegisterBus};
use skylux_regmap::{LW_BRIDGE_SPAN_BYTES, READ_LATENCY_CYCLES};
use skylux_rtl::drive::{DriveError, Driver};
use skylux_rtl::sequencer::SensorControl;
use skylux_rtl::RegisterFile;

/// Sensor pins as seen in the last cycle.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct PinState {
    pub scl: bool,
    pub sda: bool,
    pub trigger: bool,
    pub frame_valid: bool,
    pub shield_step: bool,
    pub shield_dir: bool,
    pub shield_enable: bool,
}

/// Per-frame tags, as the capture block would latch them at FRAME_VALID's rise.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct FrameTag {
    pub exposure_index: u32,
    pub frame_number: u32,
    pub timestamp_cycles: u64,
    /// System-clock cycle of the trigger's rising edge, and of FRAME_VALID's rise.
    pub trigger_cycle: u64,
    pub frame_valid_cycle: u64,
}

/// What the rig observed on the pins, for tests.
#[derive(Clone, Debug, Default)]
pub struct PinLog {
    /// Cycles with the shield away from closed (counted from the step pulses).
    pub shield_open_cycles_total: u64,
    /// Longest stretch of consecutive shield-open cycles.
    pub shield_open_cycles_max: u64,
    pub shield_position: i64,
    pub shield_max_position: i64,
    pub tags: Vec<FrameTag>,
    pub trigger_cycles: Vec<u64>,
    /// The sensor's settings of every frame it produced.
    pub sensor_frames: Vec<super::frame::FrameSettings>,
}

/// The rig.
pub struct SensorRig {
    pub regs: Driver<RegisterFile>,
    pub control: Driver<SensorControl>,
    pub sensor: Mt9p031,
    /// An external trigger pin level for the sequencer.
    pub ext_trigger: bool,
    pub pins: PinState,
    pub log: PinLog,
    cycles: u64,
    open_run: u64,
}

fn rf_clock(d: &mut RegisterFile) -> &mut Signal<In, Clock> {
    &mut d.clock
}
fn sc_clock(d: &mut SensorControl) -> &mut Signal<In, Clock> {
    &mut d.clock
}

impl SensorRig {
    pub fn new(sensor: Mt9p031) -> Self {
        let mut regs = Driver::new(RegisterFile::default());
        let d = &mut regs.dut;
        d.avs_read.next = false;
        d.avs_write.next = false;
        d.avs_byteenable.next = 0xF.into();
        let control = Driver::new(SensorControl::default());
        let mut rig = Self {
            regs,
            control,
            sensor,
            ext_trigger: false,
            pins: PinState {
                scl: true,
                sda: true,
                ..Default::default()
            },
            log: PinLog::default(),
            cycles: 0,
            open_run: 0,
        };
        rig.exchange();
        rig
    }

    /// System-clock cycles run so far.
    pub fn cycles(&self) -> u64 {
        self.cycles
    }

    /// Copies the ports between the register file and sensor control (values after the last
    /// settle).
    fn exchange(&mut self) {
        let (r, c) = (&mut self.regs.dut, &mut self.control.dut);
        macro_rules! to_control {
            ($($p:ident),*) => { $( c.$p.next = r.$p.val(); )* };
        }
        macro_rules! to_regs {
            ($($p:ident),*) => { $( r.$p.next = c.$p.val(); )* };
        }
        to_control!(
            i2c_ctrl_start,
            i2c_ctrl_read,
            i2c_target_addr7,
            i2c_reg_addr_addr,
            i2c_write_data_data,
            i2c_clock_div_half_period,
            i2c_timeout_cycles,
            seq_ctrl_start,
            seq_ctrl_abort,
            seq_ctrl_ext_trigger,
            seq_count_exposures,
            seq_shield_limit_cycles,
            seq_shield_steps_steps,
            seq_shield_step_period_cycles,
            seq_trigger_pulse_cycles
        );
        for i in 0..8 {
            c.seq_exp_shutter_width_rows[i].next = r.seq_exp_shutter_width_rows[i].val();
            c.seq_exp_shutter_delay_value[i].next = r.seq_exp_shutter_delay_value[i].val();
            c.seq_exp_gain_code[i].next = r.seq_exp_gain_code[i].val();
        }
        to_regs!(
            i2c_read_data_data,
            i2c_status_busy,
            i2c_status_done_set,
            i2c_status_nack_set,
            i2c_status_timeout_set,
            i2c_status_bus_stuck_set,
            i2c_status_refused_set,
            seq_status_busy,
            seq_status_index,
            seq_status_shield_open,
            seq_status_done_set,
            seq_status_shield_limit_hit_set,
            seq_status_i2c_error_set,
            seq_status_refused_set,
            seq_status_aborted_set,
            seq_frame_number_value
        );
        r.sys_time_lo_cycles.next = (self.cycles & 0xFFFF_FFFF).into();
        r.sys_time_hi_cycles.next = (self.cycles >> 32).into();
        c.time_cycles.next = self.cycles.into();
        c.ext_trigger.next = self.ext_trigger;
        c.frame_valid.next = self.pins.frame_valid;
        c.scl_in.next = self.pins.scl;
        c.sda_in.next = self.pins.sda;
    }

    /// One system-clock cycle of the whole rig.
    pub fn cycle(&mut self) -> Result<(), DriveError> {
        self.exchange();
        self.regs.cycle(rf_clock)?;
        self.control.cycle(sc_clock)?;
        self.cycles += 1;
        let c = &self.control.dut;
        let (scl_low, sda_low, trigger) = (c.scl_low.val(), c.sda_low.val(), c.trigger.val());
        let (step, dir, enable) = (
            c.shield_step.val(),
            c.shield_dir.val(),
            c.shield_enable.val(),
        );
        let (scl, sda) = self.sensor.step_i2c(scl_low, sda_low);
        let bus = self.sensor.tick_pixclk(trigger);
        if trigger && !self.pins.trigger {
            self.log.trigger_cycles.push(self.cycles);
        }
        if bus.timing.frame_start {
            self.log.sensor_frames.push(*self.sensor.timing.settings());
        }
        if bus.timing.frame_valid && !self.pins.frame_valid {
            let c = &self.control.dut;
            self.log.tags.push(FrameTag {
                exposure_index: c.tag_exposure_index.val().index() as u32,
                frame_number: c.tag_frame_number.val().to_u64() as u32,
                timestamp_cycles: c.tag_timestamp.val().to_u64(),
                trigger_cycle: self.log.trigger_cycles.last().copied().unwrap_or(0),
                frame_valid_cycle: self.cycles,
            });
        }
        // The stepper driver moves on the step pulse's rising edge.
        if step && !self.pins.shield_step && enable {
            self.log.shield_position += if dir { 1 } else { -1 };
            self.log.shield_max_position =
                self.log.shield_max_position.max(self.log.shield_position);
        }
        if self.log.shield_position != 0 {
            self.log.shield_open_cycles_total += 1;
            self.open_run += 1;
            self.log.shield_open_cycles_max = self.log.shield_open_cycles_max.max(self.open_run);
        } else {
            self.open_run = 0;
        }
        self.pins = PinState {
            scl,
            sda,
            trigger,
            frame_valid: bus.timing.frame_valid,
            shield_step: step,
            shield_dir: dir,
            shield_enable: enable,
        };
        Ok(())
    }

    /// Runs `n` cycles.
    pub fn run(&mut self, n: u64) -> Result<(), DriveError> {
        for _ in 0..n {
            self.cycle()?;
        }
        Ok(())
    }

    fn write_word(&mut self, word_address: u32, data: u32) -> Result<(), DriveError> {
        let d = &mut self.regs.dut;
        d.avs_address.next = u64::from(word_address).into();
        d.avs_writedata.next = u64::from(data).into();
        d.avs_write.next = true;
        self.cycle()?;
        self.regs.dut.avs_write.next = false;
        Ok(())
    }

    fn read_word(&mut self, word_address: u32) -> Result<u32, DriveError> {
        let d = &mut self.regs.dut;
        d.avs_address.next = u64::from(word_address).into();
        d.avs_read.next = true;
        self.cycle()?;
        self.regs.dut.avs_read.next = false;
        self.run(READ_LATENCY_CYCLES as u64 - 1)?;
        self.regs.settle()?;
        let data = self.regs.dut.avs_readdata.val().to_u64() as u32;
        self.cycle()?;
        Ok(data)
    }
}

impl RegisterBus for SensorRig {
    fn read32(&mut self, offset: u32) -> Result<u32, BusError> {
        check_access(offset as u64, 4, LW_BRIDGE_SPAN_BYTES as u64, 4)?;
        self.read_word(offset / 4)
            .map_err(|e| BusError::Simulation(e.to_string()))
    }

    fn write32(&mut self, offset: u32, value: u32) -> Result<(), BusError> {
        check_access(offset as u64, 4, LW_BRIDGE_SPAN_BYTES as u64, 4)?;
        self.write_word(offset / 4, value)
            .map_err(|e| BusError::Simulation(e.to_string()))
    }
}

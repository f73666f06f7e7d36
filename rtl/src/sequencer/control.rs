//! Sensor control: the I2C master shared by the HPS's configuration port and the exposure
//! sequencer.

use super::ExposureSequencer;
use crate::i2c::I2cMaster;
use rust_hdl::prelude::*;

/// The sensor-control top. Ports carry the names of the register-file ports they connect to
/// (`<block>_<register>_<field>`, `_set` for W1C set pulses), so that a whole-core top wires
/// them one to one; the sensor pins and the sequencer's tags are plain ports.
///
/// Configuration port (the HPS's register-level sequence of writes and reads): one register
/// transaction per `i2c_ctrl_start`. While the exposure sequencer owns the master (from its
/// START until its shield is closed) or a transaction is running, a START is refused
/// (`i2c_status_refused_set`) and nothing is sent. `i2c_status_done_set` pulses at the end of
/// the HPS's own transactions only; NACK, timeout and stuck-bus pulses are reported for every
/// transaction, so that they explain a `seq.status.I2C_ERROR`.
#[derive(LogicBlock, Default)]
pub struct SensorControl {
    pub clock: Signal<In, Clock>,
    // --- i2c.* ---
    pub i2c_ctrl_start: Signal<In, Bit>,
    pub i2c_ctrl_read: Signal<In, Bit>,
    pub i2c_target_addr7: Signal<In, Bits<7>>,
    pub i2c_reg_addr_addr: Signal<In, Bits<8>>,
    pub i2c_write_data_data: Signal<In, Bits<16>>,
    pub i2c_clock_div_half_period: Signal<In, Bits<16>>,
    pub i2c_timeout_cycles: Signal<In, Bits<24>>,
    pub i2c_read_data_data: Signal<Out, Bits<16>>,
    pub i2c_status_busy: Signal<Out, Bit>,
    pub i2c_status_done_set: Signal<Out, Bit>,
    pub i2c_status_nack_set: Signal<Out, Bit>,
    pub i2c_status_timeout_set: Signal<Out, Bit>,
    pub i2c_status_bus_stuck_set: Signal<Out, Bit>,
    pub i2c_status_refused_set: Signal<Out, Bit>,
    // --- seq.* ---
    pub seq_ctrl_start: Signal<In, Bit>,
    pub seq_ctrl_abort: Signal<In, Bit>,
    pub seq_ctrl_ext_trigger: Signal<In, Bit>,
    pub seq_count_exposures: Signal<In, Bits<4>>,
    pub seq_shield_limit_cycles: Signal<In, Bits<32>>,
    pub seq_shield_steps_steps: Signal<In, Bits<16>>,
    pub seq_shield_step_period_cycles: Signal<In, Bits<24>>,
    pub seq_trigger_pulse_cycles: Signal<In, Bits<16>>,
    pub seq_exp_shutter_width_rows: [Signal<In, Bits<20>>; 8],
    pub seq_exp_shutter_delay_value: [Signal<In, Bits<13>>; 8],
    pub seq_exp_gain_code: [Signal<In, Bits<16>>; 8],
    pub seq_status_busy: Signal<Out, Bit>,
    pub seq_status_index: Signal<Out, Bits<3>>,
    pub seq_status_shield_open: Signal<Out, Bit>,
    pub seq_status_done_set: Signal<Out, Bit>,
    pub seq_status_shield_limit_hit_set: Signal<Out, Bit>,
    pub seq_status_i2c_error_set: Signal<Out, Bit>,
    pub seq_status_refused_set: Signal<Out, Bit>,
    pub seq_status_aborted_set: Signal<Out, Bit>,
    pub seq_frame_number_value: Signal<Out, Bits<32>>,
    // --- the time base, the sensor and the shield ---
    /// The free-running system-clock counter (`sys.time_*`).
    pub time_cycles: Signal<In, Bits<64>>,
    /// External sequence trigger pin.
    pub ext_trigger: Signal<In, Bit>,
    /// The sensor's FRAME_VALID pin.
    pub frame_valid: Signal<In, Bit>,
    pub scl_in: Signal<In, Bit>,
    pub sda_in: Signal<In, Bit>,
    pub scl_low: Signal<Out, Bit>,
    pub sda_low: Signal<Out, Bit>,
    /// The sensor's TRIGGER pin.
    pub trigger: Signal<Out, Bit>,
    pub tag_exposure_index: Signal<Out, Bits<3>>,
    pub tag_frame_number: Signal<Out, Bits<32>>,
    pub tag_timestamp: Signal<Out, Bits<64>>,
    pub shield_step: Signal<Out, Bit>,
    pub shield_dir: Signal<Out, Bit>,
    pub shield_enable: Signal<Out, Bit>,

    master: I2cMaster,
    sequencer: ExposureSequencer,
    hps_txn: DFF<Bit>,
    refused_r: DFF<Bit>,
}

impl Logic for SensorControl {
    // Match guards are dropped from the Verilog (rust-hdl-notes §6 item 4): never collapse.
    #[allow(clippy::collapsible_match)]
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, hps_txn, refused_r);
        clock!(self, clock, master, sequencer);
        self.refused_r.d.next = false;

        // The master: the sequencer's requests while it owns it, the HPS's otherwise.
        self.master.device.next = self.i2c_target_addr7.val();
        self.master.half_period.next = self.i2c_clock_div_half_period.val();
        self.master.timeout_cycles.next = self.i2c_timeout_cycles.val();
        self.master.scl_in.next = self.scl_in.val();
        self.master.sda_in.next = self.sda_in.val();
        if self.sequencer.i2c_owner.val() {
            self.master.start.next = self.sequencer.i2c_start.val();
            self.master.read.next = false;
            self.master.reg_addr.next = self.sequencer.i2c_reg_addr.val();
            self.master.write_data.next = self.sequencer.i2c_write_data.val();
        } else {
            self.master.start.next = self.i2c_ctrl_start.val() & !self.master.busy.val();
            self.master.read.next = self.i2c_ctrl_read.val();
            self.master.reg_addr.next = self.i2c_reg_addr_addr.val();
            self.master.write_data.next = self.i2c_write_data_data.val();
        }
        // A START in the cycle right after a `done` belongs to the new transaction: the set
        // comes last so that it wins.
        if self.master.done.val() {
            self.hps_txn.d.next = false;
        }
        if self.i2c_ctrl_start.val() {
            if self.sequencer.i2c_owner.val() | self.master.busy.val() {
                self.refused_r.d.next = true;
            } else {
                self.hps_txn.d.next = true;
            }
        }

        self.sequencer.start.next = self.seq_ctrl_start.val();
        self.sequencer.abort_request.next = self.seq_ctrl_abort.val();
        self.sequencer.ext_trigger_enable.next = self.seq_ctrl_ext_trigger.val();
        self.sequencer.ext_trigger.next = self.ext_trigger.val();
        self.sequencer.exposures.next = self.seq_count_exposures.val();
        self.sequencer.shield_limit_cycles.next = self.seq_shield_limit_cycles.val();
        self.sequencer.shield_steps.next = self.seq_shield_steps_steps.val();
        self.sequencer.step_period_cycles.next = self.seq_shield_step_period_cycles.val();
        self.sequencer.trigger_pulse_cycles.next = self.seq_trigger_pulse_cycles.val();
        for i in 0..8 {
            self.sequencer.shutter_width[i].next = self.seq_exp_shutter_width_rows[i].val();
            self.sequencer.shutter_delay[i].next = self.seq_exp_shutter_delay_value[i].val();
            self.sequencer.gain[i].next = self.seq_exp_gain_code[i].val();
        }
        self.sequencer.time_cycles.next = self.time_cycles.val();
        self.sequencer.frame_valid.next = self.frame_valid.val();
        self.sequencer.i2c_busy.next = self.master.busy.val();
        self.sequencer.i2c_done.next = self.master.done.val() & !self.hps_txn.q.val();
        self.sequencer.i2c_error.next =
            (self.master.nack.val() | self.master.timeout.val()) | self.master.bus_stuck.val();

        self.i2c_read_data_data.next = self.master.read_data.val();
        self.i2c_status_busy.next = self.master.busy.val() | self.sequencer.i2c_owner.val();
        self.i2c_status_done_set.next = self.master.done.val() & self.hps_txn.q.val();
        self.i2c_status_nack_set.next = self.master.nack.val();
        self.i2c_status_timeout_set.next = self.master.timeout.val();
        self.i2c_status_bus_stuck_set.next = self.master.bus_stuck.val();
        self.i2c_status_refused_set.next = self.refused_r.q.val();
        self.scl_low.next = self.master.scl_low.val();
        self.sda_low.next = self.master.sda_low.val();

        self.seq_status_busy.next = self.sequencer.busy.val();
        self.seq_status_index.next = self.sequencer.index.val();
        self.seq_status_shield_open.next = self.sequencer.shield_open.val();
        self.seq_status_done_set.next = self.sequencer.done.val();
        self.seq_status_shield_limit_hit_set.next = self.sequencer.shield_limit_hit.val();
        self.seq_status_i2c_error_set.next = self.sequencer.i2c_failed.val();
        self.seq_status_refused_set.next = self.sequencer.refused.val();
        self.seq_status_aborted_set.next = self.sequencer.aborted.val();
        self.seq_frame_number_value.next = self.sequencer.frame_number.val();
        self.trigger.next = self.sequencer.trigger.val();
        self.tag_exposure_index.next = self.sequencer.tag_exposure_index.val();
        self.tag_frame_number.next = self.sequencer.tag_frame_number.val();
        self.tag_timestamp.next = self.sequencer.tag_timestamp.val();
        self.shield_step.next = self.sequencer.shield_step.val();
        self.shield_dir.next = self.sequencer.shield_dir.val();
        self.shield_enable.next = self.sequencer.shield_enable.val();
    }
}

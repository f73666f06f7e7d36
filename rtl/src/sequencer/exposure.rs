//! The exposure sequencer and the lens-shield actuator.

use rust_hdl::prelude::*;
use skylux_regmap::seq;

/// The hardware ceiling of the shield-open time (0.55 s at 100 MHz): `seq.shield_limit` is
/// clamped to it, so software can lower the limit but never raise it. Written as a literal in
/// the kernel (a named constant would not reach the Verilog).
pub const SHIELD_LIMIT_MAX_CYCLES: u64 = 55_000_000;
const _: () = assert!(seq::shield_limit::CYCLES.reset as u64 == SHIELD_LIMIT_MAX_CYCLES);

/// Sensor registers written before each exposure, in this order (hardware-facts.md §1.4):
/// Shutter_Width_Upper, Shutter_Width_Lower, Shutter_Delay, Global_Gain.
pub const EXPOSURE_REGISTERS: [u8; 4] = [0x08, 0x09, 0x0C, 0x35];

#[derive(Copy, Clone, PartialEq, Debug, LogicState)]
enum SeqState {
    Idle,
    Open,
    Write,
    Trigger,
    WaitFrameStart,
    WaitFrameEnd,
    Close,
}

/// Runs one HDR sequence of up to 8 snapshot exposures (`seq.*`; the sensor is in snapshot
/// mode, hardware-facts.md §1.6):
///
/// 1. START (`start` pulse, or a rising edge of `ext_trigger` when `ext_trigger_enable`):
///    refused (`refused` pulse) while busy or when `exposures` is 0 or above 8. The table
///    and the shield settings are read at START and hold for the whole sequence.
/// 2. The shield opens: `shield_dir` 1, `shield_steps` pulses on `shield_step`, one per
///    `step_period_cycles` (high for the first half), `shield_enable` high while busy.
/// 3. Per exposure `i`: four register writes through the I2C master (`i2c_*` client port,
///    [`EXPOSURE_REGISTERS`]: shutter width upper and lower, delay, gain), then a
///    `trigger_pulse_cycles` pulse on `trigger`; the sensor's FRAME_VALID (`frame_valid`,
///    synchronised here) must then rise and fall: the frame has been read out.
/// 4. The shield closes (`shield_dir` 0) back to step 0; `done` pulses.
///
/// **Shield guarantee.** The shield counts as open while its step position is not 0. The
/// block keeps the cost of closing from the current position (`position × period`) and
/// starts closing as soon as `open time + closing cost` reaches the limit (`min(limit,
/// SHIELD_LIMIT_MAX_CYCLES)`), or refuses an opening step that would reach it. Closing from
/// position p ends (p − 1) periods after it starts, so the shield is never open longer than
/// the limit, whatever software writes or fails to write (`shield_limit_hit` pulses).
/// `abort` and a failed register write (`i2c_error` with `i2c_done`; `i2c_failed` pulses)
/// close the shield too. `done` pulses at the end of every sequence that started.
///
/// **Tags (interface to the capture block).** At each trigger, `tag_exposure_index`,
/// `tag_frame_number` (frames triggered since power-up, counting from 0) and
/// `tag_timestamp` (`time_cycles` at that clock edge, the free-running system-clock counter)
/// change together, and then hold until the next trigger. The next trigger comes only after
/// this frame's FRAME_VALID has fallen (seen through the synchroniser), so the capture block
/// can latch the three in the PIXCLK domain at FRAME_VALID's rise without a handshake: they
/// have been stable since before the sensor started the frame.
#[derive(LogicBlock, Default)]
pub struct ExposureSequencer {
    pub clock: Signal<In, Clock>,
    /// `seq.ctrl.START`.
    pub start: Signal<In, Bit>,
    /// `seq.ctrl.ABORT`.
    pub abort_request: Signal<In, Bit>,
    /// `seq.ctrl.EXT_TRIGGER`.
    pub ext_trigger_enable: Signal<In, Bit>,
    /// External trigger pin (asynchronous; synchronised here).
    pub ext_trigger: Signal<In, Bit>,
    /// `seq.count.EXPOSURES`.
    pub exposures: Signal<In, Bits<4>>,
    /// `seq.shield_limit.CYCLES`.
    pub shield_limit_cycles: Signal<In, Bits<32>>,
    /// `seq.shield_steps.STEPS`.
    pub shield_steps: Signal<In, Bits<16>>,
    /// `seq.shield_step_period.CYCLES` (values below 2 act as 2: the step pin needs a high
    /// and a low clock per step).
    pub step_period_cycles: Signal<In, Bits<24>>,
    /// `seq.trigger_pulse.CYCLES` (0 acts as 1).
    pub trigger_pulse_cycles: Signal<In, Bits<16>>,
    /// `seq.exp_shutter_width[i].ROWS`.
    pub shutter_width: [Signal<In, Bits<20>>; 8],
    /// `seq.exp_shutter_delay[i].VALUE`.
    pub shutter_delay: [Signal<In, Bits<13>>; 8],
    /// `seq.exp_gain[i].CODE`.
    pub gain: [Signal<In, Bits<16>>; 8],
    /// The free-running system-clock counter (`sys.time_*`).
    pub time_cycles: Signal<In, Bits<64>>,
    /// The sensor's FRAME_VALID pin (PIXCLK domain; synchronised here).
    pub frame_valid: Signal<In, Bit>,

    /// I2C client: one-cycle request for a register write of `i2c_write_data` at
    /// `i2c_reg_addr`, issued only while the master is not busy.
    pub i2c_start: Signal<Out, Bit>,
    pub i2c_reg_addr: Signal<Out, Bits<8>>,
    pub i2c_write_data: Signal<Out, Bits<16>>,
    /// High from START until the shield is closed and no request of this block is in flight:
    /// the master belongs to the sequencer.
    pub i2c_owner: Signal<Out, Bit>,
    pub i2c_busy: Signal<In, Bit>,
    pub i2c_done: Signal<In, Bit>,
    /// NACK, timeout or stuck bus, with `i2c_done`.
    pub i2c_error: Signal<In, Bit>,

    /// `seq.status.BUSY`.
    pub busy: Signal<Out, Bit>,
    /// `seq.status.INDEX`.
    pub index: Signal<Out, Bits<3>>,
    /// `seq.status.SHIELD_OPEN`.
    pub shield_open: Signal<Out, Bit>,
    /// Pulses for `seq.status.DONE`, `SHIELD_LIMIT_HIT`, `I2C_ERROR`, `REFUSED`, `ABORTED`.
    pub done: Signal<Out, Bit>,
    pub shield_limit_hit: Signal<Out, Bit>,
    pub i2c_failed: Signal<Out, Bit>,
    pub refused: Signal<Out, Bit>,
    pub aborted: Signal<Out, Bit>,
    /// `seq.frame_number.VALUE`.
    pub frame_number: Signal<Out, Bits<32>>,
    /// The sensor's TRIGGER pin.
    pub trigger: Signal<Out, Bit>,
    pub tag_exposure_index: Signal<Out, Bits<3>>,
    pub tag_frame_number: Signal<Out, Bits<32>>,
    pub tag_timestamp: Signal<Out, Bits<64>>,
    /// Stepper driver pins.
    pub shield_step: Signal<Out, Bit>,
    pub shield_dir: Signal<Out, Bit>,
    pub shield_enable: Signal<Out, Bit>,

    state: DFF<SeqState>,
    ext_sync0: DFF<Bit>,
    ext_sync1: DFF<Bit>,
    ext_prev: DFF<Bit>,
    fv_sync0: DFF<Bit>,
    fv_sync1: DFF<Bit>,
    fv_prev: DFF<Bit>,
    count_l: DFF<Bits<4>>,
    limit_l: DFF<Bits<32>>,
    steps_l: DFF<Bits<16>>,
    period_l: DFF<Bits<24>>,
    pulse_l: DFF<Bits<16>>,
    sw_l: [DFF<Bits<20>>; 8],
    sd_l: [DFF<Bits<13>>; 8],
    gain_l: [DFF<Bits<16>>; 8],
    idx: DFF<Bits<3>>,
    write_no: DFF<Bits<2>>,
    requested: DFF<Bit>,
    position: DFF<Bits<16>>,
    step_timer: DFF<Bits<24>>,
    step_pin: DFF<Bit>,
    open_cycles: DFF<Bits<32>>,
    close_cost: DFF<Bits<48>>,
    pulse_timer: DFF<Bits<16>>,
    frames: DFF<Bits<32>>,
    tag_idx: DFF<Bits<3>>,
    tag_frame: DFF<Bits<32>>,
    tag_time: DFF<Bits<64>>,
    done_r: DFF<Bit>,
    limit_r: DFF<Bit>,
    i2c_fail_r: DFF<Bit>,
    refused_r: DFF<Bit>,
    aborted_r: DFF<Bit>,
    i2c_start_r: DFF<Bit>,

    go: Signal<Local, Bit>,
    cur_sw: Signal<Local, Bits<20>>,
    cur_sd: Signal<Local, Bits<13>>,
    cur_gain: Signal<Local, Bits<16>>,
    budget_now: Signal<Local, Bits<48>>,
    budget_next_step: Signal<Local, Bits<48>>,
    limit48: Signal<Local, Bits<48>>,
    period48: Signal<Local, Bits<48>>,
    over_budget: Signal<Local, Bit>,
    step_would_exceed: Signal<Local, Bit>,
    timer_next: Signal<Local, Bits<24>>,
    half_period: Signal<Local, Bits<24>>,
    pulse_next: Signal<Local, Bits<16>>,
    idx_next: Signal<Local, Bits<4>>,
    open_next: Signal<Local, Bits<32>>,
}

impl Logic for ExposureSequencer {
    // Match guards are dropped from the Verilog (rust-hdl-notes §6 item 4): never collapse.
    #[allow(clippy::collapsible_match)]
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            state,
            ext_sync0,
            ext_sync1,
            ext_prev,
            fv_sync0,
            fv_sync1,
            fv_prev,
            count_l,
            limit_l,
            steps_l,
            period_l,
            pulse_l,
            idx,
            write_no,
            requested,
            position,
            step_timer,
            step_pin,
            open_cycles,
            close_cost,
            pulse_timer,
            frames,
            tag_idx,
            tag_frame,
            tag_time,
            done_r,
            limit_r,
            i2c_fail_r,
            refused_r,
            aborted_r,
            i2c_start_r
        );
        for i in 0..8 {
            self.sw_l[i].clock.next = self.clock.val();
            self.sd_l[i].clock.next = self.clock.val();
            self.gain_l[i].clock.next = self.clock.val();
            self.sw_l[i].d.next = self.sw_l[i].q.val();
            self.sd_l[i].d.next = self.sd_l[i].q.val();
            self.gain_l[i].d.next = self.gain_l[i].q.val();
        }
        self.ext_sync0.d.next = self.ext_trigger.val();
        self.ext_sync1.d.next = self.ext_sync0.q.val();
        self.ext_prev.d.next = self.ext_sync1.q.val();
        self.fv_sync0.d.next = self.frame_valid.val();
        self.fv_sync1.d.next = self.fv_sync0.q.val();
        self.fv_prev.d.next = self.fv_sync1.q.val();
        self.done_r.d.next = false;
        self.limit_r.d.next = false;
        self.i2c_fail_r.d.next = false;
        self.refused_r.d.next = false;
        self.aborted_r.d.next = false;
        self.i2c_start_r.d.next = false;

        self.go.next = self.start.val()
            | ((self.ext_trigger_enable.val() & self.ext_sync1.q.val()) & !self.ext_prev.q.val());

        // The current exposure's settings (no dynamic indexing: rust-hdl-notes §6 item 5).
        self.cur_sw.next = self.sw_l[0].q.val();
        self.cur_sd.next = self.sd_l[0].q.val();
        self.cur_gain.next = self.gain_l[0].q.val();
        for i in 0..8 {
            if self.idx.q.val().index() == i {
                self.cur_sw.next = self.sw_l[i].q.val();
                self.cur_sd.next = self.sd_l[i].q.val();
                self.cur_gain.next = self.gain_l[i].q.val();
            }
        }
        self.i2c_reg_addr.next = 0x08.into();
        self.i2c_write_data.next = bit_cast::<16, 4>(self.cur_sw.val().get_bits::<4>(16));
        match self.write_no.q.val().index() {
            0 => {}
            1 => {
                self.i2c_reg_addr.next = 0x09.into();
                self.i2c_write_data.next = self.cur_sw.val().get_bits::<16>(0);
            }
            2 => {
                self.i2c_reg_addr.next = 0x0C.into();
                self.i2c_write_data.next = bit_cast::<16, 13>(self.cur_sd.val());
            }
            _ => {
                self.i2c_reg_addr.next = 0x35.into();
                self.i2c_write_data.next = self.cur_gain.val();
            }
        }

        // Shield budget, in 48 bits so that no sum wraps.
        self.limit48.next = bit_cast::<48, 32>(self.limit_l.q.val());
        self.period48.next = bit_cast::<48, 24>(self.period_l.q.val());
        self.budget_now.next =
            bit_cast::<48, 32>(self.open_cycles.q.val()) + self.close_cost.q.val();
        self.budget_next_step.next = self.budget_now.val() + self.period48.val();
        self.over_budget.next =
            (self.position.q.val() != 0) & (self.budget_now.val() >= self.limit48.val());
        self.step_would_exceed.next = self.budget_next_step.val() >= self.limit48.val();
        self.open_next.next = self.open_cycles.q.val() + 1;
        if self.position.q.val() != 0 {
            self.open_cycles.d.next = self.open_next.val();
        }

        self.timer_next.next = self.step_timer.q.val() + 1;
        self.half_period.next = self.period_l.q.val() >> 1;
        self.pulse_next.next = self.pulse_timer.q.val() + 1;
        self.idx_next.next = bit_cast::<4, 3>(self.idx.q.val()) + 1;
        // The step pin is high for the first half of each step period.
        if self.step_timer.q.val() != 0 {
            if self.timer_next.val() >= self.period_l.q.val() {
                self.step_timer.d.next = 0.into();
                self.step_pin.d.next = false;
            } else {
                self.step_timer.d.next = self.timer_next.val();
                if self.timer_next.val() >= self.half_period.val() {
                    self.step_pin.d.next = false;
                }
            }
        }

        match self.state.q.val() {
            SeqState::Idle => {
                self.step_pin.d.next = false;
                self.step_timer.d.next = 0.into();
                if self.go.val() {
                    if (self.exposures.val() == 0) | (self.exposures.val() > 8) {
                        self.refused_r.d.next = true;
                    } else {
                        self.state.d.next = SeqState::Open;
                        self.count_l.d.next = self.exposures.val();
                        if self.shield_limit_cycles.val() < 55_000_000u64 {
                            self.limit_l.d.next = self.shield_limit_cycles.val();
                        } else {
                            self.limit_l.d.next = 55_000_000u64.into();
                        }
                        self.steps_l.d.next = self.shield_steps.val();
                        if self.step_period_cycles.val() < 2 {
                            self.period_l.d.next = 2.into();
                        } else {
                            self.period_l.d.next = self.step_period_cycles.val();
                        }
                        if self.trigger_pulse_cycles.val() == 0 {
                            self.pulse_l.d.next = 1.into();
                        } else {
                            self.pulse_l.d.next = self.trigger_pulse_cycles.val();
                        }
                        for i in 0..8 {
                            self.sw_l[i].d.next = self.shutter_width[i].val();
                            self.sd_l[i].d.next = self.shutter_delay[i].val();
                            self.gain_l[i].d.next = self.gain[i].val();
                        }
                        self.idx.d.next = 0.into();
                        self.write_no.d.next = 0.into();
                        self.requested.d.next = false;
                        self.open_cycles.d.next = 0.into();
                        self.close_cost.d.next = 0.into();
                    }
                }
            }
            SeqState::Open => {
                if self.step_timer.q.val() == 0 {
                    if self.position.q.val() >= self.steps_l.q.val() {
                        self.state.d.next = SeqState::Write;
                    } else if self.step_would_exceed.val() {
                        self.limit_r.d.next = true;
                        self.state.d.next = SeqState::Close;
                    } else {
                        self.position.d.next = self.position.q.val() + 1;
                        self.close_cost.d.next = self.close_cost.q.val() + self.period48.val();
                        self.step_pin.d.next = true;
                        self.step_timer.d.next = 1.into();
                    }
                }
            }
            SeqState::Write => {
                if !self.requested.q.val() {
                    if !self.i2c_busy.val() {
                        self.i2c_start_r.d.next = true;
                        self.requested.d.next = true;
                    }
                } else if self.i2c_done.val() {
                    self.requested.d.next = false;
                    if self.i2c_error.val() {
                        self.i2c_fail_r.d.next = true;
                        self.state.d.next = SeqState::Close;
                    } else if self.write_no.q.val() == 3 {
                        self.write_no.d.next = 0.into();
                        self.state.d.next = SeqState::Trigger;
                        self.pulse_timer.d.next = 0.into();
                        self.tag_idx.d.next = self.idx.q.val();
                        self.tag_frame.d.next = self.frames.q.val();
                        self.tag_time.d.next = self.time_cycles.val();
                        self.frames.d.next = self.frames.q.val() + 1;
                    } else {
                        self.write_no.d.next = self.write_no.q.val() + 1;
                    }
                }
            }
            SeqState::Trigger => {
                self.pulse_timer.d.next = self.pulse_next.val();
                if self.pulse_next.val() >= self.pulse_l.q.val() {
                    self.state.d.next = SeqState::WaitFrameStart;
                }
            }
            SeqState::WaitFrameStart => {
                if self.fv_sync1.q.val() & !self.fv_prev.q.val() {
                    self.state.d.next = SeqState::WaitFrameEnd;
                }
            }
            SeqState::WaitFrameEnd => {
                if !self.fv_sync1.q.val() & self.fv_prev.q.val() {
                    if self.idx_next.val() >= self.count_l.q.val() {
                        self.state.d.next = SeqState::Close;
                    } else {
                        self.idx.d.next = self.idx.q.val() + 1;
                        self.state.d.next = SeqState::Write;
                    }
                }
            }
            SeqState::Close => {
                // A register write still in flight (abort, budget) completes first.
                if self.i2c_done.val() {
                    self.requested.d.next = false;
                }
                if self.step_timer.q.val() == 0 {
                    if self.position.q.val() != 0 {
                        self.position.d.next = self.position.q.val() - 1;
                        self.close_cost.d.next = self.close_cost.q.val() - self.period48.val();
                        self.step_pin.d.next = true;
                        self.step_timer.d.next = 1.into();
                    } else if !self.requested.q.val() | self.i2c_done.val() {
                        self.requested.d.next = false;
                        self.done_r.d.next = true;
                        self.state.d.next = SeqState::Idle;
                    }
                }
            }
        }
        // Whatever the state: an abort or an exhausted budget closes the shield.
        if (self.state.q.val() != SeqState::Idle) & (self.state.q.val() != SeqState::Close) {
            if self.go.val() {
                self.refused_r.d.next = true;
            }
            if self.abort_request.val() {
                self.aborted_r.d.next = true;
                self.state.d.next = SeqState::Close;
                self.step_timer.d.next = 0.into();
                self.step_pin.d.next = false;
            } else if self.over_budget.val() {
                self.limit_r.d.next = true;
                self.state.d.next = SeqState::Close;
                self.step_timer.d.next = 0.into();
                self.step_pin.d.next = false;
            }
        } else if (self.state.q.val() == SeqState::Close) & self.go.val() {
            self.refused_r.d.next = true;
        }

        self.i2c_start.next = self.i2c_start_r.q.val();
        self.i2c_owner.next = self.state.q.val() != SeqState::Idle;
        self.busy.next = self.state.q.val() != SeqState::Idle;
        self.index.next = self.idx.q.val();
        self.shield_open.next = self.position.q.val() != 0;
        self.done.next = self.done_r.q.val();
        self.shield_limit_hit.next = self.limit_r.q.val();
        self.i2c_failed.next = self.i2c_fail_r.q.val();
        self.refused.next = self.refused_r.q.val();
        self.aborted.next = self.aborted_r.q.val();
        self.frame_number.next = self.frames.q.val();
        self.trigger.next = self.state.q.val() == SeqState::Trigger;
        self.tag_exposure_index.next = self.tag_idx.q.val();
        self.tag_frame_number.next = self.tag_frame.q.val();
        self.tag_timestamp.next = self.tag_time.q.val();
        self.shield_step.next = self.step_pin.q.val();
        self.shield_dir.next =
            (self.state.q.val() != SeqState::Close) & (self.state.q.val() != SeqState::Idle);
        self.shield_enable.next = self.state.q.val() != SeqState::Idle;
    }
}

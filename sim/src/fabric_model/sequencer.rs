//! The exposure sequencer and the lens shield (`seq.*`, `skylux_rtl::sequencer::exposure`),
//! phase by phase instead of clock by clock: START latches the table and the shield settings,
//! the shield opens step by step, each exposure's four register writes go through the I2C
//! master, a TRIGGER pulse starts the sensor's snapshot, FRAME_VALID must rise and fall, then
//! the shield closes. The shield interlock is the RTL's: the limit is clamped to
//! [`SHIELD_LIMIT_MAX_CYCLES`], an opening step that would leave no budget to close is
//! refused, and the shield starts closing as soon as `open time + closing cost` reaches the
//! limit, so it is never open longer than the limit whatever the HPS writes
//! (`skylux_hps::fpga::shield_plan` plans captures around the same ceiling).

use super::i2c::Client;
use super::FabricModel;
use skylux_regmap::{seq, sys};
pub use skylux_rtl::sequencer::{EXPOSURE_REGISTERS, SHIELD_LIMIT_MAX_CYCLES};

/// Synchroniser delay of FRAME_VALID into the system clock (two flip-flops and the edge
/// register of the RTL).
pub const FV_SYNC_CYCLES: u64 = 3;

/// The RTL's states.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub enum SeqState {
    #[default]
    Idle,
    Open,
    Write,
    Trigger,
    WaitFrameStart,
    WaitFrameEnd,
    Close,
}

/// The sequencer's state.
#[derive(Clone, Debug, Default)]
pub struct Sequencer {
    pub state: SeqState,
    count: u32,
    limit: u64,
    steps: u64,
    period: u64,
    pulse: u64,
    shutter_width: [u32; 8],
    shutter_delay: [u32; 8],
    gain: [u32; 8],
    /// Index of the current exposure.
    pub idx: u32,
    write_no: usize,
    /// A register write of this block is on the wire.
    requested: bool,
    /// When the current timed phase (Open, Trigger, Close) ends.
    phase_end: u64,
    /// Opening: the first step's clock, and steps the budget allows.
    open_start: u64,
    steps_allowed: u64,
    /// Closing: its first clock and the position it starts from.
    close_start: u64,
    close_from: u64,
    /// The budget runs out at this clock while the shield is open (None: shield closed).
    deadline: Option<u64>,
    /// Entered WaitFrameStart at this clock (an edge before it is not seen).
    wait_since: u64,
    /// Frames triggered since power-up (`seq.frame_number`).
    pub frames: u32,
    /// Tags for the capture block, latched at each trigger.
    pub tag_index: u32,
    pub tag_frame: u32,
    pub tag_time: u64,
}

impl Sequencer {
    /// The master belongs to the sequencer from START until it is idle again.
    pub fn owns_i2c(&self) -> bool {
        self.state != SeqState::Idle
    }

    /// Shield position in steps at clock `t`.
    pub fn position(&self, t: u64) -> u64 {
        let stepped = |since: u64| {
            if t < since {
                0
            } else {
                (t - since) / self.period.max(1) + 1
            }
        };
        match self.state {
            SeqState::Idle => 0,
            SeqState::Open => stepped(self.open_start).min(self.steps_allowed),
            SeqState::Close => self
                .close_from
                .saturating_sub(stepped(self.close_start + 1)),
            _ => self.steps_allowed,
        }
    }
}

impl FabricModel {
    /// `seq.ctrl.START` (or the external trigger).
    pub(super) fn sequencer_start(&mut self) {
        if self.seq.state != SeqState::Idle {
            self.seq_flag(&seq::status::REFUSED);
            return;
        }
        let count = seq::count::EXPOSURES.get(self.stored(seq::count::REG.offset));
        if count == 0 || count > 8 {
            self.seq_flag(&seq::status::REFUSED);
            return;
        }
        let read = |m: &mut FabricModel, r: &skylux_regmap::Register, i: u32| {
            r.offset_of(i).map(|o| m.stored(o)).unwrap_or(0)
        };
        let s = &mut self.seq;
        s.count = count;
        let limit =
            u64::from(seq::shield_limit::CYCLES.get(self.regs.read(seq::shield_limit::REG.offset)));
        let steps =
            u64::from(seq::shield_steps::STEPS.get(self.regs.read(seq::shield_steps::REG.offset)));
        let period = u64::from(
            seq::shield_step_period::CYCLES
                .get(self.regs.read(seq::shield_step_period::REG.offset)),
        );
        let pulse = u64::from(
            seq::trigger_pulse::CYCLES.get(self.regs.read(seq::trigger_pulse::REG.offset)),
        );
        for i in 0..8u32 {
            let sw = read(self, &seq::exp_shutter_width::REG, i);
            let sd = read(self, &seq::exp_shutter_delay::REG, i);
            let g = read(self, &seq::exp_gain::REG, i);
            let s = &mut self.seq;
            s.shutter_width[i as usize] = seq::exp_shutter_width::ROWS.get(sw);
            s.shutter_delay[i as usize] = seq::exp_shutter_delay::VALUE.get(sd);
            s.gain[i as usize] = seq::exp_gain::CODE.get(g);
        }
        let now = self.now;
        let s = &mut self.seq;
        // The hardware ceiling: software may lower the limit, never raise it.
        s.limit = limit.min(SHIELD_LIMIT_MAX_CYCLES);
        s.steps = steps;
        s.period = period.max(2);
        s.pulse = pulse.max(1);
        s.idx = 0;
        s.write_no = 0;
        s.requested = false;
        s.state = SeqState::Open;
        // Step k (1-based) is refused when `open + closing cost + period` would reach the
        // limit: before it the shield has been open (k − 1) periods and closing costs as much.
        s.open_start = now + 1;
        s.steps_allowed = (1..=s.steps)
            .take_while(|&k| (2 * (k - 1) + 1) * s.period < s.limit)
            .count() as u64;
        s.phase_end = s.open_start + s.steps_allowed * s.period;
        s.deadline = None;
    }

    /// `seq.ctrl.ABORT`.
    pub(super) fn sequencer_abort(&mut self) {
        if !matches!(self.seq.state, SeqState::Idle | SeqState::Close) {
            self.seq_flag(&seq::status::ABORTED);
            self.sequencer_close();
        }
    }

    fn seq_flag(&mut self, f: &skylux_regmap::Field) {
        self.regs.set_bits(seq::status::REG.offset, f.mask());
    }

    /// Starts closing the shield from where it is now.
    fn sequencer_close(&mut self) {
        let now = self.now;
        let p = self.seq.position(now);
        let s = &mut self.seq;
        s.state = SeqState::Close;
        s.close_start = now;
        s.close_from = p;
        s.deadline = None;
        // Position p reaches 0 (p − 1) periods after the first closing step.
        s.phase_end = now + 1 + p * s.period;
        if p > 0 {
            let open = (now + 1 + (p - 1) * s.period).saturating_sub(s.open_start);
            self.log.shield_open_cycles_max = self.log.shield_open_cycles_max.max(open);
        }
    }

    /// The sequencer's next event, given the sensor's time line.
    pub(super) fn sequencer_next_event(&self) -> Option<u64> {
        let s = &self.seq;
        let own = match s.state {
            SeqState::Idle | SeqState::Write => None,
            SeqState::Open | SeqState::Trigger => Some(s.phase_end),
            SeqState::Close => (!s.requested).then_some(s.phase_end),
            SeqState::WaitFrameStart => self
                .timeline
                .rise_at()
                .map(|t| t + FV_SYNC_CYCLES)
                .filter(|&t| t >= s.wait_since),
            SeqState::WaitFrameEnd => self.timeline.fall_at().map(|t| t + FV_SYNC_CYCLES),
        };
        [own, s.deadline].into_iter().flatten().min()
    }

    /// Everything due now.
    pub(super) fn sequencer_events(&mut self) {
        let now = self.now;
        // The budget: whatever the state, an exhausted one closes the shield.
        if let Some(d) = self.seq.deadline {
            if now >= d && !matches!(self.seq.state, SeqState::Idle | SeqState::Close) {
                self.seq_flag(&seq::status::SHIELD_LIMIT_HIT);
                self.sequencer_close();
            }
        }
        match self.seq.state {
            SeqState::Idle => {}
            SeqState::Open => {
                if now >= self.seq.phase_end {
                    if self.seq.steps_allowed < self.seq.steps {
                        self.seq_flag(&seq::status::SHIELD_LIMIT_HIT);
                        self.sequencer_close();
                    } else {
                        let s = &mut self.seq;
                        s.state = SeqState::Write;
                        s.deadline = (s.steps > 0)
                            .then(|| (s.open_start + s.limit).saturating_sub(s.steps * s.period));
                    }
                }
            }
            SeqState::Write => {}
            SeqState::Trigger => {
                if now >= self.seq.phase_end {
                    self.seq.state = SeqState::WaitFrameStart;
                    self.seq.wait_since = now;
                }
            }
            SeqState::WaitFrameStart => {
                if let Some(r) = self.timeline.rise_at() {
                    if r + FV_SYNC_CYCLES <= now && r + FV_SYNC_CYCLES >= self.seq.wait_since {
                        self.seq.state = SeqState::WaitFrameEnd;
                    }
                }
            }
            SeqState::WaitFrameEnd => {
                if self
                    .timeline
                    .fall_at()
                    .is_some_and(|f| f + FV_SYNC_CYCLES <= now)
                {
                    if self.seq.idx + 1 >= self.seq.count {
                        self.sequencer_close();
                    } else {
                        self.seq.idx += 1;
                        self.seq.state = SeqState::Write;
                    }
                }
            }
            SeqState::Close => {
                if now >= self.seq.phase_end && !self.seq.requested {
                    self.seq.state = SeqState::Idle;
                    self.seq_flag(&seq::status::DONE);
                    self.irq(&sys::irq_status::SEQUENCE_DONE);
                }
            }
        }
        // A register write is issued as soon as the master is free.
        if self.seq.state == SeqState::Write && !self.seq.requested {
            let i = self.seq.idx as usize;
            let s = &self.seq;
            let value = match s.write_no {
                0 => s.shutter_width[i] >> 16,
                1 => s.shutter_width[i] & 0xFFFF,
                2 => s.shutter_delay[i],
                _ => s.gain[i],
            } as u16;
            let reg = EXPOSURE_REGISTERS[s.write_no.min(3)];
            if self.i2c_begin(Client::Sequencer, reg, Some(value)) {
                self.seq.requested = true;
            }
        }
    }

    /// The sequencer's register write ended.
    pub(super) fn sequencer_write_done(&mut self, ok: bool) {
        self.seq.requested = false;
        if self.seq.state != SeqState::Write {
            return;
        }
        if !ok {
            self.seq_flag(&seq::status::I2C_ERROR);
            self.sequencer_close();
        } else if self.seq.write_no == 3 {
            let now = self.now;
            let s = &mut self.seq;
            s.write_no = 0;
            s.state = SeqState::Trigger;
            s.tag_index = s.idx;
            s.tag_frame = s.frames;
            s.tag_time = now;
            s.frames = s.frames.wrapping_add(1);
            s.phase_end = now + s.pulse;
            self.log.triggers += 1;
            self.sensor_trigger();
        } else {
            self.seq.write_no += 1;
        }
    }

    pub(super) fn sequencer_inputs(&mut self) {
        let s = &self.seq;
        let status = seq::status::BUSY.word((s.state != SeqState::Idle).into())
            | seq::status::INDEX.word(s.idx & 7)
            | seq::status::SHIELD_OPEN.word((s.position(self.now) != 0).into());
        let frames = s.frames;
        self.regs
            .fabric_inputs
            .insert(seq::status::REG.offset, status);
        self.regs
            .fabric_inputs
            .insert(seq::frame_number::REG.offset, frames);
    }
}

//! Running an HDR exposure sequence on the fabric's sequencer (`seq.*`): shield settings,
//! START, completion and the reason a sequence ended early.

use super::Fabric;
use skylux_bus::{BusError, RegisterAccess, RegisterBus};
use skylux_regmap::seq;

/// Lens-shield actuator settings.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct ShieldConfig {
    /// Stepper steps from closed to open.
    pub steps: u32,
    /// System clocks per step.
    pub step_period_cycles: u32,
    /// Longest shield-open time per sequence; the fabric caps it at its reset value.
    pub limit_cycles: u32,
    /// Width of the sensor trigger pulse.
    pub trigger_pulse_cycles: u32,
}

/// How a sequence ended.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct SequenceOutcome {
    /// Frames triggered by this sequence (`seq.frame_number` before and after).
    pub frames: u32,
    /// Frame number of the sequence's first frame.
    pub first_frame_number: u32,
    /// `seq.status` when the sequence ended.
    pub status: u32,
}

/// Why a sequence was not run or did not complete.
#[derive(Debug, thiserror::Error)]
pub enum SequenceError {
    #[error("register bus: {0}")]
    Bus(#[from] BusError),
    #[error("shield: {field} = {value} is out of range ({allowed})")]
    OutOfRange {
        field: &'static str,
        value: u32,
        allowed: &'static str,
    },
    #[error("the sequencer refused START (busy, or seq.count.EXPOSURES is 0 or above 8)")]
    Refused,
    #[error("the hardware closed the shield at its open-time limit after {frames} frames")]
    ShieldLimit { frames: u32 },
    #[error(
        "a sensor register write failed after {frames} frames (see i2c.status {i2c_status:#x})"
    )]
    I2c { frames: u32, i2c_status: u32 },
    #[error("the sequence was aborted after {frames} frames")]
    Aborted { frames: u32 },
    #[error("the sequence did not finish within {polls} polls")]
    NoCompletion { polls: u64 },
}

impl<B: RegisterBus> Fabric<B> {
    /// Programs the shield and the trigger pulse. Refuses a limit above the hardware ceiling
    /// rather than let the fabric silently lower it.
    pub fn configure_shield(&mut self, shield: &ShieldConfig) -> Result<(), SequenceError> {
        let fields = [
            ("steps", &seq::shield_steps::STEPS, shield.steps, "16 bits"),
            (
                "step_period_cycles",
                &seq::shield_step_period::CYCLES,
                shield.step_period_cycles,
                "2 to 2^24 - 1",
            ),
            (
                "trigger_pulse_cycles",
                &seq::trigger_pulse::CYCLES,
                shield.trigger_pulse_cycles,
                "1 to 65535",
            ),
        ];
        for (field, f, value, allowed) in fields {
            let min = match field {
                "steps" => 0,
                "step_period_cycles" => 2,
                _ => 1,
            };
            if !f.fits(value) || value < min {
                return Err(SequenceError::OutOfRange {
                    field,
                    value,
                    allowed,
                });
            }
        }
        let ceiling = seq::shield_limit::CYCLES.reset;
        if shield.limit_cycles == 0 || shield.limit_cycles > ceiling {
            return Err(SequenceError::OutOfRange {
                field: "limit_cycles",
                value: shield.limit_cycles,
                allowed: "1 to the hardware ceiling seq.shield_limit reset value",
            });
        }
        let bus = self.bus();
        bus.write_reg(
            &seq::shield_steps::REG,
            0,
            seq::shield_steps::STEPS.word(shield.steps),
        )?;
        bus.write_reg(
            &seq::shield_step_period::REG,
            0,
            seq::shield_step_period::CYCLES.word(shield.step_period_cycles),
        )?;
        bus.write_reg(
            &seq::shield_limit::REG,
            0,
            seq::shield_limit::CYCLES.word(shield.limit_cycles),
        )?;
        bus.write_reg(
            &seq::trigger_pulse::REG,
            0,
            seq::trigger_pulse::CYCLES.word(shield.trigger_pulse_cycles),
        )?;
        Ok(())
    }

    /// Starts the programmed sequence (see `set_exposures`) and polls until it ends, at most
    /// `max_polls` status reads.
    pub fn run_sequence(&mut self, max_polls: u64) -> Result<SequenceOutcome, SequenceError> {
        let bus = self.bus();
        let sticky = seq::status::DONE.mask()
            | seq::status::SHIELD_LIMIT_HIT.mask()
            | seq::status::I2C_ERROR.mask()
            | seq::status::REFUSED.mask()
            | seq::status::ABORTED.mask();
        bus.write_reg(&seq::status::REG, 0, sticky)?;
        let first = bus.read_reg(&seq::frame_number::REG, 0)?;
        bus.strobe(&seq::ctrl::REG, 0, &seq::ctrl::START)?;
        for _ in 0..max_polls {
            let status = bus.read_reg(&seq::status::REG, 0)?;
            let set = |f: &skylux_regmap::Field| f.get(status) != 0;
            if set(&seq::status::REFUSED) && !set(&seq::status::BUSY) {
                return Err(SequenceError::Refused);
            }
            if !set(&seq::status::DONE) {
                continue;
            }
            let frames = bus
                .read_reg(&seq::frame_number::REG, 0)?
                .wrapping_sub(first);
            if set(&seq::status::I2C_ERROR) {
                let i2c_status = bus.read_reg(&skylux_regmap::i2c::status::REG, 0)?;
                return Err(SequenceError::I2c { frames, i2c_status });
            }
            if set(&seq::status::SHIELD_LIMIT_HIT) {
                return Err(SequenceError::ShieldLimit { frames });
            }
            if set(&seq::status::ABORTED) {
                return Err(SequenceError::Aborted { frames });
            }
            return Ok(SequenceOutcome {
                frames,
                first_frame_number: first,
                status,
            });
        }
        Err(SequenceError::NoCompletion { polls: max_polls })
    }
}

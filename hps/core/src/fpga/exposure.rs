//! The exposure table of the sequencer (`seq.exp_*`), as the HPS programs it.

use super::Fabric;
use skylux_bus::{BusError, RegisterAccess, RegisterBus};
use skylux_regmap::seq;

/// Exposures one HDR sequence can hold.
pub const MAX_EXPOSURES: usize = seq::exp_shutter_width::REG.count as usize;

/// One exposure of a sequence, in the sensor's register units.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct ExposureSlot {
    /// Shutter width in rows (sensor R0x08/R0x09).
    pub shutter_width_rows: u32,
    /// Shutter delay (sensor R0x0C).
    pub shutter_delay: u32,
    /// Global gain code (sensor R0x35; 8 is unity).
    pub gain_code: u32,
}

impl<B: RegisterBus> Fabric<B> {
    /// Programs the exposure table and the sequence length. Fails without writing anything
    /// if the table is empty or too long, or a value does not fit its field.
    pub fn set_exposures(&mut self, slots: &[ExposureSlot]) -> Result<(), ExposureError> {
        if slots.is_empty() || slots.len() > MAX_EXPOSURES {
            return Err(ExposureError::Count(slots.len()));
        }
        for (i, s) in slots.iter().enumerate() {
            let checks = [
                (
                    "shutter_width_rows",
                    &seq::exp_shutter_width::ROWS,
                    s.shutter_width_rows,
                ),
                (
                    "shutter_delay",
                    &seq::exp_shutter_delay::VALUE,
                    s.shutter_delay,
                ),
                ("gain_code", &seq::exp_gain::CODE, s.gain_code),
            ];
            for (name, field, value) in checks {
                if !field.fits(value) || (name == "shutter_width_rows" && value == 0) {
                    return Err(ExposureError::OutOfRange {
                        index: i,
                        field: name,
                        value,
                    });
                }
            }
        }
        let bus = self.bus();
        for (i, s) in slots.iter().enumerate() {
            let i = i as u32;
            bus.write_reg(
                &seq::exp_shutter_width::REG,
                i,
                seq::exp_shutter_width::ROWS.word(s.shutter_width_rows),
            )?;
            bus.write_reg(
                &seq::exp_shutter_delay::REG,
                i,
                seq::exp_shutter_delay::VALUE.word(s.shutter_delay),
            )?;
            bus.write_reg(
                &seq::exp_gain::REG,
                i,
                seq::exp_gain::CODE.word(s.gain_code),
            )?;
        }
        bus.write_field(
            &seq::count::REG,
            0,
            &seq::count::EXPOSURES,
            slots.len() as u32,
        )?;
        Ok(())
    }

    /// Reads the exposure table back (as many slots as `seq.count` says).
    pub fn exposures(&mut self) -> Result<Vec<ExposureSlot>, BusError> {
        let bus = self.bus();
        let n = bus
            .read_field(&seq::count::REG, 0, &seq::count::EXPOSURES)?
            .min(MAX_EXPOSURES as u32);
        (0..n)
            .map(|i| {
                Ok(ExposureSlot {
                    shutter_width_rows: bus.read_field(
                        &seq::exp_shutter_width::REG,
                        i,
                        &seq::exp_shutter_width::ROWS,
                    )?,
                    shutter_delay: bus.read_field(
                        &seq::exp_shutter_delay::REG,
                        i,
                        &seq::exp_shutter_delay::VALUE,
                    )?,
                    gain_code: bus.read_field(&seq::exp_gain::REG, i, &seq::exp_gain::CODE)?,
                })
            })
            .collect()
    }
}

/// Why an exposure table was refused.
#[derive(Debug, thiserror::Error)]
pub enum ExposureError {
    #[error("a sequence holds 1 to {MAX_EXPOSURES} exposures, not {0}")]
    Count(usize),
    #[error("exposure {index}: {field} = {value} is out of range")]
    OutOfRange {
        index: usize,
        field: &'static str,
        value: u32,
    },
    #[error(transparent)]
    Bus(#[from] BusError),
}

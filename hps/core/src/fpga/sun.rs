//! The sun accumulators as the HPS drives them (`sun.*`; values in `skylux_regmap::sun_values`,
//! interpretation in `crate::sun::fabric`).

use super::Fabric;
use skylux_bus::{BusError, RegisterAccess, RegisterBus};
use skylux_regmap::sun_values::{SunConfig, SunSums};
use skylux_regmap::{sun, Register};

/// Attempts at a consistent read before giving up: the sums change only while their frame
/// streams in, so a second attempt after a frame boundary succeeds.
const READ_ATTEMPTS: usize = 4;

/// Why the sums could not be read.
#[derive(Debug, thiserror::Error)]
pub enum SunReadError {
    #[error(transparent)]
    Bus(#[from] BusError),
    #[error("sun.frames changed during {READ_ATTEMPTS} reads: an armed frame is streaming in")]
    Unsettled,
}

impl<B: RegisterBus> Fabric<B> {
    /// Arms the accumulators for the frames of exposure `exposure_index` with `config`
    /// (`groups_per_line` comes from `capture.window.WIDTH` in the fabric), or disarms them.
    pub fn sun_configure(
        &mut self,
        config: &SunConfig,
        exposure_index: u8,
        enable: bool,
    ) -> Result<(), BusError> {
        let bus = self.bus();
        bus.write_reg(
            &sun::threshold::REG,
            0,
            sun::threshold::Q14.word(config.threshold_q14),
        )?;
        bus.write_reg(
            &sun::window_x::REG,
            0,
            sun::window_x::MIN.word(config.x_min.into())
                | sun::window_x::MAX.word(config.x_max.into()),
        )?;
        bus.write_reg(
            &sun::window_y::REG,
            0,
            sun::window_y::MIN.word(config.y_min.into())
                | sun::window_y::MAX.word(config.y_max.into()),
        )?;
        bus.write_reg(
            &sun::ctrl::REG,
            0,
            sun::ctrl::ENABLE.word(enable.into())
                | sun::ctrl::EXPOSURE_INDEX.word(exposure_index.into()),
        )
    }

    /// The sums of the last armed frame and the count of armed frames begun, read so that
    /// all of them belong to one frame (`sun.frames` the same before and after).
    pub fn sun_read(&mut self) -> Result<(SunSums, u16), SunReadError> {
        for _ in 0..READ_ATTEMPTS {
            let before = self.bus().read_reg(&sun::frames::REG, 0)?;
            let sums = self.sun_sums()?;
            let after = self.bus().read_reg(&sun::frames::REG, 0)?;
            if before == after {
                return Ok((sums, sun::frames::COUNT.get(after) as u16));
            }
        }
        Err(SunReadError::Unsettled)
    }

    fn sun_sums(&mut self) -> Result<SunSums, BusError> {
        let bus = self.bus();
        let mut wide = |lo: &Register, hi: &Register| -> Result<u64, BusError> {
            let (l, h) = (bus.read_reg(lo, 0)?, bus.read_reg(hi, 0)?);
            Ok(u64::from(h) << 32 | u64::from(l))
        };
        let sum_l = wide(&sun::sum_l_lo::REG, &sun::sum_l_hi::REG)?;
        let sum_xl = wide(&sun::sum_xl_lo::REG, &sun::sum_xl_hi::REG)?;
        let sum_yl = wide(&sun::sum_yl_lo::REG, &sun::sum_yl_hi::REG)?;
        let count = bus.read_reg(&sun::count::REG, 0)?;
        let over = bus.read_reg(&sun::over_count::REG, 0)?;
        let max_l = bus.read_reg(&sun::max_l::REG, 0)?;
        let box_x = bus.read_reg(&sun::box_x::REG, 0)?;
        let box_y = bus.read_reg(&sun::box_y::REG, 0)?;
        Ok(SunSums {
            count: sun::count::GROUPS.get(count),
            over_count: sun::over_count::GROUPS.get(over),
            sum_l,
            sum_xl,
            sum_yl,
            max_l: sun::max_l::Q14.get(max_l),
            min_x: sun::box_x::MIN.get(box_x) as u16,
            max_x: sun::box_x::MAX.get(box_x) as u16,
            min_y: sun::box_y::MIN.get(box_y) as u16,
            max_y: sun::box_y::MAX.get(box_y) as u16,
        })
    }
}

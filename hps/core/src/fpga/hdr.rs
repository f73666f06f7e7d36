//! HDR in the fabric as the HPS drives it (`hdr.*`; values in `skylux_regmap::hdr_values`,
//! the map's reading in `crate::hdr::fabric_map`).

use super::Fabric;
use skylux_bus::{BusError, RegisterAccess, RegisterBus};
use skylux_regmap::hdr;
use skylux_regmap::hdr_values::HdrConfig;

impl<B: RegisterBus> Fabric<B> {
    /// Makes the DMA write one map per set (`enable`), sets beginning with the frame of
    /// exposure `first_index` (the longest: the sequence must run long to short), or frames
    /// as before. The ring should then have one slot, which every frame of a set updates.
    pub fn hdr_configure(
        &mut self,
        config: &HdrConfig,
        first_index: u8,
        enable: bool,
    ) -> Result<(), BusError> {
        let bus = self.bus();
        bus.write_reg(&hdr::min::REG, 0, hdr::min::Q11.word(config.min_q11))?;
        bus.write_reg(&hdr::max::REG, 0, hdr::max::Q11.word(config.max_q11))?;
        bus.write_reg(
            &hdr::ctrl::REG,
            0,
            hdr::ctrl::ENABLE.word(enable.into()) | hdr::ctrl::FIRST_INDEX.word(first_index.into()),
        )
    }
}

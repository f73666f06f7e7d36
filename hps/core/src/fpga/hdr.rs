//! HDR in the fabric as the HPS drives it (`hdr.*`; values in `skylux_regmap::hdr_values`,
//! the map's reading in `crate::hdr::fabric_map`).

use super::Fabric;
use skylux_bus::{BusError, RegisterAccess, RegisterBus};
use skylux_regmap::hdr;
use skylux_regmap::hdr_values::HdrConfig;

impl<B: RegisterBus> Fabric<B> {
    /// Makes the DMA write maps (`enable`) with `config`'s usable range, or frames as before.
    /// The ring should have one slot in map mode, which every frame of a set updates.
    pub fn hdr_configure(&mut self, config: &HdrConfig, enable: bool) -> Result<(), BusError> {
        let bus = self.bus();
        bus.write_reg(&hdr::min::REG, 0, hdr::min::Q11.word(config.min_q11))?;
        bus.write_reg(&hdr::max::REG, 0, hdr::max::Q11.word(config.max_q11))?;
        bus.write_reg(&hdr::ctrl::REG, 0, hdr::ctrl::ENABLE.word(enable.into()))
    }

    /// The next map frame begins a set: strobe before the set's first (longest) exposure. The
    /// map words then name the set's frames 0, 1, ... in the order they come, across
    /// sequences.
    pub fn hdr_new_set(&mut self) -> Result<(), BusError> {
        self.bus().strobe(&hdr::ctrl::REG, 0, &hdr::ctrl::NEW_SET)
    }
}

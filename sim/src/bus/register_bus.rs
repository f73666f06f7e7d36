//! The simulation backend of `skylux_bus::RegisterBus`: every access is an Avalon-MM transfer
//! through the cycle-accurate fabric model.

use super::AvalonHost;
use skylux_bus::{check_access, BusError, RegisterBus};
use skylux_regmap::LW_BRIDGE_SPAN_BYTES;
use skylux_rtl::avalon::AvalonAgent;

/// A register bus backed by the rust-hdl model of the fabric.
pub struct SimRegisterBus<D: AvalonAgent> {
    pub host: AvalonHost<D>,
}

impl<D: AvalonAgent> SimRegisterBus<D> {
    pub fn new(dut: D) -> Self {
        Self {
            host: AvalonHost::new(dut),
        }
    }
}

impl<D: AvalonAgent> RegisterBus for SimRegisterBus<D> {
    fn read32(&mut self, offset: u32) -> Result<u32, BusError> {
        check_access(offset as u64, 4, LW_BRIDGE_SPAN_BYTES as u64, 4)?;
        self.host
            .read(offset / 4)
            .map_err(|e| BusError::Simulation(e.to_string()))
    }

    fn write32(&mut self, offset: u32, value: u32) -> Result<(), BusError> {
        check_access(offset as u64, 4, LW_BRIDGE_SPAN_BYTES as u64, 4)?;
        self.host
            .write(offset / 4, value, 0xF)
            .map_err(|e| BusError::Simulation(e.to_string()))
    }
}

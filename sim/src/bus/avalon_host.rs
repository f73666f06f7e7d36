//! An Avalon-MM host bus-functional model: single 32-bit transfers to a fixed-read-latency
//! agent, one cycle per address phase, as the lightweight bridge's Avalon master issues them
//! (Avalon Interface Specifications §3.5; hardware-facts.md §4).

use rust_hdl::prelude::*;
use skylux_regmap::READ_LATENCY_CYCLES;
use skylux_rtl::avalon::AvalonAgent;
use skylux_rtl::drive::{DriveError, Driver};

/// Drives the agent port of a design, transfer by transfer.
pub struct AvalonHost<D: AvalonAgent> {
    pub driver: Driver<D>,
    cycles: u64,
}

fn clock_of<D: AvalonAgent>(d: &mut D) -> &mut Signal<In, Clock> {
    d.clock()
}

impl<D: AvalonAgent> AvalonHost<D> {
    pub fn new(dut: D) -> Self {
        Self::with_driver(Driver::new(dut))
    }

    pub fn with_driver(mut driver: Driver<D>) -> Self {
        let d = &mut driver.dut;
        d.avs_read().next = false;
        d.avs_write().next = false;
        d.avs_byteenable().next = 0xF.into();
        Self { driver, cycles: 0 }
    }

    /// System-clock cycles run so far.
    pub fn cycles(&self) -> u64 {
        self.cycles
    }

    /// Runs `n` idle cycles.
    pub fn idle(&mut self, n: u64) -> Result<(), DriveError> {
        for _ in 0..n {
            self.driver.cycle(clock_of::<D>)?;
            self.cycles += 1;
        }
        Ok(())
    }

    /// One write transfer with byte enables.
    pub fn write(
        &mut self,
        word_address: u32,
        data: u32,
        byteenable: u8,
    ) -> Result<(), DriveError> {
        let d = &mut self.driver.dut;
        d.avs_address().next = (word_address as u64).into();
        d.avs_writedata().next = (data as u64).into();
        d.avs_byteenable().next = ((byteenable & 0xF) as u64).into();
        d.avs_write().next = true;
        self.idle(1)?;
        let d = &mut self.driver.dut;
        d.avs_write().next = false;
        d.avs_byteenable().next = 0xF.into();
        Ok(())
    }

    /// One read transfer: readdata is sampled `READ_LATENCY_CYCLES` rising edges after the
    /// address phase, just before that edge.
    pub fn read(&mut self, word_address: u32) -> Result<u32, DriveError> {
        let d = &mut self.driver.dut;
        d.avs_address().next = (word_address as u64).into();
        d.avs_read().next = true;
        self.idle(1)?;
        self.driver.dut.avs_read().next = false;
        self.idle(READ_LATENCY_CYCLES as u64 - 1)?;
        self.driver.settle()?;
        let data = self.driver.dut.avs_readdata().to_u64() as u32;
        self.idle(1)?;
        Ok(data)
    }
}

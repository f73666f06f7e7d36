//! Typed register access through the register map: callers name registers and fields, never
//! offsets.

use crate::{BusError, RegisterBus};
use skylux_regmap::{Field, Register};

fn offset(register: &Register, index: u32) -> Result<u32, BusError> {
    register.offset_of(index).ok_or(BusError::NoSuchElement {
        name: register.name,
        index,
        count: register.count,
    })
}

/// Register-map-aware access, for every [`RegisterBus`].
pub trait RegisterAccess: RegisterBus {
    /// Reads a register (element `index` of an array; 0 for a plain register).
    fn read_reg(&mut self, register: &Register, index: u32) -> Result<u32, BusError> {
        self.read32(offset(register, index)?)
    }
    /// Writes a whole register.
    fn write_reg(&mut self, register: &Register, index: u32, value: u32) -> Result<(), BusError> {
        self.write32(offset(register, index)?, value)
    }
    /// Reads one field.
    fn read_field(
        &mut self,
        register: &Register,
        index: u32,
        field: &Field,
    ) -> Result<u32, BusError> {
        Ok(field.get(self.read_reg(register, index)?))
    }
    /// Changes one field, keeping the register's other read/write fields (read-modify-write).
    /// Write-1-to-clear and command bits are written as 0 so they are left alone.
    fn write_field(
        &mut self,
        register: &Register,
        index: u32,
        field: &Field,
        value: u32,
    ) -> Result<(), BusError> {
        let keep = register
            .fields
            .iter()
            .filter(|f| f.access == skylux_regmap::Access::RW)
            .fold(0, |m, f| m | f.mask());
        let current = self.read_reg(register, index)? & keep;
        self.write_reg(register, index, field.set(current, value))
    }
    /// Sends a command (`W1P`) or clears status bits (`W1C`): writes only `field`'s bits.
    fn strobe(&mut self, register: &Register, index: u32, field: &Field) -> Result<(), BusError> {
        let keep = register
            .fields
            .iter()
            .filter(|f| f.access == skylux_regmap::Access::RW)
            .fold(0, |m, f| m | f.mask());
        let current = self.read_reg(register, index)? & keep;
        self.write_reg(register, index, current | field.mask())
    }
}

impl<B: RegisterBus + ?Sized> RegisterAccess for B {}

//! A behavioural model of the register file, written from the register map's semantics rather
//! than from the RTL: the golden model the generated RTL is compared against, and a fast
//! stand-in for the fabric where cycle accuracy does not matter.

use skylux_bus::{check_access, BusError, RegisterBus};
use skylux_regmap::{locate, Access, LW_BRIDGE_SPAN_BYTES, UNMAPPED_READ_VALUE};
use std::collections::BTreeMap;

/// Register-level model: what software sees, transfer by transfer.
#[derive(Clone, Debug)]
pub struct RegisterFileModel {
    /// Stored bits (RW and W1C) per byte offset.
    stored: BTreeMap<u32, u32>,
    /// Values the fabric drives on RO fields, per byte offset (already in position).
    pub fabric_inputs: BTreeMap<u32, u32>,
    /// W1P pulses of the last write: (offset, bits).
    pub last_pulse: Option<(u32, u32)>,
}

impl Default for RegisterFileModel {
    fn default() -> Self {
        let stored = skylux_regmap::reset_image()
            .into_iter()
            .map(|(offset, _)| {
                let reg = locate(offset).unwrap().register;
                let mask = reg
                    .fields
                    .iter()
                    .filter(|f| matches!(f.access, Access::RW | Access::W1C))
                    .fold(0, |m, f| m | f.mask());
                (offset, reg.reset_value() & mask)
            })
            .collect();
        Self {
            stored,
            fabric_inputs: BTreeMap::new(),
            last_pulse: None,
        }
    }
}

fn byte_mask(byteenable: u8) -> u32 {
    (0..4)
        .filter(|i| byteenable & (1 << i) != 0)
        .fold(0, |m, i| m | (0xFF << (8 * i)))
}

impl RegisterFileModel {
    /// A write with byte enables.
    pub fn write(&mut self, offset: u32, data: u32, byteenable: u8) {
        self.last_pulse = None;
        let Some(loc) = locate(offset) else {
            self.flag_unmapped(offset, false);
            return;
        };
        let mask = byte_mask(byteenable);
        let of = |acc: Access| {
            loc.register
                .fields
                .iter()
                .filter(|f| f.access == acc)
                .fold(0, |m, f| m | f.mask())
        };
        let (rw, w1c, w1p) = (
            of(Access::RW) & mask,
            of(Access::W1C) & mask,
            of(Access::W1P) & mask,
        );
        let stored = self.stored.get_mut(&offset).expect("stored register");
        *stored = ((*stored & !rw) | (data & rw)) & !(data & w1c);
        if data & w1p != 0 {
            self.last_pulse = Some((offset, data & w1p));
        }
    }

    /// A read.
    pub fn read(&mut self, offset: u32) -> u32 {
        self.last_pulse = None;
        let Some(loc) = locate(offset) else {
            self.flag_unmapped(offset, true);
            return UNMAPPED_READ_VALUE;
        };
        let mut value = self.stored.get(&offset).copied().unwrap_or(0);
        for f in loc.register.fields {
            match f.access {
                Access::Const => value = f.set(value, f.reset),
                Access::RO => {
                    value |= self.fabric_inputs.get(&offset).copied().unwrap_or(0) & f.mask()
                }
                _ => {}
            }
        }
        value
    }

    /// The fabric sets W1C bits (a one-cycle pulse).
    pub fn set_bits(&mut self, offset: u32, bits: u32) {
        if let Some(v) = self.stored.get_mut(&offset) {
            *v |= bits;
        }
    }

    fn flag_unmapped(&mut self, offset: u32, read: bool) {
        use skylux_regmap::sys::{bus_error_addr, bus_status};
        let flag = if read {
            bus_status::UNMAPPED_READ
        } else {
            bus_status::UNMAPPED_WRITE
        };
        *self.stored.get_mut(&bus_status::REG.offset).unwrap() |= flag.mask();
        self.fabric_inputs.insert(
            bus_error_addr::REG.offset,
            bus_error_addr::OFFSET.word(offset),
        );
    }
}

impl RegisterBus for RegisterFileModel {
    fn read32(&mut self, offset: u32) -> Result<u32, BusError> {
        check_access(offset as u64, 4, LW_BRIDGE_SPAN_BYTES as u64, 4)?;
        Ok(self.read(offset))
    }
    fn write32(&mut self, offset: u32, value: u32) -> Result<(), BusError> {
        check_access(offset as u64, 4, LW_BRIDGE_SPAN_BYTES as u64, 4)?;
        self.write(offset, value, 0xF);
        Ok(())
    }
}

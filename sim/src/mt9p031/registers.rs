//! The MT9P031 register file as the model implements it: the subset Skylux uses
//! (hardware-facts.md §1.3, §1.4), 8-bit addresses, 16-bit values.
//!
//! The addresses, bits and power-up values here are the model's own transcription of the
//! datasheet facts (hardware-facts.md §1), deliberately not read from the driver's table
//! (`skylux_hps::fpga::sensor::reg`): the model of the world must not share the product's
//! possible mistakes. The test `driver_table_agrees_with_the_model` compares the two.

/// Register addresses (hardware-facts.md §0 item 3, §1.4).
pub mod addr {
    pub const CHIP_VERSION: u8 = 0x00;
    pub const ROW_START: u8 = 0x01;
    pub const COLUMN_START: u8 = 0x02;
    pub const ROW_SIZE: u8 = 0x03;
    pub const COLUMN_SIZE: u8 = 0x04;
    pub const HORIZONTAL_BLANK: u8 = 0x05;
    pub const VERTICAL_BLANK: u8 = 0x06;
    pub const OUTPUT_CONTROL: u8 = 0x07;
    pub const SHUTTER_WIDTH_UPPER: u8 = 0x08;
    pub const SHUTTER_WIDTH_LOWER: u8 = 0x09;
    pub const PIXEL_CLOCK_CONTROL: u8 = 0x0A;
    pub const RESTART: u8 = 0x0B;
    pub const SHUTTER_DELAY: u8 = 0x0C;
    pub const RESET: u8 = 0x0D;
    pub const PLL_CONTROL: u8 = 0x10;
    pub const PLL_CONFIG_1: u8 = 0x11;
    pub const PLL_CONFIG_2: u8 = 0x12;
    pub const READ_MODE_1: u8 = 0x1E;
    pub const READ_MODE_2: u8 = 0x20;
    pub const ROW_ADDRESS_MODE: u8 = 0x22;
    pub const COLUMN_ADDRESS_MODE: u8 = 0x23;
    pub const GREEN1_GAIN: u8 = 0x2B;
    pub const BLUE_GAIN: u8 = 0x2C;
    pub const RED_GAIN: u8 = 0x2D;
    pub const GREEN2_GAIN: u8 = 0x2E;
    pub const GLOBAL_GAIN: u8 = 0x35;
}

/// Chip_Version of the MT9P031 (hardware-facts.md §1.4; the Linux driver checks it).
pub const CHIP_VERSION: u16 = 0x1801;
/// Read_Mode_1 bit 8: snapshot mode (hardware-facts.md §1.6).
pub const READ_MODE_1_SNAPSHOT: u16 = 1 << 8;
/// Restart bit 2: software snapshot trigger (hardware-facts.md §1.4).
pub const RESTART_TRIGGER: u16 = 1 << 2;
/// Read_Mode_2 bits 15 and 14: Mirror_Row, Mirror_Column (hardware-facts.md §1.4).
pub const READ_MODE_2_MIRROR_ROW: u16 = 1 << 15;
pub const READ_MODE_2_MIRROR_COLUMN: u16 = 1 << 14;

/// Power-up values. From hardware-facts.md §1.4 (Linux defaults, S1) where it gives one;
/// the others are 0 except the gains (0x0008, unity) and Read_Mode_1 (bit 14 set, S15) [U].
const RESETS: &[(u8, u16)] = &[
    (addr::CHIP_VERSION, CHIP_VERSION),
    (addr::ROW_START, 54),
    (addr::COLUMN_START, 16),
    (addr::ROW_SIZE, 1943),
    (addr::COLUMN_SIZE, 2591),
    (addr::VERTICAL_BLANK, 25),
    (addr::OUTPUT_CONTROL, 0x1F82),
    (addr::SHUTTER_WIDTH_LOWER, 1943),
    (addr::PLL_CONTROL, 0x0050),
    (addr::READ_MODE_1, 0x4000),
    (addr::READ_MODE_2, 0x0040),
    (addr::GREEN1_GAIN, 8),
    (addr::BLUE_GAIN, 8),
    (addr::RED_GAIN, 8),
    (addr::GREEN2_GAIN, 8),
    (addr::GLOBAL_GAIN, 8),
];

/// What a register write did besides storing the value.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum WriteEffect {
    Stored,
    /// Read-only register: nothing changed.
    Ignored,
    /// Restart.Trigger was written: a snapshot frame starts (in snapshot mode).
    SoftwareTrigger,
    /// Reset was written 1: every register returned to its power-up value.
    SoftReset,
}

/// The 256 16-bit registers.
#[derive(Clone, Debug)]
pub struct Registers {
    values: [u16; 256],
}

impl Default for Registers {
    fn default() -> Self {
        let mut values = [0u16; 256];
        for &(a, v) in RESETS {
            values[a as usize] = v;
        }
        Self { values }
    }
}

impl Registers {
    pub fn read(&self, address: u8) -> u16 {
        self.values[address as usize]
    }

    /// A complete 16-bit write (the sensor updates a register only once both bytes arrived,
    /// hardware-facts.md §1.3).
    pub fn write(&mut self, address: u8, value: u16) -> WriteEffect {
        match address {
            addr::CHIP_VERSION => WriteEffect::Ignored,
            addr::RESET if value & 1 != 0 => {
                *self = Self::default();
                self.values[addr::RESET as usize] = value;
                WriteEffect::SoftReset
            }
            addr::GLOBAL_GAIN => {
                // Global_Gain writes all four colour gains (hardware-facts.md §1.4).
                for a in [
                    addr::GREEN1_GAIN,
                    addr::BLUE_GAIN,
                    addr::RED_GAIN,
                    addr::GREEN2_GAIN,
                    addr::GLOBAL_GAIN,
                ] {
                    self.values[a as usize] = value;
                }
                WriteEffect::Stored
            }
            addr::RESTART if value & RESTART_TRIGGER != 0 => {
                self.values[address as usize] = value & !RESTART_TRIGGER;
                WriteEffect::SoftwareTrigger
            }
            _ => {
                self.values[address as usize] = value;
                WriteEffect::Stored
            }
        }
    }

    /// Shutter width in rows, `Upper[3:0] << 16 | Lower` (at least 1, hardware-facts.md §0).
    pub fn shutter_width_rows(&self) -> u32 {
        let sw = (u32::from(self.read(addr::SHUTTER_WIDTH_UPPER) & 0xF) << 16)
            | u32::from(self.read(addr::SHUTTER_WIDTH_LOWER));
        sw.max(1)
    }

    pub fn snapshot_mode(&self) -> bool {
        self.read(addr::READ_MODE_1) & READ_MODE_1_SNAPSHOT != 0
    }

    pub fn mirror_row(&self) -> bool {
        self.read(addr::READ_MODE_2) & READ_MODE_2_MIRROR_ROW != 0
    }

    pub fn mirror_column(&self) -> bool {
        self.read(addr::READ_MODE_2) & READ_MODE_2_MIRROR_COLUMN != 0
    }

    /// Total gain of a gain register code: analog `(1 + mult) · analog / 8` times digital
    /// `1 + digital / 8` (hardware-facts.md §1.4, S16). 0x0008 is unity.
    pub fn gain_of_code(code: u16) -> f64 {
        let analog = f64::from(code & 0x3F) / 8.0 * if code & 0x40 != 0 { 2.0 } else { 1.0 };
        let digital = 1.0 + f64::from((code >> 8) & 0x7F) / 8.0;
        analog * digital
    }

    /// The gain applied to the frame (the model's sensor is grey: Green1's gain for all).
    pub fn gain(&self) -> f64 {
        Self::gain_of_code(self.read(addr::GREEN1_GAIN))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every register and bit the driver writes has the address and position the model
    /// transcribed independently.
    #[test]
    fn driver_table_agrees_with_the_model() {
        use skylux_hps::fpga::sensor::{self as driver, reg};
        let pairs = [
            ("CHIP_VERSION", reg::CHIP_VERSION, addr::CHIP_VERSION),
            ("ROW_START", reg::ROW_START, addr::ROW_START),
            ("COLUMN_START", reg::COLUMN_START, addr::COLUMN_START),
            ("ROW_SIZE", reg::ROW_SIZE, addr::ROW_SIZE),
            ("COLUMN_SIZE", reg::COLUMN_SIZE, addr::COLUMN_SIZE),
            (
                "HORIZONTAL_BLANK",
                reg::HORIZONTAL_BLANK,
                addr::HORIZONTAL_BLANK,
            ),
            ("VERTICAL_BLANK", reg::VERTICAL_BLANK, addr::VERTICAL_BLANK),
            (
                "SHUTTER_WIDTH_UPPER",
                reg::SHUTTER_WIDTH_UPPER,
                addr::SHUTTER_WIDTH_UPPER,
            ),
            (
                "SHUTTER_WIDTH_LOWER",
                reg::SHUTTER_WIDTH_LOWER,
                addr::SHUTTER_WIDTH_LOWER,
            ),
            ("SHUTTER_DELAY", reg::SHUTTER_DELAY, addr::SHUTTER_DELAY),
            ("RESET", reg::RESET, addr::RESET),
            ("PLL_CONTROL", reg::PLL_CONTROL, addr::PLL_CONTROL),
            ("PLL_CONFIG_1", reg::PLL_CONFIG_1, addr::PLL_CONFIG_1),
            ("PLL_CONFIG_2", reg::PLL_CONFIG_2, addr::PLL_CONFIG_2),
            ("READ_MODE_1", reg::READ_MODE_1, addr::READ_MODE_1),
            ("READ_MODE_2", reg::READ_MODE_2, addr::READ_MODE_2),
            (
                "ROW_ADDRESS_MODE",
                reg::ROW_ADDRESS_MODE,
                addr::ROW_ADDRESS_MODE,
            ),
            (
                "COLUMN_ADDRESS_MODE",
                reg::COLUMN_ADDRESS_MODE,
                addr::COLUMN_ADDRESS_MODE,
            ),
            ("GLOBAL_GAIN", reg::GLOBAL_GAIN, addr::GLOBAL_GAIN),
        ];
        for (name, driver_addr, model_addr) in pairs {
            assert_eq!(driver_addr, model_addr, "{name}");
        }
        assert_eq!(driver::MT9P031_CHIP_VERSION, CHIP_VERSION);
        assert_eq!(driver::READ_MODE_1_SNAPSHOT, READ_MODE_1_SNAPSHOT);
        assert_eq!(driver::READ_MODE_2_MIRROR_ROW, READ_MODE_2_MIRROR_ROW);
        assert_eq!(driver::READ_MODE_2_MIRROR_COLUMN, READ_MODE_2_MIRROR_COLUMN);
        assert_eq!(
            driver::MT9P031_ADDRESS,
            crate::mt9p031::i2c_target::MT9P031_ADDRESS
        );
    }
}

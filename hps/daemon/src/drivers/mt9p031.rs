//! The MT9P031 over an HPS I2C controller (when the sensor's I2C is wired to the HPS instead
//! of the fabric's master), through embedded-hal 1.0's `I2c`. The register set, the
//! configuration's register writes and the chip constants are `skylux_hps::fpga::sensor`'s,
//! so both paths program the sensor identically.
//!
//! Protocol (hardware-facts.md §1.3): 8-bit register address, 16-bit big-endian data; a read
//! is a write of the address followed by a repeated-start read of two bytes.

use embedded_hal::i2c::{Error as _, ErrorKind, I2c, NoAcknowledgeSource};
use skylux_hps::fpga::sensor::{reg, SensorConfig, MT9P031_ADDRESS, MT9P031_CHIP_VERSION};

/// Why a sensor access failed.
#[derive(Debug, PartialEq, Eq, thiserror::Error)]
pub enum Mt9p031Error {
    #[error("sensor register {reg:#04x}: no acknowledge ({origin:?}): absent, unpowered or wrong address")]
    Nack {
        reg: u8,
        origin: NoAcknowledgeSource,
    },
    #[error("sensor register {reg:#04x}: I2C error {kind:?}")]
    Bus { reg: u8, kind: ErrorKind },
    #[error(
        "Chip_Version reads {found:#06x}, expected {MT9P031_CHIP_VERSION:#06x}: not an MT9P031"
    )]
    WrongChip { found: u16 },
    #[error("sensor register {reg:#04x}: wrote {wrote:#06x}, read back {read:#06x}")]
    Verify { reg: u8, wrote: u16, read: u16 },
    #[error("sensor configuration: {0}")]
    Config(String),
}

/// The sensor on an I2C bus.
pub struct Mt9p031<I> {
    i2c: I,
    address: u8,
}

impl<I: I2c> Mt9p031<I> {
    /// At the default address 0x5D.
    pub fn new(i2c: I) -> Self {
        Self::with_address(i2c, MT9P031_ADDRESS)
    }

    /// At `address` (0x48 when S_ADDR is high, hardware-facts.md §1.3).
    pub fn with_address(i2c: I, address: u8) -> Self {
        Self { i2c, address }
    }

    fn map(reg: u8, e: I::Error) -> Mt9p031Error {
        match e.kind() {
            ErrorKind::NoAcknowledge(origin) => Mt9p031Error::Nack { reg, origin },
            kind => Mt9p031Error::Bus { reg, kind },
        }
    }

    /// Reads a register.
    pub fn read(&mut self, r: u8) -> Result<u16, Mt9p031Error> {
        let mut buf = [0u8; 2];
        self.i2c
            .write_read(self.address, &[r], &mut buf)
            .map_err(|e| Self::map(r, e))?;
        Ok(u16::from_be_bytes(buf))
    }

    /// Writes a register.
    pub fn write(&mut self, r: u8, value: u16) -> Result<(), Mt9p031Error> {
        let [hi, lo] = value.to_be_bytes();
        self.i2c
            .write(self.address, &[r, hi, lo])
            .map_err(|e| Self::map(r, e))
    }

    /// Checks Chip_Version.
    pub fn check_chip(&mut self) -> Result<u16, Mt9p031Error> {
        let v = self.read(reg::CHIP_VERSION)?;
        if v != MT9P031_CHIP_VERSION {
            return Err(Mt9p031Error::WrongChip { found: v });
        }
        Ok(v)
    }

    /// Checks the chip, soft-resets it, then writes the window, modes, gain and shutter of
    /// `config` and reads each back (the PLL is left to the caller: it needs a ≥ 1 ms lock
    /// wait). Nothing is written if `config` is invalid.
    pub fn configure(&mut self, config: &SensorConfig) -> Result<(), Mt9p031Error> {
        config
            .validate()
            .map_err(|e| Mt9p031Error::Config(e.to_string()))?;
        self.check_chip()?;
        self.write(reg::RESET, 1)?;
        self.write(reg::RESET, 0)?;
        let writes = config.register_writes();
        for &(r, v) in &writes {
            self.write(r, v)?;
        }
        for &(r, v) in &writes {
            let read = self.read(r)?;
            if read != v {
                return Err(Mt9p031Error::Verify {
                    reg: r,
                    wrote: v,
                    read,
                });
            }
        }
        Ok(())
    }

    pub fn release(self) -> I {
        self.i2c
    }
}

/// The Linux binding: `/dev/i2c-N` through linux-embedded-hal's i2cdev.
#[cfg(target_os = "linux")]
pub fn open_linux(
    bus: &str,
) -> Result<Mt9p031<linux_embedded_hal::I2cdev>, linux_embedded_hal::i2cdev::linux::LinuxI2CError> {
    Ok(Mt9p031::new(linux_embedded_hal::I2cdev::new(bus)?))
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_hal_mock::eh1::i2c::{Mock, Transaction as T};

    #[test]
    fn read_and_write_are_big_endian() {
        let mut i2c = Mock::new(&[
            T::write_read(0x5D, vec![0x00], vec![0x18, 0x01]),
            T::write(0x5D, vec![0x09, 0x12, 0x34]),
        ]);
        let mut s = Mt9p031::new(i2c.clone());
        assert_eq!(s.check_chip().unwrap(), 0x1801);
        s.write(reg::SHUTTER_WIDTH_LOWER, 0x1234).unwrap();
        i2c.done();
    }

    #[test]
    fn nack_and_wrong_chip_are_named() {
        let mut i2c = Mock::new(&[
            T::write_read(0x5D, vec![0x00], vec![0, 0])
                .with_error(ErrorKind::NoAcknowledge(NoAcknowledgeSource::Address)),
            T::write_read(0x5D, vec![0x00], vec![0x12, 0x34]),
        ]);
        let mut s = Mt9p031::new(i2c.clone());
        assert_eq!(
            s.check_chip(),
            Err(Mt9p031Error::Nack {
                reg: 0,
                origin: NoAcknowledgeSource::Address
            })
        );
        assert_eq!(
            s.check_chip(),
            Err(Mt9p031Error::WrongChip { found: 0x1234 })
        );
        i2c.done();
    }

    #[test]
    fn configure_writes_then_verifies_every_register() {
        let config = SensorConfig::default();
        let writes = config.register_writes();
        let mut expected = vec![
            T::write_read(0x5D, vec![0x00], vec![0x18, 0x01]),
            T::write(0x5D, vec![reg::RESET, 0, 1]),
            T::write(0x5D, vec![reg::RESET, 0, 0]),
        ];
        for &(r, v) in &writes {
            let [hi, lo] = v.to_be_bytes();
            expected.push(T::write(0x5D, vec![r, hi, lo]));
        }
        for &(r, v) in &writes {
            expected.push(T::write_read(0x5D, vec![r], v.to_be_bytes().to_vec()));
        }
        let mut i2c = Mock::new(&expected);
        Mt9p031::new(i2c.clone()).configure(&config).unwrap();
        i2c.done();
    }
}

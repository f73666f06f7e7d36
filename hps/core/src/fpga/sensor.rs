//! The MT9P031's registers through the fabric's I2C master (`i2c.*`): single register
//! transactions, and the configuration sequence with read-back (hardware-facts.md §1.3,
//! §1.4, §1.7).

use super::Fabric;
use skylux_bus::{BusError, RegisterAccess, RegisterBus};
use skylux_regmap::i2c;

/// Chip_Version of the MT9P031 (hardware-facts.md §1.4).
pub const MT9P031_CHIP_VERSION: u16 = 0x1801;
/// The sensor's 7-bit I2C address (hardware-facts.md §1.3).
pub const MT9P031_ADDRESS: u8 = 0x5D;

/// Sensor register addresses the driver writes (hardware-facts.md §1.4).
pub mod reg {
    pub const CHIP_VERSION: u8 = 0x00;
    pub const ROW_START: u8 = 0x01;
    pub const COLUMN_START: u8 = 0x02;
    pub const ROW_SIZE: u8 = 0x03;
    pub const COLUMN_SIZE: u8 = 0x04;
    pub const HORIZONTAL_BLANK: u8 = 0x05;
    pub const VERTICAL_BLANK: u8 = 0x06;
    pub const SHUTTER_WIDTH_UPPER: u8 = 0x08;
    pub const SHUTTER_WIDTH_LOWER: u8 = 0x09;
    pub const SHUTTER_DELAY: u8 = 0x0C;
    pub const RESET: u8 = 0x0D;
    pub const PLL_CONTROL: u8 = 0x10;
    pub const PLL_CONFIG_1: u8 = 0x11;
    pub const PLL_CONFIG_2: u8 = 0x12;
    pub const READ_MODE_1: u8 = 0x1E;
    pub const READ_MODE_2: u8 = 0x20;
    pub const ROW_ADDRESS_MODE: u8 = 0x22;
    pub const COLUMN_ADDRESS_MODE: u8 = 0x23;
    pub const GLOBAL_GAIN: u8 = 0x35;
}

/// Read_Mode_1 bit 8: snapshot mode (hardware-facts.md §1.6).
pub const READ_MODE_1_SNAPSHOT: u16 = 1 << 8;
/// Read_Mode_2 bits 15 and 14: Mirror_Row, Mirror_Column (hardware-facts.md §1.4).
pub const READ_MODE_2_MIRROR_ROW: u16 = 1 << 15;
pub const READ_MODE_2_MIRROR_COLUMN: u16 = 1 << 14;

/// PLL settings: `f_PIXCLK = f_EXT M / (N P1)` (hardware-facts.md §1.2, Linux limits).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct PllConfig {
    pub m: u32,
    pub n: u32,
    pub p1: u32,
}

/// What the driver programs. Sizes are output pixels; start and window are in full-array
/// coordinates (hardware-facts.md §1.1, §1.4).
#[derive(Clone, Debug, PartialEq)]
pub struct SensorConfig {
    pub row_start: u32,
    pub col_start: u32,
    /// Full-array rows and columns of the window (even).
    pub height: u32,
    pub width: u32,
    /// Skip factor 1 to 8 (rows and columns alike).
    pub skip: u32,
    /// Bin factor 1, 2 or 4; must divide `skip` (Linux rule, hardware-facts.md §1.4).
    pub bin: u32,
    /// Horizontal and vertical blanking register values (HB = value + 1).
    pub horizontal_blank: u32,
    pub vertical_blank: u32,
    pub mirror_row: bool,
    pub mirror_column: bool,
    /// Snapshot mode (the exposure sequencer triggers each frame).
    pub snapshot: bool,
    pub global_gain_code: u32,
    pub shutter_width_rows: u32,
    pub shutter_delay: u32,
    /// `None`: leave the PLL off (PIXCLK = EXTCLK).
    pub pll: Option<PllConfig>,
}

impl Default for SensorConfig {
    /// The full active array (2592x1944 at column 16, row 54), snapshot mode, unity gain.
    fn default() -> Self {
        Self {
            row_start: 54,
            col_start: 16,
            height: 1944,
            width: 2592,
            skip: 1,
            bin: 1,
            horizontal_blank: 0,
            vertical_blank: 25,
            mirror_row: false,
            mirror_column: false,
            snapshot: true,
            global_gain_code: 8,
            shutter_width_rows: 1,
            shutter_delay: 0,
            pll: None,
        }
    }
}

/// Why a sensor access or the configuration failed.
#[derive(Debug, thiserror::Error)]
pub enum SensorError {
    #[error("register bus: {0}")]
    Bus(#[from] BusError),
    #[error("sensor register {reg:#04x}: the sensor did not acknowledge (absent, unpowered or wrong address)")]
    Nack { reg: u8 },
    #[error("sensor register {reg:#04x}: the I2C transaction timed out (SCL held low)")]
    Timeout { reg: u8 },
    #[error("sensor register {reg:#04x}: SDA is held low by a device on the bus")]
    BusStuck { reg: u8 },
    #[error("sensor register {reg:#04x}: the exposure sequencer owns the I2C master (stop the sequence first)")]
    Refused { reg: u8 },
    #[error(
        "sensor register {reg:#04x}: the I2C master never reported completion after {polls} polls"
    )]
    NoCompletion { reg: u8, polls: u32 },
    #[error(
        "Chip_Version reads {found:#06x}, expected {MT9P031_CHIP_VERSION:#06x}: not an MT9P031"
    )]
    WrongChip { found: u16 },
    #[error("sensor register {reg:#04x}: wrote {wrote:#06x}, read back {read:#06x}")]
    Verify { reg: u8, wrote: u16, read: u16 },
    #[error("sensor configuration: {field} = {value} is out of range ({allowed})")]
    OutOfRange {
        field: &'static str,
        value: u32,
        allowed: &'static str,
    },
}

fn check(
    field: &'static str,
    value: u32,
    ok: bool,
    allowed: &'static str,
) -> Result<(), SensorError> {
    if ok {
        Ok(())
    } else {
        Err(SensorError::OutOfRange {
            field,
            value,
            allowed,
        })
    }
}

impl SensorConfig {
    /// Checks every field against the sensor's limits (hardware-facts.md §1.1, §1.2, §1.4).
    pub fn validate(&self) -> Result<(), SensorError> {
        check(
            "row_start",
            self.row_start,
            self.row_start <= 2004 && self.row_start.is_multiple_of(2),
            "even, 0 to 2004",
        )?;
        check(
            "col_start",
            self.col_start,
            self.col_start <= 2750 && self.col_start.is_multiple_of(2),
            "even, 0 to 2750",
        )?;
        check(
            "height",
            self.height,
            (2..=2006).contains(&self.height) && self.height.is_multiple_of(2),
            "even, 2 to 2006",
        )?;
        check(
            "width",
            self.width,
            (2..=2752).contains(&self.width) && self.width.is_multiple_of(2),
            "even, 2 to 2752",
        )?;
        check("skip", self.skip, (1..=8).contains(&self.skip), "1 to 8")?;
        check(
            "bin",
            self.bin,
            matches!(self.bin, 1 | 2 | 4) && self.skip.is_multiple_of(self.bin),
            "1, 2 or 4, dividing skip",
        )?;
        check(
            "horizontal_blank",
            self.horizontal_blank,
            self.horizontal_blank <= 4095,
            "0 to 4095",
        )?;
        check(
            "vertical_blank",
            self.vertical_blank,
            self.vertical_blank <= 0xFFFF,
            "0 to 65535",
        )?;
        check(
            "global_gain_code",
            self.global_gain_code,
            self.global_gain_code <= 0xFFFF,
            "16 bits",
        )?;
        check(
            "shutter_width_rows",
            self.shutter_width_rows,
            (1..1 << 20).contains(&self.shutter_width_rows),
            "1 to 2^20 - 1",
        )?;
        check(
            "shutter_delay",
            self.shutter_delay,
            self.shutter_delay < 1 << 13,
            "0 to 8191",
        )?;
        if let Some(p) = self.pll {
            check("pll.m", p.m, (16..=255).contains(&p.m), "16 to 255")?;
            check("pll.n", p.n, (1..=64).contains(&p.n), "1 to 64")?;
            check("pll.p1", p.p1, (1..=128).contains(&p.p1), "1 to 128")?;
        }
        Ok(())
    }

    /// The register writes of the window, modes, gain and shutter, in order, all of which
    /// read back as written.
    pub fn register_writes(&self) -> Vec<(u8, u16)> {
        let mode = |bin: u32| (((bin - 1) << 4) | (self.skip - 1)) as u16;
        let mut read_mode_1 = 0x4000u16; // bit 14 set as in the reset value (S15)
        if self.snapshot {
            read_mode_1 |= READ_MODE_1_SNAPSHOT;
        }
        let read_mode_2 = 0x0040u16 // Row_BLC, the Linux default
            | if self.mirror_row {
                READ_MODE_2_MIRROR_ROW
            } else {
                0
            }
            | if self.mirror_column {
                READ_MODE_2_MIRROR_COLUMN
            } else {
                0
            };
        vec![
            (reg::ROW_START, self.row_start as u16),
            (reg::COLUMN_START, self.col_start as u16),
            (reg::ROW_SIZE, (self.height - 1) as u16),
            (reg::COLUMN_SIZE, (self.width - 1) as u16),
            (reg::HORIZONTAL_BLANK, self.horizontal_blank as u16),
            (reg::VERTICAL_BLANK, self.vertical_blank as u16),
            (reg::ROW_ADDRESS_MODE, mode(self.bin)),
            (reg::COLUMN_ADDRESS_MODE, mode(self.bin)),
            (reg::READ_MODE_1, read_mode_1),
            (reg::READ_MODE_2, read_mode_2),
            (reg::GLOBAL_GAIN, self.global_gain_code as u16),
            (
                reg::SHUTTER_WIDTH_UPPER,
                (self.shutter_width_rows >> 16) as u16,
            ),
            (reg::SHUTTER_WIDTH_LOWER, self.shutter_width_rows as u16),
            (reg::SHUTTER_DELAY, self.shutter_delay as u16),
        ]
    }
}

/// I2C bus settings of the fabric's master.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct I2cTiming {
    /// System clocks per half SCL period (`i2c.clock_div`).
    pub half_period_cycles: u32,
    /// Transaction watchdog (`i2c.timeout`).
    pub timeout_cycles: u32,
}

impl<B: RegisterBus> Fabric<B> {
    /// Sets the I2C master's clock divider, watchdog and target address (the MT9P031's).
    pub fn sensor_bus_setup(&mut self, timing: I2cTiming) -> Result<(), SensorError> {
        check(
            "half_period_cycles",
            timing.half_period_cycles,
            i2c::clock_div::HALF_PERIOD.fits(timing.half_period_cycles)
                && timing.half_period_cycles >= 2,
            "2 to 65535",
        )?;
        check(
            "timeout_cycles",
            timing.timeout_cycles,
            i2c::timeout::CYCLES.fits(timing.timeout_cycles) && timing.timeout_cycles > 0,
            "1 to 2^24 - 1",
        )?;
        let bus = self.bus();
        bus.write_reg(
            &i2c::clock_div::REG,
            0,
            i2c::clock_div::HALF_PERIOD.word(timing.half_period_cycles),
        )?;
        bus.write_reg(
            &i2c::timeout::REG,
            0,
            i2c::timeout::CYCLES.word(timing.timeout_cycles),
        )?;
        bus.write_reg(
            &i2c::target::REG,
            0,
            i2c::target::ADDR7.word(MT9P031_ADDRESS.into()),
        )?;
        Ok(())
    }

    /// One register transaction; returns the read value (0 for a write).
    fn sensor_transaction(&mut self, reg_addr: u8, write: Option<u16>) -> Result<u16, SensorError> {
        let timeout = self
            .bus()
            .read_field(&i2c::timeout::REG, 0, &i2c::timeout::CYCLES)?;
        let bus = self.bus();
        let sticky = i2c::status::DONE.mask()
            | i2c::status::NACK.mask()
            | i2c::status::TIMEOUT.mask()
            | i2c::status::BUS_STUCK.mask()
            | i2c::status::REFUSED.mask();
        bus.write_reg(&i2c::status::REG, 0, sticky)?;
        bus.write_reg(
            &i2c::reg_addr::REG,
            0,
            i2c::reg_addr::ADDR.word(reg_addr.into()),
        )?;
        if let Some(v) = write {
            bus.write_reg(
                &i2c::write_data::REG,
                0,
                i2c::write_data::DATA.word(v.into()),
            )?;
        }
        let read = i2c::ctrl::READ.word(write.is_none().into());
        bus.write_reg(&i2c::ctrl::REG, 0, read | i2c::ctrl::START.mask())?;
        // The fabric's watchdog ends every transaction within `timeout` clocks, and each poll
        // takes at least one clock: this bound is never reached by a working fabric.
        let max_polls = timeout.saturating_add(1000);
        for _ in 0..max_polls {
            let s = bus.read_reg(&i2c::status::REG, 0)?;
            let flag = |f: &skylux_regmap::Field| f.get(s) != 0;
            if flag(&i2c::status::REFUSED) {
                return Err(SensorError::Refused { reg: reg_addr });
            }
            if flag(&i2c::status::BUSY) || !flag(&i2c::status::DONE) {
                continue;
            }
            if flag(&i2c::status::BUS_STUCK) {
                return Err(SensorError::BusStuck { reg: reg_addr });
            }
            if flag(&i2c::status::TIMEOUT) {
                return Err(SensorError::Timeout { reg: reg_addr });
            }
            if flag(&i2c::status::NACK) {
                return Err(SensorError::Nack { reg: reg_addr });
            }
            return Ok(bus.read_field(&i2c::read_data::REG, 0, &i2c::read_data::DATA)? as u16);
        }
        Err(SensorError::NoCompletion {
            reg: reg_addr,
            polls: max_polls,
        })
    }

    /// Reads one sensor register.
    pub fn sensor_read(&mut self, reg_addr: u8) -> Result<u16, SensorError> {
        self.sensor_transaction(reg_addr, None)
    }

    /// Writes one sensor register.
    pub fn sensor_write(&mut self, reg_addr: u8, value: u16) -> Result<(), SensorError> {
        self.sensor_transaction(reg_addr, Some(value)).map(|_| ())
    }

    /// Waits at least `cycles` system clocks (under 2^32), timed by the fabric's free-running
    /// counter, reading it every `pause` (zero where time advances only with accesses, as in
    /// the simulated fabrics; a millisecond on the board keeps the core free).
    pub fn wait_cycles(&mut self, cycles: u64, pause: std::time::Duration) -> Result<(), BusError> {
        use skylux_regmap::sys;
        let bus = self.bus();
        let start = bus.read_reg(&sys::time_lo::REG, 0)?;
        loop {
            let now = bus.read_reg(&sys::time_lo::REG, 0)?;
            if u64::from(now.wrapping_sub(start)) >= cycles {
                return Ok(());
            }
            if !pause.is_zero() {
                std::thread::sleep(pause);
            }
        }
    }

    /// Configures the sensor (hardware-facts.md §1.7): checks Chip_Version, soft reset, the
    /// PLL (power, configure, ≥ 1 ms, use), then the window, modes, gain and shutter, each
    /// read back. Returns the chip version. Nothing is written if `config` is invalid.
    pub fn sensor_configure(&mut self, config: &SensorConfig) -> Result<u16, SensorError> {
        config.validate()?;
        let version = self.sensor_read(reg::CHIP_VERSION)?;
        if version != MT9P031_CHIP_VERSION {
            return Err(SensorError::WrongChip { found: version });
        }
        self.sensor_write(reg::RESET, 1)?;
        self.sensor_write(reg::RESET, 0)?;
        if let Some(p) = config.pll {
            self.sensor_write(reg::PLL_CONTROL, 0x0051)?;
            self.sensor_write(reg::PLL_CONFIG_1, ((p.m << 8) | (p.n - 1)) as u16)?;
            self.sensor_write(reg::PLL_CONFIG_2, (p.p1 - 1) as u16)?;
            // PLL lock: at least 1 ms (Linux mt9p031 pll_enable, S1).
            let clock_hz = u64::from(self.info().sys_clock_hz);
            self.wait_cycles(clock_hz.div_ceil(1000), std::time::Duration::ZERO)?;
            self.sensor_write(reg::PLL_CONTROL, 0x0053)?;
        }
        let mut writes = config.register_writes();
        if let Some(p) = config.pll {
            writes.push((reg::PLL_CONFIG_1, ((p.m << 8) | (p.n - 1)) as u16));
            writes.push((reg::PLL_CONFIG_2, (p.p1 - 1) as u16));
            writes.push((reg::PLL_CONTROL, 0x0053));
        }
        for &(r, v) in &writes {
            if r != reg::PLL_CONFIG_1 && r != reg::PLL_CONFIG_2 && r != reg::PLL_CONTROL {
                self.sensor_write(r, v)?;
            }
        }
        for &(r, v) in &writes {
            let read = self.sensor_read(r)?;
            if read != v {
                return Err(SensorError::Verify {
                    reg: r,
                    wrote: v,
                    read,
                });
            }
        }
        Ok(version)
    }
}

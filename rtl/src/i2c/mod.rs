//! Two-wire (I2C) master for the image sensor's registers (issue 3 item 1; registers `i2c.*`;
//! protocol hardware-facts.md §1.3: 7-bit address 0x5D, 8-bit register address, 16-bit data
//! MSB first).
//!
//! - [`I2cMaster`]: one whole register transaction per `start` (write, or write-address then
//!   repeated-start read), open-drain outputs, clock stretching, NACK, stuck-bus and watchdog
//!   detection.

mod master;

pub use master::{I2cMaster, SYNC_STAGES};

//! Sensor control in the fabric (issue 3 items 1 and 2; registers `i2c.*` and `seq.*`).
//!
//! - [`ExposureSequencer`]: up to 8 snapshot exposures per HDR sequence, their register
//!   writes, the sensor trigger, per-frame tags for the capture block, and the lens shield
//!   with its hardware open-time ceiling.
//! - [`SensorControl`]: the I2C master, the configuration port the HPS drives (one register
//!   transaction per `i2c.ctrl.START`) and the exposure sequencer, sharing the master.

mod control;
mod exposure;

pub use control::SensorControl;
pub use exposure::{ExposureSequencer, EXPOSURE_REGISTERS, SHIELD_LIMIT_MAX_CYCLES};

//! Peripheral drivers against embedded-hal 1.0, used on Linux through linux-embedded-hal
//! (GPIO character device, i2cdev) and tested with embedded-hal-mock.

pub mod mt9p031;
pub mod shield;

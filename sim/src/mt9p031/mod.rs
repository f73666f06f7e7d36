//! The MT9P031 image sensor (issue 3): register file, two-wire target with fault injection,
//! row/frame/exposure timing, FV/LV waveforms and pixel values through the one camera model.
//! [`rig`] puts the sensor on the two-wire bus of the fabric's sensor-control RTL and behind
//! `skylux_bus::RegisterBus`.
//!
//! - [`registers`]: the register subset, power-up values, gain codes.
//! - [`timing`]: row time, frame time and exposure (both shutter-overhead variants).
//! - [`i2c_target`]: the target, stepped once per bus sample, faults ([`I2cFault`]).
//! - [`frame`]: the FV/LV state machine, one PIXCLK per tick (the pixel path's driver).
//! - [`pixels`]: frame samples from a scene ([`SceneSource`]) or a ramp, with mirroring.
//! - [`Mt9p031`]: all of it together.

pub mod frame;
pub mod i2c_target;
pub mod pixels;
pub mod registers;
pub mod rig;
mod sensor;
pub mod timing;

pub use frame::{BusState, FrameSettings, FrameTiming, Mode};
pub use i2c_target::{I2cFault, I2cTarget, MT9P031_ADDRESS};
pub use pixels::{PixelSource, RampSource, SceneSource};
pub use registers::{Registers, CHIP_VERSION};
pub use sensor::{Mt9p031, PixelBus};
pub use timing::{FrameGeometry, ShutterOverhead};

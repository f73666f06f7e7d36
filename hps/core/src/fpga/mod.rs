//! Drivers for the Skylux fabric, written against the bus traits only.

mod bringup;
pub mod bvh_unit;
pub mod capture;
mod exposure;
pub mod frames;
mod hdr;
pub mod raybox;
pub mod sensor;
pub mod sequence;
pub mod shield_plan;
mod sun;

pub use bringup::{BringUpError, Fabric, FabricInfo};
pub use capture::{CaptureConfig, CaptureConfigError, CaptureFaults, GroupingConfig};
pub use exposure::{ExposureError, ExposureSlot, MAX_EXPOSURES};
pub use sun::SunReadError;

//! Drivers for the Skylux fabric, written against the bus traits only.

mod bringup;
mod exposure;

pub use bringup::{BringUpError, Fabric, FabricInfo};
pub use exposure::{ExposureError, ExposureSlot, MAX_EXPOSURES};

//! The sky as the device measures it: sky maps aggregated into patches, the representation
//! daylight coefficients are computed for.

mod patches;

pub use patches::{PatchSky, SkyPatches};

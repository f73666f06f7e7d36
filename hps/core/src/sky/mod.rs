//! The sky as the device measures it: sky maps aggregated into patches, the representation
//! daylight coefficients are computed for.

pub mod cie;
mod lookup;
mod patches;
pub mod perez;

pub use cie::{
    hemisphere_integral, CieDistribution, CieError, CieParameters, CieSky, HemisphereGrid,
    ScaledCieSky, CIE_STANDARD_SKIES,
};
pub use lookup::SkyLookup;
pub use patches::{PatchSky, SkyPatches};
pub use perez::{ErrorSky, GendaylitUnits, PerezConditions, PerezError, PerezInput, PerezSky};

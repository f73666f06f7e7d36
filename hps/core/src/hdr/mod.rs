//! HDR synthesis: raw Bayer exposures to one calibrated luminance map, one value per 2x2
//! Bayer group, with per-group flags, directions and solid angles.

mod geometry;
mod merge;

pub use geometry::GroupGeometry;
pub use merge::{merge, Exposure, HdrError, LuminanceMap, MapFlag, Samples};

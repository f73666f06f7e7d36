//! HDR synthesis: raw Bayer exposures to one calibrated luminance map, one value per 2x2
//! Bayer group, with per-group flags, directions and solid angles.

mod capture;
mod exr_file;
mod fabric_map;
mod geometry;
mod merge;
mod radiance_sky;

pub use capture::{map_capture, CaptureMap, CaptureMapError};
pub use exr_file::{
    parse_exr, read_exr, write_exr, MapFileError, DEVICE_ATTRIBUTE, READOUT_ATTRIBUTE,
};
pub use fabric_map::{fabric_map, FabricMap, MapExposure};
pub use geometry::{GeometryCache, GroupGeometry};
pub use merge::{
    merge, Exposure, ExposureFrame, GroupParams, GroupedFrame, HdrError, LuminanceMap, MapFlag,
    Samples,
};
pub use radiance_sky::{picture_direction, sky_description, write_radiance_sky, CAL_FILE};

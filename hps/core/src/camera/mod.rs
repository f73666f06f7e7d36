//! The one camera model: what a raw sample means (black level, valid range, response,
//! weights) and where it looks (Kannala-Brandt fisheye, vignetting, orientation). It is read
//! from and written to the campaign's `device.toml`, and `sim/` renders frames with this same
//! model, so the simulator and the device cannot disagree about the camera.

mod device;
mod fisheye;
mod model;

pub use device::{
    DeviceConfig, DeviceError, LensConfig, NoiseConfig, OrientationConfig, ResponseConfig,
    SensorConfig,
};
pub use fisheye::KannalaBrandt;
pub use model::{
    alt_az_from_direction, direction_from_alt_az, orientation_from_rotation, CameraModel,
    ImagePoint,
};

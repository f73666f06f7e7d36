//! `device.toml`: the camera's calibration (campaign spec, "device.toml").

use crate::camera::DeviceConfig;
use std::path::Path;

pub(super) fn device_toml(bytes: &[u8]) {
    if let Err(e) = DeviceConfig::parse(&super::checks::text(bytes), Path::new("device.toml")) {
        super::checks::assert_names(&e.to_string(), "device.toml");
    }
}

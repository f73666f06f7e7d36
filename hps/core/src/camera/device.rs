//! `device.toml` (shared/spec/campaign.md): the camera calibration as a file.
//!
//! Unknown keys are kept out of the model and reported as warnings, never errors (the format
//! is extended by later tools); malformed or missing required keys, and values that are NaN,
//! infinite or out of range, are errors that name the file and the key.

use serde::{Deserialize, Serialize};
use std::path::Path;

/// `[sensor]`: how raw samples are cleaned.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SensorConfig {
    /// Subtracted from every sample before anything else, digital numbers.
    pub black_level_dn: f64,
    /// Samples below this (before black subtraction) are not used.
    pub valid_min_dn: f64,
    /// Samples above this (before black subtraction) are not used.
    pub valid_max_dn: f64,
}

/// `[response]`: `L = cg (w_r R + w_g G + w_b B) / (t gain V(α))`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ResponseConfig {
    /// Luminance per (weighted digital number per second), cd/m² · s / DN.
    pub cg: f64,
    /// w_r, w_g, w_b.
    pub weights: [f64; 3],
}

/// `[lens]`: Kannala-Brandt fisheye and vignetting.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LensConfig {
    pub focal_px: f64,
    /// Principal point, full-array pixel coordinates (pixel (i, j) has its centre at
    /// (i + 0.5, j + 0.5)).
    pub center_px: [f64; 2],
    /// k1..k4.
    pub distortion: [f64; 4],
    /// a_0..a_n of V(α) = Σ a_i cos(α)^i.
    pub vignetting: Vec<f64>,
}

/// `[orientation]`: where the optical axis points and the roll about it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct OrientationConfig {
    /// Degrees from north towards east.
    pub axis_azimuth_deg: f64,
    /// Degrees above the horizon.
    pub axis_altitude_deg: f64,
    /// Right-handed rotation of the camera about its optical axis (the axis pointing out of
    /// the lens), degrees. 0: image up lies in the vertical plane, upward; for an axis at the
    /// zenith, image up is north.
    pub roll_deg: f64,
}

/// `[noise]` (optional; a Skylux extension of campaign.md): the sensor's noise at unity gain,
/// used for noise-optimal HDR weights and for the noise bound the tests derive.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct NoiseConfig {
    /// Digital numbers per photo-electron at unity analog gain. Default: a 12-bit full scale
    /// (4095 DN) over the full well implied by the MT9P031's 38.1 dB peak SNR
    /// (SNR_max = √N_full, so N_full = 10^(38.1/10) = 6457 e⁻): 0.634 DN/e⁻.
    pub conversion_dn_per_e: f64,
    /// Temporal read noise, DN RMS. Default 2.0: a typical figure for this sensor class, not a
    /// datasheet value; calibrate it from dark frames.
    pub read_noise_dn: f64,
}

impl Default for NoiseConfig {
    fn default() -> Self {
        Self {
            conversion_dn_per_e: 4095.0 / 10f64.powf(38.1 / 10.0),
            read_noise_dn: 2.0,
        }
    }
}

/// The whole `device.toml`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DeviceConfig {
    pub sensor: SensorConfig,
    pub response: ResponseConfig,
    pub lens: LensConfig,
    pub orientation: OrientationConfig,
    #[serde(default)]
    pub noise: NoiseConfig,
}

/// Why a `device.toml` could not be used.
pub type DeviceError = crate::toml_file::TomlFileError;

const KNOWN_KEYS: &[(&str, &[&str])] = &[
    (
        "sensor",
        &["black_level_dn", "valid_min_dn", "valid_max_dn"],
    ),
    ("response", &["cg", "weights"]),
    (
        "lens",
        &["focal_px", "center_px", "distortion", "vignetting"],
    ),
    (
        "orientation",
        &["axis_azimuth_deg", "axis_altitude_deg", "roll_deg"],
    ),
    ("noise", &["conversion_dn_per_e", "read_noise_dn"]),
];

impl Default for DeviceConfig {
    /// The example of shared/spec/campaign.md: a 1136-pixel focal length, equidistant fisheye
    /// centred on the 2592 x 1944 array, facing south 16° above the horizon.
    fn default() -> Self {
        Self {
            sensor: SensorConfig {
                black_level_dn: 0.0,
                valid_min_dn: 40.0,
                valid_max_dn: 3100.0,
            },
            response: ResponseConfig {
                cg: 1.0,
                weights: [0.2, 0.7, 0.1],
            },
            lens: LensConfig {
                focal_px: 1136.0,
                center_px: [1296.0, 972.0],
                distortion: [0.0; 4],
                vignetting: vec![1.0, 0.0, 0.0, 0.0, 0.0],
            },
            orientation: OrientationConfig {
                axis_azimuth_deg: 180.0,
                axis_altitude_deg: 16.0,
                roll_deg: 0.0,
            },
            noise: NoiseConfig::default(),
        }
    }
}

impl DeviceConfig {
    /// Reads and validates a `device.toml`. Returns the configuration and one warning per
    /// unknown key.
    pub fn read(path: &Path) -> Result<(Self, Vec<String>), DeviceError> {
        let text = DeviceError::read_text(path)?;
        Self::parse(&text, path)
    }

    /// Parses and validates `device.toml` text; `path` only names the source in messages.
    pub fn parse(text: &str, path: &Path) -> Result<(Self, Vec<String>), DeviceError> {
        let parse_error = |e: toml::de::Error| DeviceError::parse(path, text, &e);
        let table: toml::Table = toml::from_str(text).map_err(parse_error)?;
        let mut warnings = vec![];
        for (key, value) in &table {
            match KNOWN_KEYS.iter().find(|(section, _)| section == key) {
                None => warnings.push(format!("{}: unknown key `{key}` ignored", path.display())),
                Some((section, keys)) => {
                    if let Some(inner) = value.as_table() {
                        for k in inner.keys().filter(|k| !keys.contains(&k.as_str())) {
                            warnings.push(format!(
                                "{}: unknown key `{section}.{k}` ignored",
                                path.display()
                            ));
                        }
                    }
                }
            }
        }
        let config: DeviceConfig = toml::from_str(text).map_err(parse_error)?;
        config.validate(path)?;
        Ok((config, warnings))
    }

    /// Writes the configuration as `device.toml`.
    pub fn write(&self, path: &Path) -> Result<(), DeviceError> {
        self.validate(path)?;
        let text = toml::to_string_pretty(self).map_err(|e| DeviceError::Parse {
            path: path.into(),
            message: e.to_string(),
        })?;
        std::fs::write(path, text).map_err(|source| DeviceError::Io {
            path: path.into(),
            source,
        })
    }

    /// Checks every value for the range the model needs.
    pub fn validate(&self, path: &Path) -> Result<(), DeviceError> {
        let bad = |field: &'static str, reason: String| {
            Err(DeviceError::Invalid {
                path: path.into(),
                field: field.into(),
                reason,
            })
        };
        let finite: [(&'static str, &[f64]); 10] = [
            ("sensor.black_level_dn", &[self.sensor.black_level_dn]),
            ("sensor.valid_min_dn", &[self.sensor.valid_min_dn]),
            ("sensor.valid_max_dn", &[self.sensor.valid_max_dn]),
            ("response.cg", &[self.response.cg]),
            ("response.weights", &self.response.weights),
            ("lens.focal_px", &[self.lens.focal_px]),
            ("lens.center_px", &self.lens.center_px),
            ("lens.distortion", &self.lens.distortion),
            ("lens.vignetting", &self.lens.vignetting),
            (
                "orientation",
                &[
                    self.orientation.axis_azimuth_deg,
                    self.orientation.axis_altitude_deg,
                    self.orientation.roll_deg,
                ],
            ),
        ];
        for (field, values) in finite {
            if let Some(v) = values.iter().find(|v| !v.is_finite()) {
                return bad(field, format!("{v} is not a finite number"));
            }
        }
        let s = &self.sensor;
        if !(0.0..=4095.0).contains(&s.black_level_dn) {
            return bad(
                "sensor.black_level_dn",
                format!("{} is outside 0..4095", s.black_level_dn),
            );
        }
        if !(s.valid_min_dn >= 0.0 && s.valid_min_dn < s.valid_max_dn && s.valid_max_dn <= 4095.0) {
            return bad(
                "sensor.valid_min_dn",
                format!(
                    "need 0 <= valid_min_dn < valid_max_dn <= 4095, got {} and {}",
                    s.valid_min_dn, s.valid_max_dn
                ),
            );
        }
        if s.valid_max_dn <= s.black_level_dn {
            return bad(
                "sensor.valid_max_dn",
                "must be above the black level".into(),
            );
        }
        if self.response.cg <= 0.0 {
            return bad(
                "response.cg",
                format!("{} must be positive", self.response.cg),
            );
        }
        if self.response.weights.iter().any(|w| *w < 0.0)
            || self.response.weights.iter().sum::<f64>() <= 0.0
        {
            return bad(
                "response.weights",
                "must be non-negative with a positive sum".into(),
            );
        }
        if self.lens.focal_px <= 0.0 {
            return bad(
                "lens.focal_px",
                format!("{} must be positive", self.lens.focal_px),
            );
        }
        if self.lens.vignetting.is_empty() || self.lens.vignetting.iter().sum::<f64>() <= 0.0 {
            return bad(
                "lens.vignetting",
                "needs at least a_0, and V(0) = sum of a_i must be positive".into(),
            );
        }
        let n = &self.noise;
        if !(n.conversion_dn_per_e.is_finite() && n.conversion_dn_per_e > 0.0) {
            return bad(
                "noise.conversion_dn_per_e",
                format!("{} must be a positive number", n.conversion_dn_per_e),
            );
        }
        if !(n.read_noise_dn.is_finite() && n.read_noise_dn >= 0.0) {
            return bad(
                "noise.read_noise_dn",
                format!("{} must be a non-negative number", n.read_noise_dn),
            );
        }
        if !(-90.0..=90.0).contains(&self.orientation.axis_altitude_deg) {
            return bad(
                "orientation.axis_altitude_deg",
                format!("{} is outside -90..90", self.orientation.axis_altitude_deg),
            );
        }
        Ok(())
    }
}

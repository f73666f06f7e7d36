//! `campaign.toml` and the whole campaign folder (shared/spec/campaign.md): site, file
//! index, captures in time order, lux-meter readings and the optional pyranometer record.

use super::luxmeters::{read_luxmeters, LuxmeterReading};
use super::CaptureConfig;
use crate::io::irradiance::{read_pyranometer_file, PyranometerTable};
use crate::toml_file::TomlFileError;
use chrono::{DateTime, FixedOffset};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// Where the campaign was measured.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Site {
    /// North positive.
    pub latitude_deg: f64,
    /// East positive.
    pub longitude_deg: f64,
    #[serde(default)]
    pub elevation_m: f64,
}

/// The file index, relative to the campaign folder; every entry has the spec's default.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct CampaignFiles {
    pub device: String,
    pub scene: String,
    pub sensors: String,
    pub captures: String,
    pub luxmeters: String,
    pub pyranometer: String,
}

impl Default for CampaignFiles {
    fn default() -> Self {
        Self {
            device: "device.toml".into(),
            scene: "room/scene.rad".into(),
            sensors: "room/sensors.pts".into(),
            captures: "captures".into(),
            luxmeters: "luxmeters.csv".into(),
            pyranometer: "pyranometer.csv".into(),
        }
    }
}

/// `campaign.toml`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CampaignConfig {
    pub name: String,
    pub site: Site,
    #[serde(default)]
    pub files: CampaignFiles,
}

/// Why a campaign could not be read.
#[derive(Debug, thiserror::Error)]
pub enum CampaignError {
    /// `campaign.toml`, a `capture.toml`, or the captures folder.
    #[error(transparent)]
    File(#[from] TomlFileError),
    #[error(transparent)]
    Luxmeters(#[from] super::luxmeters::LuxmeterError),
    #[error(transparent)]
    Pyranometer(#[from] crate::io::irradiance::IrradianceError),
}

impl CampaignConfig {
    pub fn read(path: &Path) -> Result<Self, CampaignError> {
        let text = TomlFileError::read_text(path)?;
        Self::parse(&text, path)
    }

    /// Parses and validates; unknown keys are ignored (the spec: a warning, never an error).
    pub fn parse(text: &str, path: &Path) -> Result<Self, CampaignError> {
        let c: Self = toml::from_str(text)
            .map_err(|e: toml::de::Error| TomlFileError::parse(path, text, &e))?;
        let bad = |field: &str, reason: String| {
            Err(CampaignError::File(TomlFileError::Invalid {
                path: path.into(),
                field: field.into(),
                reason,
            }))
        };
        if !(c.site.latitude_deg.is_finite() && c.site.latitude_deg.abs() <= 90.0) {
            return bad(
                "site.latitude_deg",
                format!("{} is not in [-90, 90]", c.site.latitude_deg),
            );
        }
        if !(c.site.longitude_deg.is_finite() && c.site.longitude_deg.abs() <= 180.0) {
            return bad(
                "site.longitude_deg",
                format!("{} is not in [-180, 180]", c.site.longitude_deg),
            );
        }
        if !c.site.elevation_m.is_finite() {
            return bad("site.elevation_m", "must be a number".into());
        }
        Ok(c)
    }

    pub fn write(&self, path: &Path) -> Result<(), CampaignError> {
        let text = toml::to_string(self).map_err(|e| TomlFileError::Parse {
            path: path.into(),
            message: e.to_string(),
        })?;
        std::fs::write(path, text).map_err(|source| {
            CampaignError::File(TomlFileError::Io {
                path: path.into(),
                source,
            })
        })
    }
}

/// One capture folder with its parsed `capture.toml`.
#[derive(Clone, Debug)]
pub struct CaptureEntry {
    pub dir: PathBuf,
    pub time: DateTime<FixedOffset>,
    pub config: CaptureConfig,
}

/// A campaign folder, read and checked (frames are read later, capture by capture).
#[derive(Clone, Debug)]
pub struct Campaign {
    pub dir: PathBuf,
    pub config: CampaignConfig,
    /// In time order.
    pub captures: Vec<CaptureEntry>,
    pub luxmeters: Vec<LuxmeterReading>,
    /// Gaps (empty lux fields) skipped in `luxmeters.csv`.
    pub luxmeter_gaps: usize,
    pub pyranometer: Option<PyranometerTable>,
}

impl Campaign {
    pub fn open(dir: &Path) -> Result<Self, CampaignError> {
        let config = CampaignConfig::read(&dir.join("campaign.toml"))?;
        let captures_dir = dir.join(&config.files.captures);
        let listing = std::fs::read_dir(&captures_dir).map_err(|source| TomlFileError::Io {
            path: captures_dir.clone(),
            source,
        })?;
        let mut captures = Vec::new();
        for entry in listing {
            let entry = entry.map_err(|source| TomlFileError::Io {
                path: captures_dir.clone(),
                source,
            })?;
            let sub = entry.path();
            let toml_path = sub.join("capture.toml");
            if !toml_path.is_file() {
                continue;
            }
            let capture = CaptureConfig::read(&toml_path)?;
            let time = DateTime::parse_from_rfc3339(&capture.time).map_err(|e| {
                TomlFileError::Invalid {
                    path: toml_path.clone(),
                    field: "time".into(),
                    reason: format!("`{}` is not RFC 3339 with an offset: {e}", capture.time),
                }
            })?;
            captures.push(CaptureEntry {
                dir: sub,
                time,
                config: capture,
            });
        }
        captures.sort_by_key(|c| c.time);
        if captures.is_empty() {
            return Err(TomlFileError::Invalid {
                path: captures_dir,
                field: "captures".into(),
                reason: "no capture folder with a capture.toml".into(),
            }
            .into());
        }
        let (luxmeters, luxmeter_gaps) = read_luxmeters(&dir.join(&config.files.luxmeters))?;
        let pyr_path = dir.join(&config.files.pyranometer);
        let pyranometer = if pyr_path.is_file() {
            Some(read_pyranometer_file(&pyr_path)?)
        } else {
            None
        };
        Ok(Self {
            dir: dir.into(),
            config,
            captures,
            luxmeters,
            luxmeter_gaps,
            pyranometer,
        })
    }

    pub fn path(&self, relative: &str) -> PathBuf {
        self.dir.join(relative)
    }
}

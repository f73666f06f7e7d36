//! `captures/<stamp>/capture.toml`: one HDR capture (campaign.md).

use serde::{Deserialize, Serialize};
use std::path::Path;

/// Colours of the first 2x2 block of the raw frames.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum BayerPattern {
    GRBG,
    RGGB,
    BGGR,
    GBRG,
}

/// Colour channel of a Bayer sample.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Channel {
    Red,
    Green,
    Blue,
}

impl BayerPattern {
    /// Channel of the sample at (dx, dy) inside a 2x2 block.
    pub fn channel(self, dx: usize, dy: usize) -> Channel {
        use Channel::*;
        let layout = match self {
            BayerPattern::GRBG => [Green, Red, Blue, Green],
            BayerPattern::RGGB => [Red, Green, Green, Blue],
            BayerPattern::BGGR => [Blue, Green, Green, Red],
            BayerPattern::GBRG => [Green, Blue, Red, Green],
        };
        layout[(dy & 1) * 2 + (dx & 1)]
    }

    /// Offsets (dx, dy) of the red sample, the two green samples and the blue sample.
    pub fn offsets(self) -> [(usize, usize); 4] {
        let mut r = (0, 0);
        let mut g = vec![];
        let mut b = (0, 0);
        for dy in 0..2 {
            for dx in 0..2 {
                match self.channel(dx, dy) {
                    Channel::Red => r = (dx, dy),
                    Channel::Green => g.push((dx, dy)),
                    Channel::Blue => b = (dx, dy),
                }
            }
        }
        [r, g[0], g[1], b]
    }
}

/// `[readout]`: which part of the active array the frames hold.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Readout {
    pub col_start: u32,
    pub row_start: u32,
    /// 1: every pixel; k: read 2 columns/rows, skip 2(k − 1).
    pub skip: u32,
    /// The MT9P031's binning (an extension of campaign.md, docs/readout.md): each sample is
    /// the mean of `bin` x `bin` same-colour pixels from the start of its `skip` block, so a
    /// group integrates the 2 bin x 2 bin pixels it starts with. 1 (the default, and what a
    /// file without the key means), 2 or 4, dividing `skip`.
    #[serde(default = "one", skip_serializing_if = "is_one")]
    pub bin: u32,
}

fn one() -> u32 {
    1
}

fn is_one(v: &u32) -> bool {
    *v == 1
}

impl Readout {
    /// A readout without binning.
    pub fn skipping(col_start: u32, row_start: u32, skip: u32) -> Self {
        Self {
            col_start,
            row_start,
            skip,
            bin: 1,
        }
    }

    /// The binning the Linux driver picks for `skip`: the largest of 4, 2, 1 that divides it
    /// (hardware-facts.md §1, "Binning rule").
    pub fn largest_bin(skip: u32) -> u32 {
        [4, 2, 1]
            .into_iter()
            .find(|b| skip.is_multiple_of(*b))
            .unwrap_or(1)
    }

    /// Full-array coordinate (pixel edges, the first pixel spans 0..1) of the centre of group
    /// `g`'s sensitive area along one axis: its first raw sample's pixel plus `bin` (the
    /// 2 bin pixels it integrates; 2 pixels without binning).
    pub fn group_centre(start: u32, skip: u32, bin: u32, g: u32) -> f64 {
        f64::from(Self::active_coordinate(start, skip, 2 * g)) + f64::from(bin.max(1))
    }

    /// Checks the binning against the sensor's rule (hardware-facts.md §1 "Binning rule":
    /// 1x, 2x or 4x, dividing the skip factor).
    pub fn check_bin(&self) -> Result<(), String> {
        if matches!(self.bin, 1 | 2 | 4) && self.skip.is_multiple_of(self.bin) {
            Ok(())
        } else {
            Err(format!(
                "bin = {} must be 1, 2 or 4 and divide skip = {}",
                self.bin, self.skip
            ))
        }
    }

    /// Full-array coordinate of raw column (or row) `i` (campaign.md:
    /// `start + (i / 2) * 2k + (i % 2)`).
    pub fn active_coordinate(start: u32, skip: u32, i: u32) -> u32 {
        start + (i / 2) * 2 * skip + (i % 2)
    }
}

/// One `[[exposure]]` entry.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ExposureEntry {
    pub file: String,
    /// Commanded integration time, as written to the sensor, µs.
    pub exposure_us: f64,
    /// Analog gain.
    pub gain: f64,
    /// Start of this exposure after the capture's `time`, ms.
    #[serde(default)]
    pub offset_ms: f64,
}

/// The whole `capture.toml`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CaptureConfig {
    /// Start of the exposure sequence, RFC 3339 with an explicit offset.
    pub time: String,
    pub bayer: BayerPattern,
    pub sensor_temperature_c: Option<f64>,
    pub readout: Readout,
    pub exposure: Vec<ExposureEntry>,
}

/// Why a capture could not be used.
pub type CaptureError = crate::toml_file::TomlFileError;

impl CaptureConfig {
    /// Reads and validates `capture.toml`.
    pub fn read(path: &Path) -> Result<Self, CaptureError> {
        let text = CaptureError::read_text(path)?;
        Self::parse(&text, path)
    }

    /// Writes `capture.toml` (after validating it, so no tool writes what it would refuse).
    pub fn write(&self, path: &Path) -> Result<(), CaptureError> {
        let text = toml::to_string(self).map_err(|e| CaptureError::Parse {
            path: path.into(),
            message: e.to_string(),
        })?;
        Self::parse(&text, path)?;
        std::fs::write(path, text).map_err(|source| CaptureError::Io {
            path: path.into(),
            source,
        })
    }

    /// Parses and validates `capture.toml` text; `path` names the source in messages.
    pub fn parse(text: &str, path: &Path) -> Result<Self, CaptureError> {
        let config: Self = toml::from_str(text)
            .map_err(|e: toml::de::Error| CaptureError::parse(path, text, &e))?;
        let bad = |field: String, reason: String| {
            Err(CaptureError::Invalid {
                path: path.into(),
                field,
                reason,
            })
        };
        if config.exposure.is_empty() {
            return bad(
                "exposure".into(),
                "a capture needs at least one [[exposure]]".into(),
            );
        }
        if config.readout.skip == 0
            || !config.readout.col_start.is_multiple_of(2)
            || !config.readout.row_start.is_multiple_of(2)
        {
            return bad(
                "readout".into(),
                "skip must be at least 1 and the starts even".into(),
            );
        }
        if let Err(reason) = config.readout.check_bin() {
            return bad("readout.bin".into(), reason);
        }
        for (i, e) in config.exposure.iter().enumerate() {
            if !(e.exposure_us.is_finite() && e.exposure_us > 0.0) {
                return bad(
                    format!("exposure[{i}].exposure_us"),
                    format!("{} must be a positive number", e.exposure_us),
                );
            }
            if !(e.gain.is_finite() && e.gain > 0.0) {
                return bad(
                    format!("exposure[{i}].gain"),
                    format!("{} must be a positive number", e.gain),
                );
            }
            if !e.offset_ms.is_finite() {
                return bad(
                    format!("exposure[{i}].offset_ms"),
                    "must be a finite number".into(),
                );
            }
            if e.file.is_empty() || e.file.contains("..") || Path::new(&e.file).is_absolute() {
                return bad(
                    format!("exposure[{i}].file"),
                    format!("{:?} must name a file inside the capture folder", e.file),
                );
            }
        }
        Ok(config)
    }
}

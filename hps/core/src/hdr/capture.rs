//! A capture folder (campaign.md `captures/<stamp>/`) to a luminance map: the path every
//! tool shares (`skylux hdr`, the daemon, the loop).

use super::{merge, Exposure, GroupGeometry, HdrError, LuminanceMap};
use crate::camera::{CameraModel, DeviceConfig};
use crate::campaign::{CaptureConfig, CaptureError, RawFrame, RawFrameError};
use std::path::{Path, PathBuf};

/// Why a capture could not be turned into a map. Every variant names the file.
#[derive(Debug, thiserror::Error)]
pub enum CaptureMapError {
    #[error(transparent)]
    Capture(#[from] CaptureError),
    #[error(transparent)]
    Frame(#[from] RawFrameError),
    #[error("{path}: {width}x{height} samples, but {first} is {first_width}x{first_height}: all exposures of a capture must match")]
    SizeMismatch {
        path: PathBuf,
        width: usize,
        height: usize,
        first: PathBuf,
        first_width: usize,
        first_height: usize,
    },
    #[error("{capture}: {source}")]
    Merge { capture: PathBuf, source: HdrError },
}

/// A merged capture.
pub struct CaptureMap {
    pub capture: CaptureConfig,
    pub map: LuminanceMap,
    pub geometry: GroupGeometry,
}

/// Reads `dir/capture.toml` and its frames and merges them with `device`.
pub fn map_capture(dir: &Path, device: &DeviceConfig) -> Result<CaptureMap, CaptureMapError> {
    let toml_path = dir.join("capture.toml");
    let capture = CaptureConfig::read(&toml_path)?;
    let mut frames = Vec::with_capacity(capture.exposure.len());
    for entry in &capture.exposure {
        let path = dir.join(&entry.file);
        let frame = RawFrame::read(&path)?;
        if let Some((first_path, first)) = frames
            .first()
            .map(|(p, f): &(PathBuf, RawFrame)| (p.clone(), f))
        {
            if (frame.width, frame.height) != (first.width, first.height) {
                return Err(CaptureMapError::SizeMismatch {
                    path,
                    width: frame.width,
                    height: frame.height,
                    first: first_path,
                    first_width: first.width,
                    first_height: first.height,
                });
            }
        }
        frames.push((path, frame));
    }
    let camera = CameraModel::new(device.clone());
    let (w, h) = (frames[0].1.width, frames[0].1.height);
    let geometry = GroupGeometry::new(&camera, &capture.readout, w, h);
    let exposures: Vec<Exposure> = frames
        .iter()
        .zip(&capture.exposure)
        .map(|((_, f), e)| Exposure {
            frame: f,
            exposure_s: e.exposure_us * 1e-6,
            gain: e.gain,
        })
        .collect();
    let map = merge(&exposures, device, capture.bayer, &geometry).map_err(|source| {
        CaptureMapError::Merge {
            capture: toml_path,
            source,
        }
    })?;
    Ok(CaptureMap {
        capture,
        map,
        geometry,
    })
}

//! Writes simulated captures in the campaign format (shared/spec/campaign.md), so every tool
//! reads simulated data through the same reader as field data.

use skylux_hps::campaign::{CaptureConfig, CaptureError, RawFrame, RawFrameError};
use std::path::Path;

/// Why a capture could not be written.
#[derive(Debug, thiserror::Error)]
pub enum WriteCaptureError {
    #[error("{path}: {source}")]
    Io {
        path: std::path::PathBuf,
        source: std::io::Error,
    },
    #[error(transparent)]
    Capture(#[from] CaptureError),
    #[error(transparent)]
    Frame(#[from] RawFrameError),
    #[error("{0} frames for {1} exposure entries")]
    Count(usize, usize),
}

/// Writes `dir/capture.toml` and one PGM per exposure (the entries' `file` names).
pub fn write_capture(
    dir: &Path,
    capture: &CaptureConfig,
    frames: &[RawFrame],
) -> Result<(), WriteCaptureError> {
    if frames.len() != capture.exposure.len() {
        return Err(WriteCaptureError::Count(
            frames.len(),
            capture.exposure.len(),
        ));
    }
    std::fs::create_dir_all(dir).map_err(|source| WriteCaptureError::Io {
        path: dir.into(),
        source,
    })?;
    for (entry, frame) in capture.exposure.iter().zip(frames) {
        frame.write(&dir.join(&entry.file))?;
    }
    capture.write(&dir.join("capture.toml"))?;
    Ok(())
}

/// What to simulate: a readout window, its size and the exposure ladder.
#[derive(Clone, Debug)]
pub struct CaptureSpec {
    pub time: String,
    pub readout: skylux_hps::campaign::Readout,
    pub raw_width: usize,
    pub raw_height: usize,
    pub exposures_us: Vec<f64>,
    pub gain: f64,
    pub seed: u64,
    /// How each group integrates the scene (real pixels: `Footprint::Integrated`).
    pub footprint: crate::sensor::Footprint,
}

/// Renders one HDR capture of `field` through `camera` with the sensor's noise and writes it
/// to `dir` in the campaign format. Returns what was written.
pub fn simulate_capture(
    dir: &Path,
    camera: &skylux_hps::camera::CameraModel,
    field: &(dyn Fn(glam::DVec3) -> f64 + Sync),
    spec: &CaptureSpec,
) -> Result<CaptureConfig, WriteCaptureError> {
    use crate::sensor::{FrameRenderer, Noise};
    use skylux_hps::campaign::{BayerPattern, ExposureEntry};
    let renderer = FrameRenderer {
        camera,
        readout: spec.readout,
        raw_width: spec.raw_width,
        raw_height: spec.raw_height,
        footprint: spec.footprint,
    };
    let scene = renderer.scene(field);
    let frames: Vec<RawFrame> = spec
        .exposures_us
        .iter()
        .enumerate()
        .map(|(k, &t)| {
            renderer.render_scene(
                &scene,
                t * 1e-6,
                spec.gain,
                Noise::Sensor {
                    seed: spec.seed.wrapping_add(k as u64),
                },
            )
        })
        .collect();
    let capture = CaptureConfig {
        time: spec.time.clone(),
        bayer: BayerPattern::GRBG,
        sensor_temperature_c: None,
        readout: spec.readout,
        exposure: spec
            .exposures_us
            .iter()
            .enumerate()
            .map(|(k, &t)| ExposureEntry {
                file: format!("e{k}.pgm"),
                exposure_us: t,
                gain: spec.gain,
                offset_ms: 0.0,
            })
            .collect(),
    };
    write_capture(dir, &capture, &frames)?;
    Ok(capture)
}

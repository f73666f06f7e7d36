//! Writes simulated captures in the campaign format (shared/spec/campaign.md), so every tool
//! reads simulated data through the same reader as field data.

use skylux_hps::campaign::{CaptureConfig, RawFrame, RawFrameError};
use skylux_hps::toml_file::TomlFileError;
use std::path::Path;

/// Why a capture could not be written.
#[derive(Debug, thiserror::Error)]
pub enum WriteCaptureError {
    #[error("{path}: {source}")]
    Io {
        path: std::path::PathBuf,
        source: std::io::Error,
    },
    /// `capture.toml` or `device.toml`.
    #[error(transparent)]
    File(#[from] TomlFileError),
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
    /// Analog gain per exposure; a single value applies to every exposure.
    pub gains: Vec<f64>,
    pub seed: u64,
    /// How each group integrates the scene (real pixels: `Footprint::Integrated`).
    pub footprint: crate::sensor::Footprint,
    /// Sources that may be smaller than a group (the solar disk; `Footprint::AsRead`).
    pub small_sources: Vec<crate::sensor::SmallSource>,
}

impl CaptureSpec {
    /// The analog gain of exposure `k` (`gains[k]`, or the one gain of all; 1 when none).
    pub fn gain_of(&self, k: usize) -> f64 {
        match self.gains.as_slice() {
            [] => 1.0,
            [g] => *g,
            gains => gains.get(k).copied().unwrap_or(1.0),
        }
    }

    /// The frame renderer for this capture's readout through `camera`.
    pub fn renderer<'a>(
        &self,
        camera: &'a skylux_hps::camera::CameraModel,
    ) -> crate::sensor::FrameRenderer<'a> {
        crate::sensor::FrameRenderer {
            camera,
            readout: self.readout,
            raw_width: self.raw_width,
            raw_height: self.raw_height,
            footprint: self.footprint,
            small_sources: self.small_sources.clone(),
        }
    }
}

/// Renders one HDR capture of `field` through `camera` with the sensor's noise and writes it
/// to `dir` in the campaign format. Returns what was written.
pub fn simulate_capture(
    dir: &Path,
    camera: &skylux_hps::camera::CameraModel,
    field: &(dyn Fn(glam::DVec3) -> f64 + Sync),
    spec: &CaptureSpec,
) -> Result<CaptureConfig, WriteCaptureError> {
    let (capture, frames) = simulate_frames(camera, field, spec);
    write_capture(dir, &capture, &frames)?;
    Ok(capture)
}

/// [`simulate_capture`] in memory: the capture's configuration (the files it would be
/// written as) and its frames, as a camera hands them over without a disk.
pub fn simulate_frames(
    camera: &skylux_hps::camera::CameraModel,
    field: &(dyn Fn(glam::DVec3) -> f64 + Sync),
    spec: &CaptureSpec,
) -> (CaptureConfig, Vec<RawFrame>) {
    use crate::sensor::Noise;
    let renderer = spec.renderer(camera);
    let scene = renderer.scene(field);
    let frames: Vec<RawFrame> = spec
        .exposures_us
        .iter()
        .enumerate()
        .map(|(k, &t)| {
            renderer.render_scene(
                &scene,
                t * 1e-6,
                spec.gain_of(k),
                Noise::Sensor {
                    seed: spec.seed.wrapping_add(k as u64),
                },
            )
        })
        .collect();
    (spec_config(spec), frames)
}

/// Writes `frames` (one per exposure of `spec`, GRBG) as the capture folder `dir`, named
/// `e0.pgm`, `e1.pgm`, ... as campaign.md lays them out. Returns the capture's configuration.
pub(crate) fn write_spec_capture(
    dir: &Path,
    spec: &CaptureSpec,
    frames: &[RawFrame],
) -> Result<CaptureConfig, WriteCaptureError> {
    let capture = spec_config(spec);
    write_capture(dir, &capture, frames)?;
    Ok(capture)
}

/// The `capture.toml` of a capture made to `spec`.
fn spec_config(spec: &CaptureSpec) -> CaptureConfig {
    use skylux_hps::campaign::{BayerPattern, ExposureEntry};
    CaptureConfig {
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
                gain: spec.gain_of(k),
                offset_ms: 0.0,
            })
            .collect(),
    }
}

/// A small example capture (a 128x96 window of a sky with the sun, three exposures) and its
/// `device.toml` (the campaign spec's example camera) in `dir`: a quick, complete input for
/// the tools' tests. Returns the camera configuration written.
pub fn write_example_capture(
    dir: &Path,
    seed: u64,
) -> Result<skylux_hps::camera::DeviceConfig, WriteCaptureError> {
    use skylux_hps::camera::{CameraModel, DeviceConfig};
    let device = DeviceConfig::default();
    let sky = crate::sky::SimulatedSky {
        zenith_luminance_cd_m2: 5000.0,
        sun_direction: glam::DVec3::new(0.0, -0.9, 0.3).normalize(),
        sun_luminance_cd_m2: 1.6e9,
        sun_radius_deg: 0.2665,
        ground_luminance_cd_m2: 1000.0,
    };
    let spec = CaptureSpec {
        time: "2017-05-08T10:00:00+02:00".into(),
        readout: skylux_hps::campaign::Readout {
            col_start: 1200,
            row_start: 900,
            skip: 1,
            bin: 1,
        },
        raw_width: 128,
        raw_height: 96,
        exposures_us: vec![10.0, 1000.0, 100_000.0],
        gains: vec![1.0],
        seed,
        footprint: crate::sensor::Footprint::Integrated,
        small_sources: vec![],
    };
    simulate_capture(
        dir,
        &CameraModel::new(device.clone()),
        &move |d| sky.luminance_cd_m2(d),
        &spec,
    )?;
    device.write(&dir.join("device.toml"))?;
    Ok(device)
}

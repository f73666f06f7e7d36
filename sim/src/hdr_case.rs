//! The full-frame HDR case that `skylux bench hdr` and the criterion bench
//! (`cargo bench -p skylux-tests --bench hdr_merge`) share, so both time the same work: five
//! noisy 2592x1944 frames from 1 µs to 500 ms of a log-ramp field from 1.2e2 to 3.8e9 cd/m²
//! (150 dB), rendered by the sensor model through a 600 px fisheye.

use crate::sensor::{FrameRenderer, Noise};
use glam::DVec3;
use skylux_hps::camera::{CameraModel, DeviceConfig, OrientationConfig};
use skylux_hps::campaign::{RawFrame, Readout};
use skylux_hps::hdr::{Exposure, GroupGeometry};
use std::time::Instant;

/// Integration times of the five frames, s: a geometric series from 1 µs to 500 ms.
pub const EXPOSURES_S: [f64; 5] = [1e-6, 2.659_148e-5, 7.071_068e-4, 1.880_302e-2, 0.5];
/// The MT9P031's full active array (hardware-facts.md §1).
pub const WIDTH_PX: usize = 2592;
pub const HEIGHT_PX: usize = 1944;
/// The field's range, cd/m²: a dim façade to the solar disc (issue 4).
pub const FIELD_MIN_CD_M2: f64 = 1.2e2;
pub const FIELD_MAX_CD_M2: f64 = 3.8e9;

/// The case: the device, its per-group geometry (computed once per camera) and the frames.
pub struct HdrCase {
    pub device: DeviceConfig,
    pub camera: CameraModel,
    pub readout: Readout,
    pub geometry: GroupGeometry,
    /// Time the one-off geometry took, ms.
    pub geometry_ms: f64,
    pub frames: Vec<RawFrame>,
    ramp_axis: DVec3,
    ramp_lo: f64,
    ramp_hi: f64,
}

impl HdrCase {
    /// Renders the five frames (with the sensor's noise; seeds fixed).
    pub fn new() -> Self {
        let mut device = DeviceConfig::default();
        device.response.cg = 1.4;
        device.sensor.black_level_dn = 10.0;
        device.sensor.valid_min_dn = 50.0;
        device.sensor.valid_max_dn = 3110.0;
        device.lens.focal_px = 600.0;
        device.lens.vignetting = vec![0.6, 0.3, 0.1, 0.0, 0.0];
        device.orientation = OrientationConfig {
            axis_azimuth_deg: 0.0,
            axis_altitude_deg: 90.0,
            roll_deg: 0.0,
        };
        let camera = CameraModel::new(device.clone());
        let readout = Readout {
            col_start: 0,
            row_start: 0,
            skip: 1,
            bin: 1,
        };
        let start = Instant::now();
        let geometry = GroupGeometry::new(&camera, &readout, WIDTH_PX, HEIGHT_PX);
        let geometry_ms = start.elapsed().as_secs_f64() * 1e3;

        // The log ramp runs along this axis across the directions the lens sees.
        let ramp_axis = DVec3::new(1.0, 0.4, 0.2).normalize();
        let (ramp_lo, ramp_hi) = geometry
            .direction
            .iter()
            .filter(|d| d.is_finite())
            .map(|d| d.as_dvec3().dot(ramp_axis))
            .fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
        let mut case = HdrCase {
            device,
            camera,
            readout,
            geometry,
            geometry_ms,
            frames: Vec::new(),
            ramp_axis,
            ramp_lo,
            ramp_hi,
        };
        let renderer = FrameRenderer {
            camera: &case.camera,
            readout: case.readout,
            raw_width: WIDTH_PX,
            raw_height: HEIGHT_PX,
            footprint: Default::default(),
            small_sources: vec![],
        };
        let frames = EXPOSURES_S
            .iter()
            .enumerate()
            .map(|(k, &t)| {
                renderer.render(
                    &|d| case.truth_cd_m2(d),
                    t,
                    1.0,
                    Noise::Sensor {
                        seed: 100 + k as u64,
                    },
                )
            })
            .collect();
        case.frames = frames;
        case
    }

    /// The true luminance in direction `d`, cd/m².
    pub fn truth_cd_m2(&self, d: DVec3) -> f64 {
        let s = ((d.dot(self.ramp_axis) - self.ramp_lo) / (self.ramp_hi - self.ramp_lo))
            .clamp(0.0, 1.0);
        FIELD_MIN_CD_M2 * (FIELD_MAX_CD_M2 / FIELD_MIN_CD_M2).powf(s)
    }

    /// The frames as the merge takes them (unit gain).
    pub fn exposures(&self) -> Vec<Exposure<'_>> {
        self.frames
            .iter()
            .zip(EXPOSURES_S)
            .map(|(frame, exposure_s)| Exposure {
                frame,
                exposure_s,
                gain: 1.0,
            })
            .collect()
    }
}

impl Default for HdrCase {
    fn default() -> Self {
        Self::new()
    }
}

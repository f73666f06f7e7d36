//! The HDR path through files: a simulated capture written in the campaign format, read back
//! by the one campaign reader, merged, written as OpenEXR and read back.

use skylux_hps::camera::{CameraModel, DeviceConfig};
use skylux_hps::campaign::Readout;
use skylux_hps::hdr::{map_capture, read_exr, MapFlag};
use skylux_sim::capture::{simulate_capture, CaptureSpec};
use skylux_sim::sky::SimulatedSky;
use std::path::Path;

/// A small simulated capture of a sky with the sun, and its device.toml, in `dir`.
pub fn simulate(dir: &Path) -> DeviceConfig {
    let device = DeviceConfig::default();
    let camera = CameraModel::new(device.clone());
    let sky = SimulatedSky {
        zenith_luminance_cd_m2: 5000.0,
        sun_direction: glam::DVec3::new(0.0, -0.9, 0.3).normalize(),
        sun_luminance_cd_m2: 1.6e9,
        sun_radius_deg: 0.2665,
        ground_luminance_cd_m2: 1000.0,
    };
    let spec = CaptureSpec {
        time: "2017-05-08T10:00:00+02:00".into(),
        readout: Readout {
            col_start: 1200,
            row_start: 900,
            skip: 1,
        },
        raw_width: 128,
        raw_height: 96,
        exposures_us: vec![10.0, 1000.0, 100_000.0],
        gain: 1.0,
        seed: 7,
        footprint: skylux_sim::sensor::Footprint::Integrated,
    };
    simulate_capture(dir, &camera, &move |d| sky.luminance_cd_m2(d), &spec).unwrap();
    device.write(&dir.join("device.toml")).unwrap();
    device
}

#[test]
fn capture_files_merge_and_round_trip_through_exr() {
    let dir = tempfile::tempdir().unwrap();
    let device = simulate(dir.path());
    let merged = map_capture(dir.path(), &device).unwrap();
    assert_eq!((merged.map.width, merged.map.height), (64, 48));
    assert!(
        merged
            .map
            .flags
            .iter()
            .filter(|f| **f == MapFlag::Valid)
            .count()
            > 3000
    );
    let out = dir.path().join("map.exr");
    skylux_hps::hdr::write_exr(&out, &merged.map, &device, &merged.capture.readout).unwrap();
    let (back, back_device, back_readout) = read_exr(&out).unwrap();
    assert_eq!(back_device, device);
    assert_eq!(back_readout, merged.capture.readout);
    assert_eq!(back.flags, merged.map.flags);
    for (a, b) in back.luminance_cd_m2.iter().zip(&merged.map.luminance_cd_m2) {
        assert!(a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()));
    }
}

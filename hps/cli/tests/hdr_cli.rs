//! `skylux hdr` on a simulated capture, and the errors a user will meet.

use skylux_hps::camera::{CameraModel, DeviceConfig};
use skylux_hps::campaign::Readout;
use skylux_sim::capture::{simulate_capture, CaptureSpec};
use skylux_sim::sky::SimulatedSky;
use std::process::Command;

fn skylux(args: &[&str]) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(args)
        .env("RUST_BACKTRACE", "0")
        .output()
        .unwrap();
    (
        out.status.success(),
        format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ),
    )
}

#[test]
fn hdr_command_writes_a_map_and_reports_bad_input_clearly() {
    let dir = tempfile::tempdir().unwrap();
    let device = DeviceConfig::default();
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
        seed: 1,
        footprint: skylux_sim::sensor::Footprint::Integrated,
    };
    simulate_capture(
        dir.path(),
        &CameraModel::new(device.clone()),
        &move |d| sky.luminance_cd_m2(d),
        &spec,
    )
    .unwrap();
    device.write(&dir.path().join("device.toml")).unwrap();

    let d = dir.path().to_str().unwrap();
    let device_path = format!("{d}/device.toml");
    let out = format!("{d}/map.exr");
    let sky = format!("{d}/radiance");
    let (ok, text) = skylux(&[
        "hdr",
        d,
        "--device",
        &device_path,
        "--out",
        &out,
        "--radiance-sky",
        &sky,
    ]);
    assert!(
        ok && text.contains("64x48 groups from 3 exposures") && text.contains("patches filled"),
        "{text}"
    );
    assert!(std::path::Path::new(&out).exists());
    for f in ["sky.hdr", "sky.rad", "skylux_sky.cal"] {
        assert!(std::path::Path::new(&sky).join(f).exists(), "{f}");
    }
    // A missing frame, a frame of the wrong size, a broken device.toml, a missing capture.
    std::fs::remove_file(dir.path().join("e1.pgm")).unwrap();
    let (ok, text) = skylux(&["hdr", d, "--device", &device_path, "--out", &out]);
    assert!(!ok && text.contains("e1.pgm"), "{text}");
    skylux_hps::campaign::RawFrame::new(64, 48)
        .write(&dir.path().join("e1.pgm"))
        .unwrap();
    let (ok, text) = skylux(&["hdr", d, "--device", &device_path, "--out", &out]);
    assert!(
        !ok && text.contains("e1.pgm: 64x48 samples") && text.contains("must match"),
        "{text}"
    );
    let (ok, text) = skylux(&[
        "hdr",
        "/nonexistent/capture",
        "--device",
        &device_path,
        "--out",
        &out,
    ]);
    assert!(
        !ok && text.contains("/nonexistent/capture/capture.toml"),
        "{text}"
    );
    std::fs::write(&device_path, "[sensor]\nblack_level_dn = nan\n").unwrap();
    let (ok, text) = skylux(&["hdr", d, "--device", &device_path, "--out", &out]);
    assert!(!ok && text.contains("device.toml"), "{text}");
    assert!(!text.contains("panicked"), "{text}");
}

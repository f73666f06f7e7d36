//! `skylux calibrate` as a user runs it: the spectral step on the shared Nikon D5100
//! sensitivities (NPL measurement, via colour-science; see shared/data/README.md), and the
//! geometry step on correspondences written from a known camera.

use skylux_hps::camera::{alt_az_from_direction, CameraModel, DeviceConfig, ImagePoint};
use std::path::PathBuf;
use std::process::{Command, Output};

fn skylux(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(args)
        .output()
        .expect("running the skylux binary")
}

fn data_dir() -> PathBuf {
    let dir = std::env::var_os("SKYLUX_DATA_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data"));
    assert!(
        dir.join("spectral").is_dir(),
        "{} not found: set SKYLUX_DATA_DIR to the shared data folder",
        dir.display()
    );
    dir
}

#[test]
fn spectral_writes_device_toml_and_both_reports() {
    let tmp = tempfile::tempdir().unwrap();
    let data = data_dir();
    let sens = data.join("spectral/camera_sensitivity_nikon_5100_npl.csv");
    let out = tmp.path().join("out");
    let o = skylux(&[
        "calibrate",
        "spectral",
        "--sensitivities",
        sens.to_str().unwrap(),
        "--data",
        data.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(stdout.contains("f1'"), "{stdout}");
    let (device, _) = DeviceConfig::read(&out.join("device.toml")).unwrap();
    assert_ne!(
        device.response.weights,
        DeviceConfig::default().response.weights
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("spectral_report.json")).unwrap())
            .unwrap();
    let after = json["report"]["after"]["f1_prime_a"].as_f64().unwrap();
    let before = json["report"]["before"]["f1_prime_a"].as_f64().unwrap();
    assert!(after < before, "{after} vs {before}");
    assert!(out.join("spectral_report.md").is_file());
}

#[test]
fn geometry_fits_correspondences_and_bad_input_names_the_field() {
    let tmp = tempfile::tempdir().unwrap();
    let mut truth = DeviceConfig::default();
    truth.lens.focal_px = 1120.0;
    truth.orientation.axis_altitude_deg = 25.0;
    let camera = CameraModel::new(truth.clone());
    let mut csv = String::from("x_px,y_px,altitude_deg,azimuth_deg\n");
    for j in 0..8 {
        for i in 0..10 {
            let p = ImagePoint {
                x_px: 100.0 + 260.0 * i as f64,
                y_px: 100.0 + 250.0 * j as f64,
            };
            let (alt, az) = alt_az_from_direction(camera.unproject(p).unwrap());
            csv.push_str(&format!("{},{},{alt},{az}\n", p.x_px, p.y_px));
        }
    }
    let points = tmp.path().join("points.csv");
    std::fs::write(&points, csv).unwrap();
    let out = tmp.path().join("geo");
    let o = skylux(&[
        "calibrate",
        "geometry",
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (fitted, _) = DeviceConfig::read(&out.join("device.toml")).unwrap();
    assert!(
        (fitted.lens.focal_px - 1120.0).abs() < 0.01,
        "{}",
        fitted.lens.focal_px
    );
    assert!((fitted.orientation.axis_altitude_deg - 25.0).abs() < 1e-4);
    assert!(out.join("geometry_report.md").is_file());
    // A NaN: the error names the file, the column and the line; no panic.
    let bad = tmp.path().join("bad.csv");
    std::fs::write(&bad, "x_px,y_px,altitude_deg,azimuth_deg\n1,2,NaN,4\n").unwrap();
    let o = skylux(&[
        "calibrate",
        "geometry",
        bad.to_str().unwrap(),
        "--out",
        "unused",
    ]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(
        stderr.contains("bad.csv") && stderr.contains("altitude_deg") && stderr.contains("line 2"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
}

//! Calibration against the simulator (issue 4, item 4): `sim/` renders a uniform source
//! through a camera whose vignetting polynomial and response `cg` are known, with the
//! MT9P031's noise (shot noise at the 38.1 dB peak SNR, read noise, quantisation, clipping);
//! the calibration steps, reading the frames through the campaign format like field data,
//! must recover them within the noise. Then the check of the published calibration: 5 frames
//! of a uniform source merged with the calibrated device, 3 x 3 groups averaged, within ±2 %
//! and mean ≤ 0.8 % of the truth.

use skylux_hps::calibration::response::{
    calibrate_response, uniform_source_check, KnownSource, ResponseOptions,
};
use skylux_hps::calibration::vignetting::{calibrate_vignetting, VignettingOptions};
use skylux_hps::calibration::{write_outputs, CalibrationError};
use skylux_hps::camera::{CameraModel, DeviceConfig};
use skylux_hps::campaign::Readout;
use skylux_hps::hdr::map_capture;
use skylux_sim::capture::{simulate_capture, CaptureSpec};
use skylux_sim::sensor::Footprint;
use std::path::Path;

/// The truth: a vignetting falling to 45 % at 90° (V(0) = 1) and a response of 0.05 cd/m² s
/// per weighted DN.
fn truth() -> DeviceConfig {
    let mut d = DeviceConfig::default();
    d.lens.vignetting = vec![0.45, 0.3, 0.4, -0.2, 0.05];
    d.response.cg = 0.05;
    d
}

/// The whole array read with skip 4: 648 x 486 samples, 324 x 243 groups.
fn spec(exposures_us: Vec<f64>, seed: u64) -> CaptureSpec {
    CaptureSpec {
        time: "2017-05-08T10:00:00+02:00".into(),
        readout: Readout {
            col_start: 0,
            row_start: 0,
            skip: 4,
            bin: 1,
        },
        raw_width: 648,
        raw_height: 486,
        exposures_us,
        gains: vec![1.0],
        seed,
        footprint: Footprint::Centre,
        small_sources: vec![],
    }
}

const SOURCE_CD_M2: f64 = 5000.0;

/// Exposure giving `dn` black-subtracted DN on axis for the uniform source, µs.
fn exposure_for_dn(device: &DeviceConfig, dn: f64) -> f64 {
    let w: f64 = device.response.weights.iter().sum();
    dn * device.response.cg * w / SOURCE_CD_M2 * 1e6
}

fn capture(dir: &Path, device: &DeviceConfig, exposures_us: Vec<f64>, seed: u64) {
    let camera = CameraModel::new(device.clone());
    simulate_capture(dir, &camera, &|_| SOURCE_CD_M2, &spec(exposures_us, seed)).unwrap();
}

#[test]
fn vignetting_response_and_the_uniform_source_check_recover_the_simulated_truth() {
    let truth = truth();
    let tmp = tempfile::tempdir().unwrap();
    // Start from a device that knows neither: no vignetting, cg 1.
    let mut start = truth.clone();
    start.lens.vignetting = vec![1.0, 0.0, 0.0, 0.0, 0.0];
    start.response.cg = 1.0;

    // (b) Vignetting: one capture of the uniform source, five exposures around 2000 DN.
    let vdir = tmp.path().join("uniform");
    let t0 = exposure_for_dn(&truth, 2000.0);
    capture(
        &vdir,
        &truth,
        vec![0.25 * t0, 0.5 * t0, t0, 1.4 * t0, 2.0 * t0],
        11,
    );
    let (vr, after_v) = calibrate_vignetting(&vdir, &start, &VignettingOptions::default()).unwrap();
    println!(
        "vignetting: {:?}, {} groups to {:.1} deg, RMSE {:.4} % (groups {:.3} %), R² {:.5} ({:.4})",
        vr.coefficients,
        vr.groups_used,
        vr.max_off_axis_deg_seen,
        100.0 * vr.rmse_smoothed,
        100.0 * vr.rmse_groups,
        vr.r_squared_smoothed,
        vr.r_squared_groups
    );
    let true_camera = CameraModel::new(truth.clone());
    let fitted_camera = CameraModel::new(after_v.clone());
    for &(deg, v, se, _) in &vr.table {
        let t = true_camera.vignetting(deg.to_radians());
        println!("  {deg:>4.0} deg: fitted {v:.5} ± {se:.1e}, truth {t:.5}");
        // Within the fit's noise (4 standard errors) plus the bias of the 5 x 5 smoothing
        // window where the sensor's edge cuts it to one side (the far corners: 5e-4 here).
        assert!((v - t).abs() < 4.0 * se + 1e-3, "{deg} deg: {v} vs {t}");
        assert!((fitted_camera.vignetting(deg.to_radians()) - v).abs() < 1e-12);
    }
    assert!(vr.max_off_axis_deg_seen > 75.0);
    assert!(vr.r_squared_smoothed > 0.999);

    // (c) Response: six exposures from near black to saturation, on the vignetting-calibrated
    // device.
    let rdir = tmp.path().join("known");
    let exposures = vec![0.02 * t0, 0.3 * t0, 0.7 * t0, t0, 1.5 * t0, 1.8 * t0];
    capture(&rdir, &truth, exposures.clone(), 23);
    let source = KnownSource {
        dir: rdir.clone(),
        luminance_cd_m2: SOURCE_CD_M2,
    };
    let (rr, calibrated) =
        calibrate_response(&[source], &after_v, &ResponseOptions::default()).unwrap();
    for e in &rr.exposures {
        println!(
            "  {:>9.2} us: mean {:.0}/{:.0}/{:.0} DN, {:?} {:?}",
            e.exposure_us, e.mean_dn[0], e.mean_dn[1], e.mean_dn[2], e.excluded, e.relative_error
        );
    }
    println!(
        "cg {:.6} (truth {}), {} used, mean |err| {:.4} %, max {:.4} %",
        rr.cg,
        truth.response.cg,
        rr.used,
        100.0 * rr.mean_abs_rel_error,
        100.0 * rr.max_abs_rel_error
    );
    // Near black (40 DN) and near saturation (> 0.9 x 3100 DN) are excluded.
    let excluded: Vec<bool> = rr.exposures.iter().map(|e| e.excluded.is_some()).collect();
    assert_eq!(excluded, [true, false, false, false, true, true]);
    // Per exposure: ~10⁴ groups of ~1 % noise each, and the vignetting fit's ~1e-4: the
    // truth within 1e-3.
    assert!(
        (rr.cg / truth.response.cg - 1.0).abs() < 1e-3,
        "cg {}",
        rr.cg
    );
    assert!(rr.max_abs_rel_error < 1e-3);

    // The published check: 5 new frames of the source, each merged with the calibrated
    // device, 3 x 3 groups averaged over the 5 frames.
    let mut maps = vec![];
    for k in 0..5 {
        let dir = tmp.path().join(format!("check{k}"));
        capture(&dir, &truth, vec![t0], 100 + k);
        maps.push(map_capture(&dir, &calibrated).unwrap());
    }
    let inside: Vec<bool> = maps[0]
        .geometry
        .inverse_vignetting
        .iter()
        .map(|v| *v > 0.0)
        .collect();
    let refs: Vec<_> = maps.iter().map(|m| &m.map).collect();
    let check = uniform_source_check(&refs, &inside, SOURCE_CD_M2).unwrap();
    println!("{check:?}");
    assert!(check.readings > 5000);
    assert!(check.passes, "{check:?}");
    assert!(check.max_abs_rel_error < 0.02 && check.mean_abs_rel_error <= 0.008);
    assert!(check.mean_rel_error.abs() < 1e-3);

    // Both steps write device.toml and their reports.
    let out = tmp.path().join("out");
    write_outputs(&out, &vr.output(after_v.clone())).unwrap();
    write_outputs(&out, &rr.output(calibrated.clone())).unwrap();
    let (back, _) = DeviceConfig::read(&out.join("device.toml")).unwrap();
    assert_eq!(back, calibrated);
    for f in [
        "vignetting_report.md",
        "vignetting_report.json",
        "response_report.md",
        "response_report.json",
    ] {
        assert!(out.join(f).is_file(), "{f}");
    }
}

#[test]
fn unusable_calibration_frames_are_a_clear_error() {
    let truth = truth();
    let tmp = tempfile::tempdir().unwrap();
    // Every exposure near black: no linear region.
    let dir = tmp.path().join("dark");
    capture(&dir, &truth, vec![exposure_for_dn(&truth, 20.0)], 5);
    let e = calibrate_response(
        &[KnownSource {
            dir: dir.clone(),
            luminance_cd_m2: SOURCE_CD_M2,
        }],
        &truth,
        &ResponseOptions::default(),
    )
    .unwrap_err();
    assert!(matches!(e, CalibrationError::Fit { .. }));
    let msg = e.to_string();
    assert!(
        msg.contains("dark") && msg.contains("linear region"),
        "{msg}"
    );
    // A missing frame names the file.
    std::fs::remove_file(dir.join("e0.pgm")).unwrap();
    let msg = calibrate_vignetting(&dir, &truth, &VignettingOptions::default())
        .unwrap_err()
        .to_string();
    assert!(msg.contains("e0.pgm"), "{msg}");
    // A non-positive luminance names the field.
    let msg = calibrate_response(
        &[KnownSource {
            dir,
            luminance_cd_m2: f64::NAN,
        }],
        &truth,
        &ResponseOptions::default(),
    )
    .unwrap_err()
    .to_string();
    assert!(msg.contains("luminance_cd_m2"), "{msg}");
}

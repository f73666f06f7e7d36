//! `skylux sun` as a user runs it, on a small simulated campaign (one clear day in Lausanne,
//! five captures at a quarter of the full resolution) whose camera is not oriented as its
//! `device.toml` says: the world's camera is turned 4° in azimuth (the simulator's undeclared
//! orientation effect), and the declared file is further off by 2.5° in altitude and 1.5° in
//! roll. The references are the simulator's truth: the camera it rendered with, the sun where
//! SPA puts it, and the pyranometer's DNI its sky was made from.

use glam::DVec3;
use skylux_hps::camera::{CameraModel, DeviceConfig, OrientationConfig};
use skylux_hps::sun::{parse_time_utc, solar_position, Site, SOLAR_DISK_SR};
use skylux_sim::campaign::{simulate_campaign, CampaignSpec, DaySky};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

const ROOM: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../../shared/scenes/test-module"
);
const AZIMUTH_ERROR_DEG: f64 = 4.0;

fn skylux(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(args)
        .output()
        .expect("running the skylux binary")
}

fn text(o: &Output) -> (String, String) {
    (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

fn ok(args: &[&str]) -> String {
    let o = skylux(args);
    let (out, err) = text(&o);
    assert!(o.status.success(), "skylux {args:?} failed:\n{out}\n{err}");
    println!("{out}");
    out
}

/// The simulated campaign (written once per test binary) and the camera it was rendered with.
fn campaign() -> &'static (tempfile::TempDir, DeviceConfig) {
    static CAMPAIGN: OnceLock<(tempfile::TempDir, DeviceConfig)> = OnceLock::new();
    CAMPAIGN.get_or_init(|| {
        assert!(
            Path::new(ROOM).join("scene.rad").is_file(),
            "{ROOM} not found: the reference room beside the checkout is needed"
        );
        let dir = tempfile::tempdir().unwrap();
        let mut spec = CampaignSpec::lausanne(PathBuf::from(ROOM));
        spec.days = vec![(
            chrono::NaiveDate::from_ymd_opt(2017, 5, 8).unwrap(),
            DaySky::Clear,
        )];
        // When the sun is in view of a camera facing south 16° above the horizon.
        spec.hours = vec![10.0, 11.5, 13.5, 15.5, 17.0];
        spec.truth_samples = 16; // the lux-meters are not used here
        spec.effects
            .set(&format!("orientation_error={AZIMUTH_ERROR_DEG}"))
            .unwrap();
        simulate_campaign(dir.path(), &spec, &|_, _| {}).expect("simulated campaign");
        let mut truth = spec.device.clone();
        truth.orientation.axis_azimuth_deg += AZIMUTH_ERROR_DEG;
        // The owner's belief is off in altitude and roll too.
        let mut declared = spec.device.clone();
        declared.orientation.axis_altitude_deg -= 2.5;
        declared.orientation.roll_deg = -1.5;
        declared.write(&dir.path().join("device.toml")).unwrap();
        (dir, truth)
    })
}

/// A copy of the campaign (frames and all) to alter.
fn copy_campaign(to: &Path) {
    fn copy(from: &Path, to: &Path) {
        std::fs::create_dir_all(to).unwrap();
        for e in std::fs::read_dir(from).unwrap() {
            let e = e.unwrap();
            let target = to.join(e.file_name());
            if e.file_type().unwrap().is_dir() {
                copy(&e.path(), &target);
            } else {
                std::fs::copy(e.path(), target).unwrap();
            }
        }
    }
    copy(campaign().0.path(), to);
}

fn capture_tomls(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir.join("captures"))
        .unwrap()
        .map(|e| e.unwrap().path().join("capture.toml"))
        .collect();
    v.sort();
    v
}

/// `sun.csv` as rows of named fields (no field of these files holds a quoted comma except
/// the last, `note`, which is dropped).
fn read_csv(path: &Path) -> Vec<std::collections::BTreeMap<String, String>> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    assert_eq!(header.last().map(String::as_str), Some("note"));
    lines
        .map(|l| {
            header[..header.len() - 1]
                .iter()
                .cloned()
                .zip(l.split(',').map(String::from))
                .collect()
        })
        .collect()
}

fn num(row: &std::collections::BTreeMap<String, String>, key: &str) -> Option<f64> {
    let v = row.get(key).unwrap_or_else(|| panic!("no column {key}"));
    (!v.is_empty()).then(|| v.parse().unwrap_or_else(|_| panic!("{key} = {v}")))
}

fn angle_deg(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}

const SITE: Site = Site {
    latitude_deg: 46.52,
    longitude_deg: 6.57,
    elevation_m: 400.0,
};

/// The declared camera is ~5° off; `--fit-orientation --write-device` recovers the camera
/// the simulator rendered with within 0.05°, the written device.toml reads back and
/// round-trips, and with it the sun sightings agree with SPA within 0.05°.
#[test]
fn fit_orientation_recovers_the_camera_and_writes_device_toml() {
    let (dir, truth) = campaign();
    let out = tempfile::tempdir().unwrap();
    let device_file = out.path().join("device.toml");
    let stdout = ok(&[
        "sun",
        "--campaign",
        dir.path().to_str().unwrap(),
        "--out",
        out.path().to_str().unwrap(),
        "--fit-orientation",
        "--write-device",
        device_file.to_str().unwrap(),
    ]);
    assert!(stdout.contains("fit residual: rms"), "{stdout}");

    // The written device.toml: parses without warnings, equals the fitted camera of
    // sun_fit.json, and writes back to the same text.
    let (fitted, warnings) = DeviceConfig::read(&device_file).unwrap();
    assert!(warnings.is_empty(), "{warnings:?}");
    let again = out.path().join("again.toml");
    fitted.write(&again).unwrap();
    assert_eq!(DeviceConfig::read(&again).unwrap().0, fitted);
    assert_eq!(
        std::fs::read_to_string(&again).unwrap(),
        std::fs::read_to_string(&device_file).unwrap()
    );
    let (declared, _) = DeviceConfig::read(&dir.path().join("device.toml")).unwrap();
    assert_eq!(fitted.lens, declared.lens, "only the orientation is fitted");
    assert_eq!(fitted.response, declared.response);

    // Against the camera the world was rendered with.
    let t = CameraModel::new(truth.clone());
    let f = CameraModel::new(fitted.clone());
    let d = CameraModel::new(declared.clone());
    let before = angle_deg(d.axis(), t.axis());
    let axis = angle_deg(f.axis(), t.axis());
    let x = angle_deg(f.world_to_camera.row(0), t.world_to_camera.row(0));
    println!(
        "declared axis {before:.3} deg off; fitted: axis {axis:.4} deg, x-axis {x:.4} deg off; \
         fitted {:?}",
        fitted.orientation
    );
    assert!(before > 4.0, "a real orientation error: {before}");
    assert!(axis <= 0.05 && x <= 0.05, "axis {axis} deg, x-axis {x} deg");

    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.path().join("sun_fit.json")).unwrap())
            .unwrap();
    let o: OrientationConfig = serde_json::from_value(json["orientation"].clone()).unwrap();
    assert_eq!(o, fitted.orientation);
    assert!(json["residual_rms_deg"].as_f64().unwrap() <= 0.05, "{json}");
    assert!(json["residual_max_deg"].as_f64().unwrap() <= 0.05, "{json}");
    assert_eq!(json["sightings_used"], 5);

    // sun.csv: SPA columns against SPA computed here, errors before and after the fit.
    let rows = read_csv(&out.path().join("sun.csv"));
    assert_eq!(rows.len(), 5);
    for r in &rows {
        let time = parse_time_utc(&r["time"]).unwrap();
        let spa = solar_position(time, &SITE, None).unwrap();
        assert!((num(r, "spa_altitude_deg").unwrap() - spa.altitude_deg()).abs() < 1e-5);
        assert!((num(r, "spa_azimuth_deg").unwrap() - spa.azimuth_deg).abs() < 1e-5);
        assert_eq!(r["dni_source"], "map");
        assert!(num(r, "error_deg").unwrap() > 1.0, "{r:?}");
        let after = num(r, "fitted_error_deg").unwrap();
        assert!(after <= 0.05, "{r:?}");
        // The disk luminance against the pyranometer (the DNI the simulated sky was made
        // from, through the same Perez efficacy): within 3 %.
        let l = num(r, "disk_luminance_cd_m2").unwrap();
        let reference = num(r, "pyranometer_dni_lux").unwrap() / SOLAR_DISK_SR;
        assert!((l / reference - 1.0).abs() < 0.03, "{l} vs {reference}");
    }
    assert!(out.path().join("sun.png").is_file());

    // With the written device.toml, the campaign's sightings agree with SPA.
    let copy = tempfile::tempdir().unwrap();
    copy_campaign(copy.path());
    std::fs::copy(&device_file, copy.path().join("device.toml")).unwrap();
    let out2 = tempfile::tempdir().unwrap();
    ok(&[
        "sun",
        "--campaign",
        copy.path().to_str().unwrap(),
        "--out",
        out2.path().to_str().unwrap(),
    ]);
    let rows = read_csv(&out2.path().join("sun.csv"));
    let errors: Vec<f64> = rows.iter().filter_map(|r| num(r, "error_deg")).collect();
    assert_eq!(errors.len(), 5);
    let max = errors.iter().cloned().fold(0.0, f64::max);
    println!("with the written device.toml: sun direction error max {max:.4} deg");
    assert!(max <= 0.05, "{errors:?}");
}

/// The disk saturated even in the shortest exposure (the 1 µs frame left out of each
/// capture): the pyranometer's DNI is used, marked, and its disk luminance agrees with what
/// the map measures when the disk is not saturated. Without a pyranometer: no DNI, and a
/// note says why.
#[test]
fn a_saturated_disk_takes_the_pyranometers_dni() {
    let (dir, _) = campaign();
    let measured = tempfile::tempdir().unwrap();
    ok(&[
        "sun",
        "--campaign",
        dir.path().to_str().unwrap(),
        "--out",
        measured.path().to_str().unwrap(),
    ]);
    let measured = read_csv(&measured.path().join("sun.csv"));

    let copy = tempfile::tempdir().unwrap();
    copy_campaign(copy.path());
    for toml in capture_tomls(copy.path()) {
        let text = std::fs::read_to_string(&toml).unwrap();
        let kept: Vec<&str> = text
            .split("[[exposure]]")
            .filter(|part| !part.contains("exposure_us = 1.0\n"))
            .collect();
        assert_eq!(kept.len(), 5, "{}", toml.display());
        std::fs::write(&toml, kept.join("[[exposure]]")).unwrap();
    }
    let out = tempfile::tempdir().unwrap();
    let stdout = ok(&[
        "sun",
        "--campaign",
        copy.path().to_str().unwrap(),
        "--out",
        out.path().to_str().unwrap(),
        "--fit-orientation",
    ]);
    assert!(stdout.contains("DNI from the pyranometer in 5"), "{stdout}");
    let rows = read_csv(&out.path().join("sun.csv"));
    for (r, m) in rows.iter().zip(&measured) {
        assert_eq!(r["time"], m["time"]);
        assert!(r["flags"].contains("saturated"), "{r:?}");
        assert_eq!(r["dni_source"], "pyranometer");
        let dni = num(r, "dni_lux").unwrap();
        assert!((dni - num(r, "pyranometer_dni_lux").unwrap()).abs() <= 0.1);
        let l = num(r, "disk_luminance_cd_m2").unwrap();
        assert!((l * SOLAR_DISK_SR / dni - 1.0).abs() < 1e-5);
        let from_map = num(m, "disk_luminance_cd_m2").unwrap();
        assert_eq!(m["dni_source"], "map");
        assert!(
            (l / from_map - 1.0).abs() < 0.03,
            "{}: pyranometer {l:.4e} vs map {from_map:.4e}",
            r["time"]
        );
    }
    // No pyranometer: the disk is still found (and flagged), but no DNI.
    std::fs::remove_file(copy.path().join("pyranometer.csv")).unwrap();
    let out = tempfile::tempdir().unwrap();
    ok(&[
        "sun",
        "--campaign",
        copy.path().to_str().unwrap(),
        "--out",
        out.path().to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(out.path().join("sun.csv")).unwrap();
    for line in text.lines().skip(1) {
        assert!(line.contains(",none,"), "{line}");
        assert!(line.contains("no pyranometer DNI"), "{line}");
        assert!(line.contains("saturated"), "{line}");
    }
}

/// Bad input: clear errors that name the file or folder, never a panic.
#[test]
fn bad_input_is_a_clear_error() {
    let missing = tempfile::tempdir().unwrap().path().join("nowhere");
    let o = skylux(&["sun", "--campaign", missing.to_str().unwrap()]);
    let (_, err) = text(&o);
    assert!(!o.status.success());
    assert!(err.contains("nowhere"), "{err}");
    assert!(!err.contains("panicked"), "{err}");

    let (dir, _) = campaign();
    let o = skylux(&[
        "sun",
        "--campaign",
        dir.path().to_str().unwrap(),
        "--write-device",
        "x.toml",
    ]);
    let (_, err) = text(&o);
    assert!(!o.status.success());
    assert!(err.contains("--fit-orientation"), "{err}");

    // One day of sightings cannot give the principal point: refused, nothing written.
    let out = tempfile::tempdir().unwrap();
    let device_file = out.path().join("device.toml");
    let o = skylux(&[
        "sun",
        "--campaign",
        dir.path().to_str().unwrap(),
        "--out",
        out.path().to_str().unwrap(),
        "--fit-principal-point",
        "--write-device",
        device_file.to_str().unwrap(),
    ]);
    let (_, err) = text(&o);
    assert!(!o.status.success());
    assert!(
        err.contains("do not determine the principal point"),
        "{err}"
    );
    assert!(!device_file.exists() && !out.path().join("sun_fit.json").exists());
    assert!(out.path().join("sun.csv").is_file(), "the tracking is kept");

    // A campaign with no sun: the exposures claim a thousand times the integration time, so
    // the disk reads a thousand times dimmer, below the threshold; and a night capture.
    let copy = tempfile::tempdir().unwrap();
    copy_campaign(copy.path());
    let tomls = capture_tomls(copy.path());
    for toml in &tomls {
        let text = std::fs::read_to_string(toml).unwrap();
        let text: String = text
            .lines()
            .map(|l| match l.strip_prefix("exposure_us = ") {
                Some(v) => format!("exposure_us = {:?}", v.parse::<f64>().unwrap() * 1000.0),
                None => l.to_string(),
            })
            .collect::<Vec<_>>()
            .join("\n");
        std::fs::write(toml, text).unwrap();
    }
    let night = std::fs::read_to_string(&tomls[0])
        .unwrap()
        .replace("T10:00:00+02:00", "T01:00:00+02:00");
    std::fs::write(&tomls[0], night).unwrap();
    let out = tempfile::tempdir().unwrap();
    let args = [
        "sun",
        "--campaign",
        copy.path().to_str().unwrap(),
        "--out",
        out.path().to_str().unwrap(),
    ];
    let stdout = ok(&args);
    assert!(stdout.contains("no capture shows the sun"), "{stdout}");
    let csv = std::fs::read_to_string(out.path().join("sun.csv")).unwrap();
    assert!(csv.contains("no_sun:below_horizon"), "{csv}");
    assert_eq!(csv.matches("no_sun:below_threshold").count(), 4, "{csv}");
    let o = skylux(&[&args[..], &["--fit-orientation"]].concat());
    let (_, err) = text(&o);
    assert!(!o.status.success());
    assert!(err.contains(copy.path().to_str().unwrap()), "{err}");
    assert!(
        err.contains("0 usable sun sightings among 5 captures"),
        "{err}"
    );
    assert!(!err.contains("panicked"), "{err}");

    // A malformed capture.toml: the error names it.
    std::fs::write(&tomls[1], "time = \"not a time\"\n").unwrap();
    let o = skylux(&args);
    let (_, err) = text(&o);
    assert!(!o.status.success());
    assert!(err.contains("capture.toml"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

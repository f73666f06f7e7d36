//! Calibration (issue 4, item 4): spectral f1' against an independent computation, weight and
//! filter fits, geometry recovery from synthetic correspondences, and bad input.
//!
//! Data: `shared/data/spectral` (see its README): CIE V(λ) and D65 (via colour-science,
//! BSD-3), the NPL-measured Nikon D5100 sensitivities (a Bayer CMOS camera standing in for the
//! MT9P031, whose curves are not public), the Canon EOS 5D Mark II curves (rawtoaces).

use rand::{Rng, SeedableRng};
use skylux_hps::calibration::geometry::{
    calibrate_geometry, read_correspondences, Correspondence, GeometryOptions,
};
use skylux_hps::calibration::spectral::{
    calibrate_spectral, f1_pair, read_filters, SpectralInputs,
};
use skylux_hps::calibration::{write_outputs, CalibrationError};
use skylux_hps::camera::{direction_from_alt_az, CameraModel, DeviceConfig};
use skylux_hps::photometry::spectral::{
    illuminant_a, load_d65, load_photopic, load_rgb_sensitivities, Curve,
};
use std::path::{Path, PathBuf};

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

const NIKON: &str = "spectral/camera_sensitivity_nikon_5100_npl.csv";
const CANON: &str = "spectral/camera_sensitivity_canon_eos_5d_mark_ii_rawtoaces.csv";

fn inputs(file: &str) -> SpectralInputs {
    let d = data_dir();
    SpectralInputs {
        channels: load_rgb_sensitivities(&d.join(file)).unwrap(),
        channels_source: file.into(),
        photopic: load_photopic(&d).unwrap(),
        illuminant_a: illuminant_a(),
        d65: load_d65(&d).unwrap(),
    }
}

/// A whole table read by hand: rows of numbers after the header (independent of the
/// library's reader).
fn rows(path: &Path) -> Vec<Vec<f64>> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .filter_map(|l| {
            let v: Vec<f64> = l.split(',').filter_map(|f| f.trim().parse().ok()).collect();
            (v.len() == l.split(',').count()).then_some(v)
        })
        .collect()
}

/// The camera file, V(λ) and D65 read by hand: (wavelength, R, G, B), (wavelength, V) and
/// (wavelength, D65).
fn tables(file: &str) -> [Vec<Vec<f64>>; 3] {
    let d = data_dir();
    [
        rows(&d.join(file)),
        rows(&d.join("spectral/cie_1924_photopic_V.csv")),
        rows(&d.join("spectral/cie_illuminant_D65.csv")),
    ]
}

/// Illuminant A from the CIE's own formula constants (CIE 15:2004 eq. 3.1: c2 = 1.435e-2
/// m K, T = 2848 K), not the library's 2856 K with c2 = 1.4388e-2.
fn cie_a(nm: f64) -> f64 {
    100.0 * (560.0 / nm).powi(5) * ((1.435e7f64 / (2848.0 * 560.0)).exp() - 1.0)
        / ((1.435e7 / (2848.0 * nm)).exp() - 1.0)
}

/// One integration sample: (s, V, S_A, S_D65, integration weight).
type Sample = (f64, f64, f64, f64, f64);

/// f1' (A, D65) from samples with integration weights.
fn f1_of(samples: &[Sample]) -> (f64, f64) {
    let f1 = |illum: &dyn Fn(&Sample) -> f64| {
        let sv: f64 = samples.iter().map(|s| s.4 * illum(s) * s.1).sum();
        let ss: f64 = samples.iter().map(|s| s.4 * illum(s) * s.0).sum();
        let num: f64 = samples
            .iter()
            .map(|s| s.4 * (s.0 * sv / ss - s.1).abs())
            .sum();
        num / samples.iter().map(|s| s.4 * s.1).sum::<f64>()
    };
    (f1(&|s| s.2), f1(&|s| s.3))
}

/// Linear interpolation in a table's column `c`, written apart from the library's.
fn lerp(t: &[Vec<f64>], c: usize, nm: f64) -> f64 {
    let k = t.iter().position(|r| r[0] >= nm).unwrap_or(t.len() - 1);
    if k == 0 || t[k][0] == nm {
        return t[k][c];
    }
    let (a, b) = (&t[k - 1], &t[k]);
    a[c] + (b[c] - a[c]) * (nm - a[0]) / (b[0] - a[0])
}

/// f1' computed independently by the midpoint rule in 0.1 nm steps on this file's own linear
/// interpolation (the library: trapezoid in 1 nm steps), with the CIE-constant illuminant A.
fn independent_f1(file: &str, w: [f64; 3]) -> (f64, f64) {
    let [cam, v, d65] = tables(file);
    let samples: Vec<_> = (0..4000)
        .map(|i| {
            let nm = 380.0 + 0.1 * (i as f64 + 0.5);
            let s = w[0] * lerp(&cam, 1, nm) + w[1] * lerp(&cam, 2, nm) + w[2] * lerp(&cam, 3, nm);
            (s, lerp(&v, 1, nm), cie_a(nm), lerp(&d65, 1, nm), 0.1)
        })
        .collect();
    f1_of(&samples)
}

/// f1' from the 5 nm samples of the camera file summed directly (V(λ) and D65 taken at the
/// same 5 nm wavelengths, no interpolation). Sampling V(λ) every 5 nm misses its curvature
/// inside the steps: under |·| that does not cancel, and costs about (5 nm)²/12 ∫|V''| dλ /
/// ∫V dλ ≈ 1e-3 (V'' of a Gaussian of σ ≈ 42 nm), so this agrees to 2.5e-3 only.
fn five_nm_f1(file: &str, w: [f64; 3]) -> (f64, f64) {
    let [cam, v, d65] = tables(file);
    let at = |t: &[Vec<f64>], nm: f64| t.iter().find(|r| (r[0] - nm).abs() < 1e-9).unwrap()[1];
    let samples: Vec<_> = cam
        .iter()
        .filter(|r| (380.0..=780.0).contains(&r[0]))
        .map(|r| {
            let s = w[0] * r[1] + w[1] * r[2] + w[2] * r[3];
            (s, at(&v, r[0]), cie_a(r[0]), at(&d65, r[0]), 5.0)
        })
        .collect();
    assert_eq!(samples.len(), 81, "380-780 nm every 5 nm");
    f1_of(&samples)
}

#[test]
fn f1_prime_of_the_nikon_matches_an_independent_computation_and_the_fit_lowers_it() {
    let inp = inputs(NIKON);
    let device = DeviceConfig::default();
    let (report, out) = calibrate_spectral(&inp, &[], &device).unwrap();
    for r in [
        &report.before,
        &report.green_only,
        &report.fitted_nnls,
        &report.fitted,
    ] {
        let (a, d) = independent_f1(NIKON, r.weights);
        let (a5, d5) = five_nm_f1(NIKON, r.weights);
        println!(
            "{:<20} w {:.4} {:.4} {:.4}: f1'(A) {:.5} (0.1 nm midpoint {:.5}, 5 nm sum {:.5}), \
             f1'(D65) {:.5} ({:.5}, {:.5})",
            r.label,
            r.weights[0],
            r.weights[1],
            r.weights[2],
            r.f1_prime_a,
            a,
            a5,
            r.f1_prime_d65,
            d,
            d5
        );
        assert!(
            (r.f1_prime_a - a).abs() < 1e-3,
            "{}: {} vs {a}",
            r.label,
            r.f1_prime_a
        );
        assert!(
            (r.f1_prime_d65 - d).abs() < 1e-3,
            "{}: {} vs {d}",
            r.label,
            r.f1_prime_d65
        );
        assert!(
            (r.f1_prime_a - a5).abs() < 2.5e-3,
            "{}: {} vs {a5}",
            r.label,
            r.f1_prime_a
        );
        assert!(
            (r.f1_prime_d65 - d5).abs() < 2.5e-3,
            "{}: {} vs {d5}",
            r.label,
            r.f1_prime_d65
        );
    }
    assert!(report.fitted.f1_prime_a < report.before.f1_prime_a);
    assert!(report.fitted.f1_prime_a < report.green_only.f1_prime_a);
    assert!(report.fitted.f1_prime_a <= report.fitted_nnls.f1_prime_a + 1e-12);
    assert!(report.fitted_nnls.f1_prime_a < report.before.f1_prime_a);
    assert!(report.fitted.weights.iter().all(|w| *w >= 0.0));
    assert!((report.fitted.weights.iter().sum::<f64>() - 1.0).abs() < 1e-12);
    assert_eq!(out.response.weights, report.fitted.weights);
}

#[test]
fn the_canon_curves_give_a_mismatch_too() {
    let inp = inputs(CANON);
    let (report, _) = calibrate_spectral(&inp, &[], &DeviceConfig::default()).unwrap();
    let (a, _) = independent_f1(CANON, report.fitted.weights);
    println!(
        "Canon: before {:.4}, fitted {:.4} (independent {a:.4})",
        report.before.f1_prime_a, report.fitted.f1_prime_a
    );
    assert!((report.fitted.f1_prime_a - a).abs() < 1e-3);
    assert!(report.fitted.f1_prime_a < report.before.f1_prime_a);
}

/// Synthetic transmittance curves (the shared data holds none): a neutral density, an
/// infrared cut and a smooth band-pass near V(λ)'s peak. The neutral filter changes nothing;
/// the chosen filter is the one with the lowest f1' after refitting, and beats no filter.
#[test]
fn the_filter_with_the_lowest_refitted_f1_prime_is_chosen() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("wavelength_nm,neutral,ir_cut,bandpass\n");
    for nm in (350..=800).step_by(5) {
        let x = nm as f64;
        let ir_cut = 1.0 / (1.0 + ((x - 660.0) / 12.0).exp());
        let bandpass = (-((x - 560.0) / 70.0).powi(2)).exp();
        text.push_str(&format!("{nm},0.5,{ir_cut},{bandpass}\n"));
    }
    std::fs::write(dir.path().join("set.csv"), &text).unwrap();
    // A second file in percent.
    let mut pct = String::from("wavelength,half_percent\n");
    for nm in (350..=800).step_by(10) {
        pct.push_str(&format!("{nm},50\n"));
    }
    std::fs::write(dir.path().join("more.csv"), &pct).unwrap();
    let filters = read_filters(dir.path()).unwrap();
    assert_eq!(filters.len(), 4);
    let inp = inputs(NIKON);
    let (report, out) = calibrate_spectral(&inp, &filters, &DeviceConfig::default()).unwrap();
    for f in &report.filters {
        println!(
            "{:<20} f1'(A) {:.4} (NNLS weights {:.4})",
            f.name, f.refined.f1_prime_a, f.nnls.f1_prime_a
        );
    }
    let by = |n: &str| report.filters.iter().find(|f| f.name == n).unwrap();
    for neutral in ["set:neutral", "more:half_percent"] {
        assert!((by(neutral).refined.f1_prime_a - report.fitted.f1_prime_a).abs() < 1e-6);
    }
    let best = report.chosen_filter.clone().expect("a filter beats none");
    assert_eq!(best, report.filters[0].name);
    assert!(report.after.f1_prime_a < report.fitted.f1_prime_a);
    assert_eq!(out.response.weights, report.after.weights);
    // The chosen filter's f1' by an independent route: the filter folded into the channels.
    let t = &filters.iter().find(|(n, _)| *n == best).unwrap().1;
    let folded = SpectralInputs {
        channels: inp
            .channels
            .clone()
            .map(|c| Curve::sampled(380.0, 780.0, 1.0, |nm| c.at(nm) * t.at(nm))),
        ..inputs(NIKON)
    };
    let (a, _) = f1_pair(&folded, None, report.after.weights);
    assert!((a - report.after.f1_prime_a).abs() < 1e-3);
    // The outputs: device.toml that reads back, and both reports.
    let out_dir = dir.path().join("out");
    let written = write_outputs(&out_dir, &report.output(out.clone())).unwrap();
    assert_eq!(written.len(), 3);
    let (back, _) = DeviceConfig::read(&out_dir.join("device.toml")).unwrap();
    assert_eq!(back.response.weights, out.response.weights);
    let md = std::fs::read_to_string(out_dir.join("spectral_report.md")).unwrap();
    assert!(md.contains(&best));
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn bad_spectral_and_filter_input_is_a_clear_error() {
    let dir = tempfile::tempdir().unwrap();
    let missing = write(
        dir.path(),
        "missing.csv",
        "wavelength_nm,R,G\n380,1,2\n385,1,2\n",
    );
    let e = load_rgb_sensitivities(&missing).unwrap_err().to_string();
    assert!(e.contains("missing.csv") && e.contains("\"B\""), "{e}");
    let nan = write(
        dir.path(),
        "nan.csv",
        "wavelength_nm,R,G,B\n380,1,2,3\n385,1,NaN,3\n",
    );
    let e = load_rgb_sensitivities(&nan).unwrap_err().to_string();
    assert!(
        e.contains("nan.csv") && e.contains("line 3") && e.contains("(G)"),
        "{e}"
    );
    let short = write(dir.path(), "short.csv", "wavelength_nm,R,G,B\n380,1,2,3\n");
    let e = load_rgb_sensitivities(&short).unwrap_err().to_string();
    assert!(
        e.contains("short.csv") && e.contains("fewer than two"),
        "{e}"
    );
    let neg = write(dir.path(), "neg.csv", "wavelength,t\n380,0.5\n385,-0.1\n");
    let e = read_filters(&neg).unwrap_err().to_string();
    assert!(e.contains("neg.csv") && e.contains(": t:"), "{e}");
    let empty = dir.path().join("empty");
    std::fs::create_dir(&empty).unwrap();
    assert!(read_filters(&empty)
        .unwrap_err()
        .to_string()
        .contains("no *.csv"));
}

fn truth_device() -> DeviceConfig {
    let mut d = DeviceConfig::default();
    d.lens.focal_px = 1102.0;
    d.lens.center_px = [1301.5, 968.25];
    d.lens.distortion = [-0.021, 0.0032, -0.0004, 0.00002];
    d.orientation.axis_azimuth_deg = 172.0;
    d.orientation.axis_altitude_deg = 31.0;
    d.orientation.roll_deg = 2.5;
    d
}

/// Correspondences of `truth` over the sensor (2592 x 1944), off-axis angles up to the
/// corners, with Gaussian noise of `sigma_px` per coordinate.
fn synthetic(truth: &DeviceConfig, n: usize, sigma_px: f64, seed: u64) -> Vec<Correspondence> {
    let camera = CameraModel::new(truth.clone());
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let mut out = vec![];
    while out.len() < n {
        let (x, y) = (rng.gen_range(20.0..2572.0), rng.gen_range(20.0..1924.0));
        let p = skylux_hps::camera::ImagePoint { x_px: x, y_px: y };
        let Some(d) = camera.unproject(p) else {
            continue;
        };
        // Box-Muller noise.
        let (u1, u2): (f64, f64) = (rng.gen_range(1e-12..1.0), rng.gen_range(0.0..1.0));
        let r = (-2.0 * u1.ln()).sqrt() * sigma_px;
        let (s, c) = (std::f64::consts::TAU * u2).sin_cos();
        out.push(Correspondence {
            image_point: skylux_hps::camera::ImagePoint {
                x_px: x + r * c,
                y_px: y + r * s,
            },
            direction: d,
        });
    }
    out
}

#[test]
fn geometry_is_recovered_from_synthetic_correspondences() {
    let truth = truth_device();
    let points = synthetic(&truth, 300, 0.3, 7);
    let (report, fitted) = calibrate_geometry(
        &points,
        &DeviceConfig::default(),
        &GeometryOptions::default(),
        "synthetic",
    )
    .unwrap();
    println!("{report:#?}");
    // The noise is 0.3 px per coordinate: the 2-D residual RMS is 0.3 √2 less the fitted
    // parameters' share.
    assert!((0.38..0.46).contains(&report.rms_px), "{}", report.rms_px);
    assert!(report.rms_px_before > 10.0);
    let (t, f) = (
        CameraModel::new(truth.clone()),
        CameraModel::new(fitted.clone()),
    );
    // The lens's radius function agrees to a fraction of the noise over the field.
    let mut worst_r = 0.0f64;
    for k in 0..=80 {
        let theta = (k as f64).to_radians();
        worst_r = worst_r.max((t.lens.radius_px(theta) - f.lens.radius_px(theta)).abs());
    }
    assert!(worst_r < 0.15, "radius differs by {worst_r} px");
    for i in 0..2 {
        assert!((fitted.lens.center_px[i] - truth.lens.center_px[i]).abs() < 0.15);
    }
    let axis = t.axis().angle_between(f.axis()).to_degrees();
    assert!(axis < 0.01, "axis off by {axis} deg");
    assert!((fitted.orientation.roll_deg - truth.orientation.roll_deg).abs() < 0.01);
    // Directions through the fitted model: within 0.01 deg everywhere.
    for p in &points {
        let a = f.unproject(p.image_point).unwrap();
        let b = t.unproject(p.image_point).unwrap();
        assert!(a.angle_between(b).to_degrees() < 0.01);
    }
    // Standard errors reported and consistent with the actual errors.
    let se = |name: &str| {
        report
            .standard_errors
            .iter()
            .find(|(n, _)| n == name)
            .unwrap()
            .1
    };
    assert!((fitted.lens.center_px[0] - truth.lens.center_px[0]).abs() < 5.0 * se("cx_px"));
    assert!((fitted.lens.focal_px - truth.lens.focal_px).abs() < 5.0 * se("focal_px"));
}

#[test]
fn geometry_with_the_lens_held_fits_orientation_only() {
    let truth = truth_device();
    let points = synthetic(&truth, 12, 0.0, 3);
    let mut start = truth.clone();
    start.orientation = DeviceConfig::default().orientation;
    let options = GeometryOptions {
        fit_focal: false,
        fit_center: false,
        fit_distortion_terms: 0,
        fit_orientation: true,
    };
    let (report, fitted) = calibrate_geometry(&points, &start, &options, "synthetic").unwrap();
    assert!(report.rms_px < 1e-6, "{}", report.rms_px);
    assert!((fitted.orientation.axis_altitude_deg - 31.0).abs() < 1e-6);
    assert_eq!(fitted.lens, truth.lens);
    assert!(report.standard_errors[0].1.is_nan());
}

#[test]
fn bad_correspondences_are_a_clear_error() {
    let dir = tempfile::tempdir().unwrap();
    let few = write(
        dir.path(),
        "few.csv",
        "x_px,y_px,altitude_deg,azimuth_deg\n1296,972,16,180\n1400,972,16,175\n",
    );
    let points = read_correspondences(&few).unwrap();
    let e = calibrate_geometry(
        &points,
        &DeviceConfig::default(),
        &GeometryOptions::default(),
        "few.csv",
    )
    .unwrap_err();
    assert!(matches!(e, CalibrationError::Fit { .. }));
    let e = e.to_string();
    assert!(
        e.contains("few.csv") && e.contains("2 correspondences"),
        "{e}"
    );
    let missing = write(dir.path(), "missing.csv", "x_px,y_px,altitude_deg\n1,2,3\n");
    let e = read_correspondences(&missing).unwrap_err().to_string();
    assert!(
        e.contains("missing.csv") && e.contains("azimuth_deg") && e.contains("missing column"),
        "{e}"
    );
    let nan = write(
        dir.path(),
        "nan.csv",
        "x_px,y_px,dx,dy,dz\n1,2,0,0,1\n1,NaN,0,1,0\n",
    );
    let e = read_correspondences(&nan).unwrap_err().to_string();
    assert!(
        e.contains("nan.csv") && e.contains("y_px") && e.contains("line 3"),
        "{e}"
    );
    let zero = write(dir.path(), "zero.csv", "x_px,y_px,dx,dy,dz\n1,2,0,0,0\n");
    let e = read_correspondences(&zero).unwrap_err().to_string();
    assert!(e.contains("zero.csv") && e.contains("zero vector"), "{e}");
    // Directions given as vectors read the same as altitude and azimuth.
    let d = direction_from_alt_az(20.0, 150.0);
    let v = write(
        dir.path(),
        "v.csv",
        &format!("x_px,y_px,dx,dy,dz\n5,6,{},{},{}\n", d.x, d.y, d.z),
    );
    let p = read_correspondences(&v).unwrap();
    assert!((p[0].direction - d).length() < 1e-12);
}

//! HDR synthesis against a known luminance field rendered by the sensor model (issue 4):
//! 1.2e2 to 3.8e9 cd/m² (150 dB) in one set of five exposures, 1 µs to 500 ms.
//! - without noise (ideal ADC): maximum relative error ≤ 0.1 %, ≥ 150 dB recovered;
//! - with shot noise, read noise and quantisation: mean relative error within ±0.2 % and RMS
//!   relative error within 10 % of the noise-limited bound, derived here from the noise model
//!   and the true luminance (not from the merge's own estimate).

use glam::DVec3;
use skylux_hps::camera::{CameraModel, DeviceConfig, OrientationConfig};
use skylux_hps::campaign::{BayerPattern, Readout};
use skylux_hps::hdr::{merge, Exposure, GroupGeometry, LuminanceMap, MapFlag, Samples};
use skylux_sim::sensor::{FrameRenderer, Noise};

const L_MIN: f64 = 1.2e2;
const L_MAX: f64 = 3.8e9;
/// 1 µs to 500 ms in four equal ratios (26.6x, inside the 77x valid range of a sample).
const EXPOSURES_S: [f64; 5] = [1e-6, 2.659_148e-5, 7.071_068e-4, 1.880_302e-2, 0.5];

fn device() -> DeviceConfig {
    let mut d = DeviceConfig::default();
    d.response.cg = 1.4; // so that 3.8e9 cd/m² at 1 µs and 120 cd/m² at 500 ms are both in range
    d.sensor.black_level_dn = 10.0;
    d.sensor.valid_min_dn = 50.0;
    d.sensor.valid_max_dn = 3110.0;
    d.lens.distortion = [0.01, -0.002, 0.0, 0.0];
    d.lens.vignetting = vec![0.6, 0.3, 0.1, 0.0, 0.0];
    d.orientation = OrientationConfig {
        axis_azimuth_deg: 0.0,
        axis_altitude_deg: 90.0,
        roll_deg: 0.0,
    };
    d
}

struct Setup {
    camera: CameraModel,
    readout: Readout,
    geometry: GroupGeometry,
    field: Box<dyn Fn(DVec3) -> f64 + Sync>,
}

/// A log-linear luminance ramp across the window, from exactly L_MIN to L_MAX.
fn setup() -> Setup {
    let camera = CameraModel::new(device());
    let readout = Readout {
        col_start: 1040,
        row_start: 780,
        skip: 1,
        bin: 1,
    };
    let geometry = GroupGeometry::new(&camera, &readout, 512, 384);
    let v = DVec3::new(1.0, 0.4, 0.0).normalize();
    let dots: Vec<f64> = geometry
        .direction
        .iter()
        .map(|d| d.as_dvec3().dot(v))
        .collect();
    let (lo, hi) = dots
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
    let field = Box::new(move |d: DVec3| {
        let u = ((d.dot(v) - lo) / (hi - lo)).clamp(0.0, 1.0);
        L_MIN * (L_MAX / L_MIN).powf(u)
    });
    Setup {
        camera,
        readout,
        geometry,
        field,
    }
}

/// The frames of the exposure ladder merged into a map (unity gain, GRBG).
fn merged<F: Samples>(s: &Setup, frames: &[F]) -> LuminanceMap {
    let exposures: Vec<Exposure<F>> = frames
        .iter()
        .zip(EXPOSURES_S)
        .map(|(f, t)| Exposure {
            frame: f,
            exposure_s: t,
            gain: 1.0,
        })
        .collect();
    merge(
        &exposures,
        &s.camera.config,
        BayerPattern::GRBG,
        &s.geometry,
    )
    .unwrap()
}

fn truth(s: &Setup) -> Vec<f64> {
    s.geometry
        .direction
        .iter()
        .map(|d| (s.field)(d.as_dvec3()))
        .collect()
}

fn relative_errors(map: &LuminanceMap, truth: &[f64]) -> Vec<(usize, f64)> {
    (0..truth.len())
        .filter(|&i| map.flags[i] == MapFlag::Valid)
        .map(|i| (i, map.luminance_cd_m2[i] as f64 / truth[i] - 1.0))
        .collect()
}

#[test]
fn noiseless_merge_is_exact_over_150_db() {
    let s = setup();
    let r = FrameRenderer {
        camera: &s.camera,
        readout: s.readout,
        raw_width: 512,
        raw_height: 384,
        footprint: Default::default(),
        small_sources: vec![],
    };
    let frames: Vec<_> = EXPOSURES_S
        .iter()
        .map(|&t| r.render_analog(&*s.field, t, 1.0))
        .collect();
    let map = merged(&s, &frames);
    let truth = truth(&s);
    let errors = relative_errors(&map, &truth);
    assert_eq!(
        errors.len(),
        truth.len(),
        "every group has a valid exposure"
    );
    let max = errors.iter().map(|(_, e)| e.abs()).fold(0.0, f64::max);
    assert!(max <= 1e-3, "max relative error {max}");
    let valid: Vec<f64> = errors
        .iter()
        .map(|&(i, _)| map.luminance_cd_m2[i] as f64)
        .collect();
    let range_db = 20.0
        * (valid.iter().cloned().fold(0.0, f64::max)
            / valid.iter().cloned().fold(f64::MAX, f64::min))
        .log10();
    assert!(range_db >= 150.0, "dynamic range {range_db} dB");
    println!(
        "noiseless: max relative error {max:.2e}, dynamic range {range_db:.2} dB over {} groups",
        errors.len()
    );
}

/// The noise-limited RMS relative error over `groups`, from the true luminance
/// (`skylux_sim::analysis`, derived from the noise model, independent of the merge).
fn noise_bound(s: &Setup, truth: &[f64], groups: &[usize]) -> f64 {
    let d = &s.camera.config;
    let sum: f64 = groups
        .iter()
        .map(|&i| {
            let rate = truth[i] / s.geometry.inverse_vignetting[i] as f64 / d.response.cg;
            skylux_sim::analysis::hdr_relative_sigma_bound(d, &EXPOSURES_S, rate)
                .unwrap()
                .powi(2)
        })
        .sum();
    (sum / groups.len() as f64).sqrt()
}

#[test]
fn noisy_merge_is_unbiased_and_at_the_noise_bound() {
    let s = setup();
    let r = FrameRenderer {
        camera: &s.camera,
        readout: s.readout,
        raw_width: 512,
        raw_height: 384,
        footprint: Default::default(),
        small_sources: vec![],
    };
    let frames: Vec<_> = EXPOSURES_S
        .iter()
        .enumerate()
        .map(|(k, &t)| {
            r.render(
                &*s.field,
                t,
                1.0,
                Noise::Sensor {
                    seed: 42 + k as u64,
                },
            )
        })
        .collect();
    assert!(frames.iter().all(|f| f.width() == 512), "raw frames");
    let map = merged(&s, &frames);
    let truth = truth(&s);
    let errors = relative_errors(&map, &truth);
    assert!(
        errors.len() as f64 > 0.99 * truth.len() as f64,
        "{} of {} groups valid",
        errors.len(),
        truth.len()
    );
    let n = errors.len() as f64;
    let mean = errors.iter().map(|(_, e)| e).sum::<f64>() / n;
    let rms = (errors.iter().map(|(_, e)| e * e).sum::<f64>() / n).sqrt();
    let groups: Vec<usize> = errors.iter().map(|&(i, _)| i).collect();
    let bound = noise_bound(&s, &truth, &groups);
    println!("noisy: {} groups, mean relative error {mean:+.3e}, RMS {rms:.4e}, noise-limited bound {bound:.4e} (ratio {:.3})", errors.len(), rms / bound);
    assert!(mean.abs() <= 2e-3, "bias {mean}");
    assert!(
        rms <= 1.1 * bound && rms >= 0.9 * bound,
        "RMS {rms} vs bound {bound}"
    );
}

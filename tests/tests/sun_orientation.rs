//! Device orientation from a day of sun sightings (issue 6): the camera's true orientation is
//! off the declared one by several degrees; the sun is imaged (integrating sensor model,
//! noise, HDR merge) and extracted through the *declared* model at each capture; the fit
//! against NREL SPA positions recovers the true orientation within 0.05°, and after it the
//! extracted sun directions agree with SPA within 0.05°.

use glam::DVec3;
use skylux_hps::camera::{CameraModel, DeviceConfig, OrientationConfig};
use skylux_hps::campaign::{BayerPattern, Readout};
use skylux_hps::hdr::{merge, Exposure, GroupGeometry};
use skylux_hps::sun::{
    extract_sun, fit_orientation, parse_time_utc, solar_position, Site, SunObservation, SunSearch,
};
use skylux_sim::sensor::{Footprint, FrameRenderer, Noise};

const EXPOSURES_S: [f64; 3] = [1e-6, 2.659_148e-5, 7.071_068e-4];

fn device(orientation: OrientationConfig) -> DeviceConfig {
    let mut d = DeviceConfig::default();
    d.lens.focal_px = 700.0; // the sun's whole daily path on the sensor
    d.lens.distortion = [0.01, -0.002, 0.0, 0.0];
    d.orientation = orientation;
    d
}

fn angle_deg(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}

#[test]
fn a_day_of_sun_sightings_recovers_the_orientation() {
    let truth = CameraModel::new(device(OrientationConfig {
        axis_azimuth_deg: 180.0,
        axis_altitude_deg: 86.4,
        roll_deg: 2.5,
    }));
    let declared = CameraModel::new(device(OrientationConfig {
        axis_azimuth_deg: 0.0,
        axis_altitude_deg: 90.0,
        roll_deg: 0.0,
    }));
    assert!(
        angle_deg(truth.axis(), declared.axis()) > 3.0,
        "a real orientation error"
    );
    let site = Site {
        latitude_deg: 46.52,
        longitude_deg: 6.57,
        elevation_m: 400.0,
    };
    let mut sightings = vec![];
    let mut truths = vec![];
    for hour in [7.0, 8.0, 9.0, 10.5, 12.0, 13.5, 15.0, 16.0, 17.0] {
        let t = parse_time_utc(&format!(
            "2017-05-08T{:02}:{:02}:00Z",
            hour as u32,
            ((hour % 1.0) * 60.0) as u32
        ))
        .unwrap();
        let sun = solar_position(t, &site, None).unwrap().direction();
        // Render a window around where the sun truly lands.
        let p = truth.project(sun).unwrap();
        let even = |v: f64| ((v as i64 - 96).max(0) as u32) & !1;
        let readout = Readout {
            col_start: even(p.x_px),
            row_start: even(p.y_px),
            skip: 1,
            bin: 1,
        };
        let field = move |d: DVec3| {
            if d.normalize().dot(sun) >= 0.26645f64.to_radians().cos() {
                1.5e9
            } else {
                9000.0
            }
        };
        let r = FrameRenderer {
            camera: &truth,
            readout,
            raw_width: 192,
            raw_height: 192,
            footprint: Footprint::Integrated,
            small_sources: vec![],
        };
        let frames: Vec<_> = EXPOSURES_S
            .iter()
            .enumerate()
            .map(|(k, &e)| {
                r.render(
                    &field,
                    e,
                    1.0,
                    Noise::Sensor {
                        seed: (hour * 10.0) as u64 + k as u64,
                    },
                )
            })
            .collect();
        let exposures: Vec<Exposure> = frames
            .iter()
            .zip(EXPOSURES_S)
            .map(|(f, e)| Exposure {
                frame: f,
                exposure_s: e,
                gain: 1.0,
            })
            .collect();
        // The device only knows the declared model.
        let geometry = GroupGeometry::new(&declared, &readout, 192, 192);
        let map = merge(&exposures, &declared.config, BayerPattern::GRBG, &geometry).unwrap();
        // The prediction can be several degrees off the blob until the orientation is known.
        let search = SunSearch {
            predicted_direction: Some(sun),
            max_offset_deg: 10.0,
            ..Default::default()
        };
        let found = extract_sun(&map, &geometry, &search).unwrap();
        sightings.push(SunObservation {
            image_point: declared.project(found.direction).unwrap(),
            sun_direction: sun,
        });
        truths.push(sun);
    }
    let before: f64 = sightings
        .iter()
        .map(|s| angle_deg(declared.unproject(s.image_point).unwrap(), s.sun_direction))
        .fold(0.0, f64::max);
    let fit = fit_orientation(&declared.config, &sightings).unwrap();
    let fitted = CameraModel::new(DeviceConfig {
        orientation: fit.orientation.clone(),
        ..declared.config.clone()
    });
    let axis_err = angle_deg(fitted.axis(), truth.axis());
    let x_err = angle_deg(fitted.world_to_camera.row(0), truth.world_to_camera.row(0));
    let after: f64 = sightings
        .iter()
        .map(|s| angle_deg(fitted.unproject(s.image_point).unwrap(), s.sun_direction))
        .fold(0.0, f64::max);
    println!(
        "orientation fit: sun direction error before {before:.3} deg, after {after:.4} deg (residual RMS {:.4} deg); axis error {axis_err:.4} deg, roll-axis error {x_err:.4} deg; fitted {:?}",
        fit.residual_rms_deg, fit.orientation
    );
    assert!(before > 3.0);
    assert!(
        axis_err <= 0.05 && x_err <= 0.05,
        "orientation error {axis_err} / {x_err} deg"
    );
    assert!(after <= 0.05, "direction error after the fit {after} deg");
}

//! Issue 21 item 3: `skyluxd --sim` reports glare at a declared occupant view. One cycle of a
//! clear May afternoon in Lausanne (the sun extracted from the measured sky) with one view,
//! from the back of the test module towards its window:
//! - `/v1/latest` carries the view's `ev_lux`, `dgp`, `dgps` and `method`, all finite;
//! - Ev from the rendered fisheye agrees with the illuminance sensor at the eye (the engine's
//!   illuminance code, no picture involved) within 3 combined standard errors or 3 %;
//! - the DGP is `skylux_hps::glare`'s (the code of `skylux glare`) on the picture the daemon
//!   kept, and DGPs is Wienold's line through the reported Ev;
//! - a second start with no time to render reports DGPs from the sensor, and says why.

mod common;

use common::*;
use skylux_hps::glare::{self, metrics, GlareOptions};
use std::path::Path;
use std::time::Duration;

/// The eye: seated at the back of the room (x = 1.45 m, 4.7 m from the façade, 1.2 m high),
/// looking south at the window.
const VIEW: &str = r#"
[[views]]
name = "back"
position_m = [1.45, 4.7, 1.2]
direction = [0, -1, 0]
"#;

/// One cycle at 13:00 (sun extracted, 60° high: its patch lies on the floor, in view).
fn run_one_cycle(config: &Path, out: &Path, log: &Path) -> serde_json::Value {
    // A stale address from an earlier run would be read before this run's API is up.
    let _ = std::fs::remove_file(out.join("api.address"));
    let mut child = SimRun::new(config, out)
        .cycles(1)
        .clock("2017-05-08T13:00:00+02:00", 3600)
        .serve_after()
        .start(log);
    let address = until(Duration::from_secs(25), log, || {
        std::fs::read_to_string(out.join("api.address")).ok()
    });
    let latest: serde_json::Value = until(Duration::from_secs(25), log, || {
        let (status, body) = http_get(address.trim(), "/v1/latest");
        (status == 200).then(|| serde_json::from_str(&body).ok())?
    });
    signal(&child, libc::SIGTERM);
    assert!(wait(&mut child, Duration::from_secs(20)).success());
    latest
}

fn number(v: &serde_json::Value, key: &str) -> f64 {
    let x = v[key].as_f64().unwrap_or(f64::NAN);
    assert!(x.is_finite(), "{key} = {} in {v}", v[key]);
    x
}

#[test]
fn a_view_reports_ev_and_dgp_of_its_render_and_falls_back_to_dgps() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let log = tmp.path().join("stderr.log");
    let extra = format!("{VIEW}\n[glare]\nresolution_px = 64\nsamples_per_pixel = 16\n");
    let config = config_with(tmp.path(), &[], &extra);
    let latest = run_one_cycle(&config, &out, &log);
    assert_eq!(latest["sun"]["extracted"], true, "{latest}");
    let views = latest["views"].as_array().expect("views in /v1/latest");
    assert_eq!(views.len(), 1);
    let v = &views[0];
    assert_eq!(v["view"], "back");
    assert_eq!(v["method"], "render", "{v}");
    let (ev, ev_se) = (number(v, "ev_lux"), number(v, "ev_stderr_lux"));
    let (sensor, sensor_se) = (
        number(v, "sensor_ev_lux"),
        number(v, "sensor_ev_stderr_lux"),
    );
    let (dgp, dgps) = (number(v, "dgp"), number(v, "dgps"));
    assert!(ev > 100.0 && ev_se > 0.0 && sensor_se > 0.0, "{v}");

    // The picture's Ev against the sensor's, within their noise.
    let combined = (ev_se * ev_se + sensor_se * sensor_se).sqrt();
    let allowed = (3.0 * combined).max(0.03 * sensor);
    eprintln!(
        "Ev render {ev:.1} ± {ev_se:.1} lx, sensor {sensor:.1} ± {sensor_se:.1} lx, \
         difference {:.1} lx (allowed {allowed:.1}); DGP {dgp:.4}, DGPs {dgps:.4}",
        ev - sensor
    );
    assert!((ev - sensor).abs() <= allowed, "{v}");

    // DGP: the glare module on the picture the daemon kept; DGPs: Wienold's line.
    let image_path = out.join(v["image"].as_str().expect("the picture is kept"));
    let image = glare::load_image(&image_path, None).unwrap();
    let report = glare::evaluate(&image, &GlareOptions::default()).unwrap();
    assert!((report.dgp - dgp).abs() <= 1e-12, "{} {dgp}", report.dgp);
    assert!(
        (report.ev_lux - ev).abs() <= 1e-9 * ev,
        "{} {ev}",
        report.ev_lux
    );
    assert_eq!(v["sources"].as_u64(), Some(report.sources.len() as u64));
    assert!((dgps - metrics::dgps(ev)).abs() < 1e-12);
    assert!((0.0..=1.0).contains(&dgp) && dgp > 0.159, "{dgp}");
    assert_eq!(v["low_light"], ev < metrics::LOW_LIGHT_LIMIT_LUX, "{v}");

    // No time to render (a 6 ms budget): DGPs from the sensor, and why.
    let extra = format!("{extra}budget_fraction = 0.0001\n");
    let config = config_with(tmp.path(), &[], &extra);
    let latest = run_one_cycle(&config, &out, &log);
    let v = &latest["views"][0];
    assert_eq!(v["method"], "dgps", "{v}");
    assert!(v["dgp"].is_null(), "{v}");
    assert!(v["reason"].as_str().unwrap().contains("budget"), "{v}");
    let ev = number(v, "ev_lux");
    assert_eq!(ev, number(v, "sensor_ev_lux"));
    assert!((number(v, "dgps") - metrics::dgps(ev)).abs() < 1e-12);
    assert_eq!(v["low_light"], ev < metrics::LOW_LIGHT_LIMIT_LUX, "{v}");
}

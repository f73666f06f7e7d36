//! End to end: `skyluxd --sim --cycles 3 --config hps/skyluxd.toml` runs three cycles,
//! serves `/v1/latest` and `/v1/health` over HTTP, exits 0 on SIGTERM, and its illuminance
//! equals the offline pipeline's (the device model, `skylux_hps::model`) on the same frames,
//! with the daylight coefficients recomputed offline from the room (never the daemon's cache).

mod common;

use common::*;
use skylux_hps::campaign::Campaign;
use skylux_hps::engine::{daylight_coefficients, Settings, World};
use skylux_hps::model::{capture_terms, load_captures, predict, ModelState, Room};
use std::time::Duration;

#[test]
fn three_cycles_serve_http_and_match_the_offline_pipeline() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let log = tmp.path().join("stderr.log");
    let config = example_config();
    // Three hours of a clear May day in Lausanne, an hour apart.
    let mut child = SimRun::new(&config, &out)
        .cycles(3)
        .clock("2017-05-08T10:00:00+02:00", 3600)
        .serve_after()
        .start(&log);
    let results = out.join("results.jsonl");
    until(Duration::from_secs(50), &log, || {
        (complete_lines(&results).len() >= 3).then_some(())
    });
    let address = std::fs::read_to_string(out.join("api.address")).unwrap();
    let address = address.trim();

    // The API (the state is updated right after the files are written).
    let latest: serde_json::Value = until(Duration::from_secs(10), &log, || {
        let (status, body) = http_get(address, "/v1/latest");
        let v: serde_json::Value = serde_json::from_str(&body).ok()?;
        (status == 200 && v["sequence"] == 3).then_some(v)
    });
    assert_eq!(latest["time"], "2017-05-08T12:00:00+02:00");
    assert_eq!(latest["sequence"], 3);
    assert_eq!(latest["illuminance"].as_array().unwrap().len(), 5);
    assert!(latest["sun"]["spa_altitude_deg"].as_f64().unwrap() > 50.0);
    let (status, body) = http_get(address, "/v1/health");
    assert_eq!(status, 200);
    let health: serde_json::Value = serde_json::from_str(&body).unwrap();
    assert_eq!(health["status"], "ok");
    assert_eq!(health["consecutive_failures"], 0);
    assert_eq!(health["cycles_ok"], 3);
    let (status, metrics) = http_get(address, "/v1/metrics");
    assert_eq!(status, 200);
    assert!(
        metrics.contains("skyluxd_cycles_total{outcome=\"ok\"} 3"),
        "{metrics}"
    );
    assert!(
        metrics.contains("skyluxd_stage_duration_ms{stage=\"hdr\"}"),
        "{metrics}"
    );
    // Read-only.
    assert_eq!(http(address, "POST", "/v1/latest").0, 405);
    assert_eq!(http(address, "DELETE", "/v1/health").0, 405);

    // SIGTERM: a clean exit.
    signal(&child, libc::SIGTERM);
    let status = wait(&mut child, Duration::from_secs(20));
    assert_eq!(
        status.code(),
        Some(0),
        "{}",
        std::fs::read_to_string(&log).unwrap()
    );
    let log_text = std::fs::read_to_string(&log).unwrap();
    assert!(log_text.contains("stop requested"), "{log_text}");

    // The records.
    let records: Vec<serde_json::Value> = complete_lines(&results)
        .iter()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(records.len(), 3);
    let latest_file: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("latest.json")).unwrap()).unwrap();
    assert_eq!(latest_file, records[2]);
    for r in &records {
        let map = out.join(r["map"].as_str().unwrap());
        assert!(map.is_file(), "{}", map.display());
        assert!(r["durations_ms"]["hdr_ms"].as_f64().unwrap() > 0.0);
    }
    let csv = std::fs::read_to_string(out.join("illuminance.csv")).unwrap();
    assert!(csv.starts_with("time,sensor,lux_model,lux_measured,model\n"));
    assert_eq!(csv.lines().count(), 1 + 3 * 5);

    // The offline pipeline on the captures the daemon kept.
    let compared = compare_with_offline(tmp.path(), &out, &records, 262_144);
    assert_eq!(compared, 15);
}

/// Runs the offline pipeline on the captures the daemon kept in `out` (a campaign around
/// them, the room and its daylight coefficients computed here from the scene, the loop's
/// functions) and compares every sensor of every record to 1e-9 relative: a wrong matrix in
/// the daemon (or a wrong cache) would disagree. Returns the values compared.
fn compare_with_offline(
    tmp: &std::path::Path,
    out: &std::path::Path,
    records: &[serde_json::Value],
    dc_samples: u32,
) -> usize {
    let hps = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let room_dir = hps.join("../../shared/scenes/test-module");
    let campaign_dir = tmp.join("campaign");
    std::fs::create_dir_all(&campaign_dir).unwrap();
    std::fs::write(
        campaign_dir.join("campaign.toml"),
        format!(
            "name = \"skyluxd-e2e\"\n[site]\nlatitude_deg = 46.52\nlongitude_deg = 6.57\n\
             elevation_m = 400.0\n[files]\ndevice = \"{}\"\nscene = \"{}\"\nsensors = \"{}\"\n\
             captures = \"{}\"\n",
            hps.join("daemon/device.toml").display(),
            room_dir.join("scene.rad").display(),
            room_dir.join("sensors.pts").display(),
            out.join("captures").display()
        ),
    )
    .unwrap();
    std::fs::write(campaign_dir.join("luxmeters.csv"), "time,sensor,lux\n").unwrap();
    let campaign = Campaign::open(&campaign_dir).unwrap();
    assert_eq!(campaign.captures.len(), records.len());
    let (device, _) =
        skylux_hps::camera::DeviceConfig::read(&hps.join("daemon/device.toml")).unwrap();
    let captures = load_captures(&campaign, &device, &|_, _| {}).unwrap();
    let scene = skylux_hps::scene::load(room_dir.join("scene.rad")).unwrap();
    let world = World::new(&scene).unwrap();
    let sensors = skylux_hps::scene::load_sensors(room_dir.join("sensors.pts")).unwrap();
    // hps/skyluxd.toml: mf = 1, dc_samples = 262144, ambient_bounces = 12 (converged), seed = 1.
    let settings = Settings {
        ambient_bounces: skylux_hps::engine::integrator::CONVERGED_AMBIENT_BOUNCES,
        samples_per_sensor: dc_samples,
        seed: 1,
        ..Settings::default()
    };
    let mut dc = daylight_coefficients(&world, &sensors, 1, &settings, &|_, _| {}).unwrap();
    // The daemon keeps its matrix in RADIANCE's matrix format, FORMAT=float: float32.
    for c in &mut dc.lux_per_cd_m2 {
        *c = f64::from(*c as f32);
    }
    let mut room = Room {
        world,
        sensors,
        dc,
        settings,
    };
    let terms = capture_terms(&mut room, &captures, &device, &|_, _| {}).unwrap();
    let mut compared = 0;
    for (c, t) in captures.iter().zip(&terms) {
        let offline = predict(&ModelState::default(), t);
        let r = records
            .iter()
            .find(|r| {
                chrono::DateTime::parse_from_rfc3339(r["time"].as_str().unwrap()).unwrap() == c.time
            })
            .expect("a record per capture");
        let daemon: Vec<f64> = r["illuminance"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| s["lux"].as_f64().unwrap())
            .collect();
        assert_eq!(daemon.len(), offline.len());
        for (s, (d, o)) in daemon.iter().zip(&offline).enumerate() {
            assert!(o.is_finite() && *o > 0.0, "S{}: offline {o}", s + 1);
            let rel = (d - o).abs() / o.abs();
            assert!(
                rel <= 1e-9,
                "{}: S{}: daemon {d} lux, offline {o} lux",
                c.time,
                s + 1
            );
            compared += 1;
        }
        assert_eq!(r["sun"]["extracted"].as_bool().unwrap(), t.sun.is_some());
        if let Some(sun) = &t.sun {
            let dn = r["sun"]["direct_normal_lux"].as_f64().unwrap();
            assert_eq!(dn, sun.direct_normal_illuminance_lux);
        }
    }
    compared
}

/// At a quarter of the full resolution the groups resolve the solar disk, so the sun is
/// extracted and handed over as a concentrated source; the daemon still equals the offline
/// pipeline, and its full Monte-Carlo agrees with the daylight coefficients. Native only:
/// one 648 x 486 capture renders in ~5 s here and in minutes under qemu-arm, and the ARM run
/// already covers the same code at 1/16 resolution above.
#[cfg(not(target_arch = "arm"))]
#[test]
fn quarter_resolution_extracts_the_sun_matches_offline_and_monte_carlo() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let log = tmp.path().join("stderr.log");
    let config = config_with(
        tmp.path(),
        &[("monte_carlo = false", "monte_carlo = true")],
        "",
    );
    let mut child = SimRun::new(&config, &out)
        .cycles(1)
        .clock("2017-05-08T12:00:00+02:00", 3600)
        .start(&log);
    let status = wait(&mut child, Duration::from_secs(55));
    assert_eq!(
        status.code(),
        Some(0),
        "{}",
        std::fs::read_to_string(&log).unwrap()
    );
    let records: Vec<serde_json::Value> = complete_lines(&out.join("results.jsonl"))
        .iter()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(records.len(), 1);
    let r = &records[0];
    assert_eq!(r["sun"]["extracted"], true, "{r}");
    // The extracted sun within 0.5 degrees of SPA.
    let d_alt = r["sun"]["extracted_altitude_deg"].as_f64().unwrap()
        - r["sun"]["spa_altitude_deg"].as_f64().unwrap();
    let d_az = r["sun"]["extracted_azimuth_deg"].as_f64().unwrap()
        - r["sun"]["spa_azimuth_deg"].as_f64().unwrap();
    assert!(d_alt.abs() < 0.5 && d_az.abs() < 0.5, "{d_alt} {d_az}");
    assert_eq!(compare_with_offline(tmp.path(), &out, &records, 262_144), 5);
    // Monte-Carlo under the measured sky agrees with the daylight coefficients within its
    // noise and the patch discretisation (4 standard errors + 5 %).
    for (dc, mc) in r["illuminance"]
        .as_array()
        .unwrap()
        .iter()
        .zip(r["monte_carlo"].as_array().unwrap())
    {
        let (a, b, e) = (
            dc["lux"].as_f64().unwrap(),
            mc["lux"].as_f64().unwrap(),
            mc["stderr_lux"].as_f64().unwrap(),
        );
        assert!((a - b).abs() <= 4.0 * e + 0.05 * a, "{dc} vs {mc}");
    }
}

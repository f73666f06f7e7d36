//! The engine under a measured HDR sky against RADIANCE's `rtrace -I` under the same sky.
//!
//! A sky is imaged by the simulated camera (sensor noise, five exposures, a 180° fisheye at
//! row/column skip 4), merged into a luminance map by the product's HDR path, and looked up
//! through `SkyLookup`. Our engine takes the lookup as its environment; RADIANCE takes the
//! same map as the product exports it for RADIANCE (`write_radiance_sky`: an angular-fisheye
//! picture and a `colorpict` glow). Both trace the reference room
//! (shared/scenes/test-module); the illuminance per sensor must agree within max(2 %, 4
//! combined standard errors), as for the analytic skies (hps/core/tests/engine_vs_rtrace.rs).

#[path = "../../hps/core/tests/common/radiance.rs"]
mod radiance;

use glam::DVec3;
use radiance::{
    agreement_failures, check_output, radiance_or_skip, rtrace_lux_runs, tool, RTRACE_PATH_TRACING,
};
use skylux_hps::camera::{CameraModel, DeviceConfig, OrientationConfig};
use skylux_hps::campaign::Readout;
use skylux_hps::engine::{self, Settings, World};
use skylux_hps::hdr::{map_capture, write_radiance_sky, CaptureMap};
use skylux_hps::scene;
use skylux_hps::sky::SkyLookup;
use skylux_sim::capture::{simulate_capture, CaptureSpec};
use std::path::Path;
use std::sync::Arc;

const ROOM: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../shared/scenes/test-module"
);
/// Uniform ground below the horizon, cd/m² (both programs).
const GROUND_CD_M2: f64 = 2500.0;
const OUR_SAMPLES: u32 = if cfg!(target_arch = "arm") {
    16_384
} else {
    131_072
};

/// A bright, strongly anisotropic clear-ish sky: a circumsolar peak south-south-east at 40°
/// altitude over a gradation, 2e3 to about 1e5 cd/m² (no solar disc: a disc would be handed
/// to both programs as a `light`, which hps/core/tests/engine_vs_rtrace.rs covers).
fn true_sky(d: DVec3) -> f64 {
    let sun = DVec3::new(0.25, -0.7, 0.64).normalize();
    let gamma = d.dot(sun).clamp(-1.0, 1.0).acos();
    4000.0 * (0.6 + 0.8 * d.z) * (1.0 + 25.0 * (-gamma / 0.12).exp() + 0.8 * d.dot(sun).max(0.0))
}

#[test]
fn a_measured_sky_map_lights_the_room_as_in_rtrace() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();

    // The camera: a zenith-looking 180° fisheye whose horizon circle fits the array.
    let mut device = DeviceConfig::default();
    device.lens.focal_px = 590.0;
    device.lens.center_px = [1296.0, 972.0];
    device.lens.distortion = [0.0; 4];
    device.lens.vignetting = vec![1.0, 0.0, 0.0, 0.0, 0.0];
    device.orientation = OrientationConfig {
        axis_azimuth_deg: 0.0,
        axis_altitude_deg: 90.0,
        roll_deg: 0.0,
    };
    let camera = CameraModel::new(device.clone());
    let capture_dir = dir.path().join("capture");
    simulate_capture(
        &capture_dir,
        &camera,
        &|d: DVec3| {
            if d.z < 0.0 {
                GROUND_CD_M2
            } else {
                true_sky(d)
            }
        },
        &CaptureSpec {
            time: "2017-05-08T12:00:00+02:00".into(),
            readout: Readout {
                col_start: 0,
                row_start: 0,
                skip: 4,
                bin: 1,
            },
            raw_width: 648,
            raw_height: 486,
            exposures_us: vec![10.0, 100.0, 1000.0, 10_000.0, 100_000.0],
            gains: vec![1.0],
            seed: 5,
            footprint: skylux_sim::sensor::Footprint::Integrated,
            small_sources: vec![],
        },
    )
    .unwrap();
    let map = map_capture(&capture_dir, &device).unwrap();
    let lookup = SkyLookup::new(&camera, &map, 4);
    // The map itself is a measurement of the sky (within its noise and pixel footprint).
    for d in [
        DVec3::Z,
        DVec3::new(0.3, -0.6, 0.74).normalize(),
        DVec3::new(-0.8, 0.2, 0.3).normalize(),
    ] {
        let (got, want) = (lookup.luminance_cd_m2(d), true_sky(d));
        assert!(
            (got / want - 1.0).abs() < 0.05,
            "map at {d}: {got} vs {want}"
        );
    }

    // RADIANCE: the exported picture as the sky glow (a source's last argument is the cone's
    // full angle: 180° is the upper hemisphere), the ground as a second glow below.
    let sky_dir = dir.path().join("sky");
    write_radiance_sky(&sky_dir, 768, &|d| lookup.luminance_cd_m2(d)).unwrap();
    let g = GROUND_CD_M2 / skylux_hps::photometry::WHITE_EFFICACY_LM_PER_W;
    let sky_rad = std::fs::read_to_string(sky_dir.join("sky.rad"))
        .unwrap()
        + &format!(
            "\nvoid glow ground_glow\n0\n0\n4 {g} {g} {g} 0\n\nground_glow source ground\n0\n0\n4 0 0 -1 180\n"
        );
    std::fs::write(sky_dir.join("sky.rad"), sky_rad).unwrap();
    let room = Path::new(ROOM).join("scene.rad");
    let mut oconv = tool(&bin, &lib, "oconv");
    oconv.current_dir(&sky_dir).arg(&room).arg("sky.rad");
    let octree = sky_dir.join("room.oct");
    std::fs::write(&octree, check_output(oconv, None)).unwrap();
    let points = std::fs::read(Path::new(ROOM).join("sensors.pts")).unwrap();
    let reference = rtrace_lux_runs(
        &bin,
        &lib,
        &sky_dir,
        &octree,
        &points,
        RTRACE_PATH_TRACING,
        32,
    );

    // Ours: the room alone, the map as the environment.
    let scene = scene::load_files(&[&room]).unwrap();
    let mut world = World::new(&scene).unwrap();
    // The environment must own what it reads; the test's camera and map live to its end.
    let camera: &'static CameraModel = Box::leak(Box::new(camera));
    let map: &'static CaptureMap = Box::leak(Box::new(map));
    let lookup = Arc::new(SkyLookup::new(camera, map, 4));
    world.set_environment(Some(Arc::new(move |d: DVec3| {
        let l = if d.z < 0.0 {
            GROUND_CD_M2
        } else {
            lookup.luminance_cd_m2(d)
        };
        DVec3::splat(l / skylux_hps::photometry::WHITE_EFFICACY_LM_PER_W)
    })));
    let sensors = scene::load_sensors(Path::new(ROOM).join("sensors.pts")).unwrap();
    let settings = Settings {
        ambient_bounces: 8,
        samples_per_sensor: OUR_SAMPLES,
        seed: 31,
        ..Settings::default()
    };
    let ours = engine::illuminance(&world, &sensors, &settings, &|_, _| {}).unwrap();
    let failures = agreement_failures("hdr-map-sky", &ours, &reference, 4.0);
    assert!(failures.is_empty(), "{failures:?}");
}

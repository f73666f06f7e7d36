//! Daylight coefficients against direct path tracing on the reference room: the matrix times
//! the patch luminances of a sky must give what the engine computes under that sky traced
//! directly (an environment radiance function), and the sun coefficient what a `light` sun
//! gives. Both sides are Monte-Carlo with independent streams, so the tolerance is their
//! combined standard error plus the patch discretisation.

use glam::DVec3;
use skylux_hps::engine::{
    daylight_coefficients, illuminance, sun_coefficients, DaylightCoefficients, Settings, World,
};
use skylux_hps::scene;
use std::sync::Arc;

const ROOM: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../../shared/scenes/test-module"
);

fn room() -> (World, Vec<scene::Sensor>) {
    let scene = scene::load(format!("{ROOM}/scene.rad")).expect("reference room");
    let sensors = scene::load_sensors(format!("{ROOM}/sensors.pts")).expect("sensors");
    (World::new(&scene).unwrap(), sensors)
}

/// A CIE-overcast-like sky with a brighter south, and a uniform ground: smooth, so MF2
/// patches resolve it.
fn sky_cd_m2(d: DVec3) -> f64 {
    if d.z < 0.0 {
        2000.0
    } else {
        8000.0 * (1.0 + 2.0 * d.z) / 3.0 * (1.0 - 0.3 * d.y)
    }
}

#[test]
fn matrix_product_equals_direct_tracing() {
    let (mut world, sensors) = room();
    // The 32-bit build runs in CI under qemu-arm, some 35 times slower here: an eighth of the
    // paths there; the tolerance below follows the standard error.
    let samples_per_sensor = if cfg!(target_pointer_width = "32") {
        50_000
    } else {
        400_000
    };
    let settings = Settings {
        ambient_bounces: 4,
        samples_per_sensor,
        seed: 7,
        ..Default::default()
    };
    let dc = daylight_coefficients(&world, &sensors, 2, &settings, &|_, _| {}).unwrap();
    let patches = dc.patches();
    // Patch luminance: the mean over a 5x5 grid inside the patch would be better; the centre
    // value is enough for a sky this smooth at MF2 (checked by the tolerance below).
    let mut lum = Vec::with_capacity(dc.bins);
    for p in 0..patches.len() {
        lum.push(sky_cd_m2(patches.centre(p)));
    }
    for p in 0..patches.len() {
        let c = patches.centre(p);
        lum.push(sky_cd_m2(DVec3::new(c.x, c.y, -c.z)));
    }
    let from_dc = dc.apply(&lum).unwrap();
    world.set_environment(Some(Arc::new(|d: DVec3| {
        DVec3::splat(sky_cd_m2(d) / 179.0)
    })));
    let direct = illuminance(&world, &sensors, &settings, &|_, _| {}).unwrap();
    for (s, (e_dc, e)) in from_dc.iter().zip(&direct).enumerate() {
        let rel = e_dc / e.illuminance_lux - 1.0;
        // The DC side has about the same relative noise as the direct side.
        let tol = 0.01 + 3.0 * std::f64::consts::SQRT_2 * e.stderr_lux / e.illuminance_lux;
        println!(
            "S{}: DC {e_dc:.1} lux, direct {:.1} ± {:.1} lux ({:+.2} %)",
            s + 1,
            e.illuminance_lux,
            e.stderr_lux,
            100.0 * rel
        );
        assert!(rel.abs() < tol, "sensor {s}: {rel} vs {tol}");
    }
    // Wrong-length input is an error, not a panic.
    assert!(dc.apply(&lum[1..]).is_err());
    // Every escape is binned: the ground bins get the downward escapes (the floor-level
    // view through the glazing of the ground outside).
    let ground: f64 = dc.row(0)[patches.len()..].iter().sum();
    assert!(ground > 0.0);
    assert_eq!(
        DaylightCoefficients::bin_of(&patches, DVec3::new(0.0, -1.0, -0.2).normalize()),
        patches
            .patch_of(DVec3::new(0.0, -1.0, 0.2).normalize())
            .map(|p| p + patches.len())
    );
}

#[test]
fn sun_coefficient_matches_a_light_sun_and_the_direct_closed_form() {
    let (mut world, sensors) = room();
    let settings = Settings {
        ambient_bounces: 0,
        samples_per_sensor: 256,
        seed: 3,
        ..Default::default()
    };
    // A low southern sun: with -ab 0 only the direct beam counts. Through the glazing
    // (RADIANCE glass, 0.65 at normal incidence) it reaches the sensors it is not shadowed
    // from; the others get 0.
    let sun = skylux_hps::camera::direction_from_alt_az(30.0, 180.0);
    let k = sun_coefficients(&mut world, &sensors, sun, &settings).unwrap();
    assert!(
        world.distant_sources().is_empty(),
        "the room is handed back"
    );
    let cos = sun.z; // sensors face up
    for (s, (c, _)) in k.iter().enumerate() {
        // Either in the beam (transmittance at 30° incidence on the south glazing between 0.55 and 0.66 of the
        // normal-incidence 0.65) or shadowed.
        let t = c / cos;
        println!("S{}: {c:.4} lux per lux DNI (t = {t:.3})", s + 1);
        assert!(
            t.abs() < 1e-12 || (0.55..0.66).contains(&t),
            "S{}: {t}",
            s + 1
        );
    }
    assert!(k.iter().any(|(c, _)| *c > 0.0), "some sensor is sunlit");
    // Refused when the room already carries a sky.
    world.set_environment(Some(Arc::new(|_| DVec3::ONE)));
    assert!(sun_coefficients(&mut world, &sensors, sun, &settings).is_err());
}

#[test]
fn matrix_file_round_trips_and_bad_files_are_errors() {
    let (world, sensors) = room();
    let settings = Settings {
        ambient_bounces: 2,
        samples_per_sensor: 256,
        seed: 5,
        ..Default::default()
    };
    let dc = daylight_coefficients(&world, &sensors, 1, &settings, &|_, _| {}).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("room.dc");
    dc.write(&path).unwrap();
    let back = DaylightCoefficients::read(&path).unwrap();
    assert_eq!(back.sensors, dc.sensors);
    assert_eq!((back.mf, back.bins), (dc.mf, dc.bins));
    for (a, b) in back.lux_per_cd_m2.iter().zip(&dc.lux_per_cd_m2) {
        assert!((a - b).abs() <= 1e-6 * b.abs().max(1e-30), "{a} vs {b}");
    }
    let lum = vec![1000.0; dc.bins];
    let mut out = vec![0.0; dc.sensors.len()];
    back.apply_into(&lum, &mut out).unwrap();
    for (o, e) in out.iter().zip(back.apply(&lum).unwrap()) {
        assert!((o - e).abs() <= 1e-9 * e.abs());
    }
    assert!(back.apply_into(&lum[1..], &mut out).is_err());
    // Truncated data, a wrong header, a missing file: errors that name the file.
    let bytes = std::fs::read(&path).unwrap();
    std::fs::write(&path, &bytes[..bytes.len() - 3]).unwrap();
    let e = DaylightCoefficients::read(&path).unwrap_err();
    assert!(e.contains("room.dc") && e.contains("data bytes"), "{e}");
    std::fs::write(&path, b"#?RADIANCE\nNROWS=1\nNCOLS=7\nSKYLUX_MF=1\n\n").unwrap();
    assert!(DaylightCoefficients::read(&path)
        .unwrap_err()
        .contains("NCOLS"));
    std::fs::write(&path, b"garbage").unwrap();
    assert!(DaylightCoefficients::read(&path).is_err());
    assert!(DaylightCoefficients::read(&dir.path().join("none")).is_err());
}

//! The map as a RADIANCE sky, read back by RADIANCE itself: rtrace looks into the glow sky
//! written by `write_radiance_sky` in many directions and must see the luminance the map
//! holds there (within the picture's resampling and RGBE quantisation, 1 %).

mod common;
use common::radiance::{check_output, radiance, tool};
use glam::DVec3;
use skylux_hps::hdr::{picture_direction, write_radiance_sky};
use skylux_hps::photometry::WHITE_EFFICACY_LM_PER_W;

#[test]
fn rtrace_sees_the_map_through_the_sky_description() {
    // Unit tests of the picture geometry first (no RADIANCE needed).
    let zenith = picture_direction(256, 256, 513).unwrap();
    assert!((zenith - DVec3::Z).length() < 1e-9);
    let north = picture_direction(256, 10, 513).unwrap();
    assert!(
        north.y > 0.9 && north.x.abs() < 1e-9,
        "north is up: {north}"
    );
    let east = picture_direction(10, 256, 513).unwrap();
    assert!(east.x > 0.9, "east is left (seen from below): {east}");
    assert!(
        picture_direction(0, 0, 513).is_none(),
        "corners are outside the horizon"
    );

    let Some((bin, lib)) = radiance() else {
        skylux_hps::prerequisite::available_or_skip(
            false,
            skylux_hps::prerequisite::REQUIRE_RADIANCE,
            "RADIANCE not found (pip install pyradiance)",
        );
        return;
    };
    // A smooth, strongly anisotropic sky: brighter towards the south-east and the zenith.
    let field = |d: DVec3| {
        4000.0 * (1.0 + 2.0 * d.z) * (1.5 + 0.5 * d.dot(DVec3::new(0.5, -0.7, 0.3).normalize()))
    };
    let dir = tempfile::tempdir().unwrap();
    write_radiance_sky(dir.path(), 1024, &field).unwrap();
    let octree = check_output(
        {
            let mut c = tool(&bin, &lib, "oconv");
            c.current_dir(dir.path()).arg("sky.rad");
            c
        },
        None,
    );
    std::fs::write(dir.path().join("sky.oct"), octree).unwrap();
    let directions: Vec<DVec3> = (0..60)
        .map(|k| {
            let alt = (5.0 + 80.0 * ((k * 37) % 60) as f64 / 60.0).to_radians();
            let az = (k as f64 * 137.5).to_radians();
            DVec3::new(az.sin() * alt.cos(), az.cos() * alt.cos(), alt.sin())
        })
        .collect();
    let rays: String = directions
        .iter()
        .map(|d| format!("0 0 0 {} {} {}\n", d.x, d.y, d.z))
        .collect();
    let out = check_output(
        {
            let mut c = tool(&bin, &lib, "rtrace");
            c.current_dir(dir.path())
                .args(["-h", "-ab", "0", "-ov", "sky.oct"]);
            c
        },
        Some(rays.as_bytes()),
    );
    let text = String::from_utf8(out).unwrap();
    let mut worst = 0.0f64;
    for (line, d) in text.lines().zip(&directions) {
        let v: Vec<f64> = line
            .split_whitespace()
            .map(|x| x.parse().unwrap())
            .collect();
        let luminance = WHITE_EFFICACY_LM_PER_W * (0.265 * v[0] + 0.670 * v[1] + 0.065 * v[2]);
        worst = worst.max((luminance / field(*d) - 1.0).abs());
    }
    assert_eq!(text.lines().count(), directions.len());
    println!(
        "rtrace reads the sky map back within {:.3} % (60 directions)",
        100.0 * worst
    );
    assert!(worst < 0.01, "worst relative difference {worst}");
}

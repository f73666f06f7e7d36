//! Mirror virtual sources (`engine::virtual_sources`): the sun reflected by a mirror on the
//! floor lights a ceiling sensor that no direct sun reaches, as RADIANCE's virtual source
//! method computes (rtrace uses it by default).
//!
//! The room: 4 × 4 × 3 m, a 2 × 1.3 m opening in the south wall, a 1 × 1 m mirror of
//! reflectance 0.9 on the floor, the sun due south at 60° elevation. The sensor at
//! (2, 3.2, 2.99) faces down: the sun is behind it, and its mirror image 30° from its normal
//! lies inside the mirror as seen from it.

use glam::DVec3;
use skylux_hps::engine::{self, Settings, World};
use skylux_hps::scene;
mod common;
use common::radiance::{check_output, lux_of_line, radiance_or_skip, rtrace_lux_runs, tool};

const SUN_RADIANCE: f64 = 1.0e6;
const SUN_ANGLE_DEG: f64 = 0.533;
const MIRROR_REFLECTANCE: f64 = 0.9;
const SENSOR: &str = "2 3.2 2.99 0 0 -1\n";

fn sun_direction() -> DVec3 {
    let e = 60f64.to_radians();
    DVec3::new(0.0, -e.cos(), e.sin())
}

fn scene_text() -> String {
    let s = sun_direction();
    format!(
        "void plastic white 0 0 5 0.6 0.6 0.6 0 0\n\
         void mirror silver 0 0 3 {r} {r} {r}\n\
         void light solar 0 0 3 {ls} {ls} {ls}\n\
         solar source sun 0 0 4 {sx} {sy} {sz} {a}\n\
         white polygon floor 0 0 12 0 0 0 0 4 0 4 4 0 4 0 0\n\
         white polygon ceiling 0 0 12 0 0 3 4 0 3 4 4 3 0 4 3\n\
         white polygon west 0 0 12 0 0 0 0 0 3 0 4 3 0 4 0\n\
         white polygon east 0 0 12 4 0 0 4 4 0 4 4 3 4 0 3\n\
         white polygon north 0 0 12 0 4 0 0 4 3 4 4 3 4 4 0\n\
         white polygon south_low 0 0 12 0 0 0 4 0 0 4 0 1.5 0 0 1.5\n\
         white polygon south_high 0 0 12 0 0 2.8 4 0 2.8 4 0 3 0 0 3\n\
         white polygon south_left 0 0 12 0 0 1.5 1 0 1.5 1 0 2.8 0 0 2.8\n\
         white polygon south_right 0 0 12 3 0 1.5 4 0 1.5 4 0 2.8 3 0 2.8\n\
         silver polygon mirror 0 0 12 1.5 1 0.001 2.5 1 0.001 2.5 2 0.001 1.5 2 0.001\n",
        r = MIRROR_REFLECTANCE,
        ls = SUN_RADIANCE,
        sx = s.x,
        sy = s.y,
        sz = s.z,
        a = SUN_ANGLE_DEG,
    )
}

fn ours(ab: u32, samples: u32) -> (f64, f64) {
    let dir = tempfile::tempdir().unwrap();
    let rad = dir.path().join("room.rad");
    std::fs::write(&rad, scene_text()).unwrap();
    let pts = dir.path().join("s.pts");
    std::fs::write(&pts, SENSOR).unwrap();
    let world = World::new(&scene::load_files(&[&rad]).unwrap()).unwrap();
    let sensors = scene::load_sensors(&pts).unwrap();
    let settings = Settings {
        ambient_bounces: ab,
        samples_per_sensor: samples,
        seed: 11,
        ..Settings::default()
    };
    let r = engine::illuminance(&world, &sensors, &settings, &|_, _| {}).unwrap();
    (r[0].illuminance_lux, r[0].stderr_lux)
}

/// Mean and standard error of rtrace -I over `samples` independent estimates
/// (`rtrace_lux_runs`); one sample, standard error 0, for a deterministic setting (`-ab 0`).
fn rtrace_lux(args: &[&str], samples: usize) -> Option<(f64, f64)> {
    let (bin, lib) = radiance_or_skip()?;
    let dir = tempfile::tempdir().unwrap();
    let rad = dir.path().join("room.rad");
    std::fs::write(&rad, scene_text()).unwrap();
    let mut oconv = tool(&bin, &lib, "oconv");
    oconv.arg(&rad);
    let oct = dir.path().join("room.oct");
    std::fs::write(&oct, check_output(oconv, None)).unwrap();
    let args: Vec<&str> = ["-h", "-I", "-u+"].iter().chain(args).copied().collect();
    if samples == 1 {
        let mut c = tool(&bin, &lib, "rtrace");
        c.args(&args).arg(&oct);
        let out = String::from_utf8(check_output(c, Some(SENSOR.as_bytes()))).unwrap();
        return Some((lux_of_line(&out), 0.0));
    }
    let runs = rtrace_lux_runs(
        &bin,
        &lib,
        dir.path(),
        &oct,
        SENSOR.as_bytes(),
        &args,
        samples,
    );
    Some(runs[0])
}

/// Direct light only (-ab 0): the sensor sees the sun only in the mirror. Closed form:
/// E = Ls Ω × ρ_mirror × cos 30° (the mirror image of the sun is 30° off the sensor's
/// normal), in lux 179 × that; rtrace -ab 0 (virtual sources on by default) within 2 %.
#[test]
fn sun_in_a_floor_mirror_lights_the_ceiling() {
    let half = (SUN_ANGLE_DEG / 2.0).to_radians();
    let omega = 2.0 * std::f64::consts::PI * (1.0 - half.cos());
    let expect = 179.0 * SUN_RADIANCE * omega * MIRROR_REFLECTANCE * 30f64.to_radians().cos();
    let (lux, se) = ours(0, 4096);
    println!("ab 0: ours {lux:.1} ± {se:.2} lux, closed form {expect:.1} lux");
    assert!(
        (lux - expect).abs() < 2e-3 * expect,
        "ours {lux} vs closed form {expect}"
    );
    if let Some((r, _)) = rtrace_lux(&["-ab", "0"], 1) {
        println!("ab 0: rtrace {r:.1} lux ({:+.2} %)", 100.0 * (lux - r) / r);
        assert!((lux - r).abs() < 0.02 * r, "ours {lux} vs rtrace {r}");
    }
}

/// With interreflection (-ab 2), against rtrace's pure path tracing: the mirrored sun now
/// also lights the room's walls and floor through the virtual source at every diffuse vertex.
/// An ambient path that reaches the sun after a mirror bounce collects nothing (RADIANCE's
/// `badcomponent`); counting it too would add, in expectation, the whole virtual-source share
/// again (here it is found by too few paths for this test to see reliably; the agreement
/// shows the rest of the accounting). Acceptance: within max(2 %, 4 × the combined standard
/// error).
#[test]
fn mirror_light_is_counted_once_with_interreflection() {
    let (lux, se) = ours(2, 16_384);
    let Some((r, r_se)) = rtrace_lux(
        &[
            "-ab", "2", "-aa", "0", "-ad", "2048", "-as", "0", "-lw", "1e-5",
        ],
        32,
    ) else {
        return;
    };
    let combined = (se * se + r_se * r_se).sqrt();
    println!(
        "ab 2: ours {lux:.1} ± {se:.1} lux, rtrace {r:.1} ± {r_se:.1} lux, diff {:+.2} % ({:+.2} σ)",
        100.0 * (lux - r) / r,
        (lux - r) / combined
    );
    let (direct_only, _) = ours(0, 1024);
    assert!(lux > direct_only * 1.01, "interreflection adds light");
    assert!(
        (lux - r).abs() <= (0.02 * r).max(4.0 * combined),
        "ours {lux} vs rtrace {r}"
    );
}

/// A mirror's back is black, as RADIANCE's `m_mirror` makes it (m_mirror.c: `r->rod < 0`
/// returns no light). A sensor facing up under a 200 m square mirror 1 m above it, a glow
/// of radiance 1 below the horizon and another above: with the mirror's front facing down,
/// the sensor sees the lower glow in it, E = ρ π L × 179 lm/W (less the 1e-4 of its
/// cosine-weighted view that passes beside the mirror); with the front facing up, it sees
/// the mirror's back, black, and the sky beside it: E ≈ 1e-4 π L × 179.
#[test]
fn a_mirror_seen_from_behind_is_black() {
    let lux = |front_down: bool| {
        let dir = tempfile::tempdir().unwrap();
        let square = if front_down {
            "-100 -100 1 -100 100 1 100 100 1 100 -100 1"
        } else {
            "-100 -100 1 100 -100 1 100 100 1 -100 100 1"
        };
        let text = format!(
            "void mirror silver 0 0 3 {r} {r} {r}\n\
             void glow bright 0 0 4 1 1 1 0\n\
             bright source sky 0 0 4 0 0 1 180\n\
             bright source ground 0 0 4 0 0 -1 180\n\
             silver polygon mirror 0 0 12 {square}\n",
            r = MIRROR_REFLECTANCE,
        );
        let rad = dir.path().join("m.rad");
        std::fs::write(&rad, text).unwrap();
        let pts = dir.path().join("s.pts");
        std::fs::write(&pts, "0 0 0 0 0 1\n").unwrap();
        let world = World::new(&scene::load_files(&[&rad]).unwrap()).unwrap();
        let sensors = scene::load_sensors(&pts).unwrap();
        let settings = Settings {
            ambient_bounces: 2,
            samples_per_sensor: 4096,
            seed: 5,
            ..Settings::default()
        };
        engine::illuminance(&world, &sensors, &settings, &|_, _| {}).unwrap()[0].illuminance_lux
    };
    let unit = std::f64::consts::PI * engine::WHITE_EFFICACY_LM_PER_W;
    let (front, back) = (lux(true), lux(false));
    println!("front {front:.2} lux, back {back:.4} lux, π L 179 = {unit:.1} lux");
    assert!(
        (front / (MIRROR_REFLECTANCE * unit) - 1.0).abs() < 0.01,
        "front: {front} lux against {}",
        MIRROR_REFLECTANCE * unit
    );
    assert!(back < 1e-3 * unit, "back: {back} lux, should be black");
}

/// A patterned mirror relays the sun with its colour times the pattern where the relayed ray
/// meets it (m_mirror.c): the same room at `-ab 0` with the mirror under a `colorfunc` that
/// varies along both axes, five ceiling sensors whose mirror images of the sun fall on
/// different parts of it. Each within 0.5 % of the closed form L Ω ρ(q) cos 30° (ρ(q) the
/// colour times the pattern at the point q the sensor sees the sun in) and within 1 % of
/// rtrace `-ab 0`.
#[test]
fn a_patterned_mirror_relays_the_sun_with_its_pattern() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("mirror.cal"),
        "mr = 0.5 + 0.5 * (Px - 1.5);\nmg = 1 - 0.6 * (Py - 1);\nmb = 0.7;\n",
    )
    .unwrap();
    let text = scene_text().replace(
        "void mirror silver 0 0 3",
        "void colorfunc tint 4 mr mg mb mirror.cal\n0\n0\ntint mirror silver 0 0 3",
    );
    let rad = dir.path().join("room.rad");
    std::fs::write(&rad, &text).unwrap();
    // Mirror points with y from 1.1 to 1.5: further north the wall above the opening
    // shades the relayed sun.
    let sensors_text = "2 3.2 2.99 0 0 -1\n1.7 3.2 2.99 0 0 -1\n2.3 3.0 2.99 0 0 -1\n\
                        1.6 2.85 2.99 0 0 -1\n2.4 3.1 2.99 0 0 -1\n";
    let pts = dir.path().join("s.pts");
    std::fs::write(&pts, sensors_text).unwrap();
    let scene = scene::load_files_with(
        &[&rad],
        &scene::LoadOptions {
            working_directory: Some(dir.path().to_path_buf()),
            ..Default::default()
        },
    )
    .unwrap();
    let world = World::new(&scene).unwrap();
    let sensors = scene::load_sensors(&pts).unwrap();
    let settings = Settings {
        ambient_bounces: 0,
        samples_per_sensor: 4096,
        seed: 5,
        ..Settings::default()
    };
    let ours = engine::illuminance(&world, &sensors, &settings, &|_, _| {}).unwrap();
    let half = (SUN_ANGLE_DEG / 2.0).to_radians();
    let omega = 2.0 * std::f64::consts::PI * (1.0 - half.cos());
    // Where each sensor sees the sun: down its mirrored direction to the floor.
    let s = sun_direction();
    let mirrored = DVec3::new(s.x, s.y, -s.z);
    let rtrace = radiance_or_skip().map(|(bin, lib)| {
        let mut oconv = tool(&bin, &lib, "oconv");
        oconv.current_dir(dir.path()).arg("room.rad");
        let oct = dir.path().join("room.oct");
        std::fs::write(&oct, check_output(oconv, None)).unwrap();
        let mut c = tool(&bin, &lib, "rtrace");
        c.current_dir(dir.path())
            .args(["-h", "-I", "-ab", "0"])
            .arg(&oct);
        let out = String::from_utf8(check_output(c, Some(sensors_text.as_bytes()))).unwrap();
        out.lines().map(lux_of_line).collect::<Vec<f64>>()
    });
    let mut values = Vec::new();
    for (k, (sensor, result)) in sensors.iter().zip(&ours).enumerate() {
        let p = sensor.position_m;
        let q = p + mirrored * (p.z - 0.001) / -mirrored.z;
        let pattern = DVec3::new(0.5 + 0.5 * (q.x - 1.5), 1.0 - 0.6 * (q.y - 1.0), 0.7);
        let rho = MIRROR_REFLECTANCE * pattern;
        let expect = 179.0
            * SUN_RADIANCE
            * omega
            * (0.265 * rho.x + 0.670 * rho.y + 0.065 * rho.z)
            * 30f64.to_radians().cos();
        let lux = result.illuminance_lux;
        println!(
            "S{k}: ours {lux:.1} lux, closed form {expect:.1} (mirror point {:.2}, {:.2}){}",
            q.x,
            q.y,
            rtrace
                .as_ref()
                .map(|r| format!(", rtrace {:.1}", r[k]))
                .unwrap_or_default()
        );
        assert!((lux / expect - 1.0).abs() < 5e-3, "S{k}: {lux} vs {expect}");
        if let Some(r) = &rtrace {
            assert!(
                (lux / r[k] - 1.0).abs() < 0.01,
                "S{k}: {lux} vs rtrace {}",
                r[k]
            );
        }
        values.push(lux);
    }
    let spread = values.iter().cloned().fold(f64::MIN, f64::max)
        / values.iter().cloned().fold(f64::MAX, f64::min);
    assert!(
        spread > 1.2,
        "the pattern must vary over the mirror ({spread})"
    );
}

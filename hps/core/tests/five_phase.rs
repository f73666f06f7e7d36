//! The five-phase direct-sun term (issue 20 item 4) beside the three-phase, on a room with
//! the LBNL tutorial's venetian blinds in its window, against our engine's direct path
//! tracing of the detailed geometry (clear glass and 306 slat polygons, the geometry genBSDF
//! made `blinds.xml` from) under a gensky sunny sky.
//!
//! The three-phase (T = `blinds.xml`, Klems) smears the sun over its Tregenza patch and the
//! Klems patches; the five-phase replaces the sun's direct part by the sun at its actual
//! direction through the detailed geometry (C_ds: the room blackened, the blinds as they
//! are). The detailed geometry is genBSDF's input for `blinds.xml` (the tutorial's
//! `blinds.rad`), placed as RADIANCE's matrices read the XML. Sensors in the beam are taken in groups of 24 along 17 cm of the workplane (four
//! periods of the slats' shadow stripes), whose mean is compared: a point sensor sits in a
//! stripe or in a shadow, which no BSDF resolves.
//!
//! Needs RADIANCE's gensky (pyradiance wheel); skipped without it.

mod common;

use common::corpus::corpus;
use common::radiance::radiance_or_skip;
use glam::DVec3;
use skylux_hps::bsdf::{Band, KlemsTransmission};
use skylux_hps::engine::material::bright;
use skylux_hps::engine::phase::{
    daylight_matrix, five_phase, view_matrix, KlemsWindow, PhaseMatrices,
};
use skylux_hps::engine::sky::DistantKind;
use skylux_hps::engine::{self, Settings, World};
use skylux_hps::scene;
use skylux_hps::sky::SkyPatches;
use std::path::Path;

/// A 6.096 m × 6.096 m × 3.048 m room with the tutorial's glazing opening in its south wall
/// (x 0..6.096, z 0.9144..2.4384, y = 0); `reflectance` of its walls (0: blackened).
fn room(walls: f64, floor: f64, ceiling: f64) -> String {
    let (w, d, h, lo, hi) = (6.096, 6.096, 3.048, 0.9144, 2.4384);
    let quad = |m: &str, name: &str, c: [[f64; 3]; 4]| {
        let mut s = format!("{m} polygon {name} 0 0 12");
        for p in c {
            s.push_str(&format!(" {} {} {}", p[0], p[1], p[2]));
        }
        s + "\n"
    };
    let mut s = format!(
        "void plastic wall 0 0 5 {walls} {walls} {walls} 0 0\n\
         void plastic floor 0 0 5 {floor} {floor} {floor} 0 0\n\
         void plastic ceiling 0 0 5 {ceiling} {ceiling} {ceiling} 0 0\n"
    );
    s += &quad(
        "floor",
        "floor",
        [[0., 0., 0.], [w, 0., 0.], [w, d, 0.], [0., d, 0.]],
    );
    s += &quad(
        "ceiling",
        "ceiling",
        [[0., 0., h], [0., d, h], [w, d, h], [w, 0., h]],
    );
    s += &quad(
        "wall",
        "east",
        [[w, 0., 0.], [w, 0., h], [w, d, h], [w, d, 0.]],
    );
    s += &quad(
        "wall",
        "west",
        [[0., 0., 0.], [0., d, 0.], [0., d, h], [0., 0., h]],
    );
    s += &quad(
        "wall",
        "north",
        [[0., d, 0.], [w, d, 0.], [w, d, h], [0., d, h]],
    );
    s += &quad(
        "wall",
        "sill",
        [[0., 0., 0.], [0., 0., lo], [w, 0., lo], [w, 0., 0.]],
    );
    s += &quad(
        "wall",
        "head",
        [[0., 0., hi], [0., 0., h], [w, 0., h], [w, 0., hi]],
    );
    s
}

const WINDOW: &str = "void glow g 0 0 4 1 1 1 0\n\
    g polygon window 0 0 12 0 0 0.9144 0 0 2.4384 6.096 0 2.4384 6.096 0 0.9144\n";

/// Groups of 24 workplane sensors (0.75 m, facing up) along y at x = 3.048 m, each 17.2 cm
/// long (a period or more of the slats' stripes).
const GROUPS: [(&str, f64); 3] = [
    ("beam middle", 2.0),
    ("beam near edge", 0.65),
    ("before the beam", 0.3),
];
const PER_GROUP: usize = 24;

fn sensors() -> String {
    let mut s = String::new();
    for (_, y0) in GROUPS {
        for k in 0..PER_GROUP {
            let y = y0 + 0.172 * (k as f64 + 0.5) / PER_GROUP as f64;
            s.push_str(&format!("3.048 {y:.5} 0.75 0 0 1\n"));
        }
    }
    s
}

fn world(files: &[&Path]) -> World {
    World::new(&scene::load_files(files).unwrap()).unwrap()
}

#[test]
fn five_phase_sensors_in_the_beam_match_the_detailed_geometry() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let path = |name: &str| dir.path().join(name);
    std::fs::write(path("room.rad"), room(0.5, 0.2, 0.7)).unwrap();
    std::fs::write(path("black.rad"), room(0.0, 0.0, 0.0)).unwrap();
    std::fs::write(path("window.rad"), WINDOW).unwrap();
    std::fs::write(path("sensors.pts"), sensors()).unwrap();
    // CIE clear sky with its sun due south at 15°, low enough to pass between the slats
    // (the blinds' T for light travelling 35° down is 0.05, at 15° about 0.2).
    let sky_text = common::compare::sky(&bin, &lib, "gensky", &["-ang", "15", "0", "+s"]);
    std::fs::write(path("sky.rad"), &sky_text).unwrap();
    // The blinds as genBSDF saw them (its input, `blinds.rad`: glass at z = 0, slats on its
    // -z side, up +y) turned so that genBSDF's +z faces the room, as RADIANCE reads the XML
    // on a window whose normal points in: the slats stand outside the glass. (The tutorial's
    // `blindsOnly.rad` puts them inside, mirrored: slats that descend into the room, which
    // pass the sky that the XML's T, identical to rmtxop's, blocks.)
    let blinds = path("blinds.rad");
    std::fs::write(
        &blinds,
        format!(
            "!xform -ry 180 -rx 90 -t 6.096 0 0.9271 {}\n",
            corpus()
                .join("sariths-matrix-tutorial/room/blinds/blinds.rad")
                .display()
        ),
    )
    .unwrap();
    let sensors = scene::load_sensors(path("sensors.pts")).unwrap();

    // The reference: the room with the glass and the slats, under the sky and its sun.
    let reference_world = world(&[&path("room.rad"), &blinds, &path("sky.rad")]);
    let reference = engine::illuminance(
        &reference_world,
        &sensors,
        &Settings {
            ambient_bounces: 6,
            samples_per_sensor: common::compare::our_samples_here(16_384),
            seed: 1,
            ..Default::default()
        },
        &|_, _| {},
    )
    .unwrap();

    // The sun and the sky vector without it (a `light` sun is not in escape_radiance).
    let sky_world = world(&[&path("sky.rad")]);
    let sun = sky_world
        .distant_sources()
        .iter()
        .find(|s| s.kind == DistantKind::Light)
        .expect("gensky +s has a sun");
    let sun_direction = sun.direction;
    let dni_w_m2 = bright(sun.radiance_w_sr_m2) * sun.solid_angle_sr;
    let patches = SkyPatches::tregenza();
    let (mut sum, mut count) = (vec![0.0; 1 + patches.len()], vec![0.0; 1 + patches.len()]);
    let n = 600;
    for i in 0..n {
        let z = -1.0 + 2.0 * (i as f64 + 0.5) / n as f64;
        for j in 0..2 * n {
            let phi = std::f64::consts::TAU * (j as f64 + 0.5) / (2 * n) as f64;
            let r = (1.0 - z * z).sqrt();
            let d = DVec3::new(r * phi.cos(), r * phi.sin(), z);
            let bin = if z < 0.0 {
                Some(0)
            } else {
                patches.patch_of(d).map(|p| p + 1)
            };
            if let Some(b) = bin {
                sum[b] += bright(sky_world.escape_radiance(d));
                count[b] += 1.0;
            }
        }
    }
    let sky: Vec<f64> = sum.iter().zip(&count).map(|(s, c)| s / c).collect();

    // The matrices: the room without its glazing, the blinds as their Klems BSDF.
    let t = KlemsTransmission::load(
        &corpus().join("bsdf/sariths-matrix-tutorial/room/blinds/blinds.xml"),
        Band::Visible,
    )
    .unwrap();
    let window =
        KlemsWindow::load(&path("window.rad"), DVec3::Z, t.incident_basis.clone()).unwrap();
    let room_world = world(&[&path("room.rad")]);
    let settings = |ab: u32, n: u32, seed: u64| Settings {
        ambient_bounces: ab,
        samples_per_sensor: common::compare::our_samples_here(n),
        seed,
        ..Default::default()
    };
    let v = view_matrix(
        &room_world,
        &sensors,
        &window,
        &settings(6, 65_536, 2),
        &|_, _| {},
    )
    .unwrap();
    let v_direct = view_matrix(
        &room_world,
        &sensors,
        &window,
        &settings(1, 65_536, 3),
        &|_, _| {},
    )
    .unwrap();
    let d = daylight_matrix(&room_world, &window, 1, &settings(2, 16_384, 4), &|_, _| {}).unwrap();
    let d_direct =
        daylight_matrix(&room_world, &window, 1, &settings(0, 16_384, 5), &|_, _| {}).unwrap();
    // C_ds: the sun at its direction through the slats and the glass, the room black.
    let mut black = world(&[&path("black.rad"), &blinds]);
    let c_ds: Vec<f64> =
        engine::sun_coefficients(&mut black, &sensors, sun_direction, &settings(3, 4096, 6))
            .unwrap()
            .into_iter()
            .map(|(c, _)| c)
            .collect();
    let m = PhaseMatrices {
        v: &v,
        t: &t.matrix,
        d: &d,
        v_direct: &v_direct,
        d_direct: &d_direct,
    };
    let (five, three) = five_phase(&m, &sky, 1, sun_direction, dni_w_m2, &c_ds).unwrap();

    // Beside it, reported only: C_ds through a thin BSDF on the window instead of the
    // detailed blinds, the room black, one bounce (the sun through the data at the window
    // hit): the corpus's tensor tree of the same blinds (`blindsT3.xml`, genBSDF -t3 5) and
    // the Klems data. TensorTree3 is isotropic: it cannot hold venetian blinds' dependence on
    // the profile angle (the tutorial's anisotropic T4 file is not in the corpus snapshot);
    // one run read the beam 81-107 % high with it, 18-39 % low with Klems.
    let thin_bsdf_c_ds = |xml: &str, name: &str, seed: u64| {
        std::fs::write(
            path(name),
            format!(
                "void BSDF thin 6 0 {} 0 0 1 .\n0\n0\nthin polygon window 0 0 12 0 0 0.9144 \
                 0 0 2.4384 6.096 0 2.4384 6.096 0 0.9144\n",
                corpus()
                    .join("bsdf/sariths-matrix-tutorial/room/blinds")
                    .join(xml)
                    .display()
            ),
        )
        .unwrap();
        let mut room = world(&[&path("black.rad"), &path(name)]);
        let c: Vec<f64> = engine::sun_coefficients(
            &mut room,
            &sensors,
            sun_direction,
            &settings(1, 16_384, seed),
        )
        .unwrap()
        .into_iter()
        .map(|(c, _)| c)
        .collect();
        let (e, _) = five_phase(&m, &sky, 1, sun_direction, dni_w_m2, &c).unwrap();
        e.iter().map(|e| 179.0 * e).collect::<Vec<f64>>()
    };
    let five_tree_lux = thin_bsdf_c_ds("blindsT3.xml", "tree.rad", 7);
    let five_klems_lux = thin_bsdf_c_ds("blinds.xml", "klems.rad", 8);

    let mean = |values: &[f64], g: usize| {
        values[g * PER_GROUP..(g + 1) * PER_GROUP]
            .iter()
            .sum::<f64>()
            / PER_GROUP as f64
    };
    let reference_lux: Vec<f64> = reference.iter().map(|s| s.illuminance_lux).collect();
    let five_lux: Vec<f64> = five.iter().map(|e| 179.0 * e).collect();
    let three_lux: Vec<f64> = three.iter().map(|e| 179.0 * e).collect();
    println!(
        "sun {:.1}° altitude, DNI {:.0} W/m2 ({:.0} lux)",
        sun_direction.z.asin().to_degrees(),
        dni_w_m2,
        179.0 * dni_w_m2
    );
    let mut errors = Vec::new();
    for (g, (label, _)) in GROUPS.iter().enumerate() {
        let (r, f, t3) = (
            mean(&reference_lux, g),
            mean(&five_lux, g),
            mean(&three_lux, g),
        );
        println!(
            "{label}: detailed geometry {r:.0} lux, five-phase {f:.0} lux ({:+.1} %), \
             three-phase {t3:.0} lux ({:+.1} %)",
            100.0 * (f / r - 1.0),
            100.0 * (t3 / r - 1.0)
        );
        let (ft, fk) = (mean(&five_tree_lux, g), mean(&five_klems_lux, g));
        println!(
            "{label}: five-phase with C_ds through a thin BSDF: the isotropic tensor tree \
             {ft:.0} lux ({:+.1} %), the Klems data {fk:.0} lux ({:+.1} %)",
            100.0 * (ft / r - 1.0),
            100.0 * (fk / r - 1.0)
        );
        errors.push((f / r - 1.0, t3 / r - 1.0));
    }
    // In the beam: the five-phase within 5 %; the three-phase off by far more (its sun is
    // smeared over a Tregenza patch and the Klems patches).
    for (g, (five_err, three_err)) in errors.iter().enumerate().take(2) {
        let label = GROUPS[g].0;
        assert!(five_err.abs() < 0.05, "{label}: five-phase {five_err}");
        assert!(
            three_err.abs() > 0.1 && three_err.abs() > 3.0 * five_err.abs(),
            "{label}: three-phase {three_err} against five-phase {five_err}"
        );
    }
}

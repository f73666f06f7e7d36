//! The image-based five-phase method (issue 20 item 4) on a simulated campaign: a room with
//! the LBNL tutorial's venetian blinds as detailed geometry in its south window (genBSDF's
//! input, `blinds.rad`, placed as RADIANCE reads `blinds.xml`), a clear winter noon in
//! Lausanne (the sun at 20°, low enough to pass between the slats). The campaign's truth is
//! the engine's direct path tracing of the detailed geometry under the true sky; the
//! five-phase sees only what the device sees: the captures' luminance map with the sun
//! removed as the sky vector, and the sun from the extracted disk (direction and direct-normal
//! illuminance), through V, T = `blinds.xml`, D and the direct matrices, with C_ds through
//! the detailed blinds at the extracted sun's direction (the room blackened).
//!
//! Sensors in the beam are taken in groups of 24 along 17 cm of the workplane (the slats'
//! stripes), group means compared; the three-phase (the measured sky with the sun left in
//! its patch) is reported beside.

use glam::DVec3;
use skylux_hps::bsdf::{Band, KlemsTransmission};
use skylux_hps::campaign::Campaign;
use skylux_hps::engine::phase::{
    daylight_matrix, five_phase, sky_vector_from_luminance, view_matrix, KlemsWindow, PhaseMatrices,
};
use skylux_hps::engine::{self, Settings, World, WHITE_EFFICACY_LM_PER_W};
use skylux_hps::model::{capture_terms, load_captures, Room};
use skylux_hps::scene;
use skylux_sim::campaign::{simulate_campaign, CampaignSpec, DaySky};
use std::path::{Path, PathBuf};

fn corpus() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/data/radiance-corpus")
}

/// A 6.096 m × 6.096 m × 3.048 m room, the tutorial's 6.096 m × 1.524 m opening in its south
/// wall (y = 0).
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

/// The blinds as genBSDF saw them, genBSDF's +z towards the room (see tests/five_phase.rs in
/// hps/core): the slats outside the glass.
fn blinds() -> String {
    format!(
        "!xform -ry 180 -rx 90 -t 6.096 0 0.9271 {}\n",
        corpus()
            .join("sariths-matrix-tutorial/room/blinds/blinds.rad")
            .display()
    )
}

const GROUPS: [(&str, f64); 3] = [
    ("beam middle", 2.0),
    ("beam near edge", 0.55),
    ("before the beam", 0.2),
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

#[test]
fn image_based_five_phase_against_the_campaign_truth() {
    let blinds_rad = corpus().join("sariths-matrix-tutorial/room/blinds/blinds.rad");
    assert!(
        blinds_rad.is_file(),
        "{} not found: the shared corpus beside the checkout is needed",
        blinds_rad.display()
    );
    let dir = tempfile::tempdir().unwrap();
    let p = |name: &str| dir.path().join(name);
    let room_dir = p("room");
    std::fs::create_dir_all(&room_dir).unwrap();
    std::fs::write(room_dir.join("scene.rad"), room(0.5, 0.2, 0.7) + &blinds()).unwrap();
    std::fs::write(room_dir.join("sensors.pts"), sensors()).unwrap();
    std::fs::write(p("room-only.rad"), room(0.5, 0.2, 0.7)).unwrap();
    std::fs::write(p("black.rad"), room(0.0, 0.0, 0.0) + &blinds()).unwrap();
    std::fs::write(
        p("window.rad"),
        "void glow g 0 0 4 1 1 1 0\n\
         g polygon window 0 0 12 0 0 0.9144 0 0 2.4384 6.096 0 2.4384 6.096 0 0.9144\n",
    )
    .unwrap();

    // The campaign: one clear capture at 13:30 (UTC+2 clock) on 21 December.
    let mut spec = CampaignSpec::lausanne(room_dir.clone());
    spec.days = vec![(
        chrono::NaiveDate::from_ymd_opt(2017, 12, 21).unwrap(),
        DaySky::Clear,
    )];
    spec.hours = vec![13.5];
    // Full-resolution frames at skip 4: at skip 8 the disk covers too few groups to
    // extract (undersampled, fill factor 0.25).
    spec.skip = 4;
    spec.truth_samples = 4096;
    let out = p("campaign");
    let start = std::time::Instant::now();
    let truth = simulate_campaign(&out, &spec, &|_, _| {}).expect("simulated campaign");
    println!("campaign: {:.1} s", start.elapsed().as_secs_f64());
    let truth = &truth[0];

    // What the device sees: the merged map, the sun extracted, the sky without it.
    let campaign = Campaign::open(&out).unwrap();
    let captures = load_captures(&campaign, &spec.device, &|_, _| {}).unwrap();
    let light = Settings {
        ambient_bounces: 1,
        samples_per_sensor: 16,
        seed: 1,
        ..Default::default()
    };
    let mut model_room = Room::load(&campaign, 1, light, &|_, _| {}).unwrap();
    let terms = capture_terms(&mut model_room, &captures, &spec.device, &|_, _| {}).unwrap();
    let terms = &terms[0];
    println!(
        "truth: sun altitude {:.1}°, azimuth {:.1}° (from north towards east), GHI {:.0} lux",
        truth.sun_direction.z.asin().to_degrees(),
        truth
            .sun_direction
            .x
            .atan2(truth.sun_direction.y)
            .to_degrees(),
        truth.global_horizontal_lux
    );
    let sun = terms
        .sun
        .as_ref()
        .unwrap_or_else(|| panic!("no sun extracted: {:?}", terms.sun_missing));
    let patches = model_room.dc.patches().len();
    let ground_cd_m2 = 0.2 * terms.outdoor_horizontal_lux / std::f64::consts::PI;
    let sky = sky_vector_from_luminance(&terms.bins_without_sun_cd_m2[..patches], ground_cd_m2);
    let dni_w_m2 = sun.direct_normal_illuminance_lux / WHITE_EFFICACY_LM_PER_W;
    println!(
        "sun extracted at {:.2}° from the truth's, DNI {:.0} lux; outdoor horizontal {:.0} lux \
         (truth {:.0})",
        sun.direction
            .angle_between(truth.sun_direction)
            .to_degrees(),
        sun.direct_normal_illuminance_lux,
        terms.outdoor_horizontal_lux,
        truth.global_horizontal_lux
    );

    // The matrices of the room without its glazing, T the blinds' Klems XML.
    let t = KlemsTransmission::load(
        &corpus().join("bsdf/sariths-matrix-tutorial/room/blinds/blinds.xml"),
        Band::Visible,
    )
    .unwrap();
    let window = KlemsWindow::load(&p("window.rad"), DVec3::Z, t.incident_basis.clone()).unwrap();
    let sensors = scene::load_sensors(room_dir.join("sensors.pts")).unwrap();
    let room_world = World::new(&scene::load(p("room-only.rad")).unwrap()).unwrap();
    let settings = |ab: u32, n: u32, seed: u64| Settings {
        ambient_bounces: ab,
        samples_per_sensor: n,
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
    let mut black = World::new(&scene::load(p("black.rad")).unwrap()).unwrap();
    let c_ds: Vec<f64> =
        engine::sun_coefficients(&mut black, &sensors, sun.direction, &settings(3, 4096, 6))
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
    let (five, three) = five_phase(&m, &sky, 1, sun.direction, dni_w_m2, &c_ds).unwrap();

    let mean = |values: &[f64], g: usize| {
        values[g * PER_GROUP..(g + 1) * PER_GROUP]
            .iter()
            .sum::<f64>()
            / PER_GROUP as f64
    };
    let lux = |e: &[f64]| {
        e.iter()
            .map(|e| WHITE_EFFICACY_LM_PER_W * e)
            .collect::<Vec<_>>()
    };
    let (five, three) = (lux(&five), lux(&three));
    let mut errors = Vec::new();
    for (g, (label, _)) in GROUPS.iter().enumerate() {
        let (r, f, t3) = (mean(&truth.room_lux, g), mean(&five, g), mean(&three, g));
        println!(
            "{label}: truth (detailed geometry, true sky) {r:.0} lux, image-based five-phase \
             {f:.0} lux ({:+.1} %), three-phase {t3:.0} lux ({:+.1} %)",
            100.0 * (f / r - 1.0),
            100.0 * (t3 / r - 1.0)
        );
        errors.push((f / r - 1.0, t3 / r - 1.0));
    }
    // In the beam: the image-based five-phase within 5 % of the truth, and closer than the
    // three-phase (one run: +2.4 % and -1.9 % against +8.5 % and -7.1 %; the three-phase's
    // error depends on where the sun falls in its Tregenza patch, 24-33 % in
    // hps/core/tests/five_phase.rs).
    for (g, (five_err, three_err)) in errors.iter().enumerate().take(2) {
        let label = GROUPS[g].0;
        assert!(five_err.abs() < 0.05, "{label}: five-phase {five_err}");
        assert!(
            three_err.abs() > five_err.abs(),
            "{label}: three-phase {three_err} against five-phase {five_err}"
        );
    }
}

//! A window declared with several shading states (issue 20 item 5): every state's
//! illuminance from the room's matrices traced once (V, V_d, D, D_d), one product per state
//! and a sun term over a grid of window points, against a converged `rtrace` of the room with
//! that state's XML as its `BSDF` window, live from the pyradiance wheel.
//!
//! - the data: a state's T is its data averaged over the window's Klems patch pairs; on
//!   Klems data the average is the data, and for the electrochromic glazing (alike both
//!   ways) the file's matrix as dctimestep reads it; a tensor tree is refused by name;
//! - the states against rtrace: the box room of `bsdf_windows_vs_rtrace` (4 m × 5 m × 3 m,
//!   one south window) with the frads Satine shade, the electrochromic glazing and the 30°
//!   blinds, under a CIE overcast sky and a clear sky whose sun comes through the window
//!   at 60°, on the workplane and at an occupant's eye facing the window (the glare views'
//!   Ev); the room's glazing is taken out of the room by the window file itself.

mod common;

use common::box_room::{box_room, BOX_SENSORS};
use common::compare::sky;
use common::corpus::corpus;
use common::radiance::{check_output, radiance_or_skip, rtrace_lux_runs, tool};
use glam::DVec3;
use skylux_hps::bsdf::{AngleBasis, Band, Bsdf, KlemsTransmission};
use skylux_hps::engine::phase::shading_states::klems_average;
use skylux_hps::engine::phase::{
    remove_glazing, sky_vector_of_world, KlemsWindow, ShadedWindow, ShadingState, StateMatrices,
    SunView,
};
use skylux_hps::engine::{Settings, World, WHITE_EFFICACY_LM_PER_W};
use skylux_hps::scene;
use std::path::{Path, PathBuf};

/// The window as the matrices' receiver: front normal +y, into the room.
const WINDOW: &str = "void glow window_glow 0 0 4 1 1 1 0\n\
                      window_glow polygon window 0 0 12 1 0 0.9 1 0 2.1 3 0 2.1 3 0 0.9\n";

/// The box room's workplane sensors and an occupant's eye at 1.2 m facing the window (S7).
fn sensors() -> String {
    format!("{BOX_SENSORS}2.0 3.0 1.2 0 -1 0\n")
}

const STATES: [(&str, &str); 3] = [
    ("satine", "bsdf/frads/2011-SA1.xml"),
    ("ec60", "bsdf/frads/ec60.xml"),
    ("blinds30", "bsdf/frads/blinds30.xml"),
];

fn window(dir: &Path) -> KlemsWindow {
    let path = dir.join("window.rad");
    std::fs::write(&path, WINDOW).unwrap();
    KlemsWindow::load(
        &path,
        DVec3::Z,
        AngleBasis::builtin("LBNL/Klems Full").unwrap(),
    )
    .unwrap()
}

#[test]
fn klems_data_averaged_over_the_window_patches_is_the_data() {
    let dir = tempfile::tempdir().unwrap();
    let window = window(dir.path());
    for (name, file) in STATES {
        let text = std::fs::read_to_string(corpus().join(file)).unwrap();
        let data = Bsdf::from_xml(&text, "state.xml", Band::Visible).unwrap();
        // Klems data is constant over each patch pair: 9 × 9 direction pairs per entry give
        // what one gives.
        let (one, nine) = (
            klems_average(&data, &window, 1),
            klems_average(&data, &window, 3),
        );
        let worst = one
            .values
            .iter()
            .zip(&nine.values)
            .map(|(a, b)| (a - b).abs() / b.abs().max(1e-3))
            .fold(0.0, f64::max);
        assert!(worst < 1e-9, "{name}: {worst}");
        let state = ShadingState::from_xml(name, &text, "state.xml", &window).unwrap();
        assert_eq!(state.transmission().values, one.values, "{name}");
    }
    // The electrochromic glazing's two transmission blocks are alike and symmetric: read as
    // rtrace reads it (the room's side incident), T is the file's matrix as dctimestep reads
    // it, entry by entry. Through a mirrored or rotated frame it would not be.
    let text = std::fs::read_to_string(corpus().join(STATES[1].1)).unwrap();
    let state = ShadingState::from_xml("ec60", &text, "ec60.xml", &window).unwrap();
    let file_t = KlemsTransmission::from_xml(&text, "ec60.xml", Band::Visible).unwrap();
    let worst = state
        .transmission()
        .values
        .iter()
        .zip(&file_t.matrix.values)
        .map(|(a, b)| (a - b).abs() / b.abs().max(1e-3))
        .fold(0.0, f64::max);
    println!("ec60: T read both ways, worst relative difference {worst:.2e}");
    // The blocks agree to the file's printed digits, not bit for bit.
    assert!(worst < 1e-3, "ec60: {worst}");
    // A tensor tree (the LBNL tutorial's blinds at tree resolution) is refused, naming the
    // file and what converts it: averaged over 3 x 3 direction pairs per patch pair it read
    // -19 % to +30 % against rtrace.
    let tree = corpus().join("bsdf/sariths-matrix-tutorial/room/blinds/blindsT3.xml");
    let e = ShadingState::load("tree", &tree, &window)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("blindsT3.xml") && e.contains("bsdf2klems"),
        "{e}"
    );
}

/// The room's shaded window, its matrices traced once, and the world the sun crosses.
struct Case {
    dir: tempfile::TempDir,
    shaded: ShadedWindow,
    outside: World,
}

fn case() -> Case {
    let dir = tempfile::tempdir().unwrap();
    let window = window(dir.path());
    // The room as the user has it (its glazing a BSDF of the first state), the glazing taken
    // out by the window file.
    let room_path = dir.path().join("room.rad");
    std::fs::write(&room_path, box_room(&corpus().join(STATES[0].1))).unwrap();
    let mut room_scene = scene::load(&room_path).unwrap();
    let removed = remove_glazing(&mut room_scene, &window);
    assert_eq!(removed, vec!["window".to_string()]);
    let room = World::new(&room_scene).unwrap();
    let sensors = scene::parse_sensors("sensors.pts", sensors().as_bytes()).unwrap();
    let view = Settings {
        ambient_bounces: 8,
        samples_per_sensor: VIEW_PATHS,
        seed: 11,
        ..Settings::default()
    };
    let daylight = Settings {
        ambient_bounces: 2,
        samples_per_sensor: 4096,
        seed: 12,
        ..Settings::default()
    };
    let m = StateMatrices::trace(
        &room,
        &room,
        &sensors,
        &window,
        4,
        &view,
        &daylight,
        &|_, _| {},
    )
    .unwrap();
    let states = STATES
        .iter()
        .map(|(name, file)| ShadingState::load(name, &corpus().join(file), &window).unwrap())
        .collect();
    let sun_view = SunView::new(&room, &sensors, &window, 32);
    let shaded = ShadedWindow::new(window.clone(), 4, states, &m, sun_view).unwrap();
    Case {
        dir,
        shaded,
        outside: room,
    }
}

fn rtrace_reference(
    bin: &Path,
    lib: &Option<PathBuf>,
    dir: &Path,
    xml: &Path,
    sky_text: &[u8],
    label: &str,
) -> Vec<(f64, f64)> {
    let room = dir.join(format!("{label}.rad"));
    std::fs::write(&room, box_room(xml)).unwrap();
    let sky_path = dir.join(format!("{label}-sky.rad"));
    std::fs::write(&sky_path, sky_text).unwrap();
    let mut oconv = tool(bin, lib, "oconv");
    oconv.arg("-f").arg(&room).arg(&sky_path);
    let octree = dir.join(format!("{label}.oct"));
    std::fs::write(&octree, check_output(oconv, None)).unwrap();
    rtrace_lux_runs(
        bin,
        lib,
        dir,
        &octree,
        sensors().as_bytes(),
        &[
            "-h", "-I", "-u+", "-ab", "8", "-aa", "0", "-ad", "2048", "-as", "0", "-lw", "1e-5",
            "-lr", "-16", "-st", "0",
        ],
        32,
    )
}

/// Per sensor: within 6 % of rtrace or 4 of its standard errors (its estimates are heavy-
/// tailed where a path must find a window's peak: the 32-run standard error itself wavers).
/// The matrix method bins the sky (Reinhart MF 4) and the window's directions (Klems), and
/// takes the window as a hole for the room's own light (as `rfluxmtx`'s V does: a state's
/// reflection back into the room is missing): observed per sensor −5.6 % to +4.0 %.
const SENSOR_BAND: f64 = 0.06;
const K_SIGMA: f64 = 4.0;
/// Per state and sky, the mean relative difference over the sensors where rtrace has
/// converged (standard error under 5 %) within 5 %: observed −3.9 % to +0.6 % over seven runs
/// (the electrochromic glazing under the sun, whose rtrace estimates are heavy-tailed, at the
/// low end; the others within ±2.1 %).
const SET_BAND: f64 = 0.05;
const CONVERGED: f64 = 0.05;
/// V's paths per sensor. A clear glazing sends the sun's beam into one Klems patch, so the
/// sun's interreflected light rests on one entry of V per sensor: at 32,768 paths a sensor
/// at the back of the room read 16 % low (122 lux for rtrace's 146 ± 5), at 262,144 −4.9 %.
const VIEW_PATHS: u32 = 262_144;

#[test]
fn every_state_under_overcast_and_sun_against_rtrace() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let case = case();
    let skies: [(&str, &[&str]); 2] = [
        ("overcast", &["-ang", "45", "0", "-c", "-B", "55.8"]),
        ("sun-steep", &["-ang", "60", "0", "+s"]),
    ];
    let mut failures = Vec::new();
    for (sky_label, args) in skies {
        let sky_text = sky(&bin, &lib, "gensky", args);
        let sky_world = World::new(&scene::parse("sky.rad", &sky_text).unwrap()).unwrap();
        let (vector, suns) = sky_vector_of_world(&sky_world, 4);
        let ours = case
            .shaded
            .irradiance_w_m2(&vector, &suns, &case.outside)
            .unwrap();
        for (k, (name, file)) in STATES.iter().enumerate() {
            let label = format!("{name}-{sky_label}");
            let reference = rtrace_reference(
                &bin,
                &lib,
                case.dir.path(),
                &corpus().join(file),
                &sky_text,
                &label,
            );
            let mut relative = Vec::new();
            for (s, ((mean, se), e)) in reference.iter().zip(&ours[k]).enumerate() {
                let lux = WHITE_EFFICACY_LM_PER_W * e;
                let rel = lux / mean - 1.0;
                if *se < CONVERGED * mean {
                    relative.push(rel);
                }
                println!(
                    "{label} S{}: ours {lux:.1} lux, rtrace {mean:.1} ± {se:.1} ({:+.1} %)",
                    s + 1,
                    100.0 * rel
                );
                if (lux - mean).abs() > (SENSOR_BAND * mean).max(K_SIGMA * se) {
                    failures.push(format!(
                        "{label} S{}: {lux:.1} vs {mean:.1} ± {se:.1}",
                        s + 1
                    ));
                }
            }
            assert!(
                relative.len() >= 3,
                "{label}: rtrace converged at too few sensors"
            );
            let bias = relative.iter().sum::<f64>() / relative.len() as f64;
            println!("{label}: mean relative difference {:+.2} %", 100.0 * bias);
            if bias.abs() > SET_BAND {
                failures.push(format!("{label}: mean relative difference {bias:+.4}"));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

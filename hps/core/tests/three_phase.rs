//! The three-phase method (issue 20 item 4) against RADIANCE, live from the pyradiance
//! wheel, on a box room (4 m × 5 m × 3 m) with one south window (x 1..3 m, z 0.9..2.1 m,
//! front normal into the room) and a 5 m high building 6 m to the south:
//!
//! - our V (sensors to the window's Klems patches) against `rfluxmtx -I+` with the window a
//!   `#@rfluxmtx h=kf u=Z` receiver, and our D (Klems patches to ground + Tregenza sky)
//!   against `rfluxmtx` with the window the sender and the tutorial's `skyglow.rad` the
//!   receiver: each row sum within 2 %, and the patch-wise distribution alike (which catches
//!   a mirrored or rotated Klems frame, which row sums cannot);
//! - our T from the LBNL tutorial's venetian blinds (`blinds.xml`, Klems full, front and back
//!   unlike) against `rmtxop` reading the same XML, entry by entry;
//! - `dctimestep` on our V and D files (read by RADIANCE), the XML and a `gendaymtx` sky
//!   vector against our own product V T D s, 1e-6 relative;
//! - the three-phase illuminance under a CIE overcast sky against our engine's direct path
//!   tracing of the room with the blinds as a `BSDF` window (reported; the matrix method
//!   bins the sky and the window into patches, so it is an approximation, bounded loosely).

mod common;

use common::box_room::BOX_SENSORS;
use common::corpus::corpus;
use common::radiance::{check_output, radiance_or_skip, tool};
use glam::DVec3;
use skylux_hps::bsdf::{Band, KlemsTransmission};
use skylux_hps::engine::phase::{
    daylight_matrix, three_phase, view_matrix, KlemsWindow, RadianceMatrix,
};
use skylux_hps::engine::{self, Settings, World};
use skylux_hps::io::radiance_matrix::MatrixFormat;
use skylux_hps::scene;
use skylux_hps::sky::SkyPatches;
use std::path::{Path, PathBuf};

/// The room without its glazing (the window is an opening; V's paths leave through it).
const ROOM: &str = "\
void plastic wall 0 0 5 0.5 0.5 0.5 0 0
void plastic floor 0 0 5 0.2 0.2 0.2 0 0
void plastic ceiling 0 0 5 0.7 0.7 0.7 0 0
floor polygon floor 0 0 12 0 0 0 4 0 0 4 5 0 0 5 0
ceiling polygon ceiling 0 0 12 0 0 3 0 5 3 4 5 3 4 0 3
wall polygon east 0 0 12 4 0 0 4 0 3 4 5 3 4 5 0
wall polygon west 0 0 12 0 0 0 0 5 0 0 5 3 0 0 3
wall polygon north 0 0 12 0 5 0 4 5 0 4 5 3 0 5 3
wall polygon south_low 0 0 12 0 0 0 0 0 0.9 4 0 0.9 4 0 0
wall polygon south_high 0 0 12 0 0 2.1 0 0 3 4 0 3 4 0 2.1
wall polygon south_west 0 0 12 0 0 0.9 0 0 2.1 1 0 2.1 1 0 0.9
wall polygon south_east 0 0 12 3 0 0.9 3 0 2.1 4 0 2.1 4 0 0.9
";

/// A building across the street: its north face, 6 m south of the window, 5 m high.
const OUTSIDE: &str = "\
void plastic facade 0 0 5 0.3 0.3 0.3 0 0
facade polygon across 0 0 12 -12 -6 0 -12 -6 5 16 -6 5 16 -6 0
";

/// The window, as rfluxmtx reads a receiver or sender (front normal +y, into the room).
const WINDOW: &str = "\
void glow window_glow 0 0 4 1 1 1 0
#@rfluxmtx h=kf u=Z
window_glow polygon window 0 0 12 1 0 0.9 1 0 2.1 3 0 2.1 3 0 0.9
";

fn blinds_xml() -> PathBuf {
    corpus().join("bsdf/sariths-matrix-tutorial/room/blinds/blinds.xml")
}

struct Case {
    dir: tempfile::TempDir,
    bin: PathBuf,
    lib: Option<PathBuf>,
    window: KlemsWindow,
    sensors: Vec<scene::Sensor>,
}

fn case() -> Option<Case> {
    let (bin, lib) = radiance_or_skip()?;
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in [
        ("room.rad", ROOM),
        ("outside.rad", OUTSIDE),
        ("window.rad", WINDOW),
        ("sensors.pts", BOX_SENSORS),
    ] {
        std::fs::write(dir.path().join(name), text).unwrap();
    }
    std::fs::copy(
        corpus().join("sariths-matrix-tutorial/room/skyDomes/skyglow.rad"),
        dir.path().join("skyglow.rad"),
    )
    .unwrap();
    let t = KlemsTransmission::load(&blinds_xml(), Band::Visible).unwrap();
    let window =
        KlemsWindow::load(&dir.path().join("window.rad"), DVec3::Z, t.incident_basis).unwrap();
    let sensors = scene::load_sensors(dir.path().join("sensors.pts")).unwrap();
    Some(Case {
        dir,
        bin,
        lib,
        window,
        sensors,
    })
}

impl Case {
    fn path(&self, name: &str) -> PathBuf {
        self.dir.path().join(name)
    }

    fn run(&self, name: &str, args: &[&str], stdin: Option<&Path>) -> Vec<u8> {
        let mut c = tool(&self.bin, &self.lib, name);
        c.current_dir(self.dir.path()).args(args);
        match stdin {
            Some(f) => {
                let input = std::fs::read(f).unwrap();
                check_output(c, Some(&input))
            }
            None => check_output(c, None),
        }
    }

    fn world(&self, files: &[&str]) -> World {
        let paths: Vec<PathBuf> = files.iter().map(|f| self.path(f)).collect();
        World::new(&scene::load_files(&paths).unwrap()).unwrap()
    }

    /// The room and the building across, frozen (rfluxmtx's `-i` octree for V and D: its
    /// window receiver stops V's rays at the window).
    fn octree(&self) -> PathBuf {
        let oct = self.run("oconv", &["-f", "room.rad", "outside.rad"], None);
        let path = self.path("scene.oct");
        std::fs::write(&path, oct).unwrap();
        path
    }
}

/// Relative L1 distance of two non-negative vectors: Σ|a−b| / Σb.
fn l1_distance(a: &[f64], b: &[f64]) -> f64 {
    let diff: f64 = a.iter().zip(b).map(|(x, y)| (x - y).abs()).sum();
    diff / b.iter().sum::<f64>()
}

fn column_sums(m: &RadianceMatrix) -> Vec<f64> {
    (0..m.cols)
        .map(|c| (0..m.rows).map(|r| m.get(r, c, 0)).sum())
        .collect()
}

#[test]
fn view_and_daylight_matrices_match_rfluxmtx() {
    let Some(case) = case() else {
        return;
    };
    check_view_and_daylight(&case, "window.rad", &case.window, 4, 262_144);
}

/// The Klems half and quarter bases (`h=kh`, `h=kq`; 77 and 41 patches a hemisphere): the
/// same comparisons as for the full basis, on the same room, with V from two rfluxmtx runs at
/// `-ad 65536` (the rows within 2 % or 4 of rfluxmtx's standard errors; the rows do not
/// depend on the basis, the patch-wise distribution and D do).
#[test]
fn half_and_quarter_klems_bases_match_rfluxmtx() {
    let Some(case) = case() else {
        return;
    };
    for (code, name, patches) in [
        ("kh", "LBNL/Klems Half", 77),
        ("kq", "LBNL/Klems Quarter", 41),
    ] {
        let file = format!("window_{code}.rad");
        std::fs::write(
            case.path(&file),
            WINDOW.replace("h=kf", &format!("h={code}")),
        )
        .unwrap();
        let basis = skylux_hps::bsdf::AngleBasis::builtin(name).unwrap();
        assert_eq!(basis.len(), patches);
        let window = KlemsWindow::load(&case.path(&file), DVec3::Z, basis).unwrap();
        println!("{name}:");
        check_view_and_daylight(&case, &file, &window, 2, 65_536);
    }
}

/// Our V and D for the window in `window_file` (a `#@rfluxmtx` receiver and sender) against
/// rfluxmtx's: V from `v_runs` runs at `-ad v_ad` (ours at 262,144 paths), D at 8192 rays a
/// patch (ours 65,536).
fn check_view_and_daylight(
    case: &Case,
    window_file: &str,
    window: &KlemsWindow,
    v_runs: usize,
    v_ad: u32,
) {
    let oct = case.octree();
    let oct = oct.to_str().unwrap();
    // V: 6 sensors, 4 bounces; rfluxmtx's -ad rays at the first bounce, one ray on after.
    // Runs averaged (rcontrib seeds by the clock: each in its own second): one run's dimmest
    // rows scatter by about 1.3 % from run to run at -ad 262144.
    let v_ad_arg = v_ad.to_string();
    let start = std::time::Instant::now();
    let runs: Vec<RadianceMatrix> = (0..v_runs)
        .map(|k| {
            if k > 0 {
                std::thread::sleep(std::time::Duration::from_millis(1100));
            }
            let bytes = case.run(
                "rfluxmtx",
                &[
                    "-I+",
                    "-ab",
                    "4",
                    "-ad",
                    &v_ad_arg,
                    "-lw",
                    "3e-6",
                    "-faf",
                    "-y",
                    "6",
                    "-",
                    window_file,
                    "-i",
                    oct,
                ],
                Some(&case.path("sensors.pts")),
            );
            RadianceMatrix::parse("rfluxmtx V", &bytes).unwrap()
        })
        .collect();
    let mut v_ref = runs[0].clone();
    for (k, value) in v_ref.values.iter_mut().enumerate() {
        *value = runs.iter().map(|r| r.values[k]).sum::<f64>() / v_runs as f64;
    }
    let row_sums: Vec<Vec<f64>> = runs.iter().map(|r| r.row_sums(0)).collect();
    assert!(
        row_sums.windows(2).any(|w| w[0] != w[1]),
        "rfluxmtx's runs were not independent"
    );
    let rflux_v_s = start.elapsed().as_secs_f64();
    let settings = Settings {
        ambient_bounces: 4,
        samples_per_sensor: common::compare::our_samples_here(262_144),
        seed: 11,
        ..Default::default()
    };
    let start = std::time::Instant::now();
    let v = view_matrix(
        &case.world(&["room.rad"]),
        &case.sensors,
        window,
        &settings,
        &|_, _| {},
    )
    .unwrap();
    let our_v_s = start.elapsed().as_secs_f64();
    assert_eq!((v.rows, v.cols), (v_ref.rows, v_ref.cols));
    println!("V: rfluxmtx {rflux_v_s:.1} s, ours {our_v_s:.1} s");
    let (ours, theirs) = (v.row_sums(0), v_ref.row_sums(0));
    for (s, (a, b)) in ours.iter().zip(&theirs).enumerate() {
        let rel = a / b - 1.0;
        // rfluxmtx's standard error from its runs' spread.
        let n = v_runs as f64;
        let spread = row_sums.iter().map(|r| (r[s] - b).powi(2)).sum::<f64>() / (n - 1.0);
        let se_rel = (spread / n).sqrt() / b;
        println!(
            "V row S{}: ours {a:.5}, rfluxmtx {b:.5} ± {:.2} % ({:+.2} %)",
            s + 1,
            100.0 * se_rel,
            100.0 * rel
        );
        // 2 %, or 4 of rfluxmtx's own standard errors where its runs spread wider (the deep
        // sensor S5: its mean moved by 1.1 % between two CI-like runs, ours fixed by the seed).
        let band = 0.02_f64.max(4.0 * se_rel);
        assert!(rel.abs() < band, "V row {s}: {rel} (band {band})");
    }
    // The patch-wise distribution: a mirrored or rotated frame moves the window's light
    // between patches (the building below the horizon, the sky above): tens of per cent.
    let dist = l1_distance(&column_sums(&v), &column_sums(&v_ref));
    println!("V column sums, relative L1 distance {:.3}", dist);
    assert!(dist < 0.05, "V patches: {dist}");

    // D: every Klems patch, 2 bounces outside (the building), ground + Tregenza columns.
    // -ad 128: at -ad 512 rfluxmtx's second-bounce rays fall under -lw 1e-4 and its rows
    // that see the building read up to 2.4 % low (one run).
    let start = std::time::Instant::now();
    let d_bytes = case.run(
        "rfluxmtx",
        &[
            "-ff",
            "-ab",
            "2",
            "-ad",
            "128",
            "-lw",
            "1e-4",
            "-c",
            "8192",
            window_file,
            "skyglow.rad",
            "-i",
            oct,
        ],
        None,
    );
    let d_ref = RadianceMatrix::parse("rfluxmtx D", &d_bytes).unwrap();
    let rflux_d_s = start.elapsed().as_secs_f64();
    // 65536 rays a patch: a row that sees the ground below the horizon was a binary choice
    // per ray before D stratified its directions (ground fraction p ~ 0.3: σ = √(p(1−p)/n),
    // 1.2 % of the row at 8192 rays); rfluxmtx stratifies its sender samples too.
    let settings = Settings {
        ambient_bounces: 2,
        samples_per_sensor: common::compare::our_samples_here(65_536),
        seed: 12,
        ..Default::default()
    };
    let start = std::time::Instant::now();
    let d = daylight_matrix(
        &case.world(&["room.rad", "outside.rad"]),
        window,
        1,
        &settings,
        &|_, _| {},
    )
    .unwrap();
    let our_d_s = start.elapsed().as_secs_f64();
    println!("D: rfluxmtx {rflux_d_s:.1} s, ours {our_d_s:.1} s");
    assert_eq!((d.rows, d.cols), (d_ref.rows, d_ref.cols));
    assert_eq!(d.cols, 1 + SkyPatches::tregenza().len());
    let (ours, theirs) = (d.row_sums(0), d_ref.row_sums(0));
    let mut worst: f64 = 0.0;
    for (p, (a, b)) in ours.iter().zip(&theirs).enumerate() {
        let rel = a / b - 1.0;
        worst = worst.max(rel.abs());
        assert!(rel.abs() < 0.02, "D row {p}: ours {a}, rfluxmtx {b}");
    }
    println!(
        "D row sums: worst of {} rows {:.2} %, mean ours {:.4} rfluxmtx {:.4}",
        d.rows,
        100.0 * worst,
        ours.iter().sum::<f64>() / d.rows as f64,
        theirs.iter().sum::<f64>() / d.rows as f64
    );
    let dist = l1_distance(&d.values, &d_ref.brightness().values);
    println!("D entries, relative L1 distance {dist:.3}");
    assert!(dist < 0.05, "D entries: {dist}");
}

#[test]
fn transmission_matrix_is_what_rmtxop_reads() {
    let Some(case) = case() else {
        return;
    };
    let xml = blinds_xml();
    let theirs = RadianceMatrix::parse(
        "rmtxop blinds.xml",
        &case.run("rmtxop", &["-fd", xml.to_str().unwrap()], None),
    )
    .unwrap();
    let t = KlemsTransmission::load(&xml, Band::Visible).unwrap();
    assert_eq!((t.matrix.rows, t.matrix.cols), (theirs.rows, theirs.cols));
    let mut worst: f64 = 0.0;
    for r in 0..theirs.rows {
        for c in 0..theirs.cols {
            let (a, b) = (t.matrix.get(r, c, 0), theirs.get(r, c, 0));
            worst = worst.max((a - b).abs() / b.abs().max(1e-12));
        }
    }
    println!("T against rmtxop: worst relative difference {worst:.2e}");
    assert!(worst < 1e-6, "{worst}");
    // Not symmetric: the other orientation (or the back data) would fail above.
    assert!((t.matrix.get(1, 0, 0) - t.matrix.get(0, 1, 0)).abs() > 1e-6);
}

#[test]
fn dctimestep_on_our_matrices_equals_our_product() {
    let Some(case) = case() else {
        return;
    };
    let settings = Settings {
        ambient_bounces: 2,
        samples_per_sensor: 4096,
        seed: 5,
        ..Default::default()
    };
    let window = &case.window;
    let v = view_matrix(
        &case.world(&["room.rad"]),
        &case.sensors,
        window,
        &settings,
        &|_, _| {},
    )
    .unwrap();
    let d_settings = Settings {
        samples_per_sensor: 256,
        ..settings
    };
    let d = daylight_matrix(
        &case.world(&["room.rad", "outside.rad"]),
        window,
        1,
        &d_settings,
        &|_, _| {},
    )
    .unwrap();
    // As `skylux dc --three-phase` writes them: float, RGB.
    for (m, name) in [(&v, "v.mtx"), (&d, "d.mtx")] {
        m.with_components(3)
            .unwrap()
            .write(&case.path(name), MatrixFormat::Float, &["test".into()])
            .unwrap();
    }
    // A sky vector from RADIANCE: the tutorial's NYC 10:30 sky, one step of gendaymtx.
    std::fs::write(
        case.path("one.wea"),
        "place NYC\nlatitude 40.78\nlongitude 73.96\ntime_zone 75\nsite_elevation 40\n\
         weather_data_file_units 1\n3 20 10.5 706 162\n",
    )
    .unwrap();
    let sky_bytes = case.run("gendaymtx", &["-m", "1", "one.wea"], None);
    std::fs::write(case.path("sky.smx"), &sky_bytes).unwrap();
    let sky = RadianceMatrix::parse("gendaymtx", &sky_bytes).unwrap();
    let xml = blinds_xml();
    let theirs = RadianceMatrix::parse(
        "dctimestep",
        &case.run(
            "dctimestep",
            &["-od", "v.mtx", xml.to_str().unwrap(), "d.mtx", "sky.smx"],
            None,
        ),
    )
    .unwrap();
    // Ours from the files as written (float), as dctimestep reads them.
    let v = RadianceMatrix::read(&case.path("v.mtx")).unwrap();
    let d = RadianceMatrix::read(&case.path("d.mtx")).unwrap();
    let t = KlemsTransmission::load(&xml, Band::Visible).unwrap();
    let ours = three_phase(&v, &t.matrix, &d, &sky).unwrap();
    assert_eq!(
        (ours.rows, ours.cols, ours.ncomp),
        (theirs.rows, theirs.cols, theirs.ncomp)
    );
    let mut worst: f64 = 0.0;
    for (a, b) in ours.values.iter().zip(&theirs.values) {
        worst = worst.max((a - b).abs() / b.abs());
    }
    for s in 0..ours.rows {
        println!(
            "S{}: ours {:.3} lux, dctimestep {:.3} lux",
            s + 1,
            179.0 * ours.brightness().get(s, 0, 0),
            179.0 * theirs.brightness().get(s, 0, 0)
        );
    }
    println!("dctimestep against our product: worst relative difference {worst:.2e}");
    assert!(worst < 1e-6, "{worst}");
}

#[test]
fn three_phase_against_direct_tracing_of_the_bsdf_window() {
    let Some(case) = case() else {
        return;
    };
    // CIE overcast, 10 000 lux horizontal (gensky -c -B 55.866).
    let sky_text = common::compare::sky(
        &case.bin,
        &case.lib,
        "gensky",
        &["-ang", "45", "0", "-c", "-B", "55.866"],
    );
    std::fs::write(case.path("sky.rad"), &sky_text).unwrap();
    std::fs::write(
        case.path("glazing.rad"),
        format!(
            "void BSDF blinds 6 0 {} 0 0 1 .\n0\n0\nblinds polygon window 0 0 12 1 0 0.9 1 0 2.1 \
             3 0 2.1 3 0 0.9\n",
            blinds_xml().display()
        ),
    )
    .unwrap();
    // The sky vector: the sky's mean radiance over each Tregenza patch (and the ground),
    // integrated over a fine grid of directions.
    let sky_world = case.world(&["sky.rad"]);
    let patches = SkyPatches::tregenza();
    let (mut sum, mut weight) = (vec![0.0; 1 + patches.len()], vec![0.0; 1 + patches.len()]);
    let n = 800;
    for i in 0..n {
        let z = -1.0 + 2.0 * (i as f64 + 0.5) / n as f64;
        for j in 0..2 * n {
            let phi = std::f64::consts::TAU * (j as f64 + 0.5) / (2 * n) as f64;
            let r = (1.0 - z * z).sqrt();
            let dir = DVec3::new(r * phi.cos(), r * phi.sin(), z);
            let bin = if z < 0.0 {
                Some(0)
            } else {
                patches.patch_of(dir).map(|p| p + 1)
            };
            if let Some(b) = bin {
                sum[b] += skylux_hps::engine::material::bright(sky_world.escape_radiance(dir));
                weight[b] += 1.0;
            }
        }
    }
    let sky: Vec<f64> = sum.iter().zip(&weight).map(|(s, w)| s / w).collect();
    let sky = RadianceMatrix::from_grey(sky.len(), 1, sky).unwrap();
    let settings = Settings {
        ambient_bounces: 6,
        samples_per_sensor: common::compare::our_samples_here(65_536),
        seed: 21,
        ..Default::default()
    };
    let window = &case.window;
    let v = view_matrix(
        &case.world(&["room.rad"]),
        &case.sensors,
        window,
        &settings,
        &|_, _| {},
    )
    .unwrap();
    let d = daylight_matrix(
        &case.world(&["room.rad", "outside.rad"]),
        window,
        1,
        &Settings {
            samples_per_sensor: 4096,
            ..settings
        },
        &|_, _| {},
    )
    .unwrap();
    let t = KlemsTransmission::load(&blinds_xml(), Band::Visible).unwrap();
    let lux3 = three_phase(&v, &t.matrix, &d, &sky).unwrap();
    let world = case.world(&["room.rad", "outside.rad", "glazing.rad", "sky.rad"]);
    let direct = engine::illuminance(&world, &case.sensors, &settings, &|_, _| {}).unwrap();
    for (s, e) in direct.iter().enumerate() {
        let e3 = 179.0 * lux3.get(s, 0, 0);
        let rel = e3 / e.illuminance_lux - 1.0;
        println!(
            "S{}: three-phase {e3:.1} lux, direct {:.1} ± {:.1} lux ({:+.1} %)",
            s + 1,
            e.illuminance_lux,
            e.stderr_lux,
            100.0 * rel
        );
        // Patches of 0.02-0.1 sr for a smooth sky and a diffusing blind: a few per cent.
        assert!(rel.abs() < 0.15, "S{}: {rel}", s + 1);
    }
}

//! Issue 19: the LBNL matrix tutorial's rooms (shared/data/radiance-corpus, Sarith
//! Subramaniam's tutorial; see its PROVENANCE.txt), loaded as the tutorial loads them
//! (`materials.rad room.rad`, the room's `!xform` lines run natively), under the tutorial's
//! `gendaylit` sky (the corpus's expanded `gendaylit 9 19 10:30EDT ... -W 706 162`, completed
//! with the sky and ground glows), at every sensor of each room's `points.txt`, against a
//! converged `rtrace -I` run live.
//!
//! rtrace traces paths purely (`-aa 0 -as 0`, no ambient cache) with 12 bounces and weight
//! limit 1e-5, so more bounces change nothing; every sensor is traced `RTRACE_SAMPLES`
//! times with fresh random numbers (`-u+`), which gives its mean and its own standard error.
//! Acceptance (`agreement_failures`): per sensor within 2 % of rtrace or 4 combined standard
//! errors, rtrace's own moderated towards the room's median; and no shared bias over the
//! room (mean z × √n within ±4). 4 rather than 3, and the moderation: rtrace's error is itself
//! estimated from 16 runs, heavy-tailed where sun patches are seen, and 293 sensors at 3σ
//! failed now and then with both sides right (seen: S26 of room2 at +4.3 of its unmoderated
//! σ in CI, whose 16 runs had half the room's typical spread).

mod common;
use common::compare::{compare_with_rtrace, Effort, SKY_GLOWS};
use std::path::{Path, PathBuf};

const TUTORIAL: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../../shared/data/radiance-corpus/sariths-matrix-tutorial"
);
const SKY: &str = "EXPANDED_gendaylit_9_19_10-30EDT_NYC_W706_162.sky";

/// Converged pure path tracing, the brief's setting.
const RTRACE_CONVERGED: &[&str] = &[
    "-h", "-I", "-u+", "-ab", "12", "-aa", "0", "-ad", "256", "-as", "0", "-lw", "1e-5", "-lr",
    "-24",
];
/// Independent rtrace estimates per sensor.
const RTRACE_SAMPLES: usize = 16;

fn tutorial_room(name: &str) {
    let dir = tempfile::tempdir().unwrap();
    let room_dir = Path::new(TUTORIAL).join(name);
    let mut sky = std::fs::read(Path::new(TUTORIAL).join(SKY)).unwrap();
    sky.extend_from_slice(SKY_GLOWS.as_bytes());
    let sensors = std::fs::read(room_dir.join("points.txt")).unwrap();
    let effort = Effort {
        rtrace_args: RTRACE_CONVERGED,
        rtrace_samples: RTRACE_SAMPLES,
        our_samples: 16_384,
        our_bounces: 12,
        k_sigma: 4.0,
    };
    let files = [PathBuf::from("materials.rad"), PathBuf::from("room.rad")];
    compare_with_rtrace(
        &format!("tutorial-{name}"),
        &files,
        &sky,
        &sensors,
        &room_dir,
        dir.path(),
        &effort,
    );
}

#[test]
fn tutorial_room_at_all_100_sensors() {
    tutorial_room("room");
}

#[test]
fn tutorial_room2_at_all_93_sensors() {
    tutorial_room("room2");
}

#[test]
fn tutorial_room3_at_all_100_sensors() {
    tutorial_room("room3");
}

const FRADS_OFFICE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../../shared/data/radiance-corpus/frads-office/tests"
);

/// frads' LBNL open-plan office (13,966 polygons, in feet) as its `two_phase.cfg` assembles it
/// (its material file and scene files, less `deskleg.rad` and `chairs.rad`, absent from the
/// snapshot: docs/radiance-compatibility.md), its two glazings as the file declares them
/// (`glass`), under a `gendaylit` sky of its own site (Oakland, 1 January 10:30, the sun
/// through the south glazing), at every point of its sensor grid `Resources/grid.txt` (195
/// points at z = 3 ft; the grid's coordinates fall in the office's feet). 37 of them lie
/// inside furniture and one nearly so (rtrace reads below 1 lux there): those must read
/// below 1 lux in our engine too, and the other 157 are compared.
#[test]
fn frads_office_at_its_195_grid_points() {
    let Some((bin, lib)) = common::radiance::radiance_or_skip() else {
        return;
    };
    let office = Path::new(FRADS_OFFICE);
    let mut files = vec![PathBuf::from("Objects/materials.mat")];
    for f in common::corpus::FRADS_OFFICE_SCENE {
        files.push(PathBuf::from(format!("Objects/{f}.rad")));
    }
    let sky = common::compare::sky(
        &bin,
        &lib,
        "gendaylit",
        &[
            "1", "1", "10.5", "-a", "37.72", "-o", "122.22", "-m", "120", "-W", "712", "95",
        ],
    );
    let grid = std::fs::read_to_string(office.join("Resources/grid.txt")).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let (enclosed, open) = split_enclosed(&bin, &lib, office, &files, &sky, &grid, dir.path());
    assert_eq!(enclosed.len() + open.len(), 195, "the grid's points");
    assert!(open.len() > 150, "{} points outside furniture", open.len());
    // Ours reads nothing inside the furniture either.
    let scene_files: Vec<PathBuf> = files.iter().map(|f| office.join(f)).collect();
    let mut scene = skylux_hps::scene::load_files(&scene_files).unwrap();
    scene.add_bytes(dir.path().join("sky.rad"), &sky).unwrap();
    let world = skylux_hps::engine::World::new(&scene).unwrap();
    let inside =
        skylux_hps::scene::parse_sensors("enclosed.pts", enclosed.join("\n").as_bytes()).unwrap();
    let settings = skylux_hps::engine::Settings {
        samples_per_sensor: 256,
        ..Default::default()
    };
    for s in skylux_hps::engine::illuminance(&world, &inside, &settings, &|_, _| {}).unwrap() {
        assert!(
            s.illuminance_lux < 1.0,
            "{} inside furniture: {s:?}",
            s.name
        );
    }
    let sensors = open.join("\n").into_bytes();
    let effort = Effort {
        rtrace_args: RTRACE_CONVERGED,
        // 64, not 16: the office's deep sensors see the sun's patches through cubicle gaps, and
        // 16 estimates left rtrace's error at 5-7 % there.
        rtrace_samples: 64,
        our_samples: 16_384,
        our_bounces: 12,
        k_sigma: 4.0,
    };
    compare_with_rtrace(
        "frads-office",
        &files,
        &sky,
        &sensors,
        office,
        dir.path(),
        &effort,
    );
}

/// The grid's lines split into those rtrace reads below 1 lux (a point inside a closed
/// object, where no ray leaves it, or nearly so: one point sits where a gap lets 0.05 lux
/// in) and the others, by one quick rtrace pass.
fn split_enclosed(
    bin: &Path,
    lib: &Option<PathBuf>,
    scene_dir: &Path,
    files: &[PathBuf],
    sky: &[u8],
    grid: &str,
    work: &Path,
) -> (Vec<String>, Vec<String>) {
    use common::radiance::{check_output, tool};
    let sky_path = work.join("sky.rad");
    std::fs::write(&sky_path, sky).unwrap();
    let mut oconv = tool(bin, lib, "oconv");
    oconv
        .current_dir(scene_dir)
        .arg("-f")
        .args(files)
        .arg(&sky_path);
    let octree = work.join("quick.oct");
    std::fs::write(&octree, check_output(oconv, None)).unwrap();
    let mut rtrace = tool(bin, lib, "rtrace");
    rtrace
        .args(["-h", "-I", "-ab", "3", "-ad", "1024", "-aa", "0"])
        .arg(&octree);
    let lines: Vec<String> = grid
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(str::to_string)
        .collect();
    let input: String = lines.iter().map(|l| format!("{l}\n")).collect();
    let out = String::from_utf8(check_output(rtrace, Some(input.as_bytes()))).unwrap();
    let readings: Vec<&str> = out.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(readings.len(), lines.len(), "one rtrace answer per point");
    let (mut enclosed, mut open) = (Vec::new(), Vec::new());
    for (line, reading) in lines.into_iter().zip(readings) {
        if common::radiance::lux_of_line(reading) < 1.0 {
            enclosed.push(line);
        } else {
            open.push(line);
        }
    }
    (enclosed, open)
}

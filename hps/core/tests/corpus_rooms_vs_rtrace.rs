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

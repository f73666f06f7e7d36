//! Small scenes against a converged `rtrace -I`: the settings and lighting the primitive
//! tests share (tests/primitives_vs_rtrace.rs, tests/sources_vs_rtrace.rs).
#![allow(dead_code)]

use super::compare::{compare_with_rtrace, Effort};
use std::path::PathBuf;

/// Pure path tracing with enough bounces that more change nothing in these small scenes,
/// and full source jitter (`-dj 1`): with the default `-dj 0` rtrace samples each piece of a
/// large source (a spot disc, an illum window) at its centre, a midpoint rule whose error
/// no number of runs averages out (7 % at the edge of a spot's cone, 3 % near an illum).
pub const RTRACE_ARGS: &[&str] = &[
    "-h", "-I", "-u+", "-ab", "8", "-aa", "0", "-ad", "1024", "-as", "0", "-lw", "1e-5", "-lr",
    "-16", "-dj", "1",
];
/// Independent rtrace estimates per sensor.
pub const RTRACE_SAMPLES: usize = 16;
/// Our paths per sensor (an eighth under qemu-arm: [`super::compare::our_samples_here`]).
pub const OUR_SAMPLES: u32 = 65_536;

/// A uniform sky and ground (`glow`, no pattern) and a sun (`light` source) from the
/// south-east, 45° high: what the outdoor scenes are lit by.
pub const SUN_AND_SKY: &str = "void light solar 0 0 3 6e5 6e5 6e5\n\
    solar source sun 0 0 4 0.45 -0.54 0.71 0.533\n\
    void glow sky_glow 0 0 4 8 8 9 0\n\
    sky_glow source sky 0 0 4 0 0 1 180\n\
    void glow ground_glow 0 0 4 2 2 2 0\n\
    ground_glow source ground 0 0 4 0 0 -1 180\n";

/// The effort of these comparisons with rtrace's `args`: every sensor within 2 % or 3
/// combined standard errors.
pub fn effort<'a>(args: &'a [&'a str]) -> Effort<'a> {
    Effort {
        rtrace_args: args,
        rtrace_samples: RTRACE_SAMPLES,
        our_samples: OUR_SAMPLES,
        our_bounces: 8,
        k_sigma: 3.0,
    }
}

/// Writes `scene` to a scratch folder and compares both programs on it under `sky` at
/// `sensors` (`.pts` text), with [`effort`].
pub fn compare(label: &str, scene: &str, sky: &str, sensors: &str) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.rad"), scene).unwrap();
    let effort = effort(RTRACE_ARGS);
    compare_with_rtrace(
        label,
        &[PathBuf::from("scene.rad")],
        sky.as_bytes(),
        sensors.as_bytes(),
        dir.path(),
        dir.path(),
        &effort,
    );
}

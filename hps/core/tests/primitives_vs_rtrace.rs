//! Issue 19: RADIANCE's remaining primitives, each in a small scene where it decides the
//! result, against a converged `rtrace -I` run live (pure path tracing `-aa 0 -as 0 -ab 8
//! -lw 1e-5`, independent `-u+` estimates), through `compare_with_rtrace`:
//!
//! - a round room of inward surfaces: `tube` walls, a `cup` roof and a `bubble` dome, each a
//!   `glow` that lights the room only if its normal points in;
//! - a `spotlight` aimed at one corner of a `!genbox` room, with sensors inside and outside
//!   its cone, the room's materials named through `alias` (both `void` and `inherit`);
//! - a `dielectric` block and an `interface` block in a sunbeam, with sensors in their
//!   refracted sun, in their shade and in the open;
//! - an `illum` over a window: the room sees the illum's radiance where the sky would be,
//!   while the sun still shines through it.
//!
//! Acceptance: every sensor within 2 % of rtrace or 3 combined standard errors (rtrace's
//! moderated towards the scene's median), and no shared bias (`agreement_failures`).
//! Without RADIANCE the tests print SKIPPED, unless `SKYLUX_REQUIRE_RADIANCE` is set.

mod common;
use common::compare::{compare_with_rtrace, Effort};
use std::path::PathBuf;

/// Pure path tracing with enough bounces that more change nothing in these small scenes,
/// and full source jitter (`-dj 1`): with the default `-dj 0` rtrace samples each piece of a
/// large source (the spot disc, the illum window) at its centre, a midpoint rule whose error
/// no number of runs averages out (7 % at the edge of the spot's cone, 3 % near the illum).
const RTRACE_ARGS: &[&str] = &[
    "-h", "-I", "-u+", "-ab", "8", "-aa", "0", "-ad", "1024", "-as", "0", "-lw", "1e-5", "-lr",
    "-16", "-dj", "1",
];
/// Independent rtrace estimates per sensor.
const RTRACE_SAMPLES: usize = 16;
/// Our paths per sensor; fewer under qemu-arm (about ten times slower), where the band widens
/// with the larger standard error.
const OUR_SAMPLES: u32 = if cfg!(target_arch = "arm") {
    8_192
} else {
    65_536
};

/// A uniform sky and ground (`glow`, no pattern) and a sun (`light` source) from the
/// south-east, 50° high: what the outdoor scenes are lit by.
const SUN_AND_SKY: &str = "void light solar 0 0 3 6e5 6e5 6e5\n\
    solar source sun 0 0 4 0.45 -0.54 0.71 0.533\n\
    void glow sky_glow 0 0 4 8 8 9 0\n\
    sky_glow source sky 0 0 4 0 0 1 180\n\
    void glow ground_glow 0 0 4 2 2 2 0\n\
    ground_glow source ground 0 0 4 0 0 -1 180\n";

fn compare(label: &str, scene: &str, sky: &str, sensors: &str) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.rad"), scene).unwrap();
    let effort = Effort {
        rtrace_args: RTRACE_ARGS,
        rtrace_samples: RTRACE_SAMPLES,
        our_samples: OUR_SAMPLES,
        our_bounces: 8,
        k_sigma: 3.0,
    };
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

#[test]
fn inward_tube_cup_and_bubble_light_the_room_they_face() {
    let scene = "void glow wall_glow 0 0 4 1 1 1 0\n\
        void plastic floor_white 0 0 5 .4 .4 .4 0 0\n\
        void glow dome_glow 0 0 4 3 3 3 0\n\
        void glow roof_glow 0 0 4 2 1.5 1 0\n\
        wall_glow tube walls 0 0 7 0 0 0 0 0 3 2\n\
        floor_white ring floor 0 0 8 0 0 0 0 0 1 0 2\n\
        roof_glow cup roof 0 0 8 0 0 3 0 0 3.5 2 0.8\n\
        dome_glow bubble dome 0 0 4 0 0 0 20\n";
    let sensors = "0 0 0.8 0 0 1\n1.2 0 0.8 0 0 1\n0 1 1.5 1 0 0\n0.5 -0.5 1 0 0 -1\n\
        -1 -1 2.5 0 0 1\n";
    compare("inward", scene, "", sensors);
}

#[test]
fn a_spotlight_lights_its_cone_only() {
    // A 4 x 4 x 3 m room (genbox -i: normals in); a 0.5 m spot disc under the ceiling aimed
    // 40° off the vertical towards +x, a 50° cone, its focus 1 m behind it (the direction
    // vector's length).
    let scene = "void plastic grey 0 0 5 .5 .5 .5 0 0\n\
        void alias wall grey\n\
        inherit alias floor_grey grey\n\
        void plastic grey 0 0 5 .9 .9 .9 0 0\n\
        !genbox wall room 4 4 3 -i\n\
        floor_grey polygon low 0 0 12 0.01 0.01 0.01 3.99 0.01 0.01 3.99 3.99 0.01 0.01 3.99 0.01\n\
        void spotlight spot 0 0 7 400 400 400 50 0.64 0 -0.77\n\
        spot ring lamp 0 0 8 1.5 2 2.98 0 0 -1 0 0.5\n";
    // In the cone (towards +x), under the lamp's back side, and in the far corner.
    let sensors = "3.2 2 0.8 0 0 1\n2.6 2.4 0.8 0 0 1\n0.6 2 0.8 0 0 1\n0.5 0.5 0.8 0 0 1\n\
        3.5 3.5 1.5 -1 0 0\n";
    compare("spotlight", scene, "", sensors);
}

#[test]
fn dielectric_and_interface_blocks_in_a_sunbeam() {
    // Two 1 x 1 x 0.25 m blocks 1 m above a ground plane: glass-like dielectric (n = 1.5,
    // 80 % left after 1 m) and an interface block of index 1.33 in a medium of index 1.
    let scene = "void plastic ground_grey 0 0 5 .3 .3 .3 0 0\n\
        ground_grey polygon ground 0 0 12 -10 -10 0 10 -10 0 10 10 0 -10 10 0\n\
        void dielectric crystal 0 0 5 .8 .8 .8 1.5 0\n\
        !genbox crystal slab 1 1 0.25 | xform -t -1 -0.5 1\n\
        void interface water 0 0 8 .9 .95 1 1.33 1 1 1 1\n\
        !genbox water pool 1 1 0.25 | xform -t 1 -0.5 1\n";
    // The blocks' shadows fall 1.1 m from under them along (-0.64, 0.77): sensors in the
    // refracted sun under each block, in the open, and right under each block's middle.
    let sensors = "-1.13 0.70 0 0 0 1\n0.79 0.85 0 0 0 1\n0.5 -2 0 0 0 1\n\
        -0.5 0 0.01 0 0 1\n1.5 0 0.01 0 0 1\n-0.5 0 0.9 0 0 -1\n";
    compare("dielectric", scene, SUN_AND_SKY, sensors);
}

#[test]
fn an_illum_over_a_window_replaces_the_sky_but_lets_the_sun_in() {
    // A 4 x 5 x 3 m room with a 2 x 1.4 m opening in its south wall (y = 0), covered by an
    // illum facing in (+y; void: invisible to other rays, so the sun passes), brighter than
    // the sky behind it.
    let scene = "void plastic white 0 0 5 .7 .7 .7 0 0\n\
        void plastic dark 0 0 5 .2 .2 .2 0 0\n\
        dark polygon floor 0 0 12 0 0 0 0 5 0 4 5 0 4 0 0\n\
        white polygon ceiling 0 0 12 0 0 3 4 0 3 4 5 3 0 5 3\n\
        white polygon west 0 0 12 0 0 0 0 0 3 0 5 3 0 5 0\n\
        white polygon east 0 0 12 4 0 0 4 5 0 4 5 3 4 0 3\n\
        white polygon north 0 0 12 0 5 0 0 5 3 4 5 3 4 5 0\n\
        white polygon south 0 0 30 0 0 0 4 0 0 4 0 3 0 0 3 0 0 0 1 0 0.8 1 0 2.2 3 0 2.2 3 0 0.8 1 0 0.8\n\
        void illum window_light 1 void 0 3 30 30 32\n\
        window_light polygon window 0 0 12 1 0 0.8 1 0 2.2 3 0 2.2 3 0 0.8\n";
    // The sun (from the south-east, 50° high) lands on the floor near x 1.2..3.2, y 0.7..1.7.
    let sensors = "2.2 1.2 0 0 0 1\n1 3 0.8 0 0 1\n3 4 0.8 0 0 1\n2 2.5 1.5 0 -1 0\n\
        2 2.5 2.9 0 0 -1\n";
    compare("illum", scene, SUN_AND_SKY, sensors);
}

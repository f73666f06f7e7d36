//! Issue 19: RADIANCE's `spotlight` and `illum`, each in a small room where it decides the
//! result, against a converged `rtrace -I` run live (pure path tracing `-aa 0 -as 0 -ab 8
//! -lw 1e-5`, source jitter `-dj 1`, independent `-u+` estimates):
//!
//! - a `spotlight` aimed at one side of a `!genbox` room, with sensors inside and outside
//!   its cone, the room's materials named through `alias` (both `void` and `inherit`);
//! - an `illum` over a window: the room sees the illum's radiance where the sky would be,
//!   while the sun still shines through it.
//!
//! Acceptance as in tests/primitives_vs_rtrace.rs.

mod common;
use common::small_scenes::{compare, SUN_AND_SKY};

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
    // Two sensors that see the whole disc inside the cone (where the cone's edge crosses the
    // disc, rtrace's jittered source samples are heavy-tailed, and its unjittered ones off
    // by up to 7 %), two outside it (lit by the walls only) and one on a wall.
    let sensors = "3.2 2 0.8 0 0 1\n3.6 2.6 0.8 0 0 1\n0.6 2 0.8 0 0 1\n0.5 0.5 0.8 0 0 1\n\
        3.5 3.5 1.5 -1 0 0\n";
    compare("spotlight", scene, "", sensors);
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
    // The sun (from the south-east, 45° high) lands on the floor near x -0.4..2.5, y 0.6..1.7:
    // S1 is in it.
    let sensors = "1.8 1.2 0 0 0 1\n1 3 0.8 0 0 1\n3 4 0.8 0 0 1\n2 2.5 1.5 0 -1 0\n\
        2 2.5 2.9 0 0 -1\n";
    compare("illum", scene, SUN_AND_SKY, sensors);
}

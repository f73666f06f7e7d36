//! Issue 19: RADIANCE's remaining surface and material primitives, each in a small scene
//! where it decides the result, against a converged `rtrace -I` run live (pure path tracing
//! `-aa 0 -as 0 -ab 8 -lw 1e-5`, independent `-u+` estimates), through `compare_with_rtrace`:
//!
//! - a round room of inward surfaces: `tube` walls, a `cup` roof and a `bubble` dome, each a
//!   `glow` that lights the room only if its normal points in;
//! - a `dielectric` block and an `interface` block in a sunbeam, with sensors in their
//!   refracted sun, in the open and under them;
//! - a window cut by an `antimatter` box through a thick `!genbox` wall: the sun and sky come
//!   in through the hole, and the hole's reveals are shaded as the wall.
//!
//! (Light sources, `spotlight` and `illum`: tests/sources_vs_rtrace.rs.) Acceptance: every
//! sensor within 2 % of rtrace or 3 combined standard errors (rtrace's moderated towards the
//! scene's median), and no shared bias (`agreement_failures`). Without RADIANCE the tests
//! print SKIPPED, unless `SKYLUX_REQUIRE_RADIANCE` is set.

mod common;
use common::small_scenes::{compare, SUN_AND_SKY};

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
fn an_antimatter_box_cuts_a_window_through_a_thick_wall() {
    // A 4 x 5 x 3 m room (y > 0) whose south wall is a 0.3 m thick box of `wall_mat`; a
    // 2 x 1.4 m antimatter box through it, reaching into the room and out of the wall.
    let scene = "void plastic wall_mat 0 0 5 .6 .6 .6 0 0\n\
        void plastic white 0 0 5 .7 .7 .7 0 0\n\
        void plastic dark 0 0 5 .2 .2 .2 0 0\n\
        void antimatter hole_am 1 wall_mat 0 0\n\
        dark polygon floor 0 0 12 0 0 0 0 5 0 4 5 0 4 0 0\n\
        white polygon ceiling 0 0 12 0 0 3 4 0 3 4 5 3 0 5 3\n\
        white polygon west 0 0 12 0 0 0 0 0 3 0 5 3 0 5 0\n\
        white polygon east 0 0 12 4 0 0 4 5 0 4 5 3 4 0 3\n\
        white polygon north 0 0 12 0 5 0 0 5 3 4 5 3 4 5 0\n\
        !genbox wall_mat south 4 0.3 3 | xform -t 0 -0.3 0\n\
        !genbox hole_am hole 2 0.5 1.4 | xform -t 1 -0.4 0.8\n";
    // In the sun patch, deep in the room, on the wall beside the hole, and one looking at a
    // reveal of the hole from the side.
    let sensors = "1.5 1.2 0 0 0 1\n1 3 0.8 0 0 1\n3 4 0.8 0 0 1\n3.5 0.05 1.5 0 1 0\n\
        0.5 0.6 1.5 1 -1 0\n";
    compare("antimatter", scene, SUN_AND_SKY, sensors);
}

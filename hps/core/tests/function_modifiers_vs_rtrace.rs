//! Function modifiers against RADIANCE run live: a room of our own whose window carries a
//! `BRTDfunc` roller shade with its `.cal` file (specular reflection and transmission as
//! functions of the incidence, Lambertian parts, a directional-diffuse part for the sun), a
//! ceiling that is a `mixfunc` of two plastics, a north wall bumped by a `texfunc` (under a
//! transform) and patterned by a 2-D `brightdata`, a west wall coloured by a 1-D
//! `colordata` extrapolated past its data, a floor coloured by a `colorfunc` (translated)
//! over a `texfunc` that tilts it towards the sun (which a small ripple alone would not show
//! at the sensors)
//! and an east wall shaded by a `brightfunc`, under a sunny `gensky` sky: our illuminance at every sensor must be within
//! 2 % or k combined standard errors of a converged rtrace (pure path tracing, independent
//! `-u+` estimates), via `compare_with_rtrace`.

mod common;
use common::compare::{compare_with_rtrace, sky, Effort};
use common::radiance::{radiance_or_skip, RTRACE_PATH_TRACING};
use std::path::Path;

/// rtrace estimates per sensor, each of `-ad 2048` paths (the test stays under 30 s).
const RTRACE_SAMPLES: usize = 8;
/// Our paths per sensor (an eighth under qemu-arm: `common::compare::our_samples_here`).
const OUR_SAMPLES: u32 = 16_384;

/// [`RTRACE_PATH_TRACING`] with half its paths per estimate.
fn rtrace_args() -> Vec<&'static str> {
    let mut args = RTRACE_PATH_TRACING.to_vec();
    let ad = args
        .iter()
        .position(|a| *a == "-ad")
        .expect("-ad in the setting");
    args[ad + 1] = "2048";
    args
}

/// The roller shade's optics (our own file): openness `arg(10)` seen straight on, falling
/// with the cosine of incidence; a faint specular reflection growing towards grazing; a
/// directional-diffuse part (1/sr) for light sources, stronger for light from above.
const SHADE_CAL: &str = "{ shade.cal: a roller shade for BRTDfunc }
openness = arg(10);
cos_in = abs(Rdot);
tspec = openness * sqrt(cos_in);
rspec = 0.03 + 0.04 * (1 - abs(RdotP));
brtd(lx, ly, lz, om) = 0.03 / PI * (1 + lz * lz);
";

/// Patterns, texture and mixture of the room's other surfaces (our own file).
const ROOM_CAL: &str = "{ room.cal: patterns for the function-modifier room }
floor_r = 0.75 + 0.2 * sin(2 * Px);
floor_g = 0.8 + 0.15 * cos(3 * Py);
floor_b = 0.7;
wall_bright = 0.8 + 0.2 * cos(4 * Pz);
bump_x = 0.12 * sin(6 * Px);
bump_y = 0;
bump_z = 0.12 * cos(5 * Pz);
tilt_x = 0.1;
tilt_y = -0.1 + 0.05 * sin(3 * Px);
tilt_z = 0;
ceiling_mix = 0.5 + 0.5 * sin(1.5 * Px) * cos(1.2 * Py);
clip(v) = if(v - 1.1, 1.1, v);
same(v) = v;
grey3(r, g, b) = (r + g + b) / 3;
";

/// brightdata on the north wall: 2-D over x (evenly spaced) and z (irregular points).
const NORTH_DAT: &str = "2
0.5 3.5 4
0 0 3 0.2 1.0 2.5
0.7 0.9 1.0
1.2 0.8 0.95
0.6 1.0 0.85
0.9 0.75 1.15
";

/// colordata on the west wall: 1-D over y from 1 m to 4 m (the wall spans 0 to 5 m, so
/// its ends are extrapolated, as data.c does).
const WEST_DAT: [(&str, &str); 3] = [
    ("west_r.dat", "1\n1 4 4\n0.9 0.8 1.0 0.85\n"),
    ("west_g.dat", "1\n1 4 4\n0.7 0.9 0.8 0.95\n"),
    ("west_b.dat", "1\n1 4 4\n0.6 0.7 0.9 0.8\n"),
];

/// Room 4 m (x, east) by 5 m (y, north) by 2.7 m, a south window (y = 0) behind the shade.
fn room() -> String {
    let materials = "\
void plastic wall_white 0 0 5 0.7 0.7 0.7 0 0
void plastic wall_grey 0 0 5 0.35 0.35 0.35 0 0
void glass pane 0 0 3 0.96 0.96 0.96
void texfunc tilt 4 tilt_x tilt_y tilt_z room.cal
0 0
tilt colorfunc floor_colour 8 floor_r floor_g floor_b room.cal -t 1 0 0
0 0
floor_colour plastic floor 0 0 5 0.5 0.45 0.4 0 0
void texfunc bumps 6 bump_x bump_y bump_z room.cal -s 0.5
0 0
bumps brightdata north_data 5 clip north.dat room.cal Px Pz
0 0
north_data plastic bumpy_wall 0 0 5 0.6 0.6 0.6 0 0
void colordata west_colour 8 same same grey3 west_r.dat west_g.dat west_b.dat room.cal Py
0 0
west_colour plastic west_wall 0 0 5 0.45 0.45 0.45 0 0
void brightfunc wall_shading 2 wall_bright room.cal
0 0
wall_shading plastic shaded_wall 0 0 5 0.65 0.6 0.55 0 0
void mixfunc ceiling 4 wall_white wall_grey ceiling_mix room.cal
0 0
void BRTDfunc shade
10 rspec rspec rspec tspec tspec tspec brtd brtd brtd shade.cal
0
10 0.55 0.55 0.5 0.45 0.45 0.45 0.12 0.12 0.11 0.1
";
    let poly = |m: &str, name: &str, v: &[[f64; 3]]| {
        let coords: Vec<String> = v.iter().flatten().map(|c| format!("{c}")).collect();
        format!(
            "{m} polygon {name}\n0\n0\n{} {}\n",
            coords.len(),
            coords.join(" ")
        )
    };
    let (w, d, h) = (4.0, 5.0, 2.7);
    let (x0, x1, z0, z1) = (0.8, 3.2, 0.9, 2.2);
    [
        materials.to_string(),
        poly(
            "floor",
            "floor",
            &[[0., 0., 0.], [w, 0., 0.], [w, d, 0.], [0., d, 0.]],
        ),
        poly(
            "ceiling",
            "ceiling",
            &[[0., 0., h], [0., d, h], [w, d, h], [w, 0., h]],
        ),
        poly(
            "bumpy_wall",
            "north",
            &[[0., d, 0.], [w, d, 0.], [w, d, h], [0., d, h]],
        ),
        poly(
            "shaded_wall",
            "east",
            &[[w, 0., 0.], [w, 0., h], [w, d, h], [w, d, 0.]],
        ),
        poly(
            "wall_grey",
            "west",
            &[[0., 0., 0.], [0., d, 0.], [0., d, h], [0., 0., h]],
        ),
        poly(
            "wall_white",
            "south_low",
            &[[0., 0., 0.], [0., 0., z0], [w, 0., z0], [w, 0., 0.]],
        ),
        poly(
            "wall_white",
            "south_high",
            &[[0., 0., z1], [0., 0., h], [w, 0., h], [w, 0., z1]],
        ),
        poly(
            "wall_white",
            "south_w",
            &[[0., 0., z0], [0., 0., z1], [x0, 0., z1], [x0, 0., z0]],
        ),
        poly(
            "wall_white",
            "south_e",
            &[[x1, 0., z0], [x1, 0., z1], [w, 0., z1], [w, 0., z0]],
        ),
        poly(
            "pane",
            "window",
            &[[x0, 0., z0], [x0, 0., z1], [x1, 0., z1], [x1, 0., z0]],
        ),
        poly(
            "shade",
            "roller",
            &[[x0, 0.1, z0], [x0, 0.1, z1], [x1, 0.1, z1], [x1, 0.1, z0]],
        ),
    ]
    .concat()
}

/// Sensors on the workplane, each well inside or well outside the sun patch (rtrace aims
/// its shadow rays at the sun's centre, `-dj 0`; we sample the disc, so a sensor on the
/// patch's edge would differ by the penumbra).
const SENSORS: &str = "\
1.0 1.0 0.8 0 0 1
2.0 1.2 0.8 0 0 1
3.0 1.0 0.8 0 0 1
2.0 2.5 0.8 0 0 1
1.0 3.5 0.8 0 0 1
3.0 4.0 0.8 0 0 1
";

fn write(dir: &Path, name: &str, text: &str) -> std::path::PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn brtdfunc_shade_mixfunc_texfunc_and_patterns_match_rtrace() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "shade.cal", SHADE_CAL);
    write(dir.path(), "room.cal", ROOM_CAL);
    write(dir.path(), "north.dat", NORTH_DAT);
    for (name, text) in WEST_DAT {
        write(dir.path(), name, text);
    }
    let room = write(dir.path(), "room.rad", &room());
    // Our loader reads rayinit.cal (PI) through RAYPATH, as rtrace does.
    if let Some(lib) = &lib {
        std::env::set_var("RAYPATH", format!(".:{}", lib.display()));
    }
    // Vernal equinox, 10:00 solar time in Lausanne: the sun in the south-east, through the
    // shade's openness onto the floor.
    let sky_text = sky(
        &bin,
        &lib,
        "gensky",
        &[
            "3", "21", "+10", "-a", "46.5", "-o", "-6.6", "-m", "-15", "+s",
        ],
    );
    let rtrace_args = rtrace_args();
    let effort = Effort {
        rtrace_args: &rtrace_args,
        rtrace_samples: RTRACE_SAMPLES,
        our_samples: OUR_SAMPLES,
        our_bounces: 8,
        k_sigma: 3.0,
    };
    compare_with_rtrace(
        "function-modifiers",
        &[room],
        &sky_text,
        SENSORS.as_bytes(),
        dir.path(),
        dir.path(),
        &effort,
    );
}

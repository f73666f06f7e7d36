//! The function and anisotropic materials, `texdata` and `mixdata` against RADIANCE run
//! live: a room of our own in which each of the eleven types covers a large surface that the sensors see, under a sunny
//! `gensky` sky, so that the parts only light sources see (the functions of the source
//! direction and the data over it) are lit by the sun:
//! - floor, all in the sun patch of a clear window: in front, a `plasfunc` with RADIANCE's
//!   own W-G-M-D model in `.cal` (`absdf` of the corpus' `aniso.cal`, through
//!   `rayinit.cal`'s `Ldx`.. frame) and a `metfunc` with a glossy lobe of our own about the
//!   viewer's mirror direction (a function of `Dx Dy Dz`, `NxP`.. and the sun's
//!   direction), tilted towards the sun by a `texdata` (2-D data over the floor); behind,
//!   a `plasdata` (1-D data over the sun's angle of incidence);
//! - west wall: `metdata` (2-D data over incidence and the sun's height, irregular points),
//!   sunlit through the same window; north wall: `metal2` brushed vertically, sunlit
//!   through an east window, its highlight seen by a sensor facing it (turning the brushing
//!   horizontal raises that sensor by 60 % in rtrace);
//! - ceiling: a `mixdata` (1-D data along x) of a `metfunc` (lit by no source: its ambient
//!   part) and a grey plastic; east wall: `plastic2` whose grain turns with height;
//! - three panes behind clear glass: `trans2`, `transdata` (data over the angle between the
//!   view and the sun), and a clerestory of `transfunc` (a forward-scattering lobe).
//!
//! Sensors look up, down at the floor, and at each wall and the panes, each out of the
//! sun's beam (rtrace aims its shadow rays at the sun's centre, we sample the disc). Our
//! illuminance must be within the shared agreement band of a converged rtrace (pure path
//! tracing, `-st 0` so that rtrace samples every highlight as we do), via
//! `compare_with_rtrace`.

mod common;
use common::compare::{compare_with_rtrace, sky, Effort};
use common::corpus::corpus;
use common::radiance::{radiance_or_skip, RTRACE_PATH_TRACING};
use std::path::Path;

/// rtrace estimates per sensor, each of [`RTRACE_PATHS`] paths (the test stays under 30 s).
const RTRACE_SAMPLES: usize = 5;
/// rtrace's `-ad` per estimate: with `-lw 1e-5` it also sets how deep rtrace goes (a ray
/// of weight below 1e-5 ends), so it stays what the other rooms use (at 1536 one run read
/// up to 4 % brighter here: deeper).
const RTRACE_PATHS: &str = "2048";
/// Our paths per sensor (an eighth under qemu-arm: `common::compare::our_samples_here`).
const OUR_SAMPLES: u32 = 10_240;

/// [`RTRACE_PATH_TRACING`] with [`RTRACE_PATHS`] per estimate and every highlight sampled
/// (`-st 0`: rtrace's default .15 would fold the weaker ones into the diffuse part).
fn rtrace_args() -> Vec<&'static str> {
    let mut args = RTRACE_PATH_TRACING.to_vec();
    let ad = args
        .iter()
        .position(|a| *a == "-ad")
        .expect("-ad in the setting");
    args[ad + 1] = RTRACE_PATHS;
    args.extend(["-st", "0"]);
    args
}

/// The directional parts (our own file). `gloss`: a normalised Phong lobe, (n + 2)/2π
/// cosⁿ, n = 4, about the mirror direction of the view (r·l = D·l + 2 RdotP (N·l));
/// `forward`: a transmitted lobe about the ray; the data forms' coordinates (degrees) and
/// their value per steradian; the east wall's grain.
const BRDF_CAL: &str = "{ brdf.cal: directional parts for the function-material room }
pos(x) = if(x, x, 0);
ndotl(lx, ly, lz) = NxP * lx + NyP * ly + NzP * lz;
gloss(lx, ly, lz, om) = 3 / PI * pos(Dx * lx + Dy * ly + Dz * lz + 2 * RdotP * ndotl(lx, ly, lz)) ^ 4;
forward(lx, ly, lz, om) = 5 / (2 * PI) * pos(Dx * lx + Dy * ly + Dz * lz) ^ 3;
incidence(lx, ly, lz, om) = acos(abs(ndotl(lx, ly, lz))) * 180 / PI;
lvert(lx, ly, lz, om) = lz;
spread(lx, ly, lz, om) = acos(Dx * lx + Dy * ly + Dz * lz) * 180 / PI;
scale(v, lx, ly, lz, om) = v / PI;
clip01(v) = if(v - 1, 1, if(v, v, 0));
first(a, b, c) = a;
second(a, b, c) = b;
third(a, b, c) = c;
grain_y = sin(2 * Pz);
grain_z = cos(2 * Pz);
";

/// texdata on the floor's glossy part: a tilt towards the sun (+x, −y) over (Px, Py), one
/// file per component.
const TILT_DAT: [(&str, &str); 3] = [
    (
        "tilt_x.dat",
        "2\n1 4 3\n0 1.6 2\n0.1 0.15\n0.2 0.12\n0.15 0.1\n",
    ),
    (
        "tilt_y.dat",
        "2\n1 4 3\n0 1.6 2\n-0.15 -0.05\n-0.1 -0.12\n-0.2 -0.1\n",
    ),
    ("tilt_z.dat", "2\n1 4 3\n0 1.6 2\n0 0\n0 0\n0 0\n"),
];
/// mixdata on the ceiling: the glossy metfunc's share along x.
const CEILING_DAT: &str = "1\n0 4 5\n0.2 0.9 0.5 0.1 0.7\n";

/// plasdata on the floor's back half: over the incidence angle, evenly spaced.
const FLOOR_DAT: &str = "1\n0 90 4\n0.4 0.6 0.9 1.4\n";
/// metdata on the west wall: incidence (evenly spaced) by the sun's height (irregular).
const WEST_DAT: &str = "2\n0 90 3\n0 0 3 0.2 0.5 0.7\n0.6 0.8 1.0\n0.9 1.1 1.3\n1.5 1.2 0.8\n";
/// transdata on a pane: over the angle between the view and the sun (irregular points).
const PANE_DAT: &str = "1\n0 0 4 0 15 40 90\n1.8 1.1 0.4 0.1\n";

/// The room: 4 m (x, east) by 5 m (y, north) by 2.7 m.
const W: f64 = 4.0;
const D: f64 = 5.0;
const H: f64 = 2.7;

const MATERIALS: &str = "\
void plastic wall_white 0 0 5 0.6 0.6 0.6 0 0
void glass pane 0 0 3 0.96 0.96 0.96
void plasfunc floor_aniso 2 absdf aniso.cal 0 9 0.5 0.45 0.4 0.12 0.05 0.15 1 0 0
void texdata tilt 9 first second third tilt_x.dat tilt_y.dat tilt_z.dat brdf.cal Px Py 0 0
tilt metfunc floor_gloss 2 gloss brdf.cal 0 4 0.55 0.5 0.45 0.15
void plasdata floor_back 4 scale floor.dat brdf.cal incidence 0 4 0.45 0.5 0.4 0.2
void metdata west_wall 5 scale west.dat brdf.cal incidence lvert 0 4 0.6 0.55 0.5 0.3
void metal2 brushed 4 0 0 1 . 0 6 0.6 0.65 0.7 0.5 0.04 0.3
void metfunc ceiling_gloss 2 gloss brdf.cal 0 4 0.85 0.85 0.85 0.25
void plastic ceiling_grey 0 0 5 0.4 0.4 0.4 0 0
void mixdata ceiling 6 ceiling_gloss ceiling_grey clip01 ceiling.dat brdf.cal Px 0 0
void plastic2 grained 4 0 grain_y grain_z brdf.cal 0 6 0.6 0.6 0.55 0.08 0.05 0.2
void trans2 frosted 4 1 0 0 . 0 8 0.8 0.8 0.8 0.04 0.12 0.04 0.6 0.5
void transdata scattering 4 scale pane.dat brdf.cal spread 0 6 0.85 0.85 0.85 0.03 0.6 0.5
void transfunc clerestory 2 forward brdf.cal 0 6 0.8 0.8 0.75 0.03 0.7 0.6
";

fn polygon(material: &str, name: &str, vertices: &[[f64; 3]]) -> String {
    let coords: Vec<String> = vertices.iter().flatten().map(|c| format!("{c}")).collect();
    format!(
        "{material} polygon {name}\n0\n0\n{} {}\n",
        coords.len(),
        coords.join(" ")
    )
}

/// A rectangle in the plane y = `y` (normal +y), x in `x`, z in `z`.
fn south_facing(material: &str, name: &str, y: f64, x: [f64; 2], z: [f64; 2]) -> String {
    polygon(
        material,
        name,
        &[
            [x[0], y, z[0]],
            [x[1], y, z[0]],
            [x[1], y, z[1]],
            [x[0], y, z[1]],
        ],
    )
}

/// The south wall (y = 0) around its openings: the clear window (x 1.2–2.8), the trans2
/// (0.2–1.0) and transdata (3.0–3.8) panes at z 0.9–2.2, and the clerestory (z 2.35–2.6).
fn south_wall() -> String {
    let mut out = String::new();
    let bands = [[0.0, 0.9], [2.2, 2.35], [2.6, H]];
    for (i, z) in bands.iter().enumerate() {
        out += &south_facing("wall_white", &format!("south_band{i}"), 0.0, [0.0, W], *z);
    }
    for (i, x) in [[0.0, 0.2], [1.0, 1.2], [2.8, 3.0], [3.8, W]]
        .iter()
        .enumerate()
    {
        out += &south_facing("wall_white", &format!("south_pier{i}"), 0.0, *x, [0.9, 2.2]);
    }
    for (i, x) in [[0.0, 0.2], [3.8, W]].iter().enumerate() {
        out += &south_facing("wall_white", &format!("south_end{i}"), 0.0, *x, [2.35, 2.6]);
    }
    let openings = [
        ([0.2, 1.0], [0.9, 2.2], Some("frosted")),
        ([1.2, 2.8], [0.9, 2.2], None),
        ([3.0, 3.8], [0.9, 2.2], Some("scattering")),
        ([0.2, 3.8], [2.35, 2.6], Some("clerestory")),
    ];
    for (i, (x, z, inner)) in openings.iter().enumerate() {
        out += &south_facing("pane", &format!("glass{i}"), 0.0, *x, *z);
        if let Some(m) = inner {
            out += &south_facing(m, &format!("inner{i}"), 0.05, *x, *z);
        }
    }
    out
}

/// The east wall (x = W, normal −x) around a clear window at y 2.5–4.0, z 0.9–2.2.
fn east_wall() -> String {
    let rect = |m: &str, name: &str, y: [f64; 2], z: [f64; 2]| {
        polygon(
            m,
            name,
            &[
                [W, y[0], z[0]],
                [W, y[0], z[1]],
                [W, y[1], z[1]],
                [W, y[1], z[0]],
            ],
        )
    };
    [
        rect("grained", "east_low", [0.0, D], [0.0, 0.9]),
        rect("grained", "east_high", [0.0, D], [2.2, H]),
        rect("grained", "east_front", [0.0, 2.5], [0.9, 2.2]),
        rect("grained", "east_back", [4.0, D], [0.9, 2.2]),
        rect("pane", "east_window", [2.5, 4.0], [0.9, 2.2]),
    ]
    .concat()
}

fn room() -> String {
    [
        MATERIALS.to_string(),
        polygon(
            "floor_aniso",
            "floor_west",
            &[[0., 0., 0.], [1., 0., 0.], [1., 1.6, 0.], [0., 1.6, 0.]],
        ),
        polygon(
            "floor_gloss",
            "floor_east",
            &[[1., 0., 0.], [W, 0., 0.], [W, 1.6, 0.], [1., 1.6, 0.]],
        ),
        polygon(
            "floor_back",
            "floor_back",
            &[[0., 1.6, 0.], [W, 1.6, 0.], [W, D, 0.], [0., D, 0.]],
        ),
        polygon(
            "ceiling",
            "ceiling",
            &[[0., 0., H], [0., D, H], [W, D, H], [W, 0., H]],
        ),
        polygon(
            "brushed",
            "north",
            &[[0., D, 0.], [W, D, 0.], [W, D, H], [0., D, H]],
        ),
        polygon(
            "west_wall",
            "west",
            &[[0., 0., 0.], [0., D, 0.], [0., D, H], [0., 0., H]],
        ),
        south_wall(),
        east_wall(),
    ]
    .concat()
}

/// Up at the workplane; down over the floor's two halves; at the west wall's sun patch,
/// the north and east walls, the south panes; up under the ceiling; low, facing the north
/// wall's sunlit highlight; facing the sun's glint on the `aniso.cal` floor (a quarter of its
/// light in rtrace; its line to the sun meets the wall 5 cm below the clerestory).
const SENSORS: &str = "\
3.2 1.5 0.8 0 0 1
2.0 3.0 0.8 0 0 1
1.0 4.0 0.8 0 0 1
2.2 4.5 0.8 0 0 1
1.0 1.5 1.0 0 0 -1
1.0 2.3 1.0 0 0 -1
1.5 2.5 0.4 -1 0 0
2.0 4.0 1.2 0 1 0
2.0 2.5 1.6 0 -1 0
2.0 2.0 1.5 0 0 1
3.0 3.0 1.0 1 0 0
2.2 4.0 0.3 0.5 0.63 0.59
0.2 1.93 0.45 0.5 -0.633 -0.591
";

fn write(dir: &Path, name: &str, text: &str) -> std::path::PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn function_and_anisotropic_materials_match_rtrace() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "brdf.cal", BRDF_CAL);
    write(dir.path(), "floor.dat", FLOOR_DAT);
    write(dir.path(), "west.dat", WEST_DAT);
    write(dir.path(), "pane.dat", PANE_DAT);
    write(dir.path(), "ceiling.dat", CEILING_DAT);
    for (name, text) in TILT_DAT {
        write(dir.path(), name, text);
    }
    // RADIANCE's own file (BSD-style licence, header kept), as the corpus holds it.
    std::fs::copy(
        corpus().join("radiance-test-renders/test/renders/aniso.cal"),
        dir.path().join("aniso.cal"),
    )
    .unwrap();
    let room = write(dir.path(), "room.rad", &room());
    // Our loader reads rayinit.cal (PI) through RAYPATH, as rtrace does.
    if let Some(lib) = &lib {
        std::env::set_var("RAYPATH", format!(".:{}", lib.display()));
    }
    // Vernal equinox, 10:00 solar time in Lausanne: the sun in the south-east (altitude
    // 36°), through the clear south window onto the floor and the west wall, and through
    // the east window onto the north wall.
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
        "brdf-materials",
        &[room],
        &sky_text,
        SENSORS.as_bytes(),
        dir.path(),
        dir.path(),
        &effort,
    );
}

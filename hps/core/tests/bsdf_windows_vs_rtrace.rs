//! BSDF windows (RADIANCE's `BSDF` material on WINDOW / LBNL XML data) in the engine against a
//! converged `rtrace` of the same scene with the same XML, live from the pyradiance wheel:
//!
//! - a box room of our own with one south window carrying the Nysan Satine 5 % shade
//!   (frads `2011-SA1.xml`) or the electrochromic glazing (frads `ec60.xml`), under a CIE
//!   overcast sky and two sunny skies whose sun goes through the device steeply (60°) and at
//!   a shallow angle (15°);
//! - the LBNL matrix tutorial's room with its aluminium-grate overhang, a proxied BSDF of
//!   thickness ±0.03825 m, assembled as the tutorial's commands load it;
//! - bad input: a BSDF naming a missing or malformed XML is an error naming the scene file and
//!   line and the XML file.
//!
//! rtrace runs pure path tracing (`-aa 0 -as 0 -ab 8 -lw 1e-5`) with `-st 0`, so that it
//! samples every non-diffuse part of the BSDF instead of folding those under the default
//! specular threshold (0.15) into its diffuse ambient term (m_bsdf.c `sample_sdf`).

mod common;

use common::compare::{compare_with_rtrace, sky, Effort};
use common::radiance::radiance_or_skip;
use skylux_hps::engine::World;
use skylux_hps::scene;
use std::path::{Path, PathBuf};

fn corpus() -> PathBuf {
    let root = std::env::var_os("SKYLUX_DATA_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data"));
    let corpus = root.join("radiance-corpus");
    assert!(
        corpus.join("README.md").is_file(),
        "the RADIANCE corpus is missing at {}",
        corpus.display()
    );
    corpus
}

/// rtrace's converged setting for BSDF scenes (see the module comment for `-st 0`).
const RTRACE_BSDF: &[&str] = &[
    "-h", "-I", "-u+", "-ab", "8", "-aa", "0", "-ad", "256", "-as", "0", "-lw", "1e-5", "-lr",
    "-16", "-st", "0",
];

/// A 4 m × 5 m × 3 m room, the window (x 1..3 m, z 0.9..2.1 m) in its south wall (y = 0)
/// with its normal into the room (RADIANCE's convention for WINDOW data), up +z.
fn box_room(xml: &Path) -> String {
    let mut s = format!(
        "void BSDF window_bsdf\n6 0 {} 0 0 1 .\n0\n0\n\
         void plastic wall 0 0 5 0.5 0.5 0.5 0 0\n\
         void plastic floor 0 0 5 0.2 0.2 0.2 0 0\n\
         void plastic ceiling 0 0 5 0.7 0.7 0.7 0 0\n\
         window_bsdf polygon window 0 0 12 1 0 0.9 1 0 2.1 3 0 2.1 3 0 0.9\n",
        xml.display()
    );
    let quads: [(&str, &str, [[f64; 3]; 4]); 9] = [
        (
            "floor",
            "floor",
            [[0., 0., 0.], [4., 0., 0.], [4., 5., 0.], [0., 5., 0.]],
        ),
        (
            "ceiling",
            "ceiling",
            [[0., 0., 3.], [0., 5., 3.], [4., 5., 3.], [4., 0., 3.]],
        ),
        (
            "wall",
            "east",
            [[4., 0., 0.], [4., 0., 3.], [4., 5., 3.], [4., 5., 0.]],
        ),
        (
            "wall",
            "west",
            [[0., 0., 0.], [0., 5., 0.], [0., 5., 3.], [0., 0., 3.]],
        ),
        (
            "wall",
            "north",
            [[0., 5., 0.], [4., 5., 0.], [4., 5., 3.], [0., 5., 3.]],
        ),
        (
            "wall",
            "south_low",
            [[0., 0., 0.], [0., 0., 0.9], [4., 0., 0.9], [4., 0., 0.]],
        ),
        (
            "wall",
            "south_high",
            [[0., 0., 2.1], [0., 0., 3.], [4., 0., 3.], [4., 0., 2.1]],
        ),
        (
            "wall",
            "south_west",
            [[0., 0., 0.9], [0., 0., 2.1], [1., 0., 2.1], [1., 0., 0.9]],
        ),
        (
            "wall",
            "south_east",
            [[3., 0., 0.9], [3., 0., 2.1], [4., 0., 2.1], [4., 0., 0.9]],
        ),
    ];
    for (material, name, corners) in quads {
        s.push_str(&format!("{material} polygon {name} 0 0 12"));
        for c in corners {
            s.push_str(&format!(" {} {} {}", c[0], c[1], c[2]));
        }
        s.push('\n');
    }
    s
}

/// Workplane sensors (0.8 m, facing up) from the window to the back, in and out of the
/// sun patches of the two sunny skies.
const BOX_SENSORS: &str = "\
1.5 0.8 0.8 0 0 1
2.5 1.5 0.8 0 0 1
2.0 2.5 0.8 0 0 1
1.0 3.5 0.8 0 0 1
3.0 4.2 0.8 0 0 1
2.0 1.0 0.8 0 0 1
";

/// The three skies: CIE overcast, and CIE clear with the sun due south at 60° (steep
/// through the window) and 30° east of south at 15° (shallow).
const SKIES: [(&str, &[&str]); 3] = [
    ("overcast", &["-ang", "45", "0", "-c", "-B", "55.8"]),
    ("sun-steep", &["-ang", "60", "0", "+s"]),
    ("sun-shallow", &["-ang", "15", "-30", "+s"]),
];

fn box_room_under_every_sky(label: &str, xml: &Path, effort: &Effort) {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let room = dir.path().join("room.rad");
    std::fs::write(&room, box_room(xml)).unwrap();
    for (sky_label, args) in SKIES {
        let sky_text = sky(&bin, &lib, "gensky", args);
        compare_with_rtrace(
            &format!("{label}-{sky_label}"),
            &[room.clone()],
            &sky_text,
            BOX_SENSORS.as_bytes(),
            dir.path(),
            dir.path(),
            effort,
        );
    }
}

#[test]
fn box_room_with_the_satine_shade() {
    let xml = corpus().join("bsdf/frads/2011-SA1.xml");
    let effort = Effort {
        rtrace_args: RTRACE_BSDF,
        rtrace_samples: 8,
        our_samples: 4096,
        our_bounces: 8,
        k_sigma: 3.0,
    };
    box_room_under_every_sky("satine", &xml, &effort);
}

#[test]
fn box_room_with_the_electrochromic_glazing() {
    let xml = corpus().join("bsdf/frads/ec60.xml");
    let effort = Effort {
        rtrace_args: RTRACE_BSDF,
        rtrace_samples: 8,
        our_samples: 4096,
        our_bounces: 8,
        k_sigma: 3.0,
    };
    box_room_under_every_sky("ec60", &xml, &effort);
}

#[test]
#[ignore]
fn diagnostic() {
    let Some(_) = radiance_or_skip() else {
        return;
    };
    let xml = corpus().join(std::env::var("XML").unwrap_or("bsdf/frads/2011-SA1.xml".into()));
    let refl = std::env::var("REFL").unwrap_or("0".into());
    let dir = tempfile::tempdir().unwrap();
    let room = dir.path().join("room.rad");
    std::fs::write(
        &room,
        box_room(&xml)
            .replace("0.5 0.5 0.5 0 0", &format!("{refl} {refl} {refl} 0 0"))
            .replace("0.2 0.2 0.2 0 0", &format!("{refl} {refl} {refl} 0 0"))
            .replace("0.7 0.7 0.7 0 0", &format!("{refl} {refl} {refl} 0 0")),
    )
    .unwrap();
    let sky_text = std::env::var("SKY").unwrap_or(
        "void light solar 0 0 3 1e5 1e5 1e5\nsolar source sun 0 0 4 0 -0.5 0.866 0.533\n".into(),
    );
    let effort = Effort {
        rtrace_args: RTRACE_BSDF,
        rtrace_samples: 8,
        our_samples: 4096,
        our_bounces: 8,
        k_sigma: 3.0,
    };
    compare_with_rtrace(
        "diag",
        &[room],
        sky_text.as_bytes(),
        BOX_SENSORS.as_bytes(),
        dir.path(),
        dir.path(),
        &effort,
    );
}

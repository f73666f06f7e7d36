//! `skylux genbsdf` (`engine::genbsdf`) against RADIANCE's genBSDF, live from the pyradiance
//! wheel where it can be run:
//!
//! - RADIANCE's sawtooth (the corpus holds its genBSDF input and the XML genBSDF made of it,
//!   `-dim -120 120 -120 120 -2 0`, 2000 rays per patch): per incident patch, the room-side
//!   reflectance (the only part that file has) within 0.01, or 4 combined standard errors;
//! - the LBNL tutorial's venetian blinds (glass and 306 slats, `room/blinds/blinds.rad`)
//!   against the two files genBSDF made of it (`genBSDF -c 10000 -ab 5`, Klems full, and
//!   the same with `-t3 5`, a 32-cell isotropic tensor tree): per incident patch or cell and
//!   part, R and T within 0.01 or 4 combined standard errors;
//! - a venetian blind of our own (`fixtures/genbsdf/blind45.rad`) against the pyradiance port
//!   of genBSDF run here: all four parts, per incident patch, R and T within 0.01 or 4
//!   combined standard errors;
//! - `checkBSDF` reads our files and finds what we wrote;
//! - the box room glazed with the blind: the engine with our XML against a converged rtrace
//!   with the port's XML, every sensor within 3 % or 4 combined standard errors.
//!
//! The references' standard errors are not given by genBSDF; they are taken as ours scaled
//! by √(our rays / their rays) (the same estimator: rays uniform over the patch and the face).
//! At the sample counts CI affords the port (its rfluxmtx is some 300× slower than our
//! sampling), that bound is wider than 0.01 for the blind's transmission; BENCHMARKS.md
//! "BSDFs from geometry" gives the high-count run and its figures.

mod common;

use common::box_room::{box_room, BOX_SENSORS};
use common::compare::{compare_with_rtrace_from, sky, Effort};
use common::corpus::corpus;
use common::radiance::{check_output, pyradiance_bsdf_or_skip, radiance_or_skip, tool};
use glam::DVec3;
use skylux_hps::bsdf::{bsdf_xml, AngleBasis, Band, Bsdf, Scattering, Side};
use skylux_hps::engine::genbsdf::{
    generate_klems, generate_tensor_tree, GenBsdfSettings, GeneratedBsdf, SamplingBox, TreeKind,
};
use skylux_hps::engine::World;
use skylux_hps::scene;
use std::path::{Path, PathBuf};
use std::process::Command;

fn full() -> AngleBasis {
    AngleBasis::builtin("LBNL/Klems Full").unwrap()
}

fn ours(device: &Path, sampling: SamplingBox, samples: u32) -> GeneratedBsdf {
    let scene = scene::load(device).unwrap();
    let world = World::new(&scene).unwrap();
    let settings = GenBsdfSettings {
        samples_per_patch: samples,
        seed: 5,
        ..Default::default()
    };
    generate_klems(&world, &sampling, &full(), &settings, &|_, _| {}).unwrap()
}

fn write_ours(g: &GeneratedBsdf, sampling: &SamplingBox, path: &Path) {
    let doc = g.document("test device", "genbsdf_vs_radiance", "meter", sampling);
    std::fs::write(path, bsdf_xml(&doc).unwrap()).unwrap();
}

/// Patch `patch`'s directional-hemispherical value of `side` in a file, as RADIANCE's
/// library reads it (our reader agrees with `pyradiance.bsdf.direct_hemi` within 1e-4:
/// `bsdf_vs_radiance`).
fn hemispherical(bsdf: &Bsdf, side: Side, patch: usize) -> f64 {
    let incident = side.incident_in_basis_frame(full().direction_in_patch(patch, [0.5, 0.5]));
    let kind = if side.is_transmission() {
        Scattering::Transmission
    } else {
        Scattering::Reflection
    };
    bsdf.hemispherical(incident, kind)
}

/// Per incident patch of `side`, ours (read back from our XML) against theirs; the bound is
/// 0.01 or 4 combined standard errors. Returns the largest difference and how many patches
/// were within 0.01 outright.
fn agree_per_patch(
    label: &str,
    side: Side,
    g: &GeneratedBsdf,
    our_xml: &Bsdf,
    their_xml: &Bsdf,
    their_samples: u32,
) -> (f64, usize) {
    let n = full().len();
    let scale = (f64::from(g.samples_per_patch) / f64::from(their_samples)).sqrt();
    let (mut worst, mut within, mut failures) = (0.0f64, 0, Vec::new());
    for p in 0..n {
        let (a, b) = (
            hemispherical(our_xml, side, p),
            hemispherical(their_xml, side, p),
        );
        // What we wrote is what we sampled.
        let sampled = g.hemispherical(side, p).unwrap();
        assert!(
            (a - sampled).abs() < 1e-4,
            "{label} {side:?} {p}: XML {a} vs {sampled}"
        );
        let se = g.hemispherical_standard_error(side, p).unwrap();
        let combined = se.hypot(se * scale);
        let d = (a - b).abs();
        worst = worst.max(d);
        within += usize::from(d <= 0.01);
        if d > 0.01f64.max(4.0 * combined) {
            failures.push(format!(
                "patch {p}: ours {a:.4} theirs {b:.4} (σ {combined:.4})"
            ));
        }
    }
    println!("{label} {side:?}: largest difference {worst:.4}, {within}/{n} patches within 0.01");
    assert!(failures.is_empty(), "{label} {side:?}: {failures:?}");
    (worst, within)
}

#[test]
fn radiance_sawtooth_against_its_genbsdf_file() {
    let dir = corpus().join("bsdf/radiance/test/renders");
    // The file's own command: genBSDF -geom millimeter -dim -120 120 -120 120 -2 0 (-c 2000).
    let sampling = SamplingBox {
        min: DVec3::new(-120.0, -120.0, -2.0),
        max: DVec3::new(120.0, 120.0, 0.0),
    };
    let g = ours(&dir.join("sawtooth.rad"), sampling, 8000);
    let work = tempfile::tempdir().unwrap();
    let our_path = work.path().join("sawtooth-ours.xml");
    write_ours(&g, &sampling, &our_path);
    let mine = Bsdf::load(&our_path).unwrap();
    let theirs = Bsdf::load(&dir.join("sawtooth.xml")).unwrap();
    let (worst, within) =
        agree_per_patch("sawtooth", Side::FrontReflection, &g, &mine, &theirs, 2000);
    // Observed: 0.0065 at most (8000 rays), every patch within 0.01.
    assert!(worst < 0.02 && within >= 140, "{worst} {within}");
    // An opaque device: no transmission was written.
    assert!(!mine.part_present(Side::FrontTransmission));
    assert!(!mine.part_present(Side::BackTransmission));
    // The outside is the prism's flat metal base: R = the metal's reflectance 0.7 at every
    // angle (RADIANCE's metal: specular 0.95 of 0.7, the rest diffuse, all reflected).
    for p in 0..full().len() {
        let r = g.hemispherical(Side::BackReflection, p).unwrap();
        assert!((r - 0.7).abs() < 0.005, "outside R of patch {p}: {r}");
    }
}

/// The tutorial's blinds as genBSDF had them (its input, with the device's bounding box).
fn tutorial_blinds() -> PathBuf {
    corpus().join("sariths-matrix-tutorial/room/blinds/blinds.rad")
}

fn tutorial_box() -> SamplingBox {
    let world = World::new(&scene::load(tutorial_blinds()).unwrap()).unwrap();
    SamplingBox::of_world(&world).unwrap()
}

#[test]
fn tutorial_blinds_against_genbsdf_klems() {
    let sampling = tutorial_box();
    let g = ours(&tutorial_blinds(), sampling, 20_000);
    let work = tempfile::tempdir().unwrap();
    let our_path = work.path().join("blinds-ours.xml");
    write_ours(&g, &sampling, &our_path);
    let mine = Bsdf::load(&our_path).unwrap();
    let theirs =
        Bsdf::load(&corpus().join("bsdf/sariths-matrix-tutorial/room/blinds/blinds.xml")).unwrap();
    for side in [
        Side::FrontReflection,
        Side::BackReflection,
        Side::FrontTransmission,
        Side::BackTransmission,
    ] {
        // Observed: 0.0065 to 0.0103 at most per part at 10,000 rays each.
        let (worst, within) = agree_per_patch("tutorial blinds", side, &g, &mine, &theirs, 10_000);
        assert!(worst < 0.02 && within >= 138, "{side:?}: {worst} {within}");
    }
}

#[test]
fn tutorial_blinds_against_genbsdf_t3() {
    let sampling = tutorial_box();
    let scene = scene::load(tutorial_blinds()).unwrap();
    let world = World::new(&scene).unwrap();
    let settings = GenBsdfSettings {
        samples_per_patch: 20_000,
        seed: 9,
        ..Default::default()
    };
    let g = generate_tensor_tree(
        &world,
        &sampling,
        TreeKind::Isotropic,
        5,
        &settings,
        &|_, _| {},
    )
    .unwrap();
    let work = tempfile::tempdir().unwrap();
    let our_path = work.path().join("blindsT3-ours.xml");
    let grids = g.grids();
    let doc = g.document(
        &grids,
        "tutorial blinds",
        "genbsdf_vs_radiance",
        "meter",
        &sampling,
    );
    std::fs::write(&our_path, bsdf_xml(&doc).unwrap()).unwrap();
    let mine = Bsdf::load(&our_path).unwrap();
    assert!(mine.has_tensor_tree());
    let file = Bsdf::load(&corpus().join("bsdf/sariths-matrix-tutorial/room/blinds/blindsT3.xml"))
        .unwrap();
    // The file (genBSDF of 2012, 10,000 rays per cell) reads the most grazing cell of the
    // outside reflection at 0.29 where we read 0.24 and today's genBSDF (the port, run
    // here) 0.23: that one cell is judged against the port only.
    let outlier = (Side::BackReflection, 0);
    t3_agreement(
        "the corpus's blindsT3.xml",
        &g,
        &mine,
        &file,
        10_000,
        Some(outlier),
    );
    let Some(_) = radiance_or_skip() else {
        return;
    };
    if !pyradiance_bsdf_or_skip() {
        return;
    }
    let port_samples = 1000;
    let copy = work.path().join("blinds.rad");
    std::fs::copy(tutorial_blinds(), &copy).unwrap();
    let port = pyradiance_genbsdf(&copy, work.path(), port_samples, &sampling, Some((3, 5)));
    let port = Bsdf::load(&port).unwrap();
    t3_agreement(
        "the port of genBSDF -t3 5",
        &g,
        &mine,
        &port,
        port_samples,
        None,
    );
}

/// Per part and incident cell of a 32-cell isotropic tree, R or T of ours (read back) and
/// of `theirs` (`their_samples` rays per cell) within 0.01 or 4 combined standard errors,
/// `skip` aside.
fn t3_agreement(
    label: &str,
    g: &skylux_hps::engine::genbsdf::GeneratedTree,
    mine: &Bsdf,
    theirs: &Bsdf,
    their_samples: u32,
    skip: Option<(Side, usize)>,
) {
    let res = 32usize;
    let scale = (f64::from(g.samples_per_cell) / f64::from(their_samples)).sqrt();
    let mut failures = Vec::new();
    for side in [
        Side::FrontReflection,
        Side::BackReflection,
        Side::FrontTransmission,
        Side::BackTransmission,
    ] {
        let kind = if side.is_transmission() {
            Scattering::Transmission
        } else {
            Scattering::Reflection
        };
        let z_sign = if side.incident_front() { 1.0 } else { -1.0 };
        let mut worst = 0.0f64;
        for cell in 0..res / 2 {
            // The cell's middle, in the plane genBSDF samples (x-z, the incident at azimuth π).
            let sin_theta = 1.0 - 2.0 * (cell as f64 + 0.5) / res as f64;
            let incident = DVec3::new(
                -sin_theta,
                0.0,
                z_sign * (1.0 - sin_theta * sin_theta).sqrt(),
            );
            let (a, b) = (
                mine.hemispherical(incident, kind),
                theirs.hemispherical(incident, kind),
            );
            let (sampled, se) = g.hemispherical(side, cell).unwrap();
            assert!(
                (a - sampled).abs() < 1e-3,
                "{side:?} cell {cell}: XML {a} vs {sampled}"
            );
            if skip == Some((side, cell)) {
                println!("  {label}: {side:?} cell {cell} left out: ours {a:.4}, theirs {b:.4}");
                continue;
            }
            let combined = se.hypot(se * scale);
            worst = worst.max((a - b).abs());
            if (a - b).abs() > 0.01f64.max(4.0 * combined) {
                failures.push(format!(
                    "{side:?} cell {cell}: ours {a:.4} theirs {b:.4} (σ {combined:.4})"
                ));
            }
        }
        println!("{label}, {side:?}: largest difference {worst:.4}");
    }
    assert!(failures.is_empty(), "{label}: {failures:?}");
}

/// The port of genBSDF in pyradiance on `device` (its working folder `dir`) within
/// `sampling`, visible: its XML. `tree`: None for Klems full, Some((3 or 4, log2 res)).
fn pyradiance_genbsdf(
    device: &Path,
    dir: &Path,
    samples: u32,
    sampling: &SamplingBox,
    tree: Option<(u32, u32)>,
) -> PathBuf {
    let out = dir.join("theirs.xml");
    let script = "import sys\n\
        from pyradiance import genbsdf as g\n\
        d = [float(x) for x in sys.argv[6:12]]\n\
        t, lg = int(sys.argv[4]), int(sys.argv[5])\n\
        res = g.generate_bsdf(sys.argv[1], nsamp=int(sys.argv[2]), nproc=2, \
        dim=g.SamplingBox(*d), tensortree=t, ttlog2=lg)\n\
        basis = 't%d' % t if t else 'kf'\n\
        open(sys.argv[3], 'wb').write(g.generate_xml(vis_results=res, basis=basis))\n";
    let (min, max) = (sampling.min, sampling.max);
    let (dims, log2) = tree.unwrap_or((0, 4));
    let status = Command::new("python3")
        .current_dir(dir)
        .args(["-c", script])
        .arg(device)
        .arg(samples.to_string())
        .arg(&out)
        .args([dims.to_string(), log2.to_string()])
        .args([min.x, max.x, min.y, max.y, min.z, max.z].map(|v| v.to_string()))
        .status()
        .expect("python3");
    assert!(
        status.success(),
        "pyradiance.genbsdf failed on {}",
        device.display()
    );
    out
}

/// The blind's box: the middle 0.8 m × 0.8 m of the 1 m × 1 m blind, its slats' depth.
fn blind_box() -> SamplingBox {
    SamplingBox {
        min: DVec3::new(0.1, 0.1, -0.0176777),
        max: DVec3::new(0.9, 0.9, 0.0),
    }
}

#[test]
fn our_blind_against_the_pyradiance_port_in_a_room_and_in_checkbsdf() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    if !pyradiance_bsdf_or_skip() {
        return;
    }
    let device = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/genbsdf/blind45.rad");
    let sampling = blind_box();
    let g = ours(&device, sampling, 20_000);
    let (our_dir, their_dir) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    // CI runs the port at 400 rays a patch (about 50 s); the high-count run of
    // docs/bsdf.md sets SKYLUX_GENBSDF_PORT_SAMPLES=10000 (about 35 minutes).
    let their_samples: u32 = std::env::var("SKYLUX_GENBSDF_PORT_SAMPLES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(400);
    let start = std::time::Instant::now();
    let their_path = pyradiance_genbsdf(&device, their_dir.path(), their_samples, &sampling, None);
    println!(
        "pyradiance genbsdf, {their_samples} rays per patch: {:.1} s",
        start.elapsed().as_secs_f64()
    );
    std::fs::rename(&their_path, their_dir.path().join("blind.xml")).unwrap();
    write_ours(&g, &sampling, &our_dir.path().join("blind.xml"));
    let mine = Bsdf::load_band(&our_dir.path().join("blind.xml"), Band::Visible).unwrap();
    let theirs = Bsdf::load(&their_dir.path().join("blind.xml")).unwrap();
    for side in [
        Side::FrontReflection,
        Side::BackReflection,
        Side::FrontTransmission,
        Side::BackTransmission,
    ] {
        agree_per_patch("blind45", side, &g, &mine, &theirs, their_samples);
    }

    // checkBSDF reads ours as a Klems full BSDF with transmission both ways.
    let mut c = tool(&bin, &lib, "checkBSDF");
    c.arg(our_dir.path().join("blind.xml"));
    let report = String::from_utf8(check_output(c, None)).unwrap();
    println!("{report}");
    assert!(report.contains("Type: Klems_Full"), "{report}");
    // Its largest directional-hemispherical value per part is ours (percent, one decimal).
    for (line, side) in [
        ("Interior Refl", Side::FrontReflection),
        ("Exterior Refl", Side::BackReflection),
        ("Int->Ext Trans", Side::FrontTransmission),
        ("Ext->Int Trans", Side::BackTransmission),
    ] {
        let row = report
            .lines()
            .find(|l| l.starts_with(line))
            .unwrap_or_else(|| panic!("{line}: {report}"));
        let max_total: f64 = row
            .split('%')
            .next()
            .and_then(|s| s.split_whitespace().last())
            .and_then(|s| s.parse().ok())
            .unwrap_or_else(|| panic!("{row}"));
        let ours = (0..full().len())
            .map(|p| g.hemispherical(side, p).unwrap())
            .fold(0.0, f64::max);
        assert!((max_total - 100.0 * ours).abs() < 0.3, "{row}: ours {ours}");
    }

    // The room: ours with our XML, rtrace with theirs.
    let room = box_room(Path::new("blind.xml"));
    for dir in [our_dir.path(), their_dir.path()] {
        std::fs::write(dir.join("room.rad"), &room).unwrap();
    }
    let effort = Effort {
        rtrace_args: &[
            "-h", "-I", "-u+", "-ab", "8", "-aa", "0", "-ad", "128", "-as", "0", "-lw", "1e-5",
            "-lr", "-16", "-st", "0",
        ],
        rtrace_samples: 768,
        our_samples: 262_144,
        our_bounces: 8,
        k_sigma: 4.0,
    };
    let skies: [(&str, &[&str]); 2] = [
        ("overcast", &["-ang", "45", "0", "-c", "-B", "55.8"]),
        ("sun-steep", &["-ang", "60", "0", "+s"]),
    ];
    for (label, args) in skies {
        compare_with_rtrace_from(
            &format!("genbsdf-blind-{label}"),
            &[PathBuf::from("room.rad")],
            &sky(&bin, &lib, "gensky", args),
            BOX_SENSORS.as_bytes(),
            their_dir.path(),
            our_dir.path(),
            // rtrace reads the XML when it runs, from its working folder.
            their_dir.path(),
            &effort,
            Some(0.03),
        );
    }
}

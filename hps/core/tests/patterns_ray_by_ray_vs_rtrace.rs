//! Patterns against RADIANCE run live, ray by ray: rays straight down onto a floor lit by a
//! distant source, rtrace at `-ab 0` giving each ray's radiance without noise.
//!
//! - `colorpict`: a real picture (RADIANCE's `flower.hdr` from its test renders, 525 x 525 with
//!   an `EXPOSURE=` line) on the floor, and a reduced copy with non-square pixels (`pfilt -p`, a
//!   `PIXASPECT=` line) under a transform; ours must agree ray by ray to 1e-3 (the mean of 64
//!   samples of the sun's disc): the picture's placement (smaller side 1, first pixel at 0,
//!   last at the size, y major), its stored values (exposure not removed), the interpolation
//!   and its extrapolation past the picture's edge, the functions of the three channels;
//! - `mixpict`: two plastics mixed by the picture;
//! - a pattern mixture (a `mixfunc` of a picture and stripes) under an alias;
//! - a patterned pane of `glass` between the sun and the floor;
//! - the text patterns (`brighttext`, `colortext`, `mixtext`) in a font of our own
//!   (`tests/fixtures/text/block.fnt`): inline words and a text file found on RAYPATH,
//!   uniform, proportional and squeezed spacing, a mixture of two plastics, under `!xform`.

mod common;

use common::corpus::corpus;
use common::radiance::{check_output, radiance_or_skip, tool};
use glam::DVec3;
use skylux_hps::engine::radiance::ray_radiance;
use skylux_hps::engine::ray::Ray;
use skylux_hps::engine::rng::Rng;
use skylux_hps::engine::{Settings, World};
use skylux_hps::scene;

/// Our estimates per ray (see `compare`).
const ESTIMATES: usize = 64;

/// Channel functions and coordinates (our own file): u runs past 1 at the floor's far end
/// (extrapolated, then tapered, as data.c does).
const PICT_CAL: &str = "{ pict.cal }
r3(r, g, b) = r;
g3(r, g, b) = 0.5 * g + 0.1 * b;
b3(r, g, b) = b;
u = Px / 3 - 0.1;
v = Py / 3 - 0.05;
";

fn scene_text(picture: &std::path::Path, transform: &str) -> String {
    let words = 7 + transform.split_whitespace().count();
    format!(
        "void light sunlight 0 0 3 2e4 2e4 2e4\n\
         sunlight source sun 0 0 4 0.1 0.2 1 0.5\n\
         void colorpict pat {words} r3 g3 b3 {} pict.cal u v {transform}\n0\n0\n\
         pat plastic floor_mat 0 0 5 0.6 0.6 0.6 0 0\n\
         floor_mat polygon floor 0 0 12 0 0 0 4 0 0 4 3 0 0 3 0\n",
        picture.display()
    )
}

/// Rays straight down onto a grid of the floor.
fn rays() -> Vec<Ray> {
    let mut out = Vec::new();
    for j in 0..23 {
        for i in 0..31 {
            let origin = DVec3::new(0.03 + 0.13 * f64::from(i), 0.04 + 0.13 * f64::from(j), 1.0);
            out.push(Ray::new(origin, DVec3::new(0.0, 0.0, -1.0)));
        }
    }
    out
}

fn compare(
    dir: &std::path::Path,
    picture: &std::path::Path,
    transform: &str,
    bin: &std::path::Path,
    lib: &Option<std::path::PathBuf>,
) {
    let what = format!("{} {transform:?}", picture.display());
    compare_scene(dir, &scene_text(picture, transform), &what, bin, lib);
}

/// Our radiance along every ray of [`rays`] (the mean of [`ESTIMATES`]) against rtrace
/// `-ab 0` on the same scene text, ray by ray within 1e-3.
fn compare_scene(
    dir: &std::path::Path,
    text: &str,
    what: &str,
    bin: &std::path::Path,
    lib: &Option<std::path::PathBuf>,
) -> Vec<DVec3> {
    compare_scene_from(dir, text, what, 1.0, bin, lib)
}

/// [`compare_scene`] with the rays starting at `height_m` above the floor.
fn compare_scene_from(
    dir: &std::path::Path,
    text: &str,
    what: &str,
    height_m: f64,
    bin: &std::path::Path,
    lib: &Option<std::path::PathBuf>,
) -> Vec<DVec3> {
    let scene_path = dir.join("scene.rad");
    std::fs::write(&scene_path, text).unwrap();
    let world = World::new(&scene::load_files(&[&scene_path]).unwrap()).unwrap();
    let settings = Settings {
        ambient_bounces: 0,
        seed: 3,
        ..Settings::default()
    };
    let rays: Vec<Ray> = rays()
        .into_iter()
        .map(|r| {
            Ray::new(
                DVec3::new(r.origin_m.x, r.origin_m.y, height_m),
                r.direction,
            )
        })
        .collect();
    let theirs = rtrace_along(dir, &rays, bin, lib);
    assert_eq!(theirs.len(), rays.len());
    let (mut worst, mut sum) = (0.0f64, DVec3::ZERO);
    for (k, (ray, want)) in rays.iter().zip(&theirs).enumerate() {
        // The sun's disc is sampled: its cosine varies by ±1e-3 over the disc here (0.25°
        // at 12.6° incidence), so each ray takes the mean of 64 directions.
        let got = (0..ESTIMATES)
            .map(|e| {
                let mut rng = Rng::for_stream(3, (k * ESTIMATES + e) as u64);
                ray_radiance(&world, *ray, &settings, &mut rng)
            })
            .sum::<DVec3>()
            / ESTIMATES as f64;
        let scale = want.max_element().max(1e-3);
        let err = (got - *want).abs().max_element() / scale;
        worst = worst.max(err);
        sum += *want;
        assert!(
            err < 1e-3,
            "{what}: ray {k} at {:?}: ours {got:?}, rtrace {want:?}",
            ray.origin_m
        );
    }
    println!(
        "{what}: {} rays, worst relative difference {worst:.1e}, mean rtrace {:?}",
        rays.len(),
        sum / rays.len() as f64
    );
    // The picture varies over the floor (the comparison is not of a constant).
    let spread = theirs.iter().map(|c| c.x).fold(f64::MIN, f64::max)
        - theirs.iter().map(|c| c.x).fold(f64::MAX, f64::min);
    assert!(spread > 0.1 * (sum.x / rays.len() as f64), "a flat picture");
    theirs
}

#[test]
fn colorpict_matches_rtrace_ray_by_ray() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let flower = corpus().join("radiance-test-renders/test/renders/flower.hdr");
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("pict.cal"), PICT_CAL).unwrap();
    compare(dir.path(), &flower, "", &bin, &lib);
    // Non-square pixels, and a non-square picture, under a transform of the pattern.
    let mut pfilt = tool(&bin, &lib, "pfilt");
    pfilt
        .args(["-1", "-x", "60", "-y", "40", "-p", "1.5"])
        .arg(&flower);
    let wide = dir.path().join("wide.hdr");
    std::fs::write(&wide, check_output(pfilt, None)).unwrap();
    let header = std::fs::read(&wide).unwrap();
    assert!(
        String::from_utf8_lossy(&header[..400.min(header.len())]).contains("PIXASPECT"),
        "pfilt -p wrote no PIXASPECT line"
    );
    compare(dir.path(), &wide, "-rz 10 -s 1.5 -t 0.3 0.2 0", &bin, &lib);
}

/// `mixpict`: the floor a mixture of two plastics by a function of the picture's (r, g, b).
/// rtrace weights both sides by the coefficient; we choose a side with its probability, so
/// each ray's mean over [`MIX_ESTIMATES`] paths is compared within 4.5 standard errors (of
/// that choice), and the mean over all rays of the standardised differences within 4/√n.
#[test]
fn mixpict_matches_rtrace() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    const MIX_ESTIMATES: usize = 256;
    let flower = corpus().join("radiance-test-renders/test/renders/flower.hdr");
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("mix.cal"),
        "mixc(r, g, b) = if(1 - 8 * (r + g + b), 8 * (r + g + b), 1);\nu = Px / 4;\nv = Py / 3;\n",
    )
    .unwrap();
    let scene_path = dir.path().join("scene.rad");
    std::fs::write(
        &scene_path,
        format!(
            "void light sunlight 0 0 3 2e4 2e4 2e4\n\
             sunlight source sun 0 0 4 0.1 0.2 1 0.5\n\
             void plastic red_paint 0 0 5 0.8 0.2 0.2 0 0\n\
             void plastic blue_paint 0 0 5 0.2 0.2 0.8 0 0\n\
             void mixpict floor_mat 7 red_paint blue_paint mixc {} mix.cal u v\n0\n0\n\
             floor_mat polygon floor 0 0 12 0 0 0 4 0 0 4 3 0 0 3 0\n",
            flower.display()
        ),
    )
    .unwrap();
    let world = World::new(&scene::load_files(&[&scene_path]).unwrap()).unwrap();
    let settings = Settings {
        ambient_bounces: 0,
        seed: 5,
        ..Settings::default()
    };
    let rays: Vec<Ray> = rays().into_iter().step_by(7).collect();
    let theirs = rtrace_along(dir.path(), &rays, &bin, &lib);
    // Each side alone, for the spread of a single choice: red and blue plastics.
    let side = |rho: DVec3| rho * 2e4 * 5.9808e-5 * (1.0 / 1.05f64.sqrt()) / std::f64::consts::PI;
    let (fore, back) = (
        side(DVec3::new(0.8, 0.2, 0.2)),
        side(DVec3::new(0.2, 0.2, 0.8)),
    );
    let (mut z_sum, mut mixed) = (0.0, 0);
    assert_eq!(theirs.len(), rays.len());
    for (k, (ray, &want)) in rays.iter().zip(&theirs).enumerate() {
        // rtrace's coefficient, from its red channel (the sides differ there).
        let c = ((want.x - back.x) / (fore.x - back.x)).clamp(0.0, 1.0);
        let got = (0..MIX_ESTIMATES)
            .map(|e| {
                let mut rng = Rng::for_stream(5, (k * MIX_ESTIMATES + e) as u64);
                ray_radiance(&world, *ray, &settings, &mut rng)
            })
            .sum::<DVec3>()
            / MIX_ESTIMATES as f64;
        let se = (fore.x - back.x).abs() * (c * (1.0 - c) / MIX_ESTIMATES as f64).sqrt();
        let allowed = 4.5 * se + 2e-3 * want.x;
        assert!(
            (got.x - want.x).abs() <= allowed && (got.y - want.y).abs() <= 1e-3 * want.y,
            "ray {k}: ours {got:?}, rtrace {want:?} (coefficient {c:.3}, SE {se:.2e})"
        );
        if se > 0.0 {
            z_sum += (got.x - want.x) / se;
            mixed += 1;
        }
    }
    let z_mean = z_sum / f64::from(mixed);
    println!(
        "mixpict: {} rays, {mixed} mixed, mean z {z_mean:+.2}",
        rays.len()
    );
    assert!(
        mixed >= 20,
        "too few rays with a mixed coefficient: {mixed}"
    );
    assert!(
        z_mean.abs() <= 4.0 / f64::from(mixed).sqrt(),
        "mean z {z_mean}"
    );
}

/// A pattern mixture (raytrace.c `raymixture`: a `mixfunc` of two patterns is a pattern
/// blending their colours), under an alias that gives a plastic that modifier, as RADIANCE's
/// own virtual office frames its pictures (furniture.rad): the flower inside a frame, faded
/// stripes outside it.
#[test]
fn pattern_mixtures_match_rtrace() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let flower = corpus().join("radiance-test-renders/test/renders/flower.hdr");
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("pict.cal"),
        format!(
            "{PICT_CAL}stripe = 0.5 + 0.4 * sin(8 * Px);\n\
             frame = if(Px - 0.5, if(3.5 - Px, if(Py - 0.5, if(2.5 - Py, 1, 0.3), 0.3), 0.3), 0.3) \
             * (0.5 + 0.2 * Py);\n"
        ),
    )
    .unwrap();
    let text = format!(
        "void light sunlight 0 0 3 2e4 2e4 2e4\n\
         sunlight source sun 0 0 4 0.1 0.2 1 0.5\n\
         void colorpict pat 7 r3 g3 b3 {} pict.cal u v\n0\n0\n\
         void brightfunc stripes 2 stripe pict.cal\n0\n0\n\
         void mixfunc framed 4 pat stripes frame pict.cal\n0\n0\n\
         void plastic paper 0 0 5 0.6 0.6 0.6 0 0\n\
         framed alias framed_paper paper\n\
         framed_paper polygon floor 0 0 12 0 0 0 4 0 0 4 3 0 0 3 0\n",
        flower.display()
    );
    compare_scene(dir.path(), &text, "pattern mixture", &bin, &lib);
}

/// A pane of `glass` under a `colorfunc` (different in each channel) between the sun and
/// the floor: the floor's direct light is the sun through the pane, whose transmissivity the
/// pattern scales (m_glass.c). The pattern varies slowly, so that the sun's disc (sampled by
/// us, aimed at its centre by rtrace) crosses the pane where it differs by under 0.15 %
/// (the mean of 64 samples of the disc then well within 1e-3).
#[test]
fn patterned_glass_matches_rtrace() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("pane.cal"),
        "pr = 0.6 + 0.2 * sin(0.7 * Px);\npg = 0.7 + 0.15 * cos(0.6 * Py);\npb = 0.5 + 0.1 * Px / 4;\n",
    )
    .unwrap();
    let text = "void light sunlight 0 0 3 2e4 2e4 2e4\n\
         sunlight source sun 0 0 4 0.1 0.2 1 0.5\n\
         void colorfunc tint 4 pr pg pb pane.cal\n0\n0\n\
         tint glass pane_glass 0 0 3 0.9 0.9 0.9\n\
         pane_glass polygon pane 0 0 12 -2 -2 1.5 6 -2 1.5 6 5 1.5 -2 5 1.5\n\
         void plastic grey 0 0 5 0.6 0.6 0.6 0 0\n\
         grey polygon floor 0 0 12 0 0 0 4 0 0 4 3 0 0 3 0\n";
    // Rays start between the pane and the floor.
    compare_scene_from(dir.path(), text, "patterned glass", 1.0, &bin, &lib);
}

/// A pane of `glass` under a `texfunc` ripple, seen from above against a floor whose colour
/// changes along x and y: glass.c bends the view ray's transmitted child by 2 (1 − n) pert,
/// so it lands elsewhere on the floor, and takes the Fresnel terms at the perturbed normal
/// for the view ray and for the sun's shadow rays (which go straight). The pane's choice
/// between transmission and reflection is sampled by us, traced both ways by rtrace, so
/// each ray is judged against our own standard error (4.5σ, 1024 estimates a ray) and the
/// mean of all rays within 0.3 %; and the texture must move rtrace's values, or the test
/// would not see it.
#[test]
fn textured_glass_matches_rtrace() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("ripple.cal"),
        "dx = 0.06 * sin(2.5 * Px);\ndy = 0.05 * cos(1.7 * Py);\ndz = 0;\nflat = 0;\n",
    )
    .unwrap();
    write_floor_stripes(dir.path());
    // The pane facing up, then down (its back towards the eye: flipsurface turns pert).
    for pane in [
        "-2 -2 1.5 6 -2 1.5 6 5 1.5 -2 5 1.5",
        "-2 5 1.5 6 5 1.5 6 -2 1.5 -2 -2 1.5",
    ] {
        let scene = |texture: &str| {
            format!(
                "void light sunlight 0 0 3 2e4 2e4 2e4\n\
             sunlight source sun 0 0 4 0.1 0.2 1 0.5\n\
             {texture}\
             ripple glass pane_glass 0 0 3 0.9 0.9 0.9\n\
             pane_glass polygon pane 0 0 12 {pane}\n\
             void colorfunc stripes 4 fr fg fb floor.cal\n0\n0\n\
             stripes plastic grey 0 0 5 0.6 0.6 0.6 0 0\n\
             grey polygon floor 0 0 12 0 0 0 4 0 0 4 3 0 0 3 0\n"
            )
        };
        let textured = scene("void texfunc ripple 4 dx dy dz ripple.cal\n0\n0\n");
        let untextured = scene("void texfunc ripple 4 flat flat flat ripple.cal\n0\n0\n");
        let rays: Vec<Ray> = rays()
            .into_iter()
            .map(|r| Ray::new(DVec3::new(r.origin_m.x, r.origin_m.y, 2.5), r.direction))
            .collect();
        std::fs::write(dir.path().join("scene.rad"), &untextured).unwrap();
        let straight = rtrace_along(dir.path(), &rays, &bin, &lib);
        std::fs::write(dir.path().join("scene.rad"), &textured).unwrap();
        let theirs = rtrace_along(dir.path(), &rays, &bin, &lib);
        let moved = moved_by_the_texture(&theirs, &straight);

        let world =
            World::new(&scene::load_files(&[dir.path().join("scene.rad")]).unwrap()).unwrap();
        let settings = Settings {
            ambient_bounces: 0,
            seed: 5,
            ..Settings::default()
        };
        const N: usize = 1024;
        let (mut ours_sum, mut theirs_sum, mut worst_z) = (0.0, 0.0, 0.0f64);
        for (k, (ray, want)) in rays.iter().zip(&theirs).enumerate() {
            let (mut sum, mut sum2) = (DVec3::ZERO, DVec3::ZERO);
            for e in 0..N {
                let mut rng = Rng::for_stream(5, (k * N + e) as u64);
                let v = ray_radiance(&world, *ray, &settings, &mut rng);
                sum += v;
                sum2 += v * v;
            }
            let mean = sum / N as f64;
            let var = (sum2 / N as f64 - mean * mean).max(DVec3::ZERO) / (N as f64 - 1.0);
            let se = DVec3::new(var.x.sqrt(), var.y.sqrt(), var.z.sqrt());
            for c in 0..3 {
                let z = (mean[c] - want[c]).abs() / (se[c] + 1e-3 * want[c].abs() + 1e-9);
                worst_z = worst_z.max(z);
                assert!(
                    z < 4.5,
                    "ray {k} at {:?}, channel {c}: ours {} ± {}, rtrace {}",
                    ray.origin_m,
                    mean[c],
                    se[c],
                    want[c]
                );
            }
            ours_sum += mean.x + mean.y + mean.z;
            theirs_sum += want.x + want.y + want.z;
        }
        println!(
        "textured glass ({pane}): {} rays, worst {worst_z:.2} standard errors, mean ratio {:.5}; the texture moved {moved} rays by over 5 %",
        rays.len(),
        ours_sum / theirs_sum
    );
        assert!((ours_sum / theirs_sum - 1.0).abs() < 3e-3);
    }
}

/// A `mirror` under a `texfunc` ripple over a floor that glows in stripes (a `colorfunc`
/// on a `glow`): rays from below meet the mirror's face, m_mirror reflects them about the
/// perturbed normal (about its own where that would go through it) and they land on the
/// floor elsewhere than a flat mirror sends them. Everything here is specular and
/// deterministic, so each ray within 1e-3 of rtrace `-ab 0`; the ripple must move rtrace's
/// values.
#[test]
fn textured_mirror_matches_rtrace() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("ripple.cal"),
        "dx = 0.08 * sin(2.5 * Px);\ndy = 0.06 * cos(1.7 * Py);\ndz = 0;\nflat = 0;\n",
    )
    .unwrap();
    write_floor_stripes(dir.path());
    let scene = |texture: &str| {
        format!(
            "{texture}\
             ripple mirror silver 0 0 3 0.9 0.8 0.7\n\
             silver polygon mirror 0 0 12 -2 5 1.5 6 5 1.5 6 -2 1.5 -2 -2 1.5\n\
             void colorfunc stripes 4 fr fg fb floor.cal\n0\n0\n\
             stripes glow floor_glow 0 0 4 10 10 10 0\n\
             floor_glow polygon floor 0 0 12 -1 -1 0 5 -1 0 5 4 0 -1 4 0\n"
        )
    };
    let rays: Vec<Ray> = rays()
        .into_iter()
        .map(|r| {
            Ray::new(
                DVec3::new(r.origin_m.x, r.origin_m.y, 1.0),
                DVec3::new(0.0, 0.1, 1.0).normalize(),
            )
        })
        .collect();
    std::fs::write(
        dir.path().join("scene.rad"),
        scene("void texfunc ripple 4 flat flat flat ripple.cal\n0\n0\n"),
    )
    .unwrap();
    let straight = rtrace_along(dir.path(), &rays, &bin, &lib);
    std::fs::write(
        dir.path().join("scene.rad"),
        scene("void texfunc ripple 4 dx dy dz ripple.cal\n0\n0\n"),
    )
    .unwrap();
    let theirs = rtrace_along(dir.path(), &rays, &bin, &lib);
    let moved = moved_by_the_texture(&theirs, &straight);
    let scene = scene::load_files_with(
        &[dir.path().join("scene.rad")],
        &scene::LoadOptions {
            working_directory: Some(dir.path().to_path_buf()),
            ..Default::default()
        },
    )
    .unwrap();
    let world = World::new(&scene).unwrap();
    let settings = Settings {
        ambient_bounces: 0,
        ..Settings::default()
    };
    let mut worst = 0.0f64;
    for (k, (ray, want)) in rays.iter().zip(&theirs).enumerate() {
        let got = ray_radiance(&world, *ray, &settings, &mut Rng::for_stream(1, k as u64));
        let err = (got - *want).abs().max_element() / want.max_element().max(1e-3);
        worst = worst.max(err);
        assert!(
            err < 1e-3,
            "ray {k} at {:?}: ours {got:?}, rtrace {want:?}",
            ray.origin_m
        );
    }
    println!(
        "textured mirror: {} rays, worst {worst:.1e}; the ripple moved {moved}",
        rays.len()
    );
}

/// A texture above a `mixfunc` of two materials (as `!genrev ... -s` writes one over the
/// modifier it is given: RADIANCE's test render `torus.rad` has its smoothing texture over a
/// `mixfunc` of a metal and a glow): both sides take the perturbed normal, and a pattern
/// above colours both. The sides alternate in stripes (a coefficient of 1 or 0, so rtrace
/// traces one side and we choose it for sure); ray by ray within 1e-3 of rtrace, and the
/// texture changes at least a quarter of rtrace's rays.
#[test]
fn texture_above_a_material_mixfunc_matches_rtrace() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("ripple.cal"),
        "dx = 0.3 * sin(2.5 * Px);\ndy = 0.2 * cos(1.7 * Py);\ndz = 0;\nflat = 0;\n\
         tint = 0.7 + 0.3 * cos(2 * Px + Py);\n",
    )
    .unwrap();
    let scene = |dx: &str| {
        format!(
            "void light sunlight 0 0 3 2e4 2e4 2e4\n\
             sunlight source sun 0 0 4 0.3 0.2 1 0.5\n\
             void plastic red 0 0 5 0.7 0.2 0.1 0 0\n\
             void plastic blue 0 0 5 0.1 0.3 0.7 0 0\n\
             void mixfunc striped 4 red blue if(sin(3*Px),1,0) .\n0\n0\n\
             striped texfunc ripple 4 {dx} ripple.cal\n0\n0\n\
             ripple brightfunc tinted 2 tint ripple.cal\n0\n0\n\
             tinted polygon floor 0 0 12 0 0 0 4 0 0 4 3 0 0 3 0\n"
        )
    };
    std::fs::write(dir.path().join("scene.rad"), scene("flat flat flat")).unwrap();
    let straight = rtrace_along(dir.path(), &rays(), &bin, &lib);
    let theirs = compare_scene(
        dir.path(),
        &scene("dx dy dz"),
        "a texture and a pattern above a mixfunc of two plastics",
        &bin,
        &lib,
    );
    moved_by_the_texture(&theirs, &straight);
}

/// `floor.cal`: stripes of colour along x and y, so a ray that lands elsewhere reads
/// otherwise.
fn write_floor_stripes(dir: &std::path::Path) {
    std::fs::write(
        dir.join("floor.cal"),
        "fr = 0.5 + 0.4 * sin(3 * Px);\nfg = 0.5 + 0.4 * cos(2.5 * Py);\nfb = 0.5;\n",
    )
    .unwrap();
}

/// How many of rtrace's rays a texture changed by over 5 % (`straight`: without it); at
/// least a quarter, or the comparison would not see the texture.
fn moved_by_the_texture(textured: &[DVec3], straight: &[DVec3]) -> usize {
    let moved = textured
        .iter()
        .zip(straight)
        .filter(|(t, s)| (**t - **s).abs().max_element() > 0.05 * s.max_element())
        .count();
    assert!(
        moved > textured.len() / 4,
        "the texture moved only {moved} rays"
    );
    moved
}

/// Our test font (written for these tests, RADIANCE's `.fnt` format) and a three-line text
/// file: glyphs the font lacks (`?`), spaces, a run of three spaces (an indent for
/// proportional spacing), a glyph with a hole (`O`) and a narrow one (`.`).
fn text_fixtures(dir: &std::path::Path) -> std::path::PathBuf {
    let fixtures = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/text");
    for name in ["block.fnt", "label.txt"] {
        std::fs::copy(fixtures.join(name), dir.join(name)).unwrap();
    }
    fixtures.join("block.fnt")
}

/// Floor and sun for the text patterns: `label` modifies the plastic `paper` (or is the
/// floor's material when `label_is_material`).
fn text_scene(pattern: &str, label_is_material: bool) -> String {
    let floor = if label_is_material {
        "label polygon floor 0 0 12 0 0 0 4 0 0 4 3 0 0 3 0\n"
    } else {
        "label plastic paper 0 0 5 0.6 0.6 0.6 0 0\n\
         paper polygon floor 0 0 12 0 0 0 4 0 0 4 3 0 0 3 0\n"
    };
    format!(
        "void light sunlight 0 0 3 2e4 2e4 2e4\n\
         sunlight source sun 0 0 4 0.1 0.2 1 0.5\n\
         {pattern}{floor}"
    )
}

/// How many of rtrace's values are near `low` and near `high` in red (each ray is one or the
/// other on a text pattern): both must be well represented for the comparison to test the
/// glyphs and the background.
fn foreground_and_background(theirs: &[DVec3], low: f64, high: f64) -> (usize, usize) {
    let near = |v: f64, target: f64| (v - target).abs() <= 2e-3 * target.abs().max(1e-9);
    (
        theirs.iter().filter(|c| near(c.x, high)).count(),
        theirs.iter().filter(|c| near(c.x, low)).count(),
    )
}

/// The radiance of the 0.6 plastic (red) under the sun, times `scale`: rtrace's direct
/// term, as [`mixpict_matches_rtrace`] computes a side.
fn paper(scale: f64) -> f64 {
    scale * 0.6 * 2e4 * 5.9808e-5 * (1.0 / 1.05f64.sqrt()) / std::f64::consts::PI
}

/// `brighttext` with inline words (the font named by its absolute path) and with the text
/// file (found through RAYPATH, with proportional spacing): rays inside glyph strokes, in
/// the holes and gaps between glyphs, and outside the text's box, ray by ray against rtrace.
#[test]
fn brighttext_matches_rtrace_ray_by_ray() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let font = text_fixtures(dir.path());
    let inline = format!(
        "void brighttext label 5 {} . SKY LUX OK?\n0\n\
         11 0.2 2.8 0  0.4 0 0  0 -1.3 0  1 0.25\n",
        font.display()
    );
    let theirs = compare_scene(
        dir.path(),
        &text_scene(&inline, false),
        "brighttext inline",
        &bin,
        &lib,
    );
    let (inside, outside) = foreground_and_background(&theirs, paper(0.25), paper(1.0));
    println!("brighttext inline: {inside} rays in glyphs, {outside} elsewhere");
    assert!(inside >= 40 && outside >= 300, "{inside} in, {outside} out");
    assert_eq!(inside + outside, theirs.len());
    // The text file, three lines, proportional spacing 0.15 (a slanted down vector).
    let file = "void brighttext label 2 block.fnt label.txt\n0\n\
         12 0.1 2.9 0  0.5 0 0  0.1 -0.9 0  0.9 0.3 0.15\n";
    let theirs = compare_scene(
        dir.path(),
        &text_scene(file, false),
        "brighttext file, proportional",
        &bin,
        &lib,
    );
    let (inside, outside) = foreground_and_background(&theirs, paper(0.3), paper(0.9));
    println!("brighttext file: {inside} rays in glyphs, {outside} elsewhere");
    assert!(inside >= 60 && outside >= 200, "{inside} in, {outside} out");
    assert_eq!(inside + outside, theirs.len());
}

/// `colortext` with squeezed spacing, the whole floor moved by `!xform` (rotated, scaled and
/// translated: the anchor and the motion vectors go with it).
#[test]
fn colortext_under_xform_matches_rtrace_ray_by_ray() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    text_fixtures(dir.path());
    let label = "void colortext label 5 block.fnt . LUX XYLO. IS\n0\n\
         16 0.1 2.2 0  0.5 0 0  0 -1.2 0  0.9 0.5 0.2  0.2 0.4 0.7  -0.1\n";
    std::fs::write(dir.path().join("label.rad"), text_scene(label, false)).unwrap();
    let scene = "!xform -rz 12 -s 1.1 -t 0.3 -0.25 0 label.rad\n";
    let theirs = compare_scene(dir.path(), scene, "colortext squeezed, xform", &bin, &lib);
    // Red and blue change in opposite directions between glyph and background.
    let glyph = theirs.iter().filter(|c| c.x > 2.0 * c.z).count();
    let background = theirs.iter().filter(|c| c.z > 2.0 * c.x).count();
    println!("colortext: {glyph} rays in glyphs, {background} on the background");
    assert!(
        glyph >= 40 && background >= 200,
        "{glyph} in, {background} out"
    );
}

/// `mixtext` of two plastics (the text file, spacing given as 0: uniform cells whose width
/// is the font's mean glyph width, text.c's scale when the spacing argument is present),
/// and `mixtext` of two patterns over one plastic.
#[test]
fn mixtext_matches_rtrace_ray_by_ray() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    text_fixtures(dir.path());
    let materials = "void plastic red_paint 0 0 5 0.8 0.2 0.2 0 0\n\
         void plastic blue_paint 0 0 5 0.2 0.2 0.8 0 0\n\
         void mixtext label 4 red_paint blue_paint block.fnt label.txt\n0\n\
         10 0.15 2.8 0  0.6 0 0  0 -0.85 0  0\n";
    let theirs = compare_scene(
        dir.path(),
        &text_scene(materials, true),
        "mixtext of two plastics",
        &bin,
        &lib,
    );
    let red = theirs.iter().filter(|c| c.x > 2.0 * c.z).count();
    let blue = theirs.iter().filter(|c| c.z > 2.0 * c.x).count();
    println!("mixtext: {red} rays red (glyphs), {blue} blue");
    assert!(
        red >= 60 && blue >= 300 && red + blue == theirs.len(),
        "{red} red, {blue} blue"
    );
    let patterns = "void brightfunc dim 2 0.4 .\n0\n0\n\
         void colorfunc warm 4 1 0.7 0.4 .\n0\n0\n\
         void mixtext label 7 warm dim block.fnt . OK SKY XL\n0\n\
         9 0.3 2.4 0  0.55 0 0  0 -1 0\n";
    compare_scene(
        dir.path(),
        &text_scene(patterns, false),
        "mixtext of two patterns",
        &bin,
        &lib,
    );
}

/// rtrace's radiance along `rays` in `dir`'s `scene.rad`, at `-ab 0` and aimed at the
/// sources' centres (`-dj 0 -ds 0`): no noise.
fn rtrace_along(
    dir: &std::path::Path,
    rays: &[Ray],
    bin: &std::path::Path,
    lib: &Option<std::path::PathBuf>,
) -> Vec<DVec3> {
    let mut oconv = tool(bin, lib, "oconv");
    oconv.current_dir(dir).arg("scene.rad");
    std::fs::write(dir.join("scene.oct"), check_output(oconv, None)).unwrap();
    let input: String = rays
        .iter()
        .map(|r| {
            let (o, d) = (r.origin_m, r.direction);
            format!("{} {} {} {} {} {}\n", o.x, o.y, o.z, d.x, d.y, d.z)
        })
        .collect();
    let mut rtrace = tool(bin, lib, "rtrace");
    rtrace.current_dir(dir).args([
        "-h",
        "-ab",
        "0",
        "-av",
        "0",
        "0",
        "0",
        "-dj",
        "0",
        "-ds",
        "0",
        "scene.oct",
    ]);
    let out = String::from_utf8(check_output(rtrace, Some(input.as_bytes()))).unwrap();
    out.lines()
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|w| w.parse().unwrap()).collect();
            DVec3::new(v[0], v[1], v[2])
        })
        .collect()
}

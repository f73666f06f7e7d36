//! Rendering (`engine::render`): views against RADIANCE's `vwrays`, pixel values against
//! closed forms and against `rtrace` on the same rays, and the picture files against
//! RADIANCE's readers.
//!
//! RADIANCE comes from the `pyradiance` wheel (or `SKYLUX_RADIANCE_BIN`, or PATH); without it
//! the comparisons print SKIPPED and pass, unless `SKYLUX_REQUIRE_RADIANCE` is set.

use glam::DVec3;
use skylux_hps::engine::render::{self, RenderSettings, View, ViewError};
use skylux_hps::engine::{Settings, World};
use skylux_hps::glare::{self, GlareOptions, LuminanceImage};
use skylux_hps::picture::falsecolour::{
    write_falsecolour_png, ColourScale, FalsecolourOptions, LegendUnit,
};
use skylux_hps::picture::rgbe::{rgbe, write_hdr};
use skylux_hps::picture::{exr::write_exr, Picture};
use skylux_hps::scene;
use std::path::{Path, PathBuf};
mod common;
use common::radiance::{check_output, radiance, tool};

const ROOM: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../../shared/scenes/test-module"
);

fn radiance_or_skip() -> Option<(PathBuf, Option<PathBuf>)> {
    let found = radiance();
    skylux_hps::prerequisite::available_or_skip(
        found.is_some(),
        skylux_hps::prerequisite::REQUIRE_RADIANCE,
        "RADIANCE not found (pip install pyradiance)",
    );
    found
}

fn world_from(text: &str) -> (tempfile::TempDir, World) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.rad");
    std::fs::write(&path, text).unwrap();
    let scene = scene::load_files(&[&path]).unwrap();
    let world = World::new(&scene).unwrap();
    (dir, world)
}

fn settings(w: u32, h: u32, spp: u32, ab: u32) -> RenderSettings {
    RenderSettings {
        width_px: w,
        height_px: h,
        samples_per_pixel: spp,
        trace: Settings {
            ambient_bounces: ab,
            seed: 7,
            ..Settings::default()
        },
        filtered: false,
    }
}

/// Every pixel's direction (and origin) agrees with `vwrays` (double output, `-fd`) to 1e-6
/// for perspective, hemispherical and angular fisheye views, shifted and lifted, and our
/// square-pixel resolution equals vwrays' (`normaspect`).
#[test]
fn view_rays_match_vwrays() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let views = [
        "-vtv -vp 1 2 1.2 -vd 0.3 -1 0.1 -vu 0 0 1 -vh 60 -vv 45",
        "-vtv -vp 0 0 0 -vd 1 1 0 -vu 0 0 1 -vh 30 -vv 70 -vs 0.2 -vl -0.1 -vo 0.5",
        "-vth -vp 1 1 1 -vd 0 0 1 -vu 0 1 0 -vh 180 -vv 180",
        "-vth -vd 0 -1 0.2 -vh 150 -vv 120",
        "-vta -vp 0 0 1 -vd 0 0 1 -vu 0 1 0 -vh 180 -vv 180",
        "-vta -vd 1 0 0 -vh 270 -vv 200 -vs 0.1",
    ];
    for text in views {
        let view = View::parse(text).unwrap().prepare().unwrap();
        let (w, h) = view.fit_resolution(9, 7);
        let mut c = tool(&bin, &lib, "vwrays");
        c.arg("-d")
            .args(text.split_whitespace())
            .args(["-x", "9", "-y", "7"]);
        let res = String::from_utf8(check_output(c, None)).unwrap();
        assert_eq!(res.trim(), format!("-x {w} -y {h}"), "{text}");
        let mut c = tool(&bin, &lib, "vwrays");
        c.arg("-fd")
            .args(text.split_whitespace())
            .args(["-x", "9", "-y", "7"]);
        let bytes = check_output(c, None);
        let values: Vec<f64> = bytes
            .chunks_exact(8)
            .map(|b| f64::from_ne_bytes(b.try_into().unwrap()))
            .collect();
        assert_eq!(values.len(), (w * h * 6) as usize, "{text}");
        let mut outside = 0;
        for row in 0..h {
            for column in 0..w {
                let k = ((row * w + column) * 6) as usize;
                let origin = DVec3::new(values[k], values[k + 1], values[k + 2]);
                let dir = DVec3::new(values[k + 3], values[k + 4], values[k + 5]);
                match view.pixel_centre_ray(column, row, w, h) {
                    None => {
                        assert_eq!(
                            dir,
                            DVec3::ZERO,
                            "{text} ({column},{row}): vwrays has a ray"
                        );
                        outside += 1;
                    }
                    Some(ray) => {
                        assert!(
                            (ray.direction - dir).abs().max_element() < 1e-6,
                            "{text} ({column},{row}): {} vs vwrays {dir}",
                            ray.direction
                        );
                        assert!(
                            (ray.origin_m - origin).abs().max_element() < 1e-6,
                            "{text} ({column},{row}): origin {} vs {origin}",
                            ray.origin_m
                        );
                    }
                }
            }
        }
        println!("{text}: {w}x{h}, {outside} pixels outside the fisheye");
    }
}

#[test]
fn bad_views_name_the_option() {
    let err = |s: &str| View::parse(s).unwrap_err();
    let msg = err("-vtv -vh sixty").to_string();
    assert!(msg.contains("-vh") && msg.contains("sixty"), "{msg}");
    let msg = err("-vtv -vp 1 2").to_string();
    assert!(msg.contains("-vp") && msg.contains("3 number"), "{msg}");
    let msg = err("-vtx").to_string();
    assert!(msg.contains("-vtx"), "{msg}");
    let msg = err("-vq 3").to_string();
    assert!(msg.contains("-vq"), "{msg}");
    assert!(matches!(err(""), ViewError::Option { .. }));
    // Parses, but setview refuses it.
    let msg = View::parse("-vtv -vh 180")
        .unwrap()
        .prepare()
        .unwrap_err()
        .to_string();
    assert!(msg.contains("horizontal view size"), "{msg}");
    let msg = View::parse("-vd 0 0 1 -vu 0 0 2")
        .unwrap()
        .prepare()
        .unwrap_err()
        .to_string();
    assert!(msg.contains("parallel"), "{msg}");
    // A view file: a picture header's VIEW= line is read, a stray line is named by number.
    let dir = tempfile::tempdir().unwrap();
    let vf = dir.path().join("a.vf");
    std::fs::write(&vf, "rvu -vtv -vp 1 2 3 -vd 0 1 0\n-vh 30\n").unwrap();
    let v = View::default().with_file(&vf).unwrap();
    assert_eq!(v.position_m, DVec3::new(1.0, 2.0, 3.0));
    assert_eq!(v.horizontal_deg, 30.0);
    std::fs::write(&vf, "-vtv\nnonsense here\n").unwrap();
    let msg = View::default().with_file(&vf).unwrap_err().to_string();
    assert!(msg.contains("a.vf:2"), "{msg}");
}

/// A camera looking down at a large Lambertian plane of reflectance ρ under a uniform glow
/// sky of radiance L sees ρ L in every pixel (-ab 1): every cosine-sampled path from the
/// plane escapes to the sky, so each estimate is exact. With a sun instead (-ab 0), every
/// pixel sees ρ/π · Ls Ω cos θ; and a narrow view aimed at the sun sees the sun's radiance.
#[test]
fn closed_forms_on_a_plane() {
    let rho = DVec3::new(0.2, 0.5, 0.8);
    let l_sky = 3.0;
    let plane = format!(
        "void plastic ground_mat 0 0 5 {} {} {} 0 0\n\
         ground_mat polygon plane 0 0 12 -1000 -1000 0 1000 -1000 0 1000 1000 0 -1000 1000 0\n",
        rho.x, rho.y, rho.z
    );
    let sky = format!(
        "void glow sky_glow 0 0 4 {l_sky} {l_sky} {l_sky} 0\nsky_glow source sky 0 0 4 0 0 1 180\n"
    );
    let (_d, world) = world_from(&format!("{plane}{sky}"));
    for (view, filtered) in [
        ("-vtv -vp 0 0 1 -vd 0 0 -1 -vu 0 1 0 -vh 60 -vv 60", false),
        ("-vta -vp 0 0 1 -vd 0 0 -1 -vu 0 1 0 -vh 120 -vv 120", false),
        ("-vta -vp 0 0 1 -vd 0 0 -1 -vu 0 1 0 -vh 120 -vv 120", true),
    ] {
        let v = View::parse(view).unwrap().prepare().unwrap();
        let s = RenderSettings {
            filtered,
            ..settings(12, 12, 64, 1)
        };
        let image = render::render(&world, &v, &s, &|_, _| {}).unwrap();
        let expect = rho * l_sky;
        let lum = 179.0 * (0.265 * expect.x + 0.670 * expect.y + 0.065 * expect.z);
        let (mut seen, mut sum, mut var) = (0, 0.0, 0.0);
        for (i, c) in image.radiance_rgb.iter().enumerate() {
            if c.max_element() == 0.0 {
                continue; // outside the fisheye circle
            }
            seen += 1;
            let (l, se) = (image.luminance_cd_m2[i], image.luminance_stderr_cd_m2[i]);
            // The sky's next-event estimation makes single paths noisy, not biased.
            assert!(
                (l - lum).abs() <= 5.0 * se + 1e-9,
                "{view} pixel {i}: {l} ± {se} vs {lum}"
            );
            // Colour: every channel scales with ρ (the estimate's weights are grey).
            assert!(((*c / rho) / (*c / rho).x - DVec3::ONE).abs().max_element() < 1e-9);
            sum += l;
            var += se * se;
        }
        let mean = sum / f64::from(seen);
        let se = var.sqrt() / f64::from(seen);
        println!("{view}: mean {mean:.4} ± {se:.4} cd/m², closed form {lum:.4}");
        assert!((mean - lum).abs() <= 4.0 * se + 1e-9 && (mean - lum).abs() < 0.01 * lum);
        assert!(seen >= 100, "{view}: {seen} pixels");
    }

    // The sun at 40° elevation, 0.533° across, radiance 1e6 (gensky's order).
    let elevation = 40f64.to_radians();
    let sun_dir = DVec3::new(0.0, elevation.cos(), elevation.sin());
    let ls = 1.0e6;
    let sun = format!(
        "void light solar 0 0 3 {ls} {ls} {ls}\nsolar source sun 0 0 4 {} {} {} 0.533\n",
        sun_dir.x, sun_dir.y, sun_dir.z
    );
    let (_d2, world) = world_from(&format!("{plane}{sun}"));
    let v = View::parse("-vtv -vp 0 0 1 -vd 0 0 -1 -vu 0 1 0 -vh 40 -vv 40")
        .unwrap()
        .prepare()
        .unwrap();
    let image = render::render(&world, &v, &settings(8, 8, 16, 0), &|_, _| {}).unwrap();
    let half = (0.533f64 / 2.0).to_radians();
    let omega = 2.0 * std::f64::consts::PI * (1.0 - half.cos());
    // Mean of cos over the cone, to first order: cos θ (1 − δ²/4), δ the half angle.
    let expect = rho / std::f64::consts::PI * ls * omega * elevation.sin();
    // Sampling the 0.53° disc moves cos θ by up to ±0.6 %: each pixel (16 directions) is
    // within 0.3 %, the image's mean (1024) within 0.05 %.
    for c in &image.radiance_rgb {
        assert!(
            ((*c - expect) / expect).abs().max_element() < 3e-3,
            "{c} vs {expect}"
        );
    }
    let mean = image.radiance_rgb.iter().sum::<DVec3>() / image.radiance_rgb.len() as f64;
    println!("sun: mean {mean} vs closed form {expect}");
    assert!(((mean - expect) / expect).abs().max_element() < 5e-4);
    // Looking at the sun: a 0.1° view inside its 0.533° disc sees its radiance.
    let at_sun = View::parse(&format!(
        "-vtv -vp 0 0 1 -vd {} {} {} -vu 0 0 1 -vh 0.1 -vv 0.1",
        sun_dir.x, sun_dir.y, sun_dir.z
    ))
    .unwrap()
    .prepare()
    .unwrap();
    let image = render::render(&world, &at_sun, &settings(4, 4, 2, 0), &|_, _| {}).unwrap();
    for c in &image.radiance_rgb {
        assert!((*c - DVec3::splat(ls)).abs().max_element() < 1e-6, "{c}");
    }
}

/// The sun's disc in a fisheye is integrated over the pixels, not hit by chance: a 180°
/// fisheye's picture of a sun alone gives Ev = L Ω cos θ (its illuminance on the plane
/// facing the view) with one path per pixel, to within the picture's pixel, and through a glass
/// pane in front, that times the glass's transmission at the sun's incidence as rtrace's
/// shadow rays take it.
#[test]
fn sun_in_a_fisheye_gives_its_illuminance() {
    let elevation = 35f64.to_radians();
    let sun_dir = DVec3::new(0.3, elevation.cos(), elevation.sin()).normalize();
    let ls = 1.0e6;
    let sun = format!(
        "void light solar 0 0 3 {ls} {ls} {ls}\nsolar source sun 0 0 4 {} {} {} 0.533\n",
        sun_dir.x, sun_dir.y, sun_dir.z
    );
    let half = (0.533f64 / 2.0).to_radians();
    let omega = 2.0 * std::f64::consts::PI * (1.0 - half.cos());
    let view_dir = DVec3::Y;
    let expected_lux = 179.0 * ls * omega * sun_dir.dot(view_dir);
    let glass = "void glass pane 0 0 3 0.96 0.96 0.96\n\
                 pane polygon window 0 0 12 -50 5 -50 50 5 -50 50 5 50 -50 5 50\n";
    // The pane's transmission for the sun's incidence, as world.source_transmission takes it.
    let (_g, glazed) = world_from(&format!("{glass}{sun}"));
    let t = glazed
        .source_transmission(DVec3::new(0.0, 0.0, 1.2), None, sun_dir)
        .x;
    assert!(t > 0.5 && t < 0.96, "{t}");
    for (scene, factor) in [(sun.clone(), 1.0), (format!("{glass}{sun}"), t)] {
        let (_d, world) = world_from(&scene);
        let v = View::parse("-vta -vp 0 0 1.2 -vd 0 1 0 -vu 0 0 1 -vh 180 -vv 180")
            .unwrap()
            .prepare()
            .unwrap();
        for size in [64u32, 256, 512] {
            let image =
                render::render(&world, &v, &settings(size, size, 1, 0), &|_, _| {}).unwrap();
            let picture = LuminanceImage {
                width_px: size,
                height_px: size,
                view: v.view.clone(),
                luminance_cd_m2: image.luminance_cd_m2.clone(),
            };
            let ev = glare::evaluate(&picture, &GlareOptions::default())
                .unwrap()
                .ev_lux;
            let want = expected_lux * factor;
            println!("{size} px, transmission {factor:.4}: Ev {ev:.1} lx for {want:.1}");
            // A picture keeps where the sun is only to its pixel: the glare evaluation takes
            // the pixel's centre and solid angle, 2.8° across at 64 px (2 % here), 0.7° at
            // 256 px.
            let allowed = if size >= 256 { 5e-3 } else { 3e-2 };
            assert!(
                (ev / want - 1.0).abs() < allowed,
                "{size} px: {ev} vs {want}"
            );
        }
    }
}

/// The filter keeps the picture's light: a room under a sky, filtered and unfiltered at
/// the same paths per pixel (a view of the room's back, all Lambertian), has the same mean
/// luminance within the unfiltered image's standard error, and the filtered picture is much
/// closer pixel by pixel to a picture of 16 times the paths than the unfiltered one is
/// (its RMS relative error less than half).
#[test]
fn filtered_picture_keeps_the_mean_and_loses_the_grain() {
    let room = Path::new(ROOM).join("scene.rad");
    let dir = tempfile::tempdir().unwrap();
    let sky = dir.path().join("sky.rad");
    std::fs::write(
        &sky,
        "void glow sky_glow 0 0 4 1 1 1 0\nsky_glow source sky 0 0 4 0 0 1 180\n\
         void glow ground_glow 0 0 4 0.2 0.2 0.2 0\nground_glow source ground 0 0 4 0 0 -1 180\n",
    )
    .unwrap();
    let world = World::new(&scene::load_files(&[&room, &sky]).unwrap()).unwrap();
    let v = View::parse("-vtv -vp 1.45 1.5 1.2 -vd 0 1 -0.2 -vu 0 0 1 -vh 70 -vv 50")
        .unwrap()
        .prepare()
        .unwrap();
    let (w, h) = v.fit_resolution(96, 96);
    let at = |spp: u32, filtered: bool, seed: u64| {
        let mut s = RenderSettings {
            filtered,
            ..settings(w, h, spp, 5)
        };
        s.trace.seed = seed;
        render::render(&world, &v, &s, &|_, _| {}).unwrap()
    };
    let mean = |p: &Picture| p.luminance_cd_m2.iter().sum::<f64>() / p.luminance_cd_m2.len() as f64;
    let unfiltered = at(16, false, 1);
    let filtered = at(16, true, 2);
    let reference = at(256, false, 3);
    let n = unfiltered.luminance_cd_m2.len() as f64;
    let se = unfiltered
        .luminance_stderr_cd_m2
        .iter()
        .map(|s| s * s)
        .sum::<f64>()
        .sqrt()
        / n;
    let (mu, mf, mr) = (mean(&unfiltered), mean(&filtered), mean(&reference));
    println!("mean: unfiltered {mu:.3} ± {se:.3}, filtered {mf:.3}, 256 paths {mr:.3} cd/m²");
    assert!(
        (mf - mu).abs() <= 4.0 * se * std::f64::consts::SQRT_2,
        "{mf} vs {mu} ± {se}"
    );
    assert!((mf - mr).abs() <= 4.0 * se, "{mf} vs {mr} ± {se}");
    // The reference's own noise taken out: independent errors add in quadrature.
    let rms = |p: &Picture| {
        let s: f64 = p
            .luminance_cd_m2
            .iter()
            .zip(&reference.luminance_cd_m2)
            .zip(&reference.luminance_stderr_cd_m2)
            .filter(|((_, r), _)| **r > 0.0)
            .map(|((o, r), se)| ((o - r) / r).powi(2) - (se / r).powi(2))
            .sum();
        (s / n).max(0.0).sqrt()
    };
    let (ru, rf) = (rms(&unfiltered), rms(&filtered));
    println!(
        "RMS relative error against 256 paths, its noise out: unfiltered {ru:.3}, filtered {rf:.3}"
    );
    assert!(rf < 0.5 * ru, "filtered {rf} vs unfiltered {ru}");
}

/// The same seed gives the same image on one thread and on several.
#[test]
fn image_does_not_depend_on_threads() {
    let room = Path::new(ROOM).join("scene.rad");
    let dir = tempfile::tempdir().unwrap();
    let sky = dir.path().join("sky.rad");
    std::fs::write(
        &sky,
        "void glow sky_glow 0 0 4 1 1 1 0\nsky_glow source sky 0 0 4 0 0 1 180\n",
    )
    .unwrap();
    let world = World::new(&scene::load_files(&[&room, &sky]).unwrap()).unwrap();
    let v = View::parse("-vtv -vp 1.45 5.5 1.2 -vd 0 -1 0 -vh 60 -vv 45")
        .unwrap()
        .prepare()
        .unwrap();
    let s = settings(10, 8, 3, 2);
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| render::render(&world, &v, &s, &|_, _| {}).unwrap())
    };
    let one = run(1);
    let two = run(3);
    assert_eq!(one, two);
    assert!(one.luminance_cd_m2.iter().any(|l| *l > 0.0));
}

/// Block means of the reference room's image under a CIE clear sky with sun (gensky) against
/// rtrace on vwrays' rays for the same view: jittered rays (`-pj 1`), 4 per pixel (`-c 4`),
/// pure path tracing (`-ab 5 -aa 0 -ad 512 -lw 1e-4`). Each block's rtrace standard error is
/// from the spread of the 4 rays of each pixel; ours from each pixel's samples. Acceptance:
/// |ours − rtrace| <= max(3 % of rtrace, 3 × the combined standard error).
#[test]
fn room_image_agrees_with_rtrace() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let mut sky = check_output(
        {
            let mut c = tool(&bin, &lib, "gensky");
            c.args([
                "3", "21", "12", "+s", "-a", "46.5", "-o", "-6.6", "-m", "-15",
            ]);
            c
        },
        None,
    );
    sky.extend_from_slice(
        b"\nskyfunc glow sky_glow 0 0 4 1 1 1 0\nsky_glow source sky 0 0 4 0 0 1 180\n\
          skyfunc glow ground_glow 0 0 4 1 1 1 0\nground_glow source ground 0 0 4 0 0 -1 180\n",
    );
    let sky_path = dir.path().join("sky.rad");
    std::fs::write(&sky_path, &sky).unwrap();
    let room = Path::new(ROOM).join("scene.rad");
    let mut oconv = tool(&bin, &lib, "oconv");
    oconv.current_dir(dir.path()).arg(&room).arg(&sky_path);
    let octree = dir.path().join("room.oct");
    std::fs::write(&octree, check_output(oconv, None)).unwrap();

    let view_text = "-vtv -vp 1.45 5.5 1.2 -vd 0 -1 -0.15 -vu 0 0 1 -vh 60 -vv 45";
    let view = View::parse(view_text).unwrap().prepare().unwrap();
    let (w, h) = view.fit_resolution(32, 32);
    const REPEATS: usize = 4;
    let mut vwrays = tool(&bin, &lib, "vwrays");
    vwrays
        .args(["-ff", "-pj", "1", "-c", &REPEATS.to_string()])
        .args(view_text.split_whitespace())
        .args(["-x", "32", "-y", "32"]);
    let rays = check_output(vwrays, None);
    let rays_path = dir.path().join("view.rays");
    std::fs::write(&rays_path, &rays).unwrap();
    let mut rtrace = tool(&bin, &lib, "rtrace");
    rtrace
        .current_dir(dir.path())
        .args([
            "-ff", "-h", "-ab", "5", "-aa", "0", "-ad", "512", "-as", "0", "-lw", "1e-4",
        ])
        .arg(&octree)
        .stdin(std::fs::File::open(&rays_path).unwrap());
    let start = std::time::Instant::now();
    let out = rtrace.output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let rtrace_s = start.elapsed().as_secs_f64();
    let values: Vec<f32> = out
        .stdout
        .chunks_exact(4)
        .map(|b| f32::from_ne_bytes(b.try_into().unwrap()))
        .collect();
    assert_eq!(values.len(), (w * h) as usize * REPEATS * 3);
    // Per pixel: mean and variance of the mean over its repeats.
    let lum = |k: usize| {
        179.0
            * (0.265 * f64::from(values[3 * k])
                + 0.670 * f64::from(values[3 * k + 1])
                + 0.065 * f64::from(values[3 * k + 2]))
    };
    let reference: Vec<(f64, f64)> = (0..(w * h) as usize)
        .map(|p| {
            let xs: Vec<f64> = (0..REPEATS).map(|r| lum(p * REPEATS + r)).collect();
            let n = REPEATS as f64;
            let m = xs.iter().sum::<f64>() / n;
            let var = xs.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (n - 1.0);
            (m, var / n)
        })
        .collect();

    let world = World::new(&scene::load_files(&[&room, &sky_path]).unwrap()).unwrap();
    let mut failures = Vec::new();
    for filtered in [false, true] {
        let start = std::time::Instant::now();
        let s = RenderSettings {
            filtered,
            ..settings(w, h, 64, 5)
        };
        let image = render::render(&world, &view, &s, &|_, _| {}).unwrap();
        let ours_s = start.elapsed().as_secs_f64();
        println!("{w}x{h}: rtrace {REPEATS} rays/pixel in {rtrace_s:.1} s, ours 64 paths/pixel in {ours_s:.1} s (filtered: {filtered})");

        // 3 x 2 blocks tiling the image.
        let (bx, by) = (3u32, 2u32);
        for j in 0..by {
            for i in 0..bx {
                let (c0, c1) = (i * w / bx, (i + 1) * w / bx);
                let (r0, r1) = (j * h / by, (j + 1) * h / by);
                let (mut o, mut o_var, mut r, mut r_var, mut n) = (0.0, 0.0, 0.0, 0.0, 0.0);
                for row in r0..r1 {
                    for column in c0..c1 {
                        let k = image.index(column, row);
                        o += image.luminance_cd_m2[k];
                        o_var += image.luminance_stderr_cd_m2[k].powi(2);
                        r += reference[k].0;
                        r_var += reference[k].1;
                        n += 1.0;
                    }
                }
                let (o, r) = (o / n, r / n);
                let combined = (o_var + r_var).sqrt() / n;
                let allowed = (0.03 * r).max(3.0 * combined);
                println!(
                "  block ({i},{j}): ours {o:.2} cd/m², rtrace {r:.2} cd/m², diff {:+.2} % ({:+.2} σ)",
                100.0 * (o - r) / r,
                (o - r) / combined
            );
                if (o - r).abs() > allowed {
                    failures.push(format!(
                    "filtered {filtered}, block ({i},{j}): {o:.2} vs {r:.2} (allowed ±{allowed:.2})"
                ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures:?}");
}

/// An occupant's 180° fisheye in the LBNL tutorial room (the corpus's, loaded as its
/// authors load it): the Ev of our filtered picture at 4 paths per pixel against rtrace -I
/// at the eye (pure path tracing, 12 bounces, 32 independent estimates of 2048 paths), with
/// the sun in the window and under an overcast sky: within 1 %, the bound.
#[test]
fn fisheye_ev_agrees_with_rtrace_at_the_eye() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let room = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data/radiance-corpus/sariths-matrix-tutorial/room");
    let dir = tempfile::tempdir().unwrap();
    let glows = "skyfunc glow skyglow 0 0 4 1 1 1 0\nskyglow source sky 0 0 4 0 0 1 180\n\
                 skyfunc glow groundglow 0 0 4 1 1 1 0\n\
                 groundglow source ground 0 0 4 0 0 -1 180\n";
    let eye = "3.0 1.5 1.2 0 -1 0\n";
    let view = View::parse("-vta -vp 3.0 1.5 1.2 -vd 0 -1 0 -vu 0 0 1 -vh 180 -vv 180")
        .unwrap()
        .prepare()
        .unwrap();
    for (name, generator) in [
        (
            "sun in the window",
            "!gendaylit 12 21 10.5 -a 40.7 -o 74 -m 75 -W 750 60",
        ),
        (
            "overcast",
            "!gensky 12 21 10.5 -c -a 40.7 -o 74 -m 75 -B 40",
        ),
    ] {
        let sky = dir.path().join(format!("sky-{}.rad", name.len()));
        std::fs::write(&sky, format!("{generator}\n{glows}")).unwrap();
        let files = [
            room.join("materials.rad"),
            room.join("room.rad"),
            sky.clone(),
        ];
        let mut oconv = tool(&bin, &lib, "oconv");
        oconv.current_dir(&room).arg("-f").args(&files);
        let octree = dir.path().join(format!("room-{}.oct", name.len()));
        std::fs::write(&octree, check_output(oconv, None)).unwrap();
        let args = [
            "-h", "-I", "-u+", "-ab", "12", "-aa", "0", "-ad", "2048", "-as", "0", "-lw", "1e-5",
            "-lr", "-16",
        ];
        let (rtrace_lux, rtrace_se) = common::radiance::rtrace_lux_runs(
            &bin,
            &lib,
            dir.path(),
            &octree,
            eye.as_bytes(),
            &args,
            32,
        )[0];

        let scene = scene::load_files_with(
            &files,
            &scene::LoadOptions {
                working_directory: Some(room.clone()),
                ..Default::default()
            },
        )
        .unwrap();
        let world = World::new(&scene).unwrap();
        let s = RenderSettings {
            filtered: true,
            ..settings(256, 256, 4, 12)
        };
        let image = render::render(&world, &view, &s, &|_, _| {}).unwrap();
        let picture = LuminanceImage {
            width_px: 256,
            height_px: 256,
            view: view.view.clone(),
            luminance_cd_m2: image.luminance_cd_m2.clone(),
        };
        let ev = glare::evaluate(&picture, &GlareOptions::default())
            .unwrap()
            .ev_lux;
        let diff = ev / rtrace_lux - 1.0;
        println!(
            "{name}: Ev {ev:.1} lx from our picture, rtrace -I {rtrace_lux:.1} ± {rtrace_se:.1} lx ({:+.2} %)",
            100.0 * diff
        );
        assert!(
            diff.abs() < 0.01 + 3.0 * rtrace_se / rtrace_lux,
            "{name}: {diff:+.4}"
        );
    }
}

/// The .hdr file reads back through RADIANCE: `getinfo` finds the VIEW= and FORMAT lines,
/// `getinfo -d` the resolution, and `pvalue` the pixel values to RGBE's precision (1/256 of
/// the largest channel); the EXR's channels are the image's, and the PNG has the size stated.
#[test]
fn picture_files_read_back() {
    let image = Picture {
        width_px: 5,
        height_px: 3,
        view: View::parse("-vth -vp 1 2 3 -vd 0 0 1 -vu 0 1 0 -vh 180 -vv 180")
            .unwrap()
            .to_radiance_string(),
        radiance_rgb: (0..15)
            .map(|i| {
                let f = f64::from(i);
                DVec3::new(0.001 * (f + 1.0), 10.0 * f, 1.0e5 * f * f)
                    * if i == 7 { 0.0 } else { 1.0 }
            })
            .collect(),
        luminance_cd_m2: (0..15).map(|i| f64::from(i) * 10.0).collect(),
        luminance_stderr_cd_m2: vec![0.0; 15],
        samples_per_pixel: 1,
    };
    assert_eq!(rgbe(DVec3::new(1.0, 0.5, 0.25)), [128, 64, 32, 129]);
    assert_eq!(rgbe(DVec3::ZERO), [0, 0, 0, 0]);
    let dir = tempfile::tempdir().unwrap();
    let hdr = dir.path().join("a.hdr");
    write_hdr(&hdr, &image, None).unwrap();
    let exr = dir.path().join("a.exr");
    write_exr(&exr, &image).unwrap();
    let png = dir.path().join("a.png");
    let outcome = write_falsecolour_png(
        &png,
        &image,
        &FalsecolourOptions {
            unit: LegendUnit::Lux,
            scale: ColourScale::Log { decades: 2.0 },
            maximum: None,
            minimum: None,
            divisions: 4,
        },
    )
    .unwrap();
    // 99th percentile of π × 0..140 is π × 140 = 439.8: rounded up to 500.
    assert_eq!(outcome.maximum, 500.0);
    let png_bytes = std::fs::read(&png).unwrap();
    assert_eq!(&png_bytes[1..4], b"PNG");
    let be = |o: usize| u32::from_be_bytes(png_bytes[o..o + 4].try_into().unwrap());
    assert_eq!((be(16), be(20)), (outcome.width_px, outcome.height_px));

    let ex = exr::prelude::read_all_flat_layers_from_file(&exr).unwrap();
    let layer = &ex.layer_data[0];
    let channel = |name: &str| -> Vec<f32> {
        let c = layer
            .channel_data
            .list
            .iter()
            .find(|c| c.name.to_string() == name)
            .unwrap();
        c.sample_data.values_as_f32().collect()
    };
    assert_eq!(channel("B")[4], (1.0e5 * 16.0) as f32);
    assert_eq!(channel("Y")[14], 140.0);

    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let mut c = tool(&bin, &lib, "getinfo");
    c.arg(&hdr);
    let info = String::from_utf8(check_output(c, None)).unwrap();
    assert!(
        info.contains("VIEW= -vth -vp 1 2 3 -vd 0 0 1 -vu 0 1 0 -vh 180 -vv 180"),
        "{info}"
    );
    assert!(info.contains("FORMAT=32-bit_rle_rgbe"), "{info}");
    let mut c = tool(&bin, &lib, "getinfo");
    c.arg("-d").arg(&hdr);
    let dims = String::from_utf8(check_output(c, None)).unwrap();
    assert!(dims.contains("-Y 3 +X 5"), "{dims}");
    let mut c = tool(&bin, &lib, "pvalue");
    c.args(["-h", "-H", "-o"]).arg(&hdr);
    let text = String::from_utf8(check_output(c, None)).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .map(|l| l.split_whitespace().map(|t| t.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 15);
    for r in rows {
        // pvalue prints x y r g b with y counted from the bottom.
        let (x, y) = (r[0] as usize, r[1] as usize);
        let k = (2 - y) * 5 + x;
        let want = image.radiance_rgb[k];
        let tol = want.max_element() / 128.0 + 1e-30;
        for ch in 0..3 {
            assert!(
                (r[2 + ch] - want[ch]).abs() <= tol,
                "pixel ({x},{y}) channel {ch}: pvalue {} vs {}",
                r[2 + ch],
                want[ch]
            );
        }
    }
}

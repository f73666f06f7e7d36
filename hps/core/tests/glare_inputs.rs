//! Glare evaluation's inputs: closed forms of the pixel geometry (solid angles, Ev of a
//! uniform field, DGP without sources), the position index against evalglare's own map
//! (`evalglare -p`), OpenEXR pictures as `skylux render` writes them, and clear errors for
//! bad pictures and settings (no view, a projection that does not fit, NaN or negative
//! values, truncated files), with the OpenEXR reader fuzzed.

mod common;

use common::radiance::{radiance_or_skip, tool};
use glam::DVec3;
use proptest::prelude::*;
use skylux_hps::engine::render::View;
use skylux_hps::glare::{self, GlareError, GlareOptions, LuminanceImage};
use skylux_hps::picture::exr::{read_exr_luminance, write_exr};
use skylux_hps::picture::rgbe::write_hdr;
use skylux_hps::picture::Picture;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

fn corpus_image() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(
        "../../../shared/data/radiance-corpus/glare-testimage/resources/evalglare/testimage.hdr",
    )
}

/// A picture of `view` at most `size` pixels a side, luminance `scene(direction)`.
fn image_of(view: &str, size: u32, scene: &dyn Fn(DVec3) -> f64) -> LuminanceImage {
    let view = View::parse(view).unwrap();
    let prepared = view.prepare().unwrap();
    let (w, h) = prepared.fit_resolution(size, size);
    let luminance_cd_m2 = (0..h)
        .flat_map(|row| (0..w).map(move |column| (column, row)))
        .map(|(column, row)| {
            prepared
                .pixel_centre_ray(column, row, w, h)
                .map_or(0.0, |r| scene(r.direction))
        })
        .collect();
    LuminanceImage {
        width_px: w,
        height_px: h,
        view,
        luminance_cd_m2,
    }
}

fn picture_of(image: &LuminanceImage) -> Picture {
    let n = image.luminance_cd_m2.len();
    Picture {
        width_px: image.width_px,
        height_px: image.height_px,
        view: image.view.to_radiance_string(),
        radiance_rgb: image
            .luminance_cd_m2
            .iter()
            .map(|l| DVec3::splat(l / 179.0))
            .collect(),
        luminance_cd_m2: image.luminance_cd_m2.clone(),
        luminance_stderr_cd_m2: vec![0.0; n],
        samples_per_pixel: 1,
    }
}

const FISHEYE: &str = "-vta -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 180 -vv 180";

#[test]
fn uniform_fields_give_the_closed_forms() {
    // A hemisphere of 1000 cd/m² (below the 2000 cd/m² threshold): Σω = 2π, Ev = π L, no
    // source, DGP = 5.87e-5 Ev + 0.159 and VCP 100.
    let l = 1000.0;
    let r = glare::evaluate(&image_of(FISHEYE, 400, &|_| l), &GlareOptions::default()).unwrap();
    println!(
        "hemisphere: Σω {:.6} sr, Ev {:.3} lx",
        r.solid_angle_sr, r.ev_lux
    );
    assert!((r.solid_angle_sr - 2.0 * PI).abs() < 1e-3 * 2.0 * PI);
    assert!((r.ev_lux - PI * l).abs() < 2e-3 * PI * l);
    assert!(r.sources.is_empty());
    assert!((r.dgp - (5.87e-5 * r.ev_lux + 0.159)).abs() < 1e-12);
    assert_eq!((r.vcp, r.dgi, r.cgi), (100.0, 0.0, 0.0));
    // A perspective view of 70° × 50°: Σω = 4 asin(sin 35° sin 25°), the solid angle of a
    // rectangular pyramid.
    let r = glare::evaluate(
        &image_of("-vtv -vd 0 1 0 -vu 0 0 1 -vh 70 -vv 50", 300, &|_| l),
        &GlareOptions::default(),
    )
    .unwrap();
    let expected = 4.0 * (35f64.to_radians().sin() * 25f64.to_radians().sin()).asin();
    println!(
        "perspective: Σω {:.6} sr, expected {expected:.6}",
        r.solid_angle_sr
    );
    assert!((r.solid_angle_sr - expected).abs() < 1e-6 * expected);
    // One source straight ahead on a dark field: a disk of 5° radius at 20 000 cd/m².
    let disk = |d: DVec3| {
        if d.y >= 5f64.to_radians().cos() {
            20_000.0
        } else {
            0.0
        }
    };
    let r = glare::evaluate(&image_of(FISHEYE, 400, &disk), &GlareOptions::default()).unwrap();
    assert_eq!(r.sources.len(), 1);
    let s = &r.sources[0];
    let omega = 2.0 * PI * (1.0 - 5f64.to_radians().cos());
    println!(
        "disk: ω {:.6} (cap {omega:.6}), P {:.4}",
        s.solid_angle_sr, s.position_index
    );
    assert!((s.solid_angle_sr - omega).abs() < 0.03 * omega);
    assert!((s.position_index - 1.0).abs() < 0.01);
    assert!((s.mean_luminance_cd_m2 - 20_000.0).abs() < 1e-6);
    // Ev = L π sin² 5° from a disk about the normal; all of it direct.
    let ev = 20_000.0 * PI * 5f64.to_radians().sin().powi(2);
    assert!((r.ev_lux - ev).abs() < 0.03 * ev && (r.ev_direct_lux - r.ev_lux).abs() < 1e-9);
}

#[test]
fn position_index_matches_evalglares_map() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let view = "-vta -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 180 -vv 180";
    let image = image_of(view, 121, &|_| 100.0);
    let input = dir.path().join("flat.hdr");
    write_hdr(&input, &picture_of(&image), None).unwrap();
    let map = dir.path().join("posindex.hdr");
    // evalglare -p writes the map and exits with status 1, by design.
    let mut c = tool(&bin, &lib, "evalglare");
    c.arg("-p").arg("-c").arg(&map).arg(&input);
    let status = c.output().expect("running evalglare").status;
    assert!(map.is_file(), "evalglare -p wrote no map ({status})");
    let theirs = glare::load_image(&map, None).unwrap();
    let prepared = image.view.prepare().unwrap();
    let (w, h) = (image.width_px, image.height_px);
    let (mut compared, mut worst) = (0, 0.0f64);
    for row in 0..h {
        for column in 0..w {
            let their = theirs.luminance_cd_m2[(row * w + column) as usize];
            let Some(ray) = prepared.pixel_centre_ray(column, row, w, h) else {
                continue;
            };
            if their == 0.0 || ray.direction.y < 0.0 {
                continue;
            }
            let ours = glare::position_index::position_index(ray.direction, DVec3::Y, DVec3::Z);
            // RGBE keeps 8 bits of mantissa: 1 % at worst.
            worst = worst.max((ours - their).abs() / their);
            compared += 1;
        }
    }
    println!("position index: {compared} pixels, worst relative difference {worst:.4}");
    assert!(compared > 9000);
    assert!(worst < 0.01);
}

#[test]
fn exr_pictures_read_as_skylux_render_writes_them() {
    let dir = tempfile::tempdir().unwrap();
    let image = image_of(FISHEYE, 200, &|d| if d.z > 0.3 { 5000.0 } else { 300.0 });
    let path = dir.path().join("view.exr");
    write_exr(&path, &picture_of(&image)).unwrap();
    let read = glare::load_image(&path, None).unwrap();
    assert_eq!(read.view, image.view);
    assert_eq!(read.luminance_cd_m2, image.luminance_cd_m2);
    let (a, b) = (
        glare::evaluate(&read, &GlareOptions::default()).unwrap(),
        glare::evaluate(&image, &GlareOptions::default()).unwrap(),
    );
    assert_eq!(a, b);
}

fn error<T>(result: Result<T, GlareError>) -> String {
    match result {
        Ok(_) => panic!("expected an error"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn bad_pictures_get_clear_errors() {
    let dir = tempfile::tempdir().unwrap();
    // No view in the file: an error, unless --view gives one.
    let no_view = dir.path().join("no_view.hdr");
    let mut bytes = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n".to_vec();
    bytes.extend_from_slice(&[100, 100, 100, 130].repeat(4));
    std::fs::write(&no_view, &bytes).unwrap();
    let e = error(glare::load_image(&no_view, None));
    assert!(e.contains("no_view.hdr") && e.contains("no view"), "{e}");
    assert!(glare::load_image(&no_view, Some("-vtv -vh 40 -vv 40")).is_ok());
    // Perspective pictures (lit to their corners) given as fisheyes: a 4:3 one does not
    // have the fisheye's aspect; a square one has light where a hemispherical fisheye has none.
    for (size, fisheye, message) in [
        (
            "-vh 90 -vv 70",
            "-vta -vh 180 -vv 180",
            "is not a picture of that view",
        ),
        (
            "-vh 90 -vv 90",
            "-vth -vh 180 -vv 180",
            "not a fisheye picture",
        ),
    ] {
        let flat = image_of(&format!("-vtv -vd 0 1 0 -vu 0 0 1 {size}"), 100, &|_| 500.0);
        let path = dir.path().join("perspective.hdr");
        write_hdr(&path, &picture_of(&flat), None).unwrap();
        let as_fisheye = glare::load_image(&path, Some(fisheye)).unwrap();
        let e = error(glare::evaluate(&as_fisheye, &GlareOptions::default()));
        assert!(e.contains(message), "{e}");
    }
    // The fisheye photograph given as a perspective view.
    let fisheye = glare::load_image(&corpus_image(), Some("-vtv -vh 60 -vv 60")).unwrap();
    let e = error(glare::evaluate(&fisheye, &GlareOptions::default()));
    assert!(e.contains("looks like a fisheye"), "{e}");
    // NaN and negative luminance, in memory and through an OpenEXR file.
    for (bad, text) in [(f64::NAN, "NaN"), (-3.0, "-3")] {
        let mut image = image_of(FISHEYE, 50, &|_| 100.0);
        image.luminance_cd_m2[2 * 50 + 7] = bad;
        let e = error(glare::evaluate(&image, &GlareOptions::default()));
        assert!(e.contains("column 7, row 2") && e.contains(text), "{e}");
        let path = dir.path().join("bad.exr");
        write_exr(&path, &picture_of(&image)).unwrap();
        let read = glare::load_image(&path, None).unwrap();
        let e = error(glare::evaluate(&read, &GlareOptions::default()));
        assert!(e.contains("column 7, row 2"), "{e}");
    }
    // A truncated picture.
    let whole = std::fs::read(corpus_image()).unwrap();
    let cut = dir.path().join("cut.hdr");
    std::fs::write(&cut, &whole[..whole.len() * 2 / 3]).unwrap();
    let e = error(glare::load_image(&cut, None));
    assert!(e.contains("cut.hdr") && e.contains("truncated"), "{e}");
    // A missing file, bad settings.
    let e = error(glare::load_image(&dir.path().join("missing.exr"), None));
    assert!(e.contains("missing.exr"), "{e}");
    let image = image_of(FISHEYE, 50, &|_| 100.0);
    for options in [
        GlareOptions {
            threshold: Some(-1.0),
            ..GlareOptions::default()
        },
        GlareOptions {
            detection: glare::DetectionSettings {
                search_radius_rad: f64::NAN,
                ..Default::default()
            },
            ..GlareOptions::default()
        },
    ] {
        let e = error(glare::evaluate(&image, &options));
        assert!(e.contains("must be a positive number"), "{e}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// The OpenEXR reader on mutated files: an error naming the file or a picture, never a
    /// panic, in bounded time.
    #[test]
    fn mutated_exr_files_never_panic(
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..6),
        cut in any::<prop::sample::Index>(),
    ) {
        let dir = tempfile::tempdir().unwrap();
        let good = dir.path().join("good.exr");
        write_exr(&good, &picture_of(&image_of(FISHEYE, 16, &|d| 100.0 + d.z))).unwrap();
        let mut bytes = std::fs::read(&good).unwrap();
        for (at, value) in edits {
            let i = at.index(bytes.len());
            bytes[i] = value;
        }
        let end = cut.index(bytes.len() + 1);
        let path = dir.path().join("fuzz.exr");
        for body in [&bytes[..], &bytes[..end]] {
            std::fs::write(&path, body).unwrap();
            let start = std::time::Instant::now();
            match read_exr_luminance(&path) {
                Ok(p) => prop_assert_eq!(p.luminance_cd_m2.len(), (p.width_px * p.height_px) as usize),
                Err(e) => prop_assert!(e.to_string().contains("fuzz.exr"), "{}", e),
            }
            prop_assert!(start.elapsed().as_secs_f64() < 2.0);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// Evaluation of arbitrary small pictures under arbitrary views and settings: a report or
    /// an error, never a panic, in bounded time; reports hold finite Ev and DGP in [0, 1].
    #[test]
    fn arbitrary_pictures_never_panic(
        size in 1u32..40,
        square in any::<bool>(),
        kind in 0usize..3,
        (hv, vv) in (1.0f64..360.0, 1.0f64..360.0),
        values in proptest::collection::vec(prop_oneof![0.0f64..3000.0, 1e4f64..1e8, Just(0.0)], 1600),
        threshold in prop::option::of(0.5f64..5000.0),
        radius in 0.01f64..1.0,
    ) {
        let kind = ["-vta", "-vth", "-vtv"][kind];
        let (hv, vv) = if kind == "-vta" { (hv, vv) } else { (hv.min(179.0), vv.min(179.0)) };
        let view = View::parse(&format!("{kind} -vd 0 1 0 -vu 0 0 1 -vh {hv} -vv {vv}")).unwrap();
        // Mostly the view's own aspect (as rpict frames it), sometimes a square.
        let (w, h) = if square {
            (size, size)
        } else {
            view.prepare().unwrap().fit_resolution(size, size)
        };
        let image = LuminanceImage {
            width_px: w,
            height_px: h,
            view,
            luminance_cd_m2: values[..(w * h) as usize].to_vec(),
        };
        let options = GlareOptions {
            threshold,
            detection: glare::DetectionSettings { search_radius_rad: radius, ..Default::default() },
            ..GlareOptions::default()
        };
        let start = std::time::Instant::now();
        if let Ok(r) = glare::evaluate(&image, &options) {
            prop_assert!(r.ev_lux.is_finite() && r.ev_lux >= 0.0);
            prop_assert!((0.0..=1.0).contains(&r.dgp), "DGP {}", r.dgp);
        }
        prop_assert!(start.elapsed().as_secs_f64() < 2.0);
    }
}

//! `compare` (measured against rendered luminance pictures): known errors put in by hand are
//! found again (shift, 1.2 × scale, Gaussian noise of known σ, per-region offsets), two views
//! of one analytic luminance field map onto each other, two rpict renders with different
//! settings give per-pixel errors equal to what `pcomb` computes live, and bad input gives
//! clear errors. Without RADIANCE the live test prints SKIPPED and passes, unless
//! `SKYLUX_REQUIRE_RADIANCE` is set.

mod common;

use common::radiance::{check_output, radiance_or_skip, tool};
use glam::DVec3;
use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use skylux_hps::compare::{self, regions, CompareError, CompareOptions, Regions};
use skylux_hps::engine::render::View;
use skylux_hps::glare::LuminanceImage;
use skylux_hps::picture::{rgbe, Picture};
use std::path::Path;

const MEASURED_VIEW: &str = "-vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 60 -vv 45";

/// A smooth, everywhere positive luminance field over directions, cd/m².
fn field_cd_m2(d: DVec3) -> f64 {
    100.0 * (0.8 * d.z + 0.3 * d.x).exp() + 20.0
}

/// The field drawn into a `width` × `height` picture of `view` (0 where a pixel has no ray).
fn draw(view: &str, width: u32, height: u32, field: impl Fn(DVec3) -> f64) -> LuminanceImage {
    let view = View::parse(view).unwrap();
    let prepared = view.prepare().unwrap();
    let mut luminance_cd_m2 = Vec::new();
    for row in 0..height {
        for column in 0..width {
            let l = prepared
                .pixel_centre_ray(column, row, width, height)
                .map_or(0.0, |r| field(r.direction));
            luminance_cd_m2.push(l);
        }
    }
    LuminanceImage {
        width_px: width,
        height_px: height,
        view,
        luminance_cd_m2,
    }
}

fn measured() -> LuminanceImage {
    draw(MEASURED_VIEW, 64, 48, field_cd_m2)
}

fn with_values(image: &LuminanceImage, values: Vec<f64>) -> LuminanceImage {
    LuminanceImage {
        luminance_cd_m2: values,
        ..image.clone()
    }
}

fn run(m: &LuminanceImage, r: &LuminanceImage) -> compare::Comparison {
    compare::compare(m, r, &Regions::default(), &CompareOptions::default()).unwrap()
}

#[test]
fn scaled_by_1_2_gives_plus_20_percent_everywhere() {
    let m = measured();
    let r = with_values(&m, m.luminance_cd_m2.iter().map(|l| 1.2 * l).collect());
    let c = run(&m, &r);
    assert_eq!(c.excluded_outside_view + c.excluded_below_floor, 0);
    for e in c.relative_error.iter() {
        assert!((e.unwrap() - 0.2).abs() < 1e-9, "{e:?}");
    }
    let s = c.summary.unwrap();
    assert_eq!(s.count, 64 * 48);
    for (what, v) in [
        ("mean", s.mean_abs),
        ("median", s.median_abs),
        ("p90", s.p90_abs),
        ("signed", s.mean_signed),
        ("rms", s.rms),
    ] {
        assert!((v - 0.2).abs() < 1e-9, "{what} {v}");
    }
    let h = c.histogram.unwrap();
    assert_eq!(h.measured.iter().sum::<usize>(), 64 * 48);
    assert_eq!(h.rendered.iter().sum::<usize>(), 64 * 48);
    assert_eq!(h.edges_cd_m2.len(), h.measured.len() + 1);
}

#[test]
fn shifted_picture_gives_the_directly_computed_error_map() {
    let m = measured();
    let (w, h, k) = (64usize, 48usize, 3usize);
    // R(column) = M(column − k): the picture moved right by k pixels (edge columns repeated).
    let shifted: Vec<f64> = (0..w * h)
        .map(|i| {
            let (column, row) = (i % w, i / w);
            m.luminance_cd_m2[row * w + column.saturating_sub(k)]
        })
        .collect();
    let r = with_values(&m, shifted.clone());
    let c = run(&m, &r);
    let mut direct = Vec::new();
    for (i, e) in c.relative_error.iter().enumerate() {
        let expected = (shifted[i] - m.luminance_cd_m2[i]) / m.luminance_cd_m2[i];
        assert!(
            (e.unwrap() - expected).abs() < 1e-9,
            "pixel {i}: {e:?} vs {expected}"
        );
        direct.push(expected.abs());
    }
    direct.sort_by(f64::total_cmp);
    let s = c.summary.unwrap();
    let mean = direct.iter().sum::<f64>() / direct.len() as f64;
    assert!((s.mean_abs - mean).abs() < 1e-12);
    assert!(
        s.mean_abs > 0.005,
        "a 3-pixel shift of this field is visible: {}",
        s.mean_abs
    );
}

/// A standard normal deviate (Box–Muller).
fn gaussian(rng: &mut impl Rng) -> f64 {
    let (u, v): (f64, f64) = (rng.gen::<f64>().max(1e-300), rng.gen());
    (-2.0 * u.ln()).sqrt() * (2.0 * std::f64::consts::PI * v).cos()
}

#[test]
fn noise_of_known_sigma_is_recovered() {
    let m = draw(MEASURED_VIEW, 200, 150, field_cd_m2);
    let sigma = 0.05;
    let mut rng = rand::rngs::StdRng::seed_from_u64(21);
    let noisy = m
        .luminance_cd_m2
        .iter()
        .map(|l| l * (1.0 + sigma * gaussian(&mut rng)))
        .collect();
    let s = run(&m, &with_values(&m, noisy)).summary.unwrap();
    let n = s.count as f64;
    // Sampling errors of the estimates (normal theory): RMS σ/√(2n), mean σ/√n; quantiles of
    // |N(0, σ)|: median 0.6745 σ, p90 1.6449 σ, mean σ √(2/π).
    assert!(
        (s.rms - sigma).abs() < 4.0 * sigma / (2.0 * n).sqrt(),
        "rms {}",
        s.rms
    );
    assert!(
        s.mean_signed.abs() < 4.0 * sigma / n.sqrt(),
        "mean {}",
        s.mean_signed
    );
    assert!(
        (s.median_abs / sigma - 0.6745).abs() < 0.02,
        "median {}",
        s.median_abs
    );
    assert!(
        (s.p90_abs / sigma - 1.6449).abs() < 0.03,
        "p90 {}",
        s.p90_abs
    );
    let mean_abs = sigma * (2.0 / std::f64::consts::PI).sqrt();
    assert!(
        (s.mean_abs - mean_abs).abs() < 0.01 * sigma * 2.0,
        "mean |e| {}",
        s.mean_abs
    );
}

#[test]
fn different_views_of_one_field_map_onto_each_other() {
    let m = measured();
    // The same field seen through a fisheye at another resolution and with a different up.
    let fisheye = "-vta -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 180 -vv 180";
    let r = draw(fisheye, 301, 301, field_cd_m2);
    let s = run(&m, &r).summary.unwrap();
    assert_eq!(s.count, 64 * 48);
    assert!(
        s.p90_abs < 2e-3,
        "bilinear resampling error p90 {}",
        s.p90_abs
    );
    let r12 = draw(fisheye, 301, 301, |d| 1.2 * field_cd_m2(d));
    let s12 = run(&m, &r12).summary.unwrap();
    assert!((s12.mean_signed - 0.2).abs() < 3e-3, "{}", s12.mean_signed);
    // A perspective picture looking 20° to the left covers only part of the measured one.
    let turned = "-vtv -vp 0 0 0 -vd -0.364 1 0 -vu 0 0 1 -vh 60 -vv 45";
    let c = run(&m, &draw(turned, 64, 48, field_cd_m2));
    assert!(c.excluded_outside_view > 64 * 48 / 5 && c.excluded_outside_view < 64 * 48 / 2);
    assert!(c.summary.unwrap().p90_abs < 5e-3);
}

#[test]
fn regions_from_polygons_and_mask_get_their_own_errors() {
    let m = measured();
    let (w, h) = (64usize, 48usize);
    let values = (0..w * h)
        .map(|i| m.luminance_cd_m2[i] * if i % w < w / 2 { 1.1 } else { 0.9 })
        .collect();
    let r = with_values(&m, values);
    let json = r#"[{"name": "left", "polygon": [[0, 0], [32, 0], [32, 48], [0, 48]]},
                   {"name": "right", "polygon": [[32, 0], [64, 0], [64, 48], [32, 48]]}]"#;
    let polygons = regions::parse_polygons(json).unwrap();
    let from_polygons = regions::rasterise(&polygons, 64, 48);
    let dir = tempfile::tempdir().unwrap();
    let mask_path = dir.path().join("mask.hdr");
    let ids = (0..w * h).map(|i| if i % w < w / 2 { 1.0 } else { 2.0 });
    write_picture(&mask_path, 64, 48, ids.collect());
    let from_mask = compare::read_regions(&mask_path, 64, 48).unwrap();
    assert_eq!(from_mask.id_of_pixel, from_polygons.id_of_pixel);
    let options = CompareOptions::default();
    for regions in [from_polygons, from_mask] {
        let c = compare::compare(&m, &r, &regions, &options).unwrap();
        assert_eq!(c.regions.len(), 2);
        for (region, expected) in c.regions.iter().zip([0.1, -0.1]) {
            let s = region.summary.as_ref().unwrap();
            assert_eq!((region.pixels, s.count), (32 * 48, 32 * 48));
            assert!((s.mean_signed - expected).abs() < 1e-9, "{}", s.mean_signed);
        }
        assert!((c.summary.unwrap().mean_abs - 0.1).abs() < 1e-9);
    }
}

#[test]
fn dark_pixels_below_the_floor_are_left_out_and_counted() {
    let m = measured();
    let mut values = m.luminance_cd_m2.clone();
    for v in values.iter_mut().take(100) {
        *v = 0.5;
    }
    let m = with_values(&m, values);
    let options = CompareOptions {
        min_luminance_cd_m2: 1.0,
    };
    let c = compare::compare(&m, &m, &Regions::default(), &options).unwrap();
    assert_eq!(c.excluded_below_floor, 100);
    assert_eq!(c.summary.unwrap().count, 64 * 48 - 100);
    let bad = CompareOptions {
        min_luminance_cd_m2: f64::NAN,
    };
    assert!(compare::compare(&m, &m, &Regions::default(), &bad).is_err());
}

/// Writes a grey RADIANCE picture whose three channels hold `values` (view: MEASURED_VIEW).
fn write_picture(path: &Path, width: u32, height: u32, values: Vec<f64>) {
    let n = values.len();
    let picture = Picture {
        width_px: width,
        height_px: height,
        view: MEASURED_VIEW.into(),
        radiance_rgb: values.iter().map(|&v| DVec3::splat(v)).collect(),
        luminance_cd_m2: values.iter().map(|v| v * 179.0).collect(),
        luminance_stderr_cd_m2: vec![0.0; n],
        samples_per_pixel: 1,
    };
    rgbe::write_hdr(path, &picture, None).unwrap();
}

#[test]
fn bad_input_gives_clear_errors() {
    let m = measured();
    let away = "-vtv -vp 0 0 0 -vd 0 -1 0 -vu 0 0 1 -vh 60 -vv 45";
    let e = compare::compare(
        &m,
        &draw(away, 64, 48, field_cd_m2),
        &Regions::default(),
        &CompareOptions::default(),
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("do not show the same view"), "{e}");
    let moved = "-vtv -vp 1 0 0 -vd 0 1 0 -vu 0 0 1 -vh 60 -vv 45";
    let e = compare::compare(
        &m,
        &draw(moved, 64, 48, field_cd_m2),
        &Regions::default(),
        &CompareOptions::default(),
    )
    .unwrap_err();
    assert!(matches!(e, CompareError::Views(_)), "{e}");
    assert!(e.to_string().contains("eye points"), "{e}");

    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("good.hdr");
    write_picture(
        &good,
        64,
        48,
        m.luminance_cd_m2.iter().map(|l| l / 179.0).collect(),
    );
    let bytes = std::fs::read(&good).unwrap();
    let truncated = dir.path().join("truncated.hdr");
    std::fs::write(&truncated, &bytes[..bytes.len() / 2]).unwrap();
    let e = compare::load_picture(&truncated, None)
        .unwrap_err()
        .to_string();
    assert!(e.contains("truncated.hdr"), "{e}");

    // NaN and negative values (an EXR can hold them).
    for (name, bad) in [("nan.exr", f64::NAN), ("negative.exr", -3.0)] {
        let path = dir.path().join(name);
        let mut values = m.luminance_cd_m2.clone();
        values[70] = bad;
        let picture = Picture {
            width_px: 64,
            height_px: 48,
            view: MEASURED_VIEW.into(),
            radiance_rgb: vec![DVec3::ZERO; 64 * 48],
            luminance_cd_m2: values,
            luminance_stderr_cd_m2: vec![0.0; 64 * 48],
            samples_per_pixel: 1,
        };
        skylux_hps::picture::exr::write_exr(&path, &picture).unwrap();
        let e = compare::load_picture(&path, None).unwrap_err().to_string();
        assert!(e.contains(name) && e.contains("column 6, row 1"), "{e}");
    }

    let small_mask = dir.path().join("small.hdr");
    write_picture(&small_mask, 10, 10, vec![1.0; 100]);
    let e = compare::read_regions(&small_mask, 64, 48)
        .unwrap_err()
        .to_string();
    assert!(e.contains("small.hdr") && e.contains("10 × 10"), "{e}");
    let polygons = dir.path().join("p.json");
    std::fs::write(&polygons, r#"[{"name": "w", "polygon": [[0, 0], [1, 1]]}]"#).unwrap();
    let e = compare::read_regions(&polygons, 64, 48)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("p.json") && e.contains("`w`") && e.contains("3"),
        "{e}"
    );
}

#[test]
fn locate_is_the_inverse_of_ray_in_every_view_type() {
    let views = [
        "-vtv -vp 1 2 3 -vd 1 0.5 -0.2 -vu 0 0 1 -vh 70 -vv 50 -vs 0.1 -vl -0.05",
        "-vth -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 180 -vv 180",
        "-vta -vp 0 0 0 -vd 0 0 1 -vu 0 1 0 -vh 180 -vv 180",
        "-vta -vp 0 0 0 -vd 1 1 0 -vu 0 0 1 -vh 300 -vv 200",
    ];
    for text in views {
        let view = View::parse(text).unwrap().prepare().unwrap();
        let mut checked = 0;
        for i in 0..41 {
            for j in 0..41 {
                let (x, y) = (f64::from(i) / 40.0, f64::from(j) / 40.0);
                let Some(ray) = view.ray(x, y) else { continue };
                let (u, v) = view.locate(ray.direction).unwrap();
                assert!(
                    (u - x).abs() < 1e-9 && (v - y).abs() < 1e-9,
                    "{text}: ({x}, {y}) → ({u}, {v})"
                );
                checked += 1;
            }
        }
        assert!(checked > 41 * 41 / 2, "{text}: {checked}");
    }
    let perspective = View::parse(MEASURED_VIEW).unwrap().prepare().unwrap();
    assert!(
        perspective.locate(DVec3::new(0.0, -1.0, 0.0)).is_none(),
        "behind"
    );
    assert!(perspective.locate(DVec3::ZERO).is_none());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// Random text as a polygon file and random bytes as a mask never panic and end fast.
    #[test]
    fn region_readers_never_panic(text in ".{0,300}", bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        let started = std::time::Instant::now();
        let _ = regions::parse_polygons(&text);
        let _ = regions::mask_regions(Path::new("fuzz.hdr"), &bytes, 8, 8);
        let mut mask = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 8\n".to_vec();
        mask.extend_from_slice(&bytes);
        let _ = regions::mask_regions(Path::new("fuzz.hdr"), &mask, 8, 8);
        prop_assert!(started.elapsed().as_secs_f64() < 1.0);
    }

    /// Random polygons with wild corners rasterise within the picture.
    #[test]
    fn polygons_with_any_corners_rasterise(corners in proptest::collection::vec((-1e6f64..1e6, -1e6f64..1e6), 3..12)) {
        let polygon = regions::PolygonRegion { name: "p".into(), polygon: corners.iter().map(|&(x, y)| [x, y]).collect() };
        let r = regions::rasterise(&[polygon], 16, 12);
        prop_assert_eq!(r.id_of_pixel.len(), 16 * 12);
    }

    /// Random small pictures and views compare without panicking: an answer or an error.
    #[test]
    fn any_small_pictures_compare_or_fail_cleanly(
        (w, h) in (1u32..12, 1u32..12),
        (rw, rh) in (1u32..12, 1u32..12),
        kind in 0usize..3,
        angle in 1.0f64..179.0,
        direction in (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0),
        values in proptest::collection::vec(0.0f64..1e6, 144),
        floor in 0.0f64..10.0,
    ) {
        let types = ["-vtv", "-vth", "-vta"];
        let view = format!("{} -vp 0 0 0 -vd {} {} {} -vu 0 0 1 -vh {angle} -vv {angle}",
            types[kind], direction.0, direction.1, direction.2);
        let (Ok(mv), Ok(rv)) = (View::parse(MEASURED_VIEW), View::parse(&view)) else { return Ok(()); };
        let image = |view: View, w: u32, h: u32| LuminanceImage {
            width_px: w, height_px: h, view, luminance_cd_m2: values[..(w * h) as usize].to_vec(),
        };
        let options = CompareOptions { min_luminance_cd_m2: floor };
        let _ = compare::compare(&image(mv, w, h), &image(rv, rw, rh), &Regions::default(), &options);
    }
}

/// A room with a window to a glowing sky: grey walls so that pcomb's luminance and ours weigh
/// the channels alike (the wall around the window sees no sky: the renders add an ambient
/// value, so that no pixel is black).
const ROOM: &str = "\
void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n\
void glow sky_glow 0 0 4 3 3 3 0\n\
sky_glow source sky 0 0 4 0 1 0.3 170\n\
grey polygon floor 0 0 12 0 0 0  0 4 0  4 4 0  4 0 0\n\
grey polygon ceiling 0 0 12 0 0 3  4 0 3  4 4 3  0 4 3\n\
grey polygon west 0 0 12 0 0 0  0 0 3  0 4 3  0 4 0\n\
grey polygon east 0 0 12 4 0 0  4 4 0  4 4 3  4 0 3\n\
grey polygon south 0 0 12 0 0 0  4 0 0  4 0 3  0 0 3\n\
grey polygon north_low 0 0 12 0 4 0  0 4 1  4 4 1  4 4 0\n\
grey polygon north_high 0 0 12 0 4 2.5  0 4 3  4 4 3  4 4 2.5\n\
grey polygon north_left 0 0 12 0 4 1  0 4 2.5  1 4 2.5  1 4 1\n\
grey polygon north_right 0 0 12 3 4 1  3 4 2.5  4 4 2.5  4 4 1\n\
";

fn rpict(
    bin: &Path,
    lib: &Option<std::path::PathBuf>,
    dir: &Path,
    octree: &Path,
    settings: &[&str],
) -> Vec<u8> {
    let mut c = tool(bin, lib, "rpict");
    c.current_dir(dir).args([
        "-vtv", "-vp", "2", "0.5", "1.5", "-vd", "0", "1", "-0.1", "-vu", "0", "0", "1", "-vh",
        "70", "-vv", "55", "-x", "96", "-y", "96", "-ps", "1", "-dj", "0", "-av", "0.05", "0.05",
        "0.05",
    ]);
    c.args(settings).arg(octree);
    check_output(c, None)
}

#[test]
fn two_rpict_renders_agree_with_pcomb_differences() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("room.rad");
    std::fs::write(&scene, ROOM).unwrap();
    let mut oconv = tool(&bin, &lib, "oconv");
    oconv.arg(&scene);
    let octree = dir.path().join("room.oct");
    std::fs::write(&octree, check_output(oconv, None)).unwrap();
    let one = dir.path().join("ab1.hdr");
    let two = dir.path().join("ab2.hdr");
    std::fs::write(
        &one,
        rpict(
            &bin,
            &lib,
            dir.path(),
            &octree,
            &["-ab", "1", "-aa", "0.2", "-ad", "256"],
        ),
    )
    .unwrap();
    std::fs::write(
        &two,
        rpict(
            &bin,
            &lib,
            dir.path(),
            &octree,
            &["-ab", "2", "-aa", "0.1", "-ad", "512"],
        ),
    )
    .unwrap();
    // Measured: the -ab 2 render; rendered: the -ab 1 one. pcomb's ratio li(2)/li(1) (an RGBE picture cannot hold the negative difference).
    let mut pcomb = tool(&bin, &lib, "pcomb");
    pcomb.args(["-e", "lo=li(2)/li(1)"]).arg(&two).arg(&one);
    let ratio_path = dir.path().join("ratio.hdr");
    std::fs::write(&ratio_path, check_output(pcomb, None)).unwrap();
    let ratio = rgbe::read_hdr(&ratio_path).unwrap();

    let measured = compare::load_picture(&two, None).unwrap();
    let rendered = compare::load_picture(&one, None).unwrap();
    let options = CompareOptions {
        min_luminance_cd_m2: 0.0,
    };
    let c = compare::compare(&measured, &rendered, &Regions::default(), &options).unwrap();
    assert_eq!(
        (ratio.width_px, ratio.height_px),
        (measured.width_px, measured.height_px)
    );
    let s = c.summary.as_ref().unwrap();
    assert_eq!(
        s.count, c.pixels,
        "every pixel of a lit room is compared: {} outside, {} dark",
        c.excluded_outside_view, c.excluded_below_floor
    );
    let mut worst = 0.0f64;
    let mut pcomb_errors = Vec::new();
    for (e, p) in c.relative_error.iter().zip(&ratio.pixels) {
        let pcomb_error = f64::from(p[0]) - 1.0;
        // RGBE keeps 8 mantissa bits (setcolr truncates, colr_color adds half a step): the
        // stored ratio is within 1/256 of the true one, so within 1/255 of itself.
        let allowed = f64::from(p[0]) / 255.0 + 1e-6;
        let gap = (e.unwrap() - pcomb_error).abs();
        assert!(gap <= allowed, "ours {e:?}, pcomb {pcomb_error}");
        worst = worst.max(gap / allowed);
        pcomb_errors.push(pcomb_error);
    }
    let n = pcomb_errors.len() as f64;
    let pcomb_mean = pcomb_errors.iter().sum::<f64>() / n;
    let pcomb_rms = (pcomb_errors.iter().map(|e| e * e).sum::<f64>() / n).sqrt();
    println!(
        "ab2 (measured) vs ab1 on {} px: mean signed ours {:.5} pcomb {pcomb_mean:.5}, rms ours {:.5} pcomb \
         {pcomb_rms:.5}, worst gap {:.2} of the RGBE step",
        s.count, s.mean_signed, s.rms, worst
    );
    assert!(
        s.mean_signed < -0.05,
        "one bounce less darkens the room: {}",
        s.mean_signed
    );
    // The per-pixel bound carried to the means: |Δ mean| ≤ mean ratio / 255, and the RMS
    // differ by at most the RMS of the gaps (triangle inequality), ≤ RMS ratio / 255.
    assert!((s.mean_signed - pcomb_mean).abs() <= (1.0 + pcomb_mean) / 255.0);
    assert!((s.rms - pcomb_rms).abs() <= (1.0 + pcomb_rms) / 255.0);
}

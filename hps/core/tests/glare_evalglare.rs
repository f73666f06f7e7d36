//! Glare evaluation against evalglare: the corpus's real fisheye photograph of an office
//! (RADIANCE's own evalglare test image, checked against the reference values its
//! PROVENANCE.txt records) and pictures of our own, each compared with evalglare run live
//! from the pyradiance wheel. Without RADIANCE the live comparisons print SKIPPED and pass,
//! unless `SKYLUX_REQUIRE_RADIANCE` is set.

mod common;

use common::radiance::{check_output, radiance_or_skip, tool};
use glam::DVec3;
use skylux_hps::engine::render::View;
use skylux_hps::glare::{self, GlareOptions, GlareReport};
use skylux_hps::picture::{rgbe::write_hdr, Picture};
use std::path::{Path, PathBuf};

fn corpus_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data/radiance-corpus/glare-testimage")
}

fn corpus_image() -> PathBuf {
    corpus_dir().join("resources/evalglare/testimage.hdr")
}

fn evaluate_file(path: &Path, options: &GlareOptions) -> GlareReport {
    let image = glare::load_image(path, None).unwrap_or_else(|e| panic!("{e}"));
    glare::evaluate(&image, options).unwrap_or_else(|e| panic!("{e}"))
}

/// The number written after `key` in the corpus's PROVENANCE.txt (e.g. `dgp 0.5306`).
fn provenance_value(key: &str) -> f64 {
    let path = corpus_dir().join("PROVENANCE.txt");
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("{}: {e} (the shared corpus is needed)", path.display()));
    let at = text
        .find(key)
        .unwrap_or_else(|| panic!("{} does not mention `{key}`", path.display()));
    let rest = &text[at + key.len()..];
    let number: String = rest
        .trim_start()
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.')
        .collect();
    number
        .parse()
        .unwrap_or_else(|_| panic!("no number after `{key}` in {}", path.display()))
}

/// One glare source as evalglare `-d` prints it.
#[derive(Debug)]
struct EvalglareSource {
    pixels: f64,
    x_px: f64,
    /// evalglare's y: the picture's height less its bottom-up centre.
    y_px: f64,
    luminance: f64,
    omega: f64,
    position_index: f64,
}

/// evalglare `-d`'s results.
#[derive(Debug)]
struct Evalglare {
    sources: Vec<EvalglareSource>,
    values: std::collections::HashMap<String, f64>,
}

impl Evalglare {
    fn get(&self, name: &str) -> f64 {
        *self
            .values
            .get(name)
            .unwrap_or_else(|| panic!("evalglare printed no {name}: {:?}", self.values))
    }
}

/// Runs `evalglare -d ARGS PICTURE` and parses its source table and summary line.
fn run_evalglare(bin: &Path, lib: &Option<PathBuf>, picture: &Path, args: &[&str]) -> Evalglare {
    let mut c = tool(bin, lib, "evalglare");
    c.arg("-d").args(args).arg(picture);
    let out = String::from_utf8(check_output(c, None)).expect("evalglare prints text");
    let lines: Vec<&str> = out.lines().collect();
    let head = lines
        .iter()
        .position(|l| l.contains("No pixels"))
        .unwrap_or_else(|| panic!("no source table in evalglare's output:\n{out}"));
    let count: usize = lines[head]
        .split_whitespace()
        .next()
        .unwrap()
        .parse()
        .unwrap();
    let sources = lines[head + 1..head + 1 + count]
        .iter()
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|t| t.parse().unwrap()).collect();
            EvalglareSource {
                pixels: v[1],
                x_px: v[2],
                y_px: v[3],
                luminance: v[4],
                omega: v[5],
                position_index: v[6],
            }
        })
        .collect();
    let summary = lines
        .iter()
        .find(|l| l.starts_with("dgp,av_lum"))
        .unwrap_or_else(|| panic!("no summary line in evalglare's output:\n{out}"));
    let (names, numbers) = summary.split_once(':').unwrap();
    let values = names
        .split(',')
        .map(str::to_string)
        .zip(
            numbers
                .split_whitespace()
                .map(|t| t.parse::<f64>().unwrap()),
        )
        .collect();
    Evalglare { sources, values }
}

/// Asserts `ours` within `relative` of `theirs` (or within `absolute`, for values near 0).
fn assert_close(what: &str, ours: f64, theirs: f64, relative: f64, absolute: f64) {
    let tolerance = (relative * theirs.abs()).max(absolute);
    assert!(
        (ours - theirs).abs() <= tolerance,
        "{what}: ours {ours}, evalglare {theirs} (tolerance {tolerance})"
    );
}

/// Compares every index and every source with evalglare's.
fn compare(label: &str, ours: &GlareReport, theirs: &Evalglare, height_px: f64, metric_rel: f64) {
    println!(
        "{label}: Ev {:.2}/{:.2} lx, DGP {:.4}/{:.4}, DGI {:.3}/{:.3}, UGR {:.3}/{:.3}, \
         CGI {:.3}/{:.3}, VCP {:.2}/{:.2}, sources {}/{} (ours/evalglare)",
        ours.ev_lux,
        theirs.get("E_v"),
        ours.dgp,
        theirs.get("dgp"),
        ours.dgi,
        theirs.get("dgi"),
        ours.ugr.unwrap_or(-99.0),
        theirs.get("ugr"),
        ours.cgi,
        theirs.get("cgi"),
        ours.vcp,
        theirs.get("vcp"),
        ours.sources.len(),
        theirs.sources.len()
    );
    assert_close(
        &format!("{label} Ev"),
        ours.ev_lux,
        theirs.get("E_v"),
        1e-3,
        1e-6,
    );
    assert_close(
        &format!("{label} DGP"),
        ours.dgp,
        theirs.get("dgp"),
        0.0,
        0.005,
    );
    for (name, value) in [
        ("dgi", ours.dgi),
        ("ugr", ours.ugr.unwrap_or(-99.0)),
        ("cgi", ours.cgi),
        ("vcp", ours.vcp),
    ] {
        assert_close(
            &format!("{label} {name}"),
            value,
            theirs.get(name),
            metric_rel,
            0.02,
        );
    }
    assert_eq!(
        ours.sources.len(),
        theirs.sources.len(),
        "{label}: number of glare sources, ours {:#?} evalglare {:#?}",
        ours.sources,
        theirs.sources
    );
    for (k, (s, t)) in ours.sources.iter().zip(&theirs.sources).enumerate() {
        let what = format!("{label} source {}", k + 1);
        // evalglare's y counts from the top edge to the centre measured from the bottom:
        // height − y_up = row from the top + 1.
        assert_close(&format!("{what} column"), s.column_px, t.x_px, 0.0, 0.5);
        assert_close(&format!("{what} row"), s.row_px + 1.0, t.y_px, 0.0, 0.5);
        assert!(height_px > 0.0);
        assert_close(
            &format!("{what} pixels"),
            s.pixels as f64,
            t.pixels,
            0.01,
            0.5,
        );
        assert_close(
            &format!("{what} L"),
            s.mean_luminance_cd_m2,
            t.luminance,
            metric_rel,
            1e-3,
        );
        assert_close(
            &format!("{what} ω"),
            s.solid_angle_sr,
            t.omega,
            metric_rel,
            1e-9,
        );
        assert_close(
            &format!("{what} P"),
            s.position_index,
            t.position_index,
            metric_rel,
            1e-3,
        );
    }
}

#[test]
fn corpus_photograph_matches_evalglare_reference_values() {
    let ours = evaluate_file(&corpus_image(), &GlareOptions::default());
    let ev_reference = provenance_value("E_v =");
    let dgp_reference = provenance_value("dgp");
    println!(
        "Ev {:.3} lx (reference {ev_reference}), DGP {:.4} (reference {dgp_reference}), {} sources",
        ours.ev_lux,
        ours.dgp,
        ours.sources.len()
    );
    assert!((ours.ev_lux - ev_reference).abs() <= 1e-3 * ev_reference);
    assert!((ours.dgp - dgp_reference).abs() <= 0.005);
    // The mean and peak luminance the provenance records ("av_lum 1729.7", "max pixel
    // luminance 37142.5").
    let mean = provenance_value("av_lum");
    assert!((ours.average_luminance_cd_m2 - mean).abs() <= 1e-3 * mean);
    let peak = provenance_value("max pixel luminance");
    let brightest = ours
        .sources
        .iter()
        .map(|s| s.max_luminance_cd_m2)
        .fold(0.0, f64::max);
    assert!(
        (brightest - peak).abs() <= 1e-3 * peak,
        "{brightest} vs {peak}"
    );
}

#[test]
fn corpus_photograph_matches_live_evalglare() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let ours = evaluate_file(&corpus_image(), &GlareOptions::default());
    let theirs = run_evalglare(&bin, &lib, &corpus_image(), &[]);
    compare("corpus photograph", &ours, &theirs, 786.0, 1e-3);
    // The brief's bounds, explicitly: DGI, UGR and CGI within 0.2.
    for (name, value) in [
        ("dgi", ours.dgi),
        ("ugr", ours.ugr.unwrap()),
        ("cgi", ours.cgi),
    ] {
        assert!((value - theirs.get(name)).abs() <= 0.2, "{name}");
    }
}

/// Luminance (cd/m²) seen in a direction.
type Scene = dyn Fn(DVec3) -> f64;

/// A luminance picture of `view` at `size` × `size` pixels (fewer rows for a perspective
/// view's aspect), each pixel the luminance `scene` gives its centre's direction, written as
/// a grey RADIANCE picture. Returns its path.
fn synthesize(
    dir: &Path,
    name: &str,
    view: &str,
    size: u32,
    scene: &dyn Fn(DVec3) -> f64,
) -> PathBuf {
    let prepared = View::parse(view).unwrap().prepare().unwrap();
    let (w, h) = prepared.fit_resolution(size, size);
    let mut luminance = Vec::with_capacity((w * h) as usize);
    for row in 0..h {
        for column in 0..w {
            let l = prepared
                .pixel_centre_ray(column, row, w, h)
                .map_or(0.0, |ray| scene(ray.direction));
            luminance.push(l);
        }
    }
    let picture = Picture {
        width_px: w,
        height_px: h,
        view: view.to_string(),
        radiance_rgb: luminance.iter().map(|l| DVec3::splat(l / 179.0)).collect(),
        luminance_cd_m2: luminance,
        luminance_stderr_cd_m2: vec![0.0; (w * h) as usize],
        samples_per_pixel: 1,
    };
    let path = dir.join(format!("{name}.hdr"));
    write_hdr(&path, &picture, None).unwrap();
    path
}

/// Elevation and azimuth (from +y towards +x) of a direction, degrees.
fn elevation_azimuth_deg(d: DVec3) -> (f64, f64) {
    (
        d.z.clamp(-1.0, 1.0).asin().to_degrees(),
        d.x.atan2(d.y).to_degrees(),
    )
}

/// Unit direction at elevation and azimuth (degrees, azimuth from +y towards +x).
fn direction_deg(elevation: f64, azimuth: f64) -> DVec3 {
    let (e, a) = (elevation.to_radians(), azimuth.to_radians());
    DVec3::new(e.cos() * a.sin(), e.cos() * a.cos(), e.sin())
}

fn within_deg(d: DVec3, centre: DVec3, radius_deg: f64) -> bool {
    d.dot(centre) >= radius_deg.to_radians().cos()
}

/// An office wall with a window (4000 cd/m²) and a sun of 10⁶ cd/m² in it.
fn sun_in_window(d: DVec3) -> f64 {
    let (el, az) = elevation_azimuth_deg(d);
    if within_deg(d, direction_deg(18.0, 12.0), 1.5) {
        1.0e6
    } else if (-25.0..25.0).contains(&az) && (0.0..35.0).contains(&el) {
        4000.0 + 30.0 * el
    } else {
        150.0 + 250.0 * d.z.max(0.0)
    }
}

/// A CIE-overcast-like sky above the horizon, a darker ground below.
fn overcast(d: DVec3) -> f64 {
    if d.z > 0.0 {
        3200.0 * (1.0 + 2.0 * d.z) / 3.0
    } else {
        350.0 - 100.0 * d.z
    }
}

/// A large bright patch with a smaller one 8° beside it (merged into it), one below the line
/// of sight (Iwata's index) and one far to the side.
fn patches(d: DVec3) -> f64 {
    if within_deg(d, direction_deg(8.0, -30.0), 7.0) {
        9000.0
    } else if within_deg(d, direction_deg(8.0, -15.5), 2.5) {
        6000.0
    } else if within_deg(d, direction_deg(-25.0, 20.0), 4.0) {
        3500.0
    } else if within_deg(d, direction_deg(30.0, 70.0), 5.0) {
        2600.0
    } else {
        250.0 + 100.0 * d.x.abs()
    }
}

/// A dim room: Ev well under 1000 lx, one small window.
fn dim(d: DVec3) -> f64 {
    let (el, az) = elevation_azimuth_deg(d);
    if (30.0..45.0).contains(&az) && (5.0..20.0).contains(&el) {
        2500.0
    } else {
        60.0 + 20.0 * d.z
    }
}

#[test]
fn synthetic_pictures_match_live_evalglare() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let fisheye = "-vta -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 180 -vv 180";
    let cases: [(&str, &str, &Scene, &[&str], GlareOptions); 7] = [
        (
            "sun_in_window",
            fisheye,
            &sun_in_window,
            &[],
            GlareOptions::default(),
        ),
        ("overcast", fisheye, &overcast, &[], GlareOptions::default()),
        ("patches", fisheye, &patches, &[], GlareOptions::default()),
        (
            "dim_low_light",
            fisheye,
            &dim,
            &["-C", "l+"],
            GlareOptions {
                low_light_correction: true,
                ..GlareOptions::default()
            },
        ),
        (
            "factor_threshold",
            fisheye,
            &patches,
            &["-b", "7"],
            GlareOptions {
                threshold: Some(7.0),
                ..GlareOptions::default()
            },
        ),
        (
            "perspective",
            "-vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 100 -vv 80",
            &sun_in_window,
            &[],
            GlareOptions::default(),
        ),
        (
            "hemispherical",
            "-vth -vp 0 0 0 -vd 0.3 1 0.1 -vu 0 0 1 -vh 180 -vv 180",
            &patches,
            &[],
            GlareOptions::default(),
        ),
    ];
    for (name, view, scene, args, options) in cases {
        let path = synthesize(dir.path(), name, view, 300, scene);
        let ours = evaluate_file(&path, &options);
        let theirs = run_evalglare(&bin, &lib, &path, args);
        println!("{name}: threshold {:.1} cd/m²", ours.threshold_cd_m2);
        compare(name, &ours, &theirs, 300.0, 0.01);
        assert!((ours.dgp - theirs.get("dgp")).abs() <= 0.01, "{name} DGP");
    }
}

/// A 4 × 6 × 3 m office with a 3 × 1.7 m window in its north wall (+y), RADIANCE syntax.
const ROOM: &str = "\
void plastic wall 0 0 5 0.6 0.6 0.6 0 0\n\
void plastic floor_mat 0 0 5 0.3 0.3 0.3 0 0\n\
void glass pane 0 0 3 0.96 0.96 0.96\n\
wall polygon south 0 0 12 0 0 0 4 0 0 4 0 3 0 0 3\n\
wall polygon west 0 0 12 0 0 0 0 0 3 0 6 3 0 6 0\n\
wall polygon east 0 0 12 4 0 0 4 6 0 4 6 3 4 0 3\n\
floor_mat polygon floor 0 0 12 0 0 0 0 6 0 4 6 0 4 0 0\n\
wall polygon ceiling 0 0 12 0 0 3 4 0 3 4 6 3 0 6 3\n\
wall polygon north_low 0 0 12 0 6 0 0 6 0.8 4 6 0.8 4 6 0\n\
wall polygon north_high 0 0 12 0 6 2.5 0 6 3 4 6 3 4 6 2.5\n\
wall polygon north_left 0 0 12 0 6 0.8 0 6 2.5 0.5 6 2.5 0.5 6 0.8\n\
wall polygon north_right 0 0 12 3.5 6 0.8 3.5 6 2.5 4 6 2.5 4 6 0.8\n\
pane polygon window 0 0 12 0.5 6 0.8 3.5 6 0.8 3.5 6 2.5 0.5 6 2.5\n\
";

/// The sky and ground glows of a gensky sky.
const SKY_GLOWS: &str = "\
skyfunc glow sky_glow 0 0 4 1 1 1 0\n\
sky_glow source sky 0 0 4 0 0 1 180\n\
skyfunc glow ground_glow 0 0 4 1 1 1 0\n\
ground_glow source ground 0 0 4 0 0 -1 180\n\
";

/// Renders the office with `rpict -vta` from its middle towards the window under the gensky
/// sky of `gensky_args`; returns the picture's path.
fn render_office(
    bin: &Path,
    lib: &Option<PathBuf>,
    dir: &Path,
    name: &str,
    gensky_args: &[&str],
) -> PathBuf {
    let mut gensky = tool(bin, lib, "gensky");
    gensky.args(gensky_args);
    let sky = String::from_utf8(check_output(gensky, None)).unwrap();
    let scene = dir.join(format!("{name}.rad"));
    std::fs::write(&scene, format!("{sky}\n{SKY_GLOWS}\n{ROOM}")).unwrap();
    let mut oconv = tool(bin, lib, "oconv");
    oconv.current_dir(dir).arg(&scene);
    let octree = dir.join(format!("{name}.oct"));
    std::fs::write(&octree, check_output(oconv, None)).unwrap();
    let mut rpict = tool(bin, lib, "rpict");
    rpict.current_dir(dir).args([
        "-vta", "-vp", "2", "1.5", "1.2", "-vd", "0", "1", "0", "-vu", "0", "0", "1", "-vh", "180",
        "-vv", "180", "-x", "240", "-y", "240", "-ab", "1", "-ad", "256", "-as", "0", "-aa",
        "0.15", "-ps", "2",
    ]);
    rpict.arg(&octree);
    let picture = dir.join(format!("{name}.hdr"));
    std::fs::write(&picture, check_output(rpict, None)).unwrap();
    picture
}

#[test]
fn rendered_office_matches_live_evalglare() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    // A low sun in the north seen through the window, a sun behind the viewer (out of view),
    // and an overcast sky.
    let skies: [(&str, &[&str]); 3] = [
        ("sun_in_view", &["-ang", "15", "180", "+s"]),
        ("sun_out_of_view", &["-ang", "40", "0", "+s"]),
        ("overcast", &["-ang", "40", "0", "-c", "-B", "100"]),
    ];
    for (name, gensky_args) in skies {
        let path = render_office(&bin, &lib, dir.path(), name, gensky_args);
        let ours = evaluate_file(&path, &GlareOptions::default());
        let theirs = run_evalglare(&bin, &lib, &path, &[]);
        compare(name, &ours, &theirs, 240.0, 0.01);
        assert!((ours.dgp - theirs.get("dgp")).abs() <= 0.01, "{name} DGP");
    }
}

/// The golden `band:` line RADIANCE's own test of evalglare expects (the corpus's
/// test_evalglare.cmake, for `-B 0.4` on the photograph).
fn golden_band_line() -> Vec<f64> {
    let path = corpus_dir().join("resources/cmake_tests/test_evalglare.cmake");
    let text = std::fs::read_to_string(&path).unwrap();
    let line = text
        .lines()
        .find(|l| l.contains("band:band_omega"))
        .unwrap_or_else(|| panic!("no band line in {}", path.display()));
    let values = line.rsplit_once(": ").unwrap().1;
    values
        .split_whitespace()
        .map(|t| t.trim_end_matches(['"', ')']).parse().unwrap())
        .collect()
}

#[test]
fn corpus_band_matches_radiance_golden_output() {
    let golden = golden_band_line();
    assert_eq!(golden.len(), 8);
    let options = GlareOptions {
        threshold: Some(2500.0),
        band_half_width_rad: Some(0.4),
        ..GlareOptions::default()
    };
    let band = evaluate_file(&corpus_image(), &options)
        .band
        .expect("a band");
    let ours = [
        band.solid_angle_sr,
        band.mean_luminance_cd_m2,
        band.median_luminance_cd_m2,
        band.std_luminance_cd_m2,
        band.percentile_75_cd_m2,
        band.percentile_95_cd_m2,
        band.min_luminance_cd_m2,
        band.max_luminance_cd_m2,
    ];
    println!("band ours {ours:?}\nband golden {golden:?}");
    for (k, (a, b)) in ours.iter().zip(&golden).enumerate() {
        assert!(
            (a - b).abs() <= 1e-3 * b.abs(),
            "band value {k}: ours {a}, golden {b}"
        );
    }
}

//! The camera model: forward and inverse maps invert each other, the orientation conventions
//! of campaign.md hold, solid angles integrate to the imaged cone, and device.toml is read
//! strictly.

use glam::DVec3;
use proptest::prelude::*;
use skylux_hps::camera::*;
use std::path::Path;

fn model(distortion: [f64; 4], az: f64, alt: f64, roll: f64) -> CameraModel {
    let mut c = DeviceConfig::default();
    c.lens.distortion = distortion;
    c.orientation = OrientationConfig {
        axis_azimuth_deg: az,
        axis_altitude_deg: alt,
        roll_deg: roll,
    };
    CameraModel::new(c)
}

fn angle_rad(a: DVec3, b: DVec3) -> f64 {
    // atan2 of |a x b| and a.b: accurate for tiny angles, unlike acos.
    a.normalize()
        .cross(b.normalize())
        .length()
        .atan2(a.normalize().dot(b.normalize()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]
    /// Direction -> pixel -> direction to 1e-9 rad, and the pixel round trip to 1e-6 px, over
    /// the whole imaged hemisphere and beyond, for realistic distortion and any orientation.
    #[test]
    fn project_and_unproject_invert_each_other(
        k1 in -0.05f64..0.05, k2 in -0.01f64..0.01, k3 in -0.002f64..0.002, k4 in -0.0005f64..0.0005,
        az in 0.0f64..360.0, alt in -90.0f64..90.0, roll in -180.0f64..180.0,
        theta in 0.0f64..1.75, phi in 0.0f64..std::f64::consts::TAU,
    ) {
        let m = model([k1, k2, k3, k4], az, alt, roll);
        prop_assume!(theta < m.max_theta_rad());
        let cam = DVec3::new(theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos());
        let world = m.world_to_camera.transpose() * cam;
        let p = m.project(world).unwrap();
        let back = m.unproject(p).unwrap();
        prop_assert!(angle_rad(world, back) < 1e-9, "error {} rad", angle_rad(world, back));
        let p2 = m.project(back).unwrap();
        prop_assert!((p.x_px - p2.x_px).abs() < 1e-6 && (p.y_px - p2.y_px).abs() < 1e-6);
    }
}

#[test]
fn orientation_follows_the_campaign_conventions() {
    let [cx, cy] = DeviceConfig::default().lens.center_px;
    // Facing south, 16° up: the axis lands on the principal point, a higher direction on a
    // smaller row, a direction to the west (right when facing south) on a larger column.
    let m = model([0.0; 4], 180.0, 16.0, 0.0);
    let axis = m.project(direction_from_alt_az(16.0, 180.0)).unwrap();
    assert!((axis.x_px - cx).abs() < 1e-9 && (axis.y_px - cy).abs() < 1e-9);
    let higher = m.project(direction_from_alt_az(30.0, 180.0)).unwrap();
    assert!(higher.y_px < cy - 100.0 && (higher.x_px - cx).abs() < 1e-6);
    let west = m.project(direction_from_alt_az(16.0, 200.0)).unwrap();
    assert!(west.x_px > cx + 100.0);
    // Equidistant lens: 30° off axis is f * π/6 pixels from the centre.
    let off = m.project(direction_from_alt_az(46.0, 180.0)).unwrap();
    assert!(((cy - off.y_px) - 1136.0 * std::f64::consts::FRAC_PI_6).abs() < 1e-6);
    // Facing the zenith, roll 0: north is image up, east is image left (seen from below).
    let z = model([0.0; 4], 0.0, 90.0, 0.0);
    let north = z.project(direction_from_alt_az(60.0, 0.0)).unwrap();
    let east = z.project(direction_from_alt_az(60.0, 90.0)).unwrap();
    assert!(north.y_px < cy - 100.0 && (north.x_px - cx).abs() < 1e-6);
    assert!(east.x_px < cx - 100.0 && (east.y_px - cy).abs() < 1e-6);
    // Roll 90° (right-handed about the axis): image up turns to what was image left, so north
    // now lands to the left... of where east was, i.e. at the former left/right axis.
    let rolled = model([0.0; 4], 0.0, 90.0, 90.0);
    let north_r = rolled.project(direction_from_alt_az(60.0, 0.0)).unwrap();
    assert!((north_r.y_px - cy).abs() < 1e-6 && (north_r.x_px - cx).abs() > 100.0);
    // Altitude/azimuth round trip.
    let (alt, az) = alt_az_from_direction(direction_from_alt_az(12.5, 271.0));
    assert!((alt - 12.5).abs() < 1e-12 && (az - 271.0).abs() < 1e-12);
}

/// Summing the per-pixel solid angle over every pixel within θ_max of the centre gives the
/// cone's 2π(1 − cos θ_max) (an independent closed form), for a distorted lens.
#[test]
fn pixel_solid_angles_integrate_to_the_cone() {
    // A short focal length keeps the pixel count small; the formula does not depend on it.
    let mut c = DeviceConfig::default();
    c.lens.focal_px = 150.0;
    c.lens.distortion = [0.02, -0.004, 0.0005, -0.0001];
    let m = CameraModel::new(c);
    let theta_max = 80f64.to_radians();
    let r_max = m.lens.radius_px(theta_max);
    let [cx, cy] = m.config.lens.center_px;
    let mut total = 0.0;
    let n = 4; // sub-samples per pixel side, for the edge
    for j in (cy - r_max - 2.0) as i64..(cy + r_max + 2.0) as i64 {
        for i in (cx - r_max - 2.0) as i64..(cx + r_max + 2.0) as i64 {
            for sj in 0..n {
                for si in 0..n {
                    let p = ImagePoint {
                        x_px: i as f64 + (si as f64 + 0.5) / n as f64,
                        y_px: j as f64 + (sj as f64 + 0.5) / n as f64,
                    };
                    if ((p.x_px - cx).powi(2) + (p.y_px - cy).powi(2)).sqrt() <= r_max {
                        total += m.solid_angle_per_px2(p).unwrap() / (n * n) as f64;
                    }
                }
            }
        }
    }
    let exact = std::f64::consts::TAU * (1.0 - theta_max.cos());
    assert!((total / exact - 1.0).abs() < 2e-4, "sum {total} vs {exact}");
}

#[test]
fn vignetting_polynomial_in_cos_alpha() {
    let mut c = DeviceConfig::default();
    c.lens.vignetting = vec![0.5, 0.3, 0.2];
    let m = CameraModel::new(c);
    assert!((m.vignetting(0.0) - 1.0).abs() < 1e-15);
    let a = 1.0f64;
    assert!((m.vignetting(a) - (0.5 + 0.3 * a.cos() + 0.2 * a.cos().powi(2))).abs() < 1e-15);
}

const SPEC_EXAMPLE: &str = r#"
[sensor]
black_level_dn = 0.0
valid_min_dn = 40
valid_max_dn = 3100
[response]
cg = 1.0
weights = [0.2, 0.7, 0.1]
[lens]
focal_px = 1136.0
center_px = [1296.0, 972.0]
distortion = [0.0, 0.0, 0.0, 0.0]
vignetting = [1.0, 0.0, 0.0, 0.0, 0.0]
[orientation]
axis_azimuth_deg = 180.0
axis_altitude_deg = 16.0
roll_deg = 0.0
"#;

#[test]
fn reads_the_spec_example_and_writes_it_back() {
    let (c, warnings) = DeviceConfig::parse(SPEC_EXAMPLE, Path::new("device.toml")).unwrap();
    assert!(warnings.is_empty());
    assert_eq!(c, DeviceConfig::default());
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("device.toml");
    let mut changed = c.clone();
    changed.lens.distortion = [0.01, -0.002, 1e-4, -1e-5];
    changed.write(&path).unwrap();
    assert_eq!(DeviceConfig::read(&path).unwrap().0, changed);
}

#[test]
fn unknown_keys_warn_and_bad_values_name_the_field() {
    let extended = format!("{SPEC_EXAMPLE}\n[filters]\nnd = 3\n")
        .replace("roll_deg = 0.0", "roll_deg = 0.0\nsource = \"bench\"");
    let (_, warnings) = DeviceConfig::parse(&extended, Path::new("d.toml")).unwrap();
    assert_eq!(warnings.len(), 2, "{warnings:?}");
    assert!(warnings.iter().any(|w| w.contains("orientation.source")));

    let cases = [
        ("cg = 1.0", "cg = nan", "response.cg"),
        ("cg = 1.0", "cg = -2.0", "response.cg"),
        ("focal_px = 1136.0", "focal_px = 0.0", "lens.focal_px"),
        (
            "valid_max_dn = 3100",
            "valid_max_dn = 20",
            "sensor.valid_min_dn",
        ),
        (
            "weights = [0.2, 0.7, 0.1]",
            "weights = [0.2, -0.7, 0.1]",
            "response.weights",
        ),
        (
            "axis_altitude_deg = 16.0",
            "axis_altitude_deg = 96.0",
            "orientation.axis_altitude_deg",
        ),
        (
            "distortion = [0.0, 0.0, 0.0, 0.0]",
            "distortion = [0.0, inf, 0.0, 0.0]",
            "lens.distortion",
        ),
    ];
    for (from, to, field) in cases {
        let e = DeviceConfig::parse(&SPEC_EXAMPLE.replace(from, to), Path::new("d.toml"))
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("d.toml: ") && e.contains(field), "{to}: {e}");
    }
    // Missing key and wrong type: named, with the line.
    let e = DeviceConfig::parse(&SPEC_EXAMPLE.replace("cg = 1.0\n", ""), Path::new("d.toml"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("cg"), "{e}");
    let e = DeviceConfig::parse(
        &SPEC_EXAMPLE.replace("focal_px = 1136.0", "focal_px = \"wide\""),
        Path::new("d.toml"),
    )
    .unwrap_err()
    .to_string();
    assert!(e.starts_with("d.toml: line 10:"), "{e}");
}

proptest! {
    /// The reader never panics, whatever the bytes.
    #[test]
    fn device_reader_never_panics(text in ".{0,400}", cut in 0usize..600, junk in "[\\[\\]=\"a-z0-9.\\n -]{0,40}") {
        let _ = DeviceConfig::parse(&text, Path::new("fuzz.toml"));
        let mut s = SPEC_EXAMPLE.to_string();
        let at = cut.min(s.len());
        s.insert_str(at, &junk);
        let _ = DeviceConfig::parse(&s, Path::new("fuzz.toml"));
    }
}

//! Sky patches: counts and solid angles as RADIANCE's gendaymtx defines them, every direction
//! in exactly one patch, and map aggregation with explicit filling.

use glam::DVec3;
use skylux_hps::camera::{CameraModel, DeviceConfig, OrientationConfig};
use skylux_hps::campaign::Readout;
use skylux_hps::hdr::{GroupGeometry, LuminanceMap, MapFlag};
use skylux_hps::sky::SkyPatches;

#[test]
fn counts_and_solid_angles_match_the_definition() {
    for (mf, count) in [(1, 145), (2, 577), (4, 2305), (6, 5185)] {
        let p = SkyPatches::reinhart(mf);
        assert_eq!(p.len(), count, "144 n^2 + 1 (hardware-facts.md §5.3)");
        let total: f64 = (0..p.len()).map(|i| p.solid_angle_sr(i)).sum();
        assert!(
            (total - std::f64::consts::TAU).abs() < 1e-6,
            "MF{mf}: {total}"
        );
    }
    // Tregenza: 12° bands centred at 6°, 18°, ... with 30 patches in the first band.
    let t = SkyPatches::tregenza();
    assert!((t.row_height_rad.to_degrees() - 12.0).abs() < 1e-12);
    let first = t.centre(0);
    assert!(
        (first.z.asin().to_degrees() - 6.0).abs() < 1e-9 && first.x.abs() < 1e-12 && first.y > 0.0,
        "first patch centred on north"
    );
    let second = t.centre(1);
    assert!(second.x > 0.0, "patches proceed towards east");
}

/// Monte-Carlo check of the solid angles: uniform directions on the hemisphere fall into each
/// patch in proportion to its solid angle, and every direction lands in exactly one patch
/// whose centre is its nearest in the row.
#[test]
fn directions_fall_into_patches_by_solid_angle() {
    use rand::{Rng, SeedableRng};
    let p = SkyPatches::reinhart(2);
    let mut rng = rand::rngs::StdRng::seed_from_u64(3);
    let n = 2_000_000;
    let mut hits = vec![0usize; p.len()];
    for _ in 0..n {
        let z: f64 = rng.gen_range(0.0..1.0); // uniform on the hemisphere: z uniform
        let phi: f64 = rng.gen_range(0.0..std::f64::consts::TAU);
        let r = (1.0 - z * z).sqrt();
        hits[p
            .patch_of(DVec3::new(r * phi.cos(), r * phi.sin(), z))
            .unwrap()] += 1;
    }
    let mut worst = 0.0f64;
    for (i, &h) in hits.iter().enumerate() {
        let expected = n as f64 * p.solid_angle_sr(i) / std::f64::consts::TAU;
        worst = worst.max(((h as f64 - expected) / expected.sqrt()).abs());
    }
    assert!(worst < 5.0, "worst deviation {worst} sigma");
    assert_eq!(
        p.patch_of(DVec3::new(0.0, 1.0, -0.01)),
        None,
        "below the horizon"
    );
    assert_eq!(p.patch_of(DVec3::Z), Some(p.len() - 1), "zenith cap");
}

/// A sky map of a known field, seen by a south-facing fisheye that misses the northern sky:
/// patches it sees get the field's mean; patches it misses are filled and listed.
#[test]
fn aggregation_measures_what_it_sees_and_fills_the_rest() {
    let mut device = DeviceConfig::default();
    device.lens.focal_px = 500.0;
    device.orientation = OrientationConfig {
        axis_azimuth_deg: 180.0,
        axis_altitude_deg: 20.0,
        roll_deg: 0.0,
    };
    let camera = CameraModel::new(device);
    let readout = Readout {
        col_start: 0,
        row_start: 0,
        skip: 1,
        bin: 1,
    };
    let geometry = GroupGeometry::new(&camera, &readout, 2592, 1944);
    let field = |d: DVec3| 1000.0 * (1.0 + 2.0 * d.z) / 3.0;
    let n = geometry.width * geometry.height;
    let luminance: Vec<f32> = geometry
        .direction
        .iter()
        .map(|d| {
            if d.is_finite() {
                field(d.as_dvec3()) as f32
            } else {
                f32::NAN
            }
        })
        .collect();
    let flags = geometry
        .direction
        .iter()
        .map(|d| {
            if d.is_finite() {
                MapFlag::Valid
            } else {
                MapFlag::UnderRange
            }
        })
        .collect();
    let map = LuminanceMap {
        width: geometry.width,
        height: geometry.height,
        luminance_cd_m2: luminance,
        flags,
        relative_sigma: vec![0.0; n],
    };
    let patches = SkyPatches::tregenza();
    let sky = patches.aggregate(&map, &geometry.direction, &geometry.solid_angle_sr, 0.5);
    assert!(!sky.filled.is_empty() && sky.filled.len() < patches.len());
    let north = patches.patch_of(DVec3::new(0.0, 1.0, 0.1)).unwrap();
    let south = patches.patch_of(DVec3::new(0.0, -1.0, 0.1)).unwrap();
    assert!(sky.filled.contains(&north) && !sky.filled.contains(&south));
    for p in 0..patches.len() {
        if sky.filled.contains(&p) {
            assert!(
                sky.luminance_cd_m2[p].is_finite(),
                "filled patch {p} has a value"
            );
            continue;
        }
        // The patch's band [a, b] in altitude; (1 + 2 sin h)/3 averaged over it with the solid
        // angle weight cos h dh is (1 + sin a + sin b)/3, the exact patch mean when fully seen.
        let centre_alt = patches.centre(p).z.asin();
        let half = patches.row_height_rad / 2.0;
        let (a, b) = if p == patches.len() - 1 {
            (centre_alt - half, centre_alt)
        } else {
            (centre_alt - half, centre_alt + half)
        };
        let l = sky.luminance_cd_m2[p];
        if sky.coverage[p] > 0.99 && p != patches.len() - 1 {
            let exact = 1000.0 * (1.0 + a.sin() + b.sin()) / 3.0;
            assert!((l / exact - 1.0).abs() < 0.005, "patch {p}: {l} vs {exact}");
        } else {
            assert!(
                l >= field(DVec3::new(0.0, a.cos(), a.sin())) * 0.999 && l <= 1000.0 * 1.001,
                "patch {p}: {l} outside its band"
            );
        }
    }
}

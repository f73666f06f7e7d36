//! The room's glazing as the loop needs it: per glazing plane, the outward normal (towards
//! the sky), the glazed area and its centroid. The solar incidence angle on the glazing and
//! the sensors' distance from the façade (residual variables) and the glazing's angular
//! transmittance (`effect_glazing_angular`) are read from it.
//!
//! The windows are the engine's portals ([`World::portal_polygons`]): glass or invisible
//! polygons with a side open to the outside, found once when the world is built. A `trans`
//! surface scatters what it transmits, so a direction outside does not tell at which angle
//! the light crossed it; it is not a portal and not glazing here.

use super::prediction::Param;
use super::terms::Terms;
use crate::engine::{DaylightCoefficients, World};
use glam::DVec3;

/// Normals within this angle, degrees, are one plane.
const SAME_NORMAL_DEG: f64 = 1.0;
/// Plane offsets within this distance, metres, are one plane.
const SAME_OFFSET_M: f64 = 0.01;

/// One plane of glazing (coplanar panes together).
#[derive(Clone, Debug, PartialEq)]
pub struct GlazingPlane {
    /// Unit normal pointing out of the room, towards the sky.
    pub normal_out: DVec3,
    /// Glazed area, m².
    pub area_m2: f64,
    /// Area-weighted centroid of the panes, m.
    pub centroid_m: DVec3,
    /// The panes' surface names.
    pub surfaces: Vec<String>,
}

impl GlazingPlane {
    /// Angle between unit direction `towards` (e.g. the sun) and the outward normal, degrees:
    /// the incidence angle of light arriving from `towards`. NaN when `towards` is below the
    /// horizon or behind the plane (no light from there crosses this glazing).
    pub fn incidence_deg(&self, towards: DVec3) -> f64 {
        let cos = self.normal_out.dot(towards);
        if !towards.is_finite() || towards.z <= 0.0 || cos <= 0.0 {
            return f64::NAN;
        }
        cos.clamp(-1.0, 1.0).acos().to_degrees()
    }

    /// Distance of point `p` from the plane, metres, positive on the room's side.
    pub fn depth_m(&self, p: DVec3) -> f64 {
        (self.centroid_m - p).dot(self.normal_out)
    }
}

/// All the glazing of a room, largest plane first.
#[derive(Clone, Debug, PartialEq)]
pub struct Glazing {
    pub planes: Vec<GlazingPlane>,
}

/// Why a room's glazing could not be described.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum GlazingError {
    #[error("the scene has no window: no glass or invisible polygon opens to the outside")]
    NoWindow,
    #[error("window `{0}`: both of its sides open to the outside, so which way is out is unknown")]
    BothSidesOpen(String),
    #[error("window `{0}`: degenerate polygon (no area)")]
    Degenerate(String),
}

/// Newell's normal (not normalised: its length is twice the area) and the area-weighted
/// centroid of a planar polygon.
fn normal_and_centroid(v: &[DVec3]) -> (DVec3, DVec3) {
    let mut n = DVec3::ZERO;
    for i in 0..v.len() {
        let (a, b) = (v[i], v[(i + 1) % v.len()]);
        n += DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    let (mut c, mut w) = (DVec3::ZERO, 0.0);
    for i in 1..v.len().saturating_sub(1) {
        let a = 0.5
            * (v[i] - v[0])
                .cross(v[i + 1] - v[0])
                .dot(n.normalize_or_zero());
        c += a * (v[0] + v[i] + v[i + 1]) / 3.0;
        w += a;
    }
    let centroid = if w.abs() > 1e-12 {
        c / w
    } else {
        v.iter().copied().sum::<DVec3>() / v.len().max(1) as f64
    };
    (n, centroid)
}

impl Glazing {
    /// The glazing of `world`: its portal polygons grouped by plane, each with the normal of
    /// the side from which rays leave the scene (nine rays per side from the pane's centre:
    /// the normal and eight at 60° from it; the side with more escapes is outside).
    pub fn of_world(world: &World) -> Result<Self, GlazingError> {
        let mut planes: Vec<(GlazingPlane, f64, DVec3)> = Vec::new();
        for (primitive, name, vertices) in world.portal_polygons() {
            let (n, centroid) = normal_and_centroid(vertices);
            let area = 0.5 * n.length();
            if area.is_nan() || area <= 1e-9 || !centroid.is_finite() {
                return Err(GlazingError::Degenerate(name.to_string()));
            }
            let n = n / (2.0 * area);
            let escapes = |side: DVec3| -> usize {
                let (u, v) = crate::engine::sampling::basis(side);
                let mut dirs = vec![side];
                for k in 0..8 {
                    let phi = k as f64 * std::f64::consts::FRAC_PI_4;
                    dirs.push(
                        (side * 0.5 + (u * phi.cos() + v * phi.sin()) * 0.75_f64.sqrt())
                            .normalize(),
                    );
                }
                dirs.into_iter()
                    .filter(|d| {
                        world.shadow_transmission(centroid, Some(primitive), *d) != DVec3::ZERO
                    })
                    .count()
            };
            let (front, back) = (escapes(n), escapes(-n));
            let out = match front.cmp(&back) {
                std::cmp::Ordering::Greater => n,
                std::cmp::Ordering::Less => -n,
                std::cmp::Ordering::Equal => {
                    return Err(GlazingError::BothSidesOpen(name.to_string()))
                }
            };
            let offset = out.dot(centroid);
            let same = planes.iter_mut().find(|(p, o, _)| {
                p.normal_out.dot(out) >= SAME_NORMAL_DEG.to_radians().cos()
                    && (o - offset).abs() <= SAME_OFFSET_M
            });
            match same {
                Some((p, _, weighted)) => {
                    *weighted += area * centroid;
                    p.area_m2 += area;
                    p.centroid_m = *weighted / p.area_m2;
                    p.surfaces.push(name.to_string());
                }
                None => planes.push((
                    GlazingPlane {
                        normal_out: out,
                        area_m2: area,
                        centroid_m: centroid,
                        surfaces: vec![name.to_string()],
                    },
                    offset,
                    area * centroid,
                )),
            }
        }
        if planes.is_empty() {
            return Err(GlazingError::NoWindow);
        }
        let mut planes: Vec<GlazingPlane> = planes.into_iter().map(|(p, _, _)| p).collect();
        planes.sort_by(|a, b| b.area_m2.total_cmp(&a.area_m2));
        Ok(Self { planes })
    }

    /// The largest plane.
    pub fn primary(&self) -> &GlazingPlane {
        &self.planes[0]
    }

    /// Whether every plane faces the same way (within 1°): then the angle at which a ray
    /// leaving the room along a direction crossed the glazing is known from the direction
    /// alone.
    pub fn single_orientation(&self) -> bool {
        let n = self.primary().normal_out;
        self.planes
            .iter()
            .all(|p| p.normal_out.dot(n) >= SAME_NORMAL_DEG.to_radians().cos())
    }

    /// Distance of `p` from the nearest glazing plane on whose room side it is, metres (NaN
    /// if it is on the room side of none).
    pub fn facade_distance_m(&self, p: DVec3) -> f64 {
        self.planes
            .iter()
            .map(|g| g.depth_m(p))
            .filter(|d| *d >= 0.0)
            .fold(f64::NAN, f64::min)
    }
}

/// The glazing's angular transmittance beyond the scene's glass: ASHRAE's incidence-angle
/// modifier parameter b0 (`glazing_angular`). Applied to the terms ([`AngularGlazing::apply`]),
/// so terms computed afresh need it re-applied.
pub const GLAZING_ANGULAR_B0: Param = Param {
    key: "glazing_angular.b0",
    default: 0.0,
};

/// The angular transmittance model: ASHRAE's one-parameter incidence-angle modifier (Souka &
/// Safwat 1966, "Determination of the optimum orientations for the double-exposure, flat-plate
/// collector and its reflectors", Solar Energy 10(4); ASHRAE Standard 93; pvlib `iam.ashrae`,
/// b0 = 0.05 for clean glass): IAM(θ) = 1 − b0 (1/cos θ − 1), clamped to [0, 1]. Since
/// RADIANCE-style glass does not refract, light that reaches a sensor from the sky direction d
/// crossed the glazing at the angle between d and the glazing's outward normal.
/// ASHRAE's incidence-angle modifier at cosine of incidence `cos_theta`, clamped to [0, 1];
/// 0 at or beyond grazing incidence.
pub fn iam_ashrae(cos_theta: f64, b0: f64) -> f64 {
    if cos_theta.is_nan() || cos_theta <= 0.0 {
        return 0.0;
    }
    (1.0 - b0 * (1.0 / cos_theta.min(1.0) - 1.0)).clamp(0.0, 1.0)
}

/// Per bin (sky patches, then mirrored ground patches), the cosine of incidence on glazing
/// of outward normal `normal_out` of light arriving from the bin's centre.
pub fn bin_cosines(dc: &DaylightCoefficients, normal_out: DVec3) -> Vec<f64> {
    let patches = dc.patches();
    let n = patches.len();
    (0..2 * n)
        .map(|b| {
            let c = patches.centre(b % n);
            let d = if b < n { c } else { DVec3::new(c.x, c.y, -c.z) };
            d.dot(normal_out)
        })
        .collect()
}

/// The terms with the glazing's angular transmittance of parameter `b0` applied to every sky
/// and ground bin and to the sun: `base` must be the terms without it (as
/// [`crate::model::capture_terms`] computes them).
pub fn apply_glazing_angular(
    dc: &DaylightCoefficients,
    cosines: &[f64],
    normal_out: DVec3,
    base: &[Terms],
    b0: f64,
) -> Vec<Terms> {
    let factor: Vec<f64> = cosines.iter().map(|c| iam_ashrae(*c, b0)).collect();
    let sensors = dc.sensors.len();
    let n = cosines.len() / 2;
    base.iter()
        .map(|t| {
            let mut out = t.clone();
            if t.bins_with_sun_cd_m2.len() != cosines.len() {
                return out;
            }
            let apply = |lum: &[f64]| -> Vec<f64> {
                (0..sensors)
                    .map(|s| {
                        dc.row(s)
                            .iter()
                            .zip(lum)
                            .zip(&factor)
                            .filter(|((_, l), _)| l.is_finite())
                            .map(|((c, l), f)| c * l * f)
                            .sum()
                    })
                    .collect()
            };
            out.sky_with_sun_lux = apply(&t.bins_with_sun_cd_m2);
            out.sky_without_sun_lux = apply(&t.bins_without_sun_cd_m2);
            out.unseen_ground_lux_per_cd_m2 = (0..sensors)
                .map(|s| {
                    (0..n)
                        .filter(|&p| !t.bin_seen[n + p])
                        .map(|p| dc.row(s)[n + p] * factor[n + p])
                        .sum()
                })
                .collect();
            if let Some(sun) = &t.sun {
                let f = iam_ashrae(sun.direction.dot(normal_out), b0);
                for k in &mut out.sun_lux_per_dn_lux {
                    *k *= f;
                }
            }
            out
        })
        .collect()
}

/// The glazing the effect acts on: the room's daylight coefficients (a copy: the loop keeps
/// the room mutable), the bins' cosines of incidence and the outward normal.
pub struct AngularGlazing {
    pub dc: DaylightCoefficients,
    pub normal_out: DVec3,
    pub cosines: Vec<f64>,
    /// Per sensor, the distance from the glazing plane, m (for the evidence).
    pub sensor_depth_m: Vec<f64>,
}

impl AngularGlazing {
    pub fn new(dc: &DaylightCoefficients, normal_out: DVec3, sensor_depth_m: Vec<f64>) -> Self {
        Self {
            dc: dc.clone(),
            normal_out,
            cosines: bin_cosines(dc, normal_out),
            sensor_depth_m,
        }
    }

    /// `base` (terms without the effect) with the effect of parameter `b0`.
    pub fn apply(&self, base: &[Terms], b0: f64) -> Vec<Terms> {
        apply_glazing_angular(&self.dc, &self.cosines, self.normal_out, base, b0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn world(text: &str) -> World {
        let scene = crate::scene::parse("test.rad", text.as_bytes()).unwrap();
        World::new(&scene).unwrap()
    }

    const BOX: &str = "void plastic w 0 0 5 .5 .5 .5 0 0
void glass g 0 0 3 .7 .7 .7
w polygon floor 0 0 12 0 0 0  0 4 0  3 4 0  3 0 0
w polygon ceiling 0 0 12 0 0 3  3 0 3  3 4 3  0 4 3
w polygon west 0 0 12 0 0 0  0 0 3  0 4 3  0 4 0
w polygon east 0 0 12 3 0 0  3 4 0  3 4 3  3 0 3
w polygon back 0 0 12 0 4 0  0 4 3  3 4 3  3 4 0
w polygon below 0 0 12 0 0 0  3 0 0  3 0 1  0 0 1
w polygon above 0 0 12 0 0 2  3 0 2  3 0 3  0 0 3
w polygon left 0 0 12 0 0 1  1 0 1  1 0 2  0 0 2
w polygon right 0 0 12 2 0 1  3 0 1  3 0 2  2 0 2
";

    /// A 3 × 4 × 3 m box with a 1 × 1 m pane in its y = 0 wall: the outward normal is −y,
    /// whichever way the pane's vertices turn, and the centroid is the pane's centre.
    #[test]
    fn one_pane_in_a_box() {
        for pane in [
            "g polygon pane 0 0 12 1 0 1  2 0 1  2 0 2  1 0 2",
            "g polygon pane 0 0 12 1 0 1  1 0 2  2 0 2  2 0 1",
        ] {
            let g = Glazing::of_world(&world(&format!("{BOX}{pane}\n"))).unwrap();
            assert_eq!(g.planes.len(), 1);
            let p = g.primary();
            assert!((p.normal_out - DVec3::new(0.0, -1.0, 0.0)).length() < 1e-12);
            assert!((p.area_m2 - 1.0).abs() < 1e-12);
            assert!((p.centroid_m - DVec3::new(1.5, 0.0, 1.5)).length() < 1e-12);
            assert_eq!(p.surfaces, vec!["pane".to_string()]);
            // Sun due south at 30° altitude: incidence 30°; from the north: behind.
            let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
            assert!((p.incidence_deg(DVec3::new(0.0, -c, s)) - 30.0).abs() < 1e-9);
            assert!(p.incidence_deg(DVec3::new(0.0, c, s)).is_nan());
            assert!(p
                .incidence_deg(DVec3::new(0.0, -1.0, -0.1).normalize())
                .is_nan());
            assert!((g.facade_distance_m(DVec3::new(1.5, 2.5, 0.8)) - 2.5).abs() < 1e-12);
            assert!(g.facade_distance_m(DVec3::new(1.5, -1.0, 0.8)).is_nan());
        }
    }

    #[test]
    fn no_window_is_an_error_not_a_panic() {
        let closed = format!("{BOX}w polygon pane 0 0 12 1 0 1  2 0 1  2 0 2  1 0 2\n");
        assert_eq!(
            Glazing::of_world(&world(&closed)),
            Err(GlazingError::NoWindow)
        );
        // A free-standing pane: both sides open.
        let free =
            "void glass g 0 0 3 .7 .7 .7\ng polygon pane 0 0 12 0 0 0  1 0 0  1 0 1  0 0 1\n";
        assert!(matches!(
            Glazing::of_world(&world(free)),
            Err(GlazingError::BothSidesOpen(_))
        ));
    }

    /// The reference room, against its geometry read by hand from `scene.rad`: six panes in
    /// the façade y = 0 facing south (x 0.15–0.976667, 1.03667–1.86333, 1.92333–2.75; z
    /// 0.5–1.4425 and 1.5025–2.445), 4.6748 m² in all (the scene's own comment), centroid
    /// at x = 1.45 (symmetric) and z the area-weighted mean of the two rows' centres.
    #[test]
    fn reference_room() {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../../shared/scenes/test-module/scene.rad"
        );
        let Ok(scene) = crate::scene::load(path) else {
            eprintln!("{path} not present; skipped");
            return;
        };
        let g = Glazing::of_world(&World::new(&scene).unwrap()).unwrap();
        assert_eq!(g.planes.len(), 1);
        assert!(g.single_orientation());
        let p = g.primary();
        assert_eq!(p.surfaces.len(), 6);
        assert!((p.normal_out - DVec3::new(0.0, -1.0, 0.0)).length() < 1e-9);
        let w = [0.976667 - 0.15, 1.86333 - 1.03667, 2.75 - 1.92333];
        let (h1, h2) = (1.4425 - 0.5, 2.445 - 1.5025);
        let area = w.iter().sum::<f64>() * (h1 + h2);
        assert!((area - 4.6748).abs() < 1e-3, "{area}");
        assert!((p.area_m2 - area).abs() < 1e-9, "{}", p.area_m2);
        let z = (h1 * (0.5 + 1.4425) / 2.0 + h2 * (1.5025 + 2.445) / 2.0) / (h1 + h2);
        let x = w
            .iter()
            .zip([0.15, 1.03667, 1.92333])
            .map(|(w, x0)| w * (x0 + w / 2.0))
            .sum::<f64>()
            / w.iter().sum::<f64>();
        assert!((x - 1.45).abs() < 1e-3);
        assert!(
            (p.centroid_m - DVec3::new(x, 0.0, z)).length() < 1e-9,
            "{:?}",
            p.centroid_m
        );
        // The sensors at 1 and 4.7 m from the façade.
        assert!((g.facade_distance_m(DVec3::new(1.45, 1.0, 0.8)) - 1.0).abs() < 1e-12);
        assert!((g.facade_distance_m(DVec3::new(1.45, 4.7, 0.8)) - 4.7).abs() < 1e-12);
    }
}

#[cfg(test)]
mod angular_tests {
    use super::*;
    use crate::model::CaptureTerms;

    /// pvlib's `iam.ashrae` at b = 0.05: 60° → 1 − 0.05 (2 − 1) = 0.95; 80° →
    /// 1 − 0.05 (5.758770 − 1) = 0.7620615; 0 at 90° and beyond; 1 at normal incidence.
    #[test]
    fn ashrae_modifier() {
        let c = |deg: f64| deg.to_radians().cos();
        assert!((iam_ashrae(c(60.0), 0.05) - 0.95).abs() < 1e-12);
        assert!((iam_ashrae(c(80.0), 0.05) - 0.7620615).abs() < 1e-6);
        assert_eq!(iam_ashrae(1.0, 0.3), 1.0);
        assert_eq!(iam_ashrae(0.0, 0.05), 0.0);
        assert_eq!(iam_ashrae(-0.5, 0.05), 0.0);
        assert_eq!(iam_ashrae(f64::NAN, 0.05), 0.0);
        // Clamped at grazing: 1/cos − 1 > 1/b0.
        assert_eq!(iam_ashrae(c(89.0), 0.05), 0.0);
    }

    /// One sensor lit by one sky bin and one unseen ground bin: the applied terms are the
    /// coefficients times the luminance times the IAM of each bin centre's incidence on a
    /// south-facing glazing, computed here from the patch centres.
    #[test]
    fn bins_are_rescaled_by_their_incidence() {
        let patches = crate::sky::SkyPatches::reinhart(1);
        let n = patches.len();
        let normal = DVec3::new(0.0, -1.0, 0.0);
        // A southern sky patch and the mirror of another as unseen ground.
        let sky = (0..n).find(|&p| patches.centre(p).y < -0.5).unwrap();
        let ground = (0..n).find(|&p| patches.centre(p).y < -0.8).unwrap();
        let mut coefficients = vec![0.0; 2 * n];
        coefficients[sky] = 0.3;
        coefficients[n + ground] = 0.2;
        let dc = DaylightCoefficients {
            sensors: vec!["S1".into()],
            mf: 1,
            bins: 2 * n,
            lux_per_cd_m2: coefficients,
            samples_per_sensor: 1,
        };
        let mut lum = vec![1000.0; 2 * n];
        lum[n + ground] = f64::NAN;
        let mut seen = vec![true; 2 * n];
        seen[n + ground] = false;
        let terms = CaptureTerms {
            sun: None,
            sun_missing: Some(crate::model::terms::SunMissing::BelowHorizon {
                altitude_deg: -10.0,
            }),
            sky_with_sun_lux: vec![300.0],
            sky_without_sun_lux: vec![300.0],
            sun_lux_per_dn_lux: vec![0.0],
            sun_dn_lux: 0.0,
            unseen_ground_lux_per_cd_m2: vec![0.2],
            outdoor_horizontal_lux: 1.0,
            unseen_sky_fraction: 0.0,
            saturated_fraction: 0.0,
            bins_with_sun_cd_m2: lum.clone(),
            bins_without_sun_cd_m2: lum,
            bin_seen: seen,
        };
        let b0 = 0.2;
        let g = AngularGlazing::new(&dc, normal, vec![1.0]);
        let terms = Terms::new(terms);
        let out = &g.apply(std::slice::from_ref(&terms), b0)[0];
        let iam = |d: DVec3| {
            let cos = -d.y;
            (1.0 - b0 * (1.0 / cos - 1.0)).clamp(0.0, 1.0)
        };
        let c = patches.centre(sky);
        let expect = 0.3 * 1000.0 * iam(c);
        assert!(iam(c) < 0.99);
        assert!((out.sky_without_sun_lux[0] - expect).abs() < 1e-9);
        assert!((out.sky_with_sun_lux[0] - expect).abs() < 1e-9);
        let cg = patches.centre(ground);
        let expect = 0.2 * iam(DVec3::new(cg.x, cg.y, -cg.z));
        assert!((out.unseen_ground_lux_per_cd_m2[0] - expect).abs() < 1e-12);
        // b0 = 0 leaves the terms as they were.
        let same = &g.apply(std::slice::from_ref(&terms), 0.0)[0];
        assert!((same.sky_without_sun_lux[0] - 300.0).abs() < 1e-9);
        assert!((same.unseen_ground_lux_per_cd_m2[0] - 0.2).abs() < 1e-12);
    }
}

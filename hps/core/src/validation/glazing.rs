//! The room's glazing as the loop needs it: per glazing plane, the outward normal (towards
//! the sky), the glazed area and its centroid. The solar incidence angle on the glazing and
//! the sensors' distance from the façade (residual variables) and the glazing's angular
//! transmittance (`effect_glazing_angular`) are read from it.
//!
//! The windows are the engine's portals ([`World::portal_polygons`]): glass or invisible
//! polygons with a side open to the outside, found once when the world is built. A `trans`
//! surface scatters what it transmits, so a direction outside does not tell at which angle
//! the light crossed it; it is not a portal and not glazing here.

use crate::engine::World;
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
                let (u, v) = crate::engine::material::basis(side);
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

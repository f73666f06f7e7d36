//! The window of the matrix methods: its polygons, and the Klems frame `rfluxmtx` gives a
//! surface declared `#@rfluxmtx h=kf u=<up>` (RADIANCE `klems_full.cal` `kbin`, RHS = 1):
//! z the polygons' front normal (into the room, as RADIANCE's WINDOW data expects), y the up
//! vector made perpendicular to it, x = y × z. A patch of the basis stands for light
//! travelling *into the room* along the patch's direction in that frame: a sensor ray meeting
//! the window from the room with direction d is in the patch of −d (V's columns), and the
//! daylight matrix's sender ray for a patch leaves outward along minus the patch's direction
//! (D's rows; `rfluxmtx`'s `sample_klems`, checked against its output by the tests).

use crate::bsdf::AngleBasis;
use crate::engine::ray::Ray;
use crate::scene::{self, Polygon, Shape};
use glam::DVec3;
use std::path::Path;

/// A window file that cannot be used.
#[derive(Debug, thiserror::Error)]
pub enum WindowError {
    #[error("{0}")]
    Scene(#[from] scene::SceneError),
    #[error("{at}: {message}")]
    Geometry { at: String, message: String },
}

/// The window: one or more coplanar-facing polygons and their Klems frame.
#[derive(Debug, Clone)]
pub struct KlemsWindow {
    polygons: Vec<Polygon>,
    /// Front normal, into the room.
    pub normal: DVec3,
    /// Frame axes x, y (z is `normal`).
    x: DVec3,
    y: DVec3,
    pub basis: AngleBasis,
    /// Triangles of the polygons (fans) and their running areas, for uniform points.
    triangles: Vec<[DVec3; 3]>,
    cumulative_area_m2: Vec<f64>,
}

impl KlemsWindow {
    /// A window of `polygons` (all facing one way), with the `up` vector of its frame.
    /// `at` names where they come from in errors.
    pub fn new(
        polygons: Vec<Polygon>,
        up: DVec3,
        basis: AngleBasis,
        at: &str,
    ) -> Result<Self, WindowError> {
        let bad = |message: String| WindowError::Geometry {
            at: at.to_string(),
            message,
        };
        let first = polygons
            .first()
            .ok_or_else(|| bad("no polygon: the window needs at least one".into()))?;
        let normal = first.normal;
        if let Some(p) = polygons.iter().find(|p| p.normal.dot(normal) < 1.0 - 1e-6) {
            return Err(bad(format!(
                "polygons face different ways ({:?} and {:?}): one window faces one way",
                normal, p.normal
            )));
        }
        let up_perp = up - up.dot(normal) * normal;
        if !up.is_finite() || up_perp.length() < 1e-6 * up.length().max(1e-300) {
            return Err(bad(format!(
                "up vector {up:?} is parallel to the window normal {normal:?}: give another"
            )));
        }
        let y = up_perp.normalize();
        let x = y.cross(normal);
        let mut triangles = Vec::new();
        for p in &polygons {
            let v = &p.vertices_m;
            for k in 1..v.len().saturating_sub(1) {
                triangles.push([v[0], v[k], v[k + 1]]);
            }
        }
        let mut total = 0.0;
        let cumulative_area_m2 = triangles
            .iter()
            .map(|t| {
                total += 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).length();
                total
            })
            .collect();
        Ok(KlemsWindow {
            polygons,
            normal,
            x,
            y,
            basis,
            triangles,
            cumulative_area_m2,
        })
    }

    /// Every surface of a RADIANCE scene file, which must all be polygons (`rfluxmtx`'s
    /// receiver file; modifiers are ignored).
    pub fn load(path: &Path, up: DVec3, basis: AngleBasis) -> Result<Self, WindowError> {
        let scene = scene::load(path)?;
        let mut polygons = Vec::new();
        for s in scene.surfaces() {
            match &s.shape {
                Shape::Polygon(p) => polygons.push(p.clone()),
                other => {
                    return Err(WindowError::Geometry {
                        at: s.origin.to_string(),
                        message: format!(
                            "window surface `{}` is a {}, not a polygon",
                            s.name,
                            other.type_name()
                        ),
                    })
                }
            }
        }
        Self::new(polygons, up, basis, &path.display().to_string())
    }

    /// Total area, m².
    pub fn area_m2(&self) -> f64 {
        self.cumulative_area_m2.last().copied().unwrap_or(0.0)
    }

    /// The patch of light travelling into the room along unit `propagation` (None when it
    /// travels outward).
    pub fn patch_of_arrival(&self, propagation: DVec3) -> Option<usize> {
        let local = DVec3::new(
            propagation.dot(self.x),
            propagation.dot(self.y),
            propagation.dot(self.normal),
        );
        self.basis.patch_of(local)
    }

    /// The direction light of `patch` travels into the room, for `u` in [0,1)² uniform in
    /// projected solid angle over the patch.
    pub fn arrival_direction(&self, patch: usize, u: [f64; 2]) -> DVec3 {
        let l = self.basis.direction_in_patch(patch, u);
        l.x * self.x + l.y * self.y + l.z * self.normal
    }

    /// A world direction in the window's frame (x, y, z = the front normal, into the room):
    /// the frame of the window's BSDF too (RADIANCE `SDcompXform` with the same up vector).
    pub fn to_local(&self, v: DVec3) -> DVec3 {
        DVec3::new(v.dot(self.x), v.dot(self.y), v.dot(self.normal))
    }

    /// `n` × `n` points over the window, one per cell of a grid of `u` (stratified in area):
    /// each stands for area / n² of the window.
    pub fn grid_points(&self, n: usize) -> Vec<DVec3> {
        let cell = |k: usize| (k as f64 + 0.5) / n as f64;
        (0..n)
            .flat_map(|i| (0..n).map(move |j| [cell(i), cell(j)]))
            .map(|u| self.sample_point(u))
            .collect()
    }

    /// Whether `polygon` is part of the window's glazing: in the window's plane (within
    /// `PLANE_TOLERANCE_M`) with its centroid inside one of the window's polygons.
    pub fn holds(&self, polygon: &Polygon) -> bool {
        let Some(first) = self.polygons.first() else {
            return false;
        };
        let origin = first.vertices_m[0];
        let in_plane = polygon
            .vertices_m
            .iter()
            .all(|v| (*v - origin).dot(self.normal).abs() <= PLANE_TOLERANCE_M);
        if !in_plane || polygon.vertices_m.is_empty() {
            return false;
        }
        let centroid =
            polygon.vertices_m.iter().copied().sum::<DVec3>() / polygon.vertices_m.len() as f64;
        // A ray from just inside the room back through the centroid crosses the window there.
        let probe = Ray::new(centroid + self.normal * 0.01, -self.normal);
        self.crosses(&probe)
    }

    /// A point uniform over the window's area for `u` in [0,1)².
    pub fn sample_point(&self, u: [f64; 2]) -> DVec3 {
        let target = u[0] * self.area_m2();
        let k = self
            .cumulative_area_m2
            .partition_point(|&a| a <= target)
            .min(self.triangles.len().saturating_sub(1));
        let [a, b, c] = self.triangles[k];
        // The triangle's own share of u[0], re-stretched to [0,1).
        let lo = if k == 0 {
            0.0
        } else {
            self.cumulative_area_m2[k - 1]
        };
        let span = self.cumulative_area_m2[k] - lo;
        let s = if span > 0.0 {
            ((target - lo) / span).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let r = s.sqrt();
        a * (1.0 - r) + b * (r * (1.0 - u[1])) + c * (r * u[1])
    }

    /// Does `ray` cross one of the window's polygons ahead of its origin?
    pub fn crosses(&self, ray: &Ray) -> bool {
        self.polygons.iter().any(|p| crosses_polygon(p, ray))
    }
}

/// How far from the window's plane a glazing polygon may lie, m (a pane's thickness is
/// modelled apart; 1 mm absorbs rounding in exported models).
const PLANE_TOLERANCE_M: f64 = 1e-3;

/// Ray against a planar polygon: the plane's crossing, then an even-odd test in the plane.
fn crosses_polygon(p: &Polygon, ray: &Ray) -> bool {
    let denominator = ray.direction.dot(p.normal);
    if denominator.abs() < 1e-12 {
        return false;
    }
    let t = (p.vertices_m[0] - ray.origin_m).dot(p.normal) / denominator;
    if t.is_nan() || t <= 0.0 {
        return false;
    }
    let hit = ray.origin_m + t * ray.direction;
    // Drop the normal's largest axis and test in the other two.
    let n = p.normal.abs();
    let (i, j) = if n.x >= n.y && n.x >= n.z {
        (1, 2)
    } else if n.y >= n.z {
        (0, 2)
    } else {
        (0, 1)
    };
    let (hx, hy) = (hit[i], hit[j]);
    let v = &p.vertices_m;
    let mut inside = false;
    let mut prev = v[v.len() - 1];
    for &cur in v {
        let (xa, ya, xb, yb) = (prev[i], prev[j], cur[i], cur[j]);
        if (ya > hy) != (yb > hy) && hx < xa + (hy - ya) * (xb - xa) / (yb - ya) {
            inside = !inside;
        }
        prev = cur;
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;

    fn south_window() -> KlemsWindow {
        // The LBNL tutorial's glazing: x 0..6.096, z 0.9144..2.4384 in the plane y = 0, front
        // normal +y (into the room).
        let text = "void glow g 0 0 4 1 1 1 0\ng polygon w 0 0 12 0 0 0.9144 0 0 2.4384 \
                    6.096 0 2.4384 6.096 0 0.9144\n";
        let scene = scene::parse("window.rad", text.as_bytes()).unwrap();
        let Shape::Polygon(p) = scene.surfaces()[0].shape.clone() else {
            unreachable!()
        };
        KlemsWindow::new(
            vec![p],
            DVec3::Z,
            AngleBasis::builtin("LBNL/Klems Full").unwrap(),
            "window.rad",
        )
        .unwrap()
    }

    #[test]
    fn frame_is_rfluxmtx_kbin() {
        let w = south_window();
        assert_eq!(w.normal, DVec3::Y);
        // klems_full.cal kbinS: light arriving along +y (from the south) is patch 0; azimuth 0
        // of the frame is up × normal = -x (west), 90° is up.
        assert_eq!(w.patch_of_arrival(DVec3::Y), Some(0));
        let tilt = 10f64.to_radians();
        let towards = |axis: DVec3| (tilt.cos() * DVec3::Y + tilt.sin() * axis).normalize();
        assert_eq!(w.patch_of_arrival(towards(-DVec3::X)), Some(1));
        assert_eq!(w.patch_of_arrival(towards(DVec3::Z)), Some(3));
        assert_eq!(w.patch_of_arrival(-DVec3::Y), None);
        for patch in [0, 7, 60, 144] {
            let d = w.arrival_direction(patch, [0.3, 0.6]);
            assert_eq!(w.patch_of_arrival(d), Some(patch));
        }
    }

    #[test]
    fn points_and_crossings() {
        let w = south_window();
        assert!((w.area_m2() - 6.096 * 1.524).abs() < 1e-9);
        for u in [[0.0, 0.0], [0.5, 0.5], [0.999, 0.2]] {
            let p = w.sample_point(u);
            assert!(p.y.abs() < 1e-12 && (0.9..2.45).contains(&p.z), "{p:?}");
        }
        let out = Ray::new(DVec3::new(3.0, 2.0, 1.5), -DVec3::Y);
        assert!(w.crosses(&out));
        assert!(!w.crosses(&Ray::new(DVec3::new(3.0, 2.0, 0.5), -DVec3::Y)));
        assert!(!w.crosses(&Ray::new(DVec3::new(3.0, 2.0, 1.5), DVec3::Y)));
    }
}

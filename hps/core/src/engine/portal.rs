//! Portals: the openings (windows) through which the sky lights a room, sampled by area so
//! that next-event estimation reaches the sky from deep inside a room (Bitterli et al.,
//! "Portal-masked environment map sampling", 2015, use the same idea for environment maps).
//!
//! Portals are only a sampling distribution: any set of polygons gives an unbiased estimate
//! as long as [`Portals::pdf`] is the density [`Portals::sample`] draws from. So the polygons
//! are fan-triangulated (exact for the convex panes of windows; a concave outline only
//! samples some points twice and some outside, which the density accounts for), and the
//! density of a direction sums every triangle the line from the point crosses, whether or not
//! something is in the way.

use super::rng::Rng;
use glam::DVec3;

/// One triangle of a portal polygon.
#[derive(Clone, Debug)]
struct Triangle {
    v0: DVec3,
    e1: DVec3,
    e2: DVec3,
    /// Unit normal.
    normal: DVec3,
}

impl Triangle {
    /// Distance along unit `d` from `o` at which the triangle is crossed (Möller–Trumbore,
    /// "Fast, minimum storage ray/triangle intersection", 1997), if ahead.
    fn hit(&self, o: DVec3, d: DVec3) -> Option<f64> {
        // The plane first: most lines from a point leave most portals' planes behind.
        let towards = self.normal.dot(d);
        if towards == 0.0 || self.normal.dot(self.v0 - o) / towards <= 0.0 {
            return None;
        }
        let p = d.cross(self.e2);
        let det = self.e1.dot(p);
        if det.abs() < 1e-15 {
            return None;
        }
        let inv = 1.0 / det;
        let s = o - self.v0;
        let u = s.dot(p) * inv;
        if !(0.0..=1.0).contains(&u) {
            return None;
        }
        let q = s.cross(self.e1);
        let v = d.dot(q) * inv;
        if v < 0.0 || u + v > 1.0 {
            return None;
        }
        let t = self.e2.dot(q) * inv;
        (t > 1e-9).then_some(t)
    }
}

impl Triangle {
    /// |n · s| when the half-line from `y` along unit `s` crosses the triangle nearer than
    /// `t_max_m`: the one test the sun-patch density and its sampler share.
    fn projected_crossing(&self, y: DVec3, s: DVec3, t_max_m: f64) -> Option<f64> {
        let dist = self.hit(y, s)?;
        let c = self.normal.dot(s).abs();
        (dist < t_max_m && c > 1e-12).then_some(c)
    }
}

/// The portals of a world: triangles sampled in proportion to their area.
#[derive(Clone, Debug, Default)]
pub struct Portals {
    triangles: Vec<Triangle>,
    /// Running sum of the areas (the last is the total).
    cumulative_m2: Vec<f64>,
    /// Primitive indices of the portal polygons, for reports.
    primitives: Vec<u32>,
}

impl Portals {
    /// Portals from polygons given as (primitive index, vertices).
    pub fn new(polygons: &[(u32, Vec<DVec3>)]) -> Self {
        let mut portals = Portals::default();
        for (primitive, vertices) in polygons {
            if portals.push_polygon(vertices) {
                portals.primitives.push(*primitive);
            }
        }
        portals
    }

    /// Adds openings (rectangles with no surface in them, so no primitive), sampled like the
    /// rest.
    pub fn add_openings(&mut self, openings: &[[DVec3; 4]]) {
        for o in openings {
            self.push_polygon(o);
        }
    }

    /// Fan-triangulates a polygon into the portals; false if it has no area.
    fn push_polygon(&mut self, vertices: &[DVec3]) -> bool {
        if vertices.len() < 3 {
            return false;
        }
        let mut added = false;
        for i in 1..vertices.len() - 1 {
            let (v0, v1, v2) = (vertices[0], vertices[i], vertices[i + 1]);
            let (e1, e2) = (v1 - v0, v2 - v0);
            let c = e1.cross(e2);
            let area_m2 = 0.5 * c.length();
            if (area_m2).partial_cmp(&1e-12) != Some(std::cmp::Ordering::Greater)
                || !area_m2.is_finite()
            {
                continue;
            }
            let total = self.total_area_m2() + area_m2;
            self.triangles.push(Triangle {
                v0,
                e1,
                e2,
                normal: c.normalize(),
            });
            self.cumulative_m2.push(total);
            added = true;
        }
        added
    }

    /// Whether some part of the portals lies in front of the plane through `x` with unit
    /// normal `n` (a surface there can send light towards them).
    pub fn any_in_front(&self, x: DVec3, n: DVec3) -> bool {
        self.triangles.iter().any(|t| {
            [t.v0, t.v0 + t.e1, t.v0 + t.e2]
                .iter()
                .any(|v| (*v - x).dot(n) > 1e-9)
        })
    }

    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    pub fn total_area_m2(&self) -> f64 {
        self.cumulative_m2.last().copied().unwrap_or(0.0)
    }

    /// Primitive indices of the polygons used as portals.
    pub fn primitives(&self) -> &[u32] {
        &self.primitives
    }

    /// A direction from `x` towards a point drawn uniformly over the portals' area, with its
    /// density in solid angle (the sum over every portal triangle on that line, see
    /// [`Portals::pdf`]). None if there are no portals or `x` lies in a portal's plane.
    pub fn sample(&self, x: DVec3, rng: &mut Rng) -> Option<(DVec3, f64)> {
        let total = self.total_area_m2();
        if (total).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let (y, _) = self.point(rng, total);
        let to = y - x;
        let dist2 = to.length_squared();
        if (dist2).partial_cmp(&1e-18) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let d = to / dist2.sqrt();
        let pdf = self.pdf(x, d);
        (pdf > 0.0 && pdf.is_finite()).then_some((d, pdf))
    }

    /// A point drawn uniformly over the portals' area, with the index of its triangle (for
    /// [`Portals::projection_crosses`]).
    pub fn sample_point(&self, rng: &mut Rng) -> Option<(DVec3, usize)> {
        let total = self.total_area_m2();
        if (total).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let (p, i) = self.point(rng, total);
        Some((p, i))
    }

    /// A point uniform over the portals (total area `total` > 0) and its triangle's index,
    /// from two uniforms: the first chooses the triangle by area and, rescaled within
    /// the triangle's share, gives the first coordinate, so stratified pairs stay stratified
    /// across triangles.
    fn point(&self, rng: &mut Rng, total: f64) -> (DVec3, usize) {
        let target = rng.uniform() * total;
        let i = self
            .cumulative_m2
            .partition_point(|&c| c <= target)
            .min(self.triangles.len() - 1);
        let t = &self.triangles[i];
        let below = if i == 0 {
            0.0
        } else {
            self.cumulative_m2[i - 1]
        };
        let share = self.cumulative_m2[i] - below;
        let u = ((target - below) / share).clamp(0.0, 1.0);
        // Uniform point on the triangle (square-root parametrisation).
        let (r1, r2) = (u.sqrt(), rng.uniform());
        (t.v0 + t.e1 * (r1 * (1.0 - r2)) + t.e2 * (r1 * r2), i)
    }

    /// Density per unit area at a point `y` (unit normal `n_y`) of the points reached by
    /// following unit direction −`s` from a point drawn by [`Portals::sample_point`]: Σ over
    /// the portal triangles the half-line from `y` along `s` crosses nearer than `t_max_m`
    /// of |n_y · s| / (A |n_p · s|) (a parallel projection scales areas by that ratio).
    ///
    /// A sampler must keep only the points whose own triangle counts here
    /// ([`Portals::projection_crosses`]): where a portal lies in the plane of an opaque
    /// surface (an opening's edge cells overlap the wall around the hole), whether a crossing
    /// is nearer than the surface is a matter of rounding, and the sampler and this density
    /// must decide it alike.
    pub fn projected_area_pdf(&self, y: DVec3, n_y: DVec3, s: DVec3, t_max_m: f64) -> f64 {
        let total = self.total_area_m2();
        if (total).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return 0.0;
        }
        let cy = n_y.dot(s).abs();
        self.triangles
            .iter()
            .filter_map(|t| t.projected_crossing(y, s, t_max_m))
            .map(|c| cy / (total * c))
            .sum()
    }

    /// Whether triangle `triangle` counts in [`Portals::projected_area_pdf`] at `y`.
    pub fn projection_crosses(&self, triangle: usize, y: DVec3, s: DVec3, t_max_m: f64) -> bool {
        self.triangles
            .get(triangle)
            .is_some_and(|t| t.projected_crossing(y, s, t_max_m).is_some())
    }

    /// Density in solid angle with which [`Portals::sample`] from `x` produces unit `d`:
    /// Σ t² / (A |n · d|) over the portal triangles the half-line crosses at distance t,
    /// A the total portal area.
    pub fn pdf(&self, x: DVec3, d: DVec3) -> f64 {
        self.pdf_and_first_crossing(x, d).0
    }

    /// [`Portals::pdf`], and the distance along `d` from `x` to the nearest portal triangle
    /// crossed (infinite if none): where the outside begins on that line.
    pub fn pdf_and_first_crossing(&self, x: DVec3, d: DVec3) -> (f64, f64) {
        let total = self.total_area_m2();
        if (total).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return (0.0, f64::INFINITY);
        }
        let (mut p, mut first) = (0.0, f64::INFINITY);
        for t in &self.triangles {
            if let Some(dist) = t.hit(x, d) {
                let c = t.normal.dot(d).abs();
                if c > 1e-12 {
                    p += dist * dist / (total * c);
                    first = first.min(dist);
                }
            }
        }
        (p, first)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The density integrates to the solid angle's share: for a point in front of a square
    /// portal, sampling then averaging 1/pdf estimates the portal's solid angle, which for a
    /// square of side 2a at distance h on axis is 4 asin(a² / (a² + h²)) (the solid angle of
    /// a rectangle, Mathar 2015 / van Oosterom & Strackee 1983).
    #[test]
    fn inverse_density_averages_to_the_solid_angle() {
        let (a, h) = (0.5_f64, 1.0_f64);
        let portals = Portals::new(&[(
            0,
            vec![
                DVec3::new(-a, -a, h),
                DVec3::new(a, -a, h),
                DVec3::new(a, a, h),
                DVec3::new(-a, a, h),
            ],
        )]);
        let mut rng = Rng::for_stream(3, 0);
        let n = 200_000;
        let mut sum = 0.0;
        for _ in 0..n {
            let (d, p) = portals.sample(DVec3::ZERO, &mut rng).unwrap();
            assert!(d.z > 0.0);
            sum += 1.0 / p;
        }
        let expect = 4.0 * (a * a / (a * a + h * h)).asin();
        assert!(
            (sum / n as f64 / expect - 1.0).abs() < 0.01,
            "{sum} {expect}"
        );
        // Off the portal: zero density.
        assert_eq!(portals.pdf(DVec3::ZERO, DVec3::new(1.0, 0.0, 0.0)), 0.0);
    }
}

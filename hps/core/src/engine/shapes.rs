//! Ray intersection with RADIANCE's surfaces (reference manual §2.1.1), in the forms
//! precomputed from [`crate::scene::Shape`].
//!
//! Every intersection returns the distance and the geometric normal on the front side as
//! RADIANCE defines it (polygon: right-hand rule; sphere, cylinder, cone: outward; ring: its
//! given normal). Which side was hit is decided by the material, as RADIANCE's `flipsurface`.

use super::ray::Ray;
use super::slab::Aabb;
use crate::scene::{Cone, Cylinder, Polygon, Ring, Sphere};
use glam::{DVec2, DVec3};

/// A ray hit on a primitive.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeHit {
    pub t_m: f64,
    /// Unit front normal at the hit point.
    pub normal: DVec3,
}

/// A surface ready for intersection.
#[derive(Clone, Debug)]
pub enum Primitive {
    Polygon(PreparedPolygon),
    Sphere(Sphere),
    Cone(PreparedCone),
    Ring(Ring),
    /// RADIANCE's `bubble`, `tube` and `cup`: the surface of its inner primitive with the
    /// normal pointing in.
    Inward(Box<Primitive>),
}

impl Primitive {
    /// Flat primitives cannot be hit again by a ray leaving them, so the tracer excludes the
    /// surface a ray starts on instead of using a distance epsilon.
    pub fn is_flat(&self) -> bool {
        matches!(self, Primitive::Polygon(_) | Primitive::Ring(_))
    }

    pub fn bounds(&self) -> Aabb {
        match self {
            Primitive::Polygon(p) => p.bounds,
            Primitive::Sphere(s) => Aabb {
                min_m: s.centre_m - DVec3::splat(s.radius_m),
                max_m: s.centre_m + DVec3::splat(s.radius_m),
            },
            Primitive::Cone(c) => {
                // Bound each end disc: extent of a disc of radius r with unit normal a along
                // axis i is r sqrt(1 - a_i²).
                let disc = |centre: DVec3, r: f64| {
                    let e = r
                        * (DVec3::ONE - c.axis * c.axis)
                            .max(DVec3::ZERO)
                            .map(f64::sqrt);
                    Aabb {
                        min_m: centre - e,
                        max_m: centre + e,
                    }
                };
                disc(c.start_m, c.start_radius_m)
                    .union(disc(c.start_m + c.axis * c.length_m, c.end_radius_m))
            }
            Primitive::Ring(r) => {
                let e = r.outer_radius_m
                    * (DVec3::ONE - r.normal * r.normal)
                        .max(DVec3::ZERO)
                        .map(f64::sqrt);
                Aabb {
                    min_m: r.centre_m - e,
                    max_m: r.centre_m + e,
                }
            }
            Primitive::Inward(inner) => inner.bounds(),
        }
        // Flat boxes are fine for the slab test; a small pad guards against rounding.
        .padded(1e-9)
    }

    /// The nearest hit with `t_min_m < t < t_max_m`.
    pub fn intersect(&self, ray: &Ray, t_min_m: f64, t_max_m: f64) -> Option<ShapeHit> {
        match self {
            Primitive::Polygon(p) => p.intersect(ray, t_min_m, t_max_m),
            Primitive::Sphere(s) => intersect_sphere(s, ray, t_min_m, t_max_m),
            Primitive::Cone(c) => c.intersect(ray, t_min_m, t_max_m),
            Primitive::Ring(r) => intersect_ring(r, ray, t_min_m, t_max_m),
            Primitive::Inward(inner) => inner.intersect(ray, t_min_m, t_max_m).map(|h| ShapeHit {
                normal: -h.normal,
                ..h
            }),
        }
    }
}

/// A polygon with its plane and its outline projected onto the coordinate plane most nearly
/// parallel to it, for the point-in-polygon test.
#[derive(Clone, Debug)]
pub struct PreparedPolygon {
    pub normal: DVec3,
    /// Plane offset: normal · x = offset_m for points x on the plane.
    offset_m: f64,
    /// The two world axes kept by the projection.
    axes: (usize, usize),
    outline: Vec<DVec2>,
    bounds: Aabb,
}

impl PreparedPolygon {
    pub fn new(p: &Polygon) -> Self {
        let n = p.normal;
        let a = n.abs();
        let drop = if a.x >= a.y && a.x >= a.z {
            0
        } else if a.y >= a.z {
            1
        } else {
            2
        };
        let axes = ((drop + 1) % 3, (drop + 2) % 3);
        // Plane through the centroid of the vertices: for slightly non-planar input this is
        // the least-biased choice (RADIANCE face.c also fits the plane through an average).
        let centroid = p.vertices_m.iter().copied().sum::<DVec3>() / p.vertices_m.len() as f64;
        PreparedPolygon {
            normal: n,
            offset_m: n.dot(centroid),
            axes,
            outline: p
                .vertices_m
                .iter()
                .map(|v| DVec2::new(v[axes.0], v[axes.1]))
                .collect(),
            bounds: Aabb::from_points(p.vertices_m.iter().copied()),
        }
    }

    fn intersect(&self, ray: &Ray, t_min_m: f64, t_max_m: f64) -> Option<ShapeHit> {
        let denom = self.normal.dot(ray.direction);
        if denom.abs() < 1e-15 {
            return None;
        }
        let t = (self.offset_m - self.normal.dot(ray.origin_m)) / denom;
        if !(t > t_min_m && t < t_max_m) {
            return None;
        }
        let p = ray.at(t);
        let q = DVec2::new(p[self.axes.0], p[self.axes.1]);
        self.contains(q).then_some(ShapeHit {
            t_m: t,
            normal: self.normal,
        })
    }

    /// Even-odd (crossing number) test, valid for concave outlines and for RADIANCE's holes
    /// made by seams of coincident edges, whose two crossings cancel (Haines, "Point in
    /// polygon strategies", Graphics Gems IV, 1994).
    fn contains(&self, q: DVec2) -> bool {
        let mut inside = false;
        let n = self.outline.len();
        let mut j = n - 1;
        for i in 0..n {
            let (a, b) = (self.outline[i], self.outline[j]);
            if (a.y > q.y) != (b.y > q.y) {
                let x = a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y);
                if q.x < x {
                    inside = !inside;
                }
            }
            j = i;
        }
        inside
    }
}

/// Smaller root first, computed without cancellation (Numerical Recipes §5.6).
fn solve_quadratic(a: f64, b: f64, c: f64) -> Option<(f64, f64)> {
    if a.abs() < 1e-300 {
        if b == 0.0 {
            return None;
        }
        let t = -c / b;
        return Some((t, t));
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return None;
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    let (r0, r1) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
    Some(if r0 <= r1 { (r0, r1) } else { (r1, r0) })
}

fn intersect_sphere(s: &Sphere, ray: &Ray, t_min_m: f64, t_max_m: f64) -> Option<ShapeHit> {
    let oc = ray.origin_m - s.centre_m;
    let (t0, t1) = solve_quadratic(
        1.0,
        2.0 * oc.dot(ray.direction),
        oc.dot(oc) - s.radius_m * s.radius_m,
    )?;
    let t = [t0, t1]
        .into_iter()
        .find(|t| *t > t_min_m && *t < t_max_m)?;
    Some(ShapeHit {
        t_m: t,
        normal: (ray.at(t) - s.centre_m) / s.radius_m,
    })
}

fn intersect_ring(r: &Ring, ray: &Ray, t_min_m: f64, t_max_m: f64) -> Option<ShapeHit> {
    let denom = r.normal.dot(ray.direction);
    if denom.abs() < 1e-15 {
        return None;
    }
    let t = r.normal.dot(r.centre_m - ray.origin_m) / denom;
    if !(t > t_min_m && t < t_max_m) {
        return None;
    }
    let d2 = (ray.at(t) - r.centre_m).length_squared();
    (d2 >= r.inner_radius_m * r.inner_radius_m && d2 <= r.outer_radius_m * r.outer_radius_m)
        .then_some(ShapeHit {
            t_m: t,
            normal: r.normal,
        })
}

/// A cone or cylinder (a cone of equal radii): the open lateral surface between the end
/// points, radius varying linearly along the axis.
#[derive(Clone, Debug)]
pub struct PreparedCone {
    start_m: DVec3,
    /// Unit axis from start to end.
    axis: DVec3,
    length_m: f64,
    start_radius_m: f64,
    end_radius_m: f64,
}

impl PreparedCone {
    pub fn from_cone(c: &Cone) -> Self {
        let v = c.end_m - c.start_m;
        let length_m = v.length();
        PreparedCone {
            start_m: c.start_m,
            axis: v / length_m,
            length_m,
            start_radius_m: c.start_radius_m,
            end_radius_m: c.end_radius_m,
        }
    }

    pub fn from_cylinder(c: &Cylinder) -> Self {
        Self::from_cone(&Cone {
            start_m: c.start_m,
            end_m: c.end_m,
            start_radius_m: c.radius_m,
            end_radius_m: c.radius_m,
        })
    }

    /// Points x with radial distance |r(x)| = r0 + k z(x), 0 <= z <= L, where z is the
    /// position along the axis and k = (r1 − r0)/L: a quadratic in t.
    fn intersect(&self, ray: &Ray, t_min_m: f64, t_max_m: f64) -> Option<ShapeHit> {
        let k = (self.end_radius_m - self.start_radius_m) / self.length_m;
        let oc = ray.origin_m - self.start_m;
        let (oz, dz) = (oc.dot(self.axis), ray.direction.dot(self.axis));
        let (or, dr) = (oc - oz * self.axis, ray.direction - dz * self.axis);
        let r_at_origin = self.start_radius_m + k * oz;
        let a = dr.dot(dr) - k * k * dz * dz;
        let b = 2.0 * (or.dot(dr) - k * r_at_origin * dz);
        let c = or.dot(or) - r_at_origin * r_at_origin;
        let (t0, t1) = solve_quadratic(a, b, c)?;
        for t in [t0, t1] {
            if !(t > t_min_m && t < t_max_m) {
                continue;
            }
            let z = oz + t * dz;
            let radius = self.start_radius_m + k * z;
            if !(0.0..=self.length_m).contains(&z) || radius < 0.0 {
                continue;
            }
            let radial = or + t * dr;
            // Gradient of |r|² − (r0 + k z)²: 2 r − 2 (r0 + k z) k a.
            let g = radial - radius * k * self.axis;
            let len = g.length();
            if len == 0.0 {
                continue;
            }
            return Some(ShapeHit {
                t_m: t,
                normal: g / len,
            });
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn poly(v: &[[f64; 3]]) -> PreparedPolygon {
        let vertices_m: Vec<DVec3> = v.iter().map(|p| DVec3::from_array(*p)).collect();
        let mut twice = DVec3::ZERO;
        for i in 0..vertices_m.len() {
            twice += vertices_m[i].cross(vertices_m[(i + 1) % vertices_m.len()]);
        }
        PreparedPolygon::new(&Polygon {
            normal: twice.normalize(),
            area_m2: 0.5 * twice.length(),
            vertices_m,
        })
    }

    fn down_at(x: f64, y: f64) -> Ray {
        Ray::new(DVec3::new(x, y, 1.0), -DVec3::Z)
    }

    #[test]
    fn concave_polygon() {
        // An L shape: the notch at (1.5, 1.5) is outside.
        let l = poly(&[
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, 2.0, 0.0],
            [0.0, 2.0, 0.0],
        ]);
        let hit = |x, y| l.intersect(&down_at(x, y), 0.0, 10.0);
        assert_eq!(hit(0.5, 0.5).unwrap().t_m, 1.0);
        assert!(hit(1.5, 0.5).is_some());
        assert!(hit(0.5, 1.5).is_some());
        assert!(hit(1.5, 1.5).is_none());
        assert!(hit(2.5, 0.5).is_none());
    }

    #[test]
    fn polygon_with_a_hole_by_seam() {
        // Outer square 0..3, hole 1..2 joined by a seam along y = 0 .. 1 at x = 1.
        let p = poly(&[
            [0.0, 0.0, 0.0],
            [3.0, 0.0, 0.0],
            [3.0, 3.0, 0.0],
            [0.0, 3.0, 0.0],
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, 2.0, 0.0],
            [2.0, 2.0, 0.0],
            [2.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
        ]);
        assert!(p.intersect(&down_at(1.5, 1.5), 0.0, 10.0).is_none());
        assert!(p.intersect(&down_at(0.5, 2.5), 0.0, 10.0).is_some());
        assert!(p.intersect(&down_at(2.5, 0.5), 0.0, 10.0).is_some());
    }

    #[test]
    fn sphere_from_outside_and_inside() {
        let s = Sphere {
            centre_m: DVec3::ZERO,
            radius_m: 2.0,
        };
        let h = intersect_sphere(
            &s,
            &Ray::new(DVec3::new(0.0, 0.0, 5.0), -DVec3::Z),
            0.0,
            1e9,
        )
        .unwrap();
        assert!((h.t_m - 3.0).abs() < 1e-12);
        assert!((h.normal - DVec3::Z).length() < 1e-12);
        let h = intersect_sphere(&s, &Ray::new(DVec3::ZERO, DVec3::X), 0.0, 1e9).unwrap();
        assert!((h.t_m - 2.0).abs() < 1e-12 && (h.normal - DVec3::X).length() < 1e-12);
    }

    #[test]
    fn cylinder_and_cone() {
        let cyl = PreparedCone::from_cylinder(&Cylinder {
            start_m: DVec3::ZERO,
            end_m: DVec3::new(0.0, 0.0, 2.0),
            radius_m: 1.0,
        });
        let h = cyl
            .intersect(&Ray::new(DVec3::new(5.0, 0.0, 1.0), -DVec3::X), 0.0, 1e9)
            .unwrap();
        assert!((h.t_m - 4.0).abs() < 1e-12 && (h.normal - DVec3::X).length() < 1e-12);
        // Above the end: misses (open tube).
        assert!(cyl
            .intersect(&Ray::new(DVec3::new(5.0, 0.0, 2.5), -DVec3::X), 0.0, 1e9)
            .is_none());
        // Down the axis from inside: misses the open ends.
        assert!(cyl
            .intersect(&Ray::new(DVec3::new(0.0, 0.0, 1.0), DVec3::Z), 0.0, 1e9)
            .is_none());
        // Cone of radius 1 at z = 0 to 0 at z = 1: the slant at z = 0.5 has radius 0.5, and its
        // outward normal leans up at 45°.
        let cone = PreparedCone::from_cone(&Cone {
            start_m: DVec3::ZERO,
            end_m: DVec3::Z,
            start_radius_m: 1.0,
            end_radius_m: 0.0,
        });
        let h = cone
            .intersect(&Ray::new(DVec3::new(3.0, 0.0, 0.5), -DVec3::X), 0.0, 1e9)
            .unwrap();
        assert!((h.t_m - 2.5).abs() < 1e-12, "{}", h.t_m);
        let expect = DVec3::new(1.0, 0.0, 1.0).normalize();
        assert!((h.normal - expect).length() < 1e-12, "{}", h.normal);
        // The mirrored nappe (z < 0) does not count.
        assert!(cone
            .intersect(&Ray::new(DVec3::new(3.0, 0.0, -0.5), -DVec3::X), 0.0, 1e9)
            .is_none());
    }

    #[test]
    fn inward_shapes_turn_the_normal_only() {
        let bubble = Primitive::Inward(Box::new(Primitive::Sphere(Sphere {
            centre_m: DVec3::ZERO,
            radius_m: 2.0,
        })));
        let h = bubble
            .intersect(&Ray::new(DVec3::ZERO, DVec3::X), 0.0, 1e9)
            .unwrap();
        assert!((h.t_m - 2.0).abs() < 1e-12 && (h.normal + DVec3::X).length() < 1e-12);
        assert!(!bubble.is_flat());
        // The same box (padded once more, by a nanometre).
        let outward = Primitive::Sphere(Sphere {
            centre_m: DVec3::ZERO,
            radius_m: 2.0,
        });
        assert!((bubble.bounds().max_m - outward.bounds().max_m).length() < 1e-8);
    }

    #[test]
    fn ring_annulus() {
        let r = Ring {
            centre_m: DVec3::ZERO,
            normal: DVec3::Z,
            inner_radius_m: 0.5,
            outer_radius_m: 1.0,
        };
        assert!(intersect_ring(&r, &down_at(0.0, 0.0), 0.0, 10.0).is_none());
        assert!(intersect_ring(&r, &down_at(0.75, 0.0), 0.0, 10.0).is_some());
        assert!(intersect_ring(&r, &down_at(0.0, 1.1), 0.0, 10.0).is_none());
        let b = Primitive::Ring(r).bounds();
        assert!((b.max_m.x - 1.0).abs() < 1e-6 && b.max_m.z.abs() < 1e-6);
    }
}

//! Ray/axis-aligned box tests: the one operation the FPGA ray-box unit takes over.
//!
//! The BVH calls box tests only through [`BoxTest`], so a hardware implementation (a batch of
//! boxes sent to the fabric, entry distances read back) replaces [`SlabTest`] without touching
//! the traversal.

use super::ray::{Ray, RayBoxQuery};
use glam::DVec3;

/// An axis-aligned box in metres. An empty box has `min > max`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min_m: DVec3,
    pub max_m: DVec3,
}

impl Aabb {
    pub const EMPTY: Aabb = Aabb {
        min_m: DVec3::splat(f64::INFINITY),
        max_m: DVec3::splat(f64::NEG_INFINITY),
    };

    pub fn from_points(points: impl IntoIterator<Item = DVec3>) -> Self {
        points.into_iter().fold(Self::EMPTY, |b, p| b.including(p))
    }

    pub fn including(self, p: DVec3) -> Self {
        Aabb {
            min_m: self.min_m.min(p),
            max_m: self.max_m.max(p),
        }
    }

    pub fn union(self, o: Aabb) -> Self {
        Aabb {
            min_m: self.min_m.min(o.min_m),
            max_m: self.max_m.max(o.max_m),
        }
    }

    pub fn centre_m(&self) -> DVec3 {
        0.5 * (self.min_m + self.max_m)
    }

    /// Surface area in m² (0 for an empty box), the cost measure of the SAH.
    pub fn surface_area_m2(&self) -> f64 {
        let d = (self.max_m - self.min_m).max(DVec3::ZERO);
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
    }

    /// The box grown by `margin_m` on every side (so flat primitives get a thickness).
    pub fn padded(self, margin_m: f64) -> Self {
        Aabb {
            min_m: self.min_m - DVec3::splat(margin_m),
            max_m: self.max_m + DVec3::splat(margin_m),
        }
    }
}

/// Tests one ray against a batch of boxes.
pub trait BoxTest: Sync {
    /// For each box, writes into `entry_m` the distance at which the ray enters it (clamped to
    /// the query's interval), or `f64::INFINITY` if the ray misses it within
    /// `[t_min_m, t_max_m]`. `entry_m.len() == boxes.len()`.
    fn hits(&self, ray: &RayBoxQuery, boxes: &[Aabb], entry_m: &mut [f64]);

    /// A traversal of `kind` begins for `ray` over `[t_min_m, t_max_m]`. Only a test that
    /// counts the traversal's work (`engine::traversal_stats`, which sizes a ray unit that
    /// traverses the tree itself) does anything here.
    #[inline]
    fn traversal_begins(&self, _kind: TraversalKind, _ray: &Ray, _t_min_m: f64, _t_max_m: f64) {}

    /// The traversal reached a leaf holding `primitives` primitives, each of which it tests.
    #[inline]
    fn leaf_reached(&self, _primitives: usize) {}
}

/// The two traversals of the BVH.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum TraversalKind {
    /// The closest hit: near child first, subtrees past the best hit pruned.
    Closest,
    /// Every primitive whose box the ray crosses (shadow rays), in no order.
    Crossed,
}

/// The software slab test (Kay & Kajiya 1986; the robust form of Williams et al. 2005, "An
/// efficient and robust ray-box intersection algorithm", with the NaN of 0 × ∞ discarded by
/// `min`/`max` ordering as in pbrt-v4 `Bounds3::IntersectP`).
#[derive(Clone, Copy, Debug, Default)]
pub struct SlabTest;

impl SlabTest {
    /// Entry distance into one box, or `None`.
    ///
    /// Branch-free per axis (selects, no early exit: the traversal's mispredicted branches
    /// cost more than the work they skip). The selects are ordered so that a NaN bound (origin
    /// on a slab plane with a zero direction component: 0 × ∞) constrains nothing: `lo` keeps
    /// a NaN `near` and `hi` a NaN `far`, and a NaN never wins a comparison.
    #[inline]
    pub fn entry(ray: &RayBoxQuery, b: &Aabb) -> Option<f64> {
        let mut t0 = ray.t_min_m;
        let mut t1 = ray.t_max_m;
        for axis in 0..3 {
            let inv = ray.inverse_direction[axis];
            let o = ray.origin_m[axis];
            let near = (b.min_m[axis] - o) * inv;
            let far = (b.max_m[axis] - o) * inv;
            let swapped = far < near;
            let lo = if swapped { far } else { near };
            let hi = if swapped { near } else { far };
            t0 = if lo > t0 { lo } else { t0 };
            t1 = if hi < t1 { hi } else { t1 };
        }
        (t0 <= t1).then_some(t0)
    }
}

impl BoxTest for SlabTest {
    fn hits(&self, ray: &RayBoxQuery, boxes: &[Aabb], entry_m: &mut [f64]) {
        for (b, out) in boxes.iter().zip(entry_m.iter_mut()) {
            *out = Self::entry(ray, b).unwrap_or(f64::INFINITY);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::ray::Ray;

    fn unit_box() -> Aabb {
        Aabb {
            min_m: DVec3::ZERO,
            max_m: DVec3::ONE,
        }
    }

    #[test]
    fn hits_and_misses() {
        let q = |o: DVec3, d: DVec3| RayBoxQuery::new(&Ray::new(o, d.normalize()), 0.0, 100.0);
        let b = unit_box();
        let e = SlabTest::entry(&q(DVec3::new(-1.0, 0.5, 0.5), DVec3::X), &b).unwrap();
        assert!((e - 1.0).abs() < 1e-12);
        // Inside: entry is t_min.
        assert_eq!(
            SlabTest::entry(&q(DVec3::splat(0.5), DVec3::Z), &b),
            Some(0.0)
        );
        assert!(SlabTest::entry(&q(DVec3::new(-1.0, 2.0, 0.5), DVec3::X), &b).is_none());
        // Pointing away.
        assert!(SlabTest::entry(&q(DVec3::new(-1.0, 0.5, 0.5), -DVec3::X), &b).is_none());
        // Axis-parallel ray exactly in a face plane (0 × inf = NaN) still gets an answer.
        let r = q(DVec3::new(-1.0, 0.0, 0.5), DVec3::X);
        assert!(SlabTest::entry(&r, &b).is_some());
        // Beyond t_max.
        let far = RayBoxQuery::new(&Ray::new(DVec3::new(-5.0, 0.5, 0.5), DVec3::X), 0.0, 2.0);
        assert!(SlabTest::entry(&far, &b).is_none());
    }

    #[test]
    fn flat_box_is_hit() {
        let b = Aabb {
            min_m: DVec3::new(0.0, 0.0, 1.0),
            max_m: DVec3::new(1.0, 1.0, 1.0),
        };
        let r = RayBoxQuery::new(&Ray::new(DVec3::new(0.5, 0.5, 0.0), DVec3::Z), 0.0, 10.0);
        assert_eq!(SlabTest::entry(&r, &b), Some(1.0));
        let mut out = [0.0; 2];
        SlabTest.hits(&r, &[b, unit_box()], &mut out);
        assert_eq!(out, [1.0, 0.0]);
    }
}

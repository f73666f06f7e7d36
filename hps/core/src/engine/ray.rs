//! Rays: a half-line from an origin, and the precomputed form the box tests take.

use glam::DVec3;

/// RADIANCE's `FTINY` (fvect.h): the tolerance its vector and shading code compares with.
pub const FTINY: f64 = 1e-6;

/// A ray in the world frame (metres); `direction` is a unit vector.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    pub origin_m: DVec3,
    pub direction: DVec3,
}

impl Ray {
    pub fn new(origin_m: DVec3, direction: DVec3) -> Self {
        Self {
            origin_m,
            direction,
        }
    }

    /// The point at distance `t_m` along the ray.
    pub fn at(&self, t_m: f64) -> DVec3 {
        self.origin_m + self.direction * t_m
    }
}

/// What a box test needs of a ray, computed once per ray (the form the FPGA ray-box unit will
/// also receive): origin, reciprocal direction and the interval of interest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayBoxQuery {
    pub origin_m: DVec3,
    /// 1 / direction per axis (±inf for a zero component; the slab test handles it).
    pub inverse_direction: DVec3,
    /// Only hits with `t_min_m <= t <= t_max_m` count.
    pub t_min_m: f64,
    pub t_max_m: f64,
}

impl RayBoxQuery {
    pub fn new(ray: &Ray, t_min_m: f64, t_max_m: f64) -> Self {
        Self {
            origin_m: ray.origin_m,
            inverse_direction: DVec3::ONE / ray.direction,
            t_min_m,
            t_max_m,
        }
    }
}

//! Directions drawn from the distributions every part of the engine shares: the cosine lobe
//! of a Lambertian surface or sensor, and the cone of a distant source.

use super::rng::Rng;
use super::sky::DistantEmitter;
use glam::DVec3;
use std::f64::consts::PI;

/// An orthonormal basis (u, v) around unit `n` (Duff et al., "Building an orthonormal basis,
/// revisited", JCGT 2017).
pub fn basis(n: DVec3) -> (DVec3, DVec3) {
    let sign = 1f64.copysign(n.z);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (
        DVec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
        DVec3::new(b, sign + n.y * n.y * a, -n.y),
    )
}

/// A cosine-distributed direction about unit `n` (Malley's method; pdf cos θ / π).
pub fn cosine_direction(n: DVec3, rng: &mut Rng) -> DVec3 {
    let (u, v) = basis(n);
    let r2 = rng.uniform();
    let phi = 2.0 * PI * rng.uniform();
    let r = r2.sqrt();
    (u * (r * phi.cos()) + v * (r * phi.sin()) + n * (1.0 - r2).max(0.0).sqrt()).normalize()
}

/// A direction uniformly distributed in the cone of a distant source (pdf 1/Ω).
pub fn sample_cone(source: &DistantEmitter, rng: &mut Rng) -> DVec3 {
    let cos_theta = 1.0 - rng.uniform() * (1.0 - source.cos_half_angle);
    let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    let phi = 2.0 * PI * rng.uniform();
    let (u, v) = basis(source.direction);
    (u * (sin_theta * phi.cos()) + v * (sin_theta * phi.sin()) + source.direction * cos_theta)
        .normalize()
}

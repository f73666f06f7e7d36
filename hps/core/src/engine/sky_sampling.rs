//! Importance sampling of what lies beyond the scene (the sky and ground `glow`s and a
//! measured sky map): directions drawn in proportion to their radiance, so that a small
//! bright region (the circumsolar aureole of a Perez sky, ~20 times its surroundings within a
//! few degrees of the sun) is found by next-event estimation instead of by chance.
//!
//! The sphere is cut into cells equal in solid angle (equal steps of z = cos θ and of φ,
//! Archimedes' hat-box theorem), each weighted by the mean luminance of a few points in it;
//! a cell is chosen by its weight and a direction uniformly inside it, so the density is
//! weight / (Σ weights × cell solid angle). Any weights give an unbiased estimate once
//! combined with the other strategies by multiple importance sampling; the table only sets
//! how well the samples are spent.

use super::material::bright;
use super::rng::Rng;
use glam::DVec3;
use std::f64::consts::PI;

/// Cells along z = cos θ (from −1 to 1) and along φ: 64 × 128 cells of 1.5e-3 sr each
/// (about 2.2° across), fine enough to resolve an aureole that halves within ~7°.
const Z_CELLS: usize = 64;
const PHI_CELLS: usize = 128;
/// Points per cell side at which the radiance is averaged.
const SUB: usize = 3;

/// A radiance-proportional distribution of directions over the sphere.
#[derive(Clone, Debug)]
pub struct SkyDistribution {
    /// Running sum of the cell weights, z-major (the last is the total).
    cumulative: Vec<f64>,
    weight: Vec<f64>,
}

fn cell_solid_angle_sr() -> f64 {
    4.0 * PI / (Z_CELLS * PHI_CELLS) as f64
}

fn direction(z: f64, phi: f64) -> DVec3 {
    let r = (1.0 - z * z).max(0.0).sqrt();
    DVec3::new(r * phi.cos(), r * phi.sin(), z)
}

impl SkyDistribution {
    /// The distribution for `radiance(d)` (RGB, weighted by luminance). None if it is zero
    /// everywhere.
    pub fn new(radiance: impl Fn(DVec3) -> DVec3) -> Option<Self> {
        let dz = 2.0 / Z_CELLS as f64;
        let dphi = 2.0 * PI / PHI_CELLS as f64;
        let mut weight = Vec::with_capacity(Z_CELLS * PHI_CELLS);
        for iz in 0..Z_CELLS {
            for ip in 0..PHI_CELLS {
                let mut sum = 0.0;
                for a in 0..SUB {
                    for b in 0..SUB {
                        let z = -1.0 + dz * (iz as f64 + (a as f64 + 0.5) / SUB as f64);
                        let phi = dphi * (ip as f64 + (b as f64 + 0.5) / SUB as f64);
                        let l = bright(radiance(direction(z, phi)));
                        if l.is_finite() && l > 0.0 {
                            sum += l;
                        }
                    }
                }
                weight.push(sum / (SUB * SUB) as f64);
            }
        }
        let mut cumulative = Vec::with_capacity(weight.len());
        let mut total = 0.0;
        for w in &weight {
            total += w;
            cumulative.push(total);
        }
        (total > 0.0 && total.is_finite()).then_some(Self { cumulative, weight })
    }

    fn total(&self) -> f64 {
        *self.cumulative.last().unwrap_or(&0.0)
    }

    /// A direction and its density in solid angle.
    pub fn sample(&self, rng: &mut Rng) -> (DVec3, f64) {
        let target = rng.uniform() * self.total();
        let mut i = self
            .cumulative
            .partition_point(|&c| c <= target)
            .min(self.weight.len() - 1);
        while self.weight[i] <= 0.0 && i > 0 {
            i -= 1; // rounding landed on an empty cell: take the previous non-empty one
        }
        let (iz, ip) = (i / PHI_CELLS, i % PHI_CELLS);
        // The first uniform, rescaled within the chosen cell's weight, places the point in z
        // (two uniforms per direction keep stratified pairs stratified).
        let below = if i == 0 { 0.0 } else { self.cumulative[i - 1] };
        let fz = ((target - below) / self.weight[i]).clamp(0.0, 1.0 - f64::EPSILON / 2.0);
        let fz = if fz.is_finite() { fz } else { 0.5 };
        let z = -1.0 + 2.0 / Z_CELLS as f64 * (iz as f64 + fz);
        let phi = 2.0 * PI / PHI_CELLS as f64 * (ip as f64 + rng.uniform());
        let d = direction(z.clamp(-1.0, 1.0), phi);
        (d, self.weight[i] / (self.total() * cell_solid_angle_sr()))
    }

    /// Density in solid angle of unit `d`.
    pub fn pdf(&self, d: DVec3) -> f64 {
        let iz = (((d.z + 1.0) * 0.5 * Z_CELLS as f64) as usize).min(Z_CELLS - 1);
        let mut phi = d.y.atan2(d.x);
        if phi < 0.0 {
            phi += 2.0 * PI;
        }
        let ip = ((phi / (2.0 * PI) * PHI_CELLS as f64) as usize).min(PHI_CELLS - 1);
        self.weight[iz * PHI_CELLS + ip] / (self.total() * cell_solid_angle_sr())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// E[f / pdf] = ∫ f dω for a function with a sharp peak: the integral of
    /// exp(−5.86 γ) over the sphere around a direction is 2π ∫ exp(−kγ) sin γ dγ
    /// = 2π (1 + e^{−kπ}) / (1 + k²) (integration by parts).
    #[test]
    fn importance_sampled_integral_of_a_peak() {
        let k = 5.86;
        let sun = DVec3::new(0.12, -0.49, 0.86).normalize();
        let f = |d: DVec3| (-k * d.dot(sun).clamp(-1.0, 1.0).acos()).exp();
        let dist = SkyDistribution::new(|d| DVec3::splat(f(d))).unwrap();
        let mut rng = Rng::for_stream(9, 1);
        let n = 100_000;
        let (mut sum, mut sum2) = (0.0, 0.0);
        for _ in 0..n {
            let (d, p) = dist.sample(&mut rng);
            assert!((dist.pdf(d) / p - 1.0).abs() < 1e-9);
            let x = f(d) / p;
            sum += x;
            sum2 += x * x;
        }
        let mean = sum / n as f64;
        let expect = 2.0 * PI * (1.0 + (-k * PI).exp()) / (1.0 + k * k);
        let sd = (sum2 / n as f64 - mean * mean).sqrt();
        assert!((mean / expect - 1.0).abs() < 0.005, "{mean} {expect}");
        // Close to the zero-variance sampler: per-sample spread well under the mean.
        assert!(sd < 0.2 * mean, "{sd} {mean}");
    }
}

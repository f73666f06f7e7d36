//! RADIANCE's `glass` (src/rt/glass.c `m_glass`): one thin pane, with the angle-dependent
//! transmission and reflection of its two interfaces and the internal reflections summed.

use super::scattering::{bright, glass_fractions, reflect, Scatter};
use crate::engine::rng::Rng;
use crate::scene::Glass;
use glam::DVec3;

/// A thin pane of `glass`.
#[derive(Clone, Debug)]
pub struct GlassMaterial {
    /// glass.c's transmissivity tn per RGB channel (not the transmittance at normal incidence).
    pub transmissivity_rgb: DVec3,
    pub refractive_index: f64,
    /// A pattern's colour (1 without one): glass.c multiplies the transmitted coefficient
    /// by it, after the Fresnel terms, and leaves the reflection alone.
    pub pattern_rgb: DVec3,
    /// What a texture adds to the transmitted direction of every ray but a shadow ray
    /// (glass.c: rdir + 2 (1 − n) pert, pert turned with the surface when the ray meets its
    /// back); zero without a texture.
    pub transmitted_bend: DVec3,
}

impl From<&Glass> for GlassMaterial {
    fn from(g: &Glass) -> Self {
        Self {
            transmissivity_rgb: g.transmissivity_rgb,
            refractive_index: g.refractive_index,
            pattern_rgb: DVec3::ONE,
            transmitted_bend: DVec3::ZERO,
        }
    }
}

impl GlassMaterial {
    /// The pane under a texture's perturbation `perturbation` (`raytexture`'s pert, in the
    /// surface's own frame), met by a ray along unit `d` at a surface of geometric normal
    /// `normal`.
    pub fn textured(mut self, perturbation: DVec3, d: DVec3, normal: DVec3) -> Self {
        // flipsurface turns pert with the normal when the ray meets the back.
        let pert = if d.dot(normal) > 0.0 {
            -perturbation
        } else {
            perturbation
        };
        self.transmitted_bend = 2.0 * (1.0 - self.refractive_index) * pert;
        self
    }

    /// Transmitted and reflected fractions for unit direction `d` at a pane of normal `normal`.
    fn fractions(&self, d: DVec3, normal: DVec3) -> (DVec3, DVec3) {
        let (t, r) = glass_fractions(
            self.transmissivity_rgb,
            self.refractive_index,
            d.dot(normal).abs(),
        );
        (t * self.pattern_rgb, r)
    }

    /// What a shadow ray keeps crossing the pane: its transmitted fraction (glass.c traces
    /// shadow rays straight through).
    pub fn shadow_transmission(&self, d: DVec3, normal: DVec3) -> DVec3 {
        self.fractions(d, normal).0
    }

    /// Transmission or reflection, chosen in proportion to their brightness and weighted by
    /// the inverse of that probability; absorbed when the pane is black.
    pub fn sample(&self, d: DVec3, normal: DVec3, rng: &mut Rng) -> Scatter {
        let (t, r) = self.fractions(d, normal);
        let (bt, br) = (bright(t), bright(r));
        if bt + br <= 0.0 || (bt + br).is_nan() {
            return Scatter::Absorbed;
        }
        if rng.uniform() * (bt + br) < bt {
            let direction = if self.transmitted_bend == DVec3::ZERO {
                d
            } else {
                // glass.c keeps the ray's own direction on a "bad perturbation".
                (d + self.transmitted_bend).try_normalize().unwrap_or(d)
            };
            Scatter::Specular {
                direction,
                weight: t * ((bt + br) / bt),
            }
        } else {
            Scatter::Specular {
                direction: reflect(d, normal),
                weight: r * ((bt + br) / br),
            }
        }
    }
}

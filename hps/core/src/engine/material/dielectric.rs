//! RADIANCE's `dielectric` and `interface` (src/rt/dielectric.c `m_dielectric`): a boundary
//! between two media that reflects and refracts by Fresnel's equations (unpolarised light,
//! the mean of the s and p reflectances), with Beer-Lambert absorption along the path inside
//! each medium.

use super::scattering::{reflect, Scatter};
use crate::engine::ray::FTINY;
use crate::engine::rng::Rng;
use crate::scene::{Dielectric, Medium};
use glam::DVec3;

/// A refracting boundary; the inside medium lies behind the surface normal.
#[derive(Clone, Debug)]
pub struct DielectricMaterial {
    inside_index: f64,
    outside_index: f64,
    /// Extinction coefficients per metre (−ln of the transmission per metre), per channel.
    inside_extinction_per_m: DVec3,
    outside_extinction_per_m: DVec3,
}

/// dielectric.c's `mylog`: transmissions of 1 or more absorb nothing, and below 1e-40 the
/// extinction is capped at 100 per unit length.
fn extinction_per_m(medium: &Medium) -> DVec3 {
    medium.transmission_per_m_rgb.map(|x| {
        if x < 1e-40 {
            100.0
        } else if x >= 1.0 {
            0.0
        } else {
            -x.ln()
        }
    })
}

impl From<&Dielectric> for DielectricMaterial {
    fn from(d: &Dielectric) -> Self {
        Self {
            inside_index: d.inside.refractive_index,
            outside_index: d.outside.refractive_index,
            inside_extinction_per_m: extinction_per_m(&d.inside),
            outside_extinction_per_m: extinction_per_m(&d.outside),
        }
    }
}

/// What happens at the boundary for one incoming direction.
struct Boundary {
    /// Unit normal on the side the ray comes from.
    facing_normal: DVec3,
    /// cos of the angle of incidence (> 0).
    cos_incidence: f64,
    /// Ratio of the index on the incoming side to that on the far side.
    index_ratio: f64,
}

impl DielectricMaterial {
    fn boundary(&self, d: DVec3, normal: DVec3) -> Boundary {
        let cos = -d.dot(normal);
        if cos < 0.0 {
            Boundary {
                facing_normal: -normal,
                cos_incidence: -cos,
                index_ratio: self.inside_index / self.outside_index,
            }
        } else {
            Boundary {
                facing_normal: normal,
                cos_incidence: cos,
                index_ratio: self.outside_index / self.inside_index,
            }
        }
    }

    /// The Fresnel reflectance and, unless totally reflected, the refracted unit direction
    /// (m_dielectric: `refl` from the s and p amplitudes, `p.rdir`).
    fn fresnel(b: &Boundary, d: DVec3) -> (f64, Option<DVec3>) {
        let (c1, nr) = (b.cos_incidence, b.index_ratio);
        let d2 = 1.0 - nr * nr * (1.0 - c1 * c1);
        if d2 < FTINY {
            return (1.0, None);
        }
        let c2 = d2.sqrt();
        let s = (c1 - nr * c2) / (c1 + nr * c2);
        let p = (1.0 / c1 - nr / c2) / (1.0 / c1 + nr / c2);
        let reflectance = 0.5 * (s * s + p * p);
        let refracted = (nr * d + (nr * c1 - c2) * b.facing_normal).normalize();
        (reflectance, Some(refracted))
    }

    /// Refraction or reflection, chosen in proportion to the Fresnel fractions. A refracted
    /// ray carries the radiance change of the solid angle's compression, `index_ratio²`, as
    /// m_dielectric does.
    pub fn sample(&self, d: DVec3, normal: DVec3, rng: &mut Rng) -> Scatter {
        let b = self.boundary(d, normal);
        let (reflectance, refracted) = Self::fresnel(&b, d);
        match refracted {
            Some(t) if rng.uniform() >= reflectance => Scatter::Specular {
                direction: t,
                weight: DVec3::splat(b.index_ratio * b.index_ratio),
            },
            _ => Scatter::Specular {
                direction: reflect(d, b.facing_normal),
                weight: DVec3::ONE,
            },
        }
    }

    /// The path of a shadow ray towards a light source: refracted only, as dielectric.c
    /// traces shadow rays (no reflected ray for them), with the transmitted fraction; None
    /// when totally reflected.
    pub fn shadow_refraction(&self, d: DVec3, normal: DVec3) -> Option<(DVec3, DVec3)> {
        let b = self.boundary(d, normal);
        let (reflectance, refracted) = Self::fresnel(&b, d);
        let factor = (1.0 - reflectance) * b.index_ratio * b.index_ratio;
        refracted.map(|t| (t, DVec3::splat(factor)))
    }

    /// The absorption of a ray that travelled `distance_m` in the medium it arrives from
    /// (rayvalue's extinction over `r->rot`, set by m_dielectric per side).
    pub fn arrival_attenuation(&self, d: DVec3, normal: DVec3, distance_m: f64) -> DVec3 {
        let extinction = if d.dot(normal) > 0.0 {
            self.inside_extinction_per_m
        } else {
            self.outside_extinction_per_m
        };
        (-extinction * distance_m).exp()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn block() -> DielectricMaterial {
        DielectricMaterial::from(&Dielectric {
            inside: Medium {
                transmission_per_m_rgb: DVec3::new(0.5, 1.0, 2.0),
                refractive_index: 1.5,
            },
            outside: Medium::VACUUM,
            is_interface: false,
        })
    }

    #[test]
    fn normal_incidence_reflects_the_fresnel_fraction_and_refraction_obeys_snell() {
        let m = block();
        // ((n - 1)/(n + 1))² = 0.04 at normal incidence (Born & Wolf, §1.5.3).
        let (r, t) = DielectricMaterial::fresnel(&m.boundary(-DVec3::Z, DVec3::Z), -DVec3::Z);
        assert!((r - 0.04).abs() < 1e-12, "{r}");
        assert!((t.unwrap() + DVec3::Z).length() < 1e-12);
        // 30° in air: sin θ2 = sin 30° / 1.5.
        let d = DVec3::new(0.5, 0.0, -(0.75f64).sqrt());
        let (_, t) = DielectricMaterial::fresnel(&m.boundary(d, DVec3::Z), d);
        let t = t.unwrap();
        assert!((t.x - 0.5 / 1.5).abs() < 1e-12, "{t}");
        // From inside past the critical angle asin(1/1.5) ≈ 41.8°: total reflection.
        let d = DVec3::new(0.8, 0.0, 0.6);
        let (r, t) = DielectricMaterial::fresnel(&m.boundary(d, DVec3::Z), d);
        assert_eq!((r, t), (1.0, None));
    }

    #[test]
    fn absorption_applies_inside_only_and_never_amplifies() {
        let m = block();
        let a = m.arrival_attenuation(DVec3::Z, DVec3::Z, 2.0);
        assert!((a - DVec3::new(0.25, 1.0, 1.0)).length() < 1e-12, "{a}");
        assert_eq!(m.arrival_attenuation(-DVec3::Z, DVec3::Z, 2.0), DVec3::ONE);
    }
}

//! Optics shared by the materials, each written once: RADIANCE's brightness of a colour, the
//! mirror direction, normal.c's Fresnel estimate, the thin pane's transmitted and reflected
//! fractions, and the two shapes a scattering event takes for the integrator (the sampled
//! [`Scatter`] and the [`DiffuseLobe`] next-event estimation is weighted against).

use glam::DVec3;
use std::f64::consts::PI;

/// RADIANCE's `bright()` (color.h, the `CIE_` luminance weights of the default primaries):
/// 0.265 R + 0.670 G + 0.065 B.
pub fn bright(c: DVec3) -> f64 {
    0.265 * c.x + 0.670 * c.y + 0.065 * c.z
}

/// Unit `d` mirrored about the plane of unit normal `n` (either side): d − 2 (d·n) n.
pub fn reflect(d: DVec3, n: DVec3) -> DVec3 {
    d - 2.0 * d.dot(n) * n
}

/// Estimate of the Fresnel function, normal.c `FRESNE(ci)`.
pub fn fresne(ci: f64) -> f64 {
    (-5.85 * ci).exp() - 0.00287989916
}

/// Transmitted and reflected fractions of RADIANCE's thin `glass` for a ray at cosine of
/// incidence `pdot` (glass.c `m_glass`): per channel with d = tn^(1/cos θt),
/// cos θt = sqrt(1 − (1 − pdot²)/n²),
/// T = ½ Σ_{s,p} (1 − r)² d / (1 − r² d²),  R = ½ Σ_{s,p} r (1 + (1 − 2r) d²) / (1 − r² d²),
/// with r the single-interface Fresnel reflectances r1e, r1m, `transmissivity_rgb` tn and
/// `refractive_index` n.
pub fn glass_fractions(
    transmissivity_rgb: DVec3,
    refractive_index: f64,
    pdot: f64,
) -> (DVec3, DVec3) {
    let n = refractive_index;
    let pdot = pdot.clamp(1e-9, 1.0);
    let cos2 = ((1.0 - 1.0 / (n * n)) + pdot * pdot / (n * n)).sqrt();
    let mcolor = transmissivity_rgb;
    // Grey glass (the usual case) needs one power, not three.
    let d = if mcolor.x == mcolor.y && mcolor.y == mcolor.z {
        DVec3::splat(mcolor.x.powf(1.0 / cos2))
    } else {
        DVec3::new(
            mcolor.x.powf(1.0 / cos2),
            mcolor.y.powf(1.0 / cos2),
            mcolor.z.powf(1.0 / cos2),
        )
    };
    let r1e = ((pdot - n * cos2) / (pdot + n * cos2)).powi(2);
    let r1m = ((1.0 / pdot - n / cos2) / (1.0 / pdot + n / cos2)).powi(2);
    let mut trans = DVec3::ZERO;
    let mut refl = DVec3::ZERO;
    for i in 0..3 {
        let di = d[i];
        if mcolor[i] > 0.0 {
            trans[i] = 0.5 * (1.0 - r1e) * (1.0 - r1e) * di / (1.0 - r1e * r1e * di * di)
                + 0.5 * (1.0 - r1m) * (1.0 - r1m) * di / (1.0 - r1m * r1m * di * di);
        }
        let d2 = di * di;
        refl[i] = 0.5 * r1e * (1.0 + (1.0 - 2.0 * r1e) * d2) / (1.0 - r1e * r1e * d2)
            + 0.5 * r1m * (1.0 + (1.0 - 2.0 * r1m) * d2) / (1.0 - r1m * r1m * d2);
    }
    (trans, refl)
}

/// How a normal material divides the light it does not absorb (normal.c, aniso.c,
/// m_brdf.c `m_brdf2`): the specular reflectance `rspec`, the transmissivity
/// trans = trans_arg (1 − rspec), its specular part tspec = trans tspec_arg, and the
/// diffuse rests tdiff = trans − tspec, rdiff = 1 − trans − rspec (all fractions of the
/// material colour).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalSplit {
    pub rspec: f64,
    pub trans: f64,
    pub tspec: f64,
    pub tdiff: f64,
    pub rdiff: f64,
}

impl NormalSplit {
    /// From the `spec`, `trans` and `tspec` arguments (the last two 0 for opaque materials).
    pub fn new(specularity: f64, transmissivity: f64, transmitted_specularity: f64) -> Self {
        let rspec = specularity;
        let trans = transmissivity * (1.0 - rspec);
        let tspec = trans * transmitted_specularity;
        NormalSplit {
            rspec,
            trans,
            tspec,
            tdiff: trans - tspec,
            rdiff: 1.0 - trans - rspec,
        }
    }
}

/// What a sampled scattering event does to the path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scatter {
    /// The path ends here.
    Absorbed,
    /// Diffuse reflection or transmission: an ambient bounce in RADIANCE's terms (`-ab`).
    Diffuse { direction: DVec3, weight: DVec3 },
    /// Specular reflection or transmission (smooth or Gaussian): not an ambient bounce.
    Specular { direction: DVec3, weight: DVec3 },
}

/// The diffuse (Lambertian) scattering at a vertex: for a direction ω on the `normal` side
/// the integrand is `front_rgb` |cos θ| L(ω), and the vertex's own sampling produces ω with
/// density `front_probability` |cos θ| / π; likewise behind with the `back_` values. A
/// sensor is the lobe with front 1 and probability 1 (E = ∫ L cos θ dω).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiffuseLobe {
    pub normal: DVec3,
    pub front_rgb: DVec3,
    pub back_rgb: DVec3,
    pub front_probability: f64,
    pub back_probability: f64,
}

impl DiffuseLobe {
    /// The lobe of a sensor facing unit `normal`.
    pub fn sensor(normal: DVec3) -> Self {
        Self {
            normal,
            front_rgb: DVec3::ONE,
            back_rgb: DVec3::ZERO,
            front_probability: 1.0,
            back_probability: 0.0,
        }
    }

    /// (value × |cos θ|, density of the vertex's own sampling) for unit direction `d`.
    pub fn eval(&self, d: DVec3) -> (DVec3, f64) {
        let c = self.normal.dot(d);
        if c > 0.0 {
            (self.front_rgb * c, self.front_probability * c / PI)
        } else {
            (self.back_rgb * -c, self.back_probability * -c / PI)
        }
    }
}

impl DiffuseLobe {
    /// The Lambertian parts of a surface that samples its four `components` (specular
    /// reflection, specular transmission, diffuse reflection, diffuse transmission, zero where
    /// absent) with [`choose_component`]: ρ/π on each side of `normal` and the probability
    /// of each diffuse pick. None when neither diffuse component would be picked.
    pub fn of_components(normal: DVec3, components: &[DVec3; 4]) -> Option<DiffuseLobe> {
        let b = components.map(|c| bright(c).max(0.0));
        let total: f64 = b.iter().sum();
        let (br, bt) = (b[2], b[3]);
        if (total).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) || br + bt <= 0.0 {
            return None;
        }
        Some(DiffuseLobe {
            normal,
            front_rgb: if br > 0.0 {
                components[2] / PI
            } else {
                DVec3::ZERO
            },
            back_rgb: if bt > 0.0 {
                components[3] / PI
            } else {
                DVec3::ZERO
            },
            front_probability: br / total,
            back_probability: bt / total,
        })
    }
}

/// Picks one of `components` (coefficients per RGB channel) with probability proportional to
/// its brightness, from one uniform number: its index and its weight, the coefficient over
/// the probability, so the estimate stays unbiased. None if all are black.
pub fn choose_component(
    components: &[DVec3; 4],
    rng: &mut crate::engine::rng::Rng,
) -> Option<(usize, DVec3)> {
    let b = components.map(|w| bright(w).max(0.0));
    let total: f64 = b.iter().sum();
    if total <= 0.0 || total.is_nan() {
        return None;
    }
    let mut x = rng.uniform() * total;
    let mut pick = 3;
    for (i, bi) in b.iter().enumerate() {
        if x < *bi {
            pick = i;
            break;
        }
        x -= bi;
    }
    while b[pick] == 0.0 {
        pick -= 1; // rounding put x past the last non-zero component
    }
    Some((pick, components[pick] * (total / b[pick])))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::GLASS_DEFAULT_REFRACTIVE_INDEX;

    /// glass.c's own comment: tn = (sqrt(.8402528435 + .0072522239 Tn²) − .9166530661)
    /// / .0036261119 / Tn, so the transmittance at normal incidence of tn must come back as Tn.
    #[test]
    fn glass_normal_transmittance_inverts_the_manual_formula() {
        for tn_meas in [0.65_f64, 0.88, 0.3] {
            let tn = ((0.8402528435 + 0.0072522239 * tn_meas * tn_meas).sqrt() - 0.9166530661)
                / 0.0036261119
                / tn_meas;
            let (t, r) = glass_fractions(DVec3::splat(tn), GLASS_DEFAULT_REFRACTIVE_INDEX, 1.0);
            assert!((t.x - tn_meas).abs() < 1e-6, "{tn_meas}: {}", t.x);
            // Energy: T + R <= 1.
            assert!(t.x + r.x <= 1.0 + 1e-12);
        }
        // The reference room's value: 0.708456 gives 0.65.
        let tn = DVec3::splat(0.708456);
        assert!((glass_fractions(tn, 1.52, 1.0).0.x - 0.65).abs() < 1e-5);
        // Grazing: transmission falls to zero, reflection to one.
        let (t, r) = glass_fractions(tn, 1.52, 1e-6);
        assert!(t.x < 1e-4 && r.x > 0.99, "{t} {r}");
    }
}

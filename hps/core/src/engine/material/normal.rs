//! RADIANCE's normal materials, `plastic`, `metal` and `trans` (src/rt/normal.c: `m_normal`,
//! `dirnorm`, `gaussamp`): a Lambertian part, an isotropic Gaussian (Ward 1992) specular part
//! with RADIANCE's Fresnel estimate for smooth surfaces, and for `trans` diffuse and specular
//! transmission.

use super::scattering::{choose_component, fresne, DiffuseLobe, Scatter};
use crate::engine::ray::FTINY;
use crate::engine::rng::Rng;
use crate::engine::sampling::{basis, cosine_direction};
use crate::scene::{Metal, Plastic, Trans};
use glam::DVec3;
use std::f64::consts::PI;

/// Most tries at a Gaussian specular direction above the surface (normal.c `MAXITER`).
const MAXITER: usize = 10;
/// Smallest specularity given the Fresnel estimate (normal.c `FRESTHRESH`).
const FRESTHRESH: f64 = 0.017999;

/// Which kind of normal material: they differ only in the colour of the specular part and
/// in transmission.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NormalKind {
    Plastic,
    Metal,
    Trans,
}

/// `plastic`, `metal` or `trans` arguments.
#[derive(Clone, Debug)]
pub struct NormalMaterial {
    pub kind: NormalKind,
    pub color_rgb: DVec3,
    pub specularity: f64,
    pub roughness: f64,
    /// `trans` only (0 otherwise).
    pub transmissivity: f64,
    pub transmitted_specularity: f64,
}

impl From<&Plastic> for NormalMaterial {
    fn from(p: &Plastic) -> Self {
        Self {
            kind: NormalKind::Plastic,
            color_rgb: p.reflectance_rgb,
            specularity: p.specularity,
            roughness: p.roughness,
            transmissivity: 0.0,
            transmitted_specularity: 0.0,
        }
    }
}

impl From<&Metal> for NormalMaterial {
    fn from(p: &Metal) -> Self {
        Self {
            kind: NormalKind::Metal,
            color_rgb: p.reflectance_rgb,
            specularity: p.specularity,
            roughness: p.roughness,
            transmissivity: 0.0,
            transmitted_specularity: 0.0,
        }
    }
}

impl From<&Trans> for NormalMaterial {
    fn from(p: &Trans) -> Self {
        Self {
            kind: NormalKind::Trans,
            color_rgb: p.color_rgb,
            specularity: p.specularity,
            roughness: p.roughness,
            transmissivity: p.transmissivity,
            transmitted_specularity: p.transmitted_specularity,
        }
    }
}

/// The state of m_normal's `NORMDAT` at one hit.
#[derive(Clone, Debug)]
pub struct NormalShading {
    mcolor: DVec3,
    scolor: DVec3,
    /// Ray direction (unit, towards the surface).
    rdir: DVec3,
    /// Surface normal turned to face the ray.
    pnorm: DVec3,
    /// The normal the diffuse (ambient) hemisphere is sampled around: `pnorm`, unless a
    /// texture perturbed it, when RADIANCE's `samp_hemi` (-aa 0) keeps the surface's own.
    ambient_normal: DVec3,
    /// cos of incidence, clamped at .001 as normal.c does for `dirnorm`.
    pdot: f64,
    alpha2: f64,
    pure: bool,
    flat: bool,
    rspec: f64,
    trans: f64,
    tspec: f64,
    tdiff: f64,
    rdiff: f64,
}

impl NormalMaterial {
    /// Purely diffuse and opaque: its outgoing radiance is the same towards every viewer on
    /// one side, so a path's estimate of it can serve other sensors (path reuse).
    pub fn is_lambertian(&self) -> bool {
        self.specularity <= 0.0 && self.kind != NormalKind::Trans
    }

    /// m_normal's set-up for a ray in direction `rdir` hitting a surface of front normal
    /// `normal` (`flat` for polygons and rings).
    pub fn shade(&self, rdir: DVec3, normal: DVec3, flat: bool) -> NormalShading {
        let mut rod = -rdir.dot(normal);
        let mut pnorm = normal;
        if rod < 0.0 {
            // flipsurface: the back of the surface is shaded as a front.
            rod = -rod;
            pnorm = -normal;
        }
        let alpha2 = self.roughness * self.roughness;
        let pure = alpha2 <= FTINY;
        let mcolor = self.color_rgb;
        let mut rspec = self.specularity;
        // Fresnel approximation for smooth surfaces: rspec += FRESNE(rod) (1 − rspec).
        let fest = if pure && rspec >= FRESTHRESH {
            let f = fresne(rod);
            rspec += f * (1.0 - rspec);
            f
        } else {
            0.0
        };
        let (trans, tspec, tdiff) = if self.kind == NormalKind::Trans {
            let trans = self.transmissivity * (1.0 - rspec);
            let tspec = trans * self.transmitted_specularity;
            (trans, tspec, trans - tspec)
        } else {
            (0.0, 0.0, 0.0)
        };
        let scolor = if self.kind != NormalKind::Metal {
            DVec3::splat(rspec)
        } else if fest > FTINY {
            let d = rspec * (1.0 - fest);
            DVec3::splat(fest) + mcolor * d
        } else {
            mcolor * rspec
        };
        NormalShading {
            mcolor,
            scolor,
            rdir,
            pnorm,
            ambient_normal: pnorm,
            pdot: rod.max(0.001),
            alpha2,
            pure,
            flat,
            rspec,
            trans,
            tspec,
            tdiff,
            rdiff: 1.0 - trans - rspec,
        }
    }
}

impl NormalShading {
    /// The same shading with its diffuse parts sampled around the surface's own `normal`
    /// (turned to the side of `pnorm`): what a texture leaves to the ambient calculation.
    pub fn with_ambient_normal(mut self, normal: DVec3) -> Self {
        self.ambient_normal = if normal.dot(self.pnorm) < 0.0 {
            -normal
        } else {
            normal
        };
        self
    }

    /// The Lambertian parts of this shading as [`NormalShading::sample`] samples them: the
    /// BRDF (front, the side of the ray) and BTDF (back) values ρ/π per RGB channel and the
    /// probability that `sample` picks each, so next-event estimation at this vertex can be
    /// combined with the sampled continuation by multiple importance sampling. None when no
    /// diffuse component would be sampled (`allow_diffuse` false or no diffuse colour).
    pub fn diffuse_lobe(&self, allow_diffuse: bool) -> Option<DiffuseLobe> {
        if !allow_diffuse {
            return None;
        }
        DiffuseLobe::of_components(self.ambient_normal, &self.components(true))
    }

    /// m_normal's four components, in [`choose_component`]'s order: specular reflection,
    /// specular transmission, diffuse reflection, diffuse transmission (the last two only
    /// with `allow_diffuse`), each zero below `FTINY`.
    fn components(&self, allow_diffuse: bool) -> [DVec3; 4] {
        let above = |x: f64, c: DVec3| if x > FTINY { c } else { DVec3::ZERO };
        let diffuse = |x: f64| {
            if allow_diffuse {
                above(x, self.mcolor * x)
            } else {
                DVec3::ZERO
            }
        };
        [
            above(self.rspec, self.scolor),
            above(self.tspec, self.mcolor * self.tspec),
            diffuse(self.rdiff),
            diffuse(self.tdiff),
        ]
    }

    /// What a shadow ray keeps going through this surface: only smooth `trans` lets source
    /// light through, straight and scaled by colour × tspec (normal.c, the SHADOW branch).
    pub fn shadow_transmission(&self) -> DVec3 {
        if self.tspec > FTINY && self.pure {
            self.mcolor * self.tspec
        } else {
            DVec3::ZERO
        }
    }

    /// normal.c `dirnorm`: the coefficient that turns the radiance of a source of solid angle
    /// `omega_sr` seen in unit direction `ldir` into reflected (or transmitted) radiance.
    pub fn source_coefficient(&self, ldir: DVec3, omega_sr: f64) -> DVec3 {
        let mut cval = DVec3::ZERO;
        let ldot = self.pnorm.dot(ldir);
        if if ldot < 0.0 {
            self.trans <= FTINY
        } else {
            self.trans >= 1.0 - FTINY
        } {
            return cval;
        }
        let (mut lrdiff, mut ltdiff) = (self.rdiff, self.tdiff);
        if self.pure && self.rspec >= FRESTHRESH && (lrdiff > FTINY || ltdiff > FTINY) {
            let d = 1.0 - fresne(ldot.abs());
            lrdiff *= d;
            ltdiff *= d;
        }
        if ldot > FTINY && lrdiff > FTINY {
            // Lambertian: ρ cos Ω / π.
            cval += self.mcolor * (ldot * omega_sr * lrdiff / PI);
        }
        if ldot > FTINY && self.rspec > FTINY && !self.pure {
            // Isotropic Gaussian lobe (Ward 1992, normal.c): exp(−tan²δ / α²) / (4π pdot α²),
            // α² widened by Ω/4π for a flat surface.
            let mut a2 = self.alpha2;
            if self.flat {
                a2 += omega_sr * (0.25 / PI);
            }
            let h = ldir - self.rdir;
            let hn = h.dot(self.pnorm);
            let tan2 = (h.dot(h) - hn * hn) / (hn * hn);
            let g = (-tan2 / a2).exp() / (4.0 * PI * self.pdot * a2);
            if g > FTINY {
                cval += self.scolor * (g * omega_sr);
            }
        }
        if ldot < -FTINY && ltdiff > FTINY {
            cval += self.mcolor * (-ldot * omega_sr * ltdiff / PI);
        }
        if ldot < -FTINY && self.tspec > FTINY && !self.pure {
            // Gaussian transmission around the unrefracted direction.
            let a2 = self.alpha2 + omega_sr / PI;
            let g = ((2.0 * self.rdir.dot(ldir) - 2.0) / a2).exp() / (PI * a2);
            if g > FTINY {
                cval += self.mcolor * (g * self.tspec * omega_sr * (-ldot / self.pdot).sqrt());
            }
        }
        cval
    }

    /// Samples one of m_normal's components (specular reflection, specular transmission,
    /// diffuse reflection, diffuse transmission) with probability proportional to its
    /// brightness; the weight is the component's coefficient over that probability, so the
    /// estimate is unbiased. Diffuse components take part only if `allow_diffuse` (ambient
    /// bounces left); past `-ab` RADIANCE gives them the ambient value, here 0 as `-av 0`.
    pub fn sample(&self, allow_diffuse: bool, rng: &mut Rng) -> Scatter {
        let Some((pick, weight)) = choose_component(&self.components(allow_diffuse), rng) else {
            return Scatter::Absorbed;
        };
        let direction = match pick {
            0 => {
                if self.pure {
                    // vrefl = rdir + 2 pdot pnorm (with the unclamped cosine).
                    let rod = -self.rdir.dot(self.pnorm);
                    Some((self.rdir + 2.0 * rod * self.pnorm).normalize())
                } else {
                    self.gaussian_reflection(rng)
                }
            }
            1 => {
                if self.pure {
                    Some(self.rdir)
                } else {
                    self.gaussian_transmission(rng)
                }
            }
            2 => Some(cosine_direction(self.ambient_normal, rng)),
            _ => Some(cosine_direction(-self.ambient_normal, rng)),
        };
        match (direction, pick) {
            (None, _) => Scatter::Absorbed,
            (Some(direction), 0 | 1) => Scatter::Specular { direction, weight },
            (Some(direction), _) => Scatter::Diffuse { direction, weight },
        }
    }

    /// gaussamp's reflected direction: a facet normal h = n + d (cos φ u + sin φ v),
    /// d = sqrt(−α² ln ξ), the ray mirrored about it; up to MAXITER tries to land above the
    /// surface, else nothing (as RADIANCE).
    fn gaussian_reflection(&self, rng: &mut Rng) -> Option<DVec3> {
        let (u, v) = basis(self.pnorm);
        for _ in 0..MAXITER {
            let phi = 2.0 * PI * rng.uniform();
            let xi = 1.0 - rng.uniform();
            let d = if xi <= FTINY {
                1.0
            } else {
                (self.alpha2 * -xi.ln()).sqrt()
            };
            let h = self.pnorm + d * (phi.cos() * u + phi.sin() * v);
            let s = -2.0 * h.dot(self.rdir) / (1.0 + d * d);
            let dir = self.rdir + s * h;
            if dir.dot(self.pnorm) > FTINY {
                return Some(dir.normalize());
            }
        }
        None
    }

    /// gaussamp's transmitted direction: the unrefracted direction perturbed by the same
    /// Gaussian, kept if it leaves through the back.
    fn gaussian_transmission(&self, rng: &mut Rng) -> Option<DVec3> {
        let (u, v) = basis(self.pnorm);
        for _ in 0..MAXITER {
            let phi = 2.0 * PI * rng.uniform();
            let xi = 1.0 - rng.uniform();
            let d = if xi <= FTINY {
                1.0
            } else {
                (self.alpha2 * -xi.ln()).sqrt()
            };
            let dir = self.rdir + d * (phi.cos() * u + phi.sin() * v);
            if dir.dot(self.pnorm) < -FTINY {
                return Some(dir.normalize());
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lambertian_source_coefficient() {
        let m = NormalMaterial {
            kind: NormalKind::Plastic,
            color_rgb: DVec3::splat(0.5),
            specularity: 0.0,
            roughness: 0.0,
            transmissivity: 0.0,
            transmitted_specularity: 0.0,
        };
        let sh = m.shade(-DVec3::Z, DVec3::Z, true);
        let l = DVec3::new(0.6, 0.0, 0.8);
        let c = sh.source_coefficient(l, 1e-4);
        assert!((c.x - 0.5 * 0.8 * 1e-4 / PI).abs() < 1e-15);
        // From below a plastic: nothing.
        assert_eq!(sh.source_coefficient(-l, 1e-4), DVec3::ZERO);
        // Back face hit: shaded as front (normal flipped towards the ray).
        let back = m.shade(DVec3::Z, DVec3::Z, true);
        assert!(back.source_coefficient(-l, 1e-4).x > 0.0);
    }

    #[test]
    fn sampling_weights_average_to_the_albedo() {
        let m = NormalMaterial {
            kind: NormalKind::Trans,
            color_rgb: DVec3::new(0.8, 0.6, 0.4),
            specularity: 0.05,
            roughness: 0.1,
            transmissivity: 0.5,
            transmitted_specularity: 0.3,
        };
        let sh = m.shade(DVec3::new(0.0, 0.6, -0.8), DVec3::Z, true);
        let mut rng = Rng::for_stream(5, 0);
        let n = 200_000;
        let mut sum = DVec3::ZERO;
        for _ in 0..n {
            match sh.sample(true, &mut rng) {
                Scatter::Diffuse { weight, .. } | Scatter::Specular { weight, .. } => sum += weight,
                Scatter::Absorbed => {}
            }
        }
        // Total coefficient mcolor (rdiff + tdiff + tspec) + rspec, except what gaussamp
        // loses below the surface (small for α = 0.1).
        let expect = m.color_rgb * (sh.rdiff + sh.tdiff + sh.tspec) + DVec3::splat(sh.rspec);
        let mean = sum / n as f64;
        assert!(
            (mean - expect).abs().max_element() < 0.01,
            "{mean} vs {expect}"
        );
    }
}

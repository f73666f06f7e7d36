//! The CIE skies: the 15 standard general skies of ISO 15469:2004 / CIE S 011/E:2003, and the
//! two older CIE skies `gensky` writes, the traditional overcast sky (Moon & Spencer 1942,
//! `gensky -c`) and the 1973 clear sky (`gensky +s`/`-s`). Luminance relative to the zenith,
//! and absolute from a zenith luminance or a diffuse horizontal illuminance, the latter by
//! integrating over the hemisphere ([`hemisphere_integral`]).
//!
//! ISO 15469 (hardware-facts.md §5.4): L/Lz = f(χ) φ(Z) / (f(Zs) φ(0)), gradation
//! φ(Z) = 1 + a exp(b / cos Z) (φ = 1 at the horizon when b < 0), indicatrix
//! f(χ) = 1 + c [exp(d χ) − exp(d π/2)] + e cos²χ, χ the angle from the sun, Zs the sun's
//! zenith angle.

use glam::DVec3;
use std::f64::consts::{FRAC_PI_2, PI};

/// Gradation (a, b) and indicatrix (c, d, e) parameters of one standard sky.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CieParameters {
    pub a: f64,
    pub b: f64,
    pub c: f64,
    pub d: f64,
    pub e: f64,
}

const fn p(a: f64, b: f64, c: f64, d: f64, e: f64) -> CieParameters {
    CieParameters { a, b, c, d, e }
}

/// The 15 standard general skies, type 1 first: ISO 15469:2004 / CIE S 011/E:2003 Table 1
/// (hardware-facts.md §5.4). Types 1–5 overcast (1 = the standard overcast sky), 6–10
/// intermediate, 11–15 clear (12 = standard clear, low turbidity; 13 = clear, polluted).
pub const CIE_STANDARD_SKIES: [CieParameters; 15] = [
    p(4.0, -0.70, 0.0, -1.0, 0.00),
    p(4.0, -0.70, 2.0, -1.5, 0.15),
    p(1.1, -0.80, 0.0, -1.0, 0.00),
    p(1.1, -0.80, 2.0, -1.5, 0.15),
    p(0.0, -1.00, 0.0, -1.0, 0.00),
    p(0.0, -1.00, 2.0, -1.5, 0.15),
    p(0.0, -1.00, 5.0, -2.5, 0.30),
    p(0.0, -1.00, 10.0, -3.0, 0.45),
    p(-1.0, -0.55, 2.0, -1.5, 0.15),
    p(-1.0, -0.55, 5.0, -2.5, 0.30),
    p(-1.0, -0.55, 10.0, -3.0, 0.45),
    p(-1.0, -0.32, 10.0, -3.0, 0.45),
    p(-1.0, -0.32, 16.0, -3.0, 0.30),
    p(-1.0, -0.15, 16.0, -3.0, 0.30),
    p(-1.0, -0.15, 24.0, -2.8, 0.15),
];

/// Which luminance distribution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CieDistribution {
    /// An ISO 15469 standard general sky (its parameters).
    Standard(CieParameters),
    /// The traditional CIE overcast sky, L/Lz = (1 + 2 cos Z)/3 (Moon & Spencer 1942), as
    /// `skybright.cal` `cloudysky` (gensky `-c`).
    TraditionalOvercast,
    /// The CIE 1973 clear sky as `skybright.cal` `sunnysky` (gensky `+s`):
    /// (0.91 + 10 e^{−3χ} + 0.45 cos²χ)(1 − e^{−0.32/cos Z}), over its zenith value.
    Clear1973,
    /// Uniform luminance (gensky `-u`).
    Uniform,
}

/// Inputs a CIE sky cannot take.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum CieError {
    #[error("sky_type {value} is not one of the standard skies 1..=15")]
    SkyType { value: u8 },
    #[error("sun_direction {value:?} is not a finite vector at or above the horizon")]
    SunDirection { value: DVec3 },
    #[error("{field} = {value} is not a finite non-negative number")]
    Scale { field: &'static str, value: f64 },
}

/// A CIE sky shape for a sun position: luminance relative to the zenith.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CieSky {
    distribution: CieDistribution,
    /// Unit vector towards the sun (world frame, +z up).
    sun: DVec3,
    /// The distribution's unnormalised value at the zenith.
    zenith_value: f64,
}

impl CieSky {
    /// A sky of `distribution` with the sun towards `sun_direction` (at or above the
    /// horizon; ignored by the azimuth-free skies but still checked).
    pub fn new(distribution: CieDistribution, sun_direction: DVec3) -> Result<Self, CieError> {
        let len = sun_direction.length();
        if !(len.is_finite() && len > 0.0) || sun_direction.z < 0.0 {
            return Err(CieError::SunDirection {
                value: sun_direction,
            });
        }
        let mut sky = Self {
            distribution,
            sun: sun_direction / len,
            zenith_value: 1.0,
        };
        sky.zenith_value = sky.unnormalised(DVec3::Z);
        Ok(sky)
    }

    /// ISO 15469 standard sky `sky_type` (1..=15).
    pub fn standard(sky_type: u8, sun_direction: DVec3) -> Result<Self, CieError> {
        let parameters = sky_type
            .checked_sub(1)
            .and_then(|i| CIE_STANDARD_SKIES.get(usize::from(i)))
            .ok_or(CieError::SkyType { value: sky_type })?;
        Self::new(CieDistribution::Standard(*parameters), sun_direction)
    }

    pub fn distribution(&self) -> CieDistribution {
        self.distribution
    }

    pub fn sun_direction(&self) -> DVec3 {
        self.sun
    }

    fn unnormalised(&self, d: DVec3) -> f64 {
        let cos_z = d.z;
        let cos_chi = d.dot(self.sun).clamp(-1.0, 1.0);
        match self.distribution {
            CieDistribution::Standard(CieParameters { a, b, c, d: dd, e }) => {
                // exp(b / cos Z) → 0 at the horizon for b < 0 (all standard skies).
                let gradation = if cos_z > 0.0 {
                    1.0 + a * (b / cos_z).exp()
                } else {
                    1.0
                };
                let chi = cos_chi.acos();
                let indicatrix =
                    1.0 + c * ((dd * chi).exp() - (dd * FRAC_PI_2).exp()) + e * cos_chi * cos_chi;
                gradation * indicatrix
            }
            CieDistribution::TraditionalOvercast => (1.0 + 2.0 * cos_z) / 3.0,
            CieDistribution::Clear1973 => {
                let chi = cos_chi.acos();
                let gradation = if cos_z > 0.0 {
                    1.0 - (-0.32 / cos_z).exp()
                } else {
                    1.0
                };
                (0.91 + 10.0 * (-3.0 * chi).exp() + 0.45 * cos_chi * cos_chi) * gradation
            }
            CieDistribution::Uniform => 1.0,
        }
    }

    /// L/Lz along `direction` (any length); 0 below the horizon.
    pub fn relative_luminance(&self, direction: DVec3) -> f64 {
        let d = direction.normalize_or_zero();
        if d.z < 0.0 || d == DVec3::ZERO {
            return 0.0;
        }
        self.unnormalised(d) / self.zenith_value
    }

    /// Horizontal illuminance per unit zenith luminance, ∫ (L/Lz) cos θ dΩ over the upper
    /// hemisphere (sr), by [`hemisphere_integral`].
    pub fn horizontal_illuminance_per_zenith_luminance(&self, grid: HemisphereGrid) -> f64 {
        hemisphere_integral(|d| self.relative_luminance(d), grid)
    }

    /// The absolute sky with zenith luminance `zenith_cd_m2`.
    pub fn with_zenith_luminance(self, zenith_cd_m2: f64) -> Result<ScaledCieSky, CieError> {
        if !(zenith_cd_m2.is_finite() && zenith_cd_m2 >= 0.0) {
            return Err(CieError::Scale {
                field: "zenith_cd_m2",
                value: zenith_cd_m2,
            });
        }
        Ok(ScaledCieSky {
            sky: self,
            zenith_cd_m2,
        })
    }

    /// The absolute sky whose diffuse horizontal illuminance is `diffuse_horizontal_lux`.
    pub fn with_diffuse_horizontal_illuminance(
        self,
        diffuse_horizontal_lux: f64,
        grid: HemisphereGrid,
    ) -> Result<ScaledCieSky, CieError> {
        if !(diffuse_horizontal_lux.is_finite() && diffuse_horizontal_lux >= 0.0) {
            return Err(CieError::Scale {
                field: "diffuse_horizontal_lux",
                value: diffuse_horizontal_lux,
            });
        }
        let per_zenith = self.horizontal_illuminance_per_zenith_luminance(grid);
        self.with_zenith_luminance(diffuse_horizontal_lux / per_zenith)
    }
}

/// A CIE sky with an absolute scale.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledCieSky {
    pub sky: CieSky,
    pub zenith_cd_m2: f64,
}

impl ScaledCieSky {
    /// Luminance along `direction`, cd/m² (0 below the horizon).
    pub fn luminance_cd_m2(&self, direction: DVec3) -> f64 {
        self.zenith_cd_m2 * self.sky.relative_luminance(direction)
    }

    pub fn horizontal_illuminance_lux(&self, grid: HemisphereGrid) -> f64 {
        self.zenith_cd_m2 * self.sky.horizontal_illuminance_per_zenith_luminance(grid)
    }
}

/// The quadrature of [`hemisphere_integral`]: `rings` bands of equal zenith angle, each cut
/// into `sectors` equal azimuth steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HemisphereGrid {
    pub rings: usize,
    pub sectors: usize,
}

impl Default for HemisphereGrid {
    /// 0.5° rings × 0.5° sectors: the circumsolar peaks of the clearest skies (Perez d ≈ −7,
    /// CIE type 15) are resolved to < 1e-4 of the integral.
    fn default() -> Self {
        Self {
            rings: 180,
            sectors: 720,
        }
    }
}

/// ∫ f(d) cos θ dΩ over the upper hemisphere: f at each cell's centre times the cell's exact
/// projected solid angle (sin²θ₂ − sin²θ₁)/2 · Δφ, so a constant is integrated exactly (π)
/// and smooth functions to O(h²). Used to normalise skies to a horizontal illuminance.
pub fn hemisphere_integral(f: impl Fn(DVec3) -> f64, grid: HemisphereGrid) -> f64 {
    let rings = grid.rings.max(1);
    let sectors = grid.sectors.max(1);
    let d_theta = FRAC_PI_2 / rings as f64;
    let d_phi = 2.0 * PI / sectors as f64;
    let mut total = 0.0;
    for i in 0..rings {
        let (t0, t1) = (i as f64 * d_theta, (i + 1) as f64 * d_theta);
        let weight = 0.5 * (t1.sin().powi(2) - t0.sin().powi(2)) * d_phi;
        let theta = 0.5 * (t0 + t1);
        let (sin_t, cos_t) = theta.sin_cos();
        let mut ring = 0.0;
        for k in 0..sectors {
            let (sin_p, cos_p) = ((k as f64 + 0.5) * d_phi).sin_cos();
            ring += f(DVec3::new(sin_t * sin_p, sin_t * cos_p, cos_t));
        }
        total += ring * weight;
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sun(alt_deg: f64, az_deg: f64) -> DVec3 {
        crate::sun::sun_direction(90.0 - alt_deg, az_deg)
    }

    #[test]
    fn relative_luminance_is_one_at_the_zenith_and_zero_below() {
        for t in 1..=15 {
            let s = CieSky::standard(t, sun(35.0, 200.0)).unwrap();
            assert!(
                (s.relative_luminance(DVec3::Z) - 1.0).abs() < 1e-12,
                "type {t}"
            );
            assert_eq!(s.relative_luminance(DVec3::new(0.3, 0.2, -0.5)), 0.0);
        }
    }

    /// Type 1 is azimuth-free and (almost) the traditional overcast sky: at the horizon
    /// 1/(1 + 4e^{-0.7}) against 1/3.
    #[test]
    fn type_1_gradation() {
        let s = CieSky::standard(1, sun(30.0, 0.0)).unwrap();
        let h = s.relative_luminance(DVec3::X);
        assert!((h - 1.0 / (1.0 + 4.0 * (-0.7f64).exp())).abs() < 1e-12);
        let a = s.relative_luminance(sun(40.0, 10.0));
        let b = s.relative_luminance(sun(40.0, 250.0));
        assert!((a - b).abs() < 1e-12);
    }

    /// The clear skies peak at the sun.
    #[test]
    fn clear_skies_peak_towards_the_sun() {
        let sd = sun(40.0, 135.0);
        for t in 11..=15 {
            let s = CieSky::standard(t, sd).unwrap();
            let at_sun = s.relative_luminance(sd);
            let opposite = s.relative_luminance(sun(40.0, 315.0));
            assert!(at_sun > 5.0 * opposite, "type {t}: {at_sun} vs {opposite}");
        }
    }

    #[test]
    fn bad_inputs() {
        assert_eq!(
            CieSky::standard(0, DVec3::Z).unwrap_err(),
            CieError::SkyType { value: 0 }
        );
        assert_eq!(
            CieSky::standard(16, DVec3::Z).unwrap_err(),
            CieError::SkyType { value: 16 }
        );
        assert!(CieSky::standard(3, DVec3::new(f64::NAN, 0.0, 1.0)).is_err());
        assert!(CieSky::standard(3, DVec3::new(0.0, 1.0, -0.1)).is_err());
        let s = CieSky::standard(3, DVec3::Z).unwrap();
        assert!(s.with_zenith_luminance(-1.0).is_err());
        assert!(s
            .with_diffuse_horizontal_illuminance(f64::INFINITY, HemisphereGrid::default())
            .is_err());
    }
}

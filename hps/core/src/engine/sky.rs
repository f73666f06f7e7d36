//! The sky as RADIANCE describes it: `brightfunc` patterns from `skybright.cal` (gensky) and
//! `perezlum.cal` (gendaylit), and distant `source`s carrying a `glow` (sky, ground) or a
//! `light` (the sun).
//!
//! The functions are the .cal files transcribed (RADIANCE `lib/skybright.cal` v2.7,
//! `lib/perezlum.cal` v1.2), with `Acos` and `Exp` as `lib/rayinit.cal` defines them. `D` is
//! the ray direction, pointing away from the scene towards the sky.

use super::error::EngineError;
use crate::scene::{Brightfunc, SourceLocation};
use glam::DVec3;

/// A sky brightness function, ready to evaluate.
#[derive(Clone, Debug, PartialEq)]
pub enum SkyFunction {
    /// `skybr` of `skybright.cal`: A1 = 1 CIE clear, 2 CIE overcast, 3 uniform, 4 CIE
    /// intermediate; A2 zenith brightness; A3 ground brightness; A4 normalisation; A5..A7 sun
    /// direction (A4.. needed for types 1 and 4 only).
    Skybright {
        sky_type: u8,
        zenith: f64,
        ground: f64,
        normalisation: f64,
        sun: DVec3,
    },
    /// `skybright` of `perezlum.cal`: A1 diffuse normalisation, A2 ground brightness,
    /// A3..A7 Perez coefficients a..e, A8..A10 sun direction.
    Perez {
        normalisation: f64,
        ground: f64,
        coefficients: [f64; 5],
        sun: DVec3,
    },
}

/// `Acos(x) : acos(bound(-1,x,1))` (rayinit.cal).
fn acos_bounded(x: f64) -> f64 {
    x.clamp(-1.0, 1.0).acos()
}

/// `Exp(x) : if(-x-100, 0, exp(x))` (rayinit.cal).
fn exp_bounded(x: f64) -> f64 {
    if -x - 100.0 > 0.0 {
        0.0
    } else {
        x.exp()
    }
}

/// `wmean(a, x, b, y) : (a*x + b*y) / (a + b)`, blending sky and ground near the horizon with
/// weights (Dz+1.01)^10 and (Dz+1.01)^-10 (both .cal files).
fn horizon_blend(dz: f64, sky: f64, ground: f64) -> f64 {
    let a = (dz + 1.01).powi(10);
    let b = (dz + 1.01).powi(-10);
    (a * sky + b * ground) / (a + b)
}

impl SkyFunction {
    /// Reads a `brightfunc` as RADIANCE would evaluate it; anything else is an error naming
    /// where the pattern is defined.
    pub fn from_brightfunc(b: &Brightfunc, at: &SourceLocation) -> Result<Self, EngineError> {
        let unsupported = |why: String| EngineError::Unsupported {
            at: at.clone(),
            what: format!("brightfunc `{} {}`: {why}", b.function_name, b.cal_file),
        };
        if !b.transform.is_empty() {
            return Err(unsupported(format!(
                "transform `{}` is not supported",
                b.transform.join(" ")
            )));
        }
        let file = std::path::Path::new(&b.cal_file)
            .file_name()
            .and_then(|f| f.to_str())
            .unwrap_or("");
        let a = &b.real_args;
        let need = |n: usize, usage: &str| {
            if a.len() < n {
                Err(unsupported(format!(
                    "{} real arguments; expected at least {n} ({usage})",
                    a.len()
                )))
            } else {
                Ok(())
            }
        };
        let sun_at = |i: usize| -> Result<DVec3, EngineError> {
            let s = DVec3::new(a[i], a[i + 1], a[i + 2]);
            let len = s.length();
            if !(len > 0.0 && len.is_finite()) {
                return Err(unsupported("the sun direction is zero".into()));
            }
            // gensky writes 6 decimals; renormalise as the .cal uses it as a unit vector.
            Ok(s / len)
        };
        match (file, b.function_name.as_str()) {
            ("skybright.cal", "skybr") => {
                need(3, "type zenith ground [norm sunx suny sunz]")?;
                let sky_type = match a[0] {
                    1.0 => 1,
                    2.0 => 2,
                    3.0 => 3,
                    4.0 => 4,
                    t => {
                        return Err(unsupported(format!(
                            "sky type A1 = {t}; expected 1, 2, 3 or 4"
                        )))
                    }
                };
                let (normalisation, sun) = if sky_type == 1 || sky_type == 4 {
                    need(7, "type zenith ground norm sunx suny sunz")?;
                    if a[3] == 0.0 {
                        return Err(unsupported("normalisation A4 is 0".into()));
                    }
                    (a[3], sun_at(4)?)
                } else {
                    (1.0, DVec3::Z)
                };
                Ok(SkyFunction::Skybright {
                    sky_type,
                    zenith: a[1],
                    ground: a[2],
                    normalisation,
                    sun,
                })
            }
            ("perezlum.cal", "skybright") => {
                need(10, "norm ground a b c d e sunx suny sunz")?;
                Ok(SkyFunction::Perez {
                    normalisation: a[0],
                    ground: a[1],
                    coefficients: [a[2], a[3], a[4], a[5], a[6]],
                    sun: sun_at(7)?,
                })
            }
            _ => Err(unsupported(
                "only `skybr skybright.cal` (gensky) and `skybright perezlum.cal` (gendaylit) \
                 are evaluated"
                    .into(),
            )),
        }
    }

    /// The pattern's value for a ray travelling in unit direction `d`.
    pub fn value(&self, d: DVec3) -> f64 {
        match *self {
            SkyFunction::Skybright {
                sky_type,
                zenith,
                ground,
                normalisation,
                sun,
            } => {
                let sky = match sky_type {
                    // sunnysky = A2 (.91 + 10 exp(-3γ) + .45 cos²γ)
                    //            × if(Dz − .01, 1 − exp(−.32/Dz), 1) / A4
                    1 => {
                        let cos_gamma = d.dot(sun);
                        let gamma = acos_bounded(cos_gamma);
                        let horizon = if d.z - 0.01 > 0.0 {
                            1.0 - (-0.32 / d.z).exp()
                        } else {
                            1.0
                        };
                        zenith
                            * (0.91 + 10.0 * (-3.0 * gamma).exp() + 0.45 * cos_gamma * cos_gamma)
                            * horizon
                            / normalisation
                    }
                    // cloudysky = A2 (1 + 2 Dz) / 3 (Moon & Spencer)
                    2 => zenith * (1.0 + 2.0 * d.z) / 3.0,
                    // unifsky = A2
                    3 => zenith,
                    // intersky = A2 ((1.35 sin(5.631 − 3.59η) + 3.12) sin(4.396 − 2.6 zt)
                    //            + 6.37 − η) / 2.326 × exp(γ (−.563) ((2.629 − η)(1.562 − zt)
                    //            + .812)) / A4
                    _ => {
                        let gamma = acos_bounded(d.dot(sun));
                        let zt = acos_bounded(sun.z);
                        let eta = acos_bounded(d.z);
                        zenith
                            * ((1.35 * (5.631 - 3.59 * eta).sin() + 3.12)
                                * (4.396 - 2.6 * zt).sin()
                                + 6.37
                                - eta)
                            / 2.326
                            * (gamma * -0.563 * ((2.629 - eta) * (1.562 - zt) + 0.812)).exp()
                            / normalisation
                    }
                };
                horizon_blend(d.z, sky, ground)
            }
            SkyFunction::Perez {
                normalisation,
                ground,
                coefficients: [a, b, c, dd, e],
                sun,
            } => {
                // intersky = A1 (1 + A3 Exp(A4 / max-ish(Dz, .01))) (1 + A5 Exp(A6 γ) + A7 cos²γ)
                let cos_gamma = d.dot(sun);
                let gamma = acos_bounded(cos_gamma);
                let dz = if d.z - 0.01 > 0.0 { d.z } else { 0.01 };
                let sky = normalisation
                    * (1.0 + a * exp_bounded(b / dz))
                    * (1.0 + c * exp_bounded(dd * gamma) + e * cos_gamma * cos_gamma);
                horizon_blend(d.z, sky, ground)
            }
        }
    }
}

/// What a distant source emits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DistantKind {
    /// `light` (the sun): reached only by next-event estimation, as RADIANCE counts it only
    /// in its direct calculation (source.c `badcomponent`).
    Light,
    /// `glow` (sky, ground): reached by sampled rays; RADIANCE skips distant glows as direct
    /// sources (`SSKIP`) and finds them through the ambient calculation.
    Glow,
}

/// A `source` primitive with its emitting material.
#[derive(Clone, Debug)]
pub struct DistantEmitter {
    pub name: String,
    pub kind: DistantKind,
    /// Unit direction towards the source's centre.
    pub direction: DVec3,
    /// cos of the half angle: directions d with d · direction >= this are inside.
    pub cos_half_angle: f64,
    pub solid_angle_sr: f64,
    /// Material radiance per RGB channel.
    pub radiance_w_sr_m2: DVec3,
    /// Patterns on the modifier chain, multiplied together.
    pub patterns: Vec<SkyFunction>,
}

impl DistantEmitter {
    /// A sun: a uniform `light` disk of `solid_angle_sr` around unit `direction`, of white
    /// radiance `radiance_w_sr_m2` (RADIANCE units: luminance / 179).
    pub fn sun(direction: DVec3, solid_angle_sr: f64, radiance_w_sr_m2: f64) -> Self {
        Self {
            name: "skylux_sun".into(),
            kind: DistantKind::Light,
            direction: direction.normalize(),
            cos_half_angle: 1.0 - solid_angle_sr / std::f64::consts::TAU,
            solid_angle_sr,
            radiance_w_sr_m2: DVec3::splat(radiance_w_sr_m2),
            patterns: vec![],
        }
    }

    /// Inside the source's cone (RADIANCE's test in raytrace.c `sourcehit` is
    /// 2π(1 − D · dir) <= Ω, the same cone); the 1e-12 keeps a direction exactly on the rim
    /// of a hemisphere (the horizon) inside despite cos(π/2) rounding to 6e-17.
    pub fn contains(&self, d: DVec3) -> bool {
        d.dot(self.direction) >= self.cos_half_angle - 1e-12
    }

    /// Radiance seen along `d` (assumed inside).
    pub fn radiance(&self, d: DVec3) -> DVec3 {
        self.patterns
            .iter()
            .fold(self.radiance_w_sr_m2, |l, p| l * p.value(d))
    }
}

/// Which distant source a ray escaping the scene in direction `d` sees, as RADIANCE's
/// `sourcehit` chooses: the first `light` containing it, else the first `glow`.
pub fn source_seen(sources: &[DistantEmitter], d: DVec3) -> Option<&DistantEmitter> {
    let mut glow = None;
    for s in sources {
        if !s.contains(d) {
            continue;
        }
        match s.kind {
            DistantKind::Light => return Some(s),
            DistantKind::Glow => {
                if glow.is_none() {
                    glow = Some(s)
                }
            }
        }
    }
    glow
}

#[cfg(test)]
mod tests {
    use super::*;

    fn overcast(zenith: f64, ground: f64) -> SkyFunction {
        SkyFunction::Skybright {
            sky_type: 2,
            zenith,
            ground,
            normalisation: 1.0,
            sun: DVec3::Z,
        }
    }

    /// Values worked by hand from skybright.cal.
    #[test]
    fn skybright_overcast_matches_the_cal_file() {
        let f = overcast(40.93, 6.366);
        // Zenith: wmean(2.01^10, 40.93, 2.01^-10, 6.366) ≈ 40.93 (weight of ground ~ 1e-6).
        let z = f.value(DVec3::Z);
        let w = 2.01f64.powi(20);
        assert!((z - (w * 40.93 + 6.366) / (w + 1.0)).abs() < 1e-12);
        // Horizon: sky = A2/3, blended with the ground by 1.01^±10.
        let h = f.value(DVec3::X);
        let (a, b) = (1.01f64.powi(10), 1.01f64.powi(-10));
        assert!((h - (a * 40.93 / 3.0 + b * 6.366) / (a + b)).abs() < 1e-12);
        // Nadir: wmean(0.01^10, ..., 0.01^-10, A3) = A3 to 1e-40.
        assert!((f.value(-DVec3::Z) - 6.366).abs() < 1e-9);
    }

    #[test]
    fn skybright_clear_sky_peaks_at_the_sun() {
        let sun = DVec3::new(0.177949, -0.718629, 0.672240).normalize();
        let f = SkyFunction::Skybright {
            sky_type: 1,
            zenith: 8.855,
            ground: 20.1,
            normalisation: 0.5298,
            sun,
        };
        // At the sun: gamma = 0, horizon factor 1 - exp(-.32/Dz).
        let expect = 8.855 * (0.91 + 10.0 + 0.45) * (1.0 - (-0.32 / sun.z).exp()) / 0.5298;
        let w = (sun.z + 1.01).powi(20);
        let expect = (w * expect + 20.1) / (w + 1.0);
        // acos near 1 leaves gamma ~ 1e-8 rather than 0: exp(-3 gamma) differs by ~3e-8.
        assert!((f.value(sun) - expect).abs() < 1e-6 * expect);
        let away = DVec3::new(-0.2, 0.7, 0.68).normalize();
        assert!(f.value(away) < f.value(sun) / 5.0);
    }

    #[test]
    fn source_choice_prefers_lights_then_the_first_glow() {
        let mk = |name: &str, kind, direction: DVec3, angle_deg: f64| {
            let half = 0.5 * f64::to_radians(angle_deg);
            DistantEmitter {
                name: name.into(),
                kind,
                direction,
                cos_half_angle: half.cos(),
                solid_angle_sr: 2.0 * std::f64::consts::PI * (1.0 - half.cos()),
                radiance_w_sr_m2: DVec3::ONE,
                patterns: vec![],
            }
        };
        let sources = vec![
            mk("sky", DistantKind::Glow, DVec3::Z, 180.0),
            mk("ground", DistantKind::Glow, -DVec3::Z, 180.0),
            mk("sun", DistantKind::Light, DVec3::new(0.0, 0.6, 0.8), 0.5),
        ];
        assert_eq!(
            source_seen(&sources, DVec3::new(0.0, 0.6, 0.8))
                .unwrap()
                .name,
            "sun"
        );
        assert_eq!(source_seen(&sources, DVec3::Z).unwrap().name, "sky");
        assert_eq!(source_seen(&sources, -DVec3::Z).unwrap().name, "ground");
        // Exactly horizontal: both hemispheres contain it; the first glow wins.
        assert_eq!(source_seen(&sources, DVec3::X).unwrap().name, "sky");
    }
}

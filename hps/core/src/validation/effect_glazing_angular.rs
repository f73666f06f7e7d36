//! Effect `glazing_angular`: the glazing's transmittance falls with the incidence angle more
//! than the scene's glass says (dirt, a coating, another glass).
//!
//! Model: ASHRAE's one-parameter incidence-angle modifier (Souka & Safwat 1966, "Determination
//! of the optimum orientations for the double-exposure, flat-plate collector and its
//! reflectors", Solar Energy 10(4); ASHRAE Standard 93; pvlib `iam.ashrae`, b0 = 0.05 for
//! clean glass): IAM(θ) = 1 − b0 (1/cos θ − 1), clamped to [0, 1]. Light crossing the
//! glazing at incidence θ is multiplied by IAM(θ) on top of the scene's glass.
//!
//! Since RADIANCE-style glass does not refract, light that reaches a sensor from the sky
//! direction d crossed the glazing at the angle between d and the glazing's outward normal:
//! each sky and ground bin of the daylight coefficients is rescaled by IAM at its centre's
//! incidence angle, the sun by IAM at the sun's, and the rows re-applied
//! ([`apply_glazing_angular`]). b0 is fitted on the fit set by a scan and golden-section
//! search ([`fit_glazing_angular`]). Signature: the residual of the sunlit readings falls
//! with the solar incidence angle on the glazing (over-prediction growing with the angle).
//!
//! Limitation: one glazing orientation (every plane facing the same way, as in the reference
//! room); with several, the loop does not try the effect.

use super::device_model::{predict, CaptureTerms, ModelState};
use super::effects::{fit_error, fit_linear, Candidate, Effect, FreeLinear, Sample};
use super::split::FitSet;
use crate::engine::DaylightCoefficients;
use glam::DVec3;
use std::collections::BTreeMap;

/// Largest b0 the fit considers (IAM(60°) = 0 at b0 = 1).
pub const MAX_B0: f64 = 1.0;

/// ASHRAE's incidence-angle modifier at cosine of incidence `cos_theta`, clamped to [0, 1];
/// 0 at or beyond grazing incidence.
pub fn iam_ashrae(cos_theta: f64, b0: f64) -> f64 {
    if cos_theta.is_nan() || cos_theta <= 0.0 {
        return 0.0;
    }
    (1.0 - b0 * (1.0 / cos_theta.min(1.0) - 1.0)).clamp(0.0, 1.0)
}

/// Per bin (sky patches, then mirrored ground patches), the cosine of incidence on glazing
/// of outward normal `normal_out` of light arriving from the bin's centre.
pub fn bin_cosines(dc: &DaylightCoefficients, normal_out: DVec3) -> Vec<f64> {
    let patches = dc.patches();
    let n = patches.len();
    (0..2 * n)
        .map(|b| {
            let c = patches.centre(b % n);
            let d = if b < n { c } else { DVec3::new(c.x, c.y, -c.z) };
            d.dot(normal_out)
        })
        .collect()
}

/// The terms with the glazing's angular transmittance of parameter `b0` applied to every sky
/// and ground bin and to the sun: `base` must be the terms without it (as
/// [`super::device_model::capture_terms`] computes them).
pub fn apply_glazing_angular(
    dc: &DaylightCoefficients,
    cosines: &[f64],
    normal_out: DVec3,
    base: &[CaptureTerms],
    b0: f64,
) -> Vec<CaptureTerms> {
    let factor: Vec<f64> = cosines.iter().map(|c| iam_ashrae(*c, b0)).collect();
    let sensors = dc.sensors.len();
    let n = cosines.len() / 2;
    base.iter()
        .map(|t| {
            let mut out = t.clone();
            if t.bins_with_sun_cd_m2.len() != cosines.len() {
                return out;
            }
            let apply = |lum: &[f64]| -> Vec<f64> {
                (0..sensors)
                    .map(|s| {
                        dc.row(s)
                            .iter()
                            .zip(lum)
                            .zip(&factor)
                            .filter(|((_, l), _)| l.is_finite())
                            .map(|((c, l), f)| c * l * f)
                            .sum()
                    })
                    .collect()
            };
            out.sky_with_sun_lux = apply(&t.bins_with_sun_cd_m2);
            out.sky_without_sun_lux = apply(&t.bins_without_sun_cd_m2);
            out.unseen_ground_lux_per_cd_m2 = (0..sensors)
                .map(|s| {
                    (0..n)
                        .filter(|&p| !t.bin_seen[n + p])
                        .map(|p| dc.row(s)[n + p] * factor[n + p])
                        .sum()
                })
                .collect();
            if let Some(sun) = &t.sun {
                let f = iam_ashrae(sun.direction.dot(normal_out), b0);
                for k in &mut out.sun_lux_per_dn_lux {
                    *k *= f;
                }
            }
            out
        })
        .collect()
}

/// The glazing the effect acts on: the room's daylight coefficients (a copy: the loop keeps
/// the room mutable), the bins' cosines of incidence and the outward normal.
pub struct AngularGlazing {
    pub dc: DaylightCoefficients,
    pub normal_out: DVec3,
    pub cosines: Vec<f64>,
    /// Per sensor, the distance from the glazing plane, m (for the evidence).
    pub sensor_depth_m: Vec<f64>,
}

impl AngularGlazing {
    pub fn new(dc: &DaylightCoefficients, normal_out: DVec3, sensor_depth_m: Vec<f64>) -> Self {
        Self {
            dc: dc.clone(),
            normal_out,
            cosines: bin_cosines(dc, normal_out),
            sensor_depth_m,
        }
    }

    /// `base` (terms without the effect) with the effect of parameter `b0`.
    pub fn apply(&self, base: &[CaptureTerms], b0: f64) -> Vec<CaptureTerms> {
        apply_glazing_angular(&self.dc, &self.cosines, self.normal_out, base, b0)
    }
}

/// Relative residual of the sunlit fit-set readings (modelled direct sun > 5 % of the
/// reading) against the solar incidence angle on the glazing (degrees, from the extracted
/// sun): (angle, residual) pairs.
fn sunlit_by_incidence(
    state: &ModelState,
    terms: &[CaptureTerms],
    fit: &FitSet<Sample>,
    normal_out: DVec3,
) -> Vec<(f64, f64)> {
    let mut xy = Vec::new();
    for s in fit.samples() {
        let t = &terms[s.capture];
        let Some(sun) = &t.sun else { continue };
        let cos = sun.direction.dot(normal_out);
        if cos <= 0.0 {
            continue;
        }
        let p = predict(state, t);
        for (k, pk) in p.iter().enumerate() {
            let Some(m) = s.measured(k, state.clock_offset_s).filter(|m| *m > 0.0) else {
                continue;
            };
            let direct = state.glazing_transmittance * t.sun_lux_per_dn_lux[k] * t.sun_dn_lux;
            if direct > 0.05 * m {
                xy.push((cos.clamp(-1.0, 1.0).acos().to_degrees(), pk / m - 1.0));
            }
        }
    }
    xy
}

/// Fits b0 on the fit set from `state` (whose b0 must be 0: `base` are the terms without the
/// effect), with the linear effects already `accepted` refitted at each trial. Returns the
/// candidate, its fit-set error and the terms with the effect. `None` if the best b0 is 0.
pub fn fit_glazing_angular(
    glazing: &AngularGlazing,
    state: &ModelState,
    accepted: &[Effect],
    base: &[CaptureTerms],
    fit: &FitSet<Sample>,
) -> Option<(Candidate, f64, Vec<CaptureTerms>)> {
    let free = FreeLinear::of(accepted);
    let refit = free != FreeLinear::default();
    let evaluate = |b0: f64| -> (f64, ModelState, Vec<CaptureTerms>) {
        let terms = glazing.apply(base, b0);
        let mut st = ModelState {
            glazing_angular_b0: b0,
            ..state.clone()
        };
        if refit {
            if let Some(next) = fit_linear(&st, free, &terms, fit) {
                st = next;
            }
        }
        let e = fit_error(&st, &terms, fit);
        (if e.is_finite() { e } else { f64::INFINITY }, st, terms)
    };
    // Scan, then golden section between the best's neighbours.
    let step = 0.025;
    let grid: Vec<f64> = (0..=(MAX_B0 / step).round() as usize)
        .map(|k| k as f64 * step)
        .collect();
    let errors: Vec<f64> = grid.iter().map(|&b| evaluate(b).0).collect();
    let i = (0..grid.len()).min_by(|&a, &b| errors[a].total_cmp(&errors[b]))?;
    if i == 0 {
        return None;
    }
    let (x, e) = crate::numerics::golden_section(
        grid[i - 1],
        grid.get(i + 1).copied().unwrap_or(MAX_B0),
        (grid[i], errors[i]),
        20,
        |b0| evaluate(b0).0,
    );
    let best = (e, x);
    let (err, next, terms) = evaluate(best.1);
    let xy = sunlit_by_incidence(state, base, fit, glazing.normal_out);
    let (r, slope) = crate::numerics::pearson(&xy).map_or((f64::NAN, f64::NAN), |p| (p.r, p.slope));
    // The diffuse part: near the façade a sensor sees the sky through the glazing at wider
    // angles, so the over-prediction falls with depth.
    let depth_xy: Vec<(f64, f64)> = fit
        .samples()
        .iter()
        .flat_map(|s| {
            let p = predict(state, &base[s.capture]);
            (0..p.len())
                .filter_map(|k| {
                    let m = s.measured(k, state.clock_offset_s).filter(|m| *m > 0.0)?;
                    let depth = *glazing.sensor_depth_m.get(k)?;
                    depth.is_finite().then(|| (depth, p[k] / m - 1.0))
                })
                .collect::<Vec<_>>()
        })
        .collect();
    let (r_depth, _) =
        crate::numerics::pearson(&depth_xy).map_or((f64::NAN, f64::NAN), |p| (p.r, p.slope));
    let mut parameters = BTreeMap::new();
    parameters.insert("b0".into(), next.glazing_angular_b0);
    let evidence = format!(
        "the measured / modelled illuminance of the {} sunlit readings falls with the solar \
         incidence angle on the glazing: the relative residual (model / measured − 1) follows \
         the angle (r = {r:.2}, {:+.1} % per 10°), over-prediction growing with it, as a \
         transmittance that falls off with incidence faster than the scene's glass; and over \
         all {} readings the over-prediction falls with the sensor's distance from the façade \
         (r = {r_depth:.2}), whose sky is seen at wider angles near the glazing; ASHRAE \
         incidence-angle modifier fitted",
        xy.len(),
        1000.0 * slope,
        depth_xy.len()
    );
    Some((
        Candidate {
            effect: Effect::GlazingAngular,
            state: next,
            parameters,
            evidence,
        },
        err,
        terms,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// pvlib's `iam.ashrae` at b = 0.05: 60° → 1 − 0.05 (2 − 1) = 0.95; 80° →
    /// 1 − 0.05 (5.758770 − 1) = 0.7620615; 0 at 90° and beyond; 1 at normal incidence.
    #[test]
    fn ashrae_modifier() {
        let c = |deg: f64| deg.to_radians().cos();
        assert!((iam_ashrae(c(60.0), 0.05) - 0.95).abs() < 1e-12);
        assert!((iam_ashrae(c(80.0), 0.05) - 0.7620615).abs() < 1e-6);
        assert_eq!(iam_ashrae(1.0, 0.3), 1.0);
        assert_eq!(iam_ashrae(0.0, 0.05), 0.0);
        assert_eq!(iam_ashrae(-0.5, 0.05), 0.0);
        assert_eq!(iam_ashrae(f64::NAN, 0.05), 0.0);
        // Clamped at grazing: 1/cos − 1 > 1/b0.
        assert_eq!(iam_ashrae(c(89.0), 0.05), 0.0);
    }

    /// One sensor lit by one sky bin and one unseen ground bin: the applied terms are the
    /// coefficients times the luminance times the IAM of each bin centre's incidence on a
    /// south-facing glazing, computed here from the patch centres.
    #[test]
    fn bins_are_rescaled_by_their_incidence() {
        let patches = crate::sky::SkyPatches::reinhart(1);
        let n = patches.len();
        let normal = DVec3::new(0.0, -1.0, 0.0);
        // A southern sky patch and the mirror of another as unseen ground.
        let sky = (0..n).find(|&p| patches.centre(p).y < -0.5).unwrap();
        let ground = (0..n).find(|&p| patches.centre(p).y < -0.8).unwrap();
        let mut coefficients = vec![0.0; 2 * n];
        coefficients[sky] = 0.3;
        coefficients[n + ground] = 0.2;
        let dc = DaylightCoefficients {
            sensors: vec!["S1".into()],
            mf: 1,
            bins: 2 * n,
            lux_per_cd_m2: coefficients,
            samples_per_sensor: 1,
        };
        let mut lum = vec![1000.0; 2 * n];
        lum[n + ground] = f64::NAN;
        let mut seen = vec![true; 2 * n];
        seen[n + ground] = false;
        let terms = CaptureTerms {
            sun: None,
            sky_with_sun_lux: vec![300.0],
            sky_without_sun_lux: vec![300.0],
            sun_lux_per_dn_lux: vec![0.0],
            sun_dn_lux: 0.0,
            unseen_ground_lux_per_cd_m2: vec![0.2],
            outdoor_horizontal_lux: 1.0,
            unseen_sky_fraction: 0.0,
            saturated_fraction: 0.0,
            bins_with_sun_cd_m2: lum.clone(),
            bins_without_sun_cd_m2: lum,
            bin_seen: seen,
            spectral: None,
        };
        let b0 = 0.2;
        let g = AngularGlazing::new(&dc, normal, vec![1.0]);
        let out = &g.apply(std::slice::from_ref(&terms), b0)[0];
        let iam = |d: DVec3| {
            let cos = -d.y;
            (1.0 - b0 * (1.0 / cos - 1.0)).clamp(0.0, 1.0)
        };
        let c = patches.centre(sky);
        let expect = 0.3 * 1000.0 * iam(c);
        assert!(iam(c) < 0.99);
        assert!((out.sky_without_sun_lux[0] - expect).abs() < 1e-9);
        assert!((out.sky_with_sun_lux[0] - expect).abs() < 1e-9);
        let cg = patches.centre(ground);
        let expect = 0.2 * iam(DVec3::new(cg.x, cg.y, -cg.z));
        assert!((out.unseen_ground_lux_per_cd_m2[0] - expect).abs() < 1e-12);
        // b0 = 0 leaves the terms as they were.
        let same = &g.apply(std::slice::from_ref(&terms), 0.0)[0];
        assert!((same.sky_without_sun_lux[0] - 300.0).abs() < 1e-9);
        assert!((same.unseen_ground_lux_per_cd_m2[0] - 0.2).abs() < 1e-12);
    }
}

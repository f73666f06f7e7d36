//! Effects on the measured sky itself: the lens's relative illumination steeper than the
//! declared polynomial (`vignetting`, here) and the sky beyond a clipped field of view
//! (`sky_outside_fov`, [`super::effect_fov`]). Both rescale the per-bin luminances the map
//! gives ([`CaptureTerms::bins_with_sun_cd_m2`]) and re-apply the daylight coefficients, so a
//! trial parameter costs a few dot products per capture.
//!
//! Vignetting model: the true relative illumination is the declared V(α) times
//! `1 − v (α / 90°)²`, the leading term of the even radial polynomial 1 + a₂ r² + … that
//! models a lens's fall-off (Goldman, "Vignette and exposure calibration and compensation",
//! IEEE TPAMI 32(12), 2010), with the equidistant fisheye's image radius proportional to α.
//! The map under-reads a group at α by that factor; the model divides each bin's luminance
//! by the solid-angle-weighted mean factor of the groups that measured it (linear in v, so
//! the mean of (α/90°)² per bin is computed once), the sun's direct-normal illuminance by
//! the factor at the sun's off-axis angle, and re-fills the unseen sky from the corrected
//! seen sky as [`SkyPatches::aggregate`] fills it.

use super::device_model::{CaptureData, CaptureTerms, ModelState};
use super::effects::{fit_error, pearson_r, residual_points, Candidate, Effect, Sample};
use super::split::FitSet;
use crate::camera::{CameraModel, DeviceConfig};
use crate::engine::DaylightCoefficients;
use crate::hdr::{GeometryCache, MapFlag};
use crate::sky::SkyPatches;
use glam::DVec3;
use std::collections::BTreeMap;

/// `(α / 90°)²`: the variable the extra vignetting is linear in.
fn radial2(off_axis_rad: f64) -> f64 {
    (off_axis_rad / std::f64::consts::FRAC_PI_2).powi(2)
}

/// The extra relative illumination `1 − v (α / 90°)²` at a given `(α / 90°)²`, floored so a
/// trial never divides by zero.
fn factor(v: f64, a: f64) -> f64 {
    (1.0 - v * a).max(0.05)
}

/// A sun beyond the maps' field: per sensor, lux per lux of direct-normal illuminance, and
/// the reference direct-normal illuminance, lux.
pub type HiddenSun = (Vec<f64>, f64);

/// Per capture, where the map's light came from in the camera: what the sky effects need
/// beyond [`CaptureTerms`].
#[derive(Clone, Debug)]
pub struct SkyGeometry {
    /// Per capture, per bin (sky patches, then mirrored ground patches), the
    /// solid-angle-weighted mean of (α/90°)² over the valid groups in the bin (NaN: none).
    pub bin_radial2: Vec<Vec<f64>>,
    /// Per capture, (α/90°)² of the extracted sun (NaN: no sun).
    pub sun_radial2: Vec<f64>,
    /// Per capture, the largest off-axis angle of a valid or over-range group, degrees: the
    /// field of view the map shows.
    pub shown_fov_deg: Vec<f64>,
    /// The largest off-axis angle the declared lens images onto the readout, degrees.
    pub lens_fov_deg: f64,
    /// Per bin, the off-axis angle of the bin's centre (ground: its mirrored direction),
    /// degrees.
    pub bin_off_axis_deg: Vec<f64>,
    /// Per capture, the extracted sun's off-axis angle, degrees (NaN: no sun).
    pub sun_off_axis_deg: Vec<f64>,
    /// Per capture, a sun the declared lens would image but the maps' field does not show:
    /// its lux per lux of direct-normal illuminance per sensor and the pyranometer's
    /// direct-normal illuminance, lux ([`super::effect_fov::hidden_suns`]; empty until set).
    pub hidden_sun: Vec<Option<HiddenSun>>,
}

impl SkyGeometry {
    /// Computes the geometry of every capture under the camera `device`.
    pub fn new(
        patches: &SkyPatches,
        captures: &[CaptureData],
        terms: &[CaptureTerms],
        device: &DeviceConfig,
    ) -> Self {
        let camera = CameraModel::new(device.clone());
        let n = patches.len();
        let mut bin_off_axis_deg: Vec<f64> = (0..n)
            .map(|p| camera.off_axis_rad(patches.centre(p)).to_degrees())
            .collect();
        bin_off_axis_deg.extend((0..n).map(|p| {
            let c = patches.centre(p);
            camera.off_axis_rad(DVec3::new(c.x, c.y, -c.z)).to_degrees()
        }));
        let mut geometries = GeometryCache::default();
        let (mut bin_radial2, mut sun_radial2, mut shown, mut sun_deg) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let mut lens_fov_deg: f64 = 0.0;
        for (c, t) in captures.iter().zip(terms) {
            let geometry = geometries.get(&camera, &c.readout, c.raw_width, c.raw_height);
            let (mut sum, mut omega) = (vec![0.0f64; 2 * n], vec![0.0f64; 2 * n]);
            let mut max_deg: f64 = 0.0;
            for i in 0..c.map.luminance_cd_m2.len().min(geometry.direction.len()) {
                let d = geometry.direction[i];
                let w = geometry.solid_angle_sr[i] as f64;
                if !d.is_finite() || w <= 0.0 {
                    continue;
                }
                let d = d.as_dvec3();
                let alpha = camera.off_axis_rad(d);
                lens_fov_deg = lens_fov_deg.max(alpha.to_degrees());
                if c.map.flags[i] == MapFlag::UnderRange {
                    continue;
                }
                max_deg = max_deg.max(alpha.to_degrees());
                if c.map.flags[i] != MapFlag::Valid {
                    continue;
                }
                let bin = if d.z >= 0.0 {
                    patches.patch_of(d)
                } else {
                    patches.patch_of(DVec3::new(d.x, d.y, -d.z)).map(|p| n + p)
                };
                if let Some(b) = bin {
                    sum[b] += w * radial2(alpha);
                    omega[b] += w;
                }
            }
            bin_radial2.push(
                sum.iter()
                    .zip(&omega)
                    .map(|(s, o)| if *o > 0.0 { s / o } else { f64::NAN })
                    .collect(),
            );
            let sun_alpha = t
                .sun
                .as_ref()
                .map_or(f64::NAN, |s| camera.off_axis_rad(s.direction));
            sun_radial2.push(radial2(sun_alpha));
            sun_deg.push(sun_alpha.to_degrees());
            shown.push(max_deg);
        }
        Self {
            bin_radial2,
            sun_radial2,
            shown_fov_deg: shown,
            lens_fov_deg,
            bin_off_axis_deg,
            sun_off_axis_deg: sun_deg,
            hidden_sun: Vec::new(),
        }
    }

    /// The field of view the maps show: the median over captures of the largest off-axis
    /// angle with valid groups, degrees.
    pub fn median_shown_fov_deg(&self) -> f64 {
        let mut v: Vec<f64> = self
            .shown_fov_deg
            .iter()
            .copied()
            .filter(|x| *x > 0.0)
            .collect();
        if v.is_empty() {
            return f64::NAN;
        }
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    }
}

/// Fills the unseen sky patches of `lum` (the first `patches.len()` entries) from the seen
/// ones exactly as [`SkyPatches::aggregate`] does: within a row, the seen patches weighted
/// by (1 + cos of the angle between centres)⁴; a row with none seen takes the nearest row's
/// mean.
fn refill(patches: &SkyPatches, lum: &mut [f64], seen: &[bool]) {
    patches.fill_unseen(lum, seen);
}

/// The terms of one capture with the sky effects of `state` applied to `raw` (terms without
/// them): seen bins divided by the extra vignetting, the unseen sky re-filled from them and
/// scaled by the unseen-sky factor, the sun's direct-normal illuminance divided by the extra
/// vignetting at the sun, and the daylight coefficients re-applied.
pub fn correct_capture(
    raw: &CaptureTerms,
    dc: &DaylightCoefficients,
    patches: &SkyPatches,
    bin_radial2: &[f64],
    sun_radial2: f64,
    hidden_sun: Option<&HiddenSun>,
    state: &ModelState,
) -> CaptureTerms {
    let (v, k) = (
        state.extra_vignetting,
        state.unseen_sky_factor.unwrap_or(1.0),
    );
    let mut out = raw.clone();
    if v == 0.0 && state.unseen_sky_factor.is_none() {
        return out;
    }
    if let (Some((per_dn, dn)), Some(_), None) = (hidden_sun, state.unseen_sky_factor, &raw.sun) {
        out.sun_lux_per_dn_lux = per_dn.clone();
        out.sun_dn_lux = *dn;
    }
    let n = patches.len();
    let fix = |lum: &[f64]| -> Vec<f64> {
        let mut l: Vec<f64> = lum
            .iter()
            .enumerate()
            .map(|(b, x)| {
                let a = bin_radial2.get(b).copied().unwrap_or(f64::NAN);
                if raw.bin_seen.get(b).copied().unwrap_or(false) && a.is_finite() {
                    x / factor(v, a)
                } else {
                    *x
                }
            })
            .collect();
        if v != 0.0 && l.len() >= n {
            refill(patches, &mut l[..n], &raw.bin_seen[..n]);
        }
        for (p, x) in l.iter_mut().enumerate().take(n) {
            if !raw.bin_seen[p] {
                *x *= k;
            }
        }
        l
    };
    out.bins_with_sun_cd_m2 = fix(&raw.bins_with_sun_cd_m2);
    out.bins_without_sun_cd_m2 = fix(&raw.bins_without_sun_cd_m2);
    if sun_radial2.is_finite() {
        out.sun_dn_lux = raw.sun_dn_lux / factor(v, sun_radial2);
    }
    out.sky_with_sun_lux = dc.apply_seen(&out.bins_with_sun_cd_m2);
    out.sky_without_sun_lux = dc.apply_seen(&out.bins_without_sun_cd_m2);
    out
}

/// [`correct_capture`] for every capture.
pub fn correct_terms(
    raw: &[CaptureTerms],
    dc: &DaylightCoefficients,
    geometry: &SkyGeometry,
    state: &ModelState,
) -> Vec<CaptureTerms> {
    let patches = dc.patches();
    raw.iter()
        .enumerate()
        .map(|(i, t)| {
            correct_capture(
                t,
                dc,
                &patches,
                &geometry.bin_radial2[i],
                geometry.sun_radial2[i],
                geometry.hidden_sun.get(i).and_then(Option::as_ref),
                state,
            )
        })
        .collect()
}

/// Per sensor, the mean off-axis angle (degrees, in the camera) of the light the model
/// brings to the sensor: the bins' and the concentrated sun's contributions weighted by
/// the illuminance each gives. The variable the extra vignetting's residual grows with.
pub fn light_off_axis_deg(
    t: &CaptureTerms,
    dc: &DaylightCoefficients,
    geometry: &SkyGeometry,
    capture: usize,
) -> Vec<f64> {
    (0..t.sky_without_sun_lux.len())
        .map(|s| {
            let (mut num, mut den) = (0.0, 0.0);
            for (b, (c, l)) in dc.row(s).iter().zip(&t.bins_without_sun_cd_m2).enumerate() {
                let a = geometry.bin_off_axis_deg[b];
                if l.is_finite() && t.bin_seen[b] && a.is_finite() {
                    num += c * l * a;
                    den += c * l;
                }
            }
            let sun = t.sun_lux_per_dn_lux[s] * t.sun_dn_lux;
            let a = geometry.sun_off_axis_deg[capture];
            if sun > 0.0 && a.is_finite() {
                num += sun * a;
                den += sun;
            }
            if den > 0.0 {
                num / den
            } else {
                f64::NAN
            }
        })
        .collect()
}

/// Golden-section minimum of `f` on [a, b] after a scan of `steps` + 1 points.
pub fn minimise_1d(f: &dyn Fn(f64) -> f64, a: f64, b: f64, steps: usize) -> (f64, f64) {
    let h = (b - a) / steps as f64;
    let mut best = (a, f(a));
    for i in 1..=steps {
        let x = a + h * i as f64;
        let e = f(x);
        if e < best.1 {
            best = (x, e);
        }
    }
    let (lo, hi) = ((best.0 - h).max(a), (best.0 + h).min(b));
    crate::numerics::golden_section(lo, hi, best, 30, f)
}

/// Largest extra vignetting the fit considers.
pub const MAX_EXTRA_VIGNETTING: f64 = 0.9;

/// Fits the extra vignetting v on the fit set: the fit-set error of the terms corrected for
/// each trial v, minimised over [0, [`MAX_EXTRA_VIGNETTING`]]. `None` if the best v is under
/// 0.01 above the current one. Returns the candidate and its corrected terms.
pub fn fit_vignetting(
    state: &ModelState,
    raw: &[CaptureTerms],
    dc: &DaylightCoefficients,
    geometry: &SkyGeometry,
    fit: &FitSet<Sample>,
) -> Option<(Candidate, Vec<CaptureTerms>)> {
    let error = |v: f64| {
        let st = ModelState {
            extra_vignetting: v,
            ..state.clone()
        };
        let e = fit_error(&st, &correct_terms(raw, dc, geometry, &st), fit);
        if e.is_finite() {
            e
        } else {
            f64::INFINITY
        }
    };
    let (v, _) = minimise_1d(&error, 0.0, MAX_EXTRA_VIGNETTING, 18);
    if v < state.extra_vignetting + 0.01 {
        return None;
    }
    let next = ModelState {
        extra_vignetting: v,
        ..state.clone()
    };
    // Signature: the relative residual grows (negative: under-read) with the off-axis angle
    // of the light reaching the sensor.
    let current = correct_terms(raw, dc, geometry, state);
    let xy = residual_points(state, &current, fit, |capture, t| {
        light_off_axis_deg(t, dc, geometry, capture)
    });
    let r = pearson_r(&xy);
    let mut parameters = BTreeMap::new();
    parameters.insert("extra_vignetting".into(), v);
    let evidence = format!(
        "the relative residual falls as the light reaching the sensors comes from further \
         off the lens's axis (r = {r:.2} over {} readings against its mean off-axis angle): \
         the lens's fall-off is steeper than the declared polynomial, by 1 − {v:.3} (α/90°)²",
        xy.len()
    );
    let terms = correct_terms(raw, dc, geometry, &next);
    Some((
        Candidate {
            effect: Effect::Vignetting,
            state: next,
            parameters,
            evidence,
        },
        terms,
    ))
}

//! Where the map's light came from in the camera, per capture, and the sky effects that act
//! on it: the lens's relative illumination steeper than declared (`vignetting`) and the sky
//! beyond a clipped field of view (`sky_outside_fov`). Both rescale the per-bin luminances the
//! map gives ([`CaptureTerms::bins_with_sun_cd_m2`]) and re-apply the daylight coefficients
//! in one pass ([`correct_terms`]), so a trial parameter costs a few dot products per
//! capture; their parameters are declared here, with that pass.
//!
//! Vignetting: the true relative illumination is the declared V(α) times `1 − v (α / 90°)²`;
//! the map under-reads a group at α by that factor, so each bin's luminance is divided by the
//! solid-angle-weighted mean factor of the groups that measured it (linear in v, so the mean
//! of (α/90°)² per bin is computed once), the sun's direct-normal illuminance by the factor
//! at the sun, and the unseen sky re-filled from the corrected seen sky as
//! [`SkyPatches::aggregate`] fills it. The field of view: the unseen sky patches' filled
//! luminance times a factor k, and a sun beyond the shown field taken from the pyranometer.

use super::prediction::{LoopState, Param};
use super::sample::nearest_in_time;
use super::terms::Terms;
use crate::camera::{CameraModel, DeviceConfig};
use crate::campaign::Campaign;
use crate::engine::DaylightCoefficients;
use crate::hdr::{GeometryCache, MapFlag};
use crate::model::{CaptureData, CaptureTerms, ModelError, Room};
use crate::sky::perez::{PerezConditions, PerezSky};
use crate::sky::SkyPatches;
use chrono::{Datelike, TimeDelta};
use glam::DVec3;

/// Extra vignetting v: the true relative illumination is the declared one times
/// 1 − v (α/90°)² (`vignetting`).
pub const EXTRA_VIGNETTING: Param = Param {
    key: "vignetting.extra_vignetting",
    default: 0.0,
};
/// The factor on the extrapolated luminance of the sky patches the lens did not see; set, it
/// also fills the sun beyond the maps' field from the pyranometer (`sky_outside_fov`).
pub const UNSEEN_SKY_FACTOR: Param = Param {
    key: "sky_outside_fov.unseen_sky_factor",
    default: 1.0,
};

/// `(α / 90°)²`: the variable the extra vignetting is linear in.
fn radial2(off_axis_rad: f64) -> f64 {
    (off_axis_rad / std::f64::consts::FRAC_PI_2).powi(2)
}

/// The extra relative illumination `1 − v (α / 90°)²` at a given `(α / 90°)²`, floored so a
/// trial never divides by zero.
fn factor(v: f64, a: f64) -> f64 {
    (1.0 - v * a).max(0.05)
}

/// A sun beyond the maps' field, taken from the pyranometer.
#[derive(Clone, Debug, PartialEq)]
pub struct HiddenSun {
    /// Per sensor, lux per lux of direct-normal illuminance.
    pub lux_per_dn_lux: Vec<f64>,
    /// The pyranometer's direct-normal illuminance, lux.
    pub dn_lux: f64,
}

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
    /// direct-normal illuminance, lux ([`hidden_suns`]; empty until set).
    pub hidden_sun: Vec<Option<HiddenSun>>,
}

impl SkyGeometry {
    /// No captures yet.
    pub fn empty() -> Self {
        Self {
            bin_radial2: Vec::new(),
            sun_radial2: Vec::new(),
            shown_fov_deg: Vec::new(),
            lens_fov_deg: 0.0,
            bin_off_axis_deg: Vec::new(),
            sun_off_axis_deg: Vec::new(),
            hidden_sun: Vec::new(),
        }
    }

    /// Computes the geometry of every capture under the camera `device`.
    pub fn new(
        patches: &SkyPatches,
        captures: &[CaptureData],
        terms: &[Terms],
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
    raw: &Terms,
    dc: &DaylightCoefficients,
    patches: &SkyPatches,
    bin_radial2: &[f64],
    sun_radial2: f64,
    hidden_sun: Option<&HiddenSun>,
    state: &LoopState,
) -> Terms {
    let unseen_sky_factor = state.value(UNSEEN_SKY_FACTOR);
    let (v, k) = (
        state.get(EXTRA_VIGNETTING),
        unseen_sky_factor.unwrap_or(1.0),
    );
    let mut out = raw.clone();
    if v == 0.0 && unseen_sky_factor.is_none() {
        return out;
    }
    if let (Some(hidden), Some(_), None) = (hidden_sun, unseen_sky_factor, &raw.sun) {
        out.sun_lux_per_dn_lux = hidden.lux_per_dn_lux.clone();
        out.sun_dn_lux = hidden.dn_lux;
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
    raw: &[Terms],
    dc: &DaylightCoefficients,
    geometry: &SkyGeometry,
    state: &LoopState,
) -> Vec<Terms> {
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

/// Per capture, the sun the declared lens would image (onto the readout) but the maps'
/// field does not show (SPA off-axis angle beyond the capture's shown field of view) and the
/// map did not give: per sensor its lux per lux of direct-normal illuminance and the
/// pyranometer's direct-normal illuminance (nearest row within 5 min), lux. `None` where the
/// sun was extracted, is below the horizon, is within the shown field, lies outside the
/// readout, or no pyranometer row gives a beam.
pub fn hidden_suns(
    campaign: &Campaign,
    room: &mut Room,
    captures: &[CaptureData],
    terms: &[Terms],
    device: &DeviceConfig,
    geometry: &SkyGeometry,
) -> Result<Vec<Option<HiddenSun>>, ModelError> {
    let camera = CameraModel::new(device.clone());
    let mut out = Vec::with_capacity(captures.len());
    for (i, c) in captures.iter().enumerate() {
        let shown = geometry.shown_fov_deg.get(i).copied().unwrap_or(f64::NAN);
        let alpha = camera.off_axis_rad(c.spa_sun).to_degrees();
        let on_readout = camera.project(c.spa_sun).is_some_and(|p| {
            let (x0, y0) = (
                f64::from(c.readout.col_start),
                f64::from(c.readout.row_start),
            );
            let skip = f64::from(c.readout.skip.max(1));
            p.x_px >= x0
                && p.y_px >= y0
                && p.x_px < x0 + skip * c.raw_width as f64
                && p.y_px < y0 + skip * c.raw_height as f64
        });
        if terms[i].sun.is_some()
            || c.spa_sun.z <= 0.0
            || !on_readout
            || alpha.partial_cmp(&(shown + 0.5)) != Some(std::cmp::Ordering::Greater)
        {
            out.push(None);
            continue;
        }
        let Some(dn) = reference_direct_normal_lux(campaign, c) else {
            out.push(None);
            continue;
        };
        let k = room.sun_coefficients(c.spa_sun)?;
        out.push(Some(HiddenSun {
            lux_per_dn_lux: k.into_iter().map(|(c, _)| c).collect(),
            dn_lux: dn,
        }));
    }
    Ok(out)
}

/// The pyranometer's direct-normal illuminance at a capture, lux: its DNI (or GHI and DHI)
/// through the Perez 1990 model as gendaylit converts (the loop's Perez baseline).
pub fn reference_direct_normal_lux(campaign: &Campaign, c: &CaptureData) -> Option<f64> {
    let table = campaign.pyranometer.as_ref()?;
    let row = nearest_in_time(&table.rows, TimeDelta::minutes(5), |r| r.time - c.time)?;
    let input = row.perez_input()?;
    let conditions = PerezConditions {
        day_of_year: c.time.ordinal() as u16,
        ..PerezConditions::gendaylit_ang(c.spa_sun)
    };
    let dn = PerezSky::new(input, &conditions)
        .ok()?
        .direct_normal_illuminance_lux();
    (dn.is_finite() && dn > 0.0).then_some(dn)
}

/// The maps must show a field at least this much narrower than the declared lens images,
/// degrees, for the effect to be considered (a group at skip 4 spans some 0.4°).
pub const MIN_CLIPPED_DEG: f64 = 2.0;

//! The model's illuminance per capture, decomposed into terms computed once: daylight
//! coefficients of the room times the measured sky (and seen ground) patches, the sun as a
//! concentrated source, and the unseen ground. What is expensive (sun extraction, daylight and
//! sun coefficients) is done here once per capture and camera orientation; a change of the
//! model's parameters then only rescales or adds terms.

use super::captures::CaptureData;
use super::error::ModelError;
use super::room::Room;
use crate::camera::{CameraModel, DeviceConfig};
use crate::hdr::{GeometryCache, GroupGeometry, LuminanceMap, MapFlag};
use crate::sky::SkyPatches;
use crate::sun::{extract_sun, remove_sun, ExtractedSun, NoSun, SunSearch};
use glam::DVec3;

/// Minimum fraction of a patch's solid angle the lens must see for the patch to count as
/// measured.
pub const MIN_COVERAGE: f64 = 0.3;

/// How far from SPA's sun the model looks for the disk, degrees: the camera's orientation as
/// declared may be off by this much before the orientation effect refits it. The fabric's
/// accumulators are given a window of the same reach (`skyluxd`).
pub const SUN_MAX_OFFSET_DEG: f64 = 12.0;

/// Why a capture has no extracted sun.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SunMissing {
    #[error("the sun is below the horizon (SPA altitude {altitude_deg:.2} deg)")]
    BelowHorizon { altitude_deg: f64 },
    #[error("no sun extracted: {0}")]
    NotFound(#[from] NoSun),
    #[error("a sun was found but its direct-normal illuminance is not finite")]
    NotMeasurable,
}

impl SunMissing {
    /// The reason as a short tag, as `sun.csv` writes it after `no_sun:`.
    pub fn tag(&self) -> &'static str {
        match self {
            SunMissing::BelowHorizon { .. } => "below_horizon",
            SunMissing::NotFound(no_sun) => no_sun.tag(),
            SunMissing::NotMeasurable => "not_measurable",
        }
    }
}

/// Per capture, what the model derives from the map under one camera orientation.
#[derive(Clone, Debug)]
pub struct CaptureTerms {
    /// The sun, if the map shows one.
    pub sun: Option<ExtractedSun>,
    /// Why `sun` is `None` (always set then; `None` when a sun was extracted): a record
    /// never says "no sun" without a reason.
    pub sun_missing: Option<SunMissing>,
    /// Illuminance per sensor from the measured sky and the seen ground, with the sun left
    /// inside the map's patches (spread over its patch: the undersampled sun).
    pub sky_with_sun_lux: Vec<f64>,
    /// The same with the sun disk removed and filled from the circumsolar sky.
    pub sky_without_sun_lux: Vec<f64>,
    /// Per sensor, lux per lux of direct-normal illuminance, for the extracted sun's
    /// direction (0 without a sun).
    pub sun_lux_per_dn_lux: Vec<f64>,
    /// Direct-normal illuminance of the extracted sun, lux (0 without a sun).
    pub sun_dn_lux: f64,
    /// Per sensor, lux per cd/m² of the ground the lens does not see.
    pub unseen_ground_lux_per_cd_m2: Vec<f64>,
    /// Outdoor horizontal illuminance the map implies, lux.
    pub outdoor_horizontal_lux: f64,
    /// Fraction of the sky's daylight-coefficient weight (sensor-averaged) that falls on
    /// patches the lens did not see.
    pub unseen_sky_fraction: f64,
    /// Fraction of valid groups over-range.
    pub saturated_fraction: f64,
    /// Per bin (sky patches, then mirrored ground patches: the daylight coefficients'
    /// order), the map's luminance with the sun left in, cd/m²: unseen sky patches filled as
    /// [`SkyPatches::aggregate`] fills them, unseen ground NaN. What effects acting on the
    /// measured sky itself (vignetting, the field of view, the glazing's angular
    /// transmittance) rescale before the daylight coefficients apply.
    pub bins_with_sun_cd_m2: Vec<f64>,
    /// The same with the sun disk removed and filled from the circumsolar sky.
    pub bins_without_sun_cd_m2: Vec<f64>,
    /// Per bin, whether the lens saw at least `MIN_COVERAGE` of it.
    pub bin_seen: Vec<bool>,
}

/// Sky and ground bin luminances of a map (sky patches then mirrored ground patches, as the
/// daylight coefficients order them); unseen ground bins are NaN. Returns also the outdoor
/// horizontal illuminance of the sky part.
fn bins(
    patches: &SkyPatches,
    map: &LuminanceMap,
    geometry: &GroupGeometry,
) -> (Vec<f64>, Vec<bool>, f64) {
    let n = patches.len();
    let sky = patches.aggregate(
        map,
        &geometry.direction,
        &geometry.solid_angle_sr,
        MIN_COVERAGE,
    );
    let (mut sum, mut omega) = (vec![0.0f64; n], vec![0.0f64; n]);
    for i in 0..map.luminance_cd_m2.len() {
        let d = geometry.direction[i];
        if map.flags[i] != MapFlag::Valid || !d.is_finite() || d.z >= 0.0 {
            continue;
        }
        let d = d.as_dvec3();
        if let Some(p) = patches.patch_of(DVec3::new(d.x, d.y, -d.z)) {
            let w = geometry.solid_angle_sr[i] as f64;
            sum[p] += w * map.luminance_cd_m2[i] as f64;
            omega[p] += w;
        }
    }
    let mut lum = sky.luminance_cd_m2.clone();
    let mut seen = vec![true; 2 * n];
    for &p in &sky.filled {
        seen[p] = false;
    }
    for p in 0..n {
        if omega[p] >= MIN_COVERAGE * patches.solid_angle_sr(p) {
            lum.push(sum[p] / omega[p]);
        } else {
            lum.push(f64::NAN);
            seen[n + p] = false;
        }
    }
    // Horizontal illuminance: Σ L cos θ ω over the measured groups of each patch (the
    // patch's mean of L cos θ times its solid angle), the patch centre's cosine only where a
    // patch was filled rather than seen. The centre's cosine alone is gendaylit's 145-point
    // quadrature, whose error (2-3 % of the diffuse light, most with a low sun) a sky
    // normalised by that same sum would hide.
    let (mut sum_cos, mut omega_sky) = (vec![0.0f64; n], vec![0.0f64; n]);
    for i in 0..map.luminance_cd_m2.len() {
        let d = geometry.direction[i];
        let w = geometry.solid_angle_sr[i] as f64;
        if map.flags[i] != MapFlag::Valid || !d.is_finite() || w <= 0.0 {
            continue;
        }
        let d = d.as_dvec3();
        if let Some(p) = patches.patch_of(d) {
            sum_cos[p] += w * map.luminance_cd_m2[i] as f64 * d.z.max(0.0);
            omega_sky[p] += w;
        }
    }
    let horizontal: f64 = (0..n)
        .map(|p| {
            let l = sky.luminance_cd_m2[p];
            if !l.is_finite() {
                0.0
            } else if seen[p] && omega_sky[p] > 0.0 {
                sum_cos[p] / omega_sky[p] * patches.solid_angle_sr(p)
            } else {
                l * patches.centre(p).z * patches.solid_angle_sr(p)
            }
        })
        .sum();
    (lum, seen, horizontal)
}

/// Computes the terms of every capture for the camera `device` (its orientation is what the
/// orientation effect changes).
pub fn capture_terms(
    room: &mut Room,
    captures: &[CaptureData],
    device: &DeviceConfig,
    progress: &dyn Fn(usize, usize),
) -> Result<Vec<CaptureTerms>, ModelError> {
    let camera = CameraModel::new(device.clone());
    let patches = room.dc.patches();
    let mut out = Vec::with_capacity(captures.len());
    // Captures of one campaign share a readout: compute the geometry once per readout.
    let mut geometries = GeometryCache::default();
    for (k, c) in captures.iter().enumerate() {
        progress(k, captures.len());
        let geometry = geometries.get(&camera, &c.readout, c.raw_width, c.raw_height);
        out.push(terms_of(room, &patches, c, geometry)?);
    }
    Ok(out)
}

/// One capture's terms: the sun extracted from the map, the bins with and without it, and
/// the daylight and sun coefficients applied.
fn terms_of(
    room: &mut Room,
    patches: &SkyPatches,
    c: &CaptureData,
    geometry: &GroupGeometry,
) -> Result<CaptureTerms, ModelError> {
    let sensors = room.sensors.len();
    let search = SunSearch {
        predicted_direction: Some(c.spa_sun),
        max_offset_deg: SUN_MAX_OFFSET_DEG,
        ..Default::default()
    };
    let found = if c.spa_sun.z > 0.0 {
        // A sun measured elsewhere (the fabric's accumulators) spares the scan of the map.
        let found = match &c.sun {
            Some(s) => Ok(s.clone()),
            None => extract_sun(&c.map, geometry, &search),
        };
        match found {
            Ok(s) if s.direct_normal_illuminance_lux.is_finite() => Ok(s),
            Ok(_) => Err(SunMissing::NotMeasurable),
            Err(e) => Err(SunMissing::NotFound(e)),
        }
    } else {
        Err(SunMissing::BelowHorizon {
            altitude_deg: c.spa_sun.z.clamp(-1.0, 1.0).asin().to_degrees(),
        })
    };
    let (sun, sun_missing) = match found {
        Ok(s) => (Some(s), None),
        Err(e) => (None, Some(e)),
    };
    // A disk the readout cannot measure (it skips pixels between its samples) is kept out of
    // the sky: its groups read as if the disk filled them, and spread over their patches
    // they would add light no sky has (the old daemon example's 200-450 klx at noon).
    let masked;
    let map = match &sun_missing {
        Some(SunMissing::NotFound(NoSun::Undersampled { groups, .. })) => {
            masked = without_groups(&c.map, groups);
            &masked
        }
        _ => &c.map,
    };
    let (with_sun, seen, horizontal_map) = bins(patches, map, geometry);
    // With a sun extracted, the outdoor horizontal illuminance is the sky without the
    // disk plus the disk's direct beam (the disk itself may be over-range in the map).
    let (without_sun, horizontal) = match &sun {
        Some(s) => {
            let (b, _, h) = bins(patches, &remove_sun(&c.map, s), geometry);
            (
                b,
                h + s.direct_normal_illuminance_lux * s.direction.z.max(0.0),
            )
        }
        None => (with_sun.clone(), horizontal_map),
    };
    let (unseen_ground, unseen_sky_fraction) = unseen_weights(room, &seen);
    let (sun_lux_per_dn_lux, sun_dn_lux) = match &sun {
        Some(s) => {
            let k = room.sun_coefficients(s.direction)?;
            (
                k.into_iter().map(|(c, _)| c).collect(),
                s.direct_normal_illuminance_lux,
            )
        }
        None => (vec![0.0; sensors], 0.0),
    };
    Ok(CaptureTerms {
        sun_missing,
        sky_with_sun_lux: room.dc.apply_seen(&with_sun),
        sky_without_sun_lux: room.dc.apply_seen(&without_sun),
        sun_lux_per_dn_lux,
        sun_dn_lux,
        unseen_ground_lux_per_cd_m2: unseen_ground,
        outdoor_horizontal_lux: horizontal,
        unseen_sky_fraction,
        saturated_fraction: saturated_fraction(&c.map),
        sun,
        bins_with_sun_cd_m2: with_sun,
        bins_without_sun_cd_m2: without_sun,
        bin_seen: seen,
    })
}

/// `map` with `groups` and their 8 neighbours marked unusable (under-range), so the sky patches
/// are filled from the rest of their groups.
fn without_groups(map: &LuminanceMap, groups: &[usize]) -> LuminanceMap {
    let mut out = map.clone();
    let (w, h) = (map.width as i64, map.height as i64);
    for &i in groups {
        let (x, y) = ((i as i64) % w.max(1), (i as i64) / w.max(1));
        for dy in -1..=1 {
            for dx in -1..=1 {
                let (nx, ny) = (x + dx, y + dy);
                if nx >= 0 && ny >= 0 && nx < w && ny < h {
                    out.flags[(ny * w + nx) as usize] = MapFlag::UnderRange;
                }
            }
        }
    }
    out
}

/// Per sensor, the daylight coefficients of the ground bins the lens did not see (lux per
/// cd/m²), and the fraction of the sky's coefficient weight (summed over sensors) on sky
/// patches it did not see.
fn unseen_weights(room: &Room, seen: &[bool]) -> (Vec<f64>, f64) {
    let n = seen.len() / 2;
    let sensors = room.sensors.len();
    let unseen_ground: Vec<f64> = (0..sensors)
        .map(|s| {
            (0..n)
                .filter(|&p| !seen[n + p])
                .map(|p| room.dc.row(s)[n + p])
                .sum()
        })
        .collect();
    let (sky_weight, unseen_weight) = (0..sensors).fold((0.0, 0.0), |(a, b), s| {
        let row = room.dc.row(s);
        (
            a + row[..n].iter().sum::<f64>(),
            b + (0..n).filter(|&p| !seen[p]).map(|p| row[p]).sum::<f64>(),
        )
    });
    let fraction = if sky_weight > 0.0 {
        unseen_weight / sky_weight
    } else {
        0.0
    };
    (unseen_ground, fraction)
}

/// Fraction of the map's valid (not under-range) groups that are over-range.
fn saturated_fraction(map: &LuminanceMap) -> f64 {
    let valid = map
        .flags
        .iter()
        .filter(|f| **f != MapFlag::UnderRange)
        .count();
    let over = map
        .flags
        .iter()
        .filter(|f| **f == MapFlag::OverRange)
        .count();
    if valid > 0 {
        over as f64 / valid as f64
    } else {
        0.0
    }
}

//! The spectral-mismatch effect: the device's luminance `L = cg (w · RGB) / (t g V)` is exact
//! only for the spectrum its weights and `cg` were calibrated under. Under a sky of another
//! colour (a deep blue clear sky, a redder sun) each channel responds differently, and the
//! measured luminance is off by a factor that depends on the spectrum: the spectral mismatch
//! that a photometer's f1' summarises (CIE S 023 / ISO/CIE 19476).
//!
//! Model: the measured luminance of a sky patch (and of the sun) is the true one times
//! `1 + m (c − c_ref)`, with `c` the colour index the device measures from its own raw frames
//! (blue / red, [`super::sky_colour`]) for that patch (the sun's own index for the sun) and
//! `c_ref` = [`REFERENCE_INDEX`], the index of the calibration source (1 for a device whose
//! channels are balanced under it). For CIE daylights of 4,000-25,000 K the mismatch of a
//! Bayer camera with fixed weights is close to linear in blue / red, so one slope `m` covers
//! the blue sky, the overcast sky and the sun. The model divides each measured patch by its
//! factor before the daylight coefficients apply (the ground, lit by the global daylight, is
//! left as measured). `m` is fitted on the fit set by a scan and a golden-section search of
//! the fit-set error, the accepted linear effects refitted at each trial.
//!
//! Signature: the relative residual correlates with the sky's colour index across captures
//! (clear against overcast skies).

use super::device_model::{CaptureTerms, ModelState, Room};
use super::effects::{
    fit_error, fit_linear, pearson_r, residual_points, Candidate, Effect, FreeLinear, Sample,
};
use super::sky_colour::CaptureColour;
use super::split::FitSet;
use std::collections::BTreeMap;

/// The colour index of the calibration source: the simulator's frames, and a device balanced
/// under its calibration source, give 1 for it.
pub const REFERENCE_INDEX: f64 = 1.0;

/// Least spread of the fit set's sky colour indices (max − min) for the slope to be
/// determined: below it every capture has the same colour and the factor is a common scale
/// (the glazing transmittance's signature).
const MIN_INDEX_SPREAD: f64 = 0.05;

/// Slopes scanned before the golden-section search (coarse grid, per unit of index).
const SLOPE_SCAN: (f64, f64, f64) = (-0.6, 0.6, 0.05);

/// Per capture, what the correction needs.
#[derive(Clone, Debug, PartialEq)]
pub struct SpectralTerms {
    pub colour: CaptureColour,
    /// Per sensor, per sky patch, lux from the patch's measured luminance with the sun disk
    /// removed (daylight coefficient × luminance; 0 where the bin is NaN).
    pub sky_lux_per_patch: Vec<Vec<f64>>,
}

impl SpectralTerms {
    /// The terms of one capture from its colour and the room's daylight coefficients.
    pub fn new(room: &Room, t: &CaptureTerms, colour: CaptureColour) -> Self {
        let n = room.dc.patches().len();
        let sky_lux_per_patch = (0..room.sensors.len())
            .map(|s| {
                room.dc
                    .row(s)
                    .iter()
                    .zip(&t.bins_without_sun_cd_m2)
                    .take(n)
                    .map(|(c, l)| if l.is_finite() { c * l } else { 0.0 })
                    .collect()
            })
            .collect();
        Self {
            colour,
            sky_lux_per_patch,
        }
    }
}

/// The measured-over-true luminance factor at colour index `c` for slope `m` (kept above 0.2
/// so a wild trial slope cannot divide by zero).
pub fn factor(slope: f64, c: f64) -> f64 {
    (1.0 + slope * (c - REFERENCE_INDEX)).max(0.2)
}

/// Sensor `s`'s room light `room` (the model's sky, seen ground and sun, lux) with the
/// measured sky patches and the sun divided by their spectral-mismatch factors under
/// `state`. Unchanged without the effect or without a colour for the capture.
pub fn corrected_room(state: &ModelState, t: &CaptureTerms, s: usize, room: f64) -> f64 {
    let m = state.spectral_slope;
    if m == 0.0 {
        return room;
    }
    let Some(sp) = &t.spectral else {
        return room;
    };
    let c_sky = sp.colour.sky_index;
    if !c_sky.is_finite() {
        return room;
    }
    let Some(per_patch) = sp.sky_lux_per_patch.get(s) else {
        return room;
    };
    let (mut measured, mut corrected) = (0.0, 0.0);
    for (p, e) in per_patch.iter().enumerate() {
        let c = sp
            .colour
            .patch_index
            .get(p)
            .copied()
            .filter(|c| c.is_finite())
            .unwrap_or(c_sky);
        measured += e;
        corrected += e / factor(m, c);
    }
    let sun = if state.concentrated_sun {
        t.sun_lux_per_dn_lux[s] * t.sun_dn_lux
    } else {
        t.sky_with_sun_lux[s] - t.sky_without_sun_lux[s]
    };
    let c_sun = if sp.colour.sun_index.is_finite() {
        sp.colour.sun_index
    } else {
        c_sky
    };
    room - measured - sun + corrected + sun / factor(m, c_sun)
}

/// Fits the slope `m` on the fit set from `state`, the linear effects already `accepted`
/// refitted at each trial. `None` if the fit set's skies do not differ in colour (no spread
/// of the index, as on a spectrally grey world) or the best slope is the current one.
pub fn fit_spectral(
    state: &ModelState,
    accepted: &[Effect],
    terms: &[CaptureTerms],
    fit: &FitSet<Sample>,
) -> Option<Candidate> {
    let indices: Vec<f64> = fit
        .samples()
        .iter()
        .filter_map(|s| terms[s.capture].spectral.as_ref())
        .map(|sp| sp.colour.sky_index)
        .filter(|c| c.is_finite())
        .collect();
    let (lo, hi) = indices
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| {
            (a.min(*c), b.max(*c))
        });
    if indices.len() < 3 || hi - lo < MIN_INDEX_SPREAD {
        return None;
    }
    let free = FreeLinear::of(accepted);
    let linear = free.glazing || free.ground || free.leak;
    let at = |m: f64| -> (f64, ModelState) {
        let mut st = ModelState {
            spectral_slope: m,
            ..state.clone()
        };
        if linear {
            if let Some(next) = fit_linear(&st, free, terms, fit) {
                st = next;
            }
        }
        let e = fit_error(&st, terms, fit);
        (if e.is_finite() { e } else { f64::INFINITY }, st)
    };
    let (from, to, step) = SLOPE_SCAN;
    let grid: Vec<f64> = (0..=((to - from) / step).round() as usize)
        .map(|k| from + step * k as f64)
        .collect();
    let errors: Vec<f64> = grid.iter().map(|m| at(*m).0).collect();
    let i = (0..grid.len()).min_by(|&a, &b| errors[a].total_cmp(&errors[b]))?;
    let (x, e) = crate::numerics::golden_section(
        grid[i.saturating_sub(1)],
        grid[(i + 1).min(grid.len() - 1)],
        (grid[i], errors[i]),
        24,
        |m| at(m).0,
    );
    let best = (e, x);
    if !best.0.is_finite() || (best.1 - state.spectral_slope).abs() < 0.005 {
        return None;
    }
    let (_, next) = at(best.1);
    // Signature: the relative residual under `state` against the capture's sky colour index.
    // The sky colour index is per capture (NaN without one: left out).
    let xy = residual_points(state, terms, fit, |_, t| {
        let c = t
            .spectral
            .as_ref()
            .map_or(f64::NAN, |sp| sp.colour.sky_index);
        vec![c; t.sky_with_sun_lux.len()]
    });
    let r = pearson_r(&xy);
    let mut parameters = BTreeMap::new();
    parameters.insert("slope_per_index".into(), best.1);
    parameters.insert("reference_index".into(), REFERENCE_INDEX);
    let evidence = format!(
        "the relative residual follows the sky's colour index (blue / red from the raw frames, \
         {lo:.2} to {hi:.2} over the fit captures; r = {r:.2} over {} readings): the camera's \
         luminance depends on the sky's spectrum; each measured patch and the sun divided by \
         1 {:+.3} (c − {REFERENCE_INDEX})",
        xy.len(),
        best.1
    );
    Some(Candidate {
        effect: Effect::SpectralMismatch,
        state: next,
        parameters,
        evidence,
    })
}

/// Computes the colour of every capture (from its raw frames, under the declared camera, the
/// sun's groups from the terms) and attaches the spectral terms to `terms`.
pub fn sky_colours(
    campaign: &crate::campaign::Campaign,
    device: &crate::camera::DeviceConfig,
    captures: &[super::device_model::CaptureData],
    room: &Room,
    terms: &[CaptureTerms],
) -> Result<Vec<CaptureColour>, super::device_model::ModelError> {
    let camera = crate::camera::CameraModel::new(device.clone());
    let patches = room.dc.patches();
    let mut geometries = crate::hdr::GeometryCache::default();
    let mut out = Vec::with_capacity(captures.len());
    for ((c, t), info) in captures.iter().zip(terms).zip(&campaign.captures) {
        let g = geometries.get(&camera, &c.readout, c.raw_width, c.raw_height);
        let sun_groups: &[usize] = t.sun.as_ref().map_or(&[], |s| &s.groups);
        out.push(super::sky_colour::capture_colour(
            &info.dir, device, g, &patches, sun_groups,
        )?);
    }
    Ok(out)
}

/// Attaches the spectral terms of `colours` to `terms` (after every recomputation of the
/// terms: the colours come from the raw frames and do not change with the model).
pub fn attach(room: &Room, terms: &mut [CaptureTerms], colours: &[CaptureColour]) {
    for (t, c) in terms.iter_mut().zip(colours) {
        t.spectral = Some(SpectralTerms::new(room, t, c.clone()));
    }
}

//! The loop's terms per capture: the device model's terms ([`CaptureTerms`]) and what the
//! loop measures beside them, the sky's colour from the raw frames.

use super::sky_colour::CaptureColour;
use crate::model::{CaptureData, CaptureTerms, ModelError, Room};
use std::ops::{Deref, DerefMut};

/// One capture's terms as the loop uses them: the model's, and the sky's colour and per-patch
/// sky light (`None` until [`attach`]ed) that the spectral-mismatch effect corrects.
#[derive(Clone, Debug)]
pub struct Terms {
    pub model: CaptureTerms,
    pub spectral: Option<SpectralTerms>,
}

impl Terms {
    /// The model's terms without a colour.
    pub fn new(model: CaptureTerms) -> Self {
        Self {
            model,
            spectral: None,
        }
    }

    /// Every capture's terms without a colour.
    pub fn all(model: Vec<CaptureTerms>) -> Vec<Self> {
        model.into_iter().map(Self::new).collect()
    }
}

impl Deref for Terms {
    type Target = CaptureTerms;
    fn deref(&self) -> &CaptureTerms {
        &self.model
    }
}

impl DerefMut for Terms {
    fn deref_mut(&mut self) -> &mut CaptureTerms {
        &mut self.model
    }
}

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

/// Where the campaign has a pyranometer, the outdoor horizontal illuminance it implies
/// replaces the map's own estimate (which extrapolates the sky the lens does not see).
pub fn use_reference_outdoor(terms: &mut [Terms], outdoor: &[Option<f64>]) {
    for (t, o) in terms.iter_mut().zip(outdoor) {
        if let Some(o) = o {
            t.outdoor_horizontal_lux = *o;
        }
    }
}

/// Computes the colour of every capture (from its raw frames, under the declared camera, the
/// sun's groups from the terms) and attaches the spectral terms to `terms`.
pub fn sky_colours(
    campaign: &crate::campaign::Campaign,
    device: &crate::camera::DeviceConfig,
    captures: &[CaptureData],
    room: &Room,
    terms: &[Terms],
) -> Result<Vec<CaptureColour>, ModelError> {
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
pub fn attach(room: &Room, terms: &mut [Terms], colours: &[CaptureColour]) {
    for (t, c) in terms.iter_mut().zip(colours) {
        t.spectral = Some(SpectralTerms::new(room, t, c.clone()));
    }
}

//! Per-channel spectral response: what each Bayer channel gives for a scene whose spectrum
//! differs from the one the device was calibrated under.
//!
//! The device turns a group into luminance with fixed weights, `L = cg (w · RGB) / (t g V)`
//! (`device.toml` `[response]`). That is exact only for the calibration spectrum. Under
//! another spectrum channel `c` gives `rel_c` times its calibrated signal, with
//!
//! ```text
//! rel_c = [∫ S s_c dλ / ∫ S V dλ] / [∫ S_cal s_c dλ / ∫ S_cal V dλ]
//! ```
//!
//! (`s_c` the channel's spectral sensitivity, `V` the CIE photopic curve), so the device reads
//! `L Σ w_c rel_c / Σ w_c`: the spectral mismatch a photometer's f1' summarises (CIE S 023).
//! Sensitivities, V(λ) and the daylight basis come from `shared/data/spectral` (see its README
//! for provenance); the MT9P031's own curves are not in it, so a measured Bayer CMOS camera
//! stands in for them, and tests say so. The curves, their CSV reader, the integration and
//! CIE daylight are `skylux_hps::photometry::spectral` (shared with the calibration), re-exported
//! here; this module keeps what only the simulator needs.

use skylux_hps::campaign::{BayerPattern, Channel};
// The generic spectral machinery lives in the product library (`skylux_hps::photometry`),
// one source of truth for the calibration and the simulator; it is re-exported here.
pub use skylux_hps::photometry::spectral::{
    cie_daylight, overlap, read_columns, Curve, SpectralError,
};
use skylux_hps::photometry::spectral::{
    load_daylight_basis, load_photopic, load_rgb_sensitivities,
};
use std::path::Path;

/// The curves the response needs.
#[derive(Clone, Debug)]
pub struct SpectralData {
    /// R, G, B sensitivities.
    pub channels: [Curve; 3],
    pub photopic: Curve,
    pub daylight_basis: [Curve; 3],
}

impl SpectralData {
    /// Reads `shared/data/spectral` with the Nikon D5100 sensitivities (NPL) as the stand-in
    /// for the MT9P031's.
    pub fn load(data_dir: &Path) -> Result<Self, SpectralError> {
        let channels = load_rgb_sensitivities(
            &data_dir
                .join("spectral")
                .join("camera_sensitivity_nikon_5100_npl.csv"),
        )?;
        Ok(Self {
            channels,
            photopic: load_photopic(data_dir)?,
            daylight_basis: load_daylight_basis(data_dir)?,
        })
    }
}

/// Each channel's signal relative to the calibration spectrum, per unit luminance.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct ChannelResponse {
    /// R, G, B.
    pub relative: [f64; 3],
}

impl ChannelResponse {
    /// A spectrally grey scene, or the calibration spectrum itself: every channel exact.
    pub const GREY: Self = Self { relative: [1.0; 3] };

    /// The response to `scene` for a device calibrated under `calibration`.
    pub fn of(data: &SpectralData, scene: &Curve, calibration: &Curve) -> Self {
        let per_lux = |s: &Curve, c: &Curve| overlap(s, c) / overlap(s, &data.photopic);
        let relative = std::array::from_fn(|i| {
            per_lux(scene, &data.channels[i]) / per_lux(calibration, &data.channels[i])
        });
        Self { relative }
    }

    /// The channel gain of a sample of `channel`.
    pub fn gain(&self, channel: Channel) -> f64 {
        match channel {
            Channel::Red => self.relative[0],
            Channel::Green => self.relative[1],
            Channel::Blue => self.relative[2],
        }
    }

    /// Relative luminance error of the device's fixed weights under this response:
    /// `Σ w_c rel_c / Σ w_c - 1` (weights R, G, B; G counts once for the mean of G1 and G2).
    pub fn luminance_error(&self, weights: [f64; 3]) -> f64 {
        let sum: f64 = weights.iter().sum();
        weights
            .iter()
            .zip(&self.relative)
            .map(|(w, r)| w * r)
            .sum::<f64>()
            / sum
            - 1.0
    }

    /// Applies the response to a frame of per-group mean signals (black subtracted), sample by
    /// sample, for a raw frame whose first 2x2 block has `pattern`.
    pub fn sample_gain(&self, pattern: BayerPattern, x: usize, y: usize) -> f64 {
        self.gain(pattern.channel(x & 1, y & 1))
    }
}

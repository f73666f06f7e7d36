//! The merge: `L = cg (w · RGB) / (t gain V(α))` per exposure, combined with noise-optimal
//! (inverse-variance) weights.
//!
//! Weights are computed from the signal *predicted* by a pilot estimate, not from the measured
//! signal: weights built from the measured value correlate with its noise and bias the mean.
//! The pilot is the ratio estimator Σ S_k / Σ t_k g_k over the valid exposures, which is
//! already optimal when shot noise dominates. A group with no valid exposure is flagged over-
//! or under-range and gets no value (NaN), never an invented one.

use super::GroupGeometry;
use crate::camera::DeviceConfig;
use crate::campaign::{BayerPattern, RawFrame};
use rayon::prelude::*;

/// Samples of a frame, in digital numbers. Raw 12-bit frames implement it; so can unquantised
/// frames of a simulator, to test the merge's arithmetic apart from quantisation.
pub trait Samples: Sync {
    /// One sample's storage (u16 for raw frames).
    type Sample: Copy + Into<f64>;
    fn width(&self) -> usize;
    fn height(&self) -> usize;
    /// Row `y` of samples, DN.
    fn row(&self, y: usize) -> &[Self::Sample];
    /// The sample at column `x`, row `y`, DN.
    fn sample_dn(&self, x: usize, y: usize) -> f64 {
        self.row(y)[x].into()
    }
}

impl Samples for RawFrame {
    type Sample = u16;
    fn width(&self) -> usize {
        self.width
    }
    fn height(&self) -> usize {
        self.height
    }
    #[inline]
    fn row(&self, y: usize) -> &[u16] {
        &self.samples_dn[y * self.width..(y + 1) * self.width]
    }
}

/// One exposure of an HDR set.
#[derive(Copy, Clone, Debug)]
pub struct Exposure<'a, F: Samples = RawFrame> {
    pub frame: &'a F,
    /// Integration time, seconds.
    pub exposure_s: f64,
    /// Analog gain.
    pub gain: f64,
}

/// Per-group status of a luminance map (the `flags` channel of the EXR).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum MapFlag {
    Valid = 0,
    /// No exposure below valid_max: too bright for the shortest exposure.
    OverRange = 1,
    /// No exposure above valid_min: too dark for the longest exposure.
    UnderRange = 2,
}

/// A luminance map, one value per 2x2 Bayer group, in the raw frames' orientation.
#[derive(Clone, Debug)]
pub struct LuminanceMap {
    pub width: usize,
    pub height: usize,
    /// cd/m²; NaN where the flag is not `Valid`.
    pub luminance_cd_m2: Vec<f32>,
    pub flags: Vec<MapFlag>,
    /// Predicted standard deviation of the luminance relative to it (noise model), NaN where
    /// not valid.
    pub relative_sigma: Vec<f32>,
}

/// Why an HDR set could not be merged.
#[derive(Debug, thiserror::Error)]
pub enum HdrError {
    #[error("no exposures to merge")]
    Empty,
    #[error("exposure {index}: frame is {width}x{height} samples, the set's geometry needs {expected_width}x{expected_height}")]
    FrameSize {
        index: usize,
        width: usize,
        height: usize,
        expected_width: usize,
        expected_height: usize,
    },
    #[error("exposure {index}: {field} = {value} must be a positive number")]
    BadExposure {
        index: usize,
        field: &'static str,
        value: f64,
    },
}

/// Merges raw exposures into a luminance map.
pub fn merge<F: Samples>(
    exposures: &[Exposure<F>],
    device: &DeviceConfig,
    pattern: BayerPattern,
    geometry: &GroupGeometry,
) -> Result<LuminanceMap, HdrError> {
    if exposures.is_empty() {
        return Err(HdrError::Empty);
    }
    for (index, e) in exposures.iter().enumerate() {
        if e.frame.width() != 2 * geometry.width || e.frame.height() != 2 * geometry.height {
            return Err(HdrError::FrameSize {
                index,
                width: e.frame.width(),
                height: e.frame.height(),
                expected_width: 2 * geometry.width,
                expected_height: 2 * geometry.height,
            });
        }
        if !(e.exposure_s.is_finite() && e.exposure_s > 0.0) {
            return Err(HdrError::BadExposure {
                index,
                field: "exposure_s",
                value: e.exposure_s,
            });
        }
        if !(e.gain.is_finite() && e.gain > 0.0) {
            return Err(HdrError::BadExposure {
                index,
                field: "gain",
                value: e.gain,
            });
        }
    }
    let merger = Merger::new(exposures, device, pattern);
    let width = geometry.width;
    let rows: Vec<(Vec<f32>, Vec<MapFlag>, Vec<f32>)> = (0..geometry.height)
        .into_par_iter()
        .map(|gy| {
            let mut l = Vec::with_capacity(width);
            let mut f = Vec::with_capacity(width);
            let mut s = Vec::with_capacity(width);
            // The two raw rows of this group row, per exposure: fetched once per row.
            let rows: Vec<[&[F::Sample]; 2]> = exposures
                .iter()
                .map(|e| [e.frame.row(2 * gy), e.frame.row(2 * gy + 1)])
                .collect();
            for gx in 0..width {
                let inv_v = geometry.inverse_vignetting[gy * width + gx] as f64;
                let (lum, flag, sigma) = merger.group(&rows, gx, inv_v);
                l.push(lum);
                f.push(flag);
                s.push(sigma);
            }
            (l, f, s)
        })
        .collect();
    let mut map = LuminanceMap {
        width,
        height: geometry.height,
        luminance_cd_m2: Vec::with_capacity(width * geometry.height),
        flags: Vec::with_capacity(width * geometry.height),
        relative_sigma: Vec::with_capacity(width * geometry.height),
    };
    for (l, f, s) in rows {
        map.luminance_cd_m2.extend(l);
        map.flags.extend(f);
        map.relative_sigma.extend(s);
    }
    Ok(map)
}

/// Everything per-set that the per-group merge needs, precomputed.
struct Merger<'a, F: Samples> {
    exposures: &'a [Exposure<'a, F>],
    /// t g per exposure.
    tg: Vec<f64>,
    /// Index of the exposure with the smallest t g.
    shortest: usize,
    /// (dx, dy) and weight of the R, G1, G2, B samples: w_r, w_g/2, w_g/2, w_b.
    taps: [((usize, usize), f64); 4],
    /// Σ of the tap weights squared.
    q: f64,
    /// Σ of the tap weights (w_r + w_g + w_b): a grey sample is S / this.
    weight_sum: f64,
    black: f64,
    valid_min: f64,
    valid_max: f64,
    cg: f64,
    conversion: f64,
    /// Read noise plus quantisation (1/12 DN²), DN² per sample.
    floor_var: f64,
}

impl<'a, F: Samples> Merger<'a, F> {
    fn new(exposures: &'a [Exposure<'a, F>], device: &DeviceConfig, pattern: BayerPattern) -> Self {
        let [wr, wg, wb] = device.response.weights;
        let [r, g1, g2, b] = pattern.offsets();
        let taps = [(r, wr), (g1, wg / 2.0), (g2, wg / 2.0), (b, wb)];
        let tg: Vec<f64> = exposures.iter().map(|e| e.exposure_s * e.gain).collect();
        let shortest = (0..tg.len())
            .min_by(|&a, &b| tg[a].total_cmp(&tg[b]))
            .unwrap_or(0);
        Self {
            exposures,
            shortest,
            q: taps.iter().map(|(_, w)| w * w).sum(),
            weight_sum: wr + wg + wb,
            taps,
            tg,
            black: device.sensor.black_level_dn,
            valid_min: device.sensor.valid_min_dn,
            valid_max: device.sensor.valid_max_dn,
            cg: device.response.cg,
            conversion: device.noise.conversion_dn_per_e,
            floor_var: device.noise.read_noise_dn.powi(2) + 1.0 / 12.0,
        }
    }

    /// Luminance, flag and relative sigma of group `gx` of the row pair `rows` (per exposure).
    #[inline]
    fn group(
        &self,
        rows: &[[&[F::Sample]; 2]],
        gx: usize,
        inverse_vignetting: f64,
    ) -> (f32, MapFlag, f32) {
        // Up to 8 exposures per sequence: fixed-size scratch, no allocation per group.
        let mut signal = [0.0f64; 16];
        let mut valid = [false; 16];
        let (mut sum_s, mut sum_tg) = (0.0, 0.0);
        let (mut all_over, mut all_under) = (true, true);
        let n = self.exposures.len().min(16);
        for k in 0..n {
            let (mut s, mut ok, mut over, mut under) = (0.0, true, false, false);
            for ((dx, dy), w) in self.taps {
                let x: f64 = rows[k][dy][2 * gx + dx].into();
                over |= x > self.valid_max;
                under |= x < self.valid_min;
                ok &= x >= self.valid_min && x <= self.valid_max;
                s += w * (x - self.black);
            }
            all_over &= over;
            all_under &= under;
            signal[k] = s;
            valid[k] = ok;
            if ok {
                sum_s += s;
                sum_tg += self.tg[k];
            }
        }
        if sum_tg == 0.0 || inverse_vignetting == 0.0 {
            let flag = if all_over {
                MapFlag::OverRange
            } else if all_under {
                MapFlag::UnderRange
            } else {
                // Mixed: the shortest exposure decides (too bright there means too bright).
                let shortest = &rows[self.shortest];
                let over = self.taps.iter().any(|((dx, dy), _)| {
                    Into::<f64>::into(shortest[*dy][2 * gx + dx]) > self.valid_max
                });
                if over {
                    MapFlag::OverRange
                } else {
                    MapFlag::UnderRange
                }
            };
            return (f32::NAN, flag, f32::NAN);
        }
        // Pilot rate (signal per unit t g), then inverse-variance weights from the predicted
        // signal of each exposure.
        let pilot = (sum_s / sum_tg).max(0.0);
        let (mut num, mut den) = (0.0, 0.0);
        for k in 0..n {
            if !valid[k] {
                continue;
            }
            let gain = self.exposures[k].gain;
            let predicted_sample = pilot * self.tg[k] / self.weight_sum;
            let var_s = self.q * (self.conversion * gain * predicted_sample + self.floor_var);
            let inv = self.tg[k] * self.tg[k] / var_s;
            num += inv * signal[k] / self.tg[k];
            den += inv;
        }
        let rate = num / den;
        let luminance = self.cg * rate * inverse_vignetting;
        let sigma = (1.0 / den).sqrt() / rate.abs();
        (luminance as f32, MapFlag::Valid, sigma as f32)
    }
}

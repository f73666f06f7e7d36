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

/// What a frame gives the merge per 2x2 group: raw samples (any [`Samples`]) or the fabric's
/// grouped words ([`GroupedFrame`]).
pub trait ExposureFrame: Sync {
    /// Width and height in groups.
    fn groups(&self) -> (usize, usize);
    /// For group row `gy`: the black-subtracted weighted signal `Σ w X'` (DN) and whether a
    /// sample was above `valid_max` or below `valid_min`.
    fn group_row(
        &self,
        gy: usize,
        p: &GroupParams,
        signal: &mut [f64],
        over: &mut [bool],
        under: &mut [bool],
    );
}

/// The per-sample constants of the group signal.
pub struct GroupParams {
    /// Weight of the sample at (dx, dy) of a 2x2 block, indexed [dy][dx].
    pub weight_at: [[f64; 2]; 2],
    pub black: f64,
    pub valid_min: f64,
    pub valid_max: f64,
}

impl<F: Samples> ExposureFrame for F {
    fn groups(&self) -> (usize, usize) {
        (self.width() / 2, self.height() / 2)
    }

    fn group_row(
        &self,
        gy: usize,
        p: &GroupParams,
        signal: &mut [f64],
        over: &mut [bool],
        under: &mut [bool],
    ) {
        let width = signal.len();
        let [[w00, w10], [w01, w11]] = p.weight_at;
        let top = &self.row(2 * gy)[..2 * width];
        let bottom = &self.row(2 * gy + 1)[..2 * width];
        // A9 cost (timing::a9::merge::GROUP_ROW_INLINE, armv7 listing): per group, 60
        // instructions (4 u16 loads and conversions, 4 subtractions, 1 multiply and 3 VMLA for
        // the signal, 2 compares and stores for the flags, 15 register moves) and six calls of
        // libm's fmin/fmax: VFPv3 has no min/max instruction, so each `min`/`max` below is a
        // call. 106 cycles, bound by the load/store/VFP issue port.
        for (gx, (t, b)) in top.chunks_exact(2).zip(bottom.chunks_exact(2)).enumerate() {
            let (a, bb, c, d): (f64, f64, f64, f64) =
                (t[0].into(), t[1].into(), b[0].into(), b[1].into());
            let lo = a.min(bb).min(c.min(d));
            let hi = a.max(bb).max(c.max(d));
            signal[gx] = w00 * (a - p.black)
                + w10 * (bb - p.black)
                + w01 * (c - p.black)
                + w11 * (d - p.black);
            over[gx] = hi > p.valid_max;
            under[gx] = lo < p.valid_min;
        }
    }
}

/// A frame as the fabric's DMA wrote it in grouped mode: one word per 2x2 group
/// (`skylux_regmap::words::grouped`: the weighted, black-subtracted luminance in Q16.14 and the
/// over/under flags), row pairs top to bottom. The fabric's `bayer.*` registers must hold the
/// device's black level, valid range and weights (to Q2.14): the merge takes the signal as
/// the fabric computed it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GroupedFrame {
    /// Groups per row and rows of groups.
    pub width: usize,
    pub height: usize,
    pub words: Vec<u32>,
}

impl ExposureFrame for GroupedFrame {
    fn groups(&self) -> (usize, usize) {
        if self.words.len() == self.width * self.height {
            (self.width, self.height)
        } else {
            // A payload of the wrong length fits no geometry: the size check refuses it.
            (0, 0)
        }
    }

    fn group_row(
        &self,
        gy: usize,
        _p: &GroupParams,
        signal: &mut [f64],
        over: &mut [bool],
        under: &mut [bool],
    ) {
        use skylux_regmap::words::grouped;
        let width = signal.len();
        let row = &self.words[gy * self.width..gy * self.width + width];
        for (gx, &w) in row.iter().enumerate() {
            signal[gx] = grouped::luma(w);
            over[gx] = grouped::over(w);
            under[gx] = grouped::under(w);
        }
    }
}

/// One exposure of an HDR set.
#[derive(Copy, Clone, Debug)]
pub struct Exposure<'a, F: ExposureFrame = RawFrame> {
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
    #[error("exposure {index}: frame is {width}x{height} samples (or a grouped payload that is not whole rows), the set's geometry needs {expected_width}x{expected_height}")]
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
pub fn merge<F: ExposureFrame>(
    exposures: &[Exposure<F>],
    device: &DeviceConfig,
    pattern: BayerPattern,
    geometry: &GroupGeometry,
) -> Result<LuminanceMap, HdrError> {
    if exposures.is_empty() {
        return Err(HdrError::Empty);
    }
    for (index, e) in exposures.iter().enumerate() {
        let (gw, gh) = e.frame.groups();
        if (gw, gh) != (geometry.width, geometry.height) {
            return Err(HdrError::FrameSize {
                index,
                width: 2 * gw,
                height: 2 * gh,
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
    let merger = Merger::new(
        exposures.iter().map(|e| (e.exposure_s, e.gain)),
        device,
        pattern,
    );
    let (width, height) = (geometry.width, geometry.height);
    let mut map = LuminanceMap {
        width,
        height,
        luminance_cd_m2: vec![f32::NAN; width * height],
        flags: vec![MapFlag::UnderRange; width * height],
        relative_sigma: vec![f32::NAN; width * height],
    };
    if width > 0 {
        map.luminance_cd_m2
            .par_chunks_mut(width)
            .zip(map.flags.par_chunks_mut(width))
            .zip(map.relative_sigma.par_chunks_mut(width))
            .enumerate()
            .for_each_init(
                || RowScratch::new(exposures.len(), width),
                |scratch, (gy, ((luminance, flags), sigma))| {
                    let inverse_vignetting =
                        &geometry.inverse_vignetting[gy * width..(gy + 1) * width];
                    let out = RowOut {
                        luminance,
                        flags,
                        sigma,
                    };
                    merger.row(exposures, gy, inverse_vignetting, scratch, out);
                },
            );
    }
    Ok(map)
}

/// One row of the map, written in place.
struct RowOut<'a> {
    luminance: &'a mut [f32],
    flags: &'a mut [MapFlag],
    sigma: &'a mut [f32],
}

/// Per-row working arrays, reused across the rows a thread merges.
struct RowScratch {
    /// Weighted black-subtracted signal per exposure and group (exposure-major).
    signal: Vec<f64>,
    /// Per exposure and group: 1 valid, 0 not.
    valid: Vec<bool>,
    over: Vec<bool>,
    under: Vec<bool>,
    /// Per group: Σ signal and Σ t g over the valid exposures, the pilot rate, and the
    /// inverse-variance sums.
    sum_s: Vec<f64>,
    sum_tg: Vec<f64>,
    pilot: Vec<f64>,
    num: Vec<f64>,
    den: Vec<f64>,
}

impl RowScratch {
    fn new(exposures: usize, width: usize) -> Self {
        Self {
            signal: vec![0.0; exposures * width],
            valid: vec![false; exposures * width],
            over: vec![false; exposures * width],
            under: vec![false; exposures * width],
            sum_s: vec![0.0; width],
            sum_tg: vec![0.0; width],
            pilot: vec![0.0; width],
            num: vec![0.0; width],
            den: vec![0.0; width],
        }
    }
}

/// Everything per-set that the per-group merge needs, precomputed. The fabric's map
/// (`super::fabric_map`) uses the same calibration for its one exposure per group.
pub(super) struct Merger {
    /// t g per exposure, and its inverse.
    tg: Vec<f64>,
    inv_tg: Vec<f64>,
    /// q K g t / Σw per exposure: the shot-noise variance of the signal per unit pilot rate.
    shot_var_per_rate: Vec<f64>,
    /// Index of the exposure with the smallest t g.
    shortest: usize,
    /// The sample weights (w_r, w_g/2 twice and w_b placed by the Bayer phase), black level
    /// and valid range.
    params: GroupParams,
    /// q (read noise² + 1/12): the variance floor of a group's signal.
    floor_var: f64,
    cg: f64,
}

impl Merger {
    /// The calibration of a set whose exposures have these (integration time s, gain).
    pub(super) fn new(
        exposures: impl Iterator<Item = (f64, f64)>,
        device: &DeviceConfig,
        pattern: BayerPattern,
    ) -> Self {
        let exposures: Vec<(f64, f64)> = exposures.collect();
        let [wr, wg, wb] = device.response.weights;
        let [r, g1, g2, b] = pattern.offsets();
        let mut weight_at = [[0.0; 2]; 2];
        for ((dx, dy), w) in [(r, wr), (g1, wg / 2.0), (g2, wg / 2.0), (b, wb)] {
            weight_at[dy][dx] = w;
        }
        let q: f64 = weight_at.iter().flatten().map(|w| w * w).sum();
        let weight_sum = wr + wg + wb;
        let tg: Vec<f64> = exposures.iter().map(|(t, gain)| t * gain).collect();
        let shortest = (0..tg.len())
            .min_by(|&a, &b| tg[a].total_cmp(&tg[b]))
            .unwrap_or(0);
        Self {
            inv_tg: tg.iter().map(|t| 1.0 / t).collect(),
            shot_var_per_rate: exposures
                .iter()
                .zip(&tg)
                .map(|((_, gain), t)| q * device.noise.conversion_dn_per_e * gain * t / weight_sum)
                .collect(),
            tg,
            shortest,
            params: GroupParams {
                weight_at,
                black: device.sensor.black_level_dn,
                valid_min: device.sensor.valid_min_dn,
                valid_max: device.sensor.valid_max_dn,
            },
            floor_var: q * (device.noise.read_noise_dn.powi(2) + 1.0 / 12.0),
            cg: device.response.cg,
        }
    }

    /// One group's luminance (cd/m²) and relative standard deviation from exposure `k` alone,
    /// with signal `signal_dn` (the weighted, black-subtracted sum): the merge's formula with
    /// one valid exposure (its pilot is the exposure's own rate). `None` for an exposure the
    /// set does not have.
    pub(super) fn single(
        &self,
        k: usize,
        signal_dn: f64,
        inverse_vignetting: f32,
    ) -> Option<(f32, f32)> {
        let (inv_tg, shot) = (*self.inv_tg.get(k)?, self.shot_var_per_rate[k]);
        // One division and one square root a group (the A9's VFP holds the pipeline 20 and
        // 28 cycles for them: `timing::a9::fabric_map`): the rate by the precomputed 1/(t g),
        // and σ_rate = sqrt(rate⁺ shot + floor) / (t g), relative to |rate|.
        let rate = signal_dn * inv_tg;
        let luminance = (self.cg * rate * inverse_vignetting as f64) as f32;
        let sigma = (rate.max(0.0) * shot + self.floor_var).sqrt() * inv_tg / rate.abs();
        Some((luminance, sigma as f32))
    }

    /// Merges group row `gy`: a first pass per exposure over the row's groups (the frame's
    /// samples or the fabric's words), then a pass per group.
    fn row<F: ExposureFrame>(
        &self,
        exposures: &[Exposure<F>],
        gy: usize,
        inverse_vignetting: &[f32],
        scratch: &mut RowScratch,
        out: RowOut<'_>,
    ) {
        let width = inverse_vignetting.len();
        let n = exposures.len();
        for (k, e) in exposures.iter().enumerate() {
            let range = k * width..(k + 1) * width;
            e.frame.group_row(
                gy,
                &self.params,
                &mut scratch.signal[range.clone()],
                &mut scratch.over[range.clone()],
                &mut scratch.under[range.clone()],
            );
            // A9: 13 instructions per group (timing::a9::merge::VALID).
            for i in range {
                scratch.valid[i] = !(scratch.over[i] || scratch.under[i]);
            }
        }
        // The per-group passes run exposure-major over the whole row, without branches, so
        // the compiler vectorises them; each group's sums are still taken in exposure order,
        // so the result is the same as a per-group loop's.
        let (sum_s, sum_tg) = (&mut scratch.sum_s, &mut scratch.sum_tg);
        sum_s.iter_mut().for_each(|x| *x = 0.0);
        sum_tg.iter_mut().for_each(|x| *x = 0.0);
        // A9: 14 instructions per group and exposure, 2 VADD.F64 (timing::a9::merge::SUMS).
        for k in 0..n {
            let row = k * width..(k + 1) * width;
            let tg = self.tg[k];
            for (((s, t), &x), &ok) in sum_s
                .iter_mut()
                .zip(sum_tg.iter_mut())
                .zip(&scratch.signal[row.clone()])
                .zip(&scratch.valid[row])
            {
                *s += if ok { x } else { 0.0 };
                *t += if ok { tg } else { 0.0 };
            }
        }
        // Pilot rate (signal per unit t g), then inverse-variance weights from the signal it
        // predicts for each exposure.
        let (num, den) = (&mut scratch.num, &mut scratch.den);
        // A9: one VDIV.F64 (20 cycles of the VFP pipeline) and an fmax call per group
        // (timing::a9::merge::PILOT_INLINE).
        for ((p, s), t) in scratch
            .pilot
            .iter_mut()
            .zip(sum_s.iter())
            .zip(sum_tg.iter())
        {
            *p = (s / t).max(0.0);
        }
        num.iter_mut().for_each(|x| *x = 0.0);
        den.iter_mut().for_each(|x| *x = 0.0);
        // A9: per group and valid exposure one VDIV.F64, one VMLA, two VMUL, two VADD: 31 VFP
        // cycles (timing::a9::merge::WEIGHTS_VALID); 9 cycles when not valid (no division).
        for k in 0..n {
            let row = k * width..(k + 1) * width;
            let (tg, inv_tg) = (self.tg[k], self.inv_tg[k]);
            let (shot, floor) = (self.shot_var_per_rate[k], self.floor_var);
            for ((((a, b), &p), &x), &ok) in num
                .iter_mut()
                .zip(den.iter_mut())
                .zip(&scratch.pilot)
                .zip(&scratch.signal[row.clone()])
                .zip(&scratch.valid[row])
            {
                let inv = tg * tg / (p * shot + floor);
                *a += if ok { inv * x * inv_tg } else { 0.0 };
                *b += if ok { inv } else { 0.0 };
            }
        }
        // A9: a valid group costs three VDIV.F64 and one VSQRT.F64 (28 cycles): 100 VFP cycles
        // (timing::a9::merge::OUTPUT_VALID); a flagged one a loop over the exposures' flags.
        for (gx, &inv_v) in inverse_vignetting.iter().enumerate() {
            if sum_tg[gx] == 0.0 || inv_v == 0.0 {
                let (mut all_over, mut all_under) = (true, true);
                for k in 0..n {
                    all_over &= scratch.over[k * width + gx];
                    all_under &= scratch.under[k * width + gx];
                }
                let flag = if all_over || (!all_under && scratch.over[self.shortest * width + gx]) {
                    // Mixed: the shortest exposure decides (too bright there means too bright).
                    MapFlag::OverRange
                } else {
                    MapFlag::UnderRange
                };
                out.luminance[gx] = f32::NAN;
                out.flags[gx] = flag;
                out.sigma[gx] = f32::NAN;
                continue;
            }
            let rate = num[gx] / den[gx];
            out.luminance[gx] = (self.cg * rate * inv_v as f64) as f32;
            out.flags[gx] = MapFlag::Valid;
            out.sigma[gx] = ((1.0 / den[gx]).sqrt() / rate.abs()) as f32;
        }
    }
}

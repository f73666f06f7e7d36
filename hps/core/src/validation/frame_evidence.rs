//! Evidence the raw frames give on their own, with no lux-meter: the shutter's overhead from
//! the ratio of two exposures.
//!
//! A pixel valid (above the floor, below saturation) in two exposures of one capture records
//! the same light for both, so the ratio of its black-subtracted, gain-normalised signals is
//! the ratio of the true integration times, (t_j + t0) / (t_i + t0), whatever the sky or the
//! sun does. A fixed overhead t0 shows there directly: with the declared times 26.59 and
//! 707.1 µs, an overhead of 9 µs makes the ratio 20.1 instead of 26.6. Each pair of
//! exposures gives t0 = (t_j − r t_i) / (r − 1) from its median ratio r; the pairs are
//! combined by their inverse variances (the ratios' spread, through dt0/dr =
//! (t_i − t_j) / (r − 1)²), so the short pairs, which are the sensitive ones, dominate.
//!
//! This needs exposures that overlap where they are short. With the device's ladder (1,
//! 26.6, 707, 18,803 and 500,000 µs, 26.6x apart for a 78:1 valid range) only the sun is bright
//! in the short frames, and its core is valid in one of them alone; what they share is the
//! sun's edge, the groups that part of the disc covers, a few per capture in sun (their
//! ratios give the overhead within 0.5 µs on the battery's campaigns #70 and #72 at 10 µs,
//! where the core saturates every frame). The pixels valid in the two longest are the sky,
//! where µs do not show. Where no capture shows the sun's edge in two frames, the sun tells
//! instead, against the pyranometer (an instrument beside the camera, not the lux-meters):
//! [`sun_over_pyranometer`].

use crate::camera::DeviceConfig;
use crate::campaign::{Campaign, CaptureConfig, RawFrame};
use crate::model::ModelError;

/// Fewest pixels valid in both exposures for a pair to count. The short pairs overlap only
/// at the sun's edge, where a group covered by part of the disc reads between the two
/// frames' ranges: a handful of pixels per capture in sun (20 over campaign #70 of the
/// seed-18 battery, 40 over #72, 4 over #74's two captures in sun), each of which moves the
/// ratio by tens of % per µs, so a few are evidence; the median's standard error (from the
/// MAD) says how much.
const MIN_PIXELS: usize = 4;

/// Pixels must read at least this many DN above black in the shorter exposure: well above
/// the read noise (2 DN in the simulated sensor), so the ratio's noise stays a few %.
const MIN_SIGNAL_DN: f64 = 60.0;

/// Most pixels kept per pair and capture (evenly strided over those valid in both, never
/// before the selection: striding the frame first dropped the sun's few edge pixels, the
/// only overlap of the short frames), to bound the time of the median.
const MAX_PIXELS_PER_CAPTURE: usize = 20_000;

/// Floor on a pair's median ratio's relative error, for what pixel noise does not show (the
/// response's departure from linearity, a black-level error, and above all the choice of the
/// pixels valid in both, made on noisy values at the edges of the valid range): 2 %. The two
/// longest exposures' ratio reads 1.0-1.4 % off the declared one on the eight campaigns
/// without an overhead of the seed-18 battery (a "260 ± 100 µs overhead" each time with a
/// 0.5 % floor, named once beside a bright ground: campaign #42); with 10⁵ sky pixels and no
/// sensitivity to µs, that pair must not outweigh the short ones or show an overhead alone.
const RATIO_SYSTEMATIC: f64 = 0.02;

/// The shutter overhead the frames show, µs, with its standard error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OverheadEstimate {
    pub overhead_us: f64,
    pub standard_error_us: f64,
    /// Exposure pairs that contributed.
    pub pairs: usize,
    /// Pixels over all pairs.
    pub pixels: usize,
}

impl OverheadEstimate {
    /// Whether the frames show an overhead: at least [`MIN_OVERHEAD_US`] and four standard
    /// errors from zero.
    pub fn shows_overhead(&self) -> bool {
        self.overhead_us >= MIN_OVERHEAD_US && self.overhead_us > 4.0 * self.standard_error_us
    }
}

/// Smallest overhead worth naming, µs: a tenth of the shortest exposure the device takes
/// (1 µs), below which the sun's measurement changes by under 10 %.
pub const MIN_OVERHEAD_US: f64 = 0.1;

/// The per-pixel signal ratios of exposure `j` over exposure `i` (i the shorter) in one
/// capture, pixels valid in both.
fn ratios(short: &RawFrame, long: &RawFrame, gains: (f64, f64), device: &DeviceConfig) -> Vec<f64> {
    let s = &device.sensor;
    let valid = |v: f64| v >= s.valid_min_dn && v <= s.valid_max_dn;
    let all: Vec<f64> = short
        .samples_dn
        .iter()
        .zip(&long.samples_dn)
        .filter_map(|(&a, &b)| {
            let (a, b) = (f64::from(a), f64::from(b));
            let sa = a - s.black_level_dn;
            (valid(a) && valid(b) && sa >= MIN_SIGNAL_DN)
                .then(|| ((b - s.black_level_dn) / gains.1) / (sa / gains.0))
        })
        .collect();
    let stride = all.len().div_ceil(MAX_PIXELS_PER_CAPTURE).max(1);
    all.into_iter().step_by(stride).collect()
}

/// Estimates the shutter overhead from the frames of the captures `which` (indices into the
/// campaign's captures) with the declared camera. `None` where no pair of exposures shares
/// enough valid pixels.
pub fn shutter_overhead(
    campaign: &Campaign,
    device: &DeviceConfig,
    which: &[usize],
) -> Result<Option<OverheadEstimate>, ModelError> {
    // Per pair of consecutive exposures (by declared time), the ratios over all captures.
    let mut by_pair: Vec<((f64, f64), Vec<f64>)> = Vec::new();
    for &i in which {
        let Some(c) = campaign.captures.get(i) else {
            continue;
        };
        let path = c.dir.join("capture.toml");
        let config = CaptureConfig::read(&path).map_err(crate::hdr::CaptureMapError::from)?;
        let mut entries: Vec<_> = config.exposure.iter().collect();
        entries.sort_by(|a, b| a.exposure_us.total_cmp(&b.exposure_us));
        let frames = entries
            .iter()
            .map(|e| RawFrame::read(&c.dir.join(&e.file)))
            .collect::<Result<Vec<_>, _>>()
            .map_err(crate::hdr::CaptureMapError::from)?;
        for k in 1..entries.len() {
            let key = (entries[k - 1].exposure_us, entries[k].exposure_us);
            if key.0 <= 0.0 || key.1 <= key.0 {
                continue;
            }
            let r = ratios(
                &frames[k - 1],
                &frames[k],
                (entries[k - 1].gain, entries[k].gain),
                device,
            );
            match by_pair.iter_mut().find(|(p, _)| *p == key) {
                Some((_, v)) => v.extend(r),
                None => by_pair.push((key, r)),
            }
        }
    }
    let (mut sw, mut swx, mut pairs, mut pixels) = (0.0, 0.0, 0, 0);
    for ((ti, tj), mut v) in by_pair {
        if v.len() < MIN_PIXELS {
            continue;
        }
        let (r, r_noise) = crate::numerics::stats::median_and_standard_error(&mut v);
        let r_err = r_noise.hypot(RATIO_SYSTEMATIC * r);
        if r.is_nan() || r <= 1.0 || r_err <= 0.0 {
            continue;
        }
        let t0 = (tj - r * ti) / (r - 1.0);
        let err = (ti - tj).abs() / (r - 1.0).powi(2) * r_err;
        if !t0.is_finite() || !err.is_finite() || err <= 0.0 {
            continue;
        }
        let w = 1.0 / (err * err);
        sw += w;
        swx += w * t0;
        pairs += 1;
        pixels += v.len();
    }
    if pairs == 0 {
        return Ok(None);
    }
    Ok(Some(OverheadEstimate {
        overhead_us: swx / sw,
        standard_error_us: sw.sqrt().recip(),
        pairs,
        pixels,
    }))
}

/// The extracted sun's direct-normal illuminance over the pyranometer's, at the captures that
/// show both: (capture, ratio, the capture's shortest declared exposure in µs). The sun is
/// measured in the shortest exposure, so an overhead t0 makes the ratio (t + t0) / t; the
/// sun's colour (a few %) and the lens's fall-off at the sun (below 1) move it much less.
pub fn sun_over_pyranometer(
    campaign: &Campaign,
    captures: &[crate::model::CaptureData],
    suns: &[Option<f64>],
) -> Vec<(usize, f64, f64)> {
    let mut out = Vec::new();
    for (i, (c, sun_dn_lux)) in captures.iter().zip(suns).enumerate() {
        let Some(sun_dn_lux) = sun_dn_lux.filter(|v| v.is_finite() && *v > 0.0) else {
            continue;
        };
        let Some(reference) =
            crate::validation::sky_geometry::reference_direct_normal_lux(campaign, c)
        else {
            continue;
        };
        let shortest = campaign
            .captures
            .get(i)
            .and_then(|cap| CaptureConfig::read(&cap.dir.join("capture.toml")).ok())
            .and_then(|cfg| {
                cfg.exposure
                    .iter()
                    .map(|e| e.exposure_us)
                    .min_by(f64::total_cmp)
            });
        if let Some(t) = shortest.filter(|t| *t > 0.0) {
            out.push((i, sun_dn_lux / reference, t));
        }
    }
    out
}

//! The sky's colour as the device measures it from its own raw frames: a separate, cheap pass
//! beside the (monochrome) HDR merge, for the spectral-mismatch effect of the loop.
//!
//! The colour index of a set of groups is the ratio of their blue to their red signal, each
//! black-subtracted and divided by its frame's exposure and gain, summed over the groups
//! weighted by solid angle: `c = Σ ω B / Σ ω R`. Each group is read in the longest exposure
//! in which none of its four samples is out of the valid range, so the index weights the sky
//! as its luminance does. A device whose channels are balanced under its calibration source
//! gives `c = 1` for that source (and for a spectrally grey scene in the simulator); a bluer
//! sky gives a larger index, a redder sun a smaller one.

use crate::camera::DeviceConfig;
use crate::campaign::{BayerPattern, CaptureConfig, Channel, RawFrame};
use crate::hdr::GroupGeometry;
use crate::sky::SkyPatches;
use glam::DVec3;
use std::path::Path;

/// A group's colour signal counts only if its red and blue signals are at least this many DN
/// above black (and above the sensor's `valid_min_dn`) in the frame it is read from (below,
/// read noise dominates the ratio).
const MIN_SIGNAL_DN: f64 = 8.0;

/// Groups closer to the sun than this are left out of the sky's index, degrees (the sun's
/// own colour is [`CaptureColour::sun_index`]).
const SUN_EXCLUSION_DEG: f64 = 3.0;

/// Fewest groups a sky patch needs for its own index.
const MIN_PATCH_GROUPS: usize = 4;

/// What the colour pass gives per capture.
#[derive(Clone, Debug, PartialEq)]
pub struct CaptureColour {
    /// Blue / red over the sky the lens sees above the horizon, the sun's surroundings left
    /// out (NaN if no sky group is readable).
    pub sky_index: f64,
    /// Blue / red over the sun's groups (NaN without a sun, or if every frame saturates it).
    pub sun_index: f64,
    /// Per sky patch (the daylight coefficients' order), blue / red of its groups; NaN where
    /// the lens saw fewer than [`MIN_PATCH_GROUPS`] readable groups.
    pub patch_index: Vec<f64>,
}

/// Per group, the exposure-normalised red and blue signals (DN per second at unity gain),
/// read in the longest exposure that keeps the group's four samples in the valid range;
/// `None` where no exposure does or the signal is too weak.
pub fn group_colours(
    frames: &[(&RawFrame, f64, f64)],
    bayer: BayerPattern,
    device: &DeviceConfig,
) -> Vec<Option<(f64, f64)>> {
    let Some(first) = frames.first() else {
        return Vec::new();
    };
    let (gw, gh) = (first.0.width / 2, first.0.height / 2);
    // Longest exposure first.
    let mut order: Vec<usize> = (0..frames.len()).collect();
    order.sort_by(|&a, &b| (frames[b].1 * frames[b].2).total_cmp(&(frames[a].1 * frames[a].2)));
    let s = &device.sensor;
    (0..gw * gh)
        .map(|g| {
            let (gx, gy) = (g % gw, g / gw);
            for &k in &order {
                let (frame, exposure_s, gain) = frames[k];
                if frame.width != first.0.width || frame.height != first.0.height {
                    return None;
                }
                let (mut r, mut b, mut ok) = (0.0, 0.0, true);
                for dy in 0..2 {
                    for dx in 0..2 {
                        let (x, y) = (2 * gx + dx, 2 * gy + dy);
                        let v = f64::from(frame.samples_dn[y * frame.width + x]);
                        if v > s.valid_max_dn {
                            ok = false;
                        }
                        match bayer.channel(dx, dy) {
                            Channel::Red => r = v - s.black_level_dn,
                            Channel::Blue => b = v - s.black_level_dn,
                            Channel::Green => {}
                        }
                    }
                }
                if !ok {
                    continue;
                }
                let floor = MIN_SIGNAL_DN.max(s.valid_min_dn - s.black_level_dn);
                if r < floor || b < floor || exposure_s <= 0.0 || gain <= 0.0 {
                    return None;
                }
                let k = 1.0 / (exposure_s * gain);
                return Some((r * k, b * k));
            }
            None
        })
        .collect()
}

/// The colour indices of one capture from its group colours, the groups' geometry, the sky
/// patches and the groups of the extracted sun (empty without a sun).
pub fn colour_indices(
    colours: &[Option<(f64, f64)>],
    geometry: &GroupGeometry,
    patches: &SkyPatches,
    sun_groups: &[usize],
) -> CaptureColour {
    let n = patches.len();
    let sun_dir = {
        let (mut sum, mut w) = (DVec3::ZERO, 0.0);
        for &g in sun_groups {
            if let (Some(d), Some(Some((r, _)))) = (geometry.direction.get(g), colours.get(g)) {
                if d.is_finite() {
                    sum += d.as_dvec3() * *r;
                    w += *r;
                }
            }
        }
        (w > 0.0).then(|| sum.normalize())
    };
    let cos_exclusion = SUN_EXCLUSION_DEG.to_radians().cos();
    let (mut sky_r, mut sky_b) = (0.0, 0.0);
    let mut per_patch = vec![(0.0f64, 0.0f64, 0usize); n];
    for (i, c) in colours.iter().enumerate() {
        let Some((r, b)) = *c else { continue };
        let d = geometry.direction[i];
        if !d.is_finite() || d.z < 0.0 {
            continue;
        }
        let d = d.as_dvec3();
        if sun_dir.is_some_and(|s| d.dot(s) > cos_exclusion) {
            continue;
        }
        let w = f64::from(geometry.solid_angle_sr[i]);
        sky_r += w * r;
        sky_b += w * b;
        if let Some(p) = patches.patch_of(d) {
            per_patch[p].0 += w * r;
            per_patch[p].1 += w * b;
            per_patch[p].2 += 1;
        }
    }
    let (mut sun_r, mut sun_b) = (0.0, 0.0);
    for &g in sun_groups {
        if let Some(Some((r, b))) = colours.get(g) {
            sun_r += r;
            sun_b += b;
        }
    }
    let ratio = |b: f64, r: f64| if r > 0.0 { b / r } else { f64::NAN };
    CaptureColour {
        sky_index: ratio(sky_b, sky_r),
        sun_index: ratio(sun_b, sun_r),
        patch_index: per_patch
            .into_iter()
            .map(|(r, b, k)| {
                if k >= MIN_PATCH_GROUPS {
                    ratio(b, r)
                } else {
                    f64::NAN
                }
            })
            .collect(),
    }
}

/// Reads a capture folder's frames and gives its colour indices (see [`colour_indices`]).
pub fn capture_colour(
    dir: &Path,
    device: &DeviceConfig,
    geometry: &GroupGeometry,
    patches: &SkyPatches,
    sun_groups: &[usize],
) -> Result<CaptureColour, crate::hdr::CaptureMapError> {
    let capture = CaptureConfig::read(&dir.join("capture.toml"))?;
    let mut frames = Vec::with_capacity(capture.exposure.len());
    for e in &capture.exposure {
        frames.push(RawFrame::read(&dir.join(&e.file))?);
    }
    let with_times: Vec<(&RawFrame, f64, f64)> = frames
        .iter()
        .zip(&capture.exposure)
        .map(|(f, e)| (f, e.exposure_us * 1e-6, e.gain))
        .collect();
    let colours = group_colours(&with_times, capture.bayer, device);
    if colours.len() != geometry.direction.len() {
        return Ok(CaptureColour {
            sky_index: f64::NAN,
            sun_index: f64::NAN,
            patch_index: vec![f64::NAN; patches.len()],
        });
    }
    Ok(colour_indices(&colours, geometry, patches, sun_groups))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::CameraModel;
    use crate::campaign::Readout;

    /// A GRBG frame whose every group has the given black-subtracted channel signals.
    fn frame(w: usize, h: usize, black: f64, rgb: [f64; 3]) -> RawFrame {
        let samples_dn = (0..w * h)
            .map(|i| {
                let (x, y) = (i % w, i / w);
                let v = match BayerPattern::GRBG.channel(x & 1, y & 1) {
                    Channel::Red => rgb[0],
                    Channel::Green => rgb[1],
                    Channel::Blue => rgb[2],
                };
                (black + v).round() as u16
            })
            .collect();
        RawFrame {
            width: w,
            height: h,
            samples_dn,
        }
    }

    fn setup() -> (DeviceConfig, GroupGeometry, SkyPatches) {
        let device = DeviceConfig::default();
        let camera = CameraModel::new(device.clone());
        let readout = Readout {
            col_start: 0,
            row_start: 0,
            skip: 8,
            bin: 1,
        };
        let geometry = GroupGeometry::new(&camera, &readout, 2592 / 8, 1944 / 8);
        (device, geometry, SkyPatches::reinhart(2))
    }

    /// A grey scene (equal channels) gives the grey index 1 over the sky and in every patch.
    #[test]
    fn grey_frame_gives_the_grey_index() {
        let (device, geometry, patches) = setup();
        let black = device.sensor.black_level_dn;
        let f = frame(324, 242, black, [400.0, 400.0, 400.0]);
        let colours = group_colours(&[(&f, 1e-3, 1.0)], BayerPattern::GRBG, &device);
        let c = colour_indices(&colours, &geometry, &patches, &[]);
        assert!((c.sky_index - 1.0).abs() < 1e-12, "{}", c.sky_index);
        assert!(c.sun_index.is_nan());
        let seen: Vec<f64> = c
            .patch_index
            .iter()
            .copied()
            .filter(|v| v.is_finite())
            .collect();
        assert!(seen.len() > 10, "{}", seen.len());
        assert!(seen.iter().all(|v| (v - 1.0).abs() < 1e-12));
    }

    /// A bluer sky (blue 1.4 times red) gives an index of 1.4; a saturated long frame is
    /// skipped for the shorter one, which keeps the ratio; the sun's groups give their own.
    #[test]
    fn bluer_sky_gives_a_larger_index_and_saturated_frames_are_skipped() {
        let (device, geometry, patches) = setup();
        let black = device.sensor.black_level_dn;
        let long = frame(324, 242, black, [4000.0, 4000.0, 4000.0]);
        let short = frame(324, 242, black, [200.0, 300.0, 280.0]);
        let mut colours = group_colours(
            &[(&long, 1e-2, 1.0), (&short, 1e-4, 1.0)],
            BayerPattern::GRBG,
            &device,
        );
        // A "sun" group: redder, somewhere the lens sees the sky.
        let sun = (0..geometry.direction.len())
            .find(|&i| geometry.direction[i].is_finite() && geometry.direction[i].z > 0.5)
            .unwrap();
        colours[sun] = Some((1e9, 0.8e9));
        let c = colour_indices(&colours, &geometry, &patches, &[sun]);
        assert!((c.sky_index - 1.4).abs() < 1e-9, "{}", c.sky_index);
        assert!((c.sun_index - 0.8).abs() < 1e-9, "{}", c.sun_index);
        assert!(c.patch_index.iter().any(|v| (v - 1.4).abs() < 1e-9));
    }

    /// Signals too weak to carry a ratio are left out.
    #[test]
    fn weak_signals_are_left_out() {
        let (device, _, _) = setup();
        let f = frame(8, 8, device.sensor.black_level_dn, [2.0, 2.0, 2.0]);
        let colours = group_colours(&[(&f, 1e-3, 1.0)], BayerPattern::GRBG, &device);
        assert!(colours.iter().all(Option::is_none));
    }
}

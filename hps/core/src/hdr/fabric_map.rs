//! The fabric's HDR map (`hdr.*`, word format `skylux_regmap::words::hdr_map`) into the
//! [`LuminanceMap`] the pipeline uses: each group's word is the grouped word of the longest
//! exposure of the set in which it was usable, so its luminance is that exposure's signal
//! through the merge's own calibration (response, exposure, gain, vignetting). The HPS merge
//! of raw or grouped frames stays for calibration and raw captures.

use super::merge::Merger;
use super::{GroupGeometry, HdrError, LuminanceMap, MapFlag};
use crate::camera::DeviceConfig;
use crate::campaign::BayerPattern;
use rayon::prelude::*;
use skylux_regmap::hdr_values::HdrConfig;
use skylux_regmap::words::hdr_map;

/// One exposure of the set as the map's words name it by index.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct MapExposure {
    /// Integration time, seconds.
    pub exposure_s: f64,
    /// Analog gain.
    pub gain: f64,
}

/// A map as the fabric's DMA wrote it: one word per group, row pairs top to bottom.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FabricMap {
    /// Groups per row and rows of groups.
    pub width: usize,
    pub height: usize,
    pub words: Vec<u32>,
}

/// The luminance map of a fabric map. `exposures[k]` is the exposure of index `k` in the
/// sequence; `config` the `hdr.*` thresholds the fabric used. A group is valid when its word
/// is usable (the fabric's own rule, exact on the map word) and names an exposure of the set;
/// otherwise it is over-range when its word (the last exposure's) says so, else under-range.
pub fn fabric_map(
    map: &FabricMap,
    exposures: &[MapExposure],
    config: &HdrConfig,
    device: &DeviceConfig,
    pattern: BayerPattern,
    geometry: &GroupGeometry,
) -> Result<LuminanceMap, HdrError> {
    if exposures.is_empty() {
        return Err(HdrError::Empty);
    }
    if map.words.len() != map.width * map.height
        || (map.width, map.height) != (geometry.width, geometry.height)
    {
        return Err(HdrError::FrameSize {
            index: 0,
            width: 2 * map.width,
            height: 2 * map.height,
            expected_width: 2 * geometry.width,
            expected_height: 2 * geometry.height,
        });
    }
    for (index, e) in exposures.iter().enumerate() {
        for (field, value) in [("exposure_s", e.exposure_s), ("gain", e.gain)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(HdrError::BadExposure {
                    index,
                    field,
                    value,
                });
            }
        }
    }
    let merger = Merger::new(
        exposures.iter().map(|e| (e.exposure_s, e.gain)),
        device,
        pattern,
    );
    let n = map.words.len();
    let mut out = LuminanceMap {
        width: map.width,
        height: map.height,
        luminance_cd_m2: vec![f32::NAN; n],
        flags: vec![MapFlag::UnderRange; n],
        relative_sigma: vec![f32::NAN; n],
    };
    // Rows in parallel (the daemon's two cores; `timing::a9::hdr_fabric_map`).
    let width = map.width.max(1);
    out.luminance_cd_m2
        .par_chunks_mut(width)
        .zip(out.relative_sigma.par_chunks_mut(width))
        .zip(out.flags.par_chunks_mut(width))
        .zip(map.words.par_chunks(width))
        .zip(geometry.inverse_vignetting.par_chunks(width))
        .for_each(|((((luminance, sigma), flags), words), inv_vs)| {
            for (i, (&word, &inv_v)) in words.iter().zip(inv_vs).enumerate() {
                let k = usize::from(hdr_map::exposure_index(word));
                let single = (config.usable_map_word(word) && inv_v != 0.0)
                    .then(|| merger.single(k, hdr_map::luma(word), inv_v))
                    .flatten();
                match single {
                    Some((l, s)) => {
                        luminance[i] = l;
                        sigma[i] = s;
                        flags[i] = MapFlag::Valid;
                    }
                    None if hdr_map::over(word) => flags[i] = MapFlag::OverRange,
                    None => {}
                }
            }
        });
    Ok(out)
}

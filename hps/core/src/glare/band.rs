//! Luminance statistics of a horizontal band of the view (evalglare's `-B angle`): the pixels
//! within `angle` of the picture's middle row, column by column.

use super::pixels::PixelGrid;

/// The band's statistics as evalglare prints them on its `band:` line.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct BandStatistics {
    pub solid_angle_sr: f64,
    /// Mean luminance weighted by solid angle, cd/m².
    pub mean_luminance_cd_m2: f64,
    /// Median, standard deviation (population) and percentiles of the pixels' luminance,
    /// unweighted, cd/m².
    pub median_luminance_cd_m2: f64,
    pub std_luminance_cd_m2: f64,
    pub percentile_75_cd_m2: f64,
    pub percentile_95_cd_m2: f64,
    pub min_luminance_cd_m2: f64,
    pub max_luminance_cd_m2: f64,
}

/// The statistics of the valid pixels at most `half_width_rad` (plain angle) from the pixel
/// of their column on the middle row, that row included; None if the band holds no pixel.
pub fn band_statistics(
    grid: &PixelGrid,
    luminance: &[f64],
    half_width_rad: f64,
) -> Option<BandStatistics> {
    let middle = (grid.height_px - 1) / 2;
    let cos_half_width = half_width_rad.cos();
    let (mut omega, mut weighted) = (0.0, 0.0);
    let mut samples = Vec::new();
    for x in 0..grid.width_px {
        let centre = grid.index(x, middle);
        for y in 0..grid.height_px {
            let i = grid.index(x, y);
            if !grid.is_valid(i) {
                continue;
            }
            let near = grid.direction[centre].dot(grid.direction[i]) >= cos_half_width;
            if near || y == middle {
                omega += grid.solid_angle_sr[i];
                weighted += grid.solid_angle_sr[i] * luminance[i];
                samples.push(luminance[i]);
            }
        }
    }
    if samples.is_empty() || omega <= 0.0 {
        return None;
    }
    samples.sort_by(f64::total_cmp);
    let n = samples.len();
    let mean = samples.iter().sum::<f64>() / n as f64;
    let variance = samples.iter().map(|l| l * l).sum::<f64>() / n as f64 - mean * mean;
    Some(BandStatistics {
        solid_angle_sr: omega,
        mean_luminance_cd_m2: weighted / omega,
        median_luminance_cd_m2: median(&samples),
        std_luminance_cd_m2: variance.max(0.0).sqrt(),
        percentile_75_cd_m2: percentile(&samples, 0.75),
        percentile_95_cd_m2: percentile(&samples, 0.95),
        min_luminance_cd_m2: samples[0],
        max_luminance_cd_m2: samples[n - 1],
    })
}

/// The middle sample, or the mean of the two middle ones.
fn median(sorted: &[f64]) -> f64 {
    let n = sorted.len();
    if n.is_multiple_of(2) {
        (sorted[n / 2] + sorted[n / 2 - 1]) / 2.0
    } else {
        sorted[n / 2]
    }
}

/// evalglare's percentile (RADIANCE muc_randvar.c): the mean of the samples at indices
/// ⌊n p⌋ and ⌊n p − 1⌋ of the sorted samples.
fn percentile(sorted: &[f64], p: f64) -> f64 {
    let n = sorted.len() as f64;
    let upper = ((n * p) as usize).min(sorted.len() - 1);
    let lower = ((n * p - 1.0).max(0.0) as usize).min(sorted.len() - 1);
    (sorted[upper] + sorted[lower]) / 2.0
}

//! Summaries of relative errors (mean, median, 90th percentile of |error|, mean signed, RMS)
//! and log-binned luminance histograms.

use serde::Serialize;

/// Statistics of a set of relative errors (R − M)/M.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ErrorSummary {
    pub count: usize,
    pub mean_abs: f64,
    pub median_abs: f64,
    /// 90th percentile of |error| (nearest rank).
    pub p90_abs: f64,
    pub mean_signed: f64,
    pub rms: f64,
}

impl ErrorSummary {
    /// The summary of `errors` (all finite); None when there are none.
    pub fn of(errors: &[f64]) -> Option<ErrorSummary> {
        if errors.is_empty() {
            return None;
        }
        let n = errors.len() as f64;
        let mut abs: Vec<f64> = errors.iter().map(|e| e.abs()).collect();
        abs.sort_by(f64::total_cmp);
        Some(ErrorSummary {
            count: errors.len(),
            mean_abs: abs.iter().sum::<f64>() / n,
            median_abs: median_of_sorted(&abs),
            p90_abs: nearest_rank(&abs, 0.9),
            mean_signed: errors.iter().sum::<f64>() / n,
            rms: (errors.iter().map(|e| e * e).sum::<f64>() / n).sqrt(),
        })
    }
}

fn median_of_sorted(sorted: &[f64]) -> f64 {
    let n = sorted.len();
    if n % 2 == 1 {
        sorted[n / 2]
    } else {
        0.5 * (sorted[n / 2 - 1] + sorted[n / 2])
    }
}

/// Nearest-rank percentile: the smallest value with at least `q` of the values at or below.
fn nearest_rank(sorted: &[f64], q: f64) -> f64 {
    let rank = (q * sorted.len() as f64).ceil() as usize;
    sorted[rank.clamp(1, sorted.len()) - 1]
}

/// Luminance histogram in log bins: `edges_cd_m2` has one more entry than each count list.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LuminanceHistogram {
    pub edges_cd_m2: Vec<f64>,
    pub measured: Vec<usize>,
    pub rendered: Vec<usize>,
}

/// Bins per decade of the histogram.
const BINS_PER_DECADE: f64 = 4.0;

impl LuminanceHistogram {
    /// Both pictures' luminances over the compared pixels, binned from the lowest to the
    /// highest decade either reaches; None when there are no positive values.
    pub fn of(pairs: &[(f64, f64)]) -> Option<LuminanceHistogram> {
        let positive = pairs.iter().flat_map(|&(m, r)| [m, r]).filter(|&v| v > 0.0);
        let (lo, hi) = positive.fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
        if hi <= 0.0 || !lo.is_finite() {
            return None;
        }
        let first = (lo.log10() * BINS_PER_DECADE).floor();
        let last = (hi.log10() * BINS_PER_DECADE).floor() + 1.0;
        let bins = ((last - first) as usize).max(1);
        let edges_cd_m2 = (0..=bins)
            .map(|k| 10f64.powf((first + k as f64) / BINS_PER_DECADE))
            .collect();
        let bin = |v: f64| -> Option<usize> {
            (v > 0.0)
                .then(|| (((v.log10() * BINS_PER_DECADE).floor() - first) as usize).min(bins - 1))
        };
        let (mut measured, mut rendered) = (vec![0; bins], vec![0; bins]);
        for &(m, r) in pairs {
            if let Some(k) = bin(m) {
                measured[k] += 1;
            }
            if let Some(k) = bin(r) {
                rendered[k] += 1;
            }
        }
        Some(LuminanceHistogram {
            edges_cd_m2,
            measured,
            rendered,
        })
    }
}

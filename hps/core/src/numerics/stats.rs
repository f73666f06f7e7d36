//! Pearson's correlation and the least-squares slope, with one rule for the edge cases.

/// Pearson's correlation `r` of y with x and the least-squares slope of y on x.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pearson {
    pub r: f64,
    pub slope: f64,
}

/// Pearson's correlation and slope over the pairs whose two values are finite (the others are
/// left out). `None` with fewer than 3 such pairs or when x does not vary (neither is then
/// defined); `r` is 0 when y does not vary (x explains nothing of a constant).
pub fn pearson(xy: &[(f64, f64)]) -> Option<Pearson> {
    let finite = || {
        xy.iter()
            .copied()
            .filter(|(x, y)| x.is_finite() && y.is_finite())
    };
    let count = finite().count();
    if count < 3 {
        return None;
    }
    let n = count as f64;
    let (mx, my) = (
        finite().map(|p| p.0).sum::<f64>() / n,
        finite().map(|p| p.1).sum::<f64>() / n,
    );
    let (mut sxy, mut sxx, mut syy) = (0.0, 0.0, 0.0);
    for (x, y) in finite() {
        sxy += (x - mx) * (y - my);
        sxx += (x - mx).powi(2);
        syy += (y - my).powi(2);
    }
    if sxx <= 0.0 {
        return None;
    }
    let r = if syy > 0.0 {
        sxy / (sxx * syy).sqrt()
    } else {
        0.0
    };
    Some(Pearson {
        r,
        slope: sxy / sxx,
    })
}

/// Median and the standard error of the median (1.2533 σ/√n, σ from the MAD × 1.4826: the
/// normal-consistent constants); sorts `v`. NaN for an empty `v`.
pub fn median_and_standard_error(v: &mut [f64]) -> (f64, f64) {
    if v.is_empty() {
        return (f64::NAN, f64::NAN);
    }
    v.sort_by(f64::total_cmp);
    let med = v[v.len() / 2];
    let mut dev: Vec<f64> = v.iter().map(|x| (x - med).abs()).collect();
    dev.sort_by(f64::total_cmp);
    let sigma = 1.4826 * dev[dev.len() / 2];
    (med, 1.2533 * sigma / (v.len() as f64).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_correlates_fully() {
        let xy: Vec<(f64, f64)> = (0..10).map(|i| (i as f64, 3.0 - 2.0 * i as f64)).collect();
        let p = pearson(&xy).unwrap();
        assert!((p.r + 1.0).abs() < 1e-12);
        assert!((p.slope + 2.0).abs() < 1e-12);
    }

    /// The known value of a small hand-computed case: x 1 2 3 4, y 2 1 4 3 gives r = 0.6.
    #[test]
    fn hand_computed_case() {
        let p = pearson(&[(1.0, 2.0), (2.0, 1.0), (3.0, 4.0), (4.0, 3.0)]).unwrap();
        assert!((p.r - 0.6).abs() < 1e-12, "{}", p.r);
        assert!((p.slope - 0.6).abs() < 1e-12);
    }

    #[test]
    fn edge_cases() {
        assert!(pearson(&[(1.0, 1.0), (2.0, 2.0)]).is_none());
        assert!(pearson(&[(1.0, 1.0), (1.0, 2.0), (1.0, 3.0)]).is_none());
        let flat = pearson(&[(1.0, 5.0), (2.0, 5.0), (3.0, 5.0)]).unwrap();
        assert_eq!(flat.r, 0.0);
        // Non-finite pairs are left out, not propagated.
        let p = pearson(&[
            (1.0, 1.0),
            (f64::NAN, 9.0),
            (2.0, 2.0),
            (3.0, f64::INFINITY),
            (4.0, 4.0),
        ])
        .unwrap();
        assert!((p.r - 1.0).abs() < 1e-12);
    }
}

//! One-dimensional minimisation for the fits of a single parameter.

/// Golden-section search for a minimum of `f` between `a` and `b` (unimodal there), for
/// `iterations` steps, starting from `best` = (x, f(x)); returns the best (x, f(x)) seen.
/// Unimodality is the caller's claim; outside it the search still returns the best point seen.
pub fn golden_section(
    mut a: f64,
    mut b: f64,
    mut best: (f64, f64),
    iterations: usize,
    mut f: impl FnMut(f64) -> f64,
) -> (f64, f64) {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..iterations {
        let (x1, x2) = (b - g * (b - a), a + g * (b - a));
        let (e1, e2) = (f(x1), f(x2));
        if e1 < e2 {
            b = x2;
            if e1 < best.1 {
                best = (x1, e1);
            }
        } else {
            a = x1;
            if e2 < best.1 {
                best = (x2, e2);
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A parabola's minimum is found to the interval the iterations leave.
    #[test]
    fn finds_a_parabola_minimum() {
        let f = |x: f64| (x - 0.3).powi(2) + 2.0;
        let (x, fx) = golden_section(-1.0, 2.0, (2.0, f(2.0)), 40, f);
        assert!((x - 0.3).abs() < 1e-6, "{x}");
        assert!((fx - 2.0).abs() < 1e-12);
    }

    /// The starting point is kept when nothing better is seen.
    #[test]
    fn keeps_a_better_start() {
        let (x, fx) = golden_section(0.0, 1.0, (5.0, -1.0), 10, |x| x);
        assert_eq!((x, fx), (5.0, -1.0));
    }
}

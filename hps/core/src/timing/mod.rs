//! Wall-clock timing for the `bench` subcommands and the daemon's cycle budget, and the A9
//! cost model that budget sets beside its measurements ([`a9`]).

pub mod a9;

use std::time::Instant;

/// The median wall time of `repeat` runs of `f` (at least one), in milliseconds: the median
/// rather than the mean, so one run disturbed by the rest of the machine does not move it.
pub fn median_ms(repeat: usize, mut f: impl FnMut()) -> f64 {
    let mut times_ms: Vec<f64> = (0..repeat.max(1))
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    times_ms.sort_by(f64::total_cmp);
    times_ms[times_ms.len() / 2]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Zero repeats still time one run (no empty median), and the work runs that often.
    #[test]
    fn runs_at_least_once() {
        let mut runs = 0;
        let t = median_ms(0, || runs += 1);
        assert_eq!(runs, 1);
        assert!(t >= 0.0);
        median_ms(5, || runs += 1);
        assert_eq!(runs, 6);
    }
}

//! Fitting an HDR capture into the lens shield's open-time ceiling.
//!
//! The fabric guarantees the shield is never open longer than `seq.shield_limit` (at most
//! 0.55 s) per sequence, whatever software does. In electronic-rolling-shutter snapshot mode
//! every row gets the same exposure but the rows are offset by one row time, so light must
//! reach the sensor from the first row's reset to the last row's read: exposure plus readout
//! (hardware-facts.md §1.5). At full resolution and 96 MHz the readout alone is 1944 rows of
//! 3492 PIXCLK = 70.7 ms, so the five exposures of an HDR sky (1 µs to 500 ms) need about
//! 0.9 s of light: more than one opening allows.
//!
//! The decision: the hardware limit stays as it is (it protects the sensor from the sun), and
//! the HPS splits the capture into as few sequences as fit, in exposure order, each one
//! shield opening. An exposure that cannot fit even alone (500 ms plus a 70.7 ms full-frame
//! readout exceeds 0.55 s) is refused with the figures, never truncated by the hardware
//! mid-frame: the caller shortens it (raising the gain) or reads a smaller window.

/// What one shield opening costs besides the exposures.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct OpeningCost {
    /// Time to open plus time to close the shield (steps x step period, twice).
    pub motion_us: f64,
    /// Readout of one frame: rows x row time (hardware-facts.md §1.5).
    pub readout_us: f64,
    /// Fixed per-frame overhead between frames (trigger, I2C writes of the next exposure).
    pub per_frame_us: f64,
    /// The shield's open-time ceiling (`seq.shield_limit`).
    pub limit_us: f64,
}

impl OpeningCost {
    /// Light time a group of exposures needs in one opening.
    pub fn open_time_us(&self, exposures_us: &[f64]) -> f64 {
        self.motion_us
            + exposures_us
                .iter()
                .map(|e| e + self.readout_us + self.per_frame_us)
                .sum::<f64>()
    }

    /// Light time of a group of exposures whose frames are each followed by a gap (`gaps_us`,
    /// one per exposure): the sensor's vertical blanking beyond the one in `readout_us`, during
    /// which it holds the next trigger (hardware-facts.md §1.5: `VB_MIN = max(8, SW − H) + 1`
    /// rows, so a long exposure is followed by a long blanking). The last frame's gap is not
    /// in the opening: the shield closes once its readout ends.
    pub fn open_time_with_gaps_us(&self, exposures_us: &[f64], gaps_us: &[f64]) -> f64 {
        let n = exposures_us.len().saturating_sub(1);
        self.open_time_us(exposures_us) + gaps_us.iter().take(n).sum::<f64>()
    }
}

/// Why a capture cannot be planned.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ShieldPlanError {
    #[error("exposure {index} ({exposure_us} µs) needs {needed_us:.0} µs of open shield with its {readout_us:.0} µs readout and {motion_us:.0} µs of shield motion, over the {limit_us:.0} µs limit: shorten it to at most {max_exposure_us:.0} µs or read a smaller window")]
    TooLong {
        index: usize,
        exposure_us: f64,
        needed_us: f64,
        readout_us: f64,
        motion_us: f64,
        limit_us: f64,
        max_exposure_us: f64,
    },
    #[error("exposure {index} is {exposure_us} µs: not a finite positive time")]
    Invalid { index: usize, exposure_us: f64 },
    #[error("the opening costs are not finite non-negative times, or the limit is not positive")]
    BadCost,
}

/// Groups `exposures_us` (in order) into the fewest consecutive runs that each fit one
/// opening. Returns the runs as index ranges.
pub fn plan_openings(
    exposures_us: &[f64],
    cost: &OpeningCost,
) -> Result<Vec<std::ops::Range<usize>>, ShieldPlanError> {
    plan_openings_with_gaps(exposures_us, &[], cost)
}

/// [`plan_openings`] with the sensor's blanking gap after each frame
/// ([`OpeningCost::open_time_with_gaps_us`]); a missing gap counts as 0.
pub fn plan_openings_with_gaps(
    exposures_us: &[f64],
    gaps_us: &[f64],
    cost: &OpeningCost,
) -> Result<Vec<std::ops::Range<usize>>, ShieldPlanError> {
    if gaps_us.iter().any(|g| !(g.is_finite() && *g >= 0.0)) {
        return Err(ShieldPlanError::BadCost);
    }
    let gap = |r: std::ops::RangeInclusive<usize>| -> Vec<f64> {
        r.map(|k| gaps_us.get(k).copied().unwrap_or(0.0)).collect()
    };
    let ok = |v: f64| v.is_finite() && v >= 0.0;
    let costs_ok = ok(cost.motion_us) && ok(cost.readout_us) && ok(cost.per_frame_us);
    if !costs_ok || !cost.limit_us.is_finite() || cost.limit_us <= 0.0 {
        return Err(ShieldPlanError::BadCost);
    }
    let mut runs = Vec::new();
    let mut start = 0;
    for (i, &e) in exposures_us.iter().enumerate() {
        if !(e.is_finite() && e > 0.0) {
            return Err(ShieldPlanError::Invalid {
                index: i,
                exposure_us: e,
            });
        }
        let alone = cost.open_time_us(&[e]);
        if alone > cost.limit_us {
            return Err(ShieldPlanError::TooLong {
                index: i,
                exposure_us: e,
                needed_us: alone,
                readout_us: cost.readout_us,
                motion_us: cost.motion_us,
                limit_us: cost.limit_us,
                max_exposure_us: (cost.limit_us
                    - cost.motion_us
                    - cost.readout_us
                    - cost.per_frame_us)
                    .max(0.0),
            });
        }
        if cost.open_time_with_gaps_us(&exposures_us[start..=i], &gap(start..=i)) > cost.limit_us {
            runs.push(start..i);
            start = i;
        }
    }
    if start < exposures_us.len() {
        runs.push(start..exposures_us.len());
    }
    Ok(runs)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A long blanking after a frame is counted only when another frame of the same opening
    /// follows it.
    #[test]
    fn blanking_gaps_split_openings_but_not_after_the_last_frame() {
        let cost = OpeningCost {
            motion_us: 0.0,
            readout_us: 10.0,
            per_frame_us: 0.0,
            limit_us: 100.0,
        };
        let e = [20.0, 50.0];
        assert_eq!(plan_openings(&e, &cost).unwrap(), vec![0..2]);
        assert_eq!(
            plan_openings_with_gaps(&e, &[30.0, 500.0], &cost).unwrap(),
            vec![0..1, 1..2]
        );
        assert_eq!(
            plan_openings_with_gaps(&e, &[5.0, 500.0], &cost).unwrap(),
            vec![0..2]
        );
        assert_eq!(cost.open_time_with_gaps_us(&e, &[5.0, 500.0]), 95.0);
        assert_eq!(
            plan_openings_with_gaps(&e, &[f64::NAN], &cost),
            Err(ShieldPlanError::BadCost)
        );
    }

    /// Full frame at 96 MHz: 1944 rows x 3492 PIXCLK (hardware-facts.md §1.5); a 0.55 s
    /// limit; shield motion 2 x 20 ms.
    fn full_frame() -> OpeningCost {
        OpeningCost {
            motion_us: 40_000.0,
            readout_us: 1944.0 * 3492.0 / 96.0,
            per_frame_us: 100.0,
            limit_us: 550_000.0,
        }
    }

    #[test]
    fn the_published_500_ms_exposure_does_not_fit_a_full_frame_opening() {
        let e = [1.0, 20.0, 1_000.0, 30_000.0, 500_000.0];
        match plan_openings(&e, &full_frame()) {
            Err(ShieldPlanError::TooLong {
                index,
                max_exposure_us,
                ..
            }) => {
                assert_eq!(index, 4);
                // 550 - 40 - 70.7 - 0.1 ms.
                assert!(
                    (max_exposure_us - 439_187.0).abs() < 1.0,
                    "{max_exposure_us}"
                );
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn an_hdr_capture_splits_into_the_fewest_openings_that_fit() {
        let e = [1.0, 20.0, 1_000.0, 30_000.0, 400_000.0];
        let cost = full_frame();
        let runs = plan_openings(&e, &cost).unwrap();
        assert_eq!(runs, vec![0..4, 4..5]);
        for r in &runs {
            assert!(cost.open_time_us(&e[r.clone()]) <= cost.limit_us);
        }
        // A small window (100 rows of 972 PIXCLK) reads fast: one opening holds all five.
        let small = OpeningCost {
            readout_us: 100.0 * 972.0 / 96.0,
            ..cost
        };
        assert_eq!(plan_openings(&e, &small).unwrap(), vec![0..5]);
    }

    #[test]
    fn bad_input_is_refused_not_planned() {
        let cost = full_frame();
        assert!(matches!(
            plan_openings(&[1.0, f64::NAN], &cost),
            Err(ShieldPlanError::Invalid { index: 1, .. })
        ));
        assert!(matches!(
            plan_openings(
                &[1.0],
                &OpeningCost {
                    limit_us: 0.0,
                    ..cost
                }
            ),
            Err(ShieldPlanError::BadCost)
        ));
        assert_eq!(plan_openings(&[], &cost).unwrap(), vec![]);
    }
}

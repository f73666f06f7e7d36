//! The box test offloaded to the ray-box unit: each (ray, box) pair is quantised to the unit's
//! fixed-point grid (`skylux_regmap::raybox_format`) with outward rounding, so the unit's exact
//! integer answer is **conservative**: it may report a hit the f64 slab test misses by a
//! rounding margin (under 0.5 mm), never miss one, and its entry distance is never later.
//!
//! Why it is conservative (ARCHITECTURE.md, "Ray-box unit"): the unit tests exactly the ray
//! `o' + t d'` with `o'` the origin rounded to the grid and `d'_i = 1 / (mant_i 2^-shift_i)`,
//! against the box rounded outward and grown by `E_i` grid steps per axis. A point of the true
//! ray inside the true box, at a distance `t <= T` (`T` bounds every `t` that can reach the
//! box), lies within `|o'_i - o_i| + t |d'_i - d_i| <= 0.5 step + T |d'_i - d_i|` of the unit's
//! ray point at the same `t`, so it is inside the grown box when `E_i` covers that sum. The
//! entry and exit distances are rounded outward too, and `[t_min, t_max]` is widened.
//!
//! Pairs the format cannot hold (a coordinate beyond ±256 m, non-finite values, an empty box)
//! are answered by the software [`SlabTest`] instead, and counted.

use super::ray::RayBoxQuery;
use super::slab::{Aabb, BoxTest, SlabTest};
use crate::fpga::raybox::{ItemWords, RayBoxBackend, RayBoxError};
use skylux_regmap::raybox_format::{
    unpack_result, TestResult, WorkItem, COORD_FRAC_BITS, COORD_MAX, COORD_MIN, MANT_MAX,
    METRES_PER_STEP, SHIFT_MAX,
};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

/// Grid steps per metre.
const STEPS_PER_M: f64 = (1u64 << COORD_FRAC_BITS) as f64;
/// Extra growth of every box, in grid steps, beyond the proven bound: it absorbs the f64
/// rounding of the reference slab test itself (relative 2^-52 of distances under 1 km, so
/// far below 1e-9 m) and of the bound's own computation.
const SLACK_STEPS: f64 = 1.0 / 1024.0;
/// Smallest normalised mantissa magnitude (2^23): the relative error of the inverse
/// direction is then at most 2^-24.
const MANT_NORMAL: f64 = (1u64 << 23) as f64;

/// The inverse direction of one axis as (mantissa, shift), or `None` when it is zero (an
/// infinite direction component) or NaN.
pub fn encode_inverse(inv: f64) -> Option<(i32, u8)> {
    if inv.is_nan() || inv == 0.0 {
        return None;
    }
    let a = inv.abs();
    let max = MANT_MAX as f64;
    let (m, s) = if a >= max {
        // Near-parallel (or exactly parallel: inv = ±inf): the largest inverse the format
        // has. The direction error this leaves is bounded below like any other.
        (max, 0u8)
    } else {
        // Normalise: m = a 2^s in [2^23, 2^24).
        let mut s = (23 - a.log2().floor() as i64).clamp(0, SHIFT_MAX as i64);
        let mut m = (a * 2f64.powi(s as i32)).round();
        while m > max && s > 0 {
            s -= 1;
            m = (a * 2f64.powi(s as i32)).round();
        }
        while m < MANT_NORMAL && s < SHIFT_MAX as i64 {
            s += 1;
            m = (a * 2f64.powi(s as i32)).round();
        }
        if m < 1.0 || m > max {
            return None;
        }
        (m, s as u8)
    };
    let m = m as i32;
    Some((if inv < 0.0 { -m } else { m }, s))
}

/// The unit's work item for one (ray, box) pair, rounded so the unit's answer is
/// conservative; `None` when the format cannot hold the pair.
pub fn quantise(query: &RayBoxQuery, b: &Aabb) -> Option<WorkItem> {
    let o = query.origin_m;
    let (t_min, t_max) = (query.t_min_m, query.t_max_m);
    if !(o.is_finite() && b.min_m.is_finite() && b.max_m.is_finite()) {
        return None;
    }
    if t_min.is_nan() || t_max.is_nan() || !t_min.is_finite() || t_max < t_min {
        return None;
    }
    if b.min_m.cmpgt(b.max_m).any() {
        return None;
    }
    let mut item = WorkItem::default();
    let mut direction = [0.0f64; 3];
    let mut unit_direction = [0.0f64; 3];
    for axis in 0..3 {
        let inv = query.inverse_direction[axis];
        let (m, s) = encode_inverse(inv)?;
        item.mant[axis] = m;
        item.shift[axis] = s;
        direction[axis] = 1.0 / inv; // ±0 for an infinite inverse
        unit_direction[axis] = 2f64.powi(s as i32) / m as f64;
        let oq = (o[axis] * STEPS_PER_M).round();
        if oq < COORD_MIN as f64 || oq > COORD_MAX as f64 {
            return None;
        }
        item.origin[axis] = oq as i32;
    }
    let speed = direction.iter().map(|d| d * d).sum::<f64>().sqrt();
    if speed == 0.0 || !speed.is_finite() {
        return None;
    }
    // Every t at which the true ray can be inside the box: |p - o| = |t| |d| is at most the
    // distance from the origin to the box's farthest corner.
    let corner_m = (0..3)
        .map(|a| {
            let far = (b.min_m[a] - o[a]).abs().max((b.max_m[a] - o[a]).abs());
            far * far
        })
        .sum::<f64>()
        .sqrt();
    let t_bound = (corner_m / speed).min(t_max.abs().max(t_min.abs())) * (1.0 + 1e-12);
    for axis in 0..3 {
        let deviation_m = t_bound * (unit_direction[axis] - direction[axis]).abs();
        let grow = (0.5 + deviation_m * STEPS_PER_M * (1.0 + 1e-12) + SLACK_STEPS).ceil();
        let lo = (b.min_m[axis] * STEPS_PER_M).floor() - grow;
        let hi = (b.max_m[axis] * STEPS_PER_M).ceil() + grow;
        if !(lo >= COORD_MIN as f64 && hi <= COORD_MAX as f64) {
            return None;
        }
        let (lo, hi) = (lo as i32, hi as i32);
        let (entry, exit) = if item.mant[axis] > 0 {
            (lo, hi)
        } else {
            (hi, lo)
        };
        item.entry_plane[axis] = entry;
        item.exit_plane[axis] = exit;
    }
    item.t_min = ((t_min * STEPS_PER_M).floor() - 1.0).max(i32::MIN as f64) as i32;
    item.t_max = if t_max.is_finite() {
        ((t_max * STEPS_PER_M).ceil() + 1.0).min(i32::MAX as f64) as i32
    } else {
        i32::MAX
    };
    Some(item)
}

/// The entry distance (metres) a result stands for: a miss is `INFINITY`; a hit's distance is
/// rounded down by the unit and raised to `t_min_m`, so it is never after the true entry.
pub fn entry_m(query: &RayBoxQuery, result: TestResult) -> f64 {
    if !result.hit {
        return f64::INFINITY;
    }
    (result.t_near as f64 * METRES_PER_STEP).max(query.t_min_m)
}

/// Counts of what the accelerated test did.
#[derive(Debug, Default)]
pub struct AccelStats {
    /// Pairs the unit (or its model) answered.
    pub offloaded: AtomicU64,
    /// Pairs the format could not hold, answered in software.
    pub fallbacks: AtomicU64,
    /// Batches the backend failed; they were answered in software.
    pub failed_batches: AtomicU64,
}

/// A [`BoxTest`] that sends its pairs to a [`RayBoxBackend`].
pub struct AcceleratedBoxTest<B: RayBoxBackend> {
    backend: Mutex<B>,
    pub stats: AccelStats,
    /// The last backend error, kept so a caller can report the fault it survived.
    pub last_error: Mutex<Option<String>>,
}

impl<B: RayBoxBackend> AcceleratedBoxTest<B> {
    pub fn new(backend: B) -> Self {
        Self {
            backend: Mutex::new(backend),
            stats: AccelStats::default(),
            last_error: Mutex::new(None),
        }
    }

    /// Runs a batch through the backend; `None` (and the error kept) if it failed.
    fn offload(&self, items: &[ItemWords]) -> Option<Vec<u64>> {
        let mut results = Vec::with_capacity(items.len());
        let outcome: Result<(), RayBoxError> = match self.backend.lock() {
            Ok(mut b) => b.run(items, &mut results),
            Err(_) => Err(RayBoxError::NoCompletion { polls: 0 }),
        };
        match outcome {
            Ok(()) if results.len() == items.len() => Some(results),
            Ok(()) => {
                self.fail(format!(
                    "{} results for {} items",
                    results.len(),
                    items.len()
                ));
                None
            }
            Err(e) => {
                self.fail(e.to_string());
                None
            }
        }
    }

    fn fail(&self, why: String) {
        self.stats.failed_batches.fetch_add(1, Ordering::Relaxed);
        if let Ok(mut e) = self.last_error.lock() {
            *e = Some(why);
        }
    }
}

impl<B: RayBoxBackend> BoxTest for AcceleratedBoxTest<B> {
    fn hits(&self, ray: &RayBoxQuery, boxes: &[Aabb], entry: &mut [f64]) {
        let mut items = Vec::with_capacity(boxes.len());
        let mut slots = Vec::with_capacity(boxes.len());
        for (k, b) in boxes.iter().enumerate() {
            match quantise(ray, b) {
                Some(item) => {
                    items.push(item.pack());
                    slots.push(k);
                }
                None => {
                    self.stats.fallbacks.fetch_add(1, Ordering::Relaxed);
                    entry[k] = SlabTest::entry(ray, b).unwrap_or(f64::INFINITY);
                }
            }
        }
        if items.is_empty() {
            return;
        }
        match self.offload(&items) {
            Some(results) => {
                self.stats
                    .offloaded
                    .fetch_add(items.len() as u64, Ordering::Relaxed);
                for (&k, &word) in slots.iter().zip(&results) {
                    entry[k] = entry_m(ray, unpack_result(word).1);
                }
            }
            None => {
                for &k in &slots {
                    entry[k] = SlabTest::entry(ray, &boxes[k]).unwrap_or(f64::INFINITY);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::ray::Ray;
    use crate::fpga::raybox::GoldenRayBox;
    use glam::DVec3;
    use skylux_regmap::raybox_format::test as golden;

    #[test]
    fn inverse_encoding_relative_error() {
        for inv in [1.0, -1.0, 1.5, 3.0e-7, -7.7e5, 16_777_214.0, 1.0 / 0.577] {
            let (m, s) = encode_inverse(inv).unwrap();
            let back = m as f64 / 2f64.powi(s as i32);
            assert!(
                ((back - inv) / inv).abs() <= 2f64.powi(-24),
                "{inv}: {m} {s}"
            );
            assert!(m.unsigned_abs() >= 1 << 23, "{inv} not normalised: {m}");
        }
        assert_eq!(encode_inverse(f64::INFINITY), Some((MANT_MAX, 0)));
        assert_eq!(encode_inverse(f64::NEG_INFINITY), Some((-MANT_MAX, 0)));
        assert_eq!(encode_inverse(0.0), None);
        assert_eq!(encode_inverse(f64::NAN), None);
    }

    #[test]
    fn axis_ray_through_a_millimetre_box() {
        let q = RayBoxQuery::new(&Ray::new(DVec3::new(-3.0, 0.2, 0.1), DVec3::X), 0.0, 1e3);
        let b = Aabb {
            min_m: DVec3::new(1.0, 0.1995, 0.0995),
            max_m: DVec3::new(1.001, 0.2005, 0.1005),
        };
        let r = golden(&quantise(&q, &b).unwrap());
        assert!(r.hit);
        let e = entry_m(&q, r);
        assert!(e <= 4.0 && e > 4.0 - 0.001, "{e}");
        // 2 mm beside it in y: a miss.
        let beside = Aabb {
            min_m: b.min_m + DVec3::Y * 0.002,
            max_m: b.max_m + DVec3::Y * 0.002,
        };
        assert!(!golden(&quantise(&q, &beside).unwrap()).hit);
    }

    #[test]
    fn out_of_range_pairs_fall_back_to_software() {
        let q = RayBoxQuery::new(&Ray::new(DVec3::ZERO, DVec3::X), 0.0, f64::INFINITY);
        let far = Aabb {
            min_m: DVec3::new(300.0, -1.0, -1.0),
            max_m: DVec3::new(301.0, 1.0, 1.0),
        };
        assert!(quantise(&q, &far).is_none());
        let t = AcceleratedBoxTest::new(GoldenRayBox);
        let mut e = [0.0; 2];
        let near = Aabb {
            min_m: DVec3::new(3.0, -1.0, -1.0),
            max_m: DVec3::new(4.0, 1.0, 1.0),
        };
        t.hits(&q, &[far, near], &mut e);
        assert_eq!(e[0], 300.0);
        assert!(e[1] <= 3.0 && e[1] > 2.999);
        assert_eq!(t.stats.fallbacks.load(Ordering::Relaxed), 1);
        assert_eq!(t.stats.offloaded.load(Ordering::Relaxed), 1);
    }
}

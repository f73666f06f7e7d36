//! The lux-meters' side of the loop: each capture with the readings at its time, and the
//! logger's series around it (what a clock offset re-matches).

use super::split::Timed;
use crate::campaign::Campaign;
use chrono::{TimeDelta, Utc};
use std::collections::BTreeMap;

/// Widest logger clock offset the loop considers, seconds: ±30 min. A logger set by hand
/// drifts by minutes a month (a quartz clock's 20-50 ppm is 1-2 min a month); one left on
/// the wrong daylight-saving zone is an hour off, which no scan over a day of hourly captures
/// can tell from the weather and is for the user to declare.
pub const MAX_CLOCK_OFFSET_S: f64 = 1800.0;

/// Half-width of the logger series kept around each capture, seconds: the widest clock
/// offset plus the ±60 s over which a rate of change is read, and a margin.
pub const SERIES_HALF_WINDOW_S: f64 = MAX_CLOCK_OFFSET_S + 2.0 * 60.0;

/// One fit-set sample: a capture and the lux-meter readings at its time.
#[derive(Clone, Debug)]
pub struct Sample {
    pub capture: usize,
    pub time_utc: chrono::DateTime<chrono::Utc>,
    /// Per sensor (in the room's order); `None` where no reading matched.
    pub measured_lux: Vec<Option<f64>>,
    /// Per sensor, the logger's readings near the capture: (logger timestamp − capture time,
    /// seconds; lux), in time order. What the clock-offset effect re-matches.
    pub series: Vec<Vec<(f64, f64)>>,
}

/// Longest gap between two logger readings across which a reading is interpolated, s.
pub const MAX_INTERPOLATION_GAP_S: f64 = 150.0;

/// The logger's reading at `at_s` (seconds from the capture, logger clock), linearly
/// interpolated between the two readings around it; `None` outside the series or across a
/// gap longer than [`MAX_INTERPOLATION_GAP_S`].
pub fn interpolate(series: &[(f64, f64)], at_s: f64) -> Option<f64> {
    let i = series.partition_point(|(t, _)| *t < at_s);
    if i < series.len() && series[i].0 == at_s {
        return Some(series[i].1);
    }
    if i == 0 || i == series.len() {
        return None;
    }
    let ((t0, v0), (t1, v1)) = (series[i - 1], series[i]);
    if t1 - t0 > MAX_INTERPOLATION_GAP_S || t1 <= t0 {
        return None;
    }
    Some(v0 + (v1 - v0) * (at_s - t0) / (t1 - t0))
}

/// Relative rate of change of a logger series at `at_s`, per minute: the slope of the
/// readings within ±60 s (least squares) over their mean. NaN with fewer than 2 readings.
pub fn relative_rate_per_min(series: &[(f64, f64)], at_s: f64) -> f64 {
    let near: Vec<(f64, f64)> = series
        .iter()
        .copied()
        .filter(|(t, _)| (t - at_s).abs() <= 60.0 + 1e-9)
        .collect();
    if near.len() < 2 {
        return f64::NAN;
    }
    let n = near.len() as f64;
    let (mt, mv) = (
        near.iter().map(|p| p.0).sum::<f64>() / n,
        near.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let (sxy, sxx) = near.iter().fold((0.0, 0.0), |(a, b), (t, v)| {
        (a + (t - mt) * (v - mv), b + (t - mt).powi(2))
    });
    if sxx <= 0.0 || mv <= 0.0 {
        return f64::NAN;
    }
    60.0 * sxy / sxx / mv
}

impl Sample {
    /// Sensor `k`'s reading of the light at the capture time for a logger clock running
    /// `clock_offset_s` ahead of the device's: the matched reading without an offset, else
    /// the series interpolated at the offset.
    pub fn measured(&self, k: usize, clock_offset_s: f64) -> Option<f64> {
        if clock_offset_s == 0.0 {
            return self.measured_lux.get(k).copied().flatten();
        }
        interpolate(self.series.get(k)?, clock_offset_s)
    }
}

impl Timed for Sample {
    fn time_utc(&self) -> chrono::DateTime<chrono::Utc> {
        self.time_utc
    }
}

/// The item whose time offset (item minus target) is smallest in magnitude and within
/// `window`: the one rule by which readings are matched to capture times.
pub fn nearest_in_time<'a, T>(
    items: impl IntoIterator<Item = &'a T>,
    window: TimeDelta,
    offset: impl Fn(&T) -> TimeDelta,
) -> Option<&'a T> {
    items
        .into_iter()
        .filter(|r| offset(r).abs() <= window)
        .min_by_key(|r| offset(r).abs())
}

/// The lux-meter `sensor`'s reading nearest to `time` within `window`.
pub fn reading_at<Tz: chrono::TimeZone>(
    campaign: &Campaign,
    sensor: &str,
    time: chrono::DateTime<Tz>,
    window: TimeDelta,
) -> Option<f64> {
    nearest_in_time(
        campaign.luxmeters.iter().filter(|r| r.sensor == sensor),
        window,
        |r| r.time.signed_duration_since(time.clone()),
    )
    .map(|r| r.illuminance_lux)
}

/// The lux-meter readings per sensor in time order, for the series around each capture.
pub struct LoggerSeries {
    by_sensor: BTreeMap<String, Vec<(chrono::DateTime<Utc>, f64)>>,
}

impl LoggerSeries {
    pub fn new(campaign: &Campaign) -> Self {
        let mut by_sensor: BTreeMap<String, Vec<(chrono::DateTime<Utc>, f64)>> = BTreeMap::new();
        for r in &campaign.luxmeters {
            by_sensor
                .entry(r.sensor.clone())
                .or_default()
                .push((r.time.with_timezone(&Utc), r.illuminance_lux));
        }
        for v in by_sensor.values_mut() {
            v.sort_by_key(|p| p.0);
        }
        Self { by_sensor }
    }

    /// `sensor`'s readings within `half_window_s` of `time`: (seconds from `time`, lux).
    pub fn around<Tz: chrono::TimeZone>(
        &self,
        sensor: &str,
        time: chrono::DateTime<Tz>,
        half_window_s: f64,
    ) -> Vec<(f64, f64)> {
        let Some(v) = self.by_sensor.get(sensor) else {
            return Vec::new();
        };
        let t = time.with_timezone(&Utc);
        let half = TimeDelta::milliseconds((half_window_s * 1000.0) as i64);
        let start = v.partition_point(|p| p.0 < t - half);
        v[start..]
            .iter()
            .take_while(|p| p.0 <= t + half)
            .map(|p| ((p.0 - t).num_milliseconds() as f64 / 1000.0, p.1))
            .collect()
    }
}

//! When a capture is raw (issue 22 item 3). In map mode (`[fabric] hdr = "fabric"`, the
//! default) the fabric writes one HDR map per capture and nothing raw exists to keep; raw
//! frames, merged on the HPS and kept in campaign format, are what calibration and audits
//! need (the loop's captures, a check of the fabric's map against the HPS merge). So a capture
//! is raw on a cadence (`[fabric] raw_every_s`, in capture time) or on request (SIGUSR1,
//! which asks for the next one), and a request stays pending until a raw capture succeeds.

use chrono::{DateTime, FixedOffset};

/// The raw-capture schedule of one daemon run.
#[derive(Clone, Debug, Default)]
pub struct RawSchedule {
    /// `[fabric] raw_every_s` (None: on request only).
    every_s: Option<f64>,
    /// Where the cadence counts from: the last successful raw capture, or the first cycle.
    anchor: Option<DateTime<FixedOffset>>,
    /// A request (SIGUSR1) not yet served by a successful raw capture.
    requested: bool,
}

/// Why the capture at hand is raw.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum RawReason {
    /// `raw_every_s` has passed since the last raw capture.
    Cadence,
    /// Asked for by SIGUSR1.
    Request,
}

impl RawSchedule {
    pub fn new(every_s: Option<f64>) -> Self {
        RawSchedule {
            every_s,
            ..Default::default()
        }
    }

    /// A new cadence after a configuration reload (the anchor and a pending request stay).
    pub fn set_every_s(&mut self, every_s: Option<f64>) {
        self.every_s = every_s;
    }

    /// Records a request (SIGUSR1): the next capture is raw.
    pub fn request(&mut self) {
        self.requested = true;
    }

    /// Whether the capture at `at` is to be raw, and why (`None`: a map). When the source
    /// makes no maps (`hdr = "hps"`, or the simulated camera) every capture is raw anyway and
    /// nothing is scheduled. A clock that stepped back
    /// before the anchor restarts the cadence there, so a wrong clock cannot hold raw
    /// captures back for longer than one cadence after it is right again.
    pub fn due(&mut self, makes_maps: bool, at: DateTime<FixedOffset>) -> Option<RawReason> {
        if !makes_maps {
            return None;
        }
        let anchor = *self.anchor.get_or_insert(at);
        if at < anchor {
            self.anchor = Some(at);
        }
        if self.requested {
            return Some(RawReason::Request);
        }
        let every_s = self.every_s?;
        let elapsed_s = (at - anchor).num_milliseconds() as f64 * 1e-3;
        (elapsed_s >= every_s).then_some(RawReason::Cadence)
    }

    /// A raw capture at `at` succeeded: the request is served and the cadence restarts.
    pub fn taken(&mut self, at: DateTime<FixedOffset>) {
        self.requested = false;
        self.anchor = Some(at);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn t(minutes: i64) -> DateTime<FixedOffset> {
        DateTime::parse_from_rfc3339("2017-05-08T10:00:00+02:00").unwrap()
            + chrono::TimeDelta::minutes(minutes)
    }

    #[test]
    fn the_cadence_counts_from_the_first_cycle_then_from_each_raw_capture() {
        let mut s = RawSchedule::new(Some(3600.0));
        let due: Vec<bool> = (0..=130)
            .map(|m| {
                let r = s.due(true, t(m));
                if r.is_some() {
                    s.taken(t(m));
                }
                r.is_some()
            })
            .collect();
        let raw: Vec<usize> = (0..due.len()).filter(|&m| due[m]).collect();
        assert_eq!(raw, vec![60, 120]);
    }

    #[test]
    fn a_request_waits_for_a_successful_raw_capture() {
        let mut s = RawSchedule::new(None);
        assert_eq!(s.due(true, t(0)), None, "no cadence: maps only");
        s.request();
        assert_eq!(s.due(true, t(1)), Some(RawReason::Request));
        // The raw capture failed: still pending.
        assert_eq!(s.due(true, t(2)), Some(RawReason::Request));
        s.taken(t(2));
        assert_eq!(s.due(true, t(3)), None);
        assert_eq!(s.due(true, t(10_000)), None);
    }

    #[test]
    fn no_maps_schedule_nothing_and_a_clock_step_back_restarts_the_cadence() {
        let mut s = RawSchedule::new(Some(600.0));
        s.request();
        assert_eq!(s.due(false, t(0)), None);
        let mut s = RawSchedule::new(Some(600.0));
        assert_eq!(s.due(true, t(120)), None);
        // Two hours back: the cadence counts from there.
        assert_eq!(s.due(true, t(0)), None);
        assert_eq!(s.due(true, t(9)), None);
        assert_eq!(s.due(true, t(10)), Some(RawReason::Cadence));
    }
}

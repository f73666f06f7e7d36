//! Test-only pauses inside the cycle's writes, so that a crash test can kill `skyluxd` at a
//! chosen point of a write on purpose rather than by luck (`tests/faults.rs`).
//!
//! `SKYLUX_TEST_WRITE_PAUSE=<point>:<ms>[:<nth>]`, read once: at the `nth` (default 1st)
//! time the daemon reaches `point`, it logs `test write pause: inside the write` with the
//! point and the cycle's time, sleeps `ms`, then logs `test write pause: resumed`. Inert when
//! the variable is absent; a malformed value is logged as an error and ignored. Never set it
//! on a device.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::OnceLock;
use std::time::Duration;

/// The environment variable.
pub const VARIABLE: &str = "SKYLUX_TEST_WRITE_PAUSE";

/// The points inside a cycle's writes, in the order a cycle reaches them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WritePoint {
    /// An EXR map or view picture written and synced, before its rename.
    Map,
    /// The capture folder in the spool with its first frame written.
    CaptureFrames,
    /// The capture folder complete in the spool, before its rename.
    CaptureRename,
    /// Half of the record's line appended to `results.jsonl`.
    Jsonl,
    /// The first of the cycle's rows appended to `illuminance.csv`.
    Csv,
    /// The new `latest.json` written and synced, before its rename.
    Latest,
    /// The cycle on disk, before retention deletes the oldest maps and captures.
    Retention,
}

impl WritePoint {
    pub const ALL: [WritePoint; 7] = [
        WritePoint::Map,
        WritePoint::CaptureFrames,
        WritePoint::CaptureRename,
        WritePoint::Jsonl,
        WritePoint::Csv,
        WritePoint::Latest,
        WritePoint::Retention,
    ];

    /// The name used in the variable and the log.
    pub fn name(self) -> &'static str {
        match self {
            WritePoint::Map => "map",
            WritePoint::CaptureFrames => "capture_frames",
            WritePoint::CaptureRename => "capture_rename",
            WritePoint::Jsonl => "jsonl",
            WritePoint::Csv => "csv",
            WritePoint::Latest => "latest",
            WritePoint::Retention => "retention",
        }
    }

    /// Whether a kill here comes after the record's line is complete in `results.jsonl`
    /// (the cycle's commit point): the record must then survive the crash.
    pub fn after_commit(self) -> bool {
        matches!(
            self,
            WritePoint::Csv | WritePoint::Latest | WritePoint::Retention
        )
    }

    /// Where an append paused at this point is split: mid-line for the record, after the
    /// first row for the CSV.
    pub fn split(self, bytes: &[u8]) -> usize {
        match self {
            WritePoint::Csv => bytes
                .iter()
                .position(|&b| b == b'\n')
                .map_or(bytes.len() / 2, |i| i + 1),
            _ => bytes.len() / 2,
        }
    }
}

/// A parsed `SKYLUX_TEST_WRITE_PAUSE`.
#[derive(Debug, PartialEq)]
struct Pause {
    point: WritePoint,
    ms: u64,
    nth: u64,
}

fn parse(value: &str) -> Result<Pause, String> {
    let mut parts = value.split(':');
    let name = parts.next().unwrap_or_default();
    let point = WritePoint::ALL
        .into_iter()
        .find(|p| p.name() == name)
        .ok_or_else(|| format!("unknown point {name:?}"))?;
    let number = |what: &str, part: Option<&str>, default: Option<u64>| match (part, default) {
        (Some(s), _) => s.parse::<u64>().map_err(|e| format!("{what} {s:?}: {e}")),
        (None, Some(d)) => Ok(d),
        (None, None) => Err(format!("{what} missing")),
    };
    let ms = number("ms", parts.next(), None)?;
    let nth = number("nth", parts.next(), Some(1))?.max(1);
    if parts.next().is_some() {
        return Err("expected <point>:<ms>[:<nth>]".into());
    }
    Ok(Pause { point, ms, nth })
}

fn armed() -> Option<&'static Pause> {
    static PAUSE: OnceLock<Option<Pause>> = OnceLock::new();
    PAUSE
        .get_or_init(|| {
            let value = std::env::var(VARIABLE).ok()?;
            parse(&value)
                .map_err(|e| tracing::error!("{VARIABLE}={value:?} ignored: {e}"))
                .ok()
        })
        .as_ref()
}

/// Whether a pause is armed for `point` (appends split their write only then).
pub fn is_armed(point: WritePoint) -> bool {
    armed().is_some_and(|p| p.point == point)
}

/// Pauses here if the variable asks for it (see the module's doc).
pub fn at(point: WritePoint, time: &str) {
    static REACHED: AtomicU64 = AtomicU64::new(0);
    let Some(pause) = armed().filter(|p| p.point == point) else {
        return;
    };
    if REACHED.fetch_add(1, Ordering::Relaxed) + 1 != pause.nth {
        return;
    }
    tracing::warn!(
        point = point.name(),
        time,
        pause_ms = pause.ms,
        "test write pause: inside the write"
    );
    std::thread::sleep(Duration::from_millis(pause.ms));
    tracing::warn!(point = point.name(), time, "test write pause: resumed");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_variable_is_parsed_or_refused() {
        assert_eq!(
            parse("jsonl:250"),
            Ok(Pause {
                point: WritePoint::Jsonl,
                ms: 250,
                nth: 1
            })
        );
        assert_eq!(parse("csv:10:3").map(|p| p.nth), Ok(3));
        for bad in ["", "jsonl", "nowhere:10", "map:x", "map:1:2:3", "map:-1"] {
            assert!(parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn splits_fall_inside_the_write() {
        assert_eq!(WritePoint::Jsonl.split(b"{\"a\":1}\n"), 4);
        assert_eq!(WritePoint::Csv.split(b"t,S1,1,,hdr\nt,S2,2,,hdr\n"), 12);
        assert_eq!(WritePoint::Csv.split(b"t,S1"), 2);
    }
}

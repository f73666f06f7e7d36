//! Start-up repair of what a crash (SIGKILL, power cut) left in the output directory, so
//! that every completed cycle's record is present exactly once and whole, and nothing of an
//! uncompleted one stays behind.
//!
//! A cycle commits when its line in `results.jsonl` is complete (`output.rs` writes the
//! pictures and the capture before it, the CSV rows and `latest.json` after it). So:
//! - before the commit, the cycle's pictures and capture are orphans: the stamp in
//!   `spool/cycle.pending` names them, and they are deleted unless the last record has that
//!   stamp;
//! - after it, the CSV rows and `latest.json` may be missing or stale: they are rebuilt from
//!   the last record (the record is the truth, the others are indexes of it).

use super::{
    err, latest_bytes, write_atomic, LineLog, Output, OutputError, Recovery, CAPTURES_DIR,
    LATEST_FILE, MAPS_DIR, SPOOL_DIR, TMP_SUFFIX, VIEWS_DIR,
};
use crate::cycle::CycleRecord;
use std::path::Path;

/// The journal of the cycle being written: its stamp, in the spool.
pub const PENDING_FILE: &str = "cycle.pending";

/// The stamp of a cycle that was being written when the daemon stopped, if any.
pub fn pending_stamp(dir: &Path) -> Option<String> {
    let text = std::fs::read_to_string(dir.join(SPOOL_DIR).join(PENDING_FILE)).ok()?;
    let stamp = text.trim();
    // A stamp is `YYYYMMDDTHHMMSSZ` (or `unknown`): never a path.
    (!stamp.is_empty() && stamp.chars().all(|c| c.is_ascii_alphanumeric()))
        .then(|| stamp.to_string())
}

/// Removes stale temporaries (`.name.tmp`) and everything in the spool.
pub fn remove_leftovers(dir: &Path, recovery: &mut Recovery) -> Result<(), OutputError> {
    for d in [dir.to_path_buf(), dir.join(MAPS_DIR), dir.join(VIEWS_DIR)] {
        for entry in std::fs::read_dir(&d).map_err(err(&d, "list"))?.flatten() {
            let name = entry.file_name().to_string_lossy().into_owned();
            if name.starts_with('.')
                && name.ends_with(TMP_SUFFIX)
                && std::fs::remove_file(entry.path()).is_ok()
            {
                recovery.stale_files_removed += 1;
            }
        }
    }
    let spool = dir.join(SPOOL_DIR);
    for entry in std::fs::read_dir(&spool)
        .map_err(err(&spool, "list"))?
        .flatten()
    {
        if remove_path(&entry.path()) {
            recovery.stale_files_removed += 1;
        }
    }
    Ok(())
}

/// Deletes a file or a folder; whether it was there and is gone.
fn remove_path(p: &Path) -> bool {
    let removed = if p.is_dir() {
        std::fs::remove_dir_all(p)
    } else {
        std::fs::remove_file(p)
    };
    removed.is_ok()
}

/// The repair after the logs' partial lines are gone: orphans of `pending`, then the last
/// record's CSV rows and `latest.json`. Returns the last record (`None`: none, or it does not
/// parse).
pub fn after_crash(
    output: &mut Output,
    pending: Option<&str>,
    recovery: &mut Recovery,
) -> Result<Option<CycleRecord>, OutputError> {
    let last = match last_record(&mut output.results) {
        Ok(last) => last,
        Err(reason) => {
            recovery.last_record_unreadable = Some(reason);
            return Ok(None);
        }
    };
    let last_stamp = last.as_ref().map(|r| Output::stamp(&r.time));
    if let Some(stamp) = pending.filter(|s| Some(*s) != last_stamp.as_deref()) {
        recovery.orphan_files_removed = remove_cycle_files(&output.dir, stamp);
    }
    let Some(last) = last else {
        return Ok(None);
    };
    recovery.csv_rows_rebuilt = rebuild_csv_rows(&mut output.csv, &last)?;
    recovery.latest_rebuilt = rebuild_latest(&output.dir, &last)?;
    Ok(Some(last))
}

/// The last complete record of `results.jsonl` (`None`: the log is empty), or why it does not
/// parse.
fn last_record(results: &mut LineLog) -> Result<Option<CycleRecord>, String> {
    let tail = results.tail_lines(1).map_err(|e| e.to_string())?;
    let Some((start, line)) = tail.into_iter().next() else {
        return Ok(None);
    };
    serde_json::from_slice(&line).map(Some).map_err(|e| {
        format!(
            "{}: the record at byte {start} does not parse: {e}",
            results.path.display()
        )
    })
}

/// Deletes the map, view pictures and capture folder named by `stamp`; how many.
fn remove_cycle_files(dir: &Path, stamp: &str) -> usize {
    let mut removed = usize::from(remove_path(
        &dir.join(MAPS_DIR).join(format!("{stamp}.exr")),
    ));
    removed += usize::from(remove_path(&dir.join(CAPTURES_DIR).join(stamp)));
    let views = dir.join(VIEWS_DIR);
    let prefix = format!("{stamp}-");
    if let Ok(listing) = std::fs::read_dir(&views) {
        for entry in listing.flatten() {
            let name = entry.file_name().to_string_lossy().into_owned();
            if name.starts_with(&prefix) && remove_path(&entry.path()) {
                removed += 1;
            }
        }
    }
    removed
}

/// Makes the CSV end with exactly the last record's rows: the rows of its time at the end
/// (with anything after them, a cycle whose rollback failed) are replaced by the record's
/// own; when they are absent (the crash came before the first row) they are appended.
/// Whether anything changed.
fn rebuild_csv_rows(csv: &mut LineLog, last: &CycleRecord) -> Result<bool, OutputError> {
    let expected = super::csv_rows(last);
    // The record's rows, and at most one other cycle's after them.
    let window = 2 * last.illuminance.len() + 1;
    let tail = csv.tail_lines(window)?;
    let prefix = format!("{},", last.time);
    let last_own = tail
        .iter()
        .rposition(|(_, l)| l.starts_with(prefix.as_bytes()));
    let cut = match last_own {
        Some(i) => {
            let first_own = tail[..=i]
                .iter()
                .rposition(|(_, l)| !l.starts_with(prefix.as_bytes()))
                .map_or(0, |j| j + 1);
            tail[first_own].0
        }
        None => csv.len(),
    };
    let present: Vec<u8> = tail
        .iter()
        .filter(|(start, _)| *start >= cut)
        .flat_map(|(_, l)| l.iter().copied())
        .collect();
    if present == expected.as_bytes() {
        return Ok(false);
    }
    csv.cut(cut)?;
    csv.append(expected.as_bytes())?;
    Ok(true)
}

/// Rewrites `latest.json` from the last record when it is missing, unreadable or another
/// record. Whether it did.
fn rebuild_latest(dir: &Path, last: &CycleRecord) -> Result<bool, OutputError> {
    let path = dir.join(LATEST_FILE);
    let current: Option<CycleRecord> = std::fs::read(&path)
        .ok()
        .and_then(|b| serde_json::from_slice(&b).ok());
    if current.as_ref() == Some(last) {
        return Ok(false);
    }
    write_atomic(&path, &latest_bytes(last))?;
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::super::{CSV_FILE, CSV_HEADER, RESULTS_FILE};
    use super::*;

    fn record(time: &str, lux: &[f64]) -> CycleRecord {
        let mut r = super::super::tests::record(time);
        r.illuminance = lux
            .iter()
            .enumerate()
            .map(|(i, &lux)| crate::cycle::SensorLux {
                sensor: format!("S{}", i + 1),
                lux,
                stderr_lux: None,
            })
            .collect();
        r
    }

    fn line(r: &CycleRecord) -> String {
        format!("{}\n", serde_json::to_string(r).unwrap())
    }

    /// A crash between the record and its rows: the rows are rebuilt, once, with any rows of
    /// a later, uncommitted cycle dropped; `latest.json` follows the record.
    #[test]
    fn rows_and_latest_are_rebuilt_from_the_last_record() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (
            record("2017-05-08T10:00:00+02:00", &[1.0, 2.0]),
            record("2017-05-08T11:00:00+02:00", &[3.5, 4.25]),
        );
        let rows = |r: &CycleRecord| super::super::csv_rows(r);
        let p = dir.path();
        std::fs::write(p.join(RESULTS_FILE), line(&a) + &line(&b)).unwrap();
        let full = format!("{CSV_HEADER}{}{}", rows(&a), rows(&b));
        for csv in [
            // No row of b, one row of b, b's rows then a stray row of a later cycle.
            format!("{CSV_HEADER}{}", rows(&a)),
            format!(
                "{CSV_HEADER}{}2017-05-08T11:00:00+02:00,S1,3.5,,hdr\n",
                rows(&a)
            ),
            format!("{full}2017-05-08T12:00:00+02:00,S1,9,,hdr\n"),
        ] {
            std::fs::write(p.join(CSV_FILE), &csv).unwrap();
            std::fs::write(p.join(LATEST_FILE), latest_bytes(&a)).unwrap();
            let (_, recovery) = Output::open(p, 2, 2).unwrap();
            assert!(
                recovery.csv_rows_rebuilt && recovery.latest_rebuilt,
                "{csv}"
            );
            assert_eq!(std::fs::read_to_string(p.join(CSV_FILE)).unwrap(), full);
            assert_eq!(
                std::fs::read(p.join(LATEST_FILE)).unwrap(),
                latest_bytes(&b)
            );
            // A second start finds nothing to do.
            let (_, again) = Output::open(p, 2, 2).unwrap();
            assert!(!again.repaired_anything(), "{again:?}");
        }
    }

    /// A crash before the record: the pending cycle's map and capture go, the last
    /// record's stay.
    #[test]
    fn files_of_a_cycle_without_its_record_are_removed() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path();
        let a = record("2017-05-08T10:00:00+02:00", &[1.0]);
        Output::open(p, 4, 4).unwrap();
        std::fs::write(p.join(RESULTS_FILE), line(&a)).unwrap();
        for stamp in ["20170508T080000Z", "20170508T090000Z"] {
            std::fs::write(p.join(MAPS_DIR).join(format!("{stamp}.exr")), b"x").unwrap();
            std::fs::create_dir_all(p.join(CAPTURES_DIR).join(stamp)).unwrap();
            std::fs::write(p.join(VIEWS_DIR).join(format!("{stamp}-desk.exr")), b"x").unwrap();
        }
        std::fs::write(p.join(SPOOL_DIR).join(PENDING_FILE), "20170508T090000Z\n").unwrap();
        let (_, recovery) = Output::open(p, 4, 4).unwrap();
        assert_eq!(recovery.orphan_files_removed, 3);
        assert!(p.join(MAPS_DIR).join("20170508T080000Z.exr").exists());
        assert!(p.join(CAPTURES_DIR).join("20170508T080000Z").exists());
        assert!(!p.join(MAPS_DIR).join("20170508T090000Z.exr").exists());
        assert!(!p.join(CAPTURES_DIR).join("20170508T090000Z").exists());
        assert!(!p.join(VIEWS_DIR).join("20170508T090000Z-desk.exr").exists());
        // The journal names the last record itself (the crash came after the commit):
        // nothing is removed. A journal that is not a stamp is ignored.
        for journal in ["20170508T080000Z\n", "../../etc\n"] {
            std::fs::write(p.join(SPOOL_DIR).join(PENDING_FILE), journal).unwrap();
            let (_, recovery) = Output::open(p, 4, 4).unwrap();
            assert_eq!(recovery.orphan_files_removed, 0, "{journal}");
            assert!(p.join(MAPS_DIR).join("20170508T080000Z.exr").exists());
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(32))]
        /// Whatever a crash or a hand left in the four files the repair reads (the logs, the
        /// journal, `latest.json`; also mutations of a valid record), opening never panics,
        /// and what it keeps of the record log is complete lines.
        #[test]
        fn any_leftover_is_repaired_or_refused_without_panic(
            results in proptest::collection::vec(proptest::prelude::any::<u8>(), 0..400),
            csv in proptest::collection::vec(proptest::prelude::any::<u8>(), 0..400),
            latest in proptest::collection::vec(proptest::prelude::any::<u8>(), 0..200),
            pending in "[A-Za-z0-9./]{0,24}",
            cut in 0usize..400,
            valid in proptest::prelude::any::<bool>(),
        ) {
            let dir = tempfile::tempdir().unwrap();
            let p = dir.path();
            std::fs::create_dir_all(p.join(SPOOL_DIR)).unwrap();
            let results = if valid {
                // A valid record cut anywhere, then the random bytes.
                let mut l = line(&record("2017-05-08T10:00:00+02:00", &[1.0, 2.0])).into_bytes();
                l.truncate(cut.min(l.len()));
                l.extend_from_slice(&results);
                l
            } else {
                results
            };
            std::fs::write(p.join(RESULTS_FILE), &results).unwrap();
            std::fs::write(p.join(CSV_FILE), &csv).unwrap();
            std::fs::write(p.join(LATEST_FILE), &latest).unwrap();
            std::fs::write(p.join(SPOOL_DIR).join(PENDING_FILE), &pending).unwrap();
            if Output::open(p, 2, 2).is_ok() {
                let kept = std::fs::read(p.join(RESULTS_FILE)).unwrap();
                proptest::prop_assert!(kept.is_empty() || kept.ends_with(b"\n"));
                proptest::prop_assert!(results.starts_with(&kept));
            }
        }
    }

    /// A last record that does not parse is reported, and the indexes left alone.
    #[test]
    fn an_unreadable_last_record_is_reported() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path();
        Output::open(p, 1, 1).unwrap();
        std::fs::write(p.join(RESULTS_FILE), "{\"not\":\"a record\"}\n").unwrap();
        let (_, recovery) = Output::open(p, 1, 1).unwrap();
        let reason = recovery.last_record_unreadable.unwrap();
        assert!(
            reason.contains("results.jsonl") && reason.contains("byte 0"),
            "{reason}"
        );
        assert!(!p.join(LATEST_FILE).exists());
    }
}

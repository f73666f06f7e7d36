//! Results on disk, written so that a crash, a power cut or a full disk never costs an
//! earlier result.
//!
//! - `results.jsonl` and `illuminance.csv` are append-only logs. A cycle's lines are appended
//!   with one `write` and an `fsync`. If the write fails (ENOSPC), the file is truncated back
//!   to its length before the cycle, so no partial line stays behind; a crash in the middle
//!   of the write can leave one partial last line, which [`Output::open`] truncates away on
//!   the next start. Both logs are rolled back together, so they always hold the same cycles.
//! - `latest.json`, the EXR maps and the kept captures are written to a temporary name,
//!   fsynced, then renamed over the final name (rename is atomic on POSIX file systems),
//!   and the directory is fsynced. A crash before the rename leaves the previous file; the
//!   stale temporary is removed on the next start.
//! - Maps and captures beyond their retention limit are deleted, oldest first.

use crate::cycle::CycleRecord;
use skylux_hps::camera::DeviceConfig;
use skylux_hps::campaign::RawFrame;
use skylux_hps::hdr::{write_exr, LuminanceMap};
use skylux_hps::picture::Picture;
use std::fs::{File, OpenOptions};
use std::io::{Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// Header of `illuminance.csv`: the columns of campaign.md's results (`lux_measured` empty:
/// the daemon has no lux-meter; `model` = `hdr`).
pub const CSV_HEADER: &str = "time,sensor,lux_model,lux_measured,model\n";
pub const RESULTS_FILE: &str = "results.jsonl";
pub const CSV_FILE: &str = "illuminance.csv";
pub const LATEST_FILE: &str = "latest.json";
/// Written once the API is bound: the address it listens on.
pub const API_ADDRESS_FILE: &str = "api.address";
pub const MAPS_DIR: &str = "maps";
pub const CAPTURES_DIR: &str = "captures";
/// The occupant views' pictures, kept as the maps are.
pub const VIEWS_DIR: &str = "views";
/// Partial captures and scratch files; emptied on start.
pub const SPOOL_DIR: &str = "spool";
use skylux_hps::output::atomic::TMP_SUFFIX;

/// Why the output could not be written.
#[derive(Debug, thiserror::Error)]
#[error("{}: {what}: {source}", path.display())]
pub struct OutputError {
    pub path: PathBuf,
    pub what: &'static str,
    pub source: std::io::Error,
}

impl OutputError {
    /// Whether the disk was full.
    pub fn is_disk_full(&self) -> bool {
        self.source.raw_os_error() == Some(libc::ENOSPC)
    }
}

fn err<'a>(path: &'a Path, what: &'static str) -> impl FnOnce(std::io::Error) -> OutputError + 'a {
    move |source| OutputError {
        path: path.to_path_buf(),
        what,
        source,
    }
}

pub use skylux_hps::output::{fsync_dir, fsync_file, tmp_name};

/// Writes `bytes` to `path` atomically and durably (`skylux_hps::output::write_atomic_with`).
/// `before_rename` runs between the temporary's fsync and the rename (tests use it to stand
/// for a crash there).
pub fn write_atomic_with(
    path: &Path,
    bytes: &[u8],
    before_rename: impl FnOnce() -> std::io::Result<()>,
) -> Result<(), OutputError> {
    skylux_hps::output::write_atomic_with(path, bytes, before_rename)
        .map_err(|e| err(path, "atomic write")(e.source))
}

/// [`write_atomic_with`] without a hook.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    write_atomic_with(path, bytes, || Ok(()))
}

/// An append-only log of complete lines.
#[derive(Debug)]
pub struct LineLog {
    path: PathBuf,
    file: File,
    len: u64,
}

impl LineLog {
    /// Opens (creating with `header`) the log, truncating a partial last line left by a
    /// crash. Returns the log and the number of bytes dropped.
    pub fn open(path: &Path, header: &str) -> Result<(Self, u64), OutputError> {
        let mut file = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(path)
            .map_err(err(path, "open"))?;
        let mut len = file.metadata().map_err(err(path, "stat"))?.len();
        let mut dropped = 0;
        if len > 0 {
            // Find the last newline by reading backwards in blocks.
            let mut end = len;
            let mut keep = 0;
            let mut buf = vec![0u8; 4096];
            'search: while end > 0 {
                let start = end.saturating_sub(buf.len() as u64);
                let n = (end - start) as usize;
                file.seek(SeekFrom::Start(start))
                    .map_err(err(path, "seek"))?;
                file.read_exact(&mut buf[..n]).map_err(err(path, "read"))?;
                if let Some(i) = buf[..n].iter().rposition(|&b| b == b'\n') {
                    keep = start + i as u64 + 1;
                    break 'search;
                }
                end = start;
            }
            if keep < len {
                file.set_len(keep).map_err(err(path, "truncate"))?;
                file.sync_all().map_err(err(path, "fsync"))?;
                dropped = len - keep;
                len = keep;
            }
        }
        let mut log = Self {
            path: path.to_path_buf(),
            file,
            len,
        };
        if log.len == 0 && !header.is_empty() {
            log.append(header.as_bytes())?;
        }
        if let Some(dir) = path.parent() {
            fsync_dir(dir).map_err(err(dir, "fsync"))?;
        }
        Ok((log, dropped))
    }

    /// Current length, bytes (complete lines only).
    pub fn len(&self) -> u64 {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Appends complete lines with one write and an fsync; on failure the file is cut back
    /// to its previous length.
    pub fn append(&mut self, bytes: &[u8]) -> Result<(), OutputError> {
        let before = self.len;
        let result = (|| {
            self.file.seek(SeekFrom::Start(before))?;
            self.file.write_all(bytes)?;
            self.file.sync_data()
        })();
        match result {
            Ok(()) => {
                self.len = before + bytes.len() as u64;
                Ok(())
            }
            Err(e) => {
                self.rollback(before);
                Err(err(&self.path, "append")(e))
            }
        }
    }

    /// Cuts the log back to `len` bytes (best effort: if even this fails, the next start's
    /// recovery drops the partial line).
    pub fn rollback(&mut self, len: u64) {
        if self.file.set_len(len).is_ok() {
            let _ = self.file.sync_all();
            self.len = len;
        }
    }
}

/// Injected output faults (`--sim` fault schedule).
pub trait FaultHook {
    /// An error to return instead of writing, if the fault is due.
    fn output_fault(&mut self) -> Option<std::io::Error>;
}

/// No faults.
pub struct NoFaults;

impl FaultHook for NoFaults {
    fn output_fault(&mut self) -> Option<std::io::Error> {
        None
    }
}

/// The pictures of one cycle: the sky map and the views' renders (index into the record's
/// views, picture).
struct Pictures<'a> {
    map: &'a LuminanceMap,
    views: &'a [(usize, Picture)],
}

/// The daemon's output directory.
pub struct Output {
    pub dir: PathBuf,
    results: LineLog,
    csv: LineLog,
    max_maps: usize,
    max_captures: usize,
}

/// What [`Output::open`] found and repaired.
#[derive(Debug, Default)]
pub struct Recovery {
    pub partial_bytes_dropped: u64,
    pub stale_files_removed: usize,
}

impl Output {
    /// Opens the directory, creating what is missing, and repairs what a crash left.
    pub fn open(
        dir: &Path,
        max_maps: usize,
        max_captures: usize,
    ) -> Result<(Self, Recovery), OutputError> {
        for d in [
            dir.to_path_buf(),
            dir.join(MAPS_DIR),
            dir.join(VIEWS_DIR),
            dir.join(CAPTURES_DIR),
            dir.join(SPOOL_DIR),
        ] {
            std::fs::create_dir_all(&d).map_err(err(&d, "create directory"))?;
        }
        let mut recovery = Recovery::default();
        // Stale temporaries and partial captures from a crash.
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
            let p = entry.path();
            let removed = if p.is_dir() {
                std::fs::remove_dir_all(&p)
            } else {
                std::fs::remove_file(&p)
            };
            if removed.is_ok() {
                recovery.stale_files_removed += 1;
            }
        }
        let (results, a) = LineLog::open(&dir.join(RESULTS_FILE), "")?;
        let (csv, b) = LineLog::open(&dir.join(CSV_FILE), CSV_HEADER)?;
        recovery.partial_bytes_dropped = a + b;
        Ok((
            Self {
                dir: dir.to_path_buf(),
                results,
                csv,
                max_maps,
                max_captures,
            },
            recovery,
        ))
    }

    /// The stamp used in file names: UTC, so that names sort in time order.
    pub fn stamp(record_time: &str) -> String {
        chrono::DateTime::parse_from_rfc3339(record_time)
            .map(|t| {
                t.with_timezone(&chrono::Utc)
                    .format("%Y%m%dT%H%M%SZ")
                    .to_string()
            })
            .unwrap_or_else(|_| "unknown".into())
    }

    /// Writes one cycle: the map, the capture (if kept), the log lines, `latest.json`.
    /// On any error nothing of this cycle stays in the logs, and earlier results are
    /// untouched. Fills `record.map`, `record.capture` and each rendered view's `image`
    /// (`view_pictures`: index into `record.views`, picture), kept as the maps are.
    pub fn write_cycle(
        &mut self,
        record: &mut CycleRecord,
        map: &LuminanceMap,
        view_pictures: &[(usize, Picture)],
        device: &DeviceConfig,
        capture: Option<(&skylux_hps::campaign::CaptureConfig, &[RawFrame])>,
        faults: &mut dyn FaultHook,
    ) -> Result<(), OutputError> {
        if let Some(e) = faults.output_fault() {
            return Err(err(&self.dir, "write (injected fault)")(e));
        }
        let stamp = Self::stamp(&record.time);
        // What this cycle created, removed again if a later step fails.
        let mut created: Vec<PathBuf> = Vec::new();
        let pictures = Pictures {
            map,
            views: view_pictures,
        };
        let result =
            self.write_cycle_files(&stamp, record, &pictures, device, capture, &mut created);
        if result.is_err() {
            for p in created {
                let _ = if p.is_dir() {
                    std::fs::remove_dir_all(&p)
                } else {
                    std::fs::remove_file(&p)
                };
            }
            return result;
        }
        // Retention only after the cycle is safely on disk: a failed cycle deletes nothing.
        if self.max_maps > 0 {
            prune(&self.dir.join(MAPS_DIR), self.max_maps, |n| {
                n.ends_with(".exr")
            });
            let per_cycle = view_pictures.len().max(1);
            prune(&self.dir.join(VIEWS_DIR), self.max_maps * per_cycle, |n| {
                n.ends_with(".exr")
            });
        }
        if self.max_captures > 0 {
            prune(&self.dir.join(CAPTURES_DIR), self.max_captures, |n| {
                !n.starts_with('.')
            });
        }
        Ok(())
    }

    fn write_cycle_files(
        &mut self,
        stamp: &str,
        record: &mut CycleRecord,
        pictures: &Pictures,
        device: &DeviceConfig,
        capture: Option<(&skylux_hps::campaign::CaptureConfig, &[RawFrame])>,
        created: &mut Vec<PathBuf>,
    ) -> Result<(), OutputError> {
        if self.max_maps > 0 {
            let rel = format!("{MAPS_DIR}/{stamp}.exr");
            self.write_whole(&rel, "EXR map", created, &|tmp| {
                write_exr(tmp, pictures.map, device, &capture_readout(capture))
                    .map_err(|e| e.to_string())
            })?;
            record.map = Some(rel);
            for (i, picture) in pictures.views {
                let Some(view) = record.views.get_mut(*i) else {
                    continue;
                };
                let rel = format!("{VIEWS_DIR}/{stamp}-{}.exr", view.view);
                self.write_whole(&rel, "view picture", created, &|tmp| {
                    skylux_hps::picture::exr::write_exr(tmp, picture).map_err(|e| e.to_string())
                })?;
                view.image = Some(rel);
            }
        }
        if let (Some((config, frames)), true) = (capture, self.max_captures > 0) {
            let rel = format!("{CAPTURES_DIR}/{stamp}");
            let existed = self.dir.join(&rel).exists();
            self.write_capture(stamp, config, frames)?;
            if !existed {
                created.push(self.dir.join(&rel));
            }
            record.capture = Some(rel);
        }
        let mut json = serde_json::to_vec(record).map_err(|e| OutputError {
            path: self.dir.join(RESULTS_FILE),
            what: "serialise",
            source: std::io::Error::other(e.to_string()),
        })?;
        json.push(b'\n');
        let mut csv = String::new();
        for s in &record.illuminance {
            csv.push_str(&format!("{},{},{},,hdr\n", record.time, s.sensor, s.lux));
        }
        let (results_len, csv_len) = (self.results.len(), self.csv.len());
        self.results.append(&json)?;
        if let Err(e) = self.csv.append(csv.as_bytes()) {
            self.results.rollback(results_len);
            return Err(e);
        }
        let mut latest = serde_json::to_vec_pretty(record).unwrap_or_default();
        latest.push(b'\n');
        if let Err(e) = write_atomic(&self.dir.join(LATEST_FILE), &latest) {
            self.results.rollback(results_len);
            self.csv.rollback(csv_len);
            return Err(e);
        }
        Ok(())
    }

    /// Writes the file `rel` (under the output directory) whole or not at all: `write` fills a
    /// temporary beside it, which is fsynced and renamed into place. A new file is added to
    /// `created`.
    fn write_whole(
        &self,
        rel: &str,
        what: &'static str,
        created: &mut Vec<PathBuf>,
        write: &dyn Fn(&Path) -> Result<(), String>,
    ) -> Result<(), OutputError> {
        let path = self.dir.join(rel);
        let dir = path.parent().unwrap_or(&self.dir).to_path_buf();
        let existed = path.exists();
        let tmp = tmp_name(&path);
        write(&tmp)
            .map_err(|e| {
                let _ = std::fs::remove_file(&tmp);
                OutputError {
                    path: path.clone(),
                    what,
                    source: std::io::Error::other(e),
                }
            })
            .and_then(|_| {
                fsync_file(&tmp)
                    .and_then(|_| std::fs::rename(&tmp, &path))
                    .and_then(|_| fsync_dir(&dir))
                    .map_err(|e| {
                        let _ = std::fs::remove_file(&tmp);
                        err(&path, what)(e)
                    })
            })?;
        if !existed {
            created.push(path);
        }
        Ok(())
    }

    /// The capture in campaign format under `captures/<stamp>/`, assembled in the spool and
    /// renamed into place whole.
    fn write_capture(
        &self,
        stamp: &str,
        config: &skylux_hps::campaign::CaptureConfig,
        frames: &[RawFrame],
    ) -> Result<(), OutputError> {
        let partial = self.dir.join(SPOOL_DIR).join(format!("capture-{stamp}"));
        let target = self.dir.join(CAPTURES_DIR).join(stamp);
        let result = (|| -> std::io::Result<()> {
            std::fs::create_dir_all(&partial)?;
            for (e, f) in config.exposure.iter().zip(frames) {
                let p = partial.join(&e.file);
                std::fs::write(&p, f.to_pgm())?;
                fsync_file(&p)?;
            }
            let text = toml::to_string(config).map_err(std::io::Error::other)?;
            let p = partial.join("capture.toml");
            std::fs::write(&p, text)?;
            fsync_file(&p)?;
            fsync_dir(&partial)?;
            if target.exists() {
                std::fs::remove_dir_all(&target)?;
            }
            std::fs::rename(&partial, &target)?;
            fsync_dir(&self.dir.join(CAPTURES_DIR))
        })();
        result.map_err(|e| {
            let _ = std::fs::remove_dir_all(&partial);
            err(&target, "capture folder")(e)
        })
    }
}

fn capture_readout(
    capture: Option<(&skylux_hps::campaign::CaptureConfig, &[RawFrame])>,
) -> skylux_hps::campaign::Readout {
    capture
        .map(|(c, _)| c.readout)
        .unwrap_or(skylux_hps::campaign::Readout {
            col_start: 0,
            row_start: 0,
            skip: 1,
        })
}

/// Deletes the oldest entries of `dir` (by name: UTC stamps sort in time order) beyond `keep`.
fn prune(dir: &Path, keep: usize, wanted: impl Fn(&str) -> bool) {
    let Ok(listing) = std::fs::read_dir(dir) else {
        return;
    };
    let mut names: Vec<String> = listing
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| wanted(n) && !n.starts_with('.'))
        .collect();
    names.sort();
    let excess = names.len().saturating_sub(keep);
    for n in &names[..excess] {
        let p = dir.join(n);
        let r = if p.is_dir() {
            std::fs::remove_dir_all(&p)
        } else {
            std::fs::remove_file(&p)
        };
        match r {
            Ok(()) => tracing::info!(path = %p.display(), "retention: deleted"),
            Err(e) => tracing::warn!(path = %p.display(), error = %e, "retention: cannot delete"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn partial_last_line_is_truncated_on_open() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("log.jsonl");
        std::fs::write(&p, b"{\"a\":1}\n{\"a\":2}\n{\"a\":").unwrap();
        let (log, dropped) = LineLog::open(&p, "").unwrap();
        assert_eq!(dropped, 5);
        assert_eq!(log.len(), 16);
        assert_eq!(std::fs::read(&p).unwrap(), b"{\"a\":1}\n{\"a\":2}\n");
        // A file that is one partial line loses it; a clean file is untouched.
        std::fs::write(&p, b"garbage").unwrap();
        assert_eq!(LineLog::open(&p, "").unwrap().1, 7);
        assert_eq!(std::fs::read(&p).unwrap(), b"");
        std::fs::write(&p, b"x\n").unwrap();
        assert_eq!(LineLog::open(&p, "").unwrap().1, 0);
        // Long lines: the backwards search crosses block boundaries.
        let long = "y".repeat(10_000);
        std::fs::write(&p, format!("{long}\n{long}")).unwrap();
        let (log, dropped) = LineLog::open(&p, "").unwrap();
        assert_eq!((log.len(), dropped), (10_001, 10_000));
    }

    #[test]
    fn header_is_written_once() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("x.csv");
        let (mut log, _) = LineLog::open(&p, CSV_HEADER).unwrap();
        log.append(b"a,b,1,,hdr\n").unwrap();
        drop(log);
        let (_, _) = LineLog::open(&p, CSV_HEADER).unwrap();
        assert_eq!(
            std::fs::read_to_string(&p).unwrap(),
            format!("{CSV_HEADER}a,b,1,,hdr\n")
        );
    }

    #[test]
    fn crash_between_temp_write_and_rename_keeps_the_old_file() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join(LATEST_FILE);
        write_atomic(&p, b"old\n").unwrap();
        // The "crash": the hook fails after the temporary is written and synced. The error
        // path removes the temporary; a real crash leaves it, so put one back as a crash would.
        let e = write_atomic_with(&p, b"new\n", || {
            Err(std::io::Error::other("simulated crash"))
        })
        .unwrap_err();
        assert!(e.to_string().contains("simulated crash"));
        assert_eq!(std::fs::read(&p).unwrap(), b"old\n");
        std::fs::write(tmp_name(&p), b"ne").unwrap();
        // The next start removes the stale temporary and keeps the old file.
        let (_, recovery) = Output::open(dir.path(), 2, 0).unwrap();
        assert_eq!(recovery.stale_files_removed, 1);
        assert!(!tmp_name(&p).exists());
        assert_eq!(std::fs::read(&p).unwrap(), b"old\n");
    }

    /// A file standing for a full disk: `/dev/full` returns ENOSPC on every write.
    #[test]
    fn enospc_on_append_rolls_back_to_complete_lines() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("log");
        let (mut log, _) = LineLog::open(&p, "").unwrap();
        log.append(b"one\n").unwrap();
        // Swap in /dev/full for the write, as a disk filling up mid-cycle would behave.
        if let Ok(full) = OpenOptions::new().write(true).open("/dev/full") {
            let good = std::mem::replace(&mut log.file, full);
            let e = log.append(b"two\n").unwrap_err();
            assert!(e.is_disk_full(), "{e}");
            log.file = good;
        }
        log.append(b"three\n").unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"one\nthree\n");
    }

    fn record(time: &str) -> CycleRecord {
        CycleRecord {
            time: time.into(),
            sequence: 1,
            source: "test".into(),
            sun: crate::cycle::SunRecord {
                spa_altitude_deg: 40.0,
                spa_azimuth_deg: 180.0,
                extracted: false,
                extracted_altitude_deg: None,
                extracted_azimuth_deg: None,
                direct_normal_lux: None,
                flags: vec!["no_sun:below_threshold".into()],
                missing_reason: Some("no sun extracted: no direct sun in the map".into()),
            },
            illuminance: vec![crate::cycle::SensorLux {
                sensor: "S1".into(),
                lux: 123.5,
                stderr_lux: None,
            }],
            monte_carlo: None,
            views: vec![],
            outdoor_horizontal_lux: 1e5,
            saturated_fraction: 0.0,
            map: None,
            capture: None,
            durations_ms: Default::default(),
            truth_outdoor_horizontal_lux: None,
            plausibility: vec![],
        }
    }

    /// A cycle whose log write fails leaves no map behind and deletes no earlier map.
    #[test]
    fn a_failed_cycle_deletes_nothing_and_leaves_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let (mut out, _) = Output::open(dir.path(), 1, 0).unwrap();
        let map = LuminanceMap {
            width: 2,
            height: 1,
            luminance_cd_m2: vec![1.0, 2.0],
            flags: vec![skylux_hps::hdr::MapFlag::Valid; 2],
            relative_sigma: vec![0.01; 2],
        };
        let device = DeviceConfig::default();
        let mut r1 = record("2017-05-08T10:00:00+02:00");
        out.write_cycle(&mut r1, &map, &[], &device, None, &mut NoFaults)
            .unwrap();
        let maps = |d: &Path| {
            let mut v: Vec<String> = std::fs::read_dir(d.join(MAPS_DIR))
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .collect();
            v.sort();
            v
        };
        assert_eq!(maps(dir.path()), vec!["20170508T080000Z.exr"]);
        let Ok(full) = OpenOptions::new().write(true).open("/dev/full") else {
            return;
        };
        let good = std::mem::replace(&mut out.results.file, full);
        let mut r2 = record("2017-05-08T11:00:00+02:00");
        let e = out
            .write_cycle(&mut r2, &map, &[], &device, None, &mut NoFaults)
            .unwrap_err();
        assert!(e.is_disk_full());
        out.results.file = good;
        // Retention did not run: the earlier map is still there, the new one is gone.
        assert_eq!(maps(dir.path()), vec!["20170508T080000Z.exr"]);
        let text = std::fs::read_to_string(dir.path().join(RESULTS_FILE)).unwrap();
        assert_eq!(text.lines().count(), 1);
        let mut r3 = record("2017-05-08T12:00:00+02:00");
        out.write_cycle(&mut r3, &map, &[], &device, None, &mut NoFaults)
            .unwrap();
        assert_eq!(maps(dir.path()), vec!["20170508T100000Z.exr"]);
        let csv = std::fs::read_to_string(dir.path().join(CSV_FILE)).unwrap();
        assert_eq!(
            csv,
            format!(
                "{CSV_HEADER}2017-05-08T10:00:00+02:00,S1,123.5,,hdr\n\
                 2017-05-08T12:00:00+02:00,S1,123.5,,hdr\n"
            )
        );
    }

    #[test]
    fn prune_keeps_the_newest() {
        let dir = tempfile::tempdir().unwrap();
        for n in [
            "20170508T100000Z.exr",
            "20170508T090000Z.exr",
            "20170508T110000Z.exr",
        ] {
            std::fs::write(dir.path().join(n), b"x").unwrap();
        }
        prune(dir.path(), 2, |n| n.ends_with(".exr"));
        let mut left: Vec<String> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        left.sort();
        assert_eq!(left, vec!["20170508T100000Z.exr", "20170508T110000Z.exr"]);
    }
}

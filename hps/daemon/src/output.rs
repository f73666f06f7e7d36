//! Results on disk, written so that a crash, a power cut or a full disk never costs an
//! earlier result, and never leaves half of a cycle behind.
//!
//! A cycle is written in this order: the EXR map and view pictures, the capture folder, the
//! record's line in `results.jsonl` (the commit point), its rows in `illuminance.csv`,
//! `latest.json`, then retention. Before the first of these, the cycle's stamp is written to
//! `spool/cycle.pending`.
//!
//! - `results.jsonl` and `illuminance.csv` are append-only logs. A cycle's lines are appended
//!   with one `write` and an `fsync`. If the write fails (ENOSPC), the file is truncated back
//!   to its length before the cycle, so no partial line stays behind; both logs are rolled
//!   back together.
//! - `latest.json`, the EXR maps and the kept captures are written to a temporary name,
//!   fsynced, then renamed over the final name (rename is atomic on POSIX file systems),
//!   and the directory is fsynced.
//! - A crash anywhere in a cycle is repaired by [`Output::open`] on the next start
//!   (`repair.rs`): a partial last line is truncated, stale temporaries and the spool are
//!   removed, the files of a cycle that never reached its record are deleted, and the CSV
//!   rows and `latest.json` are rebuilt from the last record when the crash came after it.
//!   Every completed cycle's record is then present exactly once and whole.
//! - Maps and captures beyond their retention limit are deleted, oldest first, after each
//!   cycle and at start.
//!
//! `write_pause.rs` holds the test-only pauses that let the crash test kill the daemon inside
//! each of these writes.

mod repair;
pub mod write_pause;

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
use write_pause::WritePoint;

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
        let keep = last_newline_before(&mut file, len)
            .map_err(err(path, "read"))?
            .map_or(0, |i| i + 1);
        if keep < len {
            file.set_len(keep).map_err(err(path, "truncate"))?;
            file.sync_all().map_err(err(path, "fsync"))?;
            dropped = len - keep;
            len = keep;
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
        self.append_at(bytes, None)
    }

    /// [`append`](Self::append), split in two around the test-only pause at `point` when one
    /// is armed there (`write_pause`); `time` is the cycle's, for the pause's log line.
    fn append_at(
        &mut self,
        bytes: &[u8],
        pause: Option<(WritePoint, &str)>,
    ) -> Result<(), OutputError> {
        let before = self.len;
        let pause = pause.filter(|(point, _)| write_pause::is_armed(*point));
        let split = pause.map_or(bytes.len(), |(point, _)| point.split(bytes));
        let result = (|| {
            self.file.seek(SeekFrom::Start(before))?;
            self.file.write_all(&bytes[..split])?;
            if let Some((point, time)) = pause {
                write_pause::at(point, time);
            }
            self.file.write_all(&bytes[split..])?;
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

    /// The last `max` complete lines (newline included), oldest first, each with the offset
    /// where it starts; fewer when the log has fewer.
    pub fn tail_lines(&mut self, max: usize) -> Result<Vec<(u64, Vec<u8>)>, OutputError> {
        let mut lines = Vec::new();
        let mut end = self.len;
        while lines.len() < max && end > 0 {
            let start = last_newline_before(&mut self.file, end - 1)
                .map_err(err(&self.path, "read"))?
                .map_or(0, |i| i + 1);
            let mut line = vec![0u8; (end - start) as usize];
            self.file
                .seek(SeekFrom::Start(start))
                .and_then(|_| self.file.read_exact(&mut line))
                .map_err(err(&self.path, "read"))?;
            lines.push((start, line));
            end = start;
        }
        lines.reverse();
        Ok(lines)
    }

    /// Cuts the log back to `len` bytes, durably (start-up repair: errors are reported).
    pub fn cut(&mut self, len: u64) -> Result<(), OutputError> {
        self.file
            .set_len(len)
            .map_err(err(&self.path, "truncate"))?;
        self.file.sync_all().map_err(err(&self.path, "fsync"))?;
        self.len = len;
        Ok(())
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

/// The offset of the last newline in `file[..end]`, read backwards in blocks.
fn last_newline_before(file: &mut File, end: u64) -> std::io::Result<Option<u64>> {
    let mut end = end;
    let mut buf = vec![0u8; 4096];
    while end > 0 {
        let start = end.saturating_sub(buf.len() as u64);
        let n = (end - start) as usize;
        file.seek(SeekFrom::Start(start))?;
        file.read_exact(&mut buf[..n])?;
        if let Some(i) = buf[..n].iter().rposition(|&b| b == b'\n') {
            return Ok(Some(start + i as u64));
        }
        end = start;
    }
    Ok(None)
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
    states: &'a [(usize, usize, Picture)],
}

/// The daemon's output directory.
pub struct Output {
    pub dir: PathBuf,
    /// The time of the last record on disk (RFC 3339), if any.
    last_time: Option<String>,
    results: LineLog,
    csv: LineLog,
    max_maps: usize,
    max_captures: usize,
}

/// What [`Output::open`] found and repaired.
#[derive(Debug, Default)]
pub struct Recovery {
    /// Partial last lines of the two logs, bytes.
    pub partial_bytes_dropped: u64,
    /// Temporaries and spool entries.
    pub stale_files_removed: usize,
    /// Maps, view pictures and capture folders of a cycle that crashed before its record.
    pub orphan_files_removed: usize,
    /// The last record's CSV rows were rewritten (the crash came between record and rows).
    pub csv_rows_rebuilt: bool,
    /// `latest.json` was rewritten from the last record.
    pub latest_rebuilt: bool,
    /// Why the last record could not be read back (its CSV rows and `latest.json` are then
    /// left as they are).
    pub last_record_unreadable: Option<String>,
}

impl Recovery {
    /// Whether anything was repaired.
    pub fn repaired_anything(&self) -> bool {
        self.partial_bytes_dropped > 0
            || self.stale_files_removed > 0
            || self.orphan_files_removed > 0
            || self.csv_rows_rebuilt
            || self.latest_rebuilt
            || self.last_record_unreadable.is_some()
    }
}

impl Output {
    /// Opens the directory, creating what is missing, repairs what a crash left
    /// (`repair.rs`) and applies retention.
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
        let pending = repair::pending_stamp(dir);
        repair::remove_leftovers(dir, &mut recovery)?;
        let (results, a) = LineLog::open(&dir.join(RESULTS_FILE), "")?;
        let (csv, b) = LineLog::open(&dir.join(CSV_FILE), CSV_HEADER)?;
        recovery.partial_bytes_dropped = a + b;
        let mut output = Self {
            dir: dir.to_path_buf(),
            last_time: None,
            results,
            csv,
            max_maps,
            max_captures,
        };
        let last = repair::after_crash(&mut output, pending.as_deref(), &mut recovery)?;
        output.retain(last.as_ref().map_or(0, |r| r.views.len()));
        output.last_time = last.map(|r| r.time);
        Ok((output, recovery))
    }

    /// The time of the last record on disk (RFC 3339), if any.
    pub fn last_time(&self) -> Option<&str> {
        self.last_time.as_deref()
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
    /// (`view_pictures`: index into `record.views`, picture; `state_pictures`: the views
    /// under the window's states, index into `record.window_states`, into its views, picture),
    /// kept as the maps are.
    #[allow(clippy::too_many_arguments)]
    pub fn write_cycle(
        &mut self,
        record: &mut CycleRecord,
        map: &LuminanceMap,
        view_pictures: &[(usize, Picture)],
        state_pictures: &[(usize, usize, Picture)],
        device: &DeviceConfig,
        capture: Option<(&skylux_hps::campaign::CaptureConfig, &[RawFrame])>,
        faults: &mut dyn FaultHook,
    ) -> Result<(), OutputError> {
        if let Some(e) = faults.output_fault() {
            return Err(err(&self.dir, "write (injected fault)")(e));
        }
        let stamp = Self::stamp(&record.time);
        // The journal: the next start deletes this stamp's files unless its record made it.
        let pending = self.dir.join(SPOOL_DIR).join(repair::PENDING_FILE);
        write_atomic(&pending, format!("{stamp}\n").as_bytes())?;
        // What this cycle created, removed again if a later step fails.
        let mut created: Vec<PathBuf> = Vec::new();
        let pictures = Pictures {
            map,
            views: view_pictures,
            states: state_pictures,
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
            let _ = std::fs::remove_file(&pending);
            return result;
        }
        // Retention only after the cycle is safely on disk: a failed cycle deletes nothing.
        write_pause::at(WritePoint::Retention, &record.time);
        self.retain(view_pictures.len() + state_pictures.len());
        let _ = std::fs::remove_file(&pending);
        self.last_time = Some(record.time.clone());
        Ok(())
    }

    /// Deletes the oldest maps, view pictures and captures beyond their limits.
    fn retain(&self, views_per_cycle: usize) {
        if self.max_maps > 0 {
            prune(&self.dir.join(MAPS_DIR), self.max_maps, |n| {
                n.ends_with(".exr")
            });
            let per_cycle = views_per_cycle.max(1);
            prune(&self.dir.join(VIEWS_DIR), self.max_maps * per_cycle, |n| {
                n.ends_with(".exr")
            });
        }
        if self.max_captures > 0 {
            prune(&self.dir.join(CAPTURES_DIR), self.max_captures, |n| {
                !n.starts_with('.')
            });
        }
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
            self.write_whole(&rel, "EXR map", &record.time, created, &|tmp| {
                write_exr(tmp, pictures.map, device, &capture_readout(capture))
                    .map_err(|e| e.to_string())
            })?;
            record.map = Some(rel);
            let time = record.time.clone();
            for (i, picture) in pictures.views {
                let Some(view) = record.views.get_mut(*i) else {
                    continue;
                };
                let rel = format!("{VIEWS_DIR}/{stamp}-{}.exr", view.view);
                self.write_whole(&rel, "view picture", &time, created, &|tmp| {
                    skylux_hps::picture::exr::write_exr(tmp, picture).map_err(|e| e.to_string())
                })?;
                view.image = Some(rel);
            }
            for (s, v, picture) in pictures.states {
                let Some(state) = record.window_states.get_mut(*s) else {
                    continue;
                };
                let Some(glare) = state
                    .views
                    .get_mut(*v)
                    .and_then(|view| view.rendered.as_mut())
                else {
                    continue;
                };
                let rel = format!("{VIEWS_DIR}/{stamp}-{}-{}.exr", glare.view, state.state);
                self.write_whole(&rel, "view picture", &time, created, &|tmp| {
                    skylux_hps::picture::exr::write_exr(tmp, picture).map_err(|e| e.to_string())
                })?;
                glare.image = Some(rel);
            }
        }
        // A fabric map has no raw frames to keep (its capture only names the map's readout).
        let kept = capture.filter(|(_, frames)| self.max_captures > 0 && !frames.is_empty());
        if let Some((config, frames)) = kept {
            let rel = format!("{CAPTURES_DIR}/{stamp}");
            let existed = self.dir.join(&rel).exists();
            self.write_capture(stamp, &record.time, config, frames)?;
            if !existed {
                created.push(self.dir.join(&rel));
            }
            record.capture = Some(rel);
        }
        self.write_logs(record)
    }

    /// The record's line (the commit point), its CSV rows, then `latest.json`; on failure
    /// both logs are cut back to their length before the cycle.
    fn write_logs(&mut self, record: &CycleRecord) -> Result<(), OutputError> {
        let mut json = serde_json::to_vec(record).map_err(|e| OutputError {
            path: self.dir.join(RESULTS_FILE),
            what: "serialise",
            source: std::io::Error::other(e.to_string()),
        })?;
        json.push(b'\n');
        let time = record.time.as_str();
        let (results_len, csv_len) = (self.results.len(), self.csv.len());
        self.results
            .append_at(&json, Some((WritePoint::Jsonl, time)))?;
        let rows = csv_rows(record);
        if let Err(e) = self
            .csv
            .append_at(rows.as_bytes(), Some((WritePoint::Csv, time)))
        {
            self.results.rollback(results_len);
            return Err(e);
        }
        let latest_path = self.dir.join(LATEST_FILE);
        let written = write_atomic_with(&latest_path, &latest_bytes(record), || {
            write_pause::at(WritePoint::Latest, time);
            Ok(())
        });
        if let Err(e) = written {
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
        time: &str,
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
                    .map(|_| write_pause::at(WritePoint::Map, time))
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
        time: &str,
        config: &skylux_hps::campaign::CaptureConfig,
        frames: &[RawFrame],
    ) -> Result<(), OutputError> {
        let partial = self.dir.join(SPOOL_DIR).join(format!("capture-{stamp}"));
        let target = self.dir.join(CAPTURES_DIR).join(stamp);
        let result = (|| -> std::io::Result<()> {
            std::fs::create_dir_all(&partial)?;
            for (i, (e, f)) in config.exposure.iter().zip(frames).enumerate() {
                let p = partial.join(&e.file);
                std::fs::write(&p, f.to_pgm())?;
                fsync_file(&p)?;
                if i == 0 {
                    write_pause::at(WritePoint::CaptureFrames, time);
                }
            }
            let text = toml::to_string(config).map_err(std::io::Error::other)?;
            let p = partial.join("capture.toml");
            std::fs::write(&p, text)?;
            fsync_file(&p)?;
            fsync_dir(&partial)?;
            write_pause::at(WritePoint::CaptureRename, time);
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

/// The CSV rows of a record (one per sensor), as `illuminance.csv` holds them.
fn csv_rows(record: &CycleRecord) -> String {
    record
        .illuminance
        .iter()
        .map(|s| format!("{},{},{},,hdr\n", record.time, s.sensor, s.lux))
        .collect()
}

/// `latest.json`'s bytes for a record.
fn latest_bytes(record: &CycleRecord) -> Vec<u8> {
    let mut latest = serde_json::to_vec_pretty(record).unwrap_or_default();
    latest.push(b'\n');
    latest
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
            bin: 1,
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
        let full = OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .expect("/dev/full (every Linux has it)");
        let good = std::mem::replace(&mut log.file, full);
        let e = log.append(b"two\n").unwrap_err();
        assert!(e.is_disk_full(), "{e}");
        log.file = good;
        log.append(b"three\n").unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"one\nthree\n");
    }

    pub(super) fn record(time: &str) -> CycleRecord {
        CycleRecord::minimal(time, "test")
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
        out.write_cycle(&mut r1, &map, &[], &[], &device, None, &mut NoFaults)
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
        let full = OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .expect("/dev/full (every Linux has it)");
        let good = std::mem::replace(&mut out.results.file, full);
        let mut r2 = record("2017-05-08T11:00:00+02:00");
        let e = out
            .write_cycle(&mut r2, &map, &[], &[], &device, None, &mut NoFaults)
            .unwrap_err();
        assert!(e.is_disk_full());
        out.results.file = good;
        // Retention did not run: the earlier map is still there, the new one is gone.
        assert_eq!(maps(dir.path()), vec!["20170508T080000Z.exr"]);
        let text = std::fs::read_to_string(dir.path().join(RESULTS_FILE)).unwrap();
        assert_eq!(text.lines().count(), 1);
        let mut r3 = record("2017-05-08T12:00:00+02:00");
        out.write_cycle(&mut r3, &map, &[], &[], &device, None, &mut NoFaults)
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

//! Faults: each injected fault is logged with a clear message and retried with back-off, the
//! daemon keeps running, and no earlier result is lost or corrupted. A bad configuration is
//! refused with the file, line and field. A daemon killed with SIGKILL, again and again, in
//! the middle of each of its writes, loses, duplicates and corrupts no record.

mod common;

use common::*;
use skyluxd::output::write_pause::WritePoint;
use std::collections::BTreeSet;
use std::path::Path;
use std::time::Duration;

const T0: &str = "2017-05-08T10:00:00+02:00";
/// Smaller frames than the example's (81 x 60 samples): these tests run many cycles, also
/// under qemu-arm on a shared machine.
const SMALL: (&str, &str) = (SIM_SKIP, "skip = 32 # 2592/32");

#[test]
fn injected_faults_are_logged_retried_with_backoff_and_survived() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let log = tmp.path().join("stderr.log");
    // Attempt 1 succeeds, 2..6 fail one way each, 7 and 8 succeed.
    let faults = [
        (2, "sensor_absent"),
        (3, "i2c_nack"),
        (4, "dma_timeout"),
        (5, "flagged_frame"),
        (6, "disk_full"),
    ];
    let extra: String = faults
        .iter()
        .map(|(a, k)| format!("[[sim.fault]]\nattempt = {a}\nkind = \"{k}\"\n"))
        .collect();
    let config = config_with(tmp.path(), &[SMALL], &extra);
    let mut child = SimRun::new(&config, &out)
        .cycles(3)
        .clock(T0, 3600)
        .start(&log);
    let status = wait(&mut child, Duration::from_secs(55));
    let text = std::fs::read_to_string(&log).unwrap();
    assert_eq!(status.code(), Some(0), "{text}");
    // Every fault, by kind, with its message and the back-off (2, 4, 8, 16, 32 s).
    for ((_, kind), (message, retry)) in faults.iter().zip([
        ("sensor absent", 2),
        ("I2C NACK at sensor register 0x09", 4),
        ("DMA timeout", 8),
        ("frame flagged [\"FIFO_OVERFLOW\"]", 16),
        ("No space left on device", 32),
    ]) {
        let line = text
            .lines()
            .find(|l| l.contains("cycle failed") && l.contains(&format!("kind=\"{kind}\"")))
            .unwrap_or_else(|| panic!("no log line for {kind}:\n{text}"));
        assert!(line.contains(message), "{line}");
        assert!(line.contains(&format!("retry_in_s={retry}")), "{line}");
    }
    assert!(!text.contains("panicked"), "{text}");
    // Three records, complete, and the capture times show the back-off: the second cycle
    // ran 1 h + 2+4+8+16+32 s after the first.
    let lines = complete_lines(&out.join("results.jsonl"));
    assert_eq!(lines.len(), 3);
    let times: Vec<String> = lines
        .iter()
        .map(|l| {
            let v: serde_json::Value = serde_json::from_str(l).unwrap();
            v["time"].as_str().unwrap().to_string()
        })
        .collect();
    assert_eq!(
        times,
        vec![
            "2017-05-08T10:00:00+02:00",
            "2017-05-08T11:01:02+02:00",
            "2017-05-08T12:01:02+02:00"
        ]
    );
    // The failed disk-full cycle left nothing behind: 3 x 5 CSV rows, 3 maps, 3 captures.
    let csv = std::fs::read_to_string(out.join("illuminance.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 15);
    assert_eq!(std::fs::read_dir(out.join("maps")).unwrap().count(), 3);
    assert_eq!(std::fs::read_dir(out.join("captures")).unwrap().count(), 3);
}

/// The clock steps back two hours after a good cycle: the capture time is not after the last
/// record's, so the cycle fails, flagged in the log and `/v1/health` with its cause, and
/// retried until the clock has passed the last record; then a good cycle, in time order.
#[test]
fn a_clock_stepping_back_is_flagged_and_followed_by_a_good_cycle() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let log = tmp.path().join("stderr.log");
    let extra = "[[sim.fault]]\nattempt = 2\nkind = \"clock_back\"\n";
    let config = config_with(tmp.path(), &[SMALL], extra);
    let mut child = SimRun::new(&config, &out)
        .cycles(2)
        .clock(T0, 3600)
        .serve_after()
        .start(&log);
    let results = out.join("results.jsonl");
    until(Duration::from_secs(40), &log, || {
        (complete_lines(&results).len() >= 2).then_some(())
    });
    let address = std::fs::read_to_string(out.join("api.address")).unwrap();
    // The record is made durable before the health counters move: poll until they do.
    let h: serde_json::Value = until(Duration::from_secs(20), &log, || {
        let (code, body) = http_get(address.trim(), "/v1/health");
        assert_eq!(code, 200, "{body}");
        let h: serde_json::Value = serde_json::from_str(&body).unwrap();
        (h["cycles_ok"].as_u64() >= Some(2)).then_some(h)
    });
    signal(&child, libc::SIGTERM);
    assert_eq!(wait(&mut child, Duration::from_secs(20)).code(), Some(0));
    let text = std::fs::read_to_string(&log).unwrap();
    // Flagged: the log and the health name the cause; the good cycle since cleared the
    // degraded status.
    let line = text
        .lines()
        .find(|l| l.contains("cycle failed") && l.contains("kind=\"clock\""))
        .unwrap_or_else(|| panic!("no clock failure logged:\n{text}"));
    assert!(line.contains("the clock went backwards"), "{line}");
    assert_eq!(h["last_error"]["kind"], "clock", "{h}");
    assert!(
        h["last_error"]["message"]
            .as_str()
            .unwrap()
            .contains("not after the last record's time 2017-05-08T10:00:00+02:00"),
        "{h}"
    );
    assert_eq!(h["status"], "ok", "{h}");
    assert_eq!(h["cycles_ok"], 2, "{h}");
    // Two records, in time order, the second after the first.
    let times: Vec<chrono::DateTime<chrono::FixedOffset>> = complete_lines(&results)
        .iter()
        .map(|l| {
            let v: serde_json::Value = serde_json::from_str(l).unwrap();
            chrono::DateTime::parse_from_rfc3339(v["time"].as_str().unwrap()).unwrap()
        })
        .collect();
    assert_eq!(times.len(), 2);
    assert!(times[1] > times[0], "{times:?}");
}

#[test]
fn bad_configs_are_refused_with_file_line_and_field() {
    let tmp = tempfile::tempdir().unwrap();
    for (replace, expect_line, field) in [
        (
            ("period_s = 60.0", "period_s = 0.1"),
            "period_s = 0.1",
            "capture.period_s",
        ),
        (
            ("register_base = 0xFF200000", "register_base = 0xC0000000"),
            "register_base = 0xC0000000",
            "hardware.register_base",
        ),
        (
            ("address = \"127.0.0.1:8740\"", "address = \"0.0.0.0:8740\""),
            "address = \"0.0.0.0:8740\"",
            "api.address",
        ),
        (
            ("sky = \"clear\"", "sky = \"stormy\""),
            "sky = \"stormy\"",
            "stormy",
        ),
    ] {
        let config = config_with(tmp.path(), &[replace], "");
        let text = std::fs::read_to_string(&config).unwrap();
        let line = text
            .lines()
            .position(|l| l.starts_with(expect_line))
            .unwrap()
            + 1;
        let log = tmp.path().join("stderr.log");
        let mut child = start(
            &[
                "--sim",
                "--cycles",
                "1",
                "--config",
                config.to_str().unwrap(),
            ],
            &log,
        );
        let status = wait(&mut child, Duration::from_secs(20));
        let err = std::fs::read_to_string(&log).unwrap();
        assert_eq!(status.code(), Some(78), "{err}");
        assert!(
            err.contains(&format!("skyluxd.toml:{line}")),
            "line {line}: {err}"
        );
        assert!(err.contains(field), "{err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    // A missing file.
    let log = tmp.path().join("stderr.log");
    let mut child = start(&["--sim", "--config", "/nonexistent/skyluxd.toml"], &log);
    assert_eq!(wait(&mut child, Duration::from_secs(20)).code(), Some(78));
    assert!(std::fs::read_to_string(&log)
        .unwrap()
        .contains("/nonexistent/skyluxd.toml"));
}

/// Makes `paths` unwritable: permission bits for an ordinary user; for root (who ignores
/// them) the immutable attribute. Returns false if neither is possible here.
fn make_read_only(paths: &[&Path], on: bool) -> bool {
    let root = unsafe { libc::geteuid() } == 0;
    for p in paths {
        if root {
            let ok = std::process::Command::new("chattr")
                .arg(if on { "+i" } else { "-i" })
                .arg(p)
                .status()
                .is_ok_and(|s| s.success());
            if !ok {
                return false;
            }
        } else {
            use std::os::unix::fs::PermissionsExt;
            let mode = match (p.is_dir(), on) {
                (true, true) => 0o555,
                (true, false) => 0o755,
                (false, true) => 0o444,
                (false, false) => 0o644,
            };
            std::fs::set_permissions(p, std::fs::Permissions::from_mode(mode)).unwrap();
        }
    }
    true
}

#[test]
fn read_only_output_is_retried_and_earlier_results_survive() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let log = tmp.path().join("stderr.log");
    let config = config_with(tmp.path(), &[SMALL], "");
    let run = |cycles: u64, start: &str| {
        SimRun::new(&config, &out)
            .cycles(cycles)
            .clock(start, 3600)
            .start(&log)
    };
    // One good cycle.
    let mut child = run(1, T0);
    assert_eq!(wait(&mut child, Duration::from_secs(40)).code(), Some(0));
    let before = std::fs::read(out.join("results.jsonl")).unwrap();
    let csv_before = std::fs::read(out.join("illuminance.csv")).unwrap();
    assert_eq!(complete_lines(&out.join("results.jsonl")).len(), 1);

    // The disk turns read-only.
    let ro: Vec<std::path::PathBuf> = [
        "results.jsonl",
        "illuminance.csv",
        "latest.json",
        "maps",
        "captures",
        "spool",
        "cache",
        "",
    ]
    .iter()
    .map(|n| out.join(n))
    .collect();
    let refs: Vec<&Path> = ro.iter().map(|p| p.as_path()).collect();
    if !skylux_hps::prerequisite::available_or_skip(
        make_read_only(&refs, true),
        skylux_hps::prerequisite::REQUIRE_HOST,
        "cannot make a directory read-only here (root without chattr +i on this file system)",
    ) {
        return;
    }
    let mut child = run(1, "2017-05-08T14:00:00+02:00");
    // The daemon fails, logs, backs off and keeps running.
    until(Duration::from_secs(40), &log, || {
        let t = std::fs::read_to_string(&log).unwrap_or_default();
        (t.matches("cycle failed").count() >= 3).then_some(())
    });
    assert!(
        child.try_wait().unwrap().is_none(),
        "the daemon must keep running"
    );
    let text = std::fs::read_to_string(&log).unwrap();
    assert!(text.contains("kind=\"output\""), "{text}");
    assert_eq!(std::fs::read(out.join("results.jsonl")).unwrap(), before);
    // The disk comes back: the next attempt succeeds, and the earlier result is intact.
    make_read_only(&refs, false);
    let status = wait(&mut child, Duration::from_secs(40));
    assert_eq!(
        status.code(),
        Some(0),
        "{}",
        std::fs::read_to_string(&log).unwrap()
    );
    let after = std::fs::read(out.join("results.jsonl")).unwrap();
    assert!(after.starts_with(&before) && after.len() > before.len());
    assert_eq!(complete_lines(&out.join("results.jsonl")).len(), 2);
    assert!(std::fs::read(out.join("illuminance.csv"))
        .unwrap()
        .starts_with(&csv_before));
}

/// Retention in the crash test: small, so that it deletes in almost every cycle.
const KEEP: usize = 2;

/// What the output directory must hold after a run was killed at `point` inside the cycle
/// of `in_flight` (or after a clean run: `None`): every record of `committed` exactly once
/// and whole, none of `lost`; the CSV rows, `latest.json`, maps and captures consistent with
/// the records (the earlier kills repaired by this run's start); retention held.
fn check_output(
    out: &Path,
    committed: &BTreeSet<String>,
    lost: &BTreeSet<String>,
    kill: Option<(WritePoint, &str)>,
) -> Result<(), String> {
    let records = records(out)?;
    let times: Vec<&str> = records.iter().map(|r| r.time.as_str()).collect();
    let unique: BTreeSet<String> = times.iter().map(|t| t.to_string()).collect();
    if unique.len() != times.len() {
        return Err(format!("a record is duplicated: {times:?}"));
    }
    if &unique != committed {
        return Err(format!("records {unique:?}, expected {committed:?}"));
    }
    if let Some(t) = lost.iter().find(|t| unique.contains(*t)) {
        return Err(format!("{t}: killed before its commit, yet recorded"));
    }
    let point = kill.map(|(p, _)| p);
    check_csv(out, &records, point)?;
    check_latest(out, &records, point)?;
    check_retention(out, &records, kill)
}

/// The complete records of `results.jsonl`; a partial last line only while a kill at the
/// record's own write is unrepaired.
fn records(out: &Path) -> Result<Vec<skyluxd::cycle::CycleRecord>, String> {
    complete_lines(&out.join("results.jsonl"))
        .iter()
        .map(|l| serde_json::from_str(l).map_err(|e| format!("a record does not parse: {e}: {l}")))
        .collect()
}

/// Every record's rows, in order, exactly once; the last one's first row only when the kill
/// came between its rows.
fn check_csv(
    out: &Path,
    records: &[skyluxd::cycle::CycleRecord],
    point: Option<WritePoint>,
) -> Result<(), String> {
    let text = std::fs::read_to_string(out.join("illuminance.csv")).map_err(|e| e.to_string())?;
    let mut expected = String::from(skyluxd::output::CSV_HEADER);
    for (i, r) in records.iter().enumerate() {
        let cut = point == Some(WritePoint::Csv) && i + 1 == records.len();
        for s in r.illuminance.iter().take(if cut { 1 } else { usize::MAX }) {
            expected.push_str(&format!("{},{},{},,hdr\n", r.time, s.sensor, s.lux));
        }
    }
    (text == expected)
        .then_some(())
        .ok_or_else(|| format!("illuminance.csv:\n{text}\nexpected:\n{expected}"))
}

/// `latest.json` parses and is the last record, or the one before while the kill sits
/// between the record and the new `latest.json`.
fn check_latest(
    out: &Path,
    records: &[skyluxd::cycle::CycleRecord],
    point: Option<WritePoint>,
) -> Result<(), String> {
    let stale = matches!(point, Some(WritePoint::Csv | WritePoint::Latest));
    let want = records.len().checked_sub(if stale { 2 } else { 1 });
    let latest = std::fs::read_to_string(out.join("latest.json")).ok();
    let latest: Option<skyluxd::cycle::CycleRecord> = latest
        .map(|t| serde_json::from_str(&t).map_err(|e| format!("latest.json: {e}")))
        .transpose()?;
    match (want.map(|i| &records[i]), latest) {
        (None, None) => Ok(()),
        (Some(w), Some(l)) if *w == l => Ok(()),
        (w, l) => Err(format!(
            "latest.json is {:?}, expected {:?}",
            l.map(|l| l.time),
            w.map(|w| &w.time)
        )),
    }
}

/// The maps and captures are exactly those of the newest `KEEP` records (plus the killed
/// cycle's own once they are in place, and one more while retention has not run), nothing
/// is left in the spool after a clean run.
fn check_retention(
    out: &Path,
    records: &[skyluxd::cycle::CycleRecord],
    kill: Option<(WritePoint, &str)>,
) -> Result<(), String> {
    let listing = |dir: &str| -> BTreeSet<String> {
        std::fs::read_dir(out.join(dir))
            .map(|l| {
                l.flatten()
                    .map(|e| format!("{dir}/{}", e.file_name().to_string_lossy()))
                    .filter(|n| !n.contains("/."))
                    .collect()
            })
            .unwrap_or_default()
    };
    let stamp = |t: &str| skyluxd::output::Output::stamp(t);
    // The cycles whose files must be on disk, newest first: the killed one (once its files
    // are in place and its record is not yet written), then the records.
    let mut newest: Vec<String> = records.iter().rev().map(|r| stamp(&r.time)).collect();
    let point = kill.map(|(p, _)| p);
    if let Some((_, t)) = kill.filter(|(p, _)| !p.after_commit() && *p != WritePoint::Map) {
        newest.insert(0, stamp(t));
    }
    // Retention runs after the commit: one more of each until it has.
    let keep = KEEP + usize::from(point.is_some_and(|p| p != WritePoint::Map));
    let map_of = |s: &String| format!("maps/{s}.exr");
    let capture_of = |s: &String| format!("captures/{s}");
    let maps_expected: BTreeSet<String> = newest.iter().take(keep).map(map_of).collect();
    let captures_ready = !matches!(
        point,
        Some(WritePoint::CaptureFrames | WritePoint::CaptureRename)
    );
    let mut captures_expected: BTreeSet<String> =
        newest.iter().take(keep).map(capture_of).collect();
    if !captures_ready {
        // Killed inside the capture: the map is in place, the capture is still in the spool.
        captures_expected = newest
            .iter()
            .skip(1)
            .take(keep - 1)
            .map(capture_of)
            .collect();
    }
    let (maps, captures) = (listing("maps"), listing("captures"));
    if maps != maps_expected || captures != captures_expected {
        return Err(format!(
            "maps {maps:?} captures {captures:?}, expected {maps_expected:?} and \
             {captures_expected:?}"
        ));
    }
    if kill.is_none() && std::fs::read_dir(out.join("spool")).map_or(0, |d| d.count()) > 0 {
        return Err("the spool is not empty after a clean run".into());
    }
    Ok(())
}

/// The value of `key=` in a log line (quotes removed).
fn log_field<'a>(line: &'a str, key: &str) -> Option<&'a str> {
    let start = line.find(&format!(" {key}="))? + key.len() + 2;
    let rest = &line[start..];
    let end = rest.find(' ').unwrap_or(rest.len());
    Some(rest[..end].trim_matches('"'))
}

/// Kills `skyluxd` with SIGKILL inside each of its writes (the test-only pause of
/// `output/write_pause.rs` holds it there), in the first cycle of a run and after a completed
/// one, and restarts it: each restart repairs what the kill left, so that every completed
/// cycle's record is present exactly once and whole, a cycle killed before its record's
/// line is complete leaves nothing, `latest.json` parses and follows the records, and
/// retention holds.
#[test]
fn sigkill_inside_every_write_loses_and_duplicates_nothing() {
    const ROUNDS: u64 = 2;
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let keep = format!("max_maps = {KEEP} ");
    let captures = format!("max_captures = {KEEP} ");
    let config = config_with(
        tmp.path(),
        &[
            SMALL,
            ("max_maps = 48 ", &keep),
            ("max_captures = 24 ", &captures),
        ],
        "",
    );
    let (mut committed, mut lost) = (BTreeSet::new(), BTreeSet::new());
    let (mut kills, mut mid_write) = (0, 0);
    let mut day = 0;
    for round in 0..ROUNDS {
        for point in WritePoint::ALL {
            day += 1;
            let log = tmp
                .path()
                .join(format!("stderr-{round}-{}.log", point.name()));
            // Round 0 kills in the run's first cycle, round 1 after a completed one.
            let pause = format!("{}:60000:{}", point.name(), round + 1);
            let mut child = SimRun::new(&config, &out)
                .clock(&format!("2017-05-{day:02}T10:00:00+02:00"), 600)
                .env(skyluxd::output::write_pause::VARIABLE, &pause)
                .start(&log);
            // A ceiling for qemu-arm (the first run also computes the room's matrix).
            let inside = until(Duration::from_secs(60), &log, || {
                let text = std::fs::read_to_string(&log).unwrap_or_default();
                text.lines()
                    .find(|l| l.contains("test write pause: inside the write"))
                    .map(String::from)
            });
            signal(&child, libc::SIGKILL);
            let status = wait(&mut child, Duration::from_secs(10));
            assert_eq!(
                std::os::unix::process::ExitStatusExt::signal(&status),
                Some(libc::SIGKILL)
            );
            kills += 1;
            let text = std::fs::read_to_string(&log).unwrap();
            assert!(!text.contains("panicked"), "{text}");
            // Inside the write: the pause never resumed.
            if !text.contains("test write pause: resumed") {
                mid_write += 1;
            }
            for l in text.lines().filter(|l| l.contains("cycle done")) {
                committed.insert(log_field(l, "time").unwrap().to_string());
            }
            let time = log_field(&inside, "time").unwrap().to_string();
            assert_eq!(log_field(&inside, "point"), Some(point.name()), "{inside}");
            if point.after_commit() {
                committed.insert(time.clone());
            } else {
                lost.insert(time.clone());
            }
            if let Err(e) = check_output(&out, &committed, &lost, Some((point, &time))) {
                panic!(
                    "killed at {} ({time}), round {round}: {e}\n{text}",
                    point.name()
                );
            }
        }
    }
    // A last, clean run repairs the last kill and completes one cycle.
    let log = tmp.path().join("stderr-final.log");
    let mut child = SimRun::new(&config, &out)
        .cycles(1)
        .clock("2017-06-01T10:00:00+02:00", 600)
        .start(&log);
    assert_eq!(wait(&mut child, Duration::from_secs(60)).code(), Some(0));
    let text = std::fs::read_to_string(&log).unwrap();
    assert!(text.contains("output: repaired"), "{text}");
    committed.insert("2017-06-01T10:00:00+02:00".to_string());
    if let Err(e) = check_output(&out, &committed, &lost, None) {
        panic!("after the clean run: {e}\n{text}");
    }
    // By construction every kill landed inside a write; the counts are the report's figures.
    assert_eq!(mid_write, kills);
    assert!(kills >= 14 && !lost.is_empty() && committed.len() > lost.len());
    eprintln!(
        "{kills} kills, {mid_write} inside a write ({} points x {ROUNDS} rounds); {} records \
         kept exactly once, {} killed cycles left nothing",
        WritePoint::ALL.len(),
        committed.len(),
        lost.len()
    );
}

/// A small tmpfs mounted for one test (root only), unmounted when dropped.
struct SmallTmpfs(std::path::PathBuf);

impl SmallTmpfs {
    fn mount(dir: &Path, size: &str) -> Option<Self> {
        std::fs::create_dir_all(dir).unwrap();
        let ok = std::process::Command::new("mount")
            .args(["-t", "tmpfs", "-o", &format!("size={size}"), "tmpfs"])
            .arg(dir)
            .stderr(std::process::Stdio::null())
            .status()
            .is_ok_and(|s| s.success());
        ok.then(|| Self(dir.to_path_buf()))
    }
}

impl Drop for SmallTmpfs {
    fn drop(&mut self) {
        let _ = std::process::Command::new("umount")
            .args(["-l"])
            .arg(&self.0)
            .status();
    }
}

/// Fills the file system of `dir` with `dir/filler`, then leaves `free_bytes` free.
fn fill_leaving(dir: &Path, free_bytes: u64) -> std::path::PathBuf {
    use std::io::Write;
    let path = dir.join("filler");
    let mut f = std::fs::File::create(&path).unwrap();
    let block = vec![0u8; 64 * 1024];
    loop {
        match f.write(&block) {
            Ok(0) => break,
            Ok(_) => {}
            Err(e) if e.raw_os_error() == Some(libc::ENOSPC) => break,
            Err(e) => panic!("filling {}: {e}", path.display()),
        }
    }
    let len = f.metadata().unwrap().len();
    f.set_len(len.saturating_sub(free_bytes)).unwrap();
    path
}

/// Kills the daemon if the test fails before it exits.
struct KillOnDrop(std::process::Child);

impl Drop for KillOnDrop {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// The disk really full: the output on a 1 MiB tmpfs filled to 48 KiB short of full, so
/// the kernel itself answers ENOSPC inside the cycle's writes (no injected error). The
/// daemon flags it (`disk_full` in the log and `/v1/health`), leaves nothing of the failed
/// cycles, keeps retrying, and records its cycles once space comes back.
#[test]
fn a_real_full_disk_is_flagged_rolled_back_and_followed_by_good_cycles() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let log = tmp.path().join("stderr.log");
    let Some(mount) = SmallTmpfs::mount(&out, "1m") else {
        skylux_hps::prerequisite::available_or_skip(
            false,
            skylux_hps::prerequisite::REQUIRE_HOST,
            "cannot mount a tmpfs here (needs root with CAP_SYS_ADMIN)",
        );
        return;
    };
    let cache = tmp.path().join("cache");
    let cache_line = format!("cache_dir = \"{}\"", cache.display());
    let config = config_with(
        tmp.path(),
        &[SMALL, ("# cache_dir = \"...\"", cache_line.as_str())],
        "",
    );
    let filler = fill_leaving(&out, 48 * 1024);
    let mut child = KillOnDrop(
        SimRun::new(&config, &out)
            .cycles(2)
            .clock(T0, 3600)
            .start(&log),
    );
    // The kernel's ENOSPC, flagged as a full disk, again and again while it lasts.
    until(Duration::from_secs(60), &log, || {
        let t = std::fs::read_to_string(&log).unwrap_or_default();
        (t.matches("kind=\"disk_full\"").count() >= 3).then_some(())
    });
    let address = std::fs::read_to_string(out.join("api.address")).unwrap();
    let (code, body) = http_get(address.trim(), "/v1/health");
    assert_eq!(code, 200, "{body}");
    let h: serde_json::Value = serde_json::from_str(&body).unwrap();
    assert_eq!(h["status"], "degraded", "{h}");
    assert_eq!(h["last_error"]["kind"], "disk_full", "{h}");
    let message = h["last_error"]["message"].as_str().unwrap();
    assert!(message.contains("No space left on device"), "{message}");
    let text = std::fs::read_to_string(&log).unwrap();
    assert!(
        !text.contains("(injected)"),
        "a fake error in a real-disk test"
    );
    // Nothing of the failed cycles: no record, no map, no capture.
    assert!(complete_lines(&out.join("results.jsonl")).is_empty());
    for folder in ["maps", "captures"] {
        assert_eq!(
            std::fs::read_dir(out.join(folder)).map_or(0, |d| d.count()),
            0,
            "{folder} after failed cycles"
        );
    }
    // Space comes back: both cycles are recorded once, complete.
    std::fs::remove_file(&filler).unwrap();
    let status = wait(&mut child.0, Duration::from_secs(60));
    assert_eq!(
        status.code(),
        Some(0),
        "{}",
        std::fs::read_to_string(&log).unwrap()
    );
    let lines = complete_lines(&out.join("results.jsonl"));
    assert_eq!(lines.len(), 2);
    let sensors = records(&out).unwrap()[0].illuminance.len();
    let csv = std::fs::read_to_string(out.join("illuminance.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 2 * sensors, "{csv}");
    let latest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("latest.json")).unwrap()).unwrap();
    let last: serde_json::Value = serde_json::from_str(&lines[1]).unwrap();
    assert_eq!(latest["time"], last["time"]);
    drop(mount);
}

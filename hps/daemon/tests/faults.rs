//! Faults: each injected fault is logged with a clear message and retried with back-off, the
//! daemon keeps running, and no earlier result is lost or corrupted. A bad configuration is
//! refused with the file, line and field. A daemon killed with SIGKILL, again and again, in
//! the middle of its work, leaves every earlier result intact.

mod common;

use common::*;
use std::path::Path;
use std::time::Duration;

const T0: &str = "2017-05-08T10:00:00+02:00";
/// Smaller frames than the example's (81 x 60 samples): these tests run many cycles, also
/// under qemu-arm on a shared machine.
const SMALL: (&str, &str) = ("skip = 16 ", "skip = 32 ");

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
    if !make_read_only(&refs, true) {
        eprintln!(
            "SKIPPED: cannot make a directory read-only here (root without chattr +i); the \
             disk-full path is covered by the injected disk_full fault"
        );
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

#[test]
fn sigkill_in_a_loop_never_corrupts_earlier_results() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let results = out.join("results.jsonl");
    let csv = out.join("illuminance.csv");
    let config = config_with(tmp.path(), &[SMALL], "");
    let mut earlier: Vec<u8> = Vec::new();
    let mut earlier_csv: Vec<u8> = Vec::new();
    let mut kills_with_partial = 0;
    for round in 0..5u64 {
        let log = tmp.path().join(format!("stderr-{round}.log"));
        let start_time = format!("2017-05-{:02}T10:00:00+02:00", 8 + round);
        let mut child = SimRun::new(&config, &out)
            .clock(&start_time, 600)
            .start(&log);
        // Let it complete at least one new cycle, then kill it at a varying moment of the
        // next one (the writes are a few ms of a cycle; some rounds land in them).
        let n = complete_lines(&results).len();
        until(Duration::from_secs(45), &log, || {
            (complete_lines(&results).len() > n).then_some(())
        });
        std::thread::sleep(Duration::from_millis(37 * round));
        signal(&child, libc::SIGKILL);
        let status = wait(&mut child, Duration::from_secs(10));
        assert_eq!(
            std::os::unix::process::ExitStatusExt::signal(&status),
            Some(libc::SIGKILL)
        );

        // Every earlier result is still there, byte for byte; every complete line parses.
        let now = std::fs::read(&results).unwrap();
        assert!(
            now.starts_with(&earlier),
            "round {round}: an earlier result changed"
        );
        let now_csv = std::fs::read(&csv).unwrap();
        assert!(
            now_csv.starts_with(&earlier_csv),
            "round {round}: the CSV changed"
        );
        if now.last().is_some_and(|&b| b != b'\n') {
            kills_with_partial += 1;
        }
        for l in complete_lines(&results) {
            serde_json::from_str::<serde_json::Value>(&l).expect("a complete JSON line");
        }
        // latest.json is replaced by rename: absent (killed before the first one) or whole.
        if let Ok(latest) = std::fs::read_to_string(out.join("latest.json")) {
            serde_json::from_str::<serde_json::Value>(&latest).expect("latest.json is whole");
        }
        // What the next start keeps: the complete lines.
        earlier = complete_lines(&results).concat().into_bytes();
        let csv_text = String::from_utf8(now_csv).unwrap();
        earlier_csv = csv_text
            .split_inclusive('\n')
            .filter(|l| l.ends_with('\n'))
            .collect::<String>()
            .into_bytes();
    }
    // A last, clean run repairs any partial line and appends after the earlier results.
    let log = tmp.path().join("stderr-final.log");
    let mut child = SimRun::new(&config, &out)
        .cycles(1)
        .clock("2017-05-20T10:00:00+02:00", 600)
        .start(&log);
    assert_eq!(wait(&mut child, Duration::from_secs(40)).code(), Some(0));
    let text = std::fs::read_to_string(&results).unwrap();
    assert!(text.as_bytes().starts_with(&earlier));
    assert!(text.ends_with('\n'));
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines.len() >= 6, "{} lines", lines.len());
    for l in &lines {
        serde_json::from_str::<serde_json::Value>(l).expect("every line parses after repair");
    }
    eprintln!("{kills_with_partial} of 5 kills left a partial line (repaired on restart)");
}

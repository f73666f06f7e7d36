//! Soak (issue 23 item 6): `skyluxd --sim` on a simulated clock for many cycles with faults
//! drawn at random, watched from outside the whole time:
//!
//! - resident memory and open file descriptors sampled from `/proc/PID` while it runs, and
//!   their growth per successful cycle fitted over the second half (after warm-up): flat;
//! - the API asked for `/v1/health` at every sample: it answers every time;
//! - at the end, every successful cycle recorded exactly once (records in time order, none
//!   partial, the CSV's rows match), `latest.json` is the last record, and retention held.
//!
//! CI runs [`CI_CYCLES`]; the 2,000 (docs/reliability.md has the figures):
//! `SKYLUX_SOAK_CYCLES=2000 cargo test --test soak -- --nocapture` (`SKYLUX_SOAK_SAMPLES=FILE`
//! writes the samples as CSV). Native only: under
//! qemu-arm, `/proc/PID` would be the emulator's.

#![cfg(not(target_arch = "arm"))]

mod common;

use common::*;
use std::path::Path;
use std::time::{Duration, Instant};

/// Successful cycles in CI (about 35 s): enough that the second half starts past the
/// allocator's warm-up (resident memory settles within about 200 cycles).
const CI_CYCLES: u64 = 400;
/// Share of attempts given a fault, and the kinds drawn (uniformly).
const FAULT_PROBABILITY: f64 = 0.05;
const FAULT_KINDS: [&str; 6] = [
    "sensor_absent",
    "i2c_nack",
    "dma_timeout",
    "flagged_frame",
    "disk_full",
    "clock_back",
];
/// Retention, small so that it acts hundreds of times.
const MAX_MAPS: usize = 5;
const MAX_CAPTURES: usize = 3;
/// Growth allowed over the second half (the fitted slope times its cycles). Resident memory
/// climbs by about 1 MB over the first 200 cycles, still by about 0.5 KB a cycle between 200
/// and 400 (95 KB over CI's second half), then wanders ±50 KB with no trend (2,000-cycle run,
/// docs/reliability.md). 256 KB so CI does not fail on that tail: CI's run catches a leak of
/// 1.3 KB or more per cycle (one record is about 1 KB), the 2,000-cycle run one of 0.26 KB.
const RSS_GROWTH_LIMIT_KB: f64 = 256.0;
const FD_GROWTH_LIMIT: f64 = 1.0;

/// SplitMix64 (Steele, Lea & Flood 2014): a fixed, seedable draw without a dependency.
struct SplitMix(u64);
impl SplitMix {
    fn next_f64(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `[[sim.fault]]` tables for attempts 1..=attempts, each faulty with [`FAULT_PROBABILITY`].
fn random_faults(seed: u64, attempts: u64) -> (String, Vec<(u64, &'static str)>) {
    let mut rng = SplitMix(seed);
    let mut drawn = Vec::new();
    for attempt in 1..=attempts {
        if rng.next_f64() < FAULT_PROBABILITY {
            let k = (rng.next_f64() * FAULT_KINDS.len() as f64) as usize;
            drawn.push((attempt, FAULT_KINDS[k.min(FAULT_KINDS.len() - 1)]));
        }
    }
    let text = drawn
        .iter()
        .map(|(a, k)| format!("[[sim.fault]]\nattempt = {a}\nkind = \"{k}\"\n"))
        .collect();
    (text, drawn)
}

/// One look from outside: successful cycles so far, resident KB, open descriptors.
#[derive(Clone, Copy, Debug)]
struct Sample {
    cycles_ok: u64,
    rss_kb: f64,
    fds: f64,
}

fn resident_kb(pid: u32) -> Option<f64> {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let line = status.lines().find(|l| l.starts_with("VmRSS:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

fn open_fds(pid: u32) -> Option<f64> {
    Some(std::fs::read_dir(format!("/proc/{pid}/fd")).ok()?.count() as f64)
}

/// Least-squares slope of y over x.
fn slope(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
    });
    sxy / sxx
}

fn count_files(dir: &Path) -> usize {
    std::fs::read_dir(dir).map_or(0, |d| d.count())
}

#[test]
fn a_long_run_with_random_faults_stays_flat_records_every_cycle_once_and_keeps_retention() {
    let cycles: u64 = std::env::var("SKYLUX_SOAK_CYCLES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(CI_CYCLES);
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let log = tmp.path().join("stderr.log");
    // Faults for more attempts than the run can make (each clock_back costs ~30 attempts).
    let (faults, drawn) = random_faults(23, cycles * 2 + 200);
    let config = config_with(
        tmp.path(),
        &[
            // The soak's world stays small (162 x 120 samples): it measures the daemon,
            // not the sensor.
            (SIM_SKIP, "skip = 16 # 2592/16"),
            ("max_maps = 48 ", &format!("max_maps = {MAX_MAPS} ")),
            (
                "max_captures = 24 ",
                &format!("max_captures = {MAX_CAPTURES} "),
            ),
        ],
        &faults,
    );
    let began = Instant::now();
    let mut child = SimRun::new(&config, &out)
        .cycles(cycles)
        .clock("2017-05-08T05:00:00+02:00", 600)
        .start(&log);
    let pid = child.id();
    let address = until(Duration::from_secs(60), &log, || {
        std::fs::read_to_string(out.join("api.address")).ok()
    });
    let address = address.trim().to_string();

    // Watch until it exits: every sample asks the API and reads /proc.
    let mut samples = Vec::new();
    let mut api_answers = 0u64;
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        assert!(
            began.elapsed() < Duration::from_secs(60 + cycles / 2),
            "the soak did not finish in time; log tail:\n{}",
            tail(&log)
        );
        let (rss, fds) = (resident_kb(pid), open_fds(pid));
        // The process may exit between the /proc reads and the request: only a live
        // daemon's silence is a failure.
        let answer = std::panic::catch_unwind(|| http_get(&address, "/v1/health"));
        match (answer, rss, fds) {
            (Ok((200, body)), Some(rss_kb), Some(fds)) => {
                api_answers += 1;
                let h: serde_json::Value = serde_json::from_str(&body).unwrap();
                let cycles_ok = h["cycles_ok"].as_u64().unwrap();
                samples.push(Sample {
                    cycles_ok,
                    rss_kb,
                    fds,
                });
            }
            (answer, _, _) => {
                if child.try_wait().unwrap().is_none() {
                    panic!(
                        "the API did not answer a live daemon: {:?}; log tail:\n{}",
                        answer.map(|(c, _)| c),
                        tail(&log)
                    );
                }
            }
        }
        std::thread::sleep(Duration::from_millis(100));
    };
    let text = std::fs::read_to_string(&log).unwrap();
    assert_eq!(status.code(), Some(0), "{}", tail(&log));
    assert!(!text.contains("panicked"), "a panic in the log");
    let wall_s = began.elapsed().as_secs_f64();

    // Every successful cycle recorded exactly once, in time order, none partial.
    let lines = complete_lines(&out.join("results.jsonl"));
    let all = std::fs::read_to_string(out.join("results.jsonl")).unwrap();
    assert!(all.ends_with('\n'), "a partial last record");
    assert_eq!(lines.len() as u64, cycles, "records for {cycles} cycles");
    let records: Vec<serde_json::Value> = lines
        .iter()
        .map(|l| serde_json::from_str(l).expect("a record parses"))
        .collect();
    let times: Vec<chrono::DateTime<chrono::FixedOffset>> = records
        .iter()
        .map(|r| chrono::DateTime::parse_from_rfc3339(r["time"].as_str().unwrap()).unwrap())
        .collect();
    assert!(
        times.windows(2).all(|w| w[0] < w[1]),
        "records out of time order (a cycle recorded twice or the clock followed back)"
    );
    let sensors = records[0]["illuminance"].as_array().unwrap().len();
    let csv = std::fs::read_to_string(out.join("illuminance.csv")).unwrap();
    assert_eq!(csv.lines().count() - 1, lines.len() * sensors, "CSV rows");
    let latest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("latest.json")).unwrap()).unwrap();
    assert_eq!(latest["time"], records.last().unwrap()["time"]);
    // Retention held: exactly the newest maps and captures, nothing else.
    assert_eq!(count_files(&out.join("maps")), MAX_MAPS, "maps kept");
    assert_eq!(
        count_files(&out.join("captures")),
        MAX_CAPTURES,
        "captures kept"
    );
    for r in records.iter().rev().take(MAX_MAPS) {
        assert!(
            out.join(r["map"].as_str().unwrap()).exists(),
            "{}",
            r["map"]
        );
    }

    // The faults happened and were survived: each failure logged with its kind.
    let failures = text.lines().filter(|l| l.contains("cycle failed")).count();
    let injected = drawn
        .iter()
        .filter(|(a, _)| *a <= cycles + failures as u64)
        .count();
    assert!(injected >= 5, "only {injected} faults fell inside the run");
    for kind in ["sensor_absent", "i2c_nack", "dma_timeout", "flagged_frame"] {
        let fell = drawn
            .iter()
            .any(|(a, k)| *k == kind && *a <= cycles + failures as u64);
        if fell {
            assert!(
                text.contains(&format!("kind=\"{kind}\"")),
                "a {kind} fault drawn but not logged"
            );
        }
    }

    if let Ok(path) = std::env::var("SKYLUX_SOAK_SAMPLES") {
        let rows: String = samples
            .iter()
            .map(|s| format!("{},{},{}\n", s.cycles_ok, s.rss_kb, s.fds))
            .collect();
        std::fs::write(path, format!("cycles_ok,resident_kb,open_fds\n{rows}")).unwrap();
    }

    // Flat: resident memory and descriptors against successful cycles, second half.
    let half: Vec<&Sample> = samples
        .iter()
        .filter(|s| s.cycles_ok >= cycles / 2)
        .collect();
    assert!(
        half.len() >= 10,
        "{} samples in the second half",
        half.len()
    );
    let rss_slope = slope(
        &half
            .iter()
            .map(|s| (s.cycles_ok as f64, s.rss_kb))
            .collect::<Vec<_>>(),
    );
    let fd_slope = slope(
        &half
            .iter()
            .map(|s| (s.cycles_ok as f64, s.fds))
            .collect::<Vec<_>>(),
    );
    let (rss_min, rss_max) = samples.iter().fold((f64::MAX, 0.0f64), |(a, b), s| {
        (a.min(s.rss_kb), b.max(s.rss_kb))
    });
    let (fd_min, fd_max) = samples
        .iter()
        .fold((f64::MAX, 0.0f64), |(a, b), s| (a.min(s.fds), b.max(s.fds)));
    println!(
        "soak: {cycles} cycles, {failures} failed attempts ({injected} faults drawn in range), \
         {wall_s:.0} s; {} samples, {api_answers} API answers; resident {rss_min:.0}-{rss_max:.0} KB, \
         slope {rss_slope:.4} KB/cycle (second half); descriptors {fd_min}-{fd_max}, slope \
         {fd_slope:.5}/cycle",
        samples.len()
    );
    let span = (cycles - cycles / 2) as f64;
    assert!(
        rss_slope * span < RSS_GROWTH_LIMIT_KB,
        "resident memory grows {rss_slope:.3} KB per cycle: {:.0} KB over the second half",
        rss_slope * span
    );
    assert!(
        fd_slope * span < FD_GROWTH_LIMIT,
        "descriptors grow {fd_slope:.5} per cycle: {:.2} over the second half",
        fd_slope * span
    );
}

fn tail(log: &Path) -> String {
    let text = std::fs::read_to_string(log).unwrap_or_default();
    let lines: Vec<&str> = text.lines().collect();
    lines[lines.len().saturating_sub(30)..].join("\n")
}

//! Helpers shared by the daemon's end-to-end tests: start the real `skyluxd` binary (through
//! qemu-arm when the tests themselves run under it), talk HTTP with a plain TcpStream, read
//! the output files.

#![allow(dead_code)]

use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, Stdio};
use std::time::{Duration, Instant};

/// The repository's example configuration.
pub fn example_config() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../skyluxd.toml")
}

/// The example configuration with its relative paths made absolute and `extra` appended
/// (the example ends in its `[sim]` section, so `[[sim.fault]]` tables can follow), written
/// into `dir`.
/// The `[sim]` section's skip line of the example (the `[fabric]` section also reads
/// `skip = 4`): tests that shrink the simulated camera replace this.
pub const SIM_SKIP: &str = "skip = 4                      # 2592/4";

pub fn config_with(dir: &Path, replace: &[(&str, &str)], extra: &str) -> PathBuf {
    let hps = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut text = std::fs::read_to_string(example_config()).unwrap();
    text = text.replace(
        "\"daemon/device.toml\"",
        &format!("\"{}\"", hps.join("daemon/device.toml").display()),
    );
    text = text.replace(
        "\"../../shared/",
        &format!("\"{}/", hps.join("../../shared").display()),
    );
    for (a, b) in replace {
        assert!(text.contains(a), "the example config has no `{a}`");
        text = text.replace(a, b);
    }
    text.push_str(extra);
    let path = dir.join("skyluxd.toml");
    std::fs::write(&path, text).unwrap();
    path
}

/// The one `skyluxd --sim` command line of the tests: `--config`, `--out`, an ephemeral API
/// port, and optionally `--cycles`, the simulated clock and `--serve-after`.
pub struct SimRun {
    config: String,
    out: String,
    cycles: Option<u64>,
    clock: Option<(String, u64)>,
    serve_after: bool,
    env: Vec<(String, String)>,
}

impl SimRun {
    pub fn new(config: &Path, out: &Path) -> Self {
        Self {
            config: config.to_str().unwrap().to_string(),
            out: out.to_str().unwrap().to_string(),
            cycles: None,
            clock: None,
            serve_after: false,
            env: Vec::new(),
        }
    }
    /// Stop after `n` successful cycles.
    pub fn cycles(mut self, n: u64) -> Self {
        self.cycles = Some(n);
        self
    }
    /// The simulated clock: first capture at `start` (RFC 3339), `step_s` apart.
    pub fn clock(mut self, start: &str, step_s: u64) -> Self {
        self.clock = Some((start.to_string(), step_s));
        self
    }
    pub fn serve_after(mut self) -> Self {
        self.serve_after = true;
        self
    }
    /// An environment variable for the daemon (e.g. `SKYLUX_TEST_WRITE_PAUSE`).
    pub fn env(mut self, key: &str, value: &str) -> Self {
        self.env.push((key.to_string(), value.to_string()));
        self
    }
    pub fn args(&self) -> Vec<String> {
        let mut a: Vec<String> = vec!["--sim".into()];
        if let Some(n) = self.cycles {
            a.extend(["--cycles".into(), n.to_string()]);
        }
        a.extend([
            "--config".into(),
            self.config.clone(),
            "--out".into(),
            self.out.clone(),
            "--api".into(),
            "127.0.0.1:0".into(),
        ]);
        if let Some((t, s)) = &self.clock {
            a.extend([
                "--time-start".into(),
                t.clone(),
                "--time-step-s".into(),
                s.to_string(),
            ]);
        }
        if self.serve_after {
            a.push("--serve-after".into());
        }
        a
    }
    /// Starts it, stderr into `log`.
    pub fn start(&self, log: &Path) -> Child {
        start_with_env(&self.args(), &self.env, log)
    }
}

/// Starts skyluxd with `args`, stderr captured into `dir/stderr.log`.
pub fn start<S: AsRef<std::ffi::OsStr>>(args: &[S], log: &Path) -> Child {
    start_with_env(args, &[], log)
}

/// [`start`] with environment variables added.
pub fn start_with_env<S: AsRef<std::ffi::OsStr>>(
    args: &[S],
    env: &[(String, String)],
    log: &Path,
) -> Child {
    let exe = Path::new(env!("CARGO_BIN_EXE_skyluxd"));
    let mut cmd = skyluxd::spawn::command_for(exe);
    cmd.args(args)
        .envs(env.iter().map(|(k, v)| (k, v)))
        .stdout(Stdio::null())
        .stderr(std::fs::File::create(log).unwrap());
    cmd.spawn().expect("skyluxd starts")
}

/// Waits for the child to exit (at most `limit`), killing it on timeout.
pub fn wait(child: &mut Child, limit: Duration) -> std::process::ExitStatus {
    let end = Instant::now() + limit;
    loop {
        if let Some(s) = child.try_wait().unwrap() {
            return s;
        }
        if Instant::now() > end {
            let _ = child.kill();
            panic!("skyluxd did not exit within {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// Polls `f` until it returns Some, or panics after `limit`, showing the log.
pub fn until<T>(limit: Duration, log: &Path, mut f: impl FnMut() -> Option<T>) -> T {
    let end = Instant::now() + limit;
    loop {
        if let Some(v) = f() {
            return v;
        }
        if Instant::now() > end {
            panic!(
                "timed out after {limit:?}; daemon log:\n{}",
                std::fs::read_to_string(log).unwrap_or_default()
            );
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// Complete lines of `results.jsonl` (a partial last line is not counted).
pub fn complete_lines(path: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let mut lines: Vec<String> = text.split_inclusive('\n').map(String::from).collect();
    if lines.last().is_some_and(|l| !l.ends_with('\n')) {
        lines.pop();
    }
    lines
}

/// A GET over a plain TcpStream: (status, body).
pub fn http_get(address: &str, path: &str) -> (u16, String) {
    http(address, "GET", path)
}

pub fn http(address: &str, method: &str, path: &str) -> (u16, String) {
    let mut s = std::net::TcpStream::connect(address).expect("connect to the API");
    s.set_read_timeout(Some(Duration::from_secs(20))).unwrap();
    write!(
        s,
        "{method} {path} HTTP/1.1\r\nHost: {address}\r\nConnection: close\r\nContent-Length: 0\r\n\r\n"
    )
    .unwrap();
    let mut text = String::new();
    s.read_to_string(&mut text).unwrap();
    let status = text
        .split_whitespace()
        .nth(1)
        .and_then(|c| c.parse().ok())
        .unwrap_or(0);
    let body = text
        .split_once("\r\n\r\n")
        .map(|(_, b)| b.to_string())
        .unwrap_or_default();
    (status, body)
}

/// Sends `signal` to the child.
pub fn signal(child: &Child, signal: i32) {
    let rc = unsafe { libc::kill(child.id() as libc::pid_t, signal) };
    assert_eq!(rc, 0, "kill({}, {signal})", child.id());
}

/// Sensor names and lux of a record's `illuminance` or `truth_illuminance`.
fn lux_of(sensors: &serde_json::Value) -> Vec<(String, f64)> {
    sensors
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            (
                s["sensor"].as_str().unwrap().to_string(),
                s["lux"].as_f64().unwrap(),
            )
        })
        .collect()
}

/// Per sensor, the median over `records` (sun above 10°) of measured / world − 1; prints
/// each cycle's values.
pub fn interior_median_errors(records: &[serde_json::Value]) -> Vec<(String, f64)> {
    let mut ratios: Vec<(String, Vec<f64>)> = vec![];
    for r in records {
        if r["sun"]["spa_altitude_deg"].as_f64().unwrap() <= 10.0 {
            continue;
        }
        let measured = lux_of(&r["illuminance"]);
        let truth = lux_of(&r["truth_illuminance"]);
        assert_eq!(measured.len(), truth.len());
        if ratios.is_empty() {
            ratios = measured.iter().map(|(n, _)| (n.clone(), vec![])).collect();
        }
        let line: Vec<String> = measured
            .iter()
            .zip(&truth)
            .zip(ratios.iter_mut())
            .map(|(((name, m), (tn, t)), (_, v))| {
                assert_eq!(name, tn);
                v.push(m / t - 1.0);
                format!("{name} {m:.0}/{t:.0}")
            })
            .collect();
        println!("{}: interior {}", r["time"], line.join(", "));
    }
    assert!(!ratios.is_empty(), "no cycle with the sun above 10°");
    ratios
        .into_iter()
        .map(|(name, mut v)| {
            v.sort_by(f64::total_cmp);
            (name, v[v.len() / 2])
        })
        .collect()
}

/// The example configuration on a small fabric window: a 128 x 96 array window around the lens
/// axis read with skip 8, unbinned (16 x 12 samples), two exposures of 300 and 1000 µs at the
/// highest analog gain (7.875) so that the sky near the horizon lands in the valid range, and
/// `[sim] source = source` (`fabric`: the cycle-accurate core; `fabric-model`: the behavioural
/// fabric), every capture raw (`hdr = "hps"`).
pub fn tiny_fabric_config(dir: &Path, source: &str) -> PathBuf {
    config_with(
        dir,
        &[
            (
                "exposures_us = [20.0, 421.0, 8870.0, 186900.0, 500000.0]",
                "exposures_us = [300.0, 1000.0]",
            ),
            ("source = \"sim\"", &format!("source = \"{source}\"")),
            ("gain = [1.0, 1.0, 1.0, 1.0, 7.875]", "gain = 7.875"),
            ("row_start = 54 ", "row_start = 924 "),
            ("col_start = 16 ", "col_start = 1232 "),
            ("width = 2592 ", "width = 128 "),
            ("height = 1944\n", "height = 96\n"),
            ("skip = 4 ", "skip = 8 "),
            ("bin = 4 ", "bin = 1 "),
            ("frame_timeout_s = 2.0 ", "frame_timeout_s = 120.0 "),
            // Raw frames, so the captures are kept and merged on the HPS (`tiny_map_config`
            // in fabric_sim.rs makes maps).
            ("hdr = \"fabric\" ", "hdr = \"hps\" "),
        ],
        "",
    )
}

/// Runs `skyluxd --sim` on `config` for `cycles` captures `step_s` apart from `start` (RFC
/// 3339), writing into `out` (stderr into `log`), waits for it to exit on its own, and returns
/// its records.
pub fn sim_records(
    config: &Path,
    out: &Path,
    log: &Path,
    (start, step_s): (&str, u64),
    cycles: u64,
    limit: Duration,
) -> Vec<serde_json::Value> {
    let mut child = SimRun::new(config, out)
        .cycles(cycles)
        .clock(start, step_s)
        .start(log);
    let results = out.join("results.jsonl");
    let lines = until(limit, log, || {
        let l = complete_lines(&results);
        (l.len() as u64 >= cycles).then_some(l)
    });
    // `--cycles` done: the daemon exits on its own.
    assert!(
        child.wait().unwrap().success(),
        "skyluxd did not exit cleanly"
    );
    lines
        .iter()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// The map the RTL's golden models make of `frames` (a set, long to short, as the sensor sent
/// them) with the grouping map mode programs for `device`: the Bayer grouper's words
/// (`skylux_rtl::bayer::golden`), then the HDR selection (`skylux_rtl::hdr::golden`).
pub fn golden_map(
    device: &skylux_hps::camera::DeviceConfig,
    hdr: &skylux_regmap::hdr_values::HdrConfig,
    frames: &[skylux_hps::campaign::RawFrame],
) -> Vec<u32> {
    use skylux_rtl::hdr::golden::{select, SetFrame};
    let grouped: Vec<Vec<u32>> = frames.iter().map(|f| golden_words(device, f)).collect();
    let set: Vec<SetFrame> = grouped
        .iter()
        .enumerate()
        .map(|(k, words)| SetFrame {
            exposure_index: k as u8,
            first_of_set: k == 0,
            words,
        })
        .collect();
    select(hdr, &set)
}

/// The grouped words of `frame` (`skylux_rtl::bayer::golden`) with the grouping map mode
/// programs for `device`.
pub fn golden_words(
    device: &skylux_hps::camera::DeviceConfig,
    f: &skylux_hps::campaign::RawFrame,
) -> Vec<u32> {
    use skylux_rtl::bayer::golden::{expected_words, BayerConfig, Frame, Phase};
    let g = skyluxd::fabric_source::MapMode::of_device(
        device,
        skylux_hps::campaign::BayerPattern::GRBG,
    )
    .grouping;
    let bayer = BayerConfig {
        phase: Phase::from_register(g.phase),
        black: g.black_level_dn as u16,
        valid_min: g.valid_min_dn as u16,
        valid_max: g.valid_max_dn as u16,
        weight_r: g.weight_r_q2_14 as u16,
        weight_g: g.weight_g_q2_14 as u16,
        weight_b: g.weight_b_q2_14 as u16,
        raw: false,
    };
    let frame = Frame {
        width: f.width,
        height: f.height,
        samples: f.samples_dn.clone(),
    };
    expected_words(&frame, &bayer)
}

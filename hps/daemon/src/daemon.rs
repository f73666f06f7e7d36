//! The main loop: set up, then capture → process → write on the schedule, with failures
//! logged and retried with capped exponential back-off, until SIGTERM/SIGINT or `--cycles`.
//!
//! Nothing a cycle does can end the daemon: every error (and even a panic inside the
//! pipeline) is caught, logged with its kind, counted for `/v1/health` and `/v1/metrics`,
//! and the cycle is retried later. Only set-up errors (configuration, room, API address)
//! end the process, with a non-zero status systemd can act on.
//!
//! On SIGTERM or SIGINT the loop stops at the next stage boundary: a capture in progress is
//! discarded if it has not been processed yet (nothing of it is written; the fabric source
//! ends its wait for frames at once and releases every ring slot), and a cycle already
//! writing finishes its (atomic) writes. During the first daylight-coefficient computation
//! (minutes) the computation is abandoned and nothing is cached. Then the daemon exits 0.
//!
//! On SIGHUP the configuration file is read and validated again and applied from the next
//! cycle; a bad file is logged with its file, line and field and the running configuration
//! kept (see `reload_config` for what a reload can change).
//!
//! On SIGUSR1 the next capture is raw (in map mode, the default: `raw_captures`): merged on
//! the HPS and kept in campaign format, for calibration and audits.

use crate::api::{ApiServer, ApiState, ErrorReport, SharedState};
use crate::config::{Config, FaultKind, Overrides, SimSourceKind};
use crate::cycle::{CycleError, Pipeline};
use crate::notify::Notifier;
use crate::output::{FaultHook, Output, API_ADDRESS_FILE};
use crate::raw_captures::RawSchedule;
use crate::source::{CaptureSource, SimSource, SourceError};
use chrono::{DateTime, FixedOffset, Timelike, Utc};
use std::panic::AssertUnwindSafe;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Exit statuses (sysexits.h): a bad configuration is not worth restarting for.
pub const EXIT_CONFIG: i32 = 78;
pub const EXIT_SOFTWARE: i32 = 70;
pub const EXIT_UNAVAILABLE: i32 = 69;
pub const EXIT_CANTCREAT: i32 = 73;

/// What `main` parsed.
#[derive(Clone, Debug, Default)]
pub struct Options {
    pub config: PathBuf,
    pub sim: bool,
    /// Stop after this many successful cycles.
    pub cycles: Option<u64>,
    /// Simulated clock: first capture time, and seconds between captures.
    pub time_start: Option<DateTime<FixedOffset>>,
    pub time_step_s: Option<f64>,
    /// Keep serving the API after `--cycles` until a signal.
    pub serve_after: bool,
    pub overrides: Overrides,
}

/// The daemon's clock: the wall clock, or a simulated one that jumps instead of sleeping.
enum Clock {
    Wall {
        offset: FixedOffset,
        next_due: Option<Instant>,
    },
    Sim {
        now: DateTime<FixedOffset>,
        step: chrono::TimeDelta,
    },
}

impl Clock {
    fn now(&self) -> DateTime<FixedOffset> {
        match self {
            // Whole seconds: capture stamps and file names have second resolution.
            Clock::Wall { offset, .. } => {
                let now = Utc::now().with_timezone(offset);
                now.with_nanosecond(0).unwrap_or(now)
            }
            Clock::Sim { now, .. } => *now,
        }
    }
}

/// Sleeps up to `d`, waking for the stop flag and the watchdog.
fn sleep_interruptible(
    d: Duration,
    stop: &AtomicBool,
    notifier: &Notifier,
    last_ping: &mut Instant,
) {
    let end = Instant::now() + d;
    loop {
        ping(notifier, last_ping);
        if stop.load(Ordering::Relaxed) {
            return;
        }
        let now = Instant::now();
        if now >= end {
            return;
        }
        std::thread::sleep((end - now).min(Duration::from_millis(100)));
    }
}

fn ping(notifier: &Notifier, last_ping: &mut Instant) {
    if let Some(interval) = notifier.watchdog_interval() {
        if last_ping.elapsed() >= interval {
            notifier.watchdog();
            *last_ping = Instant::now();
        }
    }
}

/// Back-off after `failures` consecutive failures: initial · 2^(failures − 1), capped.
pub fn backoff_s(initial_s: f64, max_s: f64, failures: u64) -> f64 {
    let exp = failures.saturating_sub(1).min(62) as i32;
    (initial_s * 2f64.powi(exp)).min(max_s)
}

/// Output faults from the `--sim` schedule, by attempt.
struct SimOutputFaults<'a> {
    rules: &'a [crate::config::FaultRule],
    attempt: u64,
}

impl FaultHook for SimOutputFaults<'_> {
    fn output_fault(&mut self) -> Option<std::io::Error> {
        (SimSource::fault_for(self.rules, self.attempt) == Some(FaultKind::DiskFull))
            .then(|| std::io::Error::from_raw_os_error(libc::ENOSPC))
    }
}

/// Runs the daemon; returns the process exit status.
pub fn run(options: &Options) -> i32 {
    match start(options) {
        Ok(mut daemon) => {
            daemon.serve();
            daemon.notifier.stopping();
            daemon.api.stop();
            tracing::info!(
                cycles_ok = daemon.counts.ok,
                attempts = daemon.counts.attempts,
                "skyluxd stopped"
            );
            0
        }
        Err(code) => code,
    }
}

/// The stop (SIGTERM, SIGINT), reload (SIGHUP) and raw-capture request (SIGUSR1) flags.
struct Signals {
    stop: Arc<AtomicBool>,
    reload: Arc<AtomicBool>,
    raw_request: Arc<AtomicBool>,
}

/// Cycles counted since start.
#[derive(Clone, Copy, Debug, Default)]
struct CycleCounts {
    /// Cycles that wrote their results.
    ok: u64,
    attempts: u64,
    /// Failures since the last success.
    consecutive_failures: u64,
}

/// A started daemon: everything the schedule needs.
struct Daemon<'a> {
    options: &'a Options,
    config: Config,
    kind: SourceKind,
    source: Box<dyn CaptureSource>,
    pipeline: Pipeline,
    signals: Signals,
    notifier: Notifier,
    last_ping: Instant,
    state: SharedState,
    api: ApiServer,
    clock: Clock,
    /// Opened lazily, so a full or read-only disk at start is retried like any other failure.
    output: Option<Output>,
    api_address_written: bool,
    counts: CycleCounts,
    /// When a capture is raw in map mode.
    raw_schedule: RawSchedule,
}

/// Start-up: configuration, signals, hardware and source, the room, the API and the clock.
/// `Err`: the exit status (0 when a stop was requested during the room's computation).
fn start(options: &Options) -> Result<Daemon<'_>, i32> {
    let config = Config::load(&options.config, &options.overrides).map_err(|e| {
        tracing::error!(kind = "config", "refusing to start: {e}");
        EXIT_CONFIG
    })?;
    check_clock_options(options)?;
    tracing::info!(
        config = %config.path.display(),
        output = %config.output.dir.display(),
        sim = options.sim,
        "skyluxd {} starting",
        env!("CARGO_PKG_VERSION")
    );
    let signals = install_signal_handlers()?;
    let (kind, source) = open_source(options, &config, &signals.stop)?;
    let notifier = Notifier::from_env();
    let last_ping = Instant::now();
    let pipeline = compute_room(&config, &signals.stop, &notifier)?;
    let (state, api) = start_api(&config)?;
    let offset = config.utc_offset();
    let clock = match (options.time_start, options.time_step_s) {
        (Some(start), Some(step)) => Clock::Sim {
            now: start.with_timezone(&offset),
            step: chrono::TimeDelta::milliseconds((step * 1e3).round() as i64),
        },
        _ => Clock::Wall {
            offset,
            next_due: None,
        },
    };
    notifier.ready(&format!("API on {}", api.address));
    let raw_schedule = RawSchedule::new(config.fabric.raw_every_s);
    Ok(Daemon {
        options,
        config,
        kind,
        source,
        pipeline,
        signals,
        notifier,
        last_ping,
        state,
        api,
        clock,
        output: None,
        api_address_written: false,
        counts: CycleCounts::default(),
        raw_schedule,
    })
}

/// The simulated clock's options: both or neither, only with `--sim`, a step from 1 s to a
/// year.
fn check_clock_options(options: &Options) -> Result<(), i32> {
    if let (Some(_), None) | (None, Some(_)) = (options.time_start, options.time_step_s) {
        tracing::error!(
            kind = "config",
            "--time-start and --time-step-s go together"
        );
        return Err(EXIT_CONFIG);
    }
    if options.time_start.is_some() && !options.sim {
        tracing::error!(
            kind = "config",
            "a simulated clock (--time-start) needs --sim"
        );
        return Err(EXIT_CONFIG);
    }
    if let Some(s) = options.time_step_s {
        if !(s.is_finite() && (1.0..=86_400.0 * 366.0).contains(&s)) {
            tracing::error!(kind = "config", "--time-step-s {s}: expected 1 s to a year");
            return Err(EXIT_CONFIG);
        }
    }
    Ok(())
}

fn install_signal_handlers() -> Result<Signals, i32> {
    let stop = Arc::new(AtomicBool::new(false));
    for signal in [signal_hook::consts::SIGTERM, signal_hook::consts::SIGINT] {
        if let Err(e) = signal_hook::flag::register(signal, stop.clone()) {
            tracing::error!(error = %e, "cannot install the signal handler");
            return Err(EXIT_SOFTWARE);
        }
    }
    let reload = Arc::new(AtomicBool::new(false));
    let raw_request = Arc::new(AtomicBool::new(false));
    for (signal, flag) in [
        (signal_hook::consts::SIGHUP, &reload),
        (signal_hook::consts::SIGUSR1, &raw_request),
    ] {
        if let Err(e) = signal_hook::flag::register(signal, flag.clone()) {
            tracing::error!(error = %e, signal, "cannot install the signal handler");
            return Err(EXIT_SOFTWARE);
        }
    }
    Ok(Signals {
        stop,
        reload,
        raw_request,
    })
}

/// The hardware: map the two windows, then give up root, then bring the fabric up (before
/// the long first daylight-coefficient computation, so a dead fabric is reported at once).
/// In --sim nothing is mapped.
fn open_source(
    options: &Options,
    config: &Config,
    stop: &Arc<AtomicBool>,
) -> Result<(SourceKind, Box<dyn CaptureSource>), i32> {
    let mut kind = if options.sim {
        tracing::info!(
            source = ?config.sim.source,
            "sim: no hardware window mapped; dropping root skipped in --sim"
        );
        match config.sim.source {
            SimSourceKind::Sim => SourceKind::Sim,
            SimSourceKind::Fabric => SourceKind::FabricSim,
            SimSourceKind::FabricModel => SourceKind::FabricModelSim,
        }
    } else {
        SourceKind::Board(Some(map_hardware(config)?))
    };
    match make_source(&mut kind, config, stop.clone()) {
        Ok(source) => Ok((kind, source)),
        Err(e) => {
            tracing::error!(kind = e.kind(), "cannot set up the capture source: {e}");
            Err(if options.sim {
                EXIT_CONFIG
            } else {
                EXIT_UNAVAILABLE
            })
        }
    }
}

/// The room and its daylight coefficients (minutes the first time, then cached), on a thread
/// of its own so that SIGTERM ends the wait at once: the computation is abandoned and the
/// cache is never left partly written (cycle.rs writes it whole, then renames it, and not at
/// all once abandoned).
fn compute_room(config: &Config, stop: &AtomicBool, notifier: &Notifier) -> Result<Pipeline, i32> {
    notifier.status("computing daylight coefficients");
    let cancel = Arc::new(AtomicBool::new(false));
    let worker = {
        let config = config.clone();
        let cancel = cancel.clone();
        std::thread::spawn(move || {
            let notifier = Notifier::from_env();
            let last_report = std::sync::Mutex::new((0u64, Instant::now()));
            Pipeline::new_cancellable(
                &config,
                &|done, total| {
                    let pct = 100 * done / total.max(1);
                    let mut last = last_report.lock().unwrap_or_else(|p| p.into_inner());
                    if pct >= last.0 + 10 {
                        last.0 = pct;
                        tracing::info!(percent = pct, "daylight coefficients");
                    }
                    // Keep the watchdog fed through a long first computation.
                    if last.1.elapsed() >= Duration::from_secs(1) {
                        last.1 = Instant::now();
                        notifier.watchdog();
                    }
                },
                &cancel,
            )
        })
    };
    while !worker.is_finished() {
        if stop.load(Ordering::Relaxed) {
            crate::cycle::abandon_dc(&cancel, config);
            tracing::info!(
                "stop requested during the daylight-coefficient computation: abandoned, \
                 nothing cached; exiting"
            );
            notifier.stopping();
            return Err(0);
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let Ok(pipeline) = worker.join() else {
        tracing::error!(
            kind = "room",
            "the daylight-coefficient computation panicked"
        );
        return Err(EXIT_SOFTWARE);
    };
    pipeline.map_err(|e| {
        tracing::error!(kind = "room", "cannot set up the pipeline: {e}");
        EXIT_CONFIG
    })
}

fn start_api(config: &Config) -> Result<(SharedState, ApiServer), i32> {
    let state: SharedState = Arc::new(std::sync::Mutex::new(ApiState {
        started_unix_s: Utc::now().timestamp_millis() as f64 / 1e3,
        ..ApiState::default()
    }));
    let api = ApiServer::start(config.api_address(), state.clone()).map_err(|e| {
        tracing::error!(kind = "api", "{e}");
        EXIT_UNAVAILABLE
    })?;
    tracing::info!(address = %api.address, "API listening (GET /v1/latest, /v1/health, /v1/metrics)");
    Ok((state, api))
}

impl Daemon<'_> {
    /// The schedule: a cycle whenever one is due, until a stop, or `--cycles` are done.
    fn serve(&mut self) {
        let stop = self.signals.stop.clone();
        loop {
            ping(&self.notifier, &mut self.last_ping);
            if stop.load(Ordering::Relaxed) {
                tracing::info!("stop requested: exiting");
                break;
            }
            if self.signals.reload.swap(false, Ordering::Relaxed) {
                self.reload();
            }
            if self.options.cycles.is_some_and(|n| self.counts.ok >= n) {
                if self.options.serve_after {
                    self.sleep(Duration::from_millis(200));
                    continue;
                }
                tracing::info!(cycles = self.counts.ok, "requested cycles done: exiting");
                break;
            }
            // Wait for the capture's time (wall clock only).
            if let Clock::Wall {
                next_due: Some(due),
                ..
            } = &self.clock
            {
                let now = Instant::now();
                if *due > now {
                    let wait = *due - now;
                    self.sleep(wait);
                    continue;
                }
            }
            if !self.attempt_cycle() {
                break;
            }
        }
    }

    /// SIGHUP: [`reload_config`], its outcome shown in `/v1/health` (a refused file until a
    /// good one is loaded).
    fn reload(&mut self) {
        let next_sequence = self.counts.ok + 1;
        let outcome = reload_config(
            self.options,
            &mut self.config,
            &mut self.kind,
            &self.signals.stop,
            next_sequence,
        );
        let mut s = self.state.lock().unwrap_or_else(|p| p.into_inner());
        match outcome {
            Ok(source) => {
                s.config_error = None;
                self.raw_schedule
                    .set_every_s(self.config.fabric.raw_every_s);
                if let Some(source) = source {
                    self.source = source;
                }
            }
            Err(message) => {
                s.config_error = Some(ErrorReport {
                    kind: "config".into(),
                    message,
                    time: self.clock.now().to_rfc3339(),
                })
            }
        }
    }

    fn sleep(&mut self, d: Duration) {
        sleep_interruptible(d, &self.signals.stop, &self.notifier, &mut self.last_ping);
    }

    /// One attempt at a cycle, its success or failure recorded; `false` when a stop came
    /// during the capture.
    fn attempt_cycle(&mut self) -> bool {
        self.counts.attempts += 1;
        self.sim_clock_fault();
        let at = self.clock.now();
        if let Err(e) = self.open_output().and_then(|_| self.check_clock(at)) {
            self.failed(&e, at);
            return true;
        }
        self.record_api_address();
        let Some(out) = self.output.as_mut() else {
            return true;
        };
        let started = Instant::now();
        let (attempts, sequence) = (self.counts.attempts, self.counts.ok + 1);
        if self.signals.raw_request.swap(false, Ordering::Relaxed) {
            tracing::info!("SIGUSR1: the next capture is raw");
            self.raw_schedule.request();
        }
        let raw = self.raw_schedule.due(self.source.makes_maps(), at);
        if let Some(reason) = raw {
            tracing::info!(
                ?reason,
                "raw capture (merged on the HPS, kept in campaign format)"
            );
        }
        let result = std::panic::catch_unwind(AssertUnwindSafe(|| {
            run_cycle(
                self.source.as_mut(),
                &mut self.pipeline,
                out,
                &self.config,
                at,
                raw.is_some(),
                attempts,
                sequence,
                &self.signals.stop,
            )
        }))
        .unwrap_or_else(|panic| {
            let what = panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_else(|| "unknown panic".into());
            Err(CycleError::Model(format!(
                "internal error (panic caught): {what}"
            )))
        });
        match result {
            Ok(Some((record, output_ms))) => {
                if record.hdr == "hps" {
                    self.raw_schedule.taken(at);
                }
                self.succeeded(record, output_ms, started)
            }
            Ok(None) => {
                tracing::info!(
                    "stop requested during the capture: capture discarded, nothing written"
                );
                return false;
            }
            Err(e) => self.failed(&e, at),
        }
        true
    }

    /// `[[sim.fault]] kind = "clock_back"`: the simulated clock steps back before this attempt.
    fn sim_clock_fault(&mut self) {
        let fault = SimSource::fault_for(&self.config.sim.faults, self.counts.attempts);
        if let (Some(FaultKind::ClockBack), Clock::Sim { now, .. }) = (fault, &mut self.clock) {
            *now -= chrono::TimeDelta::seconds(crate::config::CLOCK_BACK_S);
            tracing::warn!(
                now = %now.to_rfc3339(),
                "sim: the clock steps back {} s (injected)",
                crate::config::CLOCK_BACK_S
            );
        }
    }

    /// A capture time not after the last record's means the clock went backwards: the
    /// record could not be placed (results are in time order, files are named by time), and
    /// the sun would be computed for the wrong time. The cycle fails, flagged, until the
    /// clock is past the last record again.
    fn check_clock(&self, at: DateTime<FixedOffset>) -> Result<(), CycleError> {
        let last = self.output.as_ref().and_then(|o| o.last_time());
        let Some(last) = last.and_then(|t| DateTime::parse_from_rfc3339(t).ok()) else {
            return Ok(());
        };
        if at > last {
            return Ok(());
        }
        Err(CycleError::Clock(format!(
            "the clock went backwards: {} is not after the last record's time {}; no record \
             until it is",
            at.to_rfc3339(),
            last.to_rfc3339()
        )))
    }

    /// The output directory, opened (and repaired) if it is not yet.
    fn open_output(&mut self) -> Result<(), CycleError> {
        if self.output.is_some() {
            return Ok(());
        }
        let output = &self.config.output;
        let (o, recovery) = Output::open(&output.dir, output.max_maps, output.max_captures)
            .map_err(|e| CycleError::Output(e.to_string()))?;
        if recovery.repaired_anything() {
            tracing::warn!(
                partial_bytes_dropped = recovery.partial_bytes_dropped,
                stale_files_removed = recovery.stale_files_removed,
                orphan_files_removed = recovery.orphan_files_removed,
                csv_rows_rebuilt = recovery.csv_rows_rebuilt,
                latest_rebuilt = recovery.latest_rebuilt,
                last_record_unreadable = recovery.last_record_unreadable.as_deref(),
                "output: repaired what an interrupted write left"
            );
        }
        self.output = Some(o);
        Ok(())
    }

    fn record_api_address(&mut self) {
        if self.api_address_written {
            return;
        }
        let p = self.config.output.dir.join(API_ADDRESS_FILE);
        match crate::output::write_atomic(&p, format!("{}\n", self.api.address).as_bytes()) {
            Ok(()) => self.api_address_written = true,
            Err(e) => tracing::warn!(error = %e, "cannot record the API address"),
        }
    }

    fn succeeded(&mut self, record: crate::cycle::CycleRecord, output_ms: f64, started: Instant) {
        self.counts.ok += 1;
        self.counts.consecutive_failures = 0;
        tracing::info!(
            sequence = record.sequence,
            time = %record.time,
            sun_altitude_deg = record.sun.spa_altitude_deg,
            sun_extracted = record.sun.extracted,
            sun_flags = ?record.sun.flags,
            sun_source = %record.sun_source,
            plausibility = ?record.plausibility,
            sensors = record.illuminance.len(),
            first_lux = record.illuminance.first().map_or(f64::NAN, |s| s.lux),
            capture_ms = record.durations_ms.capture_ms,
            hdr_ms = record.durations_ms.hdr_ms,
            terms_ms = record.durations_ms.terms_ms,
            output_ms,
            cycle_ms = started.elapsed().as_secs_f64() * 1e3,
            "cycle done"
        );
        self.notifier
            .status(&format!("cycle {} at {}", record.sequence, record.time));
        {
            let mut s = self.state.lock().unwrap_or_else(|p| p.into_inner());
            s.cycles_ok += 1;
            *s.cycles_by_hdr.entry(record.hdr.clone()).or_default() += 1;
            *s.cycles_by_sun_source
                .entry(record.sun_source.clone())
                .or_default() += 1;
            if let Some(f) = &record.sun_fallback {
                *s.sun_fallbacks_by_reason
                    .entry(f.reason.clone())
                    .or_default() += 1;
            }
            s.consecutive_failures = 0;
            s.last_durations = Some(record.durations_ms.clone());
            s.last_output_ms = output_ms;
            for flag in &record.plausibility {
                *s.plausibility_by_flag.entry(flag.clone()).or_default() += 1;
            }
            s.latest = Some(record);
        }
        match &mut self.clock {
            Clock::Sim { now, step } => *now += *step,
            Clock::Wall { next_due, .. } => {
                let period = Duration::from_secs_f64(self.config.capture.period_s);
                let due = next_due.map_or(started, |d| d) + period;
                // Fallen behind (a long cycle): start the schedule again from now.
                *next_due = Some(if due < Instant::now() {
                    Instant::now()
                } else {
                    due
                });
            }
        }
    }

    fn failed(&mut self, e: &CycleError, at: DateTime<FixedOffset>) {
        self.counts.consecutive_failures += 1;
        fail(
            &self.state,
            &self.config,
            &mut self.clock,
            e,
            at,
            self.counts.attempts,
            self.counts.consecutive_failures,
            &self.notifier,
        );
    }
}

/// Logs and counts a failed cycle, then backs off.
#[allow(clippy::too_many_arguments)]
fn fail(
    state: &SharedState,
    config: &Config,
    clock: &mut Clock,
    e: &CycleError,
    at: DateTime<FixedOffset>,
    attempt: u64,
    consecutive: u64,
    notifier: &Notifier,
) {
    let retry_s = backoff_s(config.retry.initial_s, config.retry.max_s, consecutive);
    tracing::error!(
        kind = e.kind(),
        attempt,
        consecutive_failures = consecutive,
        retry_in_s = retry_s,
        time = %at.to_rfc3339(),
        "cycle failed: {e}"
    );
    {
        let mut s = state.lock().unwrap_or_else(|p| p.into_inner());
        s.cycles_failed += 1;
        s.consecutive_failures = consecutive;
        *s.failures_by_kind.entry(e.kind().to_string()).or_default() += 1;
        s.last_error = Some(ErrorReport {
            kind: e.kind().to_string(),
            message: e.to_string(),
            time: at.to_rfc3339(),
        });
    }
    notifier.status(&format!(
        "degraded: {} ({} in a row)",
        e.kind(),
        consecutive
    ));
    match clock {
        Clock::Sim { now, .. } => {
            // The simulated clock jumps the back-off; a short real pause keeps a persistent
            // failure from spinning.
            *now += chrono::TimeDelta::milliseconds((retry_s * 1e3).round() as i64);
            std::thread::sleep(Duration::from_millis(50));
        }
        Clock::Wall { next_due, .. } => {
            *next_due = Some(Instant::now() + Duration::from_secs_f64(retry_s));
        }
    }
}

/// One cycle. `Ok(None)`: stopped during the capture, which was discarded.
#[allow(clippy::too_many_arguments)]
fn run_cycle(
    source: &mut dyn CaptureSource,
    pipeline: &mut Pipeline,
    output: &mut Output,
    config: &Config,
    at: DateTime<FixedOffset>,
    raw: bool,
    attempt: u64,
    sequence: u64,
    stop: &AtomicBool,
) -> Result<Option<(crate::cycle::CycleRecord, f64)>, CycleError> {
    let t = Instant::now();
    let set = if raw {
        source.capture_raw(at)
    } else {
        source.capture(at)
    };
    // Stopped during the capture: whatever it gave (frames, or an error from the abandoned
    // wait) is discarded, and nothing is written.
    if stop.load(Ordering::Relaxed) {
        return Ok(None);
    }
    let set = set?;
    let capture_ms = t.elapsed().as_secs_f64() * 1e3;
    let products = pipeline.process(
        &set,
        capture_ms,
        source.name(),
        &crate::views::ViewRequest::from_config(config),
    )?;
    let mut record = products.record;
    record.sequence = sequence;
    let t = Instant::now();
    let mut faults = SimOutputFaults {
        rules: &config.sim.faults,
        attempt,
    };
    output
        .write_cycle(
            &mut record,
            &products.map,
            &products.view_pictures,
            &products.state_view_pictures,
            &pipeline.device,
            // A fabric map has no raw frames to keep, but its readout goes into the map's EXR
            // (without it the map's groups would be placed as a skip-1 readout's).
            Some((&set.config, set.frames.as_slice())),
            &mut faults,
        )
        .map_err(|e| {
            if e.is_disk_full() {
                CycleError::DiskFull(e.to_string())
            } else {
                CycleError::Output(e.to_string())
            }
        })?;
    Ok(Some((record, t.elapsed().as_secs_f64() * 1e3)))
}

/// Where captures come from.
enum SourceKind {
    /// `--sim` with `[sim] source = "sim"`.
    Sim,
    /// `--sim` with `[sim] source = "fabric"`: the cycle-accurate core.
    FabricSim,
    /// `--sim` with `[sim] source = "fabric-model"`: the behavioural fabric model.
    FabricModelSim,
    /// The board; the windows are taken by the first source built.
    Board(Option<crate::hardware::Windows>),
}

/// Builds the capture source of `kind` for `config`.
fn make_source(
    kind: &mut SourceKind,
    config: &Config,
    stop: Arc<AtomicBool>,
) -> Result<Box<dyn CaptureSource>, SourceError> {
    let device = || {
        skylux_hps::camera::DeviceConfig::read(&config.camera.device)
            .map(|(d, _)| d)
            .map_err(|e| SourceError::Other(e.to_string()))
    };
    Ok(match kind {
        SourceKind::Sim => Box::new(
            SimSource::new(
                device()?,
                skylux_hps::sun::Site {
                    latitude_deg: config.site.latitude_deg,
                    longitude_deg: config.site.longitude_deg,
                    elevation_m: config.site.elevation_m,
                },
                config.sim.clone(),
                config.camera.exposures_us.clone(),
                config.camera.gains(),
            )
            .with_interior(
                crate::interior_truth::InteriorTruth::for_config(config)
                    .map_err(SourceError::Other)?,
            ),
        ),
        SourceKind::FabricSim => Box::new(crate::fabric_source::sim_fabric_source(
            config,
            &device()?,
            stop,
        )?),
        SourceKind::FabricModelSim => Box::new(
            crate::fabric_model_source::sim_fabric_model_source(config, &device()?, stop)?,
        ),
        SourceKind::Board(windows) => {
            let Some(w) = windows.take() else {
                return Err(SourceError::Other(
                    "the hardware windows are in use: restart skyluxd to apply a new \
                     [camera] or [fabric] section"
                        .into(),
                ));
            };
            let wait = crate::fabric_source::board_wait(config.hardware.uio_device.as_deref())
                .map_err(|e| SourceError::Other(format!("interrupt: {e}")))?;
            // The fabric's own clock is read back at bring-up; the register map's constant
            // is the design's, used for the settings until then.
            let settings =
                crate::fabric_source::fabric_settings(config, skylux_regmap::SYS_CLOCK_HZ, false)
                    .with_map(config, &device()?);
            Box::new(crate::fabric_source::FabricSource::new(
                w.registers,
                w.dma,
                wait,
                settings,
                stop,
            )?)
        }
    })
}

/// SIGHUP: re-reads and validates the configuration. A bad file is logged and the running
/// configuration kept. A good one is applied from the next cycle: the schedule, retry,
/// output retention, camera exposures and gain, `[sim]` and `[fabric]`; what is bound at
/// start (site, room and its daylight coefficients, API address, output directory, hardware
/// windows) keeps its running value, with a warning naming it. Returns the rebuilt source,
/// or why the file was refused (logged).
fn reload_config(
    options: &Options,
    config: &mut Config,
    kind: &mut SourceKind,
    stop: &Arc<AtomicBool>,
    next_sequence: u64,
) -> Result<Option<Box<dyn CaptureSource>>, String> {
    let mut new = match Config::load(&options.config, &options.overrides) {
        Ok(c) => c,
        Err(e) => {
            let message = format!("reload refused, the running configuration is kept: {e}");
            tracing::error!(kind = "config", "SIGHUP: {message}");
            return Err(message);
        }
    };
    let mut kept = Vec::new();
    let d = |a: &dyn std::fmt::Debug, b: &dyn std::fmt::Debug| format!("{a:?}") != format!("{b:?}");
    if d(&new.site, &config.site) {
        kept.push("site");
        new.site = config.site.clone();
    }
    if d(&new.room, &config.room) {
        kept.push("room");
        new.room = config.room.clone();
    }
    if d(&new.camera.device, &config.camera.device) {
        kept.push("camera.device");
        new.camera.device = config.camera.device.clone();
    }
    if d(&new.api, &config.api) {
        kept.push("api");
        new.api = config.api.clone();
    }
    if new.output.dir != config.output.dir {
        kept.push("output.dir");
        new.output.dir = config.output.dir.clone();
    }
    if d(&new.hardware, &config.hardware) {
        kept.push("hardware");
        new.hardware = config.hardware.clone();
    }
    if options.sim && new.sim.source != config.sim.source {
        kept.push("sim.source");
        new.sim.source = config.sim.source;
    }
    if !kept.is_empty() {
        tracing::warn!(
            kept = ?kept,
            "SIGHUP: these settings are bound at start and keep their running values until a restart"
        );
    }
    let source_changed = d(&new.camera, &config.camera)
        || d(&new.sim, &config.sim)
        || d(&new.fabric, &config.fabric);
    let mut rebuilt = None;
    if source_changed {
        match make_source(kind, &new, stop.clone()) {
            Ok(s) => rebuilt = Some(s),
            Err(e) => {
                let message = format!(
                    "reload refused, the capture source cannot take it ({e}); the running \
                     configuration is kept"
                );
                tracing::error!(kind = "config", "SIGHUP: {message}");
                return Err(message);
            }
        }
    }
    *config = new;
    tracing::info!(
        next_sequence,
        raw_every_s = config.fabric.raw_every_s,
        period_s = config.capture.period_s,
        source_rebuilt = rebuilt.is_some(),
        "SIGHUP: configuration reloaded, applied from the next cycle"
    );
    Ok(rebuilt)
}

/// On the board: map the register window and the DMA buffer, then drop root. The fabric is
/// brought up by the source (`FabricSource::new`). Returns the exit status on failure.
fn map_hardware(config: &Config) -> Result<crate::hardware::Windows, i32> {
    // The physical addresses are the Cyclone V HPS's: mapping them on another machine would
    // touch whatever that machine has there.
    if !cfg!(all(target_arch = "arm", target_os = "linux")) {
        tracing::error!(
            kind = "hardware",
            "the hardware mode runs on the DE1-SoC's ARM Linux only: use --sim here"
        );
        return Err(EXIT_UNAVAILABLE);
    }
    let windows = match crate::hardware::map(&config.hardware) {
        Ok(w) => w,
        Err(e) => {
            tracing::error!(kind = "hardware", "{e}");
            return Err(EXIT_CANTCREAT);
        }
    };
    match crate::privilege::drop_root(&config.hardware.user, config.hardware.group.as_deref()) {
        Ok(d) => tracing::info!(?d, "privileges"),
        Err(e) => {
            tracing::error!(kind = "privilege", "{e}");
            return Err(EXIT_SOFTWARE);
        }
    }
    Ok(windows)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn backoff_doubles_and_caps() {
        let b: Vec<f64> = (1..=6).map(|k| backoff_s(2.0, 20.0, k)).collect();
        assert_eq!(b, vec![2.0, 4.0, 8.0, 16.0, 20.0, 20.0]);
        assert_eq!(backoff_s(1.0, 300.0, u64::MAX), 300.0);
        assert_eq!(backoff_s(1.0, 300.0, 0), 1.0);
    }
}

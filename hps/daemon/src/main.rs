//! `skyluxd --config FILE [--sim] [--cycles N] [--time-start RFC3339 --time-step-s S]`
//! `skyluxd --bench-cycle [--json] [--repeat N]`: the cycle budget (BENCHMARKS.md).

use clap::Parser;
use skyluxd::config::Overrides;
use skyluxd::daemon::{run, Options};
use std::path::PathBuf;

/// The Skylux HPS daemon.
#[derive(Parser)]
#[command(name = "skyluxd", version, about)]
struct Args {
    /// The configuration (see hps/skyluxd.toml).
    #[arg(long, required_unless_present = "bench_cycle")]
    config: Option<PathBuf>,
    /// Measure the cycle budget by stage at full resolution and exit (src/budget.rs).
    #[arg(long)]
    bench_cycle: bool,
    /// With --bench-cycle: print only the JSON line.
    #[arg(long)]
    json: bool,
    /// With --bench-cycle: repeats per measured stage (median reported).
    #[arg(long, default_value_t = 5)]
    repeat: usize,
    /// Run against the simulated camera and sky instead of the fabric.
    #[arg(long)]
    sim: bool,
    /// Stop after this many successful cycles.
    #[arg(long)]
    cycles: Option<u64>,
    /// Simulated clock: time of the first capture (RFC 3339), with --time-step-s.
    #[arg(long, value_parser = parse_time)]
    time_start: Option<chrono::DateTime<chrono::FixedOffset>>,
    /// Simulated clock: seconds between captures (no waiting: the clock jumps).
    #[arg(long)]
    time_step_s: Option<f64>,
    /// Overrides output.dir.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Overrides api.address (the same loopback rule applies).
    #[arg(long)]
    api: Option<String>,
    /// After --cycles, keep serving the API until SIGTERM/SIGINT.
    #[arg(long)]
    serve_after: bool,
    /// Log level: error, warn, info, debug, trace.
    #[arg(long, default_value = "info")]
    log_level: tracing::Level,
}

fn parse_time(s: &str) -> Result<chrono::DateTime<chrono::FixedOffset>, String> {
    chrono::DateTime::parse_from_rfc3339(s)
        .map_err(|e| format!("{s:?} is not RFC 3339 with an offset: {e}"))
}

fn main() {
    let args = Args::parse();
    tracing_subscriber::fmt()
        .with_writer(std::io::stderr)
        .with_ansi(false)
        .with_max_level(args.log_level)
        .with_target(false)
        .init();
    if args.bench_cycle {
        match skyluxd::budget::run(args.json, args.repeat) {
            Ok(()) => std::process::exit(0),
            Err(e) => {
                tracing::error!("bench-cycle: {e:#}");
                std::process::exit(skyluxd::daemon::EXIT_SOFTWARE);
            }
        }
    }
    let code = run(&Options {
        config: args.config.unwrap_or_default(),
        sim: args.sim,
        cycles: args.cycles,
        time_start: args.time_start,
        time_step_s: args.time_step_s,
        serve_after: args.serve_after,
        overrides: Overrides {
            output_dir: args.out,
            api_address: args.api,
        },
    });
    std::process::exit(code);
}

//! `skylux closure`: the pyranometer closure GHI = DNI cos Z + DHI on a campaign
//! `pyranometer.csv` (`skylux_hps::validation::closure`), with the loop's report.

use anyhow::Context;
use chrono::TimeDelta;
use skylux_hps::io::irradiance::{read_pyranometer_file, StampConvention};
use skylux_hps::sun::Site;
use skylux_hps::validation::closure::{prepare, run_closure, write_outputs, ClosureOptions};
use std::io::Write;
use std::path::PathBuf;

/// Which instant of its averaging interval a row's time names.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum Stamp {
    Start,
    Centre,
    End,
}

#[derive(clap::Args)]
#[command(after_help = "\
Input: a campaign pyranometer.csv (time,ghi_wm2,dhi_wm2,dni_wm2; RFC 3339 times); rows need all \
three values. Output in --out: report.json (campaign report schema, metric mean_abs_wm2 of the \
closure residual GHI - (DNI cos Z + DHI) on hold-out times), report.md and PNG plots. The times \
are split into alternate fit / hold-out blocks; effects are fitted on the fit blocks only.")]
pub struct ClosureArgs {
    /// The pyranometer.csv file.
    file: PathBuf,
    /// Latitude in degrees, north positive.
    #[arg(long, allow_negative_numbers = true)]
    lat: f64,
    /// Longitude in degrees, east positive.
    #[arg(long, allow_negative_numbers = true)]
    lon: f64,
    /// Height above sea level in metres.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    elevation: f64,
    /// Folder for report.json, report.md and the plots (created if missing).
    #[arg(long)]
    out: PathBuf,
    /// Which instant of its averaging interval a row's time names.
    #[arg(long, value_enum, default_value_t = Stamp::Centre)]
    stamp: Stamp,
    /// Averaging interval in seconds [default: the median step between rows].
    #[arg(long)]
    interval_s: Option<f64>,
    /// Length of the alternating fit / hold-out blocks, in minutes.
    #[arg(long, default_value_t = 30)]
    block_minutes: u32,
    /// Daytime samples: sun zenith below this, in degrees.
    #[arg(long, default_value_t = 85.0)]
    max_zenith: f64,
    /// Leave night samples (zenith > 102°) out of the fit and the scores.
    #[arg(long)]
    day_only: bool,
}

pub fn run(args: &ClosureArgs) -> anyhow::Result<()> {
    let table = read_pyranometer_file(&args.file)?;
    let site = Site {
        latitude_deg: args.lat,
        longitude_deg: args.lon,
        elevation_m: args.elevation,
    };
    let stamp = match args.stamp {
        Stamp::Start => StampConvention::IntervalStart,
        Stamp::Centre => StampConvention::IntervalCentre,
        Stamp::End => StampConvention::IntervalEnd,
    };
    let mut options = ClosureOptions::new(site, stamp);
    options.max_zenith_deg = args.max_zenith;
    options.include_night = !args.day_only;
    options.block = TimeDelta::minutes(i64::from(args.block_minutes));
    if let Some(s) = args.interval_s {
        if !(s.is_finite() && (0.001..=86_400.0).contains(&s)) {
            anyhow::bail!("--interval-s: {s} is outside 0.001 ..= 86400");
        }
        options.interval = Some(TimeDelta::milliseconds((s * 1000.0).round() as i64));
    }
    let prepared = prepare(&table, &options).with_context(|| args.file.display().to_string())?;
    let result = run_closure(&prepared, &options)?;
    let report = write_outputs(&result, &args.out)?;
    // Written, not println!-ed: a closed stdout is an error to report, not a panic.
    let mut out = std::io::stdout().lock();
    let max = |k: &str| report.secondary.get(k).map_or(f64::NAN, |s| s.all);
    writeln!(
        out,
        "hold-out closure residual: mean |r| {:.3} -> {:.3} W/m², max |r| {:.3} -> {:.3} W/m²",
        report.before.all,
        report.after.all,
        max("max_abs_wm2_before"),
        max("max_abs_wm2_after")
    )?;
    for e in &report.effects {
        let params: Vec<String> = e
            .parameters
            .iter()
            .map(|(k, v)| format!("{k}={v:.4}"))
            .collect();
        writeln!(
            out,
            "effect {}: {} (gain {:.3} W/m²)",
            e.name,
            params.join(" "),
            e.gain
        )?;
    }
    if report.effects.is_empty() {
        writeln!(out, "no effect added")?;
    }
    writeln!(out, "report: {}", args.out.join("report.json").display())?;
    Ok(())
}

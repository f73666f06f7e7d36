//! `skylux loop <campaign-dir> --out <dir>`: the device model against the lux-meters, with
//! the effects the residual calls for, reported before and after on held-out times.

use anyhow::Context;
use clap::Args;
use skylux_hps::campaign::Campaign;
use skylux_hps::output::write_atomic;
use skylux_hps::validation::illuminance_loop::{run_loop, LoopOptions, LoopOutcome};
use std::path::{Path, PathBuf};

#[derive(Args)]
pub struct LoopArgs {
    /// The campaign folder (shared/spec/campaign.md).
    pub campaign: PathBuf,
    /// Where report.json, report.md (with the residual table), residuals.csv,
    /// illuminance.csv and the figures go.
    #[arg(long)]
    pub out: PathBuf,
    /// Leave the sun in the map's patches in the base model (as the published device first
    /// did), so the loop can find the undersampling.
    #[arg(long)]
    pub sun_in_map: bool,
    /// Paths per sensor for the daylight coefficients.
    #[arg(long, default_value_t = skylux_hps::validation::illuminance_loop::DC_SAMPLES_PER_SENSOR)]
    pub samples: u32,
    /// Length of the alternating fit and hold-out blocks, minutes.
    #[arg(long, default_value_t = 120)]
    pub block_minutes: i64,
}

pub fn run(args: &LoopArgs) -> anyhow::Result<()> {
    let campaign = Campaign::open(&args.campaign)?;
    let mut options = LoopOptions::default();
    options.base.model.concentrated_sun = !args.sun_in_map;
    options.settings.samples_per_sensor = args.samples;
    options.block = chrono::TimeDelta::minutes(args.block_minutes);
    let outcome = run_with_progress(&campaign, &options)?;
    write_outcome(&args.out, &campaign, &outcome)?;
    print_summary(&args.out, &outcome);
    Ok(())
}

/// Runs the loop with a progress bar on stderr.
pub fn run_with_progress(
    campaign: &Campaign,
    options: &LoopOptions,
) -> anyhow::Result<LoopOutcome> {
    let bar = indicatif::ProgressBar::new(1);
    bar.set_style(
        indicatif::ProgressStyle::with_template("  {msg:28} [{bar:30}] {pos}/{len}")
            .expect("template")
            .progress_chars("=> "),
    );
    let outcome = run_loop(campaign, options, &|stage, done, total| {
        bar.set_message(stage.to_string());
        bar.set_length(total.max(1));
        bar.set_position(done);
    })
    .with_context(|| format!("the loop on {}", campaign.dir.display()))?;
    bar.finish_and_clear();
    Ok(outcome)
}

/// Writes report.json, report.md and illuminance.csv into `out`.
pub fn write_outcome(out: &Path, campaign: &Campaign, outcome: &LoopOutcome) -> anyhow::Result<()> {
    std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    let mut report = outcome.report.clone();
    report.figures = skylux_hps::validation::loop_figures::write_loop_figures(out, outcome)?;
    report.write_json(&out.join("report.json"))?;
    let mut md = report.markdown(&format!("Skylux loop: {}", campaign.config.name));
    md.push_str(&skylux_hps::validation::report::residual_markdown(
        &outcome.residuals,
    ));
    let mut table =
        String::from("variable,group,readings,before_r,before_slope,after_r,after_slope\n");
    for r in &outcome.residuals {
        table.push_str(&format!(
            "\"{}\",{},{},{},{},{},{}\n",
            r.variable, r.group, r.n, r.before_r, r.before_slope, r.after_r, r.after_slope
        ));
    }
    write_atomic(&out.join("residuals.csv"), table.as_bytes())?;
    write_atomic(&out.join("report.md"), md.as_bytes())?;
    let mut csv = String::from("time,sensor,lux_model,lux_measured,model\n");
    for r in &outcome.rows {
        csv.push_str(&format!(
            "{},{},{:.3},{},{}\n",
            r.time,
            r.sensor,
            r.lux_model,
            r.lux_measured
                .map(|m| format!("{m:.3}"))
                .unwrap_or_default(),
            r.model
        ));
    }
    write_atomic(&out.join("illuminance.csv"), csv.as_bytes())?;
    Ok(())
}

/// The before/after table on stdout.
pub fn print_summary(out: &Path, outcome: &LoopOutcome) {
    let r = &outcome.report;
    println!(
        "  hold-out mean |relative error| per sensor ({} times):",
        r.holdout_times.len()
    );
    println!("    sensor   before    after   Perez");
    let mut names: Vec<&String> = r.before.per_sensor.keys().collect();
    names.sort_by_key(|n| (n.len(), n.to_string()));
    let pct = |v: Option<f64>| match v {
        Some(v) if v.is_finite() => format!("{:6.1} %", 100.0 * v),
        _ => "     n/a".into(),
    };
    for n in names {
        println!(
            "    {n:6} {} {} {}",
            pct(r.before.per_sensor.get(n).copied()),
            pct(r.after.per_sensor.get(n).copied()),
            pct(r
                .baseline_perez
                .as_ref()
                .and_then(|p| p.per_sensor.get(n).copied()))
        );
    }
    println!(
        "    all    {} {} {}",
        pct(Some(r.before.all)),
        pct(Some(r.after.all)),
        pct(r.baseline_perez.as_ref().map(|p| p.all))
    );
    if r.effects.is_empty() {
        println!("  effects added: none");
    }
    for e in &r.effects {
        let params: Vec<String> = e
            .parameters
            .iter()
            .map(|(k, v)| format!("{k}={v:.4}"))
            .collect();
        let params = if params.is_empty() {
            String::new()
        } else {
            format!(" ({})", params.join(", "))
        };
        println!("  effect added: {}{params}: {}", e.name, e.evidence);
    }
    println!("  report: {}", out.join("report.md").display());
}

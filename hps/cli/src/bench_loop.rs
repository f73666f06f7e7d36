//! `skylux bench loop --campaigns N --seed S [--keep DIR] [--json] [--only CLASS]
//! [--shard K/M] [--jsonl FILE]`: the loop against a battery of random campaigns whose truth
//! comes from RADIANCE, not from the engine the loop's model uses (issue 18;
//! `skylux_sim::battery`). `skylux bench loop --summarise FILE...` makes the tables from the
//! JSON lines of earlier runs (a battery run in shards, on several machines or days).
//!
//! The campaigns run interleaved (the first of every bucket, then the second of every
//! bucket, ...), so a battery stopped early, or one shard of it, still covers every class.
//! `--cases 2,40,90` runs those campaigns of the battery alone (CI's small battery).
//! A battery with RADIANCE truth takes minutes per campaign (rcontrib's converged daylight
//! coefficients, every capture's sun a light source tested at every path vertex).
//!
//! Per campaign: simulate it, run the loop as `skylux loop` does, and compare the effects it
//! names and their parameters with the world's. Per effect class: recall (named when
//! present), campaigns with a false discovery (a named effect absent from the world;
//! `sun_undersampling` is the loop's own model choice, docs/loop.md, never counted),
//! parameter error against [`TOLERANCES`], hold-out error before and after, time; and the
//! confusion matrix of true class against named effects.

use anyhow::Context;
use serde_json::{json, Value};
use skylux_hps::campaign::Campaign;
use skylux_hps::validation::effects::registry;
use skylux_hps::validation::illuminance_loop::LoopOptions;
use skylux_hps::validation::report::Report;
use skylux_hps::validation::scoring::MIN_RELATIVE_GAIN;
use skylux_sim::battery::{battery_campaigns, BatteryCase, EFFECT_RANGES};
use skylux_sim::campaign::{simulate_campaign, TruthSource};
use skylux_sim::sky_colour::MismatchLine;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

#[derive(clap::Args)]
pub struct LoopBenchArgs {
    /// Campaigns in the battery.
    #[arg(long, default_value_t = 12)]
    campaigns: usize,
    /// The battery's seed: the same seed, the same campaigns.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Keep each campaign and its loop report in DIR/NNN-CLASS/ (default: a temporary
    /// folder, removed).
    #[arg(long)]
    keep: Option<PathBuf>,
    /// With `--keep`: where DIR/NNN-CLASS/campaign already holds a campaign (a battery run
    /// kept before), run the loop on it instead of simulating it again, so a change to the
    /// loop is re-judged on the same data in seconds per campaign rather than minutes.
    #[arg(long, requires = "keep")]
    reuse: bool,
    /// Print one JSON object instead of the tables.
    #[arg(long)]
    json: bool,
    /// Only the campaigns holding this effect class (or `none`).
    #[arg(long)]
    only: Option<String>,
    /// Paths per sensor for the loop's daylight coefficients.
    #[arg(long, default_value_t = skylux_hps::validation::illuminance_loop::DC_SAMPLES_PER_SENSOR)]
    samples: u32,
    /// The campaigns' truth: radiance (converged), radiance:N (N bounces) or engine.
    #[arg(long, default_value = "radiance")]
    truth: TruthSource,
    /// Run only every M-th campaign of the interleaved order, from the K-th (0-based): `K/M`.
    #[arg(long, value_parser = parse_shard)]
    shard: Option<(usize, usize)>,
    /// Run only the campaigns of these battery indices (as the tables print them: `#40`).
    #[arg(long, value_delimiter = ',')]
    cases: Vec<usize>,
    /// Append each campaign's result to FILE as one JSON line as soon as it is known.
    #[arg(long)]
    jsonl: Option<PathBuf>,
    /// Make the tables from these JSON-lines files instead of running campaigns.
    #[arg(long, num_args = 1..)]
    summarise: Vec<PathBuf>,
    /// Exit with an error unless every campaign meets issue 18's rule (see [`shortfalls`]):
    /// CI's small battery.
    #[arg(long)]
    check: bool,
}

fn parse_shard(text: &str) -> Result<(usize, usize), String> {
    let bad = || format!("--shard {text}: expected K/M with 0 <= K < M, e.g. 0/2");
    let (k, m) = text.split_once('/').ok_or_else(bad)?;
    let (k, m): (usize, usize) = (
        k.trim().parse().map_err(|_| bad())?,
        m.trim().parse().map_err(|_| bad())?,
    );
    (k < m).then_some((k, m)).ok_or_else(bad)
}

/// The battery's cases in round-robin over their buckets (`none`, each single class, pairs),
/// each bucket in index order.
fn interleaved(cases: Vec<BatteryCase>) -> Vec<BatteryCase> {
    let bucket = |c: &BatteryCase| match c.effects.len() {
        2 => "pair".to_string(),
        _ => c.class.clone(),
    };
    let mut seen: BTreeMap<String, usize> = BTreeMap::new();
    let mut keyed: Vec<(usize, usize, BatteryCase)> = cases
        .into_iter()
        .map(|c| {
            let rank = seen.entry(bucket(&c)).or_default();
            *rank += 1;
            (*rank, c.index, c)
        })
        .collect();
    keyed.sort_by_key(|(rank, index, _)| (*rank, *index));
    keyed.into_iter().map(|(_, _, c)| c).collect()
}

/// How close a fitted parameter must be to the world's to count as right.
struct Tolerance {
    effect: &'static str,
    /// The parameter the loop reports.
    parameter: &'static str,
    /// Absolute, or relative to the truth when `relative`.
    tolerance: f64,
    relative: bool,
}

/// Per effect: the loop's parameter for the world's, and the tolerance (the accuracy a user
/// of the effect needs, and the loop's tests hold it to on the reference room).
const TOLERANCES: &[Tolerance] = &[
    Tolerance {
        effect: "glazing_transmittance",
        parameter: "relative_transmittance",
        tolerance: 0.03,
        relative: false,
    },
    Tolerance {
        effect: "light_leak",
        parameter: "lux_per_outdoor_lux",
        tolerance: 0.2,
        relative: true,
    },
    Tolerance {
        effect: "ground_reflectance",
        parameter: "reflectance",
        tolerance: 0.1,
        relative: false,
    },
    Tolerance {
        effect: "orientation_error",
        parameter: "axis_azimuth_deg",
        tolerance: 1.0,
        relative: false,
    },
    Tolerance {
        effect: "clock_offset",
        parameter: "logger_minus_device_s",
        tolerance: 30.0,
        relative: false,
    },
    Tolerance {
        effect: "shutter_overhead",
        parameter: "overhead_us",
        tolerance: 1.0,
        relative: false,
    },
    Tolerance {
        effect: "spectral_mismatch",
        parameter: "slope_per_index",
        tolerance: 0.2,
        relative: true,
    },
    Tolerance {
        effect: "glazing_angular",
        parameter: "b0",
        tolerance: 0.03,
        relative: false,
    },
    Tolerance {
        effect: "vignetting",
        parameter: "extra_vignetting",
        tolerance: 0.05,
        relative: false,
    },
    Tolerance {
        effect: "sky_outside_fov",
        parameter: "field_of_view_deg",
        tolerance: 2.0,
        relative: false,
    },
];

/// The loop's model choice, not a world effect: never a false discovery (docs/loop.md).
const MODEL_CHOICES: &[&str] = &["sun_undersampling"];

/// A world parameter against the loop's.
struct ParameterCheck {
    effect: &'static str,
    truth: f64,
    /// What the loop's parameter should be (the truth, or derived from it).
    expected: Option<f64>,
    fitted: Option<f64>,
}

impl ParameterCheck {
    fn error(&self) -> Option<f64> {
        Some(self.fitted? - self.expected?)
    }
    fn within(&self) -> Option<bool> {
        let t = TOLERANCES.iter().find(|t| t.effect == self.effect)?;
        let e = self.error()?;
        let allowed = if t.relative {
            t.tolerance * self.expected?.abs()
        } else {
            t.tolerance
        };
        Some(e.abs() <= allowed)
    }
}

/// One campaign's outcome.
struct CaseResult {
    index: usize,
    class: String,
    truth: Vec<(&'static str, f64)>,
    /// Named effects (model choices included) with their parameters.
    named: Vec<(String, BTreeMap<String, f64>)>,
    checks: Vec<ParameterCheck>,
    before: f64,
    after: f64,
    /// The hold-out error of the declared model on the case's twin without its effects (the
    /// same room, sky, noise and lux-meters): the model's own error against the world, which
    /// no effect removes. Measured only where the error is not halved outright.
    floor: Option<f64>,
    simulate_s: f64,
    loop_s: f64,
    error: Option<String>,
}

/// An effect's name as the battery's static table spells it.
fn effect_name(name: &str) -> anyhow::Result<&'static str> {
    EFFECT_RANGES
        .iter()
        .map(|e| e.name)
        .find(|n| *n == name)
        .ok_or_else(|| anyhow::anyhow!("unknown effect {name:?}"))
}

impl CaseResult {
    /// The inverse of [`CaseResult::json`].
    fn from_json(v: &Value) -> anyhow::Result<CaseResult> {
        let field = |k: &str| v.get(k).ok_or_else(|| anyhow::anyhow!("no field {k:?}"));
        let number =
            |k: &str| -> anyhow::Result<f64> { Ok(field(k)?.as_f64().unwrap_or(f64::NAN)) };
        let truth = field("truth")?
            .as_object()
            .ok_or_else(|| anyhow::anyhow!("truth: not an object"))?
            .iter()
            .map(|(k, x)| Ok((effect_name(k)?, x.as_f64().unwrap_or(f64::NAN))))
            .collect::<anyhow::Result<Vec<_>>>()?;
        let named = field("named")?
            .as_array()
            .ok_or_else(|| anyhow::anyhow!("named: not a list"))?
            .iter()
            .map(|n| {
                let name = n.get("name").and_then(Value::as_str).unwrap_or_default();
                let parameters: BTreeMap<String, f64> =
                    serde_json::from_value(n.get("parameters").cloned().unwrap_or(json!({})))?;
                Ok((name.to_string(), parameters))
            })
            .collect::<anyhow::Result<Vec<_>>>()?;
        let checks = field("parameters")?
            .as_array()
            .ok_or_else(|| anyhow::anyhow!("parameters: not a list"))?
            .iter()
            .map(|c| {
                Ok(ParameterCheck {
                    effect: effect_name(
                        c.get("effect").and_then(Value::as_str).unwrap_or_default(),
                    )?,
                    truth: c.get("world").and_then(Value::as_f64).unwrap_or(f64::NAN),
                    expected: c.get("expected").and_then(Value::as_f64),
                    fitted: c.get("fitted").and_then(Value::as_f64),
                })
            })
            .collect::<anyhow::Result<Vec<_>>>()?;
        Ok(CaseResult {
            index: field("index")?.as_u64().unwrap_or(0) as usize,
            class: field("class")?.as_str().unwrap_or_default().to_string(),
            truth,
            named,
            checks,
            before: number("holdout_before")?,
            after: number("holdout_after")?,
            floor: v.get("holdout_floor").and_then(Value::as_f64),
            simulate_s: number("simulate_s")?,
            loop_s: number("loop_s")?,
            error: field("error")?.as_str().map(str::to_string),
        })
    }

    fn false_discoveries(&self) -> Vec<&str> {
        self.named
            .iter()
            .map(|(n, _)| n.as_str())
            .filter(|n| !MODEL_CHOICES.contains(n) && !self.truth.iter().any(|t| t.0 == *n))
            .collect()
    }
    fn names(&self, effect: &str) -> bool {
        self.named.iter().any(|(n, _)| n == effect)
    }
    fn json(&self) -> Value {
        json!({
            "index": self.index,
            "class": self.class,
            "truth": self.truth.iter().map(|(n, v)| (n.to_string(), json!(v))).collect::<serde_json::Map<_, _>>(),
            "named": self.named.iter().map(|(n, p)| json!({"name": n, "parameters": p})).collect::<Vec<_>>(),
            "false_discoveries": self.false_discoveries(),
            "parameters": self.checks.iter().map(|c| json!({
                "effect": c.effect, "world": c.truth, "expected": c.expected,
                "fitted": c.fitted, "error": c.error(), "within_tolerance": c.within(),
            })).collect::<Vec<_>>(),
            "holdout_before": self.before,
            "holdout_after": self.after,
            "holdout_floor": self.floor,
            "simulate_s": self.simulate_s,
            "loop_s": self.loop_s,
            "error": self.error,
        })
    }
}

pub fn run(args: &LoopBenchArgs) -> anyhow::Result<()> {
    if !args.summarise.is_empty() {
        let mut results = Vec::new();
        for path in &args.summarise {
            results.extend(read_jsonl(path)?);
        }
        anyhow::ensure!(
            !results.is_empty(),
            "no campaign results in {:?}",
            args.summarise
        );
        return report(args, &results, None);
    }
    if let Some(only) = &args.only {
        anyhow::ensure!(
            only == "none" || EFFECT_RANGES.iter().any(|e| e.name == only),
            "--only {only}: expected none or one of {}",
            EFFECT_RANGES
                .iter()
                .map(|e| e.name)
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    if let Some(bad) = args.cases.iter().find(|&&i| i >= args.campaigns) {
        anyhow::bail!(
            "--cases {bad}: the battery of --campaigns {} has campaigns 0 to {}",
            args.campaigns,
            args.campaigns.saturating_sub(1)
        );
    }
    if matches!(args.truth, TruthSource::Radiance { .. }) {
        skylux_sim::radiance_tools::Radiance::find()?;
    }
    let cases: Vec<BatteryCase> = interleaved(battery_campaigns(args.campaigns, args.seed))
        .into_iter()
        .enumerate()
        .filter(|(position, _)| args.shard.is_none_or(|(k, m)| position % m == k))
        .map(|(_, c)| c)
        .filter(|c| args.cases.is_empty() || args.cases.contains(&c.index))
        .filter(|c| match args.only.as_deref() {
            None => true,
            Some("none") => c.effects.is_empty(),
            Some(only) => c.effects.iter().any(|e| e.0 == only),
        })
        .collect();
    anyhow::ensure!(
        !cases.is_empty(),
        "no campaign of the battery (--campaigns {}, --seed {}) holds {}",
        args.campaigns,
        args.seed,
        args.only.as_deref().unwrap_or("anything")
    );
    let data_dir = skylux_hps::photometry::spectral::data_dir_from_env().or_else(|| {
        let d = crate::sim_cmd::default_room().ok()?.join("../../data");
        d.join("spectral").is_dir().then_some(d)
    });
    let slope = data_dir.as_deref().and_then(spectral_slope);
    let temp = tempfile::tempdir().context("a temporary folder")?;
    let root = args
        .keep
        .clone()
        .unwrap_or_else(|| temp.path().to_path_buf());
    let mut results = Vec::new();
    for (i, case) in cases.iter().enumerate() {
        eprintln!(
            "campaign {}/{} (battery case {}): {} — lat {:.1}°, façade {:.0}°, {} captures/day, {:?}",
            i + 1,
            cases.len(),
            case.index,
            case.class,
            case.site.latitude_deg,
            case.room.facade_azimuth_deg,
            case.hours.len(),
            case.days.iter().map(|d| d.1).collect::<Vec<_>>()
        );
        let dir = root.join(format!("{:03}-{}", case.index, case.class));
        let r = run_case(case, &dir, args, data_dir.clone(), slope);
        eprintln!(
            "  simulated in {:.0} s, loop in {:.0} s; named: {}; hold-out {:.1} % -> {:.1} %{}",
            r.simulate_s,
            r.loop_s,
            if r.named.is_empty() {
                "none".to_string()
            } else {
                r.named
                    .iter()
                    .map(|n| n.0.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            },
            100.0 * r.before,
            100.0 * r.after,
            r.error
                .as_ref()
                .map(|e| format!("; FAILED: {e}"))
                .unwrap_or_default()
        );
        if let Some(path) = &args.jsonl {
            append_line(path, &r.json())?;
        }
        results.push(r);
    }
    report(args, &results, slope)
}

/// Appends one JSON value as a line (the file is created if absent).
fn append_line(path: &Path, value: &Value) -> anyhow::Result<()> {
    use std::io::Write as _;
    let mut f = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(path)
        .with_context(|| format!("opening {}", path.display()))?;
    writeln!(f, "{value}").with_context(|| format!("writing {}", path.display()))
}

/// Campaign results written by `--jsonl`; a line that is not one is an error naming it.
fn read_jsonl(path: &Path) -> anyhow::Result<Vec<CaseResult>> {
    let text =
        std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
    text.lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(i, l)| {
            let v: Value = serde_json::from_str(l)
                .with_context(|| format!("{} line {}: not JSON", path.display(), i + 1))?;
            CaseResult::from_json(&v).with_context(|| {
                format!("{} line {}: not a campaign result", path.display(), i + 1)
            })
        })
        .collect()
}

/// The tables (or one JSON object) for these results.
fn report(args: &LoopBenchArgs, results: &[CaseResult], slope: Option<f64>) -> anyhow::Result<()> {
    let summary = summarise(results);
    if args.json {
        let out = json!({
            "campaigns": results.len(),
            "seed": args.seed,
            "truth": format!("{:?}", args.truth),
            "tolerances": TOLERANCES.iter().map(|t| json!({
                "effect": t.effect, "parameter": t.parameter,
                "tolerance": t.tolerance, "relative": t.relative,
            })).collect::<Vec<_>>(),
            "expected_spectral_slope_per_index": slope,
            "classes": summary.iter().map(ClassRow::json).collect::<Vec<_>>(),
            "confusion": confusion(results),
            "cases": results.iter().map(CaseResult::json).collect::<Vec<_>>(),
        });
        println!("{}", serde_json::to_string_pretty(&out)?);
    } else {
        print_tables(results, &summary);
    }
    if args.check {
        let failures: Vec<String> = results.iter().flat_map(shortfalls).collect();
        anyhow::ensure!(
            failures.is_empty(),
            "{} of {} campaigns fall short:\n  {}",
            failures.len(),
            results.len(),
            failures.join("\n  ")
        );
    }
    Ok(())
}

/// What a campaign misses of issue 18's rule: it ran; it names every effect of its world
/// and nothing else; each named parameter within tolerance; and where an effect acts, the
/// hold-out error after at most half of before.
fn shortfalls(r: &CaseResult) -> Vec<String> {
    let id = format!("#{} {}", r.index, r.class);
    if let Some(e) = &r.error {
        return vec![format!("{id}: {e}")];
    }
    let mut out: Vec<String> = r
        .truth
        .iter()
        .filter(|(n, _)| !r.names(n))
        .map(|(n, v)| format!("{id}: {n} ({v}) not named"))
        .collect();
    out.extend(
        r.false_discoveries()
            .iter()
            .map(|n| format!("{id}: {n} named but absent")),
    );
    out.extend(
        r.checks
            .iter()
            .filter(|c| c.within() == Some(false))
            .map(|c| {
                format!(
                    "{id}: {} fitted {:?} for {:?}",
                    c.effect, c.fitted, c.expected
                )
            }),
    );
    if !r.truth.is_empty() && !r.halved() {
        let floor = r.floor.map_or(String::new(), |f| {
            format!(
                " (its part over the {:.1} % without the effects)",
                100.0 * f
            )
        });
        out.push(format!(
            "{id}: hold-out {:.1} % -> {:.1} %, not halved{floor}",
            100.0 * r.before,
            100.0 * r.after
        ));
    }
    out
}

impl CaseResult {
    /// Issue 18's "hold-out error after ≤ half of before where an effect acts": halved
    /// outright, or the effects' part of it, over the [`CaseResult::floor`] of the twin
    /// without them; or the effects do not act on the hold-out set, raising its error over
    /// the floor by less than the loop's own relevance, [`MIN_RELATIVE_GAIN`] of it (a baffle
    /// whose clipped sky the model's fill restores: 1.59 % without it, 1.66 % with it, in
    /// campaign #110). False when a figure is NaN.
    fn halved(&self) -> bool {
        self.after <= 0.5 * self.before
            || self.floor.is_some_and(|f| {
                self.after - f <= 0.5 * (self.before - f) || self.before - f < MIN_RELATIVE_GAIN * f
            })
    }
}

/// Simulates one case, runs the loop on it and compares; failures are recorded, not fatal.
fn run_case(
    case: &BatteryCase,
    dir: &Path,
    args: &LoopBenchArgs,
    data_dir: Option<PathBuf>,
    slope: Option<f64>,
) -> CaseResult {
    let mut r = CaseResult {
        index: case.index,
        class: case.class.clone(),
        truth: case.effects.clone(),
        named: vec![],
        checks: vec![],
        before: f64::NAN,
        after: f64::NAN,
        floor: None,
        simulate_s: 0.0,
        loop_s: 0.0,
        error: None,
    };
    let start = Instant::now();
    let simulated = simulated_campaign(case, dir, "campaign", args, data_dir.clone());
    r.simulate_s = start.elapsed().as_secs_f64();
    let campaign = match simulated {
        Ok(c) => c,
        Err(e) => {
            r.error = Some(format!("simulation: {e:#}"));
            return r;
        }
    };
    let start = Instant::now();
    let mut options = LoopOptions::default();
    options.settings.samples_per_sensor = args.samples;
    let outcome = match crate::loop_cmd::run_with_progress(&campaign, &options) {
        Ok(o) => o,
        Err(e) => {
            r.loop_s = start.elapsed().as_secs_f64();
            r.error = Some(format!("loop: {e:#}"));
            return r;
        }
    };
    r.loop_s = start.elapsed().as_secs_f64();
    if args.keep.is_some() {
        if let Err(e) = crate::loop_cmd::write_outcome(&dir.join("loop"), &campaign, &outcome) {
            r.error = Some(format!("writing the loop's report: {e:#}"));
        }
    }
    compare(&mut r, &outcome.report, slope);
    if !r.truth.is_empty() && !r.halved() {
        let start = Instant::now();
        match twin_floor(case, dir, args, data_dir) {
            Ok(f) => r.floor = Some(f),
            Err(e) => r.error = Some(format!("the twin without effects: {e:#}")),
        }
        r.simulate_s += start.elapsed().as_secs_f64();
    }
    r
}

/// The case simulated into `dir/name` (or, with `--reuse`, the one kept there).
fn simulated_campaign(
    case: &BatteryCase,
    dir: &Path,
    name: &str,
    args: &LoopBenchArgs,
    data_dir: Option<PathBuf>,
) -> anyhow::Result<Campaign> {
    let kept = dir.join(name);
    // A campaign is kept whole once its simulation returned (the marker), or once the loop
    // ran on it (kept before the marker existed); one cut short by a stopped run is simulated
    // again.
    let whole = kept.join(SIMULATED_MARKER).is_file()
        || (name == "campaign" && dir.join("loop/report.json").is_file());
    if args.reuse && whole && kept.join("campaign.toml").is_file() {
        return Ok(Campaign::open(&kept)?);
    }
    let room = dir.join(if name == "campaign" {
        "room".to_string()
    } else {
        format!("{name}-room")
    });
    case.write_room(&room)?;
    let mut spec = case.spec(room)?;
    spec.truth = args.truth;
    spec.spectral_data_dir = data_dir;
    if kept.exists() {
        // What a stopped run left: captures of another draw must not mix with this one's.
        std::fs::remove_dir_all(&kept)?;
    }
    simulate_campaign(&kept, &spec, &|_, _| {})?;
    std::fs::write(kept.join(SIMULATED_MARKER), "")?;
    Ok(Campaign::open(&kept)?)
}

/// The file a kept campaign's folder holds once its simulation is complete.
const SIMULATED_MARKER: &str = ".simulated";

/// The hold-out error of the declared model (no effect fitted) on the case's twin: the same
/// draw without its effects, simulated into `dir/twin`.
fn twin_floor(
    case: &BatteryCase,
    dir: &Path,
    args: &LoopBenchArgs,
    data_dir: Option<PathBuf>,
) -> anyhow::Result<f64> {
    let mut twin = case.clone();
    twin.effects.clear();
    let campaign = simulated_campaign(&twin, dir, "twin", args, data_dir)?;
    let mut options = LoopOptions::default();
    options.settings.samples_per_sensor = args.samples;
    options.max_effects = 0;
    Ok(crate::loop_cmd::run_with_progress(&campaign, &options)?
        .report
        .before
        .all)
}

/// The named effects, hold-out errors and parameter checks of a report.
fn compare(r: &mut CaseResult, report: &Report, slope: Option<f64>) {
    r.named = report
        .effects
        .iter()
        .map(|e| (e.name.clone(), e.parameters.clone()))
        .collect();
    r.before = report.before.all;
    r.after = report.after.all;
    r.checks = r
        .truth
        .iter()
        .map(|&(effect, truth)| {
            let tol = TOLERANCES.iter().find(|t| t.effect == effect);
            let expected = match effect {
                "spectral_mismatch" => slope,
                _ => Some(truth),
            };
            let fitted = tol.and_then(|t| {
                report
                    .effects
                    .iter()
                    .find(|e| e.name == effect)
                    .and_then(|e| e.parameters.get(t.parameter).copied())
            });
            ParameterCheck {
                effect,
                truth,
                expected,
                fitted,
            }
        })
        .collect();
}

/// The world's slope of the camera's relative luminance error against its blue / red index
/// ([`MismatchLine`]) for the declared weights; `None` without the spectral data.
fn spectral_slope(data: &Path) -> Option<f64> {
    let weights = skylux_hps::camera::DeviceConfig::default().response.weights;
    MismatchLine::of_daylights(data, weights)
        .ok()
        .map(|l| l.slope_per_index)
}

/// One row of the per-class table.
struct ClassRow {
    class: String,
    campaigns: usize,
    /// Campaigns that named the effect (effect classes only).
    recalled: Option<usize>,
    /// Campaigns with at least one false discovery.
    with_false: usize,
    /// Named parameters within tolerance, of those named.
    within: usize,
    checked: usize,
    /// Median |fitted − expected|.
    median_error: Option<f64>,
    before: f64,
    after: f64,
    seconds: f64,
    failed: usize,
}

impl ClassRow {
    fn json(&self) -> Value {
        json!({
            "class": self.class, "campaigns": self.campaigns, "recalled": self.recalled,
            "campaigns_with_false_discovery": self.with_false,
            "parameters_within_tolerance": self.within, "parameters_checked": self.checked,
            "median_abs_parameter_error": self.median_error,
            "mean_holdout_before": self.before, "mean_holdout_after": self.after,
            "mean_seconds_per_campaign": self.seconds, "failed": self.failed,
        })
    }
}

/// Per effect class (every campaign holding it, alone or in a pair), then `none`, then all.
fn summarise(results: &[CaseResult]) -> Vec<ClassRow> {
    let row = |class: &str, of: Vec<&CaseResult>, effect: Option<&str>| {
        let ok: Vec<&&CaseResult> = of.iter().filter(|r| r.error.is_none()).collect();
        let mean = |f: &dyn Fn(&CaseResult) -> f64| {
            ok.iter().map(|r| f(r)).sum::<f64>() / ok.len().max(1) as f64
        };
        let checks: Vec<&ParameterCheck> = ok
            .iter()
            .flat_map(|r| r.checks.iter())
            .filter(|c| effect == Some(c.effect))
            .collect();
        let mut errors: Vec<f64> = checks
            .iter()
            .filter_map(|c| c.error())
            .map(f64::abs)
            .collect();
        errors.sort_by(f64::total_cmp);
        ClassRow {
            class: class.to_string(),
            campaigns: of.len(),
            recalled: effect.map(|e| ok.iter().filter(|r| r.names(e)).count()),
            with_false: ok
                .iter()
                .filter(|r| !r.false_discoveries().is_empty())
                .count(),
            within: checks.iter().filter(|c| c.within() == Some(true)).count(),
            checked: checks.iter().filter(|c| c.within().is_some()).count(),
            median_error: errors.get(errors.len() / 2).copied(),
            before: mean(&|r| r.before),
            after: mean(&|r| r.after),
            seconds: of.iter().map(|r| r.simulate_s + r.loop_s).sum::<f64>()
                / of.len().max(1) as f64,
            failed: of.len() - ok.len(),
        }
    };
    let mut rows: Vec<ClassRow> = EFFECT_RANGES
        .iter()
        .filter_map(|e| {
            let of: Vec<&CaseResult> = results
                .iter()
                .filter(|r| r.truth.iter().any(|t| t.0 == e.name))
                .collect();
            (!of.is_empty()).then(|| row(e.name, of, Some(e.name)))
        })
        .collect();
    let none: Vec<&CaseResult> = results.iter().filter(|r| r.truth.is_empty()).collect();
    if !none.is_empty() {
        rows.push(row("none", none, None));
    }
    rows.push(row("all", results.iter().collect(), None));
    rows
}

/// True class (as the case names it) × named effect: campaigns.
fn confusion(results: &[CaseResult]) -> BTreeMap<String, BTreeMap<String, usize>> {
    let mut m: BTreeMap<String, BTreeMap<String, usize>> = BTreeMap::new();
    for r in results {
        let row = m.entry(r.class.clone()).or_default();
        *row.entry("campaigns".into()).or_default() += 1;
        for (n, _) in &r.named {
            *row.entry(n.clone()).or_default() += 1;
        }
        if r.named.is_empty() && r.error.is_none() {
            *row.entry("(nothing)".into()).or_default() += 1;
        }
    }
    m
}

fn print_tables(results: &[CaseResult], rows: &[ClassRow]) {
    println!("per effect class (a class counts every campaign holding it, alone or paired):");
    println!(
        "  {:22} {:>5} {:>7} {:>9} {:>11} {:>10} {:>15} {:>7} {:>6}",
        "class",
        "runs",
        "recall",
        "false-ds",
        "params ok",
        "median err",
        "hold-out b -> a",
        "s/run",
        "failed"
    );
    for r in rows {
        println!(
            "  {:22} {:>5} {:>7} {:>9} {:>11} {:>10} {:>6.1} -> {:>4.1} % {:>7.0} {:>6}",
            r.class,
            r.campaigns,
            r.recalled
                .map(|k| format!("{k}/{}", r.campaigns - r.failed))
                .unwrap_or_else(|| "-".into()),
            format!("{}/{}", r.with_false, r.campaigns - r.failed),
            if r.checked > 0 {
                format!("{}/{}", r.within, r.checked)
            } else {
                "-".into()
            },
            r.median_error
                .map(|e| format!("{e:.3}"))
                .unwrap_or_else(|| "-".into()),
            100.0 * r.before,
            100.0 * r.after,
            r.seconds,
            r.failed
        );
    }
    println!("tolerances:");
    for t in TOLERANCES {
        println!(
            "  {:22} {} ±{}{}",
            t.effect,
            t.parameter,
            if t.relative {
                100.0 * t.tolerance
            } else {
                t.tolerance
            },
            if t.relative { " %" } else { "" }
        );
    }
    let columns: Vec<&str> = registry::EFFECTS
        .iter()
        .map(|e| e.name())
        .filter(|n| *n != "luxmeter_calibration")
        .chain(["(nothing)"])
        .collect();
    println!("confusion (true class × named effect, campaigns):");
    let short = |n: &str| n.chars().take(8).collect::<String>();
    print!("  {:42} {:>4}", "true class", "runs");
    for c in &columns {
        print!(" {:>8}", short(c));
    }
    println!();
    for (class, row) in confusion(results) {
        print!(
            "  {class:42} {:>4}",
            row.get("campaigns").copied().unwrap_or(0)
        );
        for c in &columns {
            match row.get(*c) {
                Some(k) => print!(" {k:>8}"),
                None => print!(" {:>8}", "."),
            }
        }
        println!();
    }
    println!("campaigns:");
    for r in results {
        let params: Vec<String> = r
            .checks
            .iter()
            .map(|c| {
                format!(
                    "{} world {:.4} expected {} fitted {}{}",
                    c.effect,
                    c.truth,
                    c.expected.map_or("-".into(), |v| format!("{v:.4}")),
                    c.fitted.map_or("-".into(), |v| format!("{v:.4}")),
                    match c.within() {
                        Some(true) => " (ok)",
                        Some(false) => " (off)",
                        None => "",
                    }
                )
            })
            .collect();
        println!(
            "  #{:<3} {:40} named [{}] false [{}] {:.1} -> {:.1} % {:.0}+{:.0} s{}{}",
            r.index,
            r.class,
            r.named
                .iter()
                .map(|n| n.0.as_str())
                .collect::<Vec<_>>()
                .join(", "),
            r.false_discoveries().join(", "),
            100.0 * r.before,
            100.0 * r.after,
            r.simulate_s,
            r.loop_s,
            if params.is_empty() {
                String::new()
            } else {
                format!("; {}", params.join("; "))
            },
            r.error
                .as_ref()
                .map(|e| format!("; FAILED: {e}"))
                .unwrap_or_default()
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_result_survives_its_json_line() {
        let r = CaseResult {
            index: 7,
            class: "clock_offset+glazing_transmittance".into(),
            truth: vec![("clock_offset", 420.0), ("glazing_transmittance", 0.85)],
            named: vec![(
                "clock_offset".into(),
                BTreeMap::from([("logger_minus_device_s".into(), 415.0)]),
            )],
            checks: vec![ParameterCheck {
                effect: "clock_offset",
                truth: 420.0,
                expected: Some(420.0),
                fitted: Some(415.0),
            }],
            before: 0.18,
            after: 0.07,
            floor: Some(0.02),
            simulate_s: 120.0,
            loop_s: 20.0,
            error: None,
        };
        let line = r.json().to_string();
        let back = CaseResult::from_json(&serde_json::from_str(&line).unwrap()).unwrap();
        assert_eq!(back.json(), r.json());
        assert_eq!(back.checks[0].within(), Some(true));
        let bad = line.replace("clock_offset", "clock_offsett");
        let Err(err) = CaseResult::from_json(&serde_json::from_str(&bad).unwrap()) else {
            panic!("an unknown effect was read");
        };
        assert!(err.to_string().contains("clock_offsett"), "{err}");
    }

    #[test]
    fn the_interleaved_order_visits_every_bucket_before_repeating_one() {
        let cases = interleaved(battery_campaigns(36, 5));
        assert_eq!(cases.len(), 36);
        let first: Vec<String> = cases
            .iter()
            .take(12)
            .map(|c| match c.effects.len() {
                2 => "pair".to_string(),
                _ => c.class.clone(),
            })
            .collect();
        let distinct: std::collections::BTreeSet<&String> = first.iter().collect();
        assert_eq!(distinct.len(), 12, "{first:?}");
        let mut indices: Vec<usize> = cases.iter().map(|c| c.index).collect();
        indices.sort_unstable();
        assert_eq!(indices, (0..36).collect::<Vec<_>>());
    }

    #[test]
    fn a_campaign_falls_short_for_each_broken_rule() {
        let ok = CaseResult {
            index: 1,
            class: "light_leak".into(),
            truth: vec![("light_leak", 0.01)],
            named: vec![(
                "light_leak".into(),
                BTreeMap::from([("lux_per_outdoor_lux".into(), 0.011)]),
            )],
            checks: vec![ParameterCheck {
                effect: "light_leak",
                truth: 0.01,
                expected: Some(0.01),
                fitted: Some(0.011),
            }],
            before: 0.2,
            after: 0.05,
            floor: None,
            simulate_s: 1.0,
            loop_s: 1.0,
            error: None,
        };
        assert!(shortfalls(&ok).is_empty());
        let mut off = CaseResult::from_json(&ok.json()).unwrap();
        off.checks[0].fitted = Some(0.013);
        off.after = 0.15;
        off.named.push(("vignetting".into(), BTreeMap::new()));
        let why = shortfalls(&off).join("; ");
        assert!(why.contains("light_leak fitted"), "{why}");
        assert!(why.contains("not halved"), "{why}");
        assert!(why.contains("vignetting named but absent"), "{why}");
        // Not halved outright, but the effects' part over the twin's floor is.
        let mut floored = CaseResult::from_json(&ok.json()).unwrap();
        (floored.before, floored.after) = (0.04, 0.025);
        assert!(shortfalls(&floored).join("; ").contains("not halved"));
        floored.floor = Some(0.02);
        assert!(
            shortfalls(&floored).is_empty(),
            "{:?}",
            shortfalls(&floored)
        );
        floored.floor = Some(0.005);
        assert!(shortfalls(&floored)[0].contains("over the 0.5 % without"));
        // Effects that do not act on the hold-out set: nothing to halve.
        (floored.before, floored.after, floored.floor) = (0.0166, 0.0167, Some(0.0159));
        assert!(
            shortfalls(&floored).is_empty(),
            "{:?}",
            shortfalls(&floored)
        );
    }

    #[test]
    fn shards_are_checked() {
        assert_eq!(parse_shard("1/3"), Ok((1, 3)));
        assert!(parse_shard("3/3").is_err());
        assert!(parse_shard("x").is_err());
    }
}

//! `skylux bench illuminance`: the engine's speed against `rtrace` at equal error.
//!
//! Both programs compute the workplane illuminance of the reference room
//! (shared/scenes/test-module) under the same sky file. A converged reference comes first:
//! many independent estimates of pure path-traced rtrace, until their standard error is small
//! next to the 1 % target; it is cached, keyed by the scene, the points, the sky and the
//! settings. Then each configuration of rtrace and of our engine is run several times at
//! increasing sample counts, its RMS relative error against the reference measured (the
//! reference's own variance subtracted, as the two are independent), and the time at which
//! it reaches the target interpolated in log-log (Monte-Carlo error falls as t^-1/2, which is
//! also how a point is extrapolated when no measured pair brackets the target).
//!
//! Independent rtrace estimates in one process: with `-u+` rtrace draws from `random()`
//! seeded once per process by the wall clock in seconds (RADIANCE rtmain.c
//! `srandom((long)time(0))`), so repeating the sensor lines k times in the input gives k
//! independent estimates, and processes are started in different seconds. Without an
//! ambient cache (`-aa 0`) nothing is shared between the repetitions. The ambient-cache
//! configuration shares its cache within a process, so each of its estimates is one process.

use anyhow::{bail, Context};
use skylux_hps::engine::{self, Settings, World};
use skylux_hps::scene;
use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::time::Instant;

use skylux_sim::radiance_tools::Radiance;

#[derive(clap::Args)]
pub struct IlluminanceBenchArgs {
    /// Print one JSON object instead of the table.
    #[arg(long)]
    json: bool,
    /// Use the 400-point grid (grid400.pts) instead of the five sensors.
    #[arg(long)]
    grid: bool,
    /// Sky: `perez` (gendaylit, Lausanne 2017-05-08 12:00, DNI 801 W/m², DHI 98 W/m²) or
    /// `overcast` (gensky CIE overcast for the same place and time, 98 W/m² diffuse).
    #[arg(long, default_value = "perez")]
    sky: String,
    /// Folder of the reference room (scene.rad, sensors.pts, grid400.pts).
    #[arg(long)]
    room: Option<PathBuf>,
    /// The room's scene files, relative to `--room`, in the order oconv takes them (default
    /// scene.rad): a corpus room as its authors load it, inline commands run from `--room`
    /// (the LBNL tutorial: `--scene materials.rad room.rad`).
    #[arg(long, num_args = 1..)]
    scene: Vec<PathBuf>,
    /// The points file, relative to `--room` (default sensors.pts, or grid400.pts with --grid).
    #[arg(long)]
    points: Option<PathBuf>,
    /// RMS relative error at which the times are compared.
    #[arg(long, default_value_t = 0.01)]
    target_rel_err: f64,
    /// Largest relative standard error of the reference per point (default 0.002 for the
    /// sensors, 0.01 for the grid).
    #[arg(long)]
    reference_rel_se: Option<f64>,
    /// Most wall time spent building the reference, s (default 900 sensors, 1500 grid).
    #[arg(long)]
    reference_budget_s: Option<f64>,
    /// Independent runs per configuration and sample count.
    #[arg(long, default_value_t = 8)]
    runs: usize,
    /// Skip rtrace's ambient-cache configuration (35-95 s per run).
    #[arg(long)]
    skip_cache_config: bool,
    /// Runs of the ambient-cache configuration (each its own process).
    #[arg(long, default_value_t = 2)]
    cache_runs: usize,
    /// Only the faster rtrace layout (two processes) and the engine's main configurations.
    #[arg(long)]
    quick: bool,
    /// rtrace's specular threshold `-st` for the reference and its runs (default RADIANCE's
    /// 0.15). Scenes with `BSDF` materials need 0: our material samples every component, as
    /// rtrace does at `-st 0` (at 0.15 m_bsdf.c folds the weaker ones into its diffuse term).
    #[arg(long)]
    rtrace_st: Option<f64>,
    /// Our engine only, scored against the reference (cached, or built first): for tuning
    /// the engine between benches; no rtrace timings and no ratio. Incompatible with --json.
    #[arg(long)]
    engine_only: bool,
}

impl IlluminanceBenchArgs {
    /// rtrace's pure path tracing options with `-ad ad` and `-lw lw` (None: [`PURE_ARGS`]'s).
    fn pure_args(&self, ad: u32, lw: Option<&str>) -> Vec<String> {
        let mut a: Vec<String> = PURE_ARGS.iter().map(|s| s.to_string()).collect();
        if let Some(lw) = lw {
            a[PURE_LW] = lw.to_string();
        }
        if let Some(st) = self.rtrace_st {
            a.extend(["-st".to_string(), st.to_string()]);
        }
        a.extend(["-ad".to_string(), ad.to_string()]);
        a
    }
}

/// rtrace's pure path tracing, the specified settings (`-ad` added per run).
const PURE_ARGS: &[&str] = &[
    "-h", "-I", "-u+", "-ab", "12", "-lr", "-16", "-aa", "0", "-as", "0", "-lw", "2e-5",
];
/// Index of `-lw`'s value in [`PURE_ARGS`].
const PURE_LW: usize = 12;
/// The published ambient-cache settings.
const CACHE_ARGS: &[&str] = &[
    "-h", "-I", "-u+", "-ab", "5", "-ad", "1024", "-as", "512", "-aa", "0.1", "-ar", "256",
];
/// Our engine's bounces, as rtrace's pure path tracing.
const OUR_AB: u32 = 12;

/// A cache key of several parts (`numerics::fnv`, each part followed by 0xff).
pub(crate) fn fnv1a(parts: &[&[u8]]) -> u64 {
    use skylux_hps::numerics::fnv::{fnv1a, FNV1A_OFFSET};
    let mut h = FNV1A_OFFSET;
    for p in parts {
        fnv1a(&mut h, p);
        fnv1a(&mut h, &[0xff]);
    }
    h
}

fn lux(rgb: [f64; 3]) -> f64 {
    engine::WHITE_EFFICACY_LM_PER_W * (0.265 * rgb[0] + 0.670 * rgb[1] + 0.065 * rgb[2])
}

fn unix_second() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_secs())
        .unwrap_or(0)
}

/// Waits until the wall clock is in a second later than `last` (rtrace `-u+` seeds with it).
pub(crate) fn next_second(last: &mut u64) {
    while unix_second() <= *last {
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    *last = unix_second();
}

struct Bench<'a> {
    radiance: &'a Radiance,
    dir: PathBuf,
    octree: PathBuf,
    /// The points file's text.
    points: String,
    n_points: usize,
    last_second: u64,
}

impl Bench<'_> {
    /// Starts rtrace with `args` on `replicates` copies of the points (each copy an
    /// independent estimate), without waiting.
    fn spawn(
        &mut self,
        args: &[&str],
        replicates: usize,
        tag: &str,
    ) -> anyhow::Result<std::process::Child> {
        let input = self.dir.join(format!("input-{tag}.pts"));
        std::fs::write(&input, self.points.repeat(replicates))
            .with_context(|| format!("writing {}", input.display()))?;
        next_second(&mut self.last_second);
        let mut c = self.radiance.tool("rtrace");
        c.args(args)
            .arg(&self.octree)
            .stdin(std::fs::File::open(&input)?)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped());
        c.spawn().with_context(|| format!("starting {c:?}"))
    }

    /// rtrace -I output of `replicates` copies of the points: lux per replicate per point.
    fn parse(&self, out: std::process::Output, replicates: usize) -> anyhow::Result<Vec<Vec<f64>>> {
        if !out.status.success() {
            bail!(
                "rtrace failed: {}",
                String::from_utf8_lossy(&out.stderr).trim()
            );
        }
        let text = String::from_utf8_lossy(&out.stdout);
        let mut values = Vec::new();
        for (i, line) in text.lines().filter(|l| !l.trim().is_empty()).enumerate() {
            let v: Vec<f64> = line
                .split_whitespace()
                .map(|x| x.parse::<f64>())
                .collect::<Result<_, _>>()
                .with_context(|| format!("rtrace output line {}: `{line}`", i + 1))?;
            if v.len() != 3 {
                bail!(
                    "rtrace output line {}: expected 3 values, got `{line}`",
                    i + 1
                );
            }
            values.push(lux([v[0], v[1], v[2]]));
        }
        if values.len() != replicates * self.n_points {
            bail!(
                "rtrace gave {} values for {} points x {replicates}",
                values.len(),
                self.n_points
            );
        }
        Ok(values.chunks(self.n_points).map(|c| c.to_vec()).collect())
    }

    /// Runs rtrace on `processes` concurrent processes sharing `replicates` estimates:
    /// the estimates and the wall time per estimate (all points once). Each process is
    /// timed from its start (after `spawn`'s wait for a new second) to its end, and the
    /// concurrent processes' rates (estimates per second) add up.
    fn run(
        &mut self,
        args: &[&str],
        replicates: usize,
        processes: usize,
    ) -> anyhow::Result<(Vec<Vec<f64>>, f64)> {
        let per = replicates.div_ceil(processes);
        let mut children = Vec::new();
        let mut left = replicates;
        for p in 0..processes {
            let n = per.min(left);
            if n == 0 {
                break;
            }
            left -= n;
            let child = self.spawn(args, n, &format!("p{p}"))?;
            children.push((child, n, Instant::now()));
        }
        let finished: Vec<_> = std::thread::scope(|scope| {
            let handles: Vec<_> = children
                .into_iter()
                .map(|(child, n, t0)| {
                    scope.spawn(move || {
                        let out = child.wait_with_output();
                        (out, n, t0.elapsed().as_secs_f64())
                    })
                })
                .collect();
            handles
                .into_iter()
                .map(|h| h.join().expect("rtrace waiting thread"))
                .collect()
        });
        let mut estimates = Vec::new();
        let mut rate_per_s = 0.0;
        for (out, n, seconds) in finished {
            estimates.extend(self.parse(out?, n)?);
            rate_per_s += n as f64 / seconds.max(1e-9);
        }
        Ok((estimates, 1.0 / rate_per_s))
    }
}

/// The converged reference: mean and standard error per point, lux.
#[derive(Clone, Debug)]
struct Reference {
    mean_lux: Vec<f64>,
    se_lux: Vec<f64>,
    estimates: usize,
    rtrace_ad: u32,
    seconds: f64,
    cached: bool,
}

impl Reference {
    fn worst_rel_se(&self) -> f64 {
        self.mean_lux
            .iter()
            .zip(&self.se_lux)
            .map(|(m, s)| s / m.abs().max(1e-9))
            .fold(0.0, f64::max)
    }

    fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "mean_lux": self.mean_lux, "se_lux": self.se_lux, "estimates": self.estimates,
            "rtrace_ad": self.rtrace_ad, "seconds": self.seconds,
        })
    }

    fn from_json(v: &serde_json::Value) -> Option<Self> {
        let list = |k: &str| -> Option<Vec<f64>> {
            v.get(k)?.as_array()?.iter().map(|x| x.as_f64()).collect()
        };
        Some(Self {
            mean_lux: list("mean_lux")?,
            se_lux: list("se_lux")?,
            estimates: v.get("estimates")?.as_u64()? as usize,
            rtrace_ad: v.get("rtrace_ad")?.as_u64()? as u32,
            seconds: v.get("seconds")?.as_f64()?,
            cached: true,
        })
    }
}

fn stats(estimates: &[Vec<f64>], n_points: usize) -> (Vec<f64>, Vec<f64>) {
    let n = estimates.len() as f64;
    (0..n_points)
        .map(|s| {
            let mean = estimates.iter().map(|e| e[s]).sum::<f64>() / n;
            let var =
                estimates.iter().map(|e| (e[s] - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
            (mean, (var / n).sqrt())
        })
        .unzip()
}

/// RMS relative error over points and runs, and the worst point's, against the reference,
/// with the reference's own variance taken out (E[(x − r)²] = var x + var r for independent
/// estimates).
fn rel_errors(estimates: &[Vec<f64>], reference: &Reference) -> RelErrors {
    let mut per_point = Vec::new();
    for (s, (&m, &se)) in reference.mean_lux.iter().zip(&reference.se_lux).enumerate() {
        if m.abs() < 1e-9 {
            continue;
        }
        let mse = estimates
            .iter()
            .map(|e| ((e[s] - m) / m).powi(2))
            .sum::<f64>()
            / estimates.len() as f64;
        per_point.push((mse - (se / m).powi(2)).max(0.0));
    }
    let rms = (per_point.iter().sum::<f64>() / per_point.len().max(1) as f64).sqrt();
    let worst = per_point.iter().copied().fold(0.0, f64::max).sqrt();
    RelErrors { rms, worst }
}

/// Relative errors against the reference: RMS over points and runs, and the worst point's.
#[derive(Clone, Copy, Debug)]
struct RelErrors {
    rms: f64,
    worst: f64,
}

/// When a configuration reaches the target error, and how that time was found.
#[derive(Clone, Copy, Debug)]
struct TimeAtTarget {
    seconds: f64,
    how: &'static str,
}

/// One measured point of a configuration.
#[derive(Clone, Debug)]
struct Point {
    samples: u32,
    seconds: f64,
    rms_rel_err: f64,
    worst_rel_err: f64,
}

impl Point {
    fn new(samples: u32, seconds: f64, errors: RelErrors) -> Self {
        Self {
            samples,
            seconds,
            rms_rel_err: errors.rms,
            worst_rel_err: errors.worst,
        }
    }
}

/// Time at which the RMS error reaches `target`: a least-squares line in log-log (error
/// against time) through the measured points with errors within a factor 2.5 of the target
/// on either side (each point's RMS, from a few runs, is itself uncertain by ±10-15 %, so one
/// pair alone could land on a lucky or unlucky point); else log-log interpolation between the
/// two points that bracket it; else t^-1/2 extrapolation from the point whose error is
/// nearest; and how it was found.
fn time_to(points: &[Point], target: f64) -> Option<TimeAtTarget> {
    let ok: Vec<&Point> = points
        .iter()
        .filter(|p| p.rms_rel_err > 0.0 && p.seconds > 0.0)
        .collect();
    let near: Vec<(f64, f64)> = ok
        .iter()
        .filter(|p| (p.rms_rel_err / target).ln().abs() <= 2.5f64.ln())
        .map(|p| (p.seconds.ln(), p.rms_rel_err.ln()))
        .collect();
    let brackets =
        near.iter().any(|p| p.1 >= target.ln()) && near.iter().any(|p| p.1 <= target.ln());
    if near.len() >= 2 && brackets {
        let n = near.len() as f64;
        let (mx, my) = (
            near.iter().map(|p| p.0).sum::<f64>() / n,
            near.iter().map(|p| p.1).sum::<f64>() / n,
        );
        let sxx: f64 = near.iter().map(|p| (p.0 - mx).powi(2)).sum();
        let sxy: f64 = near.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
        if sxx > 0.0 && sxy < 0.0 {
            let slope = sxy / sxx;
            return Some(TimeAtTarget {
                seconds: (mx + (target.ln() - my) / slope).exp(),
                how: "log-log fit",
            });
        }
    }
    for w in ok.windows(2).rev() {
        let (a, b) = (w[0], w[1]);
        if (a.rms_rel_err - target) * (b.rms_rel_err - target) <= 0.0
            && a.rms_rel_err != b.rms_rel_err
        {
            let f = (target.ln() - a.rms_rel_err.ln()) / (b.rms_rel_err.ln() - a.rms_rel_err.ln());
            return Some(TimeAtTarget {
                seconds: (a.seconds.ln() + f * (b.seconds.ln() - a.seconds.ln())).exp(),
                how: "interpolated",
            });
        }
    }
    let nearest = ok.iter().min_by(|a, b| {
        (a.rms_rel_err / target)
            .ln()
            .abs()
            .total_cmp(&(b.rms_rel_err / target).ln().abs())
    })?;
    Some(TimeAtTarget {
        seconds: nearest.seconds * (nearest.rms_rel_err / target).powi(2),
        how: "extrapolated (t^-1/2)",
    })
}

fn cache_dir() -> PathBuf {
    bench_cache_dir("bench-illuminance")
}

/// `$XDG_CACHE_HOME/skylux/NAME` (or `~/.cache/...`): where benches keep their references.
pub(crate) fn bench_cache_dir(name: &str) -> PathBuf {
    let base = std::env::var_os("XDG_CACHE_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))
        .unwrap_or_else(std::env::temp_dir);
    base.join("skylux").join(name)
}

pub fn run(args: &IlluminanceBenchArgs) -> anyhow::Result<()> {
    if !(args.target_rel_err > 0.0 && args.target_rel_err < 1.0) {
        bail!(
            "--target-rel-err {}: expected between 0 and 1",
            args.target_rel_err
        );
    }
    if args.engine_only && args.json {
        bail!("--engine-only prints its measurements as lines; it has no --json form");
    }
    if args.runs < 2 {
        bail!("--runs {}: expected at least 2", args.runs);
    }
    let radiance = Radiance::find()?;
    let room = Room::read(args)?;
    let sky_spec = SkySpec::of(&args.sky)?;
    let sky = sky_spec.write(&radiance)?;
    let dir = cache_dir();
    std::fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))?;
    let work = tempfile_dir(&dir)?;
    let sky_path = work.join("sky.rad");
    std::fs::write(&sky_path, &sky)?;
    let octree = work.join("room.oct");
    let oct = radiance.output({
        let mut c = radiance.tool("oconv");
        // Frozen (-f): the octree holds the scene, so rtrace need not run where oconv did.
        c.current_dir(&room.dir)
            .arg("-f")
            .args(&room.scene_paths)
            .arg(&sky_path);
        c
    })?;
    std::fs::write(&octree, oct)?;
    let mut bench = Bench {
        radiance: &radiance,
        dir: work.clone(),
        octree,
        points: room.points.clone(),
        n_points: room.sensors.len(),
        last_second: 0,
    };
    let log = |msg: String| {
        if !args.json {
            eprintln!("{msg}");
        }
    };
    let reference = converged_reference(&mut bench, args, &room, &sky, &dir, &log)?;
    let mut scene_files = room.scene_paths.clone();
    scene_files.push(sky_path.clone());
    let mut rtrace_configs = Vec::new();
    if !args.engine_only {
        rtrace_configs = measure_rtrace_pure(&mut bench, args, &reference, &log)?;
        if !args.skip_cache_config {
            rtrace_configs.push(measure_rtrace_cache(&mut bench, args, &reference, &log)?);
        }
    }
    let skylux_configs = measure_engine(
        args,
        &scene_files,
        &room.dir,
        &room.sensors,
        &reference,
        &log,
    )?;
    if args.engine_only {
        // Tuning: the lines above are the result.
        let _ = std::fs::remove_dir_all(&work);
        return Ok(());
    }
    let outcome = Outcome {
        room: &room,
        sky: format!("{} {}", sky_spec.tool, sky_spec.args.join(" ")),
        target: args.target_rel_err,
        reference: &reference,
        reference_command: args.pure_args(reference_ad(args), None).join(" "),
        rtrace_configs: &rtrace_configs,
        skylux_configs: &skylux_configs,
    };
    let summary = outcome.summary()?;
    let _ = std::fs::remove_dir_all(&work);
    if args.json {
        println!("{}", summary.json);
        return Ok(());
    }
    outcome.print_table(&summary);
    Ok(())
}

/// The reference room's files: the scene, and the points as rtrace reads them.
struct Room {
    /// The folder the scene's inline commands and relative paths are read from.
    dir: PathBuf,
    scene_paths: Vec<PathBuf>,
    /// The scene files' texts, one after the other (the reference cache's key; files they
    /// include are not read into it).
    scene_text: Vec<u8>,
    points_path: PathBuf,
    /// The points file without blank or comment lines.
    points: String,
    sensors: Vec<scene::Sensor>,
}

impl Room {
    fn read(args: &IlluminanceBenchArgs) -> anyhow::Result<Self> {
        let room = args.room.clone().unwrap_or_else(|| {
            PathBuf::from(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../../../shared/scenes/test-module"
            ))
        });
        // Absolute: oconv runs in the room's folder.
        let room =
            std::fs::canonicalize(&room).with_context(|| format!("--room {}", room.display()))?;
        let scene_paths: Vec<PathBuf> = if args.scene.is_empty() {
            vec![room.join("scene.rad")]
        } else {
            args.scene.iter().map(|f| room.join(f)).collect()
        };
        let points_path = room.join(args.points.clone().unwrap_or_else(|| {
            PathBuf::from(if args.grid {
                "grid400.pts"
            } else {
                "sensors.pts"
            })
        }));
        let mut scene_text = Vec::new();
        for path in &scene_paths {
            scene_text.extend(
                std::fs::read(path).with_context(|| format!("reading {}", path.display()))?,
            );
        }
        let points = std::fs::read_to_string(&points_path)
            .with_context(|| format!("reading {}", points_path.display()))?;
        let sensors = scene::load_sensors(&points_path)?;
        if sensors.is_empty() {
            bail!("{}: no points", points_path.display());
        }
        let points: String = points
            .lines()
            .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
            .map(|l| format!("{l}\n"))
            .collect();
        Ok(Self {
            dir: room,
            scene_paths,
            scene_text,
            points_path,
            points,
            sensors,
        })
    }
}

/// The sky, the same file for both programs: a RADIANCE generator and its arguments.
struct SkySpec {
    tool: &'static str,
    args: &'static [&'static str],
}

impl SkySpec {
    fn of(name: &str) -> anyhow::Result<Self> {
        Ok(match name {
            "perez" => Self {
                tool: "gendaylit",
                args: &[
                    "5", "8", "12", "-a", "46.52", "-o", "-6.63", "-m", "-15", "-W", "801", "98",
                ],
            },
            "overcast" => Self {
                tool: "gensky",
                args: &[
                    "5", "8", "12", "-c", "-a", "46.52", "-o", "-6.63", "-m", "-15", "-B", "98",
                ],
            },
            other => bail!("--sky {other}: expected perez or overcast"),
        })
    }

    /// The generator's output with the glow sources of sky and ground added.
    fn write(&self, radiance: &Radiance) -> anyhow::Result<Vec<u8>> {
        let mut sky = radiance.output({
            let mut c = radiance.tool(self.tool);
            c.args(self.args);
            c
        })?;
        sky.extend_from_slice(
            b"\nskyfunc glow sky_glow 0 0 4 1 1 1 0\nsky_glow source sky 0 0 4 0 0 1 180\n\
              skyfunc glow ground_glow 0 0 4 1 1 1 0\nground_glow source ground 0 0 4 0 0 -1 180\n",
        );
        Ok(sky)
    }
}

/// The reference: read from the cache, or rtrace's pure path tracing over many seeds until
/// its standard error per point is small enough (or the budget is spent), then cached.
fn converged_reference(
    bench: &mut Bench,
    args: &IlluminanceBenchArgs,
    room: &Room,
    sky: &[u8],
    dir: &Path,
    log: &dyn Fn(String),
) -> anyhow::Result<Reference> {
    let n_points = room.sensors.len();
    let target_se = args
        .reference_rel_se
        .unwrap_or(if args.grid { 0.01 } else { 0.002 });
    let budget_s = args
        .reference_budget_s
        .unwrap_or(if args.grid { 1500.0 } else { 900.0 });
    let ref_ad = reference_ad(args);
    let ref_args_owned = args.pure_args(ref_ad, None);
    let ref_args: Vec<&str> = ref_args_owned.iter().map(String::as_str).collect();
    let key = fnv1a(&[
        &room.scene_text,
        room.points.as_bytes(),
        sky,
        ref_args.join(" ").as_bytes(),
        format!("{target_se} {budget_s}").as_bytes(),
    ]);
    let cache_file = dir.join(format!("reference-{key:016x}.json"));
    if let Some(r) = std::fs::read(&cache_file)
        .ok()
        .and_then(|b| serde_json::from_slice::<serde_json::Value>(&b).ok())
        .and_then(|v| Reference::from_json(&v))
        .filter(|r| r.mean_lux.len() == n_points)
    {
        log(format!(
            "reference: cached in {} ({} estimates, worst relative standard error {:.3} %)",
            cache_file.display(),
            r.estimates,
            100.0 * r.worst_rel_se()
        ));
        return Ok(r);
    }
    log(format!(
        "reference: rtrace {} over many seeds until the standard error is below {:.2} % \
         per point (at most {budget_s:.0} s; cached in {})",
        ref_args.join(" "),
        100.0 * target_se,
        cache_file.display()
    ));
    let start = Instant::now();
    let per_process = if args.grid { 1 } else { 8 };
    let mut all: Vec<Vec<f64>> = Vec::new();
    loop {
        let (e, _) = bench.run(&ref_args, 2 * per_process, 2)?;
        all.extend(e);
        let (mean, se) = stats(&all, n_points);
        let r = Reference {
            mean_lux: mean,
            se_lux: se,
            estimates: all.len(),
            rtrace_ad: ref_ad,
            seconds: start.elapsed().as_secs_f64(),
            cached: false,
        };
        let worst = r.worst_rel_se();
        log(format!(
            "  {} estimates, {:.0} s: worst relative standard error {:.3} %",
            all.len(),
            r.seconds,
            100.0 * worst
        ));
        if (all.len() >= 8 && worst <= target_se) || r.seconds >= budget_s {
            std::fs::write(&cache_file, serde_json::to_vec(&r.to_json())?)?;
            return Ok(r);
        }
    }
}

/// The reference's `-ad`: pure path tracing, [`PURE_ARGS`], with this many ambient divisions.
fn reference_ad(args: &IlluminanceBenchArgs) -> u32 {
    if args.grid {
        8192
    } else {
        32768
    }
}

/// One configuration of a program, and its measured points.
struct Measured {
    label: String,
    points: Vec<Point>,
}

/// rtrace's pure path tracing at increasing `-ad`, with each `-lw` rule and process layout.
fn measure_rtrace_pure(
    bench: &mut Bench,
    args: &IlluminanceBenchArgs,
    reference: &Reference,
    log: &dyn Fn(String),
) -> anyhow::Result<Vec<Measured>> {
    let mut configs = Vec::new();
    let ads: &[u32] = if args.grid {
        &[512, 1024, 2048, 4096]
    } else {
        &[1024, 2048, 4096, 8192, 16384, 32768]
    };
    // -lw: with -lr negative, rays whose weight falls below it go on by Russian roulette
    // (unbiased; RADIANCE rayorigin), so -lw trades time per estimate for variance. With
    // -aa 0 a first-bounce ray weighs about ρ/ad, so the specified 2e-5 puts roulette on the
    // first bounce from -ad 32768 on. Both that value and one that keeps the first two
    // bounces above it (0.1/ad) are timed, and rtrace gets the faster.
    let lw_of = |fixed: bool, ad: u32| {
        if fixed {
            "2e-5".to_string()
        } else {
            format!("{:.3e}", 0.1 / f64::from(ad))
        }
    };
    let lws = [("-lw 2e-5", true), ("-lw 0.1/ad", false)];
    let layouts: &[usize] = if args.quick { &[2] } else { &[1, 2] };
    for &processes in layouts {
        for &(lw_label, fixed) in &lws {
            let mut points_measured = Vec::new();
            for &ad in ads {
                let lw_text = lw_of(fixed, ad);
                let owned = args.pure_args(ad, Some(&lw_text));
                let a: Vec<&str> = owned.iter().map(String::as_str).collect();
                let runs = if args.grid { 2 } else { args.runs };
                let (estimates, seconds) = bench.run(&a, runs.max(processes), processes)?;
                let errors = rel_errors(&estimates, reference);
                log(format!(
                    "rtrace pure path tracing, {processes} process(es), -ad {ad} -lw {lw_text}: \
                     {seconds:.3} s per run, RMS error {:.2} %, worst point {:.2} %",
                    100.0 * errors.rms,
                    100.0 * errors.worst
                ));
                points_measured.push(Point::new(ad, seconds, errors));
            }
            configs.push(Measured {
                label: format!(
                    "pure path tracing {} -ad N, {lw_label}, {processes} process(es){}",
                    PURE_ARGS[3..PURE_LW - 1].join(" "),
                    if processes == 2 {
                        " (the runs split between two concurrent processes: both cores)"
                    } else {
                        ""
                    }
                ),
                points: points_measured,
            });
        }
    }
    Ok(configs)
}

/// rtrace with the published ambient-cache settings, one process per estimate.
fn measure_rtrace_cache(
    bench: &mut Bench,
    args: &IlluminanceBenchArgs,
    reference: &Reference,
    log: &dyn Fn(String),
) -> anyhow::Result<Measured> {
    let mut estimates = Vec::new();
    let mut seconds = 0.0;
    for _ in 0..args.cache_runs.max(1) {
        // One process per estimate: the cache is shared within a process.
        let (e, s) = bench.run(CACHE_ARGS, 1, 1)?;
        estimates.extend(e);
        seconds += s;
    }
    seconds /= args.cache_runs.max(1) as f64;
    let errors = rel_errors(&estimates, reference);
    log(format!(
        "rtrace ambient cache {}: {seconds:.2} s per run, RMS error {:.2} %, worst point {:.2} %",
        CACHE_ARGS[3..].join(" "),
        100.0 * errors.rms,
        100.0 * errors.worst
    ));
    Ok(Measured {
        label: format!("ambient cache {}, 1 process", CACHE_ARGS[3..].join(" ")),
        points: vec![Point::new(1024, seconds, errors)],
    })
}

/// One sampling configuration of our engine.
struct EngineVariant {
    label: &'static str,
    portal_sampling: bool,
    sky_sampling: bool,
    sun_portal_sampling: bool,
    stratified: bool,
    path_reuse: bool,
}

const fn variant(
    label: &'static str,
    [portal_sampling, sky_sampling, sun_portal_sampling, stratified, path_reuse]: [bool; 5],
) -> EngineVariant {
    EngineVariant {
        label,
        portal_sampling,
        sky_sampling,
        sun_portal_sampling,
        stratified,
        path_reuse,
    }
}

/// The engine's configurations, the default first; `--quick` runs the first three.
/// Flags: portal, sky, sun-patch sampling, stratified, path reuse.
const ENGINE_VARIANTS: [EngineVariant; 8] = [
    variant(
        "stratified, portal + sky + sun-patch sampling (MIS), path reuse: the default",
        [true, true, true, true, true],
    ),
    variant(
        "stratified, portal + sun-patch sampling, path reuse",
        [true, false, true, true, true],
    ),
    variant(
        "stratified, portal + sun-patch sampling, no path reuse",
        [true, false, true, true, false],
    ),
    variant(
        "stratified, portal + sky + sun-patch sampling (MIS), no path reuse",
        [true, true, true, true, false],
    ),
    variant(
        "independent samples, portal + sky + sun-patch sampling, no path reuse",
        [true, true, true, false, false],
    ),
    variant(
        "independent samples, portal + sun-patch sampling, no path reuse",
        [true, false, true, false, false],
    ),
    variant(
        "independent samples, portal sampling only, no path reuse",
        [true, false, false, false, false],
    ),
    variant(
        "independent samples, no next-event estimation of sky or sun patch, no path reuse",
        [false, false, false, false, false],
    ),
];

/// Our engine, both cores, at increasing paths per point until well past the target.
fn measure_engine(
    args: &IlluminanceBenchArgs,
    scene_files: &[PathBuf],
    scene_dir: &Path,
    sensors: &[scene::Sensor],
    reference: &Reference,
    log: &dyn Fn(String),
) -> anyhow::Result<Vec<Measured>> {
    let variants = &ENGINE_VARIANTS[..if args.quick { 3 } else { ENGINE_VARIANTS.len() }];
    let counts: &[u32] = if args.grid {
        &[64, 128, 256, 512, 1024]
    } else {
        &[256, 512, 1024, 2048, 4096, 8192, 16384]
    };
    let mut configs = Vec::new();
    for v in variants {
        let mut measured = Vec::new();
        for &n in counts {
            let mut estimates = Vec::new();
            let mut seconds = 0.0;
            for run in 0..args.runs {
                let start = Instant::now();
                // Loaded as oconv read it: inline commands and relative paths from the room.
                let options = scene::LoadOptions {
                    working_directory: Some(scene_dir.to_path_buf()),
                    ..Default::default()
                };
                let scene = scene::load_files_with(scene_files, &options)?;
                let mut world = World::new(&scene)?;
                let points: Vec<_> = sensors.iter().map(|s| s.position_m).collect();
                engine::openings::add_openings(&mut world, &points);
                let settings = Settings {
                    ambient_bounces: OUR_AB,
                    samples_per_sensor: n,
                    seed: 1000 + run as u64,
                    portal_sampling: v.portal_sampling,
                    sky_sampling: v.sky_sampling,
                    sun_portal_sampling: v.sun_portal_sampling,
                    stratified: v.stratified,
                    path_reuse: v.path_reuse,
                    ..Settings::default()
                };
                let result = engine::illuminance(&world, sensors, &settings, &|_, _| {})?;
                seconds += start.elapsed().as_secs_f64();
                estimates.push(result.iter().map(|s| s.illuminance_lux).collect::<Vec<_>>());
            }
            seconds /= args.runs as f64;
            let errors = rel_errors(&estimates, reference);
            log(format!(
                "skylux {}, {n} paths per point: {seconds:.3} s per run, RMS error {:.2} %, \
                 worst point {:.2} %",
                v.label,
                100.0 * errors.rms,
                100.0 * errors.worst
            ));
            measured.push(Point::new(n, seconds, errors));
            // Past the target by a margin: larger counts only cost time.
            if errors.rms < 0.5 * args.target_rel_err {
                break;
            }
        }
        configs.push(Measured {
            label: format!(
                "{}, -ab {OUR_AB}, {} threads",
                v.label,
                rayon::current_num_threads()
            ),
            points: measured,
        });
    }
    Ok(configs)
}

/// The fastest configuration of a program at the target.
#[derive(Clone, Debug)]
struct Fastest {
    label: String,
    at_target: TimeAtTarget,
}

/// The summary as printed with `--json`, and the fastest of each program.
struct Summary {
    json: serde_json::Value,
    rtrace: Fastest,
    skylux: Fastest,
}

/// Everything measured, to summarise and print.
struct Outcome<'a> {
    room: &'a Room,
    /// The sky generator's command line.
    sky: String,
    target: f64,
    reference: &'a Reference,
    /// The reference's rtrace arguments.
    reference_command: String,
    rtrace_configs: &'a [Measured],
    skylux_configs: &'a [Measured],
}

impl Outcome<'_> {
    fn fastest(&self, configs: &[Measured], only_pure: bool) -> Option<Fastest> {
        configs
            .iter()
            .filter(|c| !only_pure || c.label.starts_with("pure"))
            .filter_map(|c| {
                time_to(&c.points, self.target).map(|at_target| Fastest {
                    label: c.label.clone(),
                    at_target,
                })
            })
            .min_by(|a, b| a.at_target.seconds.total_cmp(&b.at_target.seconds))
    }

    /// rtrace's fastest: pure path tracing at the target, or the cache configuration where
    /// it met the target as measured (its error is mostly its bias, which more time at the
    /// same settings does not remove).
    fn rtrace_fastest(&self) -> Option<Fastest> {
        let cache_at_target = self
            .rtrace_configs
            .iter()
            .filter(|c| c.label.starts_with("ambient"))
            .filter_map(|c| {
                c.points
                    .first()
                    .filter(|p| p.rms_rel_err <= self.target)
                    .map(|p| Fastest {
                        label: c.label.clone(),
                        at_target: TimeAtTarget {
                            seconds: p.seconds,
                            how: "measured",
                        },
                    })
            })
            .min_by(|a, b| a.at_target.seconds.total_cmp(&b.at_target.seconds));
        match (self.fastest(self.rtrace_configs, true), cache_at_target) {
            (Some(a), Some(b)) => Some(if b.at_target.seconds < a.at_target.seconds {
                b
            } else {
                a
            }),
            (a, b) => a.or(b),
        }
    }

    fn configs_json(&self, configs: &[Measured]) -> Vec<serde_json::Value> {
        configs
            .iter()
            .map(|c| {
                let t = time_to(&c.points, self.target);
                serde_json::json!({
                    "config": c.label,
                    "seconds_at_target": t.map(|x| x.seconds),
                    "how": t.map(|x| x.how),
                    "points": c.points.iter().map(|p| serde_json::json!({
                        "samples": p.samples, "seconds": p.seconds,
                        "rms_rel_err": p.rms_rel_err, "worst_rel_err": p.worst_rel_err,
                    })).collect::<Vec<_>>(),
                })
            })
            .collect()
    }

    /// Times at the target and the ratio, as one JSON object.
    fn summary(&self) -> anyhow::Result<Summary> {
        // Our fastest configuration (all are the same unbiased estimator with other sampling).
        let (Some(rb), Some(ob)) = (
            self.rtrace_fastest(),
            self.fastest(self.skylux_configs, false),
        ) else {
            bail!("no configuration reached a measurable error");
        };
        let reference = self.reference;
        let json = serde_json::json!({
            "sensors": self.room.sensors.len(),
            "points_file": self.room.points_path.display().to_string(),
            "sky": self.sky,
            "target_rel_err": self.target,
            "error_measure": "RMS over points and runs of (x - reference) / reference, the reference's variance subtracted",
            "rtrace_s": rb.at_target.seconds,
            "rtrace_rel_err": self.target,
            "rtrace_config": rb.label,
            "rtrace_how": rb.at_target.how,
            "skylux_s": ob.at_target.seconds,
            "skylux_rel_err": self.target,
            "skylux_config": ob.label,
            "skylux_how": ob.at_target.how,
            "ratio": ob.at_target.seconds / rb.at_target.seconds,
            "threads": rayon::current_num_threads(),
            "reference": {
                "rtrace": self.reference_command,
                "estimates": reference.estimates,
                "worst_rel_se": reference.worst_rel_se(),
                "seconds": reference.seconds,
                "cached": reference.cached,
            },
            "rtrace_configs": self.configs_json(self.rtrace_configs),
            "skylux_configs": self.configs_json(self.skylux_configs),
        });
        Ok(Summary {
            json,
            rtrace: rb,
            skylux: ob,
        })
    }

    /// The Markdown table of every measured point, the times at the target, and the ratio.
    fn print_table(&self, summary: &Summary) {
        let reference = self.reference;
        let target = self.target;
        println!(
            "{} points, sky `{}`; reference: {} rtrace estimates{} (worst relative standard error {:.3} %)",
            self.room.sensors.len(),
            self.sky,
            reference.estimates,
            if reference.cached { ", cached" } else { "" },
            100.0 * reference.worst_rel_se()
        );
        println!("| program | configuration | samples | s per run | RMS error | worst point |");
        println!("|---|---|---|---|---|---|");
        for (program, configs) in [
            ("rtrace", self.rtrace_configs),
            ("skylux", self.skylux_configs),
        ] {
            for c in configs {
                for p in &c.points {
                    println!(
                        "| {program} | {} | {} | {:.3} | {:.2} % | {:.2} % |",
                        c.label,
                        p.samples,
                        p.seconds,
                        100.0 * p.rms_rel_err,
                        100.0 * p.worst_rel_err
                    );
                }
                if let Some(t) = time_to(&c.points, target) {
                    println!(
                        "| {program} | {} | at {:.1} % | {:.3} ({}) | | |",
                        c.label,
                        100.0 * target,
                        t.seconds,
                        t.how
                    );
                }
            }
        }
        let (rb, ob) = (&summary.rtrace, &summary.skylux);
        println!(
            "time to {:.1} % RMS: rtrace {:.3} s ({}), skylux {:.3} s ({}); ratio ours/rtrace {:.4}",
            100.0 * target,
            rb.at_target.seconds,
            rb.label,
            ob.at_target.seconds,
            ob.label,
            ob.at_target.seconds / rb.at_target.seconds
        );
    }
}

/// A fresh working folder under `base` for this run's sky, octree and inputs.
pub(crate) fn tempfile_dir(base: &Path) -> anyhow::Result<PathBuf> {
    let d = base.join(format!("run-{}-{}", std::process::id(), unix_second()));
    std::fs::create_dir_all(&d).with_context(|| format!("creating {}", d.display()))?;
    Ok(d)
}

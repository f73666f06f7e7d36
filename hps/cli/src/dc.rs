//! `skylux dc`: the daylight-coefficient matrix of a room, and the illuminance under a sky
//! as one matrix-vector product.

use anyhow::Context;
use clap::Args;
use skylux_hps::engine::{self, Settings, World};
use skylux_hps::scene;
use std::path::PathBuf;

#[derive(Args)]
pub struct DcArgs {
    /// The room (RADIANCE scene files, without sky).
    #[arg(long = "scene", required = true)]
    pub scenes: Vec<PathBuf>,
    /// Run inline commands Skylux does not implement (`!cmd` lines other than xform and the
    /// gen* generators) through /bin/sh, as oconv would. A scene file can then run any
    /// program with your rights: use only on files you trust.
    #[arg(long)]
    pub allow_commands: bool,
    #[arg(long)]
    pub sensors: PathBuf,
    /// Reinhart multiplication factor (1: Tregenza 145 patches, 4: 2305).
    #[arg(long, default_value_t = 2)]
    pub mf: usize,
    /// Paths per sensor.
    #[arg(long, default_value_t = 50_000)]
    pub ad: u32,
    #[arg(long, default_value_t = 5)]
    pub ab: u32,
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// The matrix file (RADIANCE matrix format, float32); with --three-phase a folder.
    #[arg(long)]
    pub out: PathBuf,
    /// Three-phase matrices instead of daylight coefficients: V (sensors to the window's
    /// Klems patches, through --scene, the room without its glazing), T (the --bsdf XML),
    /// D (Klems patches to ground + Reinhart MF --mf sky, through --scene and --outside),
    /// written as v.mtx, t.mtx, d.mtx in --out for dctimestep and rmtxop; with --sky, the
    /// product V T D s too (result.mtx, and lux per sensor printed).
    #[arg(long, requires_all = ["window", "bsdf"])]
    pub three_phase: bool,
    /// The window polygons (a RADIANCE file, as rfluxmtx's receiver); front normal into the
    /// room.
    #[arg(long)]
    pub window: Option<PathBuf>,
    /// The up vector of the window's Klems frame (rfluxmtx's `u=`).
    #[arg(long, num_args = 3, allow_negative_numbers = true, default_values_t = [0.0, 0.0, 1.0])]
    pub window_up: Vec<f64>,
    /// The window's BSDF (WINDOW / LBNL XML, Klems).
    #[arg(long)]
    pub bsdf: Option<PathBuf>,
    /// Another state of the same window, NAME=XML (blinds at another angle, a shade down, a
    /// tint: a Klems BSDF on the --bsdf's basis); repeat for several. Written as
    /// t-NAME.mtx; with --sky, the lux under every state (the --bsdf's named "bsdf") from
    /// one product each, V and D traced once.
    #[arg(long = "state", requires = "three_phase")]
    pub states: Vec<String>,
    /// Scene files outside the room (obstructions) that D sees and V does not.
    #[arg(long = "outside")]
    pub outside: Vec<PathBuf>,
    /// Rays per Klems patch for D.
    #[arg(long, default_value_t = 4096)]
    pub d_samples: u32,
    /// Diffuse bounces outside for D.
    #[arg(long, default_value_t = 2)]
    pub d_ab: u32,
    /// Also the five-phase's direct matrices: vd.mtx (V with -ab 1, the sensors' direct view
    /// of the window) and dd.mtx (D with -ab 0, the window's direct view of the sky).
    #[arg(long, requires = "three_phase")]
    pub direct: bool,
    /// A sky vector (RADIANCE matrix: ground, then the MF --mf sky patches, radiance;
    /// gendaymtx's output) to multiply.
    #[arg(long)]
    pub sky: Option<PathBuf>,
}

pub fn run(args: &DcArgs) -> anyhow::Result<()> {
    anyhow::ensure!((1..=8).contains(&args.mf), "--mf must be between 1 and 8");
    if args.three_phase {
        return crate::dc_phase::run(args);
    }
    let scene = scene::load_files_with(
        &args.scenes,
        &scene::LoadOptions {
            allow_commands: args.allow_commands,
            ..Default::default()
        },
    )?;
    let sensors = scene::load_sensors(&args.sensors)?;
    let world = World::new(&scene)?;
    anyhow::ensure!(
        world.distant_sources().is_empty(),
        "the scene holds a sky or sun (distant sources): daylight coefficients need the room alone"
    );
    let settings = Settings {
        ambient_bounces: args.ab,
        samples_per_sensor: args.ad,
        seed: args.seed,
        ..Default::default()
    };
    let bar = indicatif::ProgressBar::new(1);
    let dc = engine::daylight_coefficients(&world, &sensors, args.mf, &settings, &|d, n| {
        bar.set_length(n);
        bar.set_position(d);
    })?;
    bar.finish_and_clear();
    dc.write(&args.out)
        .with_context(|| format!("writing {}", args.out.display()))?;
    println!(
        "{} sensors x {} bins (Reinhart MF{} sky, then mirrored ground) -> {}",
        dc.sensors.len(),
        dc.bins,
        dc.mf,
        args.out.display()
    );
    Ok(())
}

/// `skylux bench dc --json`: one daylight-coefficient update (matrix times patch
/// luminances) for 400 sensors, on one core and all cores.
pub fn bench(json: bool, repeat: usize) -> anyhow::Result<()> {
    let case = skylux_sim::dc_case::DcCase::new();
    let (dc, lum) = (&case.dc, &case.luminance_cd_m2);
    let (sensors, patches, bins) = (dc.sensors.len(), case.sky_patches, dc.bins);
    let mut out = vec![0.0; sensors];
    let time = |pool: &rayon::ThreadPool, out: &mut Vec<f64>| -> anyhow::Result<f64> {
        let mut times = Vec::new();
        for _ in 0..repeat {
            let t = std::time::Instant::now();
            pool.install(|| dc.apply_into(lum, out))?;
            times.push(t.elapsed().as_secs_f64() * 1e3);
        }
        times.sort_by(f64::total_cmp);
        Ok(times[times.len() / 2])
    };
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build()?;
    let all = rayon::ThreadPoolBuilder::new().build()?;
    let single_ms = time(&one, &mut out)?;
    let all_ms = time(&all, &mut out)?;
    // Only the sky patches (2305), as the issue states the budget.
    let sky_only: f64 = {
        let mut times = Vec::new();
        for _ in 0..repeat {
            let t = std::time::Instant::now();
            case.sky_only_update(&mut out);
            times.push(t.elapsed().as_secs_f64() * 1e3);
        }
        times.sort_by(f64::total_cmp);
        times[times.len() / 2]
    };
    let checksum: f64 = out.iter().sum();
    if json {
        println!(
            "{}",
            serde_json::json!({
                "sensors": sensors,
                "sky_patches": patches,
                "bins_with_ground": bins,
                "sky_only_single_core_ms": sky_only,
                "single_core_ms": single_ms,
                "all_cores_ms": all_ms,
                "budget_ms": 1.0,
                "checksum": checksum,
            })
        );
    } else {
        println!(
            "daylight-coefficient update, {sensors} sensors: {patches} sky patches on one core \
             {sky_only:.3} ms; {bins} sky+ground bins {single_ms:.3} ms on one core, \
             {all_ms:.3} ms on all (budget 1 ms)"
        );
    }
    Ok(())
}

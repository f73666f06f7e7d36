//! `skylux illuminance`: workplane illuminance at virtual sensors by path tracing a RADIANCE
//! scene and sky (`skylux_hps::engine`), as `rtrace -I` with converted output would give.

use skylux_hps::engine::{self, Settings, World};
use skylux_hps::scene;
use std::io::Write;
use std::path::PathBuf;

#[derive(clap::Args)]
#[command(after_help = "\
Output (CSV on stdout): a header line `sensor,lux,stderr_lux`, then one line per sensor in the \
order of the sensors file (S1, S2, ...): the illuminance in lux (RADIANCE's 179 lm/W times \
0.265 R + 0.670 G + 0.065 B of the irradiance) and its Monte-Carlo standard error. The sky is \
given as scene files too, e.g. gensky output with its sky and ground glow sources appended.

With --window and --state (a window with several shading states, each a BSDF XML): CSV \
`state,sensor,lux`, every state under the scene's sky from the room's matrices (V, V_d, D, \
D_d, traced once; kept in --matrices DIR for the next sky), the sun through each state at \
its exact direction.")]
pub struct IlluminanceArgs {
    /// RADIANCE scene file; repeat for several (room, then sky), read in order as oconv would.
    #[arg(long = "scene", required = true)]
    scenes: Vec<PathBuf>,
    /// Run inline commands Skylux does not implement (`!cmd` lines other than xform and the
    /// gen* generators) through /bin/sh, as oconv would. A scene file can then run any
    /// program with your rights: use only on files you trust.
    #[arg(long)]
    allow_commands: bool,
    /// Sensor points, RADIANCE .pts (`x y z dx dy dz` per line).
    #[arg(long)]
    sensors: PathBuf,
    /// Most diffuse bounces per path (rtrace -ab).
    #[arg(long, default_value_t = 5)]
    ab: u32,
    /// Paths per sensor (rtrace -ad), at least 1.
    #[arg(long, default_value_t = 1024)]
    ad: u32,
    /// Seed of the random streams; a seed gives the same result on any number of threads.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    #[command(flatten)]
    states: crate::illuminance_states::StatesArgs,
}

pub fn run(args: &IlluminanceArgs) -> anyhow::Result<()> {
    if args.states.window.is_some() {
        return crate::illuminance_states::run(
            &args.scenes,
            args.allow_commands,
            &args.sensors,
            args.seed,
            &args.states,
        );
    }
    let scene = scene::load_files_with(
        &args.scenes,
        &scene::LoadOptions {
            allow_commands: args.allow_commands,
            ..Default::default()
        },
    )?;
    let sensors = scene::load_sensors(&args.sensors)?;
    let mut world = World::new(&scene)?;
    let points: Vec<_> = sensors.iter().map(|s| s.position_m).collect();
    engine::openings::add_openings(&mut world, &points);
    let settings = Settings {
        ambient_bounces: args.ab,
        samples_per_sensor: args.ad,
        seed: args.seed,
        ..Settings::default()
    };
    // Progress on stderr, at most every 5 %, only when stderr is a terminal.
    let show = std::io::IsTerminal::is_terminal(&std::io::stderr());
    let last = std::sync::atomic::AtomicU64::new(0);
    let progress = |done: u64, total: u64| {
        if !show || total == 0 {
            return;
        }
        let percent = done * 100 / total;
        if percent >= last.load(std::sync::atomic::Ordering::Relaxed) + 5 || done == total {
            last.store(percent, std::sync::atomic::Ordering::Relaxed);
            eprint!("\rtracing: {percent:3} %");
            if done == total {
                eprintln!();
            }
        }
    };
    let results = engine::illuminance(&world, &sensors, &settings, &progress)?;
    let mut out = std::io::stdout().lock();
    writeln!(out, "sensor,lux,stderr_lux")?;
    for r in results {
        writeln!(
            out,
            "{},{:.3},{:.3}",
            r.name, r.illuminance_lux, r.stderr_lux
        )?;
    }
    Ok(())
}

//! `skylux`: the command-line tool of the Skylux device.

mod bench;
mod bench_capture;
mod bench_raybox;
mod closure;
mod demo;
mod hdr;
mod illuminance;
mod regs;
mod solpos;

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(
    name = "skylux",
    version,
    about = "Skylux: measure the sky, compute daylight inside"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Runs the main job on a built-in default (today: the deepest slice that works end to end,
    /// the HPS drivers against the cycle-accurate fabric model, then a simulated full-sensor
    /// sky capture through HDR synthesis).
    Demo {
        /// Folder for the simulated campaign and the results.
        #[arg(long, default_value = "skylux-demo")]
        out: std::path::PathBuf,
    },
    /// The pyranometer closure GHI = DNI cos Z + DHI: residual, instrument effects, report.
    Closure(closure::ClosureArgs),
    /// Measures speed next to a reference (`skylux bench hdr --json`).
    Bench(bench::BenchArgs),
    /// Merges a capture folder into a calibrated luminance map (OpenEXR).
    Hdr(hdr::HdrArgs),
    /// Computes workplane illuminance at sensor points by path tracing a RADIANCE scene and sky.
    Illuminance(illuminance::IlluminanceArgs),
    /// Reads every register and prints it decoded, field by field.
    Regs(regs::RegsArgs),
    /// Prints the sun's zenith and azimuth (NREL SPA) for one time and place, as CSV.
    Solpos(solpos::SolposArgs),
}

fn main() -> anyhow::Result<()> {
    match Cli::parse().command {
        Command::Demo { out } => demo::run(&out),
        Command::Hdr(args) => hdr::run(&args),
        Command::Illuminance(args) => illuminance::run(&args),
        Command::Bench(args) => bench::run(&args),
        Command::Closure(args) => closure::run(&args),
        Command::Regs(args) => regs::run(&args),
        Command::Solpos(args) => solpos::run(&args),
    }
}

//! `skylux`: the command-line tool of the Skylux device.

mod bench;
mod bench_capture;
mod bench_genbsdf;
mod bench_illuminance;
mod bench_loop;
mod bench_raybox;
mod bench_raybox_traversal;
mod bench_raybox_unit;
mod bench_render;
mod calibrate;
mod closure;
mod compare;
mod dc;
mod dc_phase;
mod demo;
mod genbsdf;
mod glare;
mod hdr;
mod illuminance;
mod illuminance_states;
mod loop_cmd;
mod regs;
mod render;
mod scene_check;
mod sim_cmd;
mod solpos;
mod sun_cmd;

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
    /// Runs the main job on a built-in default: the drivers against the cycle-accurate fabric
    /// model, then a simulated campaign (Lausanne, a clear and an overcast day, an undeclared
    /// effect) through HDR, sun, daylight coefficients and the loop, with its report.
    Demo {
        /// Folder for the simulated campaign and the results.
        #[arg(long, default_value = "skylux-demo")]
        out: std::path::PathBuf,
    },
    /// Camera calibration: `skylux calibrate spectral|vignetting|response|geometry ...`
    /// writes device.toml and a report (docs/calibration.md).
    Calibrate(calibrate::CalibrateArgs),
    /// The pyranometer closure GHI = DNI cos Z + DHI: residual, instrument effects, report.
    Closure(closure::ClosureArgs),
    /// Measures speed next to a reference (`skylux bench hdr --json`).
    Bench(bench::BenchArgs),
    /// Computes a room's daylight-coefficient matrix (illuminance per unit sky patch).
    Dc(dc::DcArgs),
    /// A Klems BSDF (WINDOW / LBNL XML) from a detailed RADIANCE model of a blind, a frit, a
    /// PV tile, as genBSDF makes it: `skylux genbsdf DEVICE.rad --out device.xml`.
    Genbsdf(genbsdf::GenBsdfArgs),
    /// Merges a capture folder into a calibrated luminance map (OpenEXR).
    Hdr(hdr::HdrArgs),
    /// Computes workplane illuminance at sensor points by path tracing a RADIANCE scene and sky.
    Illuminance(illuminance::IlluminanceArgs),
    /// Runs the device model against a campaign's lux-meters, adds the effects the residual
    /// calls for, and reports before and after on held-out times.
    Loop(loop_cmd::LoopArgs),
    /// The simulated world: `skylux sim campaign --out DIR [--effect NAME=VALUE]`.
    Sim(sim_cmd::SimArgs),
    /// Compares a measured luminance picture with a rendered one of the same view: relative
    /// errors per pixel and per region, luminance histograms, a falsecolour error map.
    Compare(compare::CompareArgs),
    /// Glare indices (Ev, DGP, DGI, UGR, CGI, VCP) and glare sources of a luminance picture,
    /// as evalglare computes them.
    Glare(glare::GlareArgs),
    /// Renders an image of a RADIANCE scene from a view: PREFIX.exr, PREFIX.hdr, PREFIX.png.
    Render(render::RenderArgs),
    /// Scene files: `skylux scene check FILE... [--json]` loads them as the engine would and
    /// reports counts, bounds, units, missing files and unused modifiers.
    Scene(scene_check::SceneArgs),
    /// Reads every register and prints it decoded, field by field.
    Regs(regs::RegsArgs),
    /// Prints the sun's zenith and azimuth (NREL SPA) for one time and place, as CSV.
    Solpos(solpos::SolposArgs),
    /// Tracks the sun in every capture of a campaign against SPA (sun.csv, sun.png); fits
    /// the camera's orientation and principal point from the sightings.
    Sun(sun_cmd::SunArgs),
}

fn main() -> anyhow::Result<()> {
    quiet_on_closed_pipe();
    match Cli::parse().command {
        Command::Demo { out } => demo::run(&out),
        Command::Dc(args) => dc::run(&args),
        Command::Compare(args) => compare::run(&args),
        Command::Glare(args) => glare::run(&args),
        Command::Genbsdf(args) => genbsdf::run(&args),
        Command::Hdr(args) => hdr::run(&args),
        Command::Illuminance(args) => illuminance::run(&args),
        Command::Bench(args) => bench::run(&args),
        Command::Calibrate(args) => calibrate::run(&args),
        Command::Closure(args) => closure::run(&args),
        Command::Loop(args) => loop_cmd::run(&args),
        Command::Sim(args) => sim_cmd::run(&args),
        Command::Regs(args) => regs::run(&args),
        Command::Render(args) => render::run(&args),
        Command::Scene(args) => scene_check::run(&args),
        Command::Solpos(args) => solpos::run(&args),
        Command::Sun(args) => sun_cmd::run(&args),
    }
}

/// `skylux ... | head` ends quietly when the reader goes, as other Unix tools do, instead of
/// panicking in `println!` on the broken pipe: SIGPIPE back to its default action (Rust
/// starts programs with it ignored).
fn quiet_on_closed_pipe() {
    #[cfg(unix)]
    // SAFETY: called first in main, before any thread starts; SIG_DFL is a valid handler.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}

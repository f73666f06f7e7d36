//! `skylux sim campaign --out DIR [--effect NAME=VALUE ...] [--sky clear|overcast|partly]`:
//! a campaign from the simulated world, with effects present but not declared.

use anyhow::Context;
use clap::{Args, Subcommand};
use skylux_sim::campaign::{simulate_campaign, CampaignSpec, DaySky, LoggerSchedule, TruthSource};
use std::path::PathBuf;

#[derive(Args)]
pub struct SimArgs {
    #[command(subcommand)]
    pub what: SimCommand,
}

#[derive(Subcommand)]
pub enum SimCommand {
    /// Writes a campaign (campaign.toml, device.toml, room, captures, luxmeters.csv,
    /// pyranometer.csv).
    Campaign(SimCampaignArgs),
}

#[derive(Args)]
pub struct SimCampaignArgs {
    #[arg(long)]
    pub out: PathBuf,
    /// An undeclared effect, NAME=VALUE (the loop's effect names, or their aliases);
    /// repeatable. glazing_transmittance (relative, 0.1 to
    /// 1.5), light_leak (lux per outdoor lux, 0 to 0.2), ground_reflectance (0 to 1),
    /// orientation_error (axis azimuth, degrees, ±10), clock_offset (lux-meter logger minus
    /// device clock, seconds, ±1800 (beyond ±5 min give --logger-half-window-s); visible only when the light changes within minutes: use
    /// --sky partly), shutter_overhead (µs added to every declared exposure, 0 to 100),
    /// spectral_mismatch (the clear sky's colour temperature far from the sun, K, 4000 to
    /// 25000: frames rendered with the sky's real colour through measured camera
    /// sensitivities, device.toml calibrated under D65; needs the shared data folder,
    /// $SKYLUX_DATA_DIR or shared/data beside the room).
    /// glazing_angular (ASHRAE incidence-angle modifier b0 of the glazing, 0 to 1: light
    /// through it at incidence θ times 1 − b0 (1/cos θ − 1); 0.05 is clean glass).
    /// vignetting (v of an extra relative illumination 1 − v (α/90°)² on top of the declared
    /// polynomial, 0 to 0.9), sky_outside_fov (also fov_limit_deg: a baffle darkens the
    /// image beyond this off-axis angle, degrees, 20 to 180).
    #[arg(long = "effect")]
    pub effects: Vec<String>,
    /// The sky of every day (default: one clear and one overcast day). `partly`: broken
    /// clouds; at two captures in three they pass over the sun within minutes (the direct
    /// beam switches on and off every 2 to 4 min, each edge taking some 30 s), and the
    /// lux-meters then log every 30 s within ±10 min of each capture.
    #[arg(long)]
    pub sky: Option<DaySky>,
    /// The room folder (scene.rad, sensors.pts); default: the reference test module.
    #[arg(long)]
    pub room: Option<PathBuf>,
    /// Capture every this many minutes from 8:00 to 18:00.
    #[arg(long, default_value_t = 60)]
    pub every_minutes: u32,
    #[arg(long, default_value_t = 2017)]
    pub seed: u64,
    /// Paths per sensor of the engine run that gives the true illuminance.
    #[arg(long, default_value_t = 16_384)]
    pub truth_samples: u32,
    /// Readout skip of the simulated frames (1: full 2592x1944; 4: 648x486).
    #[arg(long, default_value_t = 4)]
    pub skip: u32,
    /// What gives the lux-meters' truth: `engine` (Skylux's own, 12 bounces), `radiance`
    /// (RADIANCE's rcontrib daylight coefficients, 12 bounces: independent of the engine the
    /// loop's model uses; needs RADIANCE) or `radiance:N` (N bounces).
    #[arg(long, default_value = "engine")]
    pub truth: TruthSource,
    /// Every capture's lux-meters log a reading every 30 s within this many seconds of it (0
    /// to 1800; at most half the capture spacing less 30 s, so windows never overlap).
    /// Default: one reading per capture, or ±600 s on partly cloudy days and with a clock
    /// offset.
    #[arg(long)]
    pub logger_half_window_s: Option<f64>,
}

/// The reference test module beside the checkout (`../shared/scenes/test-module`), or
/// `$SKYLUX_ROOM_DIR`.
pub fn default_room() -> anyhow::Result<PathBuf> {
    if let Some(d) = std::env::var_os("SKYLUX_ROOM_DIR") {
        return Ok(d.into());
    }
    let candidates = [
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/scenes/test-module"),
        PathBuf::from("../shared/scenes/test-module"),
    ];
    candidates
        .into_iter()
        .find(|p| p.join("scene.rad").is_file())
        .context(
            "the reference room (shared/scenes/test-module beside the checkout) is missing; \
             give --room or set SKYLUX_ROOM_DIR",
        )
}

pub fn spec_from(args: &SimCampaignArgs) -> anyhow::Result<CampaignSpec> {
    let room = match &args.room {
        Some(r) => r.clone(),
        None => default_room()?,
    };
    let mut spec = CampaignSpec::lausanne(room);
    for e in &args.effects {
        spec.effects.set(e).map_err(anyhow::Error::msg)?;
    }
    if let Some(sky) = args.sky {
        for d in &mut spec.days {
            d.1 = sky;
        }
    }
    anyhow::ensure!(
        (10..=240).contains(&args.every_minutes),
        "--every-minutes must be between 10 and 240"
    );
    spec.hours = (0..)
        .map(|k| 8.0 + f64::from(k * args.every_minutes) / 60.0)
        .take_while(|h| *h <= 18.0 + 1e-9)
        .collect();
    spec.seed = args.seed;
    anyhow::ensure!(args.truth_samples > 0, "--truth-samples must be at least 1");
    spec.truth_samples = args.truth_samples;
    anyhow::ensure!(
        (1..=8).contains(&args.skip),
        "--skip must be between 1 and 8"
    );
    spec.skip = args.skip;
    spec.truth = args.truth;
    if let Some(half) = args.logger_half_window_s {
        let widest = LoggerSchedule::continuous(f64::from(args.every_minutes) * 60.0);
        anyhow::ensure!(
            half >= 0.0 && half <= widest.half_window_s,
            "--logger-half-window-s {half}: must be within 0 to {} s with captures every {} min",
            widest.half_window_s,
            args.every_minutes
        );
        spec.logger = Some(LoggerSchedule {
            half_window_s: half,
            ..widest
        });
    }
    Ok(spec)
}

pub fn run(args: &SimArgs) -> anyhow::Result<()> {
    match &args.what {
        SimCommand::Campaign(a) => {
            let spec = spec_from(a)?;
            let truth = simulate_campaign(&a.out, &spec, &|_, _| {})?;
            println!(
                "wrote {} captures to {} (effects: {:?})",
                truth.len(),
                a.out.display(),
                spec.effects
            );
            Ok(())
        }
    }
}

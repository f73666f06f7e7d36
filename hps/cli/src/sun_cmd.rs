//! `skylux sun --campaign DIR`: the sun in every capture of a campaign, measured against SPA
//! (`sun.csv`, `sun.png`), and optionally the camera's orientation and principal point fitted
//! from the sightings (`sun_fit.json`, `--write-device`). The work is in
//! `skylux_hps::sun::tracking`; this file parses and prints.

use anyhow::Context;
use clap::Args;
use serde_json::json;
use skylux_hps::camera::DeviceConfig;
use skylux_hps::campaign::Campaign;
use skylux_hps::output::write_atomic;
use skylux_hps::sun::tracking::{
    fit_camera, reproject, summarise, track_campaign, write_csv, write_plot, FitTarget, SunFit,
    TrackingOptions, TrackingSummary,
};
use skylux_hps::sun::SunFlag;
use std::path::{Path, PathBuf};

#[derive(Args)]
#[command(after_help = "\
Writes into --out: sun.csv (one row per capture: measured and SPA altitude and azimuth, \
angular error, disk luminance, DNI in lux and its source, flags), sun.png (luminance, altitude \
and azimuth against time), and with a fit sun_fit.json (the fitted orientation, principal point \
and the residual in degrees). The measured angles are through the campaign's device.toml; \
with a fit, the fitted_* columns are through the fitted camera.")]
pub struct SunArgs {
    /// The campaign folder (shared/spec/campaign.md).
    #[arg(long)]
    pub campaign: PathBuf,
    /// Where the results go [default: <campaign>/sun].
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Groups at or above this luminance are sun candidates, cd/m2.
    #[arg(long, default_value_t = skylux_hps::sun::SUNSHINE_THRESHOLD_CD_M2)]
    pub threshold_cd_m2: f64,
    /// Fit the camera's orientation to the sun sightings.
    #[arg(long)]
    pub fit_orientation: bool,
    /// Fit the principal point jointly with the orientation (implies --fit-orientation).
    #[arg(long)]
    pub fit_principal_point: bool,
    /// Write the campaign's device.toml with the fitted orientation (and principal point) to
    /// FILE.
    #[arg(long, value_name = "FILE")]
    pub write_device: Option<PathBuf>,
    /// Compare with the apparent (refracted) sun for the standard atmosphere at the site's
    /// elevation, as a real camera sees it; the simulator renders the geometric sun.
    #[arg(long)]
    pub refraction: bool,
}

fn deg(v: Option<f64>) -> String {
    v.map(|v| format!("{v:.4} deg"))
        .unwrap_or_else(|| "n/a".into())
}

pub fn run(args: &SunArgs) -> anyhow::Result<()> {
    anyhow::ensure!(
        args.threshold_cd_m2.is_finite() && args.threshold_cd_m2 > 0.0,
        "--threshold-cd-m2 must be a positive number, got {}",
        args.threshold_cd_m2
    );
    let target = if args.fit_principal_point {
        Some(FitTarget::OrientationAndPrincipalPoint)
    } else if args.fit_orientation {
        Some(FitTarget::Orientation)
    } else {
        None
    };
    anyhow::ensure!(
        args.write_device.is_none() || target.is_some(),
        "--write-device needs --fit-orientation or --fit-principal-point"
    );
    let campaign = Campaign::open(&args.campaign)
        .with_context(|| format!("opening the campaign {}", args.campaign.display()))?;
    let device_path = campaign.path(&campaign.config.files.device);
    let (device, warnings) = DeviceConfig::read(&device_path)?;
    for w in warnings {
        eprintln!("warning: {w}");
    }
    let out = args.out.clone().unwrap_or_else(|| campaign.dir.join("sun"));
    std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
    let options = TrackingOptions {
        threshold_cd_m2: args.threshold_cd_m2,
        refraction: args.refraction,
        ..Default::default()
    };
    let bar = indicatif::ProgressBar::new(campaign.captures.len() as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template("  sun per capture [{bar:30}] {pos}/{len}")
            .expect("template")
            .progress_chars("=> "),
    );
    let tracks = track_campaign(&campaign, &device, &options, &|done, _| {
        bar.set_position(done as u64)
    })?;
    bar.finish_and_clear();
    let declared = summarise(&tracks, None);

    let csv = out.join("sun.csv");
    let title = format!("Sun: {}", campaign.config.name);
    // The tracking first, so that a fit that fails leaves it to look at.
    write_csv(&csv, &tracks, None)?;
    write_plot(&out.join("sun.png"), &title, &tracks, None)?;
    let fit = match target {
        None => None,
        Some(t) => Some(fit_camera(&device, &tracks, t).with_context(|| {
            format!(
                "fitting the camera to the sun sightings of {} (device {}; the sightings \
                 are in {})",
                campaign.dir.display(),
                device_path.display(),
                csv.display()
            )
        })?),
    };
    let fitted_directions = fit.as_ref().map(|f| reproject(&tracks, &f.device));
    let after = fitted_directions
        .as_deref()
        .map(|d| summarise(&tracks, Some(d)));
    if let Some(directions) = fitted_directions.as_deref() {
        write_csv(&csv, &tracks, Some(directions))?;
        write_plot(&out.join("sun.png"), &title, &tracks, Some(directions))?;
    }
    print_summary(&declared, after.as_ref());
    if let Some(fit) = &fit {
        if let Some(path) = &args.write_device {
            write_device(path, &fit.device)?;
        }
        let json = fit_json(
            &device,
            fit,
            &tracks,
            &declared,
            args.write_device.as_deref(),
        );
        write_atomic(
            &out.join("sun_fit.json"),
            serde_json::to_string_pretty(&json)?.as_bytes(),
        )?;
        print_fit(&device, fit, tracks.len());
        if let Some(path) = &args.write_device {
            println!("  device.toml with the fitted camera: {}", path.display());
        }
    }
    if declared.suns == 0 {
        println!(
            "  no capture shows the sun ({} captures; see the flags and notes in sun.csv)",
            tracks.len()
        );
    }
    println!("  results: {}", out.display());
    Ok(())
}

/// Writes `device` to `path` through a temporary file and a rename, then reads it back.
fn write_device(path: &Path, device: &DeviceConfig) -> anyhow::Result<()> {
    let tmp = path.with_extension("toml.tmp");
    device.write(&tmp)?;
    std::fs::rename(&tmp, path)
        .with_context(|| format!("renaming {} to {}", tmp.display(), path.display()))?;
    let (back, _) = DeviceConfig::read(path)?;
    anyhow::ensure!(
        &back == device,
        "{}: the written device.toml does not read back to the fitted camera",
        path.display()
    );
    Ok(())
}

fn fit_json(
    declared: &DeviceConfig,
    fit: &SunFit,
    tracks: &[skylux_hps::sun::tracking::SunTrack],
    before: &TrackingSummary,
    device_file: Option<&Path>,
) -> serde_json::Value {
    let time = |i: &usize| tracks[*i].time.to_rfc3339();
    json!({
        "fit": match fit.target {
            FitTarget::Orientation => "orientation",
            FitTarget::OrientationAndPrincipalPoint => "orientation_and_principal_point",
        },
        "sightings_used": fit.used.len(),
        "saturated_sightings_used": fit
            .used
            .iter()
            .filter(|&&i| tracks[i].flags.contains(&SunFlag::Saturated))
            .count(),
        "sightings_dropped": fit.dropped.iter().map(time).collect::<Vec<_>>(),
        "residual_rms_deg": fit.residual_rms_deg,
        "residual_max_deg": fit.residual_max_deg,
        "declared_error_rms_deg": before.direction_rms_deg,
        "declared_error_max_deg": before.direction_max_deg,
        "orientation": fit.device.orientation,
        "declared_orientation": declared.orientation,
        "center_px": fit.device.lens.center_px,
        "declared_center_px": declared.lens.center_px,
        "center_sd_px": fit.center_sd_px,
        "device_written": device_file.map(|p| p.display().to_string()),
    })
}

fn print_summary(declared: &TrackingSummary, after: Option<&TrackingSummary>) {
    println!(
        "  {} captures: sun found in {} ({} saturated, {} partly covered), DNI from the \
         pyranometer in {}",
        declared.captures,
        declared.suns,
        declared.saturated,
        declared.partly_covered,
        declared.dni_from_pyranometer
    );
    println!(
        "  sun direction vs SPA, declared camera: rms {}, max {}",
        deg(declared.direction_rms_deg),
        deg(declared.direction_max_deg)
    );
    if let Some(a) = after {
        println!(
            "  sun direction vs SPA, fitted camera:   rms {}, max {}",
            deg(a.direction_rms_deg),
            deg(a.direction_max_deg)
        );
    }
    match declared.luminance_rel_rmse {
        Some(r) => println!(
            "  disk luminance vs pyranometer DNI: relative RMSE {:.2} % over {} captures",
            100.0 * r,
            declared.luminance_compared
        ),
        None => println!("  disk luminance vs pyranometer DNI: no capture to compare"),
    }
}

fn print_fit(declared: &DeviceConfig, fit: &SunFit, captures: usize) {
    let o = &fit.device.orientation;
    let d = &declared.orientation;
    println!(
        "  fitted orientation from {} of {} captures ({} dropped as outliers): axis azimuth \
         {:.4} deg ({:+.4}), altitude {:.4} deg ({:+.4}), roll {:.4} deg ({:+.4})",
        fit.used.len(),
        captures,
        fit.dropped.len(),
        o.axis_azimuth_deg,
        (o.axis_azimuth_deg - d.axis_azimuth_deg + 540.0).rem_euclid(360.0) - 180.0,
        o.axis_altitude_deg,
        o.axis_altitude_deg - d.axis_altitude_deg,
        o.roll_deg,
        (o.roll_deg - d.roll_deg + 540.0).rem_euclid(360.0) - 180.0,
    );
    if let Some(sd) = fit.center_sd_px {
        let c = fit.device.lens.center_px;
        println!(
            "  fitted principal point: ({:.3}, {:.3}) px ({:+.3}, {:+.3}), standard error \
             ({:.3}, {:.3}) px",
            c[0],
            c[1],
            c[0] - declared.lens.center_px[0],
            c[1] - declared.lens.center_px[1],
            sd[0],
            sd[1]
        );
    }
    println!(
        "  fit residual: rms {:.4} deg, max {:.4} deg",
        fit.residual_rms_deg, fit.residual_max_deg
    );
}

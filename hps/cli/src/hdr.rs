//! `skylux hdr <capture-dir> --device device.toml --out map.exr`: a capture to a calibrated
//! luminance map.

use anyhow::Context;
use skylux_hps::camera::DeviceConfig;
use skylux_hps::hdr::{map_capture, write_exr, MapFlag};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct HdrArgs {
    /// The capture folder (holding capture.toml and the raw frames).
    capture_dir: PathBuf,
    /// The camera calibration.
    #[arg(long)]
    device: PathBuf,
    /// Where to write the OpenEXR luminance map.
    #[arg(long)]
    out: PathBuf,
    /// Also write the map as a RADIANCE sky (sky.hdr, skylux_sky.cal, sky.rad) in this folder;
    /// directions the lens did not see are filled from Reinhart MF4 sky patches.
    #[arg(long)]
    radiance_sky: Option<PathBuf>,
}

pub fn run(args: &HdrArgs) -> anyhow::Result<()> {
    let (device, warnings) = DeviceConfig::read(&args.device)?;
    for w in warnings {
        eprintln!("warning: {w}");
    }
    let merged = map_capture(&args.capture_dir, &device)?;
    write_exr(&args.out, &merged.map, &device, &merged.capture.readout)
        .with_context(|| "writing the map")?;
    if let Some(dir) = &args.radiance_sky {
        let camera = skylux_hps::camera::CameraModel::new(device.clone());
        let lookup = skylux_hps::sky::SkyLookup::new(&camera, &merged, 4);
        skylux_hps::hdr::write_radiance_sky(dir, 1024, &|d| lookup.luminance_cd_m2(d))
            .with_context(|| format!("writing the RADIANCE sky to {}", dir.display()))?;
        println!(
            "{}: RADIANCE sky (sky.rad, sky.hdr, skylux_sky.cal); {} of {} MF4 patches filled",
            dir.display(),
            lookup.patch_sky.filled.len(),
            lookup.patches.len()
        );
    }
    let map = &merged.map;
    let count = |f: MapFlag| map.flags.iter().filter(|x| **x == f).count();
    let valid: Vec<f32> = map
        .luminance_cd_m2
        .iter()
        .zip(&map.flags)
        .filter(|(_, f)| **f == MapFlag::Valid)
        .map(|(l, _)| *l)
        .filter(|l| *l > 0.0)
        .collect();
    let (lo, hi) = valid
        .iter()
        .fold((f32::MAX, 0.0f32), |(a, b), &l| (a.min(l), b.max(l)));
    println!(
        "{}: {}x{} groups from {} exposures; valid {}, over-range {}, under-range {}",
        args.out.display(),
        map.width,
        map.height,
        merged.capture.exposure.len(),
        count(MapFlag::Valid),
        count(MapFlag::OverRange),
        count(MapFlag::UnderRange)
    );
    if !valid.is_empty() {
        println!(
            "luminance {lo:.3e} to {hi:.3e} cd/m2 ({:.1} dB)",
            20.0 * (hi as f64 / lo as f64).log10()
        );
    }
    Ok(())
}

//! `skylux calibrate spectral|vignetting|response|geometry ...`: the camera calibration steps
//! of `skylux_hps::calibration`. Each reads a starting `device.toml` (or the campaign spec's
//! example camera), fits its part, and writes `device.toml` and `<step>_report.{json,md}` into
//! `--out` (atomic writes). See docs/calibration.md.

use anyhow::Context;
use clap::{Args, Subcommand};
use skylux_hps::calibration::geometry::{
    calibrate_geometry, read_correspondences, GeometryOptions,
};
use skylux_hps::calibration::response::{calibrate_response, parse_known_source, ResponseOptions};
use skylux_hps::calibration::spectral::{calibrate_spectral, read_filters, SpectralInputs};
use skylux_hps::calibration::vignetting::{calibrate_vignetting, VignettingOptions};
use skylux_hps::calibration::{write_outputs, StepOutput};
use skylux_hps::camera::DeviceConfig;
use skylux_hps::photometry::spectral::{
    data_dir_from_env, illuminant_a, load_d65, load_photopic, load_rgb_sensitivities,
};
use std::path::{Path, PathBuf};

#[derive(Args)]
pub struct CalibrateArgs {
    #[command(subcommand)]
    step: Step,
}

/// Options every step shares.
#[derive(Args)]
struct Common {
    /// The device.toml to start from [default: the campaign spec's example camera].
    #[arg(long)]
    device: Option<PathBuf>,
    /// Folder for device.toml and the report (<step>_report.json, <step>_report.md).
    #[arg(long)]
    out: PathBuf,
}

#[derive(Subcommand)]
enum Step {
    /// f1' (ISO/CIE 19476, illuminant A; and the D65 variant) of measured RGB sensitivities,
    /// the RGB weights that minimise it, and the best filter of a set.
    Spectral {
        /// CSV of the camera's sensitivities: wavelength_nm (or wavelength), R, G, B.
        #[arg(long)]
        sensitivities: PathBuf,
        /// Transmittance curves (a CSV, every column after the wavelength one filter, or a
        /// folder of them); the best one, with refitted weights, is chosen if it beats none.
        #[arg(long)]
        filters: Option<PathBuf>,
        /// The shared data folder holding spectral/cie_1924_photopic_V.csv and
        /// spectral/cie_illuminant_D65.csv [default: $SKYLUX_DATA_DIR, else ../shared/data].
        #[arg(long)]
        data: Option<PathBuf>,
        #[command(flatten)]
        common: Common,
    },
    /// V(α) = Σ a_i cos^i α from a capture folder of a uniform source.
    Vignetting {
        /// The capture folder (capture.toml and frames).
        capture_dir: PathBuf,
        /// Polynomial order.
        #[arg(long, default_value_t = 4)]
        order: usize,
        /// Half-width of the 2-D smoothing window, groups.
        #[arg(long, default_value_t = 2)]
        smooth: usize,
        /// Groups farther off axis are not used, degrees.
        #[arg(long, default_value_t = 90.0)]
        max_off_axis_deg: f64,
        #[command(flatten)]
        common: Common,
    },
    /// cg from captures of a source of known luminance at several exposures (linear region
    /// only), and the uniform-source check (3 x 3 groups averaged over the captures).
    Response {
        /// CAPTURE_DIR=LUMINANCE_CD_M2, one per capture (repeat captures of one source share
        /// its luminance).
        #[arg(long = "source", required = true, value_parser = parse_known_source)]
        sources: Vec<skylux_hps::calibration::response::KnownSource>,
        /// Only groups at most this far off axis are used, degrees.
        #[arg(long, default_value_t = 30.0)]
        max_off_axis_deg: f64,
        /// Exposures with a channel mean below this (black subtracted) are near black, DN.
        #[arg(long, default_value_t = 100.0)]
        min_signal_dn: f64,
        /// Exposures with a channel mean above this fraction of valid_max - black are near
        /// saturation.
        #[arg(long, default_value_t = 0.9)]
        linear_max_fraction: f64,
        #[command(flatten)]
        common: Common,
    },
    /// Focal length, principal point, k1..k4 and orientation from point correspondences.
    Geometry {
        /// CSV: x_px,y_px and altitude_deg,azimuth_deg (or dx,dy,dz, world frame).
        correspondences: PathBuf,
        /// How many of k1..k4 to fit (the rest are held).
        #[arg(long, default_value_t = 4)]
        distortion_terms: usize,
        /// Hold the focal length.
        #[arg(long)]
        fix_focal: bool,
        /// Hold the principal point.
        #[arg(long)]
        fix_center: bool,
        /// Hold the orientation.
        #[arg(long)]
        fix_orientation: bool,
        #[command(flatten)]
        common: Common,
    },
}

fn start_device(path: Option<&Path>) -> anyhow::Result<DeviceConfig> {
    match path {
        None => Ok(DeviceConfig::default()),
        Some(p) => {
            let (device, warnings) = DeviceConfig::read(p)?;
            for w in warnings {
                eprintln!("warning: {w}");
            }
            Ok(device)
        }
    }
}

fn finish(out: &Path, step: &StepOutput) -> anyhow::Result<()> {
    let written =
        write_outputs(out, step).with_context(|| format!("writing into {}", out.display()))?;
    for p in written {
        println!("wrote {}", p.display());
    }
    Ok(())
}

pub fn run(args: &CalibrateArgs) -> anyhow::Result<()> {
    match &args.step {
        Step::Spectral {
            sensitivities,
            filters,
            data,
            common,
        } => {
            let device = start_device(common.device.as_deref())?;
            let data = data
                .clone()
                .or_else(data_dir_from_env)
                .unwrap_or_else(|| PathBuf::from("../shared/data"));
            let inputs = SpectralInputs {
                channels: load_rgb_sensitivities(sensitivities)?,
                channels_source: sensitivities.display().to_string(),
                photopic: load_photopic(&data)?,
                illuminant_a: illuminant_a(),
                d65: load_d65(&data)?,
            };
            let filters = match filters {
                Some(f) => read_filters(f)?,
                None => vec![],
            };
            let (report, out) = calibrate_spectral(&inputs, &filters, &device)?;
            println!(
                "f1' (A / D65): device weights {:.2} % / {:.2} %; fitted {:.2} % / {:.2} %; \
                 written ({}) {:.2} % / {:.2} %",
                100.0 * report.before.f1_prime_a,
                100.0 * report.before.f1_prime_d65,
                100.0 * report.fitted.f1_prime_a,
                100.0 * report.fitted.f1_prime_d65,
                report.after.label,
                100.0 * report.after.f1_prime_a,
                100.0 * report.after.f1_prime_d65
            );
            finish(&common.out, &report.output(out))
        }
        Step::Vignetting {
            capture_dir,
            order,
            smooth,
            max_off_axis_deg,
            common,
        } => {
            let device = start_device(common.device.as_deref())?;
            let options = VignettingOptions {
                order: *order,
                smoothing_half_width: *smooth,
                max_off_axis_deg: *max_off_axis_deg,
            };
            let (report, out) = calibrate_vignetting(capture_dir, &device, &options)?;
            println!(
                "vignetting a = {:?}: RMSE {:.3} % (R² {:.4}) smoothed, {:.3} % (R² {:.4}) per group",
                report.coefficients,
                100.0 * report.rmse_smoothed,
                report.r_squared_smoothed,
                100.0 * report.rmse_groups,
                report.r_squared_groups
            );
            finish(&common.out, &report.output(out))
        }
        Step::Response {
            sources,
            max_off_axis_deg,
            min_signal_dn,
            linear_max_fraction,
            common,
        } => {
            let device = start_device(common.device.as_deref())?;
            let options = ResponseOptions {
                max_off_axis_deg: *max_off_axis_deg,
                min_signal_dn: *min_signal_dn,
                linear_max_fraction: *linear_max_fraction,
            };
            let (report, out) = calibrate_response(sources, &device, &options)?;
            println!(
                "cg = {:.6e} from {} exposures: mean |relative error| {:.3} %, max {:.3} %",
                report.cg,
                report.used,
                100.0 * report.mean_abs_rel_error,
                100.0 * report.max_abs_rel_error
            );
            for c in &report.checks {
                println!(
                    "uniform-source check at {:.4e} cd/m2 ({} captures, {} readings): mean |error| \
                     {:.3} %, max {:.3} %: {}",
                    c.luminance_cd_m2,
                    c.frames,
                    c.readings,
                    100.0 * c.mean_abs_rel_error,
                    100.0 * c.max_abs_rel_error,
                    if c.passes { "pass" } else { "FAIL" }
                );
            }
            finish(&common.out, &report.output(out))
        }
        Step::Geometry {
            correspondences,
            distortion_terms,
            fix_focal,
            fix_center,
            fix_orientation,
            common,
        } => {
            let device = start_device(common.device.as_deref())?;
            let points = read_correspondences(correspondences)?;
            let options = GeometryOptions {
                fit_focal: !fix_focal,
                fit_center: !fix_center,
                fit_distortion_terms: *distortion_terms,
                fit_orientation: !fix_orientation,
            };
            let (report, out) = calibrate_geometry(
                &points,
                &device,
                &options,
                &correspondences.display().to_string(),
            )?;
            println!(
                "geometry from {} points: residual RMS {:.3} px ({:.4} deg), max {:.3} px ({:.4} deg)",
                report.points, report.rms_px, report.rms_deg, report.max_px, report.max_deg
            );
            finish(&common.out, &report.output(out))
        }
    }
}

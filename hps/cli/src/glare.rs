//! `skylux glare`: glare indices of a fisheye or perspective luminance picture, computed as
//! evalglare computes them (`skylux_hps::glare`).

use anyhow::Context;
use glam::DVec3;
use skylux_hps::glare::{self, DetectionSettings, GlareOptions, GlareReport, TaskArea};
use skylux_hps::picture::falsecolour::{self, ColourScale, FalsecolourOptions};
use skylux_hps::picture::Picture;
use std::path::PathBuf;

#[derive(clap::Args)]
#[command(after_help = "\
Computes what evalglare (J. Wienold) computes with its defaults: the vertical eye illuminance \
Ev over the view, the glare sources (pixels above the threshold, grouped within the search \
radius, larger sources absorbing smaller ones nearby, peaks above 50 000 cd/m² split off), \
their Guth position index, and DGP, DGI, UGR, CGI and VCP. The picture is a RADIANCE .hdr \
with its VIEW= line or an OpenEXR as `skylux render` writes it (Y channel, skylux.view); \
--view overrides or supplies the view (RADIANCE options, -vta/-vth/-vtv).")]
pub struct GlareArgs {
    /// The picture (.hdr, .pic or .exr).
    image: PathBuf,
    /// View options over the picture's own, e.g. "-vta -vh 180 -vv 180 -vd 0 1 0 -vu 0 0 1".
    #[arg(long, allow_hyphen_values = true)]
    view: Option<String>,
    /// Print the results as JSON.
    #[arg(long)]
    json: bool,
    /// Source threshold (evalglare -b): above 100 in cd/m², else a factor on the task's (or
    /// the view's) mean luminance. Default 2000 cd/m², or 5 with --task.
    #[arg(short = 'b', long = "threshold", allow_negative_numbers = true)]
    threshold: Option<f64>,
    /// Search radius in evalglare's measure (-r), rad.
    #[arg(
        short = 'r',
        long = "search-radius",
        default_value_t = 0.2,
        allow_negative_numbers = true
    )]
    search_radius: f64,
    /// Peak extraction limit (evalglare -Y), cd/m².
    #[arg(
        long = "peak-limit",
        default_value_t = 50_000.0,
        allow_negative_numbers = true
    )]
    peak_limit: f64,
    /// No peak extraction (evalglare -x).
    #[arg(long = "no-peaks")]
    no_peaks: bool,
    /// Apply DGP's low-light correction below 1000 lx (evalglare -C l+).
    #[arg(long = "low-light")]
    low_light: bool,
    /// Task area: column, row (from the top) and opening angle in rad (evalglare -t, whose
    /// rows count from the bottom).
    #[arg(long, num_args = 3, value_names = ["COLUMN", "ROW", "ANGLE"])]
    task: Option<Vec<f64>>,
    /// Report the luminance statistics of a horizontal band this many rad either side of the
    /// middle row (evalglare -B).
    #[arg(short = 'B', long = "band")]
    band: Option<f64>,
    /// Write a falsecolour PNG of the picture with the glare sources outlined.
    #[arg(long)]
    png: Option<PathBuf>,
}

pub fn run(args: &GlareArgs) -> anyhow::Result<()> {
    let image = glare::load_image(&args.image, args.view.as_deref())?;
    let options = GlareOptions {
        threshold: args.threshold,
        task: args.task.as_deref().map(task_area).transpose()?,
        detection: DetectionSettings {
            search_radius_rad: args.search_radius,
            peak_limit_cd_m2: (!args.no_peaks).then_some(args.peak_limit),
        },
        low_light_correction: args.low_light,
        band_half_width_rad: args.band,
    };
    let report = glare::evaluate(&image, &options)
        .with_context(|| format!("evaluating glare in {}", args.image.display()))?;
    if let Some(png) = &args.png {
        write_png(png, &image, &report)?;
    }
    if args.json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        print_text(&report);
    }
    Ok(())
}

fn task_area(values: &[f64]) -> anyhow::Result<TaskArea> {
    let [column, row, angle] = values else {
        anyhow::bail!("--task needs COLUMN ROW ANGLE");
    };
    let pixel = |v: f64, name: &str| -> anyhow::Result<u32> {
        anyhow::ensure!(
            v.is_finite() && v >= 0.0 && v.fract() == 0.0 && v <= f64::from(u32::MAX),
            "--task {name} must be a whole pixel number ≥ 0, not {v}"
        );
        Ok(v as u32)
    };
    Ok(TaskArea {
        column_px: pixel(*column, "COLUMN")?,
        row_px: pixel(*row, "ROW")?,
        opening_rad: *angle,
    })
}

fn print_text(r: &GlareReport) {
    let ugr = r
        .ugr
        .map_or("n/a (dark background)".to_string(), |u| format!("{u:.2}"));
    println!(
        "Ev {:.1} lx  (direct from sources {:.1} lx)",
        r.ev_lux, r.ev_direct_lux
    );
    println!(
        "DGP {:.4}  DGI {:.2}  UGR {ugr}  CGI {:.2}  VCP {:.1}",
        r.dgp, r.dgi, r.cgi, r.vcp
    );
    println!(
        "mean luminance {:.1} cd/m2, background {:.1} cd/m2, threshold {:.1} cd/m2",
        r.average_luminance_cd_m2, r.background_luminance_cd_m2, r.threshold_cd_m2
    );
    if let Some(b) = &r.band {
        println!(
            "band: {:.6} sr, mean {:.2}, median {:.2}, std {:.2}, p75 {:.2}, p95 {:.2}, min {:.2}, \
             max {:.2} cd/m2",
            b.solid_angle_sr,
            b.mean_luminance_cd_m2,
            b.median_luminance_cd_m2,
            b.std_luminance_cd_m2,
            b.percentile_75_cd_m2,
            b.percentile_95_cd_m2,
            b.min_luminance_cd_m2,
            b.max_luminance_cd_m2
        );
    }
    println!("{} glare source(s)", r.sources.len());
    println!("  #  column    row  pixels  L cd/m2  omega sr  P      direction");
    for (k, s) in r.sources.iter().enumerate() {
        let [dx, dy, dz] = s.direction;
        println!(
            "{:3} {:7.1} {:6.1} {:7} {:8.1} {:9.6} {:5.2}  {dx:.3} {dy:.3} {dz:.3}",
            k + 1,
            s.column_px,
            s.row_px,
            s.pixels,
            s.mean_luminance_cd_m2,
            s.solid_angle_sr,
            s.position_index
        );
    }
}

/// Falsecolour of the luminance on a 4-decade log scale with each source's edge drawn.
fn write_png(
    path: &std::path::Path,
    image: &glare::LuminanceImage,
    r: &GlareReport,
) -> anyhow::Result<()> {
    let (w, h) = (image.width_px as usize, image.height_px as usize);
    let picture = Picture {
        width_px: image.width_px,
        height_px: image.height_px,
        view: image.view.to_radiance_string(),
        radiance_rgb: vec![DVec3::ZERO; w * h],
        luminance_cd_m2: image.luminance_cd_m2.clone(),
        luminance_stderr_cd_m2: vec![0.0; w * h],
        samples_per_pixel: 1,
    };
    let marks = glare::outline::source_outlines(&r.source_of_pixel, w, h);
    let peak = image.luminance_cd_m2.iter().copied().fold(0.0, f64::max);
    falsecolour::write_falsecolour_png_marked(
        path,
        &picture,
        &FalsecolourOptions {
            scale: ColourScale::Log { decades: 4.0 },
            maximum: (peak > 0.0).then_some(peak),
            ..FalsecolourOptions::default()
        },
        &marks,
    )?;
    Ok(())
}

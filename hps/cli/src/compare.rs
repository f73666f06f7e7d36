//! `skylux compare`: a measured luminance picture against a rendered one of the same view
//! (`skylux_hps::compare`).

use skylux_hps::compare::{self, CompareOptions, Comparison, ErrorSummary, Regions};
use std::path::PathBuf;

#[derive(clap::Args)]
#[command(after_help = "\
RENDERED is resampled onto MEASURED's pixel grid through both pictures' views (each measured \
pixel's direction is located in the rendered view and read bilinearly), so the two may differ \
in resolution, type (-vta/-vth/-vtv) and direction, but not in eye point. The relative error \
is (R - M)/M; pixels outside either view or with M below --min-luminance are left out and \
counted. Regions: a .json list [{\"name\": \"window\", \"polygon\": [[x, y], ...]}] in pixel \
coordinates of MEASURED (x from the left, y from the top), or a RADIANCE mask picture of \
MEASURED's size whose red value is the region id (0: none).")]
pub struct CompareArgs {
    /// The measured picture (.hdr, .pic or .exr).
    measured: PathBuf,
    /// The rendered picture (.hdr, .pic or .exr).
    rendered: PathBuf,
    /// Regions compared on their own: polygons (.json) or a mask picture.
    #[arg(long)]
    regions: Option<PathBuf>,
    /// Print the results as JSON.
    #[arg(long)]
    json: bool,
    /// Write a falsecolour PNG of the signed relative error (grey: left out).
    #[arg(long)]
    png: Option<PathBuf>,
    /// Measured pixels darker than this are left out, cd/m².
    #[arg(
        long = "min-luminance",
        default_value_t = 0.01,
        allow_negative_numbers = true
    )]
    min_luminance: f64,
    /// View options over the measured picture's own (RADIANCE syntax).
    #[arg(long = "measured-view", allow_hyphen_values = true)]
    measured_view: Option<String>,
    /// View options over the rendered picture's own (RADIANCE syntax).
    #[arg(long = "rendered-view", allow_hyphen_values = true)]
    rendered_view: Option<String>,
}

pub fn run(args: &CompareArgs) -> anyhow::Result<()> {
    let measured = compare::load_picture(&args.measured, args.measured_view.as_deref())?;
    let rendered = compare::load_picture(&args.rendered, args.rendered_view.as_deref())?;
    let regions = match &args.regions {
        Some(path) => compare::read_regions(path, measured.width_px, measured.height_px)?,
        None => Regions::default(),
    };
    let options = CompareOptions {
        min_luminance_cd_m2: args.min_luminance,
    };
    let comparison = compare::compare(&measured, &rendered, &regions, &options)?;
    if let Some(png) = &args.png {
        compare::difference_png::write_difference_png(png, &comparison, None)?;
    }
    if args.json {
        println!("{}", serde_json::to_string_pretty(&comparison)?);
    } else {
        print_text(&comparison);
    }
    Ok(())
}

fn print_text(c: &Comparison) {
    println!(
        "{} × {} pixels: {} compared, {} outside a view, {} below {} cd/m2",
        c.width_px,
        c.height_px,
        c.pixels - c.excluded_outside_view - c.excluded_below_floor,
        c.excluded_outside_view,
        c.excluded_below_floor,
        c.min_luminance_cd_m2
    );
    println!(
        "{:<20} {:>8} {:>9} {:>9} {:>9} {:>10} {:>9}",
        "region", "pixels", "mean|e|", "median|e|", "p90|e|", "mean e", "rms e"
    );
    print_row("all", c.summary.as_ref());
    for r in &c.regions {
        print_row(&r.name, r.summary.as_ref());
    }
}

fn print_row(name: &str, s: Option<&ErrorSummary>) {
    match s {
        Some(s) => println!(
            "{name:<20} {:>8} {:>9.4} {:>9.4} {:>9.4} {:>+10.4} {:>9.4}",
            s.count, s.mean_abs, s.median_abs, s.p90_abs, s.mean_signed, s.rms
        ),
        None => println!("{name:<20} {:>8} (no pixel compared)", 0),
    }
}

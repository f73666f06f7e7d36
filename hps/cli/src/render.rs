//! `skylux render`: an image of a RADIANCE scene from a view, by path tracing
//! (`skylux_hps::engine::render`), written as OpenEXR, RADIANCE `.hdr` and a falsecolour PNG.

use anyhow::Context;
use skylux_hps::engine::render::{self, RenderSettings, View};
use skylux_hps::engine::{Settings, World};
use skylux_hps::picture::falsecolour::{self, ColourScale, FalsecolourOptions, LegendUnit};
use skylux_hps::picture::{exr, rgbe};
use skylux_hps::scene;
use std::path::PathBuf;

#[derive(clap::Args)]
#[command(after_help = "\
Views have RADIANCE's meaning (rpict's -vt{v,h,a} -vp -vd -vu -vh -vv -vs -vl -vo): the view \
file is read first, then --view's options override it. The resolution is reduced to the view's \
aspect with square pixels, as rpict does (-pa 1). Each pixel is the mean of --spp paths through \
jittered positions, each what rtrace (without -I) gives for that ray. Output: PREFIX.exr \
(float R, G, B radiance in W/sr/m² and Y luminance in cd/m²), PREFIX.hdr (RADIANCE picture with \
the VIEW= line) and PREFIX.png (falsecolour of luminance in cd/m², or with --lux of π × luminance, \
the illuminance on a white Lambertian diffuser of that luminance, in lux).")]
pub struct RenderArgs {
    /// RADIANCE scene file; repeat for several (room, then sky), read in order as oconv would.
    #[arg(long = "scene", required = true)]
    scenes: Vec<PathBuf>,
    /// Run inline commands Skylux does not implement (`!cmd` lines other than xform and the
    /// gen* generators) through /bin/sh, as oconv would. A scene file can then run any
    /// program with your rights: use only on files you trust.
    #[arg(long)]
    allow_commands: bool,
    /// View options, rpict style, e.g. "-vtv -vp 1.4 5 1.2 -vd 0 -1 0 -vh 60 -vv 45".
    #[arg(long, allow_hyphen_values = true)]
    view: Option<String>,
    /// RADIANCE view file (rvu/rpict view lines or a picture header's VIEW= line).
    #[arg(long)]
    view_file: Option<PathBuf>,
    /// Largest image width in pixels (rpict -x).
    #[arg(short = 'x', default_value_t = 512)]
    width: u32,
    /// Largest image height in pixels (rpict -y).
    #[arg(short = 'y', default_value_t = 512)]
    height: u32,
    /// Most diffuse bounces per path (rtrace -ab).
    #[arg(long, default_value_t = 5)]
    ab: u32,
    /// Paths per pixel, at least 1.
    #[arg(long, default_value_t = 16)]
    spp: u32,
    /// Leave every pixel its own mean of --spp paths. By default the light that varies slowly
    /// along a surface (sky and interreflections on Lambertian surfaces) is averaged over
    /// neighbouring pixels on the same surface by an edge-aware filter, which removes most
    /// of the grain; the sun's direct light, reflectances and glossy surfaces stay as traced.
    #[arg(long)]
    unfiltered: bool,
    /// Seed of the random streams; a seed gives the same image on any number of threads.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Label the falsecolour legend in lux (π × luminance) instead of cd/m².
    #[arg(long)]
    lux: bool,
    /// Logarithmic falsecolour scale over this many decades below the maximum.
    #[arg(long)]
    log: Option<f64>,
    /// Top of the falsecolour scale (cd/m², or lux with --lux); default: 1, 2 or 5 × 10^k at
    /// or above the 99th percentile.
    #[arg(long)]
    scale: Option<f64>,
    /// Output prefix: writes PREFIX.exr, PREFIX.hdr and PREFIX.png.
    #[arg(long)]
    out: PathBuf,
}

pub fn run(args: &RenderArgs) -> anyhow::Result<()> {
    let mut view = View::default();
    if args.view.is_none() && args.view_file.is_none() {
        anyhow::bail!("give a view: --view \"-vtv -vp X Y Z -vd DX DY DZ ...\" or --view-file F");
    }
    if let Some(path) = &args.view_file {
        view = view.with_file(path)?;
    }
    if let Some(text) = &args.view {
        view = view.with_options(text)?;
    }
    let prepared = view.prepare()?;
    let (width_px, height_px) = prepared.fit_resolution(args.width, args.height);
    let settings = RenderSettings {
        width_px,
        height_px,
        samples_per_pixel: args.spp,
        trace: Settings {
            ambient_bounces: args.ab,
            seed: args.seed,
            ..Settings::default()
        },
        filtered: !args.unfiltered,
    };
    settings.validate()?;
    if let Some(d) = args.log {
        if !(d > 0.0 && d.is_finite()) {
            anyhow::bail!("--log {d}: the number of decades must be > 0");
        }
    }
    if let Some(s) = args.scale {
        if !(s > 0.0 && s.is_finite()) {
            anyhow::bail!("--scale {s}: the scale maximum must be > 0");
        }
    }
    let scene = scene::load_files_with(
        &args.scenes,
        &scene::LoadOptions {
            allow_commands: args.allow_commands,
            ..Default::default()
        },
    )?;
    let world = World::new(&scene)?;

    let bar = indicatif::ProgressBar::new(u64::from(height_px));
    bar.set_style(
        indicatif::ProgressStyle::with_template("  render [{bar:30}] {pos}/{len} rows {eta}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    let start = std::time::Instant::now();
    let image = render::render(&world, &prepared, &settings, &|done, _| {
        bar.set_position(done)
    })?;
    bar.finish_and_clear();
    let seconds = start.elapsed().as_secs_f64();

    let with_ext = |ext: &str| {
        let mut s = args.out.clone().into_os_string();
        s.push(ext);
        PathBuf::from(s)
    };
    if let Some(parent) = args.out.parent().filter(|p| !p.as_os_str().is_empty()) {
        std::fs::create_dir_all(parent)
            .with_context(|| format!("creating {}", parent.display()))?;
    }
    let (exr_path, hdr_path, png) = (with_ext(".exr"), with_ext(".hdr"), with_ext(".png"));
    exr::write_exr(&exr_path, &image)?;
    rgbe::write_hdr(&hdr_path, &image, None)?;
    let outcome = falsecolour::write_falsecolour_png(
        &png,
        &image,
        &FalsecolourOptions {
            unit: if args.lux {
                LegendUnit::Lux
            } else {
                LegendUnit::Luminance
            },
            scale: match args.log {
                Some(decades) => ColourScale::Log { decades },
                None => ColourScale::Linear,
            },
            maximum: args.scale,
            minimum: None,
            divisions: 8,
        },
    )?;
    let n = image.luminance_cd_m2.len().max(1) as f64;
    let mean = image.luminance_cd_m2.iter().sum::<f64>() / n;
    println!(
        "{width_px}x{height_px} pixels, {} paths/pixel, -ab {} in {seconds:.1} s; mean luminance \
         {mean:.2} cd/m²",
        args.spp, args.ab
    );
    println!(
        "wrote {}, {}, {} (scale 0..{} {}{})",
        exr_path.display(),
        hdr_path.display(),
        png.display(),
        outcome.maximum,
        if args.lux { "lux" } else { "cd/m²" },
        if outcome.text {
            ""
        } else {
            "; no system font found, legend without numbers"
        }
    );
    Ok(())
}

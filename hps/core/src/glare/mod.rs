//! Glare from a luminance picture (`skylux glare`, issue 21 item 1), computed as evalglare
//! (J. Wienold, RADIANCE `src/util/evalglare.c`, version 3.06) computes it with its defaults:
//! the vertical eye illuminance Ev, the glare sources ([`detection`]) with their position
//! indices ([`position_index`]), and DGP, DGI, UGR, CGI and VCP ([`metrics`]).
//!
//! Deviations from evalglare, all invisible on square pictures with a centred view: pixel
//! solid angles are taken at the pixel itself (evalglare mirrors the row for `-vs`/`-vl`
//! shifted views), and peak grouping searches the picture's full width (evalglare stops at
//! its height).

pub mod band;
pub mod detection;
pub mod error;
pub mod ev_noise;
pub mod image;
pub mod metrics;
pub mod neighbourhood;
pub mod outline;
pub mod pixels;
pub mod position_index;
pub mod sources;

pub use detection::DetectionSettings;
pub use error::GlareError;
pub use ev_noise::ev_stderr_lux;
pub use image::{load_image, LuminanceImage};

use glam::DVec3;
use metrics::SourceTerms;
use pixels::PixelGrid;

/// A task area (evalglare's `-t x y angle`): the threshold becomes a multiple of its mean
/// luminance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TaskArea {
    /// Pixel at its centre, column from the left and row from the top.
    pub column_px: u32,
    pub row_px: u32,
    /// Opening angle, rad (evalglare's measure: twice the angle to the centre).
    pub opening_rad: f64,
}

/// What to evaluate and how (evalglare's options; the default is evalglare's).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GlareOptions {
    /// evalglare's `-b`: above 100 a luminance threshold in cd/m², else a factor on the task's
    /// (or without one the field of view's) mean luminance. None: 2000 cd/m², or 5 × the task
    /// luminance when a task is given.
    pub threshold: Option<f64>,
    pub task: Option<TaskArea>,
    pub detection: DetectionSettings,
    /// DGP's low-light correction below 1000 lx (evalglare `-C l+`; off by default since
    /// evalglare 2.x).
    pub low_light_correction: bool,
    /// Half width, rad, of a horizontal band whose luminance statistics to report
    /// (evalglare's `-B`); None for none.
    pub band_half_width_rad: Option<f64>,
}

/// One glare source.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct GlareSource {
    /// Luminance-weighted centre, pixels: column from the left and row from the top (pixel
    /// centres at whole numbers).
    pub column_px: f64,
    pub row_px: f64,
    pub pixels: u64,
    /// Unit direction of the centre's pixel (x, y, z of the scene).
    pub direction: [f64; 3],
    pub solid_angle_sr: f64,
    pub mean_luminance_cd_m2: f64,
    pub max_luminance_cd_m2: f64,
    pub position_index: f64,
    /// The source's part of the vertical eye illuminance, lux.
    pub direct_illuminance_lux: f64,
}

/// The glare evaluation of one picture.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct GlareReport {
    pub ev_lux: f64,
    pub dgp: f64,
    pub dgi: f64,
    /// None when the background is dark.
    pub ugr: Option<f64>,
    pub cgi: f64,
    pub vcp: f64,
    pub dgr: f64,
    /// The low-light factor applied to DGP (1 when the correction is off or Ev ≥ 1000 lx).
    pub low_light_factor: f64,
    /// Direct part of Ev from the sources, lux.
    pub ev_direct_lux: f64,
    pub background_luminance_cd_m2: f64,
    /// Mean luminance of the field of view, weighted by solid angle.
    pub average_luminance_cd_m2: f64,
    /// The task's (or field's) mean luminance the threshold factor applies to.
    pub task_luminance_cd_m2: f64,
    pub threshold_cd_m2: f64,
    pub solid_angle_sr: f64,
    pub sources: Vec<GlareSource>,
    /// The band's luminance statistics, when asked for.
    pub band: Option<band::BandStatistics>,
    /// Source number (1 = first of `sources`) of each pixel, 0 for none; rows from the top.
    #[serde(skip)]
    pub source_of_pixel: Vec<u32>,
}

/// Most pixels evaluated: 2^22 (2048 × 2048). A pixel costs about 100 bytes here, so this
/// fits a 32-bit process; glare pictures are rarely over 1500 pixels a side.
pub const MAX_PIXELS: u64 = 1 << 22;

/// Sums over the valid pixels of the field of view.
struct Field {
    ev_lux: f64,
    solid_angle_sr: f64,
    average_luminance_cd_m2: f64,
}

/// Evaluates glare on `image`.
pub fn evaluate(image: &LuminanceImage, options: &GlareOptions) -> Result<GlareReport, GlareError> {
    check_options(options)?;
    if u64::from(image.width_px) * u64::from(image.height_px) > MAX_PIXELS {
        return Err(GlareError::Picture(format!(
            "{} × {} pixels is more than the {MAX_PIXELS} glare evaluation takes; reduce the \
             picture (e.g. pfilt -x /2 -y /2)",
            image.width_px, image.height_px
        )));
    }
    image::check_values(image)?;
    let view = image
        .view
        .prepare()
        .map_err(|e| GlareError::Picture(e.to_string()))?;
    image::check_projection(image, &view)?;
    let (w, h) = (image.width_px as usize, image.height_px as usize);
    let grid = PixelGrid::new(&view, w, h);
    let luminance = grid_luminance(&grid, image);
    let field = field_sums(&grid, &luminance);
    let task_luminance = match options.task {
        Some(task) => task_luminance(&grid, &luminance, task)?,
        None => field.average_luminance_cd_m2,
    };
    let factor = options
        .threshold
        .unwrap_or(if options.task.is_some() { 5.0 } else { 2000.0 });
    let threshold_cd_m2 = if factor > 100.0 {
        factor
    } else {
        factor * task_luminance
    };
    let found = detection::detect(&grid, &luminance, threshold_cd_m2, &options.detection);
    let (sources, source_of_pixel) = summarise_sources(&grid, &luminance, &found);
    let mut report = report(
        field,
        task_luminance,
        threshold_cd_m2,
        sources,
        source_of_pixel,
        options,
    );
    report.band = options
        .band_half_width_rad
        .and_then(|half_width| band::band_statistics(&grid, &luminance, half_width));
    Ok(report)
}

fn check_options(options: &GlareOptions) -> Result<(), GlareError> {
    let positive = |name: &str, v: f64| {
        if v.is_finite() && v > 0.0 {
            Ok(())
        } else {
            Err(GlareError::Setting(format!(
                "{name} must be a positive number, not {v}"
            )))
        }
    };
    if let Some(b) = options.threshold {
        positive("the threshold (-b)", b)?;
    }
    positive(
        "the search radius (-r)",
        options.detection.search_radius_rad,
    )?;
    if let Some(limit) = options.detection.peak_limit_cd_m2 {
        positive("the peak extraction limit (-Y)", limit)?;
    }
    if let Some(task) = options.task {
        positive("the task opening angle", task.opening_rad)?;
    }
    if let Some(half_width) = options.band_half_width_rad {
        positive("the band half width (-B)", half_width)?;
    }
    Ok(())
}

/// Luminance per grid pixel (y from the bottom), 0 where the pixel does not count (as
/// evalglare blackens them).
fn grid_luminance(grid: &PixelGrid, image: &LuminanceImage) -> Vec<f64> {
    let (w, h) = (grid.width_px, grid.height_px);
    let mut out = vec![0.0; w * h];
    for y in 0..h {
        for x in 0..w {
            let i = grid.index(x, y);
            if grid.is_valid(i) {
                out[i] = image.luminance_cd_m2[(h - 1 - y) * w + x];
            }
        }
    }
    out
}

/// Ev = Σ L ω cos θ and the mean luminance over the valid pixels.
fn field_sums(grid: &PixelGrid, luminance: &[f64]) -> Field {
    let (mut ev, mut omega, mut weighted) = (0.0, 0.0, 0.0);
    for (i, &l) in luminance.iter().enumerate() {
        if grid.is_valid(i) {
            let o = grid.solid_angle_sr[i];
            ev += grid.direction[i].dot(grid.view_direction) * o * l;
            omega += o;
            weighted += o * l;
        }
    }
    Field {
        ev_lux: ev,
        solid_angle_sr: omega,
        average_luminance_cd_m2: if omega > 0.0 { weighted / omega } else { 0.0 },
    }
}

/// Mean luminance, weighted by solid angle, of the pixels within the task's opening.
fn task_luminance(grid: &PixelGrid, luminance: &[f64], task: TaskArea) -> Result<f64, GlareError> {
    let (w, h) = (grid.width_px, grid.height_px);
    if task.column_px as usize >= w || task.row_px as usize >= h {
        return Err(GlareError::Setting(format!(
            "task position ({}, {}) is outside the {w} × {h} picture",
            task.column_px, task.row_px
        )));
    }
    let centre = grid.index(task.column_px as usize, h - 1 - task.row_px as usize);
    let (mut sum, mut omega) = (0.0, 0.0);
    for (i, l) in luminance.iter().enumerate() {
        if grid.doubled_angle_rad(centre, i) <= task.opening_rad {
            sum += grid.solid_angle_sr[i] * l;
            omega += grid.solid_angle_sr[i];
        }
    }
    if omega > 0.0 {
        Ok(sum / omega)
    } else {
        Err(GlareError::Setting(
            "the task area holds no pixel of the view".into(),
        ))
    }
}

/// The sources with pixels, numbered from 1 in label order, and each pixel's number.
fn summarise_sources(
    grid: &PixelGrid,
    luminance: &[f64],
    found: &detection::Detection,
) -> (Vec<GlareSource>, Vec<u32>) {
    let mut number = vec![0u32; found.sources.len()];
    let mut direct = vec![0.0; found.sources.len()];
    for (i, &label) in found.labels.iter().enumerate() {
        if label > 0 {
            let d = grid.direction[i].dot(grid.view_direction);
            direct[label as usize] += d * grid.solid_angle_sr[i] * luminance[i];
        }
    }
    let mut sources = Vec::new();
    for (label, sums) in found.sources.iter().enumerate().skip(1) {
        if sums.is_empty() {
            continue;
        }
        // evalglare evaluates a source's direction at the pixel its centre falls in.
        let (x, y) = (sums.mean_x_px as usize, sums.mean_y_px as usize);
        let at = grid.index(x.min(grid.width_px - 1), y.min(grid.height_px - 1));
        let direction: DVec3 = grid.direction[at];
        sources.push(GlareSource {
            column_px: sums.mean_x_px,
            row_px: grid.row_from_top(sums.mean_y_px),
            pixels: sums.pixels as u64,
            direction: direction.to_array(),
            solid_angle_sr: sums.solid_angle_sr,
            mean_luminance_cd_m2: sums.mean_luminance_cd_m2,
            max_luminance_cd_m2: sums.max_luminance_cd_m2,
            position_index: position_index::position_index(
                direction,
                grid.view_direction,
                grid.view_up,
            ),
            direct_illuminance_lux: direct[label],
        });
        number[label] = sources.len() as u32;
    }
    let (w, h) = (grid.width_px, grid.height_px);
    let mut per_pixel = vec![0u32; w * h];
    for y in 0..h {
        for x in 0..w {
            per_pixel[(h - 1 - y) * w + x] = number[found.labels[grid.index(x, y)] as usize];
        }
    }
    (sources, per_pixel)
}

/// The indices from the field and the sources.
fn report(
    field: Field,
    task_luminance_cd_m2: f64,
    threshold_cd_m2: f64,
    sources: Vec<GlareSource>,
    source_of_pixel: Vec<u32>,
    options: &GlareOptions,
) -> GlareReport {
    let terms: Vec<SourceTerms> = sources
        .iter()
        .map(|s| SourceTerms {
            luminance_cd_m2: s.mean_luminance_cd_m2,
            solid_angle_sr: s.solid_angle_sr,
            position_index: s.position_index,
        })
        .collect();
    let ev = field.ev_lux;
    let ev_direct: f64 = sources.iter().map(|s| s.direct_illuminance_lux).sum();
    let background = metrics::background_luminance_cd_m2(ev, ev_direct);
    let low_light_factor = if options.low_light_correction {
        metrics::low_light_factor(ev)
    } else {
        1.0
    };
    let none = terms.is_empty();
    let dgr = if none {
        0.0
    } else {
        metrics::dgr(field.average_luminance_cd_m2, &terms)
    };
    GlareReport {
        ev_lux: ev,
        dgp: metrics::dgp(ev, &terms) * low_light_factor,
        dgi: if none {
            0.0
        } else {
            metrics::dgi(background, &terms)
        },
        ugr: if none {
            Some(0.0)
        } else {
            metrics::ugr(background, &terms)
        },
        cgi: if none {
            0.0
        } else {
            metrics::cgi(ev, ev_direct, &terms)
        },
        vcp: if none { 100.0 } else { metrics::vcp(dgr) },
        dgr,
        low_light_factor,
        ev_direct_lux: ev_direct,
        background_luminance_cd_m2: background,
        average_luminance_cd_m2: field.average_luminance_cd_m2,
        task_luminance_cd_m2,
        threshold_cd_m2,
        solid_angle_sr: field.solid_angle_sr,
        sources,
        band: None,
        source_of_pixel,
    }
}

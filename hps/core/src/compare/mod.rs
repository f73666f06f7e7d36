//! A measured luminance picture against a rendered one of the same view (`skylux compare`):
//! RENDERED is resampled onto MEASURED's pixel grid through both views, each pixel's
//! relative error (R − M)/M is computed where M is at or above a floor, and the errors are
//! summarised over the picture and per region, with both pictures' luminance histograms.

pub mod difference_png;
pub mod error;
pub mod regions;
pub mod resample;
pub mod statistics;

pub use error::CompareError;
pub use regions::{read_regions, Regions};
pub use statistics::{ErrorSummary, LuminanceHistogram};

use crate::glare::{self, LuminanceImage};
use serde::Serialize;
use std::path::Path;

/// Settings of a comparison.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompareOptions {
    /// Measured pixels below this luminance are left out (the relative error divides by it),
    /// cd/m².
    pub min_luminance_cd_m2: f64,
}

impl Default for CompareOptions {
    fn default() -> Self {
        Self {
            min_luminance_cd_m2: 0.01,
        }
    }
}

/// What the comparison found.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Comparison {
    pub width_px: u32,
    pub height_px: u32,
    /// Measured pixels in all.
    pub pixels: usize,
    /// Left out: no ray in the measured view, or outside the rendered picture.
    pub excluded_outside_view: usize,
    /// Left out: measured luminance below the floor.
    pub excluded_below_floor: usize,
    pub min_luminance_cd_m2: f64,
    /// Over every compared pixel; None when none is compared.
    pub summary: Option<ErrorSummary>,
    pub regions: Vec<RegionSummary>,
    pub histogram: Option<LuminanceHistogram>,
    /// (R − M)/M per measured pixel, rows from the top; None where left out.
    #[serde(skip)]
    pub relative_error: Vec<Option<f64>>,
    /// The rendered luminance on the measured grid, cd/m².
    #[serde(skip)]
    pub rendered_on_measured_cd_m2: Vec<Option<f64>>,
}

/// One region's errors.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RegionSummary {
    pub id: u32,
    pub name: String,
    /// Pixels of the region, compared or not.
    pub pixels: usize,
    pub summary: Option<ErrorSummary>,
}

/// Reads a picture for comparison (`.hdr`/`.pic`/`.exr`, its view or `view_override`) and
/// checks its values (finite, ≥ 0).
pub fn load_picture(
    path: &Path,
    view_override: Option<&str>,
) -> Result<LuminanceImage, CompareError> {
    let wrap = |source| CompareError::Picture {
        path: path.into(),
        source,
    };
    let image = glare::load_image(path, view_override).map_err(wrap)?;
    glare::image::check_values(&image).map_err(wrap)?;
    Ok(image)
}

/// Compares RENDERED with MEASURED on MEASURED's pixel grid; `regions` (ids per measured
/// pixel) may be empty.
pub fn compare(
    measured: &LuminanceImage,
    rendered: &LuminanceImage,
    regions: &Regions,
    options: &CompareOptions,
) -> Result<Comparison, CompareError> {
    check_options(options)?;
    let pixels = measured.luminance_cd_m2.len();
    if !regions.id_of_pixel.is_empty() && regions.id_of_pixel.len() != pixels {
        return Err(CompareError::Setting(format!(
            "{} region ids for {pixels} measured pixels",
            regions.id_of_pixel.len()
        )));
    }
    let prepare = |image: &LuminanceImage, which: &str| {
        image
            .view
            .prepare()
            .map_err(|e| CompareError::Views(format!("the {which} view: {e}")))
    };
    let (measured_view, rendered_view) = (
        prepare(measured, "measured")?,
        prepare(rendered, "rendered")?,
    );
    let resampled = resample::resample_onto(measured, &measured_view, rendered, &rendered_view)?;
    let (mut outside, mut below) = (0, 0);
    let relative_error: Vec<Option<f64>> = resampled
        .iter()
        .zip(&measured.luminance_cd_m2)
        .map(|(r, &m)| match r {
            None => {
                outside += 1;
                None
            }
            Some(_) if m < options.min_luminance_cd_m2 || m <= 0.0 => {
                below += 1;
                None
            }
            Some(r) => Some((r - m) / m),
        })
        .collect();
    if outside == pixels {
        return Err(CompareError::Views(format!(
            "no measured pixel's direction falls inside the rendered view (`{}` against `{}`): \
             the pictures do not show the same view",
            measured.view.to_radiance_string(),
            rendered.view.to_radiance_string()
        )));
    }
    let errors: Vec<f64> = relative_error.iter().flatten().copied().collect();
    let pairs: Vec<(f64, f64)> = resampled
        .iter()
        .zip(&measured.luminance_cd_m2)
        .zip(&relative_error)
        .filter(|(_, e)| e.is_some())
        .filter_map(|((r, &m), _)| r.map(|r| (m, r)))
        .collect();
    Ok(Comparison {
        width_px: measured.width_px,
        height_px: measured.height_px,
        pixels,
        excluded_outside_view: outside,
        excluded_below_floor: below,
        min_luminance_cd_m2: options.min_luminance_cd_m2,
        summary: ErrorSummary::of(&errors),
        regions: region_summaries(regions, &relative_error),
        histogram: LuminanceHistogram::of(&pairs),
        relative_error,
        rendered_on_measured_cd_m2: resampled,
    })
}

fn check_options(options: &CompareOptions) -> Result<(), CompareError> {
    let floor = options.min_luminance_cd_m2;
    if !(floor.is_finite() && floor >= 0.0) {
        return Err(CompareError::Setting(format!(
            "the luminance floor must be a finite number ≥ 0 cd/m², not {floor}"
        )));
    }
    Ok(())
}

/// Each region's summary, in id order.
fn region_summaries(regions: &Regions, relative_error: &[Option<f64>]) -> Vec<RegionSummary> {
    regions
        .names
        .iter()
        .map(|(&id, name)| {
            let members = regions
                .id_of_pixel
                .iter()
                .zip(relative_error)
                .filter(|(&r, _)| r == id);
            let pixels = members.clone().count();
            let errors: Vec<f64> = members.filter_map(|(_, e)| *e).collect();
            RegionSummary {
                id,
                name: name.clone(),
                pixels,
                summary: ErrorSummary::of(&errors),
            }
        })
        .collect()
}

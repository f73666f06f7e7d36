//! A falsecolour PNG of the signed relative error (R − M)/M, symmetric about 0, with the
//! pixels left out in grey.

use super::Comparison;
use crate::picture::falsecolour::{self, FalsecolourOptions, FalsecolourOutcome, LegendUnit};
use crate::picture::{OutputError, Picture};
use glam::DVec3;
use std::path::Path;

/// Colour of the pixels that were not compared.
const LEFT_OUT_RGB: [u8; 3] = [128, 128, 128];

/// Writes the error map: the scale runs from −`span` to +`span` (None: the comparison's
/// 90th percentile of |error|, at least 0.001).
pub fn write_difference_png(
    path: &Path,
    comparison: &Comparison,
    span: Option<f64>,
) -> Result<FalsecolourOutcome, OutputError> {
    let n = comparison.relative_error.len();
    let span = span.unwrap_or_else(|| {
        comparison
            .summary
            .as_ref()
            .map_or(1.0, |s| s.p90_abs)
            .max(1e-3)
    });
    let picture = Picture {
        width_px: comparison.width_px,
        height_px: comparison.height_px,
        view: String::new(),
        radiance_rgb: vec![DVec3::ZERO; n],
        luminance_cd_m2: comparison
            .relative_error
            .iter()
            .map(|e| e.unwrap_or(0.0))
            .collect(),
        luminance_stderr_cd_m2: vec![0.0; n],
        samples_per_pixel: 1,
    };
    let marks: Vec<Option<[u8; 3]>> = comparison
        .relative_error
        .iter()
        .map(|e| e.is_none().then_some(LEFT_OUT_RGB))
        .collect();
    falsecolour::write_falsecolour_png_marked(
        path,
        &picture,
        &FalsecolourOptions {
            unit: LegendUnit::RelativeError,
            minimum: Some(-span),
            maximum: Some(span),
            ..FalsecolourOptions::default()
        },
        &marks,
    )
}

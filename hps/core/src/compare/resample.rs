//! RENDERED onto MEASURED's pixel grid: each measured pixel's direction (through its view) is
//! located in the rendered view and the rendered luminance read there, bilinearly between
//! the four nearest pixel centres.

use super::error::CompareError;
use crate::engine::render::PreparedView;
use crate::glare::LuminanceImage;

/// How far apart the two eye points may be, m: the pictures are mapped by direction only,
/// which holds for one eye point.
const SAME_POINT_M: f64 = 0.01;

/// The rendered luminance at each measured pixel; None where the measured pixel has no ray
/// or its direction falls outside the rendered picture (or its fisheye circle).
pub fn resample_onto(
    measured: &LuminanceImage,
    measured_view: &PreparedView,
    rendered: &LuminanceImage,
    rendered_view: &PreparedView,
) -> Result<Vec<Option<f64>>, CompareError> {
    check_same_point(measured, rendered)?;
    let (w, h) = (measured.width_px, measured.height_px);
    let inside = rendered_pixels_with_rays(rendered, rendered_view);
    let mut out = Vec::with_capacity(w as usize * h as usize);
    for row in 0..h {
        for column in 0..w {
            let value = measured_view
                .pixel_centre_ray(column, row, w, h)
                .and_then(|ray| rendered_view.locate(ray.direction))
                .and_then(|(x, y)| bilinear(rendered, &inside, x, y));
            out.push(value);
        }
    }
    Ok(out)
}

fn check_same_point(
    measured: &LuminanceImage,
    rendered: &LuminanceImage,
) -> Result<(), CompareError> {
    let gap_m = measured.view.position_m.distance(rendered.view.position_m);
    if gap_m.is_nan() || gap_m > SAME_POINT_M {
        return Err(CompareError::Views(format!(
            "the two views are taken from points {gap_m:.3} m apart ({} and {}): pictures from \
             different eye points cannot be mapped pixel to pixel; give both the same -vp",
            fmt_point(measured.view.position_m),
            fmt_point(rendered.view.position_m)
        )));
    }
    Ok(())
}

fn fmt_point(p: glam::DVec3) -> String {
    format!("{:.3} {:.3} {:.3}", p.x, p.y, p.z)
}

/// Whether each rendered pixel has a ray (false beyond a fisheye's circle).
fn rendered_pixels_with_rays(rendered: &LuminanceImage, view: &PreparedView) -> Vec<bool> {
    let (w, h) = (rendered.width_px, rendered.height_px);
    (0..h)
        .flat_map(|row| (0..w).map(move |column| (column, row)))
        .map(|(column, row)| view.pixel_centre_ray(column, row, w, h).is_some())
        .collect()
}

/// Bilinear value at image position (x, y) (0..1, y from the bottom); None outside the
/// picture or when a pixel it draws on has no ray. Half a pixel at the border is read from
/// the border pixels.
fn bilinear(image: &LuminanceImage, inside: &[bool], x: f64, y: f64) -> Option<f64> {
    if !((0.0..=1.0).contains(&x) && (0.0..=1.0).contains(&y)) {
        return None;
    }
    let (w, h) = (image.width_px as usize, image.height_px as usize);
    let column = (x * w as f64 - 0.5).clamp(0.0, (w - 1) as f64);
    let row = ((1.0 - y) * h as f64 - 0.5).clamp(0.0, (h - 1) as f64);
    let (c0, r0) = (column.floor() as usize, row.floor() as usize);
    let (c1, r1) = ((c0 + 1).min(w - 1), (r0 + 1).min(h - 1));
    let (fx, fy) = (column - c0 as f64, row - r0 as f64);
    let mut sum = 0.0;
    for (c, r, weight) in [
        (c0, r0, (1.0 - fx) * (1.0 - fy)),
        (c1, r0, fx * (1.0 - fy)),
        (c0, r1, (1.0 - fx) * fy),
        (c1, r1, fx * fy),
    ] {
        if weight <= 1e-9 {
            continue;
        }
        let i = r * w + c;
        if !inside[i] {
            return None;
        }
        sum += weight * image.luminance_cd_m2[i];
    }
    Some(sum)
}

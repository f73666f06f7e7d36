//! The picture glare is evaluated on: luminance per pixel and the view it was taken with,
//! read from a RADIANCE `.hdr` or from an OpenEXR as `skylux render` writes it, and checked
//! (values, and whether the picture looks like the view it claims).

use super::error::GlareError;
use crate::engine::render::{luminance_from_radiance, PreparedView, View, ViewType};
use crate::picture::{exr, rgbe};
use glam::DVec3;
use std::path::Path;

/// evalglare's "black" for the corners of a picture, cd/m².
const BLACK_CD_M2: f64 = 7.0;

/// A luminance picture with its view.
#[derive(Clone, Debug, PartialEq)]
pub struct LuminanceImage {
    pub width_px: u32,
    pub height_px: u32,
    pub view: View,
    /// cd/m², rows from the top.
    pub luminance_cd_m2: Vec<f64>,
}

/// Reads a `.hdr` (or `.pic`) or `.exr` picture. `view_override` (RADIANCE options) is
/// applied over the file's view, or stands alone when the file has none.
pub fn load_image(path: &Path, view_override: Option<&str>) -> Result<LuminanceImage, GlareError> {
    let is_exr = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("exr"));
    let (width_px, height_px, file_view, luminance_cd_m2) = if is_exr {
        let p = exr::read_exr_luminance(path)?;
        (p.width_px, p.height_px, p.view, p.luminance_cd_m2)
    } else {
        let p = rgbe::read_hdr(path)?;
        let luminance = hdr_luminance(&p);
        (p.width_px, p.height_px, p.view, luminance)
    };
    let view = match (file_view, view_override) {
        (None, None) => {
            return Err(GlareError::Input {
                path: path.into(),
                message: "the picture has no view (no VIEW= line): give one with --view \
                          (e.g. \"-vta -vh 180 -vv 180 -vd 0 1 0 -vu 0 0 1\")"
                    .into(),
            })
        }
        (Some(v), None) => View::parse(&v),
        (None, Some(o)) => View::parse(o),
        (Some(v), Some(o)) => View::parse(&v).and_then(|v| v.with_options(o)),
    }
    .map_err(|e| GlareError::Input {
        path: path.into(),
        message: e.to_string(),
    })?;
    Ok(LuminanceImage {
        width_px,
        height_px,
        view,
        luminance_cd_m2,
    })
}

/// Luminance of a RADIANCE picture's pixels, cd/m².
fn hdr_luminance(p: &rgbe::HdrPicture) -> Vec<f64> {
    use crate::photometry::WHITE_EFFICACY_LM_PER_W;
    p.pixels
        .iter()
        .map(|&[a, b, c]| match p.format {
            rgbe::PixelFormat::Rgbe => {
                luminance_from_radiance(DVec3::new(f64::from(a), f64::from(b), f64::from(c)))
            }
            rgbe::PixelFormat::Xyze => WHITE_EFFICACY_LM_PER_W * f64::from(b),
        })
        .collect()
}

/// Checks the values: every pixel finite and not negative.
pub fn check_values(image: &LuminanceImage) -> Result<(), GlareError> {
    let expected = image.width_px as usize * image.height_px as usize;
    if image.luminance_cd_m2.len() != expected || expected == 0 {
        return Err(GlareError::Picture(format!(
            "{} luminance values for {} × {} pixels",
            image.luminance_cd_m2.len(),
            image.width_px,
            image.height_px
        )));
    }
    for (i, &l) in image.luminance_cd_m2.iter().enumerate() {
        if !l.is_finite() || l < 0.0 {
            let w = image.width_px as usize;
            return Err(GlareError::Picture(format!(
                "pixel (column {}, row {} from the top) has luminance {l} cd/m²: a luminance \
                 picture needs finite values ≥ 0",
                i % w,
                i / w
            )));
        }
    }
    Ok(())
}

/// Checks that the picture looks like its view: its aspect is the view's (as rpict makes
/// it), a fisheye's pixels without a ray (beyond its circle) are black (else the picture is
/// not that fisheye), and a perspective picture does not have black corners around a lit
/// middle (evalglare's check: it then is a fisheye given a wrong view). An angular fisheye's
/// pixels beyond 90° are not checked: rpict renders what lies behind there.
pub fn check_projection(image: &LuminanceImage, view: &PreparedView) -> Result<(), GlareError> {
    let (w, h) = (image.width_px as usize, image.height_px as usize);
    let lit = |i: usize| image.luminance_cd_m2[i] >= BLACK_CD_M2;
    let expected_h = w as f64 * view.aspect();
    if (expected_h - h as f64).abs() > 1.0 + 0.01 * expected_h {
        return Err(GlareError::Picture(format!(
            "the picture is {w} × {h} pixels, but the view `{}` frames {w} × {expected_h:.0}: \
             this is not a picture of that view; give its real view with --view",
            view.view.to_radiance_string()
        )));
    }
    match view.view.kind {
        ViewType::Angular | ViewType::Hemispherical => {
            let outside: Vec<usize> = (0..w * h)
                .filter(|&i| {
                    let (column, row) = ((i % w) as u32, (i / w) as u32);
                    view.pixel_centre_ray(column, row, w as u32, h as u32)
                        .is_none()
                })
                .collect();
            let lit_outside = outside.iter().filter(|&&i| lit(i)).count();
            if outside.len() * 100 >= w * h && lit_outside * 10 > outside.len() * 3 {
                return Err(GlareError::Picture(format!(
                    "the view is a fisheye (`{}`), but {lit_outside} of the {} pixels outside \
                     its circle are lit (≥ {BLACK_CD_M2} cd/m²): this is not a fisheye picture; \
                     give its real view with --view",
                    view.view.to_radiance_string(),
                    outside.len()
                )));
            }
        }
        ViewType::Perspective => {
            let (cx, cy) = ((w / 2) as f64, (h / 2) as f64);
            let rim = (cx + cy) / 2.0;
            let (mut corner, mut corner_black, mut inner, mut inner_black) = (0, 0, 0, 0);
            for i in 0..w * h {
                let (x, y) = ((i % w) as f64, (i / w) as f64);
                let outer = ((x - cx).powi(2) + (y - cy).powi(2)).sqrt() > rim;
                let black = !lit(i) as usize;
                if outer {
                    corner += 1;
                    corner_black += black;
                } else {
                    inner += 1;
                    inner_black += black;
                }
            }
            if corner > 0 && corner_black * 10 > corner * 7 && inner_black * 10 < inner * 3 {
                return Err(GlareError::Picture(format!(
                    "the view is perspective, but {corner_black} of the {corner} corner pixels \
                     are black around a lit middle: this looks like a fisheye picture; give \
                     its real view with --view (e.g. -vta -vh 180 -vv 180)"
                )));
            }
        }
    }
    Ok(())
}

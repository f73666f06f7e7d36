//! The Monte-Carlo standard error of a rendered picture's vertical eye illuminance: Ev is a
//! weighted sum of independent pixel means (Ev = Σ L ω cos θ, as [`super::evaluate`] sums
//! it), so its variance is Σ (ω cos θ)² s², s each pixel's standard error.

use super::error::GlareError;
use super::image::LuminanceImage;
use super::pixels::PixelGrid;

/// Standard error of Ev, lux, for `image` with per-pixel luminance standard errors
/// `stderr_cd_m2` (rows from the top, as the picture's luminance).
pub fn ev_stderr_lux(image: &LuminanceImage, stderr_cd_m2: &[f64]) -> Result<f64, GlareError> {
    let (w, h) = (image.width_px as usize, image.height_px as usize);
    if stderr_cd_m2.len() != w * h {
        return Err(GlareError::Picture(format!(
            "{} standard errors for {w} × {h} pixels",
            stderr_cd_m2.len()
        )));
    }
    let view = image
        .view
        .prepare()
        .map_err(|e| GlareError::Picture(e.to_string()))?;
    let grid = PixelGrid::new(&view, w, h);
    let mut variance = 0.0;
    for y in 0..h {
        for x in 0..w {
            let i = grid.index(x, y);
            if grid.is_valid(i) {
                let weight = grid.direction[i].dot(grid.view_direction) * grid.solid_angle_sr[i];
                variance += (weight * stderr_cd_m2[(h - 1 - y) * w + x]).powi(2);
            }
        }
    }
    Ok(variance.sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::render::View;

    #[test]
    fn a_uniform_error_adds_in_quadrature_over_the_hemisphere() {
        let view = View::parse("-vta -vh 180 -vv 180").unwrap();
        let n = 64u32;
        let image = LuminanceImage {
            width_px: n,
            height_px: n,
            view,
            luminance_cd_m2: vec![1.0; (n * n) as usize],
        };
        let s = ev_stderr_lux(&image, &vec![1.0; (n * n) as usize]).unwrap();
        // Var = Σ ω (ω cos² θ): an equidistant pixel spans (π/n)² sinθ/θ sr, between
        // (π/n)² at the centre and 2/π of it at 90°, and Σ ω cos² θ over the hemisphere is
        // 2π/3; so Var lies between 2/π and 1 times (π/n)² 2π/3.
        let scale = (std::f64::consts::PI / f64::from(n)).powi(2) * std::f64::consts::TAU / 3.0;
        let ratio = s * s / scale;
        assert!(ratio > 0.6 && ratio < 1.02, "{ratio}");
        // Doubling every error doubles Ev's.
        let s2 = ev_stderr_lux(&image, &vec![2.0; (n * n) as usize]).unwrap();
        assert!((s2 - 2.0 * s).abs() < 1e-12 * s);
        assert!(ev_stderr_lux(&image, &[1.0]).is_err());
    }
}

//! An edge-aware filter for the smooth part of a render: the irradiance of the first
//! Lambertian surface less the sun's direct light ([`super::first_hit`]).
//!
//! The edge-avoiding à-trous wavelet filter (Dammertz, Sewtz, Hanika and Lensch, "Edge-avoiding
//! À-Trous wavelet transform for fast global illumination filtering", HPG 2010) with the
//! variance-guided luminance weight of SVGF (Schied et al., "Spatiotemporal
//! variance-guided filtering", HPG 2017): five passes of a 5 × 5 B3-spline kernel whose taps
//! are 1, 2, 4, 8 and 16 pixels apart, each tap weighted by
//! - the normals' agreement, (n_p · n_q)^[`NORMAL_POWER`];
//! - the distance of q's point from p's tangent plane, against [`PLANE_TOLERANCE`] of p's
//!   distance from the eye (points on the same plane always agree);
//! - the difference of the irradiances' luminance against [`LUMINANCE_SIGMAS`] standard
//!   errors of it (a real edge, such as a sky-lit patch's border, stops the filter; noise
//!   does not).
//!
//! Only the irradiance is filtered: the reflectance, the sun's direct light and every
//! non-Lambertian surface stay as traced, so textures and sun shadows stay sharp.

use glam::DVec3;

/// Half width of the window over which [`pool_variances`] averages (7 × 7 pixels, SVGF's).
const POOL_RADIUS: usize = 3;
/// Passes of the filter (taps up to 2⁴ = 16 pixels apart: a support of 61 pixels).
pub const PASSES: u32 = 5;
/// Exponent of the normal weight (SVGF's σ_n = 128 is for noisy shading normals; flat
/// surfaces here have exact ones, and a corner between two walls has n·n = 0).
const NORMAL_POWER: i32 = 64;
/// Distance off p's tangent plane, as a fraction of p's distance from the eye, at which q's
/// weight has fallen to 1/e.
const PLANE_TOLERANCE: f64 = 0.01;
/// Standard errors of a luminance difference at which q's weight has fallen to 1/e (SVGF's
/// σ_l = 4).
const LUMINANCE_SIGMAS: f64 = 4.0;
/// Relative standard error below which a pixel is left as it is: each pass trades noise for
/// blur, and past this the blur of the irradiance's real gradients costs more than the
/// noise it removes (BENCHMARKS.md, the render bench).
const QUIET_RELATIVE_ERROR: f64 = 0.02;
/// The B3-spline kernel's weights (1, 4, 6, 4, 1) / 16.
const KERNEL: [f64; 5] = [1.0 / 16.0, 1.0 / 4.0, 3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0];

/// One pixel's smooth part before and after filtering.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilterPixel {
    /// The mean of the pixel's estimates of the irradiance (W/m² per RGB channel).
    pub irradiance_rgb: DVec3,
    /// The variance of that mean's luminance weight (bright()) of the irradiance.
    pub variance: f64,
    /// Mean point and unit normal of the surface seen, and its distance from the eye; None
    /// where no sample saw a Lambertian surface (nothing to filter).
    pub surface: Option<(DVec3, DVec3, f64)>,
}

/// Filters `pixels` (row-major, `width_px` wide) in place.
pub fn filter(pixels: &mut [FilterPixel], width_px: usize) {
    if width_px == 0 {
        return;
    }
    let height_px = pixels.len() / width_px;
    pool_variances(pixels, width_px, height_px);
    let mut scratch = pixels.to_vec();
    for pass in 0..PASSES {
        let step = 1usize << pass;
        {
            use rayon::prelude::*;
            let source: &[FilterPixel] = pixels;
            scratch
                .par_chunks_mut(width_px)
                .enumerate()
                .for_each(|(row, out)| {
                    for (column, target) in out.iter_mut().enumerate() {
                        *target = filtered_at(source, width_px, height_px, row, column, step);
                    }
                });
        }
        pixels.copy_from_slice(&scratch);
    }
}

/// Replaces each pixel's variance by the mean over the pixels of the same surface within
/// [`POOL_RADIUS`] (SVGF's spatial estimate where a pixel has few samples): from a handful
/// of paths a pixel's own spread is often near zero by chance, which would make it refuse
/// its neighbours and the filter's weights lopsided, losing light that only a few pixels
/// happened to find.
fn pool_variances(pixels: &mut [FilterPixel], width_px: usize, height_px: usize) {
    use rayon::prelude::*;
    let source = pixels.to_vec();
    pixels
        .par_chunks_mut(width_px)
        .enumerate()
        .for_each(|(row, out)| {
            for (column, target) in out.iter_mut().enumerate() {
                let Some((x_p, n_p, distance_p)) = target.surface else {
                    continue;
                };
                let (mut sum, mut weights) = (0.0, 0.0);
                let rows = row.saturating_sub(POOL_RADIUS)..(row + POOL_RADIUS + 1).min(height_px);
                for y in rows {
                    let columns = column.saturating_sub(POOL_RADIUS)
                        ..(column + POOL_RADIUS + 1).min(width_px);
                    for x in columns {
                        let q = &source[y * width_px + x];
                        let Some((x_q, n_q, _)) = q.surface else {
                            continue;
                        };
                        let w = geometry_weight(x_p, n_p, distance_p, x_q, n_q);
                        sum += w * q.variance;
                        weights += w;
                    }
                }
                target.variance = sum / weights;
            }
        });
}

/// The normal and tangent-plane parts of a tap's weight (1 for the same plane).
fn geometry_weight(x_p: DVec3, n_p: DVec3, distance_p: f64, x_q: DVec3, n_q: DVec3) -> f64 {
    let plane_scale = PLANE_TOLERANCE * distance_p.max(1e-9);
    n_p.dot(n_q).max(0.0).powi(NORMAL_POWER) * (-(x_q - x_p).dot(n_p).abs() / plane_scale).exp()
}

/// One pass of the filter at pixel (row, column), taps `step` apart.
fn filtered_at(
    pixels: &[FilterPixel],
    width_px: usize,
    height_px: usize,
    row: usize,
    column: usize,
    step: usize,
) -> FilterPixel {
    let centre = pixels[row * width_px + column];
    let Some((x_p, n_p, distance_p)) = centre.surface else {
        return centre;
    };
    let l_p = luminance(centre.irradiance_rgb);
    // Quiet enough already: wider taps would only blur the light's real variation.
    if centre.variance.max(0.0).sqrt() <= QUIET_RELATIVE_ERROR * l_p {
        return centre;
    }
    let (mut sum, mut weights, mut variance) = (DVec3::ZERO, 0.0, 0.0);
    for (i, kernel_y) in KERNEL.iter().enumerate() {
        let Some(y) = offset(row, i, step, height_px) else {
            continue;
        };
        for (j, kernel_x) in KERNEL.iter().enumerate() {
            let Some(x) = offset(column, j, step, width_px) else {
                continue;
            };
            let q = pixels[y * width_px + x];
            let Some((x_q, n_q, _)) = q.surface else {
                continue;
            };
            let geometry = geometry_weight(x_p, n_p, distance_p, x_q, n_q);
            // Symmetric in p and q, so that light one pixel has by chance too much of is
            // shared with its neighbours as theirs is with it: the filter keeps the mean.
            let luminance_scale =
                LUMINANCE_SIGMAS * (centre.variance.max(0.0) + q.variance.max(0.0)).sqrt();
            let light =
                (-(luminance(q.irradiance_rgb) - l_p).abs() / (luminance_scale + 1e-300)).exp();
            let w = kernel_y * kernel_x * geometry * light;
            sum += w * q.irradiance_rgb;
            weights += w;
            variance += w * w * q.variance;
        }
    }
    // The centre tap always has weight KERNEL[2]² > 0.
    FilterPixel {
        irradiance_rgb: sum / weights,
        variance: variance / (weights * weights),
        surface: centre.surface,
    }
}

/// The pixel `step × (tap − 2)` from `at`, if inside 0..len.
fn offset(at: usize, tap: usize, step: usize, len: usize) -> Option<usize> {
    let shifted = (at + tap * step).checked_sub(2 * step)?;
    (shifted < len).then_some(shifted)
}

/// RADIANCE's `bright()` weights, the luminance weight of an RGB triple.
fn luminance(rgb: DVec3) -> f64 {
    super::super::material::bright(rgb)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flat(
        width: usize,
        height: usize,
        mut value: impl FnMut(usize, usize) -> f64,
    ) -> Vec<FilterPixel> {
        let mut out = Vec::new();
        for y in 0..height {
            for x in 0..width {
                out.push(FilterPixel {
                    irradiance_rgb: DVec3::splat(value(x, y)),
                    variance: 0.04,
                    surface: Some((
                        DVec3::new(x as f64 * 0.01, y as f64 * 0.01, 0.0),
                        DVec3::Z,
                        2.0,
                    )),
                });
            }
        }
        out
    }

    #[test]
    fn noise_on_one_plane_is_averaged_and_the_mean_kept() {
        let mut rng = crate::engine::rng::Rng::for_stream(3, 0);
        let mut pixels = flat(64, 64, |_, _| {
            1.0 + 0.2 * (rng_uniform(&mut rng) - 0.5) * 3.46
        });
        let before: f64 = pixels.iter().map(|p| p.irradiance_rgb.x).sum::<f64>() / 4096.0;
        let spread = |p: &[FilterPixel]| {
            let m = p.iter().map(|p| p.irradiance_rgb.x).sum::<f64>() / p.len() as f64;
            (p.iter()
                .map(|p| (p.irradiance_rgb.x - m).powi(2))
                .sum::<f64>()
                / p.len() as f64)
                .sqrt()
        };
        let noisy = spread(&pixels);
        filter(&mut pixels, 64);
        let after: f64 = pixels.iter().map(|p| p.irradiance_rgb.x).sum::<f64>() / 4096.0;
        assert!((after - before).abs() < 0.01, "mean {before} -> {after}");
        assert!(
            spread(&pixels) < noisy / 5.0,
            "{noisy} -> {}",
            spread(&pixels)
        );
    }

    fn rng_uniform(rng: &mut crate::engine::rng::Rng) -> f64 {
        rng.uniform()
    }

    #[test]
    fn a_corner_and_a_strong_edge_are_kept() {
        // Left half a wall facing +x, right half the floor: nothing crosses the corner.
        let mut pixels = flat(32, 8, |x, _| if x < 16 { 5.0 } else { 1.0 });
        for (i, p) in pixels.iter_mut().enumerate() {
            if i % 32 < 16 {
                p.surface = p.surface.map(|(x, _, d)| (x, DVec3::X, d));
            }
        }
        filter(&mut pixels, 32);
        for (i, p) in pixels.iter().enumerate() {
            let want = if i % 32 < 16 { 5.0 } else { 1.0 };
            assert!(
                (p.irradiance_rgb.x - want).abs() < 1e-9,
                "{i}: {}",
                p.irradiance_rgb.x
            );
        }
        // The same step on one plane, 50 standard errors high: kept to within 1 %.
        let mut step = flat(32, 8, |x, _| if x < 16 { 11.0 } else { 1.0 });
        filter(&mut step, 32);
        for (i, p) in step.iter().enumerate() {
            let want = if i % 32 < 16 { 11.0 } else { 1.0 };
            assert!(
                (p.irradiance_rgb.x - want).abs() < 0.01 * want,
                "{i}: {}",
                p.irradiance_rgb.x
            );
        }
    }

    #[test]
    fn pixels_without_a_surface_are_left_alone() {
        let mut pixels = flat(8, 8, |_, _| 1.0);
        pixels[9].surface = None;
        pixels[9].irradiance_rgb = DVec3::splat(100.0);
        filter(&mut pixels, 8);
        assert_eq!(pixels[9].irradiance_rgb, DVec3::splat(100.0));
        assert!(pixels
            .iter()
            .enumerate()
            .all(|(i, p)| i == 9 || p.irradiance_rgb.x == 1.0));
    }
}

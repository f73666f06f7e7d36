//! Images of a scene from a view (`skylux render`, issue 5 item 7): RADIANCE's views
//! ([`view`]) and the radiance of every pixel by path tracing, written by
//! [`crate::picture`] as OpenEXR, RADIANCE `.hdr` and a falsecolour PNG with a legend.
//!
//! A pixel's value is the mean of `samples_per_pixel` estimates of rtrace's value
//! ([`super::radiance::ray_radiance`]) for rays through jittered positions in the pixel
//! (stratified on a √n × √n grid, the rest uniform). Each pixel has its own random stream
//! from (seed, pixel index), and rows are spread over rayon's threads, so an image does not
//! depend on the number of threads.
//!
//! Two things make a picture clean at a given time (issue 21 item 2), both keeping the
//! quantities a glare evaluation sums:
//! - the sun's disc seen straight through the view is integrated over the pixels
//!   ([`sun_in_view`]) instead of being hit by chance, so Ev and DGP with the sun in view do
//!   not depend on a few lucky rays;
//! - filtered renders ([`RenderSettings::filtered`]) split each sample at the first
//!   Lambertian surface ([`first_hit`]) and average the smooth part of its irradiance over
//!   neighbouring pixels on the same surface ([`filter`]); reflectances, the sun's direct
//!   light and every other surface stay as traced.

pub mod filter;
pub mod first_hit;
pub mod sun_in_view;
pub mod view;

pub use view::{PreparedView, View, ViewError, ViewType};

use super::error::EngineError;
use super::illuminance::lux_from_irradiance;
use super::integrator::Settings;
use super::material::bright;
use super::radiance::{ray_radiance_with, SunDisc};
use super::rng::Rng;
use super::world::World;
use crate::picture::Picture;
use filter::FilterPixel;
use glam::DVec3;
use rayon::prelude::*;

/// Largest image side, and most pixels: the image and its statistics (40 bytes a pixel) must
/// fit in a 32-bit process's memory.
pub const MAX_SIDE_PX: u32 = 16384;
pub const MAX_PIXELS: u64 = 1 << 24;

/// Image size, samples and tracing controls.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderSettings {
    pub width_px: u32,
    pub height_px: u32,
    /// Paths per pixel, at least 1.
    pub samples_per_pixel: u32,
    /// `-ab`, `-lr` and the seed; `samples_per_sensor` is not used.
    pub trace: Settings,
    /// Average the smooth part of the light over neighbouring pixels on the same surface
    /// ([`first_hit`], [`filter`]): far less grain at the same time; off, every pixel is
    /// its own unbiased mean.
    pub filtered: bool,
}

impl RenderSettings {
    pub fn validate(&self) -> Result<(), EngineError> {
        for (name, value) in [
            ("image width (-x)", self.width_px),
            ("image height (-y)", self.height_px),
        ] {
            if value == 0 || value > MAX_SIDE_PX {
                return Err(EngineError::Setting {
                    name,
                    value: value.to_string(),
                    expected: "1 to 16384 pixels",
                });
            }
        }
        if u64::from(self.width_px) * u64::from(self.height_px) > MAX_PIXELS {
            return Err(EngineError::Setting {
                name: "image size (-x × -y)",
                value: format!("{}x{}", self.width_px, self.height_px),
                expected: "at most 16777216 pixels",
            });
        }
        if self.samples_per_pixel == 0 {
            return Err(EngineError::Setting {
                name: "samples per pixel (--spp)",
                value: "0".into(),
                expected: "at least 1",
            });
        }
        Ok(())
    }
}

/// Luminance (cd/m²) from RGB radiance (W/sr/m²): RADIANCE's 179 lm/W and `bright` weights,
/// the same conversion as illuminance from irradiance.
pub fn luminance_from_radiance(radiance_rgb: DVec3) -> f64 {
    lux_from_irradiance(radiance_rgb)
}

/// Renders `view` of `world`. `progress` is called with (rows done, rows in all) from the
/// worker threads.
pub fn render(
    world: &World,
    view: &PreparedView,
    settings: &RenderSettings,
    progress: &(dyn Fn(u64, u64) + Sync),
) -> Result<Picture, EngineError> {
    settings.validate()?;
    let (w, h) = (settings.width_px, settings.height_px);
    let done = std::sync::atomic::AtomicU64::new(0);
    let pixels: Vec<PixelEstimate> = (0..h)
        .into_par_iter()
        .map(|row| {
            let out: Vec<PixelEstimate> = (0..w)
                .map(|column| pixel_estimate(world, view, settings, row, column))
                .collect();
            let d = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(d, u64::from(h));
            out
        })
        .collect::<Vec<_>>()
        .into_iter()
        .flatten()
        .collect();
    let mut smooth: Vec<FilterPixel> = pixels.iter().map(|p| p.smooth).collect();
    if settings.filtered {
        filter::filter(&mut smooth, w as usize);
    }
    let mut image = Picture {
        width_px: w,
        height_px: h,
        view: view.view.to_radiance_string(),
        radiance_rgb: Vec::with_capacity((w * h) as usize),
        luminance_cd_m2: Vec::with_capacity((w * h) as usize),
        luminance_stderr_cd_m2: Vec::with_capacity((w * h) as usize),
        samples_per_pixel: settings.samples_per_pixel,
    };
    for (pixel, smooth) in pixels.iter().zip(&smooth) {
        image
            .radiance_rgb
            .push(pixel.unfiltered_rgb + pixel.albedo_rgb * smooth.irradiance_rgb);
        image.luminance_stderr_cd_m2.push(pixel.stderr_cd_m2);
    }
    sun_in_view::add_discs(world, view, w, h, &mut image.radiance_rgb);
    image.luminance_cd_m2 = image
        .radiance_rgb
        .iter()
        .map(|&rgb| luminance_from_radiance(rgb))
        .collect();
    Ok(image)
}

/// One pixel's samples: radiance `unfiltered_rgb + albedo_rgb ⊙ smooth.irradiance_rgb`.
struct PixelEstimate {
    unfiltered_rgb: DVec3,
    albedo_rgb: DVec3,
    smooth: FilterPixel,
    /// Standard error of the pixel's luminance before any filtering.
    stderr_cd_m2: f64,
}

/// The mean of `samples_per_pixel` samples through jittered positions in the pixel
/// (stratified on a √n × √n grid, the rest uniform), with its own random stream from (seed,
/// pixel index). Unfiltered renders take each sample whole ([`ray_radiance`]); filtered ones
/// split it at the first Lambertian surface ([`first_hit::camera_sample`]).
fn pixel_estimate(
    world: &World,
    view: &PreparedView,
    settings: &RenderSettings,
    row: u32,
    column: u32,
) -> PixelEstimate {
    let (w, h) = (settings.width_px, settings.height_px);
    let n = settings.samples_per_pixel;
    let grid = (f64::from(n).sqrt() as u32).max(1);
    let pixel = u64::from(row) * u64::from(w) + u64::from(column);
    let mut rng = Rng::for_stream(settings.trace.seed, pixel);
    let mut estimate = PixelEstimate {
        unfiltered_rgb: DVec3::ZERO,
        albedo_rgb: DVec3::ZERO,
        smooth: FilterPixel {
            irradiance_rgb: DVec3::ONE,
            variance: 0.0,
            surface: None,
        },
        stderr_cd_m2: 0.0,
    };
    let (mut sum, mut sum2) = (0.0, 0.0);
    let (mut rest, mut rest_l, mut rest_l2, mut seen) = (DVec3::ZERO, 0.0, 0.0, 0u32);
    // Σ albedo ⊙ irradiance: divided by Σ albedo, the irradiance that reproduces the
    // pixel's unfiltered mean exactly where its samples see surfaces of different colours.
    let mut modulated = DVec3::ZERO;
    let (mut position, mut normal, mut distance) = (DVec3::ZERO, DVec3::ZERO, 0.0);
    for s in 0..n {
        let (jx, jy) = if s < grid * grid {
            (
                (f64::from(s % grid) + rng.uniform()) / f64::from(grid),
                (f64::from(s / grid) + rng.uniform()) / f64::from(grid),
            )
        } else {
            (rng.uniform(), rng.uniform())
        };
        let x = (f64::from(column) + jx) / f64::from(w);
        let y = (f64::from(h - 1 - row) + jy) / f64::from(h);
        let Some(ray) = view.ray(x, y) else {
            continue;
        };
        let l = if settings.filtered {
            let sample =
                first_hit::camera_sample(world, ray, &settings.trace, SunDisc::Apart, &mut rng);
            estimate.unfiltered_rgb += sample.unfiltered_rgb;
            estimate.albedo_rgb += sample.albedo_rgb;
            if let Some(f) = sample.feature {
                let e = sample.rest_irradiance_rgb;
                rest += e;
                modulated += sample.albedo_rgb * e;
                rest_l += bright(e);
                rest_l2 += bright(e) * bright(e);
                seen += 1;
                position += f.position_m;
                normal += f.normal;
                distance += f.eye_distance_m;
            }
            sample.unfiltered_rgb + sample.albedo_rgb * sample.rest_irradiance_rgb
        } else {
            let l = ray_radiance_with(world, ray, &settings.trace, SunDisc::Apart, &mut rng);
            estimate.unfiltered_rgb += l;
            l
        };
        let lum = luminance_from_radiance(l);
        sum += lum;
        sum2 += lum * lum;
    }
    let nf = f64::from(n);
    estimate.unfiltered_rgb /= nf;
    estimate.albedo_rgb /= nf;
    let mean = sum / nf;
    if n > 1 {
        let var = ((sum2 - nf * mean * mean) / (nf - 1.0)).max(0.0);
        estimate.stderr_cd_m2 = (var / nf).sqrt();
    }
    if seen > 0 {
        let k = f64::from(seen);
        let m = rest_l / k;
        let albedo_sum = estimate.albedo_rgb * nf;
        let irradiance = DVec3::from_array(std::array::from_fn(|c| {
            if albedo_sum[c] > 0.0 {
                modulated[c] / albedo_sum[c]
            } else {
                rest[c] / k
            }
        }));
        estimate.smooth = FilterPixel {
            irradiance_rgb: irradiance,
            // The variance of the mean; one sample gives no spread, so its variance is
            // taken as its own square (no neighbour is then refused on its account).
            variance: if seen > 1 {
                ((rest_l2 - k * m * m) / (k - 1.0)).max(0.0) / k
            } else {
                m * m
            },
            surface: Some((
                position / k,
                normal.try_normalize().unwrap_or(DVec3::Z),
                distance / k,
            )),
        };
    }
    estimate
}

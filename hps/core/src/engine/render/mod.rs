//! Images of a scene from a view (`skylux render`, issue 5 item 7): RADIANCE's views
//! ([`view`]) and the radiance of every pixel by path tracing, written by
//! [`crate::picture`] as OpenEXR, RADIANCE `.hdr` and a falsecolour PNG with a legend.
//!
//! A pixel's value is the mean of `samples_per_pixel` estimates of rtrace's value
//! ([`super::radiance::ray_radiance`]) for rays through jittered positions in the pixel
//! (stratified on a √n × √n grid, the rest uniform). Each pixel has its own random stream
//! from (seed, pixel index), and rows are spread over rayon's threads, so an image does not
//! depend on the number of threads.

pub mod view;

pub use view::{PreparedView, View, ViewError, ViewType};

use super::error::EngineError;
use super::illuminance::lux_from_irradiance;
use super::integrator::Settings;
use super::radiance::ray_radiance;
use super::rng::Rng;
use super::world::World;
use crate::picture::Picture;
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
    let n = settings.samples_per_pixel;
    let grid = (f64::from(n).sqrt() as u32).max(1);
    let done = std::sync::atomic::AtomicU64::new(0);
    let rows: Vec<Vec<(DVec3, f64, f64)>> = (0..h)
        .into_par_iter()
        .map(|row| {
            let out = (0..w)
                .map(|column| {
                    let pixel = u64::from(row) * u64::from(w) + u64::from(column);
                    let mut rng = Rng::for_stream(settings.trace.seed, pixel);
                    let (mut rgb, mut sum, mut sum2) = (DVec3::ZERO, 0.0, 0.0);
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
                        let l = match view.ray(x, y) {
                            Some(ray) => ray_radiance(world, ray, &settings.trace, &mut rng),
                            None => DVec3::ZERO,
                        };
                        let lum = luminance_from_radiance(l);
                        rgb += l;
                        sum += lum;
                        sum2 += lum * lum;
                    }
                    let nf = f64::from(n);
                    let mean = sum / nf;
                    let var = if n > 1 {
                        ((sum2 - nf * mean * mean) / (nf - 1.0)).max(0.0)
                    } else {
                        0.0
                    };
                    (rgb / nf, mean, (var / nf).sqrt())
                })
                .collect();
            let d = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(d, u64::from(h));
            out
        })
        .collect();
    let mut image = Picture {
        width_px: w,
        height_px: h,
        view: view.view.to_radiance_string(),
        radiance_rgb: Vec::with_capacity((w * h) as usize),
        luminance_cd_m2: Vec::with_capacity((w * h) as usize),
        luminance_stderr_cd_m2: Vec::with_capacity((w * h) as usize),
        samples_per_pixel: n,
    };
    for (rgb, lum, se) in rows.into_iter().flatten() {
        image.radiance_rgb.push(rgb);
        image.luminance_cd_m2.push(lum);
        image.luminance_stderr_cd_m2.push(se);
    }
    Ok(image)
}

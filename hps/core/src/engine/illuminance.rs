//! Workplane illuminance at the virtual sensors: the mean of the path estimates of the
//! irradiance, converted to lux, with its standard error.
//!
//! Lux = 179 × (0.265 R + 0.670 G + 0.065 B), R, G, B irradiance in W/m²: RADIANCE's
//! `WHTEFFICACY` and luminance weights (src/common/color.h; hardware-facts §6), which is what
//! `rtrace -I` output converted the same way gives.
//!
//! Samples are cut into fixed batches, each with its own random stream from (seed, sensor,
//! batch); rayon runs the batches in any order and the sums are combined in batch order, so a
//! result does not depend on the number of threads.

use super::error::EngineError;
use super::integrator::{irradiance_sample, Settings};
use super::material::bright;
use super::rng::Rng;
use super::world::World;
use crate::scene::Sensor;
use glam::DVec3;
use rayon::prelude::*;

/// RADIANCE's luminous efficacy of its "white" radiometric unit, lm/W (color.h WHTEFFICACY).
pub const WHITE_EFFICACY_LM_PER_W: f64 = 179.0;

/// Paths per random stream.
const BATCH_SAMPLES: u32 = 64;

/// The illuminance at one sensor.
#[derive(Clone, Debug, PartialEq)]
pub struct SensorIlluminance {
    pub name: String,
    pub illuminance_lux: f64,
    /// Standard error of `illuminance_lux` from the sample variance, s / √n.
    pub stderr_lux: f64,
    /// Mean irradiance per RGB channel, W/m² (what `rtrace -I` prints).
    pub irradiance_rgb_w_m2: DVec3,
    pub samples: u32,
}

/// Illuminance from RGB irradiance.
pub fn lux_from_irradiance(irradiance_rgb_w_m2: DVec3) -> f64 {
    WHITE_EFFICACY_LM_PER_W * bright(irradiance_rgb_w_m2)
}

#[derive(Clone, Copy, Default)]
struct Sums {
    rgb: DVec3,
    lux: f64,
    lux2: f64,
}

/// Illuminance at every sensor. `progress` is called with (batches done, batches in all)
/// from the worker threads.
pub fn illuminance(
    world: &World,
    sensors: &[Sensor],
    settings: &Settings,
    progress: &(dyn Fn(u64, u64) + Sync),
) -> Result<Vec<SensorIlluminance>, EngineError> {
    settings.validate()?;
    let n = settings.samples_per_sensor;
    let batches = n.div_ceil(BATCH_SAMPLES);
    let total = sensors.len() as u64 * u64::from(batches);
    let done = std::sync::atomic::AtomicU64::new(0);
    let jobs: Vec<(usize, u32)> = (0..sensors.len())
        .flat_map(|s| (0..batches).map(move |b| (s, b)))
        .collect();
    let sums: Vec<Sums> = jobs
        .par_iter()
        .map(|&(s, b)| {
            let sensor = &sensors[s];
            let mut rng = Rng::for_stream(settings.seed, ((s as u64) << 32) | u64::from(b));
            let count = BATCH_SAMPLES.min(n - b * BATCH_SAMPLES);
            let mut acc = Sums::default();
            for _ in 0..count {
                let e = irradiance_sample(
                    world,
                    sensor.position_m,
                    sensor.direction,
                    settings,
                    &mut rng,
                );
                let lux = lux_from_irradiance(e);
                acc.rgb += e;
                acc.lux += lux;
                acc.lux2 += lux * lux;
            }
            let d = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(d, total);
            acc
        })
        .collect();
    Ok(sensors
        .iter()
        .enumerate()
        .map(|(s, sensor)| {
            let mut t = Sums::default();
            for b in &sums[s * batches as usize..(s + 1) * batches as usize] {
                t.rgb += b.rgb;
                t.lux += b.lux;
                t.lux2 += b.lux2;
            }
            let nf = f64::from(n);
            let mean = t.lux / nf;
            let variance = if n > 1 {
                ((t.lux2 - nf * mean * mean) / (nf - 1.0)).max(0.0)
            } else {
                0.0
            };
            SensorIlluminance {
                name: sensor.name.clone(),
                illuminance_lux: mean,
                stderr_lux: (variance / nf).sqrt(),
                irradiance_rgb_w_m2: t.rgb / nf,
                samples: n,
            }
        })
        .collect())
}

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
//!
//! With [`Settings::stratified`] the first [`super::qmc::DIMENSIONS`] numbers of each path
//! come from a scrambled low-discrepancy point set ([`super::qmc`]). Path i of a sensor
//! belongs to replicate i mod R (R = [`REPLICATES`]) and is point ⌊i / R⌋ of that
//! replicate's own randomisation; the replicates are independent, so the standard error is
//! the spread of their means (the paths within one are not independent, and their spread
//! would overstate it).

use super::error::EngineError;
use super::integrator::{irradiance_sample, Settings};
use super::material::bright;
use super::qmc::Randomisation;
use super::rng::Rng;
use super::world::World;
use crate::scene::Sensor;
use glam::DVec3;
use rayon::prelude::*;

/// RADIANCE's luminous efficacy of its "white" radiometric unit, lm/W (color.h WHTEFFICACY).
pub const WHITE_EFFICACY_LM_PER_W: f64 = 179.0;

/// Paths per random stream.
const BATCH_SAMPLES: u32 = 64;

/// Independent randomisations of the stratified point set per sensor: enough for a standard
/// error known to about ±18 % (a χ² with 15 degrees of freedom), few enough that each
/// keeps most of the stratification's gain.
pub const REPLICATES: u32 = 16;

/// Offset of the seeds of the point sets' randomisations, so they are not the paths' streams.
const RANDOMISATION_SEED: u64 = 0x51A7_1F1E_D000_0001;

/// The illuminance at one sensor.
#[derive(Clone, Debug, PartialEq)]
pub struct SensorIlluminance {
    pub name: String,
    pub illuminance_lux: f64,
    /// Standard error of `illuminance_lux`: s / √n from the paths' variance, or with
    /// [`Settings::stratified`] from the spread of the independent replicates' means.
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
    /// Lux summed per replicate (stratified sampling).
    replicate_lux: [f64; REPLICATES as usize],
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
    let replicates = if settings.stratified {
        REPLICATES.min(n)
    } else {
        1
    };
    // One randomisation per sensor and replicate, drawn up front (a fixed order).
    let randomisations: Vec<Randomisation> = if settings.stratified {
        (0..sensors.len() as u64)
            .flat_map(|s| (0..u64::from(replicates)).map(move |r| (s << 32) | r))
            .map(|stream| {
                Randomisation::new(&mut Rng::for_stream(
                    settings.seed ^ RANDOMISATION_SEED,
                    stream,
                ))
            })
            .collect()
    } else {
        Vec::new()
    };
    let sums: Vec<Sums> = jobs
        .par_iter()
        .map(|&(s, b)| {
            let sensor = &sensors[s];
            let mut rng = Rng::for_stream(settings.seed, ((s as u64) << 32) | u64::from(b));
            let count = BATCH_SAMPLES.min(n - b * BATCH_SAMPLES);
            let mut acc = Sums::default();
            for k in 0..count {
                let i = b * BATCH_SAMPLES + k;
                let r = i % replicates;
                if settings.stratified {
                    let set = &randomisations[s * replicates as usize + r as usize];
                    let point = set.point(i / replicates, &mut rng);
                    rng.set_prefix(&point);
                }
                let e = irradiance_sample(
                    world,
                    sensor.position_m,
                    sensor.direction,
                    settings,
                    &mut rng,
                );
                rng.clear_prefix();
                let lux = lux_from_irradiance(e);
                acc.rgb += e;
                acc.lux += lux;
                acc.lux2 += lux * lux;
                acc.replicate_lux[r as usize] += lux;
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
                for (a, x) in t.replicate_lux.iter_mut().zip(&b.replicate_lux) {
                    *a += x;
                }
            }
            let nf = f64::from(n);
            let mean = t.lux / nf;
            let stderr_lux = if settings.stratified {
                replicate_stderr(&t.replicate_lux[..replicates as usize], n, mean)
            } else if n > 1 {
                (((t.lux2 - nf * mean * mean) / (nf - 1.0)).max(0.0) / nf).sqrt()
            } else {
                0.0
            };
            SensorIlluminance {
                name: sensor.name.clone(),
                illuminance_lux: mean,
                stderr_lux,
                irradiance_rgb_w_m2: t.rgb / nf,
                samples: n,
            }
        })
        .collect())
}

/// Standard error of the mean `mean` of `n` paths dealt round-robin into independent
/// replicates whose lux sums are `sums`: the between-replicate variance of the mean,
/// R / (R − 1) Σ (S_r − n_r mean)² / n² (the usual estimator for independent groups, which
/// for equal groups is the variance of the group means over R).
fn replicate_stderr(sums: &[f64], n: u32, mean: f64) -> f64 {
    let r = sums.len() as u32;
    if r < 2 {
        return 0.0;
    }
    let ss: f64 = sums
        .iter()
        .enumerate()
        .map(|(k, s)| {
            // Paths i < n with i mod r = k.
            let n_k = n / r + u32::from((k as u32) < n % r);
            (s - f64::from(n_k) * mean).powi(2)
        })
        .sum();
    let rf = f64::from(r);
    (rf / (rf - 1.0) * ss).sqrt() / f64::from(n)
}

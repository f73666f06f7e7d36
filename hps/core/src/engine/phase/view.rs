//! The view matrix V: for each sensor, the irradiance per unit radiance leaving the window
//! into the room in each Klems patch (what `rfluxmtx -I+ - window.rad -i room.oct` computes
//! with the window a receiver). The paths are the engine's own sensor paths
//! (`integrator::escape_ray_sample`) through the room without its glazing; a path that leaves
//! the room through the window's polygons is credited to the patch of its direction (the
//! light's, reversed), any other escape to none.

use super::window::KlemsWindow;
use super::BATCH_SAMPLES;
use crate::engine::error::EngineError;
use crate::engine::integrator::{escape_ray_sample, Settings};
use crate::engine::material::bright;
use crate::engine::rng::Rng;
use crate::engine::world::World;
use crate::io::radiance_matrix::RadianceMatrix;
use crate::scene::Sensor;
use rayon::prelude::*;

/// V of `world` (the room without its glazing and without sky or sun) for `sensors`:
/// sensors × window patches, W/m² per W/(m² sr) (lux per cd/m²), one component.
pub fn view_matrix(
    world: &World,
    sensors: &[Sensor],
    window: &KlemsWindow,
    settings: &Settings,
    progress: &(dyn Fn(u64, u64) + Sync),
) -> Result<RadianceMatrix, EngineError> {
    Ok(view_matrices(world, sensors, window, settings, progress)?.0)
}

/// V and V_d (the five-phase's direct view: what V holds of the paths' first segments,
/// the sensors' direct view of the window, `rfluxmtx -ab 1`'s) from the same paths. The
/// five-phase takes the sun's direct part out by V_d T D_d s_sun and keeps V T D s_sun:
/// traced apart, their direct parts carry independent noise, and near the sun's beam the
/// difference of two noisy terms can be negative (observed: 24 of 145 patches of a sensor
/// with V < V_d, the sun's interreflected light 118 lux below zero); from the same paths the
/// direct part cancels exactly.
pub fn view_matrices(
    world: &World,
    sensors: &[Sensor],
    window: &KlemsWindow,
    settings: &Settings,
    progress: &(dyn Fn(u64, u64) + Sync),
) -> Result<(RadianceMatrix, RadianceMatrix), EngineError> {
    settings.validate()?;
    let patches = window.basis.len();
    let n = settings.samples_per_sensor;
    let batches = n.div_ceil(BATCH_SAMPLES);
    let total = sensors.len() as u64 * u64::from(batches);
    let done = std::sync::atomic::AtomicU64::new(0);
    let jobs: Vec<(usize, u32)> = (0..sensors.len())
        .flat_map(|s| (0..batches).map(move |b| (s, b)))
        .collect();
    let partial: Vec<(Vec<f64>, Vec<f64>)> = jobs
        .par_iter()
        .map(|&(s, b)| {
            let sensor = &sensors[s];
            // A stream family of its own (bit 62), independent of illuminance's and dc's.
            let stream = (1u64 << 62) | ((s as u64) << 32) | u64::from(b);
            let mut rng = Rng::for_stream(settings.seed, stream);
            let count = BATCH_SAMPLES.min(n - b * BATCH_SAMPLES);
            let mut acc = vec![0.0; patches];
            let mut direct = vec![0.0; patches];
            for _ in 0..count {
                escape_ray_sample(
                    world,
                    sensor.position_m,
                    sensor.direction,
                    settings,
                    &mut rng,
                    &mut |weight, ray| {
                        if !window.crosses(ray) {
                            return;
                        }
                        if let Some(p) = window.patch_of_arrival(-ray.direction) {
                            acc[p] += bright(weight);
                            // The path's first segment leaves from the sensor itself.
                            if ray.origin_m == sensor.position_m {
                                direct[p] += bright(weight);
                            }
                        }
                    },
                );
            }
            let d = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(d, total);
            (acc, direct)
        })
        .collect();
    let mut v = RadianceMatrix::zeros(sensors.len(), patches, 1);
    let mut v_direct = RadianceMatrix::zeros(sensors.len(), patches, 1);
    for (&(s, _), (acc, direct)) in jobs.iter().zip(&partial) {
        let row = s * patches..(s + 1) * patches;
        for (c, a) in v.values[row.clone()].iter_mut().zip(acc) {
            *c += a / f64::from(n);
        }
        for (c, a) in v_direct.values[row].iter_mut().zip(direct) {
            *c += a / f64::from(n);
        }
    }
    Ok((v, v_direct))
}

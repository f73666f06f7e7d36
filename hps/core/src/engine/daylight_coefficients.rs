//! Daylight coefficients: for a fixed room and sensors, the illuminance each sky (and ground)
//! patch of unit luminance gives at each sensor, so that the illuminance under any sky is one
//! matrix-vector product (RADIANCE's `rcontrib`/`rfluxmtx` idea, Tregenza 1983).
//!
//! The paths are the engine's own (`integrator::escape_sample`): the same materials, bounces
//! and specular handling as `skylux illuminance`, with every ray that leaves the room
//! credited to the patch it leaves through instead of being shaded. With `n` paths per
//! sensor, the coefficient of patch `p` is (1/n) Σ π bright(throughput) over the paths
//! escaping through `p`, in lux per cd/m² (a white sky of luminance L cd/m² has RADIANCE
//! radiance L/179 in every channel, and lux = 179 bright(E)).
//!
//! Bins: the sky patches of a Reinhart subdivision, then the same subdivision mirrored below
//! the horizon for the ground (patch `p` of the ground is the mirror image of sky patch `p`).
//! The sun is not binned: it is handed over as a concentrated source ([`sun_coefficients`]).

use super::error::EngineError;
use super::illuminance::illuminance;
use super::integrator::{escape_sample, Settings};
use super::material::bright;
use super::rng::Rng;
use super::sky::{DistantEmitter, DistantKind};
use super::world::World;
use crate::scene::Sensor;
use crate::sky::SkyPatches;
use glam::DVec3;
use rayon::prelude::*;

/// Paths per random stream (as in `illuminance`, so results do not depend on thread count).
const BATCH_SAMPLES: u32 = 64;

/// The daylight-coefficient matrix of a room.
#[derive(Clone, Debug)]
pub struct DaylightCoefficients {
    pub sensors: Vec<String>,
    /// Reinhart multiplication factor of the sky (and mirrored ground) patches.
    pub mf: usize,
    /// Sky patches, then ground patches.
    pub bins: usize,
    /// Row-major, sensors × bins, lux per cd/m².
    pub lux_per_cd_m2: Vec<f64>,
    pub samples_per_sensor: u32,
}

impl DaylightCoefficients {
    /// Sky patches (and, after them, as many ground patches).
    pub fn patches(&self) -> SkyPatches {
        SkyPatches::reinhart(self.mf)
    }

    /// The coefficients of one sensor.
    pub fn row(&self, sensor: usize) -> &[f64] {
        &self.lux_per_cd_m2[sensor * self.bins..(sensor + 1) * self.bins]
    }

    /// Illuminance per sensor, lux, for bin luminances in cd/m² (sky patches, then ground).
    pub fn apply(&self, luminance_cd_m2: &[f64]) -> Result<Vec<f64>, EngineError> {
        if luminance_cd_m2.len() != self.bins {
            return Err(EngineError::Setting {
                name: "patch luminances",
                value: luminance_cd_m2.len().to_string(),
                expected: "one per daylight-coefficient bin (sky patches, then ground)",
            });
        }
        Ok((0..self.sensors.len())
            .map(|s| {
                self.row(s)
                    .iter()
                    .zip(luminance_cd_m2)
                    .map(|(c, l)| c * l)
                    .sum()
            })
            .collect())
    }

    /// The bin a direction leaves through: its sky patch, or the mirrored patch + sky count
    /// for a direction below the horizon.
    pub fn bin_of(patches: &SkyPatches, d: DVec3) -> Option<usize> {
        if !d.is_finite() {
            return None;
        }
        if d.z >= 0.0 {
            patches.patch_of(d)
        } else {
            patches
                .patch_of(DVec3::new(d.x, d.y, -d.z))
                .map(|p| p + patches.len())
        }
    }
}

/// Computes the daylight coefficients of `world` (the room, without sky or sun: any distant
/// source in it is ignored) for `sensors`, with Reinhart MF `mf` patches.
pub fn daylight_coefficients(
    world: &World,
    sensors: &[Sensor],
    mf: usize,
    settings: &Settings,
    progress: &(dyn Fn(u64, u64) + Sync),
) -> Result<DaylightCoefficients, EngineError> {
    settings.validate()?;
    let patches = SkyPatches::reinhart(mf);
    let bins = 2 * patches.len();
    let n = settings.samples_per_sensor;
    let batches = n.div_ceil(BATCH_SAMPLES);
    let total = sensors.len() as u64 * u64::from(batches);
    let done = std::sync::atomic::AtomicU64::new(0);
    let jobs: Vec<(usize, u32)> = (0..sensors.len())
        .flat_map(|s| (0..batches).map(move |b| (s, b)))
        .collect();
    let partial: Vec<Vec<f64>> = jobs
        .par_iter()
        .map(|&(s, b)| {
            let sensor = &sensors[s];
            // A different stream family from `illuminance`'s, so the two are independent.
            let stream = (1u64 << 63) | ((s as u64) << 32) | u64::from(b);
            let mut rng = Rng::for_stream(settings.seed, stream);
            let count = BATCH_SAMPLES.min(n - b * BATCH_SAMPLES);
            let mut acc = vec![0.0; bins];
            for _ in 0..count {
                escape_sample(
                    world,
                    sensor.position_m,
                    sensor.direction,
                    settings,
                    &mut rng,
                    &mut |weight, d| {
                        if let Some(bin) = DaylightCoefficients::bin_of(&patches, d) {
                            acc[bin] += bright(weight);
                        }
                    },
                );
            }
            let d = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(d, total);
            acc
        })
        .collect();
    let mut lux_per_cd_m2 = vec![0.0; sensors.len() * bins];
    for (&(s, _), acc) in jobs.iter().zip(&partial) {
        for (c, a) in lux_per_cd_m2[s * bins..(s + 1) * bins].iter_mut().zip(acc) {
            *c += a / f64::from(n);
        }
    }
    Ok(DaylightCoefficients {
        sensors: sensors.iter().map(|s| s.name.clone()).collect(),
        mf: patches.mf,
        bins,
        lux_per_cd_m2,
        samples_per_sensor: n,
    })
}

/// The sun's solid angle for a 0.533° disk (gendaylit and gensky write `source solar 0 0 4
/// x y z 0.533`), sr.
pub const SUN_DISK_ANGLE_DEG: f64 = 0.533;

/// Illuminance per sensor, lux, per unit of direct-normal illuminance (1 lux) from a sun in
/// unit direction `sun_direction`, including its interreflections, with its standard error.
/// The sun is a `light` of 0.533°, reached by next-event estimation, as RADIANCE treats
/// gendaylit's sun. `world` must be the room alone (no distant source, no environment): it
/// is lent for the computation and handed back unchanged.
pub fn sun_coefficients(
    world: &mut World,
    sensors: &[Sensor],
    sun_direction: DVec3,
    settings: &Settings,
) -> Result<Vec<(f64, f64)>, EngineError> {
    if !world.distant_sources().is_empty() || world.has_environment() {
        return Err(EngineError::Setting {
            name: "room for sun coefficients",
            value: format!("{} distant sources", world.distant_sources().len()),
            expected: "the room alone, without sky, ground or sun",
        });
    }
    let half = 0.5 * SUN_DISK_ANGLE_DEG.to_radians();
    let solid_angle_sr = std::f64::consts::TAU * (1.0 - half.cos());
    // Radiance giving 1 lux at normal incidence: 179 × L × Ω = 1.
    let radiance = 1.0 / (super::WHITE_EFFICACY_LM_PER_W * solid_angle_sr);
    world.add_distant(DistantEmitter {
        name: "skylux_sun".into(),
        kind: DistantKind::Light,
        direction: sun_direction.normalize(),
        cos_half_angle: half.cos(),
        solid_angle_sr,
        radiance_w_sr_m2: DVec3::splat(radiance),
        patterns: vec![],
    });
    let result = illuminance(world, sensors, settings, &|_, _| {});
    world.clear_distant();
    Ok(result?
        .into_iter()
        .map(|s| (s.illuminance_lux, s.stderr_lux))
        .collect())
}

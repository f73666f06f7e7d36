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
use super::sky::DistantEmitter;
use super::world::World;
use crate::io::radiance_matrix::{self, MatrixFormat, RadianceMatrix};
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

    /// Illuminance per sensor, lux, from the bins whose luminance is known: a bin with a
    /// non-finite luminance (one the camera did not see) adds nothing.
    pub fn apply_seen(&self, luminance_cd_m2: &[f64]) -> Vec<f64> {
        (0..self.sensors.len())
            .map(|s| {
                self.row(s)
                    .iter()
                    .zip(luminance_cd_m2)
                    .filter(|(_, l)| l.is_finite())
                    .map(|(c, l)| c * l)
                    .sum()
            })
            .collect()
    }

    /// As [`Self::apply`], into `out`, with the sensors shared among the rayon threads:
    /// the per-capture update of a daemon (400 sensors × 2305 patches is ~1 M multiply-adds).
    pub fn apply_into(&self, luminance_cd_m2: &[f64], out: &mut [f64]) -> Result<(), EngineError> {
        if luminance_cd_m2.len() != self.bins || out.len() != self.sensors.len() {
            return Err(EngineError::Setting {
                name: "patch luminances or output",
                value: format!("{} and {}", luminance_cd_m2.len(), out.len()),
                expected: "one luminance per bin and one output per sensor",
            });
        }
        // A9 cost (timing::a9::DC_PER_COEFFICIENT, armv7 listing): per coefficient `vldmia`,
        // `vldmia`, `vmla.f64`, `subs`, `bne`; the in-order sum makes each VMLA wait 9 cycles
        // for the last. 8 bytes of the matrix a coefficient from the DDR3: memory-bound there.
        out.par_iter_mut()
            .zip(self.lux_per_cd_m2.par_chunks(self.bins))
            .for_each(|(o, row)| {
                *o = row.iter().zip(luminance_cd_m2).map(|(c, l)| c * l).sum();
            });
        Ok(())
    }

    /// Writes the matrix in RADIANCE's matrix format (`crate::io::radiance_matrix`: `NROWS`
    /// sensors, `NCOLS` bins, `NCOMP=1`, `FORMAT=float`, little-endian binary float32), with
    /// Skylux's layout in the header: `SKYLUX_MF`, `SKYLUX_BINS=sky+ground`, `SKYLUX_SAMPLES`
    /// and `SKYLUX_SENSOR=` lines.
    pub fn write(&self, path: &std::path::Path) -> std::io::Result<()> {
        let mut header = vec![
            "skylux dc: daylight coefficients, lux per cd/m2".to_string(),
            format!("SKYLUX_MF={}", self.mf),
            "SKYLUX_BINS=sky+ground".to_string(),
            format!("SKYLUX_SAMPLES={}", self.samples_per_sensor),
        ];
        header.extend(self.sensors.iter().map(|n| format!("SKYLUX_SENSOR={n}")));
        std::fs::write(
            path,
            radiance_matrix::encode(
                self.sensors.len(),
                self.bins,
                1,
                &self.lux_per_cd_m2,
                MatrixFormat::Float,
                &header,
            ),
        )
    }

    /// Reads what [`Self::write`] wrote; every malformed header or size is an error naming
    /// the file and the field.
    pub fn read(path: &std::path::Path) -> Result<Self, String> {
        let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
        Self::parse(path, &bytes)
    }

    /// Parses the bytes of a matrix file (RADIANCE's matrix format, any of its encodings,
    /// one component, with `skylux dc`'s header lines); `path` names it in errors.
    pub fn parse(path: &std::path::Path, bytes: &[u8]) -> Result<Self, String> {
        let file = path.display().to_string();
        let bad = |what: String| format!("{file}: {what}");
        let (matrix, header) =
            RadianceMatrix::parse_with_header(&file, bytes).map_err(|e| e.to_string())?;
        if matrix.ncomp != 1 {
            return Err(bad(format!("NCOMP={}: expected 1", matrix.ncomp)));
        }
        let (mut mf, mut samples) = (None, 0u32);
        let mut sensors = Vec::new();
        for line in &header {
            let Some((k, v)) = line.split_once('=') else {
                continue;
            };
            let num = |v: &str| {
                v.trim()
                    .parse::<usize>()
                    .map_err(|_| bad(format!("{k}={v}: not a count")))
            };
            match k {
                "SKYLUX_MF" => mf = Some(num(v)?),
                "SKYLUX_SAMPLES" => samples = num(v)?.min(u32::MAX as usize) as u32,
                "SKYLUX_SENSOR" => sensors.push(v.to_string()),
                _ => {}
            }
        }
        let (rows, cols) = (matrix.rows, matrix.cols);
        let mf = mf.ok_or_else(|| bad("no SKYLUX_MF: not written by skylux dc".into()))?;
        if !(1..=30).contains(&mf) || cols != 2 * SkyPatches::reinhart(mf).len() {
            return Err(bad(format!(
                "NCOLS={cols} does not match SKYLUX_MF={mf} (sky + ground)"
            )));
        }
        if sensors.len() != rows {
            return Err(bad(format!(
                "{} SKYLUX_SENSOR lines for NROWS={rows}",
                sensors.len()
            )));
        }
        Ok(Self {
            sensors,
            mf,
            bins: cols,
            lux_per_cd_m2: matrix.values,
            samples_per_sensor: samples,
        })
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
    world.add_distant(DistantEmitter::sun(sun_direction, solid_angle_sr, radiance));
    let result = illuminance(world, sensors, settings, &|_, _| {});
    world.clear_distant();
    Ok(result?
        .into_iter()
        .map(|s| (s.illuminance_lux, s.stderr_lux))
        .collect())
}

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
//! With [`Settings::stratified`] the first [`super::rng::STRATIFIED_DIMENSIONS`] numbers of each path
//! come from a scrambled low-discrepancy point set ([`super::qmc`]). Path i of a sensor
//! belongs to replicate i mod R (R = [`REPLICATES`]) and is point ⌊i / R⌋ of that
//! replicate's own randomisation; the replicates are independent, so the standard error is
//! the spread of their means (the paths within one are not independent, and their spread
//! would overstate it).
//!
//! With [`Settings::path_reuse`] the sensors go in groups of up to [`REUSE_GROUP`]
//! consecutive ones (a grid's rows are neighbours), and path i of every sensor of a group is
//! traced together. When a path's first vertex is a Lambertian surface, its estimate of the
//! radiance there serves every sensor of the group that sees the point: sensor j takes
//! L G_j / Σ_k p_k, G_j its geometry term and p_k the area density with which sensor k's first
//! direction (cosine-weighted, or mixed with the `BSDF` windows) lands there (the balance
//! heuristic over the group's sensors; Veach 1997 §9.2;
//! path reuse as in Bekaert, Sbert & Halton 2002, "Accelerating path tracing by re-using
//! paths"). Sample i of sensor j is then its own path's remaining terms plus its shares of
//! the group's i-th vertices, so the samples of different i stay independent and the
//! replicates stay valid. The expensive part of a path, everything past the first vertex,
//! is thus used by several sensors for one visibility ray each.

use super::error::EngineError;
use super::integrator::{
    irradiance_sample_shared_with, irradiance_sample_with, SensorDirections, Settings, SharedVertex,
};
use super::material::bright;
use super::qmc::Randomisation;
use super::ray::Ray;
use super::rng::Rng;
use super::window_sun::{SensorWindowLight, SunThroughWindows};
use super::world::World;
use crate::scene::Sensor;
use glam::DVec3;
use rayon::prelude::*;

pub use crate::photometry::WHITE_EFFICACY_LM_PER_W;

/// Paths per random stream.
const BATCH_SAMPLES: u32 = 64;

/// Independent randomisations of the stratified point set per sensor: enough for a standard
/// error known to about ±18 % (a χ² with 15 degrees of freedom), few enough that each
/// keeps most of the stratification's gain.
pub const REPLICATES: u32 = 16;

/// Most sensors sharing their paths' first vertices. Each shared vertex costs a visibility
/// ray per other sensor of the group, so a larger group pays more rays for vertices that
/// distant sensors rarely see; on the LBNL tutorial room's 100 sensors 48 had 0.5 of the
/// variance × time of 8 (BENCHMARKS.md, "the LBNL matrix tutorial's room").
pub const REUSE_GROUP: usize = 48;

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
    let groups = if settings.path_reuse {
        reuse_groups(sensors, REUSE_GROUP)
    } else {
        (0..sensors.len()).map(|s| vec![s]).collect()
    };
    let jobs: Vec<(usize, u32)> = (0..groups.len())
        .flat_map(|g| (0..batches).map(move |b| (g, b)))
        .collect();
    let total = jobs.len() as u64;
    let done = std::sync::atomic::AtomicU64::new(0);
    let run = Run::new(world, sensors, settings);
    let job_sums: Vec<Vec<Sums>> = jobs
        .par_iter()
        .map(|&(g, b)| {
            let acc = run.batch(&groups[g], b);
            let d = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(d, total);
            acc
        })
        .collect();
    // Per sensor, its batches' sums in batch order.
    let mut sums: Vec<Sums> = vec![Sums::default(); sensors.len() * batches as usize];
    for (&(g, b), per_sensor) in jobs.iter().zip(&job_sums) {
        for (&s, one) in groups[g].iter().zip(per_sensor) {
            sums[s * batches as usize + b as usize] = *one;
        }
    }
    Ok(sensors
        .iter()
        .enumerate()
        .map(|(s, sensor)| {
            run.result(
                sensor,
                &sums[s * batches as usize..(s + 1) * batches as usize],
            )
        })
        .collect())
}

/// What every batch of one [`illuminance`] call shares.
struct Run<'a> {
    world: &'a World,
    sensors: &'a [Sensor],
    settings: &'a Settings,
    /// Paths per sensor.
    n: u32,
    replicates: u32,
    /// One randomisation per sensor and replicate (stratified only).
    randomisations: Vec<Randomisation>,
    /// Per sensor, its directions towards the `BSDF` windows' sun light (None: none).
    tables: Vec<Option<SensorWindowLight>>,
}

impl<'a> Run<'a> {
    fn new(world: &'a World, sensors: &'a [Sensor], settings: &'a Settings) -> Self {
        let n = settings.samples_per_sensor;
        let replicates = if settings.stratified {
            REPLICATES.min(n)
        } else {
            1
        };
        // Drawn up front, in a fixed order.
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
        // Drawn up for each sensor once: each traces many paths. The windows' table is built
        // here, once a run, for the world's sources as they are now.
        let sun = (settings.bsdf_window_sampling && !world.bsdf_windows().is_empty())
            .then(|| SunThroughWindows::new(world))
            .flatten();
        let tables = match &sun {
            Some(sun) => sensors
                .par_iter()
                .map(|s| SensorWindowLight::new(sun, s.position_m, s.direction))
                .collect(),
            None => Vec::new(),
        };
        Self {
            world,
            sensors,
            settings,
            n,
            replicates,
            randomisations,
            tables,
        }
    }

    /// The sums of batch `b` of the sensors of `group` (indices into the sensors), in the
    /// group's order.
    fn batch(&self, group: &[usize], b: u32) -> Vec<Sums> {
        let (world, settings, replicates) = (self.world, self.settings, self.replicates);
        let members: Vec<&Sensor> = group.iter().map(|&s| &self.sensors[s]).collect();
        let tables: Vec<Option<&SensorWindowLight>> = group
            .iter()
            .map(|&s| self.tables.get(s).and_then(Option::as_ref))
            .collect();
        let directions: Vec<SensorDirections> = members
            .iter()
            .zip(&tables)
            .map(|(sensor, &table)| {
                let normal = sensor.direction.normalize_or_zero();
                SensorDirections::new(world, settings, sensor.position_m, normal, table)
            })
            .collect();
        let reuse = members.len() > 1;
        let mut rngs: Vec<Rng> = group
            .iter()
            .map(|&s| Rng::for_stream(settings.seed, ((s as u64) << 32) | u64::from(b)))
            .collect();
        let count = BATCH_SAMPLES.min(self.n - b * BATCH_SAMPLES);
        let mut acc = vec![Sums::default(); members.len()];
        let mut e = vec![DVec3::ZERO; members.len()];
        let mut shared: Vec<(usize, SharedVertex)> = Vec::with_capacity(members.len());
        for k in 0..count {
            let i = b * BATCH_SAMPLES + k;
            let r = i % replicates;
            e.fill(DVec3::ZERO);
            shared.clear();
            for (local, (&s, sensor)) in group.iter().zip(&members).enumerate() {
                let rng = &mut rngs[local];
                if settings.stratified {
                    let set = &self.randomisations[s * replicates as usize + r as usize];
                    let point = set.point(i / replicates, rng);
                    rng.set_prefix(&point);
                }
                let (position, normal) = (sensor.position_m, sensor.direction);
                if reuse {
                    let (own, vertex) = irradiance_sample_shared_with(
                        world,
                        position,
                        normal,
                        tables[local],
                        settings,
                        rng,
                    );
                    e[local] += own;
                    if let Some(v) = vertex {
                        shared.push((local, v));
                    }
                } else {
                    e[local] += irradiance_sample_with(
                        world,
                        position,
                        normal,
                        tables[local],
                        settings,
                        rng,
                    );
                }
                rng.clear_prefix();
            }
            for (from, v) in &shared {
                share_vertex(world, &members, &directions, *from, v, &mut e);
            }
            for (a, x) in acc.iter_mut().zip(&e) {
                let lux = lux_from_irradiance(*x);
                a.rgb += *x;
                a.lux += lux;
                a.lux2 += lux * lux;
                a.replicate_lux[r as usize] += lux;
            }
        }
        acc
    }

    /// A sensor's estimate and standard error from its batches' sums, in batch order.
    fn result(&self, sensor: &Sensor, batches: &[Sums]) -> SensorIlluminance {
        let n = self.n;
        let mut t = Sums::default();
        for b in batches {
            t.rgb += b.rgb;
            t.lux += b.lux;
            t.lux2 += b.lux2;
            for (a, x) in t.replicate_lux.iter_mut().zip(&b.replicate_lux) {
                *a += x;
            }
        }
        let nf = f64::from(n);
        let mean = t.lux / nf;
        let stderr_lux = if self.settings.stratified {
            replicate_stderr(&t.replicate_lux[..self.replicates as usize], n, mean)
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
    }
}

/// Sensors in groups of at most `size` neighbours, as few groups as that allows and of even
/// sizes, in a fixed order: the first sensor not yet placed with the unplaced ones nearest
/// to it. (Consecutive lines of a file are
/// not always neighbours: a grid's row ends next to the next row's start.)
fn reuse_groups(sensors: &[Sensor], size: usize) -> Vec<Vec<usize>> {
    // As many groups as `size` needs, of even sizes: no small leftover group whose
    // sensors share with few others.
    let size = sensors
        .len()
        .div_ceil(sensors.len().div_ceil(size.max(1)).max(1));
    let mut placed = vec![false; sensors.len()];
    let mut groups = Vec::new();
    for first in 0..sensors.len() {
        if placed[first] {
            continue;
        }
        let at = sensors[first].position_m;
        let mut others: Vec<usize> = (first + 1..sensors.len()).filter(|&s| !placed[s]).collect();
        others.sort_by(|&a, &b| {
            let (da, db) = (
                sensors[a].position_m.distance_squared(at),
                sensors[b].position_m.distance_squared(at),
            );
            da.total_cmp(&db).then(a.cmp(&b))
        });
        let mut group = vec![first];
        group.extend(others.into_iter().take(size.saturating_sub(1)));
        for &s in &group {
            placed[s] = true;
        }
        groups.push(group);
    }
    groups
}

/// Hands the shared vertex `v`, found by the path of sensor `from` of `group`, to every sensor
/// of the group that sees it directly from the same side: sensor j's irradiance sample `e[j]`
/// gains L G_j / Σ_k p_k, where G_j = cos θ_j cos θ_v / d_j² and p_k = p_k(ω_k) cos θ_v / d_k²
/// is the area density at the vertex of sensor k's first direction (its cosine lobe,
/// p = cos θ_k / π, so that j gains π L p_j / Σ p_k, or that mixed with the `BSDF` windows
/// and the sensor's table of their light: `integrator::SensorDirections`; 0 where the vertex is not k's first hit). Over the
/// group's paths this counts the light of the Lambertian first vertices once for each sensor
/// in expectation (balance heuristic).
fn share_vertex(
    world: &World,
    group: &[&Sensor],
    directions: &[SensorDirections],
    from: usize,
    v: &SharedVertex,
    e: &mut [DVec3],
) {
    let side = (group[from].position_m - v.position_m)
        .dot(v.normal)
        .signum();
    let mut density = [0.0f64; REUSE_GROUP];
    let mut geometry = [0.0f64; REUSE_GROUP];
    let mut total = 0.0;
    for (k, sensor) in group.iter().enumerate() {
        let to = v.position_m - sensor.position_m;
        let d2 = to.length_squared();
        if (d2).partial_cmp(&1e-18) != Some(std::cmp::Ordering::Greater) {
            continue;
        }
        let dist = d2.sqrt();
        let w = to / dist;
        let normal = sensor.direction.normalize_or_zero();
        let cos_k = normal.dot(w);
        let cos_v = -w.dot(v.normal) * side;
        if !(cos_k > 0.0 && cos_v > 0.0) {
            continue;
        }
        // The vertex must be sensor k's first hit along w (the sensor that found it saw it):
        // nothing before it.
        if k != from
            && world.blocked_within(&Ray::new(sensor.position_m, w), None, dist * (1.0 - 1e-6))
        {
            continue;
        }
        let pdf_sr = directions[k].pdf_sr(w);
        density[k] = pdf_sr * cos_v / d2;
        geometry[k] = cos_k * cos_v / d2;
        total += density[k];
    }
    if (total).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return;
    }
    for ((x, p), g) in e.iter_mut().zip(&density).zip(&geometry) {
        if *p > 0.0 {
            *x += v.radiance_rgb * (g / total);
        }
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A 20 × 20 grid in raster order (a row's end is nowhere near the next row's start)
    /// goes into groups of at most [`REUSE_GROUP`] that hold every point once, and nearly all
    /// groups are compact: every member near the group's first point (the first is the first
    /// unplaced point in raster order, so its neighbours fill about a quarter disc, whose
    /// radius for G points of 0.145 × 0.32 m each is 2 √(G a / π); a margin of 1.2 on it).
    #[test]
    fn reuse_groups_are_neighbourhoods() {
        let text: String = (0..400)
            .map(|i| {
                format!(
                    "{} {} 0.8 0 0 1\n",
                    0.0725 + 0.145 * (i % 20) as f64,
                    0.16 + 0.32 * (i / 20) as f64
                )
            })
            .collect();
        let sensors = crate::scene::parse_sensors("grid.pts", text.as_bytes()).unwrap();
        let groups = reuse_groups(&sensors, REUSE_GROUP);
        let mut seen = vec![0; sensors.len()];
        let mut compact = 0;
        let radius_m =
            1.2 * 2.0 * (REUSE_GROUP as f64 * 0.145 * 0.32 / std::f64::consts::PI).sqrt();
        for g in &groups {
            assert!(!g.is_empty() && g.len() <= REUSE_GROUP);
            for &s in g {
                seen[s] += 1;
            }
            let at = sensors[g[0]].position_m;
            if g.iter()
                .all(|&s| sensors[s].position_m.distance(at) < radius_m)
            {
                compact += 1;
            }
        }
        assert!(seen.iter().all(|&c| c == 1));
        assert_eq!(groups.len(), 400usize.div_ceil(REUSE_GROUP));
        // Only the last, leftover groups may straggle.
        assert!(
            compact + 2 >= groups.len(),
            "{compact} of {} groups compact",
            groups.len()
        );
    }
}

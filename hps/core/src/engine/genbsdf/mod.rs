//! BSDFs from a detailed model of a fenestration device, as RADIANCE's `genBSDF` makes them
//! (its manual page; the Python port `pyradiance.genbsdf`), by our own paths.
//!
//! The device lies behind the z = 0 plane with the room on +z: +z is the BSDF's front in
//! RADIANCE's frame (WINDOW's back), so a `BSDF` material with up vector +y on a surface whose
//! normal is +z reads the file in the device's own axes. For each Klems patch of each side,
//! rays start at points uniform over the sampling box's face on that side and enter along
//! directions uniform in projected solid angle over the patch (8 × 8 strata per batch, as
//! `rfluxmtx` samples a sender), follow the engine's paths through the device (at most `-ab`
//! diffuse bounces), and every escape is credited to the patch of the hemisphere it leaves
//! into. A part's value is the flux fraction into an outgoing patch over that patch's
//! projected solid angle (1/sr), so that Σⱼ fⱼᵢ Ωⱼ is patch i's hemispherical R or T, the
//! quantity `wrapBSDF -c` writes. [`klems`] samples over a Klems basis, [`tensor_tree`] over
//! the Shirley–Chiu square (RADIANCE's tensor trees, `genBSDF -t3`/`-t4`).

pub mod klems;
pub mod tensor_tree;

pub use klems::{generate_klems, Asymmetry, GeneratedBsdf, Reciprocity};
pub use tensor_tree::{generate_tensor_tree, GeneratedTree, TreeKind};

use super::error::EngineError;
use super::integrator::{escape_path, Settings};
use super::material::bright;
use super::ray::Ray;
use super::rng::Rng;
use super::world::World;
use crate::bsdf::{BsdfDocument, DocumentData, DocumentPart, Side};
use glam::DVec3;
use rayon::prelude::*;

/// The region sampled, in the geometry's own units: rays enter through its z faces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SamplingBox {
    pub min: DVec3,
    pub max: DVec3,
}

impl SamplingBox {
    /// The bounding box of every surface of `world` (what `genBSDF` takes from `getbbox`
    /// when `-dim` is not given), or None for an empty world.
    pub fn of_world(world: &World) -> Option<SamplingBox> {
        let n = world.primitive_count();
        (n > 0).then(|| {
            (0..n as u32).map(|k| world.primitive(k).bounds()).fold(
                SamplingBox {
                    min: DVec3::splat(f64::INFINITY),
                    max: DVec3::splat(f64::NEG_INFINITY),
                },
                |b, a| SamplingBox {
                    min: b.min.min(a.min_m),
                    max: b.max.max(a.max_m),
                },
            )
        })
    }

    /// What is wrong with the box for sampling, if anything: a face of no area or a box
    /// entirely in the room.
    pub fn check(&self) -> Result<(), String> {
        let size = self.max - self.min;
        if !size.is_finite() || size.x <= 0.0 || size.y <= 0.0 || size.z < 0.0 {
            return Err(format!(
                "sampling box {:?} .. {:?} has no area in x and y",
                self.min.to_array(),
                self.max.to_array()
            ));
        }
        if self.min.z >= 0.0 && size.z > 0.0 {
            return Err(
                "the device lies entirely in the room (z ≥ 0): it must lie behind z = 0, \
                        the room on +z"
                    .into(),
            );
        }
        Ok(())
    }

    /// genBSDF's warnings: the device reaches into the room, or lies far behind z = 0.
    pub fn warnings(&self) -> Vec<String> {
        let size = self.max - self.min;
        let mut w = Vec::new();
        if self.max.z > 1e-5 {
            w.push(format!(
                "the device extends {} into the room (z > 0)",
                self.max.z
            ));
        } else if self.max.z * self.max.z > 0.01 * size.x * size.y {
            w.push(format!(
                "the device lies far behind z = 0 (its top at z = {})",
                self.max.z
            ));
        }
        w
    }
}

/// How hard to sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GenBsdfSettings {
    /// Rays per incident patch and side (genBSDF's `-c`, 2000 by default).
    pub samples_per_patch: u32,
    /// Most diffuse bounces in the device (genBSDF runs `rfluxmtx -ab 5`).
    pub ambient_bounces: u32,
    pub seed: u64,
    /// Light from the room side (+z): the room-side reflection and the transmission out.
    pub from_room: bool,
    /// Light from outside (−z): the outside reflection and the transmission in.
    pub from_outside: bool,
}

impl Default for GenBsdfSettings {
    fn default() -> Self {
        GenBsdfSettings {
            samples_per_patch: 2000,
            ambient_bounces: 5,
            seed: 1,
            from_room: true,
            from_outside: true,
        }
    }
}

/// One part as sampled: `values[outgoing * n_incident + incident]` in 1/sr (a Klems matrix's
/// layout, whatever the cells), with the Monte-Carlo standard error of each (from the spread
/// of single paths, which overstates it a little for stratified directions).
#[derive(Clone, Debug)]
pub struct GeneratedPart {
    pub side: Side,
    pub n_incident: usize,
    pub values: Vec<f64>,
    pub standard_error: Vec<f64>,
}

impl GeneratedPart {
    /// Incident cell `incident`'s directional-hemispherical value (R or T) and its standard
    /// error (the cells' errors taken as independent, which they are not quite: a path
    /// lands in one), `omega_sr(o)` the projected solid angle of outgoing cell o.
    pub fn hemispherical(&self, incident: usize, omega_sr: impl Fn(usize) -> f64) -> (f64, f64) {
        let n_out = self.values.len() / self.n_incident;
        let (mut sum, mut var) = (0.0, 0.0);
        for o in 0..n_out {
            let w = omega_sr(o);
            sum += self.values[o * self.n_incident + incident] * w;
            var += (self.standard_error[o * self.n_incident + incident] * w).powi(2);
        }
        (sum, var.sqrt())
    }
}

/// A document of `parts` over `data`, the device's size the sampling box's.
fn document<'a>(
    name: &'a str,
    created_by: &'a str,
    unit: &'a str,
    sampling: &SamplingBox,
    data: DocumentData<'a>,
    parts: Vec<DocumentPart<'a>>,
) -> BsdfDocument<'a> {
    let size = sampling.max - sampling.min;
    BsdfDocument {
        name,
        created_by,
        unit,
        thickness: size.z,
        width: size.x,
        height: size.y,
        data,
        parts,
    }
}

/// How far outside the box's face a ray starts, in the geometry's units (genBSDF's `FEPS`).
const START_OFFSET: f64 = 1e-6;
/// Rays per batch; directions are stratified 8 × 8 within a full batch.
const BATCH: u32 = 64;
const STRATA: u32 = 8;
/// Most specular events per path: a ray between two mirror-like slats may bounce dozens of
/// times (rfluxmtx stops by weight, `-lw 3e-6`: some 40 reflections at 0.7).
const MAX_SPECULAR_EVENTS: u32 = 64;

/// The cells of one sampling: incident cells per side, outgoing cells per side, and where a
/// direction falls. Directions are unit vectors in the device's frame pointing away from it.
pub(crate) trait Cells: Sync {
    fn incident_count(&self) -> usize;
    fn outgoing_count(&self) -> usize;
    /// An incident direction in cell `cell` of side `front` for `u` uniform in [0,1)²,
    /// uniform in projected solid angle over the cell.
    fn incident(&self, front: bool, cell: usize, u: [f64; 2]) -> DVec3;
    /// The outgoing cell of `outgoing` for light in from side `front` along `incident`.
    fn outgoing_cell(&self, front: bool, incident: DVec3, outgoing: DVec3) -> Option<usize>;
    /// Projected solid angle of an outgoing cell, sr.
    fn outgoing_projected_solid_angle_sr(&self, cell: usize) -> f64;
}

/// Samples every incident cell of the sides asked for and returns the four (or two) parts.
pub(crate) fn sample_parts(
    world: &World,
    sampling: &SamplingBox,
    cells: &dyn Cells,
    settings: &GenBsdfSettings,
    progress: &(dyn Fn(u64, u64) + Sync),
) -> Result<Vec<GeneratedPart>, EngineError> {
    check(sampling, settings)?;
    let sides: Vec<bool> = [(settings.from_room, true), (settings.from_outside, false)]
        .into_iter()
        .filter_map(|(on, front)| on.then_some(front))
        .collect();
    let (n_in, n_out) = (cells.incident_count(), cells.outgoing_count());
    let total = (sides.len() * n_in) as u64;
    let done = std::sync::atomic::AtomicU64::new(0);
    let jobs: Vec<(bool, usize)> = sides
        .iter()
        .flat_map(|&front| (0..n_in).map(move |p| (front, p)))
        .collect();
    let sampled: Vec<CellSums> = jobs
        .par_iter()
        .map(|&(front, cell)| {
            let sums = sample_cell(world, sampling, cells, front, cell, settings);
            let d = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(d, total);
            sums
        })
        .collect();
    let count = f64::from(settings.samples_per_patch);
    let mut parts = Vec::new();
    for &front in &sides {
        for out_front in [true, false] {
            let mut values = vec![0.0; n_in * n_out];
            let mut standard_error = vec![0.0; n_in * n_out];
            for ((_, incident), sums) in jobs.iter().zip(&sampled).filter(|(j, _)| j.0 == front) {
                for out in 0..n_out {
                    let bin = out_bin(out_front, out, n_out);
                    let mean = sums.sum[bin] / count;
                    let variance =
                        (sums.sum_sq[bin] / count - mean * mean).max(0.0) / (count - 1.0);
                    let omega = cells.outgoing_projected_solid_angle_sr(out);
                    values[out * n_in + incident] = mean / omega;
                    standard_error[out * n_in + incident] = variance.sqrt() / omega;
                }
            }
            parts.push(GeneratedPart {
                side: Side::of(front, out_front),
                n_incident: n_in,
                values,
                standard_error,
            });
        }
    }
    Ok(parts)
}

fn check(sampling: &SamplingBox, settings: &GenBsdfSettings) -> Result<(), EngineError> {
    if settings.samples_per_patch < 2 {
        return Err(EngineError::Setting {
            name: "samples per patch",
            value: settings.samples_per_patch.to_string(),
            expected: "at least 2",
        });
    }
    if !settings.from_room && !settings.from_outside {
        return Err(EngineError::Setting {
            name: "sides",
            value: "none".into(),
            expected: "the room side, the outside or both",
        });
    }
    sampling.check().map_err(|_| EngineError::Setting {
        name: "sampling box",
        value: format!(
            "{:?} .. {:?}",
            sampling.min.to_array(),
            sampling.max.to_array()
        ),
        expected: "an area in x and y, behind z = 0",
    })
}

/// The settings of every path: no sky to sample, more specular events than a room needs.
fn path_settings(settings: &GenBsdfSettings) -> Settings {
    Settings {
        ambient_bounces: settings.ambient_bounces,
        samples_per_sensor: 1,
        seed: settings.seed,
        max_specular_events: MAX_SPECULAR_EVENTS,
        portal_sampling: false,
        sky_sampling: false,
        russian_roulette: true,
        sun_portal_sampling: false,
        stratified: false,
        path_reuse: false,
        bsdf_window_sampling: false,
        sunlit_outside_sampling: false,
    }
}

/// Flux sums of one incident cell's paths: per outgoing bin (front cells, then back).
struct CellSums {
    sum: Vec<f64>,
    sum_sq: Vec<f64>,
}

fn out_bin(out_front: bool, cell: usize, n: usize) -> usize {
    if out_front {
        cell
    } else {
        n + cell
    }
}

fn sample_cell(
    world: &World,
    sampling: &SamplingBox,
    cells: &dyn Cells,
    front: bool,
    cell: usize,
    settings: &GenBsdfSettings,
) -> CellSums {
    let n_out = cells.outgoing_count();
    let mut sums = CellSums {
        sum: vec![0.0; 2 * n_out],
        sum_sq: vec![0.0; 2 * n_out],
    };
    let path_settings = path_settings(settings);
    let z = if front {
        sampling.max.z + START_OFFSET
    } else {
        sampling.min.z - START_OFFSET
    };
    let size = sampling.max - sampling.min;
    let mut path: Vec<(usize, f64)> = Vec::with_capacity(4);
    let batches = settings.samples_per_patch.div_ceil(BATCH);
    for b in 0..batches {
        let stream = (5u64 << 60) | (u64::from(front) << 59) | ((cell as u64) << 32) | u64::from(b);
        let mut rng = Rng::for_stream(settings.seed, stream);
        let count = BATCH.min(settings.samples_per_patch - b * BATCH);
        let strata = if count == BATCH { STRATA } else { 0 };
        for i in 0..count {
            let incident = cells.incident(front, cell, stratified(i, strata, &mut rng));
            let origin = DVec3::new(
                sampling.min.x + rng.uniform() * size.x,
                sampling.min.y + rng.uniform() * size.y,
                z,
            );
            path.clear();
            let ray = Ray::new(origin, -incident);
            escape_path(world, ray, &path_settings, &mut rng, &mut |w, ray| {
                let d = ray.direction;
                if d.z == 0.0 {
                    return;
                }
                let out_front = d.z > 0.0;
                if let Some(c) = cells.outgoing_cell(front, incident, d) {
                    path.push((out_bin(out_front, c, n_out), bright(w)));
                }
            });
            sums.add_path(&mut path);
        }
    }
    sums
}

/// Sample `i` of a batch stratified `strata` × `strata` over the unit square (plain uniform
/// numbers for `strata` 0).
fn stratified(i: u32, strata: u32, rng: &mut Rng) -> [f64; 2] {
    if strata == 0 {
        return [rng.uniform(), rng.uniform()];
    }
    let (a, c) = (i % strata, i / strata);
    [
        (f64::from(a) + rng.uniform()) / f64::from(strata),
        (f64::from(c) + rng.uniform()) / f64::from(strata),
    ]
}

impl CellSums {
    /// Adds one path's escapes (bin, flux): a path may leave more than once (a split at
    /// glass), and its flux per bin is one draw of the estimator.
    fn add_path(&mut self, path: &mut [(usize, f64)]) {
        path.sort_unstable_by_key(|e| e.0);
        for group in path.chunk_by(|a, b| a.0 == b.0) {
            let w: f64 = group.iter().map(|e| e.1).sum();
            self.sum[group[0].0] += w;
            self.sum_sq[group[0].0] += w * w;
        }
    }
}

//! The daylight matrix D: for each Klems patch of the window, the mean radiance arriving
//! along the patch per unit radiance of each sky patch (what `rfluxmtx window.rad sky.rad`
//! computes with the window a sender and the sky a receiver). For each patch, rays start at
//! points uniform over the window and leave outward along directions uniform in projected
//! solid angle over the patch, and follow the engine's paths through the outside geometry;
//! each escape is credited to its sky patch.
//!
//! Columns: the ground first (every direction below the horizon, as the tutorial's
//! `skyglow.rad` has it: a `u` ground receiver, then Reinhart MF n sky patches), so that
//! D's columns are `gendaymtx -m n`'s rows.

use super::window::KlemsWindow;
use super::BATCH_SAMPLES;
use crate::engine::error::EngineError;
use crate::engine::integrator::{escape_path, Settings};
use crate::engine::material::bright;
use crate::engine::ray::Ray;
use crate::engine::rng::Rng;
use crate::engine::world::World;
use crate::io::radiance_matrix::RadianceMatrix;
use crate::sky::SkyPatches;
use rayon::prelude::*;

/// Strata per axis of a batch's directions (8 × 8 = `BATCH_SAMPLES`).
const STRATA: u32 = 8;
const _: () = assert!(STRATA * STRATA == BATCH_SAMPLES);

/// How far out of the window's plane a sender ray starts, m: clear of coplanar walls.
const START_OFFSET_M: f64 = 1e-6;

/// D of `world` (the outside, and the room's outer faces; no sky or sun) for `window`, with
/// `settings.samples_per_sensor` rays per window patch: patches × (1 + Reinhart MF `mf` sky
/// patches), dimensionless, one component.
pub fn daylight_matrix(
    world: &World,
    window: &KlemsWindow,
    mf: usize,
    settings: &Settings,
    progress: &(dyn Fn(u64, u64) + Sync),
) -> Result<RadianceMatrix, EngineError> {
    settings.validate()?;
    let sky = SkyPatches::reinhart(mf);
    let bins = 1 + sky.len();
    let patches = window.basis.len();
    let n = settings.samples_per_sensor;
    let batches = n.div_ceil(BATCH_SAMPLES);
    let total = patches as u64 * u64::from(batches);
    let done = std::sync::atomic::AtomicU64::new(0);
    let jobs: Vec<(usize, u32)> = (0..patches)
        .flat_map(|p| (0..batches).map(move |b| (p, b)))
        .collect();
    let partial: Vec<Vec<f64>> = jobs
        .par_iter()
        .map(|&(patch, b)| {
            let stream = (3u64 << 61) | ((patch as u64) << 32) | u64::from(b);
            let mut rng = Rng::for_stream(settings.seed, stream);
            let count = BATCH_SAMPLES.min(n - b * BATCH_SAMPLES);
            let mut acc = vec![0.0; bins];
            // A full batch's directions are jittered over an 8 × 8 grid of the patch (as
            // rfluxmtx stratifies its sender samples): a row that sees the ground is then no
            // longer a coin toss per ray. A partial batch is sampled plainly (unbiased).
            let strata = if count == STRATA * STRATA { STRATA } else { 0 };
            for i in 0..count {
                let point = window.sample_point([rng.uniform(), rng.uniform()]);
                let u = if strata > 0 {
                    let (a, b) = (i % strata, i / strata);
                    [
                        (f64::from(a) + rng.uniform()) / f64::from(strata),
                        (f64::from(b) + rng.uniform()) / f64::from(strata),
                    ]
                } else {
                    [rng.uniform(), rng.uniform()]
                };
                let arrival = window.arrival_direction(patch, u);
                let ray = Ray::new(point - START_OFFSET_M * window.normal, -arrival);
                escape_path(world, ray, settings, &mut rng, &mut |weight, ray| {
                    let d = ray.direction;
                    let bin = if d.z < 0.0 {
                        Some(0)
                    } else {
                        sky.patch_of(d).map(|p| p + 1)
                    };
                    if let Some(bin) = bin {
                        acc[bin] += bright(weight);
                    }
                });
            }
            let d = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(d, total);
            acc
        })
        .collect();
    let mut m = RadianceMatrix::zeros(patches, bins, 1);
    for (&(p, _), acc) in jobs.iter().zip(&partial) {
        for (c, a) in m.values[p * bins..(p + 1) * bins].iter_mut().zip(acc) {
            *c += a / f64::from(n);
        }
    }
    Ok(m)
}

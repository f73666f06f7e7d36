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
//! quantity `wrapBSDF -c` writes.

use super::error::EngineError;
use super::integrator::{escape_path, Settings};
use super::material::bright;
use super::ray::Ray;
use super::rng::Rng;
use super::world::World;
use crate::bsdf::{AngleBasis, KlemsDocument, KlemsPart, Side};
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

/// One part as sampled: `values[outgoing * n + incident]` in 1/sr, with the Monte-Carlo
/// standard error of each (from the spread of single paths, which overstates it a little
/// for stratified directions).
#[derive(Clone, Debug)]
pub struct GeneratedPart {
    pub side: Side,
    pub values: Vec<f64>,
    pub standard_error: Vec<f64>,
}

/// A sampled BSDF over one Klems basis.
#[derive(Clone, Debug)]
pub struct GeneratedBsdf {
    pub basis: AngleBasis,
    pub parts: Vec<GeneratedPart>,
    pub samples_per_patch: u32,
}

/// How far outside the box's face a ray starts, in the geometry's units (genBSDF's `FEPS`).
const START_OFFSET: f64 = 1e-6;
/// Rays per batch; directions are stratified 8 × 8 within a full batch.
const BATCH: u32 = 64;
const STRATA: u32 = 8;
/// Most specular events per path: a ray between two mirror-like slats may bounce dozens of
/// times (rfluxmtx stops by weight, `-lw 3e-6`: some 40 reflections at 0.7).
const MAX_SPECULAR_EVENTS: u32 = 64;

/// Samples the device `world` over `basis` within `sampling` (see the module comment).
/// `progress(done, total)` is called per incident patch.
pub fn generate_klems(
    world: &World,
    sampling: &SamplingBox,
    basis: &AngleBasis,
    settings: &GenBsdfSettings,
    progress: &(dyn Fn(u64, u64) + Sync),
) -> Result<GeneratedBsdf, EngineError> {
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
    })?;
    let sides: Vec<bool> = [(settings.from_room, true), (settings.from_outside, false)]
        .into_iter()
        .filter_map(|(on, front)| on.then_some(front))
        .collect();
    let n = basis.len();
    let total = (sides.len() * n) as u64;
    let done = std::sync::atomic::AtomicU64::new(0);
    let path_settings = Settings {
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
    };
    let jobs: Vec<(bool, usize)> = sides
        .iter()
        .flat_map(|&front| (0..n).map(move |p| (front, p)))
        .collect();
    let sampled: Vec<PatchSums> = jobs
        .par_iter()
        .map(|&(front, patch)| {
            let sums = sample_patch(
                world,
                sampling,
                basis,
                front,
                patch,
                settings,
                &path_settings,
            );
            let d = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(d, total);
            sums
        })
        .collect();
    let count = f64::from(settings.samples_per_patch);
    let mut parts = Vec::new();
    for &front in &sides {
        for out_front in [true, false] {
            let side = Side::of(front, out_front);
            let mut values = vec![0.0; n * n];
            let mut standard_error = vec![0.0; n * n];
            for ((_, incident), sums) in jobs.iter().zip(&sampled).filter(|(j, _)| j.0 == front) {
                for out in 0..n {
                    let bin = out_bin(out_front, out, n);
                    let mean = sums.sum[bin] / count;
                    let variance =
                        (sums.sum_sq[bin] / count - mean * mean).max(0.0) / (count - 1.0);
                    let omega = basis.projected_solid_angle_sr(out);
                    values[out * n + incident] = mean / omega;
                    standard_error[out * n + incident] = variance.sqrt() / omega;
                }
            }
            parts.push(GeneratedPart {
                side,
                values,
                standard_error,
            });
        }
    }
    Ok(GeneratedBsdf {
        basis: basis.clone(),
        parts,
        samples_per_patch: settings.samples_per_patch,
    })
}

/// Flux sums of one incident patch's paths: per outgoing bin (front patches, then back).
struct PatchSums {
    sum: Vec<f64>,
    sum_sq: Vec<f64>,
}

fn out_bin(out_front: bool, patch: usize, n: usize) -> usize {
    if out_front {
        patch
    } else {
        n + patch
    }
}

fn sample_patch(
    world: &World,
    sampling: &SamplingBox,
    basis: &AngleBasis,
    front: bool,
    patch: usize,
    settings: &GenBsdfSettings,
    path_settings: &Settings,
) -> PatchSums {
    let n = basis.len();
    let mut sums = PatchSums {
        sum: vec![0.0; 2 * n],
        sum_sq: vec![0.0; 2 * n],
    };
    // The incident frame of either part from this side (reflection and transmission share it).
    let side = Side::of(front, front);
    let z = if front {
        sampling.max.z + START_OFFSET
    } else {
        sampling.min.z - START_OFFSET
    };
    let size = sampling.max - sampling.min;
    let mut path: Vec<(usize, f64)> = Vec::with_capacity(4);
    let batches = settings.samples_per_patch.div_ceil(BATCH);
    for b in 0..batches {
        let stream =
            (5u64 << 60) | (u64::from(front) << 59) | ((patch as u64) << 32) | u64::from(b);
        let mut rng = Rng::for_stream(settings.seed, stream);
        let count = BATCH.min(settings.samples_per_patch - b * BATCH);
        let strata = if count == BATCH { STRATA } else { 0 };
        for i in 0..count {
            let u = if strata > 0 {
                let (a, c) = (i % strata, i / strata);
                [
                    (f64::from(a) + rng.uniform()) / f64::from(strata),
                    (f64::from(c) + rng.uniform()) / f64::from(strata),
                ]
            } else {
                [rng.uniform(), rng.uniform()]
            };
            let incident = side.incident_in_basis_frame(basis.direction_in_patch(patch, u));
            let origin = DVec3::new(
                sampling.min.x + rng.uniform() * size.x,
                sampling.min.y + rng.uniform() * size.y,
                z,
            );
            path.clear();
            escape_path(
                world,
                Ray::new(origin, -incident),
                path_settings,
                &mut rng,
                &mut |w, ray| {
                    let d = ray.direction;
                    if d.z == 0.0 {
                        return;
                    }
                    let out_front = d.z > 0.0;
                    let out_side = Side::of(front, out_front);
                    if let Some(p) = basis.patch_of(out_side.outgoing_in_basis_frame(d)) {
                        path.push((out_bin(out_front, p, n), bright(w)));
                    }
                },
            );
            // A path may leave more than once (a split at glass): its flux per bin is one draw.
            path.sort_unstable_by_key(|e| e.0);
            let mut k = 0;
            while k < path.len() {
                let bin = path[k].0;
                let mut w = 0.0;
                while k < path.len() && path[k].0 == bin {
                    w += path[k].1;
                    k += 1;
                }
                sums.sum[bin] += w;
                sums.sum_sq[bin] += w * w;
            }
        }
    }
    sums
}

/// How far a sampled BSDF is from reciprocal, f(ωi → ωo) = f(ωo → ωi), over the pairs of
/// patch centres: per kind of part (None where a part is missing).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Reciprocity {
    pub transmission: Option<Asymmetry>,
    pub room_reflection: Option<Asymmetry>,
    pub outside_reflection: Option<Asymmetry>,
}

/// One kind of part's departure from reciprocity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Asymmetry {
    /// Σ|a − b| Ωa Ωb / Σ ½(a + b) Ωa Ωb: includes the sampling noise.
    pub relative: f64,
    /// The RMS of (a − b) / √(σa² + σb²) over pairs with any light: about 1 for a
    /// reciprocal device sampled without bias, whatever the sample count.
    pub rms_standard_errors: f64,
}

impl GeneratedBsdf {
    pub fn part(&self, side: Side) -> Option<&GeneratedPart> {
        self.parts.iter().find(|p| p.side == side)
    }

    /// Patch `incident`'s directional-hemispherical value of `side`: R or T.
    pub fn hemispherical(&self, side: Side, incident: usize) -> Option<f64> {
        let n = self.basis.len();
        let part = self.part(side)?;
        Some(
            (0..n)
                .map(|o| part.values[o * n + incident] * self.basis.projected_solid_angle_sr(o))
                .sum(),
        )
    }

    /// The standard error of [`Self::hemispherical`] (errors of the patches taken as
    /// independent, which they are not quite: a path lands in one).
    pub fn hemispherical_standard_error(&self, side: Side, incident: usize) -> Option<f64> {
        let n = self.basis.len();
        let part = self.part(side)?;
        Some(
            (0..n)
                .map(|o| {
                    (part.standard_error[o * n + incident] * self.basis.projected_solid_angle_sr(o))
                        .powi(2)
                })
                .sum::<f64>()
                .sqrt(),
        )
    }

    /// See [`Reciprocity`].
    pub fn reciprocity(&self) -> Reciprocity {
        let pair = |a: Side, b: Side| {
            let (pa, pb) = (self.part(a)?, self.part(b)?);
            Some(self.asymmetry(pa, pb))
        };
        Reciprocity {
            transmission: pair(Side::FrontTransmission, Side::BackTransmission),
            room_reflection: pair(Side::FrontReflection, Side::FrontReflection),
            outside_reflection: pair(Side::BackReflection, Side::BackReflection),
        }
    }

    fn asymmetry(&self, a: &GeneratedPart, b: &GeneratedPart) -> Asymmetry {
        let n = self.basis.len();
        let centre = |p: usize| self.basis.direction_in_patch(p, [0.5, 0.5]);
        let (mut diff, mut mean) = (0.0, 0.0);
        let (mut z2, mut pairs) = (0.0, 0usize);
        for i in 0..n {
            let incident = a.side.incident_in_basis_frame(centre(i));
            for o in 0..n {
                let outgoing = a.side.outgoing_in_basis_frame(centre(o));
                // The same pair of directions the other way round, in b's patches.
                let bi = self
                    .basis
                    .patch_of(b.side.incident_in_basis_frame(outgoing));
                let bo = self
                    .basis
                    .patch_of(b.side.outgoing_in_basis_frame(incident));
                let (Some(bi), Some(bo)) = (bi, bo) else {
                    continue;
                };
                let w =
                    self.basis.projected_solid_angle_sr(i) * self.basis.projected_solid_angle_sr(o);
                let (va, vb) = (a.values[o * n + i], b.values[bo * n + bi]);
                diff += (va - vb).abs() * w;
                mean += 0.5 * (va + vb) * w;
                let sigma = a.standard_error[o * n + i].hypot(b.standard_error[bo * n + bi]);
                if sigma > 0.0 {
                    z2 += ((va - vb) / sigma).powi(2);
                    pairs += 1;
                }
            }
        }
        Asymmetry {
            relative: if mean > 0.0 { diff / mean } else { 0.0 },
            rms_standard_errors: if pairs > 0 {
                (z2 / pairs as f64).sqrt()
            } else {
                0.0
            },
        }
    }

    /// The XML document of the parts that carry any light (genBSDF leaves out a part that is
    /// zero everywhere, as an opaque device's transmission).
    pub fn document<'a>(
        &'a self,
        name: &'a str,
        created_by: &'a str,
        unit: &'a str,
        sampling: &SamplingBox,
    ) -> KlemsDocument<'a> {
        let size = sampling.max - sampling.min;
        KlemsDocument {
            name,
            created_by,
            unit,
            thickness: size.z,
            width: size.x,
            height: size.y,
            basis: &self.basis,
            parts: self
                .parts
                .iter()
                .filter(|p| p.values.iter().any(|&v| v > 0.0))
                .map(|p| KlemsPart {
                    side: p.side,
                    values: &p.values,
                })
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene;

    fn world(text: &str) -> World {
        World::new(&scene::parse("device.rad", text.as_bytes()).unwrap()).unwrap()
    }

    fn unit_box() -> SamplingBox {
        SamplingBox {
            min: DVec3::new(-0.5, -0.5, -0.1),
            max: DVec3::new(0.5, 0.5, 0.0),
        }
    }

    fn settings(samples: u32) -> GenBsdfSettings {
        GenBsdfSettings {
            samples_per_patch: samples,
            ..Default::default()
        }
    }

    #[test]
    fn nothing_in_the_box_transmits_every_ray_into_its_own_patch() {
        // A device of nothing but an invisible surface: every ray goes straight through.
        let w = world("void polygon nothing 0 0 12 5 5 -3  -5 5 -3  -5 -5 -3  5 -5 -3\n");
        let basis = AngleBasis::builtin("LBNL/Klems Full").unwrap();
        let g = generate_klems(&w, &unit_box(), &basis, &settings(64), &|_, _| {}).unwrap();
        for side in [Side::FrontTransmission, Side::BackTransmission] {
            let part = g.part(side).unwrap();
            for i in 0..basis.len() {
                let t = g.hemispherical(side, i).unwrap();
                assert!((t - 1.0).abs() < 1e-12, "{side:?} patch {i}: T {t}");
                let own = part.values[i * basis.len() + i] * basis.projected_solid_angle_sr(i);
                assert!(
                    (own - 1.0).abs() < 1e-12,
                    "{side:?} patch {i} not onto itself: {own}"
                );
            }
        }
        for side in [Side::FrontReflection, Side::BackReflection] {
            assert!(g.part(side).unwrap().values.iter().all(|&v| v == 0.0));
        }
        let r = g.reciprocity();
        assert!(r.transmission.unwrap().relative < 1e-12, "{r:?}");
        // The empty reflections are left out of the file.
        let doc = g.document("clear", "test", "meter", &unit_box());
        assert_eq!(doc.parts.len(), 2);
    }

    #[test]
    fn a_lambertian_plane_reflects_its_reflectance_evenly() {
        // Grey plastic 0.6 inside the whole sampling box: R = 0.6 from the room for every
        // patch, f = 0.6/π into every patch, nothing through.
        let w = world(
            "void plastic grey 0 0 5 .6 .6 .6 0 0\n\
             grey polygon plate 0 0 12 -50 -50 -0.05  50 -50 -0.05  50 50 -0.05  -50 50 -0.05\n",
        );
        let basis = AngleBasis::builtin("LBNL/Klems Quarter").unwrap();
        let g = generate_klems(&w, &unit_box(), &basis, &settings(4096), &|_, _| {}).unwrap();
        let n = basis.len();
        let part = g.part(Side::FrontReflection).unwrap();
        for i in 0..n {
            let r = g.hemispherical(Side::FrontReflection, i).unwrap();
            let se = g
                .hemispherical_standard_error(Side::FrontReflection, i)
                .unwrap();
            assert!(
                (r - 0.6).abs() < 1e-9 + 5.0 * se.max(1e-3),
                "patch {i}: R {r} ± {se}"
            );
            for o in 0..n {
                let (v, e) = (part.values[o * n + i], part.standard_error[o * n + i]);
                assert!(
                    (v - 0.6 / std::f64::consts::PI).abs() < 5.0 * e + 1e-9,
                    "f({i}->{o}) = {v} ± {e}"
                );
            }
            assert!(g.hemispherical(Side::FrontTransmission, i).unwrap() == 0.0);
        }
        // Reciprocal within its noise (the relative figure is the noise itself here).
        let r = g.reciprocity();
        let z = r.room_reflection.unwrap().rms_standard_errors;
        assert!(z > 0.5 && z < 1.3, "{r:?}");
    }

    #[test]
    fn a_flat_mirror_reflects_each_patch_into_its_mirror_patch() {
        // An ideal mirror tilted nowhere: light in from patch i leaves by the mirror direction,
        // which the reflection part's frames put in patch i too (RADIANCE's fi/fo frames:
        // the incident azimuth is turned by 180°).
        let w = world(
            "void mirror m 0 0 3 .9 .9 .9\n\
             m polygon plate 0 0 12 -50 -50 -0.05  50 -50 -0.05  50 50 -0.05  -50 50 -0.05\n",
        );
        let basis = AngleBasis::builtin("LBNL/Klems Full").unwrap();
        let g = generate_klems(&w, &unit_box(), &basis, &settings(64), &|_, _| {}).unwrap();
        let n = basis.len();
        let part = g.part(Side::FrontReflection).unwrap();
        for i in 0..n {
            let own = part.values[i * n + i] * basis.projected_solid_angle_sr(i);
            assert!((own - 0.9).abs() < 1e-9, "patch {i}: {own}");
        }
    }

    #[test]
    fn bad_settings_and_boxes_are_refused() {
        let w = world("void polygon nothing 0 0 12 5 5 -3  -5 5 -3  -5 -5 -3  5 -5 -3\n");
        let basis = AngleBasis::builtin("LBNL/Klems Quarter").unwrap();
        assert!(generate_klems(&w, &unit_box(), &basis, &settings(1), &|_, _| {}).is_err());
        let flat = SamplingBox {
            min: DVec3::new(0.0, -1.0, -1.0),
            max: DVec3::new(0.0, 1.0, 0.0),
        };
        assert!(flat.check().is_err());
        assert!(generate_klems(&w, &flat, &basis, &settings(64), &|_, _| {}).is_err());
        let in_room = SamplingBox {
            min: DVec3::new(-1.0, -1.0, 0.5),
            max: DVec3::new(1.0, 1.0, 1.0),
        };
        assert!(in_room.check().is_err());
    }
}

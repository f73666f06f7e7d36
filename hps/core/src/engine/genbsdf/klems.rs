//! Sampling over a Klems basis: the patches as `rfluxmtx` uses them for a sender (`h=kf`) and
//! the receiving hemispheres, each part's patches in the frame RADIANCE reads it in
//! ([`Side::incident_in_basis_frame`]), so that the matrix lands where `BSDF` looks.

use super::{document, sample_parts, Cells, GenBsdfSettings, GeneratedPart, SamplingBox};
use crate::bsdf::{AngleBasis, BsdfDocument, DocumentData, DocumentPart, Side};
use crate::engine::error::EngineError;
use crate::engine::world::World;
use glam::DVec3;

/// A sampled BSDF over one Klems basis.
#[derive(Clone, Debug)]
pub struct GeneratedBsdf {
    pub basis: AngleBasis,
    pub parts: Vec<GeneratedPart>,
    pub samples_per_patch: u32,
}

struct KlemsCells<'a>(&'a AngleBasis);

impl Cells for KlemsCells<'_> {
    fn incident_count(&self) -> usize {
        self.0.len()
    }

    fn outgoing_count(&self) -> usize {
        self.0.len()
    }

    fn incident(&self, front: bool, cell: usize, u: [f64; 2]) -> DVec3 {
        // Reflection and transmission from one side share the incident frame.
        Side::of(front, front).incident_in_basis_frame(self.0.direction_in_patch(cell, u))
    }

    fn outgoing_cell(&self, front: bool, _incident: DVec3, outgoing: DVec3) -> Option<usize> {
        let side = Side::of(front, outgoing.z > 0.0);
        self.0.patch_of(side.outgoing_in_basis_frame(outgoing))
    }

    fn outgoing_projected_solid_angle_sr(&self, cell: usize) -> f64 {
        self.0.projected_solid_angle_sr(cell)
    }
}

/// Samples the device `world` over `basis` within `sampling` (see [`super`]).
/// `progress(done, total)` is called per incident patch.
pub fn generate_klems(
    world: &World,
    sampling: &SamplingBox,
    basis: &AngleBasis,
    settings: &GenBsdfSettings,
    progress: &(dyn Fn(u64, u64) + Sync),
) -> Result<GeneratedBsdf, EngineError> {
    let parts = sample_parts(world, sampling, &KlemsCells(basis), settings, progress)?;
    Ok(GeneratedBsdf {
        basis: basis.clone(),
        parts,
        samples_per_patch: settings.samples_per_patch,
    })
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
        let part = self.part(side)?;
        Some(
            part.hemispherical(incident, |o| self.basis.projected_solid_angle_sr(o))
                .0,
        )
    }

    /// The standard error of [`Self::hemispherical`].
    pub fn hemispherical_standard_error(&self, side: Side, incident: usize) -> Option<f64> {
        let part = self.part(side)?;
        Some(
            part.hemispherical(incident, |o| self.basis.projected_solid_angle_sr(o))
                .1,
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
    ) -> BsdfDocument<'a> {
        let parts = self
            .parts
            .iter()
            .filter(|p| p.values.iter().any(|&v| v > 0.0))
            .map(|p| DocumentPart {
                side: p.side,
                values: &p.values,
            })
            .collect();
        let data = DocumentData::Klems(&self.basis);
        document(name, created_by, unit, sampling, data, parts)
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

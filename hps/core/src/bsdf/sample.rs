//! Sampling scattered directions by the data's own distribution: a Lambertian lobe per side,
//! then each part's patches or cells by f·projected solid angle, uniform in projected solid
//! angle inside a patch or cell (RADIANCE `SDsampBSDF`). The density is f·cosθo/(R+T) up to
//! RADIANCE's ±0.03 % perturbation of values.

use super::part::PartDistribution;
use super::shirley_chiu::square_to_disk;
use super::{Bsdf, Scattering, Side};
use glam::DVec3;
use std::f64::consts::PI;

/// One sampled scattered direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BsdfSample {
    pub direction: DVec3,
    /// f(ωi, ωo) in 1/sr.
    pub value_per_sr: f64,
    /// Probability density of `direction` per steradian.
    pub pdf_per_sr: f64,
    /// The chosen lobe alone: its f(ωi, ωo) in 1/sr and the density per steradian of
    /// choosing it and drawing `direction` from it, so that `lobe_value_per_sr` |cos θo| /
    /// `lobe_pdf_per_sr` estimates that lobe's share without bias (one-sample lobe selection,
    /// what a caller needs to treat Lambertian and directional lobes differently).
    pub lobe_value_per_sr: f64,
    pub lobe_pdf_per_sr: f64,
    /// The direction came from a Lambertian lobe (diffuse, an ambient bounce for RADIANCE).
    pub lambertian: bool,
}

enum Lobe<'a> {
    Lambertian {
        hemispherical: f64,
        outgoing_front: bool,
    },
    Part(PartDistribution<'a>),
}

impl Lobe<'_> {
    fn total(&self) -> f64 {
        match self {
            Lobe::Lambertian { hemispherical, .. } => *hemispherical,
            Lobe::Part(d) => d.total(),
        }
    }
}

/// Everything light from one incident direction can scatter into.
pub struct OutgoingDistribution<'a> {
    bsdf: &'a Bsdf,
    incident: DVec3,
    lobes: Vec<Lobe<'a>>,
    total: f64,
}

/// Below this R+T nothing is sampled (RADIANCE `SDsampBSDF`).
const NOTHING_TO_SAMPLE: f64 = 1e-6;

impl Bsdf {
    /// The scattered-direction distribution for light from `incident` (build once, sample many).
    pub fn distribution(&self, incident: DVec3) -> OutgoingDistribution<'_> {
        let inf = incident.z > 0.0;
        let mut lobes = Vec::new();
        for kind in [Scattering::Reflection, Scattering::Transmission] {
            let outgoing_front = (kind == Scattering::Reflection) == inf;
            let hemispherical = self.lambertian_of(Side::of(inf, outgoing_front));
            if hemispherical > 0.0 {
                lobes.push(Lobe::Lambertian {
                    hemispherical,
                    outgoing_front,
                });
            }
            let part = self.part_for(inf, outgoing_front);
            if let Some(d) = part.and_then(|p| p.distribution(incident, self.quantum)) {
                if d.total() > 0.0 {
                    lobes.push(Lobe::Part(d));
                }
            }
        }
        let total = lobes.iter().map(Lobe::total).sum();
        OutgoingDistribution {
            bsdf: self,
            incident,
            lobes,
            total,
        }
    }

    /// One scattered direction for `u` in [0,1)³, or None when nothing scatters.
    pub fn sample(&self, incident: DVec3, u: [f64; 3]) -> Option<BsdfSample> {
        self.distribution(incident).sample(u)
    }
}

impl OutgoingDistribution<'_> {
    /// R + T for this incident direction.
    pub fn total(&self) -> f64 {
        self.total
    }

    pub fn sample(&self, u: [f64; 3]) -> Option<BsdfSample> {
        if self.total <= NOTHING_TO_SAMPLE {
            return None;
        }
        let mut target = u[0].clamp(0.0, 1.0) * self.total;
        let last = self.lobes.len() - 1;
        let (_, lobe) = self.lobes.iter().enumerate().find(|(k, l)| {
            let inside = target < l.total() || *k == last;
            if !inside {
                target -= l.total();
            }
            inside
        })?;
        let u0 = (target / lobe.total()).clamp(0.0, 1.0 - f64::EPSILON);
        let (direction, lobe_value_per_sr, lobe_per_projected_sr) = match lobe {
            Lobe::Lambertian {
                outgoing_front,
                hemispherical,
            } => {
                let d = cosine_direction(*outgoing_front, u[1], u[2]);
                (d, hemispherical / PI, hemispherical / PI)
            }
            Lobe::Part(p) => {
                let d = p.sample([u0, u[1], u[2]]);
                let f = self
                    .bsdf
                    .part_for(self.incident.z > 0.0, d.z > 0.0)
                    .map_or(0.0, |part| part.eval(self.incident, d));
                (d, f, p.weight_per_projected_sr(d))
            }
        };
        Some(BsdfSample {
            direction,
            value_per_sr: self.bsdf.eval(self.incident, direction),
            pdf_per_sr: self.pdf_per_sr(direction),
            lobe_value_per_sr,
            lobe_pdf_per_sr: lobe_per_projected_sr * direction.z.abs() / self.total,
            lambertian: matches!(lobe, Lobe::Lambertian { .. }),
        })
    }

    /// Density of `sample` per steradian at `outgoing`.
    pub fn pdf_per_sr(&self, outgoing: DVec3) -> f64 {
        if self.total <= NOTHING_TO_SAMPLE {
            return 0.0;
        }
        let per_projected_sr: f64 = self
            .lobes
            .iter()
            .map(|lobe| match lobe {
                Lobe::Lambertian {
                    hemispherical,
                    outgoing_front,
                } => {
                    if (outgoing.z > 0.0) == *outgoing_front {
                        hemispherical / PI
                    } else {
                        0.0
                    }
                }
                Lobe::Part(d) => d.weight_per_projected_sr(outgoing),
            })
            .sum();
        per_projected_sr * outgoing.z.abs() / self.total
    }
}

/// A cosine-distributed direction on the +z (`front`) or -z side, through the concentric map.
fn cosine_direction(front: bool, u1: f64, u2: f64) -> DVec3 {
    let [x, y] = square_to_disk(u1, u2);
    let z = (1.0 - x * x - y * y).max(0.0).sqrt();
    DVec3::new(x, y, if front { z } else { -z })
}

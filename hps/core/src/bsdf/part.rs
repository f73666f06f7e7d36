//! One scattering part (front or back, reflection or transmission) of a BSDF, whichever way
//! the file stores it: a Klems matrix or a tensor tree.

use super::klems::{KlemsMatrix, PatchDistribution};
use super::side::Side;
use super::tensor_tree::{CellDistribution, TensorTree};
use glam::DVec3;
use std::f64::consts::PI;

#[derive(Debug, Clone)]
pub enum Part {
    Klems(KlemsMatrix),
    Tree(TensorTree),
}

/// Scattered directions of one part for one incident direction.
pub enum PartDistribution<'a> {
    Klems(PatchDistribution<'a>),
    Tree(CellDistribution<'a>),
}

impl Part {
    pub fn side(&self) -> Side {
        match self {
            Part::Klems(m) => m.side,
            Part::Tree(t) => t.side,
        }
    }

    pub fn max_hemispherical(&self) -> f64 {
        match self {
            Part::Klems(m) => m.max_hemispherical(),
            Part::Tree(t) => t.max_hemispherical(),
        }
    }

    pub fn extract_diffuse(&mut self) -> f64 {
        match self {
            Part::Klems(m) => m.extract_diffuse(),
            Part::Tree(t) => t.extract_diffuse(),
        }
    }

    /// The smallest projected solid angle the data resolves (RADIANCE's `minProjSA`): the
    /// smallest Klems patch, or π w² for the smallest tree leaf of width w.
    pub fn min_projected_solid_angle(&self) -> f64 {
        match self {
            Part::Klems(m) => m.min_projected_solid_angle(),
            Part::Tree(t) => PI * t.smallest_leaf().powi(2),
        }
    }

    /// The projected solid angles of the data's cells holding the pair (`v1`, `v2`), 0 for
    /// none (RADIANCE's `queryProjSA` of a component with two vectors).
    pub fn pair_projected_solid_angles(&self, v1: DVec3, v2: DVec3) -> [f64; 2] {
        match self {
            Part::Klems(m) => m.pair_projected_solid_angles(v1, v2),
            Part::Tree(t) => {
                let psa = t.pair_projected_solid_angle(v1, v2).unwrap_or(0.0);
                [psa, psa]
            }
        }
    }

    /// f(ωi, ωo) in 1/sr without the Lambertian part; 0 when the pair is not this part's.
    pub fn eval(&self, incident: DVec3, outgoing: DVec3) -> f64 {
        match self {
            Part::Klems(m) => m.eval(incident, outgoing),
            Part::Tree(t) => t.eval(incident, outgoing),
        }
    }

    /// `quantum`: the incident-coordinate step of tree distributions (see `Bsdf`).
    pub fn distribution(&self, incident: DVec3, quantum: f64) -> Option<PartDistribution<'_>> {
        match self {
            Part::Klems(m) => m.distribution(incident).map(PartDistribution::Klems),
            Part::Tree(t) => t
                .distribution(incident, quantum)
                .map(PartDistribution::Tree),
        }
    }
}

impl PartDistribution<'_> {
    /// ∫ f cos θo dωo of this part (its share of the hemispherical R or T).
    pub fn total(&self) -> f64 {
        match self {
            PartDistribution::Klems(d) => d.total(),
            PartDistribution::Tree(d) => d.total(),
        }
    }

    pub fn sample(&self, u: [f64; 3]) -> DVec3 {
        match self {
            PartDistribution::Klems(d) => d.sample(u),
            PartDistribution::Tree(d) => d.sample(u),
        }
    }

    /// Sampling density per projected steradian at `outgoing`, times `total`.
    pub fn weight_per_projected_sr(&self, outgoing: DVec3) -> f64 {
        match self {
            PartDistribution::Klems(d) => d.weight_per_projected_sr(outgoing),
            PartDistribution::Tree(d) => d.weight_per_projected_sr(outgoing),
        }
    }
}

//! One scattering part (front or back, reflection or transmission) of a BSDF, whichever way
//! the file stores it: a Klems matrix or a tensor tree.

use super::klems::{KlemsMatrix, PatchDistribution};
use super::side::Side;
use super::tensor_tree::{CellDistribution, TensorTree};
use glam::DVec3;

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

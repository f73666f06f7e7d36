//! Sampling over the Shirley–Chiu square, RADIANCE's tensor-tree cells (`bsdf_t.c`; genBSDF
//! `-t4`/`-t3`): a direction's cell is its concentric-map square point, the incident taken
//! reversed (−x, −y), so that a cell of either hemisphere is π/res² of projected solid angle.
//!
//! - [`TreeKind::Anisotropic`] (`TensorTree4`): res² incident cells per side, any device.
//! - [`TreeKind::Isotropic`] (`TensorTree3`): res/2 incident cells along the incident's
//!   sin θ (the tree's coordinate 0.5 − ½ sin θ), in the x-z plane as genBSDF `-t3` samples
//!   them (rays travelling towards +x, jittered by up to 1/res across), the outgoing
//!   direction turned onto the tree's frame as RADIANCE turns it for a lookup. Right for a
//!   device with no preferred direction (a frit, a diffuser); for any other it is the device
//!   under light in its x-z plane only, as genBSDF's is (blinds with slats along x: light
//!   along the slats). The grid's upper half in that coordinate is never read and is written
//!   as zeros, as RADIANCE's own trees have it.
//!
//! The grid is written whole (no reduction: RADIANCE reads a one-leaf tree as a reduced one).

use super::{document, sample_parts, Cells, GenBsdfSettings, GeneratedPart, SamplingBox};
use crate::bsdf::{disk_to_square, square_to_disk, BsdfDocument, DocumentData, DocumentPart, Side};
use crate::engine::error::EngineError;
use crate::engine::world::World;
use glam::DVec3;
use std::f64::consts::PI;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TreeKind {
    /// `TensorTree3`.
    Isotropic,
    /// `TensorTree4`.
    Anisotropic,
}

impl TreeKind {
    pub fn dims(self) -> u32 {
        match self {
            TreeKind::Isotropic => 3,
            TreeKind::Anisotropic => 4,
        }
    }
}

/// A sampled tensor-tree BSDF.
#[derive(Clone, Debug)]
pub struct GeneratedTree {
    pub kind: TreeKind,
    /// 2^log2_res cells per dimension.
    pub log2_res: u32,
    /// Per part, `values[outgoing cell * n_incident + incident cell]`.
    pub parts: Vec<GeneratedPart>,
    pub samples_per_cell: u32,
}

struct TreeCells {
    kind: TreeKind,
    res: usize,
}

impl TreeCells {
    fn cell_of_square(&self, s: [f64; 2]) -> usize {
        let k = |x: f64| ((x * self.res as f64) as usize).min(self.res - 1);
        k(s[0]) * self.res + k(s[1])
    }
}

impl Cells for TreeCells {
    fn incident_count(&self) -> usize {
        match self.kind {
            TreeKind::Isotropic => self.res / 2,
            TreeKind::Anisotropic => self.res * self.res,
        }
    }

    fn outgoing_count(&self) -> usize {
        self.res * self.res
    }

    fn incident(&self, front: bool, cell: usize, u: [f64; 2]) -> DVec3 {
        let z_sign = if front { 1.0 } else { -1.0 };
        let res = self.res as f64;
        let (x, y) = match self.kind {
            TreeKind::Anisotropic => {
                let (a, b) = ((cell / self.res) as f64, (cell % self.res) as f64);
                let [x, y] = square_to_disk((a + u[0]) / res, (b + u[1]) / res);
                (-x, -y)
            }
            TreeKind::Isotropic => {
                // genBSDF -t3: the ray travels towards +x (the incident at azimuth π), its
                // x component uniform over the cell, jittered across by up to 1/res in y.
                let dx = 1.0 - 2.0 * (cell as f64 + u[0]) / res;
                let dy = (1.0 / res).min((1.0 - dx * dx).max(0.0).sqrt()) * (2.0 * u[1] - 1.0);
                (-dx, -dy)
            }
        };
        DVec3::new(x, y, z_sign * (1.0 - x * x - y * y).max(0.0).sqrt())
    }

    fn outgoing_cell(&self, _front: bool, incident: DVec3, outgoing: DVec3) -> Option<usize> {
        let o = match self.kind {
            TreeKind::Anisotropic => outgoing,
            // Turned about z with the incident onto the tree's plane, as bsdf_t.c turns it
            // (by −atan2(−iy, −ix)) before its lookup.
            TreeKind::Isotropic => {
                let (s, c) = (-(-incident.y).atan2(-incident.x)).sin_cos();
                DVec3::new(
                    outgoing.x * c - outgoing.y * s,
                    outgoing.y * c + outgoing.x * s,
                    outgoing.z,
                )
            }
        };
        Some(self.cell_of_square(disk_to_square(o.x, o.y)))
    }

    fn outgoing_projected_solid_angle_sr(&self, _cell: usize) -> f64 {
        PI / (self.res * self.res) as f64
    }
}

/// Samples the device `world` as a tensor tree of 2^`log2_res` cells per dimension within
/// `sampling` (see [`super`] and this module). `progress(done, total)` per incident cell.
pub fn generate_tensor_tree(
    world: &World,
    sampling: &SamplingBox,
    kind: TreeKind,
    log2_res: u32,
    settings: &GenBsdfSettings,
    progress: &(dyn Fn(u64, u64) + Sync),
) -> Result<GeneratedTree, EngineError> {
    // A t4 grid of 64 cells per dimension is 16.7 M values per part (a gigabyte with the
    // errors of four parts): the limit is 32, genBSDF's default being 16.
    let (largest, expected) = match kind {
        TreeKind::Isotropic => (6, "2 to 6 (4 to 64 cells per dimension) for t3"),
        TreeKind::Anisotropic => (5, "2 to 5 (4 to 32 cells per dimension) for t4"),
    };
    if !(2..=largest).contains(&log2_res) {
        return Err(EngineError::Setting {
            name: "tensor tree resolution (log2)",
            value: log2_res.to_string(),
            expected,
        });
    }
    let cells = TreeCells {
        kind,
        res: 1 << log2_res,
    };
    let parts = sample_parts(world, sampling, &cells, settings, progress)?;
    Ok(GeneratedTree {
        kind,
        log2_res,
        parts,
        samples_per_cell: settings.samples_per_patch,
    })
}

impl GeneratedTree {
    pub fn part(&self, side: Side) -> Option<&GeneratedPart> {
        self.parts.iter().find(|p| p.side == side)
    }

    /// Incident cell `incident`'s directional-hemispherical value of `side` (R or T) and
    /// its standard error.
    pub fn hemispherical(&self, side: Side, incident: usize) -> Option<(f64, f64)> {
        let res = 1usize << self.log2_res;
        let omega = PI / (res * res) as f64;
        Some(self.part(side)?.hemispherical(incident, |_| omega))
    }

    /// Each part's grid as the file holds it: incident cells slowest, then the outgoing
    /// square's two coordinates; an isotropic tree's unused upper half zero. Parts that
    /// carry no light are left out (as genBSDF leaves them).
    pub fn grids(&self) -> Vec<(Side, Vec<f64>)> {
        self.parts
            .iter()
            .filter(|p| p.values.iter().any(|&v| v > 0.0))
            .map(|p| (p.side, self.grid_of(p, &p.values)))
            .collect()
    }

    /// `per_element` (a part's values or standard errors, in the part's layout) as the
    /// file's grid.
    pub fn grid_of(&self, part: &GeneratedPart, per_element: &[f64]) -> Vec<f64> {
        let res = 1usize << self.log2_res;
        let n_out = res * res;
        let rows = match self.kind {
            TreeKind::Isotropic => res,
            TreeKind::Anisotropic => res * res,
        };
        let mut grid = vec![0.0; rows * n_out];
        for i in 0..part.n_incident {
            for o in 0..n_out {
                grid[i * n_out + o] = per_element[o * part.n_incident + i];
            }
        }
        grid
    }

    /// The XML document of `grids` (from [`Self::grids`]).
    pub fn document<'a>(
        &self,
        grids: &'a [(Side, Vec<f64>)],
        name: &'a str,
        created_by: &'a str,
        unit: &'a str,
        sampling: &SamplingBox,
    ) -> BsdfDocument<'a> {
        let data = DocumentData::TensorTree {
            dims: self.kind.dims(),
            log2_res: self.log2_res,
        };
        let parts = grids
            .iter()
            .map(|(side, values)| DocumentPart {
                side: *side,
                values,
            })
            .collect();
        document(name, created_by, unit, sampling, data, parts)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene;

    #[test]
    fn nothing_in_the_box_transmits_every_cell_whole_and_t4_onto_its_own_cell() {
        let world = World::new(
            &scene::parse(
                "empty.rad",
                b"void polygon nothing 0 0 12 5 5 -3  -5 5 -3  -5 -5 -3  5 -5 -3\n",
            )
            .unwrap(),
        )
        .unwrap();
        let sampling = SamplingBox {
            min: DVec3::new(-0.5, -0.5, -0.1),
            max: DVec3::new(0.5, 0.5, 0.0),
        };
        let settings = GenBsdfSettings {
            samples_per_patch: 64,
            ..Default::default()
        };
        for kind in [TreeKind::Isotropic, TreeKind::Anisotropic] {
            let g =
                generate_tensor_tree(&world, &sampling, kind, 3, &settings, &|_, _| {}).unwrap();
            for side in [Side::FrontTransmission, Side::BackTransmission] {
                let part = g.part(side).unwrap();
                for i in 0..part.n_incident {
                    let (t, se) = g.hemispherical(side, i).unwrap();
                    assert!((t - 1.0).abs() < 1e-9, "{kind:?} {side:?} {i}: {t}");
                    if kind == TreeKind::Anisotropic {
                        // (An isotropic cell's rays land in neighbouring outgoing cells as
                        // their sin θ varies over it: per cell a spread, in sum exactly 1.)
                        assert!(se < 1e-9, "{side:?} {i}: σ {se}");
                        // The square point of the reversed incident is the outgoing one.
                        let own = part.values[i * part.n_incident + i] * PI / 64.0;
                        assert!((own - 1.0).abs() < 1e-9, "{side:?} cell {i}: {own}");
                    }
                }
            }
            // The grid as written: an isotropic tree's upper half of dimension 0 is zero.
            for (_, grid) in g.grids() {
                assert_eq!(grid.len(), 1 << (kind.dims() * 3));
                if kind == TreeKind::Isotropic {
                    assert!(grid[grid.len() / 2..].iter().all(|&v| v == 0.0));
                }
            }
        }
    }

    #[test]
    fn resolutions_beyond_the_memory_limit_are_refused() {
        let world = World::new(&scene::parse("e.rad", b"").unwrap()).unwrap();
        let sampling = SamplingBox {
            min: DVec3::new(-0.5, -0.5, -0.1),
            max: DVec3::new(0.5, 0.5, 0.0),
        };
        let s = GenBsdfSettings::default();
        let go = |kind, log2| generate_tensor_tree(&world, &sampling, kind, log2, &s, &|_, _| {});
        assert!(go(TreeKind::Anisotropic, 6).is_err());
        assert!(go(TreeKind::Isotropic, 7).is_err());
        assert!(go(TreeKind::Anisotropic, 1).is_err());
    }
}

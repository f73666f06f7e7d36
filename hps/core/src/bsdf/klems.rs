//! Klems angle bases (full, half, quarter, or one the file defines) and the BSDF matrices
//! over them, with the semantics of RADIANCE's `bsdf_m.c`: how a direction finds its patch,
//! which side frame each basis is read in, the matrix orientation (rows outgoing, columns
//! incident), reciprocity when the matrix covers the other direction, and the diffuse part.

use super::error::BsdfError;
use super::side::Side;
use super::xml::{DataStructure, NamedAt, RawAngleBasis, RawBlock};
use glam::DVec3;
use std::f64::consts::PI;
use std::sync::{Arc, OnceLock};

/// One ring of patches between two polar angles.
#[derive(Debug, Clone, PartialEq)]
struct Ring {
    theta_min_deg: f64,
    theta_max_deg: f64,
    n_phis: usize,
    first_patch: usize,
}

/// A Klems-style angle basis: rings of equal-azimuth patches about the normal.
#[derive(Debug, Clone, PartialEq)]
pub struct AngleBasis {
    pub name: String,
    rings: Vec<Ring>,
    n_patches: usize,
}

/// The three LBNL bases, ring lower bounds in degrees and patch counts, closed by 90°
/// (Klems 1994; WINDOW 6; the table in RADIANCE `bsdf_m.c` `abase_list`).
const KLEMS_FULL: &[(f64, usize)] = &[
    (0., 1),
    (5., 8),
    (15., 16),
    (25., 20),
    (35., 24),
    (45., 24),
    (55., 24),
    (65., 16),
    (75., 12),
    (90., 0),
];
const KLEMS_HALF: &[(f64, usize)] = &[
    (0., 1),
    (6.5, 8),
    (19.5, 12),
    (32.5, 16),
    (45.5, 20),
    (58.5, 12),
    (71.5, 8),
    (90., 0),
];
const KLEMS_QUARTER: &[(f64, usize)] =
    &[(0., 1), (9., 8), (27., 12), (45., 12), (63., 8), (90., 0)];
/// RADIANCE's `MAXLATS`: no basis has more rings.
const MAX_RINGS: usize = 46;

impl AngleBasis {
    /// One of the LBNL bases by name (case-insensitive), as RADIANCE knows them.
    pub fn builtin(name: &str) -> Option<AngleBasis> {
        let table = match name.to_ascii_lowercase().as_str() {
            "lbnl/klems full" => KLEMS_FULL,
            "lbnl/klems half" => KLEMS_HALF,
            "lbnl/klems quarter" => KLEMS_QUARTER,
            _ => return None,
        };
        let names = ["LBNL/Klems Full", "LBNL/Klems Half", "LBNL/Klems Quarter"];
        let canonical = names
            .iter()
            .find(|n| n.eq_ignore_ascii_case(name))
            .unwrap_or(&"");
        let rings = table
            .windows(2)
            .map(|w| (w[0].0, w[1].0, w[0].1))
            .collect::<Vec<_>>();
        Some(Self::from_rings(canonical, &rings))
    }

    fn from_rings(name: &str, rings: &[(f64, f64, usize)]) -> AngleBasis {
        let mut first_patch = 0;
        let rings = rings
            .iter()
            .map(|&(theta_min_deg, theta_max_deg, n_phis)| {
                let ring = Ring {
                    theta_min_deg,
                    theta_max_deg,
                    n_phis,
                    first_patch,
                };
                first_patch += n_phis;
                ring
            })
            .collect();
        AngleBasis {
            name: name.to_string(),
            rings,
            n_patches: first_patch,
        }
    }

    /// A basis the file defines. A built-in name keeps the built-in table, as RADIANCE does
    /// (`load_angle_basis`: "assume it's the same"), but the definition must still be sound.
    pub fn from_raw(raw: &RawAngleBasis, file: &str) -> Result<AngleBasis, BsdfError> {
        let error = |line, message: String| BsdfError::new(file, line, "AngleBasisBlock", message);
        if raw.rings.is_empty() || raw.rings.len() > MAX_RINGS {
            let message = format!(
                "basis '{}' has {} rings (1 to {MAX_RINGS})",
                raw.name,
                raw.rings.len()
            );
            return Err(BsdfError::new(file, raw.line, "AngleBasis", message));
        }
        let mut rings = Vec::with_capacity(raw.rings.len());
        let mut lower = 0.0;
        for (k, ring) in raw.rings.iter().enumerate() {
            if let Some(given) = ring.lower_theta_deg.filter(|_| k > 0) {
                // RADIANCE's `fequal`: equal within 1e-6 relative.
                if ((given - lower).abs()) > 1e-6 * lower.abs() {
                    return Err(error(
                        ring.line,
                        format!("LowerTheta {given} is not the previous UpperTheta {lower}"),
                    ));
                }
            }
            if !(ring.upper_theta_deg > lower && ring.upper_theta_deg <= 90.0) {
                return Err(error(
                    ring.line,
                    format!("UpperTheta {} not in ({lower}, 90]", ring.upper_theta_deg),
                ));
            }
            if ring.n_phis == 1 && k > 0 {
                return Err(error(
                    ring.line,
                    "a single patch is only allowed around the normal".into(),
                ));
            }
            rings.push((lower, ring.upper_theta_deg, ring.n_phis));
            lower = ring.upper_theta_deg;
        }
        Ok(Self::builtin(&raw.name).unwrap_or_else(|| Self::from_rings(&raw.name, &rings)))
    }

    /// The patch holding `v` (unit, +z hemisphere of the basis's own frame), as RADIANCE's
    /// `fo_getndx`: rings by polar angle, patches centred on their azimuth.
    pub fn patch_of(&self, v: DVec3) -> Option<usize> {
        if v.z < 0.0 || v.z > 1.00001 || v.is_nan() {
            return None;
        }
        let polar_deg = 180.0 / PI * if v.z >= 1.0 { 0.0 } else { v.z.acos() };
        let mut azimuth_deg = 180.0 / PI * v.y.atan2(v.x);
        if azimuth_deg < 0.0 {
            azimuth_deg += 360.0;
        }
        let last = self.rings.last()?;
        if last.theta_max_deg <= polar_deg {
            return None;
        }
        let ring = self
            .rings
            .iter()
            .rev()
            .find(|r| r.theta_min_deg <= polar_deg)?;
        let mut index = ((1.0 / 360.0) * azimuth_deg * ring.n_phis as f64 + 0.5) as usize;
        if index >= ring.n_phis {
            index = 0;
        }
        Some(ring.first_patch + index)
    }

    /// The rings as (lower θ°, upper θ°, patches), from the normal out: what a file's
    /// `AngleBasisBlock`s declare.
    pub fn rings(&self) -> impl Iterator<Item = (f64, f64, usize)> + '_ {
        self.rings
            .iter()
            .map(|r| (r.theta_min_deg, r.theta_max_deg, r.n_phis))
    }

    /// Number of patches.
    pub fn len(&self) -> usize {
        self.n_patches
    }

    pub fn is_empty(&self) -> bool {
        self.n_patches == 0
    }

    fn ring_of(&self, patch: usize) -> &Ring {
        let k = self
            .rings
            .partition_point(|r| r.first_patch + r.n_phis <= patch);
        &self.rings[k.min(self.rings.len() - 1)]
    }

    /// Projected solid angle of a patch, π (cos²θ₀ − cos²θ₁) / nφ (RADIANCE `io_getohm`).
    pub fn projected_solid_angle_sr(&self, patch: usize) -> f64 {
        let ring = self.ring_of(patch);
        PI * (cos2(ring.theta_min_deg) - cos2(ring.theta_max_deg)) / ring.n_phis as f64
    }

    /// A direction in `patch`, uniform in projected solid angle for uniform `u`
    /// (RADIANCE `fo_getvec`: linear in cos²θ, azimuth about the patch centre).
    pub fn direction_in_patch(&self, patch: usize, u: [f64; 2]) -> DVec3 {
        let ring = self.ring_of(patch);
        let z = ((1.0 - u[0]) * cos2(ring.theta_min_deg) + u[0] * cos2(ring.theta_max_deg)).sqrt();
        let index = (patch - ring.first_patch) as f64;
        let azimuth = 2.0 * PI * (index + u[1] - 0.5) / ring.n_phis as f64;
        let sin_polar = (1.0 - z * z).max(0.0).sqrt();
        DVec3::new(azimuth.cos() * sin_polar, azimuth.sin() * sin_polar, z)
    }
}

/// cos²θ for θ in degrees.
fn cos2(theta_deg: f64) -> f64 {
    (PI / 180.0 * theta_deg).cos().powi(2)
}

/// The frame a basis is read in: RADIANCE's fo/fi/bo/bi, each its own inverse.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum BasisFrame {
    FrontOutgoing,
    FrontIncident,
    BackOutgoing,
    BackIncident,
}

impl BasisFrame {
    fn map(self, v: DVec3) -> DVec3 {
        match self {
            BasisFrame::FrontOutgoing => v,
            BasisFrame::FrontIncident => DVec3::new(-v.x, -v.y, v.z),
            BasisFrame::BackOutgoing => DVec3::new(v.x, v.y, -v.z),
            BasisFrame::BackIncident => -v,
        }
    }

    /// Incident and outgoing frames of a part (RADIANCE `load_bsdf_data`).
    fn of(side: Side) -> (BasisFrame, BasisFrame) {
        match side {
            Side::FrontReflection => (BasisFrame::FrontIncident, BasisFrame::FrontOutgoing),
            Side::BackReflection => (BasisFrame::BackIncident, BasisFrame::BackOutgoing),
            Side::FrontTransmission => (BasisFrame::FrontIncident, BasisFrame::BackOutgoing),
            Side::BackTransmission => (BasisFrame::BackIncident, BasisFrame::FrontOutgoing),
        }
    }
}

impl Side {
    /// An incident direction of this part (unit, pointing away from the surface) in the frame
    /// its column basis is read in; the map is its own inverse, so it also turns a direction
    /// of that frame into the incident direction. What a writer of Klems data needs to put
    /// each value where RADIANCE will read it.
    pub fn incident_in_basis_frame(self, v: DVec3) -> DVec3 {
        BasisFrame::of(self).0.map(v)
    }

    /// An outgoing direction of this part in the frame its row basis is read in (and back).
    pub fn outgoing_in_basis_frame(self, v: DVec3) -> DVec3 {
        BasisFrame::of(self).1.map(v)
    }
}

/// One Klems BSDF matrix (1/sr) of one part.
#[derive(Debug, Clone)]
pub struct KlemsMatrix {
    pub side: Side,
    incident: AngleBasis,
    outgoing: AngleBasis,
    frames: (BasisFrame, BasisFrame),
    /// Values at `outgoing_patch * n_incident + incident_patch`.
    values: Vec<f32>,
    /// Each fixed patch's cumulative patch weights, built on first use and kept (RADIANCE
    /// caches its `SDCDst` likewise): a material samples one per hit. Index 0 for an
    /// incident patch, 1 for an outgoing one (the reversed direction).
    cumulative_cache: [Vec<OnceLock<Arc<[f64]>>>; 2],
}

/// Finds a basis by name: those the file defines first, then the built-in ones.
fn find_basis(
    named: &Option<NamedAt>,
    element: &str,
    defined: &[AngleBasis],
    block: &RawBlock,
    file: &str,
) -> Result<AngleBasis, BsdfError> {
    let Some(named) = named else {
        return Err(BsdfError::new(
            file,
            block.line,
            element,
            format!("missing <{element}>"),
        ));
    };
    defined
        .iter()
        .find(|b| b.name.eq_ignore_ascii_case(&named.name))
        .cloned()
        .or_else(|| AngleBasis::builtin(&named.name))
        .ok_or_else(|| {
            BsdfError::new(
                file,
                named.line,
                element,
                format!("undefined angle basis '{}'", named.name),
            )
        })
}

impl KlemsMatrix {
    /// Reads one block of a `Columns` or `Rows` file.
    pub fn from_block(
        block: &RawBlock,
        structure: DataStructure,
        defined: &[AngleBasis],
        file: &str,
    ) -> Result<KlemsMatrix, BsdfError> {
        let incident = find_basis(
            &block.column_basis,
            "ColumnAngleBasis",
            defined,
            block,
            file,
        )?;
        let outgoing = find_basis(&block.row_basis, "RowAngleBasis", defined, block, file)?;
        let (n_in, n_out) = (incident.n_patches, outgoing.n_patches);
        let read = block.data.values(file)?;
        // Checked: a custom basis may claim more patches than a 32-bit usize can multiply.
        if n_in.checked_mul(n_out) != Some(read.len()) {
            let message = format!(
                "{} values, but the bases '{}' ({n_in}) and '{}' ({n_out}) need {}",
                read.len(),
                incident.name,
                outgoing.name,
                n_in as u64 * n_out as u64
            );
            return Err(BsdfError::new(
                file,
                block.data.line,
                "ScatteringData",
                message,
            ));
        }
        let values = match structure {
            DataStructure::Rows => (0..n_in * n_out)
                .map(|k| read[(k % n_in) * n_out + k / n_in])
                .collect(),
            _ => read,
        };
        let side = block_side(block);
        let cumulative_cache = [
            (0..incident.n_patches).map(|_| OnceLock::new()).collect(),
            (0..outgoing.n_patches).map(|_| OnceLock::new()).collect(),
        ];
        Ok(KlemsMatrix {
            side,
            incident,
            outgoing,
            frames: BasisFrame::of(side),
            values,
            cumulative_cache,
        })
    }

    pub fn incident_basis(&self) -> &AngleBasis {
        &self.incident
    }

    pub fn outgoing_basis(&self) -> &AngleBasis {
        &self.outgoing
    }

    /// The file's value (1/sr) for a pair of patches, before any Lambertian share is taken out.
    pub fn value(&self, outgoing_patch: usize, incident_patch: usize) -> f32 {
        self.values[outgoing_patch * self.incident.n_patches + incident_patch]
    }

    fn incident_patch(&self, v: DVec3) -> Option<usize> {
        self.incident.patch_of(self.frames.0.map(v))
    }

    fn outgoing_patch(&self, v: DVec3) -> Option<usize> {
        self.outgoing.patch_of(self.frames.1.map(v))
    }

    /// The value with RADIANCE's position-specific perturbation of ±0.03 % (`mBSDF_color`),
    /// which breaks ties in its sampling; kept so that values agree with RADIANCE exactly.
    fn perturbed(&self, incident_patch: usize, outgoing_patch: usize) -> f32 {
        let (n_in, n_out) = (
            self.incident.n_patches as f64,
            self.outgoing.n_patches as f64,
        );
        let mut d = 2.0 * n_in / (incident_patch as f64 + 0.22545)
            + 4.0 * n_out / (outgoing_patch as f64 + 0.70281);
        d -= d.trunc();
        (self.value(outgoing_patch, incident_patch) as f64 * (1.0 + 6e-4 * (d - 0.5))) as f32
    }

    /// The smallest projected solid angle of a patch of the outgoing basis, and of the
    /// incident basis when it differs (`get_extrema`'s `minProjSA`).
    pub fn min_projected_solid_angle(&self) -> f64 {
        let smallest = |b: &AngleBasis| {
            (0..b.n_patches)
                .map(|k| b.projected_solid_angle_sr(k))
                .fold(PI, f64::min)
        };
        let mut min = smallest(&self.outgoing);
        if self.incident.name != self.outgoing.name {
            min = min.min(smallest(&self.incident));
        }
        min
    }

    /// The projected solid angles of the patches holding `v1` as an outgoing and `v2` as an
    /// incident direction, or the other way round when neither is found that way; 0 for a
    /// direction in no patch (RADIANCE `SDqueryMtxProjSA`).
    pub fn pair_projected_solid_angles(&self, v1: DVec3, v2: DVec3) -> [f64; 2] {
        let psa = |basis: &AngleBasis, patch: Option<usize>| {
            patch.map_or(0.0, |k| basis.projected_solid_angle_sr(k))
        };
        let out = psa(&self.outgoing, self.outgoing_patch(v1));
        let inc = psa(&self.incident, self.incident_patch(v2));
        if out <= 0.0 && inc <= 0.0 && v1 != v2 {
            [
                psa(&self.incident, self.incident_patch(v1)),
                psa(&self.outgoing, self.outgoing_patch(v2)),
            ]
        } else {
            [out, inc]
        }
    }

    /// The largest directional-hemispherical value over incident patches (`get_extrema`).
    pub fn max_hemispherical(&self) -> f64 {
        let ohm: Vec<f64> = (0..self.outgoing.n_patches)
            .map(|o| self.outgoing.projected_solid_angle_sr(o))
            .collect();
        (0..self.incident.n_patches)
            .map(|i| {
                ohm.iter()
                    .enumerate()
                    .rev()
                    .map(|(o, w)| w * self.value(o, i) as f64)
                    .sum::<f64>()
            })
            .fold(0.0, f64::max)
    }

    /// Takes the smallest value out as a Lambertian part and returns its hemispherical
    /// value, π·min, unless below 0.01 (RADIANCE `subtract_min`).
    pub fn extract_diffuse(&mut self) -> f64 {
        let mut min_value = f32::MAX;
        for i in 0..self.incident.n_patches {
            for o in 0..self.outgoing.n_patches {
                min_value = min_value.min(self.perturbed(i, o));
            }
        }
        if min_value as f64 <= 0.01 / PI {
            return 0.0;
        }
        self.values.iter_mut().for_each(|v| *v -= min_value);
        // Distributions built before this are stale.
        self.cumulative_cache
            .iter_mut()
            .flatten()
            .for_each(|c| *c = OnceLock::new());
        PI * min_value as f64
    }

    /// f(ωi, ωo) of this part in 1/sr, or 0 when the pair is not this part's.
    pub fn eval(&self, incident: DVec3, outgoing: DVec3) -> f64 {
        let mut patches = (self.incident_patch(incident), self.outgoing_patch(outgoing));
        if patches.0.is_none() && patches.1.is_none() {
            patches = (self.incident_patch(outgoing), self.outgoing_patch(incident));
        }
        match patches {
            (Some(i), Some(o)) => self.perturbed(i, o) as f64,
            _ => 0.0,
        }
    }

    /// The outgoing distribution for `incident` over this part's patches, or None when the
    /// direction is not on this part's sides (RADIANCE `SDgetMtxCDist`).
    pub fn distribution(&self, incident: DVec3) -> Option<PatchDistribution<'_>> {
        let (patch, reversed) = match self.incident_patch(incident) {
            Some(i) => (i, false),
            None => (self.outgoing_patch(incident)?, true),
        };
        let cumulative = self.cumulative_cache[usize::from(reversed)][patch]
            .get_or_init(|| self.cumulative_weights(patch, reversed))
            .clone();
        Some(PatchDistribution {
            matrix: self,
            patch,
            reversed,
            cumulative,
        })
    }

    /// Running sums of the patch weights scattered from patch `fixed`, starting at 0.
    fn cumulative_weights(&self, fixed: usize, reversed: bool) -> Arc<[f64]> {
        let n = if reversed {
            self.incident.n_patches
        } else {
            self.outgoing.n_patches
        };
        let mut cumulative = Vec::with_capacity(n + 1);
        let mut sum = 0.0;
        cumulative.push(0.0);
        for k in 0..n {
            sum += self.weight(fixed, k, reversed);
            cumulative.push(sum);
        }
        cumulative.into()
    }

    /// f·projected solid angle of scattered patch `k` for the fixed patch `fixed`.
    fn weight(&self, fixed: usize, k: usize, reversed: bool) -> f64 {
        if reversed {
            self.value(fixed, k) as f64 * self.incident.projected_solid_angle_sr(k)
        } else {
            self.value(k, fixed) as f64 * self.outgoing.projected_solid_angle_sr(k)
        }
    }
}

fn block_side(block: &RawBlock) -> Side {
    Side::from_window(block.direction)
}

/// Scattered directions from one incident patch, by patch weight f·Ω_proj.
pub struct PatchDistribution<'a> {
    matrix: &'a KlemsMatrix,
    patch: usize,
    reversed: bool,
    cumulative: Arc<[f64]>,
}

impl PatchDistribution<'_> {
    /// ∫ f cos θo dωo over the scattered hemisphere (this part's share of R or T).
    pub fn total(&self) -> f64 {
        *self.cumulative.last().unwrap_or(&0.0)
    }

    /// A scattered direction for `u` in [0,1)³, uniform in projected solid angle in its patch.
    pub fn sample(&self, u: [f64; 3]) -> DVec3 {
        let target = u[0] * self.total();
        let k = self
            .cumulative
            .partition_point(|&c| c <= target)
            .clamp(1, self.cumulative.len() - 1)
            - 1;
        let m = self.matrix;
        let (basis, frame) = if self.reversed {
            (&m.incident, m.frames.0)
        } else {
            (&m.outgoing, m.frames.1)
        };
        frame.map(basis.direction_in_patch(k, [u[1], u[2]]))
    }

    /// The density of `sample` per projected steradian times `total`, at `outgoing`.
    pub fn weight_per_projected_sr(&self, outgoing: DVec3) -> f64 {
        let m = self.matrix;
        let k = if self.reversed {
            m.incident_patch(outgoing)
        } else {
            m.outgoing_patch(outgoing)
        };
        match k {
            Some(k) if self.reversed => m.value(self.patch, k) as f64,
            Some(k) => m.value(k, self.patch) as f64,
            None => 0.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_bases_cover_the_hemisphere() {
        for (name, n) in [
            ("LBNL/Klems Full", 145),
            ("lbnl/klems half", 77),
            ("LBNL/Klems Quarter", 41),
        ] {
            let basis = AngleBasis::builtin(name).unwrap();
            assert_eq!(basis.n_patches, n, "{name}");
            // The projected solid angles of a partition of the hemisphere add up to π.
            let total: f64 = (0..n).map(|p| basis.projected_solid_angle_sr(p)).sum();
            assert!((total - PI).abs() < 1e-12, "{name}: {total}");
            for patch in 0..n {
                for u in [[0.5, 0.5], [0.01, 0.02], [0.99, 0.98]] {
                    let v = basis.direction_in_patch(patch, u);
                    assert_eq!(
                        basis.patch_of(v),
                        Some(patch),
                        "{name} patch {patch} at {u:?}"
                    );
                }
            }
        }
        assert!(AngleBasis::builtin("LBNL/Klems Eighth").is_none());
    }

    #[test]
    fn patches_are_centred_on_their_azimuth() {
        let basis = AngleBasis::builtin("LBNL/Klems Full").unwrap();
        // Ring 5°–15° has 8 patches of 45°, the first centred on φ = 0 (RADIANCE `fo_getndx`).
        let at = |deg: f64| {
            let (t, p) = (10f64.to_radians(), deg.to_radians());
            basis.patch_of(DVec3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos()))
        };
        assert_eq!(at(-22.0), Some(1));
        assert_eq!(at(22.0), Some(1));
        assert_eq!(at(23.0), Some(2));
        assert_eq!(basis.patch_of(DVec3::Z), Some(0));
        assert_eq!(basis.patch_of(-DVec3::Z), None);
    }
}

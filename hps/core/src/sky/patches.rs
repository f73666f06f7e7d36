//! Sky subdivisions: Reinhart MF n (MF 1 is Tregenza's 145 patches), and a luminance map
//! aggregated into them.
//!
//! Geometry as RADIANCE's `gendaymtx.c` (`rh_init`; hardware-facts.md §5.3): row height
//! α = (π/2)/(7n + 0.5); Tregenza band b (patch counts 30, 30, 24, 24, 18, 12, 6) splits into
//! n rows of `tnaz_b · n` patches; the zenith cap has half-angle α/2. Patch solid angle
//! 2π (sin α(r+1) − sin αr) / count; cap 2π (1 − cos(α/2)). The first patch of a row is centred
//! on north and the patches proceed towards east (azimuth from north towards east).

use crate::hdr::{LuminanceMap, MapFlag};
use glam::{DVec3, Vec3};
use std::f64::consts::{FRAC_PI_2, TAU};

/// Tregenza's patches per band (RADIANCE `tnaz`).
const TREGENZA_PER_BAND: [usize; 7] = [30, 30, 24, 24, 18, 12, 6];

/// A subdivision of the upper hemisphere.
#[derive(Clone, Debug)]
pub struct SkyPatches {
    /// Reinhart multiplication factor (1 = Tregenza).
    pub mf: usize,
    /// Row height α, radians.
    pub row_height_rad: f64,
    /// Patches per row, bottom row first (the zenith cap is the last patch).
    pub per_row: Vec<usize>,
    /// Index of each row's first patch.
    row_start: Vec<usize>,
}

impl SkyPatches {
    /// Reinhart MF `mf` (≥ 1): 144 mf² + 1 patches.
    pub fn reinhart(mf: usize) -> Self {
        let mf = mf.max(1);
        let row_height_rad = FRAC_PI_2 / (7.0 * mf as f64 + 0.5);
        let per_row: Vec<usize> = TREGENZA_PER_BAND
            .iter()
            .flat_map(|&n| std::iter::repeat_n(n * mf, mf))
            .collect();
        let mut row_start = Vec::with_capacity(per_row.len());
        let mut next = 0;
        for n in &per_row {
            row_start.push(next);
            next += n;
        }
        Self {
            mf,
            row_height_rad,
            per_row,
            row_start,
        }
    }

    /// Tregenza's 145 patches.
    pub fn tregenza() -> Self {
        Self::reinhart(1)
    }

    /// Number of patches, the zenith cap included.
    pub fn len(&self) -> usize {
        self.per_row.iter().sum::<usize>() + 1
    }

    /// Always false: a subdivision has at least the cap.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Solid angle of patch `i`, sr.
    pub fn solid_angle_sr(&self, i: usize) -> f64 {
        let a = self.row_height_rad;
        if i == self.len() - 1 {
            return TAU * (1.0 - (a / 2.0).cos());
        }
        let row = self.row_of(i);
        TAU * ((a * (row + 1) as f64).sin() - (a * row as f64).sin()) / self.per_row[row] as f64
    }

    fn row_of(&self, i: usize) -> usize {
        self.row_start.partition_point(|&s| s <= i) - 1
    }

    /// Unit direction of patch `i`'s centre (world frame).
    pub fn centre(&self, i: usize) -> DVec3 {
        if i == self.len() - 1 {
            return DVec3::Z;
        }
        let row = self.row_of(i);
        let altitude = self.row_height_rad * (row as f64 + 0.5);
        let azimuth = TAU * (i - self.row_start[row]) as f64 / self.per_row[row] as f64;
        DVec3::new(
            azimuth.sin() * altitude.cos(),
            azimuth.cos() * altitude.cos(),
            altitude.sin(),
        )
    }

    /// The patch containing a direction of the upper hemisphere, or `None` below the horizon.
    pub fn patch_of(&self, direction: DVec3) -> Option<usize> {
        let d = direction.normalize();
        if d.z.is_nan() || d.z < 0.0 {
            return None;
        }
        let altitude = d.z.clamp(-1.0, 1.0).asin();
        let row = (altitude / self.row_height_rad) as usize;
        if row >= self.per_row.len() {
            return Some(self.len() - 1);
        }
        let n = self.per_row[row];
        let azimuth = d.x.atan2(d.y).rem_euclid(TAU);
        let k = ((azimuth / TAU * n as f64 + 0.5) as usize) % n;
        Some(self.row_start[row] + k)
    }

    /// Fills the patches not `seen` by the extrapolation [`Self::aggregate`] documents (the
    /// seen patches of the same row weighted by cosine-power proximity in azimuth; for a row
    /// seen nowhere, the nearest seen row's mean) and returns the filled patches. Shared by
    /// effects that rescale the seen patches and must re-fill the rest the same way.
    pub fn fill_unseen(&self, luminance: &mut [f64], seen: &[bool]) -> Vec<usize> {
        let n = self.len();
        let mut filled = vec![];
        // Row means of the seen patches, for rows with no seen patch at all.
        let rows = self.per_row.len() + 1;
        let row_range = |r: usize| {
            if r == rows - 1 {
                (n - 1, n)
            } else {
                (self.row_start[r], self.row_start[r] + self.per_row[r])
            }
        };
        let row_mean: Vec<Option<f64>> = (0..rows)
            .map(|r| {
                let (a, b) = row_range(r);
                let v: Vec<f64> = (a..b).filter(|&p| seen[p]).map(|p| luminance[p]).collect();
                (!v.is_empty()).then(|| v.iter().sum::<f64>() / v.len() as f64)
            })
            .collect();
        for r in 0..rows {
            let (a, b) = row_range(r);
            for p in a..b {
                if seen[p] {
                    continue;
                }
                let centre = self.centre(p);
                let (mut num, mut den) = (0.0, 0.0);
                for q in (a..b).filter(|&q| seen[q]) {
                    let w = (1.0 + centre.dot(self.centre(q))).powi(4);
                    num += w * luminance[q];
                    den += w;
                }
                luminance[p] = if den > 0.0 {
                    num / den
                } else {
                    (0..rows)
                        .filter_map(|s| row_mean[s].map(|m| (s.abs_diff(r), m)))
                        .min_by_key(|(dist, _)| *dist)
                        .map(|(_, m)| m)
                        .unwrap_or(f64::NAN)
                };
                filled.push(p);
            }
        }
        filled
    }

    /// Aggregates a luminance map (with each group's direction and solid angle) into patches:
    /// each patch gets the solid-angle-weighted mean of its valid groups. A patch with less
    /// than `min_coverage` of its solid angle seen (outside the field of view, or over- or
    /// under-range) is filled by a documented extrapolation: the coverage-weighted mean of the
    /// seen patches of the same row, weighted by the cosine-power proximity in azimuth; for a
    /// row seen nowhere, the nearest seen row's mean. Filled patches are listed.
    pub fn aggregate(
        &self,
        map: &LuminanceMap,
        direction: &[Vec3],
        solid_angle_sr: &[f32],
        min_coverage: f64,
    ) -> PatchSky {
        let n = self.len();
        let (mut sum, mut omega) = (vec![0.0f64; n], vec![0.0f64; n]);
        for i in 0..map.luminance_cd_m2.len() {
            if map.flags[i] != MapFlag::Valid
                || !direction[i].is_finite()
                || solid_angle_sr[i] <= 0.0
            {
                continue;
            }
            if let Some(p) = self.patch_of(direction[i].as_dvec3()) {
                let w = solid_angle_sr[i] as f64;
                sum[p] += w * map.luminance_cd_m2[i] as f64;
                omega[p] += w;
            }
        }
        let seen: Vec<bool> = (0..n)
            .map(|p| omega[p] >= min_coverage * self.solid_angle_sr(p))
            .collect();
        let mut luminance: Vec<f64> = (0..n)
            .map(|p| if seen[p] { sum[p] / omega[p] } else { f64::NAN })
            .collect();
        let filled = self.fill_unseen(&mut luminance, &seen);
        PatchSky {
            luminance_cd_m2: luminance,
            filled,
            coverage: (0..n).map(|p| omega[p] / self.solid_angle_sr(p)).collect(),
        }
    }
}

/// A sky as patch luminances.
#[derive(Clone, Debug)]
pub struct PatchSky {
    /// Mean luminance per patch, cd/m².
    pub luminance_cd_m2: Vec<f64>,
    /// Patches whose value was extrapolated rather than measured.
    pub filled: Vec<usize>,
    /// Fraction of each patch's solid angle covered by valid measured groups.
    pub coverage: Vec<f64>,
}
